// SPDX-License-Identifier: BSL-1.0
#pragma once
// Self-intersections of one 2D Bézier, B-spline or NURBS curve: self_intersection(); row
// int2.polycurve, book section 7.4 (the loop of a cubic). Result CurveHits2<T>
// (detail/polycurve2.hpp): the double points, each once, with param_a < param_b the two
// parameters of the point on the curve, ordered by param_a; multiplicity 1 a crossing of the two
// branches, 2 the branches touch (tangents parallel within sqrt(tolerance)); kind empty, point,
// points, or coincident when the curve retraces a stretch of itself (the overlap's ends listed
// as consecutive hits of multiplicity 0, param_a the first pass, param_b the second).
// Method: the curve (its Bézier pieces; a B-spline or NURBS through its spans) is cut by
// de Casteljau halving into monotone segments, whose projected control points advance along one
// direction (no self-intersection inside one: variation diminishing); every pair of segments
// whose boxes meet is intersected by intersection() of curve_curve.hpp with the given options
// (method, tolerance, budget), and the joint of two consecutive segments (their common end) is
// excluded, within sqrt(tolerance) of either segment's parameter width. A cusp is not a double
// point: its segment stops after 20 halvings and the cusp is not reported. The closing point of
// a closed curve (first point == last point) is not reported either.
// Conditioning: as intersection() of curve_curve.hpp; in addition a loop whose two parameters
// both lie within sqrt(tolerance) x segment width of a segment joint is taken for the joint,
// and a loop inside the 2^-20 of a piece that holds a cusp is not separated from it.
// Bad input: NaN/Inf: non_finite_input; an invalid curve: its validate() status; no hits.
// Exhausted budget (max_steps halvings or box pairs of one segment pair): limit_exceeded.
// Cost: O(s^2) box tests for s monotone segments (a few per inflection or turn), then the
// pairwise cost of intersection(); allocates.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/polycurve2.hpp>
#include <locus/intersection/result.hpp>

namespace locus {

/// The double points of a Bézier / B-spline / NURBS curve (see the header comment).
template <PolyCurve2 C>
[[nodiscard]] CurveHits2<curve_scalar_t<C>> self_intersection(const C& c,
                                                              const CurveHitOptions& opt = {}) {
  namespace pc = detail::polycurve2;
  return pc::cast<curve_scalar_t<C>>(pc::self_curve(pc::as_curve(c), opt));
}

}  // namespace locus
