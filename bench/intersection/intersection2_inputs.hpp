// SPDX-License-Identifier: BSL-1.0
#pragma once
// The inputs of intersection2_bench.cpp (locus) and intersection2_peers_bench.cpp (CGAL Epick,
// Boost.Geometry): the same seeded double inputs, generated once in each translation unit. The
// two files are separate translation units so that locus is compiled with the flags a locus user
// has, not with the -frounding-math that CGAL's CMake target adds to each source.
//   generic:       4096 segment pairs in [-2, 2]^2 at any angle; half cross, the others miss in
//                  three ways (the crossing of the lines lies beyond an end of either segment, or
//                  the second segment lies on one side of the first).
//   near_parallel: 4096 pairs whose crossing angle is 2^-k radians, k uniform in [20, 60], built
//                  like the generic ones: below about 2^-50 the rounded end points decide alone
//                  and the exact fallbacks of the predicates run.
//   polygons:      1024 pairs of convex polygons with 8 to 32 vertices (random angles on circles
//                  of radius 0.5 to 1), centres at a distance that makes about half the pairs meet.

#include <locus/core/vec.hpp>
#include <locus/primitives/segment.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace locus_bench_int2 {

using V = locus::Vec2<double>;
using Seg = locus::Segment2<double>;

constexpr std::size_t kSegmentPairs = 4096;
constexpr std::size_t kPolygonPairs = 1024;

struct SegmentPairs {
  std::vector<Seg> a, b;
};

/// Pairs crossing at angles 2^-k, k uniform in [kmin, kmax] (any angle when kmax < 0).
inline SegmentPairs make_segment_pairs(std::uint64_t seed, double kmin, double kmax) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u01(0, 1);
  const auto u = [&](double lo, double hi) { return lo + (hi - lo) * u01(g); };
  SegmentPairs s;
  for (std::size_t i = 0; i < kSegmentPairs; ++i) {
    const double phi = u(0, 2 * std::numbers::pi), len = u(0.5, 2);
    const V a0{u(-1, 1), u(-1, 1)}, d{std::cos(phi), std::sin(phi)};
    const V a1 = a0 + len * d;
    const double angle =
        kmax < 0 ? u(0.05, std::numbers::pi - 0.05) : std::ldexp(1.0, -int(u(kmin, kmax + 1)));
    const double psi = phi + (u01(g) < 0.5 ? angle : -angle);
    const V e{std::cos(psi), std::sin(psi)};
    // Where b crosses a's line (parameter t on a) and how far b reaches back (r) and forward (f).
    const int kind = int(u01(g) * 4);
    double t = u(0.05, 0.95), r = u(0.1, 1), f = u(0.1, 1);
    if (kind == 2) t = u01(g) < 0.5 ? u(-1, -0.05) : u(1.05, 2);  // beyond an end of a
    if (kind == 3) r = -u(0.05, 0.5);                             // b on one side of a
    const V x = a0 + t * (a1 - a0);
    s.a.push_back({a0, a1});
    s.b.push_back({x - r * len * e, x + f * len * e});
  }
  return s;
}

inline const SegmentPairs& generic_pairs() {
  static const SegmentPairs s = make_segment_pairs(20261204, 0, -1);
  return s;
}
inline const SegmentPairs& near_parallel_pairs() {
  static const SegmentPairs s = make_segment_pairs(20261205, 20, 60);
  return s;
}

/// Convex polygons, counter-clockwise, open (the last vertex is not repeated).
struct PolygonPairs {
  std::vector<std::vector<V>> a, b;
};

inline std::vector<V> make_convex(std::mt19937_64& g, const V& c, double radius) {
  std::uniform_real_distribution<double> u01(0, 1);
  const int n = 8 + int(u01(g) * 25);
  std::vector<double> angle(static_cast<std::size_t>(n));
  for (double& t : angle) t = 2 * std::numbers::pi * u01(g);
  std::sort(angle.begin(), angle.end());
  std::vector<V> p;
  for (double t : angle) p.push_back(c + radius * V{std::cos(t), std::sin(t)});
  return p;
}

inline const PolygonPairs& polygon_pairs() {
  static const PolygonPairs s = [] {
    std::mt19937_64 g(20261206);
    std::uniform_real_distribution<double> u01(0, 1);
    PolygonPairs p;
    for (std::size_t i = 0; i < kPolygonPairs; ++i) {
      const double ra = 0.5 + 0.5 * u01(g), rb = 0.5 + 0.5 * u01(g);
      const double dist = (0.3 + 1.2 * u01(g)) * (ra + rb), phi = 2 * std::numbers::pi * u01(g);
      const V ca{u01(g), u01(g)};
      p.a.push_back(make_convex(g, ca, ra));
      p.b.push_back(make_convex(g, ca + dist * V{std::cos(phi), std::sin(phi)}, rb));
    }
    return p;
  }();
  return s;
}

/// Runs query(i) for i cycling over n inputs (n a power of two); items per second = queries
/// per second. query returns a double (0 when the pair misses) that is accumulated, so no
/// query can be dropped; the hit rate is reported as a counter.
template <class Query>
void cycle(benchmark::State& state, std::size_t n, Query query) {
  std::size_t i = 0, hits = 0;
  double acc = 0;
  for (auto _ : state) {
    const double v = query(i);
    hits += v != 0;
    acc += v;
    benchmark::DoNotOptimize(acc);
    i = (i + 1) & (n - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["hit_rate"] = double(hits) / double(std::max<std::int64_t>(state.iterations(), 1));
}

}  // namespace locus_bench_int2
