// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a sphere in 3D; row dist3.pt-ellipsoid (sphere part); book
// section 10.5 (the sphere as the quadric |X - C|^2 = r^2).
//
// The Sphere3 primitive is the SURFACE { X : |X - C| = r } (primitives/sphere.hpp); distance(p,
// sphere) returns Distance<T, 3, NoParam, Vec2<T>> to that surface: closest[1] = C + r (p - C) /
// |p - C|, param_b = (theta, phi) with point_at(sphere, (theta, phi)) = closest[1] (theta in
// (-pi, pi] the azimuth from +x towards +y, phi in [0, pi] from +z). A point inside is at
// distance r - |p - C|. The distance to the solid BALL is distance_to_ball(p, sphere) =
// max(0, |p - C| - r). distance(sphere, p) is the swapped result.
//
// Degenerate input: p = C is equidistant from the whole sphere: the north pole (phi = 0) is
// returned with unique = false. A zero radius is the point C. A negative radius and NaN or
// infinite values give non_finite_distance() (result.hpp); distance_to_ball gives NaN.
// Cost: O(1), one normalisation, atan2 and acos for the parameter.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/sphere.hpp>

#include <cmath>
#include <limits>

namespace locus {

/// Distance from p to the sphere's surface; param_b = (theta, phi).
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, Vec2<T>> distance(const Vec3<T>& p,
                                                               const Sphere3<T>& s) noexcept {
  if (!is_finite(p) || !is_valid(s)) return non_finite_distance<T, 3, NoParam, Vec2<T>>();
  const Normalized<T, 3> d = normalize_with_length(p - s.center);
  if (d.length == T(0)) {
    const Vec3<T> pole = s.center + Vec3<T>{T(0), T(0), s.radius};
    return detail::make_distance(p, pole, NoParam{}, Vec2<T>{}, !(s.radius > T(0)));
  }
  const Vec2<T> tp{std::atan2(d.dir.y, d.dir.x), std::acos(clamp(d.dir.z, T(-1), T(1)))};
  return detail::make_distance(p, s.center + s.radius * d.dir, NoParam{}, tp, true);
}

/// Distance from p to the solid ball: max(0, |p - C| - r); NaN for invalid input.
template <Real T>
[[nodiscard]] inline T distance_to_ball(const Vec3<T>& p, const Sphere3<T>& s) noexcept {
  if (!is_finite(p) || !is_valid(s)) return std::numeric_limits<T>::quiet_NaN();
  const T d = length(p - s.center) - s.radius;
  return d > T(0) ? d : T(0);
}

/// The swapped query: closest[0] and param_a belong to the sphere.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, NoParam> distance(const Sphere3<T>& s,
                                                               const Vec3<T>& p) noexcept {
  return swapped(distance(p, s));
}

}  // namespace locus
