// SPDX-License-Identifier: BSL-1.0
// Rows int2.linear and int2.sat-static against their peers (issue 19, item 10): segment-segment
// find (with the point) and the convex polygon test, on the inputs of intersection2_inputs.hpp.
// The peers (CGAL Epick's intersection, Boost.Geometry's intersection and intersects) are in
// intersection2_peers_bench.cpp, a separate translation unit: CGAL's CMake target adds
// -frounding-math to every source that links it, and bench/CMakeLists.txt takes it back
// (-fno-rounding-math) for this file, which holds only locus code.
// Names: <input>/locus<double>, beside <input>/cgal<Epick> and <input>/boost in the same run
// (scripts/bench_rounds --peer-double 'cgal<Epick>' or 'boost' forms the ratios).

#include "intersection/intersection2_inputs.hpp"

#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/segment_segment.hpp>
#include <locus/intersection/segment_segment_batch.hpp>

#include <benchmark/benchmark.h>

namespace {

using namespace locus_bench_int2;

/// 0 when the segments miss, else a value depending on the constructed point.
double locus_find(const Seg& a, const Seg& b) noexcept {
  const auto r = locus::intersection(a, b);
  if (r.kind == locus::Kind::empty) return 0.0;
  return 16.0 + r.point[0].x + r.point[0].y;
}

void segments(benchmark::State& state, const SegmentPairs& s) {
  cycle(state, kSegmentPairs, [&](std::size_t i) { return locus_find(s.a[i], s.b[i]); });
}

/// The batched form (segment_segment_batch.hpp): all the pairs per iteration, the same
/// accumulation of each answer; items per second = pairs per second.
void segments_batch(benchmark::State& state, const SegmentPairs& s) {
  std::vector<locus::LinearIntersection2<double>> out(s.a.size());
  std::size_t hits = 0;
  double acc = 0;
  for (auto _ : state) {
    locus::intersections(s.a, s.b, out);
    for (const auto& r : out) {
      if (r.kind == locus::Kind::empty) continue;
      ++hits;
      acc += 16.0 + r.point[0].x + r.point[0].y;
    }
    benchmark::DoNotOptimize(acc);
  }
  const auto pairs = static_cast<std::int64_t>(state.iterations() * s.a.size());
  state.SetItemsProcessed(pairs);
  state.counters["hit_rate"] = double(hits) / double(std::max<std::int64_t>(pairs, 1));
}

void BM_generic_locus(benchmark::State& state) { segments(state, generic_pairs()); }
void BM_generic_batch(benchmark::State& state) { segments_batch(state, generic_pairs()); }
void BM_near_parallel_batch(benchmark::State& state) {
  segments_batch(state, near_parallel_pairs());
}
void BM_near_parallel_locus(benchmark::State& state) { segments(state, near_parallel_pairs()); }
void BM_polygons_locus(benchmark::State& state) {
  const PolygonPairs& p = polygon_pairs();
  cycle(state, kPolygonPairs, [&](std::size_t i) {
    return locus::intersects_convex_polygons(p.a[i], p.b[i]) ? 1.0 : 0.0;
  });
}

}  // namespace

BENCHMARK(BM_generic_locus)->Name("segments_generic/locus<double>");
BENCHMARK(BM_near_parallel_locus)->Name("segments_near_parallel/locus<double>");
BENCHMARK(BM_generic_batch)->Name("segments_generic/locus_batch<double>");
BENCHMARK(BM_near_parallel_batch)->Name("segments_near_parallel/locus_batch<double>");
BENCHMARK(BM_polygons_locus)->Name("convex_polygons/locus<double>");
