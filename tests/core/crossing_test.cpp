// SPDX-License-Identifier: BSL-1.0
// core/crossing.hpp: turn2d_value(a, b, c, d) = det[b - a; d - c] rounded from its exact value.
// Oracle: the determinant in GMP rationals. Checks: relative error below 2 eps (double eps) and
// the sign equal to turn2d's, on random points, on nearly degenerate configurations (d a rounded
// point of the line through a and b, where the naive formula keeps no correct digit), on exact
// degeneracies (value exactly 0), over a wide exponent range, and NaN/Inf (NaN result); residues
// from 2^-40 to 2^-110 of the products under every compiled version (FMA and Dekker products:
// detail::set_batch_isa picks them, src/core/crossing.cpp).
// side_of_crossing and compare_crossing_params against the crossing points computed in
// rationals: random lines, exact ties on integer grids (lines through one lattice point), near
// ties a few ulps apart, parallel lines (zero) and non-finite input (zero).

#include <locus/core/crossing.hpp>
#include <locus/core/detail/batch_isa.hpp>
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

// d = a point of the line ab moved off it by 2^-k (k in [40, 110]), c near a: the determinant
// falls into each tier of src/core/crossing.cpp (double-double, triple length, expansion), under
// each compiled version of it.
TYPED_TEST(CoreCrossing, EveryTierAndVersionKeepsRelativeAccuracy) {
  using T = TypeParam;
  using locus::detail::BatchIsa;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const BatchIsa before = locus::detail::batch_isa();
  for (const BatchIsa isa : {BatchIsa::baseline, BatchIsa::avx2, BatchIsa::x86_64_v4}) {
    locus::detail::set_batch_isa(isa);
    for (int i = 0; i < 300; ++i) {
      const Vec2<T> a = rng.vec<T, 2>(-2, 2), b = rng.vec<T, 2>(-2, 2);
      const Vec2<T> ab = b - a;
      const T off = std::ldexp(T(1), -rng.uniform_int(40, 110));
      const Vec2<T> d = a + rng.uniform<T>(-2, 2) * ab + off * Vec2<T>{-ab.y, ab.x};
      const Vec2<T> c = a + rng.uniform<T>(-1, 1) * off * ab;
      check(a, b, c, d);
      check(c, d, a, b);
      if (::testing::Test::HasFatalFailure()) break;
    }
  }
  locus::detail::set_batch_isa(before);
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

struct QP {
  mpq_class x, y;
};
template <class T>
QP qp(const Vec2<T>& v) {
  return {mpq_class(double(v.x)), mpq_class(double(v.y))};
}
// The crossing of the lines p0 p1 and q0 q1 (not parallel), in rationals.
template <class T>
QP exact_crossing(const Vec2<T>& p0, const Vec2<T>& p1, const Vec2<T>& q0, const Vec2<T>& q1) {
  const QP a = qp(p0), b = qp(p1), c = qp(q0), d = qp(q1);
  const mpq_class dx = b.x - a.x, dy = b.y - a.y, ex = d.x - c.x, ey = d.y - c.y;
  const mpq_class den = dx * ey - dy * ex;
  const mpq_class t = ((c.x - a.x) * ey - (c.y - a.y) * ex) / den;
  return {a.x + t * dx, a.y + t * dy};
}
template <class T>
int exact_side(const Vec2<T>& p0, const Vec2<T>& p1, const Vec2<T>& q0, const Vec2<T>& q1,
               const Vec2<T>& a, const Vec2<T>& b) {
  if (locus::turn2d(p0, p1, q0, q1) == locus::Sign::zero) return 0;
  const QP x = exact_crossing(p0, p1, q0, q1), qa = qp(a), qb = qp(b);
  return sgn((qb.x - qa.x) * (x.y - qa.y) - (qb.y - qa.y) * (x.x - qa.x));
}
// t of the crossing of line x0 x1 with the line o + t (b - a), in rationals.
template <class T>
mpq_class exact_param(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& o, const Vec2<T>& x0,
                      const Vec2<T>& x1) {
  const QP qa = qp(a), qb = qp(b), qo = qp(o), p = qp(x0), q = qp(x1);
  const mpq_class dx = qb.x - qa.x, dy = qb.y - qa.y, ex = q.x - p.x, ey = q.y - p.y;
  return ((p.x - qo.x) * ey - (p.y - qo.y) * ex) / (dx * ey - dy * ex);
}
template <class T>
int exact_compare(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& o, const Vec2<T>& p0,
                  const Vec2<T>& p1, const Vec2<T>& q0, const Vec2<T>& q1) {
  if (locus::turn2d(a, b, p0, p1) == locus::Sign::zero ||
      locus::turn2d(a, b, q0, q1) == locus::Sign::zero)
    return 0;
  return sgn(exact_param(a, b, o, q0, q1) - exact_param(a, b, o, p0, p1));
}

TYPED_TEST(CoreCrossing, CrossingPredicatesRandom) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 3000; ++i) {
    Vec2<T> v[7];
    for (auto& p : v) p = rng.vec<T, 2>(-1, 1);
    EXPECT_EQ(locus::to_int(locus::side_of_crossing(v[0], v[1], v[2], v[3], v[4], v[5])),
              exact_side(v[0], v[1], v[2], v[3], v[4], v[5]));
    EXPECT_EQ(
        locus::to_int(locus::compare_crossing_params(v[0], v[1], v[2], v[3], v[4], v[5], v[6])),
        exact_compare(v[0], v[1], v[2], v[3], v[4], v[5], v[6]));
    if (::testing::Test::HasFatalFailure()) return;
  }
}

// Lines through one lattice point X give exact zeros; moving one input by an ulp gives the
// tiniest nonzero values. Both predicates must match the rationals.
TYPED_TEST(CoreCrossing, CrossingPredicatesTiesAndNearTies) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int zeros = 0;
  for (int i = 0; i < 3000; ++i) {
    const auto gi = [&](int r) { return T(rng.uniform_int(-r, r)); };
    const Vec2<T> x{gi(64), gi(64)};
    const auto through = [&](Vec2<T>& p, Vec2<T>& q) {
      Vec2<T> u{gi(7), gi(7)};
      if (u == Vec2<T>{}) u.x = 1;
      p = x + gi(5) * u;
      q = x + (gi(5) + T(11)) * u;
    };
    Vec2<T> v[7];
    through(v[0], v[1]);
    through(v[2], v[3]);
    through(v[4], v[5]);
    v[6] = Vec2<T>{gi(64), gi(64)};
    if (i % 3 != 0) {  // a near tie: one coordinate moved by one ulp
      T& c = v[rng.uniform_int(0, 5)][rng.uniform_int(0, 1)];
      c = std::nextafter(c, rng.uniform_int(0, 1) ? T(1000) : T(-1000));
    }
    const int s = exact_side(v[0], v[1], v[2], v[3], v[4], v[5]);
    zeros += s == 0 ? 1 : 0;
    EXPECT_EQ(locus::to_int(locus::side_of_crossing(v[0], v[1], v[2], v[3], v[4], v[5])), s);
    // Ordering along the line v[4] v[5] (origin v[6]) of its crossings with v[0] v[1] and v[2]
    // v[3]: they meet it at X (tie) or a hair away.
    EXPECT_EQ(
        locus::to_int(locus::compare_crossing_params(v[4], v[5], v[6], v[0], v[1], v[2], v[3])),
        exact_compare(v[4], v[5], v[6], v[0], v[1], v[2], v[3]));
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(zeros, 500);
}

TYPED_TEST(CoreCrossing, CrossingPredicatesParallelAndNonFinite) {
  using T = TypeParam;
  const Vec2<T> p0{0, 0}, p1{2, 1}, q0{0, 1}, q1{4, 3}, a{-1, 0}, b{1, 5};
  EXPECT_EQ(locus::side_of_crossing(p0, p1, q0, q1, a, b), locus::Sign::zero);  // parallel
  EXPECT_EQ(locus::compare_crossing_params(p0, p1, a, a, b, q0, q1), locus::Sign::zero);
  EXPECT_NE(locus::side_of_crossing(p0, p1, a, b, q0, q1), locus::Sign::zero);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(locus::side_of_crossing(p0, Vec2<T>{nan, 1}, a, b, q0, q1), locus::Sign::zero);
  EXPECT_EQ(locus::compare_crossing_params(a, b, q0, p0, Vec2<T>{1, nan}, q0, p1),
            locus::Sign::zero);
}

}  // namespace
