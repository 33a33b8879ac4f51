// SPDX-License-Identifier: BSL-1.0
#pragma once
// Monotone decomposition and triangulation of a polygon with holes (book section 13.9.3,
// figures 13.62-13.73; CAPABILITIES row cg.triangulate). Input, output and status:
// triangulate/polygon_triangulation.hpp.
// monotone_decomposition: a sweep from top to bottom ("above" = larger y, ties broken by
// smaller x: lexicographic, exact) classifies every vertex as start, split, end, merge or
// regular, keeps the edges the sweep line crosses in a balanced tree ordered by orient2d
// (exact; valid because edges do not cross; each new pair of neighbours is tested for a
// crossing, as in Shamos and Hoey) and adds a diagonal from each split and to each merge vertex
// through the helper vertices of the edges with the interior to their right. The result: the
// diagonals and the y-monotone pieces, counter-clockwise vertex rings back to back (`vertices`,
// `piece_ends`). triangulate_monotone: each piece triangulated by the stack walk over its two
// chains; n + 2h - 2 triangles for n vertices (after clean-up) and h holes. Degenerate input:
// straight runs keep their middle vertices (they are regular vertices, every vertex is used);
// duplicates and spike tips are dropped (polygon_triangulation.hpp). The rings must be simple and
// disjoint: a crossing the sweep detects (an edge missing from the tree, no edge left of a split or
// merge vertex, a vertex outside its interval, two tree neighbours crossing, a piece that is not
// closed, a wrong triangle count) gives invalid_topology and no pieces or triangles; an undetected
// crossing gives terminating, in-range output. Use ear clipping for a best effort on such input.
// Cost O(n log n); the faster route for simple polygons (bench/results/triangulate.md).
// docs/notes/triangulate.md.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/triangulate/polygon_triangulation.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// The y-monotone pieces of a polygon with holes and the diagonals that cut it into them.
struct MonotoneDecomposition {
  Status status = Status::empty_input;
  std::vector<std::uint32_t> vertices;    ///< pieces back to back, each a CCW ring of indices
  std::vector<std::uint32_t> piece_ends;  ///< piece k is vertices[piece_ends[k-1] .. piece_ends[k])
  std::vector<std::array<std::uint32_t, 2>> diagonals;  ///< the added diagonals (index pairs)

  [[nodiscard]] std::size_t piece_count() const noexcept { return piece_ends.size(); }
};

/// The monotone decomposition (see the top of the header).
template <Real T>
[[nodiscard]] MonotoneDecomposition monotone_decomposition(
    std::span<const Vec2<T>> points, std::span<const std::uint32_t> ring_ends);

/// Triangulation through the monotone decomposition (see the top of the header).
template <Real T>
[[nodiscard]] PolygonTriangulation triangulate_monotone(std::span<const Vec2<T>> points,
                                                        std::span<const std::uint32_t> ring_ends);

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] MonotoneDecomposition monotone_decomposition(
    const R& points, std::span<const std::uint32_t> ring_ends) {
  return monotone_decomposition(point_span(points), ring_ends);
}
template <PointRange2 R>
[[nodiscard]] PolygonTriangulation triangulate_monotone(const R& points,
                                                        std::span<const std::uint32_t> ring_ends) {
  return triangulate_monotone(point_span(points), ring_ends);
}

extern template MonotoneDecomposition monotone_decomposition<float>(std::span<const Vec2<float>>,
                                                                    std::span<const std::uint32_t>);
extern template MonotoneDecomposition monotone_decomposition<double>(
    std::span<const Vec2<double>>, std::span<const std::uint32_t>);
extern template PolygonTriangulation triangulate_monotone<float>(std::span<const Vec2<float>>,
                                                                 std::span<const std::uint32_t>);
extern template PolygonTriangulation triangulate_monotone<double>(std::span<const Vec2<double>>,
                                                                  std::span<const std::uint32_t>);

}  // namespace locus
