// SPDX-License-Identifier: BSL-1.0
// locus mincircle, minsphere, minrect, minbox: smallest enclosing shapes of point files
// (bounding/min_circle.hpp, min_sphere.hpp, min_rect2.hpp, min_box3.hpp).

#include "commands.hpp"
#include "io.hpp"

#include <locus/bounding/min_box3.hpp>
#include <locus/bounding/min_circle.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/bounding/min_sphere.hpp>
#include <locus/io/svg_primitives.hpp>

#include <memory>

namespace locus_cli {

namespace {

template <int N>
std::string vec_text(const locus::Vec<double, N>& v) {
  std::string s;
  for (int i = 0; i < N; ++i) s += ' ' + num(v[i]);
  return s;
}

std::string support_text(std::span<const std::uint32_t> s) {
  std::string t = "support";
  for (const std::uint32_t i : s) t += ' ' + std::to_string(i);
  return t + '\n';
}

// Status limit_exceeded still carries a valid enclosing shape: reported, not an error.
void require_result(locus::Status s, const std::string& what) {
  if (s != locus::Status::limit_exceeded) require_ok(s, what);
}

void run_mincircle(const Common& c) {
  const std::vector<Vec2d> pts = load_points2(c);
  locus::MinCircleResult<double> r;
  {
    Progress p("smallest enclosing circle", pts.size());
    r = locus::min_circle(std::span<const Vec2d>(pts));
  }
  require_result(r.status, c.input + ": smallest enclosing circle");
  const std::span<const std::uint32_t> support(r.support.data(),
                                               static_cast<std::size_t>(r.support_count));
  JsonObject j;
  j.str("command", "mincircle")
      .str("status", locus::to_string(r.status))
      .raw("center", json_vec<2>(r.circle.center))
      .number("radius", r.circle.radius)
      .raw("support", json_indices(support));
  emit(c,
       "center" + vec_text<2>(r.circle.center) + "\nradius " + num(r.circle.radius) + '\n' +
           support_text(support),
       j);
  if (!c.svg.empty()) {
    locus::SvgWriter svg;
    locus::draw(svg, r.circle, result_style());
    for (const Vec2d& p : pts) svg.point(p, input_style());
    locus::SvgStyle s = result_style();
    s.fill = s.stroke;
    for (const std::uint32_t i : support) svg.point(pts[i], s);
    save_svg(c, svg);
  }
}

void run_minsphere(const Common& c) {
  const std::vector<Vec3d> pts = load_points3(c);
  locus::MinSphereResult<double> r;
  {
    Progress p("smallest enclosing sphere", pts.size());
    r = locus::min_sphere(std::span<const Vec3d>(pts));
  }
  require_result(r.status, c.input + ": smallest enclosing sphere");
  const std::span<const std::uint32_t> support(r.support.data(),
                                               static_cast<std::size_t>(r.support_count));
  JsonObject j;
  j.str("command", "minsphere")
      .str("status", locus::to_string(r.status))
      .raw("center", json_vec<3>(r.sphere.center))
      .number("radius", r.sphere.radius)
      .raw("support", json_indices(support));
  emit(c,
       "center" + vec_text<3>(r.sphere.center) + "\nradius " + num(r.sphere.radius) + '\n' +
           support_text(support),
       j);
}

struct MinRectOptions {
  Common c;
  bool perimeter = false;
};

void run_minrect(const MinRectOptions& o) {
  const std::vector<Vec2d> pts = load_points2(o.c);
  locus::MinRectResult<double> r;
  {
    Progress p("minimum enclosing rectangle", pts.size());
    r = locus::min_rect(std::span<const Vec2d>(pts),
                        o.perimeter ? locus::RectCriterion::perimeter : locus::RectCriterion::area);
  }
  require_ok(r.status, o.c.input + ": minimum enclosing rectangle");
  const auto& rect = r.rectangle;
  JsonObject j;
  j.str("command", "minrect")
      .raw("center", json_vec<2>(rect.center))
      .raw("axis0", json_vec<2>(rect.axis[0]))
      .raw("axis1", json_vec<2>(rect.axis[1]))
      .raw("extent", json_vec<2>(rect.extent))
      .number("area", r.area)
      .number("perimeter", r.perimeter)
      .raw("edge", json_indices(r.edge));
  emit(o.c,
       "center" + vec_text<2>(rect.center) + "\naxis0" + vec_text<2>(rect.axis[0]) + "\naxis1" +
           vec_text<2>(rect.axis[1]) + "\nextent" + vec_text<2>(rect.extent) + "\narea " +
           num(r.area) + "\nperimeter " + num(r.perimeter) + "\nedge " + std::to_string(r.edge[0]) +
           ' ' + std::to_string(r.edge[1]) + '\n',
       j);
  if (!o.c.svg.empty()) {
    locus::SvgWriter svg;
    locus::draw(svg, rect, result_style());
    for (const Vec2d& p : pts) svg.point(p, input_style());
    save_svg(o.c, svg);
  }
}

void run_minbox(const Common& c) {
  const std::vector<Vec3d> pts = load_points3(c);
  locus::MinBoxResult<double> r;
  {
    Progress p("minimum enclosing box", pts.size());
    r = locus::min_box(std::span<const Vec3d>(pts));
  }
  require_result(r.status, c.input + ": minimum enclosing box");
  const auto& b = r.box;
  JsonObject j;
  j.str("command", "minbox")
      .str("status", locus::to_string(r.status))
      .raw("center", json_vec<3>(b.center))
      .raw("axis0", json_vec<3>(b.axis[0]))
      .raw("axis1", json_vec<3>(b.axis[1]))
      .raw("axis2", json_vec<3>(b.axis[2]))
      .raw("extent", json_vec<3>(b.extent))
      .number("volume", r.volume)
      .boolean("certified", r.certified);
  emit(c,
       "center" + vec_text<3>(b.center) + "\naxis0" + vec_text<3>(b.axis[0]) + "\naxis1" +
           vec_text<3>(b.axis[1]) + "\naxis2" + vec_text<3>(b.axis[2]) + "\nextent" +
           vec_text<3>(b.extent) + "\nvolume " + num(r.volume) + "\ncertified " +
           (r.certified ? "yes" : "no") + '\n',
       j);
}

}  // namespace

void register_bounding(CLI::App& app) {
  {
    auto o = std::make_shared<Common>();
    CLI::App* sub = app.add_subcommand("mincircle", "smallest circle enclosing a 2D point file");
    add_common(sub, *o, true, "2D points (.csv .txt .tsv; '-' reads CSV from stdin)");
    sub->footer(
        "Prints the centre, the radius and the input indices of the support points (numbers\n"
        "in the shortest form that reads back to the same double).\n"
        "Example:\n  locus mincircle points.csv --svg circle.svg");
    sub->callback([o] { run_mincircle(*o); });
  }
  {
    auto o = std::make_shared<Common>();
    CLI::App* sub = app.add_subcommand("minsphere", "smallest sphere enclosing a 3D point file");
    add_common(sub, *o, false, "3D points (.csv .txt .tsv .xyz, or a mesh's vertices)");
    sub->footer(
        "Prints the centre, the radius and the input indices of the support points.\n"
        "Example:\n  locus minsphere bunny.ply --json");
    sub->callback([o] { run_minsphere(*o); });
  }
  {
    auto o = std::make_shared<MinRectOptions>();
    CLI::App* sub =
        app.add_subcommand("minrect", "minimum-area rectangle enclosing a 2D point file");
    add_common(sub, o->c, true, "2D points (.csv .txt .tsv; '-' reads CSV from stdin)");
    sub->add_flag("--perimeter", o->perimeter, "minimise the perimeter instead of the area");
    sub->footer(
        "Prints the centre, the unit axes, the half extents, the area, the perimeter and the\n"
        "input indices of the hull edge the rectangle is flush with.\n"
        "Example:\n  locus minrect points.csv --svg rect.svg");
    sub->callback([o] { run_minrect(*o); });
  }
  {
    auto o = std::make_shared<Common>();
    CLI::App* sub = app.add_subcommand("minbox", "minimum-volume box enclosing a 3D point file");
    add_common(sub, *o, false, "3D points (.csv .txt .tsv .xyz, or a mesh's vertices)");
    sub->footer(
        "Prints the centre, the unit axes, the half extents, the volume and whether the\n"
        "branch and bound certified the volume minimal (bounding/min_box3.hpp).\n"
        "Example:\n  locus minbox part.stl");
    sub->callback([o] { run_minbox(*o); });
  }
}

}  // namespace locus_cli
