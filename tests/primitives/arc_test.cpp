// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/arc.hpp (row prim2.quadratic, circular arcs; book section 5.2.3).
#include <locus/primitives/arc.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class ArcTest : public ::testing::Test {};
TYPED_TEST_SUITE(ArcTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Arc2d> && std::is_trivially_copyable_v<Arc2f>);

TYPED_TEST(ArcTest, QuarterArcEndpointsAndLength) {
  using T = TypeParam;
  const Arc2<T> arc{{{T(1), T(1)}, T(2)}, T(0), pi_v<T> / 2};
  EXPECT_TRUE(locus_test::vec_near(start_point(arc), Vec2<T>{T(3), T(1)}, tol<T>(4, T(3))));
  EXPECT_TRUE(locus_test::vec_near(end_point(arc), Vec2<T>{T(1), T(3)}, tol<T>(4, T(3))));
  EXPECT_NEAR(length(arc), pi_v<T>, tol<T>(2, T(4)));
  EXPECT_TRUE(contains_angle(arc, T(0.7)));
  EXPECT_FALSE(contains_angle(arc, T(-0.1)));
  EXPECT_TRUE(contains_angle(arc, T(0.7) - T(4) * pi_v<T>));
  EXPECT_TRUE(contains_direction(arc, Vec2<T>{T(2), T(2)}));
  EXPECT_TRUE(contains_direction(arc, Vec2<T>{T(5), T(1)}));  // on the start ray
  EXPECT_FALSE(contains_direction(arc, Vec2<T>{T(0), T(0)}));
  EXPECT_FALSE(contains_direction(arc, Vec2<T>{T(0), T(1.5)}));
  EXPECT_FALSE(contains_direction(arc, arc.circle.center));
  EXPECT_FALSE(is_degenerate(arc));
}

// Oracle: contains_direction (vector tests) agrees with contains_angle of atan2 (angle tests)
// for directions not within rounding distance of the end rays; reflex, convex, half and full
// sweeps.
TYPED_TEST(ArcTest, DirectionTestAgreesWithAngleTest) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int inside = 0, outside = 0;
  for (int k = 0; k < 20000; ++k) {
    T sweep = rng.uniform<T>(0, T(2) * pi_v<T>);
    if (k % 10 == 0) sweep = pi_v<T>;
    if (k % 10 == 1) sweep = T(2) * pi_v<T>;
    const Arc2<T> arc{
        {rng.vec<T, 2>(-3, 3), rng.uniform<T>(T(0.5), 2)}, rng.uniform<T>(-10, 10), sweep};
    const T ang = rng.uniform<T>(-10, 10);
    const Vec2<T> p =
        arc.circle.center + rng.uniform<T>(T(0.1), 3) * Vec2<T>{std::cos(ang), std::sin(ang)};
    // Skip directions within 1e-3 rad of an end ray, where both tests round differently.
    const auto near_angle = [&](T x, T y) {
      T d = std::fmod(std::abs(x - y), T(2) * pi_v<T>);
      return std::min(d, T(2) * pi_v<T> - d) < T(1e-3);
    };
    if (sweep < T(2) * pi_v<T> && (near_angle(ang, arc.start) || near_angle(ang, end_angle(arc))))
      continue;
    const bool a = contains_angle(arc, ang), d = contains_direction(arc, p);
    EXPECT_EQ(a, d) << "start " << arc.start << " sweep " << sweep << " angle " << ang;
    (a ? inside : outside)++;
    EXPECT_TRUE(contains_angle(arc, arc.start + rng.uniform<T>(0, 1) * sweep));
  }
  EXPECT_GT(inside, 5000);
  EXPECT_GT(outside, 5000);
}

TYPED_TEST(ArcTest, ArcBetweenPointsRoundTrip) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    const Circle2<T> c{rng.vec<T, 2>(-3, 3), rng.uniform<T>(T(0.5), 2)};
    const T a0 = rng.uniform<T>(-4, 4), a1 = rng.uniform<T>(-4, 4);
    const Vec2<T> p0 = point_at(c, a0), p1 = point_at(c, a1);
    const Arc2<T> arc = arc_between(c, p0, p1);
    EXPECT_GE(arc.sweep, T(0));
    EXPECT_LE(arc.sweep, T(2) * pi_v<T>);
    EXPECT_TRUE(locus_test::vec_near(start_point(arc), p0, tol<T>(64, T(8))));
    EXPECT_TRUE(locus_test::vec_near(end_point(arc), p1, tol<T>(64, T(8))));
    // The sweep is the counter-clockwise angle from a0 to a1, modulo 2 pi.
    T expect = std::fmod(a1 - a0, T(2) * pi_v<T>);
    if (expect < T(0)) expect += T(2) * pi_v<T>;
    const T diff = std::abs(arc.sweep - expect);
    EXPECT_TRUE(diff < tol<T>(64, T(8)) || std::abs(diff - T(2) * pi_v<T>) < tol<T>(64, T(8)));
  }
}

TYPED_TEST(ArcTest, DegenerateArcs) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Circle2<T> c{{T(0), T(0)}, T(1)};
  EXPECT_TRUE(is_degenerate(Arc2<T>{c, T(0), T(-0.5)}));
  EXPECT_TRUE(is_degenerate(Arc2<T>{c, T(0), T(7)}));
  EXPECT_TRUE(is_degenerate(Arc2<T>{c, nan, T(1)}));
  EXPECT_TRUE(is_degenerate(Arc2<T>{{{T(0), T(0)}, T(0)}, T(0), T(1)}));
  const Arc2<T> zero{c, T(1), T(0)};
  EXPECT_FALSE(is_degenerate(zero));
  EXPECT_TRUE(contains_angle(zero, T(1)));
  EXPECT_FALSE(contains_angle(zero, T(1.01)));
  EXPECT_FALSE(contains_direction(zero, Vec2<T>{-std::cos(T(1)), -std::sin(T(1))}));
  EXPECT_FALSE(contains_angle(Arc2<T>{c, T(0), T(1)}, nan));
  EXPECT_FALSE(contains_direction(Arc2<T>{c, T(0), T(1)}, Vec2<T>{nan, T(0)}));
  const Arc2<T> same = arc_between(c, Vec2<T>{T(0), T(2)}, Vec2<T>{T(0), T(5)});
  EXPECT_EQ(same.sweep, T(0));
}
