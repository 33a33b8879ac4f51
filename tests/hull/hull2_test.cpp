// SPDX-License-Identifier: BSL-1.0
// Tests of locus/hull/hull2.hpp (cg.hull2): book figures 13.32-13.38, degenerate and bad input,
// the Kettner et al. robustness sets, a brute-force exact oracle on small sets, cross-checks of
// the three methods, exact invariants on every output, transform invariance.

#include <locus/hull/hull2.hpp>

#include <support/typed.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <vector>

namespace {

using locus::Hull2Method;
using locus::Hull2Options;
using locus::Hull2Result;
using locus::Sign;
using locus::Status;
using locus::Vec2;

constexpr Hull2Method kMethods[] = {Hull2Method::monotone_chain, Hull2Method::incremental,
                                    Hull2Method::divide_and_conquer};

template <class T>
bool lex_yx_less(const Vec2<T>& a, const Vec2<T>& b) {
  return a.y < b.y || (a.y == b.y && a.x < b.x);
}

// p on the closed segment ab (exact).
template <class T>
bool on_segment(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& p) {
  if (locus::orient2d(a, b, p) != Sign::zero) return false;
  const Vec2<T> lo = lex_yx_less(a, b) ? a : b, hi = lex_yx_less(a, b) ? b : a;
  return !lex_yx_less(p, lo) && !lex_yx_less(hi, p);
}

// Brute-force oracle (exact predicates only, O(n^4)): p is extreme iff it is in no closed
// triangle or segment of other (distinct from p) points.
template <class T>
std::vector<bool> brute_extreme(const std::vector<Vec2<T>>& pts) {
  const std::size_t n = pts.size();
  std::vector<bool> ext(n, true);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2<T>& p = pts[i];
    std::vector<Vec2<T>> other;
    for (const auto& q : pts)
      if (!(q == p)) other.push_back(q);
    bool inside = false;
    for (std::size_t a = 0; a < other.size() && !inside; ++a)
      for (std::size_t b = a + 1; b < other.size() && !inside; ++b) {
        if (on_segment(other[a], other[b], p)) inside = true;
        for (std::size_t c = b + 1; c < other.size() && !inside; ++c) {
          const Sign o = locus::orient2d(other[a], other[b], other[c]);
          if (o == Sign::zero) continue;
          const Sign s1 = locus::orient2d(other[a], other[b], p);
          const Sign s2 = locus::orient2d(other[b], other[c], p);
          const Sign s3 = locus::orient2d(other[c], other[a], p);
          if (s1 != -o && s2 != -o && s3 != -o) inside = true;
        }
      }
    ext[i] = !inside;
  }
  return ext;
}

// p on the boundary of the hull (n distinct >= 2): some line through p and another point has
// every point on one closed side.
template <class T>
bool brute_on_boundary(const std::vector<Vec2<T>>& pts, const Vec2<T>& p) {
  for (const auto& q : pts) {
    if (q == p) continue;
    bool left = true, right = true;
    for (const auto& r : pts) {
      const Sign s = locus::orient2d(p, q, r);
      if (s == Sign::negative) left = false;
      if (s == Sign::positive) right = false;
    }
    if (left || right) return true;
  }
  return false;
}

template <class T>
std::uint32_t representative(const std::vector<Vec2<T>>& pts, std::uint32_t i) {
  for (std::uint32_t j = 0; j < i; ++j)
    if (pts[j] == pts[i]) return j;
  return i;
}

// Exact invariants of a result, O(n log h): valid representatives, the lowest-leftmost start,
// strict convexity (or collinear continuation when keeping collinear points), a fan that winds
// once, every point inside or on the polygon, and (keep_collinear) every boundary point listed.
template <class T>
::testing::AssertionResult check_hull(const std::vector<Vec2<T>>& pts, const Hull2Result& r,
                                      bool keep) {
  if (r.status != Status::ok) return ::testing::AssertionFailure() << "status not ok";
  const auto& id = r.indices;
  for (auto i : id)
    if (i >= pts.size()) return ::testing::AssertionFailure() << "index out of range";
  // The start: the lowest-leftmost point, its smallest index.
  std::uint32_t low = 0;
  for (std::uint32_t i = 1; i < pts.size(); ++i)
    if (lex_yx_less(pts[i], pts[low])) low = i;
  if (id.empty() || id[0] != low) return ::testing::AssertionFailure() << "wrong start";
  std::set<std::uint32_t> listed(id.begin(), id.end());
  if (listed.size() != id.size()) return ::testing::AssertionFailure() << "repeated index";
  // Representatives: the smallest index of equal points (checked on a sample for big inputs).
  if (pts.size() <= 600)
    for (auto i : id)
      if (representative(pts, i) != i) return ::testing::AssertionFailure() << "not smallest dup";
  if (r.dimension == 0) {
    for (const auto& p : pts)
      if (!(p == pts[id[0]])) return ::testing::AssertionFailure() << "dim 0 with distinct pts";
    return id.size() == 1 ? ::testing::AssertionSuccess()
                          : ::testing::AssertionFailure() << "dim 0 size";
  }
  if (r.dimension == 1) {
    const Vec2<T> a = pts[id.front()], b = pts[id.back()];
    for (const auto& p : pts)
      if (!on_segment(a, b, p)) return ::testing::AssertionFailure() << "point off the segment";
    for (std::size_t k = 1; k < id.size(); ++k)
      if (!lex_yx_less(pts[id[k - 1]], pts[id[k]]))
        return ::testing::AssertionFailure() << "dim 1 order";
    if (!keep && id.size() != 2) return ::testing::AssertionFailure() << "dim 1 size";
    if (keep) {
      std::set<std::pair<T, T>> distinct;
      for (const auto& p : pts) distinct.insert({p.x, p.y});
      if (distinct.size() != id.size()) return ::testing::AssertionFailure() << "dim 1 keep size";
    }
    return ::testing::AssertionSuccess();
  }
  if (r.dimension != 2) return ::testing::AssertionFailure() << "bad dimension";
  // Strict vertices; in keep mode the others must continue straight.
  std::vector<Vec2<T>> v;
  const std::size_t h = id.size();
  for (std::size_t k = 0; k < h; ++k) {
    const Vec2<T>& a = pts[id[(k + h - 1) % h]];
    const Vec2<T>& b = pts[id[k]];
    const Vec2<T>& c = pts[id[(k + 1) % h]];
    const Sign s = locus::orient2d(a, b, c);
    if (s == Sign::negative) return ::testing::AssertionFailure() << "right turn at " << k;
    if (s == Sign::zero) {
      if (!keep) return ::testing::AssertionFailure() << "collinear vertex at " << k;
      if (!on_segment(a, c, b)) return ::testing::AssertionFailure() << "backtrack at " << k;
    } else {
      v.push_back(b);
    }
  }
  if (v.size() < 3) return ::testing::AssertionFailure() << "fewer than 3 strict vertices";
  for (std::size_t k = 1; k + 1 < v.size(); ++k)
    if (locus::orient2d(v[0], v[k], v[k + 1]) != Sign::positive)
      return ::testing::AssertionFailure() << "polygon winds more than once";
  // Every point inside or on; count boundary points.
  std::size_t on_boundary = 0;
  std::set<std::pair<T, T>> boundary_pts;
  for (const auto& p : pts) {
    if (locus::orient2d(v[0], v[1], p) == Sign::negative ||
        locus::orient2d(v[0], v.back(), p) == Sign::positive)
      return ::testing::AssertionFailure() << "point outside (fan)";
    // Largest k in [1, size-1) with orient(v0, vk, p) >= 0.
    std::size_t lo = 1, hi = v.size() - 1;
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      if (locus::orient2d(v[0], v[mid], p) != Sign::negative)
        lo = mid;
      else
        hi = mid;
    }
    const Sign s = locus::orient2d(v[lo], v[lo + 1], p);
    if (s == Sign::negative) return ::testing::AssertionFailure() << "point outside an edge";
    bool bd = s == Sign::zero || on_segment(v[0], v[1], p) || on_segment(v[0], v.back(), p);
    if (bd && boundary_pts.insert({p.x, p.y}).second) ++on_boundary;
  }
  if (keep && on_boundary != h)
    return ::testing::AssertionFailure() << "boundary points " << on_boundary << " listed " << h;
  return ::testing::AssertionSuccess();
}

template <class T>
Hull2Result hull(const std::vector<Vec2<T>>& pts, Hull2Method m, bool keep = false) {
  return locus::convex_hull(pts, Hull2Options{keep, m});
}

// Every method, both modes: invariants hold and all methods agree exactly.
template <class T>
void check_all(const std::vector<Vec2<T>>& pts) {
  for (bool keep : {false, true}) {
    const Hull2Result ref = hull(pts, Hull2Method::monotone_chain, keep);
    EXPECT_TRUE(check_hull(pts, ref, keep)) << "keep " << keep;
    for (auto m : kMethods) {
      const Hull2Result r = hull(pts, m, keep);
      EXPECT_EQ(r.status, ref.status);
      EXPECT_EQ(r.dimension, ref.dimension) << "method " << int(m) << " keep " << keep;
      EXPECT_EQ(r.indices, ref.indices) << "method " << int(m) << " keep " << keep;
    }
  }
}

// Compare with the brute-force oracle: strict output = extreme points; keep output = boundary.
template <class T>
void check_oracle(const std::vector<Vec2<T>>& pts) {
  const std::vector<bool> ext = brute_extreme(pts);
  std::set<std::uint32_t> want, want_bd;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    const std::uint32_t r = representative(pts, i);
    if (ext[i]) want.insert(r);
    if (brute_on_boundary(pts, pts[i])) want_bd.insert(r);
  }
  for (auto m : kMethods) {
    const Hull2Result r = hull(pts, m, false);
    ASSERT_EQ(r.status, Status::ok);
    const std::set<std::uint32_t> got(r.indices.begin(), r.indices.end());
    EXPECT_EQ(got, want) << "method " << int(m);
    const Hull2Result rk = hull(pts, m, true);
    const std::set<std::uint32_t> gotk(rk.indices.begin(), rk.indices.end());
    if (rk.dimension == 2) {
      EXPECT_EQ(gotk, want_bd) << "keep, method " << int(m);
    }
  }
  check_all(pts);
}

template <class T>
std::vector<Vec2<T>> make(std::initializer_list<std::pair<double, double>> xy) {
  std::vector<Vec2<T>> v;
  for (auto [x, y] : xy) v.push_back(Vec2<T>{T(x), T(y)});
  return v;
}

template <class T>
class Hull2 : public ::testing::Test {};
TYPED_TEST_SUITE(Hull2, locus_test::RealTypes);

// Figures 13.32/13.33: a point set and its hull; hull vertices and the edge point by inspection.
TYPED_TEST(Hull2, Figure13_33PointSetAndHull) {
  using T = TypeParam;
  const auto pts = make<T>({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}, {1, 3}, {2, 0}, {3, 1}});
  for (auto m : kMethods) {
    const Hull2Result r = hull(pts, m);
    EXPECT_EQ(r.dimension, 2);
    EXPECT_EQ(r.indices, (std::vector<std::uint32_t>{0, 1, 2, 3}));
    const Hull2Result k = hull(pts, m, true);
    EXPECT_EQ(k.indices, (std::vector<std::uint32_t>{0, 6, 1, 2, 3}));
  }
  check_oracle(pts);
}

// Figure 13.34: a hull and an outside point; its tangent points survive, the edges it sees go.
TYPED_TEST(Hull2, Figure13_34TangentsFromOutsidePoint) {
  using T = TypeParam;
  // Hexagon, then V far right: the tangent points are 0 and 3; vertices 1 and 2 are hidden.
  const auto pts = make<T>({{0, -2}, {2, -1}, {2, 1}, {0, 2}, {-2, 1}, {-2, -1}, {10, 0}});
  for (auto m : kMethods) {
    const Hull2Result r = hull(pts, m);
    EXPECT_EQ(r.indices, (std::vector<std::uint32_t>{0, 6, 3, 4, 5}));
  }
  check_oracle(pts);
}

// Figure 13.35: P against a segment Q0Q1: (a) left, (b) right, (c) on the line beyond Q0,
// (d) beyond Q1, (e) inside the segment.
TYPED_TEST(Hull2, Figure13_35FiveCases) {
  using T = TypeParam;
  const Vec2<T> q0{T(0), T(0)}, q1{T(4), T(2)};
  struct Case {
    Vec2<T> p;
    int dim;
    std::vector<std::uint32_t> strict;
  };
  const Case cases[] = {
      {{T(1), T(3)}, 2, {0, 1, 2}},   // (a) left: CCW q0, q1, p
      {{T(3), T(-1)}, 2, {0, 2, 1}},  // (b) right: p is lowest... start at lowest
      {{T(-2), T(-1)}, 1, {2, 1}},    // (c) beyond Q0
      {{T(6), T(3)}, 1, {0, 2}},      // (d) beyond Q1
      {{T(2), T(1)}, 1, {0, 1}},      // (e) inside
  };
  for (const Case& c : cases) {
    const std::vector<Vec2<T>> pts{q0, q1, c.p};
    for (auto m : kMethods) {
      const Hull2Result r = hull(pts, m);
      EXPECT_EQ(r.dimension, c.dim);
      if (c.dim == 2 && c.p.y < T(0)) {
        EXPECT_EQ(r.indices, (std::vector<std::uint32_t>{2, 1, 0}));  // (b): starts at p
      } else {
        EXPECT_EQ(r.indices, c.strict);
      }
    }
    check_oracle(pts);
  }
}

// Figures 13.36-13.38: two hulls merged by their tangents, including extremes on one line
// across the split (in the (y, x) order the split line is horizontal: equal y on both sides).
TYPED_TEST(Hull2, Figures13_36To13_38Merge) {
  using T = TypeParam;
  // Left/right halves in y order; many points share y = 2 across the split.
  const auto pts = make<T>({{0, 0},
                            {3, 0},
                            {1, 1},
                            {-1, 2},
                            {0, 2},
                            {2, 2},
                            {4, 2},
                            {5, 2},
                            {1, 3},
                            {2, 4},
                            {3, 4},
                            {0, 5}});
  check_oracle(pts);
  // Two separated diamonds whose tangents are found from extremes on one horizontal line.
  const auto two = make<T>({{0, 0}, {1, 1}, {-1, 1}, {0, 2}, {5, 2}, {6, 3}, {4, 3}, {5, 4}});
  check_oracle(two);
}

TYPED_TEST(Hull2, BadInput) {
  using T = TypeParam;
  for (auto m : kMethods) {
    const std::vector<Vec2<T>> empty;
    const Hull2Result e = hull(empty, m);
    EXPECT_EQ(e.status, Status::empty_input);
    EXPECT_EQ(e.dimension, -1);
    EXPECT_TRUE(e.indices.empty());
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    for (T bad : {nan, inf, -inf}) {
      for (std::size_t n : {std::size_t(3), std::size_t(1000)}) {
        std::vector<Vec2<T>> pts(n);
        for (std::size_t i = 0; i < n; ++i) pts[i] = {T(i % 17), T(i % 13)};
        pts[n / 2].y = bad;
        const Hull2Result r = hull(pts, m);
        EXPECT_EQ(r.status, Status::non_finite_input);
        EXPECT_EQ(r.dimension, -1);
        EXPECT_TRUE(r.indices.empty());
      }
    }
  }
}

TYPED_TEST(Hull2, SmallAndEqualSets) {
  using T = TypeParam;
  for (auto m : kMethods) {
    const auto one = make<T>({{1, 2}});
    Hull2Result r = hull(one, m);
    EXPECT_EQ(r.status, Status::ok);
    EXPECT_EQ(r.dimension, 0);
    EXPECT_EQ(r.indices, (std::vector<std::uint32_t>{0}));
    const std::vector<Vec2<T>> same(2000, Vec2<T>{T(3), T(-1)});
    r = hull(same, m, true);
    EXPECT_EQ(r.dimension, 0);
    EXPECT_EQ(r.indices, (std::vector<std::uint32_t>{0}));
    const auto two = make<T>({{1, 2}, {-1, 2}});
    r = hull(two, m);
    EXPECT_EQ(r.dimension, 1);
    EXPECT_EQ(r.indices, (std::vector<std::uint32_t>{1, 0}));
    const auto tri = make<T>({{0, 1}, {0, 0}, {1, 0}});
    r = hull(tri, m);
    EXPECT_EQ(r.dimension, 2);
    EXPECT_EQ(r.indices, (std::vector<std::uint32_t>{1, 2, 0}));
  }
}

TYPED_TEST(Hull2, Collinear) {
  using T = TypeParam;
  // 3000 points on the line y = 3x - 1 with integer coordinates, shuffled, with duplicates.
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec2<T>> pts;
  for (int i = 0; i < 3000; ++i) {
    const int x = rng.uniform_int(-500, 500);
    pts.push_back({T(x), T(3 * x - 1)});
  }
  for (auto m : kMethods) {
    const Hull2Result r = hull(pts, m);
    EXPECT_EQ(r.dimension, 1);
    EXPECT_TRUE(check_hull(pts, r, false));
    const Hull2Result k = hull(pts, m, true);
    EXPECT_EQ(k.dimension, 1);
    EXPECT_TRUE(check_hull(pts, k, true));
  }
  check_all(pts);
  // Vertical and horizontal lines.
  std::vector<Vec2<T>> v, h;
  for (int i = 0; i < 500; ++i) {
    v.push_back({T(7), T((i * 37) % 101)});
    h.push_back({T((i * 37) % 101), T(-7)});
  }
  check_all(v);
  check_all(h);
}

TYPED_TEST(Hull2, Cocircular) {
  using T = TypeParam;
  // Integer points exactly on x^2 + y^2 = r^2 (every one is extreme): 5^4 = 625 has 20 such
  // points (oracle), 5^2 13^2 17^2 = 1221025 has 4 * 3 * 3 * 3 = 108 (methods agree).
  for (int r2 : {625, 1221025}) {
    std::vector<Vec2<T>> pts;
    const int r = static_cast<int>(std::sqrt(double(r2)));
    for (int x = -r; x <= r; ++x) {
      const int y = static_cast<int>(std::lround(std::sqrt(double(r2 - x * x))));
      if (x * x + y * y == r2) {
        pts.push_back({T(x), T(y)});
        if (y != 0) pts.push_back({T(x), T(-y)});
      }
    }
    const auto n = pts.size();
    ASSERT_GE(n, 20u);
    for (std::size_t i = 0; i < n; ++i) pts.push_back(pts[(i * 7) % n]);  // duplicates
    if (r2 == 625)
      check_oracle(pts);
    else
      check_all(pts);
    for (auto m : kMethods) EXPECT_EQ(hull(pts, m).indices.size(), n);
  }
}

TYPED_TEST(Hull2, IntegerGrid) {
  using T = TypeParam;
  // A 120 x 120 grid (the 1000 x 1000 grid is in the benchmark): 4 extreme points, 4 * 119
  // boundary points.
  std::vector<Vec2<T>> pts;
  for (int i = 0; i < 120; ++i)
    for (int j = 0; j < 120; ++j) pts.push_back({T((i * 53) % 120), T(j)});
  for (auto m : kMethods) {
    const Hull2Result r = hull(pts, m);
    EXPECT_EQ(r.indices.size(), 4u);
    const Hull2Result k = hull(pts, m, true);
    EXPECT_EQ(k.indices.size(), 4u * 119u);
  }
  check_all(pts);
}

// Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness problems" (2008),
// section 4.2 (values from /work/shared/research/reliability-perf.md A1.1).
TEST(Hull2Kettner, ClassroomExamples) {
  using V = Vec2<double>;
  const std::vector<V> a1{{7.3000000000000194, 7.3000000000000167},
                          {24.000000000000068, 24.000000000000071},
                          {24.00000000000005, 24.000000000000053},
                          {0.50000000000001621, 0.50000000000001243},
                          {8, 4},
                          {4, 9},
                          {15, 27},
                          {26, 25},
                          {19, 11}};
  // The paper: the exact hull is p4, p5, p9, p8, p7, p6 (1-based), counter-clockwise.
  for (auto m : kMethods) {
    const Hull2Result r = hull(a1, m);
    EXPECT_EQ(r.indices, (std::vector<std::uint32_t>{3, 4, 8, 7, 6, 5}));
  }
  check_oracle(a1);
  const std::vector<V> a2{{27.643564356435643, -21.881188118811881},
                          {83.366336633663366, 15.544554455445542},
                          {4.0, 4.0},
                          {73.415841584158414, 8.8613861386138595}};
  check_oracle(a2);
  const std::vector<V> b1{{200.0, 49.200000000000003},
                          {100.0, 49.600000000000001},
                          {-233.33333333333334, 50.93333333333333},
                          {166.66666666666669, 49.333333333333336}};
  check_oracle(b1);
  const std::vector<V> b2{{0.50000000000001243, 0.50000000000000189},
                          {0.50000000000001243, 0.50000000000000333},
                          {24.00000000000005, 24.000000000000053},
                          {24.000000000000068, 24.000000000000071},
                          {17.300000000000001, 17.300000000000001}};
  check_oracle(b2);
  const std::vector<V> g{{0.10000000000000001, 0.10000000000000001},
                         {0.20000000000000001, 0.20000000000000004},
                         {0.79999999999999993, 0.80000000000000004},
                         {1.267650600228229e30, 1.2676506002282291e30}};
  for (auto m : kMethods) EXPECT_EQ(hull(g, m).indices.size(), 4u);  // all strictly convex
  check_oracle(g);
  // The grid of figure 2 (near-collinear points around the line y = x), 24 x 24 ulp cells.
  std::vector<V> grid{{12, 12}, {24, 24}};
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) grid.push_back({0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53});
  check_all(grid);
}

// Random small sets against the brute-force oracle: reals, and small integer grids (collinear
// triples and duplicates everywhere).
TYPED_TEST(Hull2, RandomVsBruteForce) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 300; ++trial) {
    const int n = rng.uniform_int(1, 16);
    std::vector<Vec2<T>> pts;
    const int mode = trial % 3;
    for (int i = 0; i < n; ++i) {
      if (mode == 0)
        pts.push_back(rng.vec<T, 2>(T(-1), T(1)));
      else if (mode == 1)
        pts.push_back({T(rng.uniform_int(0, 3)), T(rng.uniform_int(0, 3))});
      else
        pts.push_back({T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-1, 1) * 2)});
    }
    SCOPED_TRACE(trial);
    check_oracle(pts);
  }
}

// Larger sets (filter and bucket sort active): methods agree and invariants hold exactly.
TYPED_TEST(Hull2, LargeSetsAgree) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const int n = 8000;
  std::vector<Vec2<T>> square, disk, circle, clustered;
  for (int i = 0; i < n; ++i) {
    square.push_back(rng.vec<T, 2>(T(0), T(1)));
    const auto u = rng.unit<T, 2>();
    circle.push_back(u * T(1000));
    disk.push_back(u * std::sqrt(rng.uniform<T>(T(0), T(1))));
    clustered.push_back(Vec2<T>{T(rng.uniform_int(0, 3)), T(0)} + rng.vec<T, 2>(T(0), T(1e-3)));
  }
  check_all(square);
  check_all(disk);
  check_all(circle);
  check_all(clustered);
}

// Sets large enough for the two-level key sort (more than 2^15 points to sort): on a circle
// every point survives the filter; snapped to a coarse grid the circle has duplicates, equal y and
// collinear boundary points; few rows give long runs of equal keys; a y range of a few
// subnormals (double) cannot be scaled to keys and takes the other sort. The methods share that
// sort, so the exact invariants of check_hull (convex, winding once, containing every point,
// every boundary point listed) and the smallest-index representatives are the oracle.
TYPED_TEST(Hull2, LargeSetsKeySort) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const int n = 36000;
  std::vector<std::vector<Vec2<T>>> sets(4);
  for (int i = 0; i < n; ++i) {
    const auto u = rng.unit<T, 2>();
    sets[0].push_back(u);
    sets[1].push_back({std::round(u.x * T(300)) / T(64), std::round(u.y * T(300)) / T(64)});
    sets[2].push_back({rng.uniform<T>(T(-1), T(1)), T(rng.uniform_int(0, 3))});
    if constexpr (std::is_same_v<T, double>)
      sets[3].push_back({rng.uniform<T>(T(-1), T(1)), T(rng.uniform_int(0, 8)) * T(1e-310)});
  }
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const auto& pts = sets[k];
    if (pts.empty()) continue;
    std::map<std::pair<T, T>, std::uint32_t> first;
    for (std::uint32_t i = 0; i < pts.size(); ++i) first.emplace(std::pair{pts[i].x, pts[i].y}, i);
    for (bool keep : {false, true}) {
      const Hull2Result ref = hull(pts, Hull2Method::monotone_chain, keep);
      EXPECT_TRUE(check_hull(pts, ref, keep)) << "set " << k << " keep " << keep;
      for (auto i : ref.indices) EXPECT_EQ(first.at({pts[i].x, pts[i].y}), i);
      // One other method per case, alternating (the invariants above are the oracle; this keeps
      // the sanitizer run short).
      const auto m = (k + keep) % 2 ? Hull2Method::incremental : Hull2Method::divide_and_conquer;
      EXPECT_EQ(hull(pts, m, keep).indices, ref.indices) << "set " << k << " method " << int(m);
    }
  }
}

// Scaling by powers of two (exact) gives the same indices, down to tiny and up to huge
// coordinates; integer translation and the exact 90-degree rotation keep the same point set.
TYPED_TEST(Hull2, TransformInvariance) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec2<T>> pts;
  for (int i = 0; i < 3000; ++i)
    pts.push_back({T(rng.uniform_int(-100, 100)), T(rng.uniform_int(-60, 60))});
  // Dyadic reals with few bits, so the translations below are exact in float too.
  for (int i = 0; i < 300; ++i)
    pts.push_back(
        {T(rng.uniform_int(-6400, 6400)) / T(64), T(rng.uniform_int(-6400, 6400)) / T(64)});
  const Hull2Result ref = hull(pts, Hull2Method::monotone_chain, true);
  ASSERT_TRUE(check_hull(pts, ref, true));
  const int e = std::is_same_v<T, float> ? 100 : 450;
  for (int s : {e, -e}) {
    std::vector<Vec2<T>> q = pts;
    for (auto& p : q) p = {std::ldexp(p.x, s), std::ldexp(p.y, s)};
    for (auto m : kMethods) EXPECT_EQ(hull(q, m, true).indices, ref.indices) << s;
  }
  std::vector<Vec2<T>> rot = pts, tr = pts;
  for (auto& p : rot) p = {-p.y, p.x};
  for (auto& p : tr) p = {p.x + T(1024), p.y - T(4096)};
  const auto as_set = [](const Hull2Result& r) {
    return std::set<std::uint32_t>(r.indices.begin(), r.indices.end());
  };
  for (auto m : kMethods) {
    EXPECT_EQ(as_set(hull(rot, m, true)), as_set(ref));
    EXPECT_EQ(hull(tr, m, true).indices, ref.indices);
  }
  // Permutation (reversal): the same points, so the same hull up to index renaming.
  std::vector<Vec2<T>> rev(pts.rbegin(), pts.rend());
  const Hull2Result rr = hull(rev, Hull2Method::monotone_chain);
  const Hull2Result r0 = hull(pts, Hull2Method::monotone_chain);
  ASSERT_EQ(rr.indices.size(), r0.indices.size());
  for (std::size_t i = 0; i < r0.indices.size(); ++i)
    EXPECT_TRUE(rev[rr.indices[i]] == pts[r0.indices[i]]);
}

TYPED_TEST(Hull2, ReusableBuilder) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  locus::ConvexHull2<T> builder;
  Hull2Result out;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec2<T>> pts;
    const int n = rng.uniform_int(0, 3000);
    for (int i = 0; i < n; ++i) pts.push_back(rng.vec<T, 2>(T(-1), T(1)));
    for (auto m : kMethods) {
      const Hull2Options o{trial % 2 == 0, m};
      builder.compute(std::span<const Vec2<T>>(pts), o, out);
      const Hull2Result fresh = locus::convex_hull(pts, o);
      EXPECT_EQ(out.status, fresh.status);
      EXPECT_EQ(out.indices, fresh.indices);
    }
  }
}

}  // namespace
