// SPDX-License-Identifier: BSL-1.0
#pragma once
// Affine frames and change of coordinates (row core.frames; book sections 3.4, 4.2-4.4,
// figures 2.1, 3.35-3.40, 4.6-4.8, 4.10).
//
// A Frame<T, N> is an origin O and N axis vectors v_0..v_{N-1} (orthonormal, or any basis).
// Local coordinates (c_0, ..., c_{N-1}) of a point denote O + sum c_i v_i (figure 3.35); those of
// a vector denote sum c_i v_i (no origin). to_world_* maps local to world coordinates,
// to_local_* the reverse.
//
// Matrix form (column vectors, y = M x, see mat.hpp): to_matrix(f) is the (N+1) x (N+1) affine
// matrix [A O; 0 1] whose columns are the axes and the origin, acting on homogeneous points
// (w = 1) and vectors (w = 0) exactly like to_world_point / to_world_vector. compose(f, g) is the
// frame g given in f's local coordinates, re-expressed in world coordinates:
// to_matrix(compose(f, g)) = to_matrix(f) * to_matrix(g), so compose(inverse(B), A) converts
// A-coordinates to B-coordinates (figures 4.6-4.8).
// Inverses: inverse(f) inverts a general basis (the closed-form adjugate inverse of mat.hpp,
// N <= 4) and returns std::nullopt for a singular or non-finite basis; rigid_inverse(f) assumes
// orthonormal axes and uses the transpose (cheap, exact up to the orthonormality of the input;
// not checked -- test with is_orthonormal). to_local_point/to_local_vector work for any basis;
// for a singular one they return the zero vector (call inverse() to detect it). For an
// orthonormal frame, to_world_point(rigid_inverse(f), p) is the cheaper equivalent.
//
// Degenerate input: NaN/infinite frames propagate NaN through to_world_*; inverse() returns
// std::nullopt; to_frame() returns std::nullopt when the bottom row of the matrix is not
// (0, ..., 0, 1) (a projective, not affine, matrix). Cost: to_world O(N^2); to_local O(N^3) for the
// inverse, O(N^2) with a precomputed inverse frame; compose O(N^3).

#include <locus/core/basis.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstddef>
#include <optional>

namespace locus {

/// An affine frame: origin and axis[i] (the images of the unit coordinate vectors).
template <class T, int N>
struct Frame {
  Vec<T, N> origin;
  std::array<Vec<T, N>, N> axis;

  /// The world frame: origin 0, axes e_0..e_{N-1}.
  [[nodiscard]] static constexpr Frame identity() noexcept {
    Frame f{};
    for (int i = 0; i < N; ++i) f.axis[static_cast<std::size_t>(i)] = unit_vec<T, N>(i);
    return f;
  }
};

template <Real T>
using Frame2 = Frame<T, 2>;
template <Real T>
using Frame3 = Frame<T, 3>;
using Frame2f = Frame2<float>;
using Frame3f = Frame3<float>;
using Frame2d = Frame2<double>;
using Frame3d = Frame3<double>;

/// The N x N matrix whose columns are the axes (the linear part of the frame).
template <Real T, int N>
[[nodiscard]] constexpr Mat<T, N, N> axes_matrix(const Frame<T, N>& f) noexcept {
  Mat<T, N, N> m{};
  for (int c = 0; c < N; ++c)
    for (int r = 0; r < N; ++r) m.a[r][c] = f.axis[static_cast<std::size_t>(c)][r];
  return m;
}

/// World coordinates of the vector with local coordinates v: sum v_i axis_i.
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> to_world_vector(const Frame<T, N>& f,
                                                  const Vec<T, N>& v) noexcept {
  Vec<T, N> r = f.axis[0] * v[0];
  for (int i = 1; i < N; ++i) r += f.axis[static_cast<std::size_t>(i)] * v[i];
  return r;
}

/// World coordinates of the point with local coordinates p: origin + sum p_i axis_i.
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> to_world_point(const Frame<T, N>& f,
                                                 const Vec<T, N>& p) noexcept {
  return f.origin + to_world_vector(f, p);
}

/// Local coordinates of the world vector v (any invertible basis); zero for a singular basis.
template <Real T, int N>
requires(N >= 2 && N <= 4)
    [[nodiscard]] constexpr Vec<T, N> to_local_vector(const Frame<T, N>& f,
                                                      const Vec<T, N>& v) noexcept {
  const std::optional<Mat<T, N, N>> inv = inverse(axes_matrix(f));
  if (!inv) return Vec<T, N>{};
  return *inv * v;
}

/// Local coordinates of the world point p (any invertible basis); zero for a singular basis.
template <Real T, int N>
requires(N >= 2 && N <= 4)
    [[nodiscard]] constexpr Vec<T, N> to_local_point(const Frame<T, N>& f,
                                                     const Vec<T, N>& p) noexcept {
  return to_local_vector(f, p - f.origin);
}

/// The affine matrix [A O; 0 1] of the frame (3x3 for 2D frames, 4x4 for 3D frames).
template <Real T, int N>
[[nodiscard]] constexpr Mat<T, N + 1, N + 1> to_matrix(const Frame<T, N>& f) noexcept {
  Mat<T, N + 1, N + 1> m{};
  for (int c = 0; c < N; ++c)
    for (int r = 0; r < N; ++r) m.a[r][c] = f.axis[static_cast<std::size_t>(c)][r];
  for (int r = 0; r < N; ++r) m.a[r][N] = f.origin[r];
  m.a[N][N] = T(1);
  return m;
}

/// The frame of an affine matrix [A O; 0 1]; std::nullopt when the bottom row is not
/// (0, ..., 0, 1).
template <Real T, int M>
requires(M >= 2) [[nodiscard]] constexpr std::optional<Frame<T, M - 1>> to_frame(
    const Mat<T, M, M>& m) noexcept {
  constexpr int N = M - 1;
  for (int c = 0; c < N; ++c)
    if (!(m.a[N][c] == T(0))) return std::nullopt;
  if (!(m.a[N][N] == T(1))) return std::nullopt;
  Frame<T, N> f{};
  for (int r = 0; r < N; ++r) {
    f.origin[r] = m.a[r][N];
    for (int c = 0; c < N; ++c) f.axis[static_cast<std::size_t>(c)][r] = m.a[r][c];
  }
  return f;
}

/// The frame g (given in f's local coordinates) in world coordinates: to_world(compose(f, g), x)
/// = to_world(f, to_world(g, x)), and to_matrix(compose(f, g)) = to_matrix(f) * to_matrix(g).
template <Real T, int N>
[[nodiscard]] constexpr Frame<T, N> compose(const Frame<T, N>& f, const Frame<T, N>& g) noexcept {
  Frame<T, N> h{};
  h.origin = to_world_point(f, g.origin);
  for (std::size_t i = 0; i < static_cast<std::size_t>(N); ++i)
    h.axis[i] = to_world_vector(f, g.axis[i]);
  return h;
}

/// The inverse frame: to_world_point(*inverse(f), p) = to_local_point(f, p). std::nullopt for a
/// singular or non-finite basis.
template <Real T, int N>
requires(N >= 2 && N <= 4)
    [[nodiscard]] constexpr std::optional<Frame<T, N>> inverse(const Frame<T, N>& f) noexcept {
  if (!is_finite(f.origin)) return std::nullopt;
  const std::optional<Mat<T, N, N>> inv = inverse(axes_matrix(f));
  if (!inv) return std::nullopt;
  Frame<T, N> g{};
  for (int c = 0; c < N; ++c) g.axis[static_cast<std::size_t>(c)] = col(*inv, c);
  g.origin = -(*inv * f.origin);
  return g;
}

/// The inverse of a frame with orthonormal axes, by transposition (A^-1 = A^T). Precondition
/// (not checked): is_orthonormal(f); otherwise the result is not the inverse.
template <Real T, int N>
[[nodiscard]] constexpr Frame<T, N> rigid_inverse(const Frame<T, N>& f) noexcept {
  Frame<T, N> g{};
  for (int c = 0; c < N; ++c)
    for (int r = 0; r < N; ++r)
      g.axis[static_cast<std::size_t>(c)][r] = f.axis[static_cast<std::size_t>(r)][c];
  for (int r = 0; r < N; ++r) g.origin[r] = -dot(f.axis[static_cast<std::size_t>(r)], f.origin);
  return g;
}

/// True when the axes are orthonormal to tol (see is_orthonormal in basis.hpp).
template <Real T, int N>
[[nodiscard]] constexpr bool is_orthonormal(const Frame<T, N>& f,
                                            T tol = T(8 * N) * eps_v<T>) noexcept {
  return is_orthonormal(f.axis, tol);
}

}  // namespace locus
