// SPDX-License-Identifier: BSL-1.0
// Tests for distance/line_circle.hpp and circle_circle.hpp (row dist3.misc: line / ray / segment
// to circle and circle to circle in 3D).
//
// Oracles: the generic harness (random parameter search), and an independent long-double brute
// force: dense sampling of the (first) circle's angle with the exact closed-form distance from
// each sample to the other object (point-linear clamp or point-circle), then golden-section
// refinement of every discrete local minimum.
#include <locus/distance/circle_circle.hpp>
#include <locus/distance/line_circle.hpp>

#include "distance/harness.hpp"
#include "distance/linear_oracle.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <utility>

using namespace locus;
using locus_test::Rng;
namespace dist = locus_test::dist;

template <class T>
class Circle3PairsTest : public ::testing::Test {};
TYPED_TEST_SUITE(Circle3PairsTest, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kCaseScale = 4;
#else
constexpr int kCaseScale = 1;
#endif

using locus_test::linear_oracle::LD;
using locus_test::linear_oracle::min_over_angle;
using locus_test::linear_oracle::near_ld;
using locus_test::linear_oracle::sqr_to_linear;
using locus_test::linear_oracle::to_ld;
using V = Vec3<LD>;

struct CircleLD {
  V c, u, v, n;
  LD r;
};

template <class T>
CircleLD to_ld(const Circle3<T>& c) {
  const V n = vec_cast<LD>(c.normal) / std::sqrt(sqr_length(vec_cast<LD>(c.normal)));
  // An independent basis of the plane (any will do: the oracle only needs the point set).
  const V h = std::abs(n.x) < LD(0.6) ? V{1, 0, 0} : V{0, 1, 0};
  V u = cross(n, h);
  u = u / std::sqrt(sqr_length(u));
  return {vec_cast<LD>(c.center), u, cross(n, u), n, LD(c.radius)};
}

LD sqr_to_circle(const V& p, const CircleLD& c) {
  const V d = p - c.c;
  const LD z = dot(d, c.n);
  const LD rho = std::sqrt(sqr_length(d - z * c.n));
  return z * z + (rho - c.r) * (rho - c.r);
}

using LinLD = locus_test::linear_oracle::LinLD<3>;

template <class Lin, class T>
LD brute_linear_circle(const Lin& lin, const Circle3<T>& c) {
  const CircleLD cl = to_ld(c);
  const LinLD ll = to_ld(lin);
  return std::sqrt(min_over_angle([&](LD a) {
    return sqr_to_linear(cl.c + cl.r * (std::cos(a) * cl.u + std::sin(a) * cl.v), ll);
  }));
}

template <class T>
LD brute_circle_circle(const Circle3<T>& c0, const Circle3<T>& c1) {
  const CircleLD a = to_ld(c0), b = to_ld(c1);
  return std::sqrt(min_over_angle(
      [&](LD t) { return sqr_to_circle(a.c + a.r * (std::cos(t) * a.u + std::sin(t) * a.v), b); }));
}

template <class T>
Circle3<T> random_circle(Rng& rng, T s) {
  const T r = rng.uniform_int(0, 15) == 0 ? T(0) : rng.uniform<T>(T(0.2), T(6));
  return {rng.vec<T, 3>(-s, s), rng.unit<T, 3>() * rng.uniform<T>(T(0.5), T(3)), r};
}

/// A circle in a special position relative to `base`: coplanar, coaxial, or through its axis.
template <class T>
Circle3<T> related_circle(Rng& rng, const Circle3<T>& base, T s) {
  Circle3<T> c = random_circle(rng, s);
  const Vec3<T> n = normalize(base.normal);
  switch (rng.uniform_int(0, 3)) {
    case 0:  // coplanar
      c.normal = base.normal;
      c.center = c.center - dot(c.center - base.center, n) * n;
      break;
    case 1:  // coaxial
      c.normal = -T(2) * base.normal;
      c.center = base.center + rng.uniform<T>(-s, s) * n;
      break;
    case 2:  // center on base's axis, tilted
      c.center = base.center + rng.uniform<T>(-s, s) * n;
      break;
    default:
      break;
  }
  return c;
}

template <class T>
T dist_tol(T s) {
  // Roots are computed in double; the final points are rounded to T.
  return (std::is_same_v<T, float> ? T(4e-6) : T(1e-12)) * s;
}

}  // namespace

TYPED_TEST(Circle3PairsTest, Harness) {
  using T = TypeParam;
  const T S = 10;
  dist::Options<T> opt;
  opt.cases = 100 / kCaseScale;
  // Circles are not convex: the harness's local search stalls in local minima (always above
  // the answer; check 5's one-sided bound still applies). Agreement is checked against the
  // brute force below instead.
  opt.check_agreement = false;
  dist::check_pairs<T, 3, Line<T, 3>, Circle3<T>>(
      [&](Rng& rng) {
        return std::pair{Line<T, 3>{rng.vec<T, 3>(-S, S), rng.unit<T, 3>() * T(2)},
                         random_circle(rng, S)};
      },
      opt);
  dist::check_pairs<T, 3, Ray<T, 3>, Circle3<T>>(
      [&](Rng& rng) {
        return std::pair{Ray<T, 3>{rng.vec<T, 3>(-S, S), rng.unit<T, 3>() * T(0.7)},
                         random_circle(rng, S)};
      },
      opt);
  dist::check_pairs<T, 3, Segment<T, 3>, Circle3<T>>(
      [&](Rng& rng) {
        return std::pair{Segment<T, 3>{rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S)},
                         random_circle(rng, S)};
      },
      opt);
  dist::check_pairs<T, 3, Circle3<T>, Circle3<T>>(
      [&](Rng& rng) {
        const Circle3<T> a = random_circle(rng, S);
        return std::pair{
            a, rng.uniform_int(0, 2) == 0 ? related_circle(rng, a, S) : random_circle(rng, S / 2)};
      },
      opt);
}

TYPED_TEST(Circle3PairsTest, LinearAgainstBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T S = 8;
  for (int i = 0; i < 60 / kCaseScale; ++i) {
    const Circle3<T> c = random_circle(rng, S);
    Vec3<T> o = rng.vec<T, 3>(-S, S), d = rng.unit<T, 3>() * rng.uniform<T>(T(0.5), T(4));
    const Vec3<T> n = normalize(c.normal);
    switch (i % 4) {
      case 0:  // in the circle's plane
        o = o - dot(o - c.center, n) * n;
        d = d - dot(d, n) * n;
        break;
      case 1:  // through the axis
        o = c.center + rng.uniform<T>(-S, S) * n;
        break;
      case 2:  // parallel to the axis
        d = n * T(3);
        break;
      default:
        break;
    }
    SCOPED_TRACE("case " + std::to_string(i));
    const Line<T, 3> line{o, d};
    const Ray<T, 3> ray{o, d};
    const Segment<T, 3> seg{o, o + d};
    const auto rl = distance(line, c), rr = distance(ray, c), rs = distance(seg, c);
    EXPECT_TRUE(near_ld(LD(rl.distance), brute_linear_circle(line, c), LD(dist_tol<T>(S))));
    EXPECT_TRUE(near_ld(LD(rr.distance), brute_linear_circle(ray, c), LD(dist_tol<T>(S))));
    EXPECT_TRUE(near_ld(LD(rs.distance), brute_linear_circle(seg, c), LD(dist_tol<T>(S))));
    EXPECT_LE(rl.distance, rr.distance + dist_tol<T>(S));
    EXPECT_LE(rr.distance, rs.distance + dist_tol<T>(S));
    const auto sw = distance(c, seg);
    EXPECT_EQ(sw.distance, rs.distance);
    EXPECT_EQ(sw.closest[0], rs.closest[1]);
    EXPECT_EQ(sw.param_b, rs.param_a);
  }
}

// LOCUS_TEST_SEED=24, LinearAgainstBruteForce case 52: a line in the circle's plane crossing it.
// The crossings were only the quartic's roots, whose squared coefficients left 1.1e-10 in double
// instead of ~0; they are now also the roots of the quadratic g(t) = r^2.
TYPED_TEST(Circle3PairsTest, InPlaneCrossing) {
  using T = TypeParam;
  const Circle3<T> c{{T(-0x1.0adfbd0da34d4p+1), T(-0x1.229411f29da8cp+1), T(-0x1.3273fe90397edp+2)},
                     {T(-0x1.5d3020ece2632p-1), T(0x1.326c9697602d3p-1), T(-0x1.1c8e3e77d6f38p-1)},
                     T(0x1.e699dac3bd668p-3)};
  const Vec3<T> o{T(-0x1.29e9d9e6504f9p+2), T(0x1.d2a3cea508f3cp+1), T(0x1.2f16648be321bp+2)};
  const Vec3<T> d{T(0x1.611286e5d1bfep-1), T(-0x1.7e3586a120897p+0), T(-0x1.3a1ba78d9e733p+1)};
  // In T the line is in the plane to the rounding of its coordinates (up to 8), and the crossing
  // is found to rounding: a few eps of that scale.
  const T e = T(16) * eps_v<T> * T(8);
  for (const auto& r : {distance(Line<T, 3>{o, d}, c), distance(Ray<T, 3>{o, d}, c)}) {
    EXPECT_LE(r.distance, e);
    EXPECT_NEAR(length(r.closest[0] - r.closest[1]), r.distance, e);
    EXPECT_NEAR(length(r.closest[1] - c.center), c.radius, e);
  }
}

TYPED_TEST(Circle3PairsTest, CircleCircleAgainstBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T S = 6;
  for (int i = 0; i < 80 / kCaseScale; ++i) {
    const Circle3<T> a = random_circle(rng, S);
    const Circle3<T> b = i % 2 ? related_circle(rng, a, S) : random_circle(rng, S);
    SCOPED_TRACE("case " + std::to_string(i));
    const auto r = distance(a, b);
    EXPECT_TRUE(near_ld(LD(r.distance), brute_circle_circle(a, b), LD(dist_tol<T>(S))));
    const auto q = distance(b, a);
    EXPECT_EQ(q.distance, r.distance);
    EXPECT_EQ(q.closest[0], r.closest[1]);
    EXPECT_EQ(q.param_a, r.param_b);
    EXPECT_EQ(q.unique, r.unique);
  }
}

TYPED_TEST(Circle3PairsTest, LinearSpecialConfigurations) {
  using T = TypeParam;
  const Vec3<T> z{0, 0, 1};
  const Circle3<T> c{{T(1), T(2), T(3)}, z * T(4), T(2)};
  const Vec3<T> o = c.center;
  const T e = T(64) * eps_v<T> * T(10);
  // The line is the axis: every circle point is closest to the center.
  const auto axis = distance(Line<T, 3>{o + T(5) * z, -z}, c);
  EXPECT_NEAR(axis.distance, T(2), e);
  EXPECT_FALSE(axis.unique);
  EXPECT_TRUE(locus_test::vec_near(axis.closest[0], o, e));
  // A segment along the axis ending above the center: its end is closest, non-unique.
  const auto up = distance(Segment<T, 3>{o + z, o + T(5) * z}, c);
  EXPECT_NEAR(up.distance, std::sqrt(T(5)), e);
  EXPECT_FALSE(up.unique);
  EXPECT_EQ(up.param_a, T(0));
  // In the plane, crossing the circle: distance 0.
  const auto cross_in = distance(Line<T, 3>{o + Vec3<T>{-5, T(0.5), 0}, {1, 0, 0}}, c);
  EXPECT_NEAR(cross_in.distance, T(0), e);
  EXPECT_NEAR(cross_in.closest[0].y, o.y + T(0.5), e);
  // In the plane, outside: the point of the circle nearest the line.
  const auto out = distance(Line<T, 3>{o + Vec3<T>{-5, 3, 0}, {2, 0, 0}}, c);
  EXPECT_NEAR(out.distance, T(1), e);
  EXPECT_TRUE(locus_test::vec_near(out.closest[0], o + Vec3<T>{0, 3, 0}, e));
  EXPECT_TRUE(locus_test::vec_near(out.closest[1], o + Vec3<T>{0, 2, 0}, e));
  EXPECT_TRUE(out.unique);
  // Parallel to the axis outside the circle.
  const auto par = distance(Ray<T, 3>{o + Vec3<T>{5, 0, -3}, z}, c);
  EXPECT_NEAR(par.distance, T(3), e);
  EXPECT_NEAR(par.param_a, T(3), e);
  EXPECT_TRUE(locus_test::vec_near(par.closest[1], o + Vec3<T>{2, 0, 0}, e));
  // Parallel to the axis inside the circle, ray starting above the plane pointing away.
  const auto par_in = distance(Ray<T, 3>{o + Vec3<T>{T(0.5), 0, 1}, z}, c);
  EXPECT_NEAR(par_in.distance, std::sqrt(T(1) + T(1.5) * T(1.5)), e);
  // Zero radius: point-line distance; zero-length segment: point-circle distance.
  const auto pt = distance(Line<T, 3>{o + Vec3<T>{0, 3, 7}, {1, 0, 0}}, Circle3<T>{o, z, T(0)});
  EXPECT_NEAR(pt.distance, std::sqrt(T(58)), e);
  const auto zs = distance(Segment<T, 3>{o + Vec3<T>{0, 5, 0}, o + Vec3<T>{0, 5, 0}}, c);
  EXPECT_NEAR(zs.distance, T(3), e);
  EXPECT_EQ(zs.param_a, T(0));
  // Swapped overloads.
  const auto sw = distance(c, Ray<T, 3>{o + Vec3<T>{5, 0, -3}, z});
  EXPECT_EQ(sw.closest[0], par.closest[1]);
  EXPECT_EQ(sw.param_a, par.param_b);
}

// A tilted axis is never hit exactly in floating point: the whole circle is still equidistant
// from the axis point, so unique must be false (point_circle.hpp alone only sees exact axis
// points). A line clearly off the axis keeps unique = true.
TYPED_TEST(Circle3PairsTest, LinearOnTiltedAxis) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 20; ++i) {
    const Vec3<T> n = rng.unit<T, 3>();
    const T r = rng.uniform<T>(T(0.5), T(4));
    const Circle3<T> c{rng.vec<T, 3>(T(-5), T(5)), n * rng.uniform<T>(T(0.5), T(2)), r};
    const T e = T(1024) * eps_v<T> * T(10);
    const T h = rng.uniform<T>(T(0.5), T(3));
    // The axis as a line: closest at the center, distance r.
    const auto line = distance(Line<T, 3>{c.center + h * n, n * rng.uniform<T>(T(-2), T(-0.3))}, c);
    EXPECT_NEAR(line.distance, r, e);
    EXPECT_FALSE(line.unique);
    // A segment of the axis ending at height h above the center: its end, distance sqrt(r^2+h^2).
    const auto seg = distance(Segment<T, 3>{c.center + h * n, c.center + (h + T(2)) * n}, c);
    EXPECT_NEAR(seg.distance, std::sqrt(r * r + h * h), e);
    EXPECT_FALSE(seg.unique);
    EXPECT_EQ(seg.param_a, T(0));
    // Parallel to the axis at a visible offset: a single closest pair.
    const Vec3<T> off = normalize(cross(n, rng.unit<T, 3>())) * (r * T(0.3));
    const auto par =
        distance(Segment<T, 3>{c.center + off + h * n, c.center + off + (h + 2) * n}, c);
    EXPECT_NEAR(par.distance, std::sqrt(r * r * T(0.49) + h * h), e);
    EXPECT_TRUE(par.unique);
  }
}

TYPED_TEST(Circle3PairsTest, CircleSpecialConfigurations) {
  using T = TypeParam;
  const Vec3<T> z{0, 0, 1}, o{T(1), T(-2), T(0.5)};
  const T e = T(256) * eps_v<T> * T(10);
  // Coaxial: every pair at the same angle is closest.
  const auto coax = distance(Circle3<T>{o, z, T(1)}, Circle3<T>{o + T(3) * z, T(-2) * z, T(2)});
  EXPECT_NEAR(coax.distance, std::sqrt(T(10)), e);
  EXPECT_FALSE(coax.unique);
  // Concentric coplanar.
  const auto conc = distance(Circle3<T>{o, z, T(1)}, Circle3<T>{o, z, T(2.5)});
  EXPECT_NEAR(conc.distance, T(1.5), e);
  EXPECT_FALSE(conc.unique);
  // Coplanar, apart and touching.
  const auto apart = distance(Circle3<T>{o, z, T(1)}, Circle3<T>{o + Vec3<T>{5, 0, 0}, z, T(2)});
  EXPECT_NEAR(apart.distance, T(2), e);
  EXPECT_TRUE(apart.unique);
  EXPECT_TRUE(locus_test::vec_near(apart.closest[0], o + Vec3<T>{1, 0, 0}, e));
  EXPECT_TRUE(locus_test::vec_near(apart.closest[1], o + Vec3<T>{3, 0, 0}, e));
  const auto touch = distance(Circle3<T>{o, z, T(1)}, Circle3<T>{o + Vec3<T>{3, 0, 0}, z, T(2)});
  EXPECT_NEAR(touch.distance, T(0), std::sqrt(e));
  // Coplanar, one inside the other (internally nested, not concentric).
  const auto nest = distance(Circle3<T>{o, z, T(4)}, Circle3<T>{o + Vec3<T>{1, 0, 0}, z, T(1)});
  EXPECT_NEAR(nest.distance, T(2), e);
  // Crossing transversally at o + (1, 0, 0).
  const auto cr =
      distance(Circle3<T>{o, z, T(1)}, Circle3<T>{o + Vec3<T>{T(0.5), 0, 0}, {0, 1, 0}, T(0.5)});
  EXPECT_NEAR(cr.distance, T(0), e);
  EXPECT_TRUE(locus_test::vec_near(cr.closest[0], o + Vec3<T>{1, 0, 0}, std::sqrt(e)));
  // Linked rings (Hopf link): positive distance, compared with the brute force.
  const Circle3<T> ring0{o, z, T(1)}, ring1{o + Vec3<T>{1, 0, 0}, {0, 1, 0}, T(1)};
  EXPECT_TRUE(near_ld(LD(distance(ring0, ring1).distance), brute_circle_circle(ring0, ring1),
                      LD(dist_tol<T>(T(10)))));
  // Zero radii.
  const auto p1 = distance(Circle3<T>{o, z, T(1)}, Circle3<T>{o + T(2) * z, z, T(0)});
  EXPECT_NEAR(p1.distance, std::sqrt(T(5)), e);
  EXPECT_FALSE(p1.unique);  // on the first circle's axis
  const auto p2 = distance(Circle3<T>{o, z, T(0)}, Circle3<T>{o + Vec3<T>{4, 0, 0}, z, T(1)});
  EXPECT_NEAR(p2.distance, T(3), e);
  const auto p3 = distance(Circle3<T>{o, z, T(0)}, Circle3<T>{o + Vec3<T>{0, 4, 0}, z, T(0)});
  EXPECT_NEAR(p3.distance, T(4), e);
}

// Regression (Harness, LOCUS_TEST_SEED=77, case 88): b's center is on a's axis, and b is solved
// as circle 0 (canonical order). The squared critical-point equation then has double roots at
// the zeros of h' (the extremes of b along a's normal), one of them the minimiser; rounding made
// it a complex pair and the solver returned a local minimum (119.48 instead of 18.80).
TYPED_TEST(Circle3PairsTest, CenterOnOtherAxisDoubleRoot) {
  using T = TypeParam;
  const auto cv = [](double x) { return static_cast<T>(x); };
  const Circle3<T> a{{cv(8.0760788670268333), cv(-3.8761022117420021), cv(9.277412506695498)},
                     {cv(-1.3802033580830606), cv(0.46272116145862374), cv(-1.5099719219043668)},
                     cv(2.0263537321561724)};
  const Circle3<T> b{{cv(3.1204513271790111), cv(-2.2146994064484873), cv(3.8558502443206031)},
                     {cv(1.073405959990289), cv(0.80082399321442277), cv(-1.4535371557892707)},
                     cv(3.4628619201707207)};
  const LD brute = brute_circle_circle(a, b);
  EXPECT_NEAR(double(brute), 4.3357333, 1e-4);  // sqrt(18.7986), not the local sqrt(119.48)
  const auto r = distance(a, b);
  const auto q = distance(b, a);
  EXPECT_TRUE(near_ld(LD(r.distance), brute, LD(dist_tol<T>(T(10)))));
  EXPECT_TRUE(near_ld(LD(q.distance), brute, LD(dist_tol<T>(T(10)))));
  EXPECT_EQ(q.distance, r.distance);
  EXPECT_EQ(q.closest[0], r.closest[1]);
  EXPECT_EQ(q.closest[1], r.closest[0]);
  EXPECT_NEAR(length(r.closest[0] - r.closest[1]), r.distance, dist_tol<T>(T(10)));
}

TYPED_TEST(Circle3PairsTest, NonFinite) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Circle3<T> good{{0, 0, 0}, {0, 0, 1}, T(1)};
  const Line<T, 3> line{{0, 0, 2}, {1, 0, 0}};
  EXPECT_TRUE(dist::is_nan_result(distance(Line<T, 3>{{nan, 0, 0}, {1, 0, 0}}, good)));
  EXPECT_TRUE(dist::is_nan_result(distance(Ray<T, 3>{{0, 0, 0}, {inf, 0, 0}}, good)));
  EXPECT_TRUE(dist::is_nan_result(distance(Segment<T, 3>{{0, 0, 0}, {0, nan, 0}}, good)));
  EXPECT_TRUE(dist::is_nan_result(distance(line, Circle3<T>{{0, 0, 0}, {0, 0, 1}, nan})));
  EXPECT_TRUE(dist::is_nan_result(distance(line, Circle3<T>{{0, 0, 0}, {0, 0, 0}, T(1)})));
  EXPECT_TRUE(dist::is_nan_result(distance(line, Circle3<T>{{0, 0, 0}, {0, 0, 1}, T(-1)})));
  EXPECT_TRUE(dist::is_nan_result(distance(good, Circle3<T>{{inf, 0, 0}, {0, 0, 1}, T(1)})));
  EXPECT_TRUE(dist::is_nan_result(distance(Circle3<T>{{0, 0, 0}, {nan, 0, 1}, T(1)}, good)));
  EXPECT_TRUE(dist::is_nan_result(distance(good, Circle3<T>{{0, 0, 0}, {0, 0, 0}, T(0)})));
}
