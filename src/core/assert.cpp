// SPDX-License-Identifier: BSL-1.0
#include <locus/config.hpp>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace locus {
namespace {

void default_handler(const char* condition, const char* message, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: locus assertion failed: %s (%s)\n", file, line, condition, message);
}

std::atomic<AssertHandler> g_handler{nullptr};

}  // namespace

AssertHandler set_assert_handler(AssertHandler handler) noexcept {
  return g_handler.exchange(handler);
}

namespace detail {
void assert_failed(const char* condition, const char* message, const char* file,
                   int line) noexcept {
  AssertHandler h = g_handler.load();
  (h ? h : default_handler)(condition, message, file, line);
  // A handler that returns (rather than throwing or jumping) still must not let execution
  // continue past a broken precondition.
  std::abort();
}
}  // namespace detail

}  // namespace locus
