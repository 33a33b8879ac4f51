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
// tetrahedra. Evaluated by brute force: a non-degenerate quadruple is a lower facet iff every
// other lifted point lies above its hyperplane, i.e. the perturbed insphere test is negative
// for every other point. O(n^5) time: for small n (at most 64 points, else invalid_input) and as
// an independent oracle of the incremental method.
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
//                            exactly the same coordinates.
//   dimension                3 for a real tetrahedralization; 2 when all points are coplanar,
//                            1 collinear, 0 all equal (then tetrahedra and hull are empty and
//                            duplicate_of is still filled); -1 for empty or bad input.
// Lower-dimensional output is data: the status stays ok.
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
// result in place. Exactly cospherical quintuples (grids) are decided by a double evaluation
// proven exact on small lattices before the adaptive predicate is tried. Measured
// (bench/delaunay/delaunay3_bench.cpp, -O3, CPU time on a loaded shared 2-core machine, so
// absolute times are inflated; the ratios held over repeated runs): 10^5 uniform points
// 0.52-0.55 s vs CGAL Delaunay_triangulation_3<Epick> 0.68-0.76 s; 10^6 points 5.6 s vs 8.0 s;
// the 50^3 integer grid 1.2-1.3 s vs 1.3-1.4 s (same cell counts as CGAL in all three). Peak
// memory above the input, 10^6 points: 285 MB vs CGAL's 550 MB.

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

  [[nodiscard]] std::size_t tetrahedron_count() const noexcept { return tetrahedra.size(); }
};

/// Algorithm used by delaunay (3D).
enum class Delaunay3Method : std::uint8_t {
  incremental,  ///< Bowyer-Watson with BRIO/Hilbert order and walking (fast, any n)
  lifted_hull,  ///< lower hull of the lifted points by brute force, O(n^5), n <= 64 (oracle)
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

/// Reusable 3D Delaunay tetrahedralizer: keeps its buffers between calls.
template <Real T>
class Delaunay3 {
 public:
  /// Tetrahedralizes `points` (copied), replacing any previous state.
  const Delaunay3Result& triangulate(std::span<const Vec3<T>> points);
  /// The same for a flat array x0, y0, z0, x1, ... of n points.
  const Delaunay3Result& triangulate(const T* xyz, std::size_t n);

  /// The last result.
  [[nodiscard]] const Delaunay3Result& result() const noexcept { return result_; }
  /// Moves the result out (the internal arrays become the result without a copy) and resets
  /// the object.
  Delaunay3Result take_result();

  [[nodiscard]] std::span<const Vec3<T>> points() const noexcept { return points_; }

 private:
  struct Boundary {  // a face of the cavity: vertices seen from inside, and the cell outside
    std::uint32_t a, b, c;
    std::int32_t outside;
  };

  void run();
  void compact(bool in_place);
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
  std::uint32_t walk_rng_ = 0x2545F491u;
  int dimension_ = -1;
  Status status_ = Status::empty_input;
  Delaunay3Result result_;
};

/// The same for a vector of points.
template <Real T>
[[nodiscard]] inline Delaunay3Result delaunay(const std::vector<Vec3<T>>& points,
                                              const Delaunay3Options& options = {}) {
  return delaunay(std::span<const Vec3<T>>(points), options);
}

extern template class Delaunay3<float>;
extern template class Delaunay3<double>;
extern template Delaunay3Result delaunay<float>(std::span<const Vec3<float>>,
                                                const Delaunay3Options&);
extern template Delaunay3Result delaunay<double>(std::span<const Vec3<double>>,
                                                 const Delaunay3Options&);
extern template Sign insphere_perturbed<float>(const Vec3<float>&, const Vec3<float>&,
                                               const Vec3<float>&, const Vec3<float>&,
                                               const Vec3<float>&) noexcept;
extern template Sign insphere_perturbed<double>(const Vec3<double>&, const Vec3<double>&,
                                                const Vec3<double>&, const Vec3<double>&,
                                                const Vec3<double>&) noexcept;

}  // namespace locus
