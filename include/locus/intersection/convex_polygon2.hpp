// SPDX-License-Identifier: BSL-1.0
#pragma once
// Stationary convex polygons in the plane by separating axes: intersects() (the book's test) and
// the intersection set (find); row int2.sat-static, book section 7.7.1-7.7.2, figures 7.12-7.16.
// Inputs: triangles, rectangles and oriented boxes (as their four corners, rounded by corners()),
// and general convex polygons as any contiguous range of vertices (counter-clockwise or
// clockwise; collinear and repeated consecutive vertices allowed; convexity is a precondition,
// not checked). Polygons are closed regions: touching counts as meeting.
// Exact decisions: the polygons are disjoint iff an edge line of one has the other strictly on
// its outer side (or, for a segment-like polygon, its own line; docs/notes/intersection2.md);
// every such side is an exact orient2d over the input coordinates, so intersects() is the exact
// answer for the floating-point input, symmetric and invariant under power-of-two scaling.
// Intersection set (kind decided exactly): empty; point or segment when two regions only touch
// (a weakly separating edge line holds the set; its end points are input vertices, exactly);
// polygon when the interiors overlap: counter-clockwise, from the lexicographically smallest
// vertex, no repeated or straight-angle vertex (decided exactly; rounding may merge close ones).
// Its vertices are input vertices (exact) or crossings of an edge of each polygon, clipped by
// Sutherland-Hodgman with symbolic vertices whose sides are exact (core/crossing.hpp) and
// constructed once from the input: |X - X*|inf <= 6 eps max(|X*|inf, m), m the largest input
// |coordinate|, eps of T. A segment against a polygon clips the segment the same way.
// Degenerate polygons act as the point or segment they span (all vertices collinear, decided
// exactly); an empty range acts as the empty set. NaN/Inf: intersects false, kind empty (status
// non_finite_input for the range form). Cost: O(nm) exact signs (book's method, early exit on a
// separating edge); fixed-size types never allocate; compiled in src/intersection/sat2.cpp.
// Moving polygons: intersection/moving_convex2.hpp.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/polygon.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace locus {

/// The intersection of two general convex polygons: kind (empty, point, segment or polygon) and
/// the vertices (1, 2, or >= 3 counter-clockwise); status ok, or non_finite_input (kind empty).
template <Real T>
struct ConvexIntersection2 {
  Status status = Status::ok;
  Kind kind = Kind::empty;
  std::vector<Vec2<T>> vertices;
};

namespace detail::sat2 {

/// Exact separating-axis test (src/intersection/sat2.cpp).
template <Real T>
[[nodiscard]] bool test(std::span<const Vec2<T>> a, std::span<const Vec2<T>> b) noexcept;

/// A line through two points p != q (its left side is the inside of a clipping half-plane).
struct Line {
  Vec2<double> p, q;
};
/// A vertex of the clipper: an input point p, or (crossing) the crossing of lines l1 and l2 (p
/// unused); out is the line of the edge leaving it.
struct Sym {
  Vec2<double> p;
  bool crossing;
  Line l1, l2, out;
};

/// The intersection set written to out[0..count) (capacity >= a.size() + b.size()); returns the
/// kind. work: scratch of work_size(a.size(), b.size()) entries.
template <Real T>
[[nodiscard]] Kind find(std::span<const Vec2<T>> a, std::span<const Vec2<T>> b, Vec2<T>* out,
                        int& count, Sym* work) noexcept;

[[nodiscard]] constexpr std::size_t work_size(std::size_t na, std::size_t nb) noexcept {
  return 2 * (na + nb + 4);
}

extern template bool test<float>(std::span<const Vec2<float>>,
                                 std::span<const Vec2<float>>) noexcept;
extern template bool test<double>(std::span<const Vec2<double>>,
                                  std::span<const Vec2<double>>) noexcept;
extern template Kind find<float>(std::span<const Vec2<float>>, std::span<const Vec2<float>>,
                                 Vec2<float>*, int&, Sym*) noexcept;
extern template Kind find<double>(std::span<const Vec2<double>>, std::span<const Vec2<double>>,
                                  Vec2<double>*, int&, Sym*) noexcept;

template <Real T, int NA, int NB>
[[nodiscard]] inline Intersection<T, 2, NoParam, NoParam, NA + NB> find_fixed(
    const std::array<Vec2<T>, NA>& a, const std::array<Vec2<T>, NB>& b) noexcept {
  Intersection<T, 2, NoParam, NoParam, NA + NB> r;
  Sym work[work_size(NA, NB)];
  r.kind = find<T>(std::span<const Vec2<T>>(a), std::span<const Vec2<T>>(b), r.point.data(),
                   r.count, work);
  return r;
}

template <Real T>
[[nodiscard]] constexpr std::array<Vec2<T>, 3> vertices_of(const Triangle2<T>& t) noexcept {
  return {t.v0, t.v1, t.v2};
}

}  // namespace detail::sat2

/// Whether two convex polygons (any vertex order) meet (exact; see the header comment).
template <Real T>
[[nodiscard]] inline bool intersects_convex_polygons(std::span<const Vec2<T>> a,
                                                     std::span<const Vec2<T>> b) noexcept {
  return detail::sat2::test<T>(a, b);
}

/// The same for any contiguous ranges of Vec2 (std::vector, std::array, Polygon2::vertices).
template <PointRange2 RA, PointRange2 RB>
requires std::same_as<range_point_t<RA>, range_point_t<RB>>
[[nodiscard]] inline bool intersects_convex_polygons(const RA& a, const RB& b) noexcept {
  return detail::sat2::test<range_scalar_t<RA>>(point_span(a), point_span(b));
}

/// The intersection set of two convex polygons (see the header comment). Allocates the result.
template <Real T>
[[nodiscard]] inline ConvexIntersection2<T> convex_polygon_intersection(
    std::span<const Vec2<T>> a, std::span<const Vec2<T>> b) {
  ConvexIntersection2<T> r;
  for (const Vec2<T>& p : a)
    if (!is_finite(p)) r.status = Status::non_finite_input;
  for (const Vec2<T>& p : b)
    if (!is_finite(p)) r.status = Status::non_finite_input;
  if (r.status != Status::ok) return r;
  const std::size_t n = a.size() + b.size();
  r.vertices.resize(n);
  std::vector<detail::sat2::Sym> work(detail::sat2::work_size(a.size(), b.size()));
  int count = 0;
  r.kind = detail::sat2::find<T>(a, b, r.vertices.data(), count, work.data());
  r.vertices.resize(static_cast<std::size_t>(count));
  return r;
}

/// The same for any contiguous ranges of Vec2.
template <PointRange2 RA, PointRange2 RB>
requires std::same_as<range_point_t<RA>, range_point_t<RB>>
[[nodiscard]] inline ConvexIntersection2<range_scalar_t<RA>> convex_polygon_intersection(
    const RA& a, const RB& b) {
  return convex_polygon_intersection<range_scalar_t<RA>>(point_span(a), point_span(b));
}

/// Whether two triangles in the plane meet (exact; any vertex order).
template <Real T>
[[nodiscard]] inline bool intersects(const Triangle2<T>& a, const Triangle2<T>& b) noexcept {
  const auto va = detail::sat2::vertices_of(a), vb = detail::sat2::vertices_of(b);
  return detail::sat2::test<T>(va, vb);
}

/// The common set of two triangles: empty, point, segment or polygon (3 to 6 vertices).
template <Real T>
[[nodiscard]] inline Intersection<T, 2, NoParam, NoParam, 6> intersection(
    const Triangle2<T>& a, const Triangle2<T>& b) noexcept {
  return detail::sat2::find_fixed<T, 3, 3>(detail::sat2::vertices_of(a),
                                           detail::sat2::vertices_of(b));
}

/// Whether two rectangles in the plane meet (exact over their rounded corners).
template <Real T>
[[nodiscard]] inline bool intersects(const Rectangle2<T>& a, const Rectangle2<T>& b) noexcept {
  const auto va = corners(a), vb = corners(b);
  return detail::sat2::test<T>(va, vb);
}

/// The common set of two rectangles: empty, point, segment or polygon (3 to 8 vertices).
template <Real T>
[[nodiscard]] inline Intersection<T, 2, NoParam, NoParam, 8> intersection(
    const Rectangle2<T>& a, const Rectangle2<T>& b) noexcept {
  return detail::sat2::find_fixed<T, 4, 4>(corners(a), corners(b));
}

namespace detail::sat2 {
/// The corners of a 2D oriented box in cyclic order (OrientedBox numbers them by bits).
template <Real T>
[[nodiscard]] constexpr std::array<Vec2<T>, 4> cycle(const OrientedBox2<T>& b) noexcept {
  const auto c = corners(b);
  return {c[0], c[1], c[3], c[2]};
}
}  // namespace detail::sat2

/// Whether two oriented boxes in the plane meet (exact over their rounded corners).
template <Real T>
[[nodiscard]] inline bool intersects(const OrientedBox2<T>& a, const OrientedBox2<T>& b) noexcept {
  const auto va = detail::sat2::cycle(a), vb = detail::sat2::cycle(b);
  return detail::sat2::test<T>(va, vb);
}

/// The common set of two oriented boxes: empty, point, segment or polygon (3 to 8 vertices).
template <Real T>
[[nodiscard]] inline Intersection<T, 2, NoParam, NoParam, 8> intersection(
    const OrientedBox2<T>& a, const OrientedBox2<T>& b) noexcept {
  return detail::sat2::find_fixed<T, 4, 4>(detail::sat2::cycle(a), detail::sat2::cycle(b));
}

}  // namespace locus
