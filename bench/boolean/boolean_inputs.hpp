// SPDX-License-Identifier: BSL-1.0
#pragma once
// The seeded inputs of boolean_bench.cpp (issue 21 item 7), in locus's ring layout (counter-
// clockwise rings, no repeated closing vertex); each peer converts them to its own layout
// outside the timed loop.
//   few:   two wobbly circles of 10^5 vertices each (radius 1 + 0.05 sin(7 t + phase) + a random
//          1e-4 jitter), the second shifted by (0.4, 0.1): a few dozen crossings.
//   spiky: two star polygons of 10^5 vertices each (5 * 10^4 spikes, tips at random radii in
//          [0.9, 1], valleys in [0.8, 0.9]), the second rotated by a third of a spike: the spikes
//          cross their neighbours, about 10^5 crossings. (Deeper spikes, valleys in [0.05, 0.4],
//          give about 10^9 pairs of overlapping edge boxes: GEOS ran for minutes, as did locus.)
//   many:  10^4 random squares and hexagons (radius 0.5 to 1.5, random rotation, centres
//          uniform in [0, 100]^2: each point is covered about 2.3 times on average), united.

#include <locus/core/vec.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace locus_bench_bool {

using V = locus::Vec2<double>;
using Ring = std::vector<V>;

constexpr std::size_t kBigVertices = 100000;
constexpr std::size_t kSmallPolygons = 10000;

inline Ring wobbly_circle(std::size_t n, std::uint64_t seed, V centre, double phase) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> jitter(-1e-4, 1e-4);
  Ring r;
  r.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * double(i) / double(n);
    const double rad = 1 + 0.05 * std::sin(7 * t + phase) + jitter(g);
    r.push_back({centre.x + rad * std::cos(t), centre.y + rad * std::sin(t)});
  }
  return r;
}

inline Ring spiky_star(std::size_t n, std::uint64_t seed, double rotation) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> tip(0.9, 1.0), valley(0.8, 0.9);
  Ring r;
  r.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = rotation + 2 * std::numbers::pi * double(i) / double(n);
    const double rad = (i % 2 == 0) ? tip(g) : valley(g);
    r.push_back({rad * std::cos(t), rad * std::sin(t)});
  }
  return r;
}

inline std::vector<Ring> small_polygons(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u01(0, 1);
  std::vector<Ring> out;
  out.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const V c{100 * u01(g), 100 * u01(g)};
    const double rad = 0.5 + u01(g), rot = 2 * std::numbers::pi * u01(g);
    const int sides = u01(g) < 0.5 ? 4 : 6;
    Ring r;
    for (int i = 0; i < sides; ++i) {
      const double t = rot + 2 * std::numbers::pi * i / sides;
      r.push_back({c.x + rad * std::cos(t), c.y + rad * std::sin(t)});
    }
    out.push_back(r);
  }
  return out;
}

/// The operands of the two-polygon inputs.
struct Pair {
  Ring a, b;
};
inline Pair few_crossings() {
  const std::size_t n = kBigVertices;
  return {wobbly_circle(n, 21, {0, 0}, 0.0), wobbly_circle(n, 22, {0.4, 0.1}, 1.0)};
}
inline Pair many_crossings() {
  const std::size_t n = kBigVertices;
  return {spiky_star(n, 23, 0.0), spiky_star(n, 24, 2 * std::numbers::pi / double(n / 2) / 3)};
}

}  // namespace locus_bench_bool
