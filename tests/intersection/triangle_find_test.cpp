// SPDX-License-Identifier: BSL-1.0
// Row int3.plane-triangle (triangle-triangle find): intersection(Triangle3, Triangle3), float and
// double. Oracle in GMP rationals, independent of the library's method (which orders interval
// ends by orient3d signs and clips symbolically): not coplanar, each triangle's rational points
// in the other plane are projected on D = n_a x n_b and the two intervals intersected; coplanar,
// a is clipped by b's three edge half-planes in rationals and the area vector compared. Checks:
// kind (and its agreement with the exact intersects), points within the header's bound of the
// oracle's, parameters reproducing the points, order along D, polygon area; integer grids
// (shared edges and vertices, touching, coplanar, degenerate), figure 11.27, NaN, swap, scaling.

#include <locus/intersection/triangle_triangle.hpp>

#include "intersection/linear3_oracle.hpp"
#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace locus;
using locus_test::Rng;
using locus_test::exact3::is_zero;
using locus_test::exact3::q;
using locus_test::exact3::Q3;
using locus_test::exact3::qcross;
using locus_test::exact3::qdot;

template <class T>
class TriangleFind : public ::testing::Test {};
TYPED_TEST_SUITE(TriangleFind, locus_test::RealTypes);

struct Oracle {
  Kind kind = Kind::empty;
  std::vector<Q3> pts;  // segment/point: its ends; polygon: the clipped vertices
  Q3 area{};            // polygon: twice the area vector
  bool coplanar = false;
};

void add_unique(std::vector<Q3>& v, const Q3& x) {
  for (const Q3& y : v) {
    if (y == x) return;
  }
  v.push_back(x);
}

// Points of triangle v in the plane { X : dot(n, X - o) = 0 } (not containing v).
std::vector<Q3> plane_points(const Q3 v[3], const Q3& n, const Q3& o) {
  std::vector<Q3> out;
  mpq_class f[3];
  for (int i = 0; i < 3; ++i) f[i] = qdot(n, v[i] - o);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (f[i] == 0) add_unique(out, v[i]);
    if (f[i] * f[j] < 0) add_unique(out, v[i] + (f[i] / (f[i] - f[j])) * (v[j] - v[i]));
  }
  return out;
}

template <class T>
Oracle oracle(const Triangle3<T>& ta, const Triangle3<T>& tb) {
  const Q3 a[3] = {q(ta.v0), q(ta.v1), q(ta.v2)}, b[3] = {q(tb.v0), q(tb.v1), q(tb.v2)};
  const Q3 na = qcross(a[1] - a[0], a[2] - a[0]), nb = qcross(b[1] - b[0], b[2] - b[0]);
  Oracle o;
  const Q3 d = qcross(na, nb);
  if (!is_zero(d)) {
    const std::vector<Q3> pa = plane_points(a, nb, b[0]), pb = plane_points(b, na, a[0]);
    if (pa.empty() || pb.empty()) return o;
    const auto lo_hi = [&](const std::vector<Q3>& p, Q3& lo, Q3& hi) {
      lo = hi = p[0];
      for (const Q3& x : p) {
        if (qdot(d, x) < qdot(d, lo)) lo = x;
        if (qdot(d, x) > qdot(d, hi)) hi = x;
      }
    };
    Q3 la, ha, lb, hb;
    lo_hi(pa, la, ha);
    lo_hi(pb, lb, hb);
    const Q3 lo = qdot(d, la) >= qdot(d, lb) ? la : lb;
    const Q3 hi = qdot(d, ha) <= qdot(d, hb) ? ha : hb;
    const mpq_class len = qdot(d, hi) - qdot(d, lo);
    if (len < 0) return o;
    o.kind = len == 0 ? Kind::point : Kind::segment;
    o.pts = {lo};
    if (len > 0) o.pts.push_back(hi);
    return o;
  }
  // Coplanar (callers pass non-degenerate triangles; parallel distinct planes give empty).
  if (qdot(na, b[0] - a[0]) != 0) return o;
  o.coplanar = true;
  std::vector<Q3> poly(a, a + 3);
  for (int j = 0; j < 3; ++j) {
    const Q3 e = b[(j + 1) % 3] - b[j];
    const auto side = [&](const Q3& x) { return qdot(qcross(e, x - b[j]), nb); };
    std::vector<Q3> next;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Q3& p = poly[k];
      const Q3& r = poly[(k + 1) % poly.size()];
      const mpq_class sp = side(p), sr = side(r);
      if (sp >= 0) add_unique(next, p);
      if (sp * sr < 0) add_unique(next, p + (sp / (sp - sr)) * (r - p));
    }
    poly = next;
  }
  if (poly.empty()) return o;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    o.area = o.area + qcross(poly[k], poly[(k + 1) % poly.size()]);
  }
  o.pts = poly;
  if (!is_zero(o.area)) {
    o.kind = Kind::polygon;
  } else {
    o.kind = poly.size() == 1 ? Kind::point : Kind::segment;
  }
  return o;
}

double dist_inf(const Vec3<double>& x, const Q3& y) {
  return std::max(
      {std::abs(x.x - y.x.get_d()), std::abs(x.y - y.y.get_d()), std::abs(x.z - y.z.get_d())});
}

// The header's bound for a crossing of an edge with the other triangle's plane, taken over the
// crossing edges of both: 2^-49 L^3 / |n| / sin(angle) + 4 eps |X|.
template <class T>
double bound(const Triangle3<T>& a, const Triangle3<T>& b) {
  double l = 0, worst = 0, mag = 0;
  const Triangle3<double> t[2] = {
      {vec_cast<double>(a.v0), vec_cast<double>(a.v1), vec_cast<double>(a.v2)},
      {vec_cast<double>(b.v0), vec_cast<double>(b.v1), vec_cast<double>(b.v2)}};
  for (int u = 0; u < 2; ++u) {
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) mag = std::max(mag, std::abs(t[u][i][k]));
      for (int j = 0; j < 3; ++j) l = std::max(l, length(t[u][i] - t[1 - u][j]));
    }
  }
  for (int u = 0; u < 2; ++u) {
    const Vec3<double> n = cross(t[1 - u].v1 - t[1 - u].v0, t[1 - u].v2 - t[1 - u].v0);
    for (int i = 0; i < 3; ++i) {
      const Vec3<double> e = t[u][(i + 1) % 3] - t[u][i];
      const double s = std::abs(dot(n, e)) / (length(n) * length(e));
      if (s > 0) worst = std::max(worst, 1.0 / (length(n) * s));
    }
  }
  return std::ldexp(1.0, -49) * l * l * l * worst + 4 * double(eps_v<T>) * mag;
}

template <class T>
void check(const Triangle3<T>& a, const Triangle3<T>& b, const std::string& where) {
  SCOPED_TRACE(where);
  const TriangleTriangleIntersection<T> r = intersection(a, b);
  ASSERT_EQ(r.kind != Kind::empty, intersects(a, b));
  if (is_degenerate(a) || is_degenerate(b)) return;
  const Oracle o = oracle(a, b);
  ASSERT_EQ(r.kind, o.kind);
  if (o.kind == Kind::empty) return;
  const double tol = o.kind == Kind::polygon ? 8 * double(eps_v<T>) * 4 : bound(a, b);
  for (int i = 0; i < r.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec3<double> x = vec_cast<double>(r.point[k]);
    double best = 1e300;
    for (const Q3& y : o.pts) best = std::min(best, dist_inf(x, y));
    EXPECT_LE(best, o.kind == Kind::polygon ? 64 * double(eps_v<T>) * 4 : tol) << "point " << i;
    // Parameters give the point back on both triangles.
    const Vec2<T> sa = r.param_a[k], sb = r.param_b[k];
    const Vec3<double> pa = vec_cast<double>(a.v0) + double(sa.x) * vec_cast<double>(a.v1 - a.v0) +
                            double(sa.y) * vec_cast<double>(a.v2 - a.v0);
    const Vec3<double> pb = vec_cast<double>(b.v0) + double(sb.x) * vec_cast<double>(b.v1 - b.v0) +
                            double(sb.y) * vec_cast<double>(b.v2 - b.v0);
    EXPECT_LE(length(pa - x), 1e3 * tol + 1e-4) << "param_a " << i;
    EXPECT_LE(length(pb - x), 1e3 * tol + 1e-4) << "param_b " << i;
  }
  if (o.kind == Kind::polygon) {
    Vec3<double> area{};
    for (int i = 0; i < r.count; ++i) {
      area += cross(vec_cast<double>(r.point[static_cast<std::size_t>(i)]),
                    vec_cast<double>(r.point[static_cast<std::size_t>((i + 1) % r.count)]));
    }
    const double want = std::sqrt(qdot(o.area, o.area).get_d());
    EXPECT_NEAR(length(area), want, 256 * double(eps_v<T>) * (want + 16));
    // Same orientation as a.
    EXPECT_GT(dot(area, vec_cast<double>(cross(a.v1 - a.v0, a.v2 - a.v0))), 0.0);
  }
  if (r.kind == Kind::segment && !o.coplanar &&
      dist_inf(vec_cast<double>(r.point[0]), o.pts[0]) > tol) {
    ADD_FAILURE() << "segment not ordered along n_a x n_b";
  }
  // Swapped arguments: the same kind.
  EXPECT_EQ(intersection(b, a).kind, r.kind);
}

TYPED_TEST(TriangleFind, RandomAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int hits = 0;
  for (int trial = 0; trial < 120; ++trial) {
    Triangle3<T> a, b;
    for (int i = 0; i < 3; ++i) {
      a[i] = rng.template vec<T, 3>(T(-1), T(1));
      b[i] = rng.template vec<T, 3>(T(-1), T(1));
    }
    hits += intersects(a, b);
    check(a, b, "trial " + std::to_string(trial));
  }
  EXPECT_GT(hits, 15);
}

// Coplanar random pairs: both in the plane z = x / 2 + y / 4 (exact for these coordinates).
TYPED_TEST(TriangleFind, CoplanarRandom) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int polys = 0;
  for (int trial = 0; trial < 100; ++trial) {
    Triangle3<T> t[2];
    for (auto& tri : t) {
      for (int i = 0; i < 3; ++i) {
        const T x = T(rng.uniform_int(-64, 64)) / 64, y = T(rng.uniform_int(-64, 64)) / 64;
        tri[i] = {x, y, x / 2 + y / 4};
      }
    }
    if (is_degenerate(t[0]) || is_degenerate(t[1])) continue;
    polys += intersection(t[0], t[1]).kind == Kind::polygon;
    check(t[0], t[1], "trial " + std::to_string(trial));
  }
  EXPECT_GT(polys, 10);
}

// Integer grids: shared edges and vertices, touching, coplanar and degenerate triangles.
TYPED_TEST(TriangleFind, IntegerGrid) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int kinds[8] = {};
  for (int trial = 0; trial < 400; ++trial) {
    Triangle3<T> a, b;
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) {
        a[i][k] = T(rng.uniform_int(0, 2));
        b[i][k] = T(rng.uniform_int(0, 2));
      }
    }
    // Often share a vertex or an edge.
    if (trial % 3 == 0) b.v0 = a.v1;
    if (trial % 6 == 0) b.v1 = a.v2;
    ++kinds[static_cast<int>(intersection(a, b).kind)];
    check(a, b, "trial " + std::to_string(trial));
  }
  EXPECT_GT(kinds[static_cast<int>(Kind::point)], 4);
  EXPECT_GT(kinds[static_cast<int>(Kind::segment)], 4);
  EXPECT_GT(kinds[static_cast<int>(Kind::polygon)], 1);
}

// Figure 11.27: (a) parallel planes, (b) coplanar, (c) crossing, (d) planes cross, triangles not.
TYPED_TEST(TriangleFind, Figure11_27) {
  using T = TypeParam;
  const Triangle3<T> a{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  const Triangle3<T> par{{0, 0, 1}, {4, 0, 1}, {0, 4, 1}};
  const Triangle3<T> cop{{1, 1, 0}, {5, 1, 0}, {1, 5, 0}};
  const Triangle3<T> crs{{1, 1, -1}, {1, 1, 1}, {3, -1, 0}};
  const Triangle3<T> miss{{5, 5, -1}, {5, 5, 1}, {7, 3, 0}};
  EXPECT_EQ(intersection(a, par).kind, Kind::empty);
  EXPECT_EQ(intersection(a, cop).kind, Kind::polygon);
  EXPECT_EQ(intersection(a, crs).kind, Kind::segment);
  EXPECT_EQ(intersection(a, miss).kind, Kind::empty);
  for (const auto* t : {&par, &cop, &crs, &miss}) check(a, *t, "figure");
  // Shared edge from opposite sides (a hinge): the edge; a vertex touch: that vertex.
  const Triangle3<T> hinge{{4, 0, 0}, {0, 4, 0}, {3, 3, 2}};
  auto r = intersection(a, hinge);
  ASSERT_EQ(r.kind, Kind::segment);
  EXPECT_TRUE((r.point[0] == a.v1 && r.point[1] == a.v2) ||
              (r.point[0] == a.v2 && r.point[1] == a.v1));
  const Triangle3<T> touch{{4, 0, 0}, {5, 0, 1}, {5, 1, -1}};
  r = intersection(a, touch);
  ASSERT_EQ(r.kind, Kind::point);
  EXPECT_EQ(r.point[0], a.v1);
}

TYPED_TEST(TriangleFind, NonFiniteAndScaling) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Triangle3<T> a{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  EXPECT_EQ(intersection(a, Triangle3<T>{{nan, 1, -1}, {1, 1, 1}, {3, -1, 0}}).kind, Kind::empty);
  Rng rng(11);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 100; ++trial) {
    Triangle3<T> x, y;
    for (int i = 0; i < 3; ++i) {
      x[i] = rng.template vec<T, 3>(T(-1), T(1));
      y[i] = rng.template vec<T, 3>(T(-1), T(1));
    }
    const auto r = intersection(x, y);
    const T f = std::ldexp(T(1), 16);
    const auto s = intersection(Triangle3<T>{x.v0 * f, x.v1 * f, x.v2 * f},
                                Triangle3<T>{y.v0 * f, y.v1 * f, y.v2 * f});
    ASSERT_EQ(s.kind, r.kind);
    ASSERT_EQ(s.count, r.count);
    for (int i = 0; i < r.count; ++i) {
      EXPECT_EQ(s.point[static_cast<std::size_t>(i)], r.point[static_cast<std::size_t>(i)] * f);
    }
  }
}

}  // namespace
