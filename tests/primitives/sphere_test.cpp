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

namespace {
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

TYPED_TEST(SphereTest, ParametrisationConventions) {
  using T = TypeParam;
  const Sphere3<T> s{{1, 2, 3}, 2};
  const T pi = pi_v<T>;
  EXPECT_TRUE(vec_near(point_at(s, Vec2<T>{0, 0}), Vec3<T>{1, 2, 5}, tol<T>(8, 4)));  // north pole
  EXPECT_TRUE(vec_near(point_at(s, Vec2<T>{0, pi / 2}), Vec3<T>{3, 2, 3}, tol<T>(8, 4)));  // +x
  EXPECT_TRUE(
      vec_near(point_at(s, Vec2<T>{pi / 2, pi / 2}), Vec3<T>{1, 4, 3}, tol<T>(8, 4)));  // +y
  EXPECT_TRUE(vec_near(point_at(s, Vec2<T>{0, pi}), Vec3<T>{1, 2, 1}, tol<T>(8, 4)));   // south
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
  const auto pt = [&](double a, double b) { return point_at(sd, Vec2<double>{a, b}); };
  const auto ref = [&](double, double) { return sd.center; };
  double sum = 0;
  (void)flux_volume(pt, ref, 0, 2 * pi_v<double>, 0, pi_v<double>, Vec3<double>{}, 64, 32, &sum);
  // Gauss error O(h^4) ~ 1e-8, central differences ~ 1e-10 relative.
  EXPECT_NEAR(double(surface_area(s)), sum, 1e-6 * sum + double(tol<T>(16)) * sum);
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

TYPED_TEST(SphereTest, VolumeByDivergenceTheorem) {
  using T = TypeParam;
  const Sphere3<double> sd{{1, -2, 0.5}, 1.75};
  const Sphere3<T> s{vec_cast<T>(sd.center), T(sd.radius)};
  const auto pt = [&](double a, double b) { return point_at(sd, Vec2<double>{a, b}); };
  const auto ref = [&](double, double) { return sd.center; };
  const double v =
      flux_volume(pt, ref, 0, 2 * pi_v<double>, 0, pi_v<double>, Vec3<double>{3, 1, -2}, 64, 32);
  EXPECT_NEAR(double(volume(s)), v, 1e-6 * v + double(tol<T>(16)) * v);
}
