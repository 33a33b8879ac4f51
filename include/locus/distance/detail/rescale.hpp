// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internal: running a distance query's solver on a copy of its input scaled by a power of two.
//
// The solvers form products of up to four coordinates (|dA x dB|^2, a c, Cramer's determinants;
// more for the polynomial ones). Squares of coordinates stay in range for magnitudes between
// ~1e-154 and ~1e154 (double), but products of four overflow above ~1e77 and underflow below
// ~1e-77:
// a triangle or a pair of segments with coordinates of 1e-100 has determinant 0, and the solver
// would take it for a degenerate one. The parameters the solvers return (barycentric
// coordinates, segment and line parameters) are dimensionless, so a solver can run on the input
// scaled by the power of two that brings its largest coordinate into [1, 2) (normalising_scale,
// core/scalar.hpp). That is exact: no coordinate is rounded, except ones that fall below the
// normal range of the scaled copy, which are negligible against the largest. The caller then
// evaluates the closest points and the squared distance from those parameters on the ORIGINAL
// input, so they are the unscaled query's.

#include <locus/core/scalar.hpp>

#include <limits>

namespace locus::detail {

/// Whether products of `degree` coordinates of magnitude up to m may leave the range of T (or
/// lose precision below the normal range): m outside [2^-k, 2^k] with k = (E - 8) / degree and E
/// the largest exponent (degree 4: double k = 254, about 3.4e-77 .. 2.9e76; float k = 30, about
/// 9.3e-10 .. 1.1e9).
template <class T, int degree = 4>
[[nodiscard]] constexpr bool outside_product_range(T m) noexcept {
  constexpr T hi = [] {
    T h = T(1);
    for (int i = 0; i < (std::numeric_limits<T>::max_exponent - 8) / degree; ++i) h *= T(2);
    return h;
  }();
  return !(m <= hi && m >= T(1) / hi);
}

}  // namespace locus::detail
