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
#include <sstream>
#include <string>
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

// The defining points of a component in hexadecimal floating point (exact), for failure messages
// that reproduce the input.
template <class T, int N>
std::string hex(const Vec<T, N>& v) {
  std::ostringstream os;
  os << std::hexfloat << '{';
  for (int i = 0; i < N; ++i) os << (i ? ", " : "") << double(v[i]);
  return os.str() + '}';
}
template <class T, int N>
std::string describe(const Line<T, N>& l) {
  return "Line{" + hex(l.origin) + ", " + hex(l.direction) + "}";
}
template <class T, int N>
std::string describe(const Ray<T, N>& l) {
  return "Ray{" + hex(l.origin) + ", " + hex(l.direction) + "}";
}
template <class T, int N>
std::string describe(const Segment<T, N>& s) {
  return "Segment{" + hex(s.p0) + ", " + hex(s.p1) + "}";
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
    EXPECT_NEAR(double(r.sqr_distance), exact, double(tol<T>(64, scale * scale)))
        << "case " << n << ": " << describe(a) << ", " << describe(b) << " params " << r.param_a
        << ", " << r.param_b;
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
        EXPECT_TRUE(std::isnan(
            sqr_distance(Segment2<T>{p2(a.p0), p2(a.p1)}, Segment2<T>{p2(b.p0), p2(b.p1)})))
            << k;
      }
    }
  }
}

namespace {

// The components meet: distance and squared distance exactly 0, the exact rational distance 0,
// and each closest point (point_at of its component's parameter, bit for bit) the crossing to
// rounding. A parameter has relative error a few eps (accurate 2x2 minors), so each point's exact
// distance to the OTHER component is within 8 eps |X| (the rounding of origin + t dir plus the
// parameter error times |dir| sin angle).
template <class T, class A, class B>
void expect_meet(const A& a, const B& b) {
  SCOPED_TRACE(describe(a) + ", " + describe(b));
  const auto r = distance(a, b);
  EXPECT_EQ(r.sqr_distance, T(0));
  EXPECT_EQ(r.distance, T(0));
  EXPECT_EQ(r.closest[0], point_at(a, r.param_a));
  EXPECT_EQ(r.closest[1], point_at(b, r.param_b));
  // (unique follows the numerical-parallelism rule, sin^2 angle <= 64 eps^2; not checked here.)
  EXPECT_EQ(ex::sqr_linear_linear(q_of(a), q_of(b)), 0);
  const double scale =
      std::max({1.0, double(max_abs(r.closest[0])), double(max_abs(r.closest[1]))});
  const double bound = 8.0 * double(eps_v<T>) * scale;
  EXPECT_LE(ex::sqr_point_linear(ex::to_q(r.closest[0]), q_of(b)).get_d(), bound * bound);
  EXPECT_LE(ex::sqr_point_linear(ex::to_q(r.closest[1]), q_of(a)).get_d(), bound * bound);
  const auto q = distance(b, a);
  EXPECT_EQ(q.sqr_distance, T(0));
  EXPECT_EQ(q.closest[0], r.closest[1]);
  EXPECT_EQ(q.closest[1], r.closest[0]);
  EXPECT_EQ(q.param_a, r.param_b);
  EXPECT_EQ(q.param_b, r.param_a);
}

}  // namespace

// Regression (LOCUS_TEST_SEED=19, 21, 27 of HarnessAndExactOracle2D, float): nearly parallel
// lines and rays in the plane (sin angle ~1e-4 .. 1e-6) that cross far away (s ~ 1e4 .. 2e7).
// Cramer's rule from dot products cancels completely there (for the first pair its numerator
// rounded to 0), so the library returned the projection of an origin, at squared distance 2.4,
// 1.0e-3 and 4.9e-4 where the exact answer is 0. Whether the components meet is now decided
// exactly (orientation signs), and then the crossing is the answer, at distance exactly 0. The
// inputs are floats, exact in double too.
TYPED_TEST(LinearLinearTest, NearlyParallelLinesAndRaysInThePlaneMeetFarAway) {
  using T = TypeParam;
  const Vec2<T> o0{T(0x1.19e114p+1f), T(0x1.b39fe8p+1f)}, d0{T(-0x1.5a3dc4p+2f), T(0x1.a826a6p+1f)};
  const Vec2<T> o1{T(0x1.df71acp+1f), T(0x1.48139cp-1f)}, d1{T(-0x1.5a481p+2f), T(0x1.a83344p+1f)};
  expect_meet<T>(Line2<T>{o0, d0}, Line2<T>{o1, d1});  // seed 19, case 45
  expect_meet<T>(Line2<T>{o0, d0}, Ray2<T>{o1, d1});
  expect_meet<T>(Ray2<T>{o0, d0}, Ray2<T>{o1, d1});
  expect_meet<T>(
      Line2<T>{{T(-0x1.af5078p+1f), T(-0x1.c165f6p+0f)}, {T(0x1.46d57ep+2f), T(0x1.002e64p+1f)}},
      Line2<T>{{T(0x1.fa201p+1f), T(0x1.0b0d7cp+0f)},
               {T(0x1.46e38ep+2f), T(0x1.0038d8p+1f)}});  // seed 21
  const Vec2<T> o2{T(-0x1.adc43p-1f), T(-0x1.6ab282p-1f)}, d2{T(0x1.650188p+2f), T(0x1.5bf51cp+2f)};
  const Vec2<T> o3{T(0x1.424842p+1f), T(0x1.5fc254p+0f)},
      d3{T(-0x1.f3dc68p+1f), T(-0x1.e7310ep+1f)};
  expect_meet<T>(Line2<T>{o2, d2}, Line2<T>{o3, d3});  // seed 27, case 336
  expect_meet<T>(Line2<T>{o2, d2}, Ray2<T>{o3, d3});
  if constexpr (std::is_same_v<T, double>) {
    // LOCUS_TEST_SEED=5, case 266 (double): sin angle ~1e-12; the origin projection was at squared
    // distance 1.2e-4.
    const Vec2<T> o4{0x1.5bce2395a5bcap+1, 0x1.c945aa2401b3p+0},
        d4{0x1.7817bdd63251p+2, 0x1.28b44497c4416p+1};
    const Vec2<T> o5{0x1.7cd5b4bd96068p-1, 0x1.05113005b29dp+0},
        d5{-0x1.0743d1af8bacdp+2, -0x1.9f62c66e160b9p+0};
    expect_meet<T>(Line2<T>{o4, d4}, Line2<T>{o5, d5});
    expect_meet<T>(Line2<T>{o4, d4}, Ray2<T>{o5, d5});
  }
}

// Regression (LOCUS_TEST_SEED=2 of HarnessAndExactOracle3D, double, case 240): nearly parallel
// skew lines in 3D. The common perpendicular is at s ~ 1e8; Cramer's rule from dot products gave
// garbage there, so the projection of an origin (squared distance 9.7138363) won over the exact
// 9.71383612749. The minimiser now comes from accurately rounded 2x2 minors (the cross product):
// within k eps scale^2 of the exact squared distance, scale being the closest points' magnitude.
TYPED_TEST(LinearLinearTest, NearlyParallelSkewLinesMeetTheirCommonPerpendicularFarAway) {
  using T = TypeParam;
  if constexpr (std::is_same_v<T, double>) {
    const Line3<T> a{{-0x1.8302e252031a8p+1, 0x1.d6cd578f1845p-1, -0x1.7532afefc9428p-2},
                     {0x1.0cac0676d6212p-1, 0x1.6eda47016667cp+2, -0x1.0f4fbbf7545ecp-3}};
    const Line3<T> b{{-0x1.6764d0972f8c4p-1, -0x1.093748a399fb6p+1, -0x1.057dedccde83p+1},
                     {-0x1.7824090cbbb4bp-2, -0x1.00cbfe80f9beap+2, 0x1.7bd607273d4b3p-4}};
    const auto r = distance(a, b);
    const double exact = ex::sqr_linear_linear(q_of(a), q_of(b)).get_d();
    const T scale = std::max({T(8), max_abs(r.closest[0]), max_abs(r.closest[1])});
    EXPECT_GT(scale, T(1e7));  // the far crossing, not an origin's projection
    EXPECT_NEAR(r.sqr_distance, exact, tol<T>(64, scale * scale));
    const auto q = distance(b, a);
    EXPECT_EQ(q.sqr_distance, r.sqr_distance);
    EXPECT_EQ(q.closest[0], r.closest[1]);
  }
  // A ray and a line, a ray and a ray (float too): b's direction tilted towards a by 2^-20 in the
  // plane z = 1, so the common perpendicular (length 1) lies at s = 2^20 on both.
  const Ray3<T> ra{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}};
  const Ray3<T> rb{{T(0), T(1), T(1)}, {T(1), -T(0x1p-20), T(0)}};
  const auto rr = distance(ra, rb);
  const T s = std::max(max_abs(rr.closest[0]), max_abs(rr.closest[1]));
  EXPECT_NEAR(rr.sqr_distance, T(1), tol<T>(64, s * s));
  EXPECT_NEAR(rr.param_a, T(0x1p20), T(0x1p20) * T(1e-3));
  const auto rl = distance(Line3<T>{ra.origin, ra.direction}, rb);
  EXPECT_NEAR(rl.sqr_distance, T(1), tol<T>(64, s * s));
}

// Touching decided exactly (2D): a ray whose origin lies exactly on a nearly parallel line and
// turns away from it meets the line only at its origin (distance exactly 0, t = 0, the origin
// itself); moved off the line by one ulp of 1 it misses it by about that ulp (the exact
// distance), which the rounding of the candidates' points (~eps 2^k) alone could not tell from
// 0. Also segments: an end point exactly on the other, leaving it at an angle of ~1 ulp.
TYPED_TEST(LinearLinearTest, TouchingAtAnEndPointIsDecidedExactlyInThePlane) {
  using T = TypeParam;
  constexpr int k = std::is_same_v<T, float> ? 12 : 40;  // tilt 2^-k, 2^-2k on top
  const T tilt = std::ldexp(T(1), -k), tiny = std::ldexp(T(1), -2 * k);
  const Line2<T> line{{T(0), T(0)}, {T(1), tilt}};
  const Vec2<T> on{std::ldexp(T(1), k), T(1)};  // exactly on the line
  const Ray2<T> away{on, {T(1), tilt + tiny}};
  const auto r = distance(line, away);
  EXPECT_EQ(r.sqr_distance, T(0));
  EXPECT_EQ(r.param_b, T(0));
  EXPECT_EQ(r.closest[1], on);
  const Ray2<T> off{{on.x, std::nextafter(T(1), T(2))}, away.direction};
  const auto q = distance(line, off);
  const double exact = ex::sqr_linear_linear(q_of(line), q_of(off)).get_d();
  EXPECT_GT(exact, 0.0);
  EXPECT_GT(q.sqr_distance, T(0));
  EXPECT_NEAR(double(q.sqr_distance), exact, double(tol<T>(64, on.x * on.x)));
  // Segments: b starts exactly on a (2D) and leaves it at the tiny angle.
  const Segment2<T> a{{T(0), T(0)}, {std::ldexp(T(1), k + 1), T(2)}};
  const Segment2<T> b{on, {on.x + std::ldexp(T(1), k - 1), std::nextafter(T(1.5), T(2))}};
  ASSERT_EQ(ex::sqr_linear_linear(q_of(a), q_of(b)), 0);
  const auto sg = distance(a, b);
  EXPECT_EQ(sg.sqr_distance, T(0));
  EXPECT_EQ(sg.param_b, T(0));
  EXPECT_EQ(sg.closest[1], on);
  const auto gs = distance(b, a);
  EXPECT_EQ(gs.sqr_distance, T(0));
  EXPECT_EQ(gs.param_a, T(0));
  EXPECT_EQ(gs.closest[0], on);
}
