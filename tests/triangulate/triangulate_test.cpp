// SPDX-License-Identifier: BSL-1.0
// Ear clipping and monotone triangulation: exact oracle checks (triangulation_check.hpp) on
// seeded polygons with holes, degenerate and bad input, scale covariance; float and double.

#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>
#include <locus/triangulate/polygon_triangulation.hpp>
#include <locus/triangulate/trapezoid_decomposition.hpp>

#include "polygons.hpp"
#include "support/sanitizer.hpp"
#include "support/scale_covariance.hpp"
#include "support/typed.hpp"
#include "triangulation_check.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace {

using locus::Status;
using locus::Vec2;
using locus_test::Method;
using locus_test::Polygon;

template <class T>
class Triangulate : public ::testing::Test {};
TYPED_TEST_SUITE(Triangulate, locus_test::RealTypes);

constexpr Method kMethods[] = {Method::ear_clipping, Method::monotone};

template <class T>
void expect_valid(const Polygon<T>& p, Method m, std::size_t expected_count = 0) {
  SCOPED_TRACE(locus_test::method_name(m));
  const auto r = locus_test::triangulate(m, p);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(locus_test::check_triangulation<T>(p.points, p.ends, r.triangles), "");
  if (expected_count) {
    EXPECT_EQ(r.triangles.size(), expected_count);
  }
}

TYPED_TEST(Triangulate, ConvexAndSimpleShapes) {
  using T = TypeParam;
  Polygon<T> square;
  square.add_ring({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  Polygon<T> cw_l;  // an L, clockwise
  cw_l.add_ring({{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}});
  Polygon<T> framed;  // a square with a square hole: 8 vertices, 1 hole -> 8 triangles
  framed.add_ring({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  framed.add_ring({{1, 1}, {3, 1}, {3, 3}, {1, 3}});
  for (const Method m : kMethods) {
    expect_valid(square, m, 2);
    expect_valid(cw_l, m, 4);
    expect_valid(framed, m, 8);
  }
}

TYPED_TEST(Triangulate, RandomStarsWithHoles) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 40; ++trial) {
    const int n = rng.uniform_int(3, 300);
    const int holes = rng.uniform_int(0, 6);
    const auto p = locus_test::star_polygon<T>(rng, n, 0.6, 1.0, holes);
    // The sanitizer build (-O0) checks every 4th trial, the same draws (all 40 took 5.5 s of CPU
    // per type there, most of it in the exact checker; 10 take 1.9 s); the optimised run checks
    // all 40, and the other tests here run both methods on combs, fixtures and holes too.
    if (locus_test::kSanitizerBuild && trial % 4 != 0) continue;
    SCOPED_TRACE("trial " + std::to_string(trial));
    // A polygon with n vertices (all rings) and h holes has n + 2h - 2 triangles when every
    // vertex is used (monotone keeps all; ear clipping may drop the middle of straight runs).
    const std::size_t count = p.points.size() + 2 * std::size_t(holes) - 2;
    for (const Method m : kMethods) {
      const auto r = locus_test::triangulate(m, p);
      EXPECT_EQ(r.status, Status::ok) << locus_test::method_name(m);
      EXPECT_EQ(locus_test::check_triangulation<T>(p.points, p.ends, r.triangles), "")
          << locus_test::method_name(m);
      if (m == Method::monotone) {
        EXPECT_EQ(r.triangles.size(), count);
      }
      EXPECT_LE(r.triangles.size(), count);
    }
  }
}

TYPED_TEST(Triangulate, CombsManyReflexVertices) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (const int teeth : {1, 5, 50, 150}) {
    const auto p = locus_test::comb_polygon<T>(rng, teeth);
    for (const Method m : kMethods) expect_valid(p, m);
  }
}

TYPED_TEST(Triangulate, DegenerateInputGivesValidTriangles) {
  using T = TypeParam;
  // Repeated consecutive points, a closing duplicate, a straight run, a zero-area spike.
  Polygon<T> p;
  p.add_ring({{0, 0},
              {0, 0},
              {1, 0},
              {2, 0},
              {3, 0},
              {3, 0},
              {3, 2},
              {3, 3},
              {2, 3},
              {2, 5},
              {2, 3},
              {0, 3},
              {0, 0}});
  for (const Method m : kMethods) expect_valid(p, m);
  // A hole touching the outer ring at a vertex (ear clipping: zero-length bridge).
  Polygon<T> touch;
  touch.add_ring({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  touch.add_ring({{0, 0}, {2, 1}, {1, 2}});
  expect_valid(touch, Method::ear_clipping);
  // Two holes touching each other at a vertex.
  Polygon<T> two;
  two.add_ring({{0, 0}, {6, 0}, {6, 6}, {0, 6}});
  two.add_ring({{1, 1}, {3, 1}, {3, 3}, {1, 3}});
  two.add_ring({{3, 3}, {5, 3}, {5, 5}, {3, 5}});
  expect_valid(two, Method::ear_clipping);
  // A collinear reflex vertex on a would-be diagonal must block the ear.
  Polygon<T> blocked;
  blocked.add_ring({{0, 0}, {4, 0}, {2, 1}, {4, 2}, {0, 2}});
  for (const Method m : kMethods) expect_valid(blocked, m, 3);
}

TYPED_TEST(Triangulate, BadInputStatus) {
  using T = TypeParam;
  for (const Method m : kMethods) {
    SCOPED_TRACE(locus_test::method_name(m));
    Polygon<T> empty;
    EXPECT_EQ(locus_test::triangulate(m, empty).status, Status::empty_input);
    Polygon<T> nan;
    nan.add_ring({{0, 0}, {1, 0}, {std::numeric_limits<T>::quiet_NaN(), 1}});
    EXPECT_EQ(locus_test::triangulate(m, nan).status, Status::non_finite_input);
    Polygon<T> inf;
    inf.add_ring({{0, 0}, {std::numeric_limits<T>::infinity(), 0}, {0, 1}, {-1, 1}});
    EXPECT_EQ(locus_test::triangulate(m, inf).status, Status::non_finite_input);
    Polygon<T> line;
    line.add_ring({{0, 0}, {1, 1}, {2, 2}, {1, 1}});
    const auto r = locus_test::triangulate(m, line);
    EXPECT_EQ(r.status, Status::degenerate_input);
    EXPECT_TRUE(r.triangles.empty());
    Polygon<T> bad_ends = line;
    bad_ends.ends = {7};
    EXPECT_EQ(locus_test::triangulate(m, bad_ends).status, Status::invalid_input);
    // A zero-area hole is dropped; the outer ring is still triangulated.
    Polygon<T> flat_hole;
    flat_hole.add_ring({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
    flat_hole.add_ring({{1, 1}, {2, 2}, {3, 3}});
    const auto f = locus_test::triangulate(m, flat_hole);
    EXPECT_EQ(f.status, Status::ok);
    EXPECT_EQ(f.triangles.size(), 2u);
  }
}

TYPED_TEST(Triangulate, SelfIntersectionTerminatesInRange) {
  using T = TypeParam;
  // A bow tie and a hole crossing the outer ring: terminate, stay in range; a status other
  // than ok, or a valid triangulation of what was given, never garbage labelled ok.
  Polygon<T> bow;
  bow.add_ring({{0, 0}, {2, 2}, {2, 0}, {0, 2}});
  Polygon<T> crossing;
  crossing.add_ring({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  crossing.add_ring({{3, 1}, {6, 1}, {6, 3}, {3, 3}});
  for (const Method m : kMethods)
    for (const auto* p : {&bow, &crossing}) {
      const auto r = locus_test::triangulate(m, *p);
      for (const auto& t : r.triangles)
        for (const auto v : t) EXPECT_LT(v, p->points.size());
      if (r.status == Status::ok) {
        EXPECT_EQ(locus_test::check_triangulation<T>(p->points, p->ends, r.triangles), "")
            << locus_test::method_name(m);
      }
    }
}

TYPED_TEST(Triangulate, PowerOfTwoScalingGivesTheSameTriangles) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto p = locus_test::star_polygon<T>(rng, 200, 0.5, 1.0, 3);
  for (const Method m : kMethods) {
    const auto base = locus_test::triangulate(m, p);
    ASSERT_EQ(base.status, Status::ok);
    for (const int k : locus_test::far_scale_exponents<T>()) {
      Polygon<T> q = p;
      q.points = locus_test::scaled(p.points, k);
      const auto r = locus_test::triangulate(m, q);
      EXPECT_EQ(r.status, Status::ok) << k;
      EXPECT_EQ(r.triangles, base.triangles) << locus_test::method_name(m) << " 2^" << k;
    }
  }
}

}  // namespace
