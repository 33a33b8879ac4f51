// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two parametric surfaces (BezierPatch, BSplineSurface, NurbsSurface, in any
// combination with the same scalar): intersection() returns the intersection curves as polylines;
// row int3.surface-surface, book section 11.8 (figures 11.59, 11.60: two B-spline surfaces and
// the curves in each parameter space). Result SurfaceCurves<T> (intersection/detail/surface3.hpp):
// status and curves, each closed or open (ends on a domain boundary of either surface), with
// points (on the first surface), param_a (u, v on the first) and param_b (on the second).
// Method: seeds by subdivision: every Bézier span of each surface is split into
// (opt.grid / 2)^2 leaves; for each pair of leaves whose control-net boxes overlap, a
// minimum-norm Gauss-Newton iteration on S_a(u, v) = S_b(s, t) from the leaf centres gives a point
// of the curve. Tracing: from the first seed not yet on a traced curve, predictor (a step h along
// the tangent n_a x n_b, h = opt.step times the box diagonal, halved where the corrector fails or
// the tangent turns by more than ~25 degrees) and corrector (Newton on the four parameters with
// S_a = S_b and the plane through the predicted point normal to the tangent), in both directions
// until a domain boundary (the end point solved on it) or the start (a closed loop). Every point
// satisfies |S_a - S_b| <= 2^-36 times the size. Not found or cut short: curve components that
// no leaf pair seeds (tiny loops), branches through points where the surfaces touch (tangent
// zero: the branch ends there), and branch crossings (traced through or ended). Degenerate:
// invalid surfaces: validate()'s status; coincident surfaces are not detected (more than 2^14
// overlapping leaf pairs stop the seeding with limit_exceeded). Float input is computed in double.
// Cost: O(leaf pairs) seeds plus O(length / h) Newton steps per curve; allocates.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/surface3.hpp>

#include <type_traits>

namespace locus {

/// The intersection curves of two surfaces (see the header comment). A and B are each a
/// BezierPatch<T, 3>, BSplineSurface<T, 3> or NurbsSurface<T, 3>.
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> intersection(const BSplineSurface<T, 3>& a,
                                                   const BSplineSurface<T, 3>& b,
                                                   const SurfaceCurveOptions& opt = {}) {
  namespace s = detail::surface3;
  return s::cast<T>(s::surface_curves(s::as_nurbs(a), s::as_nurbs(b), opt));
}
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> intersection(const NurbsSurface<T, 3>& a,
                                                   const NurbsSurface<T, 3>& b,
                                                   const SurfaceCurveOptions& opt = {}) {
  namespace s = detail::surface3;
  return s::cast<T>(s::surface_curves(s::as_nurbs(a), s::as_nurbs(b), opt));
}
template <Real T>
[[nodiscard]] inline SurfaceCurves<T> intersection(const BezierPatch<T, 3>& a,
                                                   const BezierPatch<T, 3>& b,
                                                   const SurfaceCurveOptions& opt = {}) {
  namespace s = detail::surface3;
  return s::cast<T>(s::surface_curves(s::as_nurbs(a), s::as_nurbs(b), opt));
}

namespace detail::surface3 {
/// The scalar of a parametric surface type (BezierPatch, BSplineSurface, NurbsSurface in 3D).
template <class S>
struct SurfaceScalar {};
template <Real T>
struct SurfaceScalar<BezierPatch<T, 3>> {
  using type = T;
};
template <Real T>
struct SurfaceScalar<BSplineSurface<T, 3>> {
  using type = T;
};
template <Real T>
struct SurfaceScalar<NurbsSurface<T, 3>> {
  using type = T;
};
}  // namespace detail::surface3

/// Two surfaces of different kinds (a Bézier patch and a B-spline surface, ...), same scalar.
template <class A, class B>
requires(!std::is_same_v<A, B> && std::is_same_v<typename detail::surface3::SurfaceScalar<A>::type,
                                                 typename detail::surface3::SurfaceScalar<B>::type>)
    [[nodiscard]] inline auto intersection(const A& a, const B& b,
                                           const SurfaceCurveOptions& opt = {}) {
  namespace s = detail::surface3;
  using T = typename s::SurfaceScalar<A>::type;
  return s::cast<T>(s::surface_curves(s::as_nurbs(a), s::as_nurbs(b), opt));
}

}  // namespace locus
