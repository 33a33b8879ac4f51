// SPDX-License-Identifier: BSL-1.0
#pragma once
// Horizontal trapezoidal map of non-crossing segments, built incrementally with a point-location
// structure (book section 13.9.2, figures 13.57-13.67; Seidel 1991; CAPABILITIES row
// cg.triangulate). Segments are index pairs into `points`. Each endpoint splits the trapezoid
// containing it by a horizontal line (split_at); each segment splits every trapezoid it crosses
// into a left and a right part (insert); merge() joins vertically adjacent trapezoids with the
// same left and right segments, giving the map of maximal trapezoids (3n + 1 of them for n
// segments with distinct endpoints; a split at a point of no inserted segment is undone). With
// `merge_each_insertion` (the default, Seidel's form) insert() merges as it goes, so the map is
// maximal after every insertion; without it the states are the book's figures. locate(q): the
// trapezoid containing q. Trapezoids are exact, with no constructed point: `bottom`/`top` are point
// indices (or trapezoid_unbounded) whose heights bound it, `left`/`right` segment indices (or
// unbounded); the whole plane is one trapezoid with all four unbounded. trapezoid_map_corners()
// rounds. Order (symbolic, exact): "above" = larger y, ties broken by SMALLER x, so no two points
// are level (horizontal segments behave as if tilted). Left/right of a segment: orient2d against it
// directed upward. A query on a boundary goes to the trapezoid above / right of it.
// Degenerate input: equal coordinates are one point (smallest index); a zero-length segment is
// skipped; segments may share endpoints. Segments crossing, overlapping or touching another's
// interior give invalid_topology (that segment is not inserted; the map stays valid).
// Status: empty_input (no segment: the plane), invalid_input (index out of range),
// non_finite_input (NaN/Inf in a used point: nothing built). Insertion order: as given, or
// shuffled by `shuffle_seed` (nonzero) for Seidel's expected O(n log n) time, O(n) size and
// O(log n) query; a chosen order can cost O(n^2). Walks along a segment relocate through the
// structure (no neighbour links). docs/notes/triangulate.md.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// Marks an unbounded side of a MapTrapezoid.
inline constexpr std::uint32_t trapezoid_unbounded = 0xffffffffu;

/// A trapezoid of the map (see the top of the header).
struct MapTrapezoid {
  std::uint32_t bottom = trapezoid_unbounded;  ///< point whose height bounds it below
  std::uint32_t top = trapezoid_unbounded;     ///< point whose height bounds it above
  std::uint32_t left = trapezoid_unbounded;    ///< segment bounding it on the left
  std::uint32_t right = trapezoid_unbounded;   ///< segment bounding it on the right

  friend bool operator==(const MapTrapezoid&, const MapTrapezoid&) = default;
};

struct TrapezoidMapOptions {
  bool merge_each_insertion = true;  ///< Seidel's maximal map after each insert()
  std::uint64_t shuffle_seed = 0;    ///< build(): nonzero shuffles the insertion order
};

/// The trapezoids of a built map and its status.
struct TrapezoidMap {
  Status status = Status::empty_input;
  std::vector<MapTrapezoid> trapezoids;
};

/// Reusable incremental trapezoidal map with point location.
template <Real T>
class TrapezoidMap2 {
 public:
  /// Starts a map of the plane for these segments (none inserted yet). Status as in the header;
  /// on invalid_input or non_finite_input every later step does nothing.
  Status begin(std::span<const Vec2<T>> points,
               std::span<const std::array<std::uint32_t, 2>> segments,
               TrapezoidMapOptions options = {});
  /// Splits the trapezoid containing points[p] by the horizontal through it (no-op if present).
  Status split_at(std::uint32_t point);
  /// Inserts segment s, splitting its endpoints first if needed.
  Status insert(std::uint32_t segment);
  /// Joins vertically adjacent trapezoids with equal left and right segments.
  void merge();
  /// begin, insert every segment (shuffled if asked), merge. Stops at the first bad segment.
  Status build(std::span<const Vec2<T>> points,
               std::span<const std::array<std::uint32_t, 2>> segments,
               TrapezoidMapOptions options = {});

  /// The live trapezoids (indices change after every step).
  [[nodiscard]] std::span<const MapTrapezoid> trapezoids() const noexcept { return traps_; }
  /// Index into trapezoids() of the trapezoid containing q (ties: above, then right);
  /// trapezoid_unbounded before begin() or after a failed one.
  [[nodiscard]] std::uint32_t locate(const Vec2<T>& q) const noexcept;
  /// The canonical index of a point (the smallest index with equal coordinates).
  [[nodiscard]] std::uint32_t canonical(std::uint32_t point) const noexcept {
    return canon_[point];
  }
  /// The segment's endpoints, canonical, lower (in the order above) first.
  [[nodiscard]] std::array<std::uint32_t, 2> segment(std::uint32_t s) const noexcept {
    return segs_[s];
  }
  [[nodiscard]] Status status() const noexcept { return status_; }
  /// Nodes of the point-location structure (its size).
  [[nodiscard]] std::size_t node_count() const noexcept { return nodes_.size(); }

 private:
  struct Node {
    std::uint8_t kind;  // 0 leaf, 1 point, 2 segment, 3 redirect
    std::uint32_t key;  // trapezoid, point or segment
    std::uint32_t child[2];
  };
  std::uint32_t add_trapezoid(const MapTrapezoid& t, std::uint32_t leaf);
  void remove_trapezoid(std::uint32_t id);
  [[nodiscard]] std::uint32_t locate_along(std::uint32_t s, std::uint32_t from) const noexcept;
  [[nodiscard]] int segment_side(std::uint32_t s, std::uint32_t other) const noexcept;
  [[nodiscard]] bool segments_touch(std::uint32_t s, std::uint32_t other) const noexcept;
  [[nodiscard]] bool below(std::uint32_t a, std::uint32_t b) const noexcept;

  std::span<const Vec2<T>> points_;
  std::vector<std::uint32_t> canon_;
  std::vector<std::array<std::uint32_t, 2>> segs_;
  std::vector<std::uint8_t> has_point_, inserted_;
  std::vector<MapTrapezoid> traps_;
  std::vector<std::uint32_t> leaf_of_;
  std::vector<Node> nodes_;
  TrapezoidMapOptions options_;
  Status status_ = Status::empty_input;
};

/// The maximal trapezoidal map of the segments (one call over TrapezoidMap2).
template <Real T>
[[nodiscard]] TrapezoidMap trapezoid_map(std::span<const Vec2<T>> points,
                                         std::span<const std::array<std::uint32_t, 2>> segments,
                                         TrapezoidMapOptions options = {});

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] TrapezoidMap trapezoid_map(const R& points,
                                         std::span<const std::array<std::uint32_t, 2>> segments,
                                         TrapezoidMapOptions options = {}) {
  return trapezoid_map(point_span(points), segments, options);
}

/// Corners of a trapezoid clipped to the box [lo, hi], counter-clockwise from bottom left
/// (rounded constructions; an unbounded side becomes the box side).
template <Real T>
[[nodiscard]] std::array<Vec2<T>, 4> trapezoid_map_corners(
    std::span<const Vec2<T>> points, std::span<const std::array<std::uint32_t, 2>> segments,
    const MapTrapezoid& t, const Vec2<T>& lo, const Vec2<T>& hi) noexcept;

extern template class TrapezoidMap2<float>;
extern template class TrapezoidMap2<double>;
extern template TrapezoidMap trapezoid_map<float>(std::span<const Vec2<float>>,
                                                  std::span<const std::array<std::uint32_t, 2>>,
                                                  TrapezoidMapOptions);
extern template TrapezoidMap trapezoid_map<double>(std::span<const Vec2<double>>,
                                                   std::span<const std::array<std::uint32_t, 2>>,
                                                   TrapezoidMapOptions);
extern template std::array<Vec2<float>, 4> trapezoid_map_corners<float>(
    std::span<const Vec2<float>>, std::span<const std::array<std::uint32_t, 2>>,
    const MapTrapezoid&, const Vec2<float>&, const Vec2<float>&) noexcept;
extern template std::array<Vec2<double>, 4> trapezoid_map_corners<double>(
    std::span<const Vec2<double>>, std::span<const std::array<std::uint32_t, 2>>,
    const MapTrapezoid&, const Vec2<double>&, const Vec2<double>&) noexcept;

}  // namespace locus
