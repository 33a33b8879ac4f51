// SPDX-License-Identifier: BSL-1.0
// Tests for fit/line_fit.hpp (row num.fit; book figure 2.9): exact recovery, recovery from noisy
// samples within noise-derived bounds, brute-force search over directions as the oracle of the
// orthogonal fit, Eigen's QR least squares as the oracle of the vertical fit, rigid-motion
// invariance, and degenerate input.
#include <locus/fit/line_fit.hpp>

#include "fit/fit_test_util.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

using namespace locus;
using fit_test::gauss;
using fit_test::nan_v;
using fit_test::sin_angle;
using locus_test::Rng;

template <class T>
class LineFitTest : public ::testing::Test {};
TYPED_TEST_SUITE(LineFitTest, locus_test::RealTypes);

TYPED_TEST(LineFitTest, ExactRecovery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3d o = rng.vec<double, 3>(-5, 5), d = rng.unit<double, 3>();
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 20; ++i) pts.push_back(vec_cast<T>(o + rng.uniform<double>(-3, 3) * d));
    const LineFit<T, 3> f = fit_line(pts);
    ASSERT_EQ(f.status, Status::ok);
    // The only error is the rounding of the input points to T (relative eps(T) of |p| <= 14):
    // the direction is tilted by at most that over the spread (>= ~1), the origin is off the
    // line by at most the same.
    const double e = 64 * double(eps_v<T>) * 14;
    EXPECT_LT(sin_angle(vec_cast<double>(f.line.direction), d), e);
    const Vec3d q = vec_cast<double>(f.line.origin) - o;
    EXPECT_LT(std::sqrt(sqr_length(q - dot(q, d) * d)), e);
    EXPECT_NEAR(length(f.line.direction), T(1), T(4) * eps_v<T>);
    EXPECT_LT(double(f.rms), e);
  }
}

// Noisy samples: n points at parameters uniform on [-L, L] (variance L^2/3) with N(0, sigma^2)
// noise perpendicular to the line. The least-squares slope in the line's frame has standard
// deviation sigma / (sqrt(n) * L / sqrt(3)) and the offset at the centroid sigma / sqrt(n);
// six standard deviations bound both (a false failure has probability < 1e-8).
TYPED_TEST(LineFitTest, NoisyRecovery2D) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int n = 400;
  const double sigma = 0.01, L = 10;
  for (int trial = 0; trial < 10; ++trial) {
    const Vec2d o = rng.vec<double, 2>(-5, 5), d = rng.unit<double, 2>(), nrm = perp(d);
    std::vector<Vec2<T>> pts;
    for (int i = 0; i < n; ++i)
      pts.push_back(vec_cast<T>(o + rng.uniform<double>(-L, L) * d + gauss(rng, sigma) * nrm));
    const LineFit<T, 2> f = fit_line(pts);
    ASSERT_EQ(f.status, Status::ok);
    const double slope_sd = sigma / (std::sqrt(double(n)) * L / std::sqrt(3.0));
    EXPECT_LT(sin_angle(vec_cast<double>(f.line.direction), d), 6 * slope_sd);
    EXPECT_LT(std::abs(dot(vec_cast<double>(f.line.origin) - o, nrm)),
              6 * sigma / std::sqrt(double(n)));
    // rms^2 estimates sigma^2 (n - 2) / n with relative standard deviation sqrt(2 / n).
    EXPECT_NEAR(double(f.rms), sigma, 6 * sigma / std::sqrt(2.0 * n) + sigma * 2.0 / n);
  }
}

TYPED_TEST(LineFitTest, NoisyRecovery3D) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int n = 500;
  const double sigma = 0.02, L = 5;
  for (int trial = 0; trial < 10; ++trial) {
    const Mat3<double> r = fit_test::random_rotation3(rng);
    const Vec3d o = rng.vec<double, 3>(-5, 5), d = col(r, 0), u = col(r, 1), v = col(r, 2);
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < n; ++i)
      pts.push_back(vec_cast<T>(o + rng.uniform<double>(-L, L) * d + gauss(rng, sigma) * u +
                                gauss(rng, sigma) * v));
    const LineFit<T, 3> f = fit_line(pts);
    ASSERT_EQ(f.status, Status::ok);
    // Two independent tilt components, each with the 2D standard deviation: 6 sd of each gives
    // 6 sqrt(2) sd for the angle.
    const double slope_sd = sigma / (std::sqrt(double(n)) * L / std::sqrt(3.0));
    EXPECT_LT(sin_angle(vec_cast<double>(f.line.direction), d), 6 * std::sqrt(2.0) * slope_sd);
    const Vec3d q = vec_cast<double>(f.line.origin) - o;
    EXPECT_LT(length(q - dot(q, d) * d), 6 * std::sqrt(2.0) * sigma / std::sqrt(double(n)));
  }
}

// Oracle: brute force over directions in [0, pi) of the orthogonal cost about the centroid (the
// optimal line passes through it). The grid's best direction is within half a step of the
// optimum; the fitted cost must not exceed the grid's best (up to
// rounding), and the angles must agree to half a step plus the eigenvector's sensitivity.
TYPED_TEST(LineFitTest, BruteForceDirectionOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 12; ++trial) {
    const double a = rng.uniform<double>(0, pi_v<double>), sx = rng.uniform<double>(1, 3),
                 sy = rng.uniform<double>(0.1, 0.5);
    const Vec2d d{std::cos(a), std::sin(a)};
    std::vector<Vec2<T>> pts;
    for (int i = 0; i < 60; ++i)
      pts.push_back(vec_cast<T>(Vec2d{1, -2} + gauss(rng, sx) * d + gauss(rng, sy) * perp(d)));
    const LineFit<T, 2> f = fit_line(pts);
    ASSERT_EQ(f.status, Status::ok);
    Vec2d mean{};
    for (const auto& p : pts) mean += vec_cast<double>(p);
    mean = mean / double(pts.size());
    auto cost = [&](const Vec2d& dir) {
      double s = 0;
      for (const auto& p : pts) s += sqr(perp_dot(dir, vec_cast<double>(p) - mean));
      return s;
    };
    // Coarse grid of 2000 angles, then 2000 over the two cells around the best one (the cost
    // A + B cos(2 t - phi) is unimodal on [0, pi), so the optimum lies there): resolution
    // pi / 2000 * 2 / 2000 = pi / 2e6.
    double best = 1e300, best_t = 0;
    for (int k = 0; k < 2000; ++k) {
      const double t = pi_v<double> * k / 2000;
      const double c = cost(Vec2d{std::cos(t), std::sin(t)});
      if (c < best) best = c, best_t = t;
    }
    const double t0 = best_t - pi_v<double> / 2000;
    for (int k = 0; k <= 2000; ++k) {
      const double t = t0 + 2 * pi_v<double> / 2000 * k / 2000;
      const double c = cost(Vec2d{std::cos(t), std::sin(t)});
      if (c < best) best = c, best_t = t;
    }
    const double steps = 2e6;
    const double ours = cost(vec_cast<double>(f.line.direction));
    EXPECT_LE(ours, best * (1 + 64 * double(eps_v<T>)) + 1e-300);
    EXPECT_NEAR(double(f.rms), std::sqrt(ours / double(pts.size())), 64 * double(eps_v<T>) * 3);
    EXPECT_LT(
        sin_angle(vec_cast<double>(f.line.direction), Vec2d{std::cos(best_t), std::sin(best_t)}),
        pi_v<double> / steps + 64 * double(eps_v<T>) * 30);
  }
}

TYPED_TEST(LineFitTest, RigidMotionInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec3<T>> pts;
    const Vec3d d = rng.unit<double, 3>();
    for (int i = 0; i < 50; ++i)
      pts.push_back(vec_cast<T>(rng.uniform<double>(-4, 4) * d + rng.vec<double, 3>(-0.3, 0.3)));
    const Mat3<double> r = fit_test::random_rotation3(rng);
    const Vec3d t = rng.vec<double, 3>(-10, 10);
    const auto moved = fit_test::moved(pts, r, t);
    const LineFit<T, 3> a = fit_line(pts), b = fit_line(moved);
    ASSERT_EQ(a.status, Status::ok);
    ASSERT_EQ(b.status, Status::ok);
    // Rounding the moved points to T perturbs them by eps(T) * 17; the direction's sensitivity
    // is that over the spread gap (>= 1 here), so 256 eps(T) * 17 bounds the difference.
    const double e = 256 * double(eps_v<T>) * 17;
    EXPECT_LT(sin_angle(vec_cast<double>(b.line.direction), r * vec_cast<double>(a.line.direction)),
              e);
    const Vec3d q = vec_cast<double>(b.line.origin) - (r * vec_cast<double>(a.line.origin) + t);
    EXPECT_LT(length(q), e);
    EXPECT_NEAR(double(a.rms), double(b.rms), e);
  }
}

TYPED_TEST(LineFitTest, VerticalFitAgainstEigen) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  {  // figure 2.9 (the line closest to the points in vertical squared distance), exact data:
     // y = 2 x + 1 at integer x
    std::vector<Vec2<T>> pts;
    for (int i = -3; i <= 5; ++i) pts.push_back({T(i), T(2 * i + 1)});
    const VerticalLineFit<T> f = fit_line_vertical(pts);
    ASSERT_EQ(f.status, Status::ok);
    EXPECT_NEAR(f.slope, T(2), T(16) * eps_v<T>);
    EXPECT_NEAR(f.intercept, T(1), T(64) * eps_v<T>);
    EXPECT_NEAR(f.rms, T(0), T(64) * eps_v<T>);
    // The line's parametrisation: origin on the line, direction (1, slope).
    EXPECT_NEAR(f.line.origin.y, f.slope * f.line.origin.x + f.intercept, T(16) * eps_v<T>);
    EXPECT_EQ(f.line.direction.x, T(1));
  }
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 200;
    const double a = rng.uniform<double>(-3, 3), b = rng.uniform<double>(-5, 5), sigma = 0.05;
    std::vector<Vec2<T>> pts;
    Eigen::MatrixXd am(n, 2);
    Eigen::VectorXd bm(n);
    double sx = 0, sxx = 0;
    for (int i = 0; i < n; ++i) {
      const double x = rng.uniform<double>(-2, 4);
      pts.push_back(vec_cast<T>(Vec2d{x, a * x + b + gauss(rng, sigma)}));
      am(i, 0) = double(pts.back().x);
      am(i, 1) = 1;
      bm(i) = double(pts.back().y);
      sx += x;
      sxx += x * x;
    }
    const VerticalLineFit<T> f = fit_line_vertical(pts);
    ASSERT_EQ(f.status, Status::ok);
    // Oracle: Eigen's column-pivoting QR on the same (rounded) data, in double. Agreement to
    // cond(A) * eps of the compute type (cond < 100 here) plus rounding the result to T.
    const Eigen::VectorXd sol = am.colPivHouseholderQr().solve(bm);
    EXPECT_NEAR(double(f.slope), sol(0), 4 * double(eps_v<T>) * 3 + 1e-12);
    EXPECT_NEAR(double(f.intercept), sol(1), 4 * double(eps_v<T>) * 15 + 1e-12);
    EXPECT_NEAR(double(f.rms), (am * sol - bm).norm() / std::sqrt(double(n)),
                16 * double(eps_v<T>) * 20 + 1e-12);
    // Noise bound: var(slope) = sigma^2 / (n var(x)); var(intercept) = sigma^2 (1/n +
    // mean^2 / (n var(x))). Six standard deviations (rounding to float adds ~1e-6, negligible).
    const double mx = sx / n, vx = sxx / n - mx * mx;
    EXPECT_NEAR(double(f.slope), a, 6 * sigma / std::sqrt(n * vx));
    EXPECT_NEAR(double(f.intercept), b, 6 * sigma * std::sqrt(1.0 / n + mx * mx / (n * vx)));
  }
}

TYPED_TEST(LineFitTest, DegenerateInput) {
  using T = TypeParam;
  const std::vector<Vec2<T>> none;
  EXPECT_EQ(fit_line(none).status, Status::empty_input);
  EXPECT_EQ(fit_line_vertical(none).status, Status::empty_input);
  const std::vector<Vec2<T>> one{{T(1), T(2)}};
  EXPECT_EQ(fit_line(one).status, Status::degenerate_input);
  EXPECT_EQ(fit_line_vertical(one).status, Status::degenerate_input);
  // Coincident points (at a coordinate whose rounding would hide a tiny spread).
  const std::vector<Vec3<T>> same(7, Vec3<T>{T(1000.5), T(-3), T(0.1)});
  const LineFit<T, 3> s = fit_line(same);
  EXPECT_EQ(s.status, Status::degenerate_input);
  EXPECT_TRUE(std::isnan(s.rms));
  EXPECT_EQ(s.line.direction, (Vec3<T>{}));
  // Vertical fit of points with equal x: a vertical line has no slope.
  const std::vector<Vec2<T>> vert{{T(3), T(0)}, {T(3), T(1)}, {T(3), T(5)}};
  const VerticalLineFit<T> v = fit_line_vertical(vert);
  EXPECT_EQ(v.status, Status::degenerate_input);
  EXPECT_TRUE(std::isnan(v.rms));
  EXPECT_EQ(fit_line(vert).status, Status::ok);  // the orthogonal fit handles it
  EXPECT_NEAR(std::abs(fit_line(vert).line.direction.y), T(1), T(4) * eps_v<T>);
  // NaN and Inf.
  std::vector<Vec2<T>> bad{{T(0), T(0)}, {T(1), T(1)}, {nan_v<T>(), T(2)}};
  EXPECT_EQ(fit_line(bad).status, Status::non_finite_input);
  EXPECT_EQ(fit_line_vertical(bad).status, Status::non_finite_input);
  bad[2].x = std::numeric_limits<T>::infinity();
  EXPECT_EQ(fit_line(bad).status, Status::non_finite_input);
  // Two points: the line through them, exactly.
  const std::vector<Vec2<T>> two{{T(0), T(0)}, {T(3), T(4)}};
  const LineFit<T, 2> t2 = fit_line(two);
  ASSERT_EQ(t2.status, Status::ok);
  EXPECT_NEAR(t2.line.direction.x, T(0.6), T(4) * eps_v<T>);
  EXPECT_NEAR(t2.line.direction.y, T(0.8), T(4) * eps_v<T>);
}
