// SPDX-License-Identifier: BSL-1.0
// locus curvehit: a line, ray or segment against a Bézier / B-spline / NURBS curve
// (intersection/line_curve.hpp, ray_curve.hpp, segment_curve.hpp), or two curves
// (intersection/curve_curve.hpp), by the algebraic, hierarchy, resultant or raster method, or the
// curve's self-intersections (intersection/curve_self.hpp).

#include "commands.hpp"
#include "io.hpp"

#include <locus/intersection/curve_curve.hpp>
#include <locus/intersection/curve_self.hpp>
#include <locus/intersection/line_curve.hpp>
#include <locus/intersection/ray_curve.hpp>
#include <locus/intersection/segment_curve.hpp>

#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace locus_cli {

namespace {

using AnyCurve = std::variant<locus::BezierCurve2<double>, locus::BSplineCurve2<double>,
                              locus::NurbsCurve2<double>>;

struct CurveHitOptions {
  Common c;
  int degree = -1;
  std::vector<double> knots, weights;
  std::vector<double> line, ray, segment;
  std::string other;
  std::string method = "algebraic";
  int cells = 256;
  bool self = false;
};

AnyCurve make_curve(std::vector<Vec2d> control, int degree, const std::vector<double>& knots,
                    const std::vector<double>& weights) {
  if (knots.empty()) return locus::BezierCurve2<double>{std::move(control)};
  if (weights.empty()) return locus::BSplineCurve2<double>{degree, std::move(control), knots};
  return locus::NurbsCurve2<double>{degree, std::move(control), weights, knots};
}

void run_curvehit(const CurveHitOptions& o) {
  const std::vector<Vec2d> control = load_points2(o.c);
  if (!o.knots.empty() && o.degree < 0) throw InputError("curvehit: --knots needs --degree");
  const AnyCurve curve = make_curve(control, o.degree, o.knots, o.weights);
  locus::CurveHitOptions opt;
  opt.raster_cells = o.cells;
  if (o.method == "algebraic")
    opt.method = locus::CurveMethod::algebraic;
  else if (o.method == "hierarchy")
    opt.method = locus::CurveMethod::hierarchy;
  else if (o.method == "raster")
    opt.method = locus::CurveMethod::raster;
  else if (o.method == "resultant")
    opt.method = locus::CurveMethod::resultant;
  else
    throw InputError("curvehit: --method must be algebraic, hierarchy, resultant or raster");
  const int given = int(!o.line.empty()) + int(!o.ray.empty()) + int(!o.segment.empty()) +
                    int(!o.other.empty()) + int(o.self);
  if (given != 1)
    throw InputError("curvehit: give exactly one of --line, --ray, --segment, --other, --self");
  locus::CurveHits2<double> r;
  std::vector<Vec2d> other_control;
  if (o.self) {
    r = std::visit([&](const auto& a) { return locus::self_intersection(a, opt); }, curve);
  } else if (!o.other.empty()) {
    Common oc = o.c;
    oc.input = o.other;
    oc.format.clear();
    other_control = load_points2(oc);
    const locus::BezierCurve2<double> b{other_control};
    r = std::visit([&](const auto& a) { return locus::intersection(a, b, opt); }, curve);
  } else {
    const std::vector<double>& v = !o.line.empty() ? o.line : !o.ray.empty() ? o.ray : o.segment;
    const Vec2d p{v[0], v[1]}, q{v[2], v[3]};
    r = std::visit(
        [&](const auto& a) {
          if (!o.line.empty()) return locus::intersection(locus::Line2d{p, q}, a, opt);
          if (!o.ray.empty()) return locus::intersection(locus::Ray2d{p, q}, a, opt);
          return locus::intersection(locus::Segment2d{p, q}, a, opt);
        },
        curve);
  }
  require_ok(r.status, "curvehit");
  std::string text = "kind " + std::string(locus::to_string(r.kind)) + '\n';
  std::string hits = "[";
  for (std::size_t i = 0; i < r.hits.size(); ++i) {
    const auto& h = r.hits[i];
    text += "hit " + num(h.point.x) + ' ' + num(h.point.y) + ' ' + num(h.param_a) + ' ' +
            num(h.param_b) + ' ' + std::to_string(h.multiplicity) + '\n';
    hits += std::string(i ? "," : "") + "{\"point\":" + json_vec<2>(h.point) +
            ",\"param_a\":" + json_number(h.param_a) + ",\"param_b\":" + json_number(h.param_b) +
            ",\"multiplicity\":" + std::to_string(h.multiplicity) + "}";
  }
  JsonObject j;
  j.str("command", "curvehit").str("kind", locus::to_string(r.kind)).raw("hits", hits + "]");
  emit(o.c, text, j);
  if (!o.c.svg.empty()) {
    locus::SvgWriter svg;
    const auto draw = [&svg](const auto& cv) {
      const auto dom = [&]() {
        if constexpr (requires { cv.knots; })
          return locus::domain(cv);
        else
          return locus::ParamDomain<double>{0.0, 1.0};
      }();
      svg.curve([&cv](double t) { return locus::point_at(cv, t); }, dom.min, dom.max, 200);
    };
    std::visit(draw, curve);
    if (!other_control.empty()) draw(locus::BezierCurve2<double>{other_control});
    for (const auto& h : r.hits) svg.point(h.point);
    save_svg(o.c, svg);
  }
}

}  // namespace

void register_curvehit(CLI::App& app) {
  auto o = std::make_shared<CurveHitOptions>();
  CLI::App* sub = app.add_subcommand(
      "curvehit", "a line, ray, segment or second curve against a Bezier/B-spline/NURBS curve");
  add_common(sub, o->c, true, "the curve's control points (2D points)");
  sub->add_option("--degree", o->degree, "B-spline / NURBS degree (with --knots)");
  sub->add_option("--knots", o->knots, "knot vector: a B-spline (Bezier without)");
  sub->add_option("--weights", o->weights, "weights: a NURBS curve (with --knots)");
  sub->add_option("--line", o->line, "ox oy dx dy: a line")->expected(4);
  sub->add_option("--ray", o->ray, "ox oy dx dy: a ray")->expected(4);
  sub->add_option("--segment", o->segment, "x0 y0 x1 y1: a segment")->expected(4);
  sub->add_option("--other", o->other, "a second curve: its Bezier control points");
  sub->add_flag("--self", o->self, "the curve's own double points (self-intersections)");
  sub->add_option("--method", o->method, "algebraic (default), hierarchy, resultant or raster");
  sub->add_option("--cells", o->cells, "raster grid cells along the longer side (256)");
  sub->footer(
      "Prints `kind` and `hit x y param_a param_b multiplicity` lines (param_a on the line,\n"
      "ray, segment or first curve; multiplicity 1 crossing, 2 tangency, 0 the ends of a\n"
      "shared stretch; with --self param_a < param_b are the two passes of a double point).\n"
      "Example:\n  locus curvehit cubic.csv --line 0 0 1 0.1\n"
      "  locus curvehit spline.csv --degree 3 --knots 0 0 0 0 1 2 2 2 2 --other b.csv\n"
      "  locus curvehit a.csv --other b.csv --method resultant\n"
      "  locus curvehit loop.csv --self");
  sub->callback([o] { run_curvehit(*o); });
}

}  // namespace locus_cli
