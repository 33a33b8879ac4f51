// SPDX-License-Identifier: BSL-1.0
// The accuracy beside the speed of distance_bench.cpp and distance_peers_bench.cpp: the exact
// oracle (exact_sqr_distances, distance_inputs.hpp) and the peers' accuracy runs
// <pair>/max_err/cgal<Kernel> (report_error; locus's are in distance_bench.cpp). A translation unit
// of its own: with CGAL's exact rationals in the same file as the timed peers, CGAL's
// segment-segment query ran 1.3x slower in the timed loop (its code placement, not its work).

#include "distance/distance_inputs.hpp"

#include <benchmark/benchmark.h>

#include <vector>

#if defined(LOCUS_HAVE_CGAL)
#include "distance/cgal_query.hpp"

#include <CGAL/Gmpq.h>

#include <map>
#include <tuple>
#include <type_traits>

namespace {

using namespace locus_bench_distance;

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

// The peer's accuracy on the same inputs (report_error).
template <class Pair, class K>
void cgal_accuracy(benchmark::State& state) {
  const auto in = Pair::input(state);
  report_error(state, to_cgal_all<K>(in.first), to_cgal_all<K>(in.second), CgalQuery<K>{},
               Pair::exact(state, std::is_same_v<typename K::FT, float>));
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

#define LOCUS_ACCURACY_CGAL(Pair, name, args)                                            \
  LOCUS_ACCURACY_RUN(name, "cgal<Simple_cartesian>", args, cgal_accuracy<Pair, Simple>); \
  LOCUS_ACCURACY_RUN(name, "cgal<Simple_cartesian<float>>", args, cgal_accuracy<Pair, SimpleFloat>)
LOCUS_FOR_CGAL_PAIRS(LOCUS_ACCURACY_CGAL);
#else
namespace locus_bench_distance {
const std::vector<double>& exact_sqr_distances(ExactPair, bool, bool) {
  static const std::vector<double> none;  // no exact oracle without CGAL
  return none;
}
}  // namespace locus_bench_distance
#endif
