// SPDX-License-Identifier: BSL-1.0
#pragma once
// Point in tetrahedron, convex polyhedron (planes or a convex triangle mesh) and general closed
// triangle mesh; row cg.piph; book section 13.4, figures 13.18 and 13.19.
// Every answer is EXACT for finite input (orient3d / orient2d, exact comparisons, exact sign of
// dot(normal, p) - constant). classify() returns Side::boundary for a point on the closed
// surface, inside / outside otherwise; contains(region, p) = classify(p, region) != outside.
//  * Tetrahedron3: either orientation; a flat one has no interior (points of its four triangles
//    are boundary, the rest outside).
//  * Planes: each Plane3 {normal, constant} bounds dot(normal, X) <= constant (normals point
//    OUT). No planes: the whole space (inside). A plane with a non-finite coefficient: outside.
//  * Triangle mesh (vertices, triangles): triangle {i, j, k} has normal (vj - vi) x (vk - vi).
//    classify_convex needs a closed convex mesh with outward normals (not checked); O(F).
//  * classify(p, vertices, triangles): any closed mesh (every edge used by an even number of
//    triangles; orientation, convexity, manifoldness not needed; self-intersections are read by
//    the even-odd rule). Boundary first, then the parity of crossings of a ray along +x, with
//    degenerate rays (figs 13.18, 13.19) resolved by Simulation of Simplicity (method:
//    docs/notes/containment.md). O(F) with a box rejection per triangle; no allocation.
//  * Non-closed meshes give a meaningless parity; check with is_closed_mesh() (O(F log F),
//    allocates).
// Bad input: a non-finite query point is outside. Triangles with an out-of-range index or a
// non-finite vertex are skipped. Empty meshes contain nothing (outside).

#include <locus/config.hpp>
#include <locus/core/exact_sum.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/side.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/tetrahedron.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace locus {

namespace detail {

template <Real T>
[[nodiscard]] constexpr Vec2<T> drop_axis(const Vec3<T>& v, int k) noexcept {
  return k == 0 ? Vec2<T>{v.y, v.z} : (k == 1 ? Vec2<T>{v.z, v.x} : Vec2<T>{v.x, v.y});
}

/// Exact: p on the closed segment [a, b] in 3D (a point when a == b).
template <Real T>
[[nodiscard]] inline bool on_closed_segment3(const Vec3<T>& a, const Vec3<T>& b,
                                             const Vec3<T>& p) noexcept {
  for (int i = 0; i < 3; ++i)
    if (!(std::min(a[i], b[i]) <= p[i] && p[i] <= std::max(a[i], b[i]))) return false;
  for (int k = 0; k < 3; ++k)
    if (orient2d(drop_axis(a, k), drop_axis(b, k), drop_axis(p, k)) != Sign::zero) return false;
  return true;
}

/// Exact: p on the closed triangle abc (a segment or point when degenerate).
template <Real T>
[[nodiscard]] inline bool on_closed_triangle3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                              const Vec3<T>& p) noexcept {
  if (orient3d(a, b, c, p) != Sign::zero) return false;
  for (int k = 0; k < 3; ++k) {
    const Vec2<T> a2 = drop_axis(a, k), b2 = drop_axis(b, k), c2 = drop_axis(c, k);
    const Sign o = orient2d(a2, b2, c2);
    if (o == Sign::zero) continue;
    // Projection along axis k is a bijection of the triangle's plane: decide in 2D.
    const Vec2<T> p2 = drop_axis(p, k);
    return to_int(orient2d(a2, b2, p2) * o) >= 0 && to_int(orient2d(b2, c2, p2) * o) >= 0 &&
           to_int(orient2d(c2, a2, p2) * o) >= 0;
  }
  return on_closed_segment3(a, b, p) || on_closed_segment3(b, c, p) || on_closed_segment3(c, a, p);
}

/// Sign of orient2d((a.y, a.z), (b.y, b.z), (q.y + e, q.z + e^2)) for infinitesimal e > 0.
template <Real T>
[[nodiscard]] inline int perturbed_side_yz(const Vec3<T>& a, const Vec3<T>& b,
                                           const Vec3<T>& q) noexcept {
  const Sign s = orient2d(Vec2<T>{a.y, a.z}, Vec2<T>{b.y, b.z}, Vec2<T>{q.y, q.z});
  if (s != Sign::zero) return to_int(s);
  // d/dq.y of (b.y - a.y)(q.z - a.z) - (b.z - a.z)(q.y - a.y) is a.z - b.z; d/dq.z is b.y - a.y.
  if (a.z != b.z) return a.z > b.z ? 1 : -1;
  if (a.y != b.y) return b.y > a.y ? 1 : -1;
  return 0;
}

/// Exact sign of dot(n, p) - c for finite inputs.
template <Real T>
[[nodiscard]] inline int plane_side_exact(const Vec3<T>& n, T c, const Vec3<T>& p) noexcept {
  const double t0 = double(n.x) * double(p.x), t1 = double(n.y) * double(p.y),
               t2 = double(n.z) * double(p.z), cd = double(c);
  const double value = ((t0 + t1) + t2) - cd;
  const double permanent = std::abs(t0) + std::abs(t1) + std::abs(t2) + std::abs(cd);
  // Three rounded products and three rounded sums: 8 eps * permanent covers them with room;
  // below 2^-900 products may be subnormal, so the relative bound does not hold: go exact.
  if (permanent > 0x1p-900 && std::abs(value) > 0x1p-50 * permanent) return value > 0.0 ? 1 : -1;
  if (permanent == 0.0) return 0;
  const ExactMonomial m[4] = {{1, 0, 2, {double(n.x), double(p.x), 0.0}},
                              {1, 0, 2, {double(n.y), double(p.y), 0.0}},
                              {1, 0, 2, {double(n.z), double(p.z), 0.0}},
                              {-1, 0, 1, {cd, 0.0, 0.0}}};
  return exact_sign_of_sum(m);
}

template <Real T>
[[nodiscard]] inline bool valid_triangle(std::span<const Vec3<T>> v,
                                         const std::array<std::uint32_t, 3>& t) noexcept {
  return t[0] < v.size() && t[1] < v.size() && t[2] < v.size() && is_finite(v[t[0]]) &&
         is_finite(v[t[1]]) && is_finite(v[t[2]]);
}

}  // namespace detail

// ---- tetrahedron -------------------------------------------------------------------------------

/// Exact classification against a tetrahedron of either orientation.
template <Real T>
[[nodiscard]] inline Side classify(const Vec3<T>& p, const Tetrahedron3<T>& t) noexcept {
  if (!is_finite(p)) return Side::outside;
  for (const Vec3<T>& v : t.v)
    if (!is_finite(v)) return Side::outside;
  if (orientation(t) == 0) {
    for (int i = 0; i < 4; ++i) {
      const Triangle3<T> f = face(t, i);
      if (detail::on_closed_triangle3(f.v0, f.v1, f.v2, p)) return Side::boundary;
    }
    return Side::outside;
  }
  bool on_face = false;
  for (int i = 0; i < 4; ++i) {
    const Triangle3<T> f = face(t, i);  // outward: positive orient3d is outside
    const Sign s = orient3d(f.v0, f.v1, f.v2, p);
    if (s == Sign::positive) return Side::outside;
    on_face = on_face || s == Sign::zero;
  }
  return on_face ? Side::boundary : Side::inside;
}

template <Real T>
[[nodiscard]] inline bool contains(const Tetrahedron3<T>& t, const Vec3<T>& p) noexcept {
  return classify(p, t) != Side::outside;
}

// ---- convex polyhedra --------------------------------------------------------------------------

/// Exact classification against the intersection of the half-spaces dot(n, X) <= c.
template <Real T>
[[nodiscard]] inline Side classify(const Vec3<T>& p, std::span<const Plane3<T>> planes) noexcept {
  if (!is_finite(p)) return Side::outside;
  bool on_plane = false;
  for (const Plane3<T>& pl : planes) {
    if (!is_finite(pl.normal) || !is_finite(pl.constant)) return Side::outside;
    const int s = detail::plane_side_exact(pl.normal, pl.constant, p);
    if (s > 0) return Side::outside;
    on_plane = on_plane || s == 0;
  }
  return on_plane ? Side::boundary : Side::inside;
}

template <Real T>
[[nodiscard]] inline bool contains(std::span<const Plane3<T>> planes, const Vec3<T>& p) noexcept {
  return classify(p, planes) != Side::outside;
}

/// Exact classification against a closed convex mesh with outward normals (not checked).
template <Real T>
[[nodiscard]] inline Side classify_convex(
    const Vec3<T>& p, std::span<const Vec3<T>> vertices,
    std::span<const std::array<std::uint32_t, 3>> triangles) noexcept {
  if (!is_finite(p) || triangles.empty()) return Side::outside;
  bool on_plane = false;
  for (const auto& t : triangles) {
    if (!detail::valid_triangle(vertices, t)) continue;
    const Sign s = orient3d(vertices[t[0]], vertices[t[1]], vertices[t[2]], p);
    if (s == Sign::positive) return Side::outside;
    on_plane = on_plane || s == Sign::zero;
  }
  return on_plane ? Side::boundary : Side::inside;
}

// ---- general closed meshes ---------------------------------------------------------------------

/// Exact classification against a closed triangle mesh (see the header comment).
template <Real T>
[[nodiscard]] inline Side classify(
    const Vec3<T>& p, std::span<const Vec3<T>> vertices,
    std::span<const std::array<std::uint32_t, 3>> triangles) noexcept {
  if (!is_finite(p)) return Side::outside;
  bool odd = false;
  for (const auto& t : triangles) {
    if (!detail::valid_triangle(vertices, t)) continue;
    const Vec3<T>&a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    // The perturbed ray stays within the closed yz-box of p and in x >= p.x.
    const T ylo = std::min({a.y, b.y, c.y}), yhi = std::max({a.y, b.y, c.y});
    const T zlo = std::min({a.z, b.z, c.z}), zhi = std::max({a.z, b.z, c.z});
    if (p.y < ylo || p.y > yhi || p.z < zlo || p.z > zhi) continue;
    const T xlo = std::min({a.x, b.x, c.x}), xhi = std::max({a.x, b.x, c.x});
    if (p.x > xhi) continue;
    if (p.x >= xlo && detail::on_closed_triangle3(a, b, c, p)) return Side::boundary;
    const int s = to_int(orient2d(Vec2<T>{a.y, a.z}, Vec2<T>{b.y, b.z}, Vec2<T>{c.y, c.z}));
    if (s == 0) continue;  // parallel to x: the perturbed ray misses it
    if (detail::perturbed_side_yz(a, b, p) != s || detail::perturbed_side_yz(b, c, p) != s ||
        detail::perturbed_side_yz(c, a, p) != s)
      continue;
    // The x-line through the perturbed point meets the triangle; in front of p iff p is on the
    // side of the plane opposite to the normal's x-component (whose sign is s). Zero would put
    // p on the triangle, which the test above has excluded.
    const int o = to_int(orient3d(a, b, c, p));
    if (o == -s) odd = !odd;
  }
  return odd ? Side::inside : Side::outside;
}

template <Real T>
[[nodiscard]] inline bool contains(std::span<const Vec3<T>> vertices,
                                   std::span<const std::array<std::uint32_t, 3>> triangles,
                                   const Vec3<T>& p) noexcept {
  return classify(p, vertices, triangles) != Side::outside;
}

// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] inline Side classify_convex(
    const range_point_t<R>& p, const R& vertices,
    std::span<const std::array<std::uint32_t, 3>> triangles) noexcept {
  return classify_convex(p, point_span(vertices), triangles);
}
template <PointRange3 R>
[[nodiscard]] inline Side classify(
    const range_point_t<R>& p, const R& vertices,
    std::span<const std::array<std::uint32_t, 3>> triangles) noexcept {
  return classify(p, point_span(vertices), triangles);
}
template <PointRange3 R>
[[nodiscard]] inline bool contains(const R& vertices,
                                   std::span<const std::array<std::uint32_t, 3>> triangles,
                                   const range_point_t<R>& p) noexcept {
  return contains(point_span(vertices), triangles, p);
}

/// True when every undirected edge {i, j} (i != j) is used by an even number of triangles, the
/// condition under which classify() on a mesh is meaningful. Empty meshes are closed.
[[nodiscard]] inline bool is_closed_mesh(std::span<const std::array<std::uint32_t, 3>> triangles) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = t[std::size_t(k)], j = t[std::size_t((k + 1) % 3)];
      if (i != j) edges.emplace_back(std::min(i, j), std::max(i, j));
    }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if ((j - i) % 2 != 0) return false;
    i = j;
  }
  return true;
}

}  // namespace locus
