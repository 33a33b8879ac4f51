// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a line and a (solid) rectangle in 3D; row dist3.linear-rectangle; book section
// 10.5.2 (figures 10.42, 10.43).
//
// distance(line, rect) returns Distance<T, 3, T, Vec2<T>>: closest[0] = point_at(line, t) with
//   t = param_a in R, point_at(line, t) = origin + t direction (direction need not be unit),
// and closest[1] = point_at(rect, param_b) with param_b = (s, t) the rectangle's symmetric
//   coordinates (|s| <= extent[0], |t| <= extent[1]; primitives/rectangle.hpp).
// distance(rect, line) is the swapped result. The rectangle is filled: a line passing through it
// has distance 0.
//
// Method: detail/linear_planar.hpp (docs/notes/distance.md): the crossing with the plane when
// it lies in the prism, else the facets its parameters violate (KKT, the regions of figure
// 10.43); nearly parallel or rounding-sensitive cases evaluate every candidate, so the answer
// is continuous through parallel configurations and never divides by a vanishing determinant.
//
// unique = false when the line is parallel to the rectangle's plane (sin^2 angle <= 64 eps^2) and
// the closest pair can slide along it (above the interior, or along the nearest side).
// Preconditions and degenerate input: the axes are unit and orthogonal (the rectangle's contract,
// not checked). A zero extent gives a segment or a point (continuously; a negative extent is
// treated as 0); a zero direction acts as the point origin (t = 0). NaN or infinite values give
// non_finite_distance() (result.hpp). Decisions are rounded (the rectangle's corners are not
// input points, so no exact predicate applies); the squared distance is within a few
// eps * scale^2 of the exact one. Cost: O(1): a change of frame, one division and one to three
// point-rectangle / linear-segment queries in the generic case, at most 6 in the nearly
// parallel case.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear_planar.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/rectangle.hpp>

namespace locus {

/// Distance between a line and a solid rectangle; param_a = t in R, param_b = (s, t).
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> distance(const Line3<T>& line,
                                                         const Rectangle3<T>& rect) noexcept {
  return detail::linear_rectangle_distance<T>(line, rect);
}

/// The swapped query: closest[0] and param_a belong to the rectangle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, T> distance(const Rectangle3<T>& rect,
                                                         const Line3<T>& line) noexcept {
  return swapped(distance(line, rect));
}

}  // namespace locus
