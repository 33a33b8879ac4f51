// SPDX-License-Identifier: BSL-1.0
// The one engine behind exact_sign_of_sum (core/exact_sum.hpp, terms of up to 4 factors) and
// exact_sign_of_terms (core/exact_poly.hpp, up to 8): the exact sign of a sum of monomials
// sign * 2^pow2 * f_0 * ... * f_(count-1) in finite doubles, pow2 in [0, 64].
//
// First a floating-point evaluation with an a-priori error bound decides every sum that is not
// near zero (docs/notes/core.md derives the bound). The rest are evaluated exactly on core's big
// integer: every finite double is m 2^e with m an integer below 2^53 (decompose); a term is the
// integer m_0 ... m_(count-1) times 2^(pow2 + sum e), and shifting every term by its exponent
// minus the smallest makes the whole sum one integer. Private to src/core.
#pragma once

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "big_int.hpp"

namespace locus::detail::exact_terms {

inline constexpr int undecided = 2;

template <class Term>
bool live(const Term& t) noexcept {
  if (t.sign == 0) return false;
  for (int j = 0; j < t.count; ++j)
    if (t.f[j] == 0.0) return false;
  return true;
}

// The sign when the rounded sum is farther from zero than its error bound, else `undecided`.
// Each product of at most F factors rounds at most F - 1 times and every partial product is
// checked to be normal (so each rounding is relative, at most u = 2^-53); the scaling by 2^pow2
// is exact (overflow is caught by the finiteness test); recursive summation of n terms adds at
// most (n - 1) u relative to the sum of magnitudes M. 2 (n + F) u M covers both with room for
// the rounding of M itself.
template <int F, class Term>
int filtered_sign(std::span<const Term> terms) noexcept {
  if (terms.size() > (std::size_t{1} << 20)) return undecided;
  double sum = 0.0, magnitude = 0.0;
  for (const Term& t : terms) {
    if (!live(t)) continue;
    double p = 1.0;
    for (int j = 0; j < t.count; ++j) {
      p = j == 0 ? t.f[0] : p * t.f[j];
      if (!(std::abs(p) >= 0x1p-1022)) return undecided;  // underflow (or NaN)
    }
    // 2^pow2 from its bits (pow2 in [0, 64]): an exact scaling.
    p *= std::bit_cast<double>(static_cast<std::uint64_t>(1023 + t.pow2) << 52);
    sum += t.sign > 0 ? p : -p;
    magnitude += std::abs(p);
  }
  if (!std::isfinite(magnitude)) return undecided;
  if (magnitude == 0.0) return 0;  // no live term
  const double bound = 2.0 * static_cast<double>(terms.size() + F) * 0x1p-53 * magnitude;
  if (sum > bound) return 1;
  if (-sum > bound) return -1;
  return undecided;
}

// Limbs of the exact sum: factor exponents lie in [-1074, 971], so a term's shift is at most
// F * 2045 + 64 bits; with its F * 53-bit mantissa and 32 bits of carries (up to 2^32 terms)
// the sum stays below F * 2098 + 96 bits; four spare limbs take each addition's carry.
template <int F>
inline constexpr std::size_t sum_limbs = (static_cast<std::size_t>(F) * 2098 + 96 + 31) / 32 + 4;

template <int F, class Term>
int exact_sign(std::span<const Term> terms) noexcept {
  using Sum = BigInt<sum_limbs<F>>;
  int emin = INT_MAX;
  for (const Term& t : terms) {
    if (!live(t)) continue;
    int e = t.pow2;
    for (int j = 0; j < t.count; ++j) e += low_exponent(t.f[j]);
    emin = e < emin ? e : emin;
  }
  if (emin == INT_MAX) return 0;
  Sum sum;
  for (const Term& t : terms) {
    if (!live(t)) continue;
    Limb product[2 * F] = {1}, next[2 * F] = {};
    std::size_t n = 1;
    int e = t.pow2;
    bool negative = t.sign < 0;
    for (int j = 0; j < t.count; ++j) {
      negative = negative != std::signbit(t.f[j]);
      const DoubleParts d = decompose(t.f[j]);
      const Limb m[2] = {static_cast<Limb>(d.mantissa), static_cast<Limb>(d.mantissa >> 32)};
      n = limbs::mul({product, n}, m, next);
      std::copy_n(next, n, product);
      e += d.exponent;
    }
    Sum term = Sum::from_limbs({product, n}, negative);
    term <<= static_cast<std::size_t>(e - emin);
    sum += term;
  }
  return sum.sign();
}

/// The exact sign (0 when a factor is not finite); the caller asserts count <= F, pow2 in range.
template <int F, class Term>
int sign(std::span<const Term> terms) noexcept {
  for (const Term& t : terms)
    for (int j = 0; j < t.count; ++j)
      if (!std::isfinite(t.f[j])) return 0;
  const int s = filtered_sign<F>(terms);
  return s != undecided ? s : exact_sign<F>(terms);
}

}  // namespace locus::detail::exact_terms
