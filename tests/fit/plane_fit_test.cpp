// SPDX-License-Identifier: BSL-1.0
// Tests for fit/plane_fit.hpp (row num.fit): exact and noisy recovery of planes, Eigen's
// JacobiSVD of the centred data as the oracle of the N-D hyperplane fit, Eigen's QR least squares
// for the vertical fit, rigid-motion invariance, and degenerate input (collinear, coincident,
// too few, NaN).
#include <locus/fit/plane_fit.hpp>

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
class PlaneFitTest : public ::testing::Test {};
TYPED_TEST_SUITE(PlaneFitTest, locus_test::RealTypes);

TYPED_TEST(PlaneFitTest, ExactRecovery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 50; ++trial) {
    const Mat3<double> r = fit_test::random_rotation3(rng);
    const Vec3d o = rng.vec<double, 3>(-5, 5), n = col(r, 2);
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 30; ++i)
      pts.push_back(vec_cast<T>(o + rng.uniform<double>(-3, 3) * col(r, 0) +
                                rng.uniform<double>(-3, 3) * col(r, 1)));
    const PlaneFit<T> f = fit_plane(pts);
    ASSERT_EQ(f.status, Status::ok);
    // Input rounding (eps(T) * |p| <= 14 eps(T)) is the only error; its effect on the normal is
    // that over the in-plane spread (~1.7).
    const double e = 64 * double(eps_v<T>) * 14;
    EXPECT_LT(sin_angle(vec_cast<double>(f.plane.normal), n), e);
    EXPECT_NEAR(length(f.plane.normal), T(1), T(4) * eps_v<T>);
    EXPECT_NEAR(double(signed_value(f.plane, vec_cast<T>(o))), 0.0, e);
    EXPECT_LT(double(f.rms), e);
  }
}

// Noisy samples: n points uniform on a 2L x 2L square (in-plane variance L^2/3 per axis) with
// N(0, sigma^2) noise along the normal. Each tilt component of the fitted normal has standard
// deviation sigma / (sqrt(n) L / sqrt(3)) and the offset at the centroid sigma / sqrt(n); six
// standard deviations (times sqrt 2 for the two tilt components) bound them.
TYPED_TEST(PlaneFitTest, NoisyRecovery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int n = 600;
  const double sigma = 0.01, L = 4;
  for (int trial = 0; trial < 10; ++trial) {
    const Mat3<double> r = fit_test::random_rotation3(rng);
    const Vec3d o = rng.vec<double, 3>(-5, 5), nrm = col(r, 2);
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < n; ++i)
      pts.push_back(vec_cast<T>(o + rng.uniform<double>(-L, L) * col(r, 0) +
                                rng.uniform<double>(-L, L) * col(r, 1) + gauss(rng, sigma) * nrm));
    const PlaneFit<T> f = fit_plane(pts);
    ASSERT_EQ(f.status, Status::ok);
    const double tilt_sd = sigma / (std::sqrt(double(n)) * L / std::sqrt(3.0));
    EXPECT_LT(sin_angle(vec_cast<double>(f.plane.normal), nrm), 6 * std::sqrt(2.0) * tilt_sd);
    // Offset of the true origin o (within L sqrt 2 of the centroid) from the fitted plane.
    EXPECT_LT(std::abs(double(signed_value(f.plane, vec_cast<T>(o)))),
              6 * sigma / std::sqrt(double(n)) + 6 * std::sqrt(2.0) * tilt_sd * L * std::sqrt(2.0));
    EXPECT_NEAR(double(f.rms), sigma, 6 * sigma / std::sqrt(2.0 * n) + 3 * sigma / n);
  }
}

// Oracle: the normal of the orthogonal least-squares hyperplane is the right singular vector of
// the centred data matrix for the smallest singular value (Eigen's JacobiSVD, double). Clouds
// with distinct spreads keep the singular vector well conditioned (gap >= 0.5 relative).
TYPED_TEST(PlaneFitTest, HyperplaneAgainstEigenSvd) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  constexpr int N = 5;
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 80;
    Eigen::MatrixXd rot = Eigen::MatrixXd::Zero(N, N);
    for (int r = 0; r < N; ++r)
      for (int c = 0; c < N; ++c) rot(r, c) = rng.uniform<double>(-1, 1);
    rot = Eigen::HouseholderQR<Eigen::MatrixXd>(rot).householderQ();
    std::vector<Vec<T, N>> pts;
    Eigen::MatrixXd data(n, N);
    for (int i = 0; i < n; ++i) {
      Eigen::VectorXd z(N);
      for (int k = 0; k < N; ++k) z(k) = gauss(rng, k == 0 ? 0.05 : 1.0 + k);
      const Eigen::VectorXd x = rot * z + Eigen::VectorXd::Constant(N, 2.0);
      Vec<T, N> p{};
      for (int k = 0; k < N; ++k) p[k] = T(x(k));
      pts.push_back(p);
      for (int k = 0; k < N; ++k) data(i, k) = double(p[k]);
    }
    const HyperplaneFit<T, N> f = fit_hyperplane(pts);
    ASSERT_EQ(f.status, Status::ok);
    const Eigen::RowVectorXd mean = data.colwise().mean();
    const Eigen::MatrixXd centred = data.rowwise() - mean;
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeThinV);
    const Eigen::VectorXd ne = svd.matrixV().col(N - 1);
    Vec<double, N> nd{}, ours = vec_cast<double>(f.normal);
    for (int k = 0; k < N; ++k) nd[k] = ne(k);
    // Eigenvector error of the covariance route: eps(C) * lambda_max / gap (~1e-14) plus
    // rounding the normal to T.
    EXPECT_LT(sin_angle(ours, nd), 8 * double(eps_v<T>) + 1e-12) << trial;
    const double rms_e = svd.singularValues()(N - 1) / std::sqrt(double(n));
    EXPECT_NEAR(double(f.rms), rms_e, 8 * double(eps_v<T>) * 5 + 1e-12);
    double c = 0;
    for (int k = 0; k < N; ++k) c += nd[k] * mean(k);
    EXPECT_NEAR(std::abs(double(f.constant)), std::abs(c), 16 * double(eps_v<T>) * 10 + 1e-12);
  }
}

TYPED_TEST(PlaneFitTest, RigidMotionInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 60; ++i)
      pts.push_back(vec_cast<T>(
          Vec3d{rng.uniform<double>(-4, 4), rng.uniform<double>(-2, 2), gauss(rng, 0.1)}));
    const Mat3<double> r = fit_test::random_rotation3(rng);
    const Vec3d t = rng.vec<double, 3>(-10, 10);
    const PlaneFit<T> a = fit_plane(pts), b = fit_plane(fit_test::moved(pts, r, t));
    ASSERT_EQ(a.status, Status::ok);
    ASSERT_EQ(b.status, Status::ok);
    // Rounding the moved points (|p| <= 22) to T; the normal's sensitivity is 1 / (spread gap
    // ~1): 256 eps(T) * 22 bounds the differences.
    const double e = 256 * double(eps_v<T>) * 22;
    const Vec3d na = r * vec_cast<double>(a.plane.normal);
    EXPECT_LT(sin_angle(vec_cast<double>(b.plane.normal), na), e);
    const double sgn = dot(na, vec_cast<double>(b.plane.normal)) > 0 ? 1 : -1;
    EXPECT_NEAR(double(b.plane.constant), sgn * (double(a.plane.constant) + dot(na, t)), e);
    EXPECT_NEAR(double(a.rms), double(b.rms), e);
  }
}

TYPED_TEST(PlaneFitTest, VerticalFitAgainstEigen) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  {  // exact: z = 2x - 3y + 0.5 at small integers
    std::vector<Vec3<T>> pts;
    for (int i = -2; i <= 2; ++i)
      for (int j = -2; j <= 3; ++j) pts.push_back({T(i), T(j), T(2 * i - 3 * j) + T(0.5)});
    const VerticalHyperplaneFit<T, 3> f = fit_hyperplane_vertical(pts);
    ASSERT_EQ(f.status, Status::ok);
    EXPECT_NEAR(f.coefficients.x, T(2), T(16) * eps_v<T>);
    EXPECT_NEAR(f.coefficients.y, T(-3), T(16) * eps_v<T>);
    EXPECT_NEAR(f.constant, T(0.5), T(64) * eps_v<T>);
    EXPECT_NEAR(f.rms, T(0), T(64) * eps_v<T>);
  }
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 150;
    const Vec3d coef = rng.vec<double, 3>(-2, 2);
    std::vector<Vec3<T>> pts;
    Eigen::MatrixXd am(n, 3);
    Eigen::VectorXd bm(n);
    for (int i = 0; i < n; ++i) {
      const double x = rng.uniform<double>(-3, 3), y = rng.uniform<double>(-1, 5);
      pts.push_back(vec_cast<T>(Vec3d{x, y, coef.x * x + coef.y * y + coef.z + gauss(rng, 0.1)}));
      am(i, 0) = double(pts.back().x);
      am(i, 1) = double(pts.back().y);
      am(i, 2) = 1;
      bm(i) = double(pts.back().z);
    }
    const VerticalHyperplaneFit<T, 3> f = fit_hyperplane_vertical(pts);
    ASSERT_EQ(f.status, Status::ok);
    // Oracle: Eigen's column-pivoting QR in double; cond(A) < 20 here, so the solutions agree to
    // ~1e-14 plus rounding to T (relative 4 eps(T) of coefficients up to ~10).
    const Eigen::VectorXd sol = am.colPivHouseholderQr().solve(bm);
    EXPECT_NEAR(double(f.coefficients.x), sol(0), 4 * double(eps_v<T>) * 10 + 1e-12);
    EXPECT_NEAR(double(f.coefficients.y), sol(1), 4 * double(eps_v<T>) * 10 + 1e-12);
    EXPECT_NEAR(double(f.constant), sol(2), 4 * double(eps_v<T>) * 30 + 1e-12);
    EXPECT_NEAR(double(f.rms), (am * sol - bm).norm() / std::sqrt(double(n)),
                16 * double(eps_v<T>) * 30 + 1e-12);
  }
}

TYPED_TEST(PlaneFitTest, DegenerateInput) {
  using T = TypeParam;
  const std::vector<Vec3<T>> none;
  EXPECT_EQ(fit_plane(none).status, Status::empty_input);
  const std::vector<Vec3<T>> two{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}};
  EXPECT_EQ(fit_plane(two).status, Status::degenerate_input);
  // Collinear points (exact, small integers) and collinear points with rounded coordinates.
  std::vector<Vec3<T>> line;
  for (int i = 0; i < 10; ++i) line.push_back({T(i), T(2 * i), T(-i)});
  const PlaneFit<T> l = fit_plane(line);
  EXPECT_EQ(l.status, Status::degenerate_input);
  EXPECT_TRUE(std::isnan(l.rms));
  EXPECT_EQ(l.plane.normal, (Vec3<T>{}));
  std::vector<Vec3<T>> rounded;
  const Vec3d d = normalize(Vec3d{0.3, -0.7, 0.2});
  for (int i = 0; i < 10; ++i)
    rounded.push_back(vec_cast<T>(Vec3d{100, 200, 300} + (0.37 * i) * d));
  EXPECT_EQ(fit_plane(rounded).status, Status::degenerate_input);
  const std::vector<Vec3<T>> same(5, Vec3<T>{T(2), T(3), T(4)});
  EXPECT_EQ(fit_plane(same).status, Status::degenerate_input);
  std::vector<Vec3<T>> bad{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), nan_v<T>()}};
  EXPECT_EQ(fit_plane(bad).status, Status::non_finite_input);
  EXPECT_EQ(fit_hyperplane_vertical(bad).status, Status::non_finite_input);
  // Vertical fit of a vertical plane (x + y = 1 for all points): no height function.
  std::vector<Vec3<T>> vert;
  for (int i = 0; i < 6; ++i) vert.push_back({T(i), T(1 - i), T(i * i)});
  const VerticalHyperplaneFit<T, 3> v = fit_hyperplane_vertical(vert);
  EXPECT_EQ(v.status, Status::degenerate_input);
  EXPECT_TRUE(std::isnan(v.rms));
  EXPECT_EQ(fit_plane(vert).status, Status::ok);  // the orthogonal fit handles it
  // A hyperplane in 4D through 3 points: too few.
  const std::vector<Vec4<T>> three(3, Vec4<T>{1, 2, 3, 4});
  EXPECT_EQ(fit_hyperplane(three).status, Status::degenerate_input);
}
