// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two circular arcs in the plane: intersects() (the book's test) and
// intersection() (find); row int2.quadratic, book sections 7.2 (figure 7.1) and 7.5.1.
// Parameters: on a circle the angle in (-pi, pi] of point - center; on an arc the angle start +
// s, s in [0, sweep] (primitives/arc.hpp).
// Result (ArcIntersection2<T>, intersection/result.hpp): empty; point / points (crossings,
// multiplicity 1, or a tangency, multiplicity 2); on a common circle the overlap: kind arc, three
// points per piece (start, middle, end by increasing angle on the first argument; two pieces when
// both arcs exceed a half turn and overlap at both ends), multiplicity 0; kind point / points when
// the arcs only share end points; coincident when both are whole circles. Method: circle_circle.hpp
// (count, tangency and the common circle decided exactly, the same bound), then membership of each
// point's computed angle in the arc: an arc's end points are cos/sin of its angles, not polynomial
// in the input, so a point within a few ulps of an arc end may fall either way (figure 7.1's
// side-of-chord test has the same limit). Degenerate: sweep >= 2 pi is the whole circle; a negative
// or non-finite sweep, a negative radius, any NaN/Inf: empty. Swapping the arguments gives the same
// set. Cost: that of circle_circle.hpp plus an fmod per point; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/conic2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/arc.hpp>

namespace locus {

/// The common points (or arcs) of two arcs (see the header comment).
template <Real T>
[[nodiscard]] inline ArcIntersection2<T> intersection(const Arc2<T>& a, const Arc2<T>& b) noexcept {
  namespace c = detail::conic2;
  return c::cast<T>(c::arc_arc(c::as_arc(a), c::as_arc(b)));
}
/// Whether two arcs have a common point.
template <Real T>
[[nodiscard]] inline bool intersects(const Arc2<T>& a, const Arc2<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}

}  // namespace locus
