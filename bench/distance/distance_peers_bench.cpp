// SPDX-License-Identifier: BSL-1.0
// The CGAL peers of distance_bench.cpp (see there): <pair>/cgal<Kernel> on the same double inputs
// and in the same loop (distance_inputs.hpp), converted to CGAL once, outside the loop. A separate
// translation unit so that CGAL keeps the -frounding-math its kernels need (Epick's interval
// filters) while the locus code in distance_bench.cpp is compiled without it.

#include "distance/distance_inputs.hpp"

#include <benchmark/benchmark.h>

#if defined(LOCUS_HAVE_CGAL)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <map>
#include <tuple>
#include <type_traits>
#include <vector>

namespace {

using namespace locus_bench_distance;

using Simple = CGAL::Simple_cartesian<double>;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
// The float peer of locus's float queries (the same inputs rounded to float).
using SimpleFloat = CGAL::Simple_cartesian<float>;

template <class K>
typename K::Point_3 to_cgal(const locus::Vec3d& v) {
  using FT = typename K::FT;
  return {static_cast<FT>(v.x), static_cast<FT>(v.y), static_cast<FT>(v.z)};
}
template <class K>
typename K::Segment_3 to_cgal(const locus::Segment3<double>& s) {
  return {to_cgal<K>(s.p0), to_cgal<K>(s.p1)};
}
template <class K>
typename K::Triangle_3 to_cgal(const locus::Triangle3<double>& t) {
  return {to_cgal<K>(t.v0), to_cgal<K>(t.v1), to_cgal<K>(t.v2)};
}
template <class K, class X>
auto to_cgal_all(const std::vector<X>& v) {
  std::vector<decltype(to_cgal<K>(v[0]))> r;
  for (const X& x : v) r.push_back(to_cgal<K>(x));
  return r;
}

template <class K>
struct CgalQuery {
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return CGAL::squared_distance(a, b);
  }
  // CGAL 5.5 has no Segment_3 / Triangle_3 squared_distance (it arrived in CGAL 6): the peer is
  // the usual composition from CGAL's own queries: 0 when do_intersect(segment, triangle),
  // otherwise the minimum over the two end points to the triangle and the segment to the three
  // edges (the closest pair of disjoint convex sets has a point on a boundary feature).
  double operator()(const typename K::Segment_3& seg, const typename K::Triangle_3& tri) const {
    if (CGAL::do_intersect(seg, tri)) return 0.0;
    double d = CGAL::to_double(CGAL::squared_distance(seg.source(), tri));
    d = std::min(d, CGAL::to_double(CGAL::squared_distance(seg.target(), tri)));
    for (int e = 0; e < 3; ++e)
      d = std::min(d, CGAL::to_double(CGAL::squared_distance(
                          seg, typename K::Segment_3(tri.vertex(e), tri.vertex((e + 1) % 3)))));
    return d;
  }
};

template <class Pair, class K>
void cgal_bench(benchmark::State& state) {
  const auto in = Pair::input(state);
  cycle(state, to_cgal_all<K>(in.first), to_cgal_all<K>(in.second), CgalQuery<K>{},
        Pair::exact(state, std::is_same_v<typename K::FT, float>));
}

// The exact oracle: CGAL's own queries over rationals. A float input is rounded to float and
// widened back to double first (both exact steps), so that Gmpq is built from a double.
using Exact = CGAL::Simple_cartesian<CGAL::Gmpq>;

template <class X, class Y>
std::vector<double> exact_of(const std::vector<X>& x, const std::vector<Y>& y, bool single) {
  const auto widen = [single](const auto& v) {
    return single ? cast_all<double>(cast_all<float>(v)) : v;
  };
  const auto a = to_cgal_all<Exact>(widen(x));
  const auto b = to_cgal_all<Exact>(widen(y));
  std::vector<double> r;
  for (std::size_t i = 0; i < a.size(); ++i)
    r.push_back(CGAL::to_double(CgalQuery<Exact>{}(a[i], b[i])));
  return r;
}

}  // namespace

namespace locus_bench_distance {
const std::vector<double>& exact_sqr_distances(ExactPair pair, bool near_parallel, bool single) {
  static std::map<std::tuple<int, bool, bool>, std::vector<double>> cache;
  const auto key = std::tuple{static_cast<int>(pair), near_parallel, single};
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  std::vector<double> r;
  if (pair == kExactPointTriangle) {
    const auto& in = point_triangle_input();
    r = exact_of(in.p, in.t, single);
  } else if (pair == kExactSegmentSegment) {
    const auto& in = segment_pair_input(near_parallel);
    r = exact_of(in.a, in.b, single);
  } else {
    const auto& in = segment_triangle_input();
    r = exact_of(in.s, in.t, single);
  }
  return cache.emplace(key, std::move(r)).first->second;
}
}  // namespace locus_bench_distance

#define LOCUS_BENCH_CGAL(Pair, name, ...)                                                \
  BENCHMARK(cgal_bench<Pair, Simple>)->Name(name "/cgal<Simple_cartesian>") __VA_ARGS__; \
  BENCHMARK(cgal_bench<Pair, Epick>)->Name(name "/cgal<Epick>") __VA_ARGS__;             \
  BENCHMARK(cgal_bench<Pair, SimpleFloat>)->Name(name "/cgal<Simple_cartesian<float>>") __VA_ARGS__

LOCUS_BENCH_CGAL(PointTriangle, "point_triangle");
LOCUS_BENCH_CGAL(SegmentSegment, "segment_segment", ->ArgName("near_parallel")->Arg(0)->Arg(1));
LOCUS_BENCH_CGAL(SegmentTriangle, "segment_triangle");
#else
namespace locus_bench_distance {
const std::vector<double>& exact_sqr_distances(ExactPair, bool, bool) {
  static const std::vector<double> none;  // no exact oracle without CGAL
  return none;
}
}  // namespace locus_bench_distance
#endif
