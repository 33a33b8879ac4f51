// SPDX-License-Identifier: BSL-1.0
#pragma once
// Vec<T, N>: fixed-size vectors and points (row core.tuple; book chapter 3, figures 3.1-3.12).
//
// Points and vectors share one type; whether a Vec is a point (w = 1) or a direction (w = 0) is
// decided by the operation applied to it (see core/affine.hpp for homogeneous forms).
// Layout: N consecutive T with no padding, so an array of Vec3f is a dense float[3n].
// Vec<T, 2..4> have members x, y, z, w; larger N have an array member `c`. operator[] is
// bounds-checked by LOCUS_ASSERT only.
//
// Conventions: right-handed coordinates. perp((x, y)) = (-y, x) is the counter-clockwise
// rotation by 90 degrees, and perp_dot(a, b) = a.x*b.y - a.y*b.x = dot(perp(a), b) is positive
// when b is counter-clockwise from a.
//
// Degenerate input: normalize() of a zero, NaN or infinite vector returns the zero vector (and
// the returned length is 0); it never divides by zero. Everything else follows IEEE arithmetic.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>

#include <cmath>
#include <cstddef>

namespace locus {

template <class T, int N>
struct Vec {
  static_assert(N >= 1, "locus: Vec needs at least one component");
  T c[N];
  [[nodiscard]] constexpr T& operator[](int i) noexcept {
    LOCUS_ASSERT(i >= 0 && i < N, "Vec index out of range");
    return c[i];
  }
  [[nodiscard]] constexpr const T& operator[](int i) const noexcept {
    LOCUS_ASSERT(i >= 0 && i < N, "Vec index out of range");
    return c[i];
  }
};

template <Field T>
struct Vec<T, 2> {
  T x, y;
  [[nodiscard]] constexpr T& operator[](int i) noexcept {
    LOCUS_ASSERT(i >= 0 && i < 2, "Vec index out of range");
    return i == 0 ? x : y;
  }
  [[nodiscard]] constexpr const T& operator[](int i) const noexcept {
    LOCUS_ASSERT(i >= 0 && i < 2, "Vec index out of range");
    return i == 0 ? x : y;
  }
};

template <Field T>
struct Vec<T, 3> {
  T x, y, z;
  [[nodiscard]] constexpr T& operator[](int i) noexcept {
    LOCUS_ASSERT(i >= 0 && i < 3, "Vec index out of range");
    return i == 0 ? x : (i == 1 ? y : z);
  }
  [[nodiscard]] constexpr const T& operator[](int i) const noexcept {
    LOCUS_ASSERT(i >= 0 && i < 3, "Vec index out of range");
    return i == 0 ? x : (i == 1 ? y : z);
  }
};

template <Field T>
struct Vec<T, 4> {
  T x, y, z, w;
  [[nodiscard]] constexpr T& operator[](int i) noexcept {
    LOCUS_ASSERT(i >= 0 && i < 4, "Vec index out of range");
    return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w));
  }
  [[nodiscard]] constexpr const T& operator[](int i) const noexcept {
    LOCUS_ASSERT(i >= 0 && i < 4, "Vec index out of range");
    return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w));
  }
};

template <Field T>
using Vec2 = Vec<T, 2>;
template <Field T>
using Vec3 = Vec<T, 3>;
template <Field T>
using Vec4 = Vec<T, 4>;
using Vec2f = Vec2<float>;
using Vec3f = Vec3<float>;
using Vec4f = Vec4<float>;
using Vec2d = Vec2<double>;
using Vec3d = Vec3<double>;
using Vec4d = Vec4<double>;

// ---- construction -------------------------------------------------------------------------

/// A vector with every component equal to s.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> splat(T s) noexcept {
  Vec<T, N> r{};
  for (int i = 0; i < N; ++i) r[i] = s;
  return r;
}

/// The i-th unit coordinate vector e_i.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> unit_vec(int i) noexcept {
  Vec<T, N> r{};
  r[i] = T(1);
  return r;
}

/// Component-wise conversion to another scalar type.
template <class U, class T, int N>
[[nodiscard]] constexpr Vec<U, N> vec_cast(const Vec<T, N>& v) noexcept {
  Vec<U, N> r{};
  for (int i = 0; i < N; ++i) r[i] = static_cast<U>(v[i]);
  return r;
}

// ---- arithmetic ---------------------------------------------------------------------------

template <class T, int N>
constexpr Vec<T, N>& operator+=(Vec<T, N>& a, const Vec<T, N>& b) noexcept {
  for (int i = 0; i < N; ++i) a[i] += b[i];
  return a;
}
template <class T, int N>
constexpr Vec<T, N>& operator-=(Vec<T, N>& a, const Vec<T, N>& b) noexcept {
  for (int i = 0; i < N; ++i) a[i] -= b[i];
  return a;
}
template <class T, int N>
constexpr Vec<T, N>& operator*=(Vec<T, N>& a, T s) noexcept {
  for (int i = 0; i < N; ++i) a[i] *= s;
  return a;
}
template <class T, int N>
constexpr Vec<T, N>& operator/=(Vec<T, N>& a, T s) noexcept {
  for (int i = 0; i < N; ++i) a[i] /= s;
  return a;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> operator+(Vec<T, N> a, const Vec<T, N>& b) noexcept {
  return a += b;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> operator-(Vec<T, N> a, const Vec<T, N>& b) noexcept {
  return a -= b;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> operator-(Vec<T, N> a) noexcept {
  for (int i = 0; i < N; ++i) a[i] = -a[i];
  return a;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> operator*(Vec<T, N> a, T s) noexcept {
  return a *= s;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> operator*(T s, Vec<T, N> a) noexcept {
  return a *= s;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> operator/(Vec<T, N> a, T s) noexcept {
  return a /= s;
}
template <class T, int N>
[[nodiscard]] constexpr bool operator==(const Vec<T, N>& a, const Vec<T, N>& b) noexcept {
  for (int i = 0; i < N; ++i)
    if (!(a[i] == b[i])) return false;
  return true;
}

/// Component-wise (Hadamard) product.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> cwise_mul(Vec<T, N> a, const Vec<T, N>& b) noexcept {
  for (int i = 0; i < N; ++i) a[i] *= b[i];
  return a;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> cwise_min(Vec<T, N> a, const Vec<T, N>& b) noexcept {
  for (int i = 0; i < N; ++i) a[i] = b[i] < a[i] ? b[i] : a[i];
  return a;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> cwise_max(Vec<T, N> a, const Vec<T, N>& b) noexcept {
  for (int i = 0; i < N; ++i) a[i] = a[i] < b[i] ? b[i] : a[i];
  return a;
}
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> cwise_abs(Vec<T, N> a) noexcept {
  for (int i = 0; i < N; ++i) a[i] = a[i] < T(0) ? -a[i] : a[i];
  return a;
}
/// The largest absolute component (0 for the zero vector; NaN components are skipped).
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE constexpr T max_abs(const Vec<T, N>& a) noexcept {
  T m = T(0);
  for (int i = 0; i < N; ++i) {
    T v = a[i] < T(0) ? -a[i] : a[i];
    if (m < v) m = v;
  }
  return m;
}

/// Affine combination (1 - t) a + t b; exact at t = 0 and t = 1.
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE constexpr Vec<T, N> lerp(const Vec<T, N>& a, const Vec<T, N>& b,
                                                           T t) noexcept {
  Vec<T, N> r{};
  for (int i = 0; i < N; ++i) r[i] = (T(1) - t) * a[i] + t * b[i];
  return r;
}

/// True when every component is finite.
template <class T, int N>
[[nodiscard]] constexpr bool is_finite(const Vec<T, N>& v) noexcept {
  for (int i = 0; i < N; ++i)
    if (!is_finite(v[i])) return false;
  return true;
}

/// 0 when every component of every argument is finite, NaN otherwise, without a branch: x * 0
/// is +-0 for finite x and NaN for an infinity or a NaN, and a NaN absorbs the sum. Adding it
/// to a result turns the result into NaN for non-finite input; comparing it with 0 tests the
/// whole input with one (well-predicted) branch, where is_finite() on each argument costs two
/// compares and a branch per component.
template <class T, int... N>
[[nodiscard]] constexpr T finite_zero(const Vec<T, N>&... v) noexcept {
  const auto one = []<int M>(const Vec<T, M>& x) {
    T z = x[0] * T(0);
    for (int i = 1; i < M; ++i) z += x[i] * T(0);
    return z;
  };
  return (T(0) + ... + one(v));
}

/// True when every component of every argument is finite: finite_zero(v...) == 0.
template <class T, int... N>
[[nodiscard]] constexpr bool all_finite(const Vec<T, N>&... v) noexcept {
  return finite_zero(v...) == T(0);
}

// ---- products and lengths -----------------------------------------------------------------

template <class T, int N>
[[nodiscard]] constexpr T dot(const Vec<T, N>& a, const Vec<T, N>& b) noexcept {
  T s = a[0] * b[0];
  for (int i = 1; i < N; ++i) s += a[i] * b[i];
  return s;
}
template <class T, int N>
[[nodiscard]] constexpr T sqr_length(const Vec<T, N>& a) noexcept {
  return dot(a, a);
}
/// Euclidean length. Scales by the largest component first when the plain sum of squares
/// would overflow or underflow, so length((1e200, 1e200)) is finite.
template <class T, int N>
[[nodiscard]] LOCUS_ALWAYS_INLINE inline T length(const Vec<T, N>& a) noexcept {
  T s = sqr_length(a);
  if (s > std::numeric_limits<T>::min() && s < std::numeric_limits<T>::max()) return std::sqrt(s);
  T m = max_abs(a);
  if (m == T(0) || !is_finite(m)) return s == s ? m : s;  // 0, inf, or NaN
  // By a power of two (exact): the length of 2^k a is exactly 2^k times that of a.
  const T f = normalising_scale(m);
  return std::sqrt(sqr_length(f * a)) / f;
}

/// A vector and its length, returned by normalize_with_length.
template <class T, int N>
struct Normalized {
  Vec<T, N> dir;
  T length;
};

/// Unit vector along a and the length of a. A zero or non-finite vector gives {0, 0}.
template <class T, int N>
[[nodiscard]] inline Normalized<T, N> normalize_with_length(const Vec<T, N>& a) noexcept {
  // Fast path, one square root: the sum of squares neither overflowed nor lost precision to
  // underflow, so sqrt(s) is the length to within an ulp or so.
  const T s = sqr_length(a);
  if (s >= std::numeric_limits<T>::min() && s <= std::numeric_limits<T>::max()) {
    const T len = std::sqrt(s);
    return {a / len, len};
  }
  // Huge, tiny (subnormal), zero or non-finite: rescale by the largest component first.
  T len = length(a);
  if (!(len > T(0)) || !is_finite(len)) return {Vec<T, N>{}, T(0)};
  const Vec<T, N> scaled = normalising_scale(max_abs(a)) * a;
  return {scaled / length(scaled), len};
}

/// Unit vector along a; the zero vector when a is zero or not finite.
template <class T, int N>
[[nodiscard]] inline Vec<T, N> normalize(const Vec<T, N>& a) noexcept {
  return normalize_with_length(a).dir;
}

/// Cross product a x b (3D); |a x b| = |a||b| sin(angle), right-handed.
template <Field T>
[[nodiscard]] constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// The counter-clockwise perpendicular (-y, x) of a 2D vector.
template <Field T>
[[nodiscard]] constexpr Vec2<T> perp(const Vec2<T>& a) noexcept {
  return {-a.y, a.x};
}
/// Perp-dot product a.x*b.y - a.y*b.x = dot(perp(a), b): twice the signed area of (0, a, b).
template <Field T>
[[nodiscard]] constexpr T perp_dot(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return a.x * b.y - a.y * b.x;
}

}  // namespace locus
