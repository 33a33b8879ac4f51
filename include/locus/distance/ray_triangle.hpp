// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a ray and a (solid) triangle in 3D; row dist3.linear-triangle; book section
// 10.5.1 (figures 10.38-10.41).
//
// distance(ray, tri) returns Distance<T, 3, T, Vec3<T>>: closest[0] = point_at(ray, param_a) with
//   t >= 0, point_at(ray, t) = origin + t direction (direction need not be unit),
// and closest[1] = point_at_barycentric(tri, param_b) with param_b = (u, v, w)
//   barycentric (u + v + w = 1, all >= 0; as in point_triangle.hpp).
// distance(tri, ray) is the swapped result. The triangle is filled: a ray passing through it
// has distance 0.
//
// Method: detail/linear_planar.hpp (docs/notes/distance.md): the crossing with the plane when
// it lies in the prism, else the facets its parameters violate (KKT, the regions of figure
// 10.40); nearly parallel or rounding-sensitive cases evaluate every candidate, so the answer
// is continuous through parallel configurations and never divides by a vanishing determinant.
//
// unique = false when the ray is parallel to the triangle's plane (sin^2 angle <= 64 eps^2) and
// the closest pair can slide along it (above the interior, or along the nearest edge), or when a
// flat triangle's nearest edge is parallel to it.
// Degenerate input: a zero direction acts as the point origin (t = 0; the point-triangle query); a
// (nearly) flat triangle (|e0 x e1|^2 <= 64 eps |e0|^2 |e1|^2: collinear or coincident vertices)
// acts as the union of its three edges, so the answer is the distance to the segment or point
// it spans, continuously. NaN or infinite coordinates give non_finite_distance() (result.hpp).
// Cost: O(1): one 3x3 solve and one to three point-triangle / linear-segment queries in the
// generic case, at most 6 sub-queries in the nearly parallel case.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear_planar.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/triangle.hpp>

namespace locus {

/// Distance between a ray and a solid triangle; param_a = t >= 0, param_b = barycentric (u, v, w).
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, Vec3<T>> distance(const Ray3<T>& ray,
                                                         const Triangle3<T>& tri) noexcept {
  return detail::linear_triangle_distance<T>(ray, tri);
}

/// The swapped query: closest[0] and param_a belong to the triangle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec3<T>, T> distance(const Triangle3<T>& tri,
                                                         const Ray3<T>& ray) noexcept {
  return swapped(distance(ray, tri));
}

}  // namespace locus
