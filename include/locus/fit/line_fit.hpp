// SPDX-License-Identifier: BSL-1.0
#pragma once
// Least-squares line fits (row num.fit; book section 2.9, figure 2.9, and appendix A.7).
//
//   fit_line_vertical(points2)  the line y = slope x + intercept minimising the sum of squared
//                               VERTICAL distances (figure 2.9): linear least squares on the
//                               centred x (QR with column pivoting, numeric/least_squares.hpp).
//                               line = {(mean x, y at mean x), (1, slope)}: the parameter t is the
//                               x offset from the mean. rms = RMS vertical residual.
//   fit_line(points)            the line minimising the sum of squared ORTHOGONAL distances, in
//                               any dimension N >= 2: it passes through the mean, along the
//                               eigenvector of the covariance with the largest eigenvalue.
//                               line = {mean, unit direction}; the direction's sign is chosen so
//                               that its largest-magnitude component is positive.
//                               rms = RMS orthogonal distance of the points to the line.
//
// Degenerate input (FitOptions::rank_tolerance, see fit/fit_common.hpp for the rule): no points
// -> empty_input; NaN/Inf -> non_finite_input; fewer than 2 points, all points coincident
// (fit_line), or all x equal (fit_line_vertical, a vertical line has no slope) ->
// degenerate_input. Then the line is zero-initialised and rms is NaN. A direction that is not
// unique (an isotropic cloud, e.g. the vertices of a square) is NOT detected: any maximiser is
// returned. Computed in compute_t<T> (double for float input), rounded to T.
// Cost: O(n N^2) plus an N x N eigensolve (closed form for N = 2, 3).

#include <locus/fit/fit_common.hpp>
#include <locus/primitives/line.hpp>

#include <span>
#include <vector>

namespace locus {

/// Result of fit_line().
template <class T, int N>
struct LineFit {
  Status status = Status::empty_input;  ///< ok, empty_input, degenerate_input, non_finite_input
  Line<T, N> line{};                    ///< origin = mean, unit direction
  T rms{};                              ///< RMS orthogonal distance
};

/// Result of fit_line_vertical().
template <Real T>
struct VerticalLineFit {
  Status status = Status::empty_input;  ///< ok, empty_input, degenerate_input, non_finite_input
  T slope{};
  T intercept{};    ///< y = slope x + intercept
  Line2<T> line{};  ///< {(mean x, slope mean x + intercept), (1, slope)}
  T rms{};          ///< RMS vertical residual
};

/// Orthogonal least-squares line through points in N dimensions.
template <class T, int N>
[[nodiscard]] LineFit<T, N> fit_line(std::span<const Vec<T, N>> pts,
                                     const FitOptions<T>& opt = {}) {
  static_assert(N >= 2, "fit_line needs N >= 2");
  using C = compute_t<T>;
  LineFit<T, N> out;
  out.status = Status::ok;
  out.rms = std::numeric_limits<T>::quiet_NaN();
  out.status = detail::check_points(pts, 2);
  if (out.status != Status::ok) return out;
  const detail::Moments<C, N> m = detail::moments<C>(pts);
  const SymmetricEigen<C, N> e = detail::eigen_any(m.covariance);
  if (detail::negligible_variance<C, N>(e.values[N - 1], e.values[N - 1],
                                        detail::coordinate_scale<C>(pts) * m.scale,
                                        C(detail::fit_rank_tolerance(opt)))) {
    out.status = Status::degenerate_input;
    return out;
  }
  const Vec<C, N> d = detail::canonical_sign(col(e.vectors, N - 1));
  C s = C(0);
  for (const Vec<T, N>& p : pts) {
    const Vec<C, N> q = m.centred(p);
    s += std::max(C(0), sqr_length(q - dot(q, d) * d));
  }
  out.line = {vec_cast<T>(m.unscale(m.mean)), vec_cast<T>(d)};
  out.rms = T(m.unscale(std::sqrt(s / C(pts.size()))));
  out.status = e.status == Status::limit_exceeded ? Status::limit_exceeded : Status::ok;
  return out;
}

template <PointRange R>
[[nodiscard]] LineFit<range_scalar_t<R>, range_dimension_v<R>> fit_line(
    const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_line(point_span(pts), opt);
}

/// Least-squares line y = slope x + intercept with vertical residuals (figure 2.9).
template <Real T>
[[nodiscard]] VerticalLineFit<T> fit_line_vertical(std::span<const Vec2<T>> pts,
                                                   const FitOptions<T>& opt = {}) {
  VerticalLineFit<T> out;
  out.status = Status::ok;
  const detail::VerticalSolution<T, 2> v =
      detail::vertical_fit(pts, detail::fit_rank_tolerance(opt));
  out.status = v.status;
  out.rms = T(v.rms);
  if (v.status != Status::ok) return out;
  const auto mx = v.mean.x;
  out.slope = T(v.coef[0]);
  out.intercept = T(v.constant);
  out.line = {Vec2<T>{T(mx), T(v.coef[0] * mx + v.constant)}, Vec2<T>{T(1), T(v.coef[0])}};
  return out;
}

template <PointRange2 R>
[[nodiscard]] VerticalLineFit<range_scalar_t<R>> fit_line_vertical(
    const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_line_vertical(point_span(pts), opt);
}

}  // namespace locus
