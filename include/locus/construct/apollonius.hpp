// SPDX-License-Identifier: BSL-1.0
#pragma once
// Apollonius' problem: the circles tangent to three circles; row cons2.apollonius (beyond the
// book; the limiting cases are the circle through three points, 8.1, and tangent lines, 8.6).
//
// apollonius(c0, c1, c2) with radii >= 0 (a zero radius is a point the solution passes through).
// A solution circle (X, r), r > 0, is tangent to c_i with sign s_i: |X - c_i.center| = r + s_i
// c_i.radius (s_i = +1: the circles touch from outside; -1: internally, one inside the other).
// The eight sign patterns are handled as four with s_0 = +1 and a signed radius (a root r < 0 is
// the circle of radius -r for the negated pattern); a pattern differing only in the sign of a
// zero radius is skipped (same equations). Each pattern is a line of (X, r) space meeting the
// cone |X - c_0|^2 = (r + s_0 r_0)^2: 0, 1 or 2 solutions, decided exactly by the sign of
// k01 k02 k12 with k_ij = |c_i - c_j|^2 - (s_i r_i - s_j r_j)^2 (docs/notes/construct.md).
// Degenerate patterns, decided exactly too:
//  - the pattern's linear system has full rank but its line is parallel to the cone (its Gram
//    determinant k01 k02 - g12^2 = 0): one solution is a LINE tangent to the three circles (a
//    circle of infinite radius), reported in `line`, plus at most one finite circle;
//  - rank-deficient patterns (collinear centres with radii in proportion, coincident circles):
//    either no finite circle (with 0 or 2 tangent lines) or infinitely many (infinite set).
// A radius-0 root (the three circles pass through one common point P; two mirror points when the
// centres are collinear) solves every pattern: it is reported once, as the circle of radius
// exactly 0 at P with signs +1, decided exactly (core's big integer: the radical centre on the
// circles, docs/notes/construct.md).
//
// Result: up to 8 circles with their signs s[i] (before: +1 outside, -1 inside), up to 4 lines
// with the signs of the three circles' sides (+1: the circle is on the left of the line).
// Bad input: non-finite values give non_finite_input, a negative radius degenerate_input.
// Accuracy: each residual |X - c_i| - |r + s_i r_i| is within 256 eps_T S k, S the largest
// magnitude of the input, k = 1 + (the size of the solution / S) (double computation). Cost: a
// few exact signs per pattern, O(1).

#include <locus/construct/solutions.hpp>
#include <locus/core/scalar.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>

#include <array>

namespace locus {

/// A solution of Apollonius' problem: the circle and its tangency sign with each input circle.
template <Real T>
struct ApolloniusCircle {
  Circle2<T> circle;
  std::array<int, 3> s;  ///< +1: |X - c_i| = r + r_i (outside); -1: |X - c_i| = |r - r_i|
};

/// A line tangent to the three circles (a solution of infinite radius).
template <Real T>
struct ApolloniusLine {
  Line2<T> line;         ///< unit direction, origin the tangent point on c0
  std::array<int, 3> s;  ///< +1: circle i lies on the left of the line, -1 on the right
};

/// All solutions of Apollonius' problem (see the header comment).
template <Real T>
struct ApolloniusSolutions {
  Solutions<ApolloniusCircle<T>, 8> circles;  ///< status and infinite live here
  Solutions<ApolloniusLine<T>, 4> lines;      ///< status mirrors circles.status
};

/// The circles (and lines) tangent to three circles.
template <Real T>
[[nodiscard]] ApolloniusSolutions<T> apollonius(const Circle2<T>& c0, const Circle2<T>& c1,
                                                const Circle2<T>& c2) noexcept;

extern template ApolloniusSolutions<float> apollonius<float>(const Circle2<float>&,
                                                             const Circle2<float>&,
                                                             const Circle2<float>&) noexcept;
extern template ApolloniusSolutions<double> apollonius<double>(const Circle2<double>&,
                                                               const Circle2<double>&,
                                                               const Circle2<double>&) noexcept;

}  // namespace locus
