// SPDX-License-Identifier: BSL-1.0
#pragma once
// Batched 2D segment - segment intersection: many pairs in one call, four per SIMD instruction
// (row int2.linear; the per-pair function is intersection() in segment_segment.hpp).
//
// intersections(a, b, out) sets out[i] = intersection(a[i], b[i]) for every i: the same kind,
// count, point and parameters, bit for bit, for every input (the same exact decisions and the
// same accuracy bound, segment_segment.hpp), when the caller's code is compiled without
// floating-point contraction (the default on x86-64 unless FMA is enabled, e.g. by -march=native;
// as for the batched distances, distance/batch.hpp). The spans must have the same length
// (LOCUS_ASSERT; with assertions off, the shortest length is processed).
// How: the SIMD kernel (src/intersection/batch_segment2.cpp) evaluates the four filtered end point
// sides, the exact side values where a filter fails, the decision and the construction's tiers in
// the lanes of one register, as the per-pair code does; a lane the lanes cannot finish (touching,
// collinear, degenerate, non-finite or extreme input, side values needing the exact expansion)
// is recomputed by intersection(). On x86-64 the kernel is compiled for x86-64-v4, AVX2 and the
// baseline and picked at each call like the batched distances (detail::batch_isa()). Float pairs
// are computed by the per-pair function (in double, as it does). Throughput:
// bench/results/intersection2.md. No allocation; noexcept.

#include <locus/intersection/segment_segment.hpp>

#include <span>

namespace locus {

/// out[i] = intersection(a[i], b[i]) (see the header comment).
void intersections(std::span<const Segment2<double>> a, std::span<const Segment2<double>> b,
                   std::span<LinearIntersection2<double>> out) noexcept;
/// out[i] = intersection(a[i], b[i]), per pair.
void intersections(std::span<const Segment2<float>> a, std::span<const Segment2<float>> b,
                   std::span<LinearIntersection2<float>> out) noexcept;

}  // namespace locus
