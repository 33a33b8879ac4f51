// SPDX-License-Identifier: BSL-1.0
// Polygon booleans through BSP trees (bsp/bsp2_boolean.hpp). Oracles, all exact: the result's
// ends from their definitions in GMP rationals; the winding number of the result's edges at
// sampled points (not on an input edge) against op(inside A, inside B), where inside is an
// even-odd crossing count on the inputs with orient2d (no BSP tree); exact areas:
// |A u B| + |A n B| = |A| + |B|, |A \ B| = |A| - |A n B|, |A xor B| = |A u B| - |A n B|; loops
// closed and covering every edge. Figure configurations 13.27-13.31, A op A, shared edges,
// touching vertices, empty and non-finite operands, 2^k scaling.

#include <locus/bsp/bsp2.hpp>
#include <locus/bsp/bsp2_boolean.hpp>
#include <locus/core/predicates.hpp>

#include "support/typed.hpp"
#include "triangulate/polygons.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using locus::Bsp2;
using locus::Bsp2BooleanResult;
using locus::Bsp2Op;
using locus::Status;
using locus::Vec2;
using locus_test::Polygon;

template <class T>
class Bsp2BooleanTest : public ::testing::Test {};
TYPED_TEST_SUITE(Bsp2BooleanTest, locus_test::RealTypes);

constexpr Bsp2Op all_ops[] = {Bsp2Op::intersection, Bsp2Op::union_, Bsp2Op::difference,
                              Bsp2Op::exclusive_or};

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

/// The exact end x of result edge r (the header's definition).
template <class T>
Q2 exact_end(const Bsp2<T>& a, const Bsp2<T>& b, const locus::Bsp2BooleanEdge<T>& r,
             const locus::Bsp2End<T>& x) {
  if (x.line == locus::bsp2_none) return q2(x.point);
  const Bsp2<T>& own = r.operand == 0 ? a : b;
  const Bsp2<T>& other = r.operand == 0 ? b : a;
  const auto f = own.edges()[r.edge], g = other.edges()[x.line];
  const Q2 p = q2(own.points()[f[0]]), q = q2(own.points()[f[1]]);
  const Q2 ga = q2(other.points()[g[0]]), gb = q2(other.points()[g[1]]);
  const mpq_class op = orient(ga, gb, p), oq = orient(ga, gb, q);
  const mpq_class t = op / (op - oq);
  return {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
}

template <class T>
std::vector<std::array<Q2, 2>> exact_edges(const Bsp2<T>& a, const Bsp2<T>& b,
                                           const Bsp2BooleanResult<T>& r) {
  std::vector<std::array<Q2, 2>> out;
  for (const auto& e : r.edges)
    out.push_back({exact_end(a, b, e, e.end[0]), exact_end(a, b, e, e.end[1])});
  return out;
}

mpq_class twice_area(const std::vector<std::array<Q2, 2>>& edges) {
  mpq_class s = 0;
  for (const auto& e : edges) s += e[0].x * e[1].y - e[0].y * e[1].x;
  return s;
}

/// Winding number of closed edge chains around m (half-open crossing rule, exact).
int winding(const std::vector<std::array<Q2, 2>>& edges, const Q2& m) {
  int w = 0;
  for (const auto& e : edges) {
    const Q2 &p = e[0], &q = e[1];
    if (p.y <= m.y && m.y < q.y && orient(p, q, m) > 0) ++w;
    if (q.y <= m.y && m.y < p.y && orient(p, q, m) < 0) --w;
  }
  return w;
}

/// The input polygon's exact classification with orient2d: 1 inside, 0 on an edge, -1 outside.
template <class T>
int inside_input(const Polygon<T>& p, const Vec2<T>& m) {
  bool in = false;
  std::uint32_t b = 0;
  for (const std::uint32_t e : p.ends) {
    for (std::uint32_t i = b; i < e; ++i) {
      const Vec2<T> u = p.points[i], v = p.points[i + 1 == e ? b : i + 1];
      const locus::Sign o = locus::orient2d(u, v, m);
      if (o == locus::Sign::zero && std::min(u.x, v.x) <= m.x && m.x <= std::max(u.x, v.x) &&
          std::min(u.y, v.y) <= m.y && m.y <= std::max(u.y, v.y))
        return 0;
      if ((u.y > m.y) != (v.y > m.y) && (v.y > u.y) == (o == locus::Sign::positive)) in = !in;
    }
    b = e;
  }
  return in ? 1 : -1;
}

/// Whether the rings are simple and pairwise disjoint (no two non-adjacent edges meet).
template <class T>
bool valid_rings(const Polygon<T>& p) {
  struct E {
    Vec2<T> a, b;
    std::uint32_t i, j;
  };
  std::vector<E> edges;
  std::uint32_t b = 0;
  for (const std::uint32_t e : p.ends) {
    for (std::uint32_t i = b; i < e; ++i)
      edges.push_back({p.points[i], p.points[i + 1 == e ? b : i + 1], i, i + 1 == e ? b : i + 1});
    b = e;
  }
  const auto on = [](const Vec2<T>& u, const Vec2<T>& v, const Vec2<T>& m) {
    return locus::orient2d(u, v, m) == locus::Sign::zero && std::min(u.x, v.x) <= m.x &&
           m.x <= std::max(u.x, v.x) && std::min(u.y, v.y) <= m.y && m.y <= std::max(u.y, v.y);
  };
  for (std::size_t x = 0; x < edges.size(); ++x)
    for (std::size_t y = 0; y < x; ++y) {
      const E &e = edges[x], &f = edges[y];
      if (e.i == f.j || e.j == f.i) continue;
      const auto o1 = locus::orient2d(e.a, e.b, f.a), o2 = locus::orient2d(e.a, e.b, f.b);
      const auto o3 = locus::orient2d(f.a, f.b, e.a), o4 = locus::orient2d(f.a, f.b, e.b);
      if (o1 * o2 == locus::Sign::negative && o3 * o4 == locus::Sign::negative) return false;
      if (on(e.a, e.b, f.a) || on(e.a, e.b, f.b) || on(f.a, f.b, e.a) || on(f.a, f.b, e.b))
        return false;
    }
  return true;
}

bool apply(Bsp2Op op, bool a, bool b) {
  switch (op) {
    case Bsp2Op::intersection:
      return a && b;
    case Bsp2Op::union_:
      return a || b;
    case Bsp2Op::difference:
      return a && !b;
    case Bsp2Op::exclusive_or:
      return a != b;
  }
  return false;
}

/// Every edge is in exactly one loop, and each loop is chained end to start (exactly).
template <class T>
void check_loops(const Bsp2BooleanResult<T>& r, const std::vector<std::array<Q2, 2>>& ex) {
  ASSERT_TRUE(r.closed);
  ASSERT_EQ(r.loop_edges.size(), r.edges.size());
  std::vector<int> seen(r.edges.size(), 0);
  std::uint32_t b = 0;
  for (const std::uint32_t e : r.loop_ends) {
    ASSERT_LT(b, e);
    for (std::uint32_t i = b; i < e; ++i) {
      const std::uint32_t cur = r.loop_edges[i], next = r.loop_edges[i + 1 == e ? b : i + 1];
      ++seen[cur];
      ASSERT_TRUE(ex[cur][1].x == ex[next][0].x && ex[cur][1].y == ex[next][0].y);
    }
    b = e;
  }
  for (const int s : seen) ASSERT_EQ(s, 1);
}

template <class T>
struct Case {
  Polygon<T> a, b;
  Bsp2<T> ta, tb;
  Case(Polygon<T> pa, Polygon<T> pb)
      : a(std::move(pa)), b(std::move(pb)), ta(a.points, a.ends), tb(b.points, b.ends) {}
};

/// All four operations checked against the oracles; returns twice the exact areas.
template <class T>
void check_all_into(const Case<T>& c, const std::vector<Vec2<T>>& probes,
                    std::array<mpq_class, 4>& area) {
  for (int k = 0; k < 4; ++k) {
    const Bsp2Op op = all_ops[k];
    SCOPED_TRACE("op " + std::to_string(k));
    const auto r = locus::bsp2_boolean(op, c.ta, c.tb);
    EXPECT_EQ(r.status, Status::ok);
    const auto ex = exact_edges(c.ta, c.tb, r);
    check_loops(r, ex);
    area[std::size_t(k)] = twice_area(ex);
    for (const Vec2<T>& m : probes) {
      const int ia = inside_input(c.a, m), ib = inside_input(c.b, m);
      if (ia == 0 || ib == 0) continue;
      const int w = winding(ex, q2(m));
      ASSERT_EQ(w, apply(op, ia > 0, ib > 0) ? 1 : 0) << m.x << " " << m.y;
    }
  }
}
template <class T>
std::array<mpq_class, 4> check_all(const Case<T>& c, const std::vector<Vec2<T>>& probes) {
  std::array<mpq_class, 4> area;
  check_all_into(c, probes, area);
  return area;
}

template <class T>
mpq_class input_area(const Polygon<T>& p) {
  // Twice the area with holes counted negative, whatever the rings' orientation.
  mpq_class s = 0;
  std::uint32_t b = 0;
  for (std::size_t k = 0; k < p.ends.size(); ++k) {
    mpq_class r = 0;
    for (std::uint32_t i = b; i < p.ends[k]; ++i) {
      const Q2 u = q2(p.points[i]), v = q2(p.points[i + 1 == p.ends[k] ? b : i + 1]);
      r += u.x * v.y - u.y * v.x;
    }
    s += (k == 0 ? 1 : -1) * abs(r);
    b = p.ends[k];
  }
  return s;
}

template <class T>
void check_areas(const Case<T>& c, const std::array<mpq_class, 4>& area) {
  const mpq_class aa = input_area(c.a), ab = input_area(c.b);
  EXPECT_EQ(area[1] + area[0], aa + ab);
  EXPECT_EQ(area[2], aa - area[0]);
  EXPECT_EQ(area[3], area[1] - area[0]);
}

template <class T>
Polygon<T> ring(std::initializer_list<Vec2<T>> pts) {
  Polygon<T> p;
  p.add_ring(std::vector<Vec2<T>>(pts));
  return p;
}

template <class T>
std::vector<Vec2<T>> grid_probes(T lo, T hi, int n) {
  std::vector<Vec2<T>> out;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      out.push_back({lo + (hi - lo) * T(i + 0.37) / T(n), lo + (hi - lo) * T(j + 0.61) / T(n)});
  return out;
}

TYPED_TEST(Bsp2BooleanTest, Figure13_27TwoTriangles) {
  using T = TypeParam;
  const Case<T> c(ring<T>({{0, 0}, {6, 0}, {3, 6}}), ring<T>({{0, 4}, {3, -2}, {6, 4}}));
  const auto area = check_all(c, grid_probes<T>(-1, 7, 24));
  check_areas(c, area);
  const auto r = locus::bsp2_boolean(Bsp2Op::intersection, c.ta, c.tb);
  EXPECT_EQ(r.edges.size(), 6u);  // a hexagon: one piece of each of the six edges
  EXPECT_EQ(r.loop_ends.size(), 1u);
  EXPECT_TRUE(r.segments.empty());
  EXPECT_TRUE(r.points.empty());
}

TYPED_TEST(Bsp2BooleanTest, OneCallFormOnAnyRange) {
  using T = TypeParam;
  const std::vector<Vec2<T>> a{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const std::array<Vec2<T>, 3> b{{{2, 2}, {6, 2}, {2, 6}}};
  const std::uint32_t ea[] = {4}, eb[] = {3};
  const auto r = locus::bsp2_boolean(Bsp2Op::union_, a, ea, b, eb);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.loop_ends.size(), 1u);
  EXPECT_EQ(locus::bsp2_twice_area(r), 2 * (16.0 + 8.0 - 4.0));  // overlap [2, 4]^2
}

TYPED_TEST(Bsp2BooleanTest, Figure13_28SharedEdgeOppositeIsASegment) {
  using T = TypeParam;
  const Case<T> c(ring<T>({{0, 0}, {2, 0}, {2, 2}, {0, 2}}),
                  ring<T>({{2, 0}, {4, 0}, {4, 2}, {2, 2}}));
  const auto r = locus::bsp2_boolean(Bsp2Op::intersection, c.ta, c.tb);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_TRUE(r.edges.empty());      // the regularised intersection is empty (the book's answer)
  ASSERT_EQ(r.segments.size(), 1u);  // the true set intersection: the shared edge
  const auto& s = r.segments[0];
  EXPECT_EQ(s.end[0].point.x, T(2));
  EXPECT_EQ(s.end[1].point.x, T(2));
  EXPECT_EQ(std::abs(s.end[1].point.y - s.end[0].point.y), T(2));
  EXPECT_TRUE(r.points.empty());
  const auto u = locus::bsp2_boolean(Bsp2Op::union_, c.ta, c.tb);
  EXPECT_EQ(u.edges.size(), 6u);  // the shared edge is interior to the union
  EXPECT_EQ(u.loop_ends.size(), 1u);
  check_areas(c, check_all(c, grid_probes<T>(-1, 5, 18)));
}

TYPED_TEST(Bsp2BooleanTest, Figure13_29RegionPlusSegments) {
  using T = TypeParam;
  const Case<T> c(ring<T>({{0, 0}, {2, 0}, {2, 2}, {0, 2}}),
                  ring<T>({{1, 0}, {3, 0}, {3, 3}, {0, 3}, {0, 2}, {2, 2}, {2, 1}, {1, 1}}));
  const auto r = locus::bsp2_boolean(Bsp2Op::intersection, c.ta, c.tb);
  ASSERT_EQ(r.status, Status::ok);
  const auto ex = exact_edges(c.ta, c.tb, r);
  EXPECT_EQ(twice_area(ex), 2);  // the unit square [1, 2] x [0, 1]
  // The lower-dimensional part: y = 2 for x in [0, 2] and x = 2 for y in [1, 2].
  mpq_class length = 0;
  for (const auto& s : r.segments)
    length += abs(s.end[1].point.x - s.end[0].point.x) + abs(s.end[1].point.y - s.end[0].point.y);
  EXPECT_EQ(length, 3);
  EXPECT_TRUE(r.points.empty());  // (2, 1) and (0, 2) end segments or edges
  check_areas(c, check_all(c, grid_probes<T>(-1, 4, 20)));
}

TYPED_TEST(Bsp2BooleanTest, Figures13_30And13_31KeyholeMatchesHole) {
  using T = TypeParam;
  Polygon<T> holed = ring<T>({{0, 0}, {8, 0}, {8, 6}, {0, 6}});
  holed.add_ring({{3, 2}, {3, 4}, {5, 4}, {5, 2}});
  // The keyhole: one ring, the bridge (0, 3) - (3, 3) walked both ways.
  const Polygon<T> keyhole = ring<T>({{0, 0},
                                      {8, 0},
                                      {8, 6},
                                      {0, 6},
                                      {0, 3},
                                      {3, 3},
                                      {3, 4},
                                      {5, 4},
                                      {5, 2},
                                      {3, 2},
                                      {3, 3},
                                      {0, 3}});
  const Polygon<T> rect = ring<T>({{-1, 1}, {6, 1}, {6, 5}, {-1, 5}});
  const Case<T> c1(rect, holed), c2(rect, keyhole);
  const auto probes = grid_probes<T>(-2, 9, 22);
  const auto a1 = check_all(c1, probes);
  check_areas(c1, a1);
  const auto r2 = locus::bsp2_boolean(Bsp2Op::intersection, c2.ta, c2.tb);
  ASSERT_EQ(r2.status, Status::ok);
  const auto ex2 = exact_edges(c2.ta, c2.tb, r2);
  check_loops(r2, ex2);
  EXPECT_EQ(twice_area(ex2), a1[0]);  // the slit adds no area (figure 13.31)
  for (const Vec2<T>& m : probes) {
    if (inside_input(rect, m) == 0 || inside_input(holed, m) == 0 || m.y == T(3)) continue;
    const bool in = inside_input(rect, m) > 0 && inside_input(holed, m) > 0;
    ASSERT_EQ(winding(ex2, q2(m)), in ? 1 : 0) << m.x << " " << m.y;
  }
  // The bridge inside the rectangle is kept both ways: a slit from x = 0 to x = 3 at y = 3.
  int slit = 0;
  for (const auto& e : ex2)
    if (e[0].y == 3 && e[1].y == 3 && e[0].x >= 0 && e[1].x >= 0 && e[0].x <= 3 && e[1].x <= 3)
      ++slit;
  EXPECT_EQ(slit, 2);
}

TYPED_TEST(Bsp2BooleanTest, RandomStarPolygonsWithHoles) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  int valid = 0;
  for (int round = 0; round < 10; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    Polygon<T> a =
        locus_test::star_polygon<T>(rng, rng.uniform_int(5, 12), 4, 8, rng.uniform_int(0, 2));
    Polygon<T> b =
        locus_test::star_polygon<T>(rng, rng.uniform_int(5, 12), 3, 7, rng.uniform_int(0, 2));
    const T dx = locus_test::snap<T>(rng.uniform(-5.0, 5.0)),
            dy = locus_test::snap<T>(rng.uniform(-5.0, 5.0));
    for (auto& p : b.points) p = p + Vec2<T>{dx, dy};
    if (!valid_rings(a) || !valid_rings(b)) continue;  // a hole crossing a wide-gapped star
    ++valid;
    const Case<T> c(a, b);
    ASSERT_EQ(c.ta.status(), Status::ok);
    std::vector<Vec2<T>> probes;
    for (int i = 0; i < 30; ++i) probes.push_back(rng.vec<T, 2>(T(-13), T(13)));
    check_areas(c, check_all(c, probes));
  }
  EXPECT_GE(valid, 5);
}

TYPED_TEST(Bsp2BooleanTest, WithItselfAndNegation) {
  using T = TypeParam;
  locus_test::Rng rng(7);
  const Polygon<T> a = locus_test::star_polygon<T>(rng, 9, 4, 8, 1);
  const Bsp2<T> t(a.points, a.ends);
  const mpq_class aa = input_area(a);
  for (const Bsp2Op op : all_ops) {
    const auto r = locus::bsp2_boolean(op, t, t);
    ASSERT_EQ(r.status, Status::ok);
    const auto ex = exact_edges(t, t, r);
    check_loops(r, ex);
    const bool keeps = op == Bsp2Op::intersection || op == Bsp2Op::union_;
    EXPECT_EQ(r.edges.size(), keeps ? t.edges().size() : 0u);
    EXPECT_EQ(twice_area(ex), keeps ? aa : mpq_class(0));
    EXPECT_TRUE(r.segments.empty());
  }
  const auto n = locus::bsp2_negation(t);
  ASSERT_EQ(n.status, Status::ok);
  const auto ex = exact_edges(t, t, n);
  check_loops(n, ex);
  EXPECT_EQ(twice_area(ex), -aa);
  EXPECT_EQ(n.loop_ends.size(), 2u);
  // A \ B = A n (not B): same area.
  const Polygon<T> bp = ring<T>({{-2, -9}, {9, -1}, {1, 9}});
  const Bsp2<T> tb(bp.points, bp.ends);
  const auto d = locus::bsp2_boolean(Bsp2Op::difference, t, tb);
  const auto i = locus::bsp2_boolean(Bsp2Op::intersection, t, tb);
  EXPECT_EQ(twice_area(exact_edges(t, tb, d)), aa - twice_area(exact_edges(t, tb, i)));
}

TYPED_TEST(Bsp2BooleanTest, TouchingVerticesAreReported) {
  using T = TypeParam;
  const Case<T> c(ring<T>({{0, 0}, {2, 0}, {2, 2}, {0, 2}}),
                  ring<T>({{2, 2}, {4, 2}, {4, 4}, {2, 4}}));
  const auto r = locus::bsp2_boolean(Bsp2Op::intersection, c.ta, c.tb);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_TRUE(r.edges.empty());
  EXPECT_TRUE(r.segments.empty());
  ASSERT_EQ(r.points.size(), 1u);
  EXPECT_EQ(r.points[0], (Vec2<T>{2, 2}));
  const auto u = locus::bsp2_boolean(Bsp2Op::union_, c.ta, c.tb);
  const auto ex = exact_edges(c.ta, c.tb, u);
  check_loops(u, ex);
  EXPECT_EQ(u.loop_ends.size(), 2u);  // the loops touch at (2, 2) but stay apart
  check_areas(c, check_all(c, grid_probes<T>(-1, 5, 18)));
  // A vertex of B on an edge of A from outside, and one from inside.
  const Case<T> c2(ring<T>({{0, 0}, {4, 0}, {4, 4}, {0, 4}}), ring<T>({{2, 4}, {3, 6}, {1, 6}}));
  const auto r2 = locus::bsp2_boolean(Bsp2Op::intersection, c2.ta, c2.tb);
  ASSERT_EQ(r2.points.size(), 1u);
  EXPECT_EQ(r2.points[0], (Vec2<T>{2, 4}));
  const Case<T> c3(ring<T>({{0, 0}, {4, 0}, {4, 4}, {0, 4}}), ring<T>({{2, 4}, {1, 2}, {3, 2}}));
  const auto r3 = locus::bsp2_boolean(Bsp2Op::intersection, c3.ta, c3.tb);
  EXPECT_TRUE(r3.points.empty());
  EXPECT_EQ(r3.edges.size(), 3u);
  check_areas(c3, check_all(c3, grid_probes<T>(-1, 5, 18)));
}

TYPED_TEST(Bsp2BooleanTest, EmptyAndNonFiniteOperands) {
  using T = TypeParam;
  const Polygon<T> a = ring<T>({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  const Bsp2<T> ta(a.points, a.ends), empty;
  ASSERT_EQ(empty.status(), Status::empty_input);
  EXPECT_EQ(locus::bsp2_boolean(Bsp2Op::intersection, ta, empty).edges.size(), 0u);
  EXPECT_EQ(locus::bsp2_boolean(Bsp2Op::union_, ta, empty).edges.size(), 4u);
  EXPECT_EQ(locus::bsp2_boolean(Bsp2Op::union_, empty, ta).edges.size(), 4u);
  EXPECT_EQ(locus::bsp2_boolean(Bsp2Op::difference, empty, ta).edges.size(), 0u);
  EXPECT_EQ(locus::bsp2_boolean(Bsp2Op::exclusive_or, empty, ta).status, Status::ok);
  const Polygon<T> flat = ring<T>({{0, 0}, {1, 1}, {2, 2}});  // zero area
  const Bsp2<T> tf(flat.points, flat.ends);
  EXPECT_EQ(locus::bsp2_boolean(Bsp2Op::union_, ta, tf).edges.size(), 4u);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Polygon<T> bad = ring<T>({{0, 0}, {nan, 0}, {2, 2}});
  const Bsp2<T> tbad(bad.points, bad.ends);
  for (const Bsp2Op op : all_ops) {
    const auto r = locus::bsp2_boolean(op, ta, tbad);
    EXPECT_EQ(r.status, Status::non_finite_input);
    EXPECT_TRUE(r.edges.empty());
  }
  EXPECT_EQ(locus::bsp2_negation(tbad).status, Status::non_finite_input);
}

TYPED_TEST(Bsp2BooleanTest, PowerOfTwoScaling) {
  using T = TypeParam;
  locus_test::Rng rng(11);
  Polygon<T> a = locus_test::star_polygon<T>(rng, 10, 4, 8, 1);
  Polygon<T> b = locus_test::star_polygon<T>(rng, 8, 3, 7, 0);
  for (auto& p : b.points) p = p + Vec2<T>{T(2.5), T(-1.25)};
  for (const int k : {-20, 7, 30}) {
    const T s = std::ldexp(T(1), k);
    Polygon<T> as = a, bs = b;
    for (auto& p : as.points) p = p * s;
    for (auto& p : bs.points) p = p * s;
    const Case<T> c(a, b), cs(as, bs);
    for (const Bsp2Op op : all_ops) {
      const auto r = locus::bsp2_boolean(op, c.ta, c.tb),
                 rs = locus::bsp2_boolean(op, cs.ta, cs.tb);
      ASSERT_EQ(r.edges.size(), rs.edges.size());
      for (std::size_t i = 0; i < r.edges.size(); ++i)
        for (int j = 0; j < 2; ++j) {
          EXPECT_EQ(rs.edges[i].end[std::size_t(j)].point,
                    r.edges[i].end[std::size_t(j)].point * s);
          EXPECT_EQ(rs.edges[i].end[std::size_t(j)].line, r.edges[i].end[std::size_t(j)].line);
        }
      EXPECT_EQ(rs.loop_edges, r.loop_edges);
    }
  }
}

}  // namespace

namespace {

/// Small integer triangles and rectangles: shared edges, overlapping collinear edges and
/// touching vertices are frequent.
template <class T>
locus_test::Polygon<T> grid_shape(locus_test::Rng& rng) {
  for (;;) {
    std::vector<Vec2<T>> v;
    if (rng.uniform_int(0, 1)) {
      const int x0 = rng.uniform_int(0, 3), y0 = rng.uniform_int(0, 3);
      const int x1 = rng.uniform_int(x0 + 1, 4), y1 = rng.uniform_int(y0 + 1, 4);
      v = {{T(x0), T(y0)}, {T(x1), T(y0)}, {T(x1), T(y1)}, {T(x0), T(y1)}};
    } else {
      for (int i = 0; i < 3; ++i) v.push_back({T(rng.uniform_int(0, 4)), T(rng.uniform_int(0, 4))});
      if (locus::orient2d(v[0], v[1], v[2]) == locus::Sign::zero) continue;
    }
    if (rng.uniform_int(0, 1)) std::reverse(v.begin(), v.end());
    locus_test::Polygon<T> p;
    p.add_ring(v);
    return p;
  }
}

TYPED_TEST(Bsp2BooleanTest, RandomGridShapesWithSharedEdges) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec2<T>> probes;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) probes.push_back({T(i) / 2 + T(0.125), T(j) / 2 + T(0.375)});
  for (int round = 0; round < 40; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const Case<T> c(grid_shape<T>(rng), grid_shape<T>(rng));
    check_areas(c, check_all(c, probes));
    // The lower-dimensional parts lie on both boundaries.
    const auto r = locus::bsp2_boolean(Bsp2Op::intersection, c.ta, c.tb);
    for (const auto& s : r.segments) {
      const Vec2<T> m = (s.end[0].point + s.end[1].point) * T(0.5);
      EXPECT_EQ(inside_input(c.a, m), 0);
      EXPECT_EQ(inside_input(c.b, m), 0);
    }
    for (const Vec2<T>& p : r.points) {
      EXPECT_EQ(inside_input(c.a, p), 0);
      EXPECT_EQ(inside_input(c.b, p), 0);
    }
  }
}

}  // namespace
