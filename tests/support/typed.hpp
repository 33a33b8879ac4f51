// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared test scaffolding: typed tests over float and double, seeded random generators that
// print their seed on failure, and tolerance helpers scaled by the type's epsilon.

#include <gtest/gtest.h>

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

namespace locus_test {

using RealTypes = ::testing::Types<float, double>;

/// Default seed of every randomized test; override with LOCUS_TEST_SEED in the environment.
inline std::uint64_t test_seed(std::uint64_t fallback = 20261122) {
  if (const char* s = std::getenv("LOCUS_TEST_SEED")) return std::stoull(s);
  return fallback;
}

/// A seeded generator. Put `SCOPED_TRACE(rng.trace())` in the test so a failure prints the seed.
class Rng {
 public:
  explicit Rng(std::uint64_t seed = test_seed()) : seed_(seed), engine_(seed) {}
  std::string trace() const { return "seed = " + std::to_string(seed_); }
  std::uint64_t seed() const { return seed_; }
  std::mt19937_64& engine() { return engine_; }

  template <class T>
  T uniform(T lo, T hi) {
    return static_cast<T>(std::uniform_real_distribution<double>(double(lo), double(hi))(engine_));
  }
  int uniform_int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  template <class T, int N>
  locus::Vec<T, N> vec(T lo, T hi) {
    locus::Vec<T, N> v{};
    for (int i = 0; i < N; ++i) v[i] = uniform<T>(lo, hi);
    return v;
  }
  /// A random unit vector, uniform on the sphere.
  template <class T, int N>
  locus::Vec<T, N> unit() {
    std::normal_distribution<double> g;
    for (;;) {
      locus::Vec<double, N> v{};
      for (int i = 0; i < N; ++i) v[i] = g(engine_);
      double l = std::sqrt(locus::sqr_length(v));
      if (l > 1e-3) return locus::vec_cast<T>(v / l);
    }
  }

 private:
  std::uint64_t seed_;
  std::mt19937_64 engine_;
};

/// Tolerance k * eps(T) * scale, the shape of every floating-point check in the tests.
template <class T>
constexpr T tol(T k, T scale = T(1)) {
  return k * locus::eps_v<T> * scale;
}

template <class T, int N>
::testing::AssertionResult vec_near(const locus::Vec<T, N>& a, const locus::Vec<T, N>& b,
                                    T abs_tol) {
  for (int i = 0; i < N; ++i) {
    if (!(std::abs(a[i] - b[i]) <= abs_tol)) {
      std::string sa, sb;
      for (int j = 0; j < N; ++j) {
        sa += std::to_string(a[j]) + " ";
        sb += std::to_string(b[j]) + " ";
      }
      return ::testing::AssertionFailure()
             << "component " << i << " differs: (" << sa << ") vs (" << sb << "), tol " << abs_tol;
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace locus_test
