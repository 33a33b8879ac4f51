// SPDX-License-Identifier: BSL-1.0
// Rows int2.linear-polycurve and int2.polycurve: Line2 / Ray2 / Segment2 against Bézier,
// B-spline and NURBS curves, and curve against curve, float and double, by the algebraic,
// hierarchy and raster methods. Oracles: for a linear component, the signed distance of the
// curve from the line sampled densely by the curves' own evaluators (de Casteljau / de Boor,
// independent of the engine's Bézier extraction) and its sign changes bracketed (cases where a
// sample comes near zero without a sign change, i.e. near tangencies, are skipped and counted);
// for two curves, crossings of their dense polylines at two resolutions (skipped when the two
// disagree). Lines pass through known curve points so every case has a hit. Checked: counts,
// one hit per bracket, residuals (point on both objects through both parameters), the three
// methods (and the resultant for curve pairs) agree, swapped overloads, power-of-two scaling (exact
// for the algebraic method) and exact rigid motions of exact tangencies (one hit of multiplicity
// 2), joints found once, overlaps (coincident), degenerate and non-finite input.

#include <locus/intersection/curve_curve.hpp>
#include <locus/intersection/line_curve.hpp>
#include <locus/intersection/ray_curve.hpp>
#include <locus/intersection/segment_curve.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class Polycurve : public ::testing::Test {};
TYPED_TEST_SUITE(Polycurve, locus_test::RealTypes);

constexpr CurveMethod methods[3] = {CurveMethod::algebraic, CurveMethod::hierarchy,
                                    CurveMethod::raster};
// Curve pairs also by the resultant (for a linear component it is the algebraic method).
constexpr CurveMethod curve_methods[4] = {CurveMethod::algebraic, CurveMethod::hierarchy,
                                          CurveMethod::raster, CurveMethod::resultant};

CurveHitOptions with(CurveMethod m) {
  CurveHitOptions o;
  o.method = m;
  o.raster_cells = 64;  // coarser than the default 256: the tests' time budget
  return o;
}

// ---- random curves with dyadic data (exact in float) -------------------------------------------
template <class T>
T dy(Rng& rng, int lo, int hi, int den) {
  return static_cast<T>(rng.uniform_int(lo * den, hi * den)) / static_cast<T>(den);
}
template <class T>
std::vector<Vec2<T>> control(Rng& rng, int n) {
  std::vector<Vec2<T>> p;
  for (int i = 0; i < n; ++i) p.push_back({dy<T>(rng, -4, 4, 16), dy<T>(rng, -4, 4, 16)});
  return p;
}
template <class T>
std::vector<T> knots(Rng& rng, int n, int d, bool clamped) {
  std::vector<T> k;
  T x = dy<T>(rng, -1, 1, 4);
  for (int i = 0; i < n + d + 1; ++i) {
    k.push_back(x);
    x += static_cast<T>(rng.uniform_int(1, 2)) / T(4);
  }
  if (clamped) {
    for (int i = 0; i < d; ++i) k[static_cast<std::size_t>(i)] = k[static_cast<std::size_t>(d)];
    for (int i = n + 1; i < n + d + 1; ++i)
      k[static_cast<std::size_t>(i)] = k[static_cast<std::size_t>(n)];
  }
  return k;
}
template <class T>
BezierCurve2<T> random_bezier(Rng& rng) {
  return {control<T>(rng, 4)};
}
template <class T>
BSplineCurve2<T> random_bspline(Rng& rng) {
  const int n = rng.uniform_int(4, 7);
  return {3, control<T>(rng, n), knots<T>(rng, n, 3, rng.uniform_int(0, 1) == 1)};
}
template <class T>
NurbsCurve2<T> random_nurbs(Rng& rng) {
  const int d = rng.uniform_int(2, 3);
  const int n = rng.uniform_int(d + 1, 6);
  std::vector<T> w;
  for (int i = 0; i < n; ++i) w.push_back(static_cast<T>(rng.uniform_int(2, 12)) / T(4));
  return {d, control<T>(rng, n), w, knots<T>(rng, n, d, rng.uniform_int(0, 1) == 1)};
}

template <class T>
ParamDomain<T> dom(const BezierCurve2<T>&) {
  return {T(0), T(1)};
}
template <class C>
auto dom(const C& c) {
  return domain(c);
}
template <class T>
BezierCurve2<T> scaled(BezierCurve2<T> c, T s, Vec2<T> shift = {}) {
  for (auto& p : c.control) p = s * p + shift;
  return c;
}
template <class C>
C scaled(C c, curve_scalar_t<C> s, Vec2<curve_scalar_t<C>> shift = {}) {
  for (auto& p : c.control) p = s * p + shift;
  return c;
}
template <class C>
double curve_max(const C& c) {
  double m = 0.0;
  for (const auto& p : c.control) m = std::max(m, double(max_abs(p)));
  return m;
}
/// The same curve in double (exact: the data are dyadic).
template <class T>
BezierCurve2<double> widen(const BezierCurve2<T>& c) {
  BezierCurve2<double> w;
  for (const auto& p : c.control) w.control.push_back(vec_cast<double>(p));
  return w;
}
template <class T>
BSplineCurve2<double> widen(const BSplineCurve2<T>& c) {
  BSplineCurve2<double> w{c.degree, {}, {}};
  for (const auto& p : c.control) w.control.push_back(vec_cast<double>(p));
  for (T k : c.knots) w.knots.push_back(double(k));
  return w;
}
template <class T>
NurbsCurve2<double> widen(const NurbsCurve2<T>& c) {
  NurbsCurve2<double> w{c.degree, {}, {}, {}};
  for (const auto& p : c.control) w.control.push_back(vec_cast<double>(p));
  for (T k : c.weights) w.weights.push_back(double(k));
  for (T k : c.knots) w.knots.push_back(double(k));
  return w;
}
/// The curve's point by its own evaluator (de Casteljau / de Boor) in double.
template <class C>
Vec2<double> pt(const C& c, double t) {
  if constexpr (std::is_same_v<curve_scalar_t<C>, double>)
    return point_at(c, t);
  else
    return point_at(widen(c), t);
}

// ---- the sampled oracle for a linear component -------------------------------------------------
struct Bracket {
  double t0, t1;
};
/// Sign changes of the signed distance along the curve; nullopt when ambiguous (a sample within
/// 1e-4 scale of the line at a local minimum of |distance| without a sign change, or a
/// sign change whose point lies within 1e-6 of the component's parameter range ends).
template <class C>
std::optional<std::vector<Bracket>> oracle(const C& given, Vec2<double> o, Vec2<double> d,
                                           double lo, double hi, double scale) {
  const auto c = widen(given);
  const auto dm = dom(c);
  const double a = double(dm.min), b = double(dm.max);
  constexpr int m = 1500;
  std::vector<double> t(m + 1), g(m + 1);
  for (int i = 0; i <= m; ++i) {
    t[std::size_t(i)] = a + (b - a) * i / m;
    g[std::size_t(i)] = perp_dot(d, pt(c, t[std::size_t(i)]) - o) / length(d);
  }
  std::vector<Bracket> out;
  for (std::size_t i = 0; i < std::size_t(m); ++i) {
    if (g[i] == 0.0) return std::nullopt;
    if ((g[i] < 0.0) != (g[i + 1] < 0.0)) {
      // The component's parameter at both samples: ambiguous when they straddle an end.
      const auto sp = [&](double tt) { return dot(pt(c, tt) - o, d) / dot(d, d); };
      const double s = sp(0.5 * (t[i] + t[i + 1]));
      const double s0 = std::min(sp(t[i]), sp(t[i + 1])), s1 = std::max(sp(t[i]), sp(t[i + 1]));
      const double pad = 1e-6 * std::max(1.0, std::abs(s));
      if ((s0 - pad <= lo && lo <= s1 + pad) || (s0 - pad <= hi && hi <= s1 + pad))
        return std::nullopt;
      if (s >= lo && s <= hi) out.push_back({t[i], t[i + 1]});
    } else if (i > 0 && (g[i - 1] < 0.0) == (g[i] < 0.0) && std::abs(g[i]) <= std::abs(g[i - 1]) &&
               std::abs(g[i]) <= std::abs(g[i + 1]) && std::abs(g[i]) < 1e-4 * scale) {
      return std::nullopt;  // a near tangency: not what this oracle decides
    }
  }
  for (std::size_t i = 1; i < out.size(); ++i)
    if (out[i].t0 <= out[i - 1].t1) return std::nullopt;  // two roots in adjacent samples
  return out;
}

template <class T>
Vec2<double> lin_at(const Line2<T>& l, double s) {
  return vec_cast<double>(l.origin) + s * vec_cast<double>(l.direction);
}
template <class T>
Vec2<double> lin_at(const Ray2<T>& l, double s) {
  return vec_cast<double>(l.origin) + s * vec_cast<double>(l.direction);
}
template <class T>
Vec2<double> lin_at(const Segment2<T>& l, double s) {
  return vec_cast<double>(l.p0) + s * (vec_cast<double>(l.p1) - vec_cast<double>(l.p0));
}

/// Every hit on both objects: through param_a on the component, through param_b on the curve.
template <class L, class C>
void check_on_both(const L& l, const C& c, const CurveHits2<curve_scalar_t<C>>& r, double scale,
                   double tol_rel) {
  using T = curve_scalar_t<C>;
  for (const auto& h : r.hits) {
    const Vec2<double> p = vec_cast<double>(h.point);
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
    const double bound = tol_rel * scale + 64.0 * double(eps_v<T>) * scale;
    EXPECT_LE(length(p - pt(c, double(h.param_b))), bound) << "multiplicity " << h.multiplicity;
    EXPECT_LE(length(p - lin_at(l, double(h.param_a))), bound);
  }
}

template <class L, class C>
void linear_case(const L& l, const C& c, Vec2<double> o, Vec2<double> d, double lo, double hi,
                 int& decided) {
  const double scale = std::max(curve_max(c), std::max(std::abs(o.x), std::abs(o.y)));
  const auto want = oracle(c, o, d, lo, hi, scale);
  if (!want) return;
  ++decided;
  for (CurveMethod m : methods) {
    SCOPED_TRACE(int(m));
    const auto r = intersection(l, c, with(m));
    ASSERT_EQ(r.status, Status::ok);
    // The raster merges crossings closer than about two cells: compare only when separated.
    bool separated = true;
    for (std::size_t i = 1; i < want->size(); ++i)
      separated = separated && length(pt(c, (*want)[i].t0) - pt(c, (*want)[i - 1].t1)) >
                                   8.0 * (2.0 * scale) / 64.0;
    if (m == CurveMethod::raster && !separated) continue;
    ASSERT_EQ(r.hits.size(), want->size());
    // One hit per bracket (the hits are ordered by param_a, the brackets by the curve's t).
    std::vector<double> tb;
    for (const auto& h : r.hits) {
      tb.push_back(double(h.param_b));
      EXPECT_EQ(h.multiplicity, 1);
    }
    std::sort(tb.begin(), tb.end());
    for (std::size_t i = 0; i < tb.size(); ++i) {
      const double slack = 4.0 * double(eps_v<curve_scalar_t<C>>) * (1.0 + std::abs(tb[i]));
      EXPECT_GE(tb[i], (*want)[i].t0 - slack);
      EXPECT_LE(tb[i], (*want)[i].t1 + slack);
    }
    check_on_both(l, c, r, scale, 1e-9);
    EXPECT_EQ(r.kind, r.hits.empty()       ? Kind::empty
                      : r.hits.size() == 1 ? Kind::point
                                           : Kind::points);
    // The swapped overload.
    const auto s = intersection(c, l, with(m));
    ASSERT_EQ(s.hits.size(), r.hits.size());
    EXPECT_EQ(intersects(l, c, with(m)), !r.hits.empty());
  }
}

template <class T, class C>
void random_linear(Rng& rng, const C& c, int& decided) {
  const auto dm = dom(c);
  const T t = dm.min + (dm.max - dm.min) * rng.uniform<T>(T(0.05), T(0.95));
  const Vec2<T> p = point_at(c, t);
  Vec2<T> d{dy<T>(rng, -2, 2, 8), dy<T>(rng, -2, 2, 8)};
  if (d.x == T(0) && d.y == T(0)) d = {T(1), T(0)};
  const Vec2<double> o = vec_cast<double>(p), dd = vec_cast<double>(d);
  const double inf = std::numeric_limits<double>::infinity();
  switch (rng.uniform_int(0, 2)) {
    case 0:
      linear_case(Line2<T>{p, d}, c, o, dd, -inf, inf, decided);
      break;
    case 1: {
      const Vec2<T> start = p - T(2) * d;
      linear_case(Ray2<T>{start, d}, c, vec_cast<double>(start), dd, 0.0, inf, decided);
      break;
    }
    default: {
      const Vec2<T> a = p - T(3) * d, b = p + dy<T>(rng, -2, 4, 4) * d;  // may end before p
      const Vec2<double> ad = vec_cast<double>(a);
      linear_case(Segment2<T>{a, b}, c, ad, vec_cast<double>(b) - ad, 0.0, 1.0, decided);
    }
  }
}

TYPED_TEST(Polycurve, LinearAgainstSampledOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int decided = 0, total = 0;
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE(trial);
    random_linear<T>(rng, random_bezier<T>(rng), decided);
    random_linear<T>(rng, random_bspline<T>(rng), decided);
    random_linear<T>(rng, random_nurbs<T>(rng), decided);
    total += 3;
  }
  EXPECT_GE(decided, total * 2 / 3) << "too many cases the oracle could not decide";
}

// ---- exact tangencies, rigid motions and scaling ----------------------------------------------
// y(t) = 3 (t - 1/2)^2 (t + 1): a double root at t = 1/2 on y = 0; Bernstein coefficients
// of 3 t^3 - 9/4 t + 3/4 are 3/4, 0, -3/4, 3/2 (exact dyadics).
template <class T>
BezierCurve2<T> tangent_cubic() {
  return {{{T(0), T(0.75)}, {T(1), T(0)}, {T(2), T(-0.75)}, {T(3), T(1.5)}}};
}

template <class T, class L, class C>
void expect_one_tangency(const L& l, const C& c, Vec2<double> at, double scale) {
  for (CurveMethod m : methods) {
    SCOPED_TRACE(int(m));
    const auto r = intersection(l, c, with(m));
    ASSERT_EQ(r.status, Status::ok);
    ASSERT_EQ(r.hits.size(), 1u);
    EXPECT_EQ(r.hits[0].multiplicity, 2);
    // A tangency is located to about sqrt(gap): 2^-20 of the scale with the default tolerance.
    EXPECT_LE(length(vec_cast<double>(r.hits[0].point) - at), 0x1p-18 * scale);
  }
}

TYPED_TEST(Polycurve, ExactTangencyUnderRigidMotionsAndScaling) {
  using T = TypeParam;
  const BezierCurve2<T> c = tangent_cubic<T>();
  expect_one_tangency<T>(Line2<T>{{T(-5), T(0)}, {T(1), T(0)}}, c, {1.5, 0.0}, 3.0);
  expect_one_tangency<T>(Segment2<T>{{T(-5), T(0)}, {T(7), T(0)}}, c, {1.5, 0.0}, 3.0);
  expect_one_tangency<T>(Ray2<T>{{T(7), T(0)}, {T(-2), T(0)}}, c, {1.5, 0.0}, 3.0);
  // Rotations by quarter turns, reflections and integer translations are exact on this data.
  for (int rot = 0; rot < 4; ++rot)
    for (int flip = 0; flip < 2; ++flip) {
      SCOPED_TRACE(rot * 2 + flip);
      const auto f = [&](Vec2<T> p) {
        if (flip) p.x = -p.x;
        for (int k = 0; k < rot; ++k) p = {-p.y, p.x};
        return p + Vec2<T>{T(3), T(-2)};
      };
      BezierCurve2<T> m = c;
      for (auto& p : m.control) p = f(p);
      const Vec2<T> o = f({T(-5), T(0)}), e = f({T(1), T(0)});
      const Vec2<T> at = f({T(1.5), T(0)});
      expect_one_tangency<T>(Line2<T>{o, e - o}, m, vec_cast<double>(at), 6.0);
    }
  // Power-of-two scaling: the algebraic method's answer scales exactly.
  const Line2<T> l{{T(-5), T(0.25)}, {T(1), T(0)}};
  const auto r = intersection(l, c);
  ASSERT_EQ(r.hits.size(), 2u);
  for (int e : {-6, 5}) {
    const T s = std::ldexp(T(1), e);
    const auto q = intersection(Line2<T>{s * l.origin, s * l.direction}, scaled(c, s));
    ASSERT_EQ(q.hits.size(), r.hits.size());
    for (std::size_t i = 0; i < q.hits.size(); ++i) {
      EXPECT_EQ(q.hits[i].param_b, r.hits[i].param_b);
      EXPECT_EQ(q.hits[i].param_a, r.hits[i].param_a);
      EXPECT_EQ(q.hits[i].point.x, s * r.hits[i].point.x);
      EXPECT_EQ(q.hits[i].point.y, s * r.hits[i].point.y);
    }
  }
}

// A tangency exactly at a joint of a B-spline and a crossing at a joint: each reported once.
TYPED_TEST(Polycurve, JointsAndOverlaps) {
  using T = TypeParam;
  // Quadratic clamped B-spline: the joint at knot 1/2 is the midpoint of P1 and P2 = (1, 1).
  const BSplineCurve2<T> b{2,
                           {{T(0), T(0)}, {T(0.5), T(1)}, {T(1.5), T(1)}, {T(2), T(0)}},
                           {T(0), T(0), T(0), T(0.5), T(1), T(1), T(1)}};
  for (CurveMethod m : methods) {
    SCOPED_TRACE(int(m));
    const auto top = intersection(Line2<T>{{T(0), T(1)}, {T(1), T(0)}}, b, with(m));
    ASSERT_EQ(top.hits.size(), 1u);  // y = 1 touches the arch at its joint
    EXPECT_EQ(top.hits[0].multiplicity, 2);
    EXPECT_NEAR(double(top.hits[0].param_b), 0.5, 1e-6);
    const auto vert = intersection(Line2<T>{{T(1), T(-3)}, {T(0), T(1)}}, b, with(m));
    ASSERT_EQ(vert.hits.size(), 1u);  // x = 1 crosses at the joint
    EXPECT_EQ(vert.hits[0].multiplicity, 1);
    EXPECT_NEAR(double(vert.hits[0].param_b), 0.5, 1e-6);
    EXPECT_NEAR(double(vert.hits[0].param_a), 4.0, 1e-6);
  }
  // A straight piece on the line: coincident, with the overlap's ends.
  const BezierCurve2<T> flat{{{T(0), T(1)}, {T(1), T(1)}, {T(3), T(1)}}};
  const auto ov = intersection(Line2<T>{{T(0), T(1)}, {T(2), T(0)}}, flat);
  EXPECT_EQ(ov.kind, Kind::coincident);
  ASSERT_EQ(ov.hits.size(), 2u);
  EXPECT_EQ(ov.hits[0].multiplicity, 0);
  EXPECT_EQ(ov.hits[1].point.x, T(3));
}

TYPED_TEST(Polycurve, DegenerateAndNonFiniteInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const BezierCurve2<T> c = tangent_cubic<T>();
  const Line2<T> far{{T(0), T(100)}, {T(1), T(0)}};
  for (CurveMethod m : methods) {
    SCOPED_TRACE(int(m));
    EXPECT_TRUE(intersection(far, c, with(m)).hits.empty());
    EXPECT_EQ(intersection(far, c, with(m)).status, Status::ok);
    EXPECT_FALSE(intersects(Segment2<T>{{T(0), T(-1)}, {T(0), T(-2)}}, c, with(m)));
  }
  // A curve of coincident control points: off the line no hit; on it the whole (point) piece.
  const BezierCurve2<T> dot{{{T(1), T(2)}, {T(1), T(2)}, {T(1), T(2)}}};
  EXPECT_TRUE(intersection(Line2<T>{{T(0), T(0)}, {T(1), T(0)}}, dot).hits.empty());
  const auto on = intersection(Line2<T>{{T(0), T(2)}, {T(1), T(0)}}, dot);
  EXPECT_EQ(on.kind, Kind::coincident);
  for (const auto& h : on.hits) EXPECT_EQ(h.point, (Vec2<T>{T(1), T(2)}));
  // Non-finite anywhere: no hits, the status says why.
  BezierCurve2<T> bad = c;
  bad.control[2].y = nan;
  for (CurveMethod m : methods) {
    const auto r = intersection(Line2<T>{{T(0), T(0)}, {T(1), T(0)}}, bad, with(m));
    EXPECT_EQ(r.status, Status::non_finite_input);
    EXPECT_TRUE(r.hits.empty());
    const auto q = intersection(Line2<T>{{nan, T(0)}, {T(1), T(0)}}, c, with(m));
    EXPECT_EQ(q.status, Status::non_finite_input);
    EXPECT_TRUE(q.hits.empty());
    EXPECT_TRUE(intersection(c, bad, with(m)).hits.empty());
  }
  EXPECT_EQ(intersection(Line2<T>{{T(0), T(0)}, {T(0), T(0)}}, c).status, Status::degenerate_input);
  EXPECT_EQ(intersection(Line2<T>{{T(0), T(0)}, {T(1), T(0)}}, BezierCurve2<T>{}).status,
            Status::empty_input);
  BSplineCurve2<T> wrong{3, {{T(0), T(0)}, {T(1), T(1)}}, {T(0), T(1)}};
  EXPECT_EQ(intersection(Line2<T>{{T(0), T(0)}, {T(1), T(0)}}, wrong).status,
            Status::invalid_input);
  NurbsCurve2<T> zero_weight{2,
                             {{T(0), T(0)}, {T(1), T(1)}, {T(2), T(0)}},
                             {T(1), T(0), T(1)},
                             {T(0), T(0), T(0), T(1), T(1), T(1)}};
  EXPECT_EQ(intersection(Line2<T>{{T(0), T(0)}, {T(1), T(0)}}, zero_weight).status,
            Status::invalid_input);
}

// ---- curve against curve ----------------------------------------------------------------------
bool segments_cross(Vec2<double> a, Vec2<double> b, Vec2<double> c, Vec2<double> d) {
  const double o1 = perp_dot(b - a, c - a), o2 = perp_dot(b - a, d - a);
  const double o3 = perp_dot(d - c, a - c), o4 = perp_dot(d - c, b - c);
  return ((o1 < 0.0) != (o2 < 0.0)) && ((o3 < 0.0) != (o4 < 0.0));
}
template <class C>
std::vector<Vec2<double>> polyline(const C& given, int m) {
  const auto c = widen(given);
  const auto dm = dom(c);
  std::vector<Vec2<double>> p;
  for (int i = 0; i <= m; ++i) p.push_back(pt(c, double(dm.min) + double(dm.max - dm.min) * i / m));
  return p;
}
std::vector<Vec2<double>> polyline_crossings(const std::vector<Vec2<double>>& a,
                                             const std::vector<Vec2<double>>& b) {
  std::vector<Vec2<double>> out;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    const double x0 = std::min(a[i].x, a[i + 1].x), x1 = std::max(a[i].x, a[i + 1].x);
    const double y0 = std::min(a[i].y, a[i + 1].y), y1 = std::max(a[i].y, a[i + 1].y);
    for (std::size_t j = 0; j + 1 < b.size(); ++j) {
      if (std::max(b[j].x, b[j + 1].x) < x0 || std::min(b[j].x, b[j + 1].x) > x1 ||
          std::max(b[j].y, b[j + 1].y) < y0 || std::min(b[j].y, b[j + 1].y) > y1)
        continue;
      if (segments_cross(a[i], a[i + 1], b[j], b[j + 1])) {
        const Vec2<double> u = a[i + 1] - a[i], v = b[j + 1] - b[j];
        out.push_back(a[i] + (perp_dot(b[j] - a[i], v) / perp_dot(u, v)) * u);
      }
    }
  }
  return out;
}

template <class A, class B>
void curve_case(const A& a, const B& b, int& decided) {
  using T = curve_scalar_t<A>;
  const auto coarse = polyline_crossings(polyline(a, 100), polyline(b, 100));
  const auto fine = polyline_crossings(polyline(a, 300), polyline(b, 300));
  if (coarse.size() != fine.size()) return;  // a near tangency or close crossings
  const double scale = std::max(curve_max(a), curve_max(b));
  for (std::size_t i = 0; i < fine.size(); ++i)
    for (std::size_t j = i + 1; j < fine.size(); ++j)
      if (length(fine[i] - fine[j]) < 0.1 * scale) return;  // let the raster resolve them too
  ++decided;
  for (CurveMethod m : curve_methods) {
    SCOPED_TRACE(int(m));
    const auto r = intersection(a, b, with(m));
    ASSERT_EQ(r.status, Status::ok);
    ASSERT_EQ(r.hits.size(), fine.size());
    for (std::size_t i = 0; i < r.hits.size(); ++i) {
      const auto& h = r.hits[i];
      const Vec2<double> p = vec_cast<double>(h.point);
      const double bound = 64.0 * double(eps_v<T>) * scale + 1e-9 * scale;
      EXPECT_LE(length(p - pt(a, double(h.param_a))), bound);
      EXPECT_LE(length(p - pt(b, double(h.param_b))), bound);
      EXPECT_EQ(h.multiplicity, 1);
      if (i > 0) {
        EXPECT_LE(r.hits[i - 1].param_a, h.param_a);
      }
      // Near a polyline crossing (the polylines are within their sagitta of the curves).
      double near = std::numeric_limits<double>::infinity();
      for (const auto& q : fine) near = std::min(near, length(q - p));
      EXPECT_LE(near, 0.05 * scale);
    }
    // Swap symmetry: the same points, parameters exchanged.
    const auto s = intersection(b, a, with(m));
    ASSERT_EQ(s.hits.size(), r.hits.size());
    for (const auto& h : s.hits) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& g : r.hits) {
        if (std::abs(double(g.param_a - h.param_b)) < 1e-6 * (1.0 + std::abs(double(g.param_a))))
          best = std::min(best, length(vec_cast<double>(g.point - h.point)));
      }
      EXPECT_LE(best, 1e-6 * scale);
    }
  }
}

TYPED_TEST(Polycurve, CurveCurveAgainstPolylineOracle) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 7);
  SCOPED_TRACE(rng.trace());
  int decided = 0, total = 0;
  for (int trial = 0; trial < 5; ++trial) {
    SCOPED_TRACE(trial);
    curve_case(random_bezier<T>(rng), random_bezier<T>(rng), decided);
    curve_case(random_bezier<T>(rng), random_bspline<T>(rng), decided);
    curve_case(random_nurbs<T>(rng), random_bspline<T>(rng), decided);
    total += 3;
  }
  EXPECT_GE(decided, total / 2) << "too many cases the oracle could not decide";
}

TYPED_TEST(Polycurve, CurveCurveTangencyCoincidenceAndScaling) {
  using T = TypeParam;
  // y = (1 - 2t)^2 and its mirror image touch at (1, 0) only.
  const BezierCurve2<T> up{{{T(0), T(1)}, {T(1), T(-1)}, {T(2), T(1)}}};
  const BezierCurve2<T> down{{{T(0), T(-1)}, {T(1), T(1)}, {T(2), T(-1)}}};
  for (CurveMethod m : curve_methods) {
    SCOPED_TRACE(int(m));
    const auto r = intersection(up, down, with(m));
    ASSERT_EQ(r.hits.size(), 1u);
    EXPECT_EQ(r.hits[0].multiplicity, 2);
    EXPECT_LE(length(vec_cast<double>(r.hits[0].point) - Vec2<double>{1.0, 0.0}), 0x1p-18 * 2.0);
    // Shifted apart by 2^-10: a near miss, no hit.
    EXPECT_TRUE(
        intersection(up, scaled(down, T(1), Vec2<T>{T(0), T(-0x1p-10)}), with(m)).hits.empty());
  }
  // The same curve, given again or reversed (and as a NURBS of weight 1): coincident.
  BezierCurve2<T> rev = up;
  std::reverse(rev.control.begin(), rev.control.end());
  for (const auto& other : {up, rev}) {
    const auto r = intersection(up, other);
    EXPECT_EQ(r.kind, Kind::coincident);
    ASSERT_EQ(r.hits.size(), 2u);
    EXPECT_EQ(r.hits[0].multiplicity, 0);
  }
  // Power-of-two scaling of a crossing pair: parameters unchanged, points scaled.
  const BezierCurve2<T> s1{{{T(0), T(0)}, {T(1), T(3)}, {T(2), T(-2)}, {T(3), T(1)}}};
  const auto base = intersection(up, s1);
  ASSERT_EQ(base.hits.size(), 2u);
  for (int e : {-7, 9}) {
    const T s = std::ldexp(T(1), e);
    const auto q = intersection(scaled(up, s), scaled(s1, s));
    ASSERT_EQ(q.hits.size(), base.hits.size());
    for (std::size_t i = 0; i < q.hits.size(); ++i) {
      EXPECT_EQ(q.hits[i].param_a, base.hits[i].param_a);
      EXPECT_EQ(q.hits[i].point.x, s * base.hits[i].point.x);
    }
  }
  // The raster grid: both bits set somewhere, the grid covers both curves.
  const auto g = curve_raster(up, s1, 64);
  ASSERT_EQ(g.status, Status::ok);
  EXPECT_EQ(std::max(g.nx, g.ny), 64);
  EXPECT_TRUE(std::count(g.mask.begin(), g.mask.end(), std::uint8_t{3}) > 0);
  EXPECT_EQ(curve_raster(up, s1, 0).status, Status::invalid_input);
}

}  // namespace
