// SPDX-License-Identifier: BSL-1.0
// Tests for distance/line_tetrahedron.hpp, ray_tetrahedron.hpp, segment_tetrahedron.hpp (row
// dist3.linear-tetrahedron; book figures 10.44, 10.45).
#include <locus/distance/line_tetrahedron.hpp>
#include <locus/distance/ray_tetrahedron.hpp>
#include <locus/distance/segment_tetrahedron.hpp>

#include "distance/exact.hpp"
#include "distance/exact_planar.hpp"
#include "distance/harness.hpp"
#include "distance/side_solids.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class LinearTetrahedronTest : public ::testing::Test {};
TYPED_TEST_SUITE(LinearTetrahedronTest, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kCases = 40;
#else
constexpr int kCases = 80;
#endif

// Random tetrahedra: generic (85%), flat (5%), collinear (5%), a coincident pair (5%).
template <class T>
Tetrahedron3<T> random_tetrahedron(Rng& rng, T S) {
  Tetrahedron3<T> t{
      {rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S)}};
  const int kind = rng.uniform_int(0, 19);
  const T a = rng.uniform<T>(T(-0.5), T(1)), b = rng.uniform<T>(T(-0.5), T(1));
  if (kind == 0)
    t.v[3] = t.v[0] + a * (t.v[1] - t.v[0]) + b * (t.v[2] - t.v[0]);
  else if (kind == 1)
    t.v[2] = lerp(t.v[0], t.v[1], a), t.v[3] = lerp(t.v[0], t.v[1], b);
  else if (kind == 2)
    t.v[3] = t.v[1];
  return t;
}

// A linear component: generic (55%), through a random interior point (20%), parallel to a face
// (15%), zero direction (10%).
template <class T>
std::pair<Vec3<T>, Vec3<T>> random_linear(Rng& rng, const Tetrahedron3<T>& tet, T S) {
  Vec3<T> o = rng.vec<T, 3>(-T(1.5) * S, T(1.5) * S);
  Vec3<T> d = rng.unit<T, 3>() * (rng.uniform<T>(T(0.5), T(2)) * S);
  const int kind = rng.uniform_int(0, 19);
  if (kind < 11) {
  } else if (kind < 15) {
    T w[4], sum = T(0);
    for (T& x : w) sum += (x = rng.uniform<T>(T(0.01), T(1)));
    const Vec3<T> x =
        point_at_barycentric(tet, Vec4<T>{w[0] / sum, w[1] / sum, w[2] / sum, w[3] / sum});
    o = x - rng.uniform<T>(T(0), T(1)) * d;
  } else if (kind < 18) {
    d = rng.uniform<T>(-1, 1) * (tet.v[1] - tet.v[0]) +
        rng.uniform<T>(-1, 1) * (tet.v[2] - tet.v[0]);
  } else {
    d = Vec3<T>{};
  }
  return {o, d};
}

template <class T>
ex::QLinear<3> q_of(const Line3<T>& l) {
  return ex::line(l.origin, l.direction);
}
template <class T>
ex::QLinear<3> q_of(const Ray3<T>& l) {
  return ex::ray(l.origin, l.direction);
}
template <class T>
ex::QLinear<3> q_of(const Segment3<T>& s) {
  return ex::segment(s.p0, s.p1);
}

template <class T, class L, class Make>
void run(Make make) {
  const T S = 4;
  dist::Options<T> opt;
  opt.cases = kCases;
  opt.scale = T(16);
  opt.window = T(50);
  opt.check_agreement = false;  // the exact oracle below is tighter
  dist::check_pairs<T, 3, L, Tetrahedron3<T>>(
      [&](Rng& rng) {
        const auto tet = random_tetrahedron<T>(rng, S);
        return std::pair<L, Tetrahedron3<T>>{make(random_linear<T>(rng, tet, S)), tet};
      },
      opt);
  Rng rng(locus_test::test_seed() + 41);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2 * kCases; ++n) {
    const auto tet = random_tetrahedron<T>(rng, S);
    const L l = make(random_linear<T>(rng, tet, S));
    const auto r = distance(l, tet);
    const double e = ex::sqr_linear_tetrahedron(q_of(l), ex::tet_of(tet)).get_d();
    const T scale = std::max({T(16), max_abs(r.closest[0]), max_abs(r.closest[1])});
    EXPECT_NEAR(double(r.sqr_distance), e, double(tol<T>(64, scale * scale))) << "case " << n;
  }
}

}  // namespace

TYPED_TEST(LinearTetrahedronTest, SegmentHarnessAndExactOracle) {
  using T = TypeParam;
  run<T, Segment3<T>>([](const auto& od) { return Segment3<T>{od.first, od.first + od.second}; });
}
TYPED_TEST(LinearTetrahedronTest, RayHarnessAndExactOracle) {
  using T = TypeParam;
  run<T, Ray3<T>>([](const auto& od) { return Ray3<T>{od.first, od.second}; });
}
TYPED_TEST(LinearTetrahedronTest, LineHarnessAndExactOracle) {
  using T = TypeParam;
  run<T, Line3<T>>([](const auto& od) { return Line3<T>{od.first, od.second}; });
}

// Small integer coordinates: a segment meets a non-flat solid tetrahedron iff the distance is
// exactly 0 (ends inside decided by orient3d, face contacts by segment_triangle's exact test).
TYPED_TEST(LinearTetrahedronTest, SegmentMeetsSolidExactly) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 42);
  SCOPED_TRACE(rng.trace());
  int zero = 0;
  for (int n = 0; n < 3 * kCases; ++n) {
    const auto iv = [&] {
      return Vec3<T>{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2)),
                     T(rng.uniform_int(-2, 2))};
    };
    const Tetrahedron3<T> tet{{iv(), iv(), iv(), iv()}};
    const Segment3<T> seg{iv(), iv()};
    const auto r = distance(seg, tet);
    const mpq_class e = ex::sqr_linear_tetrahedron(q_of(seg), ex::tet_of(tet));
    if (orientation(tet) != 0) {
      EXPECT_EQ(r.distance == T(0), e == 0) << "case " << n;
      zero += e == 0;
    }
    EXPECT_NEAR(double(r.sqr_distance), e.get_d(), double(tol<T>(64, T(16)))) << "case " << n;
  }
  EXPECT_GT(zero, kCases / 4);
}

// Figures 10.44, 10.45: a line against a tetrahedron, through it, past an edge, past a vertex,
// parallel to a face; uniqueness of the answers.
TYPED_TEST(LinearTetrahedronTest, Figure10_44Cases) {
  using T = TypeParam;
  const Tetrahedron3<T> tet{
      {{T(0), T(0), T(0)}, {T(2), T(0), T(0)}, {T(0), T(2), T(0)}, {T(0), T(0), T(2)}}};
  // Through the interior: distance 0 along a chord, not unique.
  const auto through = distance(Line3<T>{{T(0.5), T(0.5), T(-5)}, {T(0), T(0), T(1)}}, tet);
  EXPECT_LE(through.distance, tol<T>(8, T(2)));
  EXPECT_FALSE(through.unique);
  const auto seg_in = distance(Segment3<T>{{T(0.3), T(0.3), T(0.3)}, {T(5), T(5), T(5)}}, tet);
  EXPECT_EQ(seg_in.distance, T(0));
  EXPECT_EQ(seg_in.param_a, T(0));
  EXPECT_EQ(seg_in.closest[1], (Vec3<T>{T(0.3), T(0.3), T(0.3)}));
  EXPECT_FALSE(seg_in.unique);
  // Past the edge x = y = 0 (skew to it): the closest point is on that edge, unique.
  const auto edge = distance(Line3<T>{{T(-1), T(-1), T(1)}, {T(1), T(-1), T(0)}}, tet);
  EXPECT_NEAR(edge.sqr_distance, T(2), tol<T>(16, T(4)));
  EXPECT_TRUE(locus_test::vec_near(edge.closest[1], Vec3<T>{T(0), T(0), T(1)}, tol<T>(16, T(2))));
  EXPECT_TRUE(edge.unique);
  // Past the vertex (0, 0, 2) above it: the ray points away, so its origin is closest.
  const auto vertex = distance(Ray3<T>{{T(0), T(0), T(3)}, {T(1), T(1), T(1)}}, tet);
  EXPECT_EQ(vertex.distance, T(1));
  EXPECT_EQ(vertex.closest[1], tet.v[3]);
  EXPECT_EQ(vertex.param_b, (Vec4<T>{T(0), T(0), T(0), T(1)}));
  // Touching the vertex only: distance 0, unique.
  const auto touch = distance(Segment3<T>{{T(-1), T(1), T(2)}, {T(1), T(-1), T(2)}}, tet);
  EXPECT_EQ(touch.distance, T(0));
  EXPECT_TRUE(touch.unique);
  // Parallel to the face z = 0, below it over its interior: not unique.
  const auto below = distance(Segment3<T>{{T(0.2), T(0.2), T(-1)}, {T(0.8), T(0.5), T(-1)}}, tet);
  EXPECT_EQ(below.distance, T(1));
  EXPECT_FALSE(below.unique);
  // Swapped overloads.
  const Segment3<T> s{{T(3), T(3), T(3)}, {T(4), T(2), T(5)}};
  EXPECT_EQ(distance(s, tet).param_b, distance(tet, s).param_a);
  const Ray3<T> ray{{T(3), T(3), T(3)}, {T(1), T(2), T(5)}};
  EXPECT_EQ(distance(ray, tet).closest[1], distance(tet, ray).closest[0]);
  EXPECT_EQ(distance(Line3<T>{s.p0, s.p1}, tet).param_a,
            distance(tet, Line3<T>{s.p0, s.p1}).param_b);
}

TYPED_TEST(LinearTetrahedronTest, DegenerateInput) {
  using T = TypeParam;
  // Flat: the filled unit square in z = 0.
  const Tetrahedron3<T> flat{
      {{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(1), T(1), T(0)}, {T(0), T(1), T(0)}}};
  EXPECT_EQ(distance(Segment3<T>{{T(0.5), T(0.5), T(2)}, {T(0.5), T(0.5), T(1)}}, flat).distance,
            T(1));
  EXPECT_LE(distance(Line3<T>{{T(0.9), T(0.2), T(2)}, {T(0), T(0), T(1)}}, flat).distance,
            tol<T>(8));
  // Zero-length segment and zero ray direction act as their point.
  const Tetrahedron3<T> tet{
      {{T(0), T(0), T(0)}, {T(2), T(0), T(0)}, {T(0), T(2), T(0)}, {T(0), T(0), T(2)}}};
  const Vec3<T> p{T(0.5), T(0.5), T(-3)};
  EXPECT_EQ(distance(Segment3<T>{p, p}, tet).distance, T(3));
  EXPECT_EQ(distance(Ray3<T>{p, Vec3<T>{}}, tet).distance, T(3));
  const Vec3<T> in{T(0.2), T(0.3), T(0.4)};
  const auto r = distance(Segment3<T>{in, in}, tet);
  EXPECT_EQ(r.distance, T(0));
  EXPECT_TRUE(r.unique);  // a point: a single pair
  // A line with a zero direction inside the solid is that point: distance 0, not the distance
  // to the boundary (regression: lines had no inside test for their origin).
  for (const auto& rr :
       {distance(Line3<T>{in, Vec3<T>{}}, tet), distance(Ray3<T>{in, Vec3<T>{}}, tet)}) {
    EXPECT_EQ(rr.distance, T(0));
    EXPECT_EQ(rr.closest[0], in);
    EXPECT_TRUE(rr.unique);
  }
}

TYPED_TEST(LinearTetrahedronTest, NonFiniteInputGivesNaNResult) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Tetrahedron3<T> tet{
      {{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}};
  EXPECT_TRUE(dist::is_nan_result(distance(Segment3<T>{{nan, T(0), T(0)}, {}}, tet)));
  EXPECT_TRUE(dist::is_nan_result(distance(Ray3<T>{{}, {T(0), inf, T(0)}}, tet)));
  auto bad = tet;
  bad.v[2].x = nan;
  const auto r = distance(Line3<T>{{}, {T(1), T(1), T(1)}}, bad);
  EXPECT_TRUE(dist::is_nan_result(r));
  EXPECT_TRUE(std::isnan(r.param_a) && std::isnan(r.param_b.x));
  EXPECT_TRUE(dist::is_nan_result(distance(bad, Segment3<T>{{}, {T(1), T(1), T(1)}})));
}
