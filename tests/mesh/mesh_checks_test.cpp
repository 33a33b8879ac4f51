// SPDX-License-Identifier: BSL-1.0
// Row mesh.checks: each check against a brute-force oracle (faces per edge by scanning every
// face, components by repeated relaxation, fans by counting, self-intersection by all pairs of
// triangles with the exact GMP oracle of triangle_oracle.hpp deciding how far the common set
// reaches past shared vertices) on constructed good and bad meshes: the generators (closed,
// manifold, orientable; Euler characteristic 2, the torus 0), the book's figures 9.8-9.16
// (isolated vertex and edge, interpenetration, a depression, a vertex-touching pair, three faces
// on an edge, the dodecahedron polytope, the cylinder strip and the Möbius strip), two cubes
// glued at an edge, bow-ties, random face flips undone by make_consistent, random triangle sets
// on a small grid (many shared vertices, coplanar folds), degenerate input, float and double,
// and power-of-two scaling (every combinatorial answer unchanged).

#include <locus/intersection/triangle_triangle.hpp>
#include <locus/mesh/mesh_checks.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/mesh/polygon_mesh.hpp>
#include <locus/mesh/vet_mesh.hpp>

#include "mesh/triangle_oracle.hpp"
#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <vector>

namespace {

using namespace locus;
using locus_test::Rng;
constexpr std::uint32_t npos = VetMesh::npos;

template <class T>
class MeshChecks : public ::testing::Test {};
TYPED_TEST_SUITE(MeshChecks, locus_test::RealTypes);

template <class T>
PolygonMesh<T> make(const std::vector<Vec3<double>>& pts,
                    const std::vector<std::vector<std::uint32_t>>& faces) {
  PolygonMesh<T> m;
  for (const auto& p : pts) m.vertices.push_back(vec_cast<T>(p));
  for (const auto& f : faces) add_face(m, std::span<const std::uint32_t>(f));
  return m;
}

template <class T>
PolygonMesh<T> scaled(PolygonMesh<T> m, int k) {
  for (auto& v : m.vertices) v = v * std::ldexp(T(1), k);
  return m;
}

// ---- brute-force oracles -------------------------------------------------------------------

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;

template <class T>
std::map<EdgeKey, int> faces_per_edge(const PolygonMesh<T>& m) {
  std::map<EdgeKey, int> r;
  for (std::size_t f = 0; f < face_count(m); ++f) {
    const auto c = face(m, f);
    for (std::size_t i = 0; i < c.size(); ++i) {
      const std::uint32_t a = c[i], b = c[(i + 1) % c.size()];
      ++r[{std::min(a, b), std::max(a, b)}];
    }
  }
  return r;
}

// Face components by relaxation: repeat "take the smaller label across a shared edge" until
// nothing changes. Returns the number of distinct labels.
template <class T>
std::size_t brute_face_components(const PolygonMesh<T>& m) {
  const std::size_t n = face_count(m);
  std::vector<std::size_t> label(n);
  for (std::size_t i = 0; i < n; ++i) label[i] = i;
  std::map<EdgeKey, std::vector<std::size_t>> by_edge;
  for (std::size_t f = 0; f < n; ++f) {
    const auto c = face(m, f);
    for (std::size_t i = 0; i < c.size(); ++i) {
      const std::uint32_t a = c[i], b = c[(i + 1) % c.size()];
      by_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [e, fs] : by_edge) {
      std::size_t lo = label[fs[0]];
      for (const std::size_t f : fs) lo = std::min(lo, label[f]);
      for (const std::size_t f : fs) {
        if (label[f] != lo) {
          label[f] = lo;
          changed = true;
        }
      }
    }
  }
  return std::set<std::size_t>(label.begin(), label.end()).size();
}

// Whether the faces around v form more than one fan, by brute force: faces at v are linked
// when they share an edge {v, w} that exactly two faces use; count the groups.
template <class T>
bool brute_non_manifold_vertex(const PolygonMesh<T>& m, std::uint32_t v) {
  const auto per_edge = faces_per_edge(m);
  std::vector<std::size_t> at;
  for (std::size_t f = 0; f < face_count(m); ++f) {
    const auto c = face(m, f);
    if (std::find(c.begin(), c.end(), v) != c.end()) at.push_back(f);
  }
  if (at.empty()) return false;
  const auto nbrs = [&](std::size_t f) {
    const auto c = face(m, f);
    const std::size_t i = static_cast<std::size_t>(std::find(c.begin(), c.end(), v) - c.begin());
    return std::pair{c[(i + 1) % c.size()], c[(i + c.size() - 1) % c.size()]};
  };
  std::vector<std::size_t> label(at.size());
  for (std::size_t i = 0; i < at.size(); ++i) label[i] = i;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < at.size(); ++i) {
      for (std::size_t j = 0; j < at.size(); ++j) {
        const auto [a1, b1] = nbrs(at[i]);
        const auto [a2, b2] = nbrs(at[j]);
        for (const std::uint32_t w : {a1, b1}) {
          if ((w == a2 || w == b2) && per_edge.at({std::min(v, w), std::max(v, w)}) == 2 &&
              label[j] > label[i]) {
            label[j] = label[i];
            changed = true;
          }
        }
      }
    }
  }
  return std::set<std::size_t>(label.begin(), label.end()).size() > 1;
}

// All pairs of fan triangles of different faces; the common set must not reach past the shared
// vertex ids: none shared: disjoint (exact intersects()); s shared: max (1 - l_s) over the common
// set is 0; an edge shared: max of the third vertex's weight is 0; all shared: always reported.
template <class T>
std::vector<std::array<std::uint32_t, 2>> brute_self_intersections(const PolygonMesh<T>& m) {
  struct Tri {
    std::uint32_t face;
    std::array<std::uint32_t, 3> v;
  };
  std::vector<Tri> tris;
  for (std::uint32_t f = 0; f < face_count(m); ++f) {
    const auto c = face(m, f);
    for (std::size_t i = 1; i + 1 < c.size(); ++i) {
      const Triangle3<T> t{m.vertices[c[0]], m.vertices[c[i]], m.vertices[c[i + 1]]};
      if (!is_degenerate(t)) tris.push_back({f, {c[0], c[i], c[i + 1]}});
    }
  }
  std::set<std::array<std::uint32_t, 2>> out;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    for (std::size_t j = i + 1; j < tris.size(); ++j) {
      const Tri& s = tris[i];
      const Tri& t = tris[j];
      if (s.face == t.face) continue;
      const Triangle3<T> a{m.vertices[s.v[0]], m.vertices[s.v[1]], m.vertices[s.v[2]]};
      const Triangle3<T> b{m.vertices[t.v[0]], m.vertices[t.v[1]], m.vertices[t.v[2]]};
      std::array<mpq_class, 6> w{0, 0, 0, 0, 0, 0};
      int shared = 0;
      std::array<bool, 3> in_t{false, false, false};
      for (int x = 0; x < 3; ++x) {
        for (int y = 0; y < 3; ++y) {
          if (s.v[static_cast<std::size_t>(x)] == t.v[static_cast<std::size_t>(y)]) {
            in_t[static_cast<std::size_t>(x)] = true;
            ++shared;
          }
        }
      }
      bool hit = false;
      if (shared == 3) {
        hit = true;
      } else if (shared == 0) {
        hit = intersects(a, b);  // checked against the same GMP oracle in tests/intersection
      } else {
        mpq_class base = 0;
        for (int x = 0; x < 3; ++x) {
          const bool shared_x = in_t[static_cast<std::size_t>(x)];
          if (shared == 1 && shared_x) {
            w[static_cast<std::size_t>(x)] = -1;  // 1 - l_s
            base = 1;
          }
          if (shared == 2 && !shared_x) w[static_cast<std::size_t>(x)] = 1;
        }
        const auto best = locus_test::max_over_common_points(a, b, w);
        hit = best && *best + base > 0;
      }
      if (hit) out.insert({std::min(s.face, t.face), std::max(s.face, t.face)});
    }
  }
  return {out.begin(), out.end()};
}

// ---- tests ---------------------------------------------------------------------------------

template <class T>
void expect_closed_manifold(const PolygonMesh<T>& m, long long chi, MeshKind kind,
                            T tolerance = T(0)) {
  const MeshClassification c = classify_mesh(m, tolerance);
  ASSERT_EQ(c.status, Status::ok);
  EXPECT_TRUE(c.topology.closed);
  EXPECT_TRUE(c.topology.manifold);
  EXPECT_TRUE(c.topology.boundary_edges.empty());
  EXPECT_TRUE(c.orientation.orientable);
  EXPECT_TRUE(c.orientation.flipped_faces.empty());  // generators are consistently oriented
  EXPECT_EQ(c.orientation.components.face_component_count, 1u);
  EXPECT_EQ(c.euler_characteristic, chi);
  EXPECT_TRUE(c.intersections.face_pairs.empty());
  EXPECT_EQ(c.kind, kind);
  for (const auto& [e, n] : faces_per_edge(m)) EXPECT_EQ(n, 2);
}

// Solids whose flat parts stay exactly flat after rounding (axis-aligned faces, rectangles with
// equal x, y, triangles only) are polytopes under the exact test; pentagons and split quads on
// a sphere are flat only up to rounding, so they need a tolerance, and scaling by powers of
// two never changes either answer.
TYPED_TEST(MeshChecks, GeneratorsAreClosedOrientedPolytopes) {
  using T = TypeParam;
  const T tol = 64 * std::numeric_limits<T>::epsilon();
  const std::vector<std::pair<PolygonMesh<T>, bool>> solids = {
      {tetrahedron_mesh<T>(), true},
      {hexahedron_mesh<T>(), true},
      {octahedron_mesh<T>(), true},
      {icosahedron_mesh<T>(), true},
      {icosphere_mesh<T>(T(1), 2), true},
      {cylinder_mesh<T>(T(1), T(3), 9), true},
      {cone_mesh<T>(T(1), T(2), 7), true},
      {dodecahedron_mesh<T>(), false},
      {dodecahedron_triangle_mesh<T>(), false},
      {uv_sphere_mesh<T>(T(2), 12, 7), false}};
  for (const auto& [m, exact] : solids) {
    SCOPED_TRACE(face_count(m));
    expect_closed_manifold(m, 2, MeshKind::polytope, tol);
    if (exact) expect_closed_manifold(m, 2, MeshKind::polytope);
    const MeshKind base = classify_mesh(m).kind;
    for (const int k : {-20, 20}) {
      EXPECT_EQ(classify_mesh(scaled(m, k), tol).kind, MeshKind::polytope);
      EXPECT_EQ(classify_mesh(scaled(m, k)).kind, base);
    }
  }
}

TYPED_TEST(MeshChecks, TorusHasGenusOneAndIsNotConvex) {
  using T = TypeParam;
  const PolygonMesh<T> m = torus_mesh<T>(T(3), T(1), 16, 8);
  expect_closed_manifold(m, 0, MeshKind::polyhedron);
}

// Figure 9.11: a tetrahedron whose face is split at a vertex pushed inwards: still a
// polyhedron, no longer a polytope.
TYPED_TEST(MeshChecks, DepressionIsPolyhedronNotPolytope) {
  using T = TypeParam;
  const PolygonMesh<T> m =
      make<T>({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {1, 1, 0.5}},
              {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 4}, {2, 3, 4}, {3, 1, 4}});
  expect_closed_manifold(m, 2, MeshKind::polyhedron);
  // Pulled outwards instead: a convex polytope again.
  PolygonMesh<T> out = m;
  out.vertices[4] = {T(2), T(2), T(2)};
  expect_closed_manifold(out, 2, MeshKind::polytope);
}

// Figures 9.8 and 9.9: an isolated vertex, an isolated edge.
TYPED_TEST(MeshChecks, IsolatedVertexAndEdge) {
  using T = TypeParam;
  PolygonMesh<T> m = tetrahedron_mesh<T>();
  m.vertices.push_back({T(2), T(2), T(2)});
  MeshClassification c = classify_mesh(m);
  ASSERT_EQ(c.status, Status::ok);
  EXPECT_EQ(c.topology.isolated_vertices, (std::vector<std::uint32_t>{4}));
  EXPECT_EQ(c.kind, MeshKind::not_a_mesh);
  VetMeshBuild b = make_vet_mesh(m);
  const std::uint32_t e = b.mesh.insert_edge(0, 4);
  c = classify_mesh(b.mesh, std::span<const Vec3<T>>(m.vertices));
  EXPECT_TRUE(c.topology.isolated_vertices.empty());
  EXPECT_EQ(c.topology.isolated_edges, (std::vector<std::uint32_t>{e}));
  EXPECT_FALSE(c.topology.closed);
  EXPECT_EQ(c.kind, MeshKind::not_a_mesh);
}

// Figure 9.10: two triangles that interpenetrate; figure 9.12: a tetrahedron and a square that
// share one vertex are two face components but one vertex component.
TYPED_TEST(MeshChecks, InterpenetrationAndVertexTouching) {
  using T = TypeParam;
  const PolygonMesh<T> x =
      make<T>({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}},
              {{0, 1, 2}, {3, 4, 5}});
  const MeshSelfIntersections si = self_intersections(x);
  ASSERT_EQ(si.status, Status::ok);
  EXPECT_EQ(si.face_pairs, (std::vector<std::array<std::uint32_t, 2>>{{0, 1}}));
  EXPECT_EQ(si.face_pairs, brute_self_intersections(x));
  EXPECT_EQ(classify_mesh(x).kind, MeshKind::not_a_mesh);

  PolygonMesh<T> t = tetrahedron_mesh<T>();
  const std::uint32_t base = static_cast<std::uint32_t>(t.vertices.size());
  const Vec3<T> a = t.vertices[0];
  for (const auto& d : {Vec3<double>{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}) {
    t.vertices.push_back(a + vec_cast<T>(d));
  }
  const std::array<std::uint32_t, 4> quad{0, base, base + 1, base + 2};
  add_face(t, std::span<const std::uint32_t>(quad));
  const MeshClassification c = classify_mesh(t);
  ASSERT_EQ(c.status, Status::ok);
  EXPECT_EQ(c.orientation.components.face_component_count, 2u);
  EXPECT_EQ(brute_face_components(t), 2u);
  EXPECT_EQ(connected_components(make_vet_mesh(t).mesh).vertex_component_count, 1u);
  EXPECT_EQ(c.topology.non_manifold_vertices, (std::vector<std::uint32_t>{0}));
  EXPECT_TRUE(brute_non_manifold_vertex(t, 0));
  EXPECT_NE(c.kind, MeshKind::polyhedron);
}

// Figure 9.13 and two cubes glued along an edge: the edge has four faces (non-manifold), its end
// points are non-manifold vertices; all checked against the brute-force counts.
TYPED_TEST(MeshChecks, NonManifoldEdgesAndVertices) {
  using T = TypeParam;
  PolygonMesh<T> cubes = hexahedron_mesh<T>();
  const PolygonMesh<T> c0 = cubes;
  // The second cube: the first translated by its edge's diagonal offset so that they share
  // the edge x = y = s (vertices 3 and 7 of the first, 0 and 4 of the second).
  const T s = c0.vertices[7].x;
  std::vector<std::uint32_t> remap(8);
  for (std::uint32_t i = 0; i < 8; ++i) {
    const Vec3<T> p = c0.vertices[i] + Vec3<T>{2 * s, 2 * s, 0};
    std::uint32_t found = npos;
    for (std::uint32_t j = 0; j < cubes.vertices.size(); ++j) {
      if (cubes.vertices[j] == p) found = j;
    }
    if (found == npos) {
      found = static_cast<std::uint32_t>(cubes.vertices.size());
      cubes.vertices.push_back(p);
    }
    remap[i] = found;
  }
  for (std::size_t f = 0; f < face_count(c0); ++f) {
    std::vector<std::uint32_t> fv;
    for (const std::uint32_t v : face(c0, f)) fv.push_back(remap[v]);
    add_face(cubes, std::span<const std::uint32_t>(fv));
  }
  for (const int k : {0, -20, 20}) {
    const PolygonMesh<T> m = scaled(cubes, k);
    const MeshClassification c = classify_mesh(m);
    ASSERT_EQ(c.status, Status::ok);
    std::vector<EdgeKey> want_edges;
    for (const auto& [e, n] : faces_per_edge(m)) {
      if (n > 2) want_edges.push_back(e);
    }
    ASSERT_EQ(want_edges.size(), 1u);
    const VetMeshBuild b = make_vet_mesh(m);
    ASSERT_EQ(c.topology.non_manifold_edges.size(), 1u);
    const auto ends = b.mesh.edge_vertices(c.topology.non_manifold_edges[0]);
    EXPECT_EQ(EdgeKey(ends[0], ends[1]), want_edges[0]);
    std::vector<std::uint32_t> want_vertices;
    for (std::uint32_t v = 0; v < m.vertices.size(); ++v) {
      if (brute_non_manifold_vertex(m, v)) want_vertices.push_back(v);
    }
    EXPECT_EQ(c.topology.non_manifold_vertices, want_vertices);
    EXPECT_EQ(want_vertices.size(), 2u);
    EXPECT_FALSE(c.topology.manifold);
    EXPECT_EQ(c.kind, MeshKind::mesh);  // connected through the shared edge, not a polyhedron
    EXPECT_EQ(c.orientation.components.face_component_count, 1u);
    EXPECT_TRUE(c.intersections.face_pairs.empty());
  }
}

// Figure 9.16: a rectangle strip of quads closed into a cylinder band (orientable) or with a
// half twist (Möbius, non-orientable; no flips listed for it).
template <class T>
PolygonMesh<T> band(int n, bool twist) {
  std::vector<Vec3<double>> pts;
  for (int i = 0; i < n; ++i) {
    const double u = 2 * std::numbers::pi * i / n, tw = twist ? u / 2 : 0.0;
    for (const double w : {-0.3, 0.3}) {
      const double r = 1 + w * std::cos(tw);
      pts.push_back({r * std::cos(u), r * std::sin(u), w * std::sin(tw)});
    }
  }
  std::vector<std::vector<std::uint32_t>> faces;
  for (int i = 0; i < n; ++i) {
    const auto a = static_cast<std::uint32_t>(2 * i), b = a + 1;
    std::uint32_t c = static_cast<std::uint32_t>(2 * ((i + 1) % n)), d = c + 1;
    if (twist && i + 1 == n) std::swap(c, d);  // the half twist joins the ends crosswise
    faces.push_back({a, c, d, b});
  }
  // The quads are not planar on the Möbius strip: split them for the geometric checks.
  PolygonMesh<T> m = make<T>(pts, faces);
  const auto tris = fan_triangles(m);
  return from_triangles(std::span<const Vec3<T>>(m.vertices),
                        std::span<const std::array<std::uint32_t, 3>>(tris));
}

TYPED_TEST(MeshChecks, CylinderBandAndMoebiusStrip) {
  using T = TypeParam;
  const MeshClassification cyl = classify_mesh(band<T>(24, false));
  ASSERT_EQ(cyl.status, Status::ok);
  EXPECT_TRUE(cyl.orientation.orientable);
  EXPECT_EQ(cyl.topology.boundary_edges.size(), 48u);
  EXPECT_EQ(cyl.euler_characteristic, 0);
  EXPECT_EQ(cyl.kind, MeshKind::mesh);
  const MeshClassification mob = classify_mesh(band<T>(24, true));
  ASSERT_EQ(mob.status, Status::ok);
  EXPECT_FALSE(mob.orientation.orientable);
  EXPECT_EQ(mob.orientation.non_orientable_components, (std::vector<std::uint32_t>{0}));
  EXPECT_TRUE(mob.orientation.flipped_faces.empty());
  EXPECT_EQ(mob.topology.boundary_edges.size(), 48u);  // one boundary curve twice as long
  EXPECT_EQ(mob.euler_characteristic, 0);
  EXPECT_TRUE(mob.topology.manifold);
  EXPECT_TRUE(mob.intersections.face_pairs.empty());
  EXPECT_EQ(mob.kind, MeshKind::mesh);
}

// Random faces of a solid reversed; make_consistent restores the original orientation (up to
// one global reversal per component, decided by the lowest face id, which is never flipped).
TYPED_TEST(MeshChecks, RandomFlipsAreUndone) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const std::vector<PolygonMesh<T>> solids = {
      icosphere_mesh<T>(T(1), 2), torus_mesh<T>(T(3), T(1), 12, 6), dodecahedron_mesh<T>(),
      cylinder_mesh<T>(T(1), T(2), 8)};
  for (int trial = 0; trial < 40; ++trial) {
    const PolygonMesh<T>& original = solids[static_cast<std::size_t>(trial) % solids.size()];
    PolygonMesh<T> m = original;
    std::vector<bool> flipped(face_count(m), false);
    for (std::size_t f = 0; f < face_count(m); ++f) {
      if (rng.uniform_int(0, 2) == 0) {
        flipped[f] = true;
        std::reverse(m.face_indices.begin() + m.face_offsets[f],
                     m.face_indices.begin() + m.face_offsets[f + 1]);
      }
    }
    const MeshOrientation o = make_consistent(m);
    ASSERT_EQ(o.status, Status::ok);
    ASSERT_TRUE(o.orientable);
    // Face 0 keeps its order; the others end up agreeing with it.
    std::vector<std::uint32_t> expect;
    for (std::uint32_t f = 0; f < face_count(m); ++f) {
      if (flipped[f] != flipped[0]) expect.push_back(f);
    }
    EXPECT_EQ(o.flipped_faces, expect);
    if (flipped[0]) {
      for (std::size_t f = 0; f < face_count(m); ++f) {
        std::reverse(m.face_indices.begin() + m.face_offsets[f],
                     m.face_indices.begin() + m.face_offsets[f + 1]);
      }
    }
    EXPECT_EQ(m.face_indices, original.face_indices);
    // The VetMesh overload gives the same flips and leaves a consistent table.
    PolygonMesh<T> again = original;
    for (std::size_t f = 0; f < face_count(again); ++f) {
      if (flipped[f]) {
        std::reverse(again.face_indices.begin() + again.face_offsets[f],
                     again.face_indices.begin() + again.face_offsets[f + 1]);
      }
    }
    VetMeshBuild b = make_vet_mesh(again);
    EXPECT_EQ(make_consistent(b.mesh).flipped_faces, expect);
    EXPECT_TRUE(orient_consistently(b.mesh).flipped_faces.empty());
  }
}

// Random triangle sets on a small integer grid: shared vertices, shared edges, coplanar folds
// and touching are frequent. The sweep must find exactly the brute-force pairs.
TYPED_TEST(MeshChecks, SelfIntersectionsMatchBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  std::size_t total = 0;
  for (int trial = 0; trial < 40; ++trial) {
    PolygonMesh<T> m;
    const int nv = rng.uniform_int(6, 14);
    for (int i = 0; i < nv; ++i) {
      Vec3<T> p;
      for (int k = 0; k < 3; ++k) p[k] = static_cast<T>(rng.uniform_int(0, 3));
      if (trial % 3 == 0) p.z = 0;  // all coplanar
      m.vertices.push_back(p);
    }
    const int nf = rng.uniform_int(4, 12);
    for (int f = 0; f < nf; ++f) {
      std::array<std::uint32_t, 3> t{};
      do {
        for (auto& v : t) v = static_cast<std::uint32_t>(rng.uniform_int(0, nv - 1));
      } while (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]);
      add_face(m, std::span<const std::uint32_t>(t));
    }
    const auto want = brute_self_intersections(m);
    total += want.size();
    for (const int k : {0, -30, 30}) {
      const MeshSelfIntersections got = self_intersections(scaled(m, k));
      ASSERT_EQ(got.status, Status::ok);
      ASSERT_EQ(got.face_pairs, want) << "trial " << trial << " k " << k;
    }
  }
  EXPECT_GT(total, 60u);
}

// Faces that only touch properly (a folded pair of coplanar triangles on one side, a tent on two
// sides, a vertex-sharing pair crossing through the shared vertex) and the reported cases.
TYPED_TEST(MeshChecks, SharedVertexRules) {
  using T = TypeParam;
  const std::vector<Vec3<double>> p{{0, 0, 0}, {2, 0, 0}, {1, 2, 0},   {1, -2, 0},
                                    {1, 1, 0}, {1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}};
  const auto pairs = [&](std::vector<std::vector<std::uint32_t>> f) {
    const PolygonMesh<T> m = make<T>(p, f);
    const auto got = self_intersections(m).face_pairs;
    EXPECT_EQ(got, brute_self_intersections(m));
    return got.size();
  };
  EXPECT_EQ(pairs({{0, 1, 2}, {1, 0, 3}}), 0u);  // coplanar, opposite sides of the edge
  EXPECT_EQ(pairs({{0, 1, 2}, {1, 0, 4}}), 1u);  // coplanar fold onto the same side
  EXPECT_EQ(pairs({{0, 1, 2}, {1, 0, 5}}), 0u);  // a tent
  EXPECT_EQ(pairs({{0, 1, 2}, {0, 1, 2}}), 1u);  // repeated face
  EXPECT_EQ(pairs({{0, 1, 2}, {0, 6, 7}}), 0u);  // share vertex 0 only, the other on one side
  EXPECT_EQ(pairs({{0, 1, 2}, {0, 4, 5}}), 1u);  // share 0, the other lies on the first
}

TYPED_TEST(MeshChecks, DegenerateInput) {
  using T = TypeParam;
  EXPECT_EQ(classify_mesh(PolygonMesh<T>{}).status, Status::empty_input);
  EXPECT_EQ(self_intersections(PolygonMesh<T>{}).status, Status::empty_input);
  PolygonMesh<T> m = tetrahedron_mesh<T>();
  PolygonMesh<T> rep = m;
  const std::array<std::uint32_t, 3> bad{0, 1, 1};
  add_face(rep, std::span<const std::uint32_t>(bad));
  EXPECT_EQ(classify_mesh(rep).status, Status::degenerate_input);
  PolygonMesh<T> out = m;
  out.face_indices[0] = 17;
  EXPECT_EQ(classify_mesh(out).status, Status::invalid_input);
  EXPECT_EQ(make_consistent(out).status, Status::invalid_input);
  EXPECT_EQ(out.face_indices[0], 17u);  // unchanged
  PolygonMesh<T> nan = m;
  nan.vertices[1].y = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(classify_mesh(nan).status, Status::non_finite_input);
  // A collinear triangle: listed as degenerate, not a mesh.
  PolygonMesh<T> flat =
      make<T>({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 1, 0}}, {{0, 1, 2}, {0, 1, 3}});
  const MeshClassification c = classify_mesh(flat);
  EXPECT_EQ(c.intersections.degenerate_faces, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(c.kind, MeshKind::not_a_mesh);
  // A non-planar quad: not a mesh (figure 9.3's planar faces), listed.
  const PolygonMesh<T> warped =
      make<T>({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.25}}, {{0, 1, 2, 3}});
  EXPECT_EQ(classify_mesh(warped).non_planar_faces, (std::vector<std::uint32_t>{0}));
}

// 10^5 faces: the sweep keeps the self-intersection test fast on a surface mesh.
TYPED_TEST(MeshChecks, LargeSphereHasNoSelfIntersection) {
  using T = TypeParam;
  const PolygonMesh<T> m = icosphere_mesh<T>(T(1), 6);  // 81920 triangles
  const MeshSelfIntersections si = self_intersections(m);
  ASSERT_EQ(si.status, Status::ok);
  EXPECT_TRUE(si.face_pairs.empty());
  EXPECT_TRUE(si.degenerate_faces.empty());
}

}  // namespace
