// SPDX-License-Identifier: BSL-1.0
// Row mesh.polygon-tri: triangulate_polygon3 (mesh/polygon_triangulation3.hpp), float and double.
// Polygons are random star-shaped (non-convex) rings, with and without a hole, embedded EXACTLY
// in a tilted plane by an integer affine map (so they are truly planar), in every axis order and
// both orientations. Checked with GMP rationals: the triangles' signed areas in the projection
// along the dropped axis add up to the polygon's, each triangle's exact normal points along the
// polygon's exact Newell normal (counter-clockwise about it), no triangle is degenerate.
// Also: a convex polygon's fan (figure 9.5), planarity statuses (exact with tolerance 0, one-ulp
// and large lifts, a rotated and rounded polygon accepted by the default tolerance), degenerate,
// empty and non-finite input, and power-of-two scaling (the same triangles).

#include <locus/core/predicates.hpp>
#include <locus/mesh/polygon_mesh.hpp>
#include <locus/mesh/polygon_triangulation3.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace {

using namespace locus;
using locus_test::Rng;

template <class T>
class PolygonTri3 : public ::testing::Test {};
TYPED_TEST_SUITE(PolygonTri3, locus_test::RealTypes);

using Q3 = std::array<mpq_class, 3>;
template <class T>
Q3 q(const Vec3<T>& p) {
  return {mpq_class(double(p.x)), mpq_class(double(p.y)), mpq_class(double(p.z))};
}
Q3 sub(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
mpq_class dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Exact vector area (half the Newell normal) of a ring: sum of p_i x p_{i+1} / 2.
template <class T>
Q3 ring_area(std::span<const Vec3<T>> pts) {
  Q3 s{0, 0, 0};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Q3 c = cross(q(pts[i]), q(pts[(i + 1) % pts.size()]));
    for (int k = 0; k < 3; ++k)
      s[static_cast<std::size_t>(k)] += c[static_cast<std::size_t>(k)] / 2;
  }
  return s;
}

// A random star-shaped ring in integer coordinates (increasing angles, random radii).
std::vector<std::array<int, 2>> star(Rng& rng, int n, int rmin, int rmax, int cx = 0, int cy = 0) {
  // Jittered angles: every gap below 2 pi 1.8 / n, so the centre sees every edge and, for
  // n >= 5, edges stay farther than rmin cos(1.13) from it.
  std::vector<double> ang;
  for (int i = 0; i < n; ++i) ang.push_back(2 * std::numbers::pi * (i + rng.uniform(0.0, 0.8)) / n);
  std::vector<std::array<int, 2>> out;
  for (const double a : ang) {
    const double r = rng.uniform(double(rmin), double(rmax));
    const std::array<int, 2> p{cx + int(std::lround(r * std::cos(a))),
                               cy + int(std::lround(r * std::sin(a)))};
    if (out.empty() || out.back() != p) out.push_back(p);
  }
  return out;
}

// The exact checks of the header comment on one triangulation.
template <class T>
void expect_valid(std::span<const Vec3<T>> pts, std::span<const std::uint32_t> ends,
                  const PolygonTriangulation3<T>& r) {
  ASSERT_EQ(r.status, Status::ok);
  const Q3 outer = ring_area(pts.subspan(0, ends[0]));
  Q3 want = outer;  // holes subtract their absolute area along the outer normal
  for (std::size_t k = 1; k < ends.size(); ++k) {
    const Q3 h = ring_area(pts.subspan(ends[k - 1], ends[k] - ends[k - 1]));
    const int same = sgn(dot(h, outer)) > 0 ? 1 : -1;
    for (int i = 0; i < 3; ++i)
      want[static_cast<std::size_t>(i)] -= same * h[static_cast<std::size_t>(i)];
  }
  Q3 sum{0, 0, 0};
  for (const auto& t : r.triangles) {
    const Q3 a = q(pts[t[0]]);
    const Q3 n = cross(sub(q(pts[t[1]]), a), sub(q(pts[t[2]]), a));
    EXPECT_GT(sgn(dot(n, outer)), 0);
    for (int i = 0; i < 3; ++i)
      sum[static_cast<std::size_t>(i)] += n[static_cast<std::size_t>(i)] / 2;
  }
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(sum[static_cast<std::size_t>(i)], want[static_cast<std::size_t>(i)]);
}

TYPED_TEST(PolygonTri3, RandomStarPolygonsInTiltedPlanes) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 120; ++trial) {
    const bool hole = trial % 2 == 1;
    auto ring = star(rng, rng.uniform_int(5, 30), 20, 60);
    std::vector<std::uint32_t> ends{static_cast<std::uint32_t>(ring.size())};
    if (hole) {  // a small square hole about the centre, inside the kernel of the star
      for (const auto& p : std::vector<std::array<int, 2>>{{-5, -5}, {5, -5}, {5, 5}, {-5, 5}}) {
        ring.push_back(p);
      }
      ends.push_back(static_cast<std::uint32_t>(ring.size()));
    }
    if (trial % 4 >= 2) std::reverse(ring.begin(), ring.begin() + ends[0]);
    // P = O + x U + y V with integer U, V: exactly planar; a random axis order.
    Vec3<int> U{rng.uniform_int(-3, 3), rng.uniform_int(-3, 3), rng.uniform_int(1, 3)};
    Vec3<int> V{rng.uniform_int(1, 3), rng.uniform_int(-3, 3), rng.uniform_int(-3, 3)};
    if (U.y * V.z - U.z * V.y == 0 && U.z * V.x - U.x * V.z == 0 && U.x * V.y - U.y * V.x == 0) {
      continue;
    }
    const int perm = trial % 3;
    std::vector<Vec3<T>> pts;
    for (const auto& p : ring) {
      const int c[3] = {7 + p[0] * U.x + p[1] * V.x, -3 + p[0] * U.y + p[1] * V.y,
                        5 + p[0] * U.z + p[1] * V.z};
      pts.push_back({T(c[perm]), T(c[(perm + 1) % 3]), T(c[(perm + 2) % 3])});
    }
    const auto r = triangulate_polygon3<T>(pts, ends, T(0));  // exact planarity
    expect_valid<T>(pts, ends, r);
    // Scaling by 2^k: the same triangles.
    for (const int k : {-30, 30}) {
      std::vector<Vec3<T>> s = pts;
      for (auto& p : s) p = p * std::ldexp(T(1), k);
      const auto rs = triangulate_polygon3<T>(s, ends, T(0));
      EXPECT_EQ(rs.status, Status::ok);
      EXPECT_EQ(rs.triangles, r.triangles);
    }
  }
}

// Figure 9.5: a convex polygon's fan and its triangulation cover the same exact area.
TYPED_TEST(PolygonTri3, ConvexPolygonFanAndTriangulationAgree) {
  using T = TypeParam;
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 7; ++i) {
    const double a = 2 * std::numbers::pi * i / 7;
    const int x = int(std::lround(40 * std::cos(a))), y = int(std::lround(40 * std::sin(a)));
    pts.push_back({T(x), T(y), T(x + 2 * y)});
  }
  const std::array<std::uint32_t, 1> ends{7};
  const auto r = triangulate_polygon3<T>(pts, ends, T(0));
  expect_valid<T>(pts, ends, r);
  EXPECT_EQ(r.triangles.size(), 5u);
  PolygonMesh<T> m;
  m.vertices = pts;
  const std::array<std::uint32_t, 7> f{0, 1, 2, 3, 4, 5, 6};
  add_face(m, std::span<const std::uint32_t>(f));
  PolygonTriangulation3<T> fan{Status::ok, fan_triangles(m), {}, -1};
  expect_valid<T>(pts, ends, fan);
}

TYPED_TEST(PolygonTri3, PlanarityStatuses) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto ring = star(rng, 12, 20, 40);
  std::vector<Vec3<T>> flat;
  for (const auto& p : ring) flat.push_back({T(p[0]), T(p[1]), T(p[0] - p[1])});
  EXPECT_EQ(triangulate_polygon3<T>(flat, T(0)).status, Status::ok);
  std::vector<Vec3<T>> ulp = flat;
  ulp[3].z = std::nextafter(ulp[3].z, T(1000));
  EXPECT_EQ(triangulate_polygon3<T>(ulp, T(0)).status, Status::invalid_input);
  EXPECT_EQ(triangulate_polygon3<T>(std::span<const Vec3<T>>(ulp)).status, Status::ok);
  std::vector<Vec3<T>> lifted = flat;
  lifted[5].z += T(10);
  const auto bad = triangulate_polygon3<T>(std::span<const Vec3<T>>(lifted));
  EXPECT_EQ(bad.status, Status::invalid_input);
  EXPECT_FALSE(bad.triangles.empty());  // best effort all the same
  // A rotated, rounded copy: flat only up to rounding, accepted by the default tolerance.
  const Vec3<double> axis = normalize(Vec3<double>{0.3, -0.5, 0.8});
  const double c = std::cos(0.7), s = std::sin(0.7);
  std::vector<Vec3<T>> rot;
  for (const auto& p : flat) {
    const Vec3<double> v = vec_cast<double>(p);
    rot.push_back(vec_cast<T>(v * c + cross(axis, v) * s + axis * dot(axis, v) * (1 - c)));
  }
  const auto rr = triangulate_polygon3<T>(std::span<const Vec3<T>>(rot));
  EXPECT_EQ(rr.status, Status::ok);
  EXPECT_EQ(rr.triangles.size(), triangulate_polygon3<T>(flat, T(0)).triangles.size());
}

TYPED_TEST(PolygonTri3, DegenerateAndInvalidInput) {
  using T = TypeParam;
  const std::vector<Vec3<T>> none;
  EXPECT_EQ(triangulate_polygon3<T>(none).status, Status::empty_input);
  const std::vector<Vec3<T>> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  const auto d = triangulate_polygon3<T>(line);
  EXPECT_EQ(d.status, Status::degenerate_input);
  EXPECT_TRUE(d.triangles.empty());
  std::vector<Vec3<T>> nan{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  nan[1].y = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(triangulate_polygon3<T>(nan).status, Status::non_finite_input);
  const std::vector<Vec3<T>> tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::array<std::uint32_t, 1> past{4};
  EXPECT_EQ(triangulate_polygon3<T>(tri, past).status, Status::invalid_input);
  // A triangle seen from below: the output keeps its (clockwise from above) orientation.
  const std::vector<Vec3<T>> down{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}};
  const auto r = triangulate_polygon3<T>(down, T(0));
  ASSERT_EQ(r.triangles.size(), 1u);
  EXPECT_EQ(orient3d(down[r.triangles[0][0]], down[r.triangles[0][1]], down[r.triangles[0][2]],
                     Vec3<T>{0, 0, 1}),
            Sign::negative);
  EXPECT_EQ(r.dropped_axis, 2);
  // Any point range, without spelling T; with ring ends too.
  EXPECT_EQ(triangulate_polygon3(down).triangles, r.triangles);
  const std::vector<std::uint32_t> one{3};
  EXPECT_EQ(triangulate_polygon3(down, one, T(0)).triangles, r.triangles);
  EXPECT_LT(r.normal.z, 0);
}

}  // namespace
