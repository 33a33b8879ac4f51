// SPDX-License-Identifier: BSL-1.0
// Distance queries per second (rows dist3.pt-triangle, dist3.linear-linear, dist3.pt-obb,
// dist3.linear-triangle): point-triangle, segment-segment (generic and nearly parallel),
// segment-triangle, point-OBB and point-AABB in 3D, float and double, over 4096 random inputs
// cycled so that the data stays in cache. Items per second = queries per second.
//
// Every pair runs the same templated loop (cycle()) with three kinds of query on the same inputs:
//   <pair>/distance<T>      locus::distance: the full result (closest points, parameters, sqrt);
//   <pair>/sqr_distance<T>  locus::sqr_distance: the squared distance only, like CGAL's;
//   <pair>/cgal<Kernel>     the peer on the double inputs (converted once, outside the loop):
//     CGAL::squared_distance with Simple_cartesian<double> (plain floating point, the fair peer)
//     and Exact_predicates_inexact_constructions_kernel (what CGAL users usually take), when
//     CGAL is found (LOCUS_HAVE_CGAL). CGAL 5.5 has no segment-triangle distance: that peer is
//     composed from CGAL's own queries (see cgal_query). It has no point-box distance either
//     (no squared_distance for Iso_cuboid_3, Bbox_3 or an oriented box), so the box pairs run
//     against <pair>/textbook: the plain textbook loop written here (per axis: the coordinate in
//     the box frame, the excess over the slab with if/else, summed squares; no input checks), the
//     code a user would write instead of calling a library.
// CGAL's CMake target adds -frounding-math to this translation unit, locus code included.
//
// Run: locus_bench_distance --benchmark_min_time=0.2 --benchmark_filter='^(point|segment|seg)'

#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/distance/segment_triangle.hpp>

#include <benchmark/benchmark.h>

#if defined(LOCUS_HAVE_CGAL)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace {

constexpr std::size_t kCount = 4096;

// ---- inputs (double; every library gets the same ones) ---------------------------------------

locus::Vec3d rvec(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  const double x = u(rng), y = u(rng), z = u(rng);
  return {x, y, z};
}

struct PointTriangleInput {
  std::vector<locus::Vec3d> p;
  std::vector<locus::Triangle3<double>> t;
};
const PointTriangleInput& point_triangle_input() {
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
const SegmentPairInput& segment_pair_input(bool near_parallel) {
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
const PointObbInput& point_obb_input() {
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
const PointAabbInput& point_aabb_input() {
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
const SegmentTriangleInput& segment_triangle_input() {
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

template <class T>
locus::Vec3<T> cast(const locus::Vec3d& v) {
  return {static_cast<T>(v.x), static_cast<T>(v.y), static_cast<T>(v.z)};
}
template <class T>
locus::Segment3<T> cast(const locus::Segment3<double>& s) {
  return {cast<T>(s.p0), cast<T>(s.p1)};
}
template <class T>
locus::Triangle3<T> cast(const locus::Triangle3<double>& t) {
  return {cast<T>(t.v0), cast<T>(t.v1), cast<T>(t.v2)};
}
template <class T>
locus::OrientedBox3<T> cast(const locus::OrientedBox3<double>& b) {
  return {cast<T>(b.center), {cast<T>(b.axis[0]), cast<T>(b.axis[1]), cast<T>(b.axis[2])},
          cast<T>(b.extent)};
}
template <class T>
locus::AlignedBox3<T> cast(const locus::AlignedBox3<double>& b) {
  return {cast<T>(b.min), cast<T>(b.max)};
}
template <class T, class X>
auto cast_all(const std::vector<X>& v) {
  std::vector<decltype(cast<T>(v[0]))> r;
  for (const X& x : v) r.push_back(cast<T>(x));
  return r;
}

// The pairs: the double inputs (arg: segment-segment nearly parallel when 1).
struct PointTriangle {
  static auto input(const benchmark::State&) {
    const auto& in = point_triangle_input();
    return std::pair{in.p, in.t};
  }
};
struct SegmentSegment {
  static auto input(const benchmark::State& state) {
    const auto& in = segment_pair_input(state.range(0) != 0);
    return std::pair{in.a, in.b};
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
};

struct FullQuery {
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return locus::distance(a, b);
  }
};
struct SqrQuery {
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return locus::sqr_distance(a, b);
  }
};

// locus on the pair's inputs converted to T.
template <class Pair, class T, class Query>
void locus_bench(benchmark::State& state) {
  const auto in = Pair::input(state);
  cycle(state, cast_all<T>(in.first), cast_all<T>(in.second), Query{});
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

// ---- CGAL -------------------------------------------------------------------------------------

#if defined(LOCUS_HAVE_CGAL)
using Simple = CGAL::Simple_cartesian<double>;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

template <class K>
typename K::Point_3 to_cgal(const locus::Vec3d& v) {
  return {v.x, v.y, v.z};
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
  cycle(state, to_cgal_all<K>(in.first), to_cgal_all<K>(in.second), CgalQuery<K>{});
}
#endif

}  // namespace

// Registers <name>/distance<T>, <name>/sqr_distance<T> for float and double, then the peers.
#define LOCUS_BENCH_LOCUS(Pair, name, ...)                                                       \
  BENCHMARK(locus_bench<Pair, float, FullQuery>)->Name(name "/distance<float>") __VA_ARGS__;      \
  BENCHMARK(locus_bench<Pair, double, FullQuery>)->Name(name "/distance<double>") __VA_ARGS__;    \
  BENCHMARK(locus_bench<Pair, float, SqrQuery>)->Name(name "/sqr_distance<float>") __VA_ARGS__;   \
  BENCHMARK(locus_bench<Pair, double, SqrQuery>)->Name(name "/sqr_distance<double>") __VA_ARGS__
#if defined(LOCUS_HAVE_CGAL)
#define LOCUS_BENCH_CGAL(Pair, name, ...)                                                        \
  BENCHMARK(cgal_bench<Pair, Simple>)->Name(name "/cgal<Simple_cartesian>") __VA_ARGS__;         \
  BENCHMARK(cgal_bench<Pair, Epick>)->Name(name "/cgal<Epick>") __VA_ARGS__
#else
#define LOCUS_BENCH_CGAL(Pair, name, ...)
#endif

LOCUS_BENCH_LOCUS(PointTriangle, "point_triangle");
LOCUS_BENCH_CGAL(PointTriangle, "point_triangle");
LOCUS_BENCH_LOCUS(SegmentSegment, "segment_segment", ->ArgName("near_parallel")->Arg(0)->Arg(1));
LOCUS_BENCH_CGAL(SegmentSegment, "segment_segment", ->ArgName("near_parallel")->Arg(0)->Arg(1));
LOCUS_BENCH_LOCUS(SegmentTriangle, "segment_triangle");
LOCUS_BENCH_CGAL(SegmentTriangle, "segment_triangle");
LOCUS_BENCH_LOCUS(PointObb, "point_obb");
BENCHMARK(textbook_bench<PointObb>)->Name("point_obb/textbook<double>");
LOCUS_BENCH_LOCUS(PointAabb, "point_aabb");
BENCHMARK(textbook_bench<PointAabb>)->Name("point_aabb/textbook<double>");
