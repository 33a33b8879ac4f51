// SPDX-License-Identifier: BSL-1.0
#pragma once
// Right circular cylinders, finite and infinite; row prim3.solids; book section 9.4.2 (the
// elliptic cylinder quadric, figure 9.19) and the cylinder representations of
// chapter 11 (figures 11.11, 11.12).
//
// Cylinder3<T> {axis, radius, height}: axis.origin is the CENTER of the cylinder and
// axis.direction its unit direction D (precondition). The solid is
//   { X : |X - C - dot(D, X - C) D| <= r, |dot(D, X - C)| <= h / 2 },
// i.e. the axis segment runs from C - (h/2) D to C + (h/2) D. height = +infinity is the
// infinite cylinder (documented representation; is_infinite() tests it).
// point_at(cyl, (theta, t)) = C + t D + r (cos theta u + sin theta v) is the lateral surface,
// t in [-h/2, h/2], with (u, v, D) the right-handed basis of plane.hpp's perpendicular_basis(D).
// signed_value(cyl, X) = |X - C|^2 - dot(D, X - C)^2 - r^2 is the implicit form of the infinite
// cylinder's lateral surface (negative inside).
//
// Measures: volume pi r^2 h, lateral_area 2 pi r h, surface_area 2 pi r h + 2 pi r^2 (the two
// caps), all +infinity for an infinite cylinder with r > 0. bounding_box() of a finite cylinder
// is the tight box of its two cap disks: C +- ((h/2)|D_k| + r sqrt(1 - D_k^2)).
//
// Degenerate input: r = 0 is a segment (volume 0), h = 0 a disk. A negative or NaN radius or
// height is invalid; the measures then return NaN. A non-unit D makes point_at and the
// measures wrong (not checked). Cost O(1); no allocation.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/plane.hpp>

#include <cmath>
#include <limits>

namespace locus {

/// Right circular cylinder centred at axis.origin along the unit axis.direction.
template <Real T>
struct Cylinder3 {
  Line3<T> axis;
  T radius;
  T height;
};

using Cylinder3f = Cylinder3<float>;
using Cylinder3d = Cylinder3<double>;

/// True for height = +infinity.
template <Real T>
[[nodiscard]] constexpr bool is_infinite(const Cylinder3<T>& c) noexcept {
  return c.height == std::numeric_limits<T>::infinity();
}

/// |X - C|^2 - dot(D, X - C)^2 - r^2 (infinite lateral surface; negative inside).
template <Real T>
[[nodiscard]] constexpr T signed_value(const Cylinder3<T>& c, const Vec3<T>& x) noexcept {
  const Vec3<T> d = x - c.axis.origin;
  const T h = dot(c.axis.direction, d);
  return sqr_length(d - h * c.axis.direction) - c.radius * c.radius;
}

/// C + t D + r (cos theta u + sin theta v) with tt = (theta, t).
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const Cylinder3<T>& c, const Vec2<T>& tt) noexcept {
  const auto b = perpendicular_basis(c.axis.direction);
  return c.axis.origin + tt.y * c.axis.direction +
         c.radius * (std::cos(tt.x) * b.u + std::sin(tt.x) * b.v);
}

namespace detail {
template <Real T>
[[nodiscard]] constexpr bool cylinder_invalid(const Cylinder3<T>& c) noexcept {
  return !(c.radius >= T(0)) || !(c.height >= T(0));
}
}  // namespace detail

/// pi r^2 h (+infinity when infinite and r > 0); NaN if invalid.
template <Real T>
[[nodiscard]] constexpr T volume(const Cylinder3<T>& c) noexcept {
  if (detail::cylinder_invalid(c)) return std::numeric_limits<T>::quiet_NaN();
  if (c.radius == T(0)) return T(0);
  return pi_v<T> * c.radius * c.radius * c.height;
}

/// 2 pi r h; NaN if invalid.
template <Real T>
[[nodiscard]] constexpr T lateral_area(const Cylinder3<T>& c) noexcept {
  if (detail::cylinder_invalid(c)) return std::numeric_limits<T>::quiet_NaN();
  if (c.radius == T(0)) return T(0);
  return T(2) * pi_v<T> * c.radius * c.height;
}

/// 2 pi r h + 2 pi r^2 (lateral surface and the two caps); NaN if invalid.
template <Real T>
[[nodiscard]] constexpr T surface_area(const Cylinder3<T>& c) noexcept {
  if (detail::cylinder_invalid(c)) return std::numeric_limits<T>::quiet_NaN();
  if (c.radius == T(0)) return T(0);
  return T(2) * pi_v<T> * c.radius * (c.height + c.radius);
}

/// Tight box of the two cap disks (infinite bounds along axes not orthogonal to D when
/// the cylinder is infinite).
template <Real T>
[[nodiscard]] inline AlignedBox3<T> bounding_box(const Cylinder3<T>& c) noexcept {
  Vec3<T> h{};
  for (int k = 0; k < 3; ++k) {
    const T dk = c.axis.direction[k];
    const T along = dk == T(0) ? T(0) : T(0.5) * c.height * std::fabs(dk);
    h[k] = along + c.radius * std::sqrt(std::fmax(T(0), T(1) - dk * dk));
  }
  return {c.axis.origin - h, c.axis.origin + h};
}

/// Centroid of the solid cylinder (its center, axis.origin).
template <Real T>
[[nodiscard]] constexpr Vec3<T> centroid(const Cylinder3<T>& c) noexcept {
  return c.axis.origin;
}

}  // namespace locus
