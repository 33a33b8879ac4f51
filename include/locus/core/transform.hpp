// SPDX-License-Identifier: BSL-1.0
#pragma once
// Affine transformations of chapter 4 as matrices with inverses (rows core.xform, core.normals;
// book sections 4.2-4.7 and 4.9, figures 3.19-3.22, 4.9-4.25, 4.32-4.34). The shear and normal
// derivations: docs/notes/core.md.
//
// Affine<T, N> (N = 2 or 3) is the map x -> linear * x + translation; its homogeneous
// (N+1) x (N+1) matrix [linear translation; 0 1] acts on column vectors (x, 1), so compositions
// read right to left (compose(a, b) applies b first) and every matrix is the transpose of the
// book's row-vector form.
// Factories: translation(t); rotation_2d(angle), rotation(center, angle) (counter-clockwise for
// angle > 0); rotation_about_x/y/z(angle); rotation(point, axis, angle) (Rodrigues, about the
// line point + s axis, counter-clockwise seen from the axis tip); scaling(center, s),
// scaling_axes(center, factors), scaling_along(center, dir or D, s or factors); reflection(point,
// normal) (mirror in a line/plane); reflection_about_line(point, dir) (x -> 2 foot(x) - x);
// reflection_through_point(center); shear(point, normal, dir, angle) and shear_by_factor(...,
// k = tan(angle)): x moves along dir (projected into the fixed hyperplane) by
// k ((x - point) . n); 2D shear(point, dir, angle) uses n = perp(dir) (figure 4.23).
// inverse(Affine): std::nullopt for a numerically singular linear part (1 / cond_F(L) <=
// affine_singular_tol_v = 32 eps, adjustable) or a non-finite map.
// normal_matrix() = sign(det L) cof(L) = |det L| L^{-T}: keeps outward normals outward (also
// under reflections) and stays defined for singular L (n' may then be zero); apply_normal() does
// not normalise. normal_from_tangents(a, t0, t1) = cross(L t0, L t1) follows the tangents'
// orientation instead (figure 4.34 versus 4.33).
// Degenerate input: a zero axis, normal or direction gives the identity; a non-finite one an
// all-NaN map (inverse(): std::nullopt); NaN angles or factors propagate. Nothing divides by
// zero. Cost: O(N^2) or O(N^3), N <= 3; noexcept, constexpr where no sqrt/trig.

#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

namespace locus {

/// The affine map x -> linear * x + translation of N-space (N = 2 or 3).
template <class T, int N>
struct Affine {
  static_assert(N == 2 || N == 3, "locus: Affine is defined for N = 2 and N = 3");
  Mat<T, N, N> linear;
  Vec<T, N> translation;

  /// The identity map.
  [[nodiscard]] static constexpr Affine identity() noexcept {
    return {Mat<T, N, N>::identity(), Vec<T, N>{}};
  }
};

template <Real T>
using Affine2 = Affine<T, 2>;
template <Real T>
using Affine3 = Affine<T, 3>;
using Affine2f = Affine2<float>;
using Affine3f = Affine3<float>;
using Affine2d = Affine2<double>;
using Affine3d = Affine3<double>;

/// Default threshold of inverse(Affine), inverse_transpose() and scaling_along(center, D, f): a
/// linear part L with 1 / cond_F(L) <= 32 eps (within that relative distance of a singular
/// matrix) is treated as singular. Maps that are singular by construction but have rounded
/// entries (a zero factor along a tilted direction, composed with rotations, shears, scalings)
/// measure 1 / cond_F <= 6 eps; an inverse there would have no correct digits. Genuine maps
/// above the threshold invert with relative error about cond * eps. Pass 0 to reject only an
/// exactly zero determinant.
template <Real T>
inline constexpr T affine_singular_tol_v = T(32) * eps_v<T>;

namespace detail {

template <class T, int N>
[[nodiscard]] constexpr Affine<T, N> nan_affine() noexcept {
  Affine<T, N> a{};
  const T nan = std::numeric_limits<T>::quiet_NaN();
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) a.linear.a[r][c] = nan;
    a.translation[r] = nan;
  }
  return a;
}

/// The map with linear part L that fixes `center`: translation center - L center.
template <class T, int N>
[[nodiscard]] constexpr Affine<T, N> fixing(const Mat<T, N, N>& l,
                                            const Vec<T, N>& center) noexcept {
  return {l, center - l * center};
}

template <class T, int N>
[[nodiscard]] constexpr T sqr_frobenius(const Mat<T, N, N>& m) noexcept {
  T s = T(0);
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) s += m.a[r][c] * m.a[r][c];
  return s;
}

/// The inverse of m unless m is within relative distance singular_tol of a singular matrix
/// (1 / cond_F(m) <= singular_tol) or not finite. Works on m / max|m_ij| so that the
/// determinant neither underflows nor overflows for uniformly tiny or huge maps.
template <class T, int N>
[[nodiscard]] constexpr std::optional<Mat<T, N, N>> checked_inverse(const Mat<T, N, N>& m,
                                                                    T singular_tol) noexcept {
  if (!is_finite(m)) return std::nullopt;
  T big = T(0);
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) {
      const T v = m.a[r][c] < T(0) ? -m.a[r][c] : m.a[r][c];
      big = big < v ? v : big;
    }
  if (!(big > T(0))) return std::nullopt;
  Mat<T, N, N> s = m;
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) s.a[r][c] /= big;
  const std::optional<Mat<T, N, N>> si = inverse(s);
  if (!si) return std::nullopt;
  // cond_F^2 = |s|_F^2 |s^-1|_F^2; singular when 1 / cond_F <= tol. Squares avoid a sqrt; an
  // overflowing square is an enormous condition number and is rejected as it should be.
  if (singular_tol > T(0) &&
      !(sqr_frobenius(s) * sqr_frobenius(*si) * singular_tol * singular_tol < T(1)))
    return std::nullopt;
  Mat<T, N, N> inv = *si;
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) inv.a[r][c] /= big;
  if (!is_finite(inv)) return std::nullopt;
  return inv;
}

template <class T, int N>
[[nodiscard]] inline std::optional<Affine<T, N>> to_affine_impl(
    const Mat<T, N + 1, N + 1>& m) noexcept {
  for (int c = 0; c < N; ++c)
    if (m.a[N][c] != T(0)) return std::nullopt;  // projective, not affine (or NaN)
  const T w = m.a[N][N];
  if (w == T(0) || !is_finite(w)) return std::nullopt;
  Affine<T, N> a{};
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) a.linear.a[r][c] = m.a[r][c] / w;
    a.translation[r] = m.a[r][N] / w;
  }
  if (!is_finite(a.linear) || !is_finite(a.translation)) return std::nullopt;
  return a;
}

}  // namespace detail

// ---- conversion ---------------------------------------------------------------------------

/// The homogeneous (N+1) x (N+1) matrix [linear translation; 0 1].
template <class T, int N>
[[nodiscard]] constexpr Mat<T, N + 1, N + 1> to_matrix(const Affine<T, N>& a) noexcept {
  Mat<T, N + 1, N + 1> m{};
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) m.a[r][c] = a.linear.a[r][c];
    m.a[r][N] = a.translation[r];
  }
  m.a[N][N] = T(1);
  return m;
}

/// The affine map of a homogeneous 3x3 matrix whose last row is (0, 0, w), w != 0 (the matrix
/// is divided by w). std::nullopt for a projective last row, w = 0 or non-finite entries.
template <Real T>
[[nodiscard]] inline std::optional<Affine2<T>> to_affine(const Mat3<T>& m) noexcept {
  return detail::to_affine_impl<T, 2>(m);
}
/// The affine map of a homogeneous 4x4 matrix whose last row is (0, 0, 0, w), w != 0.
template <Real T>
[[nodiscard]] inline std::optional<Affine3<T>> to_affine(const Mat4<T>& m) noexcept {
  return detail::to_affine_impl<T, 3>(m);
}

// ---- application, composition, inverse ---------------------------------------------------

/// The image of a point: linear * p + translation.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> apply_point(const Affine<T, N>& a, const Vec<T, N>& p) noexcept {
  return a.linear * p + a.translation;
}
/// The image of a vector (a difference of points): linear * v; translation does not act.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> apply_vector(const Affine<T, N>& a, const Vec<T, N>& v) noexcept {
  return a.linear * v;
}

/// The map "b, then a" (matrix product a * b).
template <class T, int N>
[[nodiscard]] constexpr Affine<T, N> compose(const Affine<T, N>& a,
                                             const Affine<T, N>& b) noexcept {
  return {a.linear * b.linear, a.linear * b.translation + a.translation};
}
/// Same as compose(a, b): apply b first.
template <class T, int N>
[[nodiscard]] constexpr Affine<T, N> operator*(const Affine<T, N>& a,
                                               const Affine<T, N>& b) noexcept {
  return compose(a, b);
}

/// Determinant of the linear part: the factor by which signed areas (2D) / volumes (3D) change.
template <class T, int N>
[[nodiscard]] constexpr T determinant(const Affine<T, N>& a) noexcept {
  return determinant(a.linear);
}

/// The inverse map; std::nullopt when the linear part is numerically singular (1 / cond_F <=
/// singular_tol; pass 0 to reject only an exactly zero determinant) or anything is not finite.
template <class T, int N>
[[nodiscard]] constexpr std::optional<Affine<T, N>> inverse(
    const Affine<T, N>& a,
    std::type_identity_t<T> singular_tol = affine_singular_tol_v<T>) noexcept {
  const std::optional<Mat<T, N, N>> li = detail::checked_inverse(a.linear, singular_tol);
  if (!li) return std::nullopt;
  const Vec<T, N> t = -(*li * a.translation);
  if (!is_finite(t)) return std::nullopt;
  return Affine<T, N>{*li, t};
}

// ---- normals (core.normals) ---------------------------------------------------------------

/// The cofactor matrix cof(m) = transpose(adjugate(m)) = det(m) * m^{-T}; defined for every m.
template <class T, int N>
requires(N >= 2 && N <= 4)
    [[nodiscard]] constexpr Mat<T, N, N> cofactor_matrix(const Mat<T, N, N>& m) noexcept {
  return transpose(adjugate(m));
}

/// The matrix that maps normals: sign(det L) * cof(L) = |det L| * L^{-T} (header comment).
/// For det L = 0 (or NaN) the sign is taken as +1.
template <class T, int N>
[[nodiscard]] constexpr Mat<T, N, N> normal_matrix(const Affine<T, N>& a) noexcept {
  const Mat<T, N, N> cof = cofactor_matrix(a.linear);
  return determinant(a.linear) < T(0) ? -cof : cof;
}

/// The book's normal matrix (L^{-1})^T; std::nullopt when L is numerically singular (as for
/// inverse(); normal_matrix() has no such restriction).
template <class T, int N>
[[nodiscard]] constexpr std::optional<Mat<T, N, N>> inverse_transpose(
    const Affine<T, N>& a,
    std::type_identity_t<T> singular_tol = affine_singular_tol_v<T>) noexcept {
  const std::optional<Mat<T, N, N>> li = detail::checked_inverse(a.linear, singular_tol);
  if (!li) return std::nullopt;
  return transpose(*li);
}

/// The transformed normal normal_matrix(a) * n: orthogonal to every transformed tangent, on the
/// same side as n, not normalised (zero when a collapses the surface; header comment).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> apply_normal(const Affine<T, N>& a, const Vec<T, N>& n) noexcept {
  return normal_matrix(a) * n;
}

/// The normal cross(t0, t1) of a surface with tangents t0, t1 (right-handed, not normalised).
template <Real T>
[[nodiscard]] constexpr Vec3<T> normal_from_tangents(const Vec3<T>& t0,
                                                     const Vec3<T>& t1) noexcept {
  return cross(t0, t1);
}
/// The normal of the transformed surface from the transformed tangents: cross(L t0, L t1) =
/// cof(L) cross(t0, t1). Follows the tangents' orientation (flips under reflections).
template <Real T>
[[nodiscard]] constexpr Vec3<T> normal_from_tangents(const Affine3<T>& a, const Vec3<T>& t0,
                                                     const Vec3<T>& t1) noexcept {
  return cross(a.linear * t0, a.linear * t1);
}
/// The normal (t.y, -t.x) of a 2D curve with tangent t: to the right of the direction of travel,
/// i.e. outward for a counter-clockwise boundary. Not normalised.
template <Real T>
[[nodiscard]] constexpr Vec2<T> normal_from_tangent(const Vec2<T>& t) noexcept {
  return {t.y, -t.x};
}
/// The normal of the transformed curve: normal_from_tangent(L t) = cof(L) normal_from_tangent(t).
template <Real T>
[[nodiscard]] constexpr Vec2<T> normal_from_tangent(const Affine2<T>& a,
                                                    const Vec2<T>& t) noexcept {
  return normal_from_tangent(Vec2<T>(a.linear * t));
}

// ---- translation and rotation -------------------------------------------------------------

/// x -> x + t (figure 4.9). Inverse: translation(-t).
template <class T, int N>
[[nodiscard]] constexpr Affine<T, N> translation(const Vec<T, N>& t) noexcept {
  return {Mat<T, N, N>::identity(), t};
}

/// 2D rotation about the origin by `angle` radians, counter-clockwise for angle > 0 (fig. 3.21).
template <Real T>
[[nodiscard]] inline Affine2<T> rotation_2d(T angle) noexcept {
  const T c = std::cos(angle), s = std::sin(angle);
  return {{{{c, -s}, {s, c}}}, Vec2<T>{}};
}
/// 2D rotation about `center` by `angle` radians, counter-clockwise. Inverse: angle -> -angle.
template <Real T>
[[nodiscard]] inline Affine2<T> rotation(const Vec2<T>& center,
                                         std::type_identity_t<T> angle) noexcept {
  return detail::fixing(rotation_2d(angle).linear, center);
}

/// 3D rotation about the x axis: y towards z for angle > 0 (counter-clockwise seen from +x).
template <Real T>
[[nodiscard]] inline Affine3<T> rotation_about_x(T angle) noexcept {
  const T c = std::cos(angle), s = std::sin(angle);
  return {{{{T(1), T(0), T(0)}, {T(0), c, -s}, {T(0), s, c}}}, Vec3<T>{}};
}
/// 3D rotation about the y axis: z towards x for angle > 0 (counter-clockwise seen from +y).
template <Real T>
[[nodiscard]] inline Affine3<T> rotation_about_y(T angle) noexcept {
  const T c = std::cos(angle), s = std::sin(angle);
  return {{{{c, T(0), s}, {T(0), T(1), T(0)}, {-s, T(0), c}}}, Vec3<T>{}};
}
/// 3D rotation about the z axis: x towards y for angle > 0 (counter-clockwise seen from +z,
/// figure 4.11).
template <Real T>
[[nodiscard]] inline Affine3<T> rotation_about_z(T angle) noexcept {
  const T c = std::cos(angle), s = std::sin(angle);
  return {{{{c, -s, T(0)}, {s, c, T(0)}, {T(0), T(0), T(1)}}}, Vec3<T>{}};
}

/// 3D rotation by `angle` radians about the line through `point` with direction `axis`
/// (figures 4.12, 4.13), counter-clockwise when the axis points towards the viewer. The axis is
/// normalised; a zero axis gives the identity, a non-finite one the all-NaN map. Linear part
/// (Rodrigues): cos(a) I + sin(a) [u]x + (1 - cos(a)) u u^T. Inverse: angle -> -angle.
template <Real T>
[[nodiscard]] inline Affine3<T> rotation(const Vec3<T>& point, const Vec3<T>& axis,
                                         std::type_identity_t<T> angle) noexcept {
  if (!is_finite(axis)) return detail::nan_affine<T, 3>();
  const Vec3<T> u = normalize(axis);
  if (u == Vec3<T>{}) return Affine3<T>::identity();
  const T c = std::cos(angle), s = std::sin(angle);
  const Mat3<T> l = Mat3<T>::identity() * c + skew(u) * s + outer(u, u) * (T(1) - c);
  return detail::fixing(l, point);
}

// ---- scaling ------------------------------------------------------------------------------

/// Uniform scaling by s about `center` (figures 3.19, 4.15): x -> center + s (x - center).
/// s = 0 collapses space (inverse() is std::nullopt). Inverse: s -> 1/s.
template <class T, int N>
[[nodiscard]] constexpr Affine<T, N> scaling(const Vec<T, N>& center,
                                             std::type_identity_t<T> s) noexcept {
  return detail::fixing(Mat<T, N, N>::identity() * s, center);
}

/// Scaling by factors[i] along coordinate axis i about `center` (figure 3.20).
template <class T, int N>
[[nodiscard]] constexpr Affine<T, N> scaling_axes(const Vec<T, N>& center,
                                                  const Vec<T, N>& factors) noexcept {
  return detail::fixing(Mat<T, N, N>::diagonal(factors), center);
}

/// Nonuniform scaling about `center` by s along the direction `dir` and by 1 orthogonally to it
/// (book section 4.4, figure 4.16): linear part I + (s - 1) u u^T with u = dir/|dir|. A zero
/// direction gives the identity, a non-finite one the all-NaN map. Inverse: s -> 1/s.
template <class T, int N>
[[nodiscard]] inline Affine<T, N> scaling_along(const Vec<T, N>& center, const Vec<T, N>& dir,
                                                std::type_identity_t<T> s) noexcept {
  if (!is_finite(dir)) return detail::nan_affine<T, N>();
  const Vec<T, N> u = normalize(dir);
  return detail::fixing(Mat<T, N, N>::identity() + outer(u, u) * (s - T(1)), center);
}

/// Scaling about `center` by factors[i] along column i of `directions` (any linearly independent
/// directions, e.g. an orthonormal frame that is not axis-aligned): linear part
/// D diag(factors) D^{-1}; each direction is an eigenvector with its factor, and the columns'
/// lengths do not matter. std::nullopt when D is singular or not finite.
template <class T, int N>
[[nodiscard]] constexpr std::optional<Affine<T, N>> scaling_along(
    const Vec<T, N>& center, const Mat<T, N, N>& directions, const Vec<T, N>& factors) noexcept {
  const std::optional<Mat<T, N, N>> di =
      detail::checked_inverse(directions, affine_singular_tol_v<T>);
  if (!di) return std::nullopt;
  return detail::fixing(directions * Mat<T, N, N>::diagonal(factors) * *di, center);
}

// ---- reflections --------------------------------------------------------------------------

/// Mirror image in the line (2D) / plane (3D) through `point` with normal `normal` (figures
/// 4.17-4.22): x -> x - 2 ((x - point) . n) n, n = normal/|normal|. det = -1, an involution.
/// A zero normal gives the identity, a non-finite one the all-NaN map.
template <class T, int N>
[[nodiscard]] inline Affine<T, N> reflection(const Vec<T, N>& point,
                                             const Vec<T, N>& normal) noexcept {
  if (!is_finite(normal)) return detail::nan_affine<T, N>();
  const Vec<T, N> n = normalize(normal);
  return {Mat<T, N, N>::identity() - outer(n, n) * T(2), n * (T(2) * dot(n, point))};
}

/// Reflection about the line through `point` with direction `dir`: x -> 2 f - x, f the foot of
/// x on the line. In 2D this is the mirror in that line (det -1); in 3D it is the half-turn
/// about it (det +1): reflection in a line as opposed to a mirror in a plane. An involution.
/// A zero direction gives the identity, a non-finite one the all-NaN map.
template <class T, int N>
[[nodiscard]] inline Affine<T, N> reflection_about_line(const Vec<T, N>& point,
                                                        const Vec<T, N>& dir) noexcept {
  if (!is_finite(dir)) return detail::nan_affine<T, N>();
  const Vec<T, N> u = normalize(dir);
  if (u == Vec<T, N>{}) return Affine<T, N>::identity();
  return detail::fixing(outer(u, u) * T(2) - Mat<T, N, N>::identity(), point);
}

/// Point reflection x -> 2 center - x (rotation by pi in 2D; det -1 in 3D). An involution.
template <class T, int N>
[[nodiscard]] constexpr Affine<T, N> reflection_through_point(const Vec<T, N>& center) noexcept {
  return {-Mat<T, N, N>::identity(), center * T(2)};
}

// ---- shear --------------------------------------------------------------------------------

/// Shear fixing the hyperplane through `point` with normal `normal`, moving x along w by
/// k ((x - point) . n) (header comment for n, w). det = 1. Inverse: k -> -k. A zero normal, or a
/// direction with no component in the hyperplane, gives the identity; non-finite normal or
/// direction gives the all-NaN map.
template <class T, int N>
[[nodiscard]] inline Affine<T, N> shear_by_factor(const Vec<T, N>& point, const Vec<T, N>& normal,
                                                  const Vec<T, N>& dir,
                                                  std::type_identity_t<T> k) noexcept {
  if (!is_finite(normal) || !is_finite(dir)) return detail::nan_affine<T, N>();
  const Vec<T, N> n = normalize(normal);
  const Vec<T, N> w = normalize(Vec<T, N>(dir - n * dot(n, dir)));
  if (n == Vec<T, N>{} || w == Vec<T, N>{}) return Affine<T, N>::identity();
  // Re-orthogonalise once: normalize() rounds, and det = 1 needs w . n = 0 to working precision.
  const Vec<T, N> w2 = normalize(Vec<T, N>(w - n * dot(n, w)));
  return detail::fixing(Mat<T, N, N>::identity() + outer(w2, n) * k, point);
}

/// The book's general shear (section 4.7, figures 4.23-4.25): shear_by_factor with
/// k = tan(angle); |angle| < pi/2 for a finite map. Inverse: angle -> -angle.
template <class T, int N>
[[nodiscard]] inline Affine<T, N> shear(const Vec<T, N>& point, const Vec<T, N>& normal,
                                        const Vec<T, N>& dir,
                                        std::type_identity_t<T> angle) noexcept {
  return shear_by_factor(point, normal, dir, std::tan(angle));
}

/// 2D shear fixing the line through `point` along `dir`; points to the left of dir (n = perp of
/// dir) move along +dir: shear({0,0}, {1,0}, a) is (x, y) -> (x + tan(a) y, y) (figure 4.23).
template <Real T>
[[nodiscard]] inline Affine2<T> shear(const Vec2<T>& point, const Vec2<T>& dir,
                                      std::type_identity_t<T> angle) noexcept {
  return shear(point, perp(dir), dir, angle);
}

}  // namespace locus
