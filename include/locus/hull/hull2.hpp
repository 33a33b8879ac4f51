// SPDX-License-Identifier: BSL-1.0
#pragma once
// Convex hull of a finite set of 2D points (CAPABILITIES row cg.hull2; book section 13.7.1,
// figures 13.32-13.38).
//
// Input: a span of Vec2<T> (T = float or double). Output (Hull2Result): a Status, the dimension
// of the hull (0 point, 1 segment, 2 polygon; -1 when the status is not ok) and `indices` into the
// input:
//   dimension 2: the hull polygon, counter-clockwise, starting at the lowest-leftmost point
//                (minimum y, then minimum x). Without keep_collinear only strictly convex
//                vertices (the extreme points) are listed; with it, every input point on the
//                boundary is listed too, in boundary order.
//   dimension 1: the two end points of the segment, the lowest-leftmost first; with
//                keep_collinear every distinct point, sorted from that end to the other.
//   dimension 0: one index.
// Duplicated points are listed once: the smallest input index among equal points represents
// them. Every method returns the same indices for the same input (they serve as each other's
// oracles).
//
// Exactness: every combinatorial decision is an exact predicate (orient2d, lexicographic
// comparison), so the result is the exact hull of the given floating-point points, on any input:
// collinear, cocircular, duplicated, huge or tiny coordinates within orient2d's exact range (see
// core/predicates.hpp). Floating-point arithmetic is used only for heuristics (bucketing keys and
// the choice of the filter box), never for a decision that changes the result.
//
// Methods (Hull2Options::method):
//   monotone_chain (default, fastest): an Akl-Toussaint filter discards the points strictly
//     inside a box certified (by exact orient2d on its corners) to lie inside the hull of eight
//     extreme points; the survivors are sorted by a bucket sort on y (two levels, in cache, for
//     many survivors; exact ties resolved by a comparison sort inside the buckets) and one pass of
//     Andrew's monotone chain links both chains. O(n) expected on uniform input and on points in
//     convex position spread smoothly (a circle), O(n log n) worst case.
//   incremental: the book's incremental merge (figure 13.34: the tangents from the new point to
//     the current hull; figure 13.35: the five cases of a point against a degenerate hull that is
//     a segment) after a lexicographic sort, so every new point is outside and the tangent search
//     starts at the previous point: O(n log n).
//   divide_and_conquer: the book's recursive merge of two hulls separated by a (lexicographic)
//     line through their upper and lower tangents (figures 13.36-13.38): O(n log n).
//
// Bad input: an empty span gives Status::empty_input; a NaN or infinite coordinate gives
// Status::non_finite_input (no indices); more than 2^32 - 1 points gives Status::invalid_input.
// All points equal is dimension 0, not an error.
//
// Cost: see the methods; memory O(n) scratch, reused across calls by ConvexHull2.

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
