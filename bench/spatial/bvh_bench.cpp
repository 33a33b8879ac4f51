// SPDX-License-Identifier: BSL-1.0
// spatial/bvh.hpp against Embree 3 (when found): build time and single-thread closest-hit
// throughput, 10^6 rays against a 10^6-triangle mesh, and leak counts on 10^6 rays aimed
// exactly at edge points of the closed mesh from inside it (every such ray must hit).
// Mesh: torus_mesh(1, 0.4, 1000, 500) (10^6 triangles) with the tube radius of every vertex
// scaled by a random factor in [0.97, 1.03] (still closed), coordinates on the 2^-16 grid so the
// edge midpoints and quarter points used as targets are exact in float. Random rays: origins
// uniform in [-2, 2]^3, aimed at a random vertex moved by up to 0.05 per axis (most hit).
// Edge rays: from the tube's centre circle at the target's angle (on the grid, inside the solid),
// aimed at the midpoint or a quarter point of a random edge. Embree: one device with
// "threads=1", one triangle geometry, default build quality, rtcIntersect1 per ray; closest
// args 0/1 (random/edge rays) on the default scene, 2/3 with RTC_SCENE_FLAG_ROBUST.

#include <benchmark/benchmark.h>

#include <locus/mesh/platonic.hpp>
#include <locus/mesh/polygon_mesh.hpp>
#include <locus/spatial/bvh.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#if defined(LOCUS_HAVE_EMBREE)
#include <embree3/rtcore.h>
#endif

namespace {

using namespace locus;

struct Scene {
  std::vector<Vec3<float>> vf;
  std::vector<Vec3<double>> vd;
  std::vector<std::array<std::uint32_t, 3>> tris;
  std::vector<Ray3<float>> rays, edge_rays;
  std::vector<Ray3<double>> rays_d, edge_rays_d;
};

double snap(double x) { return std::round(x * 65536.0) / 65536.0; }

const Scene& scene() {
  static const Scene s = [] {
    Scene r;
    const int nu = 1000, nv = 500;
    const PolygonMesh<double> m = torus_mesh<double>(1.0, 0.4, nu, nv);
    std::mt19937_64 g(20261204);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const auto& p : m.vertices) {
      const double rho = std::sqrt(p.x * p.x + p.y * p.y);
      const Vec3<double> c{p.x / rho, p.y / rho, 0.0};  // centre circle at this angle
      const double k = 1.0 + 0.03 * u(g);
      const Vec3<double> q = c + k * (p - c);
      r.vd.push_back({snap(q.x), snap(q.y), snap(q.z)});
      r.vf.push_back(vec_cast<float>(r.vd.back()));
    }
    r.tris = fan_triangles(m);
    const std::size_t n = 1000000;
    std::uniform_int_distribution<std::size_t> pick_v(0, r.vd.size() - 1),
        pick_t(0, r.tris.size() - 1);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3<double> o{2 * u(g), 2 * u(g), 2 * u(g)};
      const Vec3<double> t = r.vd[pick_v(g)] + Vec3<double>{0.05 * u(g), 0.05 * u(g), 0.05 * u(g)};
      r.rays_d.push_back({o, t - o});
      r.rays.push_back({vec_cast<float>(o), vec_cast<float>(t - o)});
      const auto& f = r.tris[pick_t(g)];
      const int k = static_cast<int>(i % 3);
      const Vec3<double> a = r.vd[f[static_cast<std::size_t>(k)]], b = r.vd[f[(k + 1) % 3]];
      const Vec3<double> x = (i % 2) ? 0.5 * (a + b) : 0.75 * a + 0.25 * b;
      const double rho = std::sqrt(x.x * x.x + x.y * x.y);
      const Vec3<double> c{snap(x.x / rho), snap(x.y / rho), 0.0};
      r.edge_rays_d.push_back({c, x - c});
      r.edge_rays.push_back({vec_cast<float>(c), vec_cast<float>(x - c)});
    }
    return r;
  }();
  return s;
}

template <class T>
const std::vector<Vec3<T>>& verts() {
  if constexpr (std::is_same_v<T, float>)
    return scene().vf;
  else
    return scene().vd;
}
template <class T>
const std::vector<Ray3<T>>& rays(bool edge) {
  if constexpr (std::is_same_v<T, float>)
    return edge ? scene().edge_rays : scene().rays;
  else
    return edge ? scene().edge_rays_d : scene().rays_d;
}

template <class T>
const Bvh<T>& bvh() {
  static const Bvh<T> b(verts<T>(), scene().tris);
  return b;
}

template <class T>
void BM_locus_build(benchmark::State& st) {
  const auto& s = scene();
  for (auto _ : st) {
    Bvh<T> b(verts<T>(), s.tris);
    benchmark::DoNotOptimize(b.node_count());
  }
  st.counters["triangles"] = double(s.tris.size());
}

template <class T>
void BM_locus_closest(benchmark::State& st) {
  const bool edge = st.range(0) != 0;
  const auto& b = bvh<T>();
  const auto& r = rays<T>(edge);
  std::vector<MeshHit<T>> out(r.size());
  for (auto _ : st) {
    b.closest_hits(r, out);
    benchmark::ClobberMemory();
  }
  std::size_t hits = 0;
  for (const auto& h : out) hits += h ? 1 : 0;
  st.counters["rays/s"] =
      benchmark::Counter(double(r.size()), benchmark::Counter::kIsIterationInvariantRate);
  st.counters["hits"] = double(hits);
  if (edge) st.counters["leaks"] = double(r.size() - hits);
}

BENCHMARK_TEMPLATE(BM_locus_build, float)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_TEMPLATE(BM_locus_build, double)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_TEMPLATE(BM_locus_closest, float)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_TEMPLATE(BM_locus_closest, double)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

#if defined(LOCUS_HAVE_EMBREE)

struct Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  explicit Embree(bool robust = false) {
    device = rtcNewDevice("threads=1");
    scene = rtcNewScene(device);
    if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const auto& s = ::scene();
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), s.vf.size()));
    for (std::size_t i = 0; i < s.vf.size(); ++i)
      for (int a = 0; a < 3; ++a) v[3 * i + static_cast<std::size_t>(a)] = s.vf[i][a];
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), s.tris.size()));
    for (std::size_t i = 0; i < s.tris.size(); ++i)
      for (int k = 0; k < 3; ++k)
        t[3 * i + static_cast<std::size_t>(k)] = s.tris[i][static_cast<std::size_t>(k)];
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
  }
  ~Embree() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
};

void BM_embree_build(benchmark::State& st) {
  (void)scene();
  for (auto _ : st) {
    Embree e;
    benchmark::DoNotOptimize(e.scene);
  }
}

// Arg: 0 random rays, 1 edge rays; +2: the scene built with RTC_SCENE_FLAG_ROBUST.
void BM_embree_closest(benchmark::State& st) {
  const bool edge = (st.range(0) & 1) != 0;
  static const Embree fast(false), robust(true);
  const Embree& e = st.range(0) >= 2 ? robust : fast;
  const auto& r = rays<float>(edge);
  std::size_t hits = 0;
  for (auto _ : st) {
    hits = 0;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (const auto& ray : r) {
      RTCRayHit rh{};
      rh.ray.org_x = ray.origin.x;
      rh.ray.org_y = ray.origin.y;
      rh.ray.org_z = ray.origin.z;
      rh.ray.dir_x = ray.direction.x;
      rh.ray.dir_y = ray.direction.y;
      rh.ray.dir_z = ray.direction.z;
      rh.ray.tnear = 0.0f;
      rh.ray.tfar = std::numeric_limits<float>::infinity();
      rh.ray.mask = 0xffffffffu;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(e.scene, &ctx, &rh);
      hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? 1 : 0;
    }
    benchmark::DoNotOptimize(hits);
  }
  st.counters["rays/s"] =
      benchmark::Counter(double(r.size()), benchmark::Counter::kIsIterationInvariantRate);
  st.counters["hits"] = double(hits);
  if (edge) st.counters["leaks"] = double(r.size() - hits);
}

BENCHMARK(BM_embree_build)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_embree_closest)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

#endif

}  // namespace
