// SPDX-License-Identifier: BSL-1.0
#pragma once
// Accurate values and exact predicates about crossings of lines (row core.predicates; used by
// the intersection area, rows int2.linear and int2.linear-polyline; book section 7.1).
//
// turn2d_value(a, b, c, d): det[b - a; d - c] (whose exact sign is turn2d() in predicates.hpp)
// rounded from its exact value: exact differences and products in double-double, then in triple
// length, or, nearer zero, the four 2x2 minors of the raw coordinates in expansion arithmetic
// (src/core/crossing.cpp: with FMA products where the processor has them); no difference rounds
// first. Relative error below 2 eps (double eps), sign always turn2d()'s. Why:
// a crossing's parameter is a ratio of two such determinants, and at tiny crossing angles the naive
// ones lose every digit. Exact signs (floating-point filter, then core/exact_sum.hpp), for points
// given implicitly as the crossing X(p, q) of the lines p0 p1 and q0 q1:
//   side_of_crossing(p0, p1, q0, q1, a, b) = sign of orient2d(a, b, X(p, q));
//   compare_crossing_params(a, b, o, p0, p1, q0, q1) = sign of t_q - t_p, where t_x is the
//     parameter of X(line, x) on the line o + t (b - a): the order of two crossings along it.
// Both return Sign::zero when a pair of lines is parallel (no crossing) or on non-finite input.
// Range: exact products need every nonzero product of coordinates above 2^-969 in magnitude
// and every coordinate below 2^250 (products of four). Float input is promoted exactly.
// Cost: turn2d_value about 50-100 flops, about 200 in triple length (|value| below 2^-47 of its
// products), more in the exact tier (below 2^-90); the predicates a few dozen flops when the filter
// decides, a few microseconds otherwise; no allocation.

#include <locus/core/error_free.hpp>
#include <locus/core/exact_sum.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <span>

namespace locus {

namespace detail {
/// det[b - a; d - c] rounded from the exact value (src/core/crossing.cpp: double-double, triple
/// length, expansion; the version with FMA products chosen at run time).
[[nodiscard]] double turn2d_value_accurate(const Vec2<double>& a, const Vec2<double>& b,
                                           const Vec2<double>& c, const Vec2<double>& d) noexcept;
}  // namespace detail

namespace detail {
/// Double-double evaluation of det[b - a; d - c]: exact differences (two_sum), exact leading
/// products, first-order tails. Its error is at most u |v| + 32 u^2 (|p| + |q|) (u = 2^-53,
/// p and q the two leading products); accepted when that is below 1.5 u |v|. Inline only where
/// the target has FMA; elsewhere turn2d_value_accurate runs the same tier with FMA products when
/// the processor has them, then the triple-length and exact tiers. Contraction into FMAs only
/// makes the tails more accurate.
[[nodiscard]] inline double turn2d_value_dd(const Vec2<double>& a, const Vec2<double>& b,
                                            const Vec2<double>& c, const Vec2<double>& d) noexcept {
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  double h1, l1, h2, l2, h3, l3, h4, l4;
  two_sum(b.x, -a.x, h1, l1);
  two_sum(d.y, -c.y, h2, l2);
  two_sum(b.y, -a.y, h3, l3);
  two_sum(d.x, -c.x, h4, l4);
  const double p = h1 * h2, q = h3 * h4;
  const double pe = product_error(h1, h2, p), qe = product_error(h3, h4, q);
  double s, se;
  two_sum(p, -q, s, se);
  const double tail =
      (se + (pe - qe)) + ((h1 * l2 + l1 * h2) - (h3 * l4 + l3 * h4)) + (l1 * l2 - l3 * l4);
  const double v = s + tail;
  const double perm = std::abs(p) + std::abs(q);
  // 64 u perm <= |v|: the tails' rounding (32 u^2 perm) is at most u |v| / 2. Products near
  // underflow or non-finite input go to the exact path.
  if (std::abs(v) >= 0x1p-47 * perm && perm > 0x1p-900 && perm < 0x1p1000) [[likely]]
    return v;
#endif
  return turn2d_value_accurate(a, b, c, d);
}
}  // namespace detail

/// det[b - a; d - c] = perp_dot(b - a, d - c), relative error below 2 eps (see the header).
template <Real T>
[[nodiscard]] inline double turn2d_value(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c,
                                         const Vec2<T>& d) noexcept {
  return detail::turn2d_value_dd(vec_cast<double>(a), vec_cast<double>(b), vec_cast<double>(c),
                                 vec_cast<double>(d));
}

namespace detail::crossing {

/// A polynomial of degree 2 in the coordinates as monomials x_i y_j (at most 8 terms).
struct Quad {
  ExactMonomial m[8];
  int n = 0;
};
/// Adds sign * (p.x q.y - p.y q.x).
inline void add_minor(Quad& q, const Vec2<double>& p, const Vec2<double>& r, int sign) noexcept {
  q.m[q.n++] = {sign, 0, 2, {p.x, r.y, 0.0, 0.0}};
  q.m[q.n++] = {-sign, 0, 2, {p.y, r.x, 0.0, 0.0}};
}
/// orient2d(a, b, c) = det[b - a; c - a] = m(a, b) + m(b, c) + m(c, a).
inline Quad orient_terms(const Vec2<double>& a, const Vec2<double>& b,
                         const Vec2<double>& c) noexcept {
  Quad q;
  add_minor(q, a, b, 1);
  add_minor(q, b, c, 1);
  add_minor(q, c, a, 1);
  return q;
}
/// det[b - a; d - c] = m(b, d) - m(b, c) - m(a, d) + m(a, c).
inline Quad turn_terms(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
                       const Vec2<double>& d) noexcept {
  Quad q;
  add_minor(q, b, d, 1);
  add_minor(q, b, c, -1);
  add_minor(q, a, d, -1);
  add_minor(q, a, c, 1);
  return q;
}
/// Exact sign of x1 y1 - x2 y2 for degree-2 polynomials (128 monomials of degree 4 at most).
inline int sign_of_products_diff(const Quad& x1, const Quad& y1, const Quad& x2,
                                 const Quad& y2) noexcept {
  ExactMonomial m[128];
  int n = 0;
  const auto mul = [&](const Quad& x, const Quad& y, int sign) noexcept {
    for (int i = 0; i < x.n; ++i)
      for (int j = 0; j < y.n; ++j)
        m[n++] = {sign * x.m[i].sign * y.m[j].sign,
                  0,
                  4,
                  {x.m[i].f[0], x.m[i].f[1], y.m[j].f[0], y.m[j].f[1]}};
  };
  mul(x1, y1, 1);
  mul(x2, y2, -1);
  return exact_sign_of_sum(std::span<const ExactMonomial>(m, static_cast<std::size_t>(n)));
}

/// A rounded value with an absolute error bound.
struct Val {
  double v, e;
};
/// det[b - a; d - c] with orient2d's stage-A bound (Shewchuk 1997).
inline Val turn_val(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
                    const Vec2<double>& d) noexcept {
  const double p = (b.x - a.x) * (d.y - c.y), q = (b.y - a.y) * (d.x - c.x);
  return {p - q, 3.3307e-16 * (std::abs(p) + std::abs(q))};
}
/// The sign of x1 y1 - x2 y2 when the bounds decide it, else 2.
inline int filtered_products_diff(Val x1, Val y1, Val x2, Val y2) noexcept {
  const double p = x1.v * y1.v, q = x2.v * y2.v, v = p - q;
  const double bound = (x1.e * (std::abs(y1.v) + y1.e) + std::abs(x1.v) * y1.e) +
                       (x2.e * (std::abs(y2.v) + y2.e) + std::abs(x2.v) * y2.e) +
                       4.5e-16 * (std::abs(p) + std::abs(q));
  // Below 2^-900 the roundings are no longer relative; let the exact path decide.
  if (std::abs(v) > bound && std::abs(v) > 0x1p-900) return v > 0 ? 1 : -1;
  return 2;
}

inline bool finite(const Vec2<double>& p) noexcept {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

}  // namespace detail::crossing

/// Exact sign of orient2d(a, b, X) with X the crossing of the lines p0 p1 and q0 q1; zero when
/// those lines are parallel (or coincide) or on non-finite input.
template <Real T>
[[nodiscard]] inline Sign side_of_crossing(const Vec2<T>& p0_, const Vec2<T>& p1_,
                                           const Vec2<T>& q0_, const Vec2<T>& q1_,
                                           const Vec2<T>& a_, const Vec2<T>& b_) noexcept {
  namespace c = detail::crossing;
  const Vec2<double> p0 = vec_cast<double>(p0_), p1 = vec_cast<double>(p1_),
                     q0 = vec_cast<double>(q0_), q1 = vec_cast<double>(q1_),
                     a = vec_cast<double>(a_), b = vec_cast<double>(b_);
  if (!(c::finite(p0) && c::finite(p1) && c::finite(q0) && c::finite(q1) && c::finite(a) &&
        c::finite(b)))
    return Sign::zero;
  // X = (o0 p1 - o1 p0) / (o0 - o1), o_i = orient2d(q0, q1, p_i), o0 - o1 = det[p1 - p0; q1 - q0];
  // orient2d(a, b, .) is affine, so its value at X is (o0 f1 - o1 f0) / (o0 - o1).
  const Sign den = turn2d(p0, p1, q0, q1);
  if (den == Sign::zero) return Sign::zero;
  int s = c::filtered_products_diff(c::turn_val(q0, q1, q0, p0), c::turn_val(a, b, a, p1),
                                    c::turn_val(q0, q1, q0, p1), c::turn_val(a, b, a, p0));
  if (s == 2)
    s = c::sign_of_products_diff(c::orient_terms(q0, q1, p0), c::orient_terms(a, b, p1),
                                 c::orient_terms(q0, q1, p1), c::orient_terms(a, b, p0));
  return static_cast<Sign>(s) * den;
}

/// Exact sign of t_q - t_p, t_x the parameter on the line o + t (b - a) of its crossing with the
/// line x0 x1: positive iff the crossing with q0 q1 comes later along b - a. Zero when they
/// coincide, when a line x is parallel to b - a, or on non-finite input.
template <Real T>
[[nodiscard]] inline Sign compare_crossing_params(const Vec2<T>& a_, const Vec2<T>& b_,
                                                  const Vec2<T>& o_, const Vec2<T>& p0_,
                                                  const Vec2<T>& p1_, const Vec2<T>& q0_,
                                                  const Vec2<T>& q1_) noexcept {
  namespace c = detail::crossing;
  const Vec2<double> a = vec_cast<double>(a_), b = vec_cast<double>(b_), o = vec_cast<double>(o_),
                     p0 = vec_cast<double>(p0_), p1 = vec_cast<double>(p1_),
                     q0 = vec_cast<double>(q0_), q1 = vec_cast<double>(q1_);
  if (!(c::finite(a) && c::finite(b) && c::finite(o) && c::finite(p0) && c::finite(p1) &&
        c::finite(q0) && c::finite(q1)))
    return Sign::zero;
  // t_x = N_x / D_x with N_x = det[x1 - x0; o - x0], D_x = det[b - a; x1 - x0];
  // t_q - t_p = (N_q D_p - N_p D_q) / (D_p D_q).
  const Sign dp = turn2d(a, b, p0, p1), dq = turn2d(a, b, q0, q1);
  if (dp == Sign::zero || dq == Sign::zero) return Sign::zero;
  int s = c::filtered_products_diff(c::turn_val(q0, q1, q0, o), c::turn_val(a, b, p0, p1),
                                    c::turn_val(p0, p1, p0, o), c::turn_val(a, b, q0, q1));
  if (s == 2)
    s = c::sign_of_products_diff(c::orient_terms(q0, q1, o), c::turn_terms(a, b, p0, p1),
                                 c::orient_terms(p0, p1, o), c::turn_terms(a, b, q0, q1));
  return static_cast<Sign>(s) * dp * dq;
}

}  // namespace locus
