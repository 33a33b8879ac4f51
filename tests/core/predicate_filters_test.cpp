// SPDX-License-Identifier: BSL-1.0
// Tests for core/detail/predicate_filters.hpp: the stage-A filters, the semi-static insphere
// bound and the lattice shortcuts decide only with the exact sign (GMP rationals), and the
// lattice shortcuts decide on exactly degenerate grids.

#include <locus/core/detail/predicate_filters.hpp>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <vector>

namespace {

using namespace locus;

mpq_class q(double x) { return mpq_class(x); }

int sign_int(double x) { return (x > 0.0) - (x < 0.0); }

int exact_orient3d(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                   const Vec3<double>& d) {
  const mpq_class ux = q(b.x) - q(a.x), uy = q(b.y) - q(a.y), uz = q(b.z) - q(a.z);
  const mpq_class vx = q(c.x) - q(a.x), vy = q(c.y) - q(a.y), vz = q(c.z) - q(a.z);
  const mpq_class wx = q(d.x) - q(a.x), wy = q(d.y) - q(a.y), wz = q(d.z) - q(a.z);
  const mpq_class det =
      ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
  return sgn(det);
}

int exact_incircle(const Vec2<double>& a, const Vec2<double>& b, const Vec2<double>& c,
                   const Vec2<double>& d) {
  const Vec2<double>* p[3] = {&a, &b, &c};
  mpq_class x[3], y[3], l[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = q(p[i]->x) - q(d.x);
    y[i] = q(p[i]->y) - q(d.y);
    l[i] = x[i] * x[i] + y[i] * y[i];
  }
  const mpq_class det = l[0] * (x[1] * y[2] - x[2] * y[1]) + l[1] * (x[2] * y[0] - x[0] * y[2]) +
                        l[2] * (x[0] * y[1] - x[1] * y[0]);
  return sgn(det);
}

// Core's insphere sign: the negation of det[p - e, |p - e|^2] over p = a, b, c, d.
int exact_insphere(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                   const Vec3<double>& d, const Vec3<double>& e) {
  const Vec3<double>* p[4] = {&a, &b, &c, &d};
  mpq_class m[4][4];
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) m[i][k] = q((*p[i])[k]) - q(e[k]);
    m[i][3] = m[i][0] * m[i][0] + m[i][1] * m[i][1] + m[i][2] * m[i][2];
  }
  // 4x4 determinant by cofactors along the last column.
  auto det3 = [&](int r0, int r1, int r2) -> mpq_class {
    return m[r0][0] * (m[r1][1] * m[r2][2] - m[r1][2] * m[r2][1]) -
           m[r0][1] * (m[r1][0] * m[r2][2] - m[r1][2] * m[r2][0]) +
           m[r0][2] * (m[r1][0] * m[r2][1] - m[r1][1] * m[r2][0]);
  };
  const mpq_class det = -m[0][3] * det3(1, 2, 3) + m[1][3] * det3(0, 2, 3) -
                        m[2][3] * det3(0, 1, 3) + m[3][3] * det3(0, 1, 2);
  return -sgn(det);
}

// Nearly degenerate points: on a plane / circle / sphere up to a rounding, or on a small grid.
struct Gen {
  std::mt19937_64 rng;
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  double grid(int k, double unit) {
    return unit * double(std::uniform_int_distribution<int>(-k, k)(rng));
  }
};

TEST(PredicateFilters, Orient3dLanesFloatBoundDecidesOnlyTheExactSign) {
  // det3_stage_a<float> on float scalars (the lanes' arithmetic, one lane).
  Gen g{std::mt19937_64(21)};
  int decided = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Vec3<float> p[4];
    const bool flat = trial % 2 == 0;
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) p[i][k] = float(g.uniform(-1.0, 1.0));
    if (flat) {  // d near the plane of a, b, c, then rounded to float
      const double s = g.uniform(-1, 1), t = g.uniform(-1, 1);
      for (int k = 0; k < 3; ++k)
        p[3][k] = float(double(p[0][k]) + s * (double(p[1][k]) - double(p[0][k])) +
                        t * (double(p[2][k]) - double(p[0][k])));
    }
    const auto abs = [](float x) { return std::abs(x); };
    const detail::StageA<float> f =
        detail::det3_stage_a<float>(p[1] - p[0], p[2] - p[0], p[3] - p[0], abs);
    const int exact = exact_orient3d(detail::to_double(p[0]), detail::to_double(p[1]),
                                     detail::to_double(p[2]), detail::to_double(p[3]));
    if (std::abs(f.det) > f.bound) {
      ++decided;
      ASSERT_EQ(f.det > 0 ? 1 : -1, exact) << "trial " << trial;
    }
  }
  EXPECT_GT(decided, 10000);
}

TEST(PredicateFilters, StageAAndSemiStaticDecideOnlyTheExactSign) {
  Gen g{std::mt19937_64(22)};
  for (int trial = 0; trial < 4000; ++trial) {
    const bool near = trial % 2 == 0;
    Vec3<double> p[5];
    for (auto& v : p)
      for (int k = 0; k < 3; ++k) v[k] = g.uniform(-1, 1);
    if (near) {  // e near the sphere through a, b, c, d: on the unit sphere, all rounded
      for (auto& v : p) {
        const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        v = Vec3<double>{v.x / n, v.y / n, v.z / n};
      }
    }
    const detail::InsphereTerms t = detail::insphere_terms(p[0], p[1], p[2], p[3], p[4]);
    const int exact = exact_insphere(p[0], p[1], p[2], p[3], p[4]);
    const detail::StageA<double> full = detail::insphere_stage_a(p[0], p[1], p[2], p[3], p[4]);
    const detail::StageA<double> semi = detail::insphere_stage_a_semi_static(t);
    EXPECT_GE(semi.bound, full.bound * (1 - 0x1p-40)) << "trial " << trial;
    if (detail::certain(full)) {
      ASSERT_EQ(sign_int(full.det), exact) << "trial " << trial;
    }
    if (detail::certain(semi)) {
      ASSERT_EQ(sign_int(semi.det), exact) << "trial " << trial;
    }

    const Vec2<double> a{p[0].x, p[0].y}, b{p[1].x, p[1].y}, c{p[2].x, p[2].y}, d{p[3].x, p[3].y};
    const detail::StageA<double> ic = detail::incircle_stage_a(a, b, c, d);
    if (detail::certain(ic)) {
      ASSERT_EQ(sign_int(ic.det), exact_incircle(a, b, c, d));
    }
    const detail::StageA<double> o3 = detail::orient3d_stage_a(p[0], p[1], p[2], p[3]);
    if (detail::certain(o3)) {
      ASSERT_EQ(sign_int(o3.det), exact_orient3d(p[0], p[1], p[2], p[3]));
    }
  }
}

TEST(PredicateFilters, LatticeShortcutsAreExactOnGrids) {
  Gen g{std::mt19937_64(23)};
  int zeros = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // A small grid at a random scale and offset (multiples of the unit), so that cocircular and
    // cospherical configurations are frequent.
    const double unit = std::ldexp(1.0, std::uniform_int_distribution<int>(-60, 60)(g.rng));
    const double offset = g.grid(1000, unit);
    Vec3<double> p[5];
    for (auto& v : p)
      for (int k = 0; k < 3; ++k) v[k] = offset + g.grid(2, unit);
    const std::optional<detail::InsphereTerms> t =
        detail::insphere_lattice(p[0], p[1], p[2], p[3], p[4]);
    const int ins = exact_insphere(p[0], p[1], p[2], p[3], p[4]);
    if (t) {
      ASSERT_EQ(-sign_int(t->det), ins) << "trial " << trial;
    }
    const std::optional<Sign> o = detail::orient3d_lattice(p[0], p[1], p[2], p[3]);
    if (o) {
      ASSERT_EQ(int(*o), exact_orient3d(p[0], p[1], p[2], p[3]));
    }
    const Vec2<double> a{p[0].x, p[0].y}, b{p[1].x, p[1].y}, c{p[2].x, p[2].y}, d{p[3].x, p[3].y};
    const std::optional<Sign> ic = detail::incircle_lattice(a, b, c, d);
    if (ic) {
      ASSERT_EQ(int(*ic), exact_incircle(a, b, c, d));
      zeros += *ic == Sign::zero;
    }
    // Not all equal: the shortcut must apply (exact differences on a small lattice).
    bool distinct = false;
    for (int i = 0; i < 4; ++i)
      distinct |= p[i].x != p[4].x || p[i].y != p[4].y || p[i].z != p[4].z;
    if (distinct) {
      EXPECT_TRUE(t.has_value()) << "trial " << trial;
    }
  }
  EXPECT_GT(zeros, 100);
  // Off the lattice (an odd last bit far below the spread): no shortcut.
  const Vec2<double> a{0, 0}, b{1, 0}, c{0, 1}, d{1.0 + 0x1p-40, 1};
  EXPECT_FALSE(detail::incircle_lattice(a, b, c, d).has_value());
}

TEST(PredicateFilters, PointSetLattice) {
  std::vector<Vec3<float>> grid;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      grid.push_back(Vec3<float>{float(i), float(j), float(i + j) * 0.5f});
  EXPECT_TRUE(detail::points_on_insphere_lattice(std::span<const Vec3<float>>(grid)));
  grid.push_back(Vec3<float>{0.1f, 0, 0});
  EXPECT_FALSE(detail::points_on_insphere_lattice(std::span<const Vec3<float>>(grid)));
  grid.pop_back();
  grid.push_back(Vec3<float>{600, 0, 0});  // a coarser lattice: 0.5 is no multiple of q = 2
  EXPECT_FALSE(detail::points_on_insphere_lattice(std::span<const Vec3<float>>(grid)));
  EXPECT_FALSE(detail::points_on_insphere_lattice(std::span<const Vec3<float>>()));
}

}  // namespace
