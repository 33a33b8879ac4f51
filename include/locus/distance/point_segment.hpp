// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a segment in N dimensions (2D and 3D included); rows dist2.pt-linear
// and dist3.pt-linear; book sections 6.1 and 10.2, figures 6.3 and 10.4.
//
// distance(p, segment) returns Distance<T, N, NoParam, T>: closest[0] = p, closest[1] = the point
// of the segment nearest to p, param_b = its parameter (t in [0, 1], point_at(seg, t) = (1 - t) p0
// + t p1). The parameter is the projection t = (p - origin) . d / |d|^2 clamped to the segment's
// range (exact clamp, so an endpoint is reproduced bit for bit); the direction is scaled by its
// largest component first so that |d|^2 cannot underflow or overflow. unique is always true (the
// nearest point of a convex set is unique).
// distance(segment, p) is the swapped result.
//
// Degenerate input: a zero-length segment acts as the point p0 (t = 0). NaN or infinite coordinates
// give non_finite_distance() (distance NaN, unique false; see result.hpp). Cost: O(N), one
// division, one square root.
//
// sqr_distance(p, segment) (either order) returns distance(p, segment).sqr_distance, bit for bit,
// without the closest point, the parameter or the square root; NaN for non-finite input.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/segment.hpp>

namespace locus {

/// Distance from the point p to the segment; param_b is the segment's parameter of the closest
/// point.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, T> distance(const Vec<T, N>& p,
                                                         const Segment<T, N>& x) noexcept {
  return detail::point_linear(p, x);
}

/// The swapped query: closest[0] and param_a belong to the segment.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, NoParam> distance(const Segment<T, N>& x,
                                                         const Vec<T, N>& p) noexcept {
  return swapped(distance(p, x));
}

/// Squared distance from p to the segment: distance(p, x).sqr_distance (the same bits), without
/// the closest point, the parameter or the square root; NaN for non-finite input.
template <Real T, int N>
[[nodiscard]] inline T sqr_distance(const Vec<T, N>& p, const Segment<T, N>& x) noexcept {
  return detail::point_linear_core(p, x).sqr;
}

/// sqr_distance(p, x).
template <Real T, int N>
[[nodiscard]] inline T sqr_distance(const Segment<T, N>& x, const Vec<T, N>& p) noexcept {
  return sqr_distance(p, x);
}

}  // namespace locus
