// SPDX-License-Identifier: BSL-1.0
// Which compiled version the SIMD lane code runs (include/locus/core/detail/batch_isa.hpp,
// detail::batch_isa): the best one the running processor supports, capped by set_batch_isa.

#include <locus/core/detail/batch_isa.hpp>

#include <atomic>

namespace locus::detail {
namespace {

BatchIsa supported() noexcept {
#if defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
  // x86-64-v4: AVX-512 F, BW, CD, DQ and VL on top of v3 (AVX2, FMA, BMI2, ...).
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx2") &&
      __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2"))
    return BatchIsa::x86_64_v4;
  if (__builtin_cpu_supports("avx2")) return BatchIsa::avx2;
#endif
  return BatchIsa::baseline;
}

// A function-local static: batch_isa() may be reached from another unit's static initialiser.
BatchIsa supported_once() noexcept {
  static const BatchIsa level = supported();
  return level;
}

std::atomic<int> g_level{static_cast<int>(BatchIsa::x86_64_v4)};  // the cap; constant-initialised

}  // namespace

BatchIsa batch_isa() noexcept {
  const int cap = g_level.load(std::memory_order_relaxed);
  const BatchIsa best = supported_once();
  return cap < static_cast<int>(best) ? static_cast<BatchIsa>(cap) : best;
}

BatchIsa set_batch_isa(BatchIsa limit) noexcept {
  g_level.store(static_cast<int>(limit), std::memory_order_relaxed);
  return batch_isa();
}

}  // namespace locus::detail
