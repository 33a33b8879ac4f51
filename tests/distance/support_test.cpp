// SPDX-License-Identifier: BSL-1.0
// Support mappings (distance/support.hpp), checked directly against brute force: for polytopes
// the support point is a vertex attaining the maximum of dot(d, v) over all vertices; for balls
// no dense boundary sample lies farther along d; d = 0 stays finite.
#include <locus/distance/support.hpp>

#include "support/typed.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using locus::dot;
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
