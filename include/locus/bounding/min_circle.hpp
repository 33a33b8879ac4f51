// SPDX-License-Identifier: BSL-1.0
#pragma once
// Smallest enclosing circle of a 2D point set; CAPABILITIES row cg.minball; book section 13.11
// ("Minimum-area circle", figure 13.80: a point outside the current circle makes it grow, which
// may leave an earlier point outside and restart the scan).
//
// Algorithm: Welzl's randomised incremental algorithm in its move-to-front form (E. Welzl,
// "Smallest enclosing disks (balls and ellipsoids)", 1991; the list formulation of B. Gaertner):
// the points are visited in a seeded random order kept in a doubly linked list; when a point is
// outside the current circle, the circle is recomputed with that point forced onto the boundary
// (recursively over the points before it in the list, at most 3 nested levels, so the recursion
// depth is bounded by 3) and the point moves to the front of the list. Expected O(n) tests.
//
// Exactness (certified combinatorics): the circle is defined by its support points, 1 to 3
// input points on its boundary, and "is p strictly outside?" is decided exactly against them:
// for 2 supports by the exact sign of (p - a).(p - b), for 3 by exact incircle and orient2d
// (core/predicates.hpp, bounding/detail/ball_predicates.hpp). So the support set is the exact
// smallest enclosing circle of the given floating-point points, and every input point lies
// inside or on the exact circle through the supports. The reported centre and radius are
// constructions, computed in double and rounded to T: radius = max over the supports of their
// distance to the rounded centre, so a point may lie outside the *reported* circle by a few
// ulps of the circle's scale (relative error eps |x| max / h for a support triangle of smallest
// height h).
//
// Result: status, circle, support_count (0 when the status is not ok, else 1..3) and support
// (input indices; for two supports they are the diameter's end points), tests (the number of
// point-versus-circle tests made).
// Bad input: empty span -> Status::empty_input; a NaN/Inf coordinate ->
// Status::non_finite_input; more than 2^32 - 2 points -> Status::invalid_input; all points
// equal -> ok, one support, radius 0. A spent test budget -> Status::limit_exceeded.
// Speed (none of it changes the result): a core-set search runs first. S = the extreme points
// along 4 fixed directions (7 in 3D), both ends; the smallest circle of S is computed by the
// algorithm above and one sequential scan of all points adds those outside it to S; when none
// is outside, the circle of S is the circle of all points (it contains them all, and no smaller
// circle contains S). After 8 rounds, or when S exceeds max(256, n / 16) points, the algorithm
// runs on all points, so the expected O(n) bound holds on every input. The points the algorithm
// scans are copied (as double) in the seeded random order, extremes first, so the scans read
// memory sequentially. On uniform random input this takes about 1.0 n tests.
// A point is accepted as inside without an exact test only when it is deep inside the rounded
// circle, |p - c|^2 <= r^2 (1 - 2^-20), and the support set is well conditioned (condition
// estimate kappa <= 2^20 and |s0| <= 2^20 r, so the rounded centre is within about
// kappa 8 eps r of the exact one, far below the 2^-21 r margin); every other point gets the
// exact test.
// Cost: expected O(n) time for every input (the expectation is over the seeded permutation),
// up to 28 bytes of scratch per point (reused by MinCircle2 across calls).

#include <locus/bounding/detail/min_ball_common.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/circle.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// The smallest enclosing circle and the input indices of its support points.
template <class T>
struct MinCircleResult {
  Status status = Status::empty_input;
  Circle2<T> circle{};                     ///< rounded centre and radius (see the header comment)
  int support_count = 0;                   ///< 1..3 when status is ok
  std::array<std::uint32_t, 3> support{};  ///< input indices of the support points
  std::uint64_t tests = 0;                 ///< point-versus-circle tests made
};

/// Reusable smallest-enclosing-circle solver (keeps its list buffers between calls).
template <Real T>
class MinCircle2 {
 public:
  [[nodiscard]] MinCircleResult<T> compute(std::span<const Vec2<T>> points,
                                           const MinBallOptions& options = {});

 private:
  std::vector<std::uint32_t> next_, prev_, order_;
  std::vector<Vec2<double>> points_;  // the input in visiting order (sequential memory access)
};

/// The smallest circle enclosing `points` (one call over MinCircle2).
template <Real T>
[[nodiscard]] MinCircleResult<T> min_circle(std::span<const Vec2<T>> points,
                                            const MinBallOptions& options = {}) {
  MinCircle2<T> solver;
  return solver.compute(points, options);
}

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] MinCircleResult<range_scalar_t<R>> min_circle(const R& points,
                                                            const MinBallOptions& options = {}) {
  return min_circle(point_span(points), options);
}

extern template class MinCircle2<float>;
extern template class MinCircle2<double>;

}  // namespace locus
