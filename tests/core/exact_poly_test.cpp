// SPDX-License-Identifier: BSL-1.0
// core/exact_poly.hpp (the exact sign behind the int2 curve decisions) against GMP rationals:
// random polynomials of products of up to eight doubles of widely spread exponents (including
// subnormals), built with var/diff/+/-/* and power-of-two scaling, their value exactly zero by
// construction half of the time (p - p' with p' a reordered copy, or (x - y)^2 - x^2 + 2xy - y^2),
// and the capacity / factor-count limits reported through valid().

#include <locus/core/exact_poly.hpp>

#include <cmath>
#include <vector>

#include <gmpxx.h>

#include "support/typed.hpp"

namespace {

using locus::ExactPoly;
using locus_test::Rng;

mpq_class exact_value(const ExactPoly& p) {
  mpq_class sum = 0;
  for (const locus::ExactTerm& t : p.terms()) {
    mpq_class v = t.sign;
    for (int j = 0; j < t.count; ++j) v *= mpq_class(t.f[j]);
    mpz_class two = 1;
    two <<= static_cast<unsigned long>(t.pow2);
    sum += v * two;
  }
  return sum;
}

double random_double(Rng& rng) {
  const int kind = rng.uniform_int(0, 9);
  const double m = rng.uniform<double>(-1, 1);
  if (kind == 0) return std::ldexp(m, rng.uniform_int(-1074, -1000));  // subnormal range
  if (kind == 1) return std::ldexp(m, rng.uniform_int(-300, 300));
  if (kind == 2) return double(rng.uniform_int(-5, 5));
  return std::ldexp(m, rng.uniform_int(-20, 20));
}

TEST(ExactPoly, SignAgainstGmp) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 3000; ++it) {
    const int nvars = rng.uniform_int(1, 6);
    std::vector<double> x(static_cast<std::size_t>(nvars));
    for (double& v : x) v = random_double(rng);
    const auto var = [&](int i) { return ExactPoly::var(x[static_cast<std::size_t>(i)]); };
    // A random product-sum: (x0 - x1) * (x2 + x3) ... up to eight factors.
    ExactPoly p = ExactPoly::constant(1);
    const int factors = rng.uniform_int(1, 8);
    for (int f = 0; f < factors; ++f) {
      const int i = rng.uniform_int(0, nvars - 1), j = rng.uniform_int(0, nvars - 1);
      // Binomial factors first (at most 2^4 terms), then single variables.
      if (f < 4)
        p = f % 2 == 0 ? p * (var(i) - var(j)) : p * (var(i) + var(j));
      else
        p = p * var(i);
    }
    ExactPoly q = p;
    if (rng.uniform_int(0, 1)) q = q.times_pow2(rng.uniform_int(0, 3));
    ExactPoly total = q;
    const int mode = rng.uniform_int(0, 2);
    if (mode == 0) total -= p;  // zero when not scaled
    if (mode == 1) {
      // (a - b)^2 - a^2 + 2ab - b^2 = 0, added to the value.
      const ExactPoly a = var(0), b = var(nvars - 1);
      total += (a - b) * (a - b) - a * a + (a * b).times_pow2(1) - b * b;
    }
    ASSERT_TRUE(total.valid());
    EXPECT_EQ(total.sign(), sgn(exact_value(total)));
  }
}

TEST(ExactPoly, Limits) {
  ExactPoly p = ExactPoly::var(3.0);
  ExactPoly q = p;
  for (int i = 0; i < 7; ++i) q = q * p;  // eight factors: fine
  EXPECT_TRUE(q.valid());
  EXPECT_EQ(q.sign(), 1);
  EXPECT_FALSE((q * p).valid());  // nine
  EXPECT_EQ((q * p).sign(), 0);
  ExactPoly big;
  for (int i = 0; i < ExactPoly::capacity + 1; ++i) big += ExactPoly::var(1.0);
  EXPECT_FALSE(big.valid());
  EXPECT_FALSE(ExactPoly::var(1.0).times_pow2(65).valid());
  EXPECT_EQ(ExactPoly::var(std::nan("")).sign(), 0);
  EXPECT_EQ(ExactPoly().sign(), 0);
  EXPECT_EQ(ExactPoly::diff(0.1, 0.1).sign(), 0);
  EXPECT_EQ((ExactPoly::diff(0x1p-1074, 0.0) * ExactPoly::var(0x1p-1074)).sign(), 1);
}

}  // namespace
