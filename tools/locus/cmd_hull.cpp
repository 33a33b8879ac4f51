// SPDX-License-Identifier: BSL-1.0
// locus hull, locus hull3: convex hulls of point files (hull/hull2.hpp, hull/hull3.hpp).

#include "commands.hpp"
#include "io.hpp"

#include <locus/hull/hull2.hpp>
#include <locus/hull/hull3.hpp>

#include <memory>

namespace locus_cli {

namespace {

struct HullOptions {
  Common c;
  bool indices = false;
  bool collinear = false;
};

void run_hull(const HullOptions& o) {
  const std::vector<Vec2d> pts = load_points2(o.c);
  locus::Hull2Options opt;
  opt.keep_collinear = o.collinear;
  locus::Hull2Result r;
  {
    Progress p("convex hull", pts.size());
    r = locus::convex_hull(std::span<const Vec2d>(pts), opt);
  }
  require_ok(r.status, o.c.input + ": convex hull");
  std::vector<Vec2d> hull;
  for (const std::uint32_t i : r.indices) hull.push_back(pts[i]);
  JsonObject j;
  j.str("command", "hull")
      .integer("points", static_cast<std::int64_t>(pts.size()))
      .integer("dimension", r.dimension)
      .raw("indices", json_indices(r.indices));
  if (o.indices) {
    std::string text;
    for (const std::uint32_t i : r.indices) text += std::to_string(i) + '\n';
    emit(o.c, text, j);
  } else {
    emit_points<2>(o.c, hull, j);
  }
  if (!o.c.svg.empty()) {
    locus::SvgWriter svg;
    svg.polygon(hull, fill_style());
    for (const Vec2d& p : pts) svg.point(p, input_style());
    save_svg(o.c, svg);
  }
}

struct Hull3Opts {
  Common c;
  std::string method = "quickhull";
};

void run_hull3(const Hull3Opts& o) {
  const std::vector<Vec3d> pts = load_points3(o.c);
  locus::Hull3Options opt;
  opt.method = o.method == "incremental"      ? locus::Hull3Method::incremental
               : o.method == "divide-conquer" ? locus::Hull3Method::divide_and_conquer
                                              : locus::Hull3Method::quickhull;
  locus::Hull3Result r;
  {
    Progress p("convex hull", pts.size());
    r = locus::convex_hull(std::span<const Vec3d>(pts), opt);
  }
  require_ok(r.status, o.c.input + ": convex hull");
  JsonObject j;
  j.str("command", "hull3")
      .integer("points", static_cast<std::int64_t>(pts.size()))
      .integer("dimension", r.dimension)
      .raw("vertices", json_indices(r.vertices));
  std::string text;
  if (r.dimension == 3) {
    const std::span<const std::array<std::uint32_t, 3>> tris(r.triangles);
    j.raw("triangles", json_index_rows(tris));
    text = index_rows(tris);
    if (emit_mesh(o.c, triangle_mesh(pts, tris))) {
      emit_json(o.c, j);
      return;
    }
  } else {
    j.raw("polygon", json_indices(r.polygon)).integer("plane_axis", r.plane_axis);
    text = "# dimension " + std::to_string(r.dimension) + ": the hull is";
    text += r.dimension == 2 ? " a polygon" : r.dimension == 1 ? " a segment" : " a point";
    text += '\n';
    for (const std::uint32_t i : r.polygon) text += std::to_string(i) + '\n';
    if (is_mesh_name(o.c.output)) {
      throw InputError(o.c.input + ": the hull is flat (dimension " + std::to_string(r.dimension) +
                       "): no mesh to write");
    }
  }
  emit(o.c, text, j);
}

}  // namespace

void register_hull(CLI::App& app) {
  {
    auto o = std::make_shared<HullOptions>();
    CLI::App* sub = app.add_subcommand("hull", "2D convex hull of a point file");
    add_common(sub, o->c, true, "2D points (.csv .txt .tsv; '-' reads CSV from stdin)");
    sub->add_flag("--indices", o->indices, "print the input indices (0-based) of the hull");
    sub->add_flag("--collinear", o->collinear, "also keep points inside hull edges");
    sub->footer(
        "Prints the hull's vertices counter-clockwise from the lowest-leftmost point, as CSV.\n"
        "Example:\n  locus hull points.csv --svg hull.svg\n  locus hull points.csv --indices");
    sub->callback([o] { run_hull(*o); });
  }
  {
    auto o = std::make_shared<Hull3Opts>();
    CLI::App* sub = app.add_subcommand("hull3", "3D convex hull of a point or mesh file");
    add_common(sub, o->c, false, "3D points (.csv .txt .tsv .xyz, or a mesh's vertices)");
    sub->add_option("--method", o->method,
                    "quickhull (default), incremental or divide-conquer: the same hull")
        ->check(CLI::IsMember({"quickhull", "incremental", "divide-conquer"}));
    sub->footer(
        "Prints the hull's triangles (input indices, counter-clockwise seen from outside), one\n"
        "per line; -o hull.obj (.off .ply .stl) writes the hull as a mesh instead.\n"
        "Example:\n  locus hull3 cloud.xyz -o hull.obj\n"
        "  locus hull3 cloud.xyz --method divide-conquer");
    sub->callback([o] { run_hull3(*o); });
  }
}

}  // namespace locus_cli
