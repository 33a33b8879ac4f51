// SPDX-License-Identifier: BSL-1.0
// The generic intersection harness (harness.hpp) on 2D pairs (rows int2.linear,
// int2.linear-quadratic, int2.quadratic): seeded grid inputs leaning to the degenerate (shared
// end points, collinear overlaps, an end point on the other object, exact tangencies built from
// dyadic and 3-4-5 constructions), with the exact GMP oracles of linear_oracle.hpp and
// conic_oracle.hpp, and an exact circle-circle classification.

#include <locus/intersection/circle_circle.hpp>
#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/ellipse_ellipse.hpp>
#include <locus/intersection/line_segment.hpp>
#include <locus/intersection/ray_ray.hpp>
#include <locus/intersection/segment_circle.hpp>
#include <locus/intersection/segment_polyline.hpp>
#include <locus/intersection/segment_segment.hpp>

#include <gmpxx.h>

#include <optional>
#include <utility>

#include "intersection/conic_oracle.hpp"
#include "intersection/harness.hpp"
#include "intersection/linear_oracle.hpp"
#include "support/typed.hpp"

namespace {

using locus::Circle2;
using locus::Ellipse2;
using locus::Kind;
using locus::Line2;
using locus::Polyline2;
using locus::Ray2;
using locus::Segment2;
using locus::Triangle2;
using locus::Vec2;
using locus_test::Rng;
using locus_test::ix::check_intersection_pairs;
using locus_test::ix::Expected;
using locus_test::ix::grid;
using locus_test::ix::grid_vec;
using locus_test::ix::Options;

template <class T>
class IntersectionHarness2 : public ::testing::Test {};
TYPED_TEST_SUITE(IntersectionHarness2, locus_test::RealTypes);

/// Two point pairs (p0, p1), (q0, q1) on the grid, often degenerate: shared end point,
/// collinear (overlapping or not), an end point at the other's midpoint, parallel, zero length.
template <class T>
std::pair<std::array<Vec2<T>, 2>, std::array<Vec2<T>, 2>> linear_points(Rng& rng) {
  const Vec2<T> p0 = grid_vec<T, 2>(rng, -1, 1), p1 = grid_vec<T, 2>(rng, -1, 1);
  Vec2<T> q0 = grid_vec<T, 2>(rng, -1, 1), q1 = grid_vec<T, 2>(rng, -1, 1);
  const Vec2<T> d = (p1 - p0) / T(4);  // exact: the grid is fine enough
  switch (rng.uniform_int(0, 6)) {
    case 0:
      q0 = p0;
      break;  // shared end point
    case 1:
      q0 = p1;
      break;  // end to start
    case 2:   // collinear
      q0 = p0 + T(rng.uniform_int(-6, 6)) * d;
      q1 = p0 + T(rng.uniform_int(-6, 6)) * d;
      break;
    case 3:
      q0 = p0 + T(2) * d;
      break;  // end point at the midpoint
    case 4:
      q1 = q0 + T(rng.uniform_int(-4, 4)) * d;
      break;  // parallel
    case 5:
      q1 = q0;
      break;  // zero length
    default:
      break;  // generic
  }
  return {{p0, p1}, {q0, q1}};
}

template <class T>
Segment2<T> as_segment(const std::array<Vec2<T>, 2>& p) {
  return {p[0], p[1]};
}
template <class T>
Ray2<T> as_ray(const std::array<Vec2<T>, 2>& p) {
  return {p[0], p[1] - p[0]};
}
template <class T>
Line2<T> as_line(const std::array<Vec2<T>, 2>& p) {
  return {p[0], p[1] - p[0]};
}

template <class A, class B>
std::optional<Expected> linear_oracle(const A& a, const B& b) {
  namespace ex = locus_test::exact2;
  const ex::QResult q = ex::intersect(ex::ql(a), ex::ql(b));
  switch (q.kind) {
    case ex::QKind::empty:
      return Expected{Kind::empty, 0};
    case ex::QKind::point:
      return Expected{Kind::point, 1};
    case ex::QKind::segment:
      return Expected{Kind::segment, 2};
    case ex::QKind::ray:
      return Expected{Kind::ray, 2};
    case ex::QKind::line:
      return Expected{Kind::line, 2};
  }
  return std::nullopt;
}

TYPED_TEST(IntersectionHarness2, SegmentSegment) {
  using T = TypeParam;
  Options opt;
  opt.residual = 8;
  opt.exact_swap = false;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const auto pq = linear_points<T>(rng);
        return std::pair{as_segment(pq.first), as_segment(pq.second)};
      },
      opt, linear_oracle<Segment2<T>, Segment2<T>>);
}

TYPED_TEST(IntersectionHarness2, LineSegment) {
  using T = TypeParam;
  Options opt;
  opt.residual = 8;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const auto pq = linear_points<T>(rng);
        return std::pair{as_line(pq.first), as_segment(pq.second)};
      },
      opt, linear_oracle<Line2<T>, Segment2<T>>);
}

TYPED_TEST(IntersectionHarness2, RayRay) {
  using T = TypeParam;
  Options opt;
  opt.residual = 8;
  opt.exact_swap = false;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const auto pq = linear_points<T>(rng);
        return std::pair{as_ray(pq.first), as_ray(pq.second)};
      },
      opt, linear_oracle<Ray2<T>, Ray2<T>>);
}

/// A circle with radius 5 s (s on the grid), so that 3-4-5 offsets land exactly on it.
template <class T>
Circle2<T> grid_circle(Rng& rng) {
  return {grid_vec<T, 2>(rng, -1, 1), T(5) * T(rng.uniform_int(1, 64)) / T(256)};
}

TYPED_TEST(IntersectionHarness2, SegmentCircle) {
  using T = TypeParam;
  Options opt;
  opt.residual = 16;
  // Along the curve, a point near tangency is only sqrt(eps) accurate (segment_circle.hpp).
  opt.param = opt.position = std::is_same_v<T, float> ? 2e-3 : 1e-7;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const Circle2<T> c = grid_circle<T>(rng);
        const T s = c.radius / T(5);
        const Vec2<T> on{c.center.x + T(3) * s, c.center.y + T(4) * s};  // exactly on c
        Vec2<T> p0 = grid_vec<T, 2>(rng, -2, 2), p1 = grid_vec<T, 2>(rng, -2, 2);
        switch (rng.uniform_int(0, 5)) {
          case 0:
            p0 = on;
            break;   // an end point on the circle
          case 1: {  // tangent at (cx, cy + r): a horizontal segment
            const T y = c.center.y + c.radius;
            p0 = {c.center.x - T(rng.uniform_int(-8, 8)) / T(16), y};
            p1 = {c.center.x + T(rng.uniform_int(-8, 8)) / T(16), y};
            break;
          }
          case 2:
            p0 = c.center;
            break;   // from the centre
          case 3: {  // a chord between two exact points of the circle
            p0 = on;
            p1 = {c.center.x - T(4) * s, c.center.y - T(3) * s};
            break;
          }
          default:
            break;
        }
        return std::pair{Segment2<T>{p0, p1}, c};
      },
      opt,
      [](const Segment2<T>& a, const Circle2<T>& c) -> std::optional<Expected> {
        namespace co = locus_test::conic;
        const co::Q2 o = co::q(a.p0), e = co::q(a.p1);
        const co::QLin l{o, {e.x - o.x, e.y - o.y}, true, true};
        const co::LinAnswer ans = co::solve_linear_conic(co::conic_fun(c), l);
        // A zero-length segment is a point: "whole" when it lies on the circle.
        if (ans.whole) return Expected{Kind::point, 1};
        if (ans.count == 0) return Expected{Kind::empty, 0};
        return Expected{ans.count == 1 ? Kind::point : Kind::points, ans.count};
      });
}

TYPED_TEST(IntersectionHarness2, CircleCircle) {
  using T = TypeParam;
  Options opt;
  opt.residual = 16;
  opt.exact_swap = false;
  opt.param = opt.position = std::is_same_v<T, float> ? 2e-3 : 1e-7;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const Circle2<T> a = grid_circle<T>(rng);
        Circle2<T> b = grid_circle<T>(rng);
        const T s = T(rng.uniform_int(1, 32)) / T(256);
        switch (rng.uniform_int(0, 5)) {
          case 0:  // external tangency along a 3-4-5 direction
            b.radius = T(5) * s;
            b.center = a.center + ((a.radius + b.radius) / T(5)) * Vec2<T>{T(3), T(4)};
            break;
          case 1:  // internal tangency along an axis
            b.radius = a.radius + T(5) * s;
            b.center = {a.center.x + T(5) * s, a.center.y};
            break;
          case 2:
            b = a;
            break;  // coincident
          case 3:
            b.center = a.center;
            break;  // concentric
          default:
            break;
        }
        return std::pair{a, b};
      },
      opt,
      [](const Circle2<T>& a, const Circle2<T>& b) -> std::optional<Expected> {
        const mpq_class dx = mpq_class(double(b.center.x)) - mpq_class(double(a.center.x));
        const mpq_class dy = mpq_class(double(b.center.y)) - mpq_class(double(a.center.y));
        const mpq_class ra(double(a.radius)), rb(double(b.radius));
        const mpq_class d2 = dx * dx + dy * dy, sum = (ra + rb) * (ra + rb),
                        dif = (ra - rb) * (ra - rb);
        if (d2 == 0 && ra == rb) return Expected{Kind::coincident, 0};
        if (d2 > sum || d2 < dif) return Expected{Kind::empty, 0};
        if (d2 == sum || d2 == dif) return Expected{Kind::point, 1};
        return Expected{Kind::points, 2};
      });
}

/// An axis-aligned ellipse (axes a signed permutation of the unit axes, so the motions keep
/// them exact) with grid centre and extents k / 64.
template <class T>
Ellipse2<T> grid_ellipse(Rng& rng) {
  Ellipse2<T> e;
  e.center = grid_vec<T, 2>(rng, -1, 1);
  const T sx = rng.uniform_int(0, 1) ? T(1) : T(-1), sy = rng.uniform_int(0, 1) ? T(1) : T(-1);
  e.axis[0] = {sx, T(0)};
  e.axis[1] = {T(0), sy};
  if (rng.uniform_int(0, 1)) std::swap(e.axis[0], e.axis[1]);
  e.extent[0] = T(rng.uniform_int(4, 64)) / T(64);
  e.extent[1] = T(rng.uniform_int(4, 64)) / T(64);
  return e;
}

TYPED_TEST(IntersectionHarness2, EllipseEllipse) {
  using T = TypeParam;
  Options opt;
  // Points within about 2^-40 of the coordinates' magnitude (ellipse_ellipse.hpp): 4096 eps in
  // double; float results are that double answer rounded once.
  opt.residual = std::is_same_v<T, float> ? 16 : 4096;
  opt.cases = 80;  // tangencies take the big-integer path: ~1 ms a case optimised
  opt.exact_swap = false;
  // A tangent point's angle is only sqrt of the residual accurate.
  opt.param = opt.position = std::is_same_v<T, float> ? 2e-3 : 1e-5;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const Ellipse2<T> a = grid_ellipse<T>(rng);
        Ellipse2<T> b = grid_ellipse<T>(rng);
        // a's extents along x and y.
        const bool ax = a.axis[0].x != T(0);
        const T ex = ax ? a.extent[0] : a.extent[1], ey = ax ? a.extent[1] : a.extent[0];
        const bool bx = b.axis[0].x != T(0);
        const T fx = bx ? b.extent[0] : b.extent[1];
        switch (rng.uniform_int(0, 5)) {
          case 0:
            b.center = {a.center.x + ex + fx, a.center.y};
            break;  // outer tangency
          case 1:   // the same curve
            b.center = a.center;
            b.axis[0] = a.axis[1];
            b.axis[1] = a.axis[0];
            b.extent[0] = a.extent[1];
            b.extent[1] = a.extent[0];
            break;
          case 2:
            b.center = a.center;
            break;  // concentric: 0, 4 or a whole curve
          case 3:   // inner tangency at a's right-most point
            if (fx < ex) b.center = {a.center.x + ex - fx, a.center.y};
            break;
          case 4:
            b.center = {a.center.x, a.center.y + ey};
            break;  // through a's top point
          default:
            break;
        }
        return std::pair{a, b};
      },
      opt);
}

TYPED_TEST(IntersectionHarness2, TriangleTriangleSat) {
  using T = TypeParam;
  Options opt;
  opt.residual = 9;  // overlap vertices within 6 eps (convex_polygon2.hpp), inf-norm: 6 sqrt(2)
  opt.exact_swap = false;
  check_intersection_pairs<T>(
      [](Rng& rng) {
        const Triangle2<T> a{grid_vec<T, 2>(rng, -1, 1), grid_vec<T, 2>(rng, -1, 1),
                             grid_vec<T, 2>(rng, -1, 1)};
        Triangle2<T> b{grid_vec<T, 2>(rng, -1, 1), grid_vec<T, 2>(rng, -1, 1),
                       grid_vec<T, 2>(rng, -1, 1)};
        const Vec2<T> e1 = a.v1 - a.v0, e2 = a.v2 - a.v0;
        switch (rng.uniform_int(0, 4)) {
          case 0:
            b.v0 = a.v0;
            break;  // a shared vertex
          case 1:   // a shared edge, b on the other side or the same
            b.v0 = a.v1;
            b.v1 = a.v0;
            break;
          case 2:
            b.v0 = a.v0 + e1 / T(2);
            break;  // a vertex on an edge
          case 3:
            b = {a.v0 + e1 / T(4) + e2 / T(4), a.v1, a.v2};
            break;  // nested
          default:
            break;
        }
        return std::pair{a, b};
      },
      opt);
}

TYPED_TEST(IntersectionHarness2, SegmentPolyline) {
  using T = TypeParam;
  Options opt;
  opt.residual = 8;  // points within 6 eps max(|X|inf, m) (segment_polyline.hpp)
  check_intersection_pairs<T>(
      [](Rng& rng) {
        Polyline2<T> p;
        p.closed = rng.uniform_int(0, 2) == 0;
        const int n = rng.uniform_int(1, 6);
        for (int i = 0; i < n; ++i) p.vertices.push_back(grid_vec<T, 2>(rng, -1, 1));
        const Vec2<T> v = p.vertices[std::size_t(rng.uniform_int(0, n - 1))];
        const Vec2<T> w = p.vertices[std::size_t(rng.uniform_int(0, n - 1))];
        Vec2<T> p0 = grid_vec<T, 2>(rng, -1, 1), p1 = grid_vec<T, 2>(rng, -1, 1);
        switch (rng.uniform_int(0, 4)) {
          case 0:
            p0 = v;
            break;  // from a vertex
          case 1:   // through a vertex
            p1 = v + (v - p0);
            break;
          case 2:  // along an edge (or a chord between two vertices), overhanging
            p0 = v + (v - w) / T(4);
            p1 = w + (w - v) / T(4);
            break;
          case 3:
            p0 = (v + w) / T(2);
            break;  // from a point of a chord
          default:
            break;
        }
        return std::pair{Segment2<T>{p0, p1}, p};
      },
      opt);
}

}  // namespace
