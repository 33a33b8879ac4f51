// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_rectangle.hpp, point_aligned_box.hpp, point_oriented_box.hpp (rows
// dist2.pt-rectangle, dist3.pt-rectangle, dist3.pt-obb; book figures 6.10, 10.11-10.13, 10.21,
// 10.22).
#include <locus/distance/batch.hpp>
#include <locus/distance/detail/branchless.hpp>
#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_rectangle.hpp>

#include "distance/exact.hpp"
#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
namespace dist = locus_test::dist;
namespace ex = locus_test::exact;

template <class T>
class PointBoxTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointBoxTest, locus_test::RealTypes);

namespace {

// Extents in [0, 5], one in 8 exactly zero (flat boxes and rectangles).
template <class T>
T random_extent(Rng& rng) {
  return rng.uniform_int(0, 7) == 0 ? T(0) : rng.uniform<T>(T(0.01), T(5));
}

template <class T, int N>
OrientedBox<T, N> random_obb(Rng& rng, T S) {
  const auto r = dist::random_rotation<T, N>(rng);
  OrientedBox<T, N> b{};
  b.center = rng.vec<T, N>(-S, S);
  for (int i = 0; i < N; ++i) {
    b.axis[i] = col(r, i);
    b.extent[i] = random_extent<T>(rng);
  }
  return b;
}

template <class T, int N>
Rectangle<T, N> random_rectangle(Rng& rng, T S) {
  const auto r = dist::random_rotation<T, N>(rng);
  return {
      rng.vec<T, N>(-S, S), {col(r, 0), col(r, 1)}, {random_extent<T>(rng), random_extent<T>(rng)}};
}

template <class T, int N>
AlignedBox<T, N> random_aabb(Rng& rng, T S) {
  const auto c = rng.vec<T, N>(-S, S);
  Vec<T, N> e{};
  for (int i = 0; i < N; ++i) e[i] = random_extent<T>(rng);
  return {c - e, c + e};
}

template <class T, int N>
void harness() {
  const T S = 10;
  dist::check_pairs<T, N, Vec<T, N>, AlignedBox<T, N>>([&](Rng& rng) {
    return std::pair{rng.vec<T, N>(-S, S), random_aabb<T, N>(rng, S)};
  });
  dist::check_pairs<T, N, Vec<T, N>, OrientedBox<T, N>>([&](Rng& rng) {
    return std::pair{rng.vec<T, N>(-S, S), random_obb<T, N>(rng, S)};
  });
  dist::check_pairs<T, N, Vec<T, N>, Rectangle<T, N>>([&](Rng& rng) {
    return std::pair{rng.vec<T, N>(-S, S), random_rectangle<T, N>(rng, S)};
  });
}

// Exact oracle for the aligned box (sum of squared excesses in rationals); for the oriented box
// the same in rationals in the box's frame (the input axes are orthonormal to rounding, so this
// is the true distance to a few eps scale^2), and a second algorithm: the aligned query on the
// rounded frame coordinates. sqr_distance equals the full query exactly.
template <class T, int N>
void oracles() {
  Rng rng(locus_test::test_seed() + 11);
  SCOPED_TRACE(rng.trace());
  const T S = 10;
  for (int n = 0; n < 400; ++n) {
    const auto p = rng.vec<T, N>(-S, S);
    const auto box = random_aabb<T, N>(rng, S);
    mpq_class e = 0;
    for (int i = 0; i < N; ++i) {
      const mpq_class x{double(p[i])}, lo{double(box.min[i])}, hi{double(box.max[i])};
      if (x < lo) e += (lo - x) * (lo - x);
      if (x > hi) e += (x - hi) * (x - hi);
    }
    const auto r = distance(p, box);
    // Error analysis (u = eps / 2): each term sqr(p[i] - bound) carries two roundings on top of
    // the exact square and each of the N - 1 additions one more (the first adds to 0, exactly),
    // so |r - e| <= gamma_{N+2} e, gamma_k = k u / (1 - k u); plus one double ulp of e for
    // e.get_d() and the difference. Relative to e, not to S^2: the point may be 2 S off the box
    // on every axis (e up to 4 N S^2); seeds 17 and 37 found e = 569 and 558 off by 1.8 eps e,
    // beyond the former bound 8 eps S^2.
    const double u = double(locus::eps_v<T>) / 2, ku = (N + 2) * u;
    EXPECT_NEAR(double(r.sqr_distance), e.get_d(), (ku / (1 - ku) + 0x1p-52) * e.get_d())
        << "case " << n;
    EXPECT_EQ(sqr_distance(p, box), r.sqr_distance) << "case " << n;
    EXPECT_EQ(sqr_distance(box, p), r.sqr_distance) << "case " << n;
    const auto obb = random_obb<T, N>(rng, S);
    Vec<T, N> local{};
    for (int i = 0; i < N; ++i) local[i] = dot(p - obb.center, obb.axis[i]);
    const auto o = distance(p, obb);
    const auto a = distance(local, AlignedBox<T, N>{-obb.extent, obb.extent});
    EXPECT_NEAR(o.sqr_distance, a.sqr_distance, tol<T>(64, S * S)) << "case " << n;
    mpq_class eo = 0;
    const auto d = ex::sub(ex::to_q(p), ex::to_q(obb.center));
    for (int i = 0; i < N; ++i) {
      const mpq_class x = ex::dot(d, ex::to_q(obb.axis[i])), h(double(obb.extent[i]));
      if (x < -h) eo += (x + h) * (x + h);
      if (x > h) eo += (x - h) * (x - h);
    }
    EXPECT_NEAR(double(o.sqr_distance), eo.get_d(), double(tol<T>(64, S * S))) << "case " << n;
    EXPECT_EQ(sqr_distance(p, obb), o.sqr_distance) << "case " << n;
    EXPECT_EQ(sqr_distance(obb, p), o.sqr_distance) << "case " << n;
  }
}

}  // namespace

TYPED_TEST(PointBoxTest, Harness2D) { harness<TypeParam, 2>(); }
TYPED_TEST(PointBoxTest, Harness3D) { harness<TypeParam, 3>(); }
TYPED_TEST(PointBoxTest, ExactAndFrameOracles2D) { oracles<TypeParam, 2>(); }
TYPED_TEST(PointBoxTest, ExactAndFrameOracles3D) { oracles<TypeParam, 3>(); }

// Figure 6.10: the nine regions around a rectangle: inside, four edge strips, four corners.
TYPED_TEST(PointBoxTest, Figure6_10NineRegions) {
  using T = TypeParam;
  const Rectangle2<T> r{{T(1), T(1)}, {{T(0.6), T(0.8)}, {T(-0.8), T(0.6)}}, {T(5), T(2.5)}};
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      SCOPED_TRACE("region " + std::to_string(i) + "," + std::to_string(j));
      // Local coordinates: inside the strip (|s| < 5) or 3 beyond it; same for t with 2.
      const T s = i == 0 ? T(2) : T(i) * T(8), t = j == 0 ? T(-1) : T(j) * T(6.5);
      const auto p = point_at(r, Vec2<T>{s, t});
      const auto d = distance(p, r);
      const T es = i == 0 ? T(0) : T(3), et = j == 0 ? T(0) : T(4);
      EXPECT_NEAR(d.distance, std::sqrt(es * es + et * et), tol<T>(32, T(10)));
      EXPECT_NEAR(d.param_b.x, i == 0 ? s : T(i) * T(5), tol<T>(16, T(10)));
      EXPECT_NEAR(d.param_b.y, j == 0 ? t : T(j) * T(2.5), tol<T>(16, T(10)));
    }
  }
}

// Figures 10.11-10.13: a rectangle in 3D; the height above the plane adds in quadrature.
TYPED_TEST(PointBoxTest, Figure10_11RectangleIn3D) {
  using T = TypeParam;
  const Rectangle3<T> r{{T(0), T(0), T(0)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(2), T(1)}};
  const auto above = distance(Vec3<T>{T(1), T(0.5), T(4)}, r);
  EXPECT_EQ(above.distance, T(4));
  EXPECT_EQ(above.param_b, (Vec2<T>{T(1), T(0.5)}));
  const auto corner = distance(Vec3<T>{T(5), T(5), T(12)}, r);
  EXPECT_EQ(corner.closest[1], (Vec3<T>{T(2), T(1), T(0)}));
  EXPECT_EQ(corner.distance, T(13));
}

// Figures 10.21 / 10.22: point to AABB and OBB, inside, face, edge and corner regions.
TYPED_TEST(PointBoxTest, Figure10_21BoxRegions) {
  using T = TypeParam;
  const AlignedBox3<T> box{{T(0), T(0), T(0)}, {T(2), T(4), T(6)}};
  EXPECT_EQ(distance(Vec3<T>{T(1), T(1), T(1)}, box).distance, T(0));
  EXPECT_EQ(distance(Vec3<T>{T(1), T(1), T(9)}, box).distance, T(3));  // face
  EXPECT_EQ(distance(Vec3<T>{T(5), T(8), T(3)}, box).distance, T(5));  // edge
  const auto c = distance(Vec3<T>{T(-2), T(-4), T(10)}, box);          // corner
  EXPECT_EQ(c.closest[1], (Vec3<T>{T(0), T(0), T(6)}));
  EXPECT_EQ(c.distance, T(6));
  EXPECT_EQ(c.param_b, (Vec3<T>{T(0), T(0), T(1)}));
  // The same box as an OBB rotated by 90 degrees about z: (x, y) -> (-y, x).
  OrientedBox3<T> obb{{T(-2), T(1), T(3)},
                      {{T(0), T(1), T(0)}, {T(-1), T(0), T(0)}, {T(0), T(0), T(1)}},
                      {T(1), T(2), T(3)}};
  const auto o = distance(Vec3<T>{T(4), T(-2), T(10)}, obb);  // the corner case, rotated
  EXPECT_EQ(o.closest[1], (Vec3<T>{T(0), T(0), T(6)}));
  EXPECT_EQ(o.distance, T(6));
  EXPECT_EQ(o.param_b, (Vec3<T>{T(-1), T(-1), T(1)}));
  EXPECT_EQ(closest_point(Vec3<T>{T(4), T(-2), T(10)}, obb), o.closest[1]);
  EXPECT_EQ(distance(obb, Vec3<T>{T(4), T(-2), T(10)}).closest[0], o.closest[1]);
}

// Flat boxes (zero extents) and negative extents.
TYPED_TEST(PointBoxTest, FlatBoxes) {
  using T = TypeParam;
  const AlignedBox2<T> seg{{T(0), T(1)}, {T(4), T(1)}};
  const auto r = distance(Vec2<T>{T(2), T(4)}, seg);
  EXPECT_EQ(r.distance, T(3));
  EXPECT_EQ(r.param_b, (Vec2<T>{T(0.5), T(0)}));
  const OrientedBox2<T> point{{T(1), T(1)}, {{T(1), T(0)}, {T(0), T(1)}}, {T(0), T(0)}};
  EXPECT_EQ(distance(Vec2<T>{T(4), T(5)}, point).distance, T(5));
  const OrientedBox2<T> neg{{T(1), T(1)}, {{T(1), T(0)}, {T(0), T(1)}}, {T(-2), T(0)}};
  EXPECT_EQ(distance(Vec2<T>{T(4), T(5)}, neg).distance, T(5));
  const Rectangle3<T> line{
      {T(0), T(0), T(0)}, {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}}, {T(3), T(-1)}};
  EXPECT_EQ(distance(Vec3<T>{T(0), T(3), T(4)}, line).distance, T(5));
  EXPECT_EQ(sqr_distance(Vec2<T>{T(2), T(4)}, seg), T(9));
  EXPECT_EQ(sqr_distance(Vec2<T>{T(4), T(5)}, point), T(25));
  EXPECT_EQ(sqr_distance(neg, Vec2<T>{T(4), T(5)}), T(25));
  // A point inside an oriented box is at distance exactly 0 (measured in the box's frame).
  const OrientedBox3<T> tilted{
      {T(0.1), T(0.2), T(0.3)},
      {{T(0.6), T(0.8), T(0)}, {T(-0.8), T(0.6), T(0)}, {T(0), T(0), T(1)}},
      {T(1), T(2), T(3)}};
  EXPECT_EQ(distance(Vec3<T>{T(0.7), T(-0.4), T(1.1)}, tilted).distance, T(0));
  EXPECT_EQ(sqr_distance(Vec3<T>{T(0.7), T(-0.4), T(1.1)}, tilted), T(0));
}

// Axes orthonormal only to rounding: a Gram-Schmidt of two nearly parallel random directions
// (the harness's random_rotation, LOCUS_TEST_SEED=36, case 152) left axis[0] . axis[1] = 44 eps
// (double) and 26 eps (float). |sum excess[i] axis[i]| then differed from the frame distance by
// 14 eps (double) and 9 eps (float) of it; the closest point is scaled to the distance, so the
// two agree to a few ulps of the distance.
TYPED_TEST(PointBoxTest, RoundedAxesKeepClosestPointAtTheDistance) {
  using T = TypeParam;
  // The double and the float inputs as generated (not one rounded to the other: the float
  // rotation has its own 26 eps).
  const bool f = std::is_same_v<T, float>;
  const Vec3<T> p =
      f ? Vec3<T>{T(0.57035291194915771), T(0.78330159187316895), T(-3.1929647922515869)}
        : Vec3<T>{T(0.57035293498809203), T(0.78330161156357647), T(-3.1929647649279636)};
  const OrientedBox3<T> box =
      f ? OrientedBox3<T>{{T(-4.1484460830688477), T(-1.5370465517044067), T(3.1077721118927002)},
                          {{T(0.25903555750846863), T(0.86315631866455078),
                            T(-0.43343016505241394)},
                           {T(-0.94451630115509033), T(0.13254320621490479),
                            T(-0.30053487420082092)},
                           {T(-0.20196034014225006), T(0.48723107576370239),
                            T(0.84959864616394043)}},
                          {T(0), T(0), T(4.7883920669555664)}}
        : OrientedBox3<T>{
              {T(-4.1484462668237096), T(-1.5370465019321831), T(3.1077721056838783)},
              {{T(0.25903555026251074), T(0.86315634842732192), T(-0.43343015800681178)},
               {T(-0.9445165664459394), T(0.13253920289576354), T(-0.30053588039521828)},
               {T(-0.2019629654401193), T(0.48723144178651834), T(0.84959783587604765)}},
              {T(0), T(0), T(4.7883918605542366)}};
  const auto r = distance(p, box);
  EXPECT_NEAR(length(r.closest[0] - r.closest[1]), r.distance, tol<T>(4, r.distance));
  EXPECT_NEAR(r.distance, T(6.38073), tol<T>(64, T(10)) + T(1e-5));
  EXPECT_TRUE(locus_test::vec_near(point_at(box, r.param_b), r.closest[1], tol<T>(64, T(10))));
  EXPECT_EQ(sqr_distance(p, box), r.sqr_distance);
  // Exactly orthonormal axes and an integer excess: the closest point is exact.
  const OrientedBox3<T> unit{{T(0), T(0), T(0)},
                             {{T(0), T(1), T(0)}, {T(0), T(0), T(1)}, {T(1), T(0), T(0)}},
                             {T(1), T(1), T(1)}};
  const auto q = distance(Vec3<T>{T(4), T(5), T(1)}, unit);
  EXPECT_EQ(q.closest[1], (Vec3<T>{T(1), T(1), T(1)}));
  EXPECT_EQ(q.distance, T(5));
}

TYPED_TEST(PointBoxTest, NonFiniteAndEmptyInputGiveNaNResult) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const AlignedBox3<T> box{{T(0), T(0), T(0)}, {T(1), T(1), T(1)}};
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{nan, T(0), T(0)}, box)));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, empty_box<T, 3>())));
  EXPECT_TRUE(dist::is_nan_result(
      distance(Vec3<T>{}, AlignedBox3<T>{{T(2), T(0), T(0)}, {T(1), T(1), T(1)}})));
  EXPECT_TRUE(dist::is_nan_result(distance(box, Vec3<T>{T(0), inf, T(0)})));
  OrientedBox3<T> obb = oriented_box(box);
  obb.axis[1].y = nan;
  EXPECT_TRUE(dist::is_nan_result(distance(Vec3<T>{}, obb)));
  const Rectangle2<T> r{{T(0), T(0)}, {{T(1), T(0)}, {T(0), T(1)}}, {inf, T(1)}};
  const auto q = distance(Vec2<T>{}, r);
  EXPECT_TRUE(dist::is_nan_result(q));
  EXPECT_TRUE(std::isnan(q.param_b.x));
  // sqr_distance: NaN for a NaN or an infinity anywhere, and for an empty box.
  EXPECT_TRUE(std::isnan(sqr_distance(Vec3<T>{}, empty_box<T, 3>())));
  EXPECT_TRUE(
      std::isnan(sqr_distance(AlignedBox3<T>{{T(2), T(0), T(0)}, {T(1), T(1), T(1)}}, Vec3<T>{})));
  for (int k = 0; k < 9; ++k) {
    for (const T x : {nan, inf, -inf}) {
      Vec3<T> p{T(0.5), T(3), T(0.5)};
      AlignedBox3<T> b = box;
      Vec3<T>* v[3] = {&p, &b.min, &b.max};
      (*v[k / 3])[k % 3] = x;
      EXPECT_TRUE(std::isnan(sqr_distance(p, b))) << k;
      EXPECT_TRUE(std::isnan(sqr_distance(b, p))) << k;
    }
  }
  // The point outside, inside, and at the centre (where p - center = 0 meets an infinite axis).
  const OrientedBox3<T> base = oriented_box(box);
  for (int k = 0; k < 54; ++k) {
    for (const T x : {nan, inf, -inf}) {
      const Vec3<T> points[3] = {
          {T(0.5), T(3), T(0.5)}, base.center + T(0.25) * base.extent, base.center};
      Vec3<T> p = points[k / 18];
      OrientedBox3<T> o = base;
      Vec3<T>* v[6] = {&p, &o.center, &o.extent, &o.axis[0], &o.axis[1], &o.axis[2]};
      (*v[k % 18 / 3])[k % 3] = x;
      EXPECT_TRUE(std::isnan(sqr_distance(p, o))) << k;
      EXPECT_TRUE(std::isnan(sqr_distance(o, p))) << k;
      EXPECT_TRUE(dist::is_nan_result(distance(p, o))) << k;
    }
  }
}

// Finite input whose coordinates in the box frame overflow (p - center beyond the largest finite
// value): the whole result is NaN, as for non-finite input, in both the axis-aligned frame (where
// the old code's zero axis components gave a NaN squared distance presented as a valid result)
// and a rotated one (where it gave an infinite one); sqr_distance and the batch agree.
TYPED_TEST(PointBoxTest, OverflowingFrameCoordinatesGiveNaNResult) {
  using T = TypeParam;
  const T big = std::numeric_limits<T>::max();
  // Every rotated axis has a nonzero x component, so no infinite x times 0 makes a NaN.
  const T r3 = T(1) / std::sqrt(T(3)), r2 = T(1) / std::sqrt(T(2)), r6 = T(1) / std::sqrt(T(6));
  const Vec3<T> rotated[3] = {{r3, r3, r3}, {r2, -r2, T(0)}, {r6, r6, T(-2) * r6}};
  for (const bool rotate : {false, true}) {
    OrientedBox3<T> o{
        {-big, T(0), T(0)},
        {Vec3<T>{T(1), T(0), T(0)}, Vec3<T>{T(0), T(1), T(0)}, Vec3<T>{T(0), T(0), T(1)}},
        {T(1), T(1), T(1)}};
    if (rotate)
      for (int i = 0; i < 3; ++i) o.axis[i] = rotated[i];
    const Vec3<T> p{big, T(0), T(0)};
    EXPECT_TRUE(dist::is_nan_result(distance(p, o))) << rotate;
    EXPECT_TRUE(std::isnan(sqr_distance(p, o))) << rotate;
    T out[1] = {T(0)};
    sqr_distances(std::span<const Vec3<T>>(&p, 1), o, std::span<T>(out));
    EXPECT_TRUE(std::isnan(out[0])) << rotate;
  }
}

// detail/branchless.hpp, the selection primitives of the box fast paths, against the plain
// conditional and std::clamp on random values, signed zeros, infinities and NaN.
TEST(Branchless, SelectAndClampMatchTheConditionalForms) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const double inf = std::numeric_limits<double>::infinity();
  const double specials[] = {0.0, -0.0, 1.0, -1.0, inf, -inf, 5e-324, -1e308};
  for (int i = 0; i < 4000; ++i) {
    const double x = i < 64 ? specials[i % 8] : rng.uniform<double>(-4, 4);
    const double y = i < 64 ? specials[(i / 8) % 8] : rng.uniform<double>(-4, 4);
    const bool c = (i & 1) != 0;
    // Bit-exact: the blend must keep -0.0 and subnormals as they are.
    ASSERT_EQ(std::bit_cast<std::uint64_t>(detail::select(c, x, y)),
              std::bit_cast<std::uint64_t>(c ? x : y))
        << i;
    const float xf = float(x), yf = float(y);
    ASSERT_EQ(std::bit_cast<std::uint32_t>(detail::select(c, xf, yf)),
              std::bit_cast<std::uint32_t>(c ? xf : yf))
        << i;
    const double lo = std::min(x, y), hi = std::max(x, y), v = rng.uniform<double>(-5, 5);
    ASSERT_EQ(detail::clamp_minmax(v, lo, hi), std::clamp(v, lo, hi)) << i;
  }
  // A NaN argument stays NaN (never clamped to a finite-looking bound).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(detail::clamp_minmax(nan, 0.0, 1.0)));
  EXPECT_TRUE(std::isnan(detail::select(true, nan, 1.0)));
  EXPECT_EQ(detail::select(false, nan, 1.0), 1.0);
}
