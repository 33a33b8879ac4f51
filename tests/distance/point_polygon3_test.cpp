// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_polygon3.hpp and primitives/planar_polygon.hpp (row dist3.pt-polygon;
// book figures 10.14, 10.15).
#include <locus/distance/point_polygon3.hpp>
#include <locus/primitives/planar_polygon.hpp>

#include "distance/exact.hpp"
#include "distance/harness.hpp"
#include "distance/side_solids.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class PointPolygon3Test : public ::testing::Test {};
TYPED_TEST_SUITE(PointPolygon3Test, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kCases = 60;
#else
constexpr int kCases = 120;
#endif

// A random polygon star-shaped about its frame's origin (usually not convex): 3 to 12 vertices
// at jittered increasing angles with radii in [0.2 S, S]; the frame has a random origin and
// orientation.
template <class T>
PlanarPolygon3<T> random_polygon(Rng& rng, T S) {
  const auto r = dist::random_rotation<T, 3>(rng);
  PlanarPolygon3<T> poly{{rng.vec<T, 3>(-S, S), r * Vec3<T>{T(1), T(0), T(0)},
                          r * Vec3<T>{T(0), T(1), T(0)}, r * Vec3<T>{T(0), T(0), T(1)}},
                         {}};
  // Angular gaps below pi keep the frame's origin in the kernel (the harness's star map).
  const int n = rng.uniform_int(3, 12);
  const T step = T(6.283185307179586) / T(n), phase = rng.uniform<T>(T(0), step);
  for (int i = 0; i < n; ++i) {
    const T a = phase + step * (T(i) + rng.uniform<T>(T(-0.2), T(0.2)));
    const T rad = rng.uniform<T>(T(0.2) * S, S);
    poly.polygon.vertices.push_back({rad * std::cos(a), rad * std::sin(a)});
  }
  return poly;
}

// Exact: squared distance from p to the filled polygon taken in the frame's coordinates (the
// frame's rounded axes are orthonormal to ~eps, well inside the tolerance): height^2 plus, when
// the projection is outside (even-odd rule in rationals), the squared distance to the nearest
// edge.
template <class T>
mpq_class exact_sqr(const Vec3<T>& p, const PlanarPolygon3<T>& poly) {
  const auto d = ex::sub(ex::to_q(p), ex::to_q(poly.frame.origin));
  const mpq_class s = ex::dot(d, ex::to_q(poly.frame.u)), t = ex::dot(d, ex::to_q(poly.frame.v)),
                  h = ex::dot(d, ex::to_q(poly.frame.normal));
  const ex::QVec<2> q{s, t};
  const auto& v = poly.polygon.vertices;
  bool inside = false;
  mpq_class best = -1;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const auto a = ex::to_q(v[j]), b = ex::to_q(v[i]);
    if ((a[1] > t) != (b[1] > t)) {
      const mpq_class x = a[0] + (t - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
      if (x > s) inside = !inside;
    }
    const mpq_class e = ex::sqr_point_linear(q, ex::QLinear<2>{a, ex::sub(b, a), true, true});
    if (best < 0 || e < best) best = e;
  }
  return h * h + (inside ? mpq_class(0) : best);
}

}  // namespace

TYPED_TEST(PointPolygon3Test, HarnessAndExactOracle) {
  using T = TypeParam;
  const T S = 4;
  dist::Options<T> opt;
  opt.cases = kCases;
  opt.samples = 512;
  opt.check_agreement = false;  // non-convex: the compass search may stop in a local minimum
  dist::check_pairs<T, 3, Vec3<T>, PlanarPolygon3<T>>(
      [&](Rng& rng) {
        auto poly = random_polygon<T>(rng, S);
        const auto p = rng.vec<T, 3>(-T(1.5) * S, T(1.5) * S);
        return std::pair{p, std::move(poly)};
      },
      opt);
  Rng rng(locus_test::test_seed() + 51);
  SCOPED_TRACE(rng.trace());
  int inside = 0;
  for (int n = 0; n < 2 * kCases; ++n) {
    const auto poly = random_polygon<T>(rng, S);
    // Half of the points lie near the plane, where inside/outside matters most; half of those
    // project close to the frame's origin, which lies in the polygon's kernel (mostly inside),
    // the other half anywhere in the polygon's square.
    Vec3<T> p = rng.vec<T, 3>(-T(1.5) * S, T(1.5) * S);
    if (n % 2) {
      const T w = n % 4 == 1 ? T(0.1) * S : S;
      p = point_at(poly, Vec2<T>{rng.uniform<T>(-w, w), rng.uniform<T>(-w, w)}) +
          poly.frame.normal * rng.uniform<T>(T(-0.1), T(0.1));
    }
    const auto r = distance(p, poly);
    const mpq_class e = exact_sqr(p, poly);
    EXPECT_NEAR(double(r.sqr_distance), e.get_d(), double(tol<T>(64, T(100)))) << "case " << n;
    inside += r.param_b == to_plane(poly.frame, p);
  }
  EXPECT_GT(inside, kCases / 4);
}

// Figures 10.14, 10.15: a concave (L-shaped) polygon in a tilted plane; a point above its inside
// projects straight down, a point above the notch is closest to the notch's edges, a point
// beyond a convex corner to that corner.
TYPED_TEST(PointPolygon3Test, Figure10_15ConcavePolygon) {
  using T = TypeParam;
  // The plane z = 2 with the frame axes x, y; the L: (0,0) (4,0) (4,1) (1,1) (1,4) (0,4).
  PlanarPolygon3<T> L{
      {{T(0), T(0), T(2)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}},
      {{{T(0), T(0)}, {T(4), T(0)}, {T(4), T(1)}, {T(1), T(1)}, {T(1), T(4)}, {T(0), T(4)}}}};
  const auto in = distance(Vec3<T>{T(0.5), T(3), T(5)}, L);
  EXPECT_EQ(in.distance, T(3));
  EXPECT_EQ(in.param_b, (Vec2<T>{T(0.5), T(3)}));
  const auto notch = distance(Vec3<T>{T(3), T(2), T(2)}, L);  // in the plane, in the notch
  EXPECT_EQ(notch.distance, T(1));
  EXPECT_TRUE(locus_test::vec_near(notch.param_b, Vec2<T>{T(3), T(1)}, tol<T>(8, T(4))));
  // Above the notch, nearer the edge y = 1 than the edge x = 1.
  const auto notch_above = distance(Vec3<T>{T(3), T(2.5), T(4)}, L);
  EXPECT_NEAR(notch_above.sqr_distance, T(2.25) + T(4), tol<T>(16, T(8)));
  EXPECT_TRUE(locus_test::vec_near(notch_above.param_b, Vec2<T>{T(3), T(1)}, tol<T>(8, T(4))));
  const auto out = distance(Vec3<T>{T(6), T(-1), T(2)}, L);  // beyond the convex corner (4, 0)
  EXPECT_EQ(out.sqr_distance, T(5));
  EXPECT_EQ(out.closest[1], (Vec3<T>{T(4), T(0), T(2)}));
  // Either orientation of the vertex list gives the same filled region.
  auto reversed = L;
  std::reverse(reversed.polygon.vertices.begin(), reversed.polygon.vertices.end());
  EXPECT_EQ(distance(Vec3<T>{T(3), T(2), T(2)}, reversed).distance, T(1));
  EXPECT_EQ(distance(Vec3<T>{T(0.5), T(3), T(5)}, reversed).distance, T(3));
  // Swapped overload.
  const auto sw = distance(L, Vec3<T>{T(6), T(-1), T(2)});
  EXPECT_EQ(sw.closest[0], out.closest[1]);
  EXPECT_EQ(sw.param_a, out.param_b);
}

// planar_polygon() from 3D vertices: the same distances as the frame-based polygon, for a planar
// polygon given in a tilted plane.
TYPED_TEST(PointPolygon3Test, FromThreeDimensionalVertices) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int n = 0; n < 50; ++n) {
    const auto poly = random_polygon<T>(rng, T(4));
    std::vector<Vec3<T>> v3;
    for (const auto& v : poly.polygon.vertices) v3.push_back(point_at(poly, v));
    const auto built = planar_polygon<T>(v3);
    ASSERT_TRUE(built.has_value());
    EXPECT_NEAR(std::abs(dot(built->frame.normal, poly.frame.normal)), T(1), tol<T>(64));
    for (std::size_t i = 0; i < v3.size(); ++i)
      EXPECT_TRUE(locus_test::vec_near(vertex(*built, i), v3[i], tol<T>(64, T(8))));
    const auto p = rng.vec<T, 3>(T(-6), T(6));
    EXPECT_NEAR(distance(p, *built).distance, distance(p, poly).distance, tol<T>(128, T(8)));
  }
  const std::vector<Vec3<T>> collinear{{T(0), T(0), T(0)}, {T(1), T(1), T(1)}, {T(2), T(2), T(2)}};
  EXPECT_FALSE(planar_polygon<T>(collinear).has_value());
  EXPECT_FALSE(planar_polygon<T>(std::vector<Vec3<T>>{{T(0), T(0), T(0)}}).has_value());
}

TYPED_TEST(PointPolygon3Test, DegenerateAndNonFiniteInput) {
  using T = TypeParam;
  const PlaneFrame3<T> frame{
      {T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}};
  // One vertex: a point; two: a segment (no interior).
  const PlanarPolygon3<T> point{frame, {{{T(1), T(1)}}}};
  EXPECT_EQ(distance(Vec3<T>{T(1), T(4), T(5)}, point).sqr_distance, T(34));
  const PlanarPolygon3<T> seg{frame, {{{T(0), T(0)}, {T(4), T(0)}}}};
  EXPECT_EQ(distance(Vec3<T>{T(2), T(0), T(3)}, seg).distance, T(3));
  EXPECT_EQ(distance(Vec3<T>{T(2), T(1), T(0)}, seg).distance, T(1));
  // Repeated vertices change nothing.
  const PlanarPolygon3<T> sq{
      frame, {{{T(0), T(0)}, {T(2), T(0)}, {T(2), T(0)}, {T(2), T(2)}, {T(0), T(2)}}}};
  EXPECT_EQ(distance(Vec3<T>{T(1), T(1), T(1)}, sq).distance, T(1));
  EXPECT_EQ(distance(Vec3<T>{T(3), T(1), T(0)}, sq).distance, T(1));
  // Empty polygon and non-finite values.
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, PlanarPolygon3<T>{frame, {}})));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{nan, T(0), T(0)}, sq)));
  auto bad = sq;
  bad.polygon.vertices[3].x = inf;
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, bad)));
  bad = sq;
  bad.frame.normal.z = nan;
  EXPECT_TRUE(dist::is_nan_result(distance(bad, Vec3<T>{})));
}
