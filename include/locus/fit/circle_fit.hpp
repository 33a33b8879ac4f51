// SPDX-License-Identifier: BSL-1.0
#pragma once
// Least-squares circles in the plane (row num.fit; book section 2.9 and appendix A.7).
//
//   fit_circle_algebraic(points)  minimises sum_i (x_i^2 + y_i^2 + D x_i + E y_i + F)^2, a linear
//                                 least-squares problem (one solve, no iteration);
//   fit_circle(points)            the geometric fit, minimising sum_i (|p_i - c| - r)^2 by
//                                 Levenberg-Marquardt from the algebraic circle.
// Both are the N = 2 case of fit/sphere_fit.hpp (see there for the normalisation, the stopping
// rule and the iteration budget); rms is the RMS geometric distance | |p_i - c| - r |.
//
// Degenerate input: no points -> empty_input; NaN/Inf -> non_finite_input; fewer than 3 points,
// or collinear / coincident points (rule of fit/fit_common.hpp) -> degenerate_input with a zero
// circle and rms NaN. The geometric fit's budget (FitOptions::max_iterations) gives
// limit_exceeded with the best circle so far. Computed in compute_t<T>, rounded to T.

#include <locus/fit/sphere_fit.hpp>
#include <locus/primitives/circle.hpp>

#include <span>
#include <vector>

namespace locus {

/// Result of the circle fits.
template <Real T>
struct CircleFit {
  Status status =
      Status::empty_input;  ///< ok, empty_input, degenerate_input, non_finite_input,
                            ///< limit_exceeded (geometric fit budget; best circle so far)
  Circle2<T> circle{};
  T rms{};             ///< RMS geometric distance of the points to the circle
  int iterations = 0;  ///< Levenberg-Marquardt iterations (0 for the algebraic fit)
};

namespace detail {
template <Real T>
[[nodiscard]] CircleFit<T> to_circle_fit(const SphereFit<T, 2>& s) noexcept {
  return {s.status, Circle2<T>{s.sphere.center, s.sphere.radius}, s.rms, s.iterations};
}
}  // namespace detail

/// Algebraic least-squares circle.
template <Real T>
[[nodiscard]] CircleFit<T> fit_circle_algebraic(std::span<const Vec2<T>> pts,
                                                const FitOptions<T>& opt = {}) {
  return detail::to_circle_fit(fit_sphere_algebraic(pts, opt));
}
template <PointRange2 R>
[[nodiscard]] CircleFit<range_scalar_t<R>> fit_circle_algebraic(
    const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_circle_algebraic(point_span(pts), opt);
}

/// Geometric least-squares circle (Levenberg-Marquardt from the algebraic fit).
template <Real T>
[[nodiscard]] CircleFit<T> fit_circle(std::span<const Vec2<T>> pts, const FitOptions<T>& opt = {}) {
  return detail::to_circle_fit(fit_sphere(pts, opt));
}
template <PointRange2 R>
[[nodiscard]] CircleFit<range_scalar_t<R>> fit_circle(
    const R& pts, const FitOptions<range_scalar_t<R>>& opt = {}) {
  return fit_circle(point_span(pts), opt);
}

}  // namespace locus
