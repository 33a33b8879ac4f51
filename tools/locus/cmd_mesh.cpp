// SPDX-License-Identifier: BSL-1.0
// locus mesh info|check|orient|generate|convert: mesh files (io/mesh_io.hpp). `check` reports
// the checks of mesh/mesh_checks.hpp (topology, components, orientation, self-intersections,
// classification), `orient` applies make_consistent(), `generate` writes a mesh of
// mesh/platonic.hpp. The tool computes none of these itself.

#include "commands.hpp"
#include "io.hpp"

#include <locus/io/mesh_io.hpp>
#include <locus/mesh/mesh_checks.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/mesh/vet_mesh.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

namespace locus_cli {

namespace {

struct Box {
  Vec3d lo{}, hi{};
  bool empty = true;
};

Box bounding_box(const locus::PolygonMesh<double>& m) {
  Box b;
  for (const Vec3d& v : m.vertices) {
    if (b.empty) {
      b.lo = b.hi = v;
      b.empty = false;
    }
    for (int i = 0; i < 3; ++i) {
      b.lo[i] = std::min(b.lo[i], v[i]);
      b.hi[i] = std::max(b.hi[i], v[i]);
    }
  }
  return b;
}

std::string vec3_text(const Vec3d& v) { return num(v.x) + ' ' + num(v.y) + ' ' + num(v.z); }

void add_box(const Box& b, std::string& text, JsonObject& j) {
  if (b.empty) {
    text += "bbox none\n";
    j.raw("bbox", "null");
    return;
  }
  text += "bbox_min " + vec3_text(b.lo) + "\nbbox_max " + vec3_text(b.hi) + '\n';
  j.raw("bbox", "[" + json_vec<3>(b.lo) + "," + json_vec<3>(b.hi) + "]");
}

void run_info(const Common& c) {
  const locus::PolygonMesh<double> m = load_mesh(c.input, c.format);
  const std::size_t faces = locus::face_count(m);
  std::size_t min_size = 0, max_size = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    const std::size_t k = locus::face(m, f).size();
    min_size = f == 0 ? k : std::min(min_size, k);
    max_size = std::max(max_size, k);
  }
  const std::size_t triangles = locus::fan_triangle_count(m);
  std::string text = "vertices " + std::to_string(m.vertices.size()) + "\nfaces " +
                     std::to_string(faces) + "\ntriangles " + std::to_string(triangles) +
                     "\nface_size " + std::to_string(min_size) + ' ' + std::to_string(max_size) +
                     '\n';
  JsonObject j;
  j.str("command", "mesh info")
      .integer("vertices", static_cast<std::int64_t>(m.vertices.size()))
      .integer("faces", static_cast<std::int64_t>(faces))
      .integer("triangles", static_cast<std::int64_t>(triangles))
      .raw("face_size", "[" + std::to_string(min_size) + "," + std::to_string(max_size) + "]");
  add_box(bounding_box(m), text, j);
  emit(c, text, j);
}

struct CheckOptions {
  Common common;
  double tolerance = 0;  // --tolerance: classify_mesh's coplanarity tolerance
};

const char* kind_name(locus::MeshKind k) {
  switch (k) {
    case locus::MeshKind::not_a_mesh:
      return "not_a_mesh";
    case locus::MeshKind::mesh:
      return "mesh";
    case locus::MeshKind::polyhedron:
      return "polyhedron";
    case locus::MeshKind::polytope:
      return "polytope";
  }
  return "not_a_mesh";
}

// The adjacency table of a mesh read from a file; faces repeating a vertex are skipped (and
// counted), other defects of the index structure are bad input.
locus::VetMeshBuild vet_table(const locus::PolygonMesh<double>& m, const std::string& input) {
  locus::VetMeshBuild b = locus::make_vet_mesh(m);
  if (b.status == locus::Status::invalid_input) {
    throw InputError(input + ": invalid face structure (a face with fewer than 3 vertices)");
  }
  return b;
}

// Everything comes from mesh/mesh_checks.hpp: classify_mesh() runs check_topology(),
// orient_consistently() (with connected_components()) and self_intersections(), then the
// planarity and convexity tests. Face ids of the table are mapped back to input face indices.
void run_check(const CheckOptions& o) {
  const Common& c = o.common;
  if (!(o.tolerance >= 0) || !std::isfinite(o.tolerance)) {
    throw UsageError("--tolerance must be a finite number >= 0");
  }
  const locus::PolygonMesh<double> m = load_mesh(c.input, c.format);
  const locus::VetMeshBuild b = vet_table(m, c.input);
  std::vector<std::uint32_t> input_face(b.mesh.face_capacity(), locus::VetMesh::npos);
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < b.face_ids.size(); ++i) {
    if (b.face_ids[i] == locus::VetMesh::npos) {
      ++skipped;
    } else {
      input_face[b.face_ids[i]] = static_cast<std::uint32_t>(i);
    }
  }
  locus::MeshClassification r;
  {
    Progress p("mesh check", locus::face_count(m));
    r = locus::classify_mesh(b.mesh, std::span<const Vec3d>(m.vertices), o.tolerance);
  }
  const locus::MeshTopology& t = r.topology;
  const locus::MeshOrientation& orient = r.orientation;
  std::vector<std::array<std::uint32_t, 2>> pairs;
  for (const auto& [f, g] : r.intersections.face_pairs) {
    pairs.push_back({input_face[f], input_face[g]});
  }
  const auto count = [](const auto& v) { return static_cast<std::int64_t>(v.size()); };
  const auto yes = [](bool v) { return std::string(v ? "yes" : "no"); };
  const std::pair<const char*, std::int64_t> counts[] = {
      {"vertices", static_cast<std::int64_t>(m.vertices.size())},
      {"faces", static_cast<std::int64_t>(locus::face_count(m))},
      {"edges", static_cast<std::int64_t>(b.mesh.edge_count())},
      {"skipped_faces", static_cast<std::int64_t>(skipped)},
      {"isolated_vertices", count(t.isolated_vertices)},
      {"isolated_edges", count(t.isolated_edges)},
      {"boundary_edges", count(t.boundary_edges)},
      {"non_manifold_edges", count(t.non_manifold_edges)},
      {"non_manifold_vertices", count(t.non_manifold_vertices)},
      {"face_components", orient.components.face_component_count},
      {"vertex_components", orient.components.vertex_component_count},
      {"faces_to_flip", count(orient.flipped_faces)},
      {"non_orientable_components", count(orient.non_orientable_components)},
      {"self_intersections", count(pairs)},
      {"degenerate_faces", count(r.intersections.degenerate_faces)},
      {"non_planar_faces", count(r.non_planar_faces)},
      {"euler_characteristic", r.euler_characteristic}};
  std::string text;
  JsonObject j;
  j.str("command", "mesh check");
  for (const auto& [k, v] : counts) {
    text += std::string(k) + ' ' + std::to_string(v) + '\n';
    j.integer(k, v);
  }
  const std::pair<const char*, bool> flags[] = {{"closed", t.closed},
                                                {"manifold", t.manifold},
                                                {"orientable", orient.orientable},
                                                {"convex", r.convex}};
  for (const auto& [k, v] : flags) {
    text += std::string(k) + ' ' + yes(v) + '\n';
    j.boolean(k, v);
  }
  text += std::string("kind ") + kind_name(r.kind) + '\n';
  j.str("kind", kind_name(r.kind));
  j.raw("self_intersection_pairs",
        json_index_rows<2>(std::span<const std::array<std::uint32_t, 2>>(pairs)));
  add_box(bounding_box(m), text, j);
  emit(c, text, j);
}

void run_orient(const Common& c) {
  if (c.output.empty() || !is_mesh_name(c.output)) {
    throw UsageError("mesh orient needs -o with a mesh file (.obj .off .ply .stl)");
  }
  locus::PolygonMesh<double> m = load_mesh(c.input, c.format);
  (void)vet_table(m, c.input);
  const locus::MeshOrientation r = locus::make_consistent(m);
  if (r.status == locus::Status::degenerate_input) {
    throw InputError(c.input + ": a face repeats a vertex (mesh check counts them)");
  }
  require_ok(r.status == locus::Status::empty_input ? locus::Status::ok : r.status, c.input);
  (void)emit_mesh(c, m);
  const std::string text =
      "flipped_faces " + std::to_string(r.flipped_faces.size()) + "\nface_components " +
      std::to_string(r.components.face_component_count) + "\nnon_orientable_components " +
      std::to_string(r.non_orientable_components.size()) + "\norientable " +
      (r.orientable ? "yes" : "no") + '\n';
  JsonObject j;
  j.str("command", "mesh orient")
      .integer("flipped_faces", static_cast<std::int64_t>(r.flipped_faces.size()))
      .integer("face_components", r.components.face_component_count)
      .integer("non_orientable_components",
               static_cast<std::int64_t>(r.non_orientable_components.size()))
      .boolean("orientable", r.orientable)
      .raw("flipped", json_indices(r.flipped_faces))
      .raw("non_orientable", json_indices(r.non_orientable_components));
  if (c.json) {
    emit_json(c, j);
  } else {
    std::cout << text << std::flush;
  }
}

struct GenerateOptions {
  std::string shape, output;
  double radius = 1, height = 2, major_radius = 1, minor_radius = 0.25;
  int slices = 32, stacks = 16, levels = 2, major_segments = 32, minor_segments = 16;
  bool triangles = false;
  bool json = false;
};

locus::PolygonMesh<double> generate(const GenerateOptions& o) {
  const auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v)) {
      throw UsageError(std::string(name) + " must be a finite number > 0");
    }
  };
  const std::string& s = o.shape;
  if (s == "tetrahedron") return locus::tetrahedron_mesh<double>();
  if (s == "cube") return locus::hexahedron_mesh<double>();
  if (s == "octahedron") return locus::octahedron_mesh<double>();
  if (s == "dodecahedron") {
    return o.triangles ? locus::dodecahedron_triangle_mesh<double>()
                       : locus::dodecahedron_mesh<double>();
  }
  if (s == "icosahedron") return locus::icosahedron_mesh<double>();
  positive(o.radius, "--radius");
  if (s == "uvsphere") return locus::uv_sphere_mesh<double>(o.radius, o.slices, o.stacks);
  if (s == "icosphere") {
    if (o.levels < 0 || o.levels > 8) throw UsageError("--levels must be 0 to 8");
    return locus::icosphere_mesh<double>(o.radius, o.levels);
  }
  if (s == "torus") {
    positive(o.minor_radius, "--minor-radius");
    if (!(o.major_radius > o.minor_radius) || !std::isfinite(o.major_radius)) {
      throw UsageError("--major-radius must be finite and larger than --minor-radius");
    }
    return locus::torus_mesh<double>(o.major_radius, o.minor_radius, o.major_segments,
                                     o.minor_segments);
  }
  positive(o.height, "--height");
  if (s == "cylinder") return locus::cylinder_mesh<double>(o.radius, o.height, o.slices);
  return locus::cone_mesh<double>(o.radius, o.height, o.slices);
}

void run_generate(const GenerateOptions& o) {
  if (!is_mesh_name(o.output)) {
    throw UsageError("mesh generate needs -o with a mesh file (.obj .off .ply .stl)");
  }
  constexpr int max_segments = 1 << 12;
  for (const int n : {o.slices, o.stacks, o.major_segments, o.minor_segments}) {
    if (n > max_segments) throw UsageError("segment counts are at most 4096");
  }
  const locus::PolygonMesh<double> m = generate(o);
  Common c;
  c.output = o.output;
  c.json = o.json;
  (void)emit_mesh(c, m);
  const std::string text = "vertices " + std::to_string(m.vertices.size()) + "\nfaces " +
                           std::to_string(locus::face_count(m)) + '\n';
  JsonObject j;
  j.str("command", "mesh generate")
      .str("shape", o.shape)
      .integer("vertices", static_cast<std::int64_t>(m.vertices.size()))
      .integer("faces", static_cast<std::int64_t>(locus::face_count(m)));
  if (o.json) {
    emit_json(c, j);
  } else {
    std::cout << text << std::flush;
  }
}

struct ConvertOptions {
  std::string input, output, from, to;
};

locus::MeshFormat out_format(const ConvertOptions& o) {
  using F = locus::MeshFormat;
  if (o.to.empty()) {
    const F f = locus::mesh_format_from_name(o.output);
    if (f == F::from_extension) {
      throw UsageError(o.output + ": unknown mesh format (give --to or .obj .off .ply .stl)");
    }
    return f;
  }
  const std::pair<const char*, F> names[] = {{"obj", F::obj},
                                             {"off", F::off},
                                             {"ply", F::ply},
                                             {"ply-ascii", F::ply_ascii},
                                             {"ply-le", F::ply_binary_le},
                                             {"ply-be", F::ply_binary_be},
                                             {"stl", F::stl},
                                             {"stl-ascii", F::stl_ascii},
                                             {"stl-binary", F::stl_binary}};
  for (const auto& [n, f] : names) {
    if (o.to == n) return f;
  }
  throw UsageError("unknown --to '" + o.to + "'");
}

void run_convert(const ConvertOptions& o) {
  const locus::MeshFormat to = out_format(o);
  const locus::PolygonMesh<double> m = load_mesh(o.input, o.from);
  const auto w = locus::write_mesh(o.output, m, to);
  if (w.status != locus::Status::ok) throw InputError(w.message);
}

}  // namespace

void register_mesh(CLI::App& app) {
  CLI::App* mesh = app.add_subcommand(
      "mesh", "mesh files: info, check, orient, generate, convert, slice, boolean");
  mesh->require_subcommand(1);
  mesh->footer(
      "Example:\n  locus mesh info bunny.ply\n  locus mesh check bunny.ply\n"
      "  locus mesh generate icosphere --levels 3 -o sphere.obj");
  {
    auto o = std::make_shared<Common>();
    CLI::App* sub = mesh->add_subcommand("info", "counts and bounding box of a mesh file");
    add_common(sub, *o, false, "a mesh (.obj .off .ply .stl)");
    sub->footer(
        "Prints the vertex, face and (fan) triangle counts, the smallest and largest face size\n"
        "and the bounding box.\nExample:\n  locus mesh info bunny.ply --json");
    sub->callback([o] { run_info(*o); });
  }
  {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* sub = mesh->add_subcommand("check", "validity checks of a mesh file (book 9.3)");
    add_common(sub, o->common, false, "a mesh (.obj .off .ply .stl)");
    sub->add_option("--tolerance", o->tolerance,
                    "coplanarity tolerance for planar faces and convex edges, relative to the "
                    "bounding-box diagonal (default 0: exact)");
    sub->footer(
        "Reports the checks of mesh/mesh_checks.hpp: faces skipped because they repeat a vertex,\n"
        "isolated vertices, boundary (1 face) and non-manifold (3+ faces) edges, non-manifold\n"
        "vertices (bow-ties), face and vertex components, faces to flip for a consistent\n"
        "orientation, non-orientable components, self-intersecting face pairs (exact), faces\n"
        "with collinear vertices, non-planar faces, the Euler characteristic, closed, manifold,\n"
        "orientable, convex and the kind: not_a_mesh, mesh, polyhedron or polytope.\n"
        "Exit code 0 whatever it finds (a report is not a failure); 1 for an unreadable file.\n"
        "Example:\n  locus mesh check scan.stl\n  locus mesh check part.obj --tolerance 1e-9 "
        "--json");
    sub->callback([o] { run_check(*o); });
  }
  {
    auto o = std::make_shared<Common>();
    CLI::App* sub = mesh->add_subcommand("orient", "orient the faces of a mesh consistently");
    add_common(sub, *o, false, "a mesh (.obj .off .ply .stl)");
    sub->footer(
        "Writes the mesh (-o, required) with the faces of each component reordered to agree\n"
        "with its lowest-numbered face (make_consistent). Faces of a non-orientable component\n"
        "(Moebius-like) are left as they are; the report counts the flipped faces and those\n"
        "components. Faces repeating a vertex are bad input (exit 1).\n"
        "Example:\n  locus mesh orient scan.obj -o fixed.obj");
    sub->callback([o] { run_orient(*o); });
  }
  {
    auto o = std::make_shared<GenerateOptions>();
    CLI::App* sub = mesh->add_subcommand("generate", "write a Platonic solid or tessellation");
    sub->add_option("shape", o->shape, "the shape")
        ->required()
        ->check(CLI::IsMember({"tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron",
                               "uvsphere", "icosphere", "torus", "cylinder", "cone"}));
    sub->add_option("-o,--output", o->output, "the mesh file to write (.obj .off .ply .stl)")
        ->required();
    sub->add_option("--radius", o->radius, "sphere, cylinder and cone radius (default 1)");
    sub->add_option("--height", o->height, "cylinder and cone height along z (default 2)");
    sub->add_option("--slices", o->slices, "segments around z (default 32, at least 3)");
    sub->add_option("--stacks", o->stacks, "uvsphere segments pole to pole (default 16)");
    sub->add_option("--levels", o->levels, "icosphere subdivisions, 0 to 8 (default 2)");
    sub->add_option("--major-radius", o->major_radius, "torus: to the tube centre (default 1)");
    sub->add_option("--minor-radius", o->minor_radius, "torus: tube radius (default 0.25)");
    sub->add_option("--major-segments", o->major_segments, "torus: around z (default 32)");
    sub->add_option("--minor-segments", o->minor_segments, "torus: around the tube (default 16)");
    sub->add_flag("--triangles", o->triangles, "dodecahedron: fan each pentagon into triangles");
    sub->add_flag("--json", o->json, "print a JSON summary on stdout");
    sub->footer(
        "Meshes of mesh/platonic.hpp, faces counter-clockwise seen from outside, closed and\n"
        "manifold. Platonic solids have unit circumradius about the origin; spheres are about\n"
        "the origin, the torus about the z axis, cylinder and cone along z from -height/2 to\n"
        "height/2. Counts below the minimum (3 around, 2 stacks) are raised to it.\n"
        "Example:\n  locus mesh generate torus --major-radius 2 --minor-radius 0.5 -o torus.obj");
    sub->callback([o] { run_generate(*o); });
  }
  {
    auto o = std::make_shared<ConvertOptions>();
    CLI::App* sub = mesh->add_subcommand("convert", "convert a mesh file to another format");
    sub->add_option("input", o->input, "a mesh (.obj .off .ply .stl)")->required();
    sub->add_option("output", o->output, "the mesh to write (format from its extension)")
        ->required();
    sub->add_option("--format", o->from, "input format: obj, off, ply or stl");
    sub->add_option("--to", o->to,
                    "output format: obj, off, ply (binary LE), ply-ascii, ply-le, ply-be, stl "
                    "(binary), stl-ascii, stl-binary");
    sub->footer(
        "Numbers are written in the shortest form that reads back exactly, so OBJ, OFF, ASCII\n"
        "PLY and binary PLY round trips are bit-exact (binary STL rounds to float).\n"
        "Example:\n  locus mesh convert bunny.ply bunny.obj\n"
        "  locus mesh convert part.obj part.stl --to stl-ascii");
    sub->callback([o] { run_convert(*o); });
  }
  register_mesh_slice(*mesh);
  register_mesh_boolean(*mesh);
}

}  // namespace locus_cli
