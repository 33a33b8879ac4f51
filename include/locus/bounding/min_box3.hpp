// SPDX-License-Identifier: BSL-1.0
#pragma once
// Minimum-volume enclosing box of a 3D point set; CAPABILITIES row cg.minbox (3D part); book
// section 13.10.2.
//
// Method: O'Rourke ("Finding minimal enclosing boxes", 1985) showed that a minimum-volume box
// of a convex polyhedron has two adjacent faces each flush with a hull edge. Take one of them:
// its outward normal n is perpendicular to a hull edge and supports the hull along it, i.e. n
// lies on that edge's arc of the Gauss sphere (between the normals of the edge's two facets);
// and for a fixed n the best box is the minimum-area rectangle of the projection onto the
// plane perpendicular to n (whose side is then flush with a projected hull edge, O'Rourke's
// second face). So the minimum volume is exactly min over hull edges e, over n on arc(e), of
// f(n) = (width of the hull along n) * (minimum rectangle area of the projection). Steps:
//  1. the exact convex hull (hull/hull3.hpp; coplanar facets are triangulated there and
//     collinear / in-facet points are not vertices; an edge between two coplanar triangles has
//     a one-point arc, the facet normal, and is skipped);
//  2. the previous candidate search, kept as a floor: the normal of every hull facet and, when
//     the hull has at most max_pair_edges edges, the cross product of every pair of hull edge
//     directions; f by rotating calipers on the projection (bounding/min_rect2.hpp); then a
//     derivative-free descent over small rotations (refine);
//  3. (edge_arcs) the one-parameter minimisation over n on arc(e) for every hull edge: f
//     sampled every <= 0.05 rad along the arc (both ends, the facet normals, included), each
//     sampled local minimum refined by golden-section search on its bracket to 1e-9 rad; the
//     descent of step 2 is rerun from the result when it improved;
//  4. (certify_tol > 0) a proof of optimality by branch and bound over every arc: with R the
//     radius of the hull about a centre, turning the best frame at n' by the angle d to n
//     changes each width by <= 2 R d, so f(n) >= f(n') - ((2R + 2Rd)^3 - (2R)^3); arc
//     intervals are halved until this lower bound is >= (1 - certify_tol) * best. Arcs are
//     widened by 1e-7 rad at both ends to cover the rounding of the facet normals; a sliver
//     facet whose rounded normal is not trusted (sine of its angle < 1e-8, e.g. from a point
//     that rounding moved a hair off a hull edge) leaves its arcs unsearched and the result
//     uncertified (a far-from-origin set of tiny extent can also defeat the 1e-7 margin).
// Guarantee: never worse than the best facet-flush box (exact up to rounding) nor than the
// previous candidate search; when `certified` is true, no enclosing box of the point set has
// volume below (1 - certify_tol) * volume (up to the rounding of the evaluated f values). The
// branch and bound replaces O'Rourke's exact event sweep over the smooth pieces of f (and
// Jylanki's 2015 enumeration of edge triples, itself only conjectured optimal). It is cheap when
// the minimum is a kink of f (more contacts: the usual case); a smooth, flat minimum costs about
// sqrt(certify_tol) / (certify_tol * V / R^3) evaluations, and when the work budget runs out the
// result is returned with Status::limit_exceeded and certified = false. Tests compare with
// dense orientation searches and the closed-form regular tetrahedron (minimum box = the cube of
// its edges, no face flush with a facet).
//
// Exactness: the hull and the 2D hulls/calipers of the projections are exact for the rounded
// projected points; normals, projections, extents and volume are rounded constructions
// (double, then T). Every input point lies inside the box up to a few ulps of the set's scale.
//
// Result: status, box (axes orthonormal and right-handed), volume, candidates (orientations
// evaluated by calipers), arcs (hull edges whose arc was searched).
// Degenerate input: all points equal -> ok, zero box at the point; collinear -> ok, a box of
// zero width and height along the segment; coplanar -> ok, the minimum-area rectangle in the
// plane with extent[2] = 0 (volume 0). Empty -> empty_input; NaN/Inf -> non_finite_input.
// Budget: max_work bounds the number of projected vertices over all candidates, descent and arc
// points (default 4 10^8); when it runs out the best box so far is returned with
// Status::limit_exceeded (it still encloses every point).
// Cost: hull + O(C h log h) for C orientations and h hull vertices (C ~ 2h facets, E^2 edge
// pairs when E <= max_pair_edges, and per edge about phi / 0.05 + 1 samples plus ~40 golden
// steps per sampled local minimum, phi = the edge's exterior dihedral angle).

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
  bool edge_arcs = true;  ///< search every hull edge's arc of supporting normals (O'Rourke)
  double certify_tol = 1e-6;  ///< relative gap proved by branch and bound on the arcs (0: skip)
  std::uint64_t max_work = 400000000;  ///< budget of projected vertices (see the header comment)
};

/// The minimum-volume enclosing box found (see the header comment for its guarantee).
template <class T>
struct MinBoxResult {
  Status status = Status::empty_input;
  OrientedBox<T, 3> box{};
  T volume = T(0);
  std::size_t candidates = 0;  ///< orientations evaluated by calipers (directions + arc points)
  std::size_t arcs = 0;        ///< hull edges whose arc of supporting normals was searched
  bool certified = false;  ///< proved: no enclosing box has volume < (1 - certify_tol) * volume
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
