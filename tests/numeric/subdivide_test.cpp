// SPDX-License-Identifier: BSL-1.0
// Tests for numeric/subdivide.hpp (row num.subdivide): arc lengths against closed forms
// (circle, helix, line, parabola) for non-uniform parametrisations, arc-length subdivision
// checked point by point with the closed-form s(t), midpoint and variation subdivision checked
// piece by piece by dense sampling (an independent evaluation of the criterion) and against
// the closed-form depth for uniform circle arcs, budgets and bad input.
#include <locus/numeric/subdivide.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>

using namespace locus;
using locus_test::Rng;

template <class T>
class SubdivideTest : public ::testing::Test {};
TYPED_TEST_SUITE(SubdivideTest, locus_test::RealTypes);

namespace {

template <class T>
T nan_v() {
  return std::numeric_limits<T>::quiet_NaN();
}

// Closed-form arc length s(t) from 0 of the test curves, evaluated in double.
struct CircleSq {  // r (cos t^2, sin t^2): speed 2 r |t|, s = r t |t| (monotone)
  double r;
  template <class T>
  Vec2<T> operator()(T t) const {
    const double u = double(t) * double(t);
    return {T(r * std::cos(u)), T(r * std::sin(u))};
  }
  template <class T>
  Vec2<T> d(T t) const {
    const double u = double(t) * double(t);
    return {T(-2 * r * double(t) * std::sin(u)), T(2 * r * double(t) * std::cos(u))};
  }
  double s(double t) const { return r * t * std::abs(t); }
  double speed(double t) const { return 2 * r * std::abs(t); }
};

struct HelixSq {  // (r cos t^2, r sin t^2, h t^2): s = sqrt(r^2 + h^2) t |t|
  double r, h;
  template <class T>
  Vec3<T> operator()(T t) const {
    const double u = double(t) * double(t);
    return {T(r * std::cos(u)), T(r * std::sin(u)), T(h * u)};
  }
  template <class T>
  Vec3<T> d(T t) const {
    const double u = double(t) * double(t), w = 2 * double(t);
    return {T(-r * w * std::sin(u)), T(r * w * std::cos(u)), T(h * w)};
  }
  double s(double t) const { return std::sqrt(r * r + h * h) * t * std::abs(t); }
  double speed(double t) const { return 2 * std::sqrt(r * r + h * h) * std::abs(t); }
};

struct Parabola {  // (t, a t^2): s = [t q + asinh(2 a t) / (2 a)] / 2, q = sqrt(1 + 4 a^2 t^2)
  double a;
  template <class T>
  Vec2<T> operator()(T t) const {
    return {t, T(a * double(t) * double(t))};
  }
  template <class T>
  Vec2<T> d(T t) const {
    return {T(1), T(2 * a * double(t))};
  }
  double s(double t) const {
    const double q = std::sqrt(1 + 4 * a * a * t * t);
    return (t * q + std::asinh(2 * a * t) / (2 * a)) / 2;
  }
  double speed(double t) const { return std::sqrt(1 + 4 * a * a * t * t); }
};

struct LineCube {  // p + d t^3: s = |d| t^3 (signed)
  Vec3d p, dir;
  template <class T>
  Vec3<T> operator()(T t) const {
    const double c = double(t) * double(t) * double(t);
    return vec_cast<T>(p + dir * c);
  }
  template <class T>
  Vec3<T> d(T t) const {
    return vec_cast<T>(dir * (3 * double(t) * double(t)));
  }
  double s(double t) const { return length(dir) * t * t * t; }
  double speed(double t) const { return 3 * length(dir) * t * t; }
};

// Arc-length spacing check: |s(t_i) - s(t0) - i L / (n - 1)| within
//   4 * relative_tolerance * L      (quadrature and inversion error, with the estimator's slack)
// + 4 eps_T (|t_i| speed(t_i) + L)  (parameters rounded to T; oracle rounding)
// or, without a derivative, 64 eps_T^(2/3) L (finite-difference derivative; header comment).
template <class T, int N, class Curve>
void check_spacing(const Curve& cv, const CurveSamples<T, N>& r, double t0, double t1, int n,
                   bool exact_derivative) {
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(static_cast<int>(r.params.size()), n);
  ASSERT_EQ(static_cast<int>(r.points.size()), n);
  EXPECT_EQ(r.params.front(), T(t0));
  EXPECT_EQ(r.params.back(), T(t1));
  const double L = std::abs(cv.s(double(T(t1))) - cv.s(double(T(t0))));
  const double e = double(eps_v<T>);
  for (int i = 0; i < n; ++i) {
    const double t = double(r.params[static_cast<std::size_t>(i)]);
    const double got = std::abs(cv.s(t) - cv.s(double(T(t0))));
    const double want = L * i / (n - 1);
    const double bound = exact_derivative
                             ? 4 * 64 * e * L + 4 * e * (std::abs(t) * cv.speed(t) + L)
                             : 64 * std::cbrt(e * e) * L + 4 * e * (std::abs(t) * cv.speed(t) + L);
    EXPECT_NEAR(got, want, bound) << "i = " << i << " of " << n;
    if (i > 0) {
      // monotone in the direction t0 -> t1
      const double prev = double(r.params[static_cast<std::size_t>(i - 1)]);
      EXPECT_TRUE(t1 > t0 ? t >= prev : t <= prev);
    }
    EXPECT_TRUE(locus_test::vec_near(r.points[static_cast<std::size_t>(i)],
                                     cv(r.params[static_cast<std::size_t>(i)]), T(0)));
  }
}

// Maximum distance from c(t), t in [a, b] densely sampled, to the segment c(a) c(b).
template <class T, int N, class F>
double dense_chord_distance(const F& c, T a, T b, int samples = 200) {
  const Vec<double, N> pa = vec_cast<double>(c(a)), pb = vec_cast<double>(c(b));
  const Vec<double, N> d = pb - pa;
  const double dd = dot(d, d);
  double worst = 0;
  for (int k = 0; k <= samples; ++k) {
    const T t = T(double(a) + (double(b) - double(a)) * k / samples);
    const Vec<double, N> p = vec_cast<double>(c(t));
    const double u = dd > 0 ? std::clamp(dot(p - pa, d) / dd, 0.0, 1.0) : 0.0;
    worst = std::max(worst, length(p - (pa + d * u)));
  }
  return worst;
}

// RMS distance between c and its chord over [a, b] (chord linear in t), composite Simpson.
template <class T, int N, class F>
double dense_rms(const F& c, T a, T b, int samples = 400) {
  const Vec<double, N> pa = vec_cast<double>(c(a)), pb = vec_cast<double>(c(b));
  double sum = 0;
  for (int k = 0; k <= samples; ++k) {
    const double u = double(k) / samples;
    const T t = T(double(a) + (double(b) - double(a)) * u);
    const double uu =
        double(b) != double(a) ? (double(t) - double(a)) / (double(b) - double(a)) : 0;
    const double d2 = sqr_length(vec_cast<double>(c(t)) - (pa + (pb - pa) * uu));
    sum += d2 * ((k == 0 || k == samples) ? 1 : (k % 2 ? 4 : 2));
  }
  return std::sqrt(sum / (3.0 * samples));
}

}  // namespace

// ---- uniform -------------------------------------------------------------------------------

TYPED_TEST(SubdivideTest, UniformSpacingAndEnds) {
  using T = TypeParam;
  const CircleSq cv{2.0};
  for (const auto& [t0, t1] : {std::pair<T, T>{T(0), T(3)}, std::pair<T, T>{T(3), T(-1)}}) {
    const auto r = subdivide_uniform(cv, t0, t1, 7);
    ASSERT_EQ(r.status, Status::ok);
    ASSERT_EQ(r.params.size(), 7u);
    EXPECT_EQ(r.params.front(), t0);
    EXPECT_EQ(r.params.back(), t1);
    for (int i = 0; i < 7; ++i) {
      EXPECT_NEAR(double(r.params[static_cast<std::size_t>(i)]),
                  double(t0) + (double(t1) - double(t0)) * i / 6, 4 * double(eps_v<T>) * 3);
      EXPECT_TRUE(r.points[static_cast<std::size_t>(i)] ==
                  cv(r.params[static_cast<std::size_t>(i)]));
    }
  }
}

TYPED_TEST(SubdivideTest, UniformBadInput) {
  using T = TypeParam;
  const CircleSq cv{1.0};
  EXPECT_EQ(subdivide_uniform(cv, T(0), T(1), 1).status, Status::invalid_input);
  EXPECT_EQ(subdivide_uniform(cv, T(0), T(1), 0).status, Status::invalid_input);
  EXPECT_EQ(subdivide_uniform(cv, T(0), T(1), -3).status, Status::invalid_input);
  EXPECT_EQ(subdivide_uniform(cv, nan_v<T>(), T(1), 4).status, Status::non_finite_input);
  EXPECT_EQ(subdivide_uniform(cv, T(0), std::numeric_limits<T>::infinity(), 4).status,
            Status::non_finite_input);
  const auto bad = [](T t) { return Vec2<T>{t, t > T(0.5) ? nan_v<T>() : T(0)}; };
  const auto r = subdivide_uniform(bad, T(0), T(1), 5);
  EXPECT_EQ(r.status, Status::non_finite_input);
  EXPECT_TRUE(r.params.empty() && r.points.empty());
  // t0 == t1 is a valid (constant) sampling.
  const auto z = subdivide_uniform(cv, T(1), T(1), 3);
  EXPECT_EQ(z.status, Status::ok);
  for (T t : z.params) EXPECT_EQ(t, T(1));
}

// ---- arc length ------------------------------------------------------------------------------

TYPED_TEST(SubdivideTest, ArcLengthClosedForms) {
  using T = TypeParam;
  const double e = double(eps_v<T>);
  const CircleSq c{1.5};
  const HelixSq h{2.0, 0.5};
  const Parabola p{0.75};
  const LineCube l{{1, 2, 3}, {0.5, -1, 2}};
  struct Case {
    double t0, t1, want;
    ArcLength<T> got, fd;
  };
  const auto run = [](const auto& cv, double t0, double t1) {
    const auto dcv = [&](T t) { return cv.d(t); };
    return Case{t0, t1, std::abs(cv.s(double(T(t1))) - cv.s(double(T(t0)))),
                arc_length(cv, dcv, T(t0), T(t1)), arc_length(cv, T(t0), T(t1))};
  };
  for (const Case& k : {run(c, 0.0, 2.5), run(c, 2.5, 0.25), run(h, -1.0, 2.0), run(p, -2.0, 3.0),
                        run(l, -1.5, 1.25)}) {
    SCOPED_TRACE(testing::Message() << "[" << k.t0 << ", " << k.t1 << "]");
    EXPECT_EQ(k.got.status, Status::ok);
    EXPECT_NEAR(double(k.got.length), k.want, 4 * 64 * e * k.want + 16 * e * k.want);
    EXPECT_EQ(k.fd.status, Status::ok);
    EXPECT_NEAR(double(k.fd.length), k.want, 64 * std::cbrt(e * e) * k.want);
    EXPECT_GT(k.got.evaluations, 0);
  }
}

TYPED_TEST(SubdivideTest, ArcLengthSubdivisionClosedForms) {
  using T = TypeParam;
  const CircleSq c{1.5};
  const HelixSq h{2.0, 0.5};
  const Parabola p{0.75};
  const LineCube l{{1, 2, 3}, {0.5, -1, 2}};
  const auto both = [](const auto& cv, double t0, double t1, int n) {
    SCOPED_TRACE(testing::Message() << "[" << t0 << ", " << t1 << "] n = " << n);
    const auto dcv = [&](T t) { return cv.d(t); };
    check_spacing(cv, subdivide_arc_length(cv, dcv, T(t0), T(t1), n), t0, t1, n, true);
    check_spacing(cv, subdivide_arc_length(cv, T(t0), T(t1), n), t0, t1, n, false);
  };
  both(c, 0.0, 2.5, 9);    // circle, speed 0 at t = 0
  both(c, 2.5, 0.5, 6);    // reversed interval
  both(h, 0.25, 2.0, 17);  // helix
  both(p, -2.0, 3.0, 12);  // parabola: the closed-form asinh length
  both(l, -1.0, 1.5, 5);   // straight line, speed 0 inside the interval
  both(p, 0.0, 1.0, 2);    // just the ends
}

TYPED_TEST(SubdivideTest, ArcLengthSubdivisionRandom) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 20; ++k) {
    const Parabola p{rng.uniform(0.1, 3.0)};
    const HelixSq h{rng.uniform(0.2, 5.0), rng.uniform(-2.0, 2.0)};
    // t > 0: the helix's speed 2 K |t| has a kink at 0 (see the header's caveat).
    const double t0 = rng.uniform(0.05, 1.0), t1 = t0 + rng.uniform(0.5, 2.5);
    const int n = rng.uniform_int(2, 40);
    SCOPED_TRACE(testing::Message() << "a = " << p.a << " r = " << h.r << " h = " << h.h << " ["
                                    << t0 << ", " << t1 << "] n = " << n);
    const auto dp = [&](T t) { return p.d(t); };
    const auto dh = [&](T t) { return h.d(t); };
    check_spacing(p, subdivide_arc_length(p, dp, T(t0), T(t1), n), t0, t1, n, true);
    check_spacing(h, subdivide_arc_length(h, dh, T(t1), T(t0), n), t1, t0, n, true);
  }
}

TYPED_TEST(SubdivideTest, ArcLengthDegenerateAndBad) {
  using T = TypeParam;
  const auto constant = [](T) { return Vec2<T>{T(1), T(2)}; };
  const auto zero = [](T) { return Vec2<T>{}; };
  // Zero length: uniform parameters, degenerate_input.
  const auto r = subdivide_arc_length(constant, zero, T(0), T(2), 5);
  EXPECT_EQ(r.status, Status::degenerate_input);
  ASSERT_EQ(r.params.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(r.params[static_cast<std::size_t>(i)], T(i) / T(2));
  EXPECT_EQ(subdivide_arc_length(constant, T(0), T(2), 4).status, Status::degenerate_input);
  const CircleSq c{1.0};
  const auto dc = [&](T t) { return c.d(t); };
  EXPECT_EQ(subdivide_arc_length(c, dc, T(1), T(1), 4).status, Status::degenerate_input);
  EXPECT_EQ(arc_length(c, dc, T(1), T(1)).length, T(0));
  EXPECT_EQ(arc_length(constant, zero, T(0), T(1)).length, T(0));
  // Counts and parameters.
  EXPECT_EQ(subdivide_arc_length(c, dc, T(0), T(1), 1).status, Status::invalid_input);
  EXPECT_EQ(subdivide_arc_length(c, dc, T(0), T(1), 0).status, Status::invalid_input);
  EXPECT_EQ(subdivide_arc_length(c, dc, nan_v<T>(), T(1), 4).status, Status::non_finite_input);
  EXPECT_EQ(subdivide_arc_length(c, T(0), nan_v<T>(), 4).status, Status::non_finite_input);
  EXPECT_EQ(arc_length(c, dc, T(0), nan_v<T>()).status, Status::non_finite_input);
  EXPECT_TRUE(std::isnan(arc_length(c, dc, T(0), nan_v<T>()).length));
  // A derivative that is NaN somewhere.
  const auto bad = [](T t) { return Vec2<T>{T(1), t > T(0.3) ? nan_v<T>() : T(0)}; };
  const auto b = subdivide_arc_length(c, bad, T(0), T(1), 4);
  EXPECT_EQ(b.status, Status::non_finite_input);
  EXPECT_TRUE(b.params.empty());
  EXPECT_EQ(arc_length(c, bad, T(0), T(1)).status, Status::non_finite_input);
  // Budgets: a tiny evaluation budget reports limit_exceeded with a usable estimate.
  // (A steep parabola: its speed is far from polynomial, so 200 evaluations cannot reach the
  // round-off level.)
  const Parabola steep{50.0};
  const auto dsteep = [&](T t) { return steep.d(t); };
  const double want = steep.s(3.0) - steep.s(-3.0);
  ArcLengthOptions<T> opt;
  opt.relative_tolerance = T(0);
  opt.max_evaluations = 200;
  const auto lim = arc_length(steep, dsteep, T(-3), T(3), opt);
  EXPECT_EQ(lim.status, Status::limit_exceeded);
  EXPECT_NEAR(double(lim.length), want, 1e-3 * want);
  EXPECT_LT(lim.evaluations, 200 + 20);
  opt.max_evaluations = 1 << 20;
  opt.max_depth = 0;
  const auto shallow = arc_length(steep, dsteep, T(-3), T(3), opt);
  EXPECT_EQ(shallow.status, Status::limit_exceeded);
  EXPECT_NEAR(double(shallow.length), want, 1e-2 * want);
  opt.relative_tolerance = nan_v<T>();
  EXPECT_EQ(arc_length(c, dc, T(0), T(3), opt).status, Status::invalid_input);
}

// ---- midpoint distance -------------------------------------------------------------------------

// A uniform-speed circle arc of angle theta: every piece at depth d has angle theta / 2^d and
// midpoint distance (= largest chord distance) r (1 - cos(theta / 2^(d+1))), so the result is
// 2^d pieces for the smallest such d within tolerance.
TYPED_TEST(SubdivideTest, MidpointCircleClosedFormDepth) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int tested = 0;
  for (int k = 0; k < 40; ++k) {
    const double r = rng.uniform(0.5, 4.0), theta = rng.uniform(0.5, 6.0);
    const double tol = r * std::pow(10.0, rng.uniform(-4.0, -1.0));
    int d = 0;
    while (r * (1 - std::cos(theta / std::pow(2.0, d + 1))) > tol) ++d;
    // Skip cases within rounding of a threshold (the decision there is legitimately either).
    const double sag = r * (1 - std::cos(theta / std::pow(2.0, d + 1)));
    const double prev = r * (1 - std::cos(theta / std::pow(2.0, d)));
    if (sag > tol * (1 - 1e-3) || (d > 0 && prev < tol * (1 + 1e-3))) continue;
    ++tested;
    const auto c = [&](T t) {
      return Vec2<T>{T(r * std::cos(double(t))), T(r * std::sin(double(t)))};
    };
    const auto res = subdivide_midpoint(c, T(0), T(theta), T(tol));
    ASSERT_EQ(res.status, Status::ok);
    EXPECT_EQ(res.params.size(), (std::size_t(1) << d) + 1) << "depth " << d;
    for (std::size_t i = 0; i + 1 < res.params.size(); ++i)
      EXPECT_LE((dense_chord_distance<T, 2>)(c, res.params[i], res.params[i + 1]),
                tol + 16 * double(eps_v<T>) * r);
  }
  EXPECT_GT(tested, 20);
}

// Parabola: the curve's largest distance from a chord is at the parameter midpoint and is at
// most the midpoint distance, so every final chord is within tol of its piece everywhere.
TYPED_TEST(SubdivideTest, MidpointEveryChordWithinTolerance) {
  using T = TypeParam;
  const Parabola p{1.5};
  const HelixSq h{1.0, 0.3};
  for (double tol : {1e-1, 1e-2, 1e-3}) {
    const auto r = subdivide_midpoint(p, T(-2), T(1.5), T(tol));
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_GT(r.params.size(), 2u);
    for (std::size_t i = 0; i + 1 < r.params.size(); ++i) {
      EXPECT_LE((dense_chord_distance<T, 2>)(p, r.params[i], r.params[i + 1]),
                tol + 64 * double(eps_v<T>) * 4);
      EXPECT_LT(r.params[i], r.params[i + 1]);
    }
    const auto rh = subdivide_midpoint(h, T(2), T(0), T(tol));  // reversed
    ASSERT_EQ(rh.status, Status::ok);
    for (std::size_t i = 0; i + 1 < rh.params.size(); ++i) {
      EXPECT_GT(rh.params[i], rh.params[i + 1]);
      const T tm = T((double(rh.params[i]) + double(rh.params[i + 1])) / 2);
      const double md =
          length(vec_cast<double>(h(tm)) -
                 (vec_cast<double>(rh.points[i]) + vec_cast<double>(rh.points[i + 1])) / 2.0);
      EXPECT_LE(md, tol + 16 * double(eps_v<T>) * 4);
    }
  }
}

TYPED_TEST(SubdivideTest, MidpointLineSineAndMinDepth) {
  using T = TypeParam;
  const LineCube l{{0, 0, 0}, {1, 2, 2}};
  const auto rl = subdivide_midpoint(l, T(0), T(1), T(0));
  // t^3 along a line: the curve midpoint is on the chord line but not at its middle.
  EXPECT_GT(rl.params.size(), 2u);
  const auto straight = [](T t) { return Vec2<T>{T(2) * t, T(1) - t}; };
  const auto rs = subdivide_midpoint(straight, T(0), T(1), T(1e-6));
  EXPECT_EQ(rs.status, Status::ok);
  EXPECT_EQ(rs.params.size(), 2u);
  // One period of a sine fools the midpoint test (as documented); min_depth fixes it.
  const auto sine = [](T t) { return Vec2<T>{t, T(std::sin(2 * pi_v<double> * double(t)))}; };
  EXPECT_EQ(subdivide_midpoint(sine, T(0), T(1), T(1e-2)).params.size(), 2u);
  SubdivisionOptions o;
  o.min_depth = 2;
  const auto rm = subdivide_midpoint(sine, T(0), T(1), T(1e-2), o);
  EXPECT_EQ(rm.status, Status::ok);
  EXPECT_GT(rm.params.size(), 10u);
  for (std::size_t i = 0; i + 1 < rm.params.size(); ++i)
    EXPECT_LE((dense_chord_distance<T, 2>)(sine, rm.params[i], rm.params[i + 1]), 1.5e-2);
}

TYPED_TEST(SubdivideTest, MidpointAndVariationBudgetsAndBadInput) {
  using T = TypeParam;
  const auto c = [](T t) { return Vec2<T>{std::cos(t), std::sin(t)}; };
  // A zero tolerance refines until the depth budget.
  SubdivisionOptions o;
  o.max_depth = 5;
  auto r = subdivide_midpoint(c, T(0), T(1), T(0), o);
  EXPECT_EQ(r.status, Status::limit_exceeded);
  EXPECT_EQ(r.params.size(), 33u);
  r = subdivide_variation(c, T(0), T(1), T(0), o);
  EXPECT_EQ(r.status, Status::limit_exceeded);
  EXPECT_EQ(r.params.size(), 33u);
  // Point budget.
  o.max_depth = 24;
  o.max_points = 7;
  r = subdivide_midpoint(c, T(0), T(1), T(0), o);
  EXPECT_EQ(r.status, Status::limit_exceeded);
  EXPECT_EQ(r.params.size(), 7u);
  EXPECT_EQ(r.params.back(), T(1));
  // Parameter resolution: a tiny interval cannot be halved forever.
  o.max_points = 1 << 16;
  o.max_depth = 200;
  const T one_up = std::nextafter(T(1), T(2));
  const auto step = [&](T t) { return Vec2<T>{t, t < one_up ? T(0) : T(1)}; };
  r = subdivide_midpoint(step, T(1), std::nextafter(one_up, T(2)), T(0), o);
  EXPECT_EQ(r.status, Status::limit_exceeded);
  EXPECT_EQ(r.params.size(), 3u);
  // Zero-length curves: nothing to refine.
  const auto constant = [](T) { return Vec3<T>{T(1), T(2), T(3)}; };
  for (const auto& res : {subdivide_midpoint(constant, T(0), T(1), T(1e-3)),
                          subdivide_variation(constant, T(0), T(1), T(1e-3))}) {
    EXPECT_EQ(res.status, Status::ok);
    EXPECT_EQ(res.params.size(), 2u);
  }
  const auto same = subdivide_midpoint(c, T(2), T(2), T(1e-3));
  EXPECT_EQ(same.status, Status::ok);
  EXPECT_EQ(same.params.size(), 2u);
  // Bad tolerances and parameters.
  EXPECT_EQ(subdivide_midpoint(c, T(0), T(1), T(-1)).status, Status::invalid_input);
  EXPECT_EQ(subdivide_variation(c, T(0), T(1), nan_v<T>()).status, Status::invalid_input);
  EXPECT_EQ(subdivide_midpoint(c, nan_v<T>(), T(1), T(1e-3)).status, Status::non_finite_input);
  EXPECT_EQ(subdivide_variation(c, T(0), -std::numeric_limits<T>::infinity(), T(1e-3)).status,
            Status::non_finite_input);
  SubdivisionOptions bad;
  bad.max_points = 1;
  EXPECT_EQ(subdivide_midpoint(c, T(0), T(1), T(1e-3), bad).status, Status::invalid_input);
  // NaN inside the curve: found by the refinement, never accepted silently.
  const auto holed = [](T t) { return Vec2<T>{t, t > T(0.6) && t < T(0.7) ? nan_v<T>() : t * t}; };
  for (const auto& res : {subdivide_midpoint(holed, T(0), T(1), T(1e-4)),
                          subdivide_variation(holed, T(0), T(1), T(1e-4))}) {
    EXPECT_EQ(res.status, Status::non_finite_input);
    EXPECT_TRUE(res.params.empty() && res.points.empty());
  }
  const auto end_nan = [](T t) { return Vec2<T>{t, t == T(1) ? nan_v<T>() : t}; };
  EXPECT_EQ(subdivide_midpoint(end_nan, T(0), T(1), T(1e-4)).status, Status::non_finite_input);
}

// ---- variation ---------------------------------------------------------------------------------

// Every final piece's RMS distance from its chord, recomputed by dense Simpson sampling, is
// within tol (Gauss-Legendre on 5 nodes is exact for the cubic curve, so only the oracle's own
// error and rounding separate the two).
TYPED_TEST(SubdivideTest, VariationEveryPieceWithinTolerance) {
  using T = TypeParam;
  const auto cubic = [](T t) { return Vec2<T>{t, t * t * t - t}; };
  const Parabola p{2.0};
  const HelixSq h{1.5, 0.4};
  for (double tol : {5e-2, 5e-3, 5e-4}) {
    const auto r = subdivide_variation(cubic, T(-1.5), T(1.5), T(tol));
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_GT(r.params.size(), 3u);
    for (std::size_t i = 0; i + 1 < r.params.size(); ++i)
      EXPECT_LE((dense_rms<T, 2>)(cubic, r.params[i], r.params[i + 1]),
                tol * (1 + 1e-6) + 64 * double(eps_v<T>) * 2);
    const auto rp = subdivide_variation(p, T(-1), T(2), T(tol));
    ASSERT_EQ(rp.status, Status::ok);
    for (std::size_t i = 0; i + 1 < rp.params.size(); ++i)
      EXPECT_LE((dense_rms<T, 2>)(p, rp.params[i], rp.params[i + 1]),
                tol * (1 + 1e-6) + 64 * double(eps_v<T>) * 8);
    const auto rh = subdivide_variation(h, T(0.5), T(2.5), T(tol));
    ASSERT_EQ(rh.status, Status::ok);
    // The helix is not polynomial: Gauss-Legendre on a piece short enough to pass is accurate
    // to far better than 1 % of the (squared) deviation.
    for (std::size_t i = 0; i + 1 < rh.params.size(); ++i)
      EXPECT_LE((dense_rms<T, 3>)(h, rh.params[i], rh.params[i + 1]),
                tol * 1.01 + 64 * double(eps_v<T>) * 8);
  }
}

// Uniform circle: all pieces have the same RMS deviation, so the depth is the smallest d with
// RMS(theta / 2^d) <= tol, the RMS computed by the independent dense Simpson rule.
TYPED_TEST(SubdivideTest, VariationCircleDepth) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int tested = 0;
  for (int k = 0; k < 30; ++k) {
    const double r = rng.uniform(0.5, 3.0), theta = rng.uniform(0.5, 6.0);
    const double tol = r * std::pow(10.0, rng.uniform(-4.0, -1.5));
    const auto cd = [&](double t) { return Vec2d{r * std::cos(t), r * std::sin(t)}; };
    const auto rms = [&](double ang) { return dense_rms<double, 2>(cd, 0.0, ang); };
    int d = 0;
    while (rms(theta / std::pow(2.0, d)) > tol) ++d;
    if (rms(theta / std::pow(2.0, d)) > tol * (1 - 1e-3) ||
        (d > 0 && rms(theta / std::pow(2.0, d - 1)) < tol * (1 + 1e-3)))
      continue;
    ++tested;
    const auto c = [&](T t) {
      return Vec2<T>{T(r * std::cos(double(t))), T(r * std::sin(double(t)))};
    };
    const auto res = subdivide_variation(c, T(0), T(theta), T(tol));
    ASSERT_EQ(res.status, Status::ok);
    EXPECT_EQ(res.params.size(), (std::size_t(1) << d) + 1) << "depth " << d;
  }
  EXPECT_GT(tested, 15);
}

// Invariance: translating and rotating the curve does not change the chosen parameters
// (beyond decisions within rounding of the tolerance, avoided by a tolerance far from them).
TYPED_TEST(SubdivideTest, RigidMotionInvariance) {
  using T = TypeParam;
  const auto c = [](T t) { return Vec2<T>{t, T(0.5) * t * t * t}; };
  const T ca = T(0.6), sa = T(0.8);
  const auto moved = [&](T t) {
    const Vec2<T> p = c(t);
    return Vec2<T>{ca * p.x - sa * p.y + T(3), sa * p.x + ca * p.y - T(1)};
  };
  const auto a = subdivide_midpoint(c, T(-1), T(2), T(0.0123));
  const auto b = subdivide_midpoint(moved, T(-1), T(2), T(0.0123));
  EXPECT_EQ(a.params, b.params);
  const auto va = subdivide_variation(c, T(-1), T(2), T(0.00731));
  const auto vb = subdivide_variation(moved, T(-1), T(2), T(0.00731));
  EXPECT_EQ(va.params, vb.params);
}
