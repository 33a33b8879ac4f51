// SPDX-License-Identifier: BSL-1.0
// Segment-triangle distance queries per second (row dist3.linear-triangle), float and double:
// random segments and triangles in a cube (a mix of crossing and separated pairs), separated
// pairs only (segments above the triangles' cube), and nearly parallel segments (parallel to
// their triangle's plane up to a 1e-6 tilt). 4096 inputs are cycled so that the data stays in
// cache; items per second = queries per second. Each kind runs distance() (the full result) and
// sqr_distance() (the squared distance only). Segment-rectangle alongside for scale.
#include "distance/distance_inputs.hpp"

#include <locus/distance/segment_rectangle.hpp>
#include <locus/distance/segment_triangle.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using namespace locus_bench_distance;

// kind 0: everything in [-1, 1]^3; 1: segments in [-1, 1]^2 x [2, 4] (never crossing);
// 2: segments parallel to the triangle's plane up to a 1e-6 tilt, 0.1 above it.
template <class T, class Query>
void segment_triangle(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0));
  std::mt19937_64 rng(7);
  std::vector<locus::Segment3<T>> s;
  std::vector<locus::Triangle3<T>> t;
  std::size_t crossing = 0;
  for (std::size_t i = 0; i < kCount; ++i) {
    const locus::Triangle3<T> tri{cast<T>(rvec(rng, -1, 1)), cast<T>(rvec(rng, -1, 1)),
                                  cast<T>(rvec(rng, -1, 1))};
    locus::Segment3<T> seg{cast<T>(rvec(rng, -1, 1)), cast<T>(rvec(rng, -1, 1))};
    if (kind == 1) {
      seg.p0.z += T(3);
      seg.p1.z += T(3);
    } else if (kind == 2) {
      const auto n = locus::normalize(locus::cross(tri.v1 - tri.v0, tri.v2 - tri.v0));
      const auto e0 = tri.v1 - tri.v0, e1 = tri.v2 - tri.v0;
      std::uniform_real_distribution<double> u(-1, 1);
      const auto p = tri.v0 + T(u(rng)) * e0 + T(u(rng)) * e1 + T(0.1) * n;
      seg = {p, p + T(u(rng)) * e0 + T(u(rng)) * e1 + T(1e-6) * n};
    }
    s.push_back(seg);
    t.push_back(tri);
    crossing += locus::distance(seg, tri).distance == T(0) ? 1u : 0u;
  }
  cycle(state, s, t, Query{});
  state.counters["crossing_fraction"] = double(crossing) / double(kCount);
}

template <class T>
void segment_rectangle(benchmark::State& state) {
  std::mt19937_64 rng(8);
  std::vector<locus::Segment3<T>> s;
  std::vector<locus::Rectangle3<T>> r;
  for (std::size_t i = 0; i < kCount; ++i) {
    const auto x = locus::normalize(cast<T>(rvec(rng, -1, 1)));
    const auto y = locus::normalize(locus::cross(x, cast<T>(rvec(rng, -1, 1))));
    const auto e = cast<T>(rvec(rng, 0.1, 1));
    r.push_back({cast<T>(rvec(rng, -1, 1)), {x, y}, {e.x, e.y}});
    s.push_back({cast<T>(rvec(rng, -1, 1)), cast<T>(rvec(rng, -1, 1))});
  }
  cycle(state, s, r, FullQuery{});
}

BENCHMARK(segment_triangle<float, FullQuery>)
    ->Name("segment_triangle_kinds/distance<float>")
    ->ArgName("kind")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2);
BENCHMARK(segment_triangle<double, FullQuery>)
    ->Name("segment_triangle_kinds/distance<double>")
    ->ArgName("kind")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2);
BENCHMARK(segment_triangle<float, SqrQuery>)
    ->Name("segment_triangle_kinds/sqr_distance<float>")
    ->ArgName("kind")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2);
BENCHMARK(segment_triangle<double, SqrQuery>)
    ->Name("segment_triangle_kinds/sqr_distance<double>")
    ->ArgName("kind")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2);
BENCHMARK(segment_rectangle<float>);
BENCHMARK(segment_rectangle<double>);

}  // namespace
