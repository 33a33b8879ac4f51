// SPDX-License-Identifier: BSL-1.0
// Rows int3.linear-plane and int3.linear-triangle: intersects() / intersection() of Line3, Ray3
// and Segment3 with Plane3 and Triangle3, float and double, against the exact GMP oracle
// (linear3_oracle.hpp). Each case checks: the kind equals the exact one; intersects() agrees;
// each point is within the stated bound of the exact one (plane: 8 eps max(|X|, m); triangle:
// 16 eps m / sin(angle between the component and the plane)), with its parameters; an input
// point (end point, origin, vertex) met by the other argument is returned exactly; every entry
// lies on both arguments through its parameters; the swapped overload returns swapped().
// Inputs: seeded random; integer grids (components in planes, through edges and vertices,
// coplanar overlaps, zero directions, degenerate triangles); planes as rounded data (random
// unit normals); axis permutations, sign flips, integer translations and power-of-two scaling
// (decisions unchanged); NaN/Inf.

#include <locus/core/plane_side.hpp>
#include <locus/intersection/line_plane.hpp>
#include <locus/intersection/line_triangle.hpp>
#include <locus/intersection/ray_plane.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/intersection/segment_plane.hpp>
#include <locus/intersection/segment_triangle.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "intersection/linear3_oracle.hpp"
#include "support/scale_covariance.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;
namespace ex = locus_test::exact3;

template <class T>
class IntersectionLinear3 : public ::testing::Test {};
TYPED_TEST_SUITE(IntersectionLinear3, locus_test::RealTypes);

template <class P>
struct Make;
template <class T>
struct Make<Line3<T>> {
  static Line3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q - p}; }
  static std::vector<Vec3<T>> inputs(const Line3<T>& l) { return {l.origin}; }
  static constexpr const char* name = "line";
};
template <class T>
struct Make<Ray3<T>> {
  static Ray3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q - p}; }
  static std::vector<Vec3<T>> inputs(const Ray3<T>& r) { return {r.origin}; }
  static constexpr const char* name = "ray";
};
template <class T>
struct Make<Segment3<T>> {
  static Segment3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q}; }
  static std::vector<Vec3<T>> inputs(const Segment3<T>& s) { return {s.p0, s.p1}; }
  static constexpr const char* name = "segment";
};

template <class T, class F>
void for_each_linear(F&& f) {
  f.template operator()<Line3<T>>();
  f.template operator()<Ray3<T>>();
  f.template operator()<Segment3<T>>();
}

template <class T>
std::string str(const Vec3<T>& v) {
  char b[160];
  std::snprintf(b, sizeof b, "(%.17g, %.17g, %.17g)", double(v.x), double(v.y), double(v.z));
  return b;
}
template <class P>
std::string describe(const P& p) {
  if constexpr (requires { p.p0; })
    return "segment " + str(p.p0) + " " + str(p.p1);
  else
    return "origin " + str(p.origin) + " direction " + str(p.direction);
}

const char* name(ex::QKind k) {
  switch (k) {
    case ex::QKind::empty:
      return "empty";
    case ex::QKind::point:
      return "point";
    case ex::QKind::segment:
      return "segment";
    case ex::QKind::ray:
      return "ray";
    case ex::QKind::line:
      return "line";
  }
  return "?";
}

template <class T>
double err(const Vec3<T>& p, const ex::Q3& e) {
  return std::max({std::abs(mpq_class(mpq_class(double(p.x)) - e.x).get_d()),
                   std::abs(mpq_class(mpq_class(double(p.y)) - e.y).get_d()),
                   std::abs(mpq_class(mpq_class(double(p.z)) - e.z).get_d())});
}

template <class A>
double coord_max(const A& a) {
  double m = 0;
  for (const auto& p : Make<A>::inputs(a)) m = std::max(m, double(max_abs(p)));
  return m;
}

struct Worst {
  double ratio = 0;
};

// ----------------------------------------------------------------------------------------------
// Plane.

template <class T, class A>
void check_plane(const A& a, const Plane3<T>& pl, Worst* worst = nullptr) {
  SCOPED_TRACE(describe(a) + ", plane n = " + str(pl.normal) +
               " c = " + std::to_string(double(pl.constant)));
  const LinearPlaneIntersection<T> r = intersection(a, pl);
  const ex::QLin ql = ex::ql(a);
  const ex::QResult e = ex::plane(ql, ex::q(pl.normal), mpq_class(double(pl.constant)));
  ASSERT_EQ(to_string(r.kind), std::string(name(e.kind)));
  EXPECT_EQ(intersects(a, pl), e.kind != ex::QKind::empty);
  ASSERT_EQ(r.count, e.count);
  const double eps = double(eps_v<T>);
  const double m = coord_max(a);
  const double dm = ex::qmax_abs(ql.d);
  for (int i = 0; i < e.count; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    // The header's bound: 8 eps max(|X|, m) + 2^-100 |X - o| / sin(angle) (the compensated
    // dot products are as accurate as twice the precision of double).
    double bound = 8 * eps * std::max(ex::qmax_abs(e.point[i]), m);
    const mpq_class nd = ex::qdot(ex::q(pl.normal), ql.d);
    if (e.kind == ex::QKind::point && nd != 0) {
      const double sine =
          std::abs(nd.get_d()) / std::sqrt(ex::qdot(ex::q(pl.normal), ex::q(pl.normal)).get_d() *
                                           ex::qdot(ql.d, ql.d).get_d());
      bound += 0x1p-100 * ex::qmax_abs(e.point[i] - ql.o) / sine;
    }
    const double pe = err(r.point[k], e.point[i]);
    EXPECT_LE(pe, bound) << "point error " << pe << " entry " << i;
    for (const auto& in : Make<A>::inputs(a))
      if (ex::q(in) == e.point[i]) {
        EXPECT_EQ(pe, 0.0) << "an input point on the plane is returned exactly";
      }
    const double te = std::abs(mpq_class(mpq_class(double(r.param_a[k])) - e.t[i]).get_d()) * dm;
    EXPECT_LE(te, bound) << "param error " << te;
    if (worst && bound > 0) worst->ratio = std::max(worst->ratio, std::max(pe, te) / (bound / 8));
    EXPECT_TRUE(locus_test::vec_near(point_at(a, r.param_a[k]), r.point[k],
                                     T(8 * eps * std::max(m, double(max_abs(r.point[k]))))));
  }
  const auto s = intersection(pl, a);
  EXPECT_EQ(s.kind, r.kind);
  ASSERT_EQ(s.count, r.count);
  for (std::size_t i = 0; i < static_cast<std::size_t>(r.count); ++i) {
    EXPECT_EQ(s.point[i], r.point[i]);
    EXPECT_EQ(s.param_b[i], r.param_a[i]);
  }
  EXPECT_EQ(intersects(pl, a), intersects(a, pl));
}

TYPED_TEST(IntersectionLinear3, PlaneRandomAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  Worst worst;
  int hits = 0;
  for_each_linear<T>([&]<class A>() {
    SCOPED_TRACE(Make<A>::name);
    for (int i = 0; i < 2000; ++i) {
      const Vec3<T> n = rng.unit<T, 3>();
      const Plane3<T> pl = plane_from_point_normal(rng.vec<T, 3>(-1, 1), n);  // rounded data
      const A a = Make<A>::from(rng.vec<T, 3>(-1, 1), rng.vec<T, 3>(-1, 1));
      check_plane<T>(a, pl, &worst);
      hits += intersects(a, pl) ? 1 : 0;
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(hits, 1000);
  EXPECT_LT(hits, 5500);
  std::printf("[ measured ] plane: worst error / (eps max(|X|, m)) = %.3g\n", worst.ratio);
}

// Exact configurations on integer grids: components lying in the plane, end points and origins
// on it, parallel off it, zero directions.
TYPED_TEST(IntersectionLinear3, PlaneIntegerDegeneracies) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int kinds[5] = {0, 0, 0, 0, 0};
  for_each_linear<T>([&]<class A>() {
    SCOPED_TRACE(Make<A>::name);
    for (int i = 0; i < 3000; ++i) {
      const auto g = [&](int r) {
        return Vec3<T>{T(rng.uniform_int(-r, r)), T(rng.uniform_int(-r, r)),
                       T(rng.uniform_int(-r, r))};
      };
      Vec3<T> n = g(2);
      if (n == Vec3<T>{}) n.z = 1;
      const Plane3<T> pl{n, T(rng.uniform_int(-3, 3))};
      const A a = Make<A>::from(g(2), g(2));
      check_plane<T>(a, pl);
      ++kinds[static_cast<int>(
          ex::plane(ex::ql(a), ex::q(n), mpq_class(double(pl.constant))).kind)];
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(kinds[1], 500);
  EXPECT_GT(kinds[2] + kinds[3] + kinds[4], 20);  // contained components of each type
  EXPECT_GT(kinds[3], 5);
  EXPECT_GT(kinds[4], 5);
}

// Nearly parallel components a few ulps off the plane: the exact sign of dot(n, p) - c of the
// data as given decides, where the rounded evaluation of the same expression cannot.
TYPED_TEST(IntersectionLinear3, PlaneNearParallel) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for_each_linear<T>([&]<class A>() {
    SCOPED_TRACE(Make<A>::name);
    for (int i = 0; i < 1500; ++i) {
      const Vec3<T> n = rng.unit<T, 3>();
      const Vec3<T> p = rng.vec<T, 3>(-1, 1);
      const Plane3<T> pl = plane_from_point_normal(p, n);
      // A direction in the plane (rounded), so the component is parallel within a few ulps.
      const Vec3<T> d = cross(n, rng.unit<T, 3>());
      Vec3<T> q = p;
      for (int k = 0; k < 3; ++k) q[k] = std::nextafter(q[k], rng.uniform_int(0, 1) ? T(4) : T(-4));
      check_plane<T>(Make<A>::from(q, q + d), pl);
      check_plane<T>(Make<A>::from(p, p + d), pl);
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
}

// ----------------------------------------------------------------------------------------------
// Triangle.

template <class T>
std::string describe(const Triangle3<T>& t) {
  return "triangle " + str(t.v0) + " " + str(t.v1) + " " + str(t.v2);
}

template <class T, class A>
void check_triangle(const A& a, const Triangle3<T>& tri, Worst* worst = nullptr) {
  SCOPED_TRACE(describe(a) + ", " + describe(tri));
  const LinearTriangleIntersection<T> r = intersection(a, tri);
  const ex::QLin ql = ex::ql(a);
  const ex::QTri qt = ex::qt(tri);
  const ex::QResult e = ex::triangle(ql, qt);
  ASSERT_EQ(to_string(r.kind), std::string(name(e.kind)));
  EXPECT_EQ(intersects(a, tri), e.kind != ex::QKind::empty);
  ASSERT_EQ(r.count, e.count);
  const double eps = double(eps_v<T>);
  const double m = std::max(
      {coord_max(a), double(max_abs(tri.v0)), double(max_abs(tri.v1)), double(max_abs(tri.v2))});
  const double dm = ex::qmax_abs(ql.d);
  // 1 / sin(angle) between the component and the plane (1 when coplanar: the crossings are
  // then with edges in the plane, conditioned like the 2D case).
  const ex::Q3 n = ex::qcross(qt.v1 - qt.v0, qt.v2 - qt.v0);
  double kappa = 1;
  if (e.kind == ex::QKind::point && ex::qdot(n, ql.d) != 0) {
    const double nd = std::abs(ex::qdot(n, ql.d).get_d());
    kappa = std::sqrt(ex::qdot(n, n).get_d() * ex::qdot(ql.d, ql.d).get_d()) / nd;
  }
  for (int i = 0; i < e.count; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const double bound = 16 * eps * m * kappa;
    const double pe = err(r.point[k], e.point[i]);
    EXPECT_LE(pe, bound) << "point error " << pe << " entry " << i;
    for (const auto& in : Make<A>::inputs(a))
      if (ex::q(in) == e.point[i]) {
        EXPECT_EQ(pe, 0.0) << "an input point on the triangle is returned exactly";
      }
    for (const auto& v : {tri.v0, tri.v1, tri.v2})
      if (ex::q(v) == e.point[i]) {
        EXPECT_EQ(pe, 0.0) << "a vertex met is returned exactly";
      }
    const double te = std::abs(mpq_class(mpq_class(double(r.param_a[k])) - e.t[i]).get_d()) * dm;
    EXPECT_LE(te, 2 * bound) << "param_a error " << te;
    if (worst && m > 0) worst->ratio = std::max(worst->ratio, pe / (eps * m * kappa));
    // (s, t) on the triangle: the point through it is close (the barycentrics are rounded).
    EXPECT_TRUE(locus_test::vec_near(point_at(tri, r.param_b[k]), r.point[k], T(2 * bound)));
    EXPECT_GE(r.param_b[k].x, T(0));
    EXPECT_GE(r.param_b[k].y, T(0));
    EXPECT_LE(r.param_b[k].x + r.param_b[k].y, T(1) + T(4 * eps));
  }
  if (e.kind == ex::QKind::segment) {
    EXPECT_LT(r.param_a[0], r.param_a[1]);
  }
  const auto s = intersection(tri, a);
  EXPECT_EQ(s.kind, r.kind);
  ASSERT_EQ(s.count, r.count);
  for (std::size_t i = 0; i < static_cast<std::size_t>(r.count); ++i) {
    EXPECT_EQ(s.point[i], r.point[i]);
    EXPECT_EQ(s.param_b[i], r.param_a[i]);
    EXPECT_EQ(s.param_a[i], r.param_b[i]);
  }
  EXPECT_EQ(intersects(tri, a), intersects(a, tri));
  // The watertight hit is a subset of the closed-set answer; when the component crosses the
  // interior (all three exact edge signs nonzero) both agree, with the same point.
  const TriangleHit<T> h = watertight_hit(a, tri);
  if (h.hit) {
    EXPECT_NE(e.kind, ex::QKind::empty) << "a watertight hit outside the closed triangle";
  }
  if (e.kind == ex::QKind::point) {
    mpq_class s0, t0;
    ex::st_of(qt, e.point[0], s0, t0);
    const bool interior = s0 > 0 && t0 > 0 && s0 + t0 < 1 && ex::qdot(n, ql.d) != 0;
    if (interior) {
      ASSERT_TRUE(h.hit);
      EXPECT_EQ(h.point, r.point[0]);
      EXPECT_EQ(h.t, r.param_a[0]);
      EXPECT_EQ(h.front, ex::qdot(n, ql.d) < 0);
      EXPECT_NEAR(double(h.barycentric.x + h.barycentric.y + h.barycentric.z), 1.0, 4 * eps);
    }
  }
}

TYPED_TEST(IntersectionLinear3, TriangleRandomAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  Worst worst;
  int hits = 0;
  for_each_linear<T>([&]<class A>() {
    SCOPED_TRACE(Make<A>::name);
    for (int i = 0; i < 3000; ++i) {
      const Triangle3<T> tri{rng.vec<T, 3>(-1, 1), rng.vec<T, 3>(-1, 1), rng.vec<T, 3>(-1, 1)};
      const A a = Make<A>::from(rng.vec<T, 3>(-1, 1), rng.vec<T, 3>(-1, 1));
      check_triangle<T>(a, tri, &worst);
      hits += intersects(a, tri) ? 1 : 0;
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(hits, 300);
  std::printf("[ measured ] triangle: worst error / (eps m / sin angle) = %.3g\n", worst.ratio);
}

// Small integer grids: components through edges and vertices, lying in the triangle's plane
// (coplanar overlaps of every shape), zero directions, degenerate triangles.
TYPED_TEST(IntersectionLinear3, TriangleIntegerDegeneracies) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int kinds[5] = {0, 0, 0, 0, 0};
  int coplanar_points = 0;
  for_each_linear<T>([&]<class A>() {
    SCOPED_TRACE(Make<A>::name);
    for (int i = 0; i < 4000; ++i) {
      const auto g = [&] {
        // Every other case in the plane z = 0 (coplanar configurations).
        return Vec3<T>{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2)),
                       i % 2 ? T(0) : T(rng.uniform_int(-1, 1))};
      };
      const Triangle3<T> tri{g(), g(), g()};
      const A a = Make<A>::from(g(), g());
      check_triangle<T>(a, tri);
      const ex::QResult e = ex::triangle(ex::ql(a), ex::qt(tri));
      ++kinds[static_cast<int>(e.kind)];
      if (i % 2 && e.kind == ex::QKind::point) ++coplanar_points;
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(kinds[1], 1000);
  EXPECT_GT(kinds[2], 300);
  EXPECT_GT(coplanar_points, 100);
}

// Axis permutations, sign flips and integer translations are exact on the grid: the decisions
// (kind, count, intersects) and, for translations and power-of-two scaling, the watertight
// decision are unchanged; points move with the motion.
TYPED_TEST(IntersectionLinear3, ExactMotionsAndScaling) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for_each_linear<T>([&]<class A>() {
    SCOPED_TRACE(Make<A>::name);
    for (int i = 0; i < 600; ++i) {
      std::vector<Vec3<T>> pts(5);
      for (auto& p : pts)
        p = i % 2 ? Vec3<T>{T(rng.uniform_int(-3, 3)), T(rng.uniform_int(-3, 3)),
                            T(rng.uniform_int(-3, 3))}
                  : rng.vec<T, 3>(-1, 1);
      const int perm = rng.uniform_int(0, 5);
      const Vec3<T> flip{rng.uniform_int(0, 1) ? T(1) : T(-1), rng.uniform_int(0, 1) ? T(1) : T(-1),
                         rng.uniform_int(0, 1) ? T(1) : T(-1)};
      const Vec3<T> shift{T(rng.uniform_int(-4, 4)), T(rng.uniform_int(-4, 4)),
                          T(rng.uniform_int(-4, 4))};
      static constexpr int P[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                      {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
      const auto motion = [&](const Vec3<T>& p) {
        Vec3<T> q{};
        for (int k = 0; k < 3; ++k) q[k] = flip[k] * p[P[perm][k]];
        return q;
      };
      const auto run = [&](auto f) {
        const A a = Make<A>::from(f(pts[0]), f(pts[1]));
        const Triangle3<T> tri{f(pts[2]), f(pts[3]), f(pts[4])};
        const Plane3<T> pl{f(pts[3]) - f(pts[2]), T(0)};
        return std::tuple{intersection(a, tri), watertight_hit(a, tri), intersection(a, pl)};
      };
      const auto [r0, h0, p0] = run([](const Vec3<T>& p) { return p; });
      const auto [r1, h1, p1] = run(motion);
      EXPECT_EQ(r1.kind, r0.kind);
      EXPECT_EQ(r1.count, r0.count);
      if (i % 2) {  // integer translations are exact on the grid
        const auto [r2, h2, p2] = run([&](const Vec3<T>& p) { return p + shift; });
        EXPECT_EQ(r2.kind, r0.kind);
        EXPECT_EQ(h2.hit, h0.hit);
        EXPECT_EQ(h2.front, h0.front);
      }
      for (const int k : locus_test::scale_exponents<T>()) {
        const auto [r3, h3, p3] = run([&](const Vec3<T>& p) { return locus_test::scaled(p, k); });
        EXPECT_EQ(r3.kind, r0.kind);
        EXPECT_EQ(r3.count, r0.count);
        EXPECT_EQ(h3.hit, h0.hit);
        EXPECT_EQ(h3.front, h0.front);
        EXPECT_EQ(p3.kind, p0.kind);
        for (std::size_t j = 0; j < static_cast<std::size_t>(r0.count); ++j) {
          EXPECT_EQ(r3.point[j], locus_test::scaled(r0.point[j], k));
          EXPECT_EQ(r3.param_a[j], r0.param_a[j]);
        }
        for (std::size_t j = 0; j < static_cast<std::size_t>(p0.count); ++j) {
          EXPECT_EQ(p3.param_a[j], p0.param_a[j]);
        }
      }
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
}

// Book figure 11.2 style: a ray through a unit triangle's interior, edge and vertex; front and
// back; barycentrics worked by hand.
TYPED_TEST(IntersectionLinear3, BookConfigurations) {
  using T = TypeParam;
  const Triangle3<T> tri{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  const Ray3<T> down{{1, 2, 5}, {0, 0, -1}};
  const auto r = intersection(down, tri);
  ASSERT_EQ(r.kind, Kind::point);
  EXPECT_EQ(r.point[0], (Vec3<T>{1, 2, 0}));
  EXPECT_EQ(r.param_a[0], T(5));
  EXPECT_EQ(r.param_b[0], (Vec2<T>{T(0.25), T(0.5)}));
  const TriangleHit<T> h = watertight_hit(down, tri);
  EXPECT_TRUE(h.hit);
  EXPECT_TRUE(h.front);  // N = (0, 0, 16): the ray comes from +z
  EXPECT_EQ(h.barycentric, (Vec3<T>{T(0.25), T(0.25), T(0.5)}));
  EXPECT_FALSE(watertight_hit(Ray3<T>{{1, 2, -5}, {0, 0, -1}}, tri).hit);
  EXPECT_FALSE(watertight_hit(Ray3<T>{{1, 2, -5}, {0, 0, 1}}, tri).front);
  // Through the vertex v1, along the edge plane: closed-set hit at the vertex exactly.
  const auto v = intersection(Segment3<T>{{4, 0, 3}, {4, 0, -3}}, tri);
  ASSERT_EQ(v.kind, Kind::point);
  EXPECT_EQ(v.point[0], tri.v1);
  EXPECT_EQ(v.param_b[0], (Vec2<T>{1, 0}));
  // In the plane: a line crossing two edges gives the chord.
  const auto c = intersection(Line3<T>{{0, 1, 0}, {1, 0, 0}}, tri);
  ASSERT_EQ(c.kind, Kind::segment);
  EXPECT_EQ(c.point[0], (Vec3<T>{0, 1, 0}));
  EXPECT_EQ(c.point[1], (Vec3<T>{3, 1, 0}));
  // Line-plane (figure 11.1): the crossing of the line x = y = z with z = 2.
  const auto p = intersection(Line3<T>{{0, 0, 0}, {1, 1, 1}}, Plane3<T>{{0, 0, 1}, 2});
  ASSERT_EQ(p.kind, Kind::point);
  EXPECT_EQ(p.point[0], (Vec3<T>{2, 2, 2}));
}

// Zero directions and degenerate triangles / planes have documented answers.
TYPED_TEST(IntersectionLinear3, DegenerateInputs) {
  using T = TypeParam;
  const Triangle3<T> tri{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  const auto inside = intersection(Ray3<T>{{1, 1, 0}, {0, 0, 0}}, tri);
  ASSERT_EQ(inside.kind, Kind::point);
  EXPECT_EQ(inside.point[0], (Vec3<T>{1, 1, 0}));
  EXPECT_EQ(intersection(Ray3<T>{{1, 1, 1}, {0, 0, 0}}, tri).kind, Kind::empty);
  EXPECT_FALSE(watertight_hit(Ray3<T>{{1, 1, 0}, {0, 0, 0}}, tri).hit);
  const Triangle3<T> flat{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  EXPECT_EQ(intersection(Segment3<T>{{1, 1, -1}, {1, 1, 3}}, flat).kind, Kind::empty);
  EXPECT_FALSE(watertight_hit(Segment3<T>{{0, 1, 1}, {2, 1, 1}}, flat).hit);
  EXPECT_EQ(intersection(Line3<T>{{0, 0, 0}, {1, 0, 0}}, Plane3<T>{{0, 0, 0}, 0}).kind,
            Kind::empty);
  const auto pt = intersection(Segment3<T>{{1, 2, 3}, {1, 2, 3}}, Plane3<T>{{0, 0, 1}, 3});
  ASSERT_EQ(pt.kind, Kind::point);
  EXPECT_EQ(pt.point[0], (Vec3<T>{1, 2, 3}));
}

TYPED_TEST(IntersectionLinear3, NonFiniteInputGivesEmpty) {
  using T = TypeParam;
  const T bad[3] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                    -std::numeric_limits<T>::infinity()};
  for_each_linear<T>([&]<class A>() {
    const Vec3<T> p0{1, 1, -1}, p1{1, 1, 1};
    Vec3<T> tv[3] = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    ASSERT_TRUE(intersects(Make<A>::from(p0, p1), Triangle3<T>{tv[0], tv[1], tv[2]}));
    for (const T v : bad) {
      for (int which = 0; which < 15; ++which) {
        Vec3<T> pts[5] = {p0, p1, tv[0], tv[1], tv[2]};
        pts[which / 3][which % 3] = v;
        const A a = Make<A>::from(pts[0], pts[1]);
        const Triangle3<T> tri{pts[2], pts[3], pts[4]};
        EXPECT_EQ(intersection(a, tri).kind, Kind::empty);
        EXPECT_FALSE(intersects(a, tri));
        EXPECT_FALSE(watertight_hit(a, tri).hit);
        // The plane is built from pts[3] and pts[4].x; it crosses the finite component.
        const Plane3<T> pl{pts[3] + Vec3<T>{0, 0, 1}, pts[4].x};
        if (which < 6 || (which >= 9 && which <= 12)) {
          EXPECT_EQ(intersection(a, pl).kind, Kind::empty) << which;
          EXPECT_FALSE(intersects(a, pl));
        }
      }
    }
  });
}

// The exact predicates of core/plane_side.hpp against GMP on random and near-degenerate data.
TYPED_TEST(IntersectionLinear3, PlaneSidePredicatesAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto sgn = [](const mpq_class& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); };
  int zeros = 0;
  for (int i = 0; i < 20000; ++i) {
    Vec3<T> n = rng.unit<T, 3>(), p = rng.vec<T, 3>(-1, 1), d = rng.vec<T, 3>(-1, 1),
            a = rng.vec<T, 3>(-1, 1), b = rng.vec<T, 3>(-1, 1);
    T c = dot(n, p);
    if (i % 4 == 1) {  // near-degenerate: p a few ulps off the plane, d nearly in it
      p.x = std::nextafter(p.x, T(2));
      d = cross(n, d);
    } else if (i % 4 == 2) {  // exact degeneracies on a grid
      const auto g = [&] {
        return Vec3<T>{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2)),
                       T(rng.uniform_int(-2, 2))};
      };
      n = g(), p = g(), d = g(), a = g(), b = g();
      c = T(rng.uniform_int(-3, 3));
      if (i % 8 == 2) a = p + T(rng.uniform_int(-2, 2)) * d;  // the edge meets the line
    } else if (i % 4 == 3) {                                  // tiny and huge magnitudes
      const int e = rng.uniform_int(-60, 60);
      n = locus_test::scaled(n, e), d = locus_test::scaled(d, -e);
      c = dot(n, p);
    }
    const ex::Q3 qn = ex::q(n), qp = ex::q(p), qd = ex::q(d), qa = ex::q(a), qb = ex::q(b);
    const int e1 = sgn(ex::qdot(qn, qp) - mpq_class(double(c)));
    ASSERT_EQ(to_int(side_of_plane(n, c, p)), e1) << i;
    ASSERT_EQ(to_int(sign_of_dot(n, d)), sgn(ex::qdot(qn, qd))) << i;
    const int e3 = sgn(ex::qdot(qd, ex::qcross(qa - qp, qb - qp)));
    ASSERT_EQ(to_int(line_edge_side(p, d, a, b)), e3) << i;
    zeros += (e1 == 0) + (e3 == 0);
    const double v = plane_value(n, c, p);
    if (v != 0) {
      EXPECT_EQ(v > 0 ? 1 : -1, e1);
    }
  }
  EXPECT_GT(zeros, 500);
}

}  // namespace
