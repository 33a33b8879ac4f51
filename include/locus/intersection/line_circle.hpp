// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a line and a circle in the plane: intersects() (the book's test) and
// intersection() (find); row int2.linear-quadratic, book section 7.2 (figure 7.1).
// Parameters: Line2 t in R (origin + t direction); on the circle the angle in (-pi, pi] of point -
// center. Result (LinearCurveIntersection2<T>, intersection/result.hpp): empty; point (one
// crossing, or a tangency: multiplicity 2); points (two crossings, by increasing param_a,
// multiplicity 1). Exact decisions: q(t) = |p(t) - c|^2 - r^2 = A t^2 + B t + C; the signs of the
// discriminant r^2 |d|^2 - (d x (o - c))^2, of C and B at the origin and (segment) at p1 are
// polynomials in the input doubles, evaluated exactly (core/exact_poly.hpp); they fix how many
// roots lie in the parameter domain, tangency included, never a tolerance. Constructed points: the
// stable form t = -(d.w)/|d|^2 -+ sqrt((r - h)(r + h))/|d| (h = |d x w| / |d| from an accurate
// cross product, core/crossing.hpp), computed in double after exact power-of-two scaling; an input
// point lying exactly on the circle is returned exactly (t = 0 or 1). Bound: each point is within 8
// eps m of both the line and the circle (m = the largest of |coordinates| of the inputs and r, eps
// of T); along the line its error is 8 eps m away from tangency and grows like sqrt(eps) m at a
// near-tangency (the problem's conditioning). Degenerate: radius 0 is the point circle (met
// only when the line passes through the centre, as a tangency); a negative radius is empty; a
// zero direction or zero-length segment acts as its origin / p0 (parameter 0, met when exactly on
// the circle). Any NaN or infinite input gives kind empty. The swapped overload returns
// swapped(). Cost: about 1 us: a running-error filter decides the signs, the exact terms
// (about 80) are built only near tangency or for an end point on the circle.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

/// The common points of a line and a circle (see the header comment).
template <Real T>
[[nodiscard]] inline LinearCurveIntersection2<T> intersection(const Line2<T>& a,
                                                              const Circle2<T>& b) noexcept {
  return detail::conic2::cast<T>(
      detail::conic2::linear_conic(detail::conic2::as_lin(a), detail::conic2::as_conic(b)));
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline LinearCurveIntersection2<T> intersection(const Circle2<T>& a,
                                                              const Line2<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a line and a circle have a common point (exact but for the cases the header names).
template <Real T>
[[nodiscard]] inline bool intersects(const Line2<T>& a, const Circle2<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Circle2<T>& a, const Line2<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
