// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery of the linear-polyline distance headers (line/ray/segment to a polyline or
// polygon boundary); row dist2.linear-polyline; book section 6.3.3 (figure 6.22).
//
// The edges are visited in order, keeping the best squared distance mu^2 so far (started from
// edge 0). An edge is rejected without the linear-linear solve when both its endpoints lie in one
// region that is farther than mu from the linear component (figure 6.22's rejection, generalised):
//  * (any N) for a segment, or a component whose direction is zero (a point): beyond the same
//    face of the component's bounding box grown by mu;
//  * (2D, nonzero direction) on the same side of the strip |perp_dot(d, x - o)| <= mu |d| around
//    the component's line, or behind the origin (dot(d, x - o) < -mu |d|: ray and segment), or
//    beyond the far end (dot(d, x - p1) > mu |d|: segment).
// Each region is convex and every point of it is farther than mu, so a rejected edge cannot be
// closer; mu is grown by a bound on the rounding of the distances and of the tests (a few eps *
// scale, scale the largest coordinate magnitude), so that near-ties are solved rather than
// rejected and the answer is exactly the minimum over the edges; ties keep the earlier edge.
// The solve is detail::linear_linear_distance (detail/linear.hpp), so the answer is the
// brute-force minimum over the edges, bit for bit.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/segment.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

namespace locus::detail {

/// distance(l, chain through v) for a line, ray or segment l; param_b is the vertex parameter.
template <class T, int N, class L>
[[nodiscard]] inline Distance<T, N, T, T> linear_polyline_distance(const L& l,
                                                                   std::span<const Vec<T, N>> v,
                                                                   bool closed) noexcept {
  if (v.empty() || !finite_input(l)) return non_finite_distance<T, N, T, T>();
  const LinearView<T, N> lv = view(l);
  T scale = max_abs(lv.origin) + max_abs(lv.end);
  for (const Vec<T, N>& x : v) {
    if (!is_finite(x)) return non_finite_distance<T, N, T, T>();
    scale = std::max(scale, max_abs(x));
  }
  const std::size_t m = segment_count(v.size(), closed);
  if (m == 0) {  // a single vertex: the point-linear query
    const T t = closest_param(lv, v[0]);
    return make_distance(point_at(l, t), v[0], t, T(0), true);
  }
  const bool is_point = !(max_abs(lv.dir) > T(0));
  const bool use_box = lv.bounded_hi || is_point;
  Vec<T, N> box_lo{}, box_hi{};
  if (use_box) {
    const Vec<T, N> e = lv.bounded_hi ? lv.end : lv.origin;
    box_lo = cwise_min(lv.origin, e);
    box_hi = cwise_max(lv.origin, e);
  }
  const T dir_len = length(lv.dir);

  // The rejection radius: mu grown by the rounding error of the per-edge squared distances (a
  // few eps * scale^2, scale the magnitude of the closest points) and of the rejection tests
  // (a few eps * scale), so that an edge is skipped only when its computed distance could not be
  // below the best one: the answer is then exactly the minimum over the edges.
  const T s4 = T(4) * scale;
  const auto radius = [&](T d) {
    return std::sqrt(d * d + T(256) * eps_v<T> * s4 * s4) + T(16) * eps_v<T> * s4;
  };
  Distance<T, N, T, T> best = linear_linear_distance<T, N>(l, edge(v, 0));
  T mu = radius(best.distance);
  for (std::size_t i = 1; i < m; ++i) {
    const Segment<T, N> s = edge(v, i);
    bool rejected = false;
    if (use_box) {
      for (int k = 0; k < N && !rejected; ++k) {
        const T lo = box_lo[k] - mu, hi = box_hi[k] + mu;
        rejected = (s.p0[k] > hi && s.p1[k] > hi) || (s.p0[k] < lo && s.p1[k] < lo);
      }
    }
    if constexpr (N == 2) {
      if (!rejected && !is_point) {
        const T w = mu * dir_len;
        const Vec<T, N> a = s.p0 - lv.origin, b = s.p1 - lv.origin;
        const T sa = perp_dot(lv.dir, a), sb = perp_dot(lv.dir, b);
        rejected = (sa > w && sb > w) || (sa < -w && sb < -w);
        if (!rejected && lv.bounded_lo) rejected = dot(lv.dir, a) < -w && dot(lv.dir, b) < -w;
        if (!rejected && lv.bounded_hi)
          rejected = dot(lv.dir, s.p0 - lv.end) > w && dot(lv.dir, s.p1 - lv.end) > w;
      }
    }
    if (rejected) continue;
    const auto r = linear_linear_distance<T, N>(l, s);
    if (r.sqr_distance < best.sqr_distance) {
      best = r;
      best.param_b = static_cast<T>(i) + r.param_b;
      mu = radius(r.distance);
    }
  }
  return best;
}

}  // namespace locus::detail
