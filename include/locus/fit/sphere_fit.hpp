// SPDX-License-Identifier: BSL-1.0
#pragma once
// Least-squares spheres (and hyperspheres; circles are in circle_fit.hpp) (row num.fit; book
// section 2.9 and appendix A.7). The Levenberg-Marquardt details: docs/notes/fit.md.
//
//   fit_sphere_algebraic(points)  minimises sum_i (|p_i|^2 + D . p_i + F)^2, the ALGEBRAIC
//                                 distance of x^2 + D . x + F = 0: one linear least-squares
//                                 solve in (D, F) on centred, unit-RMS points (QR with column
//                                 pivoting). center = -D/2, radius^2 = |D|^2/4 - F. Biased
//                                 towards smaller spheres on short arcs but a good start for:
//   fit_sphere(points)            the GEOMETRIC fit, minimising sum_i (|p_i - c| - r)^2 over (c, r)
//                                 by Levenberg-Marquardt from the algebraic solution. Stops when
//                                 a step is below 16 eps(C) relative to the parameters, the cost
//                                 is 0, or no decrease is possible; FitOptions::max_iterations
//                                 bounds the iterations (Status::limit_exceeded, the best sphere
//                                 so far).
// Both work in any dimension N >= 2 and return Sphere<T, N>; rms is the RMS GEOMETRIC distance
// | |p_i - c| - r | for both (so they are comparable).
//
// Degenerate input (rule and FitOptions::rank_tolerance in fit/fit_common.hpp): no points ->
// empty_input; NaN/Inf -> non_finite_input; fewer than N + 1 points, or points in a hyperplane
// (coplanar for a sphere, collinear for a circle: the sphere is not determined, or its radius is
// infinite) -> degenerate_input, with a zero sphere and rms NaN. Computed in compute_t<T>.
// Cost: O(n N^2) per Levenberg-Marquardt iteration; allocates n normalised points.

#include <locus/core/linear_system.hpp>
#include <locus/core/point_range.hpp>
#include <locus/fit/fit_common.hpp>
#include <locus/primitives/sphere.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace locus {

/// Result of the sphere fits.
template <class T, int N>
struct SphereFit {
  Status status =
      Status::empty_input;  ///< ok, empty_input, degenerate_input, non_finite_input,
                            ///< limit_exceeded (geometric fit budget; best sphere so far)
  Sphere<T, N> sphere{};
  T rms{};             ///< RMS geometric distance of the points to the sphere
  int iterations = 0;  ///< Levenberg-Marquardt iterations (0 for the algebraic fit)
};

namespace detail {

template <class C, int N>
struct NormalizedSphereProblem {
  Status status = Status::empty_input;
  std::vector<Vec<C, N>> q;  ///< (unit p - mean) / scale
  C unit{};                  ///< power of two: the fit works on unit * p (see Moments)
  Vec<C, N> mean{};          ///< of unit * p
  C scale{};                 ///< RMS radius of unit * p about the mean
  Vec<C, N> center{};        ///< algebraic solution in normalised coordinates
  C radius{};
};

template <class C, class T, int N>
[[nodiscard]] NormalizedSphereProblem<C, N> algebraic_sphere(std::span<const Vec<T, N>> pts,
                                                             T rank_tol) {
  NormalizedSphereProblem<C, N> out;
  out.status = Status::ok;
  out.status = check_points(pts, static_cast<std::size_t>(N + 1));
  if (out.status != Status::ok) return out;
  const Moments<C, N> m = moments<C>(pts);
  const SymmetricEigen<C, N> e = eigen_any(m.covariance);
  if (negligible_variance<C, N>(e.values[0], e.values[N - 1], coordinate_scale<C>(pts) * m.scale,
                                C(rank_tol))) {
    out.status = Status::degenerate_input;
    return out;
  }
  out.unit = m.scale;
  out.mean = m.mean;
  out.scale = std::sqrt(trace(m.covariance));
  const std::size_t n = pts.size();
  out.q.resize(n);
  constexpr std::size_t cols = N + 1;
  std::vector<C> a(n * cols), b(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<C, N> q = m.centred(pts[i]) / out.scale;
    out.q[i] = q;
    for (int j = 0; j < N; ++j) a[i * cols + static_cast<std::size_t>(j)] = q[j];
    a[i * cols + N] = C(1);
    b[i] = -sqr_length(q);
  }
  const LeastSquares<C> ls = least_squares(a, static_cast<int>(n), N + 1, b);
  if (ls.status != Status::ok) {
    out.status = Status::degenerate_input;
    return out;
  }
  for (int j = 0; j < N; ++j) out.center[j] = -ls.x[static_cast<std::size_t>(j)] / C(2);
  const C r2 = sqr_length(out.center) - ls.x[N];
  if (!(r2 > C(0)) || !is_finite(r2)) {
    out.status = Status::degenerate_input;
    return out;
  }
  out.radius = std::sqrt(r2);
  return out;
}

template <class C, int N>
[[nodiscard]] C sphere_cost(const std::vector<Vec<C, N>>& q, const Vec<C, N>& c, C r) noexcept {
  C s = C(0);
  for (const Vec<C, N>& p : q) s += sqr(length(p - c) - r);
  return s;
}

// The cost sum (|q_i - c| - r)^2, and J^T J and J^T e of its residuals at (c, r).
template <class C, int N>
C sphere_normal_equations(const std::vector<Vec<C, N>>& q, const Vec<C, N>& c, C r,
                          Mat<C, N + 1, N + 1>& jtj, Vec<C, N + 1>& jte) noexcept {
  constexpr int P = N + 1;
  jtj = Mat<C, P, P>{};
  jte = Vec<C, P>{};
  C cost = C(0);
  for (const Vec<C, N>& p : q) {
    const Vec<C, N> d = p - c;
    const C len = length(d);
    Vec<C, P> row{};
    if (len > C(0))
      for (int j = 0; j < N; ++j) row[j] = -d[j] / len;
    row[N] = C(-1);
    const C res = len - r;
    cost += res * res;
    for (int a = 0; a < P; ++a) {
      jte[a] += row[a] * res;
      for (int b = a; b < P; ++b) jtj(a, b) += row[a] * row[b];
    }
  }
  for (int a = 0; a < P; ++a)
    for (int b = 0; b < a; ++b) jtj(a, b) = jtj(b, a);
  return cost;
}

template <class T, class C, int N>
[[nodiscard]] SphereFit<T, N> sphere_result(const NormalizedSphereProblem<C, N>& pr,
                                            const Vec<C, N>& c, C r, C cost, Status st,
                                            int iterations) {
  SphereFit<T, N> out;
  out.status = Status::ok;
  out.status = st;
  out.sphere = {vec_cast<T>((pr.mean + pr.scale * c) / pr.unit), T(pr.scale * r / pr.unit)};
  out.rms = T(pr.scale * std::sqrt(cost / C(pr.q.size())) / pr.unit);
  out.iterations = iterations;
  return out;
}

}  // namespace detail

/// Algebraic least-squares sphere (see the top comment).
template <class T, int N>
[[nodiscard]] SphereFit<T, N> fit_sphere_algebraic(std::span<const Vec<T, N>> pts,
                                                   const FitOptions<T>& opt = {}) {
  using C = compute_t<T>;
  const detail::NormalizedSphereProblem<C, N> pr =
      detail::algebraic_sphere<C>(pts, detail::fit_rank_tolerance(opt));
  if (pr.status != Status::ok) {
    SphereFit<T, N> out;
    out.status = Status::ok;
    out.status = pr.status;
    out.rms = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  return detail::sphere_result<T>(pr, pr.center, pr.radius,
                                  detail::sphere_cost(pr.q, pr.center, pr.radius), Status::ok, 0);
}

template <PointRange R>
[[nodiscard]] SphereFit<range_scalar_t<R>, range_dimension_v<R>> fit_sphere_algebraic(
    const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_sphere_algebraic(point_span(pts), opt);
}

/// Geometric least-squares sphere by Levenberg-Marquardt (see the top comment).
template <class T, int N>
[[nodiscard]] SphereFit<T, N> fit_sphere(std::span<const Vec<T, N>> pts,
                                         const FitOptions<T>& opt = {}) {
  using C = compute_t<T>;
  constexpr int P = N + 1;  // unknowns: center, radius
  const detail::NormalizedSphereProblem<C, N> pr =
      detail::algebraic_sphere<C>(pts, detail::fit_rank_tolerance(opt));
  if (pr.status != Status::ok) {
    SphereFit<T, N> out;
    out.status = Status::ok;
    out.status = pr.status;
    out.rms = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  Vec<C, N> c = pr.center;
  C r = pr.radius;
  Mat<C, P, P> jtj{};
  Vec<C, P> jte{};
  C cost = detail::sphere_normal_equations(pr.q, c, r, jtj, jte);
  C damping = C(1e-3);
  bool converged = cost == C(0);
  int it = 0;
  while (!converged && it < opt.max_iterations) {
    ++it;
    bool accepted = false;
    while (!accepted && damping <= C(1e16)) {
      Mat<C, P, P> h = jtj;
      for (int a = 0; a < P; ++a) h(a, a) += damping * std::max(jtj(a, a), eps_v<C>);
      const LinearSolution<C, Vec<C, P>> step = solve(h, -jte);
      if (step.singular) {
        damping *= C(10);
        continue;
      }
      Vec<C, N> c_new = c;
      for (int j = 0; j < N; ++j) c_new[j] += step.x[j];
      const C r_new = r + step.x[N];
      Mat<C, P, P> jtj_new{};
      Vec<C, P> jte_new{};
      const C cost_new = detail::sphere_normal_equations(pr.q, c_new, r_new, jtj_new, jte_new);
      const C pnorm = C(1) + std::sqrt(sqr_length(c) + r * r);
      const bool tiny = std::sqrt(sqr_length(step.x)) <= C(16) * eps_v<C> * pnorm;
      // Near the minimum the decrease of the cost drops below its rounding error while the
      // gradient is still well above it; a step that does not raise the cost beyond rounding
      // and shrinks the gradient is then accepted too.
      const bool lower = cost_new < cost;
      const bool flat_better = cost_new <= cost * (C(1) + C(8) * eps_v<C> * C(pr.q.size())) &&
                               sqr_length(jte_new) < sqr_length(jte);
      if (lower || flat_better) {
        c = c_new;
        r = r_new;
        cost = cost_new;
        jtj = jtj_new;
        jte = jte_new;
        damping = std::max(damping / C(10), C(1e-12));
        accepted = true;
      } else {
        damping *= C(10);
      }
      if (tiny || cost == C(0)) {
        converged = true;
        break;
      }
    }
    if (damping > C(1e16)) converged = true;  // no step lowers the cost: a minimum
  }
  return detail::sphere_result<T>(pr, c, r, cost, converged ? Status::ok : Status::limit_exceeded,
                                  it);
}

template <PointRange R>
[[nodiscard]] SphereFit<range_scalar_t<R>, range_dimension_v<R>> fit_sphere(
    const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_sphere(point_span(pts), opt);
}

}  // namespace locus
