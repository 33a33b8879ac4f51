// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a line, ray or segment and a general quadratic curve (conic) a x^2 + b xy +
// c y^2 + d x + e y + f = 0 in the plane; row dist2.linear-curve (quadratic-curve part); book
// section 6.4, figure 6.23. Method by conic class: docs/notes/distance.md.
//
// distance(linear, QuadraticCurve2) returns Distance<T, 2, T, NoParam>: param_a is the linear
// parameter of closest[0] (Line: t in R, Ray: t >= 0, Segment: t in [0, 1], as point_at); a
// general conic has no parametrisation in locus, so closest[1] itself is the answer (on the
// curve to rounding). The conic is the CURVE (a segment inside an ellipse is at a positive
// distance). distance(QuadraticCurve2, linear) is the swapped result. For an Ellipse2 in axis
// form, line_ellipse.hpp gives the angle as well. Computed in compute_t<T> (double for float).
//
// Classes (exact classify_conic()): a plane (all coefficients zero) gives distance 0 at the
// linear origin, unique = false; an empty conic gives distance = sqr_distance = +infinity,
// closest[0] = point_at(linear, 0), param_a = 0, closest[1] NaN, unique = false.
// Infimum not attained: a line or ray asymptotic to a hyperbola approaches it without reaching
// it; when that limit h is below every attained candidate the result is distance = h,
// sqr_distance = h^2, param_a = +infinity, closest points NaN, unique = false.
// unique = false also when infinitely many closest pairs exist (the component parallel to a line
// of a degenerate conic, or a winning ray / segment end whose point-conic answer is not unique);
// finitely many tied pairs return one of them with unique = true.
//
// Degenerate input: a zero direction (zero-length segment) acts as its point (the point-conic
// query, param_a = 0). NaN or infinite coefficients or linear input give non_finite_distance().
// Cost: O(1): two quadratics and at most two point-conic queries (each a quartic); degenerate
// classes one or two linear-linear queries.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/detail/pair_candidates.hpp>
#include <locus/distance/detail/quadric_lagrange.hpp>
#include <locus/distance/point_quadratic_curve.hpp>
#include <locus/distance/result.hpp>
#include <locus/numeric/roots.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/quadratic_curve.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace locus {

namespace detail {

/// The lines (point, direction) of a degenerate conic of class intersecting_lines,
/// parallel_lines, double_line or line; returns their number (0 if rounding defeats the
/// factorisation).
template <class C>
[[nodiscard]] inline int conic_lines(const QuadricN<C, 2>& q, ConicKind kind,
                                     std::array<Vec2<C>, 2>& point,
                                     std::array<Vec2<C>, 2>& dir) noexcept {
  const C a = q.a.a[0][0], hb = q.a.a[0][1], c = q.a.a[1][1];  // hb = b / 2
  if (kind == ConicKind::line) {
    const C bb = sqr_length(q.b);
    point[0] = (-q.c / bb) * q.b;
    dir[0] = perp(q.b);
    return 1;
  }
  if (kind == ConicKind::intersecting_lines) {
    // Crossing point: grad Q = 2 A X + B = 0 (det A < 0 here).
    const C det = a * c - hb * hb;
    const Vec2<C> x{(-q.b.x * c + q.b.y * hb) / (C(2) * det),
                    (-q.b.y * a + q.b.x * hb) / (C(2) * det)};
    // Null directions of a u^2 + 2 hb u v + c v^2, by the cancellation-free root pair of the
    // larger end coefficient.
    const C root = std::sqrt(hb * hb - a * c);
    const C qq = -(hb + std::copysign(root, hb));  // (-2hb -+ 2 sqrt) / 2
    if (a == C(0) && c == C(0)) {                  // b xy = 0: the coordinate axes through x
      dir[0] = {C(1), C(0)};
      dir[1] = {C(0), C(1)};
    } else if (std::fabs(a) >= std::fabs(c)) {
      if (!(qq != C(0))) return 0;
      dir[0] = {qq / a, C(1)};
      dir[1] = {c / qq, C(1)};
    } else {
      if (!(qq != C(0))) return 0;
      dir[0] = {C(1), qq / c};
      dir[1] = {C(1), a / qq};
    }
    point[0] = point[1] = x;
    return 2;
  }
  // Parallel or double line: A = lambda n n^T; Q = lambda s^2 + (B . n) s + f with s = n . X
  // (B has no component across n for these classes, up to rounding).
  const Vec2<C> r0{a, hb}, r1{hb, c};
  const Vec2<C> n = normalize(sqr_length(r0) >= sqr_length(r1) ? r0 : r1);
  const C lambda = a + c, beta = dot(q.b, n);
  if (!(lambda != C(0)) || !(max_abs(n) > C(0))) return 0;
  const C mid = -beta / (C(2) * lambda);
  int k = 0;
  if (kind == ConicKind::parallel_lines) {
    const RootsResult<C> roots = solve_quadratic<C>(q.c, beta, lambda, near_roots());
    for (const Root<C>& r : roots)
      if (k < 2) point[static_cast<std::size_t>(k++)] = r.value * n;
  }
  if (k == 0) point[static_cast<std::size_t>(k++)] = mid * n;  // double line (or rounding)
  dir[0] = dir[1] = perp(n);
  return k;
}

template <class T, class Lin>
[[nodiscard]] inline Distance<T, 2, T, NoParam> linear_conic(const Lin& lin,
                                                             const QuadraticCurve2<T>& q) noexcept {
  using R = Distance<T, 2, T, NoParam>;
  const ConicKind kind = classify_conic(q);
  if (kind == ConicKind::non_finite || !finite_input(lin))
    return non_finite_distance<T, 2, T, NoParam>();
  const LinearView<T, 2> vt = view(lin);
  if (kind == ConicKind::empty) {
    R r = non_finite_distance<T, 2, T, NoParam>();
    r.distance = r.sqr_distance = std::numeric_limits<T>::infinity();
    r.closest[0] = vt.origin;
    r.param_a = T(0);
    return r;
  }
  if (!(max_abs(vt.dir) > T(0))) {
    const Distance<T, 2, NoParam, NoParam> pc = distance(vt.origin, q);
    return {pc.distance, pc.sqr_distance, pc.closest, T(0), NoParam{}, pc.unique};
  }
  if (kind == ConicKind::plane)
    return R{T(0), T(0), {vt.origin, vt.origin}, T(0), NoParam{}, false};

  using C = compute_t<T>;
  const LinearView<C, 2> v{vec_cast<C>(vt.origin), vec_cast<C>(vt.end), vec_cast<C>(vt.dir),
                           vt.bounded_lo, vt.bounded_hi};
  QuadricN<C, 2> qc{};
  qc.a.a[0][0] = C(q.a);
  qc.a.a[0][1] = qc.a.a[1][0] = C(0.5) * C(q.b);
  qc.a.a[1][1] = C(q.c);
  qc.b = {C(q.d), C(q.e)};
  qc.c = C(q.f);

  PairCandidates<C, 2, C, NoParam> tr;
  const auto offer_point = [&](const Vec2<C>& x, bool unique) {
    const C t = closest_param(v, x);
    tr.offer(sqr_length(v.at(t) - x), t, NoParam{}, v.at(t), x, unique);
  };
  const auto result = [&]() -> R {
    if (!tr.found) return non_finite_distance<T, 2, T, NoParam>();
    const T t = vt.clamp_param(static_cast<T>(tr.best.pa));
    return make_distance(point_at(lin, t), vec_cast<T>(tr.best.xb), t, NoParam{}, tr.best.unique);
  };

  if (kind == ConicKind::point) {
    const Vec2<C> x = quadric_pseudo_center(qc, v.origin, 2);
    offer_point(x, true);
    return result();
  }
  if (kind == ConicKind::intersecting_lines || kind == ConicKind::parallel_lines ||
      kind == ConicKind::double_line || kind == ConicKind::line) {
    std::array<Vec2<C>, 2> point{}, dir{};
    const int k = conic_lines(qc, kind, point, dir);
    for (int i = 0; i < k; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      const LinearView<C, 2> w{point[ui], point[ui], dir[ui], false, false};
      const LinLinParams<C> st = linear_linear(v, w);
      const Vec2<C> xa = v.at(st.s), xb = w.at(st.t);
      tr.offer(sqr_length(xa - xb), st.s, NoParam{}, xa, xb, st.unique);
    }
    return result();
  }

  // Ellipse, circle, hyperbola, parabola.
  const Vec2<C> o = v.origin, m = v.dir;
  const Vec2<C> am = qc.a * m;
  const C mam = dot(m, am);
  // (1) Intersections with the curve.
  for (const Root<C>& root :
       solve_quadratic<C>(qc.value(o), dot(qc.gradient(o), m), mam, near_roots())) {
    const C t = root.value;
    if (!is_finite(t) || v.clamp_param(t) != t) continue;
    const Vec2<C> y = v.at(t);
    const Vec2<C> x = project_onto(qc, y);
    tr.offer(sqr_length(y - x), t, NoParam{}, y, x);
  }
  // (2) Points whose tangent is parallel to the line: on the diameter g . X + B . m = 0.
  const Vec2<C> g = C(2) * am;
  const C gg = sqr_length(g);
  if (gg > C(0) && is_finite(gg)) {
    const Vec2<C> x0 = (-dot(qc.b, m) / gg) * g;
    const Vec2<C> w = perp(g);
    for (const Root<C>& root : solve_quadratic<C>(qc.value(x0), dot(qc.gradient(x0), w),
                                                  dot(w, qc.a * w), near_roots())) {
      const Vec2<C> x = project_onto(qc, x0 + root.value * w);
      if (is_finite(x)) offer_point(x, true);
    }
  }
  // (3) The ends of a ray or segment.
  const auto offer_end = [&](const Vec2<T>& e, C t) {
    const Distance<T, 2, NoParam, NoParam> pc = distance(e, q);
    if (!is_finite(pc.closest[1])) return;
    const Vec2<C> x = vec_cast<C>(pc.closest[1]), y = vec_cast<C>(e);
    tr.offer(sqr_length(y - x), t, NoParam{}, y, x, pc.unique);
  };
  if (vt.bounded_lo) offer_end(vt.origin, C(0));
  if (vt.bounded_hi) offer_end(vt.end, C(1));

  // Asymptotic direction of a hyperbola: the distance tends to that of the parallel asymptote.
  if (kind == ConicKind::hyperbola && !v.bounded_hi) {
    const C a = qc.a.a[0][0], hb = qc.a.a[0][1], c = qc.a.a[1][1];
    const C mam_abs =
        std::fabs(a) * m.x * m.x + C(2) * std::fabs(hb * m.x * m.y) + std::fabs(c) * m.y * m.y;
    if (std::fabs(mam) <= C(64) * eps_v<C> * mam_abs) {
      const C det = a * c - hb * hb;
      const Vec2<C> centre{(-qc.b.x * c + qc.b.y * hb) / (C(2) * det),
                           (-qc.b.y * a + qc.b.x * hb) / (C(2) * det)};
      const C h = std::fabs(perp_dot(normalize(m), centre - o));
      const C scale = max_abs(o) + max_abs(centre);
      if (is_finite(h) &&
          (!tr.found || h < std::sqrt(tr.best.d2) - C(64) * static_cast<C>(eps_v<T>) * scale)) {
        R r = non_finite_distance<T, 2, T, NoParam>();
        r.distance = static_cast<T>(h);
        r.sqr_distance = static_cast<T>(h * h);
        r.param_a = std::numeric_limits<T>::infinity();
        return r;
      }
    }
  }
  return result();
}

}  // namespace detail

/// Distance between a line and a conic (the curve); param_a = t, closest[1] on the conic.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, NoParam> distance(const Line<T, 2>& l,
                                                         const QuadraticCurve2<T>& q) noexcept {
  return detail::linear_conic(l, q);
}
/// Distance between a ray and a conic (the curve); param_a = t >= 0.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, NoParam> distance(const Ray<T, 2>& r,
                                                         const QuadraticCurve2<T>& q) noexcept {
  return detail::linear_conic(r, q);
}
/// Distance between a segment and a conic (the curve); param_a = t in [0, 1].
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, NoParam> distance(const Segment<T, 2>& s,
                                                         const QuadraticCurve2<T>& q) noexcept {
  return detail::linear_conic(s, q);
}

/// The swapped query: closest[0] belongs to the conic, param_b to the line.
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, T> distance(const QuadraticCurve2<T>& q,
                                                         const Line<T, 2>& l) noexcept {
  return swapped(distance(l, q));
}
/// The swapped query: closest[0] belongs to the conic, param_b to the ray.
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, T> distance(const QuadraticCurve2<T>& q,
                                                         const Ray<T, 2>& r) noexcept {
  return swapped(distance(r, q));
}
/// The swapped query: closest[0] belongs to the conic, param_b to the segment.
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, T> distance(const QuadraticCurve2<T>& q,
                                                         const Segment<T, 2>& s) noexcept {
  return swapped(distance(s, q));
}

}  // namespace locus
