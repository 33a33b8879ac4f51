// SPDX-License-Identifier: BSL-1.0
// Tests for numeric/roots.hpp (row num.roots; book appendix A, figures A.9, A.10).
//
// Oracle: exact rational arithmetic (GMP). Test polynomials are built from chosen roots, expanded
// exactly, rounded to T; the solver is judged against the EXACT roots of the rounded polynomial
// (what it was given): an independent exact Sturm chain counts them ("no lost roots") and exact
// bisection locates them (relative error). Multiple roots are checked on polynomials whose
// coefficients are exactly representable, so the multiplicity is a fact, not a rounding accident.
#include <locus/numeric/roots.hpp>

#include "numeric/poly_oracle.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace po = poly_oracle;
using Q = po::Q;

template <class T>
class RootsTest : public ::testing::Test {};
TYPED_TEST_SUITE(RootsTest, locus_test::RealTypes);

namespace {

// Dispatch to the fixed-degree solver matching the coefficient count (low to high).
template <class T>
RootsResult<T> solve(const std::vector<T>& c) {
  std::vector<T> p = c;
  p.resize(5, T(0));
  switch (c.size()) {
    case 2:
      return solve_linear(p[0], p[1]);
    case 3:
      return solve_quadratic(p[0], p[1], p[2]);
    case 4:
      return solve_cubic(p[0], p[1], p[2], p[3]);
    default:
      return solve_quartic(p[0], p[1], p[2], p[3], p[4]);
  }
}

// Sorted roots with a minimum gap, scaled by 10^e.
std::vector<double> separated_roots(Rng& rng, int n, double gap, double scale) {
  for (;;) {
    std::vector<double> r;
    for (int i = 0; i < n; ++i) r.push_back(rng.uniform<double>(-10, 10));
    std::sort(r.begin(), r.end());
    bool ok = true;
    for (int i = 1; i < n; ++i) ok = ok && r[i] - r[i - 1] >= gap;
    if (!ok) continue;
    for (double& x : r) x *= scale;
    return r;
  }
}

template <class T>
double rel_tol_simple() {
  // double: the target. float: the answer is computed in double and rounded once to
  // float, so one float ulp (eps) relative.
  return std::is_same_v<T, double> ? 1e-12 : double(eps_v<float>);
}

double g_max_rel_err[2] = {0, 0};  // [float, double], printed for the report

}  // namespace

TYPED_TEST(RootsTest, WellSeparatedRandomRootsAreAllFoundAccurately) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  double max_err = 0;
  int lost = 0, total = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int n = 1 + trial % 4;
    const double scale = std::pow(10.0, rng.uniform_int(-4, 4));
    const auto r = separated_roots(rng, n, 0.5, scale);
    std::vector<Q> qr;
    for (double x : r) qr.emplace_back(x);
    const Q lead(rng.uniform<double>(0.5, 2.0) * (trial % 3 == 0 ? -1 : 1) *
                 std::pow(10.0, rng.uniform_int(-6, 6)));
    const auto c = po::round_to<T>(po::expand(qr, lead));
    const po::QPoly exact = po::exact_of(c);
    // Oracle count of distinct real roots of the rounded polynomial on the whole line.
    const po::Sturm st(exact);
    const Q big(1e6 * scale);
    const int expected = st.count(-big, big);
    const auto res = solve<T>(c);
    ASSERT_EQ(res.status, Status::ok);
    ASSERT_EQ(res.count, expected) << "trial " << trial;
    total += expected;
    for (const auto& root : res) {
      EXPECT_EQ(root.multiplicity, 1);
      double ex;
      ASSERT_TRUE(po::exact_root_near(exact, double(root.value), ex)) << root.value;
      const double err = std::abs(double(root.value) - ex) / std::abs(ex);
      max_err = std::max(max_err, err);
      EXPECT_LE(err, rel_tol_simple<T>()) << "root " << root.value << " exact " << ex;
    }
    for (int i = 1; i < res.count; ++i) EXPECT_LT(res.roots[i - 1].value, res.roots[i].value);
    lost += expected - res.count;
  }
  g_max_rel_err[std::is_same_v<T, double>] =
      std::max(g_max_rel_err[std::is_same_v<T, double>], max_err);
  std::printf(
      "[roots] %s: %d roots of random well-separated polynomials (deg 1-4), lost %d, "
      "max relative error %.3g\n",
      std::is_same_v<T, double> ? "double" : "float", total, lost, max_err);
}

TYPED_TEST(RootsTest, RandomQuarticsWithComplexRootsCountMatchesSturm) {
  // Real factors times irreducible quadratics: 0, 2 or 4 real roots; the exact count of the
  // rounded polynomial decides, and every reported root is a genuine sign change.
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 300; ++trial) {
    const int nreal = 2 * (trial % 3);
    const auto r = separated_roots(rng, nreal == 0 ? 1 : nreal, 0.5, 1.0);
    std::vector<Q> qr;
    for (int i = 0; i < nreal; ++i) qr.emplace_back(r[static_cast<std::size_t>(i)]);
    po::QPoly p = po::expand(qr, Q(1));
    for (int k = nreal; k < 4; k += 2) {
      const Q re(rng.uniform<double>(-5, 5)), im(rng.uniform<double>(0.2, 5));
      p = po::mul(p, po::QPoly{re * re + im * im, -2 * re, Q(1)});
    }
    const auto c = po::round_to<T>(p);
    const po::QPoly exact = po::exact_of(c);
    const int expected = po::Sturm(exact).count(Q(-1e6), Q(1e6));
    const auto res = solve<T>(c);
    ASSERT_EQ(res.count, expected) << "trial " << trial;
    for (const auto& root : res) {
      double ex;
      ASSERT_TRUE(po::exact_root_near(exact, double(root.value), ex));
      EXPECT_LE(std::abs(double(root.value) - ex), rel_tol_simple<T>() * std::abs(ex));
    }
  }
}

TYPED_TEST(RootsTest, ExactMultipleRootsHaveTheirMultiplicity) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // Roots k/8 with small k: every coefficient of the expansion is exact in float and double.
  const std::vector<std::vector<int>> patterns = {{2},       {3},    {4},    {2, 1},
                                                  {2, 1, 1}, {3, 1}, {2, 2}, {1, 1}};
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const auto& pat = patterns[static_cast<std::size_t>(trial) % patterns.size()];
    std::vector<int> ks;
    while (ks.size() < pat.size()) {
      const int k = rng.uniform_int(-24, 24);
      if (std::find(ks.begin(), ks.end(), k) == ks.end()) ks.push_back(k);
    }
    std::vector<Q> qr;
    for (std::size_t i = 0; i < pat.size(); ++i)
      for (int m = 0; m < pat[i]; ++m) qr.push_back(po::frac(ks[i], 8));
    const po::QPoly p = po::expand(qr, po::frac(rng.uniform_int(1, 9), 4));
    const auto c = po::round_to<T>(p);
    if (po::exact_of(c) != p) continue;  // not exactly representable: not a multiplicity test
    ++checked;
    const auto res = solve<T>(c);
    ASSERT_EQ(res.status, Status::ok);
    ASSERT_EQ(res.count, static_cast<int>(pat.size())) << "trial " << trial;
    for (std::size_t i = 0; i < pat.size(); ++i) {
      // Find the returned root for ks[i].
      const double want = ks[i] / 8.0;
      const Root<T>* best = nullptr;
      for (const auto& root : res)
        if (!best || std::abs(double(root.value) - want) < std::abs(double(best->value) - want))
          best = &root;
      ASSERT_NE(best, nullptr);
      EXPECT_EQ(best->multiplicity, pat[i]) << "root " << want;
      // A root of multiplicity m is conditioned like eps^(1/m); exact data and twice-precision
      // evaluation leave an error of a few ulps for m <= 2 and about eps^(1/2) for m = 3, 4.
      const double k = pat[i] <= 2 ? 1e-14 : 1e-7;
      EXPECT_LE(std::abs(double(best->value) - want),
                std::max(k, double(tol<T>(4))) * (1 + std::abs(want)));
    }
  }
  EXPECT_GT(checked, 200);
}

TYPED_TEST(RootsTest, ClusteredRootsAreNeverLost) {
  // Clusters such as (x-1)^3 (x-1-1e-7): the rounded polynomial's real roots (exact oracle) must
  // each lie near a returned root; the returned multiplicities there add up to at least the
  // number of exact roots there; every returned root is genuine: a sign change of the rounded
  // polynomial nearby, or |p(r)| (exact) within the documented noise level.
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  struct Case {
    std::vector<double> roots;
  };
  std::vector<Case> cases = {{{1, 1, 1, 1 + 1e-7}},
                             {{1, 1, 1 + 1e-9, -2}},
                             {{1, 1, 1, 1}},
                             {{0.1, 0.1, 0.1 + 1e-6, -5}},
                             {{-3, -3 + 1e-8, 2, 2 + 1e-8}},
                             {{1, 1 + 1e-12}},
                             {{1e-5, 1e-5 + 1e-12, 1e-5 + 2e-12}}};
  for (int i = 0; i < 60; ++i) {
    const double c = rng.uniform<double>(-4, 4), d = std::pow(10.0, rng.uniform_int(-12, -3));
    const int n = rng.uniform_int(2, 4);
    std::vector<double> r;
    for (int k = 0; k < n; ++k) r.push_back(c + k * d * rng.uniform<double>(0, 1));
    if (n < 4) r.push_back(rng.uniform<double>(-4, 4));
    cases.push_back({r});
  }
  for (const auto& cs : cases) {
    std::vector<Q> qr;
    for (double x : cs.roots) qr.emplace_back(x);
    const auto c = po::round_to<T>(po::expand(qr, Q(1)));
    const po::QPoly exact = po::exact_of(c);
    const int n = static_cast<int>(exact.size()) - 1;
    const auto res = solve<T>(c);
    ASSERT_EQ(res.status, Status::ok);
    EXPECT_LE(res.total_multiplicity(), n);
    // Exact roots of the rounded polynomial.
    std::vector<double> ex;
    po::isolate(po::Sturm(exact), Q(-100), Q(100), Q(1e-20), ex);
    // A cluster of m roots spreads to about (noise)^(1/m): 1e-3 covers m <= 4 at this scale in
    // double; in float the coefficients themselves are rounded to 6e-8, so (6e-8)^(1/4) ~ 0.02.
    const double radius = std::is_same_v<T, double> ? 2e-3 : 0.1;
    for (double e : ex) {
      int near_mult = 0, near_exact = 0;
      for (const auto& root : res)
        if (std::abs(double(root.value) - e) <= radius * (1 + std::abs(e)))
          near_mult += root.multiplicity;
      for (double e2 : ex)
        if (std::abs(e2 - e) <= radius * (1 + std::abs(e))) ++near_exact;
      EXPECT_GE(near_mult, 1) << "exact root " << e << " lost";
      EXPECT_GE(near_mult, near_exact) << "near " << e;
    }
    for (const auto& root : res) {
      double e;
      const bool sign_change = po::exact_root_near(exact, double(root.value), e) &&
                               std::abs(e - double(root.value)) <= radius * (1 + std::abs(e));
      if (!sign_change) {
        // Touching root: |p(r)| within the noise level 16 n eps sum |a_i||r|^i (the engine
        // uses gamma_{2n+1} at the scaled critical point; rounding r to T adds a little).
        const Q x(double(root.value));
        Q abs_sum = 0, xa = abs(x), pw = 1;
        for (const Q& a : exact) {
          abs_sum += abs(a) * pw;
          pw *= xa;
        }
        const double bound = 16.0 * n * double(eps_v<T>) * abs_sum.get_d();
        EXPECT_LE(std::abs(po::eval(exact, x).get_d()), bound)
            << "spurious root " << root.value << " of " << ::testing::PrintToString(cs.roots)
            << " coefficients " << ::testing::PrintToString(c) << " res "
            << ::testing::PrintToString(
                   std::vector<double>{double(res.roots[0].value), double(res.roots[1].value),
                                       double(res.roots[2].value), double(res.count)});
        EXPECT_GE(root.multiplicity, 2);
      }
    }
  }
}

TYPED_TEST(RootsTest, FixedCasesFromTheBookAndTextbook) {
  using T = TypeParam;
  // Figure A.9: f(x) = x^3 + 6x^2 - 7x + 19 on [-8, 3]: one real root, near -7.3126.
  const auto f = solve_cubic(T(19), T(-7), T(6), T(1));
  ASSERT_EQ(f.count, 1);
  double ex;
  ASSERT_TRUE(po::exact_root_near(po::QPoly{19, -7, 6, 1}, double(f.roots[0].value), ex));
  EXPECT_NEAR(double(f.roots[0].value), ex, double(tol<T>(1, 8)));
  EXPECT_GE(f.roots[0].value, T(-8));
  // The figure's window through the general solver: the same single root, and none in [-7, 3].
  const Polynomial<T> fp{T(19), T(-7), T(6), T(1)};
  const auto w = real_roots(fp, T(-8), T(3));
  ASSERT_EQ(static_cast<int>(w.roots.size()), 1);
  RootOptions exact;  // real_roots' default: correctly rounded, which for float can differ from
                      // near mode's double root rounded to float by an ulp
  EXPECT_EQ(w.roots[0].value, solve_cubic(T(19), T(-7), T(6), T(1), exact).roots[0].value);
  EXPECT_EQ(static_cast<int>(real_roots(fp, T(-7), T(3)).roots.size()), 0);
  // Closed interval: roots at both ends of [1, 2] of (x - 1)(x - 2) are included.
  EXPECT_EQ(static_cast<int>(real_roots(Polynomial<T>{T(2), T(-3), T(1)}, T(1), T(2)).roots.size()),
            2);
  // Figure A.10: f'(x) = 3x^2 + 12x - 7: roots -2 -+ sqrt(228)/6 (both in [-8, 3]).
  const auto d = solve_quadratic(T(-7), T(12), T(3));
  ASSERT_EQ(d.count, 2);
  const long double s = std::sqrt(228.0L) / 6.0L;
  EXPECT_NEAR(double(d.roots[0].value), double(-2.0L - s), double(tol<T>(2, 5)));
  EXPECT_NEAR(double(d.roots[1].value), double(-2.0L + s), double(tol<T>(2, 1)));
  // Cancellation-prone quadratic: x^2 - 1e8 x + 1 has roots 1e8 and 1e-8 (to 1e-16 relative).
  const auto q = solve_quadratic(T(1), T(-1e8), T(1));
  ASSERT_EQ(q.count, 2);
  EXPECT_NEAR(double(q.roots[0].value), 1e-8, 1e-8 * double(tol<T>(2)));
  EXPECT_NEAR(double(q.roots[1].value), 1e8, 1e8 * double(tol<T>(2)));
  // Depressed and biquadratic quartics.
  const auto b = solve_quartic(T(4), T(0), T(-5), T(0), T(1));  // (x^2-1)(x^2-4)
  ASSERT_EQ(b.count, 4);
  const T want[4] = {-2, -1, 1, 2};
  for (int i = 0; i < 4; ++i) EXPECT_EQ(b.roots[i].value, want[i]);
  EXPECT_EQ(solve_quartic(T(1), T(0), T(0), T(0), T(1)).count, 0);  // x^4 + 1
  const auto z = solve_quartic(T(0), T(0), T(0), T(0), T(3));       // 3 x^4
  ASSERT_EQ(z.count, 1);
  EXPECT_EQ(z.roots[0].value, T(0));
  EXPECT_EQ(z.roots[0].multiplicity, 4);
}

TYPED_TEST(RootsTest, LeadingZerosTinyLeadingAndScaling) {
  using T = TypeParam;
  // Exact zero leading coefficients drop the degree.
  const auto a = solve_quartic(T(-6), T(11), T(-6), T(1), T(0));  // (x-1)(x-2)(x-3)
  ASSERT_EQ(a.count, 3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.roots[i].value, T(i + 1), tol<T>(4, 3));
  const auto l = solve_quartic(T(-2), T(4), T(0), T(0), T(0));
  ASSERT_EQ(l.count, 1);
  EXPECT_EQ(l.roots[0].value, T(0.5));
  // A tiny leading coefficient is data: 1e-20 x^2 + x - 1 has roots near 1 and -1e20.
  const T tiny = std::is_same_v<T, double> ? T(1e-20) : T(1e-12);
  const auto t = solve_quadratic(T(-1), T(1), tiny);
  ASSERT_EQ(t.count, 2);
  EXPECT_NEAR(t.roots[0].value / (-T(1) / tiny), T(1), tol<T>(4));
  EXPECT_NEAR(t.roots[1].value, T(1), tol<T>(4));
  // Scaling the polynomial or the variable by huge/tiny powers of ten changes nothing relative.
  const int emax = std::is_same_v<T, double> ? 300 : 30;
  const int xmax = std::is_same_v<T, double> ? 70 : 7;
  for (int e : {-emax, -emax / 2, emax / 2, emax}) {
    const T s = static_cast<T>(std::pow(10.0, e));
    const auto r = solve_quartic(T(24) * s, T(-50) * s, T(35) * s, T(-10) * s, T(1) * s);
    ASSERT_EQ(r.count, 4) << e;
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.roots[i].value, T(i + 1), tol<T>(64, 4)) << e;
  }
  for (int e : {-xmax, -xmax / 2, xmax / 2, xmax}) {
    // Roots 1, 2, 3, 4 times s: coefficients 24 s^4, -50 s^3, 35 s^2, -10 s, 1.
    const double s = std::pow(10.0, e);
    std::vector<Q> qr = {Q(s), Q(2 * s), Q(3 * s), Q(4 * s)};
    const auto c = po::round_to<T>(po::expand(qr, Q(1)));
    const auto r = solve_quartic(c[0], c[1], c[2], c[3], c[4]);
    ASSERT_EQ(r.count, 4) << e;
    const po::QPoly exact = po::exact_of(c);
    for (int i = 0; i < 4; ++i) {
      double ex;
      ASSERT_TRUE(po::exact_root_near(exact, double(r.roots[i].value), ex));
      EXPECT_LE(std::abs(double(r.roots[i].value) - ex), rel_tol_simple<T>() * std::abs(ex)) << e;
    }
  }
}

TYPED_TEST(RootsTest, BadInputHasADocumentedStatusAndNoRoots) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  for (int pos = 0; pos < 5; ++pos)
    for (T bad : {nan, inf, -inf}) {
      T c[5] = {1, -2, 3, 1, 1};
      c[pos] = bad;
      const auto r = solve_quartic(c[0], c[1], c[2], c[3], c[4]);
      EXPECT_EQ(r.status, Status::non_finite_input);
      EXPECT_EQ(r.count, 0);
    }
  EXPECT_EQ(solve_quadratic(T(0), nan, T(1)).status, Status::non_finite_input);
  EXPECT_EQ(solve_linear(inf, T(1)).status, Status::non_finite_input);
  // The zero polynomial: every x is a root.
  const auto z = solve_quartic(T(0), T(0), T(0), T(0), T(0));
  EXPECT_EQ(z.status, Status::degenerate_input);
  EXPECT_EQ(z.count, 0);
  EXPECT_EQ(solve_linear(T(0), T(0)).status, Status::degenerate_input);
  // A non-zero constant: no roots, and that is a valid answer.
  const auto k = solve_cubic(T(5), T(0), T(0), T(0));
  EXPECT_EQ(k.status, Status::ok);
  EXPECT_EQ(k.count, 0);
  // Extreme but finite coefficients never hang nor leak NaN.
  const T big = std::numeric_limits<T>::max(), small = std::numeric_limits<T>::denorm_min();
  for (const auto& r :
       {solve_quartic(small, T(0), T(0), T(0), big), solve_quartic(big, -big, big, -big, small),
        solve_quartic(small, small, -big, T(1), T(1)), solve_quadratic(-big, T(0), small)}) {
    EXPECT_TRUE(r.status == Status::ok);
    for (const auto& root : r) EXPECT_TRUE(is_finite(root.value));
  }
  Polynomial<T> p{T(1), nan, T(2)};
  EXPECT_EQ(real_roots(p).status, Status::non_finite_input);
  EXPECT_EQ(real_roots(Polynomial<T>{}).status, Status::degenerate_input);
}

TYPED_TEST(RootsTest, GeneralDegreeRealRootsAgainstSturmAndExactBisection) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 60; ++trial) {
    const int nreal = rng.uniform_int(1, std::is_same_v<T, double> ? 9 : 6);
    const auto r = separated_roots(rng, nreal, 1.0, 1.0);
    std::vector<Q> qr;
    for (double x : r) qr.emplace_back(x);
    po::QPoly p = po::expand(qr, Q(1));
    for (int k = rng.uniform_int(0, 2); k > 0; --k) {
      const Q re(rng.uniform<double>(-5, 5)), im(rng.uniform<double>(0.5, 5));
      p = po::mul(p, po::QPoly{re * re + im * im, -2 * re, Q(1)});
    }
    const auto c = po::round_to<T>(p);
    const po::QPoly exact = po::exact_of(c);
    const po::Sturm st(exact);
    const Polynomial<T> poly(std::vector<T>(c.begin(), c.end()));
    const auto all = real_roots(poly);
    ASSERT_EQ(all.status, Status::ok);
    ASSERT_EQ(static_cast<int>(all.roots.size()), st.count(Q(-1e6), Q(1e6))) << "trial " << trial;
    for (const auto& root : all.roots) {
      double ex;
      ASSERT_TRUE(po::exact_root_near(exact, double(root.value), ex));
      // Degree up to 13 with roots in [-10, 10]: a few more ulps of conditioning than degree 4.
      EXPECT_LE(std::abs(double(root.value) - ex), 8 * rel_tol_simple<T>() * std::abs(ex));
    }
    // An interval returns exactly the roots inside it (closed interval).
    const T a = rng.uniform<T>(-8, 0), b = rng.uniform<T>(0, 8);
    const auto in = real_roots(poly, a, b);
    int expect_in = 0;
    for (const auto& root : all.roots) expect_in += (root.value >= a && root.value <= b);
    EXPECT_EQ(static_cast<int>(in.roots.size()), expect_in);
  }
  // Wilkinson's polynomial of degree 10 (exact integer coefficients in double).
  std::vector<Q> w;
  for (int i = 1; i <= 10; ++i) w.emplace_back(i);
  const auto wc = po::round_to<double>(po::expand(w, Q(1)));
  const auto wr = real_roots(Polynomial<double>(wc));
  ASSERT_EQ(static_cast<int>(wr.roots.size()), 10);
  for (int i = 0; i < 10; ++i)
    EXPECT_NEAR(wr.roots[static_cast<std::size_t>(i)].value, i + 1.0, 1e-12 * (i + 1));
  // x^n - 1 has the roots 1 and (n even) -1; (x - 1/2)^6 is one root of multiplicity 6.
  for (int n = 1; n <= 20; ++n) {
    std::vector<T> c(static_cast<std::size_t>(n) + 1, T(0));
    c[0] = T(-1);
    c.back() = T(1);
    const auto r = real_roots(Polynomial<T>(c));
    ASSERT_EQ(static_cast<int>(r.roots.size()), n % 2 == 0 ? 2 : 1);
    EXPECT_NEAR(r.roots.back().value, T(1), tol<T>(4));
  }
  std::vector<Q> h(6, po::frac(1, 2));
  const auto hr = real_roots(Polynomial<T>(po::round_to<T>(po::expand(h, Q(1)))));
  ASSERT_EQ(static_cast<int>(hr.roots.size()), 1);
  EXPECT_EQ(hr.roots[0].multiplicity, 6);
  EXPECT_NEAR(hr.roots[0].value, T(0.5), T(1e-2));
}

TYPED_TEST(RootsTest, InvariantUnderNegatingTheVariableAndScalingThePolynomial) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 300; ++trial) {
    T c[5];
    for (T& v : c) v = rng.uniform<T>(-4, 4);
    const auto r = solve_quartic(c[0], c[1], c[2], c[3], c[4]);
    // p(-x): negate odd coefficients (exact). Roots negate.
    const auto m = solve_quartic(c[0], -c[1], c[2], -c[3], c[4]);
    // 2^k p(x): exact scaling; identical roots.
    const auto s = solve_quartic(c[0] * T(1024), c[1] * T(1024), c[2] * T(1024), c[3] * T(1024),
                                 c[4] * T(1024));
    ASSERT_EQ(r.count, m.count);
    ASSERT_EQ(r.count, s.count);
    for (int i = 0; i < r.count; ++i) {
      EXPECT_EQ(r.roots[i].value, -m.roots[r.count - 1 - i].value);
      EXPECT_EQ(r.roots[i].value, s.roots[i].value);
      EXPECT_EQ(r.roots[i].multiplicity, s.roots[i].multiplicity);
    }
  }
}

TYPED_TEST(RootsTest, ToleranceOptionsTurnNearTangenciesIntoDoubleRoots) {
  using T = TypeParam;
  // (x - 1)^2 + d and (x - 1)^2 - d, d = 2^-20 (exact in float and double): by default a miss and
  // two roots 1 +- 2^-10; told that the constant term is only known to 2^-18, both are a double
  // root at 1.
  const T d = std::ldexp(T(1), -20);
  const auto miss = solve_quadratic(T(1) + d, T(-2), T(1));
  EXPECT_EQ(miss.count, 0);
  const auto two = solve_quadratic(T(1) - d, T(-2), T(1));
  ASSERT_EQ(two.count, 2);
  EXPECT_NEAR(two.roots[0].value, T(1) - std::ldexp(T(1), -10), tol<T>(4));
  EXPECT_NEAR(two.roots[1].value, T(1) + std::ldexp(T(1), -10), tol<T>(4));
  const double err[3] = {std::ldexp(1.0, -18), 0, 0};
  RootOptions opt = near_roots();
  opt.coefficient_error = err;
  for (const auto& r :
       {solve_quadratic(T(1) + d, T(-2), T(1), opt), solve_quadratic(T(1) - d, T(-2), T(1), opt)}) {
    ASSERT_EQ(r.count, 1);
    EXPECT_EQ(r.roots[0].multiplicity, 2);
    EXPECT_NEAR(r.roots[0].value, T(1), tol<T>(4));
  }
  // The relative form: |p(1)| = 2^-20 against 2^-16 * sum |a_i| = 2^-14.
  RootOptions rel = near_roots();
  rel.multiplicity_tolerance = std::ldexp(1.0, -16);
  const auto r = solve_quadratic(T(1) + d, T(-2), T(1), rel);
  ASSERT_EQ(r.count, 1);
  EXPECT_EQ(r.roots[0].multiplicity, 2);
  // Same through real_roots on a quartic: ((x-1)^2 + d)(x + 3)(x - 5).
  std::vector<Q> lin = {Q(-3), Q(5)};
  const po::QPoly p = po::mul(po::expand(lin, Q(1)), po::QPoly{Q(1) + Q(double(d)), Q(-2), Q(1)});
  const auto c = po::round_to<T>(p);
  EXPECT_EQ(static_cast<int>(real_roots(Polynomial<T>(c)).roots.size()), 2);
  const double e4[5] = {std::ldexp(1.0, -14), 0, 0, 0, 0};
  RootOptions o4 = near_roots();
  o4.coefficient_error = e4;
  const auto q = real_roots(Polynomial<T>(c), -std::numeric_limits<T>::infinity(),
                            std::numeric_limits<T>::infinity(), o4);
  ASSERT_EQ(static_cast<int>(q.roots.size()), 3);
  EXPECT_EQ(q.roots[1].multiplicity, 2);
  EXPECT_NEAR(q.roots[1].value, T(1), T(1e-3));
  // A non-finite error bound is bad input.
  const double bad[1] = {std::numeric_limits<double>::quiet_NaN()};
  RootOptions ob = near_roots();
  ob.coefficient_error = bad;
  EXPECT_EQ(solve_quadratic(T(1), T(-2), T(1), ob).status, Status::non_finite_input);
}

// Regression (PolySysTest.TangentCurvesGiveOnePointOfMultiplityTwo, double, seed 17, fixed first
// in polynomial_system.hpp by 250d8df): an exactly zero constant term made the root finder split
// off x = 0 as an exact root and deflate, so a linear coefficient that was only noise (5e-20,
// within its error bound 6e-18) became a second simple root beside 0: the double root at 0 came
// out as two simple roots. With error bounds, low coefficients within them after an exact zero
// constant term now raise the multiplicity of 0; above their bounds they stay data.
TYPED_TEST(RootsTest,
           LowCoefficientsWithinTheirBoundsAfterAZeroConstantRaiseTheMultiplicityOfZero) {
  using T = TypeParam;
  const T noise = T(5e-20), above = T(1e-16);  // 1e-16 > 2 * 6e-18: a root, by any criterion
  const double e2[3] = {0, 6e-18, 0};
  RootOptions o2 = near_roots();
  o2.coefficient_error = e2;
  // Without bounds the coefficients are exact: x (x + 5e-20) has the simple roots -5e-20 and 0
  // (what the bounds gave as well before the fix).
  const auto exact = solve_quadratic(T(0), noise, T(1));
  ASSERT_EQ(exact.count, 2);
  EXPECT_EQ(exact.roots[0].value, -noise);
  EXPECT_EQ(exact.roots[1].value, T(0));
  EXPECT_EQ(exact.roots[0].multiplicity, 1);
  EXPECT_EQ(exact.roots[1].multiplicity, 1);
  for (const T c1 : {noise, -noise}) {
    const auto r = solve_quadratic(T(0), c1, T(1), o2);
    ASSERT_EQ(r.count, 1) << c1;
    EXPECT_EQ(r.roots[0].value, T(0));
    EXPECT_EQ(r.roots[0].multiplicity, 2);
  }
  for (const T c1 : {above, -above}) {
    const auto r = solve_quadratic(T(0), c1, T(1), o2);
    ASSERT_EQ(r.count, 2) << c1;
    const int zi = c1 > 0 ? 1 : 0;  // the other root is -c1
    EXPECT_EQ(r.roots[zi].value, T(0));
    EXPECT_NEAR(r.roots[1 - zi].value, -c1, tol<T>(4) * above);
    EXPECT_EQ(r.roots[0].multiplicity, 1);
    EXPECT_EQ(r.roots[1].multiplicity, 1);
  }
  // Beside other roots: x^2 (x - 1)(x + 2) with its linear coefficient perturbed.
  const double e4[5] = {0, 6e-18, 0, 0, 0};
  RootOptions o4 = near_roots();
  o4.coefficient_error = e4;
  const auto q = solve_quartic(T(0), noise, T(-2), T(1), T(1), o4);
  ASSERT_EQ(q.count, 3);
  const T want[3] = {T(-2), T(0), T(1)};
  const int mult[3] = {1, 2, 1};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(q.roots[i].value, want[i], tol<T>(4)) << i;
    EXPECT_EQ(q.roots[i].multiplicity, mult[i]) << i;
  }
  EXPECT_EQ(q.roots[1].value, T(0));
  // Above the bound: the roots 0 and about above / 2 (above - 2x + x^2 + x^3 = 0) stay apart.
  const auto qa = solve_quartic(T(0), above, T(-2), T(1), T(1), o4);
  ASSERT_EQ(qa.count, 4);
  EXPECT_EQ(qa.roots[1].value, T(0));
  EXPECT_NEAR(qa.roots[2].value, above / 2, tol<T>(4) * above);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(qa.roots[i].multiplicity, 1) << i;
  // Two noise coefficients in a row through real_roots: x (5e-20 - 5e-20 x + x^2) is x^3 within
  // the bounds, a triple root at 0; with the quadratic coefficient exact, 0 is only double and
  // 5e-20 (the root of -5e-20 + x) a simple root.
  const double e3[4] = {0, 6e-18, 6e-18, 0};
  RootOptions o3 = near_roots();
  o3.coefficient_error = e3;
  const Polynomial<T> p{T(0), noise, -noise, T(1)};
  const T inf = std::numeric_limits<T>::infinity();
  const auto t = real_roots(p, -inf, inf, o3);
  ASSERT_EQ(static_cast<int>(t.roots.size()), 1);
  EXPECT_EQ(t.roots[0].value, T(0));
  EXPECT_EQ(t.roots[0].multiplicity, 3);
  const auto d = real_roots(p, -inf, inf, o4);
  ASSERT_EQ(static_cast<int>(d.roots.size()), 2);
  EXPECT_EQ(d.roots[0].value, T(0));
  EXPECT_EQ(d.roots[0].multiplicity, 2);
  EXPECT_NEAR(d.roots[1].value, noise, tol<T>(4) * noise);
  EXPECT_EQ(d.roots[1].multiplicity, 1);
}
