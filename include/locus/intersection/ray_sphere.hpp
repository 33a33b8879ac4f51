// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a ray and a sphere in 3D: intersects() and intersection() (find);
// row int3.linear-quadric, book section 11.3 (figures 11.9, 11.10).
// Parameters: Ray3 t >= 0; param_b = (theta, phi) of sphere.hpp's point_at.
// Result (LinearSurfaceIntersection3<T>, intersection/detail/quadric3.hpp): empty; point or
// points (by increasing param_a), each with the outward unit normal and its multiplicity (2 at a
// tangency); kind ray (count 2, params 0 and 1) when the ray lies on the surface.
// Exact decisions: with the
// component as a bilinear form (docs/notes/intersection3.md) the count, tangency (multiplicity
// 2) and the ends of a ray or segment on the sphere are exact signs of polynomials in the input
// (core/exact_poly.hpp): exact for the sphere as given. Points: t = -d.w/|d|^2 -+ sqrt(r^2 -
// dist^2)/|d| with dist from |d x w| (w = o - C), rounded; ends on the sphere are returned
// exactly. Bound: |(|X - C| - r)| <= 16 eps max(|X|, |C|, r) away from tangency.
// Degenerate: NaN/Inf or invalid shape (negative radius, zero axis...): empty; a zero
// direction acts as its origin (a point on the surface: one hit). Float input is computed in
// double. The swapped overload returns swapped(). Cost: about 1-10 us (exact terms built each
// call; the big-integer path only near a tie); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric3.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/sphere.hpp>

namespace locus {

/// The points where a ray meets the surface (see the header comment).
template <Real T>
[[nodiscard]] inline LinearSurfaceIntersection3<T> intersection(const Ray3<T>& a,
                                                                const Sphere3<T>& b) noexcept {
  return detail::quadric3::find<T>(a, b);
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline auto intersection(const Sphere3<T>& a, const Ray3<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a ray meets the surface.
template <Real T>
[[nodiscard]] inline bool intersects(const Ray3<T>& a, const Sphere3<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Sphere3<T>& a, const Ray3<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
