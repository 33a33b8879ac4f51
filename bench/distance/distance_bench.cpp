// SPDX-License-Identifier: BSL-1.0
// Distance queries per second (rows dist3.pt-triangle, dist3.linear-linear, dist3.pt-obb,
// dist3.linear-triangle): point-triangle, segment-segment (generic and nearly parallel),
// segment-triangle, point-OBB and point-AABB in 3D, float and double, over 4096 random inputs
// cycled so that the data stays in cache. Items per second = queries per second.
//
// Every pair runs the same templated loop (cycle()) with three kinds of query on the same inputs:
//   <pair>/distance<T>      locus::distance: the full result (closest points, parameters, sqrt);
//   <pair>/sqr_distance<T>  locus::sqr_distance: the squared distance only, like CGAL's;
//   <pair>/sqr_distances<T> locus::sqr_distances (distance/batch.hpp): the same values for all
//                           4096 pairs in one call (items = queries), several per SIMD instruction
//                           (point_triangle/sqr_distances_one_triangle<T>: 4096 points against one
//                           triangle; <pair>/sqr_distances_avx2<double>: capped to the AVX2
//                           version of the kernels, on a processor that has x86-64-v4);
//   <pair>/cgal<Kernel>     the peer on the double inputs (converted once, outside the loop):
//     CGAL::squared_distance with Simple_cartesian<double> (plain floating point, the fair peer)
//     and Exact_predicates_inexact_constructions_kernel (what CGAL users usually take), when
//     CGAL is found (LOCUS_HAVE_CGAL). CGAL 5.5 has no segment-triangle distance: that peer is
//     composed from CGAL's own queries (see cgal_query). It has no point-box distance either
//     (no squared_distance for Iso_cuboid_3, Bbox_3 or an oriented box), so the box pairs run
//     against <pair>/textbook: the plain textbook loop written here (per axis: the coordinate in
//     the box frame, the excess over the slab with if/else, summed squares; no input checks), the
//     code a user would write instead of calling a library.
// The CGAL peers live in distance_peers_bench.cpp (same inputs and loop: distance_inputs.hpp), a
// separate translation unit: CGAL's CMake target adds -frounding-math to every source that links
// it, and bench/CMakeLists.txt takes it back (-fno-rounding-math) for this file, which holds only
// locus and the textbook loops, so that locus is timed as compiled in a user's program.
// Accuracy beside speed: <pair>/max_err/sqr_distance<T> and <pair>/max_err/cgal<Kernel>, for the
// pairs CGAL has, run once and report max_err, the largest absolute error of the squared
// distance over the 4096 inputs against CGAL's own query over exact rationals (Gmpq; for float,
// on the inputs rounded to float). On nearly parallel segment pairs (squared distances 0.1-1) it
// shows what the robust path buys: CGAL double 1.9e-8 against locus 6.7e-16, CGAL float 2.9e-6
// against locus 4.1e-7.
//
// Run: locus_bench_distance --benchmark_min_time=0.2 --benchmark_filter='^(point|segment|seg)'

#include "distance/distance_inputs.hpp"

#include <locus/distance/batch.hpp>
#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/distance/segment_triangle.hpp>

#include <benchmark/benchmark.h>

#include <type_traits>

namespace {

using namespace locus_bench_distance;

// locus on the pair's inputs converted to T.
template <class Pair, class T, class Query>
void locus_bench(benchmark::State& state) {
  const auto in = Pair::input(state);
  cycle(state, cast_all<T>(in.first), cast_all<T>(in.second), Query{});
}

// The accuracy of locus's sqr_distance on the same inputs (report_error).
template <class Pair, class T>
void locus_accuracy(benchmark::State& state) {
  const auto in = Pair::input(state);
  report_error(state, cast_all<T>(in.first), cast_all<T>(in.second), SqrQuery{},
               Pair::exact(state, std::is_same_v<T, float>));
}

// locus's batch form over all the inputs at once; items per second = queries per second.
// kIsa caps the compiled version of the kernels (detail::set_batch_isa: 2 x86-64-v4 where the
// processor has it, 1 AVX2).
template <class Pair, class T, int kIsa = 2>
void batch_bench(benchmark::State& state) {
  const auto level = locus::detail::set_batch_isa(static_cast<locus::detail::BatchIsa>(kIsa));
  if (static_cast<int>(level) != kIsa) {
    state.SkipWithError("the processor lacks this instruction set");
    locus::detail::set_batch_isa(locus::detail::BatchIsa::x86_64_v4);
    return;
  }
  const auto in = Pair::input(state);
  const auto a = cast_all<T>(in.first);
  const auto b = cast_all<T>(in.second);
  using A = typename decltype(a)::value_type;
  using B = typename decltype(b)::value_type;
  std::vector<T> out(a.size());
  for (auto _ : state) {
    locus::sqr_distances(std::span<const A>(a), std::span<const B>(b), std::span<T>(out));
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(a.size()));
  locus::detail::set_batch_isa(locus::detail::BatchIsa::x86_64_v4);
}

// The "one against many" form: every point against the first triangle (a point cloud against
// one triangle); items per second = queries per second.
template <class T>
void point_cloud_triangle_bench(benchmark::State& state) {
  const auto in = PointTriangle::input(state);
  const auto p = cast_all<T>(in.first);
  const auto tri = cast<T>(in.second.front());
  std::vector<T> out(p.size());
  for (auto _ : state) {
    locus::sqr_distances(std::span<const locus::Vec3<T>>(p), tri, std::span<T>(out));
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(p.size()));
}

// ---- the textbook peer for the boxes (no library has it) --------------------------------------

struct TextbookQuery {
  static double excess(double x, double lo, double hi) {
    if (x < lo) return x - lo;
    if (x > hi) return x - hi;
    return 0.0;
  }
  double operator()(const locus::Vec3d& p, const locus::OrientedBox3<double>& b) const {
    const locus::Vec3d d = p - b.center;
    double sq = 0;
    for (int i = 0; i < 3; ++i) {
      const double x = d.x * b.axis[i].x + d.y * b.axis[i].y + d.z * b.axis[i].z;
      const double e = excess(x, -b.extent[i], b.extent[i]);
      sq += e * e;
    }
    return sq;
  }
  double operator()(const locus::Vec3d& p, const locus::AlignedBox3<double>& b) const {
    double sq = 0;
    for (int i = 0; i < 3; ++i) {
      const double e = excess(p[i], b.min[i], b.max[i]);
      sq += e * e;
    }
    return sq;
  }
};
template <class Pair>
void textbook_bench(benchmark::State& state) {
  const auto in = Pair::input(state);
  cycle(state, in.first, in.second, TextbookQuery{});
}

}  // namespace

// Registers <name>/distance<T>, <name>/sqr_distance<T>, <name>/sqr_distances<T> for float and
// double.
#define LOCUS_BENCH_LOCUS(Pair, name, ...)                                                        \
  BENCHMARK(locus_bench<Pair, float, FullQuery>)->Name(name "/distance<float>") __VA_ARGS__;      \
  BENCHMARK(locus_bench<Pair, double, FullQuery>)->Name(name "/distance<double>") __VA_ARGS__;    \
  BENCHMARK(locus_bench<Pair, float, SqrQuery>)->Name(name "/sqr_distance<float>") __VA_ARGS__;   \
  BENCHMARK(locus_bench<Pair, double, SqrQuery>)->Name(name "/sqr_distance<double>") __VA_ARGS__; \
  BENCHMARK(batch_bench<Pair, float>)->Name(name "/sqr_distances<float>") __VA_ARGS__;            \
  BENCHMARK(batch_bench<Pair, double>)->Name(name "/sqr_distances<double>") __VA_ARGS__;          \
  BENCHMARK(batch_bench<Pair, double, 1>)->Name(name "/sqr_distances_avx2<double>") __VA_ARGS__

LOCUS_BENCH_LOCUS(PointTriangle, "point_triangle");
BENCHMARK(point_cloud_triangle_bench<float>)
    ->Name("point_triangle/sqr_distances_one_triangle<float>");
BENCHMARK(point_cloud_triangle_bench<double>)
    ->Name("point_triangle/sqr_distances_one_triangle<double>");
LOCUS_BENCH_LOCUS(SegmentSegment, "segment_segment", ->ArgName("near_parallel")->Arg(0)->Arg(1));
LOCUS_BENCH_LOCUS(SegmentTriangle, "segment_triangle");
// <pair>/max_err/sqr_distance<T>: the accuracy runs (report_error), once each.
#define LOCUS_ACCURACY_LOCUS(Pair, name, args)                                        \
  LOCUS_ACCURACY_RUN(name, "sqr_distance<float>", args, locus_accuracy<Pair, float>); \
  LOCUS_ACCURACY_RUN(name, "sqr_distance<double>", args, locus_accuracy<Pair, double>)
LOCUS_FOR_CGAL_PAIRS(LOCUS_ACCURACY_LOCUS);
LOCUS_BENCH_LOCUS(PointObb, "point_obb");
BENCHMARK(textbook_bench<PointObb>)->Name("point_obb/textbook<double>");
LOCUS_BENCH_LOCUS(PointAabb, "point_aabb");
BENCHMARK(textbook_bench<PointAabb>)->Name("point_aabb/textbook<double>");
