// SPDX-License-Identifier: BSL-1.0
#pragma once
// Least-squares plane and hyperplane fits (row num.fit; book section 2.9 and appendix A.7).
//
//   fit_plane(points3)            the plane minimising the sum of squared ORTHOGONAL distances:
//                                 through the mean, normal = the eigenvector of the covariance
//                                 with the smallest eigenvalue. Plane3 {unit normal, constant =
//                                 dot(normal, mean)}.
//   fit_hyperplane(points)        the same in N dimensions (N >= 2): {unit normal, constant},
//                                 the set { X : dot(normal, X) = constant }.
//   fit_hyperplane_vertical(pts)  x_{N-1} = sum_{j < N-1} coefficients[j] x_j + constant with
//                                 VERTICAL residuals (the book's z = a x + b y + c for N = 3):
//                                 linear least squares on centred columns (QR with column
//                                 pivoting, numeric/least_squares.hpp).
// Normal signs are arbitrary for a least-squares fit; the returned normal has its
// largest-magnitude component positive. rms is the RMS orthogonal distance (vertical residual
// for the vertical fit) of the points.
//
// Degenerate input (rule and FitOptions::rank_tolerance in fit/fit_common.hpp): no points ->
// empty_input; NaN/Inf -> non_finite_input; fewer than N points, or points that span fewer than
// N - 1 dimensions (coincident, or collinear for a plane) -> degenerate_input; for the vertical
// fit, independent coordinates that span fewer than N - 1 dimensions (a vertical hyperplane) ->
// degenerate_input. Then the result is zero-initialised and rms is NaN. A normal that is not
// unique because the two smallest spreads are equal (e.g. an isotropic 3D cloud) is not
// detected: one of the minimisers is returned. Computed in compute_t<T>, rounded to T.
// Cost: O(n N^2) plus an N x N eigensolve (closed form for N = 2, 3; Jacobi otherwise).

#include <locus/fit/fit_common.hpp>
#include <locus/primitives/plane.hpp>

#include <limits>
#include <span>
#include <vector>

namespace locus {

/// Result of fit_hyperplane(): the set { X : dot(normal, X) = constant }, normal unit length.
template <class T, int N>
struct HyperplaneFit {
  Status status = Status::empty_input;  ///< ok, empty_input, degenerate_input, non_finite_input
  Vec<T, N> normal{};
  T constant{};
  T rms{};  ///< RMS orthogonal distance
};

/// Result of fit_plane().
template <Real T>
struct PlaneFit {
  Status status = Status::empty_input;  ///< ok, empty_input, degenerate_input, non_finite_input
  Plane3<T> plane{};                    ///< unit normal
  T rms{};                              ///< RMS orthogonal distance
};

/// Result of fit_hyperplane_vertical(): x_{N-1} = dot(coefficients, x_{0..N-2}) + constant.
template <class T, int N>
struct VerticalHyperplaneFit {
  Status status = Status::empty_input;  ///< ok, empty_input, degenerate_input, non_finite_input
  Vec<T, N - 1> coefficients{};
  T constant{};
  T rms{};  ///< RMS vertical residual
};

/// Orthogonal least-squares hyperplane through points in N dimensions.
template <class T, int N>
[[nodiscard]] HyperplaneFit<T, N> fit_hyperplane(std::span<const Vec<T, N>> pts,
                                                 const FitOptions<T>& opt = {}) {
  static_assert(N >= 2, "fit_hyperplane needs N >= 2");
  using C = compute_t<T>;
  HyperplaneFit<T, N> out;
  out.status = Status::ok;
  out.rms = std::numeric_limits<T>::quiet_NaN();
  out.status = detail::check_points(pts, static_cast<std::size_t>(N));
  if (out.status != Status::ok) return out;
  const detail::Moments<C, N> m = detail::moments<C>(pts);
  const SymmetricEigen<C, N> e = detail::eigen_any(m.covariance);
  if (detail::negligible_variance<C, N>(e.values[1], e.values[N - 1],
                                        detail::coordinate_scale<C>(pts) * m.scale,
                                        C(detail::fit_rank_tolerance(opt)))) {
    out.status = Status::degenerate_input;
    return out;
  }
  const Vec<C, N> n = detail::canonical_sign(col(e.vectors, 0));
  C s = C(0);
  for (const Vec<T, N>& p : pts) s += sqr(dot(n, m.centred(p)));
  out.normal = vec_cast<T>(n);
  out.constant = T(m.unscale(dot(n, m.mean)));
  out.rms = T(m.unscale(std::sqrt(s / C(pts.size()))));
  out.status = e.status == Status::limit_exceeded ? Status::limit_exceeded : Status::ok;
  return out;
}

template <PointRange R>
[[nodiscard]] HyperplaneFit<range_scalar_t<R>, range_dimension_v<R>> fit_hyperplane(
    const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_hyperplane(point_span(pts), opt);
}

/// Orthogonal least-squares plane through points in 3D.
template <Real T>
[[nodiscard]] PlaneFit<T> fit_plane(std::span<const Vec3<T>> pts, const FitOptions<T>& opt = {}) {
  const HyperplaneFit<T, 3> h = fit_hyperplane(pts, opt);
  return {h.status, Plane3<T>{h.normal, h.constant}, h.rms};
}

template <PointRange3 R>
[[nodiscard]] PlaneFit<range_scalar_t<R>> fit_plane(const R& pts,
                                                    const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_plane(point_span(pts), opt);
}

/// Least-squares hyperplane x_{N-1} = f(x_0..x_{N-2}) with vertical residuals.
template <class T, int N>
[[nodiscard]] VerticalHyperplaneFit<T, N> fit_hyperplane_vertical(std::span<const Vec<T, N>> pts,
                                                                  const FitOptions<T>& opt = {}) {
  static_assert(N >= 2, "fit_hyperplane_vertical needs N >= 2");
  VerticalHyperplaneFit<T, N> out;
  out.status = Status::ok;
  const detail::VerticalSolution<T, N> v =
      detail::vertical_fit(pts, detail::fit_rank_tolerance(opt));
  out.status = v.status;
  out.rms = T(v.rms);
  if (v.status != Status::ok) return out;
  out.coefficients = vec_cast<T>(v.coef);
  out.constant = T(v.constant);
  return out;
}

template <PointRange R>
[[nodiscard]] VerticalHyperplaneFit<range_scalar_t<R>, range_dimension_v<R>>
fit_hyperplane_vertical(const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_hyperplane_vertical(point_span(pts), opt);
}

}  // namespace locus
