// SPDX-License-Identifier: BSL-1.0
#pragma once
// Minimum-volume enclosing box of a 3D point set; CAPABILITIES row cg.minbox (3D part); book
// section 13.10.2.
//
// Method (derivation and bounds: docs/notes/bounding.md): a minimum box has two adjacent faces
// flush with hull edges (O'Rourke 1985), so its volume is the minimum over hull edges e and
// normals n on e's arc of the Gauss sphere of f(n) = width along n * minimum rectangle area of
// the projection (bounding/min_rect2.hpp). min_box takes the exact hull (hull/hull3.hpp),
// evaluates f at every facet normal (and edge-pair normals for small hulls), then searches the
// arcs by branch and bound (edge_arcs; or regions of normals for huge hulls, MinBoxSearch) and
// refines by descent over rotations.
// Guarantee: never worse than the best facet-flush box, except in the region search; certified
// = true proves that no enclosing box has volume below (1 - certify_tol) * volume (up to the
// rounding of the evaluated f values). The hulls are exact; axes, extents and volume are
// rounded constructions (double, then T); every input point lies in the box up to a few ulps
// of the set's scale. Scale-covariant: input scaled by 2^k gives the box scaled by 2^k.
// Result: status, box (axes orthonormal, right-handed), volume, candidates (normals at which f
// was evaluated), arcs (hull edges whose arc was searched), certified.
// Degenerate input: all points equal -> ok, a zero box at the point; collinear -> ok, a box of
// zero width and height along the segment; coplanar -> ok, the minimum-area rectangle in the
// plane with extent[2] = 0. Empty -> empty_input; NaN/Inf -> non_finite_input.
// Budget: max_work bounds the evaluations' work (blocks, cells, edges, vertices visited); when
// it runs out the best box so far is returned with Status::limit_exceeded, certified = false
// (it still encloses every point).
// Cost: hull + (F + evaluations) * (visited cells and edges + silhouette log silhouette).

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/oriented_box.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

namespace locus {

/// The branch and bound of min_box (see the header comment).
enum class MinBoxSearch : std::uint8_t {
  automatic,  ///< arcs, or regions when the facet pass alone would take half of max_work
  arcs,       ///< over the hull edges' arcs of normals (step 3)
  regions,    ///< over regions of normals (step 3')
};

/// Options of min_box.
struct MinBoxOptions {
  std::size_t max_pair_edges = 60;  ///< edge-pair candidates only for hulls with <= this many edges
  bool refine = true;               ///< local descent over rotations from the best candidate
  bool edge_arcs = true;      ///< search every hull edge's arc of supporting normals (O'Rourke)
  double certify_tol = 1e-6;  ///< relative gap proved by branch and bound on the arcs (0: skip)
  std::uint64_t max_work = 400000000;             ///< budget of work units (see the header comment)
  MinBoxSearch search = MinBoxSearch::automatic;  ///< with edge_arcs: which branch and bound
};

/// The minimum-volume enclosing box found (see the header comment for its guarantee).
template <Real T>
struct MinBoxResult {
  Status status = Status::empty_input;
  OrientedBox<T, 3> box{};
  T volume = T(0);
  std::size_t candidates = 0;  ///< normals at which f was evaluated (directions + arc points)
  std::size_t arcs = 0;        ///< hull edges whose arc of supporting normals was searched
  bool certified = false;      ///< proved: no enclosing box has volume < (1 - certify_tol) * volume
};

/// A minimum-volume box enclosing `points` (see the header comment).
template <Real T>
[[nodiscard]] MinBoxResult<T> min_box(std::span<const Vec3<T>> points,
                                      const MinBoxOptions& options = {});

/// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] MinBoxResult<range_scalar_t<R>> min_box(const R& points,
                                                      const MinBoxOptions& options = {}) {
  return min_box(point_span(points), options);
}

extern template MinBoxResult<float> min_box<float>(std::span<const Vec3<float>>,
                                                   const MinBoxOptions&);
extern template MinBoxResult<double> min_box<double>(std::span<const Vec3<double>>,
                                                     const MinBoxOptions&);

}  // namespace locus
