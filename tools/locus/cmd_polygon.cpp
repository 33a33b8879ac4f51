// SPDX-License-Identifier: BSL-1.0
// locus cdt, locus triangulate: triangulations of polygons with holes read from WKT or GeoJSON
// (delaunay/constrained_delaunay2.hpp, triangulate/ear_clipping.hpp, triangulate/monotone.hpp);
// locus trapezoids: the trapezoidal map of the polygons' edges with point location
// (triangulate/trapezoid_map.hpp).

#include "commands.hpp"
#include "io.hpp"

#include <locus/delaunay/constrained_delaunay2.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>
#include <locus/triangulate/trapezoid_map.hpp>

#include <algorithm>
#include <memory>

namespace locus_cli {

namespace {

// The triangles of every polygon, as indices into the points of all polygons in file order.
struct PolygonTriangles {
  std::vector<Vec2d> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

void draw_and_write(const Common& c, const std::vector<PolygonInput>& polygons,
                    const PolygonTriangles& t, JsonObject& j) {
  const std::span<const std::array<std::uint32_t, 3>> tris(t.triangles);
  j.integer("polygons", static_cast<std::int64_t>(polygons.size()))
      .integer("points", static_cast<std::int64_t>(t.points.size()))
      .raw("triangles", json_index_rows(tris));
  if (!c.svg.empty()) {
    locus::SvgWriter svg;
    for (const auto& tri : tris) {
      const std::array<Vec2d, 3> corners = {t.points[tri[0]], t.points[tri[1]], t.points[tri[2]]};
      svg.polygon(corners, fill_style());
    }
    for (const PolygonInput& p : polygons) {
      std::uint32_t begin = 0;
      for (const std::uint32_t end : p.ring_ends) {
        svg.polyline(std::span<const Vec2d>(p.points).subspan(begin, end - begin), result_style(),
                     true);
        begin = end;
      }
    }
    save_svg(c, svg);
  }
  if (is_mesh_name(c.output)) {
    if (tris.empty()) throw InputError(c.input + ": no triangles to write");
    std::vector<Vec3d> pts3;
    for (const Vec2d& p : t.points) pts3.push_back({p.x, p.y, 0.0});
    emit_mesh(c, triangle_mesh(pts3, tris));
    emit_json(c, j);
    return;
  }
  emit(c, index_rows(tris), j);
}

struct CdtOptions {
  Common c;
  bool all = false;
};

void run_cdt(const CdtOptions& o) {
  const std::vector<PolygonInput> polygons = load_polygons(o.c);
  // All rings of all polygons at once: the even-odd rule of triangulate_polygon() gives each
  // polygon's inside (holes and separate polygons alike).
  PolygonInput all;
  for (const PolygonInput& p : polygons) {
    const auto base = static_cast<std::uint32_t>(all.points.size());
    all.points.insert(all.points.end(), p.points.begin(), p.points.end());
    for (const std::uint32_t e : p.ring_ends) all.ring_ends.push_back(base + e);
  }
  locus::ConstrainedDelaunay2Result r;
  {
    Progress p("constrained Delaunay triangulation", all.points.size());
    r = locus::triangulate_polygon(std::span<const Vec2d>(all.points),
                                   std::span<const std::uint32_t>(all.ring_ends));
  }
  if (r.status == locus::Status::invalid_input && !r.rejected.empty()) {
    throw InputError(o.c.input +
                     ": constrained Delaunay triangulation: " + std::to_string(r.rejected.size()) +
                     " polygon edges cross others (the rings are not simple or intersect)");
  }
  require_ok(r.status, o.c.input + ": constrained Delaunay triangulation");
  PolygonTriangles t;
  t.points = all.points;
  for (std::size_t i = 0; i < r.triangles.size(); ++i) {
    if (o.all || r.inside[i]) t.triangles.push_back(r.triangles[i]);
  }
  JsonObject j;
  j.str("command", "cdt").integer("dimension", r.dimension);
  draw_and_write(o.c, polygons, t, j);
}

struct TriangulateOptions {
  Common c;
  std::string method = "ear";
};

void run_triangulate(const TriangulateOptions& o) {
  const std::vector<PolygonInput> polygons = load_polygons(o.c);
  PolygonTriangles t;
  Progress progress("polygon triangulation", polygons.size());
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const PolygonInput& p = polygons[k];
    const std::span<const Vec2d> pts(p.points);
    const std::span<const std::uint32_t> ends(p.ring_ends);
    const locus::PolygonTriangulation r = o.method == "monotone"
                                              ? locus::triangulate_monotone(pts, ends)
                                              : locus::triangulate_ear_clipping(pts, ends);
    require_ok(r.status, o.c.input + ": polygon " + std::to_string(k) + ": triangulation");
    const auto base = static_cast<std::uint32_t>(t.points.size());
    t.points.insert(t.points.end(), p.points.begin(), p.points.end());
    for (const auto& tri : r.triangles)
      t.triangles.push_back({base + tri[0], base + tri[1], base + tri[2]});
  }
  JsonObject j;
  j.str("command", "triangulate").str("method", o.method);
  draw_and_write(o.c, polygons, t, j);
}

struct TrapezoidOptions {
  Common c;
  std::string points;
};

std::string trapezoid_row(const locus::MapTrapezoid& t) {
  std::string s;
  for (const std::uint32_t x : {t.bottom, t.top, t.left, t.right})
    s += (s.empty() ? "" : " ") + (x == locus::trapezoid_unbounded ? "-1" : std::to_string(x));
  return s;
}

void run_trapezoids(const TrapezoidOptions& o) {
  const std::vector<PolygonInput> polygons = load_polygons(o.c);
  // Every ring's edges, numbered in file order; points as for cdt.
  std::vector<Vec2d> pts;
  std::vector<std::array<std::uint32_t, 2>> segs;
  for (const PolygonInput& p : polygons) {
    const auto base = static_cast<std::uint32_t>(pts.size());
    pts.insert(pts.end(), p.points.begin(), p.points.end());
    std::uint32_t b = 0;
    for (const std::uint32_t e : p.ring_ends) {
      for (std::uint32_t i = b; i < e; ++i)
        segs.push_back({base + i, base + (i + 1 < e ? i + 1 : b)});
      b = e;
    }
  }
  locus::TrapezoidMap2<double> map;
  const locus::Status st = map.build(std::span<const Vec2d>(pts), segs);
  if (st == locus::Status::invalid_topology)
    throw InputError(o.c.input + ": trapezoidal map: polygon edges cross or touch");
  require_ok(st, o.c.input + ": trapezoidal map");
  const auto traps = map.trapezoids();
  std::string text, rows = "[", located = "[";
  for (std::size_t i = 0; i < traps.size(); ++i) {
    const std::string r = trapezoid_row(traps[i]);
    rows += (i ? ",[" : "[") + std::string(r.begin(), r.end()) + "]";
    if (o.points.empty()) text += r + '\n';
  }
  for (char& ch : rows)
    if (ch == ' ') ch = ',';
  if (!o.points.empty()) {
    Common pc = o.c;
    pc.input = o.points;
    pc.format.clear();
    const std::vector<Vec2d> q = load_points2(pc);
    for (std::size_t i = 0; i < q.size(); ++i) {
      if (!locus::is_finite(q[i]))
        throw InputError(o.points + ": point " + std::to_string(i) + " is not finite");
      const std::uint32_t k = map.locate(q[i]);
      text += std::to_string(k) + " " + trapezoid_row(traps[k]) + '\n';
      located += (i ? "," : "") + std::to_string(k);
    }
  }
  if (!o.c.svg.empty()) {
    Vec2d lo = pts.front(), hi = pts.front();
    for (const Vec2d& p : pts) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    const Vec2d pad = 0.1 * (hi - lo) + Vec2d{1e-9, 1e-9};
    locus::SvgWriter svg;
    for (const auto& t : traps) {
      const auto c = locus::trapezoid_map_corners(
          std::span<const Vec2d>(pts), std::span<const std::array<std::uint32_t, 2>>(segs), t,
          lo - pad, hi + pad);
      svg.polygon(c, fill_style());
    }
    for (const auto& e : segs) svg.segment(pts[e[0]], pts[e[1]], result_style());
    save_svg(o.c, svg);
  }
  JsonObject j;
  j.str("command", "trapezoids")
      .integer("segments", static_cast<std::int64_t>(segs.size()))
      .integer("points", static_cast<std::int64_t>(pts.size()))
      .raw("trapezoids", rows + "]");
  if (!o.points.empty()) j.raw("located", located + "]");
  emit(o.c, text, j);
}

constexpr const char* polygon_help = "a polygon file: WKT (.wkt) or GeoJSON (.json .geojson)";

}  // namespace

void register_polygon(CLI::App& app) {
  {
    auto o = std::make_shared<CdtOptions>();
    CLI::App* sub = app.add_subcommand(
        "cdt", "constrained Delaunay triangulation of polygons with holes (WKT, GeoJSON)");
    add_common(sub, o->c, true, polygon_help);
    sub->add_flag("--all", o->all, "also list the triangles outside the polygons (the hull)");
    sub->footer(
        "Triangulates every polygon of the file with its edges as constraints (no Steiner\n"
        "points) and prints the triangles inside (even-odd rule) as index rows into the\n"
        "polygons' points in file order (rings without their closing point); -o tri.obj\n"
        "writes a mesh in the plane z = 0.\n"
        "Example:\n  locus cdt country.geojson --svg cdt.svg\n"
        "  echo 'POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))' | locus cdt - "
        "--format wkt");
    sub->callback([o] { run_cdt(*o); });
  }
  {
    auto o = std::make_shared<TriangulateOptions>();
    CLI::App* sub =
        app.add_subcommand("triangulate", "triangulation of polygons with holes (WKT, GeoJSON)");
    add_common(sub, o->c, true, polygon_help);
    sub->add_option("--method", o->method, "ear (ear clipping, default) or monotone")
        ->check(CLI::IsMember({"ear", "monotone"}));
    sub->footer(
        "Triangulates each polygon of the file (outer ring and holes) by ear clipping or by\n"
        "monotone decomposition; prints the triangles as index rows into the polygons' points\n"
        "in file order (rings without their closing point); -o tri.obj writes a mesh.\n"
        "Example:\n  locus triangulate floorplan.wkt --svg tri.svg\n"
        "  locus triangulate lakes.geojson --method monotone -o lakes.obj");
    sub->callback([o] { run_triangulate(*o); });
  }
  {
    auto o = std::make_shared<TrapezoidOptions>();
    CLI::App* sub = app.add_subcommand(
        "trapezoids", "trapezoidal map of polygon edges, with point location (WKT, GeoJSON)");
    add_common(sub, o->c, true, polygon_help);
    sub->add_option("--points", o->points, "query points to locate (.csv .xyz, as for hull)");
    sub->footer(
        "Builds the horizontal trapezoidal map of every ring edge of the file's polygons\n"
        "(Seidel's incremental algorithm, exact) and prints one trapezoid per line: bottom top\n"
        "left right, the points whose heights bound it and the edges bounding it, -1 where\n"
        "unbounded. Points are numbered as for cdt, edges in file order (edge i starts at point\n"
        "i). With --points, prints instead for each query point the index of the trapezoid\n"
        "holding it and that trapezoid.\n"
        "Example:\n  locus trapezoids floorplan.wkt --svg map.svg\n"
        "  locus trapezoids floorplan.wkt --points probes.csv --json");
    sub->callback([o] { run_trapezoids(*o); });
  }
}

}  // namespace locus_cli
