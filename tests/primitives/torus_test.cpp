// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/torus.hpp (row prim3.solids: torus, figure 9.21).
#include <locus/primitives/torus.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class TorusTest : public ::testing::Test {};
TYPED_TEST_SUITE(TorusTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Torus3d> && std::is_trivially_copyable_v<Torus3f>);

namespace {
// Distance to the center circle, written out independently of the quartic.
template <class T>
T tube_distance(const Torus3<T>& t, const Vec3<T>& x) {
  const Vec3<T> d = x - t.center;
  const T z = dot(d, t.normal);
  const T rho = length(d - z * t.normal);
  return std::hypot(rho - t.major_radius, z);
}

template <class T>
Torus3<T> random_torus(Rng& rng) {
  const T big = rng.uniform<T>(T(1), 3);
  return {rng.vec<T, 3>(-3, 3), rng.unit<T, 3>(), big, rng.uniform<T>(T(0.2), T(0.9)) * big};
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

TYPED_TEST(TorusTest, Figure9_21StandardRingTorus) {
  using T = TypeParam;
  // Center at the origin, axis +z, R = 2, r = 0.5.
  const Torus3<T> t{{0, 0, 0}, {0, 0, 1}, 2, T(0.5)};
  EXPECT_TRUE(
      vec_near(point_at(t, Vec2<T>{0, 0}), Vec3<T>{T(2.5), 0, 0}, tol<T>(8, 3)));  // outer equator
  EXPECT_TRUE(
      vec_near(point_at(t, Vec2<T>{0, pi_v<T>}), Vec3<T>{T(1.5), 0, 0}, tol<T>(8, 3)));  // inner
  EXPECT_TRUE(
      vec_near(point_at(t, Vec2<T>{0, pi_v<T> / 2}), Vec3<T>{2, 0, T(0.5)}, tol<T>(8, 3)));  // top
  EXPECT_LT(signed_value(t, Vec3<T>{2, 0, 0}), T(0));  // tube center is inside
  EXPECT_GT(signed_value(t, Vec3<T>{0, 0, 0}), T(0));  // the hole is outside
  EXPECT_GT(signed_value(t, Vec3<T>{3, 0, 0}), T(0));
  const auto b = bounding_box(t);
  EXPECT_TRUE(vec_near(b.min, Vec3<T>{T(-2.5), T(-2.5), T(-0.5)}, tol<T>(4, 3)));
  EXPECT_TRUE(vec_near(b.max, Vec3<T>{T(2.5), T(2.5), T(0.5)}, tol<T>(4, 3)));
}

TYPED_TEST(TorusTest, PointAtSatisfiesQuarticAndTubeDistance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 1000; ++trial) {
    const auto t = random_torus<T>(rng);
    const Vec2<T> ab{rng.uniform<T>(0, 2 * pi_v<T>), rng.uniform<T>(0, 2 * pi_v<T>)};
    const Vec3<T> p = point_at(t, ab);
    const T s = t.major_radius + t.minor_radius + length(t.center);
    EXPECT_NEAR(tube_distance(t, p), t.minor_radius, tol<T>(128, s));
    // The quartic is of size (R + r)^4; its rounding is relative to the terms, ~ s^4.
    EXPECT_NEAR(signed_value(t, p), T(0), tol<T>(512, s * s * s * s));
  }
}

TYPED_TEST(TorusTest, VolumeByPappusMatchesSampling) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 3; ++trial) {
    const auto t = random_torus<T>(rng);
    const auto box = bounding_box(t);
    const int n = 20000;
    int hits = 0, quartic_hits = 0;
    for (int k = 0; k < n; ++k) {
      Vec3<T> p{};
      for (int i = 0; i < 3; ++i) p[i] = rng.uniform<T>(box.min[i], box.max[i]);
      const bool in = tube_distance(t, p) <= t.minor_radius;
      hits += in;
      quartic_hits += signed_value(t, p) <= T(0);
    }
    const double frac = double(hits) / n, expect = double(volume(t)) / double(volume(box));
    EXPECT_NEAR(frac, expect, 5 * std::sqrt(expect * (1 - expect) / n));  // 5 binomial sigma
    // For a ring torus the quartic's negative set is exactly the solid (up to boundary rounding).
    EXPECT_NEAR(quartic_hits, hits, 2);
  }
}

TYPED_TEST(TorusTest, SurfaceAreaMatchesIntegratedAreaElement) {
  using T = TypeParam;
  const Torus3<double> td{{1, 0, -1}, normalize(Vec3<double>{1, 2, -2}), 2.2, 0.7};
  const Torus3<T> t{vec_cast<T>(td.center), vec_cast<T>(td.normal), T(td.major_radius),
                    T(td.minor_radius)};
  const auto pt = [&](double a, double b) { return point_at(td, Vec2<double>{a, b}); };
  const auto ref = [&](double, double) { return td.center; };
  double sum = 0;
  (void)flux_volume(pt, ref, 0, 2 * pi_v<double>, 0, 2 * pi_v<double>, Vec3<double>{}, 64, 32,
                    &sum);
  // Periodic integrand: spectrally accurate quadrature; the differences cost ~1e-10.
  EXPECT_NEAR(double(surface_area(t)), sum, 1e-7 * sum + double(tol<T>(32)) * sum);
}

TYPED_TEST(TorusTest, BoundingBoxIsTightAndDegenerateRadii) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 3; ++trial) {
    const auto t = random_torus<T>(rng);
    const auto box = bounding_box(t);
    Vec3<T> lo = splat<T, 3>(T(1e30)), hi = splat<T, 3>(T(-1e30));
    for (int i = 0; i < 360; ++i)
      for (int j = 0; j < 180; ++j) {
        const Vec3<T> p = point_at(t, Vec2<T>{T(i) * pi_v<T> / 180, T(j) * pi_v<T> / 90});
        lo = cwise_min(lo, p);
        hi = cwise_max(hi, p);
      }
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(box.min[k], lo[k] + tol<T>(64, 10));
      EXPECT_GE(box.max[k], hi[k] - tol<T>(64, 10));
      // Grid spacing pi/180 in both angles: sampled extremes within (R + r)(1 - cos(pi/180)) * 2.
      EXPECT_LE(lo[k] - box.min[k], T(2e-3));
      EXPECT_LE(box.max[k] - hi[k], T(2e-3));
    }
  }
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Torus3<T> circle{{0, 0, 0}, {0, 0, 1}, 2, 0};
  EXPECT_EQ(volume(circle), T(0));
  EXPECT_EQ(surface_area(circle), T(0));
  EXPECT_TRUE(std::isnan(volume(Torus3<T>{{0, 0, 0}, {0, 0, 1}, -2, 1})));
  EXPECT_TRUE(std::isnan(surface_area(Torus3<T>{{0, 0, 0}, {0, 0, 1}, 2, nan})));
}

TYPED_TEST(TorusTest, VolumeByDivergenceTheorem) {
  using T = TypeParam;
  const Torus3<double> td{{1, 0, -1}, normalize(Vec3<double>{1, 2, -2}), 2.2, 0.7};
  const Torus3<T> t{vec_cast<T>(td.center), vec_cast<T>(td.normal), T(td.major_radius),
                    T(td.minor_radius)};
  const auto pt = [&](double a, double b) { return point_at(td, Vec2<double>{a, b}); };
  // Outward = away from the center circle point at the same angle a.
  const auto ref = [&](double a, double) {
    return point_at(Torus3<double>{td.center, td.normal, td.major_radius, 0}, Vec2<double>{a, 0});
  };
  const double v = flux_volume(pt, ref, 0, 2 * pi_v<double>, 0, 2 * pi_v<double>,
                               Vec3<double>{-2, 3, 1}, 64, 32);
  EXPECT_NEAR(double(volume(t)), v, 1e-6 * v);  // periodic integrand: spectral accuracy
}
