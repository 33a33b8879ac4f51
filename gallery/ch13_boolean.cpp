// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 13.5: boolean operations on polygons (13.20-13.26). Every gray region is a
// locus::boolean_* result (snap-rounded, exactly decided); the operands are drawn as outlines.
// A figure fails when a boolean reports a status other than ok.
#include "gallery.hpp"

#include <locus/boolean/polygon_boolean.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

using Poly = Polygon2<double>;
using Multi = MultiPolygon2<double>;

// The operands of 13.22-13.26: an inverted L and a pentagon overlapping its corner.
Poly inverted_l() { return {{{0, 0}, {2, 0}, {2, 3}, {6, 3}, {6, 5}, {0, 5}}}; }
Poly pentagon() {
  Poly p;
  for (int k = 0; k < 5; ++k) {
    const double a = std::numbers::pi / 2 + 2 * std::numbers::pi * k / 5;
    p.vertices.push_back({3.2 + 2.2 * std::cos(a), 2.6 + 2.2 * std::sin(a)});
  }
  return p;
}

Poly moved(Poly p, const Vec2d& by) {
  for (auto& v : p.vertices) v = v + by;
  return p;
}

// Fills a boolean result in gray, its rings outlined with the inside on the left of each arrow.
void draw_region(SvgWriter& w, const Multi& m, bool arrows = false) {
  for (const auto& p : m) {
    std::vector<std::vector<Vec2d>> holes;
    for (const auto& h : p.holes) holes.push_back(h.vertices);
    w.polygon(p.outer.vertices, holes, filled(c::gray, 0.45, 0));
    for (std::size_t k = 0; k <= p.holes.size(); ++k) {
      const auto& r = k == 0 ? p.outer.vertices : p.holes[k - 1].vertices;
      for (std::size_t i = 0; i < r.size(); ++i) {
        if (arrows)
          w.arrow(r[i], r[(i + 1) % r.size()], pen(c::black, 1.6));
        else
          w.segment(r[i], r[(i + 1) % r.size()], pen(c::black, 1.6));
      }
    }
  }
}

void outline(SvgWriter& w, const Poly& p, const char* col) {
  w.polygon(p.vertices, dashed(col, 1.4));
}

// 13.20: a bounded polygon with a hole, and a half-space (the inside left of one line), drawn
// as its part inside the frame: both regions are boolean results.
bool fig_13_20(SvgWriter& w) {
  const PolygonWithHoles2<double> a{{{{0, 0}, {4, 0}, {5, 3}, {2, 5}, {-1, 3}}},
                                    {{{{1.5, 1.5}, {3, 1.5}, {2.2, 3}}}}};
  const auto left = boolean_union(a, Multi{});
  // Half-space x + 0.4 y <= 10.5 (a huge quadrilateral) within the frame [7, 13] x [-1, 6].
  const Poly half{{{10.5 + 400, -1000}, {10.5 - 400, 1000}, {-1000, 1000}, {-1000, -1000}}};
  const Poly frame{{{7, -1}, {13, -1}, {13, 6}, {7, 6}}};
  const auto right = boolean_intersection(frame, half);
  if (left.status != Status::ok || right.status != Status::ok) return false;
  draw_region(w, left.polygons);
  draw_region(w, right.polygons);
  w.line(Vec2d{10.5 + 0.4 * 6, -6}, Vec2d{-0.4, 1}, pen(c::black, 2));
  w.polygon(frame.vertices, dashed(c::gray, 1));
  return left.polygons.size() == 1 && right.polygons.size() == 1;
}

// 13.21: a polygon and its negation (the complement within a frame), edges directed so that the
// inside is on the left: the negation's hole runs clockwise.
bool fig_13_21(SvgWriter& w) {
  const Poly a{{{0, 0}, {4, 0}, {5, 3}, {2, 5}, {-1, 3}}};
  const auto self = boolean_union(a, Multi{});
  const auto neg = boolean_negation(moved(a, {8, 0}), AlignedBox2<double>{{6, -1.5}, {14, 6.5}});
  if (self.status != Status::ok || neg.status != Status::ok) return false;
  draw_region(w, self.polygons, true);
  draw_region(w, neg.polygons, true);
  return neg.polygons.size() == 1 && neg.polygons[0].holes.size() == 1;
}

// 13.22: the two operands.
bool fig_13_22(SvgWriter& w) {
  const auto l = boolean_union(inverted_l(), Multi{});
  const auto p = boolean_union(pentagon(), Multi{});
  if (l.status != Status::ok || p.status != Status::ok) return false;
  draw_region(w, l.polygons);
  draw_region(w, p.polygons);
  w.text(Vec2d{0.3, 4.3}, "A", text_style());
  w.text(Vec2d{3.6, 1.2}, "B", text_style());
  return true;
}

bool draw_op(SvgWriter& w, BooleanOp op, const Poly& a, const Poly& b) {
  const auto r = boolean_op(op, to_multipolygon(a), to_multipolygon(b));
  if (r.status != Status::ok) return false;
  draw_region(w, r.polygons);
  outline(w, a, c::blue);
  outline(w, b, c::red);
  return !r.polygons.empty();
}

bool fig_13_23(SvgWriter& w) {
  return draw_op(w, BooleanOp::intersection, inverted_l(), pentagon());
}
bool fig_13_24(SvgWriter& w) { return draw_op(w, BooleanOp::union_, inverted_l(), pentagon()); }
// 13.25: (a) A minus B, (b) B minus A, side by side.
bool fig_13_25(SvgWriter& w) {
  const Vec2d shift{8, 0};
  const bool a = draw_op(w, BooleanOp::difference, inverted_l(), pentagon());
  const bool b =
      draw_op(w, BooleanOp::difference, moved(pentagon(), shift), moved(inverted_l(), shift));
  w.text(Vec2d{2.5, -1}, "(a)", text_style());
  w.text(Vec2d{10.5, -1}, "(b)", text_style());
  return a && b;
}
bool fig_13_26(SvgWriter& w) {
  return draw_op(w, BooleanOp::symmetric_difference, inverted_l(), pentagon());
}

}  // namespace

std::vector<Figure> chapter13_boolean_figures() {
  return {
      {"13.20", "boolean_union, boolean_intersection (a half-space within a frame)", fig_13_20},
      {"13.21", "boolean_negation (within a frame)", fig_13_21},
      {"13.22", "boolean_union (each operand alone)", fig_13_22},
      {"13.23", "boolean_intersection", fig_13_23},
      {"13.24", "boolean_union", fig_13_24},
      {"13.25", "boolean_difference", fig_13_25},
      {"13.26", "boolean_xor", fig_13_26},
  };
}

}  // namespace locus_gallery
