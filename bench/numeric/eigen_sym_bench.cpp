// SPDX-License-Identifier: BSL-1.0
// Symmetric 3x3 eigendecomposition: locus's closed form against Eigen, measured in the same run.
// Eigen's SelfAdjointEigenSolver::computeDirect is its closed-form 3x3 path (fast, less
// accurate on clustered eigenvalues); compute() is its iterative QR (accurate).
#include <locus/numeric/eigen_sym.hpp>

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#if defined(LOCUS_HAVE_EIGEN)
#include <Eigen/Dense>
#endif

namespace {

std::vector<locus::Mat3d> inputs() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<locus::Mat3d> m(4096);
  for (auto& a : m)
    for (int r = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c) a(r, c) = a(c, r) = u(rng);
  return m;
}

void BM_locus_eigen3(benchmark::State& state) {
  const auto m = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    auto e = locus::eigen_symmetric(m[i++ & 4095]);
    benchmark::DoNotOptimize(e);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_locus_eigen3);

#if defined(LOCUS_HAVE_EIGEN)
std::vector<Eigen::Matrix3d> eigen_inputs() {
  std::vector<Eigen::Matrix3d> out;
  for (const auto& a : inputs()) {
    Eigen::Matrix3d e;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) e(r, c) = a(r, c);
    out.push_back(e);
  }
  return out;
}

void BM_eigen_eigen3_direct(benchmark::State& state) {
  const auto m = eigen_inputs();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  std::size_t i = 0;
  for (auto _ : state) {
    solver.computeDirect(m[i++ & 4095]);
    benchmark::DoNotOptimize(solver.eigenvectors().data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_eigen_eigen3_direct);

void BM_eigen_eigen3_iterative(benchmark::State& state) {
  const auto m = eigen_inputs();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  std::size_t i = 0;
  for (auto _ : state) {
    solver.compute(m[i++ & 4095]);
    benchmark::DoNotOptimize(solver.eigenvectors().data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_eigen_eigen3_iterative);
#endif

}  // namespace
