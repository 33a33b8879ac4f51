// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a segment and a torus in 3D: intersects() and intersection() (find);
// row int3.torus, book section 11.3.5 (figures 11.74-11.77).
// Parameters: Segment3 t in [0, 1] (p0 + t (p1 - p0)); param_b = (u, v) of torus.hpp's point_at: u
// the angle about the axis, v about the tube. Result (LinearSurfaceIntersection3<T>,
// intersection/detail/quadric3.hpp): empty; point or points (by increasing param_a), each with the
// outward unit normal and its multiplicity (2 at a tangency); kind segment (count 2, params 0 and
// 1) when the segment lies on the surface. Method: in a frame at the centre scaled by a power of
// two to R + r = O(1), the quartic (|X|^2 + R^2 - r^2)^2 - 4 R^2 |X x n|^2 along the line is solved
// by numeric/roots.hpp's solve_quartic (near mode) with the coefficients' rounding bounds as
// coefficient_error, so a near-tangent line gives a double root (multiplicity 2) within that bound
// rather than two spurious points; simple roots are polished by Newton steps on the geometric
// value. Not exact: tangency and the ends of a ray/segment are decided within ~16 eps relative to
// the scale (documented bound). Degenerate: NaN/Inf or invalid shape (negative radius, zero
// axis...): empty; a zero direction acts as its origin (a point on the surface: one hit). Float
// input is computed in double. The swapped overload returns swapped(). Cost: about 1-10 us (exact
// terms built each call; the big-integer path only near a tie); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric3.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/torus.hpp>

namespace locus {

/// The points where a segment meets the surface (see the header comment).
template <Real T>
[[nodiscard]] inline LinearSurfaceIntersection3<T> intersection(const Segment3<T>& a,
                                                                const Torus3<T>& b) noexcept {
  return detail::quadric3::find<T>(a, b);
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline auto intersection(const Torus3<T>& a, const Segment3<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a segment meets the surface.
template <Real T>
[[nodiscard]] inline bool intersects(const Segment3<T>& a, const Torus3<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Torus3<T>& a, const Segment3<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
