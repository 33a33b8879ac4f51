// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two aligned boxes in 3D: intersects() (the book's test) and intersection()
// (the common box); row int3.boxes, book section 11.12.3 (figure 11.66).
// Boxes are closed: {min <= x <= max} component-wise; touching faces, edges or corners meet.
// intersects(): for every axis, a.min <= b.max and b.min <= a.max (comparisons of the data as
// given: exact). intersection(): the common box {max(a.min, b.min), min(a.max, b.max)} (exact:
// its coordinates are input coordinates), or std::nullopt when they do not meet; a flat or
// point box when they only touch.
// Degenerate: an empty box (min > max on some axis) meets nothing. NaN coordinates compare false
// and give false / std::nullopt; infinite coordinates are valid (unbounded boxes).
// Cost: six comparisons; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <algorithm>
#include <optional>

namespace locus {

/// Whether two closed aligned boxes meet (exact).
template <Real T>
[[nodiscard]] constexpr bool intersects(const AlignedBox3<T>& a, const AlignedBox3<T>& b) noexcept {
  for (int k = 0; k < 3; ++k)
    if (!(a.min[k] <= a.max[k] && b.min[k] <= b.max[k] && a.min[k] <= b.max[k] &&
          b.min[k] <= a.max[k]))
      return false;
  return true;
}

/// The common box of two closed aligned boxes, or std::nullopt (exact).
template <Real T>
[[nodiscard]] constexpr std::optional<AlignedBox3<T>> intersection(
    const AlignedBox3<T>& a, const AlignedBox3<T>& b) noexcept {
  if (!intersects(a, b)) return std::nullopt;
  return AlignedBox3<T>{cwise_max(a.min, b.min), cwise_min(a.max, b.max)};
}

}  // namespace locus
