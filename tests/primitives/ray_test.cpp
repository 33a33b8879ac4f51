// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/ray.hpp (rows prim2.linear, prim3.linear; book figure 5.1(b)).
#include <locus/primitives/ray.hpp>

#include "support/typed.hpp"

#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class RayTest : public ::testing::Test {};
TYPED_TEST_SUITE(RayTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Ray2f> && std::is_trivially_copyable_v<Ray3d>);

// Figure 5.1(b): a ray starts at P and runs along d for t >= 0.
TYPED_TEST(RayTest, Fig5_1b_PointAtAndSupportingLine) {
  using T = TypeParam;
  const Ray2<T> ray{{T(1), T(-1)}, {T(0.5), T(2)}};
  EXPECT_EQ(point_at(ray, T(0)), ray.origin);
  EXPECT_EQ(point_at(ray, T(2)), (Vec2<T>{T(2), T(3)}));
  const Line2<T> line = supporting_line(ray);
  for (T t : {T(0), T(0.25), T(3)}) EXPECT_EQ(point_at(line, t), point_at(ray, t));
}

TYPED_TEST(RayTest, NormalizedKeepsOriginAndDirectionSense) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    const Ray3<T> ray{rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-2, 2)};
    const auto n = normalized(ray);
    ASSERT_TRUE(n.has_value());
    EXPECT_EQ(n->origin, ray.origin);
    EXPECT_NEAR(length(n->direction), T(1), tol<T>(4));
    EXPECT_NEAR(dot(n->direction, ray.direction), length(ray.direction), tol<T>(8, T(4)));
    // Point at arc length s lies on the original ray at t = s / |d|.
    const T s = rng.uniform<T>(0, 3);
    EXPECT_TRUE(locus_test::vec_near(point_at(*n, s), point_at(ray, s / length(ray.direction)),
                                     tol<T>(32, T(8))));
  }
}

TYPED_TEST(RayTest, DegenerateRays) {
  using T = TypeParam;
  const Ray3<T> zero{{T(1), T(2), T(3)}, {}};
  EXPECT_TRUE(is_degenerate(zero));
  EXPECT_FALSE(normalized(zero).has_value());
  EXPECT_EQ(point_at(zero, T(7)), zero.origin);  // acts as the point origin
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_TRUE(is_degenerate(Ray2<T>{{T(0), T(0)}, {nan, T(1)}}));
  EXPECT_TRUE(is_degenerate(Ray2<T>{{std::numeric_limits<T>::infinity(), T(0)}, {T(1), T(1)}}));
  EXPECT_FALSE(is_degenerate(Ray2<T>{{T(0), T(0)}, {T(0), T(-1)}}));
}
