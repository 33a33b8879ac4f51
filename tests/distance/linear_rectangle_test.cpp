// SPDX-License-Identifier: BSL-1.0
// Tests for distance/line_rectangle.hpp, ray_rectangle.hpp, segment_rectangle.hpp (row
// dist3.linear-rectangle; book figures 10.42, 10.43).
#include <locus/distance/line_rectangle.hpp>
#include <locus/distance/ray_rectangle.hpp>
#include <locus/distance/segment_rectangle.hpp>

#include "distance/exact.hpp"
#include "distance/exact_planar.hpp"
#include "distance/harness.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class LinearRectangleTest : public ::testing::Test {};
TYPED_TEST_SUITE(LinearRectangleTest, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kCases = 60;
#else
constexpr int kCases = 100;
#endif

// Random rectangles: random rotation, extents in (0, S] (a zero extent 10% of the time, both
// zero 5%).
template <class T>
Rectangle3<T> random_rectangle(Rng& rng, T S) {
  const auto r = dist::random_rotation<T, 3>(rng);
  Rectangle3<T> rect{rng.vec<T, 3>(-S, S),
                     {r * Vec3<T>{T(1), T(0), T(0)}, r * Vec3<T>{T(0), T(1), T(0)}},
                     {rng.uniform<T>(T(0.1), S), rng.uniform<T>(T(0.1), S)}};
  const int kind = rng.uniform_int(0, 19);
  if (kind < 2) rect.extent[kind] = T(0);
  if (kind == 2) rect.extent[0] = rect.extent[1] = T(0);
  return rect;
}

// A linear component against rect: generic (45%), through a random point of the rectangle
// (15%), parallel to its plane (10%), in its plane (5%), nearly parallel with relative tilt
// 10^-2 .. 1000 eps (10%), parallel to a side (10%), zero direction (5%).
template <class T>
std::pair<Vec3<T>, Vec3<T>> random_linear(Rng& rng, const Rectangle3<T>& rect, T S) {
  Vec3<T> o = rng.vec<T, 3>(-T(1.5) * S, T(1.5) * S);
  Vec3<T> d = rng.unit<T, 3>() * (rng.uniform<T>(T(0.5), T(2)) * S);
  const Vec3<T> n = cross(rect.axis[0], rect.axis[1]);
  const auto rect_point = [&](T spread) {
    return point_at(rect, Vec2<T>{rng.uniform<T>(-spread, spread) * rect.extent[0],
                                  rng.uniform<T>(-spread, spread) * rect.extent[1]});
  };
  const auto in_plane_dir = [&] {
    return rng.uniform<T>(-S, S) * rect.axis[0] + rng.uniform<T>(-S, S) * rect.axis[1];
  };
  const int kind = rng.uniform_int(0, 19);
  if (kind < 9) {
  } else if (kind < 12) {
    o = rect_point(T(1)) - rng.uniform<T>(T(0), T(1)) * d;
  } else if (kind < 14) {
    d = in_plane_dir();
    o = rect_point(T(2)) + n * rng.uniform<T>(-S, S);
  } else if (kind < 15) {
    d = in_plane_dir();
    o = rect_point(T(2));
  } else if (kind < 17) {
    const T lo = -std::log10(T(1000) * eps_v<T>);
    const T rel = std::pow(T(10), -rng.uniform<T>(T(2), lo));
    d = in_plane_dir() + n * (rel * S * (rng.uniform_int(0, 1) ? T(1) : T(-1)));
    o = rect_point(T(1.5)) + n * rng.uniform<T>(-S, S) * T(0.1);
  } else if (kind < 19) {
    d = rect.axis[rng.uniform_int(0, 1)] * rng.uniform<T>(-S, S);
    o = rect_point(T(2)) + rng.unit<T, 3>() * rng.uniform<T>(T(0), S);
  } else {
    d = Vec3<T>{};
  }
  return {o, d};
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
  opt.check_agreement = false;  // the exact oracle below is tighter
  dist::check_pairs<T, 3, L, Rectangle3<T>>(
      [&](Rng& rng) {
        const auto rect = random_rectangle<T>(rng, S);
        return std::pair<L, Rectangle3<T>>{make(random_linear<T>(rng, rect, S)), rect};
      },
      opt);
  Rng rng(locus_test::test_seed() + 21);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2 * kCases; ++n) {
    const auto rect = random_rectangle<T>(rng, S);
    const L l = make(random_linear<T>(rng, rect, S));
    const auto r = distance(l, rect);
    const double exact = ex::sqr_linear_rectangle(q_of(l), rect).get_d();
    const T scale = std::max({T(16), max_abs(r.closest[0]), max_abs(r.closest[1])});
    EXPECT_NEAR(double(r.sqr_distance), exact, double(tol<T>(64, scale * scale))) << "case " << n;
  }
}

}  // namespace

TYPED_TEST(LinearRectangleTest, SegmentHarnessAndExactOracle) {
  using T = TypeParam;
  run<T, Segment3<T>>([](const auto& od) { return Segment3<T>{od.first, od.first + od.second}; });
}
TYPED_TEST(LinearRectangleTest, RayHarnessAndExactOracle) {
  using T = TypeParam;
  run<T, Ray3<T>>([](const auto& od) { return Ray3<T>{od.first, od.second}; });
}
TYPED_TEST(LinearRectangleTest, LineHarnessAndExactOracle) {
  using T = TypeParam;
  run<T, Line3<T>>([](const auto& od) { return Line3<T>{od.first, od.second}; });
}

// Figure 10.43: the solution domain of a segment and a rectangle is partitioned by t < 0,
// 0 <= t <= 1, t > 1 and the nine regions of the rectangle's (s, t) plane (inside, four side
// strips, four corner quadrants). Each case crosses the plane at a chosen (s, t) at a chosen
// segment parameter, transversally.
TYPED_TEST(LinearRectangleTest, Figure10_43PartitionRegions) {
  using T = TypeParam;
  // Axis-aligned rectangle [-3, 3] x [-2, 2] in the plane z = 1, and a rotated copy.
  const Rectangle3<T> aligned{
      {T(0), T(0), T(1)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(3), T(2)}};
  const T coords_s[3] = {T(-5), T(1), T(4.5)}, coords_t[3] = {T(-3.5), T(-1), T(3)};
  const T t_values[3] = {T(-0.5), T(0.5), T(1.5)};
  const Vec3<T> dirs[2] = {{T(1), T(2), T(3)}, {T(-2), T(1), T(-1.5)}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (const Vec3<T>& d : dirs) {
          SCOPED_TRACE("s region " + std::to_string(i) + " t region " + std::to_string(j) +
                       " segment t " + std::to_string(t_values[k]));
          const Vec3<T> x{coords_s[i], coords_t[j], T(1)};
          const Vec3<T> p0 = x - t_values[k] * d;
          const Segment3<T> seg{p0, p0 + d};
          const auto r = distance(seg, aligned);
          EXPECT_NEAR(double(r.sqr_distance), ex::sqr_linear_rectangle(q_of(seg), aligned).get_d(),
                      double(tol<T>(64, T(100))));
          if (i == 1 && j == 1 && k == 1) {
            EXPECT_EQ(r.distance, T(0));
            EXPECT_EQ(r.param_b, (Vec2<T>{T(1), T(-1)}));
            EXPECT_EQ(r.param_a, T(0.5));
          } else {
            EXPECT_GT(r.distance, T(0));
          }
          // A crossing in a side strip (the segment reaching the plane) is closest to that side.
          if (i != 1 && j == 1 && k == 1) {
            EXPECT_EQ(std::abs(r.param_b.x), T(3));
          }
          const auto rl = distance(Line3<T>{p0, d}, aligned);
          EXPECT_NEAR(double(rl.sqr_distance),
                      ex::sqr_linear_rectangle(ex::line(p0, d), aligned).get_d(),
                      double(tol<T>(64, T(100))));
          const auto rr = distance(Ray3<T>{p0, d}, aligned);
          EXPECT_NEAR(double(rr.sqr_distance),
                      ex::sqr_linear_rectangle(ex::ray(p0, d), aligned).get_d(),
                      double(tol<T>(64, T(100))));
        }
}

// Figure 10.42: a line and a rectangle; parallel cases and uniqueness.
TYPED_TEST(LinearRectangleTest, Figure10_42ParallelCasesAndUniqueness) {
  using T = TypeParam;
  const Rectangle3<T> rect{
      {T(0), T(0), T(0)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(3), T(2)}};
  // A line crossing the rectangle: distance 0 at the crossing, unique.
  const auto l = distance(Line3<T>{{T(1), T(1), T(5)}, {T(0), T(0), T(-1)}}, rect);
  EXPECT_EQ(l.distance, T(0));
  EXPECT_TRUE(l.unique);
  EXPECT_EQ(l.param_a, T(5));
  EXPECT_EQ(l.param_b, (Vec2<T>{T(1), T(1)}));
  // Parallel above the interior: not unique.
  const auto above = distance(Line3<T>{{T(1), T(1), T(2)}, {T(1), T(1), T(0)}}, rect);
  EXPECT_EQ(above.distance, T(2));
  EXPECT_FALSE(above.unique);
  // Parallel to the side s = 3, beside it: not unique; crossing the side strip obliquely: unique.
  const auto side = distance(Segment3<T>{{T(5), T(-1), T(0)}, {T(5), T(1), T(0)}}, rect);
  EXPECT_EQ(side.distance, T(2));
  EXPECT_FALSE(side.unique);
  const auto oblique = distance(Segment3<T>{{T(5), T(-1), T(1)}, {T(6), T(1), T(1)}}, rect);
  EXPECT_EQ(oblique.sqr_distance, T(5));
  EXPECT_TRUE(oblique.unique);
  EXPECT_EQ(oblique.param_b, (Vec2<T>{T(3), T(-1)}));
  // A corner: the ray pointing away from the corner (3, 2) is closest at its origin.
  const auto corner = distance(Ray3<T>{{T(4), T(4), T(2)}, {T(1), T(2), T(3)}}, rect);
  EXPECT_EQ(corner.param_a, T(0));
  EXPECT_EQ(corner.param_b, (Vec2<T>{T(3), T(2)}));
  EXPECT_EQ(corner.sqr_distance, T(9));
}

TYPED_TEST(LinearRectangleTest, NearlyParallelIsContinuous) {
  using T = TypeParam;
  const Rectangle3<T> rect{
      {T(0), T(0), T(0)}, {{T(0.6), T(0.8), T(0)}, {T(-0.8), T(0.6), T(0)}}, {T(3), T(2)}};
  for (int k = -30; k <= 30; ++k) {
    const T tilt = k == 0 ? T(0) : std::ldexp(T(k < 0 ? -1 : 1), -std::abs(k));
    for (const T h : {T(0), T(1)}) {
      const Segment3<T> seg{{T(-5), T(1), h - tilt}, {T(6), T(0.5), h + tilt}};
      const auto r = distance(seg, rect);
      EXPECT_NEAR(double(r.sqr_distance), ex::sqr_linear_rectangle(q_of(seg), rect).get_d(),
                  double(tol<T>(64, T(64))))
          << "k " << k << " h " << h;
      const Line3<T> line{seg.p0, seg.p1 - seg.p0};
      EXPECT_NEAR(double(distance(line, rect).sqr_distance),
                  ex::sqr_linear_rectangle(q_of(line), rect).get_d(), double(tol<T>(64, T(64))))
          << "k " << k;
    }
  }
}

TYPED_TEST(LinearRectangleTest, DegenerateInput) {
  using T = TypeParam;
  // Zero extents: a segment and a point.
  const Rectangle3<T> seg_rect{
      {T(0), T(0), T(0)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(2), T(0)}};
  const auto a = distance(Line3<T>{{T(1), T(3), T(4)}, {T(0), T(0), T(1)}}, seg_rect);
  EXPECT_EQ(a.distance, T(3));
  EXPECT_EQ(a.param_b, (Vec2<T>{T(1), T(0)}));
  const Rectangle3<T> point_rect{{T(1), T(1), T(1)},
                                 {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}},
                                 {T(0), T(-1)}};  // negative extent acts as 0
  const auto b = distance(Segment3<T>{{T(1), T(1), T(3)}, {T(1), T(1), T(5)}}, point_rect);
  EXPECT_EQ(b.distance, T(2));
  EXPECT_EQ(b.param_b, (Vec2<T>{T(0), T(0)}));
  // A segment lying along the zero-width rectangle: distance 0, not unique.
  const auto c = distance(Segment3<T>{{T(-1), T(0), T(0)}, {T(5), T(0), T(0)}}, seg_rect);
  EXPECT_EQ(c.distance, T(0));
  EXPECT_FALSE(c.unique);
  // Zero-length segment and zero ray direction act as their point.
  const Rectangle3<T> rect{
      {T(0), T(0), T(0)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(3), T(2)}};
  const Vec3<T> p{T(5), T(0), T(0)};
  EXPECT_EQ(distance(Segment3<T>{p, p}, rect).distance, T(2));
  EXPECT_EQ(distance(Ray3<T>{p, Vec3<T>{}}, rect).distance, T(2));
  // Swapped overloads.
  const Segment3<T> s{{T(5), T(5), T(1)}, {T(6), T(7), T(4)}};
  EXPECT_EQ(distance(s, rect).param_b, distance(rect, s).param_a);
  EXPECT_EQ(distance(Line3<T>{p, p}, rect).closest[1], distance(rect, Line3<T>{p, p}).closest[0]);
  EXPECT_EQ(distance(Ray3<T>{p, p}, rect).param_a, distance(rect, Ray3<T>{p, p}).param_b);
}

TYPED_TEST(LinearRectangleTest, NonFiniteInputGivesNaNResult) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Rectangle3<T> rect{
      {T(0), T(0), T(0)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(3), T(2)}};
  EXPECT_TRUE(dist::is_nan_result(distance(Segment3<T>{{nan, T(0), T(0)}, {}}, rect)));
  EXPECT_TRUE(dist::is_nan_result(distance(Ray3<T>{{}, {T(0), inf, T(0)}}, rect)));
  EXPECT_TRUE(dist::is_nan_result(distance(Line3<T>{{}, {T(0), T(0), nan}}, rect)));
  auto bad = rect;
  bad.extent[1] = inf;
  const auto r = distance(Segment3<T>{{}, {T(1), T(1), T(1)}}, bad);
  EXPECT_TRUE(dist::is_nan_result(r));
  EXPECT_TRUE(std::isnan(r.param_b.y));
  EXPECT_TRUE(dist::is_nan_result(distance(bad, Line3<T>{{}, {T(1), T(1), T(1)}})));
}
