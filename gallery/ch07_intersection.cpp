// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 7: intersection in 2D of linear components and curves. Figure 7.1 (a line
// against an arc: the circle points and which of them lie on the arc), 7.5 (ellipse and
// parabola), 7.6 (the three relations of two circles), 7.7-7.9 (contained, transverse and
// separated ellipses), 7.10 (two ellipses meeting in four points) and the separating-axis
// figures 7.12-7.18 (stationary and moving convex polygons). Every point, overlap, contact and
// relation drawn is what intersection() / relation() / first_contact() return; 7.2-7.4 and
// 7.11 (a line and two cubic curves: the points found, the box hierarchy, the raster grids) are
// the results of intersection(Line2, BezierCurve2) / intersection(curve, curve) and
// curve_raster(); a figure fails
// when the count, kind or relation is not the one the configuration has.
#include "gallery.hpp"

#include <locus/core/predicates.hpp>
#include <locus/intersection/circle_circle.hpp>
#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/curve_curve.hpp>
#include <locus/intersection/ellipse_ellipse.hpp>
#include <locus/intersection/ellipse_quadratic_curve.hpp>
#include <locus/intersection/line_arc.hpp>
#include <locus/intersection/line_circle.hpp>
#include <locus/intersection/line_curve.hpp>
#include <locus/intersection/moving_convex2.hpp>
#include <locus/primitives/quadratic_curve.hpp>

#include <array>
#include <cmath>
#include <span>
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

// ---- separating axes (section 7.7) --------------------------------------------------------

using Poly = std::vector<Vec2d>;

/// An edge of p (counter-clockwise) with all of q strictly outside, as {start, end}; checked
/// with the same exact orient2d the library uses. Empty when there is none.
std::vector<Vec2d> separating_edge(const Poly& p, const Poly& q) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2d a = p[i], b = p[(i + 1) % p.size()];
    bool all_out = true;
    for (const Vec2d& x : q) all_out = all_out && orient2d(a, b, x) == Sign::negative;
    if (all_out) return {a, b};
  }
  return {};
}

/// [min, max] of dot(d, x) over the polygon.
std::array<double, 2> projection(const Poly& p, const Vec2d& d) {
  std::array<double, 2> r{dot(d, p[0]), dot(d, p[0])};
  for (const Vec2d& x : p) r[0] = std::min(r[0], dot(d, x)), r[1] = std::max(r[1], dot(d, x));
  return r;
}

void draw_set(SvgWriter& w, const ConvexIntersection2<double>& r) {
  if (r.kind == Kind::polygon) w.polygon(r.vertices, filled(c::red, 0.45));
  if (r.kind == Kind::segment) w.segment(r.vertices[0], r.vertices[1], pen(c::red, 4));
  if (r.kind == Kind::point) point(w, r.vertices[0], "", c::red);
}

Poly moved(const Poly& p, const Vec2d& v, double t) {
  Poly q = p;
  for (Vec2d& x : q) x += t * v;
  return q;
}

// 7.12: two separated convex polygons and a separating line (an edge line of the first).
bool fig_7_12(SvgWriter& w) {
  const Poly a{{0, 0}, {3, -0.5}, {4, 1.5}, {2, 3}, {0.3, 2.2}};
  const Poly b{{5.5, 1}, {8, 0.5}, {8.5, 3}, {6, 4}};
  const auto e = separating_edge(a, b);
  w.polygon(a, filled(c::blue));
  w.polygon(b, filled(c::green));
  if (!e.empty()) w.line(e[0], e[1] - e[0], dashed(c::black, 1.5));
  w.text(Vec2d{0, -1.8}, "intersects: false; dashed: a separating edge line",
         text_style(c::black, 0, 0));
  return !intersects_convex_polygons(a, b) && !e.empty();
}

// 7.13: (a) nonintersecting and (b) intersecting convex polygons (overlap from intersection).
bool fig_7_13(SvgWriter& w) {
  const Poly a{{0, 0}, {3, 0}, {3.5, 2}, {1, 3}};
  const Poly b{{4.2, 1}, {6.5, 0.5}, {6, 3}};
  const Poly c2{{8, 0}, {11, 0}, {11.5, 2}, {9, 3}};
  const Poly d{{10, 1}, {13, 0.5}, {12.5, 3.5}};
  w.polygon(a, filled(c::blue));
  w.polygon(b, filled(c::green));
  w.polygon(c2, filled(c::blue));
  w.polygon(d, filled(c::green));
  const auto r0 = convex_polygon_intersection(a, b), r1 = convex_polygon_intersection(c2, d);
  draw_set(w, r1);
  w.text(Vec2d{1, -1}, "(a) " + std::string(to_string(r0.kind)), text_style(c::black, 0, 0));
  w.text(Vec2d{9, -1}, "(b) " + std::string(to_string(r1.kind)), text_style(c::black, 0, 0));
  return r0.kind == Kind::empty && r1.kind == Kind::polygon;
}

// 7.14: (a) edge-edge, (b) vertex-edge and (c) vertex-vertex contact: the exact touching sets.
bool fig_7_14(SvgWriter& w) {
  const Triangle2d t{{0, 0}, {4, 0}, {0, 4}};
  const Triangle2d others[3] = {
      {{1, 3}, {3, 1}, {4, 4}}, {{2, 2}, {5, 3}, {3, 5}}, {{4, 0}, {6, 0}, {6, 2}}};
  const Kind expect[3] = {Kind::segment, Kind::point, Kind::point};
  const char* names[3] = {"(a) edge-edge", "(b) vertex-edge", "(c) vertex-vertex"};
  bool ok = true;
  for (int k = 0; k < 3; ++k) {
    const Vec2d off{8.0 * k, 0};
    const Triangle2d a{t.v0 + off, t.v1 + off, t.v2 + off};
    const Triangle2d b{others[k].v0 + off, others[k].v1 + off, others[k].v2 + off};
    const auto r = intersection(a, b);
    ok = ok && r.kind == expect[k];
    w.polygon(Poly{a.v0, a.v1, a.v2}, filled(c::blue));
    w.polygon(Poly{b.v0, b.v1, b.v2}, filled(c::green));
    if (r.kind == Kind::segment) w.segment(r.point[0], r.point[1], pen(c::red, 4));
    if (r.kind == Kind::point) point(w, r.point[0], "", c::red);
    w.text(off + Vec2d{0, -1}, names[k], text_style(c::black, 0, 0));
  }
  return ok;
}

/// Draws the edge normals of p at their edges' midpoints: green where the axis separates p and
/// q (their projections are disjoint), gray otherwise; returns how many separate.
int draw_normals(SvgWriter& w, const Poly& p, const Poly& q) {
  int n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2d a = p[i], b = p[(i + 1) % p.size()];
    const Vec2d d = normalize(Vec2d{b.y - a.y, a.x - b.x});
    const auto pa = projection(p, d), pb = projection(q, d);
    const bool sep = pa[1] < pb[0] || pb[1] < pa[0];
    n += sep;
    w.arrow(0.5 * (a + b), 0.5 * (a + b) + 1.2 * d, pen(sep ? c::green : c::gray, sep ? 2 : 1));
  }
  return n;
}

// 7.15: a separation direction D that is no edge normal; the edge normals that also separate
// come (a) from one triangle, (b) from both.
bool fig_7_15(SvgWriter& w) {
  bool ok = true;
  const Poly as[2] = {{{0, 0}, {3, 0}, {1, 2.5}}, {{10, 0}, {13, 0}, {11.5, 2}}};
  const Poly bs[2] = {{{1.5, 2}, {5, 4}, {3.5, 4.5}}, {{13.5, 2.8}, {15, 3.3}, {13.2, 4.2}}};
  for (int k = 0; k < 2; ++k) {
    const Poly& a = as[k];
    const Poly& b = bs[k];
    w.polygon(a, filled(c::blue));
    w.polygon(b, filled(c::green));
    const int na = draw_normals(w, a, b), nb = draw_normals(w, b, a);
    ok = ok && !intersects_convex_polygons(a, b) && na > 0 && (k == 0 ? nb == 0 : nb > 0);
    w.text(a[0] + Vec2d{0, -1}, k == 0 ? "(a) same triangle" : "(b) different triangles",
           text_style(c::black, 0, 0));
  }
  return ok;
}

// 7.16: separated by an edge normal of the first polygon: both projections onto that axis.
bool fig_7_16(SvgWriter& w) {
  const Poly a{{0, 0}, {3, 0}, {3.5, 2}, {1.5, 3}};
  const Poly b{{5, -1}, {7, 0}, {6, 2.5}, {4.5, 1.5}};
  const auto e = separating_edge(a, b);
  w.polygon(a, filled(c::blue));
  w.polygon(b, filled(c::green));
  if (e.empty()) return false;
  const Vec2d d = normalize(Vec2d{e[1].y - e[0].y, e[0].x - e[1].x});
  const Vec2d o{1, -3};  // the axis drawn through o
  w.line(o, d, dashed(c::gray, 1));
  const auto pa = projection(a, d), pb = projection(b, d);
  const double base = dot(d, o);
  w.segment(o + (pa[0] - base) * d, o + (pa[1] - base) * d, pen(c::blue, 4));
  w.segment(o + (pb[0] - base) * d, o + (pb[1] - base) * d, pen(c::green, 4));
  w.segment(e[0], e[1], pen(c::red, 3));
  return !intersects_convex_polygons(a, b) && (pa[1] < pb[0] || pb[1] < pa[0]);
}

/// A moving pair: the polygons at time 0 (filled) and at first contact (outlined), the
/// velocities, the contact set; returns its kind.
Kind moving_pair(SvgWriter& w, const Poly& a, const Vec2d& va, const Poly& b, const Vec2d& vb,
                 double tmax) {
  const auto r = first_contact_convex_polygons(a, va, b, vb, tmax);
  w.polygon(a, filled(c::blue));
  w.polygon(b, filled(c::green));
  w.arrow(a[0], a[0] + va, pen(c::blue, 1.5));
  w.arrow(b[0], b[0] + vb, pen(c::green, 1.5));
  const double t = r ? double(r.time) : tmax;
  w.polyline(moved(a, va, t), dashed(c::blue, 1.5), true);
  w.polyline(moved(b, vb, t), dashed(c::green, 1.5), true);
  if (r.kind == Kind::segment) w.segment(r.point[0], r.point[1], pen(c::red, 4));
  if (r.kind == Kind::point) point(w, r.point[0], "", c::red);
  const std::string what = r ? std::string(to_string(r.kind)) + " at t = " + std::to_string(t)
                             : std::string("no contact");
  w.text(a[0] + Vec2d{0, -1.2}, what, text_style(c::black, 0, 0));
  return r.kind;
}

// 7.17: predicted (a) edge-edge contact, (b) vertex-vertex contact, (c) no contact.
bool fig_7_17(SvgWriter& w) {
  const Poly sq{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const auto at = [](const Poly& p, const Vec2d& o) { return moved(p, o, 1.0); };
  const Kind k0 = moving_pair(w, sq, {0, 0}, at(sq, {5, 0.5}), {-1, 0}, 5);
  const Kind k1 = moving_pair(w, at(sq, {9, 0}), {0, 0}, at(sq, {13, 4}), {-1, -1}, 5);
  const Kind k2 = moving_pair(w, at(sq, {18, 0}), {0, 0}, at(sq, {22, 3}), {-1, 0.2}, 5);
  return k0 == Kind::segment && k1 == Kind::point && k2 == Kind::empty;
}

// 7.18: edge-edge contact of two moving triangles.
bool fig_7_18(SvgWriter& w) {
  const Poly a{{0, 0}, {3, 1}, {1, 3}};
  const Poly b{{6, 2}, {8, 4}, {4, 4}};
  return moving_pair(w, a, {0.5, 0.25}, b, {-1, -0.5}, 4) == Kind::segment;
}

// ---- polynomial curves (7.2-7.4, 7.11) ------------------------------------------------------
const BezierCurve2<double> cubic7{{{-3, -1}, {-1, 3}, {1, -3}, {3, 1}}};
const Line2d line7{{-3.5, -0.35}, {1, 0.1}};

void draw_bezier(SvgWriter& w, const BezierCurve2<double>& b, const char* col, bool polygon) {
  if (polygon) w.polyline(b.control, dashed(c::gray, 1));
  w.curve([&b](double t) { return point_at(b, t); }, 0, 1, 120, pen(col, 2.2));
}

// 7.2: a line and a cubic curve meeting in three points (the algebraic method).
bool fig_7_2(SvgWriter& w) {
  const auto r = intersection(line7, cubic7);
  draw_bezier(w, cubic7, c::blue, true);
  w.line(line7.origin, line7.direction, pen(c::black, 1.5));
  for (const auto& h : r.hits) point(w, h.point, "", c::red);
  w.text(Vec2d{-3.5, -3.4}, std::to_string(r.hits.size()) + " crossings (Bernstein roots)",
         text_style(c::black, 0, 0));
  return r.status == Status::ok && r.hits.size() == 3;
}

// 7.3: the bounding-box hierarchy: control-polygon boxes of the halves, quarters and eighths;
// those the line meets (both sides, by orient2d on the corners) are refined, the others dropped.
bool fig_7_3(SvgWriter& w) {
  std::vector<BezierCurve2<double>> level{cubic7};
  const char* cols[3] = {c::light, c::gray, c::orange};
  for (int depth = 0; depth < 3; ++depth) {
    std::vector<BezierCurve2<double>> next;
    for (const auto& b : level) {
      const auto bx = bounding_box(b);
      const std::array<Vec2d, 4> k{bx.min, Vec2d{bx.max.x, bx.min.y}, bx.max,
                                   Vec2d{bx.min.x, bx.max.y}};
      int pos = 0, neg = 0;
      for (const auto& q : k) {
        const Sign o = orient2d(line7.origin, line7.origin + line7.direction, q);
        pos += o == Sign::positive;
        neg += o == Sign::negative;
      }
      const bool meets = pos < 4 && neg < 4;
      w.polygon(std::vector<Vec2d>(k.begin(), k.end()),
                meets ? filled(cols[depth], 0.15, 1) : dashed(c::light, 0.8));
      if (!meets) continue;
      const auto halves = subdivide(b, 0.5);
      next.push_back(halves.first);
      next.push_back(halves.second);
    }
    level = std::move(next);
  }
  draw_bezier(w, cubic7, c::blue, false);
  w.line(line7.origin, line7.direction, pen(c::black, 1.5));
  CurveHitOptions o;
  o.method = CurveMethod::hierarchy;
  const auto r = intersection(line7, cubic7, o);
  for (const auto& h : r.hits) point(w, h.point, "", c::red);
  return r.hits.size() == 3 && !level.empty();
}

void draw_raster(SvgWriter& w, const CurveRaster2<double>& g) {
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const auto m = g.mask[static_cast<std::size_t>(j * g.nx + i)];
      if (m == 0) continue;
      const Vec2d lo = g.min + g.cell * Vec2d{double(i), double(j)};
      const std::vector<Vec2d> cell{lo, lo + Vec2d{g.cell, 0}, lo + Vec2d{g.cell, g.cell},
                                    lo + Vec2d{0, g.cell}};
      SvgStyle s = filled(m == 1   ? c::light
                          : m == 2 ? c::gray
                                   : c::orange,
                          m == 3 ? 0.8 : 0.5, 0.3);
      w.polygon(cell, s);
    }
}

// 7.4: the line and the curve rasterised (mask 1 light, 2 dark, both orange); the raster method
// refines each shared component by Newton.
bool fig_7_4(SvgWriter& w) {
  const auto bx = bounding_box(cubic7);
  // The line drawn across the curve's box, as the segment the raster method clips it to.
  const double s0 = (bx.min.x - line7.origin.x) / line7.direction.x;
  const double s1 = (bx.max.x - line7.origin.x) / line7.direction.x;
  const BezierCurve2<double> seg{{point_at(line7, s0), point_at(line7, s1)}};
  const auto g = curve_raster(seg, cubic7, 32);
  draw_raster(w, g);
  draw_bezier(w, cubic7, c::blue, false);
  w.line(line7.origin, line7.direction, pen(c::black, 1));
  CurveHitOptions o;
  o.method = CurveMethod::raster;
  o.raster_cells = 32;
  const auto r = intersection(line7, cubic7, o);
  for (const auto& h : r.hits) point(w, h.point, "", c::red);
  return g.status == Status::ok && r.hits.size() == 3;
}

// 7.11: two curves rasterised; shared cells seed Newton on A(s) = B(t).
bool fig_7_11(SvgWriter& w) {
  const BezierCurve2<double> other{{{-3, 2}, {-1, -4}, {2, 4}, {3, -2}}};
  const auto g = curve_raster(cubic7, other, 32);
  draw_raster(w, g);
  draw_bezier(w, cubic7, c::blue, false);
  draw_bezier(w, other, c::green, false);
  CurveHitOptions o;
  o.method = CurveMethod::raster;
  o.raster_cells = 32;
  const auto r = intersection(cubic7, other, o);
  const auto exact = intersection(cubic7, other);
  CurveHitOptions alg;
  alg.method = CurveMethod::resultant;
  const auto res = intersection(cubic7, other, alg);
  for (const auto& h : r.hits) point(w, h.point, "", c::red);
  w.text(Vec2d{-3, -4.6},
         std::to_string(r.hits.size()) + " points (raster), " + std::to_string(exact.hits.size()) +
             " (subdivision), " + std::to_string(res.hits.size()) + " (resultant, 7.4.1)",
         text_style(c::black, 0, 0));
  return g.status == Status::ok && !r.hits.empty() && r.hits.size() == exact.hits.size() &&
         res.hits.size() == exact.hits.size();
}

}  // namespace

std::vector<Figure> chapter7_intersection_figures() {
  return {
      {"7.1", "intersection(Line2, Circle2), intersection(Line2, Arc2)", fig_7_1},
      {"7.2", "intersection(Line2, BezierCurve2) (algebraic)", fig_7_2},
      {"7.3", "intersection(Line2, BezierCurve2) (hierarchy), subdivide, bounding_box", fig_7_3},
      {"7.4", "curve_raster, intersection(Line2, BezierCurve2) (raster)", fig_7_4},
      {"7.5", "intersection(Ellipse2, QuadraticCurve2)", fig_7_5},
      {"7.6", "intersection(Circle2, Circle2), relation(Circle2, Circle2)", fig_7_6},
      {"7.7", "relation(Ellipse2, Ellipse2)", fig_7_7},
      {"7.8", "intersection(Ellipse2, Ellipse2), relation", fig_7_8},
      {"7.9", "relation(Ellipse2, Ellipse2)", fig_7_9},
      {"7.10", "intersection(Ellipse2, Ellipse2)", fig_7_10},
      {"7.11", "curve_raster, intersection(BezierCurve2, BezierCurve2) (raster, resultant)",
       fig_7_11},
      {"7.12", "intersects_convex_polygons", fig_7_12},
      {"7.13", "convex_polygon_intersection", fig_7_13},
      {"7.14", "intersection(Triangle2, Triangle2)", fig_7_14},
      {"7.15", "intersects_convex_polygons (edge normals)", fig_7_15},
      {"7.16", "intersects_convex_polygons (edge-normal axis)", fig_7_16},
      {"7.17", "first_contact_convex_polygons", fig_7_17},
      {"7.18", "first_contact_convex_polygons (triangles)", fig_7_18},
  };
}

}  // namespace locus_gallery
