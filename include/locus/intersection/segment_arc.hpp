// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a segment and a circular arc in the plane: intersects() (the book's test) and
// intersection() (find); row int2.linear-quadratic, book section 7.2 (figure 7.1).
// Parameters: Segment2 t in [0, 1] ((1 - t) p0 + t p1); on the arc the angle start + s, s in [0,
// sweep] (primitives/arc.hpp). Result (LinearCurveIntersection2<T>, intersection/result.hpp):
// empty; point (one crossing or a tangency, multiplicity 2); points (two crossings by increasing
// param_a). Method: the points on the arc's circle (intersection/segment_circle.hpp: count and
// tangency decided exactly, the same bound), kept when their angle lies on the arc. The arc's end
// points are cos/sin of its angles, not polynomial in the input, so that membership is decided on
// the computed angle: a point within a few ulps of an arc end may fall either way (the book's
// side-of-chord test of figure 7.1 has the same limit with rounded end points). Degenerate: sweep
// >= 2 pi is the whole circle; a negative or non-finite sweep, a negative radius, or any NaN/Inf
// gives empty; radius 0 and zero directions as in segment_circle.hpp. The swapped overload returns
// swapped(). Cost: that of segment_circle.hpp plus an fmod per point.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/arc.hpp>
#include <locus/primitives/segment.hpp>

namespace locus {

/// The common points of a segment and a circular arc (see the header comment).
template <Real T>
[[nodiscard]] inline LinearCurveIntersection2<T> intersection(const Segment2<T>& a,
                                                              const Arc2<T>& b) noexcept {
  return detail::conic2::cast<T>(
      detail::conic2::linear_arc(detail::conic2::as_lin(a), detail::conic2::as_arc(b)));
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline LinearCurveIntersection2<T> intersection(const Arc2<T>& a,
                                                              const Segment2<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a segment and a circular arc have a common point (exact but for the cases the header
/// names).
template <Real T>
[[nodiscard]] inline bool intersects(const Segment2<T>& a, const Arc2<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Arc2<T>& a, const Segment2<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
