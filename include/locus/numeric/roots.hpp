// SPDX-License-Identifier: BSL-1.0
#pragma once
// Real roots of polynomials (row num.roots; book appendix A, figures A.9, A.10): solve_linear ..
// solve_quartic for degree <= 4 (fixed arrays) and real_roots(p, a, b) for any degree, from a
// Polynomial or a span of float/double coefficients. Coefficients are LOW TO HIGH everywhere:
// solve_quadratic(c0, c1, c2) solves c0 + c1 x + c2 x^2 = 0. Results list the DISTINCT real roots
// in increasing order with their multiplicities.
//
// Two modes (RootOptions::mode; derivations and measurements in docs/notes/numeric.md):
//  * RootMode::exact, the default of real_roots: the roots of the polynomial exactly as given,
//    each coefficient taken as the exact dyadic rational it is. Certified with exact integer
//    arithmetic (Sturm sequences of the gcd chain p, gcd(p, p'), ...): no root is invented or
//    lost, multiplicities are those of the given polynomial, and each value is the exact root
//    correctly rounded to T (ties to even). Distinct roots closer than an ulp may share a value.
//  * RootMode::near, the default of solve_*: floating point (in double), derivative recursion
//    with compensated evaluation; simple roots to about one ulp. A turning point within the
//    evaluation noise of zero (plus the caller's tolerances) is reported as a multiple root,
//    which is what coefficients carrying error need (tangencies); it is 80-190x faster.
//    Clusters closer than about sqrt(noise) come out as one root with their total multiplicity.
// Bad input: a NaN or infinite coefficient gives Status::non_finite_input; the zero polynomial
// Status::degenerate_input; a non-zero constant ok with no roots. Roots beyond the range of T
// are dropped. An exhausted budget gives Status::limit_exceeded (see RootOptions).
// Cost: near, degree 4 about 0.3-0.8 us, degree n O(n^2) Newton steps, no allocation in solve_*;
// exact, polynomial in the degree and the coefficients' bit length, allocates
// (bench/numeric/roots_bench.cpp).

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/numeric/polynomial.hpp>

#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

namespace locus {

/// A real root and its multiplicity.
template <Real T>
struct Root {
  T value;
  int multiplicity;
};

/// How roots are decided (see the header comment): exact roots of the given coefficients, or
/// floating point with multiple roots detected within noise (for speed, or for coefficients
/// that carry error).
enum class RootMode { exact, near };

/// Options of the root finders. In near mode, how far from zero a local extremum of p may be and
/// still count as touching zero (a multiple root): the tolerance at x is the evaluation noise of
/// double, gamma_{2n+1} sum |a_i| |x|^i, plus multiplicity_tolerance * sum |a_i| |x|^i, plus
/// sum coefficient_error[i] |x|^i (absolute error bounds of the coefficients; with an exactly
/// zero constant term, low coefficients within their bounds count as zero too). Exact mode
/// ignores both and gives up after max_exact_bisections interval halvings below one ulp (roots
/// closer than an ulp), and for degree > max_exact_degree, with Status::limit_exceeded (then
/// such roots are reported once, with the number of distinct roots as their multiplicity).
struct RootOptions {
  RootMode mode = RootMode::exact;
  double multiplicity_tolerance = 0.0;
  std::span<const double> coefficient_error{};
  int max_exact_bisections = 4096;
  int max_exact_degree = 256;
};

/// Roots of a polynomial of degree <= 4: no allocation in near mode.
template <Real T>
struct RootsResult {
  Status status = Status::empty_input;  ///< ok, non_finite_input, degenerate_input, limit_exceeded
  int count = 0;                        ///< number of distinct real roots
  std::array<Root<T>, 4> roots{};

  [[nodiscard]] const Root<T>* begin() const noexcept { return roots.data(); }
  [[nodiscard]] const Root<T>* end() const noexcept { return roots.data() + count; }
  [[nodiscard]] int total_multiplicity() const noexcept {
    int m = 0;
    for (int i = 0; i < count; ++i) m += roots[static_cast<std::size_t>(i)].multiplicity;
    return m;
  }
};

/// Roots of a polynomial of any degree (roots.size() distinct roots).
template <Real T>
struct RealRootsResult {
  Status status = Status::empty_input;  ///< ok, non_finite_input, degenerate_input, limit_exceeded
  std::vector<Root<T>> roots;           ///< distinct real roots, increasing

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

/// Work space size for degree n (the derivative chains of p and of its coefficient errors).
inline constexpr std::size_t work_doubles(int n) noexcept {
  return static_cast<std::size_t>((n + 1) * (n + 2));
}

/// The near-mode engine (src/numeric/roots.cpp): distinct real roots of a[0..n] (finite; exact
/// trailing zeros are trimmed), err: optional coefficient error bounds, work: work_doubles(n)
/// doubles, r1, r2: n entries each. Returns the number of roots, written to r1 increasing.
int real_roots_engine(const double* a, const double* err, int n, double* work, R* r1, R* r2,
                      double rtol, bool& budget_hit) noexcept;

/// The exact engine (src/numeric/roots_exact.cpp): roots of a[0..n] (finite, not all zero) in
/// [lo, hi], appended to out. Returns ok or limit_exceeded.
template <Real T>
Status exact_real_roots(std::span<const double> a, T lo, T hi, const RootOptions& opt,
                        std::vector<Root<T>>& out);
extern template Status exact_real_roots<float>(std::span<const double>, float, float,
                                               const RootOptions&, std::vector<Root<float>>&);
extern template Status exact_real_roots<double>(std::span<const double>, double, double,
                                                const RootOptions&, std::vector<Root<double>>&);

template <class T, std::size_t N>
RootsResult<T> solve_fixed(const std::array<T, N>& c, const RootOptions& opt) noexcept;
#define LOCUS_ROOTS_EXTERN(T, N) \
  extern template RootsResult<T> solve_fixed<T, N>(const std::array<T, N>&, const RootOptions&);
LOCUS_ROOTS_EXTERN(float, 2)
LOCUS_ROOTS_EXTERN(float, 3)
LOCUS_ROOTS_EXTERN(float, 4)
LOCUS_ROOTS_EXTERN(float, 5)
LOCUS_ROOTS_EXTERN(double, 2)
LOCUS_ROOTS_EXTERN(double, 3)
LOCUS_ROOTS_EXTERN(double, 4)
LOCUS_ROOTS_EXTERN(double, 5)
#undef LOCUS_ROOTS_EXTERN

template <Real T>
RealRootsResult<T> real_roots_span(std::span<const T> c, T a, T b, const RootOptions& opt);
extern template RealRootsResult<float> real_roots_span<float>(std::span<const float>, float, float,
                                                              const RootOptions&);
extern template RealRootsResult<double> real_roots_span<double>(std::span<const double>, double,
                                                                double, const RootOptions&);

}  // namespace detail::roots

/// Options for the fixed-degree solvers: near mode (their default; see the header comment).
inline RootOptions near_roots() noexcept {
  RootOptions o;
  o.mode = RootMode::near;
  return o;
}

/// Root of c0 + c1 x = 0 (none when c1 == 0 and c0 != 0; degenerate_input when both are 0).
template <Real T>
[[nodiscard]] RootsResult<T> solve_linear(T c0, std::type_identity_t<T> c1,
                                          const RootOptions& opt = near_roots()) noexcept {
  return detail::roots::solve_fixed<T, 2>({c0, c1}, opt);
}

/// Real roots of c0 + c1 x + c2 x^2 = 0 (low to high!). A double root has multiplicity 2.
template <Real T>
[[nodiscard]] RootsResult<T> solve_quadratic(T c0, std::type_identity_t<T> c1,
                                             std::type_identity_t<T> c2,
                                             const RootOptions& opt = near_roots()) noexcept {
  return detail::roots::solve_fixed<T, 3>({c0, c1, c2}, opt);
}

/// Real roots of c0 + c1 x + c2 x^2 + c3 x^3 = 0 (low to high!).
template <Real T>
[[nodiscard]] RootsResult<T> solve_cubic(T c0, std::type_identity_t<T> c1,
                                         std::type_identity_t<T> c2, std::type_identity_t<T> c3,
                                         const RootOptions& opt = near_roots()) noexcept {
  return detail::roots::solve_fixed<T, 4>({c0, c1, c2, c3}, opt);
}

/// Real roots of c0 + c1 x + c2 x^2 + c3 x^3 + c4 x^4 = 0 (low to high!).
template <Real T>
[[nodiscard]] RootsResult<T> solve_quartic(T c0, std::type_identity_t<T> c1,
                                           std::type_identity_t<T> c2, std::type_identity_t<T> c3,
                                           std::type_identity_t<T> c4,
                                           const RootOptions& opt = near_roots()) noexcept {
  return detail::roots::solve_fixed<T, 5>({c0, c1, c2, c3, c4}, opt);
}

/// Real roots of a polynomial of degree <= 4 given low-to-high coefficients.
template <Real T, std::size_t N>
requires(N >= 1 && N <= 5)
    [[nodiscard]] RootsResult<T> solve_polynomial(const std::array<T, N>& c,
                                                  const RootOptions& opt = near_roots()) noexcept {
  if constexpr (N == 1) {
    RootsResult<T> r;
    r.status = !locus::is_finite(c[0]) ? Status::non_finite_input
               : c[0] == T(0)          ? Status::degenerate_input
                                       : Status::ok;
    return r;
  } else {
    return detail::roots::solve_fixed<T, N>(c, opt);
  }
}

/// All distinct real roots of the polynomial with coefficients c (low to high) in the closed
/// interval [a, b] (default: the whole line), with multiplicities, increasing. Exact mode by
/// default; near mode finds the roots on the whole line and then filters them.
[[nodiscard]] inline RealRootsResult<double> real_roots(
    std::span<const double> c, double a = -std::numeric_limits<double>::infinity(),
    double b = std::numeric_limits<double>::infinity(), const RootOptions& opt = {}) {
  return detail::roots::real_roots_span<double>(c, a, b, opt);
}
[[nodiscard]] inline RealRootsResult<float> real_roots(
    std::span<const float> c, float a = -std::numeric_limits<float>::infinity(),
    float b = std::numeric_limits<float>::infinity(), const RootOptions& opt = {}) {
  return detail::roots::real_roots_span<float>(c, a, b, opt);
}

/// The same for a Polynomial.
template <Real T>
[[nodiscard]] RealRootsResult<T> real_roots(
    const Polynomial<T>& p, std::type_identity_t<T> a = -std::numeric_limits<T>::infinity(),
    std::type_identity_t<T> b = std::numeric_limits<T>::infinity(), const RootOptions& opt = {}) {
  return detail::roots::real_roots_span<T>(std::span<const T>(p.coeff), a, b, opt);
}

}  // namespace locus
