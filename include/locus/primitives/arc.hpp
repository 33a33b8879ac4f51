// SPDX-License-Identifier: BSL-1.0
#pragma once
// Circular arcs in the plane; row prim2.quadratic (arcs); book section 5.5.1 (arcs of circles,
// parametrised by an angle interval).
//
// Arc2<T> {circle, start, sweep}: the points point_at(circle, a) for angles a in
// [start, start + sweep], radians, counter-clockwise, 0 <= sweep <= 2 pi (sweep = 2 pi is the
// whole circle; sweep = 0 a single point). point_at(arc, angle) = center + radius (cos, sin)
// at that angle, the same parametrisation as Circle2. start is any real angle; nothing needs it
// normalised.
//
// Membership: contains_angle(arc, a) tests a modulo 2 pi against [start, start + sweep];
// contains_direction(arc, p) tests whether the ray from the center through p crosses the arc,
// by perp-dot signs against the start and end directions (for p near an end direction the
// answer follows the rounded cos/sin of the end angles). Both are rounded tests on rounded
// angles: no exact predicate applies to transcendental end points.
//
// arc_between(circle, p0, p1) is the counter-clockwise arc from the direction of p0 to the
// direction of p1 (as seen from the center); p0 == p1 in direction gives sweep 0.
//
// Degenerate input: is_degenerate() is true for a radius <= 0, a sweep outside [0, 2 pi], or a
// non-finite value; contains_* return false for NaN input; contains_direction(arc, center) is
// false (no direction). Cost O(1) with a few trig calls, no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/circle.hpp>

#include <cmath>

namespace locus {

/// The arc of `circle` through the angles [start, start + sweep], counter-clockwise.
template <Real T>
struct Arc2 {
  Circle2<T> circle;
  T start;
  T sweep;
};

using Arc2f = Arc2<float>;
using Arc2d = Arc2<double>;

namespace detail {
/// True when `angle` modulo 2 pi lies in [start, start + sweep]; NaN gives false.
template <Real T>
[[nodiscard]] inline bool angle_in_sweep(T angle, T start, T sweep) noexcept {
  using C = compute_t<T>;
  const C two_pi = C(2) * pi_v<C>;
  if (!(sweep >= T(0))) return false;
  if (static_cast<C>(sweep) >= two_pi) return is_finite(angle) && is_finite(start);
  C d = std::fmod(static_cast<C>(angle) - static_cast<C>(start), two_pi);
  if (d != d) return false;
  if (d < C(0)) d += two_pi;
  return d <= static_cast<C>(sweep) || d >= two_pi;  // d == 2 pi after the shift is the start
}
}  // namespace detail

/// center + radius (cos angle, sin angle), as for the full circle.
template <Real T>
[[nodiscard]] inline Vec2<T> point_at(const Arc2<T>& arc, T angle) noexcept {
  return point_at(arc.circle, angle);
}

/// start + sweep.
template <Real T>
[[nodiscard]] constexpr T end_angle(const Arc2<T>& arc) noexcept {
  return arc.start + arc.sweep;
}

/// The point at the start angle.
template <Real T>
[[nodiscard]] inline Vec2<T> start_point(const Arc2<T>& arc) noexcept {
  return point_at(arc.circle, arc.start);
}

/// The point at the end angle.
template <Real T>
[[nodiscard]] inline Vec2<T> end_point(const Arc2<T>& arc) noexcept {
  return point_at(arc.circle, end_angle(arc));
}

/// radius * sweep.
template <Real T>
[[nodiscard]] constexpr T length(const Arc2<T>& arc) noexcept {
  return arc.circle.radius * arc.sweep;
}

/// True for a radius <= 0, a sweep outside [0, 2 pi], or a non-finite value.
template <Real T>
[[nodiscard]] constexpr bool is_degenerate(const Arc2<T>& arc) noexcept {
  return is_degenerate(arc.circle) || !is_finite(arc.start) || !(arc.sweep >= T(0)) ||
         !(arc.sweep <= T(2) * pi_v<T>);
}

/// True when angle modulo 2 pi lies in [start, start + sweep].
template <Real T>
[[nodiscard]] inline bool contains_angle(const Arc2<T>& arc, T angle) noexcept {
  return detail::angle_in_sweep(angle, arc.start, arc.sweep);
}

/// True when the ray from the center through p meets the arc (p need not be on the circle).
template <Real T>
[[nodiscard]] inline bool contains_direction(const Arc2<T>& arc, const Vec2<T>& p) noexcept {
  const Vec2<T> d = p - arc.circle.center;
  if (!is_finite(d) || d == Vec2<T>{} || !(arc.sweep >= T(0)) || !is_finite(arc.start))
    return false;
  if (arc.sweep >= T(2) * pi_v<T>) return true;
  const Vec2<T> s{std::cos(arc.start), std::sin(arc.start)};
  const T e_angle = end_angle(arc);
  const Vec2<T> e{std::cos(e_angle), std::sin(e_angle)};
  if (arc.sweep <= pi_v<T>) {
    // A convex angular sector: counter-clockwise of s and clockwise of e.
    if (perp_dot(s, d) < T(0) || perp_dot(d, e) < T(0)) return false;
    return dot(d, s) > T(0) || dot(d, e) > T(0) || perp_dot(s, d) > T(0);
  }
  // Reflex sector: outside exactly when strictly inside the complementary convex sector (e, s).
  return !(perp_dot(e, d) > T(0) && perp_dot(d, s) > T(0));
}

/// The counter-clockwise arc of `circle` from the direction of p0 to the direction of p1
/// (both seen from the center). Coincident directions give sweep 0; a point at the center
/// contributes angle 0.
template <Real T>
[[nodiscard]] inline Arc2<T> arc_between(const Circle2<T>& circle, const Vec2<T>& p0,
                                         const Vec2<T>& p1) noexcept {
  using C = compute_t<T>;
  const Vec2<T> d0 = p0 - circle.center, d1 = p1 - circle.center;
  const C a0 = std::atan2(static_cast<C>(d0.y), static_cast<C>(d0.x));
  const C a1 = std::atan2(static_cast<C>(d1.y), static_cast<C>(d1.x));
  C sweep = a1 - a0;
  if (sweep < C(0)) sweep += C(2) * pi_v<C>;
  return {circle, static_cast<T>(a0), static_cast<T>(sweep)};
}

}  // namespace locus
