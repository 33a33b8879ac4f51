// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/quadratic_curve.hpp (row
// prim2.quadratic; book figures 5.13-5.16).
#include <locus/primitives/quadratic_curve.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class QuadraticCurveTest : public ::testing::Test {};
TYPED_TEST_SUITE(QuadraticCurveTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<QuadraticCurve2d> &&
              std::is_trivially_copyable_v<QuadraticCurve2f>);

namespace {

struct IntConic {
  long long a, b, c, d, e, f;
};

// Substitute x = L x' + t into the conic: with A2 = [[2a, b], [b, 2c]],
// A2' = L^T A2 L, B' = L^T (A2 t + B), f' = t^T A2 t / 2 + B . t + f (all integers).
IntConic transform(const IntConic& q, const long long l[2][2], const long long t[2]) {
  const long long A2[2][2] = {{2 * q.a, q.b}, {q.b, 2 * q.c}};
  long long AL[2][2], R[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) AL[i][j] = A2[i][0] * l[0][j] + A2[i][1] * l[1][j];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) R[i][j] = l[0][i] * AL[0][j] + l[1][i] * AL[1][j];
  const long long g[2] = {A2[0][0] * t[0] + A2[0][1] * t[1] + q.d,
                          A2[1][0] * t[0] + A2[1][1] * t[1] + q.e};
  const long long tAt =
      t[0] * (A2[0][0] * t[0] + A2[0][1] * t[1]) + t[1] * (A2[1][0] * t[0] + A2[1][1] * t[1]);
  IntConic r{};
  r.a = R[0][0] / 2;
  r.b = R[0][1];
  r.c = R[1][1] / 2;
  r.d = l[0][0] * g[0] + l[1][0] * g[1];
  r.e = l[0][1] * g[0] + l[1][1] * g[1];
  r.f = tAt / 2 + q.d * t[0] + q.e * t[1] + q.f;
  return r;
}

template <class T>
QuadraticCurve2<T> scaled(const IntConic& q, long long sign, int pow2) {
  auto cv = [&](long long v) { return std::ldexp(static_cast<T>(sign * v), pow2); };
  return {cv(q.a), cv(q.b), cv(q.c), cv(q.d), cv(q.e), cv(q.f)};
}

}  // namespace

// Figures 5.13-5.16: the canonical solution sets d0 x^2 + d1 y^2 = r (fig 5.13) and
// d0 x^2 + e1 y = r (fig 5.14), one case per cell, with the circle of fig 5.15 and the ellipse
// of fig 5.16.
TYPED_TEST(QuadraticCurveTest, Fig5_13_to_5_16_CanonicalCases) {
  using T = TypeParam;
  auto k = [](T a, T b, T c, T d, T e, T f) {
    return classify_conic(QuadraticCurve2<T>{a, b, c, d, e, f});
  };
  // Fig 5.13, d0 d1 > 0: ellipse (r same sign), point (r = 0), empty (r opposite sign).
  EXPECT_EQ(k(1, 0, 4, 0, 0, -4), ConicKind::ellipse);
  EXPECT_EQ(k(-1, 0, -4, 0, 0, 4), ConicKind::ellipse);
  EXPECT_EQ(k(1, 0, 4, 0, 0, 0), ConicKind::point);
  EXPECT_EQ(k(1, 0, 4, 0, 0, 4), ConicKind::empty);
  // Fig 5.13, d0 d1 < 0: hyperbola (r != 0) or two intersecting lines (r = 0).
  EXPECT_EQ(k(1, 0, -4, 0, 0, -4), ConicKind::hyperbola);
  EXPECT_EQ(k(1, 0, -4, 0, 0, 4), ConicKind::hyperbola);
  EXPECT_EQ(k(1, 0, -4, 0, 0, 0), ConicKind::intersecting_lines);
  EXPECT_EQ(k(0, 1, 0, 0, 0, 0), ConicKind::intersecting_lines);  // xy = 0
  EXPECT_EQ(k(0, 1, 0, 0, 0, -1), ConicKind::hyperbola);          // xy = 1
  // Fig 5.14, d1 = 0: parabola (e1 != 0); parallel lines, one line, no solution (e1 = 0).
  EXPECT_EQ(k(1, 0, 0, 0, -1, 0), ConicKind::parabola);
  EXPECT_EQ(k(0, 0, 3, 2, 0, 5), ConicKind::parabola);
  EXPECT_EQ(k(1, 0, 0, 0, 0, -4), ConicKind::parallel_lines);
  EXPECT_EQ(k(1, 0, 0, 0, 0, 0), ConicKind::double_line);
  EXPECT_EQ(k(1, 0, 0, 0, 0, 4), ConicKind::empty);
  EXPECT_EQ(k(1, 2, 1, 0, 0, -1), ConicKind::parallel_lines);  // (x + y)^2 = 1
  EXPECT_EQ(k(1, 2, 1, 0, 0, 0), ConicKind::double_line);
  EXPECT_EQ(k(1, 2, 1, 0, 0, 1), ConicKind::empty);
  EXPECT_EQ(k(1, 2, 1, 1, -1, 0), ConicKind::parabola);  // (x + y)^2 + (x - y) = 0
  // Fig 5.15: (x - 1)^2 + (y + 2)^2 = 9.
  const QuadraticCurve2<T> circ{T(1), T(0), T(1), T(-2), T(4), T(-4)};
  EXPECT_EQ(classify_conic(circ), ConicKind::circle);
  const auto c = to_circle(circ);
  ASSERT_TRUE(c.has_value());
  EXPECT_TRUE(locus_test::vec_near(c->center, Vec2<T>{T(1), T(-2)}, tol<T>(4, T(2))));
  EXPECT_NEAR(c->radius, T(3), tol<T>(4, T(3)));
  // Fig 5.16: x^2/9 + y^2 = 1 as 1 x^2 + 9 y^2 - 9 = 0.
  const auto e = to_ellipse(QuadraticCurve2<T>{T(1), T(0), T(9), T(0), T(0), T(-9)});
  ASSERT_TRUE(e.has_value());
  EXPECT_NEAR(e->extent[0], T(3), tol<T>(8, T(3)));
  EXPECT_NEAR(e->extent[1], T(1), tol<T>(8, T(3)));
  EXPECT_NEAR(std::abs(e->axis[0].x), T(1), tol<T>(8));
  // Linear and constant equations.
  EXPECT_EQ(k(0, 0, 0, 1, 2, 3), ConicKind::line);
  EXPECT_EQ(k(0, 0, 0, 0, 0, 3), ConicKind::empty);
  EXPECT_EQ(k(0, 0, 0, 0, 0, 0), ConicKind::plane);
  EXPECT_EQ(to_string(ConicKind::intersecting_lines), "intersecting_lines");
}

// Classes known by construction: integer canonical conics, transformed by random invertible
// integer affine maps (similarities for circles), multiplied by -1 and by a power of two far
// outside the range where naive floating-point evaluation of the invariants would be exact.
TYPED_TEST(QuadraticCurveTest, ClassifiesConstructedConicsExactly) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int pmin = std::is_same_v<T, float> ? -120 : -1000;
  const int pmax = std::is_same_v<T, float> ? 100 : 990;
  int counts[12] = {};
  for (int it = 0; it < 12000; ++it) {
    const long long p = rng.uniform_int(1, 6), q = rng.uniform_int(1, 6), r = rng.uniform_int(1, 6);
    const int cls = it % 13;
    IntConic base{};
    ConicKind expect{};
    switch (cls) {
      case 0:
        base = {p, 0, p == q ? q + 1 : q, 0, 0, -r};
        expect = ConicKind::ellipse;
        break;
      case 1:
        base = {p, 0, p, 0, 0, -r};
        expect = ConicKind::circle;
        break;
      case 2:
        base = {p, 0, q, 0, 0, 0};
        expect = ConicKind::point;
        break;
      case 3:
        base = {p, 0, q, 0, 0, r};
        expect = ConicKind::empty;
        break;
      case 4:
        base = {p, 0, -q, 0, 0, it % 2 ? r : -r};
        expect = ConicKind::hyperbola;
        break;
      case 5:
        base = {p, 0, -q, 0, 0, 0};
        expect = ConicKind::intersecting_lines;
        break;
      case 6:
        base = {p, 0, 0, 0, it % 2 ? q : -q, r - 3};
        expect = ConicKind::parabola;
        break;
      case 7:
        base = {p, 0, 0, 0, 0, -r};
        expect = ConicKind::parallel_lines;
        break;
      case 8:
        base = {p, 0, 0, 0, 0, 0};
        expect = ConicKind::double_line;
        break;
      case 9:
        base = {p, 0, 0, 0, 0, r};
        expect = ConicKind::empty;
        break;
      case 10:
        base = {0, 0, 0, p, q - 3, r};
        expect = ConicKind::line;
        break;
      case 11:
        base = {0, 0, 0, 0, 0, 0};
        expect = ConicKind::plane;
        break;
      default:
        base = {0, 0, 0, 0, 0, r};
        expect = ConicKind::empty;
        break;
    }
    long long l[2][2];
    if (cls == 1) {
      long long u = rng.uniform_int(-3, 3), v = rng.uniform_int(-3, 3);
      if (u == 0 && v == 0) u = 2;
      const long long refl = rng.uniform_int(0, 1) ? 1 : -1;  // rotation-scale or reflection
      l[0][0] = u;
      l[0][1] = -v * refl;
      l[1][0] = v;
      l[1][1] = u * refl;
    } else {
      do {
        for (auto& row : l)
          for (auto& x : row) x = rng.uniform_int(-3, 3);
      } while (l[0][0] * l[1][1] - l[0][1] * l[1][0] == 0);
    }
    const long long t[2] = {rng.uniform_int(-5, 5), rng.uniform_int(-5, 5)};
    const IntConic tq = transform(base, l, t);
    if (expect == ConicKind::ellipse && tq.a == tq.c && tq.b == 0) expect = ConicKind::circle;
    const int pow2 = rng.uniform_int(pmin, pmax);
    const long long sign = rng.uniform_int(0, 1) ? 1 : -1;
    const QuadraticCurve2<T> qc = scaled<T>(tq, sign, pow2);
    ASSERT_EQ(classify_conic(qc), expect)
        << "class " << cls << " coefficients " << tq.a << " " << tq.b << " " << tq.c << " " << tq.d
        << " " << tq.e << " " << tq.f << " * " << sign << " * 2^" << pow2;
    ++counts[static_cast<int>(expect)];
  }
  for (int i = 0; i < 11; ++i) EXPECT_GT(counts[i], 100) << to_string(static_cast<ConicKind>(i));
}

// Random real coefficients (not integers): classification agrees with the invariants' signs
// computed with GMP rationals, including exactly degenerate conics built as products of lines.
TYPED_TEST(QuadraticCurveTest, ClassificationMatchesGmpInvariants) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // 5-bit mantissas and exponents in [-3, 3]: each product has <= 10 significant bits and a sum
  // of two spans <= 23 bits, so the coefficients of a product of two lines are exact even in
  // float, and the conic is exactly degenerate.
  auto small = [&] {
    return std::ldexp(static_cast<T>(rng.uniform_int(-16, 16)), rng.uniform_int(-3, 3));
  };
  for (int it = 0; it < 4000; ++it) {
    QuadraticCurve2<T> q;
    if (it % 2 == 0) {
      q = {rng.uniform<T>(-2, 2), rng.uniform<T>(-2, 2), rng.uniform<T>(-2, 2),
           rng.uniform<T>(-2, 2), rng.uniform<T>(-2, 2), rng.uniform<T>(-2, 2)};
    } else {
      // (p0 x + p1 y + p2)(r0 x + r1 y + r2), possibly with the second line parallel.
      const T p0 = small(), p1 = small(), p2 = small();
      T r0 = small(), r1 = small(), r2 = small();
      if (it % 4 == 1) {
        r0 = p0 * T(2);
        r1 = p1 * T(2);
      }
      q = {p0 * r0, p0 * r1 + p1 * r0, p1 * r1, p0 * r2 + p2 * r0, p1 * r2 + p2 * r1, p2 * r2};
    }
    const mpq_class a(q.a), b(q.b), c(q.c), d(q.d), e(q.e), f(q.f);
    const int disc = sgn(mpq_class(b * b - 4 * a * c));
    const int det = sgn(
        mpq_class(8 * a * c * f - 2 * a * e * e - 2 * b * b * f + 2 * b * d * e - 2 * c * d * d));
    const int kk = sgn(mpq_class(4 * a * f - d * d + 4 * c * f - e * e));
    const ConicKind got = classify_conic(q);
    const bool quad = !(q.a == 0 && q.b == 0 && q.c == 0);
    if (!quad) continue;
    if (disc < 0) {
      if (det == 0)
        EXPECT_EQ(got, ConicKind::point);
      else if (sgn(a) * det > 0)
        EXPECT_EQ(got, ConicKind::empty);
      else
        EXPECT_TRUE(got == ConicKind::ellipse || got == ConicKind::circle);
    } else if (disc > 0) {
      EXPECT_EQ(got, det == 0 ? ConicKind::intersecting_lines : ConicKind::hyperbola);
    } else if (det != 0) {
      EXPECT_EQ(got, ConicKind::parabola);
    } else {
      EXPECT_EQ(got, kk < 0 ? ConicKind::parallel_lines
                            : (kk == 0 ? ConicKind::double_line : ConicKind::empty));
    }
    if (it % 2 == 1) {  // a product of two real lines is never a proper conic
      EXPECT_TRUE(got == ConicKind::intersecting_lines || got == ConicKind::parallel_lines ||
                  got == ConicKind::double_line || got == ConicKind::line ||
                  got == ConicKind::plane || got == ConicKind::empty)
          << to_string(got);
    }
  }
}

// Ellipse <-> quadratic coefficients round trip on random ellipses; circles too.
TYPED_TEST(QuadraticCurveTest, EllipseAndCircleConversionsRoundTrip) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 2000; ++it) {
    const T ang = rng.uniform<T>(-4, 4);
    const Vec2<T> u{std::cos(ang), std::sin(ang)};
    const Ellipse2<T> e{
        rng.vec<T, 2>(-5, 5), {u, perp(u)}, {rng.uniform<T>(T(0.3), 4), rng.uniform<T>(T(0.3), 4)}};
    const QuadraticCurve2<T> q = to_quadratic(e);
    const ConicKind kind = classify_conic(q);
    ASSERT_TRUE(kind == ConicKind::ellipse || kind == ConicKind::circle) << to_string(kind);
    const auto back = to_ellipse(q);
    ASSERT_TRUE(back.has_value());
    const T big = std::max(e.extent[0], e.extent[1]), sm = std::min(e.extent[0], e.extent[1]);
    // Rounding in the coefficients (relative eps * |center|^2 / extent^2 in f) is amplified by
    // the condition (big / small)^2 and the centre offset.
    const T cond = sqr(big / sm) * (T(1) + sqr_length(e.center) / sqr(sm));
    EXPECT_NEAR(back->extent[0], big, tol<T>(64, cond * big));
    EXPECT_NEAR(back->extent[1], sm, tol<T>(64, cond * big));
    EXPECT_TRUE(locus_test::vec_near(back->center, e.center, tol<T>(64, cond * big)));
    const Vec2<T> p = point_at(*back, rng.uniform<T>(-4, 4));
    EXPECT_NEAR(evaluate(e, p), T(0), tol<T>(256, cond));
    // Circles.
    const Circle2<T> c{rng.vec<T, 2>(-5, 5), rng.uniform<T>(T(0.3), 4)};
    const QuadraticCurve2<T> qc = to_quadratic(c);
    EXPECT_EQ(classify_conic(qc), ConicKind::circle);
    const auto cb = to_circle(qc);
    ASSERT_TRUE(cb.has_value());
    const T ccond = T(1) + sqr_length(c.center) / sqr(c.radius);
    EXPECT_NEAR(cb->radius, c.radius, tol<T>(64, ccond * c.radius));
    EXPECT_TRUE(locus_test::vec_near(cb->center, c.center, tol<T>(16, T(5))));
  }
  // Not an ellipse: no conversion.
  EXPECT_FALSE(to_ellipse(QuadraticCurve2<T>{T(1), T(0), T(-1), T(0), T(0), T(-1)}).has_value());
  EXPECT_FALSE(to_ellipse(QuadraticCurve2<T>{T(1), T(0), T(1), T(0), T(0), T(1)}).has_value());
  EXPECT_FALSE(to_circle(QuadraticCurve2<T>{T(1), T(0), T(2), T(0), T(0), T(-1)}).has_value());
  EXPECT_TRUE(to_ellipse(QuadraticCurve2<T>{T(1), T(0), T(1), T(0), T(0), T(-1)}).has_value());
}

TYPED_TEST(QuadraticCurveTest, NonFiniteAndEvaluate) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_EQ(classify_conic(QuadraticCurve2<T>{nan, T(0), T(1), T(0), T(0), T(-1)}),
            ConicKind::non_finite);
  EXPECT_EQ(classify_conic(QuadraticCurve2<T>{T(1), T(0), T(1), T(0), T(0), -inf}),
            ConicKind::non_finite);
  EXPECT_FALSE(to_ellipse(QuadraticCurve2<T>{T(1), T(0), T(1), T(0), nan, T(-1)}).has_value());
  // Extreme but finite coefficients: still classified exactly.
  const T mx = std::numeric_limits<T>::max(), dn = std::numeric_limits<T>::denorm_min();
  EXPECT_EQ(classify_conic(QuadraticCurve2<T>{mx, T(0), mx, T(0), T(0), -mx}), ConicKind::circle);
  EXPECT_EQ(classify_conic(QuadraticCurve2<T>{dn, T(0), dn, T(0), T(0), dn}), ConicKind::empty);
  EXPECT_EQ(classify_conic(QuadraticCurve2<T>{dn, T(0), -dn, T(0), T(0), T(0)}),
            ConicKind::intersecting_lines);
  const QuadraticCurve2<T> q{T(1), T(2), T(3), T(4), T(5), T(6)};
  EXPECT_EQ(evaluate(q, Vec2<T>{T(1), T(-1)}), T(1 - 2 + 3 + 4 - 5 + 6));
}

namespace locus {
// Readable names in failure messages.
inline void PrintTo(ConicKind k, std::ostream* os) { *os << to_string(k); }
}  // namespace locus
