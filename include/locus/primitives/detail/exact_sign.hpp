// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact signs of small sums of products of floating-point numbers, for the primitives'
// combinatorial decisions that are not one of the core predicates (conic invariants in
// quadratic_curve.hpp, projections onto a direction in polyline.hpp / polygon.hpp). Rows
// prim2.quadratic, prim2.polyline.
//
// Method: every factor is split exactly into a 53-bit integer mantissa and a power of two
// (frexp), each monomial sign * 2^pow2 * f0 * f1 * f2 becomes an integer of at most 159 bits
// times 2^exponent, and the positive and negative monomials are accumulated, aligned to the
// smallest exponent, in two fixed-width unsigned integers that are then compared. This is exact
// for every finite double (and so every float), needs no allocation and no GMP; it is slow
// compared to a floating-point filter (about a microsecond), so callers filter first.
// Precondition: finite factors (callers check); at most 8 monomials of at most 3 factors.

#include <cmath>
#include <cstdint>

namespace locus::detail {

/// sign * 2^pow2 * f[0] * ... * f[count - 1] (count <= 3, pow2 >= 0, finite doubles).
struct ExactMonomial {
  int sign;
  int pow2;
  int count;
  double f[3];
};

/// Fixed-width unsigned integer accumulator, 32-bit limbs, little-endian.
struct ExactAccumulator {
  // Monomial exponents (frexp exponent - 53 per factor) lie in [3 * -1126, 3 * 971 + 3], a span
  // of at most 6297 bits; a shifted 6-limb mantissa product plus its carry reaches bit
  // 6297 + 7 * 32 < 208 * 32.
  static constexpr int limbs = 208;
  std::uint32_t w[limbs];

  void add_shifted(const std::uint32_t* p, int np, int shift) noexcept {
    const int off = shift / 32, bit = shift % 32;
    std::uint64_t carry = 0;
    int i = 0;
    for (; i <= np; ++i) {
      const std::uint64_t lo = i < np ? p[i] : 0u;
      const std::uint64_t prev = i > 0 ? p[i - 1] : 0u;
      const std::uint32_t part =
          bit == 0 ? static_cast<std::uint32_t>(lo)
                   : static_cast<std::uint32_t>((lo << bit) | (prev >> (32 - bit)));
      const std::uint64_t s = static_cast<std::uint64_t>(w[off + i]) + part + carry;
      w[off + i] = static_cast<std::uint32_t>(s);
      carry = s >> 32;
    }
    for (int k = off + i; carry != 0 && k < limbs; ++k) {
      const std::uint64_t s = static_cast<std::uint64_t>(w[k]) + carry;
      w[k] = static_cast<std::uint32_t>(s);
      carry = s >> 32;
    }
  }
};

/// Exact sign (-1, 0, +1) of sum_k m[k]; every factor must be finite.
[[nodiscard]] inline int exact_sign_of_sum(const ExactMonomial* m, int n) noexcept {
  constexpr int max_terms = 8;
  std::uint32_t mant[max_terms][6] = {};
  int nlimbs[max_terms] = {};
  int expo[max_terms] = {};
  bool live[max_terms] = {};
  int sgn[max_terms] = {};
  int emin = 0;
  bool any = false;
  for (int k = 0; k < n && k < max_terms; ++k) {
    if (m[k].sign == 0) continue;
    bool zero = false;
    for (int j = 0; j < m[k].count; ++j) zero = zero || m[k].f[j] == 0.0;
    if (zero) continue;
    // Product of the integer mantissas, limb by limb (schoolbook).
    std::uint32_t prod[6] = {1u, 0u, 0u, 0u, 0u, 0u};
    int np = 1;
    int e = m[k].pow2;
    int sg = m[k].sign > 0 ? 1 : -1;
    for (int j = 0; j < m[k].count; ++j) {
      int ex = 0;
      if (m[k].f[j] < 0.0) sg = -sg;
      const double fr = std::frexp(std::abs(m[k].f[j]), &ex);          // fr in [0.5, 1)
      const auto mi = static_cast<std::uint64_t>(std::ldexp(fr, 53));  // exact 53-bit integer
      e += ex - 53;
      const std::uint32_t ml[2] = {static_cast<std::uint32_t>(mi),
                                   static_cast<std::uint32_t>(mi >> 32)};
      std::uint32_t out[6] = {};
      for (int x = 0; x < np; ++x) {
        std::uint64_t carry = 0;
        for (int y = 0; y < 2; ++y) {
          const std::uint64_t t = static_cast<std::uint64_t>(prod[x]) * ml[y] + out[x + y] + carry;
          out[x + y] = static_cast<std::uint32_t>(t);
          carry = t >> 32;
        }
        for (int z = x + 2; carry != 0 && z < 6; ++z) {
          const std::uint64_t t = static_cast<std::uint64_t>(out[z]) + carry;
          out[z] = static_cast<std::uint32_t>(t);
          carry = t >> 32;
        }
      }
      np = np + 2 < 6 ? np + 2 : 6;
      for (int x = 0; x < 6; ++x) prod[x] = out[x];
    }
    for (int x = 0; x < 6; ++x) mant[k][x] = prod[x];
    nlimbs[k] = np;
    expo[k] = e;
    sgn[k] = sg;
    live[k] = true;
    if (!any || e < emin) emin = e;
    any = true;
  }
  if (!any) return 0;
  ExactAccumulator pos{}, neg{};
  for (int k = 0; k < n && k < max_terms; ++k) {
    if (!live[k]) continue;
    (sgn[k] > 0 ? pos : neg).add_shifted(mant[k], nlimbs[k], expo[k] - emin);
  }
  for (int i = ExactAccumulator::limbs - 1; i >= 0; --i) {
    if (pos.w[i] != neg.w[i]) return pos.w[i] > neg.w[i] ? 1 : -1;
  }
  return 0;
}

/// Exact sign of dot(b - a, d) (the order of a and b along direction d); inputs must be finite.
/// A floating-point filter decides all but near-ties; the rest go to exact_sign_of_sum.
template <class T>
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
  const ExactMonomial m[4] = {{1, 0, 2, {double(bx), double(dx), 0.0}},
                              {1, 0, 2, {double(by), double(dy), 0.0}},
                              {-1, 0, 2, {double(ax), double(dx), 0.0}},
                              {-1, 0, 2, {double(ay), double(dy), 0.0}}};
  return exact_sign_of_sum(m, 4);
}

}  // namespace locus::detail
