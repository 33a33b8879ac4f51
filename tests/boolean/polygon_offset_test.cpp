// SPDX-License-Identifier: BSL-1.0
// Polygon offsetting: every output passes the independent validity checker
// (tests/support/polygon_validity.hpp). Oracle for round joins: the Minkowski sum (difference)
// with a disc, decided per sampled point by its distance to the input boundary in long double
// and its exact insideness (orient2d windings); miter and square joins: every output vertex's
// distance to the input lies between |delta| and the join's bound; exact GMP areas against
// closed forms.

#include <locus/boolean/polygon_offset.hpp>
#include <locus/core/predicates.hpp>

#include <support/polygon_validity.hpp>
#include <support/scale_covariance.hpp>
#include <support/typed.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace {

using locus::EndType;
using locus::JoinType;
using locus::MultiPolygon2;
using locus::OffsetOptions;
using locus::Polygon2;
using locus::PolygonWithHoles2;
using locus::Polyline;
using locus::Vec2;
using locus_test::Rng;

template <class T>
class PolygonOffsetTest : public ::testing::Test {};
TYPED_TEST_SUITE(PolygonOffsetTest, locus_test::RealTypes);

using locus_test::exact_winding;
template <class T>
bool inside(const MultiPolygon2<T>& m, const Vec2<T>& p) {
  int w = 0;
  for (const auto& poly : m) {
    w += exact_winding(poly.outer.vertices, p);
    for (const auto& h : poly.holes) w += exact_winding(h.vertices, p);
  }
  return w > 0;
}

using Segs = std::vector<std::array<long double, 4>>;
template <class T>
void add_chain(Segs& s, const std::vector<Vec2<T>>& v, bool closed) {
  const std::size_t n = v.size();
  if (n == 1) s.push_back({v[0].x, v[0].y, v[0].x, v[0].y});
  for (std::size_t i = 0; i + (closed ? 0 : 1) < n; ++i)
    s.push_back({v[i].x, v[i].y, v[(i + 1) % n].x, v[(i + 1) % n].y});
}
template <class T>
Segs boundary(const MultiPolygon2<T>& m) {
  Segs s;
  for (const auto& p : m) {
    add_chain(s, p.outer.vertices, true);
    for (const auto& h : p.holes) add_chain(s, h.vertices, true);
  }
  return s;
}
/// Distance from p to the segments, in long double.
template <class T>
long double distance(const Segs& segs, const Vec2<T>& p) {
  long double best = std::numeric_limits<long double>::infinity();
  for (const auto& s : segs) {
    const long double dx = s[2] - s[0], dy = s[3] - s[1];
    const long double px = p.x - s[0], py = p.y - s[1];
    const long double l2 = dx * dx + dy * dy;
    const long double t = l2 > 0 ? std::clamp((px * dx + py * dy) / l2, 0.0L, 1.0L) : 0.0L;
    best = std::min(best, std::hypot(px - t * dx, py - t * dy));
  }
  return best;
}

template <class T>
Polygon2<T> random_star(Rng& rng, double cx, double cy, double rmin, double rmax, int n) {
  Polygon2<T> p;
  for (int i = 0; i < n; ++i) {
    const double a = (i + rng.uniform(0.0, 0.5)) * 2 * std::numbers::pi / n;
    const double r = rng.uniform(rmin, rmax);
    p.vertices.push_back({T(cx + r * std::cos(a)), T(cy + r * std::sin(a))});
  }
  return p;
}
template <class T>
MultiPolygon2<T> random_region(Rng& rng) {
  PolygonWithHoles2<T> p{random_star<T>(rng, 0, 0, 0.6, 1.0, rng.uniform_int(6, 12)), {}};
  if (rng.uniform_int(0, 1)) {
    Polygon2<T> h = random_star<T>(rng, 0, 0, 0.1, 0.35, rng.uniform_int(3, 7));
    std::reverse(h.vertices.begin(), h.vertices.end());
    p.holes.push_back(h);
  }
  return {p};
}

template <class T>
Polygon2<T> square(T s) {
  return {{{0, 0}, {s, 0}, {s, s}, {0, s}}};
}
template <class T>
double area(const locus::OffsetResult<T>& r) {
  return locus_test::exact_area(r.polygons).get_d();
}

/// The round-join oracle on sampled points (chords inscribed in the arcs, gap <= tol): delta > 0:
/// inside when in the region or nearer than |delta| - tol, outside beyond |delta|; delta < 0:
/// inside when in the region and farther than |delta|, outside when nearer than |delta| - tol.
template <class T>
int check_round(const MultiPolygon2<T>& region, const Segs& segs, T delta, double tol,
                const locus::OffsetResult<T>& res, Rng& rng, int samples, double extent) {
  EXPECT_EQ(res.status, locus::Status::ok) << res.message;
  EXPECT_EQ(locus_test::polygon_validity(res.polygons), "");
  const double slack = 4 * res.grid + 1e-12;
  const double d = std::abs(double(delta));
  // Uniform samples, then samples around the input vertices at distances near |delta|, where
  // the chords of the round joins are.
  std::vector<Vec2<T>> pts;
  for (int i = 0; i < samples; ++i)
    pts.push_back({rng.uniform<T>(T(-extent), T(extent)), rng.uniform<T>(T(-extent), T(extent))});
  const int near = std::max(1, 600 / std::max(1, int(segs.size())));
  for (const auto& s : segs)
    for (int i = 0; i < near; ++i) {
      const double r = d + tol * rng.uniform(-3.0, 1.0), a = rng.uniform(0.0, 2 * std::numbers::pi);
      pts.push_back({T(double(s[0]) + r * std::cos(a)), T(double(s[1]) + r * std::sin(a))});
    }
  int decided = 0;
  for (const Vec2<T>& p : pts) {
    const bool in_region = inside(region, p);
    const double dist = double(distance(segs, p));
    int expect = -1;  // undecided within the tolerance band
    if (delta > 0) {
      if (in_region || dist < d - tol - slack) expect = 1;
      if (!in_region && dist > d + slack) expect = 0;
    } else {
      if (!in_region || dist < d - tol - slack) expect = 0;
      if (in_region && dist > d + slack) expect = 1;
    }
    if (expect < 0) continue;
    ++decided;
    EXPECT_EQ(inside(res.polygons, p), expect == 1)
        << "point (" << double(p.x) << ", " << double(p.y) << ") distance " << dist;
  }
  return decided;
}

TYPED_TEST(PolygonOffsetTest, RoundJoinsMatchMinkowskiSumWithDisc) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int decided = 0;
  for (int trial = 0; trial < 24; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const MultiPolygon2<T> region = random_region<T>(rng);
    const T delta = T(rng.uniform(0.02, 0.3) * (trial % 2 ? -1 : 1));
    OffsetOptions o;
    o.join = JoinType::round;
    o.arc_tolerance = std::abs(double(delta)) * rng.uniform(0.002, 0.05);
    const auto res = locus::offset(region, delta, o);
    decided += check_round(region, boundary(region), delta, o.arc_tolerance, res, rng, 150, 1.4);
  }
  EXPECT_GT(decided, 24 * 140);
}

TYPED_TEST(PolygonOffsetTest, DenseWavyRingMatchesMinkowskiSum) {
  // Edges much shorter than |delta|, and concave runs of curvature radius 0.25 below |delta| on
  // inflation, where the offset edges fold over each other.
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 5);
  SCOPED_TRACE(rng.trace());
  Polygon2<T> wavy;
  const int n = 160;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n, r = 1 + 0.1 * std::sin(7 * t);
    wavy.vertices.push_back({T(r * std::cos(t)), T(r * std::sin(t))});
  }
  const MultiPolygon2<T> region{{wavy, {}}};
  for (const T delta : {T(0.35), T(-0.3)}) {
    OffsetOptions o;
    o.arc_tolerance = 0.002;
    const auto res = locus::offset(region, delta, o);
    check_round(region, boundary(region), delta, o.arc_tolerance, res, rng, 60, 1.5);
  }
}

TYPED_TEST(PolygonOffsetTest, RoundBufferOfPolylinesMatchesDistance) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 1);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 16; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    Polyline<T, 2> path;
    const int n = rng.uniform_int(1, 7);
    for (int i = 0; i < n; ++i) path.vertices.push_back(rng.vec<T, 2>(T(-0.8), T(0.8)));
    path.closed = trial % 4 == 3;
    const T delta = T(rng.uniform(0.03, 0.25));
    OffsetOptions o;
    o.arc_tolerance = double(delta) * 0.01;
    const auto res = locus::offset_polyline(path, delta, o);
    Segs segs;
    add_chain(segs, path.vertices, path.closed);
    // The set within delta of the path: as the inflation of an empty region.
    check_round(MultiPolygon2<T>{}, segs, delta, o.arc_tolerance, res, rng, 150, 1.2);
  }
}

/// Every output vertex at distance in [|delta| - slack, bound |delta| + slack] of the input.
template <class T>
void check_vertex_distances(const Segs& segs, T delta, double bound,
                            const locus::OffsetResult<T>& res) {
  EXPECT_EQ(res.status, locus::Status::ok) << res.message;
  EXPECT_EQ(locus_test::polygon_validity(res.polygons), "");
  const double slack = 4 * res.grid + 1e-12, d = std::abs(double(delta));
  for (const auto& p : res.polygons)
    for (std::size_t k = 0; k <= p.holes.size(); ++k)
      for (const auto& v : k == 0 ? p.outer.vertices : p.holes[k - 1].vertices) {
        const double dist = double(distance(segs, v));
        EXPECT_GE(dist, d - slack) << double(v.x) << ", " << double(v.y);
        EXPECT_LE(dist, bound * d + slack) << double(v.x) << ", " << double(v.y);
      }
}

TYPED_TEST(PolygonOffsetTest, MiterAndSquareVerticesWithinTheirBounds) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 2);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 24; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const MultiPolygon2<T> region = random_region<T>(rng);
    const T delta = T(rng.uniform(0.02, 0.3) * (trial % 2 ? -1 : 1));
    OffsetOptions o;
    o.join = trial % 4 < 2 ? JoinType::miter : JoinType::square;
    o.miter_limit = rng.uniform(1.0, 4.0);
    const double bound =
        o.join == JoinType::miter ? std::max(o.miter_limit, std::sqrt(2.0)) : std::sqrt(2.0);
    const auto res = locus::offset(region, delta, o);
    const Segs segs = boundary(region);
    check_vertex_distances(segs, delta, bound, res);
    // It contains the round offset's sure points and nothing beyond the bound.
    const double d = std::abs(double(delta)), slack = 4 * res.grid + 1e-12;
    for (int i = 0; i < 100; ++i) {
      const Vec2<T> p{rng.uniform<T>(T(-1.6), T(1.6)), rng.uniform<T>(T(-1.6), T(1.6))};
      const bool in_region = inside(region, p);
      const double dist = double(distance(segs, p));
      const bool got = inside(res.polygons, p);
      const bool near = dist<d - slack, far = dist> bound * d + slack;
      const bool sure_in = delta > 0 ? in_region || near : in_region && far;
      const bool sure_out = delta > 0 ? !in_region && far : !in_region || near;
      EXPECT_TRUE(!sure_in || got) << double(p.x) << ", " << double(p.y);
      EXPECT_TRUE(!sure_out || !got) << double(p.x) << ", " << double(p.y);
    }
  }
}

TYPED_TEST(PolygonOffsetTest, SquareAreasMatchClosedForms) {
  using T = TypeParam;
  const T s = 3, d = T(0.5);
  const double pi = std::numbers::pi;
  const double ds = double(d), ss = double(s);
  const double tol_rel = std::is_same_v<T, float> ? 1e-6 : 1e-12;
  OffsetOptions o;
  o.arc_tolerance = 1e-4;
  // Round: s^2 + 4 s d + pi d^2, the arcs inscribed with gap <= tol: area short by at most the
  // perimeter of the disc times tol.
  const auto round = locus::offset(square(s), d, o);
  EXPECT_EQ(locus_test::polygon_validity(round.polygons), "");
  const double exact_round = ss * ss + 4 * ss * ds + pi * ds * ds;
  EXPECT_LE(area(round), exact_round * (1 + tol_rel));
  EXPECT_GE(area(round), exact_round - 2 * pi * ds * o.arc_tolerance - exact_round * tol_rel);
  o.join = JoinType::miter;
  const auto miter = locus::offset(square(s), d, o);
  EXPECT_NEAR(area(miter), (ss + 2 * ds) * (ss + 2 * ds), 1e-12);
  ASSERT_EQ(miter.polygons.size(), 1u);
  EXPECT_EQ(miter.polygons[0].outer.vertices.size(), 4u);
  // Miter limit below sqrt(2) at right angles: squared at distance d along the bisector.
  o.miter_limit = 1.2;
  const auto squared = locus::offset(square(s), d, o);
  o.join = JoinType::square;
  const auto sq = locus::offset(square(s), d, o);
  const double cut = (std::sqrt(2.0) - 1) * ds;
  EXPECT_NEAR(area(sq), (ss + 2 * ds) * (ss + 2 * ds) - 4 * cut * cut, 1e-5);
  EXPECT_EQ(area(sq), area(squared));
  EXPECT_EQ(sq.polygons[0].outer.vertices.size(), 8u);
  // Deflating a convex polygon gives sharp corners for every join.
  for (const JoinType j : {JoinType::round, JoinType::miter, JoinType::square}) {
    o.join = j;
    const auto in = locus::offset(square(s), -d, o);
    EXPECT_NEAR(area(in), (ss - 2 * ds) * (ss - 2 * ds), 1e-12);
    // A square of side s vanishes once |delta| >= s / 2.
    EXPECT_TRUE(locus::offset(square(s), -s / 2, o).polygons.empty());
    EXPECT_EQ(locus::offset(square(s), -s, o).status, locus::Status::ok);
  }
}

TYPED_TEST(PolygonOffsetTest, PolylineEndTypesAreas) {
  using T = TypeParam;
  const Polyline<T, 2> seg{{{0, 0}, {4, 0}}, false};
  const double pi = std::numbers::pi, d = 0.5, len = 4;
  OffsetOptions o;
  o.arc_tolerance = 1e-4;
  const auto round = locus::offset_polyline(seg, T(d), o);
  const double exact = 2 * d * len + pi * d * d;
  EXPECT_LE(area(round), exact + 1e-5);
  EXPECT_GE(area(round), exact - 2 * pi * d * o.arc_tolerance - 1e-5);
  o.end = EndType::square;
  EXPECT_NEAR(area(locus::offset_polyline(seg, T(d), o)), 2 * d * (len + 2 * d), 1e-12);
  o.end = EndType::butt;
  EXPECT_NEAR(area(locus::offset_polyline(seg, T(-d), o)), 2 * d * len, 1e-12);
  // A single point: a square with square caps, nothing with butt caps.
  const Polyline<T, 2> point{{{1, 1}}, false};
  EXPECT_TRUE(locus::offset_polyline(point, T(d), o).polygons.empty());
  o.end = EndType::square;
  EXPECT_NEAR(area(locus::offset_polyline(point, T(d), o)), 4 * d * d, 1e-12);
  // A closed L-shaped path with miter joins: the frame between two squares.
  const Polyline<T, 2> loop{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, true};
  o.join = JoinType::miter;
  const auto frame = locus::offset_polyline(loop, T(d), o);
  EXPECT_EQ(locus_test::polygon_validity(frame.polygons), "");
  ASSERT_EQ(frame.polygons.size(), 1u);
  EXPECT_EQ(frame.polygons[0].holes.size(), 1u);
  EXPECT_NEAR(area(frame), 25.0 - 9.0, 1e-12);
}

TYPED_TEST(PolygonOffsetTest, HolesCloseOnInflateAndRegionsVanishOnDeflate) {
  using T = TypeParam;
  // A 10 x 10 square with a 2 x 2 hole.
  PolygonWithHoles2<T> p{square(T(10)), {{{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}}};
  OffsetOptions o;
  o.join = JoinType::miter;
  const auto small = locus::offset(p, T(0.5), o);
  ASSERT_EQ(small.polygons.size(), 1u);
  ASSERT_EQ(small.polygons[0].holes.size(), 1u);
  EXPECT_NEAR(area(small), 11 * 11 - 1, 1e-12);  // the hole shrinks to 1 x 1
  const auto closed = locus::offset(p, T(1), o);
  ASSERT_EQ(closed.polygons.size(), 1u);
  EXPECT_TRUE(closed.polygons[0].holes.empty());
  EXPECT_NEAR(area(closed), 12 * 12, 1e-12);
  const auto thin = locus::offset(p, T(-1), o);  // the hole grows to 4 x 4
  EXPECT_EQ(locus_test::polygon_validity(thin.polygons), "");
  EXPECT_NEAR(area(thin), 8 * 8 - 4 * 4, 1e-12);
  // The frame is 4 wide: deflating by 2 or more leaves nothing.
  const auto gone = locus::offset(p, T(-2), o);
  EXPECT_EQ(gone.status, locus::Status::ok);
  EXPECT_TRUE(gone.polygons.empty());
  // Two squares 1 apart merge when inflated by 0.5 or more, and a dumbbell splits on deflate.
  MultiPolygon2<T> two{{square(T(2)), {}}, {{{{3, 0}, {5, 0}, {5, 2}, {3, 2}}}, {}}};
  EXPECT_EQ(locus::offset(two, T(0.4), o).polygons.size(), 2u);
  EXPECT_EQ(locus::offset(two, T(0.6), o).polygons.size(), 1u);
  const Polygon2<T> dumbbell{{{0, 0},
                              {3, 0},
                              {3, 1},
                              {4, 1},
                              {4, 0},
                              {7, 0},
                              {7, 3},
                              {4, 3},
                              {4, 2},
                              {3, 2},
                              {3, 3},
                              {0, 3}}};
  const auto split = locus::offset(dumbbell, T(-0.6), o);
  EXPECT_EQ(locus_test::polygon_validity(split.polygons), "");
  EXPECT_EQ(split.polygons.size(), 2u);
  EXPECT_NEAR(area(split), 2 * 1.8 * 1.8, 1e-5);
}

TYPED_TEST(PolygonOffsetTest, DegenerateVerticesGiveTheSameResult) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 3);
  SCOPED_TRACE(rng.trace());
  const Polygon2<T> clean{{{0, 0}, {4, 0}, {4, 3}, {2, 1}, {0, 3}}};
  // Repeated points, a closing duplicate, zero-length edges and collinear runs.
  const Polygon2<T> messy{{{0, 0},
                           {1, 0},
                           {1, 0},
                           {2, 0},
                           {4, 0},
                           {4, 1.5},
                           {4, 3},
                           {4, 3},
                           {2, 1},
                           {1, 2},
                           {0, 3},
                           {0, 1},
                           {0, 0}}};
  for (const JoinType j : {JoinType::round, JoinType::miter, JoinType::square})
    for (const T delta : {T(0.3), T(-0.3)}) {
      OffsetOptions o;
      o.join = j;
      const auto a = locus::offset(clean, delta, o);
      const auto b = locus::offset(messy, delta, o);
      EXPECT_EQ(locus_test::polygon_validity(a.polygons), "");
      EXPECT_EQ(locus_test::exact_area(a.polygons), locus_test::exact_area(b.polygons));
      EXPECT_GT(area(a), 0.0);
    }
  // delta 0: the region as the boolean engine resolves it.
  const auto zero = locus::offset(clean, T(0));
  EXPECT_EQ(zero.status, locus::Status::ok);
  EXPECT_EQ(locus_test::exact_area(zero.polygons),
            locus_test::exact_area(locus::boolean_union(clean, MultiPolygon2<T>{}).polygons));
  // Empty input, empty rings, an empty path.
  EXPECT_TRUE(locus::offset(MultiPolygon2<T>{}, T(1)).polygons.empty());
  EXPECT_EQ(locus::offset(Polygon2<T>{}, T(1)).status, locus::Status::ok);
  EXPECT_TRUE(locus::offset_polyline(Polyline<T, 2>{}, T(1)).polygons.empty());
  // A zero-area ring encloses no region: nothing to inflate.
  const Polygon2<T> flat{{{0, 0}, {2, 0}, {1, 0}}};
  OffsetOptions o;
  o.join = JoinType::miter;
  EXPECT_TRUE(locus::offset(flat, T(1), o).polygons.empty());
}

TYPED_TEST(PolygonOffsetTest, NonFiniteAndInvalidOptionsGiveStatus) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  EXPECT_EQ(locus::offset(square(T(1)), nan).status, locus::Status::non_finite_input);
  EXPECT_EQ(locus::offset(square(T(1)), inf).status, locus::Status::non_finite_input);
  Polygon2<T> bad = square(T(1));
  bad.vertices[2].x = nan;
  EXPECT_EQ(locus::offset(bad, T(1)).status, locus::Status::non_finite_input);
  EXPECT_TRUE(locus::offset(bad, T(1)).polygons.empty());
  const Polyline<T, 2> path{{{0, 0}, {inf, 1}}, false};
  EXPECT_EQ(locus::offset_polyline(path, T(1)).status, locus::Status::non_finite_input);
  OffsetOptions o;
  o.miter_limit = 0.5;
  EXPECT_EQ(locus::offset(square(T(1)), T(1), o).status, locus::Status::invalid_input);
  o = {};
  o.arc_tolerance = double(nan);
  EXPECT_EQ(locus::offset(square(T(1)), T(1), o).status, locus::Status::invalid_input);
  o = {};
  o.grid_bits = 41;
  EXPECT_EQ(locus::offset(square(T(1)), T(1), o).status, locus::Status::invalid_input);
  // Offsetting past the largest finite value.
  const T big = std::numeric_limits<T>::max() / 2;
  EXPECT_EQ(locus::offset(square(big), big * T(1.5)).status, locus::Status::non_finite_input);
}

TYPED_TEST(PolygonOffsetTest, PowerOfTwoScaleCovariance) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 4);
  SCOPED_TRACE(rng.trace());
  const MultiPolygon2<T> region = random_region<T>(rng);
  for (const JoinType j : {JoinType::round, JoinType::miter, JoinType::square})
    for (const T delta : {T(0.15), T(-0.1)}) {
      OffsetOptions o;
      o.join = j;
      o.arc_tolerance = 0;  // relative: |delta| / 1000
      const auto run = [&](int k) {
        MultiPolygon2<T> m = region;
        for (auto& p : m) {
          p.outer.vertices = locus_test::scaled(p.outer.vertices, k);
          for (auto& h : p.holes) h.vertices = locus_test::scaled(h.vertices, k);
        }
        const auto r = locus::offset(m, T(std::ldexp(delta, k)), o);
        std::vector<locus_test::Covariant> out{
            {"status", double(int(r.status)), 0},
            {"polygons", double(r.polygons.size()), 0},
            {"area", locus_test::exact_area(r.polygons).get_d(), 2}};
        if (!r.polygons.empty()) {
          out.push_back({"vertices", double(r.polygons[0].outer.vertices.size()), 0});
          locus_test::add(out, "v0", r.polygons[0].outer.vertices[0], 1);
        }
        return out;
      };
      locus_test::expect_scale_covariant(run, locus_test::covariant_exponents<T>(2));
    }
}

// The spoke shortcut (a concave corner's spoke p1 -> v -> p2 replaced by p1 -> p2 when the
// triangle p1, v, p2 lies in both adjacent bands) keeps the positive-winding set, so the
// boolean's output must be identical, ring for ring, to the construction keeping every spoke
// (detail::offset_keeping_spokes; docs/notes/polygon_offset.md, "Dropping spokes").
template <class T>
void expect_same_result(const locus::OffsetResult<T>& got, const locus::OffsetResult<T>& want) {
  ASSERT_EQ(got.status, want.status) << got.message;
  EXPECT_EQ(locus_test::polygon_validity(got.polygons), "");
  ASSERT_EQ(got.polygons.size(), want.polygons.size());
  for (std::size_t i = 0; i < got.polygons.size(); ++i) {
    const auto &g = got.polygons[i], &w = want.polygons[i];
    EXPECT_TRUE(g.outer.vertices == w.outer.vertices) << "polygon " << i << " outer ring";
    ASSERT_EQ(g.holes.size(), w.holes.size()) << "polygon " << i;
    for (std::size_t k = 0; k < g.holes.size(); ++k)
      EXPECT_TRUE(g.holes[k].vertices == w.holes[k].vertices) << "polygon " << i << " hole " << k;
  }
}
template <class T>
void expect_shortcut_exact(const MultiPolygon2<T>& region, T delta, const OffsetOptions& o) {
  SCOPED_TRACE("delta " + std::to_string(double(delta)));
  expect_same_result(locus::offset(region, delta, o),
                     locus::detail::offset_keeping_spokes(region, delta, o));
}
template <class T>
void expect_shortcut_exact(const std::vector<Polyline<T, 2>>& paths, T delta,
                           const OffsetOptions& o) {
  SCOPED_TRACE("delta " + std::to_string(double(delta)));
  expect_same_result(locus::offset_polylines(paths, delta, o),
                     locus::detail::offset_polylines_keeping_spokes(
                         std::span<const Polyline<T, 2>>(paths), delta, o));
}
OffsetOptions with_join(int k) {
  OffsetOptions o;
  o.join = k % 3 == 0 ? JoinType::miter : k % 3 == 1 ? JoinType::square : JoinType::round;
  o.arc_tolerance = 0.01;
  return o;
}

TYPED_TEST(PolygonOffsetTest, SpokeShortcutKeepsRandomRegionsExactly) {
  // Concave corners with edges longer and shorter than |delta|, on both sides (deflation's
  // concave corners are the region's convex ones), holes included.
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 6);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 24; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const MultiPolygon2<T> region = random_region<T>(rng);
    const T delta = T(std::exp(rng.uniform(std::log(0.005), std::log(0.6))) * (trial % 2 ? -1 : 1));
    expect_shortcut_exact(region, delta, with_join(trial / 2));
  }
}

TYPED_TEST(PolygonOffsetTest, SpokeShortcutKeepsDenseAndSpikyRingsExactly) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 7);
  SCOPED_TRACE(rng.trace());
  // Edges far shorter than |delta| (the benchmark's ring, 200 vertices: edges about 0.03),
  // including concave runs of curvature radius below |delta|.
  Polygon2<T> wavy;
  for (int i = 0; i < 200; ++i) {
    const double t = 2 * std::numbers::pi * i / 200, r = 1 + 0.1 * std::sin(7 * t);
    wavy.vertices.push_back({T(r * std::cos(t)), T(r * std::sin(t))});
  }
  for (const T delta : {T(0.004), T(0.03), T(0.3), T(-0.004), T(-0.05)})
    expect_shortcut_exact(MultiPolygon2<T>{{wavy, {}}}, delta, with_join(0));
  // Deep narrow notches (spikes into the region) and thin teeth: sharp concave corners whose
  // edges are long next to short ones.
  for (int trial = 0; trial < 6; ++trial) {
    SCOPED_TRACE("star " + std::to_string(trial));
    const Polygon2<T> star = random_star<T>(rng, 0, 0, 0.05, 1.0, rng.uniform_int(12, 30));
    const T delta = T(rng.uniform(0.01, 0.2) * (trial % 2 ? -1 : 1));
    expect_shortcut_exact(MultiPolygon2<T>{{star, {}}}, delta, with_join(trial));
  }
  // A square with a notch of width 2^-12 down its middle.
  const T w = T(std::ldexp(1.0, -13));
  const Polygon2<T> notched{{{0, 0},
                             {T(0.5) - w, 0},
                             {T(0.5) - w, T(0.9)},
                             {T(0.5) + w, T(0.9)},
                             {T(0.5) + w, 0},
                             {1, 0},
                             {1, 1},
                             {0, 1}}};
  int j = 0;
  for (const T delta : {T(w / 2), T(w), T(0.01), T(-0.01), T(-w)})
    expect_shortcut_exact(MultiPolygon2<T>{{notched, {}}}, delta, with_join(j++));
}

TYPED_TEST(PolygonOffsetTest, SpokeShortcutKeepsNearlyStraightConcaveCornersExactly) {
  // A square whose bottom side bows inward along a circle of radius R through m vertices: turning
  // angles about 1 / (R m), from 2^-10 down to about 2^-20 radians, with |delta| above and below
  // the edge length.
  using T = TypeParam;
  for (const double radius : {4.0, 64.0, 1024.0})
    for (const int m : {8, 64}) {
      SCOPED_TRACE("radius " + std::to_string(radius) + ", " + std::to_string(m) + " edges");
      Polygon2<T> p;
      const double half = 0.5, depth = radius - std::sqrt(radius * radius - half * half);
      for (int i = 0; i <= m; ++i) {
        const double x = -half + 2 * half * i / m;
        p.vertices.push_back({T(x), T(std::sqrt(radius * radius - x * x) - radius + depth)});
      }
      p.vertices.push_back({T(half), T(1)});
      p.vertices.push_back({T(-half), T(1)});
      int j = m;
      for (const T delta : {T(0.001), T(0.05), T(0.4), T(-0.001), T(-0.05)})
        expect_shortcut_exact(MultiPolygon2<T>{{p, {}}}, delta, with_join(j++));
    }
}

TYPED_TEST(PolygonOffsetTest, SpokeShortcutEqualityCases) {
  // The exact condition's boundary: at a right-angle concave corner with both edges of length 1,
  // p2 = v + d n2 lies on band 1's end edge exactly when d = 1 (inside for d < 1, outside for
  // d > 1). Inflation: the reflex corner (1, 1) of an L. Deflation: the convex corners (4, 0) and
  // (5, 1) of a stepped rectangle, whose step edges have length 1.
  using T = TypeParam;
  const Polygon2<T> ell{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  const Polygon2<T> step{{{0, 0}, {4, 0}, {4, 1}, {5, 1}, {5, 4}, {0, 4}}};
  const T eps = T(std::ldexp(1.0, -20));
  for (int j = 0; j < 3; ++j)
    for (const T d : {T(1) - eps, T(1), T(1) + eps, T(0.5), T(2)}) {
      SCOPED_TRACE("join " + std::to_string(j));
      expect_shortcut_exact(MultiPolygon2<T>{{ell, {}}}, d, with_join(j));
      expect_shortcut_exact(MultiPolygon2<T>{{step, {}}}, T(-d), with_join(j));
    }
  // Holes whose every corner is concave on the offset side (a square, an equilateral-ish
  // triangle): a point in the triangles of all dropped corners must keep its cover, so one spoke
  // per ring stays.
  const Polygon2<T> square_hole{{{1, 1}, {1, 3}, {3, 3}, {3, 1}}};
  const Polygon2<T> triangle_hole{{{1, 1}, {2, T(2.75)}, {3, 1}}};
  for (const Polygon2<T>* hole : {&square_hole, &triangle_hole})
    for (int j = 0; j < 3; ++j)
      for (const T d : {T(0.3), T(0.5) - eps, T(0.5), T(0.6), T(1) - eps, T(1), T(1) + eps}) {
        SCOPED_TRACE("hole, join " + std::to_string(j));
        expect_shortcut_exact(MultiPolygon2<T>{{square(T(4)), {*hole}}}, d, with_join(j));
      }
  // The areas at d = 1 from the closed form: the L (area 3) with miter joins grows to the
  // 4 x 4 square minus the unit square at its reflex corner: 15.
  OffsetOptions o;
  o.join = JoinType::miter;
  EXPECT_EQ(area(locus::offset(ell, T(1), o)), 15.0);
}

TYPED_TEST(PolygonOffsetTest, SpokeShortcutKeepsPolylinesExactly) {
  // Zigzags turn concave on each side in turn; the spikes at open ends and back-tracking
  // vertices keep their joins.
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 8);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 18; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    std::vector<Polyline<T, 2>> paths(1 + trial % 2);
    for (auto& path : paths) {
      const int n = rng.uniform_int(2, 12);
      for (int i = 0; i < n; ++i) path.vertices.push_back(rng.vec<T, 2>(T(-0.8), T(0.8)));
      path.closed = trial % 3 == 2;
    }
    if (trial % 5 == 4) paths[0].vertices.push_back(paths[0].vertices[0]);  // a spike back
    OffsetOptions o = with_join(trial);
    o.end = trial % 3 == 0 ? EndType::round : trial % 3 == 1 ? EndType::square : EndType::butt;
    expect_shortcut_exact(paths, T(std::exp(rng.uniform(std::log(0.005), std::log(0.4)))), o);
  }
}

}  // namespace
