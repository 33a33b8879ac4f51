// SPDX-License-Identifier: BSL-1.0
// Tests of locus/delaunay/delaunay2.hpp (row cg.delaunay2, book section 13.8).
// Every output is checked by delaunay_check.hpp (exact predicates and GMP rationals).

#include <locus/delaunay/delaunay2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "delaunay_check.hpp"
#include "support/typed.hpp"

namespace {

using locus::Delaunay2Result;
using locus::Location;
using locus::Sign;
using locus::Status;
using locus::Vec2;
using locus_test::check_delaunay;
using locus_test::edge_set;

template <class T>
class Delaunay2Test : public ::testing::Test {};
TYPED_TEST_SUITE(Delaunay2Test, locus_test::RealTypes);

template <class T>
std::vector<Vec2<T>> random_points(locus_test::Rng& rng, std::size_t n, T lo = T(-1), T hi = T(1)) {
  std::vector<Vec2<T>> p(n);
  for (auto& q : p) q = rng.vec<T, 2>(lo, hi);
  return p;
}

template <class T>
Delaunay2Result run(const std::vector<Vec2<T>>& p) {
  return locus::delaunay(std::span<const Vec2<T>>(p));
}

// ---- small and degenerate inputs -------------------------------------------------------

TYPED_TEST(Delaunay2Test, ZeroOneTwoThreePoints) {
  using T = TypeParam;
  std::vector<Vec2<T>> p;
  auto r = run(p);
  EXPECT_EQ(r.status, Status::empty_input);
  EXPECT_EQ(r.dimension, -1);
  EXPECT_TRUE(r.triangles.empty());

  p = {{T(1), T(2)}};
  r = run(p);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 0);
  EXPECT_EQ(r.hull, (std::vector<std::uint32_t>{0}));

  p = {{T(3), T(2)}, {T(1), T(2)}};
  r = run(p);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 1);
  EXPECT_EQ(r.hull, (std::vector<std::uint32_t>{1, 0}));  // sorted along the line

  p = {{T(0), T(0)}, {T(0), T(1)}, {T(1), T(0)}};  // clockwise input
  r = run(p);
  EXPECT_TRUE(check_delaunay(p, r, true));
  ASSERT_EQ(r.triangle_count(), 1u);
  EXPECT_EQ(r.hull, (std::vector<std::uint32_t>{0, 2, 1}));  // CCW from the smallest index
}

TYPED_TEST(Delaunay2Test, AllEqualAndDuplicates) {
  using T = TypeParam;
  std::vector<Vec2<T>> p(50, Vec2<T>{T(0.25), T(-3)});
  auto r = run(p);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 0);
  EXPECT_EQ(r.duplicate_count, 49u);
  for (auto d : r.duplicate_of) EXPECT_EQ(d, r.hull[0]);

  // Random points, each repeated up to 3 times, shuffled.
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  auto base = random_points<T>(rng, 300);
  std::vector<Vec2<T>> q;
  for (std::size_t i = 0; i < base.size(); ++i)
    for (int k = 0; k < 1 + int(i % 3); ++k) q.push_back(base[i]);
  std::shuffle(q.begin(), q.end(), rng.engine());
  r = run(q);
  EXPECT_TRUE(check_delaunay(q, r, true));
  EXPECT_EQ(r.duplicate_count, q.size() - base.size());
}

TYPED_TEST(Delaunay2Test, AllCollinear) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  // Exactly collinear: integer multiples of a direction, shuffled, with duplicates.
  std::vector<Vec2<T>> p;
  for (int i = -40; i <= 40; ++i) p.push_back({T(3 * i), T(-2 * i + 7)});
  p.push_back(p[5]);
  std::shuffle(p.begin(), p.end(), rng.engine());
  auto r = run(p);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.dimension, 1);
  EXPECT_TRUE(r.triangles.empty());
  EXPECT_EQ(r.duplicate_count, 1u);
  ASSERT_EQ(r.hull.size(), 81u);
  for (std::size_t i = 1; i < r.hull.size(); ++i)
    EXPECT_LT(p[r.hull[i - 1]].x, p[r.hull[i]].x);  // sorted along the line

  // Collinear then one point off the line: a fan.
  p.push_back({T(1), T(1)});
  r = run(p);
  EXPECT_TRUE(check_delaunay(p, r, true));
  EXPECT_EQ(r.triangle_count(), 80u);
}

TYPED_TEST(Delaunay2Test, NonFiniteInput) {
  using T = TypeParam;
  const T bad[] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                   -std::numeric_limits<T>::infinity()};
  for (T b : bad) {
    std::vector<Vec2<T>> p = {{T(0), T(0)}, {T(1), T(0)}, {T(0), T(1)}, {b, T(0.5)}};
    auto r = run(p);
    EXPECT_EQ(r.status, Status::non_finite_input);
    EXPECT_TRUE(r.triangles.empty());
    EXPECT_EQ(r.dimension, -1);
  }
  locus::Delaunay2<T> d;
  std::vector<Vec2<T>> p = {{T(0), T(0)}, {T(1), T(0)}, {T(0), T(1)}};
  d.compute(std::span<const Vec2<T>>(p));
  EXPECT_EQ(d.insert({bad[0], T(0)}), Status::non_finite_input);
  EXPECT_EQ(d.points().size(), 3u);
  EXPECT_EQ(d.locate({bad[1], T(0)}).status, Status::non_finite_input);
}

// ---- cocircular inputs (the triangulation is not unique) -------------------------------

TYPED_TEST(Delaunay2Test, ExactlyCocircularIntegerPoints) {
  using T = TypeParam;
  // Every integer point of x^2 + y^2 = 5525^2 (many, all exactly on one circle), plus centre.
  const long r0 = 5525;
  std::vector<Vec2<T>> p;
  for (long x = -r0; x <= r0; ++x) {
    const long y2 = r0 * r0 - x * x;
    const long y = std::lround(std::sqrt(double(y2)));
    if (y * y != y2) continue;
    p.push_back({T(x), T(y)});
    if (y != 0) p.push_back({T(x), T(-y)});
  }
  ASSERT_GT(p.size(), 40u);
  auto r = run(p);
  EXPECT_TRUE(check_delaunay(p, r, true));
  EXPECT_EQ(r.hull.size(), p.size());
  // Deterministic: the same input gives the same output.
  auto r2 = run(p);
  EXPECT_EQ(r.triangles, r2.triangles);
  p.push_back({T(0), T(0)});
  r = run(p);
  EXPECT_TRUE(check_delaunay(p, r, true));
}

TYPED_TEST(Delaunay2Test, IntegerGrid) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int side : {2, 3, 7, std::is_same_v<T, double> ? 200 : 100}) {
    std::vector<Vec2<T>> p;
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) p.push_back({T(i), T(j)});
    if (side < 10) std::shuffle(p.begin(), p.end(), rng.engine());
    auto r = run(p);
    EXPECT_TRUE(check_delaunay(p, r, side < 10)) << side;
    EXPECT_EQ(r.triangle_count(), std::size_t(2 * (side - 1) * (side - 1)));
    EXPECT_EQ(r.hull.size(), std::size_t(4 * (side - 1)));
  }
}

// ---- random input: brute-force oracle, transform invariance ---------------------------

TYPED_TEST(Delaunay2Test, RandomBruteForce) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const std::size_t n = 3 + std::size_t(rng.uniform_int(0, 80));
    auto p = random_points<T>(rng, n);
    if (trial % 3 == 1)  // clustered near a line: many nearly collinear triples
      for (auto& q : p) q.y = q.x * T(0.5) + q.y * T(1e-5);
    if (trial % 3 == 2)  // small integer coordinates: exact degeneracies
      for (auto& q : p) q = {std::round(q.x * T(8)), std::round(q.y * T(8))};
    auto r = run(p);
    if (r.dimension < 2) continue;
    ASSERT_TRUE(check_delaunay(p, r, true)) << "trial " << trial;
    // The Delaunay triangulation of points without 4 cocircular is unique; in any case every
    // triangle with an empty circumcircle and no point on it must appear. Brute force O(n^4):
    // count such triangles and compare.
    if (n <= 30) {
      std::size_t strict = 0;
      for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = 0; b < n; ++b)
          for (std::size_t c = 0; c < n; ++c) {
            if (r.duplicate_of[a] != a || r.duplicate_of[b] != b || r.duplicate_of[c] != c)
              continue;
            if (!(a < b && a < c)) continue;
            if (locus::orient2d(p[a], p[b], p[c]) != Sign::positive) continue;
            bool empty = true;
            for (std::size_t d = 0; d < n && empty; ++d) {
              if (d == a || d == b || d == c || r.duplicate_of[d] != d) continue;
              empty = locus::incircle(p[a], p[b], p[c], p[d]) == Sign::negative;
            }
            if (!empty) continue;
            ++strict;
            bool found = false;
            for (std::size_t t = 0; t < r.triangle_count() && !found; ++t)
              for (int k = 0; k < 3; ++k)
                found = found || (r.triangles[t][std::size_t(k)] == a &&
                                  r.triangles[t][std::size_t((k + 1) % 3)] == b &&
                                  r.triangles[t][std::size_t((k + 2) % 3)] == c);
            EXPECT_TRUE(found) << "strictly Delaunay triangle " << a << " " << b << " " << c;
          }
      EXPECT_LE(strict, r.triangle_count());
    }
  }
}

TYPED_TEST(Delaunay2Test, TransformInvariance) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  // Dyadic coordinates k / 2^12 so translation by an exact offset stays exact.
  std::vector<Vec2<T>> p(1500);
  for (auto& q : p)
    q = {T(rng.uniform_int(-4096, 4096)) / T(4096), T(rng.uniform_int(-4096, 4096)) / T(4096)};
  auto r = run(p);
  ASSERT_TRUE(check_delaunay(p, r));
  const auto edges = edge_set(r);
  bool unique = true;  // no interior edge with a cocircular opposite vertex
  for (std::size_t t = 0; t < r.triangle_count() && unique; ++t)
    for (std::size_t i = 0; i < 3 && unique; ++i) {
      const auto u = r.adjacency[t][i];
      if (u == locus::kNoTriangle) continue;
      // The vertex of u opposite the shared edge: the one that is not on triangle t.
      std::uint32_t z = r.triangles[u][0];
      for (const auto v : r.triangles[u])
        if (std::find(r.triangles[t].begin(), r.triangles[t].end(), v) == r.triangles[t].end())
          z = v;
      unique = locus::incircle(p[r.triangles[t][0]], p[r.triangles[t][1]], p[r.triangles[t][2]],
                               p[z]) != Sign::zero;
    }
  {  // translation by an exact offset
    auto q = p;
    for (auto& v : q) v = {v.x + T(3), v.y - T(5)};
    auto rq = run(q);
    EXPECT_TRUE(check_delaunay(q, rq));
    if (unique) {
      EXPECT_EQ(edge_set(rq), edges);
    }
  }
  {  // swap x and y (a reflection)
    auto q = p;
    for (auto& v : q) v = {v.y, v.x};
    auto rq = run(q);
    EXPECT_TRUE(check_delaunay(q, rq));
    if (unique) {
      EXPECT_EQ(edge_set(rq), edges);
    }
  }
  {  // permuted input order
    std::vector<std::uint32_t> perm(p.size());
    std::iota(perm.begin(), perm.end(), 0u);
    std::shuffle(perm.begin(), perm.end(), rng.engine());
    std::vector<Vec2<T>> q(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) q[i] = p[perm[i]];
    auto rq = run(q);
    EXPECT_TRUE(check_delaunay(q, rq));
    if (unique) {
      locus_test::EdgeSet mapped;
      for (auto [a, b] : edge_set(rq)) {
        const auto ma = r.duplicate_of[perm[a]], mb = r.duplicate_of[perm[b]];
        mapped.insert({std::min(ma, mb), std::max(ma, mb)});
      }
      EXPECT_EQ(mapped, edges);
    }
  }
  {  // scaling by a power of two
    auto q = p;
    for (auto& v : q) v = {v.x * T(1024), v.y * T(1024)};
    auto rq = run(q);
    EXPECT_TRUE(check_delaunay(q, rq));
    if (unique) {
      EXPECT_EQ(edge_set(rq), edges);
    }
  }
}

TYPED_TEST(Delaunay2Test, HugeAndTinyCoordinates) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  // Inside the exact range of incircle (see predicates.hpp).
  const T scales[] = {std::is_same_v<T, float> ? T(1e30) : T(1e60),
                      std::is_same_v<T, float> ? T(1e-30) : T(1e-50)};
  for (T s : scales) {
    auto p = random_points<T>(rng, 400);
    for (auto& q : p) q = {q.x * s, q.y * s};
    auto r = run(p);
    EXPECT_TRUE(check_delaunay(p, r)) << s;
  }
  // Far from the origin: a small cloud a few thousand ulps wide around (c, -c) (rounding-hostile
  // for naive code; many coordinates coincide, so there are duplicates and collinear runs).
  const T c = std::is_same_v<T, float> ? T(1024) : T(1e6);
  auto p = random_points<T>(rng, 400, T(0), T(1) / T(64));
  for (auto& q : p) q = {q.x + c, q.y - c};
  EXPECT_TRUE(check_delaunay(p, run(p)));
}

TEST(Delaunay2, OutsideExactRangeNoCrashOrHang) {
  // Beyond the predicates' exact range (predicates.hpp) the result may not be Delaunay, but the
  // call must return (budgets) with a structurally sane result.
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (double s : {1e300, 1e-300, 1e-320}) {
    auto p = random_points<double>(rng, 300);
    for (auto& q : p) q = {q.x * s, q.y * s};
    p.push_back({std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()});
    const auto r = run(p);
    EXPECT_TRUE(r.status == Status::ok || r.status == Status::limit_exceeded);
    EXPECT_LE(r.triangle_count(), 2 * p.size());
    EXPECT_EQ(r.adjacency.size(), r.triangles.size());
  }
}

// ---- point location and incremental insertion ------------------------------------------

TYPED_TEST(Delaunay2Test, LocateMatchesBruteForce) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Vec2<T>> p;
  for (int i = 0; i < 15; ++i)
    for (int j = 0; j < 15; ++j) p.push_back({T(i), T(j)});
  for (int i = 0; i < 100; ++i) p.push_back({rng.uniform<T>(0, 14), rng.uniform<T>(0, 14)});
  locus::Delaunay2<T> d;
  const auto& r = d.compute(std::span<const Vec2<T>>(p));
  ASSERT_TRUE(check_delaunay(p, r));
  for (int k = 0; k < 300; ++k) {
    // Half of the queries on grid nodes / grid lines (exact on vertices or edges).
    Vec2<T> q = k % 2 ? Vec2<T>{rng.uniform<T>(-2, 16), rng.uniform<T>(-2, 16)}
                      : Vec2<T>{T(rng.uniform_int(-1, 15)), T(rng.uniform_int(-2, 32)) / T(2)};
    const auto loc = d.locate(q);
    ASSERT_EQ(loc.status, Status::ok);
    // Brute force: signs against every triangle.
    int inside = -1, on_edges = 0, on_vertices = 0;
    for (std::size_t t = 0; t < r.triangle_count(); ++t) {
      int zeros = 0;
      bool in = true;
      for (int i = 0; i < 3; ++i) {
        const Sign s = locus::orient2d(p[r.triangles[t][std::size_t(i)]],
                                       p[r.triangles[t][std::size_t((i + 1) % 3)]], q);
        in = in && s != Sign::negative;
        zeros += s == Sign::zero;
      }
      if (!in) continue;
      if (zeros == 0) inside = int(t);
      on_edges += zeros == 1;
      on_vertices += zeros == 2;
    }
    switch (loc.location) {
      case Location::inside:
        EXPECT_EQ(loc.triangle, inside);
        break;
      case Location::on_edge: {
        EXPECT_TRUE(on_edges >= 1 && on_vertices == 0);
        const auto& tv = r.triangles[std::size_t(loc.triangle)];
        EXPECT_EQ(locus::orient2d(p[tv[std::size_t(loc.corner)]],
                                  p[tv[std::size_t((loc.corner + 1) % 3)]], q),
                  Sign::zero);
        break;
      }
      case Location::on_vertex: {
        EXPECT_GE(on_vertices, 1);
        const auto v = r.triangles[std::size_t(loc.triangle)][std::size_t(loc.corner)];
        EXPECT_TRUE(p[v].x == q.x && p[v].y == q.y);
        break;
      }
      case Location::outside: {
        EXPECT_EQ(inside, -1);
        EXPECT_EQ(on_edges + on_vertices, 0);
        // Beyond edge `corner` of `triangle`, a hull edge.
        const auto& tv = r.triangles[std::size_t(loc.triangle)];
        EXPECT_EQ(r.adjacency[std::size_t(loc.triangle)][std::size_t(loc.corner)],
                  locus::kNoTriangle);
        EXPECT_EQ(locus::orient2d(p[tv[std::size_t(loc.corner)]],
                                  p[tv[std::size_t((loc.corner + 1) % 3)]], q),
                  Sign::negative);
        break;
      }
    }
  }
  // A tiny step budget reports limit_exceeded instead of walking on.
  const auto far = locus::locate(r, std::span<const Vec2<T>>(p), Vec2<T>{T(13.5), T(13.25)}, 0, 1);
  EXPECT_TRUE(far.status == Status::limit_exceeded || far.steps <= 1);
}

TYPED_TEST(Delaunay2Test, IncrementalInsertMatchesBatch) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  auto p = random_points<T>(rng, 600);
  locus::Delaunay2<T> d;
  // Starting collinear (dimension 1), then 2D.
  std::vector<Vec2<T>> first = {{T(0), T(0)}, {T(1), T(1)}};
  d.compute(std::span<const Vec2<T>>(first));
  EXPECT_EQ(d.result().dimension, 1);
  for (const auto& q : p) EXPECT_EQ(d.insert(q), Status::ok);
  EXPECT_EQ(d.insert(p[3]), Status::ok);  // a duplicate
  std::vector<Vec2<T>> all(d.points().begin(), d.points().end());
  const auto& r = d.result();
  EXPECT_TRUE(check_delaunay(all, r));
  EXPECT_EQ(r.duplicate_of.back(), 5u);
  EXPECT_EQ(edge_set(r), edge_set(run(all)));
}

TYPED_TEST(Delaunay2Test, FlatArrayThroughPointSpan) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  auto p = random_points<T>(rng, 200);
  std::vector<T> xy;
  for (auto& q : p) {
    xy.push_back(q.x);
    xy.push_back(q.y);
  }
  auto r = locus::delaunay(locus::point_span<2>(xy.data(), p.size()));
  EXPECT_TRUE(check_delaunay(p, r));
  EXPECT_EQ(r.triangles, run(p).triangles);
}

// ---- delaunator robustness fixtures (double input) -------------------------------------

class DelaunatorFixtures : public ::testing::TestWithParam<const char*> {};

TEST_P(DelaunatorFixtures, Valid) {
  const std::string path =
      std::string(LOCUS_SHARED_DIR "/corpus/delaunator/fixtures/") + GetParam() + ".json";
  auto p = locus_test::read_xy_json(path);
  ASSERT_FALSE(p.empty()) << path;
  auto r = locus::delaunay(std::span<const Vec2<double>>(p));
  EXPECT_TRUE(check_delaunay(p, r, p.size() <= 400));
  if (std::string(GetParam()) == "robustness1") {
    for (double s : {1e-9, 1e-2, 1e2, 1e9}) {
      auto q = p;
      for (auto& v : q) v = {v.x * s, v.y * s};
      EXPECT_TRUE(check_delaunay(q, locus::delaunay(std::span<const Vec2<double>>(q)))) << s;
    }
  }
  if (std::string(GetParam()) == "robustness2") {
    std::vector<Vec2<double>> q(
        p.begin(), p.begin() + std::min<std::ptrdiff_t>(100, std::ptrdiff_t(p.size())));
    EXPECT_TRUE(check_delaunay(q, locus::delaunay(std::span<const Vec2<double>>(q)), true));
  }
  // Float input made from the same set (rounded: new degeneracies and duplicates).
  std::vector<Vec2<float>> f(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) f[i] = {float(p[i].x), float(p[i].y)};
  auto rf = locus::delaunay(std::span<const Vec2<float>>(f));
  if (rf.dimension == 2) {
    EXPECT_TRUE(check_delaunay(f, rf));
  }
}

INSTANTIATE_TEST_SUITE_P(Delaunay2, DelaunatorFixtures,
                         ::testing::Values("ukraine", "issue13", "issue43", "issue44",
                                           "robustness1", "robustness2", "robustness3",
                                           "robustness4"));

TEST(Delaunay2, UkraineMovedPoint) {
  auto p = locus_test::read_xy_json(LOCUS_SHARED_DIR "/corpus/delaunator/fixtures/ukraine.json");
  ASSERT_FALSE(p.empty());
  p[0] = {80, 220};
  EXPECT_TRUE(check_delaunay(p, locus::delaunay(std::span<const Vec2<double>>(p))));
}

}  // namespace
