// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 9.3: polygons and meshes, figures 9.5-9.17. Polygons are triangulated by
// fan_triangles and triangulate_polygon3; meshes are built as VetMesh tables (make_vet_mesh,
// insert_edge) and judged by check_topology, connected_components, orient_consistently,
// self_intersections and classify_mesh; solids come from the generators of mesh/platonic.hpp.
// Every figure highlights what the checks report and fails when a check gives another answer
// than the one the book's caption states. Solids are drawn with a small orthographic projection
// (painter's order, back faces dashed) so that faces can be filled.
#include "gallery.hpp"

#include <locus/mesh/mesh_checks.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/mesh/polygon_mesh.hpp>
#include <locus/mesh/polygon_triangulation3.hpp>
#include <locus/mesh/vet_mesh.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;
using Mesh = PolygonMesh<double>;

// Orthographic view along `dir` (towards the scene) with z up.
struct View {
  Vec3d dir, right, up;
  explicit View(const Vec3d& d) : dir(normalize(d)) {
    right = normalize(cross(dir, Vec3d{0, 0, 1}));
    up = cross(right, dir);
  }
  Vec2d operator()(const Vec3d& p) const { return {dot(p, right), dot(p, up)}; }
};

const View default_view(Vec3d{-0.9, 1.7, -0.8});

std::vector<Vec2d> face_points(const Mesh& m, std::span<const std::uint32_t> f, const View& v,
                               const Vec2d& at) {
  std::vector<Vec2d> out;
  for (const std::uint32_t i : f) out.push_back(v(m.vertices[i]) + at);
  return out;
}

// Faces in painter's order: back faces (normal away from the viewer) dashed, then front faces
// filled from far to near. face_colour(f) picks the colour of face f.
template <class Colour>
void draw_solid(SvgWriter& w, const Mesh& m, const View& v, const Vec2d& at, Colour face_colour) {
  struct Item {
    double depth;
    std::size_t f;
    bool front;
  };
  std::vector<Item> items;
  for (std::size_t f = 0; f < face_count(m); ++f) {
    const auto fv = face(m, f);
    Vec3d n{}, centre{};
    for (std::size_t i = 0; i < fv.size(); ++i) {
      const Vec3d& a = m.vertices[fv[i]];
      const Vec3d& b = m.vertices[fv[(i + 1) % fv.size()]];
      n = n + cross(a, b);
      centre = centre + a / static_cast<double>(fv.size());
    }
    items.push_back({dot(centre, v.dir), f, dot(n, v.dir) < 0});
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    return a.front != b.front ? !a.front : a.depth > b.depth;
  });
  for (const Item& it : items) {
    const auto pts = face_points(m, face(m, it.f), v, at);
    if (it.front) {
      w.polygon(pts, filled(face_colour(it.f), 0.28, 1.4));
    } else {
      w.polyline(pts, dashed(c::light, 0.9), true);
    }
  }
}

void draw_solid(SvgWriter& w, const Mesh& m, const View& v, const Vec2d& at, const char* col) {
  draw_solid(w, m, v, at, [&](std::size_t) { return col; });
}

// Edges of a VetMesh (flat drawing: x, y of the positions) with a style per edge.
template <class Style>
void draw_edges(SvgWriter& w, const VetMesh& t, const std::vector<Vec3d>& p, const View& v,
                Style style) {
  for (std::uint32_t e = 0; e < t.edge_capacity(); ++e) {
    if (!t.has_edge(e)) continue;
    const auto ends = t.edge_vertices(e);
    w.segment(v(p[ends[0]]), v(p[ends[1]]), style(e));
  }
}

// 9.5: a convex polygon and its fan from the first vertex.
bool fig_9_5(SvgWriter& w) {
  Mesh m;
  const int n = 7;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n + 0.3;
    m.vertices.push_back({3 * std::cos(a) * (1 + 0.15 * (i % 2)), 2.2 * std::sin(a), 0});
  }
  std::vector<std::uint32_t> idx;
  for (std::uint32_t i = 0; i < n; ++i) idx.push_back(i);
  add_face(m, std::span<const std::uint32_t>(idx));
  const auto tris = fan_triangles(m);
  if (tris.size() != n - 2) return false;
  for (const auto& t : tris) {
    w.polygon(std::vector<Vec2d>{{m.vertices[t[0]].x, m.vertices[t[0]].y},
                                 {m.vertices[t[1]].x, m.vertices[t[1]].y},
                                 {m.vertices[t[2]].x, m.vertices[t[2]].y}},
              filled(c::blue, 0.12, 1.0));
  }
  std::vector<Vec2d> ring;
  for (const Vec3d& p : m.vertices) ring.push_back({p.x, p.y});
  w.polyline(ring, pen(c::black, 2), true);
  for (std::size_t i = 0; i < ring.size(); ++i) point(w, ring[i], "V" + std::to_string(i));
  return true;
}

// 9.6: a non-convex polygon in a tilted plane, triangulated by projection on the dominant
// coordinate plane (Newell normal) and ear clipping; drawn in the view of the plane.
bool fig_9_6(SvgWriter& w) {
  const std::vector<Vec2d> flat{{0, 0},   {4, 0.6}, {6.5, 0}, {7, 3},     {5, 2.2},
                                {4, 4.6}, {2.6, 2}, {1, 4.2}, {-0.6, 2.4}};
  std::vector<Vec3d> pts;
  for (const Vec2d& p : flat) pts.push_back({p.x, p.y * 0.8, 0.6 * p.y + 0.1 * p.x});
  const PolygonTriangulation3<double> r = triangulate_polygon3(std::span<const Vec3d>(pts));
  if (r.status != Status::ok || r.triangles.size() != pts.size() - 2) return false;
  const View v(-r.normal);  // look at the plane face on
  for (const auto& t : r.triangles) {
    w.polygon(std::vector<Vec2d>{v(pts[t[0]]), v(pts[t[1]]), v(pts[t[2]])},
              filled(c::green, 0.15, 1.0));
  }
  std::vector<Vec2d> ring;
  for (const Vec3d& p : pts) ring.push_back(v(p));
  w.polyline(ring, pen(c::black, 2), true);
  for (std::size_t i = 0; i < ring.size(); ++i) point(w, ring[i], "V" + std::to_string(i));
  return true;
}

// A small triangle mesh: a grid of 4 x 3 cells, each split in two, with bumps.
Mesh grid_mesh() {
  Mesh m;
  const int nx = 4, ny = 3;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      m.vertices.push_back({i + 0.25 * (j % 2), j * 0.9, 0.3 * std::sin(i + 2.0 * j)});
    }
  }
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const std::array<std::uint32_t, 3> a{at(i, j), at(i + 1, j), at(i + 1, j + 1)};
      const std::array<std::uint32_t, 3> b{at(i, j), at(i + 1, j + 1), at(i, j + 1)};
      add_face(m, std::span<const std::uint32_t>(a));
      add_face(m, std::span<const std::uint32_t>(b));
    }
  }
  return m;
}

const View flat_view(Vec3d{0.15, 0.9, -0.7});

// 9.7: a triangle mesh; boundary edges (one triangle) thick, interior edges thin.
bool fig_9_7(SvgWriter& w) {
  const Mesh m = grid_mesh();
  const VetMeshBuild b = make_vet_mesh(m);
  const MeshClassification cl = classify_mesh(m);
  if (b.status != Status::ok || cl.kind != MeshKind::mesh || !cl.topology.manifold) return false;
  for (std::size_t f = 0; f < face_count(m); ++f) {
    w.polygon(face_points(m, face(m, f), flat_view, {0, 0}), filled(c::blue, 0.1, 0.5));
  }
  draw_edges(w, b.mesh, m.vertices, flat_view, [&](std::uint32_t e) {
    return b.mesh.edge_face_count(e) == 1 ? pen(c::black, 2.2) : pen(c::blue, 1.0);
  });
  for (const Vec3d& p : m.vertices) w.point(flat_view(p), dot(c::black, 2.5));
  return true;
}

// 9.8 and 9.9: the mesh plus an isolated vertex, or plus an isolated edge.
bool fig_9_8(SvgWriter& w) {
  Mesh m = grid_mesh();
  m.vertices.push_back({2.3, 3.7, 0.4});
  const MeshClassification cl = classify_mesh(m);
  if (cl.kind != MeshKind::not_a_mesh || cl.topology.isolated_vertices.size() != 1) return false;
  const VetMeshBuild b = make_vet_mesh(m);
  draw_edges(w, b.mesh, m.vertices, flat_view, [](std::uint32_t) { return pen(c::blue, 1.0); });
  const Vec3d& iso = m.vertices[cl.topology.isolated_vertices[0]];
  w.point(flat_view(iso), dot(c::red, 5));
  label(w, flat_view(iso), "isolated vertex", c::red, 8, 4);
  return true;
}

bool fig_9_9(SvgWriter& w) {
  Mesh m = grid_mesh();
  m.vertices.push_back({2.9, 3.9, 0.4});
  VetMeshBuild b = make_vet_mesh(m);
  b.mesh.insert_edge(static_cast<std::uint32_t>(m.vertices.size() - 1), 17);
  const MeshClassification cl = classify_mesh(b.mesh, std::span<const Vec3d>(m.vertices));
  if (cl.kind != MeshKind::not_a_mesh || cl.topology.isolated_edges.size() != 1) return false;
  const std::uint32_t bad = cl.topology.isolated_edges[0];
  draw_edges(w, b.mesh, m.vertices, flat_view,
             [&](std::uint32_t e) { return e == bad ? pen(c::red, 2.6) : pen(c::blue, 1.0); });
  const auto ends = b.mesh.edge_vertices(bad);
  label(w, flat_view((m.vertices[ends[0]] + m.vertices[ends[1]]) * 0.5), "isolated edge", c::red, 8,
        4);
  return true;
}

// 9.10: two triangles that interpenetrate.
bool fig_9_10(SvgWriter& w) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {4, 0, 0}, {1.5, 3, 0}, {1, 1, -1.5}, {3, 1.5, 1.5}, {0.5, 2.8, 1.2}};
  const std::array<std::uint32_t, 3> a{0, 1, 2}, b{3, 4, 5};
  add_face(m, std::span<const std::uint32_t>(a));
  add_face(m, std::span<const std::uint32_t>(b));
  const MeshSelfIntersections si = self_intersections(m);
  if (si.status != Status::ok || si.face_pairs.size() != 1) return false;
  const View v(Vec3d{0.4, 1.0, -0.35});
  draw_solid(w, m, v, {0, 0}, [](std::size_t f) { return f == 0 ? c::blue : c::red; });
  for (std::size_t f = 0; f < 2; ++f) {  // both outlined, whichever side they show
    w.polyline(face_points(m, face(m, f), v, {0, 0}), pen(c::black, 1.2), true);
  }
  label(w, v(m.vertices[4]),
        "faces " + std::to_string(si.face_pairs[0][0]) + " and " +
            std::to_string(si.face_pairs[0][1]) + " interpenetrate",
        c::red, 6, 4);
  return true;
}

// 9.11: a tetrahedron with a depression in one face: a polyhedron, not a polytope.
Mesh depression() {
  Mesh m;
  m.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {1.6, 1.6, 1.6}};
  const std::vector<std::array<std::uint32_t, 3>> f = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2},
                                                       {1, 2, 4}, {2, 3, 4}, {3, 1, 4}};
  for (const auto& t : f) add_face(m, std::span<const std::uint32_t>(t));
  return m;
}

bool fig_9_11(SvgWriter& w) {
  Mesh m = depression();
  m.vertices[4] = {1.0, 1.0, 1.0};  // pushed into the solid
  const MeshClassification cl = classify_mesh(m);
  if (cl.kind != MeshKind::polyhedron || cl.convex || cl.euler_characteristic != 2) return false;
  draw_solid(w, m, View(Vec3d{-1, -0.7, -0.5}), {0, 0},
             [](std::size_t f) { return f >= 3 ? c::orange : c::blue; });
  return true;
}

// 9.12: a tetrahedron and a square sharing one vertex: two face components.
bool fig_9_12(SvgWriter& w) {
  Mesh m = tetrahedron_mesh<double>();
  const Vec3d a = m.vertices[0];
  const std::uint32_t base = static_cast<std::uint32_t>(m.vertices.size());
  for (const Vec3d& d : {Vec3d{1.2, 0, 0}, Vec3d{1.2, 1.2, 0}, Vec3d{0, 1.2, 0}}) {
    m.vertices.push_back(a + d);
  }
  const std::array<std::uint32_t, 4> q{0, base, base + 1, base + 2};
  add_face(m, std::span<const std::uint32_t>(q));
  const MeshClassification cl = classify_mesh(m);
  if (cl.status != Status::ok || cl.orientation.components.face_component_count != 2 ||
      cl.kind == MeshKind::polyhedron) {
    return false;
  }
  const auto& comp = cl.orientation.components.face_component;
  draw_solid(w, m, View(Vec3d{-1, -1.4, -0.6}), {0, 0},
             [&](std::size_t f) { return comp[f] == 0 ? c::blue : c::green; });
  w.point(View(Vec3d{-1, -1.4, -0.6})(a), dot(c::red, 4.5));
  return true;
}

// 9.13: an edge shared by three faces.
bool fig_9_13(SvgWriter& w) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {0, 0, 3}, {2.5, 0, 1.5}, {-1.2, 2.2, 1.5}, {-1.3, -2.1, 1.5}};
  for (const std::uint32_t x : {2u, 3u, 4u}) {
    const std::array<std::uint32_t, 3> t{0, 1, x};
    add_face(m, std::span<const std::uint32_t>(t));
  }
  const MeshClassification cl = classify_mesh(m);
  const VetMeshBuild b = make_vet_mesh(m);
  if (cl.topology.non_manifold_edges.size() != 1 || cl.kind != MeshKind::mesh) return false;
  const std::uint32_t bad = cl.topology.non_manifold_edges[0];
  if (b.mesh.edge_face_count(bad) != 3) return false;
  const View v(Vec3d{1.0, 0.35, -0.35});
  for (std::size_t f = 0; f < 3; ++f) {
    w.polygon(face_points(m, face(m, f), v, {0, 0}),
              filled(f == 0 ? c::blue : (f == 1 ? c::green : c::orange), 0.25, 1.2));
  }
  const auto ends = b.mesh.edge_vertices(bad);
  w.segment(v(m.vertices[ends[0]]), v(m.vertices[ends[1]]), pen(c::red, 3));
  label(w, v(m.vertices[ends[1]]), "3 faces", c::red, 6, 4);
  return true;
}

// 9.14: the regular dodecahedron, a polytope (pentagons flat up to rounding: tolerance).
bool fig_9_14(SvgWriter& w) {
  const Mesh m = dodecahedron_mesh<double>();
  const MeshClassification cl = classify_mesh(m, 1e-12);
  if (cl.kind != MeshKind::polytope || cl.euler_characteristic != 2) return false;
  draw_solid(w, m, default_view, {0, 0}, c::blue);
  return true;
}

// 9.15: two triangles sharing an edge, in the four orientation combinations; consistent pairs
// traverse the shared edge in opposite directions (orient_consistently flips none).
bool fig_9_15(SvgWriter& w) {
  const std::vector<Vec3d> p{{0, 0, 0}, {2, 0, 0}, {1, 1.6, 0}, {1, -1.6, 0}};
  int k = 0;
  for (const bool flip0 : {false, true}) {
    for (const bool flip1 : {false, true}) {
      Mesh m;
      m.vertices = p;
      std::array<std::uint32_t, 3> a{0, 1, 2}, b{1, 0, 3};
      if (flip0) std::swap(a[1], a[2]);
      if (flip1) std::swap(b[1], b[2]);
      add_face(m, std::span<const std::uint32_t>(a));
      add_face(m, std::span<const std::uint32_t>(b));
      const MeshOrientation o = orient_consistently(make_vet_mesh(m).mesh);
      const bool consistent = o.flipped_faces.empty();
      if (!o.orientable || consistent != (flip0 == flip1)) return false;
      const Vec2d at{3.2 * k, 0};
      for (std::size_t f = 0; f < 2; ++f) {
        const auto fv = face(m, f);
        Vec2d centre{0, 0};
        for (const std::uint32_t i : fv) centre = centre + Vec2d{p[i].x, p[i].y} / 3.0;
        for (std::size_t i = 0; i < 3; ++i) {
          const Vec3d& u = p[fv[i]];
          const Vec3d& v = p[fv[(i + 1) % 3]];
          // Arrows pulled towards the face centre show its traversal.
          const Vec2d u2 = Vec2d{u.x, u.y} * 0.8 + centre * 0.2 + at;
          const Vec2d v2 = Vec2d{v.x, v.y} * 0.8 + centre * 0.2 + at;
          w.arrow(u2, v2, pen(f == 0 ? c::blue : c::green, 1.4));
        }
      }
      w.text(Vec2d{1, -2.2} + at, consistent ? "consistent" : "inconsistent",
             text_style(consistent ? c::black : c::red, 0, 0, SvgAnchor::middle, 13));
      ++k;
    }
  }
  return true;
}

// A band of quads (split in triangles): closed into a cylinder or, with a half twist, a Möbius
// strip.
Mesh band(bool twist) {
  const int n = 36;
  Mesh quads;
  for (int i = 0; i < n; ++i) {
    const double u = 2 * std::numbers::pi * i / n, tw = twist ? u / 2 : 0.0;
    for (const double s : {-0.45, 0.45}) {
      // The cylinder stands upright; the Möbius strip turns from flat to upright and back.
      const double r = twist ? 1.6 + s * std::cos(tw) : 1.6;
      quads.vertices.push_back({r * std::cos(u), r * std::sin(u), twist ? s * std::sin(tw) : s});
    }
  }
  for (int i = 0; i < n; ++i) {
    const auto a = static_cast<std::uint32_t>(2 * i), b = a + 1;
    std::uint32_t c0 = static_cast<std::uint32_t>(2 * ((i + 1) % n)), d = c0 + 1;
    if (twist && i + 1 == n) std::swap(c0, d);
    const std::array<std::uint32_t, 4> q{a, c0, d, b};
    add_face(quads, std::span<const std::uint32_t>(q));
  }
  const auto tris = fan_triangles(quads);
  return from_triangles(std::span<const Vec3d>(quads.vertices),
                        std::span<const std::array<std::uint32_t, 3>>(tris));
}

// 9.16: (a) the cylindrical strip, orientable; (b) the Möbius strip, non-orientable.
bool fig_9_16(SvgWriter& w) {
  const View v(Vec3d{0.3, 1.0, -0.65});
  for (const bool twist : {false, true}) {
    const Mesh m = band(twist);
    const MeshClassification cl = classify_mesh(m);
    if (cl.status != Status::ok || cl.orientation.orientable == twist ||
        !cl.intersections.face_pairs.empty()) {
      return false;
    }
    const Vec2d at{twist ? 4.6 : 0.0, 0};
    draw_solid(w, m, v, at, twist ? c::red : c::blue);
    w.text(Vec2d{0, -2.3} + at, twist ? "(b) Möbius: non-orientable" : "(a) cylinder: orientable",
           text_style(c::black, 0, 0, SvgAnchor::middle, 13));
  }
  return true;
}

// 9.17: the five Platonic solids.
bool fig_9_17(SvgWriter& w) {
  const std::vector<Mesh> solids = {tetrahedron_mesh<double>(), hexahedron_mesh<double>(),
                                    octahedron_mesh<double>(), dodecahedron_mesh<double>(),
                                    icosahedron_mesh<double>()};
  const char* names[] = {"tetrahedron", "hexahedron", "octahedron", "dodecahedron", "icosahedron"};
  for (std::size_t i = 0; i < solids.size(); ++i) {
    const MeshClassification cl = classify_mesh(solids[i], 1e-12);
    if (cl.kind != MeshKind::polytope || cl.euler_characteristic != 2) return false;
    const Vec2d at{2.5 * static_cast<double>(i), 0};
    // The tetrahedron turns one face to the common view; it gets its own.
    draw_solid(w, solids[i], i == 0 ? View(Vec3d{-1.0, 0.25, -0.45}) : default_view, at, c::blue);
    w.text(Vec2d{0, -1.35} + at, names[i], text_style(c::black, 0, 0, SvgAnchor::middle, 12));
  }
  return true;
}

}  // namespace

std::vector<Figure> chapter9_mesh_figures() {
  return {
      {"9.5", "PolygonMesh fan_triangles", fig_9_5},
      {"9.6", "triangulate_polygon3 (Newell normal, dominant-plane projection, ear clipping)",
       fig_9_6},
      {"9.7", "make_vet_mesh, VetMesh edge_face_count (boundary edges), classify_mesh", fig_9_7},
      {"9.8", "classify_mesh: topology.isolated_vertices", fig_9_8},
      {"9.9", "VetMesh insert_edge, classify_mesh: topology.isolated_edges", fig_9_9},
      {"9.10", "self_intersections (exact triangle-triangle test)", fig_9_10},
      {"9.11", "classify_mesh: polyhedron, not convex", fig_9_11},
      {"9.12", "classify_mesh: connected_components (edge connectivity)", fig_9_12},
      {"9.13", "check_topology: non_manifold_edges, edge_face_count", fig_9_13},
      {"9.14", "dodecahedron_mesh, classify_mesh: polytope", fig_9_14},
      {"9.15", "orient_consistently (flipped_faces)", fig_9_15},
      {"9.16", "orient_consistently: orientable band, non-orientable Möbius strip", fig_9_16},
      {"9.17", "tetrahedron/hexahedron/octahedron/dodecahedron/icosahedron_mesh, classify_mesh",
       fig_9_17},
  };
}

}  // namespace locus_gallery
