// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a solid orthogonal frustum, in 3D (Frustum3) and 2D (Frustum2,
// a trapezoid); rows dist2.pt-frustum and dist3.pt-frustum; book sections 6.1.5 (figures 6.11,
// 6.12) and 10.4.3 (figure 10.23). Method (only the faces whose plane p is outside of, every
// Voronoi region of figure 10.23 without region-specific code): docs/notes/distance.md.
//
// distance(p, fr) returns Distance<T, 3, NoParam, Vec3<T>> for Frustum3 and
// Distance<T, 2, NoParam, Vec2<T>> for Frustum2: closest[1] = the frustum point nearest to p,
// param_b = its frustum coordinates (s, t, w) (resp. (s, w)) of primitives/frustum.hpp, so
// closest[1] ~ point_at(fr, param_b): s, t in [-1, 1] across the right/up (left) bounds, w in
// [0, 1] from the near face to the far face. distance(fr, p) is the swapped result. The frustum
// is solid: a point inside has distance 0 and is its own closest point.
//
// Degenerate input: d_max == d_min (a flat frustum: a rectangle/segment) and zero bounds (r, u
// or l = 0: flat) are handled like any other frustum (the faces degenerate to segments or
// points). The frame vectors must be orthonormal (the frustum's contract, not checked). An invalid
// frustum (d_min <= 0, d_max < d_min, a negative bound: is_valid() false) has no meaning here,
// and NaN or infinite values neither: both give non_finite_distance() (result.hpp). unique is
// always true (the frustum is convex). Cost: O(1): a frame change, at most two clamps and four
// point-triangle queries (3D) or three point-segment projections (2D); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/frustum.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

namespace locus {

/// Distance from p to the solid 3D orthogonal frustum; param_b = (s, t, w).
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, Vec3<T>> distance(const Vec3<T>& p,
                                                               const Frustum3<T>& fr) noexcept {
  if (!is_finite(p) || !is_finite(fr.origin) || !is_finite(fr.direction) || !is_finite(fr.up) ||
      !is_finite(fr.right) || !is_valid(fr))
    return non_finite_distance<T, 3, NoParam, Vec3<T>>();
  const T n = fr.d_min, f = fr.d_max, r = fr.r_bound, u = fr.u_bound;
  const Vec3<T> rel = p - fr.origin;
  const T x0 = dot(rel, fr.right), y0 = dot(rel, fr.up), z = dot(rel, fr.direction);
  const T sx = x0 < T(0) ? T(-1) : T(1), sy = y0 < T(0) ? T(-1) : T(1);
  const T x = sx * x0, y = sy * y0;

  const bool out_near = z<n, out_far = z> f;
  const bool out_right = x * n > r * z, out_top = y * n > u * z;
  Vec3<T> q{x, y, z};  // nearest point, reflected frame coordinates
  if (out_near || out_far || out_right || out_top) {
    const T q_ratio = f / n;  // far face = near face scaled by f / n
    const T rf = r * q_ratio, uf = u * q_ratio;
    const Vec3<T> local{x, y, z};
    T best = std::numeric_limits<T>::infinity();
    const auto consider = [&](const Vec3<T>& c) {
      const T d2 = sqr_length(c - local);
      if (d2 < best) best = d2, q = c;
    };
    if (out_near) consider(Vec3<T>{x < r ? x : r, y < u ? y : u, n});
    if (out_far) consider(Vec3<T>{x < rf ? x : rf, y < uf ? y : uf, f});
    if (out_right) {  // trapezoid (r, 0, n) (r, u, n) (rf, uf, f) (rf, 0, f)
      const Vec3<T> a{r, T(0), n}, b{r, u, n}, c{rf, uf, f}, d{rf, T(0), f};
      consider(distance(local, Triangle3<T>{a, b, c}).closest[1]);
      consider(distance(local, Triangle3<T>{a, c, d}).closest[1]);
    }
    if (out_top) {  // trapezoid (0, u, n) (r, u, n) (rf, uf, f) (0, uf, f)
      const Vec3<T> a{T(0), u, n}, b{r, u, n}, c{rf, uf, f}, d{T(0), uf, f};
      consider(distance(local, Triangle3<T>{a, b, c}).closest[1]);
      consider(distance(local, Triangle3<T>{a, c, d}).closest[1]);
    }
  }
  // Back to the unreflected frame, then frustum coordinates and world.
  const T qx = sx * q.x, qy = sy * q.y, qz = q.z;
  const T scale = qz / n;  // the cross-section at depth qz is the near face scaled by qz / n
  Vec3<T> stw{};
  stw.x = r > T(0) ? clamp(qx / (scale * r), T(-1), T(1)) : T(0);
  stw.y = u > T(0) ? clamp(qy / (scale * u), T(-1), T(1)) : T(0);
  stw.z = f > n ? clamp((qz - n) / (f - n), T(0), T(1)) : T(0);
  const Vec3<T> world = fr.origin + qz * fr.direction + qx * fr.right + qy * fr.up;
  if (!(out_near || out_far || out_right || out_top))
    return detail::make_distance(p, p, NoParam{}, stw, true);
  return detail::make_distance(p, world, NoParam{}, stw, true);
}

/// The swapped query: closest[0] and param_a belong to the frustum.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec3<T>, NoParam> distance(const Frustum3<T>& fr,
                                                               const Vec3<T>& p) noexcept {
  return swapped(distance(p, fr));
}

/// Distance from p to the solid 2D orthogonal frustum (trapezoid); param_b = (s, w).
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, Vec2<T>> distance(const Vec2<T>& p,
                                                               const Frustum2<T>& fr) noexcept {
  if (!is_finite(p) || !is_finite(fr.origin) || !is_finite(fr.direction) || !is_finite(fr.left) ||
      !is_valid(fr))
    return non_finite_distance<T, 2, NoParam, Vec2<T>>();
  const T n = fr.d_min, f = fr.d_max, l = fr.l_bound;
  const Vec2<T> rel = p - fr.origin;
  const T x0 = dot(rel, fr.left), z = dot(rel, fr.direction);
  const T sx = x0 < T(0) ? T(-1) : T(1);
  const T x = sx * x0;

  const bool out_near = z<n, out_far = z> f, out_side = x * n > l * z;
  Vec2<T> q{x, z};
  if (out_near || out_far || out_side) {
    const T lf = l * (f / n);
    const Vec2<T> local{x, z};
    T best = std::numeric_limits<T>::infinity();
    const auto consider = [&](const Vec2<T>& c) {
      const T d2 = sqr_length(c - local);
      if (d2 < best) best = d2, q = c;
    };
    if (out_near) consider(Vec2<T>{x < l ? x : l, n});
    if (out_far) consider(Vec2<T>{x < lf ? x : lf, f});
    if (out_side) {
      const Segment2<T> side{Vec2<T>{l, n}, Vec2<T>{lf, f}};
      consider(point_at(side, detail::closest_param(detail::view(side), local)));
    }
  }
  const T qx = sx * q.x, qz = q.y;
  const T scale = qz / n;
  Vec2<T> sw{};
  sw.x = l > T(0) ? clamp(qx / (scale * l), T(-1), T(1)) : T(0);
  sw.y = f > n ? clamp((qz - n) / (f - n), T(0), T(1)) : T(0);
  if (!(out_near || out_far || out_side)) return detail::make_distance(p, p, NoParam{}, sw, true);
  const Vec2<T> world = fr.origin + qz * fr.direction + qx * fr.left;
  return detail::make_distance(p, world, NoParam{}, sw, true);
}

/// The swapped query: closest[0] and param_a belong to the frustum.
template <Real T>
[[nodiscard]] inline Distance<T, 2, Vec2<T>, NoParam> distance(const Frustum2<T>& fr,
                                                               const Vec2<T>& p) noexcept {
  return swapped(distance(p, fr));
}

}  // namespace locus
