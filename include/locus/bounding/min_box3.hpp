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
//     a one-point arc, the facet normal);
//  2. f at every facet normal (the ends of the arcs, and the facet-flush boxes) and, when the
//     hull has at most max_pair_edges edges, at the cross product of every pair of hull edge
//     directions; then a derivative-free descent over small rotations (refine);
//  3. (edge_arcs) a best-first branch and bound over every arc (angle intervals, f evaluated
//     at their ends, the interval of smallest lower bound split first) until every interval's
//     lower bound is >= (1 - certify_tol) * best (certify_tol = 0: a search to 1e-3, not a
//     proof); the descent is rerun from the result when it improved.
//     Bound: the arc of edge e is n(t) = cos(t) a + sin(t) b, a rotation about the pole a x b.
//     The width along n(t), W(t) = min over vertices v of n(t) . (p_e - v), is a minimum of
//     sinusoids that are >= 0 on the arc, hence concave: on an interval it is >= the smaller
//     end value. For the rectangle area A(t): rotating the best frame at t back to an end t'
//     (angle d) turns its sides u, v by 2 sin(d/2) |sin| and |cos| of their angle to the pole,
//     changing each width by at most that times D (a diameter bound of the hull's projection
//     along the pole), so A(t') <= (w_u + d s D)(w_v + d c D) and, every width being >= L
//     (twice the distance from the vertex centroid to the nearest facet plane),
//     A(t) >= A(t') / (1 + d D / (sqrt(2) L))^2. With the arc ends' normal errors m (the
//     rounded cross products) the interval is widened by m on every side.
//     Evaluating f: the projection's hull vertices are silhouette vertices (an incident facet
//     facing n and one facing away, undecided signs counting as both); the edges are grouped
//     in cells of nearby facet normals (a cube map on the Gauss sphere) with a bounding cone, so
//     only cells whose cone meets the plane n^perp are visited; the 2D hull of those vertices
//     and rotating calipers give the rectangle, support ascents over the vertex graph the width.
// Guarantee: never worse than the best facet-flush box (exact up to rounding); when `certified`
// is true, no enclosing box of the point set has volume below (1 - certify_tol) * volume (up to
// the rounding of the evaluated f values and of the hull vertices relative to the first). A
// sliver facet whose rounded normal is not trusted (sine of its angle < 1e-8, e.g. from a point
// that rounding moved a hair off a hull edge) leaves its arcs unsearched and the result
// uncertified. This replaces O'Rourke's exact event sweep over the smooth pieces of f (and
// Jylanki's 2015 enumeration of edge triples, itself only conjectured optimal); the bound is
// first order, so a flat f (points on or in a sphere: f varies by ~1% over all normals) needs
// many intervals: ~5 10^4 evaluations for 10^5 points in a ball (1400 hull vertices), while a
// box-like or ellipsoidal set needs few. Tests compare with dense orientation searches refined
// by descent and the closed-form regular tetrahedron (minimum box = the cube of its edges, no
// face flush with a facet).
//
// Exactness: the hull and the 2D hulls/calipers of the projections are exact for the rounded
// projected points; normals, projections, extents and volume are rounded constructions
// (double, then T). Every input point lies inside the box up to a few ulps of the set's scale
// (the returned box is always refitted over every hull vertex).
//
// Result: status, box (axes orthonormal and right-handed), volume, candidates (normals at which
// f was evaluated), arcs (hull edges whose arc was searched).
// Degenerate input: all points equal -> ok, zero box at the point; collinear -> ok, a box of
// zero width and height along the segment; coplanar -> ok, the minimum-area rectangle in the
// plane with extent[2] = 0 (volume 0). Empty -> empty_input; NaN/Inf -> non_finite_input.
// Budget: max_work bounds the work of the evaluations (cells, edges and vertices visited;
// default 4 10^8, a few seconds). When the first 64 facets show that the facet pass alone
// would exceed it (hulls of ~10^5 vertices, e.g. points on a sphere), the facets are visited in
// a spread (stride) order and the arcs are skipped. When it runs out, the best box so far
// (descended) is returned with Status::limit_exceeded and certified = false (it still encloses
// every point).
// Cost: hull + (F + evaluations) * (visited cells and edges + silhouette log silhouette); the
// evaluations are F facet normals plus the branch and bound's (a few per arc on box-like sets;
// see above for flat f). 10^5 points: cuboid (181 hull vertices) ~1800 evaluations, ellipsoid
// (1400) ~10^4, ball (1400) ~5.6 10^4, all certified; sphere (10^5) budget-limited.

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
  bool edge_arcs = true;      ///< search every hull edge's arc of supporting normals (O'Rourke)
  double certify_tol = 1e-6;  ///< relative gap proved by branch and bound on the arcs (0: skip)
  std::uint64_t max_work = 400000000;  ///< budget of work units (see the header comment)
};

/// The minimum-volume enclosing box found (see the header comment for its guarantee).
template <class T>
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

extern template MinBoxResult<float> min_box<float>(std::span<const Vec3<float>>,
                                                   const MinBoxOptions&);
extern template MinBoxResult<double> min_box<double>(std::span<const Vec3<double>>,
                                                     const MinBoxOptions&);

}  // namespace locus
