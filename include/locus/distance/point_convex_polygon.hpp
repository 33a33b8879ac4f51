// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a filled convex polygon in O(log n); row dist2.pt-convex; book
// section 6.1.6 (figure 6.13).
// distance_to_convex_polygon(p, v) takes the vertices v[0..n-1] of a convex polygon in
// counter-clockwise order (any contiguous storage; Polygon2 via distance_to_convex_polygon(p,
// poly)) and returns Distance<T, 2, NoParam, Vec2<T>>: closest[1] = the point of the filled
// polygon nearest to p (p itself when p is inside or on the boundary, distance exactly 0);
// param_b = closest[1] (a filled polygon is parametrised by the plane's own coordinates). There
// is no distance(p, Polygon2) overload, as Polygon2 need not be convex; swapped(...) of
// result.hpp gives the polygon-first order. unique is always true.
// Method (docs/notes/distance.md): two binary searches over the vertex fan with exact orient2d
// and exact dot-product signs, then three exact clamped point-segment projections. Cost: about
// 2 log2(n) orient2d and log2(n) dot signs; no allocation.
// Preconditions, NOT checked (checking is O(n); use polygon_is_convex / polygon_orientation):
// counter-clockwise, weakly convex (collinear consecutive vertices allowed), no repeated
// consecutive vertex. A violation gives an unspecified finite point of the boundary (or p),
// never a crash or loop. n = 1: the point; n = 2: the segment. All vertices collinear, or p
// exactly on the line v[0] v[n-1] beyond v[n-1], falls back to an O(n) scan. n = 0 or a
// non-finite p: non_finite_distance() (result.hpp); only the vertices the search reads are
// checked for NaN/Inf.

#include <locus/core/exact_sum.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/polygon.hpp>
#include <locus/primitives/segment.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

namespace locus {

namespace detail {

/// Exact sign of dot(p - b, b - a): > 0 when p projects beyond b on the line a -> b.
template <Real T>
[[nodiscard]] inline int sign_beyond_end(const Vec2<T>& a, const Vec2<T>& b,
                                         const Vec2<T>& p) noexcept {
  if (!is_finite(a) || !is_finite(b) || !is_finite(p)) return 0;  // the caller reports NaN
  const double ax = a.x, ay = a.y, bx = b.x, by = b.y, px = p.x, py = p.y;
  const double t0 = (px - bx) * (bx - ax), t1 = (py - by) * (by - ay);
  const double v = t0 + t1;
  // Same shape as orient2d's determinant (a sum of two products of differences), so its
  // forward error bound applies (Shewchuk's ccwerrboundA, rounded up).
  constexpr double bound = 3.3306690738754716e-16;
  const double mag = std::abs(t0) + std::abs(t1);
  if (mag > 1e-290 && std::abs(v) > bound * mag) return v > 0.0 ? 1 : -1;
  // p.b - p.a - b.b + b.a, expanded into products of input coordinates.
  const ExactMonomial m[8] = {{1, 0, 2, {px, bx, 0.0}},  {1, 0, 2, {py, by, 0.0}},
                              {-1, 0, 2, {px, ax, 0.0}}, {-1, 0, 2, {py, ay, 0.0}},
                              {-1, 0, 2, {bx, bx, 0.0}}, {-1, 0, 2, {by, by, 0.0}},
                              {1, 0, 2, {bx, ax, 0.0}},  {1, 0, 2, {by, ay, 0.0}}};
  return exact_sign_of_sum(m);
}

}  // namespace detail

/// Distance from p to the filled convex polygon v (counter-clockwise); see the header comment.
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, Vec2<T>> distance_to_convex_polygon(
    const Vec2<T>& p, std::span<const Vec2<T>> v) noexcept {
  using R = Distance<T, 2, NoParam, Vec2<T>>;
  const std::size_t n = v.size();
  if (n == 0 || !is_finite(p)) return non_finite_distance<T, 2, NoParam, Vec2<T>>();
  bool finite = true;
  const auto at = [&](std::size_t i) -> const Vec2<T>& {
    const Vec2<T>& x = v[i];
    finite = finite && is_finite(x);
    return x;
  };
  const auto inside_result = [&]() -> R { return detail::make_distance(p, p, NoParam{}, p, true); };
  // Nearest point of edge j (v[j] -> v[j+1 mod n]), exact clamp.
  const auto edge_point = [&](std::size_t j) {
    const Segment2<T> s{at(j), at(j + 1 == n ? 0 : j + 1)};
    return point_at(s, detail::closest_param(detail::view(s), p));
  };
  const auto from_point = [&](const Vec2<T>& q) -> R {
    if (!finite) return non_finite_distance<T, 2, NoParam, Vec2<T>>();
    return detail::make_distance(p, q, NoParam{}, q, true);
  };
  const auto brute_force = [&]() -> R {
    for (std::size_t i = 0; i < n; ++i) (void)at(i);
    if (!finite) return non_finite_distance<T, 2, NoParam, Vec2<T>>();
    Vec2<T> best_q = v[0];
    T best = sqr_length(v[0] - p);
    for (std::size_t j = 0; j < n; ++j) {
      const Vec2<T> q = edge_point(j);
      const T d2 = sqr_length(q - p);
      if (d2 < best) best = d2, best_q = q;
    }
    return from_point(best_q);
  };
  if (n == 1) return from_point(at(0));
  if (n == 2) return from_point(edge_point(0));

  const auto orient = [&](std::size_t a, std::size_t b) {  // orient2d(v[a], v[b], p)
    return to_int(orient2d(at(a), at(b), p));
  };
  const auto visible = [&](std::size_t j) { return orient(j, j + 1 == n ? 0 : j + 1) < 0; };
  const auto beyond = [&](std::size_t j) {
    return detail::sign_beyond_end(at(j), at(j + 1 == n ? 0 : j + 1), p) >= 0;
  };

  // Step 1: the fan at v0. g = an invisible edge, k = a visible edge.
  std::size_t g = 0, k = 0;
  const int s1 = orient(0, 1), s_last = orient(n - 1, 0);
  if (!finite) return non_finite_distance<T, 2, NoParam, Vec2<T>>();
  if (s1 < 0) {
    // p is right of v0 -> v1 (behind v0). The last j with orient(v0, v[j], p) < 0 bounds the
    // edge where the line from p through v0 exits: that edge is invisible.
    k = 0;
    if (to_int(orient2d(at(0), at(n - 1), p)) < 0) {
      g = n - 1;
    } else {
      std::size_t lo = 1, hi = n - 1;  // predicate true at lo, false at hi
      while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        (to_int(orient2d(at(0), at(mid), p)) < 0 ? lo : hi) = mid;
      }
      g = lo;
    }
  } else if (s_last < 0) {
    g = 0;
    k = n - 1;
  } else {
    // p lies in the closed angle at v0: find the last j with orient(v0, v[j], p) >= 0.
    g = 0;
    std::size_t i;
    if (to_int(orient2d(at(0), at(n - 1), p)) >= 0) {
      i = n - 1;  // p on the line v0 v[n-1] (orient is also <= 0 by s_last >= 0)
    } else {
      std::size_t lo = 1, hi = n - 1;
      while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        (to_int(orient2d(at(0), at(mid), p)) >= 0 ? lo : hi) = mid;
      }
      i = lo;
    }
    if (!finite) return non_finite_distance<T, 2, NoParam, Vec2<T>>();
    if (i == n - 1) {
      // On the line through v0 and v[n-1], on v[n-1]'s side of v0: on the edge, or beyond it.
      if (detail::on_collinear_segment(at(0), at(n - 1), p)) return inside_result();
      return brute_force();
    }
    const int wedge = to_int(orient2d(at(0), at(i), at(i + 1)));
    const int outer = orient(i, i + 1);
    if (!finite) return non_finite_distance<T, 2, NoParam, Vec2<T>>();
    if (wedge <= 0) return brute_force();  // degenerate fan triangle: collinear or invalid input
    if (outer >= 0) return inside_result();
    k = i;
  }
  if (!finite) return non_finite_distance<T, 2, NoParam, Vec2<T>>();

  // Step 2: edges in the order g + 1, ..., g + n - 1 (mod n), positions 0 .. n - 2; position
  // n - 1 is g itself (invisible, a sentinel).
  const auto edge_at = [&](std::size_t x) { return (g + 1 + x) % n; };
  const std::size_t xk = (k + n - g - 1) % n;
  std::size_t x_star;
  if (beyond(k)) {
    // "visible and beyond" holds from xk up to the switch: find the first position where not.
    std::size_t lo = xk, hi = n - 1;
    while (hi - lo > 1) {
      const std::size_t mid = lo + (hi - lo) / 2;
      const std::size_t e = edge_at(mid);
      (visible(e) && beyond(e) ? lo : hi) = mid;
    }
    x_star = hi;
  } else {
    // "visible and not beyond" holds from the switch up to xk: find where it starts.
    std::size_t lo = 0, hi = xk;
    const std::size_t e0 = edge_at(0);
    if (visible(e0) && !beyond(e0)) {
      hi = 0;
    } else {
      while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        const std::size_t e = edge_at(mid);
        (visible(e) && !beyond(e) ? hi : lo) = mid;
      }
    }
    x_star = hi;
  }
  // The nearest point is on edge x_star (or, at a chain end, its start vertex, which the
  // previous edge also reaches); the neighbours are cheap insurance.
  const std::size_t e = edge_at(x_star);
  Vec2<T> best_q = edge_point(e);
  T best = sqr_length(best_q - p);
  for (const std::size_t j : {(e + n - 1) % n, (e + 1) % n}) {
    const Vec2<T> q = edge_point(j);
    const T d2 = sqr_length(q - p);
    if (d2 < best) best = d2, best_q = q;
  }
  return from_point(best_q);
}

/// The Polygon2 overload (vertices counter-clockwise, convex; see the header comment).
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, Vec2<T>> distance_to_convex_polygon(
    const Vec2<T>& p, const Polygon2<T>& poly) noexcept {
  return distance_to_convex_polygon(p, std::span<const Vec2<T>>(poly.vertices));
}

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] inline Distance<range_scalar_t<R>, 2, NoParam, range_point_t<R>>
distance_to_convex_polygon(const range_point_t<R>& p, const R& v) noexcept {
  return distance_to_convex_polygon(p, point_span(v));
}

}  // namespace locus
