// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 13.1: BSP trees of polygons (13.1-13.3, 13.9-13.12). Every figure draws what
// locus::Bsp2 computes: the cells are the bounding box cut by the splitting lines of the
// ancestors (a drawing aid, in floating point); the fragments, split points, leaf labels and
// segment pieces are the tree's. A figure fails when the tree's status is not ok or a leaf cell
// is labelled differently from what Bsp2::classify says of an interior point of it.
#include "gallery.hpp"

#include <locus/bsp/bsp2.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

struct Sample {
  std::vector<Vec2d> points;
  std::vector<std::uint32_t> ends;
};

// A simple polygon with a notch and two dents (the input of 13.1, 13.3, 13.9, 13.12).
const Sample& sample() {
  static const Sample s = {
      {{0, 0}, {8, 0}, {8, 5}, {6, 3}, {5, 6}, {7, 8}, {2, 8}, {3, 5}, {1, 6}, {0, 3}}, {10}};
  return s;
}

std::vector<Vec2d> ring(const Sample& s) {
  return {s.points.begin(), s.points.begin() + s.ends[0]};
}

double cross(const Vec2d& u, const Vec2d& v) { return u.x * v.y - u.y * v.x; }

// The part of a convex polygon left of (side > 0) or right of (side < 0) the line a b.
std::vector<Vec2d> clip(const std::vector<Vec2d>& poly, const Vec2d& a, const Vec2d& b,
                        double side) {
  std::vector<Vec2d> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2d& p = poly[i];
    const Vec2d& q = poly[(i + 1) % poly.size()];
    const double sp = side * cross(b - a, p - a), sq = side * cross(b - a, q - a);
    if (sp >= 0) out.push_back(p);
    if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  return out;
}

Vec2d centroid(const std::vector<Vec2d>& v) {
  Vec2d s{0, 0};
  for (const auto& p : v) s = s + p;
  return s / double(v.size());
}

// Draws the cells of the tree inside `box`: chords of the splitting lines (gray), inside leaves
// filled. Returns false when a leaf's label disagrees with classify() at the cell's centroid.
bool draw_cells(SvgWriter& w, const Bsp2<double>& t, std::int32_t node,
                const std::vector<Vec2d>& cell) {
  if (cell.size() < 3) return true;
  if (node < 0) {
    const bool in = node == bsp2_inside;
    if (in) w.polygon(cell, filled(c::blue, 0.18, 0.5));
    const Side s = t.classify(centroid(cell));
    return s == Side::boundary || (s == Side::inside) == in;
  }
  const Bsp2Node& n = t.nodes()[std::size_t(node)];
  const auto e = t.edges()[n.edge];
  const Vec2d a = t.points()[e[0]], b = t.points()[e[1]];
  // The chord: the cell cut by the line (the two crossing points of its boundary).
  std::vector<Vec2d> chord;
  for (std::size_t i = 0; i < cell.size(); ++i) {
    const Vec2d& p = cell[i];
    const Vec2d& q = cell[(i + 1) % cell.size()];
    const double sp = cross(b - a, p - a), sq = cross(b - a, q - a);
    if (sp == 0) chord.push_back(p);
    if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) chord.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  if (chord.size() >= 2) w.segment(chord[0], chord[1], dashed(c::gray, 1));
  return draw_cells(w, t, n.front, clip(cell, a, b, 1)) &&
         draw_cells(w, t, n.back, clip(cell, a, b, -1));
}

std::vector<Vec2d> box(const Vec2d& lo, const Vec2d& hi) {
  return {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
}

void draw_fragments(SvgWriter& w, const Bsp2<double>& t) {
  const char* cols[] = {c::blue, c::green, c::orange, c::purple, c::red};
  for (std::size_t k = 0; k < t.nodes().size(); ++k) {
    const Bsp2Node& n = t.nodes()[k];
    for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
      const auto& f = t.fragments()[i];
      w.arrow(f.end[0].point, f.end[1].point, pen(cols[k % 5], 2.2));
      for (const auto& e : f.end)
        if (e.line != bsp2_none) w.point(e.point, dot(c::red, 4.5));
    }
  }
}

// The tree as a diagram at `at`: x by in-order position, y by depth.
void draw_tree(SvgWriter& w, const Bsp2<double>& t, const Vec2d& at, double dx, double dy) {
  int next = 0;
  const auto place = [&](const auto& self, std::int32_t node, int depth) -> Vec2d {
    if (node < 0) {
      const Vec2d p = at + Vec2d{dx * next++, -dy * depth};
      w.text(p, node == bsp2_inside ? "in" : "out",
             text_style(node == bsp2_inside ? c::blue : c::gray, 0, -4, SvgAnchor::middle, 12));
      return p;
    }
    const Bsp2Node& n = t.nodes()[std::size_t(node)];
    const Vec2d l = self(self, n.back, depth + 1);
    const Vec2d p = at + Vec2d{dx * next++, -dy * depth};
    const Vec2d r = self(self, n.front, depth + 1);
    w.segment(p, l, pen(c::gray, 1));
    w.segment(p, r, pen(c::gray, 1));
    w.point(p, dot(c::black, 5));
    w.text(p, "e" + std::to_string(n.edge), text_style(c::black, 6, 4, SvgAnchor::start, 12));
    return p;
  };
  place(place, t.root(), 0);
}

// 13.1: the partition of the plane by the tree of the sample polygon (balanced construction):
// the splitting lines cut each cell in two; the inside leaves are filled.
bool fig_13_1(SvgWriter& w) {
  const Sample& s = sample();
  const Bsp2<double> t(s.points, s.ends);
  if (t.status() != Status::ok) return false;
  const bool ok = draw_cells(w, t, t.root(), box({-1, -1}, {9, 9}));
  w.polygon(ring(s), pen(c::black, 2));
  w.text(Vec2d{-1, -1.8},
         std::to_string(t.nodes().size()) + " nodes, depth " + std::to_string(t.depth()),
         text_style(c::black, 0, 0));
  return ok;
}

// 13.2: a splitting line carrying two coincident edges whose normals (interior to the left of
// each directed edge) point to opposite sides.
bool fig_13_2(SvgWriter& w) {
  const std::vector<Vec2d> p{{0, 2}, {2, 2}, {2, 0}, {6, 0}, {6, 2}, {4, 2}, {4, 4}, {0, 4}};
  const std::uint32_t ends[] = {8};
  const Bsp2<double> t(p, ends, {Bsp2Split::first_edge});
  if (t.status() != Status::ok) return false;
  w.polygon(p, filled(c::light, 0.4, 2));
  bool found = false;
  for (const Bsp2Node& n : t.nodes()) {
    if (n.count < 2) continue;
    const auto e = t.edges()[n.edge];
    w.line(t.points()[e[0]], t.points()[e[1]] - t.points()[e[0]], dashed(c::gray, 1));
    for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
      const auto& f = t.fragments()[i];
      const Vec2d a = f.end[0].point, b = f.end[1].point, m = (a + b) * 0.5;
      const Vec2d d = b - a, normal = Vec2d{-d.y, d.x} / std::sqrt(d.x * d.x + d.y * d.y);
      w.arrow(a, b, pen(c::blue, 2.4));
      w.arrow(m, m + normal, pen(c::red, 1.6));
    }
    found = true;
  }
  return found;
}

// 13.3: the sample polygon, its vertices numbered.
bool fig_13_3(SvgWriter& w) {
  const Sample& s = sample();
  w.polygon(ring(s), pen(c::black, 2));
  for (std::size_t i = 0; i < s.ends[0]; ++i) point(w, s.points[i], std::to_string(i));
  return true;
}

// 13.9: the final state of the basic construction (splitter = first edge of each list): the
// fragments, coloured by the node that stores them, the split points in red, and the tree.
bool fig_13_9(SvgWriter& w) {
  const Sample& s = sample();
  const Bsp2<double> t(s.points, s.ends, {Bsp2Split::first_edge});
  if (t.status() != Status::ok) return false;
  draw_fragments(w, t);
  for (std::size_t i = 0; i < s.ends[0]; ++i) label(w, s.points[i], std::to_string(i));
  draw_tree(w, t, {11, 9}, 0.7, 1.1);
  return t.fragments().size() > t.edges().size();
}

// 13.10 and 13.11: a convex polygon; the basic construction gives a chain, the balanced one a
// shallower tree.
bool convex_tree(SvgWriter& w, Bsp2Split split) {
  std::vector<Vec2d> p;
  for (int i = 0; i < 8; ++i) {
    const double a = 2 * 3.14159265358979 * i / 8;
    p.push_back({3 * std::cos(a), 3 * std::sin(a)});
  }
  const std::uint32_t ends[] = {8};
  const Bsp2<double> t(p, ends, {split});
  if (t.status() != Status::ok) return false;
  const bool ok = draw_cells(w, t, t.root(), box({-4, -4}, {4, 4}));
  w.polygon(p, pen(c::black, 2));
  for (std::size_t i = 0; i < p.size(); ++i)
    label(w, (p[i] + p[(i + 1) % p.size()]) * 0.55, "e" + std::to_string(i), c::gray);
  draw_tree(w, t, {6, 4}, 0.6, split == Bsp2Split::balanced ? 1.6 : 0.9);
  return ok;
}
bool fig_13_10(SvgWriter& w) { return convex_tree(w, Bsp2Split::first_edge); }
bool fig_13_11(SvgWriter& w) { return convex_tree(w, Bsp2Split::balanced); }

// 13.12: a segment partitioned by the tree: inside (blue), outside (gray), coincident with an
// edge of the same direction (green) or the opposite one (red).
bool fig_13_12(SvgWriter& w) {
  const Sample& s = sample();
  const Bsp2<double> t(s.points, s.ends);
  if (t.status() != Status::ok) return false;
  w.polygon(ring(s), filled(c::light, 0.4, 2));
  bool ok = true;
  const std::pair<Vec2d, Vec2d> segs[] = {
      {{-1, 1.5}, {9, 6.5}}, {{9, 8}, {0, 8}}, {{-1, 0}, {9, 0}}};
  for (const auto& [a, b] : segs) {
    const auto r = t.partition(a, b);
    ok = ok && r.status == Status::ok;
    for (const auto& piece : r.pieces) {
      const char* col = piece.location == Bsp2Location::inside            ? c::blue
                        : piece.location == Bsp2Location::outside         ? c::gray
                        : piece.location == Bsp2Location::coincident_same ? c::green
                                                                          : c::red;
      w.segment(piece.end[0].point, piece.end[1].point, pen(col, 3.5));
      w.point(piece.end[1].point, dot(c::black, 3));
    }
  }
  return ok;
}

}  // namespace

std::vector<Figure> chapter13_bsp_figures() {
  return {
      {"13.1", "Bsp2 (balanced), Bsp2::classify", fig_13_1},
      {"13.2", "Bsp2 (first_edge): a node's coincident fragments", fig_13_2},
      {"13.3", "the input of the BSP figures", fig_13_3},
      {"13.9", "Bsp2 (first_edge): fragments, split points, tree", fig_13_9},
      {"13.10", "Bsp2 (first_edge) of a convex polygon", fig_13_10},
      {"13.11", "Bsp2 (balanced) of a convex polygon", fig_13_11},
      {"13.12", "Bsp2::partition", fig_13_12},
  };
}

}  // namespace locus_gallery
