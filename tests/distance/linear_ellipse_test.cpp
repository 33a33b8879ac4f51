// SPDX-License-Identifier: BSL-1.0
// Tests for distance/line_ellipse.hpp (row dist2.linear-curve, ellipse part; book figure 6.23).
//
// Oracles: the generic harness (random parameter search) and an independent long-double brute
// force: dense sampling of the ellipse's angle with the exact clamped point-linear distance
// from each sample, then golden-section refinement of every discrete local minimum.
#include <locus/distance/line_ellipse.hpp>

#include "distance/harness.hpp"
#include "distance/linear_oracle.hpp"
#include "distance/side_curved.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <utility>

using namespace locus;
using locus_test::Rng;
namespace dist = locus_test::dist;

template <class T>
class LinearEllipseTest : public ::testing::Test {};
TYPED_TEST_SUITE(LinearEllipseTest, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kCaseScale = 4;
#else
constexpr int kCaseScale = 1;
#endif

using locus_test::linear_oracle::LD;
using locus_test::linear_oracle::min_over_angle;
using locus_test::linear_oracle::near_ld;
using locus_test::linear_oracle::sqr_to_linear;
using locus_test::linear_oracle::to_ld;
using V = Vec2<LD>;

using LinLD = locus_test::linear_oracle::LinLD<2>;

template <class Lin, class T>
LD brute(const Lin& lin, const Ellipse2<T>& e) {
  const LinLD ll = to_ld(lin);
  const V c = vec_cast<LD>(e.center), a0 = vec_cast<LD>(e.axis[0]), a1 = vec_cast<LD>(e.axis[1]);
  const LD e0 = e.extent[0], e1 = e.extent[1];
  return std::sqrt(min_over_angle([&](LD a) {
    return sqr_to_linear(c + (e0 * std::cos(a)) * a0 + (e1 * std::sin(a)) * a1, ll);
  }));
}

template <class T>
Ellipse2<T> random_ellipse(Rng& rng, T s) {
  const T phi = rng.uniform<T>(T(0), T(6.283185307179586));
  const Vec2<T> a0{std::cos(phi), std::sin(phi)};
  T e0 = rng.uniform<T>(T(0.2), T(6)), e1 = rng.uniform<T>(T(0.2), T(6));
  if (rng.uniform_int(0, 15) == 0) e1 = T(0);
  if (rng.uniform_int(0, 15) == 0) e1 = e0;  // a circle
  return {rng.vec<T, 2>(-s, s), {a0, Vec2<T>{-a0.y, a0.x}}, {e0, e1}};
}

template <class T>
T dist_tol(T s) {
  return (std::is_same_v<T, float> ? T(4e-6) : T(1e-12)) * s;
}

}  // namespace

TYPED_TEST(LinearEllipseTest, Harness) {
  using T = TypeParam;
  const T S = 10;
  dist::Options<T> opt;
  opt.cases = 100 / kCaseScale;
  opt.check_agreement = false;  // the ellipse is not convex as a curve: see the brute force
  dist::check_pairs<T, 2, Line<T, 2>, Ellipse2<T>>(
      [&](Rng& rng) {
        return std::pair{Line<T, 2>{rng.vec<T, 2>(-S, S), rng.unit<T, 2>() * T(2)},
                         random_ellipse(rng, S)};
      },
      opt);
  dist::check_pairs<T, 2, Ray<T, 2>, Ellipse2<T>>(
      [&](Rng& rng) {
        return std::pair{Ray<T, 2>{rng.vec<T, 2>(-S, S), rng.unit<T, 2>() * T(0.7)},
                         random_ellipse(rng, S)};
      },
      opt);
  dist::check_pairs<T, 2, Segment<T, 2>, Ellipse2<T>>(
      [&](Rng& rng) {
        return std::pair{Segment<T, 2>{rng.vec<T, 2>(-S, S), rng.vec<T, 2>(-S, S)},
                         random_ellipse(rng, S)};
      },
      opt);
}

TYPED_TEST(LinearEllipseTest, AgainstBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const T S = 8;
  for (int i = 0; i < 80 / kCaseScale; ++i) {
    const Ellipse2<T> e = random_ellipse(rng, S);
    Vec2<T> o = rng.vec<T, 2>(-S, S);
    const Vec2<T> d = rng.unit<T, 2>() * rng.uniform<T>(T(0.3), T(5));
    if (i % 3 == 0) o = e.center + rng.uniform<T>(T(-0.5), T(0.5)) * e.extent[0] * e.axis[0];
    SCOPED_TRACE("case " + std::to_string(i));
    const Line<T, 2> line{o, d};
    const Ray<T, 2> ray{o, d};
    const Segment<T, 2> seg{o, o + d};
    const auto rl = distance(line, e), rr = distance(ray, e), rs = distance(seg, e);
    EXPECT_TRUE(near_ld(LD(rl.distance), brute(line, e), LD(dist_tol<T>(S))));
    EXPECT_TRUE(near_ld(LD(rr.distance), brute(ray, e), LD(dist_tol<T>(S))));
    EXPECT_TRUE(near_ld(LD(rs.distance), brute(seg, e), LD(dist_tol<T>(S))));
    const auto sw = distance(e, ray);
    EXPECT_EQ(sw.distance, rr.distance);
    EXPECT_EQ(sw.closest[0], rr.closest[1]);
    EXPECT_EQ(sw.param_b, rr.param_a);
  }
}

// Figure 6.23: a line missing the ellipse is closest at the point whose tangent is parallel;
// a line crossing it is at distance 0.
TYPED_TEST(LinearEllipseTest, Figure6_23) {
  using T = TypeParam;
  const Ellipse2<T> e{{T(1), T(-1)}, {{1, 0}, {0, 1}}, {T(4), T(2)}};
  const T tol = T(64) * eps_v<T> * T(10);
  // Horizontal line above: the top vertex.
  const auto above = distance(Line<T, 2>{{T(-7), T(3)}, {T(3), 0}}, e);
  EXPECT_NEAR(above.distance, T(2), tol);
  EXPECT_TRUE(locus_test::vec_near(above.closest[1], Vec2<T>{T(1), T(1)}, tol));
  EXPECT_TRUE(locus_test::vec_near(above.closest[0], Vec2<T>{T(1), T(3)}, tol));
  // Slanted line y = x + c missing the ellipse: tangent point where the slope is 1:
  // (x, y) = (-a^2, b^2) / sqrt(a^2 + b^2) from the center, distance from the line.
  const T c = T(8);
  const auto sl = distance(Line<T, 2>{{T(0), c}, {1, 1}}, e);
  const T q = std::sqrt(T(20));
  const Vec2<T> tp{T(1) - T(16) / q, T(-1) + T(4) / q};
  EXPECT_TRUE(locus_test::vec_near(sl.closest[1], tp, T(1e3) * tol));
  EXPECT_NEAR(sl.distance, std::abs(tp.y - tp.x - c) / std::sqrt(T(2)), T(1e3) * tol);
  // Crossing line: distance 0, the closest point lies on both.
  const auto cr = distance(Line<T, 2>{{T(-9), T(-1.5)}, {1, T(0.1)}}, e);
  EXPECT_NEAR(cr.distance, T(0), T(1e3) * tol);
  // A segment on the major axis inside the ellipse: distance to the curve, not 0, attained at
  // the ends (local x = +-1), where the closest point is off the vertex (Eberly's interior
  // major-axis case): distance e1 sqrt(1 - x^2 / (e0^2 - e1^2)) = sqrt(11 / 3).
  const auto in = distance(Segment<T, 2>{{T(0), T(-1)}, {T(2), T(-1)}}, e);
  EXPECT_NEAR(in.distance, std::sqrt(T(11) / T(3)), tol);
  EXPECT_TRUE(in.param_a == T(0) || in.param_a == T(1));
  // Tangent line: distance 0 at the vertex.
  const auto tg = distance(Ray<T, 2>{{T(5), T(-6)}, {0, 1}}, e);
  EXPECT_NEAR(tg.distance, T(0), tol);
  EXPECT_TRUE(locus_test::vec_near(tg.closest[1], Vec2<T>{T(5), T(-1)}, T(1e3) * tol));
}

TYPED_TEST(LinearEllipseTest, Degenerate) {
  using T = TypeParam;
  const T tol = T(64) * eps_v<T> * T(10);
  const Ellipse2<T> e{{0, 0}, {{1, 0}, {0, 1}}, {T(3), T(1)}};
  // Zero-length segment: the point query.
  const auto pt = distance(Segment<T, 2>{{T(0), T(5)}, {T(0), T(5)}}, e);
  EXPECT_NEAR(pt.distance, T(4), tol);
  EXPECT_EQ(pt.param_a, T(0));
  // Collapsed ellipse (a segment of length 6), line parallel above it.
  const Ellipse2<T> flat{{0, 0}, {{1, 0}, {0, 1}}, {T(3), T(0)}};
  EXPECT_NEAR(distance(Line<T, 2>{{T(-1), T(2)}, {1, 0}}, flat).distance, T(2), tol);
  EXPECT_NEAR(distance(Ray<T, 2>{{T(5), T(1)}, {1, 0}}, flat).distance, std::sqrt(T(5)), tol);
  // Collapsed to a point.
  const Ellipse2<T> point{{T(1), T(1)}, {{1, 0}, {0, 1}}, {T(0), T(0)}};
  EXPECT_NEAR(distance(Line<T, 2>{{T(-4), T(4)}, {1, 0}}, point).distance, T(3), tol);
  // A ray ending at the centre of a circle pointing away... from inside: closest is the far end
  // of a segment; a zero-length segment at the centre of a circle is equidistant (not unique).
  const Ellipse2<T> circle{{0, 0}, {{1, 0}, {0, 1}}, {T(2), T(2)}};
  const auto cc = distance(Segment<T, 2>{{0, 0}, {0, 0}}, circle);
  EXPECT_NEAR(cc.distance, T(2), tol);
  EXPECT_FALSE(cc.unique);
}

TYPED_TEST(LinearEllipseTest, NonFinite) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Ellipse2<T> e{{0, 0}, {{1, 0}, {0, 1}}, {T(3), T(1)}};
  EXPECT_TRUE(dist::is_nan_result(distance(Line<T, 2>{{nan, 0}, {1, 0}}, e)));
  EXPECT_TRUE(dist::is_nan_result(distance(Ray<T, 2>{{0, 0}, {inf, 0}}, e)));
  EXPECT_TRUE(dist::is_nan_result(distance(Segment<T, 2>{{0, 0}, {0, nan}}, e)));
  EXPECT_TRUE(dist::is_nan_result(
      distance(Line<T, 2>{{0, 5}, {1, 0}}, Ellipse2<T>{{0, 0}, {{1, 0}, {0, 1}}, {nan, T(1)}})));
  EXPECT_TRUE(dist::is_nan_result(
      distance(Line<T, 2>{{0, 5}, {1, 0}}, Ellipse2<T>{{0, 0}, {{1, 0}, {0, 1}}, {T(-1), T(1)}})));
  EXPECT_TRUE(dist::is_nan_result(distance(e, Segment<T, 2>{{inf, 0}, {0, 0}})));
}
