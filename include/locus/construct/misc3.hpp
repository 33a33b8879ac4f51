// SPDX-License-Identifier: BSL-1.0
#pragma once
// Chapter 12 of the book ("Miscellaneous 3D problems") as one API: projections, angles and plane
// constructions; rows misc3.projection, misc3.angles, misc3.planes; sections 12.1-12.5,
// figures 12.1-12.10.
//
// Projections (12.1): project_point(p, plane) is the orthogonal projection of a point onto the
// plane (figure 12.1), project_vector(v, plane) the part of a vector parallel to the plane,
// v - (v.n / n.n) n (figure 12.2), project_vector(u, v) the projection of u onto the direction v,
// (u.v / v.v) v (figure 12.3). Planes are Plane3 {normal, constant} (primitives/plane.hpp); the
// normal need not be unit length.
// Angles (12.2-12.4), in radians, from atan2 of normalised vectors (never acos of a rounded
// cosine, so accurate near 0 and pi; core/products.hpp):
//   angle_between(Line3, Plane3) in [-pi/2, pi/2]: pi/2 minus the angle between the direction and
//     the normal (figure 12.4); positive when the direction points to the normal's side;
//   angle_between(Plane3, Plane3) in [0, pi]: the angle between the normals (figure 12.5);
//   angle_between(Line3, Line3) in [0, pi]: the angle between the directions (figure 12.9);
//     reversing one line gives pi minus it (figure 12.10);
//   acute_angle(a, b) in [0, pi/2]: the same ignoring orientation (min(angle, pi - angle), or
//     |angle| for a line and a plane).
// Planes (12.5): plane_normal_to_line(line, p) = { X : d.(X - p) = 0 }, normal d, constant d.p
// (figures 12.6, 12.7); plane_through_points(a, b, c) has normal (b - a) x (c - a), so a, b, c run
// counter-clockwise seen from its positive side (figure 12.8). Both return PlaneResult {status,
// plane}; the constant d.p is rounded (exact for small integer input).
// Degenerate input: an angle involving a zero direction or normal, or NaN/Inf input, is NaN.
// Projection onto a zero vector is the zero vector; onto a plane with a zero normal the input
// itself (as plane.hpp's project). Plane constructions: non_finite_input for NaN/Inf input,
// degenerate_input for a zero direction or three collinear or coincident points (decided
// EXACTLY, plane_through of plane.hpp). Cost: O(1), no allocation.

#include <locus/core/products.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/plane.hpp>

#include <cmath>
#include <limits>
#include <optional>

namespace locus {

/// Orthogonal projection of the point p onto the plane (figure 12.1); p for a degenerate plane.
template <Real T>
[[nodiscard]] inline Vec3<T> project_point(const Vec3<T>& p, const Plane3<T>& pl) noexcept {
  return project(pl, p);
}

/// The part of the vector v parallel to the plane, v - (v.n / n.n) n (figure 12.2); v itself
/// for a zero normal.
template <Real T>
[[nodiscard]] inline Vec3<T> project_vector(const Vec3<T>& v, const Plane3<T>& pl) noexcept {
  return reject_from(v, pl.normal);
}

/// The projection of u onto the direction v, (u.v / v.v) v (figure 12.3); zero for v = 0.
template <Real T>
[[nodiscard]] inline Vec3<T> project_vector(const Vec3<T>& u, const Vec3<T>& v) noexcept {
  return project_onto(u, v);
}

namespace detail::misc3 {

template <Real T>
[[nodiscard]] inline bool usable(const Vec3<T>& v) noexcept {
  return is_finite(v) && !(v == Vec3<T>{});
}

/// The angle between the directions u and v in [0, pi]; NaN for a zero or non-finite one.
template <Real T>
[[nodiscard]] inline T directions(const Vec3<T>& u, const Vec3<T>& v) noexcept {
  if (!usable(u) || !usable(v)) return std::numeric_limits<T>::quiet_NaN();
  return angle_between(u, v);
}

/// min(a, pi - a) for a in [0, pi].
template <Real T>
[[nodiscard]] inline T acute(T a) noexcept {
  const T other = pi_v<T> - a;
  return other < a ? other : a;
}

}  // namespace detail::misc3

/// Angle between a line and a plane in [-pi/2, pi/2] (figure 12.4): positive when the direction
/// points to the side the normal points to; NaN for a zero direction or normal.
template <Real T>
[[nodiscard]] inline T angle_between(const Line3<T>& l, const Plane3<T>& pl) noexcept {
  if (!detail::misc3::usable(l.direction) || !detail::misc3::usable(pl.normal) ||
      !is_finite(l.origin) || !is_finite(pl.constant))
    return std::numeric_limits<T>::quiet_NaN();
  using C = compute_t<T>;
  const Vec3<C> d = normalize_with_length(vec_cast<C>(l.direction)).dir;
  const Vec3<C> n = normalize_with_length(vec_cast<C>(pl.normal)).dir;
  // sin = d.n, cos = |d x n|: accurate at both ends of the range.
  return static_cast<T>(std::atan2(dot(d, n), length(cross(d, n))));
}

/// The same angle, arguments swapped.
template <Real T>
[[nodiscard]] inline T angle_between(const Plane3<T>& pl, const Line3<T>& l) noexcept {
  return angle_between(l, pl);
}

/// Angle between the normals of two planes in [0, pi] (figure 12.5); NaN for a zero normal.
template <Real T>
[[nodiscard]] inline T angle_between(const Plane3<T>& a, const Plane3<T>& b) noexcept {
  if (!is_finite(a.constant) || !is_finite(b.constant)) return std::numeric_limits<T>::quiet_NaN();
  return detail::misc3::directions(a.normal, b.normal);
}

/// Angle between the directions of two lines in [0, pi] (figures 12.9, 12.10); NaN for a zero
/// direction. The lines need not meet.
template <Real T>
[[nodiscard]] inline T angle_between(const Line3<T>& a, const Line3<T>& b) noexcept {
  if (!is_finite(a.origin) || !is_finite(b.origin)) return std::numeric_limits<T>::quiet_NaN();
  return detail::misc3::directions(a.direction, b.direction);
}

/// The unoriented angle between two lines in [0, pi/2].
template <Real T>
[[nodiscard]] inline T acute_angle(const Line3<T>& a, const Line3<T>& b) noexcept {
  return detail::misc3::acute(angle_between(a, b));
}
/// The unoriented (dihedral) angle between two planes in [0, pi/2].
template <Real T>
[[nodiscard]] inline T acute_angle(const Plane3<T>& a, const Plane3<T>& b) noexcept {
  return detail::misc3::acute(angle_between(a, b));
}
/// The unoriented angle between a line and a plane in [0, pi/2].
template <Real T>
[[nodiscard]] inline T acute_angle(const Line3<T>& l, const Plane3<T>& pl) noexcept {
  return std::abs(angle_between(l, pl));
}
/// The unoriented angle between a plane and a line in [0, pi/2].
template <Real T>
[[nodiscard]] inline T acute_angle(const Plane3<T>& pl, const Line3<T>& l) noexcept {
  return std::abs(angle_between(l, pl));
}

/// A constructed plane with the status of the construction (plane valid only when ok).
template <Real T>
struct PlaneResult {
  Status status = Status::empty_input;
  Plane3<T> plane{};
};

/// The plane through p normal to the line (figures 12.6, 12.7): normal = the line's direction,
/// constant = direction . p.
template <Real T>
[[nodiscard]] inline PlaneResult<T> plane_normal_to_line(const Line3<T>& l,
                                                         const Vec3<T>& p) noexcept {
  if (!is_finite(l.direction) || !is_finite(l.origin) || !is_finite(p))
    return {Status::non_finite_input, {}};
  if (l.direction == Vec3<T>{}) return {Status::degenerate_input, {}};
  const Plane3<T> pl = plane_from_point_normal(p, l.direction);
  if (!is_finite(pl.constant)) return {Status::non_finite_input, {}};  // overflow
  return {Status::ok, pl};
}

/// The plane through three points (figure 12.8), normal (b - a) x (c - a).
template <Real T>
[[nodiscard]] inline PlaneResult<T> plane_through_points(const Vec3<T>& a, const Vec3<T>& b,
                                                         const Vec3<T>& c) noexcept {
  if (!is_finite(a) || !is_finite(b) || !is_finite(c)) return {Status::non_finite_input, {}};
  const std::optional<Plane3<T>> pl = plane_through(a, b, c);
  if (!pl) return {Status::degenerate_input, {}};
  return {Status::ok, *pl};
}

}  // namespace locus
