// SPDX-License-Identifier: BSL-1.0
// Direct tests of fit/fit_common.hpp (row num.fit): FitOptions defaults and fit_rank_tolerance,
// check_points, coordinate_scale, moments, eigen_any, negligible_variance, canonical_sign,
// block_variance_range and vertical_fit. Oracles: exact GMP rationals for the mean and
// covariance, a brute-force maximum for the coordinate scale, Eigen's SelfAdjointEigenSolver for
// eigen_any / block_variance_range, Eigen's column-pivoted QR in long double on the design
// matrix [x, 1] (not centred) for vertical_fit, the documented thresholds at exactly
// representable boundaries for negligible_variance, exact data on a hyperplane, and degenerate
// input (empty, too few, NaN/Inf, no spread, spread below the rank tolerance).
#include <locus/fit/fit_common.hpp>

#include "fit/fit_test_util.hpp"

#include <gmpxx.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

using namespace locus;
using fit_test::nan_v;
using locus_test::Rng;

namespace {

template <class T>
class FitCommonTest : public ::testing::Test {};
TYPED_TEST_SUITE(FitCommonTest, locus_test::RealTypes);

template <class T, int N>
std::span<const Vec<T, N>> sp(const std::vector<Vec<T, N>>& v) {
  return {v.data(), v.size()};
}

TYPED_TEST(FitCommonTest, OptionsAndRankTolerance) {
  using T = TypeParam;
  const FitOptions<T> def;
  EXPECT_EQ(def.max_iterations, 100);
  EXPECT_EQ(detail::fit_rank_tolerance(def), T(32) * eps_v<T>);  // negative selects 32 eps(T)
  FitOptions<T> o;
  o.rank_tolerance = T(0);
  EXPECT_EQ(detail::fit_rank_tolerance(o), T(0));
  o.rank_tolerance = T(0.125);
  EXPECT_EQ(detail::fit_rank_tolerance(o), T(0.125));
  o.rank_tolerance = T(-0.5);
  EXPECT_EQ(detail::fit_rank_tolerance(o), T(32) * eps_v<T>);
}

TYPED_TEST(FitCommonTest, CheckPoints) {
  using T = TypeParam;
  std::vector<Vec3<T>> p;
  EXPECT_EQ((detail::check_points<T, 3>(sp(p), 0)), Status::empty_input);
  EXPECT_EQ((detail::check_points<T, 3>(sp(p), 3)), Status::empty_input);
  for (int i = 0; i < 3; ++i) p.push_back({T(i), T(2 * i), T(-i)});
  EXPECT_EQ((detail::check_points<T, 3>(sp(p), 3)), Status::ok);
  EXPECT_EQ((detail::check_points<T, 3>(sp(p), 4)), Status::degenerate_input);
  EXPECT_EQ((detail::check_points<T, 3>(sp(p), 2)), Status::ok);
  // Non-finite input is reported before "too few", in any coordinate and any position.
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c)
      for (T bad :
           {nan_v<T>(), std::numeric_limits<T>::infinity(), -std::numeric_limits<T>::infinity()}) {
        auto q = p;
        q[static_cast<std::size_t>(i)][c] = bad;
        EXPECT_EQ((detail::check_points<T, 3>(sp(q), 3)), Status::non_finite_input);
        EXPECT_EQ((detail::check_points<T, 3>(sp(q), 10)), Status::non_finite_input);
      }
  const std::vector<Vec2<T>> one{{T(1), T(2)}};
  EXPECT_EQ((detail::check_points<T, 2>(sp(one), 2)), Status::degenerate_input);
  EXPECT_EQ((detail::check_points<T, 2>(sp(one), 1)), Status::ok);
}

TYPED_TEST(FitCommonTest, CoordinateScale) {
  using T = TypeParam;
  using C = compute_t<T>;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  EXPECT_EQ((detail::coordinate_scale<C, T, 3>(sp(std::vector<Vec3<T>>{}))), C(0));
  for (int trial = 0; trial < 50; ++trial) {
    const int n = rng.uniform_int(1, 40);
    std::vector<Vec3<T>> p;
    for (int i = 0; i < n; ++i) p.push_back(rng.vec<T, 3>(T(-100), T(100)));
    // Brute force over all coordinates, largest absolute value (the sign must not matter).
    std::vector<C> all;
    for (const auto& q : p)
      for (int c = 0; c < 3; ++c) all.push_back(C(q[c]) < 0 ? -C(q[c]) : C(q[c]));
    EXPECT_EQ((detail::coordinate_scale<C, T, 3>(sp(p))),
              *std::max_element(all.begin(), all.end()));
  }
  const std::vector<Vec2<T>> neg{{T(-7), T(3)}, {T(2), T(-1)}};
  EXPECT_EQ((detail::coordinate_scale<C, T, 2>(sp(neg))), C(7));
}

// Mean and covariance (normalised by n) against exact rationals, with the points far from the
// origin compared to their spread (a one-pass formula would lose the spread there). The bound:
// the rounded mean is off by delta <= n eps |p|max, which enters the covariance only to second
// order (the exact deviations sum to zero); each product and the sum add (n + 4) eps of d^2.
template <class T, int N>
void check_moments(Rng& rng, double offset, double spread, int n) {
  using C = compute_t<T>;
  std::vector<Vec<T, N>> p;
  const Vec<double, N> o = rng.vec<double, N>(-offset, offset);
  for (int i = 0; i < n; ++i) p.push_back(vec_cast<T>(o + rng.vec<double, N>(-spread, spread)));
  const detail::Moments<C, N> m = detail::moments<C>(sp(p));
  mpq_class mean[N];
  for (int c = 0; c < N; ++c) {
    mean[c] = 0;
    for (const auto& q : p) mean[c] += mpq_class(double(q[c]));
    mean[c] /= n;
  }
  double maxp = 0, maxd = 0;
  for (const auto& q : p)
    for (int c = 0; c < N; ++c) {
      maxp = std::max(maxp, std::abs(double(q[c])));
      maxd = std::max(maxd, std::abs(double(q[c]) - mean[c].get_d()));
    }
  // The moments are those of the points scaled by a power of two to max|coordinate| in [1, 2).
  int ex = 0;
  EXPECT_EQ(std::frexp(double(m.scale), &ex), 0.5);
  EXPECT_GE(maxp * double(m.scale), 1.0);
  EXPECT_LT(maxp * double(m.scale), 2.0);
  const double e = double(eps_v<C>);
  const double mean_tol = (n + 2) * e * maxp;
  const double cov_tol = 2 * (n + 4) * e * maxd * maxd + 4 * mean_tol * mean_tol;
  for (int r = 0; r < N; ++r) {
    EXPECT_NEAR(double(m.unscale(m.mean[r])), mean[r].get_d(), mean_tol);
    for (int c = 0; c < N; ++c) {
      mpq_class cov = 0;
      for (const auto& q : p)
        cov += (mpq_class(double(q[r])) - mean[r]) * (mpq_class(double(q[c])) - mean[c]);
      cov /= n;
      EXPECT_NEAR(double(m.unscale(m.unscale(m.covariance(r, c)))), cov.get_d(), cov_tol)
          << r << "," << c;
      EXPECT_EQ(m.covariance(r, c), m.covariance(c, r));  // exactly symmetric
    }
  }
}

TYPED_TEST(FitCommonTest, MomentsVsGmp) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const int n = rng.uniform_int(1, 60);
    check_moments<T, 2>(rng, 1.0, 1.0, n);
    check_moments<T, 3>(rng, 1e4, 1.0, n);
    check_moments<T, 5>(rng, 100.0, 1e-2, n);
  }
  // A single point: mean is the point, covariance zero.
  const std::vector<Vec2<T>> one{{T(3), T(-4)}};
  const auto m = detail::moments<compute_t<T>>(sp(one));
  EXPECT_EQ(m.unscale(m.mean[0]), 3);
  EXPECT_EQ(m.unscale(m.mean[1]), -4);
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) EXPECT_EQ(m.covariance(r, c), 0);
}

// eigen_any for N = 2..6 (closed forms and Jacobi) against Eigen's SelfAdjointEigenSolver.
template <int N>
void check_eigen_any(Rng& rng, bool repeated) {
  using Em = Eigen::Matrix<double, N, N>;
  Mat<double, N, N> a{};
  Em ea;
  if (repeated) {
    // Q diag(1, 1, ..., 2) Q^T with a random orthogonal Q: a repeated eigenvalue.
    Em x;
    for (int r = 0; r < N; ++r)
      for (int c = 0; c < N; ++c) x(r, c) = rng.uniform<double>(-1, 1);
    const Em q = Eigen::HouseholderQR<Em>(x).householderQ();
    Eigen::Matrix<double, N, 1> d = Eigen::Matrix<double, N, 1>::Ones();
    d[N - 1] = 2;
    const Em s = q * d.asDiagonal() * q.transpose();
    ea = (s + s.transpose()) / 2;
  } else {
    for (int r = 0; r < N; ++r)
      for (int c = r; c < N; ++c) ea(r, c) = ea(c, r) = rng.uniform<double>(-1, 1);
  }
  double amax = 0;
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) {
      a(r, c) = ea(r, c);
      amax = std::max(amax, std::abs(ea(r, c)));
    }
  const SymmetricEigen<double, N> e = detail::eigen_any(a);
  ASSERT_EQ(e.status, Status::ok);
  const Eigen::SelfAdjointEigenSolver<Em> ref(ea);
  const double tol = 64.0 * N * eps_v<double> * amax;
  for (int i = 0; i < N; ++i) {
    EXPECT_NEAR(e.values[i], ref.eigenvalues()[i], tol) << "N " << N << " i " << i;
    if (i > 0) {
      EXPECT_LE(e.values[i - 1], e.values[i]);
    }
    // A v = lambda v and orthonormal columns.
    for (int r = 0; r < N; ++r) {
      double av = 0;
      for (int c = 0; c < N; ++c) av += ea(r, c) * e.vectors(c, i);
      EXPECT_NEAR(av, e.values[i] * e.vectors(r, i), tol);
    }
    for (int j = 0; j < N; ++j) {
      double d = 0;
      for (int r = 0; r < N; ++r) d += e.vectors(r, i) * e.vectors(r, j);
      EXPECT_NEAR(d, i == j ? 1.0 : 0.0, 64.0 * N * eps_v<double>);
    }
  }
}

TEST(FitCommonEigen, EigenAnyVsEigen) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 40; ++trial) {
    const bool rep = trial % 4 == 3;
    check_eigen_any<2>(rng, rep);
    check_eigen_any<3>(rng, rep);
    check_eigen_any<4>(rng, rep);
    check_eigen_any<6>(rng, rep);
  }
}

TEST(FitCommonEigen, BlockVarianceRange) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 40; ++trial) {
    Mat<double, 5, 5> cov{};
    for (int r = 0; r < 5; ++r)
      for (int c = r; c < 5; ++c) cov(r, c) = cov(c, r) = rng.uniform<double>(-1, 1);
    const auto one = detail::block_variance_range<1>(cov);
    EXPECT_EQ(one.first, cov(0, 0));
    EXPECT_EQ(one.second, cov(0, 0));
    const auto check = [&](auto kc, std::pair<double, double> got) {
      constexpr int K = decltype(kc)::value;
      Eigen::Matrix<double, K, K> b;
      for (int r = 0; r < K; ++r)
        for (int c = 0; c < K; ++c) b(r, c) = cov(r, c);
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, K, K>> ref(b);
      const double tol = 64.0 * K * eps_v<double>;  // entries are at most 1 in magnitude
      EXPECT_NEAR(got.first, ref.eigenvalues()[0], tol) << "K " << K;
      EXPECT_NEAR(got.second, ref.eigenvalues()[K - 1], tol) << "K " << K;
    };
    check(std::integral_constant<int, 2>{}, detail::block_variance_range<2>(cov));
    check(std::integral_constant<int, 3>{}, detail::block_variance_range<3>(cov));
    check(std::integral_constant<int, 4>{}, detail::block_variance_range<4>(cov));
  }
}

// The documented rule, at boundaries that are exact in double: var <= 64 N eps var_max, or
// sqrt(var) <= rank_tol * coord_scale, or var_max not positive.
TEST(FitCommonVariance, NegligibleVarianceRule) {
  using detail::negligible_variance;
  const double e = eps_v<double>;
  for (double vmax : {1.0, 0x1p-30, 0x1p40}) {
    const double b2 = 64.0 * 2 * e * vmax, b3 = 64.0 * 3 * e * vmax;
    EXPECT_TRUE((negligible_variance<double, 2>(b2, vmax, 1.0, 0.0)));
    EXPECT_FALSE((negligible_variance<double, 2>(std::nextafter(b2, 1e300), vmax, 1.0, 0.0)));
    EXPECT_TRUE((negligible_variance<double, 3>(b3, vmax, 1.0, 0.0)));
    EXPECT_FALSE((negligible_variance<double, 3>(std::nextafter(b3, 1e300), vmax, 1.0, 0.0)));
    EXPECT_TRUE((negligible_variance<double, 3>(b2 * 1.25, vmax, 1.0, 0.0)));  // N matters
    EXPECT_FALSE((negligible_variance<double, 2>(b2 * 1.25, vmax, 1.0, 0.0)));
    EXPECT_TRUE((negligible_variance<double, 2>(0.0, vmax, 1.0, 0.0)));
    EXPECT_TRUE((negligible_variance<double, 2>(-vmax, vmax, 1.0, 0.0)));  // rounded negative
    EXPECT_FALSE((negligible_variance<double, 2>(vmax, vmax, 1.0, 0.0)));
  }
  // sqrt rule: rank_tol * scale = 2^-20 * 2^10 = 2^-10; var = 2^-20 is on the boundary.
  EXPECT_TRUE((negligible_variance<double, 2>(0x1p-20, 1.0, 0x1p10, 0x1p-20)));
  EXPECT_FALSE((negligible_variance<double, 2>(0x1p-20 * (1 + 4 * e), 1.0, 0x1p10, 0x1p-20)));
  EXPECT_TRUE((negligible_variance<double, 2>(0x1p-21, 1.0, 0x1p10, 0x1p-20)));
  EXPECT_FALSE((negligible_variance<double, 2>(0x1p-20, 1.0, 0x1p9, 0x1p-20)));
  // No largest variance: always negligible.
  EXPECT_TRUE((negligible_variance<double, 2>(1.0, 0.0, 1.0, 0.0)));
  EXPECT_TRUE((negligible_variance<double, 2>(1.0, -1.0, 1.0, 0.0)));
  EXPECT_TRUE((negligible_variance<double, 2>(1.0, nan_v<double>(), 1.0, 0.0)));
}

TEST(FitCommonVariance, CanonicalSign) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 200; ++trial) {
    Vec<double, 4> v = rng.vec<double, 4>(-1, 1);
    if (trial % 5 == 0) v[1] = -v[3];  // possible magnitude tie
    if (trial % 7 == 0) v[2] = 0;
    const Vec<double, 4> s = detail::canonical_sign(v);
    const bool same = s == v, flipped = s == -v;
    EXPECT_TRUE(same || flipped);
    // The largest-magnitude component (first of equal ones) is non-negative after, and the
    // result does not depend on the input's sign.
    int k = 0;
    for (int i = 1; i < 4; ++i)
      if (std::abs(v[i]) > std::abs(v[k])) k = i;
    EXPECT_GE(s[k], 0.0);
    EXPECT_EQ(detail::canonical_sign(Vec<double, 4>(-v)), s);
  }
  EXPECT_EQ(detail::canonical_sign(Vec3d{0.5, -2.0, 1.0}), (Vec3d{-0.5, 2.0, -1.0}));
  EXPECT_EQ(detail::canonical_sign(Vec3d{0.5, 2.0, -1.0}), (Vec3d{0.5, 2.0, -1.0}));
  EXPECT_EQ(detail::canonical_sign(Vec2d{0.0, 0.0}), (Vec2d{0.0, 0.0}));
}

// Independent least squares: [x_0 .. x_{K-1}, 1] c = x_K in long double, column-pivoted QR on
// the raw (uncentred) design. Returns coefficients, constant, rms.
template <class T, int N>
void reference_fit(const std::vector<Vec<T, N>>& p, Vec<double, N - 1>& coef, double& constant,
                   double& rms) {
  constexpr int K = N - 1;
  using M = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  using V = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
  const auto n = static_cast<Eigen::Index>(p.size());
  M a(n, K + 1);
  V b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& q = p[static_cast<std::size_t>(i)];
    for (int j = 0; j < K; ++j) a(i, j) = static_cast<long double>(q[j]);
    a(i, K) = 1;
    b(i) = static_cast<long double>(q[K]);
  }
  const V x = a.colPivHouseholderQr().solve(b);
  for (int j = 0; j < K; ++j) coef[j] = static_cast<double>(x(j));
  constant = static_cast<double>(x(K));
  rms = static_cast<double>((a * x - b).norm() / std::sqrt(static_cast<long double>(n)));
}

template <class T, int N>
void check_vertical(Rng& rng, double sigma, int n) {
  constexpr int K = N - 1;
  Vec<double, K> c = rng.vec<double, K>(-2, 2);
  const double k0 = rng.uniform<double>(-5, 5);
  std::vector<Vec<T, N>> p;
  for (int i = 0; i < n; ++i) {
    Vec<double, N> q{};
    double z = k0;
    for (int j = 0; j < K; ++j) {
      q[j] = rng.uniform<double>(-5, 5);
      z += c[j] * q[j];
    }
    q[K] = z + fit_test::gauss(rng, sigma);
    p.push_back(vec_cast<T>(q));
  }
  const auto f = detail::vertical_fit<T, N>(sp(p), T(32) * eps_v<T>);
  ASSERT_EQ(f.status, Status::ok);
  Vec<double, K> rc{};
  double rk = 0, rrms = 0;
  reference_fit<T, N>(p, rc, rk, rrms);
  // Same (T-rounded) input on both sides, a well-conditioned design (|x| <= 5, spread ~3): the
  // difference is rounding in compute_t<T> = double, amplified by the condition (~10) and the
  // data scale (~20).
  const double tol = 64 * double(eps_v<compute_t<T>>) * 10 * 20;
  for (int j = 0; j < K; ++j) EXPECT_NEAR(double(f.coef[j]), rc[j], tol) << "N " << N;
  EXPECT_NEAR(double(f.constant), rk, tol) << "N " << N;
  EXPECT_NEAR(double(f.rms), rrms, tol) << "N " << N;
}

TYPED_TEST(FitCommonTest, VerticalFitVsEigenLeastSquares) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const double sigma = trial % 2 == 0 ? 0.0 : 0.3;
    // At least 4 N points keep the random design well conditioned (see the tolerance).
    check_vertical<T, 2>(rng, sigma, rng.uniform_int(8, 50));
    check_vertical<T, 3>(rng, sigma, rng.uniform_int(12, 50));
    check_vertical<T, 4>(rng, sigma, rng.uniform_int(16, 50));
  }
  // Exactly N points: interpolation, zero residual.
  for (int trial = 0; trial < 10; ++trial) {
    check_vertical<T, 2>(rng, 0.3, 2);
    check_vertical<T, 3>(rng, 0.3, 3);
  }
}

// Points exactly on z = 0.5 x - 0.25 y + 3 (small integers and dyadics: exact in float and
// double): the fit recovers the plane and a zero rms; likewise a line y = -1.5 x + 0.75.
TYPED_TEST(FitCommonTest, VerticalFitExactHyperplane) {
  using T = TypeParam;
  using C = compute_t<T>;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T rt = T(32) * eps_v<T>;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec3<T>> p;
    std::vector<Vec2<T>> l;
    const int n = rng.uniform_int(10, 30);
    for (int i = 0; i < n; ++i) {
      const int x = rng.uniform_int(-100, 100), y = rng.uniform_int(-100, 100);
      p.push_back({T(x), T(y), T(0.5) * T(x) - T(0.25) * T(y) + T(3)});
      l.push_back({T(x), T(-1.5) * T(x) + T(0.75)});
    }
    const auto f = detail::vertical_fit<T, 3>(sp(p), rt);
    ASSERT_EQ(f.status, Status::ok);
    const C tol = C(64) * eps_v<C> * C(100);
    EXPECT_NEAR(f.coef[0], C(0.5), tol);
    EXPECT_NEAR(f.coef[1], C(-0.25), tol);
    EXPECT_NEAR(f.constant, C(3), tol);
    EXPECT_LE(f.rms, tol);
    const auto g = detail::vertical_fit<T, 2>(sp(l), rt);
    ASSERT_EQ(g.status, Status::ok);
    EXPECT_NEAR(g.coef[0], C(-1.5), tol);
    EXPECT_NEAR(g.constant, C(0.75), tol);
    EXPECT_LE(g.rms, tol);
  }
}

TYPED_TEST(FitCommonTest, VerticalFitDegenerate) {
  using T = TypeParam;
  const T rt = T(32) * eps_v<T>;
  // Empty, too few (N - 1 points), non-finite: status, rms NaN.
  const std::vector<Vec3<T>> none;
  auto f = detail::vertical_fit<T, 3>(sp(none), rt);
  EXPECT_EQ(f.status, Status::empty_input);
  EXPECT_TRUE(std::isnan(f.rms));
  const std::vector<Vec3<T>> two{{T(0), T(0), T(1)}, {T(1), T(2), T(3)}};
  f = detail::vertical_fit<T, 3>(sp(two), rt);
  EXPECT_EQ(f.status, Status::degenerate_input);
  EXPECT_TRUE(std::isnan(f.rms));
  std::vector<Vec3<T>> bad{{T(0), T(0), T(1)}, {T(1), T(0), T(3)}, {T(0), T(1), T(3)}};
  EXPECT_EQ((detail::vertical_fit<T, 3>(sp(bad), rt).status), Status::ok);
  bad[1].z = nan_v<T>();
  EXPECT_EQ((detail::vertical_fit<T, 3>(sp(bad), rt).status), Status::non_finite_input);
  bad[1].z = T(3);
  bad[2].x = std::numeric_limits<T>::infinity();
  EXPECT_EQ((detail::vertical_fit<T, 3>(sp(bad), rt).status), Status::non_finite_input);
  // No spread in the (x, y) block: collinear (x, y) for the plane, one x for the line.
  std::vector<Vec3<T>> col;
  std::vector<Vec2<T>> vert;
  for (int i = 0; i < 10; ++i) {
    col.push_back({T(i), T(2 * i + 1), T(i * i)});
    vert.push_back({T(4), T(i)});
  }
  EXPECT_EQ((detail::vertical_fit<T, 3>(sp(col), rt).status), Status::degenerate_input);
  EXPECT_EQ((detail::vertical_fit<T, 2>(sp(vert), rt).status), Status::degenerate_input);
  // x spread of a few ulps of |x| (std dev ~2.2 ulp < 32 eps |x| = 32 ulp at x0 = 2^20):
  // degenerate at the default rank tolerance, solvable (exactly y = 2 x) at rank_tol = 0.
  const T x0 = T(1048576), u = x0 * eps_v<T>;
  std::vector<Vec2<T>> thin;
  for (int i = 0; i < 4; ++i) thin.push_back({x0 + T(2 * i) * u, T(2) * (x0 + T(2 * i) * u)});
  EXPECT_EQ((detail::vertical_fit<T, 2>(sp(thin), rt).status), Status::degenerate_input);
  const auto g = detail::vertical_fit<T, 2>(sp(thin), T(0));
  ASSERT_EQ(g.status, Status::ok);
  using C = compute_t<T>;
  EXPECT_NEAR(g.coef[0], C(2), C(8) * eps_v<C> * C(2));
  EXPECT_LE(g.rms, C(8) * eps_v<C> * C(x0));
}

}  // namespace
