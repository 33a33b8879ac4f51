// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a circle and an ellipse in the plane: intersects() (the book's test, on the
// curves) and intersection() (find), relation() (the regions); row int2.quadratic. Method (book
// section 7.5.2, figure 7.10, and 7.5 for the general conic of figure 7.5): the circle is mapped
// onto the unit circle; the other curve, written in that frame, is restricted to it by the
// half-angle substitution x = (1 - s^2)/(1 + s^2), y = 2s/(1 + s^2): a quartic in s whose real
// roots are the common points one to one (the parametrisation's missing point is rotated to where
// the other curve is farthest from zero) and whose multiplicities are the contact orders: the
// resultant of the book in a form with no spurious roots. Roots: numeric/ roots.hpp near mode, with
// the quartic's coefficient rounding bound (64 eps of its terms) as coefficient_error: a tangency
// is reported (multiplicity 2) when the quartic's turning point is within that bound of zero, so
// exact tangencies are found and near-tangencies closer than about sqrt(eps) merge into one
// tangency; crossings far from tangency are counted exactly as for the exact curves. Not exact: the
// quartic's coefficients are rounded (degree-4 polynomials of the inputs through a frame change;
// exact evaluation would need the resultant's degree-16 terms). Parameters: the angle on a circle
// or ellipse (point_at), 0 on a general quadratic curve. Result (CurvePairIntersection2<T>): empty,
// point, points (by increasing param_a), each with its multiplicity; coincident when the quartic
// vanishes within its bound (equal curves). Bound: points lie on the circle within 8 eps m and on
// the other within 64 eps m relative to its scale away from tangency, about sqrt(eps) m along the
// curves near tangency. Degenerate: a non-positive extent or radius (radius 0: the point, exactly
// tested), parallel axes, any NaN/Inf: empty. The swapped overload returns swapped(). Cost: a few
// microseconds.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/ellipse.hpp>

namespace locus {

/// The common points of a circle and an ellipse (see the header comment).
template <Real T>
[[nodiscard]] inline CurvePairIntersection2<T> intersection(const Circle2<T>& a,
                                                            const Ellipse2<T>& b) noexcept {
  namespace c = detail::conic2;
  return c::cast<T>(c::conic_conic(c::as_conic(a), c::as_conic(b)));
}
/// Whether they have a common point.
template <Real T>
[[nodiscard]] inline bool intersects(const Circle2<T>& a, const Ellipse2<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline CurvePairIntersection2<T> intersection(const Ellipse2<T>& a,
                                                            const Circle2<T>& b) noexcept {
  return swapped(intersection(b, a));
}
template <Real T>
[[nodiscard]] inline bool intersects(const Ellipse2<T>& a, const Circle2<T>& b) noexcept {
  return intersects(b, a);
}
template <Real T>
[[nodiscard]] inline RegionRelation relation(const Ellipse2<T>& a, const Circle2<T>& b) noexcept {
  namespace c = detail::conic2;
  return c::ellipse_relation(c::as_conic(a), c::as_conic(b));
}

/// How the two regions lie relative to each other (figures 7.7-7.9): from intersection() (a
/// point of odd multiplicity means overlapping), then a boundary point of each, away from the
/// tangencies, tested exactly against the other region.
template <Real T>
[[nodiscard]] inline RegionRelation relation(const Circle2<T>& a, const Ellipse2<T>& b) noexcept {
  namespace c = detail::conic2;
  return c::ellipse_relation(c::as_conic(a), c::as_conic(b));
}

}  // namespace locus
