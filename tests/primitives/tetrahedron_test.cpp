// SPDX-License-Identifier: BSL-1.0
// Tests for primitives/tetrahedron.hpp (row prim3.solids: tetrahedron).
#include <locus/primitives/tetrahedron.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

using namespace locus;
using locus_test::Rng;
using locus_test::tol;
using locus_test::vec_near;

template <class T>
class TetrahedronTest : public ::testing::Test {};
TYPED_TEST_SUITE(TetrahedronTest, locus_test::RealTypes);

static_assert(std::is_aggregate_v<Tetrahedron3d> && std::is_trivially_copyable_v<Tetrahedron3f>);

namespace {
// Exact det[v1 - v0, v2 - v0, v3 - v0] with GMP.
template <class T>
mpq_class exact_det(const Tetrahedron3<T>& t) {
  mpq_class m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      m[i][k] = mpq_class(double(t.v[i + 1][k])) - mpq_class(double(t.v[0][k]));
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

template <class T>
Tetrahedron3<T> random_tet(Rng& rng) {
  return {{rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5)}};
}
}  // namespace

TYPED_TEST(TetrahedronTest, SignedVolumeMatchesGmpDeterminant) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 2000; ++trial) {
    const auto t = random_tet<T>(rng);
    const mpq_class d = exact_det(t);
    const double v = d.get_d() / 6;
    EXPECT_EQ(orientation(t), sgn(d));
    // The rounded determinant of differences up to 10: terms ~1000, a few dozen eps of that.
    EXPECT_NEAR(double(signed_volume(t)), v, double(tol<T>(64, 1000)) / 6);
    EXPECT_EQ(volume(t), std::fabs(signed_volume(t)));
  }
}

TYPED_TEST(TetrahedronTest, NearlyFlatTetrahedraHaveTheExactSign) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int nonzero = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    // v3 = a point of the plane v0 v1 v2 (rounded), so the exact sign is anything, often 0.
    auto t = random_tet<T>(rng);
    const T s = rng.uniform<T>(-1, 2), u = rng.uniform<T>(-1, 2);
    t.v[3] = t.v[0] + s * (t.v[1] - t.v[0]) + u * (t.v[2] - t.v[0]);
    const int e = sgn(exact_det(t));
    EXPECT_EQ(orientation(t), e);
    const T sv = signed_volume(t);
    EXPECT_EQ((sv > T(0)) - (sv < T(0)), e);  // the sign of the rounded value is exact too
    nonzero += e != 0;
  }
  EXPECT_GT(nonzero, 0);  // the test exercises the sign fix, not only exact zeros
}

TYPED_TEST(TetrahedronTest, FlatAndNonFinite) {
  using T = TypeParam;
  const Tetrahedron3<T> flat{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 7, 0}}};
  EXPECT_TRUE(is_degenerate(flat));
  EXPECT_EQ(orientation(flat), 0);
  EXPECT_EQ(signed_volume(flat), T(0));
  const Tetrahedron3<T> coincident{{{1, 1, 1}, {1, 1, 1}, {0, 1, 0}, {3, 7, 2}}};
  EXPECT_EQ(volume(coincident), T(0));
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Tetrahedron3<T> bad{{{nan, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  EXPECT_TRUE(is_degenerate(bad));  // the predicate reports zero for non-finite input
  EXPECT_EQ(signed_volume(bad), T(0));
  // Unit corner tetrahedron: volume 1/6, positively oriented (v3 on the side of e_x x e_y = e_z).
  const Tetrahedron3<T> unit{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  EXPECT_EQ(orientation(unit), 1);
  EXPECT_NEAR(signed_volume(unit), T(1) / T(6), tol<T>(2));
  EXPECT_NEAR(surface_area(unit), T(1.5) + std::sqrt(T(3)) / 2, tol<T>(8, 3));
}

TYPED_TEST(TetrahedronTest, FacesPointOutwardForBothOrientations) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 500; ++trial) {
    auto t = random_tet<T>(rng);
    if (is_degenerate(t)) continue;
    if (trial % 2) std::swap(t.v[1], t.v[2]);
    Vec3<T> sum{};
    T div = 0;  // divergence theorem: V = (1/3) sum over faces of (area normal) . (point on face)
    for (int i = 0; i < 4; ++i) {
      const auto f = face(t, i);
      // The opposite vertex is strictly behind the face plane (exact predicate).
      EXPECT_EQ(to_int(orient3d(f.v0, f.v1, f.v2, t.v[i])), -1);
      // The face uses exactly the three other vertices.
      for (const auto& p : {f.v0, f.v1, f.v2}) EXPECT_FALSE(p == t.v[i]);
      const Vec3<T> n = face_normal(t, i);
      sum += n;
      div += dot(n / T(2), centroid(f)) / T(3);
    }
    EXPECT_TRUE(vec_near(sum, Vec3<T>{}, tol<T>(256, 100)));  // a closed surface
    EXPECT_NEAR(div, volume(t), tol<T>(512, 200));
    // Heron's formula from the edge lengths as an independent area oracle.
    T area = 0;
    for (int i = 0; i < 4; ++i) {
      const auto f = face(t, i);
      const double a = length(vec_cast<double>(f.v1 - f.v0)),
                   b = length(vec_cast<double>(f.v2 - f.v1)),
                   c = length(vec_cast<double>(f.v0 - f.v2)), s = (a + b + c) / 2;
      area += T(std::sqrt(std::fmax(0.0, s * (s - a) * (s - b) * (s - c))));
    }
    EXPECT_NEAR(surface_area(t), area, tol<T>(1024, 100));
  }
}

TYPED_TEST(TetrahedronTest, ParametrisationsCentroidAndBox) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 300; ++trial) {
    const auto t = random_tet<T>(rng);
    for (int i = 0; i < 4; ++i) {
      Vec4<T> b{};
      b[i] = T(1);
      EXPECT_EQ(point_at_barycentric(t, b), t.v[i]);  // exact at the vertices
    }
    EXPECT_EQ(point_at(t, Vec3<T>{0, 0, 0}), t.v[0]);
    EXPECT_TRUE(vec_near(centroid(t),
                         point_at_barycentric(t, Vec4<T>{T(0.25), T(0.25), T(0.25), T(0.25)}),
                         tol<T>(16, 5)));
    T s = rng.uniform<T>(0, 1), u = rng.uniform<T>(0, 1), w = rng.uniform<T>(0, 1);
    if (s + u + w > 1) {
      const T k = rng.uniform<T>(0, 1) / (s + u + w);
      s *= k, u *= k, w *= k;
    }
    const Vec3<T> p = point_at(t, Vec3<T>{s, u, w});
    EXPECT_TRUE(
        vec_near(p, point_at_barycentric(t, Vec4<T>{1 - s - u - w, s, u, w}), tol<T>(64, 10)));
    const auto box = bounding_box(t);
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(box.min[k], p[k] + tol<T>(64, 10));
      EXPECT_GE(box.max[k], p[k] - tol<T>(64, 10));
      EXPECT_EQ(box.min[k],
                std::fmin(std::fmin(t.v[0][k], t.v[1][k]), std::fmin(t.v[2][k], t.v[3][k])));
    }
  }
}

TYPED_TEST(TetrahedronTest, PermutationAndTranslationInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // All 24 permutations of (0, 1, 2, 3) with their parities.
  int perm[4] = {0, 1, 2, 3};
  for (int trial = 0; trial < 200; ++trial) {
    const auto t = random_tet<T>(rng);
    const int o = orientation(t);
    const T v = volume(t);
    std::sort(perm, perm + 4);
    do {
      int inversions = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
      const Tetrahedron3<T> p{{t.v[perm[0]], t.v[perm[1]], t.v[perm[2]], t.v[perm[3]]}};
      EXPECT_EQ(orientation(p), inversions % 2 ? -o : o);
      EXPECT_NEAR(volume(p), v, tol<T>(64, 1000) / 6);
    } while (std::next_permutation(perm, perm + 4));
    // Translation by an exactly representable offset keeps the exact orientation when the
    // translated coordinates are exact too (integer grid).
    Tetrahedron3<T> g{};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) g.v[i][k] = T(rng.uniform_int(-100, 100));
    const Vec3<T> off{T(rng.uniform_int(-1000, 1000)), T(rng.uniform_int(-1000, 1000)),
                      T(rng.uniform_int(-1000, 1000))};
    Tetrahedron3<T> h = g;
    for (auto& p : h.v) p += off;
    EXPECT_EQ(orientation(h), orientation(g));
    EXPECT_EQ(orientation(h), sgn(exact_det(g)));
  }
}
