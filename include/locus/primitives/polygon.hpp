// SPDX-License-Identifier: BSL-1.0
#pragma once
// Polygons in the plane: area, orientation, convexity, simplicity, monotonicity, centroid;
// row prim2.polyline (polygon part); book section 5.4, figures 5.9, 5.10, 5.12.
// Polygon2<T> {vertices}: the closed chain v[0] .. v[n-1], back to v[0] (first vertex not
// repeated). PolygonWithHoles2<T> {outer, holes}: outer minus the holes (convention, not
// enforced: outer counter-clockwise, holes clockwise, strictly inside, pairwise disjoint).
// Every function also exists as polygon_*(points) for any point range (core/point_range.hpp).
// Combinatorial answers are EXACT for finite input (orient2d, exact comparisons and projections):
// orientation, is_convex, is_simple/self_intersection, monotone tests. Measures (signed_area,
// centroid, perimeter) are rounded, in compute_t<T>. Consecutive duplicate vertices are ignored
// by every combinatorial test. Details: docs/notes/primitives.md.
//  * orientation(): the exact sign at the lowest (then leftmost) vertex; for a simple polygon the
//    sign of the area (positive = counter-clockwise). Zero for fewer than three distinct
//    vertices, all vertices collinear, or a spike at that vertex.
//  * is_convex(): weakly convex: three or more distinct non-collinear vertices, all turns of one
//    sign or straight, no spike, winding exactly once (a pentagram is NOT convex).
//  * is_simple(): at least three vertices, adjacent edges meet only at their shared vertex,
//    non-adjacent edges disjoint as closed segments (touching at a vertex, fig 5.10b, is
//    nonsimple); collinear consecutive vertices allowed. Shamos-Hoey sweep, O(n log n) time and
//    O(n) memory, the only allocating functions here; the rest are O(n) or O(1).
//  * Monotone along d (fig 5.12): the cyclic signs of dot(v[i+1] - v[i], d), zeros skipped,
//    change exactly twice; simplicity not checked. monotone_split() also returns the two
//    extreme vertices along d. centroid(): area centroid; for zero (rounded) area the average.
// Non-finite input: orientation zero, predicates false, measures NaN/inf. Fewer than three
// vertices: area 0, not simple, not convex, orientation zero.

#include <locus/config.hpp>
#include <locus/core/exact_sum.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/segment.hpp>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <set>
#include <span>
#include <utility>
#include <vector>

namespace locus {

/// A closed polygon v[0], ..., v[n-1] (the first vertex is not repeated at the end).
template <Real T>
struct Polygon2 {
  std::vector<Vec2<T>> vertices;
};

/// A polygon with holes: outer boundary and hole boundaries (see the header comment).
template <Real T>
struct PolygonWithHoles2 {
  Polygon2<T> outer;
  std::vector<Polygon2<T>> holes;
};

using Polygon2f = Polygon2<float>;
using Polygon2d = Polygon2<double>;

namespace detail {

template <Real T>
[[nodiscard]] inline bool all_finite(std::span<const Vec2<T>> v) noexcept {
  for (const Vec2<T>& p : v)
    if (!is_finite(p)) return false;
  return true;
}

/// Indices of the vertices that differ from their cyclic predecessor (consecutive duplicates
/// removed; if all vertices coincide, the single index 0).
template <Real T>
[[nodiscard]] inline std::vector<std::size_t> distinct_cycle(std::span<const Vec2<T>> v) {
  std::vector<std::size_t> out;
  const std::size_t n = v.size();
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!out.empty() && v[i] == v[out.back()]) continue;
    out.push_back(i);
  }
  while (out.size() > 1 && v[out.back()] == v[out.front()]) out.pop_back();
  return out;
}

/// Exact: for collinear a, b, c with a != b and b != c, true when c - b points back along a - b
/// (the chain folds back on itself at b).
template <Real T>
[[nodiscard]] constexpr bool folds_back(const Vec2<T>& a, const Vec2<T>& b,
                                        const Vec2<T>& c) noexcept {
  // b - a and c - b are parallel and nonzero, so their x-components are both zero or both
  // nonzero; the sign comparison of coordinate differences is exact.
  const int sx0 = (b.x > a.x) - (b.x < a.x), sx1 = (c.x > b.x) - (c.x < b.x);
  if (sx0 != 0 || sx1 != 0) return sx0 * sx1 < 0;
  const int sy0 = (b.y > a.y) - (b.y < a.y), sy1 = (c.y > b.y) - (c.y < b.y);
  return sy0 * sy1 < 0;
}

/// Exact lexicographic (x, then y) order.
template <Real T>
[[nodiscard]] constexpr bool lex_less(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/// Exact: p lies on the closed segment [a, b], given orient2d(a, b, p) == 0.
template <Real T>
[[nodiscard]] constexpr bool on_collinear_segment(const Vec2<T>& a, const Vec2<T>& b,
                                                  const Vec2<T>& p) noexcept {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

}  // namespace detail

/// Exact test: do the closed segments [p0, p1] and [q0, q1] share a point (crossing, touching,
/// or overlapping)? Degenerate segments act as points.
template <Real T>
[[nodiscard]] inline bool segments_intersect_exact(const Vec2<T>& p0, const Vec2<T>& p1,
                                                   const Vec2<T>& q0, const Vec2<T>& q1) noexcept {
  const int o1 = to_int(orient2d(p0, p1, q0)), o2 = to_int(orient2d(p0, p1, q1));
  const int o3 = to_int(orient2d(q0, q1, p0)), o4 = to_int(orient2d(q0, q1, p1));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && detail::on_collinear_segment(p0, p1, q0)) return true;
  if (o2 == 0 && detail::on_collinear_segment(p0, p1, q1)) return true;
  if (o3 == 0 && detail::on_collinear_segment(q0, q1, p0)) return true;
  if (o4 == 0 && detail::on_collinear_segment(q0, q1, p1)) return true;
  return false;
}

// ---- measures ------------------------------------------------------------------------------

/// Signed area (shoelace relative to v[0], accumulated in compute_t<T>); positive for
/// counter-clockwise order.
template <Real T>
[[nodiscard]] inline T polygon_signed_area(std::span<const Vec2<T>> v) noexcept {
  using C = compute_t<T>;
  if (v.size() < 3) return T(0);
  const Vec2<C> o = vec_cast<C>(v[0]);
  C sum = C(0);
  for (std::size_t i = 1; i + 1 < v.size(); ++i)
    sum += perp_dot(vec_cast<C>(v[i]) - o, vec_cast<C>(v[i + 1]) - o);
  return static_cast<T>(C(0.5) * sum);
}

/// |signed area|.
template <Real T>
[[nodiscard]] inline T polygon_area(std::span<const Vec2<T>> v) noexcept {
  return std::abs(polygon_signed_area(v));
}

/// Sum of the edge lengths of the closed chain.
template <Real T>
[[nodiscard]] inline T polygon_perimeter(std::span<const Vec2<T>> v) noexcept {
  return polyline_length(v, true);
}

/// Area centroid (triangle fan from v[0], weights in compute_t<T>); the vertex average when
/// the rounded area is zero; the zero vector for an empty polygon.
template <Real T>
[[nodiscard]] inline Vec2<T> polygon_centroid(std::span<const Vec2<T>> v) noexcept {
  using C = compute_t<T>;
  if (v.empty()) return Vec2<T>{};
  const Vec2<C> o = vec_cast<C>(v[0]);
  C twice_area = C(0);
  Vec2<C> acc{};
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const Vec2<C> a = vec_cast<C>(v[i]) - o, b = vec_cast<C>(v[i + 1]) - o;
    const C w = perp_dot(a, b);
    twice_area += w;
    acc += w * (a + b);  // triangle (0, a, b) has centroid (a + b) / 3, weight w / 2
  }
  if (twice_area != C(0) && is_finite(twice_area)) {
    return vec_cast<T>(o + acc / (C(3) * twice_area));
  }
  Vec2<C> mean{};
  for (const Vec2<T>& p : v) mean += vec_cast<C>(p);
  return vec_cast<T>(mean / static_cast<C>(v.size()));
}

// ---- orientation and convexity -------------------------------------------------------------

/// Exact orientation at the lowest-leftmost vertex (see the header comment).
template <Real T>
[[nodiscard]] inline Sign polygon_orientation(std::span<const Vec2<T>> v) noexcept {
  const std::size_t n = v.size();
  if (n < 3 || !detail::all_finite(v)) return Sign::zero;
  std::size_t k = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (v[i].y < v[k].y || (v[i].y == v[k].y && v[i].x < v[k].x)) k = i;
  std::size_t prev = (k + n - 1) % n, next = (k + 1) % n;
  while (prev != k && v[prev] == v[k]) prev = (prev + n - 1) % n;
  while (next != k && v[next] == v[k]) next = (next + 1) % n;
  if (prev == k || next == k) return Sign::zero;
  // Both neighbours lie in the closed upper half-plane and not left of v[k] on its horizontal,
  // so they cannot be on opposite sides of v[k] on one line: a zero here is a spike at the
  // extreme vertex or an all-collinear polygon, and zero is the answer.
  return orient2d(v[prev], v[k], v[next]);
}

/// Exact weak convexity (see the header comment).
template <Real T>
[[nodiscard]] inline bool polygon_is_convex(std::span<const Vec2<T>> v) noexcept {
  const std::size_t n = v.size();
  if (n < 3 || !detail::all_finite(v)) return false;
  // Walk the distinct vertices without allocating: start at the first vertex of a run of
  // duplicates, and step to the first vertex of the next run.
  std::size_t s = n;
  for (std::size_t i = 0; i < n; ++i)
    if (!(v[i] == v[(i + n - 1) % n])) {
      s = i;
      break;
    }
  if (s == n) return false;  // all vertices coincide
  auto next = [&](std::size_t i) {
    std::size_t j = (i + 1) % n;
    while (v[j] == v[i]) j = (j + 1) % n;
    return j;
  };
  std::size_t m = 0;
  for (std::size_t c = s;;) {
    ++m;
    c = next(c);
    if (c == s) break;
  }
  if (m < 3) return false;
  int turn = 0;
  std::size_t ia = s, ib = next(s), ic = next(ib);
  for (std::size_t k = 0; k < m; ++k, ia = ib, ib = ic, ic = next(ic)) {
    const Vec2<T>&a = v[ia], &b = v[ib], &c = v[ic];
    const int t = to_int(orient2d(a, b, c));
    if (t == 0) {
      if (detail::folds_back(a, b, c)) return false;
      continue;
    }
    if (turn == 0) {
      turn = t;
    } else if (t != turn) {
      return false;
    }
  }
  if (turn == 0) return false;  // all collinear
  // Winding number one: the x-direction of the edges changes sign exactly twice (each full
  // turn of a monotonically turning boundary contributes two changes).
  int changes = 0, first = 0, last = 0;
  std::size_t i = s;
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t j = next(i);
    const int sx = (v[j].x > v[i].x) - (v[j].x < v[i].x);
    i = j;
    if (sx == 0) continue;
    if (first == 0) {
      first = sx;
    } else if (sx != last) {
      ++changes;
    }
    last = sx;
  }
  if (last != first) ++changes;
  return changes == 2;
}

// ---- simplicity ------------------------------------------------------------------------------

/// The first pair of offending edges found, as indices i < j of the original edges
/// (v[i], v[i+1 mod n]), or std::nullopt when the polygon is simple. A polygon with fewer than
/// three distinct vertices reports the pair (0, 0); non-finite input too.
template <Real T>
[[nodiscard]] inline std::optional<std::pair<std::size_t, std::size_t>> polygon_self_intersection(
    std::span<const Vec2<T>> v) {
  using Result = std::optional<std::pair<std::size_t, std::size_t>>;
  if (v.size() < 3 || !detail::all_finite(v))
    return Result{std::pair<std::size_t, std::size_t>{0, 0}};
  const std::vector<std::size_t> d = detail::distinct_cycle(v);
  const std::size_t m = d.size();
  if (m < 3) return Result{std::pair<std::size_t, std::size_t>{0, 0}};
  // Edge e (of the deduplicated cycle) runs from v[d[e]] to v[d[e+1]]; the original edge index
  // is the last copy of v[d[e]] in its run (the one whose successor differs).
  const std::size_t n = v.size();
  auto orig = [&](std::size_t e) {
    std::size_t j = d[e];
    while (v[(j + 1) % n] == v[d[e]]) j = (j + 1) % n;
    return j;
  };
  auto pair_of = [&](std::size_t e, std::size_t f) {
    std::size_t a = orig(e), b = orig(f);
    if (b < a) std::swap(a, b);
    return std::pair<std::size_t, std::size_t>{a, b};
  };
  auto p0 = [&](std::size_t e) -> const Vec2<T>& { return v[d[e]]; };
  auto p1 = [&](std::size_t e) -> const Vec2<T>& { return v[d[(e + 1) % m]]; };
  // Adjacent edges meet at a shared vertex; they conflict only by folding back onto each other.
  auto conflict = [&](std::size_t e, std::size_t f) {
    if (e == f) return false;
    if ((e + 1) % m == f)
      return orient2d(p0(e), p1(e), p1(f)) == Sign::zero && detail::folds_back(p0(e), p1(e), p1(f));
    if ((f + 1) % m == e)
      return orient2d(p0(f), p1(f), p1(e)) == Sign::zero && detail::folds_back(p0(f), p1(f), p1(e));
    return segments_intersect_exact(p0(e), p1(e), p0(f), p1(f));
  };
  // Left/right endpoints in the lexicographic sweep order.
  auto left = [&](std::size_t e) -> const Vec2<T>& {
    return detail::lex_less(p1(e), p0(e)) ? p1(e) : p0(e);
  };
  auto right = [&](std::size_t e) -> const Vec2<T>& {
    return detail::lex_less(p1(e), p0(e)) ? p0(e) : p1(e);
  };
  // "e below f" on the sweep line; decided on the line of the segment that started first.
  auto below = [&](std::size_t e, std::size_t f) {
    if (e == f) return false;
    if (!detail::lex_less(left(f), left(e))) {
      Sign s = orient2d(left(e), right(e), left(f));
      if (s == Sign::zero) s = orient2d(left(e), right(e), right(f));
      if (s != Sign::zero) return s == Sign::positive;
    } else {
      Sign s = orient2d(left(f), right(f), left(e));
      if (s == Sign::zero) s = orient2d(left(f), right(f), right(e));
      if (s != Sign::zero) return s == Sign::negative;
    }
    return e < f;  // collinear overlap: an intersection that the neighbour tests report
  };
  struct Event {
    std::size_t edge;
    bool insert;
  };
  std::vector<Event> events;
  events.reserve(2 * m);
  for (std::size_t e = 0; e < m; ++e) {
    events.push_back({e, true});
    events.push_back({e, false});
  }
  auto point_of = [&](const Event& ev) -> const Vec2<T>& {
    return ev.insert ? left(ev.edge) : right(ev.edge);
  };
  std::sort(events.begin(), events.end(), [&](const Event& a, const Event& b) {
    const Vec2<T>& pa = point_of(a);
    const Vec2<T>& pb = point_of(b);
    if (detail::lex_less(pa, pb)) return true;
    if (detail::lex_less(pb, pa)) return false;
    if (a.insert != b.insert) return a.insert;  // insertions first at a common point
    return a.edge < b.edge;
  });
  std::set<std::size_t, decltype(below)> status(below);
  std::vector<typename std::set<std::size_t, decltype(below)>::iterator> where(m, status.end());
  for (const Event& ev : events) {
    if (ev.insert) {
      const auto it = status.insert(ev.edge).first;
      where[ev.edge] = it;
      if (it != status.begin() && conflict(*std::prev(it), ev.edge))
        return pair_of(*std::prev(it), ev.edge);
      if (std::next(it) != status.end() && conflict(*std::next(it), ev.edge))
        return pair_of(*std::next(it), ev.edge);
    } else {
      const auto it = where[ev.edge];
      if (it != status.begin() && std::next(it) != status.end()) {
        const std::size_t lo = *std::prev(it), hi = *std::next(it);
        if (conflict(lo, hi)) return pair_of(lo, hi);
      }
      status.erase(it);
    }
  }
  return std::nullopt;
}

/// True when the polygon is simple (see the header comment); O(n log n).
template <Real T>
[[nodiscard]] inline bool polygon_is_simple(std::span<const Vec2<T>> v) {
  return !polygon_self_intersection(v).has_value();
}

// ---- monotonicity ----------------------------------------------------------------------------

/// The result of monotone_split: whether the boundary is two chains monotone along the
/// direction, and the vertices where they meet (indices into the vertex list).
struct MonotoneSplit {
  bool monotone;
  std::size_t min_vertex;  ///< a vertex of minimal projection: chains start/end here
  std::size_t max_vertex;  ///< a vertex of maximal projection
};

/// Exact monotone-polygon test along direction d (fig 5.12). The chain min_vertex ->
/// max_vertex (increasing indices, cyclically) is non-decreasing along d, the chain
/// max_vertex -> min_vertex non-increasing. Not monotone for a zero or non-finite direction,
/// non-finite vertices, fewer than three vertices, or all vertices on one perpendicular line.
template <Real T>
[[nodiscard]] inline MonotoneSplit polygon_monotone_split(std::span<const Vec2<T>> v,
                                                          const Vec2<T>& d) noexcept {
  const std::size_t n = v.size();
  MonotoneSplit r{false, 0, 0};
  if (n < 3 || !is_finite(d) || d == Vec2<T>{} || !detail::all_finite(v)) return r;
  auto sign_at = [&](std::size_t i) {
    const Vec2<T>& a = v[i];
    const Vec2<T>& b = v[(i + 1) % n];
    return detail::sign_dot_diff(a.x, a.y, b.x, b.y, d.x, d.y);
  };
  // Start at an edge with a nonzero sign so the cyclic scan sees each run once.
  std::size_t start = n;
  for (std::size_t i = 0; i < n; ++i)
    if (sign_at(i) != 0) {
      start = i;
      break;
    }
  if (start == n) return r;
  int prev = sign_at(start), changes = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t i = (start + k) % n;
    const int s = sign_at(i);
    if (s == 0 || s == prev) continue;
    ++changes;
    // The edge i starts a new run: its first vertex is a local extreme.
    if (s > 0)
      r.min_vertex = i;
    else
      r.max_vertex = i;
    prev = s;
  }
  r.monotone = changes == 2;
  return r;
}

/// Exact monotone-polygon test along direction d (fig 5.12).
template <Real T>
[[nodiscard]] inline bool polygon_is_monotone(std::span<const Vec2<T>> v,
                                              const Vec2<T>& d) noexcept {
  return polygon_monotone_split(v, d).monotone;
}

// ---- Polygon2 overloads ----------------------------------------------------------------------

template <Real T>
[[nodiscard]] inline T signed_area(const Polygon2<T>& p) noexcept {
  return polygon_signed_area(std::span<const Vec2<T>>(p.vertices));
}
template <Real T>
[[nodiscard]] inline T area(const Polygon2<T>& p) noexcept {
  return polygon_area(std::span<const Vec2<T>>(p.vertices));
}
template <Real T>
[[nodiscard]] inline T perimeter(const Polygon2<T>& p) noexcept {
  return polygon_perimeter(std::span<const Vec2<T>>(p.vertices));
}
template <Real T>
[[nodiscard]] inline Vec2<T> centroid(const Polygon2<T>& p) noexcept {
  return polygon_centroid(std::span<const Vec2<T>>(p.vertices));
}
template <Real T>
[[nodiscard]] inline Sign orientation(const Polygon2<T>& p) noexcept {
  return polygon_orientation(std::span<const Vec2<T>>(p.vertices));
}
template <Real T>
[[nodiscard]] inline bool is_convex(const Polygon2<T>& p) noexcept {
  return polygon_is_convex(std::span<const Vec2<T>>(p.vertices));
}
template <Real T>
[[nodiscard]] inline bool is_simple(const Polygon2<T>& p) {
  return polygon_is_simple(std::span<const Vec2<T>>(p.vertices));
}
template <Real T>
[[nodiscard]] inline std::optional<std::pair<std::size_t, std::size_t>> self_intersection(
    const Polygon2<T>& p) {
  return polygon_self_intersection(std::span<const Vec2<T>>(p.vertices));
}
template <Real T>
[[nodiscard]] inline bool is_monotone(const Polygon2<T>& p, const Vec2<T>& d) noexcept {
  return polygon_is_monotone(std::span<const Vec2<T>>(p.vertices), d);
}
template <Real T>
[[nodiscard]] inline MonotoneSplit monotone_split(const Polygon2<T>& p, const Vec2<T>& d) noexcept {
  return polygon_monotone_split(std::span<const Vec2<T>>(p.vertices), d);
}

/// Area of the outer boundary minus the areas of the holes (absolute values, so the result
/// does not depend on the boundaries' orientations).
template <Real T>
[[nodiscard]] inline T area(const PolygonWithHoles2<T>& p) noexcept {
  T a = area(p.outer);
  for (const Polygon2<T>& h : p.holes) a -= area(h);
  return a;
}

/// Total boundary length (outer plus holes).
template <Real T>
[[nodiscard]] inline T perimeter(const PolygonWithHoles2<T>& p) noexcept {
  T s = perimeter(p.outer);
  for (const Polygon2<T>& h : p.holes) s += perimeter(h);
  return s;
}

/// Area centroid of the region (outer minus holes); the outer centroid when the area is zero.
template <Real T>
[[nodiscard]] inline Vec2<T> centroid(const PolygonWithHoles2<T>& p) noexcept {
  using C = compute_t<T>;
  C total = static_cast<C>(area(p.outer));
  Vec2<C> acc = total * vec_cast<C>(centroid(p.outer));
  for (const Polygon2<T>& h : p.holes) {
    const C a = static_cast<C>(area(h));
    total -= a;
    acc -= a * vec_cast<C>(centroid(h));
  }
  if (!(total != C(0)) || !is_finite(total)) return centroid(p.outer);
  return vec_cast<T>(acc / total);
}

// The polygon_* functions for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] inline range_scalar_t<R> polygon_signed_area(const R& v) noexcept {
  return polygon_signed_area(point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline range_scalar_t<R> polygon_area(const R& v) noexcept {
  return polygon_area(point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline range_scalar_t<R> polygon_perimeter(const R& v) noexcept {
  return polygon_perimeter(point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline range_point_t<R> polygon_centroid(const R& v) noexcept {
  return polygon_centroid(point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline Sign polygon_orientation(const R& v) noexcept {
  return polygon_orientation(point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline bool polygon_is_convex(const R& v) noexcept {
  return polygon_is_convex(point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline std::optional<std::pair<std::size_t, std::size_t>> polygon_self_intersection(
    const R& v) {
  return polygon_self_intersection(point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline bool polygon_is_simple(const R& v) {
  return polygon_is_simple(point_span(v));
}
template <PointRange2 R>
[[nodiscard]] inline MonotoneSplit polygon_monotone_split(const R& v,
                                                          const range_point_t<R>& d) noexcept {
  return polygon_monotone_split(point_span(v), d);
}
template <PointRange2 R>
[[nodiscard]] inline bool polygon_is_monotone(const R& v, const range_point_t<R>& d) noexcept {
  return polygon_is_monotone(point_span(v), d);
}

}  // namespace locus
