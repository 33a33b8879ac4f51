// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact oracles for the curve tests: Bernstein sums, their derivatives and the Cox-de Boor
// basis, all in GMP rationals (mpq_class) over dyadic inputs, written from the definitions and
// independent of the de Casteljau / de Boor code under test.

#include <gmpxx.h>

#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bspline.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <type_traits>
#include <vector>

namespace curve_oracle {

using Q = mpq_class;

template <int N>
using QVec = std::array<Q, N>;

inline Q q(double x) { return Q(x); }  // exact for any finite double

inline Q binom(int n, int k) {
  mpz_class r;
  mpz_bin_uiui(r.get_mpz_t(), static_cast<unsigned long>(n), static_cast<unsigned long>(k));
  return Q(r);
}

inline Q qpow(const Q& x, int e) {
  Q r = 1;
  for (int i = 0; i < e; ++i) r *= x;
  return r;
}

/// Bernstein polynomial B_i^n(t), exact.
inline Q bernstein(int n, int i, const Q& t) {
  if (i < 0 || i > n) return 0;
  return binom(n, i) * qpow(t, i) * qpow(Q(1) - t, n - i);
}

template <class T, int N>
std::vector<QVec<N>> to_q(const std::vector<locus::Vec<T, N>>& p) {
  std::vector<QVec<N>> r(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int c = 0; c < N; ++c) r[i][static_cast<std::size_t>(c)] = q(static_cast<double>(p[i][c]));
  return r;
}

/// The k-th derivative of sum_i B_i^n(t) P_i: n!/(n-k)! sum_i B_i^{n-k}(t) (Delta^k P)_i.
template <int N>
QVec<N> bezier_derivative(std::vector<QVec<N>> p, int k, const Q& t) {
  const int n = static_cast<int>(p.size()) - 1;
  QVec<N> r{};
  if (k > n) return r;
  Q scale = 1;
  for (int s = 0; s < k; ++s) {
    scale *= n - s;
    for (std::size_t i = 0; i + 1 < p.size() - static_cast<std::size_t>(s); ++i)
      for (std::size_t c = 0; c < N; ++c) p[i][c] = p[i + 1][c] - p[i][c];
  }
  for (int i = 0; i <= n - k; ++i) {
    const Q b = bernstein(n - k, i, t) * scale;
    for (std::size_t c = 0; c < N; ++c) r[c] += b * p[static_cast<std::size_t>(i)][c];
  }
  return r;
}

/// The domain span by a linear scan: the largest k in [d, n-1] with t_k <= t and t_k < t_{k+1}.
inline int span_scan(const std::vector<Q>& kn, int d, int n, const Q& t) {
  int best = d;
  for (int k = d; k < n; ++k)
    if (kn[static_cast<std::size_t>(k)] <= t &&
        kn[static_cast<std::size_t>(k)] < kn[static_cast<std::size_t>(k) + 1])
      best = k;
  return best;
}

/// N_{i,p}(t) by the plain recursive Cox-de Boor definition (0/0 = 0), degree-0 functions
/// chosen by span_scan so that the domain end belongs to the last span.
inline Q cox_de_boor(const std::vector<Q>& kn, int i, int p, const Q& t, int span) {
  const auto ui = static_cast<std::size_t>(i);
  if (p == 0) return i == span ? Q(1) : Q(0);
  Q r = 0;
  const Q d1 = kn[ui + static_cast<std::size_t>(p)] - kn[ui];
  if (d1 != 0) r += (t - kn[ui]) / d1 * cox_de_boor(kn, i, p - 1, t, span);
  const Q d2 = kn[ui + static_cast<std::size_t>(p) + 1] - kn[ui + 1];
  if (d2 != 0)
    r += (kn[ui + static_cast<std::size_t>(p) + 1] - t) / d2 *
         cox_de_boor(kn, i + 1, p - 1, t, span);
  return r;
}

template <class T>
std::vector<Q> knots_q(const std::vector<T>& k) {
  std::vector<Q> r;
  for (T x : k) r.push_back(q(static_cast<double>(x)));
  return r;
}

/// max |component| of a QVec, as double.
template <int N>
double max_abs(const QVec<N>& v) {
  double m = 0;
  for (const auto& x : v) m = std::max(m, std::abs(x.get_d()));
  return m;
}

/// |a - b| componentwise <= tol, with a printable message.
template <class T, int N>
::testing::AssertionResult near_q(const locus::Vec<T, N>& a, const std::type_identity_t<QVec<N>>& b,
                                  double tol) {
  for (int c = 0; c < N; ++c) {
    const Q diff = Q(static_cast<double>(a[c])) - b[static_cast<std::size_t>(c)];
    const double e = std::abs(diff.get_d());
    if (!(e <= tol))
      return ::testing::AssertionFailure()
             << "component " << c << ": got " << a[c] << ", exact "
             << b[static_cast<std::size_t>(c)].get_d() << ", error " << e << " > tol " << tol;
  }
  return ::testing::AssertionSuccess();
}

/// A dyadic random value k/16, k in [-128, 128]: exact in float and double.
inline double dyadic(locus_test::Rng& rng) { return rng.uniform_int(-128, 128) / 16.0; }

template <class T, int N>
locus::Vec<T, N> dyadic_vec(locus_test::Rng& rng) {
  locus::Vec<T, N> v{};
  for (int c = 0; c < N; ++c) v[c] = static_cast<T>(dyadic(rng));
  return v;
}

/// Random valid dyadic knots for n control points of degree d: the first a multiple of 1 / den in
/// [-1, 1], each next one 0 to max_step / den further (repeats included); clamped ends when asked.
template <class T>
std::vector<T> random_knots(locus_test::Rng& rng, int n, int d, bool clamped, int den = 4,
                            int max_step = 2) {
  for (;;) {
    std::vector<T> k;
    double x = rng.uniform_int(-den, den) / double(den);
    for (int i = 0; i < n + d + 1; ++i) {
      k.push_back(static_cast<T>(x));
      x += rng.uniform_int(0, max_step) / double(den);
    }
    if (clamped) {
      for (int i = 0; i < d; ++i) k[static_cast<std::size_t>(i)] = k[static_cast<std::size_t>(d)];
      for (int i = n + 1; i < n + d + 1; ++i)
        k[static_cast<std::size_t>(i)] = k[static_cast<std::size_t>(n)];
    }
    if (locus::validate_knots(std::span<const T>(k), d, n) == locus::Status::ok) return k;
  }
}

template <class T, int N>
std::vector<locus::Vec<T, N>> dyadic_points(locus_test::Rng& rng, int count) {
  std::vector<locus::Vec<T, N>> p;
  for (int i = 0; i < count; ++i) p.push_back(dyadic_vec<T, N>(rng));
  return p;
}

template <class T, int N>
T max_abs_points(const std::vector<locus::Vec<T, N>>& p) {
  T m = T(0);
  for (const auto& v : p) m = std::max(m, locus::max_abs(v));
  return m;
}

}  // namespace curve_oracle
