// SPDX-License-Identifier: BSL-1.0
#pragma once
// Long-double oracles shared by the tests of linear components against curves
// (linear_curve_test.cpp, linear_ellipse_test.cpp, circle3_pairs_test.cpp): a line, ray or
// segment in long double, the exact squared distance from a point to it, and minimisation of a
// function of one parameter by dense samples whose discrete local minima are refined by golden
// section (over an interval, or over a full turn of an angle).
#include <locus/core/vec.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace locus_test::linear_oracle {

using LD = long double;

/// |got - want| <= abs_tol, reporting the three values on failure.
inline ::testing::AssertionResult near_ld(LD got, LD want, LD abs_tol) {
  if (std::fabs(got - want) <= abs_tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "got " << static_cast<double>(got) << ", oracle " << static_cast<double>(want)
         << ", diff " << static_cast<double>(got - want) << ", tol "
         << static_cast<double>(abs_tol);
}

/// The points o + t d with t >= 0 when lo and t <= 1 when hi.
template <int N>
struct LinLD {
  locus::Vec<LD, N> o, d;
  bool lo, hi;
};
template <class T, int N>
LinLD<N> to_ld(const locus::Line<T, N>& l) {
  return {locus::vec_cast<LD>(l.origin), locus::vec_cast<LD>(l.direction), false, false};
}
template <class T, int N>
LinLD<N> to_ld(const locus::Ray<T, N>& l) {
  return {locus::vec_cast<LD>(l.origin), locus::vec_cast<LD>(l.direction), true, false};
}
template <class T, int N>
LinLD<N> to_ld(const locus::Segment<T, N>& s) {
  return {locus::vec_cast<LD>(s.p0), locus::vec_cast<LD>(s.p1) - locus::vec_cast<LD>(s.p0), true,
          true};
}

/// Squared distance from p to the component (exact projection, clamped to its domain).
template <int N>
LD sqr_to_linear(const locus::Vec<LD, N>& p, const LinLD<N>& l) {
  const LD dd = sqr_length(l.d);
  LD t = dd > 0 ? dot(p - l.o, l.d) / dd : LD(0);
  if (l.lo && t < 0) t = 0;
  if (l.hi && t > 1) t = 1;
  return sqr_length(l.o + t * l.d - p);
}

/// The smaller of the two last golden-section probes of f on [a, b] after `steps` steps.
template <class F>
LD golden_section_min(F&& f, LD a, LD b, int steps) {
  const LD g = (std::sqrt(LD(5)) - 1) / 2;
  LD x1 = b - g * (b - a), x2 = a + g * (b - a);
  LD f1 = f(x1), f2 = f(x2);
  for (int k = 0; k < steps; ++k) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = f(x2);
    }
  }
  return std::min(f1, f2);
}

/// min of f over [lo, hi] given its n + 1 samples val[i] = f(lo + i (hi - lo) / n): every
/// discrete local minimum (ends included) is refined by golden section on its neighbouring
/// interval.
template <class F>
LD min_over_samples(const std::vector<LD>& val, F&& f, LD lo, LD hi) {
  const int n = static_cast<int>(val.size()) - 1;
  const LD h = (hi - lo) / n;
  LD best = std::numeric_limits<LD>::infinity();
  for (int i = 0; i <= n; ++i) {
    const LD vi = val[static_cast<std::size_t>(i)];
    const LD prev = i > 0 ? val[static_cast<std::size_t>(i - 1)] : vi;
    const LD next = i < n ? val[static_cast<std::size_t>(i + 1)] : vi;
    best = std::min(best, vi);
    if (!(vi <= prev && vi <= next)) continue;
    const LD a = lo + h * LD(std::max(i - 1, 0)), b = lo + h * LD(std::min(i + 1, n));
    best = std::min(best, golden_section_min(f, a, b, 90));
  }
  return best;
}

/// min over the angle a of f(a) (2 pi periodic): 1024 samples, each discrete local minimum
/// (neighbours taken around the turn) refined by golden section on its neighbouring interval.
template <class F>
LD min_over_angle(F&& f) {
  constexpr int n = 1024;
  const LD h = LD(2) * std::acos(LD(-1)) / n;
  std::vector<LD> val(n);
  for (int i = 0; i < n; ++i) val[static_cast<std::size_t>(i)] = f(h * LD(i));
  const auto at = [&](int i) { return val[static_cast<std::size_t>((i + n) % n)]; };
  LD best = std::numeric_limits<LD>::infinity();
  for (int i = 0; i < n; ++i) {
    if (!(at(i) <= at(i - 1) && at(i) <= at(i + 1))) continue;
    best = std::min({best, at(i), golden_section_min(f, h * LD(i - 1), h * LD(i + 1), 80)});
  }
  return best;
}

}  // namespace locus_test::linear_oracle
