// SPDX-License-Identifier: BSL-1.0
// 3D Delaunay tetrahedralization: locus vs CGAL Delaunay_triangulation_3 (Epick), row
// cg.delaunay3. Inputs: n uniform points in the unit cube (seeded), and the 50 x 50 x 50 integer
// grid (every cell cospherical: the hard case for exact predicates).
//
// Peak memory: the counter peak_MB is the largest heap growth during the timed calls (every
// malloc of the process, peers included, is counted by bench/support/heap_peak; the input and
// CGAL's converted copy of it are allocated before). The second method (the 4D lifted hull,
// Delaunay3/LiftedHull) runs on 10^4 points beside the incremental one.
//
// Build (from /work/main; CGAL is linked when found):
//   cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DLOCUS_BENCH_PEERS=ON
//   ninja -C build/bench locus_bench_delaunay
//   build/bench/bench/locus_bench_delaunay --benchmark_filter=Delaunay3

#include <benchmark/benchmark.h>

#include <locus/delaunay/delaunay3.hpp>

#include "support/heap_peak.hpp"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#if defined(LOCUS_HAVE_CGAL)
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

std::vector<locus::Vec3d> uniform_points3(std::size_t n) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<locus::Vec3d> p(n);
  for (auto& q : p) q = {u(rng), u(rng), u(rng)};
  return p;
}

std::vector<locus::Vec3d> grid_points3(int side) {
  std::vector<locus::Vec3d> p;
  p.reserve(std::size_t(side) * std::size_t(side) * std::size_t(side));
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      for (int k = 0; k < side; ++k) p.push_back({double(i), double(j), double(k)});
  return p;
}

const std::vector<locus::Vec3d>& input3(int which) {
  // Separate statics: a process running one case holds only that input.
  if (which == 0) {
    static const std::vector<locus::Vec3d> u5 = uniform_points3(100000);
    return u5;
  }
  if (which == 1) {
    static const std::vector<locus::Vec3d> u6 = uniform_points3(1000000);
    return u6;
  }
  if (which == 3) {
    static const std::vector<locus::Vec3d> u4 = uniform_points3(10000);
    return u4;
  }
  static const std::vector<locus::Vec3d> g = grid_points3(50);
  return g;
}

void set_counters3(benchmark::State& state, std::size_t n, const locus::bench::HeapPeak& peak) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(n));
  locus::bench::report_heap_peak(state, peak);
}

void locus_case3(benchmark::State& state, int which, locus::Delaunay3Method method) {
  const auto& p = input3(which);
  std::size_t cells = 0;
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    auto r = locus::delaunay(std::span<const locus::Vec3d>(p), locus::Delaunay3Options{method});
    benchmark::DoNotOptimize(r.tetrahedra.data());
    if (r.status != locus::Status::ok) state.SkipWithError("status not ok");
    cells = r.tetrahedra.size();
  }
  set_counters3(state, p.size(), peak);
  state.counters["cells"] = double(cells);
}

void locus_reuse_case3(benchmark::State& state, int which) {
  const auto& p = input3(which);
  locus::Delaunay3<double> d;
  locus::bench::HeapPeak peak;  // the first call allocates; later calls reuse the buffers
  for (auto _ : state) {
    const auto& r = d.compute(std::span<const locus::Vec3d>(p));
    benchmark::DoNotOptimize(r.tetrahedra.data());
  }
  set_counters3(state, p.size(), peak);
}

#if defined(LOCUS_HAVE_CGAL)
void cgal_case3(benchmark::State& state, int which) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using DT = CGAL::Delaunay_triangulation_3<K>;
  const auto& p = input3(which);
  std::vector<K::Point_3> pts;
  pts.reserve(p.size());
  for (const auto& q : p) pts.emplace_back(q.x, q.y, q.z);
  std::size_t cells = 0;
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    DT dt(pts.begin(), pts.end());  // spatially sorted range insertion
    cells = dt.number_of_finite_cells();
    benchmark::DoNotOptimize(cells);
  }
  set_counters3(state, p.size(), peak);
  state.counters["cells"] = double(cells);
}
#endif

void register_all3() {
  const char* names[] = {"Uniform/100000", "Uniform/1000000", "Grid/50x50x50", "Uniform/10000"};
  for (int w = 0; w < 4; ++w) {
    benchmark::RegisterBenchmark((std::string("Delaunay3/Locus/") + names[w]).c_str(), locus_case3,
                                 w, locus::Delaunay3Method::incremental)
        ->Unit(benchmark::kMillisecond);
    if (w == 3) {
      benchmark::RegisterBenchmark((std::string("Delaunay3/LiftedHull/") + names[w]).c_str(),
                                   locus_case3, w, locus::Delaunay3Method::lifted_hull)
          ->Unit(benchmark::kMillisecond);
      continue;
    }
    benchmark::RegisterBenchmark((std::string("Delaunay3/LocusReuse/") + names[w]).c_str(),
                                 locus_reuse_case3, w)
        ->Unit(benchmark::kMillisecond);
#if defined(LOCUS_HAVE_CGAL)
    benchmark::RegisterBenchmark((std::string("Delaunay3/CGAL/") + names[w]).c_str(), cgal_case3, w)
        ->Unit(benchmark::kMillisecond);
#endif
  }
}

const int registered3 = (register_all3(), 0);

}  // namespace
