// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a filled planar polygon in 3D; row dist3.pt-polygon; book section
// 10.3.3 (figures 10.14, 10.15).
//
// distance(p, poly) for a PlanarPolygon3 (primitives/planar_polygon.hpp: a plane frame plus the
// polygon's 2D plane coordinates; build one from 3D vertices with planar_polygon()) returns
// Distance<T, 3, NoParam, Vec2<T>>: closest[1] = point_at(poly, param_b), the nearest point of
// the FILLED polygon, param_b = its plane coordinates (s, t). distance(poly, p) is the swapped
// result. The polygon may be non-convex and in either orientation; its filled region is given by
// the even-odd rule (so a self-intersecting polygon is filled as containment's point_in_polygon
// fills it).
//
// Method (figure 10.15): q = p projected into the plane; inside (decided EXACTLY for the rounded
// q: even-odd crossings with orient2d and the half-open rule of figures 13.14-13.17, repeated
// here because the containment layer is above this one) gives q itself; otherwise the nearest
// boundary point by exact-clamp point-segment projections, measured from p in 3D. A q on the
// boundary may be counted either way: both give the same distance.
//
// Degenerate input: one vertex is a point, two a segment (no interior); consecutive repeated
// vertices add zero-length edges, harmlessly. An empty polygon has no points, and NaN or
// infinite values in p, the frame or a vertex give non_finite_distance() (result.hpp). The frame
// is the caller's contract (orthonormal, as plane_frame() builds it; not checked). unique is
// always true (straight edges give finitely many closest points; one is returned). Cost: O(n)
// for n vertices (one pass for inside, one for the edges); no allocation.

#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/planar_polygon.hpp>
#include <locus/primitives/segment.hpp>

#include <cstddef>

namespace locus {

/// Distance from p to the filled planar polygon; param_b = plane coordinates (s, t).
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, Vec2<T>> distance(
    const Vec3<T>& p, const PlanarPolygon3<T>& poly) noexcept {
  const auto& v = poly.polygon.vertices;
  const std::size_t n = v.size();
  bool finite = n > 0 && is_finite(p) && is_finite(poly.frame.origin) && is_finite(poly.frame.u) &&
                is_finite(poly.frame.v) && is_finite(poly.frame.normal);
  for (std::size_t i = 0; i < n && finite; ++i) finite = is_finite(v[i]);
  if (!finite) return non_finite_distance<T, 3, NoParam, Vec2<T>>();

  const Vec2<T> q = to_plane(poly.frame, p);
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2<T>& a = v[j];
    const Vec2<T>& b = v[i];
    if ((a.y > q.y) == (b.y > q.y)) continue;
    // The edge straddles the line y = q.y; it crosses the ray when q is left of it (seen going
    // upward).
    const Sign s = orient2d(a, b, q);
    if (b.y > a.y ? s == Sign::positive : s == Sign::negative) inside = !inside;
  }
  Vec2<T> st = q;
  if (!inside) {
    T best = T(0);
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const auto e = detail::view(Segment2<T>{v[j], v[i]});
      const Vec2<T> c = e.at(detail::closest_param(e, q));
      const T d2 = sqr_length(c - q);
      if (i == 0 || d2 < best) best = d2, st = c;
    }
  }
  return detail::make_distance(p, point_at(poly, st), NoParam{}, st, true);
}

/// The swapped query: closest[0] and param_a belong to the polygon.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, NoParam> distance(const PlanarPolygon3<T>& poly,
                                                               const Vec3<T>& p) noexcept {
  return swapped(distance(p, poly));
}

}  // namespace locus
