// SPDX-License-Identifier: BSL-1.0
// Bézier curves: de Casteljau against the exact Bernstein sum (GMP), derivatives against the
// exact derivative of the Bernstein form and finite differences, subdivision, degree elevation,
// the control-polygon box, arc length, and bad input.

#include <locus/curves/bezier.hpp>

#include "curve_oracle.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace locus;
using curve_oracle::Q;
using locus_test::tol;

template <class T>
class BezierTest : public ::testing::Test {};
TYPED_TEST_SUITE(BezierTest, locus_test::RealTypes);

// de Casteljau forms convex combinations level by level: each level adds at most ~2 eps of the
// largest control coordinate, so the error after n levels is below 4 (n + 1) eps * scale.
template <class T>
T eval_tol(int n, T scale) {
  return tol(T(4 * (n + 1)), scale);
}

// Figure 5.17: a planar cubic. End points and end tangents are exact (3 (P1 - P0), 3 (P3 - P2));
// the midpoint is (P0 + 3 P1 + 3 P2 + P3) / 8, exact here because the inputs are small dyadics.
TYPED_TEST(BezierTest, Figure5_17_PlanarCubic) {
  using T = TypeParam;
  const BezierCurve2<T> c{{{T(0), T(0)}, {T(1), T(2)}, {T(3), T(2)}, {T(4), T(0)}}};
  EXPECT_EQ(degree(c), 3);
  EXPECT_EQ(point_at(c, T(0)), c.control[0]);
  EXPECT_EQ(point_at(c, T(1)), c.control[3]);
  EXPECT_EQ(derivative_at(c, T(0), 1), (Vec2<T>{T(3), T(6)}));
  EXPECT_EQ(derivative_at(c, T(1), 1), (Vec2<T>{T(3), T(-6)}));
  EXPECT_EQ(point_at(c, T(0.5)), (Vec2<T>{T(2), T(1.5)}));
  // Third derivative of a cubic is constant 6 (P3 - 3 P2 + 3 P1 - P0).
  EXPECT_EQ(derivative_at(c, T(0.3), 3), (Vec2<T>{T(6) * T(4 - 9 + 3), T(6) * T(0 - 6 + 6)}));
  EXPECT_EQ(derivative_at(c, T(0.3), 4), (Vec2<T>{}));
}

// Figure 9.22: a space cubic; compare a sweep of parameters with the exact Bernstein sum.
TYPED_TEST(BezierTest, Figure9_22_SpaceCubic) {
  using T = TypeParam;
  const BezierCurve3<T> c{
      {{T(0), T(0), T(0)}, {T(1), T(2), T(1)}, {T(3), T(-1), T(2)}, {T(4), T(1), T(0)}}};
  const auto qp = curve_oracle::to_q(c.control);
  for (int k = 0; k <= 64; ++k) {
    const T t = static_cast<T>(k) / T(64);
    const auto exact = curve_oracle::bezier_derivative<3>(qp, 0, Q(static_cast<double>(t)));
    EXPECT_TRUE(curve_oracle::near_q(point_at(c, t), exact, double(eval_tol(3, T(4)))));
  }
}

TYPED_TEST(BezierTest, DeCasteljauMatchesExactBernsteinSum) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 40; ++trial) {
    const int n = rng.uniform_int(0, 9);
    const BezierCurve3<T> c{curve_oracle::dyadic_points<T, 3>(rng, n + 1)};
    const auto qp = curve_oracle::to_q(c.control);
    const T scale = curve_oracle::max_abs_points(c.control);
    for (int k = 0; k <= 16; ++k) {
      const T t = static_cast<T>(rng.uniform_int(0, 256)) / T(256);
      const auto exact = curve_oracle::bezier_derivative<3>(qp, 0, Q(static_cast<double>(t)));
      ASSERT_TRUE(curve_oracle::near_q(point_at(c, t), exact, double(eval_tol(n, scale))))
          << "n = " << n << ", t = " << t;
    }
  }
}

TYPED_TEST(BezierTest, DerivativesMatchExactBernsteinDerivative) {
  using T = TypeParam;
  locus_test::Rng rng(7);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const int n = rng.uniform_int(1, 7);
    const BezierCurve2<T> c{curve_oracle::dyadic_points<T, 2>(rng, n + 1)};
    const auto qp = curve_oracle::to_q(c.control);
    const T scale = curve_oracle::max_abs_points(c.control);
    for (int k = 0; k <= n + 1; ++k) {
      // |Delta^k P| <= 2^k max|P|, times n!/(n-k)!.
      T dscale = scale;
      for (int s = 0; s < k && s < n; ++s) dscale *= T(2) * static_cast<T>(n - s);
      for (int j = 0; j < 5; ++j) {
        const T t = static_cast<T>(rng.uniform_int(0, 64)) / T(64);
        const auto exact = curve_oracle::bezier_derivative<2>(qp, k, Q(static_cast<double>(t)));
        ASSERT_TRUE(
            curve_oracle::near_q(derivative_at(c, t, k), exact, double(eval_tol(n, dscale))))
            << "n = " << n << ", k = " << k << ", t = " << t;
      }
    }
    // The hodograph evaluated equals derivative_at (same rounding path up to the scaling).
    const BezierCurve2<T> h = derivative(c);
    EXPECT_EQ(degree(h), n - 1);
    for (int j = 0; j <= 8; ++j) {
      const T t = static_cast<T>(j) / T(8);
      const auto exact = curve_oracle::bezier_derivative<2>(qp, 1, Q(static_cast<double>(t)));
      EXPECT_TRUE(
          curve_oracle::near_q(point_at(h, t), exact, double(eval_tol(n, T(2 * n) * scale))));
    }
  }
}

TYPED_TEST(BezierTest, DerivativeMatchesCentralDifferences) {
  using T = TypeParam;
  locus_test::Rng rng(11);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int n = rng.uniform_int(2, 6);
    const BezierCurve3<T> c{curve_oracle::dyadic_points<T, 3>(rng, n + 1)};
    BezierCurve3<double> cd;
    for (const auto& p : c.control) cd.control.push_back(vec_cast<double>(p));
    const double scale = double(curve_oracle::max_abs_points(c.control)) * n * n * n * 8;
    for (int j = 1; j < 8; ++j) {
      const double t = j / 8.0, h = 1e-5;
      const Vec3<double> fd = (point_at(cd, t + h) - point_at(cd, t - h)) / (2 * h);
      // Central differences: truncation h^2/6 |C'''| plus rounding eps/h |C|.
      EXPECT_TRUE(locus_test::vec_near(derivative_at(cd, t, 1), fd, 1e-8 * scale));
      // The T-precision derivative agrees with the double one to T's rounding.
      EXPECT_TRUE(locus_test::vec_near(vec_cast<double>(derivative_at(c, static_cast<T>(t), 1)),
                                       derivative_at(cd, t, 1),
                                       double(eval_tol(n, static_cast<T>(scale)))));
    }
  }
}

TYPED_TEST(BezierTest, SubdivisionHalvesReproduceTheCurve) {
  using T = TypeParam;
  locus_test::Rng rng(13);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 25; ++trial) {
    const int n = rng.uniform_int(0, 7);
    const BezierCurve2<T> c{curve_oracle::dyadic_points<T, 2>(rng, n + 1)};
    const auto qp = curve_oracle::to_q(c.control);
    const T scale = curve_oracle::max_abs_points(c.control);
    const T split = static_cast<T>(rng.uniform_int(0, 16)) / T(16);
    const BezierSplit<T, 2> s = subdivide(c, split);
    ASSERT_EQ(s.first.control.size(), c.control.size());
    ASSERT_EQ(s.second.control.size(), c.control.size());
    EXPECT_EQ(s.first.control.front(), c.control.front());
    EXPECT_EQ(s.second.control.back(), c.control.back());
    EXPECT_EQ(s.first.control.back(), s.second.control.front());
    for (int j = 0; j <= 16; ++j) {
      const Q sq(j, 16);
      const T st = static_cast<T>(j) / T(16);
      const Q ts(static_cast<double>(split));
      // first(s) = C(t s), second(s) = C(t + (1 - t) s): exact rationals.
      const auto e1 = curve_oracle::bezier_derivative<2>(qp, 0, ts * sq);
      const auto e2 = curve_oracle::bezier_derivative<2>(qp, 0, ts + (Q(1) - ts) * sq);
      // Two rounds of de Casteljau (split, then evaluate).
      EXPECT_TRUE(curve_oracle::near_q(point_at(s.first, st), e1, double(eval_tol(2 * n, scale))));
      EXPECT_TRUE(curve_oracle::near_q(point_at(s.second, st), e2, double(eval_tol(2 * n, scale))));
    }
  }
}

TYPED_TEST(BezierTest, DegreeElevationKeepsTheCurve) {
  using T = TypeParam;
  locus_test::Rng rng(17);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 25; ++trial) {
    const int n = rng.uniform_int(0, 6);
    const int times = rng.uniform_int(1, 3);
    const BezierCurve3<T> c{curve_oracle::dyadic_points<T, 3>(rng, n + 1)};
    const auto qp = curve_oracle::to_q(c.control);
    const T scale = curve_oracle::max_abs_points(c.control);
    const BezierCurve3<T> e = elevate_degree(c, times);
    ASSERT_EQ(degree(e), n + times);
    EXPECT_EQ(e.control.front(), c.control.front());
    EXPECT_EQ(e.control.back(), c.control.back());
    for (int j = 0; j <= 16; ++j) {
      const T t = static_cast<T>(j) / T(16);
      const auto exact = curve_oracle::bezier_derivative<3>(qp, 0, Q(j, 16));
      EXPECT_TRUE(
          curve_oracle::near_q(point_at(e, t), exact, double(eval_tol(2 * (n + times), scale))));
    }
  }
  // Elevating a line: control points become equally spaced on it.
  const BezierCurve2<T> line{{{T(0), T(0)}, {T(3), T(6)}}};
  const BezierCurve2<T> l3 = elevate_degree(line, 2);
  ASSERT_EQ(l3.control.size(), 4u);
  EXPECT_TRUE(locus_test::vec_near(l3.control[1], Vec2<T>{T(1), T(2)}, tol(T(4), T(6))));
  EXPECT_TRUE(locus_test::vec_near(l3.control[2], Vec2<T>{T(2), T(4)}, tol(T(4), T(6))));
}

TYPED_TEST(BezierTest, ConvexHullPropertyOfTheControlBox) {
  using T = TypeParam;
  locus_test::Rng rng(19);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const int n = rng.uniform_int(0, 8);
    BezierCurve3<T> c;
    for (int i = 0; i <= n; ++i) c.control.push_back(rng.vec<T, 3>(T(-10), T(10)));
    const AlignedBox3<T> box = bounding_box(c);
    EXPECT_FALSE(is_empty(box));
    // Rounding of the convex combinations can step outside by a few ulps of the scale.
    const AlignedBox3<T> grown = inflate(box, eval_tol(n, T(10)));
    for (int j = 0; j <= 32; ++j) {
      const Vec3<T> p = point_at(c, rng.uniform(T(0), T(1)));
      for (int k = 0; k < 3; ++k) {
        EXPECT_GE(p[k], grown.min[k]);
        EXPECT_LE(p[k], grown.max[k]);
      }
    }
  }
}

// Affine invariance: evaluating transformed control points equals transforming the point.
TYPED_TEST(BezierTest, AffineInvariance) {
  using T = TypeParam;
  locus_test::Rng rng(23);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int n = rng.uniform_int(1, 6);
    BezierCurve2<T> c, m;
    const T ang = rng.uniform(T(0), T(6));
    const T cs = std::cos(ang), sn = std::sin(ang);
    const Vec2<T> shift = rng.vec<T, 2>(T(-5), T(5));
    const auto xf = [&](const Vec2<T>& p) {
      return Vec2<T>{cs * p.x - sn * p.y, sn * p.x + cs * p.y} + shift;
    };
    for (int i = 0; i <= n; ++i) {
      c.control.push_back(rng.vec<T, 2>(T(-3), T(3)));
      m.control.push_back(xf(c.control.back()));
    }
    for (int j = 0; j <= 10; ++j) {
      const T t = static_cast<T>(j) / T(10);
      EXPECT_TRUE(locus_test::vec_near(point_at(m, t), xf(point_at(c, t)), eval_tol(n, T(16))));
    }
  }
}

TYPED_TEST(BezierTest, ParametersAreClamped) {
  using T = TypeParam;
  const BezierCurve2<T> c{{{T(1), T(2)}, {T(5), T(-1)}, {T(3), T(3)}}};
  EXPECT_EQ(point_at(c, T(-3)), c.control.front());
  EXPECT_EQ(point_at(c, T(7)), c.control.back());
  EXPECT_EQ(derivative_at(c, T(-1), 1), derivative_at(c, T(0), 1));
  EXPECT_EQ(derivative_at(c, std::numeric_limits<T>::infinity(), 1), derivative_at(c, T(1), 1));
  EXPECT_FALSE(is_finite(point_at(c, std::numeric_limits<T>::quiet_NaN())));
  const BezierSplit<T, 2> s = subdivide(c, T(2));  // clamped to 1: second half is a point
  for (const auto& p : s.second.control) EXPECT_EQ(p, c.control.back());
}

TYPED_TEST(BezierTest, DegenerateInput) {
  using T = TypeParam;
  // Empty curve.
  const BezierCurve2<T> empty{};
  EXPECT_EQ(degree(empty), -1);
  EXPECT_FALSE(is_finite(empty));
  EXPECT_FALSE(is_finite(point_at(empty, T(0.5))));
  EXPECT_FALSE(is_finite(derivative_at(empty, T(0.5), 1)));
  EXPECT_TRUE(derivative(empty).control.empty());
  EXPECT_TRUE(is_empty(bounding_box(empty)));
  EXPECT_EQ(arc_length(empty).status, Status::empty_input);
  EXPECT_TRUE(subdivide(empty, T(0.5)).first.control.empty());
  EXPECT_TRUE(elevate_degree(empty).control.empty());
  // Single control point: the constant curve.
  const BezierCurve2<T> one{{{T(2), T(-1)}}};
  EXPECT_EQ(point_at(one, T(0.3)), one.control[0]);
  EXPECT_EQ(derivative_at(one, T(0.3), 1), (Vec2<T>{}));
  ASSERT_EQ(derivative(one).control.size(), 1u);
  EXPECT_EQ(derivative(one).control[0], (Vec2<T>{}));
  const ArcLength<T> l1 = arc_length(one);
  EXPECT_EQ(l1.status, Status::ok);
  EXPECT_EQ(l1.length, T(0));
  const BezierCurve2<T> e1 = elevate_degree(one, 3);
  for (const auto& p : e1.control) EXPECT_EQ(p, one.control[0]);
  // Repeated control points: all equal gives a constant curve of any degree.
  const BezierCurve2<T> rep{std::vector<Vec2<T>>(5, Vec2<T>{T(1), T(1)})};
  for (int j = 0; j <= 4; ++j) {
    EXPECT_TRUE(locus_test::vec_near(point_at(rep, T(j) / T(4)), rep.control[0], tol(T(8))));
    EXPECT_EQ(derivative_at(rep, T(j) / T(4), 2), (Vec2<T>{}));
  }
  // NaN control point: propagates to interior points, reported by is_finite and arc_length.
  BezierCurve2<T> bad{{{T(0), T(0)}, {std::numeric_limits<T>::quiet_NaN(), T(1)}, {T(2), T(0)}}};
  EXPECT_FALSE(is_finite(bad));
  EXPECT_FALSE(is_finite(point_at(bad, T(0.5))));
  EXPECT_EQ(arc_length(bad).status, Status::non_finite_input);
  // Negative derivative order is a bad request: NaN.
  EXPECT_FALSE(is_finite(derivative_at(rep, T(0.5), -1)));
}

TYPED_TEST(BezierTest, ArcLength) {
  using T = TypeParam;
  using std::sqrt;
  // A straight line with equally spaced control points: length |P3 - P0|.
  const BezierCurve2<T> line{{{T(0), T(0)}, {T(1), T(1)}, {T(2), T(2)}, {T(3), T(3)}}};
  const ArcLength<T> ll = arc_length(line);
  EXPECT_EQ(ll.status, Status::ok);
  EXPECT_NEAR(ll.length, T(3) * sqrt(T(2)), tol(T(64), T(5)));
  // The parabola (t, t^2): length sqrt(5)/2 + asinh(2)/4 (closed form of the integral).
  const BezierCurve2<T> par{{{T(0), T(0)}, {T(0.5), T(0)}, {T(1), T(1)}}};
  const double exact = std::sqrt(5.0) / 2 + std::asinh(2.0) / 4;
  const ArcLength<T> lp = arc_length(par);
  EXPECT_EQ(lp.status, Status::ok);
  EXPECT_NEAR(double(lp.length), exact, double(tol(T(128), T(2))));
  // Additivity and reversed bounds.
  const T a = arc_length(par, T(0), T(0.3)).length, b = arc_length(par, T(0.3), T(1)).length;
  EXPECT_NEAR(double(a + b), exact, double(tol(T(256), T(2))));
  EXPECT_EQ(arc_length(par, T(0.3), T(0)).length, a);
  // A cusp (hodograph zero at t = 1/2): the speed has a kink; still converges.
  const BezierCurve2<T> cusp{{{T(0), T(0)}, {T(2), T(2)}, {T(0), T(2)}, {T(2), T(0)}}};
  const ArcLength<T> lc = arc_length(cusp);
  EXPECT_EQ(lc.status, Status::ok);
  EXPECT_GT(lc.length, T(2) * sqrt(T(2)) * T(0.99));  // longer than the chord
  // A budget of zero subdivisions on a hard tolerance: limit_exceeded with an estimate, no hang.
  const ArcLength<T> lz = arc_length(cusp, T(0), T(1), T(0), 0);
  EXPECT_EQ(lz.status, Status::limit_exceeded);
  EXPECT_NEAR(lz.length, lc.length, T(0.05) * lc.length);
}

}  // namespace
