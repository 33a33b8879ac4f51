// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a line with a polygon's boundary (the closed chain of its vertices; the polygon
// is not filled): intersects() and intersection(); row int2.linear-polyline, book section 7.1
// (linear components against polylines and polygons). intersection(line, polygon) returns
// PolylineIntersection2<T> (intersection/result.hpp): status ok, empty_input (no vertices) or
// non_finite_input (a NaN or infinite coordinate; no pieces), and the pieces in order of increasing
// parameter along the line (t in R): a point (a crossing, or a touch) or a segment (an overlap with
// an edge, ends by increasing param_a), each with param_a on the line, param_b the vertex parameter
// on the chain (edge + local t, primitives/polyline.hpp) and its edge index. A vertex met by two
// edges, or a point at the end of an overlap, is reported once (on the lowest-index edge among
// those found at that position); each overlapping edge gives its own segment piece. Exact: which
// edges meet the line, how, and the order along it (compare_crossing_params, core/crossing.hpp);
// points and parameters are rounded as in the linear pairs
// (|point - X|inf <= 6 eps max(|X|inf, m), m the largest |coordinate| of the inputs).
// Degenerate: a zero direction or zero-length segment acts as its point (one piece at most);
// a single vertex acts as a point (edge 0); zero-length edges act as points.
// The swapped overload (Polygon2, Line2) returns swapped(): parameters exchanged, same order.
// Cost: O(n) for the edges, O(k log k) to order k pieces; allocates the result.
// 3D (row int3.linear-polygon, book section 11.3, figure 11.3): a Line3 against the FILLED
// PlanarPolygon3 (closed, even-odd: contains(), containment/point_in_polygon.hpp). intersection()
// -> LinearPlanarIntersection<T> (detail/planar3.hpp): the crossing point, or for a line in the
// plane the segment (or point) from its first to its last common point, which may span gaps;
// intersection_pieces() -> LinearPlanarPieces<T> {status, pieces}: every piece, points and
// segments by increasing param_a, param_b = frame coordinates (s, t). Exact: the side of the
// plane {dot(normal, X - origin) = 0}; a crossing X is rounded, its frame point tested exactly.
// A line in the plane is mapped to st = ((X - origin).u, (X - origin).v) (rounded, within
// 5 eps |X - origin| |u| (|v|), eps = 2^-53; parameters kept); on that image the pieces, their
// kinds and touching points are exact. Status: empty_input (no vertex), non_finite_input,
// degenerate_input (zero normal). Cost O(n log n), allocates. docs/notes/intersection.md.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/linear2.hpp>
#include <locus/intersection/detail/linear_polyline2.hpp>
#include <locus/intersection/detail/planar3.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/planar_polygon.hpp>
#include <locus/primitives/polygon.hpp>

#include <span>

namespace locus {

/// Whether a line meets the polygon boundary (exact; stops at the first edge that does).
template <Real T>
[[nodiscard]] inline bool intersects(const Line2<T>& a, const Polygon2<T>& p) noexcept {
  return detail::linear_polyline2::test<T>(detail::linear2::as_lin(a),
                                           std::span<const Vec2<T>>(p.vertices), true);
}

/// Every piece of the intersection, ordered along a line (see the header comment).
template <Real T>
[[nodiscard]] inline PolylineIntersection2<T> intersection(const Line2<T>& a,
                                                           const Polygon2<T>& p) {
  return detail::linear_polyline2::find<T>(detail::linear2::as_lin(a),
                                           std::span<const Vec2<T>>(p.vertices), true);
}

/// Swapped arguments: intersects(a, p).
template <Real T>
[[nodiscard]] inline bool intersects(const Polygon2<T>& p, const Line2<T>& a) noexcept {
  return intersects(a, p);
}

/// Swapped arguments: swapped(intersection(a, p)) (same order, parameters exchanged).
template <Real T>
[[nodiscard]] inline PolylineIntersection2<T> intersection(const Polygon2<T>& p,
                                                           const Line2<T>& a) {
  return swapped(intersection(a, p));
}

/// Whether a line meets the filled planar polygon (3D; see the header comment).
template <Real T>
[[nodiscard]] inline bool intersects(const Line3<T>& a, const PlanarPolygon3<T>& p) noexcept {
  return detail::planar3::polygon<false>(detail::linear3::as_lin(a), p).kind != Kind::empty;
}

/// The common set of a line and the filled planar polygon (3D; see the header comment).
template <Real T>
[[nodiscard]] inline LinearPlanarIntersection<T> intersection(const Line3<T>& a,
                                                              const PlanarPolygon3<T>& p) noexcept {
  return intersection_cast<T>(detail::planar3::polygon<true>(detail::linear3::as_lin(a), p));
}

/// Swapped arguments (3D): intersects(a, p).
template <Real T>
[[nodiscard]] inline bool intersects(const PlanarPolygon3<T>& p, const Line3<T>& a) noexcept {
  return intersects(a, p);
}

/// Swapped arguments (3D): swapped(intersection(a, p)).
template <Real T>
[[nodiscard]] inline Intersection<T, 3, Vec2<T>, T, 2> intersection(const PlanarPolygon3<T>& p,
                                                                    const Line3<T>& a) noexcept {
  return swapped(intersection(a, p));
}

/// Every piece of the common set of a line and the filled planar polygon, in order along the
/// line (3D; see the header comment).
template <Real T>
[[nodiscard]] inline LinearPlanarPieces<T> intersection_pieces(const Line3<T>& a,
                                                               const PlanarPolygon3<T>& p) {
  return detail::planar3::polygon_pieces<T>(detail::linear3::as_lin(a), p);
}

/// Swapped arguments (3D): swapped(intersection_pieces(a, p)).
template <Real T>
[[nodiscard]] inline IntersectionPieces<Intersection<T, 3, Vec2<T>, T, 2>> intersection_pieces(
    const PlanarPolygon3<T>& p, const Line3<T>& a) {
  return swapped(intersection_pieces(a, p));
}

}  // namespace locus
