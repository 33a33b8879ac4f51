// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a polyline (open or closed polygonal chain) in N dimensions;
// rows dist2.pt-polyline and dist3.pt-linear (polyline part); book sections 6.1.2 (figure 6.4)
// and 10.2.4 (figure 10.5).
//
// distance(p, poly) returns Distance<T, N, NoParam, T>: closest[1] = the nearest point of the
// chain, param_b = its vertex parameter t in [0, segment_count] (primitives/polyline.hpp:
// segment floor(t) at local parameter t - floor(t)), so closest[1] ~ point_at(poly, param_b).
// distance_to_polyline(p, vertices, closed) takes any contiguous vertex storage.
// distance(poly, p) is the swapped result.
//
// Method: the segments are visited in order, keeping the best squared distance mu^2 so far
// (started from vertex 0). Before the exact point-segment projection, a segment is rejected when
// both its endpoints lie beyond p[k] + mu or both below p[k] - mu for some coordinate k: the strip
// |x - p.x| <= mu of figure 6.4 and, together with the y test, the rectangle (box in N-D) around
// p. A rejected segment cannot be closer than mu (up to the rounding of mu), and ties keep the
// earlier segment, so the result is the brute-force minimum over the segments.
//
// Degenerate input: zero-length segments act as points; a single vertex is its own closest
// point (t = 0). An empty polyline has no points, and NaN or infinite coordinates have no
// meaning: both give non_finite_distance() (result.hpp). unique is true unless two segments not
// sharing the chosen point tie exactly (not detected; one pair is returned).
// Cost: O(n) with an early rejection of distant segments (a few comparisons each); no allocation.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/segment.hpp>

#include <cmath>
#include <cstddef>
#include <span>

namespace locus {

/// Distance from p to the chain through `v` (closed: also the segment v[n-1] v[0]); param_b is
/// the vertex parameter.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, T> distance_to_polyline(const Vec<T, N>& p,
                                                                     std::span<const Vec<T, N>> v,
                                                                     bool closed) noexcept {
  if (v.empty() || !is_finite(p)) return non_finite_distance<T, N, NoParam, T>();
  for (const Vec<T, N>& x : v)
    if (!is_finite(x)) return non_finite_distance<T, N, NoParam, T>();
  T best = sqr_length(v[0] - p);
  T mu = std::sqrt(best);
  T best_t = T(0);
  Vec<T, N> best_point = v[0];
  const std::size_t m = segment_count(v.size(), closed);
  for (std::size_t i = 0; i < m; ++i) {
    const Segment<T, N> s = edge(v, i);
    bool rejected = false;
    for (int k = 0; k < N && !rejected; ++k) {
      const T lo = p[k] - mu, hi = p[k] + mu;
      rejected = (s.p0[k] > hi && s.p1[k] > hi) || (s.p0[k] < lo && s.p1[k] < lo);
    }
    if (rejected) continue;
    const T lambda = detail::closest_param(detail::view(s), p);
    const Vec<T, N> c = point_at(s, lambda);
    const T q = sqr_length(c - p);
    if (q < best) {
      best = q;
      mu = std::sqrt(q);
      best_t = static_cast<T>(i) + lambda;
      best_point = c;
    }
  }
  return detail::make_distance(p, best_point, NoParam{}, best_t, true);
}

/// Distance from p to the polyline; param_b is the vertex parameter.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, T> distance(const Vec<T, N>& p,
                                                         const Polyline<T, N>& poly) noexcept {
  return distance_to_polyline(p, std::span<const Vec<T, N>>(poly.vertices), poly.closed);
}

/// The swapped query: closest[0] and param_a belong to the polyline.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, NoParam> distance(const Polyline<T, N>& poly,
                                                         const Vec<T, N>& p) noexcept {
  return swapped(distance(p, poly));
}

/// The same for any point range (core/point_range.hpp).
template <PointRange R>
[[nodiscard]] inline Distance<range_scalar_t<R>, range_dimension_v<R>, NoParam, range_scalar_t<R>>
distance_to_polyline(const range_point_t<R>& p, const R& v, bool closed) noexcept {
  return distance_to_polyline(p, point_span(v), closed);
}

}  // namespace locus
