// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact invariant checks shared by the Delaunay tests: every decision by exact predicates or GMP
// rationals, never by the code under test.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <locus/core/predicates.hpp>
#include <locus/delaunay/delaunay2.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace locus_test {

template <class T>
mpq_class exact_cross(const locus::Vec2<T>& a, const locus::Vec2<T>& b, const locus::Vec2<T>& c) {
  const mpq_class ax(double(a.x)), ay(double(a.y)), bx(double(b.x)), by(double(b.y)),
      cx(double(c.x)), cy(double(c.y));
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/// Twice the signed area of a polygon given by indices, exactly (shoelace in mpq).
template <class T>
mpq_class exact_twice_area(const std::vector<locus::Vec2<T>>& pts,
                           const std::vector<std::uint32_t>& poly) {
  mpq_class s = 0;
  const std::size_t m = poly.size();
  for (std::size_t i = 0; i < m; ++i) {
    const auto& a = pts[poly[i]];
    const auto& b = pts[poly[(i + 1) % m]];
    s += mpq_class(double(a.x)) * mpq_class(double(b.y)) -
         mpq_class(double(b.x)) * mpq_class(double(a.y));
  }
  return s;
}

using EdgeSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

inline EdgeSet edge_set(const locus::Delaunay2Result& r) {
  EdgeSet s;
  for (const auto& t : r.triangles)
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t a = t[i], b = t[(i + 1) % 3];
      s.insert({std::min(a, b), std::max(a, b)});
    }
  return s;
}

/// Checks a 2D result exactly: orientation, adjacency symmetry, hull convexity and coverage,
/// Euler's formula, exact area sum, local (hence global) empty circumcircles, duplicates.
/// With `brute` also the global empty-circle property against every point (O(n T)).
/// `constrained` (a CDT's per-edge flags) exempts those edges from the empty-circle test.
template <class T>
::testing::AssertionResult check_delaunay(
    const std::vector<locus::Vec2<T>>& pts, const locus::Delaunay2Result& r, bool brute = false,
    const std::vector<std::array<std::uint8_t, 3>>* constrained = nullptr) {
  using locus::Sign;
  const std::size_t n = pts.size();
  if (r.status != locus::Status::ok) return ::testing::AssertionFailure() << "status not ok";
  if (r.duplicate_of.size() != n) return ::testing::AssertionFailure() << "duplicate_of size";
  std::size_t dups = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t d = r.duplicate_of[i];
    if (d >= n) return ::testing::AssertionFailure() << "duplicate_of out of range";
    if (d != i) {
      ++dups;
      if (r.duplicate_of[d] != d) return ::testing::AssertionFailure() << "duplicate chain";
      if (!(pts[d].x == pts[i].x && pts[d].y == pts[i].y))
        return ::testing::AssertionFailure() << "duplicate_of names a different point " << i;
    }
  }
  if (dups != r.duplicate_count) return ::testing::AssertionFailure() << "duplicate_count";
  // Kept points are pairwise distinct (sort check).
  std::vector<std::pair<T, T>> kept;
  for (std::size_t i = 0; i < n; ++i)
    if (r.duplicate_of[i] == i) kept.push_back({pts[i].x, pts[i].y});
  std::sort(kept.begin(), kept.end());
  if (std::adjacent_find(kept.begin(), kept.end()) != kept.end())
    return ::testing::AssertionFailure() << "two kept points are equal";
  const std::size_t nv = kept.size();

  if (r.dimension != 2) return ::testing::AssertionFailure() << "dimension " << r.dimension;
  const std::size_t nt = r.triangles.size();
  if (r.adjacency.size() != nt || nt == 0 || r.triangle_count() != nt)
    return ::testing::AssertionFailure() << "array sizes";
  if (constrained && constrained->size() != nt)
    return ::testing::AssertionFailure() << "constrained size";
  const auto& tri = r.triangles;
  std::vector<char> used(n, 0);
  std::size_t boundary = 0;
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t a = tri[t][i], b = tri[t][(i + 1) % 3];
      if (a >= n || r.duplicate_of[a] != a)
        return ::testing::AssertionFailure() << "bad vertex at " << t << "," << i;
      used[a] = 1;
      const std::uint32_t u = r.adjacency[t][i];
      if (u == locus::kNoTriangle) {
        ++boundary;
        continue;
      }
      if (u >= nt) return ::testing::AssertionFailure() << "adjacency out of range at " << t;
      // The triangle across has the edge reversed (b, a), and names t across it.
      std::size_t j = 3;
      for (std::size_t k = 0; k < 3; ++k)
        if (tri[u][k] == b && tri[u][(k + 1) % 3] == a) j = k;
      if (j == 3) return ::testing::AssertionFailure() << "adjacency endpoints at " << t;
      if (r.adjacency[u][j] != t) return ::testing::AssertionFailure() << "adjacency asymmetry";
    }
  for (std::size_t i = 0; i < n; ++i)
    if (r.duplicate_of[i] == i && !used[i])
      return ::testing::AssertionFailure() << "kept point " << i << " in no triangle";
  for (std::size_t t = 0; t < nt; ++t) {
    if (locus::orient2d(pts[tri[t][0]], pts[tri[t][1]], pts[tri[t][2]]) != Sign::positive)
      return ::testing::AssertionFailure() << "triangle " << t << " not strictly CCW";
  }
  // Hull: convex (no right turn), its edges are exactly the boundary edges.
  const std::size_t h = r.hull.size();
  if (h != boundary)
    return ::testing::AssertionFailure() << "hull size " << h << " vs " << boundary;
  std::set<std::pair<std::uint32_t, std::uint32_t>> bedges;
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t i = 0; i < 3; ++i)
      if (r.adjacency[t][i] == locus::kNoTriangle) bedges.insert({tri[t][i], tri[t][(i + 1) % 3]});
  for (std::size_t i = 0; i < h; ++i) {
    const std::uint32_t a = r.hull[i], b = r.hull[(i + 1) % h], c = r.hull[(i + 2) % h];
    if (!bedges.count({a, b})) return ::testing::AssertionFailure() << "hull edge not boundary";
    if (locus::orient2d(pts[a], pts[b], pts[c]) == Sign::negative)
      return ::testing::AssertionFailure() << "hull not convex at " << i;
  }
  // Euler for a triangulated disc: V - E + F = 1, i.e. T = 2V - h - 2.
  if (nt != 2 * nv - h - 2)
    return ::testing::AssertionFailure() << "Euler: T=" << nt << " V=" << nv << " h=" << h;
  // Exact area: sum of triangles = hull area.
  mpq_class sum = 0;
  for (std::size_t t = 0; t < nt; ++t)
    sum += exact_cross(pts[tri[t][0]], pts[tri[t][1]], pts[tri[t][2]]);
  if (sum != exact_twice_area(pts, r.hull))
    return ::testing::AssertionFailure() << "area sum differs from hull area";
  // Locally Delaunay at every interior edge (implies globally Delaunay).
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t u = r.adjacency[t][i];
      if (u == locus::kNoTriangle) continue;
      const std::uint32_t a = tri[t][i], b = tri[t][(i + 1) % 3];
      std::size_t j = 0;  // edge (b, a) of u, found above
      while (!(tri[u][j] == b && tri[u][(j + 1) % 3] == a)) ++j;
      if (constrained && (*constrained)[t][i]) {
        if (!(*constrained)[u][j])
          return ::testing::AssertionFailure() << "constrained flag on one side only at " << t;
        continue;
      }
      const std::uint32_t z = tri[u][(j + 2) % 3];
      if (locus::incircle(pts[tri[t][0]], pts[tri[t][1]], pts[tri[t][2]], pts[z]) == Sign::positive)
        return ::testing::AssertionFailure()
               << "edge " << i << " of " << t << " not locally Delaunay";
    }
  if (brute && !constrained) {
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t i = 0; i < n; ++i)
        if (locus::incircle(pts[tri[t][0]], pts[tri[t][1]], pts[tri[t][2]], pts[i]) ==
            Sign::positive)
          return ::testing::AssertionFailure() << "point " << i << " inside circle of " << t;
    // Every point inside or on the hull.
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < h; ++k)
        if (locus::orient2d(pts[r.hull[k]], pts[r.hull[(k + 1) % h]], pts[i]) == Sign::negative)
          return ::testing::AssertionFailure() << "point " << i << " outside the hull";
  }
  return ::testing::AssertionSuccess();
}

/// Reads a delaunator fixture: a JSON array of [x, y] pairs.
inline std::vector<locus::Vec2<double>> read_xy_json(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  for (char& c : s)
    if (c == '[' || c == ']' || c == ',') c = ' ';
  std::istringstream is(s);
  std::vector<locus::Vec2<double>> pts;
  double x, y;
  while (is >> x >> y) pts.push_back({x, y});
  return pts;
}

}  // namespace locus_test
