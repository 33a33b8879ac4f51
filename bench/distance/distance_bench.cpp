// SPDX-License-Identifier: BSL-1.0
// Distance queries per second (rows dist3.pt-triangle, dist3.linear-linear, dist3.pt-obb):
// point-triangle, segment-segment (generic and nearly parallel) and point-OBB in 3D, float and
// double, over 4096 random inputs cycled so that the data stays in cache. Items per second =
// queries per second. (A CGAL comparison is to be added when CGAL is installed.)
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/segment_segment.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace {

constexpr std::size_t kCount = 4096;

template <class T>
locus::Vec3<T> rvec(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return {static_cast<T>(u(rng)), static_cast<T>(u(rng)), static_cast<T>(u(rng))};
}

template <class T>
void point_triangle(benchmark::State& state) {
  std::mt19937_64 rng(1);
  std::vector<locus::Vec3<T>> p;
  std::vector<locus::Triangle3<T>> t;
  for (std::size_t i = 0; i < kCount; ++i) {
    p.push_back(rvec<T>(rng, -2, 2));
    t.push_back({rvec<T>(rng, -1, 1), rvec<T>(rng, -1, 1), rvec<T>(rng, -1, 1)});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locus::distance(p[i], t[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <class T>
void segment_segment(benchmark::State& state) {
  const bool near_parallel = state.range(0) != 0;
  std::mt19937_64 rng(2);
  std::vector<locus::Segment3<T>> a, b;
  for (std::size_t i = 0; i < kCount; ++i) {
    const auto p0 = rvec<T>(rng, -1, 1), p1 = rvec<T>(rng, -1, 1);
    a.push_back({p0, p1});
    if (near_parallel) {
      const auto off = rvec<T>(rng, -1, 1);
      b.push_back({p0 + off, p1 + off + rvec<T>(rng, -1e-6, 1e-6)});
    } else {
      b.push_back({rvec<T>(rng, -1, 1), rvec<T>(rng, -1, 1)});
    }
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locus::distance(a[i], b[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <class T>
void point_obb(benchmark::State& state) {
  std::mt19937_64 rng(3);
  std::vector<locus::Vec3<T>> p;
  std::vector<locus::OrientedBox3<T>> box;
  for (std::size_t i = 0; i < kCount; ++i) {
    p.push_back(rvec<T>(rng, -3, 3));
    // A random rotation by Gram-Schmidt.
    auto x = locus::normalize(rvec<T>(rng, -1, 1));
    auto y = locus::normalize(locus::cross(x, rvec<T>(rng, -1, 1)));
    auto z = locus::cross(x, y);
    box.push_back({rvec<T>(rng, -1, 1), {x, y, z}, rvec<T>(rng, 0.1, 1)});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locus::distance(p[i], box[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

}  // namespace

BENCHMARK(point_triangle<float>);
BENCHMARK(point_triangle<double>);
BENCHMARK(segment_segment<float>)->Arg(0)->Arg(1);
BENCHMARK(segment_segment<double>)->Arg(0)->Arg(1);
BENCHMARK(point_obb<float>);
BENCHMARK(point_obb<double>);
