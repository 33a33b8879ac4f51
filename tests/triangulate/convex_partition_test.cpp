// SPDX-License-Identifier: BSL-1.0
// Convex partitions (triangulate/convex_partition.hpp), checked independently in GMP
// rationals: every piece counter-clockwise and weakly convex, the pieces (fanned into
// triangles) pass the triangulation checks of triangulation_check.hpp (exact area sum,
// pairwise disjoint interiors, no crossing of a polygon edge, no polygon vertex inside); the
// minimum against a brute force over all sets of non-crossing diagonals on polygons of at most
// 8 vertices; Hertel-Mehlhorn at most 4 x the minimum and at least the minimum.

#include <locus/triangulate/convex_partition.hpp>

#include "polygons.hpp"
#include "support/typed.hpp"
#include "triangulation_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using locus::ConvexPartition;
using locus::Status;
using locus::Vec2;
using locus_test::Polygon;

template <class T>
class ConvexPartitionTest : public ::testing::Test {};
TYPED_TEST_SUITE(ConvexPartitionTest, locus_test::RealTypes);

/// Empty string or the first failure of the checks at the top of the file.
template <class T>
std::string check_pieces(const Polygon<T>& p, const ConvexPartition& r) {
  std::vector<locus_test::Tri> fan;
  std::uint32_t b = 0;
  for (const std::uint32_t e : r.piece_ends) {
    if (e - b < 3) return "piece with fewer than 3 vertices";
    for (std::uint32_t i = b; i < e; ++i) {
      const auto& u = p.points[r.vertices[i == b ? e - 1 : i - 1]];
      const auto& v = p.points[r.vertices[i]];
      const auto& w = p.points[r.vertices[i + 1 == e ? b : i + 1]];
      if (locus_test::orient_s(u, v, w) < 0) return "piece not convex";
    }
    for (std::uint32_t i = b + 1; i + 1 < e; ++i) {
      const locus_test::Tri t{r.vertices[b], r.vertices[i], r.vertices[i + 1]};
      if (locus_test::orient_s(p.points[t[0]], p.points[t[1]], p.points[t[2]]) != 0)
        fan.push_back(t);
    }
    b = e;
  }
  return locus_test::check_triangulation<T>(p.points, p.ends, fan);
}

/// The number of reflex vertices of a simple ring (exact).
template <class T>
int reflex_count(const std::vector<Vec2<T>>& ring) {
  const mpq_class area = locus_test::twice_ring_area<T>(ring, 0, std::uint32_t(ring.size()));
  const int s = sgn(area), n = int(ring.size());
  int r = 0;
  for (int i = 0; i < n; ++i)
    r += s * locus_test::orient_s(ring[std::size_t((i + n - 1) % n)], ring[std::size_t(i)],
                                  ring[std::size_t((i + 1) % n)]) <
         0;
  return r;
}

/// Brute force: the least number of convex pieces over all sets of non-crossing diagonals.
template <class T>
int brute_min_pieces(const std::vector<Vec2<T>>& input) {
  std::vector<Vec2<T>> v = input;
  const std::uint32_t n = std::uint32_t(v.size());
  if (locus_test::twice_ring_area<T>(v, 0, n) < 0) std::reverse(v.begin(), v.end());
  const std::uint32_t ends[] = {n};
  // A diagonal: no polygon edge meets the closed segment except at its own ends (so no vertex
  // on it either), and its midpoint is strictly inside.
  std::vector<std::array<std::uint32_t, 2>> diags;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 2; b < n; ++b) {
      if (a == 0 && b == n - 1) continue;
      bool ok = true;
      for (std::uint32_t e = 0; e < n && ok; ++e) {
        const std::uint32_t f = (e + 1) % n;
        for (const std::uint32_t w : {e, f})
          if (w != a && w != b && locus_test::orient_s(v[a], v[b], v[w]) == 0) {
            const mpq_class dx = mpq_class(double(v[w].x)) - double(v[a].x),
                            ex = mpq_class(double(v[w].x)) - double(v[b].x),
                            dy = mpq_class(double(v[w].y)) - double(v[a].y),
                            ey = mpq_class(double(v[w].y)) - double(v[b].y);
            if (dx * ex <= 0 && dy * ey <= 0) ok = false;
          }
        if (e == a || e == b || f == a || f == b) continue;
        const int o1 = locus_test::orient_s(v[a], v[b], v[e]),
                  o2 = locus_test::orient_s(v[a], v[b], v[f]),
                  o3 = locus_test::orient_s(v[e], v[f], v[a]),
                  o4 = locus_test::orient_s(v[e], v[f], v[b]);
        if (o1 * o2 < 0 && o3 * o4 < 0) ok = false;
      }
      const mpq_class mx = (mpq_class(double(v[a].x)) + double(v[b].x)) / 2,
                      my = (mpq_class(double(v[a].y)) + double(v[b].y)) / 2;
      if (ok && locus_test::inside_q<T>(v, ends, mx, my)) diags.push_back({a, b});
    }
  const auto crosses = [](const std::array<std::uint32_t, 2>& d,
                          const std::array<std::uint32_t, 2>& e) {
    const auto in = [](std::uint32_t x, std::uint32_t lo, std::uint32_t hi) {
      return lo < x && x < hi;
    };
    if (d[0] == e[0] || d[0] == e[1] || d[1] == e[0] || d[1] == e[1]) return false;
    return in(e[0], d[0], d[1]) != in(e[1], d[0], d[1]);
  };
  const auto all_convex = [&](const std::vector<std::array<std::uint32_t, 2>>& set) {
    for (std::uint32_t c = 0; c < n; ++c) {
      std::vector<std::uint32_t> fan{(c + 1) % n};
      std::vector<std::uint32_t> others;
      for (const auto& d : set)
        if (d[0] == c || d[1] == c) others.push_back(d[0] == c ? d[1] : d[0]);
      std::sort(others.begin(), others.end(), [&](std::uint32_t x, std::uint32_t y) {
        return (x + n - c) % n < (y + n - c) % n;
      });
      fan.insert(fan.end(), others.begin(), others.end());
      fan.push_back((c + n - 1) % n);
      for (std::size_t k = 0; k + 1 < fan.size(); ++k)
        if (locus_test::orient_s(v[c], v[fan[k]], v[fan[k + 1]]) < 0) return false;
    }
    return true;
  };
  int best = std::numeric_limits<int>::max();
  std::vector<std::array<std::uint32_t, 2>> set;
  const auto search = [&](const auto& self, std::size_t from) -> void {
    if (int(set.size()) + 1 < best && all_convex(set)) best = int(set.size()) + 1;
    for (std::size_t k = from; k < diags.size(); ++k) {
      if (int(set.size()) + 2 >= best) return;
      bool free = true;
      for (const auto& d : set) free = free && !crosses(d, diags[k]);
      if (!free) continue;
      set.push_back(diags[k]);
      self(self, k + 1);
      set.pop_back();
    }
  };
  search(search, 0);
  return best;
}

TYPED_TEST(ConvexPartitionTest, MinimumMatchesBruteForceOnSmallPolygons) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 30; ++k) {
    const auto p = locus_test::star_polygon<T>(rng, rng.uniform_int(4, 8), 0.2, 1.0);
    const auto r = locus::min_convex_partition(p.points, p.ends);
    ASSERT_EQ(r.status, Status::ok) << k;
    ASSERT_EQ(check_pieces(p, r), "") << k;
    const int brute = brute_min_pieces(p.points);
    ASSERT_EQ(int(r.piece_count()), brute) << k;
    ASSERT_EQ(r.diagonals.size() + 1, r.piece_count());
    const auto hm = locus::convex_partition(p.points, p.ends);
    ASSERT_EQ(hm.status, Status::ok);
    ASSERT_EQ(check_pieces(p, hm), "") << k;
    EXPECT_GE(hm.piece_count(), r.piece_count());
    EXPECT_LE(hm.piece_count(), 4 * r.piece_count());
  }
}

TYPED_TEST(ConvexPartitionTest, HertelMehlhornWithinFourTimesTheMinimum) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 1);
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 6; ++k) {
    const auto p = locus_test::star_polygon<T>(rng, rng.uniform_int(10, 24), 0.2, 1.0);
    const auto m = locus::min_convex_partition(p.points, p.ends);
    const auto hm = locus::convex_partition(p.points, p.ends);
    ASSERT_EQ(m.status, Status::ok);
    ASSERT_EQ(hm.status, Status::ok);
    ASSERT_EQ(check_pieces(p, m), "") << k;
    ASSERT_EQ(check_pieces(p, hm), "") << k;
    const int r = reflex_count(p.points);
    EXPECT_GE(int(m.piece_count()), (r + 1) / 2 + 1);  // each piece resolves at most 2 reflex
    EXPECT_LE(int(hm.piece_count()), 2 * r + 1);
    EXPECT_LE(m.piece_count(), hm.piece_count());
    EXPECT_LE(hm.piece_count(), 4 * m.piece_count());
  }
}

TYPED_TEST(ConvexPartitionTest, HertelMehlhornWithHolesAndCorpus) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 2);
  SCOPED_TRACE(rng.trace());
  std::vector<Polygon<T>> cases;
  for (int k = 0; k < 3; ++k)
    cases.push_back(
        locus_test::star_polygon<T>(rng, rng.uniform_int(12, 40), 0.6, 1.0, rng.uniform_int(0, 4)));
  cases.push_back(locus_test::comb_polygon<T>(rng, 10));
  for (const auto& p : cases) {
    const auto hm = locus::convex_partition(p.points, p.ends);
    ASSERT_EQ(hm.status, Status::ok);
    ASSERT_EQ(check_pieces(p, hm), "");
  }
  // Comb: every tooth gap has two reflex vertices; pieces stay within 2r + 1.
  const auto comb = locus_test::comb_polygon<T>(rng, 10);
  EXPECT_LE(int(locus::convex_partition(comb.points, comb.ends).piece_count()),
            2 * reflex_count(comb.points) + 1);
  // (eberly-3 is left out: the monotone sweep rejects its touching rings.)
  for (const char* name : {"building", "dude", "boxy", "issue16"}) {
    SCOPED_TRACE(name);
    const auto d = locus_test::earcut_fixture<double>(name);
    Polygon<T> p;
    bool exact = true;
    for (const auto& v : d.points) {
      p.points.push_back({T(v.x), T(v.y)});
      exact = exact && double(T(v.x)) == v.x && double(T(v.y)) == v.y;
    }
    p.ends = d.ends;
    if (!exact) continue;
    const auto hm = locus::convex_partition(p.points, p.ends);
    ASSERT_EQ(hm.status, Status::ok);
    ASSERT_EQ(check_pieces(p, hm), "");
  }
}

TYPED_TEST(ConvexPartitionTest, DegenerateAndBadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  // A convex polygon (with a straight-run middle vertex): one piece, every vertex kept.
  std::vector<Vec2<T>> sq{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
  const std::uint32_t e5[] = {5};
  for (const auto& r : {locus::convex_partition(sq, e5), locus::min_convex_partition(sq, e5)}) {
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_EQ(r.piece_count(), 1u);
    EXPECT_EQ(r.vertices.size(), 5u);
  }
  // Empty, NaN, collinear, holes for the minimum, duplicates and a spike.
  EXPECT_EQ(locus::convex_partition(std::span<const Vec2<T>>{}, {}).status, Status::empty_input);
  auto bad = sq;
  bad[3].y = nan;
  EXPECT_EQ(locus::convex_partition(bad, e5).status, Status::non_finite_input);
  EXPECT_EQ(locus::min_convex_partition(bad, e5).status, Status::non_finite_input);
  std::vector<Vec2<T>> line{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}};
  EXPECT_EQ(locus::min_convex_partition(line, e5).status, Status::degenerate_input);
  EXPECT_EQ(locus::convex_partition(line, e5).status, Status::degenerate_input);
  Polygon<T> holed;
  holed.add_ring({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  holed.add_ring({{1, 1}, {1, 3}, {3, 3}, {3, 1}});
  EXPECT_EQ(locus::min_convex_partition(holed.points, holed.ends).status, Status::invalid_input);
  const auto framed = locus::convex_partition(holed.points, holed.ends);
  ASSERT_EQ(framed.status, Status::ok);
  EXPECT_EQ(check_pieces(holed, framed), "");
  Polygon<T> spiky;  // an L with a repeated point and a zero-area spike
  spiky.add_ring({{0, 0}, {2, 0}, {2, 0}, {2, 1}, {3, 1}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  const auto m = locus::min_convex_partition(spiky.points, spiky.ends);
  ASSERT_EQ(m.status, Status::ok);
  EXPECT_EQ(m.piece_count(), 2u);
  EXPECT_EQ(check_pieces(spiky, m), "");
  // A self-crossing ring (bow tie with a notch) is rejected.
  std::vector<Vec2<T>> bow{{0, 0}, {2, 2}, {2, 0}, {1, T(0.5)}, {0, 2}};
  EXPECT_EQ(locus::min_convex_partition(bow, e5).status, Status::invalid_topology);
  // Above the direct programme's size limit: the Hertel-Mehlhorn pieces with limit_exceeded;
  // Keil's programme has no such cap.
  locus_test::Rng rng;
  const auto big = locus_test::star_polygon<T>(rng, 80, 0.3, 1.0);
  const auto lim =
      locus::min_convex_partition(big.points, big.ends, locus::MinConvexMethod::direct);
  EXPECT_EQ(lim.status, Status::limit_exceeded);
  EXPECT_EQ(check_pieces(big, lim), "");
  const auto keil = locus::min_convex_partition(big.points, big.ends);
  EXPECT_EQ(keil.status, Status::ok);
  EXPECT_EQ(check_pieces(big, keil), "");
  EXPECT_LE(keil.piece_count(), lim.piece_count());
}

// Keil's programme against the direct O(n^5) one (an independent formulation: chains of valid
// diagonals, no narrowest pairs) on seeded random polygons of up to 40 vertices: equal piece
// counts, pieces convex and tiling the polygon exactly.
TYPED_TEST(ConvexPartitionTest, KeilMatchesTheDirectProgramme) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 7);
  SCOPED_TRACE(rng.trace());
  int snapped_ok = 0;
  for (int k = 0; k < 40; ++k) {
    Polygon<T> p;
    if (k % 6 == 5) {
      p = locus_test::comb_polygon<T>(rng, rng.uniform_int(2, 8));
    } else {
      p = locus_test::star_polygon<T>(rng,
                                      k < 60 ? rng.uniform_int(5, 24) : rng.uniform_int(25, 40),
                                      rng.uniform(0.1, 0.5), 1.0);
      // Every other star snapped to a coarse grid: many collinear vertices, straight angles in
      // the pieces, diagonals running along polygon edges.
      if (k % 2 == 0) {
        const T scale = T(rng.uniform_int(2, 7));
        for (auto& v : p.points) v = {std::round(v.x * scale), std::round(v.y * scale)};
      }
    }
    const auto keil = locus::min_convex_partition(p.points, p.ends);
    const auto direct =
        locus::min_convex_partition(p.points, p.ends, locus::MinConvexMethod::direct);
    if (direct.status != Status::ok) {  // snapping made it self-touching or degenerate
      EXPECT_EQ(keil.status, direct.status) << k;
      continue;
    }
    ASSERT_EQ(keil.status, Status::ok) << k;
    ASSERT_EQ(keil.piece_count(), direct.piece_count()) << k;
    ASSERT_EQ(keil.diagonals.size() + 1, keil.piece_count()) << k;
    ASSERT_EQ(check_pieces(p, keil), "") << k;
    snapped_ok += k % 6 != 5 && k % 2 == 0;
  }
  EXPECT_GT(snapped_ok, 8);
}

// Straight angles (found by comparing the two programmes on grid-snapped polygons): a piece
// whose side runs straight through both ends of its diagonal (needs the two-sided merge), a
// reflex vertex whose diagonal continues an edge, and straight polygon vertices.
TYPED_TEST(ConvexPartitionTest, KeilStraightAngles) {
  using T = TypeParam;
  const std::vector<std::vector<Vec2<T>>> rings = {
      {{2, 1}, {2, 3}, {-1, 3}, {-2, 1}, {-1, 0}, {-2, -1}, {0, -1}, {1, -2}, {2, -1}},
      {{4, 2}, {1, 3}, {-1, 2}, {-1, 1}, {-5, -2}, {-1, -3}, {2, -4}, {4, -2}},
      {{2, 1}, {1, 1}, {0, 1}, {-2, 2}, {-5, 0}, {-3, -3}, {0, -3}, {2, -3}, {2, -1}}};
  for (std::size_t k = 0; k < rings.size(); ++k) {
    Polygon<T> p;
    p.add_ring(rings[k]);
    const auto keil = locus::min_convex_partition(p.points, p.ends);
    const auto direct =
        locus::min_convex_partition(p.points, p.ends, locus::MinConvexMethod::direct);
    ASSERT_EQ(keil.status, Status::ok) << k;
    ASSERT_EQ(direct.status, Status::ok) << k;
    EXPECT_EQ(keil.piece_count(), 2u) << k;
    EXPECT_EQ(direct.piece_count(), 2u) << k;
    EXPECT_EQ(check_pieces(p, keil), "") << k;
  }
}

// Larger polygons (no cap): pieces tile the polygon, and the count lies between the lower
// bound ceil(r / 2) + 1 and Hertel-Mehlhorn's.
TYPED_TEST(ConvexPartitionTest, KeilOnLargerPolygons) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 8);
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 3; ++k) {
    const auto p = locus_test::star_polygon<T>(rng, rng.uniform_int(100, 160), 0.3, 1.0);
    const auto keil = locus::min_convex_partition(p.points, p.ends);
    ASSERT_EQ(keil.status, Status::ok) << k;
    ASSERT_EQ(check_pieces(p, keil), "") << k;
    const auto hm = locus::convex_partition(p.points, p.ends);
    EXPECT_LE(keil.piece_count(), hm.piece_count()) << k;
    const int r = reflex_count(p.points);
    EXPECT_GE(int(keil.piece_count()), (r + 1) / 2 + 1) << k;
  }
}

TYPED_TEST(ConvexPartitionTest, PowerOfTwoScalingAndReversal) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 3);
  SCOPED_TRACE(rng.trace());
  const auto p = locus_test::star_polygon<T>(rng, 16, 0.2, 1.0);
  const auto m = locus::min_convex_partition(p.points, p.ends);
  const auto hm = locus::convex_partition(p.points, p.ends);
  for (const T s : {T(0x1p-40), T(0x1p50)}) {
    auto q = p;
    for (auto& v : q.points) v = v * s;
    const auto ms = locus::min_convex_partition(q.points, q.ends);
    const auto hs = locus::convex_partition(q.points, q.ends);
    EXPECT_EQ(ms.vertices, m.vertices);
    EXPECT_EQ(hs.vertices, hm.vertices);
  }
  auto rev = p;
  std::reverse(rev.points.begin(), rev.points.end());
  EXPECT_EQ(locus::min_convex_partition(rev.points, rev.ends).piece_count(), m.piece_count());
}

}  // namespace
