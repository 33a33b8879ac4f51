// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 13.9: polygon triangulation. Ear clipping (13.53), the horizontal
// trapezoidal decomposition (13.56, 13.68), the monotone pieces (13.69) and the triangulation of
// the monotone pieces (13.70), convex partitions (13.74-13.77). Every figure draws what locus
// computes: triangulate_ear_clipping, trapezoid_decomposition (+ trapezoid_corners),
// monotone_decomposition and triangulate_monotone on one sample polygon with a hole; a figure fails
// when the status is not ok or the pieces' area differs from the polygon's.
#include "gallery.hpp"

#include <locus/triangulate/convex_partition.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>
#include <locus/triangulate/trapezoid_decomposition.hpp>

#include <cmath>
#include <cstdint>
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

// A polygon with split and merge vertices and one hole (the inputs of every figure).
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

double polygon_twice_area() {
  const Sample& s = sample();
  const std::span<const Vec2d> pts(s.points);
  return std::abs(twice_area(pts.subspan(0, 11))) - std::abs(twice_area(pts.subspan(11, 3)));
}

bool close_area(double a) { return std::abs(a - polygon_twice_area()) <= 1e-9; }

void draw_polygon(SvgWriter& w, const Vec2d& off) {
  const Sample& s = sample();
  std::vector<Vec2d> outer, hole;
  for (std::uint32_t i = 0; i < 11; ++i) outer.push_back(off + s.points[i]);
  for (std::uint32_t i = 11; i < 14; ++i) hole.push_back(off + s.points[i]);
  w.polygon(outer, pen(c::black, 2));
  w.polygon(hole, pen(c::black, 2));
}

bool draw_triangles(SvgWriter& w, const PolygonTriangulation& r, const Vec2d& off,
                    const char* col) {
  if (r.status != Status::ok) return false;
  const Sample& s = sample();
  double sum = 0;
  for (const auto& t : r.triangles) {
    const std::vector<Vec2d> v{off + s.points[t[0]], off + s.points[t[1]], off + s.points[t[2]]};
    sum += twice_area(std::span<const Vec2d>(v));
    w.polygon(v, filled(col, 0.15, 1));
  }
  draw_polygon(w, off);
  return close_area(sum);
}

// 13.53: the diagonals ear clipping finds (each triangle's third side joins mutually visible
// vertices; the hole is joined by a bridge).
bool fig_13_53(SvgWriter& w) {
  const Sample& s = sample();
  const auto r = triangulate_ear_clipping(s.points, s.ends);
  const bool ok = draw_triangles(w, r, {0, 0}, c::blue);
  w.text(Vec2d{0, -1.2},
         std::to_string(r.triangles.size()) + " ears cut (triangulate_ear_clipping)",
         text_style(c::black, 0, 0));
  return ok;
}

// 13.56: the sample polygon, its vertices numbered.
bool fig_13_56(SvgWriter& w) {
  const Sample& s = sample();
  draw_polygon(w, {0, 0});
  for (std::size_t i = 0; i < s.points.size(); ++i)
    point(w, s.points[i], "V" + std::to_string(i), i < 11 ? c::black : c::red);
  return true;
}

// 13.68: the trapezoids of the horizontal decomposition (one horizontal segment from each
// vertex to the nearest edges on either side).
bool fig_13_68(SvgWriter& w) {
  const Sample& s = sample();
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
  draw_polygon(w, {0, 0});
  w.text(Vec2d{0, -1.2}, std::to_string(d.trapezoids.size()) + " trapezoids",
         text_style(c::black, 0, 0));
  return std::abs(sum - polygon_twice_area()) <= 1e-9;
}

// 13.69: the monotone pieces (light and dark gray alternate), with the trapezoid sides.
bool fig_13_69(SvgWriter& w) {
  const Sample& s = sample();
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
    w.polygon(v, filled(k % 2 ? c::gray : c::light, 0.6, 1));
  }
  for (const auto& t : d.trapezoids) {
    const auto q = trapezoid_corners(std::span<const Vec2d>(s.points), t);
    w.segment(q[0], q[1], dashed(c::blue, 1));
    w.segment(q[3], q[2], dashed(c::blue, 1));
  }
  for (const auto& e : m.diagonals) w.segment(s.points[e[0]], s.points[e[1]], pen(c::red, 2));
  draw_polygon(w, {0, 0});
  return close_area(sum);
}

// 13.70: the monotone pieces triangulated by the stack walk.
bool fig_13_70(SvgWriter& w) {
  const Sample& s = sample();
  const auto r = triangulate_monotone(s.points, s.ends);
  const bool ok = draw_triangles(w, r, {0, 0}, c::green);
  w.text(Vec2d{0, -1.2}, std::to_string(r.triangles.size()) + " triangles (triangulate_monotone)",
         text_style(c::black, 0, 0));
  return ok;
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
      {"13.56", "the input of the trapezoid and monotone figures", fig_13_56},
      {"13.68", "trapezoid_decomposition, trapezoid_corners", fig_13_68},
      {"13.69", "monotone_decomposition, trapezoid_decomposition", fig_13_69},
      {"13.70", "triangulate_monotone", fig_13_70},
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
