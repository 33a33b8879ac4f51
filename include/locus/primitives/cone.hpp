// SPDX-License-Identifier: BSL-1.0
#pragma once
// Right circular cones: finite, infinite, truncated (frustum of a cone) and double; row
// prim3.solids; book section 9.4.1 (the elliptic cone quadric, figure 9.18) and the cone
// representations of chapter 11 (figures 11.13-11.16: acute cone, acute double cone).
//
// Cone3<T> {vertex V, axis D (unit, precondition), angle alpha (half-angle, in (0, pi/2)),
// min_height, max_height}. With the height h = dot(D, X - V) of a point, the solid is
//   { X : min_height <= h <= max_height, |X - V - h D| <= |h| tan(alpha) }.
// One representation covers every kind:
//   finite cone      min_height = 0,  0 < max_height < inf
//   infinite cone    min_height = 0,  max_height = +inf
//   truncated cone   0 < min_height < max_height (a frustum of a cone; the cap at min_height
//                    is the small disk)
//   double cone      min_height < 0: the part with h < 0 is the opposite nappe (radius |h|
//                    tan alpha); min_height = -inf, max_height = +inf is the full double cone.
// point_at(cone, (theta, h)) = V + h D + |h| tan(alpha) (cos theta u + sin theta v) on the
// lateral surface, (u, v, D) right-handed from plane.hpp's perpendicular_basis(D).
// signed_value(cone, X) = cos^2(alpha) |X - V|^2 - dot(D, X - V)^2 is the book's implicit
// quadric of the infinite double cone: negative strictly inside either nappe.
// volume, lateral_area and surface_area (with the two cap disks) integrate over h in
// [min_height, max_height] for every kind (the formulas: docs/notes/primitives.md); +infinity
// for an infinite cone. centroid() (finite cones only); bounding_box() of a finite cone is the
// box of its cap disks and, when min_height <= 0 <= max_height, the vertex.
// Degenerate input: an angle outside (0, pi/2), min_height > max_height or a NaN parameter is
// invalid (is_valid() false) and the measures return NaN. Equal heights give a disk (volume 0).
// Cost O(1); no allocation.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/plane.hpp>

#include <cmath>
#include <limits>

namespace locus {

/// Right circular cone with apex vertex, unit axis, half-angle and a height range.
template <Real T>
struct Cone3 {
  Vec3<T> vertex;
  Vec3<T> axis;
  T angle;
  T min_height;
  T max_height;
};

using Cone3f = Cone3<float>;
using Cone3d = Cone3<double>;

/// Angle in (0, pi/2) and min_height <= max_height (no NaN).
template <Real T>
[[nodiscard]] constexpr bool is_valid(const Cone3<T>& c) noexcept {
  return c.angle > T(0) && c.angle < pi_v<T> / T(2) && c.min_height <= c.max_height;
}

/// True when the height range is unbounded above or below.
template <Real T>
[[nodiscard]] constexpr bool is_infinite(const Cone3<T>& c) noexcept {
  constexpr T inf = std::numeric_limits<T>::infinity();
  return c.max_height == inf || c.min_height == -inf;
}

/// True when min_height < 0 (the cone includes part of the opposite nappe).
template <Real T>
[[nodiscard]] constexpr bool is_double(const Cone3<T>& c) noexcept {
  return c.min_height < T(0);
}

/// Radius |h| tan(alpha) of the cross-section at height h.
template <Real T>
[[nodiscard]] inline T radius_at(const Cone3<T>& c, T h) noexcept {
  return std::fabs(h) * std::tan(c.angle);
}

/// cos^2(alpha) |X - V|^2 - dot(D, X - V)^2: negative inside the infinite double cone.
template <Real T>
[[nodiscard]] inline T signed_value(const Cone3<T>& c, const Vec3<T>& x) noexcept {
  const Vec3<T> d = x - c.vertex;
  return sqr(std::cos(c.angle)) * sqr_length(d) - sqr(dot(c.axis, d));
}

/// V + h D + |h| tan(alpha) (cos theta u + sin theta v) with th = (theta, h).
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const Cone3<T>& c, const Vec2<T>& th) noexcept {
  const auto b = perpendicular_basis(c.axis);
  return c.vertex + th.y * c.axis +
         radius_at(c, th.y) * (std::cos(th.x) * b.u + std::sin(th.x) * b.v);
}

/// pi tan^2(alpha) (max^3 - min^3) / 3; NaN if invalid.
template <Real T>
[[nodiscard]] inline T volume(const Cone3<T>& c) noexcept {
  if (!is_valid(c)) return std::numeric_limits<T>::quiet_NaN();
  const T t = std::tan(c.angle);
  const T a = c.max_height, b = c.min_height;
  return pi_v<T> * t * t * (a * a * a - b * b * b) / T(3);
}

/// pi tan(alpha) / cos(alpha) (max |max| - min |min|); NaN if invalid.
template <Real T>
[[nodiscard]] inline T lateral_area(const Cone3<T>& c) noexcept {
  if (!is_valid(c)) return std::numeric_limits<T>::quiet_NaN();
  const T a = c.max_height, b = c.min_height;
  return pi_v<T> * std::tan(c.angle) / std::cos(c.angle) * (a * std::fabs(a) - b * std::fabs(b));
}

/// Lateral area plus the two cap disks pi tan^2(alpha) (max^2 + min^2); NaN if invalid.
template <Real T>
[[nodiscard]] inline T surface_area(const Cone3<T>& c) noexcept {
  if (!is_valid(c)) return std::numeric_limits<T>::quiet_NaN();
  const T t = std::tan(c.angle);
  return lateral_area(c) + pi_v<T> * t * t * (sqr(c.max_height) + sqr(c.min_height));
}

/// Box of the cap disks (and the vertex when 0 is in the height range); infinite bounds for
/// an infinite cone.
template <Real T>
[[nodiscard]] inline AlignedBox3<T> bounding_box(const Cone3<T>& c) noexcept {
  const auto disk_box = [&](T h) {
    const Vec3<T> ctr = c.vertex + h * c.axis;
    const T rho = radius_at(c, h);
    Vec3<T> w{};
    for (int k = 0; k < 3; ++k) w[k] = rho * std::sqrt(std::fmax(T(0), T(1) - sqr(c.axis[k])));
    return AlignedBox3<T>{ctr - w, ctr + w};
  };
  if (is_infinite(c)) {
    // The section at an infinite height is unbounded in every direction the cone opens to.
    const T inf = std::numeric_limits<T>::infinity();
    return {splat<T, 3>(-inf), splat<T, 3>(inf)};
  }
  AlignedBox3<T> b = merge(disk_box(c.min_height), disk_box(c.max_height));
  if (c.min_height <= T(0) && T(0) <= c.max_height) b = expand(b, c.vertex);
  return b;
}

/// Centroid of the solid: V + hbar D with hbar = (3/4) (max^4 - min^4) / (max^3 - min^3) (the
/// section area grows as h^2). NaN components if invalid, infinite or flat (min == max gives
/// the disk center V + min D).
template <Real T>
[[nodiscard]] inline Vec3<T> centroid(const Cone3<T>& c) noexcept {
  const T nan = std::numeric_limits<T>::quiet_NaN();
  if (!is_valid(c) || is_infinite(c)) return {nan, nan, nan};
  const T a = c.min_height, b = c.max_height;
  if (a == b) return c.vertex + a * c.axis;
  // (b^4 - a^4) / (b^3 - a^3) = (a + b)(a^2 + b^2) / (a^2 + a b + b^2), free of cancellation.
  const T hbar = T(0.75) * (a + b) * (a * a + b * b) / (a * a + a * b + b * b);
  return c.vertex + hbar * c.axis;
}

}  // namespace locus
