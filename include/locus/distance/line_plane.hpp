// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a line, ray or segment and a plane in 3D; row dist3.misc (linear-plane part);
// book section 10.3.1 (the point-plane building block, figures 10.6, 10.7) and the parallel /
// crossing analysis of section 11.1.
//
// distance(linear, Plane3) returns Distance<T, 3, T, Vec2<T>>: param_a is the linear parameter
// of closest[0] (Line: t in R, Ray: t >= 0, Segment: t in [0, 1], as point_at), param_b the
// coordinates (s, t) of closest[1] in plane_frame(plane), as distance(point, plane) does
// (point_plane.hpp). distance(Plane3, linear) is the swapped result. The normal need not be unit.
//
// Method and decisions (all exact, core/plane_side.hpp, on the data as given): the component
// meets the plane exactly when intersection() of intersection/line_plane.hpp (ray_plane,
// segment_plane) says so; then distance = 0 and closest[0] = closest[1] = the (rounded) crossing
// point, or the origin / p0 when the component lies in the plane. Otherwise the nearest point is
// the origin (a line or ray parallel to the plane, or a ray leaving it) or the segment end point
// nearer the plane, chosen by the exact sign of dot(normal, p0 - p1); its distance is that of
// point_plane.hpp (|signed distance|, rounded).
// unique = false when infinitely many closest pairs exist: a component of non-zero direction
// parallel to the plane (exact sign of dot(normal, direction) = 0), inside the plane or not.
//
// Degenerate input: a zero direction (zero-length segment) acts as its point (t = 0, unique). A
// zero normal (no plane) and NaN or infinite values give non_finite_distance() (result.hpp).
// Cost: O(1): a few exact-sign filters, one normalisation; no allocation.

#include <locus/core/exact_sum.hpp>
#include <locus/core/plane_side.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/point_plane.hpp>
#include <locus/distance/result.hpp>
#include <locus/intersection/line_plane.hpp>
#include <locus/intersection/ray_plane.hpp>
#include <locus/intersection/segment_plane.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <optional>

namespace locus {

namespace detail {

/// Exact sign of dot(n, a - b) = sum_k n_k a_k - n_k b_k (no rounded difference).
template <Real T>
[[nodiscard]] inline Sign sign_of_dot_diff(const Vec3<T>& n, const Vec3<T>& a,
                                           const Vec3<T>& b) noexcept {
  ExactMonomial m[6];
  for (int k = 0; k < 3; ++k) {
    m[2 * k] = {1, 0, 2, {double(n[k]), double(a[k]), 0, 0}};
    m[2 * k + 1] = {-1, 0, 2, {double(n[k]), double(b[k]), 0, 0}};
  }
  return static_cast<Sign>(exact_sign_of_sum(m));
}

/// The shared answer: the nearest point of the component is at parameter t (point x).
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> linear_plane_at(const Vec3<T>& x, T t,
                                                                const Plane3<T>& pl,
                                                                bool unique) noexcept {
  const Distance<T, 3, NoParam, Vec2<T>> d = distance(x, pl);
  return {d.distance, d.sqr_distance, {x, d.closest[1]}, t, d.param_b, unique};
}

/// A common point of the component and the plane, as a zero distance.
template <Real T, class I>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> linear_plane_meet(const I& in,
                                                                  const Plane3<T>& pl) noexcept {
  const std::optional<PlaneFrame3<T>> f = plane_frame(pl);
  const Vec3<T> p = in.point[0];
  return {T(0), T(0), {p, p}, in.param_a[0], to_plane(*f, p), in.kind == Kind::point};
}

template <Real T>
[[nodiscard]] inline bool linear_plane_ok(const Vec3<T>& a, const Vec3<T>& b,
                                          const Plane3<T>& pl) noexcept {
  return is_finite(a) && is_finite(b) && !is_degenerate(pl) && plane_frame(pl).has_value();
}

}  // namespace detail

/// Distance between a line and a plane: 0 unless the line is parallel to the plane (then
/// unique = false and closest[0] is the origin).
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> distance(const Line3<T>& l,
                                                         const Plane3<T>& pl) noexcept {
  if (!detail::linear_plane_ok(l.origin, l.direction, pl))
    return non_finite_distance<T, 3, T, Vec2<T>>();
  const auto in = intersection(l, pl);
  if (in.kind != Kind::empty) return detail::linear_plane_meet(in, pl);
  return detail::linear_plane_at(l.origin, T(0), pl, l.direction == Vec3<T>{});
}

/// Distance between a ray and a plane; param_a = t >= 0.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> distance(const Ray3<T>& r,
                                                         const Plane3<T>& pl) noexcept {
  if (!detail::linear_plane_ok(r.origin, r.direction, pl))
    return non_finite_distance<T, 3, T, Vec2<T>>();
  const auto in = intersection(r, pl);
  if (in.kind != Kind::empty) return detail::linear_plane_meet(in, pl);
  // No common point: the ray leaves the plane (origin nearest) or runs parallel to it.
  const bool parallel = sign_of_dot(pl.normal, r.direction) == Sign::zero;
  return detail::linear_plane_at(r.origin, T(0), pl, !parallel || r.direction == Vec3<T>{});
}

/// Distance between a segment and a plane; param_a = t in [0, 1].
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> distance(const Segment3<T>& s,
                                                         const Plane3<T>& pl) noexcept {
  if (!detail::linear_plane_ok(s.p0, s.p1, pl)) return non_finite_distance<T, 3, T, Vec2<T>>();
  const auto in = intersection(s, pl);
  if (in.kind != Kind::empty) return detail::linear_plane_meet(in, pl);
  // Both end points strictly on one side: p1 is nearer when side * dot(n, p0 - p1) > 0.
  const int side = static_cast<int>(side_of_plane(pl.normal, pl.constant, s.p0));
  const int diff = static_cast<int>(detail::sign_of_dot_diff(pl.normal, s.p0, s.p1));
  if (side * diff > 0) return detail::linear_plane_at(s.p1, T(1), pl, true);
  return detail::linear_plane_at(s.p0, T(0), pl, diff != 0 || s.p0 == s.p1);
}

/// The swapped query: closest[0] and param_a belong to the plane.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, T> distance(const Plane3<T>& pl,
                                                         const Line3<T>& l) noexcept {
  return swapped(distance(l, pl));
}
/// The swapped query: closest[0] and param_a belong to the plane.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, T> distance(const Plane3<T>& pl,
                                                         const Ray3<T>& r) noexcept {
  return swapped(distance(r, pl));
}
/// The swapped query: closest[0] and param_a belong to the plane.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, T> distance(const Plane3<T>& pl,
                                                         const Segment3<T>& s) noexcept {
  return swapped(distance(s, pl));
}

}  // namespace locus
