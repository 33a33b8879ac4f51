// SPDX-License-Identifier: BSL-1.0
#pragma once
// Accurate values behind the crossing of two linear components (row core.predicates; used by
// the intersection area, rows int2.linear and int2.linear-polyline; book section 7.1).
//
// turn2d_value(a, b, c, d) is det[b - a; d - c] (the quantity whose exact sign is turn2d() in
// predicates.hpp) rounded from its exact value: the four 2x2 minors of the raw coordinates are
// formed in expansion arithmetic (src/core/crossing.cpp), so no difference rounds first, and
// the exact sum is compressed and rounded once. Relative error below 2 eps (double eps) for
// double input, and the sign is always turn2d()'s. Float input is promoted exactly.
// Why: the parameter of a crossing is a ratio of two such determinants; when the two components
// cross at a tiny angle, or a point lies near a line, the naive determinants lose every digit to
// cancellation while these keep them (docs/notes/intersection.md).
//
// Range: exact products need every nonzero product of two coordinates above 2^-969 in magnitude
// and every coordinate below 2^510; outside it the result is still finite or NaN, never a hang.
// A NaN or infinite coordinate gives NaN. Cost: about 100 flops; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

namespace locus {

namespace detail {
/// det[b - a; d - c] rounded from the exact value (compiled in src/core/crossing.cpp).
[[nodiscard]] double turn2d_value_accurate(const Vec2<double>& a, const Vec2<double>& b,
                                           const Vec2<double>& c, const Vec2<double>& d) noexcept;
}  // namespace detail

/// det[b - a; d - c] = perp_dot(b - a, d - c), relative error below 2 eps (see the header).
template <Real T>
[[nodiscard]] inline double turn2d_value(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c,
                                         const Vec2<T>& d) noexcept {
  return detail::turn2d_value_accurate(vec_cast<double>(a), vec_cast<double>(b),
                                       vec_cast<double>(c), vec_cast<double>(d));
}

}  // namespace locus
