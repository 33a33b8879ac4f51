// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared pieces of the API tests: the same points as every container a user may hold them in,
// and a digest of results (every field flattened to doubles) so the forms compare exactly.

#include <locus/core/mat.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/vec.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus::api_test {

/// K points of dimension N held as std::vector, std::array, C array, std::span (const and
/// mutable) and a flat coordinate array.
template <class T, int N, std::size_t K>
struct Forms {
  std::vector<Vec<T, N>> vec;
  std::array<Vec<T, N>, K> arr{};
  Vec<T, N> carr[K]{};
  std::vector<Vec<T, N>> mut;
  std::vector<T> flat;

  explicit Forms(const std::vector<Vec<T, N>>& v) : vec(v), mut(v) {
    EXPECT_EQ(v.size(), K);
    for (std::size_t i = 0; i < K; ++i) {
      arr[i] = v[i];
      carr[i] = v[i];
      for (int k = 0; k < N; ++k) flat.push_back(v[i][k]);
    }
  }

  /// Calls f(name, points) for every form.
  template <class F>
  void each(F&& f) {
    f("std::vector", vec);
    f("std::array", arr);
    f("C array", carr);
    f("std::span<const Vec>", std::span<const Vec<T, N>>(vec));
    f("std::span<Vec>", std::span<Vec<T, N>>(mut));
    f("std::span<const Vec, K>", std::span<const Vec<T, N>, K>(arr));
    f("point_span<N>(flat, n)", point_span<N>(flat.data(), K));
  }
};

// ---- digest ------------------------------------------------------------------------------------

using Digest = std::vector<double>;

template <class X>
void put(Digest& d, const X& x);

template <class X>
void put_all(Digest& d, const X& x) {
  for (const auto& e : x) put(d, e);
}

template <class X>
void put(Digest& d, const X& x) {
  if constexpr (std::is_arithmetic_v<X>) {
    d.push_back(static_cast<double>(x));
  } else if constexpr (std::is_enum_v<X>) {
    d.push_back(static_cast<double>(static_cast<long long>(x)));
  } else if constexpr (requires { x.has_value(); }) {
    d.push_back(x.has_value() ? 1.0 : 0.0);
    if (x.has_value()) put(d, *x);
  } else if constexpr (requires {
                         x.first;
                         x.second;
                       }) {
    put(d, x.first);
    put(d, x.second);
  } else if constexpr (requires {
                         x.begin();
                         x.end();
                       } ||
                       std::is_array_v<X>) {
    d.push_back(static_cast<double>(std::size(x)));
    put_all(d, x);
  } else if constexpr (requires { x.a[0][0]; }) {  // Mat
    for (const auto& row : x.a) put_all(d, row);
  } else if constexpr (requires { x[0]; }) {  // Vec (Segment: its two end points)
    constexpr int n = static_cast<int>(sizeof(X) / sizeof(x[0]));
    for (int k = 0; k < n; ++k) put(d, x[k]);
  } else {
    static_assert(sizeof(X) == 0, "add a digest for this type in tests/api/forms.hpp");
  }
}

template <class... X>
[[nodiscard]] Digest digest(const X&... x) {
  Digest d;
  (put(d, x), ...);
  return d;
}

/// Calls `call` with every form of the points and expects digests equal to the std::vector's.
template <class T, int N, std::size_t K, class F>
void expect_same(Forms<T, N, K>& forms, const char* what, F&& call) {
  const Digest ref = call(forms.vec);
  EXPECT_FALSE(ref.empty()) << what;
  forms.each([&](const char* name, const auto& points) {
    EXPECT_EQ(call(points), ref) << what << " with " << name;
  });
}

/// Deterministic pseudo-random coordinates in [-1, 1) (the values only need to be generic).
class Lcg {
 public:
  explicit Lcg(std::uint64_t seed) : s_(seed) {}
  double next() {
    s_ = s_ * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s_ >> 11) * 0x1.0p-52 - 1.0;
  }

 private:
  std::uint64_t s_;
};

}  // namespace locus::api_test
