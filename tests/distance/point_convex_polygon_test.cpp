// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_convex_polygon.hpp (row dist2.pt-convex; book figure 6.13).
#include <locus/core/predicates.hpp>
#include <locus/distance/point_convex_polygon.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/primitives/polygon.hpp>

#include "distance/harness.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

using namespace locus;
using locus_test::Rng;
namespace dist = locus_test::dist;

namespace locus_test::dist {

// The harness's view of a filled convex polygon (a test wrapper: the library takes spans).
template <class T>
struct ConvexPoly {
  std::vector<Vec2<T>> v;
};

template <class T>
auto distance(const Vec2<T>& p, const ConvexPoly<T>& c) {
  return locus::distance_to_convex_polygon(p, std::span<const Vec2<T>>(c.v));
}
template <class T>
auto distance(const ConvexPoly<T>& c, const Vec2<T>& p) {
  return locus::swapped(distance(p, c));
}

template <class T>
struct Side<ConvexPoly<T>> {
  using P = ConvexPoly<T>;
  using Param = Vec2<T>;  // the point itself
  static constexpr int k = 2;
  static constexpr bool rotatable = true;
  static Vec2<T> map(const P& c, const T* u, T) {
    Vec2<T> centre{};
    for (const auto& x : c.v) centre += x / static_cast<T>(c.v.size());
    const T t = u[0] * static_cast<T>(c.v.size());
    const Vec2<T> b =
        point_at(locus::Polyline2<T>{c.v, true}, std::min(t, static_cast<T>(c.v.size())));
    return centre + u[1] * (b - centre);
  }
  static Vec2<T> at(const P&, const Param& x) { return x; }
  static bool param_ok(const P& c, const Param& x, T tol) {
    for (std::size_t i = 0; i < c.v.size(); ++i) {
      const Vec2<T> a = c.v[i], b = c.v[(i + 1) % c.v.size()];
      if (locus::perp_dot(b - a, x - a) < -tol * (T(1) + locus::length(b - a))) return false;
    }
    return true;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& c, const locus::Mat<T, 2, 2>& r, const Vec2<T>& t) {
    P o = c;
    for (auto& x : o.v) x = r * x + t;
    return o;
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& c, T f) {
    P o = c;
    for (auto& x : o.v) x = f * x;
    return o;
  }
};

}  // namespace locus_test::dist

template <class T>
class PointConvexPolygonTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointConvexPolygonTest, locus_test::RealTypes);

namespace {

// Counter-clockwise convex polygon: sorted angles on a random rotated ellipse; sometimes with
// collinear midpoints inserted (weakly convex).
template <class T>
std::vector<Vec2<T>> random_convex(Rng& rng, int n, T S) {
  std::vector<double> ang(static_cast<std::size_t>(n));
  for (auto& a : ang) a = rng.uniform<double>(0, 6.283185307179586);
  std::sort(ang.begin(), ang.end());
  ang.erase(std::unique(ang.begin(), ang.end()), ang.end());
  const double rx = rng.uniform<double>(0.5, double(S) / 2),
               ry = rng.uniform<double>(0.2, double(S) / 2);
  const double rot = rng.uniform<double>(0, 6.3), cx = rng.uniform<double>(-2, 2),
               cy = rng.uniform<double>(-2, 2);
  std::vector<Vec2<T>> v;
  for (const double a : ang) {
    const double x = rx * std::cos(a), y = ry * std::sin(a);
    v.push_back({T(cx + x * std::cos(rot) - y * std::sin(rot)),
                 T(cy + x * std::sin(rot) + y * std::cos(rot))});
  }
  if (v.size() >= 3 &&
      rng.uniform_int(0, 3) == 0) {  // collinear vertex on an edge (exact midpoint of
    const std::size_t i =
        static_cast<std::size_t>(rng.uniform_int(0, int(v.size()) - 1));  // a dyadic pair)
    const Vec2<T> a = v[i], b = v[(i + 1) % v.size()];
    const Vec2<T> mid = (a + b) * T(0.5);
    if (orient2d(a, mid, b) == Sign::zero && !(mid == a) && !(mid == b))
      v.insert(v.begin() + static_cast<std::ptrdiff_t>(i + 1), mid);
  }
  // The ellipse points are convex in exact arithmetic; rounding can make a nearly straight turn
  // reflex: keep the polygon only if it is convex (exact test), else retry with a triangle.
  if (v.size() < 3 || !polygon_is_convex<T>(v) || polygon_orientation<T>(v) != Sign::positive)
    return {Vec2<T>{T(-1), T(-1)}, Vec2<T>{T(2), T(-1)}, Vec2<T>{T(0), T(3)}};
  return v;
}

// Brute-force oracle: 0 if p is left of (or on) every edge (exact), else the nearest edge.
template <class T>
double brute(const Vec2<T>& p, const std::vector<Vec2<T>>& v) {
  bool inside = true;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2<T> a = v[i], b = v[(i + 1) % v.size()];
    if (orient2d(a, b, p) == Sign::negative) inside = false;
    best =
        std::min(best, double(distance(vec_cast<double>(p),
                                       Segment2<double>{vec_cast<double>(a), vec_cast<double>(b)})
                                  .distance));
  }
  return inside ? 0.0 : best;
}

}  // namespace

TYPED_TEST(PointConvexPolygonTest, HarnessAndBruteForce) {
  using T = TypeParam;
  const T S = 10;
  // The harness's compass search stalls on the kinks of the polar map above, so its agreement
  // check is replaced by the brute-force oracle below (it still checks "never worse").
  dist::Options<T> opt;
  opt.check_agreement = false;
  dist::check_pairs<T, 2, Vec2<T>, dist::ConvexPoly<T>>(
      [&](Rng& rng) {
        return std::pair{rng.vec<T, 2>(-S, S),
                         dist::ConvexPoly<T>{random_convex<T>(rng, rng.uniform_int(3, 12), S)}};
      },
      opt);
  Rng rng(locus_test::test_seed() + 71);
  SCOPED_TRACE(rng.trace());
  const double tl = std::is_same_v<T, float> ? 1e-5 : 1e-13;
  for (int n = 0; n < 600; ++n) {
    SCOPED_TRACE(n);
    const int nv = n % 10 == 0 ? rng.uniform_int(100, 400) : rng.uniform_int(3, 20);
    const auto v = random_convex<T>(rng, nv, S);
    for (int q = 0; q < 20; ++q) {
      Vec2<T> p;
      const int kind = rng.uniform_int(0, 4);
      const std::size_t i = static_cast<std::size_t>(rng.uniform_int(0, int(v.size()) - 1));
      if (kind == 0) {
        p = v[i];  // a vertex
      } else if (kind == 1) {
        p = (v[i] + v[(i + 1) % v.size()]) * T(0.5);  // (near) an edge
      } else if (kind == 2) {
        p = v[i] + rng.vec<T, 2>(T(-0.5), T(0.5));  // near a vertex
      } else {
        p = rng.vec<T, 2>(-S, S);
      }
      const auto r = distance_to_convex_polygon(p, std::span<const Vec2<T>>(v));
      ASSERT_TRUE(locus::is_finite(r.distance));
      EXPECT_NEAR(r.distance, brute(p, v), tl * S) << "kind " << kind;
      if (brute(p, v) == 0.0) {
        EXPECT_EQ(r.distance, T(0));  // exact inside decision
      }
    }
  }
}

// Integer polygons and every integer query point of a grid around them: exact collinear
// configurations (points on edge lines, on the lines through v0 and v[n-1], on fan diagonals,
// at vertices) in every region of figure 6.13.
TYPED_TEST(PointConvexPolygonTest, IntegerGridExactCases) {
  using T = TypeParam;
  using V = Vec2<T>;
  const std::vector<std::vector<V>> polys = {
      {{0, 0}, {4, 0}, {4, 4}, {0, 4}},
      {{0, 0}, {2, 0}, {4, 0}, {4, 2}, {4, 4}, {2, 4}, {0, 4}, {0, 2}},  // collinear vertices
      {{1, 0}, {3, 0}, {4, 1}, {4, 3}, {3, 4}, {1, 4}, {0, 3}, {0, 1}},  // octagon
      {{0, 0}, {6, 1}, {3, 5}},
      {{2, -3}, {5, 0}, {5, 1}, {1, 5}, {-3, 2}, {-3, 0}},
  };
  for (const auto& v : polys) {
    ASSERT_TRUE(polygon_is_convex<T>(v));
    for (int x = -6; x <= 10; ++x)
      for (int y = -6; y <= 10; ++y) {
        const V p{T(x), T(y)};
        const auto r = distance_to_convex_polygon(p, std::span<const V>(v));
        const double b = brute(p, v);
        EXPECT_NEAR(double(r.distance), b, 1e-6) << x << " " << y;
        if (b == 0.0) {
          EXPECT_EQ(r.closest[1], p);
        }
        // The result is consistent from every starting vertex (rotations of the list).
        for (std::size_t s = 1; s < v.size(); s += 2) {
          std::vector<V> w(v.begin() + static_cast<std::ptrdiff_t>(s), v.end());
          w.insert(w.end(), v.begin(), v.begin() + static_cast<std::ptrdiff_t>(s));
          EXPECT_NEAR(double(distance_to_convex_polygon(p, std::span<const V>(w)).distance), b,
                      1e-6);
        }
      }
  }
}

TYPED_TEST(PointConvexPolygonTest, DegenerateAndBadInput) {
  using T = TypeParam;
  using V = Vec2<T>;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T tl = std::is_same_v<T, float> ? T(1e-5) : T(1e-13);
  const auto d = [](const V& p, const std::vector<V>& v) {
    return distance_to_convex_polygon(p, std::span<const V>(v));
  };
  EXPECT_TRUE(dist::is_nan_result(d(V{0, 0}, {})));
  EXPECT_NEAR(d(V{3, 4}, {V{0, 0}}).distance, T(5), tl);
  EXPECT_NEAR(d(V{1, 3}, {V{0, 0}, V{2, 0}}).distance, T(3), tl);
  // All collinear: the segment they span.
  const std::vector<V> line = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  EXPECT_NEAR(d(V{5, 0}, line).distance, T(2), tl);
  EXPECT_NEAR(d(V{1.5, 2}, line).distance, T(2), tl);
  EXPECT_NEAR(d(V{-1, -1}, line).distance, std::sqrt(T(2)), tl);
  EXPECT_EQ(d(V{2.5, 0}, line).distance, T(0));
  // Polygon2 overload.
  const Polygon2<T> sq{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  EXPECT_NEAR(distance_to_convex_polygon(V{2, 2}, sq).distance, std::sqrt(T(2)), tl);
  // Non-finite query point, and a NaN vertex the search reads (v0 always is).
  EXPECT_TRUE(dist::is_nan_result(d(V{nan, 0}, sq.vertices)));
  EXPECT_TRUE(dist::is_nan_result(d(V{2, 2}, {V{nan, 0}, V{1, 0}, V{1, 1}, V{0, 1}})));
  // Non-convex and clockwise input: unspecified but finite, and never below the true distance
  // to the boundary by more than rounding when the result is positive.
  Rng rng(locus_test::test_seed() + 73);
  std::vector<V> star;
  for (int i = 0; i < 10; ++i) {
    const T a = T(0.6283185307179586) * T(i), rad = i % 2 ? T(1) : T(3);
    star.push_back({rad * std::cos(a), rad * std::sin(a)});
  }
  std::vector<V> cw(sq.vertices.rbegin(), sq.vertices.rend());
  for (int n = 0; n < 500; ++n) {
    const V p = rng.vec<T, 2>(-5, 5);
    const auto a = d(p, star), b = d(p, cw);
    EXPECT_TRUE(locus::is_finite(a.distance) && a.distance >= T(0));
    EXPECT_TRUE(locus::is_finite(b.distance) && b.distance >= T(0));
  }
}
