// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of two spheres in 3D: intersects() (the surfaces meet), intersection() (find:
// the circle, tangent point, or nothing) and relation() (the balls: separated, touching,
// overlapping, one inside the other, tangent inside, equal); row int3.surface-surface (quadric
// pairs), book section 11.8 (sphere-sphere). Result SphereSphereIntersection<T>
// (intersection/detail/quadric_pair3.hpp): kind empty, point (tangent, outside or inside),
// circle (point[0..2] three points of it; center, unit normal from a's center to b's, radius),
// coincident (equal spheres of positive radius). Exact decisions: with u = c1 - c0, the signs of
// |u|^2 - (r0 + r1)^2 and |u|^2 - (r0 - r1)^2 (polynomials of the inputs, core/exact_poly.hpp)
// decide every kind and relation without tolerance. Constructed values (rounded): after
// power-of-two scaling, the plane of the circle at distance a = (|u| + (r0 - r1)(r0 + r1)/|u|)/2
// from c0 along u/|u|, radius sqrt((r0 - a)(r0 + a)); points within a few eps of both spheres
// relative to the scale, the radius degrading to sqrt(eps) near tangency. Degenerate: radius 0 is
// a point (met when on the other sphere: kind point); a negative radius or NaN/Inf: kind empty,
// relation undecided. Swapping the arguments gives the same set (normal reversed). Float input is
// computed in double. Cost: a few dozen filtered exact terms; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric_pair3.hpp>
#include <locus/primitives/sphere.hpp>

namespace locus {

/// The common points of two spheres (see the header comment).
template <Real T>
[[nodiscard]] inline SphereSphereIntersection<T> intersection(const Sphere3<T>& a,
                                                              const Sphere3<T>& b) noexcept {
  namespace q = detail::quadric_pair3;
  return q::cast<T>(q::sphere_sphere(vec_cast<double>(a.center), double(a.radius),
                                     vec_cast<double>(b.center), double(b.radius)));
}

/// Whether the two spheres (the surfaces) have a common point; exact.
template <Real T>
[[nodiscard]] inline bool intersects(const Sphere3<T>& a, const Sphere3<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}

/// How the two balls lie relative to each other; exact.
template <Real T>
[[nodiscard]] inline RegionRelation relation(const Sphere3<T>& a, const Sphere3<T>& b) noexcept {
  namespace q = detail::quadric_pair3;
  return q::sphere_relation(vec_cast<double>(a.center), double(a.radius),
                            vec_cast<double>(b.center), double(b.radius));
}

}  // namespace locus
