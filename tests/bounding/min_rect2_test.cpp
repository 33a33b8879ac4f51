// SPDX-License-Identifier: BSL-1.0
// Tests of min_rect (row cg.minbox, 2D; figure 13.79). Oracle: brute force over the directions
// of ALL pairs of input points (a superset of the hull edges, one of which is flush with an
// optimal rectangle), each rectangle measured by projecting every point.

#include <locus/bounding/min_rect2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "support/typed.hpp"

namespace {

using locus::RectCriterion;
using locus::Status;
using locus::Vec2;
using locus_test::Rng;

template <class T>
class MinRect : public ::testing::Test {};
TYPED_TEST_SUITE(MinRect, locus_test::RealTypes);

template <class T>
double brute_force(const std::vector<Vec2<T>>& pts, RectCriterion c) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      const Vec2<double> d = vec_cast<double>(pts[j]) - vec_cast<double>(pts[i]);
      if (locus::sqr_length(d) == 0.0) continue;
      const Vec2<double> u = locus::normalize(d), v = locus::perp(u);
      double s0 = 1e300, s1 = -1e300, t0 = 1e300, t1 = -1e300;
      for (const auto& p : pts) {
        const Vec2<double> q = vec_cast<double>(p);
        s0 = std::min(s0, locus::dot(u, q));
        s1 = std::max(s1, locus::dot(u, q));
        t0 = std::min(t0, locus::dot(v, q));
        t1 = std::max(t1, locus::dot(v, q));
      }
      best = std::min(
          best, c == RectCriterion::area ? (s1 - s0) * (t1 - t0) : 2.0 * ((s1 - s0) + (t1 - t0)));
    }
  return best;
}

// Every point inside the rectangle (to the rounding of its construction), and consistency.
template <class T>
void check_contains(const std::vector<Vec2<T>>& pts, const locus::MinRectResult<T>& r,
                    double scale) {
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_TRUE(locus::is_orthonormal(r.rectangle));
  EXPECT_GT(locus::perp_dot(r.rectangle.axis[0], r.rectangle.axis[1]), T(0));
  const double t = 32.0 * static_cast<double>(locus::eps_v<T>) * scale;
  for (const auto& p : pts) {
    const Vec2<double> d = vec_cast<double>(p) - vec_cast<double>(r.rectangle.center);
    for (int k = 0; k < 2; ++k)
      EXPECT_LE(std::abs(locus::dot(d, vec_cast<double>(r.rectangle.axis[k]))),
                static_cast<double>(r.rectangle.extent[k]) + t);
  }
  // The flush edge (figure 13.79: a minimal rectangle has a side on a hull edge): both its end
  // points are on the side t = -extent[1].
  for (std::uint32_t e : r.edge) {
    const Vec2<double> d = vec_cast<double>(pts[e]) - vec_cast<double>(r.rectangle.center);
    EXPECT_NEAR(locus::dot(d, vec_cast<double>(r.rectangle.axis[1])),
                -static_cast<double>(r.rectangle.extent[1]), t);
  }
}

TYPED_TEST(MinRect, BadAndDegenerateInput) {
  using T = TypeParam;
  EXPECT_EQ(locus::min_rect<T>(std::span<const Vec2<T>>{}).status, Status::empty_input);
  std::vector<Vec2<T>> bad{{T(0), T(0)}, {std::numeric_limits<T>::quiet_NaN(), T(1)}};
  EXPECT_EQ(locus::min_rect<T>(bad).status, Status::non_finite_input);
  bad[1] = {T(1), std::numeric_limits<T>::infinity()};
  EXPECT_EQ(locus::min_rect<T>(bad).status, Status::non_finite_input);
  const std::vector<Vec2<T>> same(9, Vec2<T>{T(2), T(-3)});
  const auto r0 = locus::min_rect<T>(same);
  ASSERT_EQ(r0.status, Status::ok);
  EXPECT_EQ(r0.area, T(0));
  EXPECT_EQ(r0.rectangle.center, same[0]);
  std::vector<Vec2<T>> line;
  for (int i = 0; i < 20; ++i) line.push_back({T(1 + 3 * (i % 7)), T(2 + 4 * (i % 7))});
  const auto r1 = locus::min_rect<T>(line);
  ASSERT_EQ(r1.status, Status::ok);
  EXPECT_EQ(r1.area, T(0));
  EXPECT_NEAR(r1.rectangle.extent[0], T(15), locus_test::tol<T>(8, T(15)));  // |(18, 24)| / 2
  check_contains(line, r1, 40.0);
}

TYPED_TEST(MinRect, Figure13_79FlushEdgeAndExactShapes) {
  using T = TypeParam;
  // A square rotated by atan(3/4) with 20 collinear points per side (exact corners (0,0), (4,3),
  // (1,7), (-3,4) scaled by 5): the minimum rectangle is the square itself, area 625, even
  // though the axis-aligned box (figure 13.79's kind of non-flush rectangle) is larger.
  std::vector<Vec2<T>> sq;
  const Vec2<T> c[4] = {{T(0), T(0)}, {T(20), T(15)}, {T(5), T(35)}, {T(-15), T(20)}};
  for (int s = 0; s < 4; ++s)
    for (int k = 0; k < 20; ++k) {
      const T f = T(k) / T(20);
      sq.push_back(c[s] + f * (c[(s + 1) % 4] - c[s]));
    }
  const auto r = locus::min_rect<T>(sq);
  EXPECT_NEAR(r.area, T(625), locus_test::tol<T>(64, T(625)));
  check_contains(sq, r, 40.0);
  // Regular 12-gon: brute force agrees.
  std::vector<Vec2<T>> poly;
  for (int k = 0; k < 12; ++k)
    poly.push_back({static_cast<T>(3 * std::cos(k * 0.5235987755982988)),
                    static_cast<T>(3 * std::sin(k * 0.5235987755982988))});
  const auto rp = locus::min_rect<T>(poly);
  EXPECT_NEAR(static_cast<double>(rp.area), brute_force(poly, RectCriterion::area),
              64 * static_cast<double>(locus::eps_v<T>) * 36);
  check_contains(poly, rp, 6.0);
}

TYPED_TEST(MinRect, RandomVsBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 80; ++trial) {
    const int n = rng.uniform_int(3, 40);
    std::vector<Vec2<T>> pts;
    for (int i = 0; i < n; ++i) pts.push_back(rng.vec<T, 2>(T(-10), T(10)));
    if (trial % 4 == 1)
      for (auto& p : pts) p = {std::round(p.x / T(4)), std::round(p.y / T(4))};
    if (trial % 4 == 2)  // a thin rotated cloud
      for (auto& p : pts) p = {p.x + T(0.5) * p.y, T(0.01) * p.y + T(0.3) * p.x};
    for (RectCriterion c : {RectCriterion::area, RectCriterion::perimeter}) {
      const auto r = locus::min_rect<T>(pts, c);
      if (r.status == Status::ok && r.area == T(0) && c == RectCriterion::area) continue;
      const double bf = brute_force(pts, c);
      const double got =
          c == RectCriterion::area ? static_cast<double>(r.area) : static_cast<double>(r.perimeter);
      // Measures are rounded constructions: relative error a few eps of the squared scale.
      EXPECT_NEAR(got, bf, 64 * static_cast<double>(locus::eps_v<T>) * 400) << trial;
      check_contains(pts, r, 20.0);
    }
  }
}

TYPED_TEST(MinRect, TransformInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec2<T>> pts;
  for (int i = 0; i < 2000; ++i) {
    const Vec2<T> p = rng.vec<T, 2>(T(-100), T(100));
    pts.push_back({std::round(p.x), std::round(p.y * T(0.3))});
  }
  const auto r = locus::min_rect<T>(pts);
  auto q = pts;
  std::reverse(q.begin(), q.end());
  for (auto& p : q) p = {-T(2) * p.y + T(512), T(2) * p.x - T(64)};  // exact rotation, scale 2
  const auto rq = locus::min_rect<T>(q);
  EXPECT_NEAR(rq.area, T(4) * r.area, locus_test::tol<T>(64, T(4) * r.area));
  check_contains(pts, r, 200.0);
  check_contains(q, rq, 800.0);
}

}  // namespace
