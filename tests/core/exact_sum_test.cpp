// SPDX-License-Identifier: BSL-1.0
// Direct tests of core/exact_sum.hpp: exact_sign_of_sum (exact sign of a sum of monomials
// sign * 2^pow2 * f0 * ... * f3 of finite doubles) and sign_dot_diff (exact sign
// of dot(b - a, d), float and double). Oracle: the same sums evaluated exactly in GMP rationals
// (mpq_class, exact for every finite double). Inputs: seeded random monomials over the whole
// double exponent range (subnormals included), and adversarial cancellations built by error-free
// transformations (two-product via fma, two-sum): exact zeros, residues of 1 ulp and of
// 2^-104, the largest and smallest magnitudes in one sum (the full accumulator width), zero
// factors, sign-0 terms. The header's precondition is finite factors (callers check), so NaN and
// Inf are not inputs of these functions and are not tested here.

#include <locus/core/exact_sum.hpp>

#include <gmpxx.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

#include "support/typed.hpp"

namespace {

using locus::exact_sign_of_sum;
using locus::ExactMonomial;
using locus::detail::sign_dot_diff;
using locus_test::Rng;

int sgn(const mpq_class& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

// The exact value of sum_k m[k] as a rational.
mpq_class exact_sum(const std::vector<ExactMonomial>& m) {
  mpq_class s = 0;
  for (const ExactMonomial& t : m) {
    mpq_class term = t.sign;
    mpz_class p2 = 1;
    mpz_mul_2exp(p2.get_mpz_t(), p2.get_mpz_t(), static_cast<unsigned long>(t.pow2));
    term *= p2;
    for (int j = 0; j < t.count; ++j) term *= mpq_class(t.f[j]);
    s += term;
  }
  return s;
}

int locus_sign(const std::vector<ExactMonomial>& m) { return exact_sign_of_sum(m); }

ExactMonomial mono(int sign, int pow2, std::vector<double> f) {
  ExactMonomial t{sign, pow2, static_cast<int>(f.size()), {0.0, 0.0, 0.0, 0.0}};
  for (std::size_t j = 0; j < f.size(); ++j) t.f[j] = f[j];
  return t;
}

// A random finite double: random sign, 53-bit mantissa and binary exponent in [emin, emax];
// exponents below -1022 give subnormals (ldexp rounds them, still a valid finite double).
double random_double(Rng& rng, int emin, int emax) {
  const double mant = rng.uniform<double>(0.5, 1.0);
  const double v = std::ldexp(mant, rng.uniform_int(emin, emax));
  return rng.uniform_int(0, 1) == 0 ? v : -v;
}

constexpr double dmax = std::numeric_limits<double>::max();
constexpr double dmin_sub = std::numeric_limits<double>::denorm_min();
constexpr double dmin_norm = std::numeric_limits<double>::min();

TEST(ExactSignOfSum, RandomMonomialsVsGmp) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 3000; ++trial) {
    // Narrow exponent ranges make cancellation likely; wide ones cover the whole range.
    const int kind = trial % 3;
    const int emin = kind == 0 ? -2 : (kind == 1 ? -60 : -1074);
    const int emax = kind == 0 ? 2 : (kind == 1 ? 60 : 1024);
    const int n = rng.uniform_int(0, 12);
    std::vector<ExactMonomial> m;
    for (int k = 0; k < n; ++k) {
      ExactMonomial t{rng.uniform_int(-1, 1),
                      rng.uniform_int(0, trial % 2 == 0 ? 3 : 64),
                      rng.uniform_int(0, 4),
                      {0.0, 0.0, 0.0, 0.0}};
      for (int j = 0; j < t.count; ++j) {
        t.f[j] = random_double(rng, emin, emax);
        if (kind == 0) t.f[j] = std::round(t.f[j] * 4) / 4;  // small dyadics: many exact ties
      }
      m.push_back(t);
    }
    ASSERT_EQ(locus_sign(m), sgn(exact_sum(m))) << "trial " << trial;
  }
}

// a*b - fl(a*b) - err(a*b) == 0 exactly (fma gives the rounding error exactly), over every
// magnitude whose product and error stay normal; then the same sum plus or minus a value far
// below the error (the residue the accumulator must still see).
TEST(ExactSignOfSum, TwoProductCancellation) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 1000; ++trial) {
    const double a = random_double(rng, -400, 400), b = random_double(rng, -400, 400);
    const double p = a * b, e = std::fma(a, b, -p);
    ASSERT_TRUE(std::isfinite(p));
    std::vector<ExactMonomial> m{mono(1, 0, {a, b}), mono(-1, 0, {p}), mono(-1, 0, {e})};
    ASSERT_EQ(sgn(exact_sum(m)), 0);
    EXPECT_EQ(locus_sign(m), 0) << "trial " << trial;
    // A residue: the smallest subnormal, times a random factor and 2^pow2.
    const double tiny = dmin_sub * rng.uniform_int(1, 7);
    for (int s : {-1, 1}) {
      auto mt = m;
      mt.push_back(mono(s, rng.uniform_int(0, 3), {tiny}));
      ASSERT_EQ(sgn(exact_sum(mt)), s);
      EXPECT_EQ(locus_sign(mt), s) << "trial " << trial;
    }
    // The same cancellation spread over a third factor: a*b*c - p*c - e*c == 0.
    const double c = random_double(rng, -200, 200);
    std::vector<ExactMonomial> m3{mono(1, 0, {a, b, c}), mono(-1, 0, {p, c}), mono(-1, 0, {c, e})};
    EXPECT_EQ(locus_sign(m3), sgn(exact_sum(m3)));
    EXPECT_EQ(locus_sign(m3), 0) << "trial " << trial;
  }
}

TEST(ExactSignOfSum, OneUlpResidues) {
  const double u = std::ldexp(1.0, -52);
  // (1 + u)(1 - u) = 1 - u^2: one below 1 by 2^-104.
  std::vector<ExactMonomial> m{mono(1, 0, {1 + u, 1 - u}), mono(-1, 0, {1.0})};
  EXPECT_EQ(sgn(exact_sum(m)), -1);
  EXPECT_EQ(locus_sign(m), -1);
  m.push_back(mono(1, 0, {std::ldexp(1.0, -104)}));
  EXPECT_EQ(sgn(exact_sum(m)), 0);
  EXPECT_EQ(locus_sign(m), 0);
  m.back().pow2 = 1;  // now + 2^-103: the sum is + 2^-104
  EXPECT_EQ(sgn(exact_sum(m)), 1);
  EXPECT_EQ(locus_sign(m), 1);
  // x * nextafter(y) vs nextafter(x) * y for random x, y: differences of one ulp product.
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    const double x = random_double(rng, -300, 300), y = random_double(rng, -300, 300);
    const double xn = std::nextafter(x, dmax), yn = std::nextafter(y, -dmax);
    std::vector<ExactMonomial> d{mono(1, 0, {x, yn}), mono(-1, 0, {xn, y}), mono(1, 1, {x, y, 0.5}),
                                 mono(-1, 0, {y, x})};
    EXPECT_EQ(locus_sign(d), sgn(exact_sum(d))) << "trial " << trial;
    // pow2 equals multiplication by a power of two: 2^3 x y - 8 x y - (x y) 2^0 + x y == 0.
    std::vector<ExactMonomial> z{mono(1, 3, {x, y}), mono(-1, 0, {8.0, x, y}), mono(-1, 0, {y, x}),
                                 mono(1, 0, {x, y})};
    EXPECT_EQ(locus_sign(z), 0) << "trial " << trial;
  }
}

// The widest span the header allows: DBL_MAX^3 * 8 and denorm_min^3 in one sum, where the
// large terms cancel exactly and the sign is the tiny one's.
TEST(ExactSignOfSum, HugeAndTinyInOneSum) {
  const double big = dmax, near_big = std::nextafter(dmax, 0.0);
  for (int s : {-1, 1}) {
    std::vector<ExactMonomial> m{mono(1, 3, {big, big, big}),
                                 mono(s, 0, {dmin_sub, dmin_sub, dmin_sub}),
                                 mono(-1, 3, {big, big, big})};
    EXPECT_EQ(sgn(exact_sum(m)), s);
    EXPECT_EQ(locus_sign(m), s);
    // The tiny term first (it sets the alignment exponent).
    std::vector<ExactMonomial> r{mono(s, 0, {dmin_sub, dmin_sub, dmin_sub}),
                                 mono(-1, 3, {big, big, big}), mono(1, 3, {big, big, big})};
    EXPECT_EQ(locus_sign(r), s);
  }
  // Carries at the top of the accumulator: 4 * 8 DBL_MAX^3 against 3 * 8 DBL_MAX^3 +
  // 8 DBL_MAX^2 nextbelow(DBL_MAX): the difference is 8 DBL_MAX^2 ulp(DBL_MAX) > 0.
  std::vector<ExactMonomial> m;
  for (int k = 0; k < 4; ++k) m.push_back(mono(1, 3, {big, big, big}));
  for (int k = 0; k < 3; ++k) m.push_back(mono(-1, 3, {big, big, big}));
  m.push_back(mono(-1, 3, {big, big, near_big}));
  EXPECT_EQ(sgn(exact_sum(m)), 1);
  EXPECT_EQ(locus_sign(m), 1);
  m.back() = mono(-1, 3, {big, big, big});
  EXPECT_EQ(locus_sign(m), 0);
  // 8 equal huge positive terms (the largest possible accumulated value) against nothing.
  std::vector<ExactMonomial> full(8, mono(-1, 3, {big, big, big}));
  EXPECT_EQ(locus_sign(full), -1);
  // The widest span with four factors and the largest power of two: 2^64 DBL_MAX^4 twice
  // (carries at the top) against denorm_min^4, and thousands of terms in one sum.
  for (int s : {-1, 1}) {
    std::vector<ExactMonomial> w{
        mono(1, 64, {big, big, big, big}), mono(1, 64, {big, big, big, big}),
        mono(s, 0, {dmin_sub, dmin_sub, dmin_sub, dmin_sub}),
        mono(-1, 64, {big, big, big, near_big}), mono(-1, 64, {big, big, big, big})};
    EXPECT_EQ(sgn(exact_sum(w)), 1);
    EXPECT_EQ(locus_sign(w), 1);
    w[1] = mono(-1, 64, {big, big, big, near_big});  // now the huge terms cancel exactly
    w[3] = mono(1, 64, {big, big, big, near_big});
    EXPECT_EQ(sgn(exact_sum(w)), s);
    EXPECT_EQ(locus_sign(w), s);
  }
  std::vector<ExactMonomial> many(5000, mono(1, 64, {big, big, big, big}));
  many.push_back(mono(-1, 0, {dmin_sub}));
  for (int k = 0; k < 5000; ++k) many.push_back(mono(-1, 64, {big, big, big, big}));
  EXPECT_EQ(locus_sign(many), -1);
  // Subnormals only: 3 denorm_min - denorm_min * 3 - (min_normal * 2^-52 = denorm_min) * 2.
  std::vector<ExactMonomial> sub{
      mono(1, 0, {dmin_sub}), mono(1, 1, {dmin_sub}), mono(-1, 0, {dmin_sub, 3.0}),
      mono(1, 0, {dmin_norm, std::ldexp(1.0, -52)}), mono(-1, 0, {dmin_sub})};
  EXPECT_EQ(sgn(exact_sum(sub)), 0);
  EXPECT_EQ(locus_sign(sub), 0);
  sub.push_back(mono(-1, 0, {std::ldexp(dmin_norm, -1), std::ldexp(1.0, -600)}));
  EXPECT_EQ(sgn(exact_sum(sub)), -1);
  EXPECT_EQ(locus_sign(sub), -1);
}

// Sums whose value is a few units of roundoff of their magnitude, on both sides of the
// floating-point filter's bound 2 (n + 4) u sum|p|: sum_k a_k b_k - fl(sum_k a_k b_k) + r s 2^-52,
// r from -64 to 64, so the filter must either decide right or hand over to the exact path.
TEST(ExactSignOfSum, NearTheFilterBoundVsGmp) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 6000; ++trial) {
    const int n = rng.uniform_int(1, 10);
    std::vector<ExactMonomial> m;
    double s = 0.0;
    for (int k = 0; k < n; ++k) {
      const double a = random_double(rng, -30, 30), b = random_double(rng, -30, 30);
      m.push_back(mono(1, 0, {a, b}));
      s += a * b;
    }
    m.push_back(mono(-1, 0, {s}));
    const int r = rng.uniform_int(-64, 64);
    if (s != 0.0 && r != 0) m.push_back(mono(r > 0 ? 1 : -1, 0, {s, std::ldexp(std::abs(r), -52)}));
    ASSERT_EQ(locus_sign(m), sgn(exact_sum(m))) << "trial " << trial;
  }
}

TEST(ExactSignOfSum, ZerosAndEmpty) {
  EXPECT_EQ(exact_sign_of_sum({}), 0);
  // Sign-0 terms and terms with a zero (or negative zero) factor contribute nothing.
  std::vector<ExactMonomial> m{mono(0, 3, {dmax, dmax, dmax}), mono(1, 0, {0.0, dmax, 5.0}),
                               mono(-1, 2, {3.0, -0.0})};
  EXPECT_EQ(locus_sign(m), 0);
  m.push_back(mono(-1, 0, {dmin_sub}));
  EXPECT_EQ(locus_sign(m), -1);
  // count 0: the monomial is sign * 2^pow2.
  std::vector<ExactMonomial> c0{mono(1, 2, {}), mono(-1, 0, {2.0, 2.0})};
  EXPECT_EQ(locus_sign(c0), 0);
  c0[0].sign = -1;
  EXPECT_EQ(locus_sign(c0), -1);
  // Negative factors flip the sign: (-a)(-b)(-c) = -abc.
  std::vector<ExactMonomial> neg{mono(1, 0, {-1.5, -2.0, -3.0}), mono(1, 0, {1.5, 2.0, 3.0})};
  EXPECT_EQ(locus_sign(neg), 0);
}

// exact_sign_of_sum against GMP (moved from the quadratic-curve tests) on random monomials spanning
// the whole double range, including exact cancellations that leave a tiny residue.
TEST(ExactSignOfSum, MatchesGmpOnWideRangeSums) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  auto rnd = [&] {
    const int kind = rng.uniform_int(0, 9);
    if (kind == 0) return 0.0;
    if (kind == 1) return std::numeric_limits<double>::denorm_min() * rng.uniform_int(1, 1000);
    const double m = rng.uniform<double>(-1, 1);
    return std::ldexp(m, rng.uniform_int(-1070, 340));
  };
  int zero_results = 0;
  for (int it = 0; it < 10000; ++it) {
    ExactMonomial m[8];
    const int n = rng.uniform_int(1, 8);
    for (int k = 0; k < n; ++k) {
      m[k].sign = rng.uniform_int(0, 1) ? 1 : -1;
      m[k].pow2 = rng.uniform_int(0, 3);
      m[k].count = rng.uniform_int(1, 4);
      for (int j = 0; j < 4; ++j) m[k].f[j] = rnd();
    }
    // Half of the cases: make monomial 1 cancel monomial 0 exactly (permuted factors).
    if (n >= 2 && it % 2 == 0) {
      m[1] = m[0];
      m[1].sign = -m[0].sign;
      if (m[1].count >= 3) std::swap(m[1].f[0], m[1].f[2]);
    }
    mpq_class sum = 0;
    for (int k = 0; k < n; ++k) {
      mpq_class term = m[k].sign;
      for (int j = 0; j < m[k].count; ++j) term *= mpq_class(m[k].f[j]);
      term *= mpq_class(1 << m[k].pow2);
      sum += term;
    }
    const int got =
        exact_sign_of_sum(std::span<const ExactMonomial>(m, static_cast<std::size_t>(n)));
    ASSERT_EQ(got, sgn(sum)) << "case " << it;
    zero_results += got == 0;
  }
  EXPECT_GT(zero_results, 100);
}

// sign_dot_diff vs GMP for T = float and double.
template <class T>
class SignDotDiff : public ::testing::Test {};
TYPED_TEST_SUITE(SignDotDiff, locus_test::RealTypes);

template <class T>
int exact_dot_diff(T ax, T ay, T bx, T by, T dx, T dy) {
  const mpq_class v = (mpq_class(double(bx)) - mpq_class(double(ax))) * mpq_class(double(dx)) +
                      (mpq_class(double(by)) - mpq_class(double(ay))) * mpq_class(double(dy));
  return sgn(v);
}

// A random finite T with binary exponent in [emin, emax] (within T's range; the mantissa is
// rounded to T, which cannot overflow below 2^(max_exponent - 1)).
template <class T>
T random_t(Rng& rng, int emin, int emax) {
  return static_cast<T>(random_double(rng, emin, emax));
}

TYPED_TEST(SignDotDiff, RandomAndNearTiesVsGmp) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // Binary exponent ranges of T: unit scale, near underflow (for double below the 1e-290 cut-off
  // of the filter), huge (for double the filter's products overflow to Inf), and everything.
  constexpr int lo = std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits;
  constexpr int hi = std::numeric_limits<T>::max_exponent - 1;
  const int ranges[4][2] = {{-3, 3}, {lo, lo + 114}, {hi - 123, hi}, {lo, hi}};
  for (int trial = 0; trial < 4000; ++trial) {
    const auto& r = ranges[trial % 4];
    const T ax = random_t<T>(rng, r[0], r[1]), ay = random_t<T>(rng, r[0], r[1]);
    const T dx = random_t<T>(rng, r[0], r[1]), dy = random_t<T>(rng, r[0], r[1]);
    T bx = random_t<T>(rng, r[0], r[1]), by = random_t<T>(rng, r[0], r[1]);
    const int mode = (trial / 4) % 3;
    if (mode == 1) {
      // b = a + s (-dy, dx), rounded: dot(b - a, d) is tiny compared to its terms.
      const double s = rng.uniform<double>(-1, 1);
      bx = static_cast<T>(double(ax) - s * double(dy));
      by = static_cast<T>(double(ay) + s * double(dx));
      if (!std::isfinite(bx) || !std::isfinite(by)) continue;
    } else if (mode == 2) {
      // One ulp off a tie: nudge a coordinate of a by one ulp.
      bx = ax;
      by = std::nextafter(ay, rng.uniform_int(0, 1) ? std::numeric_limits<T>::max()
                                                    : -std::numeric_limits<T>::max());
      if (rng.uniform_int(0, 1)) bx = std::nextafter(bx, T(0));
    }
    ASSERT_EQ(sign_dot_diff<T>(ax, ay, bx, by, dx, dy), exact_dot_diff<T>(ax, ay, bx, by, dx, dy))
        << "trial " << trial << " a=(" << ax << "," << ay << ") b=(" << bx << "," << by << ") d=("
        << dx << "," << dy << ")";
  }
}

TYPED_TEST(SignDotDiff, ExactTiesAndSymmetry) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 2000; ++trial) {
    // Integers: b = a + k (-dy, dx) exactly, so dot(b - a, d) == 0; then a one-unit change.
    const T dx = T(rng.uniform_int(-300, 300)), dy = T(rng.uniform_int(-300, 300));
    const T ax = T(rng.uniform_int(-20000, 20000)), ay = T(rng.uniform_int(-20000, 20000));
    const int k = rng.uniform_int(-50, 50);
    const T bx = ax - T(k) * dy, by = ay + T(k) * dx;
    // A common power-of-two scale keeps the tie exact at any magnitude.
    const int e = rng.uniform_int(std::numeric_limits<T>::min_exponent - 10,
                                  std::numeric_limits<T>::max_exponent - 40);
    const auto sc = [e](T v) { return std::ldexp(v, e); };
    const T sax = sc(ax), say = sc(ay), sbx = sc(bx), sby = sc(by);
    ASSERT_EQ(exact_dot_diff<T>(sax, say, sbx, sby, dx, dy), 0);
    EXPECT_EQ(sign_dot_diff<T>(sax, say, sbx, sby, dx, dy), 0) << "trial " << trial;
    const T sbx1 = sc(bx + T(1));
    EXPECT_EQ(sign_dot_diff<T>(sax, say, sbx1, sby, dx, dy),
              exact_dot_diff<T>(sax, say, sbx1, sby, dx, dy))
        << "trial " << trial;
    // Antisymmetry in (a, b) and in d.
    const T rx = random_t<T>(rng, -20, 20), ry = random_t<T>(rng, -20, 20);
    const int s = sign_dot_diff<T>(sax, say, rx, ry, dx, dy);
    EXPECT_EQ(s, exact_dot_diff<T>(sax, say, rx, ry, dx, dy));
    EXPECT_EQ(sign_dot_diff<T>(rx, ry, sax, say, dx, dy), -s);
    EXPECT_EQ(sign_dot_diff<T>(sax, say, rx, ry, -dx, -dy), -s);
  }
  // Degenerate: d = 0, a == b.
  EXPECT_EQ(sign_dot_diff<T>(T(1), T(2), T(3), T(4), T(0), T(0)), 0);
  EXPECT_EQ(sign_dot_diff<T>(T(1), T(2), T(1), T(2), T(5), T(-7)), 0);
  // Subnormal only differences.
  const T tiny = std::numeric_limits<T>::denorm_min();
  EXPECT_EQ(sign_dot_diff<T>(T(0), T(0), tiny, T(0), tiny, T(0)), 1);
  EXPECT_EQ(sign_dot_diff<T>(T(0), T(0), tiny, -tiny, tiny, tiny), 0);
  EXPECT_EQ(sign_dot_diff<T>(T(0), tiny, tiny, T(0), T(1), T(1)), 0);
  EXPECT_EQ(sign_dot_diff<T>(T(0), tiny, tiny, T(0), T(1), std::nextafter(T(1), T(2))), -1);
}

}  // namespace
