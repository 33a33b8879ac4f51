// SPDX-License-Identifier: BSL-1.0
// Row int3.plane-mesh: slice_mesh(vertices, triangles | faces, plane), float and double. Closed
// meshes (an integer cube, an icosphere, a torus; mesh/platonic.hpp) cut by planes through
// vertices exactly (integer or copied coordinates): every loop closes, lies in the plane, runs
// counter-clockwise seen from the positive side; lengths and areas against the analytic values
// (cube) and against a brute force summing each triangle's own exact-sided segment
// (plane_triangle.hpp, an edge in the plane counted half per face); the vertex-on-plane rule
// (a face in the plane: its boundary once from one side, nothing from the other); an open mesh
// gives open chains; empty, NaN, bad index, zero normal; power-of-two scaling (exact).

#include <locus/intersection/plane_mesh.hpp>
#include <locus/intersection/plane_triangle.hpp>
#include <locus/mesh/platonic.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace {

using namespace locus;
using locus_test::Rng;
using Tris = std::vector<std::array<std::uint32_t, 3>>;

template <class T>
class PlaneMesh : public ::testing::Test {};
TYPED_TEST_SUITE(PlaneMesh, locus_test::RealTypes);

template <class T>
double loop_length(const Polyline3<T>& p) {
  double l = 0;
  const std::size_t n = p.vertices.size();
  for (std::size_t i = 0; i + (p.closed ? 0 : 1) < n; ++i) {
    l += length(vec_cast<double>(p.vertices[(i + 1) % n]) - vec_cast<double>(p.vertices[i]));
  }
  return l;
}

// Newell's vector: twice the signed area vector of a closed loop.
template <class T>
Vec3<double> area2(const Polyline3<T>& p) {
  Vec3<double> a{};
  const std::size_t n = p.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    a += cross(vec_cast<double>(p.vertices[i]), vec_cast<double>(p.vertices[(i + 1) % n]));
  }
  return a;
}

// The cube [-1, 1]^3 with integer coordinates (the hexahedron's topology and orientation).
template <class T>
PolygonMesh<T> cube() {
  PolygonMesh<T> m = hexahedron_mesh<T>();
  for (Vec3<T>& v : m.vertices) {
    for (int k = 0; k < 3; ++k) v[k] = v[k] > 0 ? T(1) : T(-1);
  }
  return m;
}

template <class T>
MeshSlice<T> slice(const PolygonMesh<T>& m, const Plane3<T>& p) {
  return slice_mesh(std::span<const Vec3<T>>(m.vertices),
                    std::span<const std::uint32_t>(m.face_offsets),
                    std::span<const std::uint32_t>(m.face_indices), p);
}

// Every polyline closed, every vertex on the plane, the loops' signed areas about the normal
// positive in sum (outer loops counter-clockwise, holes clockwise).
template <class T>
void expect_closed_loops(const MeshSlice<T>& s, const Plane3<T>& p, double scale) {
  ASSERT_EQ(s.status, Status::ok);
  double area = 0;
  for (const Polyline3<T>& l : s.polylines) {
    EXPECT_TRUE(l.closed);
    for (const Vec3<T>& v : l.vertices) {
      EXPECT_LE(std::abs(plane_value(p.normal, p.constant, v)),
                64 * double(eps_v<T>) * scale * length(vec_cast<double>(p.normal)));
    }
    area += dot(area2(l), vec_cast<double>(p.normal));
  }
  if (!s.polylines.empty() && s.polylines[0].vertices.size() >= 3) {
    EXPECT_GT(area, 0.0);
  }
}

// Brute force: the sum of each triangle's own intersection length (an edge lying in the plane
// is reported by both of its faces: half each).
template <class T>
double brute_length(const PolygonMesh<T>& m, const Plane3<T>& p) {
  double l = 0;
  for (const auto& t : fan_triangles(m)) {
    const Triangle3<T> tri{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    const auto r = intersection(tri, p);
    if (r.kind != Kind::segment) continue;
    const double len = length(vec_cast<double>(r.point[1]) - vec_cast<double>(r.point[0]));
    const auto at_vertex = [&](int i) {
      const Vec2<T> st = r.param_a[static_cast<std::size_t>(i)];
      return (st == Vec2<T>{0, 0} || st == Vec2<T>{1, 0} || st == Vec2<T>{0, 1}) &&
             side_of_plane(p.normal, p.constant, r.point[static_cast<std::size_t>(i)]) ==
                 Sign::zero;
    };
    l += at_vertex(0) && at_vertex(1) ? len / 2 : len;
  }
  return l;
}

template <class T>
double total_length(const MeshSlice<T>& s) {
  double l = 0;
  for (const auto& p : s.polylines) l += loop_length(p);
  return l;
}

TYPED_TEST(PlaneMesh, CubeThroughVerticesAnalytic) {
  using T = TypeParam;
  const PolygonMesh<T> m = cube<T>();
  const double r2 = std::numbers::sqrt2, r3 = std::numbers::sqrt3;
  struct Case {
    Plane3<T> p;
    double length, area;
  };
  const Case cases[] = {
      {{{0, 0, 1}, 0}, 8, 4},                // through the middle: a square
      {{{1, 1, 1}, 1}, 6 * r2, 2 * r3},      // through three vertices: a triangle
      {{{1, 1, 0}, 0}, 4 * r2 + 4, 4 * r2},  // through two opposite edges: a rectangle
      {{{0, 0, 1}, 1}, 8, 4},                // the top face in the plane: its boundary
      {{{1, 1, 1}, 3}, 0, 0},                // touching a vertex from the negative side
  };
  for (const Case& c : cases) {
    const MeshSlice<T> s = slice(m, c.p);
    expect_closed_loops(s, c.p, 1.0);
    ASSERT_EQ(s.polylines.size(), 1u);
    EXPECT_NEAR(total_length(s), c.length, 1e-5);
    EXPECT_NEAR(length(area2(s.polylines[0])) / 2, c.area, 1e-5);
  }
  // The bottom face in the plane, the rest on the positive side: nothing (the rule).
  EXPECT_TRUE(slice(m, Plane3<T>{{0, 0, 1}, -1}).polylines.empty());
  // Missing the cube.
  const MeshSlice<T> miss = slice(m, Plane3<T>{{0, 0, 1}, 2});
  EXPECT_EQ(miss.status, Status::ok);
  EXPECT_TRUE(miss.polylines.empty());
}

// Icosphere and torus cut by planes z = (a vertex's z) and x = (a vertex's x): the plane holds
// that vertex exactly; loops closed, length equal to the brute force, sphere: near 2 pi r.
TYPED_TEST(PlaneMesh, SphereAndTorusThroughVertices) {
  using T = TypeParam;
  const PolygonMesh<T> meshes[2] = {icosphere_mesh<T>(T(1), 2),
                                    torus_mesh<T>(T(2), T(0.75), 24, 12)};
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int mi = 0; mi < 2; ++mi) {
    const PolygonMesh<T>& m = meshes[mi];
    for (int trial = 0; trial < 6; ++trial) {
      const auto v = m.vertices[static_cast<std::size_t>(
          rng.uniform_int(0, static_cast<int>(m.vertices.size()) - 1))];
      const int axis = trial % 3;
      Vec3<T> n{};
      n[axis] = T(1);
      if (mi == 1 && axis == 2 && std::abs(double(v.z)) > 0.7) continue;  // tangent: skip
      const Plane3<T> p{n, v[axis]};
      const MeshSlice<T> s = slice(m, p);
      SCOPED_TRACE("mesh " + std::to_string(mi) + " trial " + std::to_string(trial));
      expect_closed_loops(s, p, 3.0);
      ASSERT_FALSE(s.polylines.empty());
      const double want = brute_length(m, p);
      EXPECT_NEAR(total_length(s), want, 1e-4 * want + 1e-6);
      if (mi == 0) {
        ASSERT_EQ(s.polylines.size(), 1u);
        const double r = std::sqrt(std::max(0.0, 1.0 - double(v[axis]) * double(v[axis])));
        EXPECT_LE(total_length(s), 2 * std::numbers::pi * r + 1e-5);
        EXPECT_GE(total_length(s), 0.8 * 2 * std::numbers::pi * r);
      }
    }
  }
  // The torus cut through its axis: two loops (the tube's sections), each near 2 pi r.
  const MeshSlice<T> s = slice(meshes[1], Plane3<T>{{0, 1, 0}, 0});
  expect_closed_loops(s, Plane3<T>{{0, 1, 0}, 0}, 3.0);
  EXPECT_EQ(s.polylines.size(), 2u);
  // Through the equator z = 0: two concentric loops, the inner one clockwise (a hole).
  const MeshSlice<T> e = slice(meshes[1], Plane3<T>{{0, 0, 1}, 0});
  ASSERT_EQ(e.polylines.size(), 2u);
  double signed_area = 0;
  for (const auto& l : e.polylines) signed_area += area2(l).z / 2;
  EXPECT_GT(signed_area, 0.0);
}

TYPED_TEST(PlaneMesh, OpenMeshGivesOpenChains) {
  using T = TypeParam;
  const PolygonMesh<T> sphere = icosphere_mesh<T>(T(1), 2);
  Tris tris;
  for (const auto& t : fan_triangles(sphere)) {
    const double z = (double(sphere.vertices[t[0]].z) + double(sphere.vertices[t[1]].z) +
                      double(sphere.vertices[t[2]].z)) /
                     3;
    if (z < 0.5) tris.push_back(t);  // the cap above z = 0.5 removed
  }
  const MeshSlice<T> s = slice_mesh(sphere.vertices, Tris(tris), Plane3<T>{{1, 0, 0}, 0});
  ASSERT_EQ(s.status, Status::ok);
  ASSERT_EQ(s.polylines.size(), 1u);
  EXPECT_FALSE(s.polylines[0].closed);
  // Both ends at the hole (z about 0.5 or more), the chain through the bottom.
  EXPECT_GT(double(s.polylines[0].vertices.front().z), 0.3);
  EXPECT_GT(double(s.polylines[0].vertices.back().z), 0.3);
}

TYPED_TEST(PlaneMesh, BadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  std::vector<Vec3<T>> v = {{0, 0, -1}, {1, 0, 1}, {0, 1, 1}};
  const Tris one = {{0, 1, 2}};
  const Plane3<T> z0{{0, 0, 1}, 0};
  EXPECT_EQ(slice_mesh(v, Tris{}, z0).status, Status::empty_input);
  EXPECT_EQ(slice_mesh(v, Tris{{0, 1, 3}}, z0).status, Status::invalid_input);
  EXPECT_EQ(slice_mesh(v, one, Plane3<T>{{0, 0, 0}, 0}).status, Status::degenerate_input);
  EXPECT_EQ(slice_mesh(v, one, Plane3<T>{{0, 0, nan}, 0}).status, Status::non_finite_input);
  const MeshSlice<T> ok = slice_mesh(v, one, z0);
  ASSERT_EQ(ok.status, Status::ok);
  ASSERT_EQ(ok.polylines.size(), 1u);
  EXPECT_FALSE(ok.polylines[0].closed);
  EXPECT_EQ(ok.polylines[0].vertices.size(), 2u);
  v[1].x = nan;
  EXPECT_EQ(slice_mesh(v, one, z0).status, Status::non_finite_input);
  const std::vector<std::uint32_t> bad_offsets = {0, 2};
  const std::vector<std::uint32_t> idx = {0, 1};
  EXPECT_EQ(slice_mesh(std::span<const Vec3<T>>(v), std::span<const std::uint32_t>(bad_offsets),
                       std::span<const std::uint32_t>(idx), z0)
                .status,
            Status::invalid_input);
}

TYPED_TEST(PlaneMesh, PowerOfTwoScalingIsExact) {
  using T = TypeParam;
  const PolygonMesh<T> m = icosphere_mesh<T>(T(1), 1);
  const Plane3<T> p{{T(0.25), T(-0.5), T(1)}, T(0.125)};
  const MeshSlice<T> s = slice(m, p);
  ASSERT_EQ(s.polylines.size(), 1u);
  for (const int k : {-16, 16}) {
    const T f = std::ldexp(T(1), k);
    PolygonMesh<T> ms = m;
    for (Vec3<T>& x : ms.vertices) x = x * f;
    const MeshSlice<T> t = slice(ms, Plane3<T>{p.normal, p.constant * f});
    ASSERT_EQ(t.polylines.size(), s.polylines.size());
    ASSERT_EQ(t.polylines[0].vertices.size(), s.polylines[0].vertices.size());
    for (std::size_t i = 0; i < s.polylines[0].vertices.size(); ++i) {
      EXPECT_EQ(t.polylines[0].vertices[i], s.polylines[0].vertices[i] * f);
    }
  }
}

}  // namespace

// ---- plane vs polygon and polygon vs triangle (plane_polygon.hpp), against brute force over
// the fan triangles of star-shaped polygons (plane_triangle.hpp, triangle-triangle find).

#include <locus/intersection/plane_polygon.hpp>

namespace {

// A star-shaped polygon (from its first vertex, the centre) in the plane z = x / 4 + y / 2.
template <class T>
std::vector<Vec3<T>> star(Rng& rng, int n) {
  std::vector<Vec3<T>> v;
  v.push_back({0, 0, 0});
  for (int i = 0; i < n; ++i) {
    const double a = 1.5 * std::numbers::pi * (i + rng.uniform(0.1, 0.9)) / n;
    const double r = rng.uniform(0.3, 1.0);
    const T x = T(std::round(r * std::cos(a) * 64) / 64),
            y = T(std::round(r * std::sin(a) * 64) / 64);
    v.push_back({x, y, x / 4 + y / 2});
  }
  return v;
}

template <class T>
double pieces_length(const std::vector<Segment3<T>>& s) {
  double l = 0;
  for (const auto& g : s) l += length(vec_cast<double>(g.p1) - vec_cast<double>(g.p0));
  return l;
}

TYPED_TEST(PlaneMesh, PlaneAgainstPolygonBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 60; ++trial) {
    const std::vector<Vec3<T>> poly = star<T>(rng, 7);
    const Plane3<T> p{{T(rng.uniform_int(-3, 3)), T(rng.uniform_int(-3, 3)), 1},
                      T(rng.uniform_int(-4, 4)) / 8};
    const auto r = intersection(std::span<const Vec3<T>>(poly), p);
    ASSERT_EQ(r.status, Status::ok);
    double want = 0;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
      const auto s = intersection(Triangle3<T>{poly[0], poly[i], poly[i + 1]}, p);
      if (s.kind == Kind::segment) {
        want += length(vec_cast<double>(s.point[1]) - vec_cast<double>(s.point[0]));
      }
    }
    EXPECT_NEAR(pieces_length(r.segments), want, 1e-4) << "trial " << trial;
    for (const auto& g : r.segments) {
      EXPECT_LE(std::abs(plane_value(p.normal, p.constant, g.p0)), 1e-5);
      EXPECT_LE(std::abs(plane_value(p.normal, p.constant, g.p1)), 1e-5);
    }
  }
  // Coplanar; a vertex touching; an edge in the plane from one side.
  const std::vector<Vec3<T>> sq = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_TRUE(intersection(std::span<const Vec3<T>>(sq), Plane3<T>{{0, 0, 1}, 0}).coplanar);
  auto t = intersection(std::span<const Vec3<T>>(sq), Plane3<T>{{1, 1, 0}, 2});
  ASSERT_EQ(t.segments.size(), 1u);
  EXPECT_EQ(t.segments[0].p0, t.segments[0].p1);
  t = intersection(std::span<const Vec3<T>>(sq), Plane3<T>{{1, 0, 0}, 1});
  ASSERT_EQ(t.segments.size(), 1u);
  EXPECT_NEAR(length(vec_cast<double>(t.segments[0].p1 - t.segments[0].p0)), 1.0, 1e-6);
  EXPECT_EQ(intersection(std::span<const Vec3<T>>(sq.data(), 2), Plane3<T>{{1, 0, 0}, 1}).status,
            Status::empty_input);
}

TYPED_TEST(PlaneMesh, PolygonAgainstTriangleBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 60; ++trial) {
    const std::vector<Vec3<T>> poly = star<T>(rng, 6);
    const bool coplanar = trial % 2 == 0;
    Triangle3<T> tri;
    for (int i = 0; i < 3; ++i) {
      const T x = T(rng.uniform_int(-64, 64)) / 64, y = T(rng.uniform_int(-64, 64)) / 64;
      tri[i] = {x, y, coplanar ? x / 4 + y / 2 : T(rng.uniform_int(-64, 64)) / 64};
    }
    if (is_degenerate(tri)) continue;
    const auto r = intersection(std::span<const Vec3<T>>(poly), tri);
    ASSERT_EQ(r.status, Status::ok);
    ASSERT_EQ(r.coplanar, coplanar);
    double want = 0;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
      const auto s = intersection(Triangle3<T>{poly[0], poly[i], poly[i + 1]}, tri);
      if (coplanar && s.kind == Kind::polygon) {
        Vec3<double> a{};
        for (int k = 0; k < s.count; ++k) {
          a += cross(vec_cast<double>(s.point[static_cast<std::size_t>(k)]),
                     vec_cast<double>(s.point[static_cast<std::size_t>((k + 1) % s.count)]));
        }
        want += length(a) / 2;
      }
      if (!coplanar && s.kind == Kind::segment) {
        want += length(vec_cast<double>(s.point[1]) - vec_cast<double>(s.point[0]));
      }
    }
    if (coplanar) {
      Vec3<double> a{};
      for (std::size_t k = 0; k < r.polygon.size(); ++k) {
        a += cross(vec_cast<double>(r.polygon[k]),
                   vec_cast<double>(r.polygon[(k + 1) % r.polygon.size()]));
      }
      EXPECT_NEAR(length(a) / 2, want, 1e-4) << "trial " << trial;
    } else {
      EXPECT_NEAR(pieces_length(r.segments), want, 1e-4) << "trial " << trial;
    }
  }
}

// Two crossings 2^-100 apart along the line (a notch of the polygon between them): they round to
// one point but are ordered exactly, so the outside gap between them is kept and the pieces stay
// two (ordering by rounded keys merged them into one piece across the notch).
TYPED_TEST(PlaneMesh, PolygonPiecesAcrossANotchBelowTheRounding) {
  using T = double;  // the notch needs double coordinates
  const double e = std::ldexp(1.0, -40), d = std::ldexp(1.0, -99);
  const std::vector<Vec3<T>> notch = {{0, -1, 0}, {2, -1, 0}, {2, 0, 0}, {0, 2 * e, 0},
                                      {2, d, 0},  {2, 3, 0},  {0, 3, 0}};
  const auto r = intersection(std::span<const Vec3<T>>(notch), Plane3<T>{{1, 0, 0}, 1});
  ASSERT_EQ(r.status, Status::ok);
  ASSERT_EQ(r.segments.size(), 2u);
  // Ordered along cross(plane normal, polygon normal) = -y (the polygon is counter-clockwise).
  EXPECT_EQ(r.segments[0].p0, (Vec3<T>{1, 3, 0}));
  EXPECT_EQ(r.segments[0].p1, (Vec3<T>{1, e, 0}));  // e + 2^-100, rounded
  EXPECT_EQ(r.segments[1].p0, (Vec3<T>{1, e, 0}));
  EXPECT_EQ(r.segments[1].p1, (Vec3<T>{1, -1, 0}));
  // The same against a triangle in the plane x = 1 spanning y in [-5, 5] at z = 0.
  const Triangle3<T> tri{{1, -10, -10}, {1, 10, -10}, {1, 0, 10}};
  const auto t = intersection(std::span<const Vec3<T>>(notch), tri);
  ASSERT_EQ(t.status, Status::ok);
  ASSERT_FALSE(t.coplanar);
  ASSERT_EQ(t.segments.size(), 2u);
  EXPECT_EQ(t.segments[0].p0, (Vec3<T>{1, 3, 0}));
  EXPECT_EQ(t.segments[1].p1, (Vec3<T>{1, -1, 0}));
  // Scaled by powers of two: the same pieces, scaled.
  for (const int k : {-500, 400}) {
    const double f = std::ldexp(1.0, k);
    std::vector<Vec3<T>> scaled;
    for (const auto& p : notch) scaled.push_back(f * p);
    const auto rs = intersection(std::span<const Vec3<T>>(scaled), Plane3<T>{{1, 0, 0}, f});
    ASSERT_EQ(rs.segments.size(), 2u);
    EXPECT_EQ(rs.segments[0].p1, f * r.segments[0].p1);
    EXPECT_EQ(rs.segments[1].p0, f * r.segments[1].p0);
  }
}

}  // namespace
