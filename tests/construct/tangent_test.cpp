// SPDX-License-Identifier: BSL-1.0
// Rows cons2.tangent-at, cons2.tangent-through, cons2.tangent-2circles, cons2.lines:
// tangent_line_at(), tangent_lines() (point-circle, circle-circle) and the line constructions of
// 8.30-8.34, float and double. Counts against exact oracles (GMP rationals: the sign of
// |p - c|^2 - r^2; for two circles the distance compared with r0 + r1 and |r0 - r1| in 1024-bit
// GMP floats). Every line is checked in GMP: unit direction, distance to each centre equal to
// the radius, passing through the given point, origin on the circle. Figures 8.3-8.7 and
// 8.30-8.34; exact ties (integer points on circles, touching circles, coincident and concentric
// circles); NaN/Inf; power-of-two scaling; 90 degree rotations.

#include <locus/construct/lines.hpp>
#include <locus/construct/tangent_lines.hpp>

#include <cmath>
#include <limits>

#include "construct/oracle.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using namespace locus_test::cons;
using locus_test::Rng;

template <class T>
class ConstructTangent : public ::testing::Test {};
TYPED_TEST_SUITE(ConstructTangent, locus_test::RealTypes);

template <class T>
constexpr double eps() {
  return double(std::numeric_limits<T>::epsilon());
}

// Distance from p to the line, in GMP.
template <class T>
double line_dist(const Line2<T>& l, const Vec2<T>& p) {
  return dist(Cond::of(l), double(p.x), double(p.y)).get_d();
}
template <class T>
void expect_tangent(const Line2<T>& l, const Circle2<T>& c, double tol) {
  EXPECT_NEAR(double(length(l.direction)), 1.0, 4 * eps<T>());
  EXPECT_LE(residual(Cond::of(l), double(c.center.x), double(c.center.y), double(c.radius)), tol);
}

template <class T>
void check_through(const Vec2<T>& p, const Circle2<T>& c) {
  const auto s = tangent_lines(p, c);
  ASSERT_EQ(s.status, Status::ok);
  const mpq_class dx = mpq_class(p.x) - c.center.x, dy = mpq_class(p.y) - c.center.y;
  const int side = sgn(mpq_class(dx * dx + dy * dy - mpq_class(c.radius) * c.radius));
  ASSERT_EQ(s.count, side < 0 ? 0 : (side == 0 ? 1 : 2));
  const double S = std::max({double(max_abs(p)), double(max_abs(c.center)), double(c.radius)});
  for (int i = 0; i < s.count; ++i) {
    const Line2<T>& l = s.item[static_cast<std::size_t>(i)];
    expect_tangent(l, c, 32 * eps<T>() * S);
    EXPECT_LE(line_dist(l, p), 32 * eps<T>() * S);
    EXPECT_LE(
        residual(Cond::of(l.origin), double(c.center.x), double(c.center.y), double(c.radius)),
        32 * eps<T>() * S);
  }
  const auto u = tangent_lines(scaled(p, 9), scaled(c, 9));
  ASSERT_EQ(u.count, s.count);
  for (int i = 0; i < s.count; ++i) {
    EXPECT_EQ(u.item[static_cast<std::size_t>(i)].origin,
              scaled(s.item[static_cast<std::size_t>(i)].origin, 9));
    EXPECT_EQ(u.item[static_cast<std::size_t>(i)].direction,
              s.item[static_cast<std::size_t>(i)].direction);
  }
  EXPECT_EQ(tangent_lines(rot(p), rot(c)).count, s.count);
}

template <class T>
int oracle_two(const Circle2<T>& a, const Circle2<T>& b, bool& inf) {
  const mpf_class d = dist(Cond::of(a.center), double(b.center.x), double(b.center.y));
  inf = false;
  if (sign_of(d) == 0) {
    inf = a.radius == b.radius;
    return 0;
  }
  const int outer = sign_of(d - abs(F(double(a.radius)) - F(double(b.radius))));
  const int inner = sign_of(d - (F(double(a.radius)) + F(double(b.radius))));
  return (outer < 0 ? 0 : (outer == 0 ? 1 : 2)) + (inner < 0 ? 0 : (inner == 0 ? 1 : 2));
}

template <class T>
void check_two(const Circle2<T>& a, const Circle2<T>& b) {
  const auto s = tangent_lines(a, b);
  ASSERT_EQ(s.status, Status::ok);
  bool inf = false;
  ASSERT_EQ(s.count, oracle_two(a, b, inf));
  EXPECT_EQ(s.infinite, inf);
  const double S = std::max(
      {double(max_abs(a.center)), double(max_abs(b.center)), double(a.radius), double(b.radius)});
  for (int i = 0; i < s.count; ++i) {
    const Line2<T>& l = s.item[static_cast<std::size_t>(i)];
    expect_tangent(l, a, 32 * eps<T>() * S);
    expect_tangent(l, b, 32 * eps<T>() * S);
    for (int j = 0; j < i; ++j)  // distinct lines
      EXPECT_FALSE(line_dist(s.item[static_cast<std::size_t>(j)], l.origin) < 1e-3 &&
                   std::abs(double(perp_dot(s.item[static_cast<std::size_t>(j)].direction,
                                            l.direction))) < 1e-3);
  }
  const auto u = tangent_lines(scaled(a, -8), scaled(b, -8));
  ASSERT_EQ(u.count, s.count);
  for (int i = 0; i < s.count; ++i)
    EXPECT_EQ(u.item[static_cast<std::size_t>(i)].origin,
              scaled(s.item[static_cast<std::size_t>(i)].origin, -8));
  EXPECT_EQ(tangent_lines(rot(a), rot(b)).count, s.count);
}

TYPED_TEST(ConstructTangent, ThroughAPoint) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 200 && !this->HasFailure(); ++it)
    check_through(rng.vec<T, 2>(T(-4), T(4)),
                  Circle2<T>{rng.vec<T, 2>(T(-2), T(2)), rng.uniform<T>(T(0.1), T(4))});
  // Figures 8.4, 8.5: outside (two), on the circle (one, an exact integer tie), inside (none).
  const Circle2<T> c{{1, 2}, 5};
  check_through(Vec2<T>{9, 9}, c);
  check_through(Vec2<T>{4, 6}, c);
  check_through(Vec2<T>{-2, -2}, c);
  check_through(Vec2<T>{2, 2}, c);
  EXPECT_EQ(tangent_lines(Vec2<T>{4, 6}, c).count, 1);
  EXPECT_EQ(tangent_lines(Vec2<T>{2, 2}, c).count, 0);
  // The tangent at a point (figure 8.3), also for a point off the circle (projected).
  for (const Vec2<T>& p : {Vec2<T>{4, 6}, Vec2<T>{9, 9}, Vec2<T>{1, 1}}) {
    const auto t = tangent_line_at(c, p);
    ASSERT_EQ(t.count, 1);
    expect_tangent(t.item[0], c, 32 * eps<T>() * 10);
    EXPECT_LE(std::abs(double(dot(t.item[0].direction, p - c.center))),
              8 * eps<T>() * double(length(p - c.center)));
  }
  EXPECT_EQ(tangent_line_at(c, c.center).count, 0);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(tangent_lines(Vec2<T>{nan, 0}, c).status, Status::non_finite_input);
  EXPECT_EQ(tangent_lines(Vec2<T>{0, 0}, Circle2<T>{{0, 0}, 0}).status, Status::degenerate_input);
  EXPECT_EQ(tangent_line_at(Circle2<T>{{0, 0}, -1}, Vec2<T>{1, 0}).status,
            Status::degenerate_input);
}

TYPED_TEST(ConstructTangent, TwoCircles) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 200 && !this->HasFailure(); ++it)
    check_two(Circle2<T>{rng.vec<T, 2>(T(-4), T(4)), rng.uniform<T>(T(0.1), T(4))},
              Circle2<T>{rng.vec<T, 2>(T(-4), T(4)), rng.uniform<T>(T(0.1), T(4))});
  // Figure 8.7: separate (4), externally tangent (3), crossing (2), internally tangent (1),
  // nested (0), concentric (0), coincident (infinitely many). Centres 10 apart.
  const Circle2<T> a{{0, 0}, 2};
  const int want[] = {4, 3, 2, 1, 0};
  const T rb[] = {3, 8, 9, 12, 13};
  for (int i = 0; i < 5; ++i) {
    check_two(a, Circle2<T>{{6, 8}, rb[i]});
    EXPECT_EQ(tangent_lines(a, Circle2<T>{{6, 8}, rb[i]}).count, want[i]);
  }
  check_two(a, Circle2<T>{{0, 0}, 3});
  check_two(a, a);
  EXPECT_TRUE(tangent_lines(a, a).infinite);
  EXPECT_EQ(tangent_lines(a, Circle2<T>{{0, std::numeric_limits<T>::infinity()}, 1}).status,
            Status::non_finite_input);
}

TYPED_TEST(ConstructTangent, LineConstructions) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double tol = 16 * eps<T>() * 8;
  for (int it = 0; it < 100; ++it) {
    const Line2<T> l{rng.vec<T, 2>(T(-4), T(4)), rng.vec<T, 2>(T(-2), T(2))};
    const Vec2<T> p = rng.vec<T, 2>(T(-4), T(4)), q = rng.vec<T, 2>(T(-4), T(4));
    const T d = rng.uniform<T>(T(0), T(3));
    // 8.30: through p, perpendicular to l.
    const auto n = normal_line(l, p);
    ASSERT_EQ(n.count, 1);
    EXPECT_LE(line_dist(n.item[0], p), tol);
    EXPECT_LE(std::abs(double(dot(n.item[0].direction, l.direction))),
              4 * eps<T>() * double(length(l.direction)));
    // 8.31: every point of the bisector is equidistant from p and q.
    const auto b = perpendicular_bisector(p, q);
    ASSERT_EQ(b.count, 1);
    for (T t : {T(-2), T(0), T(3)}) {
      const Vec2<T> x = point_at(b.item[0], t);
      EXPECT_NEAR(double(length(x - p)), double(length(x - q)), tol);
    }
    // 8.32: both parallels at distance d.
    const auto pl = parallel_lines(l, d);
    ASSERT_EQ(pl.count, 2);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(line_dist(l, pl.item[static_cast<std::size_t>(i)].origin), double(d), tol);
      EXPECT_EQ(pl.item[static_cast<std::size_t>(i)].direction, normalize(l.direction));
    }
    // 8.33: vertical and horizontal offsets.
    const auto pv = parallel_lines_vertical(l, d), ph = parallel_lines_horizontal(l, d);
    ASSERT_EQ(pv.count, 2);
    ASSERT_EQ(ph.count, 2);
    EXPECT_EQ(pv.item[1].origin, (l.origin + Vec2<T>{0, d}));
    EXPECT_EQ(ph.item[0].origin, (l.origin - Vec2<T>{d, 0}));
    // 8.34: the two tangents of a circle perpendicular to l.
    const Circle2<T> c{q, d + T(0.5)};
    const auto tn = tangent_lines_normal_to(c, l);
    ASSERT_EQ(tn.count, 2);
    for (int i = 0; i < 2; ++i) {
      expect_tangent(tn.item[static_cast<std::size_t>(i)], c, tol);
      EXPECT_LE(std::abs(double(dot(tn.item[static_cast<std::size_t>(i)].direction, l.direction))),
                4 * eps<T>() * double(length(l.direction)));
    }
  }
  // Exact cases: a vertical line shifted vertically is itself; a zero offset gives one line;
  // p == q has no bisector; bad input.
  EXPECT_EQ(parallel_lines_vertical(Line2<T>{{1, 1}, {0, 2}}, T(1)).count, 1);
  EXPECT_EQ(parallel_lines_horizontal(Line2<T>{{1, 1}, {3, 0}}, T(1)).count, 1);
  EXPECT_EQ(parallel_lines(Line2<T>{{1, 1}, {3, 0}}, T(0)).count, 1);
  EXPECT_EQ(perpendicular_bisector(Vec2<T>{1, 1}, Vec2<T>{1, 1}).status, Status::degenerate_input);
  EXPECT_EQ(parallel_lines(Line2<T>{{1, 1}, {3, 0}}, T(-1)).status, Status::degenerate_input);
  EXPECT_EQ(normal_line(Line2<T>{{1, 1}, {0, 0}}, Vec2<T>{0, 0}).status, Status::degenerate_input);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(normal_line(Line2<T>{{1, 1}, {1, 0}}, Vec2<T>{nan, 0}).status,
            Status::non_finite_input);
  EXPECT_EQ(tangent_lines_normal_to(Circle2<T>{{0, 0}, nan}, Line2<T>{{1, 1}, {1, 0}}).status,
            Status::non_finite_input);
}

}  // namespace
