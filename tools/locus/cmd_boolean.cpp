// SPDX-License-Identifier: BSL-1.0
// locus boolean: intersection, union, difference and xor of two polygon files read from WKT or
// GeoJSON (boolean/polygon_boolean.hpp); the result as one WKT MULTIPOLYGON.

#include "commands.hpp"
#include "io.hpp"

#include <locus/boolean/polygon_boolean.hpp>
#include <locus/io/geometry.hpp>

#include <memory>
#include <utility>

namespace locus_cli {

namespace {

struct BooleanOptions {
  Common c;
  std::string clip;
  std::string op = "union";
  int grid_bits = 0;
};

locus::MultiPolygon2<double> as_multipolygon(const std::vector<PolygonInput>& in) {
  locus::MultiPolygon2<double> m;
  for (const PolygonInput& p : in) m.push_back(locus::to_polygon_with_holes(p));
  return m;
}

void run_boolean(const BooleanOptions& o) {
  const std::vector<PolygonInput> a = load_polygons(o.c);
  Common clip = o.c;
  clip.input = o.clip;
  const std::vector<PolygonInput> b = load_polygons(clip);
  const locus::BooleanOp op = o.op == "intersection" ? locus::BooleanOp::intersection
                              : o.op == "difference" ? locus::BooleanOp::difference
                              : o.op == "xor"        ? locus::BooleanOp::symmetric_difference
                                                     : locus::BooleanOp::union_;
  const auto r = locus::boolean_op(op, as_multipolygon(a), as_multipolygon(b), o.grid_bits);
  require_ok(r.status, o.c.input + " " + o.op + " " + o.clip);
  locus::SvgWriter svg;
  draw_polygons(svg, r.polygons);
  for (const auto* in : {&a, &b})
    for (const PolygonInput& p : *in) {
      std::uint32_t begin = 0;
      for (const std::uint32_t end : p.ring_ends) {
        svg.polyline(std::span<const Vec2d>(p.points).subspan(begin, end - begin), input_style(),
                     true);
        begin = end;
      }
    }
  JsonObject j;
  j.str("command", "boolean").str("op", o.op);
  emit_polygons(o.c, r.polygons, r.grid, svg, std::move(j));
}

}  // namespace

void register_boolean(CLI::App& app) {
  auto o = std::make_shared<BooleanOptions>();
  CLI::App* sub = app.add_subcommand(
      "boolean", "intersection, union, difference, xor of polygons (WKT, GeoJSON)");
  add_common(sub, o->c, true, "the first operand: WKT (.wkt) or GeoJSON (.json .geojson)");
  sub->add_option("clip", o->clip, "the second operand: WKT or GeoJSON")->required();
  sub->add_option("--op", o->op, "intersection, union (default), difference (A minus B) or xor")
      ->check(CLI::IsMember({"intersection", "union", "difference", "xor"}));
  sub->add_option("--grid-bits", o->grid_bits,
                  "snap-rounding grid: 2^-bits of the largest coordinate's power of two "
                  "(1..40, default 40)")
      ->check(CLI::Range(0, 40));
  sub->footer(
      "Each operand is the union of the polygons of its file (rings in any orientation).\n"
      "Prints the result as one WKT MULTIPOLYGON: outer rings counter-clockwise, holes\n"
      "clockwise, always valid (crossings are snap rounded to the grid).\n"
      "Example:\n  locus boolean a.wkt b.geojson --op difference --svg diff.svg");
  sub->callback([o] { run_boolean(*o); });
}

}  // namespace locus_cli
