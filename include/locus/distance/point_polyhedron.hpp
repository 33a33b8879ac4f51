// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a solid convex polyhedron given as a closed triangle mesh; row
// dist3.pt-polyhedron (convex polyhedron part); book section 10.3.4 (figure 10.20). Tetrahedra:
// point_tetrahedron.hpp; general (non-convex) meshes with a tree: point_mesh.hpp.
//
// distance_to_convex_polyhedron(p, vertices, triangles) takes the mesh in the layout of
// containment/point_in_polyhedron.hpp (triangle {i, j, k} has normal (vj - vi) x (vk - vi)),
// which must be closed, convex, of positive volume and with outward normals (not checked:
// checking is as expensive as the query; hull3.hpp produces such meshes). It returns
// Distance<T, 3, NoParam, Vec3<T>>: closest[1] = the nearest point of the solid (p itself,
// distance exactly 0, when p is inside or on the boundary); param_b = closest[1] (a solid is
// parametrised by the space's own coordinates, as in point_convex_polygon.hpp).
//
// Method: a face is "violated" when p is strictly on the outer side of its plane, decided
// exactly by orient3d (core/predicates.hpp). No violated face: p is in the solid. Otherwise the
// nearest point lies on a violated face (at the nearest point q, p - q is a non-negative
// combination of the outward normals of the faces through q, so one of them has a positive
// product with p - q), so only the violated faces are queried with point_triangle.hpp, and the
// nearest wins. Cost: O(F) orient3d (a floating-point filter; exact only near zero) plus one
// point-triangle query per violated face; no allocation.
//
// Bad input: no triangles (nothing to measure), an index out of range, a non-finite vertex of a
// used triangle or a non-finite p give non_finite_distance() (result.hpp). A mesh violating the
// preconditions gives an unspecified finite answer (inward normals make every outside point look
// inside; a flat mesh reports the points of its plane as inside). unique is always true.

#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace locus {

/// Distance from p to the solid convex polyhedron (closed, outward, convex triangle mesh).
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, Vec3<T>> distance_to_convex_polyhedron(
    const Vec3<T>& p, std::span<const Vec3<T>> vertices,
    std::span<const std::array<std::uint32_t, 3>> triangles) noexcept {
  if (triangles.empty() || !is_finite(p)) return non_finite_distance<T, 3, NoParam, Vec3<T>>();
  T best = std::numeric_limits<T>::infinity();
  Vec3<T> q = p;
  for (const auto& t : triangles) {
    if (t[0] >= vertices.size() || t[1] >= vertices.size() || t[2] >= vertices.size())
      return non_finite_distance<T, 3, NoParam, Vec3<T>>();
    const Vec3<T>&a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    if (!is_finite(a) || !is_finite(b) || !is_finite(c))
      return non_finite_distance<T, 3, NoParam, Vec3<T>>();
    if (orient3d(a, b, c, p) != Sign::positive) continue;
    const auto r = distance(p, Triangle3<T>{a, b, c});
    if (r.sqr_distance < best) best = r.sqr_distance, q = r.closest[1];
  }
  return detail::make_distance(p, q, NoParam{}, q, true);
}

/// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] inline Distance<range_scalar_t<R>, 3, NoParam, range_point_t<R>>
distance_to_convex_polyhedron(const range_point_t<R>& p, const R& vertices,
                              std::span<const std::array<std::uint32_t, 3>> triangles) noexcept {
  return distance_to_convex_polyhedron(p, point_span(vertices), triangles);
}

}  // namespace locus
