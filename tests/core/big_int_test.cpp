// SPDX-License-Identifier: BSL-1.0
// src/core/big_int.hpp against GMP: every operation of BigInt<L> and DynBigInt on seeded random
// operands of many sizes and both signs, with limb patterns that force long carries and borrows
// (all-ones limbs, powers of two), zero, single limbs and the extremes of int64 and double.

#include "../../src/core/big_int.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace {

using locus::detail::Limb;

template <class B>
mpz_class to_mpz(const B& x) {
  mpz_class z;
  const auto m = x.magnitude();
  if (!m.empty()) mpz_import(z.get_mpz_t(), m.size(), -1, sizeof(Limb), 0, 0, m.data());
  return x.is_negative() ? mpz_class(-z) : z;
}

template <class B>
B from_mpz(const mpz_class& z) {
  std::vector<Limb> m((mpz_sizeinbase(z.get_mpz_t(), 2) + 31) / 32 + 1, 0u);
  std::size_t count = 0;
  mpz_export(m.data(), &count, -1, sizeof(Limb), 0, 0, z.get_mpz_t());
  return B::from_limbs(std::span<const Limb>(m.data(), count), sgn(z) < 0);
}

// A random integer of n limbs: random limbs, all-ones runs (long carries), or a power of two.
mpz_class random_operand(std::mt19937_64& rng, std::size_t n) {
  if (n == 0) return 0;
  std::vector<Limb> m(n);
  const int kind = static_cast<int>(rng() % 4);
  for (std::size_t i = 0; i < n; ++i) {
    switch (kind) {
      case 0:
        m[i] = static_cast<Limb>(rng());
        break;
      case 1:
        m[i] = 0xffffffffu;
        break;
      case 2:
        m[i] = i + 1 == n ? Limb{1} << (rng() % 32) : 0u;
        break;
      default:
        m[i] = rng() % 3 == 0 ? 0xffffffffu : (rng() % 2 == 0 ? 0u : static_cast<Limb>(rng()));
    }
  }
  if (m[n - 1] == 0) m[n - 1] = 1;
  mpz_class z;
  mpz_import(z.get_mpz_t(), n, -1, sizeof(Limb), 0, 0, m.data());
  return rng() % 2 == 0 ? z : mpz_class(-z);
}

template <class B>
class BigIntTest : public ::testing::Test {};

// The fixed owner is sized for the largest products below (2 x 30 limbs) plus carries.
using Types = ::testing::Types<locus::detail::BigInt<64>, locus::detail::DynBigInt>;
TYPED_TEST_SUITE(BigIntTest, Types);

TYPED_TEST(BigIntTest, ArithmeticMatchesGmp) {
  using B = TypeParam;
  const std::uint64_t seed = 20261203;
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 6000; ++trial) {
    const std::size_t na = rng() % 31, nb = rng() % 31;  // 0..30 limbs
    const mpz_class za = random_operand(rng, na), zb = random_operand(rng, nb);
    const B a = from_mpz<B>(za), b = from_mpz<B>(zb);
    ASSERT_EQ(to_mpz(a), za) << "seed " << seed << " trial " << trial;
    ASSERT_EQ(to_mpz(a + b), mpz_class(za + zb)) << "seed " << seed << " trial " << trial;
    ASSERT_EQ(to_mpz(a - b), mpz_class(za - zb)) << "seed " << seed << " trial " << trial;
    ASSERT_EQ(to_mpz(a * b), mpz_class(za * zb)) << "seed " << seed << " trial " << trial;
    ASSERT_EQ(to_mpz(-a), mpz_class(-za));
    ASSERT_EQ(to_mpz(abs(a)), mpz_class(abs(za)));
    B c = a;
    c += b;
    ASSERT_EQ(to_mpz(c), mpz_class(za + zb));
    c -= b;
    c -= b;
    ASSERT_EQ(to_mpz(c), mpz_class(za - zb));
    c = a;
    c *= b;
    ASSERT_EQ(to_mpz(c), mpz_class(za * zb));
    c = a;
    c += c;  // aliased operands
    ASSERT_EQ(to_mpz(c), mpz_class(2 * za));
    c *= c;
    ASSERT_EQ(to_mpz(c), mpz_class(4 * za * za));
    c = a;
    // Through a reference: clang flags the literal `c -= c` as a self-assignment.
    const B& same = c;
    c -= same;
    ASSERT_TRUE(c.is_zero());
    ASSERT_FALSE(c.is_negative());
    ASSERT_EQ(compare(a, b), cmp(za, zb) < 0 ? -1 : (cmp(za, zb) > 0 ? 1 : 0));
    ASSERT_EQ(a == b, za == zb);
    ASSERT_EQ(a < b, za < zb);
    ASSERT_EQ(a.sign(), sgn(za));
    ASSERT_EQ(a.bit_length(), za == 0 ? 0u : mpz_sizeinbase(za.get_mpz_t(), 2));
    const std::size_t sh = rng() % 200;
    ASSERT_EQ(to_mpz(a << sh), mpz_class(za << static_cast<mp_bitcnt_t>(sh)));
    mpz_class trunc;
    mpz_tdiv_q_2exp(trunc.get_mpz_t(), za.get_mpz_t(), sh);
    ASSERT_EQ(to_mpz(a >> sh), trunc) << "seed " << seed << " trial " << trial;
    if (!b.is_zero()) {
      mpz_class q, r;
      mpz_tdiv_qr(q.get_mpz_t(), r.get_mpz_t(), za.get_mpz_t(), zb.get_mpz_t());
      const auto d = divmod(a, b);
      ASSERT_EQ(to_mpz(d.quotient), q) << "seed " << seed << " trial " << trial;
      ASSERT_EQ(to_mpz(d.remainder), r) << "seed " << seed << " trial " << trial;
      ASSERT_EQ(to_mpz(a / b), q);
      ASSERT_EQ(to_mpz(a % b), r);
      ASSERT_EQ(to_mpz(divide_exact(a * b, b)), za);
    }
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), za.get_mpz_t(), zb.get_mpz_t());
    ASSERT_EQ(to_mpz(gcd(a, b)), g) << "seed " << seed << " trial " << trial;
  }
}

// Quotients whose first estimate is too large (Knuth's add-back step): divisors with a top limb
// just above a power of two and dividends made of all-ones limbs, and divisions by one limb.
TYPED_TEST(BigIntTest, DivisionEdgeCases) {
  using B = TypeParam;
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 4000; ++trial) {
    const std::size_t nb = 1 + rng() % 8, nq = rng() % 10;
    mpz_class zb = random_operand(rng, nb);
    if (trial % 3 == 0) {
      zb = mpz_class(1) << static_cast<mp_bitcnt_t>(32 * nb - 1);
      zb += rng() % 5;
    }
    if (zb == 0) zb = 1;
    const mpz_class zq = random_operand(rng, nq);
    const mpz_class zr = abs(random_operand(rng, nb)) % abs(zb);
    mpz_class za = zq * zb + (sgn(zq) < 0 ? mpz_class(-zr) : zr);
    if (trial % 5 == 0) za = (mpz_class(1) << static_cast<mp_bitcnt_t>(32 * (nb + nq))) - 1;
    mpz_class q, r;
    mpz_tdiv_qr(q.get_mpz_t(), r.get_mpz_t(), za.get_mpz_t(), zb.get_mpz_t());
    const auto d = divmod(from_mpz<B>(za), from_mpz<B>(zb));
    ASSERT_EQ(to_mpz(d.quotient), q) << "trial " << trial << " a " << za << " b " << zb;
    ASSERT_EQ(to_mpz(d.remainder), r) << "trial " << trial << " a " << za << " b " << zb;
  }
}

TYPED_TEST(BigIntTest, Int64AndStrings) {
  using B = TypeParam;
  const std::int64_t values[] = {0,
                                 1,
                                 -1,
                                 4294967295,
                                 4294967296,
                                 -4294967296,
                                 std::numeric_limits<std::int64_t>::max(),
                                 std::numeric_limits<std::int64_t>::min()};
  for (const std::int64_t v : values) {
    const B b(v);
    mpz_class z;
    mpz_set_si(z.get_mpz_t(), static_cast<long>(v));
    EXPECT_EQ(to_mpz(b), z) << v;
    EXPECT_EQ(b.to_string(), z.get_str()) << v;
    EXPECT_EQ(b.to_double(), static_cast<double>(v)) << v;
  }
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 300; ++trial) {
    const mpz_class z = random_operand(rng, rng() % 20);
    EXPECT_EQ(from_mpz<B>(z).to_string(), z.get_str());
  }
}

// from_double(x, shift) is x 2^shift exactly; low_exponent gives the exponent that makes every
// double of a set an integer; to_double rounds to nearest, ties to even.
TYPED_TEST(BigIntTest, DoublesInAndOut) {
  using B = TypeParam;
  std::mt19937_64 rng(11);
  const double specials[] = {DBL_MAX,
                             -DBL_MAX,
                             DBL_MIN,
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::denorm_min(),
                             1.0,
                             -0.75,
                             0x1p52 + 1};
  std::vector<double> xs(std::begin(specials), std::end(specials));
  for (int i = 0; i < 400; ++i) {
    const double m = std::ldexp(static_cast<double>(rng() >> 11), -53) + 0.5;
    xs.push_back((rng() % 2 ? -1 : 1) * std::ldexp(m, static_cast<int>(rng() % 2100) - 1080));
  }
  for (const double x : xs) {
    const int e = locus::detail::low_exponent(x);
    const mpq_class qx(x);
    // x 2^-e must be an integer below 2^53.
    const mpq_class s =
        e >= 0 ? mpq_class(qx / mpq_class(mpz_class(1) << static_cast<mp_bitcnt_t>(e)))
               : mpq_class(qx * mpq_class(mpz_class(1) << static_cast<mp_bitcnt_t>(-e)));
    ASSERT_EQ(s.get_den(), 1) << x;
    ASSERT_LT(abs(s.get_num()), mpz_class(1) << 53) << x;
    const int shift = -e + static_cast<int>(rng() % 70);
    const B b = B::from_double(x, shift);
    const mpq_class expect =
        shift >= 0 ? mpq_class(qx * mpq_class(mpz_class(1) << static_cast<mp_bitcnt_t>(shift)))
                   : mpq_class(qx / mpq_class(mpz_class(1) << static_cast<mp_bitcnt_t>(-shift)));
    ASSERT_EQ(mpq_class(to_mpz(b)), expect) << x << " shift " << shift;
    if (e >= 0) {
      ASSERT_EQ(B::from_double(x).to_double(), x);  // integers come back unchanged
    }
  }
  // Rounding: random integers of up to 1100 bits (beyond the double range too).
  for (int trial = 0; trial < 3000; ++trial) {
    mpz_class z = random_operand(rng, 1 + rng() % 34);
    if (trial % 4 == 0) {  // near a tie: 53 significant bits, then a half, then maybe a sticky bit
      const mp_bitcnt_t low = 1 + rng() % 900;
      z = ((mpz_class(rng() >> 11) | (mpz_class(1) << 52)) << 1 | 1) << low;
      if (rng() % 2) z += rng() % 3 == 0 ? 1 : -1;
      if (rng() % 2) z = -z;
    }
    const double d = from_mpz<B>(z).to_double();
    // Halfway between DBL_MAX = 2^1024 - 2^971 and 2^1024 and beyond, the nearest is infinite.
    if (abs(z) >= (mpz_class(1) << 1024) - (mpz_class(1) << 970)) {
      ASSERT_TRUE(std::isinf(d)) << z;
      ASSERT_EQ(std::signbit(d), sgn(z) < 0);
      continue;
    }
    ASSERT_TRUE(std::isfinite(d)) << z;
    const mpq_class err = abs(mpq_class(z) - mpq_class(d));
    const double up = std::nextafter(d, HUGE_VAL), down = std::nextafter(d, -HUGE_VAL);
    for (const double n : {up, down}) {
      if (!std::isfinite(n)) continue;
      const mpq_class other = abs(mpq_class(z) - mpq_class(n));
      ASSERT_LE(err, other) << z;
      if (err == other) {  // a tie goes to the even significand
        int k = 0;
        const double f = std::frexp(std::abs(d), &k);
        ASSERT_EQ(static_cast<std::uint64_t>(std::ldexp(f, 53)) % 2, 0u) << z;
      }
    }
  }
}

TEST(BigIntFixed, CapacityAndNoAllocationLayout) {
  // The fixed owner holds its limbs inline: a value type of fixed size.
  static_assert(sizeof(locus::detail::BigInt<8>) >= 8 * sizeof(Limb));
  static_assert(std::is_nothrow_copy_constructible_v<locus::detail::BigInt<8>>);
  // The largest magnitude below its capacity (one spare limb for a carry) adds without loss.
  locus::detail::BigInt<8> a = locus::detail::BigInt<8>::from_double(0x1p200 - 0x1p148);
  const mpz_class za = to_mpz(a);
  a += a;
  a *= locus::detail::BigInt<8>(-3);
  EXPECT_EQ(to_mpz(a), mpz_class(-6 * za));
}

}  // namespace
