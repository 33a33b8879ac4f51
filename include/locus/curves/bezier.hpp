// SPDX-License-Identifier: BSL-1.0
#pragma once
// Bézier curves in N dimensions; row prim2.curves (and the 3D curves of prim3.surfaces); book
// section 5.5 (polynomial curves, Bézier form) and 9.4 (curves in 3D), figures 5.17, 9.22.
//
// BezierCurve<T, N> {control}: control points P_0 .. P_n, degree n = control.size() - 1, and
//   C(t) = sum_i B_i^n(t) P_i,  B_i^n(t) = binom(n, i) t^i (1 - t)^(n - i),  t in [0, 1].
// C(0) = P_0 and C(1) = P_n exactly (de Casteljau's convex combinations are exact at the ends).
//
// Operations: point_at (de Casteljau, numerically stable: only convex combinations for t in
// [0, 1]); derivative (the hodograph, degree n - 1, control points n (P_{i+1} - P_i));
// derivative_at(c, t, k) (k-th derivative by k-th forward differences, scaled by n!/(n-k)!, then
// de Casteljau); subdivide (the two halves over [0, t] and [t, 1], each reparametrised to
// [0, 1]); elevate_degree (the same curve with one more control point); bounding_box (the box of
// the control polygon, which contains the curve by the convex-hull property: the bound the
// hierarchy methods of chapters 6, 7, 10 and 11 refine by subdivision); arc_length (adaptive
// 5-point Gauss-Legendre quadrature of |C'(t)|).
//
// Parameters outside [0, 1] are clamped to [0, 1] (no extrapolation); a NaN parameter gives a NaN
// point. Degenerate input: an empty curve (no control points) evaluates to a NaN point, its
// derivative is empty, its box is empty_box(); a single control point is the constant curve (all
// derivatives zero). Repeated control points are fine (the curve may have cusps where the
// hodograph vanishes). NaN/Inf control points propagate to every point that depends on them;
// is_finite(curve) checks the input, and arc_length reports non_finite_input.
//
// Cost: point_at, derivative_at, subdivide O(n^2), elevate_degree O(n). Evaluation allocates
// only for degree >= 16; curve-producing operations return new curves (they allocate).

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/numeric/subdivide.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace locus {

/// A Bézier curve of degree control.size() - 1 over t in [0, 1].
template <class T, int N>
struct BezierCurve {
  std::vector<Vec<T, N>> control;
};

template <Real T>
using BezierCurve2 = BezierCurve<T, 2>;
template <Real T>
using BezierCurve3 = BezierCurve<T, 3>;

namespace detail {

/// A work array of n values kept on the stack for n <= Inline (the common low degrees).
template <class V, std::size_t Inline = 16>
class CurveScratch {
 public:
  explicit CurveScratch(std::size_t n) : n_(n) {
    if (n > Inline) heap_.resize(n);
  }
  V* data() noexcept { return n_ > Inline ? heap_.data() : buf_.data(); }
  V& operator[](std::size_t i) noexcept { return data()[i]; }
  std::size_t size() const noexcept { return n_; }

 private:
  std::size_t n_;
  // Value-initialised: cheap next to the evaluation, and GCC cannot prove the writes-before-reads.
  std::array<V, Inline> buf_{};
  std::vector<V> heap_;
};

/// A vector whose components are all quiet NaN: the result of evaluating an invalid object.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> curve_nan() noexcept {
  return splat<T, N>(std::numeric_limits<T>::quiet_NaN());
}

/// de Casteljau in place on b[0..n]; returns the point at t. (1-t) a + t b is exact at t = 0, 1.
template <class T, class V>
[[nodiscard]] V de_casteljau_inplace(V* b, int n, T t) noexcept {
  const T s = T(1) - t;
  for (int r = 1; r <= n; ++r)
    for (int i = 0; i <= n - r; ++i) b[i] = s * b[i] + t * b[i + 1];
  return b[0];
}

/// The parameter clamped to [lo, hi]; NaN stays NaN.
template <Real T>
[[nodiscard]] constexpr T curve_clamp(T t, T lo, T hi) noexcept {
  return t < lo ? lo : (hi < t ? hi : t);
}

}  // namespace detail

/// The degree control.size() - 1 (-1 for an empty curve).
template <class T, int N>
[[nodiscard]] int degree(const BezierCurve<T, N>& c) noexcept {
  return static_cast<int>(c.control.size()) - 1;
}

/// True when every control coordinate is finite (and there is at least one control point).
template <class T, int N>
[[nodiscard]] bool is_finite(const BezierCurve<T, N>& c) noexcept {
  if (c.control.empty()) return false;
  for (const auto& p : c.control)
    if (!is_finite(p)) return false;
  return true;
}

/// C(t) by de Casteljau; t clamped to [0, 1]; NaN for an empty curve or a NaN t.
template <class T, int N>
[[nodiscard]] Vec<T, N> point_at(const BezierCurve<T, N>& c, T t) noexcept {
  const int n = degree(c);
  if (n < 0) return detail::curve_nan<T, N>();
  t = detail::curve_clamp(t, T(0), T(1));
  detail::CurveScratch<Vec<T, N>> b(c.control.size());
  for (std::size_t i = 0; i < c.control.size(); ++i) b[i] = c.control[i];
  return detail::de_casteljau_inplace(b.data(), n, t);
}

/// The hodograph C'(t): degree n - 1, control points n (P_{i+1} - P_i). A constant curve gives
/// the single zero point; an empty curve gives an empty curve.
template <class T, int N>
[[nodiscard]] BezierCurve<T, N> derivative(const BezierCurve<T, N>& c) {
  const int n = degree(c);
  if (n < 0) return {};
  if (n == 0) return {{Vec<T, N>{}}};
  BezierCurve<T, N> d;
  d.control.resize(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < d.control.size(); ++i)
    d.control[i] = static_cast<T>(n) * (c.control[i + 1] - c.control[i]);
  return d;
}

/// The k-th derivative C^(k)(t) (k = 0 is the point); zero for k > degree; t clamped to [0, 1].
template <class T, int N>
[[nodiscard]] Vec<T, N> derivative_at(const BezierCurve<T, N>& c, T t, int k) noexcept {
  const int n = degree(c);
  if (n < 0 || k < 0) return detail::curve_nan<T, N>();
  if (k > n) return Vec<T, N>{};
  t = detail::curve_clamp(t, T(0), T(1));
  detail::CurveScratch<Vec<T, N>> b(c.control.size());
  for (std::size_t i = 0; i < c.control.size(); ++i) b[i] = c.control[i];
  // k-th forward differences, scaled by n (n-1) ... (n-k+1) one factor per difference.
  for (int r = 0; r < k; ++r) {
    const T f = static_cast<T>(n - r);
    for (std::size_t i = 0; i < static_cast<std::size_t>(n - r); ++i) b[i] = f * (b[i + 1] - b[i]);
  }
  return detail::de_casteljau_inplace(b.data(), n - k, t);
}

/// The two halves of a curve split at a parameter.
template <class T, int N>
struct BezierSplit {
  BezierCurve<T, N> first;   ///< C over [0, t], reparametrised to [0, 1]
  BezierCurve<T, N> second;  ///< C over [t, 1], reparametrised to [0, 1]
};

/// Splits at t (clamped to [0, 1]) by de Casteljau: first's control points are the left edge of
/// the triangle, second's the right edge. t = 0 or 1 gives a degenerate (single-point) half.
template <class T, int N>
[[nodiscard]] BezierSplit<T, N> subdivide(const BezierCurve<T, N>& c, T t) {
  const int n = degree(c);
  if (n < 0) return {};
  t = detail::curve_clamp(t, T(0), T(1));
  const auto sz = c.control.size();
  BezierSplit<T, N> s;
  s.first.control.resize(sz);
  s.second.control.resize(sz);
  std::vector<Vec<T, N>> b = c.control;
  const T u = T(1) - t;
  s.first.control[0] = b[0];
  s.second.control[sz - 1] = b[sz - 1];
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      b[ui] = u * b[ui] + t * b[ui + 1];
    }
    s.first.control[static_cast<std::size_t>(r)] = b[0];
    s.second.control[static_cast<std::size_t>(n - r)] = b[static_cast<std::size_t>(n - r)];
  }
  return s;
}

/// The same curve with degree n + 1: Q_i = (i/(n+1)) P_{i-1} + (1 - i/(n+1)) P_i.
template <class T, int N>
[[nodiscard]] BezierCurve<T, N> elevate_degree(const BezierCurve<T, N>& c) {
  const int n = degree(c);
  if (n < 0) return {};
  BezierCurve<T, N> e;
  e.control.resize(c.control.size() + 1);
  e.control.front() = c.control.front();
  e.control.back() = c.control.back();
  const T m = static_cast<T>(n + 1);
  for (int i = 1; i <= n; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    const T a = static_cast<T>(i) / m;
    e.control[ui] = a * c.control[ui - 1] + (T(1) - a) * c.control[ui];
  }
  return e;
}

/// The curve elevated `times` times (times <= 0 returns the curve unchanged).
template <class T, int N>
[[nodiscard]] BezierCurve<T, N> elevate_degree(const BezierCurve<T, N>& c, int times) {
  BezierCurve<T, N> e = c;
  for (int i = 0; i < times; ++i) e = elevate_degree(e);
  return e;
}

/// The box of the control polygon; it contains the curve (convex-hull property). Empty for no
/// control points; NaN coordinates are skipped (see aligned_box.hpp).
template <class T, int N>
[[nodiscard]] AlignedBox<T, N> bounding_box(const BezierCurve<T, N>& c) noexcept {
  return bounding_box(c.control.data(), c.control.size());
}

namespace detail {

// 5-point Gauss-Legendre rule on [a, b] (exact for polynomials of degree <= 9).
template <class C, class F>
[[nodiscard]] C gauss_legendre5(const F& f, C a, C b) noexcept {
  const C x1 = C(0.5384693101056830910363144207002088);
  const C x2 = C(0.9061798459386639927976268782993929);
  const C w0 = C(0.5688888888888888888888888888888889);
  const C w1 = C(0.4786286704993664680412915148356382);
  const C w2 = C(0.2369268850561890875142640407755238);
  const C h = (b - a) / C(2);
  const C m = (a + b) / C(2);
  return h *
         (w0 * f(m) + w1 * (f(m - h * x1) + f(m + h * x1)) + w2 * (f(m - h * x2) + f(m + h * x2)));
}

}  // namespace detail

/// The length of C over [t0, t1] (both clamped to [0, 1]; t0 > t1 gives the length over
/// [t1, t0]) by adaptive 5-point Gauss-Legendre quadrature of |C'(t)|, computed in
/// compute_t<T>. An interval is accepted when its estimate and the sum over its two halves agree
/// to rel_tol * (length estimate of [t0, t1]) scaled by the interval's share of the parameter
/// range. At most max_intervals subintervals are examined (then limit_exceeded with the best
/// estimate). Allocates the hodograph and an interval stack.
template <class T, int N>
[[nodiscard]] ArcLength<T> arc_length(const BezierCurve<T, N>& c, T t0 = T(0), T t1 = T(1),
                                      T rel_tol = T(64) * eps_v<T>, int max_intervals = 4096) {
  using C = compute_t<T>;
  if (c.control.empty()) return {Status::empty_input, T(0), 0};
  if (!is_finite(c) || !is_finite(t0) || !is_finite(t1) || !(rel_tol >= T(0)))
    return {Status::non_finite_input, std::numeric_limits<T>::quiet_NaN(), 0};
  C a = static_cast<C>(detail::curve_clamp(t0, T(0), T(1)));
  C b = static_cast<C>(detail::curve_clamp(t1, T(0), T(1)));
  if (b < a) std::swap(a, b);
  if (c.control.size() == 1 || a == b) return {Status::ok, T(0), 0};
  BezierCurve<C, N> cc;
  cc.control.reserve(c.control.size());
  for (const auto& p : c.control) cc.control.push_back(vec_cast<C>(p));
  const BezierCurve<C, N> h = derivative(cc);
  const auto speed = [&h](C t) { return length(point_at(h, t)); };
  const C whole = detail::gauss_legendre5<C>(speed, a, b);
  // A scale for the absolute tolerance: the control polygon length bounds the arc length.
  C poly = C(0);
  for (std::size_t i = 1; i < cc.control.size(); ++i)
    poly += length(cc.control[i] - cc.control[i - 1]);
  const C tol_total = std::max(static_cast<C>(rel_tol) * poly, std::numeric_limits<C>::min());
  struct Item {
    C a, b, est;
  };
  std::vector<Item> stack{{a, b, whole}};
  C total = C(0);
  int examined = 0;
  int evaluations = 5;  // five nodes per Gauss-Legendre rule
  Status st = Status::ok;
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    evaluations += 10;
    const C m = (it.a + it.b) / C(2);
    const C l = detail::gauss_legendre5<C>(speed, it.a, m);
    const C r = detail::gauss_legendre5<C>(speed, m, it.b);
    const C share = (it.b - it.a) / (b - a);
    if (std::abs(l + r - it.est) <= tol_total * share || !(it.a < m && m < it.b)) {
      total += l + r;
      continue;
    }
    if (++examined > max_intervals) {
      st = Status::limit_exceeded;
      total += l + r;
      continue;
    }
    stack.push_back({m, it.b, r});
    stack.push_back({it.a, m, l});
  }
  return {st, static_cast<T>(total), evaluations};
}

}  // namespace locus
