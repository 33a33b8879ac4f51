// SPDX-License-Identifier: BSL-1.0
#pragma once
// Least-squares solution of over-determined systems A x ~ b (row core.lstsq; book chapter 2,
// figure 2.9: the line y = m x + c closest, in the vertical squared distance, to a point set).
// Minimises ||A x - b||_2 for a row-major m x n matrix A (element (r, c) at a[r * n + c]) and
// b of length m, m >= n expected. Two methods:
//   * LstsqMethod::qr (default) - Householder QR with column pivoting (Businger-Golub; the
//     reflections of numeric/decompose.hpp's qr): backward stable, error ~ eps * cond(A), and
//     rank-revealing in practice;
//   * LstsqMethod::normal_equations - Cholesky of A^T A x = A^T b: cheaper (n^2 m / 2 instead of
//     n^2 m) but squares the condition number, so it loses twice as many digits; use it only
//     for well-conditioned A (e.g. a line fit through points that are not clustered).
// Rank. QR: column k (after pivoting) is dependent when |R_kk| <= rank_tolerance * |R_00|
// (default max(m, n) * eps). Normal equations: a Cholesky pivot d_k <= rank_tolerance *
// max_j (A^T A)_jj (default 16 max(m, n) eps, the rounding of forming A^T A; why:
// docs/notes/core.md). Rank-deficient A (rank < n, which includes m < n): status
// degenerate_input, `rank` reports the numerical rank and x is a basic solution with the
// dependent unknowns set to zero (it still minimises the residual, but is not the minimum-norm
// solution).
// residual_norm = ||b - A x||_2: from the tail of Q^T b for QR (accurate also when tiny), and
// evaluated directly for the normal equations.
// Degenerate input: m == 0 or n == 0 gives empty_input (x = n zeros, rank 0, residual ||b||);
// NaN/Inf in A or b gives non_finite_input (x zeros, rank 0, residual NaN). Arithmetic is in T.
// Allocates the result and one m x n working copy.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/numeric/decompose.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace locus {

enum class LstsqMethod : std::uint8_t {
  qr,                ///< Householder QR with column pivoting (robust default)
  normal_equations,  ///< Cholesky of A^T A (fast, squares the condition number)
};

/// Result of least_squares().
template <Real T>
struct LeastSquares {
  Status status =
      Status::empty_input;  ///< ok; degenerate_input (rank < n); empty_input; non_finite_input
  std::vector<T> x;         ///< n unknowns
  T residual_norm;          ///< ||b - A x||_2
  int rank;                 ///< numerical rank of A
};

namespace detail {

template <Real T>
inline void lstsq_qr(std::vector<T>& a, int m, int n, std::vector<T>& b, T tol,
                     LeastSquares<T>& out) {
  const std::size_t un = static_cast<std::size_t>(n);
  std::vector<int> perm(un);
  for (int j = 0; j < n; ++j) perm[static_cast<std::size_t>(j)] = j;
  auto at = [&](int r, int c) -> T& {
    return a[static_cast<std::size_t>(r) * un + static_cast<std::size_t>(c)];
  };
  const int kmax = m < n ? m : n;
  T r00 = T(0);
  int rank = 0;
  for (int k = 0; k < kmax; ++k) {
    // Column pivoting: bring the column with the largest remaining norm to position k. The
    // norms are recomputed (not downdated), which costs no more than the reflection itself
    // and avoids the cancellation of norm downdating.
    int best = k;
    T best_norm = T(-1);
    for (int c = k; c < n; ++c) {
      const T nc = scaled_norm(&at(k, c), m - k, n);
      if (nc > best_norm) best_norm = nc, best = c;
    }
    if (k == 0) r00 = best_norm;
    if (!(best_norm > tol * r00) || !(best_norm > T(0))) break;
    if (best != k) {
      for (int r = 0; r < m; ++r) std::swap(at(r, k), at(r, best));
      std::swap(perm[static_cast<std::size_t>(k)], perm[static_cast<std::size_t>(best)]);
    }
    const T tau = make_householder(&at(k, k), m - k, n, best_norm);
    for (int c = k + 1; c < n; ++c) apply_householder(&at(k, k), n, m - k, tau, &at(k, c), n);
    apply_householder(&at(k, k), n, m - k, tau, b.data() + k, 1);
    rank = k + 1;
  }
  // Back substitution on the leading rank x rank triangle; dependent unknowns are zero.
  std::vector<T> z(un, T(0));
  for (int i = rank - 1; i >= 0; --i) {
    T s = b[static_cast<std::size_t>(i)];
    for (int c = i + 1; c < rank; ++c) s -= at(i, c) * z[static_cast<std::size_t>(c)];
    z[static_cast<std::size_t>(i)] = s / at(i, i);
  }
  out.x.assign(un, T(0));
  for (int j = 0; j < n; ++j)
    out.x[static_cast<std::size_t>(perm[static_cast<std::size_t>(j)])] =
        z[static_cast<std::size_t>(j)];
  out.residual_norm = rank < m ? scaled_norm(b.data() + rank, m - rank, 1) : T(0);
  out.rank = rank;
}

template <Real T>
inline void lstsq_normal(const std::vector<T>& a, int m, int n, const std::vector<T>& b, T tol,
                         LeastSquares<T>& out) {
  const std::size_t un = static_cast<std::size_t>(n);
  auto A = [&](int r, int c) {
    return a[static_cast<std::size_t>(r) * un + static_cast<std::size_t>(c)];
  };
  // G = A^T A (lower triangle used), h = A^T b.
  std::vector<T> g(un * un, T(0)), h(un, T(0));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= i; ++j) {
      T s = T(0);
      for (int r = 0; r < m; ++r) s += A(r, i) * A(r, j);
      g[static_cast<std::size_t>(i) * un + static_cast<std::size_t>(j)] = s;
    }
    T s = T(0);
    for (int r = 0; r < m; ++r) s += A(r, i) * b[static_cast<std::size_t>(r)];
    h[static_cast<std::size_t>(i)] = s;
  }
  auto G = [&](int i, int j) -> T& {
    return g[static_cast<std::size_t>(i) * un + static_cast<std::size_t>(j)];
  };
  T gmax = T(0);
  for (int i = 0; i < n; ++i) gmax = std::fmax(gmax, G(i, i));
  const T threshold = tol * gmax;
  // Cholesky G = L L^T in place (lower triangle); a column whose pivot falls under the threshold
  // is dependent on the previous ones: drop it (zero row/column of L, unknown fixed at 0).
  std::vector<char> active(un, 0);
  int rank = 0;
  for (int k = 0; k < n; ++k) {
    T d = G(k, k);
    for (int p = 0; p < k; ++p) d -= G(k, p) * G(k, p);
    if (!(d > threshold) || !(gmax > T(0))) {
      for (int p = 0; p <= k; ++p) G(k, p) = T(0);
      for (int i = k + 1; i < n; ++i) G(i, k) = T(0);
      continue;
    }
    const T lkk = std::sqrt(d);
    G(k, k) = lkk;
    active[static_cast<std::size_t>(k)] = 1;
    ++rank;
    for (int i = k + 1; i < n; ++i) {
      T s = G(i, k);
      for (int p = 0; p < k; ++p) s -= G(i, p) * G(k, p);
      G(i, k) = s / lkk;
    }
  }
  // L y = h, then L^T x = y, over the active unknowns (inactive rows/columns of L are zero).
  std::vector<T> y(un, T(0));
  for (int i = 0; i < n; ++i) {
    if (!active[static_cast<std::size_t>(i)]) continue;
    T s = h[static_cast<std::size_t>(i)];
    for (int p = 0; p < i; ++p) s -= G(i, p) * y[static_cast<std::size_t>(p)];
    y[static_cast<std::size_t>(i)] = s / G(i, i);
  }
  out.x.assign(un, T(0));
  for (int i = n - 1; i >= 0; --i) {
    if (!active[static_cast<std::size_t>(i)]) continue;
    T s = y[static_cast<std::size_t>(i)];
    for (int p = i + 1; p < n; ++p) s -= G(p, i) * out.x[static_cast<std::size_t>(p)];
    out.x[static_cast<std::size_t>(i)] = s / G(i, i);
  }
  std::vector<T> res(static_cast<std::size_t>(m));
  for (int r = 0; r < m; ++r) {
    T s = b[static_cast<std::size_t>(r)];
    for (int c = 0; c < n; ++c) s -= A(r, c) * out.x[static_cast<std::size_t>(c)];
    res[static_cast<std::size_t>(r)] = s;
  }
  out.residual_norm = scaled_norm(res.data(), m, 1);
  out.rank = rank;
}

}  // namespace detail

/// Least-squares solution of the row-major m x n system a x ~ b (see the top comment).
/// rank_tolerance < 0 selects the default: max(m, n) * eps for QR, 16 max(m, n) * eps for the
/// normal equations.
template <Real T>
[[nodiscard]] inline LeastSquares<T> least_squares(std::span<const T> a, int m, int n,
                                                   std::span<const T> b,
                                                   LstsqMethod method = LstsqMethod::qr,
                                                   T rank_tolerance = T(-1)) {
  LOCUS_ASSERT(m >= 0 && n >= 0 &&
                   a.size() == static_cast<std::size_t>(m) * static_cast<std::size_t>(n) &&
                   b.size() == static_cast<std::size_t>(m),
               "least_squares: a must hold m * n entries and b m entries");
  const std::size_t un = static_cast<std::size_t>(n);
  LeastSquares<T> out{Status::ok, std::vector<T>(un, T(0)), T(0), 0};
  for (const T v : a)
    if (!is_finite(v)) out.status = Status::non_finite_input;
  for (const T v : b)
    if (!is_finite(v)) out.status = Status::non_finite_input;
  if (out.status == Status::non_finite_input) {
    out.residual_norm = std::numeric_limits<T>::quiet_NaN();
    return out;
  }
  if (m == 0 || n == 0) {
    out.status = Status::empty_input;
    out.residual_norm = detail::scaled_norm(b.data(), m, 1);
    return out;
  }
  if (rank_tolerance < T(0))
    rank_tolerance =
        T(method == LstsqMethod::normal_equations ? 16 : 1) * T(m > n ? m : n) * eps_v<T>;
  std::vector<T> aw(a.begin(), a.end()), bw(b.begin(), b.end());
  if (method == LstsqMethod::normal_equations)
    detail::lstsq_normal(aw, m, n, bw, rank_tolerance, out);
  else
    detail::lstsq_qr(aw, m, n, bw, rank_tolerance, out);
  if (out.rank < n) out.status = Status::degenerate_input;
  return out;
}
template <Real T>
[[nodiscard]] inline LeastSquares<T> least_squares(const std::vector<T>& a, int m, int n,
                                                   const std::vector<T>& b,
                                                   LstsqMethod method = LstsqMethod::qr,
                                                   T rank_tolerance = T(-1)) {
  return least_squares(std::span<const T>(a), m, n, std::span<const T>(b), method, rank_tolerance);
}

}  // namespace locus
