// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a line and a disk in 3D: intersects() and intersection(); row
// int3.linear-polygon, book section 11.3 (figure 11.4).
// Disk3 {center, normal, radius} is the closed disk { X : dot(normal, X - center) = 0,
// |X - center| <= radius }; param_b is (s, t) of point_at(disk, st) = center + s u + t v with
// in_plane_axes(disk) = (u, v). Result (LinearPlanarIntersection<T>, detail/planar3.hpp): empty;
// point (a crossing, or a touch); or, for a line lying in the disk's plane, the chord: segment
// (by increasing param_a) or point (tangent).
// Decisions: the side of the plane as given is exact (dot(normal, X - center), core/exact_sum);
// whether the crossing X (or an end point lying in the plane) is in the closed disk is exact:
// |X - center|^2 <= radius^2 on the unrounded crossing (core/plane_crossing_ball.hpp), so points
// on the rim count as inside. The reported point is rounded (a few eps of the coordinates when
// the angle to the plane is not tiny). In the plane, the contact is exact too (none, a single
// point such as a tangency, or a chord: the distance from the centre to the carrier and where its
// foot lies, core/plane_crossing_ball.hpp); a chord's ends solve |o + t d|^2 = r^2 in frame
// coordinates with the stable quadratic formula (rounded); a chord shorter than that rounding is
// still a segment whose rounded ends may coincide (at its point nearest the centre if lost).
// Degenerate: a zero direction (zero-length segment) acts as its point; a zero normal, a negative
// radius or NaN/Inf input gives empty; radius 0 is the centre point. The swapped overload
// returns swapped(). Cost: a few exact-sign filters and about 150 flops; near the rim the exact
// path, about a hundred microseconds; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/planar3.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

/// Whether a line meets the closed disk (see the header comment).
template <Real T>
[[nodiscard]] inline bool intersects(const Line3<T>& a, const Disk3<T>& d) noexcept {
  return detail::planar3::disk<false>(detail::linear3::as_lin(a), d).kind != Kind::empty;
}

/// The common set of a line and the closed disk (see the header comment).
template <Real T>
[[nodiscard]] inline LinearPlanarIntersection<T> intersection(const Line3<T>& a,
                                                              const Disk3<T>& d) noexcept {
  return intersection_cast<T>(detail::planar3::disk<true>(detail::linear3::as_lin(a), d));
}

/// Swapped arguments: intersects(a, d).
template <Real T>
[[nodiscard]] inline bool intersects(const Disk3<T>& d, const Line3<T>& a) noexcept {
  return intersects(a, d);
}

/// Swapped arguments: swapped(intersection(a, d)).
template <Real T>
[[nodiscard]] inline Intersection<T, 3, Vec2<T>, T, 2> intersection(const Disk3<T>& d,
                                                                    const Line3<T>& a) noexcept {
  return swapped(intersection(a, d));
}

}  // namespace locus
