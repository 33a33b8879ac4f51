// SPDX-License-Identifier: BSL-1.0
// Row int3.plane-triangle (triangle-triangle test only): intersects(Triangle3, Triangle3), float
// and double, against an exact GMP oracle that shares nothing with the predicates: the triangles
// meet iff the system sum l_i P_i = sum m_j Q_j, sum l = sum m = 1, l, m >= 0 has a solution,
// decided by enumerating basic solutions (linearly independent column subsets, rational Gauss
// elimination). Inputs: seeded random triangles, small integer grids (coplanar, touching,
// collinear and coincident vertices: degenerate triangles), shared vertices and edges, coplanar
// overlaps and touches, one-ulp perturbations of touching configurations, NaN/Inf; checks swap
// symmetry, vertex permutation and power-of-two scaling.

#include <locus/intersection/triangle_triangle.hpp>

#include "mesh/triangle_oracle.hpp"
#include "support/scale_covariance.hpp"
#include "support/typed.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class TriangleTriangle : public ::testing::Test {};
TYPED_TEST_SUITE(TriangleTriangle, locus_test::RealTypes);

template <class T>
bool oracle(const Triangle3<T>& a, const Triangle3<T>& b) {
  return locus_test::triangles_meet_exact(a, b);
}

template <class T>
void expect_all_orders(const Triangle3<T>& a, const Triangle3<T>& b, bool want) {
  static constexpr int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                     {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& p : perm) {
    const Triangle3<T> ap{a[p[0]], a[p[1]], a[p[2]]};
    EXPECT_EQ(intersects(ap, b), want);
    EXPECT_EQ(intersects(b, ap), want);
  }
}

template <class T>
Triangle3<T> grid_triangle(Rng& rng, int lo, int hi) {
  Triangle3<T> t;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) t[i][k] = static_cast<T>(rng.uniform_int(lo, hi));
  }
  return t;
}

TYPED_TEST(TriangleTriangle, RandomAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int hits = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    Triangle3<T> a, b;
    for (int i = 0; i < 3; ++i) {
      a[i] = rng.template vec<T, 3>(T(-1), T(1));
      b[i] = rng.template vec<T, 3>(T(-1), T(1));
    }
    const bool want = oracle(a, b);
    hits += want;
    ASSERT_EQ(intersects(a, b), want) << "trial " << trial;
    ASSERT_EQ(intersects(b, a), want) << "trial " << trial;
  }
  EXPECT_GT(hits, 150);
  EXPECT_LT(hits, 1350);
}

// Small integer grids: coplanar pairs, shared and coincident vertices, touching edges and
// degenerate (segment, point) triangles are frequent; every answer checked against the oracle
// in every vertex order and both argument orders.
TYPED_TEST(TriangleTriangle, IntegerGridDegeneracies) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int hits = 0, coplanar = 0, degenerate = 0;
  for (int trial = 0; trial < 2500; ++trial) {
    const int hi = trial % 2 == 0 ? 2 : 4;
    Triangle3<T> a = grid_triangle<T>(rng, 0, hi), b = grid_triangle<T>(rng, 0, hi);
    if (trial % 3 == 0) {  // put both in the plane z = 1
      for (int i = 0; i < 3; ++i) a[i].z = b[i].z = T(1);
    }
    if (trial % 5 == 1) b.v0 = a.v1;  // a shared vertex
    if (trial % 7 == 2) {             // a shared edge
      b.v0 = a.v0;
      b.v1 = a.v2;
    }
    const bool want = oracle(a, b);
    hits += want;
    coplanar += orient3d(a.v0, a.v1, a.v2, b.v0) == Sign::zero &&
                orient3d(a.v0, a.v1, a.v2, b.v1) == Sign::zero &&
                orient3d(a.v0, a.v1, a.v2, b.v2) == Sign::zero;
    degenerate += is_degenerate(a) || is_degenerate(b);
    SCOPED_TRACE(trial);
    expect_all_orders(a, b, want);
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(hits, 250);
  EXPECT_GT(coplanar, 250);
  EXPECT_GT(degenerate, 30);
}

// Touching configurations and their one-ulp perturbations both ways: the exact answer flips
// between true and false, and the test must follow it.
TYPED_TEST(TriangleTriangle, OneUlpPerturbations) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int flips = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Triangle3<T> a, b;
    for (int i = 0; i < 3; ++i) a[i] = rng.template vec<T, 3>(T(-1), T(1));
    // b touches a: one vertex of b is a vertex of a, or b's vertex is the midpoint-ish point of
    // an edge of a in a coordinate plane (exactly representable: edge along an axis).
    const int kind = trial % 3;
    if (kind == 0) {
      b.v0 = a.v0;
      b.v1 = a.v0 + rng.template vec<T, 3>(T(0), T(1));
      b.v2 = a.v0 + rng.template vec<T, 3>(T(0), T(1));
    } else {
      // An axis-aligned configuration: a in the plane z = 1, b touching it from above (inside
      // a, or on its edge y = 1). Offsets by 1 keep one-ulp steps normal numbers (the
      // predicates' range excludes subnormal coordinates).
      const T h = rng.uniform(T(0.1), T(1));
      a = {{1, 1, 1}, {1 + h, 1, 1}, {1, 1 + h, 1}};
      b = {{1 + h / 4, 1 + h / 4, 1}, {1 + h / 4, 1 + h / 2, 2}, {1 + h / 2, 1 + h / 4, 2}};
      if (kind == 2) b = {{1 + h / 2, T(1), T(1)}, {1 + h / 2, 1 - h, 2}, {1 + h / 2, 1 - h, 0}};
    }
    const bool base = oracle(a, b);
    ASSERT_EQ(intersects(a, b), base) << trial;
    for (int axis = 0; axis < 3; ++axis) {
      for (const T dir :
           {-std::numeric_limits<T>::infinity(), std::numeric_limits<T>::infinity()}) {
        Triangle3<T> c = b;
        c.v0[axis] = std::nextafter(c.v0[axis], dir);
        const bool want = oracle(a, c);
        flips += want != base;
        ASSERT_EQ(intersects(a, c), want) << trial << " axis " << axis;
        ASSERT_EQ(intersects(c, a), want) << trial << " axis " << axis;
      }
    }
  }
  EXPECT_GT(flips, 50);
}

// Vertices exactly in the other's plane without a shared vertex (T-junctions of meshes): b's
// first vertex is the midpoint of an edge of a, a point inside a, or a point of a's plane
// outside a (2 a_i - a_j); its second optionally too (then an edge of b lies in a's plane), the
// rest random. Coordinates are multiples of 2^-k (k = 30 for double, 10 for float) so that those
// points are exact, yet far from the small lattices the predicates shortcut: the exact zeros go
// through the adaptive stages. Shared edges and vertices with random coordinates as well.
TYPED_TEST(TriangleTriangle, VertexOnEdgeAndPlaneAgainstOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const int bits = std::is_same_v<T, float> ? 10 : 30;
  const auto coord = [&] {
    return std::ldexp(std::round(std::ldexp(rng.uniform(-1.0, 1.0), bits)), -bits);
  };
  const auto point = [&] { return Vec3<T>{T(coord()), T(coord()), T(coord())}; };
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const Triangle3<T> a{point(), point(), point()};
    const int i = rng.uniform_int(0, 2), j = (i + 1) % 3, k = (i + 2) % 3;
    const auto in_plane = [&](int kind) -> Vec3<T> {
      switch (kind) {
        case 0:
          return (a[i] + a[j]) * T(0.5);  // on an edge
        case 1:
          return ((a[i] + a[j]) * T(0.5) + a[k]) * T(0.5);  // inside
        case 2:
          return a[i] * T(2) - a[j];  // outside, on the edge line
        default:
          return (a[i] + a[j]) - a[k];  // outside, beyond the edge
      }
    };
    Triangle3<T> b{in_plane(trial % 4), point(), point()};
    if (trial % 3 == 1) b.v1 = in_plane((trial / 4) % 4);  // an edge of b in a's plane
    if (trial % 7 == 3) b.v1 = a[j];                       // a shared vertex
    if (trial % 11 == 5) b = {a[i], a[j], point()};        // a shared edge
    const bool want = oracle(a, b);
    hits += want;
    misses += !want;
    SCOPED_TRACE(trial);
    expect_all_orders(a, b, want);
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(hits, 60);
  EXPECT_GT(misses, 15);
}

// The shared-normal plane filter is det3_stage_a on the transposed rows: the same decisions as
// the stage-A filter, and every decided sign is orient3d's, on generic and nearly coplanar
// points (one ulp off a's plane, where the filter must give up).
TEST(TriangleTrianglePlaneFilter, DecidesAsStageAAndAgreesWithOrient3d) {
  namespace d = detail::tri3;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int decided = 0, undecided = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    d::V3 a[3], x;
    for (auto& v : a) v = rng.template vec<double, 3>(-1.0, 1.0);
    if (trial % 2 == 0) {
      x = rng.template vec<double, 3>(-1.0, 1.0);
    } else {
      x = (a[0] + a[1]) * 0.5;
      x.x = std::nextafter(x.x, trial % 4 == 1 ? 2.0 : -2.0);
    }
    const d::PlaneFilter f = d::plane_filter(a[0], a[1], a[2]);
    const d::V3 u = a[1] - a[0], v = a[2] - a[0], w = x - a[0];
    const auto stage_a =
        detail::det3_stage_a<double>(d::V3{u.x, v.x, w.x}, d::V3{u.y, v.y, w.y},
                                     d::V3{u.z, v.z, w.z}, [](double t) { return std::abs(t); });
    const int s = d::filtered_side(f, x);
    ASSERT_EQ(s != 2, detail::certain(stage_a)) << trial;
    if (s != 2) {
      ASSERT_EQ(s, to_int(orient3d(a[0], a[1], a[2], x))) << trial;
      ++decided;
    } else {
      ++undecided;
    }
  }
  EXPECT_GT(decided, 900);
  EXPECT_GT(undecided, 100);
}

TYPED_TEST(TriangleTriangle, CoplanarOverlapAndTouch) {
  using T = TypeParam;
  const Triangle3<T> a{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  // Overlapping, nested, touching at a vertex, along an edge, and apart by one ulp.
  const Triangle3<T> overlap{{1, 1, 0}, {5, 1, 0}, {1, 5, 0}};
  const Triangle3<T> nested{{1, 1, 0}, {2, 1, 0}, {1, 2, 0}};
  const Triangle3<T> vertex{{4, 0, 0}, {6, 0, 0}, {6, 2, 0}};
  const Triangle3<T> edge{{4, 0, 0}, {0, 4, 0}, {4, 4, 0}};
  const T gap = std::nextafter(T(4), T(5));
  const Triangle3<T> apart{{gap, 0, 0}, {6, 0, 0}, {6, 2, 0}};
  for (const auto& [b, want] :
       {std::pair{overlap, true}, std::pair{nested, true}, std::pair{vertex, true},
        std::pair{edge, true}, std::pair{apart, false}}) {
    ASSERT_EQ(oracle(a, b), want);
    expect_all_orders(a, b, want);
  }
}

TYPED_TEST(TriangleTriangle, NonFiniteIsFalse) {
  using T = TypeParam;
  const Triangle3<T> a{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (const T bad : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()}) {
    Triangle3<T> b = a;
    b.v1.y = bad;
    EXPECT_FALSE(intersects(a, b));
    EXPECT_FALSE(intersects(b, a));
  }
}

TYPED_TEST(TriangleTriangle, PowerOfTwoScaleKeepsAnswer) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 800; ++trial) {
    Triangle3<T> a = grid_triangle<T>(rng, -3, 3), b = grid_triangle<T>(rng, -3, 3);
    if (trial % 2 == 0) {
      for (int i = 0; i < 3; ++i) b[i] = rng.template vec<T, 3>(T(-3), T(3));
    }
    const bool base = intersects(a, b);
    ASSERT_EQ(base, oracle(a, b));
    for (const int k : locus_test::scale_exponents<T>()) {
      Triangle3<T> as = a, bs = b;
      for (int i = 0; i < 3; ++i) {
        as[i] = as[i] * std::ldexp(T(1), k);
        bs[i] = bs[i] * std::ldexp(T(1), k);
      }
      ASSERT_EQ(intersects(as, bs), base) << trial << " k " << k;
    }
  }
}

}  // namespace
