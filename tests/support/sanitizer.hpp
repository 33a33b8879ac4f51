// SPDX-License-Identifier: BSL-1.0
#pragma once
// Whether the test is compiled with AddressSanitizer (GCC defines __SANITIZE_ADDRESS__, clang
// answers __has_feature(address_sanitizer)). CI runs every test a second time in that build at
// -O0, some 20-40 times slower: a test may run a smaller, equally covering selection there when
// the optimised run checks the full one (say which, and why the selection covers the same code).

// LOCUS_TEST_SANITIZED is 1 in that build, else 0, for #if; kSanitizerBuild is the same as a
// constant.
#if defined(__SANITIZE_ADDRESS__)
#define LOCUS_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LOCUS_TEST_SANITIZED 1
#endif
#endif
#ifndef LOCUS_TEST_SANITIZED
#define LOCUS_TEST_SANITIZED 0
#endif

namespace locus_test {

inline constexpr bool kSanitizerBuild = LOCUS_TEST_SANITIZED != 0;

}  // namespace locus_test
