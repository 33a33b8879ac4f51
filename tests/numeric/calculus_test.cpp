// SPDX-License-Identifier: BSL-1.0
// Tests for numeric/calculus.hpp (row num.calculus; book appendix A, figures A.2-A.17):
// level sets by marching squares (circle loops against the interpolation error bound,
// orientation, loop counts, saddles under both rules against the exact bilinear topology,
// samples exactly at the level, an independent winding-number oracle on random grids,
// negation invariance), critical points of the book's functions and of random quadratics
// against analytic answers, 1D critical points and absolute extrema (figures A.8-A.12) against
// closed forms and dense sampling, and bad input.
#include <locus/numeric/calculus.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

using namespace locus;
using locus_test::Rng;

template <class T>
class CalculusTest : public ::testing::Test {};
TYPED_TEST_SUITE(CalculusTest, locus_test::RealTypes);

namespace {

template <class T>
T nan_v() {
  return std::numeric_limits<T>::quiet_NaN();
}

// Signed area of a closed polyline (shoelace, in double).
template <class T>
double signed_area(const std::vector<Vec2<T>>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2<T>& u = p[i];
    const Vec2<T>& v = p[(i + 1) % p.size()];
    a += double(u.x) * double(v.y) - double(v.x) * double(u.y);
  }
  return a / 2;
}

// Winding number of a closed polyline around q, by summing turning angles (the polyline never
// passes through q in the tests that use it).
template <class T>
int winding(const std::vector<Vec2<T>>& p, const Vec2<T>& q) {
  double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double ax = double(p[i].x) - double(q.x), ay = double(p[i].y) - double(q.y);
    const Vec2<T>& n = p[(i + 1) % p.size()];
    const double bx = double(n.x) - double(q.x), by = double(n.y) - double(q.y);
    sum += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }
  return static_cast<int>(std::lround(sum / (2 * pi_v<double>)));
}

template <class T>
ScalarGrid<T> grid_from(int nx, int ny, Vec2<T> origin, Vec2<T> spacing, auto&& f) {
  ScalarGrid<T> g;
  g.nx = nx;
  g.ny = ny;
  g.origin = origin;
  g.spacing = spacing;
  g.values.resize(static_cast<std::size_t>(nx * ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) g.values[static_cast<std::size_t>(j * nx + i)] = f(i, j);
  return g;
}

}  // namespace

// ---- level sets --------------------------------------------------------------------------------

// f = x^2 + y^2 - r^2: along an axis-parallel edge f'' = 2, so the linear interpolant errs by at
// most h^2 / 4 and every vertex p satisfies | |p| - r | = |f(p)| / (|p| + r) <= h^2 / (4 r)
// (plus rounding). One loop, clockwise (f >= 0 outside is on the left), area close to pi r^2.
TYPED_TEST(CalculusTest, LevelSetCircle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 20; ++k) {
    const double r = rng.uniform(0.5, 1.8);
    const int n = rng.uniform_int(8, 60);
    const Vec2<T> lo{T(-2) + rng.uniform(T(-0.1), T(0.1)), T(-2) + rng.uniform(T(-0.1), T(0.1))};
    const auto f = [&](Vec2<T> p) { return p.x * p.x + p.y * p.y - T(r * r); };
    const auto g = sample_grid(f, lo, Vec2<T>{T(2), T(2)}, n, n + 3);
    const auto ls = level_set(g, T(0));
    ASSERT_EQ(ls.status, Status::ok);
    ASSERT_EQ(ls.contours.size(), 1u);
    const auto& c = ls.contours[0];
    EXPECT_TRUE(c.closed);
    const double h = std::max(double(g.spacing.x), double(g.spacing.y));
    const double bound = h * h / (4 * r) + 32 * double(eps_v<T>) * 4;
    for (const auto& p : c.points) EXPECT_NEAR(std::hypot(double(p.x), double(p.y)), r, bound);
    // Consecutive vertices are in neighbouring cells: no jumps.
    for (std::size_t i = 0; i < c.points.size(); ++i)
      EXPECT_LE(length(vec_cast<double>(c.points[i] - c.points[(i + 1) % c.points.size()])),
                std::sqrt(2.0) * h * (1 + 1e-6));
    const double area = signed_area(c.points);
    EXPECT_LT(area, 0);
    // Vertices within `bound` of the circle, chords of length <= sqrt(2) h with sagitta
    // <= h^2 / (4 r): the polygon's area is within 2 pi r (bound + h^2 / (4 r)) of pi r^2.
    EXPECT_NEAR(-area, pi_v<double> * r * r, 2 * pi_v<double> * r * (bound + h * h / (4 * r)));
  }
}

TYPED_TEST(CalculusTest, LevelSetOrientationAndLoopCounts) {
  using T = TypeParam;
  const Vec2<T> lo{T(-4), T(-4)}, hi{T(4), T(4)};
  // Around a maximum: counter-clockwise.
  const auto bump =
      sample_grid([](Vec2<T> p) { return T(4) - p.x * p.x - p.y * p.y; }, lo, hi, 41, 37);
  auto ls = level_set(bump, T(1));
  ASSERT_EQ(ls.contours.size(), 1u);
  EXPECT_GT(signed_area(ls.contours[0].points), 0);
  // Annulus f = (|p| - 2)^2 at 0.25: circles of radius 1.5 (ccw: f > 0.25 inside it) and 2.5
  // (cw: f > 0.25 outside it).
  const auto ring = sample_grid(
      [](Vec2<T> p) { return sqr(std::sqrt(p.x * p.x + p.y * p.y) - T(2)); }, lo, hi, 81, 81);
  ls = level_set(ring, T(0.25));
  ASSERT_EQ(ls.status, Status::ok);
  ASSERT_EQ(ls.contours.size(), 2u);
  EXPECT_EQ(ls.closed_count(), 2);
  for (const auto& c : ls.contours) {
    const double rad = std::hypot(double(c.points[0].x), double(c.points[0].y));
    if (rad < 2) {
      EXPECT_GT(signed_area(c.points), 0);
    } else {
      EXPECT_LT(signed_area(c.points), 0);
    }
  }
  // Two separated bumps: two loops, each around its own centre.
  const Vec2<T> a{T(-2), T(0.5)}, b{T(1.5), T(-1)};
  const auto two = sample_grid(
      [&](Vec2<T> p) { return std::exp(-sqr_length(p - a)) + std::exp(-sqr_length(p - b)); }, lo,
      hi, 64, 64);
  ls = level_set(two, T(0.5));
  ASSERT_EQ(ls.contours.size(), 2u);
  int around_a = 0, around_b = 0;
  for (const auto& c : ls.contours) {
    EXPECT_TRUE(c.closed);
    EXPECT_GT(signed_area(c.points), 0);
    around_a += winding(c.points, a);
    around_b += winding(c.points, b);
  }
  EXPECT_EQ(around_a, 1);
  EXPECT_EQ(around_b, 1);
  // A level below every sample or above every sample: no contours.
  EXPECT_TRUE(level_set(two, T(-1)).contours.empty());
  EXPECT_TRUE(level_set(two, T(5)).contours.empty());
  // Open contours: a plane's level line crosses the grid from boundary to boundary.
  const auto plane = sample_grid([](Vec2<T> p) { return p.x + T(0.3) * p.y; }, lo, hi, 9, 9);
  ls = level_set(plane, T(0.1));
  ASSERT_EQ(ls.contours.size(), 1u);
  EXPECT_FALSE(ls.contours[0].closed);
  for (const auto& p : ls.contours[0].points)
    EXPECT_NEAR(double(p.x) + 0.3 * double(p.y), 0.1, 64 * double(eps_v<T>) * 4);
  // Above (f >= 0.1, large x) on the left: the line runs downwards (decreasing y).
  EXPECT_GT(ls.contours[0].points.front().y, ls.contours[0].points.back().y);
}

// f = (x - a)(y - b) is bilinear, so on a grid it equals its bilinear interpolant and every
// contour vertex has f = level exactly (up to rounding). The saddle (a, b) lies inside a cell,
// off its centre: for levels between 0 (the saddle value) and the cell-centre value the two
// rules disagree, and only the asymptotic decider reproduces the true hyperbola branches.
TYPED_TEST(CalculusTest, LevelSetSaddleRules) {
  using T = TypeParam;
  const T a = T(0.13), b = T(-0.07);
  const auto f = [&](Vec2<T> p) { return (p.x - a) * (p.y - b); };
  const auto g = sample_grid(f, Vec2<T>{T(-1), T(-1)}, Vec2<T>{T(1), T(1)}, 11, 11);
  // The cell holding the saddle: [0, 0.2] x [-0.2, 0]; centre value (0.1 - a)(-0.1 - b) > 0.
  const T centre = (T(0.1) - a) * (T(-0.1) - b);
  ASSERT_GT(centre, T(0));
  const auto branch_mixing = [&](const LevelSet<T>& ls) {
    // A contour with points on both sides of x = a mixes the two hyperbola branches.
    int mixed = 0;
    for (const auto& c : ls.contours) {
      bool left = false, right = false;
      for (const auto& p : c.points) (p.x < a ? left : right) = true;
      mixed += left && right;
    }
    return mixed;
  };
  for (const T level : {centre / T(2), -centre / T(2)}) {
    SCOPED_TRACE(testing::Message() << "level " << level);
    const auto dec = level_set(g, level);
    ASSERT_EQ(dec.status, Status::ok);
    EXPECT_EQ(dec.contours.size(), 2u);
    EXPECT_EQ(dec.closed_count(), 0);
    EXPECT_EQ(branch_mixing(dec), 0);
    for (const auto& c : dec.contours)
      for (const auto& p : c.points)
        EXPECT_NEAR(double(f(p)), double(level), 64 * double(eps_v<T>));
    LevelSetOptions opt;
    opt.saddle = SaddleRule::center_average;
    const auto avg = level_set(g, level, opt);
    EXPECT_EQ(avg.contours.size(), 2u);
    // Between the saddle value and the centre average the mean joins the wrong corners.
    EXPECT_EQ(branch_mixing(avg), level > T(0) ? 2 : 0);
  }
  // Level exactly at the saddle value: the cross x = a, y = b. The centre counts as above
  // (f >= level), so the two above quadrants are joined through the cell: two open polylines,
  // each turning at the saddle cell, neither crossing the other.
  const auto at0 = level_set(g, T(0));
  ASSERT_EQ(at0.contours.size(), 2u);
  for (const auto& c : at0.contours) {
    EXPECT_FALSE(c.closed);
    // each one bounds a below quadrant: points in (x >= a, y <= b) or (x <= a, y >= b) only
    bool q4 = false, q2 = false;
    for (const auto& p : c.points) {
      EXPECT_NEAR(double(f(p)), 0.0, 64 * double(eps_v<T>));
      if (p.x > a + T(1e-3) || p.y < b - T(1e-3))
        q4 = q4 || (p.x > a - T(1e-3) && p.y < b + T(1e-3));
      if (p.x < a - T(1e-3) || p.y > b + T(1e-3))
        q2 = q2 || (p.x < a + T(1e-3) && p.y > b - T(1e-3));
    }
    EXPECT_NE(q4, q2);
  }
}

// Samples exactly at the level count as above. f = x^2 + y^2 - 4 on the integer grid is zero
// at (+-2, 0) and (0, +-2): the loop passes exactly through those grid vertices, once each.
TYPED_TEST(CalculusTest, LevelSetSamplesExactlyAtLevel) {
  using T = TypeParam;
  const auto g = grid_from<T>(7, 7, Vec2<T>{T(-3), T(-3)}, Vec2<T>{T(1), T(1)}, [](int i, int j) {
    return T((i - 3) * (i - 3) + (j - 3) * (j - 3) - 4);
  });
  const auto ls = level_set(g, T(0));
  ASSERT_EQ(ls.contours.size(), 1u);
  const auto& c = ls.contours[0];
  EXPECT_TRUE(c.closed);
  for (const Vec2<T> v :
       {Vec2<T>{T(2), T(0)}, Vec2<T>{T(-2), T(0)}, Vec2<T>{T(0), T(2)}, Vec2<T>{T(0), T(-2)}})
    EXPECT_EQ(std::count(c.points.begin(), c.points.end(), v), 1);
  for (std::size_t i = 0; i < c.points.size(); ++i)
    EXPECT_FALSE(c.points[i] == c.points[(i + 1) % c.points.size()]);
  // A maximum exactly at the level on a grid vertex: a loop shrunk to one point.
  const auto peak =
      grid_from<T>(5, 5, Vec2<T>{T(-2), T(-2)}, Vec2<T>{T(1), T(1)},
                   [](int i, int j) { return -T((i - 2) * (i - 2) + (j - 2) * (j - 2)); });
  const auto lp = level_set(peak, T(0));
  ASSERT_EQ(lp.contours.size(), 1u);
  EXPECT_TRUE(lp.contours[0].closed);
  ASSERT_EQ(lp.contours[0].points.size(), 1u);
  EXPECT_TRUE(lp.contours[0].points[0] == (Vec2<T>{T(0), T(0)}));
  // A minimum exactly at the level: the whole grid is above, no contour.
  const auto pit = grid_from<T>(5, 5, Vec2<T>{T(-2), T(-2)}, Vec2<T>{T(1), T(1)}, [](int i, int j) {
    return T((i - 2) * (i - 2) + (j - 2) * (j - 2));
  });
  EXPECT_TRUE(level_set(pit, T(0)).contours.empty());
  // A ridge f = -y^2 exactly at the level along a grid row: the boundary of the thin strip
  // f >= level, two open polylines along y = 0 in opposite directions.
  const auto ridge = grid_from<T>(6, 5, Vec2<T>{T(0), T(-2)}, Vec2<T>{T(1), T(1)},
                                  [](int, int j) { return -T((j - 2) * (j - 2)); });
  const auto lr = level_set(ridge, T(0));
  ASSERT_EQ(lr.contours.size(), 2u);
  for (const auto& k : lr.contours) {
    EXPECT_FALSE(k.closed);
    EXPECT_EQ(k.points.size(), 6u);
    for (const auto& p : k.points) EXPECT_EQ(p.y, T(0));
  }
  EXPECT_NE(lr.contours[0].points.front().x < lr.contours[0].points.back().x,
            lr.contours[1].points.front().x < lr.contours[1].points.back().x);
}

// Independent oracle on random grids whose boundary samples are below the level: all contours
// are closed and the sum of their winding numbers around a grid vertex is 1 for a vertex above
// the level and 0 for one below (this checks joining and orientation). Every grid edge with a
// sign change contributes exactly one vertex. Negating f and the level gives the same point
// sets with reversed direction.
TYPED_TEST(CalculusTest, LevelSetRandomWindingOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 30; ++k) {
    const int nx = rng.uniform_int(3, 14), ny = rng.uniform_int(3, 14);
    const T level = rng.uniform(T(-0.3), T(0.3));
    const auto g =
        grid_from<T>(nx, ny, Vec2<T>{T(0.5), T(-1)}, Vec2<T>{T(0.25), T(0.5)}, [&](int i, int j) {
          if (i == 0 || j == 0 || i == nx - 1 || j == ny - 1) return T(-2);
          return rng.uniform(T(-1), T(1));
        });
    for (const SaddleRule rule : {SaddleRule::asymptotic_decider, SaddleRule::center_average}) {
      LevelSetOptions opt;
      opt.saddle = rule;
      const auto ls = level_set(g, level, opt);
      ASSERT_EQ(ls.status, Status::ok);
      std::size_t vertices = 0;
      for (const auto& c : ls.contours) {
        EXPECT_TRUE(c.closed);
        vertices += c.points.size();
      }
      std::size_t crossings = 0;
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          if (i + 1 < nx) crossings += (g.at(i, j) >= level) != (g.at(i + 1, j) >= level);
          if (j + 1 < ny) crossings += (g.at(i, j) >= level) != (g.at(i, j + 1) >= level);
          int w = 0;
          for (const auto& c : ls.contours) w += winding(c.points, g.position(i, j));
          EXPECT_EQ(w, g.at(i, j) >= level ? 1 : 0) << "vertex " << i << ", " << j;
        }
      EXPECT_EQ(vertices, crossings);
      // Negation: same vertex multiset, opposite orientation of every loop.
      ScalarGrid<T> neg = g;
      for (T& v : neg.values) v = -v;
      const auto ln = level_set(neg, -level, opt);
      ASSERT_EQ(ln.contours.size(), ls.contours.size());
      std::map<std::pair<T, T>, int> count;
      double area = 0, narea = 0;
      for (const auto& c : ls.contours) {
        for (const auto& p : c.points) ++count[{p.x, p.y}];
        area += signed_area(c.points);
      }
      for (const auto& c : ln.contours) {
        for (const auto& p : c.points) --count[{p.x, p.y}];
        narea += signed_area(c.points);
      }
      for (const auto& [p, n] : count) EXPECT_EQ(n, 0);
      EXPECT_NEAR(area, -narea, 1e-9);
    }
  }
}

TYPED_TEST(CalculusTest, LevelSetBadInput) {
  using T = TypeParam;
  ScalarGrid<T> g;
  EXPECT_EQ(level_set(g, T(0)).status, Status::empty_input);
  g = grid_from<T>(1, 5, Vec2<T>{}, Vec2<T>{T(1), T(1)}, [](int, int j) { return T(j); });
  EXPECT_EQ(level_set(g, T(0)).status, Status::empty_input);
  g = grid_from<T>(4, 4, Vec2<T>{}, Vec2<T>{T(1), T(1)}, [](int i, int j) { return T(i - j); });
  EXPECT_EQ(level_set(g, nan_v<T>()).status, Status::non_finite_input);
  auto bad = g;
  bad.values.pop_back();
  EXPECT_EQ(level_set(bad, T(0)).status, Status::invalid_input);
  bad = g;
  bad.spacing.x = T(0);
  EXPECT_EQ(level_set(bad, T(0)).status, Status::invalid_input);
  bad.spacing.x = nan_v<T>();
  EXPECT_EQ(level_set(bad, T(0)).status, Status::non_finite_input);
  EXPECT_TRUE(sample_grid([](Vec2<T>) { return T(0); }, Vec2<T>{}, Vec2<T>{T(1), T(1)}, 1, 4)
                  .values.empty());
  EXPECT_TRUE(
      sample_grid([](Vec2<T>) { return T(0); }, Vec2<T>{T(1), T(0)}, Vec2<T>{T(0), T(1)}, 4, 4)
          .values.empty());
  // A NaN sample on the circle's path: the cells around it are a hole, the loop becomes one
  // open polyline ending at the hole, status non_finite_input.
  const auto f = [](Vec2<T> p) { return p.x * p.x + p.y * p.y - T(2.25); };
  auto circ = sample_grid(f, Vec2<T>{T(-2), T(-2)}, Vec2<T>{T(2), T(2)}, 17, 17);
  circ.values[static_cast<std::size_t>(8 * 17 + 14)] = nan_v<T>();  // (1.5, 0)
  const auto ls = level_set(circ, T(0));
  EXPECT_EQ(ls.status, Status::non_finite_input);
  ASSERT_EQ(ls.contours.size(), 1u);
  EXPECT_FALSE(ls.contours[0].closed);
  for (const auto& p : ls.contours[0].points)
    EXPECT_NEAR(std::hypot(double(p.x), double(p.y)), 1.5, 0.25 / 6 + 1e-5);
  circ.values[0] = std::numeric_limits<T>::infinity();
  EXPECT_EQ(level_set(circ, T(0)).status, Status::non_finite_input);
}

// ---- critical points, 2D -----------------------------------------------------------------------

namespace {

// Figures A.16 / A.17: f = 2 y^2 x - y x^2 + 4 x y. grad = (2y^2 - 2xy + 4y, 4xy - x^2 + 4x)
// vanishes at (0, 0), (4, 0), (0, -2) (saddles) and (4/3, -2/3) (relative minimum:
// f_xx = 4/3 > 0, det = 48/9 > 0).
template <class T>
struct BookA16 {
  T operator()(Vec2<T> p) const {
    return T(2) * p.y * p.y * p.x - p.y * p.x * p.x + T(4) * p.x * p.y;
  }
  Vec2<T> grad(Vec2<T> p) const {
    return {T(2) * p.y * p.y - T(2) * p.x * p.y + T(4) * p.y,
            T(4) * p.x * p.y - p.x * p.x + T(4) * p.x};
  }
  Mat2<T> hess(Vec2<T> p) const {
    const T fxy = T(4) * p.y - T(2) * p.x + T(4);
    return Mat2<T>::from_rows(Vec2<T>{T(-2) * p.y, fxy}, Vec2<T>{fxy, T(4) * p.x});
  }
};

template <class T>
void expect_points(const CriticalPoints2<T>& r,
                   const std::vector<std::pair<Vec2d, CriticalKind>>& want, double tol) {
  ASSERT_EQ(r.points.size(), want.size());
  for (const auto& [p, kind] : want) {
    int hits = 0;
    for (const auto& q : r.points)
      if (length(vec_cast<double>(q.point) - p) <= tol) {
        ++hits;
        EXPECT_EQ(q.kind, kind) << "at " << p.x << ", " << p.y;
      }
    EXPECT_EQ(hits, 1) << "at " << p.x << ", " << p.y;
  }
}

}  // namespace

TYPED_TEST(CalculusTest, CriticalPointsBookFigureA16) {
  using T = TypeParam;
  const BookA16<T> f;
  const auto r = critical_points_2d(
      f, [&](Vec2<T> p) { return f.grad(p); }, [&](Vec2<T> p) { return f.hess(p); },
      Vec2<T>{T(-1.3), T(-3.1)}, Vec2<T>{T(5.2), T(1.1)});
  ASSERT_EQ(r.status, Status::ok);
  // Newton converges quadratically to simple roots: accurate to a few ulps of the box scale.
  const double tol = 1e3 * double(eps_v<T>) * 8;
  expect_points(r,
                {{{0, 0}, CriticalKind::saddle},
                 {{4, 0}, CriticalKind::saddle},
                 {{0, -2}, CriticalKind::saddle},
                 {{4.0 / 3, -2.0 / 3}, CriticalKind::minimum}},
                tol);
  for (const auto& q : r.points) EXPECT_NEAR(double(q.value), double(f(q.point)), 0);
  // Sorted by x then y.
  for (std::size_t i = 1; i < r.points.size(); ++i)
    EXPECT_TRUE(r.points[i - 1].point.x < r.points[i].point.x ||
                (r.points[i - 1].point.x == r.points[i].point.x &&
                 r.points[i - 1].point.y < r.points[i].point.y));
  // The minimum's value is 2(4/9)(4/3) - (-2/3)(16/9) + 4(4/3)(-2/3) = -32/27.
  for (const auto& q : r.points) {
    if (q.kind == CriticalKind::minimum) {
      EXPECT_NEAR(double(q.value), -32.0 / 27, 1e-5);
    }
  }
  // The sampled version finds the same four points to O(h^2) (the central differences of this
  // cubic are exact, so the model is f's Taylor quadratic at the nearest vertex: one Newton
  // step from within h / sqrt(2), error about |f'''| h^2 / lambda_min).
  const auto g = sample_grid([&](Vec2<T> p) { return f(p); }, Vec2<T>{T(-1.3), T(-3.1)},
                             Vec2<T>{T(5.2), T(1.1)}, 131, 85);
  const auto rg = critical_points_2d(g);
  ASSERT_EQ(rg.status, Status::ok);
  expect_points(rg,
                {{{0, 0}, CriticalKind::saddle},
                 {{4, 0}, CriticalKind::saddle},
                 {{0, -2}, CriticalKind::saddle},
                 {{4.0 / 3, -2.0 / 3}, CriticalKind::minimum}},
                0.02);
}

TYPED_TEST(CalculusTest, CriticalPointsSimpleSurfaces) {
  using T = TypeParam;
  const Vec2<T> lo{T(-1), T(-1.2)}, hi{T(1.3), T(1)};
  // Figure A.19/A.20 bowl x^2 + y^2: one minimum; A.15 saddle x^2 - y^2.
  const auto bowl = critical_points_2d(
      [](Vec2<T> p) { return p.x * p.x + p.y * p.y; }, [](Vec2<T> p) { return T(2) * p; },
      [](Vec2<T>) {
        return Mat2<T>::from_rows(Vec2<T>{T(2), T(0)}, Vec2<T>{T(0), T(2)});
      },
      lo, hi);
  expect_points(bowl, {{{0, 0}, CriticalKind::minimum}}, 16 * double(eps_v<T>));
  EXPECT_EQ(bowl.points[0].eigenvalues, (Vec2<T>{T(2), T(2)}));
  const auto sad =
      critical_points_2d([](Vec2<T> p) { return p.x * p.x - p.y * p.y; },
                         [](Vec2<T> p) {
                           return Vec2<T>{T(2) * p.x, T(-2) * p.y};
                         },
                         [](Vec2<T>) {
                           return Mat2<T>::from_rows(Vec2<T>{T(2), T(0)}, Vec2<T>{T(0), T(-2)});
                         },
                         lo, hi);
  expect_points(sad, {{{0, 0}, CriticalKind::saddle}}, 16 * double(eps_v<T>));
  // -(x^2 + 2 y^2): maximum.
  const auto cap =
      critical_points_2d([](Vec2<T> p) { return -(p.x * p.x + T(2) * p.y * p.y); },
                         [](Vec2<T> p) {
                           return Vec2<T>{T(-2) * p.x, T(-4) * p.y};
                         },
                         [](Vec2<T>) {
                           return Mat2<T>::from_rows(Vec2<T>{T(-2), T(0)}, Vec2<T>{T(0), T(-4)});
                         },
                         lo, hi);
  expect_points(cap, {{{0, 0}, CriticalKind::maximum}}, 16 * double(eps_v<T>));
  // x^4 + y^4: the Hessian vanishes at the minimum: degenerate (test inconclusive).
  const auto flat =
      critical_points_2d([](Vec2<T> p) { return sqr(sqr(p.x)) + sqr(sqr(p.y)); },
                         [](Vec2<T> p) {
                           return Vec2<T>{T(4) * p.x * p.x * p.x, T(4) * p.y * p.y * p.y};
                         },
                         [](Vec2<T> p) {
                           return Mat2<T>::from_rows(Vec2<T>{T(12) * p.x * p.x, T(0)},
                                                     Vec2<T>{T(0), T(12) * p.y * p.y});
                         },
                         lo, hi);
  ASSERT_EQ(flat.points.size(), 1u);
  EXPECT_EQ(flat.points[0].kind, CriticalKind::degenerate);
  EXPECT_LT(length(vec_cast<double>(flat.points[0].point)), 1e-3);
  // sin x cos y on [0.3, 7] x [-1, 4]: critical points where cos x cos y = sin x sin y = 0:
  // (pi/2 + k pi, m pi) extrema (max when sin x cos y = 1), (k pi, pi/2 + m pi) saddles.
  const auto wave = critical_points_2d(
      [](Vec2<T> p) { return std::sin(p.x) * std::cos(p.y); },
      [](Vec2<T> p) {
        return Vec2<T>{std::cos(p.x) * std::cos(p.y), -std::sin(p.x) * std::sin(p.y)};
      },
      [](Vec2<T> p) {
        const T fxy = -std::cos(p.x) * std::sin(p.y);
        const T d = -std::sin(p.x) * std::cos(p.y);
        return Mat2<T>::from_rows(Vec2<T>{d, fxy}, Vec2<T>{fxy, d});
      },
      Vec2<T>{T(0.3), T(-1)}, Vec2<T>{T(7), T(4)});
  std::vector<std::pair<Vec2d, CriticalKind>> want;
  const double pi = pi_v<double>;
  for (int kx = 0; kx < 3; ++kx)
    for (int m = 0; m < 2; ++m) {
      const double x = pi / 2 + kx * pi, y = m * pi;
      if (x > 7) continue;
      const double v = std::sin(x) * std::cos(y);
      want.push_back({{x, y}, v > 0 ? CriticalKind::maximum : CriticalKind::minimum});
    }
  for (int kx = 1; kx < 3; ++kx)
    for (int m = -1; m < 2; ++m) {
      const double y = pi / 2 + m * pi;
      if (y < -1 || y > 4) continue;
      want.push_back({{kx * pi, y}, CriticalKind::saddle});
    }
  ASSERT_EQ(wave.status, Status::ok);
  expect_points(wave, want, 1e3 * double(eps_v<T>) * 8);
}

// Random quadratics (x - c)^T A (x - c) + k: one critical point c, classified by the signs of
// A's eigenvalues (chosen well away from zero).
TYPED_TEST(CalculusTest, CriticalPointsRandomQuadratics) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 40; ++k) {
    const double ang = rng.uniform(0.0, pi_v<double>);
    const double l0 = rng.uniform(0.2, 3.0) * (rng.uniform_int(0, 1) ? 1 : -1);
    const double l1 = rng.uniform(0.2, 3.0) * (rng.uniform_int(0, 1) ? 1 : -1);
    const double cs = std::cos(ang), sn = std::sin(ang);
    const double a = l0 * cs * cs + l1 * sn * sn, b = (l0 - l1) * cs * sn,
                 d = l0 * sn * sn + l1 * cs * cs;
    const Vec2<T> c = rng.vec<T, 2>(T(-2), T(2));
    const Mat2<T> H = Mat2<T>::from_rows(Vec2<T>{T(2 * a), T(2 * b)}, Vec2<T>{T(2 * b), T(2 * d)});
    const auto f = [&](Vec2<T> p) {
      const Vec2<T> q = p - c;
      return T(a) * q.x * q.x + T(2 * b) * q.x * q.y + T(d) * q.y * q.y;
    };
    const auto g = [&](Vec2<T> p) { return H * (p - c); };
    const auto r = critical_points_2d(
        f, g, [&](Vec2<T>) { return H; }, Vec2<T>{T(-3), T(-3)}, Vec2<T>{T(3), T(3)});
    ASSERT_EQ(r.status, Status::ok);
    const CriticalKind kind = l0 > 0 && l1 > 0   ? CriticalKind::minimum
                              : l0 < 0 && l1 < 0 ? CriticalKind::maximum
                                                 : CriticalKind::saddle;
    // Conditioning: |dx| <= |dg| / min|lambda| with |dg| a few eps times |H| |c|.
    expect_points(r, {{vec_cast<double>(c), kind}}, 64 * double(eps_v<T>) * 4 * 3 / 0.4);
  }
}

TYPED_TEST(CalculusTest, CriticalPointsDegenerateAndBad) {
  using T = TypeParam;
  const auto f = [](Vec2<T> p) { return p.x * p.x; };
  const auto g = [](Vec2<T> p) { return Vec2<T>{T(2) * p.x, T(0)}; };
  const auto h = [](Vec2<T>) {
    return Mat2<T>::from_rows(Vec2<T>{T(2), T(0)}, Vec2<T>{T(0), T(0)});
  };
  const Vec2<T> lo{T(-1), T(-1)}, hi{T(1), T(1)};
  // A line of minima: one point per seed row, all degenerate.
  const auto r = critical_points_2d(f, g, h, lo, hi);
  EXPECT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.points.size(), 12u);
  for (const auto& q : r.points) {
    EXPECT_EQ(q.kind, CriticalKind::degenerate);
    EXPECT_EQ(q.point.x, T(0));
  }
  CriticalPointOptions<T> opt;
  opt.max_points = 3;
  const auto lim = critical_points_2d(f, g, h, lo, hi, opt);
  EXPECT_EQ(lim.status, Status::limit_exceeded);
  EXPECT_EQ(lim.points.size(), 3u);
  // Bad boxes and options.
  EXPECT_EQ(critical_points_2d(f, g, h, Vec2<T>{nan_v<T>(), T(0)}, hi).status,
            Status::non_finite_input);
  EXPECT_EQ(critical_points_2d(f, g, h, hi, lo).status, Status::invalid_input);
  opt = {};
  opt.seeds_x = 0;
  EXPECT_EQ(critical_points_2d(f, g, h, lo, hi, opt).status, Status::invalid_input);
  // Everything NaN: nothing usable.
  const auto nan_g = [](Vec2<T>) { return Vec2<T>{nan_v<T>(), nan_v<T>()}; };
  const auto nan_h = [](Vec2<T>) {
    return Mat2<T>::from_rows(Vec2<T>{nan_v<T>(), T(0)}, Vec2<T>{T(0), T(1)});
  };
  EXPECT_EQ(critical_points_2d(f, nan_g, h, lo, hi).status, Status::non_finite_input);
  EXPECT_EQ(critical_points_2d(f, g, nan_h, lo, hi).status, Status::non_finite_input);
  // NaN on half the box: the seeds there are abandoned, the minimum is still found.
  const auto half_g = [](Vec2<T> p) { return p.y > T(0.5) ? Vec2<T>{nan_v<T>(), T(0)} : T(2) * p; };
  const auto id2 = [](Vec2<T>) {
    return Mat2<T>::from_rows(Vec2<T>{T(2), T(0)}, Vec2<T>{T(0), T(2)});
  };
  const auto half =
      critical_points_2d([](Vec2<T> p) { return sqr_length(p); }, half_g, id2, lo, hi);
  EXPECT_EQ(half.status, Status::ok);
  ASSERT_EQ(half.points.size(), 1u);
  EXPECT_EQ(half.points[0].kind, CriticalKind::minimum);
  // Classification helper.
  EXPECT_EQ(
      classify_critical_point(Mat2<T>::from_rows(Vec2<T>{T(1), T(3)}, Vec2<T>{T(3), T(1)}), T(0))
          .kind,
      CriticalKind::saddle);
  EXPECT_EQ(classify_critical_point(
                Mat2<T>::from_rows(Vec2<T>{nan_v<T>(), T(0)}, Vec2<T>{T(0), T(1)}), T(0))
                .kind,
            CriticalKind::degenerate);
  // Sampled: too small, NaN neighbourhoods.
  EXPECT_EQ(critical_points_2d(ScalarGrid<T>{}).status, Status::empty_input);
  auto grid = sample_grid([](Vec2<T> p) { return sqr_length(p); }, Vec2<T>{T(-1), T(-1)},
                          Vec2<T>{T(1.2), T(1)}, 12, 11);
  auto rg = critical_points_2d(grid);
  ASSERT_EQ(rg.status, Status::ok);
  // Exact for a quadratic: the model is f itself.
  expect_points(rg, {{{0, 0}, CriticalKind::minimum}}, 16 * double(eps_v<T>));
  EXPECT_NEAR(double(rg.points[0].value), 0.0, 16 * double(eps_v<T>));
  grid.values[static_cast<std::size_t>(2)] = nan_v<T>();
  rg = critical_points_2d(grid);
  EXPECT_EQ(rg.status, Status::non_finite_input);
  EXPECT_EQ(rg.points.size(), 1u);
}

// ---- critical points, 1D -----------------------------------------------------------------------

// Figures A.9 / A.10: f = x^3 + 6 x^2 - 7 x + 19 on [-8, 3]; f' = 3 x^2 + 12 x - 7 vanishes at
// -2 -+ sqrt(57) / 3 (maximum, minimum). Absolute extrema by dense sampling.
TYPED_TEST(CalculusTest, OneDimensionalBookFigures) {
  using T = TypeParam;
  const Polynomial<T> p{T(19), T(-7), T(6), T(1)};
  const auto r = critical_points(p, T(-8), T(3));
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.points.size(), 2u);
  const double x0 = -2 - std::sqrt(57.0) / 3, x1 = -2 + std::sqrt(57.0) / 3;
  EXPECT_NEAR(double(r.points[0].x), x0, 8 * double(eps_v<T>) * 5);
  EXPECT_EQ(r.points[0].kind, CriticalKind::maximum);
  EXPECT_NEAR(double(r.points[1].x), x1, 8 * double(eps_v<T>) * 5);
  EXPECT_EQ(r.points[1].kind, CriticalKind::minimum);
  const auto fd = [](double x) { return ((x + 6) * x - 7) * x + 19; };
  double lo = 1e300, hi = -1e300;
  for (int i = 0; i <= 100000; ++i) {
    const double v = fd(-8 + 11.0 * i / 100000);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_EQ(r.min_x, T(-8));  // f(-8) = -53
  EXPECT_NEAR(double(r.min_value), lo, 64 * double(eps_v<T>) * 100);
  EXPECT_NEAR(double(r.max_x), x0, 8 * double(eps_v<T>) * 5);  // f(x0) = 80.9 > f(3) = 79
  EXPECT_GE(double(r.max_value) + 64 * double(eps_v<T>) * 100, hi);
  // The same through the smooth-function version.
  const auto s = critical_points_1d([&](T x) { return p(x); },
                                    [](T x) { return (T(3) * x + T(12)) * x - T(7); }, T(-8), T(3));
  ASSERT_EQ(s.status, Status::ok);
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_NEAR(double(s.points[0].x), x0, 8 * double(eps_v<T>) * 5);
  EXPECT_EQ(s.points[0].kind, CriticalKind::maximum);
  EXPECT_NEAR(double(s.points[1].x), x1, 8 * double(eps_v<T>) * 5);
  EXPECT_EQ(s.points[1].kind, CriticalKind::minimum);
  EXPECT_EQ(s.min_x, T(-8));
  // Figure A.12: f = 3 x^(5/3) - 15 x^(2/3): maximum at the cusp 0 (f' infinite there),
  // minimum at 2 with f = -9 2^(2/3).
  const auto a12 = critical_points_1d(
      [](T x) { return T(3) * std::pow(std::cbrt(x), T(5)) - T(15) * sqr(std::cbrt(x)); },
      [](T x) { return T(5) * sqr(std::cbrt(x)) - T(10) / std::cbrt(x); }, T(-1), T(5));
  ASSERT_EQ(a12.points.size(), 2u);
  EXPECT_NEAR(double(a12.points[0].x), 0.0, 1e-30);
  EXPECT_EQ(a12.points[0].kind, CriticalKind::maximum);
  EXPECT_NEAR(double(a12.points[1].x), 2.0, 8 * double(eps_v<T>) * 2);
  EXPECT_EQ(a12.points[1].kind, CriticalKind::minimum);
  EXPECT_NEAR(double(a12.points[1].value), -9 * std::cbrt(4.0), 64 * double(eps_v<T>) * 15);
  // Figure A.7 (c), (d): stationary inflection points.
  const auto cube = critical_points(Polynomial<T>{T(0), T(0), T(0), T(1)}, T(-1), T(1));
  ASSERT_EQ(cube.points.size(), 1u);
  EXPECT_EQ(cube.points[0].kind, CriticalKind::inflection);
  EXPECT_EQ(cube.points[0].multiplicity, 2);
  EXPECT_EQ(cube.min_x, T(-1));
  EXPECT_EQ(cube.max_x, T(1));
  const auto cube1 = critical_points_1d([](T x) { return x * x * x; },
                                        [](T x) { return T(3) * x * x; }, T(-1), T(1));
  ASSERT_EQ(cube1.points.size(), 1u);  // 0 is a sample point (-1 + 2 * 128 / 256)
  EXPECT_EQ(cube1.points[0].kind, CriticalKind::inflection);
  // x^4: p' = 4 x^3 has a triple root: a minimum (odd multiplicity, p'''' > 0).
  const auto quart = critical_points(Polynomial<T>{T(0), T(0), T(0), T(0), T(1)}, T(-1), T(2));
  ASSERT_EQ(quart.points.size(), 1u);
  EXPECT_EQ(quart.points[0].kind, CriticalKind::minimum);
  EXPECT_EQ(quart.points[0].multiplicity, 3);
}

// Random polynomials built from their critical points: p' = prod (x - r_i), so the critical
// points are the r_i, alternately minima and maxima from the right.
TYPED_TEST(CalculusTest, OneDimensionalRandomPolynomials) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int k = 0; k < 30; ++k) {
    const int n = rng.uniform_int(1, 5);
    std::vector<double> roots;
    while (static_cast<int>(roots.size()) < n) {
      const double r = rng.uniform(-3.0, 3.0);
      bool far = true;
      for (double q : roots) far = far && std::abs(q - r) > 0.3;
      if (far) roots.push_back(r);
    }
    std::sort(roots.begin(), roots.end());
    std::vector<double> d{1.0};  // p' low to high
    for (double r : roots) {
      std::vector<double> e(d.size() + 1, 0.0);
      for (std::size_t i = 0; i < d.size(); ++i) {
        e[i + 1] += d[i];
        e[i] -= r * d[i];
      }
      d = e;
    }
    std::vector<T> c(d.size() + 1, T(0));
    for (std::size_t i = 0; i < d.size(); ++i) c[i + 1] = T(d[i] / double(i + 1));
    const Polynomial<T> p(c);
    const auto res = critical_points(p, T(-4), T(4));
    ASSERT_EQ(res.status, Status::ok);
    ASSERT_EQ(static_cast<int>(res.points.size()), n);
    const auto dp = derivative(p);
    const auto sm =
        critical_points_1d([&](T x) { return p(x); }, [&](T x) { return dp(x); }, T(-4), T(4));
    ASSERT_EQ(static_cast<int>(sm.points.size()), n);
    for (int i = 0; i < n; ++i) {
      // Coefficients rounded to T: roots move by about eps * (sum |d_i| |x|^i) / |p''(r)|,
      // with p'' >= 0.3^(n-1) at separated roots and sum |d_i| 3^i <= 6^5.
      const double tol = 16 * double(eps_v<T>) * std::pow(6.0, n) / std::pow(0.3, n - 1);
      const CriticalKind want =
          (n - 1 - i) % 2 == 0 ? CriticalKind::minimum : CriticalKind::maximum;
      EXPECT_NEAR(double(res.points[static_cast<std::size_t>(i)].x),
                  roots[static_cast<std::size_t>(i)], tol);
      EXPECT_EQ(res.points[static_cast<std::size_t>(i)].kind, want);
      EXPECT_NEAR(double(sm.points[static_cast<std::size_t>(i)].x),
                  roots[static_cast<std::size_t>(i)], tol);
      EXPECT_EQ(sm.points[static_cast<std::size_t>(i)].kind, want);
    }
    // Absolute extrema against dense sampling.
    double lo = 1e300, hi = -1e300;
    for (int i = 0; i <= 4000; ++i) {
      const T x = T(-4 + 8.0 * i / 4000);
      lo = std::min(lo, double(p(x)));
      hi = std::max(hi, double(p(x)));
    }
    const double scale = std::abs(lo) + std::abs(hi);
    EXPECT_LE(double(res.min_value), lo + 64 * double(eps_v<T>) * scale);
    EXPECT_GE(double(res.max_value), hi - 64 * double(eps_v<T>) * scale);
    EXPECT_LE(double(sm.min_value), lo + 64 * double(eps_v<T>) * scale);
    EXPECT_GE(double(sm.max_value), hi - 64 * double(eps_v<T>) * scale);
  }
}

TYPED_TEST(CalculusTest, OneDimensionalBadInput) {
  using T = TypeParam;
  const Polynomial<T> p{T(1), T(2), T(3)};
  EXPECT_EQ(critical_points(p, T(2), T(1)).status, Status::invalid_input);
  EXPECT_EQ(critical_points(p, nan_v<T>(), T(1)).status, Status::non_finite_input);
  EXPECT_EQ(critical_points(Polynomial<T>{nan_v<T>(), T(1)}, T(0), T(1)).status,
            Status::non_finite_input);
  const auto c = critical_points(Polynomial<T>{T(5)}, T(0), T(1));
  EXPECT_EQ(c.status, Status::degenerate_input);
  EXPECT_TRUE(c.points.empty());
  EXPECT_EQ(c.min_value, T(5));
  const auto sq = [](T x) { return x * x; };
  const auto dsq = [](T x) { return T(2) * x; };
  EXPECT_EQ(critical_points_1d(sq, dsq, T(1), T(0)).status, Status::invalid_input);
  EXPECT_EQ(critical_points_1d(sq, dsq, T(0), std::numeric_limits<T>::infinity()).status,
            Status::non_finite_input);
  CriticalPoints1Options o;
  o.samples = 0;
  EXPECT_EQ(critical_points_1d(sq, dsq, T(0), T(1), o).status, Status::invalid_input);
  // f' undefined on part of the interval: reported, the rest still found.
  const auto holed = [](T x) { return x > T(2) ? nan_v<T>() : T(2) * (x + T(0.5)); };
  const auto h = critical_points_1d(sq, holed, T(-1), T(3));
  EXPECT_EQ(h.status, Status::non_finite_input);
  ASSERT_EQ(h.points.size(), 1u);
  EXPECT_NEAR(double(h.points[0].x), -0.5, 8 * double(eps_v<T>));
  // A degenerate interval [a, a].
  const auto pt = critical_points(p, T(1), T(1));
  EXPECT_EQ(pt.status, Status::ok);
  EXPECT_EQ(pt.min_x, T(1));
  EXPECT_EQ(pt.max_value, T(6));
}
