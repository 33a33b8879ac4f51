// SPDX-License-Identifier: BSL-1.0
#pragma once
// Triangulation of a planar polygon (with holes) lying in 3D (row mesh.polygon-tri, book section
// 9.3, figures 9.5, 9.6). A convex polygon's fan is fan_triangles() in polygon_mesh.hpp; this
// header handles any simple polygon, convex or not.
// Input: points and ring_ends as in triangulate/polygon_triangulation.hpp (ring 0 the outer
// boundary, the others holes, any orientation). Method: the Newell normal n of the outer ring
// (sum over its edges of (y_i - y_j)(z_i + z_j), ... ; rounded) picks the coordinate plane of
// its largest |component|; dropping that coordinate is an exact projection (no rounding), which
// ear clipping (triangulate/ear_clipping.hpp, exact orient2d decisions) triangulates; the
// triangles are mapped back by index and ordered counter-clockwise about n (the outer ring's own
// orientation), so (v1 - v0) x (v2 - v0) . n >= 0.
// Planarity: with planarity_tolerance t > 0 (relative; default sqrt(eps of T)), the polygon is
// planar when every point lies within t * D of the plane through the centroid with normal n,
// D the diagonal of the points' bounding box. With t = 0 the test is exact: every point
// coplanar (orient3d) with three non-collinear points of the outer ring. A non-planar polygon is
// triangulated all the same and reported with invalid_input.
// Status: ear clipping's (ok, empty_input, invalid_input, non_finite_input, degenerate_input,
// invalid_topology); degenerate_input also when n = 0 (collinear or zero-area outer ring),
// then with no triangles. Cost: O(n) plus the ear clipping.

#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/polygon_triangulation.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace locus {

/// Triangles of a polygon in 3D (see the top of the header).
template <Real T>
struct PolygonTriangulation3 {
  Status status = Status::empty_input;
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into points, CCW about normal
  Vec3<T> normal{};       ///< the Newell normal of the outer ring (not normalised)
  int dropped_axis = -1;  ///< the coordinate dropped by the projection (0 x, 1 y, 2 z)
};

/// Triangulates a planar polygon with holes in 3D (see the top of the header).
template <Real T>
[[nodiscard]] PolygonTriangulation3<T> triangulate_polygon3(
    std::span<const Vec3<T>> points, std::span<const std::uint32_t> ring_ends,
    T planarity_tolerance = std::sqrt(std::numeric_limits<T>::epsilon())) {
  PolygonTriangulation3<T> out;
  const std::size_t outer_end = ring_ends.empty() ? 0 : ring_ends[0];
  if (points.empty() || ring_ends.empty() || outer_end == 0) return out;
  if (outer_end > points.size()) {
    out.status = Status::invalid_input;
    return out;
  }
  for (const Vec3<T>& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      out.status = Status::non_finite_input;
      return out;
    }
  }
  // Newell normal of the outer ring, in double.
  Vec3<double> n{};
  for (std::size_t i = 0; i < outer_end; ++i) {
    const Vec3<double> a = vec_cast<double>(points[i]);
    const Vec3<double> b = vec_cast<double>(points[i + 1 == outer_end ? 0 : i + 1]);
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  out.normal = vec_cast<T>(n);
  int axis = 2;
  if (std::abs(n.x) > std::abs(n[axis])) axis = 0;
  if (std::abs(n.y) > std::abs(n[axis])) axis = 1;
  if (n[axis] == 0) {
    out.status = Status::degenerate_input;
    return out;
  }
  out.dropped_axis = axis;
  std::vector<Vec2<T>> flat(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3<T>& p = points[i];
    flat[i] = axis == 0 ? Vec2<T>{p.y, p.z} : (axis == 1 ? Vec2<T>{p.z, p.x} : Vec2<T>{p.x, p.y});
  }
  PolygonTriangulation tri = triangulate_ear_clipping(std::span<const Vec2<T>>(flat), ring_ends);
  out.status = tri.status;
  out.triangles = std::move(tri.triangles);
  // Ear clipping returns counter-clockwise triangles in the (right-handed) projection, i.e.
  // about +axis; turn them about n.
  if (n[axis] < 0) {
    for (auto& t : out.triangles) std::swap(t[1], t[2]);
  }
  if (out.status != Status::ok) return out;
  // Planarity of every point of every ring.
  const std::size_t used = ring_ends.back();
  bool planar = true;
  if (planarity_tolerance > 0) {
    Vec3<double> c{}, lo = vec_cast<double>(points[0]), hi = lo;
    for (std::size_t i = 0; i < used; ++i) {
      const Vec3<double> p = vec_cast<double>(points[i]);
      c = c + p;
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
    c = c / static_cast<double>(used);
    const Vec3<double> u = n / length(n);
    const double limit = static_cast<double>(planarity_tolerance) * length(hi - lo);
    for (std::size_t i = 0; i < used; ++i) {
      if (std::abs(dot(u, vec_cast<double>(points[i]) - c)) > limit) planar = false;
    }
  } else {
    std::size_t j = 1, k = 0;
    while (j < outer_end && points[j] == points[0]) ++j;
    for (std::size_t m = j + 1; m < outer_end && k == 0; ++m) {
      const auto drop = [&](const Vec3<T>& p, int a) {
        return a == 0 ? Vec2<T>{p.y, p.z} : (a == 1 ? Vec2<T>{p.z, p.x} : Vec2<T>{p.x, p.y});
      };
      for (int a = 0; a < 3; ++a) {
        if (orient2d(drop(points[0], a), drop(points[j], a), drop(points[m], a)) != Sign::zero) {
          k = m;
        }
      }
    }
    for (std::size_t i = 0; i < used && k != 0; ++i) {
      if (orient3d(points[0], points[j], points[k], points[i]) != Sign::zero) planar = false;
    }
  }
  if (!planar) out.status = Status::invalid_input;
  return out;
}

/// The same for a single ring (no holes).
template <Real T>
[[nodiscard]] PolygonTriangulation3<T> triangulate_polygon3(
    std::span<const Vec3<T>> points,
    T planarity_tolerance = std::sqrt(std::numeric_limits<T>::epsilon())) {
  const std::array<std::uint32_t, 1> ends{static_cast<std::uint32_t>(points.size())};
  return triangulate_polygon3(points, std::span<const std::uint32_t>(ends), planarity_tolerance);
}

/// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] PolygonTriangulation3<range_scalar_t<R>> triangulate_polygon3(
    const R& points, std::span<const std::uint32_t> ring_ends,
    range_scalar_t<R> planarity_tolerance =
        std::sqrt(std::numeric_limits<range_scalar_t<R>>::epsilon())) {
  return triangulate_polygon3(point_span(points), ring_ends, planarity_tolerance);
}
template <PointRange3 R>
[[nodiscard]] PolygonTriangulation3<range_scalar_t<R>> triangulate_polygon3(
    const R& points, range_scalar_t<R> planarity_tolerance =
                         std::sqrt(std::numeric_limits<range_scalar_t<R>>::epsilon())) {
  return triangulate_polygon3(point_span(points), planarity_tolerance);
}

}  // namespace locus
