// SPDX-License-Identifier: BSL-1.0
#pragma once
// General quadratic curves (conics) in the plane: classification and conversions; row
// prim2.quadratic; book section 5.5, figures 5.13, 5.14 (solution sets by eigenvalue signs),
// 5.15 (circles), 5.16 (ellipses).
// QuadraticCurve2<T> {a, b, c, d, e, f} is the point set
//   { (x, y) : a x^2 + b x y + c y^2 + d x + e y + f = 0 },
// i.e. X^T A X + B^T X + f = 0 with A = [[a, b/2], [b/2, c]] and B = (d, e) in the book's
// matrix notation. evaluate() gives the (rounded) left-hand side.
// classify_conic() uses the exact signs (core/exact_sum.hpp, all finite coefficients, no
// allocation) of disc = b^2 - 4ac, D = det [[2a, b, d], [b, 2c, e], [d, e, 2f]] and
// K = (4af - d^2) + (4cf - e^2) (derivation: docs/notes/primitives.md):
//   a = b = c = 0:  d = e = 0 ? (f = 0 ? plane : empty) : line;
//   disc < 0:  D = 0 -> point;  a D < 0 -> ellipse (circle when a == c and b == 0);  else empty;
//   disc > 0:  D = 0 -> two intersecting lines;  else hyperbola;
//   disc = 0:  D != 0 -> parabola; else K < 0 -> two parallel lines, K = 0 -> one double line,
//              K > 0 -> empty (two imaginary lines).
// The class is exact for the coefficients as given (rounding them may change it, correctly).
// Non-finite coefficients give ConicKind::non_finite.
// Conversions: to_quadratic(Circle2 / Ellipse2) expands the implicit forms (rounded);
// to_ellipse(q) returns the axis form when the class is ellipse or circle (computed in
// compute_t<T>, rounded), std::nullopt otherwise; to_circle(q) the circle when the class is
// circle.

#include <locus/core/exact_sum.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/ellipse.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

namespace locus {

/// The conic a x^2 + b x y + c y^2 + d x + e y + f = 0.
template <Real T>
struct QuadraticCurve2 {
  T a, b, c, d, e, f;
};

using QuadraticCurve2f = QuadraticCurve2<float>;
using QuadraticCurve2d = QuadraticCurve2<double>;

/// The point set of a quadratic equation (book figures 5.13, 5.14).
enum class ConicKind : std::uint8_t {
  ellipse,             ///< a real ellipse that is not a circle
  circle,              ///< a real circle (a == c, b == 0)
  parabola,            ///< a parabola
  hyperbola,           ///< a hyperbola (two branches)
  point,               ///< a single point (degenerate ellipse)
  empty,               ///< no real point (imaginary ellipse, imaginary parallel lines, f != 0 = 0)
  intersecting_lines,  ///< two distinct lines crossing at a point (degenerate hyperbola)
  parallel_lines,      ///< two distinct parallel lines
  double_line,         ///< one line counted twice (e.g. x^2 = 0)
  line,                ///< one line (the equation is linear: a = b = c = 0)
  plane,               ///< every point (all coefficients are zero)
  non_finite,          ///< a coefficient is NaN or infinite
};

/// A short lower-case name ("ellipse", "intersecting_lines", ...).
[[nodiscard]] constexpr std::string_view to_string(ConicKind k) noexcept {
  switch (k) {
    case ConicKind::ellipse:
      return "ellipse";
    case ConicKind::circle:
      return "circle";
    case ConicKind::parabola:
      return "parabola";
    case ConicKind::hyperbola:
      return "hyperbola";
    case ConicKind::point:
      return "point";
    case ConicKind::empty:
      return "empty";
    case ConicKind::intersecting_lines:
      return "intersecting_lines";
    case ConicKind::parallel_lines:
      return "parallel_lines";
    case ConicKind::double_line:
      return "double_line";
    case ConicKind::line:
      return "line";
    case ConicKind::plane:
      return "plane";
    case ConicKind::non_finite:
      return "non_finite";
  }
  return "unknown";
}

namespace detail {

/// Exact signs of the invariants used by classify_conic.
struct ConicSigns {
  int disc;  ///< sign of b^2 - 4ac
  int det;   ///< sign of det [[2a, b, d], [b, 2c, e], [d, e, 2f]]
  int k;     ///< sign of 4af - d^2 + 4cf - e^2
};

[[nodiscard]] inline ConicSigns conic_signs(double a, double b, double c, double d, double e,
                                            double f) noexcept {
  const ExactMonomial disc[2] = {{1, 0, 2, {b, b, 0}}, {-1, 2, 2, {a, c, 0}}};
  const ExactMonomial det[5] = {{1, 3, 3, {a, c, f}},
                                {-1, 1, 3, {a, e, e}},
                                {-1, 1, 3, {b, b, f}},
                                {1, 1, 3, {b, d, e}},
                                {-1, 1, 3, {c, d, d}}};
  const ExactMonomial kk[4] = {
      {1, 2, 2, {a, f, 0}}, {-1, 0, 2, {d, d, 0}}, {1, 2, 2, {c, f, 0}}, {-1, 0, 2, {e, e, 0}}};
  return {exact_sign_of_sum(disc), exact_sign_of_sum(det), exact_sign_of_sum(kk)};
}

}  // namespace detail

/// a x^2 + b x y + c y^2 + d x + e y + f (rounded).
template <Real T>
[[nodiscard]] constexpr T evaluate(const QuadraticCurve2<T>& q, const Vec2<T>& p) noexcept {
  return (q.a * p.x + q.b * p.y + q.d) * p.x + (q.c * p.y + q.e) * p.y + q.f;
}

/// The exact class of the conic (see the header comment for the decision table).
template <Real T>
[[nodiscard]] inline ConicKind classify_conic(const QuadraticCurve2<T>& q) noexcept {
  if (!is_finite(q.a) || !is_finite(q.b) || !is_finite(q.c) || !is_finite(q.d) || !is_finite(q.e) ||
      !is_finite(q.f))
    return ConicKind::non_finite;
  if (q.a == T(0) && q.b == T(0) && q.c == T(0)) {
    if (q.d != T(0) || q.e != T(0)) return ConicKind::line;
    return q.f == T(0) ? ConicKind::plane : ConicKind::empty;
  }
  const detail::ConicSigns s = detail::conic_signs(q.a, q.b, q.c, q.d, q.e, q.f);
  if (s.disc < 0) {
    if (s.det == 0) return ConicKind::point;
    // a and c share the sign of the trace of A here (a c > b^2 / 4 >= 0, so a != 0).
    const int sa = q.a > T(0) ? 1 : -1;
    if (sa * s.det > 0) return ConicKind::empty;
    return (q.a == q.c && q.b == T(0)) ? ConicKind::circle : ConicKind::ellipse;
  }
  if (s.disc > 0) return s.det == 0 ? ConicKind::intersecting_lines : ConicKind::hyperbola;
  if (s.det != 0) return ConicKind::parabola;
  if (s.k < 0) return ConicKind::parallel_lines;
  return s.k == 0 ? ConicKind::double_line : ConicKind::empty;
}

/// The coefficients of |X - center|^2 - radius^2 = 0 (rounded).
template <Real T>
[[nodiscard]] constexpr QuadraticCurve2<T> to_quadratic(const Circle2<T>& c) noexcept {
  return {T(1),
          T(0),
          T(1),
          T(-2) * c.center.x,
          T(-2) * c.center.y,
          sqr_length(c.center) - c.radius * c.radius};
}

/// The coefficients of (X - C)^T M (X - C) - 1 = 0 with M from to_implicit(e) (rounded).
template <Real T>
[[nodiscard]] inline QuadraticCurve2<T> to_quadratic(const Ellipse2<T>& e) noexcept {
  const ImplicitEllipse2<T> im = to_implicit(e);
  const Mat2<T>& m = im.m;
  const Vec2<T> mc = m * e.center;
  return {m(0, 0),      m(0, 1) + m(1, 0), m(1, 1),
          T(-2) * mc.x, T(-2) * mc.y,      dot(e.center, mc) - T(1)};
}

/// The axis form of the conic when classify_conic(q) is ellipse or circle, else std::nullopt.
template <Real T>
[[nodiscard]] inline std::optional<Ellipse2<T>> to_ellipse(const QuadraticCurve2<T>& q) noexcept {
  const ConicKind k = classify_conic(q);
  if (k != ConicKind::ellipse && k != ConicKind::circle) return std::nullopt;
  using C = compute_t<T>;
  // Normalise by the largest quadratic coefficient (a power of two: exact) against overflow.
  const C s = std::ldexp(
      C(1), -std::ilogb(std::max(std::abs(C(q.a)), std::max(std::abs(C(q.b)), std::abs(C(q.c))))));
  const C a = C(q.a) * s, b = C(q.b) * s, c = C(q.c) * s, d = C(q.d) * s, e = C(q.e) * s,
          f = C(q.f) * s;
  // Centre: gradient zero, [[2a, b], [b, 2c]] X = -(d, e).
  const C det = C(4) * a * c - b * b;
  if (!(det > C(0))) return std::nullopt;
  const C cx = (b * e - C(2) * c * d) / det;
  const C cy = (b * d - C(2) * a * e) / det;
  // Value at the centre: f + (d cx + e cy) / 2; then M = A / (-value).
  const C v = f + C(0.5) * (d * cx + e * cy);
  if (!(v < C(0)) && !(v > C(0))) return std::nullopt;
  const C inv = C(-1) / v;
  const Mat2<T> m{{{static_cast<T>(a * inv), static_cast<T>(C(0.5) * b * inv)},
                   {static_cast<T>(C(0.5) * b * inv), static_cast<T>(c * inv)}}};
  const Vec2<T> center{static_cast<T>(cx), static_cast<T>(cy)};
  if (!is_finite(m) || !is_finite(center)) return std::nullopt;
  return to_axes(ImplicitEllipse2<T>{center, m});
}

/// The circle when classify_conic(q) is circle, else std::nullopt (rounded).
template <Real T>
[[nodiscard]] inline std::optional<Circle2<T>> to_circle(const QuadraticCurve2<T>& q) noexcept {
  if (classify_conic(q) != ConicKind::circle) return std::nullopt;
  using C = compute_t<T>;
  const C inv = C(1) / C(q.a);
  const C cx = C(-0.5) * C(q.d) * inv, cy = C(-0.5) * C(q.e) * inv;
  const C r2 = cx * cx + cy * cy - C(q.f) * inv;
  if (!(r2 > C(0))) return std::nullopt;
  const Circle2<T> c{{static_cast<T>(cx), static_cast<T>(cy)}, static_cast<T>(std::sqrt(r2))};
  if (!is_finite(c.center) || !is_finite(c.radius)) return std::nullopt;
  return c;
}

}  // namespace locus
