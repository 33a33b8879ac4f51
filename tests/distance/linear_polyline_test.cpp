// SPDX-License-Identifier: BSL-1.0
// Tests for distance/{line,ray,segment}_polyline.hpp (row dist2.linear-polyline; book figure
// 6.22).
#include <locus/distance/line_polyline.hpp>
#include <locus/distance/line_segment.hpp>
#include <locus/distance/point_line.hpp>
#include <locus/distance/point_ray.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/distance/ray_polyline.hpp>
#include <locus/distance/ray_segment.hpp>
#include <locus/distance/segment_polyline.hpp>
#include <locus/distance/segment_segment.hpp>

#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

using namespace locus;
using locus_test::Rng;
namespace dist = locus_test::dist;

template <class T>
class LinearPolylineTest : public ::testing::Test {};
TYPED_TEST_SUITE(LinearPolylineTest, locus_test::RealTypes);

namespace {

template <class T, int N>
Polyline<T, N> random_polyline(Rng& rng, int n, T S) {
  Polyline<T, N> p;
  p.closed = rng.uniform_int(0, 1) == 1;
  Vec<T, N> x = rng.vec<T, N>(-S, S);
  for (int i = 0; i < n; ++i) {
    p.vertices.push_back(x);
    x += rng.vec<T, N>(-S / 4, S / 4);
    if (rng.uniform_int(0, 15) == 0) x = p.vertices.back();  // a zero-length edge
  }
  return p;
}

template <class L, class T, int N>
L random_linear(Rng& rng, T S) {
  const Vec<T, N> o = rng.vec<T, N>(-S, S);
  Vec<T, N> d = rng.vec<T, N>(-S / 2, S / 2);
  if (rng.uniform_int(0, 19) == 0) d = Vec<T, N>{};  // degenerate: a point
  if constexpr (std::is_same_v<L, Segment<T, N>>)
    return {o, o + d};
  else
    return {o, d};
}

// Independent oracle per edge: |l - edge(s)|^2 = squared point-linear distance of edge(s) is
// convex in s; golden-section search over s in [0, 1] (the point-linear queries are the tested
// point_line/point_ray/point_segment headers).
template <class T, int N, class L>
double oracle(const L& l, const Polyline<T, N>& p) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t m = segment_count(p);
  if (m == 0) return double(distance(p.vertices[0], l).distance);
  for (std::size_t i = 0; i < m; ++i) {
    const Segment<T, N> e = edge(std::span<const Vec<T, N>>(p.vertices), i);
    auto f = [&](double s) { return double(distance(point_at(e, T(s)), l).sqr_distance); };
    const double g = 0.6180339887498949;
    double a = 0, b = 1, x1 = b - g, x2 = g, f1 = f(x1), f2 = f(x2);
    for (int it = 0; it < 80; ++it) {
      if (f1 <= f2) {
        b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = f(x1);
      } else {
        a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = f(x2);
      }
    }
    best = std::min({best, f1, f2, f(0), f(1)});
  }
  return std::sqrt(best);
}

template <class T, int N, class L>
void check_kind() {
  const T S = 10;
  dist::Options<T> opt;
  opt.cases = 100;
  opt.check_agreement = false;  // non-convex: the per-edge oracle below replaces it
  dist::check_pairs<T, N, L, Polyline<T, N>>(
      [&](Rng& rng) {
        return std::pair{random_linear<L, T, N>(rng, S),
                         random_polyline<T, N>(rng, rng.uniform_int(1, 12), S)};
      },
      opt);
  Rng rng(locus_test::test_seed() + 91);
  SCOPED_TRACE(rng.trace());
  const double tl = std::is_same_v<T, float> ? 2e-4 : 1e-9;
  for (int n = 0; n < 300; ++n) {
    SCOPED_TRACE(n);
    const L l = random_linear<L, T, N>(rng, S);
    const auto p = random_polyline<T, N>(rng, rng.uniform_int(1, 60), S);
    const auto r = distance(l, p);
    EXPECT_NEAR(double(r.distance), (oracle<T, N>(l, p)), tl * double(S));
    // The rejection never changes the answer: the plain minimum over the edges.
    const std::size_t m = segment_count(p);
    if (m > 0) {
      T best = std::numeric_limits<T>::infinity();
      for (std::size_t i = 0; i < m; ++i)
        best = std::min(best,
                        distance(l, edge(std::span<const Vec<T, N>>(p.vertices), i)).sqr_distance);
      EXPECT_EQ(r.sqr_distance, best);
    }
    EXPECT_TRUE(locus_test::vec_near(point_at(p, r.param_b), r.closest[1], T(tl) * S));
  }
}

}  // namespace

TYPED_TEST(LinearPolylineTest, OraclesAndRejection2D) {
  using T = TypeParam;
  check_kind<T, 2, Line<T, 2>>();
  check_kind<T, 2, Ray<T, 2>>();
  check_kind<T, 2, Segment<T, 2>>();
}

TYPED_TEST(LinearPolylineTest, OraclesAndRejection3D) {
  using T = TypeParam;
  check_kind<T, 3, Line<T, 3>>();
  check_kind<T, 3, Segment<T, 3>>();
}

// Figure 6.22: a segment near a long zig-zag; most edges are rejected by the strip and the caps.
TYPED_TEST(LinearPolylineTest, FigureCaseAndPolygon) {
  using T = TypeParam;
  using V = Vec2<T>;
  const T tl = std::is_same_v<T, float> ? T(1e-5) : T(1e-13);
  Polyline2<T> zig;
  for (int i = 0; i <= 40; ++i) zig.vertices.push_back(V{T(i), (i % 2) ? T(3) : T(5)});
  const auto r = distance(Segment2<T>{V{10.5, 0}, V{12.5, 1}}, zig);
  // Nearest pair (by hand): the end (12.5, 1) and the vertex (13, 3) (the vertex projects beyond
  // the segment's end; (11, 3) projects inside but is 5.5 / sqrt(5) ~ 2.46 away).
  EXPECT_NEAR(r.distance, std::sqrt(T(4.25)), tl * 10);
  EXPECT_NEAR(r.param_b, T(13), tl * 100);
  EXPECT_NEAR(r.param_a, T(1), tl);
  // A line crossing the chain: distance 0.
  EXPECT_EQ(distance(Line2<T>{V{0, 4}, V{1, 0}}, zig).distance, T(0));
  // A polygon boundary (closed): a ray from inside the square reaches its boundary.
  const Polyline2<T> square{{V{0, 0}, V{4, 0}, V{4, 4}, V{0, 4}}, true};
  EXPECT_EQ(distance(Ray2<T>{V{2, 2}, V{1, 0}}, square).distance, T(0));
  EXPECT_NEAR(distance(Segment2<T>{V{1, 1}, V{2, 2}}, square).distance, T(1), tl);
  EXPECT_NEAR(distance(Ray2<T>{V{6, 2}, V{1, 1}}, square).distance, T(2), tl);
  // Parallel to an edge, overlapping: unique = false.
  EXPECT_FALSE(distance(Segment2<T>{V{1, -1}, V{3, -1}}, square).unique);
}

TYPED_TEST(LinearPolylineTest, DegenerateAndNonFinite) {
  using T = TypeParam;
  using V = Vec2<T>;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T tl = std::is_same_v<T, float> ? T(1e-5) : T(1e-13);
  const Polyline2<T> empty{};
  EXPECT_TRUE(dist::is_nan_result(distance(Line2<T>{V{0, 0}, V{1, 0}}, empty)));
  const Polyline2<T> one{{V{3, 4}}, false};
  const auto r1 = distance(Segment2<T>{V{0, 0}, V{6, 0}}, one);
  EXPECT_NEAR(r1.distance, T(4), tl);
  EXPECT_EQ(r1.param_b, T(0));
  const Polyline2<T> two{{V{0, 2}, V{5, 2}}, false};
  EXPECT_NEAR(distance(Segment2<T>{V{1, 0}, V{1, 0}}, two).distance, T(2), tl);  // zero length
  EXPECT_NEAR(distance(Line2<T>{V{7, 0}, V{0, 0}}, two).distance, std::sqrt(T(8)), tl);  // zero dir
  EXPECT_TRUE(dist::is_nan_result(distance(Ray2<T>{V{nan, 0}, V{1, 0}}, two)));
  const Polyline2<T> bad{{V{0, 2}, V{nan, 2}}, false};
  EXPECT_TRUE(dist::is_nan_result(distance(Segment2<T>{V{0, 0}, V{1, 0}}, bad)));
  // Swap.
  const Segment2<T> s{V{-1, 5}, V{2, 7}};
  const auto a = distance(s, two), b = distance(two, s);
  EXPECT_EQ(a.sqr_distance, b.sqr_distance);
  EXPECT_EQ(a.param_a, b.param_b);
  EXPECT_EQ(a.closest[1], b.closest[0]);
}
