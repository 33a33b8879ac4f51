// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two parametric surfaces (BezierPatch, BSplineSurface, NurbsSurface, in any
// combination with the same scalar): intersection() returns the intersection curves as polylines;
// row int3.surface-surface, book section 11.8 (figures 11.59, 11.60). Result SurfaceCurves<T>
// (intersection/detail/surface3.hpp): status; curves (points on the first surface, param_a and
// param_b; closed, or open with first_end/last_end: boundary, tangent_point or stalled; tangent
// marks a curve along which the surfaces touch); contacts (isolated touching points); and
// coincident_a/coincident_b (parameter rectangles where the surfaces share a 2D region).
// Method: every Bézier span is split into (opt.grid / 2)^2 leaves. Coincidence: a leaf whose
// 3 x 3 corner/edge/centre samples all project (Gauss-Newton closest point) onto the other
// surface within 2^-36 times the size, normals parallel to sine 2^-20, is coincident: reported
// (merged into rectangles) and never traced; a leaf half on the other surface is not (the
// region is known to within one leaf). Seeds: Gauss-Newton on S_a = S_b from the centres of
// overlapping leaf pairs; where the leaves' (sampled) normal cones overlap (Sederberg's loop
// criterion), once per leaf, Newton on the contact system (S_b the foot of S_a, normals
// parallel): a solution with |S_a - S_b| <= 2^-36 times the size is a contact, isolated (system
// of rank 4) or on a curve of contact (rank 3: traced along the kernel); one with a gap is the
// centre of a possible small loop, seeded at the radius sqrt(-2 gap / relative curvature).
// Tracing: predictor along n_a x n_b, Newton corrector, step h = opt.step times the size,
// halved (down to 2^-20 h) on failure or turns over ~25 degrees; ends on a domain boundary, at
// the start (closed), or where the normals turn parallel (tangent_point; the touching point is
// then located as a contact). Every point satisfies |S_a - S_b| <= 2^-36 times the size.
// Tolerances decide tangency and coincidence: surfaces closer than 2^-36 of the size count as
// touching or coincident, so a float-rounded copy (error 2^-24) is not coincident; seeds and
// curves within 2^-14 of the size of a contact are dropped as its shadow; a loop shallower than
// 2^-36 of the size is reported as a contact. Limits: loops smaller than about 2^-20 h,
// features between the 3 x 3 samples, branch crossings (traced through); nearly coincident
// surfaces (farther apart than 2^-36, normals within 2^-26) yield no curves there.
// Invalid surfaces: validate()'s status (non_finite_input, ...); more than 2^14 non-coincident
// overlapping leaf pairs: limit_exceeded. Float input is computed in double. Cost: O(leaf
// pairs) seeds plus O(length / h) Newton steps per curve; allocates.

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
