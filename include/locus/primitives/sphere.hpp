// SPDX-License-Identifier: BSL-1.0
#pragma once
// Spheres (and N-dimensional hyperspheres); row prim3.solids; book sections 9.4.1 (the sphere
// as the quadric |X - C|^2 = r^2).
//
// Sphere<T, N> {center, radius} is the surface { X : |X - C| = r } bounding the ball
// { X : |X - C| <= r }; Sphere3<T> is the 3D case (a Sphere<T, 2> is a circle; prim2's
// Circle2 is the canonical 2D type).
//
// Parametrisation (3D): point_at(s, (theta, phi)) = C + r (cos theta sin phi, sin theta sin phi,
// cos phi), theta the azimuth in [0, 2 pi) measured from +x towards +y, phi the polar angle in
// [0, pi] measured from +z (phi = 0 is the north pole C + r e_z).
// Implicit form: signed_value(s, X) = |X - C|^2 - r^2, negative inside, zero on the sphere.
//
// Measures: measure(s) = pi^(N/2) / Gamma(N/2 + 1) r^N (volume of the ball), boundary_measure
// = N measure / r (surface area); volume() = 4/3 pi r^3 and surface_area() = 4 pi r^2 in 3D.
// bounding_box(s) = [C - r, C + r].
//
// Degenerate input: radius 0 is a point (measures 0). A negative or NaN radius is invalid
// (is_valid() false) and the measures return NaN for it. Non-finite centers propagate.
// O(N) per call; no allocation.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <cmath>
#include <limits>

namespace locus {

/// The sphere { X : |X - center| = radius } (and its ball).
template <class T, int N>
struct Sphere {
  Vec<T, N> center;
  T radius;
};

template <Real T>
using Sphere3 = Sphere<T, 3>;
using Sphere3f = Sphere3<float>;
using Sphere3d = Sphere3<double>;

/// True when the radius is finite and >= 0 and the center is finite.
template <class T, int N>
[[nodiscard]] constexpr bool is_valid(const Sphere<T, N>& s) noexcept {
  return is_finite(s.center) && is_finite(s.radius) && s.radius >= T(0);
}

/// |X - C|^2 - r^2: negative inside, zero on the sphere.
template <class T, int N>
[[nodiscard]] constexpr T signed_value(const Sphere<T, N>& s, const Vec<T, N>& x) noexcept {
  return sqr_length(x - s.center) - s.radius * s.radius;
}

/// C + r (cos theta sin phi, sin theta sin phi, cos phi) with tp = (theta, phi).
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const Sphere3<T>& s, const Vec2<T>& tp) noexcept {
  const T st = std::sin(tp.x), ct = std::cos(tp.x), sp = std::sin(tp.y), cp = std::cos(tp.y);
  return s.center + s.radius * Vec3<T>{ct * sp, st * sp, cp};
}

/// Volume of the N-ball, pi^(N/2) / Gamma(N/2 + 1) r^N; NaN for a negative or NaN radius.
template <class T, int N>
[[nodiscard]] inline T measure(const Sphere<T, N>& s) noexcept {
  if (!(s.radius >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  const double unit = std::pow(pi_v<double>, 0.5 * N) / std::tgamma(0.5 * N + 1.0);
  return static_cast<T>(unit * std::pow(static_cast<double>(s.radius), N));
}

/// Surface measure of the (N-1)-sphere, N pi^(N/2) / Gamma(N/2 + 1) r^(N-1); NaN if invalid.
template <class T, int N>
[[nodiscard]] inline T boundary_measure(const Sphere<T, N>& s) noexcept {
  if (!(s.radius >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  const double unit = N * std::pow(pi_v<double>, 0.5 * N) / std::tgamma(0.5 * N + 1.0);
  return static_cast<T>(unit * std::pow(static_cast<double>(s.radius), N - 1));
}

/// 4/3 pi r^3; NaN for a negative or NaN radius.
template <Real T>
[[nodiscard]] constexpr T volume(const Sphere3<T>& s) noexcept {
  if (!(s.radius >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  return T(4) / T(3) * pi_v<T> * s.radius * s.radius * s.radius;
}

/// 4 pi r^2; NaN for a negative or NaN radius.
template <Real T>
[[nodiscard]] constexpr T surface_area(const Sphere3<T>& s) noexcept {
  if (!(s.radius >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  return T(4) * pi_v<T> * s.radius * s.radius;
}

/// [C - r, C + r].
template <class T, int N>
[[nodiscard]] constexpr AlignedBox<T, N> bounding_box(const Sphere<T, N>& s) noexcept {
  return {s.center - splat<T, N>(s.radius), s.center + splat<T, N>(s.radius)};
}

/// Centroid of the ball (its center).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> centroid(const Sphere<T, N>& s) noexcept {
  return s.center;
}

}  // namespace locus
