// SPDX-License-Identifier: BSL-1.0
#pragma once
// Minimum-area (or minimum-perimeter) enclosing rectangle of a 2D point set; CAPABILITIES row
// cg.minbox (2D part); book section 13.10.1, figure 13.79 (a purported minimum rectangle with
// no side on a polygon edge, which cannot be minimal).
//
// Algorithm: the exact convex hull (hull/hull2.hpp), then rotating calipers over its edges (a
// minimal rectangle, by area or by perimeter, has a side flush with a hull edge); see
// docs/notes/bounding.md.
// Exactness: the hull and every caliper step are exact, so the extreme vertices found for each
// edge are exact; the areas are computed in double and compared rounded (among edges whose
// areas agree to rounding either may win). Centre, axes and extents are rounded constructions
// (double, then T). Scale-covariant: input scaled by 2^k gives the rectangle scaled by 2^k
// exactly (the calipers' products run on the hull scaled by a power of two when needed).
// Result: status, rectangle (axis[0] along the chosen hull edge, axis[1] = perp(axis[0])
// pointing into the hull: right-handed), area (= 4 extent[0] extent[1] rounded), perimeter,
// edge: the input indices of the flush hull edge (equal for a point).
// Degenerate input: all points equal -> ok, a zero rectangle at the point with the coordinate
// axes; all points collinear -> ok, a rectangle of width 0 along the segment (area 0).
// Empty input -> Status::empty_input; NaN/Inf -> Status::non_finite_input.
// Cost: the hull (O(n log n), expected O(n)) plus O(h); O(n) scratch.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/rectangle.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// What min_rect minimises.
enum class RectCriterion : std::uint8_t { area, perimeter };

/// The minimum enclosing rectangle.
template <Real T>
struct MinRectResult {
  Status status = Status::empty_input;
  Rectangle<T, 2> rectangle{};
  T area = T(0);
  T perimeter = T(0);
  std::array<std::uint32_t, 2>
      edge{};  ///< input indices of the hull edge the rectangle is flush with
};

/// The minimum-area (default) or minimum-perimeter rectangle enclosing `points`.
template <Real T>
[[nodiscard]] MinRectResult<T> min_rect(std::span<const Vec2<T>> points,
                                        RectCriterion criterion = RectCriterion::area);

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] MinRectResult<range_scalar_t<R>> min_rect(
    const R& points, RectCriterion criterion = RectCriterion::area) {
  return min_rect(point_span(points), criterion);
}

namespace detail {

/// The best rectangle over the edges of a strictly convex counter-clockwise polygon (h >= 3).
struct PolygonRect {
  double measure;       ///< area or perimeter
  Vec2<double> center;  ///< rounded
  Vec2<double> axis0;   ///< unit, along the flush edge
  double extent[2];     ///< along axis0 and perp(axis0)
  std::uint32_t edge;   ///< the flush edge is (poly[edge], poly[edge + 1])
};
/// Rotating calipers over `poly` (exact caliper steps, see the header comment).
[[nodiscard]] PolygonRect min_rect_of_convex_polygon(std::span<const Vec2<double>> poly,
                                                     RectCriterion criterion) noexcept;

}  // namespace detail

extern template MinRectResult<float> min_rect<float>(std::span<const Vec2<float>>, RectCriterion);
extern template MinRectResult<double> min_rect<double>(std::span<const Vec2<double>>,
                                                       RectCriterion);

}  // namespace locus
