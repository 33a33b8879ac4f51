// SPDX-License-Identifier: BSL-1.0
// Row int2.linear-quadratic: intersects() / intersection() of Line2, Ray2, Segment2 against
// Circle2, Arc2, Ellipse2 and QuadraticCurve2, float and double. The count, tangency (one point
// of multiplicity 2) and the "component lies on the curve" case are compared with the exact GMP
// oracle (conic_oracle.hpp, an independent root-location method) on random dyadic inputs, exact
// tangent configurations (Pythagorean triples: a tangent line at (3, 4) of a radius-5 circle;
// ellipses tangent at a vertex) and their one-ulp perturbations. Every returned point must lie on
// both arguments within the header's bound, through its parameters too; the roots must match
// the oracle's (256-bit) values; intersects() agrees; the swapped overload returns swapped();
// power-of-two scaling and exact rigid motions (axis swap, sign flips, integer translations of
// integer data) leave the answer unchanged. Degenerate input: radius 0 and < 0, zero direction,
// degenerate ellipses, NaN / Inf (empty, never a NaN point). Figure 7.1: points on / off an arc.

#include <locus/intersection/line_arc.hpp>
#include <locus/intersection/line_circle.hpp>
#include <locus/intersection/line_ellipse.hpp>
#include <locus/intersection/line_quadratic_curve.hpp>
#include <locus/intersection/ray_arc.hpp>
#include <locus/intersection/ray_circle.hpp>
#include <locus/intersection/ray_ellipse.hpp>
#include <locus/intersection/ray_quadratic_curve.hpp>
#include <locus/intersection/segment_arc.hpp>
#include <locus/intersection/segment_circle.hpp>
#include <locus/intersection/segment_ellipse.hpp>
#include <locus/intersection/segment_quadratic_curve.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "intersection/conic_oracle.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;
namespace oc = locus_test::conic;

template <class T>
class LinearQuadratic : public ::testing::Test {};
TYPED_TEST_SUITE(LinearQuadratic, locus_test::RealTypes);

// ---- linear components: exact-rational view, points, magnitudes -------------------------------
template <class T>
oc::QLin qlin(const Line2<T>& l) {
  return {oc::q(l.origin), oc::q(l.direction), false, false};
}
template <class T>
oc::QLin qlin(const Ray2<T>& l) {
  return {oc::q(l.origin), oc::q(l.direction), true, false};
}
template <class T>
oc::QLin qlin(const Segment2<T>& s) {
  const oc::Q2 a = oc::q(s.p0), b = oc::q(s.p1);
  return {a, {b.x - a.x, b.y - a.y}, true, true};
}
template <class T>
Vec2<double> at(const Line2<T>& l, double t) {
  return vec_cast<double>(l.origin) + t * vec_cast<double>(l.direction);
}
template <class T>
Vec2<double> at(const Ray2<T>& l, double t) {
  return vec_cast<double>(l.origin) + t * vec_cast<double>(l.direction);
}
template <class T>
Vec2<double> at(const Segment2<T>& s, double t) {
  return vec_cast<double>(s.p0) + t * (vec_cast<double>(s.p1) - vec_cast<double>(s.p0));
}
// Distance from p to the carrier line.
template <class L>
double line_distance(const L& l, const Vec2<double>& p) {
  const Vec2<double> o = at(l, 0.0), d = at(l, 1.0) - o;
  return std::abs(perp_dot(d, p - o)) / length(d);
}
template <class T>
double mag(const Line2<T>& l) {
  return double(std::max(max_abs(l.origin), max_abs(l.origin + l.direction)));
}
template <class T>
double mag(const Ray2<T>& l) {
  return double(std::max(max_abs(l.origin), max_abs(l.origin + l.direction)));
}
template <class T>
double mag(const Segment2<T>& s) {
  return double(std::max(max_abs(s.p0), max_abs(s.p1)));
}
template <class T>
double mag(const Circle2<T>& c) {
  return double(std::max(max_abs(c.center), std::abs(c.radius)));
}
template <class T>
double mag(const Ellipse2<T>& e) {
  return double(std::max({max_abs(e.center), e.extent[0], e.extent[1]}));
}
// Distance of p from a circle and an ellipse (first order, from the implicit value).
template <class T>
double curve_distance(const Circle2<T>& c, const Vec2<double>& p) {
  return std::abs(length(p - vec_cast<double>(c.center)) - double(c.radius));
}
template <class T>
double curve_distance(const Ellipse2<T>& e, const Vec2<double>& p) {
  const Vec2<double> w = p - vec_cast<double>(e.center);
  const double x = dot(vec_cast<double>(e.axis[0]), w) / double(e.extent[0]);
  const double y = dot(vec_cast<double>(e.axis[1]), w) / double(e.extent[1]);
  // |Q| / |grad Q| with Q = x^2 + y^2 - 1 in world units.
  const double g = 2.0 * std::hypot(x / double(e.extent[0]), y / double(e.extent[1]));
  return std::abs(x * x + y * y - 1.0) / g;
}

template <class L, class C>
struct Check {
  const L& l;
  const C& c;
  double bound;  // on-both-curves bound
  double along;  // error allowed along the line, relative to the oracle's parameter
};

/// The library's answer against the oracle, residuals, parameters, swap, intersects.
template <class T, class L, class C>
void check_pair(const L& l, const C& c, double k_on, double k_along) {
  const auto r = intersection(l, c);
  const oc::LinAnswer ex = oc::solve_linear_conic(oc::conic_fun(c), qlin(l));
  ASSERT_FALSE(ex.whole);
  ASSERT_EQ(r.count, ex.count) << "kind " << to_string(r.kind);
  EXPECT_EQ(r.kind, ex.count == 0 ? Kind::empty : ex.count == 1 ? Kind::point : Kind::points);
  EXPECT_EQ(intersects(l, c), ex.count > 0);
  const double m = std::max(mag(l), mag(c));
  const double eps = double(eps_v<T>);
  const Vec2<double> o = at(l, 0.0), d = at(l, 1.0) - o;
  for (int i = 0; i < r.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_EQ(r.multiplicity[k], ex.mult[i]);
    const Vec2<double> p = vec_cast<double>(r.point[k]);
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
    EXPECT_LE(line_distance(l, p), k_on * eps * m);
    EXPECT_LE(curve_distance(c, p), k_on * eps * m);
    // The parameter: the point at it, and the oracle's root (sqrt(eps) near tangency).
    EXPECT_LE(length(at(l, double(r.param_a[k])) - p), k_on * eps * m);
    // Conditioning: an error of eps m^2 in the squared half chord H^2 moves a root by
    // eps m^2 / (H |d|), H = |t2 - t1| |d| / 2 (a near-tangency); sqrt(eps) m at a tangency.
    const double gap = ex.count == 2 ? std::abs(ex.t[1] - ex.t[0]) * length(d) : m;
    const double tol_t =
        ex.mult[i] == 2 ? 4.0 * std::sqrt(eps) * m / length(d)
                        : k_along * eps * m / length(d) * (1.0 + 2.0 * m / std::max(gap, 1e-300));
    EXPECT_NEAR(double(r.param_a[k]), ex.t[i], tol_t);
  }
  // Swapped overload.
  const auto s = intersection(c, l);
  EXPECT_EQ(s.kind, r.kind);
  ASSERT_EQ(s.count, r.count);
  for (int i = 0; i < r.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_EQ(s.param_a[k], r.param_b[k]);
    EXPECT_EQ(s.param_b[k], r.param_a[k]);
    EXPECT_EQ(s.point[k], r.point[k]);
  }
  EXPECT_EQ(intersects(c, l), intersects(l, c));
}

template <class T>
T dyadic(Rng& rng, int range, int bits) {
  return static_cast<T>(std::ldexp(double(rng.uniform_int(-range, range)), -bits));
}

// ---- circles -----------------------------------------------------------------------------------

template <class T, class L>
void random_circles(Rng& rng, L (*make)(Vec2<T>, Vec2<T>)) {
  for (int it = 0; it < 400; ++it) {
    const Circle2<T> c{{dyadic<T>(rng, 64, 3), dyadic<T>(rng, 64, 3)},
                       std::abs(dyadic<T>(rng, 64, 3)) + T(0.125)};
    const Vec2<T> p{dyadic<T>(rng, 96, 3), dyadic<T>(rng, 96, 3)};
    Vec2<T> q{dyadic<T>(rng, 96, 3), dyadic<T>(rng, 96, 3)};
    if (q == p) q.x += T(1);
    check_pair<T>(make(p, q), c, 8.0, 16.0);
    // Random doubles (generic position).
    const Circle2<T> c2{rng.vec<T, 2>(T(-4), T(4)), rng.uniform<T>(T(0.5), T(3))};
    check_pair<T>(make(rng.vec<T, 2>(T(-6), T(6)), rng.vec<T, 2>(T(-6), T(6))), c2, 8.0, 16.0);
  }
}

template <class T>
Line2<T> mk_line(Vec2<T> p, Vec2<T> q) {
  return {p, q - p};
}
template <class T>
Ray2<T> mk_ray(Vec2<T> p, Vec2<T> q) {
  return {p, q - p};
}
template <class T>
Segment2<T> mk_seg(Vec2<T> p, Vec2<T> q) {
  return {p, q};
}

TYPED_TEST(LinearQuadratic, CirclesAgainstExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  random_circles<T>(rng, &mk_line<T>);
  random_circles<T>(rng, &mk_ray<T>);
  random_circles<T>(rng, &mk_seg<T>);
}

// Exact tangencies from the Pythagorean triple (3, 4, 5), in every orientation, and the
// same lines moved by one ulp either way (then 0 or 2 points, as the oracle says).
TYPED_TEST(LinearQuadratic, CircleTangencyExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 200; ++it) {
    const Vec2<T> c{T(rng.uniform_int(-50, 50)), T(rng.uniform_int(-50, 50))};
    const int sx = rng.uniform_int(0, 1) ? 1 : -1, sy = rng.uniform_int(0, 1) ? 1 : -1;
    const bool swap = rng.uniform_int(0, 1) == 1;
    Vec2<T> off{T(3 * sx), T(4 * sy)};
    if (swap) off = {off.y, off.x};
    const Vec2<T> touch = c + off;
    const Vec2<T> dir = T(rng.uniform_int(1, 3)) * perp(off);
    const Circle2<T> circle{c, T(5)};
    const T back = T(rng.uniform_int(1, 4));
    const Line2<T> line{touch - back * dir, dir};
    const auto r = intersection(line, circle);
    ASSERT_EQ(r.kind, Kind::point);
    EXPECT_EQ(r.multiplicity[0], 2);
    EXPECT_LE(max_abs(r.point[0] - touch), T(8) * eps_v<T> * T(60));
    check_pair<T>(line, circle, 8.0, 16.0);
    check_pair<T>(Ray2<T>{touch - back * dir, dir}, circle, 8.0, 16.0);
    check_pair<T>(Segment2<T>{touch - back * dir, touch + dir}, circle, 8.0, 16.0);
    // Tangent point exactly at a segment's end: included.
    const auto e = intersection(Segment2<T>{touch - dir, touch}, circle);
    ASSERT_EQ(e.kind, Kind::point);
    EXPECT_EQ(e.point[0], touch);
    EXPECT_EQ(e.param_a[0], T(1));
    // One ulp off the tangent line: the oracle decides.
    for (T sgn : {T(-1), T(1)}) {
      Vec2<T> o2 = line.origin;
      o2.x = std::nextafter(o2.x, o2.x + sgn);
      check_pair<T>(Line2<T>{o2, dir}, circle, 8.0, 16.0);
    }
  }
}

// An input point exactly on the circle is returned exactly, with parameter 0 or 1.
TYPED_TEST(LinearQuadratic, EndPointsOnCircleExact) {
  using T = TypeParam;
  const Circle2<T> c{{T(1), T(2)}, T(5)};
  const Vec2<T> on{T(4), T(6)}, on2{T(-4), T(2)};  // (3, 4) and (-5, 0) from the centre
  const auto r = intersection(Segment2<T>{on, on2}, c);
  ASSERT_EQ(r.kind, Kind::points);
  EXPECT_EQ(r.point[0], on);
  EXPECT_EQ(r.param_a[0], T(0));
  EXPECT_EQ(r.point[1], on2);
  EXPECT_EQ(r.param_a[1], T(1));
  const auto ray = intersection(Ray2<T>{on, on - c.center}, c);  // pointing outward
  ASSERT_EQ(ray.kind, Kind::point);
  EXPECT_EQ(ray.point[0], on);
  EXPECT_EQ(ray.multiplicity[0], 1);
  // Parameter on the circle: the angle of the point.
  EXPECT_NEAR(double(r.param_b[0]), std::atan2(4.0, 3.0), 4 * double(eps_v<T>));
}

// Power-of-two scaling and exact rigid motions leave the answer unchanged.
TYPED_TEST(LinearQuadratic, ScalingAndRigidMotions) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int kmax = std::is_same_v<T, float> ? 60 : 400;
  for (int it = 0; it < 300; ++it) {
    const Circle2<T> c{{dyadic<T>(rng, 64, 2), dyadic<T>(rng, 64, 2)},
                       std::abs(dyadic<T>(rng, 40, 2)) + T(0.25)};
    const Segment2<T> s{{dyadic<T>(rng, 80, 2), dyadic<T>(rng, 80, 2)},
                        {dyadic<T>(rng, 80, 2), dyadic<T>(rng, 80, 2)}};
    const auto r = intersection(s, c);
    for (int k : {-kmax, -3, 5, kmax}) {
      const auto sc = [k](Vec2<T> v) { return Vec2<T>{std::ldexp(v.x, k), std::ldexp(v.y, k)}; };
      const auto q = intersection(Segment2<T>{sc(s.p0), sc(s.p1)},
                                  Circle2<T>{sc(c.center), std::ldexp(c.radius, k)});
      ASSERT_EQ(q.kind, r.kind);
      ASSERT_EQ(q.count, r.count);
      for (int i = 0; i < r.count; ++i) {
        const auto j = static_cast<std::size_t>(i);
        EXPECT_EQ(q.point[j], sc(r.point[j]));
        EXPECT_EQ(q.param_a[j], r.param_a[j]);
        EXPECT_EQ(q.multiplicity[j], r.multiplicity[j]);
      }
    }
    // Axis swap, sign flip of x, integer translation: same kind, count, multiplicities, params.
    const auto motions = {0, 1, 2};
    for (int mo : motions) {
      const auto f = [mo](Vec2<T> v) {
        if (mo == 0) return Vec2<T>{v.y, v.x};
        if (mo == 1) return Vec2<T>{-v.x, v.y};
        return Vec2<T>{v.x + T(7), v.y - T(3)};
      };
      const auto q = intersection(Segment2<T>{f(s.p0), f(s.p1)}, Circle2<T>{f(c.center), c.radius});
      ASSERT_EQ(q.kind, r.kind);
      ASSERT_EQ(q.count, r.count);
      for (int i = 0; i < r.count; ++i) {
        const auto j = static_cast<std::size_t>(i);
        EXPECT_EQ(q.multiplicity[j], r.multiplicity[j]);
        EXPECT_LE(max_abs(q.point[j] - f(r.point[j])), T(16) * eps_v<T> * T(40));
      }
    }
  }
}

TYPED_TEST(LinearQuadratic, CircleDegenerateInput) {
  using T = TypeParam;
  const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  const Line2<T> x_axis{{T(0), T(0)}, {T(1), T(0)}};
  // Point circle: met only through its centre, as a tangency.
  auto r = intersection(x_axis, Circle2<T>{{T(3), T(0)}, T(0)});
  ASSERT_EQ(r.kind, Kind::point);
  EXPECT_EQ(r.point[0], (Vec2<T>{T(3), T(0)}));
  EXPECT_EQ(r.multiplicity[0], 2);
  EXPECT_FALSE(intersects(x_axis, Circle2<T>{{T(3), T(1)}, T(0)}));
  // Negative radius: empty.
  EXPECT_EQ(intersection(x_axis, Circle2<T>{{T(0), T(0)}, T(-1)}).kind, Kind::empty);
  // Zero direction: the origin.
  r = intersection(Line2<T>{{T(1), T(0)}, {T(0), T(0)}}, Circle2<T>{{T(0), T(0)}, T(1)});
  ASSERT_EQ(r.kind, Kind::point);
  EXPECT_EQ(r.point[0], (Vec2<T>{T(1), T(0)}));
  EXPECT_FALSE(intersects(Segment2<T>{{T(1), T(1)}, {T(1), T(1)}}, Circle2<T>{{T(0), T(0)}, T(1)}));
  // Non-finite anywhere: empty, never a NaN point.
  for (T bad : {nan, inf, -inf}) {
    EXPECT_EQ(
        intersection(Line2<T>{{bad, T(0)}, {T(1), T(0)}}, Circle2<T>{{T(0), T(0)}, T(1)}).kind,
        Kind::empty);
    EXPECT_EQ(
        intersection(Line2<T>{{T(0), T(0)}, {bad, T(0)}}, Circle2<T>{{T(0), T(0)}, T(1)}).kind,
        Kind::empty);
    EXPECT_EQ(intersection(x_axis, Circle2<T>{{T(0), bad}, T(1)}).kind, Kind::empty);
    EXPECT_EQ(intersection(x_axis, Circle2<T>{{T(0), T(0)}, bad}).kind, Kind::empty);
    EXPECT_EQ(
        intersection(Segment2<T>{{T(0), T(0)}, {bad, T(1)}}, Circle2<T>{{T(0), T(0)}, T(1)}).kind,
        Kind::empty);
    EXPECT_EQ(
        intersection(x_axis, Ellipse2<T>{{T(0), T(0)}, {{T(1), T(0)}, {T(0), T(1)}}, {bad, T(1)}})
            .kind,
        Kind::empty);
    EXPECT_EQ(intersection(x_axis, QuadraticCurve2<T>{T(1), T(0), T(1), T(0), T(0), bad}).kind,
              Kind::empty);
    EXPECT_EQ(intersection(x_axis, Arc2<T>{{{T(0), T(0)}, T(1)}, bad, T(1)}).kind, Kind::empty);
  }
}

// ---- arcs (figure 7.1) -------------------------------------------------------------------------

TYPED_TEST(LinearQuadratic, ArcFigure7_1) {
  using T = TypeParam;
  // The upper half of the unit circle, from A = (1, 0) counter-clockwise to B = (-1, 0).
  const Arc2<T> arc{{{T(0), T(0)}, T(1)}, T(0), pi_v<T>};
  // A vertical line at x = 0.6 meets the circle at (0.6, +-0.8): only P = (0.6, 0.8) is on the arc.
  const auto r = intersection(Line2<T>{{T(0.6), T(-2)}, {T(0), T(1)}}, arc);
  ASSERT_EQ(r.kind, Kind::point);
  EXPECT_LE(max_abs(r.point[0] - Vec2<T>{T(0.6), T(0.8)}), T(8) * eps_v<T>);
  EXPECT_NEAR(double(r.param_b[0]), std::atan2(0.8, 0.6), 8 * double(eps_v<T>));
  // Below the chord AB: the line y = -0.5 meets the circle, not the arc.
  EXPECT_FALSE(intersects(Line2<T>{{T(0), T(-0.5)}, {T(1), T(0)}}, arc));
  // Through the chord: the line y = 0 meets the arc at its two end points.
  EXPECT_EQ(intersection(Line2<T>{{T(-3), T(0)}, {T(1), T(0)}}, arc).count, 2);
  // A whole-circle arc equals the circle.
  const Arc2<T> full{{{T(0), T(0)}, T(1)}, T(1), T(2) * pi_v<T>};
  EXPECT_EQ(intersection(Line2<T>{{T(0), T(-0.5)}, {T(1), T(0)}}, full).count, 2);
  // Arc parameters lie in [start, start + sweep].
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 300; ++it) {
    const Arc2<T> a{{rng.vec<T, 2>(T(-2), T(2)), rng.uniform<T>(T(0.5), T(2))},
                    rng.uniform<T>(T(-7), T(7)),
                    rng.uniform<T>(T(0), T(6))};
    const Segment2<T> s{rng.vec<T, 2>(T(-4), T(4)), rng.vec<T, 2>(T(-4), T(4))};
    const auto ra = intersection(s, a);
    const auto rc = intersection(s, a.circle);
    EXPECT_LE(ra.count, rc.count);
    for (int i = 0; i < ra.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      EXPECT_GE(ra.param_b[k], a.start - T(8) * eps_v<T> * T(8));
      EXPECT_LE(ra.param_b[k], a.start + a.sweep + T(8) * eps_v<T> * T(16));
      EXPECT_LE(max_abs(point_at(a, ra.param_b[k]) - ra.point[k]), T(64) * eps_v<T> * T(4));
    }
    // Each circle point whose angle lies clearly inside the sweep is on the arc; clearly
    // outside, not.
    for (int i = 0; i < rc.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      double off = std::fmod(double(rc.param_b[k]) - double(a.start), 2 * pi_v<double>);
      if (off < 0) off += 2 * pi_v<double>;
      const bool inside = off<double(a.sweep) - 1e-4, outside = off> double(a.sweep) + 1e-4 &&
                          off < 2 * pi_v<double> - 1e-4;
      bool found = false;
      for (int j = 0; j < ra.count; ++j)
        found = found || ra.point[static_cast<std::size_t>(j)] == rc.point[k];
      if (inside) {
        EXPECT_TRUE(found);
      }
      if (outside) {
        EXPECT_FALSE(found);
      }
    }
  }
}

// ---- ellipses ----------------------------------------------------------------------------------

template <class T>
Ellipse2<T> random_ellipse(Rng& rng) {
  // Exactly orthonormal axes: a Pythagorean rotation (3/5, 4/5) or the coordinate axes, so
  // the dyadic-data oracle sees the same curve as the library's unit-axis construction.
  const int choice = rng.uniform_int(0, 3);
  Vec2<T> u{T(1), T(0)};
  if (choice == 1) u = {T(0.6), T(0.8)};
  if (choice == 2) u = {T(-0.8), T(0.6)};
  if (choice == 3) u = rng.unit<T, 2>();
  return {{dyadic<T>(rng, 40, 3), dyadic<T>(rng, 40, 3)},
          {u, perp(u)},
          {std::abs(dyadic<T>(rng, 32, 3)) + T(0.25), std::abs(dyadic<T>(rng, 32, 3)) + T(0.25)}};
}

TYPED_TEST(LinearQuadratic, EllipsesAgainstExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 400; ++it) {
    const Ellipse2<T> e = random_ellipse<T>(rng);
    const double ratio =
        double(std::max(e.extent[0], e.extent[1]) / std::min(e.extent[0], e.extent[1]));
    const Vec2<T> p{dyadic<T>(rng, 64, 3), dyadic<T>(rng, 64, 3)};
    Vec2<T> q{dyadic<T>(rng, 64, 3), dyadic<T>(rng, 64, 3)};
    if (q == p) q.y += T(1);
    // The unit-axis construction needs exactly unit axes for the oracle's curve to be the same.
    if (sqr_length(vec_cast<double>(e.axis[0])) != 1.0) continue;
    check_pair<T>(mk_line<T>(p, q), e, 16.0 * ratio, 32.0 * ratio * ratio);
    check_pair<T>(mk_ray<T>(p, q), e, 16.0 * ratio, 32.0 * ratio * ratio);
    check_pair<T>(mk_seg<T>(p, q), e, 16.0 * ratio, 32.0 * ratio * ratio);
  }
  // Tangent at a vertex: the line x = c.x + e0 (axis-aligned ellipse).
  for (int it = 0; it < 50; ++it) {
    Ellipse2<T> e = random_ellipse<T>(rng);
    e.axis[0] = {T(1), T(0)};
    e.axis[1] = {T(0), T(1)};
    const Line2<T> l{{e.center.x + e.extent[0], T(rng.uniform_int(-9, 9))}, {T(0), T(1)}};
    const auto r = intersection(l, e);
    ASSERT_EQ(r.kind, Kind::point);
    EXPECT_EQ(r.multiplicity[0], 2);
    check_pair<T>(l, e, 16.0, 32.0);
  }
}

TYPED_TEST(LinearQuadratic, EllipseDegenerate) {
  using T = TypeParam;
  const Line2<T> l{{T(0), T(0)}, {T(1), T(0)}};
  const Vec2<T> ex{T(1), T(0)}, ey{T(0), T(1)};
  EXPECT_EQ(intersection(l, Ellipse2<T>{{T(0), T(0)}, {ex, ey}, {T(0), T(1)}}).kind, Kind::empty);
  EXPECT_EQ(intersection(l, Ellipse2<T>{{T(0), T(0)}, {ex, ey}, {T(-1), T(1)}}).kind, Kind::empty);
  EXPECT_EQ(intersection(l, Ellipse2<T>{{T(0), T(0)}, {ex, ex}, {T(2), T(1)}}).kind, Kind::empty);
  const auto r = intersection(l, Ellipse2<T>{{T(0), T(0)}, {ex, ey}, {T(2), T(1)}});
  ASSERT_EQ(r.kind, Kind::points);
  EXPECT_EQ(r.point[0], (Vec2<T>{T(-2), T(0)}));
  EXPECT_EQ(r.point[1], (Vec2<T>{T(2), T(0)}));
  EXPECT_NEAR(double(r.param_b[0]), pi_v<double>, 4 * double(eps_v<T>));
}

// ---- general quadratic curves (figure 7.5's parabola, hyperbolas, line pairs) -------------------

template <class T>
double quad_residual(const QuadraticCurve2<T>& k, const Vec2<double>& p, double& scale) {
  const double a = double(k.a), b = double(k.b), c = double(k.c), d = double(k.d), e = double(k.e),
               f = double(k.f);
  scale = std::abs(a * p.x * p.x) + std::abs(b * p.x * p.y) + std::abs(c * p.y * p.y) +
          std::abs(d * p.x) + std::abs(e * p.y) + std::abs(f);
  return std::abs(a * p.x * p.x + b * p.x * p.y + c * p.y * p.y + d * p.x + e * p.y + f);
}

template <class T, class L>
void check_quad(const L& l, const QuadraticCurve2<T>& k) {
  const auto r = intersection(l, k);
  const oc::LinAnswer ex = oc::solve_linear_conic(oc::conic_fun(k), qlin(l));
  if (ex.whole) {
    const Kind whole = std::is_same_v<L, Line2<T>>  ? Kind::line
                       : std::is_same_v<L, Ray2<T>> ? Kind::ray
                                                    : Kind::segment;
    EXPECT_EQ(r.kind, whole);
    EXPECT_TRUE(intersects(l, k));
    return;
  }
  ASSERT_EQ(r.count, ex.count);
  EXPECT_EQ(intersects(l, k), ex.count > 0);
  const double eps = double(eps_v<T>);
  for (int i = 0; i < r.count; ++i) {
    const auto j = static_cast<std::size_t>(i);
    EXPECT_EQ(r.multiplicity[j], ex.mult[i]);
    const Vec2<double> p = vec_cast<double>(r.point[j]);
    double s = 0;
    const double res = quad_residual(k, p, s);
    // Rounding X (o + t d, coordinates of magnitude up to m) adds |grad Q| eps m.
    const double gx = std::abs(2 * double(k.a) * p.x + double(k.b) * p.y + double(k.d)),
                 gy = std::abs(double(k.b) * p.x + 2 * double(k.c) * p.y + double(k.e));
    const double ml = std::max(mag(l), double(max_abs(p)));
    if (ex.mult[i] == 1) {
      EXPECT_LE(res, 64.0 * eps * (s + (gx + gy) * ml) + 1e-300);
    }
    EXPECT_LE(line_distance(l, p), 8 * eps * std::max(mag(l), max_abs(p)));
  }
  const auto sw = intersection(k, l);
  EXPECT_EQ(sw.count, r.count);
}

TYPED_TEST(LinearQuadratic, QuadraticCurvesAgainstExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 400; ++it) {
    const QuadraticCurve2<T> k{dyadic<T>(rng, 8, 1), dyadic<T>(rng, 8, 1), dyadic<T>(rng, 8, 1),
                               dyadic<T>(rng, 8, 0), dyadic<T>(rng, 8, 0), dyadic<T>(rng, 16, 0)};
    const Vec2<T> p{dyadic<T>(rng, 16, 1), dyadic<T>(rng, 16, 1)};
    Vec2<T> q{dyadic<T>(rng, 16, 1), dyadic<T>(rng, 16, 1)};
    if (q == p) q.x += T(1);
    check_quad<T>(mk_line<T>(p, q), k);
    check_quad<T>(mk_ray<T>(p, q), k);
    check_quad<T>(mk_seg<T>(p, q), k);
  }
  // Figure 7.5's parabola y = x^2 (x^2 - y = 0): the line y = 1 meets it at x = -1, 1; the
  // tangent y = 2x - 1 touches at (1, 1); a line along the axis (x = 0.5) meets it once (A = 0).
  const QuadraticCurve2<T> parabola{T(1), T(0), T(0), T(0), T(-1), T(0)};
  auto r = intersection(Line2<T>{{T(0), T(1)}, {T(1), T(0)}}, parabola);
  ASSERT_EQ(r.kind, Kind::points);
  EXPECT_EQ(r.point[0], (Vec2<T>{T(-1), T(1)}));
  EXPECT_EQ(r.point[1], (Vec2<T>{T(1), T(1)}));
  r = intersection(Line2<T>{{T(0), T(-1)}, {T(1), T(2)}}, parabola);
  ASSERT_EQ(r.kind, Kind::point);
  EXPECT_EQ(r.multiplicity[0], 2);
  EXPECT_EQ(r.point[0], (Vec2<T>{T(1), T(1)}));
  r = intersection(Ray2<T>{{T(0.5), T(-3)}, {T(0), T(1)}}, parabola);
  ASSERT_EQ(r.kind, Kind::point);
  EXPECT_EQ(r.multiplicity[0], 1);
  EXPECT_EQ(r.point[0], (Vec2<T>{T(0.5), T(0.25)}));
  // A line pair (x - y)(x + y) = 0 contains the segment from (0, 0) to (2, 2).
  const QuadraticCurve2<T> pair{T(1), T(0), T(-1), T(0), T(0), T(0)};
  const auto w = intersection(Segment2<T>{{T(0), T(0)}, {T(2), T(2)}}, pair);
  EXPECT_EQ(w.kind, Kind::segment);
  EXPECT_EQ(w.point[1], (Vec2<T>{T(2), T(2)}));
}

}  // namespace
