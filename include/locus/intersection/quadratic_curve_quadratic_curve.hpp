// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two general quadratic curves (conics) in the plane: intersects() (the book's
// test) and intersection() (find); row int2.quadratic, book section 7.5 (figure 7.5).
// Method: the class of each curve is exact (classify_conic, primitives/quadratic_curve.hpp).
// When one is an ellipse or circle it becomes the frame of ellipse_ellipse.hpp's half-angle
// quartic (to_ellipse, rounded), with that header's root treatment and bound. Otherwise (both
// hyperbolas, parabolas or degenerate): the frame is rotated (one of eight angles) so that both
// y^2 coefficients are large, y is eliminated by the resultant of the two quadratics in y,
// R(x) = (a2 b0 - a0 b2)^2 - (a2 b1 - a1 b2)(a1 b0 - a0 b1), degree <= 4 (the book's approach),
// solved in numeric/roots.hpp near mode with R's rounding bound (64 eps of its terms) as the
// coefficient error; each root x takes the y of the first curve's quadratic at which the second
// is nearer zero. Multiplicities are R's: a tangency is 2 — but two common points with the same
// abscissa in the rotated frame (non-generic) also give a double root and are reported once.
// Parameters: 0 on a general curve; the angle on the ellipse when converted.
// Result (CurvePairIntersection2<T>): empty, point, points (by increasing param_a when one curve
// is an ellipse, else by x in the rotated frame), each with its multiplicity; coincident when
// the coefficients are exactly proportional (the same curve), and also when R vanishes within
// its bound: the curves then share a component (a common line of two line pairs, or equal
// curves up to rounding), whose points are not listed.
// Bound: transversal points within about 64 eps of the curves' scale (relative residual);
// about sqrt(eps) near tangency. Degenerate: any NaN/Inf coefficient: empty.
// The swapped overload gives the same set. Cost: a few microseconds; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/quadratic_curve.hpp>

#include <optional>

namespace locus {

/// The common points of two quadratic curves (see the header comment).
template <Real T>
[[nodiscard]] inline CurvePairIntersection2<T> intersection(const QuadraticCurve2<T>& a,
                                                            const QuadraticCurve2<T>& b) noexcept {
  namespace c = detail::conic2;
  const c::Conic ka = c::as_conic(a), kb = c::as_conic(b);
  if (!is_finite(a.a) || !is_finite(a.b) || !is_finite(a.c) || !is_finite(a.d) || !is_finite(a.e) ||
      !is_finite(a.f) || !is_finite(b.a) || !is_finite(b.b) || !is_finite(b.c) || !is_finite(b.d) ||
      !is_finite(b.e) || !is_finite(b.f))
    return {};
  return c::cast<T>(c::conic_conic(ka, kb));
}

/// Whether two quadratic curves have a common point.
template <Real T>
[[nodiscard]] inline bool intersects(const QuadraticCurve2<T>& a,
                                     const QuadraticCurve2<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}

}  // namespace locus
