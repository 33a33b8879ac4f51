// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a line and a triangle in 3D: intersects() and intersection() on the closed
// triangle, and watertight_hit() for meshes; row int3.linear-triangle, book section 11.2.
// Parameters: Line3 t in R (origin + t direction); on the triangle param_b = (s, t) of
// point_at(tri, st) = v0 + s (v1 - v0)
// + t (v2 - v0), barycentrics (1 - s - t, s, t); normal N = (v1 - v0) x (v2 - v0).
// intersection() (LinearTriangleIntersection<T>): empty; point (a crossing, on the boundary
// included); when the line lies in the triangle's plane, the overlap: segment (ends by
// increasing param_a) or point. Decisions exact: the signs of det[d; v_i - o; v_{i+1} - o]
// (Pluecker's side of each edge; orient3d for a segment) and orient3d of the end points
// against the plane (core/plane_side.hpp); the coplanar case in the exact 2D code after
// dropping a coordinate (exact). Points: barycentric combinations of the vertices (within
// 4 eps max|v| of the triangle); a vertex, an end point on the triangle or an edge end is
// returned exactly; param_a is the projection of the point on the component.
// watertight_hit() (TriangleHit<T>: hit, front, t, barycentric, point) decides with the same
// signs under one symbolic translation of the line by e e_x + e^2 e_y + e^3 e_z (a zero sign
// becomes the first nonzero component of d x (v_{i+1} - v_i)): a line through a shared edge
// or vertex of a closed mesh hits exactly one of the triangles there (a transversal crossing)
// and edge-on or degenerate triangles are never hit; derivation: docs/notes/intersection.md.
// front: dot(d, N) < 0 (the ray arrives from the side N points to). Domain end points count
// (t = 0 hits). Degenerate: a zero direction (zero-length segment) acts as its point for
// intersection() and never hits watertight; a degenerate triangle (collinear vertices, exact)
// gives empty / no hit. NaN or infinite input: empty, no hit. Swapped overloads return
// swapped(). Cost: three exact-sign filters plus two orient3d; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/linear3.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/triangle.hpp>

namespace locus {

/// Whether a line meets the closed triangle (exact).
template <Real T>
[[nodiscard]] inline bool intersects(const Line3<T>& a, const Triangle3<T>& t) noexcept {
  namespace l3 = detail::linear3;
  return l3::triangle<false>(l3::as_lin(a), l3::as_tri(t)).kind != Kind::empty;
}

/// The common set of a line and the closed triangle (see the header comment).
template <Real T>
[[nodiscard]] inline LinearTriangleIntersection<T> intersection(const Line3<T>& a,
                                                                const Triangle3<T>& t) noexcept {
  namespace l3 = detail::linear3;
  return intersection_cast<T>(l3::triangle<true>(l3::as_lin(a), l3::as_tri(t)));
}

/// The watertight hit of a line on a triangle of a mesh (see the header comment).
template <Real T>
[[nodiscard]] inline TriangleHit<T> watertight_hit(const Line3<T>& a,
                                                   const Triangle3<T>& t) noexcept {
  namespace l3 = detail::linear3;
  return l3::cast_hit<T>(l3::hit(l3::as_lin(a), l3::as_tri(t)));
}

/// Swapped arguments: intersects(a, t).
template <Real T>
[[nodiscard]] inline bool intersects(const Triangle3<T>& t, const Line3<T>& a) noexcept {
  return intersects(a, t);
}

/// Swapped arguments: swapped(intersection(a, t)).
template <Real T>
[[nodiscard]] inline Intersection<T, 3, Vec2<T>, T, 2> intersection(const Triangle3<T>& t,
                                                                    const Line3<T>& a) noexcept {
  return swapped(intersection(a, t));
}

}  // namespace locus
