// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a (solid) rectangle in 2D and 3D; rows dist2.pt-rectangle and
// dist3.pt-rectangle; book sections 6.1.4 (figure 6.10) and 10.3.3 (figures 10.11-10.13).
//
// distance(p, rect) returns Distance<T, N, NoParam, Vec2<T>>: closest[1] = point_at(rect, st)
// with st = param_b = (s, t), the rectangle's symmetric coordinates (|s| <= extent[0],
// |t| <= extent[1]; primitives/rectangle.hpp). distance(rect, p) is the swapped result.
// The rectangle is filled: a point inside (2D) or above the inside (3D) projects into it.
//
// Method: s = clamp((p - center) . axis[0], -extent[0], extent[0]), t likewise: the nine regions
// of figure 6.10 (inside, four edge strips, four corner quadrants) are exactly the nine
// combinations of "clamped low / not clamped / clamped high", so no region code is needed, and
// corners are reproduced as point_at of the clamped coordinates.
//
// Preconditions and degenerate input: the axes are unit and orthogonal (the rectangle's
// contract, not checked). A zero extent gives a segment or a point (the clamp then gives 0); a
// negative extent is treated as 0. NaN or infinite values give non_finite_distance()
// (result.hpp). unique is always true. Cost: O(N), no division.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/rectangle.hpp>

namespace locus {

/// Distance from p to the filled rectangle; param_b = (s, t) with closest[1] = point_at(rect, st).
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, Vec2<T>> distance(
    const Vec<T, N>& p, const Rectangle<T, N>& rect) noexcept {
  if (!is_finite(p) || !is_finite(rect.center) || !is_finite(rect.axis[0]) ||
      !is_finite(rect.axis[1]) || !is_finite(rect.extent[0]) || !is_finite(rect.extent[1]))
    return non_finite_distance<T, N, NoParam, Vec2<T>>();
  const Vec<T, N> d = p - rect.center;
  Vec2<T> st{};
  for (int i = 0; i < 2; ++i) {
    const T e = rect.extent[i] > T(0) ? rect.extent[i] : T(0);
    st[i] = clamp(dot(d, rect.axis[i]), -e, e);
  }
  return detail::make_distance(p, point_at(rect, st), NoParam{}, st, true);
}

/// The swapped query: closest[0] and param_a belong to the rectangle.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, Vec2<T>, NoParam> distance(const Rectangle<T, N>& rect,
                                                               const Vec<T, N>& p) noexcept {
  return swapped(distance(p, rect));
}

}  // namespace locus
