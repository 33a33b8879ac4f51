// SPDX-License-Identifier: BSL-1.0
#pragma once
// Smallest enclosing sphere of a 3D point set; CAPABILITIES row cg.minball; book section 13.11
// ("Minimum-volume sphere", the 3D form of figure 13.80; figure 13.81 belongs to the same
// section's growth argument).
//
// Algorithm: as bounding/min_circle.hpp (Welzl's move-to-front algorithm, core-set search
// first), with up to 4 nested levels. Derivation: docs/notes/bounding.md.
// Exactness: the sphere is defined by 1 to 4 support points on its boundary; "is p strictly
// outside?" is decided exactly (2 supports: sign of (p - a).(p - b); 3: the power of p with
// respect to the smallest sphere through them, bounding/detail/ball_predicates.hpp; 4: exact
// insphere and orient3d), so the support set is the exact smallest enclosing sphere of the
// given points. Centre and radius are constructions (double, rounded to T): a point may lie
// outside the reported sphere by a few ulps of its scale. Scale-covariant: input scaled by 2^k
// gives the sphere scaled by 2^k exactly, for every k that keeps the input finite and normal.
// Result: status, sphere, support_count (1..4), support (input indices), tests.
// Bad input: empty -> empty_input; NaN/Inf -> non_finite_input; more than 2^32 - 2 points ->
// invalid_input; all points equal -> ok, radius 0; spent budget -> limit_exceeded.
// Cost: expected O(n); up to 36 bytes of scratch per point (reused by MinSphere3).

#include <locus/bounding/detail/min_ball_common.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/sphere.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// The smallest enclosing sphere and the input indices of its support points.
template <Real T>
struct MinSphereResult {
  Status status = Status::empty_input;
  Sphere3<T> sphere{};                     ///< rounded centre and radius
  int support_count = 0;                   ///< 1..4 when status is ok
  std::array<std::uint32_t, 4> support{};  ///< input indices of the support points
  std::uint64_t tests = 0;                 ///< point-versus-sphere tests made
};

/// Reusable smallest-enclosing-sphere solver (keeps its list buffers between calls).
template <Real T>
class MinSphere3 {
 public:
  [[nodiscard]] MinSphereResult<T> compute(std::span<const Vec3<T>> points,
                                           const MinBallOptions& options = {});

 private:
  std::vector<std::uint32_t> next_, prev_, order_;
  std::vector<Vec3<double>> points_;  // the input in visiting order (sequential memory access)
};

/// The smallest sphere enclosing `points` (one call over MinSphere3).
template <Real T>
[[nodiscard]] MinSphereResult<T> min_sphere(std::span<const Vec3<T>> points,
                                            const MinBallOptions& options = {}) {
  MinSphere3<T> solver;
  return solver.compute(points, options);
}

/// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] MinSphereResult<range_scalar_t<R>> min_sphere(const R& points,
                                                            const MinBallOptions& options = {}) {
  return min_sphere(point_span(points), options);
}

extern template class MinSphere3<float>;
extern template class MinSphere3<double>;

}  // namespace locus
