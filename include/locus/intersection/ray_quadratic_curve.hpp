// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a ray and a general quadratic curve in the plane: intersects() (the book's test)
// and intersection() (find); row int2.linear-quadratic, book section 7.2 (figure 7.1). Parameters:
// Ray2 t >= 0 (origin + t direction); on the quadratic curve 0 (a general conic has no
// parametrisation). Result (LinearCurveIntersection2<T>): empty; point (a crossing, or a tangency
// with multiplicity 2); points (two, by increasing param_a); or the component itself, kind ray
// (count 2: parameters 0 and 1), when it lies on the curve (a line component of a degenerate
// conic). Exact decisions: q(t) = Q(o + t d) = A t^2 + B t + C; the signs of A, B, C, of q and q'
// at a segment's p1 and of B^2 - 4 A C are polynomials in the coefficients and coordinates (degree
// 6) evaluated exactly (core/exact_poly.hpp): the count, tangency, the linear case A = 0 (a
// direction along an asymptote or a parabola's axis) and containment are exact for the curve as
// given. Constructed points: the stable quadratic root form t = q/A, C/q with q = -(B + sign(B)
// sqrt(B^2 - 4AC))/2, in double (no scaling: coefficients of mixed degree). Bound: each root t is
// that of a q whose coefficients are perturbed by a few eps of their terms' magnitudes; tests
// check |Q(X)| <= 64 eps (S(X) + |grad Q(X)|_1 m) (S the sum of |terms| of Q at X, m the
// largest |coordinate| of the component and X) away from tangency. Degenerate:
// any NaN/Inf: empty; all coefficients zero: the component lies on the "curve" (the plane);
// a zero direction acts as its origin. The swapped overload returns swapped().
// Cost: about 1 us: a running-error filter, the exact terms (about 250) only near zero.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/quadratic_curve.hpp>
#include <locus/primitives/ray.hpp>

namespace locus {

/// The common points of a ray and a general quadratic curve (see the header comment).
template <Real T>
[[nodiscard]] inline LinearCurveIntersection2<T> intersection(
    const Ray2<T>& a, const QuadraticCurve2<T>& b) noexcept {
  return detail::conic2::cast<T>(
      detail::conic2::linear_conic(detail::conic2::as_lin(a), detail::conic2::as_conic(b)));
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline LinearCurveIntersection2<T> intersection(const QuadraticCurve2<T>& a,
                                                              const Ray2<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a ray and a general quadratic curve have a common point (exact but for the cases the
/// header names).
template <Real T>
[[nodiscard]] inline bool intersects(const Ray2<T>& a, const QuadraticCurve2<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const QuadraticCurve2<T>& a, const Ray2<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
