// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 8: miscellaneous 2D problems, the constructions of circles and lines
// (figures 8.1-8.34). Every circle and line drawn as a solution is what circle_through,
// circles_tangent_to, tangent_lines, circles_of_radius, normal_line, perpendicular_bisector,
// parallel_lines* or tangent_lines_normal_to return; the "insight" and "construction" figures draw
// the loci the solutions' centres lie on (parallels at distance r, circles of radius R +- r),
// themselves computed by parallel_lines. A figure fails when a count differs from the one the
// configuration has.
#include "gallery.hpp"

#include <locus/construct/circle_through.hpp>
#include <locus/construct/circles_of_radius.hpp>
#include <locus/construct/lines.hpp>
#include <locus/construct/tangent_lines.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

template <class S>
const auto& at(const S& s, int i) {
  return s.item[static_cast<std::size_t>(i)];
}

void draw_circles(SvgWriter& w, const auto& s, const char* col, bool centres = true) {
  for (int i = 0; i < s.count; ++i) {
    w.circle(at(s, i).center, at(s, i).radius, pen(col, 1.8));
    if (centres) point(w, at(s, i).center, "", col);
  }
}
void draw_lines(SvgWriter& w, const auto& s, const char* col) {
  for (int i = 0; i < s.count; ++i) w.line(at(s, i).origin, at(s, i).direction, pen(col, 1.6));
}
void caption_count(SvgWriter& w, const Vec2d& at_p, const std::string& what, int n) {
  w.text(at_p, what + ": " + std::to_string(n), text_style(c::black, 0, 0, SvgAnchor::start, 13));
}
void given_circle(SvgWriter& w, const Circle2d& k, const char* name) {
  w.circle(k.center, k.radius, pen(c::black, 2.2));
  label(w, k.center, name);
}
void given_line(SvgWriter& w, const Line2d& l, const char* name) {
  w.line(l.origin, l.direction, pen(c::black, 2.2));
  label(w, l.origin, name);
}
// The loci of the centres of radius-r circles tangent to k: radius R + r and |R - r|.
void circle_loci(SvgWriter& w, const Circle2d& k, double r) {
  w.circle(k.center, k.radius + r, dashed(c::gray));
  if (k.radius != r) w.circle(k.center, std::abs(k.radius - r), dashed(c::gray));
}
// The loci of the centres of radius-r circles tangent to l: its parallels at distance r.
bool line_loci(SvgWriter& w, const Line2d& l, double r) {
  const auto p = parallel_lines(l, r);
  for (int i = 0; i < p.count; ++i) w.line(at(p, i).origin, at(p, i).direction, dashed(c::gray));
  return p.count == 2;
}

// 8.1: the circle through three points.
bool fig_8_1(SvgWriter& w) {
  const Vec2d p0{0, 0}, p1{5, 1}, p2{1.5, 4};
  const auto s = circle_through(p0, p1, p2);
  draw_circles(w, s, c::blue);
  point(w, p0, "P0");
  point(w, p1, "P1");
  point(w, p2, "P2");
  return s.count == 1;
}

// 8.2: the lines of a triangle's edges; incircle and the three excircles.
bool fig_8_2(SvgWriter& w) {
  const Line2d l0{{0, 0}, {4, 0}}, l1{{4, 0}, {-2.5, 3}}, l2{{1.5, 3}, {-1.5, -3}};
  const auto s = circles_tangent_to(l0, l1, l2);
  w.set_view({-9, -9}, {15, 12});
  given_line(w, l0, "L0");
  given_line(w, l1, "L1");
  given_line(w, l2, "L2");
  if (s.count > 0) w.circle(at(s, 0).center, at(s, 0).radius, pen(c::blue, 2));
  for (int i = 1; i < s.count; ++i) w.circle(at(s, i).center, at(s, i).radius, pen(c::green, 1.5));
  return s.count == 4;
}

// 8.3: the tangent at a point of the circle.
bool fig_8_3(SvgWriter& w) {
  const Circle2d k{{0, 0}, 2};
  const Vec2d p = point_at(k, 0.7);
  const auto t = tangent_line_at(k, p);
  given_circle(w, k, "C");
  draw_lines(w, t, c::red);
  point(w, p, "P", c::red);
  return t.count == 1;
}

// 8.4: the two tangents through an outside point.
bool fig_8_4(SvgWriter& w) {
  const Circle2d k{{0, 0}, 2};
  const Vec2d p{5, 1.5};
  const auto t = tangent_lines(p, k);
  given_circle(w, k, "C");
  draw_lines(w, t, c::red);
  for (int i = 0; i < t.count; ++i) point(w, at(t, i).origin, "", c::red);
  point(w, p, "P");
  return t.count == 2;
}

// 8.5: outside (two), on the circle (one), inside (none).
bool fig_8_5(SvgWriter& w) {
  bool ok = true;
  const Vec2d ps[3] = {{4.5, 1}, {0, 2}, {0.5, 0.5}};
  const int want[3] = {2, 1, 0};
  for (int i = 0; i < 3; ++i) {
    const Circle2d k{{10.0 * i, 0}, 2};
    const Vec2d p = k.center + ps[i];
    const auto t = tangent_lines(p, k);
    given_circle(w, k, "");
    for (int j = 0; j < t.count; ++j)
      w.segment(at(t, j).origin - 3.0 * at(t, j).direction,
                at(t, j).origin + 6.0 * at(t, j).direction, pen(c::red, 1.6));
    point(w, p, "P");
    caption_count(w, k.center + Vec2d{-2, -3.5}, "tangents", t.count);
    ok = ok && t.count == want[i];
  }
  return ok;
}

// 8.6: the four common tangents of two separate circles.
bool fig_8_6(SvgWriter& w) {
  const Circle2d a{{0, 0}, 2}, b{{7, 1}, 1.2};
  const auto t = tangent_lines(a, b);
  w.set_view({-5, -6}, {12, 7});
  given_circle(w, a, "C0");
  given_circle(w, b, "C1");
  draw_lines(w, t, c::red);
  return t.count == 4;
}

// 8.7: 4, 3 (touching outside), 2 (crossing), 1 (touching inside), 0 (nested); exact ties from
// the 3-4-5 triangle.
bool fig_8_7(SvgWriter& w) {
  const double rb[5] = {1.5, 3, 4, 7, 8.5};
  const int want[5] = {4, 3, 2, 1, 0};
  bool ok = true;
  for (int i = 0; i < 5; ++i) {
    const Vec2d o{26.0 * i, 0};
    const Circle2d a{o, 2}, b{o + Vec2d{3, 4}, rb[i]};
    const auto t = tangent_lines(a, b);
    given_circle(w, a, "");
    given_circle(w, b, "");
    for (int j = 0; j < t.count; ++j)
      w.segment(at(t, j).origin - 10.0 * at(t, j).direction,
                at(t, j).origin + 10.0 * at(t, j).direction, pen(c::red, 1.4));
    caption_count(w, o + Vec2d{-4, -11}, "tangents", t.count);
    ok = ok && t.count == want[i];
  }
  return ok;
}

// 8.8-8.10: circles of radius r through two points; 8.10 adds the perpendicular bisector the
// centres lie on.
bool two_points(SvgWriter& w, int show, bool bisector) {
  const Vec2d p{0, 0}, q{3, 1};
  const double r = 2.2;
  const auto s = circles_of_radius(p, q, r);
  for (int i = 0; i < std::min(show, s.count); ++i) {
    w.circle(at(s, i).center, r, pen(i == 0 ? c::blue : c::green, 1.8));
    point(w, at(s, i).center, i == 0 ? "C0" : "C1", i == 0 ? c::blue : c::green);
  }
  if (bisector) {
    const auto b = perpendicular_bisector(p, q);
    draw_lines(w, b, c::gray);
    w.segment(p, q, dashed(c::gray));
  }
  point(w, p, "P");
  point(w, q, "Q");
  return s.count == 2;
}
bool fig_8_8(SvgWriter& w) { return two_points(w, 1, false); }
bool fig_8_9(SvgWriter& w) { return two_points(w, 2, false); }
bool fig_8_10(SvgWriter& w) { return two_points(w, 2, true); }

// 8.11, 8.12: through a point, tangent to a line.
bool point_line(SvgWriter& w, int show) {
  const Line2d l{{-3, 0}, {1, 0.15}};
  const Vec2d p{0.5, 1.5};
  const auto s = circles_of_radius(p, l, 1.3);
  given_line(w, l, "L");
  for (int i = 0; i < std::min(show, s.count); ++i) {
    w.circle(at(s, i).center, at(s, i).radius, pen(i == 0 ? c::blue : c::green, 1.8));
    point(w, at(s, i).center, "", i == 0 ? c::blue : c::green);
  }
  point(w, p, "P");
  return s.count == 2;
}
bool fig_8_11(SvgWriter& w) { return point_line(w, 1); }
bool fig_8_12(SvgWriter& w) { return point_line(w, 2); }

// 8.13: P on the line (mirrored pair) and P beyond the diameter (none).
bool fig_8_13(SvgWriter& w) {
  const Line2d l{{-3, 0}, {1, 0}}, m{{9, 0}, {1, 0}};
  const Vec2d p{0, 0}, q{13, 3};
  const auto s = circles_of_radius(p, l, 1.2), t = circles_of_radius(q, m, 1.2);
  given_line(w, Line2d{{-3, 0}, {1, 0}}, "L");
  draw_circles(w, s, c::blue);
  point(w, p, "P");
  point(w, q, "P'");
  caption_count(w, {-3, -2.5}, "on the line", s.count);
  caption_count(w, {10, -2.5}, "too far", t.count);
  return s.count == 2 && t.count == 0;
}

// 8.14-8.16: tangent to two lines; 8.16 draws the parallels whose crossings are the centres.
bool two_lines(SvgWriter& w, int show, bool loci) {
  const Line2d a{{0, 0}, {1, 0.25}}, b{{0, 0}, {0.4, 1}};
  const double r = 1;
  const auto s = circles_of_radius(a, b, r);
  w.set_view({-5, -5}, {5, 5});
  given_line(w, a, "L0");
  given_line(w, b, "L1");
  bool ok = s.count == 4;
  if (loci) ok = line_loci(w, a, r) && line_loci(w, b, r) && ok;
  for (int i = 0; i < std::min(show, s.count); ++i) {
    w.circle(at(s, i).center, r, pen(c::blue, 1.8));
    point(w, at(s, i).center, "", c::blue);
  }
  return ok;
}
bool fig_8_14(SvgWriter& w) { return two_lines(w, 1, false); }
bool fig_8_15(SvgWriter& w) { return two_lines(w, 4, false); }
bool fig_8_16(SvgWriter& w) { return two_lines(w, 4, true); }

// 8.17-8.21: through a point, tangent to a circle. 8.17: the general case; 8.18: four, two,
// none; 8.19, 8.20: the loci (radius R + r and |R - r| about the centre, r about P); 8.21: P on
// the circle.
bool point_circle(SvgWriter& w, const Circle2d& k, const Vec2d& p, double r, bool loci, int want) {
  const auto s = circles_of_radius(p, k, r);
  given_circle(w, k, "");
  if (loci) {
    circle_loci(w, k, r);
    w.circle(p, r, dashed(c::orange));
  }
  draw_circles(w, s, c::blue);
  point(w, p, "P");
  return s.count == want;
}
bool fig_8_17(SvgWriter& w) { return point_circle(w, {{0, 0}, 1}, {1.5, 2.5}, 2.5, false, 4); }
bool fig_8_18(SvgWriter& w) {
  bool ok = point_circle(w, {{0, 0}, 1}, {1.5, 2.5}, 2.5, false, 4);
  ok = point_circle(w, {{14, 0}, 3}, {14, 4}, 1.5, false, 2) && ok;
  ok = point_circle(w, {{26, 0}, 2}, {26, 7}, 1.5, false, 0) && ok;
  caption_count(w, {-3, -7}, "four", 4);
  caption_count(w, {11, -7}, "two", 2);
  caption_count(w, {23, -7}, "none", 0);
  return ok;
}
bool fig_8_19(SvgWriter& w) { return point_circle(w, {{0, 0}, 1}, {1.5, 2.5}, 2.5, true, 4); }
bool fig_8_20(SvgWriter& w) { return point_circle(w, {{0, 0}, 3}, {1.5, 4}, 1.2, true, 2); }
bool fig_8_21(SvgWriter& w) { return point_circle(w, {{0, 0}, 3}, {3, 0}, 1.2, true, 2); }

// 8.22-8.26: tangent to a line and a circle. 8.23: the counts vary; 8.24: r too small;
// 8.25, 8.26: the loci (parallels at distance r, circles R +- r).
bool line_circle(SvgWriter& w, const Line2d& l, const Circle2d& k, double r, bool loci, int want) {
  const auto s = circles_of_radius(l, k, r);
  given_line(w, l, "");
  given_circle(w, k, "");
  bool ok = s.count == want;
  if (loci) {
    circle_loci(w, k, r);
    ok = line_loci(w, l, r) && ok;
  }
  draw_circles(w, s, c::blue);
  return ok;
}
bool fig_8_22(SvgWriter& w) {
  return line_circle(w, {{-4, 0}, {1, 0}}, {{0, 2.5}, 1.5}, 1, false, 2);
}
// Clear of the line (two), crossing it (six), touching it (four).
bool fig_8_23(SvgWriter& w) {
  bool ok = line_circle(w, {{-4, 0}, {1, 0}}, {{0, 2.5}, 1.5}, 1, false, 2);
  ok = line_circle(w, {{10, 0}, {1, 0}}, {{14, 1}, 2}, 1, false, 6) && ok;
  ok = line_circle(w, {{22, 0}, {1, 0}}, {{26, 2}, 2}, 1, false, 4) && ok;
  return ok;
}
bool fig_8_24(SvgWriter& w) {
  const bool ok = line_circle(w, {{-4, 0}, {1, 0}}, {{0, 4}, 1}, 1, true, 0);
  caption_count(w, {-4, -2}, "solutions", 0);
  return ok;
}
bool fig_8_25(SvgWriter& w) {
  return line_circle(w, {{-4, 0}, {1, 0}}, {{0, 2.5}, 1.5}, 1, true, 2);
}
bool fig_8_26(SvgWriter& w) {
  return line_circle(w, {{-4, -1}, {1, 0.2}}, {{0, 2}, 1.5}, 0.8, true, 2);
}

// 8.27-8.29: tangent to two circles. 8.28: the counts vary; 8.29: the loci.
bool two_circles(SvgWriter& w, const Circle2d& a, const Circle2d& b, double r, bool loci,
                 int want) {
  const auto s = circles_of_radius(a, b, r);
  given_circle(w, a, "");
  given_circle(w, b, "");
  if (loci) {
    circle_loci(w, a, r);
    circle_loci(w, b, r);
  }
  draw_circles(w, s, c::blue);
  return s.count == want;
}
bool fig_8_27(SvgWriter& w) { return two_circles(w, {{0, 0}, 1.5}, {{5, 0}, 1}, 1.5, false, 2); }
// Two, one (the outer loci touch), none (r too small to bridge the gap).
bool fig_8_28(SvgWriter& w) {
  bool ok = two_circles(w, {{0, 0}, 1.5}, {{5, 0}, 1}, 1.5, false, 2);
  ok = two_circles(w, {{14, 0}, 1}, {{20, 0}, 1}, 2, false, 1) && ok;
  ok = two_circles(w, {{30, 0}, 1}, {{40, 0}, 1}, 1, false, 0) && ok;
  return ok;
}
bool fig_8_29(SvgWriter& w) { return two_circles(w, {{0, 0}, 1.5}, {{5, 0}, 1}, 1.5, true, 2); }

// 8.30: the normal to a line through a point.
bool fig_8_30(SvgWriter& w) {
  const Line2d l{{-3, -1}, {1, 0.4}};
  const Vec2d p{0.5, 2};
  const auto n = normal_line(l, p);
  given_line(w, l, "L");
  draw_lines(w, n, c::red);
  point(w, p, "P");
  return n.count == 1;
}
// 8.31: the perpendicular bisector.
bool fig_8_31(SvgWriter& w) {
  const Vec2d p{-2, -1}, q{2, 1.5};
  const auto b = perpendicular_bisector(p, q);
  w.segment(p, q, pen(c::black, 1.5));
  draw_lines(w, b, c::red);
  point(w, p, "P0");
  point(w, q, "P1");
  return b.count == 1;
}
// 8.32: the parallels at distance d.
bool fig_8_32(SvgWriter& w) {
  const Line2d l{{-3, -1}, {1, 0.4}};
  const auto s = parallel_lines(l, 1.2);
  given_line(w, l, "L");
  draw_lines(w, s, c::red);
  return s.count == 2;
}
// 8.33: the parallels at vertical and horizontal distance d.
bool fig_8_33(SvgWriter& w) {
  const Line2d l{{-3, -1}, {1, 0.6}};
  const auto v = parallel_lines_vertical(l, 1.0), h = parallel_lines_horizontal(l, 1.0);
  w.set_view({-4, -4}, {4, 4});
  given_line(w, l, "L");
  draw_lines(w, v, c::red);
  draw_lines(w, h, c::green);
  return v.count == 2 && h.count == 2;
}
// 8.34: the tangents of a circle normal to a line.
bool fig_8_34(SvgWriter& w) {
  const Line2d l{{-4, -2}, {1, 0.3}};
  const Circle2d k{{1, 1.5}, 1.5};
  const auto t = tangent_lines_normal_to(k, l);
  w.set_view({-5, -3}, {5, 5});
  given_line(w, l, "L");
  given_circle(w, k, "C");
  draw_lines(w, t, c::red);
  return t.count == 2;
}

}  // namespace

std::vector<Figure> chapter8_construction_figures() {
  return {
      {"8.1", "circle_through(Vec2, Vec2, Vec2)", fig_8_1},
      {"8.2", "circles_tangent_to(Line2, Line2, Line2)", fig_8_2},
      {"8.3", "tangent_line_at(Circle2, Vec2)", fig_8_3},
      {"8.4", "tangent_lines(Vec2, Circle2)", fig_8_4},
      {"8.5", "tangent_lines(Vec2, Circle2)", fig_8_5},
      {"8.6", "tangent_lines(Circle2, Circle2)", fig_8_6},
      {"8.7", "tangent_lines(Circle2, Circle2)", fig_8_7},
      {"8.8", "circles_of_radius(Vec2, Vec2, r)", fig_8_8},
      {"8.9", "circles_of_radius(Vec2, Vec2, r)", fig_8_9},
      {"8.10", "circles_of_radius(Vec2, Vec2, r), perpendicular_bisector", fig_8_10},
      {"8.11", "circles_of_radius(Vec2, Line2, r)", fig_8_11},
      {"8.12", "circles_of_radius(Vec2, Line2, r)", fig_8_12},
      {"8.13", "circles_of_radius(Vec2, Line2, r)", fig_8_13},
      {"8.14", "circles_of_radius(Line2, Line2, r)", fig_8_14},
      {"8.15", "circles_of_radius(Line2, Line2, r)", fig_8_15},
      {"8.16", "circles_of_radius(Line2, Line2, r), parallel_lines", fig_8_16},
      {"8.17", "circles_of_radius(Vec2, Circle2, r)", fig_8_17},
      {"8.18", "circles_of_radius(Vec2, Circle2, r)", fig_8_18},
      {"8.19", "circles_of_radius(Vec2, Circle2, r) and its loci", fig_8_19},
      {"8.20", "circles_of_radius(Vec2, Circle2, r) and its loci", fig_8_20},
      {"8.21", "circles_of_radius(Vec2, Circle2, r), P on the circle", fig_8_21},
      {"8.22", "circles_of_radius(Line2, Circle2, r)", fig_8_22},
      {"8.23", "circles_of_radius(Line2, Circle2, r)", fig_8_23},
      {"8.24", "circles_of_radius(Line2, Circle2, r)", fig_8_24},
      {"8.25", "circles_of_radius(Line2, Circle2, r), parallel_lines", fig_8_25},
      {"8.26", "circles_of_radius(Line2, Circle2, r), parallel_lines", fig_8_26},
      {"8.27", "circles_of_radius(Circle2, Circle2, r)", fig_8_27},
      {"8.28", "circles_of_radius(Circle2, Circle2, r)", fig_8_28},
      {"8.29", "circles_of_radius(Circle2, Circle2, r) and its loci", fig_8_29},
      {"8.30", "normal_line(Line2, Vec2)", fig_8_30},
      {"8.31", "perpendicular_bisector(Vec2, Vec2)", fig_8_31},
      {"8.32", "parallel_lines(Line2, d)", fig_8_32},
      {"8.33", "parallel_lines_vertical, parallel_lines_horizontal", fig_8_33},
      {"8.34", "tangent_lines_normal_to(Circle2, Line2)", fig_8_34},
  };
}

}  // namespace locus_gallery
