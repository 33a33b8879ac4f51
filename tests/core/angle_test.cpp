// SPDX-License-Identifier: BSL-1.0
// Tests for core/angle.hpp (row core.trig; appendix B, figures B.1-B.10).
#include <locus/core/angle.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class AngleTest : public ::testing::Test {};
TYPED_TEST_SUITE(AngleTest, locus_test::RealTypes);

namespace {

constexpr long double kPi = 3.141592653589793238462643383279502884L;

// A high-precision mpf value as long double (hi + lo split keeps ~64 bits).
long double to_ld(const mpf_class& x) {
  const double hi = x.get_d();
  const mpf_class rest = x - hi;
  return static_cast<long double>(hi) + static_cast<long double>(rest.get_d());
}

// Oracle: the angle opposite side a of the triangle with sides a, b, c (exact rationals).
// A = origin, B = (c, 0), C = (x, y): x = (b^2 + c^2 - a^2) / (2c) exactly, y = sqrt(b^2 - x^2)
// in 256-bit floating point, then atan2 in long double.
template <class T>
long double exact_angle(T a, T b, T c) {
  const mpq_class qa(a), qb(b), qc(c);
  const mpq_class x = (qb * qb + qc * qc - qa * qa) / (2 * qc);
  const mpq_class y2 = qb * qb - x * x;
  mpf_class fy(0, 256), fx(x, 256), fy2(y2, 256);
  if (y2 > 0) fy = sqrt(fy2);
  return std::atan2(to_ld(fy), to_ld(fx));
}

// Checks the three laws on a solved triangle: law of sines, law of cosines, angle sum.
template <class T>
void expect_consistent(const SolvedTriangle<T>& t, T k) {
  const long double a = t.a, b = t.b, c = t.c, al = t.alpha, be = t.beta, ga = t.gamma;
  EXPECT_NEAR(double(al + be + ga), double(kPi), double(tol<T>(k, T(4))));
  const long double s = std::max({a, b, c});
  // Law of sines in the cross-multiplied form a sin(beta) = b sin(alpha) (no division by a
  // possibly tiny sine); scale: longest side.
  EXPECT_NEAR(double(a * std::sin(be)), double(b * std::sin(al)), double(tol<T>(k, T(s))));
  EXPECT_NEAR(double(b * std::sin(ga)), double(c * std::sin(be)), double(tol<T>(k, T(s))));
  // Law of cosines for every side.
  EXPECT_NEAR(double(a * a), double(b * b + c * c - 2 * b * c * std::cos(al)),
              double(tol<T>(4 * k, T(s * s))));
  EXPECT_NEAR(double(b * b), double(a * a + c * c - 2 * a * c * std::cos(be)),
              double(tol<T>(4 * k, T(s * s))));
  EXPECT_NEAR(double(c * c), double(a * a + b * b - 2 * a * b * std::cos(ga)),
              double(tol<T>(4 * k, T(s * s))));
}

}  // namespace

// Figures B.2 and B.3: arc length s = r theta; one radian subtends an arc equal to the radius.
TYPED_TEST(AngleTest, FigB2B3RadiansAndArcLength) {
  using T = TypeParam;
  EXPECT_EQ(arc_length(T(3), T(1)), T(3));
  EXPECT_EQ(arc_length(T(2), pi_v<T>), two_pi_v<T>);
  EXPECT_EQ(to_radians(T(180)), pi_v<T>);
  EXPECT_EQ(to_radians(T(90)), pi_v<T> / T(2));
  EXPECT_EQ(to_radians(T(-45)), -pi_v<T> / T(4));
  EXPECT_EQ(to_degrees(pi_v<T>), T(180));
  EXPECT_EQ(to_degrees(pi_v<T> / T(2)), T(90));
  EXPECT_EQ(to_radians(T(0)), T(0));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    const T d = rng.uniform<T>(-720, 720);
    EXPECT_NEAR(to_degrees(to_radians(d)), d, tol<T>(4, std::abs(d)));
    // Second method: radians = degrees * pi / 180 evaluated in long double.
    EXPECT_NEAR(double(to_radians(d)), double(static_cast<long double>(d) * kPi / 180.0L),
                double(tol<T>(2, std::abs(d) / T(50))));
  }
  EXPECT_TRUE(std::isnan(to_radians(std::numeric_limits<T>::quiet_NaN())));
}

// Figure B.4: ratios of the sides of a right triangle define sin, cos, tan.
TYPED_TEST(AngleTest, FigB4RightTriangleRatios) {
  using T = TypeParam;
  const auto s = solve_sss(T(3), T(4), T(5));
  ASSERT_EQ(s.count, 1);
  const auto& t = s.solution[0];
  EXPECT_NEAR(t.gamma, pi_v<T> / T(2), tol<T>(4));
  EXPECT_NEAR(std::sin(t.alpha), T(3) / T(5), tol<T>(4));
  EXPECT_NEAR(std::cos(t.alpha), T(4) / T(5), tol<T>(4));
  EXPECT_NEAR(std::tan(t.beta), T(4) / T(3), tol<T>(8));
}

// Figures B.5-B.6: the generalised definition; the angle of (cos t, sin t) recovers t.
TYPED_TEST(AngleTest, FigB5B6Atan2RecoversTheAngleInEachRange) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    const T t = rng.uniform<T>(T(0), two_pi_v<T>);
    const T p = atan2_positive(std::sin(t), std::cos(t));
    EXPECT_GE(p, T(0));
    EXPECT_LT(p, two_pi_v<T>);
    // Compare on the circle: the two angles may straddle 0 = 2 pi.
    EXPECT_NEAR(std::abs(wrap_angle_signed(p - t)), T(0), tol<T>(8, T(8)));
    const T q = atan2_signed(std::sin(t), std::cos(t));
    EXPECT_GT(q, -pi_v<T>);
    EXPECT_LE(q, pi_v<T>);
    EXPECT_NEAR(std::cos(q - p), T(1), tol<T>(16, T(8)));
  }
  // Axis directions.
  EXPECT_EQ(atan2_positive(T(0), T(1)), T(0));
  EXPECT_EQ(atan2_positive(T(1), T(0)), pi_v<T> / T(2));
  EXPECT_EQ(atan2_positive(T(0), T(-1)), pi_v<T>);
  EXPECT_NEAR(atan2_positive(T(-1), T(0)), T(1.5) * pi_v<T>, tol<T>(4, T(5)));
  EXPECT_EQ(atan2_signed(T(-1), T(0)), -pi_v<T> / T(2));
}

TYPED_TEST(AngleTest, Atan2EdgeCasesSignedZeroAndTinyNegative) {
  using T = TypeParam;
  // Negative x-axis is +pi for both signs of zero.
  EXPECT_EQ(atan2_signed(T(0), T(-1)), pi_v<T>);
  EXPECT_EQ(atan2_signed(-T(0), T(-1)), pi_v<T>);
  // -0 is folded to +0.
  EXPECT_FALSE(std::signbit(atan2_positive(-T(0), T(1))));
  EXPECT_FALSE(std::signbit(atan2_signed(-T(0), T(1))));
  // A tiny negative angle stays strictly below 2 pi (the half-open interval).
  const T p = atan2_positive(-std::numeric_limits<T>::denorm_min(), T(1));
  EXPECT_LT(p, two_pi_v<T>);
  EXPECT_GT(p, two_pi_v<T> - tol<T>(8, T(8)));
  EXPECT_EQ(atan2_positive(T(0), T(0)), T(0));
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_TRUE(std::isnan(atan2_positive(nan, T(1))));
  EXPECT_TRUE(std::isnan(atan2_signed(T(1), nan)));
}

// Figure B.10: ranges of the inverse functions; clamping keeps rounded arguments in domain.
TYPED_TEST(AngleTest, FigB10ClampedInverseFunctions) {
  using T = TypeParam;
  const T e = eps_v<T>;
  EXPECT_EQ(acos_clamped(T(1) + e), T(0));
  EXPECT_EQ(acos_clamped(T(-1) - e), std::acos(T(-1)));
  EXPECT_EQ(asin_clamped(T(1) + T(4) * e), std::asin(T(1)));
  EXPECT_EQ(asin_clamped(T(-2)), -std::asin(T(1)));
  EXPECT_EQ(acos_clamped(std::numeric_limits<T>::infinity()), T(0));
  EXPECT_TRUE(std::isnan(acos_clamped(std::numeric_limits<T>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(asin_clamped(std::numeric_limits<T>::quiet_NaN())));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    const T x = rng.uniform<T>(-2, 2);
    const T ac = acos_clamped(x), as = asin_clamped(x);
    EXPECT_GE(ac, T(0));
    EXPECT_LE(ac, pi_v<T>);
    EXPECT_GE(as, -pi_v<T> / T(2));
    EXPECT_LE(as, pi_v<T> / T(2));
    if (std::abs(x) <= T(1)) {
      EXPECT_EQ(ac, std::acos(x));
      EXPECT_EQ(as, std::asin(x));
      // acos + asin = pi / 2.
      EXPECT_NEAR(ac + as, pi_v<T> / T(2), tol<T>(4, T(2)));
    }
  }
}

TYPED_TEST(AngleTest, WrapAnglesIntoTheirIntervals) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    const T a = rng.uniform<T>(-100, 100);
    const T p = wrap_angle_positive(a), s = wrap_angle_signed(a);
    EXPECT_GE(p, T(0));
    EXPECT_LT(p, two_pi_v<T>);
    EXPECT_GT(s, -pi_v<T>);
    EXPECT_LE(s, pi_v<T>);
    // The reduction is by a whole number of turns of 2 pi_v: exact for the signed form; the
    // positive form adds 2 pi_v to a negative remainder, one rounding (<= ulp(2 pi) / 2).
    const long double turns_p = (static_cast<long double>(a) - p) / two_pi_v<T>;
    const long double turns_s = (static_cast<long double>(a) - s) / two_pi_v<T>;
    EXPECT_NEAR(double(turns_p), std::round(double(turns_p)), double(tol<T>(1)));
    EXPECT_NEAR(double(turns_s), std::round(double(turns_s)), 1e-15);
    EXPECT_NEAR(angle_difference(a, a + T(0.5)), T(0.5), tol<T>(4, T(200)));
  }
  EXPECT_EQ(wrap_angle_signed(-pi_v<T>), pi_v<T>);
  EXPECT_EQ(wrap_angle_signed(pi_v<T>), pi_v<T>);
  EXPECT_EQ(wrap_angle_positive(two_pi_v<T>), T(0));
  EXPECT_EQ(wrap_angle_positive(-two_pi_v<T>), T(0));
  EXPECT_FALSE(std::signbit(wrap_angle_positive(-T(0))));
  EXPECT_LT(wrap_angle_positive(-std::numeric_limits<T>::denorm_min()), two_pi_v<T>);
  EXPECT_TRUE(std::isnan(wrap_angle_positive(std::numeric_limits<T>::infinity())));
  EXPECT_TRUE(std::isnan(wrap_angle_signed(std::numeric_limits<T>::quiet_NaN())));
  EXPECT_NEAR(angle_difference(T(0.1), two_pi_v<T> - T(0.1)), T(-0.2), tol<T>(8, T(8)));
}

// Law of cosines (side): compared with the exact side length, also for needle triangles where
// b^2 + c^2 - 2bc cos(alpha) cancels catastrophically.
TYPED_TEST(AngleTest, LawOfCosinesSideIsAccurateForNeedles) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    const T b = rng.uniform<T>(T(0.1), T(10)), c = rng.uniform<T>(T(0.1), T(10));
    const T alpha = k % 2 ? rng.uniform<T>(T(1e-6), T(1e-3)) : rng.uniform<T>(T(0.01), T(3.1));
    const long double lb = b, lc = c, la = alpha;
    const long double exact =
        std::sqrt((lb - lc) * (lb - lc) + 4 * lb * lc * std::sin(la / 2) * std::sin(la / 2));
    EXPECT_NEAR(double(law_of_cosines_side(b, c, alpha)), double(exact),
                double(tol<T>(8, T(exact))));
  }
  // Needle: b = c = 1 and a tiny angle: a = 2 sin(alpha / 2) to full relative accuracy.
  const T alpha = T(1e-5);
  EXPECT_NEAR(law_of_cosines_side(T(1), T(1), alpha), T(2) * std::sin(alpha / T(2)),
              tol<T>(4, alpha));
  EXPECT_TRUE(std::isnan(law_of_cosines_side(T(-1), T(1), T(1))));
  EXPECT_TRUE(std::isnan(law_of_cosines_side(std::numeric_limits<T>::quiet_NaN(), T(1), T(1))));
}

// Law of cosines (angle) against the exact-coordinates oracle, including needle triangles.
TYPED_TEST(AngleTest, LawOfCosinesAngleMatchesExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    T b = rng.uniform<T>(T(0.5), T(2)), c = rng.uniform<T>(T(0.5), T(2));
    // Needles: a close to |b - c| (tiny angle) or to b + c (angle near pi).
    T a;
    if (k % 3 == 0)
      a = std::abs(b - c) + rng.uniform<T>(T(1e-4), T(1e-2));
    else if (k % 3 == 1)
      a = (b + c) - rng.uniform<T>(T(1e-4), T(1e-2));
    else
      a = rng.uniform<T>(std::abs(b - c), b + c);
    if (!(a > std::abs(b - c) && a < b + c)) continue;
    const long double exact = exact_angle(a, b, c);
    // Kahan's formula has a small relative error in the angle (needle triangles included).
    EXPECT_NEAR(double(law_of_cosines_angle(a, b, c)), double(exact), double(tol<T>(16, T(exact))));
  }
  // Flat triangles, violations, bad input.
  EXPECT_EQ(law_of_cosines_angle(T(3), T(1), T(2)), pi_v<T>);
  EXPECT_EQ(law_of_cosines_angle(T(1), T(1), T(2)), T(0));
  EXPECT_TRUE(std::isnan(law_of_cosines_angle(T(4), T(1), T(2))));
  EXPECT_TRUE(std::isnan(law_of_cosines_angle(T(-1), T(1), T(1))));
  EXPECT_TRUE(std::isnan(law_of_cosines_angle(std::numeric_limits<T>::infinity(), T(1), T(1))));
  EXPECT_TRUE(std::isnan(law_of_cosines_angle(T(1), std::numeric_limits<T>::quiet_NaN(), T(1))));
}

// Figures B.8-B.9: the law of sines a / sin(alpha) = b / sin(beta).
TYPED_TEST(AngleTest, FigB8B9LawOfSines) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    const T alpha = rng.uniform<T>(T(0.1), T(1.5)), beta = rng.uniform<T>(T(0.1), T(1.5));
    const T a = rng.uniform<T>(T(0.5), T(5));
    const long double exact = static_cast<long double>(a) *
                              std::sin(static_cast<long double>(beta)) /
                              std::sin(static_cast<long double>(alpha));
    const T b = law_of_sines_side(a, alpha, beta);
    EXPECT_NEAR(double(b), double(exact), double(tol<T>(8, T(exact))));
    // Back to the (acute) angle.
    EXPECT_NEAR(law_of_sines_angle(a, alpha, b), beta, tol<T>(64, T(2)));
  }
  EXPECT_TRUE(std::isnan(law_of_sines_side(T(1), T(0), T(1))));
  EXPECT_TRUE(std::isnan(law_of_sines_angle(T(0), T(1), T(1))));
  // b sin(alpha) / a slightly above 1 by rounding: clamped to a right angle.
  EXPECT_EQ(law_of_sines_angle(T(1), pi_v<T> / T(2), T(1) + eps_v<T>), std::asin(T(1)));
}

// SSS on random triangles: angles against the exact oracle; all laws hold.
TYPED_TEST(AngleTest, SolveSssMatchesOracleAndLaws) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int solved = 0;
  for (int k = 0; k < 1000; ++k) {
    const auto A = rng.vec<T, 2>(-1, 1), B = rng.vec<T, 2>(-1, 1), C = rng.vec<T, 2>(-1, 1);
    const T a = length(C - B), b = length(A - C), c = length(B - A);
    const auto s = solve_sss(a, b, c);
    if (!(a < b + c && b < a + c && c < a + b)) continue;
    ASSERT_EQ(s.count, 1);
    ++solved;
    const auto& t = s.solution[0];
    EXPECT_EQ(t.a, a);
    EXPECT_NEAR(double(t.alpha), double(exact_angle(a, b, c)), double(tol<T>(16, T(4))));
    EXPECT_NEAR(double(t.beta), double(exact_angle(b, c, a)), double(tol<T>(16, T(4))));
    EXPECT_NEAR(double(t.gamma), double(exact_angle(c, a, b)), double(tol<T>(16, T(4))));
    expect_consistent(t, T(64));
  }
  EXPECT_GT(solved, 900);
  // Flat and impossible triangles, bad input.
  const auto flat = solve_sss(T(1), T(2), T(3));
  ASSERT_EQ(flat.count, 1);
  EXPECT_EQ(flat.solution[0].gamma, pi_v<T>);
  EXPECT_EQ(flat.solution[0].alpha, T(0));
  EXPECT_EQ(solve_sss(T(1), T(2), T(4)).count, 0);
  EXPECT_EQ(solve_sss(T(0), T(1), T(1)).count, 0);
  EXPECT_EQ(solve_sss(T(-1), T(1), T(1)).count, 0);
  EXPECT_EQ(solve_sss(std::numeric_limits<T>::quiet_NaN(), T(1), T(1)).count, 0);
  EXPECT_EQ(solve_sss(std::numeric_limits<T>::infinity(), T(1), T(1)).count, 0);
}

// SAS, ASA and AAS on random triangles with known parts (computed in long double).
TYPED_TEST(AngleTest, SolveSasAsaAasRecoverTheTriangle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    const T alpha = rng.uniform<T>(T(0.05), T(2.5));
    const T beta = rng.uniform<T>(T(0.05), T(3.09) - alpha);
    const T c = rng.uniform<T>(T(0.5), T(4));
    const long double la = alpha, lb = beta, lc = c, lg = kPi - la - lb;
    const long double A = lc * std::sin(la) / std::sin(lg), B = lc * std::sin(lb) / std::sin(lg);
    const T kk = T(64) / std::sin(T(lg));  // conditioning of the sine ratio near gamma = 0
    {                                      // ASA
      const auto s = solve_asa(alpha, c, beta);
      ASSERT_EQ(s.count, 1);
      const auto& t = s.solution[0];
      EXPECT_NEAR(double(t.a), double(A), double(tol<T>(kk, T(A))));
      EXPECT_NEAR(double(t.b), double(B), double(tol<T>(kk, T(B))));
      EXPECT_EQ(t.c, c);
      EXPECT_NEAR(double(t.gamma), double(lg), double(tol<T>(8, T(4))));
      expect_consistent(t, T(64));
    }
    {  // AAS
      const auto s = solve_aas(alpha, beta, T(A));
      ASSERT_EQ(s.count, 1);
      const auto& t = s.solution[0];
      EXPECT_NEAR(double(t.c), double(lc), double(tol<T>(kk, T(lc))));
      EXPECT_NEAR(double(t.b), double(B), double(tol<T>(kk, T(B))));
      expect_consistent(t, T(64));
    }
    {  // SAS: sides b, c with the included angle alpha.
      const T b = T(B);
      const auto s = solve_sas(b, alpha, c);
      ASSERT_EQ(s.count, 1);
      const auto& t = s.solution[0];
      // Oracle: second method, the plain law of cosines in long double.
      const long double lbb = b;
      const long double exact_a = std::sqrt(lbb * lbb + lc * lc - 2 * lbb * lc * std::cos(la));
      EXPECT_NEAR(double(t.a), double(exact_a), double(tol<T>(16, T(exact_a))));
      EXPECT_NEAR(double(t.beta), double(lb), double(tol<T>(kk, T(4))));
      expect_consistent(t, T(64));
    }
  }
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(solve_asa(T(2), T(1), T(2)).count, 0);  // angle sum >= pi
  EXPECT_EQ(solve_asa(T(0), T(1), T(1)).count, 0);
  EXPECT_EQ(solve_asa(nan, T(1), T(1)).count, 0);
  EXPECT_EQ(solve_aas(T(1), T(1), T(0)).count, 0);
  EXPECT_EQ(solve_aas(T(1.5), T(1.7), T(1)).count, 0);
  EXPECT_EQ(solve_aas(T(1), nan, T(1)).count, 0);
  EXPECT_EQ(solve_sas(T(1), pi_v<T>, T(1)).count, 0);
  EXPECT_EQ(solve_sas(T(1), T(1), T(-1)).count, 0);
  EXPECT_EQ(solve_sas(T(1), T(1), std::numeric_limits<T>::infinity()).count, 0);
}

// SSA, the ambiguous case: 0, 1 or 2 triangles; both triangles of the ambiguous case appear.
TYPED_TEST(AngleTest, SolveSsaAmbiguousCase) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int two = 0;
  for (int k = 0; k < 1000; ++k) {
    const T alpha = rng.uniform<T>(T(0.1), T(1.4));
    const T b = rng.uniform<T>(T(1), T(3));
    const T h = b * std::sin(alpha);
    // a between h and b: two triangles.
    const T a = h + (b - h) * rng.uniform<T>(T(0.05), T(0.95));
    const auto s = solve_ssa(a, b, alpha);
    ASSERT_EQ(s.count, 2);
    ++two;
    const auto &t0 = s.solution[0], &t1 = s.solution[1];
    EXPECT_GT(t0.c, t1.c);
    // Vieta: c0 + c1 = 2 b cos(alpha), c0 c1 = b^2 - a^2; the beta angles are supplementary.
    EXPECT_NEAR(t0.c + t1.c, T(2) * b * std::cos(alpha), tol<T>(16, T(8)));
    EXPECT_NEAR(t0.c * t1.c, (b - a) * (b + a), tol<T>(32, T(16)));
    EXPECT_NEAR(t0.beta + t1.beta, pi_v<T>, tol<T>(64, T(4) / (b - a)));
    for (const auto& t : {t0, t1}) {
      EXPECT_EQ(t.a, a);
      EXPECT_EQ(t.b, b);
      EXPECT_EQ(t.alpha, alpha);
      expect_consistent(t, T(64) * b / (b - a));
    }
  }
  EXPECT_EQ(two, 1000);
  // One solution: a >= b (acute), or alpha obtuse with a > b.
  EXPECT_EQ(solve_ssa(T(3), T(2), T(0.7)).count, 1);
  EXPECT_EQ(solve_ssa(T(2), T(2), T(0.7)).count, 1);  // isosceles: the other root is c = 0
  EXPECT_EQ(solve_ssa(T(3), T(2), T(2.2)).count, 1);
  expect_consistent(solve_ssa(T(3), T(2), T(2.2)).solution[0], T(64));
  // None: a < h, or alpha obtuse with a <= b.
  const T alpha = T(0.5), b = T(2), h = b * std::sin(alpha);
  EXPECT_EQ(solve_ssa(h * T(0.999), b, alpha).count, 0);
  EXPECT_EQ(solve_ssa(h * T(1.001), b, alpha).count, 2);
  EXPECT_EQ(solve_ssa(T(2), T(2), T(2.2)).count, 0);
  EXPECT_EQ(solve_ssa(T(1), T(2), T(2.2)).count, 0);
  // Right angle at B when a = h (tangent case) -> a single triangle with beta = pi / 2.
  const auto right = solve_ssa(T(3), T(5), std::asin(T(3) / T(5)));
  ASSERT_GE(right.count, 1);
  EXPECT_NEAR(right.solution[0].beta, pi_v<T> / T(2), T(1e-3));
  // The original triangle is among the solutions: build one with an obtuse beta.
  const auto orig = solve_sas(T(2), T(0.4), T(0.9));  // b = 2, alpha = 0.4, c = 0.9
  ASSERT_EQ(orig.count, 1);
  const auto amb = solve_ssa(orig.solution[0].a, T(2), T(0.4));
  ASSERT_EQ(amb.count, 2);
  EXPECT_NEAR(amb.solution[1].c, T(0.9), tol<T>(64));
  EXPECT_NEAR(amb.solution[1].beta, orig.solution[0].beta, tol<T>(256));
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(solve_ssa(nan, T(1), T(1)).count, 0);
  EXPECT_EQ(solve_ssa(T(1), T(1), nan).count, 0);
  EXPECT_EQ(solve_ssa(T(1), T(0), T(1)).count, 0);
  EXPECT_EQ(solve_ssa(T(1), T(1), T(0)).count, 0);
}
