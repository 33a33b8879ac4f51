// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a (solid) triangle in N dimensions (2D and 3D included); rows
// dist2.pt-triangle and dist3.pt-triangle; book sections 6.1.3 (figures 6.5-6.9) and 10.3.2
// (figures 10.8-10.10). Method (KKT over the seven regions of figure 6.6, the 3D fast path):
// docs/notes/distance.md.
//
// distance(p, tri) returns Distance<T, N, NoParam, Vec3<T>>: closest[1] = the point of the
// triangle nearest to p, param_b = its barycentric coordinates (u, v, w) (u + v + w = 1, all
// >= 0; closest[1] = point_at_barycentric(tri, param_b) up to the order of the sum, so a vertex
// is reproduced exactly).
// distance(tri, p) is the swapped result. The triangle is filled: a point inside has distance 0
// (in 2D exactly p itself).
//
// Degenerate input: when the triangle is (nearly) flat, |e0 x e1|^2 <= 64 eps |e0|^2 |e1|^2, the
// answer is the nearest of the three edges (point-segment queries), so collinear and coincident
// vertices give the distance to the segment or point they span. Coordinates beyond ~1e76 or below
// ~1e-76 (double; ~1e9 and ~1e-9 for float) are solved on a copy scaled by a power of two, with
// the barycentric coordinates evaluated on the input (detail/rescale.hpp). NaN or infinite
// coordinates give non_finite_distance() (result.hpp). unique is always true.
// Cost: O(N), one 2x2 solve, one to three point-segment projections.
//
// sqr_distance(p, tri) (either order) returns distance(p, tri).sqr_distance, bit for bit (the
// same core), without the result's closest points, the barycentric coordinates or the square
// root; NaN for non-finite input.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/branchless.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace locus {

namespace detail {

/// What a point-triangle query finds; distance() and sqr_distance() both read it. finite is
/// false (and sqr NaN) exactly when some input coordinate is NaN or infinite.
template <class T, int N>
struct PointTriangleCore {
  Vec3<T> bary;       ///< barycentric (u, v, w) of the closest point
  Vec<T, N> closest;  ///< point_at_barycentric(tri, bary) (up to the order of the sum)
  T sqr;              ///< sqr_length(closest - p)
  bool finite;
};

/// The general point-triangle query (every case; see the header comment).
template <class T, int N>
[[nodiscard]] inline PointTriangleCore<T, N> point_triangle_general(
    const Vec<T, N>& p, const Triangle<T, N>& tri) noexcept {
  if (!all_finite(p, tri.v0, tri.v1, tri.v2)) {
    constexpr T nan = std::numeric_limits<T>::quiet_NaN();
    return {splat<T, 3>(nan), splat<T, N>(nan), nan, false};
  }
  // Coordinates so large or small that products of four leave the range (det would overflow or
  // underflow to 0): solve on a copy scaled by a power of two, and evaluate the closest point
  // from its barycentric coordinates on the input (rescale.hpp).
  const T m = std::max({max_abs(p), max_abs(tri.v0), max_abs(tri.v1), max_abs(tri.v2)});
  if (m > T(0) && outside_product_range(m)) {  // (all zero: f would be 1, no progress)
    const T f = normalising_scale(m);
    const PointTriangleCore<T, N> r =
        point_triangle_general(f * p, Triangle<T, N>{f * tri.v0, f * tri.v1, f * tri.v2});
    if (N == 2 && r.sqr == T(0)) return {r.bary, p, T(0), true};  // inside: p itself
    const Vec<T, N> x = point_at_barycentric(tri, r.bary);
    return {r.bary, x, sqr_length(x - p), true};
  }
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
    if ((ccw || cw) && total != T(0)) return {{a0 / total, a1 / total, a2 / total}, p, T(0), true};
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
        const Vec<T, N> x = point_at_barycentric(tri, bary);
        return {bary, x, sqr_length(x - p), true};
      }
      // A NaN s or t (its numerator overflowed: p is far away) violates every constraint.
      edge02 = !(s >= T(0));
      edge01 = !(t >= T(0));
      edge12 = !(s + t <= T(1));
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
  return {best_bary, point_at_barycentric(tri, best_bary), best, true};
}

/// The fast path of point_triangle for the triangle (o, x, y) (a rotation of the input's
/// vertices): false when it does not apply (see the header comment); otherwise rb, the
/// barycentric coordinates in (o, x, y), cp and sqr. Mirrored lane for lane by the batch kernel
/// (src/distance/batch_kernels.hpp point_triangle_lanes).
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE inline bool point_triangle_fast(const Vec<T, N>& p,
                                                                  const Vec<T, N>& o,
                                                                  const Vec<T, N>& x,
                                                                  const Vec<T, N>& y, Vec3<T>& rb,
                                                                  Vec<T, N>& cp, T& sqr) noexcept {
  const Vec<T, N> e0 = x - o, e1 = y - o, w0 = p - o;
  const T a = dot(e0, e0), b = dot(e0, e1), c = dot(e1, e1);
  const T d = dot(e0, w0), e = dot(e1, w0);
  const T ac = a * c, det = ac - b * b;  // no harmful cancellation when well-shaped
  constexpr T lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
  // Well-shaped (16 |e0 x e1|^2 >= |e0|^2 |e1|^2: Cramer's rule is accurate to a few ulps),
  // no squares or products of squares out of range (a tiny triangle, edges below ~1e-77 in
  // double, has a c = 0 and det = 0: the test above would pass and s = 0 / 0), and finite input:
  // e0, e1 are finite when a, c are (and so are the vertices), and then d, e are finite exactly
  // when p is (a NaN or an infinity in w0 reaches every product). The plane solution's numerators
  // must be finite too: they overflow for a point far away (beyond ~sqrt(max) / |e| from a large
  // triangle), and a NaN there would violate no constraint. The edge x y has its own range test,
  // where it is needed. [[unlikely]]: GCC predicts a floating-point == to be false, took the fast
  // path for cold and left its callees out of line.
  const T sn = c * d - b * e, tn = a * e - b * d;  // det * (s, t) of the plane solution
  if (!(T(16) * det >= ac && a >= lo && c >= lo && ac >= lo && ac <= hi &&
        (d - d) + (e - e) + (sn - sn) + (tn - tn) == T(0))) [[unlikely]]
    return false;
  if (sn >= T(0) && tn >= T(0) && sn + tn <= det) {
    const T s = sn / det, t = tn / det;
    rb = {T(1) - s - t, s, t};
    cp = rb.x * o + rb.y * x + rb.z * y;
  } else {
    // Outside: ONE exact clamped projection onto the edge that holds the minimum (KKT; the rule
    // and why it is exact: docs/notes/distance.md). One violated constraint (t < 0: the edge o x,
    // s < 0: o y, s + t > 1: x y) names its edge; at a corner region the edge along which moving
    // away from the corner descends, else either edge, which then clamps to the corner: at o the
    // edge o x when d > 0 (else o y), at x the edge o x when d < a (else x y), at y the edge o y
    // when e < c (else x y).
    const bool v01 = (tn < T(0)), v02 = (sn < T(0)), v12 = (sn + tn > det);
    const bool use12 = v12 & ((!(v01 | v02)) | (v01 & !(d < a)) | (v02 & !(e < c)));
    const T zero = a - a, one = zero + T(1);  // computed bounds: the clamp becomes max and min
    if (use12) {
      const Vec<T, N> e2 = y - x, w1 = p - x;
      const T f = dot(e2, e2), g = dot(e2, w1);
      if (!(f >= lo && f <= hi && g - g == T(0))) [[unlikely]]
        return false;
      const T l = clamp_minmax(g / f, zero, one), m = T(1) - l;
      rb = {zero, m, l};
      cp = m * x + l * y;  // rb.x o + rb.y x + rb.z y without its zero term (the same value)
    } else if (v02 & ((!v01) | !(d > T(0)))) {
      const T l = clamp_minmax(e / c, zero, one), m = T(1) - l;
      rb = {m, zero, l};
      cp = m * o + l * y;
    } else {
      const T l = clamp_minmax(d / a, zero, one), m = T(1) - l;
      rb = {m, l, zero};
      cp = m * o + l * x;
    }
  }
  sqr = sqr_length(cp - p);
  return true;
}

/// point_triangle for a triangle that is not well-shaped at v0: the origin at the vertex opposite
/// the longest edge, whose angle is the triangle's largest (>= 60 degrees), so that the
/// well-shaped test fails only for needles (largest angle above ~165 degrees), whatever the vertex
/// order. Rotation r: (o, x, y) = (v1, v2, v0) or (v2, v0, v1) (v0 again when v1 v2 is the
/// longest edge), chosen with selects. Out of line: it keeps point_triangle small enough to inline.
template <class T, int N>
[[nodiscard]] PointTriangleCore<T, N> point_triangle_rotated(const Vec<T, N>& p,
                                                             const Triangle<T, N>& tri) noexcept {
  const T l01 = sqr_length(tri.v1 - tri.v0), l02 = sqr_length(tri.v2 - tri.v0);
  const T l12 = sqr_length(tri.v2 - tri.v1);
  const bool keep = l12 >= l01 && l12 >= l02;
  const bool r1 = !keep && l02 >= l01, r2 = !keep && !(l02 >= l01);
  Vec<T, N> o, x, y;
  for (int i = 0; i < N; ++i) {
    o[i] = select(r1, tri.v1[i], select(r2, tri.v2[i], tri.v0[i]));
    x[i] = select(r1, tri.v2[i], select(r2, tri.v0[i], tri.v1[i]));
    y[i] = select(r1, tri.v0[i], select(r2, tri.v1[i], tri.v2[i]));
  }
  Vec3<T> rb{};
  Vec<T, N> cp{};
  T sqr{};
  if (point_triangle_fast(p, o, x, y, rb, cp, sqr)) {
    // The barycentric coordinates back in the triangle's own vertex order.
    const Vec3<T> bary{select(r1, rb.z, select(r2, rb.y, rb.x)),
                       select(r1, rb.x, select(r2, rb.z, rb.y)),
                       select(r1, rb.y, select(r2, rb.x, rb.z))};
    return {bary, cp, sqr, true};
  }
  return point_triangle_general(p, tri);
}

/// The point-triangle query behind distance() and sqr_distance(): the fast path for finite input
/// and a well-shaped triangle in 3D (see the header comment), the general code for everything
/// else.
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE inline PointTriangleCore<T, N> point_triangle(
    const Vec<T, N>& p, const Triangle<T, N>& tri) noexcept {
  if constexpr (N != 2) {
    // The origin at v0 when the angle there is well-shaped (the fast path's own test), which
    // holds for most triangles and needs no rotation; otherwise the rotation.
    Vec3<T> rb{};
    Vec<T, N> cp{};
    T sqr{};
    if (point_triangle_fast(p, tri.v0, tri.v1, tri.v2, rb, cp, sqr)) [[likely]]
      return {rb, cp, sqr, true};
    const Vec<T, N> e0 = tri.v1 - tri.v0, e1 = tri.v2 - tri.v0;
    const T ac0 = dot(e0, e0) * dot(e1, e1), b0 = dot(e0, e1);
    if (!(T(16) * (ac0 - b0 * b0) >= ac0)) return point_triangle_rotated(p, tri);
  }
  return point_triangle_general(p, tri);
}

}  // namespace detail

/// Distance from p to the filled triangle; param_b is barycentric (u, v, w).
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, Vec3<T>> distance(const Vec<T, N>& p,
                                                               const Triangle<T, N>& tri) noexcept {
  const detail::PointTriangleCore<T, N> r = detail::point_triangle(p, tri);
  if (!r.finite) return non_finite_distance<T, N, NoParam, Vec3<T>>();
  // r.sqr is sqr_length(closest - p): make_distance's sum of squares, already computed.
  constexpr T lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
  const T len = r.sqr > lo && r.sqr < hi ? std::sqrt(r.sqr) : length(p - r.closest);
  return {len, r.sqr, {p, r.closest}, NoParam{}, r.bary, true};
}

/// The swapped query: closest[0] and param_a (barycentric) belong to the triangle.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, Vec3<T>, NoParam> distance(const Triangle<T, N>& tri,
                                                               const Vec<T, N>& p) noexcept {
  return swapped(distance(p, tri));
}

/// Squared distance from p to the filled triangle: distance(p, tri).sqr_distance (the same
/// bits), without the closest points, the parameters or the square root; NaN for non-finite
/// input.
template <Real T, int N>
[[nodiscard]] inline T sqr_distance(const Vec<T, N>& p, const Triangle<T, N>& tri) noexcept {
  return detail::point_triangle(p, tri).sqr;
}

/// sqr_distance(p, tri).
template <Real T, int N>
[[nodiscard]] inline T sqr_distance(const Triangle<T, N>& tri, const Vec<T, N>& p) noexcept {
  return sqr_distance(p, tri);
}

}  // namespace locus
