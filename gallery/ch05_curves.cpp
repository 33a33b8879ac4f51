// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 5 (polynomial curves): figures 5.17 (cubic Bézier curve) and 5.18 (cubic
// B-spline curve). Curve points come from locus::point_at (de Casteljau / de Boor), the de
// Casteljau construction from locus::subdivide, the knot vector from locus::open_uniform_knots.
#include "gallery.hpp"

#include <locus/curves/bezier.hpp>
#include <locus/curves/bspline.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

std::string fmt(double x, int prec = 2) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, x);
  return buf;
}

// 5.17: a cubic Bézier curve, its control polygon, and de Casteljau's construction at t = 0.4:
// the level-k points are the degree-k Bézier curves of k + 1 consecutive control points
// evaluated at t (locus::point_at), and the last one is C(t).
bool fig_5_17(SvgWriter& w) {
  const BezierCurve2<double> bez{{{0, 0}, {0.8, 2.2}, {3.0, 2.4}, {3.6, 0.4}}};
  w.polyline(bez.control, dashed(c::gray));
  std::vector<Vec2d> pts;
  for (int i = 0; i <= 96; ++i) pts.push_back(point_at(bez, i / 96.0));
  w.polyline(pts, pen(c::blue, 2.2));
  const char* names[] = {"P\u2080", "P\u2081", "P\u2082", "P\u2083"};
  for (std::size_t i = 0; i < 4; ++i) point(w, bez.control[i], names[i]);
  const double t = 0.4;
  const char* level_colour[] = {c::orange, c::green};
  for (std::size_t k = 1; k <= 2; ++k) {
    std::vector<Vec2d> level;
    for (std::size_t i = 0; i + k < 4; ++i) {
      const BezierCurve2<double> sub{
          std::vector<Vec2d>(bez.control.begin() + static_cast<std::ptrdiff_t>(i),
                             bez.control.begin() + static_cast<std::ptrdiff_t>(i + k + 1))};
      level.push_back(point_at(sub, t));
    }
    w.polyline(level, pen(level_colour[k - 1], 1.2));
    for (const Vec2d& p : level) w.point(p, dot(level_colour[k - 1], 2.8));
  }
  // The split curve meets at the same point: locus::subdivide's halves share C(t).
  const BezierSplit<double, 2> halves = subdivide(bez, t);
  if (halves.first.control.empty() || halves.second.control.empty()) return false;
  point(w, halves.first.control.back(), "C(" + fmt(t, 1) + ")", c::red);
  return true;
}

// 5.18: a cubic B-spline with an open uniform knot vector; the knots' images split the curve
// into its polynomial pieces.
bool fig_5_18(SvgWriter& w) {
  const std::vector<Vec2d> ctrl{{0, 0},     {0.6, 1.8}, {1.8, 2.2}, {2.4, 0.6},
                                {3.6, 0.2}, {4.2, 1.9}, {5.4, 2.0}};
  const int degree = 3;
  BSplineCurve2<double> bs{degree, ctrl,
                           open_uniform_knots<double>(static_cast<int>(ctrl.size()), degree)};
  if (validate(bs) != Status::ok) return false;
  w.polyline(bs.control, dashed(c::gray));
  const ParamDomain<double> dom = domain(bs);
  std::vector<Vec2d> pts;
  for (int i = 0; i <= 160; ++i)
    pts.push_back(point_at(bs, dom.min + (dom.max - dom.min) * i / 160.0));
  w.polyline(pts, pen(c::blue, 2.2));
  for (std::size_t i = 0; i < ctrl.size(); ++i) point(w, ctrl[i], "P" + std::to_string(i));
  for (std::size_t k = static_cast<std::size_t>(degree);
       k + static_cast<std::size_t>(degree) < bs.knots.size(); ++k) {
    const Vec2d p = point_at(bs, bs.knots[k]);
    w.point(p, dot(c::red, 3.5));
    label(w, p, "t = " + fmt(bs.knots[k]), c::red, 4, -16);
  }
  return true;
}

}  // namespace

std::vector<Figure> chapter5_curve_figures() {
  return {
      {"5.17", "BezierCurve2 point_at (de Casteljau) of the curve and its sub-polygons, subdivide",
       fig_5_17},
      {"5.18", "BSplineCurve2 open_uniform_knots, validate, domain, point_at (de Boor)", fig_5_18},
  };
}

}  // namespace locus_gallery
