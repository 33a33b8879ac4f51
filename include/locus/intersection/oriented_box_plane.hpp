// SPDX-License-Identifier: BSL-1.0
#pragma once
// An oriented box against a plane in 3D: side_of_plane() (which side the box lies on) and
// intersects(); row int3.boxes, book section 11.12.2 (figure 11.65).
// Plane3 {normal, constant} is { X : dot(normal, X) = constant }, taken as given (not
// normalised). side_of_plane(box, plane) is Sign::positive when the whole closed box lies
// strictly on the side the normal points to, Sign::negative when strictly on the other side,
// Sign::zero when they meet; intersects() is side == zero.
// Method: the extremes of the plane function over the box are at the corners
// center -+ sum_k sign(dot(normal, axis_k)) extent_k axis_k (the book's projected radius
// r = sum_k extent_k |dot(normal, axis_k)| in corner form); those two corners are computed in
// floating point (rounded, a few eps of the box's size) and their sides are then EXACT signs
// (core/plane_side.hpp). So the answer is exact for the box whose corners are the rounded ones:
// a plane within a few eps of a corner may be classified either way; axis-aligned boxes with
// small integer data are exact.
// Degenerate: a negative extent, a zero normal or NaN/Inf input: side_of_plane returns
// Sign::zero and intersects() false. Swapped overloads take (plane, box). Cost: a few dozen
// flops and two exact-sign filters; no allocation.

#include <locus/core/plane_side.hpp>
#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/box3.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/plane.hpp>

namespace locus {

namespace detail::box3 {
template <Real T>
[[nodiscard]] inline bool valid(const OrientedBox3<T>& b, const Plane3<T>& p) noexcept {
  return is_finite(b.center) && is_finite(b.axis[0]) && is_finite(b.axis[1]) &&
         is_finite(b.axis[2]) && is_finite(b.extent) && b.extent.x >= T(0) && b.extent.y >= T(0) &&
         b.extent.z >= T(0) && !is_degenerate(p);
}
}  // namespace detail::box3

/// The side of the plane the closed box lies on; Sign::zero when they meet.
template <Real T>
[[nodiscard]] inline Sign side_of_plane(const OrientedBox3<T>& b, const Plane3<T>& p) noexcept {
  if (!detail::box3::valid(b, p)) return Sign::zero;
  const Vec3<double> n = vec_cast<double>(p.normal);
  Vec3<double> lo = vec_cast<double>(b.center), hi = lo;
  for (int k = 0; k < 3; ++k) {
    const Vec3<double> a = vec_cast<double>(b.axis[k]);
    const double s = sign_of_dot(n, a) == Sign::negative ? -1.0 : 1.0;
    lo -= (s * double(b.extent[k])) * a;
    hi += (s * double(b.extent[k])) * a;
  }
  return static_cast<Sign>(detail::box3::plane_side_of_corners(n, double(p.constant), lo, hi));
}

/// Whether the closed box and the plane meet.
template <Real T>
[[nodiscard]] inline bool intersects(const OrientedBox3<T>& b, const Plane3<T>& p) noexcept {
  return detail::box3::valid(b, p) && side_of_plane(b, p) == Sign::zero;
}

/// Swapped arguments: intersects(b, p).
template <Real T>
[[nodiscard]] inline bool intersects(const Plane3<T>& p, const OrientedBox3<T>& b) noexcept {
  return intersects(b, p);
}

}  // namespace locus
