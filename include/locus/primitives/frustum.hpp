// SPDX-License-Identifier: BSL-1.0
#pragma once
// Orthogonal view frusta in 3D and 2D; row prim3.solids; the book's orthogonal frustum of the
// distance chapters (figure 10.23 in 3D; the 2D orthogonal frustum of figure 6.11(c)).
//
// Frustum3<T> {origin E, direction D, up U, right R, d_min n, d_max f, u_bound u, r_bound r}:
// D, U, R orthonormal (precondition; handedness free), 0 < n < f, u, r > 0. The near face is
// the rectangle { E + n D + s R + t U : |s| <= r, |t| <= u } at distance n along D; the solid is
// the part of the pyramid with apex E through that rectangle between the planes at distances n
// and f: { E + d D + (d/n)(s R + t U) : n <= d <= f, |s| <= r, |t| <= u }.
// point_at(fr, (s, t, w)) = E + d D + (d/n)(s r R + t u U) with d = (1 - w) n + w f,
// s, t in [-1, 1], w in [0, 1] (w = 0 near face, w = 1 far face).
// Corner k: bit 0 selects +R (else -R), bit 1 +U, bit 2 the far face (else near).
// volume = 4 r u (f^3 - n^3) / (3 n^2); surface_area = near + far rectangles + four trapezoids;
// centroid = E + (3/4)(f^4 - n^4) / (f^3 - n^3) D.
//
// Frustum2<T> {origin E, direction D, left L, d_min n, d_max f, l_bound l}: the 2D orthogonal
// frustum (a trapezoid) { E + d D + (d/n) s L : n <= d <= f, |s| <= l }; corner k: bit 0
// selects +L, bit 1 the far edge; area = l (f^2 - n^2) / n.
//
// Degenerate input: n <= 0, f < n, negative bounds or NaN are invalid (is_valid() false) and
// the measures return NaN; point_at and corners are computed as written (n = 0 divides by 0 and
// gives inf/NaN, documented). f == n gives a flat frustum (volume 0). O(1); no allocation.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace locus {

/// Orthogonal view frustum with apex origin, orthonormal direction/up/right, near distance
/// d_min, far distance d_max and near-face half extents u_bound (up) and r_bound (right).
template <Real T>
struct Frustum3 {
  Vec3<T> origin;
  Vec3<T> direction;
  Vec3<T> up;
  Vec3<T> right;
  T d_min;
  T d_max;
  T u_bound;
  T r_bound;
};

using Frustum3f = Frustum3<float>;
using Frustum3d = Frustum3<double>;

/// 0 < d_min <= d_max, bounds >= 0, all finite.
template <Real T>
[[nodiscard]] constexpr bool is_valid(const Frustum3<T>& f) noexcept {
  return f.d_min > T(0) && f.d_min <= f.d_max && is_finite(f.d_max) && f.u_bound >= T(0) &&
         f.r_bound >= T(0) && is_finite(f.u_bound) && is_finite(f.r_bound);
}

/// E + d D + (d/n)(s r R + t u U) with d = (1 - w) n + w f and stw = (s, t, w).
template <Real T>
[[nodiscard]] constexpr Vec3<T> point_at(const Frustum3<T>& f, const Vec3<T>& stw) noexcept {
  const T d = (T(1) - stw.z) * f.d_min + stw.z * f.d_max;
  const T q = d / f.d_min;
  return f.origin + d * f.direction + (q * stw.x * f.r_bound) * f.right +
         (q * stw.y * f.u_bound) * f.up;
}

/// Corner k: bit 0 +R, bit 1 +U, bit 2 far face.
template <Real T>
[[nodiscard]] constexpr Vec3<T> corner(const Frustum3<T>& f, int k) noexcept {
  LOCUS_ASSERT(k >= 0 && k < 8, "Frustum corner index out of range");
  return point_at(f,
                  Vec3<T>{(k & 1) ? T(1) : T(-1), (k & 2) ? T(1) : T(-1), (k & 4) ? T(1) : T(0)});
}

/// All 8 corners, corner(f, k) at index k.
template <Real T>
[[nodiscard]] constexpr std::array<Vec3<T>, 8> corners(const Frustum3<T>& f) noexcept {
  std::array<Vec3<T>, 8> c{};
  for (int k = 0; k < 8; ++k) c[static_cast<std::size_t>(k)] = corner(f, k);
  return c;
}

/// 4 r u (f^3 - n^3) / (3 n^2); NaN if invalid.
template <Real T>
[[nodiscard]] constexpr T volume(const Frustum3<T>& f) noexcept {
  if (!is_valid(f)) return std::numeric_limits<T>::quiet_NaN();
  const T n = f.d_min, q = f.d_max / f.d_min;
  // (f^3 - n^3) / n^2 = n (q^3 - 1), written so that it does not overflow for huge f.
  return T(4) / T(3) * f.r_bound * f.u_bound * n * (q * q * q - T(1));
}

/// Near and far rectangles plus the four side trapezoids; NaN if invalid.
template <Real T>
[[nodiscard]] inline T surface_area(const Frustum3<T>& f) noexcept {
  if (!is_valid(f)) return std::numeric_limits<T>::quiet_NaN();
  const T n = f.d_min, q = f.d_max / f.d_min, r = f.r_bound, u = f.u_bound;
  const T caps = T(4) * r * u * (T(1) + q * q);
  // A side trapezoid has parallel edges 2u and 2uq and height (q - 1) |(n, r)|.
  const T sides_r = T(2) * u * (T(1) + q) * (q - T(1)) * std::hypot(n, r);
  const T sides_u = T(2) * r * (T(1) + q) * (q - T(1)) * std::hypot(n, u);
  return caps + sides_r + sides_u;
}

/// The box of the 8 corners.
template <Real T>
[[nodiscard]] constexpr AlignedBox3<T> bounding_box(const Frustum3<T>& f) noexcept {
  AlignedBox3<T> b = empty_box<T, 3>();
  for (int k = 0; k < 8; ++k) b = expand(b, corner(f, k));
  return b;
}

/// 2D orthogonal frustum (a trapezoid) with apex origin, orthonormal direction and left.
template <Real T>
struct Frustum2 {
  Vec2<T> origin;
  Vec2<T> direction;
  Vec2<T> left;
  T d_min;
  T d_max;
  T l_bound;
};

using Frustum2f = Frustum2<float>;
using Frustum2d = Frustum2<double>;

/// 0 < d_min <= d_max, l_bound >= 0, all finite.
template <Real T>
[[nodiscard]] constexpr bool is_valid(const Frustum2<T>& f) noexcept {
  return f.d_min > T(0) && f.d_min <= f.d_max && is_finite(f.d_max) && f.l_bound >= T(0) &&
         is_finite(f.l_bound);
}

/// E + d D + (d/n) s l L with d = (1 - w) n + w f and sw = (s, w).
template <Real T>
[[nodiscard]] constexpr Vec2<T> point_at(const Frustum2<T>& f, const Vec2<T>& sw) noexcept {
  const T d = (T(1) - sw.y) * f.d_min + sw.y * f.d_max;
  return f.origin + d * f.direction + (d / f.d_min * sw.x * f.l_bound) * f.left;
}

/// Corner k: bit 0 +L, bit 1 far edge.
template <Real T>
[[nodiscard]] constexpr Vec2<T> corner(const Frustum2<T>& f, int k) noexcept {
  LOCUS_ASSERT(k >= 0 && k < 4, "Frustum corner index out of range");
  return point_at(f, Vec2<T>{(k & 1) ? T(1) : T(-1), (k & 2) ? T(1) : T(0)});
}

/// l (f^2 - n^2) / n; NaN if invalid.
template <Real T>
[[nodiscard]] constexpr T area(const Frustum2<T>& f) noexcept {
  if (!is_valid(f)) return std::numeric_limits<T>::quiet_NaN();
  const T q = f.d_max / f.d_min;
  return f.l_bound * f.d_min * (q * q - T(1));
}

/// Centroid of the solid: E + dbar D with dbar = (3/4) (f^4 - n^4) / (f^3 - n^3) (the section
/// area grows as d^2); NaN components if invalid.
template <Real T>
[[nodiscard]] constexpr Vec3<T> centroid(const Frustum3<T>& f) noexcept {
  if (!is_valid(f)) {
    const T nan = std::numeric_limits<T>::quiet_NaN();
    return {nan, nan, nan};
  }
  const T n = f.d_min, m = f.d_max;
  const T dbar = T(0.75) * (n + m) * (n * n + m * m) / (n * n + n * m + m * m);
  return f.origin + dbar * f.direction;
}

}  // namespace locus
