// SPDX-License-Identifier: BSL-1.0
// Exact sign of a sum of signed products of doubles (include/locus/core/exact_sum.hpp) on
// core's big integer. Every finite double is m 2^e with m an integer below 2^53 (low_exponent);
// a term is then the integer m_0 ... m_(count-1) (at most 212 bits) times 2^(pow2 + sum e), and
// shifting every term by its exponent minus the smallest makes the whole sum one integer.

#include <locus/core/exact_sum.hpp>

#include "big_int.hpp"

#include <climits>
#include <cmath>
#include <cstddef>

namespace locus {
namespace {

// Factor exponents lie in [-1126, 971] (denorm_min = 2^52 2^-1126, DBL_MAX < 2^53 2^971), so a
// term's shift is at most 4 * 2097 + 64 = 8452 bits; with its 212-bit mantissa and 32 bits of
// carries (up to 2^32 terms) the sum stays below 8696 bits = 272 limbs, plus one spare limb for
// the carry of each addition.
using Sum = detail::BigInt<274>;
using Mantissa = detail::BigInt<10>;  // 4 x 53 bits = 7 limbs, plus a product's room

bool live(const ExactMonomial& t) noexcept {
  if (t.sign == 0) return false;
  for (int j = 0; j < t.count; ++j)
    if (t.f[j] == 0.0) return false;
  return true;
}

}  // namespace

int exact_sign_of_sum(std::span<const ExactMonomial> terms) noexcept {
  int emin = INT_MAX;
  for (const ExactMonomial& t : terms) {
    LOCUS_ASSERT(t.count >= 0 && t.count <= 4 && t.pow2 >= 0 && t.pow2 <= 64,
                 "exact_sign_of_sum: count in [0, 4], pow2 in [0, 64]");
    for (int j = 0; j < t.count; ++j)
      if (!std::isfinite(t.f[j])) return 0;
    if (!live(t)) continue;
    int e = t.pow2;
    for (int j = 0; j < t.count; ++j) e += detail::low_exponent(t.f[j]);
    emin = e < emin ? e : emin;
  }
  if (emin == INT_MAX) return 0;
  Sum sum;
  for (const ExactMonomial& t : terms) {
    if (!live(t)) continue;
    Mantissa p(t.sign > 0 ? 1 : -1);
    int e = t.pow2;
    for (int j = 0; j < t.count; ++j) {
      const int ej = detail::low_exponent(t.f[j]);
      p *= Mantissa::from_double(t.f[j], -ej);
      e += ej;
    }
    Sum term = Sum::from_limbs(p.magnitude(), p.is_negative());
    term <<= static_cast<std::size_t>(e - emin);
    sum += term;
  }
  return sum.sign();
}

}  // namespace locus
