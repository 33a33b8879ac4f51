// SPDX-License-Identifier: BSL-1.0
// Rows cons2.circle3pts and cons2.circle3lines: circle_through(), circles_tangent_to(three
// lines), incircle(), excircles(), float and double. Oracles: the exact orientation of the three
// points (GMP rationals) decides whether the circle exists; for three lines each of the four sign
// patterns is solved again in 1024-bit GMP floats (a pattern counts when its system is regular
// and its radius non-zero), and two coincident lines (exact rationals) mean infinitely many.
// Every returned circle passes through the points / touches the lines within the header's bound
// (residuals in GMP). Figures 8.1, 8.2; degenerate inputs (collinear, coincident, parallel,
// concurrent); NaN/Inf; power-of-two scaling; 90 degree rotations.

#include <locus/construct/circle_through.hpp>
#include <locus/construct/solutions.hpp>

#include <cmath>
#include <limits>

#include "construct/oracle.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using namespace locus_test::cons;
using locus_test::Rng;

template <class T>
class ConstructCircle : public ::testing::Test {};
TYPED_TEST_SUITE(ConstructCircle, locus_test::RealTypes);

template <class T>
constexpr double eps() {
  return double(std::numeric_limits<T>::epsilon());
}

template <class T>
int exact_orient(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c) {
  const mpq_class v = (mpq_class(b.x) - a.x) * (mpq_class(c.y) - a.y) -
                      (mpq_class(b.y) - a.y) * (mpq_class(c.x) - a.x);
  return sgn(v);
}

template <class T>
void check_points(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c) {
  const auto s = circle_through(a, b, c);
  ASSERT_EQ(s.status, Status::ok);
  ASSERT_EQ(s.count, exact_orient(a, b, c) != 0 ? 1 : 0);
  if (s.count == 0) return;
  const Circle2<T> k = s.item[0];
  const double S = std::max({double(max_abs(a)), double(max_abs(b)), double(max_abs(c)),
                             double(max_abs(k.center)), double(k.radius)});
  for (const Vec2<T>& p : {a, b, c})
    EXPECT_LE(residual(Cond::of(p), double(k.center.x), double(k.center.y), double(k.radius)),
              64 * eps<T>() * S);
  const auto u = circle_through(scaled(a, 5), scaled(b, 5), scaled(c, 5));
  EXPECT_EQ(u.item[0].center, scaled(k.center, 5));
  EXPECT_EQ(u.item[0].radius, scaled(k.radius, 5));
  const auto v = circle_through(rot(a), rot(b), rot(c));
  EXPECT_LE(double(max_abs(v.item[0].center - rot(k.center))), 16 * eps<T>() * S);
}

TYPED_TEST(ConstructCircle, ThroughThreePoints) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 200 && !this->HasFailure(); ++it)
    check_points(rng.vec<T, 2>(T(-4), T(4)), rng.vec<T, 2>(T(-4), T(4)),
                 rng.vec<T, 2>(T(-4), T(4)));
  // Figure 8.1, collinear and coincident points, a right triangle (centre at the hypotenuse).
  check_points(Vec2<T>{1, 1}, Vec2<T>{5, 2}, Vec2<T>{2, 4});
  check_points(Vec2<T>{0, 0}, Vec2<T>{1, 1}, Vec2<T>{3, 3});
  check_points(Vec2<T>{2, 1}, Vec2<T>{2, 1}, Vec2<T>{3, 3});
  check_points(Vec2<T>{0, 0}, Vec2<T>{6, 0}, Vec2<T>{0, 8});
  // Nearly collinear: the centre runs far away; the bound is relative to |centre|.
  for (T tiny : {T(1e-3), T(1e-5), T(std::numeric_limits<T>::epsilon() * 4)})
    check_points(Vec2<T>{-1, 0.5}, Vec2<T>{0.25, T(0.5) + tiny}, Vec2<T>{2, 0.5});
  EXPECT_EQ(circle_through(Vec2<T>{0, 0}, Vec2<T>{6, 0}, Vec2<T>{0, 8}).item[0].radius, T(5));
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(circle_through(Vec2<T>{0, 0}, Vec2<T>{nan, 0}, Vec2<T>{0, 8}).status,
            Status::non_finite_input);
}

// The oracle count for three lines: the patterns whose system is regular with r != 0.
template <class T>
int lines_oracle(const Line2<T> (&l)[3], bool& infinite) {
  infinite = false;
  for (int j = 0; j < 3; ++j)
    for (int k = j + 1; k < 3; ++k) {
      const mpq_class cr = mpq_class(l[j].direction.x) * l[k].direction.y -
                           mpq_class(l[j].direction.y) * l[k].direction.x;
      const mpq_class off =
          mpq_class(l[j].direction.x) * (mpq_class(l[k].origin.y) - l[j].origin.y) -
          mpq_class(l[j].direction.y) * (mpq_class(l[k].origin.x) - l[j].origin.x);
      if (sgn(cr) == 0 && sgn(off) == 0) infinite = true;
    }
  if (infinite) return 0;
  int count = 0;
  for (int pat = 0; pat < 4; ++pat) {
    mpf_class m[3][4];
    for (int i = 0; i < 3; ++i) {
      const mpf_class dx = F(double(l[i].direction.x)), dy = F(double(l[i].direction.y));
      const mpf_class len = msqrt(dx * dx + dy * dy);
      const mpf_class nx = -dy / len, ny = dx / len;
      m[i][0] = nx;
      m[i][1] = ny;
      m[i][2] = (pat == i + 1) ? F(1) : F(-1);  // -e_i
      m[i][3] = nx * F(double(l[i].origin.x)) + ny * F(double(l[i].origin.y));
    }
    const auto det = [&](int c0, int c1, int c2) {
      return mpf_class(m[0][c0] * (m[1][c1] * m[2][c2] - m[1][c2] * m[2][c1]) -
                       m[0][c1] * (m[1][c0] * m[2][c2] - m[1][c2] * m[2][c0]) +
                       m[0][c2] * (m[1][c0] * m[2][c1] - m[1][c1] * m[2][c0]));
    };
    const mpf_class d = det(0, 1, 2);
    if (sign_of(d) == 0) continue;
    if (sign_of(mpf_class(det(0, 1, 3) / d)) != 0) ++count;
  }
  return count;
}

template <class T>
void check_lines(const Line2<T>& a, const Line2<T>& b, const Line2<T>& c) {
  const Line2<T> l[3] = {a, b, c};
  bool inf = false;
  const int want = lines_oracle(l, inf);
  const auto s = circles_tangent_to(a, b, c);
  ASSERT_EQ(s.status, Status::ok);
  EXPECT_EQ(s.infinite, inf);
  ASSERT_EQ(s.count, want);
  for (int i = 0; i < s.count; ++i) {
    const Circle2<T> k = s.item[static_cast<std::size_t>(i)];
    double S = std::max(double(max_abs(k.center)), double(k.radius));
    for (const auto& x : l) S = std::max(S, double(max_abs(x.origin)));
    for (const auto& x : l)
      EXPECT_LE(residual(Cond::of(x), double(k.center.x), double(k.center.y), double(k.radius)),
                64 * eps<T>() * S)
          << "circle " << i;
  }
  const auto u = circles_tangent_to(scaled(a, -6), scaled(b, -6), scaled(c, -6));
  ASSERT_EQ(u.count, s.count);
  for (int i = 0; i < s.count; ++i)
    EXPECT_EQ(u.item[static_cast<std::size_t>(i)].center,
              scaled(s.item[static_cast<std::size_t>(i)].center, -6));
  const auto v = circles_tangent_to(rot(a), rot(b), rot(c));
  ASSERT_EQ(v.count, s.count);
}

TYPED_TEST(ConstructCircle, TangentToThreeLines) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto line = [&] {
    Vec2<T> d = rng.vec<T, 2>(T(-2), T(2));
    if (d == Vec2<T>{}) d = {T(1), T(0)};
    return Line2<T>{rng.vec<T, 2>(T(-4), T(4)), d};
  };
  for (int it = 0; it < 100 && !this->HasFailure(); ++it) check_lines(line(), line(), line());
  // Figure 8.2 (a triangle's lines: four circles); a parallel pair (two); three parallels (none);
  // three concurrent lines (none); a coincident pair (infinitely many); reversed directions.
  const Line2<T> a{{0, 0}, {4, 0}}, b{{4, 0}, {-4, 3}}, c{{0, 3}, {0, -3}};
  check_lines(a, b, c);
  check_lines(Line2<T>{{4, 0}, {-4, 0}}, b, Line2<T>{{0, 0}, {0, 3}});
  check_lines(a, Line2<T>{{0, 2}, {-8, 0}}, c);
  check_lines(a, Line2<T>{{0, 2}, {3, 0}}, Line2<T>{{5, 5}, {1, 0}});
  check_lines(a, Line2<T>{{0, 0}, {1, 1}}, Line2<T>{{2, 2}, {-1, 3}});
  check_lines(a, Line2<T>{{7, 0}, {-2, 0}}, c);
  check_lines(a, Line2<T>{{7, 0}, {-2, 0}}, Line2<T>{{0, 5}, {3, 0}});
  // Nearly parallel pairs: two of the circles grow huge.
  for (T tiny : {T(1e-3), T(1e-6)}) check_lines(a, Line2<T>{{0, 2}, {-8, tiny}}, c);
  EXPECT_EQ(circles_tangent_to(a, b, c).count, 4);
  EXPECT_EQ(circles_tangent_to(a, Line2<T>{{0, 2}, {-8, 0}}, c).count, 2);
  EXPECT_TRUE(circles_tangent_to(a, Line2<T>{{7, 0}, {-2, 0}}, Line2<T>{{0, 5}, {3, 0}}).infinite);
  const T inf = std::numeric_limits<T>::infinity();
  EXPECT_EQ(circles_tangent_to(a, b, Line2<T>{{inf, 0}, {1, 0}}).status, Status::non_finite_input);
  EXPECT_EQ(circles_tangent_to(a, b, Line2<T>{{0, 0}, {0, 0}}).status, Status::degenerate_input);
}

TYPED_TEST(ConstructCircle, IncircleAndExcircles) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 100; ++it) {
    Triangle2<T> t{rng.vec<T, 2>(T(-4), T(4)), rng.vec<T, 2>(T(-4), T(4)),
                   rng.vec<T, 2>(T(-4), T(4))};
    const int o = exact_orient(t.v0, t.v1, t.v2);
    const auto in = incircle(t);
    const auto ex = excircles(t);
    ASSERT_EQ(in.count, o != 0 ? 1 : 0);
    ASSERT_EQ(ex.count, o != 0 ? 3 : 0);
    if (o == 0) continue;
    // The incentre is inside; the excircle opposite v_i lies beyond the edge v_(i+1) v_(i+2).
    for (int e = 0; e < 3; ++e) {
      const Vec2<T>& p = t[e];
      const Vec2<T>& q = t[(e + 1) % 3];
      EXPECT_EQ(exact_orient(p, q, in.item[0].center), o);
    }
    for (int i = 0; i < 3; ++i) {
      const Vec2<T>& p = t[(i + 1) % 3];
      const Vec2<T>& q = t[(i + 2) % 3];
      EXPECT_EQ(exact_orient(p, q, ex.item[static_cast<std::size_t>(i)].center), -o) << i;
      EXPECT_GT(ex.item[static_cast<std::size_t>(i)].radius, in.item[0].radius);
    }
  }
  // A 3-4-5 right triangle: inradius 1, exradii 6 (opposite the right angle), 2 and 3.
  const auto in = incircle(Triangle2<T>{{0, 0}, {4, 0}, {0, 3}});
  const auto ex = excircles(Triangle2<T>{{0, 0}, {4, 0}, {0, 3}});
  EXPECT_NEAR(double(in.item[0].radius), 1.0, 8 * eps<T>());
  EXPECT_NEAR(double(ex.item[0].radius), 6.0, 64 * eps<T>());
  EXPECT_NEAR(double(ex.item[1].radius), 2.0, 64 * eps<T>());
  EXPECT_NEAR(double(ex.item[2].radius), 3.0, 64 * eps<T>());
}

}  // namespace
