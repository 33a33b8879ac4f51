// SPDX-License-Identifier: BSL-1.0
// Quartic roots per second (row num.roots): random quartics with 0, 2 and 4 real roots, solved by
// locus::solve_quartic in near mode (its default) and in exact mode, and by Eigen's
// PolynomialSolver (companion-matrix eigenvalues, then the real ones) when Eigen's headers are
// found; and real_roots of degree 8 and 16 in both modes. Items per second = polynomials per
// second.
#include <locus/numeric/roots.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#if __has_include(<eigen3/unsupported/Eigen/Polynomials>)
#include <eigen3/unsupported/Eigen/Polynomials>
#define LOCUS_BENCH_HAVE_EIGEN 1
#endif

namespace {

// (x - r1)(x - r2)... times irreducible quadratics, low to high, leading coefficient 1.
std::vector<std::array<double, 5>> make_quartics(int real_roots, int count) {
  std::mt19937_64 rng(12345 + static_cast<unsigned>(real_roots));
  std::uniform_real_distribution<double> u(-10.0, 10.0), pos(0.1, 10.0);
  std::vector<std::array<double, 5>> out;
  for (int k = 0; k < count; ++k) {
    std::array<double, 5> c{1, 0, 0, 0, 0};
    int deg = 0;
    const auto mul = [&](double c0, double c1, double c2) {  // by c0 + c1 x + c2 x^2
      std::array<double, 5> r{};
      for (int i = 0; i <= deg; ++i) {
        r[static_cast<std::size_t>(i)] += c0 * c[static_cast<std::size_t>(i)];
        if (i + 1 <= 4) r[static_cast<std::size_t>(i + 1)] += c1 * c[static_cast<std::size_t>(i)];
        if (i + 2 <= 4) r[static_cast<std::size_t>(i + 2)] += c2 * c[static_cast<std::size_t>(i)];
      }
      c = r;
      deg += c2 != 0 ? 2 : 1;
    };
    for (int i = 0; i < real_roots; ++i) mul(-u(rng), 1, 0);
    for (int i = real_roots; i < 4; i += 2) {
      const double re = u(rng), im = pos(rng);
      mul(re * re + im * im, -2 * re, 1);
    }
    out.push_back(c);
  }
  return out;
}

template <class T, bool Exact = false>
void BM_locus_solve_quartic(benchmark::State& state) {
  const auto qs = make_quartics(static_cast<int>(state.range(0)), 1024);
  std::vector<std::array<T, 5>> q;
  for (const auto& c : qs) q.push_back({T(c[0]), T(c[1]), T(c[2]), T(c[3]), T(c[4])});
  std::size_t i = 0;
  long roots = 0;
  for (auto _ : state) {
    const auto& c = q[i++ & 1023];
    locus::RootOptions opt;
    opt.mode = Exact ? locus::RootMode::exact : locus::RootMode::near;
    const auto r = locus::solve_quartic(c[0], c[1], c[2], c[3], c[4], opt);
    roots += r.count;
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.counters["real_roots_per_quartic"] =
      benchmark::Counter(static_cast<double>(roots) / static_cast<double>(state.iterations()));
}
BENCHMARK_TEMPLATE(BM_locus_solve_quartic, double)->Arg(0)->Arg(2)->Arg(4);
BENCHMARK_TEMPLATE(BM_locus_solve_quartic, float)->Arg(0)->Arg(2)->Arg(4);
BENCHMARK_TEMPLATE(BM_locus_solve_quartic, double, true)->Arg(0)->Arg(2)->Arg(4);
BENCHMARK_TEMPLATE(BM_locus_solve_quartic, float, true)->Arg(0)->Arg(2)->Arg(4);

// Degree n (8 or 16) with n / 2 real roots in [-10, 10] and n / 4 complex pairs, expanded in
// double: real_roots in near and exact mode.
template <bool Exact>
void BM_locus_real_roots(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::mt19937_64 rng(777 + static_cast<unsigned>(n));
  std::uniform_real_distribution<double> u(-10.0, 10.0), pos(0.1, 10.0);
  std::vector<std::vector<double>> polys;
  for (int k = 0; k < 64; ++k) {
    std::vector<double> c{1.0};
    const auto mul = [&](double c0, double c1, double c2) {
      std::vector<double> r(c.size() + 2, 0.0);
      for (std::size_t i = 0; i < c.size(); ++i) {
        r[i] += c0 * c[i];
        r[i + 1] += c1 * c[i];
        r[i + 2] += c2 * c[i];
      }
      while (r.back() == 0.0) r.pop_back();
      c = r;
    };
    for (int i = 0; i < n / 2; ++i) mul(-u(rng), 1, 0);
    for (int i = 0; i < n / 4; ++i) {
      const double re = u(rng), im = pos(rng);
      mul(re * re + im * im, -2 * re, 1);
    }
    polys.push_back(c);
  }
  locus::RootOptions opt;
  opt.mode = Exact ? locus::RootMode::exact : locus::RootMode::near;
  std::size_t i = 0;
  long roots = 0;
  for (auto _ : state) {
    const auto r = locus::real_roots(polys[i++ & 63], -std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::infinity(), opt);
    roots += static_cast<long>(r.roots.size());
    benchmark::DoNotOptimize(r.roots.data());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.counters["real_roots"] =
      benchmark::Counter(static_cast<double>(roots) / static_cast<double>(state.iterations()));
}
BENCHMARK_TEMPLATE(BM_locus_real_roots, false)->Arg(8)->Arg(16);
BENCHMARK_TEMPLATE(BM_locus_real_roots, true)->Arg(8)->Arg(16);

#ifdef LOCUS_BENCH_HAVE_EIGEN
void BM_eigen_polynomial_solver(benchmark::State& state) {
  const auto qs = make_quartics(static_cast<int>(state.range(0)), 1024);
  Eigen::PolynomialSolver<double, 4> solver;
  std::size_t i = 0;
  long roots = 0;
  for (auto _ : state) {
    const auto& c = qs[i++ & 1023];
    Eigen::Matrix<double, 5, 1> p;
    p << c[0], c[1], c[2], c[3], c[4];
    solver.compute(p);
    std::vector<double> real;
    solver.realRoots(real);
    roots += static_cast<long>(real.size());
    benchmark::DoNotOptimize(real.data());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.counters["real_roots_per_quartic"] =
      benchmark::Counter(static_cast<double>(roots) / static_cast<double>(state.iterations()));
}
BENCHMARK(BM_eigen_polynomial_solver)->Arg(0)->Arg(2)->Arg(4);
#endif

}  // namespace
