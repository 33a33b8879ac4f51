// SPDX-License-Identifier: BSL-1.0
// Convex hulls (rows cg.hull2, cg.hull3) against the peers, in the same run:
//   2D: 10^6 and 10^7 uniform points in a square, 10^6 points on a circle, the 1000 x 1000
//       integer grid; locus (monotone chain; also the book's two methods at 10^6) vs CGAL
//       convex_hull_2, Boost.Geometry convex_hull, Qhull (qh_new_qhull, dimension 2).
//   3D: 10^6 uniform points in a cube, 10^5 points on a sphere; locus QuickHull vs Qhull and
//       CGAL convex_hull_3 (into a Surface_mesh).
// Targets (issue): locus <= 0.5x the fastest peer's time.
// Peak memory: the counter peak_MB is the largest heap growth during one call (every malloc of
// the process, peers included, is counted by bench/support/heap_peak; the input is allocated
// before). Peers compile only when LOCUS_HAVE_CGAL / LOCUS_HAVE_BOOST / LOCUS_HAVE_QHULL are set.
#include <locus/hull/hull2.hpp>
#include <locus/hull/hull3.hpp>

#include <benchmark/benchmark.h>

#include "support/heap_peak.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#if defined(LOCUS_HAVE_CGAL)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>
#endif
#if defined(LOCUS_HAVE_BOOST)
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_point.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#endif
#if defined(LOCUS_HAVE_QHULL)
extern "C" {
#include <libqhull_r/libqhull_r.h>
}
#endif

namespace {

using locus::Vec2;
using locus::Vec3;

using locus::bench::HeapPeak;

enum class Set2 { square, circle, grid };
enum class Set3 { cube, sphere };

const std::vector<Vec2<double>>& points2(Set2 s, std::size_t n) {
  static std::vector<Vec2<double>> cache;
  static Set2 cs{};
  static std::size_t cn = 0;
  if (cn == n && cs == s && !cache.empty()) return cache;
  cache.clear();
  cache.shrink_to_fit();
  std::mt19937_64 g(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  if (s == Set2::grid) {
    for (int i = 0; i < 1000; ++i)
      for (int j = 0; j < 1000; ++j) cache.push_back({double(i), double(j)});
    std::shuffle(cache.begin(), cache.end(), g);
  } else {
    cache.resize(n);
    for (auto& p : cache) {
      if (s == Set2::square) {
        p = {u(g), u(g)};
      } else {
        const double a = 2 * 3.14159265358979323846 * u(g);
        p = {std::cos(a), std::sin(a)};
      }
    }
  }
  cs = s;
  cn = n;
  return cache;
}

const std::vector<Vec3<double>>& points3(Set3 s, std::size_t n) {
  static std::vector<Vec3<double>> cache;
  static Set3 cs{};
  static std::size_t cn = 0;
  if (cn == n && cs == s && !cache.empty()) return cache;
  cache.assign(n, Vec3<double>{});
  std::mt19937_64 g(54321);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> nd;
  for (auto& p : cache) {
    if (s == Set3::cube) {
      p = {u(g), u(g), u(g)};
    } else {
      double x, y, z, l;
      do {
        x = nd(g), y = nd(g), z = nd(g);
        l = std::sqrt(x * x + y * y + z * z);
      } while (l < 1e-6);
      p = {x / l, y / l, z / l};
    }
  }
  cs = s;
  cn = n;
  return cache;
}

void report(benchmark::State& state, const HeapPeak& peak, std::size_t hull_size, std::size_t n) {
  locus::bench::report_heap_peak(state, peak);
  state.counters["hull"] = static_cast<double>(hull_size);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(n));
}

// ---- 2D -------------------------------------------------------------------------------------
void BM_hull2_locus(benchmark::State& state, Set2 s, std::size_t n, locus::Hull2Method m) {
  const auto& pts = points2(s, n);
  locus::Hull2Options o;
  o.method = m;
  std::size_t h = 0;
  HeapPeak peak;
  for (auto _ : state) {
    // One call, cold (no reuse of a builder), like the peers.
    const locus::Hull2Result r = locus::convex_hull(pts, o);
    h = r.indices.size();
    benchmark::DoNotOptimize(r.indices.data());
  }
  report(state, peak, h, pts.size());
}

#if defined(LOCUS_HAVE_CGAL)
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
void BM_hull2_cgal(benchmark::State& state, Set2 s, std::size_t n) {
  const auto& src = points2(s, n);
  std::vector<K::Point_2> pts;
  for (const auto& p : src) pts.emplace_back(p.x, p.y);
  std::vector<K::Point_2> out;
  std::size_t h = 0;
  HeapPeak peak;
  for (auto _ : state) {
    out.clear();
    out.shrink_to_fit();
    CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(out));
    h = out.size();
    benchmark::DoNotOptimize(out.data());
  }
  report(state, peak, h, pts.size());
}
#endif

#if defined(LOCUS_HAVE_BOOST)
namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
void BM_hull2_boost(benchmark::State& state, Set2 s, std::size_t n) {
  const auto& src = points2(s, n);
  bg::model::multi_point<BPoint> mp;
  for (const auto& p : src) mp.emplace_back(p.x, p.y);
  std::size_t h = 0;
  HeapPeak peak;
  for (auto _ : state) {
    bg::model::polygon<BPoint> hull;
    bg::convex_hull(mp, hull);
    h = hull.outer().size();
    benchmark::DoNotOptimize(hull.outer().data());
  }
  report(state, peak, h, src.size());
}
#endif

#if defined(LOCUS_HAVE_QHULL)
// Qhull's default (merged facets, no output file).
std::size_t qhull_run(int dim, const double* coords, std::size_t n) {
  qhT qh_qh;
  qhT* qh = &qh_qh;
  QHULL_LIB_CHECK
  qh_zero(qh, stderr);
  char flags[] = "qhull";
  const int err = qh_new_qhull(qh, dim, static_cast<int>(n), const_cast<double*>(coords), False,
                               flags, nullptr, stderr);
  const std::size_t nv = err == 0 ? static_cast<std::size_t>(qh->num_vertices) : 0;
  qh_freeqhull(qh, !qh_ALL);
  int curlong, totlong;
  qh_memfreeshort(qh, &curlong, &totlong);
  return nv;
}
void BM_hull2_qhull(benchmark::State& state, Set2 s, std::size_t n) {
  const auto& src = points2(s, n);
  std::size_t h = 0;
  HeapPeak peak;
  for (auto _ : state) h = qhull_run(2, &src[0].x, src.size());
  report(state, peak, h, src.size());
}
void BM_hull3_qhull(benchmark::State& state, Set3 s, std::size_t n) {
  const auto& src = points3(s, n);
  std::size_t h = 0;
  HeapPeak peak;
  for (auto _ : state) h = qhull_run(3, &src[0].x, src.size());
  report(state, peak, h, src.size());
}
#endif

// ---- 3D -------------------------------------------------------------------------------------
void BM_hull3_locus(benchmark::State& state, Set3 s, std::size_t n, locus::Hull3Method m) {
  const auto& pts = points3(s, n);
  locus::Hull3Options o;
  o.method = m;
  std::size_t h = 0;
  HeapPeak peak;
  for (auto _ : state) {
    const locus::Hull3Result r = locus::convex_hull(pts, o);
    h = r.vertices.size();
    benchmark::DoNotOptimize(r.triangles.data());
  }
  report(state, peak, h, pts.size());
}

#if defined(LOCUS_HAVE_CGAL)
void BM_hull3_cgal(benchmark::State& state, Set3 s, std::size_t n) {
  const auto& src = points3(s, n);
  std::vector<K::Point_3> pts;
  for (const auto& p : src) pts.emplace_back(p.x, p.y, p.z);
  std::size_t h = 0;
  HeapPeak peak;
  for (auto _ : state) {
    CGAL::Surface_mesh<K::Point_3> sm;
    CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
    h = sm.number_of_vertices();
    benchmark::DoNotOptimize(&sm);
  }
  report(state, peak, h, src.size());
}
#endif

void register_all() {
  using locus::Hull2Method;
  using locus::Hull3Method;
  struct C2 {
    const char* name;
    Set2 s;
    std::size_t n;
  };
  const C2 c2[] = {{"uniform_1e6", Set2::square, 1000000},
                   {"uniform_1e7", Set2::square, 10000000},
                   {"circle_1e6", Set2::circle, 1000000},
                   {"grid_1000x1000", Set2::grid, 1000000}};
  for (const C2& c : c2) {
    const std::string tag = std::string("/") + c.name;
    benchmark::RegisterBenchmark(("hull2/locus_monotone_chain" + tag).c_str(), BM_hull2_locus, c.s,
                                 c.n, Hull2Method::monotone_chain)
        ->Unit(benchmark::kMillisecond);
    if (c.n <= 1000000) {
      benchmark::RegisterBenchmark(("hull2/locus_incremental" + tag).c_str(), BM_hull2_locus, c.s,
                                   c.n, Hull2Method::incremental)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("hull2/locus_divide_and_conquer" + tag).c_str(), BM_hull2_locus,
                                   c.s, c.n, Hull2Method::divide_and_conquer)
          ->Unit(benchmark::kMillisecond);
    }
#if defined(LOCUS_HAVE_CGAL)
    benchmark::RegisterBenchmark(("hull2/cgal_convex_hull_2" + tag).c_str(), BM_hull2_cgal, c.s,
                                 c.n)
        ->Unit(benchmark::kMillisecond);
#endif
#if defined(LOCUS_HAVE_BOOST)
    benchmark::RegisterBenchmark(("hull2/boost_convex_hull" + tag).c_str(), BM_hull2_boost, c.s,
                                 c.n)
        ->Unit(benchmark::kMillisecond);
#endif
#if defined(LOCUS_HAVE_QHULL)
    benchmark::RegisterBenchmark(("hull2/qhull" + tag).c_str(), BM_hull2_qhull, c.s, c.n)
        ->Unit(benchmark::kMillisecond);
#endif
  }
  struct C3 {
    const char* name;
    Set3 s;
    std::size_t n;
  };
  const C3 c3[] = {{"cube_1e6", Set3::cube, 1000000},
                   {"sphere_1e5", Set3::sphere, 100000},
                   {"sphere_1e4", Set3::sphere, 10000}};
  for (const C3& c : c3) {
    const std::string tag = std::string("/") + c.name;
    benchmark::RegisterBenchmark(("hull3/locus_quickhull" + tag).c_str(), BM_hull3_locus, c.s, c.n,
                                 Hull3Method::quickhull)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("hull3/locus_divide_and_conquer" + tag).c_str(), BM_hull3_locus,
                                 c.s, c.n, Hull3Method::divide_and_conquer)
        ->Unit(benchmark::kMillisecond);
    if (c.n <= 10000)  // O(n h): the divide-and-conquer method against the book's incremental one
      benchmark::RegisterBenchmark(("hull3/locus_incremental" + tag).c_str(), BM_hull3_locus, c.s,
                                   c.n, Hull3Method::incremental)
          ->Unit(benchmark::kMillisecond);
#if defined(LOCUS_HAVE_QHULL)
    benchmark::RegisterBenchmark(("hull3/qhull" + tag).c_str(), BM_hull3_qhull, c.s, c.n)
        ->Unit(benchmark::kMillisecond);
#endif
#if defined(LOCUS_HAVE_CGAL)
    benchmark::RegisterBenchmark(("hull3/cgal_convex_hull_3" + tag).c_str(), BM_hull3_cgal, c.s,
                                 c.n)
        ->Unit(benchmark::kMillisecond);
#endif
  }
}

const int registered = (register_all(), 0);

}  // namespace
