// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/polygon.hpp (row prim2.polyline, polygons; book figures 5.9, 5.10, 5.12).
#include <locus/primitives/polygon.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class PolygonTest : public ::testing::Test {};
TYPED_TEST_SUITE(PolygonTest, locus_test::RealTypes);

namespace {

// ---- independent exact oracles (GMP rationals, brute force) ----------------------------------

template <class T>
int gmp_orient(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c) {
  // A long double filter with a generous error bound settles clear cases quickly; GMP decides
  // the rest exactly.
  using L = long double;
  const L d1 = (L(b.x) - L(a.x)) * (L(c.y) - L(a.y)), d2 = (L(b.y) - L(a.y)) * (L(c.x) - L(a.x));
  const L bound = (std::abs(d1) + std::abs(d2)) * L(8) * std::numeric_limits<double>::epsilon();
  if (d1 - d2 > bound) return 1;
  if (d2 - d1 > bound) return -1;
  const mpq_class det = (mpq_class(b.x) - a.x) * (mpq_class(c.y) - a.y) -
                        (mpq_class(b.y) - a.y) * (mpq_class(c.x) - a.x);
  return sgn(det);
}

// p on the closed segment [a, b] (exact).
template <class T>
bool gmp_on_segment(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& p) {
  if (a == b) return p == a;
  if (gmp_orient(a, b, p) != 0) return false;
  const mpq_class t = (mpq_class(p.x) - a.x) * (mpq_class(b.x) - a.x) +
                      (mpq_class(p.y) - a.y) * (mpq_class(b.y) - a.y);
  const mpq_class len2 = (mpq_class(b.x) - a.x) * (mpq_class(b.x) - a.x) +
                         (mpq_class(b.y) - a.y) * (mpq_class(b.y) - a.y);
  return t >= 0 && t <= len2;
}

template <class T>
bool gmp_segments_meet(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c, const Vec2<T>& d) {
  const int o1 = gmp_orient(a, b, c), o2 = gmp_orient(a, b, d), o3 = gmp_orient(c, d, a),
            o4 = gmp_orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return gmp_on_segment(a, b, c) || gmp_on_segment(a, b, d) || gmp_on_segment(c, d, a) ||
         gmp_on_segment(c, d, b);
}

template <class T>
std::vector<Vec2<T>> dedupe(const std::vector<Vec2<T>>& v) {
  std::vector<Vec2<T>> out;
  for (const auto& p : v)
    if (out.empty() || !(out.back() == p)) out.push_back(p);
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

// O(n^2) simplicity: adjacent edges may share only their common vertex, others nothing.
template <class T>
bool brute_simple(const std::vector<Vec2<T>>& raw) {
  const auto v = dedupe(raw);
  const std::size_t m = v.size();
  if (m < 3) return false;
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = i + 1; j < m; ++j) {
      const Vec2<T>&a = v[i], &b = v[(i + 1) % m], &c = v[j], &d = v[(j + 1) % m];
      const bool adj_ij = (i + 1) % m == j, adj_ji = (j + 1) % m == i;
      if (adj_ij || adj_ji) {
        // Shared vertex s; they overlap iff the far end of one lies on the other (not at s).
        const Vec2<T>& s = adj_ij ? b : a;
        const Vec2<T>& e_far = adj_ij ? a : b;  // far end of edge i
        const Vec2<T>& f_far = adj_ij ? d : c;  // far end of edge j
        if ((gmp_on_segment(s, e_far, f_far) && !(f_far == s)) ||
            (gmp_on_segment(s, f_far, e_far) && !(e_far == s)))
          return false;
        if (adj_ij && adj_ji && m == 2) return false;
        continue;
      }
      if (gmp_segments_meet(a, b, c, d)) return false;
    }
  }
  return true;
}

// Weak convexity: simple, not all collinear, and for every edge all vertices on one side,
// consistently for all edges.
template <class T>
bool brute_convex(const std::vector<Vec2<T>>& raw) {
  if (!brute_simple(raw)) return false;
  const auto v = dedupe(raw);
  const std::size_t m = v.size();
  int side = 0;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t k = 0; k < m; ++k) {
      const int s = gmp_orient(v[i], v[(i + 1) % m], v[k]);
      if (s == 0) continue;
      if (side == 0)
        side = s;
      else if (s != side)
        return false;
    }
  return side != 0;
}

template <class T>
mpq_class gmp_twice_area(const std::vector<Vec2<T>>& v) {
  mpq_class s = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto& a = v[i];
    const auto& b = v[(i + 1) % v.size()];
    s += mpq_class(a.x) * b.y - mpq_class(a.y) * b.x;
  }
  return s;
}

template <class T>
mpq_class gmp_proj(const Vec2<T>& p, const Vec2<T>& d) {
  return mpq_class(p.x) * d.x + mpq_class(p.y) * d.y;
}

// O(n^3) monotone polygon: some split i -> j non-decreasing and j -> i non-increasing.
template <class T>
bool brute_monotone(const std::vector<Vec2<T>>& v, const Vec2<T>& d) {
  const std::size_t n = v.size();
  if (n < 3) return false;
  std::vector<mpq_class> pr(n);
  for (std::size_t i = 0; i < n; ++i) pr[i] = gmp_proj(v[i], d);
  bool all_equal = true;
  for (std::size_t i = 1; i < n; ++i) all_equal = all_equal && pr[i] == pr[0];
  if (all_equal) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      bool ok = true;
      for (std::size_t k = i; k != j && ok; k = (k + 1) % n) ok = pr[k] <= pr[(k + 1) % n];
      for (std::size_t k = j; k != i && ok; k = (k + 1) % n) ok = pr[k] >= pr[(k + 1) % n];
      if (ok) return true;
    }
  return false;
}

template <class T>
std::vector<Vec2<T>> star_polygon(Rng& rng, int n, T r_min, T r_max) {
  // Jittered, evenly spaced angles: consecutive gaps stay below pi, so the origin is strictly
  // inside every fan triangle (origin, v_i, v_i+1): star-shaped with the origin in the kernel,
  // hence simple and counter-clockwise.
  std::vector<T> ang;
  for (int i = 0; i < n; ++i)
    ang.push_back((T(i) + T(0.45) * rng.uniform<T>(0, 1)) * T(2) * pi_v<T> / T(n));
  std::vector<Vec2<T>> v;
  for (T a : ang) {
    const T r = rng.uniform<T>(r_min, r_max);
    v.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return v;
}

template <class T>
std::vector<Vec2<T>> random_polygon(Rng& rng, int kind) {
  std::vector<Vec2<T>> v;
  const int n = rng.uniform_int(3, 8);
  switch (kind) {
    case 0: {  // a tiny integer grid: shared vertices, collinear overlaps, duplicates
      for (int i = 0; i < n; ++i) v.push_back({T(rng.uniform_int(0, 3)), T(rng.uniform_int(0, 3))});
      break;
    }
    case 1: {  // the same grid mapped by a rounded affine map (exact predicates still decide)
      const T s = rng.uniform<T>(T(0.05), T(3)), ox = rng.uniform<T>(-5, 5),
              oy = rng.uniform<T>(-5, 5);
      for (int i = 0; i < n; ++i)
        v.push_back({T(rng.uniform_int(0, 4)) * s + ox, T(rng.uniform_int(0, 4)) * s + oy});
      break;
    }
    case 2: {  // generic random points
      for (int i = 0; i < n; ++i) v.push_back(rng.vec<T, 2>(-1, 1));
      break;
    }
    default: {  // star-shaped (simple) around the origin, sometimes with one vertex moved
      v = star_polygon<T>(rng, n + 2, T(0.3), T(1));
      if (rng.uniform_int(0, 1) && v.size() >= 3)
        v[static_cast<std::size_t>(rng.uniform_int(0, int(v.size()) - 1))] = rng.vec<T, 2>(-1, 1);
      break;
    }
  }
  return v;
}

}  // namespace

// ---- book figures --------------------------------------------------------------------------

// Figure 5.9: (a) a simple concave polygon, (b) a simple convex polygon.
TYPED_TEST(PolygonTest, Fig5_9_SimpleConcaveAndConvex) {
  using T = TypeParam;
  const Polygon2<T> concave{{{T(0), T(0)}, {T(4), T(0)}, {T(4), T(3)}, {T(2), T(1)}, {T(0), T(3)}}};
  EXPECT_TRUE(is_simple(concave));
  EXPECT_FALSE(is_convex(concave));
  EXPECT_EQ(orientation(concave), Sign::positive);
  EXPECT_EQ(signed_area(concave), T(12 - 4));
  const Polygon2<T> convex{{{T(0), T(0)}, {T(4), T(0)}, {T(5), T(2)}, {T(2), T(4)}, {T(-1), T(2)}}};
  EXPECT_TRUE(is_simple(convex));
  EXPECT_TRUE(is_convex(convex));
  EXPECT_EQ(orientation(convex), Sign::positive);
  Polygon2<T> cw = convex;
  std::reverse(cw.vertices.begin(), cw.vertices.end());
  EXPECT_TRUE(is_convex(cw));
  EXPECT_EQ(orientation(cw), Sign::negative);
  EXPECT_EQ(signed_area(cw), -signed_area(convex));
  // Collinear consecutive vertices keep it (weakly) convex; a duplicate vertex changes nothing.
  Polygon2<T> with_mid{
      {{T(0), T(0)}, {T(2), T(0)}, {T(4), T(0)}, {T(4), T(4)}, {T(4), T(4)}, {T(0), T(4)}}};
  EXPECT_TRUE(is_convex(with_mid));
  EXPECT_TRUE(is_simple(with_mid));
  EXPECT_EQ(area(with_mid), T(16));
}

// Figure 5.10: nonsimple polygons. (a) Two edges cross at a point that is not a vertex.
// (b) Two parts touch at a vertex (a polysolid).
TYPED_TEST(PolygonTest, Fig5_10_NonsimplePolygons) {
  using T = TypeParam;
  const Polygon2<T> bowtie{{{T(0), T(0)}, {T(2), T(2)}, {T(2), T(0)}, {T(0), T(2)}}};
  EXPECT_FALSE(is_simple(bowtie));
  const auto x = self_intersection(bowtie);
  ASSERT_TRUE(x.has_value());
  EXPECT_EQ(x->first, 0u);
  EXPECT_EQ(x->second, 2u);
  EXPECT_FALSE(is_convex(bowtie));
  // Two triangles sharing the vertex (2, 1).
  const Polygon2<T> touching{
      {{T(0), T(0)}, {T(2), T(1)}, {T(4), T(0)}, {T(4), T(2)}, {T(2), T(1)}, {T(0), T(2)}}};
  EXPECT_FALSE(is_simple(touching));
  const auto y = self_intersection(touching);
  ASSERT_TRUE(y.has_value());
  EXPECT_TRUE(brute_simple<T>({}) == false);
  // The reported edges are non-adjacent and both contain the shared vertex.
  const auto& tv = touching.vertices;
  for (std::size_t e : {y->first, y->second}) {
    EXPECT_TRUE(gmp_on_segment(tv[e], tv[(e + 1) % tv.size()], Vec2<T>{T(2), T(1)}));
  }
  // A pentagram turns left at every vertex but winds twice: not convex, not simple.
  std::vector<Vec2<T>> star;
  for (int i = 0; i < 5; ++i) {
    const T a = T(2) * pi_v<T> * T(2 * i) / T(5);
    star.push_back({std::cos(a), std::sin(a)});
  }
  EXPECT_FALSE(polygon_is_convex<T>(star));
  EXPECT_FALSE(polygon_is_simple<T>(star));
  // A square traversed twice: every turn is left, the boundary winds twice.
  const std::vector<Vec2<T>> twice{{T(0), T(0)}, {T(1), T(0)}, {T(1), T(1)}, {T(0), T(1)},
                                   {T(0), T(0)}, {T(1), T(0)}, {T(1), T(1)}, {T(0), T(1)}};
  EXPECT_FALSE(polygon_is_convex<T>(twice));
  EXPECT_FALSE(polygon_is_simple<T>(twice));
  // A spike (collinear fold-back) is neither simple nor convex.
  const std::vector<Vec2<T>> spike{
      {T(0), T(0)}, {T(2), T(0)}, {T(3), T(0)}, {T(1), T(0)}, {T(1), T(2)}};
  EXPECT_FALSE(polygon_is_simple<T>(spike));
  EXPECT_FALSE(polygon_is_convex<T>(spike));
}

// Figure 5.12: a polygon monotone with respect to the x-axis, split at its leftmost and
// rightmost vertices into an upper and a lower chain; a comb is not monotone.
TYPED_TEST(PolygonTest, Fig5_12_MonotonePolygon) {
  using T = TypeParam;
  const Vec2<T> x{T(1), T(0)};
  const Polygon2<T> mono{{{T(0), T(1)},
                          {T(2), T(0)},
                          {T(3), T(1)},
                          {T(5), T(0)},
                          {T(7), T(2)},
                          {T(5), T(4)},
                          {T(4), T(3)},
                          {T(2), T(4)},
                          {T(1), T(3)}}};
  const MonotoneSplit s = monotone_split(mono, x);
  EXPECT_TRUE(s.monotone);
  EXPECT_EQ(s.min_vertex, 0u);
  EXPECT_EQ(s.max_vertex, 4u);
  EXPECT_TRUE(is_simple(mono));
  EXPECT_FALSE(is_monotone(mono, Vec2<T>{T(0), T(1)}));
  // With a vertical edge at the left (a plateau of the projection) it is still monotone.
  const Polygon2<T> plateau{{{T(0), T(0)}, {T(3), T(1)}, {T(6), T(0)}, {T(6), T(3)}, {T(0), T(3)}}};
  EXPECT_TRUE(is_monotone(plateau, x));
  const Polygon2<T> comb{{{T(0), T(0)},
                          {T(6), T(0)},
                          {T(6), T(3)},
                          {T(5), T(1)},
                          {T(4), T(3)},
                          {T(3), T(1)},
                          {T(2), T(3)},
                          {T(1), T(1)},
                          {T(0), T(3)}}};
  EXPECT_TRUE(is_monotone(comb, x));  // teeth along y: every vertical line meets it twice
  EXPECT_FALSE(is_monotone(comb, Vec2<T>{T(0), T(1)}));
  // A "C" opening to the right is monotone along y but not along x.
  const Polygon2<T> c_shape{{{T(0), T(0)},
                             {T(4), T(0)},
                             {T(4), T(1)},
                             {T(1), T(1)},
                             {T(1), T(3)},
                             {T(4), T(3)},
                             {T(4), T(4)},
                             {T(0), T(4)}}};
  EXPECT_FALSE(is_monotone(c_shape, x));
  EXPECT_TRUE(is_monotone(c_shape, Vec2<T>{T(0), T(1)}));
  EXPECT_TRUE(is_simple(comb));
}

// ---- oracle comparisons ----------------------------------------------------------------------

// Simplicity: the O(n log n) sweep against the O(n^2) GMP brute force on 10^4 small polygons
// (5000 per scalar type), most of them full of degeneracies (shared vertices, collinear
// overlaps, duplicates), each also reversed and rotated.
TYPED_TEST(PolygonTest, SimplicityMatchesBruteForce) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + (std::is_same_v<T, float> ? 0 : 1));
  SCOPED_TRACE(rng.trace());
  int simple = 0, nonsimple = 0;
  for (int it = 0; it < 5000; ++it) {
    const std::vector<Vec2<T>> v = random_polygon<T>(rng, it % 4);
    const bool expect = brute_simple(v);
    const auto got = polygon_self_intersection<T>(v);
    ASSERT_EQ(!got.has_value(), expect) << "case " << it << " kind " << it % 4 << " n " << v.size();
    if (got && dedupe(v).size() >= 3) {
      // The reported original edges really conflict.
      const std::size_t n = v.size(), i = got->first, j = got->second;
      const Vec2<T>&a = v[i], &b = v[(i + 1) % n], &c = v[j], &d = v[(j + 1) % n];
      EXPECT_FALSE(a == b);
      EXPECT_FALSE(c == d);
      EXPECT_TRUE(gmp_segments_meet(a, b, c, d));
    }
    (expect ? simple : nonsimple)++;
    // Invariance: reversal and a cyclic shift of the start vertex.
    std::vector<Vec2<T>> r(v.rbegin(), v.rend());
    EXPECT_EQ(polygon_is_simple<T>(r), expect);
    std::rotate(r.begin(), r.begin() + 1, r.end());
    EXPECT_EQ(polygon_is_simple<T>(r), expect);
  }
  EXPECT_GT(simple, 1000);
  EXPECT_GT(nonsimple, 1000);
}

// Larger polygons: star-shaped (simple) with a few hundred vertices, then one vertex moved.
TYPED_TEST(PolygonTest, SimplicityOnLargerPolygons) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 4; ++it) {
    std::vector<Vec2<T>> v = star_polygon<T>(rng, 150, T(0.5), T(1));
    EXPECT_TRUE(polygon_is_simple<T>(v));
    EXPECT_TRUE(brute_simple(v));
    v[static_cast<std::size_t>(rng.uniform_int(0, int(v.size()) - 1))] = rng.vec<T, 2>(-1, 1);
    EXPECT_EQ(polygon_is_simple<T>(v), brute_simple(v));
  }
}

// Convexity against the brute-force hull check, on convex polygons built from circles (with
// collinear midpoints, duplicates, reversed order, double winding) and random ones.
TYPED_TEST(PolygonTest, ConvexityMatchesBruteForceHullCheck) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int convex = 0, nonconvex = 0;
  for (int it = 0; it < 4000; ++it) {
    std::vector<Vec2<T>> v;
    const int kind = it % 6;
    if (kind <= 2) {
      // Points on a circle snapped to a grid: convex or nearly so (rounding can make dents).
      const int n = rng.uniform_int(3, 9);
      std::vector<T> ang;
      for (int i = 0; i < n; ++i) ang.push_back(rng.uniform<T>(0, T(2) * pi_v<T>));
      std::sort(ang.begin(), ang.end());
      const T grid = kind == 0 ? T(1) : T(64);
      for (T a : ang)
        v.push_back({std::round(T(8) * std::cos(a) * grid) / grid,
                     std::round(T(8) * std::sin(a) * grid) / grid});
      if (kind == 1 && v.size() >= 2) {  // insert an exact midpoint on an edge (collinear)
        const std::size_t k = static_cast<std::size_t>(rng.uniform_int(0, int(v.size()) - 1));
        const Vec2<T> mid = T(0.5) * (v[k] + v[(k + 1) % v.size()]);
        v.insert(v.begin() + static_cast<std::ptrdiff_t>(k) + 1, mid);
      }
      if (kind == 2 && !v.empty())
        v.insert(v.begin() + rng.uniform_int(0, int(v.size()) - 1), v[0]);  // duplicate
      if (rng.uniform_int(0, 1)) std::reverse(v.begin(), v.end());
      if (rng.uniform_int(0, 9) == 0) {  // wind twice
        const auto w = v;
        v.insert(v.end(), w.begin(), w.end());
      }
    } else {
      v = random_polygon<T>(rng, kind - 3);
    }
    const bool expect = brute_convex(v);
    ASSERT_EQ(polygon_is_convex<T>(v), expect) << "case " << it;
    (expect ? convex : nonconvex)++;
    std::rotate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    EXPECT_EQ(polygon_is_convex<T>(v), expect);
  }
  EXPECT_GT(convex, 1000);
  EXPECT_GT(nonconvex, 1000);
}

// Area against the exact GMP shoelace; orientation against the exact area sign for simple
// polygons; centroid against a triangulation from the kernel point of star-shaped polygons.
TYPED_TEST(PolygonTest, AreaOrientationCentroidAgainstExactAndSecondAlgorithm) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int checked_orientation = 0;
  for (int it = 0; it < 3000; ++it) {
    std::vector<Vec2<T>> v = random_polygon<T>(rng, it % 4);
    // Shift far from the origin: the relative-to-first-vertex shoelace must not care.
    const Vec2<T> off{T(rng.uniform_int(-1000, 1000)), T(rng.uniform_int(-1000, 1000))};
    for (auto& p : v) p += off;
    const mpq_class exact2 = gmp_twice_area(v);
    // Bound: each fan term perp_dot(v_i - v_0, v_{i+1} - v_0) carries a few roundings of its
    // own magnitude (differences exact or rounded once, products, the subtraction) and the
    // accumulation n more: (n + 6) eps * sum |terms| (terms bounded by diameter^2 <= 4 * 10).
    const double bound = double(tol<T>(T(v.size() + 6), T(40) * T(v.size())));
    EXPECT_NEAR(double(polygon_signed_area<T>(v)), exact2.get_d() / 2, bound);
    if (brute_simple(v)) {
      EXPECT_EQ(to_int(polygon_orientation<T>(v)), sgn(exact2)) << "case " << it;
      ++checked_orientation;
    }
  }
  EXPECT_GT(checked_orientation, 500);
  for (int it = 0; it < 1000; ++it) {
    const std::vector<Vec2<T>> v = star_polygon<T>(rng, rng.uniform_int(3, 30), T(0.2), T(2));
    if (v.size() < 3) continue;
    // Second algorithm: triangles (0, v_i, v_{i+1}) around the kernel point, in long double.
    long double a = 0, cx = 0, cy = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const auto& p = v[i];
      const auto& q = v[(i + 1) % v.size()];
      const long double w = (long double)p.x * q.y - (long double)p.y * q.x;
      a += w;
      cx += w * ((long double)p.x + q.x);
      cy += w * ((long double)p.y + q.y);
    }
    const Vec2<T> c = polygon_centroid<T>(v);
    const T scale = T(2) * T(2) / std::max(T(a / 2), T(1e-3));  // error ~ eps * R^3 / area
    EXPECT_NEAR(c.x, T(cx / (3 * a)), tol<T>(64, scale));
    EXPECT_NEAR(c.y, T(cy / (3 * a)), tol<T>(64, scale));
    EXPECT_EQ(polygon_orientation<T>(v), Sign::positive);
    EXPECT_TRUE(polygon_is_simple<T>(v));
    EXPECT_NEAR(polygon_perimeter<T>(v), (polyline_length<T, 2>(v, true)), tol<T>(4, T(100)));
  }
}

// Monotone polygons against the O(n^3) GMP brute force; the returned split is valid.
TYPED_TEST(PolygonTest, MonotonePolygonMatchesBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int mono = 0, nonmono = 0;
  for (int it = 0; it < 4000; ++it) {
    const std::vector<Vec2<T>> v = random_polygon<T>(rng, it % 4);
    Vec2<T> d{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2))};
    if (it % 3 == 0) d = rng.vec<T, 2>(-1, 1);
    if (d == Vec2<T>{}) d = Vec2<T>{T(1), T(0)};
    const bool expect = brute_monotone(v, d);
    const MonotoneSplit s = polygon_monotone_split<T>(v, d);
    ASSERT_EQ(s.monotone, expect) << "case " << it;
    if (s.monotone) {
      const std::size_t n = v.size();
      for (std::size_t k = s.min_vertex; k != s.max_vertex; k = (k + 1) % n)
        EXPECT_LE(gmp_proj(v[k], d), gmp_proj(v[(k + 1) % n], d));
      for (std::size_t k = s.max_vertex; k != s.min_vertex; k = (k + 1) % n)
        EXPECT_GE(gmp_proj(v[k], d), gmp_proj(v[(k + 1) % n], d));
    }
    (expect ? mono : nonmono)++;
  }
  EXPECT_GT(mono, 500);
  EXPECT_GT(nonmono, 500);
}

// The exact closed-segment test against GMP on grid segments (touching, collinear overlap,
// degenerate point segments) and random ones.
TYPED_TEST(PolygonTest, SegmentsIntersectExactMatchesGmp) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int meet = 0, apart = 0;
  for (int it = 0; it < 20000; ++it) {
    Vec2<T> p[4];
    for (auto& q : p) {
      q = it % 2 ? rng.vec<T, 2>(-1, 1)
                 : Vec2<T>{T(rng.uniform_int(0, 3)), T(rng.uniform_int(0, 3))};
    }
    const bool expect = gmp_segments_meet(p[0], p[1], p[2], p[3]);
    EXPECT_EQ(segments_intersect_exact(p[0], p[1], p[2], p[3]), expect)
        << p[0].x << "," << p[0].y << " " << p[1].x << "," << p[1].y << " " << p[2].x << ","
        << p[2].y << " " << p[3].x << "," << p[3].y;
    EXPECT_EQ(segments_intersect_exact(p[3], p[2], p[1], p[0]), expect);
    (expect ? meet : apart)++;
  }
  EXPECT_GT(meet, 3000);
  EXPECT_GT(apart, 3000);
}

// ---- degenerate input, holes ---------------------------------------------------------------

TYPED_TEST(PolygonTest, DegeneratePolygons) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  for (const std::vector<Vec2<T>>& v :
       {std::vector<Vec2<T>>{}, std::vector<Vec2<T>>{{T(1), T(1)}},
        std::vector<Vec2<T>>{{T(0), T(0)}, {T(1), T(1)}},
        std::vector<Vec2<T>>{{T(1), T(1)}, {T(1), T(1)}, {T(1), T(1)}},
        std::vector<Vec2<T>>{{T(0), T(0)}, {T(1), T(1)}, {T(0), T(0)}},
        std::vector<Vec2<T>>{{T(0), T(0)}, {T(1), T(0)}, {T(2), T(0)}}}) {
    EXPECT_EQ(polygon_area<T>(v), T(0));
    EXPECT_FALSE(polygon_is_simple<T>(v));
    EXPECT_FALSE(polygon_is_convex<T>(v));
    EXPECT_EQ(polygon_orientation<T>(v), Sign::zero);
  }
  EXPECT_EQ(polygon_centroid<T>(std::vector<Vec2<T>>{}), (Vec2<T>{}));
  EXPECT_EQ(polygon_centroid<T>(std::vector<Vec2<T>>{{T(0), T(0)}, {T(2), T(0)}, {T(4), T(0)}}),
            (Vec2<T>{T(2), T(0)}));
  const std::vector<Vec2<T>> bad{{T(0), T(0)}, {nan, T(0)}, {T(0), T(1)}};
  EXPECT_FALSE(polygon_is_simple<T>(bad));
  EXPECT_FALSE(polygon_is_convex<T>(bad));
  EXPECT_EQ(polygon_orientation<T>(bad), Sign::zero);
  EXPECT_FALSE(polygon_is_monotone<T>(bad, Vec2<T>{T(1), T(0)}));
  EXPECT_FALSE(polygon_is_monotone<T>(
      std::vector<Vec2<T>>{{T(0), T(0)}, {T(1), T(0)}, {T(0), T(1)}}, Vec2<T>{}));
  // A spike at the lowest-leftmost vertex: orientation is undefined there (zero).
  const std::vector<Vec2<T>> spike{
      {T(0), T(0)}, {T(3), T(0)}, {T(1), T(0)}, {T(1), T(2)}, {T(2), T(0)}};
  EXPECT_EQ(polygon_orientation<T>(spike), Sign::zero);
  // A closed ring with the first vertex repeated at the end is the same polygon.
  const std::vector<Vec2<T>> ring{
      {T(0), T(0)}, {T(2), T(0)}, {T(2), T(2)}, {T(0), T(2)}, {T(0), T(0)}};
  EXPECT_TRUE(polygon_is_simple<T>(ring));
  EXPECT_TRUE(polygon_is_convex<T>(ring));
  EXPECT_EQ(polygon_area<T>(ring), T(4));
  EXPECT_EQ(polygon_orientation<T>(ring), Sign::positive);
}

TYPED_TEST(PolygonTest, PolygonWithHoles) {
  using T = TypeParam;
  PolygonWithHoles2<T> p;
  p.outer.vertices = {{T(0), T(0)}, {T(4), T(0)}, {T(4), T(4)}, {T(0), T(4)}};
  p.holes.push_back(Polygon2<T>{{{T(1), T(1)}, {T(1), T(2)}, {T(2), T(2)}, {T(2), T(1)}}});
  EXPECT_EQ(area(p), T(15));
  EXPECT_EQ(perimeter(p), T(20));
  // Centroid: (16 * (2, 2) - 1 * (1.5, 1.5)) / 15.
  EXPECT_TRUE(locus_test::vec_near(centroid(p), Vec2<T>{T(30.5) / T(15), T(30.5) / T(15)},
                                   tol<T>(8, T(4))));
  // A hole that fills everything: zero area; the centroid falls back to the outer one.
  PolygonWithHoles2<T> none{p.outer, {p.outer}};
  EXPECT_EQ(area(none), T(0));
  EXPECT_EQ(centroid(none), (Vec2<T>{T(2), T(2)}));
}
