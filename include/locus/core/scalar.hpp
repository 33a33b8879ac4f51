// SPDX-License-Identifier: BSL-1.0
#pragma once
// Scalar helpers shared by every module.
//
// locus works on T = float or double. compute_t<T> is the type delicate internals (root finders,
// eigensolvers) compute in: double for float input, T otherwise; every header that promotes says
// so in its top comment.

#include <cmath>
#include <limits>
#include <type_traits>

namespace locus {

/// The scalar types locus algorithms accept.
template <class T>
concept Real = std::is_same_v<T, float> || std::is_same_v<T, double>;

/// The internal computation type for numerically delicate code: double for float, else T.
template <class T>
using compute_t = std::conditional_t<std::is_same_v<T, float>, double, T>;

/// Machine epsilon of T (distance from 1 to the next representable value).
template <class T>
inline constexpr T eps_v = std::numeric_limits<T>::epsilon();

template <class T>
inline constexpr T pi_v = static_cast<T>(3.14159265358979323846264338327950288L);

template <class T>
[[nodiscard]] constexpr T sqr(T x) noexcept {
  return x * x;
}

/// True when x is neither NaN nor infinite (usable in constexpr contexts).
template <class T>
[[nodiscard]] constexpr bool is_finite(T x) noexcept {
  return x == x && x - x == T(0);
}

template <class T>
[[nodiscard]] constexpr T clamp(T x, T lo, T hi) noexcept {
  return x < lo ? lo : (hi < x ? hi : x);
}

}  // namespace locus
