// SPDX-License-Identifier: BSL-1.0
#pragma once
// The result of every bounded intersection query, intersection(a, b), and the library-wide Kind
// of an intersection set; the foundation of rows int2.* and int3.* (book chapters 7 and 11).
//
// Intersection<T, N, ParamA, ParamB, Capacity> holds
//   kind        what the common set is (Kind below);
//   count       how many entries of point / param_a / param_b are filled (<= Capacity);
//   point[i]    a point of the set, lying on both arguments (rounded, bound in each pair header);
//   param_a[i]  its parameter on the first argument, in that primitive's point_at
//               parametrisation (Line: t in R; Ray: t >= 0; Segment: t in [0, 1]; a point:
//               NoParam), and param_b[i] likewise on the second argument.
// Every filled entry is a genuine common point with its parameters, whatever the kind, so
// generic code can check a result without knowing the pair. How each kind is described:
//   empty: count 0.  point: count 1.  points: count >= 2 isolated points, in the order the pair
//   header states.  segment: count 2, its end points, ordered by increasing param_a.
//   ray: count 2, point[0] its origin, point[1] a second point of it (the ray runs from point[0]
//   through point[1]).  line: count 2, two distinct points of it.  polygon: count >= 3 vertices
//   in order (counter-clockwise when 2D).  circle, arc, plane: three points fixing it (arc:
//   start, an interior point, end).  coincident: count 0, both arguments are the same set and
//   no kind above describes it (equal circles, ellipses, quadratic curves).
// Index 0 always refers to the first argument: the swapped-argument overload returns swapped().
// Unbounded results use vectors and a Status: PolylineIntersection2 (a linear component against
// a polyline or polygon boundary) lists PolylineCrossing2 pieces, each a point or a segment;
// IntersectionPieces<Piece> (intersection_pieces()) lists Intersection pieces the same way.
// Non-finite input gives kind empty unless the pair header says otherwise; no NaN point is ever
// reported inside count. Cost: an aggregate of Capacity (N + 2) scalars; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus {

/// The shape of an intersection set; shared by every intersection query (2D and 3D).
/// New kinds are only ever appended.
enum class Kind : std::uint8_t {
  empty,       ///< no common point
  point,       ///< exactly one common point
  points,      ///< finitely many (two or more) isolated common points
  segment,     ///< a segment of positive length (end points given)
  ray,         ///< a ray (origin and a second point given)
  line,        ///< a whole line (two of its points given)
  polyline,    ///< a chain of segments (variable-size results only)
  polygon,     ///< a planar region bounded by a polygon (vertices given in order)
  circle,      ///< a whole circle, e.g. of two spheres (three of its points given)
  arc,         ///< a circular arc of positive length (start, interior point, end given)
  plane,       ///< a whole plane, e.g. of two coincident planes (three of its points given)
  coincident,  ///< both arguments are the same set, not described by a kind above (count 0)
};

/// The result of intersection(a, b); see the header comment for the fields and each kind.
template <class T, int N, class ParamA, class ParamB, int Capacity>
struct Intersection {
  using scalar_type = T;
  using param_a_type = ParamA;
  using param_b_type = ParamB;
  static constexpr int dimension = N;
  static constexpr int capacity = Capacity;

  Kind kind = Kind::empty;                  ///< the shape of the common set
  int count = 0;                            ///< entries filled in the arrays below
  std::array<Vec<T, N>, Capacity> point{};  ///< common points (see the kind)
  std::array<ParamA, Capacity> param_a{};   ///< parameter of point[i] on the first argument
  std::array<ParamB, Capacity> param_b{};   ///< parameter of point[i] on the second argument

  /// True when the arguments meet (kind != empty).
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return kind != Kind::empty; }
};

namespace detail {
/// A parameter type with its scalar replaced by U (tags such as NoParam stay as they are).
template <class P, class U>
struct RebindParam {
  using type = P;
};
template <Real S, class U>
requires std::is_arithmetic_v<S>
struct RebindParam<S, U> {
  using type = U;
};
template <class S, int K, class U>
struct RebindParam<Vec<S, K>, U> {
  using type = Vec<U, K>;
};
template <class U, class P>
[[nodiscard]] constexpr typename RebindParam<P, U>::type cast_param(const P& p) noexcept {
  if constexpr (std::is_arithmetic_v<P>) {
    return static_cast<U>(p);
  } else if constexpr (requires { vec_cast<U>(p); }) {
    return vec_cast<U>(p);
  } else {
    return p;
  }
}
}  // namespace detail

/// The same intersection in scalar type U: every point and parameter rounded once (the
/// queries compute in double and return the caller's T through this).
template <Real U, class T, int N, class PA, class PB, int C>
[[nodiscard]] constexpr Intersection<U, N, typename detail::RebindParam<PA, U>::type,
                                     typename detail::RebindParam<PB, U>::type, C>
intersection_cast(const Intersection<T, N, PA, PB, C>& r) noexcept {
  Intersection<U, N, typename detail::RebindParam<PA, U>::type,
               typename detail::RebindParam<PB, U>::type, C>
      o;
  o.kind = r.kind;
  o.count = r.count;
  for (std::size_t i = 0; i < static_cast<std::size_t>(C); ++i) {
    o.point[i] = vec_cast<U>(r.point[i]);
    o.param_a[i] = detail::cast_param<U>(r.param_a[i]);
    o.param_b[i] = detail::cast_param<U>(r.param_b[i]);
  }
  return o;
}

/// The same answer for the swapped query intersection(b, a): parameters exchanged.
template <class T, int N, class PA, class PB, int C>
[[nodiscard]] constexpr Intersection<T, N, PB, PA, C> swapped(
    const Intersection<T, N, PA, PB, C>& r) noexcept {
  return {r.kind, r.count, r.point, r.param_b, r.param_a};
}

/// One piece of a linear component's intersection with a polyline: kind point (count 1) or
/// segment (count 2, an overlap with an edge, ends by increasing param_a), with the
/// parameters on both arguments (on a polyline or polygon: the vertex parameter edge + local t,
/// primitives/polyline.hpp) and the index of the edge it lies on.
template <Real T>
struct PolylineCrossing2 {
  Kind kind = Kind::point;
  int count = 1;
  std::array<Vec2<T>, 2> point{};
  std::array<T, 2> param_a{};
  std::array<T, 2> param_b{};
  std::size_t edge = 0;
};

/// The intersection of a linear component with a polyline or polygon boundary: the pieces in
/// order along the linear component (see the pair header).
template <Real T>
struct PolylineIntersection2 {
  Status status = Status::empty_input;
  std::vector<PolylineCrossing2<T>> crossings;
};

/// The same answer with the arguments exchanged (each piece's parameters swapped).
template <Real T>
[[nodiscard]] inline PolylineIntersection2<T> swapped(PolylineIntersection2<T> r) noexcept {
  for (PolylineCrossing2<T>& c : r.crossings) std::swap(c.param_a, c.param_b);
  return r;
}

/// A variable number of pieces of an intersection, each an Intersection of kind point or
/// segment, in the order the pair header states, with a Status (intersection_pieces()).
template <class Piece>
struct IntersectionPieces {
  Status status = Status::empty_input;
  std::vector<Piece> pieces;
};

/// The same answer for the swapped query: each piece swapped(), same order.
template <class T, int N, class PA, class PB, int C>
[[nodiscard]] inline IntersectionPieces<Intersection<T, N, PB, PA, C>> swapped(
    const IntersectionPieces<Intersection<T, N, PA, PB, C>>& r) {
  IntersectionPieces<Intersection<T, N, PB, PA, C>> s{r.status, {}};
  s.pieces.reserve(r.pieces.size());
  for (const Intersection<T, N, PA, PB, C>& p : r.pieces) s.pieces.push_back(swapped(p));
  return s;
}

/// The result of intersection() between a curve and a linear component or a curve (circle,
/// arc, ellipse, quadratic curve; rows int2.linear-quadratic, int2.quadratic): an Intersection
/// plus the multiplicity of each isolated point (1 a crossing, 2 a tangency, 3 or 4 a higher
/// contact; 0 for the points describing a segment, ray, line or arc). Parameters are T: the
/// linear parameter, the angle on a circle or arc, the angle parameter on an ellipse, 0 on a
/// general quadratic curve (it has no parametrisation). Two conics sharing a line (line pairs,
/// double lines): kind line, entries 0 and 1 the line (multiplicity 0), and entry 2 (count 3,
/// multiplicity 1) the isolated common point of the other components when there is one.
template <Real T, int Capacity>
struct CurveIntersection2 : Intersection<T, 2, T, T, Capacity> {
  std::array<int, Capacity> multiplicity{};  ///< of point[i] (see above)
};

/// The same answer for the swapped query: parameters exchanged, multiplicities kept.
template <Real T, int C>
[[nodiscard]] constexpr CurveIntersection2<T, C> swapped(
    const CurveIntersection2<T, C>& r) noexcept {
  CurveIntersection2<T, C> s = r;
  s.param_a = r.param_b;
  s.param_b = r.param_a;
  return s;
}

/// How two closed regions (disks, elliptical regions) lie relative to each other: the test
/// queries of book section 7.5 (figures 7.6-7.9). "touching" variants meet only at boundary
/// points of even multiplicity (tangencies), with the interiors disjoint (touching) or nested.
enum class RegionRelation : std::uint8_t {
  separated,              ///< disjoint, boundaries apart
  touching,               ///< interiors disjoint, boundaries tangent
  overlapping,            ///< boundaries cross: neither contains the other
  a_contains_b,           ///< b inside a, boundaries apart
  b_contains_a,           ///< a inside b, boundaries apart
  a_contains_b_touching,  ///< b inside a, boundaries tangent
  b_contains_a_touching,  ///< a inside b, boundaries tangent
  equal,                  ///< the same region
  undecided,              ///< degenerate or non-finite input
};

/// A readable name of the kind ("empty", "point", ...), for messages and the CLI.
[[nodiscard]] constexpr std::string_view to_string(Kind k) noexcept {
  switch (k) {
    case Kind::empty:
      return "empty";
    case Kind::point:
      return "point";
    case Kind::points:
      return "points";
    case Kind::segment:
      return "segment";
    case Kind::ray:
      return "ray";
    case Kind::line:
      return "line";
    case Kind::polyline:
      return "polyline";
    case Kind::polygon:
      return "polygon";
    case Kind::circle:
      return "circle";
    case Kind::arc:
      return "arc";
    case Kind::plane:
      return "plane";
    case Kind::coincident:
      return "coincident";
  }
  return "unknown";
}

}  // namespace locus
