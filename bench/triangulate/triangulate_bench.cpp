// SPDX-License-Identifier: BSL-1.0
// Polygon triangulation (row cg.triangulate): locus ear clipping, locus monotone decomposition
// + monotone triangulation, locus constrained Delaunay (triangulate_polygon) and, when found,
// CGAL's Constrained_Delaunay_triangulation_2 (Epick) of the polygon's edges, in one run.
// Inputs: star-shaped polygons with 10^4 and 10^5 vertices (random radii in [0.2, 1]: about
// half the vertices reflex), and the largest earcut fixtures (tests/data/corpus/earcut:
// water-huge3, 12864 vertices in 1444 rings; water2), which are read at start-up.
//
// Build (CGAL is linked when found):
//   cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DLOCUS_BENCH_PEERS=ON
//   ninja -C build/bench locus_bench_triangulate
//   build/bench/bench/locus_bench_triangulate
// Results: bench/results/triangulate.md.

#include <locus/delaunay/constrained_delaunay2.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>

#include <benchmark/benchmark.h>

#include "support/heap_peak.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#if defined(LOCUS_HAVE_CGAL)
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

#ifndef LOCUS_BENCH_SOURCE_DIR
#define LOCUS_BENCH_SOURCE_DIR ""
#endif

namespace {

struct Poly {
  std::vector<locus::Vec2d> points;
  std::vector<std::uint32_t> ends;
};

Poly star(std::size_t n) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Poly p;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (double(i) + 0.9 * u(rng)) / double(n);
    const double r = 0.2 + 0.8 * u(rng);
    p.points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  p.ends.push_back(std::uint32_t(n));
  return p;
}

// The fixture's rings: the numbers of the nested JSON arrays, a ring closing at depth 2.
Poly fixture(const std::string& name) {
  std::ifstream in(std::string(LOCUS_BENCH_SOURCE_DIR) + "/tests/data/corpus/earcut/fixtures/" +
                   name + ".json");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  Poly p;
  std::vector<double> coords;
  int depth = 0;
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (c == '[') {
      ++depth;
      ++i;
    } else if (c == ']') {
      if (depth == 2) p.ends.push_back(std::uint32_t(p.points.size()));
      if (depth == 3 && coords.size() >= 2) p.points.push_back({coords[0], coords[1]});
      if (depth == 3) coords.clear();
      --depth;
      ++i;
    } else if (c == '-' || c == '.' || (c >= '0' && c <= '9')) {
      std::size_t used = 0;
      coords.push_back(std::stod(s.substr(i, 40), &used));
      i += used;
    } else {
      ++i;
    }
  }
  return p;
}

const Poly& input(int which) {
  if (which == 0) {
    static const Poly p = star(10000);
    return p;
  }
  if (which == 1) {
    static const Poly p = star(100000);
    return p;
  }
  if (which == 2) {
    static const Poly p = fixture("water-huge3");
    return p;
  }
  static const Poly p = fixture("water2");
  return p;
}

const char* input_name(int which) {
  static const char* names[] = {"star_1e4", "star_1e5", "water-huge3", "water2"};
  return names[which];
}

void report(benchmark::State& state, int which, std::size_t triangles,
            const locus::bench::HeapPeak& peak) {
  state.SetLabel(input_name(which));
  state.counters["vertices"] = double(input(which).points.size());
  state.counters["triangles"] = double(triangles);
  locus::bench::report_heap_peak(state, peak);
}

void BM_EarClipping(benchmark::State& state) {
  const int which = int(state.range(0));
  const Poly& p = input(which);
  locus::EarClipping2<double> ec;
  std::size_t n = 0;
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    const auto& r = ec.compute(p.points, p.ends);
    n = r.triangles.size();
    benchmark::DoNotOptimize(r.triangles.data());
  }
  report(state, which, n, peak);
}

void BM_Monotone(benchmark::State& state) {
  const int which = int(state.range(0));
  const Poly& p = input(which);
  std::size_t n = 0;
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    const auto r = locus::triangulate_monotone(p.points, p.ends);
    n = r.triangles.size();
    benchmark::DoNotOptimize(r.triangles.data());
  }
  report(state, which, n, peak);
}

void BM_ConstrainedDelaunay(benchmark::State& state) {
  const int which = int(state.range(0));
  const Poly& p = input(which);
  std::size_t n = 0;
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    const auto r = locus::triangulate_polygon(p.points, p.ends);
    n = r.triangles.size();  // all triangles of the hull; inside[] marks the polygon's
    benchmark::DoNotOptimize(r.triangles.data());
  }
  report(state, which, n, peak);
}

#if defined(LOCUS_HAVE_CGAL)
void BM_CgalConstrainedDelaunay(benchmark::State& state) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K>;
  const int which = int(state.range(0));
  const Poly& p = input(which);
  std::vector<std::vector<K::Point_2>> rings;
  std::uint32_t b = 0;
  for (const std::uint32_t e : p.ends) {
    rings.emplace_back();
    for (std::uint32_t i = b; i < e; ++i) rings.back().emplace_back(p.points[i].x, p.points[i].y);
    b = e;
  }
  std::size_t n = 0;
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    CDT cdt;
    for (const auto& r : rings) cdt.insert_constraint(r.begin(), r.end(), true);
    n = cdt.number_of_faces();
    benchmark::DoNotOptimize(n);
  }
  report(state, which, n, peak);
}
BENCHMARK(BM_CgalConstrainedDelaunay)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
#endif

BENCHMARK(BM_EarClipping)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Monotone)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConstrainedDelaunay)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

}  // namespace
