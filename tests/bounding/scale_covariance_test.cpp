// SPDX-License-Identifier: BSL-1.0
// Scale covariance of the bounding routines (issue 17 item 6; the distance harness's check 8,
// tests/support/scale_covariance.hpp): min_circle, min_sphere, min_rect, min_box and the simplex
// balls on input scaled by 2^k. Every one of them is scale-exact (its arithmetic on the scaled
// input is the unscaled arithmetic times powers of two), so the results must be equal after
// unscaling. The first two tests reproduce the reported defect directly: a reported ball that
// misses input points or is not finite.

#include <locus/bounding/min_box3.hpp>
#include <locus/bounding/min_circle.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/bounding/min_sphere.hpp>
#include <locus/bounding/simplex_balls.hpp>

#include <cmath>
#include <vector>

#include "support/scale_covariance.hpp"
#include "support/typed.hpp"

namespace {

using locus::Status;
using locus::Vec;
using locus::Vec2;
using locus::Vec3;
using locus_test::add;
using locus_test::Covariant;
using locus_test::Rng;
using locus_test::scaled;

template <class T>
class BoundingScale : public ::testing::Test {};
TYPED_TEST_SUITE(BoundingScale, locus_test::RealTypes);

// Random points with coordinates on the grid 2^-10 Z in [-4, 4]: scaled by 2^k they stay
// normal for every k the tests use, so the scaled input is exactly the input times 2^k.
template <class T, int N>
std::vector<Vec<T, N>> grid_points(Rng& rng, int n) {
  std::vector<Vec<T, N>> pts;
  for (int i = 0; i < n; ++i) {
    Vec<T, N> p = rng.vec<T, N>(T(-4), T(4));
    for (int j = 0; j < N; ++j) p[j] = std::ldexp(std::round(std::ldexp(p[j], 10)), -10);
    pts.push_back(p);
  }
  return pts;
}

// Lengths stay finite and normal for coordinates up to 2^3 at these exponents.
template <class T>
std::vector<int> length_exponents() {
  std::vector<int> k;
  for (int e : locus_test::scale_exponents<T>()) k.push_back(e);
  for (int e : locus_test::far_scale_exponents<T>()) k.push_back(e);
  if constexpr (std::is_same_v<T, double>) {
    k.push_back(350);
    k.push_back(300);
    k.push_back(-300);
    k.push_back(-450);
    k.push_back(-500);
  }
  return k;
}

// Areas: |k| up to 500 (double), 55 (float); volumes 330 and 36.
template <class T>
std::vector<int> area_exponents() {
  std::vector<int> k;
  for (int e : locus_test::scale_exponents<T>()) k.push_back(e);
  if constexpr (std::is_same_v<T, double>) {
    k.push_back(-500);
    k.push_back(500);
  } else {
    k.push_back(-55);
    k.push_back(55);
  }
  return k;
}
template <class T>
std::vector<int> volume_exponents() {
  if constexpr (std::is_same_v<T, double>)
    return {-330, -140, 140, 330};
  else
    return {-36, -20, 20, 36};
}

// The reported ball contains every input point (to a few ulps of its radius) and is finite;
// the unscaled check is done on the result scaled back by 2^-k, which is exact.
template <class T, int N>
void expect_ball_contains(const std::vector<Vec<T, N>>& pts, int k, Vec<T, N> center, T radius) {
  ASSERT_TRUE(locus::is_finite(center) && std::isfinite(radius)) << "radius " << radius;
  const Vec<double, N> c = vec_cast<double>(scaled(center, -k));
  const double r = std::ldexp(static_cast<double>(radius), -k);
  double worst = 0.0;
  for (const auto& p : pts) worst = std::max(worst, locus::length(vec_cast<double>(p) - c) - r);
  EXPECT_LE(worst, 16.0 * static_cast<double>(locus::eps_v<T>) * 8.0)
      << "a point is outside the reported ball by " << worst / r << " r";
}

TYPED_TEST(BoundingScale, MinCircleContainsInputAtExtremeScales) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 6; ++trial) {
    const auto pts = grid_points<T, 2>(rng, 200);
    for (int k : length_exponents<T>()) {
      SCOPED_TRACE("2^" + std::to_string(k) + " trial " + std::to_string(trial));
      const auto r = locus::min_circle<T>(scaled(pts, k));
      ASSERT_EQ(r.status, Status::ok);
      expect_ball_contains<T, 2>(pts, k, r.circle.center, r.circle.radius);
    }
  }
}

TYPED_TEST(BoundingScale, MinSphereContainsInputAtExtremeScales) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 6; ++trial) {
    const auto pts = grid_points<T, 3>(rng, 200);
    for (int k : length_exponents<T>()) {
      SCOPED_TRACE("2^" + std::to_string(k) + " trial " + std::to_string(trial));
      const auto r = locus::min_sphere<T>(scaled(pts, k));
      ASSERT_EQ(r.status, Status::ok);
      expect_ball_contains<T, 3>(pts, k, r.sphere.center, r.sphere.radius);
    }
  }
}

// Huge points with a coordinate near the bottom of the range: the input is scaled down only as
// far as keeps that coordinate exact, so the ball is still found and contains every point, and
// its support is the one of the same points at scale 1 with that coordinate 0 (it decides
// nothing: the points are in general position).
TYPED_TEST(BoundingScale, MinBallWithHugeAndTinyCoordinates) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int big = locus_test::far_scale_exponents<T>()[3];
  const T tiny = std::numeric_limits<T>::denorm_min() * T(3);
  for (int trial = 0; trial < 6; ++trial) {
    auto p2 = grid_points<T, 2>(rng, 200);
    auto p3 = grid_points<T, 3>(rng, 200);
    auto q2 = scaled(p2, big);
    auto q3 = scaled(p3, big);
    q2[7].y = tiny;
    q3[7].z = tiny;
    p2[7].y = T(0);
    p3[7].z = T(0);
    const auto r2 = locus::min_circle<T>(q2);
    const auto r3 = locus::min_sphere<T>(q3);
    ASSERT_EQ(r2.status, Status::ok);
    ASSERT_EQ(r3.status, Status::ok);
    expect_ball_contains<T, 2>(scaled(q2, -big), big, r2.circle.center, r2.circle.radius);
    expect_ball_contains<T, 3>(scaled(q3, -big), big, r3.sphere.center, r3.sphere.radius);
    const auto z2 = locus::min_circle<T>(p2);
    const auto z3 = locus::min_sphere<T>(p3);
    ASSERT_EQ(r2.support_count, z2.support_count);
    ASSERT_EQ(r3.support_count, z3.support_count);
    for (int i = 0; i < r2.support_count; ++i)
      EXPECT_EQ(r2.support[std::size_t(i)], z2.support[std::size_t(i)]);
    for (int i = 0; i < r3.support_count; ++i)
      EXPECT_EQ(r3.support[std::size_t(i)], z3.support[std::size_t(i)]);
  }
}

TYPED_TEST(BoundingScale, MinCircleAndSphere) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 6; ++trial) {
    const auto p2 = grid_points<T, 2>(rng, 10 + 200 * trial);
    const auto p3 = grid_points<T, 3>(rng, 10 + 200 * trial);
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::min_circle<T>(scaled(p2, k));
          std::vector<Covariant> out{{"status", double(r.status), 0},
                                     {"support_count", double(r.support_count), 0},
                                     {"radius", double(r.circle.radius), 1}};
          for (int i = 0; i < r.support_count; ++i)
            out.push_back({"support", double(r.support[std::size_t(i)]), 0});
          add(out, "center", r.circle.center, 1);
          return out;
        },
        length_exponents<T>());
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::min_sphere<T>(scaled(p3, k));
          std::vector<Covariant> out{{"status", double(r.status), 0},
                                     {"support_count", double(r.support_count), 0},
                                     {"radius", double(r.sphere.radius), 1}};
          for (int i = 0; i < r.support_count; ++i)
            out.push_back({"support", double(r.support[std::size_t(i)]), 0});
          add(out, "center", r.sphere.center, 1);
          return out;
        },
        length_exponents<T>());
  }
}

TYPED_TEST(BoundingScale, SimplexBalls) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  auto circle2 = [](const std::optional<locus::Circle2<T>>& c) {
    std::vector<Covariant> out{{"has_value", double(c.has_value()), 0}};
    if (c) {
      add(out, "center", c->center, 1);
      out.push_back({"radius", double(c->radius), 1});
    }
    return out;
  };
  auto circle3 = [](const std::optional<locus::Circle3<T>>& c) {
    std::vector<Covariant> out{{"has_value", double(c.has_value()), 0}};
    if (c) {
      add(out, "center", c->center, 1);
      add(out, "normal", c->normal, 0);
      out.push_back({"radius", double(c->radius), 1});
    }
    return out;
  };
  auto sphere = [](const std::optional<locus::Sphere3<T>>& s) {
    std::vector<Covariant> out{{"has_value", double(s.has_value()), 0}};
    if (s) {
      add(out, "center", s->center, 1);
      out.push_back({"radius", double(s->radius), 1});
    }
    return out;
  };
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const auto a = grid_points<T, 2>(rng, 3);
    const auto b = grid_points<T, 3>(rng, 4);
    auto t2 = [&](int k) {
      return locus::Triangle<T, 2>{scaled(a[0], k), scaled(a[1], k), scaled(a[2], k)};
    };
    auto t3 = [&](int k) {
      return locus::Triangle<T, 3>{scaled(b[0], k), scaled(b[1], k), scaled(b[2], k)};
    };
    auto tet = [&](int k) {
      return locus::Tetrahedron3<T>{
          {scaled(b[0], k), scaled(b[1], k), scaled(b[2], k), scaled(b[3], k)}};
    };
    const auto ks = length_exponents<T>();
    locus_test::expect_scale_covariant(
        [&](int k) { return circle2(locus::circumscribed_circle(t2(k))); }, ks);
    locus_test::expect_scale_covariant(
        [&](int k) { return circle2(locus::inscribed_circle(t2(k))); }, ks);
    locus_test::expect_scale_covariant(
        [&](int k) { return circle3(locus::circumscribed_circle(t3(k))); }, ks);
    locus_test::expect_scale_covariant(
        [&](int k) { return circle3(locus::inscribed_circle(t3(k))); }, ks);
    locus_test::expect_scale_covariant(
        [&](int k) { return sphere(locus::circumscribed_sphere(tet(k))); }, ks);
    locus_test::expect_scale_covariant(
        [&](int k) { return sphere(locus::inscribed_sphere(tet(k))); }, ks);
  }
}

TYPED_TEST(BoundingScale, MinRect) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 6; ++trial) {
    const auto pts = grid_points<T, 2>(rng, 5 + 100 * trial);
    for (auto crit : {locus::RectCriterion::area, locus::RectCriterion::perimeter}) {
      locus_test::expect_scale_covariant(
          [&](int k) {
            const auto r = locus::min_rect<T>(scaled(pts, k), crit);
            std::vector<Covariant> out{{"status", double(r.status), 0},
                                       {"edge0", double(r.edge[0]), 0},
                                       {"edge1", double(r.edge[1]), 0},
                                       {"area", double(r.area), 2},
                                       {"perimeter", double(r.perimeter), 1},
                                       {"extent0", double(r.rectangle.extent[0]), 1},
                                       {"extent1", double(r.rectangle.extent[1]), 1}};
            add(out, "center", r.rectangle.center, 1);
            add(out, "axis0", r.rectangle.axis[0], 0);
            add(out, "axis1", r.rectangle.axis[1], 0);
            return out;
          },
          area_exponents<T>());
    }
  }
}

TYPED_TEST(BoundingScale, MinBox) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 4; ++trial) {
    const auto pts = grid_points<T, 3>(rng, 8 + 60 * trial);
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto r = locus::min_box<T>(scaled(pts, k));
          std::vector<Covariant> out{{"status", double(r.status), 0},
                                     {"volume", double(r.volume), 3},
                                     {"candidates", double(r.candidates), 0},
                                     {"arcs", double(r.arcs), 0},
                                     {"certified", double(r.certified), 0}};
          add(out, "center", r.box.center, 1);
          add(out, "extent", r.box.extent, 1);
          for (int i = 0; i < 3; ++i) add(out, "axis" + std::to_string(i), r.box.axis[i], 0);
          return out;
        },
        volume_exponents<T>());
  }
}

}  // namespace
