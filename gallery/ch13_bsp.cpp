// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 13.1 and 13.5: BSP trees of polygons (13.1-13.12) and booleans through them
// (13.27-13.31, locus::bsp2_boolean). Every figure draws what locus::Bsp2 computes: the cells are
// the bounding box cut by the splitting lines of the ancestors (a drawing aid, in floating point);
// the fragments, split points, leaf labels and segment pieces are the tree's. A figure fails when
// the tree's status is not ok or a leaf cell is labelled differently from what Bsp2::classify says
// of an interior point of it.
#include "gallery.hpp"

#include <locus/bsp/bsp2.hpp>
#include <locus/bsp/bsp2_boolean.hpp>

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
  if (node == bsp2_pending) return true;  // a subtree not built yet (13.4-13.8)
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
    if (node == bsp2_pending) {
      const Vec2d p = at + Vec2d{dx * next++, -dy * depth};
      w.text(p, "list", text_style(c::orange, 0, -4, SvgAnchor::middle, 12));
      return p;
    }
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

// 13.4-13.8: the basic construction of the sample polygon stopped after 1, 2, ... 5 nodes: the
// cells so far, the fragments stored at the nodes (coloured by node), the fragments still in
// the lists of the unbuilt subtrees (orange, thin), the split points (red) and the tree with its
// pending lists.
bool construction_state(SvgWriter& w, std::uint32_t nodes) {
  const Sample& s = sample();
  Bsp2Options o;
  o.split = Bsp2Split::first_edge;
  o.max_nodes = nodes;
  // Bsp2 starts each ring at its lowest vertex, so the first splitter is <0, 1> here (the book's
  // list happens to start at <9, 0>); the order is the book's: front lists before back lists.
  const Bsp2<double> t(s.points, s.ends, o);
  if (t.status() != Status::ok || t.nodes().size() != nodes) return false;
  const auto name = [](std::uint32_t i) { return std::to_string(i); };
  const bool ok = draw_cells(w, t, t.root(), box({-1, -1}, {9, 9}));
  draw_fragments(w, t);
  for (const auto& f : t.pending_fragments()) {
    w.arrow(f.end[0].point, f.end[1].point, pen(c::orange, 1.2));
    for (const auto& e : f.end)
      if (e.line != bsp2_none) w.point(e.point, dot(c::red, 4.5));
  }
  for (std::size_t i = 0; i < s.ends[0]; ++i) label(w, s.points[i], std::to_string(i));
  const auto last = t.edges()[t.nodes().back().edge];
  w.text(Vec2d{-1, -1.8},
         "after processing <" + name(last[0]) + ", " + name(last[1]) +
             ">; lists pending: " + std::to_string(t.pending().size()) + "; splits so far: " +
             std::to_string(t.fragments().size() + t.pending_fragments().size() - t.edges().size()),
         text_style(c::black, 0, 0));
  draw_tree(w, t, {11, 9}, 0.8, 1.2);
  return ok && !t.pending().empty();
}
bool fig_13_4(SvgWriter& w) { return construction_state(w, 1); }
bool fig_13_5(SvgWriter& w) { return construction_state(w, 2); }
bool fig_13_6(SvgWriter& w) { return construction_state(w, 3); }
bool fig_13_7(SvgWriter& w) { return construction_state(w, 4); }
bool fig_13_8(SvgWriter& w) { return construction_state(w, 5); }

// Booleans (13.27-13.31): operands drawn as outlines, result edges as arrows, the result's
// loops filled (even-odd), lower-dimensional parts in red.
struct Operand {
  std::vector<Vec2d> points;
  std::vector<std::uint32_t> ends;
  Bsp2<double> tree() const { return Bsp2<double>(points, ends); }
};

std::vector<std::vector<Vec2d>> rings_of(const Operand& p, const Vec2d& shift) {
  std::vector<std::vector<Vec2d>> out;
  std::uint32_t b = 0;
  for (const std::uint32_t e : p.ends) {
    out.emplace_back();
    for (std::uint32_t i = b; i < e; ++i) out.back().push_back(p.points[i] + shift);
    b = e;
  }
  return out;
}

void outline(SvgWriter& w, const Operand& p, const Vec2d& shift, const char* col, bool fill) {
  const auto r = rings_of(p, shift);
  const std::vector<std::vector<Vec2d>> holes(r.begin() + 1, r.end());
  w.polygon(r[0], holes, fill ? filled(col, 0.15, 1.6) : pen(col, 1.6));
}

void draw_result(SvgWriter& w, const Bsp2BooleanResult<double>& r, const Vec2d& shift,
                 int operand = -1) {
  if (operand < 0) {
    std::vector<std::vector<Vec2d>> loops;
    std::uint32_t b = 0;
    for (const std::uint32_t e : r.loop_ends) {
      loops.emplace_back();
      for (std::uint32_t i = b; i < e; ++i)
        loops.back().push_back(r.edges[r.loop_edges[i]].end[0].point + shift);
      b = e;
    }
    if (!loops.empty()) {
      const std::vector<std::vector<Vec2d>> rest(loops.begin() + 1, loops.end());
      w.polygon(loops[0], rest, filled(c::gray, 0.45, 0));
    }
  }
  for (const auto& e : r.edges)
    if (operand < 0 || e.operand == operand)
      w.arrow(e.end[0].point + shift, e.end[1].point + shift,
              pen(e.operand == 0 ? c::blue : c::green, 2.4));
  for (const auto& s : r.segments)
    w.segment(s.end[0].point + shift, s.end[1].point + shift, pen(c::red, 3.5));
  for (const auto& p : r.points) w.point(p + shift, dot(c::red, 6));
}

void caption(SvgWriter& w, const Vec2d& at, const std::string& s) {
  w.text(at, s, text_style(c::black, 0, 0, SvgAnchor::middle, 13));
}

// 13.27: two triangles; the edges of A inside B; the edges of B inside A; their union is the
// boundary of A n B.
bool fig_13_27(SvgWriter& w) {
  const Operand a{{{0, 0}, {6, 0}, {3, 6}}, {3}}, b{{{0, 4}, {3, -2}, {6, 4}}, {3}};
  const auto ta = a.tree(), tb = b.tree();
  const auto r = bsp2_boolean(Bsp2Op::intersection, ta, tb);
  if (r.status != Status::ok || !r.closed || r.loop_ends.size() != 1) return false;
  const char* names[] = {"(a) A and B", "(b) edges of A inside B", "(c) edges of B inside A",
                         "(d) A n B"};
  for (int k = 0; k < 4; ++k) {
    const Vec2d s{8.0 * k, 0};
    outline(w, a, s, k == 0 ? c::blue : c::light, false);
    outline(w, b, s, k == 0 ? c::green : c::light, false);
    if (k == 1) draw_result(w, r, s, 0);
    if (k == 2) draw_result(w, r, s, 1);
    if (k == 3) draw_result(w, r, s);
    caption(w, s + Vec2d{3, -3}, names[k]);
  }
  return true;
}

// 13.28: two squares sharing an edge walked in opposite directions: the book's method reports
// no intersection (a); the true intersection is the shared edge (b, bsp2_boolean's segments).
bool fig_13_28(SvgWriter& w) {
  const Operand a{{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, {4}}, b{{{3, 0}, {6, 0}, {6, 3}, {3, 3}}, {4}};
  const auto ta = a.tree(), tb = b.tree();
  const auto r = bsp2_boolean(Bsp2Op::intersection, ta, tb);
  if (r.status != Status::ok || !r.edges.empty() || r.segments.size() != 1) return false;
  for (const auto& ring : {std::pair{a, c::blue}, std::pair{b, c::green}})
    for (std::size_t i = 0; i < 4; ++i)
      w.arrow(ring.first.points[i], ring.first.points[(i + 1) % 4], pen(ring.second, 2));
  caption(w, {3, -1.2}, "(a) regularised A n B: no edges");
  const Vec2d s{9, 0};
  outline(w, a, s, c::light, false);
  outline(w, b, s, c::light, false);
  draw_result(w, r, s);
  caption(w, s + Vec2d{3, -1.2}, "(b) the true set: a segment");
  return true;
}

// 13.29: two polygons whose true intersection is a square plus two segments along which they
// only touch.
bool fig_13_29(SvgWriter& w) {
  const Operand a{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {4}},
      b{{{1, 0}, {3, 0}, {3, 3}, {0, 3}, {0, 2}, {2, 2}, {2, 1}, {1, 1}}, {8}};
  const auto ta = a.tree(), tb = b.tree();
  const auto r = bsp2_boolean(Bsp2Op::intersection, ta, tb);
  if (r.status != Status::ok || r.loop_ends.size() != 1 || r.segments.size() < 2) return false;
  outline(w, a, {0, 0}, c::blue, true);
  outline(w, b, {0, 0}, c::green, true);
  caption(w, {1.5, -0.8}, "(a) A and B");
  const Vec2d s{5, 0};
  outline(w, a, s, c::light, false);
  outline(w, b, s, c::light, false);
  draw_result(w, r, s);
  caption(w, s + Vec2d{1.5, -0.8}, "(b) A n B: a square and two segments");
  return true;
}

const Operand& holed() {
  static const Operand p{{{0, 0}, {8, 0}, {8, 6}, {0, 6}, {3, 2}, {3, 4}, {5, 4}, {5, 2}}, {4, 8}};
  return p;
}
const Operand& keyhole() {
  static const Operand p{{{0, 0},
                          {8, 0},
                          {8, 6},
                          {0, 6},
                          {0, 3},
                          {3, 3},
                          {3, 4},
                          {5, 4},
                          {5, 2},
                          {3, 2},
                          {3, 3},
                          {0, 3}},
                         {12}};
  return p;
}

// 13.30: a polygon with a hole as two rings (a) and as one keyhole ring (b): both trees' cells,
// which must classify every sample point alike.
bool fig_13_30(SvgWriter& w) {
  const auto t1 = holed().tree(), t2 = keyhole().tree();
  if (t1.status() != Status::ok || t2.status() != Status::ok) return false;
  bool ok = draw_cells(w, t1, t1.root(), box({-1, -1}, {9, 7}));
  std::vector<Vec2d> cell2 = box({-1, -1}, {9, 7});
  for (auto& p : cell2) p = p + Vec2d{11, 0};
  // The second tree is drawn shifted: its cells come from a shifted copy of the keyhole.
  Operand k2 = keyhole();
  for (auto& p : k2.points) p = p + Vec2d{11, 0};
  const auto t3 = k2.tree();
  ok = ok && draw_cells(w, t3, t3.root(), cell2);
  for (const auto& ring : rings_of(holed(), {0, 0})) w.polygon(ring, pen(c::black, 2));
  const auto& kp = k2.points;
  for (std::size_t i = 0; i < kp.size(); ++i)
    w.arrow(kp[i], kp[(i + 1) % kp.size()], pen(c::black, 1.6));
  for (double x = -0.7; x < 9; x += 0.5)
    for (double y = -0.7; y < 7; y += 0.5) ok = ok && t1.classify({x, y}) == t2.classify({x, y});
  caption(w, {4, -1.8}, "(a) two rings");
  caption(w, {15, -1.8}, "(b) one keyhole ring");
  return ok;
}

// 13.31: a rectangle intersected with the keyhole polygon; the bridge inside the rectangle is
// kept in both directions (a slit of zero width).
bool fig_13_31(SvgWriter& w) {
  const Operand rect{{{-1, 1}, {6, 1}, {6, 5}, {-1, 5}}, {4}};
  const auto ta = rect.tree(), tb = keyhole().tree();
  const auto r = bsp2_boolean(Bsp2Op::intersection, ta, tb);
  if (r.status != Status::ok || !r.closed) return false;
  outline(w, rect, {0, 0}, c::blue, false);
  const auto& kp = keyhole().points;
  for (std::size_t i = 0; i < kp.size(); ++i)
    w.segment(kp[i], kp[(i + 1) % kp.size()], pen(c::green, 1.4));
  const Vec2d s{11, 0};
  draw_result(w, r, s);
  caption(w, {4, -1.2}, "rectangle and keyhole");
  caption(w, s + Vec2d{3, -1.2}, "their intersection");
  return true;
}

}  // namespace

std::vector<Figure> chapter13_bsp_figures() {
  return {
      {"13.1", "Bsp2 (balanced), Bsp2::classify", fig_13_1},
      {"13.2", "Bsp2 (first_edge): a node's coincident fragments", fig_13_2},
      {"13.3", "the input of the BSP figures", fig_13_3},
      {"13.4", "Bsp2 (first_edge, max_nodes 1): construction state", fig_13_4},
      {"13.5", "Bsp2 (first_edge, max_nodes 2): construction state", fig_13_5},
      {"13.6", "Bsp2 (first_edge, max_nodes 3): construction state", fig_13_6},
      {"13.7", "Bsp2 (first_edge, max_nodes 4): construction state", fig_13_7},
      {"13.8", "Bsp2 (first_edge, max_nodes 5): construction state", fig_13_8},
      {"13.9", "Bsp2 (first_edge): fragments, split points, tree", fig_13_9},
      {"13.10", "Bsp2 (first_edge) of a convex polygon", fig_13_10},
      {"13.11", "Bsp2 (balanced) of a convex polygon", fig_13_11},
      {"13.12", "Bsp2::partition", fig_13_12},
      {"13.27", "bsp2_boolean (intersection): the pieces of each operand", fig_13_27},
      {"13.28", "bsp2_boolean (intersection): shared opposite edge as a segment", fig_13_28},
      {"13.29", "bsp2_boolean (intersection): region plus segments", fig_13_29},
      {"13.30", "Bsp2 of a polygon with a hole and of its keyhole", fig_13_30},
      {"13.31", "bsp2_boolean (intersection): rectangle and keyhole", fig_13_31},
  };
}

}  // namespace locus_gallery
