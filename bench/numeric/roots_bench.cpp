// SPDX-License-Identifier: BSL-1.0
// Quartic roots per second (row num.roots): random quartics with 0, 2 and 4 real roots, solved by
// locus::solve_quartic, and by Eigen's PolynomialSolver (companion-matrix eigenvalues, then the
// real ones) when Eigen's headers are found. Items per second = quartics per second.
#include <locus/numeric/roots.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
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

template <class T>
void BM_locus_solve_quartic(benchmark::State& state) {
  const auto qs = make_quartics(static_cast<int>(state.range(0)), 1024);
  std::vector<std::array<T, 5>> q;
  for (const auto& c : qs) q.push_back({T(c[0]), T(c[1]), T(c[2]), T(c[3]), T(c[4])});
  std::size_t i = 0;
  long roots = 0;
  for (auto _ : state) {
    const auto& c = q[i++ & 1023];
    const auto r = locus::solve_quartic(c[0], c[1], c[2], c[3], c[4]);
    roots += r.count;
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.counters["real_roots_per_quartic"] =
      benchmark::Counter(static_cast<double>(roots) / static_cast<double>(state.iterations()));
}
BENCHMARK_TEMPLATE(BM_locus_solve_quartic, double)->Arg(0)->Arg(2)->Arg(4);
BENCHMARK_TEMPLATE(BM_locus_solve_quartic, float)->Arg(0)->Arg(2)->Arg(4);

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
