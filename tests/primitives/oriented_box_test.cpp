// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/oriented_box.hpp (row prim3.solids: OBB).
#include <locus/primitives/oriented_box.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class OrientedBoxTest : public ::testing::Test {};
TYPED_TEST_SUITE(OrientedBoxTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<OrientedBox3d> && std::is_trivially_copyable_v<OrientedBox3f>);

namespace {
// A random rotation from a random unit quaternion (independent of any library rotation code).
template <class T>
Mat3<T> random_rotation(Rng& rng) {
  const auto q = rng.unit<double, 4>();
  const double w = q.x, x = q.y, y = q.z, z = q.w;
  const Mat3<double> m{{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                        {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                        {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
  Mat3<T> r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.a[i][j] = static_cast<T>(m.a[i][j]);
  return r;
}
}  // namespace

TYPED_TEST(OrientedBoxTest, FromAlignedBoxMatchesCornersAndMeasures) {
  using T = TypeParam;
  const AlignedBox3<T> a{{-1, 2, -3}, {4, 5, 6}};
  const auto b = oriented_box(a);
  const auto ca = corners(a), cb = corners(b);
  for (std::size_t k = 0; k < 8; ++k) EXPECT_EQ(ca[k], cb[k]);
  EXPECT_EQ(volume(b), volume(a));
  EXPECT_EQ(surface_area(b), surface_area(a));
  EXPECT_EQ(point_at(b, Vec3<T>{}), center(a));
  const auto bb = bounding_box(b);
  EXPECT_EQ(bb.min, a.min);
  EXPECT_EQ(bb.max, a.max);
}

TYPED_TEST(OrientedBoxTest, RotatedBoxKeepsMeasuresAndCornerDistances) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 200; ++trial) {
    auto p = rng.vec<T, 3>(-5, 5), q = rng.vec<T, 3>(-5, 5);
    const AlignedBox3<T> a{cwise_min(p, q), cwise_max(p, q)};
    const Mat3<T> r = random_rotation<T>(rng);
    const auto b = rotated(oriented_box(a), r);
    const T scale = T(10);
    EXPECT_NEAR(volume(b), volume(a), tol<T>(16) * volume(a));
    const auto ca = corners(a), cb = corners(b);
    for (std::size_t k = 0; k < 8; ++k) {
      // Rotating a corner directly agrees with the rotated box's corner.
      EXPECT_TRUE(vec_near(cb[k], r * ca[k], tol<T>(32, scale)));
      for (std::size_t j = 0; j < k; ++j)
        EXPECT_NEAR(length(cb[k] - cb[j]), length(ca[k] - ca[j]), tol<T>(64, scale));
    }
    // The bounding box is tight: brute force over the corners.
    const auto bb = bounding_box(b);
    const auto bc = bounding_box(std::span<const Vec3<T>>(cb.data(), cb.size()));
    EXPECT_TRUE(vec_near(bb.min, bc.min, tol<T>(32, scale)));
    EXPECT_TRUE(vec_near(bb.max, bc.max, tol<T>(32, scale)));
    // point_at stays inside: its coordinates along the axes are bounded by the extents.
    for (int s = 0; s < 10; ++s) {
      const auto u = rng.vec<T, 3>(-1, 1);
      const Vec3<T> x = point_at(b, u) - b.center;
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(dot(x, b.axis[i]), u[i] * b.extent[i], tol<T>(32, scale));
    }
  }
}

TYPED_TEST(OrientedBoxTest, TwoDimensionalAndDegenerate) {
  using T = TypeParam;
  const T c = std::sqrt(T(0.5));
  const OrientedBox2<T> b{{1, 1}, {{c, c}, {-c, c}}, {2, 1}};
  EXPECT_NEAR(area(b), T(8), tol<T>(4, 8));
  const auto cs = corners(b);
  // Corner 3 = center + 2 a0 + 1 a1.
  EXPECT_TRUE(vec_near(cs[3], Vec2<T>{1 + 2 * c - c, 1 + 2 * c + c}, tol<T>(8, 4)));
  // Shoelace area of the corner quadrilateral in the order 0, 1, 3, 2.
  const Vec2<T> ring[4] = {cs[0], cs[1], cs[3], cs[2]};
  T s = 0;
  for (int i = 0; i < 4; ++i) s += perp_dot(ring[i], ring[(i + 1) % 4]);
  EXPECT_NEAR(s / 2, area(b), tol<T>(32, 8));
  // Flat box and invalid extent.
  const OrientedBox3<T> flat{{0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, 0, 2}};
  EXPECT_EQ(volume(flat), T(0));
  EXPECT_EQ(surface_area(flat), T(16));
  const OrientedBox3<T> bad{{0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, -1, 2}};
  EXPECT_TRUE(std::isnan(volume(bad)));
  EXPECT_TRUE(std::isnan(surface_area(bad)));
}
