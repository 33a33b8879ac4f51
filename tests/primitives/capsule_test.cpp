// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/capsule.hpp (row prim3.solids: capsule; 2D stadium).
#include <locus/primitives/capsule.hpp>
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
class CapsuleTest : public ::testing::Test {};
TYPED_TEST_SUITE(CapsuleTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Capsule3d> && std::is_trivially_copyable_v<Capsule3f>);

namespace {
// Distance from x to the segment, written out independently (clamped projection).
template <class T, int N>
T seg_distance(const Segment<T, N>& s, const Vec<T, N>& x) {
  const Vec<T, N> d = s.p1 - s.p0;
  const T dd = dot(d, d);
  T t = dd > T(0) ? dot(x - s.p0, d) / dd : T(0);
  t = t < T(0) ? T(0) : (t > T(1) ? T(1) : t);
  return length(x - (s.p0 + t * d));
}
}  // namespace

TYPED_TEST(CapsuleTest, PointAtIsAtDistanceRadius) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    const Capsule3<T> c{{rng.vec<T, 3>(-3, 3), rng.vec<T, 3>(-3, 3)}, rng.uniform<T>(T(0.2), 2)};
    const Vec2<T> tt{rng.uniform<T>(0, 2 * pi_v<T>), rng.uniform<T>(0, 1)};
    const Vec3<T> p = point_at(c, tt);
    EXPECT_NEAR(seg_distance(c.segment, p), c.radius, tol<T>(128, 10));
  }
}

TYPED_TEST(CapsuleTest, VolumeAndAreaMatchMonteCarlo) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 3; ++trial) {
    const Capsule3<T> c{{rng.vec<T, 3>(-2, 2), rng.vec<T, 3>(-2, 2)},
                        rng.uniform<T>(T(0.3), T(1.5))};
    const auto box = bounding_box(c);
    const int n = 20000;
    int hits = 0;
    for (int s = 0; s < n; ++s) {
      Vec3<T> p{};
      for (int i = 0; i < 3; ++i) p[i] = rng.uniform<T>(box.min[i], box.max[i]);
      hits += seg_distance(c.segment, p) <= c.radius;
    }
    const double frac = double(hits) / n, expect = double(volume(c)) / double(volume(box));
    EXPECT_NEAR(frac, expect, 5 * std::sqrt(expect * (1 - expect) / n));  // 5 binomial sigma
    // The box is tight: the endpoint spheres touch it.
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(box.min[k], std::fmin(c.segment.p0[k], c.segment.p1[k]) - c.radius);
      EXPECT_EQ(box.max[k], std::fmax(c.segment.p0[k], c.segment.p1[k]) + c.radius);
    }
  }
  // 2D stadium area by Monte Carlo.
  const Capsule2<T> s{{{-1, 0}, {2, 1}}, T(0.75)};
  const auto box = bounding_box(s);
  const int n = 20000;
  int hits = 0;
  for (int k = 0; k < n; ++k) {
    const Vec2<T> p{rng.uniform<T>(box.min.x, box.max.x), rng.uniform<T>(box.min.y, box.max.y)};
    hits += seg_distance(s.segment, p) <= s.radius;
  }
  const double frac = double(hits) / n, expect = double(area(s)) / double(area(box));
  EXPECT_NEAR(frac, expect, 5 * std::sqrt(expect * (1 - expect) / n));
}

TYPED_TEST(CapsuleTest, LateralAreaIntegratedPlusSphere) {
  using T = TypeParam;
  const Capsule3<double> cd{{{1, -1, 2}, {-2, 1, 3.5}}, 0.8};
  const Capsule3<T> c{{vec_cast<T>(cd.segment.p0), vec_cast<T>(cd.segment.p1)}, T(cd.radius)};
  const int n = 64;  // constant integrand in t, periodic in theta: the midpoint rule is exact
  const double ha = 2 * pi_v<double> / n, ht = 1.0 / n, e = 1e-6;
  double lateral = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = (i + 0.5) * ha, t = (j + 0.5) * ht;
      const auto da =
          (point_at(cd, Vec2<double>{a + e, t}) - point_at(cd, Vec2<double>{a - e, t})) / (2 * e);
      const auto dt =
          (point_at(cd, Vec2<double>{a, t + e}) - point_at(cd, Vec2<double>{a, t - e})) / (2 * e);
      lateral += length(cross(da, dt)) * ha * ht;
    }
  // The two hemispherical caps make one sphere.
  const double total = lateral + double(surface_area(Sphere3<double>{{}, cd.radius}));
  EXPECT_NEAR(double(surface_area(c)), total, 1e-7 * total + double(tol<T>(32, 40)));
  // 2D perimeter: two straight sides and one full circle.
  const Capsule2<T> s{{{0, 0}, {3, 4}}, 1};
  EXPECT_NEAR(perimeter(s), T(10) + 2 * pi_v<T>, tol<T>(8, 20));
}

TYPED_TEST(CapsuleTest, Degenerate) {
  using T = TypeParam;
  const Capsule3<T> ball{{{1, 2, 3}, {1, 2, 3}}, 2};
  EXPECT_NEAR(volume(ball), volume(Sphere3<T>{{1, 2, 3}, 2}), tol<T>(8, 40));
  EXPECT_NEAR(surface_area(ball), surface_area(Sphere3<T>{{1, 2, 3}, 2}), tol<T>(8, 60));
  EXPECT_EQ(point_at(ball, Vec2<T>{1, T(0.5)}), ball.segment.p0);  // zero basis: the segment point
  const Capsule3<T> thin{{{0, 0, 0}, {1, 0, 0}}, 0};
  EXPECT_EQ(volume(thin), T(0));
  EXPECT_EQ(surface_area(thin), T(0));
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_TRUE(std::isnan(volume(Capsule3<T>{{{0, 0, 0}, {1, 0, 0}}, -1})));
  EXPECT_TRUE(std::isnan(surface_area(Capsule3<T>{{{0, 0, 0}, {1, 0, 0}}, nan})));
  EXPECT_TRUE(std::isnan(area(Capsule2<T>{{{0, 0}, {1, 0}}, -1})));
  EXPECT_TRUE(std::isnan(perimeter(Capsule2<T>{{{0, 0}, {1, 0}}, nan})));
}

TYPED_TEST(CapsuleTest, SymmetricSolidsHaveTheirCenterAsCentroid) {
  using T = TypeParam;
  const Capsule3<T> c{{{1, 2, 3}, {3, 2, -1}}, T(0.5)};
  EXPECT_EQ(centroid(c), (Vec3<T>{2, 2, 1}));
}
