// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a ray and a plane in 3D: intersects() (the book's test) and intersection()
// (find); row int3.linear-plane, book section 11.1 (figure 11.1).
// Parameters: Ray3 t >= 0 (origin + t direction). Plane3 {normal, constant} is { X : dot(normal, X)
// = constant }; the normal need not be unit length, and the plane is taken as given (rounded data,
// never normalised first). Result (LinearPlaneIntersection<T>, intersection/detail/linear3.hpp):
// empty; point (a crossing, or the origin, when it lies in the plane); or ray, when the whole ray
// lies in the plane (points: origin and origin + direction with parameters 0 and 1); param_b is
// NoParam. Exact decisions (core/plane_side.hpp, docs/notes/intersection.md "3D"): the side of each
// point is the exact sign of dot(normal, p) - constant, parallel is the exact sign of
// dot(normal, direction) = 0; no tolerance. Constructed point: the parameter t = (constant - dot(n,
// o)) / dot(n, d) with both dot products evaluated with a compensated dot product (as if in twice
// the precision; float input in double): |point - X|inf <= 8 eps max(|X|inf, m) + 2^-100 |X - o|inf
// / sin(angle) (m the largest |input coordinate|, eps of T, angle between the component and the
// plane). Point on an end point or the origin: that input point exactly. Degenerate: a zero
// direction (zero-length segment) acts as its point (parameter 0); a plane with a zero normal has
// no points: kind empty. Any NaN or infinite coordinate gives kind empty (intersects false). The
// swapped overload (Plane3, Ray3) returns swapped(). Range: decisions exact for every finite float;
// for double while products of coordinates stay in the double range. Cost: two or three exact-sign
// filters (a few ns); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/linear3.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/ray.hpp>

namespace locus {

/// Whether a ray and a plane have a common point (exact).
template <Real T>
[[nodiscard]] inline bool intersects(const Ray3<T>& a, const Plane3<T>& p) noexcept {
  return detail::linear3::plane<false>(detail::linear3::as_lin(a), vec_cast<double>(p.normal),
                                       double(p.constant))
             .kind != Kind::empty;
}

/// The common set of a ray and a plane (see the header comment).
template <Real T>
[[nodiscard]] inline LinearPlaneIntersection<T> intersection(const Ray3<T>& a,
                                                             const Plane3<T>& p) noexcept {
  return detail::linear3::cast_plane<T>(detail::linear3::plane<true>(
      detail::linear3::as_lin(a), vec_cast<double>(p.normal), double(p.constant)));
}

/// Swapped arguments: intersects(a, p).
template <Real T>
[[nodiscard]] inline bool intersects(const Plane3<T>& p, const Ray3<T>& a) noexcept {
  return intersects(a, p);
}

/// Swapped arguments: swapped(intersection(a, p)).
template <Real T>
[[nodiscard]] inline Intersection<T, 3, NoParam, T, 2> intersection(const Plane3<T>& p,
                                                                    const Ray3<T>& a) noexcept {
  return swapped(intersection(a, p));
}

}  // namespace locus
