// SPDX-License-Identifier: BSL-1.0
// Tests for fit/sphere_fit.hpp (row num.fit): exact recovery (3D and a 4D hypersphere), noisy
// recovery within noise-derived bounds, first-order optimality of the geometric fit and an
// independent minimisation (Powell, numeric/minimize.hpp) as its oracle, rigid-motion invariance,
// and degenerate input (coplanar, too few, NaN).
#include <locus/fit/sphere_fit.hpp>
#include <locus/numeric/minimize.hpp>

#include "fit/fit_test_util.hpp"

#include <cmath>
#include <vector>

using namespace locus;
using fit_test::gauss;
using fit_test::nan_v;
using locus_test::Rng;

template <class T>
class SphereFitTest : public ::testing::Test {};
TYPED_TEST_SUITE(SphereFitTest, locus_test::RealTypes);

namespace {

template <class T, int N>
std::vector<Vec<T, N>> sphere_points(Rng& rng, const Vec<double, N>& c, double r, int n,
                                     double sigma) {
  std::vector<Vec<T, N>> pts;
  for (int i = 0; i < n; ++i) {
    const double rr = r + (sigma > 0 ? gauss(rng, sigma) : 0.0);
    pts.push_back(vec_cast<T>(c + rr * rng.unit<double, N>()));
  }
  return pts;
}

template <class T>
double geometric_cost(const std::vector<Vec3<T>>& pts, const Vec3d& c, double r) {
  double s = 0;
  for (const auto& p : pts) s += sqr(length(vec_cast<double>(p) - c) - r);
  return s;
}

}  // namespace

TYPED_TEST(SphereFitTest, ExactRecovery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const Vec3d c = rng.vec<double, 3>(-10, 10);
    const double r = rng.uniform<double>(0.5, 5);
    const auto pts = sphere_points<T, 3>(rng, c, r, 4 + trial, 0.0);
    // Input rounding (eps(T) |p| <= 23 eps(T)) amplified by the conditioning of a few random
    // points (< 100 for these samples).
    const double e = 64 * double(eps_v<T>) * 23 * 100;
    for (const SphereFit<T, 3>& f : {fit_sphere_algebraic(pts), fit_sphere(pts)}) {
      ASSERT_EQ(f.status, Status::ok) << trial;
      EXPECT_TRUE(locus_test::vec_near(vec_cast<double>(f.sphere.center), c, e)) << trial;
      EXPECT_NEAR(double(f.sphere.radius), r, e) << trial;
    }
  }
  // A hypersphere in 4D.
  const Vec4d c4{1, -2, 3, 0.5};
  const auto p4 = sphere_points<T, 4>(rng, c4, 2.5, 40, 0.0);
  const SphereFit<T, 4> f4 = fit_sphere(p4);
  ASSERT_EQ(f4.status, Status::ok);
  EXPECT_TRUE(
      locus_test::vec_near(vec_cast<double>(f4.sphere.center), c4, 256 * double(eps_v<T>) * 6));
  EXPECT_NEAR(double(f4.sphere.radius), 2.5, 256 * double(eps_v<T>) * 6);
}

// Noisy sphere: n points uniform on the sphere with N(0, sigma^2) radial noise. The geometric
// fit's center has per-coordinate standard deviation sigma sqrt(3 / n) (information n/3 per
// coordinate: E[u_x^2] = 1/3) and the radius sigma / sqrt(n); six standard deviations bound them.
TYPED_TEST(SphereFitTest, NoisyRecovery) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int n = 500;
  const double sigma = 0.02;
  for (int trial = 0; trial < 8; ++trial) {
    const Vec3d c = rng.vec<double, 3>(-10, 10);
    const double r = rng.uniform<double>(2, 6);
    const auto pts = sphere_points<T, 3>(rng, c, r, n, sigma);
    const SphereFit<T, 3> f = fit_sphere(pts);
    ASSERT_EQ(f.status, Status::ok);
    EXPECT_TRUE(
        locus_test::vec_near(vec_cast<double>(f.sphere.center), c, 6 * sigma * std::sqrt(3.0 / n)));
    EXPECT_NEAR(double(f.sphere.radius), r, 6 * sigma / std::sqrt(double(n)));
    EXPECT_NEAR(double(f.rms), sigma, 6 * sigma / std::sqrt(2.0 * n) + 4 * sigma / n);
  }
}

// First-order conditions and Powell on the reduced cost (r = mean |p_i - c|) from the algebraic
// start, on caps of the sphere (polar angle <= 60 degrees), where the algebraic fit is biased.
TYPED_TEST(SphereFitTest, GeometricOptimalityAndPowellOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 8; ++trial) {
    const Vec3d c = rng.vec<double, 3>(-3, 3);
    const double r = rng.uniform<double>(1, 3);
    std::vector<Vec3<T>> pts;
    while (pts.size() < 150) {
      const Vec3d u = rng.unit<double, 3>();
      if (u.z < 0.5) continue;
      pts.push_back(vec_cast<T>(c + (r + gauss(rng, 0.03 * r)) * u));
    }
    const SphereFit<T, 3> f = fit_sphere(pts);
    ASSERT_EQ(f.status, Status::ok) << trial;
    const Vec3d fc = vec_cast<double>(f.sphere.center);
    const double fr = double(f.sphere.radius);
    double se = 0;
    Vec3d seu{};
    for (const auto& p : pts) {
      const Vec3d d = vec_cast<double>(p) - fc;
      const double e = length(d) - fr;
      se += e;
      seu += e * (d / length(d));
    }
    // Rounding the result to T (eps(T) * 8) changes the gradient by up to n times that, times
    // the conditioning of a cap (< 10).
    const double g = 150 * 64 * double(eps_v<T>) * 8 * 10;
    EXPECT_LT(std::abs(se), g) << trial;
    EXPECT_LT(length(seu), g) << trial;
    auto reduced = [&](const Vec3d& cc) {
      double m = 0;
      for (const auto& p : pts) m += length(vec_cast<double>(p) - cc);
      return geometric_cost(pts, cc, m / double(pts.size()));
    };
    const SphereFit<T, 3> a = fit_sphere_algebraic(pts);
    PowellOptions<double> po;
    po.initial_step = 0.1 * r;
    const MinimumN<double, 3> pm = minimize_powell(reduced, vec_cast<double>(a.sphere.center), po);
    ASSERT_EQ(pm.status, Status::ok);
    const double ours = geometric_cost(pts, fc, fr);
    EXPECT_LE(ours, pm.value * (1 + 1e-9) + 1e3 * double(eps_v<T>) * ours) << trial;
  }
}

TYPED_TEST(SphereFitTest, RigidMotionInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 10; ++trial) {
    const auto pts = sphere_points<T, 3>(rng, rng.vec<double, 3>(-2, 2), 2, 60, 0.05);
    const Mat3<double> rot = fit_test::random_rotation3(rng);
    const Vec3d t = rng.vec<double, 3>(-10, 10);
    const SphereFit<T, 3> a = fit_sphere(pts), b = fit_sphere(fit_test::moved(pts, rot, t));
    ASSERT_EQ(a.status, Status::ok);
    ASSERT_EQ(b.status, Status::ok);
    // Rounding the moved points (|p| <= 24) to T, amplified by < 10.
    const double e = 256 * double(eps_v<T>) * 24 * 10;
    EXPECT_TRUE(locus_test::vec_near(vec_cast<double>(b.sphere.center),
                                     rot * vec_cast<double>(a.sphere.center) + t, e));
    EXPECT_NEAR(double(b.sphere.radius), double(a.sphere.radius), e);
  }
}

TYPED_TEST(SphereFitTest, DegenerateInput) {
  using T = TypeParam;
  const std::vector<Vec3<T>> none;
  EXPECT_EQ(fit_sphere(none).status, Status::empty_input);
  const std::vector<Vec3<T>> three{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}};
  EXPECT_EQ(fit_sphere(three).status, Status::degenerate_input);
  // Coplanar points (on a circle in z = 2): no unique sphere.
  std::vector<Vec3<T>> flat;
  for (int i = 0; i < 12; ++i) {
    const T a = T(i) * T(0.5);
    flat.push_back({std::cos(a), std::sin(a), T(2)});
  }
  for (const SphereFit<T, 3>& f : {fit_sphere(flat), fit_sphere_algebraic(flat)}) {
    EXPECT_EQ(f.status, Status::degenerate_input);
    EXPECT_TRUE(std::isnan(f.rms));
    EXPECT_EQ(f.sphere.radius, T(0));
  }
  std::vector<Vec3<T>> bad = three;
  bad.push_back({T(0), std::numeric_limits<T>::infinity(), T(0)});
  bad.push_back({T(-1), T(0), T(0)});
  EXPECT_EQ(fit_sphere(bad).status, Status::non_finite_input);
  // The regular tetrahedron's vertices: the circumsphere.
  const std::vector<Vec3<T>> tet{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  const SphereFit<T, 3> t4 = fit_sphere(tet);
  ASSERT_EQ(t4.status, Status::ok);
  EXPECT_TRUE(locus_test::vec_near(t4.sphere.center, Vec3<T>{}, T(64) * eps_v<T>));
  EXPECT_NEAR(t4.sphere.radius, std::sqrt(T(3)), T(64) * eps_v<T>);
}
