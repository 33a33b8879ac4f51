// SPDX-License-Identifier: BSL-1.0
// Distance queries per second (rows dist3.pt-triangle, dist3.linear-linear, dist3.pt-obb,
// dist3.linear-triangle): point-triangle, segment-segment (generic and nearly parallel),
// segment-triangle, point-OBB and point-AABB in 3D, float and double, over 4096 random inputs
// cycled so that the data stays in cache. Items per second = queries per second.
//
// Peers (when CGAL is found, LOCUS_HAVE_CGAL): CGAL::squared_distance on the SAME inputs (the
// double inputs converted to CGAL objects once, outside the timed loop), with two kernels:
// Simple_cartesian<double> (plain floating point, the fair peer) and
// Exact_predicates_inexact_constructions_kernel (what CGAL users usually take). CGAL returns
// only the squared distance while locus also returns both closest points and their parameters.
// CGAL (5.5) has no point-box distance at all: neither an oriented box nor Iso_cuboid_3 /
// Bbox_3 has a squared_distance overload, so the box queries run for locus alone; and no
// segment-triangle distance: that peer is composed from CGAL's own queries (see below). CGAL's
// CMake target adds -frounding-math to this translation unit, locus code included.
//
// Run: locus_bench_distance --benchmark_min_time=0.2
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

// ---- locus ------------------------------------------------------------------------------------

template <class T>
locus::Vec3<T> cast(const locus::Vec3d& v) {
  return {static_cast<T>(v.x), static_cast<T>(v.y), static_cast<T>(v.z)};
}

template <class T>
void point_triangle(benchmark::State& state) {
  const auto& in = point_triangle_input();
  std::vector<locus::Vec3<T>> p;
  std::vector<locus::Triangle3<T>> t;
  for (std::size_t i = 0; i < kCount; ++i) {
    p.push_back(cast<T>(in.p[i]));
    t.push_back({cast<T>(in.t[i].v0), cast<T>(in.t[i].v1), cast<T>(in.t[i].v2)});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locus::distance(p[i], t[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <class T>
void segment_segment(benchmark::State& state) {
  const auto& in = segment_pair_input(state.range(0) != 0);
  std::vector<locus::Segment3<T>> a, b;
  for (std::size_t i = 0; i < kCount; ++i) {
    a.push_back({cast<T>(in.a[i].p0), cast<T>(in.a[i].p1)});
    b.push_back({cast<T>(in.b[i].p0), cast<T>(in.b[i].p1)});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locus::distance(a[i], b[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <class T>
void point_obb(benchmark::State& state) {
  const auto& in = point_obb_input();
  std::vector<locus::Vec3<T>> p;
  std::vector<locus::OrientedBox3<T>> box;
  for (std::size_t i = 0; i < kCount; ++i) {
    const auto& b = in.box[i];
    p.push_back(cast<T>(in.p[i]));
    box.push_back({cast<T>(b.center),
                   {cast<T>(b.axis[0]), cast<T>(b.axis[1]), cast<T>(b.axis[2])},
                   cast<T>(b.extent)});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locus::distance(p[i], box[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <class T>
void point_aabb(benchmark::State& state) {
  const auto& in = point_aabb_input();
  std::vector<locus::Vec3<T>> p;
  std::vector<locus::AlignedBox3<T>> box;
  for (std::size_t i = 0; i < kCount; ++i) {
    p.push_back(cast<T>(in.p[i]));
    box.push_back({cast<T>(in.box[i].min), cast<T>(in.box[i].max)});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locus::distance(p[i], box[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <class T>
void seg_triangle(benchmark::State& state) {
  const auto& in = segment_triangle_input();
  std::vector<locus::Segment3<T>> s;
  std::vector<locus::Triangle3<T>> t;
  for (std::size_t i = 0; i < kCount; ++i) {
    s.push_back({cast<T>(in.s[i].p0), cast<T>(in.s[i].p1)});
    t.push_back({cast<T>(in.t[i].v0), cast<T>(in.t[i].v1), cast<T>(in.t[i].v2)});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locus::distance(s[i], t[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

// ---- CGAL -------------------------------------------------------------------------------------

#if defined(LOCUS_HAVE_CGAL)
using Simple = CGAL::Simple_cartesian<double>;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

template <class K>
typename K::Point_3 cgal_point(const locus::Vec3d& v) {
  return {v.x, v.y, v.z};
}

// Runs CGAL::squared_distance(a[i], b[i]) over the cycled inputs.
template <class A, class B>
void cgal_loop(benchmark::State& state, const std::vector<A>& a, const std::vector<B>& b) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(CGAL::squared_distance(a[i], b[i]));
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <class K>
void cgal_point_triangle(benchmark::State& state) {
  const auto& in = point_triangle_input();
  std::vector<typename K::Point_3> p;
  std::vector<typename K::Triangle_3> t;
  for (std::size_t i = 0; i < kCount; ++i) {
    p.push_back(cgal_point<K>(in.p[i]));
    t.emplace_back(cgal_point<K>(in.t[i].v0), cgal_point<K>(in.t[i].v1),
                   cgal_point<K>(in.t[i].v2));
  }
  cgal_loop(state, p, t);
}

template <class K>
void cgal_segment_segment(benchmark::State& state) {
  const auto& in = segment_pair_input(state.range(0) != 0);
  std::vector<typename K::Segment_3> a, b;
  for (std::size_t i = 0; i < kCount; ++i) {
    a.emplace_back(cgal_point<K>(in.a[i].p0), cgal_point<K>(in.a[i].p1));
    b.emplace_back(cgal_point<K>(in.b[i].p0), cgal_point<K>(in.b[i].p1));
  }
  cgal_loop(state, a, b);
}

// CGAL 5.5 has no Segment_3 / Triangle_3 squared_distance (it arrived in CGAL 6): the peer is
// the usual composition from CGAL's own queries: 0 when do_intersect(segment, triangle),
// otherwise the minimum over the two end points to the triangle and the segment to the three
// edges (the closest pair of disjoint convex sets has a point on a boundary feature).
template <class K>
void cgal_seg_triangle(benchmark::State& state) {
  const auto& in = segment_triangle_input();
  std::vector<typename K::Segment_3> s;
  std::vector<typename K::Triangle_3> t;
  for (std::size_t i = 0; i < kCount; ++i) {
    s.emplace_back(cgal_point<K>(in.s[i].p0), cgal_point<K>(in.s[i].p1));
    t.emplace_back(cgal_point<K>(in.t[i].v0), cgal_point<K>(in.t[i].v1), cgal_point<K>(in.t[i].v2));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& seg = s[i];
    const auto& tri = t[i];
    double d = 0;
    if (!CGAL::do_intersect(seg, tri)) {
      d = CGAL::squared_distance(seg.source(), tri);
      d = std::min(d, CGAL::squared_distance(seg.target(), tri));
      for (int e = 0; e < 3; ++e)
        d = std::min(d, CGAL::squared_distance(
                            seg, typename K::Segment_3(tri.vertex(e), tri.vertex((e + 1) % 3))));
    }
    benchmark::DoNotOptimize(d);
    i = (i + 1) & (kCount - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
#endif

}  // namespace

BENCHMARK(point_triangle<float>);
BENCHMARK(point_triangle<double>);
#if defined(LOCUS_HAVE_CGAL)
BENCHMARK(cgal_point_triangle<Simple>)->Name("cgal_point_triangle<Simple_cartesian>");
BENCHMARK(cgal_point_triangle<Epick>)->Name("cgal_point_triangle<Epick>");
#endif
BENCHMARK(segment_segment<float>)->Arg(0)->Arg(1);
BENCHMARK(segment_segment<double>)->Arg(0)->Arg(1);
#if defined(LOCUS_HAVE_CGAL)
BENCHMARK(cgal_segment_segment<Simple>)->Name("cgal_segment_segment<Simple_cartesian>")->Arg(0)->Arg(1);
BENCHMARK(cgal_segment_segment<Epick>)->Name("cgal_segment_segment<Epick>")->Arg(0)->Arg(1);
#endif
BENCHMARK(point_obb<float>);
BENCHMARK(point_obb<double>);
BENCHMARK(seg_triangle<float>);
BENCHMARK(seg_triangle<double>);
#if defined(LOCUS_HAVE_CGAL)
BENCHMARK(cgal_seg_triangle<Simple>)->Name("cgal_seg_triangle<Simple_cartesian> (composed)");
BENCHMARK(cgal_seg_triangle<Epick>)->Name("cgal_seg_triangle<Epick> (composed)");
#endif
BENCHMARK(point_aabb<float>);
BENCHMARK(point_aabb<double>);
