// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a (solid) oriented box in N dimensions (2D oriented rectangle,
// 3D OBB); rows dist2.pt-rectangle and dist3.pt-obb; book sections 6.1.4 (figure 6.10) and
// 10.4.2 (figures 10.21, 10.22).
//
// distance(p, box) returns Distance<T, N, NoParam, Vec<T, N>>: param_b = s in [-1, 1]^N, the
// box's symmetric coordinates (oriented_box.hpp), closest[1] = point_at(box, s) =
// center + sum s[i] extent[i] axis[i]. distance(box, p) is the swapped result. The box is solid.
//
// Method: in the box's frame the query is the aligned one: x[i] = (p - center) . axis[i] is
// clamped to [-extent[i], extent[i]]; s[i] = clamped / extent[i]. The squared distance is taken
// between p and the reconstructed closest point (so |closest[0] - closest[1]| = distance).
//
// Preconditions and degenerate input: the axes are unit and mutually orthogonal (the box's
// contract, not checked). A zero extent flattens the box along that axis (s[i] = 0); a negative
// extent is treated as 0. NaN or infinite values give non_finite_distance() (result.hpp).
// unique is always true. Cost: O(N^2).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/oriented_box.hpp>

namespace locus {

/// Distance from p to the solid oriented box; param_b = s in [-1, 1]^N.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, NoParam, Vec<T, N>> distance(
    const Vec<T, N>& p, const OrientedBox<T, N>& box) noexcept {
  bool finite = is_finite(p) && is_finite(box.center) && is_finite(box.extent);
  for (int i = 0; i < N; ++i) finite = finite && is_finite(box.axis[i]);
  if (!finite) return non_finite_distance<T, N, NoParam, Vec<T, N>>();
  const Vec<T, N> d = p - box.center;
  Vec<T, N> s{};
  for (int i = 0; i < N; ++i) {
    const T e = box.extent[i];
    if (!(e > T(0))) continue;
    s[i] = clamp(dot(d, box.axis[i]) / e, T(-1), T(1));
  }
  return detail::make_distance(p, point_at(box, s), NoParam{}, s, true);
}

/// The swapped query: closest[0] and param_a belong to the box.
template <Real T, int N>
[[nodiscard]] inline Distance<T, N, Vec<T, N>, NoParam> distance(const OrientedBox<T, N>& box,
                                                                 const Vec<T, N>& p) noexcept {
  return swapped(distance(p, box));
}

}  // namespace locus
