// SPDX-License-Identifier: BSL-1.0
#pragma once
// Triangles in N dimensions; row prim2.triangle (and the 3D triangle used by prim3); book
// section 5.2, figures 5.3 (orderings), 5.4 (parametric form), 5.5 (barycentric form).
//
// Triangle<T, N> {v0, v1, v2}: three vertices, also reachable as tri[0..2]. Two
// parametrisations:
//   parametric (fig 5.4):  point_at(tri, {s, t}) = v0 + s (v1 - v0) + t (v2 - v0),
//                          the triangle is s >= 0, t >= 0, s + t <= 1;
//   barycentric (fig 5.5): point_at_barycentric(tri, {u, v, w}) = u v0 + v v1 + w v2,
//                          u + v + w = 1, the triangle is u, v, w >= 0.
// They are related by (u, v, w) = (1 - s - t, s, t).
//
// Orientation (fig 5.3): in 2D, orientation(tri) is the EXACT sign of orient2d(v0, v1, v2):
// positive for counter-clockwise order, negative for clockwise, zero when the vertices are
// collinear (including coincident vertices). signed_area() is the rounded value of the same
// determinant / 2; near zero its sign may be wrong, so decisions must use orientation().
// In 3D, normal(tri) = (v1 - v0) x (v2 - v0) (right-handed: the vertices are counter-clockwise
// seen from the side the normal points to), |normal| = 2 area.
//
// Degenerate input: is_degenerate() is exact in 2D and 3D (collinear or coincident vertices;
// in 3D three points are collinear iff their projections onto the xy, yz and zx planes are all
// collinear, each decided by exact orient2d), true for non-finite coordinates. A degenerate
// triangle has area 0 (up to rounding), unit_normal() = 0 and barycentric() = std::nullopt.
// Cost O(N), no allocation; orient2d falls back to adaptive exact arithmetic only when the fast
// floating-point filter cannot decide.

#include <locus/config.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <optional>

namespace locus {

/// The triangle with vertices v0, v1, v2 (in this order).
template <class T, int N>
struct Triangle {
  Vec<T, N> v0;
  Vec<T, N> v1;
  Vec<T, N> v2;
  /// Vertex i (0, 1 or 2).
  [[nodiscard]] constexpr Vec<T, N>& operator[](int i) noexcept {
    LOCUS_ASSERT(i >= 0 && i < 3, "Triangle vertex index out of range");
    return i == 0 ? v0 : (i == 1 ? v1 : v2);
  }
  [[nodiscard]] constexpr const Vec<T, N>& operator[](int i) const noexcept {
    LOCUS_ASSERT(i >= 0 && i < 3, "Triangle vertex index out of range");
    return i == 0 ? v0 : (i == 1 ? v1 : v2);
  }
};

template <Real T>
using Triangle2 = Triangle<T, 2>;
template <Real T>
using Triangle3 = Triangle<T, 3>;
using Triangle2f = Triangle2<float>;
using Triangle2d = Triangle2<double>;
using Triangle3f = Triangle3<float>;
using Triangle3d = Triangle3<double>;

/// Parametric form (fig 5.4): v0 + s (v1 - v0) + t (v2 - v0) with st = (s, t).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const Triangle<T, N>& tri, const Vec2<T>& st) noexcept {
  return tri.v0 + st.x * (tri.v1 - tri.v0) + st.y * (tri.v2 - tri.v0);
}

/// Barycentric form (fig 5.5): u v0 + v v1 + w v2 with b = (u, v, w); exact at the vertices.
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE constexpr Vec<T, N> point_at_barycentric(
    const Triangle<T, N>& tri, const Vec3<T>& b) noexcept {
  return b.x * tri.v0 + b.y * tri.v1 + b.z * tri.v2;
}

/// (v0 + v1 + v2) / 3, summed as thirds so that it cannot overflow.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> centroid(const Triangle<T, N>& tri) noexcept {
  constexpr T third = T(1) / T(3);
  return third * tri.v0 + third * tri.v1 + third * tri.v2;
}

/// |v1 - v0| + |v2 - v1| + |v0 - v2|.
template <class T, int N>
[[nodiscard]] inline T perimeter(const Triangle<T, N>& tri) noexcept {
  return length(tri.v1 - tri.v0) + length(tri.v2 - tri.v1) + length(tri.v0 - tri.v2);
}

/// Exact orientation of (v0, v1, v2): positive = counter-clockwise, zero = collinear.
template <Real T>
[[nodiscard]] inline Sign orientation(const Triangle2<T>& tri) noexcept {
  return orient2d(tri.v0, tri.v1, tri.v2);
}

/// Signed area, positive for counter-clockwise order (rounded; use orientation() to decide).
template <Real T>
[[nodiscard]] constexpr T signed_area(const Triangle2<T>& tri) noexcept {
  return T(0.5) * perp_dot(tri.v1 - tri.v0, tri.v2 - tri.v0);
}

/// Unnormalised normal (v1 - v0) x (v2 - v0), |normal| = 2 * area. Evaluated at the vertex
/// opposite the longest edge (the same vector mathematically), which keeps the rounding error
/// small for needle-shaped triangles.
template <Real T>
[[nodiscard]] constexpr Vec3<T> normal(const Triangle3<T>& tri) noexcept {
  const Vec3<T> e0 = tri.v1 - tri.v0, e1 = tri.v2 - tri.v1, e2 = tri.v0 - tri.v2;
  const T l0 = sqr_length(e0), l1 = sqr_length(e1), l2 = sqr_length(e2);
  if (l0 >= l1 && l0 >= l2) return cross(e1, e2);  // at v2: (v0 - v2) x (v1 - v2) = e2 x -e1
  if (l1 >= l2) return cross(e2, e0);              // at v0
  return cross(e0, e1);                            // at v1
}

/// Unit normal of a 3D triangle; the zero vector when the triangle is degenerate (or the
/// rounded cross product vanishes).
template <Real T>
[[nodiscard]] inline Vec3<T> unit_normal(const Triangle3<T>& tri) noexcept {
  return normalize(normal(tri));
}

/// Area (non-negative). 2D: |signed_area|; 3D: |normal| / 2; other N: half the norm of the
/// bivector u ^ v (sum of the squared projected cross products) of two edges.
template <class T, int N>
[[nodiscard]] inline T area(const Triangle<T, N>& tri) noexcept {
  if constexpr (N == 2) {
    return std::abs(signed_area(tri));
  } else if constexpr (N == 3) {
    return T(0.5) * length(normal(tri));
  } else {
    // |u ^ v|^2 = sum over coordinate planes of the squared projected cross products (the
    // Lagrange identity), with u, v the edges at the vertex opposite the longest edge: as
    // accurate as the 3D cross product, unlike Heron-type formulas on rounded edge lengths.
    const Vec<T, N> e0 = tri.v1 - tri.v0, e1 = tri.v2 - tri.v1, e2 = tri.v0 - tri.v2;
    const T l0 = sqr_length(e0), l1 = sqr_length(e1), l2 = sqr_length(e2);
    const Vec<T, N> u = (l0 >= l1 && l0 >= l2) ? e1 : (l1 >= l2 ? e2 : e0);
    const Vec<T, N> v = (l0 >= l1 && l0 >= l2) ? e2 : (l1 >= l2 ? e0 : e1);
    // Scale by the largest component so that the squares cannot overflow or underflow.
    const T m = max_abs(u) > max_abs(v) ? max_abs(u) : max_abs(v);
    if (!(m > T(0))) return m == m ? T(0) : m;
    T sum = T(0);
    for (int i = 0; i < N; ++i)
      for (int j = i + 1; j < N; ++j) sum += sqr((u[i] / m) * (v[j] / m) - (u[j] / m) * (v[i] / m));
    return T(0.5) * m * m * std::sqrt(sum);
  }
}

/// True when the vertices are collinear or coincident (exact in 2D and 3D) or not finite.
/// For N > 3 the test uses the rounded area (zero only when it underflows or vanishes).
template <class T, int N>
[[nodiscard]] inline bool is_degenerate(const Triangle<T, N>& tri) noexcept {
  if (!is_finite(tri.v0) || !is_finite(tri.v1) || !is_finite(tri.v2)) return true;
  if constexpr (N == 2) {
    return orient2d(tri.v0, tri.v1, tri.v2) == Sign::zero;
  } else if constexpr (N == 3) {
    // Projections onto the three coordinate planes; collinear in 3D iff collinear in all three.
    for (int k = 0; k < 3; ++k) {
      const int i = k, j = (k + 1) % 3;
      const Vec2<T> a{tri.v0[i], tri.v0[j]}, b{tri.v1[i], tri.v1[j]}, c{tri.v2[i], tri.v2[j]};
      if (orient2d(a, b, c) != Sign::zero) return false;
    }
    return true;
  } else if constexpr (N == 1) {
    return true;
  } else {
    return !(area(tri) > T(0));
  }
}

/// Barycentric coordinates (u, v, w) of p with respect to a 2D triangle, p = u v0 + v v1 + w v2
/// and u + v + w = 1 (rounded). std::nullopt when the triangle is degenerate (exact test).
template <Real T>
[[nodiscard]] inline std::optional<Vec3<T>> barycentric(const Triangle2<T>& tri,
                                                        const Vec2<T>& p) noexcept {
  if (is_degenerate(tri)) return std::nullopt;
  const Vec2<T> e1 = tri.v1 - tri.v0, e2 = tri.v2 - tri.v0, d = p - tri.v0;
  const T det = perp_dot(e1, e2);
  if (det == T(0) || !is_finite(det)) return std::nullopt;  // rounded to zero: cannot divide
  const T v = perp_dot(d, e2) / det;
  const T w = perp_dot(e1, d) / det;
  return Vec3<T>{T(1) - v - w, v, w};
}

}  // namespace locus
