// SPDX-License-Identifier: BSL-1.0
// Row int3.plane-triangle (issue 20, item 12): triangle-triangle test, locus intersects()
// (exact) against FCL's Intersect::intersect_Triangle and CGAL's do_intersect on
// Exact_predicates_inexact_constructions_kernel (exact predicates), when found. Inputs (seeded):
//   generic: 1024 random triangles in [-1, 1]^3, pairs (k, 7k + 1 mod 1024);
//   touching: pairs of neighbouring triangles of a bent grid mesh (shared edge or vertex, both
//     planes through the shared points): every pair meets, exactly.
// Each iteration answers one pair; the answers are summed. Counters: meet_rate, and disagree:
// pairs where the peer's answer differs from locus's (checked once, outside the timing).

#include <benchmark/benchmark.h>

#include <locus/intersection/triangle_triangle.hpp>

#include <array>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

#if defined(LOCUS_HAVE_FCL)
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>
#endif
#if defined(LOCUS_HAVE_CGAL)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#endif

namespace {

using namespace locus;
using Pair = std::pair<Triangle3<double>, Triangle3<double>>;

const std::vector<Pair>& pairs(int set) {
  static const std::vector<Pair> generic = [] {
    std::mt19937_64 g(20261205);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto v = [&] { return Vec3<double>{u(g), u(g), u(g)}; };
    std::vector<Triangle3<double>> t;
    for (int i = 0; i < 1024; ++i) t.push_back({v(), v(), v()});
    std::vector<Pair> p;
    for (std::size_t k = 0; k < t.size(); ++k) p.push_back({t[k], t[(7 * k + 1) % t.size()]});
    return p;
  }();
  static const std::vector<Pair> touching = [] {
    // A 33 x 33 grid on z = 0.1 x^2 - 0.3 y^2 + 0.7 x y (bent: neighbours are not coplanar),
    // coordinates rounded to doubles once; triangles (a, b, c), (b, d, c) of each cell, and
    // pairs of triangles sharing an edge (within a cell) or a vertex (across cells).
    const int m = 33;
    std::vector<Vec3<double>> q;
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < m; ++i) {
        const double x = i / 16.0 - 1, y = j / 16.0 - 1;
        q.push_back({x, y, 0.1 * x * x - 0.3 * y * y + 0.7 * x * y});
      }
    }
    const auto at = [&](int i, int j) { return q[static_cast<std::size_t>(j * m + i)]; };
    std::vector<Pair> p;
    for (int j = 0; j + 1 < m && p.size() < 1024; ++j) {
      for (int i = 0; i + 2 < m && p.size() < 1024; ++i) {
        const Triangle3<double> t0{at(i, j), at(i + 1, j), at(i, j + 1)},
            t1{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)},
            t2{at(i + 1, j), at(i + 2, j), at(i + 1, j + 1)};
        p.push_back({t0, t1});  // shared edge
        p.push_back({t0, t2});  // shared vertex
      }
    }
    return p;
  }();
  return set == 0 ? generic : touching;
}

void BM_TriangleTriangle_locus(benchmark::State& state) {
  const auto& p = pairs(static_cast<int>(state.range(0)));
  std::size_t i = 0, meet = 0;
  for (auto _ : state) {
    const Pair& q = p[i % p.size()];
    meet += intersects(q.first, q.second);
    ++i;
  }
  state.counters["meet_rate"] = double(meet) / double(i);
  benchmark::DoNotOptimize(meet);
}
BENCHMARK(BM_TriangleTriangle_locus)->Arg(0)->Arg(1);

#if defined(LOCUS_HAVE_FCL)
void BM_TriangleTriangle_fcl(benchmark::State& state) {
  const auto& p = pairs(static_cast<int>(state.range(0)));
  const auto e = [](const Vec3<double>& v) { return fcl::Vector3d(v.x, v.y, v.z); };
  std::vector<std::array<fcl::Vector3d, 6>> f;
  for (const Pair& q : p) {
    f.push_back({e(q.first.v0), e(q.first.v1), e(q.first.v2), e(q.second.v0), e(q.second.v1),
                 e(q.second.v2)});
  }
  const auto test = [](const std::array<fcl::Vector3d, 6>& t) {
    return fcl::detail::Intersectd::intersect_Triangle(t[0], t[1], t[2], t[3], t[4], t[5]);
  };
  std::size_t disagree = 0;
  for (std::size_t k = 0; k < p.size(); ++k)
    disagree += test(f[k]) != intersects(p[k].first, p[k].second);
  std::size_t i = 0, meet = 0;
  for (auto _ : state) {
    meet += test(f[i % f.size()]);
    ++i;
  }
  state.counters["meet_rate"] = double(meet) / double(i);
  state.counters["disagree"] = double(disagree);
  benchmark::DoNotOptimize(meet);
}
BENCHMARK(BM_TriangleTriangle_fcl)->Arg(0)->Arg(1);
#endif

#if defined(LOCUS_HAVE_CGAL)
void BM_TriangleTriangle_cgal_epick(benchmark::State& state) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto& p = pairs(static_cast<int>(state.range(0)));
  const auto e = [](const Vec3<double>& v) { return K::Point_3(v.x, v.y, v.z); };
  std::vector<std::pair<K::Triangle_3, K::Triangle_3>> c;
  for (const Pair& q : p) {
    c.push_back({{e(q.first.v0), e(q.first.v1), e(q.first.v2)},
                 {e(q.second.v0), e(q.second.v1), e(q.second.v2)}});
  }
  std::size_t disagree = 0;
  for (std::size_t k = 0; k < p.size(); ++k)
    disagree += CGAL::do_intersect(c[k].first, c[k].second) != intersects(p[k].first, p[k].second);
  std::size_t i = 0, meet = 0;
  for (auto _ : state) {
    const auto& q = c[i % c.size()];
    meet += CGAL::do_intersect(q.first, q.second);
    ++i;
  }
  state.counters["meet_rate"] = double(meet) / double(i);
  state.counters["disagree"] = double(disagree);
  benchmark::DoNotOptimize(meet);
}
BENCHMARK(BM_TriangleTriangle_cgal_epick)->Arg(0)->Arg(1);
#endif

}  // namespace
