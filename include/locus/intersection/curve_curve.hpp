// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two 2D Bézier, B-spline or NURBS curves (any two PolyCurve2, mixed kinds, the
// same scalar type): intersects() and intersection(); row int2.polycurve, book section 7.4
// (7.4.1 algebraic, figure 7.11 raster). Result CurveHits2<T> (detail/polycurve2.hpp), hits
// ordered by param_a, param_b on the second curve; multiplicity 1 a crossing, 2 a tangency, 3 an
// odd higher contact; kind empty, point, points, or coincident when the curves share a stretch
// (its two ends come as consecutive hits of multiplicity 0). Self-intersections: curve_self.hpp.
// Methods (CurveHitOptions::method; derivations in docs/notes/polycurve.md):
//  * algebraic (default) and hierarchy: control-polygon box pairs of the rational Bézier pieces
//    halved until below tolerance x scale (scale = the largest |coordinate|); each cluster seeds
//    Newton (Levenberg-Marquardt) on A(s) - B(t) = 0: crossings to a few ulps.
//  * resultant (7.4.1): the lower-degree piece (m <= 4) implicitised by its Bezout matrix, the
//    other (degree n) substituted: a Bernstein polynomial of degree m n, roots isolated by
//    Descartes' rule (a node settled only when every coefficient exceeds its rounding bound),
//    inverted on the implicit piece, polished by Newton; subdivision instead above degree 4 on
//    both sides, m n > 64, on overflow, or when the resultant vanishes (one algebraic curve).
//  * raster (figure 7.11): both drawn into raster_cells cells; each shared component seeds
//    Newton; crossings a few cells apart can merge. curve_raster() returns the grid.
// Shared stretches (every method): from piece ends lying on the other piece, confirmed at
// deg(a) deg(b) + 2 points between, within max(gap, 16 eps_T x scale).
// Conditioning: crossings closer than tolerance x scale may merge (resultant: about the square
// root of its noise); a tangency is found when the gap is below max(tolerance^2, 64 eps) x scale
// and located to about its square root. Computed in double (beyond 2^+-500 on an exactly
// rescaled copy). Bad input: NaN/Inf: non_finite_input; an invalid curve: its validate()
// status; max_steps exhausted: limit_exceeded. Cost: O(k log(1/tolerance)) box pairs for k
// crossings, more near tangencies; resultant O((m n)^2) per piece pair; allocates. Swapped
// arguments give the same points with parameters exchanged.

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
