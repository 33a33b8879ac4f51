// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a segment and a right circular cylinder, finite (caps included) or infinite in
// 3D: intersects() and intersection() (find); row int3.linear-quadric, book section 11.3
// (figures 11.11, 11.12). Parameters: Segment3 t in [0, 1] (p0 + t (p1 - p0)); param_b = (theta,
// height) of cylinder.hpp's point_at (a cap point: its angle and +-h/2). Result
// (LinearSurfaceIntersection3<T>, intersection/detail/quadric3.hpp): empty; point or points (by
// increasing param_a), each with the outward unit normal and its multiplicity (2 at a tangency);
// kind segment (count 2, params 0 and 1) when the segment lies on the surface. Exact decisions: the
// lateral surface |a x (X - C)|^2 = r^2 |a|^2 is decided exactly (discriminant r^2 |a x d|^2 -
// [a, d, o - C]^2, ends of a ray/segment, a direction along the axis): exact for the infinite
// cylinder as given. A finite cylinder is the closed solid: the hits are the ends of the
// line's interval inside it, the lateral interval (exact count) clipped by the cap slab
// (rounded: near a rim the hit may be attributed to the cap or the side; the ray/segment
// domain of a finite cylinder is compared in floating point). Points rounded (eps relative).
// Degenerate: NaN/Inf or invalid shape (negative radius, zero axis...): empty; a zero
// direction acts as its origin (a point on the surface: one hit). Float input is computed in
// double. The swapped overload returns swapped(). Cost: about 1-10 us (exact terms built each
// call; the big-integer path only near a tie); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric3.hpp>
#include <locus/primitives/cylinder.hpp>
#include <locus/primitives/segment.hpp>

namespace locus {

/// The points where a segment meets the surface (see the header comment).
template <Real T>
[[nodiscard]] inline LinearSurfaceIntersection3<T> intersection(const Segment3<T>& a,
                                                                const Cylinder3<T>& b) noexcept {
  return detail::quadric3::find<T>(a, b);
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline auto intersection(const Cylinder3<T>& a, const Segment3<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a segment meets the surface.
template <Real T>
[[nodiscard]] inline bool intersects(const Segment3<T>& a, const Cylinder3<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Cylinder3<T>& a, const Segment3<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
