// SPDX-License-Identifier: BSL-1.0
// Tests for construct/misc3.hpp (rows misc3.projection, misc3.angles, misc3.planes; book
// chapter 12). Oracles: exact GMP rationals for the projections of dyadic input and for the
// squared cosine of every angle; angles built analytically in a random orthonormal frame; exact
// plane equations for integer points; orientation by reversal; 2^k scale invariance.
#include <gmpxx.h>

#include <locus/construct/misc3.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <numbers>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class Misc3Test : public ::testing::Test {};
TYPED_TEST_SUITE(Misc3Test, locus_test::RealTypes);

namespace {

using Q = mpq_class;

template <class T>
Vec3<T> dyadic_vec(Rng& rng) {
  const auto d = [&] { return static_cast<T>(rng.uniform_int(-128, 128)) / T(16); };
  return {d(), d(), d()};
}
template <class T>
Q dotq(const Vec3<T>& a, const Vec3<T>& b) {
  Q s = 0;
  for (int k = 0; k < 3; ++k) s += Q(double(a[k])) * Q(double(b[k]));
  return s;
}
/// |got - (a + f b)| componentwise <= tl, exact right-hand side.
template <class T>
::testing::AssertionResult near_q(const Vec3<T>& got, const Vec3<T>& a, const Q& f,
                                  const Vec3<T>& b, T tl) {
  for (int k = 0; k < 3; ++k) {
    const Q want = Q(double(a[k])) + f * Q(double(b[k]));
    const double e = std::abs(Q(Q(double(got[k])) - want).get_d());
    if (!(e <= double(tl)))
      return ::testing::AssertionFailure() << "component " << k << ": got " << got[k] << ", want "
                                           << want.get_d() << ", error " << e << " > " << tl;
  }
  return ::testing::AssertionSuccess();
}
/// cos^2 of the angle between u and v, exact.
template <class T>
Q cos2(const Vec3<T>& u, const Vec3<T>& v) {
  const Q d = dotq(u, v);
  return d * d / (dotq(u, u) * dotq(v, v));
}

}  // namespace

// Figures 12.1-12.3 on dyadic input against the exact rational projections.
TYPED_TEST(Misc3Test, ProjectionsAgainstExactRationals) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 200; ++i) {
    Vec3<T> n = dyadic_vec<T>(rng);
    if (n == Vec3<T>{}) n.x = T(1);
    const Vec3<T> p = dyadic_vec<T>(rng), v = dyadic_vec<T>(rng);
    const T c = static_cast<T>(rng.uniform_int(-64, 64)) / T(8);
    const Plane3<T> pl{n, c};
    const Q nn = dotq(n, n);
    const T scale = T(64);
    // 12.1: q = p - ((n.p - c) / n.n) n.
    const Vec3<T> q = project_point(p, pl);
    EXPECT_TRUE(near_q(q, p, -(dotq(n, p) - Q(double(c))) / nn, n, tol(T(32), scale)));
    EXPECT_NEAR(signed_distance(pl, q), T(0), tol(T(64), scale));
    // 12.2: v - (v.n / n.n) n, perpendicular to n.
    const Vec3<T> vp = project_vector(v, pl);
    EXPECT_TRUE(near_q(vp, v, -dotq(v, n) / nn, n, tol(T(16), scale)));
    // 12.3: (u.v / v.v) v; parallel to v.
    const Vec3<T> uv = project_vector(p, v);
    if (v == Vec3<T>{}) {
      EXPECT_EQ(uv, (Vec3<T>{}));
    } else {
      EXPECT_TRUE(near_q(uv, Vec3<T>{}, dotq(p, v) / dotq(v, v), v, tol(T(16), scale)));
    }
    // Translation of a vector does not exist: the vector projection ignores the constant.
    EXPECT_EQ(project_vector(v, Plane3<T>{n, c + T(3)}), vp);
  }
}

// Figures 12.4, 12.5, 12.9: angles built in a random orthonormal frame, and cos^2 exactly.
TYPED_TEST(Misc3Test, AnglesAgainstConstructionAndExactCosine) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double pi = std::numbers::pi;
  for (int i = 0; i < 100; ++i) {
    const Vec3<double> u = rng.unit<double, 3>();
    const Vec3<double> w = normalize(cross(u, rng.unit<double, 3>()));
    const double theta = pi * rng.uniform_int(0, 64) / 64.0;
    const Vec3<double> b = std::cos(theta) * u + std::sin(theta) * w;
    const T su = rng.uniform<T>(T(0.25), T(4)), sb = rng.uniform<T>(T(0.25), T(4));
    const Vec3<T> du = su * vec_cast<T>(u), db = sb * vec_cast<T>(b);
    const Vec3<T> o = rng.vec<T, 3>(T(-5), T(5));
    // Float rounding of the inputs moves the angle by a few eps.
    const T tl = tol(T(16));
    const Line3<T> la{o, du}, lb{o + db, db};
    EXPECT_NEAR(angle_between(la, lb), T(theta), tl);
    EXPECT_NEAR(angle_between(la, Line3<T>{o, -db}), T(pi - theta), tl);  // figure 12.10
    EXPECT_NEAR(acute_angle(la, lb), T(std::min(theta, pi - theta)), tl);
    const Plane3<T> pa{du, T(1)}, pb{db, T(-2)};
    EXPECT_NEAR(angle_between(pa, pb), T(theta), tl);
    EXPECT_NEAR(acute_angle(pa, pb), T(std::min(theta, pi - theta)), tl);
    // Line against the plane with normal u: the direction b makes pi/2 - theta with it.
    EXPECT_NEAR(angle_between(lb, pa), T(pi / 2 - theta), tl);
    EXPECT_EQ(angle_between(pa, lb), angle_between(lb, pa));
    EXPECT_NEAR(acute_angle(lb, pa), T(std::abs(pi / 2 - theta)), tl);
    // Exact cos^2 on the rounded inputs.
    const double c2 = cos2(du, db).get_d();
    EXPECT_NEAR(std::pow(std::cos(double(angle_between(la, lb))), 2), c2, 8 * double(tl));
    const double s = std::sin(double(angle_between(lb, pa)));
    EXPECT_NEAR(s * s, c2, 8 * double(tl));
    // Power-of-two scaling of directions and normals leaves every angle bit for bit.
    const T f = i % 2 == 0 ? T(1024) : T(1) / T(512);
    EXPECT_EQ(angle_between(Line3<T>{o, f * du}, lb), angle_between(la, lb));
    EXPECT_EQ(angle_between(Plane3<T>{f * du, T(1)}, pb), angle_between(pa, pb));
    EXPECT_EQ(angle_between(Line3<T>{o, f * db}, pa), angle_between(lb, pa));
  }
}

// Figures 12.4, 12.5, 12.9: exact special positions.
TYPED_TEST(Misc3Test, AngleSpecialCases) {
  using T = TypeParam;
  const T pi = std::numbers::pi_v<T>;
  const Plane3<T> xy{{T(0), T(0), T(2)}, T(1)};
  const Line3<T> up{{T(0), T(0), T(0)}, {T(0), T(0), T(5)}};
  const Line3<T> flat{{T(0), T(0), T(0)}, {T(3), T(4), T(0)}};
  const Line3<T> diag{{T(1), T(1), T(1)}, {T(1), T(0), T(1)}};
  EXPECT_EQ(angle_between(up, xy), pi / 2);
  EXPECT_EQ(angle_between(Line3<T>{up.origin, -up.direction}, xy), -pi / 2);
  EXPECT_EQ(angle_between(flat, xy), T(0));
  EXPECT_NEAR(angle_between(diag, xy), pi / 4, tol(T(4)));
  EXPECT_EQ(angle_between(up, flat), pi / 2);
  EXPECT_EQ(angle_between(up, up), T(0));
  EXPECT_EQ(angle_between(up, Line3<T>{up.origin, -up.direction}), pi);
  EXPECT_EQ(acute_angle(up, Line3<T>{up.origin, -up.direction}), T(0));
  EXPECT_EQ(angle_between(xy, Plane3<T>{{T(0), T(0), T(-1)}, T(7)}), pi);
  EXPECT_EQ(acute_angle(xy, Plane3<T>{{T(0), T(0), T(-1)}, T(7)}), T(0));
  EXPECT_NEAR(acute_angle(xy, Plane3<T>{{T(0), T(1), T(-1)}, T(0)}), pi / 4, tol(T(4)));
  // Nearly parallel directions: no acos cancellation (the angle atan(2^-20) to full precision,
  // where acos of the rounded cosine would lose about half the digits).
  const T tiny = std::ldexp(T(1), -20);
  const T want = static_cast<T>(std::atan(double(tiny)));
  EXPECT_NEAR(angle_between(flat, Line3<T>{{}, {T(3), T(4), T(5) * tiny}}), want, tol(T(8), want));
}

TYPED_TEST(Misc3Test, PlaneConstructions) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 200; ++i) {
    // Small integers: every product and sum below is exact, so the equations hold exactly.
    const auto iv = [&] {
      return Vec3<T>{static_cast<T>(rng.uniform_int(-20, 20)),
                     static_cast<T>(rng.uniform_int(-20, 20)),
                     static_cast<T>(rng.uniform_int(-20, 20))};
    };
    const Vec3<T> a = iv(), b = iv(), c = iv(), d = iv();
    const PlaneResult<T> r = plane_through_points(a, b, c);
    const Vec3<T> n = cross(b - a, c - a);  // exact for these sizes
    if (n == Vec3<T>{}) {
      EXPECT_EQ(r.status, Status::degenerate_input);
    } else {
      ASSERT_EQ(r.status, Status::ok);
      for (const Vec3<T>& p : {a, b, c}) EXPECT_EQ(signed_value(r.plane, p), T(0));
      // Counter-clockwise seen from the positive side: the normal is the right-hand one.
      EXPECT_GT(dotq(r.plane.normal, n), Q(0));
    }
    const PlaneResult<T> m = plane_normal_to_line(Line3<T>{a, d}, b);
    if (d == Vec3<T>{}) {
      EXPECT_EQ(m.status, Status::degenerate_input);
    } else {
      ASSERT_EQ(m.status, Status::ok);
      EXPECT_EQ(signed_value(m.plane, b), T(0));
      EXPECT_EQ(cross(m.plane.normal, d), (Vec3<T>{}));
      EXPECT_GT(dot(m.plane.normal, d), T(0));
      // The line meets its normal plane at a right angle.
      EXPECT_EQ(angle_between(Line3<T>{a, d}, m.plane), std::numbers::pi_v<T> / 2);
    }
  }
  // Collinear points that a rounded cross product would not reveal: a, a + e, a + 3 e.
  const Vec3<T> a{T(0.1), T(0.2), T(0.3)}, e{T(1) / T(3), T(2) / T(7), T(0.7)};
  EXPECT_EQ(plane_through_points(Vec3<T>{}, e, T(2) * e).status, Status::degenerate_input);
  EXPECT_EQ(plane_through_points(a, a, e).status, Status::degenerate_input);
}

TYPED_TEST(Misc3Test, DegenerateAndNonFinite) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Vec3<T> z{}, x{T(1), T(0), T(0)}, bad{nan, T(0), T(0)};
  const Plane3<T> pl{{T(0), T(0), T(1)}, T(0)};
  EXPECT_TRUE(std::isnan(angle_between(Line3<T>{z, z}, pl)));
  EXPECT_TRUE(std::isnan(angle_between(Line3<T>{z, x}, Plane3<T>{z, T(0)})));
  EXPECT_TRUE(std::isnan(angle_between(Line3<T>{z, x}, Line3<T>{z, z})));
  EXPECT_TRUE(std::isnan(angle_between(Line3<T>{bad, x}, Line3<T>{z, x})));
  EXPECT_TRUE(std::isnan(angle_between(pl, Plane3<T>{{inf, T(0), T(0)}, T(0)})));
  EXPECT_TRUE(std::isnan(acute_angle(pl, Plane3<T>{x, nan})));
  EXPECT_TRUE(std::isnan(acute_angle(Line3<T>{z, bad}, pl)));
  // Projections: onto the zero vector, onto a plane without a normal.
  EXPECT_EQ(project_vector(x, z), z);
  EXPECT_EQ(project_vector(x, Plane3<T>{z, T(1)}), x);
  EXPECT_EQ(project_point(x, Plane3<T>{z, T(1)}), x);
  EXPECT_FALSE(is_finite(project_point(bad, pl)));
  EXPECT_EQ(plane_through_points(bad, x, z).status, Status::non_finite_input);
  EXPECT_EQ(plane_normal_to_line(Line3<T>{z, x}, bad).status, Status::non_finite_input);
  EXPECT_EQ(plane_normal_to_line(Line3<T>{z, Vec3<T>{inf, T(0), T(0)}}, x).status,
            Status::non_finite_input);
}
