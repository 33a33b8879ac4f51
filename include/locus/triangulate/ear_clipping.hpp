// SPDX-License-Identifier: BSL-1.0
#pragma once
// Ear clipping of a polygon with holes (book section 13.9.1, figures 13.53-13.56; CAPABILITIES
// row cg.triangulate). Input, output and status: triangulate/polygon_triangulation.hpp.
// Method: each hole is joined to the outer ring by a bridge (two coincident edges), holes in
// lexicographic order of their smallest vertex; Eberly's horizontal-ray candidate is used only
// if an exact test accepts it (inside both vertex cones, no edge of any ring crossing or
// touching it: orient2d, lexicographic order), else the nearest vertex that passes, from any
// hole vertex. Then ears are cut; the ear test looks only at reflex vertices, kept in a uniform
// grid, so it costs the reflex vertices near the ear, not O(n).
// Degenerate input: straight-run middles, merged duplicates and spike tips are dropped (no
// triangle uses them: T-junctions there); holes touching the outer ring or each other at a
// vertex are bridged there (zero-length bridge); pinched rings are handled by the cones of the
// copies. Rings that cross (exact grid test), a hole with no valid bridge, or a ring with no ear
// (cured as earcut does: local loops cut, then split along a valid diagonal, else a convex
// vertex cut anyway) give invalid_topology with a best effort that terminates.
// Cost: O(n log n) sorting; per bridge the cells near it of a grid of all ring edges and
// vertices (rings of cells outwards when the candidate fails); then about O(n k) for k live reflex
// vertices per grid cell (near O(n) on ordinary input). Derivation: docs/notes/triangulate.md.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/triangulate/polygon_triangulation.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// A reflex vertex in the ear-test grid (internal to EarClipping2): its point and node.
template <Real T>
struct GridEntry {
  Vec2<T> p;
  std::uint32_t node;
};

/// Reusable ear-clipping triangulator (keeps its buffers between calls).
template <Real T>
class EarClipping2 {
 public:
  /// The triangles of the polygon with holes given by its rings (see the top of the header).
  const PolygonTriangulation& compute(std::span<const Vec2<T>> points,
                                      std::span<const std::uint32_t> ring_ends);

  [[nodiscard]] const PolygonTriangulation& result() const noexcept { return result_; }

 private:
  // The ring nodes (a vertex index with its ring neighbours) and the reflex-vertex grid; the
  // algorithm lives in src/triangulate/ear_clipping.cpp.
  struct Node {
    std::uint32_t index, prev, next;
    std::uint8_t reflex, removed;
  };
  template <Real>
  friend struct EarClipRun;

  PolygonTriangulation result_;
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> ring_, hole_starts_, cell_start_, cell_count_, grid_pos_;
  std::vector<GridEntry<T>> cell_items_;
};

/// Ear clipping of a polygon with holes (one call over EarClipping2).
template <Real T>
[[nodiscard]] PolygonTriangulation triangulate_ear_clipping(
    std::span<const Vec2<T>> points, std::span<const std::uint32_t> ring_ends);

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] PolygonTriangulation triangulate_ear_clipping(
    const R& points, std::span<const std::uint32_t> ring_ends) {
  return triangulate_ear_clipping(point_span(points), ring_ends);
}

extern template class EarClipping2<float>;
extern template class EarClipping2<double>;
extern template PolygonTriangulation triangulate_ear_clipping<float>(
    std::span<const Vec2<float>>, std::span<const std::uint32_t>);
extern template PolygonTriangulation triangulate_ear_clipping<double>(
    std::span<const Vec2<double>>, std::span<const std::uint32_t>);

}  // namespace locus
