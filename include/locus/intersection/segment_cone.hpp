// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a segment and a cone: finite, truncated, infinite or double (caps included) in
// 3D: intersects() and intersection() (find); row int3.linear-quadric, book section 11.3
// (figures 11.13-11.16). Parameters: Segment3 t in [0, 1] (p0 + t (p1 - p0)); param_b = (theta, h)
// of cone.hpp's point_at (a cap point: its angle and height). Result
// (LinearSurfaceIntersection3<T>, intersection/detail/quadric3.hpp): empty; point or points (by
// increasing param_a), each with the outward unit normal and its multiplicity (2 at a tangency);
// kind segment (count 2, params 0 and 1) when the segment lies on the surface. Decisions:
// cos^2(alpha) and the implicit matrix cos^2 I - D D^T are rounded once (the angle is
// transcendental data), the component is moved by -V (rounded); the count of the line against that
// rounded quadric is exact, so a line within a few eps (relative) of tangency may come out as 0 or
// 2 points (documented bound). The solid is clipped by the nappe slabs [max(min_h, 0), max_h] and
// [min_h, min(max_h, 0)] in floating point; the ends of the interval(s) inside the solid are
// the hits (up to four for a double cone; the vertex joins the nappes).
// Degenerate: NaN/Inf or invalid shape (negative radius, zero axis...): empty; a zero
// direction acts as its origin (a point on the surface: one hit). Float input is computed in
// double. The swapped overload returns swapped(). Cost: about 1-10 us (exact terms built each
// call; the big-integer path only near a tie); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric3.hpp>
#include <locus/primitives/cone.hpp>
#include <locus/primitives/segment.hpp>

namespace locus {

/// The points where a segment meets the surface (see the header comment).
template <Real T>
[[nodiscard]] inline LinearSurfaceIntersection3<T> intersection(const Segment3<T>& a,
                                                                const Cone3<T>& b) noexcept {
  return detail::quadric3::find<T>(a, b);
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline auto intersection(const Cone3<T>& a, const Segment3<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a segment meets the surface.
template <Real T>
[[nodiscard]] inline bool intersects(const Segment3<T>& a, const Cone3<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Cone3<T>& a, const Segment3<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
