// SPDX-License-Identifier: BSL-1.0
#pragma once
// PolygonMesh: a plain indexed mesh with general polygon faces, the exchange type of the mesh
// readers and writers (io/mesh_io.hpp). No adjacency; mesh.vet builds that on top.
//
// Layout (compressed rows: three flat arrays, no per-face allocation): vertex i is vertices[i];
// face f is the index run face_indices[face_offsets[f]] .. face_indices[face_offsets[f+1] - 1],
// listed in order around the face (counter-clockwise seen from outside by the formats'
// convention; not checked). face_offsets holds face_count + 1 ascending entries and starts at 0,
// so a default-constructed mesh ({0}) is the valid empty mesh. Indices are std::uint32_t, the
// library's one index type (docs/notes/api.md).
// check_polygon_mesh(): ok, invalid_input (offsets not starting at 0, not ascending, not ending
// at face_indices.size(); a face with fewer than 3 vertices; an index >= vertices.size()), or
// non_finite_input (a NaN or infinite coordinate). Repeated indices within a face are allowed.
// fan_triangles(): face (v0, v1, ..., vk) gives the triangles (v0, vi, vi+1), i = 1..k-1, in
// face order: exact for convex faces, a valid triangulation of a non-convex face only when it
// is star-shaped from v0 (mesh.polygon-tri triangulates general planar polygons). The mesh must
// be well formed (asserted). from_triangles() is the inverse for a triangle index buffer.
// Cost: O(vertices + indices).

#include <locus/config.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

template <Real T>
struct PolygonMesh {
  std::vector<Vec3<T>> vertices;                  ///< vertex positions
  std::vector<std::uint32_t> face_offsets = {0};  ///< face f: [face_offsets[f], face_offsets[f+1])
  std::vector<std::uint32_t> face_indices;        ///< every face's vertex indices, concatenated
};

/// Number of faces (face_offsets.size() - 1; 0 for a mesh whose offsets are empty).
template <Real T>
[[nodiscard]] std::size_t face_count(const PolygonMesh<T>& mesh) noexcept {
  return mesh.face_offsets.empty() ? 0 : mesh.face_offsets.size() - 1;
}

/// The vertex indices of face f (f < face_count(mesh), asserted).
template <Real T>
[[nodiscard]] std::span<const std::uint32_t> face(const PolygonMesh<T>& mesh,
                                                  std::size_t f) noexcept {
  LOCUS_ASSERT(f + 1 < mesh.face_offsets.size(), "face index out of range");
  const std::uint32_t b = mesh.face_offsets[f];
  const std::uint32_t e = mesh.face_offsets[f + 1];
  LOCUS_ASSERT(b <= e && e <= mesh.face_indices.size(), "face offsets out of range");
  return std::span<const std::uint32_t>(mesh.face_indices).subspan(b, e - b);
}

/// Appends a face (its vertex indices in order around it).
template <Real T>
void add_face(PolygonMesh<T>& mesh, std::span<const std::uint32_t> indices) {
  if (mesh.face_offsets.empty()) mesh.face_offsets.push_back(0);
  mesh.face_indices.insert(mesh.face_indices.end(), indices.begin(), indices.end());
  mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.face_indices.size()));
}

/// Whether the mesh is well formed and finite (see the contract above for the statuses).
template <Real T>
[[nodiscard]] Status check_polygon_mesh(const PolygonMesh<T>& mesh) noexcept {
  if (mesh.face_offsets.empty() || mesh.face_offsets.front() != 0 ||
      mesh.face_offsets.back() != mesh.face_indices.size()) {
    return Status::invalid_input;
  }
  for (std::size_t f = 0; f + 1 < mesh.face_offsets.size(); ++f) {
    if (mesh.face_offsets[f + 1] < mesh.face_offsets[f] ||
        mesh.face_offsets[f + 1] - mesh.face_offsets[f] < 3) {
      return Status::invalid_input;
    }
  }
  for (const std::uint32_t i : mesh.face_indices) {
    if (i >= mesh.vertices.size()) return Status::invalid_input;
  }
  for (const Vec3<T>& v : mesh.vertices) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      return Status::non_finite_input;
    }
  }
  return Status::ok;
}

/// Number of triangles fan_triangles() returns: the sum over faces of (size - 2).
template <Real T>
[[nodiscard]] std::size_t fan_triangle_count(const PolygonMesh<T>& mesh) noexcept {
  std::size_t n = 0;
  for (std::size_t f = 0; f + 1 < mesh.face_offsets.size(); ++f) {
    const std::uint32_t k = mesh.face_offsets[f + 1] - mesh.face_offsets[f];
    if (k >= 3) n += k - 2;
  }
  return n;
}

/// Splits every face into a fan of triangles from its first vertex.
template <Real T>
[[nodiscard]] std::vector<std::array<std::uint32_t, 3>> fan_triangles(const PolygonMesh<T>& mesh) {
  std::vector<std::array<std::uint32_t, 3>> tris;
  tris.reserve(fan_triangle_count(mesh));
  for (std::size_t f = 0; f + 1 < mesh.face_offsets.size(); ++f) {
    const std::span<const std::uint32_t> v = face(mesh, f);
    for (std::size_t i = 1; i + 1 < v.size(); ++i) tris.push_back({v[0], v[i], v[i + 1]});
  }
  return tris;
}

/// A mesh with the given vertices and one face per triangle.
template <Real T>
[[nodiscard]] PolygonMesh<T> from_triangles(std::span<const Vec3<T>> vertices,
                                            std::span<const std::array<std::uint32_t, 3>> tris) {
  PolygonMesh<T> mesh;
  mesh.vertices.assign(vertices.begin(), vertices.end());
  mesh.face_offsets.reserve(tris.size() + 1);
  mesh.face_indices.reserve(3 * tris.size());
  for (const std::array<std::uint32_t, 3>& t : tris) {
    mesh.face_indices.insert(mesh.face_indices.end(), t.begin(), t.end());
    mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.face_indices.size()));
  }
  return mesh;
}
template <PointRange3 R>
[[nodiscard]] PolygonMesh<range_scalar_t<R>> from_triangles(
    const R& vertices, std::span<const std::array<std::uint32_t, 3>> tris) {
  return from_triangles(point_span(vertices), tris);
}

}  // namespace locus
