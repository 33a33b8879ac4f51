// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between two lines in N dimensions (2D and 3D included); rows
// dist2.linear-linear and dist3.linear-linear; book sections 6.3 (figures 6.16-6.17) and 10.8
// (figures 10.27-10.37).
//
// distance(x, y) returns Distance<T, N, T, T>: closest[0] = point_at(x, param_a), closest[1] =
// point_at(y, param_b), with the parametrisations
//   t in R, point_at(line, t) = origin + t direction.
// Method: detail/linear.hpp (docs/notes/distance.md). In 2D whether the two meet is decided
// exactly (orientation signs); if they do, the distance is exactly 0 at the crossing point (to
// rounding). The squared distance is within a few eps * scale^2 of the exact one, scale the
// magnitude of the closest points (far away for nearly parallel input). Like the exact distance,
// the answer jumps at exact parallelism; the parallel answer is returned only for exactly
// parallel directions, or when the crossing lies beyond the floating-point range.
// unique = false when the directions are parallel (sin^2 angle <= 64 eps^2) and the parameter
// ranges overlap in an interval (parallel lines, overlapping parallel segments): one pair of the
// infinitely many is returned.
//
// Degenerate input: a zero direction acts as the point origin (t = 0); the query then reduces to
// a point-linear distance. NaN or infinite coordinates give non_finite_distance() (result.hpp).
// Cost: O(N), at most six point-linear projections in the nearly parallel case; in 2D also up to
// five exact orientation signs (most decided by a floating-point filter) per query.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

/// Distance between two lines; param_a, param_b are their parameters.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Line<T, N>& x,
                                                   const Line<T, N>& y) noexcept {
  return detail::linear_linear_distance<T, N>(x, y);
}

}  // namespace locus
