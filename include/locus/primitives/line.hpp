// SPDX-License-Identifier: BSL-1.0
#pragma once
// Lines in N dimensions (parametric form) and in 2D (implicit form); rows prim2.linear and
// prim3.linear; book section 5.1 (linear components), figures 5.1(a) and 5.2.
//
// Parametric form Line<T, N> {origin, direction}: the point set { origin + t * direction, t in R }.
// The direction need not be unit length; point_at(line, t) = origin + t * direction, so t is
// measured in units of |direction|. A zero (or non-finite) direction is a degenerate line:
// is_degenerate() reports it, point_at() still returns origin + t * direction (the origin for a
// zero direction), and conversions that need a direction return std::nullopt.
//
// Implicit form ImplicitLine2<T> {normal = (a, b), c}: the point set { X : a x + b y + c = 0 }.
// Orientation convention: the conversion from the parametric form uses normal = perp(direction)
// = (-d.y, d.x), the counter-clockwise perpendicular, so evaluate(implicit, p) > 0 exactly on the
// left of the directed line, which is the side where orient2d(origin, origin + d, p) > 0. The
// value is a signed distance scaled by |normal|; normalized() rescales to a unit normal. A zero
// normal is degenerate (the set is empty when c != 0, the whole plane when c == 0).
//
// Conversions are computed in floating point and rounded; they are exact when the inputs are
// integers of moderate size (normal = perp(d) is always exact; c = -dot(normal, origin) rounds).
// Cost: O(N) per call, no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <optional>

namespace locus {

/// The line { origin + t * direction : t in R }; direction need not be unit length.
template <class T, int N>
struct Line {
  Vec<T, N> origin;
  Vec<T, N> direction;
};

template <Real T>
using Line2 = Line<T, 2>;
template <Real T>
using Line3 = Line<T, 3>;
using Line2f = Line2<float>;
using Line2d = Line2<double>;
using Line3f = Line3<float>;
using Line3d = Line3<double>;

/// The line { X : dot(normal, X) + c = 0 } in the plane, i.e. a x + b y + c = 0 with normal (a, b).
template <Real T>
struct ImplicitLine2 {
  Vec2<T> normal;
  T c;
};

using ImplicitLine2f = ImplicitLine2<float>;
using ImplicitLine2d = ImplicitLine2<double>;

/// origin + t * direction.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const Line<T, N>& line, T t) noexcept {
  return line.origin + t * line.direction;
}

/// True when the direction is zero or a coordinate of the line is not finite.
template <class T, int N>
[[nodiscard]] constexpr bool is_degenerate(const Line<T, N>& line) noexcept {
  return !is_finite(line.origin) || !is_finite(line.direction) || line.direction == Vec<T, N>{};
}

/// True when the normal is zero or a coefficient is not finite.
template <Real T>
[[nodiscard]] constexpr bool is_degenerate(const ImplicitLine2<T>& line) noexcept {
  return !is_finite(line.normal) || !is_finite(line.c) || line.normal == Vec2<T>{};
}

/// The same line with a unit direction (t then measures Euclidean distance along the line),
/// or std::nullopt when the line is degenerate.
template <class T, int N>
[[nodiscard]] inline std::optional<Line<T, N>> normalized(const Line<T, N>& line) noexcept {
  if (is_degenerate(line)) return std::nullopt;
  return Line<T, N>{line.origin, normalize(line.direction)};
}

/// a x + b y + c: zero on the line, positive on the side the normal points to (rounded).
template <Real T>
[[nodiscard]] constexpr T evaluate(const ImplicitLine2<T>& line, const Vec2<T>& p) noexcept {
  return dot(line.normal, p) + line.c;
}

/// The same line scaled to a unit normal, so evaluate() is the signed Euclidean distance;
/// std::nullopt when the line is degenerate.
template <Real T>
[[nodiscard]] inline std::optional<ImplicitLine2<T>> normalized(
    const ImplicitLine2<T>& line) noexcept {
  if (is_degenerate(line)) return std::nullopt;
  const Normalized<T, 2> n = normalize_with_length(line.normal);
  return ImplicitLine2<T>{n.dir, line.c / n.length};
}

/// Implicit form of a 2D line: normal = perp(direction) (left side positive),
/// c = -dot(normal, origin). std::nullopt when the line is degenerate.
template <Real T>
[[nodiscard]] constexpr std::optional<ImplicitLine2<T>> to_implicit(const Line2<T>& line) noexcept {
  if (is_degenerate(line)) return std::nullopt;
  const Vec2<T> n = perp(line.direction);
  return ImplicitLine2<T>{n, -dot(n, line.origin)};
}

/// Parametric form of an implicit line: direction = (b, -a), so that perp(direction) = normal
/// (the inverse of to_implicit's convention), origin = the point of the line closest to the
/// coordinate origin, -c * normal / |normal|^2. std::nullopt when the line is degenerate.
template <Real T>
[[nodiscard]] inline std::optional<Line2<T>> to_parametric(const ImplicitLine2<T>& line) noexcept {
  if (is_degenerate(line)) return std::nullopt;
  // Scale by the largest component first so that |normal|^2 neither overflows nor underflows.
  const T m = max_abs(line.normal);
  const Vec2<T> u = line.normal / m;
  const Vec2<T> origin = (-(line.c / m) / sqr_length(u)) * u;
  if (!is_finite(origin)) return std::nullopt;
  return Line2<T>{origin, Vec2<T>{line.normal.y, -line.normal.x}};
}

}  // namespace locus
