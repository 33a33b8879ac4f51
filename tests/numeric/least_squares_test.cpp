// SPDX-License-Identifier: BSL-1.0
// Tests for numeric/least_squares.hpp (row core.lstsq; figure 2.9): Householder QR with column
// pivoting and normal equations against the exact rational solution of the normal equations.
#include <locus/numeric/least_squares.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class LeastSquaresTest : public ::testing::Test {};
TYPED_TEST_SUITE(LeastSquaresTest, locus_test::RealTypes);

namespace {

using Q = mpq_class;
using L = long double;
constexpr LstsqMethod kMethods[] = {LstsqMethod::qr, LstsqMethod::normal_equations};

std::size_t idx(int r, int c, int cols) { return static_cast<std::size_t>(r * cols + c); }

// Exact solution of the (nonsingular) n x n rational system g y = h by Gauss-Jordan.
std::vector<Q> exact_solve(std::vector<Q> g, int n, std::vector<Q> h) {
  for (int k = 0; k < n; ++k) {
    int p = k;
    while (p < n && g[idx(p, k, n)] == 0) ++p;
    if (p == n) return {};  // singular: the caller skips this draw
    for (int c = 0; c < n; ++c) std::swap(g[idx(k, c, n)], g[idx(p, c, n)]);
    std::swap(h[static_cast<std::size_t>(k)], h[static_cast<std::size_t>(p)]);
    for (int r = 0; r < n; ++r) {
      if (r == k) continue;
      const Q l = g[idx(r, k, n)] / g[idx(k, k, n)];
      for (int c = k; c < n; ++c) g[idx(r, c, n)] -= l * g[idx(k, c, n)];
      h[static_cast<std::size_t>(r)] -= l * h[static_cast<std::size_t>(k)];
    }
  }
  for (int i = 0; i < n; ++i) h[static_cast<std::size_t>(i)] /= g[idx(i, i, n)];
  return h;
}

struct ExactLs {
  std::vector<Q> x;
  double residual;   // ||b - A x||
  double cond_gram;  // 1-norm condition number of A^T A (>= cond_2(A)^2 / n)
};

// Exact least-squares solution through the normal equations A^T A x = A^T b (A full rank).
template <class T>
ExactLs exact_ls(const std::vector<T>& a, int m, int n, const std::vector<T>& b) {
  std::vector<Q> g(static_cast<std::size_t>(n * n)), h(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      Q s = 0;
      for (int r = 0; r < m; ++r) s += Q(double(a[idx(r, i, n)])) * Q(double(a[idx(r, j, n)]));
      g[idx(i, j, n)] = s;
    }
    Q s = 0;
    for (int r = 0; r < m; ++r)
      s += Q(double(a[idx(r, i, n)])) * Q(double(b[static_cast<std::size_t>(r)]));
    h[static_cast<std::size_t>(i)] = s;
  }
  ExactLs e;
  e.x = exact_solve(g, n, h);
  if (e.x.empty()) return {{}, 0.0, std::numeric_limits<double>::infinity()};
  Q rr = 0;
  for (int r = 0; r < m; ++r) {
    Q s = Q(double(b[static_cast<std::size_t>(r)]));
    for (int c = 0; c < n; ++c) s -= Q(double(a[idx(r, c, n)])) * e.x[static_cast<std::size_t>(c)];
    rr += s * s;
  }
  e.residual = std::sqrt(rr.get_d());
  // cond_1(G) = ||G||_1 ||G^-1||_1 with the exact inverse (columns of G^-1 by solving).
  Q gn = 0, gin = 0;
  for (int c = 0; c < n; ++c) {
    Q s = 0;
    for (int r = 0; r < n; ++r) s += abs(g[idx(r, c, n)]);
    if (s > gn) gn = s;
    std::vector<Q> ec(static_cast<std::size_t>(n), Q(0));
    ec[static_cast<std::size_t>(c)] = 1;
    const std::vector<Q> col = exact_solve(g, n, ec);
    Q t = 0;
    for (const Q& v : col) t += abs(v);
    if (t > gin) gin = t;
  }
  e.cond_gram = Q(gn * gin).get_d();
  return e;
}

template <class T>
double max_abs_diff(const std::vector<T>& x, const std::vector<Q>& ex) {
  double d = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    d = std::fmax(d, std::fabs(Q(Q(double(x[i])) - ex[i]).get_d()));
  return d;
}
double max_abs(const std::vector<Q>& v) {
  double d = 0;
  for (const Q& q : v) d = std::fmax(d, std::fabs(q.get_d()));
  return d;
}

// Residual r = b - A x in long double, and A^T r.
template <class T>
std::vector<L> residual(const std::vector<T>& a, int m, int n, const std::vector<T>& b,
                        const std::vector<T>& x) {
  std::vector<L> r(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i) {
    L s = b[static_cast<std::size_t>(i)];
    for (int c = 0; c < n; ++c) s -= L(a[idx(i, c, n)]) * L(x[static_cast<std::size_t>(c)]);
    r[static_cast<std::size_t>(i)] = s;
  }
  return r;
}
L norm2(const std::vector<L>& v) {
  L s = 0;
  for (L x : v) s += x * x;
  return std::sqrt(s);
}
template <class T>
L frobenius(const std::vector<T>& a) {
  L s = 0;
  for (T x : a) s += L(x) * L(x);
  return std::sqrt(s);
}

}  // namespace

// Figure 2.9: the least-squares line y = m x + c through points. The four points deviate from
// y = 2x + 1 by +-1/2 with zero sum and zero first moment, so the exact fit is (m, c) = (2, 1)
// with residual norm sqrt(4 / 4) = 1.
TYPED_TEST(LeastSquaresTest, Figure2_9LineFitThroughPoints) {
  using T = TypeParam;
  const T xs[] = {-3, -1, 1, 3}, dev[] = {0.5, -0.5, -0.5, 0.5};
  std::vector<T> a, b;
  for (int i = 0; i < 4; ++i) {
    a.push_back(xs[i]);
    a.push_back(T(1));
    b.push_back(T(2) * xs[i] + T(1) + dev[i]);
  }
  for (LstsqMethod method : kMethods) {
    const LeastSquares<T> ls = least_squares(a, 4, 2, b, method);
    EXPECT_EQ(ls.status, Status::ok);
    EXPECT_EQ(ls.rank, 2);
    ASSERT_EQ(ls.x.size(), 2u);
    EXPECT_NEAR(ls.x[0], T(2), tol<T>(16));
    EXPECT_NEAR(ls.x[1], T(1), tol<T>(16));
    EXPECT_NEAR(ls.residual_norm, T(1), tol<T>(16));
  }
  // All points on the line: exact fit, zero residual.
  std::vector<T> bl;
  for (int i = 0; i < 4; ++i) bl.push_back(T(-0.5) * xs[i] + T(3));
  const LeastSquares<T> exact_fit = least_squares(a, 4, 2, bl);
  EXPECT_NEAR(exact_fit.x[0], T(-0.5), tol<T>(8));
  EXPECT_NEAR(exact_fit.x[1], T(3), tol<T>(8));
  EXPECT_LE(exact_fit.residual_norm, tol<T>(16, T(4)));
  // All points at the same x: the slope is undetermined (vertical line), rank 1.
  std::vector<T> av;
  for (int i = 0; i < 4; ++i) av.insert(av.end(), {T(2), T(1)});
  for (LstsqMethod method : kMethods) {
    const LeastSquares<T> ls = least_squares(av, 4, 2, b, method);
    EXPECT_EQ(ls.status, Status::degenerate_input);
    EXPECT_EQ(ls.rank, 1);
  }
}

TYPED_TEST(LeastSquaresTest, RandomTallSystemsMatchExactNormalEquations) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const int n = rng.uniform_int(1, 6), m = n + rng.uniform_int(0, 2 * n + 2);
    std::vector<T> a(static_cast<std::size_t>(m * n)), b(static_cast<std::size_t>(m));
    for (T& v : a) v = rng.uniform<T>(-1, 1);
    for (T& v : b) v = rng.uniform<T>(-1, 1);
    const ExactLs ex = exact_ls(a, m, n, b);
    const double xnorm = max_abs(ex.x);
    // LS perturbation theory: relative error <= c eps (kappa + kappa^2 ||r|| / (||A|| ||x||)).
    // kappa_2(A)^2 <= n cond_1(A^T A); write both terms with cond_gram (an upper bound).
    const double kappa2 = double(n) * ex.cond_gram;
    const double eta = ex.residual / (double(frobenius(a)) * xnorm + 1e-300);
    const double bound_qr = double(tol<T>(T(32 * m))) * (std::sqrt(kappa2) + kappa2 * eta) * xnorm;
    const double bound_ne = double(tol<T>(T(32 * m))) * kappa2 * (1 + eta) * xnorm;
    if (bound_ne > 0.01 * xnorm) continue;  // too ill-conditioned to say anything for T
    for (LstsqMethod method : kMethods) {
      SCOPED_TRACE(method == LstsqMethod::qr ? "qr" : "normal equations");
      const LeastSquares<T> ls = least_squares(a, m, n, b, method);
      ASSERT_EQ(ls.status, Status::ok);
      EXPECT_EQ(ls.rank, n);
      EXPECT_LE(max_abs_diff(ls.x, ex.x), method == LstsqMethod::qr ? bound_qr : bound_ne)
          << "m " << m << " n " << n << " cond(G) " << ex.cond_gram;
      // The residual is orthogonal to the column space (to the backward-error level), and the
      // reported norm matches ||b - A x|| and the exact minimum.
      const std::vector<L> r = residual(a, m, n, b, ls.x);
      const L anorm = frobenius(a);
      L xn = 0;
      for (T v : ls.x) xn += L(v) * L(v);
      const L scale = anorm * (norm2(r) + anorm * std::sqrt(xn) + frobenius(b));
      for (int c = 0; c < n; ++c) {
        L s = 0;
        for (int i = 0; i < m; ++i) s += L(a[idx(i, c, n)]) * r[static_cast<std::size_t>(i)];
        EXPECT_LE(double(std::fabs(s)), double(tol<T>(T(32 * m))) * double(scale) *
                                            (method == LstsqMethod::qr ? 1.0 : std::sqrt(kappa2)));
      }
      EXPECT_NEAR(double(ls.residual_norm), double(norm2(r)),
                  double(tol<T>(T(32 * m))) * double(anorm * std::sqrt(xn) + frobenius(b)));
      EXPECT_NEAR(double(ls.residual_norm), ex.residual,
                  double(tol<T>(T(32 * m))) * double(anorm * std::sqrt(xn) + frobenius(b)) *
                      (method == LstsqMethod::qr ? 1.0 : std::sqrt(kappa2)));
    }
  }
}

TYPED_TEST(LeastSquaresTest, ExactFitWhenRightHandSideIsInTheRange) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const int n = rng.uniform_int(1, 5), m = n + rng.uniform_int(0, 6);
    // Small integers: b = A x_true is computed exactly.
    std::vector<T> a(static_cast<std::size_t>(m * n)), xt(static_cast<std::size_t>(n)),
        b(static_cast<std::size_t>(m), T(0));
    for (T& v : a) v = T(rng.uniform_int(-8, 8));
    for (T& v : xt) v = T(rng.uniform_int(-8, 8));
    for (int i = 0; i < m; ++i)
      for (int c = 0; c < n; ++c)
        b[static_cast<std::size_t>(i)] += a[idx(i, c, n)] * xt[static_cast<std::size_t>(c)];
    const LeastSquares<T> probe = least_squares(a, m, n, b);
    if (probe.rank < n) continue;  // the random integer matrix happened to be rank deficient
    const ExactLs ex = exact_ls(a, m, n, b);
    if (ex.x.empty()) continue;
    EXPECT_EQ(ex.residual, 0.0);
    const double kappa = std::sqrt(double(n) * ex.cond_gram);
    const LeastSquares<T> ls = least_squares(a, m, n, b);
    EXPECT_LE(double(ls.residual_norm), double(tol<T>(T(32 * m))) * double(frobenius(b)) * kappa);
    for (int c = 0; c < n; ++c)
      EXPECT_NEAR(double(ls.x[static_cast<std::size_t>(c)]),
                  double(xt[static_cast<std::size_t>(c)]), double(tol<T>(T(32 * m))) * kappa * 8);
  }
}

TYPED_TEST(LeastSquaresTest, QrStaysAccurateWhereNormalEquationsSquareTheCondition) {
  using T = TypeParam;
  // Columns 1 and 1 + d (Laeuchli-like): cond(A) ~ 1 / d, cond(A^T A) ~ 1 / d^2.
  // d is chosen so that cond(A^T A) eps stays well below the normal equations' rank threshold
  // (16 m eps): float d = 2^-5 (cond(A) ~ 1e2), double d = 2^-16 (cond(A) ~ 1e5).
  const T d = std::is_same_v<T, float> ? T(1.0 / 32) : T(1.0 / 65536);
  const int m = 6, n = 2;
  std::vector<T> a, b;
  for (int i = 0; i < m; ++i) {
    const T t = T(i) / T(m - 1);
    a.push_back(T(1));
    a.push_back(T(1) + d * t);
    b.push_back(T(3) + T(-1) * (T(1) + d * t));  // x = (3, -1), exactly in the range
  }
  const ExactLs ex = exact_ls(a, m, n, b);
  const double kappa = std::sqrt(double(n) * ex.cond_gram);
  const LeastSquares<T> qr = least_squares(a, m, n, b, LstsqMethod::qr);
  EXPECT_EQ(qr.rank, 2);
  EXPECT_LE(max_abs_diff(qr.x, ex.x), double(tol<T>(T(64))) * kappa * 3);
  // The normal equations are allowed a kappa^2 error; they must keep the rank here and be
  // accurate to that bound.
  const LeastSquares<T> ne = least_squares(a, m, n, b, LstsqMethod::normal_equations);
  EXPECT_EQ(ne.rank, 2);
  EXPECT_LE(max_abs_diff(ne.x, ex.x), double(tol<T>(T(64))) * kappa * kappa * 3);
}

TYPED_TEST(LeastSquaresTest, RankDeficientColumnsAreReported) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 300; ++k) {
    const int r = rng.uniform_int(1, 4), extra = rng.uniform_int(1, 3), n = r + extra;
    const int m = n + rng.uniform_int(1, 5);
    // Independent columns B (random reals), then integer combinations of them.
    std::vector<T> bcols(static_cast<std::size_t>(m * r));
    for (T& v : bcols) v = rng.uniform<T>(-1, 1);
    std::vector<T> a(static_cast<std::size_t>(m * n), T(0));
    std::vector<int> coef(static_cast<std::size_t>(extra * r));
    for (int& c : coef) c = rng.uniform_int(-2, 2);
    for (int i = 0; i < m; ++i) {
      for (int c = 0; c < r; ++c) a[idx(i, c, n)] = bcols[idx(i, c, r)];
      for (int e = 0; e < extra; ++e) {
        // Combination of two columns with small integer weights: exact in T? Not in general,
        // so the dependent column is exact only to rounding - what real data looks like.
        T s = T(0);
        for (int c = 0; c < r; ++c) s += T(coef[idx(e, c, r)]) * bcols[idx(i, c, r)];
        a[idx(i, r + e, n)] = s;
      }
    }
    std::vector<T> b(static_cast<std::size_t>(m));
    for (T& v : b) v = rng.uniform<T>(-1, 1);
    const ExactLs ex = exact_ls(bcols, m, r, b);
    if (ex.x.empty()) continue;
    const double kappa2 = double(r) * ex.cond_gram;
    if (double(tol<T>(T(32 * m))) * kappa2 > 1e-3) continue;
    for (LstsqMethod method : kMethods) {
      SCOPED_TRACE(method == LstsqMethod::qr ? "qr" : "normal equations");
      const LeastSquares<T> ls = least_squares(a, m, n, b, method);
      EXPECT_EQ(ls.status, Status::degenerate_input);
      EXPECT_EQ(ls.rank, r);
      // Any basic solution reaches the minimum residual of the column space.
      const std::vector<L> res = residual(a, m, n, b, ls.x);
      EXPECT_NEAR(double(norm2(res)), ex.residual, double(tol<T>(T(64 * m))) * kappa2 * 4);
      EXPECT_NEAR(double(ls.residual_norm), ex.residual, double(tol<T>(T(64 * m))) * kappa2 * 4);
      int zeros = 0;
      for (T v : ls.x) zeros += v == T(0);
      EXPECT_GE(zeros, extra);
    }
  }
}

TYPED_TEST(LeastSquaresTest, DegenerateAndInvalidInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  // Figure 2.2 as least squares: one equation 3 x1 + 2 x2 = 6, m < n. A basic solution on the
  // line, zero residual, rank 1.
  for (LstsqMethod method : kMethods) {
    const LeastSquares<T> ls = least_squares(std::vector<T>{3, 2}, 1, 2, std::vector<T>{6}, method);
    EXPECT_EQ(ls.status, Status::degenerate_input);
    EXPECT_EQ(ls.rank, 1);
    EXPECT_NEAR(T(3) * ls.x[0] + T(2) * ls.x[1], T(6), tol<T>(16, T(6)));
    EXPECT_LE(ls.residual_norm, tol<T>(16, T(6)));
  }
  // Zero matrix: rank 0, x = 0, residual ||b||.
  for (LstsqMethod method : kMethods) {
    const LeastSquares<T> z =
        least_squares(std::vector<T>(6, T(0)), 3, 2, std::vector<T>{3, 0, 4}, method);
    EXPECT_EQ(z.status, Status::degenerate_input);
    EXPECT_EQ(z.rank, 0);
    EXPECT_EQ(z.x, std::vector<T>(2, T(0)));
    EXPECT_NEAR(z.residual_norm, T(5), tol<T>(4, T(5)));
  }
  // Empty.
  const LeastSquares<T> e = least_squares(std::vector<T>{}, 0, 2, std::vector<T>{});
  EXPECT_EQ(e.status, Status::empty_input);
  EXPECT_EQ(e.x, std::vector<T>(2, T(0)));
  EXPECT_EQ(least_squares(std::vector<T>{}, 3, 0, std::vector<T>{1, 2, 3}).status,
            Status::empty_input);
  // Non-finite.
  const LeastSquares<T> n1 =
      least_squares(std::vector<T>{1, nan, 0, 1}, 2, 2, std::vector<T>{1, 1});
  EXPECT_EQ(n1.status, Status::non_finite_input);
  EXPECT_EQ(n1.x, std::vector<T>(2, T(0)));
  EXPECT_TRUE(std::isnan(n1.residual_norm));
  EXPECT_EQ(least_squares(std::vector<T>{1, 0, 0, 1}, 2, 2, std::vector<T>{inf, 1}).status,
            Status::non_finite_input);
  // Huge entries: the column norms are overflow-safe.
  const T big = std::numeric_limits<T>::max() / T(8);
  const LeastSquares<T> h = least_squares(std::vector<T>{big, big}, 2, 1, std::vector<T>{big, big});
  EXPECT_EQ(h.status, Status::ok);
  EXPECT_NEAR(h.x[0], T(1), tol<T>(8));
}

TYPED_TEST(LeastSquaresTest, PowerOfTwoScalingAndRowOrderInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 200; ++k) {
    const int n = rng.uniform_int(1, 4), m = n + rng.uniform_int(0, 5);
    std::vector<T> a(static_cast<std::size_t>(m * n)), b(static_cast<std::size_t>(m));
    for (T& v : a) v = rng.uniform<T>(-1, 1);
    for (T& v : b) v = rng.uniform<T>(-1, 1);
    const LeastSquares<T> ls = least_squares(a, m, n, b);
    if (ls.rank < n) continue;
    // Scaling A by 2^-20 and b by 2^10 is exact, so x scales by 2^30 exactly.
    std::vector<T> as = a, bs = b;
    for (T& v : as) v = std::ldexp(v, -20);
    for (T& v : bs) v = std::ldexp(v, 10);
    const LeastSquares<T> s = least_squares(as, m, n, bs);
    for (int c = 0; c < n; ++c)
      EXPECT_EQ(s.x[static_cast<std::size_t>(c)],
                std::ldexp(ls.x[static_cast<std::size_t>(c)], 30));
    EXPECT_EQ(s.residual_norm, std::ldexp(ls.residual_norm, 10));
    // Reversing the rows is an orthogonal change of the residual space: same solution.
    std::vector<T> ar, br;
    for (int i = m - 1; i >= 0; --i) {
      for (int c = 0; c < n; ++c) ar.push_back(a[idx(i, c, n)]);
      br.push_back(b[static_cast<std::size_t>(i)]);
    }
    const LeastSquares<T> rv = least_squares(ar, m, n, br);
    const ExactLs ex = exact_ls(a, m, n, b);
    const double kappa2 = double(n) * ex.cond_gram;
    const double xnorm = max_abs(ex.x);
    const double eta = ex.residual / (double(frobenius(a)) * xnorm + 1e-300);
    const double bound = double(tol<T>(T(64 * m))) * (std::sqrt(kappa2) + kappa2 * eta) * xnorm;
    for (int c = 0; c < n; ++c)
      EXPECT_NEAR(double(rv.x[static_cast<std::size_t>(c)]),
                  double(ls.x[static_cast<std::size_t>(c)]), bound);
  }
}
