// SPDX-License-Identifier: BSL-1.0
// 2D Delaunay triangulation: locus vs CGAL Delaunay_triangulation_2 (Epick) and Qhull
// (row cg.delaunay2). Inputs: n uniform points in the unit square (seeded), and the 1000 x 1000
// integer grid (every cell cocircular: the hard case for exact predicates).
//
// Peak memory: maxrss is process-wide and only grows, so measure it with one case per process:
//   locus_bench_delaunay --benchmark_filter='Locus/Uniform/1000000$' and /usr/bin/time -v
// (the counter "rss_MB" below is the process maxrss after the case, exact when run alone).
//
// Before bench/CMakeLists.txt links the peers, build by hand (from /work/main):
//   cmake -S . -B build-delaunay-rel -G Ninja -DCMAKE_BUILD_TYPE=Release
//         -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" -DLOCUS_BUILD_TESTS=OFF -DLOCUS_BUILD_BENCH=OFF
//   ninja -C build-delaunay-rel locus
//   g++ -O2 -std=c++20 -DNDEBUG -DLOCUS_HAVE_CGAL=1 -DLOCUS_HAVE_QHULL=1 -Iinclude
//       bench/delaunay/delaunay2_bench.cpp build-delaunay-rel/liblocus.a -lbenchmark
//       -lbenchmark_main -lqhull_r -lgmp -lmpfr -lpthread -o /tmp/delaunay2_bench
// CGAL needs gmp and mpfr at link time; Qhull is libqhull_r (reentrant), options "d Qt Qbb Qz".

#include <benchmark/benchmark.h>

#include <locus/delaunay/delaunay2.hpp>

#include <sys/resource.h>

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

void set_counters(benchmark::State& state, std::size_t n) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(n));
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  state.counters["rss_MB"] = double(ru.ru_maxrss) / 1024.0;
}

// The input alone: its maxrss is the baseline to subtract from the other cases' rss_MB.
void input_case(benchmark::State& state, int which) {
  const auto& p = input(which);
  for (auto _ : state) benchmark::DoNotOptimize(p.data());
  set_counters(state, p.size());
}

void locus_case(benchmark::State& state, int which) {
  const auto& p = input(which);
  for (auto _ : state) {
    auto r = locus::delaunay(std::span<const locus::Vec2d>(p));
    benchmark::DoNotOptimize(r.triangles.data());
    if (r.status != locus::Status::ok) state.SkipWithError("status not ok");
  }
  set_counters(state, p.size());
}

void locus_reuse_case(benchmark::State& state, int which) {
  const auto& p = input(which);
  locus::Delaunay2<double> d;
  for (auto _ : state) {
    const auto& r = d.triangulate(std::span<const locus::Vec2d>(p));
    benchmark::DoNotOptimize(r.triangles.data());
  }
  set_counters(state, p.size());
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
  for (auto _ : state) {
    DT dt;
    dt.insert(pts.begin(), pts.end());  // spatially sorted range insertion
    benchmark::DoNotOptimize(dt.number_of_faces());
    if (dt.number_of_faces() != ours) state.SkipWithError("CGAL and locus triangle counts differ");
  }
  set_counters(state, p.size());
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
  set_counters(state, p.size());
}
#endif

void register_all() {
  const char* names[] = {"Uniform/100000", "Uniform/1000000", "Grid/1000x1000"};
  for (int w = 0; w < 3; ++w) {
    benchmark::RegisterBenchmark((std::string("Delaunay2/Input/") + names[w]).c_str(), input_case,
                                 w)
        ->Unit(benchmark::kMillisecond);
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
