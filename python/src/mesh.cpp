// SPDX-License-Identifier: BSL-1.0
// Polygon meshes: check_mesh (mesh/mesh_checks.hpp classify_mesh), self_intersections,
// orient_consistently, the solids of mesh/platonic.hpp, read_mesh / write_mesh (io/mesh_io.hpp),
// slice_mesh (intersection/plane_mesh.hpp).
// Faces come as an (m, k) integer array (every face k vertices) or a list of index sequences
// (polygons of any sizes >= 3); they are returned in the same two forms: an (m, k) uint32 array
// when every face has k vertices, else a list of 1-d uint32 arrays.
#include "common.hpp"

#include <locus/intersection/plane_mesh.hpp>
#include <locus/io/mesh_io.hpp>
#include <locus/mesh/mesh_checks.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/mesh/polygon_mesh.hpp>
#include <locus/mesh/vet_mesh.hpp>

#include <pybind11/stl.h>

#include <algorithm>
#include <string>

namespace locus::python {

namespace {

struct Faces {
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;
  [[nodiscard]] std::size_t count() const { return offsets.size() - 1; }
};

Faces read_faces(py::handle obj, const char* fn, std::size_t vertex_count) {
  if (obj.is_none()) fail(fn, "faces is None");
  Faces f;
  if (py::isinstance<py::array>(obj)) {
    py::array a = py::reinterpret_borrow<py::array>(obj);
    if (a.ndim() != 2) fail(fn, "faces must be an (m, k) integer array or a list of sequences");
    const int k = static_cast<int>(a.shape(1));
    if (k < 3)
      fail(fn,
           "faces must have at least 3 vertices each, got shape (m, " + std::to_string(k) + ")");
    f.indices = index_array(obj, fn, "faces", 2, k, vertex_count);
    for (std::size_t i = 0; i < static_cast<std::size_t>(a.shape(0)); ++i)
      f.offsets.push_back(static_cast<std::uint32_t>((i + 1) * static_cast<std::size_t>(k)));
    return f;
  }
  if (!py::isinstance<py::sequence>(obj) || py::isinstance<py::str>(obj))
    fail(fn, "faces must be an (m, k) integer array or a list of index sequences");
  for (py::handle face : py::reinterpret_borrow<py::sequence>(obj)) {
    py::array a = py::array::ensure(face);
    if (!a || a.ndim() != 1 || a.shape(0) < 3)
      fail(fn, "face " + std::to_string(f.count()) + " must be a sequence of at least 3 indices");
    const std::vector<std::uint32_t> v = index_array(a, fn, "faces", 1, 0, vertex_count);
    f.indices.insert(f.indices.end(), v.begin(), v.end());
    f.offsets.push_back(static_cast<std::uint32_t>(f.indices.size()));
  }
  return f;
}

py::object faces_out(const std::vector<std::uint32_t>& offsets,
                     const std::vector<std::uint32_t>& indices) {
  const std::size_t m = offsets.empty() ? 0 : offsets.size() - 1;
  bool uniform = true;
  const std::uint32_t k = m ? offsets[1] - offsets[0] : 3;
  for (std::size_t i = 0; i < m; ++i) uniform = uniform && offsets[i + 1] - offsets[i] == k;
  if (uniform) {
    std::vector<std::uint32_t> copy(indices);
    return to_numpy(std::move(copy), {static_cast<py::ssize_t>(m), static_cast<py::ssize_t>(k)});
  }
  py::list out;
  for (std::size_t i = 0; i < m; ++i) {
    std::vector<std::uint32_t> face(indices.begin() + offsets[i], indices.begin() + offsets[i + 1]);
    const auto len = static_cast<py::ssize_t>(face.size());
    out.append(to_numpy(std::move(face), {len}));
  }
  return out;
}

/// The (n, 3) vertices, read in place when C-contiguous float32/float64.
ArrayView read_vertices(py::handle obj, const char* fn) {
  return view_array(obj, fn, "vertices", 2, {3});
}

/// Input face index of every face id of a VetMesh build.
std::vector<std::uint32_t> input_index(const VetMeshBuild& b) {
  std::vector<std::uint32_t> inv(b.mesh.face_capacity(), VetMesh::npos);
  for (std::size_t i = 0; i < b.face_ids.size(); ++i)
    if (b.face_ids[i] != VetMesh::npos) inv[b.face_ids[i]] = static_cast<std::uint32_t>(i);
  return inv;
}

py::array edge_pairs(const VetMesh& mesh, const std::vector<std::uint32_t>& edges) {
  std::vector<std::array<std::uint32_t, 2>> out;
  for (const std::uint32_t e : edges) out.push_back(mesh.edge_vertices(e));
  std::sort(out.begin(), out.end());  // by vertex pair, not by internal edge id
  return to_numpy(std::move(out));
}

py::array face_list(const std::vector<std::uint32_t>& ids, const std::vector<std::uint32_t>& inv) {
  std::vector<std::uint32_t> out;
  for (const std::uint32_t f : ids) out.push_back(inv[f]);
  std::sort(out.begin(), out.end());
  const auto rows = static_cast<py::ssize_t>(out.size());
  return to_numpy(std::move(out), {rows});
}

py::array face_pairs(const std::vector<std::array<std::uint32_t, 2>>& pairs,
                     const std::vector<std::uint32_t>& inv) {
  std::vector<std::array<std::uint32_t, 2>> out;
  for (const auto& p : pairs) {
    std::uint32_t a = inv[p[0]], b = inv[p[1]];
    if (a > b) std::swap(a, b);
    out.push_back({a, b});
  }
  std::sort(out.begin(), out.end());
  return to_numpy(std::move(out));
}

py::array u32(std::vector<std::uint32_t> v) {
  const auto rows = static_cast<py::ssize_t>(v.size());
  return to_numpy(std::move(v), {rows});
}

/// An id list, increasing.
py::array sorted_u32(std::vector<std::uint32_t> v) {
  std::sort(v.begin(), v.end());
  return u32(std::move(v));
}

const char* kind_name(MeshKind k) {
  switch (k) {
    case MeshKind::mesh:
      return "mesh";
    case MeshKind::polyhedron:
      return "polyhedron";
    case MeshKind::polytope:
      return "polytope";
    case MeshKind::not_a_mesh:
      break;
  }
  return "not_a_mesh";
}

/// Builds the adjacency table; invalid_input raises, a skipped face (repeated vertex) raises
/// degenerate_input naming it.
VetMeshBuild build_vet(const Faces& f, std::size_t vertex_count, const char* fn) {
  VetMeshBuild b;
  {
    py::gil_scoped_release nogil;
    b = detail::make_vet_mesh(vertex_count, f.offsets, f.indices);
  }
  if (b.status == Status::degenerate_input) {
    for (std::size_t i = 0; i < b.face_ids.size(); ++i)
      if (b.face_ids[i] == VetMesh::npos)
        fail(fn, "degenerate_input: face " + std::to_string(i) + " repeats a vertex");
  }
  check_status(b.status, fn, false);
  return b;
}

template <class T>
py::tuple mesh_out(PolygonMesh<T>&& m) {
  std::vector<T> xyz;
  xyz.reserve(3 * m.vertices.size());
  for (const Vec3<T>& p : m.vertices) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  const auto n = static_cast<py::ssize_t>(m.vertices.size());
  return py::make_tuple(to_numpy(std::move(xyz), {n, py::ssize_t(3)}),
                        faces_out(m.face_offsets, m.face_indices));
}

template <class T>
PolygonMesh<T> mesh_in(const ArrayView& v, const Faces& f) {
  PolygonMesh<T> m;
  const auto pts = as_points<T, 3>(v);
  m.vertices.assign(pts.begin(), pts.end());
  m.face_offsets = f.offsets;
  m.face_indices = f.indices;
  return m;
}

MeshFormat format_from(const std::string& name, const char* fn) {
  static const std::pair<const char*, MeshFormat> names[] = {
      {"", MeshFormat::from_extension},
      {"obj", MeshFormat::obj},
      {"off", MeshFormat::off},
      {"ply", MeshFormat::ply},
      {"ply_ascii", MeshFormat::ply_ascii},
      {"ply_binary_le", MeshFormat::ply_binary_le},
      {"ply_binary_be", MeshFormat::ply_binary_be},
      {"stl", MeshFormat::stl},
      {"stl_ascii", MeshFormat::stl_ascii},
      {"stl_binary", MeshFormat::stl_binary}};
  for (const auto& [s, f] : names)
    if (name == s) return f;
  fail(fn, "invalid_input: unknown format '" + name +
               "' (obj, off, ply, ply_ascii, ply_binary_le, ply_binary_be, stl, stl_ascii, "
               "stl_binary)");
}

template <class T>
py::object slice_out(const ArrayView& v, const Faces& f, const Vec3<double>& normal,
                     double constant, const char* fn) {
  const Plane3<T> plane{
      Vec3<T>{static_cast<T>(normal.x), static_cast<T>(normal.y), static_cast<T>(normal.z)},
      static_cast<T>(constant)};
  MeshSlice<T> s;
  {
    py::gil_scoped_release nogil;
    s = slice_mesh<T>(as_points<T, 3>(v), f.offsets, f.indices, plane);
  }
  check_status(s.status, fn, false);
  py::list lines;
  std::vector<std::uint8_t> closed;
  for (Polyline3<T>& pl : s.polylines) {
    const auto k = static_cast<py::ssize_t>(pl.vertices.size());
    std::vector<T> flat;
    flat.reserve(pl.vertices.size() * 3);
    for (const Vec3<T>& q : pl.vertices) flat.insert(flat.end(), {q.x, q.y, q.z});
    lines.append(to_numpy(std::move(flat), {k, 3}));
    closed.push_back(pl.closed ? 1 : 0);
  }
  py::object out = new_result("MeshSlice", s.status);
  out.attr("polylines") = lines;
  out.attr("closed") = to_numpy(std::move(closed), {static_cast<py::ssize_t>(s.polylines.size())})
                           .attr("astype")("bool");
  return out;
}

}  // namespace

void bind_mesh(py::module_& m) {
  m.def(
      "check_mesh",
      [](py::handle vertices, py::handle faces, double coplanarity_tolerance) -> py::object {
        const char* fn = "check_mesh";
        const ArrayView v = read_vertices(vertices, fn);
        if (!(coplanarity_tolerance >= 0) || !std::isfinite(coplanarity_tolerance))
          fail(fn, "invalid_input: coplanarity_tolerance must be finite and >= 0");
        const Faces f = read_faces(faces, fn, v.rows);
        const VetMeshBuild b = build_vet(f, v.rows, fn);
        MeshClassification c;
        {
          py::gil_scoped_release nogil;
          if (v.is_float)
            c = classify_mesh<float>(b.mesh, as_points<float, 3>(v),
                                     static_cast<float>(coplanarity_tolerance));
          else
            c = classify_mesh<double>(b.mesh, as_points<double, 3>(v), coplanarity_tolerance);
        }
        check_status(c.status, fn, false);
        const std::vector<std::uint32_t> inv = input_index(b);
        py::object out = new_result("MeshCheck", c.status);
        out.attr("kind") = py::str(kind_name(c.kind));
        out.attr("closed") = c.topology.closed;
        out.attr("manifold") = c.topology.manifold;
        out.attr("orientable") = c.orientation.orientable;
        out.attr("convex") = c.convex;
        out.attr("euler_characteristic") = c.euler_characteristic;
        out.attr("vertex_count") = b.mesh.vertex_count();
        out.attr("edge_count") = b.mesh.edge_count();
        out.attr("face_count") = b.mesh.face_count();
        out.attr("boundary_edges") = edge_pairs(b.mesh, c.topology.boundary_edges);
        out.attr("non_manifold_edges") = edge_pairs(b.mesh, c.topology.non_manifold_edges);
        out.attr("non_manifold_vertices") = sorted_u32(c.topology.non_manifold_vertices);
        out.attr("isolated_vertices") = sorted_u32(c.topology.isolated_vertices);
        out.attr("components") = c.orientation.components.face_component_count;
        std::vector<std::uint32_t> comp(f.count());
        for (std::size_t i = 0; i < comp.size(); ++i)
          comp[i] = c.orientation.components.face_component[b.face_ids[i]];
        out.attr("face_component") = u32(std::move(comp));
        out.attr("self_intersections") = face_pairs(c.intersections.face_pairs, inv);
        out.attr("degenerate_faces") = face_list(c.intersections.degenerate_faces, inv);
        out.attr("non_planar_faces") = face_list(c.non_planar_faces, inv);
        return out;
      },
      py::arg("vertices"), py::arg("faces"), py::arg("coplanarity_tolerance") = 0.0,
      R"doc(Topology and validity report of a polygon mesh (book 9.3), decided exactly.

vertices (n, 3); faces (m, k) integers or a list of index sequences (polygons, >= 3 vertices,
no repeated vertex). MeshCheck: kind ('not_a_mesh', 'mesh', 'polyhedron', 'polytope'),
closed, manifold, orientable, convex, euler_characteristic (V - E + F), vertex_count,
edge_count, face_count, boundary_edges and non_manifold_edges ((k, 2) vertex pairs, smaller
first), non_manifold_vertices, isolated_vertices, components (face components: faces joined by
shared edges), face_component (per face), self_intersections ((k, 2) face pairs), degenerate_faces
(all vertices collinear), non_planar_faces. coplanarity_tolerance: 0 (exact planarity) or
relative to the bounding-box diagonal. NaN coordinates, out-of-range indices and repeated
vertices in a face raise ValueError. Cost: O(V + E + F) plus the self-intersection test
(near-linear on surface meshes).)doc");

  m.def(
      "self_intersections",
      [](py::handle vertices, py::handle faces) -> py::array {
        const char* fn = "self_intersections";
        const ArrayView v = read_vertices(vertices, fn);
        const Faces f = read_faces(faces, fn, v.rows);
        const VetMeshBuild b = build_vet(f, v.rows, fn);
        MeshSelfIntersections r;
        {
          py::gil_scoped_release nogil;
          if (v.is_float)
            r = self_intersections<float>(b.mesh, as_points<float, 3>(v));
          else
            r = self_intersections<double>(b.mesh, as_points<double, 3>(v));
        }
        check_status(r.status, fn, false);
        return face_pairs(r.face_pairs, input_index(b));
      },
      py::arg("vertices"), py::arg("faces"),
      R"doc(Pairs of faces (f, g), f < g, sorted, that interpenetrate: (k, 2) uint32, exact.

Faces sharing vertices count only when they meet beyond their shared vertices or edge
(mesh/mesh_checks.hpp). Polygon faces are tested through their fan triangles (exact for
convex faces). NaN coordinates raise ValueError. Near-linear on surface meshes.)doc");

  m.def(
      "orient_consistently",
      [](py::handle faces, py::object vertex_count) -> py::object {
        const char* fn = "orient_consistently";
        std::size_t n = 0;
        const bool given = !vertex_count.is_none();
        if (given) {
          const long long c = vertex_count.cast<long long>();
          if (c < 0) fail(fn, "invalid_input: vertex_count must be >= 0");
          n = static_cast<std::size_t>(c);
        } else {
          n = std::size_t(1) << 32;
        }
        Faces f = read_faces(faces, fn, n);
        if (!given) {
          n = 0;
          for (const std::uint32_t i : f.indices) n = std::max<std::size_t>(n, std::size_t(i) + 1);
        }
        const VetMeshBuild b = build_vet(f, n, fn);
        MeshOrientation o;
        {
          py::gil_scoped_release nogil;
          o = orient_consistently(b.mesh);
        }
        check_status(o.status, fn, false);
        const std::vector<std::uint32_t> inv = input_index(b);
        py::array_t<bool> flipped(static_cast<py::ssize_t>(f.count()));
        bool* fl = flipped.mutable_data();
        std::fill(fl, fl + f.count(), false);
        for (const std::uint32_t id : o.flipped_faces) {
          const std::uint32_t i = inv[id];
          fl[i] = true;
          std::reverse(f.indices.begin() + f.offsets[i], f.indices.begin() + f.offsets[i + 1]);
        }
        std::vector<std::uint32_t> comp(f.count());
        for (std::size_t i = 0; i < comp.size(); ++i)
          comp[i] = o.components.face_component[b.face_ids[i]];
        std::vector<std::uint32_t> bad = o.non_orientable_components;
        py::object out = new_result("OrientationResult", o.status);
        out.attr("faces") = faces_out(f.offsets, f.indices);
        out.attr("flipped") = flipped;
        out.attr("orientable") = o.orientable;
        out.attr("face_component") = u32(std::move(comp));
        out.attr("non_orientable_components") = sorted_u32(std::move(bad));
        return out;
      },
      py::arg("faces"), py::arg("vertex_count") = py::none(),
      R"doc(Consistent face orientation (book 9.3, figures 9.15-9.16): combinatorial.

Per face component (faces joined by edges shared by exactly two faces), the lowest face keeps
its order and the others are reversed where needed so that every such edge is traversed in
opposite directions. OrientationResult: faces (same form as the input, flipped faces reversed),
flipped (bool per face), orientable, face_component (per face), non_orientable_components
(Möbius-like components, whose faces are left as given). vertex_count defaults to the largest
index + 1. O(V + E + F).)doc");

  // ---- generators
  m.def(
      "tetrahedron", [] { return mesh_out(tetrahedron_mesh<double>()); },
      "Regular tetrahedron inscribed in the unit sphere: (vertices (4, 3), faces (4, 3)), faces "
      "counter-clockwise seen from outside.");
  m.def(
      "hexahedron", [] { return mesh_out(hexahedron_mesh<double>()); },
      "Cube inscribed in the unit sphere: (vertices (8, 3), faces (6, 4)), outward.");
  m.def(
      "octahedron", [] { return mesh_out(octahedron_mesh<double>()); },
      "Regular octahedron inscribed in the unit sphere: (vertices (6, 3), faces (8, 3)), outward.");
  m.def(
      "dodecahedron",
      [](bool triangulate) {
        return mesh_out(triangulate ? dodecahedron_triangle_mesh<double>()
                                    : dodecahedron_mesh<double>());
      },
      py::arg("triangulate") = false,
      "Regular dodecahedron inscribed in the unit sphere: (vertices (20, 3), faces (12, 5)), or "
      "(36, 3) fan triangles with triangulate=True; outward.");
  m.def(
      "icosahedron", [] { return mesh_out(icosahedron_mesh<double>()); },
      "Regular icosahedron inscribed in the unit sphere: (vertices (12, 3), faces (20, 3)), "
      "outward.");
  m.def(
      "uv_sphere",
      [](double radius, int slices, int stacks) {
        return mesh_out(uv_sphere_mesh<double>(radius, slices, stacks));
      },
      py::arg("radius") = 1.0, py::arg("slices") = 16, py::arg("stacks") = 8,
      "Latitude-longitude sphere about the origin, poles on z: (vertices, triangles (m, 3)). "
      "slices >= 3 and stacks >= 2 (smaller values are raised).");
  m.def(
      "icosphere",
      [](double radius, int levels) { return mesh_out(icosphere_mesh<double>(radius, levels)); },
      py::arg("radius") = 1.0, py::arg("levels") = 2,
      "Icosahedron with each triangle split in four `levels` times, vertices pushed onto the "
      "sphere: (vertices, triangles (20 * 4**levels, 3)).");
  m.def(
      "torus",
      [](double major_radius, double minor_radius, int major_segments, int minor_segments) {
        return mesh_out(
            torus_mesh<double>(major_radius, minor_radius, major_segments, minor_segments));
      },
      py::arg("major_radius") = 1.0, py::arg("minor_radius") = 0.25, py::arg("major_segments") = 32,
      py::arg("minor_segments") = 16,
      "Torus about the z axis (tube centre at major_radius, tube radius minor_radius): "
      "(vertices, triangles), closed, genus 1 (Euler characteristic 0).");
  m.def(
      "cylinder",
      [](double radius, double height, int slices) {
        return mesh_out(cylinder_mesh<double>(radius, height, slices));
      },
      py::arg("radius") = 1.0, py::arg("height") = 2.0, py::arg("slices") = 16,
      "Capped cylinder about the z axis from -height/2 to height/2: (vertices, faces) where faces "
      "is a list (two `slices`-gon caps, then the side triangles).");
  m.def(
      "cone",
      [](double radius, double height, int slices) {
        return mesh_out(cone_mesh<double>(radius, height, slices));
      },
      py::arg("radius") = 1.0, py::arg("height") = 2.0, py::arg("slices") = 16,
      "Cone about the z axis, base at -height/2, apex at height/2: (vertices, faces) where "
      "faces is a list (the `slices`-gon base, then the side triangles).");

  // ---- files
  m.def(
      "read_mesh",
      [](const std::string& path, const std::string& format) {
        const char* fn = "read_mesh";
        const MeshFormat f = format_from(format, fn);
        MeshReadResult<double> r;
        {
          py::gil_scoped_release nogil;
          r = read_mesh<double>(path, f);
        }
        if (r.status != Status::ok) fail(fn, std::string(to_string(r.status)) + ": " + r.message);
        return mesh_out(std::move(r.mesh));
      },
      py::arg("path"), py::arg("format") = "",
      R"doc(Reads an OBJ, OFF, PLY or STL file: (vertices (n, 3) float64, faces).

format: '' (from the extension) or one of obj, off, ply, stl, stl_ascii, stl_binary, ...
Malformed files raise ValueError with 'parse_error: file:line: reason'; unreadable ones
'io_error: ...'.)doc");
  m.def(
      "write_mesh",
      [](const std::string& path, py::handle vertices, py::handle faces,
         const std::string& format) {
        const char* fn = "write_mesh";
        const MeshFormat mf = format_from(format, fn);
        const ArrayView v = read_vertices(vertices, fn);
        const Faces f = read_faces(faces, fn, v.rows);
        MeshWriteResult r;
        if (v.is_float) {
          const PolygonMesh<float> mesh = mesh_in<float>(v, f);
          py::gil_scoped_release nogil;
          r = write_mesh<float>(path, mesh, mf);
        } else {
          const PolygonMesh<double> mesh = mesh_in<double>(v, f);
          py::gil_scoped_release nogil;
          r = write_mesh<double>(path, mesh, mf);
        }
        if (r.status != Status::ok)
          fail(fn, std::string(to_string(r.status)) + (r.message.empty() ? "" : ": ") + r.message);
      },
      py::arg("path"), py::arg("vertices"), py::arg("faces"), py::arg("format") = "",
      R"doc(Writes a mesh as OBJ, OFF, PLY (binary unless ply_ascii) or STL (binary unless
stl_ascii), chosen by format or the path's extension. Numbers round-trip exactly (STL binary
rounds to float32). NaN coordinates raise ValueError.)doc");
  m.def(
      "slice_mesh",
      [](py::handle vertices, py::handle faces, py::handle normal, double constant) {
        const char* fn = "slice_mesh";
        const ArrayView v = read_vertices(vertices, fn);
        const Faces f = read_faces(faces, fn, v.rows);
        const ArrayView n = view_array(normal, fn, "normal", 1, {3});
        Vec3<double> nd;
        for (int k = 0; k < 3; ++k)
          nd[k] = n.is_float ? double(static_cast<const float*>(n.array.data())[k])
                             : static_cast<const double*>(n.array.data())[k];
        return v.is_float ? slice_out<float>(v, f, nd, constant, fn)
                          : slice_out<double>(v, f, nd, constant, fn);
      },
      py::arg("vertices"), py::arg("faces"), py::arg("normal"), py::arg("constant"),
      R"doc(Cross-section of a mesh by the plane {X : normal . X = constant} (book 11.5.5).

vertices (n, 3); faces (m, k) integers or a list of index sequences (polygon faces are split
into fans). MeshSlice: polylines (list of (k, 3) arrays in the input's dtype), closed (bool per
polyline: closed loops for a closed manifold mesh, open chains ending on boundary edges). Vertex
sides are exact; a vertex on the plane counts as on the positive side. Outer loops of an
outward-oriented solid run counter-clockwise seen from the positive side. NaN coordinates, a
zero normal or an empty mesh raise ValueError. Cost O(n) expected.)doc");
}

}  // namespace locus::python
