// SPDX-License-Identifier: BSL-1.0
#pragma once
// MatX<T>: a dense matrix whose size is chosen at run time (row num.decomp; book appendix A).
//
// The fixed-size Mat<T, R, C> of core/mat.hpp is the type for 2x2..4x4 geometry; MatX is for the
// N x N and M x N problems of the numerical methods (decompositions, least squares, fits).
// Storage: row-major, data[r * cols + c]. Column-vector convention as everywhere: y = A * x.
// Sizes are checked by LOCUS_ASSERT (a mismatch is a programming error, not bad data).

#include <locus/core/mat.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace locus {

template <Real T>
struct MatX {
  int rows = 0;
  int cols = 0;
  std::vector<T> data;  ///< row-major, rows * cols entries

  MatX() = default;
  MatX(int r, int c, T fill = T(0))
      : rows(r), cols(c), data(std::size_t(r) * std::size_t(c), fill) {
    LOCUS_ASSERT(r >= 0 && c >= 0, "MatX size must be non-negative");
  }
  template <int R, int C>
  explicit MatX(const Mat<T, R, C>& m) : MatX(R, C) {
    for (int r = 0; r < R; ++r)
      for (int c = 0; c < C; ++c) (*this)(r, c) = m(r, c);
  }

  [[nodiscard]] static MatX identity(int n) {
    MatX m(n, n);
    for (int i = 0; i < n; ++i) m(i, i) = T(1);
    return m;
  }

  [[nodiscard]] T& operator()(int r, int c) noexcept {
    LOCUS_ASSERT(r >= 0 && r < rows && c >= 0 && c < cols, "MatX index out of range");
    return data[std::size_t(r) * std::size_t(cols) + std::size_t(c)];
  }
  [[nodiscard]] const T& operator()(int r, int c) const noexcept {
    LOCUS_ASSERT(r >= 0 && r < rows && c >= 0 && c < cols, "MatX index out of range");
    return data[std::size_t(r) * std::size_t(cols) + std::size_t(c)];
  }
  [[nodiscard]] bool empty() const noexcept { return rows == 0 || cols == 0; }

  /// Conversion to a fixed-size matrix of the same shape.
  template <int R, int C>
  [[nodiscard]] Mat<T, R, C> to_mat() const noexcept {
    LOCUS_ASSERT(rows == R && cols == C, "MatX shape mismatch");
    Mat<T, R, C> m{};
    for (int r = 0; r < R; ++r)
      for (int c = 0; c < C; ++c) m(r, c) = (*this)(r, c);
    return m;
  }
};

template <Real T>
[[nodiscard]] MatX<T> transpose(const MatX<T>& a) {
  MatX<T> t(a.cols, a.rows);
  for (int r = 0; r < a.rows; ++r)
    for (int c = 0; c < a.cols; ++c) t(c, r) = a(r, c);
  return t;
}

template <Real T>
[[nodiscard]] MatX<T> operator*(const MatX<T>& a, const MatX<T>& b) {
  LOCUS_ASSERT(a.cols == b.rows, "MatX product shape mismatch");
  MatX<T> p(a.rows, b.cols);
  for (int r = 0; r < a.rows; ++r)
    for (int k = 0; k < a.cols; ++k) {
      const T ark = a(r, k);
      for (int c = 0; c < b.cols; ++c) p(r, c) += ark * b(k, c);
    }
  return p;
}

template <Real T>
[[nodiscard]] std::vector<T> operator*(const MatX<T>& a, const std::vector<T>& x) {
  LOCUS_ASSERT(int(x.size()) == a.cols, "MatX-vector shape mismatch");
  std::vector<T> y(std::size_t(a.rows), T(0));
  for (int r = 0; r < a.rows; ++r)
    for (int c = 0; c < a.cols; ++c) y[std::size_t(r)] += a(r, c) * x[std::size_t(c)];
  return y;
}

template <Real T>
[[nodiscard]] MatX<T> operator-(MatX<T> a, const MatX<T>& b) {
  LOCUS_ASSERT(a.rows == b.rows && a.cols == b.cols, "MatX shape mismatch");
  for (std::size_t i = 0; i < a.data.size(); ++i) a.data[i] -= b.data[i];
  return a;
}

/// Frobenius norm, scaled to avoid overflow and underflow. NaN when an entry is NaN, +inf when
/// an entry is infinite (and none is NaN); 0 for an empty matrix.
template <Real T>
[[nodiscard]] T frobenius_norm(const MatX<T>& a) noexcept {
  T m = T(0);
  bool infinite = false;
  for (T v : a.data) {
    if (v != v) return v;  // a NaN entry: the norm is undefined, never a finite-looking value
    const T av = std::abs(v);
    infinite = infinite || av == std::numeric_limits<T>::infinity();
    m = av > m ? av : m;
  }
  if (infinite) return std::numeric_limits<T>::infinity();
  if (m == T(0)) return m;
  T s = T(0);
  for (T v : a.data) s += sqr(v / m);
  return m * std::sqrt(s);
}

/// True when every entry is finite.
template <Real T>
[[nodiscard]] bool is_finite(const MatX<T>& a) noexcept {
  for (T v : a.data)
    if (!is_finite(v)) return false;
  return true;
}

}  // namespace locus
