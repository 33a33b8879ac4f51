// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a (solid) triangle and a (solid) rectangle in 3D; row dist3.misc
// (triangle-rectangle).
//
// distance(tri, rect) returns Distance<T, 3, Vec3<T>, Vec2<T>>: closest[0] =
// point_at_barycentric(tri, param_a) with param_a barycentric (u, v, w) (point_triangle.hpp), and
// closest[1] = point_at(rect, param_b) with param_b = (s, t) the rectangle's symmetric
// coordinates (|s| <= extent[0], |t| <= extent[1]). distance(rect, tri) is the swapped result.
// Both are filled: pieces that meet have distance 0.
//
// Method (detail/planar_pairs.hpp): the nearest of the seven edge-piece queries (the triangle's
// three edges against the rectangle, segment_rectangle.hpp; the rectangle's four sides against
// the triangle, segment_triangle.hpp): two disjoint convex planar pieces have a closest pair on
// an edge of one of them, and two that meet do so on an edge of one of them. The rectangle's
// decisions are rounded (its corners are not input points); the squared distance is within a
// few eps * scale^2 of the exact one.
// unique = false when the pieces meet in more than one point, or when the closest pair can slide
// (parallel planes over an overlap, parallel nearest edges).
//
// Preconditions and degenerate input: the rectangle's axes are unit and orthogonal (its
// contract, not checked); a zero (or negative) extent gives a segment or point, a degenerate
// triangle the segment or point it spans, continuously. NaN or infinite values give
// non_finite_distance() (result.hpp). Cost: O(1): seven segment-piece queries.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/planar_pairs.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/triangle.hpp>

namespace locus {

/// Distance between a solid triangle and a solid rectangle in 3D; param_a barycentric, param_b
/// = (s, t).
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec3<T>, Vec2<T>> distance(const Triangle3<T>& tri,
                                                               const Rectangle3<T>& rect) noexcept {
  return detail::piece_piece_distance<T>(tri, rect);
}

/// The swapped query: closest[0] and param_a belong to the rectangle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, Vec3<T>> distance(const Rectangle3<T>& rect,
                                                               const Triangle3<T>& tri) noexcept {
  return swapped(distance(tri, rect));
}

}  // namespace locus
