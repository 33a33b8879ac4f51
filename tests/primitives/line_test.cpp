// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/line.hpp (rows prim2.linear, prim3.linear; book figures 5.1(a), 5.2).
#include <locus/primitives/line.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class LineTest : public ::testing::Test {};
TYPED_TEST_SUITE(LineTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Line3d> && std::is_trivially_copyable_v<Line3d>);
static_assert(std::is_aggregate_v<ImplicitLine2f> && std::is_trivially_copyable_v<ImplicitLine2f>);
static_assert(point_at(Line2d{{1, 2}, {3, -1}}, 2.0) == Vec2d{7, 0}, "constexpr point_at");

// Figure 5.1(a): a line through P with direction d; t ranges over all reals.
TYPED_TEST(LineTest, Fig5_1a_PointAtCoversBothSidesOfOrigin) {
  using T = TypeParam;
  const Line2<T> line{{T(1), T(1)}, {T(2), T(1)}};
  EXPECT_EQ(point_at(line, T(0)), line.origin);
  EXPECT_EQ(point_at(line, T(1)), (Vec2<T>{T(3), T(2)}));
  EXPECT_EQ(point_at(line, T(-1)), (Vec2<T>{T(-1), T(0)}));
  const Line3<T> l3{{T(0), T(1), T(2)}, {T(1), T(-1), T(0.5)}};
  EXPECT_EQ(point_at(l3, T(4)), (Vec3<T>{T(4), T(-3), T(4)}));
}

// Figure 5.2: the implicit line n . X + c = 0; the normal points to the positive side, and the
// conversion from the parametric form puts the positive side on the left of the direction.
TYPED_TEST(LineTest, Fig5_2_ImplicitFormSidesAndConversion) {
  using T = TypeParam;
  const Line2<T> line{{T(0), T(1)}, {T(1), T(0)}};  // y = 1, pointing to +x
  const auto imp = to_implicit(line);
  ASSERT_TRUE(imp.has_value());
  EXPECT_EQ(imp->normal, (Vec2<T>{T(0), T(1)}));
  EXPECT_EQ(imp->c, T(-1));
  EXPECT_GT(evaluate(*imp, Vec2<T>{T(5), T(3)}), T(0));  // left of +x is +y
  EXPECT_LT(evaluate(*imp, Vec2<T>{T(-5), T(0)}), T(0));
  EXPECT_EQ(evaluate(*imp, Vec2<T>{T(-7), T(1)}), T(0));
  // Implicit 3x + 4y - 10 = 0: the closest point to the origin is (6/5, 8/5), distance 2.
  const ImplicitLine2<T> i2{{T(3), T(4)}, T(-10)};
  const auto par = to_parametric(i2);
  ASSERT_TRUE(par.has_value());
  EXPECT_TRUE(locus_test::vec_near(par->origin, Vec2<T>{T(1.2), T(1.6)}, tol<T>(4)));
  EXPECT_EQ(perp(par->direction), i2.normal);  // the inverse of to_implicit's convention
  const auto n = normalized(i2);
  ASSERT_TRUE(n.has_value());
  EXPECT_NEAR(n->c, T(-2), tol<T>(4));
  EXPECT_NEAR(evaluate(*n, Vec2<T>{T(0), T(0)}), T(-2), tol<T>(4));  // signed distance
}

// Oracle: for integer data the implicit coefficients are exact, so the sign of evaluate()
// must equal the exact GMP sign of the orientation determinant (left of the line = positive).
TYPED_TEST(LineTest, ImplicitSignMatchesExactOrientationOnIntegers) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 5000; ++k) {
    const Vec2<T> o{T(rng.uniform_int(-100, 100)), T(rng.uniform_int(-100, 100))};
    const Vec2<T> d{T(rng.uniform_int(-100, 100)), T(rng.uniform_int(-100, 100))};
    const Vec2<T> p{T(rng.uniform_int(-100, 100)), T(rng.uniform_int(-100, 100))};
    const Line2<T> line{o, d};
    const auto imp = to_implicit(line);
    if (d == Vec2<T>{}) {
      EXPECT_FALSE(imp.has_value());
      continue;
    }
    ASSERT_TRUE(imp.has_value());
    const mpq_class det =
        mpq_class(d.x) * (mpq_class(p.y) - o.y) - mpq_class(d.y) * (mpq_class(p.x) - o.x);
    const T v = evaluate(*imp, p);
    EXPECT_EQ(sgn(det), (v > T(0)) - (v < T(0)));
  }
}

// Round trip on random lines: parametric -> implicit -> parametric gives the same point set.
TYPED_TEST(LineTest, ConversionRoundTripKeepsThePointSet) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 2000; ++k) {
    const Line2<T> line{rng.vec<T, 2>(-10, 10), rng.vec<T, 2>(-1, 1)};
    const auto imp = to_implicit(line);
    ASSERT_TRUE(imp.has_value());
    const auto back = to_parametric(*imp);
    ASSERT_TRUE(back.has_value());
    const T scale = T(10) * length(line.direction);  // |n| * |X| bounds the terms of n.X + c
    for (T t : {T(-3), T(0), T(2.5)}) {
      EXPECT_NEAR(evaluate(*imp, point_at(line, t)), T(0), tol<T>(16, scale));
      EXPECT_NEAR(evaluate(*imp, point_at(*back, t)), T(0), tol<T>(16, scale));
    }
    // Same direction sense: perp(back.direction) is the implicit normal.
    EXPECT_EQ(perp(back->direction), imp->normal);
    EXPECT_EQ(back->direction, line.direction);
    // The origin of the parametric form is the foot of the perpendicular from (0, 0).
    EXPECT_NEAR(dot(back->origin, back->direction), T(0),
                tol<T>(64, T(10) * length(line.direction)));
    const auto nl = normalized(line);
    ASSERT_TRUE(nl.has_value());
    EXPECT_NEAR(length(nl->direction), T(1), tol<T>(4));
  }
}

TYPED_TEST(LineTest, DegenerateAndNonFiniteLines) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T inf = std::numeric_limits<T>::infinity();
  const Line2<T> zero{{T(1), T(2)}, {T(0), T(0)}};
  EXPECT_TRUE(is_degenerate(zero));
  EXPECT_FALSE(to_implicit(zero).has_value());
  EXPECT_FALSE(normalized(zero).has_value());
  EXPECT_EQ(point_at(zero, T(5)), zero.origin);  // acts as its origin
  EXPECT_TRUE(is_degenerate(Line2<T>{{nan, T(0)}, {T(1), T(0)}}));
  EXPECT_TRUE(is_degenerate(Line3<T>{{T(0), T(0), T(0)}, {T(0), inf, T(0)}}));
  EXPECT_FALSE(is_degenerate(Line3<T>{{T(0), T(0), T(0)}, {T(0), T(0), T(1e-30f)}}));
  const ImplicitLine2<T> none{{T(0), T(0)}, T(1)};
  EXPECT_TRUE(is_degenerate(none));
  EXPECT_FALSE(to_parametric(none).has_value());
  EXPECT_FALSE(normalized(none).has_value());
  EXPECT_FALSE(to_parametric(ImplicitLine2<T>{{T(1), T(0)}, nan}).has_value());
  // Tiny and huge normals convert without underflow or overflow.
  const T tiny = std::numeric_limits<T>::min();
  const auto p = to_parametric(ImplicitLine2<T>{{tiny, tiny}, T(-2) * tiny});
  ASSERT_TRUE(p.has_value());
  EXPECT_TRUE(locus_test::vec_near(p->origin, Vec2<T>{T(1), T(1)}, tol<T>(4)));
  const T huge = std::numeric_limits<T>::max() / T(4);
  const auto q = to_parametric(ImplicitLine2<T>{{huge, T(0)}, -huge});
  ASSERT_TRUE(q.has_value());
  EXPECT_TRUE(locus_test::vec_near(q->origin, Vec2<T>{T(1), T(0)}, tol<T>(4)));
}

// Translating the line and the query point together leaves the signed value unchanged
// (exactly for integer data).
TYPED_TEST(LineTest, TranslationInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 1000; ++k) {
    auto iv = [&] { return Vec2<T>{T(rng.uniform_int(-50, 50)), T(rng.uniform_int(-50, 50))}; };
    const Vec2<T> o = iv(), d = iv(), p = iv(), s = iv();
    if (d == Vec2<T>{}) continue;
    const auto a = to_implicit(Line2<T>{o, d});
    const auto b = to_implicit(Line2<T>{o + s, d});
    EXPECT_EQ(evaluate(*a, p), evaluate(*b, p + s));
  }
}
