// SPDX-License-Identifier: BSL-1.0
#pragma once
// The instruction-set versions of locus's SIMD lane code (src/core/lanes.hpp, used by the
// batched distances of distance/batch.hpp and by the BVH of spatial/bvh.hpp): which version
// runs, and a cap for tests and benchmarks. Compiled in src/core/simd_level.cpp.

namespace locus::detail {

/// The instruction sets the lane code is compiled for (x86-64; elsewhere, or built with
/// LOCUS_NO_MULTIVERSION, every level runs the one compiled version).
enum class BatchIsa { baseline = 0, avx2 = 1, x86_64_v4 = 2 };
/// The version the lane code uses: the best the processor supports, capped by set_batch_isa.
[[nodiscard]] BatchIsa batch_isa() noexcept;
/// Caps the version the lane code uses (for tests and benchmarks that compare the versions;
/// default: no cap). Returns the level in use after the call (limit, or less where the
/// processor lacks it). Thread-safe; affects later calls in every thread.
BatchIsa set_batch_isa(BatchIsa limit) noexcept;

}  // namespace locus::detail
