// SPDX-License-Identifier: BSL-1.0
// Cost of the exact predicates (row core.predicates) against the naive double determinant, on
// random input (the filter decides) and on nearly degenerate input (the adaptive fallback runs).
// Each benchmark loops over 1024 precomputed cases; items/s is predicates per second, so the
// ratio of two benchmarks' ns per item is the ratio of their times.
// Target (issue): orient2d on random input within 1.3x of the naive determinant.
#include <locus/core/predicates.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {

using locus::Sign;
using locus::Vec2;
using locus::Vec3;

constexpr int cases = 1024;

template <class V, int P>
using Case = std::array<V, P>;

// The naive determinants: the filter's expression without its error bound.
inline Sign naive_orient2d(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c) {
  return locus::sign_of(locus::orient2d_value(a, b, c));
}
inline Sign naive_orient3d(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                           const Vec3<double>& d) {
  return locus::sign_of(locus::orient3d_value(a, b, c, d));
}
inline Sign naive_incircle(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
                           const Vec2<double>& d) {
  return locus::sign_of(locus::incircle_value(a, b, c, d));
}
inline Sign naive_insphere(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                           const Vec3<double>& d, const Vec3<double>& e) {
  return locus::sign_of(locus::insphere_value(a, b, c, d, e));
}

std::mt19937_64& engine() {
  static std::mt19937_64 g(20261122);
  return g;
}
double uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(engine());
}
int uniform_int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine()); }
double bump(double x) {
  const int k = uniform_int(-2, 2);
  for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, k > 0 ? 1e300 : -1e300);
  return x;
}

template <int D>
locus::Vec<double, D> random_point(double lo, double hi) {
  locus::Vec<double, D> v{};
  for (int k = 0; k < D; ++k) v[k] = uniform(lo, hi);
  return v;
}

template <int D, int P>
std::vector<Case<locus::Vec<double, D>, P>> random_cases() {
  std::vector<Case<locus::Vec<double, D>, P>> v(cases);
  for (auto& c : v)
    for (auto& p : c) p = random_point<D>(-1.0, 1.0);
  return v;
}

// Nearly degenerate: the last point lies on the line / plane through the others (orient) or on
// the circle / sphere through all (in*) up to rounding, then moves by up to two ulps.
template <int D, int P, bool Sphere>
std::vector<Case<locus::Vec<double, D>, P>> degenerate_cases() {
  std::vector<Case<locus::Vec<double, D>, P>> v(cases);
  for (auto& c : v) {
    if constexpr (Sphere) {
      const auto center = random_point<D>(-1.0, 1.0);
      const double r = uniform(0.1, 1.0);
      for (auto& p : c) {
        locus::Vec<double, D> u{};
        double len = 0.0;
        do {
          u = random_point<D>(-1.0, 1.0);
          len = std::sqrt(locus::sqr_length(u));
        } while (len < 0.1 || len > 1.0);
        p = center + (r / len) * u;
      }
    } else {
      for (int i = 0; i < D; ++i) c[std::size_t(i)] = random_point<D>(-1.0, 1.0);
      locus::Vec<double, D> q = c[0];
      for (int j = 1; j < D; ++j) q = q + uniform(-1.0, 2.0) * (c[std::size_t(j)] - c[0]);
      c[P - 1] = q;
    }
    for (int k = 0; k < D; ++k) c[P - 1][k] = bump(c[P - 1][k]);
  }
  return v;
}

const auto o2_random = random_cases<2, 3>();
const auto o2_degenerate = degenerate_cases<2, 3, false>();
const auto o3_random = random_cases<3, 4>();
const auto o3_degenerate = degenerate_cases<3, 4, false>();
const auto ic_random = random_cases<2, 4>();
const auto ic_degenerate = degenerate_cases<2, 4, true>();
const auto is_random = random_cases<3, 5>();
const auto is_degenerate = degenerate_cases<3, 5, true>();

template <class Cases, class F>
void run(benchmark::State& state, const Cases& data, F f) {
  for (auto _ : state) {
    for (const auto& c : data) {
      Sign s = f(c);
      benchmark::DoNotOptimize(s);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(data.size()));
}

#define LOCUS_PRED_BENCH(name, data, call)                \
  void name(benchmark::State& state) {                    \
    run(state, data, [](const auto& c) { return call; }); \
  }                                                       \
  BENCHMARK(name)

LOCUS_PRED_BENCH(BM_orient2d_naive_random, o2_random, naive_orient2d(c[0], c[1], c[2]));
LOCUS_PRED_BENCH(BM_orient2d_exact_random, o2_random, locus::orient2d(c[0], c[1], c[2]));
LOCUS_PRED_BENCH(BM_orient2d_naive_degenerate, o2_degenerate, naive_orient2d(c[0], c[1], c[2]));
LOCUS_PRED_BENCH(BM_orient2d_exact_degenerate, o2_degenerate, locus::orient2d(c[0], c[1], c[2]));

LOCUS_PRED_BENCH(BM_orient3d_naive_random, o3_random, naive_orient3d(c[0], c[1], c[2], c[3]));
LOCUS_PRED_BENCH(BM_orient3d_exact_random, o3_random, locus::orient3d(c[0], c[1], c[2], c[3]));
LOCUS_PRED_BENCH(BM_orient3d_naive_degenerate, o3_degenerate,
                 naive_orient3d(c[0], c[1], c[2], c[3]));
LOCUS_PRED_BENCH(BM_orient3d_exact_degenerate, o3_degenerate,
                 locus::orient3d(c[0], c[1], c[2], c[3]));

LOCUS_PRED_BENCH(BM_incircle_naive_random, ic_random, naive_incircle(c[0], c[1], c[2], c[3]));
LOCUS_PRED_BENCH(BM_incircle_exact_random, ic_random, locus::incircle(c[0], c[1], c[2], c[3]));
LOCUS_PRED_BENCH(BM_incircle_naive_degenerate, ic_degenerate,
                 naive_incircle(c[0], c[1], c[2], c[3]));
LOCUS_PRED_BENCH(BM_incircle_exact_degenerate, ic_degenerate,
                 locus::incircle(c[0], c[1], c[2], c[3]));

LOCUS_PRED_BENCH(BM_insphere_naive_random, is_random, naive_insphere(c[0], c[1], c[2], c[3], c[4]));
LOCUS_PRED_BENCH(BM_insphere_exact_random, is_random,
                 locus::insphere(c[0], c[1], c[2], c[3], c[4]));
LOCUS_PRED_BENCH(BM_insphere_naive_degenerate, is_degenerate,
                 naive_insphere(c[0], c[1], c[2], c[3], c[4]));
LOCUS_PRED_BENCH(BM_insphere_exact_degenerate, is_degenerate,
                 locus::insphere(c[0], c[1], c[2], c[3], c[4]));

}  // namespace
