// SPDX-License-Identifier: BSL-1.0
#pragma once
// The inputs and the timing loop shared by distance_bench.cpp (locus and the textbook loops) and
// distance_peers_bench.cpp (CGAL): the same seeded random inputs (double), generated identically
// in each translation unit, and one loop, cycle(), for every query. The two files are separate
// translation units so that locus is compiled with the flags a locus user has, not with the
// -frounding-math that CGAL's CMake target adds to each source that includes CGAL.

#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace locus_bench_distance {

constexpr std::size_t kCount = 4096;

// ---- inputs (double; every library gets the same ones) ---------------------------------------

inline locus::Vec3d rvec(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  const double x = u(rng), y = u(rng), z = u(rng);
  return {x, y, z};
}

struct PointTriangleInput {
  std::vector<locus::Vec3d> p;
  std::vector<locus::Triangle3<double>> t;
};
inline const PointTriangleInput& point_triangle_input() {
  static const PointTriangleInput in = [] {
    PointTriangleInput r;
    std::mt19937_64 rng(1);
    for (std::size_t i = 0; i < kCount; ++i) {
      r.p.push_back(rvec(rng, -2, 2));
      const auto a = rvec(rng, -1, 1), b = rvec(rng, -1, 1), c = rvec(rng, -1, 1);
      r.t.push_back({a, b, c});
    }
    return r;
  }();
  return in;
}

struct SegmentPairInput {
  std::vector<locus::Segment3<double>> a, b;
};
inline const SegmentPairInput& segment_pair_input(bool near_parallel) {
  static const auto make = [](bool np) {
    SegmentPairInput r;
    std::mt19937_64 rng(2);
    for (std::size_t i = 0; i < kCount; ++i) {
      const auto p0 = rvec(rng, -1, 1), p1 = rvec(rng, -1, 1);
      r.a.push_back({p0, p1});
      if (np) {
        const auto off = rvec(rng, -1, 1);
        const auto jitter = rvec(rng, -1e-6, 1e-6);
        r.b.push_back({p0 + off, p1 + off + jitter});
      } else {
        const auto q0 = rvec(rng, -1, 1), q1 = rvec(rng, -1, 1);
        r.b.push_back({q0, q1});
      }
    }
    return r;
  };
  static const SegmentPairInput generic = make(false), parallel = make(true);
  return near_parallel ? parallel : generic;
}

struct PointObbInput {
  std::vector<locus::Vec3d> p;
  std::vector<locus::OrientedBox3<double>> box;
};
inline const PointObbInput& point_obb_input() {
  static const PointObbInput in = [] {
    PointObbInput r;
    std::mt19937_64 rng(3);
    for (std::size_t i = 0; i < kCount; ++i) {
      r.p.push_back(rvec(rng, -3, 3));
      // A random rotation by Gram-Schmidt.
      const auto x = locus::normalize(rvec(rng, -1, 1));
      const auto y = locus::normalize(locus::cross(x, rvec(rng, -1, 1)));
      const auto z = locus::cross(x, y);
      const auto c = rvec(rng, -1, 1);
      const auto e = rvec(rng, 0.1, 1);
      r.box.push_back({c, {x, y, z}, e});
    }
    return r;
  }();
  return in;
}

struct PointAabbInput {
  std::vector<locus::Vec3d> p;
  std::vector<locus::AlignedBox3<double>> box;
};
inline const PointAabbInput& point_aabb_input() {
  static const PointAabbInput in = [] {
    PointAabbInput r;
    std::mt19937_64 rng(4);
    for (std::size_t i = 0; i < kCount; ++i) {
      r.p.push_back(rvec(rng, -3, 3));
      const auto c = rvec(rng, -1, 1), e = rvec(rng, 0.1, 1);
      r.box.push_back({c - e, c + e});
    }
    return r;
  }();
  return in;
}

struct SegmentTriangleInput {
  std::vector<locus::Segment3<double>> s;
  std::vector<locus::Triangle3<double>> t;
};
inline const SegmentTriangleInput& segment_triangle_input() {
  static const SegmentTriangleInput in = [] {
    SegmentTriangleInput r;
    std::mt19937_64 rng(5);
    for (std::size_t i = 0; i < kCount; ++i) {
      const auto p0 = rvec(rng, -1.5, 1.5), p1 = rvec(rng, -1.5, 1.5);
      r.s.push_back({p0, p1});
      const auto a = rvec(rng, -1, 1), b = rvec(rng, -1, 1), c = rvec(rng, -1, 1);
      r.t.push_back({a, b, c});
    }
    return r;
  }();
  return in;
}

// ---- one loop for every query -------------------------------------------------------------

// The two locus query forms a loop can time (found by argument-dependent lookup, so that this
// header needs no distance header of its own).
struct FullQuery {  // distance(a, b): closest points, parameters, square root
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return distance(a, b);
  }
};
struct SqrQuery {  // sqr_distance(a, b): the squared distance only
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return sqr_distance(a, b);
  }
};

// The exact squared distances of a pair's inputs after conversion to float (single) or as
// they are (double), rounded to double: CGAL's queries over exact rationals (Gmpq), computed once
// on first use in distance_accuracy_bench.cpp. Empty when CGAL is absent.
enum ExactPair { kExactPointTriangle, kExactSegmentSegment, kExactSegmentTriangle };
const std::vector<double>& exact_sqr_distances(ExactPair pair, bool near_parallel, bool single);

// The pairs CGAL has (and so an exact oracle), as benchmarks: M(Pair, name, args) for each, with
// args the registration's extra arguments (segment-segment: near_parallel 0 and 1).
#define LOCUS_FOR_CGAL_PAIRS(M)                                                     \
  M(PointTriangle, "point_triangle", );                                             \
  M(SegmentSegment, "segment_segment", ->ArgName("near_parallel")->Arg(0)->Arg(1)); \
  M(SegmentTriangle, "segment_triangle", )

// Registers the function (the variadic part: a template-id may hold commas) as the accuracy run
// <name>/max_err/<label>, run once (report_error).
#define LOCUS_ACCURACY_RUN(name, label, args, ...) \
  BENCHMARK(__VA_ARGS__)->Name(name "/max_err/" label)->Iterations(1) args

// Runs query(a[i], b[i]) over the cycled inputs; items per second = queries per second.
template <class A, class B, class Query>
void cycle(benchmark::State& state, const std::vector<A>& a, const std::vector<B>& b, Query query) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(query(a[i], b[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

// The accuracy beside the speed: one pass over the inputs (no timing; registered as separate
// benchmarks <pair>/max_err/..., run once) that sets the counter max_err, the largest absolute
// error of the squared distance against exact_sqr_distances. Kept out of the timed benchmarks:
// the exact values take GMP's allocations and a second call of the query in the same function
// changes how it is inlined into the timed loop.
// query returns the squared distance as a floating-point type (locus's sqr_distance, the
// Simple_cartesian kernels' FT).
template <class A, class B, class Query>
void report_error(benchmark::State& state, const std::vector<A>& a, const std::vector<B>& b,
                  Query query, const std::vector<double>& exact) {
  for (auto _ : state) {
    if (exact.size() != a.size()) {
      state.SkipWithError("no exact oracle (CGAL not found)");
      break;
    }
    double err = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
      err = std::max(err, std::fabs(static_cast<double>(query(a[k], b[k])) - exact[k]));
    state.counters["max_err"] = err;
  }
}

template <class T, class S>
locus::Vec3<T> cast(const locus::Vec3<S>& v) {
  return {static_cast<T>(v.x), static_cast<T>(v.y), static_cast<T>(v.z)};
}
template <class T, class S>
locus::Segment3<T> cast(const locus::Segment3<S>& s) {
  return {cast<T>(s.p0), cast<T>(s.p1)};
}
template <class T, class S>
locus::Triangle3<T> cast(const locus::Triangle3<S>& t) {
  return {cast<T>(t.v0), cast<T>(t.v1), cast<T>(t.v2)};
}
template <class T, class S>
locus::OrientedBox3<T> cast(const locus::OrientedBox3<S>& b) {
  return {cast<T>(b.center),
          {cast<T>(b.axis[0]), cast<T>(b.axis[1]), cast<T>(b.axis[2])},
          cast<T>(b.extent)};
}
template <class T, class S>
locus::AlignedBox3<T> cast(const locus::AlignedBox3<S>& b) {
  return {cast<T>(b.min), cast<T>(b.max)};
}
template <class T, class X>
auto cast_all(const std::vector<X>& v) {
  std::vector<decltype(cast<T>(v[0]))> r;
  for (const X& x : v) r.push_back(cast<T>(x));
  return r;
}

// The pairs: the double inputs (arg: segment-segment nearly parallel when 1).
// exact(state, single): exact_sqr_distances of the inputs, for the pairs CGAL has.
struct PointTriangle {
  static auto input(const benchmark::State&) {
    const auto& in = point_triangle_input();
    return std::pair{in.p, in.t};
  }
  static const std::vector<double>& exact(const benchmark::State&, bool single) {
    return exact_sqr_distances(kExactPointTriangle, false, single);
  }
};
struct SegmentSegment {
  static auto input(const benchmark::State& state) {
    const auto& in = segment_pair_input(state.range(0) != 0);
    return std::pair{in.a, in.b};
  }
  static const std::vector<double>& exact(const benchmark::State& state, bool single) {
    return exact_sqr_distances(kExactSegmentSegment, state.range(0) != 0, single);
  }
};
struct PointObb {
  static auto input(const benchmark::State&) {
    const auto& in = point_obb_input();
    return std::pair{in.p, in.box};
  }
};
struct PointAabb {
  static auto input(const benchmark::State&) {
    const auto& in = point_aabb_input();
    return std::pair{in.p, in.box};
  }
};
struct SegmentTriangle {
  static auto input(const benchmark::State&) {
    const auto& in = segment_triangle_input();
    return std::pair{in.s, in.t};
  }
  static const std::vector<double>& exact(const benchmark::State&, bool single) {
    return exact_sqr_distances(kExactSegmentTriangle, false, single);
  }
};

}  // namespace locus_bench_distance
