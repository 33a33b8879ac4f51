// SPDX-License-Identifier: BSL-1.0
#pragma once
// Mat<T, R, C>: fixed-size R x C matrices (rows core.tuple, core.linsys; book chapter 2).
//
// Convention: column vectors. A matrix acts on the left, y = M * x, and transforms compose
// right-to-left: (A * B) * x applies B first. (The book writes row vectors, x M; every matrix
// here is the transpose of the book's.) Storage is row-major, a[r][c], dense, no padding.
//
// Degenerate input: inverse() returns std::nullopt when the determinant is zero or the
// computed inverse is not finite; determinant() of a NaN matrix is NaN. Nothing divides by zero.
// Small closed forms (2x2, 3x3, 4x4 determinant and inverse via cofactors) live here; general
// N x N solvers, rank and least squares are in core/linear_system.hpp.

#include <locus/core/vec.hpp>

#include <optional>

namespace locus {

template <class T, int R, int C>
struct Mat {
  static_assert(R >= 1 && C >= 1, "locus: Mat needs at least one row and column");
  T a[R][C];

  [[nodiscard]] constexpr T& operator()(int r, int c) noexcept {
    LOCUS_ASSERT(r >= 0 && r < R && c >= 0 && c < C, "Mat index out of range");
    return a[r][c];
  }
  [[nodiscard]] constexpr const T& operator()(int r, int c) const noexcept {
    LOCUS_ASSERT(r >= 0 && r < R && c >= 0 && c < C, "Mat index out of range");
    return a[r][c];
  }

  [[nodiscard]] static constexpr Mat zero() noexcept { return Mat{}; }
  /// Identity (ones on the main diagonal, also for non-square shapes).
  [[nodiscard]] static constexpr Mat identity() noexcept {
    Mat m{};
    for (int i = 0; i < (R < C ? R : C); ++i) m.a[i][i] = T(1);
    return m;
  }
  /// Diagonal matrix with d on the diagonal (square only).
  [[nodiscard]] static constexpr Mat diagonal(const Vec<T, R>& d) noexcept {
    static_assert(R == C, "diagonal() needs a square matrix");
    Mat m{};
    for (int i = 0; i < R; ++i) m.a[i][i] = d[i];
    return m;
  }
  template <class... V>
  [[nodiscard]] static constexpr Mat from_rows(const V&... rows) noexcept {
    static_assert(sizeof...(V) == R, "from_rows needs R rows");
    const Vec<T, C> rs[R] = {rows...};
    Mat m{};
    for (int r = 0; r < R; ++r)
      for (int c = 0; c < C; ++c) m.a[r][c] = rs[r][c];
    return m;
  }
  template <class... V>
  [[nodiscard]] static constexpr Mat from_cols(const V&... cols) noexcept {
    static_assert(sizeof...(V) == C, "from_cols needs C columns");
    const Vec<T, R> cs[C] = {cols...};
    Mat m{};
    for (int r = 0; r < R; ++r)
      for (int c = 0; c < C; ++c) m.a[r][c] = cs[c][r];
    return m;
  }
};

template <Field T>
using Mat2 = Mat<T, 2, 2>;
template <Field T>
using Mat3 = Mat<T, 3, 3>;
template <Field T>
using Mat4 = Mat<T, 4, 4>;
using Mat2f = Mat2<float>;
using Mat3f = Mat3<float>;
using Mat4f = Mat4<float>;
using Mat2d = Mat2<double>;
using Mat3d = Mat3<double>;
using Mat4d = Mat4<double>;

template <class T, int R, int C>
[[nodiscard]] constexpr Vec<T, C> row(const Mat<T, R, C>& m, int r) noexcept {
  Vec<T, C> v{};
  for (int c = 0; c < C; ++c) v[c] = m(r, c);
  return v;
}
template <class T, int R, int C>
[[nodiscard]] constexpr Vec<T, R> col(const Mat<T, R, C>& m, int c) noexcept {
  Vec<T, R> v{};
  for (int r = 0; r < R; ++r) v[r] = m(r, c);
  return v;
}
template <class T, int R, int C>
constexpr void set_row(Mat<T, R, C>& m, int r, const Vec<T, C>& v) noexcept {
  for (int c = 0; c < C; ++c) m(r, c) = v[c];
}
template <class T, int R, int C>
constexpr void set_col(Mat<T, R, C>& m, int c, const Vec<T, R>& v) noexcept {
  for (int r = 0; r < R; ++r) m(r, c) = v[r];
}

template <class T, int R, int C>
[[nodiscard]] constexpr Mat<T, C, R> transpose(const Mat<T, R, C>& m) noexcept {
  Mat<T, C, R> t{};
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) t.a[c][r] = m.a[r][c];
  return t;
}

template <class T, int R, int C>
[[nodiscard]] constexpr Mat<T, R, C> operator+(Mat<T, R, C> x, const Mat<T, R, C>& y) noexcept {
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) x.a[r][c] += y.a[r][c];
  return x;
}
template <class T, int R, int C>
[[nodiscard]] constexpr Mat<T, R, C> operator-(Mat<T, R, C> x, const Mat<T, R, C>& y) noexcept {
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) x.a[r][c] -= y.a[r][c];
  return x;
}
template <class T, int R, int C>
[[nodiscard]] constexpr Mat<T, R, C> operator-(Mat<T, R, C> x) noexcept {
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) x.a[r][c] = -x.a[r][c];
  return x;
}
template <class T, int R, int C>
[[nodiscard]] constexpr Mat<T, R, C> operator*(Mat<T, R, C> x, T s) noexcept {
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) x.a[r][c] *= s;
  return x;
}
template <class T, int R, int C>
[[nodiscard]] constexpr Mat<T, R, C> operator*(T s, const Mat<T, R, C>& x) noexcept {
  return x * s;
}
template <class T, int R, int K, int C>
[[nodiscard]] constexpr Mat<T, R, C> operator*(const Mat<T, R, K>& x,
                                               const Mat<T, K, C>& y) noexcept {
  Mat<T, R, C> p{};
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) {
      T s = x.a[r][0] * y.a[0][c];
      for (int k = 1; k < K; ++k) s += x.a[r][k] * y.a[k][c];
      p.a[r][c] = s;
    }
  return p;
}
template <class T, int R, int C>
[[nodiscard]] constexpr Vec<T, R> operator*(const Mat<T, R, C>& m, const Vec<T, C>& v) noexcept {
  Vec<T, R> y{};
  for (int r = 0; r < R; ++r) {
    T s = m.a[r][0] * v[0];
    for (int c = 1; c < C; ++c) s += m.a[r][c] * v[c];
    y[r] = s;
  }
  return y;
}
template <class T, int R, int C>
[[nodiscard]] constexpr bool operator==(const Mat<T, R, C>& x, const Mat<T, R, C>& y) noexcept {
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c)
      if (!(x.a[r][c] == y.a[r][c])) return false;
  return true;
}

/// Outer product u v^T.
template <class T, int R, int C>
[[nodiscard]] constexpr Mat<T, R, C> outer(const Vec<T, R>& u, const Vec<T, C>& v) noexcept {
  Mat<T, R, C> m{};
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) m.a[r][c] = u[r] * v[c];
  return m;
}

template <class T, int N>
[[nodiscard]] constexpr T trace(const Mat<T, N, N>& m) noexcept {
  T s = m.a[0][0];
  for (int i = 1; i < N; ++i) s += m.a[i][i];
  return s;
}

/// True when every entry is finite.
template <class T, int R, int C>
[[nodiscard]] constexpr bool is_finite(const Mat<T, R, C>& m) noexcept {
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c)
      if (!is_finite(m.a[r][c])) return false;
  return true;
}

/// The skew-symmetric matrix [v]x with [v]x * w = cross(v, w).
template <Field T>
[[nodiscard]] constexpr Mat3<T> skew(const Vec3<T>& v) noexcept {
  return {{{T(0), -v.z, v.y}, {v.z, T(0), -v.x}, {-v.y, v.x, T(0)}}};
}

// ---- determinants and inverses (closed form, sizes 2..4) ----------------------------------

template <Field T>
[[nodiscard]] constexpr T determinant(const Mat2<T>& m) noexcept {
  return m.a[0][0] * m.a[1][1] - m.a[0][1] * m.a[1][0];
}
template <Field T>
[[nodiscard]] constexpr T determinant(const Mat3<T>& m) noexcept {
  return m.a[0][0] * (m.a[1][1] * m.a[2][2] - m.a[1][2] * m.a[2][1]) -
         m.a[0][1] * (m.a[1][0] * m.a[2][2] - m.a[1][2] * m.a[2][0]) +
         m.a[0][2] * (m.a[1][0] * m.a[2][1] - m.a[1][1] * m.a[2][0]);
}

/// The adjugate (transposed cofactor matrix): adjugate(m) * m = det(m) I.
template <Field T>
[[nodiscard]] constexpr Mat2<T> adjugate(const Mat2<T>& m) noexcept {
  return {{{m.a[1][1], -m.a[0][1]}, {-m.a[1][0], m.a[0][0]}}};
}
template <Field T>
[[nodiscard]] constexpr Mat3<T> adjugate(const Mat3<T>& m) noexcept {
  Mat3<T> r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      // Cyclic index order folds the cofactor sign in.
      r.a[j][i] = m.a[i1][j1] * m.a[i2][j2] - m.a[i1][j2] * m.a[i2][j1];
    }
  return r;
}
template <Field T>
[[nodiscard]] constexpr Mat4<T> adjugate(const Mat4<T>& m) noexcept {
  // Laplace expansion by complementary 2x2 minors of the top and bottom row pairs.
  const auto& a = m.a;
  const T s0 = a[0][0] * a[1][1] - a[1][0] * a[0][1], s1 = a[0][0] * a[1][2] - a[1][0] * a[0][2];
  const T s2 = a[0][0] * a[1][3] - a[1][0] * a[0][3], s3 = a[0][1] * a[1][2] - a[1][1] * a[0][2];
  const T s4 = a[0][1] * a[1][3] - a[1][1] * a[0][3], s5 = a[0][2] * a[1][3] - a[1][2] * a[0][3];
  const T c5 = a[2][2] * a[3][3] - a[3][2] * a[2][3], c4 = a[2][1] * a[3][3] - a[3][1] * a[2][3];
  const T c3 = a[2][1] * a[3][2] - a[3][1] * a[2][2], c2 = a[2][0] * a[3][3] - a[3][0] * a[2][3];
  const T c1 = a[2][0] * a[3][2] - a[3][0] * a[2][2], c0 = a[2][0] * a[3][1] - a[3][0] * a[2][1];
  Mat4<T> r{};
  r.a[0][0] = a[1][1] * c5 - a[1][2] * c4 + a[1][3] * c3;
  r.a[0][1] = -a[0][1] * c5 + a[0][2] * c4 - a[0][3] * c3;
  r.a[0][2] = a[3][1] * s5 - a[3][2] * s4 + a[3][3] * s3;
  r.a[0][3] = -a[2][1] * s5 + a[2][2] * s4 - a[2][3] * s3;
  r.a[1][0] = -a[1][0] * c5 + a[1][2] * c2 - a[1][3] * c1;
  r.a[1][1] = a[0][0] * c5 - a[0][2] * c2 + a[0][3] * c1;
  r.a[1][2] = -a[3][0] * s5 + a[3][2] * s2 - a[3][3] * s1;
  r.a[1][3] = a[2][0] * s5 - a[2][2] * s2 + a[2][3] * s1;
  r.a[2][0] = a[1][0] * c4 - a[1][1] * c2 + a[1][3] * c0;
  r.a[2][1] = -a[0][0] * c4 + a[0][1] * c2 - a[0][3] * c0;
  r.a[2][2] = a[3][0] * s4 - a[3][1] * s2 + a[3][3] * s0;
  r.a[2][3] = -a[2][0] * s4 + a[2][1] * s2 - a[2][3] * s0;
  r.a[3][0] = -a[1][0] * c3 + a[1][1] * c1 - a[1][2] * c0;
  r.a[3][1] = a[0][0] * c3 - a[0][1] * c1 + a[0][2] * c0;
  r.a[3][2] = -a[3][0] * s3 + a[3][1] * s1 - a[3][2] * s0;
  r.a[3][3] = a[2][0] * s3 - a[2][1] * s1 + a[2][2] * s0;
  return r;
}
template <Field T>
[[nodiscard]] constexpr T determinant(const Mat4<T>& m) noexcept {
  const Mat4<T> adj = adjugate(m);
  return m.a[0][0] * adj.a[0][0] + m.a[0][1] * adj.a[1][0] + m.a[0][2] * adj.a[2][0] +
         m.a[0][3] * adj.a[3][0];
}

/// Inverse by the adjugate; std::nullopt when det is 0 or the result is not finite. For
/// ill-conditioned systems prefer the pivoting solvers of core/linear_system.hpp.
template <class T, int N>
requires(N >= 2 && N <= 4)
    [[nodiscard]] constexpr std::optional<Mat<T, N, N>> inverse(const Mat<T, N, N>& m) noexcept {
  const T det = determinant(m);
  if (det == T(0) || !is_finite(det)) return std::nullopt;
  Mat<T, N, N> inv = adjugate(m) * (T(1) / det);
  if (!is_finite(inv)) return std::nullopt;
  return inv;
}

}  // namespace locus
