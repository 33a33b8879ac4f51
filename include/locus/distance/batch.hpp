// SPDX-License-Identifier: BSL-1.0
#pragma once
// Batched squared distances: many queries of one pair type in one call, several per SIMD
// instruction (rows dist3.pt-triangle, dist3.linear-linear, dist3.linear-triangle, dist3.pt-obb;
// the per-query functions are in the pair headers).
//
// sqr_distances(a, b, out) sets out[i] = sqr_distance(a[i], b[i]) for every i, for the pairs
//   point - triangle, segment - segment, segment - triangle, point - aligned box and
//   point - oriented box (3D, float and double),
// either as two spans of equal length (query i pairs a[i] with b[i]) or as a span and one object
// (every element against the same triangle, segment or box: the "one against many" form, e.g.
// a point cloud against one triangle). Both argument orders are offered; out.size() must equal
// the number of queries (LOCUS_ASSERT; with assertions off, min of the sizes is processed).
//
// Results: out[i] is EXACTLY the value sqr_distance(a[i], b[i]) of the pair's header returns, bit
// for bit, for every input (NaN for non-finite input; exactly 0 for a segment meeting a triangle,
// under the contact rule of segment_triangle.hpp), when the caller's code is compiled without
// floating-point contraction (the default on x86-64 unless FMA is enabled, e.g. by -march=native);
// with contraction the per-query functions may differ from these by rounding. The lanes the SIMD
// kernels (src/core/lanes.hpp) do not cover (non-finite or extreme input, needle triangles,
// undecided meeting tests, rare branches) are recomputed by the per-query function.
// On x86-64 the library carries an x86-64-v4 (AVX-512), an AVX2 and a baseline version and
// picks the best one the processor runs at each call (detail::set_batch_isa caps it, for tests
// and benchmarks; -DLOCUS_NO_MULTIVERSION compiles the kernels once, for the compiler's own
// target). Every version gives the same bits. Throughput: bench/results/distance.md.
// No allocation; noexcept.

#include <locus/core/detail/batch_isa.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <span>

namespace locus {

// The pairs and their "one against many" forms, declared for float and double (compiled in
// src/distance/batch_point_triangle.cpp, batch_segment_segment.cpp, batch_segment_triangle.cpp
// and batch_boxes.cpp).
#define LOCUS_BATCH_PAIR(A, B)                                                   \
  void sqr_distances(std::span<const A<float>> a, std::span<const B<float>> b,   \
                     std::span<float> out) noexcept;                             \
  void sqr_distances(std::span<const A<double>> a, std::span<const B<double>> b, \
                     std::span<double> out) noexcept;                            \
  void sqr_distances(std::span<const A<float>> a, const B<float>& b,             \
                     std::span<float> out) noexcept;                             \
  void sqr_distances(std::span<const A<double>> a, const B<double>& b,           \
                     std::span<double> out) noexcept;                            \
  void sqr_distances(const A<float>& a, std::span<const B<float>> b,             \
                     std::span<float> out) noexcept;                             \
  void sqr_distances(const A<double>& a, std::span<const B<double>> b,           \
                     std::span<double> out) noexcept;

LOCUS_BATCH_PAIR(Vec3, Triangle3)
LOCUS_BATCH_PAIR(Segment3, Segment3)
LOCUS_BATCH_PAIR(Segment3, Triangle3)
LOCUS_BATCH_PAIR(Vec3, AlignedBox3)
LOCUS_BATCH_PAIR(Vec3, OrientedBox3)
#undef LOCUS_BATCH_PAIR

// The swapped argument orders of the mixed pairs: the same values (sqr_distance is symmetric).
#define LOCUS_BATCH_SWAPPED(A, B, T)                                                             \
  inline void sqr_distances(std::span<const B<T>> b, std::span<const A<T>> a,                    \
                            std::span<T> out) noexcept {                                         \
    sqr_distances(a, b, out);                                                                    \
  }                                                                                              \
  inline void sqr_distances(std::span<const B<T>> b, const A<T>& a, std::span<T> out) noexcept { \
    sqr_distances(a, b, out);                                                                    \
  }                                                                                              \
  inline void sqr_distances(const B<T>& b, std::span<const A<T>> a, std::span<T> out) noexcept { \
    sqr_distances(a, b, out);                                                                    \
  }
#define LOCUS_BATCH_SWAPPED_FD(A, B) \
  LOCUS_BATCH_SWAPPED(A, B, float) LOCUS_BATCH_SWAPPED(A, B, double)
LOCUS_BATCH_SWAPPED_FD(Vec3, Triangle3)
LOCUS_BATCH_SWAPPED_FD(Segment3, Triangle3)
LOCUS_BATCH_SWAPPED_FD(Vec3, AlignedBox3)
LOCUS_BATCH_SWAPPED_FD(Vec3, OrientedBox3)
#undef LOCUS_BATCH_SWAPPED_FD
#undef LOCUS_BATCH_SWAPPED

}  // namespace locus
