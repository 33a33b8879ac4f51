// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a Bézier, B-spline or NURBS curve, in any dimension (2D and 3D
// included); rows dist2.pt-polycurve and dist3.pt-paramcurve; book sections 6.2.3 (figure 6.15)
// and 10.5.3 (figure 10.25). Method (all real roots of a per-span polynomial):
// docs/notes/distance.md.
//
// distance(p, curve) returns Distance<T, N, NoParam, T>: closest[1] = point_at(curve, param_b),
// param_b the curve's own parameter (Bézier: t in [0, 1]; B-spline and NURBS: t in the domain
// [t_d, t_n], curves/bspline.hpp). distance(curve, p) is the swapped result.
// The GLOBAL minimum, not a local Newton iterate: every interior critical point of every span
// and every span end is a candidate, so the distance is accurate to a few ulps of the scale
// whatever the conditioning of the root. Computed in compute_t<T> (double for float).
//
// unique = false when two distinct points of the curve are (to 64 eps relative in the squared
// distance) equally close, e.g. a point on a symmetry axis, or a span at constant distance (a
// NURBS circle arc seen from its centre).
//
// Degenerate input: repeated control points, cusps and zero-length spans are fine (a constant
// span is a point). Degree 0 (a piecewise-constant B-spline) gives the nearest control point of
// the domain. Invalid curves (an empty Bézier curve, validate() != ok for B-splines and NURBS:
// bad knots, non-positive weights, NaN/Inf) and a NaN/Inf point give non_finite_distance().
// Cost: per span O(d^3) for the blossoms (B-splines) plus O(N d^2) for the polynomial and O(d^2)
// Newton steps of the root engine; no allocation for degree <= 12 (B-spline/NURBS validation
// aside; larger degrees use heap scratch, like the curves' own evaluation).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bezier.hpp>
#include <locus/curves/bspline.hpp>
#include <locus/curves/nurbs.hpp>
#include <locus/distance/detail/rational_span.hpp>
#include <locus/distance/result.hpp>

#include <cmath>
#include <cstddef>

namespace locus {

namespace detail {

/// Offers the end points and the interior critical points of one rational span to `tr`.
template <class C, int N>
inline void point_span_candidates(const Vec<C, N + 1>* h, int d, const Vec<C, N>& p, C t0, C t1,
                                  NearestTracker<C, N>& tr) noexcept {
  const Vec<C, N> x0 = span_project<C, N>(h[0]), x1 = span_project<C, N>(h[d]);
  tr.offer(sqr_length(x0 - p), t0, x0);
  tr.offer(sqr_length(x1 - p), t1, x1);
  if (d == 0) return;
  SpanPower<C, N> sp(h, d, p);
  const int len = 2 * d - 1;
  SpanScratch<C, 32 * N> r(static_cast<std::size_t>(N * len)),
      ra(static_cast<std::size_t>(N * len));
  span_derivative_numerator(sp, r.data(), ra.data());
  BoundedPoly<C> g(3 * d - 2);
  for (int k = 0; k < N; ++k)
    for (int i = 0; i <= d; ++i)
      for (int m = 0; m < len; ++m) {
        const auto at = static_cast<std::size_t>(i + m);
        const auto rk = static_cast<std::size_t>(k * len + m);
        g.c[at] += sp.q(k, i) * r[rk];
        g.err[at] += sp.qabs(k, i) * ra[rk];
      }
  const C factor = span_error_factor<C>(d);
  for (int j = 0; j <= g.deg; ++j) g.err[static_cast<std::size_t>(j)] *= factor;
  SpanScratch<C, 40> u(static_cast<std::size_t>(g.deg > 0 ? g.deg : 1));
  const int cnt = span_roots(g, u.data());
  if (cnt < 0) {
    // Constant distance over the span: the end points (already offered) tie; add the middle.
    const Vec<C, N> xm = span_point_at<C, N>(h, d, C(0.5));
    tr.offer(sqr_length(xm - p), t0 + C(0.5) * (t1 - t0), xm);
    return;
  }
  for (int i = 0; i < cnt; ++i) {
    const C s = C(0.5) * (C(1) + u[static_cast<std::size_t>(i)]);
    const Vec<C, N> x = span_point_at<C, N>(h, d, s);
    tr.offer(sqr_length(x - p), t0 + s * (t1 - t0), x);
  }
}

template <class T, int N, class Curve>
[[nodiscard]] inline Distance<T, N, NoParam, T> point_curve_distance(const Vec<T, N>& p,
                                                                     const Curve& c) noexcept {
  if (!is_finite(p) || !curve_ok(c)) return non_finite_distance<T, N, NoParam, T>();
  using C = compute_t<T>;
  NearestTracker<C, N> tr;
  tr.sep2 = static_cast<C>(eps_v<T>) * static_cast<C>(control_box_sqr_size<T, N>(c));
  const Vec<C, N> pc = vec_cast<C>(p);
  for_each_span<C>(c, [&](const Vec<C, N + 1>* h, int d, C t0, C t1) {
    point_span_candidates<C, N>(h, d, pc, t0, t1, tr);
  });
  const T t = static_cast<T>(tr.best_t);
  return make_distance(p, point_at(c, t), NoParam{}, t, !tr.tied(C(64) * static_cast<C>(eps_v<T>)));
}

}  // namespace detail

/// Distance from p to the Bézier curve; param_b is t in [0, 1].
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, T> distance(const Vec<T, N>& p,
                                                         const BezierCurve<T, N>& c) noexcept {
  return detail::point_curve_distance(p, c);
}
/// Distance from p to the B-spline curve; param_b is t in the domain.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, T> distance(const Vec<T, N>& p,
                                                         const BSplineCurve<T, N>& c) noexcept {
  return detail::point_curve_distance(p, c);
}
/// Distance from p to the NURBS curve; param_b is t in the domain.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, T> distance(const Vec<T, N>& p,
                                                         const NurbsCurve<T, N>& c) noexcept {
  return detail::point_curve_distance(p, c);
}

/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, NoParam> distance(const BezierCurve<T, N>& c,
                                                         const Vec<T, N>& p) noexcept {
  return swapped(distance(p, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, NoParam> distance(const BSplineCurve<T, N>& c,
                                                         const Vec<T, N>& p) noexcept {
  return swapped(distance(p, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, NoParam> distance(const NurbsCurve<T, N>& c,
                                                         const Vec<T, N>& p) noexcept {
  return swapped(distance(p, c));
}

}  // namespace locus
