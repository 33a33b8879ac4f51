// SPDX-License-Identifier: BSL-1.0
// The BSP tree of a polygon (bsp/bsp2.hpp). Oracles: point classification against the exact
// even-odd point-in-polygon of containment/point_in_polygon.hpp (random points, vertices, edge
// midpoints, points on the extended edge lines); segment partition in GMP rationals: the
// pieces' exact ends (from their definitions) increase strictly from s0 to s1, and each
// piece's exact midpoint is inside / outside / on an edge of the stated direction, decided by
// a rational crossing-number test written here. Both constructions, float and double, star
// polygons with holes, the earcut corpus, figure-like cases, bad input, 2^k scaling.

#include <locus/bsp/bsp2.hpp>
#include <locus/containment/point_in_polygon.hpp>

#include "support/typed.hpp"
#include "triangulate/polygons.hpp"
#include "triangulate/triangulation_check.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace {

using locus::Bsp2;
using locus::Bsp2Location;
using locus::Bsp2Split;
using locus::Side;
using locus::Status;
using locus::Vec2;
using locus_test::Polygon;

template <class T>
class Bsp2Test : public ::testing::Test {};
TYPED_TEST_SUITE(Bsp2Test, locus_test::RealTypes);

template <class T>
locus::PolygonWithHoles2<T> as_region(const Polygon<T>& p) {
  locus::PolygonWithHoles2<T> r;
  std::uint32_t b = 0;
  for (std::size_t k = 0; k < p.ends.size(); ++k) {
    locus::Polygon2<T> ring{{p.points.begin() + b, p.points.begin() + p.ends[k]}};
    if (k == 0)
      r.outer = ring;
    else
      r.holes.push_back(ring);
    b = p.ends[k];
  }
  return r;
}

struct Q2 {
  mpq_class x, y;
};
template <class T>
Q2 q2(const Vec2<T>& p) {
  return {mpq_class(double(p.x)), mpq_class(double(p.y))};
}
mpq_class orient(const Q2& a, const Q2& b, const Q2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// Exact even-odd classification of a rational point: -1 outside, 0 on an edge, 1 inside; and
/// through `dir` the direction sign (+1 same, -1 opposite to d) of an edge containing m, each
/// edge oriented with the interior on its left (ring orientation from its exact area).
template <class T>
std::vector<int> ring_flips(const Polygon<T>& p) {
  std::vector<int> flips;
  std::uint32_t b = 0;
  for (std::size_t k = 0; k < p.ends.size(); ++k) {
    const int ccw = sgn(locus_test::twice_ring_area<T>(p.points, b, p.ends[k]));
    flips.push_back((k == 0) == (ccw > 0) ? 1 : -1);
    b = p.ends[k];
  }
  return flips;
}

template <class T>
int classify_q(const Polygon<T>& p, const std::vector<int>& flips, const Q2& m, const Q2& d,
               int* dir) {
  bool in = false;
  std::uint32_t b = 0;
  for (std::size_t k = 0; k < p.ends.size(); ++k) {
    const std::uint32_t e = p.ends[k];
    const int flip = flips[k];
    for (std::uint32_t i = b; i < e; ++i) {
      const Q2 a = q2(p.points[i]), c = q2(p.points[i + 1 == e ? b : i + 1]);
      if (orient(a, c, m) == 0 && (a.x - m.x) * (c.x - m.x) <= 0 &&
          (a.y - m.y) * (c.y - m.y) <= 0 && (a.x != c.x || a.y != c.y)) {
        if (dir) {
          const mpq_class dot = (c.x - a.x) * d.x + (c.y - a.y) * d.y;
          *dir = flip * sgn(dot);
        }
        return 0;
      }
      if ((a.y > m.y) != (c.y > m.y)) {
        const mpq_class o = orient(a, c, m);
        if ((c.y > a.y) == (o > 0)) in = !in;
      }
    }
    b = e;
  }
  return in ? 1 : -1;
}

Side side_of(int c) { return c > 0 ? Side::inside : (c < 0 ? Side::outside : Side::boundary); }

template <class T>
void check_points(const Polygon<T>& p, const Bsp2<T>& tree, locus_test::Rng& rng, int count) {
  const auto region = as_region(p);
  std::vector<Vec2<T>> probes;
  T lo = p.points[0].x, hi = lo;
  for (const auto& v : p.points) {
    lo = std::min({lo, v.x, v.y});
    hi = std::max({hi, v.x, v.y});
  }
  for (int i = 0; i < count; ++i)
    probes.push_back({locus_test::snap<T>(rng.uniform(double(lo), double(hi))),
                      locus_test::snap<T>(rng.uniform(double(lo), double(hi)))});
  std::uint32_t b = 0;
  for (const std::uint32_t e : p.ends) {
    for (std::uint32_t i = b; i < e; ++i) {
      const Vec2<T> a = p.points[i], c = p.points[i + 1 == e ? b : i + 1];
      probes.push_back(a);
      probes.push_back((a + c) * T(0.5));
      probes.push_back(c * T(2) - a);  // on the extended edge line
    }
    b = e;
  }
  const std::vector<int> flips = ring_flips(p);
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const Vec2<T> q = probes[i];
    if (!locus::is_finite(q)) continue;
    const Side expect = locus::classify(q, region);
    ASSERT_EQ(tree.classify(q), expect) << q.x << " " << q.y;
    // The rational oracle of the partition test, validated on a few points.
    if (i % 16 == 0) {
      ASSERT_EQ(side_of(classify_q(p, flips, q2(q), {0, 0}, nullptr)), expect);
    }
  }
}

template <class T>
Q2 end_q(const Bsp2<T>& tree, const locus::Bsp2End<T>& e, const Vec2<T>& s0, const Vec2<T>& s1) {
  if (e.line == locus::bsp2_none) return q2(e.point);
  const auto ed = tree.edges()[e.line];
  const Q2 a = q2(tree.points()[ed[0]]), b = q2(tree.points()[ed[1]]);
  const Q2 p = q2(s0), q = q2(s1);
  // p + t (q - p) on the line a b: t = orient(a, b, p) / (orient(a, b, p) - orient(a, b, q)).
  const mpq_class op = orient(a, b, p), oq = orient(a, b, q);
  const mpq_class t = op / (op - oq);
  return {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
}

template <class T>
void check_partition(const Polygon<T>& p, const Bsp2<T>& tree, const Vec2<T>& s0,
                     const Vec2<T>& s1) {
  const auto r = tree.partition(s0, s1);
  const std::vector<int> flips = ring_flips(p);
  std::ostringstream trace;
  trace.precision(17);
  trace << "segment (" << s0.x << ", " << s0.y << ") (" << s1.x << ", " << s1.y << ")";
  for (const auto& pc : r.pieces)
    trace << " [" << pc.end[0].point.x << " " << pc.end[0].point.y << " L" << int(pc.end[0].line)
          << " - " << pc.end[1].point.x << " " << pc.end[1].point.y << " L" << int(pc.end[1].line)
          << ": " << int(pc.location) << "]";
  SCOPED_TRACE(trace.str());
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_FALSE(r.pieces.empty());
  const Q2 qs0 = q2(s0), qs1 = q2(s1), d{qs1.x - qs0.x, qs1.y - qs0.y};
  const auto param = [&](const Q2& x) {
    EXPECT_EQ(orient(qs0, qs1, x), 0);  // every end lies on the segment's line
    return d.x != 0 ? mpq_class((x.x - qs0.x) / d.x) : mpq_class((x.y - qs0.y) / d.y);
  };
  mpq_class last = 0;
  const auto& first = r.pieces.front().end[0];
  EXPECT_TRUE(first.line == locus::bsp2_none && first.point == s0);
  const auto& end = r.pieces.back().end[1];
  EXPECT_TRUE(end.line == locus::bsp2_none && end.point == s1);
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const auto& piece = r.pieces[i];
    const Q2 a = end_q(tree, piece.end[0], s0, s1), b = end_q(tree, piece.end[1], s0, s1);
    const mpq_class ta = param(a), tb = param(b);
    ASSERT_EQ(ta, last) << "piece " << i << " does not start where the previous one ends";
    ASSERT_LT(ta, tb) << "piece " << i;
    last = tb;
    if (i > 0) {
      EXPECT_NE(piece.location, r.pieces[i - 1].location);
    }
    const Q2 m{(a.x + b.x) / 2, (a.y + b.y) / 2};
    int dir = 0;
    int c = classify_q(p, flips, m, d, &dir);
    if (c == 0 &&
        (piece.location == Bsp2Location::inside || piece.location == Bsp2Location::outside)) {
      // The midpoint hit a vertex the piece passes through (a touching point, not a piece):
      // the points at 1/3 and 2/3 decide.
      const Q2 m1{(2 * a.x + b.x) / 3, (2 * a.y + b.y) / 3},
          m2{(a.x + 2 * b.x) / 3, (a.y + 2 * b.y) / 3};
      c = classify_q(p, flips, m1, d, nullptr);
      ASSERT_EQ(classify_q(p, flips, m2, d, nullptr), c);
    }
    switch (piece.location) {
      case Bsp2Location::inside:
        ASSERT_EQ(c, 1) << "piece " << i;
        break;
      case Bsp2Location::outside:
        ASSERT_EQ(c, -1) << "piece " << i;
        break;
      case Bsp2Location::coincident_same:
        ASSERT_EQ(c, 0);
        ASSERT_EQ(dir, 1);
        break;
      case Bsp2Location::coincident_opposite:
        ASSERT_EQ(c, 0);
        ASSERT_EQ(dir, -1);
        break;
    }
  }
  ASSERT_EQ(last, 1);
}

template <class T>
void check_segments(const Polygon<T>& p, const Bsp2<T>& tree, locus_test::Rng& rng, int count) {
  const auto n = static_cast<int>(p.points.size());
  for (int i = 0; i < count; ++i) {
    Vec2<T> a = p.points[static_cast<std::size_t>(rng.uniform_int(0, n - 1))];
    Vec2<T> b = p.points[static_cast<std::size_t>(rng.uniform_int(0, n - 1))];
    switch (i % 4) {
      case 0:  // random grid points
        a = {locus_test::snap<T>(rng.uniform(-1.2, 1.2)),
             locus_test::snap<T>(rng.uniform(-1.2, 1.2))};
        b = {locus_test::snap<T>(rng.uniform(-1.2, 1.2)),
             locus_test::snap<T>(rng.uniform(-1.2, 1.2))};
        break;
      case 1: {  // along an edge, extended both ways (coincident pieces)
        const std::size_t k = static_cast<std::size_t>(rng.uniform_int(0, n - 2));
        const Vec2<T> u = p.points[k], v = p.points[k + 1];
        a = u * T(2) - v;
        b = v * T(3) - u * T(2);
        break;
      }
      case 2:
        break;  // vertex to vertex
      default:
        b = b * T(2) - a;  // through a vertex
    }
    if (a == b) continue;
    check_partition(p, tree, a, b);
  }
}

template <class T>
std::vector<Polygon<T>> star_cases(locus_test::Rng& rng) {
  std::vector<Polygon<T>> out;
  // With 12 vertices or more every edge stays beyond radius 0.44, clear of the holes.
  for (int k = 0; k < 6; ++k) {
    const int holes = rng.uniform_int(0, 3);
    out.push_back(
        locus_test::star_polygon<T>(rng, rng.uniform_int(holes ? 12 : 3, 40), 0.5, 1.0, holes));
  }
  Polygon<T> framed;  // a square with a square hole: many collinear edges
  framed.add_ring({{0, 0}, {T(0.5), 0}, {1, 0}, {1, 1}, {0, 1}});
  framed.add_ring({{T(0.25), T(0.25)}, {T(0.25), T(0.75)}, {T(0.75), T(0.75)}, {T(0.75), T(0.25)}});
  out.push_back(framed);
  out.push_back(locus_test::comb_polygon<T>(rng, 6));
  return out;
}

TYPED_TEST(Bsp2Test, ClassifyMatchesPointInPolygon) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const auto& p : star_cases<T>(rng)) {
    for (const Bsp2Split split : {Bsp2Split::first_edge, Bsp2Split::balanced}) {
      const Bsp2<T> tree(p.points, p.ends, {split});
      ASSERT_EQ(tree.status(), Status::ok);
      // Every fragment lies on its edge's line, so no fragment is lost or invented: the
      // fragments of each edge have exact lengths that sum to the edge (checked via coverage of
      // the partition below); here, the classification.
      check_points(p, tree, rng, 60);
    }
  }
}

TYPED_TEST(Bsp2Test, SegmentPartitionIsExact) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 1);
  SCOPED_TRACE(rng.trace());
  for (const auto& p : star_cases<T>(rng)) {
    for (const Bsp2Split split : {Bsp2Split::first_edge, Bsp2Split::balanced}) {
      const Bsp2<T> tree(p.points, p.ends, {split});
      check_segments(p, tree, rng, 8);
    }
  }
}

TYPED_TEST(Bsp2Test, EarcutCorpus) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 2);
  SCOPED_TRACE(rng.trace());
  for (const char* name : {"building", "dude", "eberly-3", "boxy", "issue16"}) {
    SCOPED_TRACE(name);
    auto p = locus_test::earcut_fixture<double>(name);
    Polygon<T> pt;  // in float only fixtures whose coordinates are floats
    bool exact = true;
    for (const auto& v : p.points) {
      pt.points.push_back({T(v.x), T(v.y)});
      exact = exact && double(T(v.x)) == v.x && double(T(v.y)) == v.y;
    }
    pt.ends = p.ends;
    if (!exact) continue;
    const Bsp2<T> tree(pt.points, pt.ends);
    ASSERT_EQ(tree.status(), Status::ok);
    check_points(pt, tree, rng, 100);
  }
}

TYPED_TEST(Bsp2Test, BalancedIsShallowerThanFirstEdge) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 3);
  SCOPED_TRACE(rng.trace());
  const auto p = locus_test::star_polygon<T>(rng, 160, 0.5, 1.0);
  const Bsp2<T> basic(p.points, p.ends, {Bsp2Split::first_edge});
  const Bsp2<T> balanced(p.points, p.ends, {Bsp2Split::balanced});
  EXPECT_LT(balanced.depth(), basic.depth() / 4);
  EXPECT_LT(balanced.depth(), 60u);
  // Every edge is represented: the fragments of an edge are at least one.
  std::vector<int> seen(balanced.edges().size(), 0);
  for (const auto& f : balanced.fragments()) seen[f.edge] = 1;
  for (const int s : seen) EXPECT_EQ(s, 1);
  check_points(p, balanced, rng, 50);
}

TYPED_TEST(Bsp2Test, FigureSplitsAndCoincidentPieces) {
  using T = TypeParam;
  // A square with a notch (figures 13.1-13.12 style): the edge lines cut others.
  Polygon<T> p;
  p.add_ring({{0, 0}, {4, 0}, {4, 4}, {3, 4}, {3, 1}, {1, 1}, {1, 4}, {0, 4}});
  const Bsp2<T> tree(p.points, p.ends, {Bsp2Split::first_edge});
  ASSERT_EQ(tree.status(), Status::ok);
  EXPECT_GT(tree.fragments().size(), tree.edges().size());  // some edges were split
  // A segment along y = 4 from x = -1 to 5: the edges there, (4,4)-(3,4) and (1,4)-(0,4), run
  // in -x, so the pieces are outside, coincident_opposite, outside, coincident_opposite, outside.
  const auto r = tree.partition({-1, 4}, {5, 4});
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.pieces.size(), 5u);
  const Bsp2Location o = Bsp2Location::outside, c = Bsp2Location::coincident_opposite;
  const Bsp2Location expect[5] = {o, c, o, c, o};
  for (int i = 0; i < 5; ++i) EXPECT_EQ(r.pieces[std::size_t(i)].location, expect[i]);
  check_partition(p, tree, Vec2<T>{-1, 4}, Vec2<T>{5, 4});
  check_partition(p, tree, Vec2<T>{5, 4}, Vec2<T>{-1, 4});
  check_partition(p, tree, Vec2<T>{-1, 0.5}, Vec2<T>{5, 2});
  check_partition(p, tree, Vec2<T>{2, -1}, Vec2<T>{2, 5});
  EXPECT_EQ(tree.classify({2, 2}), Side::outside);
  EXPECT_EQ(tree.classify({2, 1}), Side::boundary);
  EXPECT_EQ(tree.classify({2, T(0.5)}), Side::inside);
}

TYPED_TEST(Bsp2Test, ConstructionStatesArePrefixes) {
  using T = TypeParam;
  // max_nodes stops the construction (figures 13.4-13.8): the nodes built so far are those of
  // the full tree in the same order, and the pending lists hold every fragment not yet stored,
  // each edge's pending and stored pieces covering it once (their count adds up with the splits
  // still to come).
  locus_test::Rng rng(5);
  const Polygon<T> p = locus_test::star_polygon<T>(rng, 12, 2, 6, 1);
  for (const Bsp2Split split : {Bsp2Split::first_edge, Bsp2Split::balanced}) {
    locus::Bsp2Options o;
    o.split = split;
    const Bsp2<T> full(p.points, p.ends, o);
    ASSERT_EQ(full.status(), Status::ok);
    EXPECT_TRUE(full.pending().empty());
    for (std::uint32_t k = 1; k <= full.nodes().size(); ++k) {
      o.max_nodes = k;
      const Bsp2<T> part(p.points, p.ends, o);
      ASSERT_EQ(part.nodes().size(), k);
      for (std::uint32_t i = 0; i < k; ++i) {
        EXPECT_EQ(part.nodes()[i].edge, full.nodes()[i].edge);
        EXPECT_EQ(part.nodes()[i].count, full.nodes()[i].count);
      }
      EXPECT_EQ(part.pending().empty(), k == full.nodes().size());
      std::size_t pending = 0;
      for (const auto& l : part.pending()) {
        pending += l.count;
        const std::int32_t child = l.parent < 0 ? part.root()
                                   : l.front    ? part.nodes()[std::size_t(l.parent)].front
                                                : part.nodes()[std::size_t(l.parent)].back;
        EXPECT_EQ(child, locus::bsp2_pending);
      }
      EXPECT_EQ(pending, part.pending_fragments().size());
      EXPECT_LE(part.fragments().size() + pending, full.fragments().size());
    }
  }
}

TYPED_TEST(Bsp2Test, BadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  std::vector<Vec2<T>> sq{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::uint32_t e4[] = {4};
  Bsp2<T> tree;
  EXPECT_EQ(tree.build({}, {}), Status::empty_input);
  EXPECT_EQ(tree.classify({0, 0}), Side::outside);
  const std::uint32_t past[] = {5};
  EXPECT_EQ(tree.build(sq, past), Status::invalid_input);
  std::vector<Vec2<T>> line{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  EXPECT_EQ(tree.build(line, e4), Status::degenerate_input);
  EXPECT_EQ(tree.classify({1, 1}), Side::outside);
  auto bad = sq;
  bad[2].x = nan;
  EXPECT_EQ(tree.build(bad, e4), Status::non_finite_input);
  ASSERT_EQ(tree.build(sq, e4), Status::ok);
  EXPECT_EQ(tree.classify({nan, 0}), Side::outside);
  EXPECT_EQ(tree.partition({nan, 0}, {1, 1}).status, Status::non_finite_input);
  EXPECT_EQ(tree.partition({1, 1}, {1, 1}).status, Status::degenerate_input);
  // Repeated points and a spike are cleaned up.
  std::vector<Vec2<T>> spiky{{0, 0}, {1, 0}, {1, 0}, {2, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::uint32_t e7[] = {7};
  ASSERT_EQ(tree.build(spiky, e7), Status::ok);
  EXPECT_EQ(tree.classify({T(1.5), 0}), Side::outside);
  EXPECT_EQ(tree.classify({T(0.5), T(0.5)}), Side::inside);
}

TYPED_TEST(Bsp2Test, PowerOfTwoScaling) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 4);
  SCOPED_TRACE(rng.trace());
  const auto p = locus_test::star_polygon<T>(rng, 30, 0.5, 1.0, 2);
  const Bsp2<T> tree(p.points, p.ends);
  for (const T s : {T(0x1p-30), T(0x1p40)}) {
    auto q = p;
    for (auto& v : q.points) v = v * s;
    const Bsp2<T> scaled(q.points, q.ends);
    ASSERT_EQ(scaled.nodes().size(), tree.nodes().size());
    for (int i = 0; i < 200; ++i) {
      const Vec2<T> x{locus_test::snap<T>(rng.uniform(-1.0, 1.0)),
                      locus_test::snap<T>(rng.uniform(-1.0, 1.0))};
      ASSERT_EQ(scaled.classify(x * s), tree.classify(x));
    }
    const auto a = tree.partition({-1, T(0.25)}, {1, T(-0.125)});
    const auto b = scaled.partition(Vec2<T>{-1, T(0.25)} * s, Vec2<T>{1, T(-0.125)} * s);
    ASSERT_EQ(a.pieces.size(), b.pieces.size());
    for (std::size_t i = 0; i < a.pieces.size(); ++i)
      EXPECT_EQ(a.pieces[i].location, b.pieces[i].location);
  }
}

}  // namespace
