// SPDX-License-Identifier: BSL-1.0
#pragma once
// Ellipses in the plane and elliptical arcs; row prim2.quadratic (ellipse part); book section
// 5.5.2, figure 5.16.
//
// Axis form Ellipse2<T> {center, axis[2], extent[2]} (fig 5.16): unit orthogonal axes and
// positive half-axis lengths; the curve is { center + extent[0] cos(a) axis[0] +
// extent[1] sin(a) axis[1] : a in [0, 2 pi) } and point_at(ellipse, a) evaluates it. With
// right-handed axes (perp(axis[0]) == axis[1]) increasing a runs counter-clockwise.
//
// Matrix (implicit) form ImplicitEllipse2<T> {center, m}: (X - C)^T M (X - C) = 1 with M
// symmetric positive definite, M = sum_i axis[i] axis[i]^T / extent[i]^2. to_implicit() builds
// M; to_axes() diagonalises it with numeric/eigen_sym.hpp's closed-form 2x2 solver (the
// eigenvalue nearer zero taken as det / larger, so thin ellipses keep relative accuracy) and
// returns extent[0] >= extent[1] (axis[0] major) with axis[1] = perp(axis[0]). The general
// quadratic coefficients a x^2 + b xy + ... live in quadratic_curve.hpp (to_quadratic /
// to_ellipse). Measures: area = pi extent[0] extent[1]; perimeter() is the complete elliptic
// integral by the arithmetic-geometric mean, accurate to a few ulps; perimeter_ramanujan() is
// Ramanujan's second approximation, relative error 0 for circles, < 1e-9 for b/a >= 0.5, at most
// about 4e-4 (b = 0) (both formulas: docs/notes/primitives.md).
//
// EllipseArc2<T> {ellipse, start, sweep}: the points point_at(ellipse, a) for a in
// [start, start + sweep], sweep in [0, 2 pi] (counter-clockwise in the angle parameter).
// Degenerate input: to_axes() returns std::nullopt when M is not positive definite or not finite
// (the quadric is a hyperbola, parabola, empty or degenerate). A zero extent is degenerate
// (is_degenerate()); perimeter() of a flat ellipse is 4 extent[0]. Eigen and perimeter
// computations run in compute_t<T> (double for float input). Cost O(1), no allocation.

#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/numeric/eigen_sym.hpp>
#include <locus/primitives/arc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace locus {

/// Axis form: center, unit orthogonal axes, half-axis lengths (book fig 5.16).
template <Real T>
struct Ellipse2 {
  Vec2<T> center;
  Vec2<T> axis[2];
  Vec2<T> extent;  ///< half-axis lengths along axis[0], axis[1]
};

/// Matrix form: the curve (X - center)^T m (X - center) = 1, m symmetric positive definite.
template <Real T>
struct ImplicitEllipse2 {
  Vec2<T> center;
  Mat2<T> m;
};

/// The arc of an ellipse for angle parameters in [start, start + sweep], 0 <= sweep <= 2 pi.
template <Real T>
struct EllipseArc2 {
  Ellipse2<T> ellipse;
  T start;
  T sweep;
};

using Ellipse2f = Ellipse2<float>;
using Ellipse2d = Ellipse2<double>;

/// center + extent[0] cos(angle) axis[0] + extent[1] sin(angle) axis[1].
template <Real T>
[[nodiscard]] inline Vec2<T> point_at(const Ellipse2<T>& e, T angle) noexcept {
  return e.center + (e.extent[0] * std::cos(angle)) * e.axis[0] +
         (e.extent[1] * std::sin(angle)) * e.axis[1];
}

/// The point of the underlying ellipse at angle parameter `angle` (meaningful in
/// [start, start + sweep]).
template <Real T>
[[nodiscard]] inline Vec2<T> point_at(const EllipseArc2<T>& arc, T angle) noexcept {
  return point_at(arc.ellipse, angle);
}

/// (X - C)^T M (X - C) - 1 (rounded): negative inside, zero on, positive outside.
template <Real T>
[[nodiscard]] constexpr T evaluate(const ImplicitEllipse2<T>& e, const Vec2<T>& p) noexcept {
  const Vec2<T> d = p - e.center;
  return dot(d, e.m * d) - T(1);
}

/// sum_i (dot(X - C, axis_i) / extent_i)^2 - 1 (rounded): negative inside, zero on the curve.
template <Real T>
[[nodiscard]] constexpr T evaluate(const Ellipse2<T>& e, const Vec2<T>& p) noexcept {
  const Vec2<T> d = p - e.center;
  return sqr(dot(d, e.axis[0]) / e.extent[0]) + sqr(dot(d, e.axis[1]) / e.extent[1]) - T(1);
}

/// True when an extent is not positive or a value is not finite.
template <Real T>
[[nodiscard]] constexpr bool is_degenerate(const Ellipse2<T>& e) noexcept {
  return !(e.extent[0] > T(0)) || !(e.extent[1] > T(0)) || !is_finite(e.extent[0]) ||
         !is_finite(e.extent[1]) || !is_finite(e.center) || !is_finite(e.axis[0]) ||
         !is_finite(e.axis[1]);
}

/// pi extent[0] extent[1].
template <Real T>
[[nodiscard]] constexpr T area(const Ellipse2<T>& e) noexcept {
  return pi_v<T> * e.extent[0] * e.extent[1];
}

/// Exact perimeter (to a few ulps) by the arithmetic-geometric mean; 4 a for a flat ellipse.
template <Real T>
[[nodiscard]] inline T perimeter(const Ellipse2<T>& e) noexcept {
  using C = compute_t<T>;
  C a = std::abs(static_cast<C>(e.extent[0])), b = std::abs(static_cast<C>(e.extent[1]));
  if (a < b) {
    const C s = a;
    a = b;
    b = s;
  }
  if (!is_finite(a) || !is_finite(b)) return static_cast<T>(a + b);  // inf or NaN
  if (b == C(0)) return static_cast<T>(C(4) * a);
  // Scale to a = 1 so that the squares neither overflow nor underflow.
  const C scale = a;
  C an = C(1), bn = b / scale;
  C sum = C(0.5) * (C(1) - bn * bn);  // 2^(-1) c_0^2 with c_0^2 = a^2 - b^2
  C pow2 = C(1);
  for (int it = 0; it < 64; ++it) {
    const C cn = C(0.5) * (an - bn);
    if (!(cn > C(0))) break;
    sum += pow2 * cn * cn;  // 2^(n-1) c_n^2 for n >= 1
    const C a_next = C(0.5) * (an + bn);
    bn = std::sqrt(an * bn);
    an = a_next;
    pow2 *= C(2);
    if (cn <= std::numeric_limits<C>::epsilon() * an) break;
  }
  return static_cast<T>(scale * (C(2) * pi_v<C> / an) * (C(1) - sum));
}

/// Ramanujan's second approximation of the perimeter (see the header comment for its error).
template <Real T>
[[nodiscard]] inline T perimeter_ramanujan(const Ellipse2<T>& e) noexcept {
  using C = compute_t<T>;
  const C a = std::abs(static_cast<C>(e.extent[0])), b = std::abs(static_cast<C>(e.extent[1]));
  const C s = a + b;
  if (!(s > C(0))) return static_cast<T>(s);  // 0 or NaN
  const C h = sqr((a - b) / s);
  return static_cast<T>(pi_v<C> * s * (C(1) + C(3) * h / (C(10) + std::sqrt(C(4) - C(3) * h))));
}

/// The matrix form: M = sum_i axis_i axis_i^T / extent_i^2 (the axes are assumed orthonormal).
template <Real T>
[[nodiscard]] constexpr ImplicitEllipse2<T> to_implicit(const Ellipse2<T>& e) noexcept {
  Mat2<T> m{};
  for (int i = 0; i < 2; ++i) {
    const Vec2<T> u = e.axis[i] / e.extent[i];
    m = m + outer(u, u);
  }
  return {e.center, m};
}

/// Axis form of a matrix-form ellipse: extent[0] >= extent[1], axis[1] = perp(axis[0]).
/// std::nullopt when m is not symmetric positive definite (as rounded) or not finite; only the
/// upper triangle m(0, 1) is read for the off-diagonal entry.
template <Real T>
[[nodiscard]] inline std::optional<Ellipse2<T>> to_axes(const ImplicitEllipse2<T>& e) noexcept {
  using C = compute_t<T>;
  if (!is_finite(e.center) || !is_finite(e.m)) return std::nullopt;
  const C q = e.m(0, 1);
  const Mat2<C> m{{{C(e.m(0, 0)), q}, {q, C(e.m(1, 1))}}};
  const SymmetricEigen<C, 2> eg = eigen_symmetric(m);
  if (!(eg.values[0] > C(0))) return std::nullopt;
  // The smaller eigenvalue gives the major (longer) axis: extent = 1 / sqrt(lambda).
  const Vec2<T> major = vec_cast<T>(col(eg.vectors, 0));
  const T e0 = static_cast<T>(C(1) / std::sqrt(eg.values[0]));
  const T e1 = static_cast<T>(C(1) / std::sqrt(eg.values[1]));
  if (!is_finite(e0) || !is_finite(e1) || !(e1 > T(0))) return std::nullopt;
  return Ellipse2<T>{e.center, {major, perp(major)}, {e0, e1}};
}

/// start + sweep, the angle parameter of the arc's end point.
template <Real T>
[[nodiscard]] constexpr T end_angle(const EllipseArc2<T>& arc) noexcept {
  return arc.start + arc.sweep;
}

/// True when angle (taken modulo 2 pi) lies in [start, start + sweep] (rounded, see arc.hpp).
template <Real T>
[[nodiscard]] inline bool contains_angle(const EllipseArc2<T>& arc, T angle) noexcept {
  return detail::angle_in_sweep(angle, arc.start, arc.sweep);
}

}  // namespace locus
