// SPDX-License-Identifier: BSL-1.0
// Scale covariance of every fit (issue 17 item 6; the distance harness's check 8,
// tests/support/scale_covariance.hpp): the points scaled by 2^k about the origin give centres,
// radii, constants and RMS residuals scaled by 2^k, covariances by 2^(2k), and the same unit
// directions, slopes, iteration counts and statuses. The fits scale their input by a power of
// two before forming products, so every one is scale-exact: equality after unscaling. The
// quadratic fits return a unit coefficient vector, which is not a power-of-two image of the
// unscaled one: it is compared after unscaling and renormalising, to the tolerance of
// QuadraticFitTest.TranslationScaleInvariance's rounding (64 eps(T) here, the points being
// exact).

#include <locus/fit/circle_fit.hpp>
#include <locus/fit/gaussian_fit.hpp>
#include <locus/fit/line_fit.hpp>
#include <locus/fit/plane_fit.hpp>
#include <locus/fit/quadratic_fit.hpp>
#include <locus/fit/sphere_fit.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "fit_test_util.hpp"
#include "support/scale_covariance.hpp"

namespace {

using locus::Status;
using locus::Vec;
using locus::Vec2;
using locus::Vec3;
using locus_test::add;
using locus_test::Covariant;
using locus_test::Rng;
using locus_test::scaled;

template <class T>
class FitScale : public ::testing::Test {};
TYPED_TEST_SUITE(FitScale, locus_test::RealTypes);

// Points near a curve, coordinates on the grid 2^-12 Z (|x| < 8): exact when scaled by 2^k.
template <class T, int N, class F>
std::vector<Vec<T, N>> grid_points(Rng& rng, int n, F&& shape) {
  std::vector<Vec<T, N>> pts;
  for (int i = 0; i < n; ++i) {
    Vec<double, N> p = shape(rng);
    Vec<T, N> q{};
    for (int j = 0; j < N; ++j) q[j] = T(std::ldexp(std::round(std::ldexp(p[j], 12)), -12));
    pts.push_back(q);
  }
  return pts;
}

// Check 8's exponents, the largest |k| that keeps lengths normal and finite for values up to
// 2^24 (double +-1000, float +-104) and the driver's far exponents (double +-900 and +-1000,
// float +-100 and +-110): the fits work on the points scaled by a power of two (Moments), so
// they hold over the whole finite range.
template <class T>
std::vector<int> exponents() {
  std::vector<int> k = locus_test::covariant_exponents<T>(1);
  for (const int e : locus_test::far_scale_exponents<T>()) k.push_back(e);
  return k;
}

template <class T, int N>
Vec<double, N> noisy_line(Rng& rng) {
  Vec<double, N> d{};
  for (int i = 0; i < N; ++i) d[i] = 0.5 + 0.25 * i;
  Vec<double, N> p = rng.uniform<double>(-3, 3) * d;
  for (int i = 0; i < N; ++i) p[i] += 0.5 + fit_test::gauss(rng, 0.05);
  return p;
}

TYPED_TEST(FitScale, Lines) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 4; ++trial) {
    const auto p2 = grid_points<T, 2>(rng, 40, noisy_line<T, 2>);
    const auto p3 = grid_points<T, 3>(rng, 40, noisy_line<T, 3>);
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_line(scaled(p2, k));
          std::vector<Covariant> out{{"status", double(r.status), 0}, {"rms", double(r.rms), 1}};
          add(out, "origin", r.line.origin, 1);
          add(out, "direction", r.line.direction, 0);
          return out;
        },
        exponents<T>());
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_line(scaled(p3, k));
          std::vector<Covariant> out{{"status", double(r.status), 0}, {"rms", double(r.rms), 1}};
          add(out, "origin", r.line.origin, 1);
          add(out, "direction", r.line.direction, 0);
          return out;
        },
        exponents<T>());
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_line_vertical(scaled(p2, k));
          std::vector<Covariant> out{{"status", double(r.status), 0},
                                     {"slope", double(r.slope), 0},
                                     {"intercept", double(r.intercept), 1},
                                     {"rms", double(r.rms), 1}};
          add(out, "origin", r.line.origin, 1);
          add(out, "direction", r.line.direction, 0);
          return out;
        },
        exponents<T>());
  }
}

TYPED_TEST(FitScale, Planes) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  auto slab = [](Rng& g) {
    return Vec3<double>{g.uniform<double>(-4, 4), g.uniform<double>(-2, 2),
                        1 + 0.3 * g.uniform<double>(-4, 4) + fit_test::gauss(g, 0.1)};
  };
  for (int trial = 0; trial < 4; ++trial) {
    const auto pts = grid_points<T, 3>(rng, 50, slab);
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_plane(scaled(pts, k));
          std::vector<Covariant> out{{"status", double(r.status), 0},
                                     {"constant", double(r.plane.constant), 1},
                                     {"rms", double(r.rms), 1}};
          add(out, "normal", r.plane.normal, 0);
          return out;
        },
        exponents<T>());
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_hyperplane(scaled(pts, k));
          std::vector<Covariant> out{{"status", double(r.status), 0},
                                     {"constant", double(r.constant), 1},
                                     {"rms", double(r.rms), 1}};
          add(out, "normal", r.normal, 0);
          return out;
        },
        exponents<T>());
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_hyperplane_vertical(scaled(pts, k));
          std::vector<Covariant> out{{"status", double(r.status), 0},
                                     {"constant", double(r.constant), 1},
                                     {"rms", double(r.rms), 1}};
          add(out, "coefficients", r.coefficients, 0);
          return out;
        },
        exponents<T>());
  }
}

template <int N>
Vec<double, N> noisy_sphere_point(Rng& rng) {
  Vec<double, N> c{};
  for (int i = 0; i < N; ++i) c[i] = 0.75 - 0.5 * i;
  return c + (2.0 + fit_test::gauss(rng, 0.05)) * rng.unit<double, N>();
}

template <class R, int N>
std::vector<Covariant> sphere_quantities(const R& r) {
  std::vector<Covariant> out{{"status", double(r.status), 0},
                             {"iterations", double(r.iterations), 0},
                             {"rms", double(r.rms), 1}};
  if constexpr (N == 2) {
    add(out, "center", r.circle.center, 1);
    out.push_back({"radius", double(r.circle.radius), 1});
  } else {
    add(out, "center", r.sphere.center, 1);
    out.push_back({"radius", double(r.sphere.radius), 1});
  }
  return out;
}

TYPED_TEST(FitScale, CirclesAndSpheres) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 4; ++trial) {
    const auto p2 = grid_points<T, 2>(rng, 40, noisy_sphere_point<2>);
    const auto p3 = grid_points<T, 3>(rng, 60, noisy_sphere_point<3>);
    const auto ks = exponents<T>();
    locus_test::expect_scale_covariant(
        [&](int k) {
          return sphere_quantities<locus::CircleFit<T>, 2>(locus::fit_circle(scaled(p2, k)));
        },
        ks);
    locus_test::expect_scale_covariant(
        [&](int k) {
          return sphere_quantities<locus::CircleFit<T>, 2>(
              locus::fit_circle_algebraic(scaled(p2, k)));
        },
        ks);
    locus_test::expect_scale_covariant(
        [&](int k) {
          return sphere_quantities<locus::SphereFit<T, 3>, 3>(locus::fit_sphere(scaled(p3, k)));
        },
        ks);
    locus_test::expect_scale_covariant(
        [&](int k) {
          return sphere_quantities<locus::SphereFit<T, 3>, 3>(
              locus::fit_sphere_algebraic(scaled(p3, k)));
        },
        ks);
  }
}

// The coefficient vector (quadratic part, linear part, constant) of a fit to input scaled by
// 2^k, mapped back to the unscaled input (quadratic * 2^2k, linear * 2^k) and renormalised,
// with the largest component positive.
std::vector<Covariant> unit_form(std::vector<double> q, std::vector<int> degree, int k,
                                 Status status) {
  double norm = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    q[i] = std::ldexp(q[i], degree[i] * k);
    norm = std::max(norm, std::abs(q[i]));
  }
  for (double& x : q) x /= norm;  // the largest |component| first (no overflow)
  double sum = 0.0;
  std::size_t big = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    sum += q[i] * q[i];
    if (std::abs(q[i]) > std::abs(q[big])) big = i;
  }
  const double s = (q[big] < 0 ? -1.0 : 1.0) / std::sqrt(sum);
  std::vector<Covariant> out{{"status", double(status), 0}};
  for (std::size_t i = 0; i < q.size(); ++i)
    out.push_back({"coefficient " + std::to_string(i), s * q[i], 0});
  return out;
}

// At any k: the unit coefficient vector of the fit to the input scaled by 2^k against the one
// of the unscaled fit mapped to the scaled input (quadratic / 2^2k, linear / 2^k) and
// renormalised in long double, whose exponent range holds 2^(+-2k); entries that fall out of
// the range of T compare against 0. Absolute tolerance tol on the unit vector.
void expect_unit_form_scaled(const std::vector<double>& base, const std::vector<int>& degree, int k,
                             const std::vector<double>& got, Status status, double tol) {
  SCOPED_TRACE("scaled by 2^" + std::to_string(k));
  EXPECT_EQ(status, Status::ok);
  std::vector<long double> q(base.size());
  long double norm = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    q[i] = std::ldexp(static_cast<long double>(base[i]), -degree[i] * k);
    norm = std::max(norm, std::abs(q[i]));
  }
  long double sum = 0;
  std::size_t big = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    q[i] /= norm;
    sum += q[i] * q[i];
    if (std::abs(q[i]) > std::abs(q[big])) big = i;
  }
  const long double s = (q[big] < 0 ? -1.0L : 1.0L) / std::sqrt(sum);
  for (std::size_t i = 0; i < q.size(); ++i)
    EXPECT_NEAR(got[i], static_cast<double>(s * q[i]), tol) << "coefficient " << i;
}

TYPED_TEST(FitScale, QuadraticCurvesAndQuadrics) {
  using T = TypeParam;
  if (std::numeric_limits<long double>::max_exponent <
      4 * std::numeric_limits<double>::max_exponent)
    GTEST_SKIP() << "the oracle needs a long double with a wider exponent range than double";
  Rng rng;
  SCOPED_TRACE(rng.trace());
  auto parabola = [](Rng& g) {
    const double s = g.uniform<double>(-2, 2);
    return Vec2<double>{s + fit_test::gauss(g, 0.05), 0.5 * s * s + fit_test::gauss(g, 0.05)};
  };
  auto ellipsoid = [](Rng& g) {
    const Vec3<double> u = g.unit<double, 3>();
    return Vec3<double>{0.5 + 3 * u.x, 2 * u.y - 0.25, u.z} +
           fit_test::gauss(g, 0.02) * Vec3<double>{1, 1, 1};
  };
  const double tol = 64.0 * double(locus::eps_v<T>);
  auto curve = [](const locus::QuadraticCurveFit<T>& r) {
    const auto& c = r.curve;
    return std::vector<double>{c.a, c.b, c.c, c.d, c.e, c.f};
  };
  auto quadric = [](const locus::QuadricFit<T>& r) {  // the unit vector the fit normalises
    const auto& q = r.quadric;
    return std::vector<double>{
        q.a(0, 0),       q.a(1, 1), q.a(2, 2), 2.0 * q.a(0, 1), 2.0 * q.a(0, 2),
        2.0 * q.a(1, 2), q.b.x,     q.b.y,     q.b.z,           q.c};
  };
  const std::vector<int> deg2{2, 2, 2, 1, 1, 0}, deg3{2, 2, 2, 2, 2, 2, 1, 1, 1, 0};
  for (int trial = 0; trial < 4; ++trial) {
    const auto p2 = grid_points<T, 2>(rng, 40, parabola);
    const auto p3 = grid_points<T, 3>(rng, 80, ellipsoid);
    // Where every coefficient of the unscaled form stays in range (|2k| within it).
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_quadratic_curve(scaled(p2, k));
          return unit_form(curve(r), deg2, k, r.status);
        },
        locus_test::covariant_exponents<T>(2), tol);
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_quadric(scaled(p3, k));
          return unit_form(quadric(r), deg3, k, r.status);
        },
        locus_test::covariant_exponents<T>(2), tol);
    // Over the whole range, against the unscaled fit mapped in long double.
    const auto base2 = locus::fit_quadratic_curve(p2);
    const auto base3 = locus::fit_quadric(p3);
    ASSERT_EQ(base2.status, Status::ok);
    ASSERT_EQ(base3.status, Status::ok);
    for (const int k : exponents<T>()) {
      const auto r2 = locus::fit_quadratic_curve(scaled(p2, k));
      expect_unit_form_scaled(curve(base2), deg2, k, curve(r2), r2.status, tol);
      const auto r3 = locus::fit_quadric(scaled(p3, k));
      expect_unit_form_scaled(quadric(base3), deg3, k, quadric(r3), r3.status, tol);
    }
  }
}

TYPED_TEST(FitScale, Gaussians) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  auto blob = [](Rng& g) {
    return Vec3<double>{1 + fit_test::gauss(g, 2), fit_test::gauss(g, 1) - 0.5,
                        fit_test::gauss(g, 0.5)};
  };
  for (int trial = 0; trial < 4; ++trial) {
    const auto pts = grid_points<T, 3>(rng, 50, blob);
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_gaussian(scaled(pts, k));
          std::vector<Covariant> out{{"status", double(r.status), 0}, {"rms", double(r.rms), 1}};
          add(out, "mean", r.mean, 1);
          add(out, "center", r.box.center, 1);
          add(out, "extent", r.box.extent, 1);
          for (int i = 0; i < 3; ++i) add(out, "axis" + std::to_string(i), r.box.axis[i], 0);
          return out;
        },
        exponents<T>());
    // The covariance scales by 2^(2k): compared where that stays in range.
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::fit_gaussian(scaled(pts, k));
          std::vector<Covariant> out;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              out.push_back({"covariance", double(r.covariance(i, j)), 2});
          return out;
        },
        locus_test::covariant_exponents<T>(2));
  }
}

}  // namespace
