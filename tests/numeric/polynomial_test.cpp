// SPDX-License-Identifier: BSL-1.0
// Tests for numeric/polynomial.hpp (row num.roots: polynomial arithmetic, GCD, composition,
// evaluation with error bound, root bounds, Sturm sequences; book appendix A, figures A.9, A.10).
//
// Oracles: Polynomial<mpq_class> makes the ring identities exact (a = q b + r, (pq)(x) =
// p(x) q(x), ...); exact rational evaluation bounds the floating-point error; an independent
// rational Sturm chain (poly_oracle.hpp) checks sturm_count; known roots check the root bounds.
#include <locus/numeric/polynomial.hpp>

#include "numeric/poly_oracle.hpp"
#include "support/typed.hpp"

#include <gmpxx.h>

#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace po = poly_oracle;
using Q = mpq_class;
using PQ = Polynomial<Q>;

template <class T>
class PolynomialTest : public ::testing::Test {};
TYPED_TEST_SUITE(PolynomialTest, locus_test::RealTypes);

namespace {

PQ random_q(Rng& rng, int deg) {
  std::vector<Q> c;
  for (int i = 0; i <= deg; ++i)
    c.push_back(po::frac(rng.uniform_int(-20, 20), rng.uniform_int(1, 7)));
  if (deg >= 0 && c.back() == 0) c.back() = 1;
  return PQ(c);
}

template <class T>
Polynomial<T> random_poly(Rng& rng, int deg) {
  std::vector<T> c;
  for (int i = 0; i <= deg; ++i) c.push_back(rng.uniform<T>(-2, 2));
  return Polynomial<T>(c);
}

PQ from_roots(const std::vector<Q>& r, const Q& lead = 1) {
  PQ p = PQ::constant(lead);
  for (const Q& x : r) p = p * PQ{-x, Q(1)};
  return p;
}

}  // namespace

TEST(Polynomial, TrimmingRuleAndDegree) {
  const Polynomial<double> p{1.0, 2.0, 0.0, 0.0};
  EXPECT_EQ(p.degree(), 1);
  EXPECT_EQ(p.coeff.size(), 2u);
  EXPECT_EQ(Polynomial<double>{}.degree(), -1);
  EXPECT_EQ((Polynomial<double>{0.0, 0.0}.degree()), -1);
  EXPECT_TRUE((Polynomial<double>{0.0}.is_zero()));
  // A tiny leading coefficient is kept (it is data); trim() with a tolerance removes it.
  const Polynomial<double> t{1.0, 2.0, 1e-300};
  EXPECT_EQ(t.degree(), 2);
  EXPECT_EQ(trim(t, 1e-200).degree(), 1);
  // Untrimmed storage is still handled by every function.
  Polynomial<double> u;
  u.coeff = {3.0, 1.0, 0.0};
  EXPECT_EQ(u.degree(), 1);
  EXPECT_EQ(u.leading(), 1.0);
  EXPECT_EQ((u + Polynomial<double>{1.0}).coeff.size(), 2u);
  EXPECT_EQ((u - u).degree(), -1);
  EXPECT_EQ(derivative(u), (Polynomial<double>{1.0}));
  EXPECT_EQ(derivative(Polynomial<double>{5.0}).degree(), -1);
  EXPECT_EQ(Polynomial<double>::monomial(2.0, 3), (Polynomial<double>{0, 0, 0, 2.0}));
}

TEST(Polynomial, ExactRingIdentitiesInRationals) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 200; ++trial) {
    const PQ a = random_q(rng, rng.uniform_int(0, 6)), b = random_q(rng, rng.uniform_int(0, 4));
    const PQ c = random_q(rng, rng.uniform_int(0, 3));
    const Q x = po::frac(rng.uniform_int(-50, 50), rng.uniform_int(1, 9));
    EXPECT_EQ((a + b)(x), a(x) + b(x));
    EXPECT_EQ((a - b)(x), a(x) - b(x));
    EXPECT_EQ((a * b)(x), a(x) * b(x));
    EXPECT_EQ((a * po::frac(3, 7))(x), a(x) * po::frac(3, 7));
    EXPECT_EQ(compose(a, b)(x), a(b(x)));
    EXPECT_EQ(derivative(a * b), derivative(a) * b + a * derivative(b));
    EXPECT_EQ(derivative(compose(a, c)), compose(derivative(a), c) * derivative(c));  // chain rule
    EXPECT_EQ((a * b).degree(), a.degree() + b.degree());
    const auto d = divide(a, b);
    ASSERT_EQ(d.status, Status::ok);
    EXPECT_EQ(d.quotient * b + d.remainder, a);
    EXPECT_LT(d.remainder.degree(), b.degree());
  }
  const auto z = divide(PQ{1, 2}, PQ{});
  EXPECT_EQ(z.status, Status::degenerate_input);
  EXPECT_EQ(z.remainder, (PQ{1, 2}));
}

TEST(Polynomial, ExactGcdOfPolynomialsWithKnownCommonRoots) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 100; ++trial) {
    // Distinct rational roots; g shares the first k of them, f the first k and others.
    std::vector<Q> roots;
    while (roots.size() < 7) {
      const Q r = po::frac(rng.uniform_int(-40, 40), rng.uniform_int(1, 5));
      bool fresh = true;
      for (const Q& s : roots) fresh = fresh && s != r;
      if (fresh) roots.push_back(r);
    }
    const int k = rng.uniform_int(0, 3);
    std::vector<Q> common(roots.begin(), roots.begin() + k);
    std::vector<Q> fr = common, gr = common;
    fr.insert(fr.end(), roots.begin() + k, roots.begin() + k + 2);
    gr.insert(gr.end(), roots.begin() + k + 2, roots.begin() + k + 4);
    const PQ f = from_roots(fr, Q(rng.uniform_int(1, 9))),
             g = from_roots(gr, Q(-rng.uniform_int(1, 9)));
    EXPECT_EQ(gcd(f, g), from_roots(common));
    EXPECT_EQ(gcd(g, f), from_roots(common));
  }
  EXPECT_EQ(gcd(PQ{}, PQ{}), PQ{});
  EXPECT_EQ(gcd(PQ{2, 4}, PQ{}), (PQ{po::frac(1, 2), 1}));
}

TYPED_TEST(PolynomialTest, FloatingGcdWithTolerance) {
  using T = TypeParam;
  // (x-1)(x+3)(x-2) and (x-1)(x+3)(x+5): integer coefficients, exact in T.
  const Polynomial<T> f{T(6), T(-7), T(0), T(1)}, g{T(-15), T(7), T(7), T(1)};
  const Polynomial<T> h = gcd(f, g);
  ASSERT_EQ(h.degree(), 2);  // (x-1)(x+3) = x^2 + 2x - 3
  EXPECT_NEAR(h[0], T(-3), tol<T>(64, 3));
  EXPECT_NEAR(h[1], T(2), tol<T>(64, 2));
  EXPECT_EQ(h[2], T(1));
  // Coprime: the gcd is the constant 1.
  EXPECT_EQ(gcd(Polynomial<T>{T(-1), T(0), T(1)}, Polynomial<T>{T(-4), T(0), T(1)}),
            (Polynomial<T>{T(1)}));
}

TYPED_TEST(PolynomialTest, FloatingArithmeticMatchesExactWithinRoundoff) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 200; ++trial) {
    const auto a = random_poly<T>(rng, rng.uniform_int(1, 8)),
               b = random_poly<T>(rng, rng.uniform_int(1, 4));
    const auto d = divide(a, b);
    const auto back = d.quotient * b + d.remainder;
    // Long division is backward stable relative to |q| |b|: check coefficient-wise against
    // the size of the terms involved.
    T qb = T(0);
    for (T c : d.quotient.coeff) qb = std::max(qb, std::abs(c));
    T bb = T(0);
    for (T c : b.coeff) bb = std::max(bb, std::abs(c));
    for (int i = 0; i <= a.degree(); ++i)
      EXPECT_NEAR(back[i], a[i], tol<T>(T(16 * (a.degree() + 1)), T(1) + qb * bb)) << i;
    EXPECT_LT(d.remainder.degree(), b.degree());
  }
}

TYPED_TEST(PolynomialTest, EvaluationErrorBoundHoldsAgainstExactValue) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    const int n = rng.uniform_int(0, 10);
    const auto p = random_poly<T>(rng, n);
    // Near a root (cancellation) half of the time: x from a root of p's first two terms.
    T x = rng.uniform<T>(-2, 2);
    if (trial % 2 == 0 && p.degree() >= 1 && p[1] != T(0)) x = -p[0] / p[1];
    const auto e = evaluate_with_bound(p, x);
    Q exact = 0;
    for (int i = p.degree(); i >= 0; --i) exact = exact * Q(double(x)) + Q(double(p[i]));
    const Q err = abs(Q(double(e.value)) - exact);
    EXPECT_LE(err.get_d(), double(e.error_bound)) << "n=" << n;
    // And the bound is not vacuous: at most gamma_{2n} sum |a_i| |x|^i (Higham's a priori bound).
    T abs_sum = T(0);
    for (int i = p.degree(); i >= 0; --i) abs_sum = abs_sum * std::abs(x) + std::abs(p[i]);
    EXPECT_LE(e.error_bound, T(2 * n + 2) * eps_v<T> * abs_sum);
    EXPECT_EQ(e.value, p(x));
  }
  EXPECT_EQ(evaluate_with_bound(Polynomial<T>{}, T(3)).value, T(0));
}

TYPED_TEST(PolynomialTest, RootBoundsContainEveryComplexRoot) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 300; ++trial) {
    // Real roots and complex pairs re +- i im: the largest modulus is known.
    std::vector<Q> rr;
    double maxmod = 0;
    for (int k = rng.uniform_int(0, 3); k > 0; --k) {
      const double r = rng.uniform<double>(-50, 50);
      rr.emplace_back(r);
      maxmod = std::max(maxmod, std::abs(r));
    }
    po::QPoly p = po::expand(rr, Q(rng.uniform<double>(0.1, 10)));
    for (int k = rng.uniform_int(rr.empty() ? 1 : 0, 2); k > 0; --k) {
      const double re = rng.uniform<double>(-20, 20), im = rng.uniform<double>(0.1, 20);
      p = po::mul(p, po::QPoly{Q(re) * Q(re) + Q(im) * Q(im), Q(-2 * re), Q(1)});
      maxmod = std::max(maxmod, std::hypot(re, im));
    }
    const auto c = po::round_to<T>(p);
    const Polynomial<T> poly{std::vector<T>(c.begin(), c.end())};
    // Rounding the coefficients moves the roots by a relative O(eps * condition): allow 1e-3.
    const double slack = std::is_same_v<T, float> ? 1e-2 : 1e-6;
    EXPECT_GE(double(cauchy_root_bound(poly)), maxmod * (1 - slack));
    EXPECT_GE(double(fujiwara_root_bound(poly)), maxmod * (1 - slack));
    // Fujiwara's is within a factor 2n of the largest modulus.
    EXPECT_LE(double(fujiwara_root_bound(poly)), 2.0 * poly.degree() * maxmod * (1 + slack));
  }
  EXPECT_EQ(cauchy_root_bound(Polynomial<T>{T(3)}), T(0));
  EXPECT_EQ(fujiwara_root_bound(Polynomial<T>{}), std::numeric_limits<T>::infinity());
  // x - 5: Fujiwara's bound is exact for degree 1.
  EXPECT_EQ(fujiwara_root_bound(Polynomial<T>{T(-5), T(1)}), T(5));
}

TEST(Polynomial, SturmCountMatchesIndependentOracleAndKnownRoots) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 150; ++trial) {
    // Known rational roots with multiplicities, times an irreducible quadratic sometimes.
    std::vector<Q> roots;
    std::vector<Q> distinct;
    for (int k = rng.uniform_int(1, 5); k > 0; --k) {
      const Q r = po::frac(rng.uniform_int(-30, 30), rng.uniform_int(1, 4));
      bool fresh = true;
      for (const Q& s : distinct) fresh = fresh && s != r;
      if (fresh) distinct.push_back(r);
      for (int m = rng.uniform_int(1, 3); m > 0; --m) roots.push_back(r);
    }
    PQ p = from_roots(roots, Q(rng.uniform_int(1, 5)));
    if (trial % 2) p = p * PQ{Q(rng.uniform_int(1, 20)), Q(0), Q(1)};  // x^2 + c: no real roots
    const Q a = po::frac(rng.uniform_int(-40, 0) * 2 + 1, 3),
            b = po::frac(rng.uniform_int(0, 40) * 2 + 1, 3);
    int expected = 0;
    for (const Q& r : distinct) expected += (r > a && r <= b);
    EXPECT_EQ(sturm_count(p, a, b), expected);
    po::QPoly pc(p.coeff.begin(), p.coeff.end());
    EXPECT_EQ(po::Sturm(pc).count(a, b), expected);
    // Half-open: b itself a root counts, a does not.
    if (!distinct.empty()) {
      const Q r = distinct[0];
      EXPECT_EQ(sturm_count(p, Q(r - po::frac(1, 1000000)), r), 1);
    }
  }
  EXPECT_EQ(sturm_count(PQ{}, Q(0), Q(1)), 0);
  EXPECT_EQ(sturm_count(PQ{1}, Q(0), Q(1)), 0);
}

TEST(Polynomial, FiguresA9AndA10) {
  // A.9: f(x) = x^3 + 6x^2 - 7x + 19 on [-8, 3]; A.10: its derivative 3x^2 + 12x - 7.
  const PQ f{19, -7, 6, 1};
  const PQ fp = derivative(f);
  EXPECT_EQ(fp, (PQ{-7, 12, 3}));
  EXPECT_EQ(sturm_count(f, Q(-8), Q(3)), 1);   // one real root in the window
  EXPECT_EQ(sturm_count(fp, Q(-8), Q(3)), 2);  // two critical points: a maximum and a minimum
  EXPECT_EQ(sturm_count(f, Q(-1000), Q(1000)), 1);
  // The extreme values on [-8, 3] occur at the critical points or the ends (figure A.9's point).
  Polynomial<double> fd{19, -7, 6, 1};
  const double crit_hi = -2 + std::sqrt(228.0) / 6;  // the local minimum
  const auto e = evaluate_with_bound(fd, crit_hi);
  EXPECT_NEAR(e.value, 19 - 7 * crit_hi + 6 * crit_hi * crit_hi + crit_hi * crit_hi * crit_hi,
              1e-12);
  EXPECT_GT(e.value, 0.0);
  // Floating Sturm sequence agrees on this well-conditioned case.
  EXPECT_EQ(sturm_count(fd, -8.0, 3.0), 1);
}
