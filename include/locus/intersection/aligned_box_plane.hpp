// SPDX-License-Identifier: BSL-1.0
#pragma once
// An aligned box against a plane in 3D: side_of_plane() (which side the box lies on) and
// intersects(); row int3.boxes, book section 11.12.2 (figure 11.65).
// Plane3 {normal, constant} is { X : dot(normal, X) = constant }, taken as given (rounded data,
// not normalised). side_of_plane(box, plane) is Sign::positive when the whole closed box lies
// strictly on the side the normal points to, Sign::negative when strictly on the other side,
// Sign::zero when box and plane meet (straddling or touching); intersects() is side == zero.
// Method: the plane function is linear, so its extremes over the box are at the two corners
// chosen per axis by the sign of the normal component (the book's "near and far" vertices);
// their sides are EXACT signs of dot(normal, p) - constant (core/plane_side.hpp): a plane
// through a corner, along a face or an edge meets the box.
// Degenerate: an empty box (min > max on an axis), a zero normal or NaN/Inf input:
// side_of_plane returns Sign::zero and intersects() false. Swapped overloads take (plane, box).
// Cost: two exact-sign filters; no allocation.

#include <locus/core/plane_side.hpp>
#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/box3.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/plane.hpp>

namespace locus {

namespace detail::box3 {
template <Real T>
[[nodiscard]] inline bool valid(const AlignedBox3<T>& b, const Plane3<T>& p) noexcept {
  return is_finite(b.min) && is_finite(b.max) && !is_empty(b) && !is_degenerate(p);
}
}  // namespace detail::box3

/// The side of the plane the closed box lies on; Sign::zero when they meet (exact).
template <Real T>
[[nodiscard]] inline Sign side_of_plane(const AlignedBox3<T>& b, const Plane3<T>& p) noexcept {
  if (!detail::box3::valid(b, p)) return Sign::zero;
  Vec3<double> lo{}, hi{};
  for (int k = 0; k < 3; ++k) {
    const bool up = p.normal[k] >= T(0);
    lo[k] = double(up ? b.min[k] : b.max[k]);
    hi[k] = double(up ? b.max[k] : b.min[k]);
  }
  return static_cast<Sign>(
      detail::box3::plane_side_of_corners(vec_cast<double>(p.normal), double(p.constant), lo, hi));
}

/// Whether the closed box and the plane meet (exact).
template <Real T>
[[nodiscard]] inline bool intersects(const AlignedBox3<T>& b, const Plane3<T>& p) noexcept {
  return detail::box3::valid(b, p) && side_of_plane(b, p) == Sign::zero;
}

/// Swapped arguments: intersects(b, p).
template <Real T>
[[nodiscard]] inline bool intersects(const Plane3<T>& p, const AlignedBox3<T>& b) noexcept {
  return intersects(b, p);
}

}  // namespace locus
