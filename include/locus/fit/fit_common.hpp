// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared pieces of the least-squares fits (row num.fit; book section 2.9 and appendix A.7):
// FitOptions, the mean and covariance of a point set, and the rule that decides when a spread
// is "zero" (the input lacks a dimension the fit needs).
//
// Degeneracy rule. A standard deviation s_i of the points along a principal axis counts as zero
// when s_i <= rank_tolerance * (largest |coordinate|) - below that it is indistinguishable from
// the rounding of the input coordinates (default rank_tolerance = 32 eps(T)) - or when the
// variance s_i^2 <= 64 N eps(C) times the largest variance, the resolution of an eigensolver
// applied to a rounded covariance (computing the covariance squares the data's condition, so the
// covariance-based fits cannot see a relative width below about sqrt(eps(C))). C = compute_t<T>:
// every fit computes in double for float input and rounds its result to T.
//
// Scale: every fit works on the points scaled by a power of two that brings the largest
// |coordinate| near 1 (Moments), so it is scale-covariant over the whole finite range.
// Cost: O(n N^2) for the covariance; no allocation beyond the fits' own.

#include <locus/config.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/numeric/eigen_sym.hpp>
#include <locus/numeric/least_squares.hpp>
#include <locus/numeric/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace locus {

/// Options shared by the fits.
template <Real T>
struct FitOptions {
  /// A spread below rank_tolerance * max|coordinate| counts as zero (see the top comment);
  /// a negative value selects 32 eps(T).
  T rank_tolerance = T(-1);
  /// Budget of the iterative (geometric) fits; running out gives Status::limit_exceeded.
  int max_iterations = 100;
};

namespace detail {

template <Real T>
[[nodiscard]] T fit_rank_tolerance(const FitOptions<T>& opt) noexcept {
  return opt.rank_tolerance >= T(0) ? opt.rank_tolerance : T(32) * eps_v<T>;
}

/// Status of a point set before fitting: empty, non-finite, or fewer than `needed` points.
template <class T, int N>
[[nodiscard]] Status check_points(std::span<const Vec<T, N>> pts, std::size_t needed) noexcept {
  if (pts.empty()) return Status::empty_input;
  for (const Vec<T, N>& p : pts)
    if (!is_finite(p)) return Status::non_finite_input;
  return pts.size() < needed ? Status::degenerate_input : Status::ok;
}

/// Largest |coordinate| of the points (the scale of their rounding errors).
template <class C, class T, int N>
[[nodiscard]] C coordinate_scale(std::span<const Vec<T, N>> pts) noexcept {
  // Branch-free (compiles to max instructions): the inputs are finite, checked before.
  C m = C(0);
  for (const Vec<T, N>& p : pts)
    for (int i = 0; i < N; ++i) {
      const C v = std::abs(C(p[i]));
      m = v > m ? v : m;
    }
  return m;
}

/// Mean and covariance (normalised by n) in the compute type, by two passes (no cancellation),
/// of the points scaled by `scale`, a power of two that brings the largest |coordinate| to
/// [1, 2): then no product of two coordinates leaves the exponent range whatever the input's
/// magnitude, and every result computed from the scaled points is the same for the input
/// scaled by any power of two. A fit maps its lengths back by dividing by `scale` (exact).
template <class C, int N>
struct Moments {
  C scale = C(1);             ///< power of two; scaled point = scale * p
  Vec<C, N> mean{};           ///< of the scaled points
  Mat<C, N, N> covariance{};  ///< of the scaled points

  template <class T>
  [[nodiscard]] Vec<C, N> scaled(const Vec<T, N>& p) const noexcept {
    return vec_cast<C>(p) * scale;
  }
  template <class T>
  [[nodiscard]] Vec<C, N> centred(const Vec<T, N>& p) const noexcept {
    return scaled(p) - mean;
  }
  /// A length (or coordinate) of the scaled points back in the input's units.
  [[nodiscard]] C unscale(C x) const noexcept { return x / scale; }
  [[nodiscard]] Vec<C, N> unscale(const Vec<C, N>& x) const noexcept { return x / scale; }
};

template <class C, class T, int N>
[[nodiscard]] Moments<C, N> moments(std::span<const Vec<T, N>> pts) noexcept {
  Moments<C, N> m;
  m.scale = normalising_scale(coordinate_scale<C>(pts));
  const C inv_n = C(1) / C(pts.size());
  for (const Vec<T, N>& p : pts) m.mean += m.scaled(p);
  m.mean *= inv_n;
  for (const Vec<T, N>& p : pts) {
    const Vec<C, N> d = m.centred(p);
    for (int r = 0; r < N; ++r)
      for (int c = r; c < N; ++c) m.covariance(r, c) += d[r] * d[c];
  }
  for (int r = 0; r < N; ++r)
    for (int c = r; c < N; ++c)
      m.covariance(c, r) = m.covariance(r, c) = m.covariance(r, c) * inv_n;
  return m;
}

/// Symmetric eigendecomposition for any fixed N (closed forms for 2 and 3, Jacobi otherwise).
template <class C, int N>
[[nodiscard]] SymmetricEigen<C, N> eigen_any(const Mat<C, N, N>& a) {
  if constexpr (N == 2 || N == 3) {
    return eigen_symmetric(a);
  } else {
    const SymmetricEigenX<C> e = eigen_symmetric(MatX<C>(a));
    SymmetricEigen<C, N> out;
    out.status = Status::ok;
    out.status = e.status;
    for (int i = 0; i < N; ++i) {
      out.values[i] = e.values[static_cast<std::size_t>(i)];
      for (int r = 0; r < N; ++r) out.vectors(r, i) = e.vectors(r, i);
    }
    return out;
  }
}

/// True when the variance `var` along an axis is negligible (see the top comment).
template <class C, int N>
[[nodiscard]] bool negligible_variance(C var, C var_max, C coord_scale, C rank_tol) noexcept {
  if (!(var_max > C(0))) return true;
  if (var <= C(64) * C(N) * eps_v<C> * var_max) return true;
  return std::sqrt(std::max(var, C(0))) <= rank_tol * coord_scale;
}

/// Makes the largest-magnitude component of v positive (a deterministic sign for normals and
/// coefficient vectors, which least squares determines only up to sign).
template <class C, int N>
[[nodiscard]] Vec<C, N> canonical_sign(Vec<C, N> v) noexcept {
  int k = 0;
  for (int i = 1; i < N; ++i)
    if (std::abs(v[i]) > std::abs(v[k])) k = i;
  return v[k] < C(0) ? -v : v;
}

/// Smallest and largest eigenvalue of the leading K x K block of a covariance.
template <int K, class C, int N>
[[nodiscard]] std::pair<C, C> block_variance_range(const Mat<C, N, N>& cov) {
  if constexpr (K == 1) {
    return {cov(0, 0), cov(0, 0)};
  } else {
    Mat<C, K, K> b{};
    for (int r = 0; r < K; ++r)
      for (int c = 0; c < K; ++c) b(r, c) = cov(r, c);
    const SymmetricEigen<C, K> e = eigen_any(b);
    return {e.values[0], e.values[K - 1]};
  }
}

/// Least squares with vertical residuals: x_{N-1} ~ sum_{j<N-1} coef_j x_j + constant, solved
/// on centred columns by numeric/least_squares.hpp (QR with column pivoting) in the compute type.
template <class T, int N>
struct VerticalSolution {
  Status status = Status::empty_input;
  Vec<compute_t<T>, N - 1> coef{};
  compute_t<T> constant{};
  compute_t<T> rms{};
  Vec<compute_t<T>, N> mean{};  ///< of the points
};

template <class T, int N>
[[nodiscard]] VerticalSolution<T, N> vertical_fit(std::span<const Vec<T, N>> pts, T rank_tol) {
  using C = compute_t<T>;
  constexpr int K = N - 1;
  VerticalSolution<T, N> out;
  out.status = Status::ok;
  out.rms = std::numeric_limits<C>::quiet_NaN();
  out.status = check_points(pts, static_cast<std::size_t>(N));
  if (out.status != Status::ok) return out;
  const Moments<C, N> m = moments<C>(pts);
  C xscale = C(0);
  for (const Vec<T, N>& p : pts)
    for (int j = 0; j < K; ++j) xscale = std::max(xscale, std::abs(C(p[j])));
  const auto [vmin, vmax] = block_variance_range<K>(m.covariance);
  if (negligible_variance<C, K>(vmin, vmax, xscale * m.scale, C(rank_tol))) {
    out.status = Status::degenerate_input;
    return out;
  }
  const int n = static_cast<int>(pts.size());
  std::vector<C> a(pts.size() * static_cast<std::size_t>(K)), b(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec<C, N> d = m.centred(pts[i]);
    for (int j = 0; j < K; ++j)
      a[i * static_cast<std::size_t>(K) + static_cast<std::size_t>(j)] = d[j];
    b[i] = d[K];
  }
  const LeastSquares<C> ls = least_squares(a, n, K, b);
  if (ls.status != Status::ok) {
    out.status = Status::degenerate_input;
    return out;
  }
  C constant = m.mean[K];
  for (int j = 0; j < K; ++j) {
    out.coef[j] = ls.x[static_cast<std::size_t>(j)];
    constant -= out.coef[j] * m.mean[j];
  }
  out.constant = m.unscale(constant);
  out.mean = m.unscale(m.mean);
  out.rms = m.unscale(ls.residual_norm / std::sqrt(C(n)));
  return out;
}

}  // namespace detail
}  // namespace locus
