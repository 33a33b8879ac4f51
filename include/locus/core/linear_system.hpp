// SPDX-License-Identifier: BSL-1.0
#pragma once
// Square linear systems A x = b (row core.linsys; book chapter 2, figures 2.2 and 2.3). The
// condition-number reasoning: docs/notes/core.md.
//
//   * solve_cramer(Mat2/Mat3, Vec) - closed form by Cramer's rule (det and adjugate of mat.hpp);
//   * lu_factor / solve / determinant / inverse - Gaussian elimination with partial (row)
//     pivoting, PA = LU, for compile-time N (Mat<T, N, N>, Vec<T, N>, Mat<T, N, K> for several
//     right-hand sides); run-time n x n systems are numeric/decompose.hpp's (same contract);
//   * rank - Gaussian elimination with complete pivoting (rows and columns), any R x C.
//
// `singular`: an exactly zero pivot (det == 0) or a non-finite solution; x is then zero and the
// status degenerate_input (figure 2.3's "none" and "infinitely many" alike; rank() of A and
// [A | b] tells them apart). `near_singular` also flags rcond = 1 / (||A|| ||A^-1||) <=
// rcond_tolerance (default n * eps: where the error bound n * eps * cond reaches 1, so x may
// have no correct digits); rcond is scale-invariant. Cramer uses the infinity norm, elimination
// the 1-norm with Hager's estimate (at worst a small-factor underestimate).
// rank() counts pivots larger than rank_tolerance * max|a_ij| (default max(R, C) * eps).
//
// Degenerate input: a NaN or infinite entry in A or b gives status non_finite_input, singular,
// zero x, determinant NaN, rcond 0, and rank() returns -1. An empty system (n == 0) is ok with
// an empty solution and determinant 1. Queries never throw and never allocate. Arithmetic is
// in T (no promotion of float).
// Cost: Cramer 2x2/3x3 O(1); factorisation n^3 / 3 multiply-adds; each extra right-hand side
// n^2; condition estimate about 4 to 10 solves (n^2 each); inverse n^3; rank R C min(R, C).

#include <locus/config.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

namespace locus {

/// The default near-singularity threshold on rcond for an n x n system: n * eps.
template <Real T>
[[nodiscard]] constexpr T default_rcond_tolerance(int n) noexcept {
  return T(n < 1 ? 1 : n) * eps_v<T>;
}
/// The default rank threshold for an R x C matrix: max(R, C) * eps (relative to max|a_ij|).
template <Real T>
[[nodiscard]] constexpr T default_rank_tolerance(int rows, int cols) noexcept {
  return T(rows > cols ? (rows < 1 ? 1 : rows) : (cols < 1 ? 1 : cols)) * eps_v<T>;
}

/// Result of a linear solve. X is Vec<T, N>, Mat<T, N, K> or std::vector<T>.
template <class T, class X>
struct LinearSolution {
  Status status = Status::empty_input;  ///< ok, degenerate_input (singular), non_finite_input
  X x;                                  ///< the solution; zero when singular
  T determinant;       ///< det(A) (0 when exactly singular, NaN for non-finite input)
  T rcond;             ///< reciprocal condition number estimate in [0, 1]
  bool singular;       ///< det == 0, or the solution would not be finite
  bool near_singular;  ///< singular or rcond <= rcond_tolerance
};

/// A partial-pivoting factorisation P A = L U of a fixed-size matrix. `lu` holds L strictly
/// below the diagonal (unit diagonal implied) and U on and above it; row i of P A is row
/// perm[i] of A.
template <class T, int N>
struct Lu {
  Status status =
      Status::empty_input;  ///< ok, degenerate_input (exactly singular), non_finite_input
  Mat<T, N, N> lu;
  int perm[N];
  T determinant;
  T rcond;
  bool singular;
  bool near_singular;
};

namespace detail {

template <Real T>
[[nodiscard]] inline bool all_finite(const T* a, std::size_t count) noexcept {
  for (std::size_t i = 0; i < count; ++i)
    if (!is_finite(a[i])) return false;
  return true;
}

/// In-place P A = L U with partial pivoting on the row-major n x n array a. Returns the number
/// of columns eliminated: n on success, k < n when column k had no nonzero pivot (then the
/// factorisation stops and the matrix is exactly singular). sign receives det(P).
template <Real T>
inline int lu_inplace(T* a, int n, int* perm, int& sign) noexcept {
  sign = 1;
  for (int i = 0; i < n; ++i) perm[i] = i;
  for (int k = 0; k < n; ++k) {
    int p = k;
    T best = std::fabs(a[k * n + k]);
    for (int r = k + 1; r < n; ++r) {
      const T v = std::fabs(a[r * n + k]);
      if (v > best) best = v, p = r;
    }
    if (!(best > T(0))) return k;
    if (p != k) {
      for (int c = 0; c < n; ++c) std::swap(a[k * n + c], a[p * n + c]);
      std::swap(perm[k], perm[p]);
      sign = -sign;
    }
    const T piv = a[k * n + k];
    const T* ak = a + k * n;
    for (int r = k + 1; r < n; ++r) {
      T* ar = a + r * n;
      const T l = ar[k] / piv;
      ar[k] = l;
      if (l == T(0)) continue;
      for (int c = k + 1; c < n; ++c) ar[c] -= l * ak[c];
    }
  }
  return n;
}

/// x = A^-1 b from the factors (b and x must not overlap).
template <Real T>
inline void lu_solve(const T* lu, const int* perm, int n, const T* b, T* x) noexcept {
  for (int i = 0; i < n; ++i) {
    T s = b[perm[i]];
    for (int k = 0; k < i; ++k) s -= lu[i * n + k] * x[k];
    x[i] = s;
  }
  for (int i = n - 1; i >= 0; --i) {
    T s = x[i];
    for (int k = i + 1; k < n; ++k) s -= lu[i * n + k] * x[k];
    x[i] = s / lu[i * n + i];
  }
}

/// z = A^-T c from the factors: A^T = U^T L^T P, so solve U^T w = c, L^T v = w, z = P^T v.
/// w is scratch of size n; c, w and z must not overlap.
template <Real T>
inline void lu_solve_transposed(const T* lu, const int* perm, int n, const T* c, T* w,
                                T* z) noexcept {
  for (int i = 0; i < n; ++i) {
    T s = c[i];
    for (int k = 0; k < i; ++k) s -= lu[k * n + i] * w[k];
    w[i] = s / lu[i * n + i];
  }
  for (int i = n - 1; i >= 0; --i) {
    T s = w[i];
    for (int k = i + 1; k < n; ++k) s -= lu[k * n + i] * w[k];
    w[i] = s;
  }
  for (int i = 0; i < n; ++i) z[perm[i]] = w[i];
}

/// Maximum absolute column sum (the matrix 1-norm) of a row-major n x n array.
template <Real T>
[[nodiscard]] inline T norm1(const T* a, int n) noexcept {
  T best = T(0);
  for (int c = 0; c < n; ++c) {
    T s = T(0);
    for (int r = 0; r < n; ++r) s += std::fabs(a[r * n + c]);
    if (s > best) best = s;
  }
  return best;
}

/// Hager's estimate of ||A^-1||_1 (a lower bound, usually exact within a factor 3) with
/// Higham's extra test vector. work holds 5 n scalars.
template <Real T>
[[nodiscard]] inline T inverse_norm1_estimate(const T* lu, const int* perm, int n,
                                              T* work) noexcept {
  T* x = work;
  T* y = work + n;
  T* xi = work + 2 * n;
  T* z = work + 3 * n;
  T* w = work + 4 * n;
  for (int i = 0; i < n; ++i) x[i] = T(1) / T(n);
  T est = T(0);
  for (int iter = 0; iter < 5; ++iter) {
    lu_solve(lu, perm, n, x, y);
    T ny = T(0);
    for (int i = 0; i < n; ++i) ny += std::fabs(y[i]);
    if (iter > 0 && !(ny > est)) break;  // no progress: the previous vertex was the best
    est = ny;
    for (int i = 0; i < n; ++i) xi[i] = y[i] < T(0) ? T(-1) : T(1);
    lu_solve_transposed(lu, perm, n, xi, w, z);
    int j = 0;
    T zmax = std::fabs(z[0]), ztx = z[0] * x[0];
    for (int i = 1; i < n; ++i) {
      ztx += z[i] * x[i];
      if (std::fabs(z[i]) > zmax) zmax = std::fabs(z[i]), j = i;
    }
    if (!(zmax > ztx)) break;  // local maximum of ||A^-1 x||_1 over the unit 1-ball
    for (int i = 0; i < n; ++i) x[i] = T(0);
    x[j] = T(1);
  }
  // Higham's alternating vector catches matrices where the gradient walk stalls early.
  for (int i = 0; i < n; ++i)
    x[i] = (i % 2 == 0 ? T(1) : T(-1)) * (T(1) + (n > 1 ? T(i) / T(n - 1) : T(0)));
  lu_solve(lu, perm, n, x, y);
  T alt = T(0);
  for (int i = 0; i < n; ++i) alt += std::fabs(y[i]);
  alt = T(2) * alt / (T(3) * T(n));
  return alt > est ? alt : est;
}

/// Shared factorisation driver: factors `lu` (holding A on entry) and fills the summary.
template <Real T>
inline void factor_summary(T* lu, int n, int* perm, T* work, T rcond_tolerance, Status& status,
                           T& det, T& rcond, bool& singular, bool& near_singular) noexcept {
  const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  if (!all_finite(lu, count)) {
    for (int i = 0; i < n; ++i) perm[i] = i;
    status = Status::non_finite_input;
    det = std::numeric_limits<T>::quiet_NaN();
    rcond = T(0);
    singular = near_singular = true;
    return;
  }
  const T anorm = norm1(lu, n);
  int sign = 1;
  const int done = lu_inplace(lu, n, perm, sign);
  if (done < n) {
    status = Status::degenerate_input;
    det = T(0);
    rcond = T(0);
    singular = near_singular = true;
    return;
  }
  det = T(sign);
  for (int i = 0; i < n; ++i) det *= lu[i * n + i];
  const T inv_norm = n > 0 ? inverse_norm1_estimate(lu, perm, n, work) : T(1);
  rcond = n > 0 ? T(1) / (anorm * inv_norm) : T(1);
  if (!is_finite(rcond)) rcond = T(0);
  if (rcond > T(1)) rcond = T(1);  // rounding in the estimate; the true value is <= 1
  status = Status::ok;
  singular = false;
  near_singular = !(rcond > rcond_tolerance);
}

/// Complete-pivoting elimination rank of a row-major rows x cols array (destroyed).
template <Real T>
[[nodiscard]] inline int rank_inplace(T* a, int rows, int cols, T tolerance) noexcept {
  T scale = T(0);
  for (int i = 0; i < rows * cols; ++i) {
    if (!is_finite(a[i])) return -1;
    scale = std::fmax(scale, std::fabs(a[i]));
  }
  const T threshold = tolerance * scale;
  const int kmax = rows < cols ? rows : cols;
  for (int k = 0; k < kmax; ++k) {
    int pr = k, pc = k;
    T best = T(0);
    for (int r = k; r < rows; ++r)
      for (int c = k; c < cols; ++c)
        if (std::fabs(a[r * cols + c]) > best) best = std::fabs(a[r * cols + c]), pr = r, pc = c;
    if (!(best > threshold)) return k;
    if (pr != k)
      for (int c = 0; c < cols; ++c) std::swap(a[k * cols + c], a[pr * cols + c]);
    if (pc != k)
      for (int r = 0; r < rows; ++r) std::swap(a[r * cols + k], a[r * cols + pc]);
    const T piv = a[k * cols + k];
    for (int r = k + 1; r < rows; ++r) {
      const T l = a[r * cols + k] / piv;
      a[r * cols + k] = T(0);
      for (int c = k + 1; c < cols; ++c) a[r * cols + c] -= l * a[k * cols + c];
    }
  }
  return kmax;
}

}  // namespace detail

// ---- closed form: Cramer's rule -----------------------------------------------------------

namespace detail {
template <class T, int N>
[[nodiscard]] inline LinearSolution<T, Vec<T, N>> cramer(const Mat<T, N, N>& a, const Vec<T, N>& b,
                                                         T rcond_tolerance) noexcept {
  const T nan = std::numeric_limits<T>::quiet_NaN();
  if (!is_finite(a) || !is_finite(b))
    return {Status::non_finite_input, Vec<T, N>{}, nan, T(0), true, true};
  const T det = determinant(a);
  if (det == T(0)) return {Status::degenerate_input, Vec<T, N>{}, T(0), T(0), true, true};
  // x_i = det(A with column i replaced by b) / det = (adj(A) b)_i / det.
  const Mat<T, N, N> adj = adjugate(a);
  const Vec<T, N> x = (adj * b) / det;
  if (!is_finite(x)) return {Status::degenerate_input, Vec<T, N>{}, det, T(0), true, true};
  // Infinity-norm condition: ||A^-1|| = ||adj|| / |det| exactly (up to rounding).
  T na = T(0), nadj = T(0);
  for (int r = 0; r < N; ++r) {
    T sa = T(0), sadj = T(0);
    for (int c = 0; c < N; ++c) sa += std::fabs(a.a[r][c]), sadj += std::fabs(adj.a[r][c]);
    na = std::fmax(na, sa);
    nadj = std::fmax(nadj, sadj);
  }
  // |det| / (||A|| ||adj||), divided in two steps so that neither product overflows.
  T rcond = (std::fabs(det) / na) / nadj;
  if (!is_finite(rcond)) rcond = T(0);
  if (rcond > T(1)) rcond = T(1);
  return {Status::ok, x, det, rcond, false, !(rcond > rcond_tolerance)};
}
}  // namespace detail

/// Solves the 2x2 system a x = b by Cramer's rule. See the top comment for singular /
/// near_singular (rcond in the infinity norm, threshold rcond_tolerance, default 2 eps).
template <Real T>
[[nodiscard]] inline LinearSolution<T, Vec2<T>> solve_cramer(
    const Mat2<T>& a, const Vec2<T>& b,
    T rcond_tolerance = default_rcond_tolerance<T>(2)) noexcept {
  return detail::cramer(a, b, rcond_tolerance);
}
/// Solves the 3x3 system a x = b by Cramer's rule (default rcond_tolerance 3 eps).
template <Real T>
[[nodiscard]] inline LinearSolution<T, Vec3<T>> solve_cramer(
    const Mat3<T>& a, const Vec3<T>& b,
    T rcond_tolerance = default_rcond_tolerance<T>(3)) noexcept {
  return detail::cramer(a, b, rcond_tolerance);
}

// ---- fixed size: Gaussian elimination with partial pivoting -------------------------------

/// Factors P a = L U with partial pivoting and estimates the condition number.
template <class T, int N>
[[nodiscard]] inline Lu<T, N> lu_factor(
    const Mat<T, N, N>& a, T rcond_tolerance = default_rcond_tolerance<T>(N)) noexcept {
  Lu<T, N> f{};
  // Work on a flat copy: the elimination indexes rows as a[r * N + c], which must stay inside
  // one array object.
  T flat[N * N];
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) flat[r * N + c] = a.a[r][c];
  T work[5 * N];
  detail::factor_summary(flat, N, f.perm, work, rcond_tolerance, f.status, f.determinant, f.rcond,
                         f.singular, f.near_singular);
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) f.lu.a[r][c] = flat[r * N + c];
  return f;
}

/// Solves with a factorisation; the zero vector when the factorisation is singular.
template <class T, int N>
[[nodiscard]] inline Vec<T, N> solve(const Lu<T, N>& f, const Vec<T, N>& b) noexcept {
  if (f.singular) return Vec<T, N>{};
  Vec<T, N> x{};
  T lu[N * N];
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) lu[r * N + c] = f.lu.a[r][c];
  T bb[N];
  for (int i = 0; i < N; ++i) bb[i] = b[i];
  T xx[N];
  detail::lu_solve(lu, f.perm, N, bb, xx);
  for (int i = 0; i < N; ++i) x[i] = xx[i];
  return x;
}

/// Solves a x = b by Gaussian elimination with partial pivoting.
template <class T, int N>
[[nodiscard]] inline LinearSolution<T, Vec<T, N>> solve(
    const Mat<T, N, N>& a, const Vec<T, N>& b,
    T rcond_tolerance = default_rcond_tolerance<T>(N)) noexcept {
  const Lu<T, N> f = lu_factor(a, rcond_tolerance);
  if (f.status == Status::ok && !is_finite(b))
    return {Status::non_finite_input, Vec<T, N>{}, f.determinant, f.rcond, true, true};
  LinearSolution<T, Vec<T, N>> s{f.status, solve(f, b), f.determinant,
                                 f.rcond,  f.singular,  f.near_singular};
  if (!s.singular && !is_finite(s.x)) {
    s.status = Status::degenerate_input;
    s.x = Vec<T, N>{};
    s.singular = s.near_singular = true;
  }
  return s;
}

/// Solves a X = B for K right-hand sides (the columns of B) with one factorisation.
/// solve(a, Mat<T, N, N>::identity()) is the pivoting inverse.
template <class T, int N, int K>
[[nodiscard]] inline LinearSolution<T, Mat<T, N, K>> solve(
    const Mat<T, N, N>& a, const Mat<T, N, K>& b,
    T rcond_tolerance = default_rcond_tolerance<T>(N)) noexcept {
  const Lu<T, N> f = lu_factor(a, rcond_tolerance);
  if (f.status == Status::ok && !is_finite(b))
    return {Status::non_finite_input, Mat<T, N, K>{}, f.determinant, f.rcond, true, true};
  LinearSolution<T, Mat<T, N, K>> s{f.status, Mat<T, N, K>{}, f.determinant,
                                    f.rcond,  f.singular,     f.near_singular};
  if (f.singular) return s;
  for (int k = 0; k < K; ++k) set_col(s.x, k, solve(f, col(b, k)));
  if (!is_finite(s.x)) {
    s.status = Status::degenerate_input;
    s.x = Mat<T, N, K>{};
    s.singular = s.near_singular = true;
  }
  return s;
}

/// Determinant by elimination for the sizes mat.hpp has no closed form for (1 and > 4).
template <class T, int N>
requires(N == 1 || N > 4) [[nodiscard]] inline T determinant(const Mat<T, N, N>& a) noexcept {
  return lu_factor(a).determinant;
}

/// Inverse by elimination for sizes 1 and > 4 (mat.hpp has 2..4): std::nullopt when a is
/// singular, not finite, or the inverse overflows. Same contract as mat.hpp's inverse().
template <class T, int N>
requires(N == 1 || N > 4)
    [[nodiscard]] inline std::optional<Mat<T, N, N>> inverse(const Mat<T, N, N>& a) noexcept {
  const auto s = solve(a, Mat<T, N, N>::identity());
  if (s.singular) return std::nullopt;
  return s.x;
}

/// Numerical rank by complete pivoting: pivots <= rank_tolerance * max|a_ij| count as zero.
/// -1 for non-finite input.
template <class T, int R, int C>
[[nodiscard]] inline int rank(const Mat<T, R, C>& a,
                              T rank_tolerance = default_rank_tolerance<T>(R, C)) noexcept {
  T w[R * C];
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) w[r * C + c] = a.a[r][c];
  return detail::rank_inplace(w, R, C, rank_tolerance);
}

}  // namespace locus
