// SPDX-License-Identifier: BSL-1.0
// Tests of locus/hull/hull3.hpp (cg.hull3): book figures 13.39-13.41, degenerate and bad input,
// a brute-force exact oracle on small sets, QuickHull against the incremental method, exact
// invariants (closed manifold, symmetric adjacency, Euler, every point behind every face, every
// vertex a corner) on every output, scale invariance.

#include <locus/hull/hull3.hpp>

#include <support/typed.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace {

using locus::Hull3Method;
using locus::Hull3Options;
using locus::Hull3Result;
using locus::Sign;
using locus::Status;
using locus::Vec2;
using locus::Vec3;

constexpr Hull3Method kMethods[] = {Hull3Method::quickhull, Hull3Method::incremental};

template <class T>
Vec2<T> drop(const Vec3<T>& p, int k) {
  return {p[(k + 1) % 3], p[(k + 2) % 3]};
}

template <class T>
bool collinear(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  for (int k = 0; k < 3; ++k)
    if (locus::orient2d(drop(a, k), drop(b, k), drop(c, k)) != Sign::zero) return false;
  return true;
}

template <class T>
bool on_segment(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& p) {
  if (!collinear(a, b, p)) return false;
  const bool ab = locus::lexicographic_compare(a, b) != Sign::positive;
  const Vec3<T> lo = ab ? a : b, hi = ab ? b : a;
  return locus::lexicographic_compare(lo, p) != Sign::positive &&
         locus::lexicographic_compare(p, hi) != Sign::positive;
}

template <class T>
bool in_triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& p) {
  if (collinear(a, b, c)) return false;
  if (locus::orient3d(a, b, c, p) != Sign::zero) return false;
  for (int k = 0; k < 3; ++k) {
    const Sign o = locus::orient2d(drop(a, k), drop(b, k), drop(c, k));
    if (o == Sign::zero) continue;
    const Sign s1 = locus::orient2d(drop(a, k), drop(b, k), drop(p, k));
    const Sign s2 = locus::orient2d(drop(b, k), drop(c, k), drop(p, k));
    const Sign s3 = locus::orient2d(drop(c, k), drop(a, k), drop(p, k));
    return s1 != -o && s2 != -o && s3 != -o;
  }
  return false;
}

// Brute force (exact, O(n^5)): p is extreme iff it is in no closed tetrahedron, triangle or
// segment of other points (distinct from p).
template <class T>
std::set<std::uint32_t> brute_extreme(const std::vector<Vec3<T>>& pts) {
  std::set<std::uint32_t> ext;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    const Vec3<T>& p = pts[i];
    bool dup_before = false;
    for (std::uint32_t j = 0; j < i; ++j) dup_before |= pts[j] == p;
    if (dup_before) continue;
    std::vector<Vec3<T>> o;
    for (const auto& q : pts)
      if (!(q == p)) o.push_back(q);
    bool inside = false;
    const std::size_t m = o.size();
    for (std::size_t a = 0; a < m && !inside; ++a)
      for (std::size_t b = a + 1; b < m && !inside; ++b) {
        if (on_segment(o[a], o[b], p)) inside = true;
        for (std::size_t c = b + 1; c < m && !inside; ++c) {
          if (in_triangle(o[a], o[b], o[c], p)) inside = true;
          for (std::size_t d = c + 1; d < m && !inside; ++d) {
            const Sign s = locus::orient3d(o[a], o[b], o[c], o[d]);
            if (s == Sign::zero) continue;
            const Sign s1 = locus::orient3d(p, o[b], o[c], o[d]);
            const Sign s2 = locus::orient3d(o[a], p, o[c], o[d]);
            const Sign s3 = locus::orient3d(o[a], o[b], p, o[d]);
            const Sign s4 = locus::orient3d(o[a], o[b], o[c], p);
            if (s1 != -s && s2 != -s && s3 != -s && s4 != -s) inside = true;
          }
        }
      }
    if (!inside) ext.insert(i);
  }
  return ext;
}

template <class T>
std::uint32_t representative(const std::vector<Vec3<T>>& pts, std::uint32_t i) {
  for (std::uint32_t j = 0; j < i; ++j)
    if (pts[j] == pts[i]) return j;
  return i;
}

// Exact invariants of a result. `full`: check every point against every face (O(n F)).
template <class T>
::testing::AssertionResult check_hull(const std::vector<Vec3<T>>& pts, const Hull3Result& r,
                                      bool full = true) {
  using ::testing::AssertionFailure;
  if (r.status != Status::ok) return AssertionFailure() << "status";
  if (!std::is_sorted(r.vertices.begin(), r.vertices.end())) return AssertionFailure() << "sort";
  if (pts.size() <= 3000)
    for (auto v : r.vertices)
      if (representative(pts, v) != v) return AssertionFailure() << "not the smallest duplicate";
  if (r.dimension == 0) {
    for (const auto& p : pts)
      if (!(p == pts[r.polygon.at(0)])) return AssertionFailure() << "dim 0";
    return ::testing::AssertionSuccess();
  }
  if (r.dimension == 1) {
    if (r.polygon.size() != 2) return AssertionFailure() << "dim 1 size";
    const Vec3<T> a = pts[r.polygon[0]], b = pts[r.polygon[1]];
    if (locus::lexicographic_compare(a, b) != Sign::negative) return AssertionFailure() << "order";
    for (const auto& p : pts)
      if (!on_segment(a, b, p)) return AssertionFailure() << "off the segment";
    return ::testing::AssertionSuccess();
  }
  if (r.dimension == 2) {
    const auto& P = r.polygon;
    const int k = r.plane_axis;
    if (P.size() < 3 || k < 0 || k > 2) return AssertionFailure() << "dim 2 polygon";
    if (!r.triangles.empty()) return AssertionFailure() << "dim 2 with triangles";
    const std::size_t h = P.size();
    for (std::size_t i = 0; i < h; ++i)
      if (locus::orient2d(drop(pts[P[i]], k), drop(pts[P[(i + 1) % h]], k),
                          drop(pts[P[(i + 2) % h]], k)) != Sign::positive)
        return AssertionFailure() << "polygon not strictly convex";
    for (std::size_t i = 1; i + 1 < h; ++i)
      if (locus::orient2d(drop(pts[P[0]], k), drop(pts[P[i]], k), drop(pts[P[i + 1]], k)) !=
          Sign::positive)
        return AssertionFailure() << "polygon winds more than once";
    for (const auto& p : pts) {
      if (locus::orient3d(pts[P[0]], pts[P[1]], pts[P[2]], p) != Sign::zero)
        return AssertionFailure() << "point off the plane";
      for (std::size_t i = 0; i < h; ++i)
        if (locus::orient2d(drop(pts[P[i]], k), drop(pts[P[(i + 1) % h]], k), drop(p, k)) ==
            Sign::negative)
          return AssertionFailure() << "point outside the polygon";
    }
    return ::testing::AssertionSuccess();
  }
  if (r.dimension != 3) return AssertionFailure() << "dimension " << r.dimension;
  const auto& tri = r.triangles;
  const auto& adj = r.adjacency;
  const std::size_t F = tri.size();
  if (adj.size() != F) return AssertionFailure() << "adjacency size";
  std::set<std::uint32_t> used;
  for (std::size_t t = 0; t < F; ++t) {
    const auto& a = tri[t];
    if (a[0] == a[1] || a[1] == a[2] || a[0] == a[2]) return AssertionFailure() << "degenerate";
    for (int e = 0; e < 3; ++e) {
      used.insert(a[e]);
      const std::uint32_t u = adj[t][e];
      if (u >= F) return AssertionFailure() << "adjacency out of range";
      int back = -1;
      for (int k = 0; k < 3; ++k)
        if (tri[u][k] == a[(e + 1) % 3] && tri[u][(k + 1) % 3] == a[e]) back = k;
      if (back < 0 || adj[u][back] != t) return AssertionFailure() << "adjacency not symmetric";
      // Local convexity: the far vertex of the neighbour is not in front.
      const std::uint32_t w = tri[u][(back + 2) % 3];
      if (locus::orient3d(pts[a[0]], pts[a[1]], pts[a[2]], pts[w]) == Sign::positive)
        return AssertionFailure() << "reflex edge";
    }
  }
  if (std::vector<std::uint32_t>(used.begin(), used.end()) != r.vertices)
    return AssertionFailure() << "vertex list";
  const long V = static_cast<long>(used.size()), Fl = static_cast<long>(F);
  if (Fl % 2 != 0 || V - 3 * Fl / 2 + Fl != 2) return AssertionFailure() << "Euler";
  // Every vertex is a corner: its incident triangles span three planes.
  std::map<std::uint32_t, std::vector<std::size_t>> inc;
  for (std::size_t t = 0; t < F; ++t)
    for (int e = 0; e < 3; ++e) inc[tri[t][e]].push_back(t);
  const auto coplanar = [&](std::size_t s, std::size_t t) {
    for (int e = 0; e < 3; ++e)
      if (locus::orient3d(pts[tri[s][0]], pts[tri[s][1]], pts[tri[s][2]], pts[tri[t][e]]) !=
          Sign::zero)
        return false;
    return true;
  };
  for (const auto& [v, ts] : inc) {
    std::vector<std::size_t> planes;
    for (std::size_t t : ts) {
      bool fresh = true;
      for (std::size_t s : planes) fresh &= !coplanar(s, t);
      if (fresh) planes.push_back(t);
      if (planes.size() >= 3) break;
    }
    if (planes.size() < 3) return AssertionFailure() << "vertex " << v << " is not a corner";
  }
  if (full) {
    for (const auto& t : tri)
      for (const auto& p : pts)
        if (locus::orient3d(pts[t[0]], pts[t[1]], pts[t[2]], p) == Sign::positive)
          return AssertionFailure() << "point in front of a face";
  }
  return ::testing::AssertionSuccess();
}

template <class T>
Hull3Result hull(const std::vector<Vec3<T>>& pts, Hull3Method m) {
  return locus::convex_hull(pts, Hull3Options{m});
}

template <class T>
void check_all(const std::vector<Vec3<T>>& pts, bool full = true) {
  const Hull3Result ref = hull(pts, Hull3Method::quickhull);
  EXPECT_TRUE(check_hull(pts, ref, full));
  const Hull3Result inc = hull(pts, Hull3Method::incremental);
  EXPECT_TRUE(check_hull(pts, inc, full));
  EXPECT_EQ(inc.dimension, ref.dimension);
  EXPECT_EQ(inc.vertices, ref.vertices);
  EXPECT_EQ(inc.triangles.size(), ref.triangles.size());  // both triangulate the same facets
  if (ref.dimension < 3) {
    EXPECT_EQ(inc.polygon, ref.polygon);
  }
}

template <class T>
void check_oracle(const std::vector<Vec3<T>>& pts) {
  const std::set<std::uint32_t> want = brute_extreme(pts);
  for (auto m : kMethods) {
    const Hull3Result r = hull(pts, m);
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_EQ(std::set<std::uint32_t>(r.vertices.begin(), r.vertices.end()), want)
        << "method " << int(m) << " dim " << r.dimension;
  }
  check_all(pts);
}

template <class T>
std::vector<Vec3<T>> make(std::initializer_list<std::array<double, 3>> xyz) {
  std::vector<Vec3<T>> v;
  for (auto [x, y, z] : xyz) v.push_back(Vec3<T>{T(x), T(y), T(z)});
  return v;
}

template <class T>
class Hull3 : public ::testing::Test {};
TYPED_TEST_SUITE(Hull3, locus_test::RealTypes);

// Figure 13.39: a hull (a cube) and a point to merge, which sees one face: the 9 corners.
TYPED_TEST(Hull3, Figure13_39PointMerge) {
  using T = TypeParam;
  auto pts = make<T>({{0, 0, 0},
                      {2, 0, 0},
                      {0, 2, 0},
                      {2, 2, 0},
                      {0, 0, 2},
                      {2, 0, 2},
                      {0, 2, 2},
                      {2, 2, 2},
                      {1, 1, 1},
                      {1, 1, 4}});
  for (auto m : kMethods) {
    const Hull3Result r = hull(pts, m);
    EXPECT_EQ(r.dimension, 3);
    EXPECT_EQ(r.vertices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 9}));
    // 5 square faces (2 triangles each) and 4 triangles of the pyramid on top: 14.
    EXPECT_EQ(r.triangles.size(), 14u);
  }
  check_oracle(pts);
}

// Figure 13.40: two icosahedra (rational approximations of the golden ratio) and their hull.
TYPED_TEST(Hull3, Figure13_40TwoIcosahedra) {
  using T = TypeParam;
  const double g = 1.625;  // 13/8, exact in float
  std::vector<Vec3<T>> pts;
  for (double shift : {0.0, 3.0})
    for (double s1 : {-1.0, 1.0})
      for (double s2 : {-g, g}) {
        pts.push_back({T(0 + shift), T(s1), T(s2)});
        pts.push_back({T(s1 + shift), T(s2), T(0)});
        pts.push_back({T(s2 + shift), T(0), T(s1)});
      }
  check_oracle(pts);
}

// Figure 13.41: a pyramid with a square base and a segment behind it (the terminator of a
// segment is two cycles); the hull of pyramid and segment end points by the oracle.
TYPED_TEST(Hull3, Figure13_41PyramidAndSegment) {
  using T = TypeParam;
  const auto pts = make<T>({{0, 0, 3},
                            {-4, 0, 0},
                            {4, 0, 0},
                            {0, 0, 4},
                            {2, 2, 0},
                            {2, -2, 0},
                            {-2, -2, 0},
                            {-2, 2, 0},
                            {-1, 0, 3.5},
                            {1, 0, 3.5}});
  check_oracle(pts);
}

TYPED_TEST(Hull3, BadInput) {
  using T = TypeParam;
  for (auto m : kMethods) {
    EXPECT_EQ(hull(std::vector<Vec3<T>>{}, m).status, Status::empty_input);
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    for (T bad : {nan, inf, -inf})
      for (std::size_t n : {std::size_t(4), std::size_t(3000)}) {
        std::vector<Vec3<T>> pts(n);
        for (std::size_t i = 0; i < n; ++i) pts[i] = {T(i % 7), T(i % 11), T(i % 13)};
        pts[n / 2].z = bad;
        const Hull3Result r = hull(pts, m);
        EXPECT_EQ(r.status, Status::non_finite_input);
        EXPECT_EQ(r.dimension, -1);
        EXPECT_TRUE(r.triangles.empty());
      }
  }
}

TYPED_TEST(Hull3, LowDimensions) {
  using T = TypeParam;
  for (auto m : kMethods) {
    const Hull3Result one = hull(make<T>({{1, 2, 3}}), m);
    EXPECT_EQ(one.dimension, 0);
    EXPECT_EQ(one.polygon, (std::vector<std::uint32_t>{0}));
    const std::vector<Vec3<T>> same(3000, Vec3<T>{T(1), T(-2), T(5)});
    const Hull3Result s = hull(same, m);
    EXPECT_EQ(s.dimension, 0);
    EXPECT_EQ(s.polygon, (std::vector<std::uint32_t>{0}));
    const Hull3Result two = hull(make<T>({{1, 2, 3}, {0, 2, 3}, {1, 2, 3}}), m);
    EXPECT_EQ(two.dimension, 1);
    EXPECT_EQ(two.polygon, (std::vector<std::uint32_t>{1, 0}));
    const Hull3Result three = hull(make<T>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), m);
    EXPECT_EQ(three.dimension, 2);
    EXPECT_EQ(three.plane_axis, 2);
    EXPECT_EQ(three.polygon, (std::vector<std::uint32_t>{0, 1, 2}));
  }
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  // Collinear: integer points on the line (1, 2, 3) t + (4, -1, 0).
  std::vector<Vec3<T>> line;
  for (int i = 0; i < 2500; ++i) {
    const int t = rng.uniform_int(-300, 300);
    line.push_back({T(t + 4), T(2 * t - 1), T(3 * t)});
  }
  check_all(line);
  EXPECT_EQ(hull(line, Hull3Method::quickhull).dimension, 1);
  // Coplanar: integer points of the plane x + 2y + 3z = 6, many collinear and duplicated.
  std::vector<Vec3<T>> plane;
  for (int i = 0; i < 2500; ++i) {
    const int y = rng.uniform_int(-20, 20), z = rng.uniform_int(-20, 20);
    plane.push_back({T(6 - 2 * y - 3 * z), T(y), T(z)});
  }
  check_all(plane);
  EXPECT_EQ(hull(plane, Hull3Method::quickhull).dimension, 2);
  // The plane seen edge-on from every axis but one.
  std::vector<Vec3<T>> vert;
  for (int i = 0; i < 200; ++i) vert.push_back({T(rng.uniform_int(0, 9)), T(7), T(i % 13)});
  check_all(vert);
}

// A 12 x 12 x 12 integer grid (the large grids are in the benchmark): 8 corners; the faces'
// grid points are coplanar non-extreme points that must not be vertices.
TYPED_TEST(Hull3, IntegerGrid) {
  using T = TypeParam;
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      for (int k = 0; k < 12; ++k) pts.push_back({T((i * 5) % 12), T((j * 7) % 12), T(k)});
  for (auto m : kMethods) {
    const Hull3Result r = hull(pts, m);
    EXPECT_EQ(r.vertices.size(), 8u);
    EXPECT_EQ(r.triangles.size(), 12u);
  }
  check_all(pts);
  // Only the surface of the grid (every point but 8 lies in a facet or on an edge).
  std::vector<Vec3<T>> surface;
  for (const auto& p : pts)
    if (p.x == T(0) || p.x == T(11) || p.y == T(0) || p.y == T(11) || p.z == T(0) || p.z == T(11))
      surface.push_back(p);
  check_all(surface);
  EXPECT_EQ(hull(surface, Hull3Method::quickhull).vertices.size(), 8u);
}

// Exactly cospherical integer points (x^2 + y^2 + z^2 = 5^2 13^2 = 4225): all extreme.
TYPED_TEST(Hull3, CosphericalIntegers) {
  using T = TypeParam;
  std::vector<Vec3<T>> pts;
  for (int x = -65; x <= 65; ++x)
    for (int y = -65; y <= 65; ++y) {
      const int r = 4225 - x * x - y * y;
      if (r < 0) continue;
      const int z = static_cast<int>(std::lround(std::sqrt(double(r))));
      if (z * z != r) continue;
      pts.push_back({T(x), T(y), T(z)});
      if (z != 0) pts.push_back({T(x), T(y), T(-z)});
    }
  const std::size_t n = pts.size();
  ASSERT_GT(n, 100u);
  for (std::size_t i = 0; i < n; i += 3) pts.push_back(pts[i]);  // duplicates
  check_all(pts);
  for (auto m : kMethods) EXPECT_EQ(hull(pts, m).vertices.size(), n);
}

// Points on a unit sphere (rounded): QuickHull stays fast, the methods agree.
TYPED_TEST(Hull3, SphereAndCube) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec3<T>> sphere, cube;
  for (int i = 0; i < 500; ++i) sphere.push_back(rng.unit<T, 3>());
  for (int i = 0; i < 2000; ++i) cube.push_back(rng.vec<T, 3>(T(-1), T(1)));
  check_all(sphere);
  check_all(cube);
  // Large: only QuickHull, invariants without the O(nF) sweep, plus a sampled sweep.
  std::vector<Vec3<T>> big;
  for (int i = 0; i < 5000; ++i) big.push_back(rng.unit<T, 3>());
  const Hull3Result r = hull(big, Hull3Method::quickhull);
  EXPECT_TRUE(check_hull(big, r, false));
  std::vector<Vec3<T>> sample(big.begin(), big.begin() + 200);
  for (const auto& t : r.triangles)
    for (const auto& p : sample)
      ASSERT_NE(locus::orient3d(big[t[0]], big[t[1]], big[t[2]], p), Sign::positive);
}

// Random small sets against the brute-force oracle: reals and small integer grids (coplanar and
// collinear subsets, duplicates).
TYPED_TEST(Hull3, RandomVsBruteForce) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 150; ++trial) {
    const int n = rng.uniform_int(1, 10);
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < n; ++i) {
      if (trial % 3 == 0)
        pts.push_back(rng.vec<T, 3>(T(-1), T(1)));
      else if (trial % 3 == 1)
        pts.push_back(
            {T(rng.uniform_int(0, 2)), T(rng.uniform_int(0, 2)), T(rng.uniform_int(0, 2))});
      else
        pts.push_back({T(rng.uniform_int(0, 3)), T(rng.uniform_int(0, 1)), T(0)});
    }
    SCOPED_TRACE(trial);
    check_oracle(pts);
  }
}

// Near-degenerate: a grid of points 1 ulp apart around a plane, plus far points (the 3D analogue
// of the Kettner et al. grids).
TEST(Hull3Robust, UlpGridNearPlane) {
  std::vector<Vec3<double>> pts;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      const double x = 0.5 + i * 0x1p-53, y = 0.5 + j * 0x1p-53;
      pts.push_back({x, y, x + y});  // rounded: near the plane z = x + y
    }
  pts.push_back({12, 12, 24});
  pts.push_back({24, 24, 48});
  pts.push_back({-3, 7, 4});
  check_all(pts);
  pts.push_back({0, 0, 100});
  check_all(pts);
}

// Power-of-two scaling is exact: the same vertices down to tiny and up to huge coordinates.
TYPED_TEST(Hull3, ScaleInvariance) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 3000; ++i)
    pts.push_back(
        {T(rng.uniform_int(-20, 20)), T(rng.uniform_int(-20, 20)), T(rng.uniform_int(-20, 20))});
  for (int i = 0; i < 200; ++i) pts.push_back(rng.unit<T, 3>() * T(25));
  const Hull3Result ref = hull(pts, Hull3Method::quickhull);
  ASSERT_TRUE(check_hull(pts, ref));
  const int e = std::is_same_v<T, float> ? 90 : 280;
  for (int s : {e, -e}) {
    std::vector<Vec3<T>> q = pts;
    for (auto& p : q) p = {std::ldexp(p.x, s), std::ldexp(p.y, s), std::ldexp(p.z, s)};
    for (auto m : kMethods) EXPECT_EQ(hull(q, m).vertices, ref.vertices) << s;
  }
}

TYPED_TEST(Hull3, ReusableBuilder) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  locus::ConvexHull3<T> builder;
  Hull3Result out;
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<Vec3<T>> pts;
    const int n = rng.uniform_int(0, 2500);
    for (int i = 0; i < n; ++i)
      pts.push_back(trial % 2 ? rng.unit<T, 3>() : rng.vec<T, 3>(T(-1), T(1)));
    builder.compute(std::span<const Vec3<T>>(pts), Hull3Options{}, out);
    const Hull3Result fresh = locus::convex_hull(pts);
    EXPECT_EQ(out.status, fresh.status);
    EXPECT_EQ(out.triangles, fresh.triangles);
    EXPECT_EQ(out.adjacency, fresh.adjacency);
  }
}

}  // namespace
