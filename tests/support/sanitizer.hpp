// SPDX-License-Identifier: BSL-1.0
#pragma once
// Whether the test is compiled with AddressSanitizer (GCC defines __SANITIZE_ADDRESS__, clang
// answers __has_feature(address_sanitizer)). CI runs every test a second time in that build at
// -O0, some 20-40 times slower: a test may run a smaller, equally covering selection there when
// the optimised run checks the full one (say which, and why the selection covers the same code).

namespace locus_test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizerBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif
#else
inline constexpr bool kSanitizerBuild = false;
#endif

}  // namespace locus_test
