// SPDX-License-Identifier: BSL-1.0
// Row int2.quadratic: circle-circle, circle-arc, arc-arc, circle/ellipse/quadratic-curve pairs
// and relation() (figures 7.5-7.10), float and double. Circles: count, kind and relation against
// exact GMP rationals (|u|^2 against (r0 +- r1)^2) on random dyadic data and exact tangent
// configurations (Pythagorean triples), points on both circles within the header bound, one-ulp
// perturbations, power-of-two scaling and rigid motions, swapped arguments. Ellipses: the number
// of crossings against an independent high-precision oracle (sign changes of the second curve's
// value along the first, sampled in long double and refined by bisection), every point on both
// curves; tangent and nested configurations of figures 7.7-7.10; degenerate and non-finite input.

#include <locus/intersection/arc_arc.hpp>
#include <locus/intersection/circle_arc.hpp>
#include <locus/intersection/circle_circle.hpp>
#include <locus/intersection/circle_ellipse.hpp>
#include <locus/intersection/circle_quadratic_curve.hpp>
#include <locus/intersection/ellipse_ellipse.hpp>
#include <locus/intersection/ellipse_quadratic_curve.hpp>
#include <locus/intersection/quadratic_curve_quadratic_curve.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include <gmpxx.h>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class Quadratic : public ::testing::Test {};
TYPED_TEST_SUITE(Quadratic, locus_test::RealTypes);

template <class T>
T dyadic(Rng& rng, int range, int bits) {
  return static_cast<T>(std::ldexp(double(rng.uniform_int(-range, range)), -bits));
}

// ---- circles: the exact oracle
// -------------------------------------------------------------------

struct CircleAnswer {
  Kind kind;
  RegionRelation rel;
};
template <class T>
CircleAnswer circle_oracle(const Circle2<T>& a, const Circle2<T>& b) {
  const mpq_class ax(double(a.center.x)), ay(double(a.center.y)), bx(double(b.center.x)),
      by(double(b.center.y)), r0(double(a.radius)), r1(double(b.radius));
  const mpq_class d2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
  const mpq_class out = d2 - (r0 + r1) * (r0 + r1), in = d2 - (r0 - r1) * (r0 - r1);
  if (d2 == 0 && r0 == r1) return {r0 == 0 ? Kind::point : Kind::coincident, RegionRelation::equal};
  if (out > 0) return {Kind::empty, RegionRelation::separated};
  if (out == 0) return {Kind::point, RegionRelation::touching};
  if (in < 0)
    return {Kind::empty, r0 > r1 ? RegionRelation::a_contains_b : RegionRelation::b_contains_a};
  if (in == 0)
    return {Kind::point, r0 > r1 ? RegionRelation::a_contains_b_touching
                                 : RegionRelation::b_contains_a_touching};
  return {Kind::points, RegionRelation::overlapping};
}

template <class T>
double circle_dist(const Circle2<T>& c, const Vec2<T>& p) {
  return std::abs(length(vec_cast<double>(p) - vec_cast<double>(c.center)) - double(c.radius));
}

template <class T>
void check_circles(const Circle2<T>& a, const Circle2<T>& b) {
  const auto r = intersection(a, b);
  const CircleAnswer ex = circle_oracle(a, b);
  ASSERT_EQ(r.kind, ex.kind);
  EXPECT_EQ(relation(a, b), ex.rel);
  EXPECT_EQ(intersects(a, b), ex.kind != Kind::empty);
  const double m = std::max(
      {double(max_abs(a.center)), double(max_abs(b.center)), double(a.radius), double(b.radius)});
  const double eps = double(eps_v<T>);
  EXPECT_EQ(r.count, ex.kind == Kind::points ? 2 : ex.kind == Kind::point ? 1 : 0);
  for (int i = 0; i < r.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_EQ(r.multiplicity[k], ex.kind == Kind::point ? 2 : 1);
    EXPECT_LE(circle_dist(a, r.point[k]), 16 * eps * m);
    EXPECT_LE(circle_dist(b, r.point[k]), 16 * eps * m);
    if (a.radius > T(0)) {
      EXPECT_LE(double(max_abs(point_at(a, r.param_a[k]) - r.point[k])), 16 * eps * m);
    }
    if (b.radius > T(0)) {
      EXPECT_LE(double(max_abs(point_at(b, r.param_b[k]) - r.point[k])), 16 * eps * m);
    }
  }
  // Swapped: the same set, parameters exchanged (a tangency point is sqrt(eps) m sensitive
  // along the circles; each parameter is checked through the point it gives).
  const auto s = intersection(b, a);
  ASSERT_EQ(s.kind, r.kind);
  ASSERT_EQ(s.count, r.count);
  for (int i = 0; i < r.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    // Near tangency (two close points, gap apart) the conditioning is eps m^2 / gap.
    const double gap = r.count == 2 ? double(max_abs(r.point[0] - r.point[1])) : m;
    const double tol = r.multiplicity[k] == 2 ? 4 * std::sqrt(eps) * m
                                              : 16 * eps * m * (1 + 2 * m / std::max(gap, 1e-300));
    bool found = false;
    for (int j = 0; j < s.count; ++j) {
      const auto l = static_cast<std::size_t>(j);
      found =
          found || (double(max_abs(s.point[l] - r.point[k])) <= tol &&
                    double(max_abs(point_at(b, s.param_a[l]) - r.point[k])) <= tol + 16 * eps * m &&
                    double(max_abs(point_at(a, s.param_b[l]) - r.point[k])) <= tol + 16 * eps * m);
    }
    EXPECT_TRUE(found) << "a " << a.center.x << " " << a.center.y << " " << a.radius << " b "
                       << b.center.x << " " << b.center.y << " " << b.radius << " point "
                       << r.point[k].x << " " << r.point[k].y << " " << r.param_a[k] << " "
                       << r.param_b[k];
  }
}

TYPED_TEST(Quadratic, CirclesAgainstExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 2000; ++it) {
    const Circle2<T> a{{dyadic<T>(rng, 16, 1), dyadic<T>(rng, 16, 1)},
                       std::abs(dyadic<T>(rng, 12, 1))};
    const Circle2<T> b{{dyadic<T>(rng, 16, 1), dyadic<T>(rng, 16, 1)},
                       std::abs(dyadic<T>(rng, 12, 1))};
    check_circles(a, b);
    check_circles(Circle2<T>{rng.vec<T, 2>(T(-3), T(3)), rng.uniform<T>(T(0.1), T(3))},
                  Circle2<T>{rng.vec<T, 2>(T(-3), T(3)), rng.uniform<T>(T(0.1), T(3))});
  }
}

// Figure 7.6: (a) |u| = r0 + r1, (b) |u| = |r0 - r1|, (c) crossing; built exactly from (3, 4, 5)
// in every orientation, then moved by one ulp.
TYPED_TEST(Quadratic, CircleTangenciesFigure7_6) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 300; ++it) {
    const Vec2<T> c0{T(rng.uniform_int(-40, 40)), T(rng.uniform_int(-40, 40))};
    const int k = rng.uniform_int(1, 4);
    Vec2<T> u{T(3 * k * (rng.uniform_int(0, 1) ? 1 : -1)),
              T(4 * k * (rng.uniform_int(0, 1) ? 1 : -1))};
    if (rng.uniform_int(0, 1)) u = {u.y, u.x};
    const T len = T(5 * k);
    const T r0 = T(rng.uniform_int(1, 5 * k - 1));
    // (a) outside tangency.
    const Circle2<T> a{c0, r0}, outside{c0 + u, len - r0};
    check_circles(a, outside);
    EXPECT_EQ(relation(a, outside), RegionRelation::touching);
    const auto ra = intersection(a, outside);
    ASSERT_EQ(ra.kind, Kind::point);
    EXPECT_EQ(ra.multiplicity[0], 2);
    // (b) inside tangency: the big circle of radius r0 + len around c0 touches a.
    const Circle2<T> big{c0 - u, r0 + len};
    check_circles(a, big);
    EXPECT_EQ(relation(a, big), RegionRelation::b_contains_a_touching);
    EXPECT_EQ(relation(big, a), RegionRelation::a_contains_b_touching);
    // (c) crossing.
    check_circles(a, Circle2<T>{c0 + u, len - r0 + T(1)});
    EXPECT_EQ(relation(a, Circle2<T>{c0 + u, len - r0 + T(1)}), RegionRelation::overlapping);
    // One ulp either way.
    for (T dir : {T(-1), T(1)}) {
      const Circle2<T> moved{
          {std::nextafter(outside.center.x, outside.center.x + dir * T(100)), outside.center.y},
          outside.radius};
      check_circles(a, moved);
      check_circles(a, Circle2<T>{big.center, std::nextafter(big.radius, big.radius + dir)});
    }
  }
}

TYPED_TEST(Quadratic, CircleScalingAndMotions) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int kmax = std::is_same_v<T, float> ? 60 : 400;
  for (int it = 0; it < 500; ++it) {
    const Circle2<T> a{{dyadic<T>(rng, 16, 1), dyadic<T>(rng, 16, 1)},
                       std::abs(dyadic<T>(rng, 12, 1))};
    const Circle2<T> b{{dyadic<T>(rng, 16, 1), dyadic<T>(rng, 16, 1)},
                       std::abs(dyadic<T>(rng, 12, 1))};
    const auto r = intersection(a, b);
    const RegionRelation rel = relation(a, b);
    for (int k : {-kmax, 7, kmax}) {
      const auto sc = [k](const Circle2<T>& c) {
        return Circle2<T>{{std::ldexp(c.center.x, k), std::ldexp(c.center.y, k)},
                          std::ldexp(c.radius, k)};
      };
      const auto q = intersection(sc(a), sc(b));
      ASSERT_EQ(q.kind, r.kind);
      EXPECT_EQ(relation(sc(a), sc(b)), rel);
      for (int i = 0; i < r.count; ++i) {
        const auto j = static_cast<std::size_t>(i);
        EXPECT_EQ(q.point[j].x, std::ldexp(r.point[j].x, k));
        EXPECT_EQ(q.point[j].y, std::ldexp(r.point[j].y, k));
        EXPECT_EQ(q.param_a[j], r.param_a[j]);
      }
    }
    for (int mo = 0; mo < 3; ++mo) {
      const auto f = [mo](const Circle2<T>& c) {
        if (mo == 0) return Circle2<T>{{c.center.y, c.center.x}, c.radius};
        if (mo == 1) return Circle2<T>{{-c.center.x, c.center.y}, c.radius};
        return Circle2<T>{{c.center.x - T(5), c.center.y + T(11)}, c.radius};
      };
      EXPECT_EQ(intersection(f(a), f(b)).kind, r.kind);
      EXPECT_EQ(relation(f(a), f(b)), rel);
    }
  }
}

TYPED_TEST(Quadratic, CircleDegenerate) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Circle2<T> unit{{T(0), T(0)}, T(1)};
  EXPECT_EQ(intersection(unit, unit).kind, Kind::coincident);
  EXPECT_EQ(intersection(unit, unit).count, 0);
  EXPECT_EQ(relation(unit, unit), RegionRelation::equal);
  EXPECT_EQ(intersection(unit, Circle2<T>{{T(0), T(0)}, T(2)}).kind, Kind::empty);
  EXPECT_EQ(relation(unit, Circle2<T>{{T(0), T(0)}, T(2)}), RegionRelation::b_contains_a);
  // Point circles.
  const auto p = intersection(unit, Circle2<T>{{T(0), T(1)}, T(0)});
  ASSERT_EQ(p.kind, Kind::point);
  EXPECT_EQ(p.point[0], (Vec2<T>{T(0), T(1)}));
  EXPECT_EQ(intersection(Circle2<T>{{T(2), T(2)}, T(0)}, Circle2<T>{{T(2), T(2)}, T(0)}).kind,
            Kind::point);
  EXPECT_EQ(intersection(unit, Circle2<T>{{T(0), T(0)}, T(-1)}).kind, Kind::empty);
  EXPECT_EQ(relation(unit, Circle2<T>{{T(0), T(0)}, T(-1)}), RegionRelation::undecided);
  for (T bad : {nan, inf}) {
    EXPECT_EQ(intersection(unit, Circle2<T>{{bad, T(0)}, T(1)}).kind, Kind::empty);
    EXPECT_EQ(intersection(unit, Circle2<T>{{T(0), T(0)}, bad}).kind, Kind::empty);
    EXPECT_EQ(relation(unit, Circle2<T>{{T(0), bad}, T(1)}), RegionRelation::undecided);
  }
}

// ---- arcs
// ----------------------------------------------------------------------------------------

TYPED_TEST(Quadratic, Arcs) {
  using T = TypeParam;
  const T pi = pi_v<T>;
  const Circle2<T> unit{{T(0), T(0)}, T(1)};
  const Arc2<T> upper{unit, T(0), pi}, lower{unit, pi, pi};
  // A circle of radius 1 around (1, 0) meets the unit circle at angles +-pi/3: one on each arc.
  const Circle2<T> other{{T(1), T(0)}, T(1)};
  auto r = intersection(other, upper);
  ASSERT_EQ(r.kind, Kind::point);
  EXPECT_NEAR(double(r.param_b[0]), pi_v<double> / 3, 16 * double(eps_v<T>));
  r = intersection(lower, other);
  ASSERT_EQ(r.kind, Kind::point);
  EXPECT_NEAR(double(r.param_a[0]), 5 * pi_v<double> / 3, 16 * double(eps_v<T>));
  // The same circle: the whole arc.
  r = intersection(unit, upper);
  ASSERT_EQ(r.kind, Kind::arc);
  ASSERT_EQ(r.count, 3);
  EXPECT_NEAR(double(r.param_b[1]), pi_v<double> / 2, 16 * double(eps_v<T>));
  // Two arcs of one circle: upper [0, pi] and [pi/2, 3pi/2] overlap in [pi/2, pi].
  const auto aa = intersection(upper, Arc2<T>{unit, pi / 2, pi});
  ASSERT_EQ(aa.kind, Kind::arc);
  ASSERT_EQ(aa.count, 3);
  EXPECT_NEAR(double(aa.param_a[0]), pi_v<double> / 2, 16 * double(eps_v<T>));
  EXPECT_NEAR(double(aa.param_a[2]), pi_v<double>, 16 * double(eps_v<T>));
  // Both larger than a half turn: two pieces.
  const auto two = intersection(Arc2<T>{unit, T(0), T(4)}, Arc2<T>{unit, T(3), T(4)});
  ASSERT_EQ(two.kind, Kind::arc);
  EXPECT_EQ(two.count, 6);
  // Touching only at an end point: upper and a shorter lower arc share (-1, 0).
  const auto touch = intersection(upper, Arc2<T>{unit, pi, T(3)});
  EXPECT_EQ(touch.kind, Kind::point);
  EXPECT_EQ(touch.count, 1);
  // Disjoint arcs of crossing circles.
  EXPECT_FALSE(intersects(Arc2<T>{other, T(0), pi / 4}, upper));
  // Degenerate: negative sweep, NaN.
  EXPECT_FALSE(intersects(unit, Arc2<T>{unit, T(0), T(-1)}));
  EXPECT_FALSE(intersects(unit, Arc2<T>{other, std::numeric_limits<T>::quiet_NaN(), T(1)}));
  // Random: arc results are the circle results with angles on the arcs.
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 500; ++it) {
    const Arc2<T> a{{rng.vec<T, 2>(T(-2), T(2)), rng.uniform<T>(T(0.5), T(2))},
                    rng.uniform<T>(T(-4), T(4)),
                    rng.uniform<T>(T(0), T(6))};
    const Arc2<T> b{{rng.vec<T, 2>(T(-2), T(2)), rng.uniform<T>(T(0.5), T(2))},
                    rng.uniform<T>(T(-4), T(4)),
                    rng.uniform<T>(T(0), T(6))};
    const auto ab = intersection(a, b);
    const auto cc = intersection(a.circle, b.circle);
    EXPECT_LE(ab.count, cc.count);
    for (int i = 0; i < ab.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      EXPECT_GE(ab.param_a[k], a.start - T(1e-5));
      EXPECT_LE(ab.param_a[k], a.start + a.sweep + T(1e-5));
      EXPECT_GE(ab.param_b[k], b.start - T(1e-5));
      EXPECT_LE(ab.param_b[k], b.start + b.sweep + T(1e-5));
      EXPECT_LE(max_abs(point_at(a, ab.param_a[k]) - ab.point[k]), T(64) * eps_v<T> * T(4));
      EXPECT_LE(max_abs(point_at(b, ab.param_b[k]) - ab.point[k]), T(64) * eps_v<T> * T(4));
    }
    EXPECT_EQ(intersection(b, a).count, ab.count);
  }
}

// ---- ellipses: a high-precision sampling oracle -------------------------------------------------

/// Value of the conic b (circle or ellipse, via its implicit form) at p, in long double.
template <class T>
long double implicit_value(const Ellipse2<T>& e, long double x, long double y) {
  const long double wx = x - e.center.x, wy = y - e.center.y;
  const long double a = (e.axis[0].x * wx + e.axis[0].y * wy) / e.extent[0];
  const long double b = (e.axis[1].x * wx + e.axis[1].y * wy) / e.extent[1];
  return a * a + b * b - 1;
}
template <class T>
long double implicit_value(const Circle2<T>& c, long double x, long double y) {
  const long double wx = x - c.center.x, wy = y - c.center.y;
  return (wx * wx + wy * wy) / (static_cast<long double>(c.radius) * c.radius) - 1;
}
template <class T>
void point_ld(const Ellipse2<T>& e, long double th, long double& x, long double& y) {
  x = e.center.x + e.extent[0] * std::cos(th) * e.axis[0].x +
      e.extent[1] * std::sin(th) * e.axis[1].x;
  y = e.center.y + e.extent[0] * std::cos(th) * e.axis[0].y +
      e.extent[1] * std::sin(th) * e.axis[1].y;
}

/// Number of sign changes of b along a (crossings), or -1 when the sampling cannot tell
/// (a sample too near zero: a near-tangency the oracle leaves alone).
template <class T, class B>
int crossings_oracle(const Ellipse2<T>& a, const B& b) {
  const int n = 6000;
  int changes = 0;
  long double x, y;
  point_ld(a, 0.0L, x, y);
  long double prev = implicit_value(b, x, y);
  long double minabs = std::abs(prev);
  for (int i = 1; i <= n; ++i) {
    point_ld(a, 2 * pi_v<long double> * i / n, x, y);
    const long double v = implicit_value(b, x, y);
    minabs = std::min(minabs, std::abs(v));
    if ((v > 0) != (prev > 0)) ++changes;
    prev = v;
  }
  if (minabs < 1e-6L) return -1;
  return changes;
}

template <class T>
Ellipse2<T> rand_ellipse(Rng& rng) {
  const Vec2<T> u = rng.unit<T, 2>();
  return {rng.vec<T, 2>(T(-2), T(2)),
          {u, perp(u)},
          {rng.uniform<T>(T(0.4), T(3)), rng.uniform<T>(T(0.4), T(3))}};
}

template <class T, class A, class B>
double on_curve(const A& a, const B& b, const Vec2<T>& p) {
  return double(
      std::max(std::abs(implicit_value(a, p.x, p.y)), std::abs(implicit_value(b, p.x, p.y))));
}

TYPED_TEST(Quadratic, EllipsesAgainstSamplingOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int compared = 0;
  for (int it = 0; it < 300; ++it) {
    const Ellipse2<T> a = rand_ellipse<T>(rng), b = rand_ellipse<T>(rng);
    const auto r = intersection(a, b);
    const int ex = crossings_oracle(a, b);
    // Residuals: on both curves (relative implicit value; the conditioning of transversal
    // points is that of the curves' angle, bounded by the sampling margin above).
    for (int i = 0; i < r.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const T tol = std::is_same_v<T, float> ? T(2e-5) : T(1e-11);
      EXPECT_LE(on_curve<T>(a, b, r.point[k]), tol);
      EXPECT_LE(max_abs(point_at(a, r.param_a[k]) - r.point[k]), T(64) * eps_v<T> * T(8));
      EXPECT_LE(max_abs(point_at(b, r.param_b[k]) - r.point[k]), std::sqrt(eps_v<T>) * T(8));
    }
    const auto s = intersection(b, a);
    EXPECT_EQ(s.count, r.count);
    EXPECT_EQ(intersects(a, b), r.kind != Kind::empty);
    if (ex < 0) continue;
    ++compared;
    int odd = 0;
    for (int i = 0; i < r.count; ++i) odd += r.multiplicity[static_cast<std::size_t>(i)] % 2;
    EXPECT_EQ(odd, ex);
    // Relation: crossings mean overlapping; otherwise nested or separated by the centres.
    const RegionRelation rel = relation(a, b);
    if (ex > 0) {
      EXPECT_EQ(rel, RegionRelation::overlapping);
    } else {
      const bool b_in_a = implicit_value(a, b.center.x, b.center.y) < 0,
                 a_in_b = implicit_value(b, a.center.x, a.center.y) < 0;
      EXPECT_EQ(rel, b_in_a && !a_in_b    ? RegionRelation::a_contains_b
                     : a_in_b && !b_in_a  ? RegionRelation::b_contains_a
                     : !a_in_b && !b_in_a ? RegionRelation::separated
                                          : rel);
    }
  }
  EXPECT_GT(compared, 200);
}

// Figures 7.7-7.10: contained, transversal, separated, four points; tangencies at vertices.
TYPED_TEST(Quadratic, EllipseFigures7_7To7_10) {
  using T = TypeParam;
  const Vec2<T> ex{T(1), T(0)}, ey{T(0), T(1)};
  const Ellipse2<T> e0{{T(0), T(0)}, {ex, ey}, {T(4), T(2)}};
  // 7.7: contained.
  const Ellipse2<T> inner{{T(0.5), T(0.25)}, {ex, ey}, {T(1), T(0.5)}};
  EXPECT_EQ(relation(e0, inner), RegionRelation::a_contains_b);
  EXPECT_EQ(relation(inner, e0), RegionRelation::b_contains_a);
  EXPECT_EQ(intersection(e0, inner).kind, Kind::empty);
  // 7.8: transversal (two points).
  const Ellipse2<T> cross{{T(4), T(0)}, {ex, ey}, {T(1), T(1)}};
  EXPECT_EQ(relation(e0, cross), RegionRelation::overlapping);
  EXPECT_EQ(intersection(e0, cross).count, 2);
  // 7.9: separated.
  EXPECT_EQ(relation(e0, Ellipse2<T>{{T(7), T(3)}, {ex, ey}, {T(1), T(1)}}),
            RegionRelation::separated);
  // 7.10: four points (a tall thin ellipse across a wide one).
  const auto four = intersection(e0, Ellipse2<T>{{T(0), T(0)}, {ex, ey}, {T(1), T(5)}});
  ASSERT_EQ(four.kind, Kind::points);
  EXPECT_EQ(four.count, 4);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(four.multiplicity[static_cast<std::size_t>(i)], 1);
  // Tangent outside at the vertex (4, 0), tangent inside at (-4, 0), and both in 7.10's
  // double-tangent arrangement (same x extent: two tangencies).
  const auto t1 = intersection(e0, Ellipse2<T>{{T(6), T(0)}, {ex, ey}, {T(2), T(1)}});
  ASSERT_EQ(t1.kind, Kind::point);
  EXPECT_EQ(t1.multiplicity[0], 2);
  EXPECT_LE(max_abs(t1.point[0] - Vec2<T>{T(4), T(0)}), T(1e-3));
  EXPECT_EQ(relation(e0, Ellipse2<T>{{T(6), T(0)}, {ex, ey}, {T(2), T(1)}}),
            RegionRelation::touching);
  EXPECT_EQ(relation(e0, Ellipse2<T>{{T(-3), T(0)}, {ex, ey}, {T(1), T(0.5)}}),
            RegionRelation::a_contains_b_touching);
  const auto t2 = intersection(e0, Ellipse2<T>{{T(0), T(0)}, {ex, ey}, {T(4), T(1)}});
  ASSERT_EQ(t2.count, 2);
  EXPECT_EQ(t2.multiplicity[0], 2);
  EXPECT_EQ(t2.multiplicity[1], 2);
  // Equal ellipses.
  EXPECT_EQ(intersection(e0, e0).kind, Kind::coincident);
  EXPECT_EQ(relation(e0, e0), RegionRelation::equal);
  // Circle against ellipse, and the same circle as a quadratic curve (figure 7.5's method).
  const Circle2<T> c{{T(0), T(0)}, T(3)};
  const auto ce = intersection(c, e0);
  ASSERT_EQ(ce.count, 4);
  const auto cq = intersection(c, to_quadratic(e0));
  ASSERT_EQ(cq.count, 4);
  for (int i = 0; i < 4; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_LE(max_abs(ce.point[k] - cq.point[k]), T(1e-4));
  }
  EXPECT_EQ(relation(c, e0), RegionRelation::overlapping);
  // Figure 7.5: an ellipse and a parabola y = x^2 - 2 (x^2 - y - 2 = 0): tangent at the
  // vertex (0, -2), crossing at x = +-sqrt(3.75).
  const auto tp = intersection(e0, QuadraticCurve2<T>{T(1), T(0), T(0), T(0), T(-1), T(-2)});
  ASSERT_EQ(tp.count, 3);  // by angle on e0: the vertex (-pi/2) first
  EXPECT_EQ(tp.multiplicity[0], 2);
  EXPECT_EQ(tp.multiplicity[1], 1);
  EXPECT_EQ(tp.multiplicity[2], 1);
  EXPECT_LE(max_abs(tp.point[0] - Vec2<T>{T(0), T(-2)}), T(1e-3));
  // y = x^2 - 3: four points.
  const QuadraticCurve2<T> parabola{T(1), T(0), T(0), T(0), T(-1), T(-3)};
  const auto ep = intersection(e0, parabola);
  ASSERT_EQ(ep.count, 4);
  for (int i = 0; i < 4; ++i) {
    const Vec2<T> p = ep.point[static_cast<std::size_t>(i)];
    EXPECT_LE(std::abs(p.x * p.x - p.y - T(3)), T(64) * eps_v<T> * T(16));
  }
  EXPECT_EQ(swapped(intersection(parabola, e0)).count, 4);
}

TYPED_TEST(Quadratic, EllipseDegenerate) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Vec2<T> ex{T(1), T(0)}, ey{T(0), T(1)};
  const Ellipse2<T> e0{{T(0), T(0)}, {ex, ey}, {T(4), T(2)}};
  EXPECT_EQ(intersection(e0, Ellipse2<T>{{T(0), T(0)}, {ex, ey}, {T(0), T(2)}}).kind, Kind::empty);
  EXPECT_EQ(intersection(e0, Ellipse2<T>{{T(0), T(0)}, {ex, ex}, {T(1), T(2)}}).kind, Kind::empty);
  EXPECT_EQ(intersection(e0, Ellipse2<T>{{nan, T(0)}, {ex, ey}, {T(1), T(2)}}).kind, Kind::empty);
  EXPECT_EQ(relation(e0, Ellipse2<T>{{nan, T(0)}, {ex, ey}, {T(1), T(2)}}),
            RegionRelation::undecided);
  // A point circle on the ellipse: exactly decided.
  const auto p = intersection(Circle2<T>{{T(4), T(0)}, T(0)}, e0);
  ASSERT_EQ(p.kind, Kind::point);
  EXPECT_EQ(p.point[0], (Vec2<T>{T(4), T(0)}));
  EXPECT_EQ(intersection(Circle2<T>{{T(4), T(1)}, T(0)}, e0).kind, Kind::empty);
}

// Rigid motions (axis swap, sign flip, integer translation) and power-of-two scaling leave
// ellipse pairs' counts, multiplicities and relation unchanged; points move with the data.
TYPED_TEST(Quadratic, EllipseMotionsAndScaling) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 200; ++it) {
    const Ellipse2<T> a = rand_ellipse<T>(rng), b = rand_ellipse<T>(rng);
    if (crossings_oracle(a, b) < 0) continue;  // near-tangent: counts may legitimately merge
    const auto r = intersection(a, b);
    const RegionRelation rel = relation(a, b);
    for (int mo = 0; mo < 4; ++mo) {
      const auto f = [mo](Vec2<T> v, bool is_axis) {
        if (mo == 0) return Vec2<T>{v.y, v.x};
        if (mo == 1) return Vec2<T>{-v.x, v.y};
        if (mo == 2) return is_axis ? v : Vec2<T>{v.x + T(3), v.y - T(2)};
        return is_axis ? v : Vec2<T>{std::ldexp(v.x, 5), std::ldexp(v.y, 5)};
      };
      const auto g = [&](const Ellipse2<T>& e) {
        Ellipse2<T> o{f(e.center, false), {f(e.axis[0], true), f(e.axis[1], true)}, e.extent};
        if (mo == 3) o.extent = {std::ldexp(e.extent[0], 5), std::ldexp(e.extent[1], 5)};
        return o;
      };
      const auto q = intersection(g(a), g(b));
      ASSERT_EQ(q.count, r.count) << "motion " << mo;
      EXPECT_EQ(relation(g(a), g(b)), rel);
      int mr = 0, mq = 0;
      for (int i = 0; i < r.count; ++i) {
        mr += r.multiplicity[static_cast<std::size_t>(i)];
        mq += q.multiplicity[static_cast<std::size_t>(i)];
        // Each moved point is near one of the new points.
        const Vec2<T> moved = f(r.point[static_cast<std::size_t>(i)], false);
        T best = std::numeric_limits<T>::infinity();
        for (int j = 0; j < q.count; ++j)
          best = std::min(best, max_abs(q.point[static_cast<std::size_t>(j)] - moved));
        EXPECT_LE(best, std::sqrt(eps_v<T>) * T(mo == 3 ? 32 * 8 : 8));
      }
      EXPECT_EQ(mq, mr);
    }
  }
}

// General pairs (neither an ellipse): the resultant path.
TYPED_TEST(Quadratic, GeneralQuadraticPairs) {
  using T = TypeParam;
  // Hyperbola x^2 - y^2 = 1 and parabola y = x^2 - 3: x^2 = 2 (y = -1) and x^2 = 5 (y = 2).
  const QuadraticCurve2<T> hyp{T(1), T(0), T(-1), T(0), T(0), T(-1)};
  const QuadraticCurve2<T> par{T(1), T(0), T(0), T(0), T(-1), T(-3)};
  const auto r = intersection(hyp, par);
  ASSERT_EQ(r.kind, Kind::points);
  ASSERT_EQ(r.count, 4);
  const double s2 = std::sqrt(2.0), s5 = std::sqrt(5.0);
  const Vec2<double> expect[4] = {{-s5, 2}, {-s2, -1}, {s2, -1}, {s5, 2}};
  for (const Vec2<double>& e : expect) {
    bool found = false;
    for (int i = 0; i < 4; ++i) {
      const auto k = static_cast<std::size_t>(i);
      found = found || max_abs(vec_cast<double>(r.point[k]) - e) <= 1e3 * double(eps_v<T>);
      EXPECT_EQ(r.multiplicity[k], 1);
    }
    EXPECT_TRUE(found) << e.x << " " << e.y;
  }
  EXPECT_EQ(intersection(par, hyp).count, 4);
  // xy = 1 and y = x^2: only (1, 1) (x^3 = 1).
  const auto one = intersection(QuadraticCurve2<T>{T(0), T(1), T(0), T(0), T(0), T(-1)},
                                QuadraticCurve2<T>{T(1), T(0), T(0), T(0), T(-1), T(0)});
  ASSERT_EQ(one.kind, Kind::point);
  EXPECT_LE(max_abs(one.point[0] - Vec2<T>{T(1), T(1)}), T(64) * eps_v<T>);
  // A parabola tangent to a line pair: y = x^2 and (y + 1 - 2x)(y + 1 + 2x) = 0 touch at (+-1, 1).
  // (y + 1)^2 - 4 x^2 = y^2 + 2y + 1 - 4x^2.
  const auto tang = intersection(QuadraticCurve2<T>{T(1), T(0), T(0), T(0), T(-1), T(0)},
                                 QuadraticCurve2<T>{T(-4), T(0), T(1), T(0), T(2), T(1)});
  ASSERT_EQ(tang.count, 2);
  EXPECT_EQ(tang.multiplicity[0], 2);
  EXPECT_EQ(tang.multiplicity[1], 2);
  // Proportional coefficients: the same curve. Two line pairs sharing the line y = x: that
  // line (the other lines meet on it, so no isolated point).
  EXPECT_EQ(intersection(hyp, QuadraticCurve2<T>{T(-2), T(0), T(2), T(0), T(0), T(2)}).kind,
            Kind::coincident);
  const auto shared = intersection(QuadraticCurve2<T>{T(1), T(0), T(-1), T(0), T(0), T(0)},
                                   QuadraticCurve2<T>{T(0), T(1), T(-1), T(0), T(0), T(0)});
  EXPECT_EQ(shared.kind, Kind::line);
  EXPECT_EQ(shared.count, 2);
  // An ellipse given as a general curve uses the ellipse frame.
  const auto ell = intersection(QuadraticCurve2<T>{T(1), T(0), T(4), T(0), T(0), T(-16)}, par);
  EXPECT_EQ(ell.count, 4);
  EXPECT_EQ(intersection(par, QuadraticCurve2<T>{T(1), T(0), T(4), T(0), T(0), T(-16)}).count, 4);
  // Non-finite: empty.
  EXPECT_EQ(intersection(hyp, QuadraticCurve2<T>{std::numeric_limits<T>::quiet_NaN(), T(0), T(0),
                                                 T(0), T(-1), T(0)})
                .kind,
            Kind::empty);
}

}  // namespace
