// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a plane and a parametric surface (BezierPatch, BSplineSurface, NurbsSurface):
// intersection() returns the intersection curves as polylines; row int3.plane-surface, book
// section 11.7 (figures 11.53-11.58). Plane3 {normal N (any length), constant k}: N.X = k.
// Result SurfaceCurves<T> (intersection/detail/surface3.hpp): status and curves, each closed (a
// loop inside the domain; the first point is not repeated) or open (both ends on the domain
// boundary), with points (3D) and param_b (u, v on the surface; param_a empty, a plane has no
// parameters). Method: every Bézier span of the surface (to_bezier; NURBS in homogeneous form) is
// covered by a grid of opt.grid x opt.grid cells (the subpatches of figure 11.56); the sign of
// N.S(u, v) - k (homogeneous: N.(wP) - k w, same sign as w > 0) is evaluated at the grid nodes,
// zero counting as positive (a symbolic perturbation of the plane, so every crossing is a
// transversal sign change and the topology is consistent); on each cell edge with a sign change
// the root is bisected to full double precision and the point evaluated on the surface; a cell's
// crossings are joined (a saddle cell by the sign at its centre) and the pieces chained across
// cells (and across spans) into open branches and closed loops (figures 11.57, 11.58). Every
// listed point lies on the surface (evaluated) and within a few ulps of the plane (bisection);
// between points the polyline is a chord of the curve. Hidden features: every cell whose four
// corners share a sign is checked by subdivision (exact hull rejection, subpatch corners as
// witnesses, 5 levels): when one hides a sign region (a small loop) the grid is doubled, up to
// 256 cells per span; if one remains, status is limit_exceeded (the curves found are returned).
// Not found: two crossings of one cell edge inside a cell with mixed corners, features below
// 2^-5 of a 256-cell, pieces where the surface lies in the plane (zero counts as positive).
// Degenerate: zero normal: degenerate_input; NaN/Inf: non_finite_input; invalid surface:
// validate()'s status. Float input is computed in double. Cost: (grid + 1)^2 surface evaluations
// per span plus 64 per crossing; allocates.
// Hermite curves (book section 11.7, figures 11.54-11.57): hermite_curve(plane, surface, curve),
// for a curve of intersection(plane, surface) (its param_b, or param_a if that is empty), adds
// the unit tangent at every traced point, T = N x (S_u x S_v) normalised and oriented along the
// point order, and its (u, v) velocity per unit arc length q = (N.S_v, -N.S_u) / |.| (so that
// S_u q.x + S_v q.y = T); where S_u x S_v is parallel to N (the surface touches the plane) or
// degenerate, the chord through the neighbouring points replaces it. point_at(h, i, t)
// evaluates segment i (P_i to P_i+1, the last one closing a loop) at t in [0, 1] as the cubic
// Hermite interpolants R(t) (3-space, from the points and L T_i, L T_i+1, L the chord length)
// and p(t) (parameter space, from the (u, v) and L q). R(t) lies in the plane up to rounding
// and within O(h^4) of the surface, S(p(t)) lies on the surface and within O(h^4) of the plane,
// h the segment length (docs/notes/surface_intersection.md). hermite_basis(t) gives the four
// basis functions. Status: the surface's, non_finite_input, degenerate_input (zero normal),
// empty_input (no points), invalid_input (points and parameters of different counts); float
// input is computed in double. Cost: one surface derivative evaluation per point.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/surface3.hpp>
#include <locus/primitives/plane.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace locus {

/// The curves where a plane cuts a Bézier patch (see the header comment).
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> intersection(const Plane3<T>& a, const BezierPatch<T, 3>& b,
                                                   const SurfaceCurveOptions& opt = {}) {
  namespace s = detail::surface3;
  return s::cast<T>(
      s::plane_curves(vec_cast<double>(a.normal), double(a.constant), s::as_nurbs(b), opt));
}
/// The curves where a plane cuts a B-spline surface.
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> intersection(const Plane3<T>& a,
                                                   const BSplineSurface<T, 3>& b,
                                                   const SurfaceCurveOptions& opt = {}) {
  namespace s = detail::surface3;
  return s::cast<T>(
      s::plane_curves(vec_cast<double>(a.normal), double(a.constant), s::as_nurbs(b), opt));
}
/// The curves where a plane cuts a NURBS surface.
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> intersection(const Plane3<T>& a, const NurbsSurface<T, 3>& b,
                                                   const SurfaceCurveOptions& opt = {}) {
  namespace s = detail::surface3;
  return s::cast<T>(
      s::plane_curves(vec_cast<double>(a.normal), double(a.constant), s::as_nurbs(b), opt));
}

/// The same with the arguments exchanged: param_a holds the surface parameters.
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> intersection(const BezierPatch<T, 3>& a, const Plane3<T>& b,
                                                   const SurfaceCurveOptions& opt = {}) {
  return swapped(intersection(b, a, opt));
}
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> intersection(const BSplineSurface<T, 3>& a,
                                                   const Plane3<T>& b,
                                                   const SurfaceCurveOptions& opt = {}) {
  return swapped(intersection(b, a, opt));
}
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> intersection(const NurbsSurface<T, 3>& a, const Plane3<T>& b,
                                                   const SurfaceCurveOptions& opt = {}) {
  return swapped(intersection(b, a, opt));
}

/// A traced plane-surface curve with its tangents, interpolated piecewise by cubic Hermite
/// segments (see the header comment).
template <Real T>
struct HermiteSurfaceCurve {
  Status status = Status::empty_input;
  bool closed = false;
  std::vector<Vec3<T>> points;          ///< P_i, the traced points (on the surface)
  std::vector<Vec2<T>> params;          ///< (u_i, v_i) of P_i on the surface
  std::vector<Vec3<T>> tangents;        ///< unit tangent T_i, along the point order
  std::vector<Vec2<T>> param_tangents;  ///< (u, v) velocity per unit arc length at P_i
};

/// A point of a Hermite curve: in 3-space, R(t), and in parameter space, p(t).
template <Real T>
struct HermiteCurvePoint {
  Vec3<T> point;
  Vec2<T> param;
};

/// The cubic Hermite basis at t: {h0, h1, h2, h3}, x(t) = h0 P0 + h1 P1 + h2 D0 + h3 D1.
template <Real T>
[[nodiscard]] constexpr std::array<T, 4> hermite_basis(T t) noexcept {
  const T t2 = t * t, t3 = t2 * t;
  return {T(2) * t3 - T(3) * t2 + T(1), T(3) * t2 - T(2) * t3, t3 - T(2) * t2 + t, t3 - t2};
}

/// The cubic Hermite interpolant from p0 (derivative d0) at t = 0 to p1 (d1) at t = 1.
template <class P, Real T>
[[nodiscard]] constexpr P hermite(const P& p0, const P& p1, const P& d0, const P& d1,
                                  T t) noexcept {
  const std::array<T, 4> h = hermite_basis(t);
  return h[0] * p0 + h[1] * p1 + h[2] * d0 + h[3] * d1;
}

namespace detail::surface3 {
template <Real T>
[[nodiscard]] HermiteSurfaceCurve<T> hermite_of(const V& normal, const NS& s,
                                                const SurfaceCurve<T>& c) {
  HermiteSurfaceCurve<T> h;
  h.closed = c.closed;
  h.points = c.points;
  h.params = c.param_b.empty() ? c.param_a : c.param_b;
  std::vector<V> pts;
  std::vector<Vec2<double>> prm;
  for (const auto& p : h.points) pts.push_back(vec_cast<double>(p));
  for (const auto& p : h.params) prm.push_back(vec_cast<double>(p));
  const CurveTangents t = plane_curve_tangents(normal, s, pts, prm, c.closed);
  h.status = t.status;
  for (const auto& d : t.tangent) h.tangents.push_back(vec_cast<T>(d));
  for (const auto& d : t.param_tangent) h.param_tangents.push_back(vec_cast<T>(d));
  return h;
}
}  // namespace detail::surface3

/// The Hermite form of a curve of intersection(plane, patch) (see the header comment).
template <Real T>
[[nodiscard]] inline HermiteSurfaceCurve<T> hermite_curve(const Plane3<T>& a,
                                                          const BezierPatch<T, 3>& b,
                                                          const SurfaceCurve<T>& c) {
  namespace s = detail::surface3;
  return s::hermite_of(vec_cast<double>(a.normal), s::as_nurbs(b), c);
}
/// The Hermite form of a curve of intersection(plane, B-spline surface).
template <Real T>
[[nodiscard]] inline HermiteSurfaceCurve<T> hermite_curve(const Plane3<T>& a,
                                                          const BSplineSurface<T, 3>& b,
                                                          const SurfaceCurve<T>& c) {
  namespace s = detail::surface3;
  return s::hermite_of(vec_cast<double>(a.normal), s::as_nurbs(b), c);
}
/// The Hermite form of a curve of intersection(plane, NURBS surface).
template <Real T>
[[nodiscard]] inline HermiteSurfaceCurve<T> hermite_curve(const Plane3<T>& a,
                                                          const NurbsSurface<T, 3>& b,
                                                          const SurfaceCurve<T>& c) {
  namespace s = detail::surface3;
  return s::hermite_of(vec_cast<double>(a.normal), s::as_nurbs(b), c);
}

/// The number of Hermite segments: points - 1 (open) or points (closed, at least 2 points).
template <Real T>
[[nodiscard]] inline std::size_t segment_count(const HermiteSurfaceCurve<T>& h) noexcept {
  const std::size_t n = h.points.size();
  if (n < 2) return 0;
  return h.closed ? n : n - 1;
}

/// Segment i of the curve at t in [0, 1]: R(t) and p(t) (i < segment_count(h), asserted by the
/// caller; tangents must be present: status ok).
template <Real T>
[[nodiscard]] inline HermiteCurvePoint<T> point_at(const HermiteSurfaceCurve<T>& h, std::size_t i,
                                                   T t) noexcept {
  const std::size_t j = i + 1 < h.points.size() ? i + 1 : 0;
  const T len = length(h.points[j] - h.points[i]);
  return {
      hermite(h.points[i], h.points[j], len * h.tangents[i], len * h.tangents[j], t),
      hermite(h.params[i], h.params[j], len * h.param_tangents[i], len * h.param_tangents[j], t)};
}

}  // namespace locus
