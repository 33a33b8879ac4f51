// SPDX-License-Identifier: BSL-1.0
// Row cons2.apollonius: apollonius() (circles tangent to three circles), float and double.
// Oracle (1024-bit GMP floats, a second method): for each of the eight sign patterns s, subtract
// the tangency equations |X - c_i|^2 = (r + s_i r_i)^2 pairwise, solve the 2x2 system for X as a
// linear function of r, substitute into the first equation and count the roots r > 0 of the
// quadratic; tangent lines: per pattern, solve m . (c_i - c_0) = -(s_i r_i - s_0 r_0) and test
// |m| = 1. Counts of circles and lines must match; every circle satisfies |X - c_i| = |r + s_i
// r_i| and every line is at distance r_i from c_i on the side its sign says (residuals in GMP).
// Inputs: seeded random; exact ties (touching input circles, circles with a common tangent line,
// three equal collinear circles, three points); infinitely many; NaN/Inf and negative radii;
// power-of-two scaling; 90 degree rotations.

#include <locus/construct/apollonius.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "construct/oracle.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using namespace locus_test::cons;
using locus_test::Rng;

template <class T>
class ConstructApollonius : public ::testing::Test {};
TYPED_TEST_SUITE(ConstructApollonius, locus_test::RealTypes);

template <class T>
constexpr double eps() {
  return double(std::numeric_limits<T>::epsilon());
}

struct OracleCount {
  int circles = 0, lines = 0;
  bool collinear = false;
};

template <class T>
OracleCount oracle(const Circle2<T> (&c)[3]) {
  OracleCount out;
  mpf_class x[3], y[3], r[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = F(double(c[i].center.x));
    y[i] = F(double(c[i].center.y));
    r[i] = F(double(c[i].radius));
  }
  // Rows of M X = u + v r: M_i = -2 (c_i - c_0).
  const mpf_class m00 = -2 * (x[1] - x[0]), m01 = -2 * (y[1] - y[0]);
  const mpf_class m10 = -2 * (x[2] - x[0]), m11 = -2 * (y[2] - y[0]);
  const mpf_class det = m00 * m11 - m01 * m10;
  if (sign_of(det) == 0) {
    out.collinear = true;
    return out;
  }
  for (int pat = 0; pat < 8; ++pat) {
    const int s[3] = {pat & 1 ? -1 : 1, pat & 2 ? -1 : 1, pat & 4 ? -1 : 1};
    bool dup = false;  // a pattern differing only in the sign of a zero radius is the same
    for (int i = 0; i < 3; ++i)
      if (s[i] < 0 && c[i].radius == T(0)) dup = true;
    if (dup) continue;
    mpf_class u[2], v[2];
    for (int i = 1; i < 3; ++i) {
      u[i - 1] =
          r[i] * r[i] - r[0] * r[0] - (x[i] * x[i] + y[i] * y[i]) + (x[0] * x[0] + y[0] * y[0]);
      v[i - 1] = 2 * (s[i] * r[i] - s[0] * r[0]);
    }
    const mpf_class x0 = (u[0] * m11 - m01 * u[1]) / det, y0 = (m00 * u[1] - u[0] * m10) / det;
    const mpf_class x1 = (v[0] * m11 - m01 * v[1]) / det, y1 = (m00 * v[1] - v[0] * m10) / det;
    const mpf_class ax = x0 - x[0], ay = y0 - y[0];
    const mpf_class qa = x1 * x1 + y1 * y1 - 1;
    const mpf_class qb = 2 * (ax * x1 + ay * y1 - s[0] * r[0]);
    const mpf_class qc = ax * ax + ay * ay - r[0] * r[0];
    if (sign_of(qa) == 0) {
      if (sign_of(qb) != 0 && sign_of(mpf_class(-qc / qb)) > 0) ++out.circles;
    } else {
      const mpf_class disc = qb * qb - 4 * qa * qc;
      const int sd = sign_of(disc);
      if (sd == 0) {
        if (sign_of(mpf_class(-qb / (2 * qa))) > 0) ++out.circles;
      } else if (sd > 0) {
        const mpf_class sq = msqrt(disc);
        for (int k : {-1, 1})
          if (sign_of(mpf_class((-qb + k * sq) / (2 * qa))) > 0) ++out.circles;
      }
    }
    // Lines: m . (c_i - c_0) = -(s_i r_i - s_0 r_0), |m| = 1; s_0 = +1 only (s and -s: one line).
    if (s[0] < 0) continue;
    const mpf_class w0 = -(s[1] * r[1] - s[0] * r[0]), w1 = -(s[2] * r[2] - s[0] * r[0]);
    // (c1 - c0) . m = w0, (c2 - c0) . m = w1: rows are -M_i / 2.
    const mpf_class mx = (w0 * m11 - m01 * w1) / det * -2, my = (m00 * w1 - w0 * m10) / det * -2;
    if (sign_of(mpf_class(mx * mx + my * my - 1)) == 0) ++out.lines;
  }
  return out;
}

template <class T>
ApolloniusSolutions<T> check(const Circle2<T>& a, const Circle2<T>& b, const Circle2<T>& c,
                             bool compare = true) {
  const Circle2<T> in[3] = {a, b, c};
  const auto s = apollonius(a, b, c);
  EXPECT_EQ(s.circles.status, Status::ok);
  if (compare) {
    const OracleCount o = oracle(in);
    EXPECT_FALSE(o.collinear);
    EXPECT_EQ(s.circles.count, o.circles);
    EXPECT_EQ(s.lines.count, o.lines);
  }
  double S = 0;
  for (const auto& k : in) S = std::max({S, double(max_abs(k.center)), double(k.radius)});
  for (int i = 0; i < s.circles.count; ++i) {
    const ApolloniusCircle<T>& k = s.circles.item[static_cast<std::size_t>(i)];
    const double Si = std::max({S, double(max_abs(k.circle.center)), double(k.circle.radius)});
    for (int j = 0; j < 3; ++j) {
      const mpf_class d =
          dist(Cond::of(in[j].center), double(k.circle.center.x), double(k.circle.center.y));
      const mpf_class want = abs(F(double(k.circle.radius)) +
                                 k.s[static_cast<std::size_t>(j)] * F(double(in[j].radius)));
      EXPECT_LE(std::abs(mpf_class(d - want).get_d()), 256 * eps<T>() * Si * (1 + Si / S))
          << "circle " << i << " input " << j;
    }
  }
  for (int i = 0; i < s.lines.count; ++i) {
    const ApolloniusLine<T>& l = s.lines.item[static_cast<std::size_t>(i)];
    for (int j = 0; j < 3; ++j) {
      // Signed distance (left positive) equals s_j r_j.
      const mpf_class dx = F(double(in[j].center.x)) - F(double(l.line.origin.x));
      const mpf_class dy = F(double(in[j].center.y)) - F(double(l.line.origin.y));
      const mpf_class sd = F(double(l.line.direction.x)) * dy - F(double(l.line.direction.y)) * dx;
      const mpf_class want = l.s[static_cast<std::size_t>(j)] * F(double(in[j].radius));
      EXPECT_LE(std::abs(mpf_class(sd - want).get_d()), 256 * eps<T>() * S) << "line " << i;
    }
  }
  // Power-of-two scaling is exact; a quarter turn keeps the counts.
  const auto u = apollonius(scaled(a, 6), scaled(b, 6), scaled(c, 6));
  EXPECT_EQ(u.circles.count, s.circles.count);
  EXPECT_EQ(u.lines.count, s.lines.count);
  for (int i = 0; i < std::min(u.circles.count, s.circles.count); ++i)
    EXPECT_EQ(u.circles.item[static_cast<std::size_t>(i)].circle.center,
              scaled(s.circles.item[static_cast<std::size_t>(i)].circle.center, 6));
  const auto v = apollonius(rot(a), rot(b), rot(c));
  EXPECT_EQ(v.circles.count, s.circles.count);
  EXPECT_EQ(v.lines.count, s.lines.count);
  return s;
}

TYPED_TEST(ConstructApollonius, RandomAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int hist[9] = {};
  for (int it = 0; it < 50 && !this->HasFailure(); ++it) {
    const auto circ = [&] {
      return Circle2<T>{rng.vec<T, 2>(T(-4), T(4)), rng.uniform<T>(T(0.1), T(2.5))};
    };
    const auto s = check(circ(), circ(), circ());
    ++hist[std::clamp(s.circles.count, 0, 8)];
  }
  EXPECT_GT(hist[8], 0);  // the classic eight solutions occur
  EXPECT_GT(hist[0] + hist[2] + hist[4], 0);
}

TYPED_TEST(ConstructApollonius, DegenerateCases) {
  using T = TypeParam;
  // Three well-separated circles: eight.
  EXPECT_EQ(
      check(Circle2<T>{{0, 0}, 1}, Circle2<T>{{8, 0}, 2}, Circle2<T>{{3, 7}, 1.5}).circles.count,
      8);
  // c0 and c1 touch (3 = 1 + 2): the patterns through the contact point collapse (exact tie).
  check(Circle2<T>{{0, 0}, 1}, Circle2<T>{{3, 0}, 2}, Circle2<T>{{0, 5}, 1});
  check(Circle2<T>{{0, 0}, 1}, Circle2<T>{{5, 0}, 4}, Circle2<T>{{1, 6}, 2});
  // A common tangent line y = 0 (all above it): a line solution plus its finite partner.
  {
    const auto s = check(Circle2<T>{{0, 1}, 1}, Circle2<T>{{4, 2}, 2}, Circle2<T>{{10, 3}, 3});
    bool found = false;
    for (int i = 0; i < s.lines.count; ++i) {
      const auto& l = s.lines.item[static_cast<std::size_t>(i)].line;
      found =
          found || (std::abs(double(l.origin.y)) < 1e-5 && std::abs(double(l.direction.y)) < 1e-5);
    }
    EXPECT_TRUE(found);
  }
  // Three equal circles with collinear centres: the two lines y = +-1 and no circle touching
  // all three from outside (the oracle's elimination needs non-collinear centres).
  {
    const auto s =
        check(Circle2<T>{{0, 0}, 1}, Circle2<T>{{4, 0}, 1}, Circle2<T>{{10, 0}, 1}, false);
    EXPECT_EQ(s.lines.count, 2);
    for (int i = 0; i < s.circles.count; ++i) {
      const auto& k = s.circles.item[static_cast<std::size_t>(i)];
      EXPECT_FALSE(k.s[0] == k.s[1] && k.s[1] == k.s[2]);
    }
  }
  // Three points: the circle through them, once.
  {
    const auto s = check(Circle2<T>{{0, 0}, 0}, Circle2<T>{{6, 0}, 0}, Circle2<T>{{0, 8}, 0});
    ASSERT_EQ(s.circles.count, 1);
    EXPECT_NEAR(double(s.circles.item[0].circle.radius), 5.0, 16 * eps<T>());
  }
  // Two points and a circle.
  check(Circle2<T>{{0, 0}, 0}, Circle2<T>{{6, 0}, 0}, Circle2<T>{{2, 5}, 1});
  // Coincident input circles: infinitely many.
  EXPECT_TRUE(apollonius(Circle2<T>{{1, 1}, 2}, Circle2<T>{{1, 1}, 2}, Circle2<T>{{5, 0}, 1})
                  .circles.infinite);
  // Bad input.
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(apollonius(Circle2<T>{{nan, 1}, 2}, Circle2<T>{{1, 1}, 2}, Circle2<T>{{5, 0}, 1})
                .circles.status,
            Status::non_finite_input);
  const auto neg = apollonius(Circle2<T>{{0, 1}, -2}, Circle2<T>{{1, 1}, 2}, Circle2<T>{{5, 0}, 1});
  EXPECT_EQ(neg.circles.status, Status::degenerate_input);
  EXPECT_EQ(neg.circles.count + neg.lines.count, 0);
}

// Three circles through one common point: (P, 0) solves every sign pattern; it is reported once,
// with radius exactly 0, beside the circles of positive radius the oracle counts. Collinear
// centres share two points (mirror images), each reported once. Scaled by 2^6, the same.
TYPED_TEST(ConstructApollonius, CommonPointIsReportedOnce) {
  using T = TypeParam;
  const auto zero_radius = [](const ApolloniusSolutions<T>& s) {
    std::vector<Vec2<T>> z;
    for (int i = 0; i < s.circles.count; ++i) {
      const auto& k = s.circles.item[static_cast<std::size_t>(i)];
      if (k.circle.radius == T(0)) z.push_back(k.circle.center);
    }
    return z;
  };
  for (const int scale : {0, 6}) {
    const T f = std::ldexp(T(1), scale);
    // Through (3, 4): centres (0, 0), (6, 0), (3, 9), radius 5 each.
    const Circle2<T> a{{0, 0}, 5 * f}, b{{6 * f, 0}, 5 * f}, c{{3 * f, 9 * f}, 5 * f};
    const Circle2<T> in[3] = {a, b, c};
    const auto s = apollonius(a, b, c);
    ASSERT_EQ(s.circles.status, Status::ok);
    const auto z = zero_radius(s);
    ASSERT_EQ(z.size(), 1u) << "scale " << scale;
    EXPECT_NEAR(double(z[0].x), 3.0 * f, 64 * eps<T>() * 9 * f);
    EXPECT_NEAR(double(z[0].y), 4.0 * f, 64 * eps<T>() * 9 * f);
    EXPECT_EQ(s.circles.count, oracle(in).circles + 1);
    // Collinear centres (0, 0) r 5, (6, 0) r 5, (3, 0) r 4: both (3, 4) and (3, -4).
    const auto t = apollonius(Circle2<T>{{0, 0}, 5 * f}, Circle2<T>{{6 * f, 0}, 5 * f},
                              Circle2<T>{{3 * f, 0}, 4 * f});
    auto zt = zero_radius(t);
    ASSERT_EQ(zt.size(), 2u) << "scale " << scale;
    std::sort(zt.begin(), zt.end(), [](const Vec2<T>& p, const Vec2<T>& q) { return p.y < q.y; });
    EXPECT_NEAR(double(zt[0].y), -4.0 * f, 64 * eps<T>() * 9 * f);
    EXPECT_NEAR(double(zt[1].y), 4.0 * f, 64 * eps<T>() * 9 * f);
  }
  // Moved off the common point by one ulp of the third radius: no radius-0 circle.
  const Circle2<T> off{{3, 9}, std::nextafter(T(5), T(6))};
  EXPECT_TRUE(zero_radius(apollonius(Circle2<T>{{0, 0}, 5}, Circle2<T>{{6, 0}, 5}, off)).empty());
}

}  // namespace
