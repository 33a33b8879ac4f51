// SPDX-License-Identifier: BSL-1.0
// Polygon booleans: every output passes the independent validity checker
// (tests/support/polygon_validity.hpp); the oracle is exact point classification against the
// input (winding numbers by orient2d) away from the snapping tolerance, plus exact GMP area
// identities.

#include <locus/boolean/polygon_boolean.hpp>
#include <locus/core/predicates.hpp>

#include <support/polygon_validity.hpp>
#include <support/scale_covariance.hpp>
#include <support/typed.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <type_traits>
#include <vector>

namespace {

using locus::BooleanOp;
using locus::FillRule;
using locus::MultiPolygon2;
using locus::Polygon2;
using locus::PolygonWithHoles2;
using locus::Vec2;
using locus_test::Rng;

template <class T>
class PolygonBooleanTest : public ::testing::Test {};
TYPED_TEST_SUITE(PolygonBooleanTest, locus_test::RealTypes);

constexpr BooleanOp kOps[] = {BooleanOp::intersection, BooleanOp::union_, BooleanOp::difference,
                              BooleanOp::symmetric_difference};

bool op_of(BooleanOp op, bool a, bool b) {
  switch (op) {
    case BooleanOp::intersection:
      return a && b;
    case BooleanOp::union_:
      return a || b;
    case BooleanOp::difference:
      return a && !b;
    case BooleanOp::symmetric_difference:
      return a != b;
  }
  return false;
}

using locus_test::exact_winding;
template <class T>
bool inside_rings(const std::vector<Polygon2<T>>& rings, const Vec2<T>& p, FillRule rule) {
  int w = 0;
  for (const auto& r : rings) w += exact_winding(r.vertices, p);
  return rule == FillRule::even_odd ? (w & 1) != 0 : (rule == FillRule::non_zero ? w != 0 : w > 0);
}
/// A multipolygon operand as rings with orientation signs: inside where the winding with outer
/// rings counted CCW and holes CW is positive.
template <class T>
struct SignedRings {
  std::vector<std::pair<std::vector<Vec2<T>>, int>> rings;
  explicit SignedRings(const MultiPolygon2<T>& m) {
    for (const auto& poly : m) {
      rings.emplace_back(poly.outer.vertices,
                         locus_test::exact_twice_area(poly.outer.vertices) > 0 ? 1 : -1);
      for (const auto& h : poly.holes)
        rings.emplace_back(h.vertices, locus_test::exact_twice_area(h.vertices) < 0 ? 1 : -1);
    }
  }
  bool operator()(const Vec2<T>& p) const {
    int w = 0;
    for (const auto& r : rings) w += r.second * exact_winding(r.first, p);
    return w > 0;
  }
};
template <class T>
bool inside_result(const MultiPolygon2<T>& m, const Vec2<T>& p) {
  int w = 0;
  for (const auto& poly : m) {
    w += exact_winding(poly.outer.vertices, p);
    for (const auto& h : poly.holes) w += exact_winding(h.vertices, p);
  }
  EXPECT_TRUE(w == 0 || w == 1) << "winding " << w;
  return w == 1;
}

template <class T>
double distance_to_segment(const Vec2<T>& p, const Vec2<T>& a, const Vec2<T>& b) {
  const double dx = double(b.x) - double(a.x), dy = double(b.y) - double(a.y);
  const double px = double(p.x) - double(a.x), py = double(p.y) - double(a.y);
  const double l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp((px * dx + py * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(px - t * dx, py - t * dy);
}
template <class T>
double distance_to_rings(const std::vector<Polygon2<T>>& rings, const Vec2<T>& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& r : rings)
    for (std::size_t i = 0, n = r.vertices.size(); i < n; ++i)
      d = std::min(d, distance_to_segment(p, r.vertices[i], r.vertices[(i + 1) % n]));
  return d;
}
template <class T>
std::vector<Polygon2<T>> rings_of(const MultiPolygon2<T>& m) {
  std::vector<Polygon2<T>> r;
  for (const auto& p : m) {
    r.push_back(p.outer);
    r.insert(r.end(), p.holes.begin(), p.holes.end());
  }
  return r;
}

/// A star-shaped polygon (simple when every angle gap is below pi): sorted angles, random radii in
/// [rmin, rmax]. With spread, the angles are jittered from even spacing (gaps below 1.5 * 2 pi /
/// n).
template <class T>
Polygon2<T> random_star(Rng& rng, Vec2<double> c, double rmin, double rmax, int n,
                        bool spread = false) {
  std::vector<double> ang;
  for (int i = 0; i < n; ++i)
    ang.push_back(spread ? (i + rng.uniform(0.0, 0.5)) * 2 * std::numbers::pi / n
                         : rng.uniform(0.0, 2 * std::numbers::pi));
  std::sort(ang.begin(), ang.end());
  Polygon2<T> p;
  for (double a : ang) {
    const double r = rng.uniform(rmin, rmax);
    p.vertices.push_back({T(c.x + r * std::cos(a)), T(c.y + r * std::sin(a))});
  }
  return p;
}

template <class T>
std::vector<Vec2<T>> sample_points(Rng& rng, const std::vector<Polygon2<T>>& rings, int count,
                                   double lo, double hi) {
  std::vector<Vec2<T>> pts;
  for (int i = 0; i < count; ++i)
    pts.push_back({rng.uniform<T>(T(lo), T(hi)), rng.uniform<T>(T(lo), T(hi))});
  // Near edge midpoints, on both sides.
  for (const auto& r : rings)
    for (std::size_t i = 0, n = r.vertices.size(); i < n; ++i) {
      const auto& a = r.vertices[i];
      const auto& b = r.vertices[(i + 1) % n];
      const double mx = (double(a.x) + double(b.x)) / 2, my = (double(a.y) + double(b.y)) / 2;
      const double nx = -(double(b.y) - double(a.y)), ny = double(b.x) - double(a.x);
      const double l = std::hypot(nx, ny);
      if (l == 0) continue;
      for (double s : {-1e-4, 1e-4}) pts.push_back({T(mx + s * nx / l), T(my + s * ny / l)});
    }
  return pts;
}

/// Checks validity and the point oracle; returns the number of points compared.
template <class T, class InA, class InB>
int check_against_oracle(const locus::BooleanResult<T>& res, BooleanOp op, InA&& in_a, InB&& in_b,
                         const std::vector<Polygon2<T>>& input_rings,
                         const std::vector<Vec2<T>>& pts) {
  EXPECT_EQ(res.status, locus::Status::ok) << res.message;
  const std::string v = locus_test::polygon_validity(res.polygons);
  EXPECT_EQ(v, "");
  // Snap rounding moves an edge by less than a pixel diagonal; float input is also rounded to
  // float when sampled.
  const double tol = 4 * res.grid;
  int compared = 0;
  for (const auto& p : pts) {
    if (distance_to_rings(input_rings, p) <= tol) continue;
    ++compared;
    const bool expect = op_of(op, in_a(p), in_b(p));
    EXPECT_EQ(inside_result(res.polygons, p), expect)
        << "point (" << double(p.x) << ", " << double(p.y) << ")";
  }
  return compared;
}

TYPED_TEST(PolygonBooleanTest, RandomStarPairsMatchPointOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int compared = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const Polygon2<T> a = random_star<T>(rng, {0, 0}, 0.3, 1.0, rng.uniform_int(3, 12));
    const Polygon2<T> b = random_star<T>(rng, {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)}, 0.3,
                                         1.0, rng.uniform_int(3, 12));
    const std::vector<Polygon2<T>> rings{a, b};
    const auto pts = sample_points(rng, rings, 40, -1.6, 1.6);
    for (BooleanOp op : kOps) {
      SCOPED_TRACE("trial " + std::to_string(trial) + " op " + std::to_string(int(op)));
      const auto res = locus::boolean_op(op, locus::to_multipolygon(a), locus::to_multipolygon(b));
      compared += check_against_oracle(res, op, SignedRings<T>(locus::to_multipolygon(a)),
                                       SignedRings<T>(locus::to_multipolygon(b)), rings, pts);
    }
  }
  EXPECT_GT(compared, 12000);  // most samples are compared
}

TYPED_TEST(PolygonBooleanTest, PolygonsWithHolesAndAreaIdentities) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 1);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const auto make = [&](Vec2<double> c) {
      // Outer gaps below 67.5 degrees keep its edges beyond 0.6 cos(33.75) > 0.4 from c.
      PolygonWithHoles2<T> p{random_star<T>(rng, c, 0.6, 1.0, rng.uniform_int(8, 12), true), {}};
      Polygon2<T> h = random_star<T>(rng, c, 0.1, 0.4, rng.uniform_int(3, 8), true);
      if (rng.uniform_int(0, 1)) std::reverse(h.vertices.begin(), h.vertices.end());
      p.holes.push_back(h);
      return MultiPolygon2<T>{p};
    };
    const MultiPolygon2<T> a = make({0, 0});
    const MultiPolygon2<T> b = make({rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7)});
    std::vector<Polygon2<T>> rings = rings_of(a);
    for (const auto& r : rings_of(b)) rings.push_back(r);
    const auto pts = sample_points(rng, rings, 30, -1.8, 1.8);
    mpq_class area[4];
    for (BooleanOp op : kOps) {
      SCOPED_TRACE("op " + std::to_string(int(op)));
      const auto res = locus::boolean_op(op, a, b);
      check_against_oracle(res, op, SignedRings<T>(a), SignedRings<T>(b), rings, pts);
      area[int(op)] = locus_test::exact_area(res.polygons);
    }
    // Input areas: outer minus hole (the hole lies inside its outer ring by construction).
    const auto input_area = [](const MultiPolygon2<T>& m) {
      mpq_class s = abs(locus_test::exact_twice_area(m[0].outer.vertices));
      s -= abs(locus_test::exact_twice_area(m[0].holes[0].vertices));
      return mpq_class(s / 2);
    };
    const mpq_class area_a = input_area(a), area_b = input_area(b);
    double perimeter = 0;
    for (const auto& r : rings)
      for (std::size_t i = 0, n = r.vertices.size(); i < n; ++i)
        perimeter += std::hypot(double(r.vertices[i].x - r.vertices[(i + 1) % n].x),
                                double(r.vertices[i].y - r.vertices[(i + 1) % n].y));
    // Each output edge lies within a pixel diagonal of the exact arrangement.
    const double g = locus::boolean_union(a, b).grid;
    const mpq_class bound = mpq_class(2 * perimeter * g);
    const mpq_class i = area[0], u = area[1], d = area[2], x = area[3];
    EXPECT_LE(abs(u + i - area_a - area_b), bound);
    EXPECT_LE(abs(d + i - area_a), bound);
    EXPECT_LE(abs(x - (u - i)), 2 * bound);
  }
}

TYPED_TEST(PolygonBooleanTest, SelfIntersectingRingsUnderBothFillRules) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 2);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Polygon2<T>> sa(1), sb(1);
    for (int i = 0, n = rng.uniform_int(3, 9); i < n; ++i)
      sa[0].vertices.push_back(rng.vec<T, 2>(T(-1), T(1)));
    for (int i = 0, n = rng.uniform_int(3, 9); i < n; ++i)
      sb[0].vertices.push_back(rng.vec<T, 2>(T(-1), T(1)));
    std::vector<Polygon2<T>> rings = sa;
    rings.push_back(sb[0]);
    const auto pts = sample_points(rng, rings, 40, -1.1, 1.1);
    for (FillRule rule : {FillRule::even_odd, FillRule::non_zero})
      for (BooleanOp op : kOps) {
        SCOPED_TRACE("trial " + std::to_string(trial) + " rule " + std::to_string(int(rule)) +
                     " op " + std::to_string(int(op)));
        const auto res = locus::boolean_op<T>(op, sa, sb, {rule, 0});
        check_against_oracle(
            res, op, [&](const Vec2<T>& p) { return inside_rings(sa, p, rule); },
            [&](const Vec2<T>& p) { return inside_rings(sb, p, rule); }, rings, pts);
      }
  }
}

/// A coarse grid (grid_bits 3..7) makes snapping move almost every crossing and collapse many
/// features: the output must stay valid and agree with the input away from the snap tolerance.
TYPED_TEST(PolygonBooleanTest, CoarseGridSnappingStaysValid) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 5);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 16; ++trial) {
    std::vector<Polygon2<T>> sa(2), sb(1);
    for (auto* set : {&sa, &sb})
      for (auto& ring : *set)
        for (int i = 0, n = rng.uniform_int(3, 14); i < n; ++i)
          ring.vertices.push_back(rng.vec<T, 2>(T(-1), T(1)));
    std::vector<Polygon2<T>> rings = sa;
    rings.push_back(sb[0]);
    const auto pts = sample_points(rng, rings, 60, -1.1, 1.1);
    const int bits = rng.uniform_int(3, 7);
    const FillRule rule = trial % 2 ? FillRule::even_odd : FillRule::non_zero;
    for (BooleanOp op : kOps) {
      SCOPED_TRACE("trial " + std::to_string(trial) + " bits " + std::to_string(bits) + " op " +
                   std::to_string(int(op)));
      const auto res = locus::boolean_op<T>(op, sa, sb, {rule, bits});
      check_against_oracle(
          res, op, [&](const Vec2<T>& p) { return inside_rings(sa, p, rule); },
          [&](const Vec2<T>& p) { return inside_rings(sb, p, rule); }, rings, pts);
    }
  }
}

/// Rectangles on a small integer grid: shared collinear edges, touching vertices, overlapping
/// members. Every crossing is a grid point, so the output is exact: areas agree exactly and
/// points a hair off every boundary line classify exactly.
TYPED_TEST(PolygonBooleanTest, GridRectanglesExact) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 3);
  SCOPED_TRACE(rng.trace());
  const auto rect = [](int x0, int y0, int x1, int y1) {
    return PolygonWithHoles2<T>{
        Polygon2<T>{{{T(x0), T(y0)}, {T(x1), T(y0)}, {T(x1), T(y1)}, {T(x0), T(y1)}}}, {}};
  };
  const auto random_multi = [&]() {
    MultiPolygon2<T> m;
    for (int k = 0, n = rng.uniform_int(1, 4); k < n; ++k) {
      const int x0 = rng.uniform_int(0, 6), y0 = rng.uniform_int(0, 6);
      m.push_back(rect(x0, y0, x0 + rng.uniform_int(1, 3), y0 + rng.uniform_int(1, 3)));
    }
    return m;
  };
  std::vector<Vec2<T>> pts;
  const T eps = T(1) / T(1024);
  for (int i = 0; i <= 9; ++i)
    for (int j = 0; j <= 9; ++j) {
      pts.push_back({T(i) + T(0.5), T(j) + T(0.5)});
      for (T s : {-eps, eps}) {
        pts.push_back({T(i) + s, T(j) + T(0.5)});
        pts.push_back({T(i) + T(0.5), T(j) + s});
        pts.push_back({T(i) + s, T(j) + s});
        pts.push_back({T(i) + s, T(j) - s});
      }
    }
  for (int trial = 0; trial < 30; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const MultiPolygon2<T> a = random_multi(), b = random_multi();
    const SignedRings<T> in_a(a), in_b(b);
    mpq_class area[4];
    for (BooleanOp op : kOps) {
      const auto res = locus::boolean_op(op, a, b);
      ASSERT_EQ(res.status, locus::Status::ok);
      EXPECT_EQ(locus_test::polygon_validity(res.polygons), "") << "op " << int(op);
      for (const auto& p : pts)
        EXPECT_EQ(inside_result(res.polygons, p), op_of(op, in_a(p), in_b(p)))
            << "op " << int(op) << " point " << double(p.x) << " " << double(p.y);
      area[int(op)] = locus_test::exact_area(res.polygons);
    }
    const mpq_class area_a =
        locus_test::exact_area(locus::boolean_union(a, MultiPolygon2<T>{}).polygons);
    const mpq_class area_b =
        locus_test::exact_area(locus::boolean_union(b, MultiPolygon2<T>{}).polygons);
    EXPECT_EQ(area[1] + area[0], area_a + area_b);
    EXPECT_EQ(area[2] + area[0], area_a);
    EXPECT_EQ(area[3], area[1] - area[0]);
  }
}

template <class T>
Polygon2<T> square(T x0, T y0, T s) {
  return {{{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}}};
}

TYPED_TEST(PolygonBooleanTest, DegenerateConfigurations) {
  using T = TypeParam;
  const Polygon2<T> a = square<T>(0, 0, 2);
  // Identical operands.
  auto r = locus::boolean_union(a, a);
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].outer.vertices.size(), 4u);
  EXPECT_TRUE(locus::boolean_difference(a, a).polygons.empty());
  EXPECT_TRUE(locus::boolean_xor(a, a).polygons.empty());
  EXPECT_EQ(locus::boolean_intersection(a, a).polygons.size(), 1u);
  // Shared edge: the union is one rectangle with 4 vertices; the intersection is empty.
  r = locus::boolean_union(a, square<T>(2, 0, 2));
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].outer.vertices.size(), 4u);
  EXPECT_TRUE(locus::boolean_intersection(a, square<T>(2, 0, 2)).polygons.empty());
  // Partly shared edge.
  r = locus::boolean_union(a, square<T>(2, 1, 2));
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].outer.vertices.size(), 8u);
  // Touching at a vertex: two polygons, not one self-touching ring.
  r = locus::boolean_union(a, square<T>(2, 2, 2));
  EXPECT_EQ(r.polygons.size(), 2u);
  EXPECT_EQ(locus_test::polygon_validity(r.polygons), "");
  // A polygon inside another: the difference has a hole, the xor too.
  r = locus::boolean_difference(a, square<T>(T(0.5), T(0.5), 1));
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].holes.size(), 1u);
  EXPECT_EQ(locus_test::polygon_validity(r.polygons), "");
  // A hole touching the outer ring at a vertex stays a separate clockwise ring.
  const Polygon2<T> tri{{{0, 1}, {1, T(0.5)}, {1, T(1.5)}}};
  r = locus::boolean_difference(a, tri);
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].holes.size(), 1u);
  EXPECT_EQ(locus_test::polygon_validity(r.polygons), "");
  // A sliver: a thin triangle along the square's top edge.
  const Polygon2<T> sliver{{{-1, 2}, {3, 2}, {1, T(2.0009765625)}}};
  for (BooleanOp op : kOps) {
    r = locus::boolean_op(op, locus::to_multipolygon(a), locus::to_multipolygon(sliver));
    EXPECT_EQ(r.status, locus::Status::ok);
    EXPECT_EQ(locus_test::polygon_validity(r.polygons), "") << int(op);
  }
  EXPECT_EQ(locus::boolean_union(a, sliver).polygons.size(), 1u);
  // A crossing sliver whose crossings nearly coincide.
  const Polygon2<T> needle{{{-1, T(0.999)}, {3, T(1.001)}, {3, T(1.0011)}}};
  for (BooleanOp op : kOps) {
    r = locus::boolean_op(op, locus::to_multipolygon(a), locus::to_multipolygon(needle));
    EXPECT_EQ(locus_test::polygon_validity(r.polygons), "") << int(op);
  }
}

TYPED_TEST(PolygonBooleanTest, BadInput) {
  using T = TypeParam;
  const Polygon2<T> a = square<T>(0, 0, 2);
  // Empty operands are the empty set.
  auto r = locus::boolean_union(a, MultiPolygon2<T>{});
  EXPECT_EQ(r.status, locus::Status::ok);
  EXPECT_EQ(r.polygons.size(), 1u);
  r = locus::boolean_intersection(MultiPolygon2<T>{}, MultiPolygon2<T>{});
  EXPECT_EQ(r.status, locus::Status::ok);
  EXPECT_TRUE(r.polygons.empty());
  // NaN and infinity.
  Polygon2<T> bad = a;
  bad.vertices[1].x = std::numeric_limits<T>::quiet_NaN();
  r = locus::boolean_union(a, bad);
  EXPECT_EQ(r.status, locus::Status::non_finite_input);
  EXPECT_TRUE(r.polygons.empty());
  bad.vertices[1].x = std::numeric_limits<T>::infinity();
  EXPECT_EQ(locus::boolean_xor(bad, a).status, locus::Status::non_finite_input);
  // Zero-area and too-short rings contribute nothing; a closed (repeated) vertex is dropped.
  const Polygon2<T> flat{{{0, 0}, {1, 1}, {2, 2}}};
  r = locus::boolean_union(a, flat);
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(locus_test::exact_area(r.polygons), 4);
  Polygon2<T> closed = square<T>(1, 1, 2);
  closed.vertices.push_back(closed.vertices.front());
  r = locus::boolean_intersection(a, closed);
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(locus_test::exact_area(r.polygons), 1);
  // An inverted hole (counter-clockwise) and a clockwise outer ring are repaired.
  PolygonWithHoles2<T> ph{square<T>(0, 0, 4), {square<T>(1, 1, 2)}};
  std::reverse(ph.outer.vertices.begin(), ph.outer.vertices.end());
  r = locus::boolean_union(ph, MultiPolygon2<T>{});
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].holes.size(), 1u);
  EXPECT_EQ(locus_test::exact_area(r.polygons), 12);
  // A self-touching ring (bowtie through a vertex) under even-odd: two triangles.
  const std::vector<Polygon2<T>> bowtie{{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}};
  const auto b = locus::boolean_op<T>(BooleanOp::union_, bowtie, {}, {FillRule::even_odd, 0});
  EXPECT_EQ(b.status, locus::Status::ok);
  EXPECT_EQ(b.polygons.size(), 2u);
  EXPECT_EQ(locus_test::polygon_validity(b.polygons), "");
  EXPECT_EQ(locus_test::exact_area(b.polygons), 2);
  // Vectors of rings need no template argument; spans work too.
  const std::vector<Polygon2<T>> none;
  EXPECT_EQ(locus::boolean_op(BooleanOp::union_, bowtie, none).polygons.size(), 2u);
  EXPECT_EQ(locus::boolean_op(BooleanOp::union_, std::span<const Polygon2<T>>(bowtie),
                              std::span<const Polygon2<T>>(none))
                .polygons.size(),
            2u);
  // Near the largest finite value a vertex can snap past it: reported, never an infinity.
  const T top = std::numeric_limits<T>::max();
  const Polygon2<T> huge{{{0, 0}, {top, 0}, {top, top}}};
  const auto h = locus::boolean_union(huge, MultiPolygon2<T>{});
  if constexpr (std::is_same_v<T, double>) {  // 40-bit pixels: DBL_MAX rounds up to 2^1024
    EXPECT_EQ(h.status, locus::Status::invalid_input);
    EXPECT_TRUE(h.polygons.empty());
  } else {  // 24-bit pixels are the float grid itself at the top: nothing moves
    EXPECT_EQ(h.status, locus::Status::ok);
    EXPECT_EQ(locus_test::polygon_validity(h.polygons), "");
  }
  const Polygon2<T> large{{{0, 0}, {top / 2, 0}, {top / 2, top / 2}}};
  const auto l = locus::boolean_union(large, MultiPolygon2<T>{});
  EXPECT_EQ(l.status, locus::Status::ok);
  EXPECT_EQ(locus_test::polygon_validity(l.polygons), "");
  // grid_bits out of range.
  EXPECT_EQ(locus::boolean_union(a, a, 41).status, locus::Status::invalid_input);
  EXPECT_EQ(locus::boolean_union(a, a, -1).status, locus::Status::invalid_input);
}

TYPED_TEST(PolygonBooleanTest, NegationWithinABox) {
  using T = TypeParam;
  const Polygon2<T> a = square<T>(1, 1, 2);
  const auto r = locus::boolean_negation(a, locus::AlignedBox2<T>{{0, 0}, {4, 4}});
  ASSERT_EQ(r.status, locus::Status::ok);
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].holes.size(), 1u);
  EXPECT_EQ(locus_test::exact_area(r.polygons), 12);
}

TYPED_TEST(PolygonBooleanTest, PowerOfTwoScalingScalesTheOutput) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 4);
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 10; ++trial) {
    const Polygon2<T> a = random_star<T>(rng, {0, 0}, 0.3, 1.0, 9);
    const Polygon2<T> b = random_star<T>(rng, {0.3, 0.1}, 0.3, 1.0, 9);
    const auto base = locus::boolean_xor(a, b);
    for (int k : locus_test::scale_exponents<T>()) {
      const auto scale = [&](Polygon2<T> p) {
        for (auto& v : p.vertices) v = {std::ldexp(v.x, k), std::ldexp(v.y, k)};
        return p;
      };
      const auto scaled = locus::boolean_xor(scale(a), scale(b));
      ASSERT_EQ(scaled.polygons.size(), base.polygons.size()) << "k = " << k;
      for (std::size_t i = 0; i < base.polygons.size(); ++i) {
        EXPECT_EQ(scaled.polygons[i].outer.vertices, scale(base.polygons[i].outer).vertices);
        ASSERT_EQ(scaled.polygons[i].holes.size(), base.polygons[i].holes.size());
      }
    }
  }
}

/// Symmetric operations do not depend on the operands' order, and polygon operands not on
/// their rings' orientation or starting vertex: the outputs are identical, vertex for vertex.
TYPED_TEST(PolygonBooleanTest, OperandOrderAndRingOrientationDoNotMatter) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 6);
  SCOPED_TRACE(rng.trace());
  const auto same = [](const MultiPolygon2<T>& p, const MultiPolygon2<T>& q) {
    if (p.size() != q.size()) return false;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p[i].outer.vertices != q[i].outer.vertices || p[i].holes.size() != q[i].holes.size())
        return false;
      for (std::size_t k = 0; k < p[i].holes.size(); ++k)
        if (p[i].holes[k].vertices != q[i].holes[k].vertices) return false;
    }
    return true;
  };
  for (int trial = 0; trial < 10; ++trial) {
    const Polygon2<T> a = random_star<T>(rng, {0, 0}, 0.3, 1.0, 10, true);
    const Polygon2<T> b = random_star<T>(rng, {0.4, -0.2}, 0.3, 1.0, 10, true);
    Polygon2<T> b2 = b;
    std::reverse(b2.vertices.begin(), b2.vertices.end());
    std::rotate(b2.vertices.begin(), b2.vertices.begin() + 3, b2.vertices.end());
    for (BooleanOp op :
         {BooleanOp::intersection, BooleanOp::union_, BooleanOp::symmetric_difference}) {
      const auto ab = locus::boolean_op(op, locus::to_multipolygon(a), locus::to_multipolygon(b));
      const auto ba = locus::boolean_op(op, locus::to_multipolygon(b2), locus::to_multipolygon(a));
      EXPECT_TRUE(same(ab.polygons, ba.polygons)) << "trial " << trial << " op " << int(op);
    }
    const auto d1 = locus::boolean_difference(a, b), d2 = locus::boolean_difference(a, b2);
    EXPECT_TRUE(same(d1.polygons, d2.polygons)) << "trial " << trial;
  }
}

/// The checker itself rejects each kind of invalid output.
TYPED_TEST(PolygonBooleanTest, ValidityCheckerRejectsInvalidOutput) {
  using T = TypeParam;
  using locus_test::polygon_validity;
  const auto one = [](Polygon2<T> outer, std::vector<Polygon2<T>> holes = {}) {
    return MultiPolygon2<T>{PolygonWithHoles2<T>{std::move(outer), std::move(holes)}};
  };
  Polygon2<T> inner = square<T>(1, 1, 2);
  std::reverse(inner.vertices.begin(), inner.vertices.end());
  EXPECT_EQ(polygon_validity(one(square<T>(0, 0, 4), {inner})), "");
  EXPECT_NE(polygon_validity(one(square<T>(0, 0, 4), {square<T>(1, 1, 1)})), "");  // CCW hole
  Polygon2<T> cw = square<T>(0, 0, 4);
  std::reverse(cw.vertices.begin(), cw.vertices.end());
  EXPECT_NE(polygon_validity(one(cw)), "");
  Polygon2<T> hole = square<T>(5, 5, 1);
  std::reverse(hole.vertices.begin(), hole.vertices.end());
  EXPECT_NE(polygon_validity(one(square<T>(0, 0, 4), {hole})), "");  // hole outside
  EXPECT_NE(polygon_validity(one(Polygon2<T>{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}})), "");  // bowtie
  EXPECT_NE(polygon_validity(one(Polygon2<T>{{{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 1}}})),
            "");  // self-touching
  EXPECT_NE(polygon_validity(one(Polygon2<T>{{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {1, 0}}})), "");
  MultiPolygon2<T> two = one(square<T>(0, 0, 2));
  two.push_back({square<T>(2, 1, 2), {}});  // shares part of an edge: a vertex on an edge
  EXPECT_NE(polygon_validity(two), "");
  two[1] = {square<T>(1, 1, 2), {}};  // overlapping
  EXPECT_NE(polygon_validity(two), "");
  two[1] = {square<T>(T(0.5), T(0.5), 1), {}};  // nested without a hole
  EXPECT_NE(polygon_validity(two), "");
  two[1] = {square<T>(2, 2, 2), {}};  // touching at a shared vertex is allowed
  EXPECT_EQ(polygon_validity(two), "");
}

}  // namespace
