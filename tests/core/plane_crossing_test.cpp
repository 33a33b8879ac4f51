// SPDX-License-Identifier: BSL-1.0
// core/plane_crossing.hpp: rank_plane_crossings against crossings computed in GMP rationals.
// Checks: the ranks follow the exact order of the chosen coordinate (equal coordinates, equal
// ranks; no gaps), for planes given by a normal and a constant and by three points, mixed in one
// call; every rounded coordinate within one ulp of the exact one; near ties far below the rounding
// of the points (crossings 2^-100 apart at 2^-40), exact ties (lattice crossings), a wide
// exponent range, given points (vertices in a plane) among segment crossings, power-of-two scale
// covariance, and a broken precondition (both ends on one side: the point a).

#include <locus/core/plane_crossing.hpp>

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <vector>

#include "support/typed.hpp"

namespace {

using locus::ExactPlane3;
using locus::PlaneCrossing3;
using locus::Vec3;
using locus_test::Rng;

using Q3 = std::array<mpq_class, 3>;

Q3 q3(const Vec3<double>& p) { return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)}; }

mpq_class plane_value(const ExactPlane3& pl, const Vec3<double>& x) {
  const Q3 v = q3(x);
  if (!pl.through_points) {
    const Q3 n = q3(pl.normal);
    return n[0] * v[0] + n[1] * v[1] + n[2] * v[2] - mpq_class(pl.constant);
  }
  const Q3 a = q3(pl.p0), b = q3(pl.p1), c = q3(pl.p2);
  const Q3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]},
      d{v[0] - a[0], v[1] - a[1], v[2] - a[2]};
  return d[0] * (u[1] * w[2] - u[2] * w[1]) + d[1] * (u[2] * w[0] - u[0] * w[2]) +
         d[2] * (u[0] * w[1] - u[1] * w[0]);
}

Q3 exact_point(const PlaneCrossing3& c) {
  if (c.plane == nullptr) return q3(c.a);
  const mpq_class fa = plane_value(*c.plane, c.a), fb = plane_value(*c.plane, c.b);
  const Q3 a = q3(c.a), b = q3(c.b);
  Q3 x;
  for (int k = 0; k < 3; ++k) x[k] = (fa * b[k] - fb * a[k]) / (fa - fb);
  return x;
}

// The ranks order the exact coordinates; each rounded coordinate is within one ulp.
void check(const std::vector<PlaneCrossing3>& cs, int axis) {
  std::vector<Q3> x;
  for (const PlaneCrossing3& c : cs) x.push_back(exact_point(c));
  for (std::size_t i = 0; i < cs.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double r = cs[i].point[k];
      const double ulp =
          std::nextafter(std::abs(r), std::numeric_limits<double>::infinity()) - std::abs(r);
      EXPECT_LE(abs(mpq_class(r) - x[i][k]), mpq_class(ulp)) << "crossing " << i << " axis " << k;
    }
    for (std::size_t j = 0; j < cs.size(); ++j) {
      const int want = cmp(x[i][axis], x[j][axis]);
      const int got = cs[i].rank < cs[j].rank ? -1 : (cs[i].rank > cs[j].rank ? 1 : 0);
      ASSERT_EQ(got, want < 0 ? -1 : (want > 0 ? 1 : 0)) << i << " " << j;
    }
  }
  std::size_t top = 0;
  for (const PlaneCrossing3& c : cs) top = std::max(top, c.rank);
  std::vector<bool> used(top + 1, false);
  for (const PlaneCrossing3& c : cs) used[c.rank] = true;
  for (bool u : used) EXPECT_TRUE(u) << "ranks have a gap";
}

// Segments from a to b with the plane's exact sides strictly opposite.
std::vector<PlaneCrossing3> random_crossings(Rng& rng, const ExactPlane3& pl, int n, double s) {
  std::vector<PlaneCrossing3> cs;
  while (static_cast<int>(cs.size()) < n) {
    const Vec3<double> a = rng.vec<double, 3>(-s, s), b = rng.vec<double, 3>(-s, s);
    if (sgn(plane_value(pl, a)) * sgn(plane_value(pl, b)) < 0) cs.push_back({&pl, a, b});
  }
  return cs;
}

TEST(CorePlaneCrossing, RandomCrossingsOfTwoPlanesRankExactly) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 40; ++trial) {
    const double s = std::ldexp(1.0, rng.uniform_int(-40, 40));
    // Through a point of the inner half of the cube, so that random segments cross it.
    const Vec3<double> n = rng.vec<double, 3>(-1, 1), inner = rng.vec<double, 3>(-s / 2, s / 2);
    const ExactPlane3 by_normal = ExactPlane3::from_normal(n, locus::dot(n, inner));
    const ExactPlane3 by_points = ExactPlane3::from_points(
        rng.vec<double, 3>(-s, s), rng.vec<double, 3>(-s, s), rng.vec<double, 3>(-s, s));
    std::vector<PlaneCrossing3> cs = random_crossings(rng, by_normal, 8, s);
    for (const PlaneCrossing3& c : random_crossings(rng, by_points, 8, s)) cs.push_back(c);
    cs.push_back({nullptr, rng.vec<double, 3>(-s, s), {}});
    const int axis = trial % 3;
    locus::rank_plane_crossings(cs, axis);
    check(cs, axis);
    if (HasFatalFailure()) return;
  }
}

TEST(CorePlaneCrossing, NearAndExactTiesAreSeparatedAndJoined) {
  // The plane x = 1 crosses the segment from (2, 0, 0) to (0, 2 e, 0) at y = e = 2^-40, and the
  // one from (0, 2 e, 0) to (2, 2^-99, 0) at y = e + 2^-100: the two round to the same point but
  // rank apart; a segment crossing at exactly y = e, and a given point there, rank with the first.
  const ExactPlane3 pl = ExactPlane3::from_normal({1, 0, 0}, 1);
  const double e = std::ldexp(1.0, -40), d = std::ldexp(1.0, -99);
  std::vector<PlaneCrossing3> cs = {
      {&pl, {2, 0, 0}, {0, 2 * e, 0}},
      {&pl, {0, 2 * e, 0}, {2, d, 0}},
      {&pl, {4, e, 0}, {-2, e, 0}},
      {nullptr, {1, e, 5}, {}},
  };
  locus::rank_plane_crossings(cs, 1);
  check(cs, 1);
  EXPECT_EQ(cs[0].rank, cs[2].rank);
  EXPECT_EQ(cs[0].rank, cs[3].rank);
  EXPECT_LT(cs[0].rank, cs[1].rank);
  EXPECT_EQ(cs[0].point, cs[1].point);  // the rounded points coincide
}

TEST(CorePlaneCrossing, PowerOfTwoScalingKeepsRanksAndScalesPoints) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const ExactPlane3 pl = ExactPlane3::from_points({0, 0, 0}, {1, 0.5, 0.25}, {0.125, 1, -1});
  std::vector<PlaneCrossing3> cs = random_crossings(rng, pl, 12, 1.0);
  locus::rank_plane_crossings(cs, 2);
  for (const int k : {-600, 300}) {
    const double f = std::ldexp(1.0, k);
    const ExactPlane3 scaled = ExactPlane3::from_points(f * pl.p0, f * pl.p1, f * pl.p2);
    std::vector<PlaneCrossing3> cs2;
    for (const PlaneCrossing3& c : cs) cs2.push_back({&scaled, f * c.a, f * c.b});
    locus::rank_plane_crossings(cs2, 2);
    for (std::size_t i = 0; i < cs.size(); ++i) {
      EXPECT_EQ(cs2[i].rank, cs[i].rank);
      EXPECT_EQ(cs2[i].point, f * cs[i].point) << k;
    }
  }
}

TEST(CorePlaneCrossing, BrokenPreconditionGivesTheStartPoint) {
  const ExactPlane3 pl = ExactPlane3::from_normal({0, 0, 1}, 0);
  std::vector<PlaneCrossing3> cs = {{&pl, {1, 2, 3}, {4, 5, 6}}, {&pl, {0, 0, 1}, {0, 0, -1}}};
  locus::rank_plane_crossings(cs, 2);
  EXPECT_EQ(cs[0].point, (Vec3<double>{1, 2, 3}));
  EXPECT_EQ(cs[1].point, (Vec3<double>{0, 0, 0}));
  EXPECT_GT(cs[0].rank, cs[1].rank);
  std::vector<PlaneCrossing3> none;
  locus::rank_plane_crossings(none, 0);  // empty: nothing to do
}

}  // namespace
