// SPDX-License-Identifier: BSL-1.0
#pragma once
// The spatial sort of the library: an insertion order for incremental algorithms (Delaunay 2D and
// 3D) in which consecutive points are near each other and early points spread over the domain.
//
// hilbert_index2 / hilbert_index3: the position of a grid cell along the Hilbert curve (2D by
// two-level table lookup; 3D by Skilling's transposed-index transform, "Programming the Hilbert
// curve", 2004). brio_order: biased randomized insertion order (Amenta, Choi, Rote 2003) with
// Hilbert-sorted rounds. Point i joins round r = brio_round(i, rounds) (0 = first inserted),
// decided by a fixed hash of i: the last round holds about 7/8 of the points, the one before
// 7/64, and so on, until about 256 points remain (the first round). Each round is sorted along
// the Hilbert curve of a grid over the bounding box (about 16 cells per point in 2D, 8 in 3D;
// at most 2^16 resp. 2^10 per axis), ties in index order. Deterministic: the same points give
// the same order, on every platform.
//
// Input: finite coordinates (the callers check; a non-finite one lands in an unspecified cell
// but the result is still a permutation). Cost: O(n) hashing and quantisation plus LSD radix
// passes of at most 12 bits (std::sort below 2^14 points); no allocation when the vectors passed
// in already have the capacity. Compiled once for float and double (src/core/spatial_sort.cpp).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace locus::detail {

/// Position along the 2D Hilbert curve of order `levels` (1..16) of the cell (x, y) < 2^levels.
[[nodiscard]] std::uint32_t hilbert_index2(std::uint32_t x, std::uint32_t y, int levels) noexcept;

/// Position along the 3D Hilbert curve of order `levels` (1..10) of the cell x0, x1, x2 < 2^levels.
[[nodiscard]] std::uint32_t hilbert_index3(std::uint32_t x0, std::uint32_t x1, std::uint32_t x2,
                                           int levels) noexcept;

/// The number of BRIO rounds for n points: the smallest r >= 1 with n / 8^r <= 256 (at most 21).
[[nodiscard]] unsigned brio_rounds(std::size_t n) noexcept;

/// The round of point i (0 = inserted first) when there are `rounds` rounds: rounds - 1 - j,
/// j = min(leading zero bits of hash(i) / 3, rounds - 1), so round rounds - 1 - j holds a
/// fraction 7/8 * 8^-j of the points (the first round the rest).
[[nodiscard]] unsigned brio_round(std::size_t i, unsigned rounds) noexcept;

/// Writes to `order` the BRIO insertion order of the points (a permutation of 0 .. n-1): rounds
/// in increasing brio_round, each in Hilbert order. keys and tmp are scratch (reused storage).
template <Real T>
void brio_order(std::span<const Vec2<T>> points, std::vector<std::uint32_t>& order,
                std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& tmp);
template <Real T>
void brio_order(std::span<const Vec3<T>> points, std::vector<std::uint32_t>& order,
                std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& tmp);

extern template void brio_order<float>(std::span<const Vec2<float>>, std::vector<std::uint32_t>&,
                                       std::vector<std::uint64_t>&, std::vector<std::uint64_t>&);
extern template void brio_order<double>(std::span<const Vec2<double>>, std::vector<std::uint32_t>&,
                                        std::vector<std::uint64_t>&, std::vector<std::uint64_t>&);
extern template void brio_order<float>(std::span<const Vec3<float>>, std::vector<std::uint32_t>&,
                                       std::vector<std::uint64_t>&, std::vector<std::uint64_t>&);
extern template void brio_order<double>(std::span<const Vec3<double>>, std::vector<std::uint32_t>&,
                                        std::vector<std::uint64_t>&, std::vector<std::uint64_t>&);

}  // namespace locus::detail
