// SPDX-License-Identifier: BSL-1.0
// Tests of locus/delaunay/constrained_delaunay2.hpp (row cg.delaunay2, constrained part).
// Structure, area and the locally-constrained-Delaunay property (which implies the global one)
// are checked exactly by delaunay_check.hpp; constraint presence and inside areas by exact
// predicates and GMP rationals here.

#include <locus/delaunay/constrained_delaunay2.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <vector>

#include "delaunay_check.hpp"
#include "support/typed.hpp"

namespace {

using locus::ConstrainedDelaunay2Result;
using locus::Sign;
using locus::Status;
using locus::Vec2;
using Edge = std::array<std::uint32_t, 2>;

template <class T>
class ConstrainedDelaunay2Test : public ::testing::Test {};
TYPED_TEST_SUITE(ConstrainedDelaunay2Test, locus_test::RealTypes);

locus::Delaunay2Result as_delaunay(const ConstrainedDelaunay2Result& c) {
  locus::Delaunay2Result r;
  r.status = c.status == Status::invalid_input ? Status::ok : c.status;
  r.dimension = c.dimension;
  r.triangles = c.triangles;
  r.adjacency = c.adjacency;
  r.hull = c.hull;
  r.duplicate_of = c.duplicate_of;
  for (std::size_t i = 0; i < r.duplicate_of.size(); ++i)
    r.duplicate_count += r.duplicate_of[i] != i ? 1u : 0u;
  return r;
}

// Every accepted constraint is present, split at the vertices on its open segment, and every
// constrained half-edge lies on some constraint.
template <class T>
::testing::AssertionResult check_constraints(const std::vector<Vec2<T>>& p,
                                             const std::vector<Edge>& cons,
                                             const ConstrainedDelaunay2Result& r) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint8_t> edges;
  for (std::size_t t = 0; t < r.triangles.size(); ++t)
    for (std::size_t i = 0; i < 3; ++i) {
      const auto a = r.triangles[t][i], b = r.triangles[t][(i + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}] |= r.constrained[t][i];
    }
  std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::size_t k = 0; k < cons.size(); ++k) {
    if (std::find(r.rejected.begin(), r.rejected.end(), k) != r.rejected.end()) continue;
    const auto a = r.duplicate_of[cons[k][0]], b = r.duplicate_of[cons[k][1]];
    if (a == b) continue;
    std::vector<std::uint32_t> on;  // kept vertices on the closed segment, sorted along it
    for (std::uint32_t v = 0; v < p.size(); ++v) {
      if (r.duplicate_of[v] != v) continue;
      if (v == a || v == b ||
          (locus::orient2d(p[a], p[b], p[v]) == Sign::zero &&
           locus::lexicographic_compare(p[a], p[v]) == locus::lexicographic_compare(p[v], p[b])))
        on.push_back(v);
    }
    std::sort(on.begin(), on.end(), [&](std::uint32_t u, std::uint32_t w) {
      return locus::lexicographic_compare(p[u], p[w]) == Sign::negative;
    });
    for (std::size_t i = 0; i + 1 < on.size(); ++i) {
      const std::pair<std::uint32_t, std::uint32_t> key{std::min(on[i], on[i + 1]),
                                                        std::max(on[i], on[i + 1])};
      const auto it = edges.find(key);
      if (it == edges.end())
        return ::testing::AssertionFailure() << "constraint " << k << " piece missing";
      if (!it->second)
        return ::testing::AssertionFailure() << "constraint " << k << " piece not marked";
      expected.insert(key);
    }
  }
  for (const auto& [key, flag] : edges)
    if (flag && !expected.count(key))
      return ::testing::AssertionFailure() << "edge marked constrained but on no constraint";
  return ::testing::AssertionSuccess();
}

template <class T>
::testing::AssertionResult check_cdt(const std::vector<Vec2<T>>& p, const std::vector<Edge>& cons,
                                     const ConstrainedDelaunay2Result& r) {
  if (r.constrained.size() != r.triangles.size())
    return ::testing::AssertionFailure() << "constrained size";
  auto s = locus_test::check_delaunay(p, as_delaunay(r), true, &r.constrained);
  if (!s) return s;
  return check_constraints(p, cons, r);
}

// Do the closed segments ab and cd share a point other than a common endpoint? (exact)
template <class T>
bool segments_conflict(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c, const Vec2<T>& d) {
  const Sign o1 = locus::orient2d(a, b, c), o2 = locus::orient2d(a, b, d);
  const Sign o3 = locus::orient2d(c, d, a), o4 = locus::orient2d(c, d, b);
  if (o1 == Sign::zero && o2 == Sign::zero) return true;  // collinear: be conservative
  return o1 != o2 && o3 != o4 && o1 * o2 != Sign::positive && o3 * o4 != Sign::positive &&
         !(o1 == Sign::zero || o2 == Sign::zero || o3 == Sign::zero || o4 == Sign::zero);
}

template <class T>
mpq_class inside_twice_area(const std::vector<Vec2<T>>& p, const ConstrainedDelaunay2Result& r) {
  mpq_class s = 0;
  for (std::size_t t = 0; t < r.triangle_count(); ++t)
    if (r.inside[t])
      s +=
          locus_test::exact_cross(p[r.triangles[t][0]], p[r.triangles[t][1]], p[r.triangles[t][2]]);
  return s;
}

TYPED_TEST(ConstrainedDelaunay2Test, SquareWithDiagonalConstraint) {
  using T = TypeParam;
  // A square whose Delaunay diagonal is ambiguous, plus points that make 0-2 Delaunay-illegal
  // except as a constraint.
  std::vector<Vec2<T>> p = {{T(0), T(0)}, {T(4), T(1)}, {T(8), T(0)}, {T(4), T(-1)}};
  // Delaunay picks 1-3 (short diagonal); force 0-2.
  std::vector<Edge> cons = {{0, 2}};
  auto r = locus::constrained_delaunay(std::span<const Vec2<T>>(p), std::span<const Edge>(cons));
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_TRUE(check_cdt(p, cons, r));
  auto d = locus::delaunay(std::span<const Vec2<T>>(p));
  EXPECT_TRUE(locus_test::edge_set(d).count({1, 3}));
  EXPECT_FALSE(locus_test::edge_set(as_delaunay(r)).count({1, 3}));
}

TYPED_TEST(ConstrainedDelaunay2Test, RandomNonCrossingConstraints) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 12; ++trial) {
    const std::size_t n = 20 + std::size_t(rng.uniform_int(0, 300));
    std::vector<Vec2<T>> p(n);
    for (auto& q : p)
      q = trial % 2 ? rng.vec<T, 2>(T(-1), T(1))
                    : Vec2<T>{T(rng.uniform_int(0, 20)), T(rng.uniform_int(0, 20))};
    std::vector<Edge> cons;
    for (int k = 0; k < 60; ++k) {
      const Edge e{std::uint32_t(rng.uniform_int(0, int(n) - 1)),
                   std::uint32_t(rng.uniform_int(0, int(n) - 1))};
      bool ok = true;
      for (const auto& f : cons) ok = ok && !segments_conflict(p[e[0]], p[e[1]], p[f[0]], p[f[1]]);
      if (ok) cons.push_back(e);
    }
    auto r = locus::constrained_delaunay(std::span<const Vec2<T>>(p), std::span<const Edge>(cons));
    if (r.dimension < 2) continue;
    // Duplicate points can turn a non-crossing pair into a crossing one only if coordinates
    // coincide, which segments_conflict already saw; so nothing may be rejected.
    EXPECT_TRUE(r.rejected.empty()) << "trial " << trial;
    ASSERT_TRUE(check_cdt(p, cons, r)) << "trial " << trial;
  }
}

TYPED_TEST(ConstrainedDelaunay2Test, ConstraintThroughCollinearVertices) {
  using T = TypeParam;
  std::vector<Vec2<T>> p;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) p.push_back({T(i), T(j)});
  // Along a row, a diagonal and a knight-move line (through vertices 2 apart).
  std::vector<Edge> cons = {{0 * 9 + 4, 8 * 9 + 4}, {0, 80}, {0 * 9 + 0, 8 * 9 + 4}};
  auto r = locus::constrained_delaunay(std::span<const Vec2<T>>(p), std::span<const Edge>(cons));
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_TRUE(check_cdt(p, cons, r));
  std::size_t marked = 0;
  for (const auto& c : r.constrained) marked += std::size_t(c[0]) + c[1] + c[2];
  // 8 + 8 + 4 pieces, two half-edges each (none on the hull).
  EXPECT_EQ(marked, 2u * (8 + 8 + 4));
}

TYPED_TEST(ConstrainedDelaunay2Test, CrossingConstraintsAreReported) {
  using T = TypeParam;
  std::vector<Vec2<T>> p = {{T(0), T(0)},  {T(10), T(10)}, {T(0), T(10)},
                            {T(10), T(0)}, {T(5), T(-3)},  {T(5), T(13)}};
  std::vector<Edge> cons = {{0, 1}, {2, 3}, {4, 5}, {0, 9}};
  auto r = locus::constrained_delaunay(std::span<const Vec2<T>>(p), std::span<const Edge>(cons));
  EXPECT_EQ(r.status, Status::invalid_input);
  EXPECT_EQ(r.rejected, (std::vector<std::uint32_t>{1, 2, 3}));
  EXPECT_TRUE(check_cdt(p, cons, r));
}

TYPED_TEST(ConstrainedDelaunay2Test, PolygonWithHoles) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  // Outer: a star-shaped ring with random radii (CCW); holes: two small squares (CW) inside
  // the inner radius.
  std::vector<Vec2<T>> p;
  std::vector<std::uint32_t> ends;
  const int m = 40;
  for (int i = 0; i < m; ++i) {
    const double ang = 2 * 3.141592653589793 * i / m;
    const double rad = 10 + rng.uniform<double>(0, 5);
    p.push_back({T(std::round(rad * std::cos(ang) * 64) / 64),
                 T(std::round(rad * std::sin(ang) * 64) / 64)});
  }
  ends.push_back(std::uint32_t(p.size()));
  for (T cx : {T(-4), T(3)}) {
    p.push_back({cx, T(-1)});
    p.push_back({cx, T(1)});
    p.push_back({cx + T(2), T(1)});
    p.push_back({cx + T(2), T(-1)});
    ends.push_back(std::uint32_t(p.size()));
  }
  // Interior Steiner-free extra points are not allowed here: rings only.
  auto r =
      locus::triangulate_polygon(std::span<const Vec2<T>>(p), std::span<const std::uint32_t>(ends));
  ASSERT_EQ(r.status, Status::ok);
  std::vector<Edge> cons;
  std::uint32_t begin = 0;
  for (auto e : ends) {
    for (std::uint32_t i = begin; i < e; ++i) cons.push_back({i, i + 1 == e ? begin : i + 1});
    begin = e;
  }
  EXPECT_TRUE(check_cdt(p, cons, r));
  std::vector<std::uint32_t> outer(m), h1 = {40, 41, 42, 43}, h2 = {44, 45, 46, 47};
  std::iota(outer.begin(), outer.end(), 0u);
  const mpq_class expected = abs(locus_test::exact_twice_area(p, outer)) -
                             abs(locus_test::exact_twice_area(p, h1)) -
                             abs(locus_test::exact_twice_area(p, h2));
  EXPECT_EQ(inside_twice_area(p, r), expected);
  // Hole triangles are outside: the centre of each hole is in no inside triangle.
  std::size_t inside_count = 0;
  for (auto v : r.inside) inside_count += v;
  EXPECT_GT(inside_count, 0u);
  EXPECT_LT(inside_count, r.triangle_count());
}

TYPED_TEST(ConstrainedDelaunay2Test, BadInput) {
  using T = TypeParam;
  std::vector<Vec2<T>> p;
  std::vector<Edge> cons;
  auto r = locus::constrained_delaunay(std::span<const Vec2<T>>(p), std::span<const Edge>(cons));
  EXPECT_EQ(r.status, Status::empty_input);
  p = {{T(0), T(0)}, {std::numeric_limits<T>::quiet_NaN(), T(1)}, {T(1), T(0)}};
  r = locus::constrained_delaunay(std::span<const Vec2<T>>(p), std::span<const Edge>(cons));
  EXPECT_EQ(r.status, Status::non_finite_input);
  p = {{T(0), T(0)}, {T(1), T(1)}, {T(2), T(2)}, {T(2), T(2)}};
  cons = {{0, 2}, {2, 3}};
  r = locus::constrained_delaunay(std::span<const Vec2<T>>(p), std::span<const Edge>(cons));
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 1);
  // Zero-length constraints (after merging duplicates) are ignored; out-of-range rejected.
  p = {{T(0), T(0)}, {T(1), T(0)}, {T(0), T(1)}, {T(1), T(0)}};
  cons = {{1, 3}, {0, 7}, {0, 3}};
  r = locus::constrained_delaunay(std::span<const Vec2<T>>(p), std::span<const Edge>(cons));
  EXPECT_EQ(r.status, Status::invalid_input);
  EXPECT_EQ(r.rejected, (std::vector<std::uint32_t>{1}));
  EXPECT_TRUE(check_cdt(p, cons, r));
  // A bad ring end.
  std::vector<std::uint32_t> ends = {9};
  r = locus::triangulate_polygon(std::span<const Vec2<T>>(p), std::span<const std::uint32_t>(ends));
  EXPECT_EQ(r.status, Status::invalid_input);
}

// ---- poly2tri testbed polygons (single rings) ------------------------------------------

class Poly2triPolygons : public ::testing::TestWithParam<const char*> {};

TEST_P(Poly2triPolygons, AreaAndConstraints) {
  std::ifstream in(std::string(LOCUS_SHARED_DIR "/corpus/poly2tri/data/") + GetParam() + ".dat");
  ASSERT_TRUE(in.good());
  std::vector<Vec2<double>> p;
  double x, y;
  while (in >> x >> y) p.push_back({x, y});
  ASSERT_GE(p.size(), 3u);
  std::vector<std::uint32_t> ends = {std::uint32_t(p.size())};
  auto r = locus::triangulate_polygon(std::span<const Vec2<double>>(p),
                                      std::span<const std::uint32_t>(ends));
  std::vector<Edge> cons;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    cons.push_back({i, (i + 1) % std::uint32_t(p.size())});
  if (p.size() <= 2000) {
    EXPECT_TRUE(check_cdt(p, cons, r));
  } else {  // the O(n m) constraint scan is too slow in Debug: structure and flags only
    EXPECT_TRUE(locus_test::check_delaunay(p, as_delaunay(r), false, &r.constrained));
  }
  if (r.status == Status::ok &&
      std::all_of(r.duplicate_of.begin(), r.duplicate_of.end(),
                  [i = 0u](std::uint32_t d) mutable { return d == i++; })) {
    std::vector<std::uint32_t> ring(p.size());
    std::iota(ring.begin(), ring.end(), 0u);
    EXPECT_EQ(inside_twice_area(p, r), abs(locus_test::exact_twice_area(p, ring)));
    // A simple polygon with n vertices and no interior points has n - 2 triangles.
    std::size_t inside = 0;
    for (auto v : r.inside) inside += v;
    EXPECT_EQ(inside, p.size() - 2);
  }
}

INSTANTIATE_TEST_SUITE_P(ConstrainedDelaunay2, Poly2triPolygons,
                         ::testing::Values("2", "bird", "custom", "diamond", "dude", "funny",
                                           "kzer-za", "nazca_heron", "nazca_monkey",
                                           "polygon_test_01", "polygon_test_02", "polygon_test_03",
                                           "sketchup", "stalactite", "star", "strange", "tank",
                                           "test", "debug", "debug2"));

}  // namespace
