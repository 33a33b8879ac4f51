// SPDX-License-Identifier: BSL-1.0
#pragma once
// Whether two triangles in 3D have a common point: intersects() (the book's test, section
// 11.5.4, figures 11.25-11.28; row int3.plane-triangle, the triangle-triangle test only). Used
// by the mesh self-intersection check (mesh/mesh_checks.hpp).
// Triangles are closed sets: touching at a vertex, along an edge or in a shared plane counts.
// Every decision is an exact sign (orient3d, orient2d of core/predicates.hpp); there is no
// tolerance and no constructed point, so the answer is the exact one for the floating-point
// input and invariant under swapping the arguments, reordering the vertices and scaling by
// powers of two (inside the predicates' range).
// Method: a plane rejection first (all three vertices of one triangle strictly on one side of
// the other's plane: false). Otherwise two closed convex sets whose boundaries are their edges
// meet iff an edge of one meets the other (docs/notes/mesh.md), so six exact segment-triangle
// tests decide: a segment not in the triangle's plane meets it iff its end points are not
// strictly on one side and the three signs orient3d(a, b, edge) are not strictly mixed; a
// segment in the plane is tested in the coordinate plane, chosen exactly, where the triangle's
// projection is non-degenerate (orient2d != 0), by end-point containment and segment crossings.
// Degenerate triangles (collinear or coincident vertices, decided exactly) act as the segment
// or point they are: they are tested through their edges (segment-segment in 3D: coplanar by
// orient3d, then in a coordinate plane that is injective on the four points).
// Non-finite input: false. Cost: 6 orient3d in the common rejection; at most about 40 signs.

#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/triangle.hpp>

#include <cmath>

namespace locus {

namespace detail::tri3 {

template <Real T>
[[nodiscard]] inline Vec2<T> drop(const Vec3<T>& p, int axis) noexcept {
  // Keep a right-handed pair: dropping x gives (y, z), y gives (z, x), z gives (x, y).
  return axis == 0 ? Vec2<T>{p.y, p.z} : (axis == 1 ? Vec2<T>{p.z, p.x} : Vec2<T>{p.x, p.y});
}

/// An axis whose dropping keeps the triangle a, b, c non-degenerate, or -1 if it is degenerate.
template <Real T>
[[nodiscard]] inline int projection_axis(const Vec3<T>& a, const Vec3<T>& b,
                                         const Vec3<T>& c) noexcept {
  for (int k = 2; k >= 0; --k) {
    if (orient2d(drop(a, k), drop(b, k), drop(c, k)) != Sign::zero) return k;
  }
  return -1;
}

template <Real T>
[[nodiscard]] inline bool on_segment2(const Vec2<T>& p, const Vec2<T>& a,
                                      const Vec2<T>& b) noexcept {
  // p is collinear with a, b (checked by the caller): inside the bounding box.
  return std::fmin(a.x, b.x) <= p.x && p.x <= std::fmax(a.x, b.x) && std::fmin(a.y, b.y) <= p.y &&
         p.y <= std::fmax(a.y, b.y);
}

/// Closed segments ab and cd in the plane share a point (exact).
template <Real T>
[[nodiscard]] inline bool segments2(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c,
                                    const Vec2<T>& d) noexcept {
  const Sign s1 = orient2d(a, b, c), s2 = orient2d(a, b, d);
  const Sign s3 = orient2d(c, d, a), s4 = orient2d(c, d, b);
  if (to_int(s1) * to_int(s2) < 0 && to_int(s3) * to_int(s4) < 0) return true;
  if (s1 == Sign::zero && on_segment2(c, a, b)) return true;
  if (s2 == Sign::zero && on_segment2(d, a, b)) return true;
  if (s3 == Sign::zero && on_segment2(a, c, d)) return true;
  if (s4 == Sign::zero && on_segment2(b, c, d)) return true;
  return false;
}

/// p in the closed non-degenerate triangle abc of the plane (exact).
template <Real T>
[[nodiscard]] inline bool in_triangle2(const Vec2<T>& p, const Vec2<T>& a, const Vec2<T>& b,
                                       const Vec2<T>& c) noexcept {
  const int s = to_int(orient2d(a, b, c));
  return to_int(orient2d(a, b, p)) * s >= 0 && to_int(orient2d(b, c, p)) * s >= 0 &&
         to_int(orient2d(c, a, p)) * s >= 0;
}

/// Closed segments ab and cd in 3D share a point (exact; zero-length segments are points).
template <Real T>
[[nodiscard]] inline bool segments3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                    const Vec3<T>& d) noexcept {
  if (orient3d(a, b, c, d) != Sign::zero) return false;
  // Coplanar: find a coordinate plane injective on the affine hull of the four points.
  int axis = projection_axis(a, b, c);
  if (axis < 0) axis = projection_axis(a, b, d);
  if (axis < 0) axis = projection_axis(a, c, d);
  if (axis < 0) axis = projection_axis(b, c, d);
  if (axis < 0) {
    // All four collinear (or coincident): any axis along which two distinct points differ is
    // kept; dropping another one is injective on their line.
    const Vec3<T> pts[4] = {a, b, c, d};
    axis = 2;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        for (int k = 0; k < 3; ++k) {
          if (pts[i][k] != pts[j][k]) axis = (k + 1) % 3;
        }
      }
    }
  }
  return segments2(drop(a, axis), drop(b, axis), drop(c, axis), drop(d, axis));
}

/// Closed segment ab and closed triangle pqr share a point (exact, any degeneracy).
template <Real T>
[[nodiscard]] inline bool segment_triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& p,
                                           const Vec3<T>& q, const Vec3<T>& r) noexcept {
  const int axis = projection_axis(p, q, r);
  if (axis < 0) {
    return segments3(a, b, p, q) || segments3(a, b, q, r) || segments3(a, b, r, p);
  }
  const int sa = to_int(orient3d(p, q, r, a)), sb = to_int(orient3d(p, q, r, b));
  if (sa * sb > 0) return false;
  if (sa == 0 && sb == 0) {
    const Vec2<T> a2 = drop(a, axis), b2 = drop(b, axis), p2 = drop(p, axis);
    const Vec2<T> q2 = drop(q, axis), r2 = drop(r, axis);
    return in_triangle2(a2, p2, q2, r2) || in_triangle2(b2, p2, q2, r2) ||
           segments2(a2, b2, p2, q2) || segments2(a2, b2, q2, r2) || segments2(a2, b2, r2, p2);
  }
  // The segment meets the plane in one point; it lies in the triangle iff the line ab passes
  // no edge on the outside: the three signed volumes are not strictly mixed.
  const int s1 = to_int(orient3d(a, b, p, q)), s2 = to_int(orient3d(a, b, q, r));
  const int s3 = to_int(orient3d(a, b, r, p));
  return !((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0));
}

template <Real T>
[[nodiscard]] inline bool finite(const Triangle3<T>& t) noexcept {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(t[i].x) || !std::isfinite(t[i].y) || !std::isfinite(t[i].z)) return false;
  }
  return true;
}

/// All three vertices of u strictly on one side of the plane of t (t non-degenerate or not:
/// orient3d of a degenerate t is zero, which never rejects).
template <Real T>
[[nodiscard]] inline bool separated_by_plane(const Triangle3<T>& t,
                                             const Triangle3<T>& u) noexcept {
  const int s0 = to_int(orient3d(t.v0, t.v1, t.v2, u.v0));
  const int s1 = to_int(orient3d(t.v0, t.v1, t.v2, u.v1));
  const int s2 = to_int(orient3d(t.v0, t.v1, t.v2, u.v2));
  return (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
}

}  // namespace detail::tri3

/// Whether two closed triangles in 3D share a point (exact; see the header comment).
template <Real T>
[[nodiscard]] inline bool intersects(const Triangle3<T>& a, const Triangle3<T>& b) noexcept {
  if (!detail::tri3::finite(a) || !detail::tri3::finite(b)) return false;
  if (detail::tri3::separated_by_plane(a, b) || detail::tri3::separated_by_plane(b, a)) {
    return false;
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (detail::tri3::segment_triangle(a[i], a[j], b.v0, b.v1, b.v2)) return true;
    if (detail::tri3::segment_triangle(b[i], b[j], a.v0, a.v1, a.v2)) return true;
  }
  return false;
}

}  // namespace locus
