// SPDX-License-Identifier: BSL-1.0
// Row int3.linear-quadric: Line3, Ray3, Segment3 against Sphere3, Quadric3, Ellipsoid3,
// Cylinder3 (infinite and finite), Cone3 and Capsule3, float and double. Sphere, general quadric
// and infinite cylinder: count, tangency (multiplicity 2), asymptotic and "lies on" cases against
// an exact GMP oracle (q(t) interpolated exactly in rationals, discriminant sign exact, roots
// located with 512-bit sqrt) on small-integer data where tangencies are frequent. Every hit must
// lie on both objects (residual bounds of the headers). Finite solids: the hits against a
// brute-force membership scan along the component. Power-of-two scaling, swap, reversed segment.
// Degenerate and NaN input. Figures 11.9-11.16: a ray through a sphere, a cylinder, a cone.

#include <locus/intersection/line_capsule.hpp>
#include <locus/intersection/line_cone.hpp>
#include <locus/intersection/line_cylinder.hpp>
#include <locus/intersection/line_ellipsoid.hpp>
#include <locus/intersection/line_quadric.hpp>
#include <locus/intersection/line_sphere.hpp>
#include <locus/intersection/ray_capsule.hpp>
#include <locus/intersection/ray_cone.hpp>
#include <locus/intersection/ray_cylinder.hpp>
#include <locus/intersection/ray_ellipsoid.hpp>
#include <locus/intersection/ray_quadric.hpp>
#include <locus/intersection/ray_sphere.hpp>
#include <locus/intersection/segment_capsule.hpp>
#include <locus/intersection/segment_cone.hpp>
#include <locus/intersection/segment_cylinder.hpp>
#include <locus/intersection/segment_ellipsoid.hpp>
#include <locus/intersection/segment_quadric.hpp>
#include <locus/intersection/segment_sphere.hpp>

#include <gmpxx.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class Quadric3Hits : public ::testing::Test {};
TYPED_TEST_SUITE(Quadric3Hits, locus_test::RealTypes);

// ---- exact oracle -----------------------------------------------------------------------------
using Q3 = std::array<mpq_class, 3>;
using QFun = std::function<mpq_class(const Q3&)>;

struct OracleHit {
  double t;
  int mult;
};
struct Oracle {
  bool whole = false;
  std::vector<OracleHit> hits;
};

/// q(t) = Q(o + t d) is quadratic: C = q(0), B = (q(1) - q(-1)) / 2, A = (q(1) + q(-1)) / 2 - C.
Oracle oracle(const QFun& qf, const Q3& o, const Q3& d, bool lo, bool hi) {
  const auto at = [&](int t) {
    Q3 x;
    for (int i = 0; i < 3; ++i) x[i] = o[i] + t * d[i];
    return qf(x);
  };
  const mpq_class c = at(0), q1 = at(1), qm = at(-1);
  const mpq_class b = (q1 - qm) / 2, a = (q1 + qm) / 2 - c;
  Oracle r;
  const auto in_q = [&](const mpq_class& t) { return (!lo || t >= 0) && (!hi || t <= 1); };
  if (d[0] == 0 && d[1] == 0 && d[2] == 0) {
    // A zero direction is its point.
    if (c == 0) r.hits.push_back({0.0, 1});
    return r;
  }
  if (a == 0) {
    if (b == 0) {
      r.whole = c == 0;
      return r;
    }
    const mpq_class t = -c / b;
    if (in_q(t)) r.hits.push_back({t.get_d(), 1});
    return r;
  }
  const mpq_class disc = b * b - 4 * a * c;
  if (disc < 0) return r;
  if (disc == 0) {
    const mpq_class t = -b / (2 * a);
    if (in_q(t)) r.hits.push_back({t.get_d(), 2});
    return r;
  }
  mpf_class sd(disc, 512);
  sd = sqrt(sd);
  mpf_class ra = (mpf_class(-b, 512) - sd) / mpf_class(2 * a, 512);
  mpf_class rb = (mpf_class(-b, 512) + sd) / mpf_class(2 * a, 512);
  if (ra > rb) std::swap(ra, rb);
  for (const mpf_class* rt : {&ra, &rb}) {
    // A root at an end is exact (q(0) = 0 or q(1) = 0): decide it exactly.
    const bool at0 = c == 0 && abs(*rt) < 1e-100, at1 = q1 == 0 && abs(*rt - 1) < 1e-100;
    const bool in = at0 || at1 || ((!lo || *rt >= 0) && (!hi || *rt <= 1));
    if (in) r.hits.push_back({at0 ? 0.0 : at1 ? 1.0 : rt->get_d(), 1});
  }
  return r;
}

Q3 q3(const Vec3<double>& v) { return {mpq_class(v.x), mpq_class(v.y), mpq_class(v.z)}; }

template <class T>
Q3 qo(const Line3<T>& l) {
  return q3(vec_cast<double>(l.origin));
}
template <class T>
Q3 qd(const Line3<T>& l) {
  return q3(vec_cast<double>(l.direction));
}
template <class T>
Q3 qo(const Ray3<T>& l) {
  return q3(vec_cast<double>(l.origin));
}
template <class T>
Q3 qd(const Ray3<T>& l) {
  return q3(vec_cast<double>(l.direction));
}
template <class T>
Q3 qo(const Segment3<T>& s) {
  return q3(vec_cast<double>(s.p0));
}
template <class T>
Q3 qd(const Segment3<T>& s) {
  Q3 a = q3(vec_cast<double>(s.p0)), b = q3(vec_cast<double>(s.p1));
  return {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
}
template <class C>
constexpr bool is_lo = true;
template <>
constexpr bool is_lo<Line3<float>> = false;
template <>
constexpr bool is_lo<Line3<double>> = false;

QFun sphere_fun(const Sphere3d& s) {
  return [s](const Q3& x) {
    mpq_class r = -mpq_class(s.radius) * mpq_class(s.radius);
    for (int i = 0; i < 3; ++i) {
      const mpq_class w = x[i] - mpq_class(s.center[i]);
      r += w * w;
    }
    return r;
  };
}
QFun quadric_fun(const Quadric3d& q) {
  return [q](const Q3& x) {
    mpq_class r = q.c;
    for (int i = 0; i < 3; ++i) {
      r += mpq_class(q.b[i]) * x[i];
      for (int j = 0; j < 3; ++j)
        r += mpq_class(q.a.a[std::min(i, j)][std::max(i, j)]) * x[i] * x[j];
    }
    return r;
  };
}
QFun cylinder_fun(const Cylinder3d& c) {
  return [c](const Q3& x) {
    Q3 w, a = q3(c.axis.direction);
    for (int i = 0; i < 3; ++i) w[i] = x[i] - mpq_class(c.axis.origin[i]);
    mpq_class s = 0, aa = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const mpq_class cr = a[j] * w[k] - a[k] * w[j];
      s += cr * cr;
      aa += a[i] * a[i];
    }
    return mpq_class(s - mpq_class(c.radius) * mpq_class(c.radius) * aa);
  };
}

/// Compares a result with the oracle: kind, count, multiplicities, parameters.
template <class T, class Res>
void expect_matches(const Res& r, const Oracle& o, double scale_t) {
  if (o.whole) {
    EXPECT_TRUE(r.kind == Kind::line || r.kind == Kind::ray || r.kind == Kind::segment);
    return;
  }
  ASSERT_EQ(r.count, int(o.hits.size()));
  for (int i = 0; i < r.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_EQ(r.multiplicity[k], o.hits[k].mult) << i;
    // Tangent roots are ill-conditioned (sqrt of the noise); simple ones to a few ulps.
    const double tol = o.hits[k].mult == 2 ? 4.0 * std::sqrt(double(eps_v<T>)) * scale_t
                                           : 256.0 * double(eps_v<T>) * scale_t;
    EXPECT_NEAR(double(r.param_a[k]), o.hits[k].t, tol) << i;
  }
}

template <class T>
T ri(Rng& rng, int lo, int hi) {
  return T(rng.uniform_int(lo, hi));
}
template <class T>
Vec3<T> rv(Rng& rng, int lo, int hi) {
  return {ri<T>(rng, lo, hi), ri<T>(rng, lo, hi), ri<T>(rng, lo, hi)};
}

// ---- sphere -----------------------------------------------------------------------------------
template <class T, class C>
void sphere_case(const C& comp, const Sphere3<T>& s) {
  const Sphere3d sd{vec_cast<double>(s.center), double(s.radius)};
  const auto r = intersection(comp, s);
  const Oracle o =
      oracle(sphere_fun(sd), qo(comp), qd(comp), is_lo<C>, std::is_same_v<C, Segment3<T>>);
  expect_matches<T>(r, o, 16.0);
  for (int i = 0; i < r.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double dist = length(vec_cast<double>(r.point[k]) - sd.center);
    const double tol =
        (r.multiplicity[k] == 2 ? 4.0 * std::sqrt(double(eps_v<T>)) : 64.0 * double(eps_v<T>)) *
        16.0;
    EXPECT_NEAR(dist, sd.radius, tol);
    EXPECT_NEAR(dot(vec_cast<double>(r.normal[k]), vec_cast<double>(r.point[k]) - sd.center),
                sd.radius, tol);
  }
  EXPECT_EQ(intersects(comp, s), r.kind != Kind::empty);
  const auto sw = intersection(s, comp);
  EXPECT_EQ(sw.count, r.count);
  if (r.count > 0) {
    EXPECT_EQ(sw.param_b[0], r.param_a[0]);
  }
}

TYPED_TEST(Quadric3Hits, SphereAgainstExactOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 40; ++n) {
    const Sphere3<T> s{rv<T>(rng, -3, 3), ri<T>(rng, 0, 3)};
    const Vec3<T> o = rv<T>(rng, -5, 5), d = rv<T>(rng, -2, 2), p1 = rv<T>(rng, -5, 5);
    sphere_case(Line3<T>{o, d}, s);
    sphere_case(Ray3<T>{o, d}, s);
    sphere_case(Segment3<T>{o, p1}, s);
  }
  // Exact tangents: integer points on spheres (Pythagorean quadruples), tangent directions
  // (w x random), origins and segment ends placed on the tangent line or just off it.
  const int quad[3][4] = {{1, 2, 2, 3}, {2, 3, 6, 7}, {1, 4, 8, 9}};
  for (int n = 0; n < 24; ++n) {
    const int* qq = quad[n % 3];
    const Vec3<T> c = rv<T>(rng, -3, 3);
    const Vec3<T> w{T(qq[0] * (rng.uniform_int(0, 1) * 2 - 1)), T(qq[1]), T(qq[2])};
    const Vec3<T> d = cross(w, rv<T>(rng, -2, 2));
    if (d == Vec3<T>{}) continue;
    const Sphere3<T> s{c, T(qq[3])};
    const Vec3<T> p = c + w;
    const T k = ri<T>(rng, -3, 3);
    sphere_case(Line3<T>{p - k * d, d}, s);
    sphere_case(Ray3<T>{p - k * d, d}, s);
    sphere_case(Segment3<T>{p - k * d, p + ri<T>(rng, -3, 3) * d}, s);
    EXPECT_EQ(intersection(Line3<T>{p - k * d, d}, s).multiplicity[0], 2);
  }
}

TYPED_TEST(Quadric3Hits, SphereFigureAndTangents) {
  using T = TypeParam;
  // Figure 11.9: a ray through a unit sphere, entering and leaving.
  const Sphere3<T> s{{T(1), T(2), T(3)}, T(5)};
  const auto r = intersection(Ray3<T>{{T(-10), T(2), T(3)}, {T(1), T(0), T(0)}}, s);
  ASSERT_EQ(r.kind, Kind::points);
  EXPECT_EQ(r.param_a[0], T(6));
  EXPECT_EQ(r.param_a[1], T(16));
  // Tangent at (1, 2 + 3, 3 + 4) along a direction orthogonal to (0, 3, 4): exact double root.
  const auto t = intersection(Line3<T>{{T(-7), T(5), T(7)}, {T(1), T(0), T(0)}},
                              Sphere3<T>{{T(1), T(2), T(3)}, T(5)});
  ASSERT_EQ(t.kind, Kind::point);
  EXPECT_EQ(t.multiplicity[0], 2);
  EXPECT_EQ(t.param_a[0], T(8));
  // One ulp inside / outside: 2 and 0 points.
  const T up = std::nextafter(T(5), T(10)), dn = std::nextafter(T(5), T(0));
  EXPECT_EQ(intersection(Line3<T>{{T(-7), T(5), T(7)}, {T(1), T(0), T(0)}},
                         Sphere3<T>{{T(1), T(2), T(3)}, up})
                .count,
            2);
  EXPECT_EQ(intersection(Line3<T>{{T(-7), T(5), T(7)}, {T(1), T(0), T(0)}},
                         Sphere3<T>{{T(1), T(2), T(3)}, dn})
                .count,
            0);
  // A segment ending exactly on the sphere, a ray starting on it.
  const auto e = intersection(Segment3<T>{{T(-10), T(2), T(3)}, {T(-4), T(2), T(3)}}, s);
  ASSERT_EQ(e.count, 1);
  EXPECT_EQ(e.param_a[0], T(1));
  const auto st = intersection(Ray3<T>{{T(6), T(2), T(3)}, {T(1), T(0), T(0)}}, s);
  ASSERT_EQ(st.count, 1);
  EXPECT_EQ(st.param_a[0], T(0));
}

TYPED_TEST(Quadric3Hits, ScalingSwapReverse) {
  using T = TypeParam;
  Rng rng(7);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 30; ++n) {
    const Sphere3<T> s{rng.template vec<T, 3>(T(-2), T(2)), rng.uniform(T(0.5), T(2))};
    const Segment3<T> sg{rng.template vec<T, 3>(T(-4), T(4)), rng.template vec<T, 3>(T(-4), T(4))};
    const auto r = intersection(sg, s);
    for (int k : {-20, 3, 30}) {
      const T f = std::ldexp(T(1), k);
      const auto rs =
          intersection(Segment3<T>{sg.p0 * f, sg.p1 * f}, Sphere3<T>{s.center * f, s.radius * f});
      ASSERT_EQ(rs.count, r.count);
      for (int i = 0; i < r.count; ++i)
        EXPECT_EQ(rs.param_a[std::size_t(i)], r.param_a[std::size_t(i)]);
    }
    const auto rr = intersection(Segment3<T>{sg.p1, sg.p0}, s);
    ASSERT_EQ(rr.count, r.count);
    for (int i = 0; i < r.count; ++i)
      EXPECT_NEAR(double(rr.param_a[std::size_t(r.count - 1 - i)]),
                  1.0 - double(r.param_a[std::size_t(i)]), 1e3 * double(eps_v<T>));
  }
}

// ---- general quadric and infinite cylinder ----------------------------------------------------
template <class T, class C>
void quadric_case(const C& comp, const Quadric3<T>& q) {
  Quadric3d qd64{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) qd64.a.a[i][j] = double(q.a.a[std::min(i, j)][std::max(i, j)]);
  qd64.b = vec_cast<double>(q.b);
  qd64.c = double(q.c);
  const auto r = intersection(comp, q);
  expect_matches<T>(
      r, oracle(quadric_fun(qd64), qo(comp), qd(comp), is_lo<C>, std::is_same_v<C, Segment3<T>>),
      64.0);
}

TYPED_TEST(Quadric3Hits, QuadricAgainstExactOracle) {
  using T = TypeParam;
  Rng rng(11);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 60; ++n) {
    Quadric3<T> q{};
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) q.a.a[i][j] = q.a.a[j][i] = ri<T>(rng, -2, 2);
    q.b = rv<T>(rng, -3, 3);
    q.c = ri<T>(rng, -4, 4);
    const Vec3<T> o = rv<T>(rng, -3, 3), d = rv<T>(rng, -1, 1), p1 = rv<T>(rng, -3, 3);
    quadric_case(Line3<T>{o, d}, q);
    quadric_case(Ray3<T>{o, d}, q);
    quadric_case(Segment3<T>{o, p1}, q);
  }
  // A ruling of the hyperbolic paraboloid z = x y: the whole line lies on it.
  Quadric3<T> hp{};
  hp.a.a[0][1] = hp.a.a[1][0] = T(0.5);
  hp.b = {T(0), T(0), T(-1)};
  const auto w = intersection(Line3<T>{{T(2), T(0), T(0)}, {T(0), T(1), T(2)}}, hp);
  EXPECT_EQ(w.kind, Kind::line);
}

TYPED_TEST(Quadric3Hits, InfiniteCylinderAgainstExactOracle) {
  using T = TypeParam;
  Rng rng(13);
  SCOPED_TRACE(rng.trace());
  const T inf = std::numeric_limits<T>::infinity();
  for (int n = 0; n < 60; ++n) {
    // Axis directions need not be unit for the exact test; use integer axes.
    const Cylinder3<T> c{{rv<T>(rng, -2, 2), rv<T>(rng, -1, 1)}, ri<T>(rng, 1, 3), inf};
    if (c.axis.direction == Vec3<T>{}) continue;
    const Cylinder3d cd{{vec_cast<double>(c.axis.origin), vec_cast<double>(c.axis.direction)},
                        double(c.radius),
                        double(c.height)};
    const Vec3<T> o = rv<T>(rng, -4, 4), d = rv<T>(rng, -1, 1), p1 = rv<T>(rng, -4, 4);
    const auto chk = [&](const auto& comp) {
      using C = std::decay_t<decltype(comp)>;
      const auto r = intersection(comp, c);
      expect_matches<T>(
          r, oracle(cylinder_fun(cd), qo(comp), qd(comp), is_lo<C>, std::is_same_v<C, Segment3<T>>),
          64.0);
    };
    chk(Line3<T>{o, d});
    chk(Ray3<T>{o, d});
    chk(Segment3<T>{o, p1});
  }
}

// ---- finite solids: brute-force membership scan -------------------------------------------------
template <class Inside, class C>
int scan_changes(const Inside& inside, const C& comp, double t0, double t1, int n) {
  int changes = 0;
  bool prev = inside(t0);
  for (int i = 1; i <= n; ++i) {
    const bool cur = inside(t0 + (t1 - t0) * i / n);
    changes += cur != prev;
    prev = cur;
  }
  (void)comp;
  return changes;
}

TYPED_TEST(Quadric3Hits, FiniteSolidsAgainstScan) {
  using T = TypeParam;
  Rng rng(17);
  SCOPED_TRACE(rng.trace());
  int tried = 0, compared = 0, nonzero = 0;
  for (int n = 0; n < 24; ++n) {
    const Vec3<T> axis = normalize(rng.template vec<T, 3>(T(-1), T(1)));
    const Vec3<T> ctr = rng.template vec<T, 3>(T(-1), T(1));
    const Cylinder3<T> cyl{{ctr, axis}, rng.uniform(T(0.5), T(1.5)), rng.uniform(T(1), T(3))};
    const Cone3<T> cone{ctr, axis, rng.uniform(T(0.3), T(1.2)), rng.uniform(T(-2), T(0.5)),
                        rng.uniform(T(0.6), T(2.5))};
    const Capsule3<T> cap{{ctr, ctr + rng.template vec<T, 3>(T(-2), T(2))},
                          rng.uniform(T(0.3), T(1.2))};
    // Segments across the solids' neighbourhood (most of them hit).
    const Vec3<T> p0 = rng.template vec<T, 3>(T(-4), T(4));
    const Segment3<T> sg{p0, ctr + (ctr - p0) + rng.template vec<T, 3>(T(-1.5), T(1.5))};
    const auto at = [&](double t) {
      return vec_cast<double>(sg.p0) + t * (vec_cast<double>(sg.p1) - vec_cast<double>(sg.p0));
    };
    const auto in_cyl = [&](double t) {
      const Vec3<double> w = at(t) - vec_cast<double>(ctr);
      const double h = dot(w, vec_cast<double>(axis));
      return std::fabs(h) <= 0.5 * double(cyl.height) &&
             sqr_length(w) - h * h <= sqr(double(cyl.radius));
    };
    const auto in_cone = [&](double t) {
      const Vec3<double> w = at(t) - vec_cast<double>(ctr);
      const double h = dot(w, vec_cast<double>(axis));
      return h >= double(cone.min_height) && h <= double(cone.max_height) &&
             std::sqrt(std::max(sqr_length(w) - h * h, 0.0)) <=
                 std::fabs(h) * std::tan(double(cone.angle));
    };
    const auto in_cap = [&](double t) {
      const Vec3<double> p = at(t), a = vec_cast<double>(cap.segment.p0),
                         b = vec_cast<double>(cap.segment.p1);
      const double s = std::clamp(dot(p - a, b - a) / sqr_length(b - a), 0.0, 1.0);
      return length(p - (a + s * (b - a))) <= double(cap.radius);
    };
    const auto check = [&](const auto& r, const auto& inside) {
      ++tried;
      // Skip configurations where hits crowd each other or an end (the scan cannot resolve them).
      for (int i = 0; i < r.count; ++i) {
        const double t = double(r.param_a[std::size_t(i)]);
        if (t < 1e-3 || t > 1 - 1e-3 || r.multiplicity[std::size_t(i)] == 2) return;
        if (i > 0 && t - double(r.param_a[std::size_t(i - 1)]) < 1e-3) return;
      }
      EXPECT_EQ(r.count, scan_changes(inside, sg, 0.0, 1.0, 1500));
      ++compared;
      nonzero += r.count > 0;
    };
    check(intersection(sg, cyl), in_cyl);
    check(intersection(sg, cone), in_cone);
    check(intersection(sg, cap), in_cap);
    // Each hit is on the boundary: just inside on one side, outside on the other (or tangent).
    for (const auto& r : {intersection(sg, cyl)})
      for (int i = 0; i < r.count; ++i) {
        const double t = double(r.param_a[std::size_t(i)]);
        const Vec3<double> w = vec_cast<double>(r.point[std::size_t(i)]) - vec_cast<double>(ctr);
        const double h = dot(w, vec_cast<double>(axis));
        const double rad = std::sqrt(std::max(sqr_length(w) - h * h, 0.0));
        const double tolr = 64.0 * double(eps_v<T>) * 8.0;
        EXPECT_TRUE(std::fabs(rad - double(cyl.radius)) <= tolr ||
                    std::fabs(std::fabs(h) - 0.5 * double(cyl.height)) <= tolr)
            << t;
      }
  }
  EXPECT_GT(compared, tried / 2);
  EXPECT_GT(nonzero, compared / 2);
}

TYPED_TEST(Quadric3Hits, FiguresCylinderConeCapsule) {
  using T = TypeParam;
  const Vec3<T> ez{T(0), T(0), T(1)};
  // Figure 11.11: a ray through a finite cylinder's side and cap.
  const Cylinder3<T> cyl{{{T(0), T(0), T(0)}, ez}, T(1), T(4)};
  const auto r = intersection(Ray3<T>{{T(-4), T(0), T(0)}, {T(2), T(0), T(1)}}, cyl);
  ASSERT_EQ(r.count, 2);
  EXPECT_NEAR(double(r.param_a[0]), 1.5, 64 * double(eps_v<T>));  // the side x = -1
  EXPECT_NEAR(double(r.param_a[1]), 2.0, 64 * double(eps_v<T>));  // the cap z = 2
  EXPECT_TRUE(locus_test::vec_near(r.normal[0], Vec3<T>{T(-1), T(0), T(0)}, T(64) * eps_v<T>));
  EXPECT_EQ(r.normal[1], ez);
  // Along the axis: both caps.
  const auto a = intersection(Line3<T>{{T(0.5), T(0), T(-9)}, ez}, cyl);
  ASSERT_EQ(a.count, 2);
  EXPECT_EQ(a.param_a[0], T(7));
  EXPECT_EQ(a.param_a[1], T(11));
  EXPECT_EQ(a.normal[0], -ez);
  EXPECT_EQ(a.normal[1], ez);
  // Figure 11.15: a double cone crossed twice by a line parallel to the axis off the apex... and
  // a line through both nappes across the axis: four hits with caps.
  const Cone3<T> dc{{T(0), T(0), T(0)}, ez, T(0.7853981633974483), T(-2), T(2)};
  const auto d4 = intersection(Line3<T>{{T(0.5), T(0), T(-5)}, ez}, dc);
  ASSERT_EQ(d4.count, 4);
  EXPECT_NEAR(double(d4.param_a[0]), 3.0, 1e-5);
  EXPECT_NEAR(double(d4.param_a[1]), 4.5, 1e-5);
  EXPECT_NEAR(double(d4.param_a[2]), 5.5, 1e-5);
  EXPECT_NEAR(double(d4.param_a[3]), 7.0, 1e-5);
  // A capsule hit end-on: both hemispheres.
  const Capsule3<T> cap{{{T(0), T(0), T(-1)}, {T(0), T(0), T(1)}}, T(1)};
  const auto c2 = intersection(Line3<T>{{T(0), T(0), T(-5)}, ez}, cap);
  ASSERT_EQ(c2.count, 2);
  EXPECT_EQ(c2.param_a[0], T(3));
  EXPECT_EQ(c2.param_a[1], T(7));
  // Side-on: the cylinder part.
  const auto c3 = intersection(Line3<T>{{T(-5), T(0), T(0.5)}, {T(1), T(0), T(0)}}, cap);
  ASSERT_EQ(c3.count, 2);
  EXPECT_EQ(c3.param_a[0], T(4));
  EXPECT_EQ(c3.param_a[1], T(6));
}

TYPED_TEST(Quadric3Hits, EllipsoidPointsOnSurface) {
  using T = TypeParam;
  Rng rng(19);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 80; ++n) {
    const Vec3<T> u0 = normalize(rng.template vec<T, 3>(T(-1), T(1)));
    const Vec3<T> u1 = normalize(cross(u0, rng.template vec<T, 3>(T(-1), T(1))));
    const Ellipsoid3<T> e{
        rng.template vec<T, 3>(T(-1), T(1)),
        {u0, u1, cross(u0, u1)},
        {rng.uniform(T(0.5), T(2)), rng.uniform(T(0.5), T(2)), rng.uniform(T(0.5), T(2))}};
    const Line3<T> l{rng.template vec<T, 3>(T(-3), T(3)), rng.template vec<T, 3>(T(-1), T(1))};
    const auto r = intersection(l, e);
    for (int i = 0; i < r.count; ++i) {
      const auto k = std::size_t(i);
      if (r.multiplicity[k] == 2) continue;
      EXPECT_NEAR(double(signed_value(e, r.point[k])), 0.0, 2048.0 * double(eps_v<T>));
      EXPECT_TRUE(locus_test::vec_near(point_at(e, r.param_b[k]), r.point[k], T(2048) * eps_v<T>));
    }
  }
}

TYPED_TEST(Quadric3Hits, DegenerateInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Sphere3<T> s{{T(0), T(0), T(0)}, T(1)};
  EXPECT_EQ(intersection(Line3<T>{{nan, T(0), T(0)}, {T(1), T(0), T(0)}}, s).kind, Kind::empty);
  EXPECT_EQ(intersection(Line3<T>{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}},
                         Sphere3<T>{{T(0), T(0), T(0)}, T(-1)})
                .kind,
            Kind::empty);
  // A zero direction on the sphere: one point.
  EXPECT_EQ(intersection(Segment3<T>{{T(1), T(0), T(0)}, {T(1), T(0), T(0)}}, s).count, 1);
  EXPECT_EQ(intersection(Segment3<T>{{T(0.5), T(0), T(0)}, {T(0.5), T(0), T(0)}}, s).count, 0);
  // Radius zero: a line through the centre is tangent.
  const auto z = intersection(Line3<T>{{T(-1), T(0), T(0)}, {T(1), T(0), T(0)}},
                              Sphere3<T>{{T(0), T(0), T(0)}, T(0)});
  ASSERT_EQ(z.count, 1);
  EXPECT_EQ(z.multiplicity[0], 2);
  const T inf = std::numeric_limits<T>::infinity();
  EXPECT_EQ(intersection(Ray3<T>{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}},
                         Cylinder3<T>{{{inf, T(0), T(0)}, {T(0), T(0), T(1)}}, T(1), T(2)})
                .kind,
            Kind::empty);
  EXPECT_EQ(intersection(Ray3<T>{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}},
                         Cone3<T>{{T(0), T(0), T(0)}, {T(0), T(0), T(1)}, nan, T(0), T(1)})
                .kind,
            Kind::empty);
  EXPECT_EQ(intersection(Ray3<T>{{T(0), T(0), T(0)}, {nan, T(0), T(0)}},
                         Capsule3<T>{{{T(0), T(0), T(0)}, {T(0), T(0), T(1)}}, T(1)})
                .kind,
            Kind::empty);
  // A line on an infinite cylinder's surface.
  const auto on = intersection(Line3<T>{{T(1), T(0), T(0)}, {T(0), T(0), T(3)}},
                               Cylinder3<T>{{{T(0), T(0), T(0)}, {T(0), T(0), T(1)}}, T(1), inf});
  EXPECT_EQ(on.kind, Kind::line);
}

}  // namespace
