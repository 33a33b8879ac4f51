// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_ellipse.hpp and point_ellipsoid.hpp (rows dist2.pt-quadratic
// (ellipse), dist3.pt-ellipsoid; book sections 6.2.2 and 10.5, figures 6.14 and 10.24).
// Oracles: the generic harness (sampling + compass search), and an independent long double
// minimisation over the angle parameters (dense samples, then Newton on the parametrisation,
// three polar charts for the ellipsoid) which checks the distance to a few ulps.
#include <locus/distance/point_ellipse.hpp>
#include <locus/distance/point_ellipsoid.hpp>

#include "distance/harness.hpp"
#include "distance/side_curved.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;

template <class T>
class PointEllipseTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointEllipseTest, locus_test::RealTypes);

namespace {

// Fewer cases under the sanitizers (the CI runs every test binary there at -O1 too).
#if LOCUS_TEST_SANITIZED
constexpr int kCaseScale = 3;
#else
constexpr int kCaseScale = 1;
#endif

using LD = long double;

template <class T>
Ellipse2<T> random_ellipse(Rng& rng, T scale, bool allow_zero) {
  const T a = rng.uniform<T>(T(0), T(6.283185307179586));
  const Vec2<T> u{std::cos(a), std::sin(a)};
  T e0 = rng.uniform<T>(T(0.1), T(8)), e1 = rng.uniform<T>(T(0.1), T(8));
  if (allow_zero && rng.uniform_int(0, 9) == 0) e1 = T(0);
  if (rng.uniform_int(0, 9) == 0) e1 = e0;  // circles
  return {rng.vec<T, 2>(-scale, scale), {u, perp(u)}, {e0, e1}};
}

template <class T>
Ellipsoid3<T> random_ellipsoid(Rng& rng, T scale, bool allow_zero) {
  const auto r = dist::random_rotation<T, 3>(rng);
  Vec3<T> e{rng.uniform<T>(T(0.1), T(8)), rng.uniform<T>(T(0.1), T(8)),
            rng.uniform<T>(T(0.1), T(8))};
  if (allow_zero && rng.uniform_int(0, 9) == 0) e[rng.uniform_int(0, 2)] = T(0);
  if (rng.uniform_int(0, 9) == 0) e.y = e.x;  // spheroids
  return {rng.vec<T, 3>(-scale, scale), {col(r, 0), col(r, 1), col(r, 2)}, e};
}

/// Long double distance from p to the ellipse: 1024 samples of the angle, then Newton from the
/// best few (safeguarded: only decreasing steps).
template <class T>
LD oracle_ellipse(const Vec2<T>& p, const Ellipse2<T>& e) {
  const LD cx = e.center.x, cy = e.center.y;
  const LD ux = e.axis[0].x, uy = e.axis[0].y, vx = e.axis[1].x, vy = e.axis[1].y;
  const LD a = e.extent[0], b = e.extent[1], px = p.x, py = p.y;
  const auto f = [&](LD t, LD* d1, LD* d2) {
    const LD c = std::cos(t), s = std::sin(t);
    const LD x = cx + a * c * ux + b * s * vx - px, y = cy + a * c * uy + b * s * vy - py;
    const LD dx = -a * s * ux + b * c * vx, dy = -a * s * uy + b * c * vy;
    const LD ddx = -a * c * ux - b * s * vx, ddy = -a * c * uy - b * s * vy;
    if (d1) *d1 = 2 * (x * dx + y * dy);
    if (d2) *d2 = 2 * (dx * dx + dy * dy + x * ddx + y * ddy);
    return x * x + y * y;
  };
  constexpr int n = 1024;
  LD vals[n];
  for (int i = 0; i < n; ++i)
    vals[i] = f(LD(6.283185307179586476925L) * LD(i) / LD(n), nullptr, nullptr);
  LD best = std::numeric_limits<LD>::infinity();
  for (int i = 0; i < n; ++i) {
    const LD prev = vals[(i + n - 1) % n], next = vals[(i + 1) % n];
    if (vals[i] > prev || vals[i] > next) continue;  // only local minima of the samples
    LD t = LD(6.283185307179586476925L) * LD(i) / LD(n), ft = vals[i];
    for (int it = 0; it < 60; ++it) {
      LD g, h;
      f(t, &g, &h);
      LD step = h > 0 ? -g / h : (g > 0 ? -1e-3L : 1e-3L);
      bool moved = false;
      for (int k = 0; k < 40; ++k, step *= 0.5L) {
        const LD ftry = f(t + step, nullptr, nullptr);
        if (ftry < ft) {
          t += step, ft = ftry, moved = true;
          break;
        }
      }
      if (!moved) break;
    }
    best = std::min(best, ft);
  }
  return std::sqrt(best);
}

/// Long double distance from p to the ellipsoid surface: in each of three polar charts (axis k
/// as the pole), a 48 x 24 grid, then damped Newton in (theta, phi) from the best grid points.
template <class T>
LD oracle_ellipsoid(const Vec3<T>& p, const Ellipsoid3<T>& e) {
  LD best = std::numeric_limits<LD>::infinity();
  for (int pole = 0; pole < 3; ++pole) {
    const int i0 = (pole + 1) % 3, i1 = (pole + 2) % 3, i2 = pole;
    LD ax[3][3], ex[3], d[3];
    const int ord[3] = {i0, i1, i2};
    for (int k = 0; k < 3; ++k) {
      ex[k] = e.extent[ord[k]];
      for (int c = 0; c < 3; ++c) ax[k][c] = e.axis[ord[k]][c];
    }
    for (int c = 0; c < 3; ++c) d[c] = LD(e.center[c]) - LD(p[c]);
    // f and its gradient / Hessian in (theta, phi).
    const auto f = [&](LD th, LD ph, LD* g, LD* h) {
      const LD ct = std::cos(th), st = std::sin(th), cp = std::cos(ph), sp = std::sin(ph);
      const LD u[3] = {ct * sp, st * sp, cp};
      const LD ut[3] = {-st * sp, ct * sp, 0}, up[3] = {ct * cp, st * cp, -sp};
      const LD utt[3] = {-ct * sp, -st * sp, 0}, utp[3] = {-st * cp, ct * cp, 0},
               upp[3] = {-ct * sp, -st * sp, -cp};
      LD x[3], xt[3], xp[3], xtt[3], xtp[3], xpp[3];
      for (int c = 0; c < 3; ++c) {
        x[c] = d[c], xt[c] = xp[c] = xtt[c] = xtp[c] = xpp[c] = 0;
        for (int k = 0; k < 3; ++k) {
          x[c] += ex[k] * u[k] * ax[k][c];
          xt[c] += ex[k] * ut[k] * ax[k][c];
          xp[c] += ex[k] * up[k] * ax[k][c];
          xtt[c] += ex[k] * utt[k] * ax[k][c];
          xtp[c] += ex[k] * utp[k] * ax[k][c];
          xpp[c] += ex[k] * upp[k] * ax[k][c];
        }
      }
      const auto dt = [](const LD* a, const LD* b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      };
      if (g) {
        g[0] = 2 * dt(x, xt), g[1] = 2 * dt(x, xp);
        h[0] = 2 * (dt(xt, xt) + dt(x, xtt));
        h[1] = 2 * (dt(xt, xp) + dt(x, xtp));
        h[2] = 2 * (dt(xp, xp) + dt(x, xpp));
      }
      return dt(x, x);
    };
    constexpr int nt = 48, np = 24;
    struct Cand {
      LD f, th, ph;
    };
    Cand cands[4] = {{std::numeric_limits<LD>::infinity(), 0, 0},
                     {std::numeric_limits<LD>::infinity(), 0, 0},
                     {std::numeric_limits<LD>::infinity(), 0, 0},
                     {std::numeric_limits<LD>::infinity(), 0, 0}};
    for (int i = 0; i < nt; ++i)
      for (int j = 1; j < np; ++j) {
        const LD th = LD(6.283185307179586476925L) * LD(i) / LD(nt);
        const LD ph = LD(3.14159265358979323846L) * LD(j) / LD(np);
        const LD v = f(th, ph, nullptr, nullptr);
        if (v < cands[3].f) {
          cands[3] = {v, th, ph};
          std::sort(cands, cands + 4, [](const Cand& a, const Cand& b) { return a.f < b.f; });
        }
      }
    for (Cand c : cands) {
      for (int it = 0; it < 80; ++it) {
        LD g[2], h[3];
        f(c.th, c.ph, g, h);
        const LD det = h[0] * h[2] - h[1] * h[1];
        LD s0, s1;
        if (h[0] > 0 && det > 0) {
          s0 = -(h[2] * g[0] - h[1] * g[1]) / det;
          s1 = -(h[0] * g[1] - h[1] * g[0]) / det;
        } else {
          s0 = -1e-2L * g[0], s1 = -1e-2L * g[1];
        }
        bool moved = false;
        for (int k = 0; k < 50; ++k, s0 *= 0.5L, s1 *= 0.5L) {
          const LD v = f(c.th + s0, c.ph + s1, nullptr, nullptr);
          if (v < c.f) {
            c = {v, c.th + s0, c.ph + s1};
            moved = true;
            break;
          }
        }
        if (!moved) break;
      }
      best = std::min(best, c.f);
    }
  }
  return std::sqrt(best);
}

::testing::AssertionResult near_ld(LD got, LD want, LD abs_tol) {
  if (std::fabs(got - want) <= abs_tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "got " << static_cast<double>(got) << " want " << static_cast<double>(want) << " diff "
         << static_cast<double>(got - want) << " tol " << static_cast<double>(abs_tol);
}

}  // namespace

TYPED_TEST(PointEllipseTest, Harness) {
  using T = TypeParam;
  const T S = 10;
  dist::Options<T> opt;
  opt.cases = 150 / kCaseScale;
  // The harness oracle polishes only its best random sample by a compass search, which stays in
  // that sample's basin. Near the evolute the distance along the ellipse has two local minima of
  // almost equal depth, and with 256 samples the best one may lie in the shallower basin
  // (LOCUS_TEST_SEED=23, case 48: oracle 1.445437, true and returned 1.444544, checked by brute
  // force). Dense samples pick the right basin.
  opt.samples = 4096;
  dist::check_pairs<T, 2, Vec2<T>, Ellipse2<T>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 2>(-S, S), random_ellipse<T>(rng, S, true)};
      },
      opt);
  opt.cases = 60 / kCaseScale;
  // The harness oracle polishes only its best random sample by a compass search in (theta, phi),
  // which cannot cross the rim of a flat ellipsoid: when no sample hits the (small, ~0.6% of the
  // parameter box) patch of the near face below the far face's minimum, it settles on the far
  // face (LOCUS_TEST_SEED=31337, case 42: oracle 1.446, true distance 0.9035, the query right;
  // see EllipsoidFlatNearFace). The 4096 samples make that miss negligible too.
  dist::check_pairs<T, 3, Vec3<T>, Ellipsoid3<T>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 3>(-S, S), random_ellipsoid<T>(rng, S, true)};
      },
      opt);
}

// Regression (LOCUS_TEST_SEED=31337, Harness case 42): a flat ellipsoid (extents 0.333, 5.50,
// 7.61) seen from beyond its thin axis; the answer is on the near face at 0.903498 (the harness
// oracle had settled on the far face, 1.446). Checked against the long double oracle and the
// residual's normality.
TYPED_TEST(PointEllipseTest, EllipsoidFlatNearFace) {
  using T = TypeParam;
  const Vec3<T> p{T(-2.3888892181129195), T(-5.4755137925911246), T(8.2997644240899433)};
  const Ellipsoid3<T> e{
      {T(-4.2024517759124329), T(-4.431592185744929), T(5.3699672946993502)},
      {Vec3<T>{T(0.57227669663269964), T(-0.14483280655781552), T(-0.80716964798965984)},
       Vec3<T>{T(-0.43585113884676385), T(0.78003335403922458), T(-0.44897856446861306)},
       Vec3<T>{T(0.694646073376323), T(0.60874578005182411), T(0.38326936743229556)}},
      {T(0.33300138601518925), T(5.4956613728500141), T(7.6057906224672012)}};
  const auto r = distance(p, e);
  EXPECT_TRUE(near_ld(static_cast<LD>(r.distance), oracle_ellipsoid(p, e),
                      static_cast<LD>(tol<T>(16, T(10)))));
  EXPECT_NEAR(r.distance, T(0.903498), T(1e-5));
  EXPECT_TRUE(r.unique);
  // Near face: the closest point lies on p's side of the thin axis.
  EXPECT_GT(dot(r.closest[1] - e.center, e.axis[0]) * dot(p - e.center, e.axis[0]), T(0));
}

// Random points (half of them near the evolute's region inside), random and thin ellipses:
// the distance agrees with the long double oracle to a few ulps of the scale.
TYPED_TEST(PointEllipseTest, LongDoubleOracle2D) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  LD worst = 0;
  for (int n = 0; n < 200 / kCaseScale; ++n) {
    Ellipse2<T> e = random_ellipse<T>(rng, T(4), false);
    if (n % 4 == 1) e.extent[1] = e.extent[0] * T(1e-3);
    if (n % 4 == 2) e.extent[0] = e.extent[1] * T(1e-6);
    const T s = std::max(e.extent[0], e.extent[1]);
    const Vec2<T> p = n % 2 == 0 ? e.center + rng.vec<T, 2>(-T(0.9) * s, T(0.9) * s)
                                 : rng.vec<T, 2>(-T(12), T(12));
    SCOPED_TRACE("case " + std::to_string(n));
    const auto r = distance(p, e);
    const LD o = oracle_ellipse(p, e);
    const T scale = std::max({T(1), s, max_abs(p), max_abs(e.center)});
    EXPECT_TRUE(near_ld(static_cast<LD>(r.distance), o, static_cast<LD>(tol<T>(16, scale))));
    EXPECT_TRUE(locus_test::vec_near(point_at(e, r.param_b), r.closest[1], tol<T>(32, scale)));
    worst =
        std::max(worst, std::fabs(static_cast<LD>(r.distance) - o) / (LD(eps_v<T>) * LD(scale)));
  }
  std::printf("point-ellipse: max |distance - oracle| = %.2f eps * scale\n",
              static_cast<double>(worst));
}

TYPED_TEST(PointEllipseTest, LongDoubleOracle3D) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  LD worst = 0;
  for (int n = 0; n < 60 / kCaseScale; ++n) {
    Ellipsoid3<T> e = random_ellipsoid<T>(rng, T(4), false);
    if (n % 3 == 1) e.extent.z = e.extent.x * T(1e-3);
    const T s = std::max({e.extent.x, e.extent.y, e.extent.z});
    const Vec3<T> p = n % 2 == 0 ? e.center + rng.vec<T, 3>(-T(0.8) * s, T(0.8) * s)
                                 : rng.vec<T, 3>(-T(12), T(12));
    SCOPED_TRACE("case " + std::to_string(n));
    const auto r = distance(p, e);
    const LD o = oracle_ellipsoid(p, e);
    const T scale = std::max({T(1), s, max_abs(p), max_abs(e.center)});
    EXPECT_TRUE(near_ld(static_cast<LD>(r.distance), o, static_cast<LD>(tol<T>(16, scale))));
    EXPECT_TRUE(locus_test::vec_near(point_at(e, r.param_b), r.closest[1], tol<T>(32, scale)));
    worst =
        std::max(worst, std::fabs(static_cast<LD>(r.distance) - o) / (LD(eps_v<T>) * LD(scale)));
  }
  std::printf("point-ellipsoid: max |distance - oracle| = %.2f eps * scale\n",
              static_cast<double>(worst));
}

// Figure 6.14: the closest point X of the ellipse to P satisfies P - X parallel to the normal
// grad Q(X); on the axes the answer has a closed form (the classic failure of the quartic).
TYPED_TEST(PointEllipseTest, Figure6_14AndAxes) {
  using T = TypeParam;
  const T a = 5, b = 3;
  const Ellipse2<T> e{{T(1), T(-2)}, {{T(1), T(0)}, {T(0), T(1)}}, {a, b}};
  // Generic point: the residual is normal to the curve.
  const Vec2<T> p{T(8), T(4)};
  const auto r = distance(p, e);
  const Vec2<T> x = r.closest[1] - e.center;
  const Vec2<T> grad{x.x / (a * a), x.y / (b * b)};
  EXPECT_NEAR(perp_dot(p - r.closest[1], grad) / (length(p - r.closest[1]) * length(grad)), T(0),
              tol<T>(64));
  EXPECT_NEAR(evaluate(e, r.closest[1]), T(0), tol<T>(16));
  EXPECT_TRUE(r.unique);
  // On the minor axis, outside and inside: the co-vertex.
  EXPECT_NEAR(distance(e.center + Vec2<T>{T(0), T(7)}, e).distance, T(4), tol<T>(16, T(8)));
  EXPECT_NEAR(distance(e.center + Vec2<T>{T(0), T(-1)}, e).distance, T(2), tol<T>(16, T(8)));
  // On the major axis near the centre: two symmetric closest points
  // x0 = a^2 y0 / (a^2 - b^2), d^2 = (x0 - y0)^2 + b^2 (1 - (x0/a)^2).
  for (const T y0 : {T(0), T(0.5), T(1.5), T(-2.5)}) {
    const auto c = distance(e.center + Vec2<T>{y0, T(0)}, e);
    const T x0 = a * a * y0 / (a * a - b * b);
    const T want = std::sqrt((x0 - y0) * (x0 - y0) + b * b * (T(1) - (x0 / a) * (x0 / a)));
    EXPECT_NEAR(c.distance, want, tol<T>(16, T(8))) << y0;
    EXPECT_FALSE(c.unique) << y0;
    EXPECT_NEAR(c.closest[1].x - e.center.x, x0, tol<T>(16, T(8)));
  }
  // On the major axis beyond the evolute's cusp (a^2 - b^2) / a = 3.2: the vertex.
  const auto v = distance(e.center + Vec2<T>{T(3.5), T(0)}, e);
  EXPECT_NEAR(v.distance, T(1.5), tol<T>(16, T(8)));
  EXPECT_TRUE(v.unique);
  EXPECT_NEAR(v.param_b, T(0), tol<T>(16));
  // Continuity across the major axis: a point an ulp-ish above it gets the same distance.
  const auto above = distance(e.center + Vec2<T>{T(1.5), T(1e-6)}, e);
  const auto on = distance(e.center + Vec2<T>{T(1.5), T(0)}, e);
  EXPECT_NEAR(above.distance, on.distance, T(1e-5));
  EXPECT_TRUE(above.unique);
  // A hair off the major axis (the classic failure: x1 = y1 / (s + 1) with s + 1 rounded): the
  // same distance as on the axis, for offsets down to the smallest normal numbers.
  for (const T off :
       {T(1e-3) * eps_v<T>, eps_v<T>, std::numeric_limits<T>::min() * T(16), T(1e-30)}) {
    const auto hair = distance(e.center + Vec2<T>{T(1.5), off}, e);
    EXPECT_NEAR(hair.distance, on.distance, tol<T>(16, T(8))) << off;
    const auto hair3 = distance(
        Vec3<T>{T(1), off, off},
        Ellipsoid3<T>{
            {}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}, {T(4), T(3), T(2)}});
    const T x0 = T(16) / T(12);  // a^2 y0 / (a^2 - c^2), y0 = 1
    EXPECT_NEAR(hair3.distance, std::sqrt(sqr(x0 - T(1)) + T(4) * (T(1) - sqr(x0 / T(4)))),
                tol<T>(16, T(8)))
        << off;
  }
  // On the curve: distance 0 (to rounding) and the same point.
  const Vec2<T> onc = point_at(e, T(0.7));
  EXPECT_NEAR(distance(onc, e).distance, T(0), tol<T>(16, T(8)));
  // A rotated ellipse and a point on its (rotated) minor axis.
  const Vec2<T> u = normalize(Vec2<T>{T(3), T(4)});
  const Ellipse2<T> er{{}, {u, perp(u)}, {a, b}};
  EXPECT_NEAR(distance(T(10) * perp(u), er).distance, T(7), tol<T>(32, T(10)));
  EXPECT_NEAR(distance(T(2) * u, er).distance,
              std::sqrt(sqr(T(50) / T(16) - T(2)) + b * b * (T(1) - sqr(T(50) / T(16) / a))),
              tol<T>(32, T(10)));
}

TYPED_TEST(PointEllipseTest, CirclesAndCentres) {
  using T = TypeParam;
  const Ellipse2<T> c{{T(1), T(1)}, {{T(1), T(0)}, {T(0), T(1)}}, {T(2), T(2)}};
  const auto ctr = distance(c.center, c);
  EXPECT_EQ(ctr.distance, T(2));
  EXPECT_FALSE(ctr.unique);
  const auto gen = distance(Vec2<T>{T(4), T(5)}, c);
  EXPECT_NEAR(gen.distance, T(3), tol<T>(16, T(5)));
  EXPECT_TRUE(gen.unique);
  EXPECT_NEAR(gen.param_b, std::atan2(T(4), T(3)), tol<T>(16));
  // Ellipsoid centre, spheroid axis, sphere centre.
  const Ellipsoid3<T> el{
      {}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}, {T(4), T(3), T(2)}};
  const auto ec = distance(Vec3<T>{}, el);
  EXPECT_EQ(ec.distance, T(2));
  EXPECT_FALSE(ec.unique);
  EXPECT_NEAR(ec.param_b.y, T(0), tol<T>(8));
  // On the longest axis, inside: the closest points form a symmetric pair off the axis; the
  // closed form x0 = a^2 y0 / (a^2 - c^2), d^2 = (x0 - y0)^2 + c^2 (1 - (x0/a)^2).
  const T y0 = T(1);
  const T x0 = T(16) * y0 / (T(16) - T(4));
  const auto on_axis = distance(Vec3<T>{y0, T(0), T(0)}, el);
  EXPECT_NEAR(on_axis.distance, std::sqrt(sqr(x0 - y0) + T(4) * (T(1) - sqr(x0 / T(4)))),
              tol<T>(16, T(4)));
  EXPECT_FALSE(on_axis.unique);
  // Outside on each axis: the vertex.
  EXPECT_NEAR(distance(Vec3<T>{T(0), T(0), T(7)}, el).distance, T(5), tol<T>(16, T(8)));
  EXPECT_NEAR(distance(Vec3<T>{T(0), T(-9), T(0)}, el).distance, T(6), tol<T>(16, T(8)));
  EXPECT_NEAR(distance(Vec3<T>{T(-5), T(0), T(0)}, el).distance, T(1), tol<T>(16, T(8)));
  // Points on the coordinate planes agree with the oracle.
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 30; ++n) {
    Vec3<T> p = rng.vec<T, 3>(T(-6), T(6));
    p[n % 3] = T(0);
    if (n % 5 == 0) p[(n + 1) % 3] = T(0);
    const auto r = distance(p, el);
    EXPECT_TRUE(near_ld(static_cast<LD>(r.distance), oracle_ellipsoid(p, el),
                        static_cast<LD>(tol<T>(16, T(8)))));
  }
  // Prolate spheroid: a point on its axis inside has a ring of closest points.
  const Ellipsoid3<T> pr{{}, {el.axis[0], el.axis[1], el.axis[2]}, {T(4), T(2), T(2)}};
  EXPECT_FALSE(distance(Vec3<T>{T(0.5), T(0), T(0)}, pr).unique);
  const Ellipsoid3<T> sp{{}, {el.axis[0], el.axis[1], el.axis[2]}, {T(2), T(2), T(2)}};
  EXPECT_FALSE(distance(Vec3<T>{}, sp).unique);
  EXPECT_EQ(distance(Vec3<T>{}, sp).distance, T(2));
}

TYPED_TEST(PointEllipseTest, NearDegenerateAndDegenerate) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // Ratio 1e-6 (and 1e-9 for double): agree with the long double oracle.
  for (const T ratio : {T(1e-6), std::is_same_v<T, double> ? T(1e-9) : T(1e-7)}) {
    const Ellipse2<T> e{{}, {{T(1), T(0)}, {T(0), T(1)}}, {T(3), T(3) * ratio}};
    for (int n = 0; n < 50; ++n) {
      const Vec2<T> p =
          n % 2 ? rng.vec<T, 2>(T(-4), T(4))
                : Vec2<T>{rng.uniform<T>(T(-3), T(3)), rng.uniform<T>(-T(1e-5), T(1e-5))};
      EXPECT_TRUE(near_ld(static_cast<LD>(distance(p, e).distance), oracle_ellipse(p, e),
                          static_cast<LD>(tol<T>(16, T(4)))));
    }
  }
  // Zero extents: the segment [-e0, e0], then the point.
  const Ellipse2<T> flat{{T(1), T(0)}, {{T(1), T(0)}, {T(0), T(1)}}, {T(2), T(0)}};
  EXPECT_NEAR(distance(Vec2<T>{T(2), T(3)}, flat).distance, T(3), tol<T>(8, T(4)));
  EXPECT_NEAR(distance(Vec2<T>{T(7), T(0)}, flat).distance, T(4), tol<T>(8, T(8)));
  EXPECT_TRUE(locus_test::vec_near(point_at(flat, distance(Vec2<T>{T(2), T(3)}, flat).param_b),
                                   Vec2<T>{T(2), T(0)}, tol<T>(8, T(4))));
  const Ellipse2<T> flat1{{}, {{T(1), T(0)}, {T(0), T(1)}}, {T(0), T(2)}};
  const auto f1 = distance(Vec2<T>{T(3), T(1)}, flat1);
  EXPECT_NEAR(f1.distance, T(3), tol<T>(8, T(4)));
  EXPECT_TRUE(locus_test::vec_near(point_at(flat1, f1.param_b), f1.closest[1], tol<T>(8, T(4))));
  const Ellipse2<T> dot{{T(1), T(1)}, {{T(1), T(0)}, {T(0), T(1)}}, {T(0), T(0)}};
  EXPECT_EQ(distance(Vec2<T>{T(4), T(5)}, dot).distance, T(5));
  // Flat ellipsoid: the filled ellipse; segment; point.
  const Ellipsoid3<T> disk{
      {}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}, {T(4), T(2), T(0)}};
  const auto above = distance(Vec3<T>{T(1), T(1), T(3)}, disk);
  EXPECT_NEAR(above.distance, T(3), tol<T>(8, T(4)));
  EXPECT_TRUE(
      locus_test::vec_near(point_at(disk, above.param_b), above.closest[1], tol<T>(16, T(4))));
  EXPECT_NEAR(distance(Vec3<T>{T(7), T(0), T(4)}, disk).distance, T(5), tol<T>(8, T(8)));
  const Ellipsoid3<T> stick{{}, {disk.axis[0], disk.axis[1], disk.axis[2]}, {T(0), T(3), T(0)}};
  const auto st = distance(Vec3<T>{T(4), T(5), T(0)}, stick);
  EXPECT_NEAR(st.distance, std::sqrt(T(20)), tol<T>(8, T(8)));
  EXPECT_TRUE(locus_test::vec_near(point_at(stick, st.param_b), st.closest[1], tol<T>(16, T(4))));
  const Ellipsoid3<T> pt{
      {T(1), T(1), T(1)}, {disk.axis[0], disk.axis[1], disk.axis[2]}, {T(0), T(0), T(0)}};
  EXPECT_NEAR(distance(Vec3<T>{T(1), T(4), T(5)}, pt).distance, T(5), tol<T>(8, T(8)));
}

TYPED_TEST(PointEllipseTest, BadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Ellipse2<T> e{{}, {{T(1), T(0)}, {T(0), T(1)}}, {T(2), T(1)}};
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{nan, T(0)}, e)));
  EXPECT_TRUE(dist::is_nan_result(distance(e, Vec2<T>{inf, T(0)})));
  Ellipse2<T> bad = e;
  bad.extent[1] = T(-1);
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{}, bad)));
  bad = e;
  bad.axis[0].x = nan;
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{}, bad)));
  bad = e;
  bad.extent[0] = inf;
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{}, bad)));
  const Ellipsoid3<T> el{
      {}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}, {T(4), T(2), T(1)}};
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{T(0), nan, T(0)}, el)));
  Ellipsoid3<T> bel = el;
  bel.extent.z = T(-2);
  EXPECT_TRUE(dist::is_nan_result(distance(bel, Vec3<T>{})));
  bel = el;
  bel.center.y = inf;
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, bel)));
  // Huge and tiny coordinates: no overflow in the bracket.
  const Ellipse2<T> big{{}, {{T(1), T(0)}, {T(0), T(1)}}, {T(1e15), T(1e14)}};
  EXPECT_NEAR(distance(Vec2<T>{T(0), T(3e14)}, big).distance, T(2e14), tol<T>(16, T(3e14)));
  const Ellipse2<T> tiny{{}, {{T(1), T(0)}, {T(0), T(1)}}, {T(1e-15), T(1e-16)}};
  EXPECT_NEAR(distance(Vec2<T>{T(0), T(3e-16)}, tiny).distance, T(2e-16), tol<T>(16, T(3e-16)));
}
