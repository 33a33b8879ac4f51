// SPDX-License-Identifier: BSL-1.0
// Tests for core/affine.hpp (row core.affine; figures 3.23-3.26, 4.1, 4.2).
#include <locus/core/affine.hpp>
#include <locus/core/mat.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class AffineTest : public ::testing::Test {};
TYPED_TEST_SUITE(AffineTest, locus_test::RealTypes);

static_assert(to_homogeneous_point(Vec2d{3, 4}) == Vec3d{3, 4, 1});
static_assert(to_homogeneous_vector(Vec3d{3, 4, 5}) == Vec4d{3, 4, 5, 0});
static_assert(std::is_aggregate_v<AffineCombination<double, 3>>);

// Figures 4.1 and 4.2: a point is (p, 1), a vector (v, 0); a translation moves only points.
TYPED_TEST(AffineTest, Fig4_1And4_2PointsMoveVectorsDoNot) {
  using T = TypeParam;
  const Vec3<T> t{5, -2, 7};
  Mat4<T> m = Mat4<T>::identity();
  for (int r = 0; r < 3; ++r) m(r, 3) = t[r];
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 500; ++n) {
    const auto p = rng.vec<T, 3>(-10, 10);
    const auto hp = to_homogeneous_point(p), hv = to_homogeneous_vector(p);
    EXPECT_EQ(hp.w, T(1));
    EXPECT_EQ(hv.w, T(0));
    const auto mp = from_homogeneous(m * hp), mv = from_homogeneous(m * hv);
    EXPECT_TRUE(mp.is_point);
    EXPECT_FALSE(mv.is_point);
    EXPECT_EQ(mp.value, p + t);  // w = 1: no rounding beyond the sum
    EXPECT_EQ(mv.value, p);
    EXPECT_EQ(from_homogeneous(hp).value, p);
  }
}

TYPED_TEST(AffineTest, FromHomogeneousDividesByWAndHandlesZeroAndNaN) {
  using T = TypeParam;
  const auto a = from_homogeneous(Vec3<T>{6, -3, 2});
  EXPECT_TRUE(a.is_point);
  EXPECT_EQ(a.value, (Vec2<T>{3, T(-1.5)}));
  const auto z = from_homogeneous(Vec4<T>{1, 2, 3, 0});
  EXPECT_FALSE(z.is_point);
  EXPECT_EQ(z.value, (Vec3<T>{1, 2, 3}));
  const auto nz = from_homogeneous(Vec4<T>{1, 2, 3, -T(0)});
  EXPECT_FALSE(nz.is_point);
  EXPECT_TRUE(is_finite(nz.value));
  const auto nn = from_homogeneous(Vec3<T>{1, 2, std::numeric_limits<T>::quiet_NaN()});
  EXPECT_TRUE(nn.is_point);
  EXPECT_FALSE(is_finite(nn.value));
  // General w: each coordinate is the correctly rounded quotient.
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const auto h = rng.vec<T, 4>(-5, 5);
    if (h.w == T(0)) continue;
    const auto d = from_homogeneous(h);
    for (int i = 0; i < 3; ++i) {
      const double q = mpq_class(mpq_class(h[i]) / mpq_class(h.w)).get_d();
      EXPECT_NEAR(double(d.value[i]), q, double(tol<T>(1, std::abs(d.value[i]))));
    }
  }
}

// Figures 3.23-3.24: point subtraction is a vector; head-to-tail (Q - P) + (R - Q) = R - P.
TYPED_TEST(AffineTest, Fig3_23And3_24PointSubtractionHeadToTail) {
  using T = TypeParam;
  const Vec2<T> p{1, 2}, q{4, -1}, r{-3, 5};
  EXPECT_EQ((q - p) + (r - q), r - p);
  EXPECT_EQ(p + (q - p), q);
}

// Figure 3.25: the affine combination of two points is the lerp (1 - t) P + t Q.
TYPED_TEST(AffineTest, Fig3_25TwoPointCombinationIsLerp) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 500; ++n) {
    const auto p = rng.vec<T, 3>(-10, 10), q = rng.vec<T, 3>(-10, 10);
    const T t = rng.uniform<T>(-1, 2);
    const auto c = affine_combination(std::array<Vec3<T>, 2>{p, q}, std::array<T, 2>{T(1) - t, t});
    ASSERT_EQ(c.status, Status::ok);
    EXPECT_TRUE(locus_test::vec_near(c.point, lerp(p, q, t), tol<T>(8, T(30))));
  }
}

// Figure 3.26: affine combination of several points, against exact rational arithmetic.
TYPED_TEST(AffineTest, Fig3_26SeveralPointsMatchExactSum) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 500; ++n) {
    const std::size_t k = static_cast<std::size_t>(rng.uniform_int(1, 12));
    std::vector<Vec3<T>> pts(k);
    std::vector<T> w(k);
    T rest = T(1), scale = T(0);
    for (std::size_t i = 0; i < k; ++i) {
      pts[i] = rng.vec<T, 3>(-10, 10);
      w[i] = i + 1 < k ? rng.uniform<T>(-1, 1) : rest;
      rest -= w[i];
    }
    for (std::size_t i = 0; i < k; ++i) scale += std::abs(w[i]) * T(10);
    const auto c = affine_combination(pts.data(), w.data(), k);
    ASSERT_EQ(c.status, Status::ok);
    for (int j = 0; j < 3; ++j) {
      mpq_class e = 0;
      for (std::size_t i = 0; i < k; ++i) e += mpq_class(w[i]) * mpq_class(pts[i][j]);
      EXPECT_NEAR(double(c.point[j]), e.get_d(), double(tol<T>(T(2 * k + 2), scale)));
    }
    // Translation invariance (the defining property of an affine combination).
    const Vec3<T> shift{T(100), T(-50), T(25)};
    std::vector<Vec3<T>> moved(pts);
    for (auto& p : moved) p += shift;
    const auto cm = affine_combination(moved.data(), w.data(), k);
    EXPECT_TRUE(
        locus_test::vec_near(cm.point - shift, c.point, tol<T>(T(4 * k + 8), scale + T(200))));
  }
}

TYPED_TEST(AffineTest, BadWeightsEmptyAndNonFiniteInput) {
  using T = TypeParam;
  const std::array<Vec2<T>, 3> p{Vec2<T>{0, 0}, Vec2<T>{4, 0}, Vec2<T>{0, 4}};
  EXPECT_EQ(affine_combination(p.data(), static_cast<const T*>(nullptr), 0).status,
            Status::empty_input);
  // Weights summing to 2: not affine; the returned point uses w0 := 1 - w1 - w2.
  const auto bad = affine_combination(p, std::array<T, 3>{T(1), T(0.5), T(0.5)});
  EXPECT_EQ(bad.status, Status::degenerate_input);
  EXPECT_EQ(bad.point, (Vec2<T>{2, 2}));
  // A weight sum off by a few rounding errors is accepted; off by 1e-3 it is not.
  const T third = T(1) / T(3);
  EXPECT_EQ(affine_combination(p, std::array<T, 3>{third, third, third}).status, Status::ok);
  EXPECT_EQ(affine_combination(p, std::array<T, 3>{third, third, third + T(1e-3)}).status,
            Status::degenerate_input);
  EXPECT_EQ(affine_combination(p, std::array<T, 3>{third, third, third + T(1e-3)}, T(1e-2)).status,
            Status::ok);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const auto nw = affine_combination(p, std::array<T, 3>{nan, T(0.5), T(0.5)});
  EXPECT_EQ(nw.status, Status::non_finite_input);
  EXPECT_EQ(nw.point, (Vec2<T>{}));
  const std::array<Vec2<T>, 2> inf_pts{Vec2<T>{std::numeric_limits<T>::infinity(), 0},
                                       Vec2<T>{0, 0}};
  EXPECT_EQ(affine_combination(inf_pts, std::array<T, 2>{T(0), T(1)}).status,
            Status::non_finite_input);
  // A single point with weight 1 is itself.
  const auto one =
      affine_combination(std::array<Vec2<T>, 1>{Vec2<T>{3, 4}}, std::array<T, 1>{T(1)});
  EXPECT_EQ(one.status, Status::ok);
  EXPECT_EQ(one.point, (Vec2<T>{3, 4}));
}
