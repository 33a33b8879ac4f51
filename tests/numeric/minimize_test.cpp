// SPDX-License-Identifier: BSL-1.0
// Tests for numeric/minimize.hpp (row num.minimize; book appendix A.8-A.9, figures A.19-A.24):
// Brent and Powell on functions with known minimisers, quadratic forms against Eigen's solvers
// (unconstrained and the KKT system of the linear-constraint case), the sphere-constrained form
// against a certificate of global optimality plus brute-force sampling, the book's examples,
// budgets and bad input.
#include <locus/numeric/minimize.hpp>

#include "support/typed.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

using namespace locus;
using locus_test::Rng;

template <class T>
class MinimizeTest : public ::testing::Test {};
TYPED_TEST_SUITE(MinimizeTest, locus_test::RealTypes);

namespace {

template <class T>
T nan_v() {
  return std::numeric_limits<T>::quiet_NaN();
}

// Brent's accuracy in x: the bracket ends within 2 tol1 = 2 (rel |x| + abs) of the minimiser,
// and a smooth minimum is flat to eps * |f| within sqrt(eps |f| / f'') of it, so no method can
// do better than about sqrt(eps); allow 8 times that at the given scale.
template <class T>
T brent_bound(T scale) {
  return T(8) * std::sqrt(eps_v<T>) * std::max(scale, T(1));
}

// A random symmetric positive definite matrix R diag(l) R^T with eigenvalues in [lo, hi].
template <class T, int N>
Mat<T, N, N> random_spd(Rng& rng, double lo, double hi) {
  Eigen::MatrixXd m(N, N);
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) m(r, c) = rng.uniform<double>(-1, 1);
  Eigen::HouseholderQR<Eigen::MatrixXd> q(m);
  const Eigen::MatrixXd rot = q.householderQ();
  Eigen::VectorXd l(N);
  for (int i = 0; i < N; ++i) l(i) = rng.uniform<double>(lo, hi);
  const Eigen::MatrixXd a = rot * l.asDiagonal() * rot.transpose();
  Mat<T, N, N> out{};
  for (int r = 0; r < N; ++r)
    for (int c = r; c < N; ++c) out(r, c) = out(c, r) = T(a(r, c));
  return out;
}

template <class T, int N>
Eigen::MatrixXd to_eigen(const Mat<T, N, N>& a) {
  Eigen::MatrixXd m(N, N);
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) m(r, c) = double(a(r, c));
  return m;
}

template <class T, int N>
double quad_value(const Mat<T, N, N>& a, const Vec<T, N>& b, T c, const Vec<double, N>& x) {
  double s = double(c);
  for (int r = 0; r < N; ++r) {
    double ax = 0;
    for (int k = 0; k < N; ++k) ax += double(a(r, k)) * x[k];
    s += x[r] * (ax + double(b[r]));
  }
  return s;
}

}  // namespace

// ---- Brent ---------------------------------------------------------------------------------

TYPED_TEST(MinimizeTest, BrentKnownMinimisers) {
  using T = TypeParam;
  {  // parabola with minimiser 2
    const auto m = minimize_brent([](T x) { return (x - T(2)) * (x - T(2)) + T(1); }, T(0), T(5));
    EXPECT_EQ(m.status, Status::ok);
    EXPECT_NEAR(m.x, T(2), brent_bound(T(2)));
    EXPECT_NEAR(m.value, T(1), T(4) * eps_v<T>);
    EXPECT_LT(m.evaluations, 40);
  }
  {  // cos has its minimum at pi on [2, 4]
    const auto m = minimize_brent([](T x) { return std::cos(x); }, T(2), T(4));
    EXPECT_EQ(m.status, Status::ok);
    EXPECT_NEAR(m.x, pi_v<T>, brent_bound(pi_v<T>));
  }
  {  // x ln x has its minimum at 1/e
    const auto m = minimize_brent([](T x) { return x * std::log(x); }, T(0.05), T(1));
    EXPECT_EQ(m.status, Status::ok);
    EXPECT_NEAR(m.x, T(1) / std::exp(T(1)), brent_bound(T(1)));
  }
  {  // non-smooth |x - 0.3|: only the golden-section safeguard converges here; the accuracy is
     // then the bracket width, 2 tol1 + rounding.
    const auto m = minimize_brent([](T x) { return std::abs(x - T(0.3)); }, T(-1), T(2));
    EXPECT_EQ(m.status, Status::ok);
    EXPECT_NEAR(m.x, T(0.3), brent_bound(T(1)));
  }
  {  // a minimum at the interval end: converges onto the end
    const auto m = minimize_brent([](T x) { return x; }, T(1), T(3));
    EXPECT_EQ(m.status, Status::ok);
    EXPECT_NEAR(m.x, T(1), brent_bound(T(1)));
  }
}

TYPED_TEST(MinimizeTest, BrentRandomParabolasAgainstVertex) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 200; ++trial) {
    const T m = rng.uniform<T>(-10, 10), k = rng.uniform<T>(-5, 5), a = rng.uniform<T>(0.1f, 10);
    const T lo = m - rng.uniform<T>(0.1f, 5), hi = m + rng.uniform<T>(0.1f, 5);
    // A quartic perturbation keeps the vertex at m but makes the parabola fit inexact.
    auto f = [&](T x) { return a * (x - m) * (x - m) + (x - m) * (x - m) * (x - m) * (x - m) + k; };
    const auto r = minimize_brent(f, lo, hi);
    ASSERT_EQ(r.status, Status::ok);
    // f - k is flat to eps * (|k| + |f|) within sqrt(eps (|k| + 1) / a) of m.
    const T flat = std::sqrt(eps_v<T> * (std::abs(k) + T(1)) / a);
    EXPECT_NEAR(r.x, m, brent_bound(std::abs(m)) + T(4) * flat) << trial;
  }
}

TYPED_TEST(MinimizeTest, BracketContainsMinimum) {
  using T = TypeParam;
  auto f = [](T x) { return (x - T(10)) * (x - T(10)); };
  const Bracket<T> br = bracket_minimum(f, T(0), T(1));
  ASSERT_EQ(br.status, Status::ok);
  EXPECT_LT(std::min(br.a, br.c), T(10));
  EXPECT_GT(std::max(br.a, br.c), T(10));
  EXPECT_LT(br.fb, br.fa);
  EXPECT_LE(br.fb, br.fc);
  const auto m = minimize_brent(f, br);
  EXPECT_EQ(m.status, Status::ok);
  EXPECT_NEAR(m.x, T(10), brent_bound(T(10)));
  // Going downhill to the left from the given order.
  const Bracket<T> left = bracket_minimum(f, T(30), T(29));
  ASSERT_EQ(left.status, Status::ok);
  EXPECT_LT(std::min(left.a, left.c), T(10));
  EXPECT_GT(std::max(left.a, left.c), T(10));
}

TYPED_TEST(MinimizeTest, BrentBudgetsAndBadInput) {
  using T = TypeParam;
  BrentOptions<T> opt;
  opt.max_iterations = 3;
  const auto lim = minimize_brent([](T x) { return std::cos(x); }, T(2), T(4), opt);
  EXPECT_EQ(lim.status, Status::limit_exceeded);
  EXPECT_TRUE(lim.x >= T(2) && lim.x <= T(4));
  EXPECT_EQ(lim.value, std::cos(lim.x));
  // NaN on part of the interval acts as +infinity: the minimiser of the finite part is found.
  const auto half = minimize_brent(
      [](T x) { return x < T(1) ? nan_v<T>() : (x - T(2)) * (x - T(2)); }, T(0), T(5));
  EXPECT_EQ(half.status, Status::ok);
  EXPECT_NEAR(half.x, T(2), brent_bound(T(2)));
  // Nothing finite: a status, a NaN value, no hang.
  const auto none = minimize_brent([](T) { return nan_v<T>(); }, T(0), T(1));
  EXPECT_EQ(none.status, Status::non_finite_input);
  EXPECT_TRUE(std::isnan(none.value));
  EXPECT_EQ(minimize_brent([](T x) { return x * x; }, nan_v<T>(), T(1)).status,
            Status::non_finite_input);
  // Unbounded below: bracketing runs out of its evaluation budget.
  const Bracket<T> br = bracket_minimum([](T x) { return -x; }, T(0), T(1), 30);
  EXPECT_EQ(br.status, Status::limit_exceeded);
  EXPECT_LE(br.evaluations, 30);
  EXPECT_EQ(bracket_minimum([](T) { return nan_v<T>(); }, T(0), T(1)).status,
            Status::non_finite_input);
}

// ---- Powell --------------------------------------------------------------------------------

TYPED_TEST(MinimizeTest, PowellRosenbrock) {
  using T = TypeParam;
  auto rosen = [](const Vec2<T>& p) { return sqr(T(1) - p.x) + T(100) * sqr(p.y - p.x * p.x); };
  const auto m = minimize_powell(rosen, Vec2<T>{T(-1.2), T(1)});
  EXPECT_EQ(m.status, Status::ok);
  // At (1, 1) the Hessian has eigenvalues 0.4 and 1001.6; the line searches resolve t to
  // sqrt(eps), which along the soft direction allows an error of about sqrt(eps * cond) in x
  // relative (cond ~ 2500, so about 50 sqrt(eps)); allow 4 times that.
  const T bound = T(200) * std::sqrt(eps_v<T>);
  EXPECT_NEAR(m.x.x, T(1), bound);
  EXPECT_NEAR(m.x.y, T(1), bound);
  EXPECT_LT(m.value, T(1e-6));
}

TYPED_TEST(MinimizeTest, PowellQuadraticBowlsAgainstEigen) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const Mat<T, 4, 4> a = random_spd<T, 4>(rng, 0.5, 4);  // condition number <= 8
    const Vec<T, 4> center = rng.vec<T, 4>(-3, 3);
    auto f = [&](const Vec<T, 4>& x) { return dot(x - center, a * (x - center)) + T(2); };
    const auto m = minimize_powell(f, Vec<T, 4>{});
    ASSERT_EQ(m.status, Status::ok) << trial;
    // Oracle: Eigen solves the stationarity system 2 A x = 2 A center.
    Eigen::VectorXd rhs(4);
    const Eigen::MatrixXd ae = to_eigen(a);
    for (int i = 0; i < 4; ++i) rhs(i) = double(center[i]);
    const Eigen::VectorXd xe = ae.ldlt().solve(ae * rhs);
    // f is flat to eps |f| within sqrt(eps |f| / lambda_min) of the minimiser: with f ~ 2 and
    // lambda_min >= 0.5, that is 2 sqrt(eps); allow 8 times, scaled by |center| <= 6.
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(double(m.x[i]), xe(i), 16.0 * std::sqrt(double(eps_v<T>)) * 6) << trial;
    EXPECT_NEAR(m.value, T(2), T(16) * eps_v<T> * T(2));
  }
}

TYPED_TEST(MinimizeTest, PowellBudgetsAndBadInput) {
  using T = TypeParam;
  auto rosen = [](const Vec2<T>& p) { return sqr(T(1) - p.x) + T(100) * sqr(p.y - p.x * p.x); };
  PowellOptions<T> opt;
  opt.max_iterations = 1;
  const auto lim = minimize_powell(rosen, Vec2<T>{T(-1.2), T(1)}, opt);
  EXPECT_EQ(lim.status, Status::limit_exceeded);
  EXPECT_LT(lim.value, rosen(Vec2<T>{T(-1.2), T(1)}));  // best so far, still an improvement
  EXPECT_EQ(lim.value, rosen(lim.x));
  // NaN outside the unit disk: the minimiser (0.2, -0.3) inside is found.
  auto disk = [](const Vec2<T>& p) {
    return sqr_length(p) > T(1) ? nan_v<T>() : sqr(p.x - T(0.2)) + T(3) * sqr(p.y + T(0.3));
  };
  const auto d = minimize_powell(disk, Vec2<T>{T(0.5), T(0.5)});
  EXPECT_EQ(d.status, Status::ok);
  EXPECT_NEAR(d.x.x, T(0.2), T(16) * std::sqrt(eps_v<T>));
  EXPECT_NEAR(d.x.y, T(-0.3), T(16) * std::sqrt(eps_v<T>));
  // NaN everywhere, NaN start, unbounded below: statuses, no hang.
  const auto all_nan = minimize_powell([](const Vec2<T>&) { return nan_v<T>(); }, Vec2<T>{});
  EXPECT_EQ(all_nan.status, Status::non_finite_input);
  EXPECT_TRUE(std::isnan(all_nan.value));
  EXPECT_EQ(minimize_powell(rosen, Vec2<T>{nan_v<T>(), T(0)}).status, Status::non_finite_input);
  const auto unb = minimize_powell([](const Vec2<T>& p) { return p.x + p.y; }, Vec2<T>{});
  EXPECT_EQ(unb.status, Status::limit_exceeded);
}

// ---- quadratic forms -----------------------------------------------------------------------

// Figures A.19 and A.20: f(x, y) = x^2 + y^2 has its minimum 0 at the origin.
TYPED_TEST(MinimizeTest, FigureA19A20Paraboloid) {
  using T = TypeParam;
  const auto m = minimize_quadratic(Mat2<T>::identity(), Vec2<T>{}, T(0));
  EXPECT_EQ(m.status, Status::ok);
  EXPECT_EQ(m.x, (Vec2<T>{}));
  EXPECT_EQ(m.value, T(0));
}

TYPED_TEST(MinimizeTest, UnconstrainedQuadraticAgainstEigen) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 100; ++trial) {
    const Mat<T, 5, 5> a = random_spd<T, 5>(rng, 0.1, 10);  // cond <= 100
    const Vec<T, 5> b = rng.vec<T, 5>(-10, 10);
    const T c = rng.uniform<T>(-1, 1);
    const auto m = minimize_quadratic(a, b, c);
    ASSERT_EQ(m.status, Status::ok);
    const Eigen::MatrixXd ae = to_eigen(a);
    Eigen::VectorXd be(5);
    for (int i = 0; i < 5; ++i) be(i) = -double(b[i]) / 2;
    const Eigen::VectorXd xe = ae.fullPivLu().solve(be);
    // Relative error of a backward-stable solve: cond * eps of the compute type (double), then
    // rounded to T: 4 eps(T) |x| covers both.
    for (int i = 0; i < 5; ++i)
      EXPECT_NEAR(double(m.x[i]), xe(i),
                  4.0 * double(eps_v<T>) * xe.norm() + 1e3 * 2.3e-16 * xe.norm());
  }
}

TYPED_TEST(MinimizeTest, QuadraticNotPositiveDefinite) {
  using T = TypeParam;
  // Indefinite: unbounded below.
  const auto ind = minimize_quadratic(Mat2<T>::diagonal({T(1), T(-1)}), Vec2<T>{T(1), T(1)}, T(0));
  EXPECT_EQ(ind.status, Status::degenerate_input);
  EXPECT_TRUE(is_finite(ind.x));
  // Positive semidefinite with b in the range: a valley of minimisers; x is the minimum-norm one.
  const auto psd = minimize_quadratic(Mat2<T>::diagonal({T(1), T(0)}), Vec2<T>{T(-2), T(0)}, T(0));
  EXPECT_EQ(psd.status, Status::degenerate_input);
  EXPECT_NEAR(psd.x.x, T(1), T(4) * eps_v<T>);
  EXPECT_EQ(psd.x.y, T(0));
  // Zero matrix, NaN, non-symmetric.
  EXPECT_EQ(minimize_quadratic(Mat2<T>{}, Vec2<T>{}, T(0)).status, Status::degenerate_input);
  const auto bad = minimize_quadratic(Mat2<T>::identity(), Vec2<T>{nan_v<T>(), T(0)}, T(0));
  EXPECT_EQ(bad.status, Status::non_finite_input);
  EXPECT_TRUE(std::isnan(bad.value));
  Mat2<T> ns = Mat2<T>::identity();
  ns(0, 1) = T(1);
  EXPECT_EQ(minimize_quadratic(ns, Vec2<T>{}, T(0)).status, Status::invalid_input);
}

TYPED_TEST(MinimizeTest, LinearConstraintsAgainstKkt) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 100; ++trial) {
    const Mat<T, 4, 4> a = random_spd<T, 4>(rng, 0.2, 5);
    const Vec<T, 4> b = rng.vec<T, 4>(-5, 5);
    Mat<T, 2, 4> cm{};
    for (int r = 0; r < 2; ++r)
      for (int k = 0; k < 4; ++k) cm(r, k) = rng.uniform<T>(-1, 1);
    const Vec<T, 2> d = rng.vec<T, 2>(-2, 2);
    const auto m = minimize_quadratic(a, b, T(0), cm, d);
    ASSERT_EQ(m.status, Status::ok);
    // Oracle: Eigen's full-pivot LU of the KKT system [[2A, C^T], [C, 0]] [x; l] = [-b; d].
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(6, 6);
    Eigen::VectorXd rhs(6);
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) k(r, c) = 2 * double(a(r, c));
      rhs(r) = -double(b[r]);
    }
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 4; ++c) k(4 + r, c) = k(c, 4 + r) = double(cm(r, c));
      rhs(4 + r) = double(d[r]);
    }
    const Eigen::VectorXd sol = k.fullPivLu().solve(rhs);
    const double cond = k.jacobiSvd().singularValues()(0) / k.jacobiSvd().singularValues()(5);
    // Forward error of a stable solve of the KKT system: cond * eps (double), then rounding to T.
    const double tol = (double(eps_v<T>) * 4 + cond * 64 * 2.3e-16) * (sol.norm() + 1);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(double(m.x[i]), sol(i), tol) << trial;
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(double(m.multipliers[i]), sol(4 + i), tol) << trial;
  }
}

TYPED_TEST(MinimizeTest, LinearConstraintsDegenerate) {
  using T = TypeParam;
  // f = x^2 - y^2 is indefinite but positive definite on the line y = 1/2: minimum at x = 0.
  const Mat<T, 1, 2> row_y = Mat<T, 1, 2>::from_rows(Vec2<T>{T(0), T(1)});
  const auto ok = minimize_quadratic(Mat2<T>::diagonal({T(1), T(-1)}), Vec2<T>{}, T(0), row_y,
                                     Vec<T, 1>{T(0.5)});
  EXPECT_EQ(ok.status, Status::ok);
  EXPECT_NEAR(ok.x.x, T(0), T(4) * eps_v<T>);
  EXPECT_NEAR(ok.x.y, T(0.5), T(4) * eps_v<T>);
  EXPECT_NEAR(ok.value, T(-0.25), T(4) * eps_v<T>);
  // ... but -x^2 + y^2 on the same line is unbounded.
  EXPECT_EQ(minimize_quadratic(Mat2<T>::diagonal({T(-1), T(1)}), Vec2<T>{}, T(0), row_y,
                               Vec<T, 1>{T(0.5)})
                .status,
            Status::degenerate_input);
  // Dependent rows (the same constraint twice) and NaN.
  const Mat<T, 2, 3> dup = Mat<T, 2, 3>::from_rows(Vec3<T>{1, 1, 1}, Vec3<T>{2, 2, 2});
  const auto d = minimize_quadratic(Mat3<T>::identity(), Vec3<T>{}, T(0), dup, Vec2<T>{1, 2});
  EXPECT_EQ(d.status, Status::degenerate_input);
  EXPECT_TRUE(std::isnan(d.value));
  const Mat<T, 1, 3> row = Mat<T, 1, 3>::from_rows(Vec3<T>{1, nan_v<T>(), 1});
  EXPECT_EQ(minimize_quadratic(Mat3<T>::identity(), Vec3<T>{}, T(0), row, Vec<T, 1>{T(1)}).status,
            Status::non_finite_input);
  // Fully determined (M = N): the unique feasible point.
  const auto full = minimize_quadratic(Mat2<T>::identity(), Vec2<T>{}, T(0), Mat2<T>::identity(),
                                       Vec2<T>{T(3), T(-4)});
  EXPECT_EQ(full.status, Status::ok);
  EXPECT_NEAR(full.x.x, T(3), T(8) * eps_v<T>);
  EXPECT_NEAR(full.x.y, T(-4), T(8) * eps_v<T>);
  EXPECT_NEAR(full.value, T(25), T(32) * eps_v<T>);
}

// Figure A.22: the closest and farthest points of the sphere x^2 + y^2 + z^2 = 36 to (1, 2, 2)
// are (2, 4, 4) and (-2, -4, -4). f(x) = |x - p|^2 = x^T I x - 2 p^T x + |p|^2; Lagrange's
// condition 2 (x - p) = 2 mu x gives mu = 1/2 at the closest and 3/2 at the farthest point.
TYPED_TEST(MinimizeTest, FigureA22ClosestFarthestOnSphere) {
  using T = TypeParam;
  const Vec3<T> p{1, 2, 2};
  const auto lo =
      minimize_quadratic_on_sphere(Mat3<T>::identity(), T(-2) * p, T(9), Vec3<T>{}, T(6));
  EXPECT_EQ(lo.status, Status::ok);
  EXPECT_TRUE(lo.unique);
  EXPECT_TRUE(locus_test::vec_near(lo.x, Vec3<T>{2, 4, 4}, T(16) * eps_v<T> * T(6)));
  EXPECT_NEAR(lo.value, T(9), T(64) * eps_v<T> * T(36));  // distance 3
  EXPECT_NEAR(lo.multiplier, T(0.5), T(16) * eps_v<T>);
  const auto hi =
      maximize_quadratic_on_sphere(Mat3<T>::identity(), T(-2) * p, T(9), Vec3<T>{}, T(6));
  EXPECT_EQ(hi.status, Status::ok);
  EXPECT_TRUE(locus_test::vec_near(hi.x, Vec3<T>{-2, -4, -4}, T(16) * eps_v<T> * T(6)));
  EXPECT_NEAR(hi.value, T(81), T(64) * eps_v<T> * T(81));  // distance 9
  EXPECT_NEAR(hi.multiplier, T(1.5), T(16) * eps_v<T>);
}

// Figure A.21 shows a level ellipse of f tangent to the constraint curve at the minima. The
// caption does not give f; our reading: f(x, y) = 4 x^2 + y^2 on the unit circle, whose level
// ellipse f = 1 touches the circle at the two minima (0, +-1). g = 0 is orthogonal to the
// lowest eigenvector, so this is the solver's "hard case" with two minimisers.
TYPED_TEST(MinimizeTest, FigureA21TangentEllipse) {
  using T = TypeParam;
  const auto m = minimize_quadratic_on_sphere(Mat2<T>::diagonal({T(4), T(1)}), Vec2<T>{}, T(0),
                                              Vec2<T>{}, T(1));
  EXPECT_EQ(m.status, Status::ok);
  EXPECT_FALSE(m.unique);
  EXPECT_NEAR(m.x.x, T(0), T(4) * eps_v<T>);
  EXPECT_NEAR(std::abs(m.x.y), T(1), T(4) * eps_v<T>);
  EXPECT_NEAR(m.value, T(1), T(8) * eps_v<T>);
  EXPECT_EQ(m.multiplier, T(1));
}

// Figures A.23 and A.24: constraints g1 = x - y + z = 1 and g2 = x^2 + y^2 = 1. The caption does
// not state f; our reading is f(x, y, z) = x^2 + y^2 + z^2 (the squared distance to the origin,
// extremised along the constraint curve). Eliminating z = 1 - x + y with the linear constraint
// leaves q(x, y) = 2x^2 - 2xy + 2y^2 - 2x + 2y + 1 on the unit circle. With x = cos t,
// y = sin t: q = 1 + (1 - cos t + sin t)^2, minimum 1 where cos t - sin t = 1, i.e. at (1, 0, 0)
// and (0, -1, 0) (two minimisers: the hard case), maximum 1 + (1 + sqrt 2)^2 = 4 + 2 sqrt 2 at
// (-1/sqrt 2, 1/sqrt 2, 1 + sqrt 2). Brute force over t checks both.
TYPED_TEST(MinimizeTest, FigureA24TwoConstraintExtrema) {
  using T = TypeParam;
  const Mat2<T> a = Mat2<T>::from_rows(Vec2<T>{T(2), T(-1)}, Vec2<T>{T(-1), T(2)});
  const Vec2<T> b{T(-2), T(2)};
  const auto lo = minimize_quadratic_on_sphere(a, b, T(1), Vec2<T>{}, T(1));
  ASSERT_EQ(lo.status, Status::ok);
  EXPECT_FALSE(lo.unique);
  EXPECT_NEAR(lo.value, T(1), T(16) * eps_v<T>);
  const bool at_first = std::abs(lo.x.x - T(1)) < T(0.5);
  const Vec2<T> expect_lo = at_first ? Vec2<T>{T(1), T(0)} : Vec2<T>{T(0), T(-1)};
  EXPECT_TRUE(locus_test::vec_near(lo.x, expect_lo, T(16) * eps_v<T>));
  const auto hi = maximize_quadratic_on_sphere(a, b, T(1), Vec2<T>{}, T(1));
  ASSERT_EQ(hi.status, Status::ok);
  EXPECT_TRUE(hi.unique);
  const T s = std::sqrt(T(0.5));
  EXPECT_TRUE(locus_test::vec_near(hi.x, Vec2<T>{-s, s}, T(16) * eps_v<T>));
  EXPECT_NEAR(hi.value, T(4) + T(2) * std::sqrt(T(2)), T(32) * eps_v<T>);
  // The 3D points satisfy both constraints.
  const T z = T(1) - hi.x.x + hi.x.y;
  EXPECT_NEAR(z, T(1) + std::sqrt(T(2)), T(16) * eps_v<T>);
  // Brute force along the constraint curve (t step 2 pi / 20000: the value error at a smooth
  // extremum is q'' (dt/2)^2 / 2 <= 4 * 2.5e-8).
  double bmin = 1e300, bmax = -1e300;
  for (int i = 0; i < 20000; ++i) {
    const double t = 2 * pi_v<double> * i / 20000.0;
    const double x = std::cos(t), y = std::sin(t), zz = 1 - x + y;
    const double f = x * x + y * y + zz * zz;
    bmin = std::min(bmin, f);
    bmax = std::max(bmax, f);
  }
  EXPECT_NEAR(double(lo.value), bmin, 1e-6);
  EXPECT_NEAR(double(hi.value), bmax, 1e-6);
}

// Random sphere-constrained problems: the result is certified globally optimal by the
// necessary and sufficient conditions of this problem (|y| = r, (A - mu I) y = -g/2,
// A - mu I positive semidefinite), and compared with brute-force sampling of the sphere.
TYPED_TEST(MinimizeTest, SphereRandomCertificateAndBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    Mat3<T> a{};
    for (int r = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c) a(r, c) = a(c, r) = rng.uniform<T>(-2, 2);
    Vec3<T> b = rng.vec<T, 3>(-3, 3);
    if (trial % 4 == 3) b = b * T(1e-3);  // near the hard case
    const Vec3<T> center = rng.vec<T, 3>(-1, 1);
    const T radius = rng.uniform<T>(0.5f, 2);
    const auto m = minimize_quadratic_on_sphere(a, b, T(0), center, radius);
    ASSERT_EQ(m.status, Status::ok) << trial;
    const Vec3d y = vec_cast<double>(m.x) - vec_cast<double>(center);
    const double teps = double(eps_v<T>);
    EXPECT_NEAR(std::sqrt(sqr_length(y)), double(radius), 8 * teps * double(radius)) << trial;
    const Eigen::VectorXd ev =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(to_eigen(a)).eigenvalues();
    EXPECT_LE(double(m.multiplier), ev(0) + 64 * teps * 4) << trial;
    // Stationarity: grad f = 2 A x + b = 2 mu (x - center). The gradient's scale is
    // 2 |A| |x| + |b| < 2 * 6 * 3.8 + 5.2 < 51. y = -(A - mu I)^-1 g / 2 is computed through the
    // eigendecomposition, whose error eps(double) |A| is amplified by the conditioning
    // kappa = (lambda_max - mu) / (lambda_min - mu) of A - mu I; rounding x to T adds eps(T).
    const double kappa =
        (ev(2) - double(m.multiplier)) / std::max(ev(0) - double(m.multiplier), 1e-300);
    Vec3d grad{};
    for (int r = 0; r < 3; ++r) {
      double s = double(b[r]);
      for (int k = 0; k < 3; ++k) s += 2 * double(a(r, k)) * double(m.x[k]);
      grad[r] = s;
    }
    const Vec3d resid = grad - 2 * double(m.multiplier) * y;
    EXPECT_LT(std::sqrt(sqr_length(resid)), 64 * 51 * (teps + 2.3e-16 * kappa)) << trial;
    // Brute force: 300 x 150 angles, grid spacing h <= r 2 pi / 300 < 0.042. Ours must not be
    // above the sampled minimum (beyond rounding), and the sampled minimum exceeds the true one by
    // at most f''_max (h / sqrt 2)^2 / 2 with f'' along the sphere <= 2 |A| r^2 + |g| r < 98
    // (|A| <= 6, r <= 2, |g| <= |b| + 2 |A| |center| < 25), i.e. < 0.045: 0.05 below is a
    // genuine failure.
    double best = 1e300;
    for (int i = 0; i < 300; ++i)
      for (int j = 0; j <= 150; ++j) {
        const double th = 2 * pi_v<double> * i / 300, ph = pi_v<double> * j / 150;
        const Vec3d x = vec_cast<double>(center) +
                        double(radius) * Vec3d{std::cos(th) * std::sin(ph),
                                               std::sin(th) * std::sin(ph), std::cos(ph)};
        best = std::min(best, quad_value(a, b, T(0), x));
      }
    EXPECT_LE(double(m.value), best + 1e-9 + 64 * teps * 51 * 4) << trial;
    EXPECT_GE(double(m.value), best - 0.05) << trial;
  }
}

TYPED_TEST(MinimizeTest, SphereHardCaseAndBadInput) {
  using T = TypeParam;
  // A = diag(-1, 2, 3), g along e2 only: |y(lambda_min)| = 1/3 < r = 1 -> hard case, two
  // minimisers y = (+-sqrt(8/9), -1/3, 0), value -8/9 + 2/9 - 2/3 = -4/3.
  const Mat3<T> a = Mat3<T>::diagonal({T(-1), T(2), T(3)});
  const auto m = minimize_quadratic_on_sphere(a, Vec3<T>{T(0), T(2), T(0)}, T(0), Vec3<T>{}, T(1));
  ASSERT_EQ(m.status, Status::ok);
  EXPECT_FALSE(m.unique);
  EXPECT_NEAR(std::abs(m.x.x), std::sqrt(T(8) / T(9)), T(16) * eps_v<T>);
  EXPECT_NEAR(m.x.y, T(-1) / T(3), T(16) * eps_v<T>);
  EXPECT_NEAR(m.x.z, T(0), T(16) * eps_v<T>);
  EXPECT_NEAR(m.value, T(-4) / T(3), T(32) * eps_v<T>);
  EXPECT_NEAR(m.multiplier, T(-1), T(16) * eps_v<T>);
  // Radius 0: the center. Negative radius, NaN.
  const auto pt = minimize_quadratic_on_sphere(a, Vec3<T>{1, 2, 3}, T(0), Vec3<T>{1, 1, 1}, T(0));
  EXPECT_EQ(pt.status, Status::ok);
  EXPECT_EQ(pt.x, (Vec3<T>{1, 1, 1}));
  EXPECT_EQ(pt.value, T(-1 + 2 + 3 + 1 + 2 + 3));
  EXPECT_EQ(minimize_quadratic_on_sphere(a, Vec3<T>{}, T(0), Vec3<T>{}, T(-1)).status,
            Status::invalid_input);
  const auto bad = minimize_quadratic_on_sphere(a, Vec3<T>{}, T(0), Vec3<T>{}, nan_v<T>());
  EXPECT_EQ(bad.status, Status::non_finite_input);
  EXPECT_TRUE(std::isnan(bad.value));
  // A = 0, g = 0: every point of the sphere is a minimiser.
  const auto flat = minimize_quadratic_on_sphere(Mat3<T>{}, Vec3<T>{}, T(5), Vec3<T>{}, T(2));
  EXPECT_EQ(flat.status, Status::ok);
  EXPECT_FALSE(flat.unique);
  EXPECT_NEAR(length(flat.x), T(2), T(4) * eps_v<T>);
  EXPECT_EQ(flat.value, T(5));
}
