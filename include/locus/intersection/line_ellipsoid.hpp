// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a line and an ellipsoid in 3D: intersects() and intersection() (find);
// row int3.linear-quadric, book section 11.3 (figure 11.9 (a sphere is an ellipsoid)).
// Parameters: Line3 t in R; param_b = (theta, phi) of ellipsoid.hpp's point_at.
// Result (LinearSurfaceIntersection3<T>, intersection/detail/quadric3.hpp): empty; point or
// points (by increasing param_a), each with the outward unit normal and its multiplicity (2 at a
// tangency); kind line (count 2, params 0 and 1) when the line lies on the surface.
// Decisions: the implicit
// matrix sum u_i u_i^T / e_i^2 and the component moved by -C are rounded once (a few eps
// relative), then the general-quadric signs decide exactly for those rounded data: a
// tangency within a few eps of the scale may come out as 0 or 2 points (documented bound).
// Points: stable quadratic roots; |sum (u_i.(X - C)/e_i)^2 - 1| <= 64 eps (|X - C|/e_min)^2
// away from tangency.
// Degenerate: NaN/Inf or invalid shape (negative radius, zero axis...): empty; a zero
// direction acts as its origin (a point on the surface: one hit). Float input is computed in
// double. The swapped overload returns swapped(). Cost: about 1-10 us (exact terms built each
// call; the big-integer path only near a tie); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric3.hpp>
#include <locus/primitives/ellipsoid.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

/// The points where a line meets the surface (see the header comment).
template <Real T>
[[nodiscard]] inline LinearSurfaceIntersection3<T> intersection(const Line3<T>& a,
                                                                const Ellipsoid3<T>& b) noexcept {
  return detail::quadric3::find<T>(a, b);
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline auto intersection(const Ellipsoid3<T>& a, const Line3<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a line meets the surface.
template <Real T>
[[nodiscard]] inline bool intersects(const Line3<T>& a, const Ellipsoid3<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Ellipsoid3<T>& a, const Line3<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
