// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal: running a distance query's solver on a copy of its input scaled by a power of two.
//
// The solvers form products of up to four coordinates (|dA x dB|^2, a c, Cramer's determinants).
// Squares of coordinates stay in range for magnitudes between ~1e-154 and ~1e154 (double; ~1e-19
// and ~1e19 for float), but products of four overflow above ~1e77 and underflow below ~1e-77:
// a triangle or a pair of segments with coordinates of 1e-100 has determinant 0, and the solver
// would take it for a degenerate one. The parameters the solvers return (barycentric
// coordinates, segment and line parameters) are dimensionless, so a solver can run on the input
// scaled by a power of two f that brings its largest coordinate into [1, 2) (exact: no
// coordinate is rounded, except ones below the subnormal range of the scaled copy, which are
// negligible against the largest), and the caller evaluates its closest points and squared
// distance from those parameters on the ORIGINAL input, so they are the unscaled query's.

#include <locus/core/vec.hpp>

#include <cmath>
#include <limits>

namespace locus::detail {

/// The power of two f with m f in [1, 2) for a finite m > 0 (within the normal range of T: at
/// the ends of the range m f may fall short of 1 or reach 4); 1 for m = 0 or a non-finite m.
template <class T>
[[nodiscard]] inline T normalising_scale(T m) noexcept {
  if (!(m > T(0)) || !(m <= std::numeric_limits<T>::max())) return T(1);
  int e = 0;
  static_cast<void>(std::frexp(m, &e));  // m = x 2^e, x in [0.5, 1)
  int k = 1 - e;
  constexpr int lo = std::numeric_limits<T>::min_exponent - 1;  // 2^lo: the smallest normal
  constexpr int hi = std::numeric_limits<T>::max_exponent - 1;  // 2^hi: the largest power of 2
  k = k < lo ? lo : (k > hi ? hi : k);
  return std::ldexp(T(1), k);
}

/// Whether products of four coordinates of magnitude up to m may leave the range of T (or lose
/// precision below the normal range): m outside [2^-(E - 8) / 4, 2^(E - 8) / 4] with E the
/// exponent range (double: ~1e-76 .. 1e76, float: ~1e-9 .. 1e9).
template <class T>
[[nodiscard]] constexpr bool outside_product_range(T m) noexcept {
  constexpr T hi = [] {
    T h = T(1);
    for (int i = 0; i < (std::numeric_limits<T>::max_exponent - 8) / 4; ++i) h *= T(2);
    return h;
  }();
  return !(m <= hi && m >= T(1) / hi);
}

}  // namespace locus::detail
