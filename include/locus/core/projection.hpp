// SPDX-License-Identifier: BSL-1.0
#pragma once
// Projections as homogeneous matrices (row core.projection; book section 4.8, figures
// 4.26-4.31), the standard camera matrices of a rendering pipeline, and the cross-ratio.
// Projection onto the plane (a line when N = 2) through `point` with normal `normal` (any
// nonzero length), as (N+1) x (N+1) matrices on column vectors (x, 1) (the book's transpose):
//   orthographic_projection(point, normal)       x -> x - ((x - point) . n) n          (4.26)
//   oblique_projection(point, normal, dir)       parallel projection along dir   (4.27, 4.28)
//   perspective_projection(eye, point, normal)   where the line eye-x meets the plane (4.29);
//                                                last row (n, -n . eye), w = (x - eye) . n
// All are singular (rank N). std::nullopt: zero or non-finite normal; dir zero or parallel to the
// plane (dir . n = 0 exactly); an eye on the plane; any non-finite entry. apply_projective()
// returns std::nullopt for points with w = 0 (on the plane through the eye parallel to the target).
// Camera matrices (3D, OpenGL conventions, right-handed, column vectors):
//   look_at(eye, target, up)   the camera at eye looks down its -z axis; +y the part of up
//                              orthogonal to the view direction. nullopt for eye == target, zero
//                              up, up parallel to the view, non-finite input.
//   perspective_frustum(l, r, b, t, n, f, depth), perspective_fov(fovy, aspect, n, f, depth)
//   (0 < n < f, 0 < fovy < pi, aspect > 0), orthographic_box(l, r, b, t, n, f, depth) (n != f):
//   the frustum/box maps to [-1, 1]^2 x the depth range: DepthRange::minus_one_to_one (near -1,
//   far +1, OpenGL) or zero_to_one (Direct3D, Vulkan). nullopt for l = r, b = t, invalid
//   near/far or non-finite input. project_point(m, p) divides by w; w <= 0 gives in_front = false.
// Cross-ratio (figures 4.30, 4.31) of collinear A, B, C, D at signed positions a, b, c, d:
// ((c - a)(d - b)) / ((c - b)(d - a)), invariant under projective maps of the line; nullopt
// when C = B, D = A or input is not finite. The point version measures along the longest of
// B - A, C - A, D - A (collinearity assumed, not checked).
// Near-degenerate set-ups give large but finite entries (or nullopt, never Inf). Cost: O(N^2).

#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <cstdint>
#include <optional>

namespace locus {

namespace detail {

/// The (N+1) x (N+1) matrix [l t; r w].
template <class T, int N>
[[nodiscard]] constexpr Mat<T, N + 1, N + 1> homogeneous(const Mat<T, N, N>& l, const Vec<T, N>& t,
                                                         const Vec<T, N>& r, T w) noexcept {
  Mat<T, N + 1, N + 1> m{};
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) m.a[i][j] = l.a[i][j];
    m.a[i][N] = t[i];
    m.a[N][i] = r[i];
  }
  m.a[N][N] = w;
  return m;
}

template <class T, int M>
[[nodiscard]] constexpr std::optional<Mat<T, M, M>> finite_or_null(const Mat<T, M, M>& m) noexcept {
  if (!is_finite(m)) return std::nullopt;
  return m;
}

}  // namespace detail

// ---- projection onto a plane --------------------------------------------------------------

/// Orthographic projection onto the plane through `point` with normal `normal` (figure 4.26).
template <class T, int N>
[[nodiscard]] inline std::optional<Mat<T, N + 1, N + 1>> orthographic_projection(
    const Vec<T, N>& point, const Vec<T, N>& normal) noexcept {
  if (!is_finite(point) || !is_finite(normal)) return std::nullopt;
  const Vec<T, N> n = normalize(normal);
  if (n == Vec<T, N>{}) return std::nullopt;
  return detail::finite_or_null(detail::homogeneous<T, N>(Mat<T, N, N>::identity() - outer(n, n),
                                                          n * dot(n, point), Vec<T, N>{}, T(1)));
}

/// Oblique (parallel) projection along `dir` onto the plane through `point` with normal
/// `normal` (figures 4.27, 4.28); std::nullopt when dir is zero or parallel to the plane.
template <class T, int N>
[[nodiscard]] inline std::optional<Mat<T, N + 1, N + 1>> oblique_projection(
    const Vec<T, N>& point, const Vec<T, N>& normal, const Vec<T, N>& dir) noexcept {
  if (!is_finite(point) || !is_finite(normal) || !is_finite(dir)) return std::nullopt;
  const Vec<T, N> n = normalize(normal);
  const Vec<T, N> d = normalize(dir);
  const T dn = dot(d, n);
  if (n == Vec<T, N>{} || dn == T(0)) return std::nullopt;  // dn = 0 also for d = 0
  const Vec<T, N> ds = d / dn;
  return detail::finite_or_null(detail::homogeneous<T, N>(Mat<T, N, N>::identity() - outer(ds, n),
                                                          ds * dot(n, point), Vec<T, N>{}, T(1)));
}

/// Perspective projection from `eye` onto the plane through `point` with normal `normal`
/// (figure 4.29); std::nullopt when the eye is on the plane. Apply with apply_projective().
template <class T, int N>
[[nodiscard]] inline std::optional<Mat<T, N + 1, N + 1>> perspective_projection(
    const Vec<T, N>& eye, const Vec<T, N>& point, const Vec<T, N>& normal) noexcept {
  if (!is_finite(eye) || !is_finite(point) || !is_finite(normal)) return std::nullopt;
  const Vec<T, N> n = normalize(normal);
  if (n == Vec<T, N>{}) return std::nullopt;
  // x' = eye + delta (x - eye) / ((x - eye) . n), delta = (point - eye) . n; multiplied through
  // by the denominator this is linear in (x, 1).
  const T delta = dot(n, Vec<T, N>(point - eye));
  if (delta == T(0)) return std::nullopt;
  return detail::finite_or_null(detail::homogeneous<T, N>(
      Mat<T, N, N>::identity() * delta + outer(eye, n), eye * (-dot(n, point)), n, -dot(n, eye)));
}

// ---- applying homogeneous matrices --------------------------------------------------------

/// The point (h_0, ..., h_{M-2}) / h_{M-1}; std::nullopt when the weight is 0 or the result is
/// not finite (a point at infinity).
template <class T, int M>
requires(M >= 2)
    [[nodiscard]] constexpr std::optional<Vec<T, M - 1>> dehomogenize(const Vec<T, M>& h) noexcept {
  const T w = h[M - 1];
  if (w == T(0) || !is_finite(w)) return std::nullopt;
  Vec<T, M - 1> p{};
  for (int i = 0; i < M - 1; ++i) p[i] = h[i] / w;
  if (!is_finite(p)) return std::nullopt;
  return p;
}

/// The image of point p under the homogeneous matrix m: m (p, 1) divided by its weight;
/// std::nullopt when the weight is 0 (p maps to infinity) or the result is not finite.
template <class T, int M>
requires(M >= 2) [[nodiscard]] constexpr std::optional<Vec<T, M - 1>> apply_projective(
    const Mat<T, M, M>& m, const Vec<T, M - 1>& p) noexcept {
  Vec<T, M> h{};
  for (int i = 0; i < M - 1; ++i) h[i] = p[i];
  h[M - 1] = T(1);
  return dehomogenize(Vec<T, M>(m * h));
}

/// Result of project_point: the divided point, the clip-space weight w, and whether w > 0.
template <class T, int N>
struct ProjectedPoint {
  Vec<T, N> point;  ///< m (p, 1) divided by w; the zero vector when !in_front
  T w;              ///< the weight before the divide (= -z_view for the camera matrices)
  bool in_front;    ///< w > 0 and everything finite
};

/// Applies a camera/clip matrix to p and divides by w, reporting w <= 0 (on or behind the eye
/// plane) and non-finite results with in_front = false.
template <class T, int M>
requires(M >= 2) [[nodiscard]] constexpr ProjectedPoint<T, M - 1> project_point(
    const Mat<T, M, M>& m, const Vec<T, M - 1>& p) noexcept {
  Vec<T, M> h{};
  for (int i = 0; i < M - 1; ++i) h[i] = p[i];
  h[M - 1] = T(1);
  h = m * h;
  const T w = h[M - 1];
  if (!(w > T(0))) return {Vec<T, M - 1>{}, w, false};
  const std::optional<Vec<T, M - 1>> q = dehomogenize(h);
  if (!q) return {Vec<T, M - 1>{}, w, false};
  return {*q, w, true};
}

// ---- camera matrices ----------------------------------------------------------------------

/// Clip-space depth range after the homogeneous divide (header comment).
enum class DepthRange : std::uint8_t {
  minus_one_to_one,  ///< near plane -> -1, far plane -> +1 (OpenGL)
  zero_to_one,       ///< near plane -> 0, far plane -> 1 (Direct3D, Vulkan, Metal)
};

/// Right-handed view matrix: world to camera coordinates, camera at `eye` looking down -z
/// towards `target`, `up` projected to +y (header comment for std::nullopt).
template <Real T>
[[nodiscard]] inline std::optional<Mat4<T>> look_at(const Vec3<T>& eye, const Vec3<T>& target,
                                                    const Vec3<T>& up) noexcept {
  if (!is_finite(eye) || !is_finite(target) || !is_finite(up)) return std::nullopt;
  const Vec3<T> f = normalize(Vec3<T>(target - eye));
  const Vec3<T> s = normalize(cross(f, normalize(up)));
  if (f == Vec3<T>{} || s == Vec3<T>{}) return std::nullopt;
  const Vec3<T> u = cross(s, f);
  Mat4<T> m =
      Mat4<T>::from_rows(Vec4<T>{s.x, s.y, s.z, -dot(s, eye)}, Vec4<T>{u.x, u.y, u.z, -dot(u, eye)},
                         Vec4<T>{-f.x, -f.y, -f.z, dot(f, eye)}, Vec4<T>{T(0), T(0), T(0), T(1)});
  return detail::finite_or_null(m);
}

/// Perspective frustum to clip space (glFrustum-style; header comment).
template <Real T>
[[nodiscard]] inline std::optional<Mat4<T>> perspective_frustum(
    T left, T right, T bottom, T top, T z_near, T z_far,
    DepthRange depth = DepthRange::minus_one_to_one) noexcept {
  if (!(z_near > T(0)) || !(z_far > z_near) || !(left != right) || !(bottom != top))
    return std::nullopt;  // also rejects NaN
  const T w = right - left, h = top - bottom, d = z_far - z_near;
  Mat4<T> m{};
  m.a[0][0] = T(2) * z_near / w;
  m.a[0][2] = (right + left) / w;
  m.a[1][1] = T(2) * z_near / h;
  m.a[1][2] = (top + bottom) / h;
  if (depth == DepthRange::minus_one_to_one) {
    m.a[2][2] = -(z_far + z_near) / d;
    m.a[2][3] = -T(2) * z_far * z_near / d;
  } else {
    m.a[2][2] = -z_far / d;
    m.a[2][3] = -z_far * z_near / d;
  }
  m.a[3][2] = T(-1);
  return detail::finite_or_null(m);
}

/// Symmetric perspective frustum from the vertical field of view `fovy` (radians) and the
/// width/height `aspect` (gluPerspective-style).
template <Real T>
[[nodiscard]] inline std::optional<Mat4<T>> perspective_fov(
    T fovy, T aspect, T z_near, T z_far, DepthRange depth = DepthRange::minus_one_to_one) noexcept {
  if (!(fovy > T(0)) || !(fovy < pi_v<T>) || !(aspect > T(0)) || !is_finite(aspect))
    return std::nullopt;
  const T top = z_near * std::tan(fovy / T(2)), right = top * aspect;
  return perspective_frustum(-right, right, -top, top, z_near, z_far, depth);
}

/// Orthographic box [left, right] x [bottom, top] x [-z_far, -z_near] (view space) to clip space
/// (glOrtho-style); z_near may be negative, z_near != z_far.
template <Real T>
[[nodiscard]] inline std::optional<Mat4<T>> orthographic_box(
    T left, T right, T bottom, T top, T z_near, T z_far,
    DepthRange depth = DepthRange::minus_one_to_one) noexcept {
  if (!(left != right) || !(bottom != top) || !(z_near != z_far)) return std::nullopt;
  const T w = right - left, h = top - bottom, d = z_far - z_near;
  Mat4<T> m{};
  m.a[0][0] = T(2) / w;
  m.a[0][3] = -(right + left) / w;
  m.a[1][1] = T(2) / h;
  m.a[1][3] = -(top + bottom) / h;
  if (depth == DepthRange::minus_one_to_one) {
    m.a[2][2] = -T(2) / d;
    m.a[2][3] = -(z_far + z_near) / d;
  } else {
    m.a[2][2] = -T(1) / d;
    m.a[2][3] = -z_near / d;
  }
  m.a[3][3] = T(1);
  return detail::finite_or_null(m);
}

// ---- cross-ratio --------------------------------------------------------------------------

/// Cross-ratio ((c - a)(d - b)) / ((c - b)(d - a)) of four positions on a line (figure 4.30);
/// std::nullopt when c = b, d = a, or the result is not finite. Evaluated as the product of the
/// two ratios (c - a)/(c - b) and (d - b)/(d - a), so tiny or huge positions do not underflow or
/// overflow in the products.
template <Real T>
[[nodiscard]] constexpr std::optional<T> cross_ratio(T a, T b, T c, T d) noexcept {
  const T cb = c - b, da = d - a;
  if (cb == T(0) || da == T(0) || !is_finite(cb) || !is_finite(da)) return std::nullopt;
  const T r = ((c - a) / cb) * ((d - b) / da);
  if (!is_finite(r)) return std::nullopt;
  return r;
}

/// Cross-ratio (A, B; C, D) of four collinear points (header comment).
template <class T, int N>
[[nodiscard]] constexpr std::optional<T> cross_ratio(const Vec<T, N>& a, const Vec<T, N>& b,
                                                     const Vec<T, N>& c,
                                                     const Vec<T, N>& d) noexcept {
  if (!is_finite(a) || !is_finite(b) || !is_finite(c) || !is_finite(d)) return std::nullopt;
  const Vec<T, N> ab = b - a, ac = c - a, ad = d - a;
  // The longest difference gives the best-conditioned direction; positions are dot products
  // with it (the cross-ratio is invariant under the affine change of scale).
  Vec<T, N> u = ab;
  if (sqr_length(u) < sqr_length(ac)) u = ac;
  if (sqr_length(u) < sqr_length(ad)) u = ad;
  const T m = max_abs(u);
  if (m == T(0)) return std::nullopt;  // all four points coincide
  u = u / m;                           // keeps the dot products in range
  if (!is_finite(u)) return std::nullopt;
  return cross_ratio(T(0), dot(ab, u), dot(ac, u), dot(ad, u));
}

}  // namespace locus
