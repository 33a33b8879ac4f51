// SPDX-License-Identifier: BSL-1.0
// Heap counting for the benchmarks (see heap_peak.hpp): the malloc family defined here
// interposes glibc's for the whole process (the executable's definitions win symbol
// resolution, shared libraries included) and forwards to glibc's __libc_* entry points.
// Signed counters: a block that some path allocated without passing here (none is known) could
// otherwise wrap the count around when freed.
#include "support/heap_peak.hpp"

#include <atomic>
#include <cerrno>
#include <cstdlib>

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#include <malloc.h>
#include <unistd.h>
#define LOCUS_BENCH_COUNT_HEAP 1
#endif

namespace {
std::atomic<std::int64_t> g_heap_now{0};
std::atomic<std::int64_t> g_heap_peak{0};
}  // namespace

#if defined(LOCUS_BENCH_COUNT_HEAP)
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void __libc_free(void*);
void* __libc_memalign(std::size_t, std::size_t);

static void heap_add(void* p) noexcept {
  if (!p) return;
  const auto size = static_cast<std::int64_t>(malloc_usable_size(p));
  const std::int64_t now = g_heap_now.fetch_add(size, std::memory_order_relaxed) + size;
  std::int64_t peak = g_heap_peak.load(std::memory_order_relaxed);
  while (now > peak && !g_heap_peak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
}
static void heap_sub(void* p) noexcept {
  if (p)
    g_heap_now.fetch_sub(static_cast<std::int64_t>(malloc_usable_size(p)),
                         std::memory_order_relaxed);
}

void* malloc(std::size_t n) {
  void* p = __libc_malloc(n);
  heap_add(p);
  return p;
}
void* calloc(std::size_t count, std::size_t size) {
  void* p = __libc_calloc(count, size);
  heap_add(p);
  return p;
}
void* realloc(void* old, std::size_t n) {
  heap_sub(old);
  void* p = __libc_realloc(old, n);
  // realloc(old, 0) frees old; a failed realloc leaves old allocated.
  heap_add(p ? p : (n ? old : nullptr));
  return p;
}
void* reallocarray(void* old, std::size_t count, std::size_t size) {
  std::size_t n;
  if (__builtin_mul_overflow(count, size, &n)) {
    errno = ENOMEM;
    return nullptr;
  }
  return realloc(old, n);
}
void free(void* p) {
  heap_sub(p);
  __libc_free(p);
}
void* memalign(std::size_t align, std::size_t n) {
  void* p = __libc_memalign(align, n);
  heap_add(p);
  return p;
}
void* aligned_alloc(std::size_t align, std::size_t n) { return memalign(align, n); }
int posix_memalign(void** out, std::size_t align, std::size_t n) {
  if (align % sizeof(void*) != 0 || (align & (align - 1)) != 0) return EINVAL;
  void* p = memalign(align, n);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}
void* valloc(std::size_t n) { return memalign(static_cast<std::size_t>(sysconf(_SC_PAGESIZE)), n); }
void* pvalloc(std::size_t n) {
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  return memalign(page, (n + page - 1) / page * page);
}
}
#endif

namespace locus::bench {

bool heap_counting() noexcept {
#if defined(LOCUS_BENCH_COUNT_HEAP)
  return true;
#else
  return false;
#endif
}

std::int64_t heap_bytes() noexcept { return g_heap_now.load(std::memory_order_relaxed); }

HeapPeak::HeapPeak() noexcept : base_(g_heap_now.load(std::memory_order_relaxed)) {
  g_heap_peak.store(base_, std::memory_order_relaxed);
}

std::int64_t HeapPeak::bytes() const noexcept {
  return g_heap_peak.load(std::memory_order_relaxed) - base_;
}

}  // namespace locus::bench
