// SPDX-License-Identifier: BSL-1.0
#pragma once
// Scale covariance, the distance harness's check 8 (tests/distance/harness.hpp) for any
// routine: the input scaled by 2^k about the origin must give lengths scaled by 2^k, areas by
// 2^(2k), volumes by 2^(3k), directions and counts unchanged. The input scales exactly, so a
// difference is the routine's: an absolute tolerance hidden in it, or an intermediate that
// leaves the exponent range without a rescaled fallback.
//
// Usage: a lambda run(k) that runs the routine on the input scaled by 2^k (scaled(pts, k)) and
// returns its result as a list of Covariant quantities; expect_scale_covariant(run, exponents,
// tol, unit) compares run(k) with run(0) for each k. tol = 0 asks for equality after unscaling
// (the routine is scale-exact: all its arithmetic scales by powers of two); tol > 0 allows
// |unscaled - base| <= tol * unit^power, with unit the coordinate scale of the unscaled input.

#include <gtest/gtest.h>

#include <locus/core/vec.hpp>

#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace locus_test {

/// Check 8's exponents: double +-140 (products of four coordinates in range) and +-400
/// (squares in range, products of four not); float +-20 and +-50.
template <class T>
constexpr std::array<int, 4> scale_exponents() {
  if constexpr (std::is_same_v<T, float>)
    return {-50, -20, 20, 50};
  else
    return {-400, -140, 140, 400};
}

/// Exponents near the ends of the range for coordinates of magnitude up to 2^7: the scaled
/// input stays normal and finite, and so do lengths (double +-1000 and +-900, float +-110).
template <class T>
constexpr std::array<int, 4> far_scale_exponents() {
  if constexpr (std::is_same_v<T, float>)
    return {-110, -100, 100, 110};
  else
    return {-1000, -900, 900, 1000};
}

/// Check 8's exponents for a routine whose results scale by up to 2^(max_power k): those whose
/// results stay normal and finite for values up to 2^24, and the largest such |k| beyond them
/// (double: 999 for lengths, 499 for areas, 333 for volumes; float 104, 52, 34).
template <class T>
std::vector<int> covariant_exponents(int max_power) {
  const int limit = (std::numeric_limits<T>::max_exponent - 24) / max_power;
  std::vector<int> k;
  for (const int e : scale_exponents<T>())
    if (e <= limit && -e <= limit) k.push_back(e);
  k.push_back(-limit);
  k.push_back(limit);
  return k;
}

template <class T, int N>
locus::Vec<T, N> scaled(const locus::Vec<T, N>& p, int k) {
  locus::Vec<T, N> q{};
  for (int i = 0; i < N; ++i) q[i] = std::ldexp(p[i], k);
  return q;
}

template <class T, int N>
std::vector<locus::Vec<T, N>> scaled(const std::vector<locus::Vec<T, N>>& pts, int k) {
  std::vector<locus::Vec<T, N>> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.push_back(scaled(p, k));
  return out;
}

/// One quantity of a result that must scale by 2^(power k) (power 0: invariant, such as a
/// status, a count, an index or a unit direction).
struct Covariant {
  std::string name;
  double value;
  int power;
};

/// Appends the N coordinates of v, each scaling by 2^(power k).
template <class T, int N>
void add(std::vector<Covariant>& out, const std::string& name, const locus::Vec<T, N>& v,
         int power) {
  for (int i = 0; i < N; ++i)
    out.push_back({name + "[" + std::to_string(i) + "]", static_cast<double>(v[i]), power});
}

/// Compares run(k) for each k with run(0) (see the top comment).
template <class Run, class Exponents>
void expect_scale_covariant(Run&& run, const Exponents& exponents, double tol = 0.0,
                            double unit = 1.0) {
  const std::vector<Covariant> base = run(0);
  for (const int k : exponents) {
    SCOPED_TRACE("scaled by 2^" + std::to_string(k));
    const std::vector<Covariant> got = run(k);
    ASSERT_EQ(got.size(), base.size());
    for (std::size_t i = 0; i < base.size(); ++i) {
      SCOPED_TRACE(base[i].name);
      ASSERT_EQ(got[i].power, base[i].power);
      const double back = std::ldexp(got[i].value, -base[i].power * k);
      std::ostringstream at;
      at << std::setprecision(17) << "unscaled " << back << " against " << base[i].value
         << " (relative difference " << (back - base[i].value) / std::abs(base[i].value)
         << "); at 2^k: " << got[i].value;
      if (tol == 0.0) {
        EXPECT_EQ(back, base[i].value) << at.str();
      } else {
        EXPECT_NEAR(back, base[i].value, tol * std::pow(unit, base[i].power)) << at.str();
      }
    }
  }
}

}  // namespace locus_test
