// SPDX-License-Identifier: BSL-1.0
#pragma once
// Rays in N dimensions; rows prim2.linear and prim3.linear; book section 5.1, figure 5.1(b).
//
// Ray<T, N> {origin, direction}: the point set { origin + t * direction, t >= 0 }. The direction
// need not be unit length; point_at(ray, t) = origin + t * direction for t >= 0 (t < 0 is not
// clamped: callers that want the ray's closest point clamp t themselves). A zero or non-finite
// direction is degenerate; by the library's policy a ray with a zero direction acts as the point
// `origin` in queries. Cost O(N), no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/line.hpp>

#include <optional>

namespace locus {

/// The ray { origin + t * direction : t >= 0 }; direction need not be unit length.
template <class T, int N>
struct Ray {
  Vec<T, N> origin;
  Vec<T, N> direction;
};

template <Real T>
using Ray2 = Ray<T, 2>;
template <Real T>
using Ray3 = Ray<T, 3>;
using Ray2f = Ray2<float>;
using Ray2d = Ray2<double>;
using Ray3f = Ray3<float>;
using Ray3d = Ray3<double>;

/// origin + t * direction (meaningful for t >= 0).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const Ray<T, N>& ray, T t) noexcept {
  return ray.origin + t * ray.direction;
}

/// True when the direction is zero or a coordinate of the ray is not finite.
template <class T, int N>
[[nodiscard]] constexpr bool is_degenerate(const Ray<T, N>& ray) noexcept {
  return !is_finite(ray.origin) || !is_finite(ray.direction) || ray.direction == Vec<T, N>{};
}

/// The same ray with a unit direction, or std::nullopt when the ray is degenerate.
template <class T, int N>
[[nodiscard]] inline std::optional<Ray<T, N>> normalized(const Ray<T, N>& ray) noexcept {
  if (is_degenerate(ray)) return std::nullopt;
  return Ray<T, N>{ray.origin, normalize(ray.direction)};
}

/// The line that contains the ray (same origin and direction, hence the same parameter t).
template <class T, int N>
[[nodiscard]] constexpr Line<T, N> supporting_line(const Ray<T, N>& ray) noexcept {
  return {ray.origin, ray.direction};
}

}  // namespace locus
