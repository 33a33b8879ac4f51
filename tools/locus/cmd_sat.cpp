// SPDX-License-Identifier: BSL-1.0
// locus sat: two convex polygons by separating axes (intersection/convex_polygon2.hpp): whether
// they meet and their common set; with --tmax, moving polygons (intersection/moving_convex2.hpp):
// the first time of contact and the contact set.

#include "commands.hpp"
#include "io.hpp"

#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/moving_convex2.hpp>

#include <memory>
#include <string>
#include <vector>

namespace locus_cli {

namespace {

struct SatOptions {
  Common c;
  std::string other;
  std::vector<double> va{0, 0}, vb{0, 0};
  double tmax = -1;
};

std::string points_text(const char* tag, std::span<const Vec2d> p) {
  std::string s;
  for (const Vec2d& x : p) s += std::string(tag) + ' ' + num(x.x) + ' ' + num(x.y) + '\n';
  return s;
}

std::string points_json(std::span<const Vec2d> p) {
  std::string s = "[";
  for (std::size_t i = 0; i < p.size(); ++i) s += (i ? "," : "") + json_vec<2>(p[i]);
  return s + "]";
}

void run_sat(const SatOptions& o) {
  const std::vector<Vec2d> a = load_points2(o.c);
  Common oc = o.c;
  oc.input = o.other;
  oc.format.clear();
  const std::vector<Vec2d> b = load_points2(oc);
  if (a.empty()) throw InputError(o.c.input + ": convex polygon: empty_input");
  if (b.empty()) throw InputError(o.other + ": convex polygon: empty_input");
  JsonObject j;
  j.str("command", "sat");
  std::string text;
  std::vector<Vec2d> set;
  if (o.tmax < 0) {
    const auto r = locus::convex_polygon_intersection(a, b);
    set = r.vertices;
    text = std::string("intersects ") + (r.kind != locus::Kind::empty ? "yes" : "no") + "\nkind " +
           std::string(locus::to_string(r.kind)) + '\n' + points_text("vertex", set);
    j.boolean("intersects", r.kind != locus::Kind::empty)
        .str("kind", locus::to_string(r.kind))
        .raw("vertices", points_json(set));
  } else {
    const Vec2d va{o.va[0], o.va[1]}, vb{o.vb[0], o.vb[1]};
    const auto r = locus::first_contact_convex_polygons(a, va, b, vb, o.tmax);
    set.assign(r.point.begin(), r.point.begin() + r.count);
    text = std::string("kind ") + std::string(locus::to_string(r.kind)) + '\n';
    if (r) text += "time " + num(r.time) + '\n';
    text += points_text("point", set);
    j.str("kind", locus::to_string(r.kind)).raw("points", points_json(set));
    if (r) j.number("time", r.time);
  }
  emit(o.c, text, j);
  if (!o.c.svg.empty()) {
    locus::SvgWriter svg;
    svg.polygon(a, locus::SvgStyle{});
    svg.polygon(b, locus::SvgStyle{});
    if (set.size() >= 3) svg.polygon(set, locus::SvgStyle{});
    if (set.size() == 2) svg.segment(set[0], set[1]);
    if (set.size() == 1) svg.point(set[0]);
    save_svg(o.c, svg);
  }
}

}  // namespace

void register_sat(CLI::App& app) {
  auto o = std::make_shared<SatOptions>();
  CLI::App* sub = app.add_subcommand(
      "sat", "two convex polygons: do they meet, their common set; moving: first contact");
  add_common(sub, o->c, true, "the first convex polygon's vertices (2D points, either order)");
  sub->add_option("--other", o->other, "the second convex polygon's vertices")->required();
  sub->add_option("--va", o->va, "velocity of the first polygon (with --tmax)")->expected(2);
  sub->add_option("--vb", o->vb, "velocity of the second polygon (with --tmax)")->expected(2);
  sub->add_option("--tmax", o->tmax, "moving polygons over [0, tmax]: first contact");
  sub->footer(
      "Prints `intersects yes|no`, `kind` (empty, point, segment, polygon) and the set's\n"
      "`vertex x y` lines; with --tmax: `kind`, `time` of first contact and `point x y` lines.\n"
      "Example:\n  locus sat a.csv --other b.csv\n"
      "  locus sat a.csv --other b.csv --va 1 0 --vb -1 0 --tmax 10");
  sub->callback([o] { run_sat(*o); });
}

}  // namespace locus_cli
