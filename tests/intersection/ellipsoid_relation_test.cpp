// SPDX-License-Identifier: BSL-1.0
// Row int3.surface-surface: the exact ellipsoid-ellipsoid relation. Oracles: spheres (dyadic
// centres and radii, stored as ellipsoids with coordinate or Pythagorean-rotated axes) against
// GMP rational sphere arithmetic, including tangencies and gaps of 2^-108; constructed
// tangencies of rotated ellipsoids (exact by construction) and their 2^-45 perturbations; random
// rotated ellipsoids against a long-double dense sampling of the first boundary (decisive draws)
// and the former floating-point method; swap symmetry, scaling of positions and of the stored
// axes by powers of two, equal sets stored differently, and bad input.

#include <locus/intersection/ellipsoid_ellipsoid.hpp>

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;
using R = RegionRelation;

template <class T>
class EllipsoidRelation : public ::testing::Test {};
TYPED_TEST_SUITE(EllipsoidRelation, locus_test::RealTypes);

R swapped(R r) {
  switch (r) {
    case R::a_contains_b:
      return R::b_contains_a;
    case R::b_contains_a:
      return R::a_contains_b;
    case R::a_contains_b_touching:
      return R::b_contains_a_touching;
    case R::b_contains_a_touching:
      return R::a_contains_b_touching;
    default:
      return r;
  }
}

/// Relation of two balls with rational data (GMP): |c1 - c0|^2 against (r0 +- r1)^2.
R ball_oracle(const mpq_class (&c0)[3], const mpq_class& r0, const mpq_class (&c1)[3],
              const mpq_class& r1) {
  mpq_class d2 = 0;
  for (int i = 0; i < 3; ++i) d2 += (c1[i] - c0[i]) * (c1[i] - c0[i]);
  if (d2 == 0 && r0 == r1) return R::equal;
  const int out = sgn(d2 - (r0 + r1) * (r0 + r1)), in = sgn(d2 - (r0 - r1) * (r0 - r1));
  if (out > 0) return R::separated;
  if (out == 0) return R::touching;
  if (in > 0) return R::overlapping;
  if (in < 0) return r0 > r1 ? R::a_contains_b : R::b_contains_a;
  return r0 > r1 ? R::a_contains_b_touching : R::b_contains_a_touching;
}

template <class T>
Ellipsoid3<T> ball(const Vec3<T>& c, T r) {
  return {c, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {r, r, r}};
}
/// The same ball with the exact orthogonal axes (3,4,0), (-4,3,0), (0,0,5) (length 5).
template <class T>
Ellipsoid3<T> rotated_ball(const Vec3<T>& c, T r) {
  return {c, {{3, 4, 0}, {-4, 3, 0}, {0, 0, 5}}, {5 * r, 5 * r, 5 * r}};
}

/// The root-structure decision alone, without the cheap certificates.
template <class T>
R full_path(const Ellipsoid3<T>& a, const Ellipsoid3<T>& b) {
  using V = Vec3<double>;
  const V aa[3] = {vec_cast<double>(a.axis[0]), vec_cast<double>(a.axis[1]),
                   vec_cast<double>(a.axis[2])};
  const V ba[3] = {vec_cast<double>(b.axis[0]), vec_cast<double>(b.axis[1]),
                   vec_cast<double>(b.axis[2])};
  return detail::quadric_pair3::ellipsoid_relation(
      vec_cast<double>(a.center), aa, vec_cast<double>(a.extent), vec_cast<double>(b.center), ba,
      vec_cast<double>(b.extent), false);
}

template <class T>
void expect_both_orders(const Ellipsoid3<T>& a, const Ellipsoid3<T>& b, R want,
                        const std::string& what) {
  EXPECT_EQ(relation(a, b), want) << what;
  EXPECT_EQ(full_path(a, b), want) << what << " (root structure alone)";
  EXPECT_EQ(relation(b, a), swapped(want)) << what;
  EXPECT_EQ(intersects(a, b), want != R::separated) << what;
}

TYPED_TEST(EllipsoidRelation, SpheresAgainstRationalOracle) {
  using T = TypeParam;
  Rng rng(71);
  SCOPED_TRACE(rng.trace());
  int kinds[9] = {};
  for (int iter = 0; iter < 28; ++iter) {
    // Small dyadic data so that every relation, tangencies included, occurs; five in seven pairs
    // are 3-4-5 configurations tangent from outside or inside either way, equal, or nested.
    const T sc = T(std::ldexp(1.0, rng.uniform_int(-3, 3)));
    Vec3<T> c0{T(rng.uniform_int(-4, 4)), T(rng.uniform_int(-4, 4)), T(rng.uniform_int(-4, 4))};
    Vec3<T> c1{T(rng.uniform_int(-4, 4)), T(rng.uniform_int(-4, 4)), T(rng.uniform_int(-4, 4))};
    T r0 = T(rng.uniform_int(1, 6)), r1 = T(rng.uniform_int(1, 6));
    const int mode = iter % 7;
    if (mode < 3) {
      const int k = rng.uniform_int(1, 2);
      c1 = c0 + Vec3<T>{T(3 * k), 0, T(4 * k)};
      r0 = T(rng.uniform_int(1, 5 * k - 1));
      r1 = mode == 0 ? T(5 * k) - r0 : T(5 * k) + r0;
      if (mode == 2) std::swap(r0, r1);
    }
    if (mode == 3) {
      c1 = c0;
      r1 = r0;
    }
    if (mode == 4) {  // strictly nested either way
      c1 = c0 + Vec3<T>{1, 0, 0};
      if (iter % 2 == 0)
        r1 = r0 + T(3);
      else
        r0 = r1 + T(3);
    }
    c0 = sc * c0;
    c1 = sc * c1;
    r0 = sc * r0;
    r1 = sc * r1;
    mpq_class q0[3], q1[3];
    for (int i = 0; i < 3; ++i) {
      q0[i] = mpq_class(double(c0[i]));
      q1[i] = mpq_class(double(c1[i]));
    }
    const R want = ball_oracle(q0, mpq_class(double(r0)), q1, mpq_class(double(r1)));
    ++kinds[int(want)];
    const std::string what = "iter " + std::to_string(iter);
    expect_both_orders(ball(c0, r0), ball(c1, r1), want, what);
    if (iter % 2 == 1)
      expect_both_orders(rotated_ball(c0, r0), ball(c1, r1), want, what + " rotated");
  }
  for (R r : {R::separated, R::touching, R::overlapping, R::a_contains_b, R::b_contains_a,
              R::a_contains_b_touching, R::b_contains_a_touching, R::equal})
    EXPECT_GT(kinds[int(r)], 0) << int(r);
}

TYPED_TEST(EllipsoidRelation, NearTangentSpheres) {
  using T = TypeParam;
  // x^2/4 + y^2 + z^2 <= 1 and the unit ball at (3,0,0) touch at (2,0,0); a relative shift of
  // one float ulp (2^-21 at 3) or 2^-45 (double) separates or overlaps them.
  const Ellipsoid3<T> e{{0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {2, 1, 1}};
  const T gap = std::is_same_v<T, float> ? T(0x1p-21) : T(0x1p-45);
  expect_both_orders(e, ball<T>({3, 0, 0}, 1), R::touching, "tangent");
  expect_both_orders(e, ball<T>({3 + 3 * gap, 0, 0}, 1), R::separated, "gap");
  expect_both_orders(e, ball<T>({3 - 3 * gap, 0, 0}, 1), R::overlapping, "overlap");
  expect_both_orders(e, ball<T>({3, 0, 0}, 1 + gap), R::overlapping, "larger");
  // Inside, tangent at (2,0,0): a ball of radius 1/4 (below the curvature radius 1/2 there).
  expect_both_orders(e, ball<T>({T(1.75), 0, 0}, T(0.25)), R::a_contains_b_touching, "inner");
  expect_both_orders(e, ball<T>({T(1.75) - gap, 0, 0}, T(0.25)), R::a_contains_b, "inner gap");
  expect_both_orders(e, ball<T>({T(1.75) + gap, 0, 0}, T(0.25)), R::overlapping, "inner out");
  // The former test: a half-size ellipsoid tangent inside at (2,0,0), and outside at (2,0,0).
  const Ellipsoid3<T> half_in{{1, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, T(0.5), T(0.5)}};
  const Ellipsoid3<T> half_out{{3, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, T(0.5), T(0.5)}};
  expect_both_orders(e, half_in, R::a_contains_b_touching, "half inside");
  expect_both_orders(e, half_out, R::touching, "half outside");
  if constexpr (std::is_same_v<T, double>) {
    // Balls whose distance misses internal tangency by 2^-108 in d^2: the pencil's two roots
    // lie within an ulp of each other (the root-separating zoom decides).
    const double r1 = 0.5 - 0x1p-54;
    const mpq_class q0[3] = {0, 0, 0};
    for (double cy : {0x1p-27, 0x1p-27 + 0x1p-60, 0x1p-27 - 0x1p-60}) {
      const mpq_class q1[3] = {mpq_class(0.5), mpq_class(cy), 0};
      const R want = ball_oracle(q0, 1, q1, mpq_class(r1));
      expect_both_orders(ball<double>({0, 0, 0}, 1), ball<double>({0.5, cy, 0}, r1), want,
                         "cy " + std::to_string(cy));
    }
    // Tangent inside exactly (cz = 2^-54), or missing it by about 2^-133 and 2^-158 in d^2: the
    // two roots share a double cell and are separated by zooming.
    int seen[9] = {};
    for (double cz : {0x1p-54, 0x1p-54 - 0x1p-80, 0x1p-54 + 0x1p-80, 0x1p-54 - 0x1p-105}) {
      const mpq_class q1[3] = {mpq_class(0.5), mpq_class(0x1p-27), mpq_class(cz)};
      const R want = ball_oracle(q0, 1, q1, mpq_class(r1));
      ++seen[int(want)];
      expect_both_orders(ball<double>({0, 0, 0}, 1), ball<double>({0.5, 0x1p-27, cz}, r1), want,
                         "cz " + std::to_string(cz));
    }
    EXPECT_EQ(seen[int(R::a_contains_b_touching)], 1);
    EXPECT_EQ(seen[int(R::a_contains_b)], 2);
    EXPECT_EQ(seen[int(R::overlapping)], 1);
  }
}

TYPED_TEST(EllipsoidRelation, RotatedConstructedTangencies) {
  using T = TypeParam;
  // Semi-axes 10, 8, 8 along (3,4,0)/5, (-4,3,0)/5, (0,0,1), stored with the exact axes of
  // length 5 and extents times 5. The ball of radius 5 centred at 15 (3,4,0)/5 touches the
  // vertex 10 (3,4,0)/5 from outside; centred at 5 (3,4,0)/5 from inside (radius 5 below the
  // curvature radius 8^2/10 there).
  const Ellipsoid3<T> e{{0, 0, 0}, {{3, 4, 0}, {-4, 3, 0}, {0, 0, 5}}, {50, 40, 40}};
  const T gap = std::is_same_v<T, float> ? T(0x1p-20) : T(0x1p-45);
  expect_both_orders(e, ball<T>({9, 12, 0}, 5), R::touching, "outside");
  expect_both_orders(e, ball<T>({9, 12, 0}, 5 - 8 * gap), R::separated, "outside gap");
  expect_both_orders(e, ball<T>({9, 12, 0}, 5 + 8 * gap), R::overlapping, "outside overlap");
  expect_both_orders(e, ball<T>({3, 4, 0}, 5), R::a_contains_b_touching, "inside");
  expect_both_orders(e, ball<T>({3, 4, 0}, 5 - 8 * gap), R::a_contains_b, "inside gap");
  expect_both_orders(e, ball<T>({3, 4, 0}, 5 + 8 * gap), R::overlapping, "inside overlap");
  // Two rotated ellipsoids vertex to vertex: the second is the first moved by 20 (3,4,0)/5.
  Ellipsoid3<T> f = e;
  f.center = {12, 16, 0};
  expect_both_orders(e, f, R::touching, "vertex to vertex");
  f.center = {12 * (1 + gap), 16 * (1 + gap), 0};
  expect_both_orders(e, f, R::separated, "vertex gap");
  // Same set stored differently: axes permuted, negated, or scaled by 2 with the extents.
  Ellipsoid3<T> g{{0, 0, 0}, {{0, 0, -5}, {6, 8, 0}, {-4, 3, 0}}, {40, 100, 40}};
  expect_both_orders(e, g, R::equal, "restored");
  g.extent.y = T(100) * (1 + gap);
  expect_both_orders(e, g, R::b_contains_a_touching, "longer");
}

// ---------------------------------------------------------------------------------------------
// Random rotated ellipsoids: dense sampling and the former numeric method.

template <class T>
Ellipsoid3<T> random_ellipsoid(Rng& rng, T lo, T hi) {
  const Vec3<T> a0 = rng.unit<T, 3>();
  const Vec3<T> t = rng.unit<T, 3>();
  const Vec3<T> a1 = normalize(t - dot(t, a0) * a0);
  const Vec3<T> a2 = cross(a0, a1);
  return {rng.vec<T, 3>(T(-1.5), T(1.5)),
          {a0, a1, a2},
          {rng.uniform<T>(lo, hi), rng.uniform<T>(lo, hi), rng.uniform<T>(lo, hi)}};
}

using LD = long double;

/// Implicit value sum_i (U_i.(x - C))^2 / e_i^2 - 1 of the stored quadric, in long double.
template <class T>
LD implicit(const Ellipsoid3<T>& e, const LD (&x)[3]) {
  LD q = -1;
  for (int i = 0; i < 3; ++i) {
    LD s = 0;
    for (int k = 0; k < 3; ++k) s += LD(e.axis[i][k]) * (x[k] - LD(e.center[k]));
    q += (s / LD(e.extent[i])) * (s / LD(e.extent[i]));
  }
  return q;
}

/// Sampled extremes of b's implicit value over a's boundary: x = C + U^-1 (e_i w_i), |w| = 1
/// (the stored quadric's boundary exactly, up to long-double rounding).
template <class T>
void sample(const Ellipsoid3<T>& a, const Ellipsoid3<T>& b, LD& lo, LD& hi) {
  LD m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = LD(a.axis[i][k]);
  const LD det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                 m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  LD inv[3][3];  // inverse by cofactors
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      const int i1 = (k + 1) % 3, i2 = (k + 2) % 3, k1 = (i + 1) % 3, k2 = (i + 2) % 3;
      inv[i][k] = (m[i1][k1] * m[i2][k2] - m[i1][k2] * m[i2][k1]) / det;
    }
  lo = INFINITY;
  hi = -INFINITY;
  const int n = 24;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const LD th = LD(M_PI) * j / n, ph = LD(M_PI) * i / n;
      const LD w[3] = {std::cos(th) * std::sin(ph) * LD(a.extent[0]),
                       std::sin(th) * std::sin(ph) * LD(a.extent[1]),
                       std::cos(ph) * LD(a.extent[2])};
      LD x[3];
      for (int r = 0; r < 3; ++r)
        x[r] = LD(a.center[r]) + inv[r][0] * w[0] + inv[r][1] * w[1] + inv[r][2] * w[2];
      const LD q = implicit(b, x);
      lo = std::min(lo, q);
      hi = std::max(hi, q);
    }
}

TYPED_TEST(EllipsoidRelation, RandomAgainstSamplingAndNumericMethod) {
  using T = TypeParam;
  Rng rng(73);
  SCOPED_TRACE(rng.trace());
  int decided = 0, kinds[9] = {};
  for (int iter = 0; iter < 16; ++iter) {
    const Ellipsoid3<T> a = random_ellipsoid<T>(rng, T(0.3), T(2));
    Ellipsoid3<T> b = random_ellipsoid<T>(rng, T(0.3), T(2));
    if (iter % 4 == 0) {  // containments: a shrunken, moved copy of a
      b.center = a.center + T(0.2) * b.center;
      b.extent = T(0.3) * a.extent;
    }
    if (iter % 4 == 1) {
      b.center = a.center + T(0.1) * b.center;
      b.extent = T(2.5) * a.extent;
    }
    const R r = relation(a, b);
    ++kinds[int(r)];
    const std::string what = "iter " + std::to_string(iter);
    EXPECT_EQ(relation(b, a), swapped(r)) << what;
    LD lo = 0, hi = 0;
    sample(a, b, lo, hi);
    R want = R::undecided;
    // Sampling misses the true extremes by O(h^2) (well below 0.05 here): decisive draws only.
    if (lo < -0.05 && hi > 0.05) want = R::overlapping;
    if (hi < -0.05) want = R::b_contains_a;
    if (lo > 0.05) {
      const LD c[3] = {LD(b.center.x), LD(b.center.y), LD(b.center.z)};
      want = implicit(a, c) < 0 ? R::a_contains_b : R::separated;
    }
    if (want == R::undecided) continue;
    ++decided;
    EXPECT_EQ(r, want) << what << " lo " << double(lo) << " hi " << double(hi);
    // The former method (normalized axes, tolerance) agrees far from tangency.
    using V = Vec3<double>;
    const V aa[3] = {vec_cast<double>(a.axis[0]), vec_cast<double>(a.axis[1]),
                     vec_cast<double>(a.axis[2])};
    const V ba[3] = {vec_cast<double>(b.axis[0]), vec_cast<double>(b.axis[1]),
                     vec_cast<double>(b.axis[2])};
    // The root-structure decision without the cheap certificates agrees (every sixth draw: it costs
    // milliseconds).
    if (iter % 8 == 0) {
      EXPECT_EQ(full_path(a, b), r) << what;
    }
    EXPECT_EQ(detail::quadric_pair3::ellipsoid_relation_numeric(
                  vec_cast<double>(a.center), aa, vec_cast<double>(a.extent),
                  vec_cast<double>(b.center), ba, vec_cast<double>(b.extent), 0x1p-20),
              r)
        << what;
    // Power-of-two scaling of positions and extents, and of the stored axes, keeps the relation.
    {
      const int k = iter % 2 == 0 ? -20 : 20;
      Ellipsoid3<T> as = a, bs = b;
      const T s = T(std::ldexp(1.0, k));
      as.center = s * as.center;
      bs.center = s * bs.center;
      as.extent = s * as.extent;
      bs.extent = s * bs.extent;
      for (int i = 0; i < 3; ++i) as.axis[i] = T(0.25) * as.axis[i];
      as.extent = T(0.25) * as.extent;
      EXPECT_EQ(relation(as, bs), r) << what << " scale " << k;
    }
  }
  EXPECT_GT(decided, 10);
  for (R r : {R::separated, R::overlapping, R::a_contains_b, R::b_contains_a})
    EXPECT_GT(kinds[int(r)], 0) << int(r);
}

TYPED_TEST(EllipsoidRelation, BadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const Ellipsoid3<T> e{{0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {2, 1, 1}};
  const auto check = [&](const Ellipsoid3<T>& bad, const char* what) {
    EXPECT_EQ(relation(bad, e), R::undecided) << what;
    EXPECT_EQ(relation(e, bad), R::undecided) << what;
    EXPECT_EQ(relation(bad, bad), R::undecided) << what;
    EXPECT_FALSE(intersects(e, bad)) << what;
  };
  Ellipsoid3<T> b = e;
  b.center.y = nan;
  check(b, "nan centre");
  b = e;
  b.axis[1].z = inf;
  check(b, "inf axis");
  b = e;
  b.extent.z = T(0);
  check(b, "zero extent");
  b = e;
  b.extent.x = T(-2);
  check(b, "negative extent");
  b = e;
  b.extent.x = nan;
  check(b, "nan extent");
  b = e;
  b.axis[1] = {2, 0, 0};
  check(b, "dependent axes");
  b = e;
  b.axis[2] = {1, 1, 0};
  check(b, "coplanar axes");
  b = e;
  b.axis[0] = {0, 0, 0};
  check(b, "zero axis");
  // Extreme but valid magnitudes stay decided (the cost grows with the exponents' spread).
  Ellipsoid3<T> tiny = e, huge = e;
  const T small = T(0x1p-60);
  tiny.extent = small * tiny.extent;
  tiny.center = {small * 3, 0, 0};
  EXPECT_EQ(relation(e, tiny), R::a_contains_b);
  huge.center = {std::numeric_limits<T>::max() / 4, 0, 0};
  EXPECT_EQ(relation(e, huge), R::separated);
}

}  // namespace
