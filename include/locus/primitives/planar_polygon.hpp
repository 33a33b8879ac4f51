// SPDX-License-Identifier: BSL-1.0
#pragma once
// A polygon lying in a plane in 3D; row prim3.planar (the representation of book section 9.2.3:
// a 2D object embedded through a coordinate frame of its plane), used by row dist3.pt-polygon.
//
// PlanarPolygon3<T> {frame, polygon}: frame is a PlaneFrame3 (primitives/plane.hpp: origin,
// orthonormal in-plane axes u, v and unit normal, right-handed), polygon a 2D Polygon2 of plane
// coordinates (primitives/polygon.hpp: closed chain, first vertex not repeated, any orientation,
// convex or not). Vertex i is to_world(frame, polygon.vertices[i]); point_at(poly, (s, t)) =
// frame.origin + s u + t v evaluates a point of the plane, and the filled polygon is the set of
// such points whose (s, t) is inside polygon (the even-odd rule, as containment's
// point_in_polygon).
//
// planar_polygon(vertices) builds one from 3D vertices: the plane is best_fit_plane_newell()
// (Newell's normal through the vertex average; for vertices that are not exactly coplanar, the
// robust average plane, onto which they are projected), the frame's origin the vertex average,
// and the plane coordinates to_plane(frame, vertex) (rounded). std::nullopt when fewer than
// three vertices, a non-finite coordinate, or a zero Newell normal (collinear or coincident
// vertices, or a polygon whose signed areas cancel). Cost O(n); the result owns a vector.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/polygon.hpp>

#include <cstddef>
#include <optional>
#include <span>

namespace locus {

/// A polygon in the plane of `frame`, given by its plane coordinates.
template <Real T>
struct PlanarPolygon3 {
  PlaneFrame3<T> frame;
  Polygon2<T> polygon;
};

using PlanarPolygon3f = PlanarPolygon3<float>;
using PlanarPolygon3d = PlanarPolygon3<double>;

/// The point with plane coordinates st = (s, t): frame.origin + s u + t v.
template <Real T>
[[nodiscard]] constexpr Vec3<T> point_at(const PlanarPolygon3<T>& poly,
                                         const Vec2<T>& st) noexcept {
  return to_world(poly.frame, st);
}

/// Vertex i in 3D.
template <Real T>
[[nodiscard]] inline Vec3<T> vertex(const PlanarPolygon3<T>& poly, std::size_t i) noexcept {
  return to_world(poly.frame, poly.polygon.vertices[i]);
}

/// The polygon of 3D vertices in their Newell plane (see the header comment).
template <Real T>
[[nodiscard]] inline std::optional<PlanarPolygon3<T>> planar_polygon(
    std::span<const Vec3<T>> vertices) {
  if (vertices.size() < 3) return std::nullopt;
  for (const Vec3<T>& v : vertices)
    if (!is_finite(v)) return std::nullopt;
  const auto plane = best_fit_plane_newell(vertices);
  if (!plane) return std::nullopt;
  Vec3<T> mean{};
  const T w = T(1) / static_cast<T>(vertices.size());
  for (const Vec3<T>& v : vertices) mean += w * v;
  const auto frame = plane_frame(mean, plane->normal);
  if (!frame) return std::nullopt;
  PlanarPolygon3<T> poly{*frame, {}};
  poly.polygon.vertices.reserve(vertices.size());
  for (const Vec3<T>& v : vertices) poly.polygon.vertices.push_back(to_plane(*frame, v));
  return poly;
}

/// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] inline std::optional<PlanarPolygon3<range_scalar_t<R>>> planar_polygon(
    const R& vertices) {
  return planar_polygon(point_span(vertices));
}

}  // namespace locus
