// SPDX-License-Identifier: BSL-1.0
#pragma once
// Matrix decompositions on run-time sized matrices (row num.decomp; book appendix A).
//
//   lu_factor / solve / determinant / inverse / rank on a row-major n x n std::span or vector
//                (element (r, c) at a[r * cols + c]; k right-hand sides are an n x k block):
//                partial pivoting, with core/linear_system.hpp's contract (LinearSolution,
//                rcond, singular); compiled once; results allocate (std::vector).
//   qr(A)        A = Q R by Householder reflections (m >= n); Q is m x m orthogonal, R m x n upper.
//                (numeric/least_squares.hpp solves with the same reflections, column-pivoted.)
//   cholesky(A)  A = L L^T for symmetric positive definite A; L lower triangular.
//   svd(A)       A = U diag(s) V^T by one-sided Jacobi (Hestenes); s descending, >= 0;
//                U m x k, V n x k with k = min(m, n) (the thin SVD).
//   polar(A)     A = Q S with Q orthogonal and S symmetric positive semidefinite (square A),
//                from the SVD: Q = U V^T, S = V diag(s) V^T. For det(A) > 0, Q is the rotation
//                nearest to A.
// Float input is computed in double (compute_t) and rounded at the end.
//
// Bad input: NaN/Inf entries give Status::non_finite_input (factors are not meaningful); a
// non-square matrix where a square one is needed, or a non-symmetric one for Cholesky, gives
// Status::invalid_input; Cholesky of a matrix that is not positive definite gives
// Status::degenerate_input. The SVD's Jacobi iteration has a sweep budget (Status::limit_exceeded
// past it). Cost: O(n^3) each; the SVD costs a few sweeps of O(m n^2).

#include <locus/core/linear_system.hpp>
#include <locus/core/status.hpp>
#include <locus/numeric/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <span>
#include <vector>

namespace locus {

template <Real T>
struct QR {
  Status status = Status::empty_input;
  MatX<T> q;  ///< m x m orthogonal
  MatX<T> r;  ///< m x n upper triangular
};

template <Real T>
struct Cholesky {
  Status status = Status::empty_input;
  MatX<T> l;  ///< lower triangular, A = L L^T
};

template <Real T>
struct SVD {
  Status status = Status::empty_input;
  MatX<T> u;         ///< m x k, orthonormal columns
  std::vector<T> s;  ///< k singular values, descending
  MatX<T> v;         ///< n x k, orthonormal columns
  int sweeps = 0;
};

template <Real T>
struct Polar {
  Status status = Status::empty_input;
  MatX<T> q;  ///< orthogonal
  MatX<T> s;  ///< symmetric positive semidefinite
};

namespace detail {
template <class C, class T>
MatX<C> to_compute(const MatX<T>& a) {
  MatX<C> c(a.rows, a.cols);
  for (std::size_t i = 0; i < a.data.size(); ++i) c.data[i] = C(a.data[i]);
  return c;
}
template <class T, class C>
MatX<T> from_compute(const MatX<C>& a) {
  MatX<T> t(a.rows, a.cols);
  for (std::size_t i = 0; i < a.data.size(); ++i) t.data[i] = T(a.data[i]);
  return t;
}

/// Euclidean norm of v[0], v[stride], ... (count entries), scaled against overflow/underflow.
template <Real T>
[[nodiscard]] inline T scaled_norm(const T* v, int count, int stride) noexcept {
  T mx = T(0);
  for (int i = 0; i < count; ++i) mx = std::fmax(mx, std::fabs(v[i * stride]));
  if (!(mx > T(0))) return T(0);
  T s = T(0);
  for (int i = 0; i < count; ++i) s += sqr(v[i * stride] / mx);
  return mx * std::sqrt(s);
}

// The Householder step of every QR in the library (qr() here, least_squares()): the reflector
// H = I - tau u u^T (u_0 = 1) with H x = beta e_0, beta = -sign(x_0) |x|, so that x_0 - beta
// never cancels. x = x[0], x[stride], ... (len entries) with norm = |x| > 0; x[0] becomes beta and
// x[i stride] (i >= 1) u_i. Returns tau.
template <Real T>
[[nodiscard]] inline T make_householder(T* x, int len, int stride, T norm) noexcept {
  const T xk = x[0];
  const T beta = xk < T(0) ? norm : -norm;
  const T tau = (beta - xk) / beta;
  const T inv = T(1) / (xk - beta);
  for (int i = 1; i < len; ++i) x[i * stride] *= inv;
  x[0] = beta;
  return tau;
}

/// y <- H y for the reflector stored by make_householder at u (stride ustride, u_0 = 1 implied);
/// y = y[0], y[ystride], ... (len entries). H is symmetric, so this also applies y^T H.
template <Real T>
inline void apply_householder(const T* u, int ustride, int len, T tau, T* y, int ystride) noexcept {
  T w = y[0];
  for (int i = 1; i < len; ++i) w += u[i * ustride] * y[i * ystride];
  w *= tau;
  y[0] -= w;
  for (int i = 1; i < len; ++i) y[i * ystride] -= w * u[i * ustride];
}
}  // namespace detail

/// Householder QR, A = Q R (any shape; Q is rows x rows).
template <Real T>
[[nodiscard]] QR<T> qr(const MatX<T>& a_in) {
  using C = compute_t<T>;
  QR<T> out;
  out.status = Status::ok;
  const int m = a_in.rows, n = a_in.cols;
  if (!is_finite(a_in)) {
    out.status = Status::non_finite_input;
    out.q = MatX<T>::identity(m);
    out.r = a_in;
    return out;
  }
  MatX<C> r = detail::to_compute<C>(a_in);
  MatX<C> q = MatX<C>::identity(m);
  for (int k = 0; k < std::min(m - 1, n); ++k) {
    const C norm = detail::scaled_norm(&r(k, k), m - k, n);
    if (norm == C(0)) continue;
    const C tau = detail::make_householder(&r(k, k), m - k, n, norm);
    for (int c = k + 1; c < n; ++c) detail::apply_householder(&r(k, k), n, m - k, tau, &r(k, c), n);
    for (int row = 0; row < m; ++row)  // Q <- Q H
      detail::apply_householder(&r(k, k), n, m - k, tau, &q(row, k), 1);
    for (int i = k + 1; i < m; ++i) r(i, k) = C(0);
  }
  out.q = detail::from_compute<T>(q);
  out.r = detail::from_compute<T>(r);
  return out;
}

/// Cholesky factorisation A = L L^T of a symmetric positive definite matrix.
template <Real T>
[[nodiscard]] Cholesky<T> cholesky(const MatX<T>& a_in, T symmetry_tolerance = T(64) * eps_v<T>) {
  using C = compute_t<T>;
  Cholesky<T> out;
  out.status = Status::ok;
  const int n = a_in.rows;
  out.l = MatX<T>(n, n);
  if (a_in.rows != a_in.cols) {
    out.status = Status::invalid_input;
    return out;
  }
  if (!is_finite(a_in)) {
    out.status = Status::non_finite_input;
    return out;
  }
  C big = C(0);
  for (T x : a_in.data) big = std::max(big, std::abs(C(x)));
  for (int r = 0; r < n; ++r)
    for (int c = r + 1; c < n; ++c)
      if (std::abs(C(a_in(r, c)) - C(a_in(c, r))) > C(symmetry_tolerance) * big) {
        out.status = Status::invalid_input;
        return out;
      }
  MatX<C> l(n, n);
  for (int j = 0; j < n; ++j) {
    C d = C(a_in(j, j));
    for (int k = 0; k < j; ++k) d -= l(j, k) * l(j, k);
    if (!(d > C(0))) {
      out.status = Status::degenerate_input;  // not positive definite
      out.l = detail::from_compute<T>(l);
      return out;
    }
    l(j, j) = std::sqrt(d);
    for (int i = j + 1; i < n; ++i) {
      C s = C(a_in(i, j));
      for (int k = 0; k < j; ++k) s -= l(i, k) * l(j, k);
      l(i, j) = s / l(j, j);
    }
  }
  out.l = detail::from_compute<T>(l);
  return out;
}

/// Thin singular value decomposition by one-sided Jacobi rotations.
template <Real T>
[[nodiscard]] SVD<T> svd(const MatX<T>& a_in, int max_sweeps = 64) {
  using C = compute_t<T>;
  SVD<T> out;
  out.status = Status::ok;
  if (a_in.rows < a_in.cols) {  // A^T = V S U^T: factor the tall transpose
    SVD<T> t = svd(transpose(a_in), max_sweeps);
    std::swap(t.u, t.v);
    return t;
  }
  const int m = a_in.rows, n = a_in.cols;
  if (!is_finite(a_in)) {
    out.status = Status::non_finite_input;
    out.u = MatX<T>(m, n);
    out.v = MatX<T>::identity(n);
    out.s.assign(static_cast<std::size_t>(n), std::numeric_limits<T>::quiet_NaN());
    return out;
  }
  C scale = C(0);
  for (T x : a_in.data) scale = std::max(scale, std::abs(C(x)));
  MatX<C> u = detail::to_compute<C>(a_in);
  if (scale > C(0))
    for (C& x : u.data) x /= scale;
  MatX<C> v = MatX<C>::identity(n);
  // Rotate column pairs until every pair is orthogonal to working precision: the computed inner
  // product of two exactly orthogonal columns is only known to ~sqrt(m) eps |u_p||u_q| (dgesvj).
  const C tol = std::sqrt(C(m)) * eps_v<C>;
  // A column whose norm is below eps |A| is numerically zero; rotating it against another column
  // only stirs rounding noise and can cycle forever (rank-deficient input).
  C total = C(0);
  for (C x : u.data) total += x * x;
  const C negligible = sqr(eps_v<C>) * total;
  bool converged = n < 2;
  int sweep = 0;
  for (; sweep < max_sweeps && !converged; ++sweep) {
    converged = true;
    for (int p = 0; p < n - 1; ++p)
      for (int q = p + 1; q < n; ++q) {
        C alpha = C(0), beta = C(0), gamma = C(0);
        for (int i = 0; i < m; ++i) {
          alpha += u(i, p) * u(i, p);
          beta += u(i, q) * u(i, q);
          gamma += u(i, p) * u(i, q);
        }
        if (gamma == C(0) || std::abs(gamma) <= tol * std::sqrt(alpha * beta)) continue;
        if (alpha <= negligible || beta <= negligible) continue;
        converged = false;
        const C zeta = (beta - alpha) / (C(2) * gamma);
        const C t =
            (zeta >= C(0) ? C(1) : C(-1)) / (std::abs(zeta) + std::sqrt(C(1) + zeta * zeta));
        const C c = C(1) / std::sqrt(C(1) + t * t), s = c * t;
        for (int i = 0; i < m; ++i) {
          const C up = u(i, p), uq = u(i, q);
          u(i, p) = c * up - s * uq;
          u(i, q) = s * up + c * uq;
        }
        for (int i = 0; i < n; ++i) {
          const C vp = v(i, p), vq = v(i, q);
          v(i, p) = c * vp - s * vq;
          v(i, q) = s * vp + c * vq;
        }
      }
  }
  out.sweeps = sweep;
  if (!converged) out.status = Status::limit_exceeded;
  // Singular values are the column norms; U's columns are the normalised columns.
  std::vector<C> s(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    C big = C(0), sum = C(0);
    for (int i = 0; i < m; ++i) big = std::max(big, std::abs(u(i, j)));
    if (big > C(0))
      for (int i = 0; i < m; ++i) sum += sqr(u(i, j) / big);
    s[std::size_t(j)] = big * std::sqrt(sum);
  }
  std::vector<int> idx(static_cast<std::size_t>(n));
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(),
                   [&](int i, int j) { return s[std::size_t(i)] > s[std::size_t(j)]; });
  out.u = MatX<T>(m, n);
  out.v = MatX<T>(n, n);
  out.s.resize(static_cast<std::size_t>(n));
  MatX<C> uc(m, n);
  // Columns at or below the rotation skip threshold were never orthogonalised: their direction is
  // rounding noise. Their U columns come from completing the others to an orthonormal set by
  // Gram-Schmidt against coordinate vectors (still an SVD to within eps |A|).
  const C zero_level = std::sqrt(negligible);
  std::vector<bool> complete(static_cast<std::size_t>(n), false);
  for (int k = 0; k < n; ++k) {
    const int j = idx[std::size_t(k)];
    const C sj = s[std::size_t(j)];
    out.s[std::size_t(k)] = T(sj * scale);
    complete[std::size_t(k)] = !(sj > zero_level);
    for (int i = 0; i < m; ++i) uc(i, k) = complete[std::size_t(k)] ? C(0) : u(i, j) / sj;
    for (int i = 0; i < n; ++i) out.v(i, k) = T(v(i, j));
  }
  for (int k = 0; k < n; ++k) {
    if (!complete[std::size_t(k)]) continue;
    // Of the coordinate vectors, the one with the largest residual after projecting out the
    // other columns: its residual has length >= 1/sqrt(m), so normalising it is well conditioned.
    std::vector<C> best;
    C best_len = C(-1);
    for (int e = 0; e < m; ++e) {
      std::vector<C> w(static_cast<std::size_t>(m), C(0));
      w[std::size_t(e)] = C(1);
      for (int pass = 0; pass < 2; ++pass)
        for (int j = 0; j < n; ++j) {
          if (j == k || (complete[std::size_t(j)] && j > k)) continue;  // skip not-yet-built ones
          C d = C(0);
          for (int i = 0; i < m; ++i) d += uc(i, j) * w[std::size_t(i)];
          for (int i = 0; i < m; ++i) w[std::size_t(i)] -= d * uc(i, j);
        }
      C len = C(0);
      for (C x : w) len += x * x;
      len = std::sqrt(len);
      if (len > best_len) {
        best_len = len;
        best = std::move(w);
      }
    }
    for (int i = 0; i < m; ++i) uc(i, k) = best[std::size_t(i)] / best_len;
  }
  out.u = detail::from_compute<T>(uc);
  return out;
}

/// Polar decomposition A = Q S of a square matrix (from the SVD).
template <Real T>
[[nodiscard]] Polar<T> polar(const MatX<T>& a) {
  Polar<T> out;
  out.status = Status::ok;
  if (a.rows != a.cols) {
    out.status = Status::invalid_input;
    return out;
  }
  const SVD<T> d = svd(a);
  out.status = d.status;
  const int n = a.rows;
  out.q = MatX<T>(n, n);
  out.s = MatX<T>(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      compute_t<T> q = 0, s = 0;
      for (int k = 0; k < n; ++k) {
        q += compute_t<T>(d.u(r, k)) * compute_t<T>(d.v(c, k));
        s += compute_t<T>(d.v(r, k)) * compute_t<T>(d.s[std::size_t(k)]) * compute_t<T>(d.v(c, k));
      }
      out.q(r, c) = T(q);
      out.s(r, c) = T(s);
    }
  return out;
}

// ---- LU and rank of run-time n x n systems (compiled in src/numeric/lu.cpp) ---------------

/// A partial-pivoting factorisation of a run-time n x n matrix; layout as in Lu, row-major.
template <Real T>
struct LuDynamic {
  Status status = Status::empty_input;
  int n;
  std::vector<T> lu;
  std::vector<int> perm;
  T determinant;
  T rcond;
  bool singular;
  bool near_singular;
};

template <Real T>
inline constexpr T use_default_tolerance = T(-1);
template <Real T>
[[nodiscard]] LuDynamic<T> lu_factor(std::span<const T> a, int n,
                                     T rcond_tolerance = use_default_tolerance<T>);
template <Real T>
[[nodiscard]] inline LuDynamic<T> lu_factor(const std::vector<T>& a, int n,
                                            T rcond_tolerance = use_default_tolerance<T>) {
  return lu_factor(std::span<const T>(a), n, rcond_tolerance);
}
template <Real T>
[[nodiscard]] std::vector<T> solve(const LuDynamic<T>& f, std::span<const T> b, int nrhs = 1);
template <Real T>
[[nodiscard]] inline std::vector<T> solve(const LuDynamic<T>& f, const std::vector<T>& b,
                                          int nrhs = 1) {
  return solve(f, std::span<const T>(b), nrhs);
}
template <Real T>
[[nodiscard]] LinearSolution<T, std::vector<T>> solve(std::span<const T> a, int n,
                                                      std::span<const T> b, int nrhs = 1,
                                                      T rcond_tolerance = use_default_tolerance<T>);
template <Real T>
[[nodiscard]] inline LinearSolution<T, std::vector<T>> solve(
    const std::vector<T>& a, int n, const std::vector<T>& b, int nrhs = 1,
    T rcond_tolerance = use_default_tolerance<T>) {
  return solve(std::span<const T>(a), n, std::span<const T>(b), nrhs, rcond_tolerance);
}
template <Real T>
[[nodiscard]] T determinant(std::span<const T> a, int n);
template <Real T>
[[nodiscard]] inline T determinant(const std::vector<T>& a, int n) {
  return determinant(std::span<const T>(a), n);
}
template <Real T>
[[nodiscard]] std::optional<std::vector<T>> inverse(std::span<const T> a, int n);
template <Real T>
[[nodiscard]] inline std::optional<std::vector<T>> inverse(const std::vector<T>& a, int n) {
  return inverse(std::span<const T>(a), n);
}
template <Real T>
[[nodiscard]] int rank(std::span<const T> a, int rows, int cols,
                       T rank_tolerance = use_default_tolerance<T>);
template <Real T>
[[nodiscard]] inline int rank(const std::vector<T>& a, int rows, int cols,
                              T rank_tolerance = use_default_tolerance<T>) {
  return rank(std::span<const T>(a), rows, cols, rank_tolerance);
}

}  // namespace locus
