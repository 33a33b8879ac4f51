// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between two (solid) triangles in 3D; row dist3.misc (triangle-triangle).
//
// distance(a, b) returns Distance<T, 3, Vec3<T>, Vec3<T>>: closest[0] =
// point_at_barycentric(a, param_a), closest[1] = point_at_barycentric(b, param_b), both
// parameters barycentric (u, v, w) (sum 1, all >= 0; as in point_triangle.hpp). The triangles
// are filled: triangles that meet have distance 0.
//
// Method (detail/planar_pairs.hpp): the nearest of the six edge-triangle queries (each edge of a
// against b, each edge of b against a; segment_triangle.hpp), because two disjoint convex planar
// pieces have a closest pair on an edge of one of them, and two that meet do so on an edge of
// one of them. Contact is decided EXACTLY by segment_triangle's orient3d test: triangles that
// meet have distance exactly 0, and triangles that do not meet never have distance 0 (apart from
// underflow), whenever at least one of them is not degenerate (ill-conditioned contacts, such as
// needle triangles or grazing angles, may report the rounded pair, ~eps / angle apart).
// unique = false when the triangles meet in more than one point (transversal triangles meet
// along a segment; coplanar ones in a polygon), or when the closest pair can slide (parallel
// planes over an overlap, parallel nearest edges). The pair is solved in a canonical
// (lexicographic) order, so distance(b, a) is bit for bit the swap of distance(a, b).
//
// Degenerate input: a degenerate triangle (collinear or coincident vertices) acts as the
// segment or point it spans, continuously. NaN or infinite coordinates give
// non_finite_distance() (result.hpp). Cost: O(1): six segment-triangle queries (each a few
// exact orient3d signs and one to three sub-queries).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/planar_pairs.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/triangle.hpp>

namespace locus {

/// Distance between two solid triangles in 3D; both parameters barycentric.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec3<T>, Vec3<T>> distance(const Triangle3<T>& a,
                                                               const Triangle3<T>& b) noexcept {
  return detail::same_piece_distance<T>(a, b);
}

}  // namespace locus
