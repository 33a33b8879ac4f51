// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two circles in the plane: intersects() (the book's test, on the curves),
// intersection() (find) and relation() (the disks: separated, touching, overlapping, one inside
// the other, tangent inside, equal); row int2.quadratic, book section 7.5.1 (figure 7.6).
// Parameters: the angle in (-pi, pi] of point - center on each circle.
// Result (CurvePairIntersection2<T>, intersection/result.hpp): empty; point (a tangency, outside
// or inside: multiplicity 2); points (two crossings, multiplicity 1: point[0] to the right of
// the direction c0 -> c1, point[1] to its left); coincident (equal circles, count 0).
// Exact decisions: with u = c1 - c0, the signs of |u|^2 - (r0 + r1)^2 and |u|^2 - (r0 - r1)^2
// (polynomials in the inputs, core/exact_poly.hpp) decide separated / tangent outside /
// crossing / tangent inside / nested, so relation() and the count never use a tolerance.
// Constructed points: after exact power-of-two scaling, the foot c0 + a u/|u| with a = (|u| +
// (r0 - r1)(r0 + r1)/|u|)/2 and the half chord sqrt((r0 - a)(r0 + a)); a tangency point is
// c0 +- r0 u/|u|. Bound: each point within 16 eps m of both circles (m = the largest |coordinate|
// and radius; eps of T); its position along the circles degrades to sqrt(eps) m near tangency.
// Degenerate: radius 0 is a point circle (met when on the other circle, as a tangency; two equal
// point circles: point); a negative radius or any NaN/Inf: kind empty, relation undecided.
// Swapping the arguments gives the same set (points in the other order, parameters swapped).
// Cost: about 30 exact-sign terms and a few square roots; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/circle.hpp>

namespace locus {

/// The common points of two circles (see the header comment).
template <Real T>
[[nodiscard]] inline CurvePairIntersection2<T> intersection(const Circle2<T>& a,
                                                            const Circle2<T>& b) noexcept {
  namespace c = detail::conic2;
  return c::cast<T>(c::circle_circle(vec_cast<double>(a.center), double(a.radius),
                                     vec_cast<double>(b.center), double(b.radius)));
}

/// Whether the two circles (the curves) have a common point; exact.
template <Real T>
[[nodiscard]] inline bool intersects(const Circle2<T>& a, const Circle2<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}

/// How the two disks lie relative to each other (exact; see the header comment).
template <Real T>
[[nodiscard]] inline RegionRelation relation(const Circle2<T>& a, const Circle2<T>& b) noexcept {
  return detail::conic2::circle_relation(vec_cast<double>(a.center), double(a.radius),
                                         vec_cast<double>(b.center), double(b.radius));
}

}  // namespace locus
