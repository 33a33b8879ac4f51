// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/segment.hpp (rows prim2.linear, prim3.linear; book figure 5.1(c)).
#include <locus/primitives/segment.hpp>

#include "support/typed.hpp"

#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class SegmentTest : public ::testing::Test {};
TYPED_TEST_SUITE(SegmentTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Segment2d> && std::is_trivially_copyable_v<Segment3f>);
static_assert(std::is_aggregate_v<SegmentCDE3<double>>);
static_assert(midpoint(Segment2d{{0, 0}, {2, 4}}) == Vec2d{1, 2}, "constexpr midpoint");

// Figure 5.1(c): the segment from P0 to P1, t in [0, 1], endpoints reproduced exactly.
TYPED_TEST(SegmentTest, Fig5_1c_EndpointForm) {
  using T = TypeParam;
  const Segment2<T> s{{T(0.1), T(0.7)}, {T(3.3), T(-1.9)}};
  EXPECT_EQ(point_at(s, T(0)), s.p0);
  EXPECT_EQ(point_at(s, T(1)), s.p1);
  EXPECT_EQ(s[0], s.p0);
  EXPECT_EQ(s[1], s.p1);
  const Segment3<T> s3{{T(0), T(0), T(0)}, {T(2), T(4), T(4)}};
  EXPECT_EQ(point_at(s3, T(0.5)), (Vec3<T>{T(1), T(2), T(2)}));
  EXPECT_EQ(length(s3), T(6));
  EXPECT_EQ(sqr_length(s3), T(36));
  EXPECT_EQ(direction(s3), (Vec3<T>{T(2), T(4), T(4)}));
  EXPECT_EQ(midpoint(s3), (Vec3<T>{T(1), T(2), T(2)}));
  EXPECT_TRUE(
      locus_test::vec_near(unit_direction(s3), Vec3<T>{T(1) / 3, T(2) / 3, T(2) / 3}, tol<T>(2)));
}

// The center-direction-extent form of figure 5.1(c) (the symmetric form): round trips.
TYPED_TEST(SegmentTest, CenterDirectionExtentRoundTrip) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    const Segment3<T> s{rng.vec<T, 3>(-10, 10), rng.vec<T, 3>(-10, 10)};
    const SegmentCDE3<T> c = to_cde(s);
    EXPECT_NEAR(length(c.direction), T(1), tol<T>(4));
    EXPECT_NEAR(length(c), length(s), tol<T>(8, length(s)));
    const Segment3<T> back = to_segment(c);
    // Error: midpoint and the unit direction are rounded, scaled by the coordinates (<= 10).
    EXPECT_TRUE(locus_test::vec_near(back.p0, s.p0, tol<T>(64, T(10))));
    EXPECT_TRUE(locus_test::vec_near(back.p1, s.p1, tol<T>(64, T(10))));
    // Same parameterised point set: cde s = (t - 1/2) * length.
    const T t = rng.uniform<T>(0, 1);
    EXPECT_TRUE(locus_test::vec_near(point_at(c, (t - T(0.5)) * length(s)), point_at(s, t),
                                     tol<T>(64, T(10))));
    // The supporting line has the same parameter.
    EXPECT_TRUE(
        locus_test::vec_near(point_at(supporting_line(s), t), point_at(s, t), tol<T>(8, T(20))));
  }
}

TYPED_TEST(SegmentTest, DegenerateSegments) {
  using T = TypeParam;
  const Segment2<T> pt{{T(1), T(2)}, {T(1), T(2)}};
  EXPECT_TRUE(is_degenerate(pt));
  EXPECT_EQ(length(pt), T(0));
  EXPECT_EQ(unit_direction(pt), (Vec2<T>{}));
  const SegmentCDE2<T> c = to_cde(pt);
  EXPECT_EQ(c.center, pt.p0);
  EXPECT_EQ(c.direction, (Vec2<T>{}));
  EXPECT_EQ(c.extent, T(0));
  EXPECT_EQ(to_segment(c).p0, pt.p0);
  EXPECT_EQ(point_at(pt, T(0.3)), pt.p0);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_TRUE(is_degenerate(Segment2<T>{{nan, T(0)}, {T(1), T(1)}}));
  EXPECT_FALSE(
      is_degenerate(Segment2<T>{{T(0), T(0)}, {T(0), std::numeric_limits<T>::denorm_min()}}));
  // The midpoint of far-apart huge coordinates does not overflow.
  const T big = std::numeric_limits<T>::max();
  const Segment2<T> h{{big, -big}, {big, big}};
  EXPECT_EQ(midpoint(h), (Vec2<T>{big, T(0)}));
  // Length of a segment whose squared length overflows is still finite.
  const Segment2<T> l{{T(0), T(0)}, {big / T(2), big / T(2)}};
  EXPECT_TRUE(std::isfinite(length(l)));
}

TYPED_TEST(SegmentTest, ReversalAndTranslationInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    const Segment2<T> s{rng.vec<T, 2>(-4, 4), rng.vec<T, 2>(-4, 4)};
    const Segment2<T> r{s.p1, s.p0};
    const T t = rng.uniform<T>(0, 1);
    EXPECT_TRUE(locus_test::vec_near(point_at(s, t), point_at(r, T(1) - t), tol<T>(8, T(4))));
    EXPECT_EQ(length(s), length(r));
    EXPECT_EQ(midpoint(s), midpoint(r));
    const Vec2<T> d{T(rng.uniform_int(-8, 8)), T(rng.uniform_int(-8, 8))};
    const Segment2<T> m{s.p0 + d, s.p1 + d};
    EXPECT_NEAR(length(m), length(s), tol<T>(16, T(8)));
  }
}
