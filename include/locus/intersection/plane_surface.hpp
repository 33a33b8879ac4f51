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

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/surface3.hpp>
#include <locus/primitives/plane.hpp>

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

}  // namespace locus
