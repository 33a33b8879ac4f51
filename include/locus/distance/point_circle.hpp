// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a circle (2D and 3D) or a disk (3D); rows dist2.pt-quadratic
// (circle part) and dist3.pt-circle-disk; book sections 6.2.1 and 10.3.4 (figures 10.16-10.19).
//
// distance(p, Circle2) and distance(p, Circle3) return Distance<T, N, NoParam, T>: param_b is the
// circle's angle (point_at(circle, angle), primitives/circle.hpp: counter-clockwise from +x in
// 2D, from the in-plane axis u towards v in 3D), in (-pi, pi]. The circle is the CURVE: a point
// inside is at distance radius - |p - center| from it.
// distance(p, Disk3) returns Distance<T, 3, NoParam, Vec2<T>>: param_b = (s, t) with
// point_at(disk, st) = center + s u + t v, s^2 + t^2 <= radius^2. The disk is FILLED.
// The swapped overloads swap the results.
//
// Method (3D, figures 10.16-10.19): project p onto the circle's plane, q = p - ((p - c) . n) n
// with unit n; the in-plane offset d = q - c. Disk: if |d| <= r, the answer is q; otherwise, and
// always for the circle, it is c + r d / |d|.
//
// Degenerate input: a point on the circle's axis (d = 0; the center in 2D) is equidistant from
// the whole circle: the point at angle 0 is returned with unique = false. A zero radius is the
// point center (angle 0, unique = true). A negative radius, a zero normal (no plane), and NaN or
// infinite values give non_finite_distance() (result.hpp). Cost: O(1), one atan2.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/circle.hpp>

#include <cmath>

namespace locus {

/// Distance from p to the circle (the curve) in the plane; param_b is the angle.
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, T> distance(const Vec2<T>& p,
                                                         const Circle2<T>& c) noexcept {
  if (!is_finite(p) || !is_finite(c.center) || !is_finite(c.radius) || c.radius < T(0))
    return non_finite_distance<T, 2, NoParam, T>();
  const Normalized<T, 2> d = normalize_with_length(p - c.center);
  if (d.length == T(0)) {
    // The center: every point of the circle is at distance radius.
    return detail::make_distance(p, point_at(c, T(0)), NoParam{}, T(0), !(c.radius > T(0)));
  }
  const T angle = std::atan2(d.dir.y, d.dir.x);
  return detail::make_distance(p, c.center + c.radius * d.dir, NoParam{}, angle, true);
}

namespace detail {
/// Unit normal, in-plane axes and the in-plane offset of p's projection, for Circle3 / Disk3.
template <Real T>
struct CircleFrame3 {
  CircleAxes<T> axes;
  T s, t;  // in-plane coordinates of p's projection relative to the center
};
template <Real T>
[[nodiscard]] inline CircleFrame3<T> circle_frame(const Vec3<T>& p, const Vec3<T>& center,
                                                  const Vec3<T>& normal) noexcept {
  const CircleAxes<T> ax = circle_axes_of_normal(normal);
  const Vec3<T> d = p - center;
  return {ax, dot(d, ax.u), dot(d, ax.v)};
}
template <Real T>
[[nodiscard]] constexpr bool circle3_ok(const Vec3<T>& p, const Vec3<T>& center,
                                        const Vec3<T>& normal, T radius) noexcept {
  return is_finite(p) && is_finite(center) && is_finite(normal) && is_finite(radius) &&
         radius >= T(0) && !(normal == Vec3<T>{});
}
}  // namespace detail

/// Distance from p to the circle (the curve) in 3D; param_b is the angle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, T> distance(const Vec3<T>& p,
                                                         const Circle3<T>& c) noexcept {
  if (!detail::circle3_ok(p, c.center, c.normal, c.radius))
    return non_finite_distance<T, 3, NoParam, T>();
  const detail::CircleFrame3<T> f = detail::circle_frame(p, c.center, c.normal);
  if (f.axes.u == Vec3<T>{}) return non_finite_distance<T, 3, NoParam, T>();  // normal underflow
  const Normalized<T, 2> d = normalize_with_length(Vec2<T>{f.s, f.t});
  if (d.length == T(0))
    return detail::make_distance(p, point_at(c, T(0)), NoParam{}, T(0), !(c.radius > T(0)));
  const T angle = std::atan2(d.dir.y, d.dir.x);
  const Vec3<T> q = c.center + (c.radius * d.dir.x) * f.axes.u + (c.radius * d.dir.y) * f.axes.v;
  return detail::make_distance(p, q, NoParam{}, angle, true);
}

/// Distance from p to the filled disk in 3D; param_b = (s, t) in the disk's plane axes.
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, Vec2<T>> distance(const Vec3<T>& p,
                                                               const Disk3<T>& disk) noexcept {
  if (!detail::circle3_ok(p, disk.center, disk.normal, disk.radius))
    return non_finite_distance<T, 3, NoParam, Vec2<T>>();
  const detail::CircleFrame3<T> f = detail::circle_frame(p, disk.center, disk.normal);
  if (f.axes.u == Vec3<T>{}) return non_finite_distance<T, 3, NoParam, Vec2<T>>();
  Vec2<T> st{f.s, f.t};
  const Normalized<T, 2> d = normalize_with_length(st);
  if (d.length > disk.radius) st = disk.radius * d.dir;
  return detail::make_distance(p, point_at(disk, st), NoParam{}, st, true);
}

/// The swapped query: closest[0] and param_a belong to the circle.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, NoParam> distance(const Circle2<T>& c,
                                                         const Vec2<T>& p) noexcept {
  return swapped(distance(p, c));
}
/// The swapped query: closest[0] and param_a belong to the circle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, NoParam> distance(const Circle3<T>& c,
                                                         const Vec3<T>& p) noexcept {
  return swapped(distance(p, c));
}
/// The swapped query: closest[0] and param_a belong to the disk.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, NoParam> distance(const Disk3<T>& d,
                                                               const Vec3<T>& p) noexcept {
  return swapped(distance(p, d));
}

}  // namespace locus
