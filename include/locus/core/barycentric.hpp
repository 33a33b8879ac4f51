// SPDX-License-Identifier: BSL-1.0
#pragma once
// Barycentric coordinates (row core.affine; book section 3.3, figures 3.41, 3.42). Method (signed
// sub-volumes relative to p; rank-revealing QR for a general simplex): docs/notes/core.md.
//
// Computes: the barycentric coordinates w of a point p with respect to a segment (a, b), a
// triangle (a, b, c) in 2D and 3D, a tetrahedron (a, b, c, d), and a general simplex of K <= N + 1
// vertices in N-D; and the inverse, the point sum w_i v_i (from_barycentric).
//
// Parametrisation: w[i] belongs to the i-th vertex argument and sum w = 1 (up to rounding); each
// coordinate is exactly 1 at its own vertex. When p is not in the affine hull of the simplex, the
// coordinates are those of its orthogonal projection onto the hull (a segment: w = (1 - t, t),
// t the projected parameter; a 3D triangle: signed sub-areas measured along the normal).
//
// Degenerate input: a simplex is flat when its volume is tiny relative to its longest edge:
// |b - a| = 0 for a segment; |2 * area| <= tol * (longest edge)^2 for a triangle;
// |6 * volume| <= tol * (longest edge)^3 for a tetrahedron; for a general simplex a vertex at
// distance <= tol * (longest edge from v_0) from the hull of the previous ones (default
// tol = simplex_flat_tol_v<T> = 16 eps). A flat simplex returns valid = false and the coordinates
// w.r.t. a non-flat sub-simplex (the longest edge of a flat triangle, the largest face of a flat
// tetrahedron, the greedily independent vertices of a general simplex), the other weights 0, so
// they still reproduce p's projection onto the hull. All vertices coincident: w = (1, 0, ...).
// NaN or infinite input, or coordinates that overflow, give valid = false and w = (1, 0, ...).
// The coordinates are never NaN.
// Cost: segment O(N); triangle 2D ~15 flops + 3 divisions; 3D ~60 flops; tetrahedron ~80;
// simplex O(N K^2).

#include <locus/core/basis.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace locus {

/// Default flatness tolerance of the barycentric functions (see the header comment).
template <Real T>
inline constexpr T simplex_flat_tol_v = T(16) * eps_v<T>;

/// Barycentric coordinates w.r.t. a K-vertex simplex: w[i] belongs to vertex i. valid = false
/// for a flat simplex or non-finite input (w is then the documented fallback, never NaN).
template <class T, int K>
struct Barycentric {
  std::array<T, K> w;
  bool valid;
};

namespace detail {
template <class T, int K>
[[nodiscard]] constexpr Barycentric<T, K> first_vertex_only() noexcept {
  Barycentric<T, K> r{};
  r.w[0] = T(1);
  r.valid = false;
  return r;
}
template <class T, std::size_t K>
[[nodiscard]] constexpr bool all_finite(const std::array<T, K>& w) noexcept {
  for (const T& x : w)
    if (!is_finite(x)) return false;
  return true;
}
}  // namespace detail

/// Coordinates (1 - t, t) of p's projection onto the line of the segment (a, b),
/// t = (p - a) . (b - a) / |b - a|^2. valid = false (w = (1, 0)) when a = b.
template <Real T, int N>
[[nodiscard]] inline Barycentric<T, 2> barycentric(const Vec<T, N>& p, const Vec<T, N>& a,
                                                   const Vec<T, N>& b) noexcept {
  if (!is_finite(p) || !is_finite(a) || !is_finite(b)) return detail::first_vertex_only<T, 2>();
  const Vec<T, N> d = b - a;
  const T m = max_abs(d);
  if (m == T(0) || !is_finite(m)) return detail::first_vertex_only<T, 2>();
  const Vec<T, N> s = d / m;  // rescaled so s . s neither overflows nor underflows
  const T t = dot(p - a, s) / dot(s, s) / m;
  if (!is_finite(t)) return detail::first_vertex_only<T, 2>();
  return {{T(1) - t, t}, true};
}

namespace detail {
// Flat triangle: coordinates w.r.t. its longest edge (ties prefer ab, then ac).
template <class T, int N>
[[nodiscard]] inline Barycentric<T, 3> triangle_fallback(const Vec<T, N>& p, const Vec<T, N>& a,
                                                         const Vec<T, N>& b,
                                                         const Vec<T, N>& c) noexcept {
  const T lab = sqr_length(b - a), lac = sqr_length(c - a), lbc = sqr_length(c - b);
  Barycentric<T, 3> r{};
  r.valid = false;
  if (lab >= lac && lab >= lbc) {
    const Barycentric<T, 2> s = barycentric(p, a, b);
    r.w = {s.w[0], s.w[1], T(0)};
  } else if (lac >= lbc) {
    const Barycentric<T, 2> s = barycentric(p, a, c);
    r.w = {s.w[0], T(0), s.w[1]};
  } else {
    const Barycentric<T, 2> s = barycentric(p, b, c);
    r.w = {T(0), s.w[0], s.w[1]};
  }
  return r;
}
template <Real T>
[[nodiscard]] constexpr T max3(T x, T y, T z) noexcept {
  return x < y ? (y < z ? z : y) : (x < z ? z : x);
}
}  // namespace detail

/// Barycentric coordinates of p w.r.t. the 2D triangle (a, b, c), either orientation.
template <Real T>
[[nodiscard]] inline Barycentric<T, 3> barycentric(const Vec2<T>& p, const Vec2<T>& a,
                                                   const Vec2<T>& b, const Vec2<T>& c,
                                                   T tol = simplex_flat_tol_v<T>) noexcept {
  if (!is_finite(p) || !is_finite(a) || !is_finite(b) || !is_finite(c))
    return detail::first_vertex_only<T, 3>();
  const T det = perp_dot(b - a, c - a);
  const T e2 = detail::max3(sqr_length(b - a), sqr_length(c - a), sqr_length(c - b));
  if (!(std::abs(det) > tol * e2)) return detail::triangle_fallback(p, a, b, c);
  const Vec2<T> pa = a - p, pb = b - p, pc = c - p;
  Barycentric<T, 3> r{{perp_dot(pb, pc) / det, perp_dot(pc, pa) / det, perp_dot(pa, pb) / det},
                      true};
  if (!detail::all_finite(r.w)) return detail::first_vertex_only<T, 3>();
  return r;
}

/// Barycentric coordinates of p's projection onto the plane of the 3D triangle (a, b, c).
template <Real T>
[[nodiscard]] inline Barycentric<T, 3> barycentric(const Vec3<T>& p, const Vec3<T>& a,
                                                   const Vec3<T>& b, const Vec3<T>& c,
                                                   T tol = simplex_flat_tol_v<T>) noexcept {
  if (!is_finite(p) || !is_finite(a) || !is_finite(b) || !is_finite(c))
    return detail::first_vertex_only<T, 3>();
  const Vec3<T> n = cross(b - a, c - a);
  const T e2 = detail::max3(sqr_length(b - a), sqr_length(c - a), sqr_length(c - b));
  if (!(length(n) > tol * e2)) return detail::triangle_fallback(p, a, b, c);
  const T nn = dot(n, n);
  const Vec3<T> pa = a - p, pb = b - p, pc = c - p;
  Barycentric<T, 3> r{
      {dot(n, cross(pb, pc)) / nn, dot(n, cross(pc, pa)) / nn, dot(n, cross(pa, pb)) / nn}, true};
  if (!detail::all_finite(r.w)) return detail::first_vertex_only<T, 3>();
  return r;
}

/// Barycentric coordinates of p w.r.t. the tetrahedron (a, b, c, d), either orientation.
template <Real T>
[[nodiscard]] inline Barycentric<T, 4> barycentric(const Vec3<T>& p, const Vec3<T>& a,
                                                   const Vec3<T>& b, const Vec3<T>& c,
                                                   const Vec3<T>& d,
                                                   T tol = simplex_flat_tol_v<T>) noexcept {
  if (!is_finite(p) || !is_finite(a) || !is_finite(b) || !is_finite(c) || !is_finite(d))
    return detail::first_vertex_only<T, 4>();
  const T vol = dot(b - a, cross(c - a, d - a));
  T e2 = detail::max3(sqr_length(b - a), sqr_length(c - a), sqr_length(d - a));
  e2 = detail::max3(e2, sqr_length(c - b), sqr_length(d - b));
  if (e2 < sqr_length(d - c)) e2 = sqr_length(d - c);
  const T e = std::sqrt(e2);
  if (!(std::abs(vol) > tol * e2 * e)) {
    // Flat: coordinates w.r.t. the face of largest area (ties prefer the earlier face).
    const Vec3<T>* v[4] = {&a, &b, &c, &d};
    static constexpr int face[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    int best = 3;
    T best_area = T(-1);
    for (int f = 3; f >= 0; --f) {
      const T area =
          sqr_length(cross(*v[face[f][1]] - *v[face[f][0]], *v[face[f][2]] - *v[face[f][0]]));
      if (area >= best_area) {
        best_area = area;
        best = f;
      }
    }
    const Barycentric<T, 3> t =
        barycentric(p, *v[face[best][0]], *v[face[best][1]], *v[face[best][2]], tol);
    Barycentric<T, 4> r{};
    r.valid = false;
    for (int k = 0; k < 3; ++k)
      r.w[static_cast<std::size_t>(face[best][k])] = t.w[static_cast<std::size_t>(k)];
    return r;
  }
  const Vec3<T> pa = a - p, pb = b - p, pc = c - p, pd = d - p;
  // Each weight is the volume of the tetrahedron with p in place of that vertex, over vol.
  Barycentric<T, 4> r{{dot(pb, cross(pc, pd)) / vol, -dot(pa, cross(pc, pd)) / vol,
                       dot(pa, cross(pb, pd)) / vol, -dot(pa, cross(pb, pc)) / vol},
                      true};
  if (!detail::all_finite(r.w)) return detail::first_vertex_only<T, 4>();
  return r;
}

/// Barycentric coordinates of p (projected onto the affine hull) w.r.t. a simplex of K vertices
/// in N-D, 2 <= K <= N + 1, by QR of the edges v[i] - v[0].
template <Real T, int N, std::size_t K>
requires(K >= 2 && K <= static_cast<std::size_t>(N) + 1)
    [[nodiscard]] inline Barycentric<T, static_cast<int>(K)> barycentric(
        const Vec<T, N>& p, const std::array<Vec<T, N>, K>& v,
        T tol = simplex_flat_tol_v<T>) noexcept {
  constexpr int M = static_cast<int>(K) - 1;  // number of edges
  constexpr int KI = static_cast<int>(K);
  if (!is_finite(p)) return detail::first_vertex_only<T, KI>();
  std::array<Vec<T, N>, K - 1> e{};
  T longest = T(0);
  for (std::size_t i = 1; i < K; ++i) {
    e[i - 1] = v[i] - v[0];
    const T l = length(e[i - 1]);
    if (longest < l) longest = l;
  }
  if (!is_finite(v[0])) return detail::first_vertex_only<T, KI>();
  const detail::MgsQr<T, N, K - 1> f = detail::mgs_qr(e, tol, longest);
  if (!f.finite) return detail::first_vertex_only<T, KI>();
  T y[M] = {}, c[M] = {};
  Vec<T, N> w = p - v[0];
  for (int j = 0; j < f.rank; ++j) {
    const Vec<T, N>& qj = f.q[static_cast<std::size_t>(j)];
    y[j] = dot(qj, w);
    w -= qj * y[j];
  }
  detail::solve_kept(f, y, c);
  Barycentric<T, KI> r{};
  T sum = T(0);
  for (int i = 0; i < M; ++i) {
    const T ci = f.kept[i] ? c[i] / f.len[i] : T(0);
    r.w[static_cast<std::size_t>(i + 1)] = ci;
    sum += ci;
  }
  r.w[0] = T(1) - sum;
  r.valid = f.rank == M;
  if (!detail::all_finite(r.w)) return detail::first_vertex_only<T, KI>();
  return r;
}

// ---- the inverse: the point with given barycentric coordinates --------------------------

/// The point w[0] a + w[1] b (exact at the vertices).
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> from_barycentric(const Vec<T, N>& a, const Vec<T, N>& b,
                                                   const std::array<T, 2>& w) noexcept {
  return a * w[0] + b * w[1];
}
/// The point w[0] a + w[1] b + w[2] c.
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> from_barycentric(const Vec<T, N>& a, const Vec<T, N>& b,
                                                   const Vec<T, N>& c,
                                                   const std::array<T, 3>& w) noexcept {
  return a * w[0] + b * w[1] + c * w[2];
}
/// The point w[0] a + w[1] b + w[2] c + w[3] d.
template <Real T, int N>
[[nodiscard]] constexpr Vec<T, N> from_barycentric(const Vec<T, N>& a, const Vec<T, N>& b,
                                                   const Vec<T, N>& c, const Vec<T, N>& d,
                                                   const std::array<T, 4>& w) noexcept {
  return a * w[0] + b * w[1] + c * w[2] + d * w[3];
}
/// The point sum w[i] v[i] for a simplex given as an array.
template <Real T, int N, std::size_t K>
[[nodiscard]] constexpr Vec<T, N> from_barycentric(const std::array<Vec<T, N>, K>& v,
                                                   const std::array<T, K>& w) noexcept {
  Vec<T, N> r{};
  for (std::size_t i = 0; i < K; ++i) r += v[i] * w[i];
  return r;
}

}  // namespace locus
