// SPDX-License-Identifier: BSL-1.0
// Mesh checks (mesh/mesh_checks.hpp). Derivations (the shared-vertex rules of the
// self-intersection test, local convexity) are in docs/notes/mesh.md.

#include <locus/core/predicates.hpp>
#include <locus/intersection/triangle_triangle.hpp>
#include <locus/mesh/mesh_checks.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace locus {

namespace {

constexpr std::uint32_t npos = VetMesh::npos;

// Breadth-first labelling over a neighbour enumerator.
template <class Alive, class Neighbours>
std::uint32_t label_components(std::uint32_t n, std::vector<std::uint32_t>& label, Alive alive,
                               Neighbours neighbours) {
  label.assign(n, npos);
  std::uint32_t count = 0;
  std::vector<std::uint32_t> queue;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (!alive(s) || label[s] != npos) continue;
    label[s] = count;
    queue.assign(1, s);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      neighbours(queue[q], [&](std::uint32_t t) {
        if (label[t] == npos) {
          label[t] = count;
          queue.push_back(t);
        }
      });
    }
    ++count;
  }
  return count;
}

template <Real T>
bool finite_positions(std::span<const Vec3<T>> p) {
  for (const Vec3<T>& v : p) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
  }
  return true;
}

// Indices (i, j, k) into a face cycle of three non-collinear vertices with i < j < k, or
// nothing when all are collinear (exact).
template <Real T>
bool non_collinear_triple(std::span<const std::uint32_t> c, std::span<const Vec3<T>> p,
                          std::array<std::size_t, 3>& out) {
  const Vec3<T>& a = p[c[0]];
  std::size_t j = 1;
  while (j < c.size() && p[c[j]] == a) ++j;
  for (std::size_t k = j + 1; k < c.size(); ++k) {
    if (detail::tri3::projection_axis(a, p[c[j]], p[c[k]]) >= 0) {
      out = {0, j, k};
      return true;
    }
  }
  return false;
}

struct Tri {
  std::uint32_t face;
  std::array<std::uint32_t, 3> v;
};

template <Real T>
bool pair_interpenetrates(const Tri& s, const Tri& t, std::span<const Vec3<T>> p) {
  int shared = 0;
  std::array<int, 3> in_t{-1, -1, -1};  // position in t of each vertex of s
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (s.v[static_cast<std::size_t>(i)] == t.v[static_cast<std::size_t>(j)]) {
        in_t[static_cast<std::size_t>(i)] = j;
        ++shared;
      }
    }
  }
  const auto P = [&](std::uint32_t id) -> const Vec3<T>& { return p[id]; };
  if (shared == 0) {
    return intersects(Triangle3<T>{P(s.v[0]), P(s.v[1]), P(s.v[2])},
                      Triangle3<T>{P(t.v[0]), P(t.v[1]), P(t.v[2])});
  }
  if (shared == 3) return true;
  if (shared == 1) {
    int i = 0;
    while (in_t[static_cast<std::size_t>(i)] < 0) ++i;
    const int j = in_t[static_cast<std::size_t>(i)];
    const auto sv = [&](int k) { return P(s.v[static_cast<std::size_t>((i + k) % 3)]); };
    const auto tv = [&](int k) { return P(t.v[static_cast<std::size_t>((j + k) % 3)]); };
    return detail::tri3::segment_triangle(sv(1), sv(2), tv(0), tv(1), tv(2)) ||
           detail::tri3::segment_triangle(tv(1), tv(2), sv(0), sv(1), sv(2));
  }
  // Two shared vertices u, v; a and b the others.
  int ia = 0;
  while (in_t[static_cast<std::size_t>(ia)] >= 0) ++ia;
  int u = -1, w = -1;
  for (int i = 0; i < 3; ++i) {
    if (i == ia) continue;
    (u < 0 ? u : w) = i;
  }
  const Vec3<T>& pu = P(s.v[static_cast<std::size_t>(u)]);
  const Vec3<T>& pw = P(s.v[static_cast<std::size_t>(w)]);
  const Vec3<T>& pa = P(s.v[static_cast<std::size_t>(ia)]);
  int jb = 0;
  while (t.v[static_cast<std::size_t>(jb)] == s.v[static_cast<std::size_t>(u)] ||
         t.v[static_cast<std::size_t>(jb)] == s.v[static_cast<std::size_t>(w)]) {
    ++jb;
  }
  const Vec3<T>& pb = P(t.v[static_cast<std::size_t>(jb)]);
  if (orient3d(pu, pw, pa, pb) != Sign::zero) return false;
  const int axis = detail::tri3::projection_axis(pu, pw, pa);
  using detail::tri3::drop;
  return orient2d(drop(pu, axis), drop(pw, axis), drop(pa, axis)) ==
         orient2d(drop(pu, axis), drop(pw, axis), drop(pb, axis));
}

// The side of plane abc that q is on: exact orient3d when limit == 0, else zero within distance
// `limit` of the plane (distance rounded in double).
template <Real T>
Sign plane_side(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& q,
                double limit) {
  if (limit == 0) return orient3d(a, b, c, q);
  const Vec3<double> ad = vec_cast<double>(a);
  const Vec3<double> n = cross(vec_cast<double>(b) - ad, vec_cast<double>(c) - ad);
  const double d = dot(n, vec_cast<double>(q) - ad) / length(n);
  return std::abs(d) <= limit ? Sign::zero : (d > 0 ? Sign::positive : Sign::negative);
}

template <Real T>
bool face_planar(std::span<const std::uint32_t> c, std::span<const Vec3<T>> p, double limit) {
  if (c.size() == 3) return true;
  std::array<std::size_t, 3> t{};
  if (!non_collinear_triple(c, p, t)) return true;  // collinear: degenerate, not non-planar
  for (const std::uint32_t v : c) {
    if (plane_side(p[c[t[0]]], p[c[t[1]]], p[c[t[2]]], p[v], limit) != Sign::zero) return false;
  }
  return true;
}

// A planar face is convex when, in a coordinate plane where it projects injectively, every
// corner turns the same way or goes straight (exact orient2d) and it winds once.
template <Real T>
bool face_convex(std::span<const std::uint32_t> c, std::span<const Vec3<T>> p, int axis) {
  using detail::tri3::drop;
  const std::size_t k = c.size();
  int sign = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const int s = to_int(orient2d(drop(p[c[i]], axis), drop(p[c[(i + 1) % k]], axis),
                                  drop(p[c[(i + 2) % k]], axis)));
    if (s != 0 && sign != 0 && s != sign) return false;
    if (s != 0) sign = s;
  }
  // Winding once: the angular order around vertex 0 increases (fan triangles share its sign).
  for (std::size_t i = 1; i + 1 < k; ++i) {
    const int s =
        to_int(orient2d(drop(p[c[0]], axis), drop(p[c[i]], axis), drop(p[c[i + 1]], axis)));
    if (s != 0 && s != sign) return false;
  }
  return sign != 0;
}

}  // namespace

MeshTopology check_topology(const VetMesh& m) {
  MeshTopology r;
  r.status = m.vertex_count() == 0 ? Status::empty_input : Status::ok;
  for (std::uint32_t v = 0; v < m.vertex_capacity(); ++v) {
    if (!m.has_vertex(v)) continue;
    if (m.vertex_edge_count(v) == 0) {
      r.isolated_vertices.push_back(v);
      continue;
    }
    if (m.vertex_fans(v).size() > 1) r.non_manifold_vertices.push_back(v);
  }
  for (std::uint32_t e = 0; e < m.edge_capacity(); ++e) {
    if (!m.has_edge(e)) continue;
    const std::uint32_t n = m.edge_face_count(e);
    if (n == 0) r.isolated_edges.push_back(e);
    if (n == 1) r.boundary_edges.push_back(e);
    if (n > 2) r.non_manifold_edges.push_back(e);
  }
  r.closed = m.face_count() > 0 && r.boundary_edges.empty() && r.isolated_edges.empty();
  r.manifold = r.non_manifold_edges.empty() && r.non_manifold_vertices.empty();
  return r;
}

MeshComponents connected_components(const VetMesh& m) {
  MeshComponents r;
  r.status = m.vertex_count() == 0 ? Status::empty_input : Status::ok;
  r.face_component_count = label_components(
      m.face_capacity(), r.face_component, [&](std::uint32_t f) { return m.has_face(f); },
      [&](std::uint32_t f, auto&& visit) {
        for (const std::uint32_t e : m.face_edges(f)) m.for_each_edge_face(e, visit);
      });
  r.vertex_component_count = label_components(
      m.vertex_capacity(), r.vertex_component, [&](std::uint32_t v) { return m.has_vertex(v); },
      [&](std::uint32_t v, auto&& visit) {
        m.for_each_vertex_edge(v, [&](std::uint32_t e) {
          const auto ends = m.edge_vertices(e);
          visit(ends[0] == v ? ends[1] : ends[0]);
        });
      });
  return r;
}

MeshOrientation orient_consistently(const VetMesh& m) {
  MeshOrientation r;
  r.components = connected_components(m);
  r.status = r.components.status;
  // flip[f]: whether f must be reversed relative to its component's lowest face. Breadth-first
  // from the lowest face id of each component (face ids increase, so the first one met).
  std::vector<std::int8_t> flip(m.face_capacity(), -1);
  std::vector<char> bad(r.components.face_component_count, 0);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t s = 0; s < m.face_capacity(); ++s) {
    if (!m.has_face(s) || flip[s] >= 0) continue;
    flip[s] = 0;
    queue.assign(1, s);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const std::uint32_t f = queue[q];
      for (const std::uint32_t e : m.face_edges(f)) {
        if (m.edge_face_count(e) != 2) continue;
        std::uint32_t g = f;
        m.for_each_edge_face(e, [&](std::uint32_t h) {
          if (h != f) g = h;
        });
        // Consistent neighbours traverse the shared edge in opposite directions.
        const bool same = m.face_uses_edge_forward(f, e) == m.face_uses_edge_forward(g, e);
        const std::int8_t want = static_cast<std::int8_t>(flip[f] ^ (same ? 1 : 0));
        if (flip[g] < 0) {
          flip[g] = want;
          queue.push_back(g);
        } else if (flip[g] != want) {
          bad[r.components.face_component[f]] = 1;
        }
      }
    }
  }
  for (std::uint32_t c = 0; c < bad.size(); ++c) {
    if (bad[c]) r.non_orientable_components.push_back(c);
  }
  for (std::uint32_t f = 0; f < m.face_capacity(); ++f) {
    if (m.has_face(f) && flip[f] == 1 && !bad[r.components.face_component[f]]) {
      r.flipped_faces.push_back(f);
    }
  }
  r.orientable = r.non_orientable_components.empty();
  return r;
}

MeshOrientation make_consistent(VetMesh& m) {
  MeshOrientation r = orient_consistently(m);
  for (const std::uint32_t f : r.flipped_faces) m.flip_face(f);
  return r;
}

template <Real T>
MeshOrientation make_consistent(PolygonMesh<T>& mesh) {
  const VetMeshBuild b = make_vet_mesh(mesh);
  if (b.status != Status::ok && b.status != Status::empty_input) {
    MeshOrientation r;
    r.status = b.status;
    return r;
  }
  MeshOrientation r = orient_consistently(b.mesh);
  for (const std::uint32_t f : r.flipped_faces) {
    // Face ids equal input face indices (no face was skipped).
    std::reverse(mesh.face_indices.begin() + mesh.face_offsets[f],
                 mesh.face_indices.begin() + mesh.face_offsets[f + 1]);
  }
  return r;
}

template <Real T>
MeshSelfIntersections self_intersections(const VetMesh& m, std::span<const Vec3<T>> p) {
  MeshSelfIntersections r;
  LOCUS_ASSERT(p.size() >= m.vertex_capacity(), "too few positions");
  if (m.vertex_count() == 0) return r;
  if (!finite_positions(p)) {
    r.status = Status::non_finite_input;
    return r;
  }
  r.status = Status::ok;
  std::vector<Tri> tris;
  for (std::uint32_t f = 0; f < m.face_capacity(); ++f) {
    if (!m.has_face(f)) continue;
    const auto c = m.face_vertices(f);
    std::array<std::size_t, 3> t{};
    if (!non_collinear_triple(c, p, t)) {
      r.degenerate_faces.push_back(f);
      continue;
    }
    for (std::size_t i = 1; i + 1 < c.size(); ++i) {
      if (detail::tri3::projection_axis(p[c[0]], p[c[i]], p[c[i + 1]]) < 0) continue;
      tris.push_back({f, {c[0], c[i], c[i + 1]}});
    }
  }
  // Broad phase: boxes (exact: min and max of coordinates) sorted along the longest axis of the
  // whole box, swept; the other two axes filter.
  struct Box {
    Vec3<T> lo, hi;
  };
  std::vector<Box> box(tris.size());
  Box all{p[tris.empty() ? 0 : tris[0].v[0]], p[tris.empty() ? 0 : tris[0].v[0]]};
  for (std::size_t i = 0; i < tris.size(); ++i) {
    Box b{p[tris[i].v[0]], p[tris[i].v[0]]};
    for (int k = 1; k < 3; ++k) {
      const Vec3<T>& q = p[tris[i].v[static_cast<std::size_t>(k)]];
      for (int a = 0; a < 3; ++a) {
        b.lo[a] = std::min(b.lo[a], q[a]);
        b.hi[a] = std::max(b.hi[a], q[a]);
      }
    }
    for (int a = 0; a < 3; ++a) {
      all.lo[a] = std::min(all.lo[a], b.lo[a]);
      all.hi[a] = std::max(all.hi[a], b.hi[a]);
    }
    box[i] = b;
  }
  int axis = 0;
  for (int a = 1; a < 3; ++a) {
    if (all.hi[a] - all.lo[a] > all.hi[axis] - all.lo[axis]) axis = a;
  }
  std::vector<std::uint32_t> order(tris.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return box[a].lo[axis] < box[b].lo[axis] || (box[a].lo[axis] == box[b].lo[axis] && a < b);
  });
  for (std::size_t ii = 0; ii < order.size(); ++ii) {
    const std::uint32_t i = order[ii];
    for (std::size_t jj = ii + 1; jj < order.size(); ++jj) {
      const std::uint32_t j = order[jj];
      if (box[j].lo[axis] > box[i].hi[axis]) break;
      if (tris[i].face == tris[j].face) continue;
      bool overlap = true;
      for (int a = 0; a < 3; ++a) {
        if (box[j].lo[a] > box[i].hi[a] || box[i].lo[a] > box[j].hi[a]) overlap = false;
      }
      if (!overlap || !pair_interpenetrates(tris[i], tris[j], p)) continue;
      const std::uint32_t f = std::min(tris[i].face, tris[j].face);
      const std::uint32_t g = std::max(tris[i].face, tris[j].face);
      r.face_pairs.push_back({f, g});
    }
  }
  std::sort(r.face_pairs.begin(), r.face_pairs.end());
  r.face_pairs.erase(std::unique(r.face_pairs.begin(), r.face_pairs.end()), r.face_pairs.end());
  return r;
}

template <Real T>
MeshSelfIntersections self_intersections(const PolygonMesh<T>& mesh) {
  const VetMeshBuild b = make_vet_mesh(mesh);
  if (b.status != Status::ok) {
    MeshSelfIntersections r;
    r.status = b.status;
    return r;
  }
  return self_intersections(b.mesh, std::span<const Vec3<T>>(mesh.vertices));
}

template <Real T>
MeshClassification classify_mesh(const VetMesh& m, std::span<const Vec3<T>> p,
                                 T coplanarity_tolerance) {
  MeshClassification r;
  LOCUS_ASSERT(p.size() >= m.vertex_capacity(), "too few positions");
  r.topology = check_topology(m);
  r.orientation = orient_consistently(m);
  r.euler_characteristic = euler_characteristic(m);
  r.status = r.topology.status;
  if (r.status != Status::ok) return r;
  r.intersections = self_intersections(m, p);
  r.status = r.intersections.status;
  if (r.status != Status::ok) return r;
  // The tolerance is relative to the diagonal of the bounding box of the live vertices.
  double limit = 0;
  if (coplanarity_tolerance > 0) {
    Vec3<double> lo{}, hi{};
    bool first = true;
    for (std::uint32_t v = 0; v < m.vertex_capacity(); ++v) {
      if (!m.has_vertex(v)) continue;
      const Vec3<double> q = vec_cast<double>(p[v]);
      for (int k = 0; k < 3; ++k) {
        lo[k] = first ? q[k] : std::min(lo[k], q[k]);
        hi[k] = first ? q[k] : std::max(hi[k], q[k]);
      }
      first = false;
    }
    limit = static_cast<double>(coplanarity_tolerance) * length(hi - lo);
  }
  for (std::uint32_t f = 0; f < m.face_capacity(); ++f) {
    if (m.has_face(f) && !face_planar(m.face_vertices(f), p, limit)) {
      r.non_planar_faces.push_back(f);
    }
  }
  const MeshTopology& t = r.topology;
  const bool is_mesh = m.face_count() > 0 && t.isolated_vertices.empty() &&
                       t.isolated_edges.empty() && r.intersections.degenerate_faces.empty() &&
                       r.non_planar_faces.empty() && r.intersections.face_pairs.empty();
  if (!is_mesh) return r;
  r.kind = MeshKind::mesh;
  const bool polyhedron = r.orientation.components.face_component_count == 1 && t.closed &&
                          t.non_manifold_edges.empty() && r.orientation.orientable;
  if (!polyhedron) return r;
  r.kind = MeshKind::polyhedron;
  // Polytope: convex faces, and every edge convex for the consistent orientation or every edge
  // convex for the reversed one (docs/notes/mesh.md). Orientation of the component: flips.
  std::vector<char> flipped(m.face_capacity(), 0);
  for (const std::uint32_t f : r.orientation.flipped_faces) flipped[f] = 1;
  // For face f (in consistent orientation), a triple (a, b, c) with f's orientation.
  const auto oriented_triple = [&](std::uint32_t f, std::array<Vec3<T>, 3>& tri) {
    const auto c = m.face_vertices(f);
    std::array<std::size_t, 3> t3{};
    if (!non_collinear_triple(c, p, t3)) return false;
    // Project along the dominant normal component: a face that is flat only up to rounding
    // stays well shaped there (a near edge-on projection could fold it).
    const Vec3<double> a = vec_cast<double>(p[c[t3[0]]]);
    const Vec3<double> nrm =
        cross(vec_cast<double>(p[c[t3[1]]]) - a, vec_cast<double>(p[c[t3[2]]]) - a);
    int axis = 2;
    if (std::abs(nrm.x) > std::abs(nrm[axis])) axis = 0;
    if (std::abs(nrm.y) > std::abs(nrm[axis])) axis = 1;
    if (!face_convex(c, p, axis)) return false;
    tri = {p[c[t3[0]]], p[c[t3[1]]], p[c[t3[2]]]};
    if (flipped[f]) std::swap(tri[1], tri[2]);
    return true;
  };
  int seen_positive = 0, seen_negative = 0;
  std::array<Vec3<T>, 3> tri{};
  for (std::uint32_t e = 0; e < m.edge_capacity() && !(seen_positive && seen_negative); ++e) {
    if (!m.has_edge(e)) continue;
    std::uint32_t fs[2] = {npos, npos};
    int n = 0;
    m.for_each_edge_face(e, [&](std::uint32_t f) { fs[n++] = f; });
    if (!oriented_triple(fs[0], tri)) {
      seen_positive = seen_negative = 1;  // a non-convex face
      break;
    }
    // Any vertex of the other face off the plane tells the edge's bend.
    for (const std::uint32_t v : m.face_vertices(fs[1])) {
      const Sign s = plane_side(tri[0], tri[1], tri[2], p[v], limit);
      if (s == Sign::positive) seen_positive = 1;
      if (s == Sign::negative) seen_negative = 1;
      if (s != Sign::zero) break;
    }
  }
  r.convex = !(seen_positive && seen_negative) && (seen_positive || seen_negative);
  if (r.convex) r.kind = MeshKind::polytope;
  return r;
}

template <Real T>
MeshClassification classify_mesh(const PolygonMesh<T>& mesh, T coplanarity_tolerance) {
  const VetMeshBuild b = make_vet_mesh(mesh);
  if (b.status != Status::ok) {
    MeshClassification r;
    r.status = b.status;
    return r;
  }
  return classify_mesh(b.mesh, std::span<const Vec3<T>>(mesh.vertices), coplanarity_tolerance);
}

#define LOCUS_MESH_CHECKS_INSTANTIATE(T)                                                          \
  template MeshOrientation make_consistent<T>(PolygonMesh<T>&);                                   \
  template MeshSelfIntersections self_intersections<T>(const VetMesh&, std::span<const Vec3<T>>); \
  template MeshSelfIntersections self_intersections<T>(const PolygonMesh<T>&);                    \
  template MeshClassification classify_mesh<T>(const VetMesh&, std::span<const Vec3<T>>, T);      \
  template MeshClassification classify_mesh<T>(const PolygonMesh<T>&, T);
LOCUS_MESH_CHECKS_INSTANTIATE(float)
LOCUS_MESH_CHECKS_INSTANTIATE(double)

}  // namespace locus
