// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a circle and a general quadratic curve in the plane: intersects() (the book's
// test, on the curves) and intersection() (find); row int2.quadratic.
// Method (book section 7.5, figures 7.5 and 7.10; derivation: docs/notes/intersection.md, "Conic
// pairs: exact combinatorics"): each curve's implicit equation exactly as stored (a circle
// |X - C|^2 = r^2, an ellipse sum_i (axis[i] . (X - C))^2 / extent[i]^2 = 1 with the axes as
// given) times a power of two has integer coefficients. After an integer shear x' = x + k y, the
// resultant eliminating y is an integer polynomial R(x') of degree <= 4; for the k whose R has
// the most distinct roots, its real roots are the real common points one to one and its root
// multiplicities are the intersection multiplicities (1 a crossing, 2 a tangency, 3 or 4 a higher
// contact). Decided exactly: a floating-point filter with rigorous error bounds (the sign of R's
// discriminant, certified sign changes around each root) settles simple roots in microseconds;
// otherwise the gcd chain and Sturm sequences of numeric/roots.hpp's exact engine. Distinct points
// are never merged (points closer than an ulp may share a value, still listed separately).
// Coordinates: x' correctly rounded (exact path) or bracketed by the filter (to 2^-42 of the
// points' scale, or 2^-28 where Newton steps on both curves then apply), y from a curve's
// quadratic at x'; k is also chosen so that the projection is transversal to a curve at every
// point. Bound: points within about 2^-40 of the coordinates' magnitude, a few ulps typically.
// Parameters: the angle on a circle or ellipse (point_at), 0 on a general quadratic curve.
// Result (CurvePairIntersection2<T>): empty, point, points (by increasing param_a), each with its
// multiplicity; coincident for the same curve (proportional coefficients, exact). Degenerate: a
// non-positive extent or radius (radius 0: the point, exactly tested), parallel axes, any NaN/Inf:
// empty. The swapped overload returns swapped(). Cost: a few microseconds when the filter decides;
// tangencies and near-tangencies use big integers (tens to hundreds of microseconds, allocating;
// std::bad_alloc falls back to the rounded half-angle quartic of section 7.5.2).

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/quadratic_curve.hpp>

namespace locus {

/// The common points of a circle and a quadratic curve (see the header comment).
template <Real T>
[[nodiscard]] inline CurvePairIntersection2<T> intersection(const Circle2<T>& a,
                                                            const QuadraticCurve2<T>& b) noexcept {
  namespace c = detail::conic2;
  return c::cast<T>(c::conic_conic(c::as_conic(a), c::as_conic(b)));
}
/// Whether they have a common point.
template <Real T>
[[nodiscard]] inline bool intersects(const Circle2<T>& a, const QuadraticCurve2<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline CurvePairIntersection2<T> intersection(const QuadraticCurve2<T>& a,
                                                            const Circle2<T>& b) noexcept {
  return swapped(intersection(b, a));
}
template <Real T>
[[nodiscard]] inline bool intersects(const QuadraticCurve2<T>& a, const Circle2<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
