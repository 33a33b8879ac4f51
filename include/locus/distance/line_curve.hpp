// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a line, ray or segment and a Bézier, B-spline or NURBS curve, in any
// dimension N >= 2; row dist2.linear-curve (polynomial-curve part; the 3D pairs come along);
// book section 6.4, figure 6.23. Method (global minimum over a candidate set that contains
// every minimiser, all real roots of per-span polynomials): docs/notes/distance.md.
//
// distance(linear, curve) returns Distance<T, N, T, T>: param_a is the linear parameter of
// closest[0] (Line: t in R, Ray: t >= 0, Segment: t in [0, 1], as point_at), param_b the curve's
// own parameter of closest[1] (Bézier: [0, 1]; B-spline and NURBS: the domain [t_d, t_n],
// curves/bspline.hpp); closest[0] = point_at(linear, param_a), closest[1] = point_at(curve,
// param_b). distance(curve, linear) is the swapped result.
// Computed in compute_t<T> (double for float); the returned points are evaluated in T at the
// returned parameters (param_b the winning curve parameter rounded to T, param_a the clamped
// projection of its point), so in float a very short knot span can sit measurably off a crossing.
//
// unique = false when infinitely many closest pairs exist: the distance is constant along a piece
// of the curve (a straight span parallel to the line or lying on it, in 3D an arc of a circle
// around the line). Finitely many tied pairs return one pair with unique = true.
//
// Degenerate input: a zero direction (zero-length segment) acts as its point: the point-curve
// query (point_curve.hpp), param_a = 0. Repeated control points, cusps and zero-length spans are
// fine. Degree 0 gives the nearest control point of the domain. Invalid curves (an empty Bézier
// curve, validate() != ok: bad knots, non-positive weights, NaN/Inf) and NaN or infinite linear
// input give non_finite_distance() (result.hpp).
// Cost: per span the blossoms (B-splines, O(d^3)), O(N d^2) per polynomial and their roots
// (O(d^2) Newton steps each); no allocation for degree <= 12 (B-spline/NURBS validation aside).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bezier.hpp>
#include <locus/curves/bspline.hpp>
#include <locus/curves/nurbs.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/detail/pair_candidates.hpp>
#include <locus/distance/detail/rational_span.hpp>
#include <locus/distance/point_curve.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace locus {

namespace detail {

/// M orthonormal vectors spanning the complement of the unit vector u (M = N - 1), by
/// Gram-Schmidt on the coordinate axes of the N - 1 smallest |u_i| (the excluded axis is the one
/// most aligned with u, so none of the chosen axes is nearly dependent on it).
template <class C, int N>
[[nodiscard]] inline std::array<Vec<C, N>, N - 1> complement_basis(const Vec<C, N>& u) noexcept {
  int skip = 0;
  for (int i = 1; i < N; ++i)
    if (std::fabs(u[i]) > std::fabs(u[skip])) skip = i;
  std::array<Vec<C, N>, N - 1> e{};
  int k = 0;
  for (int i = 0; i < N; ++i) {
    if (i == skip) continue;
    Vec<C, N> v{};
    v[i] = C(1);
    v -= dot(v, u) * u;
    for (int j = 0; j < k; ++j)
      v -= dot(v, e[static_cast<std::size_t>(j)]) * e[static_cast<std::size_t>(j)];
    e[static_cast<std::size_t>(k++)] = normalize(v);
  }
  return e;
}

/// The local parameters s in (0, 1) of the span's points where the distance of the projected
/// curve P(s) = (e_k . (C(s) - o))_k from the origin is critical (the roots of G, see the header;
/// in 1D (M = 1) the roots of p~ and of r separately). Writes them to out (capacity 3d) and
/// returns the count; sets `constant` when the distance is constant over the span (G, or r,
/// vanishes within its error bound).
template <class C, int N, int M>
[[nodiscard]] inline int span_critical_params(const Vec<C, N + 1>* h, int d, const Vec<C, N>& o,
                                              const std::array<Vec<C, N>, M>& e, C* out,
                                              bool& constant) noexcept {
  constant = false;
  if (d == 0) return 0;
  const auto ud = static_cast<std::size_t>(d);
  // Projected homogeneous points g_i = (e_k . (A_i - o w_i), w_i) and the absolute sums that
  // bound their rounding: sum_l |e_kl| (|A_il| + |o_l w_i|).
  SpanScratch<Vec<C, M + 1>, 16> g(ud + 1), gabs(ud + 1);
  for (int i = 0; i <= d; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    const C w = h[i][N];
    for (int k = 0; k < M; ++k) {
      const Vec<C, N>& ek = e[static_cast<std::size_t>(k)];
      C s = C(0), sa = C(0);
      for (int l = 0; l < N; ++l) {
        s += ek[l] * (h[i][l] - o[l] * w);
        sa += std::fabs(ek[l]) * (std::fabs(h[i][l]) + std::fabs(o[l] * w));
      }
      g[ui][k] = s;
      gabs[ui][k] = sa;
    }
    g[ui][M] = w;
    gabs[ui][M] = std::fabs(w);
  }
  SpanPower<C, M> sp(g.data(), d, Vec<C, M>{});
  {
    // The constructor's absolute twins only see the projected values; use the bounds of the
    // original data instead (cancellation in e . (A - o w) must not shrink the error bound).
    SpanScratch<C, 196> m((ud + 1) * (ud + 1));
    bernstein_to_centred(d, m.data());
    for (int k = 0; k < M; ++k)
      for (int j = 0; j <= d; ++j) {
        C sa = C(0);
        for (int i = 0; i <= d; ++i)
          sa += gabs[static_cast<std::size_t>(i)][k] *
                std::fabs(m[static_cast<std::size_t>(i * (d + 1) + j)]);
        sp.qa[static_cast<std::size_t>(k * (d + 1) + j)] = sa;
      }
  }
  const int len = 2 * d - 1;
  SpanScratch<C, 32 * M> r(static_cast<std::size_t>(M * len)),
      ra(static_cast<std::size_t>(M * len));
  span_derivative_numerator(sp, r.data(), ra.data());
  const C factor = span_error_factor<C>(d);
  int count = 0;
  const auto to_local = [&](int cnt, const C* u) {
    for (int i = 0; i < cnt; ++i) out[count++] = C(0.5) * (C(1) + u[i]);
  };
  SpanScratch<C, 40> u(static_cast<std::size_t>(3 * d));
  if constexpr (M == 1) {
    BoundedPoly<C> p(d);
    for (int j = 0; j <= d; ++j) {
      p.c[static_cast<std::size_t>(j)] = sp.q(0, j);
      p.err[static_cast<std::size_t>(j)] = factor * sp.qabs(0, j);
    }
    const int cp = span_roots(p, u.data());
    if (cp < 0)
      constant = true;  // the span lies on the line
    else
      to_local(cp, u.data());
    BoundedPoly<C> rp(len - 1);
    for (int j = 0; j < len; ++j) {
      rp.c[static_cast<std::size_t>(j)] = r[static_cast<std::size_t>(j)];
      rp.err[static_cast<std::size_t>(j)] = factor * ra[static_cast<std::size_t>(j)];
    }
    const int cr = span_roots(rp, u.data());
    if (cr < 0)
      constant = true;  // straight and parallel to the line
    else
      to_local(cr, u.data());
  } else {
    BoundedPoly<C> gp(3 * d - 2);
    for (int k = 0; k < M; ++k)
      for (int i = 0; i <= d; ++i)
        for (int mm = 0; mm < len; ++mm) {
          const auto at = static_cast<std::size_t>(i + mm);
          const auto rk = static_cast<std::size_t>(k * len + mm);
          gp.c[at] += sp.q(k, i) * r[rk];
          gp.err[at] += sp.qabs(k, i) * ra[rk];
        }
    for (int j = 0; j <= gp.deg; ++j) gp.err[static_cast<std::size_t>(j)] *= factor;
    const int cg = span_roots(gp, u.data());
    if (cg < 0)
      constant = true;
    else
      to_local(cg, u.data());
  }
  return count;
}

template <class T, int N, class Lin, class Curve>
[[nodiscard]] inline Distance<T, N, T, T> linear_curve_distance(const Lin& lin,
                                                                const Curve& c) noexcept {
  static_assert(N >= 2, "linear-curve distance needs N >= 2");
  if (!finite_input(lin) || !curve_ok(c)) return non_finite_distance<T, N, T, T>();
  const LinearView<T, N> vt = view(lin);
  if (!(max_abs(vt.dir) > T(0))) {
    // A point: the point-curve query.
    const Distance<T, N, NoParam, T> pc = point_curve_distance(vt.origin, c);
    return {pc.distance, pc.sqr_distance, pc.closest, T(0), pc.param_b, pc.unique};
  }
  using C = compute_t<T>;
  const LinearView<C, N> v{vec_cast<C>(vt.origin), vec_cast<C>(vt.end), vec_cast<C>(vt.dir),
                           vt.bounded_lo, vt.bounded_hi};
  const Vec<C, N> u = normalize(v.dir);
  if (!(max_abs(u) > C(0))) return non_finite_distance<T, N, T, T>();  // |dir| overflows C
  const std::array<Vec<C, N>, N - 1> frame = complement_basis(u);
  std::array<Vec<C, N>, N> identity{};
  for (int i = 0; i < N; ++i) identity[static_cast<std::size_t>(i)][i] = C(1);
  // The linear component's ends (each gets a point-curve pass).
  std::array<Vec<C, N>, 2> ends{};
  int n_ends = 0;
  if (v.bounded_lo) ends[static_cast<std::size_t>(n_ends++)] = v.origin;
  if (v.bounded_hi) ends[static_cast<std::size_t>(n_ends++)] = v.end;

  PairCandidates<C, N, C, C> tr;
  const C box = std::sqrt(static_cast<C>(control_box_sqr_size<T, N>(c)));
  tr.sep2 = static_cast<C>(eps_v<T>) * box * box;
  for_each_span<C>(c, [&](const Vec<C, N + 1>* h, int d, C t0, C t1) {
    const auto offer = [&](C s) {
      const Vec<C, N> x = span_point_at<C, N>(h, d, s);
      const C t = closest_param(v, x);
      const Vec<C, N> y = v.at(t);
      tr.offer(sqr_length(y - x), t, t0 + s * (t1 - t0), y, x);
    };
    offer(C(0));
    offer(C(1));
    if (d == 0) return;
    SpanScratch<C, 40> s(static_cast<std::size_t>(3 * d));
    bool constant = false, any_constant = false;
    int cnt = span_critical_params<C, N, N - 1>(h, d, v.origin, frame, s.data(), constant);
    for (int i = 0; i < cnt; ++i) offer(s[static_cast<std::size_t>(i)]);
    any_constant = constant;
    for (int k = 0; k < n_ends; ++k) {
      cnt = span_critical_params<C, N, N>(h, d, ends[static_cast<std::size_t>(k)], identity,
                                          s.data(), constant);
      for (int i = 0; i < cnt; ++i) offer(s[static_cast<std::size_t>(i)]);
      any_constant = any_constant || constant;
    }
    // Constant distance over the span: its ends (offered) tie; add the middle so that the tie
    // is seen whatever the clamp does.
    if (any_constant) offer(C(0.5));
  });
  if (!tr.found) return non_finite_distance<T, N, T, T>();

  // The curve parameter is rounded to T first and the linear parameter is the projection of the
  // curve point it gives: rounding s moves the point by up to |C'(s)| ulp(s) / 2 (long in float on
  // a short knot span: 2e-3 per ulp for a 10.7-long degree-1 edge over a 3e-4 span), and keeping
  // the linear parameter of the unrounded point would pair it with a point that is no longer
  // opposite (a crossing: 9.7e-4 apart instead of 8.9e-4 at the best float s).
  const T s = static_cast<T>(tr.best.pb);
  const Vec<T, N> xb = point_at(c, s);
  const T t = vt.clamp_param(static_cast<T>(closest_param(v, vec_cast<C>(xb))));
  const Vec<T, N> xa = point_at(lin, t);
  bool unique = true;
  const C scale = std::max(static_cast<C>(max_abs(xa)), static_cast<C>(max_abs(xb))) + box;
  const C tol = C(64) * static_cast<C>(eps_v<T>) * scale;
  if (tr.tied(tol)) {
    // Two distinct pairs at the same distance: infinitely many when the curve between them stays
    // at that distance (a constant piece), finitely many otherwise (separate minima). Test the
    // curve point midway in parameter.
    const T sm = static_cast<T>(C(0.5) * (tr.best.pb + tr.alt.pb));
    const Vec<C, N> xm = vec_cast<C>(point_at(c, sm));
    const C dm = length(v.at(closest_param(v, xm)) - xm);
    if (dm - std::sqrt(tr.best.d2) <= tol) unique = false;
  }
  return make_distance(xa, xb, t, s, unique);
}

}  // namespace detail

/// Distance between a line and a Bézier curve; param_a = t, param_b = the curve's t in [0, 1].
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Line<T, N>& l,
                                                   const BezierCurve<T, N>& c) noexcept {
  return detail::linear_curve_distance<T, N>(l, c);
}
/// Distance between a ray and a Bézier curve; param_a = t >= 0, param_b = the curve's t.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Ray<T, N>& r,
                                                   const BezierCurve<T, N>& c) noexcept {
  return detail::linear_curve_distance<T, N>(r, c);
}
/// Distance between a segment and a Bézier curve; param_a = t in [0, 1], param_b = the curve's t.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Segment<T, N>& s,
                                                   const BezierCurve<T, N>& c) noexcept {
  return detail::linear_curve_distance<T, N>(s, c);
}
/// Distance between a line and a B-spline curve; param_b is in the curve's domain.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Line<T, N>& l,
                                                   const BSplineCurve<T, N>& c) noexcept {
  return detail::linear_curve_distance<T, N>(l, c);
}
/// Distance between a ray and a B-spline curve; param_b is in the curve's domain.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Ray<T, N>& r,
                                                   const BSplineCurve<T, N>& c) noexcept {
  return detail::linear_curve_distance<T, N>(r, c);
}
/// Distance between a segment and a B-spline curve; param_b is in the curve's domain.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Segment<T, N>& s,
                                                   const BSplineCurve<T, N>& c) noexcept {
  return detail::linear_curve_distance<T, N>(s, c);
}
/// Distance between a line and a NURBS curve; param_b is in the curve's domain.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Line<T, N>& l,
                                                   const NurbsCurve<T, N>& c) noexcept {
  return detail::linear_curve_distance<T, N>(l, c);
}
/// Distance between a ray and a NURBS curve; param_b is in the curve's domain.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Ray<T, N>& r,
                                                   const NurbsCurve<T, N>& c) noexcept {
  return detail::linear_curve_distance<T, N>(r, c);
}
/// Distance between a segment and a NURBS curve; param_b is in the curve's domain.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const Segment<T, N>& s,
                                                   const NurbsCurve<T, N>& c) noexcept {
  return detail::linear_curve_distance<T, N>(s, c);
}

/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const BezierCurve<T, N>& c,
                                                   const Line<T, N>& l) noexcept {
  return swapped(distance(l, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const BezierCurve<T, N>& c,
                                                   const Ray<T, N>& r) noexcept {
  return swapped(distance(r, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const BezierCurve<T, N>& c,
                                                   const Segment<T, N>& s) noexcept {
  return swapped(distance(s, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const BSplineCurve<T, N>& c,
                                                   const Line<T, N>& l) noexcept {
  return swapped(distance(l, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const BSplineCurve<T, N>& c,
                                                   const Ray<T, N>& r) noexcept {
  return swapped(distance(r, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const BSplineCurve<T, N>& c,
                                                   const Segment<T, N>& s) noexcept {
  return swapped(distance(s, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const NurbsCurve<T, N>& c,
                                                   const Line<T, N>& l) noexcept {
  return swapped(distance(l, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const NurbsCurve<T, N>& c,
                                                   const Ray<T, N>& r) noexcept {
  return swapped(distance(r, c));
}
/// The swapped query: closest[0] and param_a belong to the curve.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, T, T> distance(const NurbsCurve<T, N>& c,
                                                   const Segment<T, N>& s) noexcept {
  return swapped(distance(s, c));
}

}  // namespace locus
