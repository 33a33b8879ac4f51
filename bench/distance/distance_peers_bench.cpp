// SPDX-License-Identifier: BSL-1.0
// The CGAL peers of distance_bench.cpp (see there): <pair>/cgal<Kernel> on the same double inputs
// and in the same loop (distance_inputs.hpp), converted to CGAL once, outside the loop. A separate
// translation unit so that CGAL keeps the -frounding-math its kernels need (Epick's interval
// filters) while the locus code in distance_bench.cpp is compiled without it.

#include "distance/distance_inputs.hpp"

#include <benchmark/benchmark.h>

#if defined(LOCUS_HAVE_CGAL)
#include "distance/cgal_query.hpp"

namespace {

using namespace locus_bench_distance;

template <class Pair, class K>
void cgal_bench(benchmark::State& state) {
  const auto in = Pair::input(state);
  cycle(state, to_cgal_all<K>(in.first), to_cgal_all<K>(in.second), CgalQuery<K>{});
}

}  // namespace

#define LOCUS_BENCH_CGAL(Pair, name, args)                                        \
  BENCHMARK(cgal_bench<Pair, Simple>)->Name(name "/cgal<Simple_cartesian>") args; \
  BENCHMARK(cgal_bench<Pair, Epick>)->Name(name "/cgal<Epick>") args;             \
  BENCHMARK(cgal_bench<Pair, SimpleFloat>)->Name(name "/cgal<Simple_cartesian<float>>") args

LOCUS_FOR_CGAL_PAIRS(LOCUS_BENCH_CGAL);
#endif
