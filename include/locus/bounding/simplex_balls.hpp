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
//
// Exactness: whether the simplex is degenerate is decided exactly (orient2d, orient3d, and the
// exact 3D collinearity test of primitives/triangle.hpp). Centres and radii are constructions:
// computed in double (also for float input, which is promoted exactly) from coordinates relative
// to v0 and rounded once to T. For a triangle with smallest height h and longest edge L the
// circumcentre's relative error grows like eps L / h (an inherent conditioning, not an artefact).
// The circumradius is |v0 - centre| of the rounded centre.
//
// Degenerate input: collinear or coincident vertices (triangles), coplanar vertices
// (tetrahedra), a NaN/infinite coordinate, or a construction that overflows give std::nullopt.
// Cost O(1), no allocation.

#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/sphere.hpp>
#include <locus/primitives/tetrahedron.hpp>
#include <locus/primitives/triangle.hpp>

#include <cmath>
#include <optional>

namespace locus {

namespace detail {

/// Circumcentre of a non-degenerate 2D triangle, in double (rounded).
[[nodiscard]] inline Vec2<double> circumcenter(const Vec2<double>& a, const Vec2<double>& b,
                                               const Vec2<double>& c) noexcept {
  const Vec2<double> u = b - a, v = c - a;
  const double uu = sqr_length(u), vv = sqr_length(v);
  const double d = 2.0 * perp_dot(u, v);
  return a + Vec2<double>{(v.y * uu - u.y * vv) / d, (u.x * vv - v.x * uu) / d};
}

/// Circumcentre of a non-degenerate 3D triangle (the centre lies in its plane), in double.
[[nodiscard]] inline Vec3<double> circumcenter(const Vec3<double>& a, const Vec3<double>& b,
                                               const Vec3<double>& c) noexcept {
  const Vec3<double> u = b - a, v = c - a, w = cross(u, v);
  const Vec3<double> x = sqr_length(u) * cross(v, w) + sqr_length(v) * cross(w, u);
  return a + x / (2.0 * sqr_length(w));
}

/// Circumcentre of a non-degenerate tetrahedron, in double.
[[nodiscard]] inline Vec3<double> circumcenter(const Vec3<double>& a, const Vec3<double>& b,
                                               const Vec3<double>& c,
                                               const Vec3<double>& d) noexcept {
  const Vec3<double> u = b - a, v = c - a, w = d - a;
  const Vec3<double> vw = cross(v, w);
  const Vec3<double> x =
      sqr_length(u) * vw + sqr_length(v) * cross(w, u) + sqr_length(w) * cross(u, v);
  return a + x / (2.0 * dot(u, vw));
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
  const double r = length(a - c);
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
  const double r = length(a - c);
  const Vec3<double> n = normalize(cross(b - a, cc - a));
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
  const double la = length(c - b), lb = length(a - c), lc = length(b - a);
  const double perimeter = la + lb + lc;
  // Relative to a: the weights of b and c only, so a far-from-origin triangle keeps precision.
  const Vec2<double> center = a + (lb * (b - a) + lc * (c - a)) / perimeter;
  const double r = std::abs(perp_dot(b - a, c - a)) / perimeter;
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
  const double la = length(c - b), lb = length(a - c), lc = length(b - a);
  const double perimeter = la + lb + lc;
  const Vec3<double> center = a + (lb * (b - a) + lc * (c - a)) / perimeter;
  const Normalized<double, 3> n = normalize_with_length(cross(b - a, c - a));
  const double r = n.length / perimeter;
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
  const double r = length(a - c);
  if (!detail::finite_ball<T, 3>(c, r)) return std::nullopt;
  return Sphere3<T>{vec_cast<T>(c), static_cast<T>(r)};
}

/// The sphere tangent to the four face planes of a tetrahedron; std::nullopt if coplanar.
template <Real T>
[[nodiscard]] inline std::optional<Sphere3<T>> inscribed_sphere(
    const Tetrahedron3<T>& tet) noexcept {
  if (orient3d(tet.v[0], tet.v[1], tet.v[2], tet.v[3]) == Sign::zero) return std::nullopt;
  Vec3<double> p[4];
  for (int i = 0; i < 4; ++i) p[i] = vec_cast<double>(tet.v[i]) - vec_cast<double>(tet.v[0]);
  // Twice the area of the face opposite vertex i.
  const double area2[4] = {length(cross(p[2] - p[1], p[3] - p[1])), length(cross(p[2], p[3])),
                           length(cross(p[1], p[3])), length(cross(p[1], p[2]))};
  const double total = area2[0] + area2[1] + area2[2] + area2[3];
  const Vec3<double> offset = (area2[1] * p[1] + area2[2] * p[2] + area2[3] * p[3]) / total;
  const double six_volume = std::abs(dot(p[1], cross(p[2], p[3])));
  // r = 3 V / sum A_i = (6 V) / (sum 2 A_i).
  const double r = six_volume / total;
  const Vec3<double> center = vec_cast<double>(tet.v[0]) + offset;
  if (!detail::finite_ball<T, 3>(center, r)) return std::nullopt;
  return Sphere3<T>{vec_cast<T>(center), static_cast<T>(r)};
}

}  // namespace locus
