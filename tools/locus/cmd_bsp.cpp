// SPDX-License-Identifier: BSL-1.0
// locus bsp: BSP trees of polygons (bsp/bsp2.hpp): `bsp classify` (points against a polygon)
// and `bsp boolean` (intersection, union, difference, exclusive-or of two polygons through
// their trees, bsp/bsp2_boolean.hpp).

#include "commands.hpp"
#include "io.hpp"

#include <locus/bsp/bsp2.hpp>
#include <locus/bsp/bsp2_boolean.hpp>

#include <memory>

namespace locus_cli {

namespace {

using locus::Bsp2;

/// The one polygon (outer ring + holes) of a WKT / GeoJSON file, as a tree.
Bsp2<double> load_tree(const Common& c, const std::string& path, PolygonInput& p) {
  Common in = c;
  in.input = path;
  std::vector<PolygonInput> polygons = load_polygons(in);
  if (polygons.size() != 1) {
    throw InputError(path + ": " + std::to_string(polygons.size()) +
                     " polygons; give exactly one (its holes as inner rings)");
  }
  p = std::move(polygons[0]);
  Bsp2<double> t(std::span<const Vec2d>(p.points), std::span<const std::uint32_t>(p.ring_ends));
  require_ok(t.status(), path + ": BSP tree");
  return t;
}

std::string xy(const Vec2d& p) { return num(p.x) + " " + num(p.y); }
std::string json_xy(const Vec2d& p) {
  return "[" + json_number(p.x) + "," + json_number(p.y) + "]";
}

struct ClassifyOptions {
  Common c;
  std::string points;
};

void run_classify(const ClassifyOptions& o) {
  PolygonInput p;
  const Bsp2<double> t = load_tree(o.c, o.c.input, p);
  Common pc = o.c;
  pc.input = o.points;
  pc.format.clear();
  const std::vector<Vec2d> q = load_points2(pc);
  std::string text, rows = "[";
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (!locus::is_finite(q[i]))
      throw InputError(o.points + ": point " + std::to_string(i) + " is not finite");
    const locus::Side s = t.classify(q[i]);
    const char* name = s == locus::Side::inside     ? "inside"
                       : s == locus::Side::boundary ? "boundary"
                                                    : "outside";
    text += std::string(name) + '\n';
    rows += (i ? "," : "") + json_string(name);
  }
  JsonObject j;
  j.str("command", "bsp classify")
      .integer("nodes", static_cast<std::int64_t>(t.nodes().size()))
      .integer("depth", t.depth())
      .raw("sides", rows + "]");
  emit(o.c, text, j);
}

struct BooleanOptions {
  Common c;
  std::string other;
  std::string op = "intersection";
};

void run_boolean(const BooleanOptions& o) {
  PolygonInput pa, pb;
  const Bsp2<double> a = load_tree(o.c, o.c.input, pa), b = load_tree(o.c, o.other, pb);
  const locus::Bsp2Op op = o.op == "union"        ? locus::Bsp2Op::union_
                           : o.op == "difference" ? locus::Bsp2Op::difference
                           : o.op == "xor"        ? locus::Bsp2Op::exclusive_or
                                                  : locus::Bsp2Op::intersection;
  const locus::Bsp2BooleanResult<double> r = locus::bsp2_boolean(op, a, b);
  require_ok(r.status, "bsp boolean");
  std::string text, loops = "[", segs = "[", pts = "[";
  locus::SvgWriter svg;
  std::uint32_t begin = 0;
  for (std::size_t k = 0; k < r.loop_ends.size(); ++k) {
    std::vector<Vec2d> ring;
    text += "LINESTRING (";
    loops += k ? ",[" : "[";
    for (std::uint32_t i = begin; i < r.loop_ends[k]; ++i) {
      const Vec2d v = r.edges[r.loop_edges[i]].end[0].point;
      ring.push_back(v);
      text += xy(v) + ", ";
      loops += (i > begin ? "," : "") + json_xy(v);
    }
    text += xy(ring[0]) + ")\n";
    loops += ']';
    svg.polyline(ring, result_style(), true);
    begin = r.loop_ends[k];
  }
  for (std::size_t k = 0; k < r.segments.size(); ++k) {
    const auto& s = r.segments[k];
    text += "LINESTRING (" + xy(s.end[0].point) + ", " + xy(s.end[1].point) + ")\n";
    segs += (k ? ",[" : "[") + json_xy(s.end[0].point) + "," + json_xy(s.end[1].point) + "]";
    svg.segment(s.end[0].point, s.end[1].point, result_style());
  }
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    text += "POINT (" + xy(r.points[k]) + ")\n";
    pts += (k ? "," : "") + json_xy(r.points[k]);
    svg.point(r.points[k], result_style());
  }
  for (const PolygonInput* p : {&pa, &pb}) {
    std::uint32_t b0 = 0;
    for (const std::uint32_t e : p->ring_ends) {
      svg.polyline(std::span<const Vec2d>(p->points).subspan(b0, e - b0), fill_style(), true);
      b0 = e;
    }
  }
  if (!o.c.svg.empty()) save_svg(o.c, svg);
  JsonObject j;
  j.str("command", "bsp boolean")
      .str("op", o.op)
      .integer("edges", static_cast<std::int64_t>(r.edges.size()))
      .boolean("closed", r.closed)
      .number("area", 0.5 * locus::bsp2_twice_area(r))
      .raw("loops", loops + "]")
      .raw("segments", segs + "]")
      .raw("points", pts + "]");
  emit(o.c, text, j);
}

}  // namespace

void register_bsp(CLI::App& app) {
  CLI::App* bsp = app.add_subcommand("bsp", "BSP trees of polygons: classify, boolean");
  bsp->require_subcommand(1);
  {
    auto o = std::make_shared<ClassifyOptions>();
    CLI::App* sub = bsp->add_subcommand("classify", "points against a polygon's BSP tree");
    add_common(sub, o->c, false, "the polygon: WKT (.wkt) or GeoJSON (.json .geojson)");
    sub->add_option("--points", o->points, "the points (.csv .xyz, as for hull)")->required();
    sub->footer(
        "Builds the BSP tree of the file's one polygon (holes allowed) and prints, for each\n"
        "point, inside, boundary or outside (exact).\n"
        "Example:\n  locus bsp classify room.wkt --points probes.csv");
    sub->callback([o] { run_classify(*o); });
  }
  {
    auto o = std::make_shared<BooleanOptions>();
    CLI::App* sub = bsp->add_subcommand("boolean", "boolean of two polygons through BSP trees");
    add_common(sub, o->c, true, "polygon A: WKT (.wkt) or GeoJSON (.json .geojson)");
    sub->add_option("other", o->other, "polygon B (same formats)")->required();
    sub->add_option("--op", o->op, "intersection (default), union, difference (A \\ B) or xor")
        ->check(CLI::IsMember({"intersection", "union", "difference", "xor"}));
    sub->footer(
        "Each file holds one polygon (holes as inner rings). Prints the result's boundary loops\n"
        "as closed WKT LINESTRINGs (interior on the left: counter-clockwise outer boundaries,\n"
        "clockwise holes), then, for an intersection, the parts where the polygons only touch:\n"
        "LINESTRING segments (shared edges) and POINTs. Crossing points are rounded; every\n"
        "decision is exact (bsp/bsp2_boolean.hpp).\n"
        "Example:\n  locus bsp boolean a.wkt b.wkt --op union --svg union.svg");
    sub->callback([o] { run_boolean(*o); });
  }
}

}  // namespace locus_cli
