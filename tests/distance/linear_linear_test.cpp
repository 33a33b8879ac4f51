// SPDX-License-Identifier: BSL-1.0
// Tests for distance/line_line.hpp, line_ray.hpp, line_segment.hpp, ray_ray.hpp,
// ray_segment.hpp, segment_segment.hpp (rows dist2.linear-linear, dist3.linear-linear; book
// figures 6.16-6.21 and 10.27-10.37).
#include <locus/distance/line_line.hpp>
#include <locus/distance/line_ray.hpp>
#include <locus/distance/line_segment.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/distance/ray_ray.hpp>
#include <locus/distance/ray_segment.hpp>
#include <locus/distance/segment_segment.hpp>

#include "distance/exact.hpp"
#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class LinearLinearTest : public ::testing::Test {};
TYPED_TEST_SUITE(LinearLinearTest, locus_test::RealTypes);

namespace {

constexpr int kCases = 150;

// A pair of (origin, direction) with a mix of configurations: generic (60%), nearly parallel
// with relative perturbation 10^-3 .. 1000 eps (15%), exactly parallel or anti-parallel by a
// power-of-two factor (10%), crossing through a common point (5%), a zero direction (10%).
template <class T, int N>
std::pair<std::pair<Vec<T, N>, Vec<T, N>>, std::pair<Vec<T, N>, Vec<T, N>>> random_linear_pair(
    Rng& rng, T S) {
  const auto o0 = rng.vec<T, N>(-S, S), o1 = rng.vec<T, N>(-S, S);
  auto d0 = rng.unit<T, N>() * rng.uniform<T>(T(0.5), T(2)) * S;
  auto d1 = rng.unit<T, N>() * rng.uniform<T>(T(0.5), T(2)) * S;
  const int kind = rng.uniform_int(0, 19);
  if (kind < 3) {
    // Down to 1000 eps: below ~eps the directions are numerically parallel and the problem is
    // ill-posed (every answer between the parallel distance and the exact one is backward
    // stable); that regime is covered by the bounded continuity test below.
    const T lo = -std::log10(T(1000) * locus::eps_v<T>);
    const T rel = std::pow(T(10), -rng.uniform<T>(T(3), lo));
    d1 = d0 * (rng.uniform_int(0, 1) ? T(1) : T(-0.7)) + rng.unit<T, N>() * (rel * S);
  } else if (kind < 5) {
    d1 = d0 * (rng.uniform_int(0, 1) ? T(2) : T(-0.5));
  } else if (kind < 6) {
    // Both components pass through o0 (segments: their midpoints).
    return {{o0 - T(0.5) * d0, d0}, {o0 - T(0.5) * d1, d1}};
  } else if (kind < 8) {
    (rng.uniform_int(0, 1) ? d0 : d1) = Vec<T, N>{};
  }
  return {{o0, d0}, {o1, d1}};
}

template <class T, int N>
Line<T, N> as_line(const std::pair<Vec<T, N>, Vec<T, N>>& od) {
  return {od.first, od.second};
}
template <class T, int N>
Ray<T, N> as_ray(const std::pair<Vec<T, N>, Vec<T, N>>& od) {
  return {od.first, od.second};
}
template <class T, int N>
Segment<T, N> as_segment(const std::pair<Vec<T, N>, Vec<T, N>>& od) {
  return {od.first, od.first + od.second};
}

template <class T, int N>
ex::QLinear<static_cast<std::size_t>(N)> q_of(const Line<T, N>& l) {
  return ex::line(l.origin, l.direction);
}
template <class T, int N>
ex::QLinear<static_cast<std::size_t>(N)> q_of(const Ray<T, N>& l) {
  return ex::ray(l.origin, l.direction);
}
template <class T, int N>
ex::QLinear<static_cast<std::size_t>(N)> q_of(const Segment<T, N>& s) {
  return ex::segment(s.p0, s.p1);
}

template <class T, int N, class A, class B, class MakeA, class MakeB>
void run_pair(MakeA make_a, MakeB make_b) {
  const T S = 4;
  dist::Options<T> opt;
  opt.cases = kCases;
  opt.scale = T(8);
  opt.window = T(50);
  // Nearly parallel pairs have long narrow valleys where the compass search stalls; agreement
  // is checked against the exact rational oracle below instead (a far tighter tolerance).
  opt.check_agreement = false;
  dist::check_pairs<T, N, A, B>(
      [&](Rng& rng) {
        const auto p = random_linear_pair<T, N>(rng, S);
        return std::pair<A, B>{make_a(p.first), make_b(p.second)};
      },
      opt);
  // Exact rational oracle on the same distribution.
  Rng rng(locus_test::test_seed() + 1);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 400; ++n) {
    const auto p = random_linear_pair<T, N>(rng, S);
    const A a = make_a(p.first);
    const B b = make_b(p.second);
    const auto r = distance(a, b);
    const double exact = ex::sqr_linear_linear(q_of(a), q_of(b)).get_d();
    // The closest points are rounded: the squared distance is within k eps scale^2.
    const T scale = std::max({T(8), max_abs(r.closest[0]), max_abs(r.closest[1])});
    EXPECT_NEAR(double(r.sqr_distance), exact, double(tol<T>(64, scale * scale))) << "case " << n;
    if constexpr (requires { sqr_distance(a, b); }) {
      EXPECT_EQ(sqr_distance(a, b), r.sqr_distance) << "case " << n;
      EXPECT_EQ(sqr_distance(b, a), r.sqr_distance) << "case " << n;
    }
  }
}

template <class T, int N>
void all_pairs() {
  const auto L = [](const auto& p) { return as_line<T, N>(p); };
  const auto R = [](const auto& p) { return as_ray<T, N>(p); };
  const auto G = [](const auto& p) { return as_segment<T, N>(p); };
  run_pair<T, N, Line<T, N>, Line<T, N>>(L, L);
  run_pair<T, N, Line<T, N>, Ray<T, N>>(L, R);
  run_pair<T, N, Line<T, N>, Segment<T, N>>(L, G);
  run_pair<T, N, Ray<T, N>, Ray<T, N>>(R, R);
  run_pair<T, N, Ray<T, N>, Segment<T, N>>(R, G);
  run_pair<T, N, Segment<T, N>, Segment<T, N>>(G, G);
}

}  // namespace

TYPED_TEST(LinearLinearTest, HarnessAndExactOracle2D) { all_pairs<TypeParam, 2>(); }
TYPED_TEST(LinearLinearTest, HarnessAndExactOracle3D) { all_pairs<TypeParam, 3>(); }

// Figures 6.16 / 6.17: two lines in the plane meet (distance 0) unless parallel, and parallel
// lines have infinitely many closest pairs.
TYPED_TEST(LinearLinearTest, Figure6_16LinesMeetUnlessParallel) {
  using T = TypeParam;
  const Line2<T> a{{T(0), T(0)}, {T(1), T(1)}}, b{{T(4), T(0)}, {T(-1), T(1)}};
  const auto r = distance(a, b);
  EXPECT_EQ(r.distance, T(0));
  EXPECT_EQ(r.param_a, T(2));
  EXPECT_EQ(r.param_b, T(2));
  EXPECT_TRUE(r.unique);
  const Line2<T> c{{T(0), T(3)}, {T(-2), T(-2)}};
  const auto p = distance(a, c);
  EXPECT_FALSE(p.unique);
  EXPECT_NEAR(p.distance, T(3) / std::sqrt(T(2)), tol<T>(8));
}

// Figure 10.27: skew lines in 3D, the common perpendicular.
TYPED_TEST(LinearLinearTest, Figure10_27SkewLines) {
  using T = TypeParam;
  const Line3<T> a{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}},
      b{{T(5), T(-2), T(3)}, {T(0), T(2), T(0)}};
  const auto r = distance(a, b);
  EXPECT_EQ(r.param_a, T(5));
  EXPECT_EQ(r.param_b, T(1));
  EXPECT_EQ(r.closest[0], (Vec3<T>{T(5), T(0), T(0)}));
  EXPECT_EQ(r.closest[1], (Vec3<T>{T(5), T(0), T(3)}));
  EXPECT_EQ(r.distance, T(3));
}

// Figure 6.18: line-ray and line-segment: the ray / segment may end before the line's crossing.
TYPED_TEST(LinearLinearTest, Figure6_18LineRayLineSegment) {
  using T = TypeParam;
  const Line2<T> l{{T(0), T(0)}, {T(1), T(0)}};
  const auto cross = distance(l, Ray2<T>{{T(2), T(3)}, {T(0), T(-1)}});
  EXPECT_EQ(cross.distance, T(0));
  EXPECT_EQ(cross.param_b, T(3));
  const auto away = distance(l, Ray2<T>{{T(2), T(3)}, {T(1), T(1)}});
  EXPECT_EQ(away.param_b, T(0));
  EXPECT_EQ(away.distance, T(3));
  const auto seg = distance(l, Segment2<T>{{T(-1), T(5)}, {T(3), T(1)}});
  EXPECT_EQ(seg.param_b, T(1));
  EXPECT_EQ(seg.closest[1], (Vec2<T>{T(3), T(1)}));
  EXPECT_EQ(seg.param_a, T(3));
  EXPECT_EQ(seg.distance, T(1));
}

// Figure 6.19: ray-ray, including anti-parallel rays whose projections do not overlap.
TYPED_TEST(LinearLinearTest, Figure6_19RayRay) {
  using T = TypeParam;
  const Ray2<T> a{{T(0), T(0)}, {T(1), T(0)}};
  const auto apart = distance(a, Ray2<T>{{T(-2), T(1)}, {T(-1), T(0)}});
  EXPECT_TRUE(apart.unique);
  EXPECT_EQ(apart.param_a, T(0));
  EXPECT_EQ(apart.param_b, T(0));
  EXPECT_NEAR(apart.distance, std::sqrt(T(5)), tol<T>(4, T(3)));
  const auto facing = distance(a, Ray2<T>{{T(4), T(1)}, {T(-2), T(0)}});
  EXPECT_FALSE(facing.unique);
  EXPECT_EQ(facing.distance, T(1));
  const auto same = distance(a, Ray2<T>{{T(4), T(1)}, {T(3), T(0)}});
  EXPECT_FALSE(same.unique);
  EXPECT_EQ(same.distance, T(1));
}

// Figure 6.20: ray-segment, the segment's endpoint nearest the ray's origin region.
TYPED_TEST(LinearLinearTest, Figure6_20RaySegment) {
  using T = TypeParam;
  const Ray3<T> r{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}};
  const auto behind = distance(r, Segment3<T>{{T(-3), T(0), T(4)}, {T(-3), T(0), T(8)}});
  EXPECT_EQ(behind.param_a, T(0));
  EXPECT_EQ(behind.param_b, T(0));
  EXPECT_EQ(behind.distance, T(5));
  const auto over = distance(r, Segment3<T>{{T(2), T(-1), T(1)}, {T(2), T(1), T(1)}});
  EXPECT_EQ(over.param_a, T(2));
  EXPECT_EQ(over.param_b, T(0.5));
  EXPECT_EQ(over.distance, T(1));
}

// Figure 6.21 / 10.33-10.37: parallel segments, overlapping (many closest pairs), touching in
// projection at one point (unique), and apart (endpoint to endpoint).
TYPED_TEST(LinearLinearTest, Figure6_21ParallelSegments) {
  using T = TypeParam;
  const Segment2<T> a{{T(0), T(0)}, {T(4), T(0)}};
  const auto overlap = distance(a, Segment2<T>{{T(6), T(2)}, {T(2), T(2)}});
  EXPECT_FALSE(overlap.unique);
  EXPECT_EQ(overlap.distance, T(2));
  EXPECT_GE(overlap.closest[0].x, T(2));
  EXPECT_LE(overlap.closest[0].x, T(4));
  const auto touch = distance(a, Segment2<T>{{T(4), T(3)}, {T(7), T(3)}});
  EXPECT_TRUE(touch.unique);
  EXPECT_EQ(touch.closest[0], a.p1);
  EXPECT_EQ(touch.distance, T(3));
  const auto apart = distance(a, Segment2<T>{{T(7), T(4)}, {T(9), T(4)}});
  EXPECT_TRUE(apart.unique);
  EXPECT_EQ(apart.closest[0], a.p1);
  EXPECT_EQ(apart.closest[1], (Vec2<T>{T(7), T(4)}));
  EXPECT_EQ(apart.distance, T(5));
  // Collinear overlapping segments: distance 0, not unique.
  const auto col = distance(Segment3<T>{{T(0), T(0), T(0)}, {T(2), T(2), T(2)}},
                            Segment3<T>{{T(1), T(1), T(1)}, {T(5), T(5), T(5)}});
  EXPECT_FALSE(col.unique);
  EXPECT_EQ(col.distance, T(0));
}

// The configuration that breaks "if det < eps then parallel" code: nearly parallel segments.
// Moving an endpoint in 1e-6 steps (double; 1e-3 steps for float, whose eps is 1e9 times
// larger) through the exactly parallel position must change the distance by at most the
// Lipschitz bound (the step; the distance is 1-Lipschitz in each endpoint) plus rounding, and
// for double every answer agrees with the exact rational distance.
TYPED_TEST(LinearLinearTest, NearParallelSegmentsAreContinuous) {
  using T = TypeParam;
  const T step = std::is_same_v<T, float> ? T(1e-3) : T(1e-6);
  const int steps = 2000;
  for (int config = 0; config < 4; ++config) {
    SCOPED_TRACE("config " + std::to_string(config));
    const Segment3<T> a{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}};
    // b runs over (part of) a at height h, its second endpoint moves in y (2D-like) or z.
    const T h = config % 2 == 0 ? T(0) : T(0.25);
    const T x0 = config < 2 ? T(0.3) : T(-0.5), x1 = config < 2 ? T(0.9) : T(1.5);
    T prev = T(-1);
    for (int k = -steps / 2; k <= steps / 2; ++k) {
      const T off = static_cast<T>(k) * step;
      const Segment3<T> b{{x0, h, T(0)}, {x1, h + off, config == 3 ? off : T(0)}};
      const auto r = distance(a, b);
      ASSERT_TRUE(std::isfinite(r.distance));
      if (prev >= T(0)) {
        EXPECT_LE(std::abs(r.distance - prev), step * T(1.5) + tol<T>(64)) << "k = " << k;
      }
      prev = r.distance;
      if constexpr (std::is_same_v<T, double>) {
        const double exact =
            ex::sqr_linear_linear(ex::segment(a.p0, a.p1), ex::segment(b.p0, b.p1)).get_d();
        EXPECT_NEAR(r.sqr_distance, exact, tol<T>(16)) << "k = " << k;
      }
    }
  }
}

// Degenerate components act as points; both degenerate gives the point-point distance.
TYPED_TEST(LinearLinearTest, ZeroLengthSegmentsAndZeroDirections) {
  using T = TypeParam;
  const Segment3<T> p{{T(1), T(1), T(1)}, {T(1), T(1), T(1)}};
  const Segment3<T> q{{T(1), T(5), T(4)}, {T(1), T(5), T(4)}};
  const auto r = distance(p, q);
  EXPECT_EQ(r.distance, T(5));
  EXPECT_TRUE(r.unique);
  const auto s = distance(p, Segment3<T>{{T(-3), T(4), T(1)}, {T(5), T(4), T(1)}});
  EXPECT_EQ(s.distance, T(3));
  EXPECT_EQ(s.param_b, T(0.5));
  const auto l =
      distance(Line3<T>{{T(0), T(0), T(0)}, {}}, Ray3<T>{{T(0), T(2), T(0)}, {T(0), T(1), T(0)}});
  EXPECT_EQ(l.distance, T(2));
  EXPECT_EQ(l.param_b, T(0));
}

TYPED_TEST(LinearLinearTest, NonFiniteInputGivesNaNResult) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Vec3<T> o{T(1), T(2), T(3)}, d{T(0), T(1), T(0)}, bad{T(0), nan, T(0)},
      big{T(0), T(0), -inf};
  EXPECT_TRUE(dist::is_nan_result(distance(Line3<T>{o, d}, Line3<T>{bad, d})));
  EXPECT_TRUE(dist::is_nan_result(distance(Line3<T>{o, big}, Ray3<T>{o, d})));
  EXPECT_TRUE(dist::is_nan_result(distance(Segment3<T>{o, bad}, Line3<T>{o, d})));
  EXPECT_TRUE(dist::is_nan_result(distance(Ray3<T>{o, d}, Ray3<T>{o, bad})));
  EXPECT_TRUE(dist::is_nan_result(distance(Segment3<T>{o, d}, Ray3<T>{big, d})));
  EXPECT_TRUE(dist::is_nan_result(distance(Segment3<T>{o, d}, Segment3<T>{o, big})));
  const auto r = distance(Segment3<T>{o, d}, Segment3<T>{o, bad});
  EXPECT_TRUE(std::isnan(r.param_a) && std::isnan(r.param_b) && std::isnan(r.closest[0].x));
}

// Swapped overloads give bit-identical swapped answers.
TYPED_TEST(LinearLinearTest, SwappedOverloadsAreExactSwaps) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 50; ++n) {
    const Line3<T> l{rng.vec<T, 3>(-1, 1), rng.unit<T, 3>()};
    const Ray3<T> r{rng.vec<T, 3>(-1, 1), rng.unit<T, 3>()};
    const Segment3<T> s{rng.vec<T, 3>(-1, 1), rng.vec<T, 3>(-1, 1)};
    const auto a = distance(l, s), b = distance(s, l);
    EXPECT_EQ(a.distance, b.distance);
    EXPECT_EQ(a.closest[0], b.closest[1]);
    EXPECT_EQ(a.param_a, b.param_b);
    const auto c = distance(r, s), e = distance(s, r);
    EXPECT_EQ(c.closest[1], e.closest[0]);
    EXPECT_EQ(c.param_b, e.param_a);
    const auto f = distance(l, r), g = distance(r, l);
    EXPECT_EQ(f.closest[1], g.closest[0]);
  }
}

// The same sweep through the parallel position for a ray and a line against the moving segment
// (b's second endpoint moves; the distance is 1-Lipschitz in it), checked exactly in double.
TYPED_TEST(LinearLinearTest, NearParallelRayAndLineAreContinuous) {
  using T = TypeParam;
  const T step = std::is_same_v<T, float> ? T(1e-3) : T(1e-6);
  const int steps = 1000;
  const Ray3<T> ray{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}};
  const Line3<T> line{{T(0), T(0), T(0)}, {T(2), T(0), T(0)}};
  for (int config = 0; config < 2; ++config) {
    SCOPED_TRACE("config " + std::to_string(config));
    const T h = config == 0 ? T(0) : T(0.25);
    T prev_r = T(-1), prev_l = T(-1);
    for (int k = -steps / 2; k <= steps / 2; ++k) {
      const T off = static_cast<T>(k) * step;
      const Segment3<T> b{{T(-0.5), h, T(0)}, {T(1.5), h + off, off}};
      const auto r = distance(ray, b);
      const auto l = distance(b, line);
      ASSERT_TRUE(std::isfinite(r.distance) && std::isfinite(l.distance));
      if (prev_r >= T(0)) {
        EXPECT_LE(std::abs(r.distance - prev_r), step * T(1.5) + tol<T>(64)) << "k = " << k;
        EXPECT_LE(std::abs(l.distance - prev_l), step * T(1.5) + tol<T>(64)) << "k = " << k;
      }
      prev_r = r.distance;
      prev_l = l.distance;
      if constexpr (std::is_same_v<T, double>) {
        const auto qb = ex::segment(b.p0, b.p1);
        EXPECT_NEAR(r.sqr_distance,
                    ex::sqr_linear_linear(ex::ray(ray.origin, ray.direction), qb).get_d(),
                    tol<T>(16))
            << "k = " << k;
        EXPECT_NEAR(l.sqr_distance,
                    ex::sqr_linear_linear(qb, ex::line(line.origin, line.direction)).get_d(),
                    tol<T>(16))
            << "k = " << k;
      }
    }
  }
}

// Two segments in either order give bit-identical, swapped answers (no canonical argument order
// on the fast path: its arithmetic is mirrored exactly), over the whole mixed distribution:
// generic, nearly parallel, parallel, crossing, zero-length; sqr_distance likewise.
TYPED_TEST(LinearLinearTest, SegmentPairSwapIsBitIdentical) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 21);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2000; ++n) {
    const auto p = random_linear_pair<T, 3>(rng, T(4));
    const Segment3<T> a = as_segment<T, 3>(p.first), b = as_segment<T, 3>(p.second);
    const auto r = distance(a, b), q = distance(b, a);
    EXPECT_EQ(r.sqr_distance, q.sqr_distance) << "case " << n;
    EXPECT_EQ(r.distance, q.distance) << "case " << n;
    EXPECT_EQ(r.closest[0], q.closest[1]) << "case " << n;
    EXPECT_EQ(r.closest[1], q.closest[0]) << "case " << n;
    EXPECT_EQ(r.param_a, q.param_b) << "case " << n;
    EXPECT_EQ(r.param_b, q.param_a) << "case " << n;
    EXPECT_EQ(r.unique, q.unique) << "case " << n;
    EXPECT_EQ(sqr_distance(a, b), r.sqr_distance) << "case " << n;
    EXPECT_EQ(sqr_distance(b, a), r.sqr_distance) << "case " << n;
  }
}

// sqr_distance for a point and a segment: the full query's value exactly, the exact rational
// distance to rounding, the endpoint for a zero-length segment.
TYPED_TEST(LinearLinearTest, PointSegmentSqrDistance) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 22);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 400; ++n) {
    const auto p = rng.vec<T, 3>(-8, 8);
    Segment3<T> s{rng.vec<T, 3>(-4, 4), rng.vec<T, 3>(-4, 4)};
    if (n % 10 == 0) s.p1 = s.p0;
    const auto r = distance(p, s);
    EXPECT_EQ(sqr_distance(p, s), r.sqr_distance) << "case " << n;
    EXPECT_EQ(sqr_distance(s, p), r.sqr_distance) << "case " << n;
    const double exact = ex::sqr_point_linear(ex::to_q(p), ex::segment(s.p0, s.p1)).get_d();
    EXPECT_NEAR(double(sqr_distance(p, s)), exact, double(tol<T>(32, T(256)))) << "case " << n;
  }
  const Segment2<T> point{{T(1), T(1)}, {T(1), T(1)}};
  EXPECT_EQ(sqr_distance(Vec2<T>{T(4), T(5)}, point), T(25));
  EXPECT_EQ(sqr_distance(Vec2<T>{T(4), T(5)}, Segment2<T>{{T(0), T(1)}, {T(8), T(1)}}), T(16));
}

// sqr_distance is NaN for a NaN or an infinity in any coordinate, segment-segment (2D and 3D)
// and point-segment, in both argument orders.
TYPED_TEST(LinearLinearTest, SqrDistanceNonFiniteInputGivesNaN) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  for (int k = 0; k < 12; ++k) {
    for (const T x : {nan, inf, -inf}) {
      Segment3<T> a{{T(0), T(0), T(0)}, {T(1), T(2), T(0)}};
      Segment3<T> b{{T(3), T(0), T(1)}, {T(0), T(3), T(2)}};
      Vec3<T>* v[4] = {&a.p0, &a.p1, &b.p0, &b.p1};
      (*v[k / 3])[k % 3] = x;
      EXPECT_TRUE(std::isnan(sqr_distance(a, b))) << k;
      EXPECT_TRUE(std::isnan(sqr_distance(b, a))) << k;
      if (k < 6) {
        EXPECT_TRUE(std::isnan(sqr_distance(a, Vec3<T>{}))) << k;
      }
      if (k >= 6 && k < 9) {
        EXPECT_TRUE(std::isnan(sqr_distance(b.p0, Segment3<T>{}))) << k;
      }
      if (k % 3 < 2) {
        const auto p2 = [](const Vec3<T>& u) { return Vec2<T>{u.x, u.y}; };
        EXPECT_TRUE(std::isnan(sqr_distance(Segment2<T>{p2(a.p0), p2(a.p1)},
                                            Segment2<T>{p2(b.p0), p2(b.p1)})))
            << k;
      }
    }
  }
}
