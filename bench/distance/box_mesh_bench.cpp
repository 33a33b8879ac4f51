// SPDX-License-Identifier: BSL-1.0
// Queries per second for the box, frustum, convex-polygon and mesh distance queries (rows
// dist3.linear-obb, dist3.pt-frustum, dist2.pt-convex, dist3.pt-polyhedron): segment-OBB and
// line-AABB over 4096 random inputs cycled (in cache); point-frustum; point to a convex polygon
// of 10^5 vertices (O(log n) search vs the O(n) brute-force minimum over the edges); point to a
// closed torus mesh of 102400 triangles with the AABB tree (build time separately; query points
// uniform in the mesh's box, many of them in the hole where the whole inner ring is nearly
// equidistant, and points near the surface) vs the one-call brute force distance_to_mesh, and the
// tree's exact inside test. Items per second =
// queries per second.
//
// Run: locus_bench_distance --benchmark_filter='BoxMesh' --benchmark_min_time=0.2
#include <locus/distance/line_aligned_box.hpp>
#include <locus/distance/point_convex_polygon.hpp>
#include <locus/distance/point_frustum.hpp>
#include <locus/distance/point_mesh.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/distance/segment_oriented_box.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using namespace locus;
constexpr std::size_t kCount = 4096;

template <class T>
std::vector<Vec3<T>> random_points(std::size_t n, T lo, T hi, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u{double(lo), double(hi)};
  std::vector<Vec3<T>> v(n);
  for (auto& p : v) p = Vec3<T>{T(u(g)), T(u(g)), T(u(g))};
  return v;
}

template <class T>
void BoxMesh_SegmentOBB(benchmark::State& state) {
  const auto a = random_points<T>(kCount, T(-10), T(10), 1);
  const auto b = random_points<T>(kCount, T(-10), T(10), 2);
  std::mt19937_64 g(3);
  std::normal_distribution<double> nd;
  std::vector<OrientedBox3<T>> boxes(kCount);
  for (auto& box : boxes) {
    Vec3<double> x{nd(g), nd(g), nd(g)}, y{nd(g), nd(g), nd(g)};
    x = normalize(x);
    y = normalize(y - dot(x, y) * x);
    box.center = vec_cast<T>(Vec3<double>{nd(g), nd(g), nd(g)});
    box.axis[0] = vec_cast<T>(x);
    box.axis[1] = vec_cast<T>(y);
    box.axis[2] = vec_cast<T>(cross(x, y));
    box.extent = Vec3<T>{T(1), T(2), T(0.5)};
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(distance(Segment3<T>{a[i], b[i]}, boxes[i]));
    i = (i + 1) % kCount;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BoxMesh_LineAABB(benchmark::State& state) {
  const auto a = random_points<T>(kCount, T(-10), T(10), 4);
  const auto d = random_points<T>(kCount, T(-1), T(1), 5);
  const AlignedBox3<T> box{{T(-1), T(-2), T(-0.5)}, {T(1), T(2), T(0.5)}};
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(distance(Line3<T>{a[i], d[i]}, box));
    i = (i + 1) % kCount;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BoxMesh_PointFrustum(benchmark::State& state) {
  const auto p = random_points<T>(kCount, T(-6), T(6), 6);
  const Frustum3<T> f{{T(0), T(0), T(-2)},
                      {T(0), T(0), T(1)},
                      {T(0), T(1), T(0)},
                      {T(1), T(0), T(0)},
                      T(1),
                      T(5),
                      T(0.75),
                      T(1)};
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(distance(p[i], f));
    i = (i + 1) % kCount;
  }
  state.SetItemsProcessed(state.iterations());
}

std::vector<Vec2<double>> big_convex_polygon(std::size_t n) {
  std::vector<Vec2<double>> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * double(i) / double(n);
    v[i] = {5.0 * std::cos(a), 3.0 * std::sin(a)};
  }
  return v;
}

void BoxMesh_PointConvexPolygon_LogN(benchmark::State& state) {
  const auto v = big_convex_polygon(100000);
  const auto p3 = random_points<double>(kCount, -8.0, 8.0, 7);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(distance_to_convex_polygon(Vec2<double>{p3[i].x, p3[i].y},
                                                        std::span<const Vec2<double>>(v)));
    i = (i + 1) % kCount;
  }
  state.SetItemsProcessed(state.iterations());
}

void BoxMesh_PointConvexPolygon_BruteEdges(benchmark::State& state) {
  const auto v = big_convex_polygon(100000);
  const auto p3 = random_points<double>(kCount, -8.0, 8.0, 7);
  std::size_t i = 0;
  for (auto _ : state) {
    const Vec2<double> p{p3[i].x, p3[i].y};
    double best = 1e300;
    for (std::size_t k = 0; k < v.size(); ++k)
      best =
          std::min(best, distance(p, Segment2<double>{v[k], v[(k + 1) % v.size()]}).sqr_distance);
    benchmark::DoNotOptimize(best);
    i = (i + 1) % kCount;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
struct TorusMesh {
  std::vector<Vec3<T>> v;
  std::vector<std::array<std::uint32_t, 3>> t;
};

template <class T>
const TorusMesh<T>& torus_mesh() {
  static const TorusMesh<T> m = [] {
    TorusMesh<T> r;
    const int nu = 320, nv = 160;  // 2 * 320 * 160 = 102400 triangles
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        const double a = 6.283185307179586 * i / nu, b = 6.283185307179586 * j / nv;
        const double rr = 5.0 + 1.5 * std::cos(b);
        r.v.push_back(Vec3<T>{T(rr * std::cos(a)), T(rr * std::sin(a)), T(1.5 * std::sin(b))});
      }
    auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % nu) * nv + j % nv); };
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        r.t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        r.t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    return r;
  }();
  return m;
}

template <class T>
void BoxMesh_MeshTreeBuild(benchmark::State& state) {
  const auto& m = torus_mesh<T>();
  for (auto _ : state) {
    MeshDistanceTree<T> tree(std::span<const Vec3<T>>(m.v),
                             std::span<const std::array<std::uint32_t, 3>>(m.t));
    benchmark::DoNotOptimize(tree.triangle_count());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(m.t.size()));
}

template <class T>
void BoxMesh_PointMeshTree(benchmark::State& state) {
  const auto& m = torus_mesh<T>();
  const MeshDistanceTree<T> tree(std::span<const Vec3<T>>(m.v),
                                 std::span<const std::array<std::uint32_t, 3>>(m.t));
  const auto p = random_points<T>(kCount, T(-8), T(8), 8);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(distance(p[i], tree));
    i = (i + 1) % kCount;
  }
  state.SetItemsProcessed(state.iterations());
}

// Query points within 0.3 of the surface (vertices jittered): the common case of collision and
// projection queries, where the branch and bound opens O(log F) nodes.
template <class T>
void BoxMesh_PointMeshTreeNearSurface(benchmark::State& state) {
  const auto& m = torus_mesh<T>();
  const MeshDistanceTree<T> tree(std::span<const Vec3<T>>(m.v),
                                 std::span<const std::array<std::uint32_t, 3>>(m.t));
  auto p = random_points<T>(kCount, T(-0.3), T(0.3), 10);
  for (std::size_t k = 0; k < kCount; ++k) p[k] += m.v[(k * 7919) % m.v.size()];
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(distance(p[i], tree));
    i = (i + 1) % kCount;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BoxMesh_PointMeshBrute(benchmark::State& state) {
  const auto& m = torus_mesh<T>();
  const auto p = random_points<T>(kCount, T(-8), T(8), 8);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(distance_to_mesh(p[i], std::span<const Vec3<T>>(m.v),
                                              std::span<const std::array<std::uint32_t, 3>>(m.t)));
    i = (i + 1) % kCount;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BoxMesh_MeshTreeClassify(benchmark::State& state) {
  const auto& m = torus_mesh<T>();
  const MeshDistanceTree<T> tree(std::span<const Vec3<T>>(m.v),
                                 std::span<const std::array<std::uint32_t, 3>>(m.t));
  const auto p = random_points<T>(kCount, T(-8), T(8), 9);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(classify(p[i], tree));
    i = (i + 1) % kCount;
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

BENCHMARK(BoxMesh_SegmentOBB<float>);
BENCHMARK(BoxMesh_SegmentOBB<double>);
BENCHMARK(BoxMesh_LineAABB<double>);
BENCHMARK(BoxMesh_PointFrustum<double>);
BENCHMARK(BoxMesh_PointConvexPolygon_LogN);
BENCHMARK(BoxMesh_PointConvexPolygon_BruteEdges);
BENCHMARK(BoxMesh_MeshTreeBuild<double>)->Unit(benchmark::kMillisecond);
BENCHMARK(BoxMesh_PointMeshTree<float>);
BENCHMARK(BoxMesh_PointMeshTree<double>);
BENCHMARK(BoxMesh_PointMeshTreeNearSurface<double>);
BENCHMARK(BoxMesh_PointMeshBrute<double>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BoxMesh_MeshTreeClassify<double>);
