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
//     Bound: the arc of edge e is n(t) = cos(t) a + sin(t) b, a rotation about the pole a x b
//     (the edge direction, perpendicular to every n(t)). The width along n(t),
//     W(t) = min over vertices v of n(t) . (p_e - v), is a minimum of sinusoids that are >= 0
//     on the arc, hence concave: on an interval it is >= the chord of its end values. Every
//     frame at t is a frame at an end t' rotated by d = |t - t'| about the pole, so the
//     rectangle area A(t) >= A(t') k^2 for the factor k of either argument:
//     - chords: for a direction x at t' with extreme vertices p, q (width(x) = x . (q - p)),
//       width(R x) >= (R x) . (q - p) >= width(x) (1 - d^2/2 sec - d tan), where sec =
//       |q - p| / width(x) and tan = |(q - p) . n(t')| / width(x) (a rotation about an axis
//       perpendicular to n only tilts x towards n to first order); the largest ratios over all
//       x come from the rotating calipers (at the edge normals of the projection);
//     - Lipschitz: rotating turns the sides u, v by 2 sin(d/2) |sin| and |cos| of their angle
//       to the pole, changing each width by at most that times D (a diameter bound of the
//       hull's projection along the pole), and every width is >= L (twice the distance from
//       the vertex centroid to the nearest facet plane): k = 1 / (1 + d D / (sqrt(2) L)).
//     The interval is cut in 8 parts, each bounded by its smaller chord width times the larger
//     of the two ends' area bounds; the arc ends' normal errors m widen every distance by m.
//     The chord factor makes the loss second order for smooth, round sets (tan is about the
//     vertex spacing): 10^5 points in a ball need ~7000 evaluations instead of 5.6 10^4.
//  3'. hulls whose facet pass alone would take half of max_work (e.g. 10^5 points on a
//     sphere: 2 10^5 facets), or search = regions, replace steps 2-3 (after 64 facets) by a
//     best-first branch and bound over regions of normals: squares of the cube faces +x, +y,
//     +z in gnomonic coordinates (f(-n) = f(n)), split in four; a region of angular radius r
//     around n0 has f >= W(n0) A(n0) times the chord (or Lipschitz) factors of W and A for
//     rotations by r (every frame with a normal in it is a frame at n0 rotated by at most r
//     about an axis perpendicular to n0). Such a
//     set's f is flat (10^5 points on a sphere: within ~10^-4 of the minimum everywhere), a
//     proof would take ~5 10^5 evaluations; when the regions left predict more work than the
//     budget has left (each about (r / r')^2 evaluations, r' the radius where the first-order
//     loss of its bound drops below its gap, at most 1024), the search stops (checked every
//     512 evaluations once a sixteenth of max_work is spent) as if out of budget
//     (limit_exceeded), evaluates facet normals in a spread (stride) order with up to an
//     eighth of max_work (f's local minima lie on the arcs, often at facet normals, rarely at
//     region centres), and returns the best box of descents from the 8 best frames found.
//     Evaluating f: the projection's hull vertices are silhouette vertices (an incident facet
//     facing n and one facing away, undecided signs counting as both); the edges are grouped
//     in cells of nearby facet normals (a cube map on the Gauss sphere, cells of ~2 edges, or
//     ~16 on hulls of over 16384 edges, in blocks of 4 x 4 cells) with bounding cones, so
//     only blocks and cells whose cone meets the plane n^perp are visited, and the edges'
//     facet normals are stored in float next to them (with their rounding in the error
//     bound); the 2D hull of those vertices and rotating calipers give the rectangle, support
//     ascents over the vertex graph (started from the cube-map square of n) the width.
// Guarantee: never worse than the best facet-flush box (exact up to rounding) unless the
// facet pass is replaced by regions (3'); when `certified` is true, no enclosing box of the
// point set has volume below (1 - certify_tol) * volume (up to the rounding of the evaluated f
// values, of the chord ratios and of the hull vertices relative to the first). A sliver facet
// whose rounded normal is not trusted (sine of its angle < 1e-8, e.g. from a point that
// rounding moved a hair off a hull edge) leaves its arcs unsearched and the result
// uncertified (the regions then use the chord factors only: L is not a bound). This replaces O'Rourke's exact event sweep over the smooth pieces of f (and
// Jylanki's 2015 enumeration of edge triples, itself only conjectured optimal). Tests compare
// with dense orientation searches refined by descent and the closed-form regular tetrahedron
// (minimum box = the cube of its edges, no face flush with a facet).
//
// Exactness: the hull and the 2D hulls of the projections are exact for the rounded projected
// points; caliper steps (a near tie can only shrink an extent by rounding), normals,
// projections, extents and volume are rounded constructions
// (double, then T). Every input point lies inside the box up to a few ulps of the set's scale
// (the returned box is always refitted over every hull vertex).
//
// Result: status, box (axes orthonormal and right-handed), volume, candidates (normals at which
// f was evaluated), arcs (hull edges whose arc was searched).
// Degenerate input: all points equal -> ok, zero box at the point; collinear -> ok, a box of
// zero width and height along the segment; coplanar -> ok, the minimum-area rectangle in the
// plane with extent[2] = 0 (volume 0). Empty -> empty_input; NaN/Inf -> non_finite_input.
// Budget: max_work bounds the work of the evaluations (blocks, cells, edges and vertices
// visited; default 4 10^8, a few seconds). When the first 64 facets show that the facet pass
// alone would exceed it without edge_arcs, the facets are visited in a spread (stride) order.
// When it runs out (or the regions predict so, 3'), the best box so far (descended) is
// returned with Status::limit_exceeded and certified = false (it still encloses every point).
// Cost: hull + (F + evaluations) * (visited cells and edges + silhouette log silhouette); the
// evaluations are F facet normals plus the branch and bound's (a few per arc on box-like and
// round sets). 10^5 points: cuboid (181 hull vertices) ~1000 evaluations, ellipsoid (1400)
// ~3700, ball (1400) ~6600, all certified; sphere (10^5 vertices) ~2700 region evaluations,
// stopped as hopeless, then ~5000 facet normals (2 10^4 points on a sphere: arcs, ~6 10^4
// evaluations, certified).

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
  std::uint64_t max_work = 400000000;  ///< budget of work units (see the header comment)
  MinBoxSearch search = MinBoxSearch::automatic;  ///< with edge_arcs: which branch and bound
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
