// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery of the curve distance queries (point_curve.hpp, the linear-curve headers):
// every Bézier, B-spline and NURBS curve is seen span by span as a RATIONAL Bézier span with
// homogeneous control points h_i = (w_i P_i, w_i), i = 0..d, over the global parameter interval
// [t0, t1] (polynomial curves have w_i = 1). B-spline and NURBS spans are extracted without
// allocation by blossoming (de Boor's algorithm with the level-r argument u_r: the Bézier point j
// of span [t_k, t_{k+1}] is the blossom b(t_k^(d-j), t_{k+1}^j)).
//
// A span's coordinates are turned into power-basis polynomials in the CENTRED variable
// u = 2 s - 1 in [-1, 1] (s in [0, 1] the local Bézier parameter), which conditions the
// conversion far better than the monomials of s; alongside every coefficient the same sums are
// formed with absolute values, giving an a-priori bound of its rounding error that is passed to
// numeric/roots.hpp's engine as coefficient_error (so tangencies become double roots, and an
// identically vanishing polynomial - a span at constant distance - is recognised).
//
// Everything runs in compute_t<T> with fixed stack buffers for degree <=
// rational_span_inline_degree (heap buffers beyond).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bezier.hpp>
#include <locus/curves/bspline.hpp>
#include <locus/curves/nurbs.hpp>
#include <locus/numeric/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

namespace locus::detail {

inline constexpr int rational_span_inline_degree = 12;

/// Stack-or-heap buffer for polynomial work of curves up to the inline degree.
template <class V, std::size_t Inline>
using SpanScratch = CurveScratch<V, Inline>;

/// Row i of the Bernstein-to-centred-power matrix: the coefficients of
/// 2^-d binom(d, i) (1 + u)^i (1 - u)^(d - i) in u (exact dyadic numbers for moderate d).
template <class C>
inline void bernstein_to_centred(int d, C* m) noexcept {
  // m is (d + 1) x (d + 1), row-major.
  for (int i = 0; i <= d; ++i) {
    C* row = m + i * (d + 1);
    for (int j = 0; j <= d; ++j) row[j] = C(0);
    row[0] = C(1);
    int deg = 0;
    for (int k = 0; k < d; ++k) {
      const C sgn = k < i ? C(1) : C(-1);  // multiply by (1 + u) i times, then by (1 - u)
      for (int j = deg + 1; j >= 1; --j) row[j] = row[j] + sgn * row[j - 1];
      ++deg;
    }
    // binom(d, i) / 2^d
    C b = C(1);
    for (int k = 0; k < i; ++k) b = b * C(d - k) / C(k + 1);
    const C scale = std::ldexp(b, -d);
    for (int j = 0; j <= d; ++j) row[j] *= scale;
  }
}

/// Point of the rational span at local s in [0, 1] (de Casteljau on the homogeneous points).
template <class C, int M>
[[nodiscard]] inline Vec<C, M> span_homogeneous_at(const Vec<C, M>* h, int d, C s) noexcept {
  SpanScratch<Vec<C, M>, 32> b(static_cast<std::size_t>(d) + 1);
  for (int i = 0; i <= d; ++i) b[static_cast<std::size_t>(i)] = h[i];
  return de_casteljau_inplace(b.data(), d, s);
}

template <class C, int N>
[[nodiscard]] inline Vec<C, N> span_project(const Vec<C, N + 1>& h) noexcept {
  Vec<C, N> p{};
  for (int i = 0; i < N; ++i) p[i] = h[i] / h[N];
  return p;
}

template <class C, int N>
[[nodiscard]] inline Vec<C, N> span_point_at(const Vec<C, N + 1>* h, int d, C s) noexcept {
  if (s == C(0)) return span_project<C, N>(h[0]);
  if (s == C(1)) return span_project<C, N>(h[d]);
  return span_project<C, N>(span_homogeneous_at<C, N + 1>(h, d, s));
}

/// A polynomial in u with its coefficient error bound (both low to high, size deg + 1).
template <class C>
struct BoundedPoly {
  SpanScratch<C, 64> c, err;
  int deg;
  explicit BoundedPoly(int degree)
      : c(static_cast<std::size_t>(degree < 0 ? 1 : degree + 1)),
        err(static_cast<std::size_t>(degree < 0 ? 1 : degree + 1)),
        deg(degree) {
    for (int i = 0; i <= deg; ++i)
      c[static_cast<std::size_t>(i)] = err[static_cast<std::size_t>(i)] = C(0);
  }
};

/// Roots u in the open interval (-1, 1) (every real root when whole_line) of a bounded
/// polynomial, written to out (capacity deg); returns the count, or -1 when the polynomial
/// vanishes identically within its error bound.
template <class C>
[[nodiscard]] inline int span_roots(BoundedPoly<C>& g, C* out, bool whole_line = false) noexcept {
  int n = g.deg;
  bool all_noise = true;
  for (int i = 0; i <= n; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    if (!(std::fabs(g.c[ui]) <= g.err[ui])) all_noise = false;
  }
  if (all_noise) return -1;
  // Leading coefficients within their error bound are noise: they only add spurious huge roots
  // (and their error would swamp the tolerance the engine grants the genuine ones).
  while (n > 0 && std::fabs(g.c[static_cast<std::size_t>(n)]) <= g.err[static_cast<std::size_t>(n)])
    --n;
  if (n <= 0) return 0;
  SpanScratch<double, 64> a(static_cast<std::size_t>(n) + 1), e(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    a[static_cast<std::size_t>(i)] = static_cast<double>(g.c[static_cast<std::size_t>(i)]);
    e[static_cast<std::size_t>(i)] = static_cast<double>(g.err[static_cast<std::size_t>(i)]);
  }
  SpanScratch<double, 1280> work(roots::work_doubles(n));
  SpanScratch<roots::R, 40> r1(static_cast<std::size_t>(n)), r2(static_cast<std::size_t>(n));
  bool budget_hit = false;
  const int cnt = roots::real_roots_engine(a.data(), e.data(), n, work.data(), r1.data(), r2.data(),
                                           0.0, budget_hit);
  int k = 0;
  for (int i = 0; i < cnt; ++i) {
    const double x = r1[static_cast<std::size_t>(i)].x;
    if (whole_line || (x > -1.0 && x < 1.0)) out[k++] = static_cast<C>(x);
  }
  return k;
}

/// Error-bound factor for polynomials built from sums of products of a few dozen terms: the
/// rounding of the conversion and of the products, k * eps * (sum of absolute values).
template <class C>
[[nodiscard]] constexpr C span_error_factor(int d) noexcept {
  return C(8 * (4 * d + 8)) * std::numeric_limits<C>::epsilon();
}

/// The power coefficients (in u) of the N coordinates of q_i = h_i[0..N) - h_i[N] p and of the
/// weight w_i = h_i[N] (with absolute-value twins): qc[k][j], qa[k][j], wc[j], wa[j], j = 0..d.
template <class C, int N>
struct SpanPower {
  SpanScratch<C, 16 * (N + 1)> qc, qa;  // (N) x (d + 1)
  SpanScratch<C, 16> wc, wa;
  int d;
  SpanPower(const Vec<C, N + 1>* h, int deg, const Vec<C, N>& p)
      : qc(static_cast<std::size_t>(N * (deg + 1))),
        qa(static_cast<std::size_t>(N * (deg + 1))),
        wc(static_cast<std::size_t>(deg + 1)),
        wa(static_cast<std::size_t>(deg + 1)),
        d(deg) {
    SpanScratch<C, 196> m(static_cast<std::size_t>((d + 1) * (d + 1)));
    bernstein_to_centred(d, m.data());
    for (int j = 0; j <= d; ++j) {
      C w = C(0), wabs = C(0);
      C q[N] = {}, qabs[N] = {};
      for (int i = 0; i <= d; ++i) {
        const C mij = m[static_cast<std::size_t>(i * (d + 1) + j)];
        const C wi = h[i][N];
        w += wi * mij;
        wabs += std::fabs(wi * mij);
        for (int k = 0; k < N; ++k) {
          const C qi = h[i][k] - wi * p[k];
          q[k] += qi * mij;
          qabs[k] += (std::fabs(h[i][k]) + std::fabs(wi * p[k])) * std::fabs(mij);
        }
      }
      wc[static_cast<std::size_t>(j)] = w;
      wa[static_cast<std::size_t>(j)] = wabs;
      for (int k = 0; k < N; ++k) {
        qc[static_cast<std::size_t>(k * (d + 1) + j)] = q[k];
        qa[static_cast<std::size_t>(k * (d + 1) + j)] = qabs[k];
      }
    }
  }
  [[nodiscard]] C q(int k, int j) noexcept { return qc[static_cast<std::size_t>(k * (d + 1) + j)]; }
  [[nodiscard]] C qabs(int k, int j) noexcept {
    return qa[static_cast<std::size_t>(k * (d + 1) + j)];
  }
  [[nodiscard]] C w(int j) noexcept { return wc[static_cast<std::size_t>(j)]; }
  [[nodiscard]] C wabs(int j) noexcept { return wa[static_cast<std::size_t>(j)]; }
};

/// R_k = Q_k' W - Q_k W' (the numerator of (C - p)' times W^2 / W... up to the factor W^2):
/// coefficient m is sum_{i + j = m + 1} (i - j) q_i w_j, degree <= 2d - 2 (the top term cancels
/// exactly). Written to r[k * (2d - 1) + m] with absolute twins.
template <class C, int N>
inline void span_derivative_numerator(SpanPower<C, N>& sp, C* r, C* ra) noexcept {
  const int d = sp.d;
  const int len = 2 * d - 1;
  for (int k = 0; k < N; ++k)
    for (int m = 0; m < len; ++m) {
      C s = C(0), sa = C(0);
      for (int i = 0; i <= d; ++i) {
        const int j = m + 1 - i;
        if (j < 0 || j > d || i == j) continue;
        const C f = C(i - j);
        s += f * sp.q(k, i) * sp.w(j);
        sa += std::fabs(f) * sp.qabs(k, i) * sp.wabs(j);
      }
      r[k * len + m] = s;
      ra[k * len + m] = sa;
    }
}

/// Accumulates the closest candidate of a point (or a linear component) query over spans, and
/// whether another, distinct candidate ties with it.
template <class C, int N>
struct NearestTracker {
  bool found = false;
  C best_d2 = std::numeric_limits<C>::infinity();
  C best_t = C(0);
  Vec<C, N> best_point{};
  bool has_alt = false;
  C alt_d2 = std::numeric_limits<C>::infinity();
  Vec<C, N> alt_point{};
  C sep2 = C(0);  // squared separation below which two points are "the same point"

  void offer(C d2, C t, const Vec<C, N>& x) noexcept {
    if (!(d2 == d2)) return;
    if (!found || d2 < best_d2) {
      if (found && sqr_length(x - best_point) > sep2) {
        has_alt = true;
        alt_d2 = best_d2;
        alt_point = best_point;
      }
      found = true;
      best_d2 = d2;
      best_t = t;
      best_point = x;
    } else if (sqr_length(x - best_point) > sep2 && d2 < alt_d2) {
      has_alt = true;
      alt_d2 = d2;
      alt_point = x;
    }
  }
  /// True when a distinct candidate is within tol (relative, on squared distances) of the best.
  [[nodiscard]] bool tied(C rel_tol) const noexcept {
    return has_alt && alt_d2 - best_d2 <= rel_tol * best_d2 + std::numeric_limits<C>::min();
  }
};

/// Blossom of the B-spline (or homogeneous NURBS) span k at the arguments u[0..d-1]: de Boor's
/// algorithm with argument u[r - 1] at level r. get(i) returns the (homogeneous) control point i.
template <class C, class V, class K, class Get>
[[nodiscard]] inline V blossom(std::span<const K> knots, int d, int k, const C* u,
                               const Get& get) noexcept {
  SpanScratch<V, 32> b(static_cast<std::size_t>(d) + 1);
  for (int j = 0; j <= d; ++j) b[static_cast<std::size_t>(j)] = get(k - d + j);
  for (int r = 1; r <= d; ++r) {
    for (int j = d; j >= r; --j) {
      const int i = k - d + j;
      const C lo = static_cast<C>(knots[static_cast<std::size_t>(i)]);
      const C hi = static_cast<C>(knots[static_cast<std::size_t>(i + d + 1 - r)]);
      const C den = hi - lo;
      const C a = den != C(0) ? (u[r - 1] - lo) / den : C(0);
      b[static_cast<std::size_t>(j)] =
          (C(1) - a) * b[static_cast<std::size_t>(j - 1)] + a * b[static_cast<std::size_t>(j)];
    }
  }
  return b[static_cast<std::size_t>(d)];
}

/// The d + 1 homogeneous Bézier points of span k = [t_k, t_{k+1}] of a (homogeneous) B-spline.
template <class C, class V, class K, class Get>
inline void span_bezier(std::span<const K> knots, int d, int k, const Get& get, V* out) noexcept {
  SpanScratch<C, 32> u(static_cast<std::size_t>(d > 0 ? d : 1));
  const C a = static_cast<C>(knots[static_cast<std::size_t>(k)]);
  const C b = static_cast<C>(knots[static_cast<std::size_t>(k + 1)]);
  for (int j = 0; j <= d; ++j) {
    for (int r = 0; r < d; ++r) u[static_cast<std::size_t>(r)] = r < d - j ? a : b;
    out[j] = blossom<C, V, K>(knots, d, k, u.data(), get);
  }
}

template <class C, int N>
[[nodiscard]] constexpr Vec<C, N + 1> homogeneous(const Vec<C, N>& p, C w) noexcept {
  Vec<C, N + 1> h{};
  for (int i = 0; i < N; ++i) h[i] = w * p[i];
  h[N] = w;
  return h;
}

/// Calls f(h, d, t0, t1) for the curve's single span (homogeneous points in compute type C).
/// Precondition: a non-empty curve.
template <class C, class T, int N, class F>
inline void for_each_span(const BezierCurve<T, N>& c, F&& f) {
  const int d = static_cast<int>(c.control.size()) - 1;
  SpanScratch<Vec<C, N + 1>, 16> h(c.control.size());
  for (std::size_t i = 0; i < c.control.size(); ++i)
    h[i] = homogeneous<C, N>(vec_cast<C>(c.control[i]), C(1));
  f(h.data(), d, C(0), C(1));
}

/// Calls f(h, d, t0, t1) for every non-empty knot span. Precondition: validate(c) == ok.
template <class C, class T, int N, class F>
inline void for_each_span(const BSplineCurve<T, N>& c, F&& f) {
  const int d = c.degree, n = static_cast<int>(c.control.size());
  const std::span<const T> kn(c.knots);
  SpanScratch<Vec<C, N + 1>, 16> h(static_cast<std::size_t>(d) + 1);
  const auto get = [&c](int i) {
    return homogeneous<C, N>(vec_cast<C>(c.control[static_cast<std::size_t>(i)]), C(1));
  };
  for (int k = d; k < n; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    if (!(kn[uk] < kn[uk + 1])) continue;
    span_bezier<C, Vec<C, N + 1>, T>(kn, d, k, get, h.data());
    f(h.data(), d, static_cast<C>(kn[uk]), static_cast<C>(kn[uk + 1]));
  }
}

/// Calls f(h, d, t0, t1) for every non-empty knot span. Precondition: validate(c) == ok.
template <class C, class T, int N, class F>
inline void for_each_span(const NurbsCurve<T, N>& c, F&& f) {
  const int d = c.degree, n = static_cast<int>(c.control.size());
  const std::span<const T> kn(c.knots);
  SpanScratch<Vec<C, N + 1>, 16> h(static_cast<std::size_t>(d) + 1);
  const auto get = [&c](int i) {
    const auto ui = static_cast<std::size_t>(i);
    return homogeneous<C, N>(vec_cast<C>(c.control[ui]), static_cast<C>(c.weights[ui]));
  };
  for (int k = d; k < n; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    if (!(kn[uk] < kn[uk + 1])) continue;
    span_bezier<C, Vec<C, N + 1>, T>(kn, d, k, get, h.data());
    f(h.data(), d, static_cast<C>(kn[uk]), static_cast<C>(kn[uk + 1]));
  }
}

/// The curve is usable by the distance queries: validate() == ok (Bézier: non-empty, finite).
template <class T, int N>
[[nodiscard]] inline bool curve_ok(const BezierCurve<T, N>& c) noexcept {
  return is_finite(c);
}
template <class T, int N>
[[nodiscard]] inline bool curve_ok(const BSplineCurve<T, N>& c) noexcept {
  return validate(c) == Status::ok;
}
template <class T, int N>
[[nodiscard]] inline bool curve_ok(const NurbsCurve<T, N>& c) noexcept {
  return validate(c) == Status::ok;
}

/// Squared size of the curve's control box (for "same point" separations).
template <class T, int N, class Curve>
[[nodiscard]] inline T control_box_sqr_size(const Curve& c) noexcept {
  Vec<T, N> lo = c.control[0], hi = c.control[0];
  for (const auto& q : c.control)
    for (int i = 0; i < N; ++i) {
      lo[i] = std::min(lo[i], q[i]);
      hi[i] = std::max(hi[i], q[i]);
    }
  return sqr_length(hi - lo);
}

}  // namespace locus::detail
