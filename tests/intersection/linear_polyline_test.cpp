// SPDX-License-Identifier: BSL-1.0
// Row int2.linear-polyline: a line, ray or segment against a polyline (open, closed) or a
// polygon boundary, float and double. Oracle: every edge against the component exactly in GMP
// rationals (linear_oracle.hpp), the pieces sorted by their exact parameter along the component
// and merged by the header's rule (a point at a position already reported, as a point or an
// overlap end, is dropped). Checks: the same pieces (kind, edge, order), each point within the
// linear pairs' bound of the exact one and overlap ends exact, parameters accurate
// (point_at on both arguments), the status; swapped overloads; intersects() agrees. Inputs:
// random chains, integer grids (lines through vertices, along edges, touching at vertices,
// repeated vertices), a square and its diagonals (counted by hand), NaN and empty input.

#include <locus/intersection/line_polygon.hpp>
#include <locus/intersection/line_polyline.hpp>
#include <locus/intersection/ray_polygon.hpp>
#include <locus/intersection/ray_polyline.hpp>
#include <locus/intersection/segment_polygon.hpp>
#include <locus/intersection/segment_polyline.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "intersection/linear_oracle.hpp"
#include "support/scale_covariance.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;
namespace ex = locus_test::exact2;

template <class T>
class IntersectionLinearPolyline : public ::testing::Test {};
TYPED_TEST_SUITE(IntersectionLinearPolyline, locus_test::RealTypes);

template <class P>
struct Make;
template <class T>
struct Make<Line2<T>> {
  static Line2<T> from(const Vec2<T>& p, const Vec2<T>& q) { return {p, q - p}; }
};
template <class T>
struct Make<Ray2<T>> {
  static Ray2<T> from(const Vec2<T>& p, const Vec2<T>& q) { return {p, q - p}; }
};
template <class T>
struct Make<Segment2<T>> {
  static Segment2<T> from(const Vec2<T>& p, const Vec2<T>& q) { return {p, q}; }
};

struct OraclePiece {
  ex::QResult r;
  std::size_t edge;
};

// The exact answer by the header's rule.
template <class T, class L>
std::vector<OraclePiece> oracle(const L& l, const std::vector<Vec2<T>>& v, bool closed) {
  std::vector<OraclePiece> pieces;
  const std::size_t m = std::max<std::size_t>(segment_count(v.size(), closed), 1);
  const ex::QLin ql = ex::ql(l);
  const bool point_component = ql.d.x == 0 && ql.d.y == 0;
  for (std::size_t i = 0; i < m; ++i) {
    const Segment2<T> e = v.size() == 1 ? Segment2<T>{v[0], v[0]} : edge(v, i);
    const ex::QResult r = ex::intersect(ql, ex::ql(e));
    if (r.kind == ex::QKind::empty) continue;
    pieces.push_back({r, i});
    if (point_component) return pieces;
  }
  std::stable_sort(pieces.begin(), pieces.end(), [](const OraclePiece& a, const OraclePiece& b) {
    if (a.r.ta[0] != b.r.ta[0]) return a.r.ta[0] < b.r.ta[0];
    if (a.r.kind != b.r.kind) return a.r.kind == ex::QKind::segment;
    return a.edge < b.edge;
  });
  std::vector<OraclePiece> kept;
  for (const OraclePiece& p : pieces) {
    if (p.r.kind == ex::QKind::point && !kept.empty()) {
      const ex::QResult& last = kept.back().r;
      if (last.ta[0] == p.r.ta[0] || last.ta[last.count - 1] == p.r.ta[0]) continue;
    }
    kept.push_back(p);
  }
  return kept;
}

template <class P>
std::string describe(const P& p) {
  char b[256];
  if constexpr (requires { p.p0; })
    std::snprintf(b, sizeof b, "segment (%.9g, %.9g) (%.9g, %.9g)", double(p.p0.x), double(p.p0.y),
                  double(p.p1.x), double(p.p1.y));
  else
    std::snprintf(b, sizeof b, "origin (%.9g, %.9g) direction (%.9g, %.9g)", double(p.origin.x),
                  double(p.origin.y), double(p.direction.x), double(p.direction.y));
  return b;
}

template <class T, class L>
double coord_max(const L& l, const std::vector<Vec2<T>>& v) {
  double m = 0;
  for (const auto& p : v) m = std::max(m, double(max_abs(p)));
  if constexpr (requires { l.p0; })
    return std::max({m, double(max_abs(l.p0)), double(max_abs(l.p1))});
  else
    return std::max(m, double(max_abs(l.origin)));
}

template <class T, class L>
void check(const L& l, const std::vector<Vec2<T>>& v, bool closed, int* pieces_seen = nullptr) {
  SCOPED_TRACE(describe(l) + (closed ? " closed" : " open") + ", " + std::to_string(v.size()) +
               " vertices");
  const Polyline2<T> poly{v, closed};
  const PolylineIntersection2<T> r = intersection(l, poly);
  ASSERT_EQ(r.status, Status::ok);
  const std::vector<OraclePiece> e = oracle(l, v, closed);
  EXPECT_EQ(intersects(l, poly), !e.empty());
  EXPECT_EQ(intersects(poly, l), !e.empty());
  ASSERT_EQ(r.crossings.size(), e.size());
  if (pieces_seen) *pieces_seen += static_cast<int>(e.size());
  const double eps = double(eps_v<T>);
  const double m = coord_max(l, v);
  const ex::QLin ql = ex::ql(l);
  const double dl = std::max(std::abs(ql.d.x.get_d()), std::abs(ql.d.y.get_d()));
  for (std::size_t k = 0; k < e.size(); ++k) {
    SCOPED_TRACE("piece " + std::to_string(k));
    const PolylineCrossing2<T>& c = r.crossings[k];
    const ex::QResult& q = e[k].r;
    EXPECT_EQ(c.edge, e[k].edge);
    ASSERT_EQ(c.kind, q.kind == ex::QKind::point ? Kind::point : Kind::segment);
    ASSERT_EQ(c.count, q.count);
    for (int i = 0; i < q.count; ++i) {
      const std::size_t s = static_cast<std::size_t>(i);
      ASSERT_TRUE(is_finite(c.point[s]) && std::isfinite(c.param_a[s]) &&
                  std::isfinite(c.param_b[s]));
      const double bound =
          6 * eps * std::max({m, std::abs(q.point[i].x.get_d()), std::abs(q.point[i].y.get_d())});
      const double pe =
          std::max(std::abs(mpq_class(mpq_class(double(c.point[s].x)) - q.point[i].x).get_d()),
                   std::abs(mpq_class(mpq_class(double(c.point[s].y)) - q.point[i].y).get_d()));
      EXPECT_LE(pe, bound);
      if (q.kind == ex::QKind::segment) {
        EXPECT_EQ(pe, 0.0);
      }
      EXPECT_LE(std::abs(mpq_class(mpq_class(double(c.param_a[s])) - q.ta[i]).get_d()) * dl, bound);
      EXPECT_TRUE(
          locus_test::vec_near(point_at(l, c.param_a[s]), c.point[s], T(8 * eps * m + 8 * eps)));
      EXPECT_TRUE(
          locus_test::vec_near(point_at(poly, c.param_b[s]), c.point[s], T(8 * eps * m + 8 * eps)));
    }
    if (k > 0) {
      EXPECT_LE(r.crossings[k - 1].param_a[0], c.param_a[0]);
    }
  }
  const PolylineIntersection2<T> s = intersection(poly, l);
  ASSERT_EQ(s.crossings.size(), r.crossings.size());
  for (std::size_t k = 0; k < s.crossings.size(); ++k) {
    EXPECT_EQ(s.crossings[k].param_a, r.crossings[k].param_b);
    EXPECT_EQ(s.crossings[k].param_b, r.crossings[k].param_a);
    EXPECT_EQ(s.crossings[k].point, r.crossings[k].point);
  }
  if (closed && v.size() >= 3) {
    // The polygon boundary is the closed chain.
    const Polygon2<T> pg{v};
    const PolylineIntersection2<T> g = intersection(l, pg);
    ASSERT_EQ(g.crossings.size(), r.crossings.size());
    for (std::size_t k = 0; k < g.crossings.size(); ++k) {
      EXPECT_EQ(g.crossings[k].point, r.crossings[k].point);
      EXPECT_EQ(g.crossings[k].edge, r.crossings[k].edge);
    }
    EXPECT_EQ(intersects(l, pg), !e.empty());
  }
}

template <class T, class F>
void for_each_linear(F&& f) {
  f.template operator()<Line2<T>>();
  f.template operator()<Ray2<T>>();
  f.template operator()<Segment2<T>>();
}

TYPED_TEST(IntersectionLinearPolyline, RandomChains) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int seen = 0;
  for_each_linear<T>([&]<class L>() {
    for (int i = 0; i < 400; ++i) {
      std::vector<Vec2<T>> v(static_cast<std::size_t>(rng.uniform_int(1, 12)));
      for (auto& p : v) p = rng.vec<T, 2>(-1, 1);
      const L l = Make<L>::from(rng.vec<T, 2>(-1, 1), rng.vec<T, 2>(-1, 1));
      check<T>(l, v, i % 2 == 0, &seen);
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(seen, 1000);
}

// Vertices and components on a small integer grid: lines through vertices (one piece per
// vertex), along edges (segments), touching at a vertex, repeated vertices, zero directions.
TYPED_TEST(IntersectionLinearPolyline, IntegerGridDegeneracies) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int seen = 0;
  for_each_linear<T>([&]<class L>() {
    for (int i = 0; i < 1500; ++i) {
      const auto g = [&] { return Vec2<T>{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2))}; };
      std::vector<Vec2<T>> v(static_cast<std::size_t>(rng.uniform_int(1, 8)));
      for (auto& p : v) p = g();
      const L l = Make<L>::from(g(), g());
      check<T>(l, v, i % 2 == 0, &seen);
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(seen, 3000);
}

// The unit square (counter-clockwise) and lines counted by hand: a diagonal meets the boundary
// at two vertices (each once, though two edges contain it); a line along the bottom edge
// overlaps it (a segment) and touches nothing else; a line through one corner only touches it.
TYPED_TEST(IntersectionLinearPolyline, SquareCountedByHand) {
  using T = TypeParam;
  const Polygon2<T> sq{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const auto diag = intersection(Line2<T>{{-1, -1}, {1, 1}}, sq);
  ASSERT_EQ(diag.crossings.size(), 2u);
  EXPECT_EQ(diag.crossings[0].point[0], (Vec2<T>{0, 0}));
  EXPECT_EQ(diag.crossings[0].edge, 0u);
  EXPECT_EQ(diag.crossings[1].point[0], (Vec2<T>{1, 1}));
  EXPECT_EQ(diag.crossings[1].edge, 1u);
  EXPECT_EQ(diag.crossings[1].param_b[0], T(2));  // vertex 2 at vertex parameter 2
  const auto bottom = intersection(Line2<T>{{5, 0}, {-2, 0}}, sq);
  ASSERT_EQ(bottom.crossings.size(), 1u);
  EXPECT_EQ(bottom.crossings[0].kind, Kind::segment);
  EXPECT_EQ(bottom.crossings[0].point[0], (Vec2<T>{1, 0}));  // ordered along the line (-x)
  EXPECT_EQ(bottom.crossings[0].point[1], (Vec2<T>{0, 0}));
  const auto corner = intersection(Line2<T>{{1, 1}, {1, -1}}, sq);
  ASSERT_EQ(corner.crossings.size(), 1u);
  EXPECT_EQ(corner.crossings[0].point[0], (Vec2<T>{1, 1}));
  const auto mid = intersection(Segment2<T>{{0.5, -1}, {0.5, 0.5}}, sq);  // ends inside
  ASSERT_EQ(mid.crossings.size(), 1u);
  EXPECT_EQ(mid.crossings[0].point[0], (Vec2<T>{0.5, 0}));
  for (const auto& [l, v, c] : {std::tuple{Line2<T>{{-1, -1}, {1, 1}}, sq.vertices, true}})
    check<T>(l, v, c);
}

// Many edges through (the rounding of) one point X on the component: their crossings lie within
// a few ulps of each other, below the rounding of their parameters, so only the exact comparison
// orders them as the oracle does (and recognises the exact ties).
TYPED_TEST(IntersectionLinearPolyline, NearTiesOrderedExactly) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for_each_linear<T>([&]<class L>() {
    for (int i = 0; i < 300; ++i) {
      const Vec2<double> x{rng.uniform<double>(-1, 1), rng.uniform<double>(-1, 1)};
      const double phi = rng.uniform<double>(0, 3.14159);
      const Vec2<double> u{std::cos(phi), std::sin(phi)};
      const L l = Make<L>::from(vec_cast<T>(x - 0.7 * u), vec_cast<T>(x + 0.9 * u));
      std::vector<Vec2<T>> v;
      for (int k = 0; k < 8; ++k) {
        const double psi = phi + rng.uniform<double>(0.2, 2.9);
        const Vec2<double> w{std::cos(psi), std::sin(psi)};
        v.push_back(vec_cast<T>(x + rng.uniform<double>(0.1, 1) * w));
        v.push_back(i % 4 == 0 ? vec_cast<T>(x) : vec_cast<T>(x - rng.uniform<double>(0.1, 1) * w));
      }
      check<T>(l, v, i % 2 == 0);
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
}

// Coordinates near the ends of the exponent range: random chains and integer-grid chains scaled
// by 2^k still match the oracle (each pair rescales; the ordering predicate is exact for any
// finite input).
TYPED_TEST(IntersectionLinearPolyline, FarExponents) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for_each_linear<T>([&]<class L>() {
    for (const int k : locus_test::far_scale_exponents<T>()) {
      for (int i = 0; i < 60; ++i) {
        std::vector<Vec2<T>> v(static_cast<std::size_t>(rng.uniform_int(2, 8)));
        for (auto& p : v)
          p = i % 2 ? rng.vec<T, 2>(-1, 1)
                    : Vec2<T>{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2))};
        const Vec2<T> p = i % 2 ? rng.vec<T, 2>(-1, 1) : Vec2<T>{T(rng.uniform_int(-2, 2)), T(0)};
        const Vec2<T> q = i % 2 ? rng.vec<T, 2>(-1, 1) : Vec2<T>{T(rng.uniform_int(-2, 2)), T(1)};
        check<T>(Make<L>::from(locus_test::scaled(p, k), locus_test::scaled(q, k)),
                 locus_test::scaled(v, k), i % 3 == 0);
        if (::testing::Test::HasFatalFailure()) return;
      }
    }
  });
}

TYPED_TEST(IntersectionLinearPolyline, BadInput) {
  using T = TypeParam;
  const Line2<T> l{{0, 0}, {1, 1}};
  EXPECT_EQ(intersection(l, Polyline2<T>{}).status, Status::empty_input);
  EXPECT_FALSE(intersects(l, Polyline2<T>{}));
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  for (const T b : {nan, inf}) {
    const Polyline2<T> p{{{-1, 0}, {1, b}, {2, 2}}, false};
    const auto r = intersection(l, p);
    EXPECT_EQ(r.status, Status::non_finite_input);
    EXPECT_TRUE(r.crossings.empty());
    EXPECT_FALSE(intersects(l, p));
    const Polyline2<T> ok{{{-1, 0}, {1, 0}}, false};
    const auto s = intersection(Line2<T>{{0, b}, {1, 1}}, ok);
    EXPECT_EQ(s.status, Status::non_finite_input);
    EXPECT_FALSE(intersects(Line2<T>{{0, b}, {1, 1}}, ok));
  }
}

}  // namespace
