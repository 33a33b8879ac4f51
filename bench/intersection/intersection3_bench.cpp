// SPDX-License-Identifier: BSL-1.0
// Row int3.linear-triangle and int3.boxes: per-query cost of ray-triangle (locus watertight_hit
// and the closed-set intersects, against a textbook Moeller-Trumbore written here as a
// non-robust baseline) and of oriented box pairs (locus separating axes against FCL's
// OBB::overlap when FCL is found). Inputs: 1024 random triangles in [-1, 1]^3 and 1024 rays
// from [-2, 2]^3 aimed at random points of [-1, 1]^3 (about a fifth hit); 1024 random unit
// boxes (random rotations, extents in [0.1, 1], centres in [-1.5, 1.5]^3). Each iteration
// answers one query; the answers are summed so nothing is optimised away.

#include <benchmark/benchmark.h>

#include <locus/intersection/oriented_box_oriented_box.hpp>
#include <locus/intersection/ray_triangle.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#if defined(LOCUS_HAVE_FCL)
#include <fcl/math/bv/OBB.h>
#endif

namespace {

using namespace locus;

constexpr std::size_t n = 1024;

template <class T>
struct RayScene {
  std::vector<Triangle3<T>> tris;
  std::vector<Ray3<T>> rays;
};

template <class T>
const RayScene<T>& ray_scene() {
  static const RayScene<T> s = [] {
    std::mt19937_64 g(20261204);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto v = [&](double k) { return Vec3<T>{T(k * u(g)), T(k * u(g)), T(k * u(g))}; };
    RayScene<T> r;
    for (std::size_t i = 0; i < n; ++i) {
      r.tris.push_back({v(1), v(1), v(1)});
      const Vec3<T> o = v(2);
      r.rays.push_back({o, v(1) - o});
    }
    return r;
  }();
  return s;
}

// Moeller-Trumbore without an epsilon test on the determinant's sign beyond zero: the textbook
// baseline (not watertight, not exact).
template <class T>
bool moller_trumbore(const Ray3<T>& r, const Triangle3<T>& t) {
  const Vec3<T> e1 = t.v1 - t.v0, e2 = t.v2 - t.v0, p = cross(r.direction, e2);
  const T det = dot(e1, p);
  if (det == T(0)) return false;
  const T inv = T(1) / det;
  const Vec3<T> s = r.origin - t.v0;
  const T b1 = dot(s, p) * inv;
  if (b1 < T(0) || b1 > T(1)) return false;
  const Vec3<T> q = cross(s, e1);
  const T b2 = dot(r.direction, q) * inv;
  if (b2 < T(0) || b1 + b2 > T(1)) return false;
  return dot(e2, q) * inv >= T(0);
}

template <class T>
void BM_RayTriangle_watertight_hit(benchmark::State& state) {
  const auto& s = ray_scene<T>();
  std::size_t i = 0, hits = 0;
  for (auto _ : state) {
    const TriangleHit<T> h = watertight_hit(s.rays[i % n], s.tris[(i * 7) % n]);
    hits += h.hit;
    benchmark::DoNotOptimize(h);
    ++i;
  }
  state.counters["hit_rate"] = double(hits) / double(i);
}
template <class T>
void BM_RayTriangle_intersects(benchmark::State& state) {
  const auto& s = ray_scene<T>();
  std::size_t i = 0, hits = 0;
  for (auto _ : state) {
    hits += intersects(s.rays[i % n], s.tris[(i * 7) % n]);
    ++i;
  }
  state.counters["hit_rate"] = double(hits) / double(i);
  benchmark::DoNotOptimize(hits);
}
template <class T>
void BM_RayTriangle_textbook_moller_trumbore(benchmark::State& state) {
  const auto& s = ray_scene<T>();
  std::size_t i = 0, hits = 0;
  for (auto _ : state) {
    hits += moller_trumbore(s.rays[i % n], s.tris[(i * 7) % n]);
    ++i;
  }
  state.counters["hit_rate"] = double(hits) / double(i);
  benchmark::DoNotOptimize(hits);
}
BENCHMARK(BM_RayTriangle_watertight_hit<double>);
BENCHMARK(BM_RayTriangle_watertight_hit<float>);
BENCHMARK(BM_RayTriangle_intersects<double>);
BENCHMARK(BM_RayTriangle_textbook_moller_trumbore<double>);
BENCHMARK(BM_RayTriangle_textbook_moller_trumbore<float>);

const std::vector<OrientedBox3<double>>& boxes() {
  static const std::vector<OrientedBox3<double>> b = [] {
    std::mt19937_64 g(20261205);
    std::uniform_real_distribution<double> u(-1, 1), e(0.1, 1);
    std::normal_distribution<double> nd;
    std::vector<OrientedBox3<double>> out;
    for (std::size_t i = 0; i < n; ++i) {
      double q[4];
      double l = 0;
      for (double& x : q) x = nd(g), l += x * x;
      l = std::sqrt(l);
      const double w = q[0] / l, x = q[1] / l, y = q[2] / l, z = q[3] / l;
      out.push_back({{1.5 * u(g), 1.5 * u(g), 1.5 * u(g)},
                     {{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                      {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                      {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}},
                     {e(g), e(g), e(g)}});
    }
    return out;
  }();
  return b;
}

void BM_OrientedBoxes_locus(benchmark::State& state) {
  const auto& b = boxes();
  std::size_t i = 0, meet = 0;
  for (auto _ : state) {
    meet += intersects(b[i % n], b[(i * 7 + 1) % n]);
    ++i;
  }
  state.counters["meet_rate"] = double(meet) / double(i);
  benchmark::DoNotOptimize(meet);
}
BENCHMARK(BM_OrientedBoxes_locus);

#if defined(LOCUS_HAVE_FCL)
void BM_OrientedBoxes_fcl(benchmark::State& state) {
  const auto& b = boxes();
  std::vector<fcl::OBB<double>> f(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int c = 0; c < 3; ++c)
      f[k].axis.col(c) = fcl::Vector3d(b[k].axis[c].x, b[k].axis[c].y, b[k].axis[c].z);
    f[k].To = fcl::Vector3d(b[k].center.x, b[k].center.y, b[k].center.z);
    f[k].extent = fcl::Vector3d(b[k].extent.x, b[k].extent.y, b[k].extent.z);
  }
  // The answers agree with locus's on this input (checked once, outside the timing).
  std::size_t disagree = 0;
  for (std::size_t k = 0; k < n; ++k)
    disagree += f[k].overlap(f[(k * 7 + 1) % n]) != intersects(b[k], b[(k * 7 + 1) % n]);
  std::size_t i = 0, meet = 0;
  for (auto _ : state) {
    meet += f[i % n].overlap(f[(i * 7 + 1) % n]);
    ++i;
  }
  state.counters["meet_rate"] = double(meet) / double(i);
  state.counters["disagree"] = double(disagree);
  benchmark::DoNotOptimize(meet);
}
BENCHMARK(BM_OrientedBoxes_fcl);
#endif

}  // namespace
