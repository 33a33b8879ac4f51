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
// unique is always true. Cost: O(N), no branch on the data, N divisions for the box
// coordinates, one square root.
//
// sqr_distance(p, box) (either order) returns distance(p, box).sqr_distance, bit for bit, without
// the closest point, the box coordinates or the square root: 2 N min/max operations and N
// multiply-adds, branch-free; NaN for non-finite input or an empty box.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/branchless.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <cmath>
#include <limits>

namespace locus {

namespace detail {

/// The clamp of p to the box and the squared distance to it (finite, non-empty box assumed; the
/// two-statement clamp compiles to a max and a min instruction).
template <class T, int N>
struct PointAlignedBoxCore {
  Vec<T, N> closest;
  T sqr;
};
template <class T, int N>
[[nodiscard]] constexpr PointAlignedBoxCore<T, N> point_aligned_box(
    const Vec<T, N>& p, const AlignedBox<T, N>& box) noexcept {
  PointAlignedBoxCore<T, N> r{};
  for (int i = 0; i < N; ++i) {
    const T lo = box.min[i], hi = box.max[i];
    const T above = p[i] < lo ? lo : p[i];
    r.closest[i] = hi < above ? hi : above;  // clamp(p[i], lo, hi)
    r.sqr += sqr(p[i] - r.closest[i]);
  }
  return r;
}

template <class T, int N>
[[nodiscard]] constexpr bool any_empty_axis(const AlignedBox<T, N>& box) noexcept {
  bool empty = false;
  for (int i = 0; i < N; ++i) empty |= box.max[i] < box.min[i];
  return empty;
}

}  // namespace detail

/// Distance from p to the solid box; param_b is the closest point's box coordinates in [0, 1]^N.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, Vec<T, N>> distance(
    const Vec<T, N>& p, const AlignedBox<T, N>& box) noexcept {
  if (!all_finite(p, box.min, box.max) || detail::any_empty_axis(box))
    return non_finite_distance<T, N, NoParam, Vec<T, N>>();
  const detail::PointAlignedBoxCore<T, N> r = detail::point_aligned_box(p, box);
  Vec<T, N> u{};
  for (int i = 0; i < N; ++i) {
    const T w = box.max[i] - box.min[i];
    // w > 0: the quotient is in [0, 1] already (c in [min, max], correctly rounded division).
    u[i] = detail::select(w > T(0), (r.closest[i] - box.min[i]) / w, T(0));
  }
  return {length(p - r.closest), r.sqr, {p, r.closest}, NoParam{}, u, true};
}

/// The swapped query: closest[0] and param_a belong to the box.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, Vec<T, N>, NoParam> distance(const AlignedBox<T, N>& box,
                                                                 const Vec<T, N>& p) noexcept {
  return swapped(distance(p, box));
}

/// Squared distance from p to the solid box: distance(p, box).sqr_distance (the same bits), with
/// no branch, no closest point, no box coordinates and no square root; NaN for non-finite input
/// or an empty box.
template <Real T, int N>
[[nodiscard]] inline T sqr_distance(const Vec<T, N>& p, const AlignedBox<T, N>& box) noexcept {
  return detail::select(detail::any_empty_axis(box), std::numeric_limits<T>::quiet_NaN(),
                        detail::point_aligned_box(p, box).sqr + finite_zero(p, box.min, box.max));
}

/// sqr_distance(p, box).
template <Real T, int N>
[[nodiscard]] inline T sqr_distance(const AlignedBox<T, N>& box, const Vec<T, N>& p) noexcept {
  return sqr_distance(p, box);
}

}  // namespace locus
