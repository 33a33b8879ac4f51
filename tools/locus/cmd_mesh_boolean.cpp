// SPDX-License-Identifier: BSL-1.0
// `locus mesh boolean`: union, intersection, difference or xor of two closed mesh files through
// their BSP trees (locus::mesh_boolean, bsp/bsp3_boolean.hpp). Polygon faces are fanned into
// triangles first (convex faces expected); the result is a triangle mesh.

#include "commands.hpp"
#include "io.hpp"

#include <locus/bsp/bsp3_boolean.hpp>
#include <locus/core/status.hpp>
#include <locus/io/mesh_io.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace locus_cli {

namespace {

struct BooleanOptions {
  std::string a, b, op, format, output;
  bool json = false;
};

locus::MeshBooleanOp parse_op(const std::string& s) {
  if (s == "union") return locus::MeshBooleanOp::union_;
  if (s == "intersection") return locus::MeshBooleanOp::intersection;
  if (s == "difference") return locus::MeshBooleanOp::difference;
  if (s == "xor" || s == "symmetric-difference") return locus::MeshBooleanOp::symmetric_difference;
  throw UsageError("--op must be union, intersection, difference or xor, not '" + s + "'");
}

std::vector<std::array<std::uint32_t, 3>> fan(const locus::PolygonMesh<double>& m) {
  std::vector<std::array<std::uint32_t, 3>> t;
  for (std::size_t f = 0; f + 1 < m.face_offsets.size(); ++f) {
    const std::uint32_t b = m.face_offsets[f], e = m.face_offsets[f + 1];
    for (std::uint32_t k = b + 1; k + 1 < e; ++k)
      t.push_back({m.face_indices[b], m.face_indices[k], m.face_indices[k + 1]});
  }
  return t;
}

double volume(const locus::MeshBoolean<double>& r) {
  double s = 0;
  for (const auto& t : r.triangles)
    s += locus::dot(r.vertices[t[0]], locus::cross(r.vertices[t[1]], r.vertices[t[2]]));
  return s / 6;
}

void run_boolean(const BooleanOptions& o) {
  const locus::MeshBooleanOp op = parse_op(o.op);
  if (locus::mesh_format_from_name(o.output) == locus::MeshFormat::from_extension) {
    throw UsageError(o.output + ": unknown mesh format (give .obj .off .ply or .stl)");
  }
  const locus::PolygonMesh<double> a = load_mesh(o.a, o.format), b = load_mesh(o.b, o.format);
  const auto ta = fan(a), tb = fan(b);
  const locus::MeshBoolean<double> r =
      locus::mesh_boolean<double>(op, a.vertices, ta, b.vertices, tb);
  if (r.status == locus::Status::non_finite_input || r.status == locus::Status::invalid_input) {
    throw InputError(o.a + ", " + o.b +
                     ": mesh boolean: " + std::string(locus::to_string(r.status)));
  }
  locus::PolygonMesh<double> out;
  out.vertices = r.vertices;
  for (const auto& t : r.triangles) {
    out.face_indices.insert(out.face_indices.end(), t.begin(), t.end());
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_indices.size()));
  }
  const auto w = locus::write_mesh(o.output, out);
  if (w.status != locus::Status::ok) throw InputError(w.message);
  const double v = volume(r);
  if (o.json) {
    JsonObject j;
    j.str("command", "mesh boolean")
        .str("op", o.op)
        .str("status", locus::to_string(r.status))
        .integer("vertices", static_cast<std::int64_t>(r.vertices.size()))
        .integer("triangles", static_cast<std::int64_t>(r.triangles.size()))
        .number("volume", v);
    std::cout << j.text() << '\n' << std::flush;
  } else {
    std::cout << "status " << locus::to_string(r.status) << "\nvertices " << r.vertices.size()
              << "\ntriangles " << r.triangles.size() << "\nvolume " << num(v) << '\n'
              << std::flush;
  }
}

}  // namespace

void register_mesh_boolean(CLI::App& mesh) {
  auto o = std::make_shared<BooleanOptions>();
  CLI::App* sub = mesh.add_subcommand(
      "boolean",
      "union, intersection, difference or xor of two closed meshes (BSP trees, book 13.1)");
  sub->add_option("a", o->a, "the first closed mesh (.obj .off .ply .stl)")->required();
  sub->add_option("b", o->b, "the second closed mesh")->required();
  sub->add_option("--op", o->op,
                  "union, intersection, difference (a minus b) or xor (symmetric difference)")
      ->required();
  sub->add_option("-o,--output", o->output, "the result mesh (format from its extension)")
      ->required();
  sub->add_option("--format", o->format, "input format, overriding the extensions");
  sub->add_flag("--json", o->json, "print the summary as JSON");
  sub->footer(
      "Both meshes must be closed with outward normals; polygon faces are fanned into triangles.\n"
      "Writes the result as triangles (vertices with identical coordinates welded) and prints\n"
      "its status, counts and volume. T-junctions at rounded cut points are left as they are.\n"
      "Example:\n  locus mesh boolean --op difference box.off hole.off -o part.off");
  sub->callback([o] { run_boolean(*o); });
}

}  // namespace locus_cli
