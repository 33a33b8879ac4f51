// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a segment and a polyline or polygon boundary (a closed polyline) in N
// dimensions; row dist2.linear-polyline (3D works too, with less rejection); book section 6.3.3
// (figure 6.22).
//
// distance(segment, poly) returns Distance<T, N, T, T>: closest[0] = point_at(segment, param_a)
// with
//   t in [0, 1], point_at(seg, t) = (1 - t) p0 + t p1;
// closest[1] = point_at(poly, param_b), param_b the vertex parameter in [0, segment_count]
// (primitives/polyline.hpp). distance_to_polyline(segment, vertices, closed) takes any contiguous
// vertex storage (a Polygon2's vertices with closed = true measure to its boundary; the polygon
// is not filled). distance(poly, segment) is the swapped result.
//
// Method (detail/linear_polyline.hpp): the edges are visited in order with the best distance mu
// so far; an edge whose two endpoints lie in one region farther than mu from the segment (beyond a
// face of its mu-grown bounding box; in 2D on one side of the mu-strip around its line, or beyond
// its end caps) is rejected without a solve, the others get the exact linear-linear solve of
// detail/linear.hpp, so the answer equals the brute-force minimum over the edges. unique = false
// when the chosen edge is parallel to the segment with an overlapping range (linear_linear's rule);
// two distinct edges at exactly the same distance are not detected (one is returned).
//
// Degenerate input: A zero-length segment acts as the point p0 (t = 0); zero-length edges act as
// points; a single vertex is a point (param_b = 0). An empty polyline has no points and NaN or
// infinite coordinates have no meaning: both give non_finite_distance() (result.hpp). Cost: O(n)
// with a few comparisons per rejected edge; no allocation.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear_polyline.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/segment.hpp>

#include <span>

namespace locus {

/// Distance from the segment to the chain through `v` (closed: also the edge v[n-1] v[0]); param_b
/// is the vertex parameter.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance_to_polyline(const Segment<T, N>& x,
                                                               std::span<const Vec<T, N>> v,
                                                               bool closed) noexcept {
  return detail::linear_polyline_distance<T, N>(x, v, closed);
}

/// Distance between a segment and a polyline; param_b is the polyline's vertex parameter.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Segment<T, N>& x,
                                                   const Polyline<T, N>& poly) noexcept {
  return detail::linear_polyline_distance<T, N>(x, std::span<const Vec<T, N>>(poly.vertices),
                                                poly.closed);
}

/// The swapped query: closest[0] and param_a belong to the polyline.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Polyline<T, N>& poly,
                                                   const Segment<T, N>& x) noexcept {
  return swapped(distance(x, poly));
}

/// The same for any point range (core/point_range.hpp).
template <PointRange R>
[[nodiscard]] inline Distance<range_scalar_t<R>, range_dimension_v<R>, range_scalar_t<R>,
                              range_scalar_t<R>>
distance_to_polyline(const Segment<range_scalar_t<R>, range_dimension_v<R>>& x, const R& v,
                     bool closed) noexcept {
  return distance_to_polyline(x, point_span(v), closed);
}

}  // namespace locus
