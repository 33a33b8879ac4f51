// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a segment and a (solid) triangle in 3D; row dist3.linear-triangle; book section
// 10.5.1 (figures 10.38-10.41). Method: detail/linear_planar.hpp and docs/notes/distance.md.
//
// distance(seg, tri) returns Distance<T, 3, T, Vec3<T>>: closest[0] = point_at(seg, param_a) with
//   t in [0, 1], point_at(seg, t) = (1 - t) p0 + t p1 (endpoints exact),
// and closest[1] = point_at_barycentric(tri, param_b) with param_b = (u, v, w)
//   barycentric (u + v + w = 1, all >= 0; as in point_triangle.hpp).
// distance(tri, seg) is the swapped result. The triangle is filled: a segment passing through it
// has distance 0.
//
// unique = false when the segment is parallel to the triangle's plane (sin^2 angle <= 64 eps^2) and
// the closest pair can slide along it (above the interior, or along the nearest edge), or when a
// flat triangle's nearest edge is parallel to it.
// Exact zero: whether the segment meets a non-degenerate triangle is decided EXACTLY (orient3d,
// plus orient2d when coplanar; core/predicates.hpp). The distance is exactly 0 only when they
// meet, and whenever they meet except for ill-conditioned contacts (a needle triangle, a grazing
// angle) whose rounded closest points differ by more than 32 ulps of the largest input coordinate:
// those report the rounded pair (~eps / angle apart). When 0, both closest points are the contact
// point on the triangle. For a degenerate triangle the answer is the rounded edge distance.
// Degenerate input: a zero-length segment acts as the point p0 (t = 0; the point-triangle query); a
// (nearly) flat triangle (|e0 x e1|^2 <= 64 eps |e0|^2 |e1|^2) acts as the union of its three
// edges. NaN or infinite coordinates give non_finite_distance() (result.hpp). Cost: O(1): one 3x3
// solve, one to three sub-queries and two to five orient3d signs; at most 7 sub-queries when
// nearly parallel. sqr_distance(seg, tri) (either order) returns distance(seg, tri).sqr_distance
// bit for bit (exactly 0 under the same contact rule); NaN for non-finite input.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear_planar.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

namespace locus {

/// Distance between a segment and a solid triangle; param_a = t in [0, 1], param_b = barycentric
/// (u, v, w).
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec3<T>> distance(const Segment3<T>& seg,
                                                         const Triangle3<T>& tri) noexcept {
  return detail::linear_triangle_distance<T>(seg, tri);
}

/// The swapped query: closest[0] and param_a belong to the triangle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec3<T>, T> distance(const Triangle3<T>& tri,
                                                         const Segment3<T>& seg) noexcept {
  return swapped(distance(seg, tri));
}

/// Squared distance between a segment and a solid triangle: distance(seg, tri).sqr_distance (the
/// same bits), without the closest points, the parameters or the square root; NaN for non-finite
/// input.
template <Real T>
[[nodiscard]] inline T sqr_distance(const Segment3<T>& seg, const Triangle3<T>& tri) noexcept {
  return detail::linear_triangle_core(seg, tri).sqr;
}

/// sqr_distance(seg, tri).
template <Real T>
[[nodiscard]] inline T sqr_distance(const Triangle3<T>& tri, const Segment3<T>& seg) noexcept {
  return sqr_distance(seg, tri);
}

}  // namespace locus
