// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/frustum.hpp (row prim3.solids: orthogonal view frustum, 3D and 2D).
#include <locus/primitives/frustum.hpp>
#include <locus/primitives/tetrahedron.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class FrustumTest : public ::testing::Test {};
TYPED_TEST_SUITE(FrustumTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Frustum3d> && std::is_trivially_copyable_v<Frustum3f>);
static_assert(std::is_aggregate_v<Frustum2d>);

namespace {
template <class T>
Frustum3<T> random_frustum(Rng& rng) {
  const Vec3<T> d = rng.unit<T, 3>();
  Vec3<T> u = normalize(cross(d, rng.unit<T, 3>()));
  const Vec3<T> r = cross(d, u);
  const T n = rng.uniform<T>(T(0.5), 2);
  return {rng.vec<T, 3>(-3, 3),
          d,
          u,
          r,
          n,
          n + rng.uniform<T>(T(0.5), 5),
          rng.uniform<T>(T(0.3), 2),
          rng.uniform<T>(T(0.3), 2)};
}
}  // namespace

TYPED_TEST(FrustumTest, CornersLieOnTheNearAndFarFaces) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 300; ++trial) {
    const auto f = random_frustum<T>(rng);
    const auto cs = corners(f);
    for (int k = 0; k < 8; ++k) {
      const Vec3<T> p = cs[std::size_t(k)] - f.origin;
      const T d = (k & 4) ? f.d_max : f.d_min;
      const T q = d / f.d_min;
      EXPECT_NEAR(dot(p, f.direction), d, tol<T>(64, 10));
      EXPECT_NEAR(dot(p, f.right), ((k & 1) ? 1 : -1) * q * f.r_bound, tol<T>(64, 20));
      EXPECT_NEAR(dot(p, f.up), ((k & 2) ? 1 : -1) * q * f.u_bound, tol<T>(64, 20));
      if (k & 4) {  // far corner = near corner scaled from the apex
        EXPECT_TRUE(vec_near(p, (f.d_max / f.d_min) * (cs[std::size_t(k - 4)] - f.origin),
                             tol<T>(128, 40)));
      }
    }
    // point_at agrees with the corners and keeps w = 0 on the near plane.
    EXPECT_TRUE(vec_near(point_at(f, Vec3<T>{1, -1, 1}), cs[5], tol<T>(16, 20)));
    const Vec3<T> p = point_at(f, Vec3<T>{rng.uniform<T>(-1, 1), rng.uniform<T>(-1, 1), 0});
    EXPECT_NEAR(dot(p - f.origin, f.direction), f.d_min, tol<T>(64, 10));
  }
}

TYPED_TEST(FrustumTest, VolumeMatchesSixTetrahedraAndAreaMatchesFaces) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // The six monotone corner paths 0 -> 7 tile the hexahedron (a projective image of a cube).
  constexpr int tets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                              {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  constexpr int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                               {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (int trial = 0; trial < 300; ++trial) {
    const auto f = random_frustum<T>(rng);
    const auto c = corners(f);
    double vol = 0, area = 0;
    for (const auto& t : tets) {
      const Tetrahedron3<double> td{
          {vec_cast<double>(c[std::size_t(t[0])]), vec_cast<double>(c[std::size_t(t[1])]),
           vec_cast<double>(c[std::size_t(t[2])]), vec_cast<double>(c[std::size_t(t[3])])}};
      vol += double(volume(td));
    }
    for (const auto& q : faces) {
      // Planar quadrilateral: half the cross product of its diagonals.
      const auto d0 = vec_cast<double>(c[std::size_t(q[2])] - c[std::size_t(q[0])]);
      const auto d1 = vec_cast<double>(c[std::size_t(q[3])] - c[std::size_t(q[1])]);
      area += 0.5 * length(cross(d0, d1));
    }
    const double s = vol + 1;
    EXPECT_NEAR(double(volume(f)), vol, double(tol<T>(512, T(s))));
    EXPECT_NEAR(double(surface_area(f)), area, double(tol<T>(512, T(area))));
    // The box of the corners contains interior parameter points.
    const auto box = bounding_box(f);
    const Vec3<T> p = point_at(f, rng.vec<T, 3>(0, 1));
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(box.min[k], p[k] + tol<T>(64, 20));
      EXPECT_GE(box.max[k], p[k] - tol<T>(64, 20));
    }
  }
}

TYPED_TEST(FrustumTest, TwoDimensionalFrustum) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 300; ++trial) {
    const Vec2<T> d = rng.unit<T, 2>();
    const T n = rng.uniform<T>(T(0.5), 2);
    const Frustum2<T> f{rng.vec<T, 2>(-3, 3),     d, perp(d), n, n + rng.uniform<T>(T(0.1), 4),
                        rng.uniform<T>(T(0.2), 2)};
    ASSERT_TRUE(is_valid(f));
    const Vec2<T> ring[4] = {corner(f, 0), corner(f, 1), corner(f, 3), corner(f, 2)};
    T shoelace = 0;
    for (int i = 0; i < 4; ++i)
      shoelace += perp_dot(ring[i] - f.origin, ring[(i + 1) % 4] - f.origin);
    EXPECT_NEAR(std::fabs(shoelace) / 2, area(f), tol<T>(256, 50));
    EXPECT_NEAR(dot(corner(f, 3) - f.origin, f.direction), f.d_max, tol<T>(64, 10));
    EXPECT_TRUE(vec_near(point_at(f, Vec2<T>{-1, 0}), corner(f, 0), tol<T>(16, 10)));
  }
  const Frustum2<T> bad{{0, 0}, {1, 0}, {0, 1}, 0, 1, 1};
  EXPECT_FALSE(is_valid(bad));
  EXPECT_TRUE(std::isnan(area(bad)));
}

TYPED_TEST(FrustumTest, InvalidAndFlat) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Vec3<T> d{0, 0, 1}, u{0, 1, 0}, r{1, 0, 0};
  for (const Frustum3<T>& bad :
       {Frustum3<T>{{}, d, u, r, 0, 1, 1, 1}, Frustum3<T>{{}, d, u, r, 2, 1, 1, 1},
        Frustum3<T>{{}, d, u, r, 1, 2, -1, 1}, Frustum3<T>{{}, d, u, r, 1, 2, 1, nan},
        Frustum3<T>{{}, d, u, r, 1, inf, 1, 1}}) {
    EXPECT_FALSE(is_valid(bad));
    EXPECT_TRUE(std::isnan(volume(bad)));
    EXPECT_TRUE(std::isnan(surface_area(bad)));
  }
  const Frustum3<T> flat{{}, d, u, r, 2, 2, 1, 1};
  EXPECT_TRUE(is_valid(flat));
  EXPECT_EQ(volume(flat), T(0));
  EXPECT_NEAR(surface_area(flat), T(8), tol<T>(8, 8));  // near and far faces coincide: 2 * 4ru
  // Textbook pyramid frustum: apex E, base 2r x 2u at distance n, scaled.
  const Frustum3<T> unit{{}, d, u, r, 1, 2, 1, 1};
  EXPECT_NEAR(volume(unit), T(4) / 3 * (8 - 1), tol<T>(8, 10));
}

TYPED_TEST(FrustumTest, CentroidMatchesMonteCarloMean) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 3; ++trial) {
    const auto f = random_frustum<T>(rng);
    // Membership written out: depth along D and the scaled rectangle bounds.
    const auto inside = [&](const Vec3<T>& p) {
      const Vec3<T> d = p - f.origin;
      const T depth = dot(d, f.direction), q = depth / f.d_min;
      return f.d_min <= depth && depth <= f.d_max && std::fabs(dot(d, f.right)) <= q * f.r_bound &&
             std::fabs(dot(d, f.up)) <= q * f.u_bound;
    };
    const auto box = bounding_box(f);
    Vec3<double> sum{}, sum2{};
    int hits = 0;
    for (int s = 0; s < 40000; ++s) {
      Vec3<T> p{};
      for (int i = 0; i < 3; ++i) p[i] = rng.uniform<T>(box.min[i], box.max[i]);
      if (!inside(p)) continue;
      ++hits;
      sum += vec_cast<double>(p);
      sum2 += cwise_mul(vec_cast<double>(p), vec_cast<double>(p));
    }
    ASSERT_GT(hits, 1000);
    const Vec3<double> mean = sum / double(hits);
    const Vec3<T> g = centroid(f);
    for (int i = 0; i < 3; ++i) {
      const double sd = std::sqrt(std::fmax(0.0, sum2[i] / hits - mean[i] * mean[i]));
      EXPECT_NEAR(double(g[i]), mean[i], 5 * sd / std::sqrt(double(hits)));  // 5 standard errors
    }
  }
  EXPECT_TRUE(std::isnan(centroid(Frustum3<T>{{}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, 0, 1, 1, 1}).x));
}
