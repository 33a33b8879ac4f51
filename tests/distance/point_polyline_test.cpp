// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_polyline.hpp (rows dist2.pt-polyline, dist3.pt-linear; book figures
// 6.4 and 10.5).
#include <locus/distance/point_polyline.hpp>
#include <locus/distance/point_segment.hpp>

#include "distance/exact.hpp"
#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <limits>
#include <utility>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class PointPolylineTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointPolylineTest, locus_test::RealTypes);

namespace {

// 1..16 vertices, open or closed, with occasional repeated vertices (zero-length segments).
template <class T, int N>
Polyline<T, N> random_polyline(Rng& rng, T S) {
  Polyline<T, N> p;
  const int n = rng.uniform_int(1, 16);
  for (int i = 0; i < n; ++i) {
    if (i > 0 && rng.uniform_int(0, 9) == 0)
      p.vertices.push_back(p.vertices.back());
    else
      p.vertices.push_back(rng.vec<T, N>(-S, S));
  }
  p.closed = rng.uniform_int(0, 1) == 1;
  return p;
}

template <class T, int N>
void harness() {
  const T S = 10;
  dist::Options<T> opt;
  opt.check_agreement = false;  // not convex: the brute-force and exact oracles below agree
  dist::check_pairs<T, N, Vec<T, N>, Polyline<T, N>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, N>(-T(1.5) * S, T(1.5) * S), random_polyline<T, N>(rng, S)};
      },
      opt);
}

// Brute force over every segment (no rejection) and the exact rational minimum.
template <class T, int N>
void oracles() {
  Rng rng(locus_test::test_seed() + 3);
  SCOPED_TRACE(rng.trace());
  const T S = 10;
  for (int n = 0; n < 300; ++n) {
    const auto poly = random_polyline<T, N>(rng, S);
    const auto p = rng.vec<T, N>(-T(1.5) * S, T(1.5) * S);
    const auto r = distance(p, poly);
    T brute = sqr_length(poly.vertices[0] - p);
    mpq_class exact =
        ex::sqr_point_linear(ex::to_q(p), ex::segment(poly.vertices[0], poly.vertices[0]));
    for (std::size_t i = 0; i < segment_count(poly); ++i) {
      const auto s = edge(poly, i);
      brute = std::min(brute, distance(p, s).sqr_distance);
      const mpq_class q = ex::sqr_point_linear(ex::to_q(p), ex::segment(s.p0, s.p1));
      if (q < exact) exact = q;
    }
    EXPECT_NEAR(r.sqr_distance, brute, tol<T>(4, brute)) << "case " << n;
    EXPECT_NEAR(double(r.sqr_distance), exact.get_d(), double(tol<T>(32, S * S))) << "case " << n;
  }
}

}  // namespace

TYPED_TEST(PointPolylineTest, Harness2D) { harness<TypeParam, 2>(); }
TYPED_TEST(PointPolylineTest, Harness3D) { harness<TypeParam, 3>(); }
TYPED_TEST(PointPolylineTest, BruteForceAndExactOracles2D) { oracles<TypeParam, 2>(); }
TYPED_TEST(PointPolylineTest, BruteForceAndExactOracles3D) { oracles<TypeParam, 3>(); }

// Figure 6.4: a polyline whose segments mostly lie outside the strip |x - p.x| <= mu; the
// answer is on the one segment that crosses the strip near p.
TYPED_TEST(PointPolylineTest, Figure6_4StripRejection) {
  using T = TypeParam;
  const Polyline2<T> poly{{{T(-8), T(6)},
                           {T(-6), T(-5)},
                           {T(-3), T(7)},
                           {T(1), T(3)},
                           {T(3), T(3)},
                           {T(3), T(9)},
                           {T(9), T(5)}},
                          false};
  const auto r = distance(Vec2<T>{T(2), T(1)}, poly);
  EXPECT_EQ(r.distance, T(2));
  EXPECT_EQ(r.closest[1], (Vec2<T>{T(2), T(3)}));
  EXPECT_EQ(r.param_b, T(3.5));
  EXPECT_EQ(point_at(poly, r.param_b), r.closest[1]);
  // Closed: the closing segment (9,5)-(-8,6) can be the nearest.
  Polyline2<T> closed = poly;
  closed.closed = true;
  const auto c = distance(Vec2<T>{T(-7), T(9)}, closed);
  EXPECT_GT(c.param_b, T(6));
  EXPECT_NEAR(c.distance,
              distance(Vec2<T>{T(-7), T(9)}, Segment2<T>{{T(9), T(5)}, {T(-8), T(6)}}).distance,
              tol<T>(8, T(10)));
  EXPECT_EQ(distance(closed, Vec2<T>{T(-7), T(9)}).closest[0], c.closest[1]);
}

TYPED_TEST(PointPolylineTest, DegenerateAndBadInput) {
  using T = TypeParam;
  const Polyline3<T> one{{{T(1), T(2), T(3)}}, false};
  const auto r = distance(Vec3<T>{T(1), T(5), T(7)}, one);
  EXPECT_EQ(r.distance, T(5));
  EXPECT_EQ(r.param_b, T(0));
  const Polyline3<T> empty{};
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, empty)));
  Polyline3<T> bad{{{T(0), T(0), T(0)}, {T(1), std::numeric_limits<T>::quiet_NaN(), T(0)}}, false};
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, bad)));
  EXPECT_TRUE(
      dist::is_nan_result(distance(Vec3<T>{std::numeric_limits<T>::infinity(), T(0), T(0)}, one)));
}
