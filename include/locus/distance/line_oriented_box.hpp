// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a line and a solid oriented box in N dimensions (3D OBB; in 2D the box is a
// rectangle); row dist3.linear-obb (and its 2D analogue); book section 10.9.4 (figures
// 10.46-10.52; the zero-component cases of figures 10.48 and 10.49 included).
//
// distance(line, box) returns Distance<T, N, T, Vec<T, N>>: closest[0] = point_at(line, param_a)
// with
//   t in R, point_at(line, t) = origin + t direction;
// closest[1] = the box point nearest to closest[0], param_b = its symmetric box coordinates s in
// [-1, 1]^N (oriented_box.hpp point_at: center + sum s_i extent_i axis_i). distance(box, line) is
// the swapped result. The box is solid: a line meeting it has distance 0.
//
// Method (detail/linear_box.hpp): in the box's frame the squared distance from the line's point
// at t to the box is a convex piecewise quadratic in t; its minimiser is found by walking the
// sorted face-crossing parameters and solving the one linear piece of the derivative that changes
// sign. Direction components that are zero (parallel to a face: figure 10.49; to an edge: figure
// 10.48) or tiny need no special case, so the answer is continuous as a component passes through
// zero. unique = false when the minimisers form an interval (the line passes through the box, or
// runs parallel to a face or edge while its projection meets it); the middle of that interval is
// returned.
//
// Degenerate input: a zero direction acts as the point origin (t = 0). A zero extent flattens the
// box along that axis (a rectangle or segment); a negative extent is treated as 0. NaN or infinite
// values give non_finite_distance() (result.hpp). The axes must be unit and mutually orthogonal
// (the box's contract, not checked). Cost: O(N^2) (at most 2 N + 2 breakpoints, each checked in
// O(N)); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear_box.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/oriented_box.hpp>

namespace locus {

/// Distance between a line and a solid oriented box; param_b is the box coordinates.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, Vec<T, N>> distance(const Line<T, N>& x,
                                                           const OrientedBox<T, N>& box) noexcept {
  return detail::linear_oriented_box_distance(x, box);
}

/// The swapped query: closest[0] and param_a belong to the box.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, Vec<T, N>, T> distance(const OrientedBox<T, N>& box,
                                                           const Line<T, N>& x) noexcept {
  return swapped(distance(x, box));
}

}  // namespace locus
