// SPDX-License-Identifier: BSL-1.0
// Tests for distance/line_triangle.hpp, ray_triangle.hpp, segment_triangle.hpp (row
// dist3.linear-triangle; book figures 10.38-10.41).
#include <locus/distance/line_triangle.hpp>
#include <locus/distance/ray_triangle.hpp>
#include <locus/distance/segment_triangle.hpp>

#include "distance/exact.hpp"
#include "distance/exact_planar.hpp"
#include "distance/harness.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class LinearTriangleTest : public ::testing::Test {};
TYPED_TEST_SUITE(LinearTriangleTest, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kCases = 60;
#else
constexpr int kCases = 100;
#endif

// Random triangles: generic (80%), collinear vertices (5%), a repeated vertex (5%), a needle
// (5%), all three vertices equal (5%).
template <class T>
Triangle3<T> random_triangle(Rng& rng, T S) {
  Triangle3<T> t{rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S)};
  const int kind = rng.uniform_int(0, 19);
  if (kind == 0)
    t.v2 = lerp(t.v0, t.v1, rng.uniform<T>(T(-0.5), T(1.5)));
  else if (kind == 1)
    t.v2 = t.v1;
  else if (kind == 2)
    t.v2 = lerp(t.v0, t.v1, T(0.5)) + rng.unit<T, 3>() * (S * T(1e-4));
  else if (kind == 3)
    t.v1 = t.v2 = t.v0;
  return t;
}

// A linear component (origin, direction) against tri: generic (45%), through a random point of
// the triangle (15%), parallel to its plane above it (10%), in its plane (5%), nearly parallel
// with relative tilt 10^-2 .. 1000 eps (10%), exactly parallel to an axis-aligned triangle (5%),
// parallel to an edge (5%), zero direction (5%).
template <class T>
std::pair<Vec3<T>, Vec3<T>> random_linear(Rng& rng, Triangle3<T>& tri, T S) {
  Vec3<T> o = rng.vec<T, 3>(-T(1.5) * S, T(1.5) * S);
  Vec3<T> d = rng.unit<T, 3>() * (rng.uniform<T>(T(0.5), T(2)) * S);
  const Vec3<T> e0 = tri.v1 - tri.v0, e1 = tri.v2 - tri.v0;
  const Vec3<T> n = normalize(cross(e0, e1));
  const auto in_plane_dir = [&] {
    const T a = rng.uniform<T>(-1, 1), b = rng.uniform<T>(-1, 1);
    return a * e0 + b * e1;
  };
  const auto tri_point = [&](T lo, T hi) {
    T s = rng.uniform<T>(lo, hi), u = rng.uniform<T>(lo, hi);
    if (lo >= T(0) && s + u > T(1)) s = T(1) - s, u = T(1) - u;
    return tri.v0 + s * e0 + u * e1;
  };
  const int kind = rng.uniform_int(0, 19);
  if (kind < 9) {
  } else if (kind < 12) {
    o = tri_point(T(0), T(1)) - rng.uniform<T>(T(0), T(1)) * d;
  } else if (kind < 14) {
    d = in_plane_dir();
    o = tri_point(T(-0.5), T(1.5)) + n * rng.uniform<T>(-S, S);
  } else if (kind < 15) {
    d = in_plane_dir();
    o = tri_point(T(-1), T(2));
  } else if (kind < 17) {
    const T lo = -std::log10(T(1000) * eps_v<T>);
    const T rel = std::pow(T(10), -rng.uniform<T>(T(2), lo));
    d = in_plane_dir() + n * (rel * S * (rng.uniform_int(0, 1) ? T(1) : T(-1)));
    o = tri_point(T(-0.5), T(1.5)) + n * rng.uniform<T>(-S, S) * T(0.1);
  } else if (kind < 18) {
    const T z = rng.uniform<T>(-S, S);
    tri.v0.z = tri.v1.z = tri.v2.z = z;
    d.z = T(0);
    o.z = z + rng.uniform<T>(-S, S) * T(0.2);
  } else if (kind < 19) {
    d = (tri.v1 - tri.v0) * rng.uniform<T>(T(-2), T(2));
    o = tri_point(T(-0.5), T(1.5)) + rng.unit<T, 3>() * rng.uniform<T>(T(0), S);
  } else {
    d = Vec3<T>{};
  }
  return {o, d};
}

template <class T>
Line3<T> as_line(const std::pair<Vec3<T>, Vec3<T>>& od) {
  return {od.first, od.second};
}
template <class T>
Ray3<T> as_ray(const std::pair<Vec3<T>, Vec3<T>>& od) {
  return {od.first, od.second};
}
template <class T>
Segment3<T> as_segment(const std::pair<Vec3<T>, Vec3<T>>& od) {
  return {od.first, od.first + od.second};
}

template <class T>
ex::QLinear<3> q_of(const Line3<T>& l) {
  return ex::line(l.origin, l.direction);
}
template <class T>
ex::QLinear<3> q_of(const Ray3<T>& l) {
  return ex::ray(l.origin, l.direction);
}
template <class T>
ex::QLinear<3> q_of(const Segment3<T>& s) {
  return ex::segment(s.p0, s.p1);
}

template <class T, class L, class Make>
void run(Make make) {
  const T S = 4;
  dist::Options<T> opt;
  opt.cases = kCases;
  opt.scale = T(16);
  opt.window = T(50);
  // Nearly parallel configurations have narrow valleys that defeat the compass search: the
  // exact rational oracle below checks agreement instead (far tighter).
  opt.check_agreement = false;
  dist::check_pairs<T, 3, L, Triangle3<T>>(
      [&](Rng& rng) {
        auto tri = random_triangle<T>(rng, S);
        const auto od = random_linear<T>(rng, tri, S);
        return std::pair<L, Triangle3<T>>{make(od), tri};
      },
      opt);
  Rng rng(locus_test::test_seed() + 11);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2 * kCases; ++n) {
    auto tri = random_triangle<T>(rng, S);
    const L l = make(random_linear<T>(rng, tri, S));
    const auto r = distance(l, tri);
    const double exact = ex::sqr_linear_triangle(q_of(l), ex::tri_of(tri)).get_d();
    const T scale = std::max({T(16), max_abs(r.closest[0]), max_abs(r.closest[1])});
    EXPECT_NEAR(double(r.sqr_distance), exact, double(tol<T>(64, scale * scale))) << "case " << n;
    if constexpr (requires { sqr_distance(l, tri); }) {
      EXPECT_EQ(sqr_distance(l, tri), r.sqr_distance) << "case " << n;
      EXPECT_EQ(sqr_distance(tri, l), r.sqr_distance) << "case " << n;
    }
  }
}

}  // namespace

TYPED_TEST(LinearTriangleTest, SegmentHarnessAndExactOracle) {
  run<TypeParam, Segment3<TypeParam>>([](const auto& od) { return as_segment(od); });
}
TYPED_TEST(LinearTriangleTest, RayHarnessAndExactOracle) {
  run<TypeParam, Ray3<TypeParam>>([](const auto& od) { return as_ray(od); });
}
TYPED_TEST(LinearTriangleTest, LineHarnessAndExactOracle) {
  run<TypeParam, Line3<TypeParam>>([](const auto& od) { return as_line(od); });
}

// Small integer coordinates make touching configurations (a segment through a vertex, along an
// edge, in the plane, ending on the triangle) frequent. The segment query decides "meets"
// exactly: distance exactly 0 iff the exact rational distance is 0, and otherwise the squared
// distance agrees with the exact one.
TYPED_TEST(LinearTriangleTest, SegmentMeetsTriangleExactly) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 12);
  SCOPED_TRACE(rng.trace());
  int zero = 0, coplanar = 0;
  for (int n = 0; n < 6 * kCases; ++n) {
    const auto iv = [&] {
      return Vec3<T>{T(rng.uniform_int(-3, 3)), T(rng.uniform_int(-3, 3)),
                     T(rng.uniform_int(-1, 1))};
    };
    Triangle3<T> tri{iv(), iv(), iv()};
    Segment3<T> seg{iv(), iv()};
    if (n % 4 == 0) tri.v0.z = tri.v1.z = tri.v2.z = seg.p0.z = seg.p1.z = T(0);  // coplanar
    const auto r = distance(seg, tri);
    const mpq_class e = ex::sqr_linear_triangle(q_of(seg), ex::tri_of(tri));
    const bool degenerate = is_degenerate(tri);
    if (!degenerate) {
      EXPECT_EQ(r.distance == T(0), e == 0) << "case " << n << " exact " << e.get_d();
      EXPECT_EQ(r.sqr_distance == T(0), e == 0) << "case " << n;
      EXPECT_EQ(sqr_distance(seg, tri) == T(0), e == 0) << "case " << n;
    }
    EXPECT_EQ(sqr_distance(seg, tri), r.sqr_distance) << "case " << n;
    EXPECT_NEAR(double(r.sqr_distance), e.get_d(), double(tol<T>(64, T(64)))) << "case " << n;
    if (e == 0) {
      ++zero;
      EXPECT_TRUE(locus_test::vec_near(r.closest[0], r.closest[1], tol<T>(64, T(4))));
      EXPECT_TRUE(locus_test::vec_near(point_at(seg, r.param_a), r.closest[0], tol<T>(64, T(4))));
    }
    if (orient3d(tri.v0, tri.v1, tri.v2, seg.p0) == Sign::zero &&
        orient3d(tri.v0, tri.v1, tri.v2, seg.p1) == Sign::zero && !degenerate)
      ++coplanar;
  }
  EXPECT_GT(zero, kCases / 4);  // the touching cases are actually exercised
  EXPECT_GT(coplanar, kCases / 2);
}

// Figure 10.40: the unconstrained minimiser (t, s, u) of a segment-triangle pair falls in one of
// 3 x 7 regions: t < 0, 0 <= t <= 1, t > 1 times the seven regions of the triangle's (s, u)
// plane (0 inside; 1 beyond v1 v2; 3 left of v0 v2; 5 below v0 v1; 2, 4, 6 the vertex regions of
// v2, v0, v1; figure 10.39 / 6.6). Each case builds the segment whose line crosses the plane at a
// chosen (s, u) at a chosen t, tilted so that the crossing is transversal.
TYPED_TEST(LinearTriangleTest, Figure10_40PartitionRegions) {
  using T = TypeParam;
  const Triangle3<T> tri{{T(0), T(0), T(1)}, {T(4), T(0), T(1)}, {T(0), T(4), T(1)}};
  const Vec2<T> region_su[7] = {{T(1), T(1)},   {T(3), T(3)},  {T(-1), T(6)}, {T(-2), T(1)},
                                {T(-1), T(-2)}, {T(3), T(-5)}, {T(6), T(-1)}};
  const T t_values[3] = {T(-0.5), T(0.5), T(1.5)};
  const Vec3<T> dirs[2] = {{T(1), T(2), T(3)}, {T(-2), T(1), T(-1.5)}};
  for (int ri = 0; ri < 7; ++ri) {
    for (int ti = 0; ti < 3; ++ti) {
      for (const Vec3<T>& d : dirs) {
        SCOPED_TRACE("region " + std::to_string(ri) + " t " + std::to_string(t_values[ti]));
        const Vec3<T> x{region_su[ri].x, region_su[ri].y, T(1)};
        const Vec3<T> p0 = x - t_values[ti] * d;
        const Segment3<T> seg{p0, p0 + d};
        const auto r = distance(seg, tri);
        const double e = ex::sqr_linear_triangle(q_of(seg), ex::tri_of(tri)).get_d();
        EXPECT_NEAR(double(r.sqr_distance), e, double(tol<T>(64, T(100))));
        if (ri == 0 && ti == 1) {
          EXPECT_EQ(r.distance, T(0));
          EXPECT_TRUE(locus_test::vec_near(r.closest[1], x, tol<T>(16, T(4))));
          EXPECT_NEAR(r.param_a, T(0.5), tol<T>(16));
        } else {
          EXPECT_GT(r.distance, T(0));
        }
        // The line and ray through the same points: the line meets every crossing inside the
        // triangle, the ray those at t >= 0 (its origin is p0).
        const auto rl = distance(Line3<T>{p0, d}, tri);
        const auto rr = distance(Ray3<T>{p0, d}, tri);
        EXPECT_NEAR(double(rl.sqr_distance),
                    ex::sqr_linear_triangle(ex::line(p0, d), ex::tri_of(tri)).get_d(),
                    double(tol<T>(64, T(100))));
        EXPECT_NEAR(double(rr.sqr_distance),
                    ex::sqr_linear_triangle(ex::ray(p0, d), ex::tri_of(tri)).get_d(),
                    double(tol<T>(64, T(100))));
        if (ri == 0) {
          EXPECT_LE(rl.distance, tol<T>(16, T(4)));
        }
        if (ri == 0 && ti > 0) {
          EXPECT_LE(rr.distance, tol<T>(16, T(4)));
        }
      }
    }
  }
  // Region 4 with the segment below v0 pointing away: the closest pair is the vertex and p0.
  const Segment3<T> far{{T(-1), T(-1), T(-2)}, {T(-2), T(-3), T(-5)}};
  const auto r = distance(far, tri);
  EXPECT_EQ(r.closest[1], tri.v0);
  EXPECT_EQ(r.param_a, T(0));
  EXPECT_EQ(r.sqr_distance, T(11));
}

// Figure 10.41 (the boundary strip of region 3) and the parallel cases: a segment parallel to
// the plane above the interior slides (unique = false); parallel to an edge outside it slides
// along the edge; crossing transversally is unique.
TYPED_TEST(LinearTriangleTest, ParallelCasesAndUniqueness) {
  using T = TypeParam;
  const Triangle3<T> tri{{T(0), T(0), T(0)}, {T(4), T(0), T(0)}, {T(0), T(4), T(0)}};
  const auto above = distance(Segment3<T>{{T(0.5), T(0.5), T(2)}, {T(1.5), T(1), T(2)}}, tri);
  EXPECT_EQ(above.distance, T(2));
  EXPECT_FALSE(above.unique);
  const auto above_line = distance(Line3<T>{{T(0.5), T(0.5), T(2)}, {T(1), T(0.5), T(0)}}, tri);
  EXPECT_EQ(above_line.distance, T(2));
  EXPECT_FALSE(above_line.unique);
  // Parallel to edge v0 v1 beside it (region 5 strip), in the plane: the whole overlap is closest.
  const auto beside = distance(Segment3<T>{{T(1), T(-3), T(0)}, {T(3), T(-3), T(0)}}, tri);
  EXPECT_EQ(beside.distance, T(3));
  EXPECT_FALSE(beside.unique);
  // Region 3 strip (figure 10.41): left of v0 v2, parallel to the plane, not to the edge.
  const auto strip = distance(Segment3<T>{{T(-2), T(1), T(1)}, {T(-3), T(3), T(1)}}, tri);
  EXPECT_NEAR(strip.sqr_distance, T(4) + T(1), tol<T>(32, T(8)));
  EXPECT_TRUE(strip.unique);
  EXPECT_EQ(strip.param_a, T(0));
  // Above the interior, but leaving it: sliding is possible towards the inside only.
  const auto half = distance(Segment3<T>{{T(1), T(1), T(3)}, {T(9), T(1), T(3)}}, tri);
  EXPECT_EQ(half.distance, T(3));
  EXPECT_FALSE(half.unique);
  // Transversal crossing: unique, distance exactly 0 for the segment.
  const auto cross_seg = distance(Segment3<T>{{T(1), T(1), T(-1)}, {T(1), T(1), T(1)}}, tri);
  EXPECT_EQ(cross_seg.distance, T(0));
  EXPECT_TRUE(cross_seg.unique);
  EXPECT_EQ(cross_seg.param_a, T(0.5));
  // In the plane through the triangle: distance 0 along a chord, not unique.
  const auto chord = distance(Segment3<T>{{T(-1), T(1), T(0)}, {T(5), T(1), T(0)}}, tri);
  EXPECT_EQ(chord.distance, T(0));
  EXPECT_FALSE(chord.unique);
  // In the plane, touching only the vertex v1 from outside: unique.
  const auto touch = distance(Segment3<T>{{T(4), T(-2), T(0)}, {T(4), T(2), T(0)}}, tri);
  EXPECT_EQ(touch.distance, T(0));
  EXPECT_TRUE(touch.unique);
}

// Nearly parallel: tilting a segment above the triangle through the parallel position changes
// the distance continuously (no blow-up of the 3x3 solve).
TYPED_TEST(LinearTriangleTest, NearlyParallelIsContinuous) {
  using T = TypeParam;
  const Triangle3<T> tri{{T(0), T(0), T(0)}, {T(4), T(0), T(0)}, {T(0), T(4), T(0)}};
  for (int k = -30; k <= 30; ++k) {
    const T tilt = std::ldexp(T(k < 0 ? -1 : 1), -std::abs(k)) * (k == 0 ? T(0) : T(1));
    for (const T h : {T(0), T(1)}) {
      const Segment3<T> seg{{T(-3), T(1), h - tilt}, {T(7), T(1), h + tilt}};
      const auto r = distance(seg, tri);
      const double e = ex::sqr_linear_triangle(q_of(seg), ex::tri_of(tri)).get_d();
      EXPECT_NEAR(double(r.sqr_distance), e, double(tol<T>(64, T(64)))) << "k " << k << " h " << h;
      const auto rl = distance(Line3<T>{seg.p0, seg.p1 - seg.p0}, tri);
      const double el =
          ex::sqr_linear_triangle(ex::line(seg.p0, seg.p1 - seg.p0), ex::tri_of(tri)).get_d();
      EXPECT_NEAR(double(rl.sqr_distance), el, double(tol<T>(64, T(64)))) << "k " << k;
    }
  }
}

TYPED_TEST(LinearTriangleTest, DegenerateInput) {
  using T = TypeParam;
  const Triangle3<T> tri{{T(0), T(0), T(0)}, {T(4), T(0), T(0)}, {T(0), T(4), T(0)}};
  // A zero-length segment acts as its point.
  const Vec3<T> p{T(1), T(1), T(3)};
  const auto r = distance(Segment3<T>{p, p}, tri);
  EXPECT_EQ(r.distance, T(3));
  EXPECT_EQ(r.param_a, T(0));
  const auto rr = distance(Ray3<T>{p, Vec3<T>{}}, tri);
  EXPECT_EQ(rr.distance, T(3));
  // Collinear triangle: the segment it spans.
  const Triangle3<T> col{{T(0), T(0), T(0)}, {T(2), T(0), T(0)}, {T(4), T(0), T(0)}};
  const auto c = distance(Segment3<T>{{T(1), T(-1), T(2)}, {T(1), T(1), T(2)}}, col);
  EXPECT_NEAR(c.distance, T(2), tol<T>(8, T(2)));
  EXPECT_NEAR(c.param_a, T(0.5), tol<T>(8));
  const auto cl = distance(Line3<T>{{T(6), T(0), T(0)}, {T(1), T(0), T(0)}}, col);
  EXPECT_EQ(cl.distance, T(0));
  EXPECT_FALSE(cl.unique);
  // A point triangle.
  const Triangle3<T> pt{{T(1), T(2), T(3)}, {T(1), T(2), T(3)}, {T(1), T(2), T(3)}};
  const auto q = distance(Line3<T>{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}}, pt);
  EXPECT_NEAR(q.sqr_distance, T(13), tol<T>(16, T(13)));
  EXPECT_NEAR(q.param_a, T(1), tol<T>(8));
  // sqr_distance on the same degenerate input.
  EXPECT_EQ(sqr_distance(Segment3<T>{p, p}, tri), T(9));
  EXPECT_NEAR(sqr_distance(Segment3<T>{{T(1), T(-1), T(2)}, {T(1), T(1), T(2)}}, col), T(4),
              tol<T>(8, T(4)));
  EXPECT_EQ(sqr_distance(pt, Segment3<T>{{T(1), T(0), T(0)}, {T(1), T(4), T(0)}}), T(9));
  EXPECT_EQ(sqr_distance(Segment3<T>{{T(1), T(0), T(0)}, {T(1), T(4), T(0)}}, pt), T(9));
}

TYPED_TEST(LinearTriangleTest, SwappedOverloads) {
  using T = TypeParam;
  const Triangle3<T> tri{{T(0), T(0), T(0)}, {T(4), T(0), T(0)}, {T(0), T(4), T(0)}};
  const Segment3<T> seg{{T(5), T(5), T(1)}, {T(6), T(7), T(4)}};
  const auto a = distance(seg, tri);
  const auto b = distance(tri, seg);
  EXPECT_EQ(a.distance, b.distance);
  EXPECT_EQ(a.closest[0], b.closest[1]);
  EXPECT_EQ(a.param_b, b.param_a);
  const Ray3<T> ray{{T(5), T(5), T(1)}, {T(1), T(2), T(3)}};
  EXPECT_EQ(distance(ray, tri).param_a, distance(tri, ray).param_b);
  const Line3<T> line{{T(5), T(5), T(1)}, {T(1), T(2), T(3)}};
  EXPECT_EQ(distance(line, tri).closest[1], distance(tri, line).closest[0]);
}

TYPED_TEST(LinearTriangleTest, NonFiniteInputGivesNaNResult) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Triangle3<T> tri{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}};
  EXPECT_TRUE(dist::is_nan_result(distance(Segment3<T>{{nan, T(0), T(0)}, {}}, tri)));
  EXPECT_TRUE(dist::is_nan_result(distance(Ray3<T>{{}, {T(0), inf, T(0)}}, tri)));
  EXPECT_TRUE(dist::is_nan_result(distance(Line3<T>{{}, {T(0), T(0), nan}}, tri)));
  auto bad = tri;
  bad.v1.y = inf;
  const auto r = distance(Segment3<T>{{}, {T(1), T(1), T(1)}}, bad);
  EXPECT_TRUE(dist::is_nan_result(r));
  EXPECT_TRUE(std::isnan(r.param_a) && std::isnan(r.param_b.z));
  EXPECT_TRUE(dist::is_nan_result(distance(bad, Line3<T>{{}, {T(1), T(1), T(1)}})));
  // sqr_distance: NaN for a NaN or an infinity in any of the 15 coordinates.
  for (int k = 0; k < 15; ++k) {
    for (const T x : {nan, inf, -inf}) {
      Segment3<T> s{{T(0.2), T(0.2), T(1)}, {T(0.3), T(0.1), T(2)}};
      Triangle3<T> t = tri;
      Vec3<T>* v[5] = {&s.p0, &s.p1, &t.v0, &t.v1, &t.v2};
      (*v[k / 3])[k % 3] = x;
      EXPECT_TRUE(std::isnan(sqr_distance(s, t))) << k;
      EXPECT_TRUE(std::isnan(sqr_distance(t, s))) << k;
    }
  }
}
