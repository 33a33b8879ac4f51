// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between two segments in N dimensions (2D and 3D included); rows
// dist2.linear-linear and dist3.linear-linear; book sections 6.3 (figures 6.21) and 10.8
// (figures 10.27-10.37).
//
// distance(x, y) returns Distance<T, N, T, T>: closest[0] = point_at(x, param_a), closest[1] =
// point_at(y, param_b), with the parametrisations
//   t in [0, 1], point_at(seg, t) = (1 - t) p0 + t p1.
// Method: detail/linear.hpp (docs/notes/distance.md): the interior minimiser, or ONE exact
// clamped point-segment projection chosen by the violated constraints (segment_pair_fast), or,
// nearly parallel or degenerate, every candidate; in 2D nearly parallel segments that meet
// (decided exactly) get distance exactly 0 at the crossing. The answer is continuous through
// (nearly) parallel configurations: its squared distance is within a few eps * scale^2 of the
// exact one. distance(y, x) is bit for bit the swap of distance(x, y).
// unique = false when the directions are parallel (sin^2 angle <= 64 eps^2) and the parameter
// ranges overlap in an interval (parallel lines, overlapping parallel segments): one pair of the
// infinitely many is returned.
//
// Degenerate input: a zero-length segment acts as the point p0 (t = 0); the query then reduces to
// a point-linear distance. NaN or infinite coordinates give non_finite_distance() (result.hpp).
// Cost: O(N); two divisions, one square root in the common case; at most six point-linear
// projections in the nearly parallel case, in 2D after up to five exact orientation signs (most
// decided by a floating-point filter).
//
// sqr_distance(x, y) returns distance(x, y).sqr_distance, bit for bit, without the closest
// points, the parameters or the square root; NaN for non-finite input. Symmetric like distance.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/segment.hpp>

namespace locus {

/// Distance between two segments; param_a, param_b are their parameters.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Segment<T, N>& x,
                                                   const Segment<T, N>& y) noexcept {
  return detail::linear_linear_distance<T, N>(x, y);
}

/// Squared distance between two segments: distance(x, y).sqr_distance (the same bits), without
/// the closest points, the parameters or the square root; NaN for non-finite input.
template <Real T, int N>
[[nodiscard]] inline T sqr_distance(const Segment<T, N>& x, const Segment<T, N>& y) noexcept {
  return detail::segment_pair(x, y).sqr;
}

}  // namespace locus
