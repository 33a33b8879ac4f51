// SPDX-License-Identifier: BSL-1.0
// Tests for core/products.hpp (row core.products; figures 3.15, 3.27-3.34, 4.3-4.5).
#include <locus/core/products.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class ProductsTest : public ::testing::Test {};
TYPED_TEST_SUITE(ProductsTest, locus_test::RealTypes);

namespace {

long double to_ld(const mpf_class& x) {
  const double hi = x.get_d();
  const mpf_class rest = x - hi;
  return static_cast<long double>(hi) + static_cast<long double>(rest.get_d());
}

template <class T, int N>
mpq_class qdot(const Vec<T, N>& a, const Vec<T, N>& b) {
  mpq_class s = 0;
  for (int i = 0; i < N; ++i) s += mpq_class(a[i]) * mpq_class(b[i]);
  return s;
}

// Oracle angle: atan2(sqrt(|a|^2 |b|^2 - (a.b)^2), a.b) with the radicand exact (Lagrange's
// identity in rationals) and the root in 256-bit floating point.
template <class T, int N>
long double exact_angle(const Vec<T, N>& a, const Vec<T, N>& b) {
  const mpq_class d = qdot(a, b);
  const mpq_class s2 = qdot(a, a) * qdot(b, b) - d * d;
  mpf_class fs(s2, 256), fd(d, 256);
  fs = sqrt(fs);
  // Scale both by the same factor before converting so tiny/huge inputs stay representable.
  const mpf_class m = abs(fs) + abs(fd);
  if (m == 0) return 0;
  return std::atan2(to_ld(fs / m), to_ld(fd / m));
}

template <class T>
mpq_class exact_det3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  const mpq_class ax(a.x), ay(a.y), az(a.z), bx(b.x), by(b.y), bz(b.z), cx(c.x), cy(c.y), cz(c.z);
  return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}

}  // namespace

// Figures 3.33-3.34: the scalar triple product is the signed volume of the parallelepiped.
TYPED_TEST(ProductsTest, Fig3_33TripleProductIsSignedVolume) {
  using T = TypeParam;
  const Vec3<T> i{1, 0, 0}, j{0, 1, 0}, k{0, 0, 1};
  EXPECT_EQ(triple_product(i, j, k), T(1));
  EXPECT_EQ(triple_product(j, i, k), T(-1));
  EXPECT_EQ(triple_product(Vec3<T>{2, 0, 0}, Vec3<T>{1, 3, 0}, Vec3<T>{5, -1, 4}), T(24));
  EXPECT_EQ(triple_product(i, j, Vec3<T>{1, 1, 0}), T(0));  // coplanar: zero volume
  EXPECT_TRUE(std::isnan(triple_product(i, j, Vec3<T>{0, 0, std::numeric_limits<T>::quiet_NaN()})));
}

TYPED_TEST(ProductsTest, TripleProductMatchesExactDeterminant) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2000; ++n) {
    const auto a = rng.vec<T, 3>(-4, 4), b = rng.vec<T, 3>(-4, 4), c = rng.vec<T, 3>(-4, 4);
    const double exact = exact_det3(a, b, c).get_d();
    const T scale = length(a) * length(b) * length(c);
    const T t = triple_product(a, b, c);
    EXPECT_NEAR(double(t), exact, double(tol<T>(8, scale)));
    // Cyclic invariance and antisymmetry (a second evaluation order).
    EXPECT_NEAR(triple_product(b, c, a), t, tol<T>(16, scale));
    EXPECT_NEAR(triple_product(a, c, b), -t, tol<T>(16, scale));
  }
}

// Vector triple product a x (b x c) = b (a.c) - c (a.b), in exact arithmetic.
TYPED_TEST(ProductsTest, VectorTripleProductMatchesExactExpansion) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2000; ++n) {
    const auto a = rng.vec<T, 3>(-4, 4), b = rng.vec<T, 3>(-4, 4), c = rng.vec<T, 3>(-4, 4);
    const auto v = vector_triple_product(a, b, c);
    const mpq_class ac = qdot(a, c), ab = qdot(a, b);
    const T scale = length(a) * length(b) * length(c);
    for (int i = 0; i < 3; ++i) {
      const mpq_class e = mpq_class(b[i]) * ac - mpq_class(c[i]) * ab;
      EXPECT_NEAR(double(v[i]), e.get_d(), double(tol<T>(8, scale)));
    }
  }
  EXPECT_EQ(vector_triple_product(Vec3<T>{1, 0, 0}, Vec3<T>{1, 0, 0}, Vec3<T>{0, 1, 0}),
            (Vec3<T>{0, -1, 0}));  // x x (x x y) = x x z = -y
}

// Figures 3.15, 3.27, 3.30: the angle between vectors, obtuse when the dot product is negative.
TYPED_TEST(ProductsTest, Fig3_15AngleBetweenVectorsSpecialCases) {
  using T = TypeParam;
  EXPECT_NEAR(angle_between(Vec3<T>{1, 0, 0}, Vec3<T>{0, 1, 0}), pi_v<T> / T(2), tol<T>(2));
  EXPECT_NEAR(angle_between(Vec3<T>{1, 0, 0}, Vec3<T>{1, 1, 0}), pi_v<T> / T(4), tol<T>(2));
  EXPECT_NEAR(angle_between(Vec2<T>{1, 0}, Vec2<T>{-1, 1}), T(3) * pi_v<T> / T(4), tol<T>(4));
  EXPECT_EQ(angle_between(Vec3<T>{2, 0, 0}, Vec3<T>{-3, 0, 0}), pi_v<T>);
  EXPECT_EQ(angle_between(Vec3<T>{2, 0, 0}, Vec3<T>{3, 0, 0}), T(0));
  // Figure 3.30: cos negative -> angle above pi/2.
  EXPECT_GT(angle_between(Vec3<T>{1, 0, 0}, Vec3<T>{-1, 2, 0}), pi_v<T> / T(2));
  // Zero vectors give 0, non-finite give NaN.
  EXPECT_EQ(angle_between(Vec3<T>{0, 0, 0}, Vec3<T>{-1, 0, 0}), T(0));
  EXPECT_EQ(angle_between(Vec2<T>{-1, 0}, Vec2<T>{0, 0}), T(0));
  EXPECT_EQ(angle_between(Vec<T, 5>{}, Vec<T, 5>{}), T(0));
  EXPECT_TRUE(std::isnan(
      angle_between(Vec3<T>{std::numeric_limits<T>::quiet_NaN(), 0, 0}, Vec3<T>{1, 0, 0})));
  EXPECT_TRUE(
      std::isnan(angle_between(Vec2<T>{1, 0}, Vec2<T>{std::numeric_limits<T>::infinity(), 0})));
  // Tiny and huge vectors (their dot product under/overflows) keep the right angle.
  const T tiny = std::numeric_limits<T>::denorm_min() * T(64);
  const T huge = std::numeric_limits<T>::max() / T(4);
  EXPECT_NEAR(angle_between(Vec3<T>{tiny, 0, 0}, Vec3<T>{tiny, tiny, 0}), pi_v<T> / T(4),
              tol<T>(4));
  EXPECT_NEAR(angle_between(Vec3<T>{huge, 0, 0}, Vec3<T>{-huge, huge, 0}), T(3) * pi_v<T> / T(4),
              tol<T>(4, T(4)));
}

template <class T, int N>
void check_angles(Rng& rng) {
  for (int n = 0; n < 1500; ++n) {
    const auto a = rng.vec<T, N>(-2, 2);
    Vec<T, N> b = rng.vec<T, N>(-2, 2);
    // A third of the cases nearly parallel and a third nearly opposite: acos(dot) fails there.
    if (n % 3 == 1) b = a * T(1.5) + rng.vec<T, N>(T(-1e-4), T(1e-4));
    if (n % 3 == 2) b = a * T(-0.7) + rng.vec<T, N>(T(-1e-4), T(1e-4));
    const long double exact = exact_angle(a, b);
    // The normalised inputs carry a relative error of a few eps: an absolute angle error of the
    // same size, independent of the angle.
    EXPECT_NEAR(double(angle_between(a, b)), double(exact), double(tol<T>(8, T(2))));
    EXPECT_EQ(angle_between(a, b), angle_between(b, a));
  }
}

TYPED_TEST(ProductsTest, AngleBetweenMatchesExactOracleIn2D3DAnd5D) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  check_angles<T, 2>(rng);
  check_angles<T, 3>(rng);
  check_angles<T, 5>(rng);
}

// Figures 4.3-4.5: perp is a counter-clockwise quarter turn, perp_dot gives the signed angle and
// twice the signed area.
TYPED_TEST(ProductsTest, Fig4_4SignedAngleFollowsPerpDot) {
  using T = TypeParam;
  EXPECT_NEAR(signed_angle(Vec2<T>{1, 0}, Vec2<T>{0, 1}), pi_v<T> / T(2), tol<T>(2));
  EXPECT_NEAR(signed_angle(Vec2<T>{1, 0}, Vec2<T>{0, -1}), -pi_v<T> / T(2), tol<T>(2));
  EXPECT_EQ(signed_angle(Vec2<T>{1, 0}, Vec2<T>{-1, 0}), pi_v<T>);
  EXPECT_EQ(signed_angle(Vec2<T>{1, 0}, Vec2<T>{-1, -T(0)}), pi_v<T>);
  EXPECT_EQ(signed_angle(Vec2<T>{0, 0}, Vec2<T>{-1, 0}), T(0));
  EXPECT_TRUE(
      std::isnan(signed_angle(Vec2<T>{std::numeric_limits<T>::quiet_NaN(), 0}, Vec2<T>{1, 0})));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2000; ++n) {
    const auto a = rng.vec<T, 2>(-3, 3), b = rng.vec<T, 2>(-3, 3);
    const T s = signed_angle(a, b);
    const mpq_class pd = mpq_class(a.x) * mpq_class(b.y) - mpq_class(a.y) * mpq_class(b.x);
    const long double exact = std::copysign(exact_angle(a, b), pd.get_d());
    if (pd != 0) {
      EXPECT_EQ(s > T(0), pd > 0);
    }
    EXPECT_NEAR(double(s), double(exact), double(tol<T>(8, T(2))));
    EXPECT_NEAR(signed_angle(b, a), -s, tol<T>(2, T(4)));
    // Figure 4.5: |a||b| sin(angle) = perp_dot(a, b) = twice the signed triangle area.
    EXPECT_NEAR(length(a) * length(b) * std::sin(s), perp_dot(a, b), tol<T>(16, T(18)));
    // Figure 4.3: perp(a) is a counter-clockwise quarter turn of a.
    if (length(a) > T(0.1)) {
      EXPECT_NEAR(signed_angle(a, perp(a)), pi_v<T> / T(2), tol<T>(8));
    }
  }
}

TYPED_TEST(ProductsTest, SignedAngleAboutAnAxis) {
  using T = TypeParam;
  const Vec3<T> x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_NEAR(signed_angle(x, y, z), pi_v<T> / T(2), tol<T>(2));
  EXPECT_NEAR(signed_angle(x, y, -z), -pi_v<T> / T(2), tol<T>(2));
  EXPECT_NEAR(signed_angle(x, y, Vec3<T>{}), pi_v<T> / T(2), tol<T>(2));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 1000; ++n) {
    const auto a = rng.vec<T, 3>(-2, 2), b = rng.vec<T, 3>(-2, 2), axis = rng.vec<T, 3>(-1, 1);
    const T s = signed_angle(a, b, axis);
    EXPECT_EQ(std::abs(s), angle_between(a, b));
    const mpq_class sgn = exact_det3(axis, a, b);  // axis . (a x b)
    if (std::abs(sgn.get_d()) > 1e-3) {
      EXPECT_EQ(s < T(0), sgn < 0);
    }
  }
}

// Figure 3.29: projection of v onto d and the perpendicular rejection.
TYPED_TEST(ProductsTest, Fig3_29ProjectionAndRejection) {
  using T = TypeParam;
  EXPECT_EQ(project_onto(Vec3<T>{3, 4, 5}, Vec3<T>{2, 0, 0}), (Vec3<T>{3, 0, 0}));
  EXPECT_EQ(reject_from(Vec3<T>{3, 4, 5}, Vec3<T>{2, 0, 0}), (Vec3<T>{0, 4, 5}));
  EXPECT_EQ(scalar_projection(Vec2<T>{-3, 4}, Vec2<T>{5, 0}), T(-3));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2000; ++n) {
    const auto v = rng.vec<T, 3>(-5, 5), d = rng.vec<T, 3>(-2, 2);
    const auto p = project_onto(v, d), r = reject_from(v, d);
    const mpq_class f = qdot(v, d) / qdot(d, d);
    const T lv = length(v);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(double(p[i]), mpq_class(f * mpq_class(d[i])).get_d(), double(tol<T>(8, lv)));
      EXPECT_NEAR(double(r[i]), mpq_class(mpq_class(v[i]) - f * mpq_class(d[i])).get_d(),
                  double(tol<T>(8, lv)));
    }
    EXPECT_NEAR(dot(r, d), T(0), tol<T>(16, lv * length(d)));
    EXPECT_NEAR(length(cross(p, d)), T(0), tol<T>(16, lv * length(d)));
    const double sp =
        mpf_class(mpf_class(qdot(v, d), 128) / sqrt(mpf_class(qdot(d, d), 128))).get_d();
    EXPECT_NEAR(double(scalar_projection(v, d)), sp, double(tol<T>(8, lv)));
  }
}

TYPED_TEST(ProductsTest, ProjectionOntoZeroTinyHugeAndNonFiniteDirections) {
  using T = TypeParam;
  const Vec3<T> v{1, 2, 3};
  EXPECT_EQ(project_onto(v, Vec3<T>{}), (Vec3<T>{}));
  EXPECT_EQ(reject_from(v, Vec3<T>{}), v);
  EXPECT_EQ(scalar_projection(v, Vec3<T>{}), T(0));
  const T tiny = std::numeric_limits<T>::denorm_min();
  EXPECT_TRUE(locus_test::vec_near(project_onto(v, Vec3<T>{0, tiny, 0}), Vec3<T>{0, 2, 0}, T(0)));
  const T huge = std::numeric_limits<T>::max();
  EXPECT_TRUE(locus_test::vec_near(project_onto(v, Vec3<T>{huge, huge, 0}), Vec3<T>{1.5, 1.5, 0},
                                   tol<T>(4, T(2))));
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_FALSE(is_finite(project_onto(v, Vec3<T>{nan, 0, 0})));
  EXPECT_FALSE(is_finite(project_onto(v, Vec3<T>{inf, 0, 0})));
  EXPECT_TRUE(std::isnan(scalar_projection(v, Vec3<T>{inf, 0, 0})));
  EXPECT_FALSE(is_finite(project_onto(Vec3<T>{nan, 0, 0}, Vec3<T>{1, 0, 0})));
}
