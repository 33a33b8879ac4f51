// SPDX-License-Identifier: BSL-1.0
// Smallest enclosing circle / sphere of 10^6 points and minimum-volume box of 10^5 points
// (rows cg.minball, cg.minbox), against CGAL when it is installed. Box inputs (10^5 points
// each): uniform in a rotated 3 x 2 x 1 cuboid (small hull), uniform in the unit ball, uniform
// on the unit sphere (every point a hull vertex), uniform in a rotated ellipsoid with semi-axes
// 1.7, 1.1, 0.6. Peers:
//   Min_circle_2 (Welzl with move-to-front) over Simple_cartesian<double> (inexact: its
//     decisions are rounded) and over Exact_predicates_exact_constructions_kernel (certified,
//     like locus);
//   Min_sphere_of_spheres_d with Min_sphere_of_points_d_traits_3 over Simple_cartesian<double>
//     (its default strategy, floating point with a sqrt-field representation);
//   oriented_bounding_box (a heuristic search: genetic algorithm + Nelder-Mead over rotations of
//     the hull vertices; not exact) over Exact_predicates_inexact_constructions_kernel.
// (benchmark::DoNotOptimize on a double is avoided: with GCC its "+m,r" constraint has
// corrupted floating-point values; the results are stored to a volatile sink instead.)
// Label: radius or volume of the result, so quality can be compared next to the time (and for
// locus' box whether its minimality was certified). Peak memory: the counter peak_MB (heap
// growth during the case, bench/support/heap_peak.hpp) where that helper is built in; otherwise
// run one case per process, e.g.
//   /usr/bin/time -v build/bench/locus_bench_bounding --benchmark_filter='^BM_min_circle_locus$'
#include <locus/bounding/min_box3.hpp>
#include <locus/bounding/min_circle.hpp>
#include <locus/bounding/min_sphere.hpp>

#include <benchmark/benchmark.h>

#if __has_include("support/heap_peak.hpp")
#include "support/heap_peak.hpp"
#define LOCUS_BENCH_HEAP_PEAK 1
#endif

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#if defined(LOCUS_HAVE_CGAL)
#if defined(LOCUS_HAVE_EIGEN) && !defined(CGAL_EIGEN3_ENABLED)
#define CGAL_EIGEN3_ENABLED 1
#endif
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Min_circle_2.h>
#include <CGAL/Min_circle_2_traits_2.h>
#include <CGAL/Min_sphere_of_points_d_traits_3.h>
#include <CGAL/Min_sphere_of_spheres_d.h>
#include <CGAL/Simple_cartesian.h>
#if defined(CGAL_EIGEN3_ENABLED)
#include <CGAL/optimal_bounding_box.h>
#endif
#endif

namespace {

volatile double sink = 0.0;

using locus::Vec2;
using locus::Vec3;

constexpr std::size_t ball_points = 1000000;
constexpr std::size_t box_points = 100000;

const std::vector<Vec2<double>>& disk_points() {
  static const std::vector<Vec2<double>> pts = [] {
    std::mt19937_64 g(20261122);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Vec2<double>> p(ball_points);
    for (auto& q : p) q = {u(g), u(g)};
    return p;
  }();
  return pts;
}

const std::vector<Vec3<double>>& cube_points() {
  static const std::vector<Vec3<double>> pts = [] {
    std::mt19937_64 g(20261123);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Vec3<double>> p(ball_points);
    for (auto& q : p) q = {u(g), u(g), u(g)};
    return p;
  }();
  return pts;
}

// The box inputs: a point in the unit cube / ball / on the unit sphere, then scaled and rotated
// by fixed rotations (about z by 0.4, then about x by 1.1).
enum class BoxCase { cuboid, ball, sphere, ellipsoid };

std::vector<Vec3<double>> make_box_input(BoxCase kind) {
  std::mt19937_64 g(20261124 + static_cast<unsigned>(kind));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> normal;
  const double c1 = std::cos(0.4), s1 = std::sin(0.4), c2 = std::cos(1.1), s2 = std::sin(1.1);
  std::vector<Vec3<double>> p(box_points);
  for (auto& q : p) {
    double x = 0, y = 0, z = 0;
    switch (kind) {
      case BoxCase::cuboid:  // the true minimum box is ~ 6
        x = 1.5 * u(g), y = 1.0 * u(g), z = 0.5 * u(g);
        break;
      case BoxCase::ball:
      case BoxCase::ellipsoid:
        do {
          x = u(g), y = u(g), z = u(g);
        } while (x * x + y * y + z * z > 1.0);
        if (kind == BoxCase::ellipsoid) x *= 1.7, y *= 1.1, z *= 0.6;
        break;
      case BoxCase::sphere: {
        x = normal(g), y = normal(g), z = normal(g);
        const double r = std::sqrt(x * x + y * y + z * z);
        x /= r, y /= r, z /= r;
        break;
      }
    }
    const double x1 = c1 * x - s1 * y, y1 = s1 * x + c1 * y;  // about z
    q = {x1, c2 * y1 - s2 * z, s2 * y1 + c2 * z};             // about x
  }
  return p;
}

const std::vector<Vec3<double>>& box_input(BoxCase kind) {
  static const std::vector<Vec3<double>> inputs[4] = {
      make_box_input(BoxCase::cuboid), make_box_input(BoxCase::ball),
      make_box_input(BoxCase::sphere), make_box_input(BoxCase::ellipsoid)};
  return inputs[static_cast<int>(kind)];
}

#if defined(LOCUS_BENCH_HEAP_PEAK)
using Peak = locus::bench::HeapPeak;
void report_peak(benchmark::State& state, const Peak& peak) {
  locus::bench::report_heap_peak(state, peak);
}
#else
struct Peak {};
void report_peak(benchmark::State&, const Peak&) {}
#endif

void BM_min_circle_locus(benchmark::State& state) {
  const auto& pts = disk_points();
  locus::MinCircle2<double> solver;
  double r = 0;
  Peak peak;
  for (auto _ : state) {
    const auto res = solver.compute(pts);
    r = res.circle.radius;
    sink = r;
  }
  report_peak(state, peak);
  state.SetLabel("radius=" + std::to_string(r));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}
BENCHMARK(BM_min_circle_locus)->Unit(benchmark::kMillisecond);

void BM_min_sphere_locus(benchmark::State& state) {
  const auto& pts = cube_points();
  locus::MinSphere3<double> solver;
  double r = 0;
  Peak peak;
  for (auto _ : state) {
    const auto res = solver.compute(pts);
    r = res.sphere.radius;
    sink = r;
  }
  report_peak(state, peak);
  state.SetLabel("radius=" + std::to_string(r));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}
BENCHMARK(BM_min_sphere_locus)->Unit(benchmark::kMillisecond);

// The same inputs scaled by 2^k (Arg k; exact): the time should not depend on the scale.
template <int D>
std::vector<locus::Vec<double, D>> scaled_input(int k) {
  std::vector<locus::Vec<double, D>> p;
  if constexpr (D == 2) {
    p = disk_points();
  } else {
    p = cube_points();
  }
  for (auto& q : p)
    for (int i = 0; i < D; ++i) q[i] = std::ldexp(q[i], k);
  return p;
}

// One run of a reusable ball solver on the input scaled by 2^k (D = 2: circle, 3: sphere).
template <int D, class Solver>
void run_scaled(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const auto pts = scaled_input<D>(k);
  Solver solver;
  double r = 0;
  for (auto _ : state) {
    const auto res = solver.compute(pts);
    if constexpr (D == 2) {
      r = res.circle.radius;
    } else {
      r = res.sphere.radius;
    }
    sink = r;
  }
  state.SetLabel("radius/2^k=" + std::to_string(std::ldexp(r, -k)));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}

void BM_min_circle_locus_scaled(benchmark::State& state) {
  run_scaled<2, locus::MinCircle2<double>>(state);
}
BENCHMARK(BM_min_circle_locus_scaled)
    ->Arg(-500)
    ->Arg(-300)
    ->Arg(0)
    ->Arg(300)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);

void BM_min_sphere_locus_scaled(benchmark::State& state) {
  run_scaled<3, locus::MinSphere3<double>>(state);
}
BENCHMARK(BM_min_sphere_locus_scaled)
    ->Arg(-500)
    ->Arg(-300)
    ->Arg(0)
    ->Arg(300)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);

void BM_min_box_locus(benchmark::State& state, BoxCase kind) {
  const auto& pts = box_input(kind);
  double v = 0;
  bool certified = false;
  Peak peak;
  for (auto _ : state) {
    const auto res = locus::min_box<double>(pts);
    v = res.volume;
    certified = res.certified;
    sink = v;
  }
  report_peak(state, peak);
  state.SetLabel("volume=" + std::to_string(v) + (certified ? " certified" : " uncertified"));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}
BENCHMARK_CAPTURE(BM_min_box_locus, cuboid, BoxCase::cuboid)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_min_box_locus, ball, BoxCase::ball)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_min_box_locus, sphere, BoxCase::sphere)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_min_box_locus, ellipsoid, BoxCase::ellipsoid)->Unit(benchmark::kMillisecond);

#if defined(LOCUS_HAVE_CGAL)
template <class K>
void min_circle_cgal(benchmark::State& state) {
  using Traits = CGAL::Min_circle_2_traits_2<K>;
  const auto& src = disk_points();
  std::vector<typename K::Point_2> pts;
  pts.reserve(src.size());
  for (const auto& p : src) pts.emplace_back(p.x, p.y);
  double r = 0;
  Peak peak;
  for (auto _ : state) {
    // Randomised (shuffled) as locus; true = randomize.
    CGAL::Min_circle_2<Traits> mc(pts.begin(), pts.end(), true);
    r = std::sqrt(CGAL::to_double(mc.circle().squared_radius()));
    sink = r;
  }
  report_peak(state, peak);
  state.SetLabel("radius=" + std::to_string(r));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}
void BM_min_circle_cgal_double(benchmark::State& state) {
  min_circle_cgal<CGAL::Simple_cartesian<double>>(state);
}
void BM_min_circle_cgal_epec(benchmark::State& state) {
  min_circle_cgal<CGAL::Exact_predicates_exact_constructions_kernel>(state);
}
BENCHMARK(BM_min_circle_cgal_double)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_min_circle_cgal_epec)->Unit(benchmark::kMillisecond);

void BM_min_sphere_cgal(benchmark::State& state) {
  using K = CGAL::Simple_cartesian<double>;
  using Traits = CGAL::Min_sphere_of_points_d_traits_3<K, double>;
  const auto& src = cube_points();
  std::vector<K::Point_3> pts;
  pts.reserve(src.size());
  for (const auto& p : src) pts.emplace_back(p.x, p.y, p.z);
  double r = 0;
  Peak peak;
  for (auto _ : state) {
    CGAL::Min_sphere_of_spheres_d<Traits> ms(pts.begin(), pts.end());
    r = CGAL::to_double(ms.radius());
    sink = r;
  }
  report_peak(state, peak);
  state.SetLabel("radius=" + std::to_string(r));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}
BENCHMARK(BM_min_sphere_cgal)->Unit(benchmark::kMillisecond);

#if defined(CGAL_EIGEN3_ENABLED)
void BM_min_box_cgal(benchmark::State& state, BoxCase kind) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto& src = box_input(kind);
  std::vector<K::Point_3> pts;
  pts.reserve(src.size());
  for (const auto& p : src) pts.emplace_back(p.x, p.y, p.z);
  double v = 0;
  Peak peak;
  for (auto _ : state) {
    std::array<K::Point_3, 8> obb;
    CGAL::oriented_bounding_box(pts, obb, CGAL::parameters::use_convex_hull(true));
    // Corners 0..7: 0-1, 0-3 and 0-5 are the three edges at corner 0 (CGAL's order).
    const double a = std::sqrt(CGAL::to_double(CGAL::squared_distance(obb[0], obb[1])));
    const double b = std::sqrt(CGAL::to_double(CGAL::squared_distance(obb[0], obb[3])));
    const double c = std::sqrt(CGAL::to_double(CGAL::squared_distance(obb[0], obb[5])));
    v = a * b * c;
    sink = v;
  }
  report_peak(state, peak);
  state.SetLabel("volume=" + std::to_string(v));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}
BENCHMARK_CAPTURE(BM_min_box_cgal, cuboid, BoxCase::cuboid)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_min_box_cgal, ball, BoxCase::ball)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_min_box_cgal, sphere, BoxCase::sphere)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_min_box_cgal, ellipsoid, BoxCase::ellipsoid)->Unit(benchmark::kMillisecond);
#endif
#endif

}  // namespace
