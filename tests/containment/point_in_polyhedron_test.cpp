// SPDX-License-Identifier: BSL-1.0
// Tests of containment/point_in_polyhedron.hpp (row cg.piph). Oracles: GMP-rational barycentric
// coordinates and half-space tests for convex solids; for non-convex closed meshes, solids made
// of unit voxels (L shape, a ring like a torus, random voxel sets), classified by the occupancy
// of the eight voxels around a half-integer query point (an oracle with no ray at all), also
// after an exact integer shear and translation.
#include <locus/containment/point_in_polyhedron.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <vector>

namespace {

using locus::Plane3;
using locus::Side;
using locus::Tetrahedron3;
using locus::Vec3;
using locus_test::Rng;
using Tri = std::array<std::uint32_t, 3>;

template <class T>
class PointInPolyhedron : public ::testing::Test {};
TYPED_TEST_SUITE(PointInPolyhedron, locus_test::RealTypes);

struct Q3 {
  mpq_class x, y, z;
};
template <class T>
Q3 q(const Vec3<T>& v) {
  return {mpq_class(double(v.x)), mpq_class(double(v.y)), mpq_class(double(v.z))};
}
int sgn(const mpq_class& v) { return mpq_sgn(v.get_mpq_t()); }
// det[b - a; c - a; d - a]
int orient(const Q3& a, const Q3& b, const Q3& c, const Q3& d) {
  const mpq_class ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const mpq_class vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const mpq_class wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  return sgn(
      mpq_class(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)));
}

// Exact half-space oracle for a convex mesh with outward faces.
Side convex_oracle(const std::vector<Q3>& v, const std::vector<Tri>& tris, const Q3& p) {
  bool zero = false;
  for (const Tri& t : tris) {
    const int s = orient(v[t[0]], v[t[1]], v[t[2]], p);
    if (s > 0) return Side::outside;
    zero = zero || s == 0;
  }
  return zero ? Side::boundary : Side::inside;
}

template <class T>
Vec3<T> grid(Rng& rng, int lo, int hi) {
  return {T(rng.uniform_int(lo, hi)), T(rng.uniform_int(lo, hi)), T(rng.uniform_int(lo, hi))};
}

// ---- tetrahedron -------------------------------------------------------------------------------

TYPED_TEST(PointInPolyhedron, TetrahedronVsRationalBarycentric) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int counts[3] = {0, 0, 0};
  for (int it = 0; it < 2000; ++it) {
    Tetrahedron3<T> t{};
    for (auto& v : t.v) v = grid<T>(rng, -3, 3) * T(12);
    Vec3<T> p;
    switch (it % 5) {
      case 0:
        p = t.v[rng.uniform_int(0, 3)];
        break;
      case 1:
        p = T(0.5) * (t.v[0] + t.v[2]);
        break;
      case 2:
        p = (t.v[1] + t.v[2] + t.v[3]) / T(3);
        break;  // exact: multiples of 12
      case 3:
        p = (t.v[0] + t.v[1] + t.v[2] + t.v[3]) / T(4);
        break;
      default:
        p = grid<T>(rng, -40, 40);
    }
    // Oracle: signs of the four sub-volumes relative to the total (Cramer in rationals).
    const Q3 a = q(t.v[0]), b = q(t.v[1]), c = q(t.v[2]), d = q(t.v[3]), x = q(p);
    const int o = orient(a, b, c, d);
    Side expect;
    if (o == 0) {
      continue;  // flat tetrahedra: tested separately
    } else {
      const int s[4] = {orient(x, b, c, d) * o, orient(a, x, c, d) * o, orient(a, b, x, d) * o,
                        orient(a, b, c, x) * o};
      const bool neg = s[0] < 0 || s[1] < 0 || s[2] < 0 || s[3] < 0;
      const bool zero = s[0] == 0 || s[1] == 0 || s[2] == 0 || s[3] == 0;
      expect = neg ? Side::outside : (zero ? Side::boundary : Side::inside);
    }
    ASSERT_EQ(locus::classify(p, t), expect) << it;
    ASSERT_EQ(locus::contains(t, p), expect != Side::outside);
    ++counts[int(expect) + 1];
  }
  EXPECT_GT(counts[0], 200);
  EXPECT_GT(counts[1], 200);
  EXPECT_GT(counts[2], 100);
}

TYPED_TEST(PointInPolyhedron, FlatTetrahedronAndBadInput) {
  using T = TypeParam;
  // Four coplanar points: a square in z = 0.
  const Tetrahedron3<T> flat{
      {{T(0), T(0), T(0)}, {T(2), T(0), T(0)}, {T(2), T(2), T(0)}, {T(0), T(2), T(0)}}};
  EXPECT_EQ(locus::classify(Vec3<T>{T(1), T(1), T(0)}, flat), Side::boundary);
  EXPECT_EQ(locus::classify(Vec3<T>{T(2), T(1), T(0)}, flat), Side::boundary);
  EXPECT_EQ(locus::classify(Vec3<T>{T(1), T(1), T(1)}, flat), Side::outside);
  EXPECT_EQ(locus::classify(Vec3<T>{T(3), T(1), T(0)}, flat), Side::outside);
  // Collinear points: a segment.
  const Tetrahedron3<T> line{
      {{T(0), T(0), T(0)}, {T(1), T(1), T(1)}, {T(3), T(3), T(3)}, {T(2), T(2), T(2)}}};
  EXPECT_EQ(locus::classify(Vec3<T>{T(2.5), T(2.5), T(2.5)}, line), Side::boundary);
  EXPECT_EQ(locus::classify(Vec3<T>{T(4), T(4), T(4)}, line), Side::outside);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Tetrahedron3<T> unit{
      {{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}};
  EXPECT_EQ(locus::classify(Vec3<T>{nan, T(0.1), T(0.1)}, unit), Side::outside);
  EXPECT_EQ(locus::classify(Vec3<T>{T(0.1), T(0.1), T(0.1)}, unit), Side::inside);
  Tetrahedron3<T> bad = unit;
  bad.v[2].y = std::numeric_limits<T>::infinity();
  EXPECT_EQ(locus::classify(Vec3<T>{T(0.1), T(0.1), T(0.1)}, bad), Side::outside);
}

// ---- convex solids ------------------------------------------------------------------------------

template <class T>
struct Mesh {
  std::vector<Vec3<T>> v;
  std::vector<Tri> t;
};

// The Platonic cube [0, 2]^3, octahedron |x|+|y|+|z| <= 2 and tetrahedron, outward faces.
template <class T>
std::vector<Mesh<T>> convex_solids() {
  std::vector<Mesh<T>> out;
  Mesh<T> cube;
  for (int i = 0; i < 8; ++i)
    cube.v.push_back({T(2 * (i & 1)), T(2 * ((i >> 1) & 1)), T(2 * (i >> 2))});
  cube.t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  out.push_back(cube);
  Mesh<T> octa;
  octa.v = {{T(2), T(0), T(0)},  {T(-2), T(0), T(0)}, {T(0), T(2), T(0)},
            {T(0), T(-2), T(0)}, {T(0), T(0), T(2)},  {T(0), T(0), T(-2)}};
  octa.t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  out.push_back(octa);
  Mesh<T> tet;
  tet.v = {{T(0), T(0), T(0)}, {T(4), T(0), T(0)}, {T(0), T(4), T(0)}, {T(0), T(0), T(4)}};
  tet.t = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  out.push_back(tet);
  return out;
}

TYPED_TEST(PointInPolyhedron, ConvexMeshesVsRationalHalfSpaces) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int boundary = 0;
  for (const Mesh<T>& base : convex_solids<T>()) {
    ASSERT_TRUE(locus::is_closed_mesh(base.t));
    for (int it = 0; it < 20; ++it) {
      // A random unimodular integer map (det +-1 keeps the grid exact) and translation.
      int m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      for (int k = 0; k < 3; ++k) {
        const int r = rng.uniform_int(0, 2), s = (r + rng.uniform_int(1, 2)) % 3;
        const int f = rng.uniform_int(-2, 2);
        for (int c = 0; c < 3; ++c) m[r][c] += f * m[s][c];
      }
      const Vec3<T> shift = grid<T>(rng, -5, 5);
      Mesh<T> mesh = base;
      for (auto& x : mesh.v) {
        const Vec3<T> y = x;
        for (int r = 0; r < 3; ++r) x[r] = T(m[r][0]) * y.x + T(m[r][1]) * y.y + T(m[r][2]) * y.z;
        x += shift;
      }
      std::vector<Q3> qv;
      for (const auto& x : mesh.v) qv.push_back(q(x));
      for (int k = 0; k < 100; ++k) {
        Vec3<T> p = grid<T>(rng, -12, 12);
        if (k % 4 == 0) {
          const Tri& t = mesh.t[std::size_t(rng.uniform_int(0, int(mesh.t.size()) - 1))];
          p = T(0.5) *
              (mesh.v[t[0]] + mesh.v[t[std::size_t(1 + (k / 4) % 2)]]);  // vertex or edge midpoint
          if (k % 8 == 0) p = mesh.v[t[0]];
        }
        const Side expect = convex_oracle(qv, mesh.t, q(p));
        const std::span<const Vec3<T>> vs(mesh.v);
        const std::span<const Tri> ts(mesh.t);
        ASSERT_EQ(locus::classify_convex(p, vs, ts), expect);
        ASSERT_EQ(locus::classify(p, vs, ts), expect) << it << " " << k;
        boundary += expect == Side::boundary;
      }
    }
  }
  EXPECT_GT(boundary, 300);
}

TYPED_TEST(PointInPolyhedron, PlanesMatchBoxAndMesh) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  // The box [-1, 2] x [0, 3] x [1, 1.5] as six outward half-spaces, with non-unit normals.
  const std::vector<Plane3<T>> box{{{T(-3), T(0), T(0)}, T(3)},  {{T(2), T(0), T(0)}, T(4)},
                                   {{T(0), T(-1), T(0)}, T(0)},  {{T(0), T(5), T(0)}, T(15)},
                                   {{T(0), T(0), T(-2)}, T(-2)}, {{T(0), T(0), T(4)}, T(6)}};
  for (int k = 0; k < 3000; ++k) {
    const Vec3<T> p{T(rng.uniform_int(-6, 6)) * T(0.5), T(rng.uniform_int(-2, 8)) * T(0.5),
                    T(rng.uniform_int(0, 7)) * T(0.25)};
    const bool in =
        p.x > T(-1) && p.x < T(2) && p.y > T(0) && p.y < T(3) && p.z > T(1) && p.z < T(1.5);
    const bool closed =
        p.x >= T(-1) && p.x <= T(2) && p.y >= T(0) && p.y <= T(3) && p.z >= T(1) && p.z <= T(1.5);
    const Side expect = in ? Side::inside : (closed ? Side::boundary : Side::outside);
    ASSERT_EQ(locus::classify(p, std::span<const Plane3<T>>(box)), expect) << k;
  }
  // Near-degenerate: a tilted plane through the origin, points one ulp off it.
  const std::vector<Plane3<T>> tilt{{{T(0.1), T(0.7), T(-0.3)}, T(0)}};
  const Vec3<T> on{T(0), T(0), T(0)};
  EXPECT_EQ(locus::classify(on, std::span<const Plane3<T>>(tilt)), Side::boundary);
  for (int k = 0; k < 200; ++k) {
    const Vec3<T> p = rng.vec<T, 3>(T(-1), T(1));
    const Q3 x = q(p);
    const mpq_class val = mpq_class(double(T(0.1))) * x.x + mpq_class(double(T(0.7))) * x.y -
                          mpq_class(double(T(0.3))) * x.z;
    const Side expect =
        sgn(val) > 0 ? Side::outside : (sgn(val) == 0 ? Side::boundary : Side::inside);
    ASSERT_EQ(locus::classify(p, std::span<const Plane3<T>>(tilt)), expect);
  }
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(locus::classify(Vec3<T>{nan, T(0), T(0)}, std::span<const Plane3<T>>(box)),
            Side::outside);
  EXPECT_EQ(locus::classify(Vec3<T>{T(0), T(0), T(0)}, std::span<const Plane3<T>>()), Side::inside);
  const std::vector<Plane3<T>> bad{{{nan, T(0), T(0)}, T(0)}};
  EXPECT_EQ(locus::classify(Vec3<T>{}, std::span<const Plane3<T>>(bad)), Side::outside);
}

// ---- figures 13.18, 13.19
// ------------------------------------------------------------------------

// The octahedron |x| + |y| + |z| <= 2: rays along +x through its vertices and edges.
TYPED_TEST(PointInPolyhedron, Figures13_18And13_19DegenerateRays) {
  using T = TypeParam;
  const Mesh<T> o = convex_solids<T>()[1];
  const std::span<const Vec3<T>> vs(o.v);
  const std::span<const Tri> ts(o.t);
  auto at = [&](T x, T y, T z) { return locus::classify(Vec3<T>{x, y, z}, vs, ts); };
  // 13.18(b): the ray crosses shared edges where the faces are on opposite sides of the plane of
  // the edge and the ray (y = 1, z = 0 meets edges at x = -1 and x = 1).
  EXPECT_EQ(at(T(-5), T(1), T(0)), Side::outside);
  EXPECT_EQ(at(T(0), T(1), T(0)), Side::inside);
  EXPECT_EQ(at(T(1), T(1), T(0)), Side::boundary);
  // 13.18(a): the ray grazes the edge (0, 2, 0)-(0, 0, 2) with both faces on one side.
  EXPECT_EQ(at(T(-5), T(1), T(1)), Side::outside);
  EXPECT_EQ(at(T(0), T(1), T(1)), Side::boundary);
  EXPECT_EQ(at(T(0.5), T(1), T(1)), Side::outside);
  // 13.19 point A: the ray enters through the vertex (-2, 0, 0) and leaves through (2, 0, 0).
  EXPECT_EQ(at(T(-5), T(0), T(0)), Side::outside);
  EXPECT_EQ(at(T(0), T(0), T(0)), Side::inside);
  EXPECT_EQ(at(T(3), T(0), T(0)), Side::outside);
  // 13.19 point B: the ray touches the vertex (0, 0, 2) without entering.
  EXPECT_EQ(at(T(-5), T(0), T(2)), Side::outside);
  EXPECT_EQ(at(T(0), T(0), T(2)), Side::boundary);
}

// ---- non-convex closed meshes -------------------------------------------------------------------

using Voxels = std::set<std::tuple<int, int, int>>;

// The boundary faces of a union of unit voxels, outward, with shared (deduplicated) vertices.
template <class T>
Mesh<T> voxel_mesh(const Voxels& vox) {
  Mesh<T> m;
  std::map<std::tuple<int, int, int>, std::uint32_t> index;
  auto vid = [&](int x, int y, int z) {
    const auto key = std::make_tuple(x, y, z);
    const auto it = index.find(key);
    if (it != index.end()) return it->second;
    const auto id = static_cast<std::uint32_t>(m.v.size());
    m.v.push_back({T(x), T(y), T(z)});
    index.emplace(key, id);
    return id;
  };
  for (const auto& [x, y, z] : vox) {
    for (int axis = 0; axis < 3; ++axis)
      for (int dir = -1; dir <= 1; dir += 2) {
        int n[3] = {x, y, z};
        n[axis] += dir;
        if (vox.count({n[0], n[1], n[2]})) continue;
        // The face at the voxel's side `dir` along `axis`, corners in the other two axes.
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        int c[4][3];
        const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
        for (int k = 0; k < 4; ++k) {
          c[k][0] = x;
          c[k][1] = y;
          c[k][2] = z;
          c[k][axis] += dir > 0 ? 1 : 0;
          c[k][u] += du[k];
          c[k][w] += dw[k];
        }
        std::uint32_t id[4];
        for (int k = 0; k < 4; ++k) id[k] = vid(c[k][0], c[k][1], c[k][2]);
        // (u, w, axis) is right-handed: counter-clockwise in (u, w) faces +axis.
        if (dir > 0) {
          m.t.push_back({id[0], id[1], id[2]});
          m.t.push_back({id[0], id[2], id[3]});
        } else {
          m.t.push_back({id[0], id[2], id[1]});
          m.t.push_back({id[0], id[3], id[2]});
        }
      }
  }
  return m;
}

// Half-integer coordinates (2 * p integer): occupancy of the up to eight voxels around p.
Side voxel_oracle(const Voxels& vox, const int p2[3]) {
  int total = 0, occupied = 0;
  int lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    // p odd/2 lies inside voxel floor(p); p even/2 touches voxels p-1 and p.
    if (p2[i] % 2 != 0) {
      lo[i] = hi[i] = static_cast<int>(std::floor(p2[i] / 2.0));
    } else {
      lo[i] = p2[i] / 2 - 1;
      hi[i] = p2[i] / 2;
    }
  }
  for (int x = lo[0]; x <= hi[0]; ++x)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int z = lo[2]; z <= hi[2]; ++z) {
        ++total;
        occupied += vox.count({x, y, z}) ? 1 : 0;
      }
  return occupied == 0 ? Side::outside : (occupied == total ? Side::inside : Side::boundary);
}

template <class T>
void check_voxels(const Voxels& vox, Rng& rng, int queries, bool shear) {
  Mesh<T> m = voxel_mesh<T>(vox);
  ASSERT_TRUE(locus::is_closed_mesh(m.t));
  // An exact integer shear (x, y, z) -> (x + a y + b z, y + c z, z) + shift; queries map along.
  const int a = shear ? rng.uniform_int(-2, 2) : 0, b = shear ? rng.uniform_int(-2, 2) : 0;
  const int c = shear ? rng.uniform_int(-2, 2) : 0;
  const Vec3<T> shift = shear ? grid<T>(rng, -3, 3) : Vec3<T>{};
  auto map = [&](const Vec3<T>& v) {
    return Vec3<T>{v.x + T(a) * v.y + T(b) * v.z, v.y + T(c) * v.z, v.z} + shift;
  };
  for (auto& v : m.v) v = map(v);
  const std::span<const Vec3<T>> vs(m.v);
  const std::span<const Tri> ts(m.t);
  int counts[3] = {0, 0, 0};
  for (int k = 0; k < queries; ++k) {
    const int p2[3] = {rng.uniform_int(-2, 8), rng.uniform_int(-2, 8), rng.uniform_int(-2, 8)};
    const Vec3<T> p = map(Vec3<T>{T(p2[0]) * T(0.5), T(p2[1]) * T(0.5), T(p2[2]) * T(0.5)});
    const Side expect = voxel_oracle(vox, p2);
    ASSERT_EQ(locus::classify(p, vs, ts), expect)
        << k << " p = " << p.x << " " << p.y << " " << p.z << " shear " << a << b << c;
    ++counts[int(expect) + 1];
  }
  EXPECT_GT(counts[1], 0);
}

TYPED_TEST(PointInPolyhedron, LShapeAndRingVsVoxelOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Voxels l_shape{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 2, 0},
                       {0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {0, 1, 1}, {0, 2, 1}};
  Voxels ring;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      if (x != 1 || y != 1) ring.insert({x, y, 1});
  for (int s = 0; s < 6; ++s) {
    check_voxels<T>(l_shape, rng, 400, s > 0);
    check_voxels<T>(ring, rng, 400, s > 0);
  }
}

TYPED_TEST(PointInPolyhedron, RandomVoxelSolidsVsVoxelOracle) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 20; ++it) {
    Voxels vox;
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y)
        for (int z = 0; z < 3; ++z)
          if (rng.uniform_int(0, 1)) vox.insert({x, y, z});
    if (vox.empty()) continue;
    check_voxels<T>(vox, rng, 300, it % 2 == 1);
  }
}

TYPED_TEST(PointInPolyhedron, MeshBadInput) {
  using T = TypeParam;
  const Mesh<T> cube = convex_solids<T>()[0];
  const std::span<const Vec3<T>> vs(cube.v);
  const std::span<const Tri> ts(cube.t);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(locus::classify(Vec3<T>{nan, T(1), T(1)}, vs, ts), Side::outside);
  EXPECT_EQ(locus::classify_convex(Vec3<T>{nan, T(1), T(1)}, vs, ts), Side::outside);
  EXPECT_EQ(locus::classify(Vec3<T>{T(1), T(1), T(1)}, vs, std::span<const Tri>()), Side::outside);
  EXPECT_EQ(locus::classify_convex(Vec3<T>{T(1), T(1), T(1)}, vs, std::span<const Tri>()),
            Side::outside);
  EXPECT_TRUE(locus::contains(vs, ts, Vec3<T>{T(1), T(1), T(1)}));
  // Out-of-range indices are skipped, never read.
  std::vector<Tri> broken = cube.t;
  broken.push_back({0, 1, 99});
  EXPECT_EQ(locus::classify(Vec3<T>{T(1), T(1), T(1)}, vs, std::span<const Tri>(broken)),
            Side::inside);
  // An open mesh is reported by is_closed_mesh.
  std::vector<Tri> open = cube.t;
  open.pop_back();
  EXPECT_FALSE(locus::is_closed_mesh(open));
  EXPECT_TRUE(locus::is_closed_mesh(std::span<const Tri>()));
}

}  // namespace
