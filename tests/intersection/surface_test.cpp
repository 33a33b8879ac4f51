// SPDX-License-Identifier: BSL-1.0
// Rows int3.linear-surface, int3.plane-surface, int3.surface-surface: lines, rays and segments
// against Bézier, B-spline and NURBS surfaces; planes and surfaces against surfaces. Oracles:
// for height-field patches (x = u, y = v exactly) the hits of a line are the roots of the 1D
// function z(t) - h(x(t), y(t)), bracketed on a dense grid and bisected in long double (an
// independent algorithm); lines built through a chosen surface point (the hit is known); a NURBS
// sphere against the analytic sphere (line_sphere.hpp). Every hit is checked by its residuals
// (on the line, S(uv) = point). Plane and surface curves: every point on both arguments, and
// the topology (closed loop / open branches) of cases with known answers; their Hermite form
// (the O(h^4) rate against the step, tangents against central differences). Degenerate, NaN,
// power-of-two scaling and translation.

#include <locus/intersection/line_sphere.hpp>
#include <locus/intersection/line_surface.hpp>
#include <locus/intersection/plane_surface.hpp>
#include <locus/intersection/ray_surface.hpp>
#include <locus/intersection/segment_surface.hpp>
#include <locus/intersection/surface_surface.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;
using LD = long double;

/// A tolerance for float or for double.
template <class T>
constexpr double pick(double for_float, double for_double) {
  return std::is_same_v<T, float> ? for_float : for_double;
}

template <class T>
class SurfaceHits : public ::testing::Test {};
TYPED_TEST_SUITE(SurfaceHits, locus_test::RealTypes);

/// A bicubic height field over [0, 1]^2: x = u and y = v exactly (uniformly spaced control
/// abscissae), z random in [-h, h].
template <class T>
BezierPatch<T, 3> random_height_patch(Rng& rng, T h) {
  BezierPatch<T, 3> p{4, 4, {}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      p.control.push_back({T(i) / T(3), T(j) / T(3), rng.uniform<T>(-h, h)});
  return p;
}

/// The height of the patch at (x, y) in long double (de Casteljau on the z values).
template <class T>
LD height(const BezierPatch<T, 3>& p, LD x, LD y) {
  LD row[4];
  for (int i = 0; i < 4; ++i) {
    LD b[4];
    for (int j = 0; j < 4; ++j) b[j] = LD(p.control[static_cast<std::size_t>(i * 4 + j)].z);
    for (int r = 1; r < 4; ++r)
      for (int k = 0; k < 4 - r; ++k) b[k] = (1 - y) * b[k] + y * b[k + 1];
    row[i] = b[0];
  }
  for (int r = 1; r < 4; ++r)
    for (int k = 0; k < 4 - r; ++k) row[k] = (1 - x) * row[k] + x * row[k + 1];
  return row[0];
}

/// Oracle: roots of z(t) - h(x(t), y(t)) for t where (x, y) is in the unit square.
template <class T>
std::vector<double> oracle_hits(const BezierPatch<T, 3>& p, const Vec3<double>& o,
                                const Vec3<double>& d, double t0, double t1) {
  const auto f = [&](LD t) -> LD {
    const LD x = LD(o.x) + t * LD(d.x), y = LD(o.y) + t * LD(d.y), zz = LD(o.z) + t * LD(d.z);
    return zz - height(p, x, y);
  };
  const auto inside = [&](LD t) {
    const LD x = LD(o.x) + t * LD(d.x), y = LD(o.y) + t * LD(d.y);
    return x >= 0 && x <= 1 && y >= 0 && y <= 1;
  };
  std::vector<double> out;
  const int grid = 2000;
  LD prev_t = t0, prev = f(prev_t);
  for (int i = 1; i <= grid; ++i) {
    const LD t = LD(t0) + (LD(t1) - LD(t0)) * i / grid;
    const LD cur = f(t);
    if ((prev < 0) != (cur < 0)) {
      LD lo = prev_t, hi = t;
      for (int k = 0; k < 80; ++k) {
        const LD mid = (lo + hi) / 2;
        ((f(mid) < 0) == (prev < 0) ? lo : hi) = mid;
      }
      if (inside(lo)) out.push_back(double(lo));
    }
    prev_t = t;
    prev = cur;
  }
  return out;
}

template <class T, class Hit>
void expect_residuals(const BezierPatch<T, 3>& p, const Vec3<T>& o, const Vec3<T>& d, const Hit& h,
                      const std::string& trace) {
  const double tol = pick<T>(2e-5, 1e-9);
  const Vec3<double> on_line = vec_cast<double>(o) + double(h.t) * vec_cast<double>(d);
  EXPECT_LE(max_abs(on_line - vec_cast<double>(h.point)), tol) << trace;
  const Vec3<T> s = point_at(p, h.uv.x, h.uv.y);
  EXPECT_LE(max_abs(vec_cast<double>(s) - vec_cast<double>(h.point)), tol) << trace;
}

TYPED_TEST(SurfaceHits, RandomHeightPatchesMatchTheOracle) {
  using T = TypeParam;
  Rng rng;
  int total = 0;
  for (int iter = 0; iter < 40; ++iter) {
    const BezierPatch<T, 3> p = random_height_patch<T>(rng, T(0.6));
    // A steep-ish line through the square, several crossings possible.
    const Vec3<T> o{rng.uniform<T>(-0.2f, 1.2f), rng.uniform<T>(-0.2f, 1.2f), T(-1)};
    const Vec3<T> e{rng.uniform<T>(-0.2f, 1.2f), rng.uniform<T>(-0.2f, 1.2f), T(1)};
    const Vec3<T> d = e - o;
    const auto r = intersection(Line3<T>{o, d}, p);
    ASSERT_EQ(r.status, Status::ok) << rng.trace();
    const auto ref = oracle_hits(p, vec_cast<double>(o), vec_cast<double>(d), -0.5, 1.5);
    // The oracle finds sign changes only: tangencies are excluded by the random draw.
    ASSERT_EQ(r.hits.size(), ref.size()) << rng.trace() << " iter " << iter;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      EXPECT_NEAR(double(r.hits[i].t), ref[i], pick<T>(1e-4, 1e-9)) << rng.trace();
      expect_residuals(p, o, d, r.hits[i], rng.trace());
    }
    total += static_cast<int>(ref.size());
  }
  EXPECT_GT(total, 25);
}

TYPED_TEST(SurfaceHits, LineThroughAKnownSurfacePoint) {
  using T = TypeParam;
  Rng rng(7);
  for (int iter = 0; iter < 40; ++iter) {
    BezierPatch<T, 3> p{4, 3, {}};
    for (int k = 0; k < 12; ++k) p.control.push_back(rng.vec<T, 3>(T(-1), T(1)));
    const T u = rng.uniform<T>(T(0.05), T(0.95)), v = rng.uniform<T>(T(0.05), T(0.95));
    const Vec3<T> q = point_at(p, u, v);
    const Vec3<T> d = rng.unit<T, 3>();
    const Vec3<T> o = q - T(2) * d;
    const auto r = intersection(Ray3<T>{o, d}, p);
    ASSERT_EQ(r.status, Status::ok);
    bool found = false;
    for (const auto& h : r.hits) {
      expect_residuals(p, o, d, h, rng.trace());
      if (max_abs(vec_cast<double>(h.point) - vec_cast<double>(q)) < pick<T>(1e-4, 1e-9))
        found = true;
    }
    // The known hit is found unless the line is nearly tangent there (then the point is
    // ill-conditioned along the line; skip those draws).
    const Vec3<T> n = normal_at(p, u, v);
    if (std::fabs(double(dot(n, d))) > 0.05) {
      EXPECT_TRUE(found) << rng.trace() << " " << iter;
    }
  }
}

TYPED_TEST(SurfaceHits, RaysAndSegmentsKeepTheirRange) {
  using T = TypeParam;
  Rng rng(11);
  for (int iter = 0; iter < 30; ++iter) {
    const BezierPatch<T, 3> p = random_height_patch<T>(rng, T(0.5));
    const Vec3<T> o{rng.uniform<T>(0.1f, 0.9f), rng.uniform<T>(0.1f, 0.9f), T(-1)};
    const Vec3<T> e{rng.uniform<T>(0.1f, 0.9f), rng.uniform<T>(0.1f, 0.9f), T(1)};
    const auto all = intersection(Line3<T>{o, e - o}, p);
    const auto ray = intersection(Ray3<T>{o + T(0.5) * (e - o), e - o}, p);
    const auto seg = intersection(Segment3<T>{o, o + T(0.5) * (e - o)}, p);
    // The line's hits split at t = 0.5 between the segment (first half) and the ray.
    std::size_t before = 0;
    for (const auto& h : all.hits) before += h.t < T(0.5) ? 1 : 0;
    EXPECT_EQ(seg.hits.size(), before) << rng.trace();
    EXPECT_EQ(ray.hits.size(), all.hits.size() - before) << rng.trace();
    for (const auto& h : seg.hits) {
      EXPECT_GE(h.t, T(0));
      EXPECT_LE(h.t, T(1));
    }
    for (const auto& h : ray.hits) EXPECT_GE(h.t, T(0));
  }
}

/// The unit sphere as a NURBS surface: a half circle (meridian) times a full circle.
template <class T>
NurbsSurface<T, 3> nurbs_sphere() {
  const T h = T(std::sqrt(0.5));
  const Vec2<T> m[5] = {{0, 1}, {1, 1}, {1, 0}, {1, -1}, {0, -1}};
  const T wm[5] = {1, h, 1, h, 1};
  const Vec2<T> c[9] = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                        {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  const T wc[9] = {1, h, 1, h, 1, h, 1, h, 1};
  NurbsSurface<T, 3> s{2,
                       2,
                       5,
                       9,
                       {},
                       {},
                       {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                       {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 9; ++j) {
      s.control.push_back({m[i].x * c[j].x, m[i].x * c[j].y, m[i].y});
      s.weights.push_back(wm[i] * wc[j]);
    }
  return s;
}

TYPED_TEST(SurfaceHits, NurbsSphereAgreesWithTheAnalyticSphere) {
  using T = TypeParam;
  Rng rng(3);
  const NurbsSurface<T, 3> s = nurbs_sphere<T>();
  const double tol = pick<T>(1e-4, 1e-9);
  for (int iter = 0; iter < 40; ++iter) {
    const Vec3<T> o = rng.vec<T, 3>(T(-3), T(3));
    const Vec3<T> target = rng.vec<T, 3>(T(-1.2), T(1.2));
    const Line3<T> l{o, target - o};
    const auto r = intersection(l, s);
    const auto ref = intersection(l, Sphere3<T>{{0, 0, 0}, T(1)});
    ASSERT_EQ(r.status, Status::ok);
    if (ref.kind == Kind::point) continue;  // tangency: not drawn in practice
    ASSERT_EQ(int(r.hits.size()), ref.count) << rng.trace() << " " << iter;
    for (int i = 0; i < ref.count; ++i) {
      const auto& h = r.hits[static_cast<std::size_t>(i)];
      EXPECT_NEAR(double(h.t), double(ref.param_a[static_cast<std::size_t>(i)]), tol);
      EXPECT_NEAR(double(length(h.point)), 1.0, tol);
      // The normal is the outward radial direction (the parametrisation is outward here or
      // inward: compare up to sign).
      EXPECT_NEAR(std::fabs(double(dot(h.normal, normalize(h.point)))), 1.0, 1e-3);
    }
  }
  // Tangent: a line touching the sphere at (0, 0, 1)... on a pole the normal is the limit normal;
  // use a point on the equator instead.
  const auto tan = intersection(Line3<T>{{1, -2, 0}, {0, 1, 0}}, s);
  // (In float the weight sqrt(1/2) is rounded: the surface is off the sphere by ~1e-8 and the
  // line may cross it twice within that distance; both hits are then flagged tangent.)
  ASSERT_GE(tan.hits.size(), 1u);
  ASSERT_LE(tan.hits.size(), (std::is_same_v<T, float> ? 2u : 1u));
  EXPECT_TRUE(tan.hits[0].tangent);
  EXPECT_NEAR(double(tan.hits[0].point.x), 1.0, tol);
  EXPECT_NEAR(double(tan.hits[0].t), 2.0, pick<T>(1e-3, 1e-6));
}

TYPED_TEST(SurfaceHits, DegenerateAndNonFinite) {
  using T = TypeParam;
  Rng rng(5);
  const BezierPatch<T, 3> p = random_height_patch<T>(rng, T(0.5));
  // Missing the patch.
  const auto miss = intersection(Line3<T>{{5, 5, 0}, {0, 0, 1}}, p);
  EXPECT_EQ(miss.status, Status::ok);
  EXPECT_TRUE(miss.hits.empty());
  EXPECT_FALSE(intersects(Line3<T>{{5, 5, 0}, {0, 0, 1}}, p));
  // A line in a planar patch.
  BezierPatch<T, 3> flat{2, 2, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}}};
  const auto in = intersection(Line3<T>{{T(0.5), T(-1), 0}, {0, 1, 0}}, flat);
  EXPECT_EQ(in.status, Status::ok);
  EXPECT_TRUE(in.on_surface);
  EXPECT_TRUE(in.hits.empty());
  EXPECT_TRUE(intersects(Line3<T>{{T(0.5), T(-1), 0}, {0, 1, 0}}, flat));
  EXPECT_TRUE(intersects(flat, Segment3<T>{{T(0.5), T(0.5), 1}, {T(0.5), T(0.5), -1}}));
  EXPECT_FALSE(intersects(flat, Ray3<T>{{T(0.5), T(0.5), 1}, {0, 0, 1}}));
  // A line on a curved (ruled) surface: the saddle z = x y contains x = 1/2.
  const BezierPatch<T, 3> saddle{2, 2, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}}};
  const auto ruling = intersection(Line3<T>{{T(0.5), -1, T(-0.5)}, {0, 1, T(0.5)}}, saddle);
  EXPECT_TRUE(ruling.on_surface);
  EXPECT_TRUE(ruling.hits.empty());
  const auto off = intersection(Line3<T>{{T(0.5), -1, T(-0.25)}, {0, 1, T(0.5)}}, saddle);
  EXPECT_FALSE(off.on_surface);
  EXPECT_TRUE(off.hits.empty());
  // Crossing the planar patch.
  const auto cross = intersection(Line3<T>{{T(0.25), T(0.5), 1}, {0, 0, -2}}, flat);
  ASSERT_EQ(cross.hits.size(), 1u);
  EXPECT_FALSE(cross.on_surface);
  EXPECT_NEAR(double(cross.hits[0].t), 0.5, 1e-6);
  EXPECT_NEAR(double(cross.hits[0].uv.x), 0.25, 1e-6);
  EXPECT_NEAR(double(cross.hits[0].uv.y), 0.5, 1e-6);
  // Non-finite and zero direction.
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(intersection(Line3<T>{{nan, 0, 0}, {0, 0, 1}}, p).status, Status::non_finite_input);
  EXPECT_EQ(intersection(Line3<T>{{0, 0, 0}, {0, 0, 0}}, p).status, Status::degenerate_input);
  BezierPatch<T, 3> bad = p;
  bad.control[3].z = nan;
  EXPECT_EQ(intersection(Line3<T>{{0, 0, 0}, {0, 0, 1}}, bad).status, Status::non_finite_input);
  bad.control.pop_back();
  EXPECT_NE(intersection(Line3<T>{{0, 0, 0}, {0, 0, 1}}, bad).status, Status::ok);
}

TYPED_TEST(SurfaceHits, PowerOfTwoScalingAndTranslation) {
  using T = TypeParam;
  Rng rng(9);
  for (int iter = 0; iter < 20; ++iter) {
    const BezierPatch<T, 3> p = random_height_patch<T>(rng, T(0.5));
    const Vec3<T> o{rng.uniform<T>(0.1f, 0.9f), rng.uniform<T>(0.1f, 0.9f), T(-1)};
    const Vec3<T> d = Vec3<T>{rng.uniform<T>(0.1f, 0.9f), rng.uniform<T>(0.1f, 0.9f), T(1)} - o;
    const auto r = intersection(Line3<T>{o, d}, p);
    for (T sc : {T(0x1p-20), T(0x1p20)}) {
      BezierPatch<T, 3> q = p;
      for (auto& c : q.control) c = sc * c;
      const auto rs = intersection(Line3<T>{sc * o, d}, q);
      ASSERT_EQ(rs.hits.size(), r.hits.size()) << rng.trace();
      for (std::size_t i = 0; i < r.hits.size(); ++i) {
        EXPECT_NEAR(double(rs.hits[i].t), double(sc) * double(r.hits[i].t),
                    double(sc) * pick<T>(1e-6, 1e-12));
        EXPECT_NEAR(double(rs.hits[i].uv.x), double(r.hits[i].uv.x), pick<T>(1e-6, 1e-12));
      }
    }
    // A rotation permuting the axes (exact): the same hits.
    BezierPatch<T, 3> rot = p;
    for (auto& c : rot.control) c = Vec3<T>{c.y, c.z, c.x};
    const auto rr = intersection(Line3<T>{{o.y, o.z, o.x}, {d.y, d.z, d.x}}, rot);
    ASSERT_EQ(rr.hits.size(), r.hits.size()) << rng.trace();
    for (std::size_t i = 0; i < r.hits.size(); ++i) {
      EXPECT_NEAR(double(rr.hits[i].t), double(r.hits[i].t), pick<T>(1e-6, 1e-12));
      EXPECT_NEAR(double(rr.hits[i].uv.y), double(r.hits[i].uv.y), pick<T>(1e-6, 1e-12));
      EXPECT_NEAR(double(rr.hits[i].normal.x), double(r.hits[i].normal.y), pick<T>(1e-5, 1e-10));
    }
    // A translation (rounded in T: compared within the conditioning of the hits).
    BezierPatch<T, 3> q = p;
    const Vec3<T> shift{T(3), T(-2), T(5)};
    for (auto& c : q.control) c = c + shift;
    const auto rt = intersection(Line3<T>{o + shift, d}, q);
    ASSERT_EQ(rt.hits.size(), r.hits.size()) << rng.trace();
    for (std::size_t i = 0; i < r.hits.size(); ++i)
      EXPECT_NEAR(double(rt.hits[i].t), double(r.hits[i].t), pick<T>(1e-4, 1e-10));
  }
}

TYPED_TEST(SurfaceHits, BSplineSurfaceAgreesWithItsBezierPieces) {
  using T = TypeParam;
  Rng rng(13);
  // A bicubic B-spline height field 5 x 5 with clamped uniform knots.
  BSplineSurface<T, 3> s{
      3, 3, 5, 5, {}, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      s.control.push_back({T(i) / T(4), T(j) / T(4), rng.uniform<T>(T(-0.4), T(0.4))});
  for (int iter = 0; iter < 20; ++iter) {
    const Vec3<T> o{rng.uniform<T>(0.05f, 0.95f), rng.uniform<T>(0.05f, 0.95f), T(-1)};
    const Vec3<T> e{rng.uniform<T>(0.05f, 0.95f), rng.uniform<T>(0.05f, 0.95f), T(1)};
    const auto r = intersection(Segment3<T>{o, e}, s);
    ASSERT_EQ(r.status, Status::ok);
    int oracle = 0;
    const auto g = to_bezier(s);
    for (const auto& h : r.hits) {
      const Vec3<T> q = point_at(s, h.uv.x, h.uv.y);
      EXPECT_LE(max_abs(vec_cast<double>(q) - vec_cast<double>(h.point)), pick<T>(1e-4, 1e-9));
    }
    // Count oracle: the hits of each Bézier piece (x, y span a sub-square), merged at seams.
    std::vector<double> ts;
    for (const auto& piece : g.patches) {
      for (const auto& h : intersection(Segment3<T>{o, e}, piece).hits) {
        bool dup = false;
        for (double t : ts) dup = dup || std::fabs(t - double(h.t)) < 1e-5;
        if (!dup) ts.push_back(double(h.t));
      }
    }
    oracle = static_cast<int>(ts.size());
    EXPECT_EQ(int(r.hits.size()), oracle) << rng.trace();
  }
}

// ---- plane against surface ----

/// z = x^2 + y^2 over [-1, 1]^2 as a biquadratic Bézier patch (exact).
template <class T>
BezierPatch<T, 3> bowl(T sign = T(1), T lift = T(0)) {
  const T a[3] = {1, -1, 1};
  BezierPatch<T, 3> p{3, 3, {}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      p.control.push_back({T(i - 1), T(j - 1), lift + sign * (a[i] + a[j])});
  return p;
}

TYPED_TEST(SurfaceHits, PlaneCutsABowlInOneLoop) {
  using T = TypeParam;
  const auto r = intersection(Plane3<T>{{0, 0, 1}, T(0.5)}, bowl<T>());
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_GE(r.curves[0].points.size(), 16u);
  const double tol = pick<T>(1e-5, 1e-12);
  for (std::size_t i = 0; i < r.curves[0].points.size(); ++i) {
    const auto& p = r.curves[0].points[i];
    EXPECT_NEAR(double(p.z), 0.5, tol);
    EXPECT_NEAR(double(p.x * p.x + p.y * p.y), 0.5, 4 * tol);
    const auto& uv = r.curves[0].param_b[i];
    EXPECT_LE(max_abs(vec_cast<double>(point_at(bowl<T>(), uv.x, uv.y)) - vec_cast<double>(p)),
              4 * tol);
  }
  EXPECT_TRUE(r.curves[0].param_a.empty());
  // Higher: the circle leaves the square: four open arcs near the corners.
  const auto four = intersection(Plane3<T>{{0, 0, 1}, T(1.5)}, bowl<T>());
  ASSERT_EQ(four.curves.size(), 4u);
  for (const auto& c : four.curves) EXPECT_FALSE(c.closed);
  // Below the bottom: nothing; swapped arguments move the parameters to param_a.
  EXPECT_TRUE(intersection(Plane3<T>{{0, 0, 1}, T(-0.5)}, bowl<T>()).curves.empty());
  const auto sw = intersection(bowl<T>(), Plane3<T>{{0, 0, 2}, T(1)});
  ASSERT_EQ(sw.curves.size(), 1u);
  EXPECT_FALSE(sw.curves[0].param_a.empty());
  // Bad input.
  EXPECT_EQ(intersection(Plane3<T>{{0, 0, 0}, T(1)}, bowl<T>()).status, Status::degenerate_input);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(intersection(Plane3<T>{{0, nan, 1}, T(1)}, bowl<T>()).status, Status::non_finite_input);
}

TYPED_TEST(SurfaceHits, PlaneFindsALoopInsideOneCell) {
  using T = TypeParam;
  // The dome z = 2 - x^2 - y^2 cut just below its top: a loop of radius 0.1 inside the centre
  // cell of a 3 x 3 grid (no node sees it): the hull check refines the grid until it does.
  SurfaceCurveOptions opt;
  opt.grid = 3;
  const auto r = intersection(Plane3<T>{{0, 0, 1}, T(1.99)}, bowl<T>(T(-1), T(2)), opt);
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  for (const auto& p : r.curves[0].points)
    EXPECT_NEAR(double(p.x * p.x + p.y * p.y), 0.01, pick<T>(1e-5, 1e-12));
}

TYPED_TEST(SurfaceHits, PlaneCutsTheNurbsSphereInACircle) {
  using T = TypeParam;
  const auto s = nurbs_sphere<T>();
  for (T sc : {T(1), T(0x1p-12)}) {
    NurbsSurface<T, 3> q = s;
    for (auto& c : q.control) c = sc * c;
    const auto r = intersection(Plane3<T>{{T(0.3), T(0.2), 1}, sc * T(0.25)}, q);
    ASSERT_EQ(r.status, Status::ok);
    ASSERT_FALSE(r.curves.empty());
    // The seam u = 0 / 1 of the parametrisation cuts the 3D circle into open branches whose end
    // points pair up across the seam.
    std::size_t points = 0;
    const double tol = (pick<T>(1e-5, 1e-12)) * double(sc);
    for (const auto& c : r.curves)
      for (const auto& p : c.points) {
        EXPECT_NEAR(double(length(p)), double(sc), 8 * tol);
        EXPECT_NEAR(double(dot(Vec3<T>{T(0.3), T(0.2), 1}, p)), double(sc) * 0.25, 8 * tol);
        ++points;
      }
    EXPECT_GE(points, 20u);
  }
  // The seam splits the circle into open branches; together they cover it once (no duplicate
  // branch, nothing missing): total chord length within 1% of the circumference.
  const auto z = intersection(Plane3<T>{{0, 0, 1}, T(0.25)}, s);
  double len = 0.0;
  for (const auto& c : z.curves) {
    EXPECT_FALSE(c.closed);
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i)
      len += double(length(c.points[i + 1] - c.points[i]));
  }
  EXPECT_NEAR(len, 2 * M_PI * std::sqrt(1 - 0.0625), 0.01 * 2 * M_PI);
}

TYPED_TEST(SurfaceHits, TangentLinesOnTheBowl) {
  using T = TypeParam;
  // z = x^2 + y^2: the line z = 0 along x touches at the origin (one tangent hit); lifted by
  // 1/64 it crosses twice at x = +-1/8, lowered it misses.
  const auto bowl_patch = bowl<T>();
  const auto touch = intersection(Line3<T>{{-2, 0, 0}, {1, 0, 0}}, bowl_patch);
  ASSERT_EQ(touch.hits.size(), 1u);
  EXPECT_TRUE(touch.hits[0].tangent);
  EXPECT_NEAR(double(touch.hits[0].t), 2.0, pick<T>(1e-3, 1e-5));
  EXPECT_NEAR(double(touch.hits[0].normal.z) * double(touch.hits[0].normal.z), 1.0, 1e-6);
  const auto two = intersection(Line3<T>{{-2, 0, T(1) / 64}, {1, 0, 0}}, bowl_patch);
  ASSERT_EQ(two.hits.size(), 2u);
  EXPECT_FALSE(two.hits[0].tangent);
  EXPECT_NEAR(double(two.hits[0].t), 2.0 - 0.125, pick<T>(1e-5, 1e-12));
  EXPECT_NEAR(double(two.hits[1].t), 2.0 + 0.125, pick<T>(1e-5, 1e-12));
  EXPECT_TRUE(intersection(Line3<T>{{-2, 0, -T(1) / 64}, {1, 0, 0}}, bowl_patch).hits.empty());
}

// ---- surface against surface ----

TYPED_TEST(SurfaceHits, TwoBowlsMeetInACircle) {
  using T = TypeParam;
  // z = x^2 + y^2 and z = 1 - x^2 - y^2 meet on x^2 + y^2 = 1/2, z = 1/2.
  const auto r = intersection(bowl<T>(), bowl<T>(T(-1), T(1)));
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  const double tol = pick<T>(1e-5, 1e-9);
  for (std::size_t i = 0; i < r.curves[0].points.size(); ++i) {
    const auto& p = r.curves[0].points[i];
    EXPECT_NEAR(double(p.z), 0.5, tol);
    EXPECT_NEAR(double(p.x * p.x + p.y * p.y), 0.5, tol);
    const auto qa = point_at(bowl<T>(), r.curves[0].param_a[i].x, r.curves[0].param_a[i].y);
    const auto qb =
        point_at(bowl<T>(T(-1), T(1)), r.curves[0].param_b[i].x, r.curves[0].param_b[i].y);
    EXPECT_LE(max_abs(vec_cast<double>(qa - qb)), 4 * tol);
  }
}

TYPED_TEST(SurfaceHits, NurbsSphereMeetsAPlanePatchInACircle) {
  using T = TypeParam;
  const NurbsSurface<T, 3> sphere = nurbs_sphere<T>();
  // The plane z = 0.3 as a bilinear NURBS patch (unit weights) over [-2, 2]^2.
  const NurbsSurface<T, 3> plane{
      1,
      1,
      2,
      2,
      {{-2, -2, T(0.3)}, {-2, 2, T(0.3)}, {2, -2, T(0.3)}, {2, 2, T(0.3)}},
      {1, 1, 1, 1},
      {0, 0, 1, 1},
      {0, 0, 1, 1}};
  const auto r = intersection(sphere, plane);
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_FALSE(r.curves.empty());
  double len = 0.0;
  const double tol = pick<T>(1e-5, 1e-9);
  for (const auto& c : r.curves) {
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      EXPECT_NEAR(double(length(c.points[i])), 1.0, tol);
      EXPECT_NEAR(double(c.points[i].z), 0.3, tol);
      if (i + 1 < c.points.size()) len += double(length(c.points[i + 1] - c.points[i]));
    }
    if (c.closed) len += double(length(c.points.front() - c.points.back()));
  }
  // Covered once: the traced pieces add up to the circle (no duplicate, no gap).
  EXPECT_NEAR(len, 2 * M_PI * std::sqrt(1 - 0.09), 0.01 * 2 * M_PI);
}

TYPED_TEST(SurfaceHits, CoincidentSurfacesTerminate) {
  using T = TypeParam;
  // No transversal curve exists (the normals agree everywhere): no curve is claimed, the whole
  // domain is reported coincident.
  const auto r = intersection(bowl<T>(), bowl<T>());
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_TRUE(r.curves.empty());
  EXPECT_TRUE(r.contacts.empty());
  ASSERT_EQ(r.coincident_a.size(), 1u);
  EXPECT_EQ(r.coincident_a[0].lo, (Vec2<T>{0, 0}));
  EXPECT_EQ(r.coincident_a[0].hi, (Vec2<T>{1, 1}));
  // Bad input.
  BezierPatch<T, 3> bad = bowl<T>();
  bad.control.pop_back();
  EXPECT_NE(intersection(bad, bowl<T>()).status, Status::ok);
}

TYPED_TEST(SurfaceHits, MixedSurfaceKinds) {
  using T = TypeParam;
  // The bowl as a Bézier patch against the lid 1 - x^2 - y^2 as a NURBS surface (unit weights):
  // the same circle as two Bézier patches give.
  const BezierPatch<T, 3> lid = bowl<T>(T(-1), T(1));
  const NurbsSurface<T, 3> lid_nurbs{
      2, 2, 3, 3, lid.control, std::vector<T>(9, T(1)), {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}};
  const auto r = intersection(bowl<T>(), lid_nurbs);
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  for (const auto& p : r.curves[0].points) EXPECT_NEAR(double(p.z), 0.5, pick<T>(1e-5, 1e-9));
}

TYPED_TEST(SurfaceHits, BSplineSurfacesMeetInOpenBranches) {
  using T = TypeParam;
  Rng rng(17);
  SurfaceCurveOptions opt;
  opt.grid = 8;
  for (int iter = 0; iter < 2; ++iter) {
    BSplineSurface<T, 3> a{
        3, 3, 5, 5, {}, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}};
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j)
        a.control.push_back({T(i) / T(4), T(j) / T(4), rng.uniform<T>(T(-0.3), T(0.3))});
    // A tilted plane as a B-spline: z = c + 0.2 (x - 0.5): compare with plane-surface.
    const T c = rng.uniform<T>(T(-0.1), T(0.1));
    BSplineSurface<T, 3> b{1, 1, 2, 2, {}, {0, 0, 1, 1}, {0, 0, 1, 1}};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        const T x = T(2 * i) - T(0.5), y = T(2 * j) - T(0.5);
        b.control.push_back({x, y, c + T(0.2) * (x - T(0.5))});
      }
    const auto r = intersection(a, b, opt);
    const auto ref = intersection(Plane3<T>{{T(-0.2), 0, 1}, c - T(0.1)}, a, opt);
    ASSERT_EQ(r.status, Status::ok);
    ASSERT_EQ(r.curves.size(), ref.curves.size()) << rng.trace() << " " << iter;
    const double tol = pick<T>(1e-5, 1e-9);
    for (const auto& cv : r.curves) {
      ASSERT_EQ(cv.points.size(), cv.param_a.size());
      for (std::size_t i = 0; i < cv.points.size(); ++i) {
        const auto& p = cv.points[i];
        EXPECT_NEAR(double(p.z - T(0.2) * p.x), double(c) - 0.1, tol) << rng.trace();
        const auto qa = point_at(a, cv.param_a[i].x, cv.param_a[i].y);
        EXPECT_LE(max_abs(vec_cast<double>(qa - p)), tol);
      }
    }
  }
}

// ---- Hermite interpolation of the plane-surface curves (book section 11.7, 11.54-11.57) ----

/// The largest Hermite errors over every segment of every curve: R(t) off the plane, R(t) off
/// the surface (vertical: x = u, y = v), S(p(t)) off the plane, and the last two divided by the
/// fourth power of the segment's length after subtracting the rounding `noise` (segments longer
/// than 2^-8).
struct HermiteErrors {
  double on_plane = 0, r_off_surface = 0, p_off_plane = 0, r_scaled = 0, p_scaled = 0;
  double r_sum = 0, h4_sum = 0;  // sums over the segments of the error and of h^4
  std::size_t segments = 0;
};
template <class T>
HermiteErrors hermite_errors(const BezierPatch<T, 3>& p, const Plane3<T>& pl, int grid,
                             double noise) {
  SurfaceCurveOptions opt;
  opt.grid = grid;
  const auto r = intersection(pl, p, opt);
  HermiteErrors e;
  EXPECT_EQ(r.status, Status::ok);
  const Vec3<double> n = vec_cast<double>(pl.normal) / length(vec_cast<double>(pl.normal));
  const double k = double(pl.constant) / length(vec_cast<double>(pl.normal));
  for (const auto& c : r.curves) {
    const HermiteSurfaceCurve<T> h = hermite_curve(pl, p, c);
    EXPECT_EQ(h.status, Status::ok);
    EXPECT_EQ(h.tangents.size(), c.points.size());
    for (std::size_t i = 0; i < segment_count(h); ++i) {
      const std::size_t j = (i + 1) % h.points.size();
      const double len = double(length(h.points[j] - h.points[i]));
      const double h4 = len > 0x1p-8 ? std::pow(len, 4.0) : INFINITY;
      ++e.segments;
      double seg_error = 0;
      for (const T t : {T(0.25), T(0.5), T(0.75)}) {
        const HermiteCurvePoint<T> q = point_at(h, i, t);
        const Vec3<double> x = vec_cast<double>(q.point);
        e.on_plane = std::max(e.on_plane, std::fabs(dot(n, x) - k));
        const double off_surface = double(std::fabs(LD(x.z) - height(p, LD(x.x), LD(x.y))));
        e.r_off_surface = std::max(e.r_off_surface, off_surface);
        seg_error = std::max(seg_error, off_surface);
        e.r_scaled = std::max(e.r_scaled, std::max(off_surface - noise, 0.0) / h4);
        const Vec3<double> s = vec_cast<double>(point_at(p, q.param.x, q.param.y));
        const double off_plane = std::fabs(dot(n, s) - k);
        e.p_off_plane = std::max(e.p_off_plane, off_plane);
        e.p_scaled = std::max(e.p_scaled, std::max(off_plane - noise, 0.0) / h4);
      }
      e.r_sum += seg_error;
      e.h4_sum += std::pow(len, 4.0);
    }
  }
  return e;
}

/// A gentle random height patch (|grad h| <= 0.9) and a plane through its centre tilted more
/// steeply (slope 1.5 in a random direction): the curve has no critical point and bounded
/// curvature, so the asymptotic rate shows from coarse grids on.
template <class T>
Plane3<T> gentle_cut(Rng& rng, BezierPatch<T, 3>& p) {
  p = random_height_patch<T>(rng, T(0.15));
  const double phi = rng.uniform(0.0, 2 * std::numbers::pi);
  const Vec3<T> n{T(1.5 * std::cos(phi)), T(1.5 * std::sin(phi)), T(1)};
  return {n, dot(n, point_at(p, T(0.5), T(0.5)))};
}

TYPED_TEST(SurfaceHits, HermiteCurvesConvergeAsTheFourthPowerOfTheStep) {
  using T = TypeParam;
  Rng rng;
  for (int trial = 0; trial < 2; ++trial) {
    BezierPatch<T, 3> p;
    const Plane3<T> pl = gentle_cut(rng, p);
    std::vector<HermiteErrors> e;
    for (const int g : {8, 16, 32}) e.push_back(hermite_errors(p, pl, g, pick<T>(4e-6, 0.0)));
    for (std::size_t i = 0; i < e.size(); ++i) {
      ASSERT_GT(e[i].segments, 0u) << rng.trace();
      // R(t) combines points of the plane with tangents in it: on the plane up to rounding.
      EXPECT_LE(e[i].on_plane, pick<T>(2e-6, 1e-14)) << rng.trace();
      // Every segment: error <= C h^4 with one C for every step (here about 0.01-0.6).
      EXPECT_LE(e[i].r_scaled, 1.0) << rng.trace() << " grid " << i;
      EXPECT_LE(e[i].p_scaled, 1.0) << rng.trace() << " grid " << i;
    }
    if (std::is_same_v<T, double> && trial == 0) {
      // The rate on nested point sets: every 12th, 6th and 3rd point of a fine trace, so each
      // segment splits in two at the next level. Halving the step divides the summed error by
      // about 8 for O(h^4) (twice the segments, each 16 times better), by 4 for O(h^3).
      SurfaceCurveOptions opt;
      opt.grid = 96;
      const auto fine = intersection(pl, p, opt);
      ASSERT_EQ(fine.status, Status::ok);
      double sums[3] = {0, 0, 0};
      for (const auto& c : fine.curves) {
        const std::size_t last = (c.points.size() - 1) / 12 * 12;
        for (std::size_t level = 0; level < 3; ++level) {
          const std::size_t m = std::size_t(12) >> level;
          SurfaceCurve<T> sub;
          for (std::size_t k = 0; k <= last; k += m) {
            sub.points.push_back(c.points[k]);
            sub.param_b.push_back(c.param_b[k]);
          }
          const HermiteSurfaceCurve<T> h = hermite_curve(pl, p, sub);
          ASSERT_EQ(h.status, Status::ok);
          for (std::size_t i = 0; i < segment_count(h); ++i)
            for (const T t : {T(0.25), T(0.5), T(0.75)}) {
              const Vec3<T> x = point_at(h, i, t).point;
              sums[level] += double(std::fabs(LD(x.z) - height(p, LD(x.x), LD(x.y))));
            }
        }
      }
      EXPECT_LT(sums[1], 0.18 * sums[0]) << rng.trace();
      EXPECT_LT(sums[2], 0.18 * sums[1]) << rng.trace();
    }
  }
}

TYPED_TEST(SurfaceHits, HermiteTangentsAgreeWithFiniteDifferences) {
  using T = TypeParam;
  Rng rng;
  BezierPatch<T, 3> p;
  const Plane3<T> pl = gentle_cut(rng, p);
  const Vec3<T> n = pl.normal;
  SurfaceCurveOptions opt;
  opt.grid = 32;
  const auto r = intersection(pl, p, opt);
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_FALSE(r.curves.empty());
  // S(p + d q) - S(p - d q) over 2d is the 3D velocity for the (u, v) velocity q: the unit T.
  const double d = pick<T>(1e-2, 1e-5), tol = pick<T>(2e-3, 1e-8);
  for (const auto& c : r.curves) {
    const HermiteSurfaceCurve<T> h = hermite_curve(pl, p, c);
    ASSERT_EQ(h.status, Status::ok);
    for (std::size_t i = 0; i < h.points.size(); ++i) {
      const Vec3<double> t = vec_cast<double>(h.tangents[i]);
      EXPECT_NEAR(length(t), 1.0, tol);
      EXPECT_NEAR(dot(t, vec_cast<double>(n)), 0.0, tol);
      const Vec2<double> uv = vec_cast<double>(h.params[i]),
                         q = vec_cast<double>(h.param_tangents[i]);
      const Vec2<double> a = uv + d * q, b = uv - d * q;
      if (std::min({a.x, a.y, b.x, b.y}) < 0 || std::max({a.x, a.y, b.x, b.y}) > 1) continue;
      const Vec3<double> fd = (vec_cast<double>(point_at(p, T(a.x), T(a.y))) -
                               vec_cast<double>(point_at(p, T(b.x), T(b.y)))) /
                              (2 * d);
      EXPECT_LE(max_abs(fd - t), 10 * tol) << rng.trace() << " point " << i;
      // Along the traced points: the central chord points the same way (step 1/32).
      if (i > 0 && i + 1 < h.points.size()) {
        const Vec3<double> chord = vec_cast<double>(h.points[i + 1] - h.points[i - 1]);
        if (length(chord) > 1e-3) {
          EXPECT_GT(dot(t, chord / length(chord)), 0.99) << i;
        }
      }
    }
  }
}

TYPED_TEST(SurfaceHits, HermiteLoopOnTheBowlAndBadInput) {
  using T = TypeParam;
  const Plane3<T> pl{{0, 0, 1}, T(0.5)};
  const auto r = intersection(pl, bowl<T>());
  ASSERT_EQ(r.curves.size(), 1u);
  const HermiteSurfaceCurve<T> h = hermite_curve(pl, bowl<T>(), r.curves[0]);
  ASSERT_EQ(h.status, Status::ok);
  ASSERT_TRUE(h.closed);
  EXPECT_EQ(segment_count(h), h.points.size());  // the last segment closes the loop
  // The circle x^2 + y^2 = 1/2 at z = 1/2: R(t) within O(h^4) of it, far below the chord sag.
  double worst = 0, sag = 0;
  for (std::size_t i = 0; i < segment_count(h); ++i) {
    const Vec3<double> x = vec_cast<double>(point_at(h, i, T(0.5)).point);
    EXPECT_NEAR(x.z, 0.5, pick<T>(1e-6, 1e-14));
    worst = std::max(worst, std::fabs(std::sqrt(x.x * x.x + x.y * x.y) - std::sqrt(0.5)));
    const std::size_t j = (i + 1) % h.points.size();
    const Vec3<double> mid = vec_cast<double>(h.points[i] + h.points[j]) / 2.0;
    sag = std::max(sag, std::sqrt(0.5) - std::sqrt(mid.x * mid.x + mid.y * mid.y));
  }
  EXPECT_LT(worst, std::max(sag / 100, pick<T>(2e-6, 0.0))) << worst << " " << sag;
  // The basis: a partition of unity with the right end values and slopes.
  const auto b0 = hermite_basis(T(0)), b1 = hermite_basis(T(1)), bm = hermite_basis(T(0.5));
  EXPECT_EQ(b0[0], T(1));
  EXPECT_EQ(b1[1], T(1));
  EXPECT_EQ(b0[2] + b1[2] + b0[3] + b1[3], T(0));
  EXPECT_EQ(bm[0] + bm[1], T(1));
  EXPECT_EQ(bm[2], T(0.125));
  EXPECT_EQ(bm[3], T(-0.125));
  // Bad input: no points, a zero or NaN normal.
  EXPECT_EQ(hermite_curve(pl, bowl<T>(), SurfaceCurve<T>{}).status, Status::empty_input);
  EXPECT_EQ(hermite_curve(Plane3<T>{{0, 0, 0}, T(1)}, bowl<T>(), r.curves[0]).status,
            Status::degenerate_input);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(hermite_curve(Plane3<T>{{nan, 0, 1}, T(1)}, bowl<T>(), r.curves[0]).status,
            Status::non_finite_input);
  // B-spline and NURBS forms of the same bowl give the same tangents.
  BSplineSurface<T, 3> bs{2, 2, 3, 3, bowl<T>().control, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}};
  const HermiteSurfaceCurve<T> hb = hermite_curve(pl, bs, r.curves[0]);
  ASSERT_EQ(hb.status, Status::ok);
  for (std::size_t i = 0; i < h.points.size(); ++i)
    EXPECT_LE(max_abs(vec_cast<double>(hb.tangents[i] - h.tangents[i])), pick<T>(1e-6, 1e-14));
}

}  // namespace
