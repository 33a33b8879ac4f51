// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a line in N dimensions (2D and 3D included); rows dist2.pt-linear
// and dist3.pt-linear; book sections 6.1 and 10.2, figures 6.1 and 10.2.
//
// distance(p, line) returns Distance<T, N, NoParam, T>: closest[0] = p, closest[1] = the point of
// the line nearest to p, param_b = its parameter (t in R, point_at(line, t) = origin + t
// direction). The parameter is the projection t = (p - origin) . d / |d|^2 clamped to the line's
// range (exact clamp, so an endpoint is reproduced bit for bit); the direction is scaled by its
// largest component first so that |d|^2 cannot underflow or overflow. unique is always true (the
// nearest point of a convex set is unique).
// distance(line, p) is the swapped result.
//
// Degenerate input: a zero direction acts as the point origin (t = 0). NaN or infinite coordinates
// give non_finite_distance() (distance NaN, unique false; see result.hpp). Cost: O(N), one
// division, one square root.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

/// Distance from the point p to the line; param_b is the line's parameter of the closest point.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, T> distance(const Vec<T, N>& p,
                                                         const Line<T, N>& x) noexcept {
  return detail::point_linear(p, x);
}

/// The swapped query: closest[0] and param_a belong to the line.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, NoParam> distance(const Line<T, N>& x,
                                                         const Vec<T, N>& p) noexcept {
  return swapped(distance(p, x));
}

}  // namespace locus
