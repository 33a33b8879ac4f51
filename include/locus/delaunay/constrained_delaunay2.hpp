// SPDX-License-Identifier: BSL-1.0
#pragma once
// 2D constrained Delaunay triangulation (CDT) and triangulation of polygons with holes.
// CAPABILITIES row cg.delaunay2 ("constrained Delaunay, beyond the book"); book section 13.8.
// The Delaunay triangulation of the points (delaunay2.hpp), then each constraint inserted by
// removing the triangles it crosses and re-triangulating both sides (exact orient2d/incircle;
// method: docs/notes/delaunay.md). No point visible from a triangle's interior lies strictly
// inside its circumcircle (segments block visibility).
// Constraints (endpoints are point indices; duplicates merged as in delaunay2.hpp, duplicate_of):
//  - one through existing vertices is split there (all parts marked constrained);
//  - one that properly crosses an inserted constraint, or has an endpoint index out of range,
//    is NOT inserted (no Steiner points): it is listed in `rejected`, the status is
//    invalid_input, and the result is the CDT of the accepted ones; zero length: ignored.
// Output: the layout of Delaunay2Result (triangles CCW, adjacency[t][i] across edge
// (v[i], v[i+1]), kNoTriangle on the hull; hull CCW; duplicate_of), plus constrained[t][i] = 1
// when edge i of triangle t lies on a constraint (set on both sides), and, for
// triangulate_polygon(), inside[t] = 1 for triangles inside the polygon (even-odd rule).
// triangulate_polygon(points, ring_ends): ring k is points[ring_ends[k-1] .. ring_ends[k])
// (ring_ends[-1] = 0), closed implicitly; any orientation and nesting (even-odd rule).
// Self-intersecting rings give rejected edges and invalid_input.
// Bad input: NaN/Inf -> non_finite_input; no points -> empty_input; all points collinear ->
// dimension 1, no triangles, status ok. Every walk has a step budget (the triangle count).
// Cost: the Delaunay triangulation, plus O(k^2) per constraint crossing k edges.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/delaunay/delaunay2.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// The result of a constrained Delaunay triangulation (see the top of the header).
struct ConstrainedDelaunay2Result {
  Status status = Status::empty_input;
  int dimension = -1;
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< counter-clockwise
  std::vector<std::array<std::uint32_t, 3>> adjacency;  ///< across edge (v[i], v[i+1])
  std::vector<std::uint32_t> hull;                      ///< CCW hull vertices
  std::vector<std::uint32_t> duplicate_of;  ///< per input point: itself or the kept equal point
  std::vector<std::array<std::uint8_t, 3>> constrained;  ///< per edge: 1 on a constraint
  std::vector<std::uint8_t> inside;     ///< per triangle (triangulate_polygon only)
  std::vector<std::uint32_t> rejected;  ///< indices of constraints not inserted

  [[nodiscard]] std::size_t triangle_count() const noexcept { return triangles.size(); }
};

/// Reusable constrained Delaunay triangulator (keeps its buffers between calls).
template <Real T>
class ConstrainedDelaunay2 {
 public:
  /// The CDT of `points` with the segments `constraints` (pairs of point indices).
  const ConstrainedDelaunay2Result& compute(
      std::span<const Vec2<T>> points, std::span<const std::array<std::uint32_t, 2>> constraints);

  /// The CDT of the rings of a polygon with holes, with inside[] marked by the even-odd rule.
  const ConstrainedDelaunay2Result& compute_polygon(std::span<const Vec2<T>> points,
                                                    std::span<const std::uint32_t> ring_ends);

  [[nodiscard]] const ConstrainedDelaunay2Result& result() const noexcept { return result_; }

 private:
  enum class Insertion : std::uint8_t { inserted, crosses_constraint, failed };
  // Where segment a -> b leaves the fan of triangles around a (see find_exit).
  struct FanExit {
    std::uint32_t existing;     // a half-edge a -> x on the segment (x = b or x inside ab)
    std::uint32_t on_segment;   // that x when it lies strictly inside ab
    std::uint32_t first_cross;  // else: the half-edge a -> x of the triangle ab enters
  };
  // An edge of the cavity boundary: the cavity-side half-edge u -> v, the half-edge outside it
  // (or -1 on the hull) and whether it is a constraint.
  struct BoundaryEdge {
    std::uint32_t u, v;
    std::int32_t outside;
    std::uint8_t constrained;
  };

  void triangulate(std::span<const Vec2<T>> points,
                   std::span<const std::array<std::uint32_t, 2>> constraints);
  void load_delaunay(const Delaunay2Result& d);
  Insertion insert_segment(std::uint32_t a, std::uint32_t b);
  [[nodiscard]] FanExit find_exit(std::uint32_t a, std::uint32_t b) const;
  void mark_constrained(std::uint32_t e);
  Insertion collect_crossed(std::uint32_t a, std::uint32_t b, std::uint32_t first_cross,
                            std::uint32_t& end);
  void collect_cavity_boundary();
  void retriangulate_side(std::uint32_t a, std::uint32_t end,
                          const std::vector<std::uint32_t>& side);
  [[nodiscard]] bool replace_cavity(std::uint32_t a, std::uint32_t end);
  void mark_inside();
  void write_result();

  Delaunay2<T> delaunay_;
  std::span<const Vec2<T>> points_;
  ConstrainedDelaunay2Result result_;
  // The triangulation while constraints go in, as half-edges: tris_[3t + i] is vertex i of
  // triangle t, halfedges_[3t + i] the opposite of the half-edge v[i] -> v[i+1] (-1: hull).
  std::vector<std::uint32_t> tris_;
  std::vector<std::int32_t> halfedges_;
  std::vector<std::uint8_t> constrained_;   // per half-edge
  std::vector<std::uint8_t> inside_;        // per triangle
  std::vector<std::uint32_t> vertex_edge_;  // an outgoing half-edge per vertex
  std::vector<std::uint8_t> in_cavity_;
  std::vector<std::uint32_t> cavity_, left_, right_, new_tris_;
  std::vector<BoundaryEdge> boundary_;
};

/// Constrained Delaunay triangulation (one call over ConstrainedDelaunay2).
template <Real T>
[[nodiscard]] ConstrainedDelaunay2Result constrained_delaunay(
    std::span<const Vec2<T>> points, std::span<const std::array<std::uint32_t, 2>> constraints);

/// Triangulation of a polygon with holes given as consecutive rings (see the top of the header).
template <Real T>
[[nodiscard]] ConstrainedDelaunay2Result triangulate_polygon(
    std::span<const Vec2<T>> points, std::span<const std::uint32_t> ring_ends);

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] ConstrainedDelaunay2Result constrained_delaunay(
    const R& points, std::span<const std::array<std::uint32_t, 2>> constraints) {
  return constrained_delaunay(point_span(points), constraints);
}
template <PointRange2 R>
[[nodiscard]] ConstrainedDelaunay2Result triangulate_polygon(
    const R& points, std::span<const std::uint32_t> ring_ends) {
  return triangulate_polygon(point_span(points), ring_ends);
}

extern template class ConstrainedDelaunay2<float>;
extern template class ConstrainedDelaunay2<double>;
extern template ConstrainedDelaunay2Result constrained_delaunay<float>(
    std::span<const Vec2<float>>, std::span<const std::array<std::uint32_t, 2>>);
extern template ConstrainedDelaunay2Result constrained_delaunay<double>(
    std::span<const Vec2<double>>, std::span<const std::array<std::uint32_t, 2>>);
extern template ConstrainedDelaunay2Result triangulate_polygon<float>(
    std::span<const Vec2<float>>, std::span<const std::uint32_t>);
extern template ConstrainedDelaunay2Result triangulate_polygon<double>(
    std::span<const Vec2<double>>, std::span<const std::uint32_t>);

}  // namespace locus
