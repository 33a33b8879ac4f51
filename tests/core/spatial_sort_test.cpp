// SPDX-License-Identifier: BSL-1.0
// Tests for core/detail/spatial_sort.hpp (the Hilbert / BRIO order shared by Delaunay 2D and 3D).

#include <locus/core/detail/spatial_sort.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace {

using namespace locus;

template <class T>
class SpatialSortTest : public ::testing::Test {};
using Reals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(SpatialSortTest, Reals);

template <class T, int N>
std::vector<Vec<T, N>> random_points(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec<T, N>> p(n);
  for (auto& q : p)
    for (int i = 0; i < N; ++i) q[i] = static_cast<T>(u(rng));
  return p;
}

template <class T, int N>
std::vector<std::uint32_t> order_of(const std::vector<Vec<T, N>>& p) {
  std::vector<std::uint32_t> order;
  std::vector<std::uint64_t> keys, tmp;
  detail::brio_order(std::span<const Vec<T, N>>(p), order, keys, tmp);
  return order;
}

template <class T, int N>
double distance(const Vec<T, N>& a, const Vec<T, N>& b) {
  double s = 0.0;
  for (int i = 0; i < N; ++i) s += (double(a[i]) - double(b[i])) * (double(a[i]) - double(b[i]));
  return std::sqrt(s);
}

// The order is a permutation, the same on a second call, the rounds are contiguous and of the
// documented sizes, and consecutive points of the last round are near (their mean step is a
// small multiple of the grid spacing, and far below the mean distance of random pairs).
template <class T, int N>
void check_order(std::size_t n, std::uint32_t seed) {
  SCOPED_TRACE(::testing::Message() << "N " << N << " n " << n << " seed " << seed);
  const std::vector<Vec<T, N>> p = random_points<T, N>(n, seed);
  const std::vector<std::uint32_t> order = order_of<T, N>(p);
  ASSERT_EQ(order.size(), n);
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i);
  EXPECT_EQ((order_of<T, N>(p)), order);  // deterministic

  const unsigned rounds = detail::brio_rounds(n);
  EXPECT_GE(rounds, 1u);
  EXPECT_LE(n >> (3 * rounds), 256u);
  if (rounds > 1) {
    EXPECT_GT(n >> (3 * (rounds - 1)), 256u);
  }
  std::vector<std::size_t> size(rounds, 0);
  unsigned previous = 0;
  for (const std::uint32_t i : order) {
    const unsigned r = detail::brio_round(i, rounds);
    ASSERT_LT(r, rounds);
    ASSERT_GE(r, previous);  // rounds are contiguous, first round first
    previous = r;
    ++size[r];
  }
  // Round rounds - 1 - j holds about 7/8 * 8^-j of the points (binomial: 5 sigma).
  for (unsigned j = 0; j + 1 < rounds; ++j) {
    const double pj = 7.0 / 8.0 * std::pow(8.0, -double(j));
    const double expect = pj * double(n);
    const double sigma = std::sqrt(double(n) * pj * (1.0 - pj));
    EXPECT_NEAR(double(size[rounds - 1 - j]), expect, 5.0 * sigma + 1.0) << "round " << j;
  }

  // Locality along the last round against random pairs (for sets large enough that the grid
  // is fine and the last round holds most of the points).
  if (n < 5000) return;
  const std::size_t first_last = n - size[rounds - 1];
  double step = 0.0, random_pair = 0.0;
  for (std::size_t k = first_last + 1; k < n; ++k) {
    step += distance(p[order[k - 1]], p[order[k]]);
    random_pair += distance(p[order[k]], p[order[(k * 7919) % n]]);
  }
  EXPECT_LT(step, 0.1 * random_pair);
  // The grid has at least n cells of side about 2 n^(-1/N): a Hilbert step between points in
  // adjacent cells is a few cells; allow 4 on average.
  const double cell = 2.0 * std::pow(double(n), -1.0 / N);
  EXPECT_LT(step / double(n - first_last - 1), 4.0 * cell);
}

TYPED_TEST(SpatialSortTest, BrioOrder2) {
  for (const std::size_t n : {1u, 2u, 100u, 5000u, 40000u}) check_order<TypeParam, 2>(n, 11);
}

TYPED_TEST(SpatialSortTest, BrioOrder3) {
  for (const std::size_t n : {1u, 3u, 300u, 5000u, 40000u}) check_order<TypeParam, 3>(n, 12);
}

TYPED_TEST(SpatialSortTest, EmptyAndCoincident) {
  std::vector<Vec2<TypeParam>> none;
  EXPECT_TRUE((order_of<TypeParam, 2>(none).empty()));
  const std::vector<Vec3<TypeParam>> same(20, Vec3<TypeParam>{1, 2, 3});
  const std::vector<std::uint32_t> order = order_of<TypeParam, 3>(same);
  ASSERT_EQ(order.size(), 20u);
  // One cell: the order is by round, then by index.
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < 20; ++i) EXPECT_EQ(sorted[i], i);
}

// The Hilbert indices are a bijection of the grid onto 0 .. 4^L - 1 (8^L) and consecutive
// positions are adjacent cells (the defining property of the curve).
TEST(HilbertIndex, TwoDimensionsIsAContinuousBijection) {
  for (int levels = 1; levels <= 6; ++levels) {
    const std::uint32_t side = 1u << levels;
    std::vector<std::pair<int, int>> cell(std::size_t(side) * side, {-1, -1});
    for (std::uint32_t x = 0; x < side; ++x)
      for (std::uint32_t y = 0; y < side; ++y) {
        const std::uint32_t d = detail::hilbert_index2(x, y, levels);
        ASSERT_LT(d, side * side);
        ASSERT_EQ(cell[d].first, -1) << "index " << d << " twice";
        cell[d] = {int(x), int(y)};
      }
    for (std::size_t d = 1; d < cell.size(); ++d)
      EXPECT_EQ(std::abs(cell[d].first - cell[d - 1].first) +
                    std::abs(cell[d].second - cell[d - 1].second),
                1)
          << "levels " << levels << " d " << d;
  }
}

TEST(HilbertIndex, ThreeDimensionsIsAContinuousBijection) {
  for (int levels = 1; levels <= 4; ++levels) {
    const std::uint32_t side = 1u << levels;
    std::vector<std::array<int, 3>> cell(std::size_t(side) * side * side, {-1, -1, -1});
    for (std::uint32_t x = 0; x < side; ++x)
      for (std::uint32_t y = 0; y < side; ++y)
        for (std::uint32_t z = 0; z < side; ++z) {
          const std::uint32_t d = detail::hilbert_index3(x, y, z, levels);
          ASSERT_LT(d, side * side * side);
          ASSERT_EQ(cell[d][0], -1) << "index " << d << " twice";
          cell[d] = {int(x), int(y), int(z)};
        }
    for (std::size_t d = 1; d < cell.size(); ++d) {
      int manhattan = 0;
      for (int i = 0; i < 3; ++i) manhattan += std::abs(cell[d][i] - cell[d - 1][i]);
      EXPECT_EQ(manhattan, 1) << "levels " << levels << " d " << d;
    }
  }
}

}  // namespace
