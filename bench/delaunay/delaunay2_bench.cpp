// SPDX-License-Identifier: BSL-1.0
// 2D Delaunay triangulation: locus vs CGAL Delaunay_triangulation_2 (Epick) and Qhull
// (row cg.delaunay2). Inputs: n uniform points in the unit square (seeded), and the 1000 x 1000
// integer grid (every cell cocircular: the hard case for exact predicates).
//
// Peak memory: the counter peak_MB is the largest heap growth during one call (every malloc of
// the process, peers included, is counted by bench/support/heap_peak; the input and CGAL's
// converted copy of it are allocated before).
//
// Build (from /work/main; CGAL and Qhull are linked when found):
//   cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DLOCUS_BENCH_PEERS=ON
//   ninja -C build/bench locus_bench_delaunay
//   build/bench/bench/locus_bench_delaunay --benchmark_filter=Delaunay2
// Qhull is libqhull_r (reentrant), options "d Qt Qbb Qz".

#include <locus/delaunay/delaunay2.hpp>

#include <benchmark/benchmark.h>

#include "support/heap_peak.hpp"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#if defined(LOCUS_HAVE_CGAL)
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif
#if defined(LOCUS_HAVE_QHULL)
extern "C" {
#include <libqhull_r/qhull_ra.h>
}
#endif

namespace {

std::vector<locus::Vec2d> uniform_points(std::size_t n) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<locus::Vec2d> p(n);
  for (auto& q : p) q = {u(rng), u(rng)};
  return p;
}

std::vector<locus::Vec2d> grid_points(int side) {
  std::vector<locus::Vec2d> p;
  p.reserve(std::size_t(side) * std::size_t(side));
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) p.push_back({double(i), double(j)});
  return p;
}

const std::vector<locus::Vec2d>& input(int which) {
  // Separate statics: a process running one case holds only that input (for maxrss).
  if (which == 0) {
    static const std::vector<locus::Vec2d> u5 = uniform_points(100000);
    return u5;
  }
  if (which == 1) {
    static const std::vector<locus::Vec2d> u6 = uniform_points(1000000);
    return u6;
  }
  static const std::vector<locus::Vec2d> g = grid_points(1000);
  return g;
}

void set_counters(benchmark::State& state, std::size_t n, const locus::bench::HeapPeak& peak) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(n));
  locus::bench::report_heap_peak(state, peak);
}

void locus_case(benchmark::State& state, int which) {
  const auto& p = input(which);
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    auto r = locus::delaunay(std::span<const locus::Vec2d>(p));
    benchmark::DoNotOptimize(r.triangles.data());
    if (r.status != locus::Status::ok) state.SkipWithError("status not ok");
  }
  set_counters(state, p.size(), peak);
}

void locus_reuse_case(benchmark::State& state, int which) {
  const auto& p = input(which);
  locus::Delaunay2<double> d;
  locus::bench::HeapPeak peak;  // the first call allocates; later calls reuse the buffers
  for (auto _ : state) {
    const auto& r = d.compute(std::span<const locus::Vec2d>(p));
    benchmark::DoNotOptimize(r.triangles.data());
  }
  set_counters(state, p.size(), peak);
}

#if defined(LOCUS_HAVE_CGAL)
void cgal_case(benchmark::State& state, int which) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using DT = CGAL::Delaunay_triangulation_2<K>;
  const auto& p = input(which);
  std::vector<K::Point_2> pts;
  pts.reserve(p.size());
  for (const auto& q : p) pts.emplace_back(q.x, q.y);
  // Sanity: CGAL and locus agree on the number of triangles (unique for uniform input; equal
  // for the grid by Euler's formula).
  const std::size_t ours = locus::delaunay(std::span<const locus::Vec2d>(p)).triangle_count();
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    DT dt;
    dt.insert(pts.begin(), pts.end());  // spatially sorted range insertion
    benchmark::DoNotOptimize(dt.number_of_faces());
    if (dt.number_of_faces() != ours) state.SkipWithError("CGAL and locus triangle counts differ");
  }
  set_counters(state, p.size(), peak);
}
#endif

#if defined(LOCUS_HAVE_QHULL)
void qhull_case(benchmark::State& state, int which) {
  const auto& p = input(which);
  std::vector<coordT> xy(2 * p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    xy[2 * i] = p[i].x;
    xy[2 * i + 1] = p[i].y;
  }
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    qhT qh_qh;
    qhT* qh = &qh_qh;
    QHULL_LIB_CHECK
    qh_zero(qh, stderr);
    char flags[] = "qhull d Qt Qbb Qz";
    const int err =
        qh_new_qhull(qh, 2, static_cast<int>(p.size()), xy.data(), False, flags, nullptr, stderr);
    if (err) state.SkipWithError("qhull failed");
    benchmark::DoNotOptimize(qh->num_facets);
    qh_freeqhull(qh, !qh_ALL);
    int curlong, totlong;
    qh_memfreeshort(qh, &curlong, &totlong);
  }
  set_counters(state, p.size(), peak);
}
#endif

void register_all() {
  const char* names[] = {"Uniform/100000", "Uniform/1000000", "Grid/1000x1000"};
  for (int w = 0; w < 3; ++w) {
    benchmark::RegisterBenchmark((std::string("Delaunay2/Locus/") + names[w]).c_str(), locus_case,
                                 w)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("Delaunay2/LocusReuse/") + names[w]).c_str(),
                                 locus_reuse_case, w)
        ->Unit(benchmark::kMillisecond);
#if defined(LOCUS_HAVE_CGAL)
    benchmark::RegisterBenchmark((std::string("Delaunay2/CGAL/") + names[w]).c_str(), cgal_case, w)
        ->Unit(benchmark::kMillisecond);
#endif
#if defined(LOCUS_HAVE_QHULL)
    benchmark::RegisterBenchmark((std::string("Delaunay2/Qhull/") + names[w]).c_str(), qhull_case,
                                 w)
        ->Unit(benchmark::kMillisecond);
#endif
  }
}

const int registered = (register_all(), 0);

}  // namespace
