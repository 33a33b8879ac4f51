// SPDX-License-Identifier: BSL-1.0
#pragma once
// Error-free transformations: the rounding error of a sum or a product as a floating-point number
// of its own, and the accurately rounded difference of two products built on them. The one
// implementation that the exact predicates (src/core/expansion.hpp), the root finders
// (numeric/roots.hpp), the exact quadric classification (primitives/quadric.hpp) and the
// distance queries (distance/detail/linear.hpp) share.
//
// Written from the textbook algorithms: Knuth's TwoSum, Dekker's product with Veltkamp's split
// (T. J. Dekker, "A floating-point technique for extending the available precision", 1971), and
// Kahan's difference of products with fused multiply-adds (error analysis: C.-P. Jeannerod,
// N. Louvet and J.-M. Muller, "Further analysis of Kahan's algorithm for the accurate computation
// of 2x2 determinants", Math. Comp. 2013).
//
// Conventions: T = float or double, IEEE arithmetic in round-to-nearest. "Exact" holds barring
// overflow and underflow: a product's error is exact when |a b| is above about 2^-969 (double;
// 2^-102 for float) and |a|, |b| are below about 2^995 (double; the splitting constant must not
// overflow). NaN and infinite inputs give NaN or infinite errors; callers test finiteness first.
//
// Products use a fused multiply-add where the target has one (__FMA__: one instruction, and
// immune to contraction); elsewhere Dekker's product, whose algebra assumes every operation is
// rounded on its own. A target without FMA cannot contract, so that holds too; the one hazard is
// a function compiled for an FMA target by attribute (target or target_clones) in a unit compiled
// without -mfma under -ffp-contract=fast: it must not inline these (locus's own multi-versioned
// batch kernels do not call them). Float products are formed in double, where they are exact.
//
// Cost: two_sum 6 flops; two_product 2 flops with FMA, 17 without; diff_of_products 3 with FMA.

#include <locus/core/scalar.hpp>

#include <cmath>
#include <type_traits>

namespace locus {

/// s + e = a + b exactly, with s = fl(a + b) (Knuth's TwoSum: no precondition on the magnitudes).
template <Real T>
constexpr void two_sum(T a, T b, T& s, T& e) noexcept {
  s = a + b;
  const T b_virtual = s - a;
  const T a_virtual = s - b_virtual;
  e = (a - a_virtual) + (b - b_virtual);
}

/// The rounding error of p = fl(a b): a b - p exactly (see the header comment for the range).
template <Real T>
[[nodiscard]] inline T product_error(T a, T b, T p) noexcept {
  if constexpr (std::is_same_v<T, float>) {
    // The double product of two floats is exact (48 bits), and so is its difference from p.
    return static_cast<float>(double(a) * double(b) - double(p));
  } else {
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
    return std::fma(a, b, -p);
#else
    constexpr double splitter = 0x1p27 + 1.0;  // Veltkamp: halves of at most 26 bits each
    const double ta = splitter * a, tb = splitter * b;
    const double ah = ta - (ta - a), al = a - ah;
    const double bh = tb - (tb - b), bl = b - bh;
    return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
#endif
  }
}

/// p + e = a b exactly, with p = fl(a b).
template <Real T>
inline void two_product(T a, T b, T& p, T& e) noexcept {
  p = a * b;
  e = product_error(a, b, p);
}

/// a b - c d accurately: relative error a few eps (not the absolute eps |a b| of the naive
/// formula, which is all of the answer when the products cancel), and exactly 0 when a b == c d
/// (barring underflow). Float: the products are exact in double and one rounding remains. Double:
/// Kahan's algorithm with fused multiply-adds (error <= 2 eps relative, Jeannerod, Louvet and
/// Muller); without FMA both products split exactly into p + pe, where p - w is exact when it
/// cancels (Sterbenz), so only the last two additions round.
template <Real T>
[[nodiscard]] inline T diff_of_products(T a, T b, T c, T d) noexcept {
  if constexpr (std::is_same_v<T, float>) {
    return static_cast<float>(double(a) * double(b) - double(c) * double(d));
  } else {
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
    const double w = c * d;
    return std::fma(a, b, -w) - std::fma(c, d, -w);
#else
    const double p = a * b, w = c * d;
    return (p - w) + (product_error(a, b, p) - product_error(c, d, w));
#endif
  }
}

}  // namespace locus
