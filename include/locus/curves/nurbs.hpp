// SPDX-License-Identifier: BSL-1.0
#pragma once
// NURBS (non-uniform rational B-spline) curves in N dimensions, and circles/arcs as exact
// quadratic NURBS; row prim2.curves (and the 3D curves of prim3.surfaces); book section 5.5
// (NURBS curves), figure 5.18.
//
// NurbsCurve<T, N> {degree, control, weights, knots}: as BSplineCurve (bspline.hpp) plus one
// weight per control point,
//   C(t) = sum_i N_{i,d}(t) w_i P_i / W(t),  W(t) = sum_i N_{i,d}(t) w_i,  t in [t_d, t_n].
// Evaluation runs de Boor on the homogeneous (N+1)-D points (w_i P_i, w_i) (to_homogeneous())
// and divides; derivatives by the quotient rule (docs/notes/curves.md). With all weights 1 the
// curve is the B-spline with the same control points and knots.
//
// Weights: validate() requires every weight > 0 (the convex-hull property, and W(t) > 0
// everywhere, hold only then); zero or negative weights give invalid_input. Evaluation still
// computes with any weights: where W(t) == 0 (or the quotient is not finite) point_at returns a
// NaN point, never a finite but meaningless one; weight_at() exposes W(t) so a caller can test it.
// Other bad input, domain clamping and NaN handling are those of bspline.hpp (a weights vector
// whose size differs from control's is structurally invalid: NaN points).
// Circles: nurbs_arc(center, u, v, radius, start, sweep) is the arc center + radius (cos a u +
// sin a v), a from start to start + sweep (|sweep| <= 2 pi, clamped), as m = ceil(|sweep| /
// (pi/2)) quadratic rational pieces of angle theta = sweep / m with weights 1, cos(theta/2), 1
// and double interior knots at i/m. Every point is on the circle up to rounding; the
// parametrisation is not by arc length. to_nurbs(Circle2) and to_nurbs(Arc2) wrap it in 2D.
//
// insert_knot() refines a NURBS curve without changing it (Boehm on the homogeneous curve).
// Cost: point_at O(d^2); derivatives O(k n) (derivative curves are built, allocating).

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bspline.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/arc.hpp>
#include <locus/primitives/circle.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace locus {

/// A NURBS curve: a B-spline with one weight per control point.
template <class T, int N>
struct NurbsCurve {
  int degree;
  std::vector<Vec<T, N>> control;
  std::vector<T> weights;
  std::vector<T> knots;
};

template <Real T>
using NurbsCurve2 = NurbsCurve<T, 2>;
template <Real T>
using NurbsCurve3 = NurbsCurve<T, 3>;

namespace detail {

template <class T, int N>
[[nodiscard]] constexpr Vec<T, N + 1> nurbs_homogeneous_point(const Vec<T, N>& p, T w) noexcept {
  Vec<T, N + 1> h{};
  for (int i = 0; i < N; ++i) h[i] = w * p[i];
  h[N] = w;
  return h;
}

template <class T, int N>
[[nodiscard]] bool nurbs_shape_ok(const NurbsCurve<T, N>& c) noexcept {
  return bspline_shape_ok(c.degree, c.control.size(), c.knots.size()) &&
         c.weights.size() == c.control.size();
}

}  // namespace detail

/// ok, or the first problem: see bspline.hpp; weights.size() != control.size() or a weight
/// <= 0 gives invalid_input, a non-finite weight non_finite_input.
template <class T, int N>
[[nodiscard]] Status validate(const NurbsCurve<T, N>& c) noexcept {
  const Status s = validate(BSplineCurve<T, N>{c.degree, c.control, c.knots});
  if (s != Status::ok) return s;
  if (c.weights.size() != c.control.size()) return Status::invalid_input;
  for (T w : c.weights)
    if (!is_finite(w)) return Status::non_finite_input;
  for (T w : c.weights)
    if (!(w > T(0))) return Status::invalid_input;
  return Status::ok;
}

/// The homogeneous B-spline with control points (w_i P_i, w_i) in N + 1 dimensions.
template <class T, int N>
[[nodiscard]] BSplineCurve<T, N + 1> to_homogeneous(const NurbsCurve<T, N>& c) {
  BSplineCurve<T, N + 1> h{c.degree, {}, c.knots};
  const std::size_t n = std::min(c.control.size(), c.weights.size());
  h.control.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    h.control.push_back(detail::nurbs_homogeneous_point(c.control[i], c.weights[i]));
  return h;
}

/// The domain [t_d, t_n].
template <class T, int N>
[[nodiscard]] ParamDomain<T> domain(const NurbsCurve<T, N>& c) noexcept {
  if (!detail::nurbs_shape_ok(c))
    return {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::quiet_NaN()};
  return {c.knots[static_cast<std::size_t>(c.degree)], c.knots[c.control.size()]};
}

namespace detail {

/// The homogeneous point (A(t), W(t)) at t clamped to the domain (NaN for a bad shape).
template <class T, int N>
[[nodiscard]] Vec<T, N + 1> nurbs_homogeneous_at(const NurbsCurve<T, N>& c, T t) noexcept {
  if (!nurbs_shape_ok(c)) return curve_nan<T, N + 1>();
  const std::span<const T> kn(c.knots);
  t = curve_clamp(t, kn[static_cast<std::size_t>(c.degree)], kn[c.control.size()]);
  if (t != t) return curve_nan<T, N + 1>();
  const int k = find_span(kn, c.degree, static_cast<int>(c.control.size()), t);
  return de_boor<T, Vec<T, N + 1>>(kn, c.degree, k, t, [&c](int i) {
    const auto ui = static_cast<std::size_t>(i);
    return nurbs_homogeneous_point(c.control[ui], c.weights[ui]);
  });
}

/// A / W, NaN when W is zero or the quotient is not finite.
template <class T, int N>
[[nodiscard]] Vec<T, N> nurbs_project(const Vec<T, N + 1>& h) noexcept {
  const T w = h[N];
  if (!(w != T(0))) return curve_nan<T, N>();
  Vec<T, N> p{};
  for (int i = 0; i < N; ++i) p[i] = h[i] / w;
  return is_finite(p) ? p : curve_nan<T, N>();
}

}  // namespace detail

/// W(t) = sum N_{i,d}(t) w_i (t clamped to the domain); > 0 everywhere for a valid curve.
template <class T, int N>
[[nodiscard]] T weight_at(const NurbsCurve<T, N>& c, T t) noexcept {
  return detail::nurbs_homogeneous_at(c, t)[N];
}

/// C(t) (t clamped to the domain); a NaN point where W(t) == 0, for a bad shape or a NaN t.
template <class T, int N>
[[nodiscard]] Vec<T, N> point_at(const NurbsCurve<T, N>& c, T t) noexcept {
  return detail::nurbs_project<T, N>(detail::nurbs_homogeneous_at(c, t));
}

/// C(t), C'(t), ..., C^(order)(t) (order + 1 vectors; t clamped). All NaN where W(t) == 0 or
/// for a bad shape. Allocates the homogeneous derivative curves.
template <class T, int N>
[[nodiscard]] std::vector<Vec<T, N>> derivatives(const NurbsCurve<T, N>& c, T t, int order) {
  if (order < 0) return {};
  std::vector<Vec<T, N>> out(static_cast<std::size_t>(order) + 1, detail::curve_nan<T, N>());
  if (!detail::nurbs_shape_ok(c)) return out;
  const ParamDomain<T> dom = domain(c);
  t = detail::curve_clamp(t, dom.min, dom.max);
  if (t != t) return out;
  std::vector<Vec<T, N + 1>> h(out.size());
  BSplineCurve<T, N + 1> hc = to_homogeneous(c);
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (k > 0) hc = derivative(hc);
    h[k] = (k > static_cast<std::size_t>(c.degree)) ? Vec<T, N + 1>{} : point_at(hc, t);
  }
  const T w = h[0][N];
  if (!(w != T(0)) || !is_finite(w)) return out;
  for (std::size_t k = 0; k < out.size(); ++k) {
    Vec<T, N> a{};
    for (int i = 0; i < N; ++i) a[i] = h[k][i];
    T binom = T(1);
    for (std::size_t j = 1; j <= k; ++j) {
      binom = binom * static_cast<T>(k - j + 1) / static_cast<T>(j);
      a -= (binom * h[j][N]) * out[k - j];
    }
    out[k] = a / w;
  }
  for (auto& v : out)
    if (!is_finite(v)) v = detail::curve_nan<T, N>();
  return out;
}

/// The k-th derivative at t (k = 0 is the point); see derivatives().
template <class T, int N>
[[nodiscard]] Vec<T, N> derivative_at(const NurbsCurve<T, N>& c, T t, int k) {
  if (k < 0) return detail::curve_nan<T, N>();
  return derivatives(c, t, k).back();
}

/// Inserts the knot t (clamped to the domain) `times` times: Boehm's algorithm on the
/// homogeneous B-spline, then the new points are projected (P = A / w). The curve is unchanged.
/// New weights are convex combinations of old ones, so positive weights stay positive; with
/// non-positive weights a new weight can be 0, and its control point is then NaN. An
/// inconsistent shape is returned unchanged.
template <class T, int N>
[[nodiscard]] NurbsCurve<T, N> insert_knot(const NurbsCurve<T, N>& c, T t, int times = 1) {
  if (!detail::nurbs_shape_ok(c)) return c;
  const BSplineCurve<T, N + 1> h = insert_knot(to_homogeneous(c), t, times);
  NurbsCurve<T, N> r{c.degree, {}, {}, h.knots};
  r.control.reserve(h.control.size());
  r.weights.reserve(h.control.size());
  for (const auto& p : h.control) {
    r.control.push_back(detail::nurbs_project<T, N>(p));
    r.weights.push_back(p[N]);
  }
  return r;
}

/// The control-polygon box; it contains the curve when every weight is positive.
template <class T, int N>
[[nodiscard]] AlignedBox<T, N> bounding_box(const NurbsCurve<T, N>& c) noexcept {
  return bounding_box(c.control.data(), c.control.size());
}

/// The B-spline with the same degree, control points and knots (the weights dropped).
template <class T, int N>
[[nodiscard]] NurbsCurve<T, N> to_nurbs(const BSplineCurve<T, N>& c) {
  return {c.degree, c.control, std::vector<T>(c.control.size(), T(1)), c.knots};
}

/// The arc center + radius (cos a u + sin a v), a in [start, start + sweep] (sweep clamped to
/// [-2 pi, 2 pi]; negative runs clockwise in the (u, v) frame), as an exact quadratic NURBS over
/// [0, 1]. u and v should be orthonormal (they are used as given).
template <class T, int N>
[[nodiscard]] NurbsCurve<T, N> nurbs_arc(const Vec<T, N>& center, const Vec<T, N>& u,
                                         const Vec<T, N>& v, T radius, T start, T sweep) {
  using C = compute_t<T>;
  const C two_pi = C(2) * pi_v<C>;
  C sw = static_cast<C>(sweep);
  sw = sw < -two_pi ? -two_pi : (sw > two_pi ? two_pi : sw);
  // One piece per started quarter turn keeps every piece's angle <= pi/2 (weights >= 0.707).
  const C quarter = pi_v<C> / C(2);
  int m = 1;
  while (m < 4 && std::abs(sw) > static_cast<C>(m) * quarter) ++m;
  const C theta = sw / static_cast<C>(m);
  const C wmid = std::cos(theta / C(2));
  const auto at = [&](C a, C r) {
    return center + static_cast<T>(r * std::cos(a)) * u + static_cast<T>(r * std::sin(a)) * v;
  };
  NurbsCurve<T, N> c{2, {}, {}, {}};
  const C r = static_cast<C>(radius);
  const C a0 = static_cast<C>(start);
  for (int i = 0; i < m; ++i) {
    const C a = a0 + static_cast<C>(i) * theta;
    c.control.push_back(at(a, r));
    c.weights.push_back(T(1));
    c.control.push_back(at(a + theta / C(2), r / wmid));
    c.weights.push_back(static_cast<T>(wmid));
  }
  c.control.push_back(at(a0 + sw, r));
  c.weights.push_back(T(1));
  c.knots = {T(0), T(0), T(0)};
  for (int i = 1; i < m; ++i) {
    const T k = static_cast<T>(static_cast<C>(i) / static_cast<C>(m));
    c.knots.push_back(k);
    c.knots.push_back(k);
  }
  c.knots.insert(c.knots.end(), {T(1), T(1), T(1)});
  return c;
}

/// The 2D arc as an exact quadratic NURBS over [0, 1] (see nurbs_arc).
template <Real T>
[[nodiscard]] NurbsCurve<T, 2> to_nurbs(const Arc2<T>& a) {
  return nurbs_arc(a.circle.center, Vec2<T>{T(1), T(0)}, Vec2<T>{T(0), T(1)}, a.circle.radius,
                   a.start, a.sweep);
}

/// The whole circle, counter-clockwise from angle 0, as four quadratic rational pieces.
template <Real T>
[[nodiscard]] NurbsCurve<T, 2> to_nurbs(const Circle2<T>& c) {
  return to_nurbs(Arc2<T>{c, T(0), T(2) * pi_v<T>});
}

}  // namespace locus
