// SPDX-License-Identifier: BSL-1.0
// Tests for numeric/decompose.hpp (row num.decomp): LU, QR, Cholesky, SVD and polar
// decomposition against Eigen (peer oracle) on seeded random and adversarial matrices, plus the
// defining identities of each factorisation.
#include <locus/core/linear_system.hpp>
#include <locus/numeric/decompose.hpp>
#include <locus/numeric/matrix.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>
#include <Eigen/Dense>

#include <iostream>
#include <limits>

using namespace locus;
using locus_test::Rng;

template <class T>
class DecomposeTest : public ::testing::Test {};
TYPED_TEST_SUITE(DecomposeTest, locus_test::RealTypes);

namespace {

template <class T>
Eigen::MatrixXd to_eigen(const MatX<T>& a) {
  Eigen::MatrixXd e(a.rows, a.cols);
  for (int r = 0; r < a.rows; ++r)
    for (int c = 0; c < a.cols; ++c) e(r, c) = double(a(r, c));
  return e;
}

// Random matrices of the kinds that matter: uniform, graded (columns scaled over many orders of
// magnitude), nearly rank deficient, small integers (exact zeros, exact dependencies).
template <class T>
MatX<T> draw(Rng& rng, int m, int n, int kind) {
  MatX<T> a(m, n);
  for (int r = 0; r < m; ++r)
    for (int c = 0; c < n; ++c) {
      switch (kind) {
        case 0:
          a(r, c) = rng.uniform<T>(-1, 1);
          break;
        case 1:
          a(r, c) = rng.uniform<T>(-1, 1) * T(std::pow(10.0, -3.0 * c));
          break;
        case 2:
          a(r, c) = T(rng.uniform_int(-3, 3));
          break;
        default:
          a(r, c) = rng.uniform<T>(-1, 1);
      }
    }
  if (kind == 3 && n >= 2) {  // last column = first + tiny noise: condition ~ 1e6
    for (int r = 0; r < m; ++r) a(r, n - 1) = a(r, 0) + a(r, 1) * T(1e-6);
  }
  return a;
}

// Number of leading columns of a that are linearly independent, in exact rational arithmetic:
// |R_kk| is unique (the distance of column k from the span of the columns before it) only for
// k below this count.
template <class T>
int independent_prefix(const MatX<T>& a) {
  std::vector<std::vector<mpq_class>> basis;  // reduced columns, pivot rows in `pivots`
  std::vector<int> pivots;
  for (int c = 0; c < a.cols; ++c) {
    std::vector<mpq_class> v(static_cast<std::size_t>(a.rows));
    for (int r = 0; r < a.rows; ++r) v[std::size_t(r)] = mpq_class(double(a(r, c)));
    for (std::size_t b = 0; b < basis.size(); ++b) {
      const mpq_class f = v[std::size_t(pivots[b])] / basis[b][std::size_t(pivots[b])];
      for (int r = 0; r < a.rows; ++r) v[std::size_t(r)] -= f * basis[b][std::size_t(r)];
    }
    int piv = -1;
    for (int r = 0; r < a.rows && piv < 0; ++r)
      if (v[std::size_t(r)] != 0) piv = r;
    if (piv < 0) return c;
    basis.push_back(std::move(v));
    pivots.push_back(piv);
  }
  return a.cols;
}

}  // namespace

// LU for run-time sizes is numeric/decompose.hpp's lu_factor on a row-major span; it is
// checked here against Eigen as the peer oracle, next to the other factorisations.
TYPED_TEST(DecomposeTest, LUReconstructsAndSolvesLikeEigen) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double eps = double(eps_v<T>);
  int checked = 0;
  for (int i = 0; i < 4000; ++i) {
    const int n = 1 + i % 9;
    const MatX<T> a = draw<T>(rng, n, n, i % 3);
    const LuDynamic<T> f = lu_factor(std::span<const T>(a.data), n);
    const Eigen::MatrixXd ea = to_eigen(a);
    Eigen::FullPivLU<Eigen::MatrixXd> oracle(ea);
    if (f.singular) {
      // Only exact zero pivots make lu_factor singular: Eigen must agree the matrix is singular
      // to working precision (rank-revealing full pivoting).
      EXPECT_LT(oracle.rank(), n) << i;
      continue;
    }
    ++checked;
    // P A = L U.
    Eigen::MatrixXd l = Eigen::MatrixXd::Identity(n, n), u = Eigen::MatrixXd::Zero(n, n), pa(n, n);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const double v = double(f.lu[static_cast<std::size_t>(r * n + c)]);
        (c < r ? l(r, c) : u(r, c)) = v;
      }
    }
    for (int r = 0; r < n; ++r) pa.row(r) = ea.row(f.perm[std::size_t(r)]);
    ASSERT_LE((l * u - pa).norm(), 4.0 * n * eps * std::max(ea.norm(), 1e-300)) << i;
    ASSERT_NEAR(double(f.determinant), oracle.determinant(),
                8.0 * n * eps * std::pow(ea.norm(), n) + 1e-300)
        << i;
    std::vector<T> b(static_cast<std::size_t>(n));
    for (auto& x : b) x = rng.uniform<T>(-1, 1);
    const std::vector<T> x = solve(f, b);
    ASSERT_EQ(int(x.size()), n);
    Eigen::VectorXd eb(n), ex(n);
    for (int k = 0; k < n; ++k)
      eb(k) = double(b[std::size_t(k)]), ex(k) = double(x[std::size_t(k)]);
    // Backward stable: the residual is small relative to |A||x| (partial pivoting).
    ASSERT_LE((ea * ex - eb).norm(), 16.0 * n * eps * (ea.norm() * ex.norm() + eb.norm())) << i;
  }
  EXPECT_GT(checked, 3000);
}

TYPED_TEST(DecomposeTest, QRIsOrthogonalTimesUpperAndMatchesEigenR) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double eps = double(eps_v<T>);
  for (int i = 0; i < 4000; ++i) {
    const int n = 1 + i % 6, m = n + (i / 6) % 4;
    const MatX<T> a = draw<T>(rng, m, n, i % 4);
    const QR<T> f = qr(a);
    ASSERT_EQ(f.status, Status::ok);
    const Eigen::MatrixXd ea = to_eigen(a), q = to_eigen(f.q), r = to_eigen(f.r);
    const double na = std::max(ea.norm(), 1e-300);
    ASSERT_LE((q * r - ea).norm(), 8.0 * m * eps * na) << i;
    ASSERT_LE((q.transpose() * q - Eigen::MatrixXd::Identity(m, m)).norm(), 8.0 * m * eps) << i;
    for (int rr = 0; rr < m; ++rr) {
      for (int c = 0; c < std::min(rr, n); ++c) ASSERT_EQ(r(rr, c), 0.0);
    }
    // |R_kk| is unique while the columns up to k are independent: compare with Eigen's
    // Householder QR there. The small-integer kind is often rank-deficient (seeds 1, 3-11, 13,
    // 16-19 compared the non-unique diagonal after a dependent column).
    Eigen::HouseholderQR<Eigen::MatrixXd> oracle(ea);
    const Eigen::MatrixXd er = oracle.matrixQR().template triangularView<Eigen::Upper>();
    const int unique = independent_prefix(a);
    for (int k = 0; k < unique; ++k)
      ASSERT_NEAR(std::abs(r(k, k)), std::abs(er(k, k)), 8.0 * m * eps * na) << i;
  }
}

TYPED_TEST(DecomposeTest, CholeskyMatchesEigenAndRejectsIndefinite) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double eps = double(eps_v<T>);
  for (int i = 0; i < 4000; ++i) {
    const int n = 1 + i % 8;
    const MatX<T> g = draw<T>(rng, n, n, 0);
    Eigen::MatrixXd eg = to_eigen(g);
    Eigen::MatrixXd spd = eg * eg.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
    MatX<T> a(n, n);
    for (int r = 0; r < n; ++r)
      for (int c = r; c < n; ++c) a(r, c) = a(c, r) = T(spd(r, c));
    const Eigen::MatrixXd ea = to_eigen(a);
    const Cholesky<T> f = cholesky(a);
    ASSERT_EQ(f.status, Status::ok) << i;
    const Eigen::MatrixXd l = to_eigen(f.l);
    ASSERT_LE((l * l.transpose() - ea).norm(), 8.0 * n * eps * ea.norm()) << i;
    Eigen::LLT<Eigen::MatrixXd> oracle(ea);
    const Eigen::MatrixXd el = oracle.matrixL();
    ASSERT_LE((l - el).norm(), 1e3 * n * eps * el.norm()) << i;  // L is unique; kappa(A) <= ~1e2
  }
  MatX<T> indef = MatX<T>::identity(3);
  indef(2, 2) = T(-1);
  EXPECT_EQ(cholesky(indef).status, Status::degenerate_input);
  MatX<T> nonsym = MatX<T>::identity(2);
  nonsym(0, 1) = T(0.5);
  EXPECT_EQ(cholesky(nonsym).status, Status::invalid_input);
  EXPECT_EQ(cholesky(MatX<T>(0, 0)).status, Status::ok);  // empty product: L is empty
}

TYPED_TEST(DecomposeTest, SVDMatchesEigenSingularValuesAndReconstructs) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double eps = double(eps_v<T>);
  int cases = 0;
  for (int i = 0; i < 6000; ++i, ++cases) {
    const int m = 1 + i % 7, n = 1 + (i / 7) % 7;  // tall, square and wide
    const MatX<T> a = draw<T>(rng, m, n, i % 4);
    const SVD<T> f = svd(a);
    ASSERT_EQ(f.status, Status::ok) << i;
    const int k = std::min(m, n);
    ASSERT_EQ(int(f.s.size()), k);
    const Eigen::MatrixXd ea = to_eigen(a), u = to_eigen(f.u), v = to_eigen(f.v);
    const double na = std::max(ea.norm(), 1e-300);
    Eigen::VectorXd s(k);
    for (int j = 0; j < k; ++j) s(j) = double(f.s[std::size_t(j)]);
    Eigen::JacobiSVD<Eigen::MatrixXd> oracle(ea);
    for (int j = 0; j < k; ++j) {
      ASSERT_NEAR(s(j), oracle.singularValues()(j), 8.0 * k * eps * na) << i;
      if (j > 0) {
        ASSERT_GE(s(j - 1), s(j));
      }
      ASSERT_GE(s(j), 0.0);
    }
    ASSERT_LE((u * s.asDiagonal() * v.transpose() - ea).norm(), 16.0 * k * eps * na) << i;
    ASSERT_LE((u.transpose() * u - Eigen::MatrixXd::Identity(k, k)).norm(), 16.0 * k * eps) << i;
    ASSERT_LE((v.transpose() * v - Eigen::MatrixXd::Identity(k, k)).norm(), 16.0 * k * eps) << i;
  }
  std::cout << "[svd] " << cases << " matrices checked against Eigen::JacobiSVD\n";
}

TYPED_TEST(DecomposeTest, SVDOfRankDeficientAndZeroMatricesKeepsOrthonormalU) {
  using T = TypeParam;
  const SVD<T> z = svd(MatX<T>(4, 3));
  for (T s : z.s) EXPECT_EQ(s, T(0));
  const Eigen::MatrixXd u = to_eigen(z.u);
  EXPECT_LE((u.transpose() * u - Eigen::MatrixXd::Identity(3, 3)).norm(), 1e-6);
  MatX<T> r1(3, 3);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) r1(r, c) = T((r + 1) * (c + 1));  // rank one
  const SVD<T> f = svd(r1);
  EXPECT_NEAR(double(f.s[0]), 14.0, 1e-5);
  EXPECT_LE(double(f.s[1]), 1e-5);
  MatX<T> nan_m = MatX<T>::identity(2);
  nan_m(1, 0) = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(svd(nan_m).status, Status::non_finite_input);
}

TYPED_TEST(DecomposeTest, PolarFactorsAreOrthogonalAndSymmetricPositive) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double eps = double(eps_v<T>);
  for (int i = 0; i < 2000; ++i) {
    const int n = 1 + i % 5;
    const MatX<T> a = draw<T>(rng, n, n, i % 3);
    const Polar<T> p = polar(a);
    ASSERT_EQ(p.status, Status::ok);
    const Eigen::MatrixXd ea = to_eigen(a), q = to_eigen(p.q), s = to_eigen(p.s);
    const double na = std::max(ea.norm(), 1e-300);
    ASSERT_LE((q * s - ea).norm(), 32.0 * n * eps * na) << i;
    ASSERT_LE((q.transpose() * q - Eigen::MatrixXd::Identity(n, n)).norm(), 32.0 * n * eps) << i;
    ASSERT_LE((s - s.transpose()).norm(), 8.0 * n * eps * na) << i;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (s + s.transpose()));
    ASSERT_GE(es.eigenvalues().minCoeff(), -8.0 * n * eps * na) << i;
  }
  EXPECT_EQ(polar(MatX<T>(2, 3)).status, Status::invalid_input);
}

// MatX itself (numeric/matrix.hpp), against Eigen on the same entries: the products, transpose,
// difference and Frobenius norm the decompositions are built from, including the norm's scaling
// (entries near overflow and underflow) and its non-finite policy.
TYPED_TEST(DecomposeTest, MatXArithmeticMatchesEigen) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double eps = double(eps_v<T>);
  for (int i = 0; i < 500; ++i) {
    const int m = 1 + i % 4, k = 1 + (i / 4) % 5, n = 1 + (i / 20) % 3;
    const MatX<T> a = draw<T>(rng, m, k, i % 3), b = draw<T>(rng, k, n, (i + 1) % 3);
    const Eigen::MatrixXd ea = to_eigen(a), eb = to_eigen(b);
    const double scale = ea.cwiseAbs().maxCoeff() * eb.cwiseAbs().maxCoeff() * k + 1e-300;
    ASSERT_LE((to_eigen(a * b) - ea * eb).cwiseAbs().maxCoeff(), 4.0 * k * eps * scale) << i;
    ASSERT_EQ(to_eigen(transpose(a)), ea.transpose()) << i;
    const MatX<T> c = draw<T>(rng, m, k, 0);
    const Eigen::MatrixXd diff = ea - to_eigen(c);  // exact in double for float entries
    ASSERT_LE((to_eigen(a - c) - diff).cwiseAbs().maxCoeff(), eps * diff.cwiseAbs().maxCoeff())
        << i;
    std::vector<T> x(static_cast<std::size_t>(k));
    Eigen::VectorXd ex(k);
    for (int j = 0; j < k; ++j) ex(j) = double(x[std::size_t(j)] = rng.uniform<T>(-2, 2));
    const std::vector<T> y = a * x;
    const Eigen::VectorXd ey = ea * ex;
    ASSERT_EQ(int(y.size()), m);
    for (int r = 0; r < m; ++r)
      ASSERT_NEAR(double(y[std::size_t(r)]), ey(r),
                  4.0 * k * eps * (ea.cwiseAbs().maxCoeff() * 2 + 1e-300));
    ASSERT_NEAR(double(frobenius_norm(a)), ea.norm(), 4.0 * eps * ea.norm()) << i;
  }
  // Conversions with the fixed-size type, identity, emptiness.
  Mat<T, 2, 3> f{};
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) f(r, c) = T(r * 3 + c + 1);
  const MatX<T> fx(f);
  EXPECT_EQ(fx.rows, 2);
  EXPECT_EQ(fx.cols, 3);
  EXPECT_EQ(fx(1, 2), T(6));
  EXPECT_TRUE((fx.template to_mat<2, 3>() == f));
  EXPECT_EQ(to_eigen(MatX<T>::identity(3)), Eigen::MatrixXd::Identity(3, 3));
  EXPECT_TRUE(MatX<T>().empty());
  EXPECT_TRUE(MatX<T>(3, 0).empty());
  EXPECT_EQ(frobenius_norm(MatX<T>()), T(0));
  // Scaling: the naive sum of squares would overflow (to inf) or underflow (to 0).
  const T big = std::numeric_limits<T>::max() / T(4), tiny = std::numeric_limits<T>::denorm_min();
  MatX<T> hb(2, 2, big), ht(2, 1, tiny);
  EXPECT_NEAR(double(frobenius_norm(hb)) / double(big), 2.0, 4.0 * eps);
  EXPECT_GT(frobenius_norm(ht), T(0));
  EXPECT_TRUE(is_finite(hb));
  // Non-finite entries: the norm is NaN (a NaN anywhere) or inf, never a finite value.
  MatX<T> bad = MatX<T>::identity(3);
  bad(2, 1) = std::numeric_limits<T>::quiet_NaN();
  EXPECT_FALSE(is_finite(bad));
  EXPECT_TRUE(std::isnan(frobenius_norm(bad)));
  bad(0, 0) = std::numeric_limits<T>::infinity();
  EXPECT_TRUE(std::isnan(frobenius_norm(bad)));  // NaN wins over inf wherever it sits
  bad(2, 1) = T(1);
  EXPECT_EQ(frobenius_norm(bad), std::numeric_limits<T>::infinity());
  EXPECT_FALSE(is_finite(bad));
}
