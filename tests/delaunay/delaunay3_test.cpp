// SPDX-License-Identifier: BSL-1.0
// Tests of locus/delaunay/delaunay3.hpp (row cg.delaunay3, book section 13.8, figure 13.52).
// Every output is checked by exact invariants computed here with GMP rationals (orientation,
// empty circumspheres, volumes), by a brute-force oracle written here (every tetrahedron with an
// empty, symbolically perturbed circumsphere, in GMP), by the library's second method (the lower
// hull of the lifted points) and by the 3D convex hull (hull/hull3.hpp).

#include <gmpxx.h>

#include <locus/delaunay/delaunay3.hpp>
#include <locus/hull/hull3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "support/typed.hpp"

namespace {

using locus::Delaunay3Method;
using locus::Delaunay3Options;
using locus::Delaunay3Result;
using locus::Sign;
using locus::Status;
using locus::Vec3;

#if defined(__SANITIZE_ADDRESS__)
constexpr int kScale = 4;  // the sanitizer run uses smaller inputs
#else
constexpr int kScale = 1;
#endif

template <class T>
class Delaunay3Test : public ::testing::Test {};
TYPED_TEST_SUITE(Delaunay3Test, locus_test::RealTypes);

template <class T>
using Points = std::vector<Vec3<T>>;

template <class T>
std::array<mpq_class, 3> exact(const Vec3<T>& p) {
  return {mpq_class(double(p.x)), mpq_class(double(p.y)), mpq_class(double(p.z))};
}

// det[b - a; c - a; d - a] (six times the signed volume), exactly.
template <class T>
mpq_class exact_orient(const Vec3<T>& pa, const Vec3<T>& pb, const Vec3<T>& pc, const Vec3<T>& pd) {
  const auto a = exact(pa), b = exact(pb), c = exact(pc), d = exact(pd);
  mpq_class m[3][3];
  for (int i = 0; i < 3; ++i) {
    m[0][i] = b[std::size_t(i)] - a[std::size_t(i)];
    m[1][i] = c[std::size_t(i)] - a[std::size_t(i)];
    m[2][i] = d[std::size_t(i)] - a[std::size_t(i)];
  }
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

template <class Num>
Num det4(const Num m[4][4]) {
  Num s = 0;
  for (int c = 0; c < 4; ++c) {
    // 3x3 minor without row 0 and column c.
    int cols[3], k = 0;
    for (int j = 0; j < 4; ++j)
      if (j != c) cols[k++] = j;
    const Num minor =
        m[1][cols[0]] * (m[2][cols[1]] * m[3][cols[2]] - m[2][cols[2]] * m[3][cols[1]]) -
        m[1][cols[1]] * (m[2][cols[0]] * m[3][cols[2]] - m[2][cols[2]] * m[3][cols[0]]) +
        m[1][cols[2]] * (m[2][cols[0]] * m[3][cols[1]] - m[2][cols[1]] * m[3][cols[0]]);
    s += (c % 2 == 0 ? 1 : -1) * m[0][c] * minor;
  }
  return s;
}

// A value whose sign is "e strictly inside the sphere through a, b, c, d" when
// orient(a, b, c, d) > 0: the lifted determinant det[p - e, w_p - w_e] (p = a, b, c, d) with the
// sign fixed by its value on a known configuration (see the SignConvention test).
template <class T>
mpq_class exact_insphere(const Vec3<T>& pa, const Vec3<T>& pb, const Vec3<T>& pc, const Vec3<T>& pd,
                         const Vec3<T>& pe) {
  const Vec3<T>* p[5] = {&pa, &pb, &pc, &pd, &pe};
  mpq_class lift[5];
  for (int i = 0; i < 5; ++i) {
    const auto q = exact(*p[i]);
    lift[i] = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
  }
  const auto e = exact(pe);
  mpq_class m[4][4];
  for (int i = 0; i < 4; ++i) {
    const auto q = exact(*p[i]);
    for (int j = 0; j < 3; ++j) m[i][j] = q[std::size_t(j)] - e[std::size_t(j)];
    m[i][3] = lift[i] - lift[4];
  }
  // det[p - e, w] is positive for e outside when orient(a, b, c, d) > 0 (checked in
  // SignConvention), so its negation is the "inside" value.
  return -det4(m);
}

// The same sign with the header's symbolic perturbation written out as numbers: each lift
// w_q = |q|^2 gets + 2^(-64 (r + 1)), r = q's rank among the five points (lexicographically
// largest first), all scaled by 2^320 to stay in integers. Exact for integer coordinates below
// 2^10 (every nonzero cofactor is then at least 1 and at most 2^40).
template <class T>
int perturbed_insphere_sign(const Vec3<T>& pa, const Vec3<T>& pb, const Vec3<T>& pc,
                            const Vec3<T>& pd, const Vec3<T>& pe) {
  const Vec3<T>* p[5] = {&pa, &pb, &pc, &pd, &pe};
  mpz_class c[5][3], lift[5];
  for (int i = 0; i < 5; ++i) {
    int rank = 0;
    for (int j = 0; j < 5; ++j)
      if (locus::lexicographic_compare(*p[j], *p[i]) == Sign::positive) ++rank;
    for (int k = 0; k < 3; ++k) {
      const double x = double((*p[i])[k]);
      EXPECT_TRUE(x == std::floor(x) && std::abs(x) < 1024) << "oracle needs small integers";
      c[i][k] = long(x);
    }
    lift[i] = (c[i][0] * c[i][0] + c[i][1] * c[i][1] + c[i][2] * c[i][2]) << 320;
    lift[i] += mpz_class(1) << (64 * (4 - rank));
  }
  mpz_class m[4][4];
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) m[i][k] = c[i][k] - c[4][k];
    m[i][3] = lift[i] - lift[4];
  }
  return -sgn(det4(m));
}

std::array<std::uint32_t, 4> sorted4(std::array<std::uint32_t, 4> v) {
  std::sort(v.begin(), v.end());
  return v;
}

using TetSet = std::set<std::array<std::uint32_t, 4>>;

TetSet tet_set(const Delaunay3Result& r) {
  TetSet s;
  for (const auto& c : r.tetrahedra) s.insert(sorted4(c.vertices));
  return s;
}

// The oracle: every quadruple of kept points whose (optionally perturbed) open circumsphere
// holds no other kept point.
template <class T>
TetSet brute_force(const Points<T>& pts, bool perturb) {
  std::vector<std::uint32_t> kept;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    bool dup = false;
    for (auto k : kept)
      dup = dup || (pts[k].x == pts[i].x && pts[k].y == pts[i].y && pts[k].z == pts[i].z);
    if (!dup) kept.push_back(i);
  }
  TetSet s;
  const std::size_t m = kept.size();
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b)
      for (std::size_t c = b + 1; c < m; ++c)
        for (std::size_t d = c + 1; d < m; ++d) {
          std::array<std::uint32_t, 4> q = {kept[a], kept[b], kept[c], kept[d]};
          const mpq_class o = exact_orient(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]]);
          if (o == 0) continue;
          if (o < 0) std::swap(q[2], q[3]);
          // The exact predicate (core, tested on its own) decides the nonzero cases quickly;
          // the integer perturbation written here decides the zero ones, only for quadruples
          // that no point rejects outright.
          bool empty = true;
          std::vector<std::uint32_t> zeros;
          for (std::size_t e = 0; e < m && empty; ++e) {
            const std::uint32_t x = kept[e];
            if (x == q[0] || x == q[1] || x == q[2] || x == q[3]) continue;
            const Sign si = locus::insphere(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]], pts[x]);
            if (si == Sign::positive) empty = false;
            if (si == Sign::zero) zeros.push_back(x);
          }
          if (perturb)
            for (std::size_t k = 0; k < zeros.size() && empty; ++k)
              empty = perturbed_insphere_sign(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]],
                                              pts[zeros[k]]) < 0;
          if (empty) s.insert(sorted4(q));
        }
  return s;
}

// Exact six-fold volume enclosed by outward triangles.
template <class T>
mpq_class surface_volume(const Points<T>& pts,
                         const std::vector<std::array<std::uint32_t, 3>>& faces) {
  mpq_class v = 0;
  const Vec3<T> o = pts[faces.empty() ? 0 : faces[0][0]];
  for (const auto& f : faces) v -= exact_orient(pts[f[0]], pts[f[1]], pts[f[2]], o);
  return v;
}

/// Checks a 3D result exactly: duplicates, orientation, adjacency symmetry and face matching,
/// faces shared by at most two cells, the hull as a closed outward surface, Euler's formulas,
/// the volume sum against the hull (this result's and hull3's), and empty circumspheres (every
/// point with `brute`, else every neighbour's opposite vertex, which implies the global
/// property).
template <class T>
::testing::AssertionResult check_delaunay3(const Points<T>& pts, const Delaunay3Result& r,
                                           bool brute) {
  const std::size_t n = pts.size();
  if (r.status != Status::ok) return ::testing::AssertionFailure() << "status";
  if (r.dimension != 3) return ::testing::AssertionFailure() << "dimension " << r.dimension;
  if (r.duplicate_of.size() != n) return ::testing::AssertionFailure() << "duplicate_of size";
  std::size_t dups = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t d = r.duplicate_of[i];
    if (d >= n || r.duplicate_of[d] != d) return ::testing::AssertionFailure() << "dup chain";
    if (d != i) {
      ++dups;
      if (!(pts[d].x == pts[i].x && pts[d].y == pts[i].y && pts[d].z == pts[i].z))
        return ::testing::AssertionFailure() << "duplicate_of names a different point " << i;
    }
  }
  if (dups != r.duplicate_count) return ::testing::AssertionFailure() << "duplicate_count";
  {
    std::vector<std::array<T, 3>> kept;
    for (std::size_t i = 0; i < n; ++i)
      if (r.duplicate_of[i] == i) kept.push_back({pts[i].x, pts[i].y, pts[i].z});
    std::sort(kept.begin(), kept.end());
    if (std::adjacent_find(kept.begin(), kept.end()) != kept.end())
      return ::testing::AssertionFailure() << "two kept points are equal";
  }
  const std::size_t nt = r.tetrahedra.size();
  if (nt == 0) return ::testing::AssertionFailure() << "no tetrahedra";
  std::vector<char> used(n, 0);
  std::map<std::array<std::uint32_t, 3>, int> face_count;
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  std::vector<std::array<std::uint32_t, 3>> boundary;
  mpq_class volume = 0;
  // Orientation signs: GMP for small inputs, the (separately tested) exact predicate for large.
  auto orient_sign = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    if (brute) return static_cast<Sign>(sgn(exact_orient(pts[a], pts[b], pts[c], pts[d])));
    return locus::orient3d(pts[a], pts[b], pts[c], pts[d]);
  };
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& c = r.tetrahedra[t];
    for (auto v : c.vertices) {
      if (v >= n || r.duplicate_of[v] != v)
        return ::testing::AssertionFailure() << "bad vertex in cell " << t;
      used[v] = 1;
    }
    const auto& v = c.vertices;
    const mpq_class o = exact_orient(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]);
    if (o <= 0) return ::testing::AssertionFailure() << "cell " << t << " not positive";
    volume += o;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        edges.insert({std::min(v[std::size_t(i)], v[std::size_t(j)]),
                      std::max(v[std::size_t(i)], v[std::size_t(j)])});
    for (int i = 0; i < 4; ++i) {
      const auto& F = locus::kDelaunay3Face[std::size_t(i)];
      std::array<std::uint32_t, 3> f = {v[std::size_t(F[0])], v[std::size_t(F[1])],
                                        v[std::size_t(F[2])]};
      // The face convention: the cell's own vertex i lies on the positive side.
      if (orient_sign(f[0], f[1], f[2], v[std::size_t(i)]) != Sign::positive)
        return ::testing::AssertionFailure() << "face convention at " << t;
      std::array<std::uint32_t, 3> key = f;
      std::sort(key.begin(), key.end());
      ++face_count[key];
      const std::int32_t nb = c.neighbors[std::size_t(i)];
      if (nb < 0) {
        boundary.push_back({f[0], f[2], f[1]});  // outward
        continue;
      }
      if (std::size_t(nb) >= nt) return ::testing::AssertionFailure() << "neighbour range";
      const auto& d = r.tetrahedra[std::size_t(nb)];
      int back = -1, shared = 0;
      for (int j = 0; j < 4; ++j) {
        if (d.neighbors[std::size_t(j)] == std::int32_t(t)) back = j;
        shared += std::count(key.begin(), key.end(), d.vertices[std::size_t(j)]) > 0 ? 1 : 0;
      }
      if (back < 0) return ::testing::AssertionFailure() << "adjacency not symmetric at " << t;
      if (shared != 3) return ::testing::AssertionFailure() << "neighbour misses the face " << t;
      const std::uint32_t opposite = d.vertices[std::size_t(back)];
      if (std::count(key.begin(), key.end(), opposite) != 0)
        return ::testing::AssertionFailure() << "neighbour face index at " << t;
      if (orient_sign(f[0], f[1], f[2], opposite) != Sign::negative)
        return ::testing::AssertionFailure() << "neighbour on the same side at " << t;
      // Local Delaunay: the opposite vertex is not strictly inside the circumsphere.
      const bool inside =
          brute ? exact_insphere(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]], pts[opposite]) > 0
                : locus::insphere(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]], pts[opposite]) ==
                      Sign::positive;
      if (inside)
        return ::testing::AssertionFailure() << "face of cell " << t << " not locally Delaunay";
    }
  }
  for (const auto& [key, count] : face_count)
    if (count > 2) return ::testing::AssertionFailure() << "face in " << count << " cells";
  for (std::size_t i = 0; i < n; ++i)
    if (r.duplicate_of[i] == i && !used[i])
      return ::testing::AssertionFailure() << "kept point " << i << " in no cell";
  // The hull: exactly the boundary faces, a closed surface (each directed edge once, with its
  // reverse), Euler characteristic 2.
  {
    auto a = boundary, b = r.hull;
    auto canon = [](std::array<std::uint32_t, 3> f) {
      std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
      return f;
    };
    for (auto& f : a) f = canon(f);
    for (auto& f : b) f = canon(f);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a != b) return ::testing::AssertionFailure() << "hull differs from the boundary faces";
    std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
    std::set<std::uint32_t> hv;
    for (const auto& f : r.hull)
      for (int i = 0; i < 3; ++i) {
        hv.insert(f[std::size_t(i)]);
        if (!directed.insert({f[std::size_t(i)], f[std::size_t((i + 1) % 3)]}).second)
          return ::testing::AssertionFailure() << "hull edge used twice in one direction";
      }
    for (const auto& [x, y] : directed)
      if (!directed.count({y, x})) return ::testing::AssertionFailure() << "hull not closed";
    const long chi = long(hv.size()) - long(directed.size() / 2) + long(r.hull.size());
    if (chi != 2) return ::testing::AssertionFailure() << "hull Euler characteristic " << chi;
  }
  // Euler for a triangulated ball: V - E + F - T = 1.
  std::size_t nv = 0;
  for (std::size_t i = 0; i < n; ++i) nv += r.duplicate_of[i] == i ? 1 : 0;
  const long chi = long(nv) - long(edges.size()) + long(face_count.size()) - long(nt);
  if (chi != 1) return ::testing::AssertionFailure() << "Euler characteristic " << chi;
  // Volume: the cells fill the hull exactly.
  if (volume != surface_volume(pts, r.hull))
    return ::testing::AssertionFailure() << "cell volumes differ from the hull surface volume";
  const auto hull = locus::convex_hull(pts);
  if (hull.status != Status::ok || hull.dimension != 3)
    return ::testing::AssertionFailure() << "hull3 failed";
  std::vector<std::array<std::uint32_t, 3>> h3(hull.triangles.begin(), hull.triangles.end());
  if (volume != surface_volume(pts, h3))
    return ::testing::AssertionFailure() << "cell volumes differ from hull3's volume";
  if (brute) {
    for (std::size_t t = 0; t < nt; ++t) {
      const auto& v = r.tetrahedra[t].vertices;
      for (std::size_t i = 0; i < n; ++i)
        if (exact_insphere(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]], pts[i]) > 0)
          return ::testing::AssertionFailure() << "point " << i << " inside sphere of " << t;
    }
  }
  return ::testing::AssertionSuccess();
}

template <class T>
Delaunay3Result run(const Points<T>& p, Delaunay3Method m = Delaunay3Method::incremental) {
  return locus::delaunay(std::span<const Vec3<T>>(p), Delaunay3Options{m});
}

template <class T>
Points<T> random_points(locus_test::Rng& rng, std::size_t n, T lo = T(-1), T hi = T(1)) {
  Points<T> p(n);
  for (auto& q : p) q = rng.vec<T, 3>(lo, hi);
  return p;
}

template <class T>
Points<T> grid(int nx, int ny, int nz, T step = T(1), T offset = T(0)) {
  Points<T> p;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        p.push_back({offset + step * T(i), offset + step * T(j), offset + step * T(k)});
  return p;
}

// Integer points on the sphere x^2 + y^2 + z^2 = r2 (exactly cospherical).
template <class T>
Points<T> integer_sphere(int r2) {
  Points<T> p;
  const int r = int(std::sqrt(double(r2))) + 1;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r2) p.push_back({T(x), T(y), T(z)});
  return p;
}

// ---- the oracle's own sign convention -----------------------------------------------------

TEST(Delaunay3Oracle, SignConvention) {
  const Vec3<double> a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  ASSERT_GT(exact_orient(a, b, c, d), 0);
  EXPECT_GT(exact_insphere(a, b, c, d, Vec3<double>{0.25, 0.25, 0.25}), 0);
  EXPECT_LT(exact_insphere(a, b, c, d, Vec3<double>{3, 3, 3}), 0);
  EXPECT_EQ(exact_insphere(a, b, c, d, Vec3<double>{1, 1, 0}), 0);  // cospherical
  EXPECT_EQ(locus::insphere(a, b, c, d, Vec3<double>{0.25, 0.25, 0.25}), Sign::positive);
}

// The library's perturbed predicate against the rational perturbation written out here, on
// every quintuple of a small cospherical set.
TEST(Delaunay3Oracle, PerturbedInsphereMatchesRationalPerturbation) {
  const auto p = grid<double>(2, 2, 3);
  std::size_t zeros = 0;
  for (std::size_t a = 0; a < p.size(); ++a)
    for (std::size_t b0 = a + 1; b0 < p.size(); ++b0)
      for (std::size_t c0 = b0 + 1; c0 < p.size(); ++c0)
        for (std::size_t d = c0 + 1; d < p.size(); ++d) {
          std::size_t b = b0, c = c0;
          const Sign o = locus::orient3d(p[a], p[b], p[c], p[d]);
          if (o == Sign::zero) continue;
          if (o == Sign::negative) std::swap(b, c);
          for (std::size_t e = 0; e < p.size(); ++e) {
            if (e == a || e == b || e == c || e == d) continue;
            const int v = perturbed_insphere_sign(p[a], p[b], p[c], p[d], p[e]);
            ASSERT_NE(v, 0);
            const Sign s = locus::insphere_perturbed(p[a], p[b], p[c], p[d], p[e]);
            ASSERT_EQ(s, v > 0 ? Sign::positive : Sign::negative) << a << b << c << d << e;
            zeros += exact_insphere(p[a], p[b], p[c], p[d], p[e]) == 0 ? 1 : 0;
          }
        }
  EXPECT_GT(zeros, 20u);  // the perturbation was exercised
}

// ---- small and degenerate inputs ---------------------------------------------------------

TYPED_TEST(Delaunay3Test, ZeroToFourPoints) {
  using T = TypeParam;
  Points<T> p;
  auto r = run(p);
  EXPECT_EQ(r.status, Status::empty_input);
  EXPECT_EQ(r.dimension, -1);

  p = {{T(1), T(2), T(3)}};
  r = run(p);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 0);
  EXPECT_TRUE(r.tetrahedra.empty());

  p.push_back({T(2), T(2), T(3)});
  r = run(p);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 1);

  p.push_back({T(2), T(5), T(3)});
  r = run(p);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 2);
  EXPECT_TRUE(r.tetrahedra.empty());
  EXPECT_TRUE(r.hull.empty());

  p.push_back({T(1), T(2), T(1)});  // below the plane z = 3: any order of the input
  for (int perm = 0; perm < 24; ++perm) {
    Points<T> q = p;
    std::vector<int> idx = {0, 1, 2, 3};
    for (int k = 0; k < perm; ++k) std::next_permutation(idx.begin(), idx.end());
    for (int k = 0; k < 4; ++k) q[std::size_t(k)] = p[std::size_t(idx[std::size_t(k)])];
    r = run(q);
    ASSERT_TRUE(check_delaunay3(q, r, true));
    ASSERT_EQ(r.tetrahedron_count(), 1u);
    EXPECT_EQ(r.hull.size(), 4u);
    for (auto nb : r.tetrahedra[0].neighbors) EXPECT_EQ(nb, -1);
  }
}

TYPED_TEST(Delaunay3Test, CollinearAndCoplanar) {
  using T = TypeParam;
  Points<T> line;
  for (int i = 0; i < 20; ++i) line.push_back({T(i % 7), T(2 * (i % 7)), T(-3 * (i % 7))});
  auto r = run(line);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 1);
  EXPECT_TRUE(r.tetrahedra.empty());
  EXPECT_EQ(r.duplicate_count, 13u);  // 7 distinct points
  for (std::size_t i = 0; i < line.size(); ++i) {
    const auto d = r.duplicate_of[i];
    EXPECT_TRUE(line[d].x == line[i].x && line[d].y == line[i].y && line[d].z == line[i].z);
  }
  // A tilted plane x + 2y - z = 1 with exact integer points.
  Points<T> plane;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 200; ++i) {
    const int x = rng.uniform_int(-50, 50), y = rng.uniform_int(-50, 50);
    plane.push_back({T(x), T(y), T(x + 2 * y - 1)});
  }
  r = run(plane);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 2);
  EXPECT_TRUE(r.tetrahedra.empty());
  const auto lifted = run(plane, Delaunay3Method::lifted_hull);
  EXPECT_EQ(lifted.status, Status::invalid_input);  // more than 64 points
  // One point off the plane: a valid tetrahedralization of a flat cone.
  plane.push_back({T(0), T(0), T(7)});
  r = run(plane);
  EXPECT_TRUE(check_delaunay3(plane, r, false));
}

TYPED_TEST(Delaunay3Test, NonFiniteInput) {
  using T = TypeParam;
  locus_test::Rng rng;
  auto p = random_points<T>(rng, 50);
  for (const T bad : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                      -std::numeric_limits<T>::infinity()}) {
    for (int axis = 0; axis < 3; ++axis) {
      auto q = p;
      q[17][axis] = bad;
      for (auto m : {Delaunay3Method::incremental, Delaunay3Method::lifted_hull}) {
        const auto r = run(q, m);
        EXPECT_EQ(r.status, Status::non_finite_input);
        EXPECT_EQ(r.dimension, -1);
        EXPECT_TRUE(r.tetrahedra.empty());
      }
    }
  }
}

TYPED_TEST(Delaunay3Test, Duplicates) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  auto base = random_points<T>(rng, 300 / std::size_t(kScale));
  auto p = base;
  for (int k = 0; k < 200 / kScale; ++k)
    p.push_back(base[std::size_t(rng.uniform_int(0, int(base.size()) - 1))]);
  std::shuffle(p.begin(), p.end(), rng.engine());
  const auto r = run(p);
  ASSERT_TRUE(check_delaunay3(p, r, false));
  EXPECT_EQ(r.duplicate_count, p.size() - base.size());
  // The same tetrahedra as the input without duplicates (mapped to its indices).
  const auto r0 = run(base);
  ASSERT_TRUE(check_delaunay3(base, r0, false));
  auto key = [](const Vec3<T>& q) { return std::array<T, 3>{q.x, q.y, q.z}; };
  std::set<std::array<std::array<T, 3>, 4>> a, b;
  for (const auto& c : r.tetrahedra) {
    std::array<std::array<T, 3>, 4> t;
    for (int i = 0; i < 4; ++i) t[std::size_t(i)] = key(p[c.vertices[std::size_t(i)]]);
    std::sort(t.begin(), t.end());
    a.insert(t);
  }
  for (const auto& c : r0.tetrahedra) {
    std::array<std::array<T, 3>, 4> t;
    for (int i = 0; i < 4; ++i) t[std::size_t(i)] = key(base[c.vertices[std::size_t(i)]]);
    std::sort(t.begin(), t.end());
    b.insert(t);
  }
  EXPECT_EQ(a, b);
  // All points equal.
  Points<T> same(40, Vec3<T>{T(0.5), T(-2), T(8)});
  const auto rs = run(same);
  EXPECT_EQ(rs.status, Status::ok);
  EXPECT_EQ(rs.dimension, 0);
  EXPECT_EQ(rs.duplicate_count, 39u);
}

// ---- oracles -----------------------------------------------------------------------------

// Random points in general position: the incremental method, the lifted-hull method and the
// brute-force oracle written here give the same set of tetrahedra.
TYPED_TEST(Delaunay3Test, RandomSmallAgainstOracles) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int round = 0; round < 10 / kScale; ++round) {
    const std::size_t n = std::size_t(5 + rng.uniform_int(0, 17));
    const auto p = random_points<T>(rng, n);
    const auto r = run(p);
    ASSERT_TRUE(check_delaunay3(p, r, true)) << "round " << round;
    const auto lifted = run(p, Delaunay3Method::lifted_hull);
    ASSERT_TRUE(check_delaunay3(p, lifted, true)) << "round " << round;
    EXPECT_EQ(tet_set(r), tet_set(lifted)) << "round " << round;
    EXPECT_EQ(tet_set(r), brute_force(p, false)) << "round " << round;
  }
}

// Cospherical input: the Delaunay tetrahedralization is not unique; the perturbation picks one,
// the same one for both methods and for the rational perturbation of the oracle.
TYPED_TEST(Delaunay3Test, CosphericalAgainstOracles) {
  using T = TypeParam;
  std::vector<Points<T>> cases = {grid<T>(2, 2, 2),     grid<T>(3, 3, 3),
                                  grid<T>(2, 3, 4),     integer_sphere<T>(25),
                                  integer_sphere<T>(5), integer_sphere<T>(2)};
  Points<T> cube_center = grid<T>(2, 2, 2, T(2));
  cube_center.push_back({T(1), T(1), T(1)});
  cases.push_back(cube_center);
  auto sphere_center = integer_sphere<T>(5);
  sphere_center.push_back({T(0), T(0), T(0)});
  cases.push_back(sphere_center);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto& p = cases[k];
    if (kScale > 1 && p.size() > 25) continue;  // (sanitizer run time)
    const auto r = run(p);
    ASSERT_TRUE(check_delaunay3(p, r, true)) << "case " << k;
    const auto lifted = run(p, Delaunay3Method::lifted_hull);
    ASSERT_TRUE(check_delaunay3(p, lifted, true)) << "case " << k;
    const TetSet s = tet_set(r);
    EXPECT_EQ(s, tet_set(lifted)) << "case " << k;
    if (p.size() <= 25) {  // (test time)
      EXPECT_EQ(s, brute_force(p, true)) << "case " << k;
    }
  }
  // Book-style known answer: the cube's corners and its centre give 12 tetrahedra (the centre
  // joined to two triangles per face).
  EXPECT_EQ(run(cube_center).tetrahedron_count(), 12u);
}

// The perturbation depends on coordinates only: permuted input gives the same tetrahedra.
TYPED_TEST(Delaunay3Test, PermutationAndTranslationInvariance) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto p = grid<T>(5, 4, 6);
  const auto r = run(p);
  ASSERT_TRUE(check_delaunay3(p, r, false));
  std::vector<std::uint32_t> perm(p.size());
  std::iota(perm.begin(), perm.end(), 0u);
  std::shuffle(perm.begin(), perm.end(), rng.engine());
  Points<T> q(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) q[i] = p[perm[i]];
  const auto rq = run(q);
  ASSERT_TRUE(check_delaunay3(q, rq, false));
  TetSet mapped;
  for (const auto& c : rq.tetrahedra) {
    std::array<std::uint32_t, 4> t;
    for (int i = 0; i < 4; ++i) t[std::size_t(i)] = perm[c.vertices[std::size_t(i)]];
    mapped.insert(sorted4(t));
  }
  EXPECT_EQ(mapped, tet_set(r));
  // Exact translation and power-of-two scaling keep every predicate sign.
  Points<T> moved(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    moved[i] = {T(64) + T(0.5) * p[i].x, T(-32) + T(0.5) * p[i].y, T(16) + T(0.5) * p[i].z};
  EXPECT_EQ(tet_set(run(moved)), tet_set(r));
}

TYPED_TEST(Delaunay3Test, GridsAndSpheres) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const int side = kScale == 1 ? 10 : 6;
  const auto g = grid<T>(side, side, side, T(0.25), T(-1));
  const auto rg = run(g);
  ASSERT_TRUE(check_delaunay3(g, rg, false));
  // Points on a sphere (rounded, so nearly cospherical), with the centre.
  Points<T> s;
  for (int i = 0; i < 2000 / kScale; ++i) s.push_back(rng.unit<T, 3>());
  s.push_back({T(0), T(0), T(0)});
  const auto rs = run(s);
  ASSERT_TRUE(check_delaunay3(s, rs, false));
  // Every sphere point is a hull vertex.
  std::set<std::uint32_t> hv;
  for (const auto& f : rs.hull) hv.insert(f.begin(), f.end());
  EXPECT_EQ(hv.size(), s.size() - 1 - rs.duplicate_count);
}

TYPED_TEST(Delaunay3Test, RandomMedium) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto p = random_points<T>(rng, std::size_t(5000 / kScale));
  const auto r = run(p);
  ASSERT_TRUE(check_delaunay3(p, r, false));
  // Reuse: the class gives the same result twice and the same as the one-call function.
  locus::Delaunay3<T> d;
  const auto& a = d.triangulate(std::span<const Vec3<T>>(p));
  EXPECT_EQ(tet_set(a), tet_set(r));
  std::vector<T> flat;
  for (const auto& q : p) flat.insert(flat.end(), {q.x, q.y, q.z});
  const auto& b = d.triangulate(flat.data(), p.size());
  EXPECT_EQ(tet_set(b), tet_set(r));
}

// Clustered and anisotropic input: a thin slab, a few dense clusters, and points on a line
// plus one off it (a fan of thin cells).
TYPED_TEST(Delaunay3Test, ClusteredAndThin) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  Points<T> slab;
  for (int i = 0; i < 1000 / kScale; ++i)
    slab.push_back(
        {rng.uniform(T(-1), T(1)), rng.uniform(T(-1), T(1)), rng.uniform(T(-1e-3), T(1e-3))});
  EXPECT_TRUE(check_delaunay3(slab, run(slab), false));
  Points<T> clusters;
  for (int c = 0; c < 5; ++c) {
    const Vec3<T> centre = rng.vec<T, 3>(T(-100), T(100));
    for (int i = 0; i < 300 / kScale; ++i)
      clusters.push_back(centre + rng.vec<T, 3>(T(-1e-2), T(1e-2)));
  }
  EXPECT_TRUE(check_delaunay3(clusters, run(clusters), false));
  Points<T> fan;
  for (int i = 0; i < 100; ++i) fan.push_back({T(i), T(0), T(0)});
  fan.push_back({T(3), T(1), T(0)});
  fan.push_back({T(50), T(2), T(7)});
  EXPECT_TRUE(check_delaunay3(fan, run(fan), true));
}

TYPED_TEST(Delaunay3Test, HugeAndTinyCoordinates) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto p = random_points<T>(rng, 300);
  const auto r = run(p);
  ASSERT_TRUE(check_delaunay3(p, r, false));
  // Power-of-two scalings within insphere's exact range keep every sign.
  const int exps[] = {std::is_same_v<T, float> ? 60 : 150, std::is_same_v<T, float> ? -60 : -120};
  for (const int e : exps) {
    Points<T> q(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      for (int k = 0; k < 3; ++k) q[i][k] = std::ldexp(p[i][k], e);
    const auto rq = run(q);
    ASSERT_TRUE(check_delaunay3(q, rq, false)) << "exponent " << e;
    EXPECT_EQ(tet_set(rq), tet_set(r)) << "exponent " << e;
  }
  // A grid far from the origin: differences are small against the coordinates.
  const auto g = grid<T>(4, 4, 4, T(1), std::is_same_v<T, float> ? T(4096) : T(1 << 30));
  EXPECT_TRUE(check_delaunay3(g, run(g), false));
}

}  // namespace
