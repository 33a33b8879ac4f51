// SPDX-License-Identifier: BSL-1.0
#pragma once
// The BSP tree of a polygon with holes (book section 13.1, figures 13.1-13.12; row cg.bsp2):
// construction with splitting, a balanced construction, exact point classification and the
// partition of a segment into inside / outside / coincident-same / coincident-opposite pieces.
// Input: points and ring_ends as in triangulate/polygon_triangulation.hpp (ring 0 outer, then
// holes, any orientation; rings reoriented so the interior is LEFT of every directed edge).
// Clean-up (exact): merged duplicates and spike tips dropped, zero-area holes dropped.
// Tree: every node splits by the supporting line of one input edge (edges()[node.edge]); front
// = left (orient2d > 0), back = right. The fragments of input edges lying on that line are
// stored at the node; a leaf is inside (front of its parent) or outside.
// Exactness rule: a fragment is a piece of input edge e between two ends; an end is an input
// point, or the crossing of e's line with the line of the splitting edge that cut it
// (Bsp2End::line). Its stored point is rounded, but every side decision uses the definition:
// orient2d for input points, side_of_crossing (core/crossing.hpp) for cut ends, and the order
// of ends along a line by lexicographic order, orient2d x turn2d or compare_crossing_params. So
// classification and partition are exact on the input coordinates, at any depth of splitting.
// Balanced: the splitter is chosen among up to `sample` candidates (evenly spaced over the
// node's fragments) minimising split_cost * splits + |front - back|; first_edge takes the
// first fragment (the book's basic construction). Cost: O(n^2) fragments at worst, O(n log n)
// typical (balanced); classify O(depth), more when the point lies on splitting lines.
// Status as in triangulate/polygon_triangulation.hpp: ok, empty_input, invalid_input,
// non_finite_input, degenerate_input (outer ring of zero area: empty tree, all outside).
// Crossing or overlapping rings are not detected: the answers are then those of the tree built.
// partition(): pieces in order from s0 to s1, adjacent pieces of one location merged; non-finite
// ends give non_finite_input, s0 == s1 degenerate_input (no pieces). docs/notes/bsp.md.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/side.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

inline constexpr std::uint32_t bsp2_none = 0xffffffffu;

/// One end of a fragment or piece (see the exactness rule at the top of the header).
template <Real T>
struct Bsp2End {
  Vec2<T> point{};                   ///< exact when line == bsp2_none, else rounded
  std::uint32_t line = bsp2_none;    ///< the edge whose supporting line cuts here, or none
  std::uint32_t vertex = bsp2_none;  ///< the input point index when the end is an input point
};

/// A piece of input edge `edge`, ends in the edge's direction.
template <Real T>
struct Bsp2Fragment {
  std::uint32_t edge = 0;
  std::array<Bsp2End<T>, 2> end{};
};

/// A node: children are node indices >= 0 or the leaves bsp2_inside / bsp2_outside.
struct Bsp2Node {
  std::uint32_t edge = 0;  ///< splitting line: the supporting line of edges()[edge]
  std::int32_t front = 0, back = 0;
  std::uint32_t first = 0, count = 0;  ///< coincident fragments: fragments()[first, first + count)
};
inline constexpr std::int32_t bsp2_inside = -1, bsp2_outside = -2;
/// A child not yet built when Bsp2Options::max_nodes stopped the construction.
inline constexpr std::int32_t bsp2_pending = -3;

/// Fragments still to be processed below child `front ? front : back` of node `parent` (-1:
/// the root) when the construction stopped: pending_fragments()[first, first + count).
struct Bsp2PendingList {
  std::int32_t parent = -1;
  bool front = true;
  std::uint32_t first = 0, count = 0;
};

enum class Bsp2Split : std::uint8_t { first_edge, balanced };

struct Bsp2Options {
  Bsp2Split split = Bsp2Split::balanced;
  std::uint32_t sample = 16;     ///< candidates per node (balanced)
  std::uint32_t split_cost = 2;  ///< weight of one split against one unit of imbalance
  /// Stop after this many nodes (0: no limit), leaving bsp2_pending children and pending()
  /// lists: the state of the construction (figures 13.4-13.8), classified as outside there.
  std::uint32_t max_nodes = 0;
};

enum class Bsp2Location : std::uint8_t { inside, outside, coincident_same, coincident_opposite };

/// A piece of a partitioned segment; ends with vertex == line == bsp2_none are s0 / s1.
template <Real T>
struct Bsp2Piece {
  std::array<Bsp2End<T>, 2> end{};
  Bsp2Location location = Bsp2Location::outside;
};

template <Real T>
struct Bsp2SegmentPartition {
  Status status = Status::empty_input;
  std::vector<Bsp2Piece<T>> pieces;
};

/// The BSP tree of a polygon with holes (see the top of the header).
template <Real T>
class Bsp2 {
 public:
  Bsp2() = default;
  Bsp2(std::span<const Vec2<T>> points, std::span<const std::uint32_t> ring_ends,
       Bsp2Options options = {}) {
    build(points, ring_ends, options);
  }

  /// Builds the tree (replaces any previous one); returns status().
  Status build(std::span<const Vec2<T>> points, std::span<const std::uint32_t> ring_ends,
               Bsp2Options options = {});

  /// Exact: inside, outside, or boundary (on an edge or vertex). Non-finite p: outside.
  [[nodiscard]] Side classify(const Vec2<T>& p) const noexcept;
  /// The pieces of the segment s0 s1 in order (see the top of the header).
  [[nodiscard]] Bsp2SegmentPartition<T> partition(const Vec2<T>& s0, const Vec2<T>& s1) const;

  [[nodiscard]] Status status() const noexcept { return status_; }
  [[nodiscard]] std::int32_t root() const noexcept { return root_; }
  [[nodiscard]] std::span<const Bsp2Node> nodes() const noexcept { return nodes_; }
  [[nodiscard]] std::span<const Bsp2Fragment<T>> fragments() const noexcept { return fragments_; }
  /// The directed input edges (indices into points()), interior on the left.
  [[nodiscard]] std::span<const std::array<std::uint32_t, 2>> edges() const noexcept {
    return edges_;
  }
  [[nodiscard]] std::span<const Vec2<T>> points() const noexcept { return points_; }
  /// Lists left unprocessed by Bsp2Options::max_nodes (in the order they would be processed).
  [[nodiscard]] std::span<const Bsp2PendingList> pending() const noexcept { return pending_; }
  [[nodiscard]] std::span<const Bsp2Fragment<T>> pending_fragments() const noexcept {
    return pending_fragments_;
  }
  /// Longest root-to-leaf path (in nodes); fragments().size() - edges().size() splits were made.
  [[nodiscard]] std::uint32_t depth() const noexcept { return depth_; }

 private:
  Side classify_at(std::int32_t node, const Vec2<T>& p) const noexcept;

  Status status_ = Status::empty_input;
  std::int32_t root_ = bsp2_outside;
  std::uint32_t depth_ = 0;
  std::vector<Vec2<T>> points_;
  std::vector<std::array<std::uint32_t, 2>> edges_;
  std::vector<Bsp2Node> nodes_;
  std::vector<Bsp2Fragment<T>> fragments_;
  std::vector<Bsp2PendingList> pending_;
  std::vector<Bsp2Fragment<T>> pending_fragments_;
};

/// classify(p, tree) = tree.classify(p).
template <Real T>
[[nodiscard]] inline Side classify(const Vec2<T>& p, const Bsp2<T>& tree) noexcept {
  return tree.classify(p);
}

/// The BSP tree for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] auto make_bsp2(const R& points, std::span<const std::uint32_t> ring_ends,
                             Bsp2Options options = {}) {
  return Bsp2<range_scalar_t<R>>(point_span(points), ring_ends, options);
}

extern template class Bsp2<float>;
extern template class Bsp2<double>;

}  // namespace locus
