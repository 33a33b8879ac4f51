// SPDX-License-Identifier: BSL-1.0
// locus mesh info|check|convert: mesh files (io/mesh_io.hpp). `check` reports what can be
// computed from the indexed faces alone (counts, edges, duplicates, orientation); the
// topological checks of mesh/ (components, manifold vertices, self-intersection) join it when
// that area lands.

#include "commands.hpp"
#include "io.hpp"

#include <locus/io/mesh_io.hpp>

#include <algorithm>
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

struct Report {
  std::size_t unreferenced = 0;  // vertices no face uses
  std::size_t degenerate = 0;    // faces repeating a vertex
  std::size_t duplicate = 0;     // faces with the vertex set of an earlier face
  std::size_t edges = 0;         // undirected edges
  std::size_t boundary = 0;      // edges used by one face
  std::size_t non_manifold = 0;  // edges used by more than two faces
  std::size_t inconsistent = 0;  // edges used twice in the same direction
  std::int64_t euler = 0;        // V (used) - E + F
};

Report check_mesh(const locus::PolygonMesh<double>& m) {
  Report r;
  const std::size_t faces = locus::face_count(m);
  std::vector<std::uint8_t> used(m.vertices.size(), 0);
  // Directed edges (a, b) as (min, max, direction), sorted to group the uses of each edge.
  struct Edge {
    std::uint32_t lo, hi;
    bool forward;
    bool operator<(const Edge& o) const noexcept {
      return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : forward < o.forward;
    }
  };
  std::vector<Edge> edges;
  std::vector<std::vector<std::uint32_t>> keys;
  keys.reserve(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const auto v = locus::face(m, f);
    std::vector<std::uint32_t> key(v.begin(), v.end());
    std::sort(key.begin(), key.end());
    if (std::adjacent_find(key.begin(), key.end()) != key.end()) ++r.degenerate;
    keys.push_back(std::move(key));
    for (std::size_t k = 0; k < v.size(); ++k) {
      used[v[k]] = 1;
      const std::uint32_t a = v[k], b = v[(k + 1) % v.size()];
      if (a != b) edges.push_back({std::min(a, b), std::max(a, b), a < b});
    }
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 1; i < keys.size(); ++i) r.duplicate += keys[i] == keys[i - 1] ? 1 : 0;
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i, forward = 0;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) {
      forward += edges[j].forward ? 1 : 0;
      ++j;
    }
    const std::size_t uses = j - i;
    ++r.edges;
    if (uses == 1) ++r.boundary;
    if (uses > 2) ++r.non_manifold;
    if (uses == 2 && forward != 1) ++r.inconsistent;
    i = j;
  }
  std::size_t used_count = 0;
  for (const std::uint8_t u : used) used_count += u;
  r.unreferenced = m.vertices.size() - used_count;
  r.euler = static_cast<std::int64_t>(used_count) - static_cast<std::int64_t>(r.edges) +
            static_cast<std::int64_t>(faces);
  return r;
}

void run_check(const Common& c) {
  const locus::PolygonMesh<double> m = load_mesh(c.input, c.format);
  // The reader refuses out-of-range indices and non-finite coordinates; this states it.
  const bool valid = locus::check_polygon_mesh(m) == locus::Status::ok;
  Report r;
  {
    Progress p("mesh check", locus::face_count(m));
    r = check_mesh(m);
  }
  const bool closed = r.boundary == 0 && r.non_manifold == 0 && locus::face_count(m) > 0;
  const bool clean = valid && r.unreferenced == 0 && r.degenerate == 0 && r.duplicate == 0 &&
                     r.non_manifold == 0 && r.inconsistent == 0;
  auto line = [](const char* k, std::size_t v) {
    return std::string(k) + ' ' + std::to_string(v) + '\n';
  };
  std::string text = std::string("indices ") + (valid ? "valid" : "invalid") + '\n' +
                     line("vertices", m.vertices.size()) + line("faces", locus::face_count(m)) +
                     line("edges", r.edges) + line("unreferenced_vertices", r.unreferenced) +
                     line("degenerate_faces", r.degenerate) + line("duplicate_faces", r.duplicate) +
                     line("boundary_edges", r.boundary) +
                     line("non_manifold_edges", r.non_manifold) +
                     line("inconsistent_edges", r.inconsistent) + "euler_characteristic " +
                     std::to_string(r.euler) + '\n' + "closed " + (closed ? "yes" : "no") + '\n';
  JsonObject j;
  j.str("command", "mesh check")
      .boolean("valid_indices", valid)
      .integer("vertices", static_cast<std::int64_t>(m.vertices.size()))
      .integer("faces", static_cast<std::int64_t>(locus::face_count(m)))
      .integer("edges", static_cast<std::int64_t>(r.edges))
      .integer("unreferenced_vertices", static_cast<std::int64_t>(r.unreferenced))
      .integer("degenerate_faces", static_cast<std::int64_t>(r.degenerate))
      .integer("duplicate_faces", static_cast<std::int64_t>(r.duplicate))
      .integer("boundary_edges", static_cast<std::int64_t>(r.boundary))
      .integer("non_manifold_edges", static_cast<std::int64_t>(r.non_manifold))
      .integer("inconsistent_edges", static_cast<std::int64_t>(r.inconsistent))
      .integer("euler_characteristic", r.euler)
      .boolean("closed", closed)
      .boolean("clean", clean);
  add_box(bounding_box(m), text, j);
  text += std::string("clean ") + (clean ? "yes" : "no") + '\n';
  emit(c, text, j);
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
  CLI::App* mesh = app.add_subcommand("mesh", "mesh files: info, check, convert");
  mesh->require_subcommand(1);
  mesh->footer("Example:\n  locus mesh info bunny.ply\n  locus mesh convert bunny.ply bunny.obj");
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
    auto o = std::make_shared<Common>();
    CLI::App* sub = mesh->add_subcommand("check", "defects of a mesh file");
    add_common(sub, *o, false, "a mesh (.obj .off .ply .stl)");
    sub->footer(
        "Reports index validity, unreferenced vertices, faces repeating a vertex, duplicate\n"
        "faces, boundary edges (used once), non-manifold edges (used 3+ times), edges whose two\n"
        "faces disagree in orientation, the Euler characteristic and the bounding box.\n"
        "Exit code 0 whatever it finds (the report says `clean yes|no`).\n"
        "Example:\n  locus mesh check scan.stl");
    sub->callback([o] { run_check(*o); });
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
}

}  // namespace locus_cli
