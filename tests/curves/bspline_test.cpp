// SPDX-License-Identifier: BSL-1.0
// B-spline curves: de Boor against the exact Cox-de Boor basis sum (GMP), the basis (partition
// of unity, locality), derivative curves against finite differences and the Bézier form, knot
// insertion, conversion to Bézier segments, knot-vector helpers and validation.

#include <locus/curves/bspline.hpp>

#include "curve_oracle.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace {

using namespace locus;
using curve_oracle::Q;
using locus_test::tol;

template <class T>
class BSplineTest : public ::testing::Test {};
TYPED_TEST_SUITE(BSplineTest, locus_test::RealTypes);

// de Boor forms convex combinations (valid knots) with one rounded ratio per step: the error is
// below 8 (d + 1) eps * scale (a generous constant over the 2 (d + 1) eps * scale estimate).
template <class T>
T eval_tol(int d, T scale) {
  return tol(T(8 * (d + 1)), scale);
}

template <class T, int N>
BSplineCurve<T, N> random_curve(locus_test::Rng& rng, int d, int n, bool clamped) {
  return {d, curve_oracle::dyadic_points<T, N>(rng, n),
          curve_oracle::random_knots<T>(rng, n, d, clamped, 8, 3)};
}

/// The exact value sum_i N_{i,d}(t) P_i.
template <class T, int N>
curve_oracle::QVec<N> exact_point(const BSplineCurve<T, N>& c, const Q& t) {
  const auto kn = curve_oracle::knots_q(c.knots);
  const int n = static_cast<int>(c.control.size());
  const int span = curve_oracle::span_scan(kn, c.degree, n, t);
  const auto qp = curve_oracle::to_q(c.control);
  curve_oracle::QVec<N> r{};
  for (int i = 0; i < n; ++i) {
    const Q b = curve_oracle::cox_de_boor(kn, i, c.degree, t, span);
    for (int k = 0; k < N; ++k)
      r[static_cast<std::size_t>(k)] +=
          b * qp[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
  }
  return r;
}

// Figure 5.18: a planar cubic B-spline with uniform knots. At the knot t_{i+3} the curve is
// (P_i + 4 P_{i+1} + P_{i+2}) / 6 (the uniform cubic's knot values), exact in dyadics / 6.
TYPED_TEST(BSplineTest, Figure5_18_UniformCubicKnotValues) {
  using T = TypeParam;
  const BSplineCurve2<T> c{
      3,
      {{T(0), T(0)}, {T(1), T(3)}, {T(3), T(4)}, {T(5), T(1)}, {T(7), T(2)}, {T(8), T(5)}},
      uniform_knots<T>(6, 3)};
  ASSERT_EQ(validate(c), Status::ok);
  const ParamDomain<T> dom = domain(c);
  EXPECT_EQ(dom.min, T(0));
  EXPECT_EQ(dom.max, T(1));
  for (int i = 0; i + 2 < 6; ++i) {
    const T t = c.knots[static_cast<std::size_t>(i + 3)];
    const Vec2<T> want = (c.control[static_cast<std::size_t>(i)] +
                          T(4) * c.control[static_cast<std::size_t>(i + 1)] +
                          c.control[static_cast<std::size_t>(i + 2)]) /
                         T(6);
    EXPECT_TRUE(locus_test::vec_near(point_at(c, t), want, eval_tol(3, T(8)))) << "knot " << i;
    // The first derivative there is (P_{i+2} - P_i) / (2 h), h the knot spacing 1/3.
    const Vec2<T> dwant =
        (c.control[static_cast<std::size_t>(i + 2)] - c.control[static_cast<std::size_t>(i)]) *
        T(1.5);
    EXPECT_TRUE(locus_test::vec_near(derivative_at(c, t, 1), dwant, eval_tol(3, T(24))));
  }
}

// Figure 9.23: a space cubic B-spline with clamped knots: it interpolates the end points, with
// end tangents 3 (P1 - P0) / (t_4 - t_1), and matches the exact basis sum everywhere.
TYPED_TEST(BSplineTest, Figure9_23_ClampedSpaceCubic) {
  using T = TypeParam;
  const BSplineCurve3<T> c{3,
                           {{T(0), T(0), T(0)},
                            {T(1), T(2), T(1)},
                            {T(2), T(-1), T(2)},
                            {T(4), T(1), T(0)},
                            {T(5), T(3), T(1)}},
                           open_uniform_knots<T>(5, 3)};
  ASSERT_EQ(validate(c), Status::ok);
  EXPECT_EQ(point_at(c, T(0)), c.control.front());
  EXPECT_EQ(point_at(c, T(1)), c.control.back());
  EXPECT_TRUE(locus_test::vec_near(derivative_at(c, T(0), 1), T(6) * (c.control[1] - c.control[0]),
                                   eval_tol(3, T(12))));
  for (int j = 0; j <= 32; ++j) {
    const T t = static_cast<T>(j) / T(32);
    EXPECT_TRUE(
        curve_oracle::near_q(point_at(c, t), exact_point(c, Q(j, 32)), double(eval_tol(3, T(5)))));
  }
}

TYPED_TEST(BSplineTest, DeBoorMatchesExactCoxDeBoorSum) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 40; ++trial) {
    const int d = rng.uniform_int(0, 5);
    const int n = d + rng.uniform_int(1, 6);
    const BSplineCurve2<T> c = random_curve<T, 2>(rng, d, n, trial % 2 == 0);
    ASSERT_EQ(validate(c), Status::ok);
    const T scale = curve_oracle::max_abs_points(c.control);
    const ParamDomain<T> dom = domain(c);
    for (int j = 0; j <= 20; ++j) {
      // Dyadic parameters across the domain, its ends and the knots themselves.
      T t = j < 16 ? dom.min + (dom.max - dom.min) * static_cast<T>(j) / T(16)
                   : c.knots[static_cast<std::size_t>(rng.uniform_int(d, n))];
      if (j == 20) t = dom.max;
      ASSERT_TRUE(curve_oracle::near_q(point_at(c, t), exact_point(c, Q(static_cast<double>(t))),
                                       double(eval_tol(d, scale))))
          << "d = " << d << ", n = " << n << ", t = " << t;
    }
  }
}

TYPED_TEST(BSplineTest, BasisFunctionsExactPartitionOfUnityAndLocality) {
  using T = TypeParam;
  locus_test::Rng rng(3);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const int d = rng.uniform_int(0, 5);
    const int n = d + rng.uniform_int(1, 6);
    const std::vector<T> kv = curve_oracle::random_knots<T>(rng, n, d, trial % 3 == 0, 8, 3);
    const std::span<const T> k(kv);
    const auto kq = curve_oracle::knots_q(kv);
    for (int j = 0; j <= 16; ++j) {
      const T t = kv[static_cast<std::size_t>(d)] +
                  (kv[static_cast<std::size_t>(n)] - kv[static_cast<std::size_t>(d)]) *
                      static_cast<T>(j) / T(16);
      const Q tq(static_cast<double>(t));
      const int span = curve_oracle::span_scan(kq, d, n, tq);
      EXPECT_EQ(find_span(k, d, n, t), span);
      T sum = T(0);
      for (int i = 0; i < n; ++i) {
        const T b = basis_function(k, d, n, i, t);
        const Q e = curve_oracle::cox_de_boor(kq, i, d, tq, span);
        EXPECT_NEAR(double(b), e.get_d(), double(eval_tol(d, T(1))));
        EXPECT_GE(b, T(0));
        if (i < span - d || i > span) {
          EXPECT_EQ(b, T(0));  // locality: only d + 1 functions are non-zero on a span
        }
        sum += b;
      }
      EXPECT_NEAR(sum, T(1), eval_tol(d, T(n)));
    }
    // Outside the index range the basis is 0; a bad shape gives NaN.
    EXPECT_EQ(basis_function(k, d, n, -1, kv[0]), T(0));
    EXPECT_EQ(basis_function(k, d, n, n, kv[0]), T(0));
    EXPECT_TRUE(std::isnan(basis_function(k, d, n + 1, 0, kv[0])));
  }
}

TYPED_TEST(BSplineTest, DerivativesMatchFiniteDifferences) {
  using T = TypeParam;
  locus_test::Rng rng(5);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int d = rng.uniform_int(1, 5);
    const int n = d + rng.uniform_int(1, 5);
    const BSplineCurve3<T> c = random_curve<T, 3>(rng, d, n, trial % 2 == 0);
    BSplineCurve3<double> cd{d, {}, {}};
    for (const auto& p : c.control) cd.control.push_back(vec_cast<double>(p));
    for (T x : c.knots) cd.knots.push_back(double(x));
    const BSplineCurve3<double> dc = derivative(cd);
    EXPECT_EQ(dc.degree, d - 1);
    EXPECT_EQ(dc.control.size() + static_cast<std::size_t>(d), dc.knots.size());
    const ParamDomain<double> dom = domain(cd);
    // Non-empty spans are >= 1/8 long, so each derivative order multiplies the bound on the
    // control points by at most 2 * 8 * d: bound(k) = max|P| (16 d)^k.
    const double maxp = double(curve_oracle::max_abs_points(c.control));
    const auto bound = [&](int k) { return maxp * std::pow(16.0 * d, k); };
    for (int j = 0; j < 30; ++j) {
      const double t = dom.min + (dom.max - dom.min) * (j + 0.5) / 30.0;
      bool near_knot = false;
      for (double k : cd.knots) near_knot = near_knot || std::abs(k - t) < 1e-3;
      if (near_knot) continue;  // derivatives jump across knots of high multiplicity
      const double h = 1e-5;
      for (int order = 1; order <= std::min(d, 2); ++order) {
        const Vec3<double> fd =
            (derivative_at(cd, t + h, order - 1) - derivative_at(cd, t - h, order - 1)) / (2 * h);
        // Central differences: h^2 / 6 |C^(order+2)| truncation plus ~ 4 eps / h |C^(order-1)|.
        const double ftol = h * h * bound(order + 2) + 4e-16 / h * bound(order - 1);
        EXPECT_TRUE(locus_test::vec_near(derivative_at(cd, t, order), fd, ftol))
            << "order " << order << " at t = " << t;
      }
      EXPECT_TRUE(locus_test::vec_near(derivative_at(cd, t, 1), point_at(dc, t), 1e-14 * bound(1)));
    }
    EXPECT_EQ(derivative_at(c, c.knots[static_cast<std::size_t>(d)], d + 1), (Vec3<T>{}));
  }
}

TYPED_TEST(BSplineTest, SingleClampedSegmentEqualsBezier) {
  using T = TypeParam;
  locus_test::Rng rng(7);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int d = rng.uniform_int(0, 7);
    const std::vector<Vec2<T>> pts = curve_oracle::dyadic_points<T, 2>(rng, d + 1);
    const BSplineCurve2<T> c{d, pts, open_uniform_knots<T>(d + 1, d)};
    ASSERT_EQ(validate(c), Status::ok);
    const BezierCurve2<T> b{pts};
    const T scale = curve_oracle::max_abs_points(pts);
    for (int j = 0; j <= 16; ++j) {
      const T t = static_cast<T>(j) / T(16);
      EXPECT_TRUE(locus_test::vec_near(point_at(c, t), point_at(b, t), eval_tol(d, scale)));
      for (int k = 1; k <= d; ++k) {
        T ds = scale;
        for (int s = 0; s < k; ++s) ds *= T(2 * (d - s));
        EXPECT_TRUE(
            locus_test::vec_near(derivative_at(c, t, k), derivative_at(b, t, k), eval_tol(d, ds)))
            << "k = " << k;
      }
    }
  }
}

TYPED_TEST(BSplineTest, KnotInsertionKeepsTheCurve) {
  using T = TypeParam;
  locus_test::Rng rng(9);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const int d = rng.uniform_int(1, 5);
    const int n = d + rng.uniform_int(1, 5);
    const BSplineCurve2<T> c = random_curve<T, 2>(rng, d, n, trial % 2 == 0);
    const ParamDomain<T> dom = domain(c);
    const T scale = curve_oracle::max_abs_points(c.control);
    // Either a new dyadic value or an existing knot.
    const T u = trial % 3 == 0 ? c.knots[static_cast<std::size_t>(rng.uniform_int(d, n))]
                               : dom.min + (dom.max - dom.min) *
                                               static_cast<T>(rng.uniform_int(0, 32)) / T(32);
    const int times = rng.uniform_int(1, d + 1);
    const BSplineCurve2<T> r = insert_knot(c, u, times);
    ASSERT_EQ(validate(r), Status::ok);
    int before = 0, after = 0;
    for (T k : c.knots) before += k == u;
    for (T k : r.knots) after += k == u;
    const int expect = std::max(before, std::min(d, before + times));
    EXPECT_EQ(after, expect) << "before " << before << ", times " << times;
    EXPECT_EQ(r.control.size() - c.control.size(), static_cast<std::size_t>(after - before));
    for (int j = 0; j <= 24; ++j) {
      const T t = dom.min + (dom.max - dom.min) * static_cast<T>(j) / T(24);
      const Q tq(static_cast<double>(t));
      // Each insertion adds one round of convex combinations to the control points.
      EXPECT_TRUE(curve_oracle::near_q(point_at(r, t), exact_point(c, tq),
                                       double(eval_tol(d + times + 1, scale))))
          << "t = " << t;
    }
  }
}

TYPED_TEST(BSplineTest, ToBezierSegmentsReproduceTheCurve) {
  using T = TypeParam;
  locus_test::Rng rng(11);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 25; ++trial) {
    const int d = rng.uniform_int(1, 4);
    const int n = d + rng.uniform_int(1, 5);
    const BSplineCurve3<T> c = random_curve<T, 3>(rng, d, n, trial % 2 == 1);
    const BezierSegments<T, 3> segs = to_bezier(c);
    ASSERT_EQ(segs.status, Status::ok);
    int spans = 0;
    for (int k = d; k < n; ++k)
      spans += c.knots[static_cast<std::size_t>(k)] < c.knots[static_cast<std::size_t>(k) + 1];
    ASSERT_EQ(static_cast<int>(segs.segments.size()), spans);
    ASSERT_EQ(segs.breaks.size(), segs.segments.size() + 1);
    const T scale = curve_oracle::max_abs_points(c.control);
    for (std::size_t s = 0; s < segs.segments.size(); ++s) {
      EXPECT_EQ(degree(segs.segments[s]), d);
      const T a = segs.breaks[s], b = segs.breaks[s + 1];
      for (int j = 0; j <= 8; ++j) {
        const T t = a + (b - a) * static_cast<T>(j) / T(8);
        EXPECT_TRUE(curve_oracle::near_q(point_at(segs.segments[s], static_cast<T>(j) / T(8)),
                                         exact_point(c, Q(static_cast<double>(t))),
                                         double(eval_tol(4 * d, scale))));
      }
    }
  }
}

TYPED_TEST(BSplineTest, ConvexHullOfTheControlPolygon) {
  using T = TypeParam;
  locus_test::Rng rng(13);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int d = rng.uniform_int(0, 4);
    const int n = d + rng.uniform_int(1, 6);
    const BSplineCurve2<T> c = random_curve<T, 2>(rng, d, n, trial % 2 == 0);
    const AlignedBox2<T> box = inflate(bounding_box(c), eval_tol(d, T(8)));
    const ParamDomain<T> dom = domain(c);
    for (int j = 0; j <= 40; ++j) {
      const Vec2<T> p = point_at(c, rng.uniform(dom.min, dom.max));
      EXPECT_GE(p.x, box.min.x);
      EXPECT_GE(p.y, box.min.y);
      EXPECT_LE(p.x, box.max.x);
      EXPECT_LE(p.y, box.max.y);
    }
  }
}

TYPED_TEST(BSplineTest, KnotVectorHelpers) {
  using T = TypeParam;
  const std::vector<T> u = uniform_knots<T>(5, 2);  // (i - 2) / 3, i = 0..7
  ASSERT_EQ(u.size(), 8u);
  for (int i = 0; i < 8; ++i)
    EXPECT_NEAR(u[static_cast<std::size_t>(i)], static_cast<T>(i - 2) / T(3), tol(T(2)));
  const std::vector<T> o = open_uniform_knots<T>(5, 2);
  const std::vector<T> want{T(0), T(0), T(0), T(1) / T(3), T(2) / T(3), T(1), T(1), T(1)};
  EXPECT_EQ(o, want);
  EXPECT_TRUE(uniform_knots<T>(2, 2).empty());
  EXPECT_TRUE(open_uniform_knots<T>(3, -1).empty());
  EXPECT_EQ(validate_knots(std::span<const T>(u), 2, 5), Status::ok);
  EXPECT_EQ(validate_knots(std::span<const T>(o), 2, 5), Status::ok);
}

TYPED_TEST(BSplineTest, ValidationOfBadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const std::vector<Vec2<T>> pts{{T(0), T(0)}, {T(1), T(1)}, {T(2), T(0)}, {T(3), T(1)}};
  const auto v = [&](int d, std::vector<T> k) { return validate(BSplineCurve2<T>{d, pts, k}); };
  EXPECT_EQ(v(2, {0, 0, 0, 1, 2, 2, 2}), Status::ok);
  EXPECT_EQ(v(2, {0, 0, 0, 2, 1, 2, 2}), Status::invalid_input);     // decreasing
  EXPECT_EQ(v(2, {0, 0, 0, 1, 2, 2}), Status::invalid_input);        // too short
  EXPECT_EQ(v(2, {0, 0, 0, 1, 2, 2, 2, 2}), Status::invalid_input);  // too long
  EXPECT_EQ(v(1, {0, 1, 1, 1, 2, 3}), Status::invalid_input);        // multiplicity 3 > d + 1
  EXPECT_EQ(v(2, {0, 0, 0, 0, 2, 2, 2}), Status::invalid_input);     // end multiplicity 4 > 3
  EXPECT_EQ(v(2, {0, 0, 0, nan, 2, 2, 2}), Status::non_finite_input);
  EXPECT_EQ(v(1, {0, 0, 1, 1, 2, 2}), Status::ok);  // interior multiplicity d + 1 is allowed
  EXPECT_EQ(v(4, {0, 0, 0, 0, 0, 1, 1, 1, 1}), Status::invalid_input);  // degree >= n
  EXPECT_EQ(v(-1, {0, 1, 2}), Status::invalid_input);
  EXPECT_EQ(validate(BSplineCurve2<T>{0, {}, {}}), Status::empty_input);
  // Empty domain: t_d == t_n with all multiplicities <= d + 1.
  EXPECT_EQ(
      validate(BSplineCurve2<T>{
          2, {{T(0), T(0)}, {T(1), T(1)}, {T(2), T(0)}}, {T(0), T(1), T(1), T(1), T(2), T(3)}}),
      Status::degenerate_input);
  BSplineCurve2<T> c{2, pts, {0, 0, 0, 1, 2, 2, 2}};
  c.control[1].x = nan;
  EXPECT_EQ(validate(c), Status::non_finite_input);
}

TYPED_TEST(BSplineTest, EvaluationOfBadShapesIsSafe) {
  using T = TypeParam;
  const std::vector<Vec2<T>> pts{{T(0), T(0)}, {T(1), T(1)}, {T(2), T(0)}, {T(3), T(1)}};
  // Wrong knot count, degree out of range: NaN, never an out-of-range read.
  EXPECT_FALSE(is_finite(point_at(BSplineCurve2<T>{2, pts, {0, 0, 0, 1, 1, 1}}, T(0.5))));
  EXPECT_FALSE(is_finite(point_at(BSplineCurve2<T>{4, pts, {0, 0, 0, 0, 0, 1, 1, 1, 1}}, T(0.5))));
  EXPECT_FALSE(is_finite(point_at(BSplineCurve2<T>{-1, pts, {0, 1, 2}}, T(0.5))));
  EXPECT_FALSE(is_finite(derivative_at(BSplineCurve2<T>{2, pts, {0, 0, 1}}, T(0.5), 1)));
  EXPECT_EQ(insert_knot(BSplineCurve2<T>{2, pts, {0, 1}}, T(0.5)).knots.size(), 2u);
  EXPECT_EQ(to_bezier(BSplineCurve2<T>{2, pts, {0, 1}}).status, Status::invalid_input);
  // Decreasing knots: meaningless values, but no hang, no out-of-range read (the sanitizer
  // build checks), no division by zero (0/0 fractions are 0, so the values stay finite here).
  const BSplineCurve2<T> dec{2, pts, {3, 2, 1, 1, 1, 0, 0}};
  for (int j = -2; j <= 6; ++j) EXPECT_TRUE(is_finite(point_at(dec, static_cast<T>(j) / T(2))));
  // A NaN parameter: NaN point; find_span terminates.
  const BSplineCurve2<T> ok{2, pts, {0, 0, 0, 1, 2, 2, 2}};
  EXPECT_FALSE(is_finite(point_at(ok, std::numeric_limits<T>::quiet_NaN())));
  const int s = find_span(std::span<const T>(ok.knots), 2, 4, std::numeric_limits<T>::quiet_NaN());
  EXPECT_GE(s, 2);
  EXPECT_LE(s, 3);
}

TYPED_TEST(BSplineTest, ParametersAreClampedToTheDomain) {
  using T = TypeParam;
  locus_test::Rng rng(15);
  SCOPED_TRACE(rng.trace());
  const BSplineCurve2<T> c = random_curve<T, 2>(rng, 3, 7, false);
  const ParamDomain<T> dom = domain(c);
  EXPECT_EQ(point_at(c, dom.min - T(5)), point_at(c, dom.min));
  EXPECT_EQ(point_at(c, dom.max + T(5)), point_at(c, dom.max));
  EXPECT_EQ(point_at(c, -std::numeric_limits<T>::infinity()), point_at(c, dom.min));
  EXPECT_EQ(derivative_at(c, dom.max + T(1), 1), derivative_at(c, dom.max, 1));
  // Inserting outside the domain inserts at the clamped end.
  const BSplineCurve2<T> r = insert_knot(c, dom.max + T(3));
  int m = 0;
  for (T k : r.knots) m += k == dom.max;
  EXPECT_GE(m, 2);
}

TYPED_TEST(BSplineTest, DegreeZeroIsPiecewiseConstant) {
  using T = TypeParam;
  const BSplineCurve2<T> c{0, {{T(1), T(1)}, {T(2), T(5)}, {T(-3), T(0)}}, {0, 1, 2, 3}};
  ASSERT_EQ(validate(c), Status::ok);
  EXPECT_EQ(point_at(c, T(0.5)), c.control[0]);
  EXPECT_EQ(point_at(c, T(1)), c.control[1]);  // half-open spans
  EXPECT_EQ(point_at(c, T(3)), c.control[2]);  // the last span is closed
  EXPECT_EQ(derivative_at(c, T(1.5), 1), (Vec2<T>{}));
  const BSplineCurve2<T> dc = derivative(c);
  for (const auto& p : dc.control) EXPECT_EQ(p, (Vec2<T>{}));
  // A single control point of degree 0: the constant curve.
  const BSplineCurve2<T> one{0, {{T(4), T(2)}}, {0, 1}};
  EXPECT_EQ(validate(one), Status::ok);
  EXPECT_EQ(point_at(one, T(0.3)), one.control[0]);
}

TYPED_TEST(BSplineTest, RepeatedControlPointsAndAffineInvariance) {
  using T = TypeParam;
  locus_test::Rng rng(17);
  SCOPED_TRACE(rng.trace());
  // All control points equal: the constant curve, zero derivative.
  const BSplineCurve2<T> rep{3, std::vector<Vec2<T>>(6, Vec2<T>{T(2), T(-1)}),
                             uniform_knots<T>(6, 3)};
  for (int j = 0; j <= 8; ++j) {
    const T t = static_cast<T>(j) / T(8);
    EXPECT_TRUE(locus_test::vec_near(point_at(rep, t), rep.control[0], eval_tol(3, T(2))));
    EXPECT_TRUE(locus_test::vec_near(derivative_at(rep, t, 1), Vec2<T>{}, eval_tol(3, T(2))));
  }
  for (int trial = 0; trial < 10; ++trial) {
    BSplineCurve2<T> c = random_curve<T, 2>(rng, rng.uniform_int(1, 4), 7, trial % 2 == 0);
    BSplineCurve2<T> m = c;
    const T ang = rng.uniform(T(0), T(6)), cs = std::cos(ang), sn = std::sin(ang);
    const Vec2<T> shift = rng.vec<T, 2>(T(-4), T(4));
    const auto xf = [&](const Vec2<T>& p) {
      return Vec2<T>{cs * p.x - sn * p.y, sn * p.x + cs * p.y} + shift;
    };
    for (auto& p : m.control) p = xf(p);
    const ParamDomain<T> dom = domain(c);
    for (int j = 0; j <= 10; ++j) {
      const T t = dom.min + (dom.max - dom.min) * static_cast<T>(j) / T(10);
      EXPECT_TRUE(
          locus_test::vec_near(point_at(m, t), xf(point_at(c, t)), eval_tol(c.degree, T(24))));
    }
  }
}

}  // namespace
