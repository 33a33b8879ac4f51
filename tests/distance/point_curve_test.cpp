// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_curve.hpp (rows dist2.pt-polycurve, dist3.pt-paramcurve; book
// sections 6.2.3 and 10.5.3, figures 6.15 and 10.25). Oracles: the generic harness (sampling +
// compass search on the curves' own point_at), and an independent long double minimisation
// (the curve evaluated by its own de Casteljau / Cox-de Boor code in long double, 3000 samples,
// golden-section refinement of every sampled local minimum, the end samples included).
#include <locus/distance/point_curve.hpp>

#include "distance/harness.hpp"
#include "distance/side_curved.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;

template <class T>
class PointCurveTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointCurveTest, locus_test::RealTypes);

namespace {

// Fewer cases under the sanitizers (the CI runs every test binary there at -O1 too).
#if LOCUS_TEST_SANITIZED
constexpr int kCaseScale = 3;
#else
constexpr int kCaseScale = 1;
#endif

using LD = long double;

::testing::AssertionResult near_ld(LD got, LD want, LD abs_tol) {
  if (std::fabs(got - want) <= abs_tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "got " << static_cast<double>(got) << " want " << static_cast<double>(want) << " diff "
         << static_cast<double>(got - want) << " tol " << static_cast<double>(abs_tol);
}

template <class T, int N>
BezierCurve<T, N> random_bezier(Rng& rng, T s, int max_degree = 6) {
  BezierCurve<T, N> c;
  const int n = rng.uniform_int(1, max_degree) + 1;
  for (int i = 0; i < n; ++i) c.control.push_back(rng.vec<T, N>(-s, s));
  return c;
}

template <class T>
std::vector<T> random_knots(Rng& rng, int n, int d) {
  // Clamped or not, with occasional repeated interior knots (multiplicity <= d).
  std::vector<T> k;
  const bool clamped = rng.uniform_int(0, 1) == 0;
  T x = T(0);
  int mult = 0;
  for (int i = 0; i < n + d + 1; ++i) {
    if (clamped && i <= d) {
      k.push_back(T(0));
      continue;
    }
    if (clamped && i >= n) {
      k.push_back(T(-1));
      continue;
    }
    const bool first_inner = clamped && i == d + 1;
    if (first_inner || i == 0 || i == n || mult >= d || rng.uniform_int(0, 4) != 0) {
      x += rng.uniform<T>(T(0.2), T(1.5));
      mult = 1;
    } else {
      ++mult;
    }
    k.push_back(x);
  }
  if (clamped)
    for (auto& v : k)
      if (v < T(0)) v = x + T(1);
  return k;
}

template <class T, int N>
BSplineCurve<T, N> random_bspline(Rng& rng, T s) {
  const int d = rng.uniform_int(1, 4);
  const int n = d + 1 + rng.uniform_int(0, 5);
  BSplineCurve<T, N> c{d, {}, random_knots<T>(rng, n, d)};
  for (int i = 0; i < n; ++i) c.control.push_back(rng.vec<T, N>(-s, s));
  return c;
}

template <class T, int N>
NurbsCurve<T, N> random_nurbs(Rng& rng, T s) {
  const BSplineCurve<T, N> b = random_bspline<T, N>(rng, s);
  NurbsCurve<T, N> c{b.degree, b.control, {}, b.knots};
  for (std::size_t i = 0; i < c.control.size(); ++i)
    c.weights.push_back(rng.uniform<T>(T(0.2), T(5)));
  return c;
}

// ---- long double evaluation, written independently of the library's curves -------------------
template <int N>
using VL = std::array<LD, N>;

template <class T, int N>
VL<N> ld_point(const BezierCurve<T, N>& c, LD t) {
  std::vector<VL<N>> b(c.control.size());
  for (std::size_t i = 0; i < b.size(); ++i)
    for (int k = 0; k < N; ++k) b[i][static_cast<std::size_t>(k)] = c.control[i][k];
  for (std::size_t r = 1; r < b.size(); ++r)
    for (std::size_t i = 0; i + r < b.size(); ++i)
      for (std::size_t k = 0; k < N; ++k) b[i][k] = (1 - t) * b[i][k] + t * b[i + 1][k];
  return b[0];
}

/// N_{i,d}(t) for all i by the Cox-de Boor recursion on the full knot vector (half-open spans,
/// the last non-empty span closed).
template <class T>
std::vector<LD> ld_basis(const std::vector<T>& kn, int d, int n, LD t) {
  const int m = static_cast<int>(kn.size());
  std::vector<LD> b(static_cast<std::size_t>(m - 1), 0);
  int last = -1;
  for (int i = d; i < n; ++i)
    if (kn[static_cast<std::size_t>(i)] < kn[static_cast<std::size_t>(i) + 1]) last = i;
  for (int i = d; i <= last; ++i) {  // t lies in the domain [t_d, t_n]
    const LD a = kn[static_cast<std::size_t>(i)], c = kn[static_cast<std::size_t>(i) + 1];
    if (a < c && ((a <= t && t < c) || (i == last && t == c))) b[static_cast<std::size_t>(i)] = 1;
  }
  for (int p = 1; p <= d; ++p)
    for (int i = 0; i + p < m - 1; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      const LD ti = kn[ui], tip = kn[ui + static_cast<std::size_t>(p)], ti1 = kn[ui + 1],
               tip1 = kn[ui + static_cast<std::size_t>(p) + 1];
      LD v = 0;
      if (tip > ti) v += (t - ti) / (tip - ti) * b[ui];
      if (tip1 > ti1) v += (tip1 - t) / (tip1 - ti1) * b[ui + 1];
      b[ui] = v;
    }
  b.resize(static_cast<std::size_t>(n));
  return b;
}

template <class T, int N>
VL<N> ld_point(const BSplineCurve<T, N>& c, LD t) {
  const auto b = ld_basis(c.knots, c.degree, static_cast<int>(c.control.size()), t);
  VL<N> p{};
  for (std::size_t i = 0; i < b.size(); ++i)
    for (std::size_t k = 0; k < N; ++k) p[k] += b[i] * c.control[i][static_cast<int>(k)];
  return p;
}

template <class T, int N>
VL<N> ld_point(const NurbsCurve<T, N>& c, LD t) {
  const auto b = ld_basis(c.knots, c.degree, static_cast<int>(c.control.size()), t);
  VL<N> p{};
  LD w = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    w += b[i] * c.weights[i];
    for (std::size_t k = 0; k < N; ++k)
      p[k] += b[i] * c.weights[i] * c.control[i][static_cast<int>(k)];
  }
  for (auto& x : p) x /= w;
  return p;
}

template <class Curve>
std::pair<LD, LD> ld_domain(const Curve& c) {
  if constexpr (requires { c.knots; })
    return {c.knots[static_cast<std::size_t>(c.degree)], c.knots[c.control.size()]};
  else
    return {0, 1};
}

template <class T, int N, class Curve>
LD oracle_curve(const Vec<T, N>& p, const Curve& c) {
  const auto domain = ld_domain(c);
  const LD a = domain.first, b = domain.second;  // clang 14 cannot capture bindings
  // Clamped: a + (b - a) * n / n (and a bracket's end) can round one ulp beyond b, where no
  // basis function is 1 and ld_point returned the origin (seed 11: |p| = 10.58 taken for the
  // distance 11.95 to the end of the curve).
  const auto f = [&](LD t) {
    const VL<N> x = ld_point(c, std::clamp(t, a, b));
    LD s = 0;
    for (int k = 0; k < N; ++k)
      s += (x[static_cast<std::size_t>(k)] - p[k]) * (x[static_cast<std::size_t>(k)] - p[k]);
    return s;
  };
  constexpr int n = 3000;
  std::vector<LD> v(n + 1);
  for (int i = 0; i <= n; ++i) v[static_cast<std::size_t>(i)] = f(a + (b - a) * LD(i) / LD(n));
  LD best = std::min(v[0], v[n]);
  const LD g = (std::sqrt(5.0L) - 1) / 2;
  // Every sampled local minimum is refined, the two end samples included (bracket [a, a + h] or
  // [b - h, b]): a minimum within one sample step of an end, where the end sample is smaller than
  // its neighbour, was missed otherwise (seeds 50 and 99999: minima 0.35 and 0.08 steps from an
  // end, 2e-6 and 4e-6 below the end samples).
  for (int i = 0; i <= n; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    if ((i > 0 && v[ui] > v[ui - 1]) || (i < n && v[ui] > v[ui + 1])) continue;
    LD lo = a + (b - a) * LD(std::max(i - 1, 0)) / LD(n),
       hi = a + (b - a) * LD(std::min(i + 1, n)) / LD(n);
    LD x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
    for (int it = 0; it < 90; ++it) {
      if (f1 < f2) {
        hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
      } else {
        lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
      }
    }
    best = std::min({best, f1, f2, v[ui]});
  }
  return std::sqrt(best);
}

template <class T, int N, class Curve, class Gen>
void compare_with_oracle(Gen gen, int cases, const char* what) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  LD worst = 0;
  for (int n = 0; n < cases / kCaseScale; ++n) {
    SCOPED_TRACE("case " + std::to_string(n));
    const Curve c = gen(rng);
    const Vec<T, N> p = rng.vec<T, N>(T(-12), T(12));
    const auto r = distance(p, c);
    const LD o = oracle_curve<T, N>(p, c);
    T scale = std::max(T(1), max_abs(p));
    for (const auto& q : c.control) scale = std::max(scale, max_abs(q));
    EXPECT_TRUE(near_ld(static_cast<LD>(r.distance), o, static_cast<LD>(tol<T>(32, scale))));
    worst =
        std::max(worst, std::fabs(static_cast<LD>(r.distance) - o) / (LD(eps_v<T>) * LD(scale)));
  }
  std::printf("%s: max |distance - oracle| = %.2f eps * scale\n", what, static_cast<double>(worst));
}

}  // namespace

TYPED_TEST(PointCurveTest, Harness) {
  using T = TypeParam;
  const T S = 10;
  dist::Options<T> opt;
  opt.cases = 60 / kCaseScale;
  // The compass-search oracle can stall in a local minimum of a wiggly curve: its agreement is
  // not required (the harness still checks it never beats the answer); the long double oracle
  // below checks agreement.
  opt.check_agreement = false;
  dist::check_pairs<T, 2, Vec2<T>, BezierCurve<T, 2>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 2>(-S, S), random_bezier<T, 2>(rng, S)};
      },
      opt);
  dist::check_pairs<T, 3, Vec3<T>, BezierCurve<T, 3>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 3>(-S, S), random_bezier<T, 3>(rng, S)};
      },
      opt);
  dist::check_pairs<T, 2, Vec2<T>, BSplineCurve<T, 2>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 2>(-S, S), random_bspline<T, 2>(rng, S)};
      },
      opt);
  dist::check_pairs<T, 3, Vec3<T>, BSplineCurve<T, 3>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 3>(-S, S), random_bspline<T, 3>(rng, S)};
      },
      opt);
  dist::check_pairs<T, 2, Vec2<T>, NurbsCurve<T, 2>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 2>(-S, S), random_nurbs<T, 2>(rng, S)};
      },
      opt);
  dist::check_pairs<T, 3, Vec3<T>, NurbsCurve<T, 3>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 3>(-S, S), random_nurbs<T, 3>(rng, S)};
      },
      opt);
}

TYPED_TEST(PointCurveTest, LongDoubleOracle) {
  using T = TypeParam;
  const T S = 10;
  compare_with_oracle<T, 2, BezierCurve<T, 2>>([&](Rng& r) { return random_bezier<T, 2>(r, S, 9); },
                                               40, "point-bezier2");
  compare_with_oracle<T, 3, BezierCurve<T, 3>>([&](Rng& r) { return random_bezier<T, 3>(r, S, 9); },
                                               40, "point-bezier3");
  compare_with_oracle<T, 2, BSplineCurve<T, 2>>([&](Rng& r) { return random_bspline<T, 2>(r, S); },
                                                40, "point-bspline2");
  compare_with_oracle<T, 3, BSplineCurve<T, 3>>([&](Rng& r) { return random_bspline<T, 3>(r, S); },
                                                40, "point-bspline3");
  compare_with_oracle<T, 2, NurbsCurve<T, 2>>([&](Rng& r) { return random_nurbs<T, 2>(r, S); }, 40,
                                              "point-nurbs2");
  compare_with_oracle<T, 3, NurbsCurve<T, 3>>([&](Rng& r) { return random_nurbs<T, 3>(r, S); }, 40,
                                              "point-nurbs3");
  // High degrees (beyond the inline buffers) and wiggly curves with many local minima.
  compare_with_oracle<T, 2, BezierCurve<T, 2>>(
      [&](Rng& r) {
        BezierCurve<T, 2> c;
        const int n = r.uniform_int(13, 17);
        for (int i = 0; i < n; ++i)
          c.control.push_back({T(i), (i % 2 ? T(1) : T(-1)) * r.uniform<T>(T(2), T(6))});
        return c;
      },
      20, "point-bezier2 high degree");
}

// Figure 6.15: the closest point of a cubic; the residual is normal to the curve there, and a
// local minimum that is not global (the far lobe) is not returned.
TYPED_TEST(PointCurveTest, Figure6_15) {
  using T = TypeParam;
  const BezierCurve<T, 2> c{{{T(0), T(0)}, {T(1), T(4)}, {T(5), T(4)}, {T(6), T(0)}}};
  const Vec2<T> p{T(3), T(1)};
  const auto r = distance(p, c);
  EXPECT_TRUE(r.unique);
  // Below the arch on its symmetry axis the two end points tie.
  const auto below = distance(Vec2<T>{T(3), T(-1)}, c);
  EXPECT_FALSE(below.unique);
  EXPECT_NEAR(below.distance, std::sqrt(T(10)), tol<T>(16, T(4)));
  const Vec2<T> tan = derivative_at(c, r.param_b, 1);
  EXPECT_NEAR(dot(r.closest[1] - p, tan) / (length(tan) * (r.distance + T(1))), T(0), tol<T>(64));
  EXPECT_TRUE(near_ld(static_cast<LD>(r.distance), oracle_curve<T, 2>(p, c), tol<T>(32, T(6))));
  // Off the axis: unique, the nearer lobe.
  const auto r2 = distance(Vec2<T>{T(2.5), T(1)}, c);
  EXPECT_TRUE(r2.unique);
  EXPECT_LT(r2.closest[1].x, T(3));
  // The top of the arch from above: the apex, exactly where the derivative condition says.
  const auto top = distance(Vec2<T>{T(3), T(10)}, c);
  EXPECT_NEAR(top.param_b, T(0.5), tol<T>(64));
  EXPECT_NEAR(top.distance, T(7), tol<T>(32, T(10)));
  // Figure 10.25 in 3D: a helix-like cubic; agree with the oracle and with the swapped call.
  const BezierCurve<T, 3> h{
      {{T(1), T(0), T(0)}, {T(1), T(2), T(1)}, {T(-1), T(2), T(2)}, {T(-1), T(0), T(3)}}};
  const Vec3<T> q{T(0), T(3), T(1)};
  const auto r3 = distance(q, h);
  EXPECT_TRUE(near_ld(static_cast<LD>(r3.distance), oracle_curve<T, 3>(q, h), tol<T>(32, T(4))));
  const auto s3 = distance(h, q);
  EXPECT_EQ(s3.distance, r3.distance);
  EXPECT_EQ(s3.param_a, r3.param_b);
}

// Constant distance: a NURBS circle seen from its centre (every point is closest), and points on
// a circle arc reproduce the radius.
TYPED_TEST(PointCurveTest, NurbsCircle) {
  using T = TypeParam;
  const Circle2<T> circ{{T(1), T(2)}, T(3)};
  const NurbsCurve<T, 2> c = to_nurbs(circ);
  const auto ctr = distance(circ.center, c);
  EXPECT_NEAR(ctr.distance, T(3), tol<T>(32, T(4)));
  EXPECT_FALSE(ctr.unique);
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 50; ++i) {
    const Vec2<T> p = rng.vec<T, 2>(T(-8), T(8));
    const auto r = distance(p, c);
    EXPECT_NEAR(r.distance, std::abs(length(p - circ.center) - T(3)), tol<T>(64, T(10)));
  }
}

TYPED_TEST(PointCurveTest, Degenerate) {
  using T = TypeParam;
  // A single control point; all control points equal; a cusp.
  const BezierCurve<T, 2> one{{{T(1), T(1)}}};
  EXPECT_EQ(distance(Vec2<T>{T(4), T(5)}, one).distance, T(5));
  const BezierCurve<T, 2> same{{{T(1), T(1)}, {T(1), T(1)}, {T(1), T(1)}}};
  const auto s = distance(Vec2<T>{T(4), T(5)}, same);
  EXPECT_EQ(s.distance, T(5));
  EXPECT_TRUE(s.unique);
  const BezierCurve<T, 2> cusp{{{T(0), T(0)}, {T(2), T(2)}, {T(0), T(2)}, {T(2), T(0)}}};
  EXPECT_TRUE(near_ld(static_cast<LD>(distance(Vec2<T>{T(1), T(1.5)}, cusp).distance),
                      oracle_curve<T, 2>(Vec2<T>{T(1), T(1.5)}, cusp), tol<T>(32, T(4))));
  // A point on the curve: distance 0 to rounding.
  const BezierCurve<T, 3> cub{
      {{T(0), T(0), T(0)}, {T(1), T(3), T(0)}, {T(3), T(3), T(1)}, {T(4), T(0), T(2)}}};
  EXPECT_NEAR(distance(point_at(cub, T(0.3)), cub).distance, T(0), tol<T>(64, T(4)));
  // Degree-0 B-spline (piecewise constant): the nearest control point.
  const BSplineCurve<T, 2> step{
      0, {{T(0), T(0)}, {T(5), T(0)}, {T(9), T(0)}}, {T(0), T(1), T(2), T(3)}};
  const auto st = distance(Vec2<T>{T(6), T(2)}, step);
  EXPECT_NEAR(st.distance, std::sqrt(T(5)), tol<T>(16, T(8)));
  // Repeated knots (a C0 corner) and a linear B-spline: the polyline distance.
  const BSplineCurve<T, 2> poly{
      1, {{T(0), T(0)}, {T(4), T(0)}, {T(4), T(4)}}, {T(0), T(0), T(1), T(2), T(2)}};
  EXPECT_NEAR(distance(Vec2<T>{T(5), T(-1)}, poly).distance, std::sqrt(T(2)), tol<T>(16, T(8)));
  EXPECT_NEAR(distance(Vec2<T>{T(2), T(1)}, poly).distance, T(1), tol<T>(16, T(8)));
}

TYPED_TEST(PointCurveTest, BadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const BezierCurve<T, 2> c{{{T(0), T(0)}, {T(1), T(1)}}};
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{nan, T(0)}, c)));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{}, BezierCurve<T, 2>{})));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{}, BezierCurve<T, 2>{{{T(0), inf}}})));
  BSplineCurve<T, 3> b{
      2, {{}, {T(1), T(0), T(0)}, {T(1), T(1), T(0)}}, {T(0), T(0), T(0), T(1), T(1), T(1)}};
  EXPECT_FALSE(dist::is_nan_result(distance(Vec3<T>{}, b)));
  b.knots[3] = T(-1);  // decreasing
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, b)));
  b.knots.pop_back();
  EXPECT_TRUE(dist::is_nan_result(distance(b, Vec3<T>{})));
  NurbsCurve<T, 2> n{1, {{T(0), T(0)}, {T(1), T(0)}}, {T(1), T(0)}, {T(0), T(0), T(1), T(1)}};
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{}, n)));  // zero weight
  n.weights[1] = nan;
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{}, n)));
  n.weights[1] = T(2);
  EXPECT_NEAR(distance(Vec2<T>{T(0.5), T(1)}, n).distance, T(1), tol<T>(16, T(2)));
}

// Seeds 50 (point-bezier3 case 18) and 99999 (point-nurbs2 case 7): the minimum lies 0.35 and
// 0.08 oracle sample steps from an end of the domain, and the end sample was smaller than its
// neighbour, so the old oracle (which refined interior sample minima only) returned the end
// sample, 2.1e-6 and 4.3e-6 above the library's distance; the library's distance is realised
// at its parameter (independent long double evaluation) and the fixed oracle agrees.
template <int N, class Curve>
void check_minimum_near_end(const Vec<double, N>& p, const Curve& c, double end_t) {
  using T = double;
  const auto r = distance(p, c);
  T scale = std::max(T(1), max_abs(p));
  for (const auto& q : c.control) scale = std::max(scale, max_abs(q));
  EXPECT_TRUE(near_ld(static_cast<LD>(r.distance), oracle_curve<T, N>(p, c), tol<T>(32, scale)));
  EXPECT_GT(length(point_at(c, end_t) - p) - r.distance, T(1e-6));  // the end is not the answer
  const VL<N> x = ld_point(c, static_cast<LD>(r.param_b));
  LD d2 = 0;
  for (int k = 0; k < N; ++k)
    d2 += (x[static_cast<std::size_t>(k)] - p[k]) * (x[static_cast<std::size_t>(k)] - p[k]);
  EXPECT_TRUE(near_ld(static_cast<LD>(r.distance), std::sqrt(d2), tol<T>(16, scale)));
}

TEST(PointCurveRegression, OracleMinimumNearAnEnd) {
  using T = double;
  const BezierCurve<T, 3> b{{{0x1.af5f728ebec4cp+1, -0x1.378789a1f0684p+3, -0x1.1d5f87a0a4de4p+2},
                             {-0x1.345bbdfd0a30ep+3, 0x1.c0a422ea564e8p+1, -0x1.bc53be2494bd2p+1},
                             {0x1.f349aa393f998p+2, 0x1.0bd320fb52e88p+3, 0x1.9bd6e573778f4p+1},
                             {0x1.749d00392e9e8p+1, -0x1.252739c6ba0cep+2, 0x1.e62944b5d6138p+2}}};
  check_minimum_near_end<3>(
      Vec3<T>{0x1.2a4dd8e4891e6p+3, -0x1.f8679119ca49dp+2, 0x1.3e49e1e50b628p+2}, b, T(1));
  const NurbsCurve<T, 2> n{
      4,
      {{-0x1.41479ef835483p+2, 0x1.6ca5d2dd32e5cp+2},
       {0x1.af3db1046a89cp+2, 0x1.ed214891676bp+1},
       {-0x1.34215f75772b7p+3, 0x1.8b2106b6ef1f8p+1},
       {0x1.77c2e6edc797p+1, 0x1.55fd90f483e3p+1},
       {-0x1.0b4ffc14fb15ep+2, 0x1.9fa2f217f4fb4p+2},
       {-0x1.18ce3945c0926p+3, 0x1.13117080ebbep+2}},
      {0x1.c4478edcd9792p-2, 0x1.196ff00458fd6p-2, 0x1.640974909d12p-1, 0x1.f989625ce2d3cp+1,
       0x1.9bd6d4957b26ap-2, 0x1.7ee0d1e0907afp+0},
      {0, 0, 0, 0, 0, 0x1.29062b8d1bbfp-1, 0x1.948315c68ddf8p+0, 0x1.948315c68ddf8p+0,
       0x1.948315c68ddf8p+0, 0x1.948315c68ddf8p+0, 0x1.948315c68ddf8p+0}};
  check_minimum_near_end<2>(Vec2<T>{-0x1.3c3fb92e048a7p+2, 0x1.8bda3998a5894p+2}, n, T(0));
}

// Seed 11, point-bspline2 case 11: a degree-1 unclamped B-spline (the polyline of its control
// points). The oracle's last sample a + (b - a) * n / n rounded beyond the domain end, where its
// Cox-de Boor evaluation gives the origin: it reported |p| = 10.58 instead of the polyline
// distance 11.949482602537637 (segment P2 P3 at its end P3, by hand) that the library returns.
TEST(PointCurveRegression, OracleSampleBeyondTheDomainEnd) {
  using T = double;
  const BSplineCurve<T, 2> c{
      1,
      {{0x1.302cf48259c04p+2, 0x1.4d673bf9a6ep-4},
       {0x1.957c307f8404p+2, 0x1.4a276d1a5441p+0},
       {0x1.0ee658e913dap+3, 0x1.0f86fa0f553p+2},
       {0x1.701df862885bp+0, -0x1.338511405b63p-1},
       {0x1.41ef3e69a4b32p+2, -0x1.c7b91778ff334p+2},
       {-0x1.8085e6ff1e32cp+1, -0x1.45c7a9836f687p+2}},
      {0x1.a84751c14ced2p-2, 0x1.7e92ba962cae3p-1, 0x1.0546601f3b002p+1, 0x1.53e7bc7567948p+1,
       0x1.d3af8973d0352p+1, 0x1.3267d5f12aee4p+2, 0x1.9132e5665970ap+2, 0x1.c9213a37edec7p+2}};
  const Vec2<T> p{-0x1.956f598c32a0fp+2, 0x1.0f35b2485d058p+3};
  const auto r = distance(p, c);
  EXPECT_NEAR(r.distance, length(c.control[3] - p), tol<T>(16, T(16)));
  EXPECT_TRUE(near_ld(static_cast<LD>(r.distance), oracle_curve<T, 2>(p, c), tol<T>(32, T(16))));
}
