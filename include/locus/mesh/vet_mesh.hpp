// SPDX-License-Identifier: BSL-1.0
#pragma once
// VetMesh: the vertex-edge-face adjacency table of book section 9.3.1 (row mesh.vet, figures
// 9.7, 9.15) for general polygon faces (triangles the common case). Topology only: positions
// stay in the caller's array (PolygonMesh::vertices), indexed by the same vertex ids.
// Ids are std::uint32_t indexing flat arrays (vertex id v costs v + 1 records). A vertex exists
// once inserted or referenced by a face or edge; an edge {a, b} (a != b, unordered, one per
// vertex pair) exists once inserted or used by a face; face f is its vertex cycle v0 v1 ...
// v(k-1) (k >= 3, distinct ids) with edge i = {vi, v(i+1 mod k)}.
// Storage is flat: per-vertex and per-edge records, the faces' corners in one pool (a corner
// knows its face, its edge and the next corner on the same edge), a doubly linked list of edges
// around each vertex, and an open-addressing hash (vertex pair -> edge). insert_face and
// remove_face cost O(k) expected; find_edge O(1) expected; edge_faces(e) walks the corners of e.
// Removal policy: remove_face leaves a tombstone (has_face(f) false); ids of every other element
// stay valid; an edge left without faces is removed too unless it was inserted with
// insert_edge (then it stays, dangling); vertices are never removed implicitly (they may become
// isolated). compact() renumbers the live elements densely in id order and returns the maps.
// vertex_fans(v): the faces around v grouped in fans (maximal sequences of faces consecutive
// across edges {v, w} shared by exactly two faces), each with its rim vertices; ordered
// counter-clockwise seen from the side the first face's normal points to (following that
// face's orientation), closed when the fan goes all the way round. One fan means the vertex is
// a manifold vertex (interior if closed, boundary if open); two or more form a bow-tie.
// make_vet_mesh(PolygonMesh) keeps vertex ids; face_ids[i] is the id of input face i (i until a
// face is skipped). Bad offsets, a face with fewer than 3 vertices or an out-of-range index give
// invalid_input (empty table); a face repeating a vertex is skipped (npos) with degenerate_input.
// to_polygon_mesh() writes the live faces in id order.

#include <locus/config.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/mesh/polygon_mesh.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace locus {

/// The faces around one vertex that follow each other across manifold edges (see the top).
struct VertexFan {
  std::vector<std::uint32_t> faces;  ///< in order around the vertex
  std::vector<std::uint32_t> rim;    ///< rim vertices: faces.size() + 1 if open, else faces.size()
  bool closed = false;               ///< the fan goes all the way round the vertex
};

/// The renumbering done by VetMesh::compact(): new id of each old id (npos for removed ones).
struct VetCompaction {
  std::vector<std::uint32_t> vertex_map, edge_map, face_map;
};

class VetMesh {
 public:
  static constexpr std::uint32_t npos = 0xffffffffu;

  // ---- sizes and existence (ids below the capacity; a removed id reads as absent)
  [[nodiscard]] std::uint32_t vertex_capacity() const noexcept { return size32(vertices_); }
  [[nodiscard]] std::uint32_t edge_capacity() const noexcept { return size32(edges_); }
  [[nodiscard]] std::uint32_t face_capacity() const noexcept { return size32(faces_); }
  [[nodiscard]] std::size_t vertex_count() const noexcept { return live_vertices_; }
  [[nodiscard]] std::size_t edge_count() const noexcept { return live_edges_; }
  [[nodiscard]] std::size_t face_count() const noexcept { return live_faces_; }
  [[nodiscard]] bool has_vertex(std::uint32_t v) const noexcept {
    return v < vertices_.size() && vertices_[v].alive;
  }
  [[nodiscard]] bool has_edge(std::uint32_t e) const noexcept {
    return e < edges_.size() && edges_[e].alive;
  }
  [[nodiscard]] bool has_face(std::uint32_t f) const noexcept {
    return f < faces_.size() && faces_[f].size != 0;
  }

  // ---- building
  /// A new isolated vertex (id = vertex_capacity()).
  std::uint32_t insert_vertex();
  /// Makes vertex v exist (creating the record; no-op if it exists). v < npos.
  void ensure_vertex(std::uint32_t v);
  /// The edge {a, b}, created if missing, marked explicit (kept when its faces go); npos if a == b.
  std::uint32_t insert_edge(std::uint32_t a, std::uint32_t b);
  /// A new face with the given vertex cycle; npos (nothing inserted) if fewer than 3 vertices,
  /// a repeated vertex or an id equal to npos.
  std::uint32_t insert_face(std::span<const std::uint32_t> cycle);
  std::uint32_t insert_face(std::initializer_list<std::uint32_t> cycle) {
    return insert_face(std::span<const std::uint32_t>(cycle.begin(), cycle.size()));
  }
  /// Removes face f (false if absent); see the removal policy at the top.
  bool remove_face(std::uint32_t f);
  /// Removes edge e if no face uses it (false otherwise or if absent).
  bool remove_edge(std::uint32_t e);
  /// Removes vertex v if no edge uses it (false otherwise or if absent).
  bool remove_vertex(std::uint32_t v);
  /// Reverses the vertex cycle of face f (its orientation); ids unchanged.
  void flip_face(std::uint32_t f);
  /// Renumbers live vertices, edges and faces densely, keeping their order.
  VetCompaction compact();

  // ---- queries
  /// The edge {a, b}, or npos.
  [[nodiscard]] std::uint32_t find_edge(std::uint32_t a, std::uint32_t b) const noexcept;
  /// The end points of edge e (smaller id first).
  [[nodiscard]] std::array<std::uint32_t, 2> edge_vertices(std::uint32_t e) const noexcept {
    LOCUS_ASSERT(has_edge(e), "edge id not live");
    return {edges_[e].v[0], edges_[e].v[1]};
  }
  /// Whether e was created by insert_edge (stays when its faces are removed).
  [[nodiscard]] bool is_explicit_edge(std::uint32_t e) const noexcept {
    return has_edge(e) && edges_[e].explicit_edge;
  }
  /// The vertex cycle of face f.
  [[nodiscard]] std::span<const std::uint32_t> face_vertices(std::uint32_t f) const noexcept {
    LOCUS_ASSERT(has_face(f), "face id not live");
    return std::span<const std::uint32_t>(corner_vertex_).subspan(faces_[f].first, faces_[f].size);
  }
  /// The edges of face f: edge i joins face_vertices(f)[i] and [i + 1].
  [[nodiscard]] std::span<const std::uint32_t> face_edges(std::uint32_t f) const noexcept {
    LOCUS_ASSERT(has_face(f), "face id not live");
    return std::span<const std::uint32_t>(corner_edge_).subspan(faces_[f].first, faces_[f].size);
  }
  /// Number of faces using edge e (0: dangling, 1: boundary, 2: interior, > 2: non-manifold).
  [[nodiscard]] std::uint32_t edge_face_count(std::uint32_t e) const noexcept {
    LOCUS_ASSERT(has_edge(e), "edge id not live");
    return edges_[e].face_count;
  }
  /// Number of edges at vertex v.
  [[nodiscard]] std::uint32_t vertex_edge_count(std::uint32_t v) const noexcept {
    LOCUS_ASSERT(has_vertex(v), "vertex id not live");
    return vertices_[v].edge_count;
  }
  /// Whether face f traverses edge e from its smaller to its larger vertex id.
  [[nodiscard]] bool face_uses_edge_forward(std::uint32_t f, std::uint32_t e) const noexcept;

  /// The faces of edge e (each once; order unspecified).
  template <class Fn>
  void for_each_edge_face(std::uint32_t e, Fn&& fn) const {
    for (std::uint32_t c = edges_[e].first_corner; c != npos; c = corner_next_[c]) {
      fn(corner_face_[c]);
    }
  }
  /// The edges at vertex v.
  template <class Fn>
  void for_each_vertex_edge(std::uint32_t v, Fn&& fn) const {
    for (std::uint32_t e = vertices_[v].first_edge; e != npos;) {
      const std::uint32_t next = edges_[e].next[edges_[e].v[0] == v ? 0 : 1];
      fn(e);
      e = next;
    }
  }
  [[nodiscard]] std::vector<std::uint32_t> edge_faces(std::uint32_t e) const;
  [[nodiscard]] std::vector<std::uint32_t> vertex_edges(std::uint32_t v) const;
  /// The faces containing v (each once; order unspecified; vertex_fans() orders them).
  [[nodiscard]] std::vector<std::uint32_t> vertex_faces(std::uint32_t v) const;
  /// The vertices joined to v by an edge.
  [[nodiscard]] std::vector<std::uint32_t> vertex_neighbours(std::uint32_t v) const;
  /// Live edges with exactly one face, by increasing id.
  [[nodiscard]] std::vector<std::uint32_t> boundary_edges() const;
  /// The one-ring of v as fans (see the top); empty for a vertex without faces.
  [[nodiscard]] std::vector<VertexFan> vertex_fans(std::uint32_t v) const;

 private:
  struct VertexRec {
    std::uint32_t first_edge = npos;
    std::uint32_t edge_count = 0;
    bool alive = false;
  };
  struct EdgeRec {
    std::uint32_t v[2];
    std::uint32_t next[2];  // next / previous edge around v[0] and around v[1]
    std::uint32_t prev[2];
    std::uint32_t first_corner;
    std::uint32_t face_count;
    bool alive;
    bool explicit_edge;
  };
  struct FaceRec {
    std::uint32_t first;  // first corner in the pool
    std::uint32_t size;   // 0: removed
  };

  static std::uint32_t size32(const auto& v) noexcept {
    return static_cast<std::uint32_t>(v.size());
  }
  std::uint32_t get_edge(std::uint32_t a, std::uint32_t b);
  void unlink_edge(std::uint32_t e);
  void link_corner(std::uint32_t c);
  void unlink_corner(std::uint32_t c);
  // Open-addressing table: key (min << 32 | max) -> edge id; empty slots hold key ~0.
  void map_insert(std::uint64_t key, std::uint32_t e);
  void map_erase(std::uint64_t key);
  [[nodiscard]] std::uint32_t map_find(std::uint64_t key) const noexcept;

  std::vector<VertexRec> vertices_;
  std::vector<EdgeRec> edges_;
  std::vector<FaceRec> faces_;
  std::vector<std::uint32_t> corner_vertex_, corner_edge_, corner_next_, corner_face_;
  std::vector<std::uint64_t> map_keys_;
  std::vector<std::uint32_t> map_values_;
  std::size_t map_used_ = 0;
  std::size_t live_vertices_ = 0, live_edges_ = 0, live_faces_ = 0;
};

/// make_vet_mesh's result: the table and, per input face, its face id (npos if skipped).
struct VetMeshBuild {
  Status status = Status::empty_input;
  VetMesh mesh;
  std::vector<std::uint32_t> face_ids;
};

namespace detail {
VetMeshBuild make_vet_mesh(std::size_t vertex_count, std::span<const std::uint32_t> offsets,
                           std::span<const std::uint32_t> indices);
}  // namespace detail

/// The adjacency table of a polygon mesh (see the top for ids and statuses); every vertex of
/// mesh.vertices exists in it, so unused ones are isolated vertices.
template <Real T>
[[nodiscard]] VetMeshBuild make_vet_mesh(const PolygonMesh<T>& mesh) {
  return detail::make_vet_mesh(mesh.vertices.size(), mesh.face_offsets, mesh.face_indices);
}

/// The live faces of vet (in id order) over the given positions (one per vertex id, at least
/// vertex_capacity() of them); dangling edges are not representable and are dropped.
template <Real T>
[[nodiscard]] PolygonMesh<T> to_polygon_mesh(const VetMesh& vet,
                                             std::span<const Vec3<T>> positions) {
  LOCUS_ASSERT(positions.size() >= vet.vertex_capacity(), "too few positions");
  PolygonMesh<T> out;
  out.vertices.assign(positions.begin(), positions.end());
  for (std::uint32_t f = 0; f < vet.face_capacity(); ++f) {
    if (vet.has_face(f)) add_face(out, vet.face_vertices(f));
  }
  return out;
}

}  // namespace locus
