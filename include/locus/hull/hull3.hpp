// SPDX-License-Identifier: BSL-1.0
#pragma once
// Convex hull of a finite set of 3D points (CAPABILITIES row cg.hull3; book section 13.7.2,
// figures 13.39-13.41).
// Input: a span of Vec3<T> (T = float or double). Output (Hull3Result): a Status, the dimension
// (0..3; -1 when the status is not ok) and, by dimension:
//   3: `triangles`, index triples into the input, counter-clockwise seen from outside (the
//      outward normal is (b - a) x (c - a), so orient3d(a, b, c, p) <= 0 for every input p);
//      `adjacency[t][e]` is the triangle across edge (v[e], v[(e + 1) % 3]) of triangle t. A
//      closed 2-manifold (V - E + F = 2); the vertices are exactly the extreme points; coplanar
//      facets are triangulated (neighbouring triangles may be coplanar).
//   2: `polygon`, the extreme points counter-clockwise in the projection onto the two axes other
//      than `plane_axis`, in cyclic order (its normal has a positive `plane_axis` component).
//   1: `polygon` holds the two end points (lexicographically smaller first).
//   0: `polygon` holds one index.
// `vertices` lists the hull's vertices (sorted indices) in every dimension. Duplicated points
// are represented by their smallest index.
// Exactness: every decision is an exact orient3d / orient2d: the exact hull of the given points
// within orient3d's range (core/predicates.hpp).
// Methods (Hull3Options::method; details: docs/notes/hull.md): quickhull (default; a filter,
// then QuickHull: expected O(n log n), also with every point on the hull); incremental (the
// book's, every face tested: O(n h); used as an oracle); divide_and_conquer (lexicographic
// halves merged by wrapping a band of triangles from a bridge edge, figures 13.40-13.41; a merge
// that meets a coplanarity or a sub-hull of dimension < 3 hulls the two vertex sets
// incrementally instead). All three give the same vertices, and the same triangles wherever no
// four vertices are coplanar.
// Bad input: empty -> Status::empty_input; NaN/Inf -> Status::non_finite_input; more than
// 2^32 - 2 points -> Status::invalid_input. Memory O(n); ConvexHull3 keeps its buffers.

#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/hull/hull2.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// Algorithm used by convex_hull (3D).
enum class Hull3Method : std::uint8_t {
  quickhull,           ///< filter + QuickHull with exact predicates (fastest)
  incremental,         ///< the book's incremental method, O(n h) (oracle)
  divide_and_conquer,  ///< recursive halves merged by wrapping (Preparata-Hong)
};

/// Options of convex_hull (3D).
struct Hull3Options {
  Hull3Method method = Hull3Method::quickhull;
};

/// A 3D convex hull (see the header comment).
struct Hull3Result {
  Status status = Status::empty_input;
  int dimension = -1;                                   ///< 0..3 when ok, -1 otherwise
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< outward, counter-clockwise
  std::vector<std::array<std::uint32_t, 3>> adjacency;  ///< across edge (v[e], v[e+1])
  std::vector<std::uint32_t> polygon;                   ///< dimension 0..2
  int plane_axis = -1;                                  ///< dimension 2: see header
  std::vector<std::uint32_t> vertices;                  ///< sorted hull vertex indices
};

/// Reusable 3D hull builder: keeps its scratch buffers between calls.
template <Real T>
class ConvexHull3 {
 public:
  [[nodiscard]] Hull3Result compute(std::span<const Vec3<T>> points,
                                    const Hull3Options& options = {});
  void compute(std::span<const Vec3<T>> points, const Hull3Options& options, Hull3Result& out);

  struct Face {
    std::uint32_t v[3];
    std::uint32_t adj[3];
    std::uint32_t head;      // outside set (linked through next_)
    std::uint32_t furthest;  // heuristic choice
    double fdist;
    double n[3], off;  // rounded plane, heuristic distances only
    std::uint32_t vis, seen;
    bool alive;
  };

 private:
  int build(std::span<const std::uint32_t> ids, Hull3Method method, Hull3Result& out,
            bool allow_rebuild);
  int simplex(std::span<const std::uint32_t> ids, std::uint32_t s[4]);
  void quickhull(std::span<const std::uint32_t> ids, const std::uint32_t s[4]);
  void incremental(std::span<const std::uint32_t> ids, const std::uint32_t s[4]);
  std::uint32_t new_face(std::uint32_t a, std::uint32_t b, std::uint32_t c);
  void add_outside(std::uint32_t f, std::uint32_t q);
  void planar(std::span<const std::uint32_t> ids, const std::uint32_t s[3], Hull3Result& out);
  // src/hull/hull3_divide_conquer.cpp: the triangles and adjacency of a 3D hull into out.
  void divide_conquer(std::span<const std::uint32_t> ids, Hull3Result& out);

  const Vec3<T>* pts_ = nullptr;
  std::size_t n_ = 0;
  std::vector<Face> faces_;
  std::vector<std::uint32_t> free_, next_, start_, end_, visible_, horizon_, newf_, stack_;
  std::vector<std::uint32_t> ids_, ids2_, map_;
  std::uint32_t stamp_ = 0;
  ConvexHull2<T> hull2_;
  std::vector<Vec2<T>> proj_;
  Hull2Result r2_;
};

/// The convex hull of a 3D point set (one call over ConvexHull3).
template <Real T>
[[nodiscard]] Hull3Result convex_hull(std::span<const Vec3<T>> points,
                                      const Hull3Options& options = {}) {
  ConvexHull3<T> builder;
  return builder.compute(points, options);
}

/// The same for any point range (core/point_range.hpp).
template <PointRange3 R>
[[nodiscard]] Hull3Result convex_hull(const R& points, const Hull3Options& options = {}) {
  return convex_hull(point_span(points), options);
}

extern template class ConvexHull3<float>;
extern template class ConvexHull3<double>;

}  // namespace locus
