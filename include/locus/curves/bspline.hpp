// SPDX-License-Identifier: BSL-1.0
#pragma once
// B-spline curves in N dimensions: knot vectors, basis functions, de Boor evaluation,
// derivatives, knot insertion and conversion to Bézier segments; row prim2.curves (and the 3D
// curves of prim3.surfaces); book sections 5.5 and 9.4 (B-spline curves), figures 5.18, 9.23.
//
// BSplineCurve<T, N> {degree, control, knots}: n = control.size() control points P_0 .. P_{n-1},
// degree d (order d + 1), knots t_0 <= ... <= t_{n+d} (n + d + 1 values), and
//   C(t) = sum_i N_{i,d}(t) P_i  for t in the domain [t_d, t_n],
// with the Cox-de Boor basis N_{i,0}(t) = 1 on [t_i, t_{i+1}), 0 elsewhere, and
//   N_{i,p}(t) = (t - t_i)/(t_{i+p} - t_i) N_{i,p-1}(t) + (t_{i+p+1} - t)/(t_{i+p+1} - t_{i+1})
//                N_{i+1,p-1}(t),  a fraction with a zero denominator counting as 0.
// Spans are half-open [t_k, t_{k+1}) except the last non-empty span, which is closed, so the
// domain end t_n evaluates the limit from the left (find_span).
//
// Knot vectors: uniform_knots(n, d) = (i - d)/(n - d), i = 0..n+d (domain [0, 1], the curve does
// not reach P_0, P_{n-1}); open_uniform_knots(n, d) = d + 1 zeros, equally spaced interior knots,
// d + 1 ones (clamped: C(0) = P_0, C(1) = P_{n-1}). Any non-decreasing vector is accepted.
// Bad input: validate_knots()/validate() return a Status: empty_input (no control points),
// invalid_input (degree < 0, degree >= n, knot count != n + d + 1, decreasing knots, a knot of
// multiplicity > d + 1), non_finite_input (NaN/Inf knot or control coordinate), degenerate_input
// (empty domain t_d == t_n). Evaluation checks only the sizes (O(1)): a structurally invalid
// curve (wrong knot count, degree out of range) evaluates to a NaN point; with decreasing knots
// the result is meaningless but nothing crashes, hangs or divides by zero (0/0 fractions are 0).
// Parameters outside the domain are clamped to [t_d, t_n]; a NaN parameter gives a NaN point.
// Cost: find_span O(log n); point_at (de Boor) O(d^2); basis_function O(d^2); derivative O(n);
// insert_knot O(n) per insertion; to_bezier O(n d). Evaluation allocates only for d >= 16.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bezier.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace locus {

/// A B-spline curve of the given degree; knots.size() == control.size() + degree + 1.
template <class T, int N>
struct BSplineCurve {
  int degree;
  std::vector<Vec<T, N>> control;
  std::vector<T> knots;
};

template <Real T>
using BSplineCurve2 = BSplineCurve<T, 2>;
template <Real T>
using BSplineCurve3 = BSplineCurve<T, 3>;

/// The uniform knot vector (i - d)/(n - d), i = 0..n+d, for n control points of degree d: the
/// domain is [0, 1]. Empty when d < 0 or n <= d.
template <Real T>
[[nodiscard]] std::vector<T> uniform_knots(int n_control, int degree) {
  if (degree < 0 || n_control <= degree) return {};
  std::vector<T> k(static_cast<std::size_t>(n_control + degree + 1));
  const T m = static_cast<T>(n_control - degree);
  for (int i = 0; i <= n_control + degree; ++i)
    k[static_cast<std::size_t>(i)] = static_cast<T>(i - degree) / m;
  return k;
}

/// The open-uniform (clamped) knot vector: d + 1 zeros, (i - d)/(n - d) inside, d + 1 ones.
/// Empty when d < 0 or n <= d.
template <Real T>
[[nodiscard]] std::vector<T> open_uniform_knots(int n_control, int degree) {
  if (degree < 0 || n_control <= degree) return {};
  std::vector<T> k(static_cast<std::size_t>(n_control + degree + 1));
  const T m = static_cast<T>(n_control - degree);
  for (int i = 0; i <= n_control + degree; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    if (i <= degree)
      k[ui] = T(0);
    else if (i >= n_control)
      k[ui] = T(1);
    else
      k[ui] = static_cast<T>(i - degree) / m;
  }
  return k;
}

/// Checks a knot vector for n control points of degree d (see the header comment for codes).
template <Real T>
[[nodiscard]] Status validate_knots(std::span<const T> knots, int degree, int n_control) noexcept {
  if (n_control <= 0) return Status::empty_input;
  if (degree < 0 || degree >= n_control) return Status::invalid_input;
  if (knots.size() != static_cast<std::size_t>(n_control + degree + 1))
    return Status::invalid_input;
  for (T k : knots)
    if (!is_finite(k)) return Status::non_finite_input;
  std::size_t run = 1;
  for (std::size_t i = 1; i < knots.size(); ++i) {
    if (knots[i] < knots[i - 1]) return Status::invalid_input;
    run = knots[i] == knots[i - 1] ? run + 1 : 1;
    if (run > static_cast<std::size_t>(degree) + 1) return Status::invalid_input;
  }
  if (!(knots[static_cast<std::size_t>(degree)] < knots[static_cast<std::size_t>(n_control)]))
    return Status::degenerate_input;
  return Status::ok;
}

/// Checks the knots and that every control coordinate is finite.
template <class T, int N>
[[nodiscard]] Status validate(const BSplineCurve<T, N>& c) noexcept {
  const Status s =
      validate_knots(std::span<const T>(c.knots), c.degree, static_cast<int>(c.control.size()));
  if (s != Status::ok) return s;
  for (const auto& p : c.control)
    if (!is_finite(p)) return Status::non_finite_input;
  return Status::ok;
}

/// The parameter interval of a curve.
template <Real T>
struct ParamDomain {
  T min;
  T max;
};

namespace detail {

/// True when the sizes are consistent, so that indexing the knots and control points is safe.
[[nodiscard]] inline bool bspline_shape_ok(int degree, std::size_t n_control,
                                           std::size_t n_knots) noexcept {
  return degree >= 0 && n_control > static_cast<std::size_t>(degree) &&
         n_knots == n_control + static_cast<std::size_t>(degree) + 1;
}

/// a / b with 0 for a zero denominator (the Cox-de Boor 0/0 = 0 convention).
template <Real T>
[[nodiscard]] constexpr T knot_ratio(T a, T b) noexcept {
  return b == T(0) ? T(0) : a / b;
}

}  // namespace detail

/// The domain [t_d, t_n] (NaN bounds for a structurally invalid curve).
template <class T, int N>
[[nodiscard]] ParamDomain<T> domain(const BSplineCurve<T, N>& c) noexcept {
  if (!detail::bspline_shape_ok(c.degree, c.control.size(), c.knots.size()))
    return {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::quiet_NaN()};
  return {c.knots[static_cast<std::size_t>(c.degree)], c.knots[c.control.size()]};
}

/// The span index k in [d, n-1] with t_k <= t < t_{k+1}; for t >= t_n the last non-empty span
/// (t_k < t_{k+1}), for t <= t_d the span containing t_d. Binary search: terminates for any
/// knots (even decreasing or NaN); requires knots.size() >= n + 1 and 0 <= d < n.
template <Real T>
[[nodiscard]] int find_span(std::span<const T> knots, int degree, int n_control, T t) noexcept {
  const auto d = static_cast<std::size_t>(degree);
  const auto n = static_cast<std::size_t>(n_control);
  if (t >= knots[n]) {
    std::size_t k = n - 1;
    while (k > d && !(knots[k] < knots[k + 1])) --k;
    return static_cast<int>(k);
  }
  std::size_t lo = d, hi = n;
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (t < knots[mid])
      hi = mid;
    else
      lo = mid;
  }
  return static_cast<int>(lo);
}

namespace detail {

/// de Boor's algorithm on the d + 1 points get(k - d) .. get(k) of span k; t in the span.
template <class T, class V, class Get>
[[nodiscard]] V de_boor(std::span<const T> knots, int d, int k, T t, const Get& get) noexcept {
  CurveScratch<V> p(static_cast<std::size_t>(d) + 1);
  for (int j = 0; j <= d; ++j) p[static_cast<std::size_t>(j)] = get(j + k - d);
  for (int r = 1; r <= d; ++r) {
    for (int j = d; j >= r; --j) {
      const auto i = static_cast<std::size_t>(j + k - d);
      const T lo = knots[i];
      const T hi = knots[static_cast<std::size_t>(j + 1 + k - r)];
      const T a = knot_ratio(t - lo, hi - lo);
      const auto uj = static_cast<std::size_t>(j);
      p[uj] = (T(1) - a) * p[uj - 1] + a * p[uj];
    }
  }
  return p[static_cast<std::size_t>(d)];
}

/// Raises vals[0..p] = N_{k-p+m, p}(t), m = 0..p, in place to degree p + 1 (p + 2 values).
template <Real T>
void raise_basis(std::span<const T> knots, int k, int p, T t, T* vals) noexcept {
  for (int j = p + 1; j >= 0; --j) {
    const auto i = static_cast<std::size_t>(k - (p + 1) + j);
    const auto up = static_cast<std::size_t>(p);
    const T a = j >= 1 ? vals[j - 1] : T(0);  // N_{i, p}
    const T b = j <= p ? vals[j] : T(0);      // N_{i+1, p}
    vals[j] = knot_ratio(t - knots[i], knots[i + up + 1] - knots[i]) * a +
              knot_ratio(knots[i + up + 2] - t, knots[i + up + 2] - knots[i + 1]) * b;
  }
}

/// The d + 1 non-zero basis values N_{k-d+m, d}(t) and their first derivatives (m = 0..d) on
/// span k. vals and ders have room for d + 1 values; ders may be null.
template <Real T>
void basis_and_derivative(std::span<const T> knots, int d, int k, T t, T* vals, T* ders) noexcept {
  vals[0] = T(1);
  for (int p = 0; p + 1 < d; ++p) raise_basis(knots, k, p, t, vals);
  if (d == 0) {
    if (ders) ders[0] = T(0);
    return;
  }
  // vals holds degree d - 1 now: N_{k-d+1+m, d-1}, m = 0..d-1.
  if (ders) {
    const T fd = static_cast<T>(d);
    for (int j = 0; j <= d; ++j) {
      const auto i = static_cast<std::size_t>(k - d + j);
      const auto ud = static_cast<std::size_t>(d);
      const T a = j >= 1 ? vals[j - 1] : T(0);
      const T b = j <= d - 1 ? vals[j] : T(0);
      ders[j] = fd * (knot_ratio(a, knots[i + ud] - knots[i]) -
                      knot_ratio(b, knots[i + ud + 1] - knots[i + 1]));
    }
  }
  raise_basis(knots, k, d - 1, t, vals);
}

}  // namespace detail

/// N_{i,d}(t) by the Cox-de Boor recursion (t clamped to the domain; 0 for i outside [0, n);
/// NaN for an inconsistent shape). Independent of de Boor's algorithm: used to cross-check it.
template <Real T>
[[nodiscard]] T basis_function(std::span<const T> knots, int degree, int n_control, int i,
                               T t) noexcept {
  if (!detail::bspline_shape_ok(degree, static_cast<std::size_t>(std::max(n_control, 0)),
                                knots.size()))
    return std::numeric_limits<T>::quiet_NaN();
  if (i < 0 || i >= n_control) return T(0);
  t = detail::curve_clamp(t, knots[static_cast<std::size_t>(degree)],
                          knots[static_cast<std::size_t>(n_control)]);
  if (t != t) return t;
  const int k = find_span(knots, degree, n_control, t);
  // Degree-0 functions N_{j,0} for j = i..i+d: only the span's is 1.
  detail::CurveScratch<T> v(static_cast<std::size_t>(degree) + 1);
  for (int j = 0; j <= degree; ++j) v[static_cast<std::size_t>(j)] = (i + j == k) ? T(1) : T(0);
  for (int p = 1; p <= degree; ++p) {
    for (int j = 0; j <= degree - p; ++j) {
      const auto a = static_cast<std::size_t>(i + j);
      const auto up = static_cast<std::size_t>(p);
      const auto uj = static_cast<std::size_t>(j);
      v[uj] =
          detail::knot_ratio(t - knots[a], knots[a + up] - knots[a]) * v[uj] +
          detail::knot_ratio(knots[a + up + 1] - t, knots[a + up + 1] - knots[a + 1]) * v[uj + 1];
    }
  }
  return v[0];
}

/// C(t) by de Boor's algorithm; t clamped to the domain; NaN for an inconsistent shape or NaN t.
template <class T, int N>
[[nodiscard]] Vec<T, N> point_at(const BSplineCurve<T, N>& c, T t) noexcept {
  if (!detail::bspline_shape_ok(c.degree, c.control.size(), c.knots.size()))
    return detail::curve_nan<T, N>();
  const int n = static_cast<int>(c.control.size());
  const std::span<const T> kn(c.knots);
  t = detail::curve_clamp(t, kn[static_cast<std::size_t>(c.degree)], kn[c.control.size()]);
  if (t != t) return detail::curve_nan<T, N>();
  const int k = find_span(kn, c.degree, n, t);
  return detail::de_boor<T, Vec<T, N>>(
      kn, c.degree, k, t, [&c](int i) { return c.control[static_cast<std::size_t>(i)]; });
}

/// The derivative curve C'(t): degree d - 1, control points d (P_{i+1} - P_i) / (t_{i+d+1} -
/// t_{i+1}) (0 where the denominator is 0), knots t_1 .. t_{n+d-1}. A degree-0 curve
/// (piecewise constant) gives the same knots with zero control points; an inconsistent shape
/// is returned unchanged.
template <class T, int N>
[[nodiscard]] BSplineCurve<T, N> derivative(const BSplineCurve<T, N>& c) {
  if (!detail::bspline_shape_ok(c.degree, c.control.size(), c.knots.size())) return c;
  if (c.degree == 0) return {0, std::vector<Vec<T, N>>(c.control.size()), c.knots};
  const auto d = static_cast<std::size_t>(c.degree);
  BSplineCurve<T, N> r;
  r.degree = c.degree - 1;
  r.control.resize(c.control.size() - 1);
  for (std::size_t i = 0; i + 1 < c.control.size(); ++i)
    r.control[i] =
        detail::knot_ratio(static_cast<T>(c.degree), c.knots[i + d + 1] - c.knots[i + 1]) *
        (c.control[i + 1] - c.control[i]);
  r.knots.assign(c.knots.begin() + 1, c.knots.end() - 1);
  return r;
}

/// The k-th derivative at t (k = 0 is the point; zero vector for k > degree); allocates the
/// intermediate derivative curves.
template <class T, int N>
[[nodiscard]] Vec<T, N> derivative_at(const BSplineCurve<T, N>& c, T t, int k) {
  if (!detail::bspline_shape_ok(c.degree, c.control.size(), c.knots.size()) || k < 0)
    return detail::curve_nan<T, N>();
  if (k == 0) return point_at(c, t);
  if (k > c.degree) return t == t ? Vec<T, N>{} : detail::curve_nan<T, N>();
  // Clamp to the original domain first: the derivative curves have the same domain.
  const ParamDomain<T> dom = domain(c);
  t = detail::curve_clamp(t, dom.min, dom.max);
  BSplineCurve<T, N> r = derivative(c);
  for (int i = 1; i < k; ++i) r = derivative(r);
  return point_at(r, t);
}

/// The control-polygon box; it contains the curve over its domain (convex-hull property).
template <class T, int N>
[[nodiscard]] AlignedBox<T, N> bounding_box(const BSplineCurve<T, N>& c) noexcept {
  return bounding_box(c.control.data(), c.control.size());
}

/// Inserts the knot t (clamped to the domain) `times` times by Boehm's algorithm; the curve is
/// unchanged as a point set and parametrisation. The multiplicity of t is capped at the degree
/// (further insertions are skipped: at multiplicity d the curve already interpolates a control
/// point there). An inconsistent shape or a NaN t returns the curve unchanged.
template <class T, int N>
[[nodiscard]] BSplineCurve<T, N> insert_knot(const BSplineCurve<T, N>& c, T t, int times = 1) {
  if (!detail::bspline_shape_ok(c.degree, c.control.size(), c.knots.size())) return c;
  const ParamDomain<T> dom = domain(c);
  t = detail::curve_clamp(t, dom.min, dom.max);
  if (t != t) return c;
  BSplineCurve<T, N> r = c;
  const int d = c.degree;
  for (int rep = 0; rep < times; ++rep) {
    int mult = 0;
    for (T k : r.knots) mult += (k == t) ? 1 : 0;
    if (mult >= d) break;
    const int n = static_cast<int>(r.control.size());
    const int k = find_span(std::span<const T>(r.knots), d, n, t);
    std::vector<Vec<T, N>> q(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      if (i <= k - d) {
        q[ui] = r.control[ui];
      } else if (i > k) {
        q[ui] = r.control[ui - 1];
      } else {
        const T lo = r.knots[ui];
        const T a = detail::knot_ratio(t - lo, r.knots[ui + static_cast<std::size_t>(d)] - lo);
        q[ui] = (T(1) - a) * r.control[ui - 1] + a * r.control[ui];
      }
    }
    r.control = std::move(q);
    r.knots.insert(r.knots.begin() + (k + 1), t);
  }
  return r;
}

/// A curve as consecutive Bézier pieces; segment i covers [breaks[i], breaks[i+1]].
template <class T, int N>
struct BezierSegments {
  Status status = Status::empty_input;
  std::vector<BezierCurve<T, N>> segments;
  std::vector<T> breaks;
};

/// Converts the curve over its domain to Bézier segments, one per non-empty knot span, by
/// inserting every distinct knot in [t_d, t_n] up to multiplicity d. Works for clamped and
/// unclamped knots. status is validate(c) (segments empty unless ok).
template <class T, int N>
[[nodiscard]] BezierSegments<T, N> to_bezier(const BSplineCurve<T, N>& c) {
  BezierSegments<T, N> out{validate(c), {}, {}};
  if (out.status != Status::ok) return out;
  const ParamDomain<T> dom = domain(c);
  BSplineCurve<T, N> r = c;
  std::vector<T> distinct;
  for (T k : c.knots)
    if (k >= dom.min && k <= dom.max && (distinct.empty() || distinct.back() != k))
      distinct.push_back(k);
  for (T u : distinct) r = insert_knot(r, u, r.degree);
  const int d = r.degree;
  const int n = static_cast<int>(r.control.size());
  for (int k = d; k < n; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    if (!(r.knots[uk] < r.knots[uk + 1])) continue;
    BezierCurve<T, N> b;
    b.control.assign(r.control.begin() + (k - d), r.control.begin() + (k + 1));
    if (out.breaks.empty()) out.breaks.push_back(r.knots[uk]);
    out.breaks.push_back(r.knots[uk + 1]);
    out.segments.push_back(std::move(b));
  }
  return out;
}

}  // namespace locus
