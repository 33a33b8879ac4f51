// SPDX-License-Identifier: BSL-1.0
// Tests for distance/triangle_triangle.hpp, triangle_rectangle.hpp, rectangle_rectangle.hpp
// (row dist3.misc).
#include <locus/distance/rectangle_rectangle.hpp>
#include <locus/distance/triangle_rectangle.hpp>
#include <locus/distance/triangle_triangle.hpp>

#include "distance/exact.hpp"
#include "distance/exact_planar.hpp"
#include "distance/harness.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <limits>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class PlanarPairsTest : public ::testing::Test {};
TYPED_TEST_SUITE(PlanarPairsTest, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kCases = 24;
#else
constexpr int kCases = 50;
#endif

template <class T>
Triangle3<T> random_triangle(Rng& rng, T S) {
  Triangle3<T> t{rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S)};
  const int kind = rng.uniform_int(0, 19);
  if (kind == 0) t.v2 = lerp(t.v0, t.v1, rng.uniform<T>(T(-0.5), T(1.5)));
  if (kind == 1) t.v2 = t.v1;
  return t;
}

template <class T>
Rectangle3<T> random_rectangle(Rng& rng, T S) {
  const auto r = dist::random_rotation<T, 3>(rng);
  Rectangle3<T> rect{rng.vec<T, 3>(-S, S),
                     {r * Vec3<T>{T(1), T(0), T(0)}, r * Vec3<T>{T(0), T(1), T(0)}},
                     {rng.uniform<T>(T(0.1), S), rng.uniform<T>(T(0.1), S)}};
  if (rng.uniform_int(0, 19) == 0) rect.extent[rng.uniform_int(0, 1)] = T(0);
  return rect;
}

// The second piece's placement relative to the first: independent (60%), translated copy along
// the first's normal (parallel planes, 15%), translated within the first's plane (coplanar,
// 10%), moved so that both contain a common point (15%).
template <class T, class P>
P place(Rng& rng, P second, const Vec3<T>& normal, const Vec3<T>& anchor, const Vec3<T>& own, T S) {
  const auto shift = [&](const Vec3<T>& by) {
    if constexpr (std::is_same_v<P, Triangle3<T>>) {
      second.v0 = second.v0 + by;
      second.v1 = second.v1 + by;
      second.v2 = second.v2 + by;
    } else {
      second.center = second.center + by;
    }
  };
  const int kind = rng.uniform_int(0, 19);
  if (kind < 12) return second;
  if (kind < 15) {
    shift(normal * rng.uniform<T>(-S, S));
  } else if (kind < 17) {
    const Vec3<T> in = rng.vec<T, 3>(-S, S);
    shift((in - dot(in, normal) * normal) * T(0.3));
  } else {
    shift(anchor - own);
  }
  return second;
}

template <class T>
Vec3<T> unit_normal_of(const Triangle3<T>& t) {
  return unit_normal(t);
}
template <class T>
Vec3<T> unit_normal_of(const Rectangle3<T>& r) {
  return cross(r.axis[0], r.axis[1]);
}
template <class T>
Vec3<T> some_point(Rng& rng, const Triangle3<T>& t) {
  T s = rng.uniform<T>(0, 1), u = rng.uniform<T>(0, 1);
  if (s + u > T(1)) s = T(1) - s, u = T(1) - u;
  return point_at(t, Vec2<T>{s, u});
}
template <class T>
Vec3<T> some_point(Rng& rng, const Rectangle3<T>& r) {
  return point_at(
      r, Vec2<T>{rng.uniform<T>(-1, 1) * r.extent[0], rng.uniform<T>(-1, 1) * r.extent[1]});
}
template <class T>
Triangle3<T> make_piece(Rng& rng, T S, const Triangle3<T>*) {
  return random_triangle<T>(rng, S);
}
template <class T>
Rectangle3<T> make_piece(Rng& rng, T S, const Rectangle3<T>*) {
  return random_rectangle<T>(rng, S);
}

template <class T, class A, class B>
std::pair<A, B> random_pair(Rng& rng, T S) {
  const A a = make_piece<T>(rng, S, static_cast<const A*>(nullptr));
  const B b0 = make_piece<T>(rng, S, static_cast<const B*>(nullptr));
  const Vec3<T> n = unit_normal_of(a);
  const B b = place<T>(rng, b0, n, some_point(rng, a), some_point(rng, b0), S);
  return {a, b};
}

template <class T>
mpq_class exact_sqr(const Triangle3<T>& a, const Triangle3<T>& b) {
  return ex::sqr_triangle_triangle(ex::tri_of(a), ex::tri_of(b));
}
template <class T>
mpq_class exact_sqr(const Triangle3<T>& a, const Rectangle3<T>& b) {
  const auto r = ex::rect_triangles(b);
  return ex::min_q(ex::sqr_triangle_triangle(ex::tri_of(a), r[0]),
                   ex::sqr_triangle_triangle(ex::tri_of(a), r[1]));
}
template <class T>
mpq_class exact_sqr(const Rectangle3<T>& a, const Rectangle3<T>& b) {
  const auto ra = ex::rect_triangles(a), rb = ex::rect_triangles(b);
  mpq_class best = ex::sqr_triangle_triangle(ra[0], rb[0]);
  best = ex::min_q(best, ex::sqr_triangle_triangle(ra[0], rb[1]));
  best = ex::min_q(best, ex::sqr_triangle_triangle(ra[1], rb[0]));
  return ex::min_q(best, ex::sqr_triangle_triangle(ra[1], rb[1]));
}

template <class T, class A, class B>
void run() {
  const T S = 4;
  dist::Options<T> opt;
  opt.cases = kCases;
  opt.scale = T(16);
  opt.check_agreement = false;  // 4-parameter search; the exact oracle below is tighter
  dist::check_pairs<T, 3, A, B>([&](Rng& rng) { return random_pair<T, A, B>(rng, S); }, opt);
  Rng rng(locus_test::test_seed() + 61);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < kCases; ++n) {
    const auto [a, b] = random_pair<T, A, B>(rng, S);
    const auto r = distance(a, b);
    const T scale = std::max({T(16), max_abs(r.closest[0]), max_abs(r.closest[1])});
    EXPECT_NEAR(double(r.sqr_distance), exact_sqr(a, b).get_d(), double(tol<T>(64, scale * scale)))
        << "case " << n;
  }
}

}  // namespace

TYPED_TEST(PlanarPairsTest, TriangleTriangleHarnessAndExactOracle) {
  run<TypeParam, Triangle3<TypeParam>, Triangle3<TypeParam>>();
}
TYPED_TEST(PlanarPairsTest, TriangleRectangleHarnessAndExactOracle) {
  run<TypeParam, Triangle3<TypeParam>, Rectangle3<TypeParam>>();
}
TYPED_TEST(PlanarPairsTest, RectangleRectangleHarnessAndExactOracle) {
  run<TypeParam, Rectangle3<TypeParam>, Rectangle3<TypeParam>>();
}

// Small integer coordinates: two triangles (one at least non-degenerate) meet iff the distance is
// exactly 0.
TYPED_TEST(PlanarPairsTest, TrianglesMeetExactly) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 62);
  SCOPED_TRACE(rng.trace());
  int zero = 0;
  for (int n = 0; n < 3 * kCases; ++n) {
    const auto iv = [&] {
      return Vec3<T>{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2)),
                     T(rng.uniform_int(-1, 1))};
    };
    const Triangle3<T> a{iv(), iv(), iv()}, b{iv(), iv(), iv()};
    const auto r = distance(a, b);
    const mpq_class e = exact_sqr(a, b);
    if (!is_degenerate(a) || !is_degenerate(b)) {
      EXPECT_EQ(r.distance == T(0), e == 0) << "case " << n;
      zero += e == 0;
    }
    EXPECT_NEAR(double(r.sqr_distance), e.get_d(), double(tol<T>(64, T(16)))) << "case " << n;
  }
  EXPECT_GT(zero, kCases / 4);
}

// Configurations with known answers: crossing, touching, stacked, skew edges, coplanar.
TYPED_TEST(PlanarPairsTest, KnownConfigurations) {
  using T = TypeParam;
  const Triangle3<T> base{{T(0), T(0), T(0)}, {T(4), T(0), T(0)}, {T(0), T(4), T(0)}};
  // Crossing transversally: they meet along a segment, distance 0, not unique.
  const Triangle3<T> cross_tri{{T(1), T(1), T(-1)}, {T(1), T(1), T(1)}, {T(2), T(0.5), T(1)}};
  const auto c = distance(base, cross_tri);
  EXPECT_EQ(c.distance, T(0));
  EXPECT_FALSE(c.unique);
  // A vertex touching the interior: distance 0 at that vertex, unique.
  const Triangle3<T> touch{{T(1), T(1), T(0)}, {T(1), T(2), T(3)}, {T(2), T(1), T(3)}};
  const auto t = distance(base, touch);
  EXPECT_EQ(t.distance, T(0));
  EXPECT_TRUE(t.unique);
  EXPECT_EQ(t.closest[1], touch.v0);
  // Stacked parallel copies: distance 2, not unique.
  const Triangle3<T> up{{T(0), T(0), T(2)}, {T(4), T(0), T(2)}, {T(0), T(4), T(2)}};
  const auto s = distance(base, up);
  EXPECT_EQ(s.distance, T(2));
  EXPECT_FALSE(s.unique);
  // Skew edges: a triangle above the hypotenuse, perpendicular to it.
  const Triangle3<T> skew{{T(1), T(1), T(1)}, {T(3), T(3), T(1)}, {T(2), T(2), T(5)}};
  const auto k = distance(base, skew);
  EXPECT_NEAR(k.sqr_distance, T(1), tol<T>(16, T(4)));
  EXPECT_FALSE(k.unique);  // the bottom edge of skew runs parallel to base's plane, above it
  // Coplanar, disjoint: the gap between the hypotenuse and a vertex.
  const Triangle3<T> beside{{T(3), T(3), T(0)}, {T(6), T(3), T(0)}, {T(3), T(6), T(0)}};
  const auto b = distance(base, beside);
  EXPECT_NEAR(b.sqr_distance, T(2), tol<T>(16, T(4)));
  EXPECT_TRUE(locus_test::vec_near(b.closest[0], Vec3<T>{T(2), T(2), T(0)}, tol<T>(16, T(4))));
  EXPECT_EQ(b.closest[1], beside.v0);
  // Triangle and rectangle, rectangle and rectangle.
  const Rectangle3<T> rect{
      {T(0), T(0), T(3)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(1), T(1)}};
  const auto tr = distance(base, rect);
  EXPECT_EQ(tr.distance, T(3));
  EXPECT_FALSE(tr.unique);
  const auto rt = distance(rect, base);
  EXPECT_EQ(rt.param_a, tr.param_b);
  const Rectangle3<T> tilted{
      {T(5), T(0), T(0)}, {{T(0), T(1), T(0)}, {T(0), T(0), T(1)}}, {T(1), T(1)}};
  const auto rr = distance(rect, tilted);
  // Nearest sides x = 1, z = 3 and x = 5, z = 1 run parallel along y: 16 + 4, not unique.
  EXPECT_NEAR(rr.sqr_distance, T(20), tol<T>(16, T(20)));
  EXPECT_FALSE(rr.unique);
  EXPECT_NEAR(rr.closest[0].x, T(1), tol<T>(16, T(4)));
  EXPECT_NEAR(rr.closest[1].z, T(1), tol<T>(16, T(4)));
  const Rectangle3<T> crossing{
      {T(0), T(0), T(3)}, {{T(1), T(0), T(0)}, {T(0), T(0), T(1)}}, {T(2), T(2)}};
  const auto rc = distance(rect, crossing);
  EXPECT_LE(rc.distance, tol<T>(16, T(4)));
  EXPECT_FALSE(rc.unique);
}

TYPED_TEST(PlanarPairsTest, DegenerateInput) {
  using T = TypeParam;
  const Triangle3<T> base{{T(0), T(0), T(0)}, {T(4), T(0), T(0)}, {T(0), T(4), T(0)}};
  // Collinear and point triangles.
  const Triangle3<T> col{{T(1), T(1), T(2)}, {T(2), T(1), T(2)}, {T(3), T(1), T(2)}};
  const auto a = distance(base, col);
  EXPECT_EQ(a.distance, T(2));
  EXPECT_FALSE(a.unique);  // a segment parallel to the plane over the interior
  const Triangle3<T> pt{{T(5), T(5), T(0)}, {T(5), T(5), T(0)}, {T(5), T(5), T(0)}};
  EXPECT_NEAR(distance(base, pt).sqr_distance, T(18), tol<T>(16, T(18)));
  EXPECT_NEAR(distance(pt, base).sqr_distance, T(18), tol<T>(16, T(18)));
  // Zero-extent rectangles: a segment and a point.
  const Rectangle3<T> seg{
      {T(1), T(1), T(1)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(2), T(0)}};
  EXPECT_EQ(distance(base, seg).distance, T(1));
  const Rectangle3<T> point{
      {T(1), T(1), T(-1)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(0), T(0)}};
  EXPECT_EQ(distance(point, seg).distance, T(2));
  EXPECT_EQ(distance(base, point).distance, T(1));
}

TYPED_TEST(PlanarPairsTest, NonFiniteInputGivesNaNResult) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Triangle3<T> tri{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}};
  const Rectangle3<T> rect{
      {T(0), T(0), T(3)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(1), T(1)}};
  auto bad_tri = tri;
  bad_tri.v2.z = nan;
  auto bad_rect = rect;
  bad_rect.extent[0] = inf;
  EXPECT_TRUE(dist::is_nan_result(distance(tri, bad_tri)));
  EXPECT_TRUE(dist::is_nan_result(distance(bad_tri, tri)));
  EXPECT_TRUE(dist::is_nan_result(distance(bad_tri, rect)));
  EXPECT_TRUE(dist::is_nan_result(distance(bad_rect, tri)));
  const auto r = distance(rect, bad_rect);
  EXPECT_TRUE(dist::is_nan_result(r));
  EXPECT_TRUE(std::isnan(r.param_a.x) && std::isnan(r.param_b.y));
}
