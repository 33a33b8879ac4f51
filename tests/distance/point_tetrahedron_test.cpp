// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_tetrahedron.hpp (row dist3.pt-polyhedron, tetrahedron part; book
// figure 10.20).
#include <locus/distance/point_tetrahedron.hpp>

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
class PointTetrahedronTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointTetrahedronTest, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kCases = 60;
#else
constexpr int kCases = 120;
#endif

// Random tetrahedra: generic (80%), flat with the fourth vertex an affine combination of the
// others (5%), collinear (5%), a coincident pair (5%), a sliver (5%: the fourth vertex 1e-4 S off
// the plane of the others).
template <class T>
Tetrahedron3<T> random_tetrahedron(Rng& rng, T S) {
  Tetrahedron3<T> t{
      {rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S), rng.vec<T, 3>(-S, S)}};
  const int kind = rng.uniform_int(0, 19);
  const T a = rng.uniform<T>(T(-0.5), T(1)), b = rng.uniform<T>(T(-0.5), T(1));
  if (kind == 0) {
    t.v[3] = t.v[0] + a * (t.v[1] - t.v[0]) + b * (t.v[2] - t.v[0]);
  } else if (kind == 1) {
    t.v[2] = lerp(t.v[0], t.v[1], a);
    t.v[3] = lerp(t.v[0], t.v[1], b);
  } else if (kind == 2) {
    t.v[3] = t.v[1];
  } else if (kind == 3) {
    const Vec3<T> n = normalize(cross(t.v[1] - t.v[0], t.v[2] - t.v[0]));
    t.v[3] = t.v[0] + T(0.3) * (t.v[1] - t.v[0]) + T(0.3) * (t.v[2] - t.v[0]) + n * (S * T(1e-4));
  }
  return t;
}

}  // namespace

TYPED_TEST(PointTetrahedronTest, HarnessAndExactOracle) {
  using T = TypeParam;
  const T S = 4;
  dist::Options<T> opt;
  opt.cases = kCases;
  // The sorting map folds the cube onto the tetrahedron, which can stall the compass search at a
  // fold; agreement is checked against the exact rational oracle below instead.
  opt.check_agreement = false;
  dist::check_pairs<T, 3, Vec3<T>, Tetrahedron3<T>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 3>(-T(1.5) * S, T(1.5) * S), random_tetrahedron<T>(rng, S)};
      },
      opt);
  Rng rng(locus_test::test_seed() + 31);
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 2 * kCases; ++n) {
    const auto tet = random_tetrahedron<T>(rng, S);
    const auto p = rng.vec<T, 3>(-T(1.5) * S, T(1.5) * S);
    const auto r = distance(p, tet);
    const double e = ex::sqr_point_tetrahedron(ex::to_q(p), ex::tet_of(tet)).get_d();
    EXPECT_NEAR(double(r.sqr_distance), e, double(tol<T>(64, T(100)))) << "case " << n;
  }
}

// Small integer coordinates: inside (including the boundary) is decided exactly, so the distance
// is exactly 0 iff the exact rational distance is 0 (for non-flat tetrahedra).
TYPED_TEST(PointTetrahedronTest, InsideDecidedExactly) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 32);
  SCOPED_TRACE(rng.trace());
  int zero = 0, boundary = 0;
  for (int n = 0; n < 4 * kCases; ++n) {
    const auto iv = [&] {
      return Vec3<T>{T(rng.uniform_int(-2, 2)), T(rng.uniform_int(-2, 2)),
                     T(rng.uniform_int(-2, 2))};
    };
    const Tetrahedron3<T> tet{{iv(), iv(), iv(), iv()}};
    // A quarter of the points are vertices (boundary points, distance exactly 0).
    const Vec3<T> p = n % 4 == 0 ? tet.v[n % 3] : iv();
    const auto r = distance(p, tet);
    const mpq_class e = ex::sqr_point_tetrahedron(ex::to_q(p), ex::tet_of(tet));
    if (orientation(tet) != 0) {
      EXPECT_EQ(r.distance == T(0), e == 0) << "case " << n;
      if (e == 0) {
        ++zero;
        EXPECT_EQ(r.closest[1], p);
        EXPECT_TRUE(
            locus_test::vec_near(point_at_barycentric(tet, r.param_b), p, tol<T>(16, T(4))));
        if (!ex::inside_tetrahedron(ex::to_q(p), ex::tet_of(tet))) ++boundary;
      }
    }
    EXPECT_NEAR(double(r.sqr_distance), e.get_d(), double(tol<T>(64, T(16)))) << "case " << n;
  }
  EXPECT_GT(zero, kCases / 4);
}

// Figure 10.20: the unit tetrahedron; a point inside, beyond each kind of feature (face interior,
// edge, vertex) and in both vertex orders.
TYPED_TEST(PointTetrahedronTest, Figure10_20Regions) {
  using T = TypeParam;
  for (const bool flip : {false, true}) {
    Tetrahedron3<T> tet{
        {{T(0), T(0), T(0)}, {T(2), T(0), T(0)}, {T(0), T(2), T(0)}, {T(0), T(0), T(2)}}};
    if (flip) std::swap(tet.v[1], tet.v[2]);  // negative orientation: same solid
    SCOPED_TRACE(flip ? "negative orientation" : "positive orientation");
    const auto in = distance(Vec3<T>{T(0.25), T(0.5), T(0.5)}, tet);
    EXPECT_EQ(in.distance, T(0));
    EXPECT_TRUE(locus_test::vec_near(point_at_barycentric(tet, in.param_b),
                                     Vec3<T>{T(0.25), T(0.5), T(0.5)}, tol<T>(8, T(2))));
    // Beyond the face z = 0 (its interior): straight down.
    const auto face = distance(Vec3<T>{T(0.5), T(0.5), T(-3)}, tet);
    EXPECT_EQ(face.distance, T(3));
    EXPECT_EQ(face.closest[1], (Vec3<T>{T(0.5), T(0.5), T(0)}));
    // Beyond the slanted face x + y + z = 2.
    const auto slanted = distance(Vec3<T>{T(2), T(2), T(2)}, tet);
    EXPECT_NEAR(slanted.sqr_distance, T(16) / T(3), tol<T>(16, T(16)));
    // Beyond the edge x = y = 0 (the z axis).
    const auto edge = distance(Vec3<T>{T(-1), T(-2), T(1)}, tet);
    EXPECT_EQ(edge.sqr_distance, T(5));
    EXPECT_EQ(edge.closest[1], (Vec3<T>{T(0), T(0), T(1)}));
    // Beyond the vertex (0, 0, 0).
    const auto vertex = distance(Vec3<T>{T(-1), T(-2), T(-2)}, tet);
    EXPECT_EQ(vertex.distance, T(3));
    EXPECT_EQ(vertex.closest[1], tet.v[0]);
    EXPECT_EQ(vertex.param_b, (Vec4<T>{T(1), T(0), T(0), T(0)}));
    // Swapped overload.
    const auto sw = distance(tet, Vec3<T>{T(-1), T(-2), T(-2)});
    EXPECT_EQ(sw.closest[0], tet.v[0]);
    EXPECT_EQ(sw.param_a, vertex.param_b);
    EXPECT_EQ(closest_point(Vec3<T>{T(-1), T(-2), T(-2)}, tet), tet.v[0]);
  }
}

TYPED_TEST(PointTetrahedronTest, DegenerateTetrahedra) {
  using T = TypeParam;
  // Flat: a unit square's corners; the tetrahedron is the filled square.
  const Tetrahedron3<T> flat{
      {{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(1), T(1), T(0)}, {T(0), T(1), T(0)}}};
  EXPECT_EQ(distance(Vec3<T>{T(0.5), T(0.5), T(2)}, flat).distance, T(2));
  EXPECT_NEAR(distance(Vec3<T>{T(0.9), T(0.2), T(0)}, flat).distance, T(0), tol<T>(8));
  EXPECT_EQ(distance(Vec3<T>{T(3), T(0.5), T(0)}, flat).distance, T(2));
  // Collinear: the segment it spans.
  const Tetrahedron3<T> line{
      {{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(3), T(0), T(0)}, {T(2), T(0), T(0)}}};
  EXPECT_EQ(distance(Vec3<T>{T(2.5), T(3), T(4)}, line).distance, T(5));
  EXPECT_EQ(distance(Vec3<T>{T(5), T(0), T(0)}, line).closest[1], line.v[2]);
  // A point.
  const Tetrahedron3<T> pt{
      {{T(1), T(1), T(1)}, {T(1), T(1), T(1)}, {T(1), T(1), T(1)}, {T(1), T(1), T(1)}}};
  const auto r = distance(Vec3<T>{T(1), T(4), T(5)}, pt);
  EXPECT_EQ(r.distance, T(5));
  EXPECT_EQ(r.closest[1], pt.v[0]);
}

TYPED_TEST(PointTetrahedronTest, NonFiniteInputGivesNaNResult) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Tetrahedron3<T> tet{
      {{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}};
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{nan, T(0), T(0)}, tet)));
  auto bad = tet;
  bad.v[3].y = inf;
  const auto r = distance(Vec3<T>{}, bad);
  EXPECT_TRUE(dist::is_nan_result(r));
  EXPECT_TRUE(std::isnan(r.param_b.w));
  EXPECT_TRUE(dist::is_nan_result(distance(bad, Vec3<T>{})));
}
