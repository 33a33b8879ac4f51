// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/cylinder.hpp (row prim3.solids: finite and infinite cylinders).
#include <locus/primitives/circle.hpp>
#include <locus/primitives/cylinder.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class CylinderTest : public ::testing::Test {};
TYPED_TEST_SUITE(CylinderTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Cylinder3d> && std::is_trivially_copyable_v<Cylinder3f>);

namespace {
template <class T>
Cylinder3<T> random_cylinder(Rng& rng) {
  return {{rng.vec<T, 3>(-5, 5), rng.unit<T, 3>()},
          rng.uniform<T>(T(0.3), 2),
          rng.uniform<T>(T(0.5), 4)};
}

// Membership written out independently of the header: axial coordinate and radial distance.
template <class T>
bool inside(const Cylinder3<T>& c, const Vec3<T>& x) {
  const Vec3<T> d = x - c.axis.origin;
  const T h = dot(d, c.axis.direction);
  return std::fabs(h) <= c.height / 2 && length(cross(d, c.axis.direction)) <= c.radius;
}

// (1/3) * flux of X - p through a parametrised surface patch (quadrature over [u0,u1]x[v0,v1],
// central differences of point_at); its area in *area: the divergence theorem as a second,
// independent volume algorithm. When `outward_ref` is given, each normal is flipped to point away
// from outward_ref(u, v) (for open lateral surfaces); otherwise the parametrisation's orientation
// is used.
template <class F, class G>
double flux_volume(F&& pt, G&& outward_ref, double u0, double u1, double v0, double v1,
                   const Vec3<double>& p, int nu, int nv, double* area = nullptr) {
  // Midpoint rule in u (the periodic angle: spectrally accurate), two-point Gauss-Legendre on
  // each of the nv cells in v (exact for cubics).
  const double hu = (u1 - u0) / nu, hv = (v1 - v0) / nv, e = 1e-6, g = hv / (2 * std::sqrt(3.0));
  double s = 0, a = 0;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      for (const double off : {-g, g}) {
        const double u = u0 + (i + 0.5) * hu, v = v0 + (j + 0.5) * hv + off;
        const Vec3<double> x = pt(u, v);
        Vec3<double> nn =
            cross((pt(u + e, v) - pt(u - e, v)) / (2 * e), (pt(u, v + e) - pt(u, v - e)) / (2 * e));
        const Vec3<double> ref = outward_ref(u, v);
        if (!(ref == x) && dot(nn, x - ref) < 0) nn = -nn;
        s += dot(x - p, nn) * hu * hv / 2;
        a += length(nn) * hu * hv / 2;
      }
  if (area) *area = a;
  return s / 3;
}
}  // namespace

TYPED_TEST(CylinderTest, PointAtIsOnTheLateralSurfaceAndMatchesCircle3) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    const auto c = random_cylinder<T>(rng);
    const T theta = rng.uniform<T>(0, 2 * pi_v<T>), t = rng.uniform<T>(-c.height / 2, c.height / 2);
    const Vec3<T> p = point_at(c, Vec2<T>{theta, t});
    EXPECT_NEAR(signed_value(c, p), T(0), tol<T>(128, 50));
    EXPECT_NEAR(dot(p - c.axis.origin, c.axis.direction), t, tol<T>(64, 10));
    // The cross-section at height t is the Circle3 with the same normal, parametrised alike.
    const Circle3<T> circ{c.axis.origin + t * c.axis.direction, c.axis.direction, c.radius};
    EXPECT_TRUE(vec_near(point_at(circ, theta), p, tol<T>(64, 10)));
  }
}

TYPED_TEST(CylinderTest, VolumeMatchesMonteCarlo) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 3; ++trial) {
    const auto c = random_cylinder<T>(rng);
    const auto box = bounding_box(c);
    const int n = 20000;
    int hits = 0;
    for (int k = 0; k < n; ++k) {
      Vec3<T> p{};
      for (int i = 0; i < 3; ++i) p[i] = rng.uniform<T>(box.min[i], box.max[i]);
      hits += inside(c, p);
    }
    const double frac = double(hits) / n, expect = double(volume(c)) / double(volume(box));
    EXPECT_NEAR(frac, expect, 5 * std::sqrt(expect * (1 - expect) / n));  // 5 binomial sigma
  }
}

TYPED_TEST(CylinderTest, LateralAreaMatchesIntegratedAreaElement) {
  using T = TypeParam;
  const Cylinder3<double> cd{{{1, 2, 3}, normalize(Vec3<double>{1, -2, 2})}, 1.25, 3.5};
  const Cylinder3<T> c{
      {vec_cast<T>(cd.axis.origin), vec_cast<T>(cd.axis.direction)}, T(cd.radius), T(cd.height)};
  const auto pt = [&](double a, double h) { return point_at(cd, Vec2<double>{a, h}); };
  const auto ref = [&](double, double h) { return cd.axis.origin + h * cd.axis.direction; };
  double sum = 0;
  (void)flux_volume(pt, ref, 0, 2 * pi_v<double>, -cd.height / 2, cd.height / 2, Vec3<double>{}, 64,
                    4, &sum);
  EXPECT_NEAR(double(lateral_area(c)), sum, 1e-6 * sum + double(tol<T>(16)) * sum);
  // The two caps are disks of area pi r^2.
  EXPECT_NEAR(double(surface_area(c) - lateral_area(c)), 2 * pi_v<double> * cd.radius * cd.radius,
              double(tol<T>(64, 30)));
}

TYPED_TEST(CylinderTest, BoundingBoxIsTight) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 50; ++trial) {
    const auto c = random_cylinder<T>(rng);
    const auto box = bounding_box(c);
    Vec3<T> lo = splat<T, 3>(T(1e30)), hi = splat<T, 3>(T(-1e30));
    for (int i = 0; i < 720; ++i)
      for (const T t : {-c.height / 2, c.height / 2}) {
        const Vec3<T> p = point_at(c, Vec2<T>{T(i) * pi_v<T> / 360, t});
        lo = cwise_min(lo, p);
        hi = cwise_max(hi, p);
      }
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(box.min[k], lo[k] + tol<T>(64, 10));
      EXPECT_GE(box.max[k], hi[k] - tol<T>(64, 10));
      // Angular spacing pi/360: the sampled extreme is within r (1 - cos(pi/360)) < 1e-4.
      EXPECT_LE(lo[k] - box.min[k], T(1e-4) + tol<T>(64, 10));
      EXPECT_LE(box.max[k] - hi[k], T(1e-4) + tol<T>(64, 10));
    }
  }
}

TYPED_TEST(CylinderTest, InfiniteAndDegenerate) {
  using T = TypeParam;
  const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  const Cylinder3<T> infc{{{0, 0, 0}, {0, 0, 1}}, 1, inf};
  EXPECT_TRUE(is_infinite(infc));
  EXPECT_EQ(volume(infc), inf);
  EXPECT_EQ(lateral_area(infc), inf);
  EXPECT_EQ(signed_value(infc, Vec3<T>{1, 0, 1e6}), T(0));
  const auto b = bounding_box(infc);
  EXPECT_EQ(b.min, (Vec3<T>{-1, -1, -inf}));
  EXPECT_EQ(b.max, (Vec3<T>{1, 1, inf}));
  const Cylinder3<T> seg{{{0, 0, 0}, {0, 0, 1}}, 0, 2};
  EXPECT_FALSE(is_infinite(seg));
  EXPECT_EQ(volume(seg), T(0));
  EXPECT_EQ(surface_area(seg), T(0));
  const Cylinder3<T> disk{{{0, 0, 0}, {0, 0, 1}}, 2, 0};
  EXPECT_EQ(volume(disk), T(0));
  EXPECT_NEAR(surface_area(disk), 8 * pi_v<T>, tol<T>(8, 30));
  EXPECT_TRUE(std::isnan(volume(Cylinder3<T>{{{0, 0, 0}, {0, 0, 1}}, -1, 2})));
  EXPECT_TRUE(std::isnan(surface_area(Cylinder3<T>{{{0, 0, 0}, {0, 0, 1}}, 1, nan})));
  EXPECT_TRUE(std::isnan(lateral_area(Cylinder3<T>{{{0, 0, 0}, {0, 0, 1}}, nan, 1})));
}

TYPED_TEST(CylinderTest, VolumeByDivergenceTheorem) {
  using T = TypeParam;
  const Cylinder3<double> cd{{{1, 2, 3}, normalize(Vec3<double>{1, -2, 2})}, 1.25, 3.5};
  const Cylinder3<T> c{
      {vec_cast<T>(cd.axis.origin), vec_cast<T>(cd.axis.direction)}, T(cd.radius), T(cd.height)};
  const Vec3<double> p{-1, 0.5, 2}, d = cd.axis.direction;
  const auto pt = [&](double a, double h) { return point_at(cd, Vec2<double>{a, h}); };
  const auto ref = [&](double, double h) { return cd.axis.origin + h * d; };
  double v = flux_volume(pt, ref, 0, 2 * pi_v<double>, -cd.height / 2, cd.height / 2, p, 64, 4);
  // The caps: (X - p) . n is constant on each disk of area pi r^2.
  const double cap = pi_v<double> * cd.radius * cd.radius;
  v += (dot(cd.axis.origin + (cd.height / 2) * d - p, d) -
        dot(cd.axis.origin - (cd.height / 2) * d - p, d)) *
       cap / 3;
  EXPECT_NEAR(double(volume(c)), v, 1e-7 * v + double(tol<T>(16)) * v);
}
