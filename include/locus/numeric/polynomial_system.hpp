// SPDX-License-Identifier: BSL-1.0
#pragma once
// Systems of two polynomial equations in two unknowns (row num.polysys; book appendix A):
// resultants (elimination of one variable) and all intersections of two quadratic curves.
// Method and tolerances in detail: docs/notes/numeric.md.
//
// BivariatePolynomial<T> stores f(x, y) = sum_i coeff[i](y) x^i: a polynomial in x whose
// coefficients are Polynomial<T> in y. resultant_x(f, g) is the determinant of the Sylvester
// matrix of f and g as polynomials in x (their actual x-degrees), a polynomial in y vanishing at
// the y of common solutions (and of common roots at infinity in x); division-free, O(2^N N) for
// N = deg_x f + deg_x g <= 12, so exact for exact T (mpq_class). resultant(f, g): univariate.
//
// intersect_quadratic_curves(q1, q2) finds every real point on both curves
// a x^2 + b xy + c y^2 + d x + e y + f = 0, in compute_t<T> (double for float), from the roots of
// the quartic resultant polished by Newton; at most 4 points, sorted by x then y, each kept when
// both residuals are within residual_tolerance (default 8 sqrt(eps(T))) of the absolute terms.
//  * Tangency: reported as ONE point with multiplicity 2. The input coefficients are taken as
//    exact; for data already rounded pass tangency_tolerance of the data's precision (e.g.
//    16 eps(float)): intersections closer than about its square root then count as a tangency.
//  * Common component (coincident curves within coincidence_tolerance, default 16 eps(T), or a
//    shared line of degenerate conics): infinite = true, count = 0.
//  * A curve with all coefficients zero: degenerate_input, infinite = true. NaN/Inf
//    coefficients: non_finite_input, no points.
// Points are rounded results (about 1e-15 relative for transversal intersections, about
// sqrt(eps) along the common tangent for tangencies).

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/numeric/polynomial.hpp>
#include <locus/numeric/roots.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace locus {

/// f(x, y) = sum_i coeff[i](y) x^i.
template <Field T>
struct BivariatePolynomial {
  std::vector<Polynomial<T>> coeff;

  /// Degree in x (-1 for the zero polynomial).
  [[nodiscard]] int degree_x() const {
    int d = static_cast<int>(coeff.size()) - 1;
    while (d >= 0 && coeff[static_cast<std::size_t>(d)].is_zero()) --d;
    return d;
  }
  [[nodiscard]] T operator()(const T& x, const T& y) const {
    T r = T(0);
    for (int i = degree_x(); i >= 0; --i) r = r * x + coeff[static_cast<std::size_t>(i)](y);
    return r;
  }
};

namespace detail {

/// Determinant of an N x N matrix over a commutative ring (entries E with +, -, *), division-free
/// by Laplace expansion along columns with minors memoised by row subset.
template <class E>
E ring_determinant(const std::vector<std::vector<E>>& m, const E& zero, const E& one) {
  const int n = static_cast<int>(m.size());
  if (n == 0) return one;
  const std::size_t states = std::size_t(1) << n;
  std::vector<E> cur(states, zero), nxt(states, zero);
  std::vector<char> cur_set(states, 0), nxt_set(states, 0);
  cur[0] = one;
  cur_set[0] = 1;
  for (int k = 0; k < n; ++k) {  // column k is the last column of the k+1 column minors
    std::fill(nxt_set.begin(), nxt_set.end(), char(0));
    for (std::size_t s = 0; s < states; ++s) {
      if (!cur_set[s]) continue;
      // Add a row r not in s: minor(s u {r}) += sign * m[r][k] * minor(s).
      for (int r = 0; r < n; ++r) {
        if (s & (std::size_t(1) << r)) continue;
        const E& entry = m[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)];
        if (entry == zero) continue;
        // Position of r among the rows of s u {r}, counted from the top.
        int pos = 0;
        for (int t = 0; t < r; ++t)
          if (s & (std::size_t(1) << t)) ++pos;
        const std::size_t ns = s | (std::size_t(1) << r);
        E term = entry * cur[s];
        if ((pos + k) % 2 != 0) term = -term;
        if (nxt_set[ns])
          nxt[ns] = nxt[ns] + term;
        else {
          nxt[ns] = term;
          nxt_set[ns] = 1;
        }
      }
    }
    std::swap(cur, nxt);
    std::swap(cur_set, nxt_set);
  }
  return cur_set[states - 1] ? cur[states - 1] : zero;
}

template <class E>
std::vector<std::vector<E>> sylvester(const std::vector<E>& f, int m, const std::vector<E>& g,
                                      int n, const E& zero) {
  const int size = m + n;
  std::vector<std::vector<E>> s(static_cast<std::size_t>(size),
                                std::vector<E>(static_cast<std::size_t>(size), zero));
  for (int r = 0; r < n; ++r)
    for (int i = 0; i <= m; ++i)
      s[static_cast<std::size_t>(r)][static_cast<std::size_t>(r + m - i)] =
          f[static_cast<std::size_t>(i)];
  for (int r = 0; r < m; ++r)
    for (int i = 0; i <= n; ++i)
      s[static_cast<std::size_t>(n + r)][static_cast<std::size_t>(r + n - i)] =
          g[static_cast<std::size_t>(i)];
  return s;
}

}  // namespace detail

/// Resultant of f and g with respect to x: a polynomial in y. Zero when either is zero.
template <Field T>
[[nodiscard]] Polynomial<T> resultant_x(const BivariatePolynomial<T>& f,
                                        const BivariatePolynomial<T>& g) {
  const int m = f.degree_x(), n = g.degree_x();
  if (m < 0 || n < 0) return {};
  std::vector<Polynomial<T>> fc(f.coeff.begin(), f.coeff.begin() + m + 1);
  std::vector<Polynomial<T>> gc(g.coeff.begin(), g.coeff.begin() + n + 1);
  const Polynomial<T> zero, one = Polynomial<T>::constant(T(1));
  return detail::ring_determinant(detail::sylvester(fc, m, gc, n, zero), zero, one);
}

/// Resultant of two univariate polynomials (the Sylvester determinant). Zero when either is zero;
/// for a non-zero constant f = c and deg g = n it is c^n.
template <Field T>
[[nodiscard]] T resultant(const Polynomial<T>& f, const Polynomial<T>& g) {
  const int m = f.degree(), n = g.degree();
  if (m < 0 || n < 0) return T(0);
  std::vector<T> fc(f.coeff.begin(), f.coeff.begin() + m + 1);
  std::vector<T> gc(g.coeff.begin(), g.coeff.begin() + n + 1);
  return detail::ring_determinant(detail::sylvester(fc, m, gc, n, T(0)), T(0), T(1));
}

/// Coefficients of a x^2 + b xy + c y^2 + d x + e y + f = 0.
template <Real T>
struct QuadraticCurveCoefficients {
  T a, b, c, d, e, f;
};

/// Tolerances of intersect_quadratic_curves (relative; see the header comment).
/// A value <= 0 selects the default, which scales with the precision of T (the input data).
struct QuadraticIntersectionOptions {
  double tangency_tolerance = 0.0;     ///< relative error assumed in R; default 16 eps(double)
  double coincidence_tolerance = 0.0;  ///< parallel coefficient vectors; default 16 eps(T)
  double residual_tolerance = 0.0;     ///< |q(p)| <= this * sum of |terms| to accept a point;
                                       ///< default 8 sqrt(eps(T))
};

template <Real T>
struct QuadraticCurvesIntersection {
  Status status = Status::empty_input;  ///< ok, non_finite_input, degenerate_input (a zero curve)
  int count = 0;                        ///< number of distinct intersection points listed
  std::array<Vec2<T>, 4> point{};
  std::array<int, 4> multiplicity{};  ///< 2 at a tangency (intersection multiplicity)
  bool infinite = false;              ///< the curves share a component (coincident curves)
};

namespace detail::polysys {

struct Conic {
  double a, b, c, d, e, f;
  double operator()(double x, double y) const noexcept {
    return (a * x + b * y + d) * x + (c * y + e) * y + f;
  }
  double abs_terms(double x, double y) const noexcept {
    const double ax = std::abs(x), ay = std::abs(y);
    return std::abs(a) * ax * ax + std::abs(b) * ax * ay + std::abs(c) * ay * ay +
           std::abs(d) * ax + std::abs(e) * ay + std::abs(f);
  }
  double gx(double x, double y) const noexcept { return 2 * a * x + b * y + d; }
  double gy(double x, double y) const noexcept { return b * x + 2 * c * y + e; }
};

// Coefficients of a polynomial in y, degree <= 4 (low to high).
using P4 = std::array<double, 5>;
inline P4 mul(const P4& p, const P4& q) noexcept {
  P4 r{};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; i + j < 5; ++j)
      r[static_cast<std::size_t>(i + j)] +=
          p[static_cast<std::size_t>(i)] * q[static_cast<std::size_t>(j)];
  return r;
}
inline P4 sub(const P4& p, const P4& q) noexcept {
  P4 r{};
  for (std::size_t i = 0; i < 5; ++i) r[i] = p[i] - q[i];
  return r;
}
inline P4 add(const P4& p, const P4& q) noexcept {
  P4 r{};
  for (std::size_t i = 0; i < 5; ++i) r[i] = p[i] + q[i];
  return r;
}
inline P4 absp(const P4& p) noexcept {
  P4 r{};
  for (std::size_t i = 0; i < 5; ++i) r[i] = std::abs(p[i]);
  return r;
}

struct Candidate {
  double x, y;
  int mult;
  double residual;
};

}  // namespace detail::polysys

/// All real intersections of two quadratic curves (see the header comment).
template <Real T>
[[nodiscard]] QuadraticCurvesIntersection<T> intersect_quadratic_curves(
    const QuadraticCurveCoefficients<T>& q1, const QuadraticCurveCoefficients<T>& q2,
    const QuadraticIntersectionOptions& opt = {}) noexcept {
  using namespace detail::polysys;
  QuadraticCurvesIntersection<T> res;
  res.status = Status::ok;
  const T in[12] = {q1.a, q1.b, q1.c, q1.d, q1.e, q1.f, q2.a, q2.b, q2.c, q2.d, q2.e, q2.f};
  for (const T& v : in)
    if (!locus::is_finite(v)) {
      res.status = Status::non_finite_input;
      return res;
    }
  Conic k[2];
  for (int i = 0; i < 2; ++i) {
    double c[6], mx = 0;
    for (int j = 0; j < 6; ++j) {
      c[j] = static_cast<double>(in[6 * i + j]);
      mx = std::max(mx, std::abs(c[j]));
    }
    if (mx == 0) {
      res.status = Status::degenerate_input;
      res.infinite = true;
      return res;
    }
    // Normalise by a power of two (exact) near the largest coefficient.
    const int ex = std::ilogb(mx);
    for (double& v : c) v = std::ldexp(v, -ex);
    k[i] = {c[0], c[1], c[2], c[3], c[4], c[5]};
  }
  // Keep the variable with the larger square coefficient as the resultant's variable "y".
  const bool swap_xy =
      std::max(std::abs(k[0].a), std::abs(k[1].a)) < std::max(std::abs(k[0].c), std::abs(k[1].c));
  Conic w[2] = {k[0], k[1]};
  if (swap_xy)
    for (Conic& q : w) {
      std::swap(q.a, q.c);
      std::swap(q.d, q.e);
    }
  // As polynomials in x: A x^2 + B(y) x + C(y).
  double A[2];
  P4 B[2], C[2], Bab[2], Cab[2];
  for (int i = 0; i < 2; ++i) {
    A[i] = w[i].a;
    B[i] = {w[i].d, w[i].b, 0, 0, 0};
    C[i] = {w[i].f, w[i].e, w[i].c, 0, 0};
    Bab[i] = absp(B[i]);
    Cab[i] = absp(C[i]);
  }
  P4 R, Rabs;
  if (A[0] == 0 && A[1] == 0) {
    // Both linear in x: R = B1 C2 - B2 C1.
    R = sub(mul(B[0], C[1]), mul(B[1], C[0]));
    Rabs = add(mul(Bab[0], Cab[1]), mul(Bab[1], Cab[0]));
  } else {
    const P4 a1{A[0], 0, 0, 0, 0}, a2{A[1], 0, 0, 0, 0};
    const P4 aa1{std::abs(A[0]), 0, 0, 0, 0}, aa2{std::abs(A[1]), 0, 0, 0, 0};
    const P4 u = sub(mul(a1, C[1]), mul(a2, C[0]));      // A1 C2 - A2 C1
    const P4 v = sub(mul(a1, B[1]), mul(a2, B[0]));      // A1 B2 - A2 B1
    const P4 t = sub(mul(B[0], C[1]), mul(B[1], C[0]));  // B1 C2 - B2 C1
    R = sub(mul(u, u), mul(v, t));
    const P4 ua = add(mul(aa1, Cab[1]), mul(aa2, Cab[0]));
    const P4 va = add(mul(aa1, Bab[1]), mul(aa2, Bab[0]));
    const P4 ta = add(mul(Bab[0], Cab[1]), mul(Bab[1], Cab[0]));
    Rabs = add(mul(ua, ua), mul(va, ta));
  }
  const double eps_t = static_cast<double>(eps_v<T>);
  const double coincidence_tol =
      opt.coincidence_tolerance > 0 ? opt.coincidence_tolerance : 16.0 * eps_t;
  const double tangency_tol =
      opt.tangency_tolerance > 0 ? opt.tangency_tolerance : 16.0 * eps_v<double>;
  const double residual_tol =
      opt.residual_tolerance > 0 ? opt.residual_tolerance : 8.0 * std::sqrt(eps_t);
  // Common component. Coincident curves: the normalised coefficient vectors are parallel (all
  // 2x2 minors small), which also catches multiples rounded to T. Other shared components
  // (degenerate conics sharing a line): R vanishes identically up to its rounding errors.
  {
    const double c0[6] = {k[0].a, k[0].b, k[0].c, k[0].d, k[0].e, k[0].f};
    const double c1[6] = {k[1].a, k[1].b, k[1].c, k[1].d, k[1].e, k[1].f};
    double n0 = 0, n1 = 0, minor = 0;
    for (int i = 0; i < 6; ++i) {
      n0 = std::max(n0, std::abs(c0[i]));
      n1 = std::max(n1, std::abs(c1[i]));
      for (int j = i + 1; j < 6; ++j)
        minor = std::max(minor, std::abs(c0[i] * c1[j] - c0[j] * c1[i]));
    }
    bool r_zero = true;
    for (std::size_t i = 0; i < 5; ++i)
      if (std::abs(R[i]) > 64.0 * eps_v<double> * Rabs[i]) r_zero = false;
    if (minor <= coincidence_tol * n0 * n1 || r_zero) {
      res.infinite = true;
      return res;
    }
  }
  // A leading coefficient of R within its rounding error is zero: the curves then share a point
  // at infinity (a common asymptotic direction), which must not turn into a huge spurious root.
  for (int i = 4; i > 0; --i) {
    if (std::abs(R[static_cast<std::size_t>(i)]) >
        64.0 * eps_v<double> * Rabs[static_cast<std::size_t>(i)])
      break;
    R[static_cast<std::size_t>(i)] = 0.0;
  }
  // R's coefficients carry rounding errors up to about eps * Rabs, and the data itself is only
  // as precise as T: the root finder treats R's coefficients as known to tangency_tol * Rabs_i.
  std::array<double, 5> r_err{};
  for (std::size_t i = 0; i < 5; ++i) r_err[i] = tangency_tol * Rabs[i];
  // y = 0 gets the multiplicity these errors allow as every other y does: when R[0] is exactly 0
  // the root finder counts the following coefficients within their errors as zero (circles
  // tangent at y = 0: |R[1]| = 5e-20 below its error 6e-18 would otherwise give the simple roots
  // 0 and -1.5e-15).
  RootOptions ro = near_roots();  // R's coefficients carry error: near mode
  ro.coefficient_error = r_err;
  const auto ry = solve_quartic(R[0], R[1], R[2], R[3], R[4], ro);

  Candidate cand[16];
  int nc = 0;
  // Newton's method on (q1, q2) while the Jacobian is well conditioned and the residual drops.
  // Returns the relative residual max_i |q_i| / (sum of |terms of q_i|); `transversal` tells
  // whether the Jacobian at the result is well conditioned.
  const auto polish = [&](double& x, double& y, bool& transversal) {
    transversal = false;
    for (int it = 0; it < 8; ++it) {
      const double f1 = w[0](x, y), f2 = w[1](x, y);
      const double j11 = w[0].gx(x, y), j12 = w[0].gy(x, y);
      const double j21 = w[1].gx(x, y), j22 = w[1].gy(x, y);
      const double det = j11 * j22 - j12 * j21;
      const double scale = (std::abs(j11) + std::abs(j12)) * (std::abs(j21) + std::abs(j22));
      transversal = std::abs(det) > 1e-6 * scale;
      if (!transversal) break;
      const double dx = (f1 * j22 - f2 * j12) / det, dy = (j11 * f2 - j21 * f1) / det;
      const double nx = x - dx, ny = y - dy;
      const double before =
          std::abs(f1) / w[0].abs_terms(x, y) + std::abs(f2) / w[1].abs_terms(x, y);
      const double after = std::abs(w[0](nx, ny)) / w[0].abs_terms(nx, ny) +
                           std::abs(w[1](nx, ny)) / w[1].abs_terms(nx, ny);
      if (!(after < before)) break;
      x = nx;
      y = ny;
    }
    const double s0 = w[0].abs_terms(x, y), s1 = w[1].abs_terms(x, y);
    const double r0 = s0 > 0 ? std::abs(w[0](x, y)) / s0 : 0.0;
    const double r1 = s1 > 0 ? std::abs(w[1](x, y)) / s1 : 0.0;
    return std::max(r0, r1);
  };
  // Adds a point unless an earlier one is at the same place; returns whether it was added.
  const auto add = [&](double x, double y, int mult, double r) {
    const double sc = 1.0 + std::max(std::abs(x), std::abs(y));
    for (int i = 0; i < nc; ++i)
      if (std::abs(cand[i].x - x) <= 1e-7 * sc && std::abs(cand[i].y - y) <= 1e-7 * sc) {
        if (r < cand[i].residual)
          cand[i] = {x, y, std::max(mult, cand[i].mult), r};
        else
          cand[i].mult = std::max(mult, cand[i].mult);
        return false;
      }
    if (nc < 16) cand[nc++] = {x, y, mult, r};
    return true;
  };
  const double strict_residual = 64.0 * eps_v<double>;
  for (const auto& root : ry) {
    const double y = root.value;
    double a[2], b[2], c[2];
    for (int i = 0; i < 2; ++i) {
      a[i] = w[i].a;
      b[i] = w[i].b * y + w[i].d;
      c[i] = (w[i].c * y + w[i].e) * y + w[i].f;
    }
    if (root.multiplicity >= 2) {
      // A multiple root of R is a tangency, or several transversal points with (nearly) the same
      // y. Try the roots of each curve on this line: those that Newton's method turns into
      // well-conditioned, accurately satisfied intersections are distinct transversal points.
      const int before = nc;
      for (int i = 0; i < 2; ++i)
        for (const auto& rx : solve_quadratic(c[i], b[i], a[i])) {
          double x = rx.value, yy = y;
          bool transversal;
          const double r = polish(x, yy, transversal);
          if (transversal && r <= strict_residual) add(x, yy, 1, r);
        }
      if (nc - before >= 2) continue;
      nc = before;  // at most one: treat as a tangency below
    }
    // The single common point on this line: the two quadratics in x share exactly one root,
    // found by eliminating x^2 (a2 q1 - a1 q2 is linear in x). When they are proportional or the
    // formula fails, the roots of each curve on the line are the candidates.
    const int before = nc;
    const double den = a[1] * b[0] - a[0] * b[1], num = a[0] * c[1] - a[1] * c[0];
    if (std::abs(den) > 1e-8 * (std::abs(a[1] * b[0]) + std::abs(a[0] * b[1]))) {
      double x = num / den, yy = y;
      bool transversal;
      const double r = polish(x, yy, transversal);
      if (std::isfinite(x) && r <= residual_tol) add(x, yy, root.multiplicity, r);
    }
    if (nc == before)
      for (int i = 0; i < 2; ++i)
        for (const auto& rx : solve_quadratic(c[i], b[i], a[i])) {
          double x = rx.value, yy = y;
          bool transversal;
          const double r = polish(x, yy, transversal);
          if (r <= residual_tol) add(x, yy, 0, r);
        }
    // Multiplicity: R's multiplicity shared among the distinct points found on this line.
    const int found = nc - before;
    for (int i = before; i < nc; ++i)
      cand[i].mult = std::max(1, found > 0 ? root.multiplicity / found : 1);
  }
  // Keep the (at most 4) best, sorted by x then y in the caller's coordinates.
  for (int i = 0; i < nc; ++i)
    if (swap_xy) std::swap(cand[i].x, cand[i].y);
  std::sort(cand, cand + nc,
            [](const Candidate& p, const Candidate& q) { return p.residual < q.residual; });
  nc = std::min(nc, 4);
  std::sort(cand, cand + nc, [](const Candidate& p, const Candidate& q) {
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  for (int i = 0; i < nc; ++i) {
    const Vec2<T> p{static_cast<T>(cand[i].x), static_cast<T>(cand[i].y)};
    if (!locus::is_finite(p.x) || !locus::is_finite(p.y)) continue;
    res.point[static_cast<std::size_t>(res.count)] = p;
    res.multiplicity[static_cast<std::size_t>(res.count)] = cand[i].mult;
    ++res.count;
  }
  return res;
}

}  // namespace locus
