// SPDX-License-Identifier: BSL-1.0
// locus offset: inflate or deflate the polygons of a WKT or GeoJSON file and buffer its line
// strings and points (boolean/polygon_offset.hpp); the result as one WKT MULTIPOLYGON.

#include "commands.hpp"
#include "io.hpp"

#include <locus/boolean/polygon_offset.hpp>
#include <locus/io/geojson.hpp>
#include <locus/io/geometry.hpp>
#include <locus/io/wkt.hpp>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>

namespace locus_cli {

namespace {

struct OffsetCliOptions {
  Common c;
  double delta = 0;
  std::string join = "round";
  std::string end = "round";
  double miter_limit = 2.0;
  double arc_tolerance = 0.0;
  int grid_bits = 0;
};

std::string read_all(const std::string& path) {
  if (path == "-") {
    std::ostringstream s;
    s << std::cin.rdbuf();
    return s.str();
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Every geometry of the file: polygons, line strings and points.
std::vector<locus::Geometry2<double>> load_geometries(const Common& c) {
  std::string f = c.format;
  std::string name = c.input;
  std::transform(f.begin(), f.end(), f.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  const auto ends_with = [&name](std::string_view e) {
    return name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
  };
  if (f.empty() && ends_with(".wkt")) f = "wkt";
  if (f.empty() && (ends_with(".json") || ends_with(".geojson"))) f = "geojson";
  if (f == "json") f = "geojson";
  if (f != "wkt" && f != "geojson")
    throw UsageError(c.input + ": give a WKT (.wkt) or GeoJSON (.json .geojson) file, or " +
                     "--format wkt|geojson");
  const std::string bytes = read_all(c.input);
  auto r = f == "wkt" ? locus::parse_wkt<double>(bytes, c.input)
                      : locus::parse_geojson<double>(bytes, c.input);
  if (r.status != locus::Status::ok)
    throw InputError(r.message.empty() ? c.input + ": " + std::string(locus::to_string(r.status))
                                       : r.message);
  return std::move(r.geometries);
}

void run_offset(const OffsetCliOptions& o) {
  const auto geometries = load_geometries(o.c);
  locus::MultiPolygon2<double> region;
  std::vector<locus::Polyline<double, 2>> paths;
  for (const auto& g : geometries) {
    for (const auto& p : g.polygons) region.push_back(locus::to_polygon_with_holes(p));
    for (const auto& l : g.lines) {
      locus::Polyline<double, 2> path{l, false};
      // A line string ending where it starts is a closed path (joins everywhere, no caps).
      if (l.size() > 2 && l.front() == l.back()) {
        path.vertices.pop_back();
        path.closed = true;
      }
      paths.push_back(std::move(path));
    }
    for (const auto& p : g.points) paths.push_back({{p}, false});
  }
  if (region.empty() && paths.empty())
    throw InputError(o.c.input + ": no polygon, line string or point in the file");
  locus::OffsetOptions opt;
  opt.join = o.join == "miter"    ? locus::JoinType::miter
             : o.join == "square" ? locus::JoinType::square
                                  : locus::JoinType::round;
  opt.end = o.end == "butt"     ? locus::EndType::butt
            : o.end == "square" ? locus::EndType::square
                                : locus::EndType::round;
  opt.miter_limit = o.miter_limit;
  opt.arc_tolerance = o.arc_tolerance;
  opt.grid_bits = o.grid_bits;
  auto r = locus::offset(region, o.delta, opt);
  require_ok(r.status, o.c.input + " offset");
  if (!paths.empty()) {
    const auto lines = locus::offset_polylines(paths, o.delta, opt);
    require_ok(lines.status, o.c.input + " offset of its lines");
    if (region.empty()) {
      r = lines;
    } else {
      r = locus::boolean_union(r.polygons, lines.polygons, o.grid_bits);
      require_ok(r.status, o.c.input + " offset");
    }
  }
  locus::SvgWriter svg;
  draw_polygons(svg, r.polygons);
  for (const auto& p : region) {
    svg.polyline(p.outer.vertices, input_style(), true);
    for (const auto& h : p.holes) svg.polyline(h.vertices, input_style(), true);
  }
  for (const auto& p : paths) svg.polyline(p.vertices, input_style(), p.closed);
  JsonObject j;
  j.str("command", "offset").number("delta", o.delta).str("join", o.join).str("end", o.end);
  emit_polygons(o.c, r.polygons, r.grid, svg, std::move(j));
}

}  // namespace

void register_offset(CLI::App& app) {
  auto o = std::make_shared<OffsetCliOptions>();
  CLI::App* sub = app.add_subcommand(
      "offset", "inflate or deflate polygons, buffer line strings (WKT, GeoJSON)");
  add_common(sub, o->c, true, "polygons, line strings, points: WKT (.wkt) or GeoJSON");
  sub->add_option("--delta,-d", o->delta,
                  "offset distance: > 0 inflates, < 0 deflates polygons (lines use |delta|)")
      ->required();
  sub->add_option("--join", o->join, "round (default), miter or square")
      ->check(CLI::IsMember({"round", "miter", "square"}));
  sub->add_option("--end", o->end, "line string ends: round (default), square or butt")
      ->check(CLI::IsMember({"round", "square", "butt"}));
  sub->add_option("--miter-limit", o->miter_limit,
                  "largest miter length over |delta| (>= 1, default 2); square beyond it");
  sub->add_option("--arc-tolerance", o->arc_tolerance,
                  "largest gap between a round join's chords and its arc (default |delta|/1000)");
  sub->add_option("--grid-bits", o->grid_bits,
                  "snap-rounding grid: 2^-bits of the largest coordinate's power of two "
                  "(1..40, default 40)")
      ->check(CLI::Range(0, 40));
  sub->footer(
      "The polygons of the file are united (rings in any orientation) and offset; line strings\n"
      "(closed when the last point repeats the first) and points are buffered by |delta|.\n"
      "Prints the result as one WKT MULTIPOLYGON: outer rings counter-clockwise, holes\n"
      "clockwise, always valid.\n"
      "Example:\n  locus offset parcels.wkt --delta -2 --join miter --svg inner.svg");
  sub->callback([o] { run_offset(*o); });
}

}  // namespace locus_cli
