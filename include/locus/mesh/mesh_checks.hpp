// SPDX-License-Identifier: BSL-1.0
#pragma once
// Mesh validity checks of book section 9.3 (row mesh.checks, figures 9.8-9.16) over a VetMesh
// (mesh/vet_mesh.hpp) and, where geometry matters, one position per vertex id.
// check_topology: isolated vertices (no edge), isolated edges (no face: dangling), boundary
// edges (one face), non-manifold edges (> 2 faces), non-manifold vertices (faces around them
// form more than one fan, VetMesh::vertex_fans: bow-ties and vertices on a non-manifold edge);
// closed = at least one face, no boundary and no isolated edge; manifold = no non-manifold edge
// or vertex. connected_components: faces joined by shared edges (figure 9.12: sharing a vertex
// does not connect) and vertices joined by edges. orient_consistently: per face component, the
// lowest face id keeps its order and faces across two-face edges are flipped to traverse the
// edge the other way (figure 9.15); a component where that is impossible (Möbius, fig. 9.16) is
// non-orientable, and none of its faces is listed; edges with > 2 faces do not propagate.
// make_consistent() applies the flips. All of these are combinatorial: O(V + E + F).
// self_intersections: pairs of faces that interpenetrate, decided exactly (triangle_triangle.hpp
// and orient3d/orient2d). Polygon faces are tested through their fan triangles (exact for convex
// faces); degenerate fan triangles (collinear, exact) are skipped and a face whose vertices are
// all collinear is listed in degenerate_faces. Two fan triangles of different faces count when
// their intersection is more than the hull of their common vertex ids: no common vertex: any
// contact; one (s): the edge opposite s in either meets the other; two (an edge): coplanar and
// folded onto the same side; three: a repeated face. Equal positions under different ids count
// as contact. Broad phase: boxes sorted along the longest axis, so near-linear on surface meshes.
// classify_mesh (book 9.3): mesh = no isolated vertex or edge, no degenerate or non-planar face
// (exact), no self-intersection; polyhedron = mesh, connected, closed, every edge in exactly two
// faces, orientable; polytope = polyhedron with convex faces and every edge convex for one
// orientation (local convexity of a closed embedded surface gives global convexity). Planarity
// and edge convexity are exact by default; rounded coordinates (a dodecahedron's pentagons, the
// two triangles of a planar quad) are then rarely exactly flat, so coplanarity_tolerance t > 0
// treats points within t * (bounding-box diagonal) of a plane as on it.
// Status: ok, empty_input (no vertex), invalid_input / degenerate_input (make_vet_mesh's),
// non_finite_input (a NaN or infinite coordinate: geometric parts are skipped).

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/mesh/polygon_mesh.hpp>
#include <locus/mesh/vet_mesh.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

struct MeshTopology {
  Status status = Status::empty_input;
  std::vector<std::uint32_t> isolated_vertices;      ///< vertex ids without an edge
  std::vector<std::uint32_t> isolated_edges;         ///< edge ids without a face
  std::vector<std::uint32_t> boundary_edges;         ///< edge ids with one face
  std::vector<std::uint32_t> non_manifold_edges;     ///< edge ids with more than two faces
  std::vector<std::uint32_t> non_manifold_vertices;  ///< vertex ids with more than one fan
  bool closed = false;
  bool manifold = false;
};

struct MeshComponents {
  Status status = Status::empty_input;
  std::uint32_t face_component_count = 0;
  std::vector<std::uint32_t> face_component;  ///< per face id (npos for a removed face)
  std::uint32_t vertex_component_count = 0;
  std::vector<std::uint32_t> vertex_component;  ///< per vertex id (npos for a removed vertex)
};

struct MeshOrientation {
  Status status = Status::empty_input;
  bool orientable = false;                               ///< every component is orientable
  std::vector<std::uint32_t> flipped_faces;              ///< face ids to reverse, increasing
  std::vector<std::uint32_t> non_orientable_components;  ///< face component ids (Möbius-like)
  MeshComponents components;                             ///< the face components used
};

struct MeshSelfIntersections {
  Status status = Status::empty_input;
  std::vector<std::array<std::uint32_t, 2>> face_pairs;  ///< (f, g), f < g, sorted
  std::vector<std::uint32_t> degenerate_faces;           ///< all vertices collinear
};

enum class MeshKind : std::uint8_t { not_a_mesh, mesh, polyhedron, polytope };

struct MeshClassification {
  Status status = Status::empty_input;
  MeshKind kind = MeshKind::not_a_mesh;
  MeshTopology topology;
  MeshOrientation orientation;  ///< with the face components
  MeshSelfIntersections intersections;
  std::vector<std::uint32_t> non_planar_faces;  ///< faces whose vertices are not coplanar
  long long euler_characteristic = 0;           ///< V - E + F over live elements
  bool convex = false;                          ///< the polytope test passed
};

/// V - E + F over the live elements.
[[nodiscard]] inline long long euler_characteristic(const VetMesh& m) noexcept {
  return static_cast<long long>(m.vertex_count()) - static_cast<long long>(m.edge_count()) +
         static_cast<long long>(m.face_count());
}

[[nodiscard]] MeshTopology check_topology(const VetMesh& mesh);
[[nodiscard]] MeshComponents connected_components(const VetMesh& mesh);
[[nodiscard]] MeshOrientation orient_consistently(const VetMesh& mesh);
/// orient_consistently() and then flips the listed faces of mesh.
MeshOrientation make_consistent(VetMesh& mesh);
/// The same on a polygon mesh (reverses the index runs of the flipped faces); invalid input
/// leaves it unchanged with make_vet_mesh's status.
template <Real T>
MeshOrientation make_consistent(PolygonMesh<T>& mesh);

template <Real T>
[[nodiscard]] MeshSelfIntersections self_intersections(const VetMesh& mesh,
                                                       std::span<const Vec3<T>> positions);
template <Real T>
[[nodiscard]] MeshSelfIntersections self_intersections(const PolygonMesh<T>& mesh);

/// coplanarity_tolerance: 0 (exact) or relative to the bounding-box diagonal (see the top).
template <Real T>
[[nodiscard]] MeshClassification classify_mesh(const VetMesh& mesh,
                                               std::span<const Vec3<T>> positions,
                                               T coplanarity_tolerance = T(0));
template <Real T>
[[nodiscard]] MeshClassification classify_mesh(const PolygonMesh<T>& mesh,
                                               T coplanarity_tolerance = T(0));

#define LOCUS_MESH_CHECKS_EXTERN(T)                                                             \
  extern template MeshOrientation make_consistent<T>(PolygonMesh<T>&);                          \
  extern template MeshSelfIntersections self_intersections<T>(const VetMesh&,                   \
                                                              std::span<const Vec3<T>>);        \
  extern template MeshSelfIntersections self_intersections<T>(const PolygonMesh<T>&);           \
  extern template MeshClassification classify_mesh<T>(const VetMesh&, std::span<const Vec3<T>>, \
                                                      T);                                       \
  extern template MeshClassification classify_mesh<T>(const PolygonMesh<T>&, T);
LOCUS_MESH_CHECKS_EXTERN(float)
LOCUS_MESH_CHECKS_EXTERN(double)
#undef LOCUS_MESH_CHECKS_EXTERN

}  // namespace locus
