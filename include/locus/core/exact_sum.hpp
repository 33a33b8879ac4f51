// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact sign of a sum of signed products of doubles: the predicate behind the combinatorial
// decisions that are not one of the fixed predicates of predicates.hpp (conic and quadric
// invariants, orders along a direction, sides of planes through a normal). Row core.predicates.
//
// exact_sign_of_sum(terms) is the sign (-1, 0, +1) of sum_k sign_k 2^pow2_k f_k0 ... f_k(count-1),
// exact for every finite double factor (so for every float) and any number of terms: the
// products are formed as integers on core's one big integer (src/core/big_int.hpp; see
// docs/notes/core.md for why an integer and not expansions), aligned to the smallest exponent and
// summed. A term with sign 0, or a zero factor, adds nothing; an empty sum is 0. Preconditions:
// count in [0, 4], pow2 in [0, 64]; a non-finite factor gives 0 (callers test finiteness).
// Cost: a few hundred nanoseconds to microseconds, growing with the spread of the exponents; no
// allocation. Callers decide the easy cases with a floating-point filter first, as
// sign_dot_diff does here.

#include <locus/core/scalar.hpp>

#include <cmath>
#include <span>

namespace locus {

/// sign * 2^pow2 * f[0] * ... * f[count - 1] (count <= 4, 0 <= pow2 <= 64, finite factors).
struct ExactMonomial {
  int sign;
  int pow2;
  int count;
  double f[4];
};

/// Exact sign (-1, 0, +1) of the sum of the terms (compiled in src/core/exact_sum.cpp).
[[nodiscard]] int exact_sign_of_sum(std::span<const ExactMonomial> terms) noexcept;

namespace detail {

/// Exact sign of dot(b - a, d) (the order of a and b along direction d); inputs must be finite.
/// A floating-point filter decides all but near-ties; the rest go to exact_sign_of_sum.
template <Real T>
[[nodiscard]] inline int sign_dot_diff(T ax, T ay, T bx, T by, T dx, T dy) noexcept {
  // For T = float the products are exact in double and the filter bound covers the sums.
  const double p0 = double(bx) * double(dx), p1 = double(by) * double(dy);
  const double q0 = double(ax) * double(dx), q1 = double(ay) * double(dy);
  const double v = (p0 + p1) - (q0 + q1);
  const double mag = (std::abs(p0) + std::abs(p1)) + (std::abs(q0) + std::abs(q1));
  // Each product and each of the three additions rounds at most once (relative eps / 2 each);
  // 4 eps * mag is a safe bound. Values near underflow skip the filter.
  constexpr double eps = 2.220446049250313e-16;
  if (mag > 1e-290 && std::abs(v) > 4.0 * eps * mag) return v > 0.0 ? 1 : -1;
  const ExactMonomial m[4] = {{1, 0, 2, {double(bx), double(dx)}},
                              {1, 0, 2, {double(by), double(dy)}},
                              {-1, 0, 2, {double(ax), double(dx)}},
                              {-1, 0, 2, {double(ay), double(dy)}}};
  return exact_sign_of_sum(m);
}

}  // namespace detail
}  // namespace locus
