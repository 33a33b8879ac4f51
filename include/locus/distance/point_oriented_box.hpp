// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a (solid) oriented box in N dimensions (2D oriented rectangle,
// 3D OBB); rows dist2.pt-rectangle and dist3.pt-obb; book sections 6.1.4 (figure 6.10) and
// 10.4.2 (figures 10.21, 10.22). Error analysis for rounded axes: docs/notes/distance.md.
//
// distance(p, box) returns Distance<T, N, NoParam, Vec<T, N>>: param_b = s in [-1, 1]^N, the
// box's symmetric coordinates (oriented_box.hpp), closest[1] ~ point_at(box, s) =
// center + sum s[i] extent[i] axis[i]. distance(box, p) is the swapped result. The box is solid.
// In the box's frame the query is the aligned one (x[i] = (p - center) . axis[i] clamped to
// [-extent[i], extent[i]]): a point inside has distance exactly 0 and is its own closest point,
// and the error is a few ulps of |p - center| (not of |center|); closest[1] = p minus the excess
// mapped back and scaled to the length distance, so |closest[0] - closest[1]| = distance to a
// few ulps even when the stored axes are orthonormal only to rounding.
//
// Preconditions and degenerate input: the axes are unit and mutually orthogonal up to rounding
// (the box's contract, not checked). A zero extent flattens the box along that axis (s[i] = 0);
// a negative extent is treated as 0. NaN or infinite values give non_finite_distance()
// (result.hpp), and so does finite input so large that a coordinate in the box frame overflows.
// unique is always true. Cost: O(N^2), no branch on the data; distance() takes two square roots
// and N + 1 divisions.
//
// sqr_distance(p, box) (either order) returns distance(p, box).sqr_distance, bit for bit, without
// the closest point, the parameters or the square root: N dot products, N min/max pairs, no
// division, branch-free; NaN for non-finite input.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/branchless.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/oriented_box.hpp>

#include <cmath>
#include <limits>

namespace locus {

namespace detail {

/// In the box's frame: the clamped coordinates and the squared distance (the sum of the squared
/// excesses over the slabs), meaningful for finite input, which finite_zero tells.
template <class T, int N>
struct PointOrientedBoxCore {
  Vec<T, N> clamped;  ///< x[i] clamped to [-extent[i], extent[i]] (negative extents as 0)
  Vec<T, N> excess;   ///< x[i] - clamped[i]
  Vec<T, N> extent;   ///< max(extent[i], 0)
  T sqr;              ///< sqr_length(excess)
  /// 0 when the input is finite, NaN otherwise (or when a frame coordinate overflows): the sum of
  /// x[i] 0 and extent[i] 0 over i. The frame coordinates stand in for p, the center and the
  /// axes: a NaN or an infinity in any of them makes some x[i] NaN or infinite (an infinite
  /// coordinate of p - center times an axis component is infinite, or NaN for a zero one). That
  /// is 2 N products instead of one per input value, N (N + 3): a per-value test would be half
  /// of sqr_distance's work.
  T finite_zero;
};
template <class T, int N>
[[nodiscard]] constexpr PointOrientedBoxCore<T, N> point_oriented_box(
    const Vec<T, N>& p, const OrientedBox<T, N>& box) noexcept {
  PointOrientedBoxCore<T, N> r{};
  const Vec<T, N> d = p - box.center;
  for (int i = 0; i < N; ++i) {
    const T x = dot(d, box.axis[i]);
    const T e = select(box.extent[i] > T(0), box.extent[i], T(0));
    const T ne = -e;
    const T above = x < ne ? ne : x;
    r.clamped[i] = e < above ? e : above;
    r.extent[i] = e;
    r.excess[i] = x - r.clamped[i];
    r.finite_zero += x * T(0);
  }
  r.finite_zero += locus::finite_zero(box.extent);
  r.sqr = sqr_length(r.excess);
  return r;
}

}  // namespace detail

/// Distance from p to the solid oriented box; param_b = s in [-1, 1]^N.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, Vec<T, N>> distance(
    const Vec<T, N>& p, const OrientedBox<T, N>& box) noexcept {
  const detail::PointOrientedBoxCore<T, N> r = detail::point_oriented_box(p, box);
  if (!(r.finite_zero == T(0))) return non_finite_distance<T, N, NoParam, Vec<T, N>>();
  Vec<T, N> s{}, v{};
  for (int i = 0; i < N; ++i) {
    s[i] = detail::select(r.extent[i] > T(0), r.clamped[i] / r.extent[i], T(0));
    v += r.excess[i] * box.axis[i];
  }
  // |v| = |excess| only for exactly orthonormal axes; rounded ones (Gram matrix I + G, |G| a few
  // to tens of eps) make them differ by ~|G| |excess|. Scaling v to the measured length keeps
  // |closest[0] - closest[1]| = distance to a few ulps; the point moves by the same ~|G| |excess|
  // that already separates p - v from point_at(box, s).
  const T dist = length(r.excess), lv = length(v);
  const Vec<T, N> c = p - detail::select(lv > T(0), dist / lv, T(1)) * v;
  return {dist, r.sqr, {p, c}, NoParam{}, s, true};
}

/// The swapped query: closest[0] and param_a belong to the box.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, Vec<T, N>, NoParam> distance(const OrientedBox<T, N>& box,
                                                                 const Vec<T, N>& p) noexcept {
  return swapped(distance(p, box));
}

/// Squared distance from p to the solid oriented box: distance(p, box).sqr_distance (the same
/// bits), with no branch, no closest point, no parameters and no square root; NaN for non-finite
/// input.
template <Real T, int N>
[[nodiscard]] inline T sqr_distance(const Vec<T, N>& p, const OrientedBox<T, N>& box) noexcept {
  const detail::PointOrientedBoxCore<T, N> r = detail::point_oriented_box(p, box);
  return r.sqr + r.finite_zero;
}

/// sqr_distance(p, box).
template <Real T, int N>
[[nodiscard]] inline T sqr_distance(const OrientedBox<T, N>& box, const Vec<T, N>& p) noexcept {
  return sqr_distance(p, box);
}

}  // namespace locus
