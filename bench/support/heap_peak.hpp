// SPDX-License-Identifier: BSL-1.0
// Peak heap memory of one benchmark case, for every library in the process alike.
//
// bench/support/heap_peak.cpp (linked into every locus_bench_* executable by
// bench/CMakeLists.txt) defines malloc, calloc, realloc, free and the aligned variants on top
// of glibc's __libc_* entry points, so every heap block of the process is counted: operator new
// (libstdc++ calls malloc), CGAL, Qhull, Boost and locus. The count is the usable size of the
// live blocks (malloc_usable_size), so allocator rounding is included and mmap'd pages that
// were never touched are too (unlike maxrss, which counts only touched pages but never goes
// down, so it needs one process per case).
//
// Use: construct a HeapPeak after the input is allocated and before the timed loop, and
// report it after the loop:
//   locus::bench::HeapPeak peak;
//   for (auto _ : state) { ... }
//   locus::bench::report_heap_peak(state, peak);   // counter "peak_MB"
// The peak is process-wide: HeapPeak scopes do not nest (constructing one restarts the peak for
// every scope). Benchmarks run one case at a time on one thread, which is all this needs.
//
// Counting is off (heap_counting() is false, no counter is reported) without glibc or under
// AddressSanitizer, which owns malloc itself.
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>

namespace locus::bench {

// True when the malloc family of the process is being counted.
[[nodiscard]] bool heap_counting() noexcept;

// Bytes in live heap blocks now (0 when not counting).
[[nodiscard]] std::int64_t heap_bytes() noexcept;

// Largest heap growth over the heap size at construction, until now.
class HeapPeak {
 public:
  HeapPeak() noexcept;
  [[nodiscard]] std::int64_t bytes() const noexcept;
  [[nodiscard]] double mb() const noexcept {
    return static_cast<double>(bytes()) / (1024.0 * 1024.0);
  }

 private:
  std::int64_t base_;
};

// Sets the counter "peak_MB" (MiB) when counting is on; scripts/bench_table reads that name.
inline void report_heap_peak(benchmark::State& state, const HeapPeak& peak) {
  if (heap_counting()) state.counters["peak_MB"] = peak.mb();
}

}  // namespace locus::bench
