// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between two (solid) rectangles in 3D; row dist3.misc (rectangle-rectangle).
//
// distance(a, b) returns Distance<T, 3, Vec2<T>, Vec2<T>>: closest[0] = point_at(a, param_a),
// closest[1] = point_at(b, param_b), both parameters the rectangles' symmetric coordinates
// (s, t), |s| <= extent[0], |t| <= extent[1] (primitives/rectangle.hpp). Both are filled:
// rectangles that meet have distance 0.
//
// Method (detail/planar_pairs.hpp): the nearest of the eight side-rectangle queries (each side
// of a against b and each side of b against a; segment_rectangle.hpp): two disjoint convex
// planar pieces have a closest pair on an edge of one of them, and two that meet do so on an
// edge of one of them. Decisions are rounded (the corners are not input points); the squared
// distance is within a few eps * scale^2 of the exact one.
// unique = false when the rectangles meet in more than one point, or when the closest pair can
// slide (parallel planes over an overlap, parallel nearest sides). The pair is solved in a
// canonical (lexicographic) order, so distance(b, a) is bit for bit the swap of distance(a, b).
//
// Preconditions and degenerate input: the axes are unit and orthogonal (the rectangles'
// contract, not checked); a zero (or negative) extent gives a segment or point, continuously.
// NaN or infinite values give non_finite_distance() (result.hpp). Cost: O(1): eight
// segment-rectangle queries.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/planar_pairs.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/rectangle.hpp>

namespace locus {

/// Distance between two solid rectangles in 3D; both parameters (s, t).
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, Vec2<T>> distance(const Rectangle3<T>& a,
                                                               const Rectangle3<T>& b) noexcept {
  return detail::same_piece_distance<T>(a, b);
}

}  // namespace locus
