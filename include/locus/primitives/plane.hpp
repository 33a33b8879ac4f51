// SPDX-License-Identifier: BSL-1.0
#pragma once
// Planes in 3D, coordinate systems in a plane, and 2D objects embedded in 3D; row prim3.planar;
// book sections 9.2.1-9.2.3, figures 9.1 (point-normal form), 9.2 (meaning of the coefficients),
// 9.3 (parametric form). How 2D objects and polygons live in a plane: docs/notes/primitives.md.
//
// Plane3<T> {normal, constant} is the point set { X : dot(normal, X) = constant }, the book's
// a x + b y + c z + d = 0 with normal (a, b, c) and constant = -d. The normal need NOT be unit
// length: signed_value() is then dot(normal, X) - constant, a multiple |normal| of the signed
// distance; signed_distance() divides by |normal|. normalized() rescales to a unit normal.
// Point-normal form (fig 9.1): plane_from_point_normal(P, n) = { X : dot(n, X - P) = 0 }.
// "Positive side" = the side the normal points to (signed_value > 0). plane_through(a, b, c) has
// normal (b - a) x (c - a): a, b, c run counter-clockwise seen from the positive side.
// PlaneFrame3<T> {origin, u, v, normal} is a right-handed orthonormal frame with u x v = normal
// (fig 9.3: P + s u + t v). to_world(frame, (s, t)) embeds 2D coordinates in the plane;
// to_plane() is the inverse on the plane and the orthogonal projection followed by the inverse
// elsewhere. newell_normal(points) is Newell's normal of a closed polygon (2 * area * unit normal
// for a planar one, right-hand rule; translation errors cancel); best_fit_plane_newell() is the
// plane with that normal through the vertex average.
//
// Degenerate input: plane_through returns std::nullopt when the three points are collinear or
// coincident (decided EXACTLY by Triangle's is_degenerate, i.e. orient2d on three projections)
// or when the rounded normal is zero or not finite (underflow/overflow). A zero normal makes a
// plane degenerate (is_degenerate()); normalized() then gives {0, 0}, signed_distance() gives
// NaN, project() returns the point unchanged and plane_frame() returns std::nullopt. NaN input
// propagates through arithmetic; nothing divides by zero. Everything is O(1) except the Newell
// functions, which are O(n); no allocation.

#include <locus/config.hpp>
#include <locus/core/basis.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/triangle.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>

namespace locus {

/// The plane { X : dot(normal, X) = constant }; the normal need not be unit length.
template <Real T>
struct Plane3 {
  Vec3<T> normal;
  T constant;
};

using Plane3f = Plane3<float>;
using Plane3d = Plane3<double>;

/// Point-normal form (fig 9.1): the plane through p with normal n, { X : dot(n, X - p) = 0 }.
template <Real T>
[[nodiscard]] constexpr Plane3<T> plane_from_point_normal(const Vec3<T>& p,
                                                          const Vec3<T>& n) noexcept {
  return {n, dot(n, p)};
}

/// True when the normal is zero or a coefficient is not finite.
template <Real T>
[[nodiscard]] constexpr bool is_degenerate(const Plane3<T>& pl) noexcept {
  return !is_finite(pl.normal) || !is_finite(pl.constant) || pl.normal == Vec3<T>{};
}

/// The plane through a, b, c with normal (b - a) x (c - a); std::nullopt when the points are
/// (exactly) collinear or the rounded normal is zero or not finite.
template <Real T>
[[nodiscard]] inline std::optional<Plane3<T>> plane_through(const Vec3<T>& a, const Vec3<T>& b,
                                                            const Vec3<T>& c) noexcept {
  if (is_degenerate(Triangle3<T>{a, b, c})) return std::nullopt;
  const Vec3<T> n = cross(b - a, c - a);
  if (!is_finite(n) || n == Vec3<T>{}) return std::nullopt;
  // dot(n, a): exact whenever n and the products are (small integer coordinates), so then all
  // three points satisfy the equation exactly.
  return Plane3<T>{n, dot(n, a)};
}

/// dot(normal, X) - constant: |normal| times the signed distance; positive on the normal side.
template <Real T>
[[nodiscard]] constexpr T signed_value(const Plane3<T>& pl, const Vec3<T>& x) noexcept {
  return dot(pl.normal, x) - pl.constant;
}

/// The same plane with a unit normal; {0, 0} for a degenerate plane.
template <Real T>
[[nodiscard]] inline Plane3<T> normalized(const Plane3<T>& pl) noexcept {
  if (is_degenerate(pl)) return {Vec3<T>{}, T(0)};
  const auto nl = normalize_with_length(pl.normal);
  return {nl.dir, pl.constant / nl.length};
}

/// Signed Euclidean distance from x to the plane (positive on the normal side); NaN for a
/// degenerate plane.
template <Real T>
[[nodiscard]] inline T signed_distance(const Plane3<T>& pl, const Vec3<T>& x) noexcept {
  if (is_degenerate(pl)) return std::numeric_limits<T>::quiet_NaN();
  const auto nl = normalize_with_length(pl.normal);
  return dot(nl.dir, x) - pl.constant / nl.length;
}

/// Orthogonal projection of x onto the plane; x itself for a degenerate plane.
template <Real T>
[[nodiscard]] inline Vec3<T> project(const Plane3<T>& pl, const Vec3<T>& x) noexcept {
  if (is_degenerate(pl)) return x;
  const auto nl = normalize_with_length(pl.normal);
  return x - (dot(nl.dir, x) - pl.constant / nl.length) * nl.dir;
}

/// The point of the plane closest to the coordinate origin; the origin for a degenerate plane.
template <Real T>
[[nodiscard]] inline Vec3<T> closest_to_origin(const Plane3<T>& pl) noexcept {
  return project(pl, Vec3<T>{});
}

/// Two unit vectors u, v with (u, v, n) a right-handed orthonormal basis.
template <Real T>
struct PerpendicularBasis {
  Vec3<T> u;
  Vec3<T> v;
};

/// Completes a direction to a right-handed orthonormal basis: u, v with u x v = n / |n|: the
/// in-plane axes of core/basis.hpp's complete_basis (also used by Circle3/Disk3, so a
/// cylinder's cross-section and a Circle3 with the same normal are parametrised alike).
/// A zero or non-finite n gives u = v = 0.
template <Real T>
[[nodiscard]] inline PerpendicularBasis<T> perpendicular_basis(const Vec3<T>& n) noexcept {
  const OrthonormalBasis<T, 3> b = complete_basis(n);
  if (b.status != Status::ok) return {Vec3<T>{}, Vec3<T>{}};
  return {b.axis[1], b.axis[2]};
}

/// A right-handed orthonormal frame in a plane: origin on the plane, u x v = normal.
template <Real T>
struct PlaneFrame3 {
  Vec3<T> origin;
  Vec3<T> u;
  Vec3<T> v;
  Vec3<T> normal;
};

/// The frame with the given origin and normal direction (u from perpendicular_basis);
/// std::nullopt for a zero or non-finite normal or a non-finite origin.
template <Real T>
[[nodiscard]] inline std::optional<PlaneFrame3<T>> plane_frame(const Vec3<T>& origin,
                                                               const Vec3<T>& normal) noexcept {
  if (!is_finite(origin)) return std::nullopt;
  const Vec3<T> w = normalize(normal);
  if (w == Vec3<T>{}) return std::nullopt;
  const auto b = perpendicular_basis(w);
  return PlaneFrame3<T>{origin, b.u, b.v, w};
}

/// A frame of the plane whose origin is the plane point closest to the coordinate origin;
/// std::nullopt for a degenerate plane.
template <Real T>
[[nodiscard]] inline std::optional<PlaneFrame3<T>> plane_frame(const Plane3<T>& pl) noexcept {
  if (is_degenerate(pl)) return std::nullopt;
  return plane_frame(closest_to_origin(pl), pl.normal);
}

/// The plane of a frame (unit normal).
template <Real T>
[[nodiscard]] constexpr Plane3<T> plane_of(const PlaneFrame3<T>& f) noexcept {
  return plane_from_point_normal(f.origin, f.normal);
}

/// Embeds plane coordinates (s, t): origin + s u + t v.
template <Real T>
[[nodiscard]] constexpr Vec3<T> to_world(const PlaneFrame3<T>& f, const Vec2<T>& st) noexcept {
  return f.origin + st.x * f.u + st.y * f.v;
}

/// Parametric form of the plane (fig 9.3), the same as to_world.
template <Real T>
[[nodiscard]] constexpr Vec3<T> point_at(const PlaneFrame3<T>& f, const Vec2<T>& st) noexcept {
  return to_world(f, st);
}

/// Plane coordinates of the orthogonal projection of x: (dot(x - origin, u), dot(x - origin, v)).
template <Real T>
[[nodiscard]] constexpr Vec2<T> to_plane(const PlaneFrame3<T>& f, const Vec3<T>& x) noexcept {
  const Vec3<T> d = x - f.origin;
  return {dot(d, f.u), dot(d, f.v)};
}

/// Newell's normal of the closed polygon p[0], ..., p[n-1]: 2 * area * unit normal for a
/// planar polygon, counter-clockwise seen from the side it points to; 0 for fewer than 3 points.
template <Real T>
[[nodiscard]] constexpr Vec3<T> newell_normal(std::span<const Vec3<T>> p) noexcept {
  Vec3<T> n{};
  const std::size_t count = p.size();
  if (count < 3) return n;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3<T>& a = p[i];
    const Vec3<T>& b = p[i + 1 == count ? 0 : i + 1];
    // (a_y - b_y)(a_z + b_z), ...: each term is a trapezoid area of a projected edge.
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

/// Newell's normal of the n vertices starting at p.
template <Real T>
[[nodiscard]] constexpr Vec3<T> newell_normal(const Vec3<T>* p, std::size_t n) noexcept {
  return newell_normal(std::span<const Vec3<T>>(p, n));
}

/// The plane with Newell's normal through the vertex average; std::nullopt when the normal is
/// zero or not finite (fewer than 3 points, all collinear, or zero net area).
template <Real T>
[[nodiscard]] inline std::optional<Plane3<T>> best_fit_plane_newell(
    std::span<const Vec3<T>> p) noexcept {
  const Vec3<T> n = newell_normal(p);
  if (!is_finite(n) || n == Vec3<T>{}) return std::nullopt;
  Vec3<T> mean{};
  const T w = T(1) / static_cast<T>(p.size());
  for (const auto& q : p) mean += w * q;
  return plane_from_point_normal(mean, n);
}

/// best_fit_plane_newell of the n vertices starting at p.
template <Real T>
[[nodiscard]] inline std::optional<Plane3<T>> best_fit_plane_newell(const Vec3<T>* p,
                                                                    std::size_t n) noexcept {
  return best_fit_plane_newell(std::span<const Vec3<T>>(p, n));
}

// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] constexpr Vec3<range_scalar_t<R>> newell_normal(const R& p) noexcept {
  return newell_normal(point_span(p));
}
template <PointRange3 R>
[[nodiscard]] inline std::optional<Plane3<range_scalar_t<R>>> best_fit_plane_newell(
    const R& p) noexcept {
  return best_fit_plane_newell(point_span(p));
}

}  // namespace locus
