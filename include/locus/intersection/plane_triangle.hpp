// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a triangle and a plane in 3D: intersects() (test) and intersection() (find);
// row int3.plane-triangle, book section 11.5.3 (figures 11.25, 11.26).
// Plane3 {normal, constant} is { X : dot(normal, X) = constant }, taken as given (never
// normalised). Result TrianglePlaneIntersection<T>: param_a the triangle's (s, t) of
// point_at(tri, st) = v0 + s (v1 - v0) + t (v2 - v0), param_b NoParam. Kinds: empty; point (a
// vertex touching the plane); segment (an edge in the plane, or a crossing), its end points
// ordered along cross(plane normal, triangle normal) (the order in which plane_mesh.hpp chains
// slices: counter-clockwise seen from the positive side round an outward-oriented solid);
// polygon (the whole triangle lies in the plane: v0, v1, v2).
// Exact decisions: the side of each vertex is the exact sign of dot(normal, v) - constant
// (core/plane_side.hpp); the kind and which vertices or edges carry the end points follow from
// the three signs alone (the "lone vertex" rule, docs/notes/intersection3.md), no tolerance.
// Constructed points: a vertex in the plane is returned exactly (parameters exact); a crossing of
// edge p -> q uses t = f(p) / (f(p) - f(q)), f = dot(normal, .) - constant by a compensated dot
// product (core/plane_side.hpp plane_value), so |point - X|inf <= 8 eps max(|X|inf, m) +
// 2^-100 |q - p| / sin(angle) (eps of T, m the largest |vertex coordinate|, angle between the edge
// and the plane), as segment_plane.hpp.
// Degenerate: a triangle with (exactly) collinear or coincident vertices acts as the segment
// between its extreme vertices (segment_plane.hpp), so its answer is point, segment or empty; a
// plane with a zero normal, or any NaN or infinite coordinate, gives kind empty (intersects
// false). The swapped overloads (Plane3, Triangle3) return swapped(). Range: decisions exact
// while products of coordinates stay in the double range. Cost: three exact-sign filters and
// at most two compensated dot products; no allocation.

#include <locus/core/plane_side.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/result.hpp>
#include <locus/intersection/segment_plane.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace locus {

/// The result of intersection(Triangle3, Plane3): param_a the triangle's (s, t), param_b NoParam.
template <Real T>
using TrianglePlaneIntersection = Intersection<T, 3, Vec2<T>, NoParam, 3>;

namespace detail::plane_tri {

using V = Vec3<double>;

/// The (s, t) of vertex i of a triangle.
[[nodiscard]] constexpr Vec2<double> vertex_st(int i) noexcept {
  return i == 0 ? Vec2<double>{0, 0} : (i == 1 ? Vec2<double>{1, 0} : Vec2<double>{0, 1});
}

/// The lone vertex of three side signs: the vertex with a nonzero sign that differs from the
/// other two (each of them opposite or zero); -1 when there is none (all on one closed side).
/// When it exists the triangle meets the plane in the segment from the crossing on edge
/// (lone, lone + 1) to the crossing on edge (lone, lone + 2) (docs/notes/intersection3.md).
[[nodiscard]] constexpr int lone_vertex(const int s[3]) noexcept {
  for (int i = 0; i < 3; ++i) {
    if (s[i] == 0) continue;
    if (s[(i + 1) % 3] != s[i] && s[(i + 2) % 3] != s[i]) return i;
  }
  return -1;
}

/// The vertex with sign zero when the other two share a nonzero sign (a touching vertex), or -1.
[[nodiscard]] constexpr int touching_vertex(const int s[3]) noexcept {
  for (int i = 0; i < 3; ++i) {
    if (s[i] == 0 && s[(i + 1) % 3] == s[(i + 2) % 3] && s[(i + 1) % 3] != 0) return i;
  }
  return -1;
}

/// Extreme vertices (lexicographic order) of a degenerate triangle: its segment.
[[nodiscard]] inline std::array<int, 2> extremes(const V v[3]) noexcept {
  const auto less = [](const V& a, const V& b) {
    return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
  };
  int lo = 0, hi = 0;
  for (int i = 1; i < 3; ++i) {
    if (less(v[i], v[lo])) lo = i;
    if (less(v[hi], v[i])) hi = i;
  }
  return {lo, hi};
}

using Result = Intersection<double, 3, Vec2<double>, NoParam, 3>;

/// The point where edge p -> q meets the plane, with its (s, t); f are plane values, s signs.
inline void crossing(Result& r, const V v[3], const int s[3], const double f[3], int p,
                     int q) noexcept {
  double t;
  if (s[q] == 0) {
    t = 1.0;
  } else if (s[p] == 0) {
    t = 0.0;
  } else {
    t = std::clamp(f[p] / (f[p] - f[q]), 0.0, 1.0);
  }
  const int i = r.count++;
  r.point[i] = t == 1.0 ? v[q] : (t == 0.0 ? v[p] : v[p] + t * (v[q] - v[p]));
  r.param_a[i] = (1.0 - t) * vertex_st(p) + t * vertex_st(q);
}

template <bool Construct>
[[nodiscard]] inline Result find(const V v[3], const V& n, double c) noexcept {
  Result r;
  for (int i = 0; i < 3; ++i) {
    if (!detail::plane_side::finite3(v[i])) return r;
  }
  if (!detail::plane_side::finite3(n) || !std::isfinite(c) || n == V{}) return r;
  if (is_degenerate(Triangle3<double>{v[0], v[1], v[2]})) {
    const std::array<int, 2> e = extremes(v);
    const LinearPlaneIntersection<double> k =
        intersection(Segment3<double>{v[e[0]], v[e[1]]}, Plane3<double>{n, c});
    r.kind = k.kind;
    r.count = k.count;
    for (int i = 0; i < k.count; ++i) {
      const double t = k.param_a[static_cast<std::size_t>(i)];
      r.point[static_cast<std::size_t>(i)] = k.point[static_cast<std::size_t>(i)];
      r.param_a[static_cast<std::size_t>(i)] = (1.0 - t) * vertex_st(e[0]) + t * vertex_st(e[1]);
    }
    return r;
  }
  int s[3];
  for (int i = 0; i < 3; ++i) s[i] = to_int(side_of_plane(n, c, v[i]));
  if (s[0] == 0 && s[1] == 0 && s[2] == 0) {
    r.kind = Kind::polygon;
    r.count = 3;
    for (int i = 0; i < 3; ++i) {
      r.point[static_cast<std::size_t>(i)] = v[i];
      r.param_a[static_cast<std::size_t>(i)] = vertex_st(i);
    }
    return r;
  }
  const int a = lone_vertex(s);
  if (a < 0) {
    const int z = touching_vertex(s);
    if (z < 0) return r;
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = v[z];
    r.param_a[0] = vertex_st(z);
    return r;
  }
  r.kind = Kind::segment;
  if constexpr (!Construct) return r;
  double f[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    if (s[i] != 0) f[i] = plane_value(n, c, v[i]);
  }
  // Along cross(n, triangle normal) the crossing on edge (a, a + 1) comes first iff s[a] > 0.
  const int b = (a + 1) % 3, d = (a + 2) % 3;
  crossing(r, v, s, f, a, s[a] > 0 ? b : d);
  crossing(r, v, s, f, a, s[a] > 0 ? d : b);
  return r;
}

template <Real T>
[[nodiscard]] inline Result find(const Triangle3<T>& t, const Plane3<T>& p, bool construct) {
  const V v[3] = {vec_cast<double>(t.v0), vec_cast<double>(t.v1), vec_cast<double>(t.v2)};
  const V n = vec_cast<double>(p.normal);
  return construct ? find<true>(v, n, double(p.constant)) : find<false>(v, n, double(p.constant));
}

}  // namespace detail::plane_tri

/// Whether a closed triangle and a plane have a common point (exact).
template <Real T>
[[nodiscard]] inline bool intersects(const Triangle3<T>& t, const Plane3<T>& p) noexcept {
  return detail::plane_tri::find(t, p, false).kind != Kind::empty;
}

/// The common set of a closed triangle and a plane (see the header comment).
template <Real T>
[[nodiscard]] inline TrianglePlaneIntersection<T> intersection(const Triangle3<T>& t,
                                                               const Plane3<T>& p) noexcept {
  return intersection_cast<T>(detail::plane_tri::find(t, p, true));
}

/// Swapped arguments: intersects(t, p).
template <Real T>
[[nodiscard]] inline bool intersects(const Plane3<T>& p, const Triangle3<T>& t) noexcept {
  return intersects(t, p);
}

/// Swapped arguments: swapped(intersection(t, p)).
template <Real T>
[[nodiscard]] inline Intersection<T, 3, NoParam, Vec2<T>, 3> intersection(
    const Plane3<T>& p, const Triangle3<T>& t) noexcept {
  return swapped(intersection(t, p));
}

}  // namespace locus
