// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/ellipse.hpp (row prim2.quadratic, ellipses and elliptical arcs; book
// figure 5.16).
#include <locus/primitives/ellipse.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class EllipseTest : public ::testing::Test {};
TYPED_TEST_SUITE(EllipseTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Ellipse2d> && std::is_trivially_copyable_v<Ellipse2f>);
static_assert(std::is_aggregate_v<ImplicitEllipse2<double>> &&
              std::is_aggregate_v<EllipseArc2<float>>);

namespace {
template <class T>
Ellipse2<T> random_ellipse(Rng& rng, T min_extent = T(0.2)) {
  const T ang = rng.uniform<T>(-4, 4);
  const Vec2<T> u{std::cos(ang), std::sin(ang)};
  return {rng.vec<T, 2>(-5, 5),
          {u, perp(u)},
          {rng.uniform<T>(min_extent, 4), rng.uniform<T>(min_extent, 4)}};
}

// Independent oracle: the perimeter as the integral of |d/da point_at| over a full period by the
// trapezoidal rule in long double (spectrally accurate for periodic integrands).
long double perimeter_by_quadrature(long double a, long double b, int n) {
  long double sum = 0;
  const long double h = 2.0L * 3.14159265358979323846264338327950288L / n;
  for (int i = 0; i < n; ++i) {
    const long double t = h * i;
    sum += std::sqrt(a * a * std::sin(t) * std::sin(t) + b * b * std::cos(t) * std::cos(t));
  }
  return sum * h;
}
}  // namespace

// Figure 5.16: centre C, unit axes U0, U1, extents l0, l1; the points C + l0 cos(t) U0 +
// l1 sin(t) U1 satisfy sum ((X - C).Ui / li)^2 = 1, and the matrix form agrees.
TYPED_TEST(EllipseTest, Fig5_16_AxisAndMatrixFormsDescribeTheSameCurve) {
  using T = TypeParam;
  const T r = T(1) / std::sqrt(T(2));
  const Ellipse2<T> e{{T(1), T(2)}, {{r, r}, {-r, r}}, {T(3), T(1)}};
  EXPECT_TRUE(locus_test::vec_near(point_at(e, T(0)), Vec2<T>{T(1) + T(3) * r, T(2) + T(3) * r},
                                   tol<T>(8, T(4))));
  EXPECT_TRUE(
      locus_test::vec_near(point_at(e, pi_v<T> / 2), Vec2<T>{T(1) - r, T(2) + r}, tol<T>(8, T(4))));
  const ImplicitEllipse2<T> im = to_implicit(e);
  EXPECT_NEAR(im.m(0, 1), im.m(1, 0), tol<T>(2));
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 500; ++k) {
    const Ellipse2<T> x = random_ellipse<T>(rng);
    const ImplicitEllipse2<T> ix = to_implicit(x);
    const T a = rng.uniform<T>(-7, 7);
    const Vec2<T> p = point_at(x, a);
    // Relative error of a few roundings, amplified by (extent ratio)^2 through M.
    const T cond = sqr(std::max(x.extent[0], x.extent[1]) / std::min(x.extent[0], x.extent[1]));
    EXPECT_NEAR(evaluate(x, p), T(0), tol<T>(64, cond * T(10)));
    EXPECT_NEAR(evaluate(ix, p), T(0), tol<T>(64, cond * T(10)));
    EXPECT_LT(evaluate(x, x.center), T(0));
    EXPECT_LT(evaluate(ix, x.center), T(0));
  }
  EXPECT_NEAR(area(e), T(3) * pi_v<T>, tol<T>(4, T(10)));
}

// Random round trips axis form -> matrix form -> axis form: extents sorted (major first),
// axis[0] parallel to the original major axis, and the same point set.
TYPED_TEST(EllipseTest, MatrixFormRoundTripOnRandomEllipses) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int compared_axes = 0;
  for (int k = 0; k < 4000; ++k) {
    const Ellipse2<T> e = random_ellipse<T>(rng);
    const auto back = to_axes(to_implicit(e));
    ASSERT_TRUE(back.has_value());
    const T big = std::max(e.extent[0], e.extent[1]), small = std::min(e.extent[0], e.extent[1]);
    EXPECT_GE(back->extent[0], back->extent[1]);
    const T cond = sqr(big / small);
    EXPECT_NEAR(back->extent[0], big, tol<T>(64, cond * big));
    EXPECT_NEAR(back->extent[1], small, tol<T>(64, cond * big));
    EXPECT_EQ(back->axis[1], perp(back->axis[0]));
    EXPECT_EQ(back->center, e.center);
    // The axis direction is determined only when the extents differ clearly.
    if (big - small > T(0.05)) {
      const Vec2<T> major = e.extent[0] >= e.extent[1] ? e.axis[0] : e.axis[1];
      EXPECT_NEAR(std::abs(dot(major, back->axis[0])), T(1), tol<T>(64, cond / (big - small)));
      ++compared_axes;
    }
    // Points of the converted ellipse lie on the original curve.
    const Vec2<T> p = point_at(*back, rng.uniform<T>(-4, 4));
    EXPECT_NEAR(evaluate(e, p), T(0), tol<T>(256, cond * T(10)));
  }
  EXPECT_GT(compared_axes, 3000);
  // A circle: every direction is an eigenvector; both extents equal the radius.
  const ImplicitEllipse2<T> circ{{T(0), T(0)}, Mat2<T>::identity() * T(0.25)};
  const auto c = to_axes(circ);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->extent[0], T(2), tol<T>(4, T(2)));
  EXPECT_NEAR(c->extent[1], T(2), tol<T>(4, T(2)));
}

TYPED_TEST(EllipseTest, PerimeterAgainstQuadratureAndRamanujan) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 60; ++k) {
    Ellipse2<T> e = random_ellipse<T>(rng, T(0.05));
    if (k == 0) e.extent[1] = e.extent[0];            // a circle
    if (k == 1) e.extent[1] = e.extent[0] * T(1e-3);  // nearly flat
    const long double a = e.extent[0], b = e.extent[1];
    // The trapezoid rule on this periodic integrand converges like exp(-n min(a, b) / max(a, b));
    // 60 max/min + 64 points reach far below double precision.
    const long double ratio = std::max(a, b) / std::min(a, b);
    const long double ref = perimeter_by_quadrature(a, b, static_cast<int>(60 * ratio) + 64);
    const T p = perimeter(e);
    EXPECT_LE(std::abs(static_cast<long double>(p) - ref),
              static_cast<long double>(tol<T>(32)) * ref)
        << "a " << double(a) << " b " << double(b);
    const T pr = perimeter_ramanujan(e);
    const long double h = ((a - b) / (a + b)) * ((a - b) / (a + b));
    // Ramanujan II: relative error ~ 3 h^5 / 2^17 for small h, at most ~4e-4 at h = 1.
    const long double bound = std::max(4.2e-4L * h * h * h * h * h + 1e-12L, 0.0L);
    EXPECT_LE(std::abs(static_cast<long double>(pr) - ref),
              ref * (bound + static_cast<long double>(tol<T>(16))))
        << "a " << double(a) << " b " << double(b);
  }
  // Flat ellipse: perimeter 4a; circle: 2 pi r.
  const Ellipse2<T> flat{{T(0), T(0)}, {{T(1), T(0)}, {T(0), T(1)}}, {T(3), T(0)}};
  EXPECT_EQ(perimeter(flat), T(12));
  EXPECT_NEAR(perimeter_ramanujan(flat), T(12), T(12) * T(4.2e-4));
  const Ellipse2<T> circle{{T(0), T(0)}, {{T(1), T(0)}, {T(0), T(1)}}, {T(2), T(2)}};
  EXPECT_NEAR(perimeter(circle), T(4) * pi_v<T>, tol<T>(4, T(13)));
  EXPECT_NEAR(perimeter_ramanujan(circle), T(4) * pi_v<T>, tol<T>(4, T(13)));
}

TYPED_TEST(EllipseTest, DegenerateAndNonDefiniteInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  // Indefinite (a hyperbola's matrix), semidefinite (parallel lines), zero, NaN: no ellipse.
  EXPECT_FALSE(
      to_axes(ImplicitEllipse2<T>{{T(0), T(0)}, Mat2<T>::diagonal({T(1), T(-1)})}).has_value());
  EXPECT_FALSE(
      to_axes(ImplicitEllipse2<T>{{T(0), T(0)}, Mat2<T>::diagonal({T(1), T(0)})}).has_value());
  EXPECT_FALSE(to_axes(ImplicitEllipse2<T>{{T(0), T(0)}, Mat2<T>{}}).has_value());
  EXPECT_FALSE(
      to_axes(ImplicitEllipse2<T>{{T(0), T(0)}, Mat2<T>::diagonal({nan, T(1)})}).has_value());
  EXPECT_FALSE(to_axes(ImplicitEllipse2<T>{{nan, T(0)}, Mat2<T>::identity()}).has_value());
  // [[1, 2], [2, 1]] has eigenvalues 3 and -1.
  const Mat2<T> ind{{{T(1), T(2)}, {T(2), T(1)}}};
  EXPECT_FALSE(to_axes(ImplicitEllipse2<T>{{T(0), T(0)}, ind}).has_value());
  // Badly scaled but definite matrices still convert.
  const T tiny = T(1e-30f), huge = T(1e30f);
  const auto s = to_axes(ImplicitEllipse2<T>{{T(0), T(0)}, Mat2<T>::diagonal({tiny, tiny * T(4)})});
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->extent[0] * std::sqrt(tiny), T(1), tol<T>(8));
  const auto h = to_axes(ImplicitEllipse2<T>{{T(0), T(0)}, Mat2<T>::diagonal({huge * T(4), huge})});
  ASSERT_TRUE(h.has_value());
  EXPECT_NEAR(h->extent[1] * std::sqrt(huge) * T(2), T(1), tol<T>(8));
  EXPECT_TRUE(is_degenerate(Ellipse2<T>{{T(0), T(0)}, {{T(1), T(0)}, {T(0), T(1)}}, {T(1), T(0)}}));
  EXPECT_TRUE(is_degenerate(Ellipse2<T>{{T(0), T(0)}, {{T(1), T(0)}, {T(0), T(1)}}, {nan, T(1)}}));
}

TYPED_TEST(EllipseTest, EllipticalArcs) {
  using T = TypeParam;
  const Ellipse2<T> e{{T(0), T(0)}, {{T(1), T(0)}, {T(0), T(1)}}, {T(2), T(1)}};
  const EllipseArc2<T> arc{e, T(-1), T(2)};
  EXPECT_EQ(end_angle(arc), T(1));
  EXPECT_TRUE(contains_angle(arc, T(0)));
  EXPECT_TRUE(contains_angle(arc, T(0.5) + T(2) * pi_v<T>));
  EXPECT_FALSE(contains_angle(arc, T(2)));
  EXPECT_FALSE(contains_angle(arc, T(-1.5)));
  EXPECT_EQ(point_at(arc, T(0.3)), point_at(e, T(0.3)));
}
