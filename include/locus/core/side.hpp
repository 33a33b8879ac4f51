// SPDX-License-Identifier: BSL-1.0
#pragma once
// Side: where a point lies relative to a region (polygon, polyhedron, circle, half-space), the
// result of every classify(p, region). The enumerators are ordered outside < boundary < inside
// with boundary = 0, so a side compares and negates like a sign.

#include <cstdint>

namespace locus {

/// Where a point lies relative to a region (polygon, polyhedron, circle, half-space).
enum class Side : std::int8_t { outside = -1, boundary = 0, inside = 1 };

}  // namespace locus
