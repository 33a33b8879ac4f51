// SPDX-License-Identifier: BSL-1.0
// Support mappings (distance/support.hpp), checked directly against brute force: for polytopes
// the support point is a vertex attaining the maximum of dot(d, v) over all vertices; for balls
// no dense boundary sample lies farther along d; d = 0 stays finite.
#include <locus/distance/support.hpp>

#include "support/typed.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using locus::dot;
using locus::Vec2f;
using locus::Vec3d;

TEST(Support, PolytopesAttainTheMaximumOverTheirVertices) {
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<Vec3d> pts(12);
    for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
    const Vec3d d{u(rng), u(rng), u(rng)};
    double best = -1e300;
    for (const auto& p : pts) best = std::max(best, dot(d, p));
    const Vec3d s = locus::support(locus::ConvexPoints<double, 3>{pts}, d);
    EXPECT_DOUBLE_EQ(dot(d, s), best);

    const locus::AlignedBox<double, 3> box{{-0.5, -1, -2}, {0.5, 1, 2}};
    double box_best = -1e300;
    for (int c = 0; c < 8; ++c) {
      const Vec3d v{c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y,
                    c & 4 ? box.max.z : box.min.z};
      box_best = std::max(box_best, dot(d, v));
    }
    EXPECT_NEAR(dot(d, locus::support(box, d)), box_best, 1e-15);
  }
}

TEST(Support, ConvexPointsFlagsEveryNonFinitePointAndSurvivesOverflowingSums) {
  // A NaN or infinite coordinate anywhere (also one that would lose the comparison, -inf) makes
  // the support all NaN; huge finite coordinates whose dot products overflow when summed do not.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Vec3d d{1, 0.5, -0.25};
  for (int n = 1; n <= 9; ++n)
    for (int bad = 0; bad < n; ++bad)
      for (double v : {nan, inf, -inf}) {
        std::vector<Vec3d> pts;
        for (int i = 0; i < n; ++i) pts.push_back({double(i), -double(i), 0.5});
        pts[static_cast<std::size_t>(bad)].y = v;
        const Vec3d s = locus::support(locus::ConvexPoints<double, 3>{pts}, d);
        EXPECT_TRUE(std::isnan(s.x) && std::isnan(s.y) && std::isnan(s.z))
            << n << " " << bad << " " << v;
      }
  std::vector<Vec3d> huge;
  for (int i = 0; i < 8; ++i) huge.push_back({1e308 * (0.5 + 0.05 * i), 0, 0});
  const Vec3d h = locus::support(locus::ConvexPoints<double, 3>{huge}, Vec3d{1, 0, 0});
  EXPECT_EQ(h.x, huge.back().x);
  // Ties: the lowest index wins.
  const std::vector<Vec3d> tie{{0, 0, 0}, {1, 5, 0}, {1, -5, 0}, {1, 0, 0}};
  EXPECT_EQ(locus::support(locus::ConvexPoints<double, 3>{tie}, Vec3d{1, 0, 0}).y, 5.0);
  const std::vector<Vec2f> tie2{{0, 0}, {2, 1}, {2, 3}};
  EXPECT_EQ(locus::support(locus::ConvexPoints<float, 2>{tie2}, Vec2f{1, 0}).y, 1.0f);
}

TEST(Support, SphereIsNeverBeatenByABoundarySample) {
  const locus::Sphere<double, 3> s{{1, 2, 3}, 0.75};
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3d d{g(rng), g(rng), g(rng)};
    const Vec3d p = locus::support(s, d);
    EXPECT_NEAR(locus::length(p - s.center), s.radius, 1e-14);
    for (int k = 0; k < 50; ++k) {
      Vec3d q{g(rng), g(rng), g(rng)};
      q = s.center + (s.radius / locus::length(q)) * q;
      EXPECT_LE(dot(d, q), dot(d, p) + 1e-14 * locus::length(d));
    }
  }
  const Vec3d zero = locus::support(s, Vec3d{0, 0, 0});
  EXPECT_TRUE(std::isfinite(zero.x) && std::isfinite(zero.y) && std::isfinite(zero.z));
}

}  // namespace
