// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_frustum.hpp (rows dist2.pt-frustum, dist3.pt-frustum; book figures
// 6.11, 6.12, 10.23).
#include <locus/distance/point_frustum.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/distance/point_triangle.hpp>

#include "distance/harness.hpp"
#include "distance/side_boxes_meshes.hpp"
#include "support/typed.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <utility>

using namespace locus;
using locus_test::Rng;
namespace dist = locus_test::dist;

template <class T>
class PointFrustumTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointFrustumTest, locus_test::RealTypes);

namespace {

template <class T>
Frustum3<T> random_frustum3(Rng& rng, T S) {
  const auto r = dist::random_rotation<T, 3>(rng);
  Frustum3<T> f{};
  f.origin = rng.vec<T, 3>(-S / 2, S / 2);
  f.direction = col(r, 0);
  f.up = col(r, 1);
  f.right = col(r, 2);
  if (rng.uniform_int(0, 1)) f.right = -f.right;  // either handedness
  f.d_min = rng.uniform<T>(T(0.3), T(3));
  f.d_max = rng.uniform_int(0, 7) == 0 ? f.d_min : f.d_min + rng.uniform<T>(T(0.1), T(5));
  f.u_bound = rng.uniform_int(0, 9) == 0 ? T(0) : rng.uniform<T>(T(0.1), T(2));
  f.r_bound = rng.uniform_int(0, 9) == 0 ? T(0) : rng.uniform<T>(T(0.1), T(2));
  return f;
}

template <class T>
Frustum2<T> random_frustum2(Rng& rng, T S) {
  const auto r = dist::random_rotation<T, 2>(rng);
  Frustum2<T> f{};
  f.origin = rng.vec<T, 2>(-S / 2, S / 2);
  f.direction = col(r, 0);
  f.left = rng.uniform_int(0, 1) ? col(r, 1) : -col(r, 1);
  f.d_min = rng.uniform<T>(T(0.3), T(3));
  f.d_max = rng.uniform_int(0, 7) == 0 ? f.d_min : f.d_min + rng.uniform<T>(T(0.1), T(5));
  f.l_bound = rng.uniform_int(0, 9) == 0 ? T(0) : rng.uniform<T>(T(0.1), T(2));
  return f;
}

// The frustum as the convex hull of its 8 corners; faces as corner index quads, outward order
// decided numerically below (the oracle does not use the header's frame reasoning).
constexpr int kFaces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                              {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};

// Brute-force oracle: 0 when p is on the inner side of the 6 face planes (normals oriented away
// from the centroid), else the minimum over the 12 boundary triangles (point_triangle.hpp).
template <class T>
double oracle3(const Vec3<T>& p, const Frustum3<T>& f) {
  const auto c = corners(f);
  Vec3<double> centre{};
  for (const auto& v : c) centre += vec_cast<double>(v) / 8.0;
  // A flat frustum (zero volume) is the union of its boundary triangles: no interior test.
  bool inside = f.d_max > f.d_min && f.u_bound > T(0) && f.r_bound > T(0);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& q : kFaces) {
    const Vec3<double> a = vec_cast<double>(c[q[0]]), b = vec_cast<double>(c[q[1]]),
                       d = vec_cast<double>(c[q[2]]), e = vec_cast<double>(c[q[3]]);
    Vec3<double> nrm = cross(d - a, e - b);  // quad normal (diagonals), robust for trapezoids
    if (dot(nrm, centre - a) > 0) nrm = -nrm;
    if (dot(nrm, vec_cast<double>(p) - a) > 1e-9 * length(nrm) * (1 + max_abs(a))) inside = false;
    const Vec3<double> pd = vec_cast<double>(p);
    best = std::min(best, distance(pd, Triangle3<double>{a, b, d}).distance);
    best = std::min(best, distance(pd, Triangle3<double>{a, d, e}).distance);
  }
  return inside ? 0.0 : best;
}

template <class T>
double oracle2(const Vec2<T>& p, const Frustum2<T>& f) {
  const Vec2<double> c[4] = {vec_cast<double>(corner(f, 0)), vec_cast<double>(corner(f, 1)),
                             vec_cast<double>(corner(f, 3)), vec_cast<double>(corner(f, 2))};
  const Vec2<double> pd = vec_cast<double>(p);
  Vec2<double> centre = (c[0] + c[1] + c[2] + c[3]) / 4.0;
  bool inside = f.d_max > f.d_min && f.l_bound > T(0);
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const Vec2<double> a = c[i], b = c[(i + 1) % 4];
    double s = perp_dot(b - a, pd - a), sc = perp_dot(b - a, centre - a);
    if (sc < 0) s = -s;
    if (s < -1e-9 * (1 + max_abs(a)) * length(b - a)) inside = false;
    best = std::min(best, distance(pd, Segment2<double>{a, b}).distance);
  }
  return inside ? 0.0 : best;
}

}  // namespace

TYPED_TEST(PointFrustumTest, HarnessAndBruteForce) {
  using T = TypeParam;
  const T S = 10;
  dist::check_pairs<T, 3, Vec3<T>, Frustum3<T>>([&](Rng& rng) {
    return std::pair{rng.vec<T, 3>(-S, S), random_frustum3<T>(rng, S)};
  });
  dist::check_pairs<T, 2, Vec2<T>, Frustum2<T>>([&](Rng& rng) {
    return std::pair{rng.vec<T, 2>(-S, S), random_frustum2<T>(rng, S)};
  });

  Rng rng(locus_test::test_seed() + 61);
  SCOPED_TRACE(rng.trace());
  const double tl = std::is_same_v<T, float> ? 2e-5 : 1e-12;
  for (int n = 0; n < 3000; ++n) {
    SCOPED_TRACE(n);
    const auto f3 = random_frustum3<T>(rng, S);
    // Points near the frustum as well as far away (every Voronoi region gets hits).
    const auto p3 = n % 2 ? rng.vec<T, 3>(-S, S)
                          : point_at(f3, rng.vec<T, 3>(T(-1.5), T(1.5))) + rng.vec<T, 3>(-1, 1);
    EXPECT_NEAR(distance(p3, f3).distance, oracle3(p3, f3), tl * S);
    const auto f2 = random_frustum2<T>(rng, S);
    const auto p2 = n % 2 ? rng.vec<T, 2>(-S, S)
                          : point_at(f2, rng.vec<T, 2>(T(-1.5), T(1.5))) + rng.vec<T, 2>(-1, 1);
    EXPECT_NEAR(distance(p2, f2).distance, oracle2(p2, f2), tl * S);
  }
}

// Figure 10.23: one point in each of the 27 Voronoi regions (interior, 6 faces, 12 edges, 8
// vertices) of a canonical frustum, placed along the sum of the outward normals of the faces
// meeting the feature, so the nearest point is the feature point and the distance is known.
TYPED_TEST(PointFrustumTest, VoronoiRegions3D) {
  using T = TypeParam;
  using V = Vec3<T>;
  const Frustum3<T> f{V{1, 2, 3}, V{0, 0, 1}, V{0, 1, 0}, V{1, 0, 0}, T(1), T(3), T(0.5), T(1)};
  const auto c = corners(f);
  const V centre = centroid(f);
  std::array<V, 6> nrm{};
  for (int i = 0; i < 6; ++i) {
    const auto& q = kFaces[i];
    V m = normalize(cross(c[q[2]] - c[q[0]], c[q[3]] - c[q[1]]));
    if (dot(m, centre - c[q[0]]) > 0) m = -m;
    nrm[i] = m;
  }
  const auto on_face = [&](int face, int corner_id) {
    for (int j = 0; j < 4; ++j)
      if (kFaces[face][j] == corner_id) return true;
    return false;
  };
  const T lambda = T(0.7);
  const T tl = std::is_same_v<T, float> ? T(1e-5) : T(1e-13);
  int regions = 0;
  // Vertices.
  for (int k = 0; k < 8; ++k) {
    V dir{};
    for (int i = 0; i < 6; ++i)
      if (on_face(i, k)) dir += nrm[i];
    const V p = c[k] + lambda * normalize(dir);
    const auto r = distance(p, f);
    EXPECT_NEAR(r.distance, lambda, tl * 10) << "vertex " << k;
    EXPECT_TRUE(locus_test::vec_near(r.closest[1], c[k], tl * 10)) << "vertex " << k;
    ++regions;
  }
  // Edges: corner pairs sharing two faces.
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b) {
      V dir{};
      int shared = 0;
      for (int i = 0; i < 6; ++i)
        if (on_face(i, a) && on_face(i, b)) dir += nrm[i], ++shared;
      if (shared != 2) continue;
      const V mid = (c[a] + c[b]) * T(0.5);
      const V p = mid + lambda * normalize(dir);
      const auto r = distance(p, f);
      EXPECT_NEAR(r.distance, lambda, tl * 10) << "edge " << a << " " << b;
      EXPECT_TRUE(locus_test::vec_near(r.closest[1], mid, tl * 10)) << "edge " << a << " " << b;
      ++regions;
    }
  // Faces (through the face centroid) and the interior.
  for (int i = 0; i < 6; ++i) {
    V mid{};
    for (int j = 0; j < 4; ++j) mid += c[kFaces[i][j]] * T(0.25);
    const auto r = distance(mid + lambda * nrm[i], f);
    EXPECT_NEAR(r.distance, lambda, tl * 10) << "face " << i;
    EXPECT_TRUE(locus_test::vec_near(r.closest[1], mid, tl * 10)) << "face " << i;
    ++regions;
  }
  const auto in = distance(centre, f);
  EXPECT_EQ(in.distance, T(0));
  EXPECT_EQ(in.closest[1], centre);
  ++regions;
  EXPECT_EQ(regions, 27);
}

// Figure 6.12: the 2D regions (interior, 4 edges, 4 vertices).
TYPED_TEST(PointFrustumTest, VoronoiRegions2D) {
  using T = TypeParam;
  using V = Vec2<T>;
  const Frustum2<T> f{V{-1, 2}, V{0, 1}, V{-1, 0}, T(1), T(4), T(0.5)};
  const T tl = std::is_same_v<T, float> ? T(1e-5) : T(1e-13);
  // Corners (hand-computed): near (-1 -+ 0.5, 3), far (-1 -+ 2, 6); corner k bit 0 = +L = -x.
  const V c[4] = {{-0.5, 3}, {-1.5, 3}, {1, 6}, {-3, 6}};
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(locus_test::vec_near(corner(f, k), c[k], tl * 10));
  struct Case {
    V p;
    T dist;
    V closest;
  };
  const Case cases[] = {
      {{-1, 2}, T(1), {-1, 3}},                 // below the near edge
      {{-1, 7}, T(1), {-1, 6}},                 // above the far edge
      {{0, 2}, std::sqrt(T(1.25)), {-0.5, 3}},  // near-right vertex region
      {{2, 7}, std::sqrt(T(2)), {1, 6}},        // far-right vertex region
      {{-4, 7}, std::sqrt(T(2)), {-3, 6}},      // far-left vertex region
      {{-1, 4}, T(0), {-1, 4}},                 // inside
  };
  for (const Case& k : cases) {
    const auto r = distance(k.p, f);
    EXPECT_NEAR(r.distance, k.dist, tl * 10) << k.p.x << " " << k.p.y;
    EXPECT_TRUE(locus_test::vec_near(r.closest[1], k.closest, tl * 10)) << k.p.x << " " << k.p.y;
  }
  // Side edge region: the right side runs from (-0.5, 3) to (1, 6); its outward normal is
  // (3, -1.5) / |.|; the point mid + 0.8 n is nearest to the middle of that edge.
  const V mid{0.25, 4.5};
  const V n = normalize(V{3, -1.5});
  const auto r = distance(mid + T(0.8) * n, f);
  EXPECT_NEAR(r.distance, T(0.8), tl * 10);
  EXPECT_TRUE(locus_test::vec_near(r.closest[1], mid, tl * 10));
}

TYPED_TEST(PointFrustumTest, DegenerateAndNonFinite) {
  using T = TypeParam;
  using V = Vec3<T>;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T tl = std::is_same_v<T, float> ? T(1e-5) : T(1e-13);
  // Flat frustum (d_max == d_min): the near rectangle.
  const Frustum3<T> flat{V{0, 0, 0}, V{0, 0, 1}, V{0, 1, 0}, V{1, 0, 0}, T(2), T(2), T(1), T(1)};
  EXPECT_NEAR(distance(V{0, 0, 5}, flat).distance, T(3), tl);
  EXPECT_NEAR(distance(V{3, 0, 2}, flat).distance, T(2), tl);
  // Zero bounds: a wedge of zero width (r = 0) and a segment (r = u = 0).
  const Frustum3<T> wedge{V{0, 0, 0}, V{0, 0, 1}, V{0, 1, 0}, V{1, 0, 0}, T(1), T(3), T(1), T(0)};
  EXPECT_NEAR(distance(V{2, 0, 2}, wedge).distance, T(2), tl);
  const Frustum3<T> stick{V{0, 0, 0}, V{0, 0, 1}, V{0, 1, 0}, V{1, 0, 0}, T(1), T(3), T(0), T(0)};
  EXPECT_NEAR(distance(V{0, 4, 2}, stick).distance, T(4), tl);
  EXPECT_NEAR(distance(V{0, 0, 5}, stick).distance, T(2), tl);
  // Invalid and non-finite input.
  Frustum3<T> bad = flat;
  bad.d_min = T(0);
  EXPECT_TRUE(dist::is_nan_result(distance(V{0, 0, 1}, bad)));
  bad = flat;
  bad.d_max = T(1);  // d_max < d_min
  EXPECT_TRUE(dist::is_nan_result(distance(V{0, 0, 1}, bad)));
  EXPECT_TRUE(dist::is_nan_result(distance(V{nan, 0, 1}, flat)));
  bad = flat;
  bad.up = V{0, nan, 0};
  EXPECT_TRUE(dist::is_nan_result(distance(bad, V{0, 0, 1})));
  const Frustum2<T> f2{Vec2<T>{0, 0}, Vec2<T>{0, 1}, Vec2<T>{1, 0}, T(1), T(1), T(0)};  // a point
  EXPECT_NEAR(distance(Vec2<T>{3, 5}, f2).distance, T(5), tl);
  Frustum2<T> b2 = f2;
  b2.l_bound = T(-1);
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{0, 0}, b2)));
  EXPECT_TRUE(dist::is_nan_result(distance(Vec2<T>{nan, 0}, f2)));
  // Swap.
  const auto a = distance(V{3, -2, 7}, flat);
  const auto b = distance(flat, V{3, -2, 7});
  EXPECT_EQ(a.sqr_distance, b.sqr_distance);
  EXPECT_EQ(a.closest[1], b.closest[0]);
  EXPECT_EQ(a.param_b, b.param_a);
}
