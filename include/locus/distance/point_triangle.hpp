// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a (solid) triangle in N dimensions (2D and 3D included); rows
// dist2.pt-triangle and dist3.pt-triangle; book sections 6.1.3 (figures 6.5-6.9) and 10.3.2
// (figures 10.8-10.10).
//
// distance(p, tri) returns Distance<T, N, NoParam, Vec3<T>>: closest[1] = the point of the
// triangle nearest to p, param_b = its barycentric coordinates (u, v, w) (u + v + w = 1, all
// >= 0; closest[1] = point_at_barycentric(tri, param_b), so a vertex is reproduced exactly).
// distance(tri, p) is the swapped result. The triangle is filled: a point inside has distance 0.
//
// Method: minimise |v0 + s (v1 - v0) + t (v2 - v0) - p|^2 over s, t >= 0, s + t <= 1 (the
// parametric form of figure 5.4, (u, v, w) = (1 - s - t, s, t)). The unconstrained minimiser
// (the projection onto the triangle's plane, solved by Cramer's rule, plus two steps of iterative
// refinement when the angle at v0 is within ~14 degrees of 0 or 180) is the answer when it is
// inside (region 0 of figure 6.6); in 2D "inside" is decided first from the sub-areas relative to
// p, and then the answer is p itself (distance exactly 0). Otherwise the answer lies on an edge
// whose constraint the minimiser violates (KKT: moving towards the minimiser along a feasible
// direction would decrease the distance): s < 0 gives the edge v0 v2 (regions 2, 3, 4), t < 0 the
// edge v0 v1 (regions 4, 5, 6), s + t > 1 the edge v1 v2 (regions 1, 2, 6); each is an exact
// clamped point-segment projection, and the nearest of those edges wins. This covers the seven
// regions of figure 6.6 without region-specific code, and the vertex regions come out of the clamps
// exactly. In 3D the common case (finite input, well-shaped triangle) runs as a compact fast path
// that performs the same operations in the same order (same results), testing the finiteness
// of all the input with one branch; everything else goes through the general code.
//
// Degenerate input: when the triangle is (nearly) flat, |e0 x e1|^2 <= 64 eps |e0|^2 |e1|^2 (the
// plane solve is ill-conditioned), the answer is the nearest of the three edges, each handled as a
// point-segment query (plus the plane solution when it still lands inside), so collinear and
// coincident vertices give the distance to the segment or point they span. NaN or infinite
// coordinates give non_finite_distance() (result.hpp). unique is always true. Cost: O(N), one 2x2
// solve, one to three point-segment projections.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <limits>

namespace locus {

namespace detail {

/// The sum of x - x over the coordinates: exactly 0 when every coordinate is finite, NaN
/// otherwise; lets a fast path test all its input with one branch.
template <class T, int N>
[[nodiscard]] constexpr T finite_probe(const Vec<T, N>& v) noexcept {
  T z = T(0);
  for (int i = 0; i < N; ++i) z += v[i] - v[i];
  return z;
}

/// The general point-triangle query (every case; see the header comment).
template <class T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, Vec3<T>> point_triangle_general(
    const Vec<T, N>& p, const Triangle<T, N>& tri) noexcept {
  if (!is_finite(p) || !is_finite(tri.v0) || !is_finite(tri.v1) || !is_finite(tri.v2))
    return non_finite_distance<T, N, NoParam, Vec3<T>>();
  const Vec<T, N> e0 = tri.v1 - tri.v0, e1 = tri.v2 - tri.v0, w = tri.v0 - p;
  const T a = dot(e0, e0), b = dot(e0, e1), c = dot(e1, e1), d = dot(e0, w), e = dot(e1, w);
  const T det = detail::sqr_cross_norm(e0, e1);  // a c - b^2 without cancellation

  bool edge01 = true, edge02 = true, edge12 = true;  // edges to try when not inside
  Vec3<T> best_bary{T(1), T(0), T(0)};
  T best = T(0);
  bool found = false;
  const auto consider = [&](const Vec3<T>& bary) {
    const T q = sqr_length(point_at_barycentric(tri, bary) - p);
    if (!found || q < best) {
      best = q;
      best_bary = bary;
      found = true;
    }
  };
  if constexpr (N == 2) {
    // In the plane a point inside is its own closest point: decide inside by the signs of the
    // sub-areas taken relative to p (accurate for thin triangles, where the 2x2 solve is not),
    // and return p itself with barycentric coordinates from the same sub-areas.
    const Vec2<T> q0 = tri.v0 - p, q1 = tri.v1 - p, q2 = tri.v2 - p;
    const T a0 = perp_dot(q1, q2), a1 = perp_dot(q2, q0), a2 = perp_dot(q0, q1);
    const T total = a0 + a1 + a2;
    const bool ccw = a0 >= T(0) && a1 >= T(0) && a2 >= T(0);
    const bool cw = a0 <= T(0) && a1 <= T(0) && a2 <= T(0);
    if ((ccw || cw) && total != T(0)) {
      const Vec3<T> bary{a0 / total, a1 / total, a2 / total};
      return {T(0), T(0), {p, p}, NoParam{}, bary, true};
    }
  }
  if (det > T(0)) {
    T s = (b * e - c * d) / det, t = (b * d - a * e) / det;
    // Two steps of iterative refinement when the triangle is thin: Cramer's rule loses accuracy
    // (relative error ~ eps a c / det); the residual p - X(s, t) is computed directly.
    const int steps = T(16) * det >= a * c ? 0 : 2;  // well-shaped: already a few ulps
    for (int k = 0; k < steps; ++k) {
      const Vec<T, N> res = p - (tri.v0 + s * e0 + t * e1);
      const T g0 = dot(e0, res), g1 = dot(e1, res);
      s += (c * g0 - b * g1) / det;
      t += (a * g1 - b * g0) / det;
    }
    const bool inside = s >= T(0) && t >= T(0) && s + t <= T(1);
    if (det > T(64) * eps_v<T> * a * c) {
      if (inside) {
        const Vec3<T> bary{T(1) - s - t, s, t};
        return detail::make_distance(p, point_at_barycentric(tri, bary), NoParam{}, bary, true);
      }
      edge02 = s < T(0);
      edge01 = t < T(0);
      edge12 = s + t > T(1);
    } else if (inside) {
      // Nearly flat: the plane solve is inaccurate but its point is still a point of the
      // triangle; it competes with the three edges (a point inside a thin 2D triangle is at 0).
      consider(Vec3<T>{T(1) - s - t, s, t});
    }
  }
  const auto edge = [&](const Vec<T, N>& from, const Vec<T, N>& to, int i, int j) {
    const T lambda = detail::closest_param(detail::view(Segment<T, N>{from, to}), p);
    Vec3<T> bary{};
    bary[i] = T(1) - lambda;
    bary[j] = lambda;
    consider(bary);
  };
  if (edge01) edge(tri.v0, tri.v1, 0, 1);
  if (edge02) edge(tri.v0, tri.v2, 0, 2);
  if (edge12) edge(tri.v1, tri.v2, 1, 2);
  return detail::make_distance(p, point_at_barycentric(tri, best_bary), NoParam{}, best_bary, true);
}

}  // namespace detail

/// Distance from p to the filled triangle; param_b is barycentric (u, v, w).
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, Vec3<T>> distance(const Vec<T, N>& p,
                                                               const Triangle<T, N>& tri) noexcept {
  if constexpr (N != 2) {
    // Fast path for finite input and a well-shaped triangle (16 |e0 x e1|^2 >= |e0|^2 |e1|^2,
    // no refinement, well conditioned), the common case: the same operations, in the same
    // order, as the general code takes for it (so the same bits), with one branch for the
    // finiteness of the input and no bookkeeping. Edges v0 v1 and v0 v2 reuse the dot products:
    // dot(p - v0, e) = -dot(e, v0 - p) exactly.
    const T probe = detail::finite_probe(p) + detail::finite_probe(tri.v0) +
                    detail::finite_probe(tri.v1) + detail::finite_probe(tri.v2);
    if (probe == T(0)) {
      const Vec<T, N> e0 = tri.v1 - tri.v0, e1 = tri.v2 - tri.v0, w = tri.v0 - p;
      const T a = dot(e0, e0), b = dot(e0, e1), c = dot(e1, e1), d = dot(e0, w), e = dot(e1, w);
      const T det = detail::sqr_cross_norm(e0, e1);
      const T ac = a * c;
      constexpr T lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
      if (T(16) * det >= ac && a >= lo && c >= lo && ac <= hi) {
        const T s = (b * e - c * d) / det, t = (b * d - a * e) / det;
        Vec3<T> bary{T(1) - s - t, s, t};
        if (!(s >= T(0) && t >= T(0) && s + t <= T(1))) {
          // KKT: only the edges whose constraints the plane solution violates; ties keep the
          // first in the order v0 v1, v0 v2, v1 v2.
          T best = T(-1);  // none yet (q may overflow to inf: the first edge is still taken)
          const auto edge = [&](const Vec3<T>& cand) {
            const T q = sqr_length(point_at_barycentric(tri, cand) - p);
            if (best < T(0) || q < best) best = q, bary = cand;
          };
          if (t < T(0)) {
            const T l = clamp(-d / a, T(0), T(1));
            edge(Vec3<T>{T(1) - l, l, T(0)});
          }
          if (s < T(0)) {
            const T l = clamp(-e / c, T(0), T(1));
            edge(Vec3<T>{T(1) - l, T(0), l});
          }
          if (s + t > T(1)) {
            const T l = detail::closest_param(detail::view(Segment<T, N>{tri.v1, tri.v2}), p);
            edge(Vec3<T>{T(0), T(1) - l, l});
          }
        }
        return detail::make_distance(p, point_at_barycentric(tri, bary), NoParam{}, bary, true);
      }
    }
  }
  return detail::point_triangle_general(p, tri);
}

/// The swapped query: closest[0] and param_a (barycentric) belong to the triangle.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, Vec3<T>, NoParam> distance(const Triangle<T, N>& tri,
                                                               const Vec<T, N>& p) noexcept {
  return swapped(distance(p, tri));
}

}  // namespace locus
