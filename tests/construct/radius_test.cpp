// SPDX-License-Identifier: BSL-1.0
// Rows cons2.circle-2pts-r, -pt-line-r, -2lines-r, -pt-circle-r, -line-circle-r, -2circles-r:
// circles_of_radius() for the six argument pairs, float and double. Every returned circle has
// radius r and meets both conditions within the header's 64 eps S (residuals evaluated in
// 1024-bit GMP floats on the exact inputs); the count (and `infinite`) equals the oracle's
// locus-by-locus count (oracle.hpp). Inputs: seeded random, integer/Pythagorean configurations
// where a count changes exactly (tangent loci, parallel lines 2r apart, concentric circles),
// NaN/Inf and bad radii, power-of-two scaling (exactly covariant) and 90 degree rotations.

#include <locus/construct/circles_of_radius.hpp>

#include <cmath>
#include <limits>

#include "construct/oracle.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using namespace locus_test::cons;
using locus_test::Rng;

template <class T>
class ConstructRadius : public ::testing::Test {};
TYPED_TEST_SUITE(ConstructRadius, locus_test::RealTypes);

template <class T>
constexpr double eps() {
  return double(std::numeric_limits<T>::epsilon());
}

// Checks one call against the oracle; returns the count.
template <class T, class A, class B>
int check(const A& a, const B& b, T r) {
  const auto s = circles_of_radius(a, b, r);
  EXPECT_EQ(s.status, Status::ok);
  const Cond ca = Cond::of(a), cb = Cond::of(b);
  const int want = radius_count(ca, cb, double(r));
  if (want < 0) {
    EXPECT_TRUE(s.infinite);
    EXPECT_EQ(s.count, -1 - want);
  } else {
    EXPECT_FALSE(s.infinite);
    EXPECT_EQ(s.count, want);
  }
  const double base = std::max({ca.magnitude(), cb.magnitude(), double(r)});
  for (int i = 0; i < s.count; ++i) {
    const auto& c = s.item[static_cast<std::size_t>(i)];
    EXPECT_EQ(c.radius, r);
    const double x = double(c.center.x), y = double(c.center.y);
    const double S = std::max({base, std::abs(x), std::abs(y)});
    EXPECT_LE(residual(ca, x, y, double(r)), 64 * eps<T>() * S) << "solution " << i;
    EXPECT_LE(residual(cb, x, y, double(r)), 64 * eps<T>() * S) << "solution " << i;
  }
  // The swapped overload, where there is one, gives the same answer.
  if constexpr (!std::is_same_v<A, B> && requires { circles_of_radius(b, a, r); }) {
    const auto t = circles_of_radius(b, a, r);
    EXPECT_EQ(t.count, s.count);
    for (int i = 0; i < s.count; ++i)
      EXPECT_EQ(t.item[static_cast<std::size_t>(i)].center,
                s.item[static_cast<std::size_t>(i)].center);
  }
  // Scaling by a power of two scales every solution exactly; rotating by 90 degrees rotates them.
  for (int k : {-9, 7}) {
    const auto u = circles_of_radius(scaled(a, k), scaled(b, k), scaled(r, k));
    EXPECT_EQ(u.count, s.count);
    EXPECT_EQ(u.infinite, s.infinite);
    for (int i = 0; i < std::min(u.count, s.count); ++i)
      EXPECT_EQ(u.item[static_cast<std::size_t>(i)].center,
                scaled(s.item[static_cast<std::size_t>(i)].center, k));
  }
  const auto v = circles_of_radius(rot(a), rot(b), r);
  EXPECT_EQ(v.count, s.count);
  for (int i = 0; i < std::min(v.count, s.count); ++i) {
    const Vec2<T> w = rot(s.item[static_cast<std::size_t>(i)].center);
    const Vec2<T> got = v.item[static_cast<std::size_t>(i)].center;
    const double S = std::max(base, double(max_abs(w)));
    EXPECT_LE(double(max_abs(got - w)), 128 * eps<T>() * S) << "rotated solution " << i;
  }
  return s.infinite ? -1 : s.count;
}

template <class T>
Line2<T> random_line(Rng& rng) {
  Vec2<T> d = rng.vec<T, 2>(T(-2), T(2));
  if (d == Vec2<T>{}) d = {T(1), T(0)};
  return {rng.vec<T, 2>(T(-4), T(4)), d};
}
template <class T>
Circle2<T> random_circle(Rng& rng) {
  return {rng.vec<T, 2>(T(-4), T(4)), rng.uniform<T>(T(0.2), T(3))};
}

TYPED_TEST(ConstructRadius, RandomAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int seen[9] = {};
  for (int it = 0; it < 60; ++it) {
    const T r = rng.uniform<T>(T(0.2), T(3));
    const Vec2<T> p = rng.vec<T, 2>(T(-4), T(4)), q = rng.vec<T, 2>(T(-4), T(4));
    const Line2<T> l0 = random_line<T>(rng), l1 = random_line<T>(rng);
    const Circle2<T> c0 = random_circle<T>(rng), c1 = random_circle<T>(rng);
    const int n[6] = {check(p, q, r),  check(p, l0, r),  check(l0, l1, r),
                      check(p, c0, r), check(l0, c0, r), check(c0, c1, r)};
    for (int k : n) ++seen[std::clamp(k, 0, 8)];
    if (this->HasFailure()) return;
  }
  // The random sample reaches the different counts.
  EXPECT_GT(seen[0], 0);
  EXPECT_GT(seen[2], 0);
  EXPECT_GT(seen[4], 0);
}

TYPED_TEST(ConstructRadius, ExactTiesAndFigures) {
  using T = TypeParam;
  // Figures 8.8-8.10: two points 10 apart, r = 5 (one), 6 (two), 4 (none); coincident points.
  EXPECT_EQ(check(Vec2<T>{0, 0}, Vec2<T>{6, 8}, T(5)), 1);
  EXPECT_EQ(check(Vec2<T>{0, 0}, Vec2<T>{6, 8}, T(6)), 2);
  EXPECT_EQ(check(Vec2<T>{0, 0}, Vec2<T>{6, 8}, T(4)), 0);
  EXPECT_EQ(check(Vec2<T>{1, 2}, Vec2<T>{1, 2}, T(4)), -1);
  // Figures 8.11-8.13: line through (1, 2) along (3, 4); p on the line, 2r away, beyond, inside.
  const Line2<T> l{{1, 2}, {3, 4}};
  EXPECT_EQ(check(Vec2<T>{7, 10}, l, T(5)), 2);
  EXPECT_EQ(check(Vec2<T>{-7, 8}, l, T(5)), 1);
  EXPECT_EQ(check(Vec2<T>{-7, 8}, l, T(4)), 0);
  EXPECT_EQ(check(Vec2<T>{-7, 8}, l, T(6)), 2);
  // Figures 8.14-8.16: crossing lines (four), parallel lines exactly 2r = 10 apart, 12 apart.
  EXPECT_EQ(check(l, Line2<T>{{0, 0}, {1, -2}}, T(1)), 4);
  EXPECT_EQ(check(Line2<T>{{0, 0}, {3, 4}}, Line2<T>{{-8, 6}, {-6, -8}}, T(5)), -1);
  EXPECT_EQ(check(Line2<T>{{0, 0}, {3, 4}}, Line2<T>{{-8, 6}, {-6, -8}}, T(6)), 0);
  EXPECT_EQ(check(Line2<T>{{0, 0}, {3, 4}}, Line2<T>{{0, 0}, {6, 8}}, T(6)), -1);  // coincident
  // Figures 8.17-8.21: circle (1, 1) radius 3, r = 2: p 7 away (one, external), on the circle
  // (two), 4 away (two: the inner locus is out of reach), 1 away (one: the inner locus
  // touches), at the centre (none), centre with R = 2r (infinite); R = 1, r = 3: four.
  const Circle2<T> c{{1, 1}, 3};
  EXPECT_EQ(check(Vec2<T>{8, 1}, c, T(2)), 1);
  EXPECT_EQ(check(Vec2<T>{4, 1}, c, T(2)), 2);
  EXPECT_EQ(check(Vec2<T>{1, 5}, c, T(2)), 2);
  EXPECT_EQ(check(Vec2<T>{2, 1}, c, T(2)), 1);
  EXPECT_EQ(check(Vec2<T>{1, 1}, c, T(2)), 0);
  EXPECT_EQ(check(Vec2<T>{1, 1}, Circle2<T>{{1, 1}, 4}, T(2)), -1);
  EXPECT_EQ(check(Vec2<T>{1, 3}, Circle2<T>{{1, 1}, 4}, T(3)), 1);
  EXPECT_EQ(check(Vec2<T>{1, 4}, Circle2<T>{{1, 1}, 1}, T(3)), 4);
  // Figures 8.22-8.26: line (0, 0) along (3, 4), circle centre (-4, 3) (5 from the line).
  const Line2<T> m{{0, 0}, {3, 4}};
  EXPECT_EQ(check(m, Circle2<T>{{-4, 3}, 2}, T(1.5)), 1);  // the external locus touches
  EXPECT_EQ(check(m, Circle2<T>{{-4, 3}, 2}, T(1)), 0);    // figure 8.24: r too small
  EXPECT_EQ(check(m, Circle2<T>{{-4, 3}, 2}, T(2)), 2);
  EXPECT_EQ(check(m, Circle2<T>{{-4, 3}, 6}, T(2)), 6);
  EXPECT_EQ(check(m, Circle2<T>{{-4, 3}, 5}, T(2)), 4);  // the circle touches the line
  // Figures 8.27-8.29: circles (0, 0) r 2 and (6, 8) r 3, 10 apart.
  const Circle2<T> a{{0, 0}, 2}, b{{6, 8}, 3};
  EXPECT_EQ(check(a, b, T(2.5)), 1);  // external / external touching
  EXPECT_EQ(check(a, b, T(1)), 0);
  EXPECT_EQ(check(a, b, T(4)), 2);
  EXPECT_EQ(check(a, Circle2<T>{{3, 4}, 4}, T(1)), 6);
  EXPECT_EQ(check(Circle2<T>{{1, 1}, 1}, Circle2<T>{{1, 1}, 5}, T(2)), -1);  // concentric annulus
}

TYPED_TEST(ConstructRadius, BadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Vec2<T> p{0, 0}, q{1, 0};
  const Line2<T> l{{0, 0}, {1, 0}};
  const Circle2<T> c{{0, 0}, 1};
  EXPECT_EQ(circles_of_radius(p, Vec2<T>{nan, 0}, T(1)).status, Status::non_finite_input);
  EXPECT_EQ(circles_of_radius(p, q, inf).status, Status::non_finite_input);
  EXPECT_EQ(circles_of_radius(p, q, T(0)).status, Status::degenerate_input);
  EXPECT_EQ(circles_of_radius(p, q, T(-1)).status, Status::degenerate_input);
  EXPECT_EQ(circles_of_radius(p, Line2<T>{{0, 0}, {0, 0}}, T(1)).status, Status::degenerate_input);
  EXPECT_EQ(circles_of_radius(Line2<T>{{inf, 0}, {1, 0}}, l, T(1)).status,
            Status::non_finite_input);
  EXPECT_EQ(circles_of_radius(p, Circle2<T>{{0, 0}, 0}, T(1)).status, Status::degenerate_input);
  EXPECT_EQ(circles_of_radius(l, Circle2<T>{{0, nan}, 1}, T(1)).status, Status::non_finite_input);
  EXPECT_EQ(circles_of_radius(c, Circle2<T>{{0, 0}, -1}, T(1)).status, Status::degenerate_input);
  EXPECT_EQ(circles_of_radius(c, c, nan).count, 0);
}

}  // namespace
