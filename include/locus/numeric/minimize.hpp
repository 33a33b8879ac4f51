// SPDX-License-Identifier: BSL-1.0
#pragma once
// Minimisation (row num.minimize; book appendix A.8-A.9, figures A.19-A.24). Methods (Brent,
// Powell's safeguard, the null-space method, the secular equation and its hard case):
// docs/notes/numeric.md.
//   bracket_minimum(f, a, b)     a, b, c with f(b) < f(a), f(b) <= f(c): a local minimum of a
//                                continuous f lies between a and c (golden-ratio expansion).
//   minimize_brent(f, lo, hi) / minimize_brent(f, bracket)   Brent's method; converges when the
//                                bracket is narrower than 2 (rel_tolerance |x| + abs_tolerance).
//   minimize_powell(f, x0)       Powell's direction-set method in N dimensions.
//   minimize_quadratic(A, b, c[, C, d])   the minimiser of f(x) = x^T A x + b^T x + c, optionally
//                                subject to C x = d (M <= N rows; returns the Lagrange
//                                multipliers lambda with grad f + C^T lambda = 0).
//   minimize_quadratic_on_sphere(A, b, c, center, r), maximize_...: the global minimiser
//                                (maximiser) on |x - center| = r, grad f(x) = 2 mu (x - center);
//                                unique = false in the hard case.
// Conventions: A is read as symmetric (non-symmetric input: invalid_input); grad f = 2 A x + b.
// Quadratic routines compute in compute_t<T> (double for float); positive definite means
// lambda_min > definite_tolerance * max|lambda| (default 16 N eps of the compute type).
// Bad input and budgets: a NaN function value counts as +infinity (never seen a finite one:
// non_finite_input); non-finite starts or intervals: non_finite_input; an exhausted budget
// (max_iterations, max_evaluations): limit_exceeded with the best point so far. Quadratic forms:
// not positive definite (on the null space) -> degenerate_input with the pseudo-inverse
// stationary point; dependent or inconsistent constraints -> degenerate_input, x = 0; a negative
// radius -> invalid_input; NaN/Inf -> non_finite_input, x = 0, value NaN.
// Cost: Brent about 10-30 evaluations to sqrt(eps) relative accuracy on smooth functions; Powell
// N line searches per sweep; quadratic forms O(N^3), allocating small MatX temporaries.

#include <locus/config.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/numeric/decompose.hpp>
#include <locus/numeric/eigen_sym.hpp>
#include <locus/numeric/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace locus {

// ---- one dimension -------------------------------------------------------------------------

/// Three abscissae bracketing a minimum: f(b) < f(a) and f(b) <= f(c), b between a and c.
template <Real T>
struct Bracket {
  Status status = Status::empty_input;  ///< ok, non_finite_input, limit_exceeded (no bracket found)
  T a{}, b{}, c{};
  T fa{}, fb{}, fc{};
  int evaluations = 0;
};

/// Result of a one-dimensional minimisation.
template <Real T>
struct Minimum1 {
  Status status = Status::empty_input;  ///< ok, non_finite_input, limit_exceeded
  T x{};                                ///< the best abscissa found
  T value{};                            ///< f(x)
  int iterations = 0;
  int evaluations = 0;
};

/// Options of Brent's method.
template <Real T>
struct BrentOptions {
  T rel_tolerance = std::sqrt(eps_v<T>);  ///< relative accuracy of x (sqrt(eps) is the limit
                                          ///< for a smooth minimum: f is flat to eps there)
  T abs_tolerance = std::sqrt(eps_v<T>) * T(1e-3);  ///< absolute accuracy of x near 0
  int max_iterations = 100;
};

namespace detail {

// NaN counts as +infinity so that comparisons order it after every finite value.
template <Real T>
[[nodiscard]] inline T sanitize_value(T v) noexcept {
  return v == v ? v : std::numeric_limits<T>::infinity();
}

inline constexpr double golden_ratio = 1.618033988749894848204586834365638;
inline constexpr double golden_section = 0.381966011250105151795413165634362;  // 2 - phi

// Brent's localmin on [a, b] starting from the point x (f(x) = fx) inside it.
template <class T, class F>
Minimum1<T> brent_core(F& f, T a, T b, T x, T fx, const BrentOptions<T>& opt, int evals) {
  Minimum1<T> out;
  out.status = Status::ok;
  if (a > b) std::swap(a, b);
  T w = x, v = x, fw = fx, fv = fx;
  T d = T(0), e = T(0);  // the last step and the one before it
  const T cgold = T(golden_section);
  int it = 0;
  bool converged = false;
  for (; it < opt.max_iterations; ++it) {
    const T xm = (a + b) / T(2);
    const T tol1 = opt.rel_tolerance * std::abs(x) + opt.abs_tolerance;
    const T tol2 = T(2) * tol1;
    if (std::abs(x - xm) <= tol2 - (b - a) / T(2)) {
      converged = true;
      break;
    }
    bool golden = true;
    if (std::abs(e) > tol1) {
      // Parabola through (x, fx), (w, fw), (v, fv): its vertex is x + p / q.
      const T r = (x - w) * (fx - fv);
      T q = (x - v) * (fx - fw);
      T p = (x - v) * q - (x - w) * r;
      q = T(2) * (q - r);
      if (q > T(0)) p = -p;
      q = std::abs(q);
      const T e_prev = e;
      // Accept only a step that lands inside (a, b) and is less than half the step before
      // last: this is what guarantees at least golden-section convergence.
      if (std::abs(p) < std::abs(T(0.5) * q * e_prev) && p > q * (a - x) && p < q * (b - x) &&
          is_finite(p / q)) {
        e = d;
        d = p / q;
        const T u = x + d;
        if (u - a < tol2 || b - u < tol2) d = xm >= x ? tol1 : -tol1;
        golden = false;
      }
    }
    if (golden) {
      e = x >= xm ? a - x : b - x;
      d = cgold * e;
    }
    const T u = std::abs(d) >= tol1 ? x + d : x + (d >= T(0) ? tol1 : -tol1);
    const T fu = sanitize_value(static_cast<T>(f(u)));
    ++evals;
    if (fu <= fx) {
      if (u >= x)
        a = x;
      else
        b = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      if (u < x)
        a = u;
      else
        b = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  out.x = x;
  out.value = fx;
  out.iterations = it;
  out.evaluations = evals;
  if (fx == std::numeric_limits<T>::infinity()) {  // every value seen was NaN or +inf
    out.status = Status::non_finite_input;
    out.value = std::numeric_limits<T>::quiet_NaN();
  } else if (!converged) {
    out.status = Status::limit_exceeded;
  }
  return out;
}

}  // namespace detail

/// Finds a bracket of a minimum by golden-ratio expansion from a and b (a != b), going
/// downhill. At most max_evaluations evaluations of f.
template <class T, class F>
[[nodiscard]] Bracket<T> bracket_minimum(F&& f, T a, T b, int max_evaluations = 64) noexcept {
  Bracket<T> out;
  out.status = Status::ok;
  if (!is_finite(a) || !is_finite(b)) {
    out.status = Status::non_finite_input;
    return out;
  }
  if (a == b) b = a + (a == T(0) ? T(1) : std::abs(a) * T(1e-3));
  T fa = detail::sanitize_value(static_cast<T>(f(a)));
  T fb = detail::sanitize_value(static_cast<T>(f(b)));
  int evals = 2;
  if (!is_finite(fa) && !is_finite(fb)) {
    out = {Status::non_finite_input, a, b, b, fa, fb, fb, evals};
    return out;
  }
  if (fb > fa) {
    std::swap(a, b);
    std::swap(fa, fb);
  }
  T c = b + T(detail::golden_ratio) * (b - a);
  T fc = detail::sanitize_value(static_cast<T>(f(c)));
  ++evals;
  while (!(fc > fb)) {
    if (evals >= max_evaluations || !is_finite(c)) {
      out = {Status::limit_exceeded, a, b, c, fa, fb, fc, evals};
      return out;
    }
    if (fc == fb && fb == fa) {
      // A plateau: every point of it is a minimiser; report it as found.
      break;
    }
    a = b;
    fa = fb;
    b = c;
    fb = fc;
    c = b + T(detail::golden_ratio) * (b - a);
    fc = detail::sanitize_value(static_cast<T>(f(c)));
    ++evals;
  }
  out = {Status::ok, a, b, c, fa, fb, fc, evals};
  return out;
}

/// Brent's minimisation of f on the interval [lo, hi] (a local minimum; the global one when f is
/// unimodal there). The interval end points themselves are never evaluated.
template <class T, class F>
[[nodiscard]] Minimum1<T> minimize_brent(F&& f, T lo, T hi,
                                         const BrentOptions<T>& opt = {}) noexcept {
  if (!is_finite(lo) || !is_finite(hi)) {
    Minimum1<T> out;
    out.status = Status::ok;
    out.status = Status::non_finite_input;
    out.x = out.value = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  if (lo > hi) std::swap(lo, hi);
  const T x = lo + T(detail::golden_section) * (hi - lo);
  const T fx = detail::sanitize_value(static_cast<T>(f(x)));
  return detail::brent_core(f, lo, hi, x, fx, opt, 1);
}

/// Brent's minimisation from a bracket (bracket.b is the start point).
template <class T, class F>
[[nodiscard]] Minimum1<T> minimize_brent(F&& f, const Bracket<T>& br,
                                         const BrentOptions<T>& opt = {}) noexcept {
  if (br.status == Status::non_finite_input || !is_finite(br.a) || !is_finite(br.c)) {
    Minimum1<T> out;
    out.status = Status::ok;
    out.status = Status::non_finite_input;
    out.x = out.value = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  return detail::brent_core(f, std::min(br.a, br.c), std::max(br.a, br.c), br.b, br.fb, opt,
                            br.evaluations);
}

// ---- N dimensions --------------------------------------------------------------------------

/// Result of an N-dimensional minimisation.
template <class T, int N>
struct MinimumN {
  Status status = Status::empty_input;  ///< ok, non_finite_input, limit_exceeded
  Vec<T, N> x{};                        ///< the best point found
  T value{};                            ///< f(x)
  int iterations = 0;                   ///< direction-set sweeps
  int evaluations = 0;
};

/// Options of Powell's method.
template <Real T>
struct PowellOptions {
  T initial_step = T(1);  ///< length of the initial (coordinate) directions
  /// A sweep that lowers f by at most f_tolerance * (|f| + |f_new|) / 2 + f_abs_tolerance ends
  /// the search.
  T f_tolerance = T(8) * eps_v<T>;
  T f_abs_tolerance = std::numeric_limits<T>::min();
  int max_iterations = 500;  ///< sweeps
  int max_evaluations = 100000;
  BrentOptions<T> line{};  ///< line-search options (t is in units of the direction's length)
};

/// Powell's direction-set minimisation of f: Vec<T, N> -> T from x0 (a local minimum).
template <class T, int N, class F>
[[nodiscard]] MinimumN<T, N> minimize_powell(F&& f, const Vec<T, N>& x0,
                                             const PowellOptions<T>& opt = {}) noexcept {
  MinimumN<T, N> out;
  out.status = Status::ok;
  out.x = x0;
  if (!is_finite(x0) || !is_finite(opt.initial_step)) {
    out.status = Status::non_finite_input;
    out.value = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  Vec<T, N> dir[N];
  for (int i = 0; i < N; ++i) dir[i] = opt.initial_step * unit_vec<T, N>(i);
  Vec<T, N> x = x0;
  T fx = detail::sanitize_value(static_cast<T>(f(x)));
  int evals = 1;
  if (!is_finite(fx)) {
    out.status = Status::non_finite_input;
    out.value = std::numeric_limits<T>::quiet_NaN();
    out.evaluations = evals;
    return out;
  }
  bool line_failed = false;
  // Moves x to the minimum along d; returns the decrease of f.
  auto line_search = [&](const Vec<T, N>& d) -> T {
    auto g = [&](T t) { return f(x + t * d); };
    const Bracket<T> br = bracket_minimum(g, T(0), T(1));
    evals += br.evaluations;
    if (br.status != Status::ok) {
      line_failed = br.status == Status::limit_exceeded;
      // Keep the best point seen while bracketing.
      T best_t = T(0), best_f = fx;
      if (br.fa < best_f) best_t = br.a, best_f = br.fa;
      if (br.fb < best_f) best_t = br.b, best_f = br.fb;
      if (br.fc < best_f && is_finite(br.c)) best_t = br.c, best_f = br.fc;
      const T dec = fx - best_f;
      x = x + best_t * d;
      fx = best_f;
      return dec;
    }
    Minimum1<T> m = minimize_brent(g, br, opt.line);
    evals += m.evaluations - br.evaluations;
    T t = m.x, ft = m.value;
    if (!(ft < fx)) return T(0);  // no improvement: stay (also guards NaN)
    const T dec = fx - ft;
    x = x + t * d;
    fx = ft;
    return dec;
  };
  int it = 0;
  bool converged = false;
  for (; it < opt.max_iterations && evals < opt.max_evaluations && !line_failed; ++it) {
    const Vec<T, N> x_start = x;
    const T f_start = fx;
    int big_index = 0;
    T big_decrease = T(0);
    for (int i = 0; i < N; ++i) {
      const T dec = line_search(dir[i]);
      if (dec > big_decrease) {
        big_decrease = dec;
        big_index = i;
      }
    }
    if (T(2) * (f_start - fx) <=
        opt.f_tolerance * (std::abs(f_start) + std::abs(fx)) + opt.f_abs_tolerance) {
      converged = true;
      break;
    }
    // Powell's test: adopt the net displacement as a new direction only if the extrapolated
    // point is lower and the decrease was not dominated by one direction (which would make the
    // set nearly dependent if that direction were dropped).
    const Vec<T, N> disp = x - x_start;
    const T f_ext = detail::sanitize_value(static_cast<T>(f(x + disp)));
    ++evals;
    if (f_ext < f_start) {
      const T t1 = f_start - fx - big_decrease, t2 = f_start - f_ext;
      const T lhs = T(2) * (f_start - T(2) * fx + f_ext) * t1 * t1;
      if (lhs < big_decrease * t2 * t2) {
        line_search(disp);
        dir[big_index] = dir[N - 1];
        dir[N - 1] = disp;
      }
    }
  }
  out.x = x;
  out.value = fx;
  out.iterations = it;
  out.evaluations = evals;
  out.status = converged ? Status::ok : Status::limit_exceeded;
  return out;
}

// ---- quadratic forms -----------------------------------------------------------------------

/// Options of the quadratic-form minimisers.
template <Real T>
struct QuadraticOptions {
  /// A is positive definite when lambda_min > definite_tolerance * max|lambda|; a negative
  /// value selects 16 N eps of the compute type.
  T definite_tolerance = T(-1);
  int max_iterations = 200;  ///< secular-equation iterations (sphere constraint)
};

/// Minimiser of a quadratic form x^T A x + b^T x + c (unconstrained or with linear equality
/// constraints; then `multipliers` has one entry per constraint row).
template <class T, int N, int M = 1>
struct QuadraticMinimum {
  Status status = Status::empty_input;  ///< ok, degenerate_input, invalid_input, non_finite_input
  Vec<T, N> x{};
  T value{};                ///< f(x)
  Vec<T, M> multipliers{};  ///< constrained form: grad f(x) + C^T multipliers = 0 (zero for
                            ///< the unconstrained form)
};

/// Minimiser of a quadratic form on a sphere.
template <class T, int N>
struct SphereQuadraticExtremum {
  Status status = Status::empty_input;  ///< ok, invalid_input, non_finite_input, limit_exceeded
  Vec<T, N> x{};
  T value{};           ///< f(x)
  T multiplier{};      ///< mu with grad f(x) = 2 mu (x - center)
  bool unique = true;  ///< false in the hard case with more than one minimiser
  int iterations = 0;
};

namespace detail {

template <class C, class T, int N>
[[nodiscard]] MatX<C> to_matx(const Mat<T, N, N>& a) {
  MatX<C> m(N, N);
  for (int r = 0; r < N; ++r)
    for (int c = r; c < N; ++c) m(r, c) = m(c, r) = C(a(r, c));
  return m;
}

template <class T, int N>
[[nodiscard]] Status check_quadratic(const Mat<T, N, N>& a, const Vec<T, N>& b, T c) noexcept {
  if (!is_finite(a) || !is_finite(b) || !is_finite(c)) return Status::non_finite_input;
  T m = T(0);
  for (int r = 0; r < N; ++r)
    for (int k = 0; k < N; ++k) m = std::max(m, std::abs(a(r, k)));
  for (int r = 0; r < N; ++r)
    for (int k = r + 1; k < N; ++k)
      if (std::abs(a(r, k) - a(k, r)) > T(64) * eps_v<T> * m) return Status::invalid_input;
  return Status::ok;
}

template <class C, class T, int N>
[[nodiscard]] C eval_quadratic(const MatX<C>& a, const Vec<T, N>& b, C c,
                               const std::vector<C>& x) noexcept {
  C s = c;
  for (int r = 0; r < N; ++r) {
    C ax = C(0);
    for (int k = 0; k < N; ++k) ax += a(r, k) * x[std::size_t(k)];
    s += x[std::size_t(r)] * (ax + C(b[r]));
  }
  return s;
}

// Minimiser of y^T H y + g^T y by the eigendecomposition of H (n x n): y = -pinv(H) g / 2 over
// the eigenvalues above the definiteness threshold; `definite` reports whether all are.
template <class C>
[[nodiscard]] std::vector<C> min_quadratic_eig(const MatX<C>& h, const std::vector<C>& g, C tol,
                                               bool& definite) {
  const int n = h.rows;
  std::vector<C> y(static_cast<std::size_t>(n), C(0));
  definite = true;
  if (n == 0) return y;
  const SymmetricEigenX<C> e = eigen_symmetric(h);
  C lmax = C(0);
  for (C l : e.values) lmax = std::max(lmax, std::abs(l));
  for (int i = 0; i < n; ++i) {
    const C l = e.values[std::size_t(i)];
    if (!(l > tol * lmax)) {
      definite = false;
      continue;
    }
    C gi = C(0);
    for (int k = 0; k < n; ++k) gi += e.vectors(k, i) * g[std::size_t(k)];
    const C s = -gi / (C(2) * l);
    for (int k = 0; k < n; ++k) y[std::size_t(k)] += s * e.vectors(k, i);
  }
  if (lmax == C(0)) definite = false;
  return y;
}

template <class C>
[[nodiscard]] C definite_tol(C requested, int n) noexcept {
  return requested >= C(0) ? requested : C(16) * C(n) * eps_v<C>;
}

}  // namespace detail

/// Minimiser of f(x) = x^T A x + b^T x + c for symmetric A (see the top comment).
template <class T, int N>
[[nodiscard]] QuadraticMinimum<T, N> minimize_quadratic(const Mat<T, N, N>& a, const Vec<T, N>& b,
                                                        T c = T(0),
                                                        const QuadraticOptions<T>& opt = {}) {
  using C = compute_t<T>;
  QuadraticMinimum<T, N> out;
  out.status = Status::ok;
  out.status = detail::check_quadratic(a, b, c);
  if (out.status != Status::ok) {
    out.value = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  const MatX<C> h = detail::to_matx<C>(a);
  std::vector<C> g(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) g[std::size_t(i)] = C(b[i]);
  bool definite = true;
  const std::vector<C> x =
      detail::min_quadratic_eig(h, g, detail::definite_tol(C(opt.definite_tolerance), N), definite);
  for (int i = 0; i < N; ++i) out.x[i] = T(x[std::size_t(i)]);
  out.value = T(detail::eval_quadratic(h, b, C(c), x));
  if (!definite) out.status = Status::degenerate_input;
  return out;
}

/// Minimiser of f(x) = x^T A x + b^T x + c subject to C x = d (M <= N independent rows).
template <class T, int N, int M>
[[nodiscard]] QuadraticMinimum<T, N, M> minimize_quadratic(const Mat<T, N, N>& a,
                                                           const Vec<T, N>& b, T c,
                                                           const Mat<T, M, N>& constraint,
                                                           const Vec<T, M>& rhs,
                                                           const QuadraticOptions<T>& opt = {}) {
  static_assert(M <= N, "minimize_quadratic: more constraints than unknowns");
  using C = compute_t<T>;
  QuadraticMinimum<T, N, M> out;
  out.status = Status::ok;
  out.status = detail::check_quadratic(a, b, c);
  if (out.status == Status::ok && (!is_finite(constraint) || !is_finite(rhs)))
    out.status = Status::non_finite_input;
  if (out.status != Status::ok) {
    out.value = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  // C^T = Q R: the first M columns of Q span the row space of C, the rest its null space.
  MatX<C> ct(N, M);
  for (int r = 0; r < M; ++r)
    for (int k = 0; k < N; ++k) ct(k, r) = C(constraint(r, k));
  const QR<C> f = qr(ct);
  C rmax = C(0);
  for (int i = 0; i < M; ++i) rmax = std::max(rmax, std::abs(f.r(i, i)));
  for (int i = 0; i < M; ++i)
    if (!(std::abs(f.r(i, i)) > C(8) * C(N) * eps_v<C> * rmax)) {
      out.status = Status::degenerate_input;  // dependent (redundant or inconsistent) rows
      out.value = std::numeric_limits<T>::quiet_NaN();
      return out;
    }
  // Particular solution x_p = Q1 z with R1^T z = d (forward substitution).
  std::vector<C> z(static_cast<std::size_t>(M));
  for (int i = 0; i < M; ++i) {
    C s = C(rhs[i]);
    for (int k = 0; k < i; ++k) s -= f.r(k, i) * z[std::size_t(k)];
    z[std::size_t(i)] = s / f.r(i, i);
  }
  std::vector<C> x(static_cast<std::size_t>(N), C(0));
  for (int k = 0; k < N; ++k)
    for (int i = 0; i < M; ++i) x[std::size_t(k)] += f.q(k, i) * z[std::size_t(i)];
  const MatX<C> h = detail::to_matx<C>(a);
  bool definite = true;
  const int nz = N - M;
  if (nz > 0) {
    // Reduced problem on x_p + Z y: y^T (Z^T A Z) y + (Z^T (2 A x_p + b))^T y + const.
    std::vector<C> grad(static_cast<std::size_t>(N));
    for (int r = 0; r < N; ++r) {
      C s = C(b[r]);
      for (int k = 0; k < N; ++k) s += C(2) * h(r, k) * x[std::size_t(k)];
      grad[std::size_t(r)] = s;
    }
    MatX<C> az(N, nz), hz(nz, nz);
    for (int r = 0; r < N; ++r)
      for (int j = 0; j < nz; ++j) {
        C s = C(0);
        for (int k = 0; k < N; ++k) s += h(r, k) * f.q(k, M + j);
        az(r, j) = s;
      }
    std::vector<C> gz(static_cast<std::size_t>(nz), C(0));
    for (int i = 0; i < nz; ++i) {
      for (int j = 0; j < nz; ++j) {
        C s = C(0);
        for (int k = 0; k < N; ++k) s += f.q(k, M + i) * az(k, j);
        hz(i, j) = s;
      }
      for (int k = 0; k < N; ++k) gz[std::size_t(i)] += f.q(k, M + i) * grad[std::size_t(k)];
    }
    for (int i = 0; i < nz; ++i)  // symmetrise the rounded product
      for (int j = i + 1; j < nz; ++j) hz(i, j) = hz(j, i) = (hz(i, j) + hz(j, i)) / C(2);
    const std::vector<C> y = detail::min_quadratic_eig(
        hz, gz, detail::definite_tol(C(opt.definite_tolerance), N), definite);
    for (int k = 0; k < N; ++k)
      for (int j = 0; j < nz; ++j) x[std::size_t(k)] += f.q(k, M + j) * y[std::size_t(j)];
  }
  // Multipliers: R1 lambda = -Q1^T (2 A x + b) (back substitution).
  std::vector<C> grad(static_cast<std::size_t>(N));
  for (int r = 0; r < N; ++r) {
    C s = C(b[r]);
    for (int k = 0; k < N; ++k) s += C(2) * h(r, k) * x[std::size_t(k)];
    grad[std::size_t(r)] = s;
  }
  std::vector<C> lam(static_cast<std::size_t>(M));
  for (int i = M - 1; i >= 0; --i) {
    C s = C(0);
    for (int k = 0; k < N; ++k) s -= f.q(k, i) * grad[std::size_t(k)];
    for (int k = i + 1; k < M; ++k) s -= f.r(i, k) * lam[std::size_t(k)];
    lam[std::size_t(i)] = s / f.r(i, i);
  }
  for (int k = 0; k < N; ++k) out.x[k] = T(x[std::size_t(k)]);
  for (int i = 0; i < M; ++i) out.multipliers[i] = T(lam[std::size_t(i)]);
  out.value = T(detail::eval_quadratic(h, b, C(c), x));
  if (!definite) out.status = Status::degenerate_input;
  return out;
}

/// Global minimiser of f(x) = x^T A x + b^T x + c on the sphere |x - center| = radius.
template <class T, int N>
[[nodiscard]] SphereQuadraticExtremum<T, N> minimize_quadratic_on_sphere(
    const Mat<T, N, N>& a, const Vec<T, N>& b, T c, const Vec<T, N>& center, T radius,
    const QuadraticOptions<T>& opt = {}) {
  using C = compute_t<T>;
  SphereQuadraticExtremum<T, N> out;
  out.status = Status::ok;
  out.status = detail::check_quadratic(a, b, c);
  if (out.status == Status::ok && (!is_finite(center) || !is_finite(radius)))
    out.status = Status::non_finite_input;
  if (out.status == Status::ok && radius < T(0)) out.status = Status::invalid_input;
  if (out.status != Status::ok) {
    out.value = out.multiplier = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  const MatX<C> h = detail::to_matx<C>(a);
  // y = x - center: f = y^T A y + g^T y + const with g = b + 2 A center.
  std::vector<C> g(static_cast<std::size_t>(N));
  for (int r = 0; r < N; ++r) {
    C s = C(b[r]);
    for (int k = 0; k < N; ++k) s += C(2) * h(r, k) * C(center[k]);
    g[std::size_t(r)] = s;
  }
  const C r = C(radius);
  std::vector<C> y(static_cast<std::size_t>(N), C(0));
  C mu = C(0);
  // radius 0: the sphere is the point center (y = 0); the multiplier is undetermined, 0.
  const SymmetricEigenX<C> e = eigen_symmetric(h);
  if (e.status == Status::limit_exceeded) out.status = Status::limit_exceeded;
  std::vector<C> gamma(static_cast<std::size_t>(N), C(0));  // half the gradient in the eigenbasis
  for (int i = 0; i < N; ++i) {
    C s = C(0);
    for (int k = 0; k < N; ++k) s += e.vectors(k, i) * g[std::size_t(k)];
    gamma[std::size_t(i)] = s / C(2);
  }
  C lscale = C(0);
  for (C l : e.values) lscale = std::max(lscale, std::abs(l));
  const C l0 = e.values[0];
  // Eigenvalues within the solver's accuracy of lambda_min form the lowest eigenspace.
  const C cluster = C(16) * C(N) * eps_v<C> * lscale;
  auto in_cluster = [&](int i) { return e.values[std::size_t(i)] - l0 <= cluster; };
  C g_low = C(0), g_norm = C(0);
  for (int i = 0; i < N; ++i) {
    g_norm += sqr(gamma[std::size_t(i)]);
    if (in_cluster(i)) g_low += sqr(gamma[std::size_t(i)]);
  }
  g_norm = std::sqrt(g_norm);
  g_low = std::sqrt(g_low);
  // |y(mu)| in the eigenbasis, and its derivative in mu.
  auto ynorm = [&](C m, C& dnorm) {
    C s = C(0), ds = C(0);
    for (int i = 0; i < N; ++i) {
      const C d = e.values[std::size_t(i)] - m;
      const C yi = gamma[std::size_t(i)] / d;
      s += yi * yi;
      ds += yi * yi / d;
    }
    const C nrm = std::sqrt(s);
    dnorm = nrm > C(0) ? ds / nrm : C(0);
    return nrm;
  };
  // The part of y outside the lowest eigenspace at mu = lambda_min (the hard-case test).
  C yp = C(0);
  for (int i = 0; i < N; ++i)
    if (!in_cluster(i)) yp += sqr(gamma[std::size_t(i)] / (e.values[std::size_t(i)] - l0));
  yp = std::sqrt(yp);
  bool hard = false;
  int it = 0;
  if (r > C(0)) {
    if (g_low <= eps_v<C> * g_norm && yp < r) {
      hard = true;
    } else {
      // Root of psi(mu) = 1/|y(mu)| - 1/r in [l0 - |gamma|/r, l0): |y| <= |gamma| / (l0 - mu)
      // makes psi >= 0 at the left end; psi -> -1/r as mu -> l0 (g_low != 0).
      C lo = l0 - g_norm / r, hi = l0;
      mu = lo;
      bool converged = false;
      for (; it < opt.max_iterations; ++it) {
        C dn;
        const C n = ynorm(mu, dn);
        if (!(n > C(0)) || !is_finite(n)) {  // too close to l0: move left
          hi = mu;
          mu = lo + (hi - lo) / C(2);
          continue;
        }
        const C psi = C(1) / n - C(1) / r;
        if (std::abs(n - r) <= C(4) * eps_v<C> * r) {
          converged = true;
          break;
        }
        if (psi > C(0))
          lo = mu;
        else
          hi = mu;
        const C dpsi = -dn / (n * n);
        C next = dpsi != C(0) ? mu - psi / dpsi : (lo + hi) / C(2);
        if (!(next > lo && next < hi)) next = lo + (hi - lo) / C(2);
        if (next == mu || hi - lo <= C(2) * eps_v<C> * std::max(std::abs(lo), std::abs(hi))) {
          converged = true;
          break;
        }
        mu = next;
      }
      if (l0 - mu <= cluster && yp < r) hard = true;  // numerically the hard case
      if (!hard) {
        for (int i = 0; i < N; ++i) {
          const C yi = -gamma[std::size_t(i)] / (e.values[std::size_t(i)] - mu);
          for (int k = 0; k < N; ++k) y[std::size_t(k)] += yi * e.vectors(k, i);
        }
        // Project onto the sphere exactly (removes the residual of the root find).
        C ny = C(0);
        for (C v : y) ny += v * v;
        ny = std::sqrt(ny);
        if (ny > C(0))
          for (C& v : y) v *= r / ny;
        if (!converged) out.status = Status::limit_exceeded;
      }
    }
    if (hard) {
      mu = l0;
      std::vector<C> dir(static_cast<std::size_t>(N), C(0));
      for (int i = 0; i < N; ++i) {
        if (in_cluster(i)) continue;
        const C yi = -gamma[std::size_t(i)] / (e.values[std::size_t(i)] - l0);
        for (int k = 0; k < N; ++k) y[std::size_t(k)] += yi * e.vectors(k, i);
      }
      // The missing length goes along the lowest eigenspace: along -gamma's component there if
      // it is not exactly zero (the continuous choice), else along its first eigenvector.
      C dl = C(0);
      for (int i = 0; i < N; ++i)
        if (in_cluster(i))
          for (int k = 0; k < N; ++k)
            dir[std::size_t(k)] -= gamma[std::size_t(i)] * e.vectors(k, i);
      for (C v : dir) dl += v * v;
      dl = std::sqrt(dl);
      if (dl > C(0)) {
        for (C& v : dir) v /= dl;
      } else {
        for (int k = 0; k < N; ++k) dir[std::size_t(k)] = e.vectors(k, 0);
      }
      const C tau = std::sqrt(std::max(C(0), r * r - yp * yp));
      for (int k = 0; k < N; ++k) y[std::size_t(k)] += tau * dir[std::size_t(k)];
      out.unique = tau == C(0);
    }
  }
  std::vector<C> x(static_cast<std::size_t>(N));
  for (int k = 0; k < N; ++k) {
    x[std::size_t(k)] = C(center[k]) + y[std::size_t(k)];
    out.x[k] = T(x[std::size_t(k)]);
  }
  out.value = T(detail::eval_quadratic(h, b, C(c), x));
  out.multiplier = T(mu);
  out.iterations = it;
  return out;
}

/// Global maximiser of f(x) = x^T A x + b^T x + c on the sphere |x - center| = radius (the
/// minimiser of -f; value is f(x) and the multiplier satisfies grad f(x) = 2 mu (x - center)).
template <class T, int N>
[[nodiscard]] SphereQuadraticExtremum<T, N> maximize_quadratic_on_sphere(
    const Mat<T, N, N>& a, const Vec<T, N>& b, T c, const Vec<T, N>& center, T radius,
    const QuadraticOptions<T>& opt = {}) {
  SphereQuadraticExtremum<T, N> out = minimize_quadratic_on_sphere(-a, -b, -c, center, radius, opt);
  out.value = -out.value;
  out.multiplier = -out.multiplier;
  return out;
}

}  // namespace locus
