// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a plane in 3D; row dist3.pt-plane; book section 10.3.1 (figures
// 10.6, 10.7).
//
// distance(p, plane) returns Distance<T, 3, NoParam, Vec2<T>>: closest[1] = the orthogonal
// projection of p onto the plane, param_b = its coordinates (s, t) in plane_frame(plane) (the
// frame whose origin is the plane point nearest the coordinate origin; primitives/plane.hpp),
// so closest[1] ~ point_at(*plane_frame(plane), param_b). distance is |signed distance|; the
// SIGNED distance (positive on the side the normal points to, figure 10.7) is
// signed_distance(p, plane) below, the same value as plane.hpp's signed_distance(plane, p).
// distance(plane, p) is the swapped result. The normal need not be unit length.
//
// Degenerate input: a zero normal defines no plane, and NaN or infinite coefficients have no
// meaning: both give non_finite_distance() (result.hpp), and signed_distance() gives NaN.
// unique is always true. Cost: O(1), one normalisation (and the frame for the parameter).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/plane.hpp>

#include <limits>
#include <optional>

namespace locus {

/// Signed distance from p to the plane: positive on the normal's side; NaN for a degenerate
/// plane or non-finite input.
template <Real T>
[[nodiscard]] inline T signed_distance(const Vec3<T>& p, const Plane3<T>& plane) noexcept {
  if (!is_finite(p)) return std::numeric_limits<T>::quiet_NaN();
  return signed_distance(plane, p);
}

/// Distance from p to the plane; param_b = (s, t) in plane_frame(plane).
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, Vec2<T>> distance(const Vec3<T>& p,
                                                               const Plane3<T>& plane) noexcept {
  if (!is_finite(p)) return non_finite_distance<T, 3, NoParam, Vec2<T>>();
  const std::optional<PlaneFrame3<T>> f = plane_frame(plane);
  if (!f) return non_finite_distance<T, 3, NoParam, Vec2<T>>();
  const T sd = signed_distance(plane, p);
  const Vec3<T> c = p - sd * f->normal;
  const T ad = sd < T(0) ? -sd : sd;
  // The distance is |sd| directly (more accurate than |p - c| when p is far from the origin).
  return {ad, ad * ad, {p, c}, NoParam{}, to_plane(*f, c), true};
}

/// The swapped query: closest[0] and param_a belong to the plane.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, NoParam> distance(const Plane3<T>& plane,
                                                               const Vec3<T>& p) noexcept {
  return swapped(distance(p, plane));
}

}  // namespace locus
