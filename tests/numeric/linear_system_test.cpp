// SPDX-License-Identifier: BSL-1.0
// Tests for core/linear_system.hpp (fixed size) and the run-time solvers of numeric/decompose.hpp
// (row core.linsys; figures 2.2, 2.3): Cramer's rule, Gaussian elimination with partial pivoting,
// determinant, inverse, rank, near-singularity, against exact GMP rational arithmetic; the two
// sizes are also checked against each other, so they live in one file.
#include <locus/core/linear_system.hpp>
#include <locus/numeric/decompose.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class LinearSystemTest : public ::testing::Test {};
TYPED_TEST_SUITE(LinearSystemTest, locus_test::RealTypes);

namespace {

using Q = mpq_class;
using QVec = std::vector<Q>;

// ---- exact oracle: Gauss-Jordan elimination over the rationals ------------------------------

struct Exact {
  bool singular = false;
  QVec x;  // n x nrhs row-major
  Q det;
};

Exact exact_solve(QVec a, int n, QVec b, int nrhs) {
  Exact e;
  e.det = 1;
  for (int k = 0; k < n; ++k) {
    int p = k;
    while (p < n && a[static_cast<std::size_t>(p * n + k)] == 0) ++p;
    if (p == n) {
      e.singular = true;
      e.det = 0;
      return e;
    }
    if (p != k) {
      for (int c = 0; c < n; ++c)
        std::swap(a[static_cast<std::size_t>(k * n + c)], a[static_cast<std::size_t>(p * n + c)]);
      for (int c = 0; c < nrhs; ++c)
        std::swap(b[static_cast<std::size_t>(k * nrhs + c)],
                  b[static_cast<std::size_t>(p * nrhs + c)]);
      e.det = -e.det;
    }
    const Q piv = a[static_cast<std::size_t>(k * n + k)];
    e.det *= piv;
    for (int r = 0; r < n; ++r) {
      if (r == k) continue;
      const Q l = a[static_cast<std::size_t>(r * n + k)] / piv;
      if (l == 0) continue;
      for (int c = k; c < n; ++c)
        a[static_cast<std::size_t>(r * n + c)] -= l * a[static_cast<std::size_t>(k * n + c)];
      for (int c = 0; c < nrhs; ++c)
        b[static_cast<std::size_t>(r * nrhs + c)] -= l * b[static_cast<std::size_t>(k * nrhs + c)];
    }
  }
  e.x.resize(static_cast<std::size_t>(n * nrhs));
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < nrhs; ++c)
      e.x[static_cast<std::size_t>(r * nrhs + c)] =
          b[static_cast<std::size_t>(r * nrhs + c)] / a[static_cast<std::size_t>(r * n + r)];
  return e;
}

int exact_rank(QVec a, int rows, int cols) {
  int rank = 0;
  for (int c = 0; c < cols && rank < rows; ++c) {
    int p = rank;
    while (p < rows && a[static_cast<std::size_t>(p * cols + c)] == 0) ++p;
    if (p == rows) continue;
    for (int j = 0; j < cols; ++j)
      std::swap(a[static_cast<std::size_t>(rank * cols + j)],
                a[static_cast<std::size_t>(p * cols + j)]);
    for (int r = rank + 1; r < rows; ++r) {
      const Q l =
          a[static_cast<std::size_t>(r * cols + c)] / a[static_cast<std::size_t>(rank * cols + c)];
      for (int j = c; j < cols; ++j)
        a[static_cast<std::size_t>(r * cols + j)] -=
            l * a[static_cast<std::size_t>(rank * cols + j)];
    }
    ++rank;
  }
  return rank;
}

template <class T>
QVec to_q(const std::vector<T>& v) {
  QVec q;
  for (T x : v) q.emplace_back(double(x));
  return q;
}

QVec identity_q(int n) {
  QVec id(static_cast<std::size_t>(n * n), Q(0));
  for (int i = 0; i < n; ++i) id[static_cast<std::size_t>(i * n + i)] = 1;
  return id;
}

// Exact condition numbers of a nonsingular matrix in the infinity norm and the 1-norm.
struct Cond {
  double inf, one;
};
Cond exact_cond(const QVec& a, int n) {
  const Exact inv = exact_solve(a, n, identity_q(n), n);
  auto norm_inf = [n](const QVec& m) {
    Q best = 0;
    for (int r = 0; r < n; ++r) {
      Q s = 0;
      for (int c = 0; c < n; ++c) s += abs(m[static_cast<std::size_t>(r * n + c)]);
      if (s > best) best = s;
    }
    return best;
  };
  auto norm_one = [n](const QVec& m) {
    Q best = 0;
    for (int c = 0; c < n; ++c) {
      Q s = 0;
      for (int r = 0; r < n; ++r) s += abs(m[static_cast<std::size_t>(r * n + c)]);
      if (s > best) best = s;
    }
    return best;
  };
  return {Q(norm_inf(a) * norm_inf(inv.x)).get_d(), Q(norm_one(a) * norm_one(inv.x)).get_d()};
}

// max_i |x_i - exact_i| / max_i |exact_i|
template <class T>
double rel_error(const std::vector<T>& x, const QVec& exact) {
  Q num = 0, den = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    Q d = abs(Q(double(x[i])) - exact[i]);
    if (d > num) num = d;
    if (abs(exact[i]) > den) den = abs(exact[i]);
  }
  return den == 0 ? Q(num).get_d() : Q(num / den).get_d();
}

template <class T, int N>
std::vector<T> flat(const Mat<T, N, N>& m) {
  std::vector<T> v;
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) v.push_back(m.a[r][c]);
  return v;
}
template <class T, int N>
std::vector<T> flat(const Vec<T, N>& x) {
  std::vector<T> v;
  for (int i = 0; i < N; ++i) v.push_back(x[i]);
  return v;
}

template <class T>
std::vector<T> random_matrix(Rng& rng, int rows, int cols, bool integer) {
  std::vector<T> a(static_cast<std::size_t>(rows * cols));
  for (T& v : a) v = integer ? T(rng.uniform_int(-9, 9)) : rng.uniform<T>(-1, 1);
  return a;
}

template <class T, int N>
Mat<T, N, N> to_mat(const std::vector<T>& a) {
  Mat<T, N, N> m{};
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) m.a[r][c] = a[static_cast<std::size_t>(r * N + c)];
  return m;
}
template <class T, int N>
Vec<T, N> to_vec(const std::vector<T>& b) {
  Vec<T, N> v{};
  for (int i = 0; i < N; ++i) v[i] = b[static_cast<std::size_t>(i)];
  return v;
}

// One random system through every applicable solver, checked against the exact solution:
// forward error <= 16 n eps cond_inf (the GE bound c n eps cond with growth ~1 for random A).
template <class T, int N>
void check_fixed_system(Rng& rng, bool integer) {
  const std::vector<T> a = random_matrix<T>(rng, N, N, integer);
  const std::vector<T> b = random_matrix<T>(rng, N, 1, integer);
  const Exact ex = exact_solve(to_q(a), N, to_q(b), 1);
  const Mat<T, N, N> m = to_mat<T, N>(a);
  const Vec<T, N> v = to_vec<T, N>(b);
  const auto ge = solve(m, v);
  const auto dyn = solve(a, N, b);
  if (ex.singular) {
    // Exactly singular: exact zero pivot, or a pivot at rounding level that the condition
    // estimate flags (the factors are exact for A + E, ||E|| <= c n eps ||A||, so the
    // computed rcond is O(n eps)).
    EXPECT_TRUE(ge.near_singular) << "rcond " << ge.rcond;
    EXPECT_TRUE(ge.singular || ge.rcond <= tol<T>(64 * N)) << "rcond " << ge.rcond;
    if constexpr (N == 2 || N == 3) {
      // Small integers: the closed-form determinant is exact, so Cramer sees det == 0.
      if (integer) {
        EXPECT_TRUE(solve_cramer(m, v).singular);
      }
    }
    return;
  }
  const Cond cond = exact_cond(to_q(a), N);
  const double bound = double(tol<T>(16 * N)) * cond.inf;
  if (bound > 0.1) return;  // the error bound says nothing; near-singularity is tested apart
  EXPECT_EQ(ge.status, Status::ok);
  EXPECT_FALSE(ge.singular);
  EXPECT_LE(rel_error(flat(ge.x), ex.x), bound) << "cond " << cond.inf;
  EXPECT_LE(rel_error(dyn.x, ex.x), bound) << "cond " << cond.inf;
  // Same arithmetic in both layouts.
  EXPECT_EQ(flat(ge.x), dyn.x);
  EXPECT_NEAR(double(ge.determinant), ex.det.get_d(),
              double(tol<T>(16 * N)) * cond.inf * std::fabs(ex.det.get_d()));
  // The estimate is a lower bound on ||A^-1||_1, i.e. rcond_est >= rcond (up to rounding),
  // and within a small factor of it for random matrices.
  EXPECT_GE(double(ge.rcond), 1.0 / cond.one * (1 - 1e-3));
  EXPECT_LE(double(ge.rcond), 10.0 / cond.one);
  if constexpr (N == 2 || N == 3) {
    const auto cr = solve_cramer(m, v);
    EXPECT_EQ(cr.status, Status::ok);
    EXPECT_LE(rel_error(flat(cr.x), ex.x), 2 * bound) << "cond " << cond.inf;
    // Cramer's rcond is exact in the infinity norm (up to rounding of det and adjugate).
    EXPECT_NEAR(double(cr.rcond) * cond.inf, 1.0, double(tol<T>(64)) * cond.inf);
    EXPECT_EQ(cr.determinant, determinant(m));
  }
}

}  // namespace

// Figure 2.3: two equations in two unknowns have one solution, none (parallel lines) or
// infinitely many (the same line).
TYPED_TEST(LinearSystemTest, Figure2_3ThreeKindsOfTwoByTwoSystems) {
  using T = TypeParam;
  const Mat2<T> one = Mat2<T>::from_rows(Vec2<T>{1, 1}, Vec2<T>{1, -1});
  const Vec2<T> b1{2, 0};
  for (const auto& s : {solve_cramer(one, b1), solve(one, b1)}) {
    EXPECT_EQ(s.status, Status::ok);
    EXPECT_EQ(s.x, (Vec2<T>{1, 1}));
    EXPECT_EQ(s.determinant, T(-2));
    EXPECT_FALSE(s.near_singular);
  }
  // (b) parallel: x + y = 1, x + y = 2; (c) coincident: x + y = 1, 2x + 2y = 2.
  const Mat2<T> par = Mat2<T>::from_rows(Vec2<T>{1, 1}, Vec2<T>{1, 1});
  const Mat2<T> coin = Mat2<T>::from_rows(Vec2<T>{1, 1}, Vec2<T>{2, 2});
  const Vec2<T> bpar{1, 2}, bcoin{1, 2};
  for (const auto& s :
       {solve_cramer(par, bpar), solve(par, bpar), solve_cramer(coin, bcoin), solve(coin, bcoin)}) {
    EXPECT_EQ(s.status, Status::degenerate_input);
    EXPECT_TRUE(s.singular);
    EXPECT_TRUE(s.near_singular);
    EXPECT_EQ(s.x, (Vec2<T>{0, 0}));
    EXPECT_EQ(s.determinant, T(0));
  }
  // rank(A) < rank([A | b]): no solution; equal ranks below n: infinitely many.
  EXPECT_EQ(rank(par), 1);
  EXPECT_EQ(rank(Mat<T, 2, 3>::from_rows(Vec3<T>{1, 1, 1}, Vec3<T>{1, 1, 2})), 2);
  EXPECT_EQ(rank(coin), 1);
  EXPECT_EQ(rank(Mat<T, 2, 3>::from_rows(Vec3<T>{1, 1, 1}, Vec3<T>{2, 2, 2})), 1);
  EXPECT_EQ(rank(one), 2);
}

// Figure 2.2: the single equation 3 x1 + 2 x2 = 6 has a line of solutions: rank 1 < 2.
TYPED_TEST(LinearSystemTest, Figure2_2OneEquationTwoUnknowns) {
  using T = TypeParam;
  EXPECT_EQ(rank(Mat<T, 1, 2>{{{3, 2}}}), 1);
  EXPECT_EQ(rank(Mat<T, 1, 3>{{{3, 2, 6}}}), 1);  // consistent: augmented rank is also 1
  // As a square system padded with a zero row it is singular.
  EXPECT_TRUE(solve(Mat2<T>::from_rows(Vec2<T>{3, 2}, Vec2<T>{0, 0}), Vec2<T>{6, 0}).singular);
}

TYPED_TEST(LinearSystemTest, RandomSystemsMatchExactRationalSolution) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const bool integer = k % 2 == 0;
    check_fixed_system<T, 1>(rng, integer);
    check_fixed_system<T, 2>(rng, integer);
    check_fixed_system<T, 3>(rng, integer);
    check_fixed_system<T, 4>(rng, integer);
    check_fixed_system<T, 6>(rng, integer);
  }
}

TYPED_TEST(LinearSystemTest, SmallIntegerSingularSystemsAreDetected) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // Rank-deficient by construction: the last row is an integer combination of two others.
  for (int k = 0; k < 500; ++k) {
    Mat3<T> m{};
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 3; ++c) m.a[r][c] = T(rng.uniform_int(-9, 9));
    const T s = T(rng.uniform_int(-3, 3)), t = T(rng.uniform_int(-3, 3));
    for (int c = 0; c < 3; ++c) m.a[2][c] = s * m.a[0][c] + t * m.a[1][c];
    const Vec3<T> b{1, 2, 3};
    const auto cr = solve_cramer(m, b);
    EXPECT_TRUE(cr.singular);
    EXPECT_EQ(cr.x, (Vec3<T>{0, 0, 0}));
    const auto ge = solve(m, b);
    EXPECT_TRUE(ge.near_singular) << "rcond " << ge.rcond;
    std::vector<T> flat_m = flat(m);
    EXPECT_EQ(rank(m), exact_rank(to_q(flat_m), 3, 3));
  }
}

TYPED_TEST(LinearSystemTest, RunTimeSizesAndMultipleRightHandSides) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 150; ++k) {
    const int n = rng.uniform_int(1, 12);
    const int nrhs = rng.uniform_int(1, 4);
    const std::vector<T> a = random_matrix<T>(rng, n, n, k % 3 == 0);
    const std::vector<T> b = random_matrix<T>(rng, n, nrhs, false);
    const Exact ex = exact_solve(to_q(a), n, to_q(b), nrhs);
    if (ex.singular) continue;
    const Cond cond = exact_cond(to_q(a), n);
    const double bound = double(tol<T>(T(16 * n))) * cond.inf;
    if (bound > 0.1) continue;
    const auto s = solve(a, n, b, nrhs);
    ASSERT_EQ(s.status, Status::ok);
    ASSERT_EQ(s.x.size(), std::size_t(n * nrhs));
    EXPECT_LE(rel_error(s.x, ex.x), bound);
    // Each column is the single right-hand-side solve, bit for bit.
    const LuDynamic<T> f = lu_factor(a, n);
    for (int j = 0; j < nrhs; ++j) {
      std::vector<T> bj;
      for (int i = 0; i < n; ++i) bj.push_back(b[std::size_t(i * nrhs + j)]);
      const std::vector<T> xj = solve(f, bj);
      for (int i = 0; i < n; ++i) EXPECT_EQ(xj[std::size_t(i)], s.x[std::size_t(i * nrhs + j)]);
    }
    EXPECT_NEAR(double(determinant(a, n)), ex.det.get_d(),
                double(tol<T>(T(16 * n))) * cond.inf * std::fabs(ex.det.get_d()));
    // Inverse against the exact inverse.
    const auto inv = inverse(a, n);
    ASSERT_TRUE(inv.has_value());
    const Exact exinv = exact_solve(to_q(a), n, identity_q(n), n);
    EXPECT_LE(rel_error(*inv, exinv.x), bound);
  }
}

TYPED_TEST(LinearSystemTest, FixedSizeMultipleRightHandSidesInverseAndDeterminant) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 200; ++k) {
    const std::vector<T> a = random_matrix<T>(rng, 5, 5, false);
    const Mat<T, 5, 5> m = to_mat<T, 5>(a);
    Mat<T, 5, 2> b{};
    for (int r = 0; r < 5; ++r)
      for (int c = 0; c < 2; ++c) b.a[r][c] = rng.uniform<T>(-1, 1);
    const Cond cond = exact_cond(to_q(a), 5);
    const double bound = double(tol<T>(16 * 5)) * cond.inf;
    if (bound > 0.1) continue;
    const auto s = solve(m, b);
    ASSERT_EQ(s.status, Status::ok);
    for (int c = 0; c < 2; ++c) EXPECT_EQ(col(s.x, c), solve(m, col(b, c)).x);
    const auto inv = inverse(m);  // N = 5: elimination overload
    ASSERT_TRUE(inv.has_value());
    const Exact exinv = exact_solve(to_q(a), 5, identity_q(5), 5);
    EXPECT_LE(rel_error(flat(*inv), exinv.x), bound);
    const Exact ex = exact_solve(to_q(a), 5, identity_q(5), 5);
    EXPECT_NEAR(double(determinant(m)), ex.det.get_d(),
                double(tol<T>(16 * 5)) * cond.inf * std::fabs(ex.det.get_d()));
    // The pivoting inverse of a 3x3 agrees with mat.hpp's adjugate inverse.
    Mat3<T> m3{};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m3.a[r][c] = m.a[r][c];
    const auto i1 = inverse(m3);
    const auto i2 = solve(m3, Mat3<T>::identity());
    if (i1 && !i2.near_singular) {
      const Cond c3 = exact_cond(to_q(flat(m3)), 3);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(i1->a[r][c], i2.x.a[r][c], tol<T>(64) * T(c3.inf) * T(c3.inf));
    }
  }
  EXPECT_EQ(determinant(Mat<T, 1, 1>{{{T(-3)}}}), T(-3));
  EXPECT_EQ(inverse(Mat<T, 1, 1>{{{T(4)}}})->a[0][0], T(0.25));
  EXPECT_FALSE(inverse(Mat<T, 1, 1>{{{T(0)}}}).has_value());
  EXPECT_FALSE(inverse(Mat<T, 5, 5>{}).has_value());
}

TYPED_TEST(LinearSystemTest, HilbertMatricesAreReportedNearSingular) {
  using T = TypeParam;
  for (int n = 2; n <= 14; ++n) {
    SCOPED_TRACE(::testing::Message() << "n = " << n);
    std::vector<T> h(std::size_t(n * n));
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) h[std::size_t(r * n + c)] = T(1) / T(r + c + 1);
    const Cond cond = exact_cond(to_q(h), n);
    const LuDynamic<T> f = lu_factor(h, n);
    // Estimate vs truth; the threshold is n eps on rcond. Clear cases on either side must be
    // classified right (the estimate is within a small factor of the truth).
    const double measure = double(default_rcond_tolerance<T>(n)) * cond.one;
    if (measure > 30) {
      EXPECT_TRUE(f.near_singular) << "cond " << cond.one << " rcond " << f.rcond;
    }
    if (measure < 0.03) {
      EXPECT_FALSE(f.near_singular) << "cond " << cond.one << " rcond " << f.rcond;
    }
    // While the factorisation is accurate the estimate bounds rcond from above (it
    // underestimates ||A^-1||); beyond working precision it describes A + E instead.
    if (measure < 0.03) {
      EXPECT_GE(double(f.rcond), 1.0 / cond.one * (1 - 1e-3));
    }
  }
  // The 3x3 closed form flags a 3x3 matrix one ulp away from singular: det = eps exactly,
  // ||A||_inf ~ 2, ||A^-1||_inf ~ 2 / eps, so rcond ~ eps / 4.
  const Mat3<T> m =
      Mat3<T>::from_rows(Vec3<T>{1, 1, 0}, Vec3<T>{1, T(1) + eps_v<T>, 0}, Vec3<T>{0, 0, 1});
  EXPECT_EQ(determinant(m), eps_v<T>);
  const auto cr = solve_cramer(m, Vec3<T>{1, 1, 1});
  EXPECT_TRUE(cr.near_singular);
  EXPECT_FALSE(cr.singular);
  EXPECT_LE(cr.rcond, tol<T>(3));
  const auto ge = solve(m, Vec3<T>{1, 1, 1});
  EXPECT_TRUE(ge.near_singular);
  // A user tolerance moves the threshold (the relative scale is unchanged).
  EXPECT_FALSE(solve_cramer(m, Vec3<T>{1, 1, 1}, T(0)).near_singular);
}

TYPED_TEST(LinearSystemTest, RankOfRandomRankDeficientMatrices) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const int rows = rng.uniform_int(1, 8), cols = rng.uniform_int(1, 8);
    const int r = rng.uniform_int(0, std::min(rows, cols));
    // A = B C with B rows x r and C r x cols small integers: rank <= r, exactly known by GMP.
    std::vector<T> b = random_matrix<T>(rng, rows, r, true),
                   c = random_matrix<T>(rng, r, cols, true);
    std::vector<T> a(std::size_t(rows * cols), T(0));
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j)
        for (int p = 0; p < r; ++p)
          a[std::size_t(i * cols + j)] += b[std::size_t(i * r + p)] * c[std::size_t(p * cols + j)];
    const int exact = exact_rank(to_q(a), rows, cols);
    EXPECT_EQ(rank(a, rows, cols), exact) << rows << "x" << cols << " r=" << r;
    // Scale invariance.
    std::vector<T> as = a;
    for (T& v : as) v *= T(1e-20);
    EXPECT_EQ(rank(as, rows, cols), exact);
  }
  EXPECT_EQ(rank(Mat<T, 3, 4>{}), 0);
  EXPECT_EQ(rank(Mat<T, 4, 4>::identity()), 4);
  EXPECT_EQ(rank(Mat<T, 3, 5>::identity()), 3);
  EXPECT_EQ(rank(std::vector<T>{}, 0, 0), 0);
}

TYPED_TEST(LinearSystemTest, ZeroNaNInfAndOverflowInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  // Zero matrix.
  for (const auto& s :
       {solve(Mat3<T>{}, Vec3<T>{1, 2, 3}), solve_cramer(Mat3<T>{}, Vec3<T>{1, 2, 3})}) {
    EXPECT_TRUE(s.singular);
    EXPECT_EQ(s.status, Status::degenerate_input);
    EXPECT_EQ(s.determinant, T(0));
    EXPECT_EQ(s.x, (Vec3<T>{0, 0, 0}));
  }
  EXPECT_EQ(rank(Mat3<T>{}), 0);
  const auto zd = solve(std::vector<T>(16, T(0)), 4, std::vector<T>(4, T(1)));
  EXPECT_TRUE(zd.singular);
  EXPECT_EQ(zd.x, std::vector<T>(4, T(0)));
  // NaN / Inf in A or in b: flagged, zero solution, never garbage.
  Mat3<T> m = Mat3<T>::identity();
  m.a[1][2] = nan;
  for (const auto& s : {solve(m, Vec3<T>{1, 2, 3}), solve_cramer(m, Vec3<T>{1, 2, 3}),
                        solve(Mat3<T>::identity(), Vec3<T>{1, inf, 3}),
                        solve_cramer(Mat3<T>::identity(), Vec3<T>{nan, 0, 0})}) {
    EXPECT_EQ(s.status, Status::non_finite_input);
    EXPECT_TRUE(s.singular);
    EXPECT_TRUE(s.near_singular);
    EXPECT_EQ(s.x, (Vec3<T>{0, 0, 0}));
  }
  EXPECT_TRUE(std::isnan(solve(m, Vec3<T>{1, 2, 3}).determinant));
  EXPECT_EQ(rank(m), -1);
  std::vector<T> dm(9, T(0));
  dm[0] = dm[4] = dm[8] = T(1);
  dm[3] = inf;
  const auto dn = solve(dm, 3, std::vector<T>{1, 1, 1});
  EXPECT_EQ(dn.status, Status::non_finite_input);
  EXPECT_EQ(dn.x, std::vector<T>(3, T(0)));
  EXPECT_FALSE(inverse(dm, 3).has_value());
  EXPECT_EQ(rank(dm, 3, 3), -1);
  // A huge but perfectly conditioned matrix: the determinant overflows, the system is fine.
  const T big = std::numeric_limits<T>::max() / T(4);
  const auto hb = solve(Mat3<T>::identity() * big, Vec3<T>{big, -big, big});
  EXPECT_EQ(hb.status, Status::ok);
  EXPECT_FALSE(hb.singular);
  EXPECT_TRUE(std::isinf(hb.determinant));
  EXPECT_EQ(hb.x, (Vec3<T>{1, -1, 1}));
  // A solution that overflows is reported singular rather than returned as inf.
  const T tiny = std::numeric_limits<T>::min();
  const auto ov = solve(Mat2<T>::identity() * tiny, Vec2<T>{big, big});
  EXPECT_TRUE(ov.singular);
  EXPECT_EQ(ov.x, (Vec2<T>{0, 0}));
  // Empty run-time system.
  const auto e = solve(std::vector<T>{}, 0, std::vector<T>{});
  EXPECT_EQ(e.status, Status::ok);
  EXPECT_TRUE(e.x.empty());
  EXPECT_EQ(e.determinant, T(1));
}
