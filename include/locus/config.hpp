// SPDX-License-Identifier: BSL-1.0
#pragma once
// locus configuration: version, and the assertion hook for programming errors.
//
// LOCUS_ASSERT(cond, msg) checks preconditions (an index out of range, a broken invariant that
// only a caller's bug can cause). It is active in debug builds (NDEBUG undefined) and whenever
// LOCUS_ENABLE_ASSERTS is defined; otherwise it compiles to nothing. Bad *data* (NaN, degenerate
// shapes, malformed files) is never an assertion: queries return documented results and
// algorithms return a Status.
//
// The default handler prints file:line and the message to stderr and aborts. Replace it with
// set_assert_handler(); the handler is process-wide, set it once at start-up.

#define LOCUS_VERSION_MAJOR 0
#define LOCUS_VERSION_MINOR 1
#define LOCUS_VERSION_PATCH 0

// LOCUS_ALWAYS_INLINE: for the few small helpers on a query's hot path that the compiler's size
// heuristics would otherwise leave out of line in large callers or large translation units
// (GCC stops inlining once a unit has grown past --param inline-unit-growth, which a program
// including many headers reaches; a Vec3 returned from a call passes through the stack and
// stalls the load that reads it back).
#if defined(__GNUC__) || defined(__clang__)
#define LOCUS_ALWAYS_INLINE __attribute__((always_inline))
#elif defined(_MSC_VER)
#define LOCUS_ALWAYS_INLINE __forceinline
#else
#define LOCUS_ALWAYS_INLINE
#endif

// LOCUS_ALWAYS_INLINE_LAMBDA: the same for a lambda (placed after its parameter list).
#if defined(__GNUC__) || defined(__clang__)
#define LOCUS_ALWAYS_INLINE_LAMBDA __attribute__((always_inline))
#else
#define LOCUS_ALWAYS_INLINE_LAMBDA
#endif

// LOCUS_NOINLINE: keeps a function out of line, for a slow path that would otherwise bloat its
// callers, or a function whose address or frame must stay distinct.
#if defined(__GNUC__) || defined(__clang__)
#define LOCUS_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define LOCUS_NOINLINE __declspec(noinline)
#else
#define LOCUS_NOINLINE
#endif

// LOCUS_FLATTEN: every call in the function's body is inlined (recursively), for a function that
// calls a general routine with arguments that make most of its branches constant (the compiler
// can only fold them in an inlined copy).
#if defined(__GNUC__) || defined(__clang__)
#define LOCUS_FLATTEN __attribute__((flatten))
#else
#define LOCUS_FLATTEN
#endif

// LOCUS_COLD: a function reached only for rare input (e.g. a rescaled retry), kept out of line
// and out of the hot code's layout.
#if defined(__GNUC__) || defined(__clang__)
#define LOCUS_COLD __attribute__((cold, noinline))
#else
#define LOCUS_COLD
#endif

namespace locus {

/// Signature of an assertion handler: the failed condition, a message, the source location.
using AssertHandler = void (*)(const char* condition, const char* message, const char* file,
                               int line);

/// Installs `handler` (nullptr restores the default) and returns the previous one.
AssertHandler set_assert_handler(AssertHandler handler) noexcept;

namespace detail {
[[noreturn]] void assert_failed(const char* condition, const char* message, const char* file,
                                int line) noexcept;
}  // namespace detail

}  // namespace locus

#if !defined(NDEBUG) || defined(LOCUS_ENABLE_ASSERTS)
#define LOCUS_ASSERT(cond, msg) \
  ((cond) ? static_cast<void>(0) : ::locus::detail::assert_failed(#cond, msg, __FILE__, __LINE__))
#else
#define LOCUS_ASSERT(cond, msg) static_cast<void>(0)
#endif
