// SPDX-License-Identifier: BSL-1.0
// Tests for core/vec.hpp (row core.tuple, core.products basics).
#include <locus/core/vec.hpp>

#include "support/typed.hpp"

#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class VecTest : public ::testing::Test {};
TYPED_TEST_SUITE(VecTest, locus_test::RealTypes);

static_assert(std::is_trivially_copyable_v<Vec3f> && std::is_standard_layout_v<Vec3f>);
static_assert(std::is_aggregate_v<Vec3d>);
static_assert(sizeof(Vec3f) == 3 * sizeof(float) && sizeof(Vec<double, 7>) == 7 * sizeof(double));
static_assert(dot(Vec3d{1, 2, 3}, Vec3d{4, 5, 6}) == 32.0, "constexpr dot");
static_assert(cross(Vec3d{1, 0, 0}, Vec3d{0, 1, 0}) == Vec3d{0, 0, 1}, "right-handed cross");
static_assert(perp(Vec2d{1, 0}) == Vec2d{0, 1}, "perp is counter-clockwise");

TYPED_TEST(VecTest, ArithmeticMatchesComponentwiseDefinition) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    auto a = rng.vec<T, 4>(-10, 10), b = rng.vec<T, 4>(-10, 10);
    T s = rng.uniform<T>(-3, 3);
    auto sum = a + b, diff = a - b, sc = a * s, neg = -a;
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(sum[i], a[i] + b[i]);
      EXPECT_EQ(diff[i], a[i] - b[i]);
      EXPECT_EQ(sc[i], a[i] * s);
      EXPECT_EQ(neg[i], -a[i]);
    }
    EXPECT_EQ(a * s, s * a);
  }
}

TYPED_TEST(VecTest, CrossProductIsOrthogonalWithSineLength) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    auto a = rng.vec<T, 3>(-1, 1), b = rng.vec<T, 3>(-1, 1);
    auto c = cross(a, b);
    EXPECT_NEAR(dot(c, a), T(0), tol<T>(16));
    EXPECT_NEAR(dot(c, b), T(0), tol<T>(16));
    // Lagrange's identity |a x b|^2 = |a|^2 |b|^2 - (a.b)^2.
    EXPECT_NEAR(sqr_length(c), sqr_length(a) * sqr_length(b) - sqr(dot(a, b)), tol<T>(64));
    EXPECT_EQ(cross(b, a), -c);
  }
}

TYPED_TEST(VecTest, PerpDotIsDotWithPerpAndAntisymmetric) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    auto a = rng.vec<T, 2>(-5, 5), b = rng.vec<T, 2>(-5, 5);
    EXPECT_EQ(perp_dot(a, b), dot(perp(a), b));
    EXPECT_EQ(perp_dot(a, b), -perp_dot(b, a));
    EXPECT_EQ(dot(perp(a), a), T(0));
  }
}

TYPED_TEST(VecTest, NormalizeIsSafeOnZeroNanInfAndTinyOrHuge) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_EQ(normalize(Vec3<T>{0, 0, 0}), (Vec3<T>{0, 0, 0}));
  EXPECT_EQ(normalize(Vec3<T>{nan, 1, 0}), (Vec3<T>{0, 0, 0}));
  EXPECT_EQ(normalize(Vec3<T>{inf, 1, 0}), (Vec3<T>{0, 0, 0}));
  EXPECT_EQ(normalize_with_length(Vec2<T>{0, 0}).length, T(0));
  const T tiny = std::numeric_limits<T>::denorm_min() * T(4);
  auto u = normalize(Vec2<T>{tiny, tiny});
  EXPECT_NEAR(u.x, std::sqrt(T(0.5)), tol<T>(4));
  const T huge = std::numeric_limits<T>::max() / T(2);
  auto n = normalize_with_length(Vec2<T>{huge, huge});
  EXPECT_NEAR(n.dir.y, std::sqrt(T(0.5)), tol<T>(4));
  EXPECT_TRUE(std::isfinite(n.length));
  EXPECT_NEAR(n.length / huge, std::sqrt(T(2)), tol<T>(4));
}

TYPED_TEST(VecTest, NormalizeGivesUnitLengthAndKeepsDirection) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    auto a = rng.vec<T, 3>(-100, 100);
    auto n = normalize_with_length(a);
    EXPECT_NEAR(length(n.dir), T(1), tol<T>(4));
    EXPECT_NEAR(length(cross(n.dir, a)), T(0), tol<T>(64, n.length));
    EXPECT_GT(dot(n.dir, a), T(0));
    EXPECT_NEAR(n.length, length(a), tol<T>(2, n.length));
  }
}

TYPED_TEST(VecTest, IndexingAndLayout) {
  using T = TypeParam;
  Vec4<T> v{1, 2, 3, 4};
  EXPECT_EQ(v[0], v.x);
  EXPECT_EQ(v[3], v.w);
  v[2] = 7;
  EXPECT_EQ(v.z, T(7));
  Vec<T, 6> big{{1, 2, 3, 4, 5, 6}};
  EXPECT_EQ(dot(big, big), T(91));
  const Vec3<T> pts[2] = {{1, 2, 3}, {4, 5, 6}};
  EXPECT_EQ(reinterpret_cast<const T*>(pts)[4], T(5));  // dense layout
  EXPECT_FALSE(is_finite(Vec2<T>{std::numeric_limits<T>::infinity(), 0}));
  EXPECT_EQ(max_abs(Vec3<T>{-5, 2, 3}), T(5));
  EXPECT_EQ(lerp(Vec2<T>{1, 1}, Vec2<T>{3, 5}, T(1)), (Vec2<T>{3, 5}));
}
