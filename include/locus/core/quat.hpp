// SPDX-License-Identifier: BSL-1.0
#pragma once
// Quat<T>: quaternions q = w + x i + y j + z k, the unit ones representing 3D rotations
// (row core.rotation; book appendix A, rotation representations).
//
// Member order: w (the real/scalar part) first, then x, y, z (the vector part). Brace
// initialisation follows the same order: Quat<T>{w, x, y, z}. Products are Hamilton's
// (i^2 = j^2 = k^2 = ijk = -1), so q1 * q2 applied to a vector rotates by q2 first, then q1,
// matching the column-vector convention of mat.hpp (M1 * M2 applies M2 first).
//
// The unit quaternion for a right-handed (counter-clockwise looking down the axis towards the
// origin) rotation by angle t about the unit axis u is (cos(t/2), sin(t/2) u); q and -q give the
// same rotation. Conversions to and from matrices, axis-angle and Euler angles are in
// core/rotation.hpp.
//
// Degenerate input: normalize() of the zero quaternion or of a non-finite one returns the
// identity (a rotation is always produced, never NaN); inverse() of those also returns the
// identity. log() of the zero quaternion returns {-inf, 0, 0, 0} (as std::log(0) does).
// rotate() and slerp() assume unit input (they do not renormalise, so exact endpoints and
// speed are kept); slerp() falls back to nlerp when the inputs are nearly parallel, so it is
// finite for identical and nearly identical inputs.
//
// Cost: a product is 16 multiplies; rotate() is 15 multiplies and 15 adds (two cross products),
// cheaper than converting to a matrix for a single vector.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <limits>

namespace locus {

/// A quaternion w + x i + y j + z k (scalar part first).
template <Field T>
struct Quat {
  T w, x, y, z;

  /// The identity rotation 1 + 0i + 0j + 0k.
  [[nodiscard]] static constexpr Quat identity() noexcept { return Quat{T(1), T(0), T(0), T(0)}; }
  /// The quaternion (s, v): scalar part s, vector part v.
  [[nodiscard]] static constexpr Quat from_parts(T s, const Vec3<T>& v) noexcept {
    return Quat{s, v.x, v.y, v.z};
  }
};

using Quatf = Quat<float>;
using Quatd = Quat<double>;

/// The vector part (x, y, z).
template <Field T>
[[nodiscard]] constexpr Vec3<T> vector_part(const Quat<T>& q) noexcept {
  return {q.x, q.y, q.z};
}

// ---- arithmetic ---------------------------------------------------------------------------

template <Field T>
[[nodiscard]] constexpr Quat<T> operator+(const Quat<T>& a, const Quat<T>& b) noexcept {
  return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
}
template <Field T>
[[nodiscard]] constexpr Quat<T> operator-(const Quat<T>& a, const Quat<T>& b) noexcept {
  return {a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z};
}
template <Field T>
[[nodiscard]] constexpr Quat<T> operator-(const Quat<T>& a) noexcept {
  return {-a.w, -a.x, -a.y, -a.z};
}
template <Field T>
[[nodiscard]] constexpr Quat<T> operator*(const Quat<T>& a, T s) noexcept {
  return {a.w * s, a.x * s, a.y * s, a.z * s};
}
template <Field T>
[[nodiscard]] constexpr Quat<T> operator*(T s, const Quat<T>& a) noexcept {
  return a * s;
}
template <Field T>
[[nodiscard]] constexpr Quat<T> operator/(const Quat<T>& a, T s) noexcept {
  return {a.w / s, a.x / s, a.y / s, a.z / s};
}
/// Hamilton product: (a * b) rotates by b first, then by a.
template <Field T>
[[nodiscard]] constexpr Quat<T> operator*(const Quat<T>& a, const Quat<T>& b) noexcept {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
template <Field T>
[[nodiscard]] constexpr bool operator==(const Quat<T>& a, const Quat<T>& b) noexcept {
  return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z;
}

/// Four-dimensional dot product; for unit quaternions |dot| = cos(half the rotation angle
/// between them).
template <Field T>
[[nodiscard]] constexpr T dot(const Quat<T>& a, const Quat<T>& b) noexcept {
  return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}
/// The conjugate w - xi - yj - zk; the inverse rotation for a unit quaternion.
template <Field T>
[[nodiscard]] constexpr Quat<T> conjugate(const Quat<T>& q) noexcept {
  return {q.w, -q.x, -q.y, -q.z};
}
template <Field T>
[[nodiscard]] constexpr T sqr_norm(const Quat<T>& q) noexcept {
  return dot(q, q);
}
/// Euclidean norm |q| (overflow-safe, via the Vec4 length).
template <Field T>
[[nodiscard]] inline T norm(const Quat<T>& q) noexcept {
  return length(Vec4<T>{q.w, q.x, q.y, q.z});
}
/// True when every component is finite.
template <Field T>
[[nodiscard]] constexpr bool is_finite(const Quat<T>& q) noexcept {
  return is_finite(q.w) && is_finite(q.x) && is_finite(q.y) && is_finite(q.z);
}

/// q / |q|; the identity when q is zero or not finite (so the result is always a rotation).
template <Field T>
[[nodiscard]] inline Quat<T> normalize(const Quat<T>& q) noexcept {
  const Vec4<T> n = normalize(Vec4<T>{q.w, q.x, q.y, q.z});
  if (n == Vec4<T>{}) return Quat<T>::identity();
  return {n.x, n.y, n.z, n.w};
}

/// Multiplicative inverse conj(q) / |q|^2; the identity when q is zero or not finite.
template <Field T>
[[nodiscard]] inline Quat<T> inverse(const Quat<T>& q) noexcept {
  const T n = norm(q);
  if (!(n > T(0)) || !is_finite(n)) return Quat<T>::identity();
  // Dividing twice by |q| instead of once by |q|^2 avoids overflow/underflow of the square.
  return conjugate(q) / n / n;
}

/// Rotates v by the unit quaternion q: q v q*, evaluated as v + 2 u x (u x v + w v) with
/// u = (x, y, z). q must be unit (the formula uses |q| = 1); normalise a drifted q first.
template <Field T>
[[nodiscard]] constexpr Vec3<T> rotate(const Quat<T>& q, const Vec3<T>& v) noexcept {
  const Vec3<T> u{q.x, q.y, q.z};
  const Vec3<T> t = cross(u, v) + q.w * v;
  return v + T(2) * cross(u, t);
}

// ---- exponential and logarithm ------------------------------------------------------------

/// exp(q) = e^w (cos|v| + sin|v| v/|v|) for q = (w, v). A pure quaternion (0, t/2 u) maps to
/// the rotation by t about u. Accurate for tiny |v| (uses sin|v|/|v| -> 1).
template <Field T>
[[nodiscard]] inline Quat<T> exp(const Quat<T>& q) noexcept {
  const Vec3<T> v = vector_part(q);
  const T a = length(v);
  const T ew = std::exp(q.w);
  // sin(a)/a: below sqrt(eps) its Taylor remainder a^2/6 is under eps/6, so 1 is exact.
  const T sinc = a < std::sqrt(eps_v<T>) ? T(1) : std::sin(a) / a;
  return Quat<T>::from_parts(ew * std::cos(a), (ew * sinc) * v);
}

/// Natural logarithm log(q) = (log|q|, acos(w/|q|) v/|v|), the principal branch (vector part
/// length in [0, pi]). For a unit quaternion the result is pure: (0, t/2 u). The angle comes
/// from atan2(|v|, w), accurate near 0 and pi. A real negative q gets vector part (pi, 0, 0).
/// The zero quaternion gives {-inf, 0, 0, 0}.
template <Field T>
[[nodiscard]] inline Quat<T> log(const Quat<T>& q) noexcept {
  const Vec3<T> v = vector_part(q);
  const T vl = length(v);
  const T n = norm(q);
  if (!(n > T(0))) return {-std::numeric_limits<T>::infinity(), T(0), T(0), T(0)};
  const T angle = std::atan2(vl, q.w);
  if (!(vl > T(0))) {
    // Real quaternion: log of a negative real picks the x axis for the rotation by 2 pi.
    return {std::log(n), q.w < T(0) ? pi_v<T> : T(0), T(0), T(0)};
  }
  return Quat<T>::from_parts(std::log(n), (angle / vl) * v);
}

// ---- interpolation ------------------------------------------------------------------------

/// Normalised linear interpolation along the shorter arc (b is negated when dot(a, b) < 0).
/// Not constant speed, but cheap and always a unit quaternion (identity if the blend is zero).
template <Field T>
[[nodiscard]] inline Quat<T> nlerp(const Quat<T>& a, const Quat<T>& b, T t) noexcept {
  const Quat<T> bb = dot(a, b) < T(0) ? -b : b;
  return normalize(a * (T(1) - t) + bb * t);
}

/// Spherical linear interpolation between unit quaternions along the shorter arc: constant
/// angular velocity; slerp(a, b, 0) == a and slerp(a, b, 1) == b or -b (the same rotation)
/// exactly, since the weights are sin(theta)/sin(theta) == 1 and sin(0) == 0. The angle theta
/// between a and b is computed as 2 atan2(|a - b|, |a + b|), accurate for all angles (acos(dot)
/// loses half the digits near 0). When theta < sqrt(eps) the inputs are nearly parallel and the
/// result is nlerp, whose deviation from slerp is O(theta^3) < eps: finite and unit also for
/// identical inputs (endpoints then within an ulp, through the normalisation).
template <Field T>
[[nodiscard]] inline Quat<T> slerp(const Quat<T>& a, const Quat<T>& b, T t) noexcept {
  const Quat<T> bb = dot(a, b) < T(0) ? -b : b;
  const T theta = T(2) * std::atan2(norm(a - bb), norm(a + bb));
  if (!(theta >= std::sqrt(eps_v<T>))) return nlerp(a, bb, t);
  const T s = std::sin(theta);
  const T ca = std::sin((T(1) - t) * theta) / s;
  const T cb = std::sin(t * theta) / s;
  return a * ca + bb * cb;
}

}  // namespace locus
