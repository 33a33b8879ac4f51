// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two lines in the plane: intersects() (the book's test) and
// intersection() (find); row int2.linear, book section 7.1 (linear components).
// Parameters: t in R (origin + t direction) on each argument.
// Result (intersection/result.hpp, LinearIntersection2<T>): empty; point (a crossing, or a
// touch at an end point); or, when collinear, the overlap: line (two of its points: the first
// argument's origin and origin + direction); every entry with its parameters
// on both arguments.
// Exact decisions: parallel, collinear, whether and how they meet come from exact signs
// (turn2d, orient2d, lexicographic order; core/predicates.hpp), never from a tolerance.
// Constructed point: an input point exactly when one lies on the other argument (touching at
// an end point); otherwise |point - X|inf <= 6 eps max(|X|inf, m), X the exact intersection,
// m the largest |coordinate| of the end points and origins, eps of T; this holds at tiny
// crossing angles too: the parameter is a ratio of determinants rounded from their exact
// values (core/crossing.hpp), never of rounded differences. Parameters: within
// 6 eps max(|X|inf, m) / |direction|inf of the exact ones, clamped to the domain.
// Degenerate: a zero-length segment or a zero direction acts as the point p0 / origin
// (parameter 0). Any NaN or infinite coordinate gives kind empty (intersects false).
// Range: every finite input (far from 1 the input is rescaled by a power of two); a crossing
// of nearly parallel lines beyond the largest double has infinite coordinates.
// Cost: a few exact-sign filters; a constructed crossing adds four double-double determinants.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/linear2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

/// Whether a line and a line have a common point (exact).
template <Real T>
[[nodiscard]] inline bool intersects(const Line2<T>& a, const Line2<T>& b) noexcept {
  return detail::linear2::test(a, b);
}

/// The common set of a line and a line (see the header comment).
template <Real T>
[[nodiscard]] inline LinearIntersection2<T> intersection(const Line2<T>& a,
                                                         const Line2<T>& b) noexcept {
  return detail::linear2::find<T>(a, b);
}

}  // namespace locus
