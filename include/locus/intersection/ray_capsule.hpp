// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a ray and a capsule (sphere-swept segment) in 3D: intersects() and intersection()
// (find); row int3.linear-quadric, book section 11.3 (section 11.3 (capsules)). Parameters: Ray3 t
// >= 0; param_b = (theta, s): angle about the segment and the axis parameter s of the hit's
// projection (s < 0 or > 1 on the end caps). Result (LinearSurfaceIntersection3<T>,
// intersection/detail/quadric3.hpp): empty; point or points (by increasing param_a), each with the
// outward unit normal and its multiplicity (2 at a tangency); kind ray (count 2, params 0 and 1)
// when the ray lies on the surface. Decisions: the capsule is the union of two balls and a cylinder
// slab, all convex: the line's interval inside each part has an exact count (sphere and cylinder
// signs above), the slab clipping and the union of the intervals are rounded (a hit near a seam may
// come from the ball or the side). The hits are the ends of the union interval. Points rounded (eps
// relative). Degenerate: NaN/Inf or invalid shape (negative radius, zero axis...): empty; a zero
// direction acts as its origin (a point on the surface: one hit). Float input is computed in
// double. The swapped overload returns swapped(). Cost: about 1-10 us (exact terms built each
// call; the big-integer path only near a tie); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric3.hpp>
#include <locus/primitives/capsule.hpp>
#include <locus/primitives/ray.hpp>

namespace locus {

/// The points where a ray meets the surface (see the header comment).
template <Real T>
[[nodiscard]] inline LinearSurfaceIntersection3<T> intersection(const Ray3<T>& a,
                                                                const Capsule3<T>& b) noexcept {
  return detail::quadric3::find<T>(a, b);
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline auto intersection(const Capsule3<T>& a, const Ray3<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a ray meets the surface.
template <Real T>
[[nodiscard]] inline bool intersects(const Ray3<T>& a, const Capsule3<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Capsule3<T>& a, const Ray3<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
