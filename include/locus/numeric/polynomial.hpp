// SPDX-License-Identifier: BSL-1.0
#pragma once
// Polynomial<T>: univariate polynomials of any degree, their arithmetic, and the classical tools
// for reasoning about their real roots (row num.roots; book appendix A, figures A.9, A.10).
// Representation: `coeff[i]` multiplies x^i (low to high). Every constructor and every function
// returning a Polynomial removes trailing coefficients that are exactly zero; the zero
// polynomial has no coefficients and degree() == -1. A tiny non-zero leading coefficient is kept
// (it is data: the polynomial has large roots); trim(p, tol) drops coefficients known to be noise.
// Stored trailing zeros are handled correctly everywhere (degree() scans).
// T is any field type with +, -, *, / and comparison with T(0): float, double, or an exact type
// such as GMP's mpq_class (then everything is exact). Root bounds, evaluate_with_bound and gcd's
// tolerance need floating-point T (the Real concept). In floating point, divide sets the leading
// term to zero exactly; gcd treats a remainder whose coefficients are all <= rel_tol * (largest
// coefficient of the divisor) as zero; the Sturm sequence is only as reliable as the remainders
// (real_roots() in roots.hpp builds its own in exact integers).
// Degenerate input: division by the zero polynomial returns Status::degenerate_input (quotient 0,
// remainder = dividend). gcd(0, 0) = 0. NaN/Inf coefficients propagate through arithmetic by IEEE
// rules; use is_finite(p) to check, and the root finders report Status::non_finite_input.
// Cost: add O(n), multiply/compose O(n m) / O(n^2 m), divide O(n m), gcd O(n^2), Sturm
// sequence O(n^2), one evaluation O(n). Arithmetic allocates (std::vector); the fixed-degree
// solvers in roots.hpp do not.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <utility>
#include <vector>

namespace locus {

/// A univariate polynomial; coeff[i] multiplies x^i. See the header comment for trimming.
template <Field T>
struct Polynomial {
  std::vector<T> coeff;

  Polynomial() = default;
  /// Coefficients low to high: Polynomial<double>{c0, c1, c2} is c0 + c1 x + c2 x^2.
  Polynomial(std::initializer_list<T> c) : coeff(c) { trim_exact(); }
  explicit Polynomial(std::vector<T> c) : coeff(std::move(c)) { trim_exact(); }

  /// The constant polynomial c (the zero polynomial when c == 0).
  [[nodiscard]] static Polynomial constant(const T& c) { return Polynomial(std::vector<T>{c}); }
  /// The monomial c x^k.
  [[nodiscard]] static Polynomial monomial(const T& c, int k) {
    std::vector<T> v(static_cast<std::size_t>(k) + 1, T(0));
    v.back() = c;
    return Polynomial(std::move(v));
  }

  /// Degree, -1 for the zero polynomial (trailing exact zeros are ignored).
  [[nodiscard]] int degree() const noexcept {
    int d = static_cast<int>(coeff.size()) - 1;
    while (d >= 0 && coeff[static_cast<std::size_t>(d)] == T(0)) --d;
    return d;
  }
  [[nodiscard]] bool is_zero() const noexcept { return degree() < 0; }
  /// Coefficient of x^i; zero beyond the stored coefficients (and for i < 0).
  [[nodiscard]] T operator[](int i) const {
    return i >= 0 && i < static_cast<int>(coeff.size()) ? coeff[static_cast<std::size_t>(i)] : T(0);
  }
  /// Leading coefficient (0 for the zero polynomial).
  [[nodiscard]] T leading() const {
    const int d = degree();
    return d < 0 ? T(0) : coeff[static_cast<std::size_t>(d)];
  }
  /// Horner evaluation.
  [[nodiscard]] T operator()(const T& x) const {
    T r = T(0);
    for (int i = degree(); i >= 0; --i) r = r * x + coeff[static_cast<std::size_t>(i)];
    return r;
  }

  /// Removes trailing coefficients equal to zero (the library-wide trimming rule).
  void trim_exact() {
    while (!coeff.empty() && coeff.back() == T(0)) coeff.pop_back();
  }
};

/// p with every coefficient of magnitude <= abs_tol replaced by zero, then trimmed. For floating
/// point data whose small coefficients are known to be noise.
template <Real T>
[[nodiscard]] Polynomial<T> trim(Polynomial<T> p, T abs_tol) {
  for (auto& c : p.coeff)
    if (std::abs(c) <= abs_tol) c = T(0);
  p.trim_exact();
  return p;
}

/// True when every coefficient is finite.
template <Real T>
[[nodiscard]] bool is_finite(const Polynomial<T>& p) noexcept {
  for (const T& c : p.coeff)
    if (!locus::is_finite(c)) return false;
  return true;
}

template <Field T>
[[nodiscard]] bool operator==(const Polynomial<T>& a, const Polynomial<T>& b) {
  const int d = a.degree();
  if (d != b.degree()) return false;
  for (int i = 0; i <= d; ++i)
    if (!(a[i] == b[i])) return false;
  return true;
}

template <Field T>
[[nodiscard]] Polynomial<T> operator-(const Polynomial<T>& a) {
  std::vector<T> r(static_cast<std::size_t>(a.degree() + 1));
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = -a.coeff[i];
  return Polynomial<T>(std::move(r));
}

template <Field T>
[[nodiscard]] Polynomial<T> operator+(const Polynomial<T>& a, const Polynomial<T>& b) {
  const int n = std::max(a.degree(), b.degree());
  std::vector<T> r(static_cast<std::size_t>(n + 1));
  for (int i = 0; i <= n; ++i) r[static_cast<std::size_t>(i)] = a[i] + b[i];
  return Polynomial<T>(std::move(r));
}

template <Field T>
[[nodiscard]] Polynomial<T> operator-(const Polynomial<T>& a, const Polynomial<T>& b) {
  const int n = std::max(a.degree(), b.degree());
  std::vector<T> r(static_cast<std::size_t>(n + 1));
  for (int i = 0; i <= n; ++i) r[static_cast<std::size_t>(i)] = a[i] - b[i];
  return Polynomial<T>(std::move(r));
}

template <Field T>
[[nodiscard]] Polynomial<T> operator*(const Polynomial<T>& a, const Polynomial<T>& b) {
  const int da = a.degree(), db = b.degree();
  if (da < 0 || db < 0) return {};
  std::vector<T> r(static_cast<std::size_t>(da + db + 1), T(0));
  for (int i = 0; i <= da; ++i)
    for (int j = 0; j <= db; ++j) r[static_cast<std::size_t>(i + j)] += a[i] * b[j];
  return Polynomial<T>(std::move(r));
}

template <Field T>
[[nodiscard]] Polynomial<T> operator*(const Polynomial<T>& a, const T& s) {
  std::vector<T> r(static_cast<std::size_t>(a.degree() + 1));
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = a.coeff[i] * s;
  return Polynomial<T>(std::move(r));
}
template <Field T>
[[nodiscard]] Polynomial<T> operator*(const T& s, const Polynomial<T>& a) {
  return a * s;
}

/// Quotient and remainder of a / b: a = quotient * b + remainder, deg remainder < deg b.
template <Field T>
struct PolynomialDivision {
  Status status = Status::ok;  ///< degenerate_input when b is the zero polynomial
  Polynomial<T> quotient;
  Polynomial<T> remainder;
};

/// Long division. With floating-point T the eliminated leading term of each step is set to zero
/// exactly rather than computed, so the remainder's degree is always < deg b.
template <Field T>
[[nodiscard]] PolynomialDivision<T> divide(const Polynomial<T>& a, const Polynomial<T>& b) {
  PolynomialDivision<T> out;
  const int da = a.degree(), db = b.degree();
  if (db < 0) {
    out.status = Status::degenerate_input;
    out.remainder = a;
    return out;
  }
  if (da < db) {
    out.remainder = a;
    out.remainder.trim_exact();
    return out;
  }
  std::vector<T> r(a.coeff.begin(), a.coeff.begin() + da + 1);
  std::vector<T> q(static_cast<std::size_t>(da - db + 1), T(0));
  const T lb = b[db];
  for (int k = da - db; k >= 0; --k) {
    const T f = r[static_cast<std::size_t>(k + db)] / lb;
    q[static_cast<std::size_t>(k)] = f;
    r[static_cast<std::size_t>(k + db)] = T(0);
    for (int j = 0; j < db; ++j) r[static_cast<std::size_t>(k + j)] -= f * b[j];
  }
  r.resize(static_cast<std::size_t>(db));
  out.quotient = Polynomial<T>(std::move(q));
  out.remainder = Polynomial<T>(std::move(r));
  return out;
}

/// The derivative p'.
template <Field T>
[[nodiscard]] Polynomial<T> derivative(const Polynomial<T>& p) {
  const int n = p.degree();
  if (n <= 0) return {};
  std::vector<T> r(static_cast<std::size_t>(n));
  for (int i = 1; i <= n; ++i) r[static_cast<std::size_t>(i - 1)] = p[i] * T(i);
  return Polynomial<T>(std::move(r));
}

/// The composition p(q(x)), by Horner's scheme in the polynomial ring.
template <Field T>
[[nodiscard]] Polynomial<T> compose(const Polynomial<T>& p, const Polynomial<T>& q) {
  Polynomial<T> r;
  for (int i = p.degree(); i >= 0; --i) r = r * q + Polynomial<T>::constant(p[i]);
  return r;
}

/// p divided by its leading coefficient (the zero polynomial stays zero).
template <Field T>
[[nodiscard]] Polynomial<T> monic(const Polynomial<T>& p) {
  const int n = p.degree();
  if (n < 0) return {};
  std::vector<T> r(static_cast<std::size_t>(n + 1));
  const T l = p[n];
  for (int i = 0; i < n; ++i) r[static_cast<std::size_t>(i)] = p[i] / l;
  r[static_cast<std::size_t>(n)] = T(1);
  return Polynomial<T>(std::move(r));
}

namespace detail {
template <Field T>
T max_abs_coeff(const Polynomial<T>& p) {
  T m = T(0);
  for (int i = 0; i <= p.degree(); ++i) m = std::max(m, std::abs(p[i]));
  return m;
}
}  // namespace detail

/// The monic greatest common divisor by Euclid's algorithm (gcd(0, 0) = 0). Exact for exact T.
/// For floating-point T a remainder whose coefficients are all <= rel_tol times the largest
/// coefficient of the current divisor counts as zero; the default 1e3 * eps suits data that is
/// exact up to a few roundings; noisier data needs a larger tolerance (the gcd of perturbed
/// polynomials is ill-posed, the tolerance says how much perturbation is forgiven).
template <Field T>
[[nodiscard]] Polynomial<T> gcd(Polynomial<T> a, Polynomial<T> b,
                                [[maybe_unused]] double rel_tol = -1.0) {
  if (a.degree() < b.degree()) std::swap(a, b);
  for (int guard = 0; guard <= a.degree() + 2 && !b.is_zero(); ++guard) {
    Polynomial<T> r = divide(a, b).remainder;
    if constexpr (Real<T>) {
      const T tol =
          static_cast<T>(rel_tol < 0 ? 1e3 * double(eps_v<T>) : rel_tol) * detail::max_abs_coeff(b);
      if (!(detail::max_abs_coeff(r) > tol)) r = Polynomial<T>{};
    }
    a = std::move(b);
    b = std::move(r);
  }
  return monic(a);
}

/// Horner's value and Higham's running error bound |value - p(x)| <= error_bound (Accuracy and
/// Stability of Numerical Algorithms, 2nd ed., Algorithm 5.1; first order in eps, which we
/// cover with a factor (1 + 4 n eps)). x and the coefficients are taken as exact.
template <Field T>
struct EvaluationWithBound {
  T value;
  T error_bound;
};

template <Real T>
[[nodiscard]] EvaluationWithBound<T> evaluate_with_bound(const Polynomial<T>& p, T x) noexcept {
  const int n = p.degree();
  if (n < 0) return {T(0), T(0)};
  T y = p[n];
  T mu = std::abs(y) / T(2);
  const T ax = std::abs(x);
  for (int i = n - 1; i >= 0; --i) {
    y = y * x + p[i];
    mu = ax * mu + std::abs(y);
  }
  const T u = eps_v<T> / T(2);
  const T bound = u * (T(2) * mu - std::abs(y)) * (T(1) + T(4 * (n + 1)) * eps_v<T>);
  return {y, bound};
}

/// Cauchy's bound: every complex root z satisfies |z| <= 1 + max_{i<n} |a_i / a_n|.
/// Returns 0 for constants, +infinity for the zero polynomial (every x is a root).
template <Real T>
[[nodiscard]] T cauchy_root_bound(const Polynomial<T>& p) noexcept {
  const int n = p.degree();
  if (n < 0) return std::numeric_limits<T>::infinity();
  if (n == 0) return T(0);
  T m = T(0);
  for (int i = 0; i < n; ++i) m = std::max(m, std::abs(p[i] / p[n]));
  return T(1) + m;
}

/// Fujiwara's bound, within a factor 2 of the largest root modulus:
/// |z| <= 2 max(|a_{n-1}/a_n|, |a_{n-2}/a_n|^(1/2), ..., |a_0/(2 a_n)|^(1/n)).
/// Returns 0 for constants, +infinity for the zero polynomial.
template <Real T>
[[nodiscard]] T fujiwara_root_bound(const Polynomial<T>& p) noexcept {
  const int n = p.degree();
  if (n < 0) return std::numeric_limits<T>::infinity();
  if (n == 0) return T(0);
  T m = T(0);
  for (int i = 0; i < n; ++i) {
    T r = std::abs(p[i] / p[n]);
    if (i == 0) r /= T(2);
    m = std::max(m, std::pow(r, T(1) / T(n - i)));
  }
  return T(2) * m;
}

/// The Sturm sequence p, p', -rem(p, p'), ..., g = gcd(p, p') (up to a constant), every member
/// divided by g when g is not constant, so that multiple roots do not make the whole sequence
/// vanish: the sign variations then count distinct roots everywhere. Exact for exact T; for
/// floating-point T see the header comment. Empty for the zero polynomial.
template <Field T>
[[nodiscard]] std::vector<Polynomial<T>> sturm_sequence(const Polynomial<T>& p) {
  std::vector<Polynomial<T>> s;
  if (p.is_zero()) return s;
  s.push_back(p);
  Polynomial<T> d = derivative(p);
  while (!d.is_zero()) {
    s.push_back(d);
    const std::size_t k = s.size();
    d = -divide(s[k - 2], s[k - 1]).remainder;
  }
  if (s.back().degree() > 0) {
    const Polynomial<T> g = s.back();
    for (auto& q : s) q = divide(q, g).quotient;
  }
  return s;
}

namespace detail {
template <Field T>
int sign_variations(const std::vector<Polynomial<T>>& seq, const T& x) {
  int count = 0, last = 0;
  for (const auto& q : seq) {
    const T v = q(x);
    const int s = v > T(0) ? 1 : (v < T(0) ? -1 : 0);
    if (s != 0) {
      if (last != 0 && s != last) ++count;
      last = s;
    }
  }
  return count;
}
}  // namespace detail

/// Number of distinct real roots in (a, b] from a Sturm sequence (0 unless a < b). Exact for
/// exact T.
template <Field T>
[[nodiscard]] int sturm_count(const std::vector<Polynomial<T>>& seq, const T& a, const T& b) {
  if (seq.empty() || !(a < b)) return 0;
  return detail::sign_variations(seq, a) - detail::sign_variations(seq, b);
}

template <Field T>
[[nodiscard]] int sturm_count(const Polynomial<T>& p, const T& a, const T& b) {
  return sturm_count(sturm_sequence(p), a, b);
}

}  // namespace locus
