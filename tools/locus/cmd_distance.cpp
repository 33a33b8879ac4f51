// SPDX-License-Identifier: BSL-1.0
// locus distance: the distance from each point of a file to the surface of a mesh
// (distance/point_mesh.hpp), optionally signed (negative inside a closed mesh).

#include "commands.hpp"
#include "io.hpp"

#include <locus/distance/point_mesh.hpp>

#include <algorithm>
#include <memory>

namespace locus_cli {

namespace {

struct DistanceOptions {
  Common c;
  std::string mesh;
  std::string mesh_format;
  bool signed_distance = false;
};

void run_distance(const DistanceOptions& o) {
  const std::vector<Vec3d> pts = load_points3(o.c);
  const locus::PolygonMesh<double> mesh = load_mesh(o.mesh, o.mesh_format);
  const auto tris = locus::fan_triangles(mesh);
  // The face of each fan triangle, to report faces of the file rather than triangles.
  std::vector<std::uint32_t> face_of;
  face_of.reserve(tris.size());
  for (std::size_t f = 0; f < locus::face_count(mesh); ++f) {
    for (std::size_t k = 2; k < locus::face(mesh, f).size(); ++k) {
      face_of.push_back(static_cast<std::uint32_t>(f));
    }
  }
  std::string text = o.signed_distance ? "signed_distance,x,y,z,face\n" : "distance,x,y,z,face\n";
  std::vector<double> values;
  {
    Progress p("distances to the mesh", pts.size());
    const locus::MeshDistanceTree<double> tree(std::span<const Vec3d>(mesh.vertices),
                                               std::span<const std::array<std::uint32_t, 3>>(tris));
    require_ok(tree.status(), o.mesh + ": mesh for distances");
    if (o.signed_distance && !tree.closed()) {
      throw InputError(o.mesh + ": the mesh is not closed: no inside for --signed");
    }
    for (const Vec3d& q : pts) {
      const auto d = locus::distance(q, tree);
      const double v = o.signed_distance ? locus::signed_distance(q, tree) : d.distance;
      values.push_back(v);
      text += num(v) + ',' + num(d.closest[1].x) + ',' + num(d.closest[1].y) + ',' +
              num(d.closest[1].z) + ',' + std::to_string(face_of[d.param_b.triangle]) + '\n';
    }
  }
  JsonObject j;
  j.str("command", "distance")
      .integer("points", static_cast<std::int64_t>(pts.size()))
      .integer("faces", static_cast<std::int64_t>(locus::face_count(mesh)))
      .boolean("signed", o.signed_distance);
  if (!values.empty()) {
    j.number("min", *std::min_element(values.begin(), values.end()))
        .number("max", *std::max_element(values.begin(), values.end()));
  }
  emit(o.c, text, j);
}

}  // namespace

void register_distance(CLI::App& app) {
  auto o = std::make_shared<DistanceOptions>();
  CLI::App* sub =
      app.add_subcommand("distance", "distance from each point of a file to a mesh surface");
  add_common(sub, o->c, false, "3D query points (.csv .txt .tsv .xyz, or a mesh's vertices)");
  sub->add_option("--mesh", o->mesh, "the mesh (.obj .off .ply .stl)")->required();
  sub->add_option("--mesh-format", o->mesh_format, "the mesh's format, overriding its extension");
  sub->add_flag("--signed", o->signed_distance,
                "signed distance: negative inside the mesh, which must be closed");
  sub->footer(
      "Prints CSV: per query point the distance, the nearest surface point and the face it\n"
      "lies on (0-based, in file order).\n"
      "Example:\n  locus distance probes.csv --mesh part.stl --signed");
  sub->callback([o] { run_distance(*o); });
}

}  // namespace locus_cli
