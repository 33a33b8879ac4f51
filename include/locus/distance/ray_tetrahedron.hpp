// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a ray and a solid tetrahedron in 3D; row dist3.linear-tetrahedron; book
// section 10.5.3 (figures 10.44, 10.45).
//
// distance(ray, tet) returns Distance<T, 3, T, Vec4<T>>: closest[0] = point_at(ray, param_a) with
//   t >= 0, point_at(ray, t) = origin + t direction (direction need not be unit),
// and closest[1] = point_at_barycentric(tet, param_b), param_b = (b0, b1, b2, b3) barycentric
// (sum 1, all >= 0; primitives/tetrahedron.hpp). distance(tet, ray) is the swapped result. The
// tetrahedron is solid: a ray passing through it has distance 0.
//
// Method (detail/tetrahedron.hpp): an origin inside the solid (decided exactly by orient3d) is its
// own closest point, at distance exactly 0; otherwise the ray meets the solid iff it meets its
// boundary, so the answer is the nearest of the four faces, each a ray-triangle query
// (ray_triangle.hpp; figure 10.44's projection of the tetrahedron onto a plane perpendicular
// to the direction, figure 10.45, is replaced by these exact face queries, which need no
// projection and no 2D polygon distance).
//
// unique = false when the ray passes through the interior of the solid (a chord of positive
// length, measured in floating point against 64 eps * scale), or when a face tied with the nearest
// reports non-uniqueness (the ray parallel to a face at the minimum). Degenerate input: a flat
// tetrahedron (exact orient3d == 0: coplanar vertices) is the union of its four face triangles
// (which cover the convex hull of four coplanar points), so it acts as the quadrilateral, triangle,
// segment or point it spans, continuously; a zero direction acts as the point origin (t = 0). NaN
// or infinite coordinates give non_finite_distance() (result.hpp). Cost: O(1): five exact orient3d
// signs and four ray-triangle queries.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/tetrahedron.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/tetrahedron.hpp>

namespace locus {

/// Distance between a ray and a solid tetrahedron; param_a = t >= 0, param_b barycentric.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec4<T>> distance(const Ray3<T>& ray,
                                                         const Tetrahedron3<T>& tet) noexcept {
  return detail::linear_tetrahedron_distance<T>(ray, tet);
}

/// The swapped query: closest[0] and param_a belong to the tetrahedron.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec4<T>, T> distance(const Tetrahedron3<T>& tet,
                                                         const Ray3<T>& ray) noexcept {
  return swapped(distance(ray, tet));
}

}  // namespace locus
