// SPDX-License-Identifier: BSL-1.0
// Row int3.plane-triangle (issue 20, item 12): the triangle-triangle test, locus intersects()
// (exact), on the sets of triangle_triangle_inputs.hpp; the peers (FCL's
// Intersect::intersect_Triangle, CGAL's do_intersect on Epick) are in
// triangle_triangle_peers_bench.cpp. Names triangle_triangle/<impl>/<set> (scripts/bench_rounds
// forms the ratios). Each iteration answers one pair; the answers are summed (counter
// meet_rate). triangle_triangle/locus_general/<set> times detail::tri3::intersects_general, the
// general test intersects() used for every pair before (plane rejection, six segment-triangle
// tests), now its coplanar and degenerate path: the before/after in one run.

#include "intersection/triangle_triangle_inputs.hpp"

#include <locus/intersection/triangle_triangle.hpp>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace {

using namespace locus_bench_tritri;

void BM_locus(benchmark::State& state, int set) {
  const auto& p = pairs(set);
  std::size_t i = 0, meet = 0;
  for (auto _ : state) {
    const Pair& q = p[i % p.size()];
    meet += locus::intersects(q.first, q.second);
    ++i;
  }
  state.counters["meet_rate"] = double(meet) / double(i);
  state.SetItemsProcessed(static_cast<std::int64_t>(i));
  benchmark::DoNotOptimize(meet);
}

void BM_locus_general(benchmark::State& state, int set) {
  const auto& p = pairs(set);
  std::size_t i = 0, meet = 0;
  for (auto _ : state) {
    const Pair& q = p[i % p.size()];
    meet += locus::detail::tri3::intersects_general(q.first, q.second);
    ++i;
  }
  state.counters["meet_rate"] = double(meet) / double(i);
  state.SetItemsProcessed(static_cast<std::int64_t>(i));
  benchmark::DoNotOptimize(meet);
}

const int registered = [] {
  for (int set = 0; set < 3; ++set) {
    const std::string tail = std::string("/") + kSetNames[set];
    benchmark::RegisterBenchmark(("triangle_triangle/locus" + tail).c_str(), BM_locus, set);
    benchmark::RegisterBenchmark(("triangle_triangle/locus_general" + tail).c_str(),
                                 BM_locus_general, set);
  }
  return 0;
}();

}  // namespace
