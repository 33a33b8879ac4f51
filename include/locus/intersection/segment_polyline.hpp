// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a segment with an open or closed polyline: intersects() and intersection(); row
// int2.linear-polyline, book section 7.1 (linear components against polylines and polygons).
// intersection(segment, polyline) returns PolylineIntersection2<T> (intersection/result.hpp):
// status ok, empty_input (no vertices) or non_finite_input (a NaN or infinite coordinate; no
// pieces), and the pieces in order of increasing parameter along the segment (t in [0, 1]): a point
// (a crossing, or a touch) or a segment (an overlap with an edge, ends by increasing param_a), each
// with param_a on the segment, param_b the vertex parameter on the chain (edge + local t,
// primitives/polyline.hpp) and its edge index. A vertex met by two edges, or a point at the end
// of an overlap, is reported once (on the lowest-index edge among those found at that position);
// each overlapping edge gives its own segment piece.
// Exact: which edges meet the segment, how, and the order along it (compare_crossing_params,
// core/crossing.hpp); points and parameters are rounded as in the linear pairs
// (|point - X|inf <= 6 eps max(|X|inf, m), m the largest |coordinate| of the inputs).
// Degenerate: a zero direction or zero-length segment acts as its point (one piece at most);
// a single vertex acts as a point (edge 0); zero-length edges act as points.
// The swapped overload (Polyline2, Segment2) returns swapped(): parameters exchanged, same order.
// Cost: O(n) for the edges, O(k log k) to order k pieces; allocates the result.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/linear2.hpp>
#include <locus/intersection/detail/linear_polyline2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/segment.hpp>

#include <span>

namespace locus {

/// Whether a segment meets the polyline (exact; stops at the first edge that does).
template <Real T>
[[nodiscard]] inline bool intersects(const Segment2<T>& a, const Polyline2<T>& p) noexcept {
  return detail::linear_polyline2::test<T>(detail::linear2::as_lin(a),
                                           std::span<const Vec2<T>>(p.vertices), p.closed);
}

/// Every piece of the intersection, ordered along a segment (see the header comment).
template <Real T>
[[nodiscard]] inline PolylineIntersection2<T> intersection(const Segment2<T>& a,
                                                           const Polyline2<T>& p) {
  return detail::linear_polyline2::find<T>(detail::linear2::as_lin(a),
                                           std::span<const Vec2<T>>(p.vertices), p.closed);
}

/// The chain through `vertices` (closed: also the edge v[n-1] v[0]); see the header comment.
template <Real T>
[[nodiscard]] inline PolylineIntersection2<T> intersection(const Segment2<T>& a,
                                                           std::span<const Vec2<T>> vertices,
                                                           bool closed) {
  return detail::linear_polyline2::find<T>(detail::linear2::as_lin(a), vertices, closed);
}
template <PointRange2 R>
[[nodiscard]] inline PolylineIntersection2<range_scalar_t<R>> intersection(
    const Segment2<range_scalar_t<R>>& a, const R& vertices, bool closed) {
  return intersection(a, point_span(vertices), closed);
}

/// Swapped arguments: intersects(a, p).
template <Real T>
[[nodiscard]] inline bool intersects(const Polyline2<T>& p, const Segment2<T>& a) noexcept {
  return intersects(a, p);
}

/// Swapped arguments: swapped(intersection(a, p)) (same order, parameters exchanged).
template <Real T>
[[nodiscard]] inline PolylineIntersection2<T> intersection(const Polyline2<T>& p,
                                                           const Segment2<T>& a) {
  return swapped(intersection(a, p));
}

}  // namespace locus
