// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two segments in the plane: intersects() (the book's test) and
// intersection() (find); row int2.linear, book section 7.1 (linear components).
// Parameters: t in [0, 1] ((1 - t) p0 + t p1) on each argument.
// Result (intersection/result.hpp, LinearIntersection2<T>): empty; point (a crossing, or a
// touch at an end point); or, when collinear, the overlap: segment (end points by increasing
// param_a) or point (touching end to end); every entry with its parameters on both arguments. Exact
// decisions: parallel, collinear, whether and how they meet come from exact signs (turn2d,
// orient2d, lexicographic order; core/predicates.hpp), never from a tolerance. Constructed point:
// an input point exactly when one lies on the other argument (touching at an end point); otherwise
// |point - X|inf <= 6 eps max(|X|inf, m), X the exact intersection, m the largest |coordinate| of
// the end points and origins, eps of T; this holds at tiny crossing angles too: the parameter is a
// ratio of determinants rounded from their exact values (core/crossing.hpp), never of rounded
// differences. Parameters: within 6 eps max(|X|inf, m) / |direction|inf of the exact ones, clamped
// to the domain. Degenerate: a zero-length segment or a zero direction acts as the point p0 /
// origin (parameter 0). Any NaN or infinite coordinate gives kind empty (intersects false). Range:
// exact for coordinates whose products stay inside the double range (predicates.hpp). Cost: four
// filtered signs; a crossing reuses their values when a bound proves them accurate enough, else
// up to four double-double determinants; where a filter fails (nearly parallel), each undecided
// sign comes with its value rounded from the exact one (core/crossing.hpp), which both decides
// and constructs (docs/notes/intersection.md, "Fast path"). Many pairs at once:
// segment_segment_batch.hpp (SIMD, the same results bit for bit).

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/linear2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/segment.hpp>

namespace locus {

/// Whether a segment and a segment have a common point (exact).
template <Real T>
[[nodiscard]] inline bool intersects(const Segment2<T>& a, const Segment2<T>& b) noexcept {
  return detail::linear2::test(a, b);
}

/// The common set of a segment and a segment (see the header comment).
template <Real T>
[[nodiscard]] inline LinearIntersection2<T> intersection(const Segment2<T>& a,
                                                         const Segment2<T>& b) noexcept {
  return detail::linear2::find<T>(a, b);
}

}  // namespace locus
