// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/sphere.hpp (row prim3.solids: sphere).
#include <locus/primitives/sphere.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class SphereTest : public ::testing::Test {};
TYPED_TEST_SUITE(SphereTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Sphere3d> && std::is_trivially_copyable_v<Sphere3f>);

TYPED_TEST(SphereTest, ParametrisationConventions) {
  using T = TypeParam;
  const Sphere3<T> s{{1, 2, 3}, 2};
  const T pi = pi_v<T>;
  EXPECT_TRUE(vec_near(point_at(s, Vec2<T>{0, 0}), Vec3<T>{1, 2, 5}, tol<T>(8, 4)));        // north pole
  EXPECT_TRUE(vec_near(point_at(s, Vec2<T>{0, pi / 2}), Vec3<T>{3, 2, 3}, tol<T>(8, 4)));   // +x
  EXPECT_TRUE(vec_near(point_at(s, Vec2<T>{pi / 2, pi / 2}), Vec3<T>{1, 4, 3}, tol<T>(8, 4)));  // +y
  EXPECT_TRUE(vec_near(point_at(s, Vec2<T>{0, pi}), Vec3<T>{1, 2, 1}, tol<T>(8, 4)));       // south
}

TYPED_TEST(SphereTest, PointAtSatisfiesImplicitEquation) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    const Sphere3<T> s{rng.vec<T, 3>(-10, 10), rng.uniform<T>(T(0.1), 5)};
    const Vec2<T> tp{rng.uniform<T>(0, 2 * pi_v<T>), rng.uniform<T>(0, pi_v<T>)};
    const Vec3<T> p = point_at(s, tp);
    // |p - C|^2 - r^2 with |p| up to ~15: rounding of p is a few eps * 15, squared terms ~ 225.
    EXPECT_NEAR(signed_value(s, p), T(0), tol<T>(64, 225));
    const auto b = bounding_box(s);
    for (int i = 0; i < 3; ++i) {
      EXPECT_LE(b.min[i], p[i] + tol<T>(16, 15));
      EXPECT_GE(b.max[i], p[i] - tol<T>(16, 15));
    }
  }
}

TYPED_TEST(SphereTest, VolumeMatchesMonteCarlo) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Sphere3<T> s{{T(0.5), -1, 2}, T(1.5)};
  const auto box = bounding_box(s);
  const int n = 20000;
  int hits = 0;
  for (int k = 0; k < n; ++k) {
    Vec3<T> p{};
    for (int i = 0; i < 3; ++i) p[i] = rng.uniform<T>(box.min[i], box.max[i]);
    hits += signed_value(s, p) <= T(0);
  }
  const double frac = double(hits) / n, expect = double(volume(s)) / double(volume(box));
  // Binomial standard deviation sqrt(p(1-p)/n); 5 sigma fails with probability < 1e-6.
  EXPECT_NEAR(frac, expect, 5 * std::sqrt(expect * (1 - expect) / n));
}

TYPED_TEST(SphereTest, SurfaceAreaMatchesIntegratedAreaElement) {
  using T = TypeParam;
  // Midpoint rule over (theta, phi) of |dP/dtheta x dP/dphi| with central differences of point_at
  // (in double, independent of the closed form under test).
  const Sphere3<double> sd{{1, -2, 0.5}, 1.75};
  const Sphere3<T> s{vec_cast<T>(sd.center), T(sd.radius)};
  const int n = 200;
  const double ht = 2 * pi_v<double> / n, hp = pi_v<double> / n, e = 1e-6;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double t = (i + 0.5) * ht, p = (j + 0.5) * hp;
      const auto dt = (point_at(sd, Vec2<double>{t + e, p}) - point_at(sd, Vec2<double>{t - e, p})) / (2 * e);
      const auto dp = (point_at(sd, Vec2<double>{t, p + e}) - point_at(sd, Vec2<double>{t, p - e})) / (2 * e);
      sum += length(cross(dt, dp)) * ht * hp;
    }
  // Midpoint-rule error O(h^2) ~ 1e-4 relative; differences ~1e-9.
  EXPECT_NEAR(double(surface_area(s)), sum, 1e-3 * sum + double(tol<T>(16)) * sum);
}

TYPED_TEST(SphereTest, NDimensionalMeasuresAgreeWithClassicalFormulas) {
  using T = TypeParam;
  const T r = T(1.3), pi = pi_v<T>;
  EXPECT_NEAR(measure(Sphere<T, 2>{{0, 0}, r}), pi * r * r, tol<T>(16, 6));
  EXPECT_NEAR(boundary_measure(Sphere<T, 2>{{0, 0}, r}), 2 * pi * r, tol<T>(16, 9));
  EXPECT_NEAR(measure(Sphere3<T>{{0, 0, 0}, r}), volume(Sphere3<T>{{0, 0, 0}, r}), tol<T>(16, 10));
  EXPECT_NEAR(boundary_measure(Sphere3<T>{{0, 0, 0}, r}), surface_area(Sphere3<T>{{0, 0, 0}, r}),
              tol<T>(16, 22));
  EXPECT_NEAR((measure(Sphere<T, 4>{{}, r})), pi * pi / 2 * r * r * r * r, tol<T>(16, 15));
  EXPECT_NEAR((boundary_measure(Sphere<T, 4>{{}, r})), 2 * pi * pi * r * r * r, tol<T>(16, 45));
  EXPECT_NEAR((measure(Sphere<T, 1>{{}, r})), 2 * r, tol<T>(16, 3));
}

TYPED_TEST(SphereTest, DegenerateRadii) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Sphere3<T> pt{{1, 2, 3}, 0};
  EXPECT_TRUE(is_valid(pt));
  EXPECT_EQ(volume(pt), T(0));
  EXPECT_EQ(surface_area(pt), T(0));
  EXPECT_EQ(point_at(pt, Vec2<T>{1, 2}), pt.center);
  const Sphere3<T> neg{{0, 0, 0}, -1}, bad{{0, 0, 0}, nan}, inf_c{{nan, 0, 0}, 1};
  EXPECT_FALSE(is_valid(neg));
  EXPECT_FALSE(is_valid(bad));
  EXPECT_FALSE(is_valid(inf_c));
  EXPECT_TRUE(std::isnan(volume(neg)));
  EXPECT_TRUE(std::isnan(surface_area(bad)));
  EXPECT_TRUE(std::isnan(measure(neg)));
  EXPECT_TRUE(std::isnan(boundary_measure(bad)));
}
