// SPDX-License-Identifier: BSL-1.0
// Row int2.quadratic, the exact combinatorics of conic pairs: the number of distinct real common
// points and each one's intersection multiplicity against an independent GMP oracle (the curves'
// implicit equations in Q, the resultant eliminating x after a rational shear y' = y + m x, m
// chosen among fractions to maximise the distinct complex roots, real roots counted per
// multiplicity by Sturm sequences of the gcd chain in Q[y']); every point on both curves.
// Constructed tangencies of multiplicity 2, 3 and 4, crossings far closer than sqrt(eps), four
// points, none, nesting (relation()), line pairs sharing a line, parallel pairs, double lines,
// non-finite input, power-of-two scaling and swapped arguments.

#include <locus/intersection/circle_ellipse.hpp>
#include <locus/intersection/circle_quadratic_curve.hpp>
#include <locus/intersection/ellipse_ellipse.hpp>
#include <locus/intersection/ellipse_quadratic_curve.hpp>
#include <locus/intersection/quadratic_curve_quadratic_curve.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <gmpxx.h>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class QuadraticExact : public ::testing::Test {};
TYPED_TEST_SUITE(QuadraticExact, locus_test::RealTypes);

// ---- polynomials over Q (low to high)
using QPoly = std::vector<mpq_class>;

void trim(QPoly& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}
QPoly mul(const QPoly& a, const QPoly& b) {
  if (a.empty() || b.empty()) return {};
  QPoly r(a.size() + b.size() - 1, mpq_class(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  trim(r);
  return r;
}
QPoly sub(QPoly a, const QPoly& b) {
  if (a.size() < b.size()) a.resize(b.size(), mpq_class(0));
  for (std::size_t i = 0; i < b.size(); ++i) a[i] -= b[i];
  trim(a);
  return a;
}
QPoly rem(QPoly a, const QPoly& b) {
  while (a.size() >= b.size() && !a.empty()) {
    const mpq_class f = a.back() / b.back();
    const std::size_t s = a.size() - b.size();
    for (std::size_t i = 0; i < b.size(); ++i) a[i + s] -= f * b[i];
    a.pop_back();
    trim(a);
  }
  return a;
}
QPoly deriv(const QPoly& p) {
  QPoly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * static_cast<long>(i));
  trim(d);
  return d;
}
QPoly gcd(QPoly a, QPoly b) {
  while (!b.empty()) {
    QPoly r = rem(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}
int sign_at_inf(const QPoly& p, int side) {
  if (p.empty()) return 0;
  const int s = sgn(p.back());
  return (side < 0 && (p.size() - 1) % 2 == 1) ? -s : s;
}
/// Distinct real roots of p (Sturm: variations at -inf minus at +inf).
int distinct_real_roots(const QPoly& p) {
  if (p.size() <= 1) return 0;
  std::vector<QPoly> s{p, deriv(p)};
  for (;;) {
    QPoly r = rem(s[s.size() - 2], s.back());
    if (r.empty()) break;
    for (auto& c : r) c = -c;
    s.push_back(std::move(r));
  }
  const auto variations = [&](int side) {
    int v = 0, last = 0;
    for (const auto& q : s) {
      const int sg = sign_at_inf(q, side);
      if (sg != 0 && last != 0 && sg != last) ++v;
      if (sg != 0) last = sg;
    }
    return v;
  };
  return variations(-1) - variations(1);
}

/// a x^2 + b xy + c y^2 + d x + e y + f in Q.
using QConic = std::array<mpq_class, 6>;

template <class T>
QConic q_of(const Ellipse2<T>& el) {
  // sum_i (u_i . (X - C))^2 / e_i^2 - 1.
  QConic q{0, 0, 0, 0, 0, -1};
  for (int i = 0; i < 2; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const mpq_class ux(double(el.axis[ii].x)), uy(double(el.axis[ii].y)),
        e2 = mpq_class(double(el.extent[i])) * mpq_class(double(el.extent[i]));
    const mpq_class p = ux * mpq_class(double(el.center.x)) + uy * mpq_class(double(el.center.y));
    q[0] += ux * ux / e2;
    q[1] += 2 * ux * uy / e2;
    q[2] += uy * uy / e2;
    q[3] -= 2 * ux * p / e2;
    q[4] -= 2 * uy * p / e2;
    q[5] += p * p / e2;
  }
  return q;
}
template <class T>
QConic q_of(const QuadraticCurve2<T>& c) {
  return {mpq_class(double(c.a)), mpq_class(double(c.b)), mpq_class(double(c.c)),
          mpq_class(double(c.d)), mpq_class(double(c.e)), mpq_class(double(c.f))};
}

/// The multiset of multiplicities of the real common points, sorted (empty: none).
std::vector<int> oracle_multiplicities(const QConic& p, const QConic& q) {
  // Shear y = y' - m x; eliminate x: each conic is A2 x^2 + A1(y') x + A0(y').
  const mpq_class ms[] = {mpq_class(1, 3),  mpq_class(-2, 7),  mpq_class(3, 11), mpq_class(-5, 13),
                          mpq_class(7, 17), mpq_class(-1, 19), mpq_class(4, 23), mpq_class(-6, 29),
                          mpq_class(9, 31), mpq_class(-8, 37), mpq_class(2, 41), mpq_class(-3, 43)};
  QPoly best;
  int best_distinct = -1;
  for (const mpq_class& m : ms) {
    const auto part = [&](const QConic& k, QPoly& a2, QPoly& a1, QPoly& a0) {
      // a x^2 + b x (y' - m x) + c (y' - m x)^2 + d x + e (y' - m x) + f.
      a2 = {k[0] - k[1] * m + k[2] * m * m};
      a1 = {k[3] - k[4] * m, k[1] - 2 * k[2] * m};
      a0 = {k[5], k[4], k[2]};
      trim(a2);
      trim(a1);
      trim(a0);
    };
    QPoly a2, a1, a0, b2, b1, b0;
    part(p, a2, a1, a0);
    part(q, b2, b1, b0);
    if (a2.empty() || b2.empty()) continue;
    const QPoly s = sub(mul(a2, b0), mul(a0, b2));
    const QPoly res =
        sub(mul(s, s), mul(sub(mul(a2, b1), mul(a1, b2)), sub(mul(a1, b0), mul(a0, b1))));
    if (res.empty()) return {-1};
    const int distinct =
        static_cast<int>(res.size()) - static_cast<int>(gcd(res, deriv(res)).size());
    if (distinct > best_distinct) {
      best_distinct = distinct;
      best = res;
    }
    if (distinct == static_cast<int>(res.size()) - 1) break;  // square-free: a good shear
  }
  // Gcd chain: p_j has the roots of multiplicity > j with multiplicity reduced by j.
  std::vector<int> count_at_least;
  QPoly c = best;
  while (c.size() > 1) {
    count_at_least.push_back(distinct_real_roots(c));
    c = gcd(c, deriv(c));
  }
  std::vector<int> mult;
  for (std::size_t j = 0; j < count_at_least.size(); ++j) {
    const int exactly =
        count_at_least[j] - (j + 1 < count_at_least.size() ? count_at_least[j + 1] : 0);
    for (int i = 0; i < exactly; ++i) mult.push_back(static_cast<int>(j) + 1);
  }
  std::sort(mult.begin(), mult.end());
  return mult;
}

template <class R>
std::vector<int> multiplicities(const R& r) {
  std::vector<int> m;
  for (int i = 0; i < r.count; ++i) m.push_back(r.multiplicity[static_cast<std::size_t>(i)]);
  std::sort(m.begin(), m.end());
  return m;
}

/// |Q(p)| / (|grad Q(p)| scale): about the distance from p to the curve, relative to scale.
double rel_distance(const QConic& q, Vec2<double> p) {
  const double a = q[0].get_d(), b = q[1].get_d(), c = q[2].get_d(), d = q[3].get_d(),
               e = q[4].get_d();
  const mpq_class x(p.x), y(p.y);
  const double v =
      mpq_class(q[0] * x * x + q[1] * x * y + q[2] * y * y + q[3] * x + q[4] * y + q[5]).get_d();
  const double gx = 2 * a * p.x + b * p.y + d, gy = b * p.x + 2 * c * p.y + e;
  const double g = std::hypot(gx, gy);
  const double scale = std::max({1.0, std::abs(p.x), std::abs(p.y)});
  return g > 0 ? std::abs(v) / g / scale : std::abs(v);
}

template <class T>
Ellipse2<T> random_ellipse(Rng& rng) {
  const double th = rng.uniform<double>(0.0, 6.283185307179586);
  const T c = static_cast<T>(std::cos(th)), s = static_cast<T>(std::sin(th));
  const auto dy = [&](int range, int bits) {
    return static_cast<T>(std::ldexp(double(rng.uniform_int(-range, range)), -bits));
  };
  const T e0 = static_cast<T>(std::ldexp(double(rng.uniform_int(8, 64)), -4));
  const T e1 = static_cast<T>(std::ldexp(double(rng.uniform_int(8, 64)), -4));
  return Ellipse2<T>{{dy(32, 4), dy(32, 4)}, {Vec2<T>{c, s}, Vec2<T>{-s, c}}, {e0, e1}};
}

template <class T>
Ellipse2<T> axis_ellipse(T cx, T cy, T e0, T e1) {
  return Ellipse2<T>{{cx, cy}, {Vec2<T>{1, 0}, Vec2<T>{0, 1}}, {e0, e1}};
}

TYPED_TEST(QuadraticExact, EllipsePairsAgainstGmpOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double tol = std::is_same_v<T, float> ? 1e-5 : 1e-12;
  int with_points = 0;
  for (int it = 0; it < 60; ++it) {
    const Ellipse2<T> a = random_ellipse<T>(rng), b = random_ellipse<T>(rng);
    const auto r = intersection(a, b);
    const QConic qa = q_of(a), qb = q_of(b);
    ASSERT_EQ(multiplicities(r), oracle_multiplicities(qa, qb)) << "case " << it;
    for (int i = 0; i < r.count; ++i) {
      const auto p = vec_cast<double>(r.point[static_cast<std::size_t>(i)]);
      EXPECT_LT(rel_distance(qa, p), tol) << it;
      EXPECT_LT(rel_distance(qb, p), tol) << it;
    }
    with_points += r.count > 0;
    const auto s = intersection(b, a);
    EXPECT_EQ(multiplicities(s), multiplicities(r));
  }
  EXPECT_GT(with_points, 10);
}

TYPED_TEST(QuadraticExact, RandomTangenciesAndNearTangenciesAgainstGmpOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // An axis-aligned ellipse (half-axes a, b) and a circle of radius r centred at (a + r, 0)
  // touch at (a, 0) (both translated by a dyadic offset); r +- 64 eps gives two close crossings
  // or none. The exact path decides these.
  for (int it = 0; it < 12; ++it) {
    const auto dy = [&](int lo, int hi, int bits) {
      return static_cast<T>(std::ldexp(double(rng.uniform_int(lo, hi)), -bits));
    };
    const T a = dy(8, 40, 3), b = dy(8, 40, 3), r = dy(4, 40, 3), ox = dy(-64, 64, 4),
            oy = dy(-64, 64, 4);
    const T dr = it % 3 == 0 ? T(0) : (it % 3 == 1 ? T(64) : T(-64)) * eps_v<T>;
    const Ellipse2<T> e = axis_ellipse<T>(ox, oy, a, b);
    const Ellipse2<T> c = axis_ellipse<T>(ox + a + r, oy, r + dr, r + dr);
    const auto res = intersection(e, c);
    const auto want = oracle_multiplicities(q_of(e), q_of(c));
    ASSERT_EQ(multiplicities(res), want) << it;
    if (dr == T(0)) {
      EXPECT_EQ(want, (std::vector<int>{2})) << it;
      EXPECT_EQ(res.point[0], (Vec2<T>{ox + a, oy})) << it;
      EXPECT_EQ(relation(e, c), RegionRelation::touching) << it;
    } else {
      EXPECT_EQ(relation(e, c), dr > T(0) ? RegionRelation::overlapping : RegionRelation::separated)
          << it;
    }
    EXPECT_EQ(multiplicities(intersection(c, e)), want) << it;
  }
}

TYPED_TEST(QuadraticExact, ConstructedTangencies) {
  using T = TypeParam;
  const Ellipse2<T> e = axis_ellipse<T>(0, 0, 2, 1);
  // External tangency at the vertex (2, 0): multiplicity 2.
  {
    const Ellipse2<T> c = axis_ellipse<T>(4, 0, 2, 2);
    const auto r = intersection(e, c);
    ASSERT_EQ(r.kind, Kind::point);
    EXPECT_EQ(r.multiplicity[0], 2);
    EXPECT_EQ(r.point[0], (Vec2<T>{2, 0}));
    EXPECT_EQ(relation(e, c), RegionRelation::touching);
    EXPECT_EQ(multiplicities(r), oracle_multiplicities(q_of(e), q_of(c)));
  }
  // The osculating circle at the vertex (radius b^2 / a = 1/2): contact of order 4.
  {
    const Ellipse2<T> c = axis_ellipse<T>(T(1.5), 0, T(0.5), T(0.5));
    const auto r = intersection(e, c);
    ASSERT_EQ(r.kind, Kind::point);
    EXPECT_EQ(r.multiplicity[0], 4);
    EXPECT_EQ(r.point[0], (Vec2<T>{2, 0}));
    EXPECT_EQ(relation(e, c), RegionRelation::a_contains_b_touching);
    EXPECT_EQ(relation(c, e), RegionRelation::b_contains_a_touching);
    EXPECT_EQ(multiplicities(r), (std::vector<int>{4}));
    const Circle2<T> circ{{T(1.5), 0}, T(0.5)};
    const auto rc = intersection(circ, e);
    ASSERT_EQ(rc.kind, Kind::point);
    EXPECT_EQ(rc.multiplicity[0], 4);
  }
  // Contact of order 3: x^2 + y^2 - 2y = 0 and x^2 + xy + y^2 - 2y = 0 at the origin, plus a
  // crossing at (0, 2).
  {
    const QuadraticCurve2<T> p{1, 0, 1, 0, -2, 0}, q{1, 1, 1, 0, -2, 0};
    const auto r = intersection(p, q);
    ASSERT_EQ(r.kind, Kind::points);
    EXPECT_EQ(multiplicities(r), (std::vector<int>{1, 3}));
    EXPECT_EQ(multiplicities(r), oracle_multiplicities(q_of(p), q_of(q)));
    const Circle2<T> circ{{0, 1}, 1};
    const auto rc = intersection(circ, q);
    EXPECT_EQ(multiplicities(rc), (std::vector<int>{1, 3}));
  }
  // Two tangencies (multiplicity 2 each): concentric ellipses sharing the minor vertices.
  {
    const Ellipse2<T> f = axis_ellipse<T>(0, 0, 3, 1);
    const auto r = intersection(e, f);
    EXPECT_EQ(multiplicities(r), (std::vector<int>{2, 2}));
    EXPECT_EQ(relation(e, f), RegionRelation::b_contains_a_touching);
  }
}

TYPED_TEST(QuadraticExact, CloseCrossingsStayDistinct) {
  using T = TypeParam;
  // x^2 + y^2 = 4 and (x - 1)^2 + (y - h)^2 = 1 cross at y = h (2 +- sqrt 2): far closer than
  // sqrt(eps), two simple points; h = 0 is an internal tangency.
  const T h = static_cast<T>(std::ldexp(1.0, -36));
  const Ellipse2<T> a = axis_ellipse<T>(0, 0, 2, 2), b = axis_ellipse<T>(1, h, 1, 1);
  const auto r = intersection(a, b);
  ASSERT_EQ(r.kind, Kind::points);
  EXPECT_EQ(multiplicities(r), (std::vector<int>{1, 1}));
  EXPECT_EQ(relation(a, b), RegionRelation::overlapping);
  const double y0 = 2.0 - std::sqrt(2.0), y1 = 2.0 + std::sqrt(2.0);
  std::vector<double> ys{double(r.point[0].y) / double(h), double(r.point[1].y) / double(h)};
  std::sort(ys.begin(), ys.end());
  EXPECT_NEAR(ys[0], y0, 1e-3);
  EXPECT_NEAR(ys[1], y1, 1e-3);
  const auto t = intersection(a, axis_ellipse<T>(1, 0, 1, 1));
  ASSERT_EQ(t.kind, Kind::point);
  EXPECT_EQ(t.multiplicity[0], 2);  // internal tangency (the circular points take the other 2)
  EXPECT_EQ(t.point[0], (Vec2<T>{2, 0}));
  EXPECT_EQ(relation(a, axis_ellipse<T>(1, 0, 1, 1)), RegionRelation::a_contains_b_touching);
}

TYPED_TEST(QuadraticExact, FourNoneAndNesting) {
  using T = TypeParam;
  const Ellipse2<T> a = axis_ellipse<T>(0, 0, 2, 1), b = axis_ellipse<T>(0, 0, 1, 2);
  const auto r = intersection(a, b);
  EXPECT_EQ(multiplicities(r), (std::vector<int>{1, 1, 1, 1}));
  EXPECT_EQ(relation(a, b), RegionRelation::overlapping);
  const Ellipse2<T> far = axis_ellipse<T>(10, 3, 1, 2);
  EXPECT_EQ(intersection(a, far).kind, Kind::empty);
  EXPECT_EQ(relation(a, far), RegionRelation::separated);
  const Ellipse2<T> inner = axis_ellipse<T>(T(0.25), 0, 1, T(0.5));
  EXPECT_EQ(intersection(a, inner).kind, Kind::empty);
  EXPECT_EQ(relation(a, inner), RegionRelation::a_contains_b);
  EXPECT_EQ(relation(inner, a), RegionRelation::b_contains_a);
  EXPECT_EQ(relation(a, a), RegionRelation::equal);
  EXPECT_EQ(intersection(a, a).kind, Kind::coincident);
}

TYPED_TEST(QuadraticExact, SharedLines) {
  using T = TypeParam;
  // (x - y)(x + y - 1) and (x - y)(2x - 3y + 1): the line x = y and the point (2/5, 3/5).
  {
    const QuadraticCurve2<T> p{1, 0, -1, -1, 1, 0}, q{2, -5, 3, 1, -1, 0};
    const auto r = intersection(p, q);
    ASSERT_EQ(r.kind, Kind::line);
    ASSERT_EQ(r.count, 3);
    EXPECT_EQ(r.point[0].x, r.point[0].y);
    EXPECT_NEAR(double(r.point[1].x), double(r.point[1].y), 1e-6);
    EXPECT_NE(r.point[0], r.point[1]);
    EXPECT_EQ(r.multiplicity[2], 1);
    EXPECT_NEAR(double(r.point[2].x), 0.4, 1e-6);
    EXPECT_NEAR(double(r.point[2].y), 0.6, 1e-6);
    const auto s = intersection(q, p);
    ASSERT_EQ(s.kind, Kind::line);
    EXPECT_EQ(s.count, 3);
  }
  // Parallel remaining lines: (x - y)(x - y - 1) and (x - y)(x - y + 2): the line only.
  {
    const QuadraticCurve2<T> p{1, -2, 1, -1, 1, 0}, q{1, -2, 1, 2, -2, 0};
    const auto r = intersection(p, q);
    ASSERT_EQ(r.kind, Kind::line);
    EXPECT_EQ(r.count, 2);
  }
  // (x - y)(x - y - 1) and (x - y)(x + 1): the line and (-1, -2).
  {
    const QuadraticCurve2<T> p{1, -2, 1, -1, 1, 0}, q{1, -1, 0, 1, -1, 0};
    const auto r = intersection(p, q);
    ASSERT_EQ(r.kind, Kind::line);
    ASSERT_EQ(r.count, 3);
    EXPECT_EQ(r.point[2], (Vec2<T>{-1, -2}));
  }
  // A double line (x - y)^2 and (x - y)(x + y): the line; the other lines meet on it.
  {
    const QuadraticCurve2<T> p{1, -2, 1, 0, 0, 0}, q{1, 0, -1, 0, 0, 0};
    const auto r = intersection(p, q);
    ASSERT_EQ(r.kind, Kind::line);
    EXPECT_EQ(r.count, 2);
  }
  // Two line pairs with no common line: (x - y)(x + y) and (x - 1)(y - 2): four points.
  {
    const QuadraticCurve2<T> p{1, 0, -1, 0, 0, 0}, q{0, 1, 0, -2, -1, 2};
    const auto r = intersection(p, q);
    EXPECT_EQ(multiplicities(r), (std::vector<int>{1, 1, 1, 1}));
    EXPECT_EQ(multiplicities(r), oracle_multiplicities(q_of(p), q_of(q)));
  }
  // Proportional coefficients: the same curve.
  {
    const QuadraticCurve2<T> p{1, 0, -1, -1, 1, 0}, q{-2, 0, 2, 2, -2, 0};
    EXPECT_EQ(intersection(p, q).kind, Kind::coincident);
  }
}

TYPED_TEST(QuadraticExact, NonFiniteScalingAndSwap) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Ellipse2<T> a = axis_ellipse<T>(0, 0, 2, 1);
  EXPECT_EQ(intersection(a, axis_ellipse<T>(nan, 0, 1, 1)).kind, Kind::empty);
  EXPECT_EQ(intersection(a, axis_ellipse<T>(0, 0, inf, 1)).kind, Kind::empty);
  EXPECT_EQ(relation(a, axis_ellipse<T>(nan, 0, 1, 1)), RegionRelation::undecided);
  const QuadraticCurve2<T> q{1, 0, 1, 0, 0, nan};
  EXPECT_EQ(intersection(q, QuadraticCurve2<T>{1, 0, 1, 0, 0, -1}).kind, Kind::empty);
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 8; ++it) {
    const Ellipse2<T> e = random_ellipse<T>(rng), f = random_ellipse<T>(rng);
    const auto r = intersection(e, f);
    for (const int k : {-20, 13}) {
      const T s = static_cast<T>(std::ldexp(1.0, k));
      Ellipse2<T> es = e, fs = f;
      es.center = s * e.center;
      es.extent = {s * e.extent[0], s * e.extent[1]};
      fs.center = s * f.center;
      fs.extent = {s * f.extent[0], s * f.extent[1]};
      const auto rs = intersection(es, fs);
      ASSERT_EQ(rs.kind, r.kind);
      ASSERT_EQ(multiplicities(rs), multiplicities(r));
      for (int i = 0; i < r.count; ++i) {
        const auto ii = static_cast<std::size_t>(i);
        EXPECT_EQ(rs.point[ii], s * r.point[ii]);
      }
      EXPECT_EQ(relation(es, fs), relation(e, f));
    }
    const auto w = intersection(f, e);
    ASSERT_EQ(multiplicities(w), multiplicities(r));
    for (int i = 0; i < r.count; ++i) {
      bool found = false;
      for (int j = 0; j < w.count; ++j)
        found =
            found || w.point[static_cast<std::size_t>(j)] == r.point[static_cast<std::size_t>(i)];
      EXPECT_TRUE(found) << it;
    }
  }
}

}  // namespace
