// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a segment and a solid tetrahedron in 3D; row dist3.linear-tetrahedron; book
// section 10.5.3 (figures 10.44, 10.45; the projection onto a plane is replaced by exact face
// queries: docs/notes/distance.md).
//
// distance(seg, tet) returns Distance<T, 3, T, Vec4<T>>: closest[0] = point_at(seg, param_a) with
//   t in [0, 1], point_at(seg, t) = (1 - t) p0 + t p1 (endpoints exact),
// and closest[1] = point_at_barycentric(tet, param_b), param_b = (b0, b1, b2, b3) barycentric
// (sum 1, all >= 0; primitives/tetrahedron.hpp). distance(tet, seg) is the swapped result. The
// tetrahedron is solid: a segment passing through it has distance 0, and meeting the solid is
// decided exactly (orient3d), as in segment_triangle.hpp: the distance is 0 only when they meet.
//
// unique = false when the segment passes through the interior of the solid (a chord of positive
// length, measured in floating point against 64 eps * scale), or when a face tied with the nearest
// reports non-uniqueness (the segment parallel to a face at the minimum). Degenerate input: a flat
// tetrahedron (exact orient3d == 0: coplanar vertices) is the union of its four face triangles,
// so it acts as the quadrilateral, triangle, segment or point it spans, continuously; a
// zero-length segment acts as the point p0 (t = 0). NaN or infinite coordinates give
// non_finite_distance() (result.hpp). Cost: O(1): nine exact orient3d signs and one to four
// segment-triangle queries.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/tetrahedron.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/tetrahedron.hpp>

namespace locus {

/// Distance between a segment and a solid tetrahedron; param_a = t in [0, 1], param_b barycentric.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec4<T>> distance(const Segment3<T>& seg,
                                                         const Tetrahedron3<T>& tet) noexcept {
  return detail::linear_tetrahedron_distance<T>(seg, tet);
}

/// The swapped query: closest[0] and param_a belong to the tetrahedron.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec4<T>, T> distance(const Tetrahedron3<T>& tet,
                                                         const Segment3<T>& seg) noexcept {
  return swapped(distance(seg, tet));
}

}  // namespace locus
