// SPDX-License-Identifier: BSL-1.0
#pragma once
// Boolean operations on polygons with holes and multipolygons: intersection, union, difference,
// symmetric difference (xor) and negation (row cg.bool2; book section 13.5, figures 13.20-13.26).
// Operands: Polygon2, PolygonWithHoles2 or MultiPolygon2 (a vector of PolygonWithHoles2), any
// orientation: outer rings are turned counter-clockwise, holes clockwise, and a point is inside
// an operand when its winding number is positive (so overlapping members unite, an inverted hole
// is repaired, a hole outside its outer ring removes nothing). boolean_op() on raw rings instead
// applies FillRule::even_odd or non_zero to self-intersecting rings as given.
// Rings are closed implicitly (a repeated closing vertex is dropped); rings with fewer than 3
// distinct vertices or zero area contribute nothing. An empty operand is the empty set (status ok).
// Rounding rule (snap rounding, Hobby / Guibas-Marimont): pixels are the squares of side
// g = 2^(E - grid_bits) centred on the grid points, E the least integer with every |coordinate|
// < 2^E (grid_bits default 40 for double, 24 for float so every output vertex is exactly a float;
// at most 40). Decisions are exact on the input coordinates (core orient2d and crossing
// predicates): which edges cross, the pixel holding each crossing and each vertex, which input
// segments meet a hot pixel and their order. Every vertex's and crossing's pixel is hot and each
// segment becomes the path through the centres of the hot pixels it meets; the rest (windings,
// angular order, nesting) is exact integer arithmetic on those centres. Output vertices are grid
// points within g/sqrt(2) of the exact arrangement (input vertices included). Coordinates below
// 2^-100 of the largest are first rounded to that resolution (keeps the predicates in range).
// Output is always valid: simple rings of >= 3 vertices, outer rings counter-clockwise, holes
// clockwise inside their outer ring, rings meet at most at shared vertices (touching vertices
// split rings; collinear vertices of degree 2 are removed), member interiors disjoint.
// Status: ok; non_finite_input (NaN/Inf anywhere: no output); invalid_input (grid_bits outside
// 1..40, or a vertex within a pixel of the largest finite value snapped past it: no output).
// Negation of a bounded set is unbounded: boolean_negation(a, box) is box minus a. Cost: O((n + k)
// log n + p) for n edges, k crossings and p candidate pairs (x-sorted sweep, uniform grid of hot
// pixels, horizontal strips of edges); worst case O(h r) to place h holes. Details:
// docs/notes/boolean.md.

#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/polygon.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace locus {

enum class BooleanOp : std::uint8_t { intersection, union_, difference, symmetric_difference };

/// Which winding numbers w count as inside: odd, nonzero, or positive.
enum class FillRule : std::uint8_t { even_odd, non_zero, positive };

/// A set of polygons with pairwise disjoint interiors (as output) or any overlap (as input).
template <Real T>
using MultiPolygon2 = std::vector<PolygonWithHoles2<T>>;

struct BooleanOptions {
  FillRule fill_rule = FillRule::even_odd;  ///< boolean_op() on raw rings only
  int grid_bits = 0;                        ///< 0: 40 for double, 24 for float (see header)
};

template <Real T>
struct BooleanResult {
  Status status = Status::ok;
  std::string message;
  MultiPolygon2<T> polygons;  ///< outer CCW, holes CW, interiors disjoint
  double grid = 0;            ///< the snap-rounding grid spacing used (0 if no edge)
};

/// op on two sets of raw rings, each operand under fill_rule (self-intersections allowed).
template <Real T>
[[nodiscard]] BooleanResult<T> boolean_op(BooleanOp op, std::span<const Polygon2<T>> subject,
                                          std::span<const Polygon2<T>> clip,
                                          const BooleanOptions& options = {});

/// The same for vectors of rings (no template argument needed).
template <Real T>
[[nodiscard]] inline BooleanResult<T> boolean_op(BooleanOp op,
                                                 const std::vector<Polygon2<T>>& subject,
                                                 const std::vector<Polygon2<T>>& clip,
                                                 const BooleanOptions& options = {}) {
  return boolean_op(op, std::span<const Polygon2<T>>(subject), std::span<const Polygon2<T>>(clip),
                    options);
}

/// op on two multipolygons (orientation normalised, positive winding inside; see header).
template <Real T>
[[nodiscard]] BooleanResult<T> boolean_op(BooleanOp op, const MultiPolygon2<T>& a,
                                          const MultiPolygon2<T>& b, int grid_bits = 0);

template <Real T>
[[nodiscard]] inline MultiPolygon2<T> to_multipolygon(const Polygon2<T>& p) {
  return {PolygonWithHoles2<T>{p, {}}};
}
template <Real T>
[[nodiscard]] inline MultiPolygon2<T> to_multipolygon(const PolygonWithHoles2<T>& p) {
  return {p};
}
template <Real T>
[[nodiscard]] inline MultiPolygon2<T> to_multipolygon(const MultiPolygon2<T>& p) {
  return p;
}

/// Polygon2, PolygonWithHoles2 or MultiPolygon2: what the one-call functions accept.
template <class A>
concept BooleanOperand = requires(const A& a) {
  to_multipolygon(a);
};

/// a ∩ b, a ∪ b, a \ b, a xor b for any mix of Polygon2, PolygonWithHoles2, MultiPolygon2.
template <BooleanOperand A, BooleanOperand B>
[[nodiscard]] inline auto boolean_intersection(const A& a, const B& b, int grid_bits = 0) {
  return boolean_op(BooleanOp::intersection, to_multipolygon(a), to_multipolygon(b), grid_bits);
}
template <BooleanOperand A, BooleanOperand B>
[[nodiscard]] inline auto boolean_union(const A& a, const B& b, int grid_bits = 0) {
  return boolean_op(BooleanOp::union_, to_multipolygon(a), to_multipolygon(b), grid_bits);
}
template <BooleanOperand A, BooleanOperand B>
[[nodiscard]] inline auto boolean_difference(const A& a, const B& b, int grid_bits = 0) {
  return boolean_op(BooleanOp::difference, to_multipolygon(a), to_multipolygon(b), grid_bits);
}
template <BooleanOperand A, BooleanOperand B>
[[nodiscard]] inline auto boolean_xor(const A& a, const B& b, int grid_bits = 0) {
  return boolean_op(BooleanOp::symmetric_difference, to_multipolygon(a), to_multipolygon(b),
                    grid_bits);
}
/// The complement of a within box (box minus a): the bounded stand-in for the unbounded negation.
template <BooleanOperand A, Real T>
[[nodiscard]] inline BooleanResult<T> boolean_negation(const A& a, const AlignedBox2<T>& box,
                                                       int grid_bits = 0) {
  const Polygon2<T> frame{{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}}};
  return boolean_op(BooleanOp::difference, to_multipolygon(frame), to_multipolygon(a), grid_bits);
}

}  // namespace locus
