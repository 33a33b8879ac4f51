// SPDX-License-Identifier: BSL-1.0
// Run-time n x n linear systems by Gaussian elimination with partial pivoting, determinant,
// inverse and complete-pivoting rank (numeric/decompose.hpp; row core.linsys), compiled once for
// float and double on the elimination kernels of core/linear_system.hpp.

#include <locus/numeric/decompose.hpp>

#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace locus {

template <Real T>
LuDynamic<T> lu_factor(std::span<const T> a, int n, T rcond_tolerance) {
  LOCUS_ASSERT(n >= 0 && a.size() == static_cast<std::size_t>(n) * static_cast<std::size_t>(n),
               "lu_factor: a must hold n * n entries");
  if (rcond_tolerance < T(0)) rcond_tolerance = default_rcond_tolerance<T>(n);
  LuDynamic<T> f{Status::ok,
                 n,
                 std::vector<T>(a.begin(), a.end()),
                 std::vector<int>(static_cast<std::size_t>(n)),
                 T(1),
                 T(1),
                 false,
                 false};
  std::vector<T> work(5 * static_cast<std::size_t>(n));
  detail::factor_summary(f.lu.data(), n, f.perm.data(), work.data(), rcond_tolerance, f.status,
                         f.determinant, f.rcond, f.singular, f.near_singular);
  return f;
}

template <Real T>
std::vector<T> solve(const LuDynamic<T>& f, std::span<const T> b, int nrhs) {
  const int n = f.n;
  LOCUS_ASSERT(
      nrhs >= 0 && b.size() == static_cast<std::size_t>(n) * static_cast<std::size_t>(nrhs),
      "solve: b must hold n * nrhs entries");
  std::vector<T> x(static_cast<std::size_t>(n) * static_cast<std::size_t>(nrhs), T(0));
  if (f.singular) return x;
  std::vector<T> bc(static_cast<std::size_t>(n)), xc(static_cast<std::size_t>(n));
  for (int k = 0; k < nrhs; ++k) {
    for (int i = 0; i < n; ++i)
      bc[static_cast<std::size_t>(i)] = b[static_cast<std::size_t>(i * nrhs + k)];
    detail::lu_solve(f.lu.data(), f.perm.data(), n, bc.data(), xc.data());
    for (int i = 0; i < n; ++i)
      x[static_cast<std::size_t>(i * nrhs + k)] = xc[static_cast<std::size_t>(i)];
  }
  return x;
}

template <Real T>
LinearSolution<T, std::vector<T>> solve(std::span<const T> a, int n, std::span<const T> b, int nrhs,
                                        T rcond_tolerance) {
  LOCUS_ASSERT(
      nrhs >= 0 && b.size() == static_cast<std::size_t>(n) * static_cast<std::size_t>(nrhs),
      "solve: b must hold n * nrhs entries");
  const LuDynamic<T> f = lu_factor(a, n, rcond_tolerance);
  LinearSolution<T, std::vector<T>> s{f.status, {},         f.determinant,
                                      f.rcond,  f.singular, f.near_singular};
  if (f.status == Status::ok && !detail::all_finite(b.data(), b.size())) {
    s.status = Status::non_finite_input;
    s.singular = s.near_singular = true;
  }
  if (s.singular) {
    s.x.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(nrhs), T(0));
    return s;
  }
  s.x = solve(f, b, nrhs);
  if (!detail::all_finite(s.x.data(), s.x.size())) {
    s.status = Status::degenerate_input;
    s.x.assign(s.x.size(), T(0));
    s.singular = s.near_singular = true;
  }
  return s;
}

template <Real T>
T determinant(std::span<const T> a, int n) {
  return lu_factor(a, n).determinant;
}

template <Real T>
std::optional<std::vector<T>> inverse(std::span<const T> a, int n) {
  std::vector<T> id(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), T(0));
  for (int i = 0; i < n; ++i) id[static_cast<std::size_t>(i * n + i)] = T(1);
  auto s = solve(a, n, std::span<const T>(id), n);
  if (s.singular) return std::nullopt;
  return std::move(s.x);
}

template <Real T>
int rank(std::span<const T> a, int rows, int cols, T rank_tolerance) {
  LOCUS_ASSERT(rows >= 0 && cols >= 0 &&
                   a.size() == static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols),
               "rank: a must hold rows * cols entries");
  if (rank_tolerance < T(0)) rank_tolerance = default_rank_tolerance<T>(rows, cols);
  std::vector<T> w(a.begin(), a.end());
  return detail::rank_inplace(w.data(), rows, cols, rank_tolerance);
}

#define LOCUS_LU_INSTANTIATE(T)                                                                    \
  template LuDynamic<T> lu_factor<T>(std::span<const T>, int, T);                                  \
  template std::vector<T> solve<T>(const LuDynamic<T>&, std::span<const T>, int);                  \
  template LinearSolution<T, std::vector<T>> solve<T>(std::span<const T>, int, std::span<const T>, \
                                                      int, T);                                     \
  template T determinant<T>(std::span<const T>, int);                                              \
  template std::optional<std::vector<T>> inverse<T>(std::span<const T>, int);                      \
  template int rank<T>(std::span<const T>, int, int, T);
LOCUS_LU_INSTANTIATE(float)
LOCUS_LU_INSTANTIATE(double)
#undef LOCUS_LU_INSTANTIATE

}  // namespace locus
