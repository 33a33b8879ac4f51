// SPDX-License-Identifier: BSL-1.0
// Tests for fit/gaussian_fit.hpp (row num.fit): mean, covariance and box against Eigen on the
// same points, recovery of a known distribution from samples within sampling-error bounds, the
// exact box of a box's corners, containment and tightness of the GaussianExtent::points box,
// rigid-motion covariance, and bad input.
#include <locus/fit/gaussian_fit.hpp>

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
class GaussianFitTest : public ::testing::Test {};
TYPED_TEST_SUITE(GaussianFitTest, locus_test::RealTypes);

TYPED_TEST(GaussianFitTest, AgainstEigenOnSamePoints) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 200;
    std::vector<Vec3<T>> pts;
    Eigen::MatrixXd data(n, 3);
    const Mat3<double> r = fit_test::random_rotation3(rng);
    for (int i = 0; i < n; ++i) {
      const Vec3d z{gauss(rng, 3), gauss(rng, 1), gauss(rng, 0.2)};
      pts.push_back(vec_cast<T>(r * z + Vec3d{5, -1, 2}));
      for (int k = 0; k < 3; ++k) data(i, k) = double(pts.back()[k]);
    }
    const GaussianFit<T, 3> f = fit_gaussian(pts);
    ASSERT_EQ(f.status, Status::ok);
    const Eigen::RowVectorXd mean = data.colwise().mean();
    const Eigen::MatrixXd centred = data.rowwise() - mean;
    const Eigen::MatrixXd cov = centred.transpose() * centred / double(n);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(cov);
    // Both compute in double from the same rounded points: agreement to a few eps(double) of
    // the data scale (~10), then rounding to T.
    const double e = 8 * double(eps_v<T>) * 10 + 1e-12;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(double(f.mean[k]), mean(k), e);
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(double(f.covariance(k, j)), cov(k, j), e * 10);
      EXPECT_NEAR(double(f.box.extent[k]), std::sqrt(es.eigenvalues()(k)), e);
      // Eigenvalue gaps here are >= 0.9 (variances 9, 1, 0.04 in expectation).
      Vec3d ve{es.eigenvectors()(0, k), es.eigenvectors()(1, k), es.eigenvectors()(2, k)};
      EXPECT_LT(sin_angle(vec_cast<double>(f.box.axis[k]), ve), e);
    }
    EXPECT_NEAR(double(f.rms), std::sqrt(cov.trace()), e);
    EXPECT_EQ(f.box.center, f.mean);
  }
}

// Sampling bounds: with n samples of N(mu, Sigma), mean_k has standard deviation
// sqrt(Sigma_kk / n) and each variance estimate along a principal axis sqrt(2 / n) lambda_i, so
// sqrt(lambda_i) (the extent) has sd sqrt(lambda_i / (2 n)); the principal axes tilt by about
// sqrt(lambda_i lambda_j / n) / (lambda_i - lambda_j). Six standard deviations each.
TYPED_TEST(GaussianFitTest, RecoversDistribution) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int n = 20000;
  const double sd[2] = {0.5, 2.0};
  const double a = 0.6;
  const Vec2d mu{3, -4}, ax0{std::cos(a), std::sin(a)}, ax1 = perp(ax0);
  std::vector<Vec2<T>> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back(vec_cast<T>(mu + gauss(rng, sd[0]) * ax0 + gauss(rng, sd[1]) * ax1));
  const GaussianFit<T, 2> f = fit_gaussian(pts);
  ASSERT_EQ(f.status, Status::ok);
  EXPECT_TRUE(locus_test::vec_near(vec_cast<double>(f.mean), mu, 6 * sd[1] / std::sqrt(double(n))));
  for (int i = 0; i < 2; ++i)
    EXPECT_NEAR(double(f.box.extent[i]), sd[i], 6 * sd[i] / std::sqrt(2.0 * n));
  const double tilt = sd[0] * sd[1] / std::sqrt(double(n)) / (sd[1] * sd[1] - sd[0] * sd[0]);
  EXPECT_LT(sin_angle(vec_cast<double>(f.box.axis[0]), ax0), 6 * tilt);
  EXPECT_LT(sin_angle(vec_cast<double>(f.box.axis[1]), ax1), 6 * tilt);
}

TYPED_TEST(GaussianFitTest, BoxCornersAndPointsExtent) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // The 8 corners of a box with distinct extents: mean = center, covariance = sum e_i^2 a_i a_i^T
  // (each coordinate along an axis is +-e_i), so the std_dev box is the box itself.
  const Mat3<double> r = fit_test::random_rotation3(rng);
  OrientedBox<T, 3> box{};
  box.center = Vec3<T>{T(1), T(2), T(3)};
  const double ext[3] = {0.5, 1.5, 3.0};
  for (int i = 0; i < 3; ++i) {
    box.axis[i] = vec_cast<T>(col(r, i));
    box.extent[i] = T(ext[i]);
  }
  const auto cs = corners(box);
  const std::vector<Vec3<T>> pts(cs.begin(), cs.end());
  const double e = 64 * double(eps_v<T>) * 5;
  for (GaussianExtent ge : {GaussianExtent::std_dev, GaussianExtent::points}) {
    const GaussianFit<T, 3> f = fit_gaussian(pts, ge);
    ASSERT_EQ(f.status, Status::ok);
    EXPECT_TRUE(
        locus_test::vec_near(vec_cast<double>(f.box.center), vec_cast<double>(box.center), e));
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(double(f.box.extent[i]), ext[i], e);
      EXPECT_LT(sin_angle(vec_cast<double>(f.box.axis[i]), col(r, i)), e);
    }
  }
  // Skewed random points: the points box contains every point and touches each face.
  std::vector<Vec2<T>> sk;
  for (int i = 0; i < 300; ++i) {
    const double u = rng.uniform<double>(0, 1);
    sk.push_back(vec_cast<T>(Vec2d{u * u * 4, gauss(rng, 0.3) + u}));
  }
  const GaussianFit<T, 2> g = fit_gaussian(sk, GaussianExtent::points);
  ASSERT_EQ(g.status, Status::ok);
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& p : sk)
    for (int i = 0; i < 2; ++i) {
      const double s = dot(vec_cast<double>(p) - vec_cast<double>(g.box.center),
                           vec_cast<double>(g.box.axis[i])) /
                       double(g.box.extent[i]);
      lo[i] = std::min(lo[i], s);
      hi[i] = std::max(hi[i], s);
    }
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(lo[i], -1.0, 64 * double(eps_v<T>) * 10);
    EXPECT_NEAR(hi[i], 1.0, 64 * double(eps_v<T>) * 10);
  }
}

TYPED_TEST(GaussianFitTest, RigidMotion) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 100; ++i)
    pts.push_back(vec_cast<T>(Vec3d{gauss(rng, 2), gauss(rng, 1), gauss(rng, 0.3)}));
  const Mat3<double> r = fit_test::random_rotation3(rng);
  const Vec3d t = rng.vec<double, 3>(-10, 10);
  const GaussianFit<T, 3> a = fit_gaussian(pts), b = fit_gaussian(fit_test::moved(pts, r, t));
  ASSERT_EQ(a.status, Status::ok);
  ASSERT_EQ(b.status, Status::ok);
  // Covariance moves to R S R^T and the mean to R m + t; rounding the moved points (|p| < 25).
  Mat3<double> sa{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sa(i, j) = double(a.covariance(i, j));
  const Mat3<double> expect = r * sa * transpose(r);
  const double e = 64 * double(eps_v<T>) * 25;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(double(b.covariance(i, j)), expect(i, j), e * 10);
  EXPECT_TRUE(locus_test::vec_near(vec_cast<double>(b.mean), r * vec_cast<double>(a.mean) + t, e));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(double(b.box.extent[i]), double(a.box.extent[i]), e * 10);
}

TYPED_TEST(GaussianFitTest, BadInput) {
  using T = TypeParam;
  const std::vector<Vec3<T>> none;
  EXPECT_EQ(fit_gaussian(none).status, Status::empty_input);
  const std::vector<Vec3<T>> bad{{T(0), T(0), T(0)}, {nan_v<T>(), T(1), T(0)}};
  EXPECT_EQ(fit_gaussian(bad).status, Status::non_finite_input);
  // One point: a valid, flat box at the point.
  const std::vector<Vec3<T>> one{{T(1), T(2), T(3)}};
  const GaussianFit<T, 3> f1 = fit_gaussian(one);
  EXPECT_EQ(f1.status, Status::ok);
  EXPECT_EQ(f1.box.center, one[0]);
  EXPECT_EQ(f1.box.extent, (Vec3<T>{}));
  EXPECT_EQ(f1.rms, T(0));
  // Collinear points: lower-dimensional data, two zero extents, the third along the line.
  std::vector<Vec2<T>> line;
  for (int i = 0; i < 5; ++i) line.push_back({T(i), T(2 * i)});
  const GaussianFit<T, 2> fl = fit_gaussian(line, GaussianExtent::points);
  EXPECT_EQ(fl.status, Status::ok);
  EXPECT_NEAR(fl.box.extent[0], T(0), T(16) * eps_v<T>);
  EXPECT_NEAR(fl.box.extent[1], T(2) * std::sqrt(T(5)), T(16) * eps_v<T> * T(5));
}
