// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/polyline.hpp (row prim2.polyline; book figures 5.8, 5.11).
#include <locus/primitives/polyline.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;

template <class T>
class PolylineTest : public ::testing::Test {};
TYPED_TEST_SUITE(PolylineTest, locus_test::RealTypes);

// Figure 5.8: a typical open polyline; its length is the sum of the segment lengths, the
// vertex parameter hits the vertices exactly, and closing it adds the last segment.
TYPED_TEST(PolylineTest, Fig5_8_LengthAndParametrisations) {
  using T = TypeParam;
  Polyline2<T> p{{{T(0), T(0)}, {T(3), T(4)}, {T(3), T(0)}, {T(6), T(4)}}, false};
  EXPECT_EQ(segment_count(p), 3u);
  EXPECT_EQ(length(p), T(5 + 4 + 5));
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(point_at(p, static_cast<T>(i)), p.vertices[i]);
  EXPECT_EQ(point_at(p, T(0.5)), (Vec2<T>{T(1.5), T(2)}));
  EXPECT_EQ(point_at(p, T(-1)), p.vertices[0]);  // clamped
  EXPECT_EQ(point_at(p, T(9)), p.vertices[3]);
  EXPECT_TRUE(
      locus_test::vec_near(point_at_arc_length(p, T(7)), Vec2<T>{T(3), T(2)}, tol<T>(8, T(8))));
  EXPECT_EQ(point_at_arc_length(p, T(100)), p.vertices[3]);
  p.closed = true;
  EXPECT_EQ(segment_count(p), 4u);
  EXPECT_EQ(length(p), T(14) + std::sqrt(T(52)));
  EXPECT_EQ(point_at(p, T(4)), p.vertices[0]);
  EXPECT_EQ(edge(p, 3).p1, p.vertices[0]);
}

// Oracle: the O(log n) table-driven arc-length evaluation agrees with the O(n) walk, and both
// land at the right distance along the chain (sum of lengths up to the point).
TYPED_TEST(PolylineTest, ArcLengthTableAgreesWithWalk) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 300; ++it) {
    Polyline3<T> p;
    p.closed = it % 2 == 0;
    const int n = rng.uniform_int(1, 12);
    for (int i = 0; i < n; ++i) {
      p.vertices.push_back(rng.vec<T, 3>(-5, 5));
      if (i > 0 && rng.uniform_int(0, 5) == 0)
        p.vertices.push_back(p.vertices.back());  // zero-length
    }
    const std::span<const Vec3<T>> v(p.vertices);
    const std::vector<T> cum = cumulative_lengths(v, p.closed);
    ASSERT_EQ(cum.size(), segment_count(p) + 1);
    EXPECT_NEAR(cum.back(), length(p), tol<T>(8, cum.back() + T(1)));
    for (int k = 0; k < 20; ++k) {
      const T s = rng.uniform<T>(T(-1), cum.back() + T(1));
      const Vec3<T> a = point_at_arc_length(p, s);
      const Vec3<T> b = polyline_point_at_arc_length(v, p.closed, std::span<const T>(cum), s);
      EXPECT_TRUE(locus_test::vec_near(a, b, tol<T>(64, T(10) + cum.back())));
      // Each of the sampled points lies on the chain at the prescribed distance from the start.
      const T sc = clamp(s, T(0), cum.back());
      T best = std::numeric_limits<T>::infinity();
      for (std::size_t i = 0; i + 1 < cum.size(); ++i) {
        const Segment3<T> e = edge(p, i);
        const T len = length(e);
        if (sc < cum[i] - tol<T>(64, cum.back() + T(1)) ||
            sc > cum[i + 1] + tol<T>(64, cum.back() + T(1)))
          continue;
        const T t = len > T(0) ? clamp((sc - cum[i]) / len, T(0), T(1)) : T(0);
        best = std::min(best, length(point_at(e, t) - a));
      }
      if (segment_count(p) > 0) {
        EXPECT_LT(best, tol<T>(256, T(10) + cum.back()));
      }
    }
  }
}

TYPED_TEST(PolylineTest, DegeneratePolylines) {
  using T = TypeParam;
  const Polyline2<T> empty{};
  EXPECT_EQ(length(empty), T(0));
  EXPECT_EQ(segment_count(empty), 0u);
  EXPECT_EQ(point_at(empty, T(0.5)), (Vec2<T>{}));
  EXPECT_EQ(point_at_arc_length(empty, T(0.5)), (Vec2<T>{}));
  const Polyline2<T> one{{{T(2), T(3)}}, true};
  EXPECT_EQ(length(one), T(0));
  EXPECT_EQ(segment_count(one), 0u);
  EXPECT_EQ(point_at(one, T(0.5)), one.vertices[0]);
  EXPECT_EQ(point_at_arc_length(one, T(0.5)), one.vertices[0]);
  const Polyline2<T> pts{{{T(1), T(1)}, {T(1), T(1)}, {T(1), T(1)}}, false};
  EXPECT_EQ(length(pts), T(0));
  EXPECT_EQ(point_at_arc_length(pts, T(0.5)), pts.vertices[0]);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(point_at(pts, nan), pts.vertices[0]);
  // A two-vertex closed polyline runs there and back.
  const Polyline2<T> two{{{T(0), T(0)}, {T(2), T(0)}}, true};
  EXPECT_EQ(length(two), T(4));
  EXPECT_EQ(point_at(two, T(1.5)), (Vec2<T>{T(1), T(0)}));
}

// Figure 5.11: (a) a strictly monotone chain with respect to the x-axis; (b) monotone but not
// strictly (a vertical edge: a line perpendicular to the axis meets the chain in a segment).
TYPED_TEST(PolylineTest, Fig5_11_MonotoneChains) {
  using T = TypeParam;
  const Vec2<T> x{T(1), T(0)};
  const std::vector<Vec2<T>> a{
      {T(0), T(0)}, {T(1), T(2)}, {T(2), T(1)}, {T(4), T(3)}, {T(5), T(0)}};
  const std::vector<Vec2<T>> b{
      {T(0), T(0)}, {T(1), T(2)}, {T(1), T(-1)}, {T(4), T(3)}, {T(5), T(0)}};
  const std::vector<Vec2<T>> c{{T(0), T(0)}, {T(2), T(2)}, {T(1), T(-1)}, {T(4), T(3)}};
  EXPECT_TRUE(is_monotone_chain<T>(a, x, true));
  EXPECT_TRUE(is_monotone_chain<T>(a, x));
  EXPECT_FALSE(is_monotone_chain<T>(b, x, true));
  EXPECT_TRUE(is_monotone_chain<T>(b, x));
  EXPECT_FALSE(is_monotone_chain<T>(c, x));
  EXPECT_TRUE(is_monotone_chain<T>(a, -x, true));  // decreasing along -x is monotone too
  EXPECT_FALSE(is_monotone_chain<T>(a, Vec2<T>{T(0), T(1)}));
  EXPECT_TRUE(is_monotone_chain<T>(std::vector<Vec2<T>>{}, x, true));
  EXPECT_TRUE(is_monotone_chain<T>(std::vector<Vec2<T>>{{T(1), T(1)}}, x, true));
  EXPECT_FALSE(is_monotone_chain<T>(a, Vec2<T>{}));
  EXPECT_FALSE(is_monotone_chain<T>(a, Vec2<T>{std::numeric_limits<T>::quiet_NaN(), T(1)}));
}

// Oracle: exact GMP projections. Near-ties are forced by vertices that differ by one ulp in the
// projection or lie exactly on a common perpendicular.
TYPED_TEST(PolylineTest, MonotoneChainMatchesExactProjections) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int mono = 0, strict = 0, total = 0;
  for (int it = 0; it < 5000; ++it) {
    Vec2<T> d{T(rng.uniform_int(-3, 3)), T(rng.uniform_int(-3, 3))};
    if (it % 3 == 0) d = rng.vec<T, 2>(-1, 1);
    if (d == Vec2<T>{}) continue;
    std::vector<Vec2<T>> v;
    const int n = rng.uniform_int(2, 6);
    // Points nearly sorted along d: a random walk with small perpendicular noise.
    Vec2<T> p = rng.vec<T, 2>(-4, 4);
    for (int i = 0; i < n; ++i) {
      v.push_back(p);
      const T step = T(rng.uniform_int(-1, 6)) * T(0.25);
      const Vec2<T> side = perp(d) * T(rng.uniform_int(-4, 4));
      p = p + step * d + side;
      if (rng.uniform_int(0, 4) == 0) p.x = std::nextafter(p.x, T(100));  // a one-ulp nudge
    }
    int dir = 0;
    bool is_mono = true, is_strict = true;
    for (std::size_t i = 1; i < v.size(); ++i) {
      const mpq_class proj =
          (mpq_class(v[i].x) - v[i - 1].x) * d.x + (mpq_class(v[i].y) - v[i - 1].y) * d.y;
      const int s = sgn(proj);
      if (s == 0) {
        is_strict = false;
        continue;
      }
      if (dir == 0)
        dir = s;
      else if (s != dir)
        is_mono = is_strict = false;
    }
    EXPECT_EQ(is_monotone_chain<T>(v, d), is_mono);
    EXPECT_EQ(is_monotone_chain<T>(v, d, true), is_strict && is_mono);
    mono += is_mono;
    strict += is_strict && is_mono;
    ++total;
  }
  EXPECT_GT(mono, total / 10);
  EXPECT_GT(strict, total / 20);
  EXPECT_LT(mono, total);
}
