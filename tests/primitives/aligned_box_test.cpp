// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/aligned_box.hpp (row prim3.solids: AABB).
#include <locus/primitives/aligned_box.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <limits>
#include <type_traits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class AlignedBoxTest : public ::testing::Test {};
TYPED_TEST_SUITE(AlignedBoxTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<AlignedBox3d> && std::is_trivially_copyable_v<AlignedBox3f>);

namespace {
mpq_class q(double x) { return mpq_class(x); }
}  // namespace

TYPED_TEST(AlignedBoxTest, EmptyBoxConventions) {
  using T = TypeParam;
  const auto e = empty_box<T, 3>();
  EXPECT_TRUE(is_empty(e));
  EXPECT_EQ(measure(e), T(0));
  EXPECT_EQ(surface_area(e), T(0));
  const AlignedBox3<T> b{{1, 2, 3}, {4, 5, 6}};
  EXPECT_FALSE(is_empty(b));
  EXPECT_EQ(merge(e, b).min, b.min);
  EXPECT_EQ(merge(b, e).max, b.max);
  EXPECT_TRUE(is_empty(bounding_box(std::span<const Vec3<T>>())));
  // A point box is not empty and has zero measure.
  const AlignedBox3<T> p{{1, 1, 1}, {1, 1, 1}};
  EXPECT_FALSE(is_empty(p));
  EXPECT_EQ(volume(p), T(0));
  // NaN bounds make a box empty; an inverted box is empty.
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_TRUE(is_empty(AlignedBox3<T>{{nan, 0, 0}, {1, 1, 1}}));
  EXPECT_TRUE(is_empty(AlignedBox2<T>{{2, 0}, {1, 1}}));
  EXPECT_EQ(area(AlignedBox2<T>{{2, 0}, {1, 1}}), T(0));
  EXPECT_EQ(perimeter(AlignedBox2<T>{{2, 0}, {1, 1}}), T(0));
}

TYPED_TEST(AlignedBoxTest, BoundingBoxIsTightAgainstBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 200; ++trial) {
    const int n = rng.uniform_int(1, 40);
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < n; ++i) pts.push_back(rng.vec<T, 3>(-100, 100));
    if (trial % 3 == 0) pts.push_back({std::numeric_limits<T>::quiet_NaN(), T(0), T(0)});
    const auto b = bounding_box(std::span<const Vec3<T>>(pts));
    ASSERT_FALSE(is_empty(b));
    for (int k = 0; k < 3; ++k) {
      bool touch_min = false, touch_max = false;
      for (const auto& p : pts) {
        if (p[k] != p[k]) continue;  // NaN points are skipped by contract
        EXPECT_LE(b.min[k], p[k]);
        EXPECT_LE(p[k], b.max[k]);
        touch_min |= p[k] == b.min[k];
        touch_max |= p[k] == b.max[k];
      }
      EXPECT_TRUE(touch_min && touch_max);
    }
    // The pointer overload agrees.
    const auto b2 = bounding_box(pts.data(), pts.size());
    EXPECT_EQ(b2.min, b.min);
    EXPECT_EQ(b2.max, b.max);
  }
}

TYPED_TEST(AlignedBoxTest, MeasuresMatchExactRationals) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    auto a = rng.vec<T, 3>(-50, 50), c = rng.vec<T, 3>(-50, 50);
    const AlignedBox3<T> b{cwise_min(a, c), cwise_max(a, c)};
    mpq_class sx = q(b.max.x) - q(b.min.x), sy = q(b.max.y) - q(b.min.y),
              sz = q(b.max.z) - q(b.min.z);
    const double v = mpq_class(sx * sy * sz).get_d();
    const double s = mpq_class(2 * (sx * sy + sy * sz + sz * sx)).get_d();
    // Three rounded differences and two products: a few ulps of relative error.
    EXPECT_NEAR(double(volume(b)), v, double(tol<T>(8)) * v);
    EXPECT_NEAR(double(surface_area(b)), s, double(tol<T>(8)) * s);
    const AlignedBox2<T> b2{{b.min.x, b.min.y}, {b.max.x, b.max.y}};
    const double a2 = mpq_class(sx * sy).get_d(), p2 = mpq_class(2 * (sx + sy)).get_d();
    EXPECT_NEAR(double(area(b2)), a2, double(tol<T>(6)) * a2);
    EXPECT_NEAR(double(perimeter(b2)), p2, double(tol<T>(6)) * p2);
  }
}

TYPED_TEST(AlignedBoxTest, CornersAndParametrisation) {
  using T = TypeParam;
  const AlignedBox3<T> b{{-1, 2, -3}, {4, 5, 6}};
  const auto cs = corners(b);
  EXPECT_EQ(cs[0], b.min);
  EXPECT_EQ(cs[7], b.max);
  for (int k = 0; k < 8; ++k) {
    const Vec3<T> p{T(k & 1), T((k >> 1) & 1), T((k >> 2) & 1)};
    // point_at is exact at the parameter-space corners and agrees with the corner numbering.
    EXPECT_EQ(point_at(b, p), cs[static_cast<std::size_t>(k)]);
    for (int j = 0; j < k; ++j)
      EXPECT_FALSE(cs[static_cast<std::size_t>(j)] == cs[static_cast<std::size_t>(k)]);
  }
  EXPECT_EQ(point_at(b, Vec3<T>{T(0.5), T(0.5), T(0.5)}), center(b));
  EXPECT_EQ(extents(b), (Vec3<T>{T(2.5), T(1.5), T(4.5)}));
  EXPECT_EQ(size(b), (Vec3<T>{5, 3, 9}));
  // Volume from the corners: the extreme coordinates of the corner set span the box.
  const auto rebuilt = bounding_box(std::span<const Vec3<T>>(cs.data(), cs.size()));
  EXPECT_EQ(volume(rebuilt), volume(b));
  EXPECT_EQ(volume(b), T(135));
  EXPECT_EQ(surface_area(b), T(2 * (15 + 27 + 45)));
}

TYPED_TEST(AlignedBoxTest, MergeExpandInflateContainTheirInputs) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto inside = [](const AlignedBox3<T>& b, const Vec3<T>& p) {
    for (int i = 0; i < 3; ++i)
      if (!(b.min[i] <= p[i] && p[i] <= b.max[i])) return false;
    return true;
  };
  for (int trial = 0; trial < 300; ++trial) {
    auto a0 = rng.vec<T, 3>(-10, 10), a1 = rng.vec<T, 3>(-10, 10);
    auto c0 = rng.vec<T, 3>(-10, 10), c1 = rng.vec<T, 3>(-10, 10);
    const AlignedBox3<T> a{cwise_min(a0, a1), cwise_max(a0, a1)},
        c{cwise_min(c0, c1), cwise_max(c0, c1)};
    const auto m = merge(a, c);
    for (const auto& p : corners(a)) EXPECT_TRUE(inside(m, p));
    for (const auto& p : corners(c)) EXPECT_TRUE(inside(m, p));
    // Tight: each bound of m is a bound of a or c.
    for (int i = 0; i < 3; ++i) {
      EXPECT_TRUE(m.min[i] == a.min[i] || m.min[i] == c.min[i]);
      EXPECT_TRUE(m.max[i] == a.max[i] || m.max[i] == c.max[i]);
    }
    const auto p = rng.vec<T, 3>(-20, 20);
    EXPECT_TRUE(inside(expand(a, p), p));
    EXPECT_TRUE(inside(expand(a, p), a.min) && inside(expand(a, p), a.max));
    const T d = rng.uniform<T>(0, 2);
    const auto g = inflate(a, d);
    EXPECT_NEAR(double(size(g).x), double(size(a).x + 2 * d), double(tol<T>(64)));
    EXPECT_TRUE(is_empty(inflate(AlignedBox3<T>{{0, 0, 0}, {1, 1, 1}}, T(-0.75))));
  }
}
