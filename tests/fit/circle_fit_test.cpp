// SPDX-License-Identifier: BSL-1.0
// Tests for fit/circle_fit.hpp (row num.fit): exact and noisy recovery (algebraic and geometric
// fits), the geometric fit checked by its first-order optimality conditions and against an
// independent minimisation (Powell's method of numeric/minimize.hpp on the reduced geometric
// cost), short arcs, rigid-motion invariance, the iteration budget, and degenerate input.
#include <locus/fit/circle_fit.hpp>
#include <locus/numeric/minimize.hpp>

#include "fit/fit_test_util.hpp"

#include <cmath>
#include <vector>

using namespace locus;
using fit_test::gauss;
using fit_test::nan_v;
using locus_test::Rng;

template <class T>
class CircleFitTest : public ::testing::Test {};
TYPED_TEST_SUITE(CircleFitTest, locus_test::RealTypes);

namespace {

template <class T>
std::vector<Vec2<T>> circle_points(Rng& rng, const Vec2d& c, double r, int n, double sigma,
                                   double arc = 2 * pi_v<double>) {
  std::vector<Vec2<T>> pts;
  for (int i = 0; i < n; ++i) {
    const double a = rng.uniform<double>(0, arc);
    const double rr = r + (sigma > 0 ? gauss(rng, sigma) : 0.0);
    pts.push_back(vec_cast<T>(c + rr * Vec2d{std::cos(a), std::sin(a)}));
  }
  return pts;
}

template <class T>
double geometric_cost(const std::vector<Vec2<T>>& pts, const Vec2d& c, double r) {
  double s = 0;
  for (const auto& p : pts) s += sqr(length(vec_cast<double>(p) - c) - r);
  return s;
}

}  // namespace

TYPED_TEST(CircleFitTest, ExactRecovery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const Vec2d c = rng.vec<double, 2>(-10, 10);
    const double r = rng.uniform<double>(0.5, 5);
    const auto pts = circle_points<T>(rng, c, r, 3 + trial, 0.0);
    // Input rounding (eps(T) |p| <= 15 eps(T)) is the only error, amplified by at most ~10 by
    // the conditioning of three or more points on a random arc.
    const double e = 256 * double(eps_v<T>) * 15;
    for (const CircleFit<T>& f : {fit_circle_algebraic(pts), fit_circle(pts)}) {
      ASSERT_TRUE(f.status == Status::ok) << to_string(f.status) << " " << trial;
      EXPECT_NEAR(double(f.circle.center.x), c.x, e * 10) << trial;
      EXPECT_NEAR(double(f.circle.center.y), c.y, e * 10) << trial;
      EXPECT_NEAR(double(f.circle.radius), r, e * 10) << trial;
      EXPECT_LT(double(f.rms), e * 10);
    }
  }
}

// Noisy full circle: n points at uniform angles with N(0, sigma^2) radial noise. The geometric
// fit's center has per-coordinate standard deviation sigma sqrt(2 / n) (information matrix
// n/2 per coordinate) and the radius sigma / sqrt(n); six standard deviations bound them.
TYPED_TEST(CircleFitTest, NoisyRecovery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int n = 400;
  const double sigma = 0.02;
  for (int trial = 0; trial < 10; ++trial) {
    const Vec2d c = rng.vec<double, 2>(-10, 10);
    const double r = rng.uniform<double>(2, 6);
    const auto pts = circle_points<T>(rng, c, r, n, sigma);
    const CircleFit<T> f = fit_circle(pts);
    ASSERT_EQ(f.status, Status::ok);
    EXPECT_NEAR(double(f.circle.center.x), c.x, 6 * sigma * std::sqrt(2.0 / n));
    EXPECT_NEAR(double(f.circle.center.y), c.y, 6 * sigma * std::sqrt(2.0 / n));
    EXPECT_NEAR(double(f.circle.radius), r, 6 * sigma / std::sqrt(double(n)));
    EXPECT_NEAR(double(f.rms), sigma, 6 * sigma / std::sqrt(2.0 * n) + 3 * sigma / n);
    // The algebraic fit is within the same bounds plus its bias O(sigma^2 / r) on a full circle.
    const CircleFit<T> a = fit_circle_algebraic(pts);
    ASSERT_EQ(a.status, Status::ok);
    EXPECT_NEAR(double(a.circle.radius), r,
                6 * sigma / std::sqrt(double(n)) + 2 * sigma * sigma / r);
    EXPECT_LE(double(f.rms), double(a.rms) * (1 + 16 * double(eps_v<T>)));
  }
}

// The geometric fit is a stationary point of sum (|p_i - c| - r)^2: sum e_i = 0 and
// sum e_i u_i = 0 (e_i the residual, u_i the unit vector from c to p_i). An independent
// minimiser - Powell's method on the cost with r eliminated (r = mean |p_i - c|) - must not find
// a lower cost from the same start. Short arcs (60 to 120 degrees) make this a real test: there
// the algebraic start is biased and Levenberg-Marquardt has to work.
TYPED_TEST(CircleFitTest, GeometricOptimalityAndPowellOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 15; ++trial) {
    const Vec2d c = rng.vec<double, 2>(-3, 3);
    const double r = rng.uniform<double>(1, 4);
    const auto pts = circle_points<T>(rng, c, r, 100, 0.05 * r,
                                      rng.uniform<double>(pi_v<double> / 3, 2 * pi_v<double> / 3));
    const CircleFit<T> f = fit_circle(pts);
    ASSERT_EQ(f.status, Status::ok) << trial;
    const Vec2d fc = vec_cast<double>(f.circle.center);
    const double fr = double(f.circle.radius);
    double se = 0;
    Vec2d seu{};
    for (const auto& p : pts) {
      const Vec2d d = vec_cast<double>(p) - fc;
      const double e = length(d) - fr;
      se += e;
      seu += e * (d / length(d));
    }
    // Rounding the result to T moves it by eps(T) * 10; the gradient changes by n times that.
    const double g = 100 * 64 * double(eps_v<T>) * 10;
    EXPECT_LT(std::abs(se), g) << trial;
    EXPECT_LT(length(seu), g) << trial;
    auto reduced = [&](const Vec2d& cc) {
      double m = 0;
      for (const auto& p : pts) m += length(vec_cast<double>(p) - cc);
      return geometric_cost(pts, cc, m / double(pts.size()));
    };
    const CircleFit<T> a = fit_circle_algebraic(pts);
    PowellOptions<double> po;
    po.initial_step = 0.1 * r;
    const MinimumN<double, 2> pm = minimize_powell(reduced, vec_cast<double>(a.circle.center), po);
    ASSERT_EQ(pm.status, Status::ok);
    const double ours = geometric_cost(pts, fc, fr);
    EXPECT_LE(ours, pm.value * (1 + 1e-9) + 1e3 * double(eps_v<T>) * ours) << trial;
    EXPECT_LE(ours,
              geometric_cost(pts, vec_cast<double>(a.circle.center), double(a.circle.radius)) *
                  (1 + 64 * double(eps_v<T>)));
  }
}

TYPED_TEST(CircleFitTest, RigidMotionInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const auto pts = circle_points<T>(rng, rng.vec<double, 2>(-2, 2), rng.uniform<double>(1, 3), 50,
                                      0.05, pi_v<double>);
    const Mat2<double> rot = fit_test::random_rotation2(rng);
    const Vec2d t = rng.vec<double, 2>(-10, 10);
    const CircleFit<T> a = fit_circle(pts), b = fit_circle(fit_test::moved(pts, rot, t));
    ASSERT_EQ(a.status, Status::ok);
    ASSERT_EQ(b.status, Status::ok);
    // Rounding the moved points (|p| <= 20) to T; a half-circle arc amplifies data errors by a
    // small factor (< 10) in the center.
    const double e = 256 * double(eps_v<T>) * 20 * 10;
    const Vec2d ca = rot * vec_cast<double>(a.circle.center) + t;
    EXPECT_NEAR(double(b.circle.center.x), ca.x, e);
    EXPECT_NEAR(double(b.circle.center.y), ca.y, e);
    EXPECT_NEAR(double(b.circle.radius), double(a.circle.radius), e);
  }
}

TYPED_TEST(CircleFitTest, BudgetAndDegenerateInput) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // One Levenberg-Marquardt iteration on a noisy short arc: not converged, best so far.
  const auto arc = circle_points<T>(rng, Vec2d{0, 0}, 2, 40, 0.1, 1.0);
  FitOptions<T> opt;
  opt.max_iterations = 1;
  const CircleFit<T> lim = fit_circle(arc, opt);
  EXPECT_EQ(lim.status, Status::limit_exceeded);
  EXPECT_EQ(lim.iterations, 1);
  EXPECT_TRUE(is_finite(lim.circle.center) && is_finite(lim.circle.radius));
  EXPECT_LE(lim.rms, fit_circle_algebraic(arc).rms);
  // Empty, too few, collinear, coincident, NaN.
  const std::vector<Vec2<T>> none;
  EXPECT_EQ(fit_circle(none).status, Status::empty_input);
  const std::vector<Vec2<T>> two{{T(0), T(0)}, {T(1), T(0)}};
  EXPECT_EQ(fit_circle(two).status, Status::degenerate_input);
  std::vector<Vec2<T>> line;
  for (int i = 0; i < 8; ++i) line.push_back({T(i), T(3 * i - 1)});
  for (const CircleFit<T>& f : {fit_circle(line), fit_circle_algebraic(line)}) {
    EXPECT_EQ(f.status, Status::degenerate_input);
    EXPECT_TRUE(std::isnan(f.rms));
    EXPECT_EQ(f.circle.radius, T(0));
  }
  const std::vector<Vec2<T>> same(4, Vec2<T>{T(1), T(1)});
  EXPECT_EQ(fit_circle(same).status, Status::degenerate_input);
  std::vector<Vec2<T>> bad{{T(0), T(1)}, {T(1), T(0)}, {T(-1), T(0)}, {T(0), nan_v<T>()}};
  EXPECT_EQ(fit_circle(bad).status, Status::non_finite_input);
  // Three points: the circumcircle (3, 4, 5 right triangle: center at the hypotenuse midpoint).
  const std::vector<Vec2<T>> tri{{T(0), T(0)}, {T(4), T(0)}, {T(0), T(3)}};
  const CircleFit<T> t3 = fit_circle(tri);
  ASSERT_EQ(t3.status, Status::ok);
  EXPECT_NEAR(t3.circle.center.x, T(2), T(64) * eps_v<T> * T(4));
  EXPECT_NEAR(t3.circle.center.y, T(1.5), T(64) * eps_v<T> * T(4));
  EXPECT_NEAR(t3.circle.radius, T(2.5), T(64) * eps_v<T> * T(4));
}
