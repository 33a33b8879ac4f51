// SPDX-License-Identifier: BSL-1.0
// Row int3.surface-surface: tangential contact, coincident surfaces and small loops of two
// parametric surfaces (intersection/surface_surface.hpp). Oracles are closed forms: paraboloid
// patches z = +-(x^2 + y^2) touch exactly at one point; a cylinder (rational quadratic NURBS) on a
// plane, and on its mirror image, touches along a known line; z = 2 (rho^2 - 1/4)^2 rests on a
// plane along a circle; a saddle meets its tangent plane in y = +-x crossing at the contact; the
// cusp y^2 = x^3 of z = y^2 - x^3 ends both branches at the contact; lowered paraboloids cut a
// plane or a flatter paraboloid in circles of known radius, and a quartic bump in a small circle
// inside a larger one (checked against a long double de Casteljau evaluation); a reversed copy,
// a sub-patch (de Casteljau) and a degree-elevated copy (Bernstein elevation), exact in float too,
// cover known parameter rectangles. Non-finite input and power-of-two scaling.

#include <locus/intersection/surface_surface.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "support/typed.hpp"

namespace {

using namespace locus;

template <class T>
constexpr double pick(double for_float, double for_double) {
  return std::is_same_v<T, float> ? for_float : for_double;
}

template <class T>
class SurfaceContact : public ::testing::Test {};
TYPED_TEST_SUITE(SurfaceContact, locus_test::RealTypes);

/// z = sign (x - c)^2 + sign (y - c)^2 + lift over x, y in [-1, 1] (x = 2u - 1, y = 2v - 1), as
/// a biquadratic Bézier patch: Bernstein coefficients of x^2 are (1, -1, 1), of x (-1, 0, 1).
template <class T>
BezierPatch<T, 3> paraboloid(T sign, T lift, T c = T(0), T s = T(1)) {
  const T sq[3] = {1, -1, 1}, ln[3] = {-1, 0, 1};
  BezierPatch<T, 3> p{3, 3, {}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      p.control.push_back(
          {s * T(i - 1), s * T(j - 1),
           s * (lift + sign * (sq[i] + sq[j] - 2 * c * (ln[i] + ln[j]) + 2 * c * c))});
  return p;
}

/// The plane z = 0 as a bilinear patch over [-w, w]^2 (times s).
template <class T>
BezierPatch<T, 3> flat(T s = T(1), T w = T(2)) {
  const T e = w * s;
  return {2, 2, {{-e, -e, 0}, {-e, e, 0}, {e, -e, 0}, {e, e, 0}}};
}

/// A random bicubic patch (seeded) near the unit square, coordinates multiples of 1/64: its
/// de Casteljau halves and degree elevation are exact in float as well.
template <class T>
BezierPatch<T, 3> random_patch(locus_test::Rng& rng) {
  const auto q = [&](double lo, double hi) { return T(std::round(64 * rng.uniform(lo, hi)) / 64); };
  BezierPatch<T, 3> p{4, 4, {}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      p.control.push_back(
          {T(i) * T(0.375) + q(-0.1, 0.1), T(j) * T(0.375) + q(-0.1, 0.1), q(-0.4, 0.4)});
  return p;
}

/// The elliptic cylinder x in [0, 1] over the rational quadratic arc (-1, 1/2), (0, -1),
/// (1, 1/2) with weights 1, 1/2, 1 (times s, mirrored by `side`): its middle point is (x, 0, 0)
/// (z = (2 h - 2 w k) / (2 + 2 w) = 0) with the horizontal tangent there (symmetry), so it lies on
/// the plane z = 0 along the x-axis. Every number is exact in float.
template <class T>
NurbsSurface<T, 3> cylinder(T side = T(1), T s = T(1)) {
  const T h = side * s / 2, k = -side * s;
  return {1,
          2,
          2,
          3,
          {{0, -s, h}, {0, 0, k}, {0, s, h}, {s, -s, h}, {s, 0, k}, {s, s, h}},
          {1, T(0.5), 1, 1, T(0.5), 1},
          {0, 0, 1, 1},
          {0, 0, 0, 1, 1, 1}};
}

/// Area of a union of disjoint parameter rectangles, and whether all lie in [lo, hi].
template <class T>
double area(const std::vector<ParamRect<T>>& rects) {
  double sum = 0.0;
  for (const auto& b : rects) sum += double(b.hi.x - b.lo.x) * double(b.hi.y - b.lo.y);
  return sum;
}

TYPED_TEST(SurfaceContact, TouchingParaboloidsMeetAtOnePoint) {
  using T = TypeParam;
  const double tol = pick<T>(1e-5, 1e-9);
  for (const T s : {T(1), T(0x1p-6), T(0x1p7)}) {
    // z = (x - c)^2 + (y - c)^2 and its negative touch at (c, c, 0), c = 5/16 (exact data).
    const T c = T(5) / T(16);
    const auto r = intersection(paraboloid<T>(1, 0, c, s), paraboloid<T>(-1, 0, c, s));
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_TRUE(r.curves.empty());
    EXPECT_TRUE(r.coincident_a.empty() && r.coincident_b.empty());
    ASSERT_EQ(r.contacts.size(), 1u) << s;
    const auto& k = r.contacts[0];
    EXPECT_NEAR(double(k.point.x) / double(s), double(c), tol);
    EXPECT_NEAR(double(k.point.y) / double(s), double(c), tol);
    EXPECT_NEAR(double(k.point.z) / double(s), 0.0, tol);
    // x = 2u - 1: u = (c + 1) / 2 on both.
    for (const auto& uv : {k.param_a, k.param_b}) {
      EXPECT_NEAR(double(uv.x), (double(c) + 1) / 2, tol);
      EXPECT_NEAR(double(uv.y), (double(c) + 1) / 2, tol);
    }
    // A plane tangent to a bump: the flat patch z = 0 under z = -(x^2 + y^2).
    const auto q = intersection(flat<T>(s), paraboloid<T>(-1, 0, T(0), s));
    ASSERT_EQ(q.status, Status::ok);
    EXPECT_TRUE(q.curves.empty());
    ASSERT_EQ(q.contacts.size(), 1u);
    EXPECT_LE(double(max_abs(q.contacts[0].point)) / double(s), tol);
    EXPECT_NEAR(double(q.contacts[0].param_a.x), 0.5, tol);
    EXPECT_NEAR(double(q.contacts[0].param_b.y), 0.5, tol);
    // Lifted apart: no contact, no curve.
    const auto apart = intersection(paraboloid<T>(1, T(1) / 64, c, s), paraboloid<T>(-1, 0, c, s));
    EXPECT_EQ(apart.status, Status::ok);
    EXPECT_TRUE(apart.contacts.empty() && apart.curves.empty());
  }
}

TYPED_TEST(SurfaceContact, CylinderTouchesAPlaneAlongALine) {
  using T = TypeParam;
  const double tol = pick<T>(1e-5, 1e-9);
  for (const T s : {T(0x1p-5), T(0x1p6)}) {
    const NurbsSurface<T, 3> cyl = cylinder<T>(T(1), s);
    // On the plane patch, in both argument orders, and on the mirrored cylinder (two cylinders
    // touching along a generator).
    const auto check = [&](const SurfaceCurves<T>& r, bool cyl_first) {
      ASSERT_EQ(r.status, Status::ok);
      EXPECT_TRUE(r.contacts.empty());
      ASSERT_EQ(r.curves.size(), 1u) << s;
      const auto& c = r.curves[0];
      EXPECT_TRUE(c.tangent);
      EXPECT_FALSE(c.closed);
      EXPECT_EQ(c.first_end, SurfaceCurveEnd::boundary);
      EXPECT_EQ(c.last_end, SurfaceCurveEnd::boundary);
      double xmin = INFINITY, xmax = -INFINITY;
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        const auto& p = c.points[i];
        EXPECT_LE(std::fabs(double(p.y)) / double(s), tol);
        EXPECT_LE(std::fabs(double(p.z)) / double(s), tol);
        xmin = std::min(xmin, double(p.x) / double(s));
        xmax = std::max(xmax, double(p.x) / double(s));
        // The cylinder's parameters: v = 1/2 on the contact line, u = x.
        const Vec2<T> uv = cyl_first ? c.param_a[i] : c.param_b[i];
        EXPECT_NEAR(double(uv.y), 0.5, tol);
        EXPECT_NEAR(double(uv.x), double(p.x) / double(s), tol);
      }
      EXPECT_NEAR(xmin, 0.0, tol);
      EXPECT_NEAR(xmax, 1.0, tol);
      // Consecutive points at most a tracing step apart (the line is sampled, not skipped).
      for (std::size_t i = 0; i + 1 < c.points.size(); ++i)
        EXPECT_LE(double(length(c.points[i + 1] - c.points[i])) / double(s), 0.25);
    };
    SurfaceCurveOptions opt;
    opt.grid = 8;
    check(intersection(cyl, flat<T>(s), opt), true);
    check(intersection(flat<T>(s), cyl, opt), false);
    check(intersection(cyl, cylinder<T>(T(-1), s), opt), true);
  }
}

TYPED_TEST(SurfaceContact, SaddleBranchesCrossAtAContact) {
  using T = TypeParam;
  // z = x^2 - y^2 meets its tangent plane z = 0 in the lines y = +-x, which cross where the
  // surfaces touch.
  BezierPatch<T, 3> saddle{3, 3, {}};
  const T sq[3] = {1, -1, 1};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) saddle.control.push_back({T(i - 1), T(j - 1), sq[i] - sq[j]});
  const auto r = intersection(saddle, flat<T>());
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_LE(double(max_abs(r.contacts[0].point)), pick<T>(1e-5, 1e-9));
  ASSERT_FALSE(r.curves.empty());
  double len = 0.0;
  for (const auto& c : r.curves) {
    EXPECT_FALSE(c.tangent);
    EXPECT_FALSE(c.closed);
    // Every branch ends on the boundary or at the contact, and says which.
    for (const auto& [end, p] :
         {std::pair{c.first_end, c.points.front()}, std::pair{c.last_end, c.points.back()}}) {
      if (end == SurfaceCurveEnd::boundary)
        EXPECT_NEAR(double(std::max(std::fabs(p.x), std::fabs(p.y))), 1.0, 1e-6);
      else
        EXPECT_EQ(end, SurfaceCurveEnd::tangent_point);
    }
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      const auto& p = c.points[i];
      EXPECT_NEAR(std::fabs(double(p.x)), std::fabs(double(p.y)), pick<T>(1e-5, 1e-9));
      EXPECT_NEAR(double(p.z), 0.0, pick<T>(1e-5, 1e-9));
      if (i + 1 < c.points.size()) len += double(length(c.points[i + 1] - p));
    }
  }
  // The two diagonals, each of length 2 sqrt(2), covered once.
  EXPECT_NEAR(len, 4 * std::sqrt(2.0), 0.05);
}

TYPED_TEST(SurfaceContact, CuspBranchesEndAtTheContact) {
  using T = TypeParam;
  // z = y^2 - x^3 (x = 2u - 1: Bernstein coefficients of x, x^3 and y^2) touches z = 0 at the
  // origin, where its section y^2 = x^3 has a cusp: the two branches y = +-x^(3/2) cannot be
  // traced through it; each ends there, marked tangent_point, and the touching point is
  // reported (a degenerate one: the contact system has rank 3 there).
  BezierPatch<T, 3> p{4, 3, {}};
  const T xs[4] = {-1, T(-1) / 3, T(1) / 3, 1}, cube[4] = {-1, 1, -1, 1}, sq[3] = {1, -1, 1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) p.control.push_back({xs[i], T(j - 1), sq[j] - cube[i]});
  const auto r = intersection(p, flat<T>());
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_LE(double(max_abs(r.contacts[0].point)), 0x1p-17);
  ASSERT_EQ(r.curves.size(), 2u);
  for (const auto& c : r.curves) {
    EXPECT_FALSE(c.tangent || c.closed);
    // One end at a corner (1, +-1), the other next to the cusp.
    const bool cusp_first = c.first_end == SurfaceCurveEnd::tangent_point;
    EXPECT_EQ(cusp_first ? c.last_end : c.first_end, SurfaceCurveEnd::boundary);
    if (!cusp_first) {
      EXPECT_EQ(c.last_end, SurfaceCurveEnd::tangent_point);
    }
    const auto& tip = cusp_first ? c.points.front() : c.points.back();
    const auto& corner = cusp_first ? c.points.back() : c.points.front();
    EXPECT_LE(double(max_abs(tip)), 0x1p-8);
    EXPECT_NEAR(double(corner.x), 1.0, pick<T>(1e-5, 1e-9));
    EXPECT_NEAR(std::fabs(double(corner.y)), 1.0, pick<T>(1e-5, 1e-9));
    for (const auto& q : c.points) {
      EXPECT_NEAR(double(q.z), 0.0, pick<T>(1e-5, 1e-9));
      const long double x = q.x, y = q.y;
      EXPECT_LE(std::fabs(double(y * y - x * x * x)), pick<T>(1e-5, 1e-9));
    }
  }
}

TYPED_TEST(SurfaceContact, CoincidentCopiesAreReportedNotTraced) {
  using T = TypeParam;
  locus_test::Rng rng(29);
  SurfaceCurveOptions opt;
  opt.grid = 8;  // 4 x 4 leaves: u = 1/2 is still a leaf boundary
  for (int iter = 0; iter < 2; ++iter) {
    const BezierPatch<T, 3> p = random_patch<T>(rng);
    // The same patch.
    const auto same = intersection(p, p, opt);
    ASSERT_EQ(same.status, Status::ok) << rng.trace();
    EXPECT_TRUE(same.curves.empty() && same.contacts.empty()) << rng.trace();
    EXPECT_EQ(area(same.coincident_a), 1.0) << rng.trace();
    EXPECT_EQ(area(same.coincident_b), 1.0) << rng.trace();
    // Reparametrised: u -> 1 - u (rows reversed; the normals flip).
    BezierPatch<T, 3> reversed{4, 4, {}};
    for (int i = 3; i >= 0; --i)
      for (int j = 0; j < 4; ++j)
        reversed.control.push_back(p.control[static_cast<std::size_t>(i * 4 + j)]);
    const auto flipped = intersection(reversed, p, opt);
    ASSERT_EQ(flipped.status, Status::ok) << rng.trace();
    EXPECT_TRUE(flipped.curves.empty() && flipped.contacts.empty()) << rng.trace();
    EXPECT_EQ(area(flipped.coincident_a), 1.0) << rng.trace();
    EXPECT_EQ(area(flipped.coincident_b), 1.0) << rng.trace();
    // The half u in [0, 1/2] by de Casteljau in long double (the rows are the u direction).
    BezierPatch<T, 3> half{4, 4, p.control};
    for (int j = 0; j < 4; ++j) {
      long double b[4][3];
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) b[i][k] = p.control[static_cast<std::size_t>(i * 4 + j)][k];
      for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k)
          half.control[static_cast<std::size_t>(i * 4 + j)][k] = T(b[0][k]);
        for (int m = 0; m + 1 < 4 - i; ++m)
          for (int k = 0; k < 3; ++k) b[m][k] = (b[m][k] + b[m + 1][k]) / 2;
      }
    }
    const auto sub = intersection(half, p, opt);
    ASSERT_EQ(sub.status, Status::ok) << rng.trace();
    EXPECT_TRUE(sub.curves.empty() && sub.contacts.empty()) << rng.trace();
    EXPECT_EQ(area(sub.coincident_a), 1.0) << rng.trace();
    EXPECT_EQ(area(sub.coincident_b), 0.5) << rng.trace();
    for (const auto& b : sub.coincident_b) EXPECT_LE(double(b.hi.x), 0.5);
    // Power-of-two scaling (exact) leaves the parameter rectangles unchanged.
    for (const T k : {T(0x1p-7), T(0x1p9)}) {
      BezierPatch<T, 3> hs = half, ps = p;
      for (auto& c : hs.control) c = k * c;
      for (auto& c : ps.control) c = k * c;
      const auto scaled = intersection(hs, ps, opt);
      ASSERT_EQ(scaled.status, Status::ok);
      EXPECT_EQ(area(scaled.coincident_a), 1.0) << k;
      EXPECT_EQ(area(scaled.coincident_b), 0.5) << k;
      EXPECT_TRUE(scaled.curves.empty() && scaled.contacts.empty());
    }
    // Degree-elevated in u (Q_i = i/4 P_(i-1) + (1 - i/4) P_i), as a NURBS: the same surface.
    NurbsSurface<T, 3> up{4,
                          3,
                          5,
                          4,
                          {},
                          std::vector<T>(20, T(1)),
                          {0, 0, 0, 0, 0, 1, 1, 1, 1, 1},
                          {0, 0, 0, 0, 1, 1, 1, 1}};
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const long double t = i / 4.0L;
        Vec3<T> q{};
        for (int k = 0; k < 3; ++k) {
          const long double lo =
              i > 0 ? p.control[static_cast<std::size_t>((i - 1) * 4 + j)][k] : 0;
          const long double hi = i < 4 ? p.control[static_cast<std::size_t>(i * 4 + j)][k] : 0;
          q[k] = T(t * lo + (1 - t) * hi);
        }
        up.control.push_back(q);
      }
    const auto elevated = intersection(p, up, opt);
    ASSERT_EQ(elevated.status, Status::ok) << rng.trace();
    EXPECT_TRUE(elevated.curves.empty() && elevated.contacts.empty()) << rng.trace();
    EXPECT_EQ(area(elevated.coincident_a), 1.0) << rng.trace();
    EXPECT_EQ(area(elevated.coincident_b), 1.0) << rng.trace();
  }
  // Two plane patches sharing the strip 0 <= x <= 2 of z = 0: the halves u >= 1/2 of the
  // first and u <= 1/2 of the second.
  const BezierPatch<T, 3> right{2, 2, {{0, -2, 0}, {0, 2, 0}, {4, -2, 0}, {4, 2, 0}}};
  const auto strip = intersection(flat<T>(), right, opt);
  ASSERT_EQ(strip.status, Status::ok);
  EXPECT_TRUE(strip.curves.empty() && strip.contacts.empty());
  EXPECT_EQ(area(strip.coincident_a), 0.5);
  EXPECT_EQ(area(strip.coincident_b), 0.5);
  for (const auto& b : strip.coincident_a) EXPECT_GE(double(b.lo.x), 0.5);
  for (const auto& b : strip.coincident_b) EXPECT_LE(double(b.hi.x), 0.5);
}

TYPED_TEST(SurfaceContact, SmallLoopsHaveTheirClosedFormRadius) {
  using T = TypeParam;
  // z = delta - (x - c)^2 - (y - c)^2 cuts z = 0 in the circle of radius sqrt(delta) about
  // (c, c), and z = -((x - c)^2 + (y - c)^2) / 2 in the circle of radius sqrt(2 delta) at
  // height -delta; c = 1/8 puts its centre on the centre of a subdivision leaf (where
  // Gauss-Newton from the leaf centre stalls: the gradient vanishes there).
  for (const T s : {T(1), T(0x1p5)})
    for (const int e : {8, 20})
      for (const bool curved : {false, true}) {
        if (curved && (s != T(1) || e == 20)) continue;  // nearly parallel surfaces: costly
        const T delta = std::ldexp(T(1), -e), c = T(0.125);
        const double radius =
            std::ldexp(curved ? 2.0 : 1.0, -e / 2) / (curved ? std::sqrt(2.0) : 1.0);
        const double height = curved ? -double(delta) : 0.0;
        // On [-1, 1]^2 the other surface's leaves match the paraboloid's: the loop lies inside
        // one pair of leaves with a common centre.
        const auto r =
            curved ? intersection(paraboloid<T>(-1, delta, c, s), paraboloid<T>(T(-0.5), 0, c, s))
                   : intersection(paraboloid<T>(-1, delta, c, s), flat<T>(s, T(1)));
        ASSERT_EQ(r.status, Status::ok);
        ASSERT_EQ(r.curves.size(), 1u) << e << " " << s << " " << curved;
        const auto& cv = r.curves[0];
        EXPECT_TRUE(cv.closed) << e << " " << s;
        EXPECT_GE(cv.points.size(), 8u);
        double len = 0.0;
        for (std::size_t i = 0; i < cv.points.size(); ++i) {
          const auto& p = cv.points[i];
          const double rx = double(p.x) / double(s) - double(c),
                       ry = double(p.y) / double(s) - double(c);
          EXPECT_NEAR(std::hypot(rx, ry), radius, pick<T>(1e-5, 1e-9) + 1e-6 * radius);
          EXPECT_NEAR(double(p.z) / double(s), height, pick<T>(1e-5, 1e-9));
          len += double(length(cv.points[(i + 1) % cv.points.size()] - p)) / double(s);
        }
        // An inscribed polygon: shorter than the circle by at most 2%.
        EXPECT_LE(len, 2 * std::numbers::pi * radius * (1 + 1e-9));
        EXPECT_GE(len, 2 * std::numbers::pi * radius * 0.98);
      }
}

TYPED_TEST(SurfaceContact, NonFiniteAndInvalidInput) {
  using T = TypeParam;
  for (const T bad : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()}) {
    BezierPatch<T, 3> p = paraboloid<T>(1, 0);
    p.control[4].z = bad;
    EXPECT_EQ(intersection(p, flat<T>()).status, Status::non_finite_input);
    EXPECT_EQ(intersection(flat<T>(), p).status, Status::non_finite_input);
    NurbsSurface<T, 3> cyl = cylinder<T>();
    cyl.weights[1] = bad;
    const auto r = intersection(cyl, flat<T>());
    EXPECT_EQ(r.status, Status::non_finite_input);
    EXPECT_TRUE(r.curves.empty() && r.contacts.empty() && r.coincident_a.empty());
  }
  // Swapping the arguments swaps the parameters of contacts and coincident regions.
  const auto r = swapped(intersection(flat<T>(), paraboloid<T>(-1, 0)));
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_NEAR(double(r.contacts[0].param_a.x), 0.5, pick<T>(1e-5, 1e-9));
}

}  // namespace
namespace {
/// z = delta - rho^2 + k rho^4, rho^2 = (x - c)^2 + (y - c)^2, over [-1, 1]^2 as a biquartic
/// Bézier patch (power basis in u, v converted to Bernstein in long double).
template <class T>
BezierPatch<T, 3> ring_bump(long double delta, long double k, long double c) {
  // x - c = a0 + a1 u with a0 = -1 - c, a1 = 2; (x - c)^2 in powers of u.
  const long double a0 = -1 - c, a1 = 2;
  const long double sq[3] = {a0 * a0, 2 * a0 * a1, a1 * a1};
  long double p[5][5] = {};
  // rho^2 = sq(u) + sq(v); rho^4 = sq(u)^2 + 2 sq(u) sq(v) + sq(v)^2.
  p[0][0] += delta;
  for (int i = 0; i < 3; ++i) {
    p[i][0] -= sq[i];
    p[0][i] -= sq[i];
    for (int j = 0; j < 3; ++j) {
      p[i + j][0] += k * sq[i] * sq[j];
      p[0][i + j] += k * sq[i] * sq[j];
      p[i][j] += 2 * k * sq[i] * sq[j];
    }
  }
  const long double binom[5][5] = {{1}, {1, 1}, {1, 2, 1}, {1, 3, 3, 1}, {1, 4, 6, 4, 1}};
  BezierPatch<T, 3> out{5, 5, {}};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      long double z = 0;
      for (int a = 0; a <= i; ++a)
        for (int b = 0; b <= j; ++b)
          z += binom[i][a] / binom[4][a] * binom[j][b] / binom[4][b] * p[a][b];
      out.control.push_back({T(-1 + i / 2.0L), T(-1 + j / 2.0L), T(z)});
    }
  return out;
}

/// The height of a patch with x = 2u - 1, y = 2v - 1 at (x, y), by de Casteljau in long double.
template <class T>
long double height(const BezierPatch<T, 3>& p, long double x, long double y) {
  const long double u = (x + 1) / 2, v = (y + 1) / 2;
  std::vector<long double> row(static_cast<std::size_t>(p.rows));
  for (int i = 0; i < p.rows; ++i) {
    std::vector<long double> b(static_cast<std::size_t>(p.cols));
    for (int j = 0; j < p.cols; ++j)
      b[static_cast<std::size_t>(j)] = p.control[static_cast<std::size_t>(i * p.cols + j)].z;
    for (int r = 1; r < p.cols; ++r)
      for (int k = 0; k + r < p.cols; ++k)
        b[static_cast<std::size_t>(k)] =
            (1 - v) * b[static_cast<std::size_t>(k)] + v * b[static_cast<std::size_t>(k + 1)];
    row[static_cast<std::size_t>(i)] = b[0];
  }
  for (int r = 1; r < p.rows; ++r)
    for (int k = 0; k + r < p.rows; ++k)
      row[static_cast<std::size_t>(k)] =
          (1 - u) * row[static_cast<std::size_t>(k)] + u * row[static_cast<std::size_t>(k + 1)];
  return row[0];
}

TYPED_TEST(SurfaceContact, SmallLoopInsideALargerRing) {
  using T = TypeParam;
  // z = delta - rho^2 + 16 rho^4 about (1/8, 1/8) cuts z = 0 in two circles, rho^2 =
  // (1 -+ sqrt(1 - 64 delta)) / 32: a small loop inside a ring of radius about 1/4 through the
  // same leaves (Gauss-Newton from the leaf centres is drawn to the ring; the small loop is
  // found from the critical point of the gap at its centre).
  const double tol = pick<T>(1e-5, 1e-9);
  for (const int e : {8, 14, 20}) {
    // In float the rounded Bernstein coefficients (sixths) move the small circle of the last
    // case by ~2^-24 / (its slope 2^-9): beyond the length check (the residuals still hold).
    if (std::is_same_v<T, float> && e == 20) continue;
    const long double delta = std::ldexp(1.0L, -e);
    const BezierPatch<T, 3> bump = ring_bump<T>(delta, 16, 0.125L);
    const auto r = intersection(bump, flat<T>(T(1), T(1)));
    ASSERT_EQ(r.status, Status::ok);
    ASSERT_EQ(r.curves.size(), 2u) << e;
    const double root = std::sqrt(1 - 64 * double(delta));
    const double expected[2] = {std::sqrt((1 - root) / 32), std::sqrt((1 + root) / 32)};
    std::vector<double> lengths;
    for (const auto& c : r.curves) {
      EXPECT_TRUE(c.closed) << e;
      double len = 0.0, rmax = 0.0;
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        const auto& p = c.points[i];
        EXPECT_LE(std::fabs(double(p.z)), tol);
        EXPECT_LE(std::fabs(double(height(bump, p.x, p.y))), tol) << e;
        rmax = std::max(rmax, std::hypot(double(p.x) - 0.125, double(p.y) - 0.125));
        len += double(length(c.points[(i + 1) % c.points.size()] - p));
      }
      lengths.push_back(len);
    }
    std::sort(lengths.begin(), lengths.end());
    for (int k = 0; k < 2; ++k) {
      EXPECT_LE(lengths[static_cast<std::size_t>(k)], 2 * std::numbers::pi * expected[k] * 1.01)
          << e;
      EXPECT_GE(lengths[static_cast<std::size_t>(k)], 2 * std::numbers::pi * expected[k] * 0.98)
          << e;
    }
  }
}
}  // namespace
namespace {
TYPED_TEST(SurfaceContact, ClosedCurveOfContact) {
  using T = TypeParam;
  // z = 2 (rho^2 - 1/4)^2 = 1/8 - rho^2 + 2 rho^4 rests on z = 0 along the circle rho = 1/2: a
  // closed curve of contact (the contact system has rank 3 along it).
  // In float the rounded Bernstein coefficients (sixths) lift or sink the surface by ~2^-24,
  // far beyond the 2^-36 contact tolerance: the data no longer touch.
  if (std::is_same_v<T, float>) GTEST_SKIP() << "float data do not touch";
  const auto r = intersection(ring_bump<T>(0.125L, 2, 0), flat<T>(T(1), T(1)));
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_TRUE(r.contacts.empty());
  ASSERT_EQ(r.curves.size(), 1u);
  const auto& c = r.curves[0];
  EXPECT_TRUE(c.tangent);
  EXPECT_TRUE(c.closed);
  double len = 0.0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const auto& p = c.points[i];
    EXPECT_NEAR(std::hypot(double(p.x), double(p.y)), 0.5, 1e-9);
    EXPECT_NEAR(double(p.z), 0.0, 1e-9);
    len += double(length(c.points[(i + 1) % c.points.size()] - p));
  }
  EXPECT_LE(len, std::numbers::pi * (1 + 1e-9));
  EXPECT_GE(len, std::numbers::pi * 0.98);
}
}  // namespace
