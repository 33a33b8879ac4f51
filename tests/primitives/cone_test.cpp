// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/cone.hpp (row prim3.solids: finite, infinite, truncated, double cones).
#include <locus/primitives/cone.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class ConeTest : public ::testing::Test {};
TYPED_TEST_SUITE(ConeTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Cone3d> && std::is_trivially_copyable_v<Cone3f>);

namespace {
// Membership written out independently: height along the axis and angle to the axis.
template <class T>
bool inside(const Cone3<T>& c, const Vec3<T>& x) {
  const Vec3<T> d = x - c.vertex;
  const T h = dot(d, c.axis);
  return c.min_height <= h && h <= c.max_height &&
         length(cross(d, c.axis)) <= std::fabs(h) * std::tan(c.angle);
}

// The four kinds: finite, truncated, double (asymmetric) and a wide finite cone.
template <class T>
Cone3<T> kind(Rng& rng, int k) {
  Cone3<T> c{rng.vec<T, 3>(-3, 3), rng.unit<T, 3>(), rng.uniform<T>(T(0.3), T(1.2)), 0, 2};
  if (k == 1) c.min_height = T(0.8);
  if (k == 2) c.min_height = T(-1.3);
  if (k == 3) c.angle = T(1.4);
  return c;
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

TYPED_TEST(ConeTest, PointAtIsOnTheImplicitConeAndTheApexIsTheVertex) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    const auto c = kind<T>(rng, trial % 4);
    const T theta = rng.uniform<T>(0, 2 * pi_v<T>), h = rng.uniform<T>(c.min_height, c.max_height);
    const Vec3<T> p = point_at(c, Vec2<T>{theta, h});
    // Radius up to 2 tan(1.4) ~ 12: values of size ~ 150.
    EXPECT_NEAR(signed_value(c, p), T(0), tol<T>(256, 150));
    EXPECT_NEAR(dot(p - c.vertex, c.axis), h, tol<T>(64, 20));
    EXPECT_NEAR(length(p - c.vertex - h * c.axis), radius_at(c, h), tol<T>(64, 20));
  }
  const Cone3<T> c{{1, 2, 3}, {0, 0, 1}, T(0.5), 0, 1};
  EXPECT_EQ(point_at(c, Vec2<T>{T(0.7), 0}), c.vertex);
  // Inside the nappe the implicit value is negative, outside positive.
  EXPECT_LT(signed_value(c, Vec3<T>{1, 2, 4}), T(0));
  EXPECT_LT(signed_value(c, Vec3<T>{1, 2, 2}), T(0));  // opposite nappe of the implicit quadric
  EXPECT_GT(signed_value(c, Vec3<T>{3, 2, 3.5}), T(0));
}

TYPED_TEST(ConeTest, VolumeMatchesMonteCarloForEveryKind) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 4; ++k) {
    const auto c = kind<T>(rng, k);
    ASSERT_TRUE(is_valid(c));
    EXPECT_EQ(is_double(c), k == 2);
    const auto box = bounding_box(c);
    const int n = 20000;
    int hits = 0;
    for (int s = 0; s < n; ++s) {
      Vec3<T> p{};
      for (int i = 0; i < 3; ++i) p[i] = rng.uniform<T>(box.min[i], box.max[i]);
      hits += inside(c, p);
    }
    const double frac = double(hits) / n, expect = double(volume(c)) / double(volume(box));
    EXPECT_NEAR(frac, expect, 5 * std::sqrt(expect * (1 - expect) / n)) << "kind " << k;  // 5 sigma
  }
}

TYPED_TEST(ConeTest, LateralAreaMatchesIntegratedAreaElement) {
  using T = TypeParam;
  for (int k = 0; k < 3; ++k) {
    const double mins[3] = {0, 0.7, -1.1};
    const Cone3<double> cd{{1, 2, 3}, normalize(Vec3<double>{2, -1, 2}), 0.6, mins[k], 2.0};
    const Cone3<T> c{vec_cast<T>(cd.vertex), vec_cast<T>(cd.axis), T(cd.angle), T(cd.min_height),
                     T(cd.max_height)};
    const auto pt = [&](double a, double h) { return point_at(cd, Vec2<double>{a, h}); };
    const auto ref = [&](double, double h) { return cd.vertex + h * cd.axis; };
    // Split at the apex (h = 0) where |h| has its kink; each piece is polynomial in h.
    double sum = 0, part = 0;
    if (cd.min_height < 0) {
      (void)flux_volume(pt, ref, 0, 2 * pi_v<double>, cd.min_height, 0, Vec3<double>{}, 64, 4,
                        &part);
      sum += part;
    }
    (void)flux_volume(pt, ref, 0, 2 * pi_v<double>, std::fmax(0.0, cd.min_height), cd.max_height,
                      Vec3<double>{}, 64, 4, &part);
    sum += part;
    EXPECT_NEAR(double(lateral_area(c)), sum, 1e-7 * sum + double(tol<T>(32)) * sum)
        << "kind " << k;
    const double caps = pi_v<double> * std::pow(std::tan(cd.angle), 2) *
                        (cd.max_height * cd.max_height + cd.min_height * cd.min_height);
    EXPECT_NEAR(double(surface_area(c)), sum + caps, 1e-7 * sum + double(tol<T>(64, 40)));
  }
}

TYPED_TEST(ConeTest, BoundingBoxContainsSamplesAndIsTight) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 40; ++trial) {
    const auto c = kind<T>(rng, trial % 4);
    const auto box = bounding_box(c);
    Vec3<T> lo = splat<T, 3>(T(1e30)), hi = splat<T, 3>(T(-1e30));
    for (int i = 0; i < 720; ++i)
      for (const T h : {c.min_height, c.max_height, T(0)}) {
        if (h < c.min_height) continue;
        const Vec3<T> p = point_at(c, Vec2<T>{T(i) * pi_v<T> / 360, h});
        lo = cwise_min(lo, p);
        hi = cwise_max(hi, p);
      }
    const T slack = T(2e-4) * (T(1) + radius_at(c, c.max_height));  // angular sampling error
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(box.min[k], lo[k] + tol<T>(64, 20));
      EXPECT_GE(box.max[k], hi[k] - tol<T>(64, 20));
      EXPECT_LE(lo[k] - box.min[k], slack);
      EXPECT_LE(box.max[k] - hi[k], slack);
    }
  }
}

TYPED_TEST(ConeTest, InfiniteAndInvalid) {
  using T = TypeParam;
  const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  const Cone3<T> infc{{0, 0, 0}, {0, 0, 1}, T(0.5), 0, inf};
  EXPECT_TRUE(is_valid(infc));
  EXPECT_TRUE(is_infinite(infc));
  EXPECT_FALSE(is_double(infc));
  EXPECT_EQ(volume(infc), inf);
  EXPECT_EQ(lateral_area(infc), inf);
  const Cone3<T> dbl{{0, 0, 0}, {0, 0, 1}, T(0.5), -inf, inf};
  EXPECT_TRUE(is_double(dbl) && is_infinite(dbl));
  EXPECT_EQ(volume(dbl), inf);
  EXPECT_EQ(bounding_box(dbl).max, (splat<T, 3>(inf)));
  // A symmetric double cone has twice the volume of one nappe.
  const Cone3<T> one{{0, 0, 0}, {0, 0, 1}, T(0.5), 0, 2}, two{{0, 0, 0}, {0, 0, 1}, T(0.5), -2, 2};
  EXPECT_NEAR(volume(two), 2 * volume(one), tol<T>(8, volume(two)));
  EXPECT_NEAR(lateral_area(two), 2 * lateral_area(one), tol<T>(8, lateral_area(two)));
  // Textbook finite cone: (1/3) pi r^2 h with r = h tan(angle).
  EXPECT_NEAR(volume(one), pi_v<T> * sqr(2 * std::tan(T(0.5))) * 2 / 3, tol<T>(16, 3));
  // Equal heights: a disk.
  EXPECT_EQ(volume(Cone3<T>{{0, 0, 0}, {0, 0, 1}, T(0.5), 1, 1}), T(0));
  for (const Cone3<T>& bad :
       {Cone3<T>{{0, 0, 0}, {0, 0, 1}, 0, 0, 1}, Cone3<T>{{0, 0, 0}, {0, 0, 1}, pi_v<T> / 2, 0, 1},
        Cone3<T>{{0, 0, 0}, {0, 0, 1}, T(0.5), 2, 1}, Cone3<T>{{0, 0, 0}, {0, 0, 1}, nan, 0, 1},
        Cone3<T>{{0, 0, 0}, {0, 0, 1}, T(0.5), nan, 1}}) {
    EXPECT_FALSE(is_valid(bad));
    EXPECT_TRUE(std::isnan(volume(bad)));
    EXPECT_TRUE(std::isnan(lateral_area(bad)));
    EXPECT_TRUE(std::isnan(surface_area(bad)));
  }
}

TYPED_TEST(ConeTest, VolumeByDivergenceTheorem) {
  using T = TypeParam;
  for (int k = 0; k < 3; ++k) {
    const double mins[3] = {0, 0.7, -1.1};
    const Cone3<double> cd{{1, 2, 3}, normalize(Vec3<double>{2, -1, 2}), 0.6, mins[k], 2.0};
    const Cone3<T> c{vec_cast<T>(cd.vertex), vec_cast<T>(cd.axis), T(cd.angle), T(cd.min_height),
                     T(cd.max_height)};
    const Vec3<double> p{0, -1, 2}, d = cd.axis;
    const auto pt = [&](double a, double h) { return point_at(cd, Vec2<double>{a, h}); };
    const auto ref = [&](double, double h) { return cd.vertex + h * d; };
    double v = flux_volume(pt, ref, 0, 2 * pi_v<double>, std::fmax(0.0, cd.min_height),
                           cd.max_height, p, 64, 4);
    if (cd.min_height < 0)
      v += flux_volume(pt, ref, 0, 2 * pi_v<double>, cd.min_height, 0, p, 64, 4);
    const auto disk = [&](double h) {
      return pi_v<double> * std::pow(std::fabs(h) * std::tan(cd.angle), 2);
    };
    v += (dot(cd.vertex + cd.max_height * d - p, d) * disk(cd.max_height) -
          dot(cd.vertex + cd.min_height * d - p, d) * disk(cd.min_height)) /
         3;
    EXPECT_NEAR(double(volume(c)), v, 1e-7 * std::fabs(v) + double(tol<T>(32, 10))) << "kind " << k;
  }
}

TYPED_TEST(ConeTest, CentroidMatchesMonteCarloMean) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 4; ++k) {
    auto c = kind<T>(rng, k);
    if (k == 3) c.min_height = T(-0.4);  // an asymmetric double cone
    const auto box = bounding_box(c);
    Vec3<double> sum{}, sum2{};
    int hits = 0;
    for (int s = 0; s < 40000; ++s) {
      Vec3<T> p{};
      for (int i = 0; i < 3; ++i) p[i] = rng.uniform<T>(box.min[i], box.max[i]);
      if (!inside(c, p)) continue;
      ++hits;
      sum += vec_cast<double>(p);
      sum2 += cwise_mul(vec_cast<double>(p), vec_cast<double>(p));
    }
    ASSERT_GT(hits, 1000);
    const Vec3<double> mean = sum / double(hits);
    const Vec3<T> g = centroid(c);
    for (int i = 0; i < 3; ++i) {
      const double sd = std::sqrt(std::fmax(0.0, sum2[i] / hits - mean[i] * mean[i]));
      // 5 standard errors of the sample mean.
      EXPECT_NEAR(double(g[i]), mean[i], 5 * sd / std::sqrt(double(hits))) << "kind " << k;
    }
  }
  const T inf = std::numeric_limits<T>::infinity();
  EXPECT_TRUE(std::isnan(centroid(Cone3<T>{{0, 0, 0}, {0, 0, 1}, T(0.5), 0, inf}).x));
  EXPECT_EQ(centroid(Cone3<T>{{0, 0, 0}, {0, 0, 1}, T(0.5), -2, 2}), (Vec3<T>{0, 0, 0}));
  EXPECT_EQ(centroid(Cone3<T>{{0, 0, 0}, {0, 0, 1}, T(0.5), 1, 1}), (Vec3<T>{0, 0, 1}));
  // Textbook: a solid cone's centroid is 3/4 of the way from the apex to the base.
  EXPECT_NEAR(centroid(Cone3<T>{{0, 0, 0}, {0, 0, 1}, T(0.5), 0, 4}).z, T(3), tol<T>(4, 3));
}
