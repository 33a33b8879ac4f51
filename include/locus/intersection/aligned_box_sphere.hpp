// SPDX-License-Identifier: BSL-1.0
#pragma once
// An aligned box against a sphere (the solid ball) in 3D: intersects(); row int3.boxes, book
// section 11.12.4 (figure 11.70; Arvo's test).
// Both are closed: the box {min <= x <= max}, the ball {|x - center| <= radius}; touching
// counts. Method (Arvo): the squared distance from the centre to the box is the sum over axes
// of (c_k - clamp(c_k, min_k, max_k))^2; the ball meets the box iff it is <= radius^2. That
// comparison is EXACT on the data as given: a floating-point filter, then the exact sign of
// sum (c_k^2 - 2 c_k b_k + b_k^2) - r^2 (core/exact_sum.hpp), so a sphere tangent to a face,
// an edge or a corner is decided exactly.
// Degenerate: an empty box (min > max), a negative radius or NaN/Inf input gives false; radius
// 0 is a point (inside or on the box). Swapped overloads take (sphere, box). Cost: about 15
// flops when the filter decides; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/box3.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/sphere.hpp>

namespace locus {

/// Whether the closed box and the closed ball meet (exact).
template <Real T>
[[nodiscard]] inline bool intersects(const AlignedBox3<T>& b, const Sphere3<T>& s) noexcept {
  if (!is_finite(b.min) || !is_finite(b.max) || is_empty(b) || !is_valid(s)) return false;
  return detail::box3::sphere_box_sign(vec_cast<double>(s.center), double(s.radius),
                                       vec_cast<double>(b.min), vec_cast<double>(b.max)) <= 0;
}

/// Swapped arguments: intersects(b, s).
template <Real T>
[[nodiscard]] inline bool intersects(const Sphere3<T>& s, const AlignedBox3<T>& b) noexcept {
  return intersects(b, s);
}

}  // namespace locus
