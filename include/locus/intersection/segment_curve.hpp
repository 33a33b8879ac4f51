// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a segment and a 2D Bézier, B-spline or NURBS curve (any PolyCurve2): intersects()
// and intersection(); row int2.linear-polycurve, book sections 7.3-7.4 (figures 7.2-7.4).
// Everything as in line_curve.hpp (result, methods, conditioning, bad input, cost), with
// param_a the Segment2: t in [0, 1], (1 - t) p0 + t p1: the hits of the supporting line whose
// parameter lies in that range (a hit within 16 eps relative of the range's end is kept and its
// parameter clamped). A zero direction (a zero-length segment) gives degenerate_input and no hits.
// The swapped overload returns swapped().

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/polycurve2.hpp>
#include <locus/intersection/line_curve.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/segment.hpp>

#include <limits>

namespace locus {

namespace detail::polycurve2 {
template <Real T>
[[nodiscard]] inline Lin as_lin(const Segment2<T>& l) noexcept {
  return {vec_cast<double>(l.p0), vec_cast<double>(l.p1) - vec_cast<double>(l.p0), 0.0, 1.0};
}
}  // namespace detail::polycurve2

/// The common points of a segment and a Bézier / B-spline / NURBS curve (see line_curve.hpp).
template <PolyCurve2 C>
[[nodiscard]] CurveHits2<curve_scalar_t<C>> intersection(const Segment2<curve_scalar_t<C>>& a,
                                                         const C& b,
                                                         const CurveHitOptions& opt = {}) {
  using T = curve_scalar_t<C>;
  namespace pc = detail::polycurve2;
  return pc::cast<T>(pc::linear_curve(pc::as_lin(a), pc::as_curve(b), opt));
}

/// Swapped arguments: swapped(intersection(b, a)).
template <PolyCurve2 C>
[[nodiscard]] CurveHits2<curve_scalar_t<C>> intersection(const C& a,
                                                         const Segment2<curve_scalar_t<C>>& b,
                                                         const CurveHitOptions& opt = {}) {
  return swapped(intersection(b, a, opt));
}

/// Whether the segment meets the curve (a hit of intersection()).
template <PolyCurve2 C>
[[nodiscard]] bool intersects(const Segment2<curve_scalar_t<C>>& a, const C& b,
                              const CurveHitOptions& opt = {}) {
  return !intersection(a, b, opt).hits.empty();
}
template <PolyCurve2 C>
[[nodiscard]] bool intersects(const C& a, const Segment2<curve_scalar_t<C>>& b,
                              const CurveHitOptions& opt = {}) {
  return intersects(b, a, opt);
}

}  // namespace locus
