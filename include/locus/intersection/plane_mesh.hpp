// SPDX-License-Identifier: BSL-1.0
#pragma once
// A plane slicing a triangle mesh: slice_mesh() returns the cross-section as polylines, closed
// loops for a closed manifold mesh and open chains ending on boundary edges of an open one; row
// int3.plane-mesh, book section 11.5.5 (figure 11.29).
// Input: vertex positions and triangles (index triples), or polygon faces as PolygonMesh's
// offsets and indices (mesh/polygon_mesh.hpp; each face is split into a fan from its first
// vertex, whose diagonals are shared by two fan triangles, so the chaining sees them as edges).
// Plane3 {normal, constant} as in primitives/plane.hpp, taken as given.
// Rule for vertices on the plane (symbolic perturbation): a vertex whose exact side
// (core/plane_side.hpp) is zero counts as positive, as if the plane were moved by an
// infinitesimal amount against its normal. Every triangle is then either missed or crossed in
// one segment between two of its edges, keyed by the edge's vertex pair, so on a closed manifold
// mesh each crossed edge joins exactly two segments and every chain closes. The piece of the
// mesh lying exactly in the plane (faces coplanar with it) is not reported itself; its boundary
// against the negative side is. A vertex touching the plane from the negative side becomes a
// loop of one point (the consecutive repeated points of zero-length pieces are merged).
// Points: each crossed edge's point is computed once (shared by both of its triangles): a vertex
// on the plane exactly, else the crossing of the edge at t = f(u) / (f(u) - f(v)) from its
// lower-numbered vertex u (compensated plane values; bound as segment_plane.hpp).
// Orientation: each triangle's segment runs along cross(plane normal, triangle normal), so on a
// consistently outward-oriented solid outer loops run counter-clockwise seen from the positive
// side (holes clockwise); chains are followed across edges whatever the orientation.
// Status: ok; empty_input (no triangles); invalid_input (an index out of range, bad offsets);
// non_finite_input (a NaN or infinite coordinate, of the plane or of a vertex used);
// degenerate_input (a zero normal). Triangles repeating a vertex index are skipped. Around an
// edge shared by more than two faces the chains are joined in face order. Cost O(n) expected
// (a hash of the crossed edges); compiled in src/intersection/plane_mesh.cpp for float, double.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/polyline.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// The cross-section of a mesh by a plane (see the header comment).
template <Real T>
struct MeshSlice {
  Status status = Status::empty_input;
  std::vector<Polyline3<T>> polylines;  ///< closed loops and open chains, in discovery order
};

/// Slices the triangles (index triples into vertices) by the plane.
template <Real T>
[[nodiscard]] MeshSlice<T> slice_mesh(std::span<const Vec3<T>> vertices,
                                      std::span<const std::array<std::uint32_t, 3>> triangles,
                                      const Plane3<T>& plane);

/// Slices polygon faces (face f: indices[offsets[f]] .. indices[offsets[f + 1] - 1]).
template <Real T>
[[nodiscard]] MeshSlice<T> slice_mesh(std::span<const Vec3<T>> vertices,
                                      std::span<const std::uint32_t> face_offsets,
                                      std::span<const std::uint32_t> face_indices,
                                      const Plane3<T>& plane);

/// Any contiguous range of points (std::vector<Vec3d>, std::array, a flat span).
template <PointRange3 R>
[[nodiscard]] MeshSlice<range_scalar_t<R>> slice_mesh(
    const R& vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
    const Plane3<range_scalar_t<R>>& plane) {
  return slice_mesh(point_span(vertices), triangles, plane);
}

extern template MeshSlice<float> slice_mesh(std::span<const Vec3<float>>,
                                            std::span<const std::array<std::uint32_t, 3>>,
                                            const Plane3<float>&);
extern template MeshSlice<double> slice_mesh(std::span<const Vec3<double>>,
                                             std::span<const std::array<std::uint32_t, 3>>,
                                             const Plane3<double>&);
extern template MeshSlice<float> slice_mesh(std::span<const Vec3<float>>,
                                            std::span<const std::uint32_t>,
                                            std::span<const std::uint32_t>, const Plane3<float>&);
extern template MeshSlice<double> slice_mesh(std::span<const Vec3<double>>,
                                             std::span<const std::uint32_t>,
                                             std::span<const std::uint32_t>, const Plane3<double>&);

}  // namespace locus
