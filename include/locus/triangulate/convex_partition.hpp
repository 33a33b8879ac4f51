// SPDX-License-Identifier: BSL-1.0
#pragma once
// Convex partitioning of a polygon by diagonals (book section 13.9.4, figures 13.74-13.77; row
// cg.convexpart). Input as in triangulate/polygon_triangulation.hpp (ring 0 outer, then holes,
// any orientation, the same clean-up and statuses). Output: convex pieces, counter-clockwise
// rings of input indices back to back, and the diagonals used. A piece is weakly convex:
// orient2d(prev, v, next) >= 0 at each of its vertices (straight runs keep their middles).
//  * convex_partition (Hertel-Mehlhorn): triangulate_monotone (every input vertex used; where
//    it reports invalid_topology, e.g. rings touching at a vertex, triangulate_ear_clipping,
//    which drops straight-run middles), then each diagonal is removed when both its ends stay
//    convex in the merged piece (exact orient2d). Every kept diagonal is essential at one end, so
//    for a polygon without holes the piece count is at most 2r + 1 <= 4 x the minimum (r reflex
//    vertices; the minimum needs at least ceil(r / 2) + 1). Holes allowed. O(n log n).
//  * min_convex_partition: the minimum number of convex pieces over all partitions by
//    diagonals (no Steiner points) of a polygon WITHOUT holes, exact. Default: Keil and
//    Snoeyink's programme (book section 13.9.3's "narrowest pairs"): for each sub-polygon cut
//    off by a diagonal with a reflex (or straight) end, the least count and the narrowest
//    (first, last) vertex pairs of the piece on that diagonal; visibility by a wedge walk
//    through a triangulation; every decision by orient2d. O(n r^2) time (r reflex vertices),
//    O(n r) memory; above min_convex_partition_keil_cells table records, limit_exceeded with
//    the Hertel-Mehlhorn partition. MinConvexMethod::direct: the older direct O(n^5) programme
//    over convex chains of diagonals, n <= min_convex_partition_limit (64), kept as an
//    independent check. Holes give invalid_input, no pieces. docs/notes/triangulate.md.
// Status: that of the triangulation (polygon_triangulation.hpp): pieces only when ok (or
// limit_exceeded above). A polygon that is convex already gives one piece.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// Convex pieces of a polygon (see the top of the header).
struct ConvexPartition {
  Status status = Status::empty_input;
  std::vector<std::uint32_t> vertices;    ///< pieces back to back, each a CCW ring of indices
  std::vector<std::uint32_t> piece_ends;  ///< piece k is vertices[piece_ends[k-1] .. piece_ends[k])
  std::vector<std::array<std::uint32_t, 2>> diagonals;  ///< the diagonals between pieces

  [[nodiscard]] std::size_t piece_count() const noexcept { return piece_ends.size(); }
};

/// Which exact minimum: Keil and Snoeyink's O(n r^2) programme (default) or the direct
/// O(n^5) programme kept as an independent check (n at most min_convex_partition_limit).
enum class MinConvexMethod : std::uint8_t { keil, direct };

inline constexpr std::uint32_t min_convex_partition_limit = 64;
/// Keil's tables hold r x n records (r reflex vertices): above this, limit_exceeded.
inline constexpr std::uint64_t min_convex_partition_keil_cells = std::uint64_t(1) << 22;

/// Hertel-Mehlhorn convex partition (see the top of the header).
template <Real T>
[[nodiscard]] ConvexPartition convex_partition(std::span<const Vec2<T>> points,
                                               std::span<const std::uint32_t> ring_ends);

/// Minimum convex partition of a polygon without holes (see the top of the header).
template <Real T>
[[nodiscard]] ConvexPartition min_convex_partition(std::span<const Vec2<T>> points,
                                                   std::span<const std::uint32_t> ring_ends,
                                                   MinConvexMethod method = MinConvexMethod::keil);

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] ConvexPartition convex_partition(const R& points,
                                               std::span<const std::uint32_t> ring_ends) {
  return convex_partition(point_span(points), ring_ends);
}
template <PointRange2 R>
[[nodiscard]] ConvexPartition min_convex_partition(const R& points,
                                                   std::span<const std::uint32_t> ring_ends,
                                                   MinConvexMethod method = MinConvexMethod::keil) {
  return min_convex_partition(point_span(points), ring_ends, method);
}

extern template ConvexPartition convex_partition<float>(std::span<const Vec2<float>>,
                                                        std::span<const std::uint32_t>);
extern template ConvexPartition convex_partition<double>(std::span<const Vec2<double>>,
                                                         std::span<const std::uint32_t>);
extern template ConvexPartition min_convex_partition<float>(std::span<const Vec2<float>>,
                                                            std::span<const std::uint32_t>,
                                                            MinConvexMethod);
extern template ConvexPartition min_convex_partition<double>(std::span<const Vec2<double>>,
                                                             std::span<const std::uint32_t>,
                                                             MinConvexMethod);

}  // namespace locus
