// SPDX-License-Identifier: BSL-1.0
// Exact sign of a sum of products of up to eight doubles (include/locus/core/exact_poly.hpp).
//
// The same two stages as exact_sum.cpp, widened to eight factors: a floating-point evaluation
// with an a-priori error bound decides every sum not near zero; the rest is summed exactly on
// core's big integer, every double being m 2^e with m an integer below 2^53.

#include <locus/config.hpp>
#include <locus/core/exact_poly.hpp>

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "big_int.hpp"

namespace locus {
namespace {

// Factor exponents lie in [-1074, 971]: a term's shift is at most 8 * 2045 + 64 = 16424 bits;
// with its 8 * 53 = 424-bit mantissa and 32 bits of carries the sum stays below 16880 bits
// = 528 limbs, plus a spare limb for each addition's carry.
using Sum = detail::BigInt<532>;

constexpr int undecided = 2;

bool live(const ExactTerm& t) noexcept {
  if (t.sign == 0) return false;
  for (int j = 0; j < t.count; ++j)
    if (t.f[j] == 0.0) return false;
  return true;
}

// Each product of at most 8 factors rounds at most 7 times, every partial product checked to be
// normal (relative rounding, at most u = 2^-53 each); the 2^pow2 scaling is exact; recursive
// summation of n terms adds at most (n - 1) u of the sum of magnitudes M. 2 (n + 8) u M bounds
// the total with room for the rounding of M (the argument of docs/notes/core.md for exact_sum).
int filtered_sign(std::span<const ExactTerm> terms) noexcept {
  double sum = 0.0, magnitude = 0.0;
  for (const ExactTerm& t : terms) {
    if (!live(t)) continue;
    double p = t.count == 0 ? 1.0 : t.f[0];
    if (t.count > 0 && !(std::abs(p) >= 0x1p-1022)) return undecided;
    for (int j = 1; j < t.count; ++j) {
      p *= t.f[j];
      if (!(std::abs(p) >= 0x1p-1022)) return undecided;  // underflow (or NaN)
    }
    p *= std::bit_cast<double>(static_cast<std::uint64_t>(1023 + t.pow2) << 52);
    sum += t.sign > 0 ? p : -p;
    magnitude += std::abs(p);
  }
  if (!std::isfinite(magnitude)) return undecided;
  const double bound = 2.0 * static_cast<double>(terms.size() + 8) * 0x1p-53 * magnitude;
  if (sum > bound) return 1;
  if (-sum > bound) return -1;
  if (magnitude == 0.0) return 0;  // every term dead
  return undecided;
}

int exact_sign(std::span<const ExactTerm> terms) noexcept {
  int emin = INT_MAX;
  for (const ExactTerm& t : terms) {
    if (!live(t)) continue;
    int e = t.pow2;
    for (int j = 0; j < t.count; ++j) e += detail::low_exponent(t.f[j]);
    emin = e < emin ? e : emin;
  }
  if (emin == INT_MAX) return 0;
  Sum sum;
  for (const ExactTerm& t : terms) {
    if (!live(t)) continue;
    detail::Limb product[16] = {1}, next[16] = {};
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

int exact_sign_of_terms(std::span<const ExactTerm> terms) noexcept {
  for (const ExactTerm& t : terms) {
    LOCUS_ASSERT(t.count >= 0 && t.count <= 8 && t.pow2 >= 0 && t.pow2 <= 64,
                 "exact_sign_of_terms: count in [0, 8], pow2 in [0, 64]");
    for (int j = 0; j < t.count; ++j)
      if (!std::isfinite(t.f[j])) return 0;
  }
  const int s = filtered_sign(terms);
  return s != undecided ? s : exact_sign(terms);
}

}  // namespace locus
