// SPDX-License-Identifier: BSL-1.0
#pragma once
// The circle through three points and the circles tangent to three lines; rows
// cons2.circle3pts and cons2.circle3lines, book sections 8.1-8.2 (figures 8.1, 8.2).
//
// circle_through(p0, p1, p2): the circumscribed circle; count 1, or 0 when the points are
// collinear or two coincide (orient2d == 0, exact). The centre is the rounded ratio of 2x2
// determinants of the differences p1 - p0, p2 - p0 (computed in double), the radius its distance
// to p0.
//
// circles_tangent_to(l0, l1, l2): every circle tangent to three lines (Line2, any non-zero
// direction). A circle with centre X and radius r is tangent to line i when the signed distance
// s_i(X) = perp_dot(d_i, X - o_i) / |d_i| equals e_i r with e_i = +-1. The four sign patterns
// e = (+,+,+), (-,+,+), (+,-,+), (+,+,-) (a pattern and its negation give the same circle) are
// tried in this order; each is a 3x3 linear system in (X, r). When the lines bound a triangle all
// four exist: the incircle first, then the excircle beyond line 0, 1, 2 (so for the lines of a
// triangle's edges v0v1, v1v2, v2v0 the excircles opposite v2, v0, v1). Two parallel lines leave
// the two circles between them tangent to the third line; three distinct parallel lines, or
// three lines through one point, leave none (count 0). Two coincident lines give infinitely many
// (infinite, count 0). Parallel, coincident and concurrent are decided exactly
// (a pattern is singular exactly when e_i d_i / |d_i| sum to a dependent system; see
// docs/notes/construct.md). incircle(t) / excircles(t) apply this to the triangle's edge lines.
//
// Bad input: a non-finite coordinate gives status non_finite_input; a zero direction
// degenerate_input (count 0). Accuracy: centres and radii are rounded (double arithmetic);
// every residual |dist(X, p_i) - r|, |s_i(X)| - r is within 64 eps_T S, S the largest of the
// input magnitudes, |X| and r (near-collinear points or near-parallel lines put X far away, and
// S grows with it). Cost: O(1); the exact fallback runs only near a degeneracy.

#include <locus/construct/solutions.hpp>
#include <locus/core/scalar.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/triangle.hpp>

namespace locus {

/// The circle through three points (count 0 when they are collinear; see the header comment).
template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 1> circle_through(const Vec2<T>& p0, const Vec2<T>& p1,
                                                      const Vec2<T>& p2) noexcept;

/// Every circle tangent to three lines (up to four; see the header comment for the order).
template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 4> circles_tangent_to(const Line2<T>& l0, const Line2<T>& l1,
                                                          const Line2<T>& l2) noexcept;

/// The incircle of a triangle (count 0 for a degenerate triangle).
template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 1> incircle(const Triangle2<T>& t) noexcept;

/// The three excircles of a triangle, opposite v0, v1, v2 in this order (count 0 when degenerate).
template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 3> excircles(const Triangle2<T>& t) noexcept;

#define LOCUS_CONSTRUCT_CIRCLE_THROUGH_EXTERN(T)                                                   \
  extern template Solutions<Circle2<T>, 1> circle_through<T>(const Vec2<T>&, const Vec2<T>&,       \
                                                             const Vec2<T>&) noexcept;             \
  extern template Solutions<Circle2<T>, 4> circles_tangent_to<T>(const Line2<T>&, const Line2<T>&, \
                                                                 const Line2<T>&) noexcept;        \
  extern template Solutions<Circle2<T>, 1> incircle<T>(const Triangle2<T>&) noexcept;              \
  extern template Solutions<Circle2<T>, 3> excircles<T>(const Triangle2<T>&) noexcept;
LOCUS_CONSTRUCT_CIRCLE_THROUGH_EXTERN(float)
LOCUS_CONSTRUCT_CIRCLE_THROUGH_EXTERN(double)
#undef LOCUS_CONSTRUCT_CIRCLE_THROUGH_EXTERN

}  // namespace locus
