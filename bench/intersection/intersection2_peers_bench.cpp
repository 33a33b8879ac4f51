// SPDX-License-Identifier: BSL-1.0
// The peers of intersection2_bench.cpp (see there), on the same double inputs
// (intersection2_inputs.hpp), converted once outside the loop, in the same loop (cycle()):
//   <input>/cgal<Epick>: CGAL::intersection of two Segment_2 of Exact_predicates_inexact_
//     constructions_kernel (exact decisions, the point constructed in double); the variant is
//     visited to read the point.
//   <input>/boost: boost::geometry::intersection of two model::segment into a reused vector of
//     points (rounded decisions); convex_polygons/boost: boost::geometry::intersects of two
//     model::polygon (counter-clockwise, closed).
// Before timing, every peer's hit/miss answer is compared with locus's on every input pair
// (outside the loop): counter `disagree` (pairs on which they differ, also printed on stderr) and,
// for segment points, `max_point_diff` (largest |difference|inf of the two points).

#include "intersection/intersection2_inputs.hpp"

#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/segment_segment.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <vector>

#if defined(LOCUS_HAVE_CGAL)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#endif
#if defined(LOCUS_HAVE_BOOST)
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/geometries/segment.hpp>
#endif

namespace {

using namespace locus_bench_int2;

/// locus's answer: the point, or nothing when the segments miss.
std::optional<V> locus_point(const Seg& a, const Seg& b) {
  const auto r = locus::intersection(a, b);
  if (r.kind == locus::Kind::empty) return std::nullopt;
  return r.point[0];
}

/// Prints a disagreement once per benchmark (the function runs several times).
void report(const char* name, std::size_t disagree, std::size_t n) {
  static std::set<std::string> printed;
  if (disagree != 0 && printed.insert(name).second)
    std::fprintf(stderr, "%s: %zu of %zu pairs disagree with locus\n", name, disagree, n);
}

/// Compares a peer's answers (point or nothing; for an overlap, one of its points) with locus's.
template <class Peer>
void check_segments(benchmark::State& state, const char* name, const SegmentPairs& s, Peer peer) {
  std::size_t disagree = 0;
  double max_diff = 0;
  for (std::size_t i = 0; i < s.a.size(); ++i) {
    const std::optional<V> l = locus_point(s.a[i], s.b[i]), p = peer(i);
    if (l.has_value() != p.has_value()) {
      ++disagree;
    } else if (l) {
      max_diff = std::max({max_diff, std::abs(l->x - p->x), std::abs(l->y - p->y)});
    }
  }
  report(name, disagree, s.a.size());
  state.counters["disagree"] = double(disagree);
  state.counters["max_point_diff"] = max_diff;
}

void check_polygons(benchmark::State& state, const char* name, const PolygonPairs& p,
                    const std::vector<bool>& peer) {
  std::size_t disagree = 0;
  for (std::size_t i = 0; i < p.a.size(); ++i)
    disagree += locus::intersects_convex_polygons(p.a[i], p.b[i]) != peer[i];
  report(name, disagree, p.a.size());
  state.counters["disagree"] = double(disagree);
}

#if defined(LOCUS_HAVE_CGAL)
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct CgalSegments {
  std::vector<K::Segment_2> a, b;
};
CgalSegments to_cgal(const SegmentPairs& s) {
  CgalSegments c;
  const auto seg = [](const Seg& x) {
    return K::Segment_2(K::Point_2(x.p0.x, x.p0.y), K::Point_2(x.p1.x, x.p1.y));
  };
  for (std::size_t i = 0; i < s.a.size(); ++i) {
    c.a.push_back(seg(s.a[i]));
    c.b.push_back(seg(s.b[i]));
  }
  return c;
}

/// The point of CGAL's answer (an overlap's source), or nothing.
std::optional<K::Point_2> cgal_point(const K::Segment_2& a, const K::Segment_2& b) {
  const auto r = CGAL::intersection(a, b);
  if (!r) return std::nullopt;
  if (const K::Point_2* p = boost::get<K::Point_2>(&*r)) return *p;
  return boost::get<K::Segment_2>(&*r)->source();
}

void cgal_segments(benchmark::State& state, const char* name, const SegmentPairs& s) {
  const CgalSegments c = to_cgal(s);
  check_segments(state, name, s, [&](std::size_t i) -> std::optional<V> {
    const auto p = cgal_point(c.a[i], c.b[i]);
    if (!p) return std::nullopt;
    return V{p->x(), p->y()};
  });
  cycle(state, kSegmentPairs, [&](std::size_t i) {
    const auto p = cgal_point(c.a[i], c.b[i]);
    return p ? 16.0 + p->x() + p->y() : 0.0;
  });
}

void BM_generic_cgal(benchmark::State& state) {
  cgal_segments(state, "segments_generic/cgal<Epick>", generic_pairs());
}
void BM_near_parallel_cgal(benchmark::State& state) {
  cgal_segments(state, "segments_near_parallel/cgal<Epick>", near_parallel_pairs());
}
BENCHMARK(BM_generic_cgal)->Name("segments_generic/cgal<Epick>");
BENCHMARK(BM_near_parallel_cgal)->Name("segments_near_parallel/cgal<Epick>");
#endif

#if defined(LOCUS_HAVE_BOOST)
namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BSegment = bg::model::segment<BPoint>;
using BPolygon = bg::model::polygon<BPoint, /*ClockWise=*/false, /*Closed=*/true>;

struct BoostSegments {
  std::vector<BSegment> a, b;
};
BoostSegments to_boost(const SegmentPairs& s) {
  BoostSegments c;
  const auto seg = [](const Seg& x) {
    return BSegment(BPoint(x.p0.x, x.p0.y), BPoint(x.p1.x, x.p1.y));
  };
  for (std::size_t i = 0; i < s.a.size(); ++i) {
    c.a.push_back(seg(s.a[i]));
    c.b.push_back(seg(s.b[i]));
  }
  return c;
}

void boost_segments(benchmark::State& state, const char* name, const SegmentPairs& s) {
  const BoostSegments c = to_boost(s);
  std::vector<BPoint> out;
  out.reserve(4);
  check_segments(state, name, s, [&](std::size_t i) -> std::optional<V> {
    out.clear();
    bg::intersection(c.a[i], c.b[i], out);
    if (out.empty()) return std::nullopt;
    return V{out[0].x(), out[0].y()};
  });
  cycle(state, kSegmentPairs, [&](std::size_t i) {
    out.clear();
    bg::intersection(c.a[i], c.b[i], out);
    return out.empty() ? 0.0 : 16.0 + out[0].x() + out[0].y();
  });
}

void BM_generic_boost(benchmark::State& state) {
  boost_segments(state, "segments_generic/boost", generic_pairs());
}
void BM_near_parallel_boost(benchmark::State& state) {
  boost_segments(state, "segments_near_parallel/boost", near_parallel_pairs());
}

void BM_polygons_boost(benchmark::State& state) {
  const PolygonPairs& p = polygon_pairs();
  const auto poly = [](const std::vector<V>& v) {
    BPolygon q;
    for (const V& x : v) bg::append(q.outer(), BPoint(x.x, x.y));
    bg::append(q.outer(), BPoint(v[0].x, v[0].y));
    return q;
  };
  std::vector<BPolygon> a, b;
  std::vector<bool> answer;
  for (std::size_t i = 0; i < p.a.size(); ++i) {
    a.push_back(poly(p.a[i]));
    b.push_back(poly(p.b[i]));
    answer.push_back(bg::intersects(a.back(), b.back()));
  }
  check_polygons(state, "convex_polygons/boost", p, answer);
  cycle(state, kPolygonPairs,
        [&](std::size_t i) { return bg::intersects(a[i], b[i]) ? 1.0 : 0.0; });
}

BENCHMARK(BM_generic_boost)->Name("segments_generic/boost");
BENCHMARK(BM_near_parallel_boost)->Name("segments_near_parallel/boost");
BENCHMARK(BM_polygons_boost)->Name("convex_polygons/boost");
#endif

}  // namespace
