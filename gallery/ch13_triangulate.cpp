// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 13.9: polygon triangulation. Ear clipping (13.53, on a polygon with a hole),
// the book's sample polygon (13.56, shared with the trapezoidal map figures 13.57-13.67 through
// ch13_sample.hpp), its merged trapezoids (13.68), its monotone pieces (13.69) and an ear cut
// from one piece (13.70), the monotone walk (13.71-13.73), convex partitions (13.74-13.77).
// Every figure draws what locus computes: triangulate_ear_clipping, trapezoid_decomposition
// (+ trapezoid_corners), monotone_decomposition and triangulate_monotone; a figure fails when the
// status is not ok or the pieces' area differs from the polygon's.
#include "ch13_sample.hpp"
#include "gallery.hpp"

#include <locus/containment/point_in_polygon.hpp>
#include <locus/core/predicates.hpp>
#include <locus/intersection/segment_segment.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>
#include <locus/triangulate/convex_partition.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>
#include <locus/triangulate/trapezoid_decomposition.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <span>
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

// A polygon with split and merge vertices and one hole (the input of 13.53).
const Sample& sample() {
  static const Sample s = {{{0, 0},
                            {4, 1.2},
                            {7, 0.2},
                            {10, 2},
                            {8.6, 4.4},
                            {10.4, 7.6},
                            {6.8, 6.2},
                            {4.4, 8.4},
                            {2.2, 5.6},
                            {-0.6, 6.8},
                            {1.4, 3.2},
                            // hole
                            {4.2, 3.2},
                            {5.0, 5.0},
                            {6.6, 3.6}},
                           {11, 14}};
  return s;
}

double twice_area(std::span<const Vec2d> p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2d& u = p[i];
    const Vec2d& v = p[(i + 1) % p.size()];
    a += u.x * v.y - v.x * u.y;
  }
  return a;
}

// The book's sample polygon of 13.56-13.70 (ch13_sample.hpp): one ring.
const Sample& book_sample() {
  static const Sample s = {sample_polygon_points,
                           {static_cast<std::uint32_t>(sample_polygon_points.size())}};
  return s;
}

// Twice the area: the outer ring's minus the holes'.
double polygon_twice_area(const Sample& s) {
  const std::span<const Vec2d> pts(s.points);
  double a = 0;
  for (std::size_t k = 0, b = 0; k < s.ends.size(); b = s.ends[k++])
    a += (k == 0 ? 1 : -1) * std::abs(twice_area(pts.subspan(b, s.ends[k] - b)));
  return a;
}

bool close_area(const Sample& s, double a) { return std::abs(a - polygon_twice_area(s)) <= 1e-9; }

void draw_polygon(SvgWriter& w, const Sample& s, const Vec2d& off) {
  for (std::size_t k = 0, b = 0; k < s.ends.size(); b = s.ends[k++]) {
    std::vector<Vec2d> ring;
    for (std::size_t i = b; i < s.ends[k]; ++i) ring.push_back(off + s.points[i]);
    w.polygon(ring, pen(c::black, 2));
  }
}

bool draw_triangles(SvgWriter& w, const Sample& s, const PolygonTriangulation& r, const Vec2d& off,
                    const char* col) {
  if (r.status != Status::ok) return false;
  double sum = 0;
  for (const auto& t : r.triangles) {
    const std::vector<Vec2d> v{off + s.points[t[0]], off + s.points[t[1]], off + s.points[t[2]]};
    sum += twice_area(std::span<const Vec2d>(v));
    w.polygon(v, filled(col, 0.15, 1));
  }
  draw_polygon(w, s, off);
  return close_area(s, sum);
}

// 13.53: the diagonals ear clipping finds (each triangle's third side joins mutually visible
// vertices; the hole is joined by a bridge).
bool fig_13_53(SvgWriter& w) {
  const Sample& s = sample();
  const auto r = triangulate_ear_clipping(s.points, s.ends);
  const bool ok = draw_triangles(w, s, r, {0, 0}, c::blue);
  w.text(Vec2d{0, -1.2},
         std::to_string(r.triangles.size()) + " ears cut (triangulate_ear_clipping)",
         text_style(c::black, 0, 0));
  return ok;
}

// ---- 13.9.1 ear clipping: visibility and cones -------------------------------------------

// A counter-clockwise polygon whose convex vertex V1 = (0, 0) is not an ear: the reflex vertex
// R of a notch from the top lies in triangle <V0, V1, V2> (the input of 13.54 and 13.55).
const std::vector<Vec2d> notch{{0, 0}, {8, 0}, {8, 6}, {4, 6}, {3, 1.5}, {1, 6}, {0, 6}};
constexpr std::size_t notch_v0 = 6, notch_v1 = 0, notch_v2 = 1, notch_r = 4;

bool is_reflex(const std::vector<Vec2d>& ring, std::size_t i) {
  const std::size_t n = ring.size();
  return orient2d(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) == Sign::negative;
}

// 13.54: V0 and V2 do not see each other because triangle <V0, V1, V2> holds the reflex vertex R
// (exact orient2d, classify(Triangle2)); the diagonal crosses R's edges (intersects), and
// triangulate_ear_clipping indeed never cuts that triangle.
bool fig_13_54(SvgWriter& w) {
  const std::vector<Vec2d>& p = notch;
  const std::vector<std::uint32_t> ends{static_cast<std::uint32_t>(p.size())};
  const Triangle2<double> tri{p[notch_v0], p[notch_v1], p[notch_v2]};
  if (is_reflex(p, notch_v1) || !is_reflex(p, notch_r) || classify(p[notch_r], tri) != Side::inside)
    return false;
  const auto ears = triangulate_ear_clipping(p, ends);
  if (ears.status != Status::ok) return false;
  for (auto t : ears.triangles) {
    std::sort(t.begin(), t.end());
    if (t == std::array<std::uint32_t, 3>{0, 1, 6}) return false;
  }
  w.polygon(p, filled(c::gray, 0.12, 2));
  w.polygon(std::vector<Vec2d>{tri.v0, tri.v1, tri.v2}, filled(c::blue, 0.15, 1));
  const Segment2<double> diagonal{p[notch_v0], p[notch_v2]};
  int blocked = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t j = (i + 1) % p.size();
    if (i == notch_v0 || j == notch_v0 || i == notch_v2 || j == notch_v2) continue;
    if (!intersects(diagonal, Segment2<double>{p[i], p[j]})) continue;
    ++blocked;
    w.segment(p[i], p[j], pen(c::orange, 3));
  }
  if (blocked == 0) return false;
  w.segment(diagonal.p0, diagonal.p1, dashed(c::red, 1.6));
  point(w, p[notch_v0], "V0");
  point(w, p[notch_v1], "V1");
  point(w, p[notch_v2], "V2");
  point(w, p[notch_r], "R (reflex)", c::red);
  return true;
}

// The interior cone at vertex i of a counter-clockwise ring: from the direction to the next
// vertex counter-clockwise to the direction to the previous one, drawn as a fan of radius r.
void draw_cone(SvgWriter& w, const std::vector<Vec2d>& ring, std::size_t i, double r,
               const Vec2d& off) {
  const std::size_t n = ring.size();
  const Vec2d v = ring[i], a = ring[(i + 1) % n] - v, b = ring[(i + n - 1) % n] - v;
  const double t0 = std::atan2(a.y, a.x);
  double t1 = std::atan2(b.y, b.x);
  while (t1 <= t0) t1 += 2 * 3.14159265358979323846;
  std::vector<Vec2d> fan{off + v};
  for (int k = 0; k <= 48; ++k) {
    const double t = t0 + (t1 - t0) * k / 48;
    fan.push_back(off + v + r * Vec2d{std::cos(t), std::sin(t)});
  }
  w.polygon(fan, filled(c::green, 0.25, 0.8));
}

// The exact cone test of ear clipping: W is inside the cone at V (neighbours Vm, Vp) iff it is
// left of both edges at a convex V, left of either at a reflex V.
bool in_cone(const Vec2d& vm, const Vec2d& v, const Vec2d& vp, const Vec2d& q) {
  const bool l0 = orient2d(vm, v, q) == Sign::positive, l1 = orient2d(v, vp, q) == Sign::positive;
  return orient2d(vm, v, vp) == Sign::negative ? (l0 || l1) : (l0 && l1);
}

// 13.55: cone containment (a) at the convex vertex V1, (b) at the reflex vertex R. Each test
// point W is coloured by the exact test; checked against classify_polygon of a point just off
// V toward W (inside the polygon exactly when W is in the cone).
bool fig_13_55(SvgWriter& w) {
  const std::vector<Vec2d>& p = notch;
  const std::size_t n = p.size();
  struct Panel {
    std::size_t vertex;
    Vec2d off;
    std::vector<Vec2d> tests;
    const char* name;
  };
  const Panel panels[] = {{notch_v1, {0, 0}, {{6, 3}, {-1.5, 3}}, "(a) convex V"},
                          {notch_r, {11, 0}, {{6, 3}, {3, 5}}, "(b) reflex V"}};
  for (const Panel& pn : panels) {
    std::vector<Vec2d> moved;
    for (const Vec2d& q : p) moved.push_back(pn.off + q);
    draw_cone(w, p, pn.vertex, 1.6, pn.off);
    w.polygon(moved, pen(c::black, 1.8));
    const Vec2d v = p[pn.vertex], vm = p[(pn.vertex + n - 1) % n], vp = p[(pn.vertex + 1) % n];
    for (std::size_t k = 0; k < pn.tests.size(); ++k) {
      const Vec2d q = pn.tests[k];
      const bool in = in_cone(vm, v, vp, q);
      const Side near = classify_polygon(v + 1e-4 * (q - v), std::span<const Vec2d>(p));
      if (near != (in ? Side::inside : Side::outside)) return false;
      const char* col = in ? c::blue : c::red;
      w.segment(pn.off + v, pn.off + q, dashed(col, 1.4));
      point(w, pn.off + q, "W" + std::to_string(k) + (in ? " in" : " out"), col);
    }
    point(w, pn.off + v, "V", c::green);
    w.text(pn.off + Vec2d{0, -1.2}, pn.name, text_style(c::black, 0, 0));
  }
  return true;
}

// 13.56: the sample polygon, its edges labelled s1 .. s9 in the (random) order in which the
// trapezoidal map figures 13.57-13.67 insert them.
bool fig_13_56(SvgWriter& w) {
  const Sample& s = book_sample();
  draw_polygon(w, s, {0, 0});
  for (std::size_t k = 0; k < sample_polygon_edges.size(); ++k) {
    const Vec2d a = s.points[sample_polygon_edges[k][0]], b = s.points[sample_polygon_edges[k][1]];
    label(w, 0.5 * (a + b), "s" + std::to_string(k + 1), c::black, 4, 4);
  }
  for (const Vec2d& p : s.points) w.point(p, dot(c::black, 2.6));
  return polygon_twice_area(s) > 0;
}

// 13.68: the sample polygon's trapezoids, each as large as it can be (one horizontal segment from
// each vertex to the nearest edges on either side, inside the polygon).
bool fig_13_68(SvgWriter& w) {
  const Sample& s = book_sample();
  const auto d = trapezoid_decomposition(s.points, s.ends);
  if (d.status != Status::ok) return false;
  const char* cols[] = {c::blue, c::green, c::orange, c::purple};
  double sum = 0;
  for (std::size_t i = 0; i < d.trapezoids.size(); ++i) {
    const auto q = trapezoid_corners(std::span<const Vec2d>(s.points), d.trapezoids[i]);
    const std::vector<Vec2d> v(q.begin(), q.end());
    sum += twice_area(std::span<const Vec2d>(v));
    w.polygon(v, filled(cols[i % 4], 0.2, 1));
  }
  draw_polygon(w, s, {0, 0});
  w.text(Vec2d{0, -1.2}, std::to_string(d.trapezoids.size()) + " trapezoids",
         text_style(c::black, 0, 0));
  return close_area(s, sum);
}

// 13.69: the sample polygon as a union of monotone pieces in three shades of gray (locus's sweep
// adds one diagonal per split and merge vertex, red, so this polygon has three pieces where the
// book's has two), with the trapezoids' horizontal sides (dashed).
bool fig_13_69(SvgWriter& w) {
  const Sample& s = book_sample();
  const auto m = monotone_decomposition(s.points, s.ends);
  const auto d = trapezoid_decomposition(s.points, s.ends);
  if (m.status != Status::ok || d.status != Status::ok) return false;
  double sum = 0;
  std::uint32_t b = 0;
  for (std::size_t k = 0; k < m.piece_ends.size(); ++k) {
    std::vector<Vec2d> v;
    for (std::uint32_t i = b; i < m.piece_ends[k]; ++i) v.push_back(s.points[m.vertices[i]]);
    b = m.piece_ends[k];
    sum += twice_area(std::span<const Vec2d>(v));
    const double shade[] = {0.2, 0.65, 0.42};
    w.polygon(v, filled(c::gray, shade[k % 3], 1));
  }
  for (const auto& t : d.trapezoids) {
    const auto q = trapezoid_corners(std::span<const Vec2d>(s.points), t);
    w.segment(q[0], q[1], dashed(c::blue, 1));
    w.segment(q[3], q[2], dashed(c::blue, 1));
  }
  for (const auto& e : m.diagonals) w.segment(s.points[e[0]], s.points[e[1]], pen(c::red, 2));
  draw_polygon(w, s, {0, 0});
  w.text(Vec2d{0, -1.2}, std::to_string(m.piece_count()) + " monotone pieces",
         text_style(c::black, 0, 0));
  return close_area(s, sum);
}

// 13.70: a monotone piece of 13.69 whose triangle at an extreme vertex (the top, where
// triangulate_monotone's walk starts, or else the bottom) is an ear: the vertex is convex and the
// triangle holds no other vertex of the piece (exact orient2d and classify). Cutting it off
// leaves a polygon that monotone_decomposition again finds monotone (one piece).
bool fig_13_70(SvgWriter& w) {
  const Sample& s = book_sample();
  const auto m = monotone_decomposition(s.points, s.ends);
  if (m.status != Status::ok) return false;
  const auto above = [&](std::uint32_t a, std::uint32_t b) {  // monotone.hpp's sweep order
    return s.points[a].y > s.points[b].y ||
           (s.points[a].y == s.points[b].y && s.points[a].x < s.points[b].x);
  };
  for (std::size_t k = 0, b = 0; k < m.piece_ends.size(); b = m.piece_ends[k++]) {
    const std::vector<std::uint32_t> piece(m.vertices.begin() + std::ptrdiff_t(b),
                                           m.vertices.begin() + std::ptrdiff_t(m.piece_ends[k]));
    const std::size_t n = piece.size();
    if (n < 4) continue;
    std::size_t top = 0, bottom = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (above(piece[i], piece[top])) top = i;
      if (above(piece[bottom], piece[i])) bottom = i;
    }
    for (const std::size_t x : {top, bottom}) {
      const Vec2d& v0 = s.points[piece[(x + n - 1) % n]];
      const Vec2d& v = s.points[piece[x]];
      const Vec2d& v1 = s.points[piece[(x + 1) % n]];
      if (orient2d(v0, v, v1) != Sign::positive) continue;
      const Triangle2<double> ear{v0, v, v1};
      bool empty = true;
      for (std::size_t i = 0; i < n; ++i)
        if (i != x && i != (x + 1) % n && i != (x + n - 1) % n &&
            classify(s.points[piece[i]], ear) != Side::outside)
          empty = false;
      if (!empty) continue;
      std::vector<Vec2d> rest;
      for (std::size_t i = 0; i < n; ++i)
        if (i != x) rest.push_back(s.points[piece[i]]);
      const std::vector<std::uint32_t> rest_end{static_cast<std::uint32_t>(rest.size())};
      const auto again = monotone_decomposition(rest, rest_end);
      if (again.status != Status::ok || again.piece_count() != 1) return false;
      std::vector<Vec2d> whole;
      for (const std::uint32_t i : piece) whole.push_back(s.points[i]);
      w.polygon(s.points, dashed(c::gray, 1));
      w.polygon(rest, filled(c::light, 0.6, 2));
      w.polygon(std::vector<Vec2d>{v0, v, v1}, filled(c::red, 0.25, 2));
      point(w, v, x == top ? "extreme vertex (top)" : "extreme vertex (bottom)", c::red);
      w.text(Vec2d{0, -1.2},
             "ear cut: " + std::to_string(n) + " -> " + std::to_string(n - 1) +
                 " vertices, still monotone",
             text_style(c::black, 0, 0));
      return std::abs(twice_area(std::span<const Vec2d>(whole)) -
                      twice_area(std::span<const Vec2d>(rest)) -
                      twice_area(std::span<const Vec2d>(std::vector<Vec2d>{v0, v, v1}))) <= 1e-9;
    }
  }
  return false;  // no piece has an ear at an extreme vertex
}

// ---- 13.9.3 triangulating a monotone polygon: the reflex chain ------------------------------
// locus's walk sweeps from the top down; these figures draw the polygons upside down (y negated)
// so that it climbs from V_min as in the book. triangulate_monotone emits the triangles of each
// walk step together, all at the step's vertex W (the lowest of its three in sweep order), so
// the state before a step is the union of the triangles not yet emitted and the reflex chain is
// that region's vertices already passed.

Vec2d flip(const Vec2d& p) { return {p.x, -p.y}; }

// Sweep order of monotone.hpp: larger y first, ties by smaller x.
bool sweep_above(const std::vector<Vec2d>& pts, std::uint32_t a, std::uint32_t b) {
  return pts[a].y > pts[b].y || (pts[a].y == pts[b].y && pts[a].x < pts[b].x);
}

struct WalkStep {
  std::size_t begin, end;  // the step's triangles
  std::uint32_t w;         // the vertex processed
};

std::vector<WalkStep> walk_steps(const std::vector<Vec2d>& pts, const PolygonTriangulation& r) {
  std::vector<WalkStep> steps;
  for (std::size_t i = 0; i < r.triangles.size(); ++i) {
    std::uint32_t u = r.triangles[i][0];
    for (const std::uint32_t v : r.triangles[i])
      if (sweep_above(pts, u, v)) u = v;
    if (steps.empty() || steps.back().w != u)
      steps.push_back({i, i + 1, u});
    else
      steps.back().end = i + 1;
  }
  return steps;
}

// Boundary ring (counter-clockwise) of the union of triangles [from, end).
std::vector<std::uint32_t> remaining_ring(const PolygonTriangulation& r, std::size_t from) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::size_t i = from; i < r.triangles.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      edges.insert({r.triangles[i][k], r.triangles[i][(k + 1) % 3]});
  std::map<std::uint32_t, std::uint32_t> next;
  for (const auto& e : edges)
    if (!edges.count({e.second, e.first})) next[e.first] = e.second;
  std::vector<std::uint32_t> ring;
  if (next.empty()) return ring;
  std::uint32_t v = next.begin()->first;
  do {
    ring.push_back(v);
    v = next[v];
  } while (v != ring.front() && ring.size() <= next.size());
  return ring;
}

// The reflex chain: ring vertices above w in sweep order (or equal, if `with_w`), highest first.
std::vector<std::uint32_t> reflex_chain(const std::vector<Vec2d>& pts,
                                        const std::vector<std::uint32_t>& ring, std::uint32_t w,
                                        bool with_w) {
  std::vector<std::uint32_t> chain;
  for (const std::uint32_t v : ring)
    if (sweep_above(pts, v, w) || (with_w && v == w)) chain.push_back(v);
  std::sort(chain.begin(), chain.end(),
            [&](std::uint32_t a, std::uint32_t b) { return sweep_above(pts, a, b); });
  return chain;
}

bool ring_adjacent(std::size_t n, std::uint32_t a, std::uint32_t b) {
  return (a + 1) % n == b || (b + 1) % n == a;
}

// A y-monotone polygon (counter-clockwise): a reflex left chain T L1 L2 L3 L4, then W on the same
// side, then R2 on the other (the input of 13.72 and 13.73).
const std::vector<Vec2d> chain_polygon{{4, 10},     {3.6, 8},  {2.6, 6}, {1, 4.5}, {-1.5, 3.5},
                                       {-2.5, 2.5}, {-1, 0.5}, {2, -1},  {5, 1},   {5.5, 2}};

void draw_state(SvgWriter& w, const std::vector<Vec2d>& pts, const std::vector<std::uint32_t>& ring,
                const std::vector<std::uint32_t>& chain, const Vec2d& off) {
  std::vector<Vec2d> outer, region, path;
  for (const Vec2d& p : pts) outer.push_back(off + flip(p));
  for (const std::uint32_t v : ring) region.push_back(off + flip(pts[v]));
  for (const std::uint32_t v : chain) path.push_back(off + flip(pts[v]));
  w.polygon(outer, dashed(c::gray, 1));
  w.polygon(region, filled(c::gray, 0.15, 1.6));
  w.polyline(path, pen(c::red, 3));
  for (const Vec2d& q : path) w.point(q, dot(c::red, 3.5));
}

// One walk step: (a) the region before it, the reflex chain and the triangles the step cuts
// (W joined to the chain vertices it sees); (b) the region after, with its chain.
bool draw_walk_step(SvgWriter& w, const std::vector<Vec2d>& pts, const PolygonTriangulation& r,
                    const WalkStep& st) {
  const Vec2d off_b{10, 0};
  const auto before = remaining_ring(r, st.begin), after = remaining_ring(r, st.end);
  draw_state(w, pts, before, reflex_chain(pts, before, st.w, false), {0, 0});
  for (std::size_t i = st.begin; i < st.end; ++i) {
    std::vector<Vec2d> t;
    for (const std::uint32_t v : r.triangles[i]) t.push_back(flip(pts[v]));
    w.polygon(t, filled(c::blue, 0.3, 1));
  }
  point(w, flip(pts[st.w]), "W", c::blue);
  draw_state(w, pts, after, reflex_chain(pts, after, st.w, true), off_b);
  point(w, off_b + flip(pts[st.w]), "W", c::blue);
  w.text(Vec2d{-2.5, 1.6}, "(a)", text_style(c::black, 0, 0));
  w.text(off_b + Vec2d{-2.5, 1.6}, "(b)", text_style(c::black, 0, 0));
  return true;
}

// Checks: one monotone piece, status ok, n - 2 triangles.
bool monotone_walk(const std::vector<Vec2d>& pts, PolygonTriangulation& r) {
  const std::vector<std::uint32_t> ends{static_cast<std::uint32_t>(pts.size())};
  const auto m = monotone_decomposition(pts, ends);
  r = triangulate_monotone(pts, ends);
  return m.status == Status::ok && m.piece_count() == 1 && r.status == Status::ok &&
         r.triangles.size() + 2 == pts.size();
}

// 13.71: the triangle at the extreme vertex V_min (the walk's first, drawn lowest) and its
// neighbours V0, V1 holds a vertex of the other chain (classify(Triangle2)), so it is no ear;
// the triangles of triangulate_monotone (light) do not include it.
bool fig_13_71(SvgWriter& w) {
  const std::vector<Vec2d> pts{{4, 10}, {0, 4}, {1, 1.5}, {4, 0}, {9, 3}, {4.5, 6.5}, {8, 8}};
  PolygonTriangulation r;
  if (!monotone_walk(pts, r)) return false;
  const std::uint32_t vmin = 0, v0 = 1, v1 = 6, inside = 5;
  const Triangle2<double> tri{pts[v0], pts[vmin], pts[v1]};
  if (classify(pts[inside], tri) != Side::inside) return false;
  for (auto t : r.triangles) {
    std::sort(t.begin(), t.end());
    if (t == std::array<std::uint32_t, 3>{vmin, v0, v1}) return false;
  }
  for (const auto& t : r.triangles)
    w.polygon(std::vector<Vec2d>{flip(pts[t[0]]), flip(pts[t[1]]), flip(pts[t[2]])},
              filled(c::light, 0.25, 0.6));
  std::vector<Vec2d> outer;
  for (const Vec2d& p : pts) outer.push_back(flip(p));
  w.polygon(outer, pen(c::black, 2));
  w.polygon(std::vector<Vec2d>{flip(tri.v0), flip(tri.v1), flip(tri.v2)}, filled(c::red, 0.12, 2));
  point(w, flip(pts[vmin]), "Vmin");
  point(w, flip(pts[v0]), "V0");
  point(w, flip(pts[v1]), "V1");
  point(w, flip(pts[inside]), "inside", c::red);
  return true;
}

// 13.72: W on the chain's side sees only the lowest chain vertices (the walk stops at the first
// reflex turn), then W joins the chain.
bool fig_13_72(SvgWriter& w) {
  PolygonTriangulation r;
  if (!monotone_walk(chain_polygon, r)) return false;
  for (const WalkStep& st : walk_steps(chain_polygon, r)) {
    const auto chain = reflex_chain(chain_polygon, remaining_ring(r, st.begin), st.w, false);
    if (chain.size() >= 3 && ring_adjacent(chain_polygon.size(), st.w, chain.back()) &&
        st.end - st.begin < chain.size() - 1)
      return draw_walk_step(w, chain_polygon, r, st);
  }
  return false;
}

// 13.73: W on the other side sees every chain vertex: the whole fan is cut and the rest is a
// smaller monotone polygon.
bool fig_13_73(SvgWriter& w) {
  PolygonTriangulation r;
  if (!monotone_walk(chain_polygon, r)) return false;
  for (const WalkStep& st : walk_steps(chain_polygon, r)) {
    const auto chain = reflex_chain(chain_polygon, remaining_ring(r, st.begin), st.w, false);
    if (chain.size() >= 3 && ring_adjacent(chain_polygon.size(), st.w, chain.front()) &&
        st.end - st.begin == chain.size() - 1)
      return draw_walk_step(w, chain_polygon, r, st);
  }
  return false;
}

// ---- 13.9.4 convex partitioning ------------------------------------------------------------

// A polygon without holes with five reflex vertices (the input of 13.74-13.77).
const Sample& comb() {
  static const Sample s = {{{0, 0},
                            {10, 0},
                            {10, 6},
                            {8.4, 6},
                            {7.6, 2.4},
                            {6.4, 5.2},
                            {5, 2.2},
                            {3.6, 5.6},
                            {2.6, 2.6},
                            {1.6, 6.4},
                            {0, 4.4}},
                           {11}};
  return s;
}

bool draw_pieces(SvgWriter& w, const Sample& s, const ConvexPartition& r, const Vec2d& off) {
  if (r.status != Status::ok) return false;
  const char* cols[] = {c::blue, c::green, c::orange, c::purple, c::red};
  double sum = 0, whole = 0;
  std::uint32_t b = 0;
  for (std::size_t k = 0; k < r.piece_ends.size(); ++k) {
    std::vector<Vec2d> v;
    for (std::uint32_t i = b; i < r.piece_ends[k]; ++i) v.push_back(off + s.points[r.vertices[i]]);
    b = r.piece_ends[k];
    sum += twice_area(std::span<const Vec2d>(v));
    w.polygon(v, filled(cols[k % 5], 0.25, 1));
  }
  std::vector<Vec2d> outer;
  for (const auto& p : s.points) outer.push_back(off + p);
  whole = std::abs(twice_area(std::span<const Vec2d>(outer)));
  w.polygon(outer, pen(c::black, 2));
  return std::abs(sum - whole) <= 1e-9;
}

// 13.74: a partition into convex pieces using only the polygon's vertices (the minimum one).
bool fig_13_74(SvgWriter& w) {
  const Sample& s = comb();
  const auto r = min_convex_partition(s.points, s.ends);
  const bool ok = draw_pieces(w, s, r, {0, 0});
  w.text(Vec2d{0, -1.2}, std::to_string(r.piece_count()) + " convex pieces (min_convex_partition)",
         text_style(c::black, 0, 0));
  return ok;
}

// 13.75: Hertel-Mehlhorn. The triangulation's diagonals (dashed) are removed where both ends
// stay convex; the kept ones (red) are essential at a reflex end.
bool fig_13_75(SvgWriter& w) {
  const Sample& s = comb();
  const auto tri = triangulate_monotone(s.points, s.ends);
  const auto r = convex_partition(s.points, s.ends);
  if (tri.status != Status::ok) return false;
  const bool ok = draw_pieces(w, s, r, {0, 0});
  for (const auto& t : tri.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
      if ((a + 1) % 11 != b && (b + 1) % 11 != a)
        w.segment(s.points[a], s.points[b], dashed(c::gray, 1));
    }
  for (const auto& d : r.diagonals) w.segment(s.points[d[0]], s.points[d[1]], pen(c::red, 2.2));
  w.text(Vec2d{0, -1.2}, std::to_string(r.piece_count()) + " pieces (convex_partition)",
         text_style(c::black, 0, 0));
  return ok;
}

// 13.76: the minimum convex decomposition beside Hertel-Mehlhorn's.
bool fig_13_76(SvgWriter& w) {
  const Sample& s = comb();
  const auto m = min_convex_partition(s.points, s.ends);
  const auto h = convex_partition(s.points, s.ends);
  const bool ok = draw_pieces(w, s, m, {0, 0}) && draw_pieces(w, s, h, {12, 0});
  w.text(Vec2d{0, -1.2}, "minimum: " + std::to_string(m.piece_count()), text_style(c::black, 0, 0));
  w.text(Vec2d{12, -1.2}, "Hertel-Mehlhorn: " + std::to_string(h.piece_count()),
         text_style(c::black, 0, 0));
  return ok && m.piece_count() <= h.piece_count();
}

// 13.77: canonical triangulations: each piece of the minimum decomposition fanned from its
// first vertex (light lines); the decomposition's diagonals dotted.
bool fig_13_77(SvgWriter& w) {
  const Sample& s = comb();
  const auto r = min_convex_partition(s.points, s.ends);
  if (r.status != Status::ok) return false;
  std::uint32_t b = 0;
  for (const std::uint32_t e : r.piece_ends) {
    for (std::uint32_t i = b + 2; i + 1 < e; ++i)
      w.segment(s.points[r.vertices[b]], s.points[r.vertices[i]], pen(c::light, 1.2));
    b = e;
  }
  for (const auto& d : r.diagonals) w.segment(s.points[d[0]], s.points[d[1]], dashed(c::blue, 1.6));
  std::vector<Vec2d> outer(s.points.begin(), s.points.end());
  w.polygon(outer, pen(c::black, 2.4));
  return true;
}

}  // namespace

std::vector<Figure> chapter13_polytri_figures() {
  std::vector<Figure> figs = {
      {"13.53", "triangulate_ear_clipping", fig_13_53},
      {"13.54",
       "orient2d (reflex), classify(Triangle2), intersects(Segment2), triangulate_ear_clipping",
       fig_13_54},
      {"13.55", "orient2d cone test; classify_polygon next to V", fig_13_55},
      {"13.56", "the input of the trapezoid and monotone figures (13.57-13.70)", fig_13_56},
      {"13.68", "trapezoid_decomposition, trapezoid_corners", fig_13_68},
      {"13.69", "monotone_decomposition, trapezoid_decomposition", fig_13_69},
      {"13.70", "monotone_decomposition, orient2d, classify(Triangle2)", fig_13_70},
      {"13.71", "monotone_decomposition, triangulate_monotone, classify(Triangle2)", fig_13_71},
      {"13.72", "triangulate_monotone (its walk steps in emission order)", fig_13_72},
      {"13.73", "triangulate_monotone (its walk steps in emission order)", fig_13_73},
      {"13.74", "min_convex_partition", fig_13_74},
      {"13.75", "triangulate_monotone, convex_partition (Hertel-Mehlhorn)", fig_13_75},
      {"13.76", "min_convex_partition, convex_partition", fig_13_76},
      {"13.77", "min_convex_partition; fans of its pieces", fig_13_77},
  };
  // The incremental trapezoidal map's figures (13.57-13.67) live in ch13_trapezoid_map.cpp.
  for (const Figure& f : chapter13_trapmap_figures()) figs.push_back(f);
  return figs;
}

}  // namespace locus_gallery
