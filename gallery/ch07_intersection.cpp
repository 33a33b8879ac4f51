// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 7: intersection in 2D of linear components and curves. Figure 7.1 (a line
// against an arc: the circle points and which of them lie on the arc), 7.5 (ellipse and
// parabola), 7.6 (the three relations of two circles), 7.7-7.9 (contained, transverse and
// separated ellipses) and 7.10 (two ellipses meeting in four points). Every point and every
// relation drawn is what intersection() / relation() return; a figure fails when the count or
// the relation is not the one the configuration has.
#include "gallery.hpp"

#include <locus/intersection/circle_circle.hpp>
#include <locus/intersection/ellipse_ellipse.hpp>
#include <locus/intersection/ellipse_quadratic_curve.hpp>
#include <locus/intersection/line_arc.hpp>
#include <locus/intersection/line_circle.hpp>
#include <locus/primitives/quadratic_curve.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

std::string relation_name(RegionRelation r) {
  switch (r) {
    case RegionRelation::separated:
      return "separated";
    case RegionRelation::touching:
      return "touching";
    case RegionRelation::overlapping:
      return "overlapping";
    case RegionRelation::a_contains_b:
      return "E0 contains E1";
    case RegionRelation::b_contains_a:
      return "E1 contains E0";
    case RegionRelation::a_contains_b_touching:
      return "contains, touching";
    case RegionRelation::b_contains_a_touching:
      return "contained, touching";
    case RegionRelation::equal:
      return "equal";
    case RegionRelation::undecided:
      return "undecided";
  }
  return "?";
}

void draw_ellipse(SvgWriter& w, const Ellipse2d& e, const char* col) {
  w.ellipse(e.center, e.axis[0], e.extent[0], e.extent[1], pen(col, 2));
}

// 7.1: the arc from A to B (counter-clockwise), a line crossing the circle at P (on the arc)
// and Q (on the rest of the circle).
bool fig_7_1(SvgWriter& w) {
  const Arc2d arc{{{0, 0}, 2}, 0.35, 2.3};
  const Line2d line{{-2.4, -1.6}, {1, 0.9}};
  const auto on_circle = intersection(line, arc.circle);
  const auto on_arc = intersection(line, arc);
  w.circle(arc.circle.center, arc.circle.radius, dashed(c::gray));
  w.arc(arc.circle.center, arc.circle.radius, arc.start, arc.start + arc.sweep, pen(c::blue, 3));
  const Vec2d a = start_point(arc), b = end_point(arc);
  w.line(a, b - a, dashed(c::gray, 1));
  point(w, a, "A");
  point(w, b, "B");
  w.line(line.origin, line.direction, pen(c::black, 1.5));
  for (int i = 0; i < on_circle.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    bool kept = false;
    for (int j = 0; j < on_arc.count; ++j)
      kept = kept || on_arc.point[static_cast<std::size_t>(j)] == on_circle.point[k];
    point(w, on_circle.point[k], kept ? "P" : "Q", kept ? c::green : c::red);
  }
  return on_circle.count == 2 && on_arc.count == 1;
}

// 7.5: an ellipse and the parabola y = x^2 - 3 (four points).
bool fig_7_5(SvgWriter& w) {
  const Ellipse2d e{{0, 0}, {{1, 0}, {0, 1}}, {4, 2}};
  const QuadraticCurve2d parabola{1, 0, 0, 0, -1, -3};
  const auto r = intersection(e, parabola);
  draw_ellipse(w, e, c::blue);
  w.curve([](double x) { return Vec2d{x, x * x - 3}; }, -2.6, 2.6, 100, pen(c::orange, 2));
  for (int i = 0; i < r.count; ++i) point(w, r.point[static_cast<std::size_t>(i)], "", c::red);
  w.text(Vec2d{-4, -3.6}, std::to_string(r.count) + " points (ellipse-quadratic curve)",
         text_style(c::black, 0, 0));
  return r.count == 4;
}

// 7.6: (a) |u| = r0 + r1, (b) |u| = r0 - r1, (c) crossing; exact tangencies from (3, 4, 5).
bool fig_7_6(SvgWriter& w) {
  struct Case {
    Circle2d a, b;
    RegionRelation expect;
    const char* name;
  };
  const Case cases[3] = {
      {{{0, 0}, 2}, {{3, 4}, 3}, RegionRelation::touching, "(a)"},
      {{{20, 0}, 10}, {{23, 4}, 5}, RegionRelation::a_contains_b_touching, "(b)"},
      {{{40, 0}, 3}, {{43, 1}, 2.5}, RegionRelation::overlapping, "(c)"}};
  bool ok = true;
  for (const Case& k : cases) {
    const auto r = intersection(k.a, k.b);
    const RegionRelation rel = relation(k.a, k.b);
    ok = ok && rel == k.expect;
    w.circle(k.a.center, k.a.radius, pen(c::blue, 2));
    w.circle(k.b.center, k.b.radius, pen(c::green, 2));
    w.arrow(k.a.center, k.b.center, pen(c::gray, 1));
    for (int i = 0; i < r.count; ++i) point(w, r.point[static_cast<std::size_t>(i)], "", c::red);
    w.text(k.a.center + Vec2d{-3, -11}, std::string(k.name) + " " + relation_name(rel),
           text_style(c::black, 0, 0));
  }
  return ok;
}

bool ellipse_pair(SvgWriter& w, const Ellipse2d& e0, const Ellipse2d& e1, RegionRelation expect,
                  int points) {
  const auto r = intersection(e0, e1);
  const RegionRelation rel = relation(e0, e1);
  draw_ellipse(w, e0, c::blue);
  draw_ellipse(w, e1, c::green);
  label(w, e0.center, "E0", c::blue);
  label(w, e1.center, "E1", c::green);
  for (int i = 0; i < r.count; ++i) point(w, r.point[static_cast<std::size_t>(i)], "", c::red);
  w.text(Vec2d{-5, -4}, relation_name(rel) + ", " + std::to_string(r.count) + " points",
         text_style(c::black, 0, 0));
  return rel == expect && r.count == points;
}

const Vec2d u30{std::sqrt(3.0) / 2, 0.5};

// 7.7: E1 contained in E0.
bool fig_7_7(SvgWriter& w) {
  return ellipse_pair(w, {{0, 0}, {{1, 0}, {0, 1}}, {5, 3}}, {{0.8, 0.4}, {u30, perp(u30)}, {2, 1}},
                      RegionRelation::a_contains_b, 0);
}
// 7.8: E1 crosses E0 transversely.
bool fig_7_8(SvgWriter& w) {
  return ellipse_pair(w, {{0, 0}, {{1, 0}, {0, 1}}, {5, 3}}, {{4, 2}, {u30, perp(u30)}, {2.5, 1}},
                      RegionRelation::overlapping, 2);
}
// 7.9: E1 separated from E0.
bool fig_7_9(SvgWriter& w) {
  return ellipse_pair(w, {{0, 0}, {{1, 0}, {0, 1}}, {5, 3}}, {{7, 3.5}, {u30, perp(u30)}, {2, 1}},
                      RegionRelation::separated, 0);
}
// 7.10: two ellipses meeting in four points.
bool fig_7_10(SvgWriter& w) {
  return ellipse_pair(w, {{0, 0}, {{1, 0}, {0, 1}}, {5, 2}}, {{0.5, 0}, {u30, perp(u30)}, {1.5, 4}},
                      RegionRelation::overlapping, 4);
}

}  // namespace

std::vector<Figure> chapter7_intersection_figures() {
  return {
      {"7.1", "intersection(Line2, Circle2), intersection(Line2, Arc2)", fig_7_1},
      {"7.5", "intersection(Ellipse2, QuadraticCurve2)", fig_7_5},
      {"7.6", "intersection(Circle2, Circle2), relation(Circle2, Circle2)", fig_7_6},
      {"7.7", "relation(Ellipse2, Ellipse2)", fig_7_7},
      {"7.8", "intersection(Ellipse2, Ellipse2), relation", fig_7_8},
      {"7.9", "relation(Ellipse2, Ellipse2)", fig_7_9},
      {"7.10", "intersection(Ellipse2, Ellipse2)", fig_7_10},
  };
}

}  // namespace locus_gallery
