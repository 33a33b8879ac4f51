// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_triangle.hpp (rows dist2.pt-triangle, dist3.pt-triangle; book figures
// 6.5-6.9 and 10.8-10.10).
#include <locus/distance/batch.hpp>
#include <locus/distance/point_triangle.hpp>

#include "distance/exact.hpp"
#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class PointTriangleTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointTriangleTest, locus_test::RealTypes);

namespace {

// Random triangles: generic (80%), collinear vertices (10%), a repeated vertex (5%), a needle
// (5%).
template <class T, int N>
Triangle<T, N> random_triangle(Rng& rng, T S) {
  Triangle<T, N> t{rng.vec<T, N>(-S, S), rng.vec<T, N>(-S, S), rng.vec<T, N>(-S, S)};
  const int kind = rng.uniform_int(0, 19);
  if (kind < 2)
    t.v2 = lerp(t.v0, t.v1, rng.uniform<T>(T(-0.5), T(1.5)));
  else if (kind < 3)
    t.v2 = t.v1;
  else if (kind < 4)
    t.v2 = lerp(t.v0, t.v1, T(0.5)) + rng.unit<T, N>() * (S * T(1e-4));
  return t;
}

// Exact oracle: the squared distance to a triangle is the minimum of (a) the squared distance
// to its plane when the projection is inside and (b) the three exact point-segment distances.
// Here (a) is checked in 2D (distance 0 inside, decided by exact orient2d) and in 3D (the
// projection solved in rationals: inside when its s, t >= 0, s + t <= 1, then the squared
// distance is |p - foot|^2), and the boundary part exactly in both dimensions. sqr_distance is
// checked against the full query (exactly) and so against the same oracle.
template <class T, int N>
void check_exact(const Vec<T, N>& p, const Triangle<T, N>& tri, T S, int n) {
  const auto r = distance(p, tri);
  const auto qp = ex::to_q(p);
  mpq_class e = ex::sqr_point_linear(qp, ex::segment(tri.v0, tri.v1));
  for (const auto& q : {ex::sqr_point_linear(qp, ex::segment(tri.v0, tri.v2)),
                        ex::sqr_point_linear(qp, ex::segment(tri.v1, tri.v2))})
    if (q < e) e = q;
  if constexpr (N == 2) {
    const Sign s0 = orient2d(tri.v0, tri.v1, p), s1 = orient2d(tri.v1, tri.v2, p),
               s2 = orient2d(tri.v2, tri.v0, p);
    const bool nonneg = s0 != Sign::negative && s1 != Sign::negative && s2 != Sign::negative;
    const bool nonpos = s0 != Sign::positive && s1 != Sign::positive && s2 != Sign::positive;
    if ((nonneg || nonpos) && !is_degenerate(tri)) e = 0;
  } else {
    const auto q0 = ex::to_q(tri.v0), e0 = ex::sub(ex::to_q(tri.v1), q0),
               e1 = ex::sub(ex::to_q(tri.v2), q0), w = ex::sub(q0, qp);
    const mpq_class a = ex::dot(e0, e0), b = ex::dot(e0, e1), c = ex::dot(e1, e1),
                    dd = ex::dot(e0, w), ee = ex::dot(e1, w), det = a * c - b * b;
    if (det != 0) {
      const mpq_class s = (b * ee - c * dd) / det, t = (b * dd - a * ee) / det;
      if (s >= 0 && t >= 0 && s + t <= 1) {
        const auto foot = ex::sub(ex::axpy(ex::axpy(q0, s, e0), t, e1), qp);
        e = ex::dot(foot, foot);
      }
    }
  }
  EXPECT_NEAR(double(r.sqr_distance), e.get_d(), double(tol<T>(64, S * S * T(4)))) << "case " << n;
  EXPECT_EQ(sqr_distance(p, tri), r.sqr_distance) << "case " << n;
  EXPECT_EQ(sqr_distance(tri, p), r.sqr_distance) << "case " << n;
}

template <class T, int N>
void exact_oracle() {
  Rng rng(locus_test::test_seed() + 7);
  SCOPED_TRACE(rng.trace());
  const T S = 10;
  for (int n = 0; n < 400; ++n) {
    const auto tri = random_triangle<T, N>(rng, S);
    const auto p = rng.vec<T, N>(-T(1.5) * S, T(1.5) * S);
    check_exact(p, tri, S, n);
  }
}

template <class T, int N>
void harness() {
  const T S = 10;
  // Every harness case is also checked against the exact oracle above (check_pairs's compass
  // oracle checks agreement to opt.agree; this pins the distance to k eps).
  int n = 0;
  dist::check_pairs<T, N, Vec<T, N>, Triangle<T, N>>([&](Rng& rng) {
    const Vec<T, N> p = rng.vec<T, N>(-T(1.5) * S, T(1.5) * S);
    const Triangle<T, N> tri = random_triangle<T, N>(rng, S);
    check_exact(p, tri, S, n++);
    return std::pair{p, tri};
  });
}

}  // namespace

TYPED_TEST(PointTriangleTest, Harness2D) { harness<TypeParam, 2>(); }
TYPED_TEST(PointTriangleTest, Harness3D) { harness<TypeParam, 3>(); }
TYPED_TEST(PointTriangleTest, ExactOracle2D) { exact_oracle<TypeParam, 2>(); }
TYPED_TEST(PointTriangleTest, ExactOracle3D) { exact_oracle<TypeParam, 3>(); }

// Figure 6.6: the seven regions of the (s, t) plane around the triangle (0,0), (1,0), (0,1):
// region 0 inside; 1 beyond edge v1 v2; 3 left of v0 v2; 5 below v0 v1; 2, 4, 6 the vertex
// regions of v2, v0, v1.
TYPED_TEST(PointTriangleTest, Figure6_6SevenRegions) {
  using T = TypeParam;
  const Triangle2<T> tri{{T(0), T(0)}, {T(4), T(0)}, {T(0), T(4)}};
  struct Case {
    Vec2<T> p, closest;
    Vec3<T> bary;
  };
  const Case cases[] = {
      {{T(1), T(1)}, {T(1), T(1)}, {T(0.5), T(0.25), T(0.25)}},  // region 0
      {{T(3), T(3)}, {T(2), T(2)}, {T(0), T(0.5), T(0.5)}},      // region 1
      {{T(-1), T(6)}, {T(0), T(4)}, {T(0), T(0), T(1)}},         // region 2
      {{T(-2), T(1)}, {T(0), T(1)}, {T(0.75), T(0), T(0.25)}},   // region 3
      {{T(-1), T(-2)}, {T(0), T(0)}, {T(1), T(0), T(0)}},        // region 4
      {{T(3), T(-5)}, {T(3), T(0)}, {T(0.25), T(0.75), T(0)}},   // region 5
      {{T(6), T(-1)}, {T(4), T(0)}, {T(0), T(1), T(0)}},         // region 6
  };
  int region = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE("region " + std::to_string(region++));
    const auto r = distance(c.p, tri);
    EXPECT_TRUE(locus_test::vec_near(r.closest[1], c.closest, tol<T>(8, T(4))));
    EXPECT_TRUE(locus_test::vec_near(r.param_b, c.bary, tol<T>(8)));
    EXPECT_NEAR(r.distance, length(c.p - c.closest), tol<T>(8, T(8)));
  }
  // Vertex regions reproduce the vertex exactly.
  EXPECT_EQ(distance(Vec2<T>{T(-1), T(7)}, tri).closest[1], tri.v2);
  EXPECT_EQ(distance(Vec2<T>{T(-3), T(-3)}, tri).closest[1], tri.v0);
  EXPECT_EQ(distance(Vec2<T>{T(9), T(-0.5)}, tri).closest[1], tri.v1);
}

// Figures 10.8-10.10: a 3D triangle; points above each region project to the same closest
// points as in the plane, at the height added in quadrature.
TYPED_TEST(PointTriangleTest, Figure10_8RegionsIn3D) {
  using T = TypeParam;
  const Triangle3<T> tri{{T(0), T(0), T(2)}, {T(4), T(0), T(2)}, {T(0), T(4), T(2)}};
  const auto above = distance(Vec3<T>{T(1), T(1), T(5)}, tri);
  EXPECT_EQ(above.distance, T(3));
  EXPECT_TRUE(locus_test::vec_near(above.closest[1], Vec3<T>{T(1), T(1), T(2)}, tol<T>(8, T(4))));
  const auto edge = distance(Vec3<T>{T(3), T(3), T(6)}, tri);  // region 1, 4 above
  EXPECT_NEAR(edge.sqr_distance, T(2) + T(16), tol<T>(32, T(20)));
  const auto vertex = distance(Vec3<T>{T(-3), T(-4), T(-10)}, tri);  // region 4, 12 below
  EXPECT_EQ(vertex.closest[1], tri.v0);
  EXPECT_EQ(vertex.distance, T(13));
  // Swapped overload.
  const auto sw = distance(tri, Vec3<T>{T(-3), T(-4), T(-10)});
  EXPECT_EQ(sw.closest[0], tri.v0);
  EXPECT_EQ(sw.param_a, vertex.param_b);
  EXPECT_EQ(closest_point(Vec3<T>{T(1), T(1), T(5)}, tri), above.closest[1]);
}

// Degenerate triangles act as the segment or point their vertices span.
TYPED_TEST(PointTriangleTest, DegenerateTriangles) {
  using T = TypeParam;
  const Triangle3<T> collinear{{T(0), T(0), T(0)}, {T(2), T(2), T(2)}, {T(1), T(1), T(1)}};
  const auto r = distance(Vec3<T>{T(4), T(4), T(4)}, collinear);
  EXPECT_EQ(r.closest[1], collinear.v1);
  const auto m = distance(Vec3<T>{T(1), T(1), T(-2)}, collinear);
  EXPECT_NEAR(m.sqr_distance, T(6), tol<T>(16, T(6)));
  const Triangle2<T> point{{T(1), T(1)}, {T(1), T(1)}, {T(1), T(1)}};
  const auto q = distance(Vec2<T>{T(4), T(5)}, point);
  EXPECT_EQ(q.distance, T(5));
  EXPECT_EQ(q.closest[1], point.v0);
  // A very thin (but not flat) 2D triangle still contains its interior points.
  const Triangle2<T> thin{{T(0), T(0)}, {T(1), T(0)}, {T(0.5), T(1e-6)}};
  EXPECT_LE(distance(Vec2<T>{T(0.5), T(1e-7)}, thin).distance, tol<T>(16));
}

TYPED_TEST(PointTriangleTest, NonFiniteInputGivesNaNResult) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Triangle3<T> tri{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}};
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{nan, T(0), T(0)}, tri)));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{T(0), inf, T(0)}, tri)));
  auto bad = tri;
  bad.v2.z = nan;
  const auto r = distance(Vec3<T>{}, bad);
  EXPECT_TRUE(dist::is_nan_result(r));
  EXPECT_TRUE(std::isnan(r.param_b.x) && std::isnan(r.closest[1].y));
  EXPECT_TRUE(dist::is_nan_result(distance(bad, Vec3<T>{})));
  // sqr_distance: NaN for a NaN or an infinity in any coordinate of either argument, 2D and 3D
  // (an infinite point next to a well-shaped triangle would otherwise clamp to a vertex).
  for (int k = 0; k < 12; ++k) {
    for (const T x : {nan, inf, -inf}) {
      Vec3<T> q{T(0.2), T(0.3), T(1)};
      Triangle3<T> t3 = tri;
      Vec3<T>* v[4] = {&q, &t3.v0, &t3.v1, &t3.v2};
      (*v[k / 3])[k % 3] = x;
      EXPECT_TRUE(std::isnan(sqr_distance(q, t3))) << k;
      EXPECT_TRUE(std::isnan(sqr_distance(t3, q))) << k;
      if (k % 3 < 2) {
        const auto p2 = [](const Vec3<T>& u) { return Vec2<T>{u.x, u.y}; };
        EXPECT_TRUE(std::isnan(sqr_distance(p2(q), Triangle2<T>{p2(t3.v0), p2(t3.v1), p2(t3.v2)})))
            << k;
      }
    }
  }
}

// sqr_distance on the degenerate and figure cases, against the exact values.
TYPED_TEST(PointTriangleTest, SqrDistanceDegenerateAndRegions) {
  using T = TypeParam;
  const Triangle3<T> collinear{{T(0), T(0), T(0)}, {T(2), T(2), T(2)}, {T(1), T(1), T(1)}};
  EXPECT_EQ(sqr_distance(Vec3<T>{T(4), T(4), T(4)}, collinear), T(12));
  EXPECT_NEAR(sqr_distance(Vec3<T>{T(1), T(1), T(-2)}, collinear), T(6), tol<T>(16, T(6)));
  const Triangle3<T> point{{T(1), T(1), T(1)}, {T(1), T(1), T(1)}, {T(1), T(1), T(1)}};
  EXPECT_EQ(sqr_distance(Vec3<T>{T(4), T(5), T(1)}, point), T(25));
  const Triangle3<T> two{{T(1), T(1), T(1)}, {T(1), T(1), T(1)}, {T(4), T(1), T(1)}};
  EXPECT_EQ(sqr_distance(Vec3<T>{T(2), T(4), T(5)}, two), T(25));
  // The seven regions of figure 6.6 lifted to z = 2, the point 3 above or below: every region
  // of the branch-free path, with the exact squared distances.
  const Triangle3<T> tri{{T(0), T(0), T(2)}, {T(4), T(0), T(2)}, {T(0), T(4), T(2)}};
  struct Case {
    T x, y, sqr_in_plane;
  };
  const Case cases[] = {{T(1), T(1), T(0)},  {T(3), T(3), T(2)},   {T(-1), T(6), T(5)},
                        {T(-2), T(1), T(4)}, {T(-1), T(-2), T(5)}, {T(3), T(-5), T(25)},
                        {T(6), T(-1), T(5)}, {T(-3), T(9), T(34)}, {T(9), T(-3), T(34)}};
  for (const Case& c : cases) {
    for (const T z : {T(5), T(-1)}) {
      const Vec3<T> p{c.x, c.y, z};
      EXPECT_NEAR(sqr_distance(p, tri), c.sqr_in_plane + T(9), tol<T>(16, T(50)))
          << c.x << " " << c.y << " " << z;
      EXPECT_EQ(sqr_distance(p, tri), distance(p, tri).sqr_distance);
    }
  }
  const Triangle2<T> flat{{T(0), T(0)}, {T(4), T(0)}, {T(0), T(4)}};
  EXPECT_EQ(sqr_distance(Vec2<T>{T(1), T(1)}, flat), T(0));
  EXPECT_EQ(sqr_distance(Vec2<T>{T(-3), T(-4)}, flat), T(25));
}

// A needle triangle in 3D (angle ~2e-6 at v0 in double, 6e-3 in float): the plane solve is
// ill-conditioned (Cramer's rule alone is off by ~eps / angle^2 relative) and the refined answer
// must still be the projection, to the accuracy the rounded input allows.
TYPED_TEST(PointTriangleTest, NeedleTriangleIn3DProjectsAccurately) {
  using T = TypeParam;
  const T thin = std::is_same_v<T, float> ? T(3e-3) : T(1e-6);
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 50; ++n) {
    const auto r = dist::random_rotation<T, 3>(rng);
    const Vec3<T> o = rng.vec<T, 3>(-1, 1);
    const Triangle3<T> tri{o, o + r * Vec3<T>{T(1), T(0), T(0)},
                           o + r * Vec3<T>{T(0.5), thin, T(0)}};
    const Vec3<T> p = o + r * Vec3<T>{T(0.5), T(0.5) * thin, T(0.3)};
    const auto d = distance(p, tri);
    // Exact projection onto the plane of the (rounded) input triangle, in rationals: the tilt of
    // the rounded needle's plane is ~eps / thin, so a float "foot" would not be the reference.
    const auto q0 = ex::to_q(tri.v0), e0 = ex::sub(ex::to_q(tri.v1), q0),
               e1 = ex::sub(ex::to_q(tri.v2), q0), w = ex::sub(q0, ex::to_q(p));
    const mpq_class a = ex::dot(e0, e0), b = ex::dot(e0, e1), c = ex::dot(e1, e1),
                    dd = ex::dot(e0, w), ee = ex::dot(e1, w), det = a * c - b * b;
    const mpq_class s = (b * ee - c * dd) / det, t = (b * dd - a * ee) / det;
    ASSERT_TRUE(s > 0 && t > 0 && s + t < 1);
    const auto foot = ex::axpy(ex::axpy(q0, s, e0), t, e1);
    const Vec3<T> exact_foot{T(foot[0].get_d()), T(foot[1].get_d()), T(foot[2].get_d())};
    // The rounded edge vectors tilt the plane by ~eps / thin: that is the attainable accuracy
    // (Cramer's rule alone is off by ~eps / thin^2).
    EXPECT_TRUE(locus_test::vec_near(d.closest[1], exact_foot, tol<T>(8) / thin)) << "case " << n;
    EXPECT_NEAR(d.distance, T(0.3), tol<T>(8) / thin);
  }
}

// A point so far away that the plane solution's numerators overflow (c d and b e both infinite,
// their difference NaN) while the squared distance is still finite: the NaN violates no
// constraint, and the general code used to try no edge and return 0 (the fast path, taking the
// same test, left v1 v2 unvisited and read an unset result). Every edge is a candidate now; the
// nearest point is the vertex v1 exactly.
TYPED_TEST(PointTriangleTest, FarPointWhosePlaneSolutionOverflows) {
  using T = TypeParam;
  const T big = std::is_same_v<T, float> ? T(1e15) : T(1e100);
  const T far = std::is_same_v<T, float> ? T(1e19) : T(3e150);
  for (const bool needle : {false, true}) {
    const Triangle3<T> tri{
        {T(0), T(0), T(0)}, {big, T(0), T(0)}, {T(0.5) * big, needle ? big * T(1e-4) : big, T(0)}};
    const Vec3<T> p{far, T(0), T(0)};
    const auto d = distance(p, tri);
    EXPECT_EQ(d.closest[1], tri.v1) << "needle " << needle;
    EXPECT_EQ(d.sqr_distance, sqr_length(p - tri.v1)) << "needle " << needle;
    EXPECT_EQ(sqr_distance(p, tri), d.sqr_distance);
    EXPECT_TRUE(std::isfinite(d.sqr_distance));
  }
  // The numerators overflow for a unit triangle and a point near the end of the range: the
  // squared distance overflows to infinity (not NaN), and the closest point is a point of the
  // triangle.
  const T m = std::numeric_limits<T>::max() / T(8);
  const Triangle3<T> unit{
      {T(0.84), T(0.66), T(0.31)}, {T(-0.35), T(-0.59), T(-0.55)}, {T(-0.57), T(-0.68), T(0.77)}};
  const Vec3<T> p{T(0.83) * m, T(0.92) * m, T(0.8) * m};
  const auto d = distance(p, unit);
  EXPECT_EQ(d.sqr_distance, std::numeric_limits<T>::infinity());
  EXPECT_EQ(sqr_distance(p, unit), d.sqr_distance);
  const Vec3<T> bary = d.param_b;
  EXPECT_TRUE(bary.x >= T(0) && bary.y >= T(0) && bary.z >= T(0));
  EXPECT_NEAR(bary.x + bary.y + bary.z, T(1), tol<T>(4));
}

// A small triangle (edges ~1e-100 in double, ~1e-12 in float) whose a c = |e0|^2 |e1|^2
// underflows to 0 while a and c are normal: the fast path's range test let it through, det
// came out 0, the plane solution 0 / 0, and the answer was NaN for finite input. Now the
// triangle goes to the general code, which solves on a copy scaled by a power of two: the
// answer is the unit triangle's, scaled (the scaling is exact), in both the per-query and the
// batch forms.
TYPED_TEST(PointTriangleTest, SmallTriangleWhoseDeterminantUnderflows) {
  using T = TypeParam;
  const int k = std::is_same_v<T, float> ? -40 : -330;
  const T f = std::ldexp(T(1), k);
  const Triangle3<T> unit{{T(1), T(-9), T(8)}, {T(-0.5), T(-6), T(9)}, {T(9), T(8), T(-8)}};
  const Triangle3<T> small{f * unit.v0, f * unit.v1, f * unit.v2};
  const Vec3<T> points[] = {{T(12), T(-3), T(-6)}, {T(2), T(-1), T(3)}, {T(0), T(0), T(0)}};
  for (const Vec3<T>& p : points) {
    const auto want = distance(p, unit);
    const auto got = distance(f * p, small);
    ASSERT_TRUE(std::isfinite(got.sqr_distance));
    EXPECT_NEAR(std::ldexp(got.sqr_distance, -2 * k), want.sqr_distance,
                tol<T>(64) * (T(1) + want.sqr_distance));
    EXPECT_EQ(sqr_distance(f * p, small), got.sqr_distance);
    const Vec3<T> q = f * p;
    T batch = T(-1);
    locus::sqr_distances(std::span<const Vec3<T>>(&q, 1), std::span<const Triangle3<T>>(&small, 1),
                         std::span<T>(&batch, 1));
    EXPECT_EQ(batch, got.sqr_distance);
  }
}

// Every coordinate zero (a triangle collapsed to the origin, the point at the origin, and other
// points): the general code's rescaling must not retry on the same input (its scale is 1 for
// an all-zero input), which once recursed without end.
TYPED_TEST(PointTriangleTest, TriangleCollapsedToTheOrigin) {
  using T = TypeParam;
  const Triangle3<T> zero3{};
  const Triangle2<T> zero2{};
  EXPECT_EQ(distance(Vec3<T>{}, zero3).sqr_distance, T(0));
  EXPECT_EQ(distance(Vec2<T>{}, zero2).sqr_distance, T(0));
  EXPECT_EQ(distance(Vec3<T>{T(3), T(0), T(4)}, zero3).distance, T(5));
  EXPECT_EQ(distance(Vec2<T>{T(3), T(4)}, zero2).distance, T(5));
  EXPECT_EQ(sqr_distance(Vec3<T>{}, zero3), T(0));
}
