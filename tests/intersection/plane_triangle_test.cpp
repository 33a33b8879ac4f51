// SPDX-License-Identifier: BSL-1.0
// Row int3.plane-triangle (plane against triangle): intersects / intersection(Triangle3, Plane3),
// float and double, against an exact GMP oracle: the vertices' plane values in rationals, the
// common set as the distinct rational points (vertices in the plane, edge crossings), its kind
// from their number. Inputs: seeded random triangles and planes; integer grids with integer
// planes (vertices and edges in the plane, coplanar and degenerate triangles); figure 11.26's
// configurations; NaN/Inf; swap; power-of-two scaling (exact); the order along n x n_tri.

#include <locus/intersection/plane_triangle.hpp>

#include "intersection/linear3_oracle.hpp"
#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace locus;
using locus_test::Rng;
using locus_test::exact3::q;
using locus_test::exact3::Q3;
using locus_test::exact3::qcross;
using locus_test::exact3::qdot;

template <class T>
class PlaneTriangle : public ::testing::Test {};
TYPED_TEST_SUITE(PlaneTriangle, locus_test::RealTypes);

struct Oracle {
  Kind kind = Kind::empty;
  std::vector<Q3> pts;
};

template <class T>
Oracle oracle(const Triangle3<T>& t, const Plane3<T>& p) {
  const Q3 n = q(p.normal);
  const mpq_class c(double(p.constant));
  Q3 v[3];
  mpq_class f[3];
  for (int i = 0; i < 3; ++i) v[i] = q(t[i]), f[i] = qdot(n, v[i]) - c;
  Oracle o;
  const auto add = [&](const Q3& x) {
    for (const Q3& y : o.pts) {
      if (y == x) return;
    }
    o.pts.push_back(x);
  };
  const bool flat = locus_test::exact3::is_zero(qcross(v[1] - v[0], v[2] - v[0]));
  if (f[0] == 0 && f[1] == 0 && f[2] == 0) {
    for (int i = 0; i < 3; ++i) add(v[i]);
    o.kind = flat ? (o.pts.size() == 1 ? Kind::point : Kind::segment) : Kind::polygon;
    if (flat && o.pts.size() == 3) {
      // Collinear: keep the two extremes (the middle one is between them).
      for (int m = 0; m < 3; ++m) {
        const Q3 d1 = o.pts[m] - o.pts[(m + 1) % 3], d2 = o.pts[m] - o.pts[(m + 2) % 3];
        if (qdot(d1, d2) < 0) {
          o.pts.erase(o.pts.begin() + m);
          break;
        }
      }
    }
    return o;
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (f[i] == 0) add(v[i]);
    if (f[i] * f[j] < 0) {
      const mpq_class s = f[i] / (f[i] - f[j]);
      add(v[i] + s * (v[j] - v[i]));
    }
  }
  o.kind = o.pts.empty() ? Kind::empty : (o.pts.size() == 1 ? Kind::point : Kind::segment);
  return o;
}

template <class T>
double max_abs(const Triangle3<T>& t) {
  double m = 0;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) m = std::max(m, std::abs(double(t[i][k])));
  }
  return m;
}

// Checks r against the oracle: kind, every point near an oracle point (exact for vertices),
// parameters reproduce the point, segment order along cross(n, n_tri).
template <class T>
void check(const Triangle3<T>& t, const Plane3<T>& p, const std::string& where) {
  SCOPED_TRACE(where);
  const Oracle o = oracle(t, p);
  const TrianglePlaneIntersection<T> r = intersection(t, p);
  ASSERT_EQ(r.kind, o.kind);
  ASSERT_EQ(intersects(t, p), o.kind != Kind::empty);
  ASSERT_EQ(intersects(p, t), o.kind != Kind::empty);
  const auto s = intersection(p, t);
  ASSERT_EQ(s.kind, r.kind);
  if (o.kind == Kind::empty) return;
  ASSERT_EQ(r.count, o.kind == Kind::polygon ? 3 : static_cast<int>(o.pts.size()));
  const double m = max_abs(t);
  // Bound of the header: 8 eps max(|X|, m) (the angle term is far below for these inputs).
  const double bound = 16.0 * double(eps_v<T>) * std::max(m, 1e-300);
  for (int i = 0; i < r.count; ++i) {
    const Vec3<T> x = r.point[static_cast<std::size_t>(i)];
    ASSERT_EQ(s.point[static_cast<std::size_t>(i)], x);
    bool near = false;
    for (const Q3& y : o.pts) {
      const double d =
          std::max({std::abs(double(x.x) - y.x.get_d()), std::abs(double(x.y) - y.y.get_d()),
                    std::abs(double(x.z) - y.z.get_d())});
      near = near || d <= bound;
    }
    EXPECT_TRUE(near) << "point " << i;
    // The parameters give the point back.
    const Vec2<T> st = r.param_a[static_cast<std::size_t>(i)];
    const Vec3<double> back = vec_cast<double>(t.v0) +
                              double(st.x) * vec_cast<double>(t.v1 - t.v0) +
                              double(st.y) * vec_cast<double>(t.v2 - t.v0);
    EXPECT_LE(max_abs(Triangle3<double>{back - vec_cast<double>(x), {}, {}}), 4 * bound);
  }
  if (r.kind == Kind::segment && !is_degenerate(t)) {
    const Q3 d = qcross(q(p.normal), qcross(q(t.v1) - q(t.v0), q(t.v2) - q(t.v0)));
    EXPECT_GE(qdot(d, q(r.point[1]) - q(r.point[0])), 0) << "segment order";
  }
}

TYPED_TEST(PlaneTriangle, RandomAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int hits = 0;
  for (int trial = 0; trial < 150; ++trial) {
    Triangle3<T> t;
    for (int i = 0; i < 3; ++i) t[i] = rng.template vec<T, 3>(T(-1), T(1));
    const Vec3<T> n = rng.template vec<T, 3>(T(-1), T(1));
    const Plane3<T> p{n, rng.template uniform<T>(T(-0.5), T(0.5))};
    hits += intersects(t, p);
    check(t, p, "trial " + std::to_string(trial));
  }
  EXPECT_GT(hits, 15);
}

TYPED_TEST(PlaneTriangle, IntegerGridDegeneracies) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int kinds[8] = {};
  for (int trial = 0; trial < 400; ++trial) {
    Triangle3<T> t;
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) t[i][k] = static_cast<T>(rng.uniform_int(-2, 2));
    }
    const Vec3<T> n{T(rng.uniform_int(-1, 1)), T(rng.uniform_int(-1, 1)), T(rng.uniform_int(0, 1))};
    const Plane3<T> p{n, T(rng.uniform_int(-1, 1))};
    if (n == Vec3<T>{}) {
      EXPECT_EQ(intersection(t, p).kind, Kind::empty);
      continue;
    }
    ++kinds[static_cast<int>(oracle(t, p).kind)];
    check(t, p, "trial " + std::to_string(trial));
  }
  // Every kind occurs (vertex touch, edge in the plane, crossing, whole triangle).
  EXPECT_GT(kinds[static_cast<int>(Kind::point)], 3);
  EXPECT_GT(kinds[static_cast<int>(Kind::segment)], 3);
  EXPECT_GT(kinds[static_cast<int>(Kind::polygon)], 0);
}

// Figure 11.26: the plane z = 0 against a triangle above it touching at a vertex, along an edge,
// crossing through a vertex, crossing two edges, and lying in it.
TYPED_TEST(PlaneTriangle, Figure11_26) {
  using T = TypeParam;
  const Plane3<T> z0{{0, 0, 1}, 0};
  const Triangle3<T> vertex{{0, 0, 0}, {1, 0, 1}, {0, 1, 2}};
  const Triangle3<T> edge{{0, 0, 0}, {1, 0, 0}, {0, 1, 2}};
  const Triangle3<T> through{{0, 0, 0}, {1, 0, -1}, {0, 1, 2}};
  const Triangle3<T> cross{{0, 0, -1}, {2, 0, 1}, {0, 2, 1}};
  const Triangle3<T> in{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  auto r = intersection(vertex, z0);
  EXPECT_EQ(r.kind, Kind::point);
  EXPECT_EQ(r.point[0], vertex.v0);
  r = intersection(edge, z0);
  EXPECT_EQ(r.kind, Kind::segment);
  r = intersection(through, z0);
  EXPECT_EQ(r.kind, Kind::segment);
  r = intersection(cross, z0);
  ASSERT_EQ(r.kind, Kind::segment);
  for (const auto* t : {&vertex, &edge, &through, &cross, &in}) check(*t, z0, "figure");
  EXPECT_EQ(intersection(in, z0).kind, Kind::polygon);
}

TYPED_TEST(PlaneTriangle, NonFiniteAndZeroNormal) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Triangle3<T> t{{0, 0, -1}, {1, 0, 1}, {0, 1, 1}};
  EXPECT_FALSE(intersects(t, Plane3<T>{{0, 0, 0}, 0}));
  EXPECT_FALSE(intersects(t, Plane3<T>{{0, 0, nan}, 0}));
  EXPECT_FALSE(intersects(t, Plane3<T>{{0, 0, 1}, inf}));
  EXPECT_EQ(
      intersection(Triangle3<T>{{nan, 0, 0}, {1, 0, 1}, {0, 1, 1}}, Plane3<T>{{0, 0, 1}, 0}).kind,
      Kind::empty);
  EXPECT_TRUE(intersects(t, Plane3<T>{{0, 0, 1}, 0}));
}

TYPED_TEST(PlaneTriangle, PowerOfTwoScalingIsExact) {
  using T = TypeParam;
  Rng rng(7);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 100; ++trial) {
    Triangle3<T> t;
    for (int i = 0; i < 3; ++i) t[i] = rng.template vec<T, 3>(T(-1), T(1));
    const Plane3<T> p{rng.template vec<T, 3>(T(-1), T(1)), rng.template uniform<T>(T(-.3), T(.3))};
    const auto r = intersection(t, p);
    for (const int k : {-20, 20}) {
      const T f = std::ldexp(T(1), k);
      const Triangle3<T> ts{t.v0 * f, t.v1 * f, t.v2 * f};
      const auto s = intersection(ts, Plane3<T>{p.normal, p.constant * f});
      ASSERT_EQ(s.kind, r.kind);
      for (int i = 0; i < r.count; ++i) {
        EXPECT_EQ(s.point[static_cast<std::size_t>(i)], r.point[static_cast<std::size_t>(i)] * f);
        EXPECT_EQ(s.param_a[static_cast<std::size_t>(i)], r.param_a[static_cast<std::size_t>(i)]);
      }
    }
  }
}

}  // namespace
