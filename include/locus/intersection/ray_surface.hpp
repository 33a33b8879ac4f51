// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a ray and a parametric surface (BezierPatch, BSplineSurface, NurbsSurface) in
// 3D: intersects() and intersection() (find); row int3.linear-surface, book section 11.6 (figures
// 11.18-11.22). Parameters: Ray3 t >= 0; uv in the surface's own domain ([0, 1]^2 for a Bézier
// patch). Result LinearSurfaceHits<T> (intersection/detail/surface3.hpp): status, the isolated
// hits by increasing t (t, uv, point S(u, v), unit normal, tangent flag) and on_surface. Method
// (figures 11.20-11.22): the ray is the intersection of two planes; in a frame along it, scaled by
// a power of two, every Bézier span of the surface (to_bezier; NURBS in homogeneous form (w P, w),
// w > 0) has two coordinate patches whose zeros are the hits. A span whose control values of
// either coordinate keep one strict sign is discarded (convex-hull property; also the part behind
// a ray's origin or past a segment's end); the others are split in four down to leaves of 2^-8 of
// the span, and from each leaf's centre a damped Newton iteration on (u, v) (then t) converges to
// the hit. Guarantee: every transversal hit is found (its leaf survives and Newton converges from
// 2^-9 of the span); a tangential hit is found when the surface is not flatter than its rounding
// there; a hit is accepted when the point is within 2^-36 of the surface size of the ray, so a
// near-miss that close to a tangency reports a tangent hit. Hits closer than 2^-24 of the size are
// merged into one. tangent: the angle between the direction and the tangent plane is below 2^-20
// rad. Degenerate: a piece of the ray lying on the surface (a line in a planar patch; a ruling of
// a curved surface, seen as a run of tangential roots whose midpoints lie on it) sets on_surface
// and is not listed as hits; a zero direction or segment: status degenerate_input; NaN/Inf:
// non_finite_input; an invalid surface: validate()'s status (no hits). Budget: 2^18 subdivision
// nodes, then limit_exceeded with the hits so far. Float input is computed in double. Cost: about
// 10-100 us for a bicubic patch (allocates).

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/surface3.hpp>
#include <locus/primitives/ray.hpp>

namespace locus {

/// The hits of a ray on a Bézier patch (see the header comment).
template <Real T>
[[nodiscard]] inline LinearSurfaceHits<T> intersection(const Ray3<T>& a,
                                                       const BezierPatch<T, 3>& b) {
  namespace s = detail::surface3;
  return s::cast<T>(s::linear_hits(detail::linear3::as_lin(a), s::as_nurbs(b)));
}
/// The hits of a ray on a B-spline surface (uv in its knot domain).
template <Real T>
[[nodiscard]] inline LinearSurfaceHits<T> intersection(const Ray3<T>& a,
                                                       const BSplineSurface<T, 3>& b) {
  namespace s = detail::surface3;
  return s::cast<T>(s::linear_hits(detail::linear3::as_lin(a), s::as_nurbs(b)));
}
/// The hits of a ray on a NURBS surface (uv in its knot domain).
template <Real T>
[[nodiscard]] inline LinearSurfaceHits<T> intersection(const Ray3<T>& a,
                                                       const NurbsSurface<T, 3>& b) {
  namespace s = detail::surface3;
  return s::cast<T>(s::linear_hits(detail::linear3::as_lin(a), s::as_nurbs(b)));
}

/// The same with the arguments exchanged (the result names t and uv, nothing to swap).
template <Real T>
[[nodiscard]] inline LinearSurfaceHits<T> intersection(const BezierPatch<T, 3>& a,
                                                       const Ray3<T>& b) {
  return intersection(b, a);
}
template <Real T>
[[nodiscard]] inline LinearSurfaceHits<T> intersection(const BSplineSurface<T, 3>& a,
                                                       const Ray3<T>& b) {
  return intersection(b, a);
}
template <Real T>
[[nodiscard]] inline LinearSurfaceHits<T> intersection(const NurbsSurface<T, 3>& a,
                                                       const Ray3<T>& b) {
  return intersection(b, a);
}

/// Whether the ray meets the surface (a hit, or a piece lying on it).
template <Real T, class S>
requires requires(const Ray3<T>& a, const S& b) { intersection(a, b).on_surface; }
[[nodiscard]] inline bool intersects(const Ray3<T>& a, const S& b) {
  const LinearSurfaceHits<T> r = intersection(a, b);
  return !r.hits.empty() || r.on_surface;
}
template <Real T, class S>
requires requires(const Ray3<T>& a, const S& b) { intersection(a, b).on_surface; }
[[nodiscard]] inline bool intersects(const S& b, const Ray3<T>& a) { return intersects(a, b); }

}  // namespace locus
