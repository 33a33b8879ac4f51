// SPDX-License-Identifier: BSL-1.0
#pragma once
// The relation of two discs or balls (centres c0, c1, radii r0, r1) from two exact signs: one
// home for the mapping shared by circle_circle.hpp (conic2.cpp) and sphere_sphere.hpp
// (quadric_pair3.cpp). out = sign(|c1 - c0|^2 - (r0 + r1)^2), in = sign(|c1 - c0|^2 -
// (r0 - r1)^2); equal regions (same centre and radius) are the caller's case, decided first.

#include <locus/intersection/result.hpp>

namespace locus::detail {

[[nodiscard]] constexpr RegionRelation ball_relation(int out, int in, bool a_larger) noexcept {
  if (out > 0) return RegionRelation::separated;
  if (out == 0) return RegionRelation::touching;
  if (in < 0) return a_larger ? RegionRelation::a_contains_b : RegionRelation::b_contains_a;
  if (in == 0)
    return a_larger ? RegionRelation::a_contains_b_touching : RegionRelation::b_contains_a_touching;
  return RegionRelation::overlapping;
}

}  // namespace locus::detail
