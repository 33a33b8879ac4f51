// SPDX-License-Identifier: BSL-1.0
#pragma once
// Tori; row prim3.solids; book section 9.5 (the torus and its quartic implicit form), figure
// 9.21 (a standard "ring" torus).
//
// Torus3<T> {center C, normal N (unit axis, precondition), major_radius R, minor_radius r}: the
// surface swept by a circle of radius r whose center moves on the circle of radius R about C in
// the plane orthogonal to N. With (u, v, N) the right-handed basis of plane.hpp's
// perpendicular_basis(N):
//   point_at(torus, (a, b)) = C + (R + r cos b)(cos a u + sin a v) + r sin b N,
// a the angle around the axis, b the angle around the tube (b = 0 on the outer equator).
// Implicit quartic (section 9.5): in local coordinates x, y (in the plane) and z (along N),
//   signed_value = (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2),
// zero on the surface and negative inside the tube (for a ring torus, R > r).
//
// Measures (Pappus): volume = 2 pi^2 R r^2, surface_area = 4 pi^2 R r. They hold for ring tori
// (R > r); horn (R = r) and spindle (R < r) tori overlap themselves and the formulas then
// count the overlap twice. bounding_box() is tight: C_k +- (R sqrt(1 - N_k^2) + r).
//
// Degenerate input: negative or NaN radii are invalid (measures NaN); r = 0 is the center
// circle, R = 0 a doubly covered sphere. Cost O(1); no allocation.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/plane.hpp>

#include <cmath>
#include <limits>

namespace locus {

/// Torus with center, unit axis normal, major radius R and minor (tube) radius r.
template <Real T>
struct Torus3 {
  Vec3<T> center;
  Vec3<T> normal;
  T major_radius;
  T minor_radius;
};

using Torus3f = Torus3<float>;
using Torus3d = Torus3<double>;

/// C + (R + r cos b)(cos a u + sin a v) + r sin b N with ab = (a, b).
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const Torus3<T>& t, const Vec2<T>& ab) noexcept {
  const auto b = perpendicular_basis(t.normal);
  const T ring = t.major_radius + t.minor_radius * std::cos(ab.y);
  return t.center + ring * (std::cos(ab.x) * b.u + std::sin(ab.x) * b.v) +
         (t.minor_radius * std::sin(ab.y)) * t.normal;
}

/// (|d|^2 + R^2 - r^2)^2 - 4 R^2 (|d|^2 - dot(N, d)^2), d = X - C: negative inside the tube.
template <Real T>
[[nodiscard]] constexpr T signed_value(const Torus3<T>& t, const Vec3<T>& x) noexcept {
  const Vec3<T> d = x - t.center;
  const T dd = sqr_length(d), z = dot(t.normal, d);
  const T rr = t.major_radius * t.major_radius;
  return sqr(dd + rr - t.minor_radius * t.minor_radius) - T(4) * rr * (dd - z * z);
}

/// 2 pi^2 R r^2 (Pappus); NaN for negative or NaN radii.
template <Real T>
[[nodiscard]] constexpr T volume(const Torus3<T>& t) noexcept {
  if (!(t.major_radius >= T(0)) || !(t.minor_radius >= T(0)))
    return std::numeric_limits<T>::quiet_NaN();
  return T(2) * pi_v<T> * pi_v<T> * t.major_radius * t.minor_radius * t.minor_radius;
}

/// 4 pi^2 R r (Pappus); NaN for negative or NaN radii.
template <Real T>
[[nodiscard]] constexpr T surface_area(const Torus3<T>& t) noexcept {
  if (!(t.major_radius >= T(0)) || !(t.minor_radius >= T(0)))
    return std::numeric_limits<T>::quiet_NaN();
  return T(4) * pi_v<T> * pi_v<T> * t.major_radius * t.minor_radius;
}

/// Tight box: C_k +- (R sqrt(1 - N_k^2) + r).
template <Real T>
[[nodiscard]] inline AlignedBox3<T> bounding_box(const Torus3<T>& t) noexcept {
  Vec3<T> h{};
  for (int k = 0; k < 3; ++k)
    h[k] = t.major_radius * std::sqrt(std::fmax(T(0), T(1) - sqr(t.normal[k]))) + t.minor_radius;
  return {t.center - h, t.center + h};
}

/// Centroid of the solid torus (its center).
template <Real T>
[[nodiscard]] constexpr Vec3<T> centroid(const Torus3<T>& t) noexcept {
  return t.center;
}

}  // namespace locus
