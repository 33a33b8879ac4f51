// SPDX-License-Identifier: BSL-1.0
#pragma once
// Polygon offsetting (inflate / deflate) and polyline buffering (row cg.offset; beyond the book).
// offset(region, delta): the region is a Polygon2, PolygonWithHoles2 or MultiPolygon2 read as
// boolean_union reads it (any orientation, positive winding inside), first resolved into a valid
// multipolygon by the boolean engine. delta > 0 inflates (every boundary pushed outward, holes
// shrink and close), delta < 0 deflates (holes grow, parts thinner than 2|delta| vanish).
// offset_polyline(path, delta): the set within |delta| of an open path (end caps) or of a closed
// one (joins at every vertex, no caps); the sign of delta is ignored.
// Joins, at the convex corners of the offset side (turning angle a in (0, pi]):
//   round: the arc of radius |delta| by chords with vertices on the circle, as few as keep the
//     chord-to-arc gap <= arc_tolerance (0: |delta| / 1000; clamped to [|delta| 2^-20, |delta|]):
//     with round joins and caps the result R satisfies  S (+) disk(|delta| - tol) within R within
//     S (+) disk(|delta|)  (inflate; deflate: S (-) disk(|delta|) within R within
//     S (-) disk(|delta| - tol)), up to rounding below.
//   miter: the offset edges extended to meet, when the miter point is at most miter_limit |delta|
//     from the corner (miter_limit >= 1, default 2); beyond it the square join.
//   square: cut perpendicular to the corner's bisector at distance |delta| from the corner.
// End types (open paths): round (half disc), square (extended by |delta|), butt (flat).
// Result: the region united with (deflate: minus) a band of width |delta| on the offset side of
// every edge (paths: both sides) and a join at every convex corner, as one raw contour per ring
// resolved by boolean_op under the positive fill rule (docs/notes/polygon_offset.md); output
// valid as boolean output is (outer rings counter-clockwise, holes clockwise).
// Degenerate: delta 0 returns the resolved region (empty for a polyline); empty input or a
// region that vanishes returns no polygons, status ok; zero-length edges, repeated points and
// collinear runs are dropped; a single-point path gives a disc (round), a square (square cap)
// or nothing (butt). Status: non_finite_input (NaN/Inf coordinate or delta, or an offset
// coordinate overflows), invalid_input (miter_limit < 1 or NaN, arc_tolerance < 0 or NaN,
// grid_bits outside the boolean's range). Cost: O(n m) contour edges (m chords per round join),
// then one boolean (two for a region); concave spokes covered by both bands are dropped (exact
// test), so dense input is slow only where |delta| exceeds its curvature radius (see the notes).

#include <locus/boolean/polygon_boolean.hpp>
#include <locus/primitives/polyline.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace locus {

enum class JoinType : std::uint8_t { round, miter, square };
enum class EndType : std::uint8_t { round, square, butt };

struct OffsetOptions {
  JoinType join = JoinType::round;
  EndType end = EndType::round;  ///< open polylines only
  double miter_limit = 2.0;      ///< largest miter length over |delta| (>= 1)
  double arc_tolerance = 0.0;    ///< largest chord-to-arc gap; 0: |delta| / 1000
  int grid_bits = 0;             ///< snap-rounding grid of the boolean engine (0: its default)
};

/// The output of offset(): valid multipolygon, status, the boolean's grid spacing.
template <Real T>
using OffsetResult = BooleanResult<T>;

/// The region inflated (delta > 0) or deflated (delta < 0) by |delta|.
template <Real T>
[[nodiscard]] OffsetResult<T> offset(const MultiPolygon2<T>& region, T delta,
                                     const OffsetOptions& options = {});
template <Real T>
[[nodiscard]] inline OffsetResult<T> offset(const PolygonWithHoles2<T>& region, T delta,
                                            const OffsetOptions& options = {}) {
  return offset(to_multipolygon(region), delta, options);
}
template <Real T>
[[nodiscard]] inline OffsetResult<T> offset(const Polygon2<T>& region, T delta,
                                            const OffsetOptions& options = {}) {
  return offset(to_multipolygon(region), delta, options);
}

/// The union of the buffers of |delta| around the paths (each open or closed).
template <Real T>
[[nodiscard]] OffsetResult<T> offset_polylines(std::span<const Polyline<T, 2>> paths, T delta,
                                               const OffsetOptions& options = {});
template <Real T>
[[nodiscard]] inline OffsetResult<T> offset_polyline(const Polyline<T, 2>& path, T delta,
                                                     const OffsetOptions& options = {}) {
  return offset_polylines(std::span<const Polyline<T, 2>>(&path, 1), delta, options);
}
template <Real T>
[[nodiscard]] inline OffsetResult<T> offset_polylines(const std::vector<Polyline<T, 2>>& paths,
                                                      T delta, const OffsetOptions& options = {}) {
  return offset_polylines(std::span<const Polyline<T, 2>>(paths), delta, options);
}

namespace detail {
/// offset() and offset_polylines() with every concave corner's spoke p1 -> v -> p2 kept (the
/// construction before the spoke shortcut of docs/notes/polygon_offset.md): the tests' oracle.
template <Real T>
[[nodiscard]] OffsetResult<T> offset_keeping_spokes(const MultiPolygon2<T>& region, T delta,
                                                    const OffsetOptions& options);
template <Real T>
[[nodiscard]] OffsetResult<T> offset_polylines_keeping_spokes(std::span<const Polyline<T, 2>> paths,
                                                              T delta,
                                                              const OffsetOptions& options);
}  // namespace detail

}  // namespace locus
