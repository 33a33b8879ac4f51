// SPDX-License-Identifier: BSL-1.0
#pragma once
// Circles in the plane, circles and disks in 3D; row prim2.quadratic (circle part); book
// section 5.5.1, figure 5.15 (distance/implicit and parametric forms), and 9.2.3 (2D objects in
// a plane of 3D).
//
// Circle2<T> {center, radius}: implicit form |X - center|^2 - radius^2 = 0, evaluated (rounded)
// by evaluate(); positive outside, negative inside. Parametric form (fig 5.15):
// point_at(circle, angle) = center + radius (cos angle, sin angle), angles in radians measured
// counter-clockwise from the +x axis.
//
// Circle3<T> {center, normal, radius} is the circle of that radius in the plane through center
// perpendicular to normal; Disk3<T> has the same fields and denotes the filled disk. The normal
// need not be unit length. in_plane_axes(circle) returns unit u, v with (u, v, n / |n|) a
// right-handed orthonormal frame (u x v = n / |n|), a function of the normal's direction only;
// point_at(circle3, angle) = center + radius (cos angle u + sin angle v), so the circle runs
// counter-clockwise seen from the side the normal points to. point_at(disk3, {s, t}) =
// center + s u + t v (planar coordinates, the disk is s^2 + t^2 <= radius^2).
//
// Degenerate input: a zero or negative radius is degenerate (is_degenerate(); a zero radius
// acts as the point center). A zero or non-finite normal has no plane: in_plane_axes() returns
// zero vectors, so point_at() returns the center. Non-finite values propagate.
// Cost O(1), no allocation; point_at calls cos and sin.

#include <locus/core/basis.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>

namespace locus {

/// The circle |X - center| = radius in the plane.
template <Real T>
struct Circle2 {
  Vec2<T> center;
  T radius;
};

/// The circle of the given radius about center in the plane perpendicular to normal (3D).
template <Real T>
struct Circle3 {
  Vec3<T> center;
  Vec3<T> normal;
  T radius;
};

/// The filled disk of the given radius about center in the plane perpendicular to normal (3D).
template <Real T>
struct Disk3 {
  Vec3<T> center;
  Vec3<T> normal;
  T radius;
};

using Circle2f = Circle2<float>;
using Circle2d = Circle2<double>;
using Circle3f = Circle3<float>;
using Circle3d = Circle3<double>;
using Disk3f = Disk3<float>;
using Disk3d = Disk3<double>;

/// Two unit vectors u, v spanning the plane of a Circle3 / Disk3, with u x v = unit normal.
template <Real T>
struct CircleAxes {
  Vec3<T> u;
  Vec3<T> v;
};

namespace detail {
/// Right-handed in-plane axes of a normal: u x v = n / |n| (core/basis.hpp's completion, which
/// is accurate to a few ulps for every direction); zero vectors for a zero or non-finite n.
template <Real T>
[[nodiscard]] inline CircleAxes<T> circle_axes_of_normal(const Vec3<T>& n) noexcept {
  const OrthonormalBasis<T, 3> b = complete_basis(n);
  if (b.status != Status::ok) return {Vec3<T>{}, Vec3<T>{}};
  return {b.axis[1], b.axis[2]};
}
}  // namespace detail

/// The in-plane axes (u, v) used by point_at(Circle3) (zero vectors for a zero normal).
template <Real T>
[[nodiscard]] inline CircleAxes<T> in_plane_axes(const Circle3<T>& c) noexcept {
  return detail::circle_axes_of_normal(c.normal);
}
/// The in-plane axes (u, v) used by point_at(Disk3) (zero vectors for a zero normal).
template <Real T>
[[nodiscard]] inline CircleAxes<T> in_plane_axes(const Disk3<T>& d) noexcept {
  return detail::circle_axes_of_normal(d.normal);
}

/// center + radius (cos angle, sin angle).
template <Real T>
[[nodiscard]] inline Vec2<T> point_at(const Circle2<T>& c, T angle) noexcept {
  return c.center + c.radius * Vec2<T>{std::cos(angle), std::sin(angle)};
}

/// center + radius (cos angle u + sin angle v) with (u, v) = in_plane_axes().
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const Circle3<T>& c, T angle) noexcept {
  const CircleAxes<T> b = in_plane_axes(c);
  return c.center + (c.radius * std::cos(angle)) * b.u + (c.radius * std::sin(angle)) * b.v;
}

/// center + s u + t v with st = (s, t) and (u, v) = in_plane_axes(); in the disk when
/// s^2 + t^2 <= radius^2.
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const Disk3<T>& d, const Vec2<T>& st) noexcept {
  const CircleAxes<T> b = in_plane_axes(d);
  return d.center + st.x * b.u + st.y * b.v;
}

/// |p - center|^2 - radius^2 (rounded): negative inside, zero on, positive outside.
template <Real T>
[[nodiscard]] constexpr T evaluate(const Circle2<T>& c, const Vec2<T>& p) noexcept {
  return sqr_length(p - c.center) - c.radius * c.radius;
}

/// pi r^2 (the area of the disk bounded by the circle).
template <Real T>
[[nodiscard]] constexpr T area(const Circle2<T>& c) noexcept {
  return pi_v<T> * c.radius * c.radius;
}
/// pi r^2.
template <Real T>
[[nodiscard]] constexpr T area(const Disk3<T>& d) noexcept {
  return pi_v<T> * d.radius * d.radius;
}
/// 2 pi r.
template <Real T>
[[nodiscard]] constexpr T circumference(const Circle2<T>& c) noexcept {
  return T(2) * pi_v<T> * c.radius;
}
/// 2 pi r.
template <Real T>
[[nodiscard]] constexpr T circumference(const Circle3<T>& c) noexcept {
  return T(2) * pi_v<T> * c.radius;
}

/// True when the radius is not positive or a value is not finite.
template <Real T>
[[nodiscard]] constexpr bool is_degenerate(const Circle2<T>& c) noexcept {
  return !(c.radius > T(0)) || !is_finite(c.radius) || !is_finite(c.center);
}
/// True when the radius is not positive, the normal is zero, or a value is not finite.
template <Real T>
[[nodiscard]] constexpr bool is_degenerate(const Circle3<T>& c) noexcept {
  return !(c.radius > T(0)) || !is_finite(c.radius) || !is_finite(c.center) ||
         !is_finite(c.normal) || c.normal == Vec3<T>{};
}
/// True when the radius is not positive, the normal is zero, or a value is not finite.
template <Real T>
[[nodiscard]] constexpr bool is_degenerate(const Disk3<T>& d) noexcept {
  return is_degenerate(Circle3<T>{d.center, d.normal, d.radius});
}

}  // namespace locus
