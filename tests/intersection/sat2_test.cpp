// SPDX-License-Identifier: BSL-1.0
// Rows int2.sat-static and int2.sat-moving: convex polygons by separating axes
// (intersection/convex_polygon2.hpp, moving_convex2.hpp), float and double.
// Stationary oracle, exact in GMP rationals and independent of the library's method: the common
// set of two convex polygons is the convex hull of the vertices of each inside the other and the
// common points of every edge pair (Cramer's rule); its kind is its dimension, its vertices the
// hull's corners, its area the hull's; a second oracle, Sutherland-Hodgman in rationals, must give
// the same area. Checked: intersects() and the kind equal the exact ones; touching sets are
// exact input points; polygon vertices within the header's bound, counter-clockwise, as many as
// the exact corners, area within the bound; swapping the arguments gives the same answer.
// Moving oracle: the exact (GMP) entry and exit times of the same projection intervals (time
// within 5 eps t*), and an independent bisection on the exact stationary test at sampled times;
// the contact set lies on both moved polygons. Inputs: seeded random convex polygons (real and
// small-integer coordinates, many touching), triangles, rectangles, oriented boxes, points,
// segments, collinear vertex lists, empty ranges, NaN/Inf, power-of-two scaling.

#include <locus/core/predicates.hpp>
#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/moving_convex2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "support/typed.hpp"

#include <gmpxx.h>

namespace {

using namespace locus;
using locus_test::Rng;

// ---- exact oracle ---------------------------------------------------------------------------

struct Q {
  mpq_class x, y;
};
Q operator-(const Q& a, const Q& b) { return {a.x - b.x, a.y - b.y}; }
Q operator+(const Q& a, const Q& b) { return {a.x + b.x, a.y + b.y}; }
Q operator*(const mpq_class& s, const Q& a) { return {s * a.x, s * a.y}; }
bool operator==(const Q& a, const Q& b) { return a.x == b.x && a.y == b.y; }
bool qlt(const Q& a, const Q& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
mpq_class cross(const Q& a, const Q& b) { return a.x * b.y - a.y * b.x; }
int orient(const Q& a, const Q& b, const Q& c) { return sgn(cross(b - a, c - a)); }
template <class T>
Q q(const Vec2<T>& v) {
  return {mpq_class(double(v.x)), mpq_class(double(v.y))};
}
double dbl(const mpq_class& v) { return v.get_d(); }

/// Distinct corners of the convex hull, counter-clockwise (monotone chain, exact).
std::vector<Q> hull(std::vector<Q> p) {
  std::sort(p.begin(), p.end(), qlt);
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Q> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && orient(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && orient(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

mpq_class area(const std::vector<Q>& p) {
  mpq_class s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) s += cross(p[i], p[(i + 1) % p.size()]);
  return s / 2;
}

/// The exact polygon: its hull corners (1: a point, 2: a segment, >= 3: a region).
template <class T>
std::vector<Q> qpoly(const std::vector<Vec2<T>>& v) {
  std::vector<Q> p;
  for (const auto& x : v) p.push_back(q(x));
  return hull(p);
}

bool on_segment(const Q& a, const Q& b, const Q& x) {
  return orient(a, b, x) == 0 && std::min(a.x, b.x) <= x.x && x.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= x.y && x.y <= std::max(a.y, b.y);
}

bool contains(const std::vector<Q>& P, const Q& x) {
  if (P.size() == 1) return P[0] == x;
  if (P.size() == 2) return on_segment(P[0], P[1], x);
  for (std::size_t i = 0; i < P.size(); ++i)
    if (orient(P[i], P[(i + 1) % P.size()], x) < 0) return false;
  return true;
}

void edge_points(const Q& a, const Q& b, const Q& c, const Q& d, std::vector<Q>& out) {
  const mpq_class den = cross(b - a, d - c);
  if (den == 0) {
    for (const Q& x : {a, b})
      if (on_segment(c, d, x)) out.push_back(x);
    for (const Q& x : {c, d})
      if (on_segment(a, b, x)) out.push_back(x);
    return;
  }
  const mpq_class t = cross(c - a, d - c) / den, u = cross(c - a, b - a) / den;
  if (t >= 0 && t <= 1 && u >= 0 && u <= 1) out.push_back(a + t * (b - a));
}

/// The exact common set as hull corners (empty, 1, 2 or >= 3 points).
std::vector<Q> common(const std::vector<Q>& A, const std::vector<Q>& B) {
  std::vector<Q> c;
  for (const Q& x : A)
    if (contains(B, x)) c.push_back(x);
  for (const Q& x : B)
    if (contains(A, x)) c.push_back(x);
  const auto edges = [](const std::vector<Q>& P) {
    std::vector<std::pair<Q, Q>> e;
    if (P.size() == 2) e.push_back({P[0], P[1]});
    if (P.size() >= 3)
      for (std::size_t i = 0; i < P.size(); ++i) e.push_back({P[i], P[(i + 1) % P.size()]});
    return e;
  };
  for (const auto& [a, b] : edges(A))
    for (const auto& [cc, d] : edges(B)) edge_points(a, b, cc, d, c);
  return hull(c);
}

/// Sutherland-Hodgman in rationals (regions only): the area of A clipped by B.
mpq_class clipped_area(std::vector<Q> A, const std::vector<Q>& B) {
  for (std::size_t j = 0; j < B.size() && !A.empty(); ++j) {
    const Q &p = B[j], &r = B[(j + 1) % B.size()];
    std::vector<Q> out;
    for (std::size_t i = 0; i < A.size(); ++i) {
      const Q &s = A[i], &e = A[(i + 1) % A.size()];
      const mpq_class fs = cross(r - p, s - p), fe = cross(r - p, e - p);
      if (fs >= 0) out.push_back(s);
      if ((fs > 0 && fe < 0) || (fs < 0 && fe > 0)) out.push_back(s + (fs / (fs - fe)) * (e - s));
    }
    A = out;
  }
  return A.size() >= 3 ? area(A) : mpq_class(0);
}

Kind kind_of(const std::vector<Q>& c) {
  return c.empty()
             ? Kind::empty
             : (c.size() == 1 ? Kind::point : (c.size() == 2 ? Kind::segment : Kind::polygon));
}

template <class T>
double max_abs(const std::vector<Vec2<T>>& a, const std::vector<Vec2<T>>& b) {
  double m = 0;
  for (const auto* v : {&a, &b})
    for (const auto& p : *v) m = std::max({m, std::abs(double(p.x)), std::abs(double(p.y))});
  return m;
}

/// Every point of `got` within tol (inf-norm) of one of `want`, and the other way round.
template <class T>
void expect_same_points(const std::vector<Vec2<T>>& got, const std::vector<Q>& want, double tol) {
  const auto near = [&](const Vec2<T>& g, const Q& w) {
    return std::abs(double(g.x) - dbl(w.x)) <= tol && std::abs(double(g.y) - dbl(w.y)) <= tol;
  };
  for (const auto& g : got) {
    bool ok = false;
    for (const Q& w : want) ok = ok || near(g, w);
    EXPECT_TRUE(ok) << "reported vertex (" << g.x << ", " << g.y << ") is no exact corner";
  }
  for (const Q& w : want) {
    bool ok = false;
    for (const auto& g : got) ok = ok || near(g, w);
    EXPECT_TRUE(ok) << "exact corner (" << dbl(w.x) << ", " << dbl(w.y) << ") missing";
  }
}

/// Checks the stationary answers for a and b against the oracle; returns the exact kind.
template <class T>
Kind check_static(const std::vector<Vec2<T>>& a, const std::vector<Vec2<T>>& b) {
  const std::vector<Q> A = qpoly(a), B = qpoly(b);
  const std::vector<Q> C = (A.empty() || B.empty()) ? std::vector<Q>{} : common(A, B);
  const Kind want = kind_of(C);
  EXPECT_EQ(intersects_convex_polygons(a, b), want != Kind::empty);
  EXPECT_EQ(intersects_convex_polygons(b, a), want != Kind::empty);
  const ConvexIntersection2<T> r = convex_polygon_intersection(a, b);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.kind, want) << "exact kind " << to_string(want);
  const double eps = double(std::numeric_limits<T>::epsilon());
  const double m = max_abs(a, b);
  const double tol = 6 * eps * m;  // |X| <= m: the set lies in both polygons
  if (r.kind == want) {
    EXPECT_EQ(r.vertices.size(), C.size());
    expect_same_points(r.vertices, C, tol);
    if (want == Kind::polygon) {
      const mpq_class exact = area(C);
      EXPECT_EQ(exact, clipped_area(A, B)) << "the two oracles disagree";
      std::vector<Q> got;
      double perimeter = 0;
      for (const auto& p : r.vertices) got.push_back(q(p));
      for (std::size_t i = 0; i < C.size(); ++i) {
        const Q d = C[(i + 1) % C.size()] - C[i];
        perimeter += std::abs(dbl(d.x)) + std::abs(dbl(d.y));
      }
      EXPECT_GT(area(got), 0) << "not counter-clockwise";
      EXPECT_LE(std::abs(dbl(area(got) - exact)), 2 * tol * perimeter + 8 * tol * tol);
    }
  }
  // Swapping the arguments gives the same set, bit for bit (canonical order and construction).
  const ConvexIntersection2<T> s = convex_polygon_intersection(b, a);
  EXPECT_EQ(s.kind, r.kind);
  EXPECT_EQ(s.vertices.size(), r.vertices.size());
  if (s.vertices.size() == r.vertices.size()) {
    for (std::size_t i = 0; i < s.vertices.size(); ++i) EXPECT_EQ(s.vertices[i], r.vertices[i]);
  }
  return want;
}

// ---- random convex polygons -------------------------------------------------------------------

/// Hull corners (counter-clockwise) of the points, exact with locus's orient2d.
template <class T>
std::vector<Vec2<T>> convex(std::vector<Vec2<T>> p) {
  std::sort(p.begin(), p.end(), [](const Vec2<T>& a, const Vec2<T>& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Vec2<T>> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && orient2d(h[k - 2], h[k - 1], p[i]) != Sign::positive) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && orient2d(h[k - 2], h[k - 1], p[i]) != Sign::positive) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

template <class T>
std::vector<Vec2<T>> random_convex(Rng& rng, bool grid) {
  const int n = rng.uniform_int(1, 7);
  std::vector<Vec2<T>> p;
  const Vec2<T> c = grid ? Vec2<T>{T(rng.uniform_int(-3, 3)), T(rng.uniform_int(-3, 3))}
                         : rng.vec<T, 2>(T(-2), T(2));
  for (int i = 0; i < n; ++i) {
    if (grid)
      p.push_back(c + Vec2<T>{T(rng.uniform_int(-3, 3)), T(rng.uniform_int(-3, 3))});
    else
      p.push_back(c + rng.vec<T, 2>(T(-2), T(2)));
  }
  std::vector<Vec2<T>> h = convex(p);
  // Clockwise half of the time, and sometimes with a repeated vertex.
  if (rng.uniform_int(0, 1) == 1) std::reverse(h.begin(), h.end());
  if (h.size() >= 3 && rng.uniform_int(0, 3) == 0) h.insert(h.begin() + 1, h[1]);
  return h;
}

template <class T>
class Sat2 : public ::testing::Test {};
TYPED_TEST_SUITE(Sat2, locus_test::RealTypes);

TYPED_TEST(Sat2, RandomAgainstExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int kinds[4] = {0, 0, 0, 0};
  for (int it = 0; it < 140; ++it) {
    const bool grid = it % 2 == 0;
    const auto a = random_convex<T>(rng, grid), b = random_convex<T>(rng, grid);
    SCOPED_TRACE("case " + std::to_string(it));
    const Kind k = check_static(a, b);
    kinds[k == Kind::empty ? 0 : (k == Kind::point ? 1 : (k == Kind::segment ? 2 : 3))]++;
  }
  // Every kind occurs (the grid cases touch often): the comparison is not vacuous.
  for (int k = 0; k < 4; ++k) EXPECT_GT(kinds[k], 2) << "kind " << k;
}

TYPED_TEST(Sat2, FixedTypesAndFigureCases) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Figure 7.13: (a) separated, (b) overlapping triangles; figure 7.14's contacts: edge-edge
  // (segment), vertex-edge and vertex-vertex (points), all exact on a grid.
  const Triangle2<T> t0{{0, 0}, {4, 0}, {0, 4}};
  EXPECT_FALSE(intersects(t0, Triangle2<T>{{3, 3}, {6, 3}, {3, 6}}));
  const auto ov = intersection(t0, Triangle2<T>{{1, 1}, {5, 1}, {1, 5}});
  EXPECT_EQ(ov.kind, Kind::polygon);
  EXPECT_EQ(ov.count, 3);
  EXPECT_EQ(ov.point[0], (V{1, 1}));
  const auto ee = intersection(t0, Triangle2<T>{{1, 3}, {3, 1}, {3, 3}});
  ASSERT_EQ(ee.kind, Kind::segment);
  EXPECT_EQ(ee.point[0], (V{1, 3}));
  EXPECT_EQ(ee.point[1], (V{3, 1}));
  const auto ve = intersection(t0, Triangle2<T>{{2, 2}, {5, 3}, {3, 5}});
  ASSERT_EQ(ve.kind, Kind::point);
  EXPECT_EQ(ve.point[0], (V{2, 2}));
  const auto vv = intersection(t0, Triangle2<T>{{4, 0}, {6, 0}, {6, 2}});
  ASSERT_EQ(vv.kind, Kind::point);
  EXPECT_EQ(vv.point[0], (V{4, 0}));
  check_static<T>({t0.v0, t0.v1, t0.v2}, {{2, 2}, {5, 3}, {3, 5}});
  // Rectangles and oriented boxes: corners in cycle order.
  const Rectangle2<T> r0{{0, 0}, {{1, 0}, {0, 1}}, {2, 1}}, r1{{3, 2}, {{1, 0}, {0, 1}}, {1, 1}};
  EXPECT_TRUE(intersects(r0, r1));
  const auto rr = intersection(r0, r1);
  ASSERT_EQ(rr.kind, Kind::point);
  EXPECT_EQ(rr.point[0], (V{2, 1}));
  const OrientedBox2<T> b0{{0, 0}, {{1, 0}, {0, 1}}, {2, 2}}, b1{{2, 2}, {{0, 1}, {1, 0}}, {1, 1}};
  const auto bb = intersection(b0, b1);
  ASSERT_EQ(bb.kind, Kind::polygon);
  ASSERT_EQ(bb.count, 4);
  EXPECT_EQ(bb.point[0], (V{1, 1}));
  EXPECT_EQ(bb.point[2], (V{2, 2}));
  EXPECT_FALSE(intersects(b0, OrientedBox2<T>{{5, 0}, {{1, 0}, {0, 1}}, {1, 1}}));
}

TYPED_TEST(Sat2, DegenerateEmptyAndNonFinite) {
  using T = TypeParam;
  using P = std::vector<Vec2<T>>;
  const P tri{{0, 0}, {4, 0}, {0, 4}};
  check_static<T>(tri, P{{1, 1}});                                // point inside
  check_static<T>(tri, P{{2, 2}});                                // point on an edge
  check_static<T>(tri, P{{3, 3}});                                // point outside
  check_static<T>(tri, P{{-1, 1}, {5, 1}});                       // segment through
  check_static<T>(tri, P{{-1, 5}, {5, -1}});                      // segment along the edge
  check_static<T>(tri, P{{4, 0}, {6, 0}});                        // touching at a vertex
  check_static<T>(tri, P{{1, 1}, {1, 1}, {1, 1}});                // repeated point
  check_static<T>(tri, P{{-1, 2}, {0, 2}, {1, 2}, {3, 2}});       // collinear vertex list
  check_static<T>(P{{0, 0}, {2, 2}}, P{{0, 2}, {2, 0}});          // crossing segments
  check_static<T>(P{{0, 0}, {2, 2}}, P{{1, 1}, {3, 3}});          // collinear overlap
  check_static<T>(P{{0, 0}, {2, 2}}, P{{2, 2}, {3, 3}, {4, 4}});  // touching end to end
  check_static<T>(P{{1, 1}}, P{{1, 1}});
  const P empty;
  EXPECT_FALSE(intersects_convex_polygons(tri, empty));
  EXPECT_EQ(convex_polygon_intersection(empty, tri).kind, Kind::empty);
  for (const T bad : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()}) {
    const P nan{{0, 0}, {bad, 0}, {0, 1}};
    EXPECT_FALSE(intersects_convex_polygons(tri, nan));
    const auto r = convex_polygon_intersection(nan, tri);
    EXPECT_EQ(r.kind, Kind::empty);
    EXPECT_EQ(r.status, Status::non_finite_input);
    EXPECT_FALSE(first_contact_convex_polygons(tri, Vec2<T>{}, nan, Vec2<T>{1, 0}, T(1)));
    EXPECT_FALSE(first_contact_convex_polygons(tri, Vec2<T>{bad, 0}, tri, Vec2<T>{1, 0}, T(1)));
    EXPECT_FALSE(first_contact_convex_polygons(tri, Vec2<T>{}, tri, Vec2<T>{1, 0}, bad));
  }
}

TYPED_TEST(Sat2, PowerOfTwoScaling) {
  using T = TypeParam;
  Rng rng(7);
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 60; ++it) {
    auto a = random_convex<T>(rng, false), b = random_convex<T>(rng, false);
    const auto r = convex_polygon_intersection(a, b);
    for (const int e : {-20, 9}) {
      const T s = std::ldexp(T(1), e);
      auto as = a, bs = b;
      for (auto& p : as) p *= s;
      for (auto& p : bs) p *= s;
      const auto rs = convex_polygon_intersection(as, bs);
      ASSERT_EQ(rs.kind, r.kind);
      ASSERT_EQ(rs.vertices.size(), r.vertices.size());
      for (std::size_t i = 0; i < r.vertices.size(); ++i)
        EXPECT_EQ(rs.vertices[i], s * r.vertices[i]);
      const Vec2<T> va = rng.vec<T, 2>(T(-1), T(1)), vb = rng.vec<T, 2>(T(-1), T(1));
      const auto c = first_contact_convex_polygons(a, va, b, vb, T(4));
      const auto cs = first_contact_convex_polygons(as, s * va, bs, s * vb, T(4));
      EXPECT_EQ(c.kind, cs.kind);
      EXPECT_EQ(c.time, cs.time);
    }
  }
}

TYPED_TEST(Sat2, VertexOrderAndQuarterTurns) {
  using T = TypeParam;
  Rng rng(3);
  SCOPED_TRACE(rng.trace());
  const double eps = double(std::numeric_limits<T>::epsilon());
  for (int it = 0; it < 60; ++it) {
    const auto a = random_convex<T>(rng, it % 2 == 0), b = random_convex<T>(rng, it % 2 == 0);
    const auto r = convex_polygon_intersection(a, b);
    // Another first vertex and the opposite order describe the same polygon: the same answer,
    // bit for bit (decisions are exact, constructions canonical).
    auto a2 = a;
    std::rotate(a2.begin(), a2.begin() + static_cast<std::ptrdiff_t>(a2.size() / 2), a2.end());
    std::reverse(a2.begin(), a2.end());
    const auto r2 = convex_polygon_intersection(a2, b);
    ASSERT_EQ(r2.kind, r.kind);
    ASSERT_EQ(r2.vertices.size(), r.vertices.size());
    for (std::size_t i = 0; i < r.vertices.size(); ++i) EXPECT_EQ(r2.vertices[i], r.vertices[i]);
    // A quarter turn (x, y) -> (-y, x) is exact: the same kind, the turned points.
    const auto turn = [](std::vector<Vec2<T>> p) {
      for (auto& x : p) x = Vec2<T>{-x.y, x.x};
      return p;
    };
    const auto r3 = convex_polygon_intersection(turn(a), turn(b));
    ASSERT_EQ(r3.kind, r.kind);
    ASSERT_EQ(r3.vertices.size(), r.vertices.size());
    const auto want = turn(r.vertices);
    const double tol = 12 * eps * max_abs(a, b);
    for (const auto& g : r3.vertices) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& w : want)
        best = std::min(best, std::max(std::abs(double(g.x - w.x)), std::abs(double(g.y - w.y))));
      EXPECT_LE(best, tol);
    }
    const Vec2<T> va = rng.vec<T, 2>(T(-1), T(1)), vb = rng.vec<T, 2>(T(-1), T(1));
    const auto c = first_contact_convex_polygons(a, va, b, vb, T(6));
    const auto c2 = first_contact_convex_polygons(a2, va, b, vb, T(6));
    EXPECT_EQ(c2.kind, c.kind);
    EXPECT_EQ(c2.time, c.time);
  }
}

// ---- moving ---------------------------------------------------------------------------------

/// Exact first time from the same projection intervals (the library's axes), or -1 for none.
template <class T>
mpq_class exact_first_time(const std::vector<Vec2<T>>& a, const Vec2<T>& va,
                           const std::vector<Vec2<T>>& b, const Vec2<T>& vb, double tmax,
                           mpq_class& tlast) {
  const std::vector<Q> A = qpoly(a), B = qpoly(b);
  std::vector<std::pair<Q, Q>> axes;  // f(x) = cross(q - p, x)
  for (const auto* P : {&A, &B}) {
    const std::size_t n = P->size();
    if (n >= 3)
      for (std::size_t i = 0; i < n; ++i) axes.push_back({(*P)[i], (*P)[(i + 1) % n]});
    if (n == 2) {
      axes.push_back({(*P)[0], (*P)[1]});
      axes.push_back({Q{(*P)[0].y, -(*P)[0].x}, Q{(*P)[1].y, -(*P)[1].x}});
    }
  }
  if (A.size() < 3 || B.size() < 3) {
    axes.push_back({Q{0, 0}, Q{0, -1}});
    axes.push_back({Q{0, 0}, Q{1, 0}});
  }
  const Q w = q(vb) - q(va);
  mpq_class tf = 0;
  tlast = tmax;
  for (const auto& [p, r] : axes) {
    const Q d = r - p;
    mpq_class amin = cross(d, A[0]), amax = amin, bmin = cross(d, B[0]), bmax = bmin;
    for (const Q& x : A) amin = std::min(amin, cross(d, x)), amax = std::max(amax, cross(d, x));
    for (const Q& x : B) bmin = std::min(bmin, cross(d, x)), bmax = std::max(bmax, cross(d, x));
    const mpq_class s = cross(d, w);
    if (s == 0) {
      if (bmin > amax || bmax < amin) return -1;
      continue;
    }
    const mpq_class enter = s > 0 ? (amin - bmax) / s : (amax - bmin) / s;
    const mpq_class exit = s > 0 ? (amax - bmin) / s : (amin - bmax) / s;
    tf = std::max(tf, enter);
    tlast = std::min(tlast, exit);
  }
  return tf <= tlast ? tf : mpq_class(-1);
}

/// The exact stationary test at time t (polygons moved in rationals).
template <class T>
bool meet_at(const std::vector<Vec2<T>>& a, const Vec2<T>& va, const std::vector<Vec2<T>>& b,
             const Vec2<T>& vb, const mpq_class& t) {
  std::vector<Q> A, B;
  for (const auto& p : a) A.push_back(q(p) + t * q(va));
  for (const auto& p : b) B.push_back(q(p) + t * q(vb));
  return !common(hull(A), hull(B)).empty();
}

/// Distance (inf-norm bound) from x to the convex polygon moved to time t, in double.
template <class T>
double gap_to(const std::vector<Vec2<T>>& a, const Vec2<T>& v, double t, const Vec2<T>& x) {
  std::vector<Q> A;
  for (const auto& p : a) A.push_back(q(p));
  A = hull(A);
  const double px = double(x.x), py = double(x.y);
  double best = std::numeric_limits<double>::infinity();
  bool inside = A.size() >= 3;
  for (std::size_t i = 0; i < A.size(); ++i) {
    const double x0 = dbl(A[i].x) + t * double(v.x), y0 = dbl(A[i].y) + t * double(v.y);
    const Q& n = A[(i + 1) % A.size()];
    const double x1 = dbl(n.x) + t * double(v.x), y1 = dbl(n.y) + t * double(v.y);
    const double dx = x1 - x0, dy = y1 - y0, l2 = dx * dx + dy * dy;
    if (dx * (py - y0) - dy * (px - x0) < 0) inside = false;
    const double u = l2 > 0 ? std::clamp(((px - x0) * dx + (py - y0) * dy) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(px - x0 - u * dx, py - y0 - u * dy));
  }
  return inside ? 0.0 : best;
}

template <class T>
void check_moving(const std::vector<Vec2<T>>& a, const Vec2<T>& va, const std::vector<Vec2<T>>& b,
                  const Vec2<T>& vb, T tmax, int& contacts) {
  const Contact2<T> c = first_contact_convex_polygons(a, va, b, vb, tmax);
  EXPECT_EQ(bool(c), intersects_convex_polygons(a, va, b, vb, tmax));
  const double eps = double(std::numeric_limits<T>::epsilon());
  mpq_class tlast;
  const mpq_class te = exact_first_time(a, va, b, vb, double(tmax), tlast);
  const bool static_meet = meet_at(a, va, b, vb, mpq_class(0));
  if (static_meet) {
    EXPECT_TRUE(c);
    EXPECT_EQ(c.time, T(0));
    return;
  }
  const double margin = 1e-4 * std::max(1.0, double(tmax));
  if (te < 0) {
    // No exact contact; a grazing pass within the bound may go either way.
    return;
  }
  if (dbl(tlast - te) < margin || dbl(te) > double(tmax) - margin) return;
  ++contacts;
  ASSERT_TRUE(c) << "exact first time " << dbl(te);
  EXPECT_LE(std::abs(double(c.time) - dbl(te)), 5 * eps * dbl(te)) << "exact " << dbl(te);
  // Independent: bisection on the exact stationary test (every fourth contact: it is slow).
  mpq_class lo = 0, hi = (te + tlast) / 2;
  EXPECT_TRUE(meet_at(a, va, b, vb, hi));
  for (int i = 0; i < 24 && contacts % 4 == 0; ++i) {
    const mpq_class mid(dbl((lo + hi) / 2));
    (meet_at(a, va, b, vb, mid) ? hi : lo) = mid;
  }
  if (contacts % 4 == 0) {
    EXPECT_LE(std::abs(double(c.time) - dbl(hi)), dbl(hi - lo) + 5 * eps * dbl(hi));
  }
  // The contact set lies on both polygons at that time.
  const double m = max_abs(a, b) + double(tmax) * (std::abs(double(va.x)) + std::abs(double(va.y)) +
                                                   std::abs(double(vb.x)) + std::abs(double(vb.y)));
  for (int i = 0; i < c.count; ++i) {
    const Vec2<T>& x = c.point[static_cast<std::size_t>(i)];
    EXPECT_LE(gap_to(a, va, double(c.time), x), 16 * eps * m);
    EXPECT_LE(gap_to(b, vb, double(c.time), x), 16 * eps * m);
  }
  // Swapping the polygons: the same time and kind.
  const Contact2<T> s = first_contact_convex_polygons(b, vb, a, va, tmax);
  EXPECT_EQ(s.kind, c.kind);
  EXPECT_EQ(s.time, c.time);
}

TYPED_TEST(Sat2, MovingAgainstExactTimes) {
  using T = TypeParam;
  Rng rng(11);
  SCOPED_TRACE(rng.trace());
  int contacts = 0;
  for (int it = 0; it < 50; ++it) {
    SCOPED_TRACE("case " + std::to_string(it));
    auto a = random_convex<T>(rng, it % 3 == 0), b = random_convex<T>(rng, it % 3 == 0);
    const Vec2<T> shift = rng.vec<T, 2>(T(-8), T(8));
    for (auto& p : b) p += shift;
    const Vec2<T> va = rng.vec<T, 2>(T(-1), T(1));
    const Vec2<T> vb = va - shift * T(0.25) + rng.vec<T, 2>(T(-0.5), T(0.5));
    check_moving(a, va, b, vb, T(8), contacts);
  }
  EXPECT_GT(contacts, 12);
}

TYPED_TEST(Sat2, MovingAnalyticCases) {
  using T = TypeParam;
  using V = Vec2<T>;
  // Head-on boxes: edge-edge contact at t = 2 on x = 2.
  const Rectangle2<T> a{{0, 0}, {{1, 0}, {0, 1}}, {1, 1}}, b{{4, 0.5}, {{1, 0}, {0, 1}}, {1, 1}};
  const auto ee = first_contact(a, V{0.5, 0}, b, V{-0.5, 0}, T(10));
  ASSERT_EQ(ee.kind, Kind::segment);
  EXPECT_EQ(ee.time, T(2));
  EXPECT_EQ(ee.point[0], (V{2, -0.5}));
  EXPECT_EQ(ee.point[1], (V{2, 1}));
  EXPECT_FALSE(intersects(a, V{0.5, 0}, b, V{-0.5, 0}, T(1.5)));
  // Vertex-vertex: diagonal approach of two squares (figure 7.17(b)).
  const OrientedBox2<T> s0{{0, 0}, {{1, 0}, {0, 1}}, {1, 1}}, s1{{4, 4}, {{1, 0}, {0, 1}}, {1, 1}};
  const auto vv = first_contact(s0, V{}, s1, V{-1, -1}, T(5));
  ASSERT_EQ(vv.kind, Kind::point);
  EXPECT_EQ(vv.time, T(2));
  EXPECT_EQ(vv.point[0], (V{1, 1}));
  // Vertex-edge: a triangle's apex hits a square's edge.
  const Triangle2<T> tri{{5, 0}, {7, -1}, {7, 1}};
  const auto ve = first_contact(Triangle2<T>{{-1, -1}, {1, -1}, {1, 1}}, V{}, tri, V{-2, 0}, T(5));
  ASSERT_EQ(ve.kind, Kind::point);
  EXPECT_EQ(ve.time, T(2));
  EXPECT_EQ(ve.point[0], (V{1, 0}));
  // Moving apart, parallel motion, already overlapping, touching at time 0.
  EXPECT_FALSE(first_contact(s0, V{}, s1, V{1, 1}, T(100)));
  EXPECT_FALSE(first_contact(s0, V{}, s1, V{1, 0}, T(100)));
  const auto ov = first_contact(s0, V{}, s0, V{1, 0}, T(1));
  EXPECT_EQ(ov.kind, Kind::polygon);
  EXPECT_EQ(ov.count, 0);
  const auto tz =
      first_contact(s0, V{}, OrientedBox2<T>{{2, 0}, {{1, 0}, {0, 1}}, {1, 1}}, V{5, 0}, T(1));
  EXPECT_EQ(tz.kind, Kind::segment);
  EXPECT_EQ(tz.time, T(0));
  // A point moving into a triangle and a segment sliding onto a segment.
  const std::vector<V> pt{{3, 1}}, seg{{0, 0}, {2, 0}}, seg2{{3, 0}, {5, 0}};
  const std::vector<V> t0{{0, 0}, {2, 0}, {0, 2}};
  const auto pc = first_contact_convex_polygons(t0, V{}, pt, V{-1, 0}, T(5));
  ASSERT_EQ(pc.kind, Kind::point);
  EXPECT_EQ(pc.time, T(2));
  const auto sc = first_contact_convex_polygons(seg, V{}, seg2, V{-0.5, 0}, T(5));
  ASSERT_EQ(sc.kind, Kind::point);
  EXPECT_EQ(sc.time, T(2));
  EXPECT_EQ(sc.point[0], (V{2, 0}));
}

}  // namespace
