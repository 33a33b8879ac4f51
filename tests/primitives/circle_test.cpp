// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/circle.hpp (row prim2.quadratic, circles; book figure 5.15).
#include <locus/primitives/circle.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class CircleTest : public ::testing::Test {};
TYPED_TEST_SUITE(CircleTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Circle2d> && std::is_trivially_copyable_v<Circle3f>);
static_assert(std::is_aggregate_v<Disk3d>);

// Figure 5.15: distance form |X - C| = r and parametric form C + r (cos t, sin t) describe the
// same set; the implicit value is negative inside and positive outside.
TYPED_TEST(CircleTest, Fig5_15_ImplicitAndParametricFormsAgree) {
  using T = TypeParam;
  const Circle2<T> c{{T(1), T(-2)}, T(3)};
  EXPECT_TRUE(locus_test::vec_near(point_at(c, T(0)), Vec2<T>{T(4), T(-2)}, tol<T>(4, T(4))));
  EXPECT_TRUE(locus_test::vec_near(point_at(c, pi_v<T> / 2), Vec2<T>{T(1), T(1)}, tol<T>(4, T(4))));
  EXPECT_LT(evaluate(c, Vec2<T>{T(1), T(0)}), T(0));
  EXPECT_EQ(evaluate(c, Vec2<T>{T(1), T(1)}), T(0));
  EXPECT_GT(evaluate(c, Vec2<T>{T(5), T(0)}), T(0));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    const Circle2<T> r{rng.vec<T, 2>(-10, 10), rng.uniform<T>(T(0.1), 5)};
    const T a = rng.uniform<T>(-10, 10);
    const Vec2<T> p = point_at(r, a);
    EXPECT_NEAR(length(p - r.center), r.radius, tol<T>(16, T(15)));
    EXPECT_NEAR(evaluate(r, p), T(0), tol<T>(64, T(400)));
    // Counter-clockwise: the tangent direction at angle a is perp(p - center).
    const Vec2<T> q = point_at(r, a + T(1e-2));
    EXPECT_GT(perp_dot(p - r.center, q - r.center), T(0));
  }
  EXPECT_NEAR(area(c), T(9) * pi_v<T>, tol<T>(4, T(30)));
  EXPECT_NEAR(circumference(c), T(6) * pi_v<T>, tol<T>(4, T(20)));
}

// Circles in 3D: the in-plane axes form a right-handed orthonormal frame with the normal; every
// point lies on the sphere of radius r about C and in the plane; the disk map is affine.
TYPED_TEST(CircleTest, Circle3AndDisk3InTheirPlane) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    Vec3<T> n = rng.unit<T, 3>() * rng.uniform<T>(T(0.01), 100);
    if (k < 6)
      n = (k % 2 ? T(-1) : T(1)) * unit_vec<T, 3>(k / 2);  // the axis directions, both signs
    const Circle3<T> c{rng.vec<T, 3>(-5, 5), n, rng.uniform<T>(T(0.1), 3)};
    const CircleAxes<T> ax = in_plane_axes(c);
    const Vec3<T> un = normalize(n);
    EXPECT_NEAR(length(ax.u), T(1), tol<T>(8));
    EXPECT_NEAR(length(ax.v), T(1), tol<T>(8));
    EXPECT_NEAR(dot(ax.u, ax.v), T(0), tol<T>(8));
    EXPECT_NEAR(dot(ax.u, un), T(0), tol<T>(8));
    EXPECT_TRUE(locus_test::vec_near(cross(ax.u, ax.v), un, tol<T>(16)));
    const T a = rng.uniform<T>(-4, 4);
    const Vec3<T> p = point_at(c, a);
    EXPECT_NEAR(length(p - c.center), c.radius, tol<T>(32, T(8)));
    EXPECT_NEAR(dot(p - c.center, un), T(0), tol<T>(32, T(8)));
    const Disk3<T> d{c.center, c.normal, c.radius};
    const Vec2<T> st{c.radius * std::cos(a), c.radius * std::sin(a)};
    EXPECT_TRUE(locus_test::vec_near(point_at(d, st), p, tol<T>(32, T(8))));
    EXPECT_NEAR(area(d), pi_v<T> * c.radius * c.radius, tol<T>(8, T(30)));
  }
}

TYPED_TEST(CircleTest, DegenerateCircles) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_TRUE(is_degenerate(Circle2<T>{{T(0), T(0)}, T(0)}));
  EXPECT_TRUE(is_degenerate(Circle2<T>{{T(0), T(0)}, T(-1)}));
  EXPECT_TRUE(is_degenerate(Circle2<T>{{T(0), T(0)}, nan}));
  EXPECT_TRUE(is_degenerate(Circle2<T>{{nan, T(0)}, T(1)}));
  EXPECT_FALSE(is_degenerate(Circle2<T>{{T(0), T(0)}, T(1)}));
  const Circle2<T> pt{{T(2), T(3)}, T(0)};
  EXPECT_EQ(point_at(pt, T(1.3)), pt.center);  // a zero radius acts as the centre
  const Circle3<T> flat{{T(1), T(2), T(3)}, {}, T(2)};
  EXPECT_TRUE(is_degenerate(flat));
  EXPECT_EQ(in_plane_axes(flat).u, (Vec3<T>{}));
  EXPECT_EQ(point_at(flat, T(0.5)), flat.center);
  EXPECT_TRUE(is_degenerate(Disk3<T>{{T(0), T(0), T(0)}, {T(0), nan, T(1)}, T(1)}));
  EXPECT_EQ(point_at(Disk3<T>{{T(1), T(1), T(1)}, {T(0), nan, T(1)}, T(1)}, Vec2<T>{T(1), T(0)}),
            (Vec3<T>{T(1), T(1), T(1)}));
}
