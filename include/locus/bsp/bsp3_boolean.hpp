// SPDX-License-Identifier: BSL-1.0
#pragma once
// Boolean operations on closed triangle meshes through their BSP trees (row cg.bool3; book
// sections 13.1.2 and 13.6, extending bsp/bsp2.hpp to polyhedra). mesh_boolean(op, A, B)
// partitions each triangle of A by B's tree and each of B by A's tree and keeps
//   union_:               A outside B, B outside A, A coincident_same (coplanar faces once);
//   intersection:         A inside B,  B inside A,  A coincident_same;
//   difference:           A outside B, B inside A reversed, A coincident_opposite;
//   symmetric_difference: A outside B, B outside A, A inside B and B inside A reversed.
// Opposite coincident faces (solids touching) vanish in union and intersection; all coincident
// faces vanish in the xor, whose parts touch along the intersection curve. mesh_complement(M):
// every triangle reversed, the unbounded complement (a valid operand).
// Watertight output: every constructed vertex is named by provenance (the three planes it lies
// on, an input edge and a plane, an input vertex; planes equal up to input rounding share an
// id) and shared by that name between all pieces of both operands; a conforming pass inserts
// every output vertex of a line (by name, one order per line) into each edge on it, and pieces
// are triangulated by ears at their corners. Result: every directed edge is matched by its
// reverse, and for generic inputs (rigid motions included) each edge is used exactly once in
// each direction (a 2-manifold when the true result is one). Not guaranteed where faces of the
// two operands are coplanar only up to rounding (closed, may fold) or 4+ planes meet at a point.
// Cut points are rounded (not an exact-arithmetic boolean). docs/notes/bsp3.md.
// Status: non_finite_input / invalid_input of either operand (no output); an empty operand
// (empty_input / degenerate_input) is the empty solid, its status reported with the result
// (union = the other operand); otherwise ok (an empty result has no triangles).
// Cost: the two trees (bsp/bsp3.hpp), F_A depth_B + F_B depth_A node visits, O(T log V) naming
// and conforming: two overlapping icospheres of 1280 faces take 1.3 s in all, of 5120 14 s.

#include <locus/bsp/bsp3.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <concepts>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

enum class MeshBooleanOp : std::uint8_t { union_, intersection, difference, symmetric_difference };

template <Real T>
struct MeshBoolean {
  Status status = Status::empty_input;
  std::vector<Vec3<T>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// The complement of a closed triangle mesh: the same vertices, every triangle reversed (its
/// normals point into the solid). It bounds the unbounded region outside the mesh (volume by the
/// divergence theorem: minus the solid's); a Bsp3 built on it classifies that region as inside,
/// so it is a valid mesh_boolean operand (A intersection complement(B) = A - B). Status:
/// empty_input (no triangles), invalid_input (index out of range), non_finite_input; no output
/// then. O(V + T).
template <Real T>
[[nodiscard]] MeshBoolean<T> mesh_complement(
    std::span<const Vec3<T>> vertices, std::span<const std::array<std::uint32_t, 3>> triangles);

/// op(A, B) from the two trees (see the top of the header).
template <Real T>
[[nodiscard]] MeshBoolean<T> mesh_boolean(MeshBooleanOp op, const Bsp3<T>& a, const Bsp3<T>& b);

/// op(A, B) from two closed, outward-oriented triangle meshes (builds both trees).
template <Real T>
[[nodiscard]] MeshBoolean<T> mesh_boolean(MeshBooleanOp op, std::span<const Vec3<T>> a_vertices,
                                          std::span<const std::array<std::uint32_t, 3>> a_triangles,
                                          std::span<const Vec3<T>> b_vertices,
                                          std::span<const std::array<std::uint32_t, 3>> b_triangles,
                                          Bsp3Options options = {});

/// The same for any 3D point ranges of one scalar type (core/point_range.hpp).
template <PointRange3 RA, PointRange3 RB>
requires std::same_as<range_scalar_t<RA>, range_scalar_t<RB>>
[[nodiscard]] auto mesh_boolean(MeshBooleanOp op, const RA& a_vertices,
                                std::span<const std::array<std::uint32_t, 3>> a_triangles,
                                const RB& b_vertices,
                                std::span<const std::array<std::uint32_t, 3>> b_triangles,
                                Bsp3Options options = {}) {
  return mesh_boolean<range_scalar_t<RA>>(op, point_span(a_vertices), a_triangles,
                                          point_span(b_vertices), b_triangles, options);
}

#define LOCUS_BSP3_BOOLEAN_EXTERN(T)                                                          \
  extern template MeshBoolean<T> mesh_boolean(MeshBooleanOp, const Bsp3<T>&, const Bsp3<T>&); \
  extern template MeshBoolean<T> mesh_boolean(                                                \
      MeshBooleanOp, std::span<const Vec3<T>>, std::span<const std::array<std::uint32_t, 3>>, \
      std::span<const Vec3<T>>, std::span<const std::array<std::uint32_t, 3>>, Bsp3Options);  \
  extern template MeshBoolean<T> mesh_complement(std::span<const Vec3<T>>,                    \
                                                 std::span<const std::array<std::uint32_t, 3>>);
LOCUS_BSP3_BOOLEAN_EXTERN(float)
LOCUS_BSP3_BOOLEAN_EXTERN(double)
#undef LOCUS_BSP3_BOOLEAN_EXTERN

}  // namespace locus
