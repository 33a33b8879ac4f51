// SPDX-License-Identifier: BSL-1.0
// Tests for core/mat.hpp (rows core.tuple, core.linsys closed forms).
#include <locus/core/mat.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <limits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class MatTest : public ::testing::Test {};
TYPED_TEST_SUITE(MatTest, locus_test::RealTypes);

static_assert(Mat3d::identity() * Vec3d{1, 2, 3} == Vec3d{1, 2, 3});
static_assert(std::is_trivially_copyable_v<Mat4f> && sizeof(Mat4f) == 16 * sizeof(float));

// Exact determinant by Laplace expansion in GMP rationals: an independent oracle.
template <class T, int N>
mpq_class exact_det(const Mat<T, N, N>& m) {
  if constexpr (N == 1) {
    return mpq_class(m.a[0][0]);
  } else {
    mpq_class d = 0;
    for (int j = 0; j < N; ++j) {
      Mat<T, N - 1, N - 1> minor{};
      for (int r = 1; r < N; ++r)
        for (int c = 0, cc = 0; c < N; ++c)
          if (c != j) minor.a[r - 1][cc++] = m.a[r][c];
      mpq_class t = mpq_class(m.a[0][j]) * exact_det(minor);
      d += (j % 2 == 0) ? t : mpq_class(-t);
    }
    return d;
  }
}

template <class T, int N>
void check_det_and_inverse(Rng& rng) {
  for (int k = 0; k < 2000; ++k) {
    Mat<T, N, N> m{};
    for (int r = 0; r < N; ++r)
      for (int c = 0; c < N; ++c) m.a[r][c] = rng.uniform<T>(-2, 2);
    const double exact = exact_det(m).get_d();
    T scale = 1;
    for (int i = 0; i < N; ++i) scale *= T(2) * T(N);  // Hadamard-like bound on term sizes
    EXPECT_NEAR(double(determinant(m)), exact, double(tol<T>(8, scale)));
    auto inv = inverse(m);
    if (std::abs(exact) < 1e-2) continue;  // ill-conditioned draws are the solvers' business
    ASSERT_TRUE(inv.has_value());
    auto prod = m * *inv;
    for (int r = 0; r < N; ++r)
      for (int c = 0; c < N; ++c)
        EXPECT_NEAR(prod.a[r][c], r == c ? T(1) : T(0), tol<T>(64, scale * T(100)));
  }
}

TYPED_TEST(MatTest, DeterminantAgreesWithExactRationalAndInverseInverts) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  check_det_and_inverse<TypeParam, 2>(rng);
  check_det_and_inverse<TypeParam, 3>(rng);
  check_det_and_inverse<TypeParam, 4>(rng);
}

TYPED_TEST(MatTest, ExactSmallIntegerMatricesGiveExactDeterminant) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    Mat4<T> m{};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m.a[r][c] = T(rng.uniform_int(-9, 9));
    EXPECT_EQ(double(determinant(m)), exact_det(m).get_d());
  }
}

TYPED_TEST(MatTest, SingularAndNonFiniteMatricesHaveNoInverse) {
  using T = TypeParam;
  Mat3<T> singular = Mat3<T>::from_rows(Vec3<T>{1, 2, 3}, Vec3<T>{2, 4, 6}, Vec3<T>{0, 1, 1});
  EXPECT_EQ(determinant(singular), T(0));
  EXPECT_FALSE(inverse(singular).has_value());
  EXPECT_FALSE(inverse(Mat4<T>::zero()).has_value());
  Mat2<T> nan_m = Mat2<T>::identity();
  nan_m.a[0][1] = std::numeric_limits<T>::quiet_NaN();
  EXPECT_FALSE(inverse(nan_m).has_value());
}

TYPED_TEST(MatTest, ProductTransposeAndRowColAccess) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 500; ++k) {
    Mat<T, 2, 3> a{};
    Mat<T, 3, 4> b{};
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 3; ++c) a.a[r][c] = T(rng.uniform_int(-5, 5));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) b.a[r][c] = T(rng.uniform_int(-5, 5));
    auto p = a * b;
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(p(r, c), dot(row(a, r), col(b, c)));
    EXPECT_EQ(transpose(p), transpose(b) * transpose(a));
    auto v = rng.vec<T, 3>(-1, 1);
    EXPECT_EQ(skew(v) * v, (Vec3<T>{0, 0, 0}));
  }
  auto m = Mat3<T>::from_cols(Vec3<T>{1, 2, 3}, Vec3<T>{4, 5, 6}, Vec3<T>{7, 8, 9});
  EXPECT_EQ(m(2, 1), T(6));
  EXPECT_EQ(trace(m), T(15));
  EXPECT_EQ(outer(Vec2<T>{1, 2}, Vec2<T>{3, 4})(1, 0), T(6));
}
