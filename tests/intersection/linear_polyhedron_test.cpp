// SPDX-License-Identifier: BSL-1.0
// Row int3.linear-polyhedron, intersection/linear_polyhedron.hpp: line, ray and segment clipped
// by a convex polyhedron of half-spaces against an exact GMP oracle (the kind exactly, the
// parameters to rounding) on seeded random polyhedra and components, including components
// aimed exactly at the vertices and edges of a box and lying in its faces; degenerate, empty
// and non-finite input; swapped overloads; power-of-two scaling.

#include <locus/intersection/linear_polyhedron.hpp>

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class LinearPolyhedron : public ::testing::Test {};
TYPED_TEST_SUITE(LinearPolyhedron, locus_test::RealTypes);

/// Exact clip of o + t d (t in [lo, hi], each bound optional) by the half-spaces: the kind and
/// the exact parameter interval.
struct Oracle {
  Kind kind = Kind::empty;
  std::optional<mpq_class> t0, t1;
};

template <class T>
Oracle oracle(const Vec3<T>& o, const Vec3<T>& d, bool lo, bool hi,
              const std::vector<Plane3<T>>& planes) {
  std::optional<mpq_class> a, b;
  if (lo) a = mpq_class(0);
  if (hi) b = mpq_class(1);
  // For a segment (hi) d is the second end point: the direction q - o is exact here.
  const bool point = hi ? d == o : d == Vec3<T>{};
  for (const auto& p : planes) {
    mpq_class no = 0, nd = 0;
    for (int k = 0; k < 3; ++k) {
      no += mpq_class(double(p.normal[k])) * mpq_class(double(o[k]));
      const mpq_class dk =
          hi ? mpq_class(double(d[k])) - mpq_class(double(o[k])) : mpq_class(double(d[k]));
      nd += mpq_class(double(p.normal[k])) * dk;
    }
    const mpq_class A = mpq_class(double(p.constant)) - no;
    if (nd == 0 || point) {
      if (A < 0) return {};
      continue;
    }
    const mpq_class t = A / nd;
    if (nd < 0) {
      if (!a || t > *a) a = t;
    } else {
      if (!b || t < *b) b = t;
    }
  }
  Oracle r;
  if (point) {
    r.kind = Kind::point;
    return r;
  }
  if (a && b && *a > *b) return r;
  r.t0 = a;
  r.t1 = b;
  if (a && b)
    r.kind = *a == *b ? Kind::point : Kind::segment;
  else
    r.kind = (a || b) ? Kind::ray : Kind::line;
  return r;
}

template <class T>
std::vector<Plane3<T>> box_planes(T h) {
  std::vector<Plane3<T>> p;
  for (int k = 0; k < 3; ++k) {
    Vec3<T> n{};
    n[k] = 1;
    p.push_back({n, h});
    p.push_back({-n, h});
  }
  return p;
}

template <class T>
std::vector<Plane3<T>> random_planes(Rng& rng, int n) {
  std::vector<Plane3<T>> p;
  for (int i = 0; i < n; ++i) {
    Vec3<T> v = rng.vec<T, 3>(T(-1), T(1));
    for (int k = 0; k < 3; ++k) v[k] = T(std::round(double(v[k]) * 64) / 64);
    if (v == Vec3<T>{}) v.x = 1;
    p.push_back({v, T(std::round(rng.uniform<double>(0.5, 2.0) * 64) / 64)});
  }
  return p;
}

template <class T>
void check(const Vec3<T>& o, const Vec3<T>& d, int type, const std::vector<Plane3<T>>& planes) {
  const ConvexPolyhedron3<T> poly{planes};
  LinearPolyhedronIntersection<T> got;
  Oracle want;
  if (type == 0) {
    got = intersection(Line3<T>{o, d}, poly);
    want = oracle(o, d, false, false, planes);
  } else if (type == 1) {
    got = intersection(Ray3<T>{o, d}, poly);
    want = oracle(o, d, true, false, planes);
  } else {
    got = intersection(Segment3<T>{o, o + d}, poly);
    want = oracle(o, Vec3<T>(o + d), true, true, planes);
  }
  ASSERT_EQ(got.kind, want.kind) << "type " << type;
  const double scale = 4.0 * std::max(1.0, double(max_abs(o)) / double(max_abs(d)));
  const double tol = 64 * double(eps_v<T>) * scale;
  if (want.kind == Kind::segment) {
    EXPECT_NEAR(double(got.param_a[0]), want.t0->get_d(), tol);
    EXPECT_NEAR(double(got.param_a[1]), want.t1->get_d(), tol);
  }
  if (want.kind == Kind::point && want.t0) {
    EXPECT_NEAR(double(got.param_a[0]), want.t0->get_d(), tol);
  }
  EXPECT_EQ(intersects(Ray3<T>{o, d}, poly), intersection(Ray3<T>{o, d}, poly).kind != Kind::empty);
}

TYPED_TEST(LinearPolyhedron, RandomAgainstGmp) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 100; ++i) {
    const auto planes = random_planes<T>(rng, 4 + i % 9);
    const Vec3<T> o = rng.vec<T, 3>(T(-3), T(3));
    const Vec3<T> d = rng.vec<T, 3>(T(-2), T(2));
    for (int type = 0; type < 3; ++type) check(o, d, type, planes);
  }
}

TYPED_TEST(LinearPolyhedron, ThroughVerticesEdgesAndFacesOfABox) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 1);
  SCOPED_TRACE(rng.trace());
  const auto planes = box_planes<T>(T(1));
  int points = 0, segments = 0;
  for (int i = 0; i < 160; ++i) {
    // A target on a vertex, an edge or a face of [-1, 1]^3 (coordinates in {-1, 1} or a grid).
    Vec3<T> x{};
    const int fixed = 1 + i % 3;
    for (int k = 0; k < 3; ++k)
      x[k] = k < fixed ? T(rng.uniform_int(0, 1) ? 1 : -1) : T(rng.uniform_int(-8, 8)) / T(8);
    Vec3<T> o{};
    for (int k = 0; k < 3; ++k) o[k] = T(rng.uniform_int(-24, 24)) / T(8);
    if (i % 5 == 0) o[0] = x[0];  // in a face plane
    const Vec3<T> d = x - o;
    if (d == Vec3<T>{}) continue;
    for (int type = 0; type < 3; ++type) check(o, d, type, planes);
    const auto r = intersection(Ray3<T>{o, d}, ConvexPolyhedron3<T>{planes});
    points += r.kind == Kind::point;
    segments += r.kind == Kind::segment;
  }
  EXPECT_GT(points, 10);  // tangent rays through vertices and edges occur
  EXPECT_GT(segments, 10);
}

TYPED_TEST(LinearPolyhedron, DegenerateAndBadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const auto cube = box_planes<T>(T(1));
  const ConvexPolyhedron3<T> poly{cube};
  // Entry and exit of a ray through the centre.
  const auto r = intersection(Ray3<T>{{-3, 0, 0}, {1, 0, 0}}, poly);
  ASSERT_EQ(r.kind, Kind::segment);
  EXPECT_EQ(r.param_a[0], T(2));
  EXPECT_EQ(r.param_a[1], T(4));
  EXPECT_EQ(r.point[0], (Vec3<T>{-1, 0, 0}));
  // From inside: entry is the origin itself.
  const auto in = intersection(Ray3<T>{{0.5, 0.25, 0}, {1, 0, 0}}, poly);
  ASSERT_EQ(in.kind, Kind::segment);
  EXPECT_EQ(in.point[0], (Vec3<T>{0.5, 0.25, 0}));
  // No planes: the whole component; an open polyhedron: a ray.
  EXPECT_EQ(intersection(Line3<T>{{0, 0, 0}, {1, 2, 3}}, ConvexPolyhedron3<T>{}).kind, Kind::line);
  const std::vector<Plane3<T>> half = {{{1, 0, 0}, 0}};
  const auto lr = intersection(Line3<T>{{5, 0, 0}, {1, 0, 0}}, ConvexPolyhedron3<T>{half});
  ASSERT_EQ(lr.kind, Kind::ray);
  EXPECT_EQ(lr.point[0], (Vec3<T>{0, 0, 0}));
  EXPECT_EQ(lr.point[1], (Vec3<T>{-1, 0, 0}));
  // Zero direction / zero-length segment: a point test (the boundary counts).
  EXPECT_EQ(intersection(Ray3<T>{{1, 1, 1}, {0, 0, 0}}, poly).kind, Kind::point);
  EXPECT_EQ(intersection(Segment3<T>{{2, 0, 0}, {2, 0, 0}}, poly).kind, Kind::empty);
  // A zero normal: c >= 0 no constraint, c < 0 empty.
  std::vector<Plane3<T>> z = cube;
  z.push_back({{0, 0, 0}, 1});
  EXPECT_EQ(intersection(Ray3<T>{{-3, 0, 0}, {1, 0, 0}}, ConvexPolyhedron3<T>{z}).kind,
            Kind::segment);
  z.back().constant = -1;
  EXPECT_EQ(intersection(Ray3<T>{{-3, 0, 0}, {1, 0, 0}}, ConvexPolyhedron3<T>{z}).kind,
            Kind::empty);
  // Non-finite input.
  EXPECT_EQ(intersection(Ray3<T>{{nan, 0, 0}, {1, 0, 0}}, poly).kind, Kind::empty);
  std::vector<Plane3<T>> bad = cube;
  bad[2].constant = std::numeric_limits<T>::infinity();
  EXPECT_EQ(intersection(Ray3<T>{{-3, 0, 0}, {1, 0, 0}}, ConvexPolyhedron3<T>{bad}).kind,
            Kind::empty);
  // Swapped.
  const auto sw = intersection(poly, Ray3<T>{{-3, 0, 0}, {1, 0, 0}});
  EXPECT_EQ(sw.param_b[0], r.param_a[0]);
  EXPECT_TRUE(intersects(poly, Segment3<T>{{-3, 0, 0}, {-1, 0, 0}}));  // touches the face
  EXPECT_FALSE(intersects(poly, Segment3<T>{{-3, 0, 0}, {-1.5, 0, 0}}));
}

TYPED_TEST(LinearPolyhedron, PowerOfTwoScaling) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 2);
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 100; ++i) {
    auto planes = random_planes<T>(rng, 6);
    const Vec3<T> o = rng.vec<T, 3>(T(-3), T(3)), d = rng.vec<T, 3>(T(-2), T(2));
    const auto a = intersection(Ray3<T>{o, d}, ConvexPolyhedron3<T>{planes});
    for (const int k : {-30, 20}) {
      const T f = std::ldexp(T(1), k);
      std::vector<Plane3<T>> sp = planes;
      for (auto& p : sp) p.constant *= f;
      const auto b = intersection(Ray3<T>{f * o, f * d}, ConvexPolyhedron3<T>{sp});
      ASSERT_EQ(a.kind, b.kind);
      for (int j = 0; j < a.count; ++j)
        EXPECT_EQ(a.param_a[static_cast<std::size_t>(j)], b.param_a[static_cast<std::size_t>(j)]);
    }
  }
}

}  // namespace
