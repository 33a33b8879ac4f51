// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a line and a segment in the plane: intersects() (the book's test) and
// intersection() (find); row int2.linear, book section 7.1 (linear components).
// Parameters: Line2 t in R (origin + t direction); Segment2 t in [0, 1] ((1 - t) p0 + t p1).
// Result (intersection/result.hpp, LinearIntersection2<T>): empty; point (a crossing, or a
// touch at an end point); or, when collinear, the overlap: segment (its end points by increasing
// param_a); every entry with its parameters on both arguments. Exact decisions: parallel,
// collinear, whether and how they meet come from exact signs (turn2d, orient2d, lexicographic
// order; core/predicates.hpp), never from a tolerance. Constructed point: an input point exactly
// when one lies on the other argument (touching at an end point); otherwise |point - X|inf <= 6 eps
// max(|X|inf, m), X the exact intersection, m the largest |coordinate| of the end points and
// origins, eps of T; this holds at tiny crossing angles too: the parameter is a ratio of
// determinants rounded from their exact values (core/crossing.hpp), never of rounded differences.
// Parameters: within 6 eps max(|X|inf, m) / |direction|inf of the exact ones, clamped to the
// domain. Degenerate: a zero-length segment or a zero direction acts as the point p0 / origin
// (parameter 0). Any NaN or infinite coordinate gives kind empty (intersects false).
// The swapped overload (Segment2, Line2) returns swapped() of this one: index 0 is the first
// argument. Range: exact for coordinates whose products stay inside the double range
// (predicates.hpp). Cost: a few exact-sign filters (about ten ns); the accurate determinants only
// near parallel.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/linear2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/segment.hpp>

namespace locus {

/// Whether a line and a segment have a common point (exact).
template <Real T>
[[nodiscard]] inline bool intersects(const Line2<T>& a, const Segment2<T>& b) noexcept {
  return detail::linear2::test(a, b);
}

/// The common set of a line and a segment (see the header comment).
template <Real T>
[[nodiscard]] inline LinearIntersection2<T> intersection(const Line2<T>& a,
                                                         const Segment2<T>& b) noexcept {
  return detail::linear2::find<T>(a, b);
}

/// Swapped arguments: intersects(b, a).
template <Real T>
[[nodiscard]] inline bool intersects(const Segment2<T>& a, const Line2<T>& b) noexcept {
  return intersects(b, a);
}

/// Swapped arguments: swapped(intersection(b, a)).
template <Real T>
[[nodiscard]] inline LinearIntersection2<T> intersection(const Segment2<T>& a,
                                                         const Line2<T>& b) noexcept {
  return swapped(intersection(b, a));
}

}  // namespace locus
