// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between two segments in N dimensions (2D and 3D included); rows
// dist2.linear-linear and dist3.linear-linear; book sections 6.3 (figures 6.21) and 10.8
// (figures 10.27-10.37).
//
// distance(x, y) returns Distance<T, N, T, T>: closest[0] = point_at(x, param_a), closest[1] =
// point_at(y, param_b), with the parametrisations
//   t in [0, 1], point_at(seg, t) = (1 - t) p0 + t p1.
// Method (detail/linear.hpp): the convex quadratic |x(s) - y(t)|^2 is minimised over the
// parameter domain; when the directions are well separated and the unconstrained minimiser lies
// in the domain it is the answer. When it lies outside and the directions are not nearly
// parallel, the answer is ONE exact clamped point-segment projection on an edge of the domain
// (chosen by the violated constraints and, at a corner, by the sign of the derivative:
// segment_pair_fast). Otherwise (nearly parallel, or
// degenerate) the minimum over the in-domain interior point and the exact point-to-component
// solutions on the domain's finite edges is taken; in 2D, whether nearly parallel segments meet
// is decided exactly (orientation signs) first, and if they do the closest points are the crossing
// point (to rounding) and the distance is exactly 0. The answer is therefore continuous as the
// input passes through (nearly) parallel configurations and is never a "parallel" guess: its
// squared distance is within a few eps * scale^2 of the exact one. distance(y, x) is bit for bit
// the swap of distance(x, y).
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
