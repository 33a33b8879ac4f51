// SPDX-License-Identifier: BSL-1.0
#pragma once
// Lines tangent to circles; rows cons2.tangent-at, cons2.tangent-through, cons2.tangent-2circles,
// book sections 8.3-8.5 (figures 8.3-8.7).
//
// Every returned line has a unit direction and its origin at the point of tangency on the
// (first) circle, so a tangent line is {origin, direction} with dot(origin - center, direction)
// = 0 up to rounding.
//
// tangent_line_at(c, p): the tangent at the point of the circle nearest to p (p itself when it
// lies on the circle); count 0 when p is the centre. Direction perp((p - center) / |p - center|).
//
// tangent_lines(p, c): the lines through p tangent to c. 2 when p is outside, 1 (the tangent at
// p) when p is on the circle, 0 inside (figure 8.5): the sign of |p - center|^2 - r^2, exact.
// Order: the tangent point on the right of the ray centre -> p first, then the left one.
//
// tangent_lines(c0, c1): the common tangents of two circles (figures 8.6, 8.7), d = |c1 - c0|:
// 4 when d > r0 + r1 (two outer, two inner), 3 when externally tangent (d = r0 + r1), 2 when the
// circles cross, 1 when internally tangent (d = |r0 - r1| > 0), 0 when one is strictly inside
// the other; coincident circles have infinitely many (infinite). All decided exactly from the
// signs of d^2 - (r0 +- r1)^2. Order: the outer tangents (the circles on the same side), then the
// inner ones (opposite sides), each pair right then left of the ray c0 -> c1; a touching pair
// gives one line (the tangent at the contact point). Origins are the tangent points on c0.
//
// Bad input: non-finite values give non_finite_input, a radius <= 0 degenerate_input (count 0).
// Accuracy: directions and origins rounded; the distance of each circle's centre to a returned
// line differs from its radius by at most 32 eps_T (m + r), m the largest input magnitude, r the
// largest radius (double computation; float results rounded once). Cost O(1).

#include <locus/construct/solutions.hpp>
#include <locus/core/scalar.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

/// The tangent line at the point of c nearest to p (see the header comment).
template <Real T>
[[nodiscard]] Solutions<Line2<T>, 1> tangent_line_at(const Circle2<T>& c,
                                                     const Vec2<T>& p) noexcept;

/// The lines through p tangent to c: 0, 1 or 2, decided exactly.
template <Real T>
[[nodiscard]] Solutions<Line2<T>, 2> tangent_lines(const Vec2<T>& p, const Circle2<T>& c) noexcept;

/// The common tangent lines of two circles: 0 to 4, decided exactly.
template <Real T>
[[nodiscard]] Solutions<Line2<T>, 4> tangent_lines(const Circle2<T>& c0,
                                                   const Circle2<T>& c1) noexcept;

#define LOCUS_CONSTRUCT_TANGENT_EXTERN(T)                                              \
  extern template Solutions<Line2<T>, 1> tangent_line_at<T>(const Circle2<T>&,         \
                                                            const Vec2<T>&) noexcept;  \
  extern template Solutions<Line2<T>, 2> tangent_lines<T>(const Vec2<T>&,              \
                                                          const Circle2<T>&) noexcept; \
  extern template Solutions<Line2<T>, 4> tangent_lines<T>(const Circle2<T>&,           \
                                                          const Circle2<T>&) noexcept;
LOCUS_CONSTRUCT_TANGENT_EXTERN(float)
LOCUS_CONSTRUCT_TANGENT_EXTERN(double)
#undef LOCUS_CONSTRUCT_TANGENT_EXTERN

}  // namespace locus
