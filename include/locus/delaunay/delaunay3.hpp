// SPDX-License-Identifier: BSL-1.0
#pragma once
// 3D Delaunay tetrahedralization: incremental Bowyer-Watson insertion with every decision by an
// exact predicate (orient3d, insphere of core/predicates.hpp) and a symbolic perturbation that
// makes the output unique. CAPABILITIES row cg.delaunay3; book section 13.8, figure 13.52.
//
// Algorithm (Delaunay3Method::incremental, the default). The points are inserted in a biased
// randomized order (BRIO: a fixed-seed shuffle, then rounds of geometrically growing size, each
// sorted along a 3D Hilbert curve over the bounding box), so consecutive points are close. The
// outside of the hull is closed by "ghost" tetrahedra sharing a vertex at infinity, so points
// outside the hull are inserted by the same code. Each point is located by a visibility walk
// (exact orient3d) from a tetrahedron of the previous point; the tetrahedra in conflict with it
// (the point strictly inside their perturbed circumsphere; for a ghost on hull face abc: the
// point strictly beyond the plane abc, or on it and in conflict with the real tetrahedron under
// abc) are collected by a search over the adjacency (Bowyer-Watson "cavity"), removed, and the
// cavity's boundary faces are joined to the new point.
//
// Symbolic perturbation. Cospherical input (grids, points on a sphere) has many Delaunay
// tetrahedralizations. Every insphere test that is exactly zero is decided as if point q were
// lifted to |q|^2 + eps_q on the paraboloid, eps_q > 0 infinitesimal and larger for
// lexicographically larger points (x, then y, then z): the sign is then the sign of one of the
// orient3d cofactors, never zero (Edelsbrunner & Muecke's Simulation of Simplicity applied to
// the lifting map). The output is therefore the unique Delaunay tetrahedralization of the
// perturbed points, which is a Delaunay tetrahedralization of the given points: no input point
// lies strictly inside any tetrahedron's circumsphere. It does not depend on the input order
// (a permuted input gives the same tetrahedra) and both methods below return the same set.
//
// Second method (Delaunay3Method::lifted_hull): the book's construction - lift every point p to
// (p, |p|^2) on the paraboloid in 4D; the lower convex hull's facets project to the Delaunay
// tetrahedra. Computed as a 4D convex hull in its own right (beneath-beyond with outside sets,
// as in Qhull): the lifted points are inserted in a fixed-seed random order (no spatial sort, no
// walk), each uninserted point is kept in the outside set of one facet it sees, the facets a new
// point sees are found by a search from that facet, replaced by the cone from the point over
// their horizon, and the points of the removed facets are re-assigned to the new facets (with an
// exact scan of all facets as the fallback). The upper side is closed by a point at vertical
// infinity, so the facets through it are the 3D hull faces. orient4d of lifted points is the
// insphere determinant, so every decision is the exact (perturbed) insphere or orient3d. The
// facets through the point at infinity are seen from p when p is strictly beyond their hull face,
// or on its plane and the lower facet under that face is seen. Duplicates are removed first (the
// smallest index is kept). O(n log n) expected for random input, O(n^2) worst; about 5x slower
// than the incremental method (10^4 uniform points: 0.22 s vs 0.04 s): an independent second
// algorithm that the tests compare against.
//
// Coplanar input (dimension 2). Both methods add one synthetic point e off the plane (a copy of
// a first point with one coordinate changed) and tetrahedralize; every cell then has e as a
// vertex and its face opposite e is a Delaunay triangle of the plane: the ball through a, b, c, e
// meets the plane in the circumdisk of a, b, c, so insphere(a, b, c, e, d) is the exact in-plane
// incircle test of d, in any tilted plane, with no projection (a coordinate projection is affine
// and does not preserve circles). The perturbation then orders the in-plane ties by the
// lexicographic rank of the points (e's own term vanishes), so the planar result is the unique
// Delaunay triangulation of the perturbed points in their plane, independent of where e is and
// of the input order. Exact under the same ranges as insphere (e's changed coordinate is half
// the original one, or 1 when that is 0).
//
// Output (Delaunay3Result):
//   tetrahedra[t].vertices   input point indices with orient3d(v0, v1, v2, v3) > 0 (exactly).
//   tetrahedra[t].neighbors  neighbors[i] is the tetrahedron sharing the face opposite
//                            vertices[i], or -1 when that face is on the hull.
//   Face i of a tetrahedron is (v[a], v[b], v[c]) with (a, b, c) = kDelaunay3Face[i]; it is
//   ordered so that orient3d(face, v[i]) > 0: the tetrahedron is on the side its normal
//   (b - a) x (c - a) points to.
//   hull                     the boundary faces, each with its outward normal (b - a) x (c - a)
//                            (the convention of hull/hull3.hpp): a closed triangulated surface.
//                            Points on the hull boundary that are not extreme are vertices too.
//   duplicate_of[i]          i for a point that is a vertex, else the index of the vertex with
//                            exactly the same coordinates: of equal points the smallest index
//                            is kept, by both methods and whatever the insertion order.
//   dimension                3 for a real tetrahedralization; 2 when all points are coplanar,
//                            1 collinear, 0 all equal (then tetrahedra and hull are empty and
//                            duplicate_of is still filled); -1 for empty or bad input.
//   triangles                dimension 2 only: the Delaunay triangulation of the points in their
//                            plane (input indices). All triangles face the same way: their normal
//                            (b - a) x (c - a) has a positive component along the first axis
//                            (x, then y, then z) not parallel to the plane (counter-clockwise
//                            seen from +z for a plane z = const). They cover the points' convex
//                            polygon; points on its boundary are vertices.
//   chain                    dimension 1: the distinct points in order along their line
//                            (lexicographic order, x then y then z), consecutive ones forming
//                            the segments; dimension 0: the one kept point.
// Lower-dimensional output is data: the status stays ok.
//
// Queries on a result (free functions, also members of Delaunay3): locate(p) walks from a start
// tetrahedron toward p (visibility walk, exact orient3d, at most max_steps steps, then an exact
// scan of all tetrahedra) and reports inside / on_face / on_edge / on_vertex / outside (strictly
// outside the hull, with a hull face p lies beyond). nearest_vertex(p) locates p and then
// descends greedily over Delaunay edges to strictly closer vertices (exact distance comparison);
// on a Delaunay tetrahedralization that ends at a nearest vertex (the lifted points form a convex
// polytope whose edges are Delaunay edges, and |v - p|^2 is a linear function on it up to a
// constant, so a vertex with no improving edge is a minimum). Both are O(n^(1/3)) expected steps
// for evenly spread points from a far start, O(1) from a near one; no allocation. For results of
// dimension < 3, locate reports empty_input and nearest_vertex scans the kept points.
//
// Incremental use: Delaunay3::insert adds points to a finished tetrahedralization (the same
// walk and cavity code; a batch is Hilbert-sorted first); result() is compacted lazily, once per
// batch of insertions, O(tetrahedra). When the current result has dimension < 3, insert rebuilds
// from all points.
//
// Bad input: any NaN or infinite coordinate gives Status::non_finite_input and an empty result;
// no points gives Status::empty_input; more than 2^26 points gives Status::invalid_input. Every
// loop has a budget: a walk longer than the tetrahedron count falls back to an exact scan, and a
// cavity search longer than the tetrahedron count stops with Status::limit_exceeded (never seen
// on a valid structure).
//
// Exactness: decisions are exact in the ranges stated in core/predicates.hpp (insphere: nonzero
// |coordinates| within about 7e-49 .. 5e58 for double; every float). Outside them the result is
// still a tetrahedralization without crash or hang, but possibly not Delaunay.
//
// Cost: O(n log n) expected for evenly spread points (O(n^2) worst case, e.g. points on a
// moment curve). Memory about 32 bytes per tetrahedron (6.7 n tetrahedra for uniform points)
// plus a sorted copy of the points; the one-call delaunay() converts the internal array to the
// result in place. Exactly cospherical quintuples (grids) are decided, perturbation included,
// by a double evaluation proven exact on small lattices before the adaptive predicate is tried;
// when every input point lies on one small lattice (coordinates k q, q a power of two, extents
// below 512 q: integer grids, voxels) all predicates are exact double determinants without a
// filter. Measured (bench/delaunay/delaunay3_bench.cpp, -O3, CPU time, one run on the shared
// 2-core machine at load 3-6): 10^5 uniform points 0.50 s vs CGAL
// Delaunay_triangulation_3<Epick> 0.72 s; 10^6 points 4.6 s vs 7.7 s; the 50^3 integer grid
// 0.69 s vs 1.27 s (same cell counts as CGAL in all three). Peak heap growth (every malloc
// counted): 10^6 points 294 MB vs CGAL's 526 MB; grid 37 MB vs 58 MB.

#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// Corner indices of face i (the face opposite corner i) of a tetrahedron, ordered so that
/// corner i lies on the positive orient3d side of the face.
inline constexpr std::array<std::array<int, 3>, 4> kDelaunay3Face = {
    {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}}};

/// One tetrahedron of a Delaunay3Result.
struct Delaunay3Cell {
  std::array<std::uint32_t, 4> vertices;  ///< input indices, orient3d(v0, v1, v2, v3) > 0
  std::array<std::int32_t, 4> neighbors;  ///< across the face opposite vertices[i]; -1: hull
};

/// The result of a 3D Delaunay tetrahedralization (see the top of delaunay3.hpp).
struct Delaunay3Result {
  Status status = Status::empty_input;
  int dimension = -1;                              ///< 3, 2, 1, 0, or -1 (nothing)
  std::vector<Delaunay3Cell> tetrahedra;           ///< positively oriented, with adjacency
  std::vector<std::array<std::uint32_t, 3>> hull;  ///< boundary faces, outward normals
  std::vector<std::uint32_t> duplicate_of;         ///< per input point: itself or the kept point
  std::size_t duplicate_count = 0;                 ///< number of i with duplicate_of[i] != i
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< dimension 2: in-plane Delaunay
  std::vector<std::uint32_t> chain;                     ///< dimension 1 (or 0): sorted points

  [[nodiscard]] std::size_t tetrahedron_count() const noexcept { return tetrahedra.size(); }
};

/// Where a point lies relative to a tetrahedralization.
enum class Location3 : std::uint8_t {
  outside,    ///< strictly outside the hull: beyond hull face `face` of `tetrahedron`
  inside,     ///< strictly inside `tetrahedron`
  on_face,    ///< in the relative interior of face `face` of `tetrahedron`
  on_edge,    ///< in the relative interior of the edge (corners edge[0], edge[1])
  on_vertex,  ///< equal to corner `corner` of `tetrahedron`
};

/// The result of locate (3D).
struct Locate3Result {
  Status status = Status::empty_input;  ///< ok; empty_input (no tetrahedra); non_finite_input;
                                        ///< invalid_input (an index of the result is out of range)
  Location3 location = Location3::outside;
  std::int32_t tetrahedron = -1;       ///< a tetrahedron of the result, -1 when not found
  int face = -1;                       ///< on_face, outside: face index (opposite vertices[face])
  std::array<int, 2> edge = {-1, -1};  ///< on_edge: the edge's two corners, increasing
  int corner = -1;                     ///< on_vertex: the corner equal to the point
  std::size_t steps = 0;               ///< tetrahedra visited by the walk
  bool scanned = false;                ///< the walk ran out of steps and an exact scan decided
};

/// The result of nearest_vertex (3D).
struct NearestVertex3Result {
  Status status = Status::empty_input;  ///< ok; empty_input; non_finite_input; invalid_input
  std::uint32_t vertex = 0;       ///< input index of a nearest vertex (a kept point)
  std::int32_t tetrahedron = -1;  ///< a tetrahedron with that vertex (-1 for dimension < 3)
};

/// Algorithm used by delaunay (3D).
enum class Delaunay3Method : std::uint8_t {
  incremental,  ///< Bowyer-Watson with BRIO/Hilbert order and walking (fast)
  lifted_hull,  ///< 4D convex hull of the lifted points, beneath-beyond (second algorithm)
};

/// Options of delaunay (3D).
struct Delaunay3Options {
  Delaunay3Method method = Delaunay3Method::incremental;
};

/// The perturbed insphere predicate used by both methods: the sign of insphere(a, b, c, d, e)
/// (positive iff e is strictly inside the sphere through a, b, c, d, given
/// orient3d(a, b, c, d) > 0), with an exact zero decided by the lexicographic perturbation of
/// the header comment. Never zero when orient3d(a, b, c, d) != 0 and e differs from a, b, c, d.
template <Real T>
[[nodiscard]] Sign insphere_perturbed(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                      const Vec3<T>& d, const Vec3<T>& e) noexcept;

/// Delaunay tetrahedralization of `points` (one call over Delaunay3, or the lifted-hull oracle).
template <Real T>
[[nodiscard]] Delaunay3Result delaunay(std::span<const Vec3<T>> points,
                                       const Delaunay3Options& options = {});

/// Walks from tetrahedron `start` of `dt` toward p and reports where p lies (see the top of
/// delaunay3.hpp). max_steps = 0 means the tetrahedron count plus 64, which a walk in a Delaunay
/// tetrahedralization never exceeds (it visits no tetrahedron twice); past max_steps an exact
/// scan decides. `points` are the points `dt` was computed from.
template <Real T>
[[nodiscard]] Locate3Result locate(const Delaunay3Result& dt, std::span<const Vec3<T>> points,
                                   const Vec3<T>& p, std::int32_t start = 0,
                                   std::size_t max_steps = 0) noexcept;

/// A vertex of `dt` nearest to p (exact comparisons): locate from `start`, then greedy descent
/// over Delaunay edges. Ties: one of the nearest. Dimension < 3: a scan of the kept points.
template <Real T>
[[nodiscard]] NearestVertex3Result nearest_vertex(const Delaunay3Result& dt,
                                                  std::span<const Vec3<T>> points, const Vec3<T>& p,
                                                  std::int32_t start = 0) noexcept;

/// Reusable 3D Delaunay tetrahedralizer: keeps its buffers between calls, accepts further
/// points after a tetrahedralization, and answers locate / nearest-vertex queries.
template <Real T>
class Delaunay3 {
 public:
  /// Tetrahedralizes `points` (copied), replacing any previous state.
  const Delaunay3Result& compute(std::span<const Vec3<T>> points);
  /// The same for a flat array x0, y0, z0, x1, ... of n points.
  const Delaunay3Result& compute(const T* xyz, std::size_t n);

  /// Adds one point (index = points().size() before the call) and restores the Delaunay
  /// property: O(1) expected near the previously inserted point. When the current result has
  /// dimension < 3 everything is rebuilt. A non-finite point is refused (non_finite_input,
  /// nothing added).
  Status insert(const Vec3<T>& p);
  /// Adds several points (indices continue from points().size()), inserted along a Hilbert
  /// curve for short walks. Refused as a whole (non_finite_input) if any point is not finite.
  Status insert(std::span<const Vec3<T>> points);

  /// The tetrahedralization of every point so far (compacted lazily after insert()).
  const Delaunay3Result& result();
  /// Moves the result out (the internal arrays become the result without a copy) and resets
  /// the object.
  Delaunay3Result take_result();

  /// locate() on result(), starting from a tetrahedron of the last inserted point.
  [[nodiscard]] Locate3Result locate(const Vec3<T>& p, std::size_t max_steps = 0);
  /// nearest_vertex() on result(), starting from a tetrahedron of the last inserted point.
  [[nodiscard]] NearestVertex3Result nearest_vertex(const Vec3<T>& p);

  [[nodiscard]] std::span<const Vec3<T>> points() const noexcept { return points_; }

 private:
  struct Boundary {  // a face of the cavity: vertices seen from inside, and the cell outside
    std::uint32_t a, b, c;
    std::int32_t outside;
  };

  void run();
  void compact(bool in_place);
  void planar_triangles(bool in_place);
  void lower_dimensional(int dimension);
  std::uint32_t walk(std::uint32_t v, std::uint32_t start, std::uint32_t* duplicate) noexcept;
  std::uint32_t scan(std::uint32_t v, std::uint32_t* duplicate) noexcept;
  bool in_conflict(std::uint32_t t, std::uint32_t v) const noexcept;
  bool insert_vertex(std::uint32_t v);
  void link_around(std::span<const std::uint32_t> cells, std::uint32_t apex);
  void edges_begin(std::size_t entries);
  std::uint32_t edge_match(std::uint32_t u, std::uint32_t v, std::uint32_t code) noexcept;
  void glue(std::uint32_t code, std::uint32_t other) noexcept;

  // The one-call function converts the internal arrays into the result in place.
  template <Real U>
  friend Delaunay3Result delaunay(std::span<const Vec3<U>>, const Delaunay3Options&);

  std::vector<Vec3<T>> points_;  // as given
  std::vector<Vec3<T>> sorted_;  // internal vertex k = points_[orig_[k]], BRIO/Hilbert order
  std::vector<std::uint32_t> orig_;
  std::vector<Delaunay3Cell> cells_;  // neighbors hold 4 * cell + face while building
  std::vector<std::uint32_t> mark_;   // per cell: 2 * epoch (in cavity), 2 * epoch + 1 (not)
  std::uint32_t epoch_ = 0;
  std::vector<std::uint32_t> stack_, cavity_, fresh_, free_;
  std::vector<Boundary> boundary_;
  struct EdgeSlot {  // directed edge u -> v of the face `code` (4 * cell + face)
    std::uint32_t u, v, code, gen;
  };
  std::vector<EdgeSlot> edge_table_;
  std::uint32_t edge_gen_ = 0;
  int edge_bits_ = 8;
  std::vector<std::uint64_t> keys_, keys_tmp_;
  std::uint32_t last_ = 0;
  std::int32_t last_out_ = 0;  // a result tetrahedron of the last inserted point (query start)
  std::uint32_t walk_rng_ = 0x2545F491u;
  std::uint32_t apex_ = 0;  // dimension 2: the synthetic point off the plane (internal index)
  bool apex_flip_ = false;  // dimension 2: reverse the faces opposite the apex
  bool dirty_ = false;      // insert() ran since the last compaction
  bool lattice_ = false;    // all points on a small lattice: exact double predicates
  int dimension_ = -1;
  Status status_ = Status::empty_input;
  Delaunay3Result result_;
};

/// The same for a vector of points.
/// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] Delaunay3Result delaunay(const R& points, const Delaunay3Options& options = {}) {
  return delaunay(point_span(points), options);
}
template <PointRange3 R>
[[nodiscard]] Locate3Result locate(const Delaunay3Result& dt, const R& points,
                                   const range_point_t<R>& p, std::int32_t start = 0,
                                   std::size_t max_steps = 0) noexcept {
  return locate(dt, point_span(points), p, start, max_steps);
}
template <PointRange3 R>
[[nodiscard]] NearestVertex3Result nearest_vertex(const Delaunay3Result& dt, const R& points,
                                                  const range_point_t<R>& p,
                                                  std::int32_t start = 0) noexcept {
  return nearest_vertex(dt, point_span(points), p, start);
}

extern template class Delaunay3<float>;
extern template class Delaunay3<double>;
extern template Delaunay3Result delaunay<float>(std::span<const Vec3<float>>,
                                                const Delaunay3Options&);
extern template Delaunay3Result delaunay<double>(std::span<const Vec3<double>>,
                                                 const Delaunay3Options&);
extern template Locate3Result locate<float>(const Delaunay3Result&, std::span<const Vec3<float>>,
                                            const Vec3<float>&, std::int32_t, std::size_t) noexcept;
extern template Locate3Result locate<double>(const Delaunay3Result&, std::span<const Vec3<double>>,
                                             const Vec3<double>&, std::int32_t,
                                             std::size_t) noexcept;
extern template NearestVertex3Result nearest_vertex<float>(const Delaunay3Result&,
                                                           std::span<const Vec3<float>>,
                                                           const Vec3<float>&,
                                                           std::int32_t) noexcept;
extern template NearestVertex3Result nearest_vertex<double>(const Delaunay3Result&,
                                                            std::span<const Vec3<double>>,
                                                            const Vec3<double>&,
                                                            std::int32_t) noexcept;
extern template Sign insphere_perturbed<float>(const Vec3<float>&, const Vec3<float>&,
                                               const Vec3<float>&, const Vec3<float>&,
                                               const Vec3<float>&) noexcept;
extern template Sign insphere_perturbed<double>(const Vec3<double>&, const Vec3<double>&,
                                                const Vec3<double>&, const Vec3<double>&,
                                                const Vec3<double>&) noexcept;

}  // namespace locus
