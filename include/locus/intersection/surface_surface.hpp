// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two parametric surfaces (BezierPatch, BSplineSurface, NurbsSurface, in any
// combination with the same scalar); row int3.surface-surface, book section 11.8 (figures 11.59,
// 11.60). Result SurfaceCurves<T> (intersection/detail/surface3.hpp): status; curves as
// polylines (points on the first surface, param_a, param_b; closed, or open with
// first_end/last_end = boundary, tangent_point or stalled; `tangent` marks a curve along which
// the surfaces touch); contacts (isolated touching points); coincident_a/coincident_b
// (parameter rectangles where the surfaces share a 2D region). Derivation and the exact rules:
// docs/notes/surface_intersection.md. Method: every Bézier span is cut into (opt.grid / 2)^2
// leaves. A leaf whose 3 x 3 samples project onto the other surface within 2^-36 of the size
// (normals parallel to sine 2^-20) is coincident: reported, merged into rectangles (exact to
// one leaf), never traced. Other overlapping leaf pairs: Gauss-Newton seeds on S_a = S_b from
// their centres; where their normal cones overlap (Sederberg's loop criterion), Newton on the
// contact system (S_b the foot of S_a, normals parallel) gives a contact (gap <= 2^-36 of the
// size; isolated at rank 4, a traced curve of contact at rank 3) or the centre of a possible
// small loop, seeded at radius sqrt(-2 gap / relative curvature). Tracing: predictor along
// n_a x n_b, Newton corrector, step h = opt.step times the size, halved down to 2^-20 h; a
// branch ends on a domain bound, at its start (closed) or where the normals turn parallel
// (tangent_point, the contact then located). Every point has |S_a - S_b| <= 2^-36 of the size.
// Tolerance, not exactness, decides tangency and coincidence: surfaces within 2^-36 of the size
// touch or coincide (a float-rounded copy, 2^-24 off, does not); seeds and curves within 2^-14
// of the size of a contact are its shadow and dropped. Missed: loops below about 2^-18 h,
// features between the samples, curves of nearly coincident surfaces (apart by more than 2^-36,
// normals within 2^-26); branch crossings are traced through. Invalid surfaces: validate()'s
// status; more than 2^14 non-coincident overlapping leaf pairs: limit_exceeded. Float input is
// computed in double. Cost: O(leaf pairs) seeds and contact solves plus O(length / h) Newton
// steps per curve; allocates.

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
