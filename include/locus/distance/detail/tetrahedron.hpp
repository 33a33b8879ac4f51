// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery of the point-tetrahedron and line/ray/segment-tetrahedron distance headers
// (rows dist3.pt-polyhedron, dist3.linear-tetrahedron; book sections 10.3.4, 10.5.3, figures
// 10.20, 10.44, 10.45): the face table, exact side-of-face signs, barycentric coordinates of an
// inside point, and the linear-tetrahedron core.
//
// Faces: face i is opposite vertex i, with the vertex triples of tetrahedron.hpp's positive table
// {1 2 3}, {0 3 2}, {0 1 3}, {0 2 1}, whose orient3d normal points OUT of a positively oriented
// tetrahedron; outside(i, p) multiplies by the exact orientation so that it is positive exactly
// when p is strictly beyond face i's plane, whatever the vertex order.

#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/detail/linear_planar.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/tetrahedron.hpp>
#include <locus/primitives/triangle.hpp>

#include <limits>
#include <type_traits>

namespace locus::detail {

inline constexpr int tet_face[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

template <Real T>
[[nodiscard]] constexpr Triangle3<T> tet_face_triangle(const Tetrahedron3<T>& tet, int i) noexcept {
  return {tet.v[tet_face[i][0]], tet.v[tet_face[i][1]], tet.v[tet_face[i][2]]};
}

/// Exact: +1 when p is strictly beyond face i's plane (outside), 0 on it, -1 inside; o is the
/// tetrahedron's exact orientation (nonzero).
template <Real T>
[[nodiscard]] inline int tet_outside(const Tetrahedron3<T>& tet, int o, int i,
                                     const Vec3<T>& p) noexcept {
  const int* f = tet_face[i];
  return o * to_int(orient3d(tet.v[f[0]], tet.v[f[1]], tet.v[f[2]], p));
}

/// Exact: p lies in the closed solid tetrahedron of orientation o != 0.
template <Real T>
[[nodiscard]] inline bool tet_contains(const Tetrahedron3<T>& tet, int o,
                                       const Vec3<T>& p) noexcept {
  for (int i = 0; i < 4; ++i)
    if (tet_outside(tet, o, i, p) > 0) return false;
  return true;
}

/// Barycentric coordinates of a point p inside the tetrahedron (orientation o != 0): the
/// sub-volumes of p with each face, in double, clamped at 0 and normalised to sum 1.
template <Real T>
[[nodiscard]] inline Vec4<T> tet_inside_barycentric(const Tetrahedron3<T>& tet, int o,
                                                    const Vec3<T>& p) noexcept {
  double w[4], sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    const int* f = tet_face[i];
    const double v = -double(o) * orient3d_value(tet.v[f[0]], tet.v[f[1]], tet.v[f[2]], p);
    w[i] = v > 0.0 ? v : 0.0;
    sum += w[i];
  }
  if (!(sum > 0.0)) return {T(1), T(0), T(0), T(0)};  // unreachable for o != 0 and finite p
  return {T(w[0] / sum), T(w[1] / sum), T(w[2] / sum), T(w[3] / sum)};
}

/// The tetrahedron's barycentric coordinates of the point with barycentric coordinates b on
/// face i.
template <Real T>
[[nodiscard]] constexpr Vec4<T> tet_from_face(int i, const Vec3<T>& b) noexcept {
  Vec4<T> r{};
  for (int k = 0; k < 3; ++k) r[tet_face[i][k]] = b[k];
  return r;
}

template <Real T>
[[nodiscard]] constexpr bool finite_input(const Tetrahedron3<T>& tet) noexcept {
  return is_finite(tet.v[0]) && is_finite(tet.v[1]) && is_finite(tet.v[2]) && is_finite(tet.v[3]);
}

/// Length (in A's parameter) of the part of A inside the solid tetrahedron, by clipping against
/// the four face planes in floating point (Cyrus-Beck); 0 when it misses.
template <Real T>
[[nodiscard]] inline T tet_chord(const LinearView<T, 3>& A, const Tetrahedron3<T>& tet,
                                 int o) noexcept {
  constexpr T inf = std::numeric_limits<T>::infinity();
  T lo = A.bounded_lo ? T(0) : -inf, hi = A.bounded_hi ? T(1) : inf;
  for (int i = 0; i < 4; ++i) {
    const int* f = tet_face[i];
    const Vec3<T>& a = tet.v[f[0]];
    const Vec3<T> n = T(o) * cross(tet.v[f[1]] - a, tet.v[f[2]] - a);  // outward
    const T num = dot(n, A.origin - a), den = dot(n, A.dir);
    if (den == T(0)) {
      if (num > T(0)) return T(0);
      continue;
    }
    const T t = -num / den;
    if (den > T(0)) {
      if (t < hi) hi = t;
    } else if (t > lo) {
      lo = t;
    }
  }
  return hi > lo ? hi - lo : T(0);
}

/// distance(l, tet) for a line, ray or segment and a solid tetrahedron.
template <class T, class L>
[[nodiscard]] inline Distance<T, 3, T, Vec4<T>> linear_tetrahedron_distance(
    const L& l, const Tetrahedron3<T>& tet) noexcept {
  if (!finite_input(l) || !finite_input(tet)) return non_finite_distance<T, 3, T, Vec4<T>>();
  const LinearView<T, 3> A = view(l);
  const int o = orientation(tet);
  constexpr bool is_segment = std::is_same_v<L, Segment3<T>>;
  // A chord of positive length through the solid: infinitely many pairs at distance 0.
  const T scale = max_abs(A.origin) + max_abs(tet.v[0] - A.origin) + max_abs(tet.v[1] - tet.v[0]) +
                  max_abs(tet.v[2] - tet.v[0]) + max_abs(tet.v[3] - tet.v[0]);
  const auto through = [&] {
    return tet_chord(A, tet, o) * length(A.dir) > T(64) * eps_v<T> * scale;
  };
  int side0[4] = {0, 0, 0, 0}, side1[4] = {0, 0, 0, 0};
  if (o != 0) {
    // A finite end inside the solid is a closest point (distance exactly 0); so is the origin of
    // a zero direction (the component is that point).
    const bool has_origin = A.bounded_lo || !(max_abs(A.dir) > T(0));
    bool in0 = has_origin, in1 = A.bounded_hi;
    for (int i = 0; i < 4; ++i) {
      if (has_origin) in0 = (side0[i] = tet_outside(tet, o, i, A.origin)) <= 0 && in0;
      if (A.bounded_hi) in1 = (side1[i] = tet_outside(tet, o, i, A.end)) <= 0 && in1;
    }
    if (in0 || in1) {
      const T t = in0 ? T(0) : T(1);
      const Vec3<T> p = in0 ? A.origin : A.end;
      return {T(0), T(0), {p, p}, t, tet_inside_barycentric(tet, o, p), !through()};
    }
  }
  // Otherwise the component meets the solid iff it meets its boundary: the minimum over the
  // faces. A segment skips the faces it lies strictly behind (both ends strictly inside that
  // face's half-space): the closest point of the solid is on a face whose plane has a point of
  // the segment strictly outside (KKT). A flat tetrahedron (orientation 0) is the union of its
  // four faces (the convex hull of four coplanar points is covered by the triangles of three).
  Distance<T, 3, T, Vec4<T>> best{};
  bool found = false;
  T face_distance[4] = {};
  bool face_unique[4] = {true, true, true, true};
  for (int i = 0; i < 4; ++i) {
    if (is_segment && o != 0 && side0[i] < 0 && side1[i] < 0) continue;
    const auto r = linear_triangle_distance<T>(l, tet_face_triangle(tet, i));
    face_distance[i] = r.distance;
    face_unique[i] = r.unique;
    if (!found || r.sqr_distance < best.sqr_distance) {
      best = {r.distance, r.sqr_distance, r.closest, r.param_a, tet_from_face(i, r.param_b),
              r.unique};
      found = true;
    }
  }
  // A face tied with the winner on which the pair slides makes the answer non-unique.
  for (int i = 0; i < 4; ++i)
    if (!face_unique[i] && face_distance[i] <= best.distance + T(64) * eps_v<T> * scale)
      best.unique = false;
  if (o != 0 && best.unique && best.distance <= T(64) * eps_v<T> * scale) best.unique = !through();
  return best;
}

}  // namespace locus::detail
