// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_line.hpp, point_ray.hpp, point_segment.hpp (rows dist2.pt-linear,
// dist3.pt-linear; book figures 6.1-6.3 and 10.2-10.4).
#include <locus/distance/point_line.hpp>
#include <locus/distance/point_ray.hpp>
#include <locus/distance/point_segment.hpp>

#include "distance/exact.hpp"
#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <limits>
#include <type_traits>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class PointLinearTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointLinearTest, locus_test::RealTypes);

namespace {

// Random directions of length 0.5..2, occasionally (1 in 10) zero.
template <class T, int N>
Vec<T, N> random_dir(Rng& rng) {
  if (rng.uniform_int(0, 9) == 0) return Vec<T, N>{};
  return rng.unit<T, N>() * rng.uniform<T>(T(0.5), T(2));
}

template <class T, int N>
void harness_all() {
  const T S = 10;
  dist::check_pairs<T, N, Vec<T, N>, Line<T, N>>([&](Rng& rng) {
    return std::pair{rng.vec<T, N>(-S, S), Line<T, N>{rng.vec<T, N>(-S, S), random_dir<T, N>(rng)}};
  });
  dist::check_pairs<T, N, Vec<T, N>, Ray<T, N>>([&](Rng& rng) {
    return std::pair{rng.vec<T, N>(-S, S), Ray<T, N>{rng.vec<T, N>(-S, S), random_dir<T, N>(rng)}};
  });
  dist::check_pairs<T, N, Vec<T, N>, Segment<T, N>>([&](Rng& rng) {
    const auto p0 = rng.vec<T, N>(-S, S);
    const auto p1 = rng.uniform_int(0, 9) == 0 ? p0 : rng.vec<T, N>(-S, S);
    return std::pair{rng.vec<T, N>(-S, S), Segment<T, N>{p0, p1}};
  });
}

template <class T, int N>
void exact_all() {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T S = 10;
  for (int n = 0; n < 500; ++n) {
    const auto p = rng.vec<T, N>(-S, S), o = rng.vec<T, N>(-S, S), q = rng.vec<T, N>(-S, S);
    const auto d = random_dir<T, N>(rng);
    const auto qp = ex::to_q(p);
    // Squared distances are computed from rounded closest points: error a few eps * scale^2.
    const double t2 = double(tol<T>(32, S * S));
    EXPECT_NEAR(double(distance(p, Line<T, N>{o, d}).sqr_distance),
                ex::sqr_point_linear(qp, ex::line(o, d)).get_d(), t2);
    EXPECT_NEAR(double(distance(p, Ray<T, N>{o, d}).sqr_distance),
                ex::sqr_point_linear(qp, ex::ray(o, d)).get_d(), t2);
    EXPECT_NEAR(double(distance(p, Segment<T, N>{o, q}).sqr_distance),
                ex::sqr_point_linear(qp, ex::segment(o, q)).get_d(), t2);
  }
}

}  // namespace

TYPED_TEST(PointLinearTest, Harness2D) { harness_all<TypeParam, 2>(); }
TYPED_TEST(PointLinearTest, Harness3D) { harness_all<TypeParam, 3>(); }
TYPED_TEST(PointLinearTest, ExactRationalOracle2D) { exact_all<TypeParam, 2>(); }
TYPED_TEST(PointLinearTest, ExactRationalOracle3D) { exact_all<TypeParam, 3>(); }

// Figure 6.1 / 10.2: the projection onto the line, t measured in units of |direction|.
TYPED_TEST(PointLinearTest, Figure6_1PointLine) {
  using T = TypeParam;
  const Line2<T> l{{T(1), T(1)}, {T(2), T(0)}};
  const auto r = distance(Vec2<T>{T(4), T(5)}, l);
  EXPECT_EQ(r.param_b, T(1.5));
  EXPECT_EQ(r.closest[1], (Vec2<T>{T(4), T(1)}));
  EXPECT_EQ(r.distance, T(4));
  EXPECT_EQ(r.sqr_distance, T(16));
  EXPECT_TRUE(r.unique);
  // Behind the origin the line still projects (t < 0).
  const auto b = distance(Vec3<T>{T(-3), T(2), T(0)}, Line3<T>{{}, {T(1), T(0), T(0)}});
  EXPECT_EQ(b.param_b, T(-3));
  EXPECT_EQ(b.distance, T(2));
}

// Figure 6.2 / 10.3: a point behind the ray's origin is nearest to the origin.
TYPED_TEST(PointLinearTest, Figure6_2PointRay) {
  using T = TypeParam;
  const Ray2<T> ray{{T(1), T(1)}, {T(1), T(0)}};
  const auto front = distance(Vec2<T>{T(3), T(4)}, ray);
  EXPECT_EQ(front.param_b, T(2));
  EXPECT_EQ(front.distance, T(3));
  const auto behind = distance(Vec2<T>{T(-2), T(5)}, ray);
  EXPECT_EQ(behind.param_b, T(0));
  EXPECT_EQ(behind.closest[1], ray.origin);
  EXPECT_EQ(behind.distance, T(5));
}

// Figure 6.3 / 10.4: the three cases t <= 0, 0 < t < 1, t >= 1; endpoints are exact.
TYPED_TEST(PointLinearTest, Figure6_3PointSegmentThreeRegions) {
  using T = TypeParam;
  const Segment3<T> s{{T(0.1), T(0.2), T(0.3)}, {T(4.1), T(0.2), T(0.3)}};
  const auto before = distance(Vec3<T>{T(-2), T(0), T(0)}, s);
  EXPECT_EQ(before.param_b, T(0));
  EXPECT_EQ(before.closest[1], s.p0);
  const auto after = distance(Vec3<T>{T(9), T(5), T(-1)}, s);
  EXPECT_EQ(after.param_b, T(1));
  EXPECT_EQ(after.closest[1], s.p1);
  const auto mid = distance(Vec3<T>{T(1.1), T(3.2), T(0.3)}, s);
  EXPECT_NEAR(mid.param_b, T(0.25), tol<T>(4));
  EXPECT_NEAR(mid.distance, T(3), tol<T>(8, T(3)));
}

TYPED_TEST(PointLinearTest, SwappedArgumentsAreBitIdentical) {
  using T = TypeParam;
  const Segment2<T> s{{T(0), T(0)}, {T(1), T(3)}};
  const Vec2<T> p{T(2), T(-1)};
  const auto r = distance(p, s);
  const auto q = distance(s, p);
  EXPECT_EQ(q.distance, r.distance);
  EXPECT_EQ(q.closest[0], r.closest[1]);
  EXPECT_EQ(q.closest[1], r.closest[0]);
  EXPECT_EQ(q.param_a, r.param_b);
  EXPECT_EQ(closest_point(p, s), r.closest[1]);
  EXPECT_EQ(closest_point(p, Line2<T>{s.p0, s.p1 - s.p0}),
            distance(p, Line2<T>{s.p0, s.p1 - s.p0}).closest[1]);
}

// Zero directions and zero-length segments act as points.
TYPED_TEST(PointLinearTest, DegenerateComponentsActAsPoints) {
  using T = TypeParam;
  const Vec3<T> o{T(1), T(2), T(3)}, p{T(1), T(6), T(6)};
  for (const auto& r : {distance(p, Line3<T>{o, {}}), distance(p, Ray3<T>{o, {}}),
                        distance(p, Segment3<T>{o, o})}) {
    EXPECT_EQ(r.param_b, T(0));
    EXPECT_EQ(r.closest[1], o);
    EXPECT_EQ(r.distance, T(5));
    EXPECT_TRUE(r.unique);
  }
  // A direction whose square underflows is still a direction (it is scaled before squaring).
  const T tiny = std::is_same_v<T, float> ? T(1e-30) : T(1e-200);
  ASSERT_EQ(tiny * tiny, T(0));
  const auto r = distance(Vec2<T>{T(3), T(1)}, Line2<T>{{}, {tiny, T(0)}});
  EXPECT_TRUE(locus_test::vec_near(r.closest[1], Vec2<T>{T(3), T(0)}, tol<T>(8, T(3))));
  EXPECT_NEAR(r.distance, T(1), tol<T>(8));
}

TYPED_TEST(PointLinearTest, NonFiniteInputGivesNaNResult) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Vec3<T> p{T(1), T(2), T(3)}, bad{nan, T(0), T(0)}, big{inf, T(0), T(0)};
  const Vec3<T> d{T(1), T(0), T(0)};
  EXPECT_TRUE(dist::is_nan_result(distance(bad, Line3<T>{p, d})));
  EXPECT_TRUE(dist::is_nan_result(distance(p, Line3<T>{p, bad})));
  EXPECT_TRUE(dist::is_nan_result(distance(p, Ray3<T>{big, d})));
  EXPECT_TRUE(dist::is_nan_result(distance(p, Ray3<T>{p, big})));
  EXPECT_TRUE(dist::is_nan_result(distance(p, Segment3<T>{p, bad})));
  EXPECT_TRUE(dist::is_nan_result(distance(Segment3<T>{big, p}, p)));
  const auto r = distance(p, Segment3<T>{p, bad});
  EXPECT_TRUE(std::isnan(r.param_b));
  EXPECT_TRUE(std::isnan(r.closest[1].x));
}
