// SPDX-License-Identifier: BSL-1.0
// locus partition: convex partitions of polygons read from WKT or GeoJSON
// (triangulate/convex_partition.hpp).

#include "commands.hpp"
#include "io.hpp"

#include <locus/triangulate/convex_partition.hpp>

#include <memory>

namespace locus_cli {

namespace {

struct PartitionOptions {
  Common c;
  std::string method = "hm";
};

void run_partition(const PartitionOptions& o) {
  const std::vector<PolygonInput> polygons = load_polygons(o.c);
  std::string text, rows = "[";
  locus::SvgWriter svg;
  std::size_t pieces = 0;
  std::uint32_t base = 0;
  Progress progress("convex partition", polygons.size());
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const PolygonInput& p = polygons[k];
    const std::span<const Vec2d> pts(p.points);
    const std::span<const std::uint32_t> ends(p.ring_ends);
    const locus::ConvexPartition r = o.method == "min" ? locus::min_convex_partition(pts, ends)
                                                       : locus::convex_partition(pts, ends);
    require_ok(r.status, o.c.input + ": polygon " + std::to_string(k) + ": convex partition");
    std::uint32_t b = 0;
    for (const std::uint32_t e : r.piece_ends) {
      std::vector<Vec2d> corners;
      rows += pieces++ ? ",[" : "[";
      for (std::uint32_t i = b; i < e; ++i) {
        const std::uint32_t v = base + r.vertices[i];
        text += (i > b ? " " : "") + std::to_string(v);
        rows += (i > b ? "," : "") + std::to_string(v);
        corners.push_back(p.points[r.vertices[i]]);
      }
      text += '\n';
      rows += ']';
      svg.polygon(corners, fill_style());
      b = e;
    }
    std::uint32_t begin = 0;
    for (const std::uint32_t end : p.ring_ends) {
      svg.polyline(pts.subspan(begin, end - begin), result_style(), true);
      begin = end;
    }
    base += static_cast<std::uint32_t>(p.points.size());
  }
  if (!o.c.svg.empty()) save_svg(o.c, svg);
  JsonObject j;
  j.str("command", "partition")
      .str("method", o.method)
      .integer("polygons", static_cast<std::int64_t>(polygons.size()))
      .integer("pieces", static_cast<std::int64_t>(pieces))
      .raw("piece_indices", rows + "]");
  emit(o.c, text, j);
}

}  // namespace

void register_partition(CLI::App& app) {
  auto o = std::make_shared<PartitionOptions>();
  CLI::App* sub = app.add_subcommand("partition", "convex partition of polygons (WKT, GeoJSON)");
  add_common(sub, o->c, true, "a polygon file: WKT (.wkt) or GeoJSON (.json .geojson)");
  sub->add_option("--method", o->method,
                  "hm (Hertel-Mehlhorn, default, holes allowed) or min (minimum, no holes, at "
                  "most 64 vertices)")
      ->check(CLI::IsMember({"hm", "min"}));
  sub->footer(
      "Cuts each polygon of the file into convex pieces by diagonals and prints one piece per\n"
      "line: its vertex indices counter-clockwise, into the polygons' points in file order\n"
      "(rings without their closing point).\n"
      "Example:\n  locus partition floorplan.wkt --method min --svg pieces.svg");
  sub->callback([o] { run_partition(*o); });
}

}  // namespace locus_cli
