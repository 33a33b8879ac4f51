// SPDX-License-Identifier: BSL-1.0
#pragma once
// Minimum-volume enclosing box of a 3D point set; CAPABILITIES row cg.minbox (3D part); book
// section 13.10.2.
//
// Method (stated plainly: a candidate search, not O'Rourke's exact O(n^3) algorithm):
//  1. the exact convex hull (hull/hull3.hpp; coplanar facets and collinear points are handled
//     there, so only extreme points remain);
//  2. candidate directions for one box axis: the normal of every hull facet (coplanar
//     triangles give one plane and are tried once), and, when the hull has at most
//     max_pair_edges edges, the cross product of every pair of hull edge directions (a face
//     parallel to two hull edges);
//  3. for each candidate n the hull vertices are projected onto the plane perpendicular to n and
//     the minimum-area rectangle of the projection is found exactly by rotating calipers
//     (bounding/min_rect2.hpp); volume = rectangle area * extent along n;
//  4. the best box is refined by a derivative-free descent over small rotations (coordinate
//     steps on the three rotation angles, halving the step until 1e-9 rad), which reaches boxes
//     that touch the hull with edges only (O'Rourke's case of two adjacent faces flush with hull
//     edges) when they lie near a candidate.
// Guarantee: the result is the exact minimum (up to rounding) over all boxes having a face flush
// with a hull facet (for each facet the calipers give the best such box), and is never worse
// than that; O'Rourke ("Finding minimal enclosing boxes", 1985) showed that a minimum box has
// two adjacent faces each flush with a hull edge, which need not include a flush facet, so in
// general the result is an upper bound on the minimum, refined locally but not certified
// globally optimal. The tests compare it with a dense search over orientations.
//
// Exactness: the hull and the 2D hulls/calipers of the projections are exact for the rounded
// projected points; normals, projections, extents and volume are rounded constructions
// (double, then T). Every input point lies inside the box up to a few ulps of the set's scale.
//
// Result: status, box (axis[2] = the chosen candidate direction, axes orthonormal and
// right-handed), volume, candidates (how many directions were evaluated).
// Degenerate input: all points equal -> ok, zero box at the point; collinear -> ok, a box of
// zero width and height along the segment; coplanar -> ok, the minimum-area rectangle in the
// plane with extent[2] = 0 (volume 0). Empty -> empty_input; NaN/Inf -> non_finite_input.
// Budget: max_work bounds the number of projected vertices over all candidates (default
// 4 10^8); when it runs out the best box so far is returned with Status::limit_exceeded (it
// still encloses every point).
// Cost: hull + O(C h log h) for C candidate directions and h hull vertices (C ~ 2h facets, plus
// E^2 edge pairs when E <= max_pair_edges).

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/oriented_box.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

namespace locus {

/// Options of min_box.
struct MinBoxOptions {
  std::size_t max_pair_edges = 60;  ///< edge-pair candidates only for hulls with <= this many edges
  bool refine = true;               ///< local descent over rotations from the best candidate
  std::uint64_t max_work = 400000000;  ///< budget of projected vertices (see the header comment)
};

/// The minimum-volume enclosing box found (see the header comment for its guarantee).
template <class T>
struct MinBoxResult {
  Status status = Status::empty_input;
  OrientedBox<T, 3> box{};
  T volume = T(0);
  std::size_t candidates = 0;
};

/// A minimum-volume box enclosing `points` (see the header comment).
template <Real T>
[[nodiscard]] MinBoxResult<T> min_box(std::span<const Vec3<T>> points,
                                      const MinBoxOptions& options = {});

extern template MinBoxResult<float> min_box<float>(std::span<const Vec3<float>>,
                                                   const MinBoxOptions&);
extern template MinBoxResult<double> min_box<double>(std::span<const Vec3<double>>,
                                                     const MinBoxOptions&);

}  // namespace locus
