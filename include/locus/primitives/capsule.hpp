// SPDX-License-Identifier: BSL-1.0
#pragma once
// Capsules (sphere-swept segments; "stadiums" in 2D); row prim3.solids (the capsule of
// the book's distance and intersection chapters).
//
// Capsule<T, N> {segment, radius} is the set of points within distance radius of the segment
// (prim2's Segment {p0, p1}). Capsule3<T> is the 3D case.
// Measures with L = |p1 - p0|, r = radius:
//   3D: volume = pi r^2 L + 4/3 pi r^3, surface_area = 2 pi r L + 4 pi r^2
//   2D: area = 2 r L + pi r^2, perimeter = 2 L + 2 pi r
// point_at(capsule, (theta, t)) (3D) is the lateral cylinder point at segment parameter t in
// [0, 1]: point_at(segment, t) + r (cos theta u + sin theta v), (u, v, unit direction)
// right-handed from plane.hpp's perpendicular_basis. The hemispherical caps are the spheres of
// radius r at p0 and p1 (use sphere.hpp's point_at on them).
// bounding_box() is the box of the segment inflated by r (tight).
//
// Degenerate input: a zero-length segment is a sphere (L = 0; point_at then has u = v = 0 and
// returns the segment point); r = 0 is the segment (measures 0 in 3D). A negative or NaN
// radius is invalid and the measures return NaN. Cost O(N); no allocation.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/segment.hpp>

#include <cmath>
#include <limits>

namespace locus {

/// The points within distance radius of segment.
template <class T, int N>
struct Capsule {
  Segment<T, N> segment;
  T radius;
};

template <Real T>
using Capsule2 = Capsule<T, 2>;
template <Real T>
using Capsule3 = Capsule<T, 3>;
using Capsule3f = Capsule3<float>;
using Capsule3d = Capsule3<double>;

/// pi r^2 L + 4/3 pi r^3; NaN for a negative or NaN radius.
template <Real T>
[[nodiscard]] inline T volume(const Capsule3<T>& c) noexcept {
  const T r = c.radius;
  if (!(r >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  return pi_v<T> * r * r * (length(c.segment) + T(4) / T(3) * r);
}

/// 2 pi r L + 4 pi r^2; NaN for a negative or NaN radius.
template <Real T>
[[nodiscard]] inline T surface_area(const Capsule3<T>& c) noexcept {
  const T r = c.radius;
  if (!(r >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  return T(2) * pi_v<T> * r * (length(c.segment) + T(2) * r);
}

/// 2 r L + pi r^2 (2D); NaN for a negative or NaN radius.
template <Real T>
[[nodiscard]] inline T area(const Capsule2<T>& c) noexcept {
  const T r = c.radius;
  if (!(r >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  return r * (T(2) * length(c.segment) + pi_v<T> * r);
}

/// 2 L + 2 pi r (2D); NaN for a negative or NaN radius.
template <Real T>
[[nodiscard]] inline T perimeter(const Capsule2<T>& c) noexcept {
  const T r = c.radius;
  if (!(r >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  return T(2) * (length(c.segment) + pi_v<T> * r);
}

/// Lateral point point_at(segment, t) + r (cos theta u + sin theta v) with tt = (theta, t).
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const Capsule3<T>& c, const Vec2<T>& tt) noexcept {
  const auto b = perpendicular_basis(c.segment.p1 - c.segment.p0);
  return point_at(c.segment, tt.y) + c.radius * (std::cos(tt.x) * b.u + std::sin(tt.x) * b.v);
}

/// The segment's box inflated by the radius.
template <class T, int N>
[[nodiscard]] constexpr AlignedBox<T, N> bounding_box(const Capsule<T, N>& c) noexcept {
  const AlignedBox<T, N> b{cwise_min(c.segment.p0, c.segment.p1),
                           cwise_max(c.segment.p0, c.segment.p1)};
  return inflate(b, c.radius);
}

/// Centroid of the solid capsule (the segment midpoint, by symmetry).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> centroid(const Capsule<T, N>& c) noexcept {
  return midpoint(c.segment);
}

}  // namespace locus
