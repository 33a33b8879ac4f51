// SPDX-License-Identifier: BSL-1.0
// The incremental trapezoidal map, checked against oracles in GMP rationals: a brute-force
// search of the trapezoids finds exactly one containing each random query and it is the one
// locate() returns (so the trapezoids partition the plane); no segment enters a trapezoid's
// interior (x of both at a rational height in the overlap); 3k + 1 trapezoids after k
// insertions for distinct endpoints; the final map does not depend on insertion order or on
// merging during insertion; maximality; power-of-two scale; degenerate and bad input.

#include <locus/triangulate/trapezoid_map.hpp>

#include "polygons.hpp"
#include "support/typed.hpp"
#include "triangulation_check.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace {

using locus::MapTrapezoid;
using locus::Status;
using locus::TrapezoidMap2;
using locus::TrapezoidMapOptions;
using locus::Vec2;
using Seg = std::array<std::uint32_t, 2>;
constexpr std::uint32_t none = locus::trapezoid_unbounded;

template <class T>
class TrapezoidMapTest : public ::testing::Test {};
TYPED_TEST_SUITE(TrapezoidMapTest, locus_test::RealTypes);

template <class T>
struct Input {
  std::vector<Vec2<T>> points;
  std::vector<Seg> segments;
};

// Symbolic order of the header: larger y is above, ties broken by smaller x.
template <class T>
bool below(const Vec2<T>& a, const Vec2<T>& b) {
  return a.y < b.y || (a.y == b.y && a.x > b.x);
}

template <class T>
int sign_q(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c) {
  return sgn(locus_test::orient_q(a, b, c));
}

// The edges of a polygon's rings.
template <class T>
Input<T> polygon_edges(const locus_test::Polygon<T>& p) {
  Input<T> in{p.points, {}};
  std::uint32_t b = 0;
  for (const std::uint32_t e : p.ends) {
    for (std::uint32_t i = b; i < e; ++i) in.segments.push_back({i, i + 1 < e ? i + 1 : b});
    b = e;
  }
  return in;
}

// The same edges shrunk to their middle three quarters: disjoint, distinct endpoints.
template <class T>
Input<T> shrunk_edges(const locus_test::Polygon<T>& p) {
  const Input<T> e = polygon_edges(p);
  Input<T> in;
  for (const Seg& s : e.segments) {
    const Vec2<T> a = e.points[s[0]], b = e.points[s[1]];
    const auto n = static_cast<std::uint32_t>(in.points.size());
    in.points.push_back({locus_test::snap<T>(a.x + (b.x - a.x) / 8.0),
                         locus_test::snap<T>(a.y + (b.y - a.y) / 8.0)});
    in.points.push_back({locus_test::snap<T>(b.x + (a.x - b.x) / 8.0),
                         locus_test::snap<T>(b.y + (a.y - b.y) / 8.0)});
    in.segments.push_back({n, n + 1});
  }
  return in;
}

// Brute force, exact: does trapezoid t contain q strictly inside?
template <class T>
bool strictly_inside(const Input<T>& in, const MapTrapezoid& t, const Vec2<T>& q) {
  const auto side = [&](std::uint32_t s) {
    Vec2<T> a = in.points[in.segments[s][0]], b = in.points[in.segments[s][1]];
    if (below(b, a)) std::swap(a, b);
    return sign_q(a, b, q);
  };
  return (t.bottom == none || below(in.points[t.bottom], q)) &&
         (t.top == none || below(q, in.points[t.top])) && (t.left == none || side(t.left) < 0) &&
         (t.right == none || side(t.right) > 0);
}

template <class T>
bool on_some_segment(const Input<T>& in, const Vec2<T>& q) {
  for (const Seg& s : in.segments) {
    Vec2<T> a = in.points[s[0]], b = in.points[s[1]];
    if (below(b, a)) std::swap(a, b);
    if (sign_q(a, b, q) == 0 && !below(q, a) && !below(b, q)) return true;
  }
  return false;
}

// Every random query lies in exactly one trapezoid, the one locate() gives.
template <class T>
void check_location(const TrapezoidMap2<T>& m, const Input<T>& in, locus_test::Rng& rng,
                    int queries) {
  const auto traps = m.trapezoids();
  for (int k = 0; k < queries; ++k) {
    // Odd multiples of 2^-12: never level with the inputs' 2^-10 grid.
    const Vec2<T> q{static_cast<T>((2 * rng.uniform_int(-3000, 3000) + 1) / 4096.0),
                    static_cast<T>((2 * rng.uniform_int(-3000, 3000) + 1) / 4096.0)};
    std::vector<std::uint32_t> hits;
    for (std::size_t i = 0; i < traps.size(); ++i)
      if (strictly_inside(in, traps[i], q)) hits.push_back(static_cast<std::uint32_t>(i));
    if (hits.size() != 1 && on_some_segment(in, q)) continue;
    ASSERT_EQ(hits.size(), 1u) << "query " << q.x << " " << q.y;
    ASSERT_EQ(m.locate(q), hits[0]) << "query " << q.x << " " << q.y;
  }
}

// x of segment s at height y, exactly.
template <class T>
mpq_class x_at(const Input<T>& in, std::uint32_t s, const mpq_class& y) {
  const Vec2<T> a = in.points[in.segments[s][0]], b = in.points[in.segments[s][1]];
  const mpq_class ax(double(a.x)), ay(double(a.y)), bx(double(b.x)), by(double(b.y));
  return ax + (y - ay) / (by - ay) * (bx - ax);
}

// No segment meets the interior of a trapezoid (inputs without level segments).
template <class T>
void check_not_crossed(const Input<T>& in, std::span<const MapTrapezoid> traps) {
  for (std::size_t s = 0; s < in.segments.size(); ++s) {
    const T y0 = std::min(in.points[in.segments[s][0]].y, in.points[in.segments[s][1]].y);
    const T y1 = std::max(in.points[in.segments[s][0]].y, in.points[in.segments[s][1]].y);
    for (const MapTrapezoid& t : traps) {
      if (t.left == s || t.right == s) continue;
      mpq_class lo{double(y0)}, hi{double(y1)};
      if (t.bottom != none && lo < double(in.points[t.bottom].y))
        lo = double(in.points[t.bottom].y);
      if (t.top != none && double(in.points[t.top].y) < hi) hi = double(in.points[t.top].y);
      if (lo >= hi) continue;
      const mpq_class y = (lo + hi) / 2;
      const mpq_class x = x_at(in, static_cast<std::uint32_t>(s), y);
      const bool right_of_left = t.left == none || x_at(in, t.left, y) < x;
      const bool left_of_right = t.right == none || x < x_at(in, t.right, y);
      ASSERT_FALSE(right_of_left && left_of_right) << "segment " << s << " crosses a trapezoid";
    }
  }
}

template <class T>
std::vector<MapTrapezoid> sorted(std::span<const MapTrapezoid> t) {
  std::vector<MapTrapezoid> v(t.begin(), t.end());
  std::sort(v.begin(), v.end(), [](const MapTrapezoid& a, const MapTrapezoid& b) {
    return std::tie(a.bottom, a.top, a.left, a.right) < std::tie(b.bottom, b.top, b.left, b.right);
  });
  return v;
}

template <class T>
void check_maximal(std::span<const MapTrapezoid> traps) {
  for (const MapTrapezoid& a : traps)
    for (const MapTrapezoid& b : traps)
      ASSERT_FALSE(a.top != none && a.top == b.bottom && a.left == b.left && a.right == b.right);
}

TYPED_TEST(TrapezoidMapTest, RandomPolygonEdgesPartitionThePlane) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 12; ++c) {
    // Sequenced draws; 12+ vertices keep the holes inside the outer ring.
    const int holes = rng.uniform_int(0, 3), n = rng.uniform_int(holes ? 12 : 3, 40);
    const auto poly = locus_test::star_polygon<T>(rng, n, 0.5, 1.0, holes);
    const Input<T> in = polygon_edges(poly);
    std::vector<MapTrapezoid> reference;
    for (int variant = 0; variant < 4; ++variant) {
      TrapezoidMapOptions opt;
      opt.merge_each_insertion = variant % 2 == 0;
      opt.shuffle_seed = static_cast<std::uint64_t>(variant / 2 * (c + 7));
      TrapezoidMap2<T> m;
      ASSERT_EQ(m.build(std::span<const Vec2<T>>(in.points), in.segments, opt), Status::ok);
      check_location(m, in, rng, 60);
      check_maximal<T>(m.trapezoids());
      // The maximal map is unique: same for every order and either merging mode.
      if (variant == 0)
        reference = sorted<T>(m.trapezoids());
      else
        ASSERT_EQ(sorted<T>(m.trapezoids()), reference) << "variant " << variant;
    }
  }
}

TYPED_TEST(TrapezoidMapTest, DistinctEndpointsGive3kPlus1) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 1);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 8; ++c) {
    const int holes = rng.uniform_int(0, 2), n = rng.uniform_int(holes ? 12 : 3, 30);
    const auto poly = locus_test::star_polygon<T>(rng, n, 0.5, 1.0, holes);
    Input<T> in = shrunk_edges(poly);
    // Drop level segments so the crossing oracle has a height range to look at.
    std::erase_if(in.segments,
                  [&](const Seg& s) { return in.points[s[0]].y == in.points[s[1]].y; });
    const std::span<const Vec2<T>> pts(in.points);
    TrapezoidMap2<T> seidel, book;
    ASSERT_EQ(seidel.begin(pts, in.segments), Status::ok);
    ASSERT_EQ(book.begin(pts, in.segments, {false, 0}), Status::ok);
    for (std::uint32_t s = 0; s < in.segments.size(); ++s) {
      ASSERT_EQ(seidel.insert(s), Status::ok);
      ASSERT_EQ(book.insert(s), Status::ok);
      ASSERT_EQ(seidel.trapezoids().size(), 3 * (s + 1) + 1);
      ASSERT_GE(book.trapezoids().size(), 3 * (s + 1) + 1);
    }
    book.merge();
    ASSERT_EQ(book.trapezoids().size(), 3 * in.segments.size() + 1);
    check_not_crossed(in, seidel.trapezoids());
    check_location(book, in, rng, 60);
  }
}

TYPED_TEST(TrapezoidMapTest, BookStatesBeforeMergingPartitionThePlane) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 2);
  SCOPED_TRACE(rng.trace());
  const auto poly = locus_test::star_polygon<T>(rng, 14, 0.5, 1.0, 1);
  const Input<T> in = polygon_edges(poly);
  TrapezoidMap2<T> m;
  ASSERT_EQ(m.begin(std::span<const Vec2<T>>(in.points), in.segments, {false, 0}), Status::ok);
  ASSERT_EQ(m.trapezoids().size(), 1u);
  for (std::uint32_t s = 0; s < in.segments.size(); ++s) {
    ASSERT_EQ(m.split_at(m.segment(s)[0]), Status::ok);
    check_location(m, in, rng, 10);
    ASSERT_EQ(m.split_at(m.segment(s)[1]), Status::ok);
    ASSERT_EQ(m.insert(s), Status::ok);
    check_location(m, in, rng, 10);
  }
  m.merge();
  check_location(m, in, rng, 40);
}

TYPED_TEST(TrapezoidMapTest, CoversTheBoundingBox) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 3);
  SCOPED_TRACE(rng.trace());
  const Input<T> in = polygon_edges(locus_test::star_polygon<T>(rng, 25, 0.5, 1.0, 2));
  const auto r = locus::trapezoid_map(in.points, in.segments);
  ASSERT_EQ(r.status, Status::ok);
  const Vec2<T> lo{-2, -2}, hi{2, 2};
  double area = 0;
  for (const auto& t : r.trapezoids) {
    const auto c =
        locus::trapezoid_map_corners(std::span<const Vec2<T>>(in.points), in.segments, t, lo, hi);
    for (int i = 0; i < 4; ++i) {
      const auto& u = c[std::size_t(i)];
      const auto& v = c[std::size_t((i + 1) % 4)];
      area += 0.5 * (double(u.x) * double(v.y) - double(v.x) * double(u.y));
    }
  }
  EXPECT_NEAR(area, 16.0, 16.0 * 64 * std::numeric_limits<T>::epsilon());
}

TYPED_TEST(TrapezoidMapTest, PowerOfTwoScaleAndTranslationKeepTheMap) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 4);
  SCOPED_TRACE(rng.trace());
  Input<T> in = polygon_edges(locus_test::star_polygon<T>(rng, 30, 0.5, 1.0, 2));
  const auto base = locus::trapezoid_map(in.points, in.segments);
  for (const T f : {T(0.125), T(1024)}) {
    Input<T> scaled = in;
    for (auto& p : scaled.points) p = p * f;
    const auto r = locus::trapezoid_map(scaled.points, scaled.segments);
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_EQ(r.trapezoids, base.trapezoids);
  }
  // A translation on the input grid is exact and keeps the map too.
  Input<T> moved = in;
  for (auto& p : moved.points) p = p + Vec2<T>{T(3), T(-5)};
  const auto r = locus::trapezoid_map(moved.points, moved.segments);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.trapezoids, base.trapezoids);
}

// Whether closed segments ab and cd meet anywhere but at one shared endpoint (exact, GMP).
template <class T>
bool meet_elsewhere(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c, const Vec2<T>& d) {
  const auto on = [](const Vec2<T>& p, const Vec2<T>& q, const Vec2<T>& r) {  // r on [p, q]
    return sign_q(p, q, r) == 0 && std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) &&
           std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
  };
  const int o1 = sign_q(a, b, c), o2 = sign_q(a, b, d), o3 = sign_q(c, d, a), o4 = sign_q(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  const bool shared = a == c || a == d || b == c || b == d;
  if (!shared) return on(a, b, c) || on(a, b, d) || on(c, d, a) || on(c, d, b);
  const Vec2<T> s = a == c || a == d ? a : b, p = s == a ? b : a, q = s == c ? d : c;
  return on(a, b, q) || on(c, d, p);  // collinear overlap from the shared end
}

// Segments on a small integer grid: level and vertical segments, collinear chains, fans at
// shared endpoints and repeated points under other indices; queries level with the grid rows.
TYPED_TEST(TrapezoidMapTest, GridSegmentsWithTies) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 5);
  SCOPED_TRACE(rng.trace());
  for (int c = 0; c < 6; ++c) {
    Input<T> in;
    for (int x = 0; x <= 4; ++x)
      for (int y = 0; y <= 4; ++y) in.points.push_back({T(x), T(y)});
    for (int k = 0; k < 3; ++k) {
      const Vec2<T> copy = in.points[std::size_t(rng.uniform_int(0, 24))];
      in.points.push_back(copy);
    }
    const int last = static_cast<int>(in.points.size()) - 1;
    for (int tries = 0; tries < 30; ++tries) {
      const auto i = static_cast<std::uint32_t>(rng.uniform_int(0, last));
      const auto j = static_cast<std::uint32_t>(rng.uniform_int(0, last));
      if (in.points[i] == in.points[j]) continue;
      bool ok = true;
      for (const Seg& s : in.segments)
        ok = ok && !meet_elsewhere(in.points[i], in.points[j], in.points[s[0]], in.points[s[1]]);
      if (ok) in.segments.push_back({i, j});
    }
    std::vector<MapTrapezoid> reference;
    for (const int variant : {0, 3}) {  // Seidel in the given order; the book's, shuffled
      TrapezoidMap2<T> m;
      const TrapezoidMapOptions opt{variant % 2 == 0, static_cast<std::uint64_t>(variant / 2 * 5)};
      ASSERT_EQ(m.build(std::span<const Vec2<T>>(in.points), in.segments, opt), Status::ok);
      const auto traps = m.trapezoids();
      for (int qx = -1; qx <= 9; ++qx)
        for (int qy = -1; qy <= 9; ++qy) {
          const Vec2<T> q{T(qx * 0.5 + 0.125), T(qy * 0.5 + (qy % 2 != 0 ? 0.25 : 0.0))};
          if (on_some_segment(in, q)) continue;
          std::vector<std::uint32_t> hits;
          for (std::size_t i = 0; i < traps.size(); ++i)
            if (strictly_inside(in, traps[i], q)) hits.push_back(static_cast<std::uint32_t>(i));
          ASSERT_EQ(hits.size(), 1u) << "case " << c << " query " << q.x << " " << q.y;
          ASSERT_EQ(m.locate(q), hits[0]);
        }
      if (variant == 0)
        reference = sorted<T>(traps);
      else
        ASSERT_EQ(sorted<T>(traps), reference) << "case " << c << " variant " << variant;
    }
  }
}

TYPED_TEST(TrapezoidMapTest, DegenerateAndBadInput) {
  using T = TypeParam;
  const std::vector<Vec2<T>> none_pts;
  const auto empty = locus::trapezoid_map(none_pts, {});
  EXPECT_EQ(empty.status, Status::empty_input);
  ASSERT_EQ(empty.trapezoids.size(), 1u);  // the plane
  EXPECT_EQ(empty.trapezoids[0], MapTrapezoid{});

  // Level segments, a shared endpoint fan, a repeated point with another index, a zero-length
  // segment: the map still partitions the plane.
  Input<T> fan{{{0, 0}, {2, 0}, {1, 1}, {-1, 1}, {0, 2}, {0, 0}, {3, 3}, {3, 3}},
               {{0, 1}, {0, 2}, {0, 3}, {4, 5}, {2, 4}, {6, 7}, {1, 2}}};
  TrapezoidMap2<T> m;
  ASSERT_EQ(m.build(std::span<const Vec2<T>>(fan.points), fan.segments), Status::ok);
  EXPECT_EQ(m.canonical(5), 0u);
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  check_location(m, fan, rng, 200);
  check_maximal<T>(m.trapezoids());
  // On a boundary: above a point, right of a segment.
  const auto t = m.trapezoids()[m.locate(Vec2<T>{1, 1})];
  EXPECT_EQ(t.bottom, 2u);
  const auto u = m.trapezoids()[m.locate(Vec2<T>{T(0.5), T(0.5)})];
  EXPECT_EQ(u.left, 1u);

  const std::vector<Vec2<T>> cross_pts{{0, 0}, {2, 2}, {0, 2}, {2, 0}, {1, 1}, {1, 3}, {5, 5}};
  const std::vector<Seg> crossing{{0, 1}, {2, 3}};
  TrapezoidMap2<T> c;
  EXPECT_EQ(c.build(std::span<const Vec2<T>>(cross_pts), crossing), Status::invalid_topology);
  const Input<T> first{cross_pts, {{0, 1}}};
  check_location(c, first, rng, 100);  // the map without the bad segment stays valid
  const std::vector<Seg> t_junction{{0, 1}, {4, 5}};
  EXPECT_EQ(locus::trapezoid_map(cross_pts, t_junction).status, Status::invalid_topology);
  const std::vector<Seg> overlap{{0, 1}, {4, 6}};
  EXPECT_EQ(locus::trapezoid_map(cross_pts, overlap).status, Status::invalid_topology);
  const std::vector<Seg> overlap2{{0, 6}, {4, 1}};
  EXPECT_EQ(locus::trapezoid_map(cross_pts, overlap2).status, Status::invalid_topology);
  const std::vector<Seg> out_of_range{{0, 9}};
  EXPECT_EQ(locus::trapezoid_map(cross_pts, out_of_range).status, Status::invalid_input);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const std::vector<Vec2<T>> bad{{0, 0}, {nan, 1}};
  const std::vector<Seg> one{{0, 1}};
  const auto r = locus::trapezoid_map(bad, one);
  EXPECT_EQ(r.status, Status::non_finite_input);
  EXPECT_TRUE(r.trapezoids.empty());
  TrapezoidMap2<T> b;
  EXPECT_EQ(b.build(std::span<const Vec2<T>>(bad), one), Status::non_finite_input);
  EXPECT_EQ(b.locate(Vec2<T>{0, 0}), none);
}

}  // namespace
