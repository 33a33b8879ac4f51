// SPDX-License-Identifier: BSL-1.0
#pragma once
// Areas of 3D polygons, surface area and volume of closed triangle meshes; row cg.measure
// (with inertia.hpp). 2D polygon area, perimeter and centroid live in primitives/polygon.hpp
// (polygon_signed_area, polygon_centroid, area(Polygon2), ...) and are not repeated here.
//
// 3D polygon p[0], ..., p[n-1] (closed, first vertex not repeated): polygon_vector_area() is
// half of Newell's normal (primitives/plane.hpp newell_normal), i.e. sum_i (p[i] - p[0]) x
// (p[i+1] - p[0]) / 2, accumulated in compute_t<T> relative to p[0] so that a translated
// polygon loses no accuracy. For a planar polygon its length is the area and its direction the
// right-hand-rule normal; for a non-planar one it is the area of the projection onto the plane
// that maximises it. polygon_area() = |vector area|. polygon_centroid() for a planar polygon
// weights the fan triangles by their signed areas along the vector-area direction.
//
// Triangle mesh: (vertices, triangles) spans; triangle {i, j, k} has normal (vj - vi) x
// (vk - vi). mesh_signed_volume() sums the signed volumes of the tetrahedra (r, a, b, c) over
// the triangles (divergence theorem), r = the centre of the vertices' bounding box (any r gives
// the same value for a closed mesh; a central one keeps the terms small): positive when the
// normals point out. mesh_surface_area() sums the triangle areas. For an open mesh the volume
// depends on r and is not meaningful (containment/point_in_polyhedron.hpp is_closed_mesh checks).
//
// Bad input: triangles with an out-of-range index are skipped; non-finite coordinates give NaN
// or inf as IEEE arithmetic does; empty input gives 0 (centroid: the zero vector). Cost O(n),
// no allocation. Book: appendix C (areas of polygons, volumes of polyhedra); no figure.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/rescale.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

namespace locus {

/// Half of Newell's normal: |result| is the area of a planar polygon, its direction the normal.
template <Real T>
[[nodiscard]] inline Vec3<T> polygon_vector_area(std::span<const Vec3<T>> p) noexcept {
  using C = compute_t<T>;
  if (p.size() < 3) return Vec3<T>{};
  const Vec3<C> o = vec_cast<C>(p[0]);
  Vec3<C> sum{};
  for (std::size_t i = 1; i + 1 < p.size(); ++i)
    sum += cross(vec_cast<C>(p[i]) - o, vec_cast<C>(p[i + 1]) - o);
  return vec_cast<T>(C(0.5) * sum);
}

/// Area of a planar 3D polygon (|vector area|).
template <Real T>
[[nodiscard]] inline T polygon_area(std::span<const Vec3<T>> p) noexcept {
  return length(polygon_vector_area(p));
}

/// Area centroid of a planar 3D polygon; the vertex average when the area is zero; the zero
/// vector when empty.
template <Real T>
[[nodiscard]] inline Vec3<T> polygon_centroid(std::span<const Vec3<T>> p) noexcept {
  using C = compute_t<T>;
  if (p.empty()) return Vec3<T>{};
  const Vec3<C> o = vec_cast<C>(p[0]);
  // The weights w * (a + b) are products of five coordinates: they are formed on the vertices
  // relative to o scaled by a power of two f when those could leave the range
  // (distance/detail/rescale.hpp), and the centroid is scaled back exactly.
  C m = C(0);
  for (const Vec3<T>& q : p) m = std::max(m, max_abs(vec_cast<C>(q) - o));
  const C f = detail::outside_product_range<C, 6>(m) ? normalising_scale(m) : C(1);
  Vec3<C> n{};
  for (std::size_t i = 1; i + 1 < p.size(); ++i)
    n += cross(f * (vec_cast<C>(p[i]) - o), f * (vec_cast<C>(p[i + 1]) - o));
  C total = C(0);
  Vec3<C> acc{};
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Vec3<C> a = f * (vec_cast<C>(p[i]) - o), b = f * (vec_cast<C>(p[i + 1]) - o);
    const C w = dot(cross(a, b), n);  // 2 |n| times the signed area of triangle (0, a, b)
    total += w;
    acc += w * (a + b);
  }
  if (total != C(0) && is_finite(total)) return vec_cast<T>(o + acc / (C(3) * total) / f);
  Vec3<C> mean{};
  for (const Vec3<T>& q : p) mean += vec_cast<C>(q);
  return vec_cast<T>(mean / static_cast<C>(p.size()));
}

namespace detail {

template <Real T>
[[nodiscard]] inline bool mesh_triangle_ok(std::size_t nv,
                                           const std::array<std::uint32_t, 3>& t) noexcept {
  return t[0] < nv && t[1] < nv && t[2] < nv;
}

/// The centre of the bounding box of the referenced vertices (compute_t), zero when none.
template <Real T>
[[nodiscard]] inline Vec3<compute_t<T>> mesh_reference(
    std::span<const Vec3<T>> v, std::span<const std::array<std::uint32_t, 3>> tris) noexcept {
  using C = compute_t<T>;
  bool any = false;
  Vec3<C> lo{}, hi{};
  for (const auto& t : tris) {
    if (!mesh_triangle_ok<T>(v.size(), t)) continue;
    for (std::uint32_t i : t) {
      const Vec3<C> x = vec_cast<C>(v[i]);
      if (!any) {
        lo = hi = x;
        any = true;
      }
      for (int k = 0; k < 3; ++k) {
        lo[k] = x[k] < lo[k] ? x[k] : lo[k];
        hi[k] = x[k] > hi[k] ? x[k] : hi[k];
      }
    }
  }
  return C(0.5) * lo + C(0.5) * hi;
}

}  // namespace detail

/// Signed volume of a closed triangle mesh (positive for outward normals).
template <Real T>
[[nodiscard]] inline T mesh_signed_volume(
    std::span<const Vec3<T>> v, std::span<const std::array<std::uint32_t, 3>> tris) noexcept {
  using C = compute_t<T>;
  const Vec3<C> r = detail::mesh_reference(v, tris);
  C sum = C(0);
  for (const auto& t : tris) {
    if (!detail::mesh_triangle_ok<T>(v.size(), t)) continue;
    const Vec3<C> a = vec_cast<C>(v[t[0]]) - r, b = vec_cast<C>(v[t[1]]) - r,
                  c = vec_cast<C>(v[t[2]]) - r;
    sum += dot(a, cross(b, c));
  }
  return static_cast<T>(sum / C(6));
}

/// |mesh_signed_volume|.
template <Real T>
[[nodiscard]] inline T mesh_volume(std::span<const Vec3<T>> v,
                                   std::span<const std::array<std::uint32_t, 3>> tris) noexcept {
  return std::abs(mesh_signed_volume(v, tris));
}

/// Sum of the triangle areas.
template <Real T>
[[nodiscard]] inline T mesh_surface_area(
    std::span<const Vec3<T>> v, std::span<const std::array<std::uint32_t, 3>> tris) noexcept {
  using C = compute_t<T>;
  C sum = C(0);
  for (const auto& t : tris) {
    if (!detail::mesh_triangle_ok<T>(v.size(), t)) continue;
    const Vec3<C> a = vec_cast<C>(v[t[0]]);
    sum += length(cross(vec_cast<C>(v[t[1]]) - a, vec_cast<C>(v[t[2]]) - a));
  }
  return static_cast<T>(C(0.5) * sum);
}

// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] inline Vec3<range_scalar_t<R>> polygon_vector_area(const R& p) noexcept {
  return polygon_vector_area(point_span(p));
}
template <PointRange3 R>
[[nodiscard]] inline range_scalar_t<R> polygon_area(const R& p) noexcept {
  return polygon_area(point_span(p));
}
template <PointRange3 R>
[[nodiscard]] inline Vec3<range_scalar_t<R>> polygon_centroid(const R& p) noexcept {
  return polygon_centroid(point_span(p));
}
template <PointRange3 R>
[[nodiscard]] inline range_scalar_t<R> mesh_signed_volume(
    const R& v, std::span<const std::array<std::uint32_t, 3>> tris) noexcept {
  return mesh_signed_volume(point_span(v), tris);
}
template <PointRange3 R>
[[nodiscard]] inline range_scalar_t<R> mesh_volume(
    const R& v, std::span<const std::array<std::uint32_t, 3>> tris) noexcept {
  return mesh_volume(point_span(v), tris);
}
template <PointRange3 R>
[[nodiscard]] inline range_scalar_t<R> mesh_surface_area(
    const R& v, std::span<const std::array<std::uint32_t, 3>> tris) noexcept {
  return mesh_surface_area(point_span(v), tris);
}

}  // namespace locus
