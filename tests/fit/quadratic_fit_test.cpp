// SPDX-License-Identifier: BSL-1.0
// Tests for fit/quadratic_fit.hpp (row num.fit): exact recovery of conics (ellipse, hyperbola,
// parabola) and quadrics (ellipsoid, hyperboloid) under the documented normalisation, Eigen's
// JacobiSVD of the design matrix as the oracle, noisy ellipses within a noise-derived bound,
// translation/scale invariance, and degenerate input (too few points, collinear / coplanar-conic
// configurations with non-unique solutions, NaN).
#include <locus/fit/quadratic_fit.hpp>

#include "fit/fit_test_util.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

using namespace locus;
using fit_test::gauss;
using fit_test::nan_v;
using locus_test::Rng;

template <class T>
class QuadraticFitTest : public ::testing::Test {};
TYPED_TEST_SUITE(QuadraticFitTest, locus_test::RealTypes);

namespace {

// Unit coefficient vector with its largest-magnitude entry positive (the documented form).
template <int K>
std::array<double, K> canonical(std::array<double, K> q) {
  double n = 0;
  int big = 0;
  for (int k = 0; k < K; ++k) {
    n += q[std::size_t(k)] * q[std::size_t(k)];
    if (std::abs(q[std::size_t(k)]) > std::abs(q[std::size_t(big)])) big = k;
  }
  const double s = (q[std::size_t(big)] < 0 ? -1 : 1) / std::sqrt(n);
  for (double& v : q) v *= s;
  return q;
}

template <class T>
std::array<double, 6> coeffs(const QuadraticCurve2<T>& q) {
  return {double(q.a), double(q.b), double(q.c), double(q.d), double(q.e), double(q.f)};
}
template <class T>
std::array<double, 10> coeffs(const Quadric3<T>& q) {
  return {double(q.a(0, 0)),     double(q.a(1, 1)),
          double(q.a(2, 2)),     2 * double(q.a(0, 1)),
          2 * double(q.a(0, 2)), 2 * double(q.a(1, 2)),
          double(q.b.x),         double(q.b.y),
          double(q.b.z),         double(q.c)};
}

// The conic (X - C)^T M (X - C) = 1 of an ellipse with the given axes.
std::array<double, 6> ellipse_conic(const Vec2d& c, double angle, double a, double b) {
  const Vec2d u{std::cos(angle), std::sin(angle)}, v = perp(u);
  const Mat2<double> m = outer(u, u) * (1 / (a * a)) + outer(v, v) * (1 / (b * b));
  const Vec2d mc = m * c;
  return canonical<6>({m(0, 0), 2 * m(0, 1), m(1, 1), -2 * mc.x, -2 * mc.y, dot(c, mc) - 1});
}

double eval_conic(const std::array<double, 6>& q, const Vec2d& p) {
  return q[0] * p.x * p.x + q[1] * p.x * p.y + q[2] * p.y * p.y + q[3] * p.x + q[4] * p.y + q[5];
}

template <int K>
double max_diff(const std::array<double, K>& a, const std::array<double, K>& b) {
  double m = 0;
  for (int k = 0; k < K; ++k) m = std::max(m, std::abs(a[std::size_t(k)] - b[std::size_t(k)]));
  return m;
}

// Sensitivity of the fitted unit coefficient vector to rounding the input points to T: the
// points move by eps(T) |p|, i.e. eps(T) |p|max / s in normalised coordinates, which perturbs the
// design matrix's rows relatively by about twice that; the null vector then moves by that times
// s_0 / s_{K-2} (Wedin). Computed with Eigen's SVD of the normalised design matrix; 16 times it
// plus 16 eps(T) for rounding the result is the exact-recovery tolerance.
template <class T, int N, int K>
double rounding_tolerance(const std::vector<Vec<T, N>>& pts) {
  Vec<double, N> mean{};
  double pmax = 0;
  for (const auto& p : pts) {
    mean += vec_cast<double>(p);
    pmax = std::max(pmax, double(max_abs(p)));
  }
  mean = mean / double(pts.size());
  double s = 0;
  for (const auto& p : pts) s += sqr_length(vec_cast<double>(p) - mean);
  s = std::sqrt(s / double(pts.size()));
  Eigen::MatrixXd v(std::max<int>(int(pts.size()), K), K);
  v.setZero();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec<double, N> u = (vec_cast<double>(pts[i]) - mean) / s;
    if constexpr (N == 2) {
      v.row(int(i)) << u.x * u.x, u.x * u.y, u.y * u.y, u.x, u.y, 1;
    } else {
      v.row(int(i)) << u.x * u.x, u.y * u.y, u.z * u.z, u.x * u.y, u.x * u.z, u.y * u.z, u.x, u.y,
          u.z, 1;
    }
  }
  const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(v).singularValues();
  const double cond = sv(0) / sv(K - 2);
  return 16 * double(eps_v<T>) * (2 * (pmax / s + 1) * cond + 1);
}

}  // namespace

TYPED_TEST(QuadraticFitTest, ExactConics) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const Vec2d c = rng.vec<double, 2>(-2, 2);
    const double ang = rng.uniform<double>(0, pi_v<double>), a = rng.uniform<double>(1, 3),
                 b = rng.uniform<double>(0.5, 1);
    std::vector<Vec2<T>> pts;
    const Vec2d u{std::cos(ang), std::sin(ang)}, v = perp(u);
    for (int i = 0; i < 5 + trial; ++i) {
      const double t = rng.uniform<double>(0, 2 * pi_v<double>);
      pts.push_back(vec_cast<T>(c + a * std::cos(t) * u + b * std::sin(t) * v));
    }
    const QuadraticCurveFit<T> f = fit_quadratic_curve(pts);
    ASSERT_EQ(f.status, Status::ok) << trial;
    const double e = rounding_tolerance<T, 2, 6>(pts);
    EXPECT_LT(max_diff<6>(coeffs(f.curve), ellipse_conic(c, ang, a, b)), e) << trial;
    EXPECT_LT(double(f.rms), e);
    EXPECT_EQ(classify_conic(f.curve), ConicKind::ellipse);
  }
  {  // hyperbola x y = 1 shifted to (1, 2): (x - 1)(y - 2) = 1 -> xy - 2x - y + 1 = 0
    std::vector<Vec2<T>> pts;
    for (double t : {-3.0, -1.5, -0.5, 0.25, 0.5, 2.0, 4.0})
      pts.push_back(vec_cast<T>(Vec2d{1 + t, 2 + 1 / t}));
    const QuadraticCurveFit<T> f = fit_quadratic_curve(pts);
    ASSERT_EQ(f.status, Status::ok);
    const double e = rounding_tolerance<T, 2, 6>(pts);
    EXPECT_LT(max_diff<6>(coeffs(f.curve), canonical<6>({0, 1, 0, -2, -1, 1})), e);
    EXPECT_EQ(classify_conic(f.curve), ConicKind::hyperbola);
  }
  {  // parabola y = x^2 - 2: x^2 - y - 2 = 0, at integer points (exact input)
    std::vector<Vec2<T>> pts;
    for (int x = -3; x <= 3; ++x) pts.push_back({T(x), T(x * x - 2)});
    const QuadraticCurveFit<T> f = fit_quadratic_curve(pts);
    ASSERT_EQ(f.status, Status::ok);
    const double e = rounding_tolerance<T, 2, 6>(pts);
    EXPECT_LT(max_diff<6>(coeffs(f.curve), canonical<6>({1, 0, 0, 0, -1, -2})), e);
  }
}

// Oracle: Eigen's JacobiSVD of the design matrix in the normalised coordinates (built here
// independently). Its null vector w_u defines q_u(u); ours, mapped to the original coordinates,
// must define the same curve: q(p) / q_u((p - mean) / s) is the same constant at any probe p.
TYPED_TEST(QuadraticFitTest, ConicAgainstEigenSvd) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 60;
    std::vector<Vec2<T>> pts;
    for (int i = 0; i < n; ++i) {
      const double t = rng.uniform<double>(0, 2 * pi_v<double>);
      pts.push_back(vec_cast<T>(Vec2d{1 + 2 * std::cos(t) + gauss(rng, 0.1),
                                      -1 + std::sin(t) + 0.3 * std::cos(t) + gauss(rng, 0.1)}));
    }
    const QuadraticCurveFit<T> f = fit_quadratic_curve(pts);
    ASSERT_EQ(f.status, Status::ok);
    Vec2d mean{};
    for (const auto& p : pts) mean += vec_cast<double>(p);
    mean = mean / double(n);
    double s = 0;
    for (const auto& p : pts) s += sqr_length(vec_cast<double>(p) - mean);
    s = std::sqrt(s / n);
    Eigen::MatrixXd v(n, 6);
    for (int i = 0; i < n; ++i) {
      const Vec2d u = (vec_cast<double>(pts[std::size_t(i)]) - mean) / s;
      v.row(i) << u.x * u.x, u.x * u.y, u.y * u.y, u.x, u.y, 1;
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(v, Eigen::ComputeThinV);
    const Eigen::VectorXd w = svd.matrixV().col(5);
    const std::array<double, 6> wu{w(0), w(1), w(2), w(3), w(4), w(5)};
    const std::array<double, 6> q = coeffs(f.curve);
    // Null-vector accuracy (both solvers): 64 eps(double) s_0 / (s_4 - s_5), plus 16 eps(T) for
    // rounding our unit vector to T. A value q(p) then errs by that times |v(p)| (the monomial
    // vector's norm at the probe, Cauchy-Schwarz).
    const double sens =
        svd.singularValues()(0) / (svd.singularValues()(4) - svd.singularValues()(5));
    const double e = 16 * double(eps_v<T>) + 64 * 2.3e-16 * sens;
    auto vnorm = [](const Vec2d& p) {
      return std::sqrt(sqr(p.x * p.x) + sqr(p.x * p.y) + sqr(p.y * p.y) + sqr_length(p) + 1);
    };
    // The ratio comes from the probe with the largest |q_u| (a probe near the curve would give
    // an inaccurate ratio); its own error propagates to the other probes.
    std::vector<Vec2d> probes;
    int best = 0;
    for (int k = 0; k < 8; ++k) {
      probes.push_back(rng.vec<double, 2>(-3, 3));
      if (std::abs(eval_conic(wu, (probes[std::size_t(k)] - mean) / s)) >
          std::abs(eval_conic(wu, (probes[std::size_t(best)] - mean) / s)))
        best = k;
    }
    const Vec2d pb = probes[std::size_t(best)], ub = (pb - mean) / s;
    const double ratio = eval_conic(q, pb) / eval_conic(wu, ub);
    const double dratio =
        2 * e * (vnorm(pb) + std::abs(ratio) * vnorm(ub)) / std::abs(eval_conic(wu, ub));
    for (const Vec2d& p : probes) {
      const Vec2d u = (p - mean) / s;
      const double qu = eval_conic(wu, u), qp = eval_conic(q, p);
      EXPECT_NEAR(qp, ratio * qu,
                  2 * e * (vnorm(p) + std::abs(ratio) * vnorm(u)) + dratio * std::abs(qu))
          << trial;
    }
  }
}

// Noisy ellipse (semi-axes a = 3, b = 2, n = 500 points, radial-ish noise sigma): at a point on
// the true curve, the first-order distance |q(p)| / |grad q(p)| to the fitted conic. Each of the
// 6 normalised coefficients is determined to about sigma / sqrt(n) in units of the curve's
// size, and a point's displacement combines them: RMS about sqrt(6) sigma / sqrt(n), times the
// aspect a / b for the weighting of the algebraic distance along the curve; the algebraic fit's
// bias adds O(sigma^2 / b). Six times the first term plus 4 sigma^2 / b.
TYPED_TEST(QuadraticFitTest, NoisyEllipse) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int n = 500;
  const double sigma = 0.01, a = 3, b = 2;
  for (int trial = 0; trial < 5; ++trial) {
    const Vec2d c = rng.vec<double, 2>(-5, 5);
    const double ang = rng.uniform<double>(0, pi_v<double>);
    const Vec2d u{std::cos(ang), std::sin(ang)}, v = perp(u);
    std::vector<Vec2<T>> pts;
    std::vector<Vec2d> truth;
    for (int i = 0; i < n; ++i) {
      const double t = rng.uniform<double>(0, 2 * pi_v<double>);
      truth.push_back(c + a * std::cos(t) * u + b * std::sin(t) * v);
      pts.push_back(vec_cast<T>(truth.back() + Vec2d{gauss(rng, sigma), gauss(rng, sigma)}));
    }
    const QuadraticCurveFit<T> f = fit_quadratic_curve(pts);
    ASSERT_EQ(f.status, Status::ok);
    EXPECT_EQ(classify_conic(f.curve), ConicKind::ellipse);
    const std::array<double, 6> q = coeffs(f.curve);
    double ss = 0;
    for (const Vec2d& p : truth) {
      const Vec2d g{2 * q[0] * p.x + q[1] * p.y + q[3], q[1] * p.x + 2 * q[2] * p.y + q[4]};
      ss += sqr(eval_conic(q, p) / length(g));
    }
    const double rms_dist = std::sqrt(ss / n);
    EXPECT_LT(rms_dist,
              6 * std::sqrt(6.0) * sigma / std::sqrt(double(n)) * (a / b) + 4 * sigma * sigma / b)
        << trial;
  }
}

// Hartley normalisation makes the fit covariant under translation and uniform scaling: the
// fitted conic of k P + t is the image of the fitted conic of P.
TYPED_TEST(QuadraticFitTest, TranslationScaleInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<Vec2<T>> pts, moved;
    const double k = rng.uniform<double>(0.5, 4);
    const Vec2d t = rng.vec<double, 2>(-10, 10);
    for (int i = 0; i < 40; ++i) {
      const double s = rng.uniform<double>(-2, 2);
      pts.push_back(vec_cast<T>(Vec2d{s + gauss(rng, 0.1), s * s * 0.5 + gauss(rng, 0.1)}));
      moved.push_back(vec_cast<T>(k * vec_cast<double>(pts.back()) + t));
    }
    const QuadraticCurveFit<T> f = fit_quadratic_curve(pts), g = fit_quadratic_curve(moved);
    ASSERT_EQ(f.status, Status::ok);
    ASSERT_EQ(g.status, Status::ok);
    const std::array<double, 6> qf = coeffs(f.curve), qg = coeffs(g.curve);
    // Probes p and their images k p + t: the ratio of the values is one constant. The
    // coefficient vectors err by the rounding tolerance of their own point sets (the moved
    // points are rounded to T again), a value by that times the monomial vector's norm.
    const double ef = rounding_tolerance<T, 2, 6>(pts), eg = rounding_tolerance<T, 2, 6>(moved);
    auto vnorm = [](const Vec2d& p) {
      return std::sqrt(sqr(p.x * p.x) + sqr(p.x * p.y) + sqr(p.y * p.y) + sqr_length(p) + 1);
    };
    // The ratio from the probe with the largest |q_f| (see ConicAgainstEigenSvd).
    std::vector<Vec2d> probes;
    int best = 0;
    for (int j = 0; j < 8; ++j) {
      probes.push_back(rng.vec<double, 2>(-2, 2));
      if (std::abs(eval_conic(qf, probes[std::size_t(j)])) >
          std::abs(eval_conic(qf, probes[std::size_t(best)])))
        best = j;
    }
    const Vec2d pb = probes[std::size_t(best)];
    const double ratio = eval_conic(qg, k * pb + t) / eval_conic(qf, pb);
    const double dratio = 2 * (eg * vnorm(k * pb + t) + std::abs(ratio) * ef * vnorm(pb)) /
                          std::abs(eval_conic(qf, pb));
    for (const Vec2d& p : probes) {
      const Vec2d pm = k * p + t;
      const double a = eval_conic(qf, p), b = eval_conic(qg, pm);
      EXPECT_NEAR(b, ratio * a,
                  2 * (eg * vnorm(pm) + std::abs(ratio) * ef * vnorm(p)) + dratio * std::abs(a))
          << trial;
    }
  }
}

TYPED_TEST(QuadraticFitTest, ConicDegenerateInput) {
  using T = TypeParam;
  const std::vector<Vec2<T>> none;
  EXPECT_EQ(fit_quadratic_curve(none).status, Status::empty_input);
  const std::vector<Vec2<T>> four{{T(0), T(0)}, {T(1), T(0)}, {T(0), T(1)}, {T(1), T(1)}};
  EXPECT_EQ(fit_quadratic_curve(four).status, Status::degenerate_input);
  // Collinear points: every conic "line x any line" passes through them.
  std::vector<Vec2<T>> line;
  for (int i = 0; i < 10; ++i) line.push_back({T(i), T(2 * i - 3)});
  const QuadraticCurveFit<T> l = fit_quadratic_curve(line);
  EXPECT_EQ(l.status, Status::degenerate_input);
  EXPECT_TRUE(std::isnan(l.rms));
  EXPECT_EQ(l.curve.a, T(0));
  // Four collinear points and a fifth: the line times any line through the fifth point.
  std::vector<Vec2<T>> five{{T(0), T(0)}, {T(1), T(1)}, {T(2), T(2)}, {T(3), T(3)}, {T(0), T(5)}};
  EXPECT_EQ(fit_quadratic_curve(five).status, Status::degenerate_input);
  // Five points in general position: the unique conic through them, exactly (circle of radius
  // 5 through integer points: x^2 + y^2 - 25 = 0).
  const std::vector<Vec2<T>> circ{
      {T(5), T(0)}, {T(3), T(4)}, {T(0), T(5)}, {T(-4), T(3)}, {T(-3), T(-4)}};
  const QuadraticCurveFit<T> c5 = fit_quadratic_curve(circ);
  ASSERT_EQ(c5.status, Status::ok);
  EXPECT_LT(max_diff<6>(coeffs(c5.curve), canonical<6>({1, 0, 1, 0, 0, -25})),
            64 * double(eps_v<T>) * 25);
  const std::vector<Vec2<T>> same(8, Vec2<T>{T(1), T(2)});
  EXPECT_EQ(fit_quadratic_curve(same).status, Status::degenerate_input);
  std::vector<Vec2<T>> bad = circ;
  bad[2].y = nan_v<T>();
  EXPECT_EQ(fit_quadratic_curve(bad).status, Status::non_finite_input);
}

TYPED_TEST(QuadraticFitTest, ExactQuadrics) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 10; ++trial) {
    // Ellipsoid (X - C)^T R D R^T (X - C) = 1 with semi-axes 1..3, sampled at 9 + 3 trial points.
    const Mat3<double> r = fit_test::random_rotation3(rng);
    const Vec3d c = rng.vec<double, 3>(-2, 2),
                ax{rng.uniform<double>(1, 3), rng.uniform<double>(1, 3), rng.uniform<double>(1, 3)};
    const Mat3<double> m =
        r * Mat3<double>::diagonal({1 / (ax.x * ax.x), 1 / (ax.y * ax.y), 1 / (ax.z * ax.z)}) *
        transpose(r);
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 9 + 3 * trial; ++i) {
      const Vec3d s = rng.unit<double, 3>();
      pts.push_back(vec_cast<T>(c + r * Vec3d{ax.x * s.x, ax.y * s.y, ax.z * s.z}));
    }
    const QuadricFit<T> f = fit_quadric(pts);
    ASSERT_EQ(f.status, Status::ok) << trial;
    const double e = rounding_tolerance<T, 3, 10>(pts);
    const Vec3d mc = m * c;
    const std::array<double, 10> want =
        canonical<10>({m(0, 0), m(1, 1), m(2, 2), 2 * m(0, 1), 2 * m(0, 2), 2 * m(1, 2), -2 * mc.x,
                       -2 * mc.y, -2 * mc.z, dot(c, mc) - 1});
    EXPECT_LT(max_diff<10>(coeffs(f.quadric), want), e) << trial;
    EXPECT_EQ(quadric_type(f.quadric).type, QuadricType::ellipsoid);
  }
  {  // hyperboloid of one sheet x^2 + y^2 - z^2 = 1
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 30; ++i) {
      const double t = rng.uniform<double>(0, 2 * pi_v<double>), h = rng.uniform<double>(-2, 2);
      const double rr = std::sqrt(1 + h * h);
      pts.push_back(vec_cast<T>(Vec3d{rr * std::cos(t), rr * std::sin(t), h}));
    }
    const QuadricFit<T> f = fit_quadric(pts);
    ASSERT_EQ(f.status, Status::ok);
    const double e = rounding_tolerance<T, 3, 10>(pts);
    // Four coefficients tie in magnitude, so the sign convention is decided by rounding:
    // compare up to sign.
    const std::array<double, 10> want = canonical<10>({1, 1, -1, 0, 0, 0, 0, 0, 0, -1});
    std::array<double, 10> neg = want;
    for (double& x : neg) x = -x;
    EXPECT_LT(std::min(max_diff<10>(coeffs(f.quadric), want), max_diff<10>(coeffs(f.quadric), neg)),
              e);
  }
}

TYPED_TEST(QuadraticFitTest, QuadricDegenerateInput) {
  using T = TypeParam;
  const std::vector<Vec3<T>> none;
  EXPECT_EQ(fit_quadric(none).status, Status::empty_input);
  std::vector<Vec3<T>> eight;
  for (int i = 0; i < 8; ++i) eight.push_back({T(i % 2), T((i / 2) % 2), T(i / 4)});
  EXPECT_EQ(fit_quadric(eight).status, Status::degenerate_input);
  // Points on a circle in the plane z = 1: (z - 1) * (any linear) and the cylinder all fit.
  std::vector<Vec3<T>> circ;
  for (int i = 0; i < 20; ++i) {
    const double a = 0.3 * i;
    circ.push_back(vec_cast<T>(Vec3d{std::cos(a), std::sin(a), 1}));
  }
  const QuadricFit<T> f = fit_quadric(circ);
  EXPECT_EQ(f.status, Status::degenerate_input);
  EXPECT_TRUE(std::isnan(f.rms));
  std::vector<Vec3<T>> bad(12, Vec3<T>{1, 2, 3});
  bad[3].z = std::numeric_limits<T>::infinity();
  EXPECT_EQ(fit_quadric(bad).status, Status::non_finite_input);
}
