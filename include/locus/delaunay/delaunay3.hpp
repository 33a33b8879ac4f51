// SPDX-License-Identifier: BSL-1.0
#pragma once
// 3D Delaunay tetrahedralization; CAPABILITIES row cg.delaunay3; book section 13.8, figure 13.52.
// Method (docs/notes/delaunay.md): incremental Bowyer-Watson insertion in BRIO/Hilbert order
// (default) or the book's lower hull of the lifted points (Delaunay3Method::lifted_hull, an
// independent check, slower); every decision is an exact orient3d/insphere (core/predicates.hpp)
// under a symbolic perturbation, so the output is unique, independent of the input order and the
// same for both methods: no input point lies strictly inside any tetrahedron's circumsphere.
// Output (Delaunay3Result; the index layout of docs/notes/api.md, as hull/hull3.hpp):
// tetrahedra[t]: input indices v, orient3d(v0, v1, v2, v3) > 0; adjacency[t][i]: the tetrahedron
// across the face opposite v[i], kNoTetrahedron on the hull. Face i is (v[a], v[b], v[c]) with
// (a, b, c) = kDelaunay3Face[i], so that orient3d(face, v[i]) > 0. hull: the boundary faces,
// outward normal (b - a) x (c - a), non-extreme boundary points included as vertices.
// duplicate_of[i]: i for a vertex, else the smallest index with the same coordinates.
// dimension 3; 2 coplanar (triangles: the in-plane Delaunay triangulation, normals positive along
// the first axis, x then y then z, not parallel to the plane); 1 collinear (chain: the distinct
// points in lexicographic order); 0 all equal (chain: the kept point); -1 empty or bad input.
// Lower-dimensional output is data: the status stays ok.
// Queries: locate(p) (inside / on_face / on_edge / on_vertex / outside) and nearest_vertex(p),
// exact walks, O(n^(1/3)) expected steps, no allocation; for dimension < 3 locate reports
// empty_input and nearest_vertex scans. Delaunay3::insert adds points (rebuilds when dim < 3).
// Bad input: NaN/Inf -> non_finite_input, empty result; no points -> empty_input; more than 2^26
// points -> invalid_input; a cavity search over budget -> limit_exceeded (never seen).
// Exactness: exact within insphere's range (core/predicates.hpp: double |coordinates| about
// 7e-49 .. 5e58, every float); outside it a valid tetrahedralization, possibly not Delaunay.
// Cost: O(n log n) expected (O(n^2) worst, e.g. points on a moment curve); about 32 bytes per
// tetrahedron (6.7 n for uniform points), plus a point copy. Timings: bench/results/delaunay.md.

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

/// adjacency[t][i] of a face on the hull (no tetrahedron beyond it).
inline constexpr std::uint32_t kNoTetrahedron = 0xFFFFFFFFu;

/// The result of a 3D Delaunay tetrahedralization (see the top of delaunay3.hpp).
struct Delaunay3Result {
  Status status = Status::empty_input;
  int dimension = -1;                                    ///< 3, 2, 1, 0, or -1 (nothing)
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;  ///< positively oriented
  std::vector<std::array<std::uint32_t, 4>> adjacency;   ///< across the face opposite v[i]
  std::vector<std::array<std::uint32_t, 3>> hull;        ///< boundary faces, outward normals
  std::vector<std::uint32_t> duplicate_of;  ///< per input point: itself or the kept point
  std::size_t duplicate_count = 0;          ///< number of i with duplicate_of[i] != i
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
  std::uint32_t vertex = 0;             ///< input index of a nearest vertex (a kept point)
  std::int32_t tetrahedron = -1;        ///< a tetrahedron with that vertex (-1 for dimension < 3)
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
  /// Moves the result out and resets the object.
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
  // Cells in the result's types (compact() hands them over in place): vertices (a ghost cell has
  // kGhost at corner 3) and, while building, neighbours as codes 4 * cell + face.
  std::vector<std::array<std::uint32_t, 4>> cell_v_;
  std::vector<std::array<std::uint32_t, 4>> cell_n_;
  std::vector<std::uint32_t> mark_;  // per cell: 2 * epoch (in cavity), 2 * epoch + 1 (not)
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
