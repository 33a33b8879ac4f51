// SPDX-License-Identifier: BSL-1.0
#pragma once
// Smallest enclosing circle of a 2D point set; CAPABILITIES row cg.minball; book section 13.11
// ("Minimum-area circle", figure 13.80: a point outside the current circle makes it grow, which
// may leave an earlier point outside and restart the scan).
//
// Algorithm: Welzl's randomised incremental algorithm in move-to-front form, over a seeded
// random permutation (MinBallOptions), after a core-set search seeded by extreme points; the
// recursion depth is at most 3. Derivation and the speed devices: docs/notes/bounding.md.
// Exactness: the circle is defined by 1 to 3 support points on its boundary, and "is p strictly
// outside?" is decided exactly (core/predicates.hpp, bounding/detail/ball_predicates.hpp), so
// the support set is the exact smallest enclosing circle of the given points. The centre and
// radius are constructions (double, rounded to T; radius = max distance of the supports to the
// rounded centre): a point may lie outside the reported circle by a few ulps of its scale.
// Scale-covariant: input scaled by 2^k gives the circle scaled by 2^k exactly, for every k
// that keeps the input finite and normal (the centre is computed on edges scaled by a power of
// two when their products would leave the range).
// Result: status, circle, support_count (0 unless ok or limit_exceeded, else 1..3), support
// (input indices; two supports are a diameter's ends), tests (point-versus-circle tests made).
// Bad input: empty -> Status::empty_input; NaN/Inf -> non_finite_input; more than 2^32 - 2
// points -> invalid_input; all points equal -> ok, one support, radius 0. A spent test budget
// -> limit_exceeded with the circle of that moment.
// Cost: expected O(n) time for every input (over the seeded permutation); up to 28 bytes of
// scratch per point, reused by MinCircle2 across calls.

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
template <Real T>
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
