// SPDX-License-Identifier: BSL-1.0
// core/error_free.hpp: two_sum and two_product must be exact and diff_of_products accurately
// rounded, checked against GMP rationals on seeded random operands spread over many binades,
// on cancelling differences (where the naive a b - c d is all error), on exactly equal products
// (the answer must be exactly 0) and on non-finite operands.

#include <locus/core/error_free.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>

namespace {

using locus_test::RealTypes;
using locus_test::Rng;

template <class T>
class ErrorFreeTest : public ::testing::Test {};
TYPED_TEST_SUITE(ErrorFreeTest, RealTypes);

/// A random T with a random sign and binade in [2^-40, 2^40): far inside the exact range.
template <class T>
T random_operand(Rng& rng) {
  const T m = rng.uniform<T>(T(1), T(2));
  const int k = rng.uniform_int(-40, 39);
  return (rng.uniform_int(0, 1) ? T(1) : T(-1)) * std::ldexp(m, k);
}

mpq_class q(double x) { return mpq_class(x); }

TYPED_TEST(ErrorFreeTest, TwoSumAndTwoProductAreExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 20000; ++i) {
    const T a = random_operand<T>(rng), b = random_operand<T>(rng);
    T s, e;
    locus::two_sum(a, b, s, e);
    ASSERT_EQ(s, a + b);
    ASSERT_EQ(q(s) + q(e), q(a) + q(b)) << a << " + " << b;
    locus::two_product(a, b, s, e);
    ASSERT_EQ(s, a * b);
    ASSERT_EQ(q(s) + q(e), q(a) * q(b)) << a << " * " << b;
    ASSERT_EQ(locus::product_error(a, b, s), e);
  }
}

// The bound checked below, |r - X| <= eps |X| + eps^2 / 2 (|a b| + |c d|) with eps = 2u:
// - FMA (double): Kahan's algorithm, |r - X| <= 2u |X| (Jeannerod, Louvet, Muller 2013).
// - No FMA (double): r = fl(fl(A) + fl(B)) with A = p - w, B = ep - ew, X = A + B, |ep| <= u |ab|,
//   |ew| <= u |cd|. When p and w are within a factor 2, A is exact (Sterbenz) and the error is
//   u |B| + u |r| <= u^2 (|ab| + |cd|) + u |X| (1 + u); otherwise |B| <= 3u |A| and the error is
//   at most u |A| + u |B| + u |r|, about 2u |X|.
// - Float: the products are exact in double; one double rounding then one float rounding,
//   < 2u |X|.
TYPED_TEST(ErrorFreeTest, DiffOfProductsIsAccuratelyRounded) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const mpq_class eps(double(locus::eps_v<T>));
  int cancelling = 0;
  for (int i = 0; i < 20000; ++i) {
    const T a = random_operand<T>(rng), b = random_operand<T>(rng);
    T c = random_operand<T>(rng), d = random_operand<T>(rng);
    if (i % 2 == 0) {
      // c d within a few ulps of a b: the naive formula keeps none of the difference's bits.
      c = a * T(1 + rng.uniform_int(-8, 8) * double(locus::eps_v<T>));
      d = b;
      if (i % 4 == 0) std::swap(c, d);
      ++cancelling;
    }
    const T r = locus::diff_of_products(a, b, c, d);
    const mpq_class ab = q(a) * q(b), cd = q(c) * q(d), x = ab - cd;
    const mpq_class err = abs(q(r) - x);
    const mpq_class bound = eps * abs(x) + eps * eps / 2 * (abs(ab) + abs(cd));
    ASSERT_LE(err, bound) << a << " " << b << " " << c << " " << d << " -> " << r;
    if (x == 0) {
      ASSERT_EQ(r, T(0));
    }
  }
  EXPECT_EQ(cancelling, 10000);
}

TYPED_TEST(ErrorFreeTest, EqualProductsGiveExactlyZero) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 5000; ++i) {
    const T a = random_operand<T>(rng), b = random_operand<T>(rng);
    const int k = rng.uniform_int(-8, 8);
    // a b == (a 2^k)(b 2^-k) == b a exactly, though a * b itself rounds.
    ASSERT_EQ(locus::diff_of_products(a, b, std::ldexp(a, k), std::ldexp(b, -k)), T(0));
    ASSERT_EQ(locus::diff_of_products(a, b, b, a), T(0));
  }
}

TYPED_TEST(ErrorFreeTest, NonFiniteOperandsGiveNonFiniteResults) {
  using T = TypeParam;
  constexpr T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  for (const T bad : {inf, -inf, nan}) {
    EXPECT_FALSE(std::isfinite(locus::diff_of_products(bad, T(1), T(2), T(3))));
    EXPECT_FALSE(std::isfinite(locus::diff_of_products(T(1), T(2), T(3), bad)));
    T p = T(0), e = T(0);
    locus::two_product(bad, T(3), p, e);
    EXPECT_FALSE(std::isfinite(e));
    locus::two_sum(bad, T(3), p, e);
    EXPECT_FALSE(std::isfinite(e));
  }
}

}  // namespace
