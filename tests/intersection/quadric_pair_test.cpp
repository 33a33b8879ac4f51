// SPDX-License-Identifier: BSL-1.0
// Row int3.surface-surface (quadric pairs): sphere-sphere find and relation, ellipsoid-ellipsoid
// relation. Oracles: GMP integer arithmetic for the sphere kinds (small integer centres and
// radii, so ties - tangencies, equal spheres - occur often); for ellipsoids a dense sampling of
// the first boundary evaluated in the second's implicit form (decisive draws only) and known
// constructions (scaled copies inside, spheres as ellipsoids against the exact sphere answer).
// Constructed circle points lie on both spheres; power-of-two scaling keeps the kinds.

#include <locus/intersection/ellipsoid_ellipsoid.hpp>
#include <locus/intersection/sphere_sphere.hpp>

#include <gmpxx.h>

#include <cmath>
#include <limits>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class QuadricPairs : public ::testing::Test {};
TYPED_TEST_SUITE(QuadricPairs, locus_test::RealTypes);

template <class T>
RegionRelation gmp_relation(const Sphere3<T>& a, const Sphere3<T>& b) {
  mpz_class d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const mpz_class d = mpz_class(long(b.center[i])) - mpz_class(long(a.center[i]));
    d2 += d * d;
  }
  const mpz_class r0(long(a.radius)), r1(long(b.radius));
  if (d2 == 0 && r0 == r1) return RegionRelation::equal;
  const int out = sgn(d2 - (r0 + r1) * (r0 + r1)), in = sgn(d2 - (r0 - r1) * (r0 - r1));
  if (out > 0) return RegionRelation::separated;
  if (out == 0) return RegionRelation::touching;
  if (in < 0) return r0 > r1 ? RegionRelation::a_contains_b : RegionRelation::b_contains_a;
  if (in == 0)
    return r0 > r1 ? RegionRelation::a_contains_b_touching : RegionRelation::b_contains_a_touching;
  return RegionRelation::overlapping;
}

TYPED_TEST(QuadricPairs, SphereKindsMatchGmp) {
  using T = TypeParam;
  Rng rng;
  int counts[9] = {};
  for (int iter = 0; iter < 400; ++iter) {
    const Sphere3<T> a{
        {T(rng.uniform_int(-4, 4)), T(rng.uniform_int(-4, 4)), T(rng.uniform_int(-4, 4))},
        T(rng.uniform_int(1, 5))};
    const Sphere3<T> b{
        {T(rng.uniform_int(-4, 4)), T(rng.uniform_int(-4, 4)), T(rng.uniform_int(-4, 4))},
        T(rng.uniform_int(1, 5))};
    const RegionRelation want = gmp_relation(a, b);
    ++counts[int(want)];
    for (T sc : {T(1), T(0x1p-30), T(0x1p30)}) {
      const Sphere3<T> as{sc * a.center, sc * a.radius}, bs{sc * b.center, sc * b.radius};
      ASSERT_EQ(relation(as, bs), want) << rng.trace() << " iter " << iter;
      const auto r = intersection(as, bs);
      switch (want) {
        case RegionRelation::separated:
        case RegionRelation::a_contains_b:
        case RegionRelation::b_contains_a:
          EXPECT_EQ(r.kind, Kind::empty);
          EXPECT_FALSE(intersects(as, bs));
          break;
        case RegionRelation::touching:
        case RegionRelation::a_contains_b_touching:
        case RegionRelation::b_contains_a_touching:
          ASSERT_EQ(r.kind, Kind::point);
          // The tangent point is exact up to rounding: on both spheres.
          EXPECT_NEAR(double(length(r.point[0] - as.center)), double(as.radius),
                      1e-5 * double(sc) * 8);
          EXPECT_NEAR(double(length(r.point[0] - bs.center)), double(bs.radius),
                      1e-5 * double(sc) * 8);
          break;
        case RegionRelation::overlapping:
          ASSERT_EQ(r.kind, Kind::circle);
          for (int i = 0; i < 3; ++i) {
            const double tol = (std::is_same_v<T, float> ? 1e-5 : 1e-13) * 16 * double(sc);
            EXPECT_NEAR(double(length(r.point[i] - as.center)), double(as.radius), tol);
            EXPECT_NEAR(double(length(r.point[i] - bs.center)), double(bs.radius), tol);
          }
          break;
        case RegionRelation::equal:
          EXPECT_EQ(r.kind, Kind::coincident);
          break;
        default:
          FAIL();
      }
    }
  }
  EXPECT_GT(counts[int(RegionRelation::touching)] +
                counts[int(RegionRelation::a_contains_b_touching)] +
                counts[int(RegionRelation::b_contains_a_touching)],
            0);
  EXPECT_GT(counts[int(RegionRelation::overlapping)], 0);
}

TYPED_TEST(QuadricPairs, SphereDegenerate) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(relation(Sphere3<T>{{nan, 0, 0}, 1}, Sphere3<T>{{0, 0, 0}, 1}),
            RegionRelation::undecided);
  EXPECT_EQ(intersection(Sphere3<T>{{0, 0, 0}, -1}, Sphere3<T>{{0, 0, 0}, 1}).kind, Kind::empty);
  // A point sphere on the other sphere: a tangent point.
  const auto p = intersection(Sphere3<T>{{0, 0, 2}, 0}, Sphere3<T>{{0, 0, 0}, 2});
  ASSERT_EQ(p.kind, Kind::point);
  EXPECT_EQ(p.point[0], (Vec3<T>{0, 0, 2}));
  // Circle: unit spheres at distance 1: radius sqrt(3)/2 at the midpoint plane.
  const auto c = intersection(Sphere3<T>{{0, 0, 0}, 1}, Sphere3<T>{{1, 0, 0}, 1});
  ASSERT_EQ(c.kind, Kind::circle);
  EXPECT_NEAR(double(c.radius), std::sqrt(3.0) / 2, 1e-6);
  EXPECT_NEAR(double(c.center.x), 0.5, 1e-6);
  EXPECT_NEAR(double(c.normal.x), 1.0, 1e-6);
}

template <class T>
Ellipsoid3<T> random_ellipsoid(Rng& rng, T lo, T hi) {
  const Vec3<T> a0 = rng.unit<T, 3>();
  Vec3<T> t = rng.unit<T, 3>();
  Vec3<T> a1 = normalize(t - dot(t, a0) * a0);
  const Vec3<T> a2 = cross(a0, a1);
  return {rng.vec<T, 3>(T(-1.5), T(1.5)),
          {a0, a1, a2},
          {rng.uniform<T>(lo, hi), rng.uniform<T>(lo, hi), rng.uniform<T>(lo, hi)}};
}

/// Sampled extremes of b's implicit value over a's boundary, and whether b's centre is in a.
template <class T>
void sample(const Ellipsoid3<T>& a, const Ellipsoid3<T>& b, double& lo, double& hi) {
  lo = INFINITY;
  hi = -INFINITY;
  const int n = 32;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double th = M_PI * j / n, ph = M_PI * i / n;
      const Vec3<double> u{std::cos(th) * std::sin(ph), std::sin(th) * std::sin(ph), std::cos(ph)};
      Vec3<double> x = vec_cast<double>(a.center);
      for (int k = 0; k < 3; ++k) x = x + u[k] * double(a.extent[k]) * vec_cast<double>(a.axis[k]);
      double q = -1.0;
      for (int k = 0; k < 3; ++k) {
        const double s =
            dot(vec_cast<double>(b.axis[k]), x - vec_cast<double>(b.center)) / double(b.extent[k]);
        q += s * s;
      }
      lo = std::min(lo, q);
      hi = std::max(hi, q);
    }
}

template <class T>
bool inside(const Ellipsoid3<T>& a, const Vec3<T>& p) {
  double q = -1.0;
  for (int k = 0; k < 3; ++k) {
    const double s =
        dot(vec_cast<double>(a.axis[k]), vec_cast<double>(p - a.center)) / double(a.extent[k]);
    q += s * s;
  }
  return q < 0.0;
}

TYPED_TEST(QuadricPairs, EllipsoidsAgreeWithSampling) {
  using T = TypeParam;
  Rng rng(21);
  int decided = 0, kinds[9] = {};
  for (int iter = 0; iter < 24; ++iter) {
    const Ellipsoid3<T> a = random_ellipsoid<T>(rng, T(0.3), T(2));
    const Ellipsoid3<T> b = random_ellipsoid<T>(rng, T(0.3), T(2));
    double lo = 0, hi = 0;
    sample(a, b, lo, hi);
    const RegionRelation r = relation(a, b);
    ++kinds[int(r)];
    // Sampling misses the true extremes by O(h^2): only decisive draws are compared.
    if (lo < -0.1 && hi > 0.1) {
      EXPECT_EQ(r, RegionRelation::overlapping) << rng.trace() << " " << iter;
      ++decided;
    } else if (hi < -0.1) {
      EXPECT_EQ(r, RegionRelation::b_contains_a) << rng.trace();
      ++decided;
    } else if (lo > 0.1) {
      const RegionRelation want =
          inside(a, b.center) ? RegionRelation::a_contains_b : RegionRelation::separated;
      // The sampled minimum is an upper bound of the true one: a true crossing can hide
      // between samples only when lo is small; 0.1 is far above the O(h^2) miss.
      EXPECT_EQ(r, want) << rng.trace() << " " << iter;
      ++decided;
    }
    EXPECT_EQ(intersects(a, b), r != RegionRelation::separated);
  }
  EXPECT_GT(decided, 15);
  EXPECT_GT(kinds[int(RegionRelation::separated)], 0);
  EXPECT_GT(kinds[int(RegionRelation::overlapping)], 0);
}

TYPED_TEST(QuadricPairs, EllipsoidContainmentTangencyAndSpheres) {
  using T = TypeParam;
  Rng rng(23);
  for (int iter = 0; iter < 12; ++iter) {
    const Ellipsoid3<T> a = random_ellipsoid<T>(rng, T(0.5), T(2));
    Ellipsoid3<T> small = a;
    small.extent = T(0.5) * a.extent;
    EXPECT_EQ(relation(a, small), RegionRelation::a_contains_b) << rng.trace();
    EXPECT_EQ(relation(small, a), RegionRelation::b_contains_a) << rng.trace();
    EXPECT_EQ(relation(a, a), RegionRelation::equal);
    // Moved far away along an axis: separated, both orders.
    Ellipsoid3<T> far = a;
    far.center = a.center + T(10) * a.axis[0];
    EXPECT_EQ(relation(a, far), RegionRelation::separated);
  }
  // Tangent from outside along the first axis: two ellipsoids with the same axes, touching at one
  // point (exactly representable).
  const Ellipsoid3<T> e0{{0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {2, 1, 1}};
  const Ellipsoid3<T> e1{{3, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, T(0.5), T(0.5)}};
  EXPECT_EQ(relation(e0, e1), RegionRelation::touching);
  const Ellipsoid3<T> e2{{1, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, T(0.5), T(0.5)}};
  EXPECT_EQ(relation(e0, e2), RegionRelation::a_contains_b_touching);
  EXPECT_EQ(relation(e2, e0), RegionRelation::b_contains_a_touching);
  // Spheres as ellipsoids against the exact sphere relation (integer data, decisive or tangent).
  for (int iter = 0; iter < 40; ++iter) {
    const Sphere3<T> s0{{T(rng.uniform_int(-3, 3)), T(rng.uniform_int(-3, 3)), 0},
                        T(rng.uniform_int(1, 4))};
    const Sphere3<T> s1{{T(rng.uniform_int(-3, 3)), 0, T(rng.uniform_int(-3, 3))},
                        T(rng.uniform_int(1, 4))};
    const auto as_ell = [](const Sphere3<T>& s) {
      return Ellipsoid3<T>{
          s.center, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {s.radius, s.radius, s.radius}};
    };
    EXPECT_EQ(relation(as_ell(s0), as_ell(s1)), relation(s0, s1)) << rng.trace() << " " << iter;
  }
  // Bad input.
  Ellipsoid3<T> bad = e0;
  bad.extent.y = T(0);
  EXPECT_EQ(relation(bad, e1), RegionRelation::undecided);
  bad = e0;
  bad.center.x = std::numeric_limits<T>::infinity();
  EXPECT_EQ(relation(e1, bad), RegionRelation::undecided);
  EXPECT_FALSE(intersects(e1, bad));
  // Power-of-two scaling keeps the relation.
  for (T sc : {T(0x1p-40), T(0x1p40)}) {
    Ellipsoid3<T> s0 = e0, s1 = e1;
    s0.extent = sc * s0.extent;
    s1.extent = sc * s1.extent;
    s1.center = sc * s1.center;
    EXPECT_EQ(relation(s0, s1), RegionRelation::touching);
  }
}

}  // namespace
