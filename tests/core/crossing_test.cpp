// SPDX-License-Identifier: BSL-1.0
// core/crossing.hpp: turn2d_value(a, b, c, d) = det[b - a; d - c] rounded from its exact value.
// Oracle: the determinant in GMP rationals. Checks: relative error below 2 eps (double eps) and
// the sign equal to turn2d's, on random points, on nearly degenerate configurations (d a rounded
// point of the line through a and b, where the naive formula keeps no correct digit), on exact
// degeneracies (value exactly 0), over a wide exponent range, and NaN/Inf (NaN result).

#include <locus/core/crossing.hpp>
#include <locus/core/predicates.hpp>

#include <gmpxx.h>

#include <cmath>
#include <limits>

#include "support/typed.hpp"

namespace {

using locus::Vec2;
using locus_test::Rng;

template <class T>
class CoreCrossing : public ::testing::Test {};
TYPED_TEST_SUITE(CoreCrossing, locus_test::RealTypes);

template <class T>
mpq_class exact_turn(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c, const Vec2<T>& d) {
  const auto q = [](T v) { return mpq_class(double(v)); };
  return (q(b.x) - q(a.x)) * (q(d.y) - q(c.y)) - (q(b.y) - q(a.y)) * (q(d.x) - q(c.x));
}

// |value - exact| <= 2 eps |exact| and the same sign as turn2d; returns the relative error.
template <class T>
double check(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c, const Vec2<T>& d) {
  const double v = locus::turn2d_value(a, b, c, d);
  const mpq_class e = exact_turn(a, b, c, d);
  const int s = e > 0 ? 1 : (e < 0 ? -1 : 0);
  EXPECT_EQ((v > 0) - (v < 0), s);
  EXPECT_EQ(locus::to_int(locus::turn2d(a, b, c, d)), s);
  if (s == 0) {
    EXPECT_EQ(v, 0.0);
    return 0.0;
  }
  const double rel = std::abs(mpq_class((mpq_class(v) - e) / e).get_d());
  EXPECT_LE(rel, 2 * std::numeric_limits<double>::epsilon()) << v << " against " << e.get_d();
  return rel;
}

TYPED_TEST(CoreCrossing, RandomPointsAreAccurate) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 20000; ++i) {
    const T s = std::ldexp(T(1), rng.uniform_int(-30, 30));
    check(rng.vec<T, 2>(-s, s), rng.vec<T, 2>(-s, s), rng.vec<T, 2>(-s, s), rng.vec<T, 2>(-s, s));
    if (::testing::Test::HasFatalFailure()) return;
  }
}

// d is the rounded point of the line ab at a random parameter (and c = a or c random nearby):
// the determinant is a tiny residue of the rounding, cancelled almost entirely in the naive sum.
TYPED_TEST(CoreCrossing, NearlyCollinearKeepsRelativeAccuracy) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  double naive_worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const Vec2<T> a = rng.vec<T, 2>(-1, 1), b = rng.vec<T, 2>(-1, 1);
    const T t = rng.uniform<T>(-3, 3);
    const Vec2<T> d = a + t * (b - a);
    const Vec2<T> c = i % 2 == 0 ? a : a + rng.uniform<T>(-3, 3) * (b - a);
    check(a, b, c, d);
    const mpq_class e = exact_turn(a, b, c, d);
    if (e != 0) {
      const double naive = (double(b.x) - double(a.x)) * (double(d.y) - double(c.y)) -
                           (double(b.y) - double(a.y)) * (double(d.x) - double(c.x));
      naive_worst = std::max(naive_worst, std::abs(mpq_class((mpq_class(naive) - e) / e).get_d()));
    }
    if (::testing::Test::HasFatalFailure()) return;
  }
  // The configurations are hard: the naive formula is far off somewhere (for double input).
  if (std::is_same_v<T, double>) {
    EXPECT_GT(naive_worst, 1e-3);
  }
}

TYPED_TEST(CoreCrossing, ExactDegeneraciesGiveZero) {
  using T = TypeParam;
  Rng rng;
  for (int i = 0; i < 2000; ++i) {
    const Vec2<T> a{T(rng.uniform_int(-50, 50)), T(rng.uniform_int(-50, 50))};
    const Vec2<T> u{T(rng.uniform_int(-5, 5)) / 4, T(rng.uniform_int(-5, 5)) / 4};
    const Vec2<T> c{T(rng.uniform_int(-50, 50)), T(rng.uniform_int(-50, 50))};
    check(a, a + T(rng.uniform_int(-4, 4)) * u, c, c + T(rng.uniform_int(-4, 4)) * u);
  }
}

TYPED_TEST(CoreCrossing, NonFiniteGivesNaN) {
  using T = TypeParam;
  const T bad[] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()};
  for (const T v : bad) {
    for (int k = 0; k < 8; ++k) {
      Vec2<T> p[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
      p[k / 2][k % 2] = v;
      EXPECT_TRUE(std::isnan(locus::turn2d_value(p[0], p[1], p[2], p[3])));
    }
  }
}

}  // namespace
