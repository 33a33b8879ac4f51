// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_plane.hpp, point_circle.hpp, point_sphere.hpp (rows dist3.pt-plane,
// dist3.pt-circle-disk, dist2.pt-quadratic (circle), dist3.pt-ellipsoid (sphere); book figures
// 10.6, 10.7, 10.16-10.19).
#include <locus/distance/point_circle.hpp>
#include <locus/distance/point_plane.hpp>
#include <locus/distance/point_sphere.hpp>

#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <limits>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;

template <class T>
class PointRoundTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointRoundTest, locus_test::RealTypes);

namespace {

template <class T>
T random_radius(Rng& rng) {
  return rng.uniform_int(0, 9) == 0 ? T(0) : rng.uniform<T>(T(0.1), T(8));
}

}  // namespace

TYPED_TEST(PointRoundTest, Harness) {
  using T = TypeParam;
  const T S = 10;
  dist::check_pairs<T, 3, Vec3<T>, Plane3<T>>([&](Rng& rng) {
    const Vec3<T> n = rng.unit<T, 3>() * rng.uniform<T>(T(0.1), T(10));
    return std::pair{rng.vec<T, 3>(-S, S), plane_from_point_normal(rng.vec<T, 3>(-S, S), n)};
  });
  dist::check_pairs<T, 2, Vec2<T>, Circle2<T>>([&](Rng& rng) {
    return std::pair{rng.vec<T, 2>(-S, S), Circle2<T>{rng.vec<T, 2>(-S, S), random_radius<T>(rng)}};
  });
  dist::check_pairs<T, 3, Vec3<T>, Circle3<T>>([&](Rng& rng) {
    return std::pair{rng.vec<T, 3>(-S, S), Circle3<T>{rng.vec<T, 3>(-S, S), rng.unit<T, 3>() * T(3),
                                                      random_radius<T>(rng)}};
  });
  dist::check_pairs<T, 3, Vec3<T>, Disk3<T>>([&](Rng& rng) {
    return std::pair{rng.vec<T, 3>(-S, S),
                     Disk3<T>{rng.vec<T, 3>(-S, S), rng.unit<T, 3>(), random_radius<T>(rng)}};
  });
  dist::check_pairs<T, 3, Vec3<T>, Sphere3<T>>([&](Rng& rng) {
    return std::pair{rng.vec<T, 3>(-S, S), Sphere3<T>{rng.vec<T, 3>(-S, S), random_radius<T>(rng)}};
  });
}

// Figures 10.6 / 10.7: the signed distance is positive on the normal's side; the closest point
// is the orthogonal projection; a non-unit normal gives the same answers.
TYPED_TEST(PointRoundTest, Figure10_6SignedPointPlane) {
  using T = TypeParam;
  const Plane3<T> pl =
      plane_from_point_normal(Vec3<T>{T(0), T(0), T(2)}, Vec3<T>{T(0), T(0), T(5)});
  const auto above = distance(Vec3<T>{T(1), T(-3), T(7)}, pl);
  EXPECT_EQ(above.distance, T(5));
  EXPECT_EQ(above.closest[1], (Vec3<T>{T(1), T(-3), T(2)}));
  EXPECT_EQ(signed_distance(Vec3<T>{T(1), T(-3), T(7)}, pl), T(5));
  EXPECT_EQ(signed_distance(Vec3<T>{T(1), T(-3), T(-1)}, pl), T(-3));
  EXPECT_EQ(distance(Vec3<T>{T(1), T(-3), T(-1)}, pl).distance, T(3));
  const auto sw = distance(pl, Vec3<T>{T(1), T(-3), T(7)});
  EXPECT_EQ(sw.closest[0], above.closest[1]);
  EXPECT_EQ(closest_point(Vec3<T>{T(1), T(-3), T(7)}, pl), above.closest[1]);
  // Invariance: the signed distance of p + k n_unit grows by k.
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 100; ++i) {
    const Vec3<T> n = rng.unit<T, 3>();
    const Plane3<T> q = plane_from_point_normal(rng.vec<T, 3>(-5, 5), n * T(3));
    const Vec3<T> p = rng.vec<T, 3>(-5, 5);
    const T k = rng.uniform<T>(-5, 5);
    EXPECT_NEAR(signed_distance(p + k * n, q) - signed_distance(p, q), k, tol<T>(64, T(20)));
  }
}

// Figures 10.16-10.19: point to circle and to disk in 3D, projection inside and outside.
TYPED_TEST(PointRoundTest, Figure10_16CircleAndDisk) {
  using T = TypeParam;
  const Circle3<T> c{{T(1), T(1), T(1)}, {T(0), T(0), T(2)}, T(5)};
  const auto out = distance(Vec3<T>{T(1) + T(8), T(1), T(1) + T(4)}, c);  // 3 outside, 4 above
  EXPECT_NEAR(out.distance, T(5), tol<T>(16, T(10)));
  EXPECT_TRUE(locus_test::vec_near(out.closest[1], Vec3<T>{T(6), T(1), T(1)}, tol<T>(16, T(10))));
  const auto in = distance(Vec3<T>{T(1) + T(2), T(1), T(1) + T(4)}, c);  // 3 inside the rim
  EXPECT_NEAR(in.distance, T(5), tol<T>(16, T(10)));
  const Disk3<T> d{c.center, c.normal, c.radius};
  const auto din = distance(Vec3<T>{T(1) + T(2), T(1), T(1) + T(4)}, d);  // above the disk
  EXPECT_NEAR(din.distance, T(4), tol<T>(16, T(10)));
  EXPECT_TRUE(locus_test::vec_near(din.closest[1], Vec3<T>{T(3), T(1), T(1)}, tol<T>(16, T(10))));
  const auto dout = distance(Vec3<T>{T(1) + T(8), T(1), T(1) + T(4)}, d);
  EXPECT_NEAR(dout.distance, T(5), tol<T>(16, T(10)));
  // On the axis: every circle point is equally close.
  const auto axis = distance(Vec3<T>{T(1), T(1), T(13)}, c);
  EXPECT_FALSE(axis.unique);
  EXPECT_NEAR(axis.distance, T(13), tol<T>(16, T(13)));
  EXPECT_TRUE(distance(Vec3<T>{T(1), T(1), T(13)}, d).unique);
  // 2D circle: inside, outside, center.
  const Circle2<T> c2{{T(1), T(2)}, T(5)};
  EXPECT_EQ(distance(Vec2<T>{T(4), T(6)}, c2).distance, T(0));
  EXPECT_NEAR(distance(Vec2<T>{T(7), T(10)}, c2).distance, T(5), tol<T>(16, T(10)));
  EXPECT_NEAR(distance(Vec2<T>{T(1), T(4)}, c2).distance, T(3), tol<T>(16, T(10)));
  EXPECT_FALSE(distance(c2.center, c2).unique);
  EXPECT_EQ(distance(c2.center, c2).distance, T(5));
  EXPECT_NEAR(distance(Vec2<T>{T(1), T(10)}, c2).param_b, pi_v<T> / T(2), tol<T>(8));
}

TYPED_TEST(PointRoundTest, SphereSurfaceAndBall) {
  using T = TypeParam;
  const Sphere3<T> s{{T(1), T(2), T(3)}, T(5)};
  EXPECT_EQ(distance(Vec3<T>{T(1), T(2), T(15)}, s).distance, T(7));
  EXPECT_EQ(distance(Vec3<T>{T(1), T(2), T(4)}, s).distance, T(4));  // inside: to the surface
  EXPECT_EQ(distance_to_ball(Vec3<T>{T(1), T(2), T(4)}, s), T(0));
  EXPECT_EQ(distance_to_ball(Vec3<T>{T(1), T(2), T(15)}, s), T(7));
  const auto c = distance(s.center, s);
  EXPECT_FALSE(c.unique);
  EXPECT_EQ(c.distance, T(5));
  EXPECT_EQ(c.closest[1], (Vec3<T>{T(1), T(2), T(8)}));
  const auto e = distance(s, Vec3<T>{T(1), T(2), T(-15)});
  EXPECT_NEAR(e.param_a.y, pi_v<T>, tol<T>(8));
  EXPECT_EQ(e.distance, T(13));
}

TYPED_TEST(PointRoundTest, ZeroRadiiAndBadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  // Zero radii: the center.
  EXPECT_EQ(distance(Vec2<T>{T(4), T(5)}, Circle2<T>{{T(1), T(1)}, T(0)}).distance, T(5));
  EXPECT_TRUE(distance(Vec2<T>{T(1), T(1)}, Circle2<T>{{T(1), T(1)}, T(0)}).unique);
  EXPECT_EQ(distance(Vec3<T>{T(0), T(3), T(4)}, Circle3<T>{{}, {T(0), T(0), T(1)}, T(0)}).distance,
            T(5));
  EXPECT_EQ(distance(Vec3<T>{T(0), T(3), T(4)}, Disk3<T>{{}, {T(0), T(0), T(1)}, T(0)}).distance,
            T(5));
  EXPECT_EQ(distance(Vec3<T>{T(0), T(3), T(4)}, Sphere3<T>{{}, T(0)}).distance, T(5));
  // Negative radii, zero normals, NaN and infinity: the NaN result.
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{}, Circle2<T>{{}, T(-1)})));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, Circle3<T>{{}, {}, T(1)})));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, Disk3<T>{{}, {}, T(1)})));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, Sphere3<T>{{}, T(-2)})));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, Plane3<T>{{}, T(1)})));
  EXPECT_TRUE(std::isnan(signed_distance(Vec3<T>{}, Plane3<T>{{}, T(1)})));
  EXPECT_TRUE(
      dist::is_nan_result(distance(Vec3<T>{nan, T(0), T(0)}, Plane3<T>{{T(0), T(0), T(1)}, T(1)})));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, Sphere3<T>{{inf, T(0), T(0)}, T(1)})));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{}, Circle2<T>{{}, nan})));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, Disk3<T>{{}, {T(0), T(0), T(1)}, inf})));
  EXPECT_TRUE(std::isnan(distance_to_ball(Vec3<T>{}, Sphere3<T>{{}, T(-1)})));
}
