// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a (solid) axis-aligned box in N dimensions (2D rectangle, 3D
// box); rows dist2.pt-rectangle and dist3.pt-obb (AABB part); book section 10.4.1 (figures 10.21,
// 10.22), the axis-aligned case of 6.1.4.
//
// distance(p, box) returns Distance<T, N, NoParam, Vec<T, N>>: closest[1] = the component-wise
// clamp of p to [min, max] (exact: every coordinate is either p's or a bound), param_b = its
// box coordinates in [0, 1]^N, so closest[1] ~ point_at(box, param_b) (aligned_box.hpp; equal up
// to the rounding of that lerp; a zero-width axis has coordinate 0). distance(box, p) is the
// swapped result. The box is solid: a point inside has distance 0 and is its own closest point.
//
// The squared distance is the sum over the axes of the squared excess outside [min, max]; every
// term is computed from p and one bound, so the result is accurate to a few ulps.
//
// Degenerate input: a flat box (min[i] == max[i]) is a lower-dimensional box, handled the same
// way. An empty box (min[i] > max[i] for some i, including empty_box()) has no points, and NaN
// or infinite values have no meaning: both give non_finite_distance() (NaN, result.hpp).
// unique is always true. Cost: O(N), no square root besides the final one.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/aligned_box.hpp>

namespace locus {

/// Distance from p to the solid box; param_b is the closest point's box coordinates in [0, 1]^N.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, Vec<T, N>> distance(
    const Vec<T, N>& p, const AlignedBox<T, N>& box) noexcept {
  if (!is_finite(p) || !is_finite(box.min) || !is_finite(box.max) || is_empty(box))
    return non_finite_distance<T, N, NoParam, Vec<T, N>>();
  Vec<T, N> c{}, u{};
  for (int i = 0; i < N; ++i) {
    c[i] = clamp(p[i], box.min[i], box.max[i]);
    const T w = box.max[i] - box.min[i];
    u[i] = w > T(0) ? clamp((c[i] - box.min[i]) / w, T(0), T(1)) : T(0);
  }
  return detail::make_distance(p, c, NoParam{}, u, true);
}

/// The swapped query: closest[0] and param_a belong to the box.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, Vec<T, N>, NoParam> distance(const AlignedBox<T, N>& box,
                                                                 const Vec<T, N>& p) noexcept {
  return swapped(distance(p, box));
}

}  // namespace locus
