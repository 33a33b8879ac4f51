// SPDX-License-Identifier: BSL-1.0
// The peers of triangle_triangle_bench.cpp on the same sets: FCL's
// Intersect::intersect_Triangle (floating point) and CGAL's do_intersect on
// Exact_predicates_inexact_constructions_kernel (exact predicates), when found. Counter disagree:
// pairs where the peer's answer differs from locus's exact one (checked once, outside the
// timing).

#include "intersection/triangle_triangle_inputs.hpp"

#include <locus/intersection/triangle_triangle.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
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

using namespace locus_bench_tritri;

#if defined(LOCUS_HAVE_FCL)
void BM_fcl(benchmark::State& state, int set) {
  const auto& p = pairs(set);
  const auto e = [](const V& v) { return fcl::Vector3d(v.x, v.y, v.z); };
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
    disagree += test(f[k]) != locus::intersects(p[k].first, p[k].second);
  std::size_t i = 0, meet = 0;
  for (auto _ : state) {
    meet += test(f[i % f.size()]);
    ++i;
  }
  state.counters["meet_rate"] = double(meet) / double(i);
  state.counters["disagree"] = double(disagree);
  state.SetItemsProcessed(static_cast<std::int64_t>(i));
  benchmark::DoNotOptimize(meet);
}
#endif

#if defined(LOCUS_HAVE_CGAL)
void BM_cgal_epick(benchmark::State& state, int set) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto& p = pairs(set);
  const auto e = [](const V& v) { return K::Point_3(v.x, v.y, v.z); };
  std::vector<std::pair<K::Triangle_3, K::Triangle_3>> c;
  for (const Pair& q : p) {
    c.push_back({{e(q.first.v0), e(q.first.v1), e(q.first.v2)},
                 {e(q.second.v0), e(q.second.v1), e(q.second.v2)}});
  }
  std::size_t disagree = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    disagree +=
        CGAL::do_intersect(c[k].first, c[k].second) != locus::intersects(p[k].first, p[k].second);
  }
  std::size_t i = 0, meet = 0;
  for (auto _ : state) {
    const auto& q = c[i % c.size()];
    meet += CGAL::do_intersect(q.first, q.second);
    ++i;
  }
  state.counters["meet_rate"] = double(meet) / double(i);
  state.counters["disagree"] = double(disagree);
  state.SetItemsProcessed(static_cast<std::int64_t>(i));
  benchmark::DoNotOptimize(meet);
}
#endif

const int registered = [] {
  for (int set = 0; set < 3; ++set) {
    const std::string tail = std::string("/") + kSetNames[set];
#if defined(LOCUS_HAVE_FCL)
    benchmark::RegisterBenchmark(("triangle_triangle/fcl" + tail).c_str(), BM_fcl, set);
#endif
#if defined(LOCUS_HAVE_CGAL)
    benchmark::RegisterBenchmark(("triangle_triangle/cgal<Epick>" + tail).c_str(), BM_cgal_epick,
                                 set);
#endif
  }
  return 0;
}();

}  // namespace
