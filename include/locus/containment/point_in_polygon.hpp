// SPDX-License-Identifier: BSL-1.0
#pragma once
// Point in triangle, convex polygon, general polygon (with holes), and a slab-accelerated
// locator for many queries on one polygon; row cg.pip; book section 13.3, figures 13.13-13.17.
// Every answer is EXACT for finite input (exact comparisons and orient2d). classify() returns
// Side::boundary for a point on a closed edge or vertex, else inside / outside; contains(region,
// p) is classify(p, region) != Side::outside (the boundary counts as inside).
//  * Triangle2: either orientation; a collinear triangle has no interior (boundary on its edges,
//    outside elsewhere).
//  * classify_convex(p, vertices): a weakly convex polygon in COUNTER-CLOCKWISE order (collinear
//    and repeated consecutive vertices allowed; at least three distinct non-collinear). Not
//    checked (O(n)): a violation gives an unspecified Side, never UB or a hang. O(log n) binary
//    search on the fan from v[0]. Fewer than three vertices: the point or segment they span.
//  * Polygon2 (any orientation, simple or not): the EVEN-ODD rule by the crossing number of the
//    ray along +x, with a half-open rule for vertices and horizontal edges (figs 13.14-13.17);
//    boundary is decided first. winding_number() gives the nonzero-rule count. O(n).
//  * PolygonWithHoles2: even-odd over all rings together (any orientation); for the documented
//    convention (holes strictly inside outer, pairwise disjoint) this is "outer minus holes".
//  * PolygonLocator2: answers exactly as classify() on the same rings, faster, by a slab
//    decomposition (docs/notes/containment.md). Build O(n log n) (compiled once, float and
//    double), memory O(n); a query scans one slab (a few edges typically, O(n) at worst).
// Bad input: a non-finite query point is outside; edges with a non-finite endpoint are ignored.
// PolygonLocator2 reports non_finite_input for such rings (then answers outside) and
// empty_input for no edges. Empty polygons: everything is outside. Only PolygonLocator2's
// construction allocates.

#include <locus/config.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/side.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/polygon.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace locus {

namespace detail {

/// Exact: p on the closed segment [a, b] (a point when a == b).
template <Real T>
[[nodiscard]] inline bool on_closed_segment2(const Vec2<T>& a, const Vec2<T>& b,
                                             const Vec2<T>& p) noexcept {
  return orient2d(a, b, p) == Sign::zero && on_collinear_segment(a, b, p) && is_finite(p);
}

/// What one edge does to the +x ray from p: 2 = p on the edge, 1 = crossing (half-open rule),
/// 0 = nothing. The sign of the crossing (up = +1, down = -1) is returned through `dir`.
template <Real T>
[[nodiscard]] inline int edge_ray_event(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& p,
                                        int& dir) noexcept {
  const bool a_above = a.y > p.y, b_above = b.y > p.y;
  if (a_above == b_above) {
    // No straddle; p can still lie on the edge when both endpoints are at or below p.y (or the
    // edge is horizontal at p.y).
    if (!a_above && (a.y == p.y || b.y == p.y) && on_closed_segment2(a, b, p)) return 2;
    return 0;
  }
  const Sign s = orient2d(a, b, p);
  if (s == Sign::zero) return on_collinear_segment(a, b, p) ? 2 : 0;
  // Upward edge (b above): p strictly left of a->b means the edge is right of p.
  if (b_above) {
    dir = 1;
    return s == Sign::positive ? 1 : 0;
  }
  dir = -1;
  return s == Sign::negative ? 1 : 0;
}

/// Crossing parity and winding of one ring; returns false (and stops) when p is on the ring.
template <Real T>
[[nodiscard]] inline bool accumulate_ring(std::span<const Vec2<T>> v, const Vec2<T>& p,
                                          int& crossings, int& winding) noexcept {
  const std::size_t n = v.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    int dir = 0;
    const int e = edge_ray_event(v[j], v[i], p, dir);
    if (e == 2) return false;
    if (e == 1) {
      ++crossings;
      winding += dir;
    }
  }
  return true;
}

}  // namespace detail

// ---- triangle ------------------------------------------------------------------------------

/// Exact classification of p against a triangle of either orientation (boundary = on an edge).
template <Real T>
[[nodiscard]] inline Side classify(const Vec2<T>& p, const Triangle2<T>& t) noexcept {
  if (!is_finite(p)) return Side::outside;
  const Sign o = orient2d(t.v0, t.v1, t.v2);
  if (o == Sign::zero) {
    return detail::on_closed_segment2(t.v0, t.v1, p) || detail::on_closed_segment2(t.v1, t.v2, p) ||
                   detail::on_closed_segment2(t.v2, t.v0, p)
               ? Side::boundary
               : Side::outside;
  }
  const int s0 = to_int(orient2d(t.v0, t.v1, p) * o);
  const int s1 = to_int(orient2d(t.v1, t.v2, p) * o);
  const int s2 = to_int(orient2d(t.v2, t.v0, p) * o);
  if (s0 < 0 || s1 < 0 || s2 < 0) return Side::outside;
  if (s0 == 0 || s1 == 0 || s2 == 0) return Side::boundary;
  return Side::inside;
}

/// classify(p, t) != outside.
template <Real T>
[[nodiscard]] inline bool contains(const Triangle2<T>& t, const Vec2<T>& p) noexcept {
  return classify(p, t) != Side::outside;
}

// ---- convex polygon ------------------------------------------------------------------------

/// Exact O(log n) classification against a weakly convex counter-clockwise polygon (see the
/// header comment for the precondition).
template <Real T>
[[nodiscard]] inline Side classify_convex(const Vec2<T>& p, std::span<const Vec2<T>> v) noexcept {
  if (!is_finite(p) || v.empty()) return Side::outside;
  const std::size_t n = v.size();
  const Vec2<T>& a = v[0];
  // Skip copies of v[0] at both ends: the fan needs directions a -> v[i].
  std::size_t first = 1, last = n - 1;
  while (first < n && v[first] == a) ++first;
  while (last >= first && last > 0 && v[last] == a) --last;
  if (first > last) return p == a ? Side::boundary : Side::outside;  // all vertices equal
  // p on the line of an edge at a: boundary iff on one of the collinear edges through a.
  auto on_line_run = [&](std::size_t start, int step) {
    // Walk the edges from a along the run of vertices collinear with a and v[start].
    std::size_t prev = 0, cur = start;
    for (std::size_t k = 0; k < n; ++k) {
      if (detail::on_closed_segment2(v[prev], v[cur], p)) return true;
      const std::size_t next = step > 0 ? (cur + 1) % n : (cur + n - 1) % n;
      if (next == 0 || orient2d(a, v[start], v[next]) != Sign::zero) return false;
      prev = cur;
      cur = next;
    }
    return false;
  };
  const Sign s1 = orient2d(a, v[first], p);
  if (s1 == Sign::negative) return Side::outside;
  const Sign s2 = orient2d(a, v[last], p);
  if (s2 == Sign::positive) return Side::outside;
  if (s1 == Sign::zero || s2 == Sign::zero) {
    return (s1 == Sign::zero && on_line_run(first, +1)) ||
                   (s2 == Sign::zero && on_line_run(last, -1))
               ? Side::boundary
               : Side::outside;
  }
  // p is strictly inside the wedge at a; the predicate orient2d(a, v[i], p) >= 0 is true on a
  // prefix of [first, last] (the fan directions turn counter-clockwise by at most pi).
  std::size_t lo = first, hi = last;
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (orient2d(a, v[mid], p) != Sign::negative)
      lo = mid;
    else
      hi = mid;
  }
  const Sign e = orient2d(v[lo], v[hi], p);
  if (e == Sign::positive) return Side::inside;
  if (e == Sign::zero) return Side::boundary;
  return Side::outside;
}

/// classify_convex(p, v) != outside.
template <Real T>
[[nodiscard]] inline bool contains_convex(std::span<const Vec2<T>> v, const Vec2<T>& p) noexcept {
  return classify_convex(p, v) != Side::outside;
}

// ---- general polygons ----------------------------------------------------------------------

/// Exact even-odd classification against the closed chain v (any orientation, simple or not).
template <Real T>
[[nodiscard]] inline Side classify_polygon(const Vec2<T>& p, std::span<const Vec2<T>> v) noexcept {
  if (!is_finite(p) || v.empty()) return Side::outside;
  int crossings = 0, winding = 0;
  if (!detail::accumulate_ring(v, p, crossings, winding)) return Side::boundary;
  return (crossings & 1) ? Side::inside : Side::outside;
}

/// Exact winding number of the closed chain v around p (positive for counter-clockwise loops);
/// 0 for a non-finite p or a point on the chain (check classify first to tell them apart).
template <Real T>
[[nodiscard]] inline int winding_number(const Vec2<T>& p, std::span<const Vec2<T>> v) noexcept {
  if (!is_finite(p) || v.empty()) return 0;
  int crossings = 0, winding = 0;
  if (!detail::accumulate_ring(v, p, crossings, winding)) return 0;
  return winding;
}

// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] inline Side classify_convex(const range_point_t<R>& p, const R& v) noexcept {
  return classify_convex(p, point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline bool contains_convex(const R& v, const range_point_t<R>& p) noexcept {
  return contains_convex(point_span(v), p);
}
template <PointRange2 R>
[[nodiscard]] inline Side classify_polygon(const range_point_t<R>& p, const R& v) noexcept {
  return classify_polygon(p, point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline int winding_number(const range_point_t<R>& p, const R& v) noexcept {
  return winding_number(p, point_span(v));
}

template <Real T>
[[nodiscard]] inline Side classify(const Vec2<T>& p, const Polygon2<T>& poly) noexcept {
  return classify_polygon(p, std::span<const Vec2<T>>(poly.vertices));
}

template <Real T>
[[nodiscard]] inline bool contains(const Polygon2<T>& poly, const Vec2<T>& p) noexcept {
  return classify(p, poly) != Side::outside;
}

/// Even-odd over all rings (see the header comment).
template <Real T>
[[nodiscard]] inline Side classify(const Vec2<T>& p, const PolygonWithHoles2<T>& poly) noexcept {
  if (!is_finite(p)) return Side::outside;
  int crossings = 0, winding = 0;
  auto ring = [&](const Polygon2<T>& r) {
    return r.vertices.empty() ||
           detail::accumulate_ring(std::span<const Vec2<T>>(r.vertices), p, crossings, winding);
  };
  if (!ring(poly.outer)) return Side::boundary;
  for (const Polygon2<T>& h : poly.holes)
    if (!ring(h)) return Side::boundary;
  return (crossings & 1) ? Side::inside : Side::outside;
}

template <Real T>
[[nodiscard]] inline bool contains(const PolygonWithHoles2<T>& poly, const Vec2<T>& p) noexcept {
  return classify(p, poly) != Side::outside;
}

// ---- many queries ----------------------------------------------------------------------------

/// A slab decomposition of a set of rings for fast exact point-in-polygon queries (even-odd
/// rule, the same answers as classify(p, PolygonWithHoles2) on the same rings).
template <Real T>
class PolygonLocator2 {
 public:
  PolygonLocator2() = default;
  explicit PolygonLocator2(const Polygon2<T>& poly) {
    const std::span<const Vec2<T>> ring(poly.vertices);
    build(std::span<const std::span<const Vec2<T>>>(&ring, 1));
  }
  explicit PolygonLocator2(const PolygonWithHoles2<T>& poly) {
    std::vector<std::span<const Vec2<T>>> rings;
    rings.emplace_back(poly.outer.vertices);
    for (const Polygon2<T>& h : poly.holes) rings.emplace_back(h.vertices);
    build(std::span<const std::span<const Vec2<T>>>(rings));
  }
  explicit PolygonLocator2(std::span<const std::span<const Vec2<T>>> rings) { build(rings); }
  /// One ring given as any point range (core/point_range.hpp).
  template <PointRange2 R>
  requires std::same_as<range_scalar_t<R>, T>
  explicit PolygonLocator2(const R& ring) {
    const std::span<const Vec2<T>> r = point_span(ring);
    build(std::span<const std::span<const Vec2<T>>>(&r, 1));
  }

  /// ok, empty_input (no edge) or non_finite_input (then every query is outside).
  [[nodiscard]] Status status() const noexcept { return status_; }
  /// Number of slabs and total number of slab entries (memory is proportional to both).
  [[nodiscard]] std::size_t slab_count() const noexcept { return slabs_; }
  [[nodiscard]] std::size_t entry_count() const noexcept { return entries_.size(); }

  /// Exact classification (boundary = on an edge or vertex of any ring).
  [[nodiscard]] Side classify(const Vec2<T>& p) const noexcept {
    if (status_ != Status::ok || !is_finite(p)) return Side::outside;
    if (p.y < ylo_ || p.y > yhi_) return Side::outside;
    const std::size_t s = slab_of(p.y);
    int crossings = 0;
    for (std::uint32_t k = offsets_[s]; k < offsets_[s + 1]; ++k) {
      const Edge& e = edges_[entries_[k]];
      if (e.xmax < p.x) break;  // sorted by decreasing xmax: the rest is left of p
      int dir = 0;
      const int ev = detail::edge_ray_event(e.a, e.b, p, dir);
      if (ev == 2) return Side::boundary;
      crossings += ev;
    }
    return (crossings & 1) ? Side::inside : Side::outside;
  }

  [[nodiscard]] bool contains(const Vec2<T>& p) const noexcept {
    return classify(p) != Side::outside;
  }

 private:
  struct Edge {
    Vec2<T> a, b;
    T xmax;
  };

  [[nodiscard]] std::size_t slab_of(T y) const noexcept {
    // Monotone in y under rounding: subtraction of a constant, multiplication by a positive
    // constant and truncation all preserve order, and the clamp keeps the result in range.
    const T t = (y - ylo_) * inv_height_;
    if (!(t > T(0))) return 0;
    const T top = static_cast<T>(slabs_ - 1);
    return t >= top ? slabs_ - 1 : static_cast<std::size_t>(t);
  }

  /// Builds the slabs (src/containment/polygon_locator.cpp, compiled for float and double).
  void build(std::span<const std::span<const Vec2<T>>> rings);

  Status status_ = Status::empty_input;
  std::vector<Edge> edges_;
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> entries_;
  std::size_t slabs_ = 0;
  T ylo_ = T(0), yhi_ = T(0), inv_height_ = T(0);
};

template <PointRange2 R>
PolygonLocator2(const R&) -> PolygonLocator2<range_scalar_t<R>>;
template <Real T>
PolygonLocator2(const Polygon2<T>&) -> PolygonLocator2<T>;
template <Real T>
PolygonLocator2(const PolygonWithHoles2<T>&) -> PolygonLocator2<T>;

}  // namespace locus
