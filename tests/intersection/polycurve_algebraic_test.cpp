// SPDX-License-Identifier: BSL-1.0
// Row int2.polycurve, the algebraic parts: the resultant method (book 7.4.1) against the
// subdivision on seeded random curve pairs (same crossings within the stated bounds), tangency
// and odd-contact multiplicities; shared sub-arcs (a cubic and its subdivided, reversed and
// degree-elevated pieces, partially overlapping pieces) reported as parameter interval pairs;
// self-intersections of cubic loops against the closed-form double point evaluated in GMP
// (rationals, then a 256-bit square root), also as a two-span B-spline; degenerate and
// non-finite input.

#include <locus/intersection/curve_curve.hpp>
#include <locus/intersection/curve_self.hpp>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class PolycurveAlgebraic : public ::testing::Test {};
TYPED_TEST_SUITE(PolycurveAlgebraic, locus_test::RealTypes);

CurveHitOptions with(CurveMethod m) {
  CurveHitOptions o;
  o.method = m;
  o.raster_cells = 64;
  return o;
}

template <class T>
std::vector<Vec2<T>> control(Rng& rng, int n, int den = 16) {
  std::vector<Vec2<T>> p;
  for (int i = 0; i < n; ++i)
    p.push_back({static_cast<T>(rng.uniform_int(-4 * den, 4 * den)) / static_cast<T>(den),
                 static_cast<T>(rng.uniform_int(-4 * den, 4 * den)) / static_cast<T>(den)});
  return p;
}

template <class C>
Vec2<double> at(const C& c, double t) {
  return vec_cast<double>(point_at(c, static_cast<curve_scalar_t<C>>(t)));
}

/// The control points of the Bézier piece [lo, hi] of c (de Casteljau twice; exact at dyadics).
template <class T>
BezierCurve2<T> piece(const BezierCurve2<T>& c, T lo, T hi) {
  const auto cut = [](const std::vector<Vec2<T>>& p, T u, bool keep_right) {
    std::vector<Vec2<T>> b = p, left, right(p.size());
    left.push_back(b[0]);
    right[p.size() - 1] = b.back();
    for (std::size_t r = 1; r < p.size(); ++r) {
      for (std::size_t i = 0; i + r < p.size(); ++i) b[i] = (T(1) - u) * b[i] + u * b[i + 1];
      left.push_back(b[0]);
      right[p.size() - 1 - r] = b[p.size() - 1 - r];
    }
    return keep_right ? right : left;
  };
  std::vector<Vec2<T>> p = cut(c.control, lo, true);
  p = cut(p, (hi - lo) / (T(1) - lo), false);
  return {p};
}

// ---- the resultant against the subdivision -----------------------------------------------------

template <class A, class B>
void compare_methods(const A& a, const B& b, int& compared) {
  using T = curve_scalar_t<A>;
  const auto sub = intersection(a, b, with(CurveMethod::algebraic));
  const auto res = intersection(a, b, with(CurveMethod::resultant));
  ASSERT_EQ(sub.status, Status::ok);
  ASSERT_EQ(res.status, Status::ok);
  double scale = 0.0;
  for (const auto& p : a.control) scale = std::max(scale, double(max_abs(p)));
  for (const auto& p : b.control) scale = std::max(scale, double(max_abs(p)));
  // Compare where the crossings are well conditioned: simple, 2^-8 of the scale apart.
  for (std::size_t i = 0; i < sub.hits.size(); ++i) {
    if (sub.hits[i].multiplicity != 1) return;
    for (std::size_t j = 0; j < i; ++j)
      if (length(vec_cast<double>(sub.hits[i].point - sub.hits[j].point)) < 0x1p-8 * scale) return;
  }
  ++compared;
  ASSERT_EQ(res.hits.size(), sub.hits.size());
  const double tol = std::max(1e-9, 8.0 * double(eps_v<T>));
  for (std::size_t i = 0; i < res.hits.size(); ++i) {
    const auto& h = res.hits[i];
    EXPECT_EQ(h.multiplicity, 1);
    EXPECT_NEAR(double(h.param_a), double(sub.hits[i].param_a), tol);
    EXPECT_NEAR(double(h.param_b), double(sub.hits[i].param_b), tol);
    const Vec2<double> p = vec_cast<double>(h.point);
    EXPECT_LE(length(p - at(a, double(h.param_a))), tol * scale);
    EXPECT_LE(length(p - at(b, double(h.param_b))), tol * scale);
  }
  // The swapped order: the same points, parameters exchanged.
  const auto sw = intersection(b, a, with(CurveMethod::resultant));
  ASSERT_EQ(sw.hits.size(), res.hits.size());
}

TYPED_TEST(PolycurveAlgebraic, ResultantAgreesWithSubdivision) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 41);
  SCOPED_TRACE(rng.trace());
  int compared = 0, total = 0, crossings = 0;
  for (int trial = 0; trial < 24; ++trial) {
    SCOPED_TRACE(trial);
    const BezierCurve2<T> a{control<T>(rng, 4)}, b{control<T>(rng, rng.uniform_int(2, 4))};
    compare_methods(a, b, compared);
    crossings += static_cast<int>(intersection(a, b).hits.size());
    // Rational pieces: a NURBS of degree 2 or 3 (one span) against the cubic.
    const int d = rng.uniform_int(2, 3);
    std::vector<T> w, k;
    for (int i = 0; i <= d; ++i) w.push_back(static_cast<T>(rng.uniform_int(2, 12)) / T(4));
    for (int i = 0; i <= d; ++i) k.push_back(T(0));
    for (int i = 0; i <= d; ++i) k.push_back(T(1));
    const NurbsCurve2<T> n{d, control<T>(rng, d + 1), w, k};
    compare_methods(n, a, compared);
    total += 2;
  }
  EXPECT_GE(compared, total * 3 / 4);
  EXPECT_GE(crossings, 12);  // the pairs do cross
}

TYPED_TEST(PolycurveAlgebraic, ResultantMultiplicityAndScaling) {
  using T = TypeParam;
  // Parabolas touching at (1, 0): a double root of the resultant.
  const BezierCurve2<T> up{{{T(0), T(1)}, {T(1), T(-1)}, {T(2), T(1)}}};
  const BezierCurve2<T> down{{{T(0), T(-1)}, {T(1), T(1)}, {T(2), T(-1)}}};
  const auto r = intersection(up, down, with(CurveMethod::resultant));
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.hits.size(), 1u);
  EXPECT_EQ(r.hits[0].multiplicity, 2);
  EXPECT_LE(length(vec_cast<double>(r.hits[0].point) - Vec2<double>{1.0, 0.0}), 0x1p-18 * 2.0);
  // y = (t - 1/2)^3 against the x axis: an inflection crossing, contact of order 3.
  const BezierCurve2<T> cubic{
      {{T(0), T(-0.125)}, {T(1), T(0.125)}, {T(2), T(-0.125)}, {T(3), T(0.125)}}};
  const BezierCurve2<T> axis{{{T(-1), T(0)}, {T(4), T(0)}}};
  const auto c = intersection(axis, cubic, with(CurveMethod::resultant));
  ASSERT_EQ(c.hits.size(), 1u);
  EXPECT_EQ(c.hits[0].multiplicity, 3);
  EXPECT_NEAR(double(c.hits[0].param_b), 0.5, 1e-4);
  // Shifted apart by 2^-10: a near miss.
  BezierCurve2<T> lower = down;
  for (auto& p : lower.control) p.y -= T(0x1p-10);
  EXPECT_TRUE(intersection(up, lower, with(CurveMethod::resultant)).hits.empty());
  // Power-of-two scaling leaves the parameters unchanged.
  const BezierCurve2<T> s1{{{T(0), T(0)}, {T(1), T(3)}, {T(2), T(-2)}, {T(3), T(1)}}};
  const auto base = intersection(up, s1, with(CurveMethod::resultant));
  ASSERT_EQ(base.hits.size(), 2u);
  for (int e : {-7, 9}) {
    const T s = std::ldexp(T(1), e);
    BezierCurve2<T> u2 = up, s2 = s1;
    for (auto& p : u2.control) p = s * p;
    for (auto& p : s2.control) p = s * p;
    const auto q = intersection(u2, s2, with(CurveMethod::resultant));
    ASSERT_EQ(q.hits.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_EQ(q.hits[i].param_a, base.hits[i].param_a);
      EXPECT_EQ(q.hits[i].param_b, base.hits[i].param_b);
    }
  }
}

// ---- shared sub-arcs ---------------------------------------------------------------------------

template <class A, class B>
void expect_overlap(const A& a, const B& b, double a0, double b0, double a1, double b1) {
  for (CurveMethod m : {CurveMethod::algebraic, CurveMethod::hierarchy, CurveMethod::resultant,
                        CurveMethod::raster}) {
    SCOPED_TRACE(int(m));
    const auto r = intersection(a, b, with(m));
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_EQ(r.kind, Kind::coincident);
    ASSERT_EQ(r.hits.size(), 2u);
    EXPECT_EQ(r.hits[0].multiplicity, 0);
    EXPECT_EQ(r.hits[1].multiplicity, 0);
    EXPECT_NEAR(double(r.hits[0].param_a), a0, 1e-6);
    EXPECT_NEAR(double(r.hits[0].param_b), b0, 1e-6);
    EXPECT_NEAR(double(r.hits[1].param_a), a1, 1e-6);
    EXPECT_NEAR(double(r.hits[1].param_b), b1, 1e-6);
  }
}

TYPED_TEST(PolycurveAlgebraic, SharedSubArcs) {
  using T = TypeParam;
  const BezierCurve2<T> c{{{T(0), T(0)}, {T(1), T(3)}, {T(2), T(-2)}, {T(3), T(1)}}};
  {
    SCOPED_TRACE("left half");
    expect_overlap(c, piece(c, T(0), T(0.5)), 0.0, 0.0, 0.5, 1.0);
  }
  const BezierCurve2<T> mid = piece(c, T(0.25), T(0.75));
  {
    SCOPED_TRACE("middle piece");
    expect_overlap(c, mid, 0.25, 0.0, 0.75, 1.0);
    expect_overlap(mid, c, 0.0, 0.25, 1.0, 0.75);
  }
  {
    SCOPED_TRACE("partially overlapping pieces");
    expect_overlap(piece(c, T(0), T(0.5)), mid, 0.5, 0.0, 1.0, 0.5);
  }
  {
    SCOPED_TRACE("reversed piece");
    BezierCurve2<T> rev = mid;
    std::reverse(rev.control.begin(), rev.control.end());
    expect_overlap(c, rev, 0.25, 1.0, 0.75, 0.0);
  }
  {
    SCOPED_TRACE("degree-elevated piece");
    BezierCurve2<T> up;
    const auto& p = mid.control;
    up.control.push_back(p[0]);
    for (std::size_t i = 1; i <= 3; ++i) {
      const T f = static_cast<T>(i) / T(4);
      up.control.push_back(f * p[i - 1] + (T(1) - f) * p[i]);
    }
    up.control.push_back(p[3]);
    expect_overlap(c, up, 0.25, 0.0, 0.75, 1.0);
  }
  {
    SCOPED_TRACE("a two-span B-spline of c against the middle piece: one stretch over the joint");
    const auto& p = c.control;
    const BSplineCurve2<T> sp{
        3,
        {p[0], T(0.5) * (p[0] + p[1]), T(0.5) * (p[1] + p[2]), T(0.5) * (p[2] + p[3]), p[3]},
        {T(0), T(0), T(0), T(0), T(0.5), T(1), T(1), T(1), T(1)}};
    expect_overlap(sp, mid, 0.25, 0.0, 0.75, 1.0);
  }
  {
    SCOPED_TRACE("touching end to end: a point, no overlap");
    const auto r = intersection(piece(c, T(0), T(0.5)), piece(c, T(0.5), T(1)));
    ASSERT_EQ(r.status, Status::ok);
    ASSERT_EQ(r.kind, Kind::point);
    EXPECT_NEAR(double(r.hits[0].param_a), 1.0, 1e-6);
    EXPECT_NEAR(double(r.hits[0].param_b), 0.0, 1e-6);
  }
}

// ---- self-intersections ------------------------------------------------------------------------

/// The double point of the cubic with integer control points: parameters s < t, or none.
bool cubic_double_point(const std::vector<Vec2<int>>& p, double& s, double& t) {
  // C(u) = a u^3 + b u^2 + c u + d; (C(s) - C(t)) / (s - t) = a (S^2 - P) + b S + c = 0 with
  // S = s + t, P = s t: S = -(a x c) / (a x b), P = S^2 + (b S + c).a / a.a.
  const auto coef = [&](int k, int w0, int w1, int w2, int w3) {
    return mpq_class(w0 * p[0][k] + w1 * p[1][k] + w2 * p[2][k] + w3 * p[3][k]);
  };
  const mpq_class ax = coef(0, -1, 3, -3, 1), ay = coef(1, -1, 3, -3, 1);
  const mpq_class bx = coef(0, 3, -6, 3, 0), by = coef(1, 3, -6, 3, 0);
  const mpq_class cx = coef(0, -3, 3, 0, 0), cy = coef(1, -3, 3, 0, 0);
  const mpq_class axb = ax * by - ay * bx, axc = ax * cy - ay * cx, aa = ax * ax + ay * ay;
  if (axb == 0 || aa == 0) return false;
  const mpq_class S = -axc / axb;
  const mpq_class P = S * S + ((bx * S + cx) * ax + (by * S + cy) * ay) / aa;
  const mpq_class disc = S * S - 4 * P;
  if (disc <= 0) return false;
  const mpf_class root = sqrt(mpf_class(disc, 256));
  s = mpf_class((mpf_class(S, 256) - root) / 2).get_d();
  t = mpf_class((mpf_class(S, 256) + root) / 2).get_d();
  return true;
}

TYPED_TEST(PolycurveAlgebraic, CubicLoopAgainstClosedForm) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 43);
  SCOPED_TRACE(rng.trace());
  int loops = 0, simple = 0;
  const double tol = std::max(1e-9, 8.0 * double(eps_v<T>));
  for (int trial = 0; trial < 60; ++trial) {
    SCOPED_TRACE(trial);
    std::vector<Vec2<int>> pi;
    for (int i = 0; i < 4; ++i) pi.push_back({rng.uniform_int(-8, 8), rng.uniform_int(-8, 8)});
    BezierCurve2<T> c;
    for (const auto& q : pi) c.control.push_back({static_cast<T>(q.x), static_cast<T>(q.y)});
    double s = 0.0, t = 0.0;
    const bool has = cubic_double_point(pi, s, t);
    const bool inside = has && s > 0.01 && t < 0.99 && t - s > 0.02;
    const bool outside = !has || s < -0.01 || t > 1.01 || t - s < 1e-3;
    if (!inside && !outside) continue;  // a double point near an end or a near cusp: skipped
    const auto r = self_intersection(c);
    ASSERT_EQ(r.status, Status::ok);
    if (outside) {
      // (t - s tiny: a near cusp, no loop of any size.)
      EXPECT_TRUE(r.hits.empty());
      ++simple;
      continue;
    }
    ++loops;
    ASSERT_EQ(r.hits.size(), 1u);
    EXPECT_EQ(r.kind, Kind::point);
    EXPECT_EQ(r.hits[0].multiplicity, 1);
    EXPECT_NEAR(double(r.hits[0].param_a), s, tol);
    EXPECT_NEAR(double(r.hits[0].param_b), t, tol);
    // The same curve as a B-spline of two spans (a knot inserted at 1/2): the same double point,
    // whether its branches fall in one span or in adjacent ones.
    const auto& p = c.control;
    const BSplineCurve2<T> sp{
        3,
        {p[0], T(0.5) * (p[0] + p[1]), T(0.5) * (p[1] + p[2]), T(0.5) * (p[2] + p[3]), p[3]},
        {T(0), T(0), T(0), T(0), T(0.5), T(1), T(1), T(1), T(1)}};
    const auto q = self_intersection(sp, with(CurveMethod::resultant));
    ASSERT_EQ(q.hits.size(), 1u);
    EXPECT_NEAR(double(q.hits[0].param_a), s, tol);
    EXPECT_NEAR(double(q.hits[0].param_b), t, tol);
  }
  EXPECT_GE(loops, 5);
  EXPECT_GE(simple, 10);
}

TYPED_TEST(PolycurveAlgebraic, SelfIntersectionSpecialCases) {
  using T = TypeParam;
  // A symmetric loop: double point at (1.5, 0.75) for s = 1/2 -+ sqrt(5) / 6... computed below.
  const BezierCurve2<T> loop{{{T(0), T(0)}, {T(4), T(3)}, {T(-1), T(3)}, {T(3), T(0)}}};
  const auto r = self_intersection(loop);
  ASSERT_EQ(r.hits.size(), 1u);
  EXPECT_LE(length(at(loop, double(r.hits[0].param_a)) - at(loop, double(r.hits[0].param_b))),
            1e-6);
  EXPECT_NEAR(double(r.hits[0].param_a) + double(r.hits[0].param_b), 1.0, 1e-6);  // symmetry
  // A closed curve (first point == last) has no double point at its closing point.
  const BezierCurve2<T> closed{{{T(0), T(0)}, {T(2), T(2)}, {T(-2), T(2)}, {T(0), T(0)}}};
  EXPECT_TRUE(self_intersection(closed).hits.empty());
  // A straight cubic that runs back over itself: a retraced stretch, coincident.
  const BezierCurve2<T> back{{{T(0), T(0)}, {T(3), T(0)}, {T(-1), T(0)}, {T(1), T(0)}}};
  const auto b = self_intersection(back);
  EXPECT_EQ(b.status, Status::ok);
  EXPECT_EQ(b.kind, Kind::coincident);
  // A single point: nothing; a segment: nothing.
  const BezierCurve2<T> dot{{{T(1), T(1)}, {T(1), T(1)}, {T(1), T(1)}}};
  EXPECT_EQ(self_intersection(dot).status, Status::ok);
  EXPECT_TRUE(self_intersection(dot).hits.empty());
  EXPECT_TRUE(self_intersection(BezierCurve2<T>{{{T(0), T(0)}, {T(1), T(2)}}}).hits.empty());
}

TYPED_TEST(PolycurveAlgebraic, SelfIntersectionOfSplines) {
  using T = TypeParam;
  // A degree-1 B-spline (a polyline): its first and third spans cross at (1, 1); the corners
  // (joints of adjacent spans) are not double points.
  const BSplineCurve2<T> z{1,
                           {{T(0), T(0)}, {T(2), T(2)}, {T(2), T(0)}, {T(0), T(2)}},
                           {T(0), T(0), T(1), T(2), T(3), T(3)}};
  for (CurveMethod m : {CurveMethod::algebraic, CurveMethod::resultant, CurveMethod::hierarchy}) {
    const auto r = self_intersection(z, with(m));
    ASSERT_EQ(r.status, Status::ok);
    ASSERT_EQ(r.hits.size(), 1u);
    EXPECT_NEAR(double(r.hits[0].param_a), 0.5, 1e-6);
    EXPECT_NEAR(double(r.hits[0].param_b), 2.5, 1e-6);
    EXPECT_EQ(r.hits[0].multiplicity, 1);
  }
  // A cusp (control polygon crossing back symmetrically): no double point, no hang.
  const BezierCurve2<T> cusp{{{T(0), T(0)}, {T(2), T(2)}, {T(-1), T(2)}, {T(1), T(0)}}};
  const auto k = self_intersection(cusp);
  EXPECT_EQ(k.status, Status::ok);
  // A rational loop (NURBS, one span): the double point lies on the curve at both parameters.
  const NurbsCurve2<T> rl{3,
                          {{T(0), T(0)}, {T(4), T(3)}, {T(-1), T(3)}, {T(3), T(0)}},
                          {T(1), T(2), T(0.5), T(1)},
                          {T(0), T(0), T(0), T(0), T(1), T(1), T(1), T(1)}};
  const auto q = self_intersection(rl);
  ASSERT_EQ(q.hits.size(), 1u);
  EXPECT_LE(length(at(rl, double(q.hits[0].param_a)) - at(rl, double(q.hits[0].param_b))), 1e-5);
}

TYPED_TEST(PolycurveAlgebraic, DegenerateAndNonFiniteInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T inf = std::numeric_limits<T>::infinity();
  const BezierCurve2<T> good{{{T(0), T(0)}, {T(1), T(3)}, {T(2), T(-2)}, {T(3), T(1)}}};
  for (T bad : {nan, inf}) {
    const BezierCurve2<T> b{{{T(0), T(0)}, {bad, T(1)}, {T(2), T(0)}}};
    EXPECT_EQ(self_intersection(b).status, Status::non_finite_input);
    EXPECT_EQ(intersection(good, b, with(CurveMethod::resultant)).status, Status::non_finite_input);
  }
  EXPECT_EQ(self_intersection(BezierCurve2<T>{}).status, Status::empty_input);
  // A point curve against a curve through it and one beside it.
  const BezierCurve2<T> on{{{T(0), T(0)}, {T(0), T(0)}}};
  const auto r = intersection(on, good, with(CurveMethod::resultant));
  EXPECT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.hits.size(), 1u);
  EXPECT_NEAR(double(r.hits[0].param_b), 0.0, 1e-6);
  const BezierCurve2<T> off{{{T(0), T(1)}, {T(0), T(1)}}};
  EXPECT_TRUE(intersection(off, good, with(CurveMethod::resultant)).hits.empty());
  // Degree 5 on both sides (above the implicit degree limit): the subdivision answers.
  BezierCurve2<T> q5{
      {{T(0), T(0)}, {T(1), T(2)}, {T(2), T(-2)}, {T(3), T(2)}, {T(4), T(-2)}, {T(5), T(0)}}};
  BezierCurve2<T> h5 = q5;
  for (auto& p : h5.control) std::swap(p.x, p.y);
  const auto sub = intersection(q5, h5);
  const auto res = intersection(q5, h5, with(CurveMethod::resultant));
  EXPECT_EQ(res.hits.size(), sub.hits.size());
  // Huge coordinates (squares overflow): solved on a power-of-two scaled copy, the same answer.
  if constexpr (std::is_same_v<T, double>) {
    BezierCurve2<T> a = q5, b = h5;
    for (auto& p : a.control) p = T(0x1p900) * p;
    for (auto& p : b.control) p = T(0x1p900) * p;
    EXPECT_EQ(intersection(a, b, with(CurveMethod::resultant)).hits.size(), sub.hits.size());
    EXPECT_EQ(intersection(a, b).hits.size(), sub.hits.size());
    a.control.resize(4);
    b.control.resize(3);
    const auto small = intersection(a, b);
    const auto big = intersection(a, b, with(CurveMethod::resultant));
    EXPECT_EQ(big.status, Status::ok);
    EXPECT_EQ(big.hits.size(), small.hits.size());
  }
}

}  // namespace
