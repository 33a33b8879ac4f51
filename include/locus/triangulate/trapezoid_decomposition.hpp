// SPDX-License-Identifier: BSL-1.0
#pragma once
// Horizontal trapezoidal decomposition of a polygon with holes (book section 13.9.2, figures
// 13.57-13.61; CAPABILITIES row cg.triangulate). Input and status:
// triangulate/polygon_triangulation.hpp.
// From every vertex a horizontal segment is extended left and right inside the polygon to the
// nearest edges; they cut the polygon into trapezoids (a triangle is a trapezoid with one
// parallel side of length zero). Each trapezoid is given exactly, without constructed points:
// its left and right edges (index pairs, upper endpoint first) and the vertices `top` and
// `bottom` whose y bound it. trapezoid_corners() constructs its four corners in floating point
// (rounded; the intersection of each edge with the two horizontal lines).
// The sweep is the one of monotone.hpp (exact orient2d and lexicographic order; "above" =
// larger y, ties broken by smaller x); trapezoids of zero height (horizontal edges) are not
// listed. Straight runs keep their vertices; duplicates and spike tips are dropped. Crossing
// rings give invalid_topology (see monotone.hpp). Cost O(n log n).

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// A trapezoid with horizontal top and bottom (see the top of the header).
struct Trapezoid {
  std::array<std::uint32_t, 2> left;   ///< left edge: upper endpoint, lower endpoint
  std::array<std::uint32_t, 2> right;  ///< right edge: upper endpoint, lower endpoint
  std::uint32_t top;                   ///< the vertex on the top side's line
  std::uint32_t bottom;                ///< the vertex on the bottom side's line
};

/// The trapezoids of a polygon with holes.
struct TrapezoidDecomposition {
  Status status = Status::empty_input;
  std::vector<Trapezoid> trapezoids;
};

/// The horizontal trapezoidal decomposition (see the top of the header).
template <Real T>
[[nodiscard]] TrapezoidDecomposition trapezoid_decomposition(
    std::span<const Vec2<T>> points, std::span<const std::uint32_t> ring_ends);

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] TrapezoidDecomposition trapezoid_decomposition(
    const R& points, std::span<const std::uint32_t> ring_ends) {
  return trapezoid_decomposition(point_span(points), ring_ends);
}

/// The corners of a trapezoid, counter-clockwise from bottom left (rounded constructions).
template <Real T>
[[nodiscard]] std::array<Vec2<T>, 4> trapezoid_corners(std::span<const Vec2<T>> points,
                                                       const Trapezoid& t) noexcept {
  const auto at_y = [&](const std::array<std::uint32_t, 2>& e, T y) {
    const Vec2<T>& a = points[e[0]];
    const Vec2<T>& b = points[e[1]];
    if (y == a.y) return a.x;
    if (y == b.y || a.y == b.y) return b.x;
    return a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x);
  };
  const T yb = points[t.bottom].y, yt = points[t.top].y;
  return {Vec2<T>{at_y(t.left, yb), yb}, Vec2<T>{at_y(t.right, yb), yb},
          Vec2<T>{at_y(t.right, yt), yt}, Vec2<T>{at_y(t.left, yt), yt}};
}

extern template TrapezoidDecomposition trapezoid_decomposition<float>(
    std::span<const Vec2<float>>, std::span<const std::uint32_t>);
extern template TrapezoidDecomposition trapezoid_decomposition<double>(
    std::span<const Vec2<double>>, std::span<const std::uint32_t>);

}  // namespace locus
