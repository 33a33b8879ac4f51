// SPDX-License-Identifier: BSL-1.0
#pragma once
// Gaussian distribution fit and the oriented box it defines (row num.fit; book appendix A.7,
// "fitting a Gaussian distribution": mean + covariance -> oriented box).
//
// fit_gaussian(points, extent) computes the mean m and the covariance
//   S = (1/n) sum_i (p_i - m)(p_i - m)^T        (normalised by n: the maximum-likelihood
//                                                 estimate, not the unbiased 1/(n-1))
// and returns the OrientedBox whose axes are the unit eigenvectors of S, ordered by ASCENDING
// eigenvalue (axis[N-1] is the principal direction), and whose extents are either
//   GaussianExtent::std_dev  extent[i] = sqrt(lambda_i), the standard deviation along axis i,
//                            centred at the mean (the 1-sigma box), or
//   GaussianExtent::points   the half range of the projections of the points on axis i, with
//                            the centre moved to the middle of those ranges (the smallest box
//                            with these axes that contains every point).
// The result also holds the mean, the covariance and rms = sqrt(trace S), the RMS distance of
// the points to the mean. The axes are a right-handed frame for N = 2, 3.
//
// Bad input: no points -> empty_input; a NaN/Inf coordinate -> non_finite_input (box zero). One
// point, or points spanning fewer than N dimensions, is valid data: a flat box (zero extents).
// Computed in compute_t<T> (double for float input). Cost O(n N^2) plus an N x N eigensolve.

#include <locus/fit/fit_common.hpp>
#include <locus/primitives/oriented_box.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// How fit_gaussian() sizes its box (see the top comment).
enum class GaussianExtent : std::uint8_t {
  std_dev,  ///< extent = standard deviation along each axis, centred at the mean
  points,   ///< the box containing all points, with the covariance's axes
};

/// Result of fit_gaussian().
template <class T, int N>
struct GaussianFit {
  Status status =
      Status::empty_input;  ///< ok, empty_input, non_finite_input, limit_exceeded (Jacobi)
  OrientedBox<T, N> box{};  ///< axes = eigenvectors of the covariance, ascending eigenvalue
  Vec<T, N> mean{};
  Mat<T, N, N> covariance{};  ///< normalised by n
  T rms{};                    ///< RMS distance to the mean, sqrt(trace(covariance))
};

/// Mean, covariance and the oriented box of a point set (see the top comment).
template <class T, int N>
[[nodiscard]] GaussianFit<T, N> fit_gaussian(std::span<const Vec<T, N>> pts,
                                             GaussianExtent extent = GaussianExtent::std_dev) {
  using C = compute_t<T>;
  GaussianFit<T, N> out;
  out.status = Status::ok;
  out.status = detail::check_points(pts, 1);
  if (out.status != Status::ok) return out;
  const detail::Moments<C, N> m = detail::moments<C>(pts);
  const SymmetricEigen<C, N> e = detail::eigen_any(m.covariance);
  out.status = e.status;
  out.mean = vec_cast<T>(m.unscale(m.mean));
  // Divided by the scale twice: a covariance beyond the range of C is lost only there.
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) out.covariance(r, c) = T(m.unscale(m.unscale(m.covariance(r, c))));
  out.rms = T(m.unscale(std::sqrt(std::max(trace(m.covariance), C(0)))));
  Vec<C, N> center = m.mean;
  Vec<C, N> half{};
  if (extent == GaussianExtent::std_dev) {
    for (int i = 0; i < N; ++i) half[i] = std::sqrt(std::max(e.values[i], C(0)));
  } else {
    Vec<C, N> lo = splat<C, N>(C(0)), hi = splat<C, N>(C(0));
    for (const Vec<T, N>& p : pts) {
      const Vec<C, N> d = m.centred(p);
      for (int i = 0; i < N; ++i) {
        const C s = dot(col(e.vectors, i), d);
        lo[i] = std::min(lo[i], s);
        hi[i] = std::max(hi[i], s);
      }
    }
    for (int i = 0; i < N; ++i) {
      half[i] = (hi[i] - lo[i]) / C(2);
      center += ((hi[i] + lo[i]) / C(2)) * col(e.vectors, i);
    }
  }
  out.box.center = vec_cast<T>(m.unscale(center));
  for (int i = 0; i < N; ++i) out.box.axis[i] = vec_cast<T>(col(e.vectors, i));
  out.box.extent = vec_cast<T>(m.unscale(half));
  return out;
}

template <PointRange R>
[[nodiscard]] GaussianFit<range_scalar_t<R>, range_dimension_v<R>> fit_gaussian(
    const R& pts, GaussianExtent extent = GaussianExtent::std_dev) {
  return fit_gaussian(point_span(pts), extent);
}

}  // namespace locus
