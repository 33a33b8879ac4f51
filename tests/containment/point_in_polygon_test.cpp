// SPDX-License-Identifier: BSL-1.0
// Tests of containment/point_in_polygon.hpp (row cg.pip). Oracles: exact GMP rationals (edge
// membership, a quadrant-counting winding number, and the parity of crossings with a generic
// oblique ray, all independent of the library's half-open rule), the general test for the
// convex O(log n) one, the plain test for the slab locator.
#include <locus/containment/point_in_polygon.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace {

using locus::Polygon2;
using locus::PolygonWithHoles2;
using locus::Side;
using locus::Triangle2;
using locus::Vec2;
using locus_test::Rng;

template <class T>
class PointInPolygon : public ::testing::Test {};
TYPED_TEST_SUITE(PointInPolygon, locus_test::RealTypes);

// ---- exact oracle ----------------------------------------------------------------------------

struct Q2 {
  mpq_class x, y;
};
template <class T>
Q2 q(const Vec2<T>& v) {
  return {mpq_class(double(v.x)), mpq_class(double(v.y))};
}
int sgn(const mpq_class& v) { return mpq_sgn(v.get_mpq_t()); }
int orient(const Q2& a, const Q2& b, const Q2& c) {
  return sgn(mpq_class((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)));
}
bool on_segment(const Q2& a, const Q2& b, const Q2& p) {
  // The box test first: it is cheap and rejects almost every edge.
  if (!(std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
        p.y <= std::max(a.y, b.y)))
    return false;
  return orient(a, b, p) == 0;
}
// Winding number by quadrant counting: the quadrant of v - p (0..3 counter-clockwise) changes by
// +-1 along an edge, or by 2 when the edge jumps across p's diagonal, decided by orient.
int quadrant(const Q2& p, const Q2& v) {
  // 0: x > px, y >= py; 1: x <= px, y > py; 2: x < px, y <= py; 3: x >= px, y < py.
  if (v.x > p.x && v.y >= p.y) return 0;
  if (v.x <= p.x && v.y > p.y) return 1;
  if (v.x < p.x && v.y <= p.y) return 2;
  return 3;
}
int winding_oracle(const std::vector<Q2>& ring, const Q2& p) {
  int twice_quarters = 0;  // in quarter turns
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Q2& a = ring[i];
    const Q2& b = ring[(i + 1) % n];
    const int qa = quadrant(p, a), qb = quadrant(p, b);
    int d = (qb - qa + 4) % 4;
    if (d == 3) d = -1;
    if (d == 2) d = orient(a, b, p) > 0 ? 2 : -2;
    twice_quarters += d;
  }
  return twice_quarters / 4;
}
// Parity of crossings with the ray p + t (1, slope), t > 0, for a slope that avoids every vertex;
// the edges are closed, a crossing at an endpoint cannot happen.
int parity_oracle(const std::vector<std::vector<Q2>>& rings, const Q2& p) {
  for (int k = 1;; ++k) {
    const mpq_class slope(k, 7919);
    const Q2 far{p.x + 1, p.y + slope};
    bool degenerate = false;
    int count = 0;
    for (const auto& ring : rings) {
      const std::size_t n = ring.size();
      // Side of every vertex relative to the line through p with direction (1, slope).
      std::vector<int> side(n);
      for (std::size_t i = 0; i < n && !degenerate; ++i) {
        side[i] = orient(p, far, ring[i]);
        degenerate = side[i] == 0;
      }
      if (degenerate) break;
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        if (side[i] == side[j]) continue;
        const Q2& a = ring[i];
        const Q2& b = ring[j];
        // f(X) = orient(a, b, X) is affine: the crossing is at t = -f(p) / (f(far) - f(p)),
        // on the ray iff f(p) and f(far) - f(p) have opposite signs (f(p) != 0 unless p is on
        // the edge, which the caller excludes).
        const mpq_class fp = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        const mpq_class ff = (b.x - a.x) * (far.y - a.y) - (b.y - a.y) * (far.x - a.x);
        if (sgn(fp) != 0 && sgn(fp) * sgn(mpq_class(ff - fp)) < 0) ++count;
      }
    }
    if (!degenerate) return count & 1;
  }
}
Side oracle(const std::vector<std::vector<Q2>>& rings, const Q2& p) {
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i)
      if (on_segment(ring[i], ring[(i + 1) % ring.size()], p)) return Side::boundary;
  return parity_oracle(rings, p) ? Side::inside : Side::outside;
}

template <class T>
std::vector<Q2> qring(const std::vector<Vec2<T>>& v) {
  std::vector<Q2> r;
  for (const auto& x : v) r.push_back(q(x));
  return r;
}

template <class T>
Vec2<T> grid_point(Rng& rng, int lo, int hi, T scale) {
  return {T(rng.uniform_int(lo, hi)) * scale, T(rng.uniform_int(lo, hi)) * scale};
}

// A random polygon on an integer grid (simple or not): a star around the origin with sorted
// angles, or plain random vertices.
template <class T>
std::vector<Vec2<T>> random_polygon(Rng& rng, int n, int grid, T scale, bool star) {
  std::vector<Vec2<T>> v;
  for (int i = 0; i < n; ++i) v.push_back(grid_point<T>(rng, -grid, grid, scale));
  if (star)
    std::sort(v.begin(), v.end(), [](const Vec2<T>& a, const Vec2<T>& b) {
      return std::atan2(double(a.y), double(a.x)) < std::atan2(double(b.y), double(b.x));
    });
  return v;
}

// Exact monotone-chain convex hull (counter-clockwise), optionally with the edge midpoints
// inserted as collinear vertices.
template <class T>
std::vector<Vec2<T>> convex_hull(std::vector<Vec2<T>> p, bool midpoints) {
  std::sort(p.begin(), p.end(), [](const Vec2<T>& a, const Vec2<T>& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Vec2<T>> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && orient(q(h[k - 2]), q(h[k - 1]), q(p[i])) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && orient(q(h[k - 2]), q(h[k - 1]), q(p[i])) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  if (!midpoints) return h;
  std::vector<Vec2<T>> m;
  for (std::size_t i = 0; i < h.size(); ++i) {
    m.push_back(h[i]);
    m.push_back(T(0.5) * (h[i] + h[(i + 1) % h.size()]));  // exact: grid coordinates
  }
  return m;
}

// ---- triangle --------------------------------------------------------------------------------

TYPED_TEST(PointInPolygon, TriangleVsExactBarycentricOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int counts[3] = {0, 0, 0};
  for (int it = 0; it < 3000; ++it) {
    const Triangle2<T> t{grid_point<T>(rng, -6, 6, T(1)), grid_point<T>(rng, -6, 6, T(1)),
                         grid_point<T>(rng, -6, 6, T(1))};
    // Every fourth point is a vertex or an edge midpoint (exact on the grid).
    const Vec2<T> p = it % 4 == 0   ? t.v1
                      : it % 4 == 1 ? T(0.5) * (t.v2 + t.v0)
                                    : grid_point<T>(rng, -7, 7, T(1));
    const Side expect = oracle({qring(std::vector<Vec2<T>>{t.v0, t.v1, t.v2})}, q(p));
    ASSERT_EQ(locus::classify(p, t), expect) << it;
    ASSERT_EQ(locus::contains(t, p), expect != Side::outside);
    ++counts[int(expect) + 1];
  }
  EXPECT_GT(counts[0], 50);
  EXPECT_GT(counts[1], 50);  // boundary cases are common on the grid
  EXPECT_GT(counts[2], 50);
}

TYPED_TEST(PointInPolygon, DegenerateTriangleHasOnlyBoundary) {
  using T = TypeParam;
  const Triangle2<T> seg{{T(0), T(0)}, {T(2), T(2)}, {T(4), T(4)}};
  EXPECT_EQ(locus::classify(Vec2<T>{T(3), T(3)}, seg), Side::boundary);
  EXPECT_EQ(locus::classify(Vec2<T>{T(5), T(5)}, seg), Side::outside);
  EXPECT_EQ(locus::classify(Vec2<T>{T(1), T(2)}, seg), Side::outside);
  const Triangle2<T> pt{{T(1), T(1)}, {T(1), T(1)}, {T(1), T(1)}};
  EXPECT_EQ(locus::classify(Vec2<T>{T(1), T(1)}, pt), Side::boundary);
  EXPECT_EQ(locus::classify(Vec2<T>{T(1), T(0)}, pt), Side::outside);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Triangle2<T> ok{{T(0), T(0)}, {T(1), T(0)}, {T(0), T(1)}};
  EXPECT_EQ(locus::classify(Vec2<T>{nan, T(0.1)}, ok), Side::outside);
  EXPECT_EQ(locus::classify(Vec2<T>{std::numeric_limits<T>::infinity(), T(0)}, ok), Side::outside);
  const Triangle2<T> bad{{nan, T(0)}, {T(1), T(0)}, {T(0), T(1)}};
  EXPECT_NE(locus::classify(Vec2<T>{T(0.1), T(0.1)}, bad), Side::inside);
}

// ---- convex ------------------------------------------------------------------------------------

// Figure 13.13: P inside, Q outside a convex polygon.
TYPED_TEST(PointInPolygon, Figure13_13ConvexPolygon) {
  using T = TypeParam;
  const std::vector<Vec2<T>> v{{T(0), T(0)}, {T(4), T(-1)}, {T(7), T(1)},
                               {T(6), T(4)}, {T(3), T(5)},  {T(0), T(3)}};
  const std::span<const Vec2<T>> s(v);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(3), T(2)}, s), Side::inside);   // P
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(8), T(2)}, s), Side::outside);  // Q
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(2), T(-0.5)}, s), Side::boundary);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(6), T(4)}, s), Side::boundary);
  EXPECT_TRUE(locus::contains_convex(s, Vec2<T>{T(3), T(2)}));
}

TYPED_TEST(PointInPolygon, ConvexLogNMatchesGeneralAndOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int boundary = 0;
  for (int it = 0; it < 80; ++it) {
    std::vector<Vec2<T>> pts;
    const int m = rng.uniform_int(3, 30);
    for (int i = 0; i < m; ++i) pts.push_back(grid_point<T>(rng, -10, 10, T(2)));
    std::vector<Vec2<T>> h = convex_hull(pts, it % 3 == 0);
    if (h.size() < 3) continue;
    std::rotate(h.begin(), h.begin() + rng.uniform_int(0, int(h.size()) - 1), h.end());
    const std::vector<Q2> qr = qring(h);
    for (int k = 0; k < 60; ++k) {
      const Vec2<T> p = grid_point<T>(rng, -11, 11, T(2));
      const Side expect = oracle({qr}, q(p));
      ASSERT_EQ(locus::classify_convex(p, std::span<const Vec2<T>>(h)), expect) << it << " " << k;
      ASSERT_EQ(locus::classify_polygon(p, std::span<const Vec2<T>>(h)), expect);
      boundary += expect == Side::boundary;
    }
  }
  EXPECT_GT(boundary, 100);
}

TYPED_TEST(PointInPolygon, ConvexDegenerateInputs) {
  using T = TypeParam;
  std::vector<Vec2<T>> v;
  EXPECT_EQ(locus::classify_convex(Vec2<T>{}, std::span<const Vec2<T>>(v)), Side::outside);
  v = {{T(1), T(1)}};
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(1), T(1)}, std::span<const Vec2<T>>(v)),
            Side::boundary);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(1), T(2)}, std::span<const Vec2<T>>(v)),
            Side::outside);
  v = {{T(0), T(0)}, {T(2), T(0)}};
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(1), T(0)}, std::span<const Vec2<T>>(v)),
            Side::boundary);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(3), T(0)}, std::span<const Vec2<T>>(v)),
            Side::outside);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(1), T(1)}, std::span<const Vec2<T>>(v)),
            Side::outside);
  // Repeated vertices and v[0] in the middle of a straight edge.
  v = {{T(1), T(0)}, {T(1), T(0)}, {T(2), T(0)}, {T(2), T(2)},
       {T(0), T(2)}, {T(0), T(0)}, {T(1), T(0)}};
  const std::span<const Vec2<T>> s(v);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(1), T(1)}, s), Side::inside);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(0.5), T(0)}, s), Side::boundary);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(1.5), T(0)}, s), Side::boundary);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(3), T(0)}, s), Side::outside);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(-1), T(0)}, s), Side::outside);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(1), T(-1)}, s), Side::outside);
  EXPECT_EQ(locus::classify_convex(Vec2<T>{T(0), T(1)}, s), Side::boundary);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(locus::classify_convex(Vec2<T>{nan, T(1)}, s), Side::outside);
}

// ---- general polygons --------------------------------------------------------------------------

// Figure 13.14: the ray from P0 crosses edges transversally (5 crossings: inside); the ray from
// P1 runs through vertices and along horizontal edges.
TYPED_TEST(PointInPolygon, Figure13_14RayThroughVerticesAndEdges) {
  using T = TypeParam;
  // A comb: teeth with tips, valleys and horizontal runs on the line y = 2.
  const std::vector<Vec2<T>> v{{T(0), T(0)}, {T(12), T(0)}, {T(12), T(4)}, {T(10), T(2)},
                               {T(9), T(2)}, {T(8), T(4)},  {T(7), T(2)},  {T(6), T(4)},
                               {T(5), T(2)}, {T(4), T(2)},  {T(3), T(4)},  {T(2), T(2)},
                               {T(1), T(4)}, {T(0), T(4)}};
  const std::span<const Vec2<T>> s(v);
  const std::vector<Q2> qr = qring(v);
  // P0 at y = 3 crosses the teeth transversally.
  const Vec2<T> p0{T(0.5), T(3)};
  EXPECT_EQ(locus::classify_polygon(p0, s), Side::inside);
  EXPECT_EQ(locus::classify_polygon(p0, s), oracle({qr}, q(p0)));
  // P1 on y = 2: every point of the line, on vertices, horizontal edges and in between.
  for (int i = -2; i <= 28; ++i) {
    const Vec2<T> p1{T(i) * T(0.5), T(2)};
    EXPECT_EQ(locus::classify_polygon(p1, s), oracle({qr}, q(p1))) << i;
  }
  EXPECT_EQ(locus::classify_polygon(Vec2<T>{T(1.5), T(2)}, s), Side::inside);
  EXPECT_EQ(locus::classify_polygon(Vec2<T>{T(4.5), T(2)}, s), Side::boundary);
  EXPECT_EQ(locus::classify_polygon(Vec2<T>{T(13), T(2)}, s), Side::outside);
}

// Figure 13.15: points on left and right edges are both reported as boundary (the half-open
// crossing rule alone would call left-edge points inside and right-edge points outside).
TYPED_TEST(PointInPolygon, Figure13_15LeftAndRightEdges) {
  using T = TypeParam;
  const Polygon2<T> sq{{{T(0), T(0)}, {T(4), T(0)}, {T(4), T(4)}, {T(0), T(4)}}};
  EXPECT_EQ(locus::classify(Vec2<T>{T(0), T(2)}, sq), Side::boundary);  // P, left edge
  EXPECT_EQ(locus::classify(Vec2<T>{T(4), T(2)}, sq), Side::boundary);  // Q, right edge
  EXPECT_EQ(locus::classify(Vec2<T>{T(2), T(0)}, sq), Side::boundary);
  EXPECT_EQ(locus::classify(Vec2<T>{T(2), T(4)}, sq), Side::boundary);
  EXPECT_EQ(locus::classify(Vec2<T>{T(0), T(0)}, sq), Side::boundary);
  EXPECT_TRUE(locus::contains(sq, Vec2<T>{T(4), T(2)}));
  EXPECT_EQ(locus::classify(Vec2<T>{T(2), T(2)}, sq), Side::inside);
  EXPECT_EQ(locus::winding_number(Vec2<T>{T(2), T(2)}, std::span<const Vec2<T>>(sq.vertices)), 1);
}

// Figures 13.16 and 13.17: the tags along the horizontal line of P1 alternate consistently:
// walking the line, the classification changes only at boundary points.
TYPED_TEST(PointInPolygon, Figures13_16_17TagsAlongALine) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 40; ++it) {
    const auto v = random_polygon<T>(rng, 12, 6, T(1), true);
    const std::vector<Q2> qr = qring(v);
    const T y = T(rng.uniform_int(-6, 6));
    Side prev = Side::outside;
    for (int i = -16; i <= 16; ++i) {
      const Vec2<T> p{T(i) * T(0.5), y};
      const Side s = locus::classify_polygon(p, std::span<const Vec2<T>>(v));
      ASSERT_EQ(s, oracle({qr}, q(p)));
      // Two consecutive samples inside and outside: some edge separates them.
      if (s != prev && i > -16) {
        const Vec2<T> before{(T(i) - T(1)) * T(0.5), y};
        bool separated = false;
        for (std::size_t e = 0; e < v.size(); ++e)
          separated =
              separated || locus::segments_intersect_exact(before, p, v[e], v[(e + 1) % v.size()]);
        ASSERT_TRUE(separated) << i;
      }
      prev = s;
    }
  }
}

TYPED_TEST(PointInPolygon, GeneralPolygonVsExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int counts[3] = {0, 0, 0};
  for (int it = 0; it < 120; ++it) {
    const bool star = it % 2 == 0;
    const T scale = it % 4 < 2 ? T(1) : T(0.1);  // 0.1 is inexact: general floating input
    const auto v = random_polygon<T>(rng, rng.uniform_int(3, 25), 8, scale, star);
    const std::vector<Q2> qr = qring(v);
    const std::span<const Vec2<T>> s(v);
    for (int k = 0; k < 40; ++k) {
      const Vec2<T> p = k % 5 == 0 ? v[std::size_t(rng.uniform_int(0, int(v.size()) - 1))]
                                   : grid_point<T>(rng, -9, 9, scale);
      const Side expect = oracle({qr}, q(p));
      ASSERT_EQ(locus::classify_polygon(p, s), expect) << it << " " << k;
      if (expect != Side::boundary) {
        ASSERT_EQ(locus::winding_number(p, s), winding_oracle(qr, q(p))) << it << " " << k;
      }
      ++counts[int(expect) + 1];
    }
  }
  EXPECT_GT(counts[0], 500);
  EXPECT_GT(counts[1], 500);
  EXPECT_GT(counts[2], 500);
}

TYPED_TEST(PointInPolygon, HolesVsExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 60; ++it) {
    PolygonWithHoles2<T> poly;
    poly.outer.vertices = random_polygon<T>(rng, 10, 8, T(1), true);
    std::vector<std::vector<Q2>> rings{qring(poly.outer.vertices)};
    for (int h = 0; h < 2; ++h) {
      poly.holes.push_back({random_polygon<T>(rng, 5, 4, T(1), true)});
      rings.push_back(qring(poly.holes.back().vertices));
    }
    for (int k = 0; k < 50; ++k) {
      const Vec2<T> p = grid_point<T>(rng, -9, 9, T(1));
      ASSERT_EQ(locus::classify(p, poly), oracle(rings, q(p))) << it << " " << k;
    }
  }
}

TYPED_TEST(PointInPolygon, TransformInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 60; ++it) {
    const auto v = random_polygon<T>(rng, 12, 8, T(1), it % 2 == 0);
    auto rev = v;
    std::reverse(rev.begin(), rev.end());
    const Vec2<T> shift{T(rng.uniform_int(-50, 50)), T(rng.uniform_int(-50, 50))};
    std::vector<Vec2<T>> moved, swapped;
    for (const auto& x : v) {
      moved.push_back(x + shift);
      swapped.push_back({x.y, x.x});
    }
    for (int k = 0; k < 40; ++k) {
      const Vec2<T> p = grid_point<T>(rng, -9, 9, T(1));
      const Side s = locus::classify_polygon(p, std::span<const Vec2<T>>(v));
      ASSERT_EQ(locus::classify_polygon(p, std::span<const Vec2<T>>(rev)), s);
      ASSERT_EQ(locus::classify_polygon(p + shift, std::span<const Vec2<T>>(moved)), s);
      ASSERT_EQ(locus::classify_polygon(Vec2<T>{p.y, p.x}, std::span<const Vec2<T>>(swapped)), s);
    }
  }
}

TYPED_TEST(PointInPolygon, BadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T inf = std::numeric_limits<T>::infinity();
  const Polygon2<T> empty{};
  EXPECT_EQ(locus::classify(Vec2<T>{}, empty), Side::outside);
  EXPECT_FALSE(locus::contains(empty, Vec2<T>{}));
  const Polygon2<T> sq{{{T(0), T(0)}, {T(4), T(0)}, {T(4), T(4)}, {T(0), T(4)}}};
  EXPECT_EQ(locus::classify(Vec2<T>{nan, T(1)}, sq), Side::outside);
  EXPECT_EQ(locus::classify(Vec2<T>{T(1), inf}, sq), Side::outside);
  EXPECT_EQ(locus::winding_number(Vec2<T>{nan, T(1)}, std::span<const Vec2<T>>(sq.vertices)), 0);
  // A ring with a NaN vertex: its two edges are ignored, the rest still works, nothing hangs.
  const Polygon2<T> bad{{{T(0), T(0)}, {T(4), T(0)}, {nan, T(2)}, {T(4), T(4)}, {T(0), T(4)}}};
  (void)locus::classify(Vec2<T>{T(1), T(1)}, bad);
  EXPECT_EQ(locus::classify(Vec2<T>{T(0), T(1)}, bad), Side::boundary);
  const locus::PolygonLocator2<T> loc(bad);
  EXPECT_EQ(loc.status(), locus::Status::non_finite_input);
  EXPECT_EQ(loc.classify(Vec2<T>{T(1), T(1)}), Side::outside);
  const locus::PolygonLocator2<T> none(empty);
  EXPECT_EQ(none.status(), locus::Status::empty_input);
  EXPECT_FALSE(none.contains(Vec2<T>{}));
  // A single point and a flat ring.
  const Polygon2<T> flat{{{T(0), T(0)}, {T(2), T(0)}, {T(4), T(0)}}};
  EXPECT_EQ(locus::classify(Vec2<T>{T(3), T(0)}, flat), Side::boundary);
  EXPECT_EQ(locus::classify(Vec2<T>{T(3), T(1)}, flat), Side::outside);
  const locus::PolygonLocator2<T> lf(flat);
  EXPECT_EQ(lf.status(), locus::Status::ok);
  EXPECT_EQ(lf.classify(Vec2<T>{T(3), T(0)}), Side::boundary);
  EXPECT_EQ(lf.classify(Vec2<T>{T(5), T(0)}), Side::outside);
}

// ---- locator -----------------------------------------------------------------------------------

TYPED_TEST(PointInPolygon, LocatorMatchesPlainTestOn10kQueries) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 4; ++it) {
    PolygonWithHoles2<T> poly;
    poly.outer.vertices = random_polygon<T>(rng, 300, 40, T(1), it % 2 == 0);
    poly.holes.push_back({random_polygon<T>(rng, 40, 15, T(1), true)});
    const locus::PolygonLocator2<T> loc(poly);
    ASSERT_EQ(loc.status(), locus::Status::ok);
    EXPECT_LE(loc.entry_count(), 8 * 340u);  // the documented bound, 8 n (seed 9 gave 3074)
    int boundary = 0;
    for (int k = 0; k < 10000 / 4; ++k) {
      // Integer points hit vertices and edges; tenths are general.
      const Vec2<T> p = k % 2 ? grid_point<T>(rng, -41, 41, T(1))
                              : Vec2<T>{rng.uniform(T(-41), T(41)), rng.uniform(T(-41), T(41))};
      const Side s = locus::classify(p, poly);
      ASSERT_EQ(loc.classify(p), s) << it << " " << k;
      boundary += s == Side::boundary;
    }
    EXPECT_GT(boundary, 10);
  }
  // A single ring, and a convex polygon vs the O(log n) test.
  std::vector<Vec2<T>> pts;
  for (int i = 0; i < 200; ++i) pts.push_back(grid_point<T>(rng, -30, 30, T(1)));
  const Polygon2<T> hull{convex_hull(pts, true)};
  const locus::PolygonLocator2<T> lh(hull);
  for (int k = 0; k < 2000; ++k) {
    const Vec2<T> p = grid_point<T>(rng, -31, 31, T(1));
    ASSERT_EQ(lh.classify(p), locus::classify_convex(p, std::span<const Vec2<T>>(hull.vertices)));
  }
}

TYPED_TEST(PointInPolygon, LocatorEntriesStayWithinEightNForBoundaryStraddlingEdges) {
  using T = TypeParam;
  // Four full-height two-vertex rings (8 edges spanning the whole y-range [0, 195]) and 100 short
  // two-vertex rings (200 edges of height 0.5 centred on integers). n = 208 edges; the spans sum
  // to 8 + 200 * 0.5 / 195, so the slab count is floor(8 n / spans) = 195 and the slabs are
  // [j, j + 1): the tall edges fill 8 * 195 entries and every short edge straddles a slab
  // boundary and meets two slabs. That made 1960 entries, 9.4 n, against the documented 8 n.
  std::vector<std::vector<Vec2<T>>> rings;
  for (int k = 0; k < 4; ++k) rings.push_back({{T(-1 - k), T(0)}, {T(-1 - k), T(195)}});
  for (int k = 0; k < 100; ++k) {
    const T b = T(1 + (k % 194));
    rings.push_back({{T(k), b - T(0.25)}, {T(k) + T(0.5), b + T(0.25)}});
  }
  std::vector<std::span<const Vec2<T>>> spans;
  for (const auto& r : rings) spans.emplace_back(r);
  const locus::PolygonLocator2<T> loc{std::span<const std::span<const Vec2<T>>>(spans)};
  ASSERT_EQ(loc.status(), locus::Status::ok);
  EXPECT_LE(loc.entry_count(), 8 * 208u);
  // The answers are those of the plain even-odd test over the same rings.
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int q = 0; q < 4000; ++q) {
    const Vec2<T> p = q % 2 ? Vec2<T>{T(rng.uniform_int(-6, 102)) * T(0.25),
                                      T(rng.uniform_int(-2, 790)) * T(0.25)}
                            : Vec2<T>{rng.uniform(T(-6), T(102)), rng.uniform(T(-1), T(197))};
    bool on = false;
    int crossings = 0;
    for (const auto& r : rings) {
      const Side s = locus::classify_polygon(p, std::span<const Vec2<T>>(r));
      on = on || s == Side::boundary;
      crossings += s == Side::inside;
    }
    const Side want = on ? Side::boundary : (crossings & 1 ? Side::inside : Side::outside);
    ASSERT_EQ(loc.classify(p), want) << p.x << " " << p.y;
  }
}

}  // namespace
