// SPDX-License-Identifier: BSL-1.0
#pragma once
// Scalar helpers shared by every module.
//
// locus works on T = float or double. compute_t<T> is the type delicate internals (root finders,
// eigensolvers) compute in: double for float input, T otherwise; every header that promotes says
// so in its top comment.

#include <cmath>
#include <concepts>
#include <limits>
#include <type_traits>

namespace locus {

/// The scalar types locus algorithms accept.
template <class T>
concept Real = std::is_same_v<T, float> || std::is_same_v<T, double>;

/// The coefficient types of the few value types that are exact-safe (Polynomial): any type with
/// field arithmetic, so that tests can instantiate them with rationals. Everything else takes
/// Real; `class T` is kept for parameters that are not scalars (point and range types).
template <class T>
concept Field = requires(T a, T b) {
  { a + b } -> std::convertible_to<T>;
  { a - b } -> std::convertible_to<T>;
  { a* b } -> std::convertible_to<T>;
  { a / b } -> std::convertible_to<T>;
  { a < b } -> std::convertible_to<bool>;
  T(0);
};

/// The internal computation type for numerically delicate code: double for float, else T.
template <Field T>
using compute_t = std::conditional_t<std::is_same_v<T, float>, double, T>;

/// Machine epsilon of T (distance from 1 to the next representable value).
template <Field T>
inline constexpr T eps_v = std::numeric_limits<T>::epsilon();

template <Field T>
inline constexpr T pi_v = static_cast<T>(3.14159265358979323846264338327950288L);

template <Field T>
[[nodiscard]] constexpr T sqr(T x) noexcept {
  return x * x;
}

/// True when x is neither NaN nor infinite (usable in constexpr contexts).
template <Field T>
[[nodiscard]] constexpr bool is_finite(T x) noexcept {
  return x == x && x - x == T(0);
}

template <Field T>
[[nodiscard]] constexpr T clamp(T x, T lo, T hi) noexcept {
  return x < lo ? lo : (hi < x ? hi : x);
}

/// The power of two f with m f in [1, 2), for a finite m > 0 (f stays within the range of T, so
/// at the ends of the range m f may fall short of 1 or reach 4); 1 for m = 0 or a non-finite m.
/// Scaling by f is exact while the scaled values stay normal: algorithms whose answer is
/// invariant under scaling use it to bring extreme input to magnitudes near 1.
template <Field T>
[[nodiscard]] inline T normalising_scale(T m) noexcept {
  if (!(m > T(0)) || !(m <= std::numeric_limits<T>::max())) return T(1);
  int e = 0;  // m = x 2^e with x in [0.5, 1)
  static_cast<void>(std::frexp(m, &e));
  constexpr int lo = std::numeric_limits<T>::min_exponent - 1;  // 2^lo: the smallest normal
  constexpr int hi = std::numeric_limits<T>::max_exponent - 1;  // 2^hi: the largest power of 2
  const int k = 1 - e;
  return std::ldexp(T(1), k < lo ? lo : (k > hi ? hi : k));
}

}  // namespace locus
