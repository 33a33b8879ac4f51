// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two 2D Bézier, B-spline or NURBS curves (any two PolyCurve2, mixed kinds, the
// same scalar type): intersects() and intersection(); row int2.polycurve, book section 7.4
// (figure 7.11). Result CurveHits2<T> (detail/polycurve2.hpp): kind empty, point, points, or
// coincident (the two curves are the same pieces, as given or reversed: the two ends listed,
// multiplicity 0); hits ordered by param_a (the first curve's own parameter), param_b on the
// second; multiplicity 1 a crossing, 2 a tangency (tangents parallel within sqrt(tolerance)).
// Methods (CurveHitOptions::method):
//  * algebraic (default) and hierarchy: both curves cut into rational Bézier pieces, pairs of
//    control-polygon boxes refined by de Casteljau halving of the larger until both are smaller
//    than tolerance x scale (scale = the largest |coordinate|); leaf pairs whose parameter
//    rectangles touch form a cluster, and each cluster seeds Newton (Levenberg-Marquardt) on
//    A(s) - B(t) = 0. Crossings converge quadratically to a few ulps; a cluster whose closest
//    points stay farther apart than max(tolerance^2, 64 eps) x scale is a near miss (no hit).
//  * raster (figure 7.11): both curves drawn into a raster_cells grid over their joint box;
//    each 8-connected component of cells holding both seeds Newton. Crossings a few cells apart
//    can merge (docs/notes/polycurve.md). curve_raster() returns the grid itself.
// Conditioning: distinct crossings closer than the leaf size (tolerance x scale) may merge into
// one; a tangency is found when the gap is below max(tolerance^2, 64 eps) x scale and located
// to about sqrt of that. Overlaps other than identical pieces (a curve and a sub-arc of it)
// are not detected: the subdivision runs into max_steps and reports limit_exceeded.
// Self-intersections are not computed. Computed in double.
// Bad input: NaN/Inf: non_finite_input; an invalid curve: its validate() status; no hits.
// Cost: O(k log(1/tolerance)) box pairs for k crossings of well separated curves, more near
// tangencies; allocates. The swapped order gives the same points with parameters exchanged.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/polycurve2.hpp>
#include <locus/intersection/result.hpp>

#include <type_traits>

namespace locus {

/// The common points of two Bézier / B-spline / NURBS curves (see the header comment).
template <PolyCurve2 A, PolyCurve2 B>
requires std::is_same_v<curve_scalar_t<A>, curve_scalar_t<B>>
[[nodiscard]] CurveHits2<curve_scalar_t<A>> intersection(const A& a, const B& b,
                                                         const CurveHitOptions& opt = {}) {
  namespace pc = detail::polycurve2;
  return pc::cast<curve_scalar_t<A>>(pc::curve_curve(pc::as_curve(a), pc::as_curve(b), opt));
}

/// Whether two curves meet (a hit of intersection()).
template <PolyCurve2 A, PolyCurve2 B>
requires std::is_same_v<curve_scalar_t<A>, curve_scalar_t<B>>
[[nodiscard]] bool intersects(const A& a, const B& b, const CurveHitOptions& opt = {}) {
  return !intersection(a, b, opt).hits.empty();
}

/// The raster of the two curves on a grid of `cells` along the longer side of their joint box
/// (figures 7.4 and 7.11): mask bit 1 where the first curve passes, bit 2 the second.
template <PolyCurve2 A, PolyCurve2 B>
requires std::is_same_v<curve_scalar_t<A>, curve_scalar_t<B>>
[[nodiscard]] CurveRaster2<curve_scalar_t<A>> curve_raster(const A& a, const B& b, int cells) {
  namespace pc = detail::polycurve2;
  return pc::cast<curve_scalar_t<A>>(pc::raster(pc::as_curve(a), pc::as_curve(b), cells));
}

}  // namespace locus
