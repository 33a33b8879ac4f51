// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a ray and a ellipse in the plane: intersects() (the book's test) and
// intersection() (find); row int2.linear-quadratic, book section 7.2 (figure 7.1).
// Parameters: Ray2 t >= 0 (origin + t direction); on the ellipse the angle a of point_at(e, a)
// (axes expected orthonormal, extents positive; the curve is the zero set of evaluate(e, .)).
// Result (LinearCurveIntersection2<T>): empty; point (a crossing, or a tangency with
// multiplicity 2); points (two, by increasing param_a). Exact decisions: with alpha_i = u_i.(o -
// c), beta_i = u_i.d, the discriminant of q(t) is 4 e0^2 e1^2 (e1^2 beta0^2 + e0^2 beta1^2 -
// ((u0 x u1)(w x d))^2), a polynomial in the inputs of degree 8 whose sign is exact (core/
// exact_poly.hpp), as are the signs of q and q' at the end points: count, tangency and the
// domain test are exact for the ellipse as given. Constructed points: the line mapped into the
// ellipse's unit-circle frame, then the stable root form of line_circle.hpp, in double. Bound:
// each point within 16 eps m (e_max / e_min) of the line and of the ellipse (m = the largest
// |coordinate| of the inputs and extents), sqrt(eps) m along the line at a near-tangency.
// Degenerate: an extent <= 0, parallel or zero axes, any NaN/Inf: empty. A zero direction acts as
// its origin. The swapped overload returns swapped(). Cost: about 1 us: a running-error filter
// decides the signs; the exact terms (up to about 300) only near tangency; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/ray.hpp>

namespace locus {

/// The common points of a ray and a ellipse (see the header comment).
template <Real T>
[[nodiscard]] inline LinearCurveIntersection2<T> intersection(const Ray2<T>& a,
                                                              const Ellipse2<T>& b) noexcept {
  return detail::conic2::cast<T>(
      detail::conic2::linear_conic(detail::conic2::as_lin(a), detail::conic2::as_conic(b)));
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline LinearCurveIntersection2<T> intersection(const Ellipse2<T>& a,
                                                              const Ray2<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a ray and a ellipse have a common point (exact but for the cases the header names).
template <Real T>
[[nodiscard]] inline bool intersects(const Ray2<T>& a, const Ellipse2<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Ellipse2<T>& a, const Ray2<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
