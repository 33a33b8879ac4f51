// SPDX-License-Identifier: BSL-1.0
#pragma once
// Circumscribed and inscribed circles of triangles (2D and 3D) and spheres of tetrahedra;
// CAPABILITIES row cg.balls; book section 13.9 ("Circumscribed and inscribed balls"),
// figure 13.78.
//
// circumscribed_circle(tri): the circle through the three vertices. In 2D a Circle2; in 3D a
// Circle3 in the triangle's plane with normal = unit((v1 - v0) x (v2 - v0)).
// inscribed_circle(tri): the circle tangent to the three edges (lines of the sides), centred at
// the incentre (|v1 - v2| v0 + |v2 - v0| v1 + |v0 - v1| v2) / perimeter, radius 2 area /
// perimeter; 3D likewise, in the triangle's plane.
// circumscribed_sphere(tet): the sphere through the four vertices; inscribed_sphere(tet): the
// sphere tangent to the four face planes, centre sum_i A_i v_i / sum_i A_i (A_i the area of the
// face opposite v_i), radius 3 volume / sum_i A_i. Either vertex order (orientation) works.
// Exactness: degeneracy is decided exactly (orient2d, orient3d, the exact 3D collinearity test
// of primitives/triangle.hpp). Centres and radii are constructions computed in double (float
// input is promoted exactly) from the edges from v0, rounded once to T; the circumcentre's
// relative error grows like eps L / h (L the longest edge, h the smallest height). Products of
// edge coordinates are formed on the edges scaled by a power of two when they could leave the
// range (docs/notes/bounding.md), so the balls are scale-covariant: input scaled by 2^k gives
// them scaled by 2^k exactly, for every k that keeps the input finite and normal.
// Degenerate input: collinear or coincident vertices (triangles), coplanar vertices
// (tetrahedra), a NaN/infinite coordinate, or a result that overflows T give std::nullopt.
// Cost O(1), no allocation.

#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/sphere.hpp>
#include <locus/primitives/tetrahedron.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace locus {

namespace detail {

/// The power of two by which vectors of largest |coordinate| m are scaled before products of up
/// to `degree` coordinates are formed: normalising_scale(m) when such products could leave the
/// range of double (distance/detail/rescale.hpp), else 1. Scaling by it is exact, so a
/// construction computed on the scaled copy and scaled back is the unscaled one, times 2^k for
/// input scaled by 2^k.
template <int degree>
[[nodiscard]] inline double product_scale(double m) noexcept {
  return outside_product_range<double, degree>(m) ? normalising_scale(m) : 1.0;
}

/// |v|, computed on v scaled by a power of two when its square would leave the range.
template <int N>
[[nodiscard]] inline double scaled_length(const Vec<double, N>& v) noexcept {
  const double f = product_scale<2>(max_abs(v));
  return length(f * v) / f;
}

/// Offset from a of the circumcentre of the 2D triangle a, a + u, a + v (u, v scaled).
[[nodiscard]] inline Vec2<double> circumcenter_offset(const Vec2<double>& u,
                                                      const Vec2<double>& v) noexcept {
  const double uu = sqr_length(u), vv = sqr_length(v);
  const double d = 2.0 * perp_dot(u, v);
  return Vec2<double>{(v.y * uu - u.y * vv) / d, (u.x * vv - v.x * uu) / d};
}

/// Offset from a of the circumcentre of the 3D triangle a, a + u, a + v (in its plane).
[[nodiscard]] inline Vec3<double> circumcenter_offset(const Vec3<double>& u,
                                                      const Vec3<double>& v) noexcept {
  const Vec3<double> w = cross(u, v);
  const Vec3<double> x = sqr_length(u) * cross(v, w) + sqr_length(v) * cross(w, u);
  return x / (2.0 * sqr_length(w));
}

/// Circumcentre of a non-degenerate 2D or 3D triangle, in double (rounded). The offset from a
/// (products of up to five edge coordinates) is computed on the edges scaled by a power of two.
template <int N>
[[nodiscard]] inline Vec<double, N> circumcenter(const Vec<double, N>& a, const Vec<double, N>& b,
                                                 const Vec<double, N>& c) noexcept {
  const Vec<double, N> u = b - a, v = c - a;
  const double f = product_scale<6>(std::max(max_abs(u), max_abs(v)));
  return a + circumcenter_offset(f * u, f * v) / f;
}

/// Circumcentre of a non-degenerate tetrahedron, in double (scaled as above).
[[nodiscard]] inline Vec3<double> circumcenter(const Vec3<double>& a, const Vec3<double>& b,
                                               const Vec3<double>& c,
                                               const Vec3<double>& d) noexcept {
  Vec3<double> u = b - a, v = c - a, w = d - a;
  const double f = product_scale<6>(std::max({max_abs(u), max_abs(v), max_abs(w)}));
  u = f * u, v = f * v, w = f * w;
  const Vec3<double> vw = cross(v, w);
  const Vec3<double> x =
      sqr_length(u) * vw + sqr_length(v) * cross(w, u) + sqr_length(w) * cross(u, v);
  return a + x / (2.0 * dot(u, vw)) / f;
}

template <class T, int N>
[[nodiscard]] inline bool finite_ball(const Vec<double, N>& c, double r) noexcept {
  return is_finite(vec_cast<T>(c)) && is_finite(static_cast<T>(r));
}

}  // namespace detail

/// The circle through the vertices of a 2D triangle; std::nullopt if they are collinear.
template <Real T>
[[nodiscard]] inline std::optional<Circle2<T>> circumscribed_circle(
    const Triangle<T, 2>& tri) noexcept {
  if (orient2d(tri.v0, tri.v1, tri.v2) == Sign::zero) return std::nullopt;
  const Vec2<double> a = vec_cast<double>(tri.v0);
  const Vec2<double> c =
      detail::circumcenter(a, vec_cast<double>(tri.v1), vec_cast<double>(tri.v2));
  const double r = detail::scaled_length(a - c);
  if (!detail::finite_ball<T, 2>(c, r)) return std::nullopt;
  return Circle2<T>{vec_cast<T>(c), static_cast<T>(r)};
}

/// The circle through the vertices of a 3D triangle, in its plane; std::nullopt if collinear.
template <Real T>
[[nodiscard]] inline std::optional<Circle3<T>> circumscribed_circle(
    const Triangle<T, 3>& tri) noexcept {
  if (is_degenerate(tri)) return std::nullopt;
  const Vec3<double> a = vec_cast<double>(tri.v0), b = vec_cast<double>(tri.v1),
                     cc = vec_cast<double>(tri.v2);
  const Vec3<double> c = detail::circumcenter(a, b, cc);
  const double r = detail::scaled_length(a - c);
  const Vec3<double> u = b - a, v = cc - a;
  // (normalize forms products of four coordinates: |u x v|^2.)
  const double f = detail::product_scale<4>(std::max(max_abs(u), max_abs(v)));
  const Vec3<double> n = normalize(cross(f * u, f * v));
  if (!detail::finite_ball<T, 3>(c, r) || !is_finite(n)) return std::nullopt;
  return Circle3<T>{vec_cast<T>(c), vec_cast<T>(n), static_cast<T>(r)};
}

/// The circle tangent to the three sides of a 2D triangle; std::nullopt if collinear.
template <Real T>
[[nodiscard]] inline std::optional<Circle2<T>> inscribed_circle(
    const Triangle<T, 2>& tri) noexcept {
  if (orient2d(tri.v0, tri.v1, tri.v2) == Sign::zero) return std::nullopt;
  const Vec2<double> a = vec_cast<double>(tri.v0), b = vec_cast<double>(tri.v1),
                     c = vec_cast<double>(tri.v2);
  // On the edges scaled by a power of two f (products of two coordinates), scaled back by 1/f.
  const Vec2<double> ab = b - a, ac = c - a, bc = c - b;
  const double f = detail::product_scale<2>(std::max({max_abs(ab), max_abs(ac), max_abs(bc)}));
  const double la = length(f * bc), lb = length(f * ac), lc = length(f * ab);
  const double perimeter = la + lb + lc;
  // Relative to a: the weights of b and c only, so a far-from-origin triangle keeps precision.
  const Vec2<double> center = a + (lb * (f * ab) + lc * (f * ac)) / perimeter / f;
  const double r = std::abs(perp_dot(f * ab, f * ac)) / perimeter / f;
  if (!detail::finite_ball<T, 2>(center, r)) return std::nullopt;
  return Circle2<T>{vec_cast<T>(center), static_cast<T>(r)};
}

/// The circle tangent to the three sides of a 3D triangle, in its plane; std::nullopt if
/// collinear.
template <Real T>
[[nodiscard]] inline std::optional<Circle3<T>> inscribed_circle(
    const Triangle<T, 3>& tri) noexcept {
  if (is_degenerate(tri)) return std::nullopt;
  const Vec3<double> a = vec_cast<double>(tri.v0), b = vec_cast<double>(tri.v1),
                     c = vec_cast<double>(tri.v2);
  const Vec3<double> ab = b - a, ac = c - a, bc = c - b;
  // (normalize_with_length forms products of four coordinates: |ab x ac|^2.)
  const double f = detail::product_scale<4>(std::max({max_abs(ab), max_abs(ac), max_abs(bc)}));
  const double la = length(f * bc), lb = length(f * ac), lc = length(f * ab);
  const double perimeter = la + lb + lc;
  const Vec3<double> center = a + (lb * (f * ab) + lc * (f * ac)) / perimeter / f;
  const Normalized<double, 3> n = normalize_with_length(cross(f * ab, f * ac));
  const double r = n.length / perimeter / f;
  if (!detail::finite_ball<T, 3>(center, r) || !is_finite(n.dir)) return std::nullopt;
  return Circle3<T>{vec_cast<T>(center), vec_cast<T>(n.dir), static_cast<T>(r)};
}

/// The sphere through the four vertices of a tetrahedron; std::nullopt if they are coplanar.
template <Real T>
[[nodiscard]] inline std::optional<Sphere3<T>> circumscribed_sphere(
    const Tetrahedron3<T>& tet) noexcept {
  if (orient3d(tet.v[0], tet.v[1], tet.v[2], tet.v[3]) == Sign::zero) return std::nullopt;
  const Vec3<double> a = vec_cast<double>(tet.v[0]);
  const Vec3<double> c = detail::circumcenter(
      a, vec_cast<double>(tet.v[1]), vec_cast<double>(tet.v[2]), vec_cast<double>(tet.v[3]));
  const double r = detail::scaled_length(a - c);
  if (!detail::finite_ball<T, 3>(c, r)) return std::nullopt;
  return Sphere3<T>{vec_cast<T>(c), static_cast<T>(r)};
}

/// The sphere tangent to the four face planes of a tetrahedron; std::nullopt if coplanar.
template <Real T>
[[nodiscard]] inline std::optional<Sphere3<T>> inscribed_sphere(
    const Tetrahedron3<T>& tet) noexcept {
  if (orient3d(tet.v[0], tet.v[1], tet.v[2], tet.v[3]) == Sign::zero) return std::nullopt;
  // Edges from v0, scaled by a power of two f (products of up to three coordinates).
  Vec3<double> p[4];
  double m = 0.0;
  for (int i = 0; i < 4; ++i) {
    p[i] = vec_cast<double>(tet.v[i]) - vec_cast<double>(tet.v[0]);
    m = std::max(m, max_abs(p[i]));
  }
  const double f = detail::product_scale<4>(m);
  for (Vec3<double>& q : p) q = f * q;
  // Twice the area of the face opposite vertex i.
  const double area2[4] = {length(cross(p[2] - p[1], p[3] - p[1])), length(cross(p[2], p[3])),
                           length(cross(p[1], p[3])), length(cross(p[1], p[2]))};
  const double total = area2[0] + area2[1] + area2[2] + area2[3];
  const Vec3<double> offset = (area2[1] * p[1] + area2[2] * p[2] + area2[3] * p[3]) / total / f;
  const double six_volume = std::abs(dot(p[1], cross(p[2], p[3])));
  // r = 3 V / sum A_i = (6 V) / (sum 2 A_i).
  const double r = six_volume / total / f;
  const Vec3<double> center = vec_cast<double>(tet.v[0]) + offset;
  if (!detail::finite_ball<T, 3>(center, r)) return std::nullopt;
  return Sphere3<T>{vec_cast<T>(center), static_cast<T>(r)};
}

}  // namespace locus
