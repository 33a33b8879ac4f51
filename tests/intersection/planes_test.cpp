// SPDX-License-Identifier: BSL-1.0
// Row int3.planes: two planes and three planes, float and double. Oracle: ranks of the normal
// matrix N and of the augmented matrix [N | c] by Gaussian elimination in GMP rationals
// (Rouché-Capelli: consistent iff equal ranks; the solution set has dimension 3 - rank), which
// names the expected kind independently of the library's minors. Checks: the kind; intersects()
// agrees; constructed points lie on every plane within the stated residual bound (a few eps of
// |n| |p| + |c| over the sine of the angle between the planes); a line's two points are
// distinct, a plane's three are not collinear. Inputs: every configuration of the book's table of
// three planes built explicitly, integer grids (many parallel, coincident and pencil cases),
// random planes (rounded data), exact motions and power-of-two scaling (kinds unchanged),
// degenerate normals and NaN/Inf.

#include <locus/intersection/plane_plane.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "support/scale_covariance.hpp"
#include "support/typed.hpp"

#include <gmpxx.h>

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class IntersectionPlanes : public ::testing::Test {};
TYPED_TEST_SUITE(IntersectionPlanes, locus_test::RealTypes);

// Rank of a small rational matrix (rows x cols).
int rank(std::vector<std::vector<mpq_class>> m) {
  int r = 0;
  const int rows = static_cast<int>(m.size()), cols = static_cast<int>(m[0].size());
  for (int c = 0; c < cols && r < rows; ++c) {
    int p = r;
    while (p < rows && m[static_cast<std::size_t>(p)][static_cast<std::size_t>(c)] == 0) ++p;
    if (p == rows) continue;
    std::swap(m[static_cast<std::size_t>(p)], m[static_cast<std::size_t>(r)]);
    for (int i = 0; i < rows; ++i) {
      if (i == r) continue;
      const mpq_class f = m[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)] /
                          m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
      for (int j = 0; j < cols; ++j)
        m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] -=
            f * m[static_cast<std::size_t>(r)][static_cast<std::size_t>(j)];
    }
    ++r;
  }
  return r;
}

// The expected kind from the ranks.
template <class T>
Kind expected(const std::vector<Plane3<T>>& pl) {
  std::vector<std::vector<mpq_class>> n, a;
  for (const auto& p : pl) {
    n.push_back({mpq_class(double(p.normal.x)), mpq_class(double(p.normal.y)),
                 mpq_class(double(p.normal.z))});
    a.push_back(n.back());
    a.back().push_back(mpq_class(double(p.constant)));
  }
  const int rn = rank(n), ra = rank(a);
  if (rn != ra) return Kind::empty;
  return rn == 3 ? Kind::point : (rn == 2 ? Kind::line : Kind::plane);
}

template <class T>
void check(const std::vector<Plane3<T>>& pl, double* worst = nullptr) {
  const PlanesIntersection<T> r =
      pl.size() == 2 ? intersection(pl[0], pl[1]) : intersection(pl[0], pl[1], pl[2]);
  const bool meets = pl.size() == 2 ? intersects(pl[0], pl[1]) : intersects(pl[0], pl[1], pl[2]);
  const Kind k = expected(pl);
  ASSERT_EQ(to_string(r.kind), to_string(k));
  EXPECT_EQ(meets, k != Kind::empty);
  ASSERT_EQ(r.count, k == Kind::empty ? 0 : (k == Kind::point ? 1 : (k == Kind::line ? 2 : 3)));
  // Sine of the smallest angle between two non-parallel normals (1 if all parallel).
  double sine = 1;
  for (std::size_t i = 0; i < pl.size(); ++i)
    for (std::size_t j = i + 1; j < pl.size(); ++j) {
      const Vec3<double> a = normalize(vec_cast<double>(pl[i].normal)),
                         b = normalize(vec_cast<double>(pl[j].normal));
      const double s = length(cross(a, b));
      if (s > 0) sine = std::min(sine, s);
    }
  if (pl.size() == 3 && k == Kind::point) {
    const Vec3<double> a = normalize(vec_cast<double>(pl[0].normal)),
                       b = normalize(vec_cast<double>(pl[1].normal)),
                       c = normalize(vec_cast<double>(pl[2].normal));
    sine = std::min(sine, std::abs(dot(a, cross(b, c))));
  }
  const double eps = double(eps_v<T>);
  for (int i = 0; i < r.count; ++i) {
    const Vec3<T> p = r.point[static_cast<std::size_t>(i)];
    ASSERT_TRUE(is_finite(p));
    for (const auto& q : pl) {
      // Residual in exact arithmetic of the rounded point.
      const mpq_class v = mpq_class(double(q.normal.x)) * mpq_class(double(p.x)) +
                          mpq_class(double(q.normal.y)) * mpq_class(double(p.y)) +
                          mpq_class(double(q.normal.z)) * mpq_class(double(p.z)) -
                          mpq_class(double(q.constant));
      const double scale =
          length(vec_cast<double>(q.normal)) * double(max_abs(p)) + std::abs(double(q.constant));
      const double res = std::abs(v.get_d()) / (eps * std::max(scale, 1e-300));
      EXPECT_LE(res, 16.0 / sine) << "point " << i;
      if (worst) *worst = std::max(*worst, res * sine);
    }
  }
  if (r.kind == Kind::line) {
    EXPECT_NE(r.point[0], r.point[1]);
  }
  if (r.kind == Kind::plane) {
    EXPECT_GT(length(cross(vec_cast<double>(r.point[1] - r.point[0]),
                           vec_cast<double>(r.point[2] - r.point[0]))),
              0.0);
  }
}

// Every configuration of the book's table of three planes (and two planes), built exactly.
TYPED_TEST(IntersectionPlanes, BookTableOfConfigurations) {
  using T = TypeParam;
  using P = Plane3<T>;
  const P x0{{1, 0, 0}, 0}, x1{{1, 0, 0}, 1}, x0b{{2, 0, 0}, 0}, y0{{0, 1, 0}, 0}, z0{{0, 0, 1}, 0},
      d{{1, 1, 0}, 0}, d1{{1, 1, 0}, 3};
  const struct {
    std::vector<P> pl;
    Kind kind;
  } cases[] = {
      {{x0, y0}, Kind::line},                    // two crossing planes
      {{x0, x1}, Kind::empty},                   // parallel, distinct
      {{x0, x0b}, Kind::plane},                  // coincident (different scaling of the same plane)
      {{x0, y0, z0}, Kind::point},               // three independent normals
      {{x0, y0, d}, Kind::line},                 // a pencil: three planes through the z axis
      {{x0, y0, d1}, Kind::empty},               // a prism: three lines parallel to z
      {{x0, x0b, y0}, Kind::line},               // two coincident, one crossing
      {{x0, x0b, x1}, Kind::empty},              // two coincident, one parallel
      {{x0, x1, y0}, Kind::empty},               // two parallel distinct, one crossing
      {{x0, x1, P{{1, 0, 0}, 2}}, Kind::empty},  // three parallel distinct
      {{x0, x0b, P{{-3, 0, 0}, 0}}, Kind::plane},  // three coincident
  };
  for (const auto& c : cases) {
    check<T>(c.pl);
    EXPECT_EQ(c.pl.size() == 2 ? intersection(c.pl[0], c.pl[1]).kind
                               : intersection(c.pl[0], c.pl[1], c.pl[2]).kind,
              c.kind);
  }
  const auto p = intersection(P{{1, 0, 0}, 1}, P{{0, 1, 0}, 2}, P{{0, 0, 1}, 3});
  EXPECT_EQ(p.point[0], (Vec3<T>{1, 2, 3}));
}

TYPED_TEST(IntersectionPlanes, IntegerGridAgainstRanks) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int kinds[32] = {};
  for (int i = 0; i < 20000; ++i) {
    const auto g = [&] {
      Vec3<T> n{T(rng.uniform_int(-1, 1)), T(rng.uniform_int(-1, 1)), T(rng.uniform_int(-1, 1))};
      if (n == Vec3<T>{}) n.z = 1;
      return Plane3<T>{n, T(rng.uniform_int(-1, 1))};
    };
    std::vector<Plane3<T>> pl = {g(), g()};
    if (i % 2) pl.push_back(g());
    check<T>(pl);
    ++kinds[static_cast<int>(expected(pl)) + (i % 2 ? 16 : 0)];
    if (::testing::Test::HasFatalFailure()) return;
  }
  for (const Kind k : {Kind::empty, Kind::line, Kind::plane}) {
    EXPECT_GT(kinds[static_cast<int>(k)], 100);
    EXPECT_GT(kinds[static_cast<int>(k) + 16], k == Kind::plane ? 5 : 100);  // 3 coincident: rare
  }
  EXPECT_GT(kinds[static_cast<int>(Kind::point) + 16], 1000);
}

TYPED_TEST(IntersectionPlanes, RandomPlanesResiduals) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  double worst = 0;
  for (int i = 0; i < 6000; ++i) {
    std::vector<Plane3<T>> pl;
    for (int k = 0; k < 2 + i % 2; ++k)
      pl.push_back(plane_from_point_normal(
          rng.vec<T, 3>(-1, 1), rng.unit<T, 3>() * T(std::ldexp(1.0, rng.uniform_int(-20, 20)))));
    check<T>(pl, &worst);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::printf("[ measured ] worst residual * sine / (eps (|n| |p| + |c|)) = %.3g\n", worst);
}

// Exact motions (axis permutations, sign flips) and power-of-two scaling keep the kind.
TYPED_TEST(IntersectionPlanes, MotionsAndScaling) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 2000; ++i) {
    std::vector<Plane3<T>> pl;
    for (int k = 0; k < 3; ++k) {
      Vec3<T> n{T(rng.uniform_int(-1, 1)), T(rng.uniform_int(-1, 1)), T(rng.uniform_int(-1, 1))};
      if (n == Vec3<T>{}) n.x = 1;
      pl.push_back({n, T(rng.uniform_int(-2, 2))});
    }
    const Kind k2 = intersection(pl[0], pl[1]).kind, k3 = intersection(pl[0], pl[1], pl[2]).kind;
    const int s = rng.uniform_int(-60, 60);
    std::vector<Plane3<T>> m;
    for (const auto& p : pl)  // permute (x, y, z) -> (y, z, x), flip y, scale by 2^s
      m.push_back({Vec3<T>{p.normal.y, -p.normal.z, p.normal.x}, std::ldexp(p.constant, s)});
    EXPECT_EQ(intersection(m[0], m[1]).kind, k2);
    EXPECT_EQ(intersection(m[0], m[1], m[2]).kind, k3);
  }
}

TYPED_TEST(IntersectionPlanes, DegenerateAndNonFinite) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Plane3<T> x{{1, 0, 0}, 0}, y{{0, 1, 0}, 0}, zero{{0, 0, 0}, 0};
  EXPECT_EQ(intersection(x, zero).kind, Kind::empty);
  EXPECT_FALSE(intersects(zero, zero));
  EXPECT_EQ(intersection(x, y, zero).kind, Kind::empty);
  for (const T b : {nan, inf}) {
    EXPECT_EQ(intersection(x, Plane3<T>{{b, 1, 0}, 0}).kind, Kind::empty);
    EXPECT_EQ(intersection(x, Plane3<T>{{0, 1, 0}, b}).kind, Kind::empty);
    EXPECT_FALSE(intersects(x, y, Plane3<T>{{0, 0, 1}, b}));
  }
}

}  // namespace
