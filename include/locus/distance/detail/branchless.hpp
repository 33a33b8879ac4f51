// SPDX-License-Identifier: BSL-1.0
#pragma once
// Branch-free scalar selection for the distance fast paths (point-triangle, segment-segment,
// point-box, segment-triangle).
//
// Why: which region of a query's parameter domain holds the answer (inside a triangle, beyond an
// edge, near a vertex) is unpredictable on mixed input, and a mispredicted branch costs about as
// much as a whole point-triangle query. Compilers turn `c ? x : y` on floating-point values
// into branches whenever the arms are more than a move, so the fast paths compute every arm
// they may need (a few multiplies) and pick with select(), which is a bitwise blend the
// optimiser keeps as such, or with single-comparison conditionals `a < b ? x : y` on values
// already computed, which compile to blends (compare, and, and-not, or) as well.

#include <locus/core/scalar.hpp>

#include <bit>
#include <cstdint>
#include <type_traits>

namespace locus::detail {

/// c ? x : y, computed as a bitwise blend (no branch).
template <Real T>
[[nodiscard]] constexpr T select(bool c, T x, T y) noexcept {
  using U = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  const U m = U(0) - static_cast<U>(c);
  return std::bit_cast<T>(static_cast<U>((std::bit_cast<U>(x) & m) | (std::bit_cast<U>(y) & ~m)));
}

/// clamp(x, lo, hi) for lo <= hi, written as the two IEEE max/min idioms that compile to one
/// instruction each. Compilers keep branches for a bound that is a constant 0, so fast paths
/// pass computed bounds (zero = a - a for a finite a).
template <Real T>
[[nodiscard]] constexpr T clamp_minmax(T x, T lo, T hi) noexcept {
  const T above = x < lo ? lo : x;
  return hi < above ? hi : above;
}

}  // namespace locus::detail
