// SPDX-License-Identifier: BSL-1.0
// Tests of simplex_balls.hpp (row cg.balls, figure 13.78) and of the exact side-of-ball tests
// behind min_circle/min_sphere. Oracles: exact GMP circumcentres (equidistance checked exactly
// for rational input), distances from the incentre to each side / face plane, exact rational
// evaluation of the side-of-ball polynomials.

#include <locus/bounding/detail/ball_predicates.hpp>
#include <locus/bounding/simplex_balls.hpp>

#include <gmpxx.h>

#include <cmath>
#include <limits>

#include "support/typed.hpp"

namespace {

using locus::Vec2;
using locus::Vec3;
using locus_test::Rng;

template <class T>
class SimplexBalls : public ::testing::Test {};
TYPED_TEST_SUITE(SimplexBalls, locus_test::RealTypes);

struct Q2 {
  mpq_class x, y;
};
struct Q3 {
  mpq_class x, y, z;
};
template <class T>
Q2 q(const Vec2<T>& p) {
  return {mpq_class(static_cast<double>(p.x)), mpq_class(static_cast<double>(p.y))};
}
template <class T>
Q3 q(const Vec3<T>& p) {
  return {mpq_class(static_cast<double>(p.x)), mpq_class(static_cast<double>(p.y)),
          mpq_class(static_cast<double>(p.z))};
}

// Exact circumcentre of a 2D triangle (Cramer on the perpendicular bisectors).
Q2 exact_circumcenter(const Q2& a, const Q2& b, const Q2& c) {
  const mpq_class ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  const mpq_class uu = ux * ux + uy * uy, vv = vx * vx + vy * vy, d = 2 * (ux * vy - uy * vx);
  return {a.x + (vy * uu - uy * vv) / d, a.y + (ux * vv - vx * uu) / d};
}

TYPED_TEST(SimplexBalls, Figure13_78TriangleCircles) {
  using T = TypeParam;
  // A 3-4-5 right triangle: circumcentre the hypotenuse midpoint, radius 5/2; inradius
  // (3 + 4 - 5) / 2 = 1 at (1, 1).
  const locus::Triangle<T, 2> tri{{T(0), T(0)}, {T(4), T(0)}, {T(0), T(3)}};
  const auto cc = locus::circumscribed_circle(tri);
  ASSERT_TRUE(cc.has_value());
  const T t = locus_test::tol<T>(8, T(5));
  EXPECT_TRUE(locus_test::vec_near(cc->center, Vec2<T>{T(2), T(1.5)}, t));
  EXPECT_NEAR(cc->radius, T(2.5), t);
  const auto ic = locus::inscribed_circle(tri);
  ASSERT_TRUE(ic.has_value());
  EXPECT_TRUE(locus_test::vec_near(ic->center, Vec2<T>{T(1), T(1)}, t));
  EXPECT_NEAR(ic->radius, T(1), t);
  // Clockwise order gives the same circles.
  const locus::Triangle<T, 2> cw{tri.v0, tri.v2, tri.v1};
  EXPECT_TRUE(locus_test::vec_near(locus::circumscribed_circle(cw)->center, cc->center, t));
  EXPECT_NEAR(locus::inscribed_circle(cw)->radius, ic->radius, t);
}

TYPED_TEST(SimplexBalls, Degenerate) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const locus::Triangle<T, 2> line{{T(0), T(0)}, {T(1), T(1)}, {T(3), T(3)}};
  EXPECT_FALSE(locus::circumscribed_circle(line).has_value());
  EXPECT_FALSE(locus::inscribed_circle(line).has_value());
  const locus::Triangle<T, 2> dup{{T(1), T(2)}, {T(1), T(2)}, {T(3), T(0)}};
  EXPECT_FALSE(locus::circumscribed_circle(dup).has_value());
  const locus::Triangle<T, 2> bad{{T(0), T(0)}, {nan, T(1)}, {T(3), T(0)}};
  EXPECT_FALSE(locus::circumscribed_circle(bad).has_value());
  EXPECT_FALSE(locus::inscribed_circle(bad).has_value());
  const locus::Triangle<T, 3> line3{{T(0), T(0), T(1)}, {T(1), T(2), T(3)}, {T(2), T(4), T(5)}};
  EXPECT_FALSE(locus::circumscribed_circle(line3).has_value());
  EXPECT_FALSE(locus::inscribed_circle(line3).has_value());
  const locus::Tetrahedron3<T> flat{
      {{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(5), T(7), T(0)}}};
  EXPECT_FALSE(locus::circumscribed_sphere(flat).has_value());
  EXPECT_FALSE(locus::inscribed_sphere(flat).has_value());
  locus::Tetrahedron3<T> nant{
      {{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), nan}}};
  EXPECT_FALSE(locus::circumscribed_sphere(nant).has_value());
  // Nearly degenerate but not exactly: a result (the decision is exact).
  const locus::Triangle<T, 2> thin{{T(0), T(0)}, {T(1), T(1)}, {T(2), std::nextafter(T(2), T(3))}};
  EXPECT_TRUE(locus::inscribed_circle(thin).has_value());
}

TYPED_TEST(SimplexBalls, CircumcircleVsExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 300; ++trial) {
    const locus::Triangle<T, 2> tri{rng.vec<T, 2>(T(-10), T(10)), rng.vec<T, 2>(T(-10), T(10)),
                                    rng.vec<T, 2>(T(-10), T(10))};
    const auto cc = locus::circumscribed_circle(tri);
    ASSERT_TRUE(cc.has_value());
    const Q2 a = q(tri.v0), b = q(tri.v1), c = q(tri.v2);
    const Q2 o = exact_circumcenter(a, b, c);
    // Exact equidistance of the oracle (it is a circumcentre), then the rounded centre's error
    // in units of the condition number L^2 / (2 area), which is how the construction's error
    // grows for thin triangles.
    auto d2 = [&](const Q2& p) -> mpq_class {
      return (p.x - o.x) * (p.x - o.x) + (p.y - o.y) * (p.y - o.y);
    };
    ASSERT_EQ(d2(a), d2(b));
    ASSERT_EQ(d2(a), d2(c));
    const double area2 = std::abs(locus::orient2d_value(tri.v0, tri.v1, tri.v2));
    const double l = std::max({locus::length(vec_cast<double>(tri.v1 - tri.v0)),
                               locus::length(vec_cast<double>(tri.v2 - tri.v0)),
                               locus::length(vec_cast<double>(tri.v2 - tri.v1))});
    const double r = std::sqrt(d2(a).get_d());
    const double cond = l * l * l / area2 + 1.0;  // relative error bound / eps
    const double scale = r + locus::max_abs(vec_cast<double>(tri.v0));
    const double t = 16.0 * static_cast<double>(locus::eps_v<T>) * scale * std::min(cond, 1e6) +
                     (std::is_same_v<T, float> ? 0.0 : 16.0 * 2.2e-16 * scale * cond);
    EXPECT_NEAR(static_cast<double>(cc->center.x), o.x.get_d(), t);
    EXPECT_NEAR(static_cast<double>(cc->center.y), o.y.get_d(), t);
    EXPECT_NEAR(static_cast<double>(cc->radius), r, t);
    // Incircle: equal distance to the three side lines, centre inside.
    const auto ic = locus::inscribed_circle(tri);
    ASSERT_TRUE(ic.has_value());
    const Vec2<double> p = vec_cast<double>(ic->center);
    const Vec2<double> v[3] = {vec_cast<double>(tri.v0), vec_cast<double>(tri.v1),
                               vec_cast<double>(tri.v2)};
    for (int e = 0; e < 3; ++e) {
      const Vec2<double> s = v[(e + 1) % 3] - v[e];
      const double dist = std::abs(locus::perp_dot(s, p - v[e])) / locus::length(s);
      EXPECT_NEAR(dist, static_cast<double>(ic->radius),
                  64.0 * locus::eps_v<T> * l * (l * l / area2 + 1));
      EXPECT_EQ(locus::orient2d(tri.v0, tri.v1, tri.v2),
                locus::orient2d(vec_cast<double>(v[e]), v[(e + 1) % 3], p));
    }
  }
}

TYPED_TEST(SimplexBalls, ThreeDimensionalVsExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // Rational-exact check: integer-coordinate simplices, exact circumcentre by Cramer, then the
  // rounded results near it; incircle/insphere by distances to each side / face plane.
  for (int trial = 0; trial < 200; ++trial) {
    Vec3<T> v[4];
    for (auto& p : v) {
      const Vec3<T> r = rng.vec<T, 3>(T(-20), T(20));
      p = {std::round(r.x), std::round(r.y), std::round(r.z)};
    }
    const locus::Tetrahedron3<T> tet{{v[0], v[1], v[2], v[3]}};
    const auto cs = locus::circumscribed_sphere(tet);
    if (locus::orient3d(v[0], v[1], v[2], v[3]) == locus::Sign::zero) {
      EXPECT_FALSE(cs.has_value());
      continue;
    }
    ASSERT_TRUE(cs.has_value());
    // Exact: centre o with 2 (p_i - p_0) . o = |p_i|^2 - |p_0|^2.
    Q3 p[4];
    for (int i = 0; i < 4; ++i) p[i] = q(v[i]);
    mpq_class m[3][3], rhs[3];
    for (int i = 0; i < 3; ++i) {
      m[i][0] = 2 * (p[i + 1].x - p[0].x);
      m[i][1] = 2 * (p[i + 1].y - p[0].y);
      m[i][2] = 2 * (p[i + 1].z - p[0].z);
      rhs[i] = p[i + 1].x * p[i + 1].x + p[i + 1].y * p[i + 1].y + p[i + 1].z * p[i + 1].z -
               p[0].x * p[0].x - p[0].y * p[0].y - p[0].z * p[0].z;
    }
    auto det3 = [](mpq_class a[3][3]) -> mpq_class {
      return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
             a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const mpq_class d = det3(m);
    mpq_class o[3];
    for (int k = 0; k < 3; ++k) {
      mpq_class mk[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) mk[i][j] = j == k ? rhs[i] : m[i][j];
      o[k] = det3(mk) / d;
    }
    auto d2 = [&](const Q3& a) -> mpq_class {
      return (a.x - o[0]) * (a.x - o[0]) + (a.y - o[1]) * (a.y - o[1]) +
             (a.z - o[2]) * (a.z - o[2]);
    };
    for (int i = 1; i < 4; ++i) ASSERT_EQ(d2(p[0]), d2(p[i]));
    const double r = std::sqrt(d2(p[0]).get_d());
    const double vol6 = std::abs(locus::orient3d_value(v[0], v[1], v[2], v[3]));
    const double cond = 40.0 * 40.0 * 40.0 * 40.0 / vol6 + 1.0;
    const double t =
        16.0 * static_cast<double>(locus::eps_v<T>) * (r + 40.0) * std::min(cond, 1e4) +
        16.0 * 2.2e-16 * (r + 40.0) * cond;
    EXPECT_NEAR(static_cast<double>(cs->center.x), o[0].get_d(), t);
    EXPECT_NEAR(static_cast<double>(cs->center.y), o[1].get_d(), t);
    EXPECT_NEAR(static_cast<double>(cs->center.z), o[2].get_d(), t);
    EXPECT_NEAR(static_cast<double>(cs->radius), r, t);
    // Insphere: distance to each face plane equals the radius.
    const auto is = locus::inscribed_sphere(tet);
    ASSERT_TRUE(is.has_value());
    const Vec3<double> c = vec_cast<double>(is->center);
    const int faces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    for (const auto& f : faces) {
      const Vec3<double> a = vec_cast<double>(v[f[0]]), b = vec_cast<double>(v[f[1]]),
                         e = vec_cast<double>(v[f[2]]);
      const Vec3<double> n = locus::normalize(locus::cross(b - a, e - a));
      EXPECT_NEAR(std::abs(locus::dot(n, c - a)), static_cast<double>(is->radius),
                  64.0 * locus::eps_v<T> * 40.0 * std::min(cond, 1e4));
    }
    // The 3D triangle circles: the circumcircle passes through the vertices and lies in the
    // plane; the incircle is tangent to the three sides.
    const locus::Triangle<T, 3> tri{v[0], v[1], v[2]};
    const auto c3 = locus::circumscribed_circle(tri);
    const auto i3 = locus::inscribed_circle(tri);
    if (!c3) {
      EXPECT_TRUE(locus::is_degenerate(tri));
      continue;
    }
    ASSERT_TRUE(i3.has_value());
    const Vec3<double> cc = vec_cast<double>(c3->center);
    const double tt = 64.0 * locus::eps_v<T> * 40.0 * std::min(cond, 1e4);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(locus::length(vec_cast<double>(tri[i]) - cc), static_cast<double>(c3->radius),
                  tt);
      EXPECT_NEAR(locus::dot(vec_cast<double>(c3->normal), vec_cast<double>(tri[i]) - cc), 0.0, tt);
      const Vec3<double> a = vec_cast<double>(tri[i]), b = vec_cast<double>(tri[(i + 1) % 3]);
      const Vec3<double> u = locus::normalize(b - a), w = vec_cast<double>(i3->center) - a;
      EXPECT_NEAR(locus::length(w - locus::dot(w, u) * u), static_cast<double>(i3->radius), tt);
    }
  }
}

// The exact side-of-ball tests against rational evaluation, including inputs that force the
// big-integer fallback (exact ties, huge and tiny magnitudes).
TEST(BallPredicates, VsExactRational) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  auto sgn = [](const mpq_class& x) { return static_cast<locus::Sign>(::sgn(x)); };
  for (int trial = 0; trial < 3000; ++trial) {
    const int mode = trial % 4;
    const double s = mode == 2 ? 1e150 : (mode == 3 ? 1e-200 : 1.0);
    auto pt = [&]() {
      Vec3<double> p = rng.vec<double, 3>(-4, 4);
      if (mode == 1) p = {std::round(p.x), std::round(p.y), std::round(p.z)};  // ties
      return p * s;
    };
    const Vec3<double> a = pt(), b = pt(), c = pt();
    Vec3<double> p = pt();
    if (trial % 5 == 0) p = a + b - a;  // on the boundary-ish
    // Diametral test.
    const Q3 qa = q(a), qb = q(b), qc = q(c), qp = q(p);
    const mpq_class dot = (qp.x - qa.x) * (qp.x - qb.x) + (qp.y - qa.y) * (qp.y - qb.y) +
                          (qp.z - qa.z) * (qp.z - qb.z);
    EXPECT_EQ(locus::detail::diametral_side<3>(p, a, b), sgn(dot)) << trial;
    EXPECT_EQ(locus::detail::diametral_side_exact(&p.x, &a.x, &b.x, 3), sgn(dot)) << trial;
    // Circumcircle sphere test: sign of |p - o|^2 - |a - o|^2, o the exact circumcentre.
    const mpq_class ux = qb.x - qa.x, uy = qb.y - qa.y, uz = qb.z - qa.z;
    const mpq_class vx = qc.x - qa.x, vy = qc.y - qa.y, vz = qc.z - qa.z;
    const mpq_class wx = uy * vz - uz * vy, wy = uz * vx - ux * vz, wz = ux * vy - uy * vx;
    const mpq_class ww = wx * wx + wy * wy + wz * wz;
    if (ww == 0) continue;
    const mpq_class uu = ux * ux + uy * uy + uz * uz, vv = vx * vx + vy * vy + vz * vz;
    // X = |u|^2 (v x w) + |v|^2 (w x u); o = a + X / (2 |w|^2).
    const mpq_class xx = uu * (vy * wz - vz * wy) + vv * (wy * uz - wz * uy);
    const mpq_class xy = uu * (vz * wx - vx * wz) + vv * (wz * ux - wx * uz);
    const mpq_class xz = uu * (vx * wy - vy * wx) + vv * (wx * uy - wy * ux);
    const mpq_class ox = qa.x + xx / (2 * ww), oy = qa.y + xy / (2 * ww), oz = qa.z + xz / (2 * ww);
    auto d2 = [&](const Q3& z) -> mpq_class {
      return (z.x - ox) * (z.x - ox) + (z.y - oy) * (z.y - oy) + (z.z - oz) * (z.z - oz);
    };
    ASSERT_EQ(d2(qa), d2(qb));
    ASSERT_EQ(d2(qa), d2(qc));
    const locus::Sign expect = sgn(d2(qp) - d2(qa));
    EXPECT_EQ(locus::detail::circumcircle_sphere_side(a, b, c, p), expect) << trial;
    EXPECT_EQ(locus::detail::circumcircle_sphere_side_exact(&a.x, &b.x, &c.x, &p.x), expect)
        << trial;
    // A point exactly on that sphere: the reflection of a through the plane's... use c itself.
    EXPECT_EQ(locus::detail::circumcircle_sphere_side(a, b, c, c), locus::Sign::zero);
  }
  // Extreme magnitudes mixed in one test (the big-integer path spans the double range).
  const Vec3<double> a{1e300, 0, 0}, b{-1e300, 0, 0}, p{0, 1e-300, 5e-324};
  EXPECT_EQ(locus::detail::diametral_side_exact(&p.x, &a.x, &b.x, 3), locus::Sign::negative);
  const Vec3<double> c{0, 1e300, 0};
  EXPECT_EQ(locus::detail::circumcircle_sphere_side(a, b, c, Vec3<double>{0, 0, 1e300}),
            locus::Sign::zero);
  EXPECT_EQ(
      locus::detail::circumcircle_sphere_side(a, b, c, Vec3<double>{0, 0, 1.0000000000000002e300}),
      locus::Sign::positive);
}

}  // namespace
