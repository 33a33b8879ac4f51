// SPDX-License-Identifier: BSL-1.0
#pragma once
// Spans and bases (row core.basis; book sections 3.1-3.2, figures 3.13, 3.14, 3.16, 3.17).
// Method notes (Gram-Schmidt twice, the revised Frisvad completion): docs/notes/core.md.
//
// Computes: linear independence of K vectors in N-D, Gram-Schmidt orthonormalisation (with the
// rank when the input is dependent), completion of an orthonormal right-handed basis from one or
// two vectors, handedness and orthonormality tests, projection onto / rejection from the span of
// K vectors, and the coordinates of a vector in a (possibly non-orthogonal) basis (figure 3.17).
// Gram-Schmidt output is orthonormal to a few eps whatever the conditioning of the input, and the
// span of the first k outputs equals the span of the independent inputs among the first k.
//
// Tolerance: a vector is dependent on the preceding ones when its unit vector's component
// orthogonal to their span has length <= tol (the sine of its angle to that span); the default
// independence_tol_v<T> = 64 eps separates exactly dependent sets from independent ones; pass a
// larger tol (e.g. 1e-6) to treat nearly parallel vectors as dependent. Greedy in input order.
// Conventions: complete_basis keeps the given vector(s) first: axis[0] along the first input,
// axis[1] in the plane of the first two, right-handed (cross(axis[0], axis[1]) = axis[2] in 3D;
// axis[1] = perp(axis[0]) in 2D). A tangent frame (t, b, n) for a normal n is (axis[1], axis[2],
// axis[0]).
// Degenerate input: Gram-Schmidt reports degenerate_input and the rank (dependent and zero
// inputs skipped; basis[rank..K) zero) or non_finite_input (rank 0, all zero). complete_basis
// always returns an orthonormal right-handed basis: the standard basis for a zero / non-finite
// vector (degenerate_input / non_finite_input), the completion of the first non-zero one for two
// dependent vectors (degenerate_input). basis_coordinates: std::nullopt for a dependent or
// non-finite basis. is_right_handed is the exact sign of the determinant: false for dependent or
// non-finite vectors. Cost: Gram-Schmidt O(N K^2), about 2K square roots.

#include <locus/core/predicates.hpp>
#include <locus/core/products.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

namespace locus {

/// Default of the scale-relative independence tolerance: the sine of the angle between a vector
/// and the span of the others below which the vector counts as dependent.
template <Real T>
inline constexpr T independence_tol_v = T(64) * eps_v<T>;

/// Result of Gram-Schmidt on K vectors in N-D: basis[0..rank) orthonormal and spanning the
/// input; basis[rank..K) zero. status: ok (rank == K), degenerate_input (dependent input) or
/// non_finite_input.
template <class T, int N, std::size_t K>
struct Orthonormalization {
  Status status = Status::empty_input;
  int rank;
  std::array<Vec<T, N>, K> basis;
};

/// A complete orthonormal right-handed basis; see the header comment for the axis order.
template <class T, int N>
struct OrthonormalBasis {
  Status status = Status::empty_input;
  std::array<Vec<T, N>, N> axis;
};

namespace detail {

// Modified Gram-Schmidt QR of the normalised inputs, skipping dependent ones.
// q[0..rank) orthonormal; r[j][i] = component of unit input i along q[j]; kept[i] says whether
// input i produced a q (then q_of[i] is its index); len[i] = |input i|.
template <class T, int N, std::size_t K>
struct MgsQr {
  std::array<Vec<T, N>, K> q;
  T r[K][K];
  bool kept[K];
  int q_of[K];
  T len[K];
  int rank;
  bool finite;
};

// A column is dependent when its unit residual is <= tol or, when scale > 0, when its absolute
// residual (distance to the span of the previous columns) is <= tol * scale.
template <class T, int N, std::size_t K>
[[nodiscard]] inline MgsQr<T, N, K> mgs_qr(const std::array<Vec<T, N>, K>& v, T tol,
                                           T scale = T(0)) noexcept {
  constexpr int KI = static_cast<int>(K);
  MgsQr<T, N, K> f{};
  f.finite = true;
  for (int i = 0; i < KI; ++i)
    if (!is_finite(v[static_cast<std::size_t>(i)])) f.finite = false;
  if (!f.finite) return f;
  for (int i = 0; i < KI; ++i) {
    const Normalized<T, N> n = normalize_with_length(v[static_cast<std::size_t>(i)]);
    f.len[i] = n.length;
    f.q_of[i] = -1;
    Vec<T, N> w = n.dir;
    for (int pass = 0; pass < 2; ++pass)
      for (int j = 0; j < f.rank; ++j) {
        const Vec<T, N>& qj = f.q[static_cast<std::size_t>(j)];
        const T c = dot(qj, w);
        w -= qj * c;
        f.r[j][i] += c;
      }
    const T wl = length(w);
    if (n.length > T(0) && wl > tol && !(scale > T(0) && !(wl * n.length > tol * scale))) {
      f.q[static_cast<std::size_t>(f.rank)] = w / wl;
      f.r[f.rank][i] = wl;
      f.kept[i] = true;
      f.q_of[i] = f.rank;
      ++f.rank;
    }
  }
  return f;
}

}  // namespace detail

/// Gram-Schmidt orthonormalisation of K vectors in N-D (modified, re-orthogonalised once).
/// Dependent inputs (unit residual <= tol) are skipped and reported through rank and status.
template <Real T, int N, std::size_t K>
[[nodiscard]] inline Orthonormalization<T, N, K> gram_schmidt(
    const std::array<Vec<T, N>, K>& v, T tol = independence_tol_v<T>) noexcept {
  const detail::MgsQr<T, N, K> f = detail::mgs_qr(v, tol);
  Orthonormalization<T, N, K> r{};
  if (!f.finite) {
    r.status = Status::non_finite_input;
    return r;
  }
  r.rank = f.rank;
  r.basis = f.q;
  r.status = f.rank == static_cast<int>(K) ? Status::ok : Status::degenerate_input;
  return r;
}

/// Gram-Schmidt of two vectors: basis[0] along a, basis[1] the unit part of b orthogonal to a.
template <Real T, int N>
[[nodiscard]] inline Orthonormalization<T, N, 2> gram_schmidt(
    const Vec<T, N>& a, const Vec<T, N>& b, T tol = independence_tol_v<T>) noexcept {
  return gram_schmidt(std::array<Vec<T, N>, 2>{a, b}, tol);
}

/// Gram-Schmidt of three vectors (in 3D a right-handed input gives a right-handed output).
template <Real T, int N>
[[nodiscard]] inline Orthonormalization<T, N, 3> gram_schmidt(
    const Vec<T, N>& a, const Vec<T, N>& b, const Vec<T, N>& c,
    T tol = independence_tol_v<T>) noexcept {
  return gram_schmidt(std::array<Vec<T, N>, 3>{a, b, c}, tol);
}

/// True when the K vectors are linearly independent (each one's unit vector is farther than
/// tol from the span of the preceding ones); false for zero or non-finite vectors.
template <Real T, int N, std::size_t K>
[[nodiscard]] inline bool linearly_independent(const std::array<Vec<T, N>, K>& v,
                                               T tol = independence_tol_v<T>) noexcept {
  return gram_schmidt(v, tol).status == Status::ok;
}
/// Two vectors are independent when |sin angle| > tol (and neither is zero).
template <Real T, int N>
[[nodiscard]] inline bool linearly_independent(const Vec<T, N>& a, const Vec<T, N>& b,
                                               T tol = independence_tol_v<T>) noexcept {
  return gram_schmidt(std::array<Vec<T, N>, 2>{a, b}, tol).status == Status::ok;
}
template <Real T, int N>
[[nodiscard]] inline bool linearly_independent(const Vec<T, N>& a, const Vec<T, N>& b,
                                               const Vec<T, N>& c,
                                               T tol = independence_tol_v<T>) noexcept {
  return gram_schmidt(std::array<Vec<T, N>, 3>{a, b, c}, tol).status == Status::ok;
}

/// True when (a, b) is counter-clockwise: perp_dot(a, b) > 0, decided exactly (orient2d).
template <Real T>
[[nodiscard]] inline bool is_right_handed(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return orient2d(Vec2<T>{T(0), T(0)}, a, b) == Sign::positive;
}
/// True when (a, b, c) is right-handed: a . (b x c) > 0, decided exactly (orient3d).
template <Real T>
[[nodiscard]] inline bool is_right_handed(const Vec3<T>& a, const Vec3<T>& b,
                                          const Vec3<T>& c) noexcept {
  // orient3d(0, a, b, c) = sign det[a; b; c]; the differences with the origin are exact.
  return orient3d(Vec3<T>{T(0), T(0), T(0)}, a, b, c) == Sign::positive;
}

/// True when |v_i . v_j - delta_ij| <= tol for all pairs (unit length and mutually orthogonal).
template <Real T, int N, std::size_t K>
[[nodiscard]] constexpr bool is_orthonormal(const std::array<Vec<T, N>, K>& v,
                                            T tol = T(8 * N) * eps_v<T>) noexcept {
  for (std::size_t i = 0; i < K; ++i)
    for (std::size_t j = i; j < K; ++j) {
      const T e = dot(v[i], v[j]) - (i == j ? T(1) : T(0));
      if (!(e <= tol && -e <= tol)) return false;
    }
  return true;
}

/// The 2D orthonormal basis (d / |d|, perp(d / |d|)).
template <Real T>
[[nodiscard]] inline OrthonormalBasis<T, 2> complete_basis(const Vec2<T>& d) noexcept {
  OrthonormalBasis<T, 2> r{Status::ok, {Vec2<T>{T(1), T(0)}, Vec2<T>{T(0), T(1)}}};
  if (!is_finite(d)) {
    r.status = Status::non_finite_input;
    return r;
  }
  const Vec2<T> u = normalize(d);
  if (u == Vec2<T>{}) {
    r.status = Status::degenerate_input;
    return r;
  }
  r.axis = {u, perp(u)};
  return r;
}

/// A right-handed orthonormal basis (d / |d|, u, v) with cross(d / |d|, u) = v, by the revised
/// Frisvad method (header comment). Standard basis with a bad status for zero/non-finite d.
template <Real T>
[[nodiscard]] inline OrthonormalBasis<T, 3> complete_basis(const Vec3<T>& d) noexcept {
  OrthonormalBasis<T, 3> r{Status::ok, {unit_vec<T, 3>(0), unit_vec<T, 3>(1), unit_vec<T, 3>(2)}};
  if (!is_finite(d)) {
    r.status = Status::non_finite_input;
    return r;
  }
  const Vec3<T> n = normalize_with_length(d).dir;
  if (n == Vec3<T>{}) {
    r.status = Status::degenerate_input;
    return r;
  }
  // Frisvad's closed form divides by 1 + z; the revision mirrors through z = 0 for z < 0 so the
  // divisor sign + z is always >= 1 in magnitude.
  const T sign = std::copysign(T(1), n.z);
  const T a = T(-1) / (sign + n.z);
  const T b = n.x * n.y * a;
  const Vec3<T> t1{T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x};
  const Vec3<T> t2{b, sign + n.y * n.y * a, -n.y};
  // (t1, t2, n) is right-handed, hence so is its cyclic shift (n, t1, t2).
  r.axis = {n, t1, t2};
  return r;
}

/// A right-handed orthonormal basis (a', b', a' x b') where a' = a / |a| and b' is the unit part
/// of b orthogonal to a. For dependent a, b: status degenerate_input and the completion of the
/// first non-zero input (standard basis when both are zero).
template <Real T>
[[nodiscard]] inline OrthonormalBasis<T, 3> complete_basis(const Vec3<T>& a, const Vec3<T>& b,
                                                           T tol = independence_tol_v<T>) noexcept {
  const Orthonormalization<T, 3, 2> g = gram_schmidt(a, b, tol);
  if (g.status == Status::non_finite_input)
    return {Status::non_finite_input, {unit_vec<T, 3>(0), unit_vec<T, 3>(1), unit_vec<T, 3>(2)}};
  if (g.rank < 2) {
    OrthonormalBasis<T, 3> r = complete_basis(g.basis[0]);
    r.status = Status::degenerate_input;
    return r;
  }
  return {Status::ok, {g.basis[0], g.basis[1], cross(g.basis[0], g.basis[1])}};
}

namespace detail {
// Back-substitution through the kept columns of an MGS factorisation: coefficients of the
// unit inputs for the vector whose components along q are y.
template <class T, int N, std::size_t K>
inline void solve_kept(const MgsQr<T, N, K>& f, const T (&y)[K], T (&c)[K]) noexcept {
  constexpr int KI = static_cast<int>(K);
  for (int i = 0; i < KI; ++i) c[i] = T(0);
  for (int i = KI - 1; i >= 0; --i) {
    if (!f.kept[i]) continue;
    const int j = f.q_of[i];
    T s = y[j];
    for (int m = i + 1; m < KI; ++m)
      if (f.kept[m]) s -= f.r[j][m] * c[m];
    c[i] = s / f.r[j][i];  // r[j][i] = residual length > tol > 0
  }
}
}  // namespace detail

/// Orthogonal projection of v onto span(s[0..K)) (any spanning set: dependent members are
/// ignored by the rank-revealing Gram-Schmidt). Zero when the span is {0}.
template <Real T, int N, std::size_t K>
[[nodiscard]] inline Vec<T, N> project_onto_span(const Vec<T, N>& v,
                                                 const std::array<Vec<T, N>, K>& s,
                                                 T tol = independence_tol_v<T>) noexcept {
  const detail::MgsQr<T, N, K> f = detail::mgs_qr(s, tol);
  if (!f.finite) return splat<T, N>(std::numeric_limits<T>::quiet_NaN());
  Vec<T, N> w = v;  // residual, reduced twice against the orthonormal basis
  for (int pass = 0; pass < 2; ++pass)
    for (int j = 0; j < f.rank; ++j) {
      const Vec<T, N>& qj = f.q[static_cast<std::size_t>(j)];
      w -= qj * dot(qj, w);
    }
  return v - w;
}

/// Component of v orthogonal to span(s[0..K)): v - project_onto_span(v, s).
template <Real T, int N, std::size_t K>
[[nodiscard]] inline Vec<T, N> reject_from_span(const Vec<T, N>& v,
                                                const std::array<Vec<T, N>, K>& s,
                                                T tol = independence_tol_v<T>) noexcept {
  return v - project_onto_span(v, s, tol);
}

/// True when v lies in span(s) up to tol: |reject_from_span(v, s)| <= tol |v|.
template <Real T, int N, std::size_t K>
[[nodiscard]] inline bool in_span(const Vec<T, N>& v, const std::array<Vec<T, N>, K>& s,
                                  T tol = independence_tol_v<T>) noexcept {
  const Normalized<T, N> n = normalize_with_length(v);
  if (!is_finite(v)) return false;
  if (n.length == T(0)) return true;
  return length(reject_from_span(n.dir, s, tol)) <= tol;
}

/// Coordinates c of v in the basis b (figures 3.14, 3.17): v = sum c_i b_i when v is in the
/// span, otherwise the least-squares coefficients of v's projection onto the span. std::nullopt
/// when the b_i are dependent (per tol) or anything is non-finite.
template <Real T, int N, std::size_t K>
[[nodiscard]] inline std::optional<Vec<T, static_cast<int>(K)>> basis_coordinates(
    const Vec<T, N>& v, const std::array<Vec<T, N>, K>& b, T tol = independence_tol_v<T>) noexcept {
  constexpr int KI = static_cast<int>(K);
  const detail::MgsQr<T, N, K> f = detail::mgs_qr(b, tol);
  if (!f.finite || f.rank < KI || !is_finite(v)) return std::nullopt;
  T y[K] = {}, c[K] = {};
  Vec<T, N> w = v;
  // Modified (sequential) projections give Q^T v with the accuracy of the factorisation.
  for (int j = 0; j < KI; ++j) {
    const Vec<T, N>& qj = f.q[static_cast<std::size_t>(j)];
    y[j] = dot(qj, w);
    w -= qj * y[j];
  }
  detail::solve_kept(f, y, c);
  Vec<T, KI> out{};
  for (int i = 0; i < KI; ++i) out[i] = c[i] / f.len[i];  // the factorisation used unit inputs
  if (!is_finite(out)) return std::nullopt;
  return out;
}

}  // namespace locus
