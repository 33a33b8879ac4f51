// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal machinery shared by the line/ray/segment-triangle and line/ray/segment-rectangle
// distance headers (rows dist3.linear-triangle, dist3.linear-rectangle; book sections 10.5.1,
// 10.5.2, figures 10.38-10.43), and reused by the tetrahedron and triangle/rectangle pairs.
// The method (KKT over the prism I x P, the 3 x 7 / 3 x 9 regions of figures 10.40 and 10.43
// without region-specific code): docs/notes/distance.md.
//
// F(t, x) = |A(t) - P(x)|^2 is minimised over the linear parameter t (R, [0, inf) or [0, 1];
// detail/linear.hpp) and the planar piece's parameters x (triangle: s, u >= 0, s + u <= 1;
// rectangle: a box). Well-conditioned cases evaluate the crossing of A with P's plane and only
// the facets whose constraints it violates; nearly parallel directions (sin^2 angle <= 64 eps),
// nearly flat triangles and crossings on a rounding-sensitive boundary evaluate every candidate.
// Every candidate is a realisable pair, so the answer is never below the true distance by more
// than rounding, continuous in the input, and no division can blow up.
//
// Scale: coordinates beyond ~1e76 or below ~1e-76 (double; ~1e9 and ~1e-9 for float) are solved
// on a copy scaled by a power of two (detail/rescale.hpp: the parameters are scale-free).
// unique = false when the direction is parallel to the plane (sin^2 angle <= 64 eps^2) and the
// closest pair can slide along it, or when the winning linear-edge candidate is not unique.
// Exact zero for segment-triangle: segment_meets_triangle() decides with exact orient3d and
// orient2d whether a closed segment meets a closed non-degenerate triangle; the distance is
// exactly 0 only then, and whenever the rounded contact pair agrees to 32 ulps of the largest
// coordinate (both closest points are then the contact point on the triangle).

#include <locus/config.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace locus::detail {

/// The parameters of a closest pair: t on the linear component, param on the planar piece.
template <class T, class P>
struct LinearPlanarParams {
  T t;
  P param;
  bool unique;
};

/// The best realisable candidate so far (smallest squared distance; ties keep the first).
template <class T, class P>
struct BestCandidate {
  T sqr = std::numeric_limits<T>::infinity();
  T t{};
  P param{};
  bool unique = true;
  bool found = false;
  constexpr void offer(T q, T t_, const P& p_, bool unique_) noexcept {
    // A NaN candidate (only from overflowing arithmetic on huge input) is kept only until a
    // comparable one arrives: nothing compares below NaN.
    if (!found || q < sqr || (!(sqr == sqr) && q == q)) {
      sqr = q;
      t = t_;
      param = p_;
      unique = unique_;
      found = true;
    }
  }
};

/// Exact: the closed segment [p, q] and the closed triangle tri (coplanar with it) meet, decided
/// on the projection onto coordinate plane (i, j), in which the triangle is not degenerate.
template <Real T>
[[nodiscard]] inline bool coplanar_segment_meets_triangle(const Vec3<T>& p, const Vec3<T>& q,
                                                          const Triangle3<T>& tri, int i,
                                                          int j) noexcept {
  const auto pr = [&](const Vec3<T>& x) { return Vec2<T>{x[i], x[j]}; };
  const Vec2<T> v[3] = {pr(tri.v0), pr(tri.v1), pr(tri.v2)};
  const Vec2<T> a = pr(p), b = pr(q);
  const Sign o = orient2d(v[0], v[1], v[2]);
  // Separating axes of two convex sets in the plane: the triangle's edges and the segment's line.
  for (int k = 0; k < 3; ++k) {
    const Vec2<T>& u = v[k];
    const Vec2<T>& w = v[(k + 1) % 3];
    if (orient2d(u, w, a) * o == Sign::negative && orient2d(u, w, b) * o == Sign::negative)
      return false;
  }
  const Sign s0 = orient2d(a, b, v[0]), s1 = orient2d(a, b, v[1]), s2 = orient2d(a, b, v[2]);
  if (s0 != Sign::zero && s0 == s1 && s1 == s2) return false;
  return true;
}

/// Exact: 1 when the closed segment [p, q] meets the closed triangle, 0 when it does not, -1
/// when the triangle is degenerate (collinear vertices: not decided here).
template <Real T>
[[nodiscard]] inline int segment_meets_triangle(const Vec3<T>& p, const Vec3<T>& q,
                                                const Triangle3<T>& tri) noexcept {
  const Sign sp = orient3d(tri.v0, tri.v1, tri.v2, p), sq = orient3d(tri.v0, tri.v1, tri.v2, q);
  if (sp != Sign::zero && sp == sq) return 0;  // strictly on one side of the plane
  if (sp == Sign::zero && sq == Sign::zero) {
    // Coplanar (or a degenerate triangle): decide in a coordinate plane where the projected
    // triangle keeps its area (one exists iff the triangle is not degenerate).
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const Vec2<T> a{tri.v0[i], tri.v0[j]}, b{tri.v1[i], tri.v1[j]}, c{tri.v2[i], tri.v2[j]};
      if (orient2d(a, b, c) != Sign::zero)
        return coplanar_segment_meets_triangle(p, q, tri, i, j) ? 1 : 0;
    }
    return -1;
  }
  // The segment reaches the plane and its line is transversal to it: the line passes through
  // the closed triangle iff it sees the three directed edges with no two strictly opposite signs.
  const Sign a = orient3d(p, q, tri.v0, tri.v1), b = orient3d(p, q, tri.v1, tri.v2),
             c = orient3d(p, q, tri.v2, tri.v0);
  const bool pos = a == Sign::positive || b == Sign::positive || c == Sign::positive;
  const bool neg = a == Sign::negative || b == Sign::negative || c == Sign::negative;
  return (pos && neg) ? 0 : 1;
}

template <Real T>
LOCUS_COLD LinearPlanarParams<T, Vec3<T>> linear_triangle_rescaled(const LinearView<T, 3>& A,
                                                                   const Triangle3<T>& tri,
                                                                   int meets) noexcept;

/// Parameters (t on A, barycentric (u, v, w) on tri) of a closest pair of a linear component and
/// a solid triangle. meets: 1 / 0 when the caller knows exactly that they meet / do not meet,
/// -1 when unknown. range_checked: set by linear_triangle_rescaled (below), which handles the
/// squares out of range.
template <Real T>
[[nodiscard]] inline LinearPlanarParams<T, Vec3<T>> linear_triangle(
    const LinearView<T, 3>& A, const Triangle3<T>& tri, int meets,
    bool range_checked = false) noexcept {
  using P = Vec3<T>;
  BestCandidate<T, P> best;
  const auto point_candidate = [&](T t, const Vec3<T>& x) {
    const PointTriangleCore<T, 3> r = point_triangle(x, tri);
    best.offer(r.sqr, t, r.bary, true);
  };
  const Vec3<T>* v[3] = {&tri.v0, &tri.v1, &tri.v2};
  const auto edge_candidate = [&](int i, int j) {
    const Segment3<T> edge{*v[i], *v[j]};
    P bary{};
    if (A.bounded_lo && A.bounded_hi) {
      // A segment: the two-segment query (its fast path is branch-free; detail/linear.hpp).
      const LinearPairCore<T, 3> st = segment_pair(Segment3<T>{A.origin, A.end}, edge);
      bary[i] = T(1) - st.t;
      bary[j] = st.t;
      best.offer(st.sqr, st.s, bary, st.unique);
      return;
    }
    const LinearView<T, 3> E = view(edge);
    const LinLinParams<T> st = linear_linear(A, E);
    bary[i] = T(1) - st.t;
    bary[j] = st.t;
    best.offer(sqr_length(A.at(st.s) - E.at(st.t)), st.s, bary, st.unique);
  };
  if (!(max_abs(A.dir) > T(0))) {  // zero direction: the component is its origin
    point_candidate(T(0), A.origin);
    return {best.t, best.param, true};
  }

  const Vec3<T> e0 = tri.v1 - tri.v0, e1 = tri.v2 - tri.v0;
  const Vec3<T> n = cross(e0, e1);
  const T a = sqr_length(e0), c = sqr_length(e1), nn = sqr_length(n), dd = sqr_length(A.dir);
  const T dn = dot(n, A.dir);
  // Products of four coordinates out of range (|n|^2 and a c overflow, or underflow to 0 and
  // make the triangle look flat): the cold path rescales when the coordinates themselves are
  // beyond the range (see the header comment), from values at hand, so the common case pays two
  // comparisons.
  constexpr T lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
  if (!range_checked && !(a * c >= lo && a * c <= hi && dd >= lo && dd <= hi)) [[unlikely]]
    return linear_triangle_rescaled(A, tri, meets);
  constexpr T eps = eps_v<T>;
  const bool flat = !(nn > T(64) * eps * a * c);
  bool have_crossing = false;
  T tc = T(0);
  if (!flat) {
    // A(t) = v0 + s e0 + u e1  <=>  s e0 + u e1 - t d = w: Cramer's rule with det = -(n . d).
    const Vec3<T> w = A.origin - tri.v0;
    const Vec3<T> m = cross(A.dir, w);
    const T ts = -dot(n, w) / dn, ss = dot(e1, m) / dn, us = -dot(e0, m) / dn;
    if (is_finite(ts) && is_finite(ss) && is_finite(us)) {
      have_crossing = true;
      tc = ts;
      const bool in_t = A.clamp_param(ts) == ts;
      const bool in_tri = ss >= T(0) && us >= T(0) && ss + us <= T(1);
      // Well separated direction (angle above ~14 degrees) and a well-shaped triangle: the
      // crossing is accurate to a few ulps.
      const bool sharp = T(16) * dn * dn >= nn * dd && T(16) * nn >= a * c;
      if (in_t && in_tri) {
        if (meets != 0 && sharp) return {ts, P{T(1) - (ss + us), ss, us}, true};
      } else if (meets != 1 && T(64) * eps * nn * dd < dn * dn) {
        // Only the facets whose constraints the crossing violates (KKT, see the header). An
        // end's pair is optimal outright when moving into the component does not approach the
        // triangle: the domain is a product, so blockwise optimality is optimality.
        if (A.bounded_lo && ts < T(0)) {
          const PointTriangleCore<T, 3> r = point_triangle(A.origin, tri);
          best.offer(r.sqr, T(0), r.bary, true);
          if (dot(A.dir, A.origin - r.closest) >= T(0)) return {T(0), r.bary, true};
        }
        if (A.bounded_hi && ts > T(1)) {
          const PointTriangleCore<T, 3> r = point_triangle(A.end, tri);
          best.offer(r.sqr, T(1), r.bary, true);
          if (dot(A.dir, A.end - r.closest) <= T(0)) return {T(1), r.bary, true};
        }
        if (ss < T(0)) edge_candidate(0, 2);
        if (us < T(0)) edge_candidate(0, 1);
        if (ss + us > T(1)) edge_candidate(1, 2);
        return {best.t, best.param, true};
      }
    }
  }

  // Every candidate (nearly parallel, nearly flat, or a crossing on a rounding-sensitive
  // boundary). The crossing enters as a realisable pair: its point on A projected onto the
  // triangle, then that point projected back onto A and onto the triangle again.
  if (have_crossing) {
    const T t0 = A.clamp_param(tc);
    const PointTriangleCore<T, 3> r0 = point_triangle(A.at(t0), tri);
    best.offer(r0.sqr, t0, r0.bary, true);
    const T t1 = closest_param(A, r0.closest);
    point_candidate(t1, A.at(t1));
  }
  if (A.bounded_lo) point_candidate(T(0), A.origin);
  if (A.bounded_hi) point_candidate(T(1), A.end);
  edge_candidate(0, 1);
  edge_candidate(0, 2);
  edge_candidate(1, 2);

  bool unique = best.unique;
  if (!flat && dn * dn <= T(64) * eps * eps * nn * dd) {
    // Parallel to the plane: does the pair slide? The barycentric velocity of moving along d
    // (d projected into the plane, solved on the Gram matrix whose determinant is nn).
    const T b = dot(e0, e1), d0 = dot(e0, A.dir), d1 = dot(e1, A.dir);
    const T ds = (c * d0 - b * d1) / nn, du = (a * d1 - b * d0) / nn;
    const P db{-(ds + du), ds, du};
    const T tol = T(8) * eps * max_abs(db);
    for (const T sigma : {T(1), T(-1)}) {
      bool ok =
          sigma > T(0) ? !(A.bounded_hi && best.t >= T(1)) : !(A.bounded_lo && best.t <= T(0));
      for (int i = 0; i < 3 && ok; ++i)
        if (!(best.param[i] > T(0)) && sigma * db[i] < -tol) ok = false;
      if (ok) unique = false;
    }
  }
  return {best.t, best.param, unique};
}

/// linear_triangle on the input scaled by the power of two that brings its largest coordinate
/// into [1, 2), when that coordinate lies beyond the product range (detail/rescale.hpp: the
/// parameters are scale-free); otherwise on the input itself. (The batch kernel accepts a smaller
/// range and leaves these to this code.)
template <Real T>
LOCUS_COLD LinearPlanarParams<T, Vec3<T>> linear_triangle_rescaled(const LinearView<T, 3>& A,
                                                                   const Triangle3<T>& tri,
                                                                   int meets) noexcept {
  const T m = std::max({max_abs(A.origin), max_abs(A.end), max_abs(A.dir), max_abs(tri.v0),
                        max_abs(tri.v1), max_abs(tri.v2)});
  const T f = m > T(0) && outside_product_range(m) ? normalising_scale(m) : T(1);
  return linear_triangle(scaled_view(A, f), Triangle3<T>{f * tri.v0, f * tri.v1, f * tri.v2}, meets,
                         true);
}

/// What a linear-triangle query finds; distance() and sqr_distance() both read it. finite is
/// false (and sqr NaN) exactly when some input coordinate is NaN or infinite.
template <Real T>
struct LinearTriangleCore {
  T t;                             ///< parameter on the linear component
  Vec3<T> bary;                    ///< barycentric on the triangle
  std::array<Vec3<T>, 2> closest;  ///< on the component, on the triangle
  T sqr;                           ///< sqr_length(closest[0] - closest[1])
  bool unique;
  bool finite;
};

template <class T, class L>
[[nodiscard]] inline LinearTriangleCore<T> linear_triangle_core(const L& l,
                                                                const Triangle3<T>& tri) noexcept {
  if (!(finite_input(l) && all_finite(tri.v0, tri.v1, tri.v2))) {
    constexpr T nan = std::numeric_limits<T>::quiet_NaN();
    return {nan, splat<T, 3>(nan), {splat<T, 3>(nan), splat<T, 3>(nan)}, nan, false, false};
  }
  int meets = -1;
  if constexpr (std::is_same_v<L, Segment3<T>>) meets = segment_meets_triangle(l.p0, l.p1, tri);
  const LinearPlanarParams<T, Vec3<T>> r = linear_triangle(view(l), tri, meets);
  const Vec3<T> on_line = point_at(l, r.t), on_tri = point_at_barycentric(tri, r.param);
  // They meet exactly: report the contact as one point when the rounded pair agrees to a few
  // ulps of the coordinates' magnitude (every well-conditioned contact). A needle triangle or a
  // grazing segment can leave the rounded pair ~eps / angle apart; the pair is then reported as it
  // is.
  const auto scale = [&] {
    const T a = max_abs(tri.v0), b = max_abs(tri.v1), c = max_abs(tri.v2), d = max_abs(on_line);
    const T ab = a > b ? a : b, cd = c > d ? c : d;
    return ab > cd ? ab : cd;
  };
  if (meets == 1 && max_abs(on_line - on_tri) <= T(32) * eps_v<T> * scale())
    return {r.t, r.param, {on_tri, on_tri}, T(0), r.unique, true};
  return {r.t, r.param, {on_line, on_tri}, sqr_length(on_line - on_tri), r.unique, true};
}

/// distance(l, tri) for a line, ray or segment and a solid triangle in 3D.
template <class T, class L>
[[nodiscard]] inline Distance<T, 3, T, Vec3<T>> linear_triangle_distance(
    const L& l, const Triangle3<T>& tri) noexcept {
  const LinearTriangleCore<T> r = linear_triangle_core(l, tri);
  if (!r.finite) return non_finite_distance<T, 3, T, Vec3<T>>();
  return make_distance(r.closest[0], r.closest[1], r.t, r.bary, r.unique);
}

/// Parameters (t on A, (s, t) on rect) of a closest pair of a linear component and a solid
/// rectangle in 3D; the work is done in the rectangle's frame (center, axis[0], axis[1],
/// axis[0] x axis[1]), where the rectangle is the box [-e0, e0] x [-e1, e1] x {0}.
template <Real T>
[[nodiscard]] inline LinearPlanarParams<T, Vec2<T>> linear_rectangle(
    const LinearView<T, 3>& world, const Rectangle<T, 3>& rect) noexcept {
  using P = Vec2<T>;
  const Vec3<T> ax = rect.axis[0], ay = rect.axis[1], az = cross(ax, ay);
  const auto local_dir = [&](const Vec3<T>& x) {
    return Vec3<T>{dot(x, ax), dot(x, ay), dot(x, az)};
  };
  const auto local = [&](const Vec3<T>& x) { return local_dir(x - rect.center); };
  LinearView<T, 3> A = world;
  A.origin = local(world.origin);
  if (world.bounded_hi) {
    A.end = local(world.end);
    A.dir = A.end - A.origin;
  } else {
    A.end = A.origin;
    A.dir = local_dir(world.dir);
  }
  const T ex = rect.extent[0] > T(0) ? rect.extent[0] : T(0);
  const T ey = rect.extent[1] > T(0) ? rect.extent[1] : T(0);

  BestCandidate<T, P> best;
  const auto point_candidate = [&](T t, const Vec3<T>& x) {
    const P st{clamp(x.x, -ex, ex), clamp(x.y, -ey, ey)};
    best.offer(sqr(x.x - st.x) + sqr(x.y - st.y) + sqr(x.z), t, st, true);
  };
  // Edge k: 0 s = -ex, 1 s = +ex (t from -ey to ey); 2 t = -ey, 3 t = +ey (s from -ex to ex).
  const auto edge_candidate = [&](int k) {
    const T fixed = (k == 0) ? -ex : (k == 1) ? ex : (k == 2) ? -ey : ey;
    const T half = k < 2 ? ey : ex;
    const Vec3<T> p0 = k < 2 ? Vec3<T>{fixed, -half, T(0)} : Vec3<T>{-half, fixed, T(0)};
    const Vec3<T> p1 = k < 2 ? Vec3<T>{fixed, half, T(0)} : Vec3<T>{half, fixed, T(0)};
    const LinearView<T, 3> E = view(Segment3<T>{p0, p1});
    const LinLinParams<T> st = linear_linear(A, E);
    const T along = (T(1) - st.t) * -half + st.t * half;  // lerp(-half, half, t), exact at ends
    const P param = k < 2 ? P{fixed, along} : P{along, fixed};
    best.offer(sqr_length(A.at(st.s) - E.at(st.t)), st.s, param, st.unique);
  };
  if (!(max_abs(A.dir) > T(0))) {
    point_candidate(T(0), A.origin);
    return {best.t, best.param, true};
  }

  const T dd = sqr_length(A.dir), dz = A.dir.z;
  constexpr T eps = eps_v<T>;
  const T ts = -A.origin.z / dz;
  bool have_crossing = false;
  if (is_finite(ts)) {
    have_crossing = true;
    const Vec3<T> x = A.at(ts);
    const bool in_t = A.clamp_param(ts) == ts;
    const bool in_rect = x.x >= -ex && x.x <= ex && x.y >= -ey && x.y <= ey;
    if (in_t && in_rect) {
      if (T(16) * dz * dz >= dd) return {ts, P{x.x, x.y}, true};
    } else if (T(64) * eps * dd < dz * dz) {
      // An end's pair is optimal outright when moving into the component does not approach the
      // rectangle (blockwise optimality on the product domain).
      const auto end_optimal = [&](T t, const Vec3<T>& p) {
        point_candidate(t, p);
        const T g = A.dir.x * (p.x - best.param.x) + A.dir.y * (p.y - best.param.y) + A.dir.z * p.z;
        return t == T(0) ? g >= T(0) : g <= T(0);
      };
      if (A.bounded_lo && ts < T(0) && end_optimal(T(0), A.origin)) return {T(0), best.param, true};
      if (A.bounded_hi && ts > T(1) && end_optimal(T(1), A.end)) return {T(1), best.param, true};
      if (x.x < -ex) edge_candidate(0);
      if (x.x > ex) edge_candidate(1);
      if (x.y < -ey) edge_candidate(2);
      if (x.y > ey) edge_candidate(3);
      return {best.t, best.param, true};
    }
  }

  if (have_crossing) {
    const T t0 = A.clamp_param(ts);
    point_candidate(t0, A.at(t0));
    const P st0 = best.param;
    const T t1 = closest_param(A, Vec3<T>{st0.x, st0.y, T(0)});
    point_candidate(t1, A.at(t1));
  }
  if (A.bounded_lo) point_candidate(T(0), A.origin);
  if (A.bounded_hi) point_candidate(T(1), A.end);
  for (int k = 0; k < 4; ++k) edge_candidate(k);

  bool unique = best.unique;
  if (dz * dz <= T(64) * eps * eps * dd) {
    // Parallel to the plane: the pair slides unless a side of the rectangle (or an end of the
    // component) blocks the motion along d in both directions.
    const T tol = T(8) * eps * length(A.dir);
    const T e[2] = {ex, ey};
    for (const T sigma : {T(1), T(-1)}) {
      bool ok =
          sigma > T(0) ? !(A.bounded_hi && best.t >= T(1)) : !(A.bounded_lo && best.t <= T(0));
      for (int i = 0; i < 2 && ok; ++i) {
        const T v = sigma * A.dir[i];
        if (!(e[i] > T(0)) && std::abs(v) > tol) ok = false;
        if (best.param[i] >= e[i] && v > tol) ok = false;
        if (best.param[i] <= -e[i] && v < -tol) ok = false;
      }
      if (ok) unique = false;
    }
  }
  return {best.t, best.param, unique};
}

/// distance(l, rect) for a line, ray or segment and a solid rectangle in 3D.
template <class T, class L>
[[nodiscard]] inline Distance<T, 3, T, Vec2<T>> linear_rectangle_distance(
    const L& l, const Rectangle<T, 3>& rect) noexcept {
  if (!finite_input(l) || !is_finite(rect.center) || !is_finite(rect.axis[0]) ||
      !is_finite(rect.axis[1]) || !is_finite(rect.extent[0]) || !is_finite(rect.extent[1]))
    return non_finite_distance<T, 3, T, Vec2<T>>();
  const LinearPlanarParams<T, Vec2<T>> r = linear_rectangle(view(l), rect);
  return make_distance(point_at(l, r.t), point_at(rect, r.param), r.t, r.param, r.unique);
}

}  // namespace locus::detail
