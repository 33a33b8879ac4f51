// SPDX-License-Identifier: BSL-1.0
// Tests of the divide-and-conquer 3D hull (locus/hull/hull3.hpp, Hull3Method::divide_and_conquer;
// cg.hull3, book figures 13.40-13.41). Oracles: the incremental method (small sets) and
// QuickHull (large ones) must give the same vertices and the same facets (coplanar triangles
// merged, compared as vertex sets), and the same triangles when every facet is a triangle; every
// output is checked exactly (closed manifold, symmetric adjacency, Euler, locally convex edges,
// every input point behind every face on small sets). Random sets: uniform cube, sphere surface
// (all points on the hull), integer grids (massive coplanarity), many duplicates, two slabs that
// share x coordinates; degenerate and bad input; power-of-two scale covariance.

#include <locus/hull/hull3.hpp>

#include <support/typed.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <set>
#include <vector>

namespace {

using locus::Hull3Method;
using locus::Hull3Options;
using locus::Hull3Result;
using locus::Sign;
using locus::Status;
using locus::Vec3;
using Tri = std::array<std::uint32_t, 3>;

template <class T>
Hull3Result hull(const std::vector<Vec3<T>>& pts, Hull3Method m) {
  return locus::convex_hull(pts, Hull3Options{m});
}

// Triangles rotated to start at their smallest index (orientation kept), sorted.
std::vector<Tri> canonical(const Hull3Result& r) {
  std::vector<Tri> out;
  for (Tri t : r.triangles) {
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The facets: triangles joined across edges whose neighbour is coplanar (exact orient3d), each
// facet as the sorted set of its vertices.
template <class T>
std::set<std::vector<std::uint32_t>> facets(const std::vector<Vec3<T>>& p, const Hull3Result& r) {
  const std::size_t F = r.triangles.size();
  std::vector<std::size_t> root(F);
  std::iota(root.begin(), root.end(), std::size_t(0));
  const auto find = [&](std::size_t x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  for (std::size_t t = 0; t < F; ++t) {
    const Tri& a = r.triangles[t];
    for (const std::uint32_t u : r.adjacency[t]) {
      bool flat = true;
      for (const std::uint32_t w : r.triangles[u])
        flat &= locus::orient3d(p[a[0]], p[a[1]], p[a[2]], p[w]) == Sign::zero;
      if (flat) root[find(t)] = find(u);
    }
  }
  std::vector<std::set<std::uint32_t>> sets(F);
  for (std::size_t t = 0; t < F; ++t)
    for (const std::uint32_t v : r.triangles[t]) sets[find(t)].insert(v);
  std::set<std::vector<std::uint32_t>> out;
  for (const auto& s : sets)
    if (!s.empty()) out.insert(std::vector<std::uint32_t>(s.begin(), s.end()));
  return out;
}

// Exact invariants of a 3D result; `all_points`: every input point behind every face (O(n F)).
template <class T>
::testing::AssertionResult valid(const std::vector<Vec3<T>>& p, const Hull3Result& r,
                                 bool all_points) {
  using ::testing::AssertionFailure;
  if (r.status != Status::ok || r.dimension != 3) return AssertionFailure() << "status/dim";
  const auto& tri = r.triangles;
  const std::size_t F = tri.size();
  if (r.adjacency.size() != F) return AssertionFailure() << "adjacency size";
  std::set<std::uint32_t> used;
  for (std::size_t t = 0; t < F; ++t)
    for (int e = 0; e < 3; ++e) {
      used.insert(tri[t][e]);
      const std::uint32_t u = r.adjacency[t][e];
      if (u >= F) return AssertionFailure() << "adjacency range";
      int back = -1;
      for (int k = 0; k < 3; ++k)
        if (tri[u][k] == tri[t][(e + 1) % 3] && tri[u][(k + 1) % 3] == tri[t][e]) back = k;
      if (back < 0 || r.adjacency[u][back] != t) return AssertionFailure() << "not symmetric";
      const std::uint32_t w = tri[u][(back + 2) % 3];
      if (locus::orient3d(p[tri[t][0]], p[tri[t][1]], p[tri[t][2]], p[w]) == Sign::positive)
        return AssertionFailure() << "reflex edge";
    }
  if (std::vector<std::uint32_t>(used.begin(), used.end()) != r.vertices)
    return AssertionFailure() << "vertex list";
  const long V = static_cast<long>(used.size()), Fl = static_cast<long>(F);
  if (Fl % 2 != 0 || V - 3 * Fl / 2 + Fl != 2) return AssertionFailure() << "Euler";
  if (all_points)
    for (const Tri& t : tri)
      for (const auto& q : p)
        if (locus::orient3d(p[t[0]], p[t[1]], p[t[2]], q) == Sign::positive)
          return AssertionFailure() << "a point in front of a face";
  return ::testing::AssertionSuccess();
}

// Divide and conquer against the incremental method (n <= 400) or QuickHull.
template <class T>
void compare(const std::vector<Vec3<T>>& p) {
  const Hull3Result dc = hull(p, Hull3Method::divide_and_conquer);
  const bool small = p.size() <= 400;
  const Hull3Result ref = hull(p, small ? Hull3Method::incremental : Hull3Method::quickhull);
  ASSERT_EQ(dc.status, ref.status);
  ASSERT_EQ(dc.dimension, ref.dimension);
  EXPECT_EQ(dc.vertices, ref.vertices);
  if (dc.dimension < 3) {
    EXPECT_EQ(dc.polygon, ref.polygon);
    EXPECT_EQ(dc.plane_axis, ref.plane_axis);
    EXPECT_TRUE(dc.triangles.empty());
    return;
  }
  EXPECT_TRUE(valid(p, dc, p.size() <= 200));
  const auto fd = facets(p, dc), fr = facets(p, ref);
  EXPECT_EQ(fd, fr);
  const bool simplicial =
      std::all_of(fd.begin(), fd.end(), [](const auto& f) { return f.size() == 3; });
  if (simplicial) {
    EXPECT_EQ(canonical(dc), canonical(ref));
  }
}

template <class T>
class Hull3Dc : public ::testing::Test {};
TYPED_TEST_SUITE(Hull3Dc, locus_test::RealTypes);

// Figure 13.40: two icosahedra (golden ratio ~ 13/8) side by side; the merge wraps a band of
// triangles between them. The right one turned about a generic axis (the lexicographic halves
// are the two icosahedra, merged by one wrap), or only translated (parallel edges: coplanar
// quadruples on the band), also overlapping in x.
TYPED_TEST(Hull3Dc, Figure13_40TwoIcosahedra) {
  using T = TypeParam;
  const double g = 1.625;
  const double l = std::sqrt(14.0), u[3] = {1 / l, 2 / l, 3 / l};
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (const double shift : {3.0, 2.0, 0.5}) {
    for (const bool turn : {false, true}) {
      std::vector<Vec3<T>> pts;
      for (const double dx : {0.0, shift})
        for (const double s1 : {-1.0, 1.0})
          for (const double s2 : {-g, g})
            for (const auto& q :
                 {Vec3<double>{0, s1, s2}, Vec3<double>{s1, s2, 0}, Vec3<double>{s2, 0, s1}}) {
              Vec3<double> r = q;
              if (turn && dx != 0) {  // Rodrigues: c q + s (u x q) + (1 - c)(u . q) u
                const double d = (u[0] * q.x + u[1] * q.y + u[2] * q.z) * (1 - c);
                r = {c * q.x + s * (u[1] * q.z - u[2] * q.y) + d * u[0],
                     c * q.y + s * (u[2] * q.x - u[0] * q.z) + d * u[1],
                     c * q.z + s * (u[0] * q.y - u[1] * q.x) + d * u[2]};
              }
              pts.push_back({T(r.x + dx), T(r.y), T(r.z)});
            }
      SCOPED_TRACE(::testing::Message() << "shift " << shift << " turn " << turn);
      compare(pts);
    }
  }
}

// Figure 13.41: a pyramid and a segment behind it (a flat sub-problem at the merge).
TYPED_TEST(Hull3Dc, Figure13_41PyramidAndSegment) {
  using T = TypeParam;
  const double xyz[][3] = {{0, 0, 3},  {-4, 0, 0},  {4, 0, 0},  {0, 0, 4},    {2, 2, 0},
                           {2, -2, 0}, {-2, -2, 0}, {-2, 2, 0}, {-1, 0, 3.5}, {1, 0, 3.5}};
  std::vector<Vec3<T>> pts;
  for (const auto& c : xyz) pts.push_back({T(c[0]), T(c[1]), T(c[2])});
  compare(pts);
}

TYPED_TEST(Hull3Dc, BadAndTinyInput) {
  using T = TypeParam;
  const Hull3Method m = Hull3Method::divide_and_conquer;
  EXPECT_EQ(hull(std::vector<Vec3<T>>{}, m).status, Status::empty_input);
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  for (const T bad : {nan, inf}) {
    std::vector<Vec3<T>> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, bad, 1}};
    const Hull3Result r = hull(pts, m);
    EXPECT_EQ(r.status, Status::non_finite_input);
    EXPECT_EQ(r.dimension, -1);
    EXPECT_TRUE(r.triangles.empty());
  }
  const std::vector<Vec3<T>> one{{1, 2, 3}};
  const Hull3Result r1 = hull(one, m);
  EXPECT_EQ(r1.dimension, 0);
  EXPECT_EQ(r1.polygon, (std::vector<std::uint32_t>{0}));
  compare(std::vector<Vec3<T>>(7, Vec3<T>{1, 2, 3}));
  compare(std::vector<Vec3<T>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
}

// Lower-dimensional input of every size: collinear, coplanar (axis and skew planes), and a
// large coplanar set with one point off the plane (every merge below the top is flat).
TYPED_TEST(Hull3Dc, CollinearAndCoplanar) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const int n : {2, 9, 40, 150}) {
    std::vector<Vec3<T>> line, plane, skew;
    for (int i = 0; i < n; ++i) {
      const int a = rng.uniform_int(-50, 50), b = rng.uniform_int(-50, 50);
      line.push_back({T(a), T(2 * a + 1), T(-a)});
      plane.push_back({T(a), T(b), T(7)});
      skew.push_back({T(a), T(b), T(3 * a - 2 * b + 5)});
    }
    compare(line);
    compare(plane);
    compare(skew);
    skew.push_back({T(0), T(0), T(1000)});
    compare(skew);
  }
}

TYPED_TEST(Hull3Dc, RandomCube) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const int n : {4, 5, 6, 9, 12, 17, 33, 64, 100, 250, 1500}) {
    const int reps = n <= 100 ? 4 : 1;
    for (int rep = 0; rep < reps; ++rep) {
      std::vector<Vec3<T>> pts;
      for (int i = 0; i < n; ++i) pts.push_back(rng.vec<T, 3>(T(-1), T(1)));
      SCOPED_TRACE(n);
      compare(pts);
    }
  }
}

// Points rounded onto the unit sphere: (nearly) all on the hull, the worst case for the merge.
TYPED_TEST(Hull3Dc, SphereSurface) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const int n : {20, 150, 1000}) {
    std::vector<Vec3<T>> pts;
    while (pts.size() < static_cast<std::size_t>(n)) {
      const Vec3<double> d = rng.vec<double, 3>(-1.0, 1.0);
      const double l = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
      if (l < 0.1 || l > 1.0) continue;
      pts.push_back({T(d.x / l), T(d.y / l), T(d.z / l)});
    }
    SCOPED_TRACE(n);
    compare(pts);
  }
}

// Integer grids: four or more coplanar points everywhere, with ties in every coordinate.
TYPED_TEST(Hull3Dc, IntegerGrids) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec3<T>> full;
  for (int x = 0; x < 5; ++x)
    for (int y = 0; y < 5; ++y)
      for (int z = 0; z < 5; ++z) full.push_back({T(x), T(y), T(z)});
  compare(full);
  for (const int n : {10, 30, 100, 300, 2000}) {
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < n; ++i)
      pts.push_back({T(rng.uniform_int(0, 6)), T(rng.uniform_int(0, 6)), T(rng.uniform_int(0, 6))});
    SCOPED_TRACE(n);
    compare(pts);
  }
  // Two slabs x in {0, 1} sharing x coordinates across the halves (lexicographic cuts).
  std::vector<Vec3<T>> slabs;
  for (int i = 0; i < 120; ++i)
    slabs.push_back({T(i % 2), T(rng.uniform_int(-9, 9)), T(rng.uniform_int(-9, 9))});
  compare(slabs);
}

// A half whose hull meets the merged hull in one vertex only (a thin cluster far out on the
// axis of a wide ring: every face of it is hidden but the apex), on either side.
TYPED_TEST(Hull3Dc, HalfTouchingInOneVertex) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const double sx : {1.0, -1.0}) {
    std::vector<Vec3<T>> pts{{T(-100 * sx), T(0), T(0)}};
    for (int i = 0; i < 15; ++i)
      pts.push_back({T((-99 + rng.uniform(-0.5, 0.5)) * sx), T(rng.uniform(-0.01, 0.01)),
                     T(rng.uniform(-0.01, 0.01))});
    for (int i = 0; i < 16; ++i) {
      const double t = 0.39269908169872414 * i + rng.uniform(-0.1, 0.1);  // 2 pi / 16
      pts.push_back({T(sx * rng.uniform(0.0, 1.0)), T(50 * std::cos(t)), T(50 * std::sin(t))});
    }
    SCOPED_TRACE(sx);
    compare(pts);
    EXPECT_EQ(hull(pts, Hull3Method::divide_and_conquer).vertices.size(), 17u);
  }
}

// Many exact duplicates in shuffled order: the smallest index represents each point.
TYPED_TEST(Hull3Dc, Duplicates) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const int distinct : {4, 12, 40}) {
    std::vector<Vec3<T>> base, pts;
    for (int i = 0; i < distinct; ++i) base.push_back(rng.vec<T, 3>(T(-1), T(1)));
    for (int i = 0; i < 10 * distinct; ++i)
      pts.push_back(base[static_cast<std::size_t>(rng.uniform_int(0, distinct - 1))]);
    SCOPED_TRACE(distinct);
    compare(pts);
  }
}

// Scaling by a power of two changes no decision: the same triangles, in the same order.
TYPED_TEST(Hull3Dc, PowerOfTwoScale) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 300; ++i)
    pts.push_back(i % 3 == 0 ? Vec3<T>{T(rng.uniform_int(0, 4)), T(rng.uniform_int(0, 4)),
                                       T(rng.uniform_int(0, 4))}
                             : rng.vec<T, 3>(T(0), T(4)));
  const Hull3Result r = hull(pts, Hull3Method::divide_and_conquer);
  ASSERT_EQ(r.dimension, 3);
  for (const int e : {-30, -3, 5, 40}) {
    std::vector<Vec3<T>> q;
    for (const auto& p : pts)
      q.push_back({std::ldexp(p.x, e), std::ldexp(p.y, e), std::ldexp(p.z, e)});
    const Hull3Result s = hull(q, Hull3Method::divide_and_conquer);
    EXPECT_EQ(s.vertices, r.vertices) << e;
    EXPECT_EQ(s.triangles, r.triangles) << e;
  }
}

}  // namespace
