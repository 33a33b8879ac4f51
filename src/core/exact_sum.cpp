// SPDX-License-Identifier: BSL-1.0
// Exact sign of a sum of signed products of doubles (include/locus/core/exact_sum.hpp).
//
// First a floating-point evaluation with an a-priori error bound decides every sum that is not
// near zero (docs/notes/core.md derives the bound). The rest are evaluated exactly on core's big
// integer: every finite double is m 2^e with m an integer below 2^53 (decompose); a term is the
// integer m_0 ... m_(count-1) (at most 212 bits) times 2^(pow2 + sum e), and shifting every term
// by its exponent minus the smallest makes the whole sum one integer.

#include <locus/core/exact_sum.hpp>

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "big_int.hpp"

namespace locus {
namespace {

// Factor exponents lie in [-1074, 971], so a term's shift is at most 4 * 2045 + 64 = 8244 bits;
// with its 212-bit mantissa and 32 bits of carries (up to 2^32 terms) the sum stays below 8488
// bits = 266 limbs, plus one spare limb for the carry of each addition.
using Sum = detail::BigInt<268>;

constexpr int undecided = 2;

bool live(const ExactMonomial& t) noexcept {
  if (t.sign == 0) return false;
  for (int j = 0; j < t.count; ++j)
    if (t.f[j] == 0.0) return false;
  return true;
}

// The sign when the rounded sum is farther from zero than its error bound, else `undecided`.
// Each product of at most 4 factors is rounded at most 3 times and every partial product is
// checked to be normal (so each rounding is relative, at most u = 2^-53); the scaling by 2^pow2
// is exact (overflow is caught by the finiteness test); recursive summation of n terms adds at
// most (n - 1) u relative to the sum of magnitudes. 2 (n + 4) u M covers both with room for the
// rounding of M itself (docs/notes/core.md).
int filtered_sign(std::span<const ExactMonomial> terms) noexcept {
  if (terms.size() > (std::size_t{1} << 20)) return undecided;
  double sum = 0.0, magnitude = 0.0;
  for (const ExactMonomial& t : terms) {
    if (!live(t)) continue;
    double p = t.f[0];
    if (t.count == 0) p = 1.0;
    for (int j = 1; j < t.count; ++j) {
      p *= t.f[j];
      if (!(std::abs(p) >= 0x1p-1022)) return undecided;  // underflow (or NaN)
    }
    // 2^pow2 from its bits (pow2 in [0, 64]): an exact scaling.
    p *= std::bit_cast<double>(static_cast<std::uint64_t>(1023 + t.pow2) << 52);
    sum += t.sign > 0 ? p : -p;
    magnitude += std::abs(p);
  }
  if (!std::isfinite(magnitude)) return undecided;
  const double bound = 2.0 * static_cast<double>(terms.size() + 4) * 0x1p-53 * magnitude;
  if (sum > bound) return 1;
  if (-sum > bound) return -1;
  return undecided;
}

int exact_sign(std::span<const ExactMonomial> terms) noexcept {
  int emin = INT_MAX;
  for (const ExactMonomial& t : terms) {
    if (!live(t)) continue;
    int e = t.pow2;
    for (int j = 0; j < t.count; ++j) e += detail::low_exponent(t.f[j]);
    emin = e < emin ? e : emin;
  }
  if (emin == INT_MAX) return 0;
  Sum sum;
  for (const ExactMonomial& t : terms) {
    if (!live(t)) continue;
    detail::Limb product[8] = {1}, next[8] = {};
    std::size_t n = 1;
    int e = t.pow2;
    bool negative = t.sign < 0;
    for (int j = 0; j < t.count; ++j) {
      negative = negative != std::signbit(t.f[j]);
      const detail::DoubleParts d = detail::decompose(t.f[j]);
      const detail::Limb m[2] = {static_cast<detail::Limb>(d.mantissa),
                                 static_cast<detail::Limb>(d.mantissa >> 32)};
      n = detail::limbs::mul({product, n}, m, next);
      std::copy_n(next, n, product);
      e += d.exponent;
    }
    Sum term = Sum::from_limbs({product, n}, negative);
    term <<= static_cast<std::size_t>(e - emin);
    sum += term;
  }
  return sum.sign();
}

}  // namespace

int exact_sign_of_sum(std::span<const ExactMonomial> terms) noexcept {
  for (const ExactMonomial& t : terms) {
    LOCUS_ASSERT(t.count >= 0 && t.count <= 4 && t.pow2 >= 0 && t.pow2 <= 64,
                 "exact_sign_of_sum: count in [0, 4], pow2 in [0, 64]");
    for (int j = 0; j < t.count; ++j)
      if (!std::isfinite(t.f[j])) return 0;
  }
  const int s = filtered_sign(terms);
  return s != undecided ? s : exact_sign(terms);
}

}  // namespace locus
