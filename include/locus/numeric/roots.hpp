// SPDX-License-Identifier: BSL-1.0
#pragma once
// Real roots of polynomials: solve_linear / solve_quadratic / solve_cubic / solve_quartic for
// degree <= 4 (fixed arrays, no allocation) and real_roots(Polynomial, a, b) for any degree
// (row num.roots; book appendix A, figures A.9, A.10, sections on polynomial roots).
//
// Coefficients are LOW TO HIGH everywhere, like Polynomial: solve_quadratic(c0, c1, c2) solves
// c0 + c1 x + c2 x^2 = 0. Results list the DISTINCT real roots in increasing order, each with its
// multiplicity; "count" counts distinct roots, total_multiplicity() counts with multiplicity.
//
// Method (one robust engine for every degree, computed in compute_t<T>: double for float):
//  1. Exact preparation: trailing zero coefficients drop the degree (only EXACT zeros do: a tiny
//     leading coefficient is data and yields correspondingly large roots; pass an interval to
//     real_roots() or filter if you do not want them). Zero low coefficients give the root 0 of
//     the right multiplicity exactly. When the constant term is exactly 0 and the caller gives
//     coefficient error bounds (RootOptions::coefficient_error), the following low coefficients
//     with |a_i| <= error_i count as zero too: 0 is then a root of the multiplicity a polynomial
//     within the bounds can have there (c0 = 0, |c1| <= e1, c2 = 1 is a double root at 0, not
//     0 and -c1), as multiple roots elsewhere are (step 4). Without bounds only exact zeros count;
//     a non-zero constant term is never dropped (roots near 0 then go through step 4). The variable
//     and the polynomial are scaled by powers of two (exact) so that every root lies in (-1, 1) and
//     the largest coefficient is in [1, 2): no overflow for huge or tiny coefficients.
//  2. Derivative recursion: the real roots of p' split the line into intervals on which p is
//     monotone, so each holds at most one root, found when p changes sign between the ends.
//     Starting points: the cancellation-free closed form for the quadratic level; above it the
//     second-order Taylor model at the nearer critical point (else regula falsi). The closed
//     forms of Cardano and Ferrari are not used: they lose or invent roots through cancellation
//     at double roots and clusters, where the recursion stays reliable, and the bracketed
//     iteration is fast enough.
//  3. In a sign-change bracket the root is refined by a safeguarded Newton/bisection hybrid; the
//     sign of p is decided by Horner with an a-priori error bound and, when that is inconclusive,
//     by compensated Horner (Graillat-Langlois-Louvet: as accurate as twice the working
//     precision), so simple roots come out to about one ulp of the exact root of the polynomial
//     as given. Every loop has an iteration budget (Status::limit_exceeded if ever exhausted;
//     the root is then the midpoint of the remaining bracket).
//  4. Multiple roots: at a critical point c that is a root of p' of multiplicity k, when |p(c)|
//     is within the evaluation-noise level gamma_{2n+1} * sum |a_i| |c|^i (plus the caller's
//     tolerances, see RootOptions), c is reported as a root of multiplicity k + 1 (consecutive
//     touching critical points form one cluster root), polished as a simple root of p^(k).
//     This is how double and triple roots are never lost to a rounded discriminant, and what
//     "multiplicity" means in floating point: the returned
//     multiple root is an exact multiple root of a polynomial within that relative coefficient
//     perturbation. Consequently roots closer than about sqrt(noise) are reported as ONE root
//     with their combined multiplicity (a cluster such as (x-1)^3 (x-1-1e-7) comes out as roots
//     near 1 whose multiplicities add up, never as lost roots).
//
// Bad input: a NaN or infinite coefficient gives Status::non_finite_input and no roots; the zero
// polynomial (every x is a root) gives Status::degenerate_input and no roots; a non-zero constant
// gives Status::ok and no roots. A root whose magnitude exceeds the range of T is dropped.
//
// Cost: degree 4 is O(1): about 0.25 us with no real root to 0.85 us with four (one core, -O3;
// bench/numeric/roots_bench.cpp), 2.5-8x faster than Eigen's companion-matrix PolynomialSolver.
// Degree n is O(n^2) Newton steps of O(n) flops in the worst case; real_roots() allocates
// O(n^2) doubles of workspace.

#include <locus/core/error_free.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/numeric/polynomial.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

namespace locus {

/// A real root and its multiplicity.
template <class T>
struct Root {
  T value;
  int multiplicity;
};

/// Options of the root finders: how far from zero a local extremum of p may be and still count
/// as touching zero (a multiple root). The tolerance at x is the sum of
///  * the evaluation noise of compute_t<T> (always), gamma_{2n+1} sum |a_i| |x|^i;
///  * multiplicity_tolerance * sum |a_i| |x|^i (relative; default 0);
///  * sum coefficient_error[i] |x|^i, when the caller knows absolute error bounds of the
///    coefficients (e.g. coefficients computed from other data; entries beyond the span are 0).
///    With these bounds and an exactly zero constant term, low coefficients within their bounds
///    also count as zero: they raise the multiplicity of the root 0 (see the header comment).
/// Raise them for coefficients that carry their own errors, so that a tangency computed from
/// rounded data is reported as a double root rather than as two close roots or none.
struct RootOptions {
  double multiplicity_tolerance = 0.0;
  std::span<const double> coefficient_error{};
};

/// Roots of a polynomial of degree <= 4: no allocation.
template <class T>
struct RootsResult {
  Status status = Status::ok;  ///< ok, non_finite_input, degenerate_input (zero polynomial)
  int count = 0;               ///< number of distinct real roots
  std::array<Root<T>, 4> roots{};

  [[nodiscard]] const Root<T>* begin() const noexcept { return roots.data(); }
  [[nodiscard]] const Root<T>* end() const noexcept { return roots.data() + count; }
  [[nodiscard]] int total_multiplicity() const noexcept {
    int m = 0;
    for (int i = 0; i < count; ++i) m += roots[static_cast<std::size_t>(i)].multiplicity;
    return m;
  }
};

/// Roots of a polynomial of any degree.
template <class T>
struct RealRootsResult {
  Status status = Status::ok;  ///< ok, non_finite_input, degenerate_input, limit_exceeded
  std::vector<Root<T>> roots;  ///< distinct real roots, increasing

  [[nodiscard]] int count() const noexcept { return static_cast<int>(roots.size()); }
  [[nodiscard]] int total_multiplicity() const noexcept {
    int m = 0;
    for (const auto& r : roots) m += r.multiplicity;
    return m;
  }
};

namespace detail::roots {

struct R {
  double x;
  int m;
};

inline constexpr double unit_roundoff = 0.5 * std::numeric_limits<double>::epsilon();
inline constexpr double gamma(int k) noexcept {
  return k * unit_roundoff / (1.0 - k * unit_roundoff);
}

using locus::two_product;
using locus::two_sum;

/// Horner value, derivative, and sum |a_i| |x|^i.
struct Eval {
  double v, d, abs_sum;
};

inline Eval horner(const double* a, int n, double x) noexcept {
  double v = a[n], d = 0.0, s = std::abs(a[n]);
  const double ax = std::abs(x);
  for (int i = n - 1; i >= 0; --i) {
    d = d * x + v;
    v = v * x + a[i];
    s = s * ax + std::abs(a[i]);
  }
  return {v, d, s};
}

/// Sign of p(x) by compensated Horner; 0 when even that cannot decide (|p(x)| is below about
/// eps^2 * sum |a_i| |x|^i). *value receives the compensated value.
inline int compensated_sign(const double* a, int n, double x, double* value) noexcept {
  double s = a[n], c = 0.0, abs_sum = std::abs(a[n]);
  const double ax = std::abs(x);
  for (int i = n - 1; i >= 0; --i) {
    double p, pe, se;
    two_product(s, x, p, pe);
    two_sum(p, a[i], s, se);
    c = c * x + (pe + se);
    abs_sum = abs_sum * ax + std::abs(a[i]);
  }
  const double r = s + c;
  *value = r;
  // Langlois-Louvet: |r - p(x)| <= eps|r| + gamma_{4n+2} gamma_{2n} p~(|x|) + 2 u^2 |r|; a factor
  // 4 covers the rounding of abs_sum itself and the subnormal range is not our concern (scaled).
  const double bound = 4.0 * gamma(4 * n + 2) * gamma(2 * n) * abs_sum;
  if (std::abs(r) * (1.0 - 4.0 * unit_roundoff) > bound) return r > 0 ? 1 : -1;
  return 0;
}

inline int sgn(double v) noexcept { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

/// Sign of p(x): Horner when its error bound allows, else compensated Horner.
inline int sign_at(const double* a, int n, double x, const Eval& e) noexcept {
  if (std::abs(e.v) > gamma(2 * n + 1) * e.abs_sum) return sgn(e.v);
  double dummy;
  return compensated_sign(a, n, x, &dummy);
}

inline constexpr int refine_budget = 2200;  // bisection alone needs < 2100 steps on doubles

/// The root of p in the open bracket (lo, hi), p monotone there, sign(p(lo)) = s_lo != 0,
/// sign(p(hi)) = -s_lo. seed, when inside the bracket, starts Newton.
inline double refine(const double* a, int n, double lo, double hi, int s_lo, double seed,
                     bool polish, bool& budget_hit) noexcept {
  double x = (seed > lo && seed < hi) ? seed : 0.5 * (lo + hi);
  double dx = hi - lo, dx_old = hi - lo;
  const double noise_factor = gamma(2 * n + 1);
  bool compensated = false;  // switched on once Horner's sign is no longer reliable
  for (int it = 0; it < refine_budget; ++it) {
    const Eval e = horner(a, n, x);
    double v = e.v;
    if (!compensated && std::abs(v) <= noise_factor * e.abs_sum) {
      // x is within (noise / |p'|) of the root. Critical points need no more; the top level
      // goes on with the compensated value (as accurate as twice the working precision).
      if (!polish) return x;
      compensated = true;
    }
    int s = sgn(v);
    if (compensated) {
      s = compensated_sign(a, n, x, &v);
      if (s == 0) return x;
    }
    if (s == s_lo)
      lo = x;
    else
      hi = x;
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) return x;  // lo and hi are adjacent doubles
    const double step = e.d != 0.0 ? v / e.d : 0.0;
    const double cand = x - step;
    const bool inside = e.d != 0.0 && cand > lo && cand < hi;
    // Critical points (below the top level) only need to be good enough for the sign of p there:
    // a Newton step below 1e-12 (the variable is scaled to |y| < 2) leaves an error of that order
    // even where convergence is only linear (clusters).
    if (!polish && inside && std::abs(step) <= 1e-12) return cand;
    if (compensated &&
        (cand == x ||
         std::abs(step) <= 0.25 * std::numeric_limits<double>::epsilon() * std::abs(x)))
      return inside ? cand : x;
    // Safeguard (as in rtsafe): take the Newton step only when it stays inside the bracket and
    // is at most half the step before last; otherwise bisect.
    if (inside && std::abs(step) <= 0.5 * std::abs(dx_old)) {
      dx_old = dx;
      dx = step;
      x = cand;
    } else {
      dx_old = dx;
      dx = x - mid;
      x = mid;
    }
  }
  budget_hit = true;
  return 0.5 * (lo + hi);
}

/// Polishes x, a (numerically) simple root of the polynomial d of degree n, by up to 4 Newton
/// steps on the compensated value; steps that are large or that do not shrink are refused.
inline double polish_simple(const double* d, int n, double x) noexcept {
  double last = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k) {
    double vc;
    if (compensated_sign(d, n, x, &vc) == 0) return x;
    const double der = horner(d, n, x).d;
    if (der == 0.0) return x;
    const double step = vc / der;
    if (!(std::abs(step) < 1e-6 && std::abs(step) < 0.5 * last)) return x;
    last = std::abs(step);
    x -= step;
  }
  return x;
}

/// Roots of level j of the derivative chain (q = work + offset(j), degree m) given the sorted
/// roots of q' (crit, nc). A multiple root of multiplicity M is polished as the simple root of
/// the (M-1)-th derivative, which is deeper in the chain (deriv_of(M - 1)).
template <class DerivOf>
inline int roots_from_critical(const double* q, int m, const R* crit, int nc, R* out,
                               const double* eq, double rtol, bool polish, DerivOf deriv_of,
                               bool& budget_hit) noexcept {
  // Starting points: for a quadratic the closed form (cancellation-free), else midpoints.
  double seeds[2] = {std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::quiet_NaN()};
  if (m == 2) {
    const double disc = q[1] * q[1] - 4.0 * q[2] * q[0];
    if (disc > 0) {
      const double t = -0.5 * (q[1] + std::copysign(std::sqrt(disc), q[1]));
      double r1 = t / q[2], r2 = t != 0 ? q[0] / t : r1;
      if (r1 > r2) std::swap(r1, r2);
      seeds[0] = r1;
      seeds[1] = r2;
    }
  }
  const int lead_sign = q[m] > 0 ? 1 : -1;
  // Outer bracket ends: every root is in (-1, 1), so +-1 has the outer sign unless a root is
  // within noise of it, in which case +-2 (certainly beyond) is used.
  const auto outer = [&](double side, int sign, double& xv, double& vv) {
    const Eval e = horner(q, m, side);
    if (sgn(e.v) == sign && std::abs(e.v) > gamma(2 * m + 1) * e.abs_sum) {
      xv = side;
      vv = e.v;
    } else {
      xv = 2.0 * side;
      vv = horner(q, m, xv).v;
    }
  };
  double px = -2.0, pv = 0.0;
  int ps = (m % 2 == 0) ? lead_sign : -lead_sign;  // sign beyond every root
  bool p_outer = true;
  int count = 0;
  // A run of consecutive critical points where q touches zero is ONE root (a cluster): its
  // multiplicity is the run's total multiplicity as roots of q' plus one (so the multiplicities
  // never add up to more than the degree), its position the multiplicity-weighted mean.
  int run_m = 0;
  double run_x = 0.0;
  const auto flush = [&] {
    if (run_m == 0) return;
    const double x = run_x / run_m;
    const int mult = run_m + 1;
    out[count++] = {polish ? polish_simple(deriv_of(mult - 1), m - mult + 1, x) : x, mult};
    run_m = 0;
    run_x = 0.0;
  };
  for (int i = 0; i <= nc; ++i) {
    double x, v = 0.0;
    int s;
    if (i < nc) {
      x = crit[i].x;
      const Eval e = horner(q, m, x);
      const double noise = gamma(2 * m + 1) * e.abs_sum;
      double tol = noise > rtol * e.abs_sum ? noise : rtol * e.abs_sum;
      if (eq) {
        double es = 0.0;
        for (int t = m; t >= 0; --t) es = es * std::abs(x) + eq[t];
        tol += es;
      }
      v = e.v;
      s = std::abs(e.v) <= tol ? 0 : sgn(e.v);
    } else {
      x = 2.0;
      s = lead_sign;
    }
    if (s == 0) {
      run_m += crit[i].m;
      run_x += crit[i].m * x;
    } else {
      flush();
    }
    if (ps != 0 && s != 0 && ps != s) {
      double lo = px, lv = pv, hi = x, hv = v;
      if (p_outer) outer(-1.0, ps, lo, lv);
      if (i == nc) outer(1.0, s, hi, hv);
      // Starting point: the closed form for a quadratic; else the second-order Taylor model at
      // the bracket's critical point with the smaller |q| (where the root is nearer), c +- sqrt(
      // -2 q(c) / q''(c)); else regula falsi on the bracket.
      double seed = (m == 2) ? seeds[i < 2 ? i : 1] : std::numeric_limits<double>::quiet_NaN();
      if (m >= 3) {
        const bool left_crit = !p_outer, right_crit = i < nc;
        const bool use_left = left_crit && (!right_crit || std::abs(pv) <= std::abs(v));
        if (left_crit || right_crit) {
          const double c = use_left ? px : x, vc = use_left ? pv : v;
          const double d2 = horner(deriv_of(2), m - 2, c).v;
          const double t = d2 != 0.0 ? -2.0 * vc / d2 : -1.0;
          if (t > 0.0) seed = use_left ? c + std::sqrt(t) : c - std::sqrt(t);
        }
      }
      if (!(seed > lo && seed < hi)) seed = lo - lv * (hi - lo) / (hv - lv);
      out[count++] = {refine(q, m, lo, hi, ps, seed, polish, budget_hit), 1};
    }
    px = x;
    pv = v;
    ps = s;
    p_outer = false;
  }
  flush();
  return count;
}

/// Work space size for degree n (the derivative chains of p and of its coefficient errors).
inline constexpr std::size_t work_doubles(int n) noexcept {
  return static_cast<std::size_t>((n + 1) * (n + 2));
}

/// Distinct real roots of a[0..n] (finite, a[n] != 0 not required: exact zeros are trimmed).
/// work: work_doubles(n) doubles; r1, r2: n entries each. Returns the number of roots, written
/// to r1 in increasing order. Roots that overflow double are dropped.
inline int real_roots_engine(const double* a_in, const double* err_in, int n, double* work, R* r1,
                             R* r2, double rtol, bool& budget_hit) noexcept {
  while (n >= 0 && a_in[n] == 0.0) --n;
  if (n <= 0) return 0;
  int z = 0;  // multiplicity of the root 0
  while (a_in[z] == 0.0) ++z;
  // An exactly zero constant term makes 0 an exact root that is split off below, so the roots of
  // the rest are never compared with it. Low coefficients that are within the caller's error
  // bounds would then give simple roots within noise of 0 instead of raising its multiplicity (a
  // double root at 0 came out as 0 and -1.5e-15); they are taken as zero, which is exactly the
  // condition for 0 being a root of that multiplicity of a polynomial within the bounds. The
  // leading coefficient (non-zero) is never dropped.
  if (err_in && z > 0)
    while (z < n && std::abs(a_in[z]) <= std::abs(err_in[z])) ++z;
  const double* a = a_in + z;
  const int m = n - z;
  if (m == 0) {
    r1[0] = {0.0, z};
    return 1;
  }
  // Scale x = 2^k y with every root |y| < 1 (Fujiwara's bound in exponents: |a_i/a_m| <
  // 2^(e_i+1-e_m) so every root is below 2 max_i 2^ceil((e_i + 1 - e_m) / (m - i)), the i = 0 term
  // halved).
  const int em = std::ilogb(a[m]);
  int k = std::numeric_limits<int>::min();
  for (int i = 0; i < m; ++i) {
    if (a[i] == 0.0) continue;
    const int num = std::ilogb(a[i]) + 1 - em - (i == 0 ? 1 : 0);
    const int den = m - i;
    const int c = num >= 0 ? (num + den - 1) / den : -((-num) / den);
    if (c + 1 > k) k = c + 1;
  }
  int big = std::numeric_limits<int>::min();
  for (int i = 0; i <= m; ++i)
    if (a[i] != 0.0 && std::ilogb(a[i]) + i * k > big) big = std::ilogb(a[i]) + i * k;
  double* q = work;  // level 0: the scaled polynomial, then its derivatives
  for (int i = 0; i <= m; ++i) q[i] = a[i] == 0.0 ? 0.0 : std::ldexp(a[i], i * k - big);
  // Derivative chain: level j (the j-th derivative, degree m - j) starts at offset(j); the
  // coefficient error bounds, scaled alike, follow the same chain in the second half.
  const auto offset = [m](int j) {
    return static_cast<std::size_t>(j * (m + 1) - j * (j - 1) / 2);
  };
  double* err = err_in ? work + work_doubles(n) / 2 : nullptr;
  if (err)
    for (int i = 0; i <= m; ++i)
      err[i] = err_in[z + i] == 0.0 ? 0.0 : std::ldexp(std::abs(err_in[z + i]), i * k - big);
  for (int j = 1; j < m; ++j) {
    const double* prev = work + offset(j - 1);
    double* lj = work + offset(j);
    for (int i = 0; i <= m - j; ++i) lj[i] = prev[i + 1] * static_cast<double>(i + 1);
    if (err)
      for (int i = 0; i <= m - j; ++i)
        err[offset(j) + static_cast<std::size_t>(i)] =
            err[offset(j - 1) + static_cast<std::size_t>(i) + 1] * static_cast<double>(i + 1);
  }
  // The last level is linear; climb back up, each level's roots being the next one's critical
  // points.
  R* cur = r1;
  R* nxt = r2;
  const double* lin = work + offset(m - 1);
  cur[0] = {-lin[0] / lin[1], 1};
  int nc = 1;
  for (int j = m - 2; j >= 0; --j) {
    nc = roots_from_critical(
        work + offset(j), m - j, cur, nc, nxt, err ? err + offset(j) : nullptr, rtol, j == 0,
        [&](int order) -> const double* { return work + offset(j + order); }, budget_hit);
    R* t = cur;
    cur = nxt;
    nxt = t;
  }
  // Unscale, drop overflow, insert the root 0.
  int out = 0;
  bool zero_done = (z == 0);
  for (int i = 0; i < nc; ++i) {
    const double x = std::ldexp(cur[i].x, k);
    if (!std::isfinite(x)) continue;
    if (!zero_done && x > 0.0) {
      nxt[out++] = {0.0, z};
      zero_done = true;
    }
    nxt[out++] = {x, cur[i].m};
  }
  if (!zero_done) nxt[out++] = {0.0, z};
  for (int i = 0; i < out; ++i) r1[i] = nxt[i];
  return out;
}

template <class T, std::size_t N>
RootsResult<T> solve_fixed(const std::array<T, N>& c, const RootOptions& opt) noexcept {
  RootsResult<T> res;
  bool all_zero = true;
  for (const T& v : c) {
    if (!locus::is_finite(v)) {
      res.status = Status::non_finite_input;
      return res;
    }
    if (v != T(0)) all_zero = false;
  }
  for (const double e : opt.coefficient_error)
    if (!locus::is_finite(e)) {
      res.status = Status::non_finite_input;
      return res;
    }
  if (all_zero) {
    res.status = Status::degenerate_input;
    return res;
  }
  constexpr int n = static_cast<int>(N) - 1;
  double a[N], err[N] = {};
  for (std::size_t i = 0; i < N; ++i) a[i] = static_cast<double>(c[i]);
  for (std::size_t i = 0; i < N && i < opt.coefficient_error.size(); ++i)
    err[i] = opt.coefficient_error[i];
  double work[work_doubles(n)];
  R r1[n > 0 ? n : 1], r2[n > 0 ? n : 1];
  bool budget_hit = false;
  const int cnt = real_roots_engine(a, opt.coefficient_error.empty() ? nullptr : err, n, work, r1,
                                    r2, opt.multiplicity_tolerance, budget_hit);
  for (int i = 0; i < cnt; ++i) {
    const T x = static_cast<T>(r1[i].x);
    if (!locus::is_finite(x)) continue;
    res.roots[static_cast<std::size_t>(res.count++)] = {x, r1[i].m};
  }
  if (budget_hit) res.status = Status::limit_exceeded;
  return res;
}

}  // namespace detail::roots

/// Root of c0 + c1 x = 0 (none when c1 == 0 and c0 != 0; degenerate_input when both are 0).
template <Real T>
[[nodiscard]] RootsResult<T> solve_linear(T c0, std::type_identity_t<T> c1,
                                          const RootOptions& opt = {}) noexcept {
  return detail::roots::solve_fixed<T, 2>({c0, c1}, opt);
}

/// Real roots of c0 + c1 x + c2 x^2 = 0 (low to high!). A double root has multiplicity 2.
template <Real T>
[[nodiscard]] RootsResult<T> solve_quadratic(T c0, std::type_identity_t<T> c1,
                                             std::type_identity_t<T> c2,
                                             const RootOptions& opt = {}) noexcept {
  return detail::roots::solve_fixed<T, 3>({c0, c1, c2}, opt);
}

/// Real roots of c0 + c1 x + c2 x^2 + c3 x^3 = 0 (low to high!).
template <Real T>
[[nodiscard]] RootsResult<T> solve_cubic(T c0, std::type_identity_t<T> c1,
                                         std::type_identity_t<T> c2, std::type_identity_t<T> c3,
                                         const RootOptions& opt = {}) noexcept {
  return detail::roots::solve_fixed<T, 4>({c0, c1, c2, c3}, opt);
}

/// Real roots of c0 + c1 x + c2 x^2 + c3 x^3 + c4 x^4 = 0 (low to high!).
template <Real T>
[[nodiscard]] RootsResult<T> solve_quartic(T c0, std::type_identity_t<T> c1,
                                           std::type_identity_t<T> c2, std::type_identity_t<T> c3,
                                           std::type_identity_t<T> c4,
                                           const RootOptions& opt = {}) noexcept {
  return detail::roots::solve_fixed<T, 5>({c0, c1, c2, c3, c4}, opt);
}

/// Real roots of a polynomial of degree <= 4 given low-to-high coefficients.
template <Real T, std::size_t N>
requires(N >= 1 && N <= 5)
    [[nodiscard]] RootsResult<T> solve_polynomial(const std::array<T, N>& c,
                                                  const RootOptions& opt = {}) noexcept {
  return detail::roots::solve_fixed<T, N>(c, opt);
}

/// All distinct real roots of p in the closed interval [a, b] (default: the whole line), with
/// multiplicities, increasing. Roots are found on the whole line and then filtered, so a root
/// does not move or change multiplicity with the interval.
template <Real T>
[[nodiscard]] RealRootsResult<T> real_roots(const Polynomial<T>& p,
                                            T a = -std::numeric_limits<T>::infinity(),
                                            T b = std::numeric_limits<T>::infinity(),
                                            const RootOptions& opt = {}) {
  RealRootsResult<T> res;
  bool finite = is_finite(p);
  for (const double e : opt.coefficient_error) finite = finite && locus::is_finite(e);
  if (!finite) {
    res.status = Status::non_finite_input;
    return res;
  }
  const int n = p.degree();
  if (n < 0) {
    res.status = Status::degenerate_input;
    return res;
  }
  if (n == 0) return res;
  std::vector<double> c(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) c[static_cast<std::size_t>(i)] = static_cast<double>(p[i]);
  std::vector<double> err(static_cast<std::size_t>(n) + 1, 0.0);
  for (std::size_t i = 0; i < err.size() && i < opt.coefficient_error.size(); ++i)
    err[i] = opt.coefficient_error[i];
  std::vector<double> work(detail::roots::work_doubles(n));
  std::vector<detail::roots::R> r1(static_cast<std::size_t>(n)), r2(static_cast<std::size_t>(n));
  bool budget_hit = false;
  const int cnt = detail::roots::real_roots_engine(
      c.data(), opt.coefficient_error.empty() ? nullptr : err.data(), n, work.data(), r1.data(),
      r2.data(), opt.multiplicity_tolerance, budget_hit);
  for (int i = 0; i < cnt; ++i) {
    const T x = static_cast<T>(r1[static_cast<std::size_t>(i)].x);
    if (!locus::is_finite(x) || x < a || x > b) continue;
    res.roots.push_back({x, r1[static_cast<std::size_t>(i)].m});
  }
  if (budget_hit) res.status = Status::limit_exceeded;
  return res;
}

}  // namespace locus
