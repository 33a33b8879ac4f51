// SPDX-License-Identifier: BSL-1.0
#pragma once
// Branch-free scalar selection for the distance fast paths (point-triangle, segment-segment,
// point-box, segment-triangle).
//
// Why: which region of a query's parameter domain holds the answer (inside a triangle, beyond an
// edge, near a vertex) is unpredictable on mixed input, and a mispredicted branch costs about as
// much as a whole point-triangle query. So the fast paths compute every arm they may need (a few
// multiplies) and pick with select() or with single-comparison conditionals `a < b ? x : y` on
// values already computed, which compilers emit as compare-and-blend (or min/max) instructions.
// select() is the plain conditional, not a bitwise blend through integer registers: moving each
// value to a general-purpose register and back costs more than it saves (measured:
// bench/results/distance.md).

#include <locus/core/scalar.hpp>

namespace locus::detail {

/// c ? x : y (see above for why this is not a hand-made bitwise blend).
template <Real T>
[[nodiscard]] constexpr T select(bool c, T x, T y) noexcept {
  return c ? x : y;
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
