// SPDX-License-Identifier: BSL-1.0
#pragma once
// The engine of a linear component against a polyline or polygon boundary (row
// int2.linear-polyline): each edge against the component through the linear-pair engine
// (detail/linear2.hpp), then the pieces sorted along the component by an exact comparison and
// duplicates removed. Every position along the component is named exactly as the crossing of
// the component's line with a line x0 x1 of input points: a transversal crossing by its edge, an
// input point P (an overlap end, a crossing on a parallel edge) by the axis-parallel line through
// P and (P.x, 2 P.y) or (2 P.x, P.y) (halved instead of doubled above 1), whichever is not parallel
// to the component. Two positions are compared by compare_crossing_params (core/crossing.hpp),
// exact, so a vertex met by two edges is recognised as one point however it is rounded.
// docs/notes/intersection.md.

#include <locus/core/crossing.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/detail/linear2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/polyline.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace locus::detail::linear_polyline2 {

using linear2::Lin;
using linear2::V;

/// The crossing of the component's line with the line x0 x1.
struct Key {
  V x0, x1;
};

struct Piece {
  linear2::Result r;
  std::size_t edge;
  Key k0, k1;
};

/// A line through p that crosses the component's line (not parallel to it), named by input-exact
/// points: x = p.x when the component is not vertical, else y = p.y.
[[nodiscard]] inline Key through(const Lin& l, const V& p) noexcept {
  // Halving or doubling is exact and moves the second point off p without overflow.
  const auto other = [](double c) noexcept {
    return c == 0.0 ? 1.0 : (std::abs(c) > 1.0 ? 0.5 * c : 2.0 * c);
  };
  if (l.a.x != l.b.x) return {p, V{p.x, other(p.y)}};
  return {p, V{other(p.x), p.y}};
}

/// Sign of (position of k) - (position of j) along the component.
[[nodiscard]] inline int compare(const Lin& l, const Key& j, const Key& k) noexcept {
  return to_int(compare_crossing_params(l.a, l.b, l.o, j.x0, j.x1, k.x0, k.x1));
}

template <Real T>
[[nodiscard]] inline PolylineCrossing2<T> to_crossing(const Piece& p, std::size_t edge) noexcept {
  PolylineCrossing2<T> c;
  c.kind = p.r.kind;
  c.count = p.r.count;
  c.edge = edge;
  for (std::size_t i = 0; i < static_cast<std::size_t>(p.r.count); ++i) {
    c.point[i] = vec_cast<T>(p.r.point[i]);
    c.param_a[i] = static_cast<T>(p.r.param_a[i]);
    c.param_b[i] = static_cast<T>(static_cast<double>(edge) + p.r.param_b[i]);
  }
  return c;
}

template <Real T>
[[nodiscard]] inline bool test(const Lin& l, std::span<const Vec2<T>> v, bool closed) noexcept {
  if (v.empty() || !linear2::finite(l)) return false;
  for (const Vec2<T>& p : v)
    if (!is_finite(p)) return false;
  const std::size_t m = std::max<std::size_t>(segment_count(v.size(), closed), 1);
  for (std::size_t i = 0; i < m; ++i) {
    const Segment2<T> e = v.size() == 1 ? Segment2<T>{v[0], v[0]} : edge(v, i);
    if (linear2::intersect<false>(l, linear2::as_lin(e)).kind != Kind::empty) return true;
  }
  return false;
}

template <Real T>
[[nodiscard]] inline PolylineIntersection2<T> find(const Lin& l, std::span<const Vec2<T>> v,
                                                   bool closed) {
  PolylineIntersection2<T> out;
  if (v.empty()) return out;  // empty_input
  out.status = Status::non_finite_input;
  if (!linear2::finite(l)) return out;
  for (const Vec2<T>& p : v)
    if (!is_finite(p)) return out;
  out.status = Status::ok;
  // A single vertex is a zero-length edge 0.
  const std::size_t m = std::max<std::size_t>(segment_count(v.size(), closed), 1);
  const bool point_component = l.a == l.b;
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i < m; ++i) {
    const Segment2<T> e = v.size() == 1 ? Segment2<T>{v[0], v[0]} : edge(v, i);
    const Lin el = linear2::as_lin(e);
    const linear2::Result r = linear2::intersect<true>(l, el);
    if (r.kind == Kind::empty) continue;
    if (point_component) {
      // The component is a point: it lies on this edge; one piece, on the first such edge.
      out.crossings.push_back(to_crossing<T>(Piece{r, i, {}, {}}, i));
      return out;
    }
    Piece p{r, i, {}, {}};
    const bool transversal = el.a != el.b && turn2d(l.a, l.b, el.a, el.b) != Sign::zero;
    if (transversal && r.kind == Kind::point) {
      p.k0 = p.k1 = Key{el.a, el.b};
    } else {
      // Overlap ends and points of a parallel or zero-length edge are input points.
      p.k0 = through(l, r.point[0]);
      p.k1 = r.count == 2 ? through(l, r.point[1]) : p.k0;
    }
    pieces.push_back(p);
  }
  std::sort(pieces.begin(), pieces.end(), [&l](const Piece& a, const Piece& b) {
    const int c = compare(l, a.k0, b.k0);
    if (c != 0) return c > 0;
    if (a.r.kind != b.r.kind) return a.r.kind == Kind::segment;
    return a.edge < b.edge;
  });
  std::vector<const Piece*> kept;
  kept.reserve(pieces.size());
  for (const Piece& p : pieces) {
    if (p.r.kind == Kind::point && !kept.empty()) {
      const Piece& last = *kept.back();
      // A vertex met by two edges, or a point at the end of an overlap: reported once.
      if (compare(l, last.k0, p.k0) == 0 || compare(l, last.k1, p.k0) == 0) continue;
    }
    kept.push_back(&p);
  }
  out.crossings.reserve(kept.size());
  // The pieces' starts are in exact order; their rounded parameters may be out of order by an
  // ulp. Raising each start to its predecessor keeps it within the same bound, and sorted.
  T last = -std::numeric_limits<T>::infinity();
  for (const Piece* p : kept) {
    PolylineCrossing2<T> c = to_crossing<T>(*p, p->edge);
    c.param_a[0] = std::max(c.param_a[0], last);
    if (c.count == 2) c.param_a[1] = std::max(c.param_a[1], c.param_a[0]);
    last = c.param_a[0];
    out.crossings.push_back(c);
  }
  return out;
}

}  // namespace locus::detail::linear_polyline2
