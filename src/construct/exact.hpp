// SPDX-License-Identifier: BSL-1.0
#pragma once
// Private helpers of the construct area: exact signs of the small polynomials that decide how
// many solutions a chapter 8 construction has (core/exact_poly.hpp does the arithmetic), and the
// rounded intersections of the loci (circles and lines) that carry the solutions' centres.
// Derivations: docs/notes/construct.md.

#include <locus/core/exact_poly.hpp>
#include <locus/core/vec.hpp>

#include <algorithm>
#include <cmath>

namespace locus::detail::construct {

using P = ExactPoly;

[[nodiscard]] inline P var(double x) noexcept { return P::var(x); }
[[nodiscard]] inline P dif(double a, double b) noexcept { return P::diff(a, b); }
[[nodiscard]] inline P sqr(const P& a) noexcept { return a * a; }
/// perp_dot(d, q - o) exactly.
[[nodiscard]] inline P cross_at(const Vec2<double>& d, const Vec2<double>& q,
                                const Vec2<double>& o) noexcept {
  return var(d.x) * dif(q.y, o.y) - var(d.y) * dif(q.x, o.x);
}
/// |a - b|^2 exactly.
[[nodiscard]] inline P sqr_dist(const Vec2<double>& a, const Vec2<double>& b) noexcept {
  return sqr(dif(a.x, b.x)) + sqr(dif(a.y, b.y));
}

/// Exact sign of a - b sqrt(q) for q >= 0.
[[nodiscard]] inline int sign_a_minus_b_sqrt(const P& a, const P& b, const P& q) noexcept {
  const int sa = a.sign();
  const int t = q.sign() > 0 ? -b.sign() : 0;  // the sign of -b sqrt(q)
  if (t == 0) return sa;
  if (sa == 0 || sa == t) return t;
  return sa * (sqr(a) - sqr(b) * q).sign();
}

/// How two loci meet.
enum class Meet { none, one, two, same };

/// Two circles with exact centres a, b and radii ra, rb >= 0 given as exact polynomials.
[[nodiscard]] inline Meet circles_meet(const Vec2<double>& a, const P& ra, const Vec2<double>& b,
                                       const P& rb) noexcept {
  const P e = sqr_dist(a, b);
  if (e.sign() == 0) return (ra - rb).sign() == 0 ? Meet::same : Meet::none;
  const int hi = (sqr(ra + rb) - e).sign();
  const int lo = (e - sqr(ra - rb)).sign();
  if (hi < 0 || lo < 0) return Meet::none;
  return (hi == 0 || lo == 0) ? Meet::one : Meet::two;
}

/// The line {X : perp_dot(d, X - o) = sigma r |d|} (the parallel to the line (o, d) at signed
/// distance sigma r, r given exactly) against the circle about c of radius rho > 0.
[[nodiscard]] inline Meet offset_line_meets_circle(const Vec2<double>& o, const Vec2<double>& d,
                                                   const P& sigma_r, const Vec2<double>& c,
                                                   const P& rho) noexcept {
  const P x = cross_at(d, c, o);
  const P q = sqr(var(d.x)) + sqr(var(d.y));
  // |x / |d| - sigma r| <= rho  <=>  x - (sigma r + rho)|d| <= 0  and  x - (sigma r - rho)|d| >= 0.
  const int f1 = -sign_a_minus_b_sqrt(x, sigma_r + rho, q);
  const int f2 = sign_a_minus_b_sqrt(x, sigma_r - rho, q);
  if (f1 < 0 || f2 < 0) return Meet::none;
  return (f1 == 0 || f2 == 0) ? Meet::one : Meet::two;
}

// ---- rounded constructions (double) ---------------------------------------------------------

/// The intersections of the circles (a, ra) and (b, rb) for a decided meet (one or two): right
/// of a -> b first. Writes out[0 .. n) and returns n.
inline int circle_circle_points(const Vec2<double>& a, double ra, const Vec2<double>& b, double rb,
                                Meet m, Vec2<double>* out) noexcept {
  const Normalized<double, 2> nd = normalize_with_length(b - a);
  const double dd = nd.length;
  const Vec2<double> u = nd.dir;
  // Distance from a along u to the radical line: (d^2 + ra^2 - rb^2) / (2 d).
  const double along = 0.5 * (dd + (ra - rb) * (ra + rb) / dd);
  const Vec2<double> base = a + along * u;
  if (m == Meet::one) {
    out[0] = base;
    return 1;
  }
  const double h = std::sqrt(std::max(0.0, (ra - along) * (ra + along)));
  out[0] = base - h * perp(u);
  out[1] = base + h * perp(u);
  return 2;
}

/// The intersections of the line (p, unit u) with the circle (c, rho) for a decided meet, by
/// increasing parameter along u. Returns the count.
inline int line_circle_points(const Vec2<double>& p, const Vec2<double>& u, const Vec2<double>& c,
                              double rho, Meet m, Vec2<double>* out) noexcept {
  const Vec2<double> w = c - p;
  const Vec2<double> foot = p + dot(u, w) * u;
  if (m == Meet::one) {
    out[0] = foot;
    return 1;
  }
  const double delta = std::abs(perp_dot(u, w));
  const double h = std::sqrt(std::max(0.0, (rho - delta) * (rho + delta)));
  out[0] = foot - h * u;
  out[1] = foot + h * u;
  return 2;
}

template <class T>
[[nodiscard]] inline Vec2<double> to_d(const Vec2<T>& v) noexcept {
  return {double(v.x), double(v.y)};
}
template <class T>
[[nodiscard]] inline Vec2<T> from_d(const Vec2<double>& v) noexcept {
  return {static_cast<T>(v.x), static_cast<T>(v.y)};
}

}  // namespace locus::detail::construct
