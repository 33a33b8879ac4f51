// SPDX-License-Identifier: BSL-1.0
// NURBS curves: exact rational evaluation and derivatives (GMP), the unit-weight case against the
// B-spline, circles and arcs as exact NURBS, weights and bad input.

#include <locus/curves/nurbs.hpp>

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
class NurbsTest : public ::testing::Test {};
TYPED_TEST_SUITE(NurbsTest, locus_test::RealTypes);

/// Exact N'_{i,p}(t) = p (N_{i,p-1} / (t_{i+p} - t_i) - N_{i+1,p-1} / (t_{i+p+1} - t_{i+1})).
Q basis_derivative(const std::vector<Q>& kn, int i, int p, const Q& t, int span) {
  if (p == 0) return 0;
  const auto ui = static_cast<std::size_t>(i), up = static_cast<std::size_t>(p);
  Q r = 0;
  if (kn[ui + up] != kn[ui])
    r += curve_oracle::cox_de_boor(kn, i, p - 1, t, span) / (kn[ui + up] - kn[ui]);
  if (kn[ui + up + 1] != kn[ui + 1])
    r -= curve_oracle::cox_de_boor(kn, i + 1, p - 1, t, span) / (kn[ui + up + 1] - kn[ui + 1]);
  return r * p;
}

/// Exact C(t) and C'(t) of a NURBS curve with dyadic data.
template <class T, int N>
std::pair<curve_oracle::QVec<N>, curve_oracle::QVec<N>> exact(const NurbsCurve<T, N>& c,
                                                              const Q& t) {
  const auto kn = curve_oracle::knots_q(c.knots);
  const int n = static_cast<int>(c.control.size());
  const int span = curve_oracle::span_scan(kn, c.degree, n, t);
  const auto qp = curve_oracle::to_q(c.control);
  curve_oracle::QVec<N> a{}, da{};
  Q w = 0, dw = 0;
  for (int i = 0; i < n; ++i) {
    const Q wi(static_cast<double>(c.weights[static_cast<std::size_t>(i)]));
    const Q b = curve_oracle::cox_de_boor(kn, i, c.degree, t, span) * wi;
    const Q db = basis_derivative(kn, i, c.degree, t, span) * wi;
    w += b;
    dw += db;
    for (std::size_t k = 0; k < N; ++k) {
      a[k] += b * qp[static_cast<std::size_t>(i)][k];
      da[k] += db * qp[static_cast<std::size_t>(i)][k];
    }
  }
  curve_oracle::QVec<N> p{}, dp{};
  for (std::size_t k = 0; k < N; ++k) {
    p[k] = a[k] / w;
    dp[k] = (da[k] - dw * p[k]) / w;
  }
  return {p, dp};
}

template <class T, int N>
NurbsCurve<T, N> random_nurbs(locus_test::Rng& rng, int d, int n) {
  NurbsCurve<T, N> c{d, curve_oracle::dyadic_points<T, N>(rng, n), {}, {}};
  for (int i = 0; i < n; ++i) c.weights.push_back(static_cast<T>(rng.uniform_int(2, 16)) / T(4));
  // Clamped knots with dyadic interior values (multiplicities <= d).
  for (;;) {
    c.knots.assign(static_cast<std::size_t>(d) + 1, T(0));
    T x = T(0);
    for (int i = 0; i < n - d - 1; ++i) {
      x += static_cast<T>(rng.uniform_int(0, 2)) / T(4);
      c.knots.push_back(x);
    }
    x += T(0.25);
    c.knots.insert(c.knots.end(), static_cast<std::size_t>(d) + 1, x);
    if (validate(c) == Status::ok) return c;
  }
}

// Rational de Boor: A and W each carry ~2 (d + 1) eps relative error of their own scale; the
// quotient amplifies by wmax / wmin <= 8 here. Hence 16 (d + 1) * 8 eps * scale.
template <class T>
T rational_tol(int d, T scale) {
  return tol(T(128 * (d + 1)), scale);
}

TYPED_TEST(NurbsTest, MatchesExactRationalEvaluation) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const int d = rng.uniform_int(1, 4);
    const int n = d + rng.uniform_int(1, 5);
    const NurbsCurve2<T> c = random_nurbs<T, 2>(rng, d, n);
    const T scale = curve_oracle::max_abs_points(c.control);
    const ParamDomain<T> dom = domain(c);
    for (int j = 0; j <= 16; ++j) {
      const T t = dom.min + (dom.max - dom.min) * static_cast<T>(j) / T(16);
      const auto e = exact(c, Q(static_cast<double>(t)));
      ASSERT_TRUE(curve_oracle::near_q(point_at(c, t), e.first, double(rational_tol(d, scale))))
          << "d = " << d << ", t = " << t;
      // Derivative: |C'| <= d / (min span 1/4) * 2 max|P| * (wmax/wmin); tolerance on that scale.
      const T dscale = scale * T(8 * d) * T(8);
      ASSERT_TRUE(
          curve_oracle::near_q(derivative_at(c, t, 1), e.second, double(rational_tol(d, dscale))))
          << "d = " << d << ", t = " << t;
      // The homogeneous B-spline projects to the same point.
      const BSplineCurve<T, 3> h = to_homogeneous(c);
      const Vec3<T> hp = point_at(h, t);
      EXPECT_TRUE(locus_test::vec_near(Vec2<T>{hp.x / hp.z, hp.y / hp.z}, point_at(c, t),
                                       rational_tol(d, scale)));
      EXPECT_NEAR(weight_at(c, t), hp.z, tol(T(4), T(4)));
    }
  }
}

TYPED_TEST(NurbsTest, SecondDerivativeMatchesFiniteDifferences) {
  using T = TypeParam;
  locus_test::Rng rng(3);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 10; ++trial) {
    const int d = rng.uniform_int(2, 4);
    const NurbsCurve3<T> ct = random_nurbs<T, 3>(rng, d, d + 3);
    NurbsCurve3<double> c{d, {}, {}, {}};
    for (const auto& p : ct.control) c.control.push_back(vec_cast<double>(p));
    for (T w : ct.weights) c.weights.push_back(double(w));
    for (T k : ct.knots) c.knots.push_back(double(k));
    const ParamDomain<double> dom = domain(c);
    for (int j = 0; j < 20; ++j) {
      const double t = dom.min + (dom.max - dom.min) * (j + 0.5) / 20.0;
      bool near_knot = false;
      for (double k : c.knots) near_knot = near_knot || std::abs(k - t) < 1e-3;
      if (near_knot) continue;
      const double h = 1e-5;
      const std::vector<Vec3<double>> dv = derivatives(c, t, 2);
      ASSERT_EQ(dv.size(), 3u);
      const Vec3<double> fd = (derivative_at(c, t + h, 1) - derivative_at(c, t - h, 1)) / (2 * h);
      // Truncation h^2/6 |C''''| (|C^(k)| <= 8 (32 d)^k max|P| for these weights and spans).
      const double maxp = double(curve_oracle::max_abs_points(ct.control));
      const double ftol = h * h * 8 * std::pow(32.0 * d, 4) * maxp + 1e-10 * maxp * 64 * d;
      EXPECT_TRUE(locus_test::vec_near(dv[2], fd, ftol)) << "t = " << t;
      EXPECT_EQ(dv[0], point_at(c, t));
    }
  }
}

TYPED_TEST(NurbsTest, UnitWeightsEqualTheBSpline) {
  using T = TypeParam;
  locus_test::Rng rng(5);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int d = rng.uniform_int(0, 4);
    const int n = d + rng.uniform_int(1, 5);
    const BSplineCurve2<T> b{d, curve_oracle::dyadic_points<T, 2>(rng, n),
                             trial % 2 ? uniform_knots<T>(n, d) : open_uniform_knots<T>(n, d)};
    const NurbsCurve2<T> c = to_nurbs(b);
    ASSERT_EQ(validate(c), Status::ok);
    const T scale = curve_oracle::max_abs_points(b.control);
    for (int j = 0; j <= 16; ++j) {
      const T t = static_cast<T>(j) / T(16);
      EXPECT_TRUE(locus_test::vec_near(point_at(c, t), point_at(b, t), tol(T(8 * (d + 1)), scale)));
      EXPECT_NEAR(weight_at(c, t), T(1), tol(T(4 * (d + 1))));
      for (int k = 1; k <= 2; ++k) {
        T ds = scale;
        for (int s = 0; s < k; ++s) ds *= T(2 * d * n);
        EXPECT_TRUE(locus_test::vec_near(derivative_at(c, t, k), derivative_at(b, t, k),
                                         tol(T(32 * (d + 1)), ds)))
            << "k = " << k;
      }
    }
  }
}

TYPED_TEST(NurbsTest, CircleIsExact) {
  using T = TypeParam;
  locus_test::Rng rng(7);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 10; ++trial) {
    const Circle2<T> circ{rng.vec<T, 2>(T(-5), T(5)), rng.uniform(T(0.5), T(5))};
    const NurbsCurve2<T> c = to_nurbs(circ);
    ASSERT_EQ(validate(c), Status::ok);
    EXPECT_EQ(c.degree, 2);
    EXPECT_EQ(c.control.size(), 9u);
    const T scale = max_abs(circ.center) + circ.radius;
    for (int j = 0; j <= 200; ++j) {
      const T t = static_cast<T>(j) / T(200);
      const Vec2<T> p = point_at(c, t);
      // Control points and weights are rounded once each, evaluation a few times more.
      EXPECT_NEAR(length(p - circ.center), circ.radius, tol(T(32), scale)) << "t = " << t;
      // The tangent is perpendicular to the radius.
      const Vec2<T> dp = derivative_at(c, t, 1);
      EXPECT_NEAR(dot(dp, p - circ.center) / (length(dp) * circ.radius), T(0), tol(T(256), scale));
    }
    EXPECT_TRUE(locus_test::vec_near(point_at(c, T(0)), circ.center + Vec2<T>{circ.radius, T(0)},
                                     tol(T(8), scale)));
    EXPECT_TRUE(locus_test::vec_near(point_at(c, T(0.25)), circ.center + Vec2<T>{T(0), circ.radius},
                                     tol(T(8), scale)));
    // The control box contains the circle's box (convex hull, positive weights).
    const AlignedBox2<T> box = bounding_box(c);
    EXPECT_LE(box.min.x, circ.center.x - circ.radius + tol(T(8), scale));
    EXPECT_GE(box.max.y, circ.center.y + circ.radius - tol(T(8), scale));
  }
}

TYPED_TEST(NurbsTest, ArcsAreExactIn2DAnd3D) {
  using T = TypeParam;
  locus_test::Rng rng(9);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const T r = rng.uniform(T(0.5), T(3));
    const T start = rng.uniform(T(-4), T(4));
    T sweep = rng.uniform(T(-2) * pi_v<T>, T(2) * pi_v<T>);
    if (trial == 0) sweep = T(0);  // a degenerate arc: a single point
    const Arc2<T> arc{{rng.vec<T, 2>(T(-3), T(3)), r}, start, sweep};
    const NurbsCurve2<T> c = to_nurbs(arc);
    ASSERT_EQ(validate(c), Status::ok);
    const T scale = max_abs(arc.circle.center) + r + T(1);
    for (int j = 0; j <= 64; ++j) {
      const T t = static_cast<T>(j) / T(64);
      EXPECT_NEAR(length(point_at(c, t) - arc.circle.center), r, tol(T(64), scale));
    }
    // End points at the start and end angles; a piece never spans more than a quarter turn.
    const Vec2<T> p0 = arc.circle.center + r * Vec2<T>{std::cos(start), std::sin(start)};
    const Vec2<T> p1 =
        arc.circle.center + r * Vec2<T>{std::cos(start + sweep), std::sin(start + sweep)};
    EXPECT_TRUE(locus_test::vec_near(point_at(c, T(0)), p0, tol(T(64), scale)));
    EXPECT_TRUE(locus_test::vec_near(point_at(c, T(1)), p1, tol(T(64), scale)));
    for (std::size_t i = 1; i < c.weights.size(); i += 2) EXPECT_GE(c.weights[i], T(0.7));
    // The midpoint parameter of a single piece lies at the middle angle (symmetric weights).
    if (c.control.size() == 3) {
      const T mid = start + sweep / T(2);
      EXPECT_TRUE(locus_test::vec_near(
          point_at(c, T(0.5)), arc.circle.center + r * Vec2<T>{std::cos(mid), std::sin(mid)},
          tol(T(64), scale)));
    }
  }
  // A 3D arc in the plane spanned by orthonormal u, v.
  const Vec3<T> center{T(1), T(2), T(3)};
  const Vec3<T> u = normalize(Vec3<T>{T(1), T(1), T(0)});
  const Vec3<T> v = normalize(Vec3<T>{T(-1), T(1), T(1)});
  const Vec3<T> nrm = cross(u, v);
  const NurbsCurve3<T> c3 = nurbs_arc(center, u, v, T(2), T(0.3), T(4));
  ASSERT_EQ(validate(c3), Status::ok);
  for (int j = 0; j <= 32; ++j) {
    const Vec3<T> p = point_at(c3, static_cast<T>(j) / T(32));
    EXPECT_NEAR(length(p - center), T(2), tol(T(64), T(5)));
    EXPECT_NEAR(dot(p - center, nrm), T(0), tol(T(64), T(5)));
  }
}

TYPED_TEST(NurbsTest, KnotInsertionKeepsTheCurve) {
  using T = TypeParam;
  locus_test::Rng rng(11);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 15; ++trial) {
    const int d = rng.uniform_int(1, 4);
    const NurbsCurve2<T> c = random_nurbs<T, 2>(rng, d, d + rng.uniform_int(1, 4));
    const ParamDomain<T> dom = domain(c);
    const T t = dom.min + (dom.max - dom.min) * static_cast<T>(rng.uniform_int(0, 16)) / T(16);
    const NurbsCurve2<T> r = insert_knot(c, t, rng.uniform_int(1, d));
    ASSERT_EQ(validate(r), Status::ok);  // weights stay positive
    const T scale = curve_oracle::max_abs_points(c.control);
    for (int j = 0; j <= 16; ++j) {
      const T x = dom.min + (dom.max - dom.min) * static_cast<T>(j) / T(16);
      EXPECT_TRUE(curve_oracle::near_q(point_at(r, x), exact(c, Q(static_cast<double>(x))).first,
                                       double(T(2) * rational_tol(2 * d, scale))));
    }
  }
  // The circle stays a circle after refinement.
  const NurbsCurve2<T> circ = insert_knot(to_nurbs(Circle2<T>{{T(0), T(0)}, T(1)}), T(0.1), 2);
  for (int j = 0; j <= 32; ++j)
    EXPECT_NEAR(length(point_at(circ, static_cast<T>(j) / T(32))), T(1), tol(T(64)));
}

TYPED_TEST(NurbsTest, WeightsAndBadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const std::vector<Vec2<T>> pts{{T(0), T(0)}, {T(1), T(2)}, {T(3), T(0)}};
  const std::vector<T> kn{0, 0, 0, 1, 1, 1};
  EXPECT_EQ(validate(NurbsCurve2<T>{2, pts, {1, 2, 1}, kn}), Status::ok);
  EXPECT_EQ(validate(NurbsCurve2<T>{2, pts, {1, 0, 1}, kn}), Status::invalid_input);
  EXPECT_EQ(validate(NurbsCurve2<T>{2, pts, {1, -1, 1}, kn}), Status::invalid_input);
  EXPECT_EQ(validate(NurbsCurve2<T>{2, pts, {1, nan, 1}, kn}), Status::non_finite_input);
  EXPECT_EQ(validate(NurbsCurve2<T>{2, pts, {1, 1}, kn}), Status::invalid_input);
  EXPECT_EQ(validate(NurbsCurve2<T>{2, pts, {1, 1, 1}, {0, 0, 1, 1, 1, 1}}), Status::invalid_input);
  EXPECT_EQ(validate(NurbsCurve2<T>{2, pts, {1, 1, 1}, {0, 0, 0, 2, 1, 1}}), Status::invalid_input);
  // A mismatched weight count is structurally invalid: NaN, never an out-of-range read.
  EXPECT_FALSE(is_finite(point_at(NurbsCurve2<T>{2, pts, {1, 1}, kn}, T(0.5))));
  EXPECT_FALSE(is_finite(derivative_at(NurbsCurve2<T>{2, pts, {1, 1}, kn}, T(0.5), 1)));
  // A zero weight at an end: still evaluable inside (W > 0 there), the end point is NaN
  // because W(0) = 0 there (not a finite point presented as valid).
  const NurbsCurve2<T> z0{2, pts, {0, 1, 1}, kn};
  EXPECT_EQ(weight_at(z0, T(0)), T(0));
  EXPECT_FALSE(is_finite(point_at(z0, T(0))));
  EXPECT_TRUE(is_finite(point_at(z0, T(0.5))));
  // Weights of mixed sign: W(t) = (1 - t)^2 - 2 t (1 - t)... vanishes inside; NaN exactly there.
  const std::vector<Vec2<T>> line{{T(0), T(0)}, {T(2), T(0)}};
  const NurbsCurve2<T> mixed{1, line, {1, -1}, {0, 0, 1, 1}};  // W(t) = 1 - 2 t
  EXPECT_EQ(validate(mixed), Status::invalid_input);
  EXPECT_EQ(weight_at(mixed, T(0.5)), T(0));
  EXPECT_FALSE(is_finite(point_at(mixed, T(0.5))));
  for (const auto& dv : derivatives(mixed, T(0.5), 2)) EXPECT_FALSE(is_finite(dv));
  EXPECT_TRUE(is_finite(point_at(mixed, T(0.25))));  // (0 * 0.75 + 2 * -0.25) / 0.5 = -1
  EXPECT_TRUE(locus_test::vec_near(point_at(mixed, T(0.25)), Vec2<T>{T(-1), T(0)}, tol(T(8))));
  // All weights zero: nothing is defined.
  const NurbsCurve2<T> zero{2, pts, {0, 0, 0}, kn};
  for (int j = 0; j <= 4; ++j) EXPECT_FALSE(is_finite(point_at(zero, static_cast<T>(j) / T(4))));
  // NaN control point and NaN parameter propagate as NaN.
  EXPECT_FALSE(is_finite(point_at(
      NurbsCurve2<T>{2, {{T(0), T(0)}, {nan, T(1)}, {T(3), T(0)}}, {1, 1, 1}, kn}, T(0.5))));
  EXPECT_FALSE(is_finite(point_at(NurbsCurve2<T>{2, pts, {1, 1, 1}, kn}, nan)));
  // Parameters are clamped to the domain.
  const NurbsCurve2<T> ok{2, pts, {1, 2, 1}, kn};
  EXPECT_EQ(point_at(ok, T(-2)), pts.front());
  EXPECT_EQ(point_at(ok, T(9)), pts.back());
  EXPECT_TRUE(derivatives(ok, T(0.5), -1).empty());
}

}  // namespace
