// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a line and a 2D Bézier, B-spline or NURBS curve (any PolyCurve2): intersects()
// and intersection(); row int2.linear-polycurve, book sections 7.3-7.4 (figures 7.2-7.4).
// Result CurveHits2<T> (detail/polycurve2.hpp): status, kind (empty, point, points; coincident
// when a whole Bézier piece lies on the line, its ends listed with multiplicity 0) and hits
// ordered by param_a (Line2: t in R, origin + t direction), param_b the curve's own parameter
// (Bézier [0, 1], B-spline/NURBS the knot domain), multiplicity 1 crossing, 2 tangency, 3 an odd
// higher contact. Methods (CurveHitOptions::method):
//  * algebraic (default, the most robust): per Bézier piece the Bernstein coefficients of
//    w(t) n.(C(t) - origin) (n the normal; NURBS: the weighted numerator), roots isolated by
//    Descartes' rule in the Bernstein basis with de Casteljau halving: every simple root is
//    found exactly once and placed by bisection to an ulp of the parameter. A root whose
//    interval has all coefficients within their rounding noise (about 32 (n + 2) eps times
//    their magnitudes) is a tangency or higher contact: one hit, its multiplicity from the
//    signs on either side. Joints and split points found twice are merged.
//  * hierarchy (figure 7.3): boxes of the control polygons tested against the line, halved
//    until smaller than tolerance x scale, then runs of adjacent leaf boxes solved by bisection
//    (or least |distance|): crossings closer than that box size merge into one hit.
//  * raster (figures 7.4, 7.11): the line and the curve drawn into a raster_cells grid over the
//    curve's box; each 8-connected component of shared cells seeds Newton on the 2x2 system.
//    Crossings a few cells apart can merge, and one inside a long near-parallel stretch can
//    be missed (docs/notes/polycurve.md).
// Conditioning: a tangency is reported when the curve comes within max(tolerance^2, 64 eps) x
// scale of the line (scale = the largest |coordinate|); its position is good to about
// sqrt(that gap). Crossings at an angle below sqrt(tolerance) found by the raster or hierarchy
// method are flagged multiplicity 3. Points are C(param_b) rounded; computed in double.
// Bad input: any NaN/Inf: non_finite_input; an invalid curve: validate()'s status; a zero
// direction: degenerate_input; all with no hits. Cost: algebraic O(pieces d^2 log(1/eps)) per
// root; allocates. The swapped overload returns swapped().

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/polycurve2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/line.hpp>

#include <limits>

namespace locus {

namespace detail::polycurve2 {
template <Real T>
[[nodiscard]] inline Lin as_lin(const Line2<T>& l) noexcept {
  return {vec_cast<double>(l.origin), vec_cast<double>(l.direction),
          -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
}
}  // namespace detail::polycurve2

/// The common points of a line and a Bézier / B-spline / NURBS curve (see the header comment).
template <PolyCurve2 C>
[[nodiscard]] CurveHits2<curve_scalar_t<C>> intersection(const Line2<curve_scalar_t<C>>& a,
                                                         const C& b,
                                                         const CurveHitOptions& opt = {}) {
  using T = curve_scalar_t<C>;
  namespace pc = detail::polycurve2;
  return pc::cast<T>(pc::linear_curve(pc::as_lin(a), pc::as_curve(b), opt));
}

/// Swapped arguments: swapped(intersection(b, a)).
template <PolyCurve2 C>
[[nodiscard]] CurveHits2<curve_scalar_t<C>> intersection(const C& a,
                                                         const Line2<curve_scalar_t<C>>& b,
                                                         const CurveHitOptions& opt = {}) {
  return swapped(intersection(b, a, opt));
}

/// Whether the line meets the curve (a hit of intersection()).
template <PolyCurve2 C>
[[nodiscard]] bool intersects(const Line2<curve_scalar_t<C>>& a, const C& b,
                              const CurveHitOptions& opt = {}) {
  return !intersection(a, b, opt).hits.empty();
}
template <PolyCurve2 C>
[[nodiscard]] bool intersects(const C& a, const Line2<curve_scalar_t<C>>& b,
                              const CurveHitOptions& opt = {}) {
  return intersects(b, a, opt);
}

}  // namespace locus
