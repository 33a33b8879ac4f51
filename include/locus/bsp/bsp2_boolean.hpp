// SPDX-License-Identifier: BSL-1.0
#pragma once
// Polygon booleans through 2D BSP trees (book section 13.5, figures 13.20-13.31; row cg.bsp2).
// Operands: Bsp2 trees (bsp/bsp2.hpp) of polygons with holes, interior LEFT of every edge. The
// edges of A are partitioned by B's tree and those of B by A's (Bsp2::partition) into inside /
// outside / coincident-same / coincident-opposite pieces, and the result keeps (rev = reversed):
//   intersection   in(A by B) + in(B by A) + same(A)           lower: opposite(A) segments
//   union          out(A by B) + out(B by A) + same(A)
//   difference A\B out(A by B) + rev in(B by A) + opposite(A)
//   exclusive_or   out(A by B) + out(B by A) + rev in(A by B) + rev in(B by A)
//   negation       rev A (bsp2_negation)
// What the result represents: the boundary of the REGULARISED set (the closure of the interior
// of the operation on the interiors), as directed edges with the interior on their left; a
// region may be unbounded (negation). The true set intersection of the closed polygons adds
// lower-dimensional parts, reported separately, never dropped: `segments` (edges shared with
// opposite directions, figure 13.28b) and `points` (vertices where the operands only touch).
// Every decision is exact on the input coordinates (Bsp2's rule): a result edge's ends are
// input points or crossings X(own edge's line, other operand's edge `end.line`) (Bsp2End; for
// operand 0 `line` indexes b.edges(), for operand 1 a.edges()); their `point` is the crossing
// rounded once from double (Bsp2's cut: t from accurate determinants, then a + t (b - a)).
// Identities such as area(A u B) + area(A n B) = area(A) + area(B) hold exactly in the exact
// ends, and up to those roundings in the stored points.
// Loops: at every point (ends compared exactly) the edges in and out balance, so the edges are
// chained into closed loops (`loop_edges`, split by `loop_ends` like ring_ends); where several
// edges leave one point (touching vertices) the one turning most to the left is taken, which
// keeps touching loops apart. `closed` is false if some edge could not be chained (invalid
// input, e.g. self-crossing rings); those edges stay in `edges` only.
// Status: an operand whose status is empty_input or degenerate_input is the empty set;
// non_finite_input or invalid_input of an operand is returned (no edges). Cost: the two
// partitions (about (n + m) x tree depth, more with splits), then sorting the 2k result ends
// and comparing exactly those whose rounded points lie within the crossings' rounding of each
// other (O(k log k) unless many ends crowd one spot). docs/notes/bsp.md.

#include <locus/bsp/bsp2.hpp>

#include <array>
#include <concepts>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

enum class Bsp2Op : std::uint8_t { intersection, union_, difference, exclusive_or };

/// A directed result edge: a piece of edges()[edge] of the tree of `operand` (0 = a, 1 = b).
template <Real T>
struct Bsp2BooleanEdge {
  std::array<Bsp2End<T>, 2> end{};  ///< in the result's direction; `line` as in the header,
                                    ///< `vertex` always bsp2_none
  std::uint8_t operand = 0;
  bool reversed = false;  ///< direction opposite to the source edge
  std::uint32_t edge = 0;
};

template <Real T>
struct Bsp2BooleanResult {
  Status status = Status::empty_input;
  std::vector<Bsp2BooleanEdge<T>> edges;     ///< the regularised result, interior on the left
  std::vector<std::uint32_t> loop_edges;     ///< indices into edges, loop after loop
  std::vector<std::uint32_t> loop_ends;      ///< loop k is loop_edges[loop_ends[k-1], loop_ends[k])
  bool closed = true;                        ///< every edge is in a loop
  std::vector<Bsp2BooleanEdge<T>> segments;  ///< lower-dimensional part: segments (intersection)
  std::vector<Vec2<T>> points;               ///< lower-dimensional part: touching points
};

/// The boolean `op` of the polygons of trees a and b (see the top of the header).
template <Real T>
[[nodiscard]] Bsp2BooleanResult<T> bsp2_boolean(Bsp2Op op, const Bsp2<T>& a, const Bsp2<T>& b);

/// The complement of a's polygon: its edges reversed (an unbounded region), one loop per ring.
template <Real T>
[[nodiscard]] Bsp2BooleanResult<T> bsp2_negation(const Bsp2<T>& a);

/// The one-call form for any point ranges of one scalar type (core/point_range.hpp): builds
/// both trees (balanced) from points + ring_ends.
template <PointRange2 RA, PointRange2 RB>
requires std::same_as<range_scalar_t<RA>, range_scalar_t<RB>>
[[nodiscard]] auto bsp2_boolean(Bsp2Op op, const RA& a_points,
                                std::span<const std::uint32_t> a_ring_ends, const RB& b_points,
                                std::span<const std::uint32_t> b_ring_ends) {
  return bsp2_boolean(op, make_bsp2(a_points, a_ring_ends), make_bsp2(b_points, b_ring_ends));
}

/// Twice the signed area enclosed by the result's edges (rounded points), in double.
template <Real T>
[[nodiscard]] double bsp2_twice_area(const Bsp2BooleanResult<T>& r) noexcept {
  double s = 0;
  for (const Bsp2BooleanEdge<T>& e : r.edges) {
    const double ax = static_cast<double>(e.end[0].point.x),
                 ay = static_cast<double>(e.end[0].point.y);
    const double bx = static_cast<double>(e.end[1].point.x),
                 by = static_cast<double>(e.end[1].point.y);
    s += ax * by - ay * bx;
  }
  return s;
}

extern template Bsp2BooleanResult<float> bsp2_boolean(Bsp2Op, const Bsp2<float>&,
                                                      const Bsp2<float>&);
extern template Bsp2BooleanResult<double> bsp2_boolean(Bsp2Op, const Bsp2<double>&,
                                                       const Bsp2<double>&);
extern template Bsp2BooleanResult<float> bsp2_negation(const Bsp2<float>&);
extern template Bsp2BooleanResult<double> bsp2_negation(const Bsp2<double>&);

}  // namespace locus
