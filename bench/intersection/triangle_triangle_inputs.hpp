// SPDX-License-Identifier: BSL-1.0
#pragma once
// The inputs of triangle_triangle_bench.cpp (locus) and triangle_triangle_peers_bench.cpp (FCL,
// CGAL Epick): the same seeded double pairs, generated once in each translation unit (separate
// so that locus is compiled with a locus user's flags, without the -frounding-math CGAL's target
// adds). Row int3.plane-triangle (issue 20, item 12). Sets (1024 pairs each):
//   generic:   random triangles in [-1, 1]^3, pairs (k, 7k + 1 mod 1024); about 27% meet.
//   shared:    neighbouring triangles of a bent grid mesh sharing an edge (within a cell) or a
//              vertex (across cells); both planes pass through the shared points; all meet.
//   tjunction: a vertex of one triangle exactly on an edge of the other, shared by nothing: a
//              coarse triangle of a bent grid (coordinates multiples of 2^-30, so its edges'
//              midpoints are exact) and a finer triangle below it hanging from the midpoint of
//              its edge (a T-junction of an adaptively refined mesh). They meet exactly at that
//              point (all meet); the plane signs and interval ends there are exact zeros on no
//              small lattice, so every implementation meets its degenerate case.

#include <locus/core/vec.hpp>
#include <locus/primitives/triangle.hpp>

#include <cmath>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

namespace locus_bench_tritri {

using V = locus::Vec3<double>;
using Tri = locus::Triangle3<double>;
using Pair = std::pair<Tri, Tri>;

inline constexpr const char* kSetNames[3] = {"generic", "shared", "tjunction"};

inline std::vector<Pair> make_generic() {
  std::mt19937_64 g(20261205);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto v = [&] { return V{u(g), u(g), u(g)}; };
  std::vector<Tri> t;
  for (int i = 0; i < 1024; ++i) t.push_back({v(), v(), v()});
  std::vector<Pair> p;
  for (std::size_t k = 0; k < t.size(); ++k) p.push_back({t[k], t[(7 * k + 1) % t.size()]});
  return p;
}

/// The bent grid z = 0.1 x^2 - 0.3 y^2 + 0.7 x y at x = i / 16 - 1, y = j / 16 - 1 (z rounded
/// once to a double, or to a multiple of 2^-quantum when quantum > 0).
inline V grid_point(int i, int j, int quantum) {
  const double x = i / 16.0 - 1, y = j / 16.0 - 1;
  double z = 0.1 * x * x - 0.3 * y * y + 0.7 * x * y;
  if (quantum > 0) z = std::ldexp(std::round(std::ldexp(z, quantum)), -quantum);
  return {x, y, z};
}

inline std::vector<Pair> make_shared() {
  // Triangles (a, b, c), (b, d, c) of each cell; pairs sharing an edge (within a cell) or a
  // vertex (across cells).
  std::vector<Pair> p;
  for (int j = 0; j + 1 < 33 && p.size() < 1024; ++j) {
    for (int i = 0; i + 2 < 33 && p.size() < 1024; ++i) {
      const auto at = [&](int di, int dj) { return grid_point(i + di, j + dj, 0); };
      const Tri t0{at(0, 0), at(1, 0), at(0, 1)}, t1{at(1, 0), at(1, 1), at(0, 1)},
          t2{at(1, 0), at(2, 0), at(1, 1)};
      p.push_back({t0, t1});  // shared edge
      p.push_back({t0, t2});  // shared vertex
    }
  }
  return p;
}

inline std::vector<Pair> make_tjunction() {
  // Coarse triangle a = (P(i, j), P(i + 2, j), P(i, j + 2)) above the row j; the fine triangle
  // b = (M, P(i + 2, j - 1), P(i, j - 1)) below it, M the exact midpoint of a's edge
  // P(i, j) P(i + 2, j). Every point of b but M has y < y_j <= the y of every point of a, so
  // the common set is exactly {M}. Alternate argument orders and vertex rotations.
  std::vector<Pair> p;
  for (int j = 1; j + 2 < 33 && p.size() < 1024; ++j) {
    for (int i = 0; i + 2 < 33 && p.size() < 1024; ++i) {
      const auto at = [&](int di, int dj) { return grid_point(i + di, j + dj, 30); };
      const V m = (at(0, 0) + at(2, 0)) * 0.5;
      const Tri a{at(0, 0), at(2, 0), at(0, 2)};
      const Tri b{m, at(2, -1), at(0, -1)};
      const int r = static_cast<int>(p.size() % 3);
      const Tri br{b[r], b[(r + 1) % 3], b[(r + 2) % 3]};
      if (p.size() % 2 == 0) {
        p.push_back({a, br});
      } else {
        p.push_back({br, a});
      }
    }
  }
  return p;
}

/// The pairs of set 0 (generic), 1 (shared) or 2 (tjunction), built once.
inline const std::vector<Pair>& pairs(int set) {
  static const std::vector<Pair> sets[3] = {make_generic(), make_shared(), make_tjunction()};
  return sets[set];
}

}  // namespace locus_bench_tritri
