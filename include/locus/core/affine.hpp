// SPDX-License-Identifier: BSL-1.0
#pragma once
// Points versus vectors and affine combinations (row core.affine; book sections 3.2-3.3 and
// 4.1, figures 3.23-3.26, 4.1, 4.2). Barycentric coordinates are in core/barycentric.hpp.
//
// Computes: the homogeneous form of a point (w = 1, figure 4.1) and of a vector (w = 0,
// figure 4.2), the way back (dividing by w, or recognising a direction when w = 0), and affine
// combinations sum w_i P_i of N points whose weights sum to 1 (figure 3.26; lerp in vec.hpp is
// the two-point case of figure 3.25).
//
// Parametrisation: a Vec<T, N> point maps to Vec<T, N + 1> (x, ..., 1); a vector to
// (x, ..., 0). from_homogeneous(h) divides the first N components by w when w != 0.
//
// Degenerate input: from_homogeneous with w = 0 (exactly, either sign) returns the first N
// components unchanged with is_point = false (a direction or point at infinity); NaN w yields
// NaN coordinates with is_point = true. affine_combination reports empty_input for no points,
// non_finite_input (point = zero vector) for NaN/infinite points or weights, and
// degenerate_input when |sum w_i - 1| > tol * sum |w_i| (the weights do not define an affine
// combination); the returned point is then P_0 + sum_{i >= 1} w_i (P_i - P_0), i.e. w_0 is
// replaced by 1 - sum_{i >= 1} w_i, which is at least independent of the coordinate origin.
//
// Cost: O(N) per conversion; affine_combination O(n N) with a compensated weight sum.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace locus {

/// Homogeneous form (p, 1) of a point (figure 4.1).
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N + 1> to_homogeneous_point(const Vec<T, N>& p) noexcept {
  Vec<T, N + 1> h{};
  for (int i = 0; i < N; ++i) h[i] = p[i];
  h[N] = T(1);
  return h;
}

/// Homogeneous form (v, 0) of a vector (figure 4.2): translations do not move it.
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N + 1> to_homogeneous_vector(const Vec<T, N>& v) noexcept {
  Vec<T, N + 1> h{};
  for (int i = 0; i < N; ++i) h[i] = v[i];
  h[N] = T(0);
  return h;
}

/// The affine meaning of a homogeneous tuple: a point (is_point) or a direction (w = 0).
template <class T, int N>
struct Dehomogenized {
  Vec<T, N> value;
  bool is_point;
};

/// (x / w, is_point = true) for w != 0; (x, is_point = false) for w = 0 (no division).
template <Real T, int M>
requires(M >= 2)
    [[nodiscard]] constexpr Dehomogenized<T, M - 1> from_homogeneous(const Vec<T, M>& h) noexcept {
  Dehomogenized<T, M - 1> r{};
  const T w = h[M - 1];
  r.is_point = !(w == T(0));
  for (int i = 0; i < M - 1; ++i) r.value[i] = r.is_point ? h[i] / w : h[i];
  return r;
}

/// Default tolerance of affine_combination's weight check, relative to sum |w_i|.
template <Real T>
inline constexpr T affine_weight_tol_v = T(16) * eps_v<T>;

/// The result of affine_combination.
template <class T, int N>
struct AffineCombination {
  Status status = Status::empty_input;
  Vec<T, N> point;
};

/// Affine combination sum w_i P_i of n points with weights summing to 1 (checked to
/// tol * sum |w_i| with a compensated sum). See the header comment for bad input.
template <Real T, int N>
[[nodiscard]] inline AffineCombination<T, N> affine_combination(
    const Vec<T, N>* points, const T* weights, std::size_t n,
    T tol = affine_weight_tol_v<T>) noexcept {
  AffineCombination<T, N> r{};
  if (n == 0) {
    r.status = Status::empty_input;
    return r;
  }
  // Neumaier's compensated summation: the check must not fail because of the sum's rounding.
  T sum = T(0), comp = T(0), abs_sum = T(0);
  for (std::size_t i = 0; i < n; ++i) {
    const T w = weights[i];
    if (!is_finite(w) || !is_finite(points[i])) {
      r.status = Status::non_finite_input;
      return r;
    }
    const T t = sum + w;
    comp += std::abs(sum) >= std::abs(w) ? (sum - t) + w : (w - t) + sum;
    sum = t;
    abs_sum += std::abs(w);
  }
  const T excess = (sum - T(1)) + comp;
  if (std::abs(excess) <= tol * abs_sum) {
    Vec<T, N> p = points[0] * weights[0];
    for (std::size_t i = 1; i < n; ++i) p += points[i] * weights[i];
    r.status = Status::ok;
    r.point = p;
    return r;
  }
  Vec<T, N> p = points[0];
  for (std::size_t i = 1; i < n; ++i) p += (points[i] - points[0]) * weights[i];
  r.status = Status::degenerate_input;
  r.point = p;
  return r;
}

/// Affine combination of K points held in arrays.
template <Real T, int N, std::size_t K>
[[nodiscard]] inline AffineCombination<T, N> affine_combination(
    const std::array<Vec<T, N>, K>& points, const std::array<T, K>& weights,
    T tol = affine_weight_tol_v<T>) noexcept {
  return affine_combination(points.data(), weights.data(), K, tol);
}

}  // namespace locus
