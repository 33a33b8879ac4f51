// SPDX-License-Identifier: BSL-1.0
#pragma once
// Convex hull of a finite set of 2D points (CAPABILITIES row cg.hull2; book section 13.7.1,
// figures 13.32-13.38).
// Input: a span of Vec2<T> (T = float or double). Output (Hull2Result): a Status, the dimension
// (0 point, 1 segment, 2 polygon; -1 when the status is not ok) and `indices` into the input:
//   dimension 2: the hull polygon, counter-clockwise, starting at the lowest-leftmost point
//                (minimum y, then minimum x). Without keep_collinear only strictly convex
//                vertices (the extreme points) are listed; with it, every input point on the
//                boundary is listed too, in boundary order.
//   dimension 1: the two end points of the segment, the lowest-leftmost first; with
//                keep_collinear every distinct point, sorted from that end to the other.
//   dimension 0: one index.
// Equal points are represented by their smallest index. Every method returns the same indices.
// Exactness: every decision is an exact predicate (orient2d, lexicographic comparison): the exact
// hull of the given points within orient2d's range (core/predicates.hpp); floating point only
// steers heuristics (bucketing, the filter box).
// Methods (Hull2Options::method; details: docs/notes/hull.md):
//   monotone_chain (default, fastest): Akl-Toussaint filter, bucket sort, Andrew's monotone
//     chain; O(n) expected on uniform or smooth convex-position input, O(n log n) worst case.
//   incremental: the book's incremental merge (figures 13.34, 13.35): O(n log n).
//   divide_and_conquer: the book's recursive merge (figures 13.36-13.38): O(n log n).
// Bad input: empty -> Status::empty_input; NaN/Inf -> Status::non_finite_input (no indices); more
// than 2^32 - 1 points -> Status::invalid_input. All points equal is dimension 0, not an error.
// Memory O(n) scratch, reused across calls by ConvexHull2.

#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// Algorithm used by convex_hull (2D).
enum class Hull2Method : std::uint8_t {
  monotone_chain,      ///< Akl-Toussaint filter + bucket sort + Andrew's chain (fastest)
  incremental,         ///< the book's incremental merge after sorting
  divide_and_conquer,  ///< the book's divide-and-conquer with tangent merging
};

/// Options of convex_hull (2D).
struct Hull2Options {
  bool keep_collinear = false;  ///< also list input points in the relative interior of edges
  Hull2Method method = Hull2Method::monotone_chain;
};

/// A 2D convex hull: indices into the input (see the header comment for the order).
struct Hull2Result {
  Status status = Status::empty_input;
  int dimension = -1;                  ///< 0, 1 or 2 when status is ok; -1 otherwise
  std::vector<std::uint32_t> indices;  ///< counter-clockwise from the lowest-leftmost point
};

/// Reusable 2D hull builder: keeps its scratch buffers between calls (no allocation once warm).
template <Real T>
class ConvexHull2 {
 public:
  /// The hull of `points`.
  [[nodiscard]] Hull2Result compute(std::span<const Vec2<T>> points,
                                    const Hull2Options& options = {});
  /// The same, writing into `out` (its vector's capacity is reused).
  void compute(std::span<const Vec2<T>> points, const Hull2Options& options, Hull2Result& out);

  struct Item {
    Vec2<T> p;
    std::uint32_t index;
    std::uint32_t key;  // radix_sorted: quantised y (fills what would be padding for double)
    // Left uninitialised on purpose: resizing the large sort buffer must not zero-fill it.
    Item() noexcept {}  // NOLINT
    Item(const Vec2<T>& q, std::uint32_t i, std::uint32_t k = 0) noexcept
        : p(q), index(i), key(k) {}
  };

 private:
  void gather_sorted(std::span<const Vec2<T>> points, const std::uint32_t* selected, std::size_t m,
                     double ymin, double ymax);
  bool radix_sorted(std::span<const Vec2<T>> points, const std::uint32_t* selected, std::size_t m,
                    double ymin, double ymax);
  void monotone_chain(bool keep_collinear, Hull2Result& out);
  void incremental(Hull2Result& out);
  void divide_and_conquer(Hull2Result& out);
  void dc_merge(std::uint32_t lo, std::uint32_t mid, std::uint32_t hi);
  std::uint32_t dc_recurse(std::uint32_t lo, std::uint32_t hi);
  void emit_strict(bool keep_collinear, Hull2Result& out);

  std::vector<Item> items_;  // filtered, sorted, deduplicated points
  std::vector<std::uint32_t> counts_;
  std::vector<Item> items2_;  // radix_sorted: scratch for one bucket
  std::vector<std::uint32_t> sub_counts_;
  std::vector<std::uint32_t> hull_;  // positions in items_ (monotone chain: both chains)
  std::vector<std::uint32_t> aux_;   // method-specific
  std::vector<std::uint32_t> aux2_;
};

/// The convex hull of a 2D point set (one call over ConvexHull2).
template <Real T>
[[nodiscard]] Hull2Result convex_hull(std::span<const Vec2<T>> points,
                                      const Hull2Options& options = {}) {
  ConvexHull2<T> builder;
  return builder.compute(points, options);
}

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] Hull2Result convex_hull(const R& points, const Hull2Options& options = {}) {
  return convex_hull(point_span(points), options);
}

extern template class ConvexHull2<float>;
extern template class ConvexHull2<double>;

}  // namespace locus
