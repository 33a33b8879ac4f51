// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a line, ray or segment and a filled disk in 3D; row dist3.misc (linear-disk
// part); book section 10.3.4 (point-circle and point-disk, figures 10.16-10.19) with the
// line-circle distance of line_circle.hpp.
//
// distance(linear, Disk3) returns Distance<T, 3, T, Vec2<T>>: param_a is the linear parameter of
// closest[0] (Line: t in R, Ray: t >= 0, Segment: t in [0, 1], as point_at), param_b the disk
// coordinates (s, t) of closest[1] = point_at(disk, st) = center + s u + t v (in_plane_axes,
// s^2 + t^2 <= radius^2). The disk is FILLED. distance(Disk3, linear) is the swapped result.
//
// Method: if the component meets the disk (intersection() of intersection/line_disk.hpp,
// ray_disk, segment_disk: exact side-of-plane decisions, the crossing point rounded) the
// distance is 0 there. Otherwise the closest disk point is on the rim unless the component's
// nearest point is an end point whose projection falls inside the disk, so the answer is the
// smaller of the component-circle distance (line_circle.hpp, a quartic with global minimum) and
// the end points' point-disk distances (point_circle.hpp). Derivation: docs/notes/distance.md.
// unique = false when infinitely many closest pairs exist: the component lies in the disk's plane
// across the disk (the common chord), or is parallel to the plane (exact sign of
// dot(normal, direction) = 0) and its projection crosses the open disk along a piece of positive
// length (then the middle of that piece is returned; the piece is computed in rounded frame
// coordinates, so a component within rounding of tangency may go either way), or the
// line-circle answer is not unique and wins.
//
// Degenerate input: a zero direction (zero-length segment) acts as its point; radius 0 is the
// point center. A negative radius, a zero normal, and NaN or infinite values give
// non_finite_distance() (result.hpp). Cost: O(1): one quartic, a few exact signs; no allocation.

#include <locus/core/plane_side.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/line_circle.hpp>
#include <locus/distance/line_plane.hpp>
#include <locus/distance/point_circle.hpp>
#include <locus/distance/result.hpp>
#include <locus/intersection/line_disk.hpp>
#include <locus/intersection/ray_disk.hpp>
#include <locus/intersection/segment_disk.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <algorithm>
#include <cmath>

namespace locus {

namespace detail {

template <Real T, class Lin>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> linear_disk(const Lin& lin,
                                                            const Disk3<T>& d) noexcept {
  using R = Distance<T, 3, T, Vec2<T>>;
  if (!finite_input(lin) || !circle3_ok(d.center, d.center, d.normal, d.radius))
    return non_finite_distance<T, 3, T, Vec2<T>>();
  const CircleAxes<T> ax = in_plane_axes(d);
  if (ax.u == Vec3<T>{}) return non_finite_distance<T, 3, T, Vec2<T>>();  // normal underflow
  const auto in = intersection(lin, d);
  if (in.kind != Kind::empty) {
    const Vec3<T> p = in.point[0];
    return {T(0), T(0), {p, p}, in.param_a[0], in.param_b[0], in.kind == Kind::point};
  }
  const LinearView<T, 3> v = view(lin);
  // A direction parallel to the plane whose projection crosses the open disk: a whole piece of
  // the component is at the same (minimal) distance from the disk.
  const Sign along =
      v.bounded_hi ? sign_of_dot_diff(d.normal, v.end, v.origin) : sign_of_dot(d.normal, v.dir);
  if (along == Sign::zero && !(v.dir == Vec3<T>{})) {
    using C = compute_t<T>;
    const Vec3<C> w = vec_cast<C>(v.origin) - vec_cast<C>(d.center), m = vec_cast<C>(v.dir);
    const Vec3<C> u = vec_cast<C>(ax.u), vv = vec_cast<C>(ax.v);
    const C os = dot(w, u), ot = dot(w, vv), ms = dot(m, u), mt = dot(m, vv);
    const C r = static_cast<C>(d.radius);
    // |o + t m|^2 = r^2 in frame coordinates: a t^2 + 2 b t + c = 0, stable roots.
    const C a = ms * ms + mt * mt, b = os * ms + ot * mt;
    const C h = (os * mt - ot * ms) / std::sqrt(a);  // signed distance of the centre's projection
    const C disc = a * (r - h) * (r + h);
    if (a > C(0) && disc > C(0)) {
      const C q = -(b + std::copysign(std::sqrt(disc), b));
      const C c0 = (std::sqrt(os * os + ot * ot) - r) * (std::sqrt(os * os + ot * ot) + r);
      C t0 = q / a, t1 = q != C(0) ? c0 / q : -t0;
      if (t0 > t1) std::swap(t0, t1);
      if (v.bounded_lo) t0 = std::max(t0, C(0));
      if (v.bounded_hi) t1 = std::min(t1, C(1));
      if (t0 < t1) {
        const T tm = static_cast<T>(C(0.5) * (t0 + t1));
        const Vec3<T> p = v.at(tm);
        const Distance<T, 3, NoParam, Vec2<T>> pd = distance(p, d);
        return {pd.distance, pd.sqr_distance, {p, pd.closest[1]}, tm, pd.param_b, false};
      }
    }
  }
  // The rim: the component-circle distance, param_b converted from the angle.
  const Distance<T, 3, T, T> dc = distance(lin, Circle3<T>{d.center, d.normal, d.radius});
  const Vec2<T> st{d.radius * std::cos(dc.param_b), d.radius * std::sin(dc.param_b)};
  R best{dc.distance, dc.sqr_distance, dc.closest, dc.param_a, st, dc.unique};
  // End points whose projection may fall inside the disk.
  const auto try_end = [&](const Vec3<T>& p, T t) {
    const Distance<T, 3, NoParam, Vec2<T>> pd = distance(p, d);
    if (pd.sqr_distance < best.sqr_distance)
      best = {pd.distance, pd.sqr_distance, {p, pd.closest[1]}, t, pd.param_b, true};
  };
  if (v.bounded_lo) try_end(v.origin, T(0));
  if (v.bounded_hi) try_end(v.end, T(1));
  return best;
}

}  // namespace detail

/// Distance between a line and a filled disk in 3D; param_a = t, param_b = (s, t) in the disk.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> distance(const Line3<T>& l,
                                                         const Disk3<T>& d) noexcept {
  return detail::linear_disk(l, d);
}
/// Distance between a ray and a filled disk in 3D; param_a = t >= 0.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> distance(const Ray3<T>& r,
                                                         const Disk3<T>& d) noexcept {
  return detail::linear_disk(r, d);
}
/// Distance between a segment and a filled disk in 3D; param_a = t in [0, 1].
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> distance(const Segment3<T>& s,
                                                         const Disk3<T>& d) noexcept {
  return detail::linear_disk(s, d);
}

/// The swapped query: closest[0] and param_a belong to the disk.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, T> distance(const Disk3<T>& d,
                                                         const Line3<T>& l) noexcept {
  return swapped(distance(l, d));
}
/// The swapped query: closest[0] and param_a belong to the disk.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, T> distance(const Disk3<T>& d,
                                                         const Ray3<T>& r) noexcept {
  return swapped(distance(r, d));
}
/// The swapped query: closest[0] and param_a belong to the disk.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, T> distance(const Disk3<T>& d,
                                                         const Segment3<T>& s) noexcept {
  return swapped(distance(s, d));
}

}  // namespace locus
