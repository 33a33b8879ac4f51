// SPDX-License-Identifier: BSL-1.0
#pragma once
// Algebraic least-squares conics and quadrics (row num.fit; book appendix A.7, "fitting a
// quadratic curve / quadric surface"). Method (streaming Givens QR, then the SVD of the K x K
// triangle) and Hartley's normalisation: docs/notes/fit.md.
//
//   fit_quadratic_curve(points2)  QuadraticCurve2 {a, b, c, d, e, f}: a x^2 + b xy + c y^2 + d x
//                                 + e y + f = 0 (6 coefficients; at least 5 points)
//   fit_quadric(points3)          Quadric3 {A, b, c}: X^T A X + b . X + c = 0 with A symmetric,
//                                 i.e. the 10 coefficients of x^2, y^2, z^2, xy, xz, yz (= 2 A_01,
//                                 2 A_02, 2 A_12), x, y, z, 1 (at least 9 points)
// The coefficient vector w minimises sum_i (w . v(p_i))^2 over |w| = 1 (v(p) the monomials), in
// coordinates normalised by the points' mean and RMS radius, so the fit is invariant under
// translating and scaling the points. The returned coefficient vector (a, b, c, d, e, f), resp.
// (A_00, A_11, A_22, 2 A_01, 2 A_02, 2 A_12, b, c), has unit Euclidean norm, with its
// largest-magnitude entry positive. rms is the RMS algebraic residual of that returned unit
// vector over the points (not a distance).
//
// Degenerate input: no points -> empty_input; NaN/Inf -> non_finite_input; fewer than 5 (9)
// points, coincident points, or points through which the curve (surface) is not unique - the
// second-smallest singular value s_{K-2} <= tol * s_0 with tol = max(64 sqrt(K) eps(C),
// rank_tolerance * max|coordinate| / s) (e.g. 4 collinear points of 5, all points on a line, or
// for a quadric, points on a conic) -> degenerate_input with zero coefficients and rms NaN.
// Computed in compute_t<T>, rounded to T. Cost O(n K^2) with K = 6 or 10, plus a K x K SVD; no
// n x K matrix is stored.

#include <locus/fit/fit_common.hpp>
#include <locus/numeric/decompose.hpp>
#include <locus/primitives/quadratic_curve.hpp>
#include <locus/primitives/quadric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace locus {

/// Result of fit_quadratic_curve().
template <Real T>
struct QuadraticCurveFit {
  Status status = Status::empty_input;  ///< ok, empty_input, degenerate_input, non_finite_input
  QuadraticCurve2<T> curve{};           ///< unit coefficient vector (see the top comment)
  T rms{};                              ///< RMS algebraic residual
};

/// Result of fit_quadric().
template <Real T>
struct QuadricFit {
  Status status = Status::empty_input;  ///< ok, empty_input, degenerate_input, non_finite_input
  Quadric3<T> quadric{};                ///< unit coefficient vector (see the top comment)
  T rms{};                              ///< RMS algebraic residual
};

namespace detail {

// v(u) for the conic: x^2, xy, y^2, x, y, 1.
template <class C>
[[nodiscard]] std::array<C, 6> conic_monomials(const Vec2<C>& u) noexcept {
  return {u.x * u.x, u.x * u.y, u.y * u.y, u.x, u.y, C(1)};
}
// v(u) for the quadric: x^2, y^2, z^2, xy, xz, yz, x, y, z, 1.
template <class C>
[[nodiscard]] std::array<C, 10> quadric_monomials(const Vec3<C>& u) noexcept {
  return {u.x * u.x, u.y * u.y, u.z * u.z, u.x * u.y, u.x * u.z, u.y * u.z, u.x, u.y, u.z, C(1)};
}

// A quadratic X^T A X + b . X + c as (A, b, c) in the compute type.
template <class C, int N>
struct QuadraticForm {
  Mat<C, N, N> a{};
  Vec<C, N> b{};
  C c{};
};

template <class C, int N>
struct NullVectorResult {
  Status status = Status::empty_input;
  QuadraticForm<C, N> form;  ///< in the coordinates x = unit * p, not yet normalised
  C unit = C(1);             ///< power of two (see Moments)
};

/// The coefficient vector of a quadratic form in x = unit * p (coefficient i of degree
/// degree[i]) rewritten for p, normalised to unit length with its largest entry positive,
/// without forming unit^2 (which leaves the range at the ends of it): entry i is
/// qx[i] 2^(degree[i] j - e), j = log2(unit), e the largest exponent among them. Also the RMS
/// over the points of that unit vector's algebraic residual, from the residuals in x.
template <class C, int K>
struct UnitCoefficients {
  Vec<C, K> q{};
  C rms{};
};

template <class C, int K, class T, int N, class Monomials>
[[nodiscard]] UnitCoefficients<C, K> unit_coefficients(const Vec<C, K>& qx,
                                                       const std::array<int, K>& degree, C unit,
                                                       std::span<const Vec<T, N>> pts,
                                                       Monomials monomials) {
  const int j = std::ilogb(unit);
  int e = std::numeric_limits<int>::min();
  for (int i = 0; i < K; ++i)
    if (qx[i] != C(0)) e = std::max(e, std::ilogb(qx[i]) + degree[static_cast<std::size_t>(i)] * j);
  Vec<C, K> y{};
  for (int i = 0; i < K; ++i) y[i] = std::ldexp(qx[i], degree[static_cast<std::size_t>(i)] * j - e);
  const C len = length(y);
  UnitCoefficients<C, K> out;
  out.q = canonical_sign(y / len);
  // Entry i of q times monomial i of p = qx[i] monomial_i(x) 2^-e / len, up to the sign.
  C sum = C(0);
  for (const Vec<T, N>& p : pts) {
    const std::array<C, K> v = monomials(vec_cast<C>(p) * unit);
    C r = C(0);
    for (int i = 0; i < K; ++i) r += qx[i] * v[static_cast<std::size_t>(i)];
    sum += r * r;
  }
  out.rms = std::ldexp(std::sqrt(sum / C(pts.size())), -e) / len;
  return out;
}

// Smallest right singular vector of the design matrix of the normalised points, converted to a
// quadratic form in the original coordinates.
template <class C, class T, int N, int K, class Monomials, class ToForm>
[[nodiscard]] NullVectorResult<C, N> algebraic_quadratic(std::span<const Vec<T, N>> pts,
                                                         std::size_t needed, T rank_tol,
                                                         Monomials monomials, ToForm to_form) {
  NullVectorResult<C, N> out;
  out.status = Status::ok;
  out.status = check_points(pts, needed);
  if (out.status != Status::ok) return out;
  const Moments<C, N> m = moments<C>(pts);
  const C s = std::sqrt(trace(m.covariance));
  if (!(s > C(0))) {
    out.status = Status::degenerate_input;
    return out;
  }
  // Streaming Givens QR: R is the K x K triangle with R^T R = V^T V.
  MatX<C> r(K, K);
  for (const Vec<T, N>& p : pts) {
    std::array<C, K> w = monomials(m.centred(p) / s);
    for (int j = 0; j < K; ++j) {
      const C wj = w[static_cast<std::size_t>(j)];
      if (wj == C(0)) continue;
      const C rjj = r(j, j);
      const C h = std::hypot(rjj, wj);
      const C cs = rjj / h, sn = wj / h;
      for (int k = j; k < K; ++k) {
        const C rk = r(j, k), wk = w[static_cast<std::size_t>(k)];
        r(j, k) = cs * rk + sn * wk;
        w[static_cast<std::size_t>(k)] = -sn * rk + cs * wk;
      }
    }
  }
  const SVD<C> d = svd(r);
  if (d.status != Status::ok) {
    out.status = d.status == Status::limit_exceeded ? Status::degenerate_input : d.status;
    return out;
  }
  const C tol = std::max(C(64) * std::sqrt(C(K)) * eps_v<C>,
                         C(rank_tol) * coordinate_scale<C>(pts) * m.scale / s);
  if (!(d.s[K - 2] > tol * d.s[0])) {
    out.status = Status::degenerate_input;
    return out;
  }
  std::array<C, K> w{};
  for (int k = 0; k < K; ++k) w[static_cast<std::size_t>(k)] = d.v(k, K - 1);
  const QuadraticForm<C, N> fu = to_form(w);
  // u = (x - mean) / s: u^T Au u + bu . u + cu = x^T (Au/s^2) x + (bu/s - 2 Au mean/s^2) . x
  //                                               + mean^T Au mean / s^2 - bu . mean / s + cu.
  const Vec<C, N> am = fu.a * m.mean;
  out.form.a = fu.a * (C(1) / (s * s));
  out.form.b = fu.b / s - am * (C(2) / (s * s));
  out.form.c = dot(m.mean, am) / (s * s) - dot(fu.b, m.mean) / s + fu.c;
  out.unit = m.scale;
  return out;
}

}  // namespace detail

/// Algebraic least-squares conic through points (see the top comment for the normalisation).
template <Real T>
[[nodiscard]] QuadraticCurveFit<T> fit_quadratic_curve(std::span<const Vec2<T>> pts,
                                                       const FitOptions<T>& opt = {}) {
  using C = compute_t<T>;
  QuadraticCurveFit<T> out;
  out.status = Status::ok;
  out.rms = std::numeric_limits<T>::quiet_NaN();
  const auto res = detail::algebraic_quadratic<C, T, 2, 6>(
      pts, 5, detail::fit_rank_tolerance(opt),
      [](const Vec2<C>& u) { return detail::conic_monomials(u); },
      [](const std::array<C, 6>& w) {
        detail::QuadraticForm<C, 2> f;
        f.a = Mat2<C>::from_rows(Vec2<C>{w[0], w[1] / C(2)}, Vec2<C>{w[1] / C(2), w[2]});
        f.b = {w[3], w[4]};
        f.c = w[5];
        return f;
      });
  out.status = res.status;
  if (res.status != Status::ok) return out;
  const detail::QuadraticForm<C, 2>& f = res.form;
  const Vec<C, 6> qx{f.a(0, 0), C(2) * f.a(0, 1), f.a(1, 1), f.b.x, f.b.y, f.c};
  const auto u =
      detail::unit_coefficients<C, 6>(qx, {2, 2, 2, 1, 1, 0}, res.unit, pts,
                                      [](const Vec2<C>& x) { return detail::conic_monomials(x); });
  const Vec<C, 6>& q = u.q;
  out.curve = {T(q[0]), T(q[1]), T(q[2]), T(q[3]), T(q[4]), T(q[5])};
  out.rms = T(u.rms);
  return out;
}

template <PointRange2 R>
[[nodiscard]] QuadraticCurveFit<range_scalar_t<R>> fit_quadratic_curve(
    const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_quadratic_curve(point_span(pts), opt);
}

/// Algebraic least-squares quadric surface through points (see the top comment).
template <Real T>
[[nodiscard]] QuadricFit<T> fit_quadric(std::span<const Vec3<T>> pts,
                                        const FitOptions<T>& opt = {}) {
  using C = compute_t<T>;
  QuadricFit<T> out;
  out.status = Status::ok;
  out.rms = std::numeric_limits<T>::quiet_NaN();
  const auto res = detail::algebraic_quadratic<C, T, 3, 10>(
      pts, 9, detail::fit_rank_tolerance(opt),
      [](const Vec3<C>& u) { return detail::quadric_monomials(u); },
      [](const std::array<C, 10>& w) {
        detail::QuadraticForm<C, 3> f;
        f.a = Mat3<C>::from_rows(Vec3<C>{w[0], w[3] / C(2), w[4] / C(2)},
                                 Vec3<C>{w[3] / C(2), w[1], w[5] / C(2)},
                                 Vec3<C>{w[4] / C(2), w[5] / C(2), w[2]});
        f.b = {w[6], w[7], w[8]};
        f.c = w[9];
        return f;
      });
  out.status = res.status;
  if (res.status != Status::ok) return out;
  const detail::QuadraticForm<C, 3>& f = res.form;
  const Vec<C, 10> qx{
      f.a(0, 0), f.a(1, 1), f.a(2, 2), C(2) * f.a(0, 1), C(2) * f.a(0, 2), C(2) * f.a(1, 2), f.b.x,
      f.b.y,     f.b.z,     f.c};
  const auto u = detail::unit_coefficients<C, 10>(
      qx, {2, 2, 2, 2, 2, 2, 1, 1, 1, 0}, res.unit, pts,
      [](const Vec3<C>& x) { return detail::quadric_monomials(x); });
  const Vec<C, 10>& q = u.q;
  out.quadric.a = Mat3<T>::from_rows(Vec3<T>{T(q[0]), T(q[3] / C(2)), T(q[4] / C(2))},
                                     Vec3<T>{T(q[3] / C(2)), T(q[1]), T(q[5] / C(2))},
                                     Vec3<T>{T(q[4] / C(2)), T(q[5] / C(2)), T(q[2])});
  out.quadric.b = {T(q[6]), T(q[7]), T(q[8])};
  out.quadric.c = T(q[9]);
  out.rms = T(u.rms);
  return out;
}

template <PointRange3 R>
[[nodiscard]] QuadricFit<range_scalar_t<R>> fit_quadric(
    const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_quadric(point_span(pts), opt);
}

}  // namespace locus
