// SPDX-License-Identifier: BSL-1.0
#pragma once
// The CGAL side of the distance benchmarks, shared by distance_peers_bench.cpp (the timed peers)
// and distance_accuracy_bench.cpp (the exact oracle and the accuracy runs): the kernels, the
// conversion of the double inputs, and the query (CGAL::squared_distance, or its composition
// for segment-triangle). Include only when LOCUS_HAVE_CGAL.

#include "distance/distance_inputs.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <vector>

namespace locus_bench_distance {

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

}  // namespace locus_bench_distance
