// SPDX-License-Identifier: BSL-1.0
// Row int3.linear-polygon: Line3, Ray3 and Segment3 against a filled PlanarPolygon3 and a Disk3,
// float and double. Oracle (GMP rationals): the crossing X of the component with the plane
// {dot(normal, X - origin) = 0} of the data as given, its frame coordinates
// ((X - origin).u, (X - origin).v), and the closed region test in rationals (crossing number
// with exact boundary detection; |X - center|^2 <= r^2). For a polygon the library rounds X
// before the 2D test, so random cases are compared where the exact frame point is farther than
// 1e-9 from the region's boundary; exact frames (the xy plane, axis-aligned) on integer grids are
// compared always, including touching vertices and edges. A disk's rim is exact: every case is
// compared, and near-rim cases (on the rim, one ulp off) with dyadic data check it. In-plane
// components: the span of common parameters against a rational slab clip (axis-aligned square) and
// the chord's end points on the circle. Also: points on the component and in the plane, swap
// symmetry, degenerate and NaN input.

#include <locus/containment/point_in_polygon.hpp>
#include <locus/core/plane_crossing_ball.hpp>
#include <locus/intersection/line_disk.hpp>
#include <locus/intersection/line_polygon.hpp>
#include <locus/intersection/ray_disk.hpp>
#include <locus/intersection/ray_polygon.hpp>
#include <locus/intersection/segment_disk.hpp>
#include <locus/intersection/segment_polygon.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "intersection/linear3_oracle.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;
namespace ex = locus_test::exact3;

template <class T>
class IntersectionPlanar3 : public ::testing::Test {};
TYPED_TEST_SUITE(IntersectionPlanar3, locus_test::RealTypes);

template <class P>
struct Make;
template <class T>
struct Make<Line3<T>> {
  static Line3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q - p}; }
};
template <class T>
struct Make<Ray3<T>> {
  static Ray3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q - p}; }
};
template <class T>
struct Make<Segment3<T>> {
  static Segment3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q}; }
};
template <class T, class F>
void for_each_linear(F&& f) {
  f.template operator()<Line3<T>>();
  f.template operator()<Ray3<T>>();
  f.template operator()<Segment3<T>>();
}

struct QFrame {
  ex::Q3 o, u, v, n;
};

// The exact crossing (kind 0 none, 1 point, 2 in the plane) and its frame coordinates.
struct QCross {
  int kind = 0;
  mpq_class t, s2, t2, rho2;  // rho2 = |X - origin|^2
};
inline QCross cross_plane(const ex::QLin& l, const QFrame& f) {
  const mpq_class v0 = ex::qdot(f.n, l.o - f.o), nd = ex::qdot(f.n, l.d);
  if (nd == 0) return {v0 == 0 ? 2 : 0, 0, 0, 0, 0};
  const mpq_class t = -v0 / nd;
  if (!ex::in_domain(l, t)) return {};
  const ex::Q3 x = l.o + t * l.d - f.o;
  return {1, t, ex::qdot(x, f.u), ex::qdot(x, f.v), ex::qdot(x, x)};
}

// Closed polygon test in rationals, and the distance (double) to its boundary.
inline bool q_in_polygon(const std::vector<std::pair<mpq_class, mpq_class>>& p, const mpq_class& x,
                         const mpq_class& y, double& dist) {
  bool in = false, on = false;
  dist = 1e300;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const auto& a = p[j];
    const auto& b = p[i];
    const mpq_class ex_ = b.first - a.first, ey = b.second - a.second;
    const mpq_class cr = ex_ * (y - a.second) - ey * (x - a.first);
    const mpq_class len2 = ex_ * ex_ + ey * ey;
    const mpq_class s = (ex_ * (x - a.first) + ey * (y - a.second)) / len2;
    double d;
    if (s < 0)
      d = std::hypot(mpq_class(x - a.first).get_d(), mpq_class(y - a.second).get_d());
    else if (s > 1)
      d = std::hypot(mpq_class(x - b.first).get_d(), mpq_class(y - b.second).get_d());
    else
      d = std::abs(cr.get_d()) / std::sqrt(len2.get_d());
    dist = std::min(dist, d);
    if (cr == 0 && s >= 0 && s <= 1) on = true;
    if ((a.second > y) != (b.second > y)) {
      const mpq_class xi = a.first + (y - a.second) * ex_ / ey;
      if (xi > x) in = !in;
    }
  }
  return on || in;
}

template <class T>
PlanarPolygon3<T> star_polygon(Rng& rng, const PlaneFrame3<T>& f, int n) {
  PlanarPolygon3<T> p{f, {}};
  for (int k = 0; k < n; ++k) {
    const double a = 2 * 3.141592653589793 * k / n, r = rng.uniform<double>(0.3, 1.2);
    p.polygon.vertices.push_back({T(r * std::cos(a)), T(r * std::sin(a))});
  }
  return p;
}

template <class T, class A>
void check_polygon(const A& a, const PlanarPolygon3<T>& poly, bool exact, int& compared) {
  const ex::QLin ql = ex::ql(a);
  const QFrame qf{ex::q(poly.frame.origin), ex::q(poly.frame.u), ex::q(poly.frame.v),
                  ex::q(poly.frame.normal)};
  const QCross c = cross_plane(ql, qf);
  const auto r = intersection(a, poly);
  EXPECT_EQ(intersects(a, poly), r.kind != Kind::empty);
  const auto s = intersection(poly, a);
  EXPECT_EQ(s.kind, r.kind);
  if (c.kind == 2) return;  // in the plane: PolygonInPlane
  if (c.kind == 0) {
    EXPECT_EQ(r.kind, Kind::empty);
    return;
  }
  std::vector<std::pair<mpq_class, mpq_class>> qp;
  for (const auto& v : poly.polygon.vertices)
    qp.push_back({mpq_class(double(v.x)), mpq_class(double(v.y))});
  double dist = 0;
  const bool in = q_in_polygon(qp, c.s2, c.t2, dist);
  if (!exact && dist < (std::is_same_v<T, float> ? 1e-5 : 1e-9)) return;
  ++compared;
  ASSERT_EQ(r.kind, in ? Kind::point : Kind::empty);
  if (!in) return;
  const double eps = double(eps_v<T>);
  const double m = std::max({1.0, ex::qmax_abs(ql.o), ex::qmax_abs(ql.d)});
  EXPECT_NEAR(double(r.param_b[0].x), c.s2.get_d(), 64 * eps * m);
  EXPECT_NEAR(double(r.param_b[0].y), c.t2.get_d(), 64 * eps * m);
  EXPECT_NEAR(double(r.param_a[0]), c.t.get_d(), 64 * eps * m / ex::qmax_abs(ql.d));
  EXPECT_EQ(s.param_a[0], r.param_b[0]);
  EXPECT_EQ(s.param_b[0], r.param_a[0]);
}

TYPED_TEST(IntersectionPlanar3, PolygonRandomAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int compared = 0, hits = 0;
  for_each_linear<T>([&]<class A>() {
    for (int i = 0; i < 2000; ++i) {
      const auto f = plane_frame(rng.vec<T, 3>(-1, 1), rng.unit<T, 3>());
      ASSERT_TRUE(f.has_value());
      const PlanarPolygon3<T> poly = star_polygon<T>(rng, *f, 3 + i % 7);
      const A a = Make<A>::from(rng.vec<T, 3>(-2, 2), rng.vec<T, 3>(-2, 2));
      check_polygon<T>(a, poly, false, compared);
      hits += intersects(a, poly) ? 1 : 0;
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(compared, 4000);  // the components that cross the plane
  EXPECT_GT(hits, 300);
}

// The xy plane with its exact frame: integer-grid components through vertices and edges of an
// integer polygon: every decision exact, no margin.
TYPED_TEST(IntersectionPlanar3, PolygonExactFrameGrid) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const PlaneFrame3<T> f{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  // A non-convex "L".
  const PlanarPolygon3<T> poly{f, Polygon2<T>{{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}}};
  int compared = 0, boundary = 0;
  for_each_linear<T>([&]<class A>() {
    for (int i = 0; i < 3000; ++i) {
      const auto g = [&](int z) {
        return Vec3<T>{T(rng.uniform_int(-1, 5)), T(rng.uniform_int(-1, 5)), T(z)};
      };
      const A a = Make<A>::from(g(-rng.uniform_int(1, 2)), g(rng.uniform_int(1, 2)));
      check_polygon<T>(a, poly, true, compared);
      const auto r = intersection(a, poly);
      if (r.kind == Kind::point) {
        const Vec2<T> st = r.param_b[0];
        boundary += (st.x == 0 || st.y == 0 || st.x == 4 || st.y == 4 || (st.x == 2 && st.y >= 2) ||
                     (st.y == 2 && st.x >= 2));
      }
      if (::testing::Test::HasFatalFailure()) return;
    }
  });
  EXPECT_GT(compared, 4000);
  EXPECT_GT(boundary, 200);
}

// Components in the polygon's plane: the span of common parameters (axis-aligned square: the
// rational slab interval).
TYPED_TEST(IntersectionPlanar3, PolygonInPlane) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const PlaneFrame3<T> f{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const PlanarPolygon3<T> sq{f, Polygon2<T>{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}};
  int kinds[3] = {0, 0, 0};
  for_each_linear<T>([&]<class A>() {
    for (int i = 0; i < 2000; ++i) {
      const auto g = [&] {
        return Vec3<T>{T(rng.uniform_int(-8, 8)) / 4, T(rng.uniform_int(-8, 8)) / 4, T(1)};
      };
      const A a = Make<A>::from(g(), g());
      const ex::QLin ql = ex::ql(a);
      // Exact slab clip of the square |x|, |y| <= 1.
      bool lo_inf = !ql.lo, hi_inf = !ql.hi, empty = false;
      mpq_class lo = 0, hi = 1;
      const mpq_class o[2] = {ql.o.x, ql.o.y}, d[2] = {ql.d.x, ql.d.y};
      bool moving = false;
      for (int k = 0; k < 2; ++k) {
        if (d[k] == 0) {
          if (o[k] < -1 || o[k] > 1) empty = true;
          continue;
        }
        moving = true;
        mpq_class ta = (-1 - o[k]) / d[k], tb = (1 - o[k]) / d[k];
        if (ta > tb) std::swap(ta, tb);
        if (lo_inf || ta > lo) lo = ta, lo_inf = false;
        if (hi_inf || tb < hi) hi = tb, hi_inf = false;
      }
      const auto r = intersection(a, sq);
      if (!moving) continue;  // a point: covered by the grid test
      const int kind = empty || lo > hi ? 0 : (lo == hi ? 1 : 2);
      ++kinds[kind];
      ASSERT_EQ(r.kind == Kind::empty ? 0 : (r.kind == Kind::point ? 1 : 2), kind) << i;
      if (kind == 2) {
        const double tol = 4 * double(eps_v<T>) * 16;  // params of |o|, |d| <= 2, bounded
        EXPECT_NEAR(double(r.param_a[0]), lo.get_d(), tol);
        EXPECT_NEAR(double(r.param_a[1]), hi.get_d(), tol);
      }
    }
  });
  EXPECT_GT(kinds[0], 300);
  EXPECT_GT(kinds[1], 20);
  EXPECT_GT(kinds[2], 1000);
}

TYPED_TEST(IntersectionPlanar3, DiskAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int compared = 0, hits = 0;
  for_each_linear<T>([&]<class A>() {
    for (int i = 0; i < 3000; ++i) {
      const Disk3<T> d{rng.vec<T, 3>(-1, 1), rng.unit<T, 3>(), rng.uniform<T>(T(0.2), T(1.5))};
      const A a = Make<A>::from(rng.vec<T, 3>(-2, 2), rng.vec<T, 3>(-2, 2));
      const CircleAxes<T> ax = in_plane_axes(d);
      const ex::QLin ql = ex::ql(a);
      const QFrame qf{ex::q(d.center), ex::q(ax.u), ex::q(ax.v), ex::q(d.normal)};
      const QCross c = cross_plane(ql, qf);
      const auto r = intersection(a, d);
      EXPECT_EQ(intersects(a, d), r.kind != Kind::empty);
      EXPECT_EQ(intersection(d, a).kind, r.kind);
      if (c.kind != 1) continue;
      const mpq_class rr = mpq_class(double(d.radius)) * double(d.radius);
      ++compared;  // the rim is exact: every case is compared
      ASSERT_EQ(r.kind, c.rho2 <= rr ? Kind::point : Kind::empty) << i;
      if (r.kind == Kind::point) {
        ++hits;
        EXPECT_TRUE(
            locus_test::vec_near(point_at(d, r.param_b[0]), r.point[0], T(64 * eps_v<T> * 4)));
        EXPECT_TRUE(
            locus_test::vec_near(point_at(a, r.param_a[0]), r.point[0], T(64 * eps_v<T> * 4)));
      }
    }
  });
  EXPECT_GT(compared, 5000);
  EXPECT_GT(hits, 500);
}

// In the plane of a non-convex polygon intersection() is the span from the first to the last
// common point; the pieces, from the 2D query by the recipe below, are intersection_pieces()'s.
TYPED_TEST(IntersectionPlanar3, PolygonInPlanePieces) {
  using T = TypeParam;
  const PlaneFrame3<T> f{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const PlanarPolygon3<T> u{
      f, Polygon2<T>{{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}}};
  // The recipe: boundary crossings of the 2D segment, the ends, midpoints tested by contains().
  const auto pieces = [&](const Segment3<T>& s3) {
    const Segment2<T> s2{{s3.p0.x, s3.p0.y}, {s3.p1.x, s3.p1.y}};  // frame coordinates
    std::vector<T> cuts{T(0), T(1)};
    for (const auto& c : intersection(s2, u.polygon).crossings)
      for (int k = 0; k < c.count; ++k) cuts.push_back(c.param_a[static_cast<std::size_t>(k)]);
    std::sort(cuts.begin(), cuts.end());
    std::vector<std::pair<T, T>> out;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      if (cuts[k] == cuts[k + 1]) continue;
      const T mid = (cuts[k] + cuts[k + 1]) / 2;
      if (!contains(u.polygon, s2.p0 + mid * (s2.p1 - s2.p0))) continue;
      if (!out.empty() && out.back().second == cuts[k])
        out.back().second = cuts[k + 1];
      else
        out.push_back({cuts[k], cuts[k + 1]});
    }
    return out;
  };
  // Across both arms: the 3D answer spans the gap, the recipe gives the two pieces.
  const Segment3<T> across{{-1, 2, 1}, {4, 2, 1}};
  const auto r = intersection(across, u);
  ASSERT_EQ(r.kind, Kind::segment);
  EXPECT_EQ(r.param_a[0], T(0.2));
  EXPECT_EQ(r.param_a[1], T(0.8));
  const auto p = pieces(across);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0], (std::pair<T, T>{T(0.2), T(0.4)}));
  EXPECT_EQ(p[1], (std::pair<T, T>{T(0.6), T(0.8)}));
  EXPECT_EQ(p.front().first, r.param_a[0]);
  EXPECT_EQ(p.back().second, r.param_a[1]);
  // Through the notch's corner from inside to inside: one piece, the whole segment.
  const Segment3<T> corner{{0.5, 1.5, 1}, {1.5, 0.5, 1}};
  const auto c = intersection(corner, u);
  ASSERT_EQ(c.kind, Kind::segment);
  EXPECT_EQ(c.param_a[0], T(0));
  EXPECT_EQ(c.param_a[1], T(1));
  const auto q = pieces(corner);
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q[0], (std::pair<T, T>{T(0), T(1)}));
  // intersection_pieces() gives the recipe's pieces.
  for (const Segment3<T>& s : {across, corner}) {
    const auto want = pieces(s);
    const auto got = intersection_pieces(s, u);
    ASSERT_EQ(got.pieces.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(got.pieces[i].kind, Kind::segment);
      EXPECT_EQ(got.pieces[i].param_a[0], want[i].first);
      EXPECT_EQ(got.pieces[i].param_a[1], want[i].second);
    }
  }
}

// Near-rim crossings with exact data: a disk in a plane spanned by two orthogonal integer vectors
// u, v of equal length L, a rim point X = C + s (alpha u + beta v) from a Pythagorean triple
// (alpha, beta, gamma), radius r = s gamma L, all dyadic (exact in float). A component through X
// (exactly on the rim), or with its origin, the radius or the centre moved by one ulp; the GMP
// oracle decides |X - C|^2 <= r^2 for the crossing of the data as given. Also the core
// predicates directly (their exact path asserts its term count), and scaling by powers of two.
TYPED_TEST(IntersectionPlanar3, DiskRimExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  struct Pair {
    int u[3], v[3], len;
  };
  constexpr Pair frames[] = {{{1, 0, 0}, {0, 1, 0}, 1},
                             {{0, 0, 1}, {1, 0, 0}, 1},
                             {{2, 2, -1}, {2, -1, 2}, 3},
                             {{1, 2, 2}, {2, 1, -2}, 3},
                             {{2, 3, 6}, {6, 2, -3}, 7}};
  constexpr int triples[][3] = {{3, 4, 5}, {5, 12, 13}, {1, 0, 1}, {8, 15, 17}};
  const auto dyadic = [](int m, int e) { return T(std::ldexp(double(m), e)); };
  const auto qsign = [](const mpq_class& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); };
  const int big = std::is_same_v<T, float> ? 30 : 300;
  int rim = 0, in = 0, out = 0;
  for (int i = 0; i < 24; ++i) {  // few: the exact path runs in most cases
    const Pair& f = frames[rng.uniform_int(0, 4)];
    const int* tri = triples[rng.uniform_int(0, 3)];
    const bool swap = rng.uniform_int(0, 1) == 1;
    const int alpha = (swap ? tri[1] : tri[0]) * (rng.uniform_int(0, 1) ? 1 : -1);
    const int beta = (swap ? tri[0] : tri[1]) * (rng.uniform_int(0, 1) ? 1 : -1);
    const int sm = rng.uniform_int(1, 8);
    Vec3<T> c, x, n, dir;
    for (int k = 0; k < 3; ++k) c[k] = dyadic(rng.uniform_int(-64, 64), -3);
    for (int k = 0; k < 3; ++k) x[k] = c[k] + dyadic(sm * (alpha * f.u[k] + beta * f.v[k]), -4);
    n = {T(f.u[1] * f.v[2] - f.u[2] * f.v[1]), T(f.u[2] * f.v[0] - f.u[0] * f.v[2]),
         T(f.u[0] * f.v[1] - f.u[1] * f.v[0])};
    do {
      for (int k = 0; k < 3; ++k) dir[k] = T(rng.uniform_int(-4, 4));
    } while (dot(n, dir) == 0);
    const T tau = dyadic(rng.uniform_int(1, 4), -2), sigma = dyadic(rng.uniform_int(1, 4), -2);
    Vec3<T> p = x - tau * dir;
    const Vec3<T> q = x + sigma * dir;
    T r = dyadic(sm * tri[2] * f.len, -4);
    const T inf = std::numeric_limits<T>::infinity();
    switch (i % 6) {  // one ulp off the rim (or none)
      case 1:
        p.x = std::nextafter(p.x, inf);
        break;
      case 2:
        p.y = std::nextafter(p.y, -inf);
        break;
      case 3:
        r = std::nextafter(r, inf);
        break;
      case 4:
        r = std::nextafter(r, T(0));
        break;
      case 5:
        c.z = std::nextafter(c.z, inf);
        break;
      default:
        break;
    }
    const Disk3<T> d{c, n, r};
    const mpq_class rr = mpq_class(double(r)) * double(r);
    const QFrame qf{ex::q(c), ex::q(n), ex::q(n), ex::q(n)};
    // The core predicates on the carriers through (p, dir) and (p, q).
    const Vec3<double> pd = vec_cast<double>(p), qd = vec_cast<double>(q), cd = vec_cast<double>(c),
                       nd = vec_cast<double>(n), dd = vec_cast<double>(dir);
    const QCross line_x = cross_plane(ex::QLin{ex::q(p), ex::q(dir), false, false}, qf);
    const QCross seg_x = cross_plane(ex::QLin{ex::q(p), ex::q(q) - ex::q(p), false, false}, qf);
    ASSERT_EQ(line_x.kind, 1);
    ASSERT_EQ(seg_x.kind, 1);
    EXPECT_EQ(crossing_in_ball_line(pd, dd, cd, nd, double(r)), qsign(line_x.rho2 - rr)) << i;
    EXPECT_EQ(crossing_in_ball_segment(pd, qd, cd, nd, double(r)), qsign(seg_x.rho2 - rr)) << i;
    const int sx = qsign(seg_x.rho2 - rr);
    (sx == 0 ? rim : sx < 0 ? in : out) += 1;
    for_each_linear<T>([&]<class A>() {
      A a;
      if constexpr (std::is_same_v<A, Segment3<T>>)
        a = A{p, q};
      else
        a = A{p, dir};
      const QCross cr = cross_plane(ex::ql(a), qf);
      ASSERT_EQ(cr.kind, 1);
      const bool expected = cr.rho2 <= rr;
      const auto res = intersection(a, d);
      ASSERT_EQ(res.kind, expected ? Kind::point : Kind::empty) << i;
      EXPECT_EQ(intersects(a, d), expected) << i;
      // Scaling every input by 2^k (beyond the filter's range for double) keeps the answer.
      for (const int e : {i % 2 == 0 ? -big : big}) {
        A as = a;
        if constexpr (std::is_same_v<A, Segment3<T>>) {
          as.p0 = as.p0 * std::ldexp(T(1), e);
          as.p1 = as.p1 * std::ldexp(T(1), e);
        } else {
          as.origin = as.origin * std::ldexp(T(1), e);
        }
        const Disk3<T> ds{c * std::ldexp(T(1), e), n, r * std::ldexp(T(1), e)};
        // Only exact scalings (a one-ulp step off zero is subnormal and would underflow).
        const auto back = [&](const Vec3<T>& v, const Vec3<T>& w) {
          return v * std::ldexp(T(1), -e) == w;
        };
        bool exact = back(ds.center, c) && ds.radius * std::ldexp(T(1), -e) == r;
        if constexpr (std::is_same_v<A, Segment3<T>>)
          exact = exact && back(as.p0, a.p0) && back(as.p1, a.p1);
        else
          exact = exact && back(as.origin, a.origin);
        if (!exact) continue;
        EXPECT_EQ(intersects(as, ds), expected) << i << " 2^" << e;
      }
    });
  }
  EXPECT_GE(rim, 4);  // the unperturbed cases
  EXPECT_GE(in, 4);   // at least the larger radii
  EXPECT_GE(out, 4);  // at least the smaller radii
}

// Components in the disk's plane near tangency, exact data (frames and triples as above): the
// tangent at a rim point X, moved towards or away from the centre by 1/64 of the radius or with
// the radius one ulp off; rays and segments starting or ending at X. Oracle (GMP): the nearest
// point of the component to the centre against r decides empty / point / segment, exactly (a
// chord however short is a segment; its ends are rounded).
TYPED_TEST(IntersectionPlanar3, DiskInPlaneExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  constexpr int frames[][2][3] = {
      {{1, 0, 0}, {0, 1, 0}}, {{2, 2, -1}, {2, -1, 2}}, {{2, 3, 6}, {6, 2, -3}}};
  constexpr int triples[][2] = {{3, 4}, {5, 12}, {1, 0}};
  const int lens[] = {1, 3, 7}, hyps[] = {5, 13, 1};
  int kinds[3] = {0, 0, 0}, slivers = 0;
  for (int i = 0; i < 60; ++i) {
    const int fi = rng.uniform_int(0, 2), ti = rng.uniform_int(0, 2);
    const int alpha = triples[ti][0], beta = triples[ti][1];
    const int move = i % 5 - 2;  // -2, 2: radius one ulp off; -1, 1: the line moved; 0: tangent
    const int sm = 64 + (move == 1 || move == -1 ? move : 0);
    Vec3<T> c, x, tan, n;
    for (int k = 0; k < 3; ++k) c[k] = T(std::ldexp(double(rng.uniform_int(-64, 64)), -3));
    for (int k = 0; k < 3; ++k) {
      const int* u = frames[fi][0];
      const int* v = frames[fi][1];
      x[k] = c[k] + T(std::ldexp(double(sm * (alpha * u[k] + beta * v[k])), -8));
      tan[k] = T(-beta * u[k] + alpha * v[k]);
      n[k] = T(u[(k + 1) % 3] * v[(k + 2) % 3] - u[(k + 2) % 3] * v[(k + 1) % 3]);
    }
    T r = T(std::ldexp(double(64 * hyps[ti] * lens[fi]), -8));
    if (move == 2) r = std::nextafter(r, T(1e30));
    if (move == -2) r = std::nextafter(r, T(0));
    const Disk3<T> d{c, n, r};
    const mpq_class rr = mpq_class(double(r)) * double(r);
    const T tau = T(rng.uniform_int(1, 4)) / 4, sigma = T(rng.uniform_int(1, 4)) / 4;
    const auto check = [&](const auto& a, const ex::QLin& ql) {
      // The nearest parameter to the centre, clamped to the domain, and its squared distance.
      const ex::Q3 w = ql.o - ex::q(c);
      mpq_class t = -ex::qdot(w, ql.d) / ex::qdot(ql.d, ql.d);
      if (ql.lo && t < 0) t = 0;
      if (ql.hi && t > 1) t = 1;
      const ex::Q3 y = w + t * ql.d;
      const mpq_class m = ex::qdot(y, y);
      const auto res = intersection(a, d);
      EXPECT_EQ(intersects(a, d), m <= rr) << i;
      if (m > rr) {
        EXPECT_EQ(res.kind, Kind::empty) << i;
      } else if (m == rr) {
        EXPECT_EQ(res.kind, Kind::point) << i;
        ++kinds[1];
      } else {
        const double gap = mpq_class((rr - m) / rr).get_d();
        EXPECT_EQ(res.kind, Kind::segment) << i << " " << gap;
        if (res.kind == Kind::segment) {
          EXPECT_LE(res.param_a[0], res.param_a[1]) << i;
        }
        ++kinds[2];
        slivers += gap < 64 * double(eps_v<T>);
      }
      if (m > rr) ++kinds[0];
    };
    const Vec3<T> p = x - tau * tan, q = x + sigma * tan;
    const Line3<T> line{p, tan};
    check(line, ex::ql(line));
    const Ray3<T> from_x{x, tan}, to_x{p, tan}, away{x, -tan};
    check(from_x, ex::ql(from_x));
    check(to_x, ex::ql(to_x));
    check(away, ex::ql(away));
    const Segment3<T> seg{p, q}, end_x{p, x}, start_x{x, q};
    check(seg, ex::ql(seg));
    check(end_x, ex::ql(end_x));
    check(start_x, ex::ql(start_x));
  }
  EXPECT_GT(kinds[0], 20);
  EXPECT_GT(kinds[1], 20);
  EXPECT_GT(kinds[2], 20);
  EXPECT_GT(slivers, 3);  // chords shorter than the rounding of their ends
}

// A component in the disk's plane: the chord, its ends on the circle.
TYPED_TEST(IntersectionPlanar3, DiskChords) {
  using T = TypeParam;
  const Disk3<T> d{{1, 2, 3}, {0, 0, 2}, 2};
  const auto r = intersection(Line3<T>{{-5, 2, 3}, {1, 0, 0}}, d);
  ASSERT_EQ(r.kind, Kind::segment);
  EXPECT_NEAR(double(r.point[0].x), -1.0, 8 * double(eps_v<T>));
  EXPECT_NEAR(double(r.point[1].x), 3.0, 8 * double(eps_v<T>));
  EXPECT_EQ(intersection(Line3<T>{{-5, 4, 3}, {1, 0, 0}}, d).kind, Kind::point);  // tangent
  EXPECT_EQ(intersection(Ray3<T>{{1, 2, 3}, {0, 1, 0}}, d).kind, Kind::segment);
  EXPECT_EQ(intersection(Segment3<T>{{5, 2, 3}, {4, 2, 3}}, d).kind, Kind::empty);
  // Transversal through the centre and through the rim (exact frame coordinates here).
  const auto c = intersection(Segment3<T>{{1, 2, 0}, {1, 2, 6}}, d);
  ASSERT_EQ(c.kind, Kind::point);
  EXPECT_EQ(c.point[0], (Vec3<T>{1, 2, 3}));
  EXPECT_EQ(c.param_a[0], T(0.5));
  EXPECT_TRUE(intersects(Segment3<T>{{3, 2, 0}, {3, 2, 6}}, d));
  EXPECT_FALSE(intersects(Segment3<T>{{3.5, 2, 0}, {3.5, 2, 6}}, d));
}

TYPED_TEST(IntersectionPlanar3, DegenerateAndNonFinite) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const PlaneFrame3<T> f{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const PlanarPolygon3<T> sq{f, Polygon2<T>{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}};
  const Disk3<T> d{{0, 0, 0}, {0, 0, 1}, 1};
  const Segment3<T> through{{0, 0, -1}, {0, 0, 1}};
  ASSERT_TRUE(intersects(through, sq));
  ASSERT_TRUE(intersects(through, d));
  EXPECT_FALSE(intersects(Segment3<T>{{0, 0, nan}, {0, 0, 1}}, sq));
  EXPECT_FALSE(intersects(Segment3<T>{{0, 0, nan}, {0, 0, 1}}, d));
  EXPECT_FALSE(intersects(through, Disk3<T>{{0, 0, 0}, {0, 0, 0}, 1}));
  EXPECT_FALSE(intersects(through, Disk3<T>{{0, 0, 0}, {0, 0, 1}, -1}));
  EXPECT_FALSE(intersects(through, PlanarPolygon3<T>{f, Polygon2<T>{}}));
  PlanarPolygon3<T> bad = sq;
  bad.polygon.vertices[1].x = nan;
  EXPECT_FALSE(intersects(through, bad));
  // A zero direction acts as its point.
  EXPECT_EQ(intersection(Ray3<T>{{0.5, 0.5, 0}, {0, 0, 0}}, sq).kind, Kind::point);
  EXPECT_EQ(intersection(Ray3<T>{{0.5, 0.5, 1}, {0, 0, 0}}, d).kind, Kind::empty);
}

}  // namespace
