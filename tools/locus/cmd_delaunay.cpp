// SPDX-License-Identifier: BSL-1.0
// locus delaunay, locus delaunay3: Delaunay triangulations of point files
// (delaunay/delaunay2.hpp, delaunay/delaunay3.hpp).

#include "commands.hpp"
#include "io.hpp"

#include <locus/delaunay/delaunay2.hpp>
#include <locus/delaunay/delaunay3.hpp>

#include <memory>

namespace locus_cli {

namespace {

void run_delaunay(const Common& c) {
  const std::vector<Vec2d> pts = load_points2(c);
  locus::Delaunay2Result r;
  {
    Progress p("Delaunay triangulation", pts.size());
    r = locus::delaunay(std::span<const Vec2d>(pts));
  }
  require_ok(r.status, c.input + ": Delaunay triangulation");
  const std::span<const std::array<std::uint32_t, 3>> tris(r.triangles);
  JsonObject j;
  j.str("command", "delaunay")
      .integer("points", static_cast<std::int64_t>(pts.size()))
      .integer("dimension", r.dimension)
      .integer("duplicates", static_cast<std::int64_t>(r.duplicate_count))
      .raw("hull", json_indices(r.hull))
      .raw("triangles", json_index_rows(tris));
  if (!c.svg.empty()) {
    locus::SvgWriter svg;
    for (const auto& t : tris) {
      const std::array<Vec2d, 3> tri = {pts[t[0]], pts[t[1]], pts[t[2]]};
      svg.polygon(tri, fill_style());
    }
    for (const Vec2d& p : pts) svg.point(p, input_style());
    save_svg(c, svg);
  }
  std::vector<Vec3d> pts3;
  if (is_mesh_name(c.output)) {
    for (const Vec2d& p : pts) pts3.push_back({p.x, p.y, 0.0});
    if (tris.empty()) throw InputError(c.input + ": the points are collinear: no mesh to write");
    emit_mesh(c, triangle_mesh(pts3, tris));
    emit_json(c, j);
    return;
  }
  emit(c, index_rows(tris), j);
}

void run_delaunay3(const Common& c) {
  const std::vector<Vec3d> pts = load_points3(c);
  locus::Delaunay3Result r;
  {
    Progress p("Delaunay tetrahedralization", pts.size());
    r = locus::delaunay(std::span<const Vec3d>(pts));
  }
  require_ok(r.status, c.input + ": Delaunay tetrahedralization");
  const std::span<const std::array<std::uint32_t, 4>> tets(r.tetrahedra);
  JsonObject j;
  j.str("command", "delaunay3")
      .integer("points", static_cast<std::int64_t>(pts.size()))
      .integer("dimension", r.dimension)
      .integer("duplicates", static_cast<std::int64_t>(r.duplicate_count))
      .raw("tetrahedra", json_index_rows(tets));
  if (r.dimension == 2) {
    j.raw("triangles", json_index_rows(std::span<const std::array<std::uint32_t, 3>>(r.triangles)));
  }
  if (is_mesh_name(c.output)) {
    if (r.dimension != 3) throw InputError(c.input + ": the points are flat: no hull to write");
    emit_mesh(c, triangle_mesh(pts, r.hull));
    emit_json(c, j);
    return;
  }
  std::string text;
  if (r.dimension == 3) {
    text = index_rows(tets);
  } else if (r.dimension == 2) {
    text = "# dimension 2: the points are coplanar; triangles\n" +
           index_rows(std::span<const std::array<std::uint32_t, 3>>(r.triangles));
  } else {
    text = "# dimension " + std::to_string(r.dimension) + ": the points are " +
           (r.dimension == 1 ? "collinear" : "all equal") + "\n";
    for (const std::uint32_t i : r.chain) text += std::to_string(i) + '\n';
  }
  emit(c, text, j);
}

}  // namespace

void register_delaunay(CLI::App& app) {
  {
    auto o = std::make_shared<Common>();
    CLI::App* sub = app.add_subcommand("delaunay", "2D Delaunay triangulation of a point file");
    add_common(sub, *o, true, "2D points (.csv .txt .tsv; '-' reads CSV from stdin)");
    sub->footer(
        "Prints the triangles (input indices, counter-clockwise), one per line; -o tri.obj\n"
        "(.off .ply .stl) writes them as a mesh in the plane z = 0 instead.\n"
        "Example:\n  locus delaunay points.csv --svg delaunay.svg");
    sub->callback([o] { run_delaunay(*o); });
  }
  {
    auto o = std::make_shared<Common>();
    CLI::App* sub =
        app.add_subcommand("delaunay3", "3D Delaunay tetrahedralization of a point or mesh file");
    add_common(sub, *o, false, "3D points (.csv .txt .tsv .xyz, or a mesh's vertices)");
    sub->footer(
        "Prints the tetrahedra (input indices, positively oriented), one per line; -o hull.obj\n"
        "(.off .ply .stl) writes the boundary faces as a mesh instead.\n"
        "Example:\n  locus delaunay3 cloud.xyz --json");
    sub->callback([o] { run_delaunay3(*o); });
  }
}

}  // namespace locus_cli
