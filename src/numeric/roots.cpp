// SPDX-License-Identifier: BSL-1.0
// The near-mode root engine of numeric/roots.hpp and the solve_* / real_roots entry points,
// compiled once for float and double. Derivation: docs/notes/numeric.md.
#include <locus/core/error_free.hpp>
#include <locus/numeric/roots.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace locus {

namespace detail::roots {

namespace {

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

}  // namespace

/// Distinct real roots of a[0..n] (finite, a[n] != 0 not required: exact zeros are trimmed).
/// work: work_doubles(n) doubles; r1, r2: n entries each. Returns the number of roots, written
/// to r1 in increasing order. Roots that overflow double are dropped.
int real_roots_engine(const double* a_in, const double* err_in, int n, double* work, R* r1, R* r2,
                      double rtol, bool& budget_hit) noexcept {
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
  res.status = Status::ok;
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
  if (opt.mode == RootMode::exact) {
    // The exact engine allocates; a failed allocation is reported, never thrown from here.
    try {
      std::vector<Root<T>> out;
      res.status =
          exact_real_roots<T>(std::span<const double>(a, N), -std::numeric_limits<T>::infinity(),
                              std::numeric_limits<T>::infinity(), opt, out);
      for (const Root<T>& r : out)
        if (res.count < n) res.roots[static_cast<std::size_t>(res.count++)] = r;
    } catch (...) {
      res.status = Status::limit_exceeded;
      res.count = 0;
    }
    return res;
  }
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

template <Real T>
RealRootsResult<T> real_roots_span(std::span<const T> p, T a, T b, const RootOptions& opt) {
  RealRootsResult<T> res;
  res.status = Status::ok;
  bool finite = true;
  for (const T& v : p) finite = finite && locus::is_finite(v);
  for (const double e : opt.coefficient_error) finite = finite && locus::is_finite(e);
  if (!finite || std::isnan(a) || std::isnan(b)) {
    res.status = Status::non_finite_input;
    return res;
  }
  int n = static_cast<int>(p.size()) - 1;
  while (n >= 0 && p[static_cast<std::size_t>(n)] == T(0)) --n;
  if (n < 0) {
    res.status = Status::degenerate_input;
    return res;
  }
  if (n == 0 || !(a <= b)) return res;
  std::vector<double> c(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i)
    c[static_cast<std::size_t>(i)] = static_cast<double>(p[static_cast<std::size_t>(i)]);
  if (opt.mode == RootMode::exact) {
    res.status = exact_real_roots<T>(c, a, b, opt, res.roots);
    return res;
  }
  std::vector<double> err(static_cast<std::size_t>(n) + 1, 0.0);
  for (std::size_t i = 0; i < err.size() && i < opt.coefficient_error.size(); ++i)
    err[i] = opt.coefficient_error[i];
  std::vector<double> work(work_doubles(n));
  std::vector<R> r1(static_cast<std::size_t>(n)), r2(static_cast<std::size_t>(n));
  bool budget_hit = false;
  const int cnt =
      real_roots_engine(c.data(), opt.coefficient_error.empty() ? nullptr : err.data(), n,
                        work.data(), r1.data(), r2.data(), opt.multiplicity_tolerance, budget_hit);
  for (int i = 0; i < cnt; ++i) {
    const T x = static_cast<T>(r1[static_cast<std::size_t>(i)].x);
    if (!locus::is_finite(x) || x < a || x > b) continue;
    res.roots.push_back({x, r1[static_cast<std::size_t>(i)].m});
  }
  if (budget_hit) res.status = Status::limit_exceeded;
  return res;
}

#define LOCUS_ROOTS_INSTANTIATE(T, N) \
  template RootsResult<T> solve_fixed<T, N>(const std::array<T, N>&, const RootOptions&);
LOCUS_ROOTS_INSTANTIATE(float, 2)
LOCUS_ROOTS_INSTANTIATE(float, 3)
LOCUS_ROOTS_INSTANTIATE(float, 4)
LOCUS_ROOTS_INSTANTIATE(float, 5)
LOCUS_ROOTS_INSTANTIATE(double, 2)
LOCUS_ROOTS_INSTANTIATE(double, 3)
LOCUS_ROOTS_INSTANTIATE(double, 4)
LOCUS_ROOTS_INSTANTIATE(double, 5)
#undef LOCUS_ROOTS_INSTANTIATE
template RealRootsResult<float> real_roots_span<float>(std::span<const float>, float, float,
                                                       const RootOptions&);
template RealRootsResult<double> real_roots_span<double>(std::span<const double>, double, double,
                                                         const RootOptions&);

}  // namespace detail::roots

}  // namespace locus
