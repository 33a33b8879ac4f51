// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two general quadratic curves (conics) in the plane: intersects() (the book's
// test) and intersection() (find); row int2.quadratic, book section 7.5 (figure 7.5).
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
// Result (CurvePairIntersection2<T>): empty, point, points (by increasing x, then y), each with
// its multiplicity, parameters 0; coincident for proportional coefficients (the same curve,
// exact; also the zero curve, the whole plane). A shared component (R vanishes identically, exact)
// of two line pairs or double lines is a rational line: kind line, point[0] and point[1] two of
// its points (multiplicity 0), and when the other components meet off that line, point[2] that
// isolated common point (multiplicity 1, count 3). A curve with a = b = c = 0 is the line
// d x + e y + f = 0 (a non-zero constant: no point). Degenerate: any NaN/Inf coefficient: empty.
// The swapped overload gives the same set. Cost: as ellipse_ellipse.hpp.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/quadratic_curve.hpp>

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
