// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a plane and a parametric surface (BezierPatch, BSplineSurface, NurbsSurface):
// intersection() returns the intersection curves as polylines; row int3.plane-surface, book
// section 11.7 (figures 11.53-11.58). Plane3 {normal N (any length), constant k}: N.X = k.
// Result SurfaceCurves<T> (intersection/detail/surface3.hpp): status and curves, each closed (a
// loop; first point not repeated) or open (both ends on the domain boundary), with points (3D)
// and param_b (u, v; param_a empty). Method (docs/notes/surface_intersection.md): each Bézier
// span is covered by an opt.grid x opt.grid grid (figure 11.56); the sign of N.S(u, v) - k at the
// nodes, zero counting as positive (a symbolic perturbation: consistent topology), decides which
// cell edges cross; each crossing is bisected to full precision and evaluated on the surface;
// saddle cells are split by the centre sign, pieces chained across cells and spans. Every point
// lies on the surface and within a few ulps of the plane. Hidden features: a cell with equal
// corner signs is checked by subdivision (exact hull rejection, 5 levels); when it hides a sign
// region the grid is doubled, up to 256 per span, else limit_exceeded (curves found returned).
// Not found: two crossings of one edge of a mixed cell, features below 2^-5 of a 256-cell, parts
// where the surface lies in the plane. Degenerate: zero normal: degenerate_input; NaN/Inf:
// non_finite_input; invalid surface: validate()'s status. Float input is computed in double.
// Cost: (grid + 1)^2 surface evaluations per span plus 64 per crossing; allocates.
// Hermite form (figures 11.54-11.57): hermite_curve(plane, surface, curve) adds at every point
// the unit tangent T = N x (S_u x S_v) (oriented along the curve) and its (u, v) velocity q per
// unit arc length (S_u q.x + S_v q.y = T); where the plane touches the surface the chord through
// the neighbours replaces it. point_at(h, i, t), t in [0, 1], evaluates segment i as the cubic
// Hermite R(t) in 3-space (in the plane, O(h^4) from the surface) and p(t) in (u, v) (S(p(t))
// O(h^4) from the plane), h the segment length; hermite_basis(t) gives the basis. Status: the
// surface's, non_finite_input, degenerate_input, empty_input (no points), invalid_input (points
// and parameters of different counts). Cost: one derivative evaluation per point.

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
