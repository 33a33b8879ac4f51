// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 5 (geometric primitives): linear components, triangles, rectangles,
// polylines, monotone chains, quadratic curves, circles and ellipses. Points on the primitives
// come from their locus parametrisations (point_at, point_at_barycentric, point_at_arc_length),
// implicit sides from locus::evaluate, classifications from locus::orientation,
// is_monotone_chain and classify_conic; conic zero sets are contoured from locus::evaluate.
#include "gallery.hpp"

#include <locus/core/angle.hpp>
#include <locus/io/svg_primitives.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/polygon.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/quadratic_curve.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <span>
#include <string>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;
using locus::SvgMarker;

std::string fmt(double x, int prec = 2) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, x);
  return buf;
}

// 5.1: (a) a line, (b) a ray, (c) a segment, with their parameters 0 and 1 marked.
bool fig_5_1(SvgWriter& w) {
  w.set_view(Vec2d{-3, -4.2}, Vec2d{3, 0.6});
  const Line2<double> line{{-0.8, 0}, {1.0, 0.15}};
  const Ray<double, 2> ray{{-0.8, -1.8}, {1.0, 0.15}};
  const Segment<double, 2> seg{{-0.8, -3.6}, {1.2, -3.3}};
  draw(w, line, pen(c::blue));
  draw(w, ray, pen(c::blue));
  draw(w, seg, pen(c::blue));
  point(w, point_at(line, 0.0), "t = 0");
  point(w, point_at(line, 1.0), "t = 1");
  point(w, point_at(ray, 0.0), "t = 0");
  point(w, point_at(ray, 1.0), "t = 1");
  point(w, point_at(seg, 0.0), "t = 0");
  point(w, point_at(seg, 1.0), "t = 1");
  label(w, Vec2d{-2.9, 0.2}, "(a)");
  label(w, Vec2d{-2.9, -1.6}, "(b)");
  label(w, Vec2d{-2.9, -3.4}, "(c)");
  return true;
}

// 5.2: the implicit line n . X + c = 0 (locus::to_implicit); sample points coloured by the sign
// of locus::evaluate.
bool fig_5_2(SvgWriter& w) {
  const Line2<double> line{{0.5, 0.2}, {1.0, 0.6}};
  const auto imp = to_implicit(line);
  if (!imp) return false;
  w.set_view(Vec2d{-2, -2}, Vec2d{2.5, 2});
  draw(w, line, pen(c::black, 2));
  for (int i = 0; i <= 9; ++i)
    for (int j = 0; j <= 8; ++j) {
      const Vec2d p{-2 + 0.5 * i, -2 + 0.5 * j};
      const double v = evaluate(*imp, p);
      if (v != 0) w.point(p, dot(v > 0 ? c::red : c::blue, 2.2));
    }
  // The foot of the origin on the line: -c n / |n|^2.
  const Vec2d foot = imp->normal * (-imp->c / dot(imp->normal, imp->normal));
  w.arrow(foot, foot + normalize(imp->normal), pen(c::red, 2));
  label(w, foot + normalize(imp->normal), "n (n\u00b7X + c > 0)", c::red);
  label(w, Vec2d{0.6, -1.8}, "n\u00b7X + c < 0", c::blue, 0, 0);
  return true;
}

// 5.3: the two orderings of a triangle, classified by locus::orientation.
bool fig_5_3(SvgWriter& w) {
  const Vec2d a{0, 0}, b{2, 0.2}, cc{0.8, 1.6};
  const Triangle2<double> t1{a, b, cc};
  const Vec2d off{3, 0};
  const Triangle2<double> t2{a + off, cc + off, b + off};
  for (const Triangle2<double>* t : {&t1, &t2}) {
    const std::array<Vec2d, 3> v{t->v0, t->v1, t->v2};
    draw(w, *t, filled(c::gray, 0.1, 0.8));
    for (std::size_t i = 0; i < 3; ++i) {
      const Vec2d p = v[i], q = v[(i + 1) % 3];
      w.arrow(lerp(p, q, 0.1), lerp(p, q, 0.9), pen(c::blue, 1.6));
    }
    point(w, t->v0, "V\u2080");
    point(w, t->v1, "V\u2081");
    point(w, t->v2, "V\u2082");
    const Sign s = orientation(*t);
    label(w, centroid(*t) + Vec2d{0, -1.0},
          s == Sign::positive   ? "counterclockwise"
          : s == Sign::negative ? "clockwise"
                                : "degenerate",
          c::black, 0, 0);
  }
  return true;
}

// Domain (left) and range (right) of a parametrisation, drawn as the images of grid lines.
void domain_range(SvgWriter& w, const std::function<Vec2d(double, double)>& f, bool triangle,
                  const Vec2d& range_off) {
  const int n = 4;
  for (int k = 0; k <= n; ++k) {
    const double s = static_cast<double>(k) / n;
    const double t_max = triangle ? 1 - s : 1;
    w.segment(Vec2d{s, 0}, Vec2d{s, t_max}, pen(c::light, 1));
    w.segment(Vec2d{0, s}, Vec2d{triangle ? 1 - s : 1, s}, pen(c::light, 1));
    w.segment(range_off + f(s, 0), range_off + f(s, t_max), pen(c::light, 1));
    w.segment(range_off + f(0, s), range_off + f(triangle ? 1 - s : 1, s), pen(c::light, 1));
  }
  std::vector<Vec2d> dom{{0, 0}, {1, 0}};
  if (!triangle) dom.push_back({1, 1});
  dom.push_back({0, 1});
  std::vector<Vec2d> rng;
  for (const Vec2d& d : dom) rng.push_back(range_off + f(d.x, d.y));
  closed(w, dom, pen(c::blue));
  closed(w, rng, pen(c::red));
  label(w, Vec2d{1, 0}, "s", c::blue);
  label(w, Vec2d{0, 1}, "t", c::blue);
  // One sample point and its image.
  const Vec2d q{0.25, 0.5};
  point(w, q, "(s, t)", c::blue);
  point(w, range_off + f(q.x, q.y), "X(s, t)", c::red);
}

// 5.4: the parametric triangle (locus::point_at(triangle, st)).
bool fig_5_4(SvgWriter& w) {
  const Triangle2<double> t{{0, 0}, {2.2, 0.6}, {0.6, 1.8}};
  domain_range(
      w,
      [&](double s, double u) {
        return point_at(t, Vec2d{s, u});
      },
      true, Vec2d{1.8, -0.2});
  return true;
}

// 5.5: the barycentric form (locus::point_at_barycentric): iso-lines of each coordinate.
bool fig_5_5(SvgWriter& w) {
  const Triangle2<double> t{{0, 0}, {2.4, 0.4}, {0.8, 2.0}};
  for (int k = 1; k < 4; ++k) {
    const double u = k / 4.0;
    for (int axis = 0; axis < 3; ++axis) {
      Vec3d b0{}, b1{};
      b0[axis] = u;
      b1[axis] = u;
      b0[(axis + 1) % 3] = 1 - u;
      b1[(axis + 2) % 3] = 1 - u;
      w.segment(point_at_barycentric(t, b0), point_at_barycentric(t, b1), pen(c::light, 1));
    }
  }
  draw(w, t, pen(c::red));
  point(w, t.v0, "P\u2080 = (1, 0, 0)");
  point(w, t.v1, "P\u2081 = (0, 1, 0)");
  point(w, t.v2, "P\u2082 = (0, 0, 1)");
  const Vec3d b{0.5, 0.25, 0.25};
  point(w, point_at_barycentric(t, b), "(0.5, 0.25, 0.25)", c::blue);
  return true;
}

// 5.6: the parametric rectangle (locus::point_at(CornerRectangle, st)).
bool fig_5_6(SvgWriter& w) {
  const CornerRectangle<double, 2> r{{0, 0}, {2.0, 0.7}, {-0.5, 1.4}};
  domain_range(
      w,
      [&](double s, double u) {
        return point_at(r, Vec2d{s, u});
      },
      false, Vec2d{2.2, -0.3});
  return true;
}

// 5.7: the symmetric rectangle: centre, unit axes, extents; corners by locus::corners.
bool fig_5_7(SvgWriter& w) {
  const Vec2d u = normalize(Vec2d{1, 0.4});
  const Rectangle<double, 2> r{{1, 1}, {u, perp(u)}, {1.6, 0.8}};
  draw(w, r, filled(c::blue, 0.1));
  vector(w, r.center, r.center + r.extent[0] * r.axis[0], "e\u2080 u\u2080", c::red, -12);
  vector(w, r.center, r.center + r.extent[1] * r.axis[1], "e\u2081 u\u2081", c::green);
  point(w, r.center, "C");
  for (const Vec2d& k : corners(r)) w.point(k, dot(c::black, 2.5));
  return true;
}

// 5.8: a polyline with points every quarter of its length (locus::point_at_arc_length).
bool fig_5_8(SvgWriter& w) {
  const Polyline2<double> pl{{{0, 0}, {1, 1.2}, {2.2, 0.8}, {2.6, 2.0}, {3.8, 1.6}, {4.4, 0.2}},
                             false};
  draw(w, pl, pen(c::blue));
  for (const Vec2d& v : pl.vertices) w.point(v, dot(c::blue, 3));
  const double len = length(pl);
  for (int k = 0; k <= 4; ++k) {
    const Vec2d p = point_at_arc_length(pl, len * k / 4.0);
    w.point(p, dot(c::red, 4));
    label(w, p, "s = " + fmt(k / 4.0) + "L", c::red, 6, -16);
  }
  return true;
}

std::string yes_no(bool b, const char* what) { return std::string(b ? "" : "not ") + what; }

// 5.9: (a) a simple concave polygon, (b) a simple convex polygon (locus::is_simple, is_convex).
bool fig_5_9(SvgWriter& w) {
  const Polygon2<double> a{{{0, 0}, {2.4, 0.2}, {2.0, 1.6}, {1.2, 0.8}, {0.3, 1.8}}};
  const Polygon2<double> b{{{3.4, 0}, {5.4, 0.3}, {5.9, 1.3}, {4.6, 2.0}, {3.3, 1.2}}};
  for (const Polygon2<double>* p : {&a, &b}) {
    draw(w, *p, filled(c::blue, 0.15));
    for (const Vec2d& v : p->vertices) w.point(v, dot(c::blue, 3));
    label(w, p->vertices[0] + Vec2d{0, -0.45},
          std::string(p == &a ? "(a) " : "(b) ") + yes_no(is_simple(*p), "simple") + ", " +
              yes_no(is_convex(*p), "convex"),
          c::black, 0, 0);
  }
  return true;
}

// 5.10: nonsimple polygons: (a) two edges cross, (b) two edges meet at a vertex. The offending
// edge pair is the one locus::self_intersection reports.
bool fig_5_10(SvgWriter& w) {
  const Polygon2<double> a{
      {{0, 0}, {2.2, 0}, {2.2, 1.6}, {1.4, 1.6}, {1.4, -0.6}, {0.4, -0.6}, {0.4, 1.2}}};
  const Polygon2<double> b{{{3.4, 0}, {4.4, 0.8}, {5.4, 0}, {5.4, 1.8}, {4.4, 0.8}, {3.4, 1.8}}};
  for (const Polygon2<double>* p : {&a, &b}) {
    draw(w, *p, filled(c::blue, 0.15));
    const auto hit = self_intersection(*p);
    const std::size_t n = p->vertices.size();
    if (hit) {
      for (std::size_t e : {hit->first, hit->second})
        w.segment(p->vertices[e], p->vertices[(e + 1) % n], pen(c::red, 3));
    }
    label(w, Vec2d{p->vertices[0].x, -1.1},
          std::string(p == &a ? "(a) " : "(b) ") + yes_no(is_simple(*p), "simple") +
              (hit ? ": red edges meet" : ""),
          c::black, 0, 0);
  }
  return true;
}

// 5.12: a polygon monotone in x, split into its two chains by locus::monotone_split:
// squares on one chain, triangles on the other, circles on both.
bool fig_5_12(SvgWriter& w) {
  const Polygon2<double> p{{{0, 0.8},
                            {0.8, 0.1},
                            {1.6, 0.6},
                            {2.5, 0.0},
                            {3.4, 0.5},
                            {4.2, 1.2},
                            {3.3, 1.9},
                            {2.4, 1.4},
                            {1.5, 2.2},
                            {0.7, 1.6}}};
  const MonotoneSplit ms = monotone_split(p, Vec2d{1, 0});
  if (!ms.monotone) return false;
  draw(w, p, filled(c::gray, 0.1, 1.4));
  const std::size_t n = p.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    SvgStyle s = dot(c::blue, 4.5);
    if (i == ms.min_vertex || i == ms.max_vertex) {
      s = dot(c::black, 5);
    } else {
      // Walking from min_vertex with increasing index reaches i before max_vertex: first chain.
      const std::size_t from_min = (i + n - ms.min_vertex) % n,
                        to_max = (ms.max_vertex + n - ms.min_vertex) % n;
      s.marker = from_min < to_max ? SvgMarker::square : SvgMarker::triangle;
      s.fill = s.stroke = from_min < to_max ? c::blue : c::red;
    }
    w.point(p.vertices[i], s);
  }
  label(w, Vec2d{0, -0.5},
        yes_no(is_monotone(p, Vec2d{1, 0}), "monotone") + " with respect to the x axis", c::black,
        0, 0);
  return true;
}

// 5.11: (a) a strictly monotone chain, (b) monotone but not strict (locus::is_monotone_chain
// with respect to the x axis).
bool fig_5_11(SvgWriter& w) {
  const std::vector<Vec2d> a{{0, 0}, {0.6, 1.0}, {1.2, 0.4}, {2.0, 1.3}, {2.6, 0.6}};
  const std::vector<Vec2d> b{{3.6, 0}, {4.2, 1.0}, {4.2, 0.4}, {5.0, 1.3}, {5.6, 1.3}, {6.2, 0.6}};
  const Vec2d d{1, 0};
  for (const auto* ch : {&a, &b}) {
    w.polyline(*ch, pen(c::blue));
    for (const Vec2d& p : *ch) w.point(p, dot(c::blue, 3));
    const bool strict = is_monotone_chain(std::span<const Vec2d>(*ch), d, true);
    const bool mono = is_monotone_chain(std::span<const Vec2d>(*ch), d, false);
    label(w, (*ch)[0] + Vec2d{0, -0.5},
          std::string(ch == &a ? "(a) " : "(b) ") + (strict ? "strictly monotonic"
                                                     : mono ? "monotonic, not strict"
                                                            : "not monotonic"),
          c::black, 0, 0);
  }
  return true;
}

// Marching squares on a scalar function: the zero set as segments.
void contour(SvgWriter& w, const std::function<double(const Vec2d&)>& f, const Vec2d& lo,
             const Vec2d& hi, int n, const SvgStyle& s) {
  const Vec2d step{(hi.x - lo.x) / n, (hi.y - lo.y) / n};
  std::vector<double> v(static_cast<std::size_t>((n + 1) * (n + 1)));
  auto at = [&](int i, int j) -> double& { return v[static_cast<std::size_t>(j * (n + 1) + i)]; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) at(i, j) = f(lo + Vec2d{i * step.x, j * step.y});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2d p[4] = {
          lo + Vec2d{i * step.x, j * step.y}, lo + Vec2d{(i + 1) * step.x, j * step.y},
          lo + Vec2d{(i + 1) * step.x, (j + 1) * step.y}, lo + Vec2d{i * step.x, (j + 1) * step.y}};
      const double f4[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      std::vector<Vec2d> cuts;
      for (int e = 0; e < 4; ++e) {
        const double a = f4[e], b = f4[(e + 1) % 4];
        if ((a < 0) != (b < 0)) cuts.push_back(lerp(p[e], p[(e + 1) % 4], a / (a - b)));
      }
      if (cuts.size() == 2) w.segment(cuts[0], cuts[1], s);
      if (cuts.size() == 4) {
        w.segment(cuts[0], cuts[1], s);
        w.segment(cuts[2], cuts[3], s);
      }
    }
}

// One panel per conic: its zero set and locus::classify_conic's verdict.
void conic_panels(SvgWriter& w,
                  const std::vector<std::pair<QuadraticCurve2<double>, std::string>>& qs) {
  const double size = 4.0;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    const Vec2d off{static_cast<double>(k % 3) * (size + 2.2),
                    -static_cast<double>(k / 3) * (size + 1.2)};
    const Vec2d lo = off + Vec2d{-size / 2, -size / 2}, hi = off + Vec2d{size / 2, size / 2};
    closed(w, std::vector<Vec2d>{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, pen(c::light, 1));
    w.segment(Vec2d{lo.x, off.y}, Vec2d{hi.x, off.y}, pen(c::light, 0.8));
    w.segment(Vec2d{off.x, lo.y}, Vec2d{off.x, hi.y}, pen(c::light, 0.8));
    const QuadraticCurve2<double> q = qs[k].first;
    contour(
        w, [&](const Vec2d& p) { return evaluate(q, p - off); }, lo, hi, 96, pen(c::blue, 2));
    const ConicKind kind = classify_conic(q);
    if (kind == ConicKind::point) {
      // The single point solves grad = 0: [2a b; b 2c] x = -(d, e).
      const auto inv = inverse(Mat2d::from_rows(Vec2d{2 * q.a, q.b}, Vec2d{q.b, 2 * q.c}));
      if (inv) w.point(off + *inv * Vec2d{-q.d, -q.e}, dot(c::blue, 4));
    }
    label(w, Vec2d{lo.x, lo.y - 0.35}, qs[k].second + ": " + std::string(to_string(kind)), c::black,
          0, 0);
  }
}

// 5.13: d0 x^2 + d1 y^2 = r with d0, d1 != 0.
bool fig_5_13(SvgWriter& w) {
  conic_panels(w, {{{1, 0, 2, 0, 0, -2}, "d\u2080,d\u2081>0, r>0"},
                   {{1, 0, 2, 0, 0, 0}, "d\u2080,d\u2081>0, r=0"},
                   {{1, 0, 2, 0, 0, 1}, "d\u2080,d\u2081>0, r<0"},
                   {{1, 0, -2, 0, 0, -1}, "d\u2080>0>d\u2081, r>0"},
                   {{1, 0, -2, 0, 0, 1}, "d\u2080>0>d\u2081, r<0"},
                   {{1, 0, -2, 0, 0, 0}, "d\u2080>0>d\u2081, r=0"}});
  return true;
}

// 5.14: d0 x^2 + e1 y = r (d1 = 0).
bool fig_5_14(SvgWriter& w) {
  conic_panels(w, {{{1, 0, 0, 0, -1, -0.5}, "e\u2081\u22600"},
                   {{1, 0, 0, 0, 0, -2}, "e\u2081=0, r/d\u2080>0"},
                   {{1, 0, 0, 0, 0, 2}, "e\u2081=0, r/d\u2080<0"}});
  return true;
}

// 5.15: the circle as |X - C| = r (locus::evaluate = 0) and as C + r (cos t, sin t).
bool fig_5_15(SvgWriter& w) {
  const Circle2<double> circ{{0, 0}, 1.5};
  draw(w, circ, pen(c::blue));
  const Circle2<double> c2{{4, 0}, 1.5};
  draw(w, c2, pen(c::blue));
  const Vec2d x = point_at(circ, 0.7);
  vector(w, circ.center, x, "r", c::red);
  point(w, circ.center, "C");
  point(w, x, "X: |X \u2212 C|\u00b2 \u2212 r\u00b2 = " + fmt(evaluate(circ, x), 3), c::red);
  for (int k = 0; k < 8; ++k) {
    const double t = 2 * pi_v<double> * k / 8;
    const Vec2d p = point_at(c2, t);
    w.point(p, dot(c::green, 3));
    const char* names[] = {"0",      "\u03c0/4",  "\u03c0/2",  "3\u03c0/4",
                           "\u03c0", "5\u03c0/4", "3\u03c0/2", "7\u03c0/4"};
    label(w, p, std::string("t = ") + names[k], c::green, 4, 4);
  }
  angle_mark(w, c2.center, Vec2d{1, 0}, point_at(c2, 2 * pi_v<double> / 8) - c2.center, 0.5, "t");
  point(w, c2.center, "C");
  return true;
}

// 5.16: the ellipse C + e0 cos(t) U0 + e1 sin(t) U1 (locus::point_at(Ellipse2, t)).
bool fig_5_16(SvgWriter& w) {
  const Vec2d u = normalize(Vec2d{1, 0.35});
  const Ellipse2<double> e{{0, 0}, {u, perp(u)}, {2.2, 1.2}};
  draw(w, e, pen(c::blue));
  vector(w, e.center, e.center + e.extent[0] * e.axis[0], "e\u2080U\u2080", c::red, -12);
  vector(w, e.center, e.center + e.extent[1] * e.axis[1], "e\u2081U\u2081", c::green);
  const double t = 2.2;
  const Vec2d x = point_at(e, t);
  const Vec2d a = e.center + e.extent[0] * std::cos(t) * e.axis[0];
  w.polyline(std::vector<Vec2d>{e.center, a, x}, dashed(c::gray));
  point(w, x, "X(t)", c::purple);
  point(w, e.center, "C");
  return true;
}

}  // namespace

std::vector<Figure> chapter5_primitive_figures() {
  return {
      {"5.1", "Line2/Ray/Segment point_at; SvgWriter line/ray clipping", fig_5_1},
      {"5.2", "to_implicit, evaluate(ImplicitLine2)", fig_5_2},
      {"5.3", "orientation(Triangle2) (exact)", fig_5_3},
      {"5.4", "point_at(Triangle, st)", fig_5_4},
      {"5.5", "point_at_barycentric", fig_5_5},
      {"5.6", "point_at(CornerRectangle, st)", fig_5_6},
      {"5.7", "Rectangle, corners", fig_5_7},
      {"5.8", "Polyline, length, point_at_arc_length", fig_5_8},
      {"5.9", "Polygon2 is_simple, is_convex", fig_5_9},
      {"5.10", "Polygon2 self_intersection, is_simple", fig_5_10},
      {"5.11", "is_monotone_chain (strict and not)", fig_5_11},
      {"5.12", "monotone_split, is_monotone", fig_5_12},
      {"5.13", "evaluate(QuadraticCurve2) contoured, classify_conic", fig_5_13},
      {"5.14", "evaluate(QuadraticCurve2) contoured, classify_conic", fig_5_14},
      {"5.15", "Circle2 point_at, evaluate", fig_5_15},
      {"5.16", "Ellipse2 point_at", fig_5_16},
  };
}

}  // namespace locus_gallery
