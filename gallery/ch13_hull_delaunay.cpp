// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 13: point in polygon and polyhedron (13.13-13.18), convex hulls in 2D and 3D
// (13.32-13.41), Delaunay triangulation (13.43-13.52), circumscribed and inscribed circles
// (13.78), minimum bounding shapes (13.79, 13.80) and areas (13.81).
//
// Every figure computes what it shows with locus: classifications come from locus::classify /
// classify_convex, hulls from locus::convex_hull (2D and 3D), triangulations from
// locus::delaunay / locate, bounding shapes from min_rect / min_circle, circles from
// circumscribed_circle / inscribed_circle, visibility and in-circle decisions from the exact
// predicates orient2d / orient3d / incircle. Figures of an algorithm's intermediate state
// compute each state with the public API: the hull of the points so far, the hulls of the two
// halves and of their union, the Delaunay triangulation of the points inserted so far. The
// tangent walks of 13.37 and 13.38 step with exact orient2d and must end on the bridge edge of
// the union's hull, or the figure reports failure; likewise every figure cross-checks the
// state it draws against an independent locus computation where one exists.
#include "gallery.hpp"

#include <locus/bounding/min_circle.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/bounding/simplex_balls.hpp>
#include <locus/containment/point_in_polygon.hpp>
#include <locus/containment/point_in_polyhedron.hpp>
#include <locus/core/angle.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/products.hpp>
#include <locus/delaunay/delaunay2.hpp>
#include <locus/distance/line_segment.hpp>
#include <locus/distance/ray_segment.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/hull/hull2.hpp>
#include <locus/hull/hull3.hpp>
#include <locus/io/svg_primitives.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/polygon.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;
using Idx = std::uint32_t;
using Tri = std::array<Idx, 3>;

std::string fmt(double x, int prec = 2) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, x);
  return buf;
}

const char* side_name(Side s) {
  return s == Side::inside ? "inside" : s == Side::outside ? "outside" : "boundary";
}

std::vector<Vec2d> pick(const std::vector<Vec2d>& pts, std::span<const Idx> idx) {
  std::vector<Vec2d> out;
  for (Idx i : idx) out.push_back(pts[i]);
  return out;
}

/// The 2D hull of `pts` as a counter-clockwise index list; empty unless it is a polygon.
std::vector<Idx> hull_indices(const std::vector<Vec2d>& pts) {
  const Hull2Result r = convex_hull(pts);
  if (r.status != Status::ok || r.dimension != 2) return {};
  return r.indices;
}

/// A text label below-left of p, without a marker.
void caption_at(SvgWriter& w, const Vec2d& p, std::string_view s, const char* col = c::black,
                double size = 14) {
  w.text(p, s, text_style(col, 0, 0, SvgAnchor::start, size));
}

/// The part of a circle inside the box [lo, hi], sampled (the gallery test wants every
/// coordinate inside the document, and a fixed view does not clip).
void clipped_circle(SvgWriter& w, const Circle2<double>& circ, const Vec2d& lo, const Vec2d& hi,
                    const SvgStyle& s) {
  const int n = 720;
  std::vector<Vec2d> run;
  for (int k = 0; k <= n; ++k) {
    const double t = 2.0 * 3.14159265358979323846 * k / n;
    const Vec2d p = circ.center + circ.radius * Vec2d{std::cos(t), std::sin(t)};
    if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y) {
      run.push_back(p);
    } else {
      if (run.size() > 1) w.polyline(run, s);
      run.clear();
    }
  }
  if (run.size() > 1) w.polyline(run, s);
}

// ---- 13.2 point in polygon -------------------------------------------------------------------

// 13.13: point in a convex polygon. locus::classify_convex decides (a fan search); the edges the
// vertical line through each point crosses are found by exact x comparisons and their crossing
// points by locus::distance(Line2, Segment2).
bool fig_13_13(SvgWriter& w) {
  const std::vector<Vec2d> poly{{0, 0},     {3, -0.6}, {5, 0.6},   {5.4, 2.4},
                                {3.6, 3.8}, {1, 3.4},  {-0.6, 1.8}};
  if (!polygon_is_convex(std::span<const Vec2d>(poly))) return false;
  w.polygon(poly, filled(c::gray, 0.12, 1.6));
  const std::pair<Vec2d, const char*> queries[] = {{{2.6, 1.5}, "P"}, {{4.2, 3.9}, "Q"}};
  for (const auto& [p, name] : queries) {
    const Side s = classify_convex(p, std::span<const Vec2d>(poly));
    const char* col = s == Side::outside ? c::red : c::blue;
    const Line2<double> vertical{p, {0, 1}};
    int crossed = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2d a = poly[i], b = poly[(i + 1) % poly.size()];
      if ((a.x < p.x) == (b.x < p.x)) continue;  // the edge lies on one side of the line
      ++crossed;
      w.segment(a, b, pen(col, 3));
      w.point(distance(vertical, Segment2<double>{a, b}).closest[1], dot(col, 3));
    }
    if (crossed != 2) return false;
    w.segment(Vec2d{p.x, -1.2}, Vec2d{p.x, 4.6}, dashed(c::gray, 1));
    point(w, p, std::string(name) + ": " + side_name(s), col);
  }
  return true;
}

// The polygon of 13.14, 13.16 and 13.17: notches meet the line y = 2 at a vertex (x = 10), along
// a horizontal edge (4.5 <= x <= 6.5) and the right side passes through y = 2 at a vertex.
const std::vector<Vec2d> crossing_polygon{{0, 0}, {14, 0}, {14, 2},  {14.5, 6}, {11, 6}, {10, 2},
                                          {9, 6}, {7, 6},  {6.5, 2}, {4.5, 2},  {4, 6},  {0, 6}};

// 13.14: crossing number of the ray from P along +x. The crossings are the edges the ray meets
// (locus::distance(Ray2, Segment2) == 0); the answer is locus::classify(p, Polygon2).
bool fig_13_14(SvgWriter& w) {
  const Polygon2<double> poly{crossing_polygon};
  draw(w, poly, filled(c::gray, 0.15, 1.6));
  const std::pair<Vec2d, const char*> queries[] = {{{1, 4}, "P\u2080"}, {{1, 2}, "P\u2081"}};
  for (const auto& [p, name] : queries) {
    const Ray2<double> ray{p, {1, 0}};
    const bool generic = p.y == 4;
    const char* col = generic ? c::blue : c::orange;
    w.segment(p, Vec2d{16, p.y}, pen(col, 1.2));
    int hits = 0;
    for (std::size_t i = 0; i < poly.vertices.size(); ++i) {
      const Segment2<double> e{poly.vertices[i], poly.vertices[(i + 1) % poly.vertices.size()]};
      const auto d = distance(ray, e);
      if (d.distance > 1e-12) continue;
      ++hits;
      if (!d.unique) w.segment(e.p0, e.p1, pen(col, 3.5));  // the ray runs along the edge
      w.point(d.closest[1], dot(col, 3.2));
    }
    const Side s = classify(p, poly);
    point(w, p, name, col);
    caption_at(w, Vec2d{0.2, p.y - 0.75},
               generic ? std::to_string(hits) + " transverse crossings: " + side_name(s)
                       : std::string("through vertices and an edge: ") + side_name(s),
               col, 13);
  }
  return true;
}

// 13.15: the half-open rule on the boundary. A point on an edge is tested by the ray along +x
// counting only edges strictly to its right (locus's exact per-edge event, the one
// classify(Polygon2) uses, with "on this edge" counted as no crossing): on a "left" edge the
// point is inside (P), on a "right" edge outside (Q). Checked: classify() puts every point on
// the boundary, and the rule's answer is classify() of the point nudged right (and, much less, up).
bool fig_13_15(SvgWriter& w) {
  const std::vector<Vec2d> poly{{0, 0}, {10, 0}, {10, 6}, {7, 3}, {6, 8}, {2, 8}, {3, 4}, {0, 5}};
  const std::span<const Vec2d> ring(poly);
  w.polygon(poly, filled(c::gray, 0.15, 1.6));
  int np = 0, nq = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2d a = poly[i], b = poly[(i + 1) % poly.size()];
    const Vec2d m = 0.5 * (a + b);  // exact: even integer coordinates
    if (classify_polygon(m, ring) != Side::boundary) return false;
    int crossings = 0;
    for (std::size_t j = 0; j < poly.size(); ++j) {
      int dir = 0;
      if (detail::edge_ray_event(poly[j], poly[(j + 1) % poly.size()], m, dir) == 1) ++crossings;
    }
    const bool inside = crossings % 2 == 1;
    const Side nudged = classify_polygon(m + Vec2d{1e-6, 1e-9}, ring);
    if (nudged != (inside ? Side::inside : Side::outside)) return false;
    const char* col = inside ? c::blue : c::red;
    w.segment(a, b, pen(col, 3));
    point(w, m, inside ? "P" + std::to_string(np++) : "Q" + std::to_string(nq++), col);
  }
  caption_at(w, Vec2d{0, -1.2}, "on a left edge: inside (P); on a right edge: outside (Q)");
  return true;
}

// The points where the horizontal line through y meets the boundary (a vertex or an edge point
// per locus::distance(Line2, Segment2) == 0; both end points of an edge lying on the line),
// sorted by x.
std::vector<double> line_boundary_points(const std::vector<Vec2d>& poly, double y) {
  const Line2<double> line{{0, y}, {1, 0}};
  std::vector<double> xs;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Segment2<double> e{poly[i], poly[(i + 1) % poly.size()]};
    const auto d = distance(line, e);
    if (d.distance > 1e-12) continue;
    if (d.unique) {
      xs.push_back(d.closest[1].x);
    } else {
      xs.push_back(e.p0.x);
      xs.push_back(e.p1.x);
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  return xs;
}

// Side of the open interval (x0, x1) of the line at height y, classified at its middle.
Side interval_side(const std::vector<Vec2d>& poly, double y, double x0, double x1) {
  return classify_polygon(Vec2d{0.5 * (x0 + x1), y}, std::span<const Vec2d>(poly));
}

const char* short_side(Side s) {
  return s == Side::inside ? "in" : s == Side::outside ? "out" : "on";
}

// 13.16: the tags of the points where the line through P1 meets the boundary: the sides
// (locus::classify_polygon) of the intervals before and after each point.
bool fig_13_16(SvgWriter& w) {
  const double y = 2;
  w.polygon(crossing_polygon, filled(c::gray, 0.15, 1.2));
  w.segment(Vec2d{-1, y}, Vec2d{16, y}, pen(c::orange, 1.2));
  const std::vector<double> xs = line_boundary_points(crossing_polygon, y);
  if (xs.empty()) return false;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double before = i == 0 ? xs[0] - 1 : xs[i - 1];
    const double after = i + 1 == xs.size() ? xs[i] + 1 : xs[i + 1];
    const Vec2d q{xs[i], y};
    if (classify_polygon(q, std::span<const Vec2d>(crossing_polygon)) != Side::boundary)
      return false;
    w.point(q, dot(c::orange, 3.5));
    const std::string tag =
        std::string(short_side(interval_side(crossing_polygon, y, before, xs[i]))) + "|" +
        short_side(interval_side(crossing_polygon, y, xs[i], after));
    w.text(q, tag, text_style(c::black, 0, i % 2 ? 10 : -20, SvgAnchor::middle, 13));
  }
  point(w, Vec2d{1, y}, "P\u2081", c::orange);
  return true;
}

// 13.17: the tags of the intervals between those points (locus::classify_polygon at each
// interval's middle): inside blue, outside red, on the boundary orange.
bool fig_13_17(SvgWriter& w) {
  const double y = 2;
  w.polygon(crossing_polygon, filled(c::gray, 0.15, 1.2));
  std::vector<double> xs = line_boundary_points(crossing_polygon, y);
  if (xs.empty()) return false;
  xs.insert(xs.begin(), -1.0);
  xs.push_back(16.0);
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const Side s = interval_side(crossing_polygon, y, xs[i], xs[i + 1]);
    const char* col = s == Side::inside ? c::blue : s == Side::outside ? c::red : c::orange;
    w.segment(Vec2d{xs[i], y}, Vec2d{xs[i + 1], y}, pen(col, 4));
    w.text(Vec2d{0.5 * (xs[i] + xs[i + 1]), y}, short_side(s),
           text_style(col, 0, i % 2 ? 8 : -20, SvgAnchor::middle, 13));
  }
  for (std::size_t i = 1; i + 1 < xs.size(); ++i) w.point(Vec2d{xs[i], y}, dot(c::black, 3));
  return true;
}

// ---- 3D helpers ------------------------------------------------------------------------------

std::vector<Vec3d> pick3(const std::vector<Vec3d>& pts, std::span<const Idx> idx) {
  std::vector<Vec3d> out;
  for (Idx i : idx) out.push_back(pts[i]);
  return out;
}

Vec3d face_normal(const std::vector<Vec3d>& v, const Tri& t) {
  return cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]);
}

// Whether triangle t faces the (orthographic) camera of w.
bool front_facing(const SvgWriter& w, const std::vector<Vec3d>& v, const Tri& t) {
  return dot(face_normal(v, t), w.camera().eye - w.camera().target) > 0;
}

// Triangle indices sorted far to near along the camera's view direction (painter's order).
std::vector<std::size_t> back_to_front(const SvgWriter& w, const std::vector<Vec3d>& v,
                                       const std::vector<Tri>& tris) {
  const Vec3d view = w.camera().target - w.camera().eye;
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t i = 0; i < tris.size(); ++i)
    order.emplace_back(-dot((v[tris[i][0]] + v[tris[i][1]] + v[tris[i][2]]) / 3.0, view), i);
  std::sort(order.begin(), order.end());
  std::vector<std::size_t> out;
  for (const auto& o : order) out.push_back(o.second);
  return out;
}

using EdgeKey = std::pair<Idx, Idx>;
EdgeKey edge_key(Idx a, Idx b) { return a < b ? EdgeKey{a, b} : EdgeKey{b, a}; }

// The undirected edges of a triangle mesh with the triangles using each.
std::map<EdgeKey, std::vector<std::size_t>> edge_faces(const std::vector<Tri>& tris) {
  std::map<EdgeKey, std::vector<std::size_t>> m;
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (std::size_t e = 0; e < 3; ++e) m[edge_key(tris[i][e], tris[i][(e + 1) % 3])].push_back(i);
  return m;
}

SvgStyle dotted_pen(const char* col, double width = 1.4) {
  SvgStyle s = pen(col, width);
  s.dash = {1.5, 3.5};
  return s;
}

// ---- 13.3 point in polyhedron ------------------------------------------------------------------

struct Mesh3 {
  std::vector<Vec3d> v;
  std::vector<Tri> t;
};

// The octahedron |x| + |y| + |z| <= 1, triangles counter-clockwise seen from outside.
Mesh3 octahedron(const Vec3d& at) {
  Mesh3 m;
  m.v = {at + Vec3d{1, 0, 0},  at + Vec3d{-1, 0, 0}, at + Vec3d{0, 1, 0},
         at + Vec3d{0, -1, 0}, at + Vec3d{0, 0, 1},  at + Vec3d{0, 0, -1}};
  m.t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// 13.18: a ray from p along +x through the interior of an edge shared by two faces. (a) Both
// faces lie on one side of the plane of the edge and the ray (exact orient3d): the ray grazes,
// parity unchanged; (b) opposite sides: the ray crosses. The hit point is where
// locus::distance(Ray3, Segment3) is 0; the answer is locus::classify(p, mesh).
bool fig_13_18(SvgWriter& w) {
  w.set_camera(camera({3.0, -8, 3.0}, {2.4, 0, 0}));
  struct Case {
    Vec3d at, p;
    Idx e0, e1;  // the shared edge
    const char* name;
  };
  const Case cases[] = {{{0, 0, 0}, {-1.6, -0.5, 0.5}, 3, 4, "(a)"},
                        {{4.6, 0, 0}, {4.6, -0.5, 0}, 0, 3, "(b)"}};
  for (const Case& k : cases) {
    const Mesh3 m = octahedron(k.at);
    const Vec3d a = m.v[k.e0], b = m.v[k.e1];
    const Vec3d dir{1, 0, 0};
    const auto hit = distance(Ray3<double>{k.p, dir}, Segment3<double>{a, b});
    if (hit.distance > 1e-12) return false;
    const Vec3d h = hit.closest[0];
    // The two faces on the edge and their sides of the plane through a, b and the ray.
    int sides[2] = {0, 0}, found = 0;
    for (const Tri& t : m.t) {
      for (int i = 0; i < 3; ++i) {
        const Idx u = t[static_cast<std::size_t>(i)], v = t[static_cast<std::size_t>((i + 1) % 3)];
        if (!((u == k.e0 && v == k.e1) || (u == k.e1 && v == k.e0))) continue;
        const Vec3d third = m.v[t[static_cast<std::size_t>((i + 2) % 3)]];
        if (found < 2) sides[found++] = to_int(orient3d(a, b, h + dir, third));
        closed(w, std::vector<Vec3d>{m.v[t[0]], m.v[t[1]], m.v[t[2]]},
               filled(sides[found - 1] > 0 ? c::blue : c::green, 0.35, 1));
      }
    }
    if (found != 2) return false;
    for (const Tri& t : m.t)
      for (int i = 0; i < 3; ++i) {
        const Idx u = t[static_cast<std::size_t>(i)], v = t[static_cast<std::size_t>((i + 1) % 3)];
        if (u < v) w.segment(m.v[u], m.v[v], pen(c::black, 0.8));
      }
    w.segment(a, b, pen(c::red, 3));
    w.arrow(k.p, h + 1.3 * dir, pen(c::black, 1.4));
    w.point(h, dot(c::red, 4));
    const Side s = classify(k.p, std::span<const Vec3d>(m.v), std::span<const Tri>(m.t));
    point(w, k.p, "p", c::black);
    const bool same = sides[0] == sides[1];
    w.text(k.at + Vec3d{0, 0, -1.3},
           std::string(k.name) +
               (same ? " faces on one side: parity kept" : " faces on both sides: parity toggled"),
           text_style(c::black, 0, 0, SvgAnchor::middle, 12));
    w.text(k.at + Vec3d{0, 0, -1.3}, std::string("classify(p) = ") + side_name(s),
           text_style(c::black, 0, -16, SvgAnchor::middle, 12));
  }
  return true;
}

// 13.19: the spherical polygon cut from a small sphere about the vertex V by the cone of the
// edges at V (a pyramid, locus::convex_hull). A ray through V whose direction points into the
// cone (A) interpenetrates the polyhedron; one pointing outside it (B) only touches V. Which
// case holds is decided by locus::classify_convex of a point just past V along the ray.
bool fig_13_19(SvgWriter& w) {
  std::vector<Vec3d> v{{0, 0, 2}};
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * 3.14159265358979 * i / 5 + 0.3;
    v.push_back({1.7 * std::cos(a), 1.7 * std::sin(a), 0});
  }
  const Hull3Result h = convex_hull(v);
  if (h.status != Status::ok || h.dimension != 3) return false;
  const Vec3d apex = v[0];
  const double r = 0.75;
  w.set_camera(camera({6, -7, 4.0}, {0, 0, 1.2}));
  for (std::size_t i : back_to_front(w, v, h.triangles)) {
    const Tri& t = h.triangles[i];
    if (!front_facing(w, v, t)) continue;
    SvgStyle st = filled(c::gray, 0.12, 0.6);
    st.stroke = "none";
    closed(w, pick3(v, t), st);
  }
  for (const auto& [e, faces] : edge_faces(h.triangles)) {
    bool front = false;
    for (std::size_t f : faces) front = front || front_facing(w, v, h.triangles[f]);
    SvgStyle st = pen(c::black, 1.2);
    if (!front) {
      st.dash = {4, 3};
      st.opacity = 0.4;
    }
    w.segment(v[e.first], v[e.second], st);
  }
  // The sphere about V (three great circles) and the spherical polygon: arcs between the unit
  // directions of consecutive edges at V (the base ring order).
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<Vec3d> ring;
    for (int k = 0; k <= 96; ++k) {
      const double t = 2 * 3.14159265358979 * k / 96;
      Vec3d d{};
      d[axis] = std::cos(t);
      d[(axis + 1) % 3] = std::sin(t);
      ring.push_back(apex + r * d);
    }
    SvgStyle st = pen(c::light, 0.8);
    w.polyline(ring, st);
  }
  std::vector<Vec3d> poly;
  for (std::size_t i = 1; i <= 5; ++i) {
    const Vec3d u0 = normalize(v[i] - apex), u1 = normalize(v[i % 5 + 1] - apex);
    for (int k = 0; k < 16; ++k) poly.push_back(apex + r * normalize(lerp(u0, u1, k / 16.0)));
  }
  closed(w, poly, filled(c::blue, 0.25, 1.8));
  const std::pair<Vec3d, const char*> rays[] = {{normalize(Vec3d{0.25, 0.1, -1}), "A"},
                                                {normalize(Vec3d{-1, -0.3, -0.12}), "B"}};
  std::string verdict;
  for (const auto& [d, name] : rays) {
    const bool enters = classify_convex(apex + 0.05 * d, std::span<const Vec3d>(v),
                                        std::span<const Tri>(h.triangles)) == Side::inside;
    const char* col = enters ? c::green : c::red;
    w.segment(apex - 2.2 * d, apex, pen(col, 1.4));
    SvgStyle after = pen(col, 1.4);
    if (enters) after.dash = {4, 3};
    w.arrow(apex, apex + (enters ? 1.2 : 2.0) * d, after);
    point(w, apex + r * d, name, col);
    verdict += std::string(verdict.empty() ? "" : "; ") + name +
               (enters ? ": ray enters (parity toggles)" : ": ray touches V only");
  }
  point(w, apex, "V", c::black);
  w.text(Vec3d{0, 0, -0.6}, verdict, text_style(c::black, 0, -10, SvgAnchor::middle, 12));
  return true;
}

// ---- 13.6 convex hulls -------------------------------------------------------------------------

// 13.32: (a) a convex set: the segment between any two of its points stays inside; (b) a set
// that is not convex (locus::polygon_is_convex): the segment PQ leaves it. The segment is split
// where locus::distance(Segment2, Segment2) meets an edge, each piece classified at its middle.
bool fig_13_32(SvgWriter& w) {
  const std::vector<Vec2d> a{{0, 0}, {2.6, -0.3}, {3.4, 1.4}, {2.2, 3}, {0.2, 2.6}, {-0.6, 1.2}};
  const std::vector<Vec2d> b{{4.6, 0},   {8, 0},     {8, 3},   {6.9, 3},
                             {6.9, 0.9}, {5.7, 0.9}, {5.7, 3}, {4.6, 3}};
  const std::pair<const std::vector<Vec2d>*, std::pair<Vec2d, Vec2d>> sets[] = {
      {&a, {{0.4, 0.6}, {2.4, 2.2}}}, {&b, {{5.1, 2.5}, {7.5, 2.3}}}};
  for (const auto& [poly, pq] : sets) {
    const std::span<const Vec2d> ring(*poly);
    const bool convex = polygon_is_convex(ring);
    w.polygon(*poly, filled(c::gray, 0.15, 1.5));
    const auto [p, q] = pq;
    if (classify_polygon(p, ring) != Side::inside || classify_polygon(q, ring) != Side::inside)
      return false;
    std::vector<double> ts{0, 1};
    const Segment2<double> pqs{p, q};
    for (std::size_t i = 0; i < poly->size(); ++i) {
      const auto d = distance(pqs, Segment2<double>{(*poly)[i], (*poly)[(i + 1) % poly->size()]});
      if (d.distance <= 1e-12) ts.push_back(d.param_a);
    }
    std::sort(ts.begin(), ts.end());
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      const Vec2d m = point_at(pqs, 0.5 * (ts[i] + ts[i + 1]));
      const bool out = classify_polygon(m, ring) == Side::outside;
      w.segment(point_at(pqs, ts[i]), point_at(pqs, ts[i + 1]), pen(out ? c::red : c::blue, 2.2));
    }
    point(w, p, "P", c::blue);
    point(w, q, "Q", c::blue);
    caption_at(w, Vec2d{(*poly)[0].x, -0.9},
               std::string(poly == &a ? "(a) " : "(b) ") + (convex ? "convex" : "not convex"));
  }
  return true;
}

// A fixed scattered point set (the input of the 2D hull figures).
const std::vector<Vec2d> scatter{
    {0.2, 1.1}, {1.3, 0.2}, {2.6, 0.5}, {3.8, 0.1}, {4.6, 1.2}, {4.9, 2.6}, {4.1, 3.7}, {2.9, 4.2},
    {1.4, 3.9}, {0.4, 2.9}, {1.2, 1.4}, {2.1, 1.9}, {3.2, 1.3}, {3.6, 2.6}, {2.5, 3.1}, {1.5, 2.7},
    {2.9, 2.2}, {1.9, 0.9}, {3.9, 1.8}, {0.9, 2.2}, {2.2, 3.6}, {3.4, 3.4}, {4.2, 0.7}, {0.7, 0.6}};

// 13.33: a point set and its convex hull (locus::convex_hull): hull vertices black.
bool fig_13_33(SvgWriter& w) {
  const std::vector<Idx> h = hull_indices(scatter);
  if (h.empty()) return false;
  w.polygon(pick(scatter, h), filled(c::gray, 0.25, 1.2));
  for (const Vec2d& p : scatter) w.point(p, dot(c::gray, 3));
  for (Idx i : h) w.point(scatter[i], dot(c::black, 4));
  return true;
}

// The neighbours of the last point in the hull of `pts` (its tangent points on the hull of the
// others): {previous, next} counter-clockwise, or nullopt if it is not a hull vertex.
std::optional<std::pair<Idx, Idx>> hull_neighbours_of_last(const std::vector<Vec2d>& pts) {
  const std::vector<Idx> h = hull_indices(pts);
  const Idx last = static_cast<Idx>(pts.size() - 1);
  for (std::size_t i = 0; i < h.size(); ++i)
    if (h[i] == last)
      return std::make_pair(h[(i + h.size() - 1) % h.size()], h[(i + 1) % h.size()]);
  return std::nullopt;
}

// 13.34: the tangents from V to the hull H: V's neighbours in the hull of H and V
// (locus::convex_hull of both sets).
bool fig_13_34(SvgWriter& w) {
  const std::vector<Vec2d> pts(scatter.begin(), scatter.begin() + 18);
  const std::vector<Idx> h = hull_indices(pts);
  if (h.empty()) return false;
  std::vector<Vec2d> with_v = pts;
  const Vec2d v{7.4, 2.0};
  with_v.push_back(v);
  const auto nb = hull_neighbours_of_last(with_v);
  if (!nb) return false;
  w.polygon(pick(pts, h), filled(c::gray, 0.2, 1.4));
  for (const Vec2d& p : pts) w.point(p, dot(c::gray, 2.5));
  const Vec2d pl = with_v[nb->first], pu = with_v[nb->second];  // counter-clockwise: lower first
  w.segment(v, pu, pen(c::blue, 1.8));
  w.segment(v, pl, pen(c::blue, 1.8));
  point(w, v, "V");
  point(w, pu, "P_U", c::blue);
  point(w, pl, "P_L", c::blue);
  label(w, Vec2d{2.4, 2.4}, "H", c::black);
  return true;
}

// 13.35: the five relations of P to the segment <Q0, Q1>: the side by exact orient2d, and for
// collinear P the signs of (P - Q0).(Q1 - Q0) and (P - Q1).(Q1 - Q0).
bool fig_13_35(SvgWriter& w) {
  const Vec2d q0{0, 0}, q1{2, 1};
  const Vec2d ps[] = {{0.6, 1.2}, {1.6, -0.2}, {-1, -0.5}, {3, 1.5}, {1, 0.5}};
  const char* names[] = {"(a)", "(b)", "(c)", "(d)", "(e)"};
  for (int k = 0; k < 5; ++k) {
    const Vec2d off{5.0 * (k % 3), k < 3 ? 0.0 : -3.6};
    const Vec2d p = ps[k];
    std::string what;
    const Sign s = orient2d(q0, q1, p);
    if (s == Sign::positive) {
      what = "left of the segment";
    } else if (s == Sign::negative) {
      what = "right of the segment";
    } else if (dot(p - q0, q1 - q0) < 0) {
      what = "on the line, before Q\u2080";
    } else if (dot(p - q1, q1 - q0) > 0) {
      what = "on the line, after Q\u2081";
    } else {
      what = "on the segment";
    }
    if (s == Sign::zero)
      w.segment(off + Vec2d{-1.4, -0.7}, off + Vec2d{3.4, 1.7}, dashed(c::light, 1));
    w.arrow(off + q0, off + q1, pen(c::black, 1.8));
    label(w, off + q0, "Q\u2080", c::black, 4, -16);
    label(w, off + q1, "Q\u2081", c::black, 6, 2);
    w.point(off + p, dot(c::red, 4));
    label(w, off + p, "P", c::red, -4, 6);
    caption_at(w, off + Vec2d{-1.2, -1.5}, std::string(names[k]) + " " + what, c::black, 12);
  }
  return true;
}

// Left and right point sets of the divide-and-conquer figures (separated by x = 3.5).
const std::vector<Vec2d> left_set{{0, 1.2},   {0.8, 0},   {2.2, 0.4}, {3.0, 2.6},
                                  {2.0, 3.4}, {0.6, 3.0}, {1.4, 1.6}, {2.2, 2.0}};
const std::vector<Vec2d> right_set{{4.0, 3.2}, {4.6, 0.8}, {6.4, -0.4}, {7.6, 1.0},
                                   {7.2, 3.4}, {5.6, 4.2}, {5.8, 1.8},  {5.0, 2.8}};

struct Bridges {
  std::pair<Idx, Idx> lower, upper;  // (left index, right index) into left_set / right_set
};

// The upper and lower tangents of two x-separated sets: the edges of the hull of their union
// joining a left point to a right point (locus::convex_hull of the union).
std::optional<Bridges> bridges(const std::vector<Vec2d>& l, const std::vector<Vec2d>& r) {
  std::vector<Vec2d> all = l;
  all.insert(all.end(), r.begin(), r.end());
  const std::vector<Idx> h = hull_indices(all);
  const Idx nl = static_cast<Idx>(l.size());
  std::vector<std::pair<Idx, Idx>> found;  // counter-clockwise order: left->right is lower
  Bridges b{};
  int count = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Idx u = h[i], v = h[(i + 1) % h.size()];
    if ((u < nl) == (v < nl)) continue;
    ++count;
    if (u < nl)
      b.lower = {u, v - nl};  // counter-clockwise from the left set to the right: the bottom
    else
      b.upper = {v, u - nl};
  }
  if (count != 2) return std::nullopt;
  return b;
}

void draw_two_hulls(SvgWriter& w, const std::vector<Idx>& hl, const std::vector<Idx>& hr) {
  w.polygon(pick(left_set, hl), filled(c::blue, 0.12, 1.4));
  w.polygon(pick(right_set, hr), filled(c::green, 0.12, 1.4));
  for (const Vec2d& p : left_set) w.point(p, dot(c::blue, 2.5));
  for (const Vec2d& p : right_set) w.point(p, dot(c::green, 2.5));
  label(w, Vec2d{1.3, 2.4}, "H_L", c::blue);
  label(w, Vec2d{5.6, 2.6}, "H_R", c::green);
}

// 13.36: the hulls of the two halves and their upper and lower tangents.
bool fig_13_36(SvgWriter& w) {
  const std::vector<Idx> hl = hull_indices(left_set), hr = hull_indices(right_set);
  const auto b = bridges(left_set, right_set);
  if (hl.empty() || hr.empty() || !b) return false;
  draw_two_hulls(w, hl, hr);
  w.segment(left_set[b->upper.first], right_set[b->upper.second], pen(c::red, 2.2));
  w.segment(left_set[b->lower.first], right_set[b->lower.second], pen(c::red, 2.2));
  label(w, lerp(left_set[b->upper.first], right_set[b->upper.second], 0.5), "upper tangent", c::red,
        0, 8);
  label(w, lerp(left_set[b->lower.first], right_set[b->lower.second], 0.5), "lower tangent", c::red,
        0, -18);
  return true;
}

// The book's search for the lower tangent: from the pair (l, r), move l clockwise on H_L while
// its clockwise neighbour is strictly below the line l -> r, then r counter-clockwise on H_R
// while its neighbour is strictly below, until neither moves (exact orient2d). Returns every
// candidate pair, positions into hl / hr.
std::vector<std::pair<std::size_t, std::size_t>> lower_tangent_walk(
    const std::vector<Vec2d>& l, const std::vector<Idx>& hl, const std::vector<Vec2d>& r,
    const std::vector<Idx>& hr, std::size_t li, std::size_t ri) {
  std::vector<std::pair<std::size_t, std::size_t>> steps{{li, ri}};
  for (int guard = 0; guard < 100; ++guard) {
    bool moved = false;
    for (;;) {
      const std::size_t prev = (li + hl.size() - 1) % hl.size();
      if (orient2d(l[hl[li]], r[hr[ri]], l[hl[prev]]) != Sign::negative) break;
      li = prev;
      moved = true;
      steps.emplace_back(li, ri);
    }
    for (;;) {
      const std::size_t next = (ri + 1) % hr.size();
      if (orient2d(l[hl[li]], r[hr[ri]], r[hr[next]]) != Sign::negative) break;
      ri = next;
      moved = true;
      steps.emplace_back(li, ri);
    }
    if (!moved) break;
  }
  return steps;
}

// Position of the lexicographically largest (smallest) point of a hull.
std::size_t extreme(const std::vector<Vec2d>& pts, const std::vector<Idx>& h, bool largest) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < h.size(); ++i) {
    const Vec2d a = pts[h[i]], b = pts[h[best]];
    const bool less = a.x < b.x || (a.x == b.x && a.y < b.y);
    if (largest ? (!less && a != b) : less) best = i;
  }
  return best;
}

// Draws the candidate tangents of a walk (numbered, dotted) and the final one; false when the
// walk does not end on the lower bridge of the union's hull.
bool draw_walk(SvgWriter& w, const std::vector<Vec2d>& l, const std::vector<Idx>& hl,
               const std::vector<Vec2d>& r, const std::vector<Idx>& hr, std::size_t li,
               std::size_t ri) {
  const auto b = bridges(l, r);
  if (!b) return false;
  const auto steps = lower_tangent_walk(l, hl, r, hr, li, ri);
  const auto [lf, rf] = steps.back();
  if (hl[lf] != b->lower.first || hr[rf] != b->lower.second) return false;
  SvgStyle dotted = pen(c::gray, 1.3);
  dotted.dash = {2, 3};
  for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
    const Vec2d a = l[hl[steps[k].first]], bb = r[hr[steps[k].second]];
    w.segment(a, bb, dotted);
    label(w, lerp(a, bb, 0.5), std::to_string(k), c::gray, 2, 2);
  }
  w.segment(l[hl[lf]], r[hr[rf]], pen(c::red, 2.2));
  w.text(lerp(l[hl[lf]], r[hr[rf]], 0.5),
         "lower tangent (step " + std::to_string(steps.size() - 1) + ")",
         text_style(c::red, 0, -22, SvgAnchor::middle));
  return true;
}

// 13.37: the incremental search for the lower tangent, from the rightmost point of H_L and the
// leftmost of H_R.
bool fig_13_37(SvgWriter& w) {
  const std::vector<Idx> hl = hull_indices(left_set), hr = hull_indices(right_set);
  if (hl.empty() || hr.empty()) return false;
  draw_two_hulls(w, hl, hr);
  return draw_walk(w, left_set, hl, right_set, hr, extreme(left_set, hl, true),
                   extreme(right_set, hr, false));
}

// 13.38: the extreme points that start the search lie on one vertical line (the halves are
// split lexicographically); the initial candidate (step 0, vertical) is not a tangent.
bool fig_13_38(SvgWriter& w) {
  const std::vector<Vec2d> l{{0, 1.2}, {1.0, -0.2}, {2.4, 0.2}, {3, 1.0}, {2.4, 2.6}, {0.8, 2.8}};
  const std::vector<Vec2d> r{{3, 2.2}, {3, 3.8}, {4.6, 4.6}, {6.4, 3.4}, {6.2, 1.0}, {4.8, 0.6}};
  const std::vector<Idx> hl = hull_indices(l), hr = hull_indices(r);
  if (hl.empty() || hr.empty()) return false;
  w.polygon(pick(l, hl), filled(c::blue, 0.12, 1.4));
  w.polygon(pick(r, hr), filled(c::green, 0.12, 1.4));
  for (const Vec2d& p : l) w.point(p, dot(c::blue, 2.5));
  for (const Vec2d& p : r) w.point(p, dot(c::green, 2.5));
  const std::size_t li = extreme(l, hl, true), ri = extreme(r, hr, false);
  if (l[hl[li]].x != r[hr[ri]].x) return false;
  w.segment(Vec2d{l[hl[li]].x, -1.2}, Vec2d{l[hl[li]].x, 5.0}, dashed(c::light, 1));
  w.text(l[hl[li]], "L₀", text_style(c::blue, -6, -4, SvgAnchor::end));
  w.text(r[hr[ri]], "R₀", text_style(c::green, 6, -4));
  caption_at(w, Vec2d{-0.2, -1.4},
             "L₀ = rightmost of H_L and R₀ = leftmost of H_R on one "
             "vertical line",
             c::black, 12);
  return draw_walk(w, l, hl, r, hr, li, ri);
}

// ---- 3D hulls ----------------------------------------------------------------------------------

// 13.39: the current hull (locus::convex_hull, 3D) and a point P to merge. A face is visible
// when P is strictly above its plane (exact orient3d > 0); the terminator is the set of edges
// between visible and hidden faces (dashed); the cone from P to it is dotted. Checked: the hull
// of the points and P has exactly the hidden faces plus one new face per terminator edge.
bool fig_13_39(SvgWriter& w) {
  const std::vector<Vec3d> pts{{0, 0, 0},       {2, 0, 0.2},   {2.2, 1.8, 0}, {0.2, 2, 0.1},
                               {0.1, 0.2, 1.8}, {1.9, 0.1, 2}, {2.1, 2, 1.9}, {0, 1.8, 2.1},
                               {1, 1, 2.7},     {1, -0.6, 1},  {2.7, 1, 1},   {1, 2.6, 1},
                               {-0.6, 1, 1},    {1, 1, -0.6}};
  const Vec3d p{4.4, 2.2, 1.5};
  const Hull3Result h = convex_hull(pts);
  if (h.status != Status::ok || h.dimension != 3) return false;
  std::vector<Vec3d> with_p = pts;
  with_p.push_back(p);
  const Hull3Result merged = convex_hull(with_p);
  if (merged.status != Status::ok) return false;
  w.set_camera(camera({9, -4, 5}, {1.6, 1.0, 1.0}));
  std::vector<bool> visible(h.triangles.size());
  std::size_t hidden = 0;
  for (std::size_t i = 0; i < h.triangles.size(); ++i) {
    const Tri& t = h.triangles[i];
    visible[i] = orient3d(pts[t[0]], pts[t[1]], pts[t[2]], p) == Sign::positive;
    if (!visible[i]) ++hidden;
  }
  for (std::size_t i : back_to_front(w, pts, h.triangles)) {
    const Tri& t = h.triangles[i];
    if (!front_facing(w, pts, t)) continue;
    closed(w, pick3(pts, t), filled(visible[i] ? c::light : c::gray, visible[i] ? 0.6 : 0.75, 0.8));
  }
  // Vertices and edges on the far side of the hull (no incident face towards the camera) are
  // drawn faint.
  std::vector<bool> vertex_front(pts.size(), false);
  for (const Tri& t : h.triangles)
    if (front_facing(w, pts, t))
      for (Idx v : t) vertex_front[v] = true;
  std::size_t terminator = 0;
  std::set<Idx> rim;
  for (std::size_t i = 0; i < h.triangles.size(); ++i)
    for (std::size_t e = 0; e < 3; ++e) {
      const std::size_t j = h.adjacency[i][e];
      if (!visible[i] || visible[j]) continue;
      const Idx a = h.triangles[i][e], b = h.triangles[i][(e + 1) % 3];
      ++terminator;
      rim.insert(a);
      rim.insert(b);
      SvgStyle s = dashed(c::black, 2.2);
      s.opacity =
          front_facing(w, pts, h.triangles[i]) || front_facing(w, pts, h.triangles[j]) ? 1.0 : 0.3;
      w.segment(pts[a], pts[b], s);
    }
  if (merged.triangles.size() != hidden + terminator) return false;
  for (Idx v : rim) {
    SvgStyle s = dotted_pen(c::blue);
    s.opacity = vertex_front[v] ? 1.0 : 0.35;
    w.segment(p, pts[v], s);
  }
  point(w, p, "P", c::blue);
  return true;
}

// The 12 vertices of an icosahedron (circumradius about 1.9 times `scale`) centred at `at`.
std::vector<Vec3d> icosahedron(const Vec3d& at, double scale) {
  const double g = 0.5 * (1 + std::sqrt(5.0));
  std::vector<Vec3d> v;
  for (double s0 : {-1.0, 1.0})
    for (double s1 : {-1.0, 1.0}) {
      v.push_back(at + scale * Vec3d{0, s0, s1 * g});
      v.push_back(at + scale * Vec3d{s0, s1 * g, 0});
      v.push_back(at + scale * Vec3d{s1 * g, 0, s0});
    }
  return v;
}

// Draws the edges of a hull mesh, edges behind it (both faces facing away) faint.
void hull_wireframe(SvgWriter& w, const std::vector<Vec3d>& v, const std::vector<Tri>& tris,
                    const Vec3d& offset, const char* col) {
  for (const auto& [e, faces] : edge_faces(tris)) {
    bool front = false;
    for (std::size_t f : faces) front = front || front_facing(w, v, tris[f]);
    SvgStyle s = pen(col, front ? 1.5 : 0.8);
    s.opacity = front ? 1.0 : 0.3;
    w.segment(v[e.first] + offset, v[e.second] + offset, s);
  }
}

// Triangles rotated to start at their smallest index, sorted: equal hulls, equal lists.
std::vector<Tri> canonical_triangles(const Hull3Result& r) {
  std::vector<Tri> out;
  for (Tri t : r.triangles) {
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// 13.40: (a) two icosahedra (locus::convex_hull of each); (b) the hull of their union by the
// divide-and-conquer method (the lexicographic halves are the two icosahedra, merged by wrapping
// the band of new faces), checked against the incremental hull. Its faces that are faces of an
// original hull are "old": edges between old faces dashed, edges between new (band) faces
// dotted, edges where old meets new solid.
bool fig_13_40(SvgWriter& w) {
  // The right one turned about a generic axis: a translated copy would give parallel edges,
  // hence coplanar quadruples on the band, where the method falls back to the incremental hull.
  const Vec3d right{3.0, 0.6, 1.2};
  const std::vector<Vec3d> a = icosahedron({0, 0, 0}, 0.8),
                           b = map_points(rotation(right, Vec3d{1, 2, 3}, 0.7),
                                          icosahedron(right, 0.8));
  std::vector<Vec3d> all = a;
  all.insert(all.end(), b.begin(), b.end());
  const Hull3Result ha = convex_hull(a), hb = convex_hull(b);
  const Hull3Result hu = convex_hull(all, Hull3Options{Hull3Method::divide_and_conquer});
  const Hull3Result hi = convex_hull(all, Hull3Options{Hull3Method::incremental});
  for (const Hull3Result* r : {&ha, &hb, &hu, &hi})
    if (r->status != Status::ok || r->dimension != 3) return false;
  if (canonical_triangles(hu) != canonical_triangles(hi)) return false;
  w.set_camera(camera({3, -14, 4}, {4.5, 0, 0.6}));
  hull_wireframe(w, a, ha.triangles, {0, 0, 0}, c::blue);
  hull_wireframe(w, b, hb.triangles, {0, 0, 0}, c::green);
  const Vec3d off{8.5, 0, 0};
  std::set<std::array<Idx, 3>> old;
  const Idx na = static_cast<Idx>(a.size());
  for (const Tri& t : ha.triangles) {
    std::array<Idx, 3> k = t;
    std::sort(k.begin(), k.end());
    old.insert(k);
  }
  for (const Tri& t : hb.triangles) {
    std::array<Idx, 3> k{t[0] + na, t[1] + na, t[2] + na};
    std::sort(k.begin(), k.end());
    old.insert(k);
  }
  std::vector<bool> is_old;
  for (const Tri& t : hu.triangles) {
    std::array<Idx, 3> k = t;
    std::sort(k.begin(), k.end());
    is_old.push_back(old.count(k) > 0);
  }
  for (const auto& [e, faces] : edge_faces(hu.triangles)) {
    int olds = 0;
    bool front = false;
    for (std::size_t f : faces) {
      olds += is_old[f] ? 1 : 0;
      front = front || front_facing(w, all, hu.triangles[f]);
    }
    SvgStyle s = olds == 2   ? dashed(c::blue, 1.4)
                 : olds == 0 ? dotted_pen(c::red, 1.6)
                             : pen(c::black, 1.6);
    s.opacity = front ? 1.0 : 0.3;
    w.segment(all[e.first] + off, all[e.second] + off, s);
  }
  w.text(Vec3d{1.5, 0, -2.2}, "(a)", text_style(c::black, 0, 0, SvgAnchor::middle));
  w.text(off + Vec3d{1.5, 0, -2.2}, "(b)", text_style(c::black, 0, 0, SvgAnchor::middle));
  return true;
}

// 13.41: a pyramid (apex 2, base quadrilateral 3 4 5 6; locus::convex_hull) and a segment <0, 1>
// behind its base. Face visibility from a point of the segment is the sign of orient3d, linear
// along the segment: the points a, b where it changes are interpolated from orient3d_value. The
// faces no point of the segment sees bound the terminator (red): two cycles through vertex 2.
// (a) side view; (b) the scene rotated (locus::rotation_about_x) to look from behind the segment.
// The merge of a hull with a segment (a flat half) is where the divide-and-conquer method hulls
// the two vertex sets incrementally: its hull of pyramid and segment is checked against the
// incremental one.
bool fig_13_41(SvgWriter& w) {
  const std::vector<Vec3d> pyr{{0, 0, 2}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const Vec3d s0{-3.5, 0, -1}, s1{3.5, 0, -1};
  const Hull3Result h = convex_hull(pyr);
  if (h.status != Status::ok || h.dimension != 3) return false;
  std::vector<Vec3d> both = pyr;
  both.push_back(s0);
  both.push_back(s1);
  const Hull3Result hd = convex_hull(both, Hull3Options{Hull3Method::divide_and_conquer});
  const Hull3Result hi = convex_hull(both, Hull3Options{Hull3Method::incremental});
  if (hd.status != Status::ok || hd.vertices != hi.vertices) return false;
  std::vector<double> ts;
  std::vector<bool> seen;
  for (const Tri& t : h.triangles) {
    const double v0 = orient3d_value(pyr[t[0]], pyr[t[1]], pyr[t[2]], s0);
    const double v1 = orient3d_value(pyr[t[0]], pyr[t[1]], pyr[t[2]], s1);
    const Sign g0 = orient3d(pyr[t[0]], pyr[t[1]], pyr[t[2]], s0);
    const Sign g1 = orient3d(pyr[t[0]], pyr[t[1]], pyr[t[2]], s1);
    seen.push_back(g0 == Sign::positive || g1 == Sign::positive);
    if (g0 != g1 && g0 != Sign::zero && g1 != Sign::zero) ts.push_back(v0 / (v0 - v1));
  }
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  if (ts.size() != 2) return false;
  const Vec3d pa = lerp(s0, s1, ts[0]), pb = lerp(s0, s1, ts[1]);
  w.set_camera(camera({2.5, -12, 3.0}, {0, 0, 0}));
  const Affine3d views[] = {Affine3d::identity(),
                            translation(Vec3d{0, 0, -5.2}) * rotation_about_x(-1.2)};
  const char* names[] = {"(a) side view", "(b) from behind the segment"};
  std::size_t terminator = 0;
  for (int k = 0; k < 2; ++k) {
    const Affine3d& m = views[k];
    const std::vector<Vec3d> v = map_points(m, pyr);
    for (std::size_t i : back_to_front(w, v, h.triangles)) {
      const Tri& t = h.triangles[i];
      if (!front_facing(w, v, t)) continue;
      SvgStyle st = filled(seen[i] ? c::light : c::gray, 0.7, 0.8);
      st.stroke = "none";
      closed(w, pick3(v, t), st);
    }
    for (const auto& [e, faces] : edge_faces(h.triangles)) {
      const bool term = faces.size() == 2 && seen[faces[0]] != seen[faces[1]];
      if (k == 0 && term) ++terminator;
      // The coplanar base triangles share a diagonal that is not an edge of the pyramid.
      if (faces.size() == 2) {
        const Tri& f0 = h.triangles[faces[0]];
        const Tri& f1 = h.triangles[faces[1]];
        const Idx far = f1[0] != e.first && f1[0] != e.second   ? f1[0]
                        : f1[1] != e.first && f1[1] != e.second ? f1[1]
                                                                : f1[2];
        if (orient3d(pyr[f0[0]], pyr[f0[1]], pyr[f0[2]], pyr[far]) == Sign::zero) continue;
      }
      SvgStyle st = term ? pen(c::red, 2.4) : pen(c::black, 1.0);
      bool front = false;
      for (std::size_t f : faces) front = front || front_facing(w, v, h.triangles[f]);
      if (!front) {
        st.dash = {4, 3};
        st.opacity = 0.45;
      }
      w.segment(v[e.first], v[e.second], st);
    }
    const Vec3d q0 = apply_point(m, s0), q1 = apply_point(m, s1), qa = apply_point(m, pa),
                qb = apply_point(m, pb);
    w.segment(q0, q1, pen(c::blue, 2));
    point(w, q0, "0", c::blue);
    point(w, q1, "1", c::blue);
    point(w, qa, "a", c::blue);
    point(w, qb, "b", c::blue);
    for (std::size_t i = 0; i < v.size(); ++i)
      label(w, v[i], std::to_string(i + 2), c::black, 4, 4);
    w.text(apply_point(m, Vec3d{0, 0, 0}) + Vec3d{-3.5, 0, 1.6}, names[k],
           text_style(c::black, 0, 0, SvgAnchor::start, 13));
  }
  return terminator == 6;
}

// ---- 13.7 Delaunay triangulation ---------------------------------------------------------------

// Triangles of a Delaunay2Result as index triples.
std::vector<Tri> triangles_of(const Delaunay2Result& dt) { return dt.triangles; }

void draw_edges(SvgWriter& w, const std::vector<Vec2d>& pts, const Delaunay2Result& dt,
                const Vec2d& off, const SvgStyle& s) {
  for (std::size_t t = 0; t < dt.triangle_count(); ++t)
    for (std::size_t i = 0; i < 3; ++i) {
      const Idx twin = dt.adjacency[t][i];  // each interior edge once, from its lower triangle
      if (twin != kNoTriangle && twin < t) continue;
      w.segment(off + pts[dt.triangles[t][i]], off + pts[dt.triangles[t][(i + 1) % 3]], s);
    }
}

// 13.42: two triangulations of one point set, both covering its convex hull: (a) every point is
// a vertex (locus::delaunay of all points); (b) only the hull vertices are used
// (locus::convex_hull, then locus::delaunay of its vertices), the other points lie inside
// triangles.
bool fig_13_42(SvgWriter& w) {
  const std::vector<Vec2d> pts(scatter.begin(), scatter.begin() + 16);
  const std::vector<Idx> h = hull_indices(pts);
  if (h.empty()) return false;
  const std::vector<Vec2d> corners = pick(pts, h);
  const Delaunay2Result all = delaunay(std::span<const Vec2d>(pts));
  const Delaunay2Result outer = delaunay(std::span<const Vec2d>(corners));
  if (all.status != Status::ok || outer.status != Status::ok) return false;
  const Vec2d off{6.2, 0};
  draw_edges(w, pts, all, {0, 0}, pen(c::blue, 1.2));
  draw_edges(w, corners, outer, off, pen(c::blue, 1.2));
  for (const Vec2d& p : pts) {
    w.point(p, dot(c::black, 3));
    w.point(p + off, dot(c::black, 3));
  }
  caption_at(w, Vec2d{0, -0.9}, "(a) every point is a vertex", c::black, 13);
  caption_at(w, off + Vec2d{0, -0.9}, "(b) only the hull vertices are used", c::black, 13);
  return true;
}

double min_angle(const std::vector<Vec2d>& p, const Tri& t, std::size_t& at) {
  double best = 10;
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec2d a = p[t[i]], b = p[t[(i + 1) % 3]], cc = p[t[(i + 2) % 3]];
    const double ang = angle_between(b - a, cc - a);
    if (ang < best) {
      best = ang;
      at = i;
    }
  }
  return best;
}

// The rhombus of 13.43 / 13.44, its Delaunay triangulation (locus::delaunay) and the other
// triangulation (the flipped diagonal).
struct QuadPair {
  std::vector<Vec2d> p{{-2, 0}, {0, -1}, {2, 0}, {0, 1}};
  std::array<Tri, 2> del{}, other{};
};
std::optional<QuadPair> quad_pair() {
  QuadPair q;
  const Delaunay2Result dt = delaunay(std::span<const Vec2d>(q.p));
  if (dt.status != Status::ok || dt.triangle_count() != 2) return std::nullopt;
  for (std::size_t i = 0; i < 3; ++i) {
    const Idx across = dt.adjacency[0][i];
    if (across == kNoTriangle) continue;
    const Tri& t0 = dt.triangles[0];
    const Tri& t1 = dt.triangles[across];
    const Idx u = t0[i], v = t0[(i + 1) % 3], x = t0[(i + 2) % 3];
    Idx y = t1[0];  // the vertex of the other triangle off the shared edge
    for (const Idx k : t1)
      if (k != u && k != v) y = k;
    q.del = {Tri{u, v, x}, Tri{v, u, y}};
    q.other = {Tri{x, y, v}, Tri{y, x, u}};
    return q;
  }
  return std::nullopt;
}

// 13.43: the two triangulations of a convex quadrilateral and their minimum angles
// (locus::angle_between); (b) is locus::delaunay's.
bool fig_13_43(SvgWriter& w) {
  const auto q = quad_pair();
  if (!q) return false;
  const std::pair<const std::array<Tri, 2>*, Vec2d> panels[] = {{&q->other, {0, 0}},
                                                                {&q->del, {5.5, 0}}};
  for (int k = 0; k < 2; ++k) {
    const auto& [tris, off] = panels[k];
    double worst = 10;
    for (const Tri& t : *tris) {
      const std::vector<Vec2d> v{off + q->p[t[0]], off + q->p[t[1]], off + q->p[t[2]]};
      w.polygon(v, filled(t == (*tris)[0] ? c::blue : c::green, 0.12, 1.5));
      std::size_t at = 0;
      const double a = min_angle(q->p, t, at);
      worst = std::min(worst, a);
      const Vec2d d0 = v[(at + 1) % 3] - v[at], d1 = v[(at + 2) % 3] - v[at];
      angle_mark(w, v[at], d0, d1, 0.7, "", c::red);
      w.text(v[at] + 1.05 * normalize(normalize(d0) + normalize(d1)), fmt(a),
             text_style(c::red, 0, -5, SvgAnchor::middle, 13));
    }
    caption_at(w, off + Vec2d{-2, -1.6},
               std::string(k == 0 ? "(a)" : "(b) Delaunay:") + " minimum angle " + fmt(worst));
  }
  return true;
}

// 13.44: the circumcircles (locus::circumscribed_circle) of both triangulations; the exact
// incircle test says whether the fourth vertex is inside.
bool fig_13_44(SvgWriter& w) {
  const auto q = quad_pair();
  if (!q) return false;
  const std::pair<const std::array<Tri, 2>*, Vec2d> panels[] = {{&q->other, {0, 0}},
                                                                {&q->del, {6.5, 0}}};
  for (int k = 0; k < 2; ++k) {
    const auto& [tris, off] = panels[k];
    bool empty = true;
    for (const Tri& t : *tris) {
      const Triangle2<double> tri{off + q->p[t[0]], off + q->p[t[1]], off + q->p[t[2]]};
      const auto circ = circumscribed_circle(tri);
      if (!circ) return false;
      const char* col = t == (*tris)[0] ? c::blue : c::green;
      draw(w, tri, filled(col, 0.12, 1.5));
      draw(w, *circ, dashed(col, 1.2));
      const Idx fourth = 6 - t[0] - t[1] - t[2];
      const Sign s =
          orient2d(tri.v0, tri.v1, tri.v2) * incircle(tri.v0, tri.v1, tri.v2, off + q->p[fourth]);
      empty = empty && s != Sign::positive;
    }
    caption_at(w, off + Vec2d{-2.2, -4.6},
               std::string(k == 0 ? "(a)" : "(b)") +
                   (empty ? " circumcircles empty" : " each circle holds the 4th vertex"),
               c::black, 13);
  }
  return true;
}

const std::vector<Vec2d> small_set{{0, 0}, {4, 0}, {2, 3.2}, {-1.4, 2.2}, {5.4, 2.6}, {2, -2.2}};

// 13.45: inserting P: (a) locus::locate finds it strictly inside a triangle, split in three;
// (b) on an edge (the exact midpoint of a dyadic edge), both triangles split in two.
bool fig_13_45(SvgWriter& w) {
  const Delaunay2Result dt = delaunay(std::span<const Vec2d>(small_set));
  if (dt.status != Status::ok) return false;
  const std::pair<Vec2d, Vec2d> cases[] = {{{2, 1.1}, {0, 0}},
                                           {lerp(small_set[0], small_set[1], 0.5), {8.5, 0}}};
  for (int k = 0; k < 2; ++k) {
    const auto& [p, off] = cases[k];
    const LocateResult loc = locate(dt, std::span<const Vec2d>(small_set), p);
    if (loc.status != Status::ok) return false;
    if (loc.location != (k == 0 ? Location::inside : Location::on_edge)) return false;
    std::vector<Idx> tris{static_cast<Idx>(loc.triangle)};
    if (k == 1) {
      const Idx twin = dt.adjacency[static_cast<std::size_t>(loc.triangle)]
                                   [static_cast<std::size_t>(loc.corner)];
      if (twin != kNoTriangle) tris.push_back(twin);
    }
    for (Idx t : tris) {
      std::vector<Vec2d> v;
      for (std::size_t i = 0; i < 3; ++i) v.push_back(off + small_set[dt.triangles[t][i]]);
      w.polygon(v, filled(c::blue, 0.15, 0.5));
    }
    draw_edges(w, small_set, dt, off, pen(c::black, 1.3));
    for (Idx t : tris)
      for (std::size_t i = 0; i < 3; ++i)
        w.segment(off + p, off + small_set[dt.triangles[t][i]], pen(c::red, 1.8));
    w.point(off + p, dot(c::black, 4));
    caption_at(w, off + Vec2d{-1.2, -3.0}, k == 0 ? "(a) inside a triangle" : "(b) on an edge");
  }
  return true;
}

// 13.46: the pair <T, A>: the opposite vertex of A is strictly inside T's circumcircle (exact
// incircle), so their common edge is swapped; the new triangles N0, N1 form pairs with B0, B1,
// each tested again.
bool fig_13_46(SvgWriter& w) {
  const Vec2d p{0, 0}, v0{2, -1.4}, v1{2, 1.4}, q{2.9, 0}, w0{3.9, -2.0}, w1{3.9, 2.0};
  const Triangle2<double> t{p, v0, v1}, a{v1, v0, q}, b0{v0, w0, q}, b1{q, w1, v1};
  if (incircle(t.v0, t.v1, t.v2, q) != Sign::positive) return false;
  const auto circ = circumscribed_circle(t);
  if (!circ) return false;
  const Vec2d off{6.5, 0};
  draw(w, t, filled(c::blue, 0.15));
  draw(w, a, filled(c::red, 0.15));
  for (const Triangle2<double>* x : {&b0, &b1}) draw(w, *x, filled(c::gray, 0.1, 1));
  draw(w, *circ, dashed(c::blue, 1.2));
  label(w, centroid(t), "T", c::blue, -4, -6);
  label(w, centroid(a), "A", c::red, -4, -6);
  label(w, centroid(b0), "B\u2080", c::gray, -6, -6);
  label(w, centroid(b1), "B\u2081", c::gray, -6, -6);
  point(w, p, "P", c::black);
  caption_at(w, Vec2d{-0.4, -2.6}, "(a) A's far vertex is in T's circle", c::black, 13);
  // After the swap: the diagonal P-Q.
  const Triangle2<double> n0{off + p, off + v0, off + q}, n1{off + p, off + q, off + v1};
  const Triangle2<double> c0{off + b0.v0, off + b0.v1, off + b0.v2},
      c1{off + b1.v0, off + b1.v1, off + b1.v2};
  draw(w, n0, filled(c::blue, 0.15));
  draw(w, n1, filled(c::green, 0.15));
  label(w, centroid(n0), "N\u2080", c::blue, -6, -6);
  label(w, centroid(n1), "N\u2081", c::green, -6, -6);
  std::string verdict;
  for (const auto& [n, bb, name, far] :
       {std::tuple{n0, c0, "B\u2080", off + w0}, std::tuple{n1, c1, "B\u2081", off + w1}}) {
    const bool swap = incircle(n.v0, n.v1, n.v2, far) == Sign::positive;
    draw(w, bb, filled(swap ? c::red : c::gray, 0.1, 1));
    label(w, centroid(bb), name, c::gray, -6, -6);
    verdict += std::string(verdict.empty() ? "" : ", ") + (swap ? "swap" : "keep");
  }
  point(w, off + p, "P", c::black);
  caption_at(w, off + Vec2d{-0.4, -2.6}, "(b) after the swap: " + verdict, c::black, 13);
  return true;
}

// The Bowyer-Watson figures (13.47-13.51): a supertriangle around the points and the Delaunay
// triangulations of it with the first k points.
const std::vector<Vec2d> bw_points{{0.2, 0.3}, {2.4, 0.1}, {3.6, 1.2}, {1.4, 1.5},
                                   {0.5, 2.6}, {2.1, 2.3}, {3.4, 2.9}, {1.6, 3.6}};
const std::size_t bw_next = 5;  // the point being inserted in 13.48 and 13.49

// An equilateral triangle whose incircle is 1.3 times the smallest enclosing circle of the
// points (locus::min_circle), so every point is strictly inside (checked with locus::classify).
std::optional<std::array<Vec2d, 3>> supertriangle(const std::vector<Vec2d>& pts,
                                                  Circle2<double>* enclosing = nullptr) {
  const MinCircleResult<double> mc = min_circle(std::span<const Vec2d>(pts));
  if (mc.status != Status::ok) return std::nullopt;
  const double r = 2.0 * 1.3 * mc.circle.radius;  // circumradius = 2 inradius
  std::array<Vec2d, 3> s{};
  for (std::size_t i = 0; i < 3; ++i) {
    const double ang = 3.14159265358979 * (0.5 + 2.0 * static_cast<double>(i) / 3.0);
    s[i] = mc.circle.center + r * Vec2d{std::cos(ang), std::sin(ang)};
  }
  const Triangle2<double> t{s[0], s[1], s[2]};
  for (const Vec2d& p : pts)
    if (classify(p, t) != Side::inside) return std::nullopt;
  if (enclosing) *enclosing = mc.circle;
  return s;
}

// The supertriangle's vertices (indices 0, 1, 2) followed by the first k points.
std::vector<Vec2d> bw_input(const std::array<Vec2d, 3>& s, std::size_t k) {
  std::vector<Vec2d> v(s.begin(), s.end());
  v.insert(v.end(), bw_points.begin(), bw_points.begin() + static_cast<std::ptrdiff_t>(k));
  return v;
}

void bw_view(SvgWriter& w, const std::array<Vec2d, 3>& s) {
  Vec2d lo = s[0], hi = s[0];
  for (const Vec2d& p : s) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  w.set_view(lo - Vec2d{0.3, 0.3}, hi + Vec2d{0.3, 0.3});
}

// 13.47: the supertriangle of the point set.
bool fig_13_47(SvgWriter& w) {
  Circle2<double> mc{};
  const auto s = supertriangle(bw_points, &mc);
  if (!s) return false;
  bw_view(w, *s);
  w.polygon(std::vector<Vec2d>(s->begin(), s->end()), filled(c::gray, 0.08, 1.6));
  draw(w, mc, dashed(c::gray, 1));
  for (const Vec2d& p : bw_points) w.point(p, dot(c::black, 3.5));
  for (std::size_t i = 0; i < 3; ++i) point(w, (*s)[i], "S" + std::to_string(i), c::gray);
  return true;
}

// Triangles (of dt over the input `in`) whose circumcircle strictly contains p (exact incircle).
std::vector<std::size_t> conflicts(const Delaunay2Result& dt, const std::vector<Vec2d>& in,
                                   const Vec2d& p) {
  std::vector<std::size_t> out;
  for (std::size_t t = 0; t < dt.triangle_count(); ++t)
    if (incircle(in[dt.triangles[t][0]], in[dt.triangles[t][1]], in[dt.triangles[t][2]], p) ==
        Sign::positive)
      out.push_back(t);
  return out;
}

void bw_mesh(SvgWriter& w, const std::vector<Vec2d>& in, const Delaunay2Result& dt) {
  draw_edges(w, in, dt, {0, 0}, pen(c::gray, 1));
  for (std::size_t i = 3; i < in.size(); ++i) w.point(in[i], dot(c::black, 3.2));
}

// 13.48: the triangles of the current mesh (locus::delaunay of the supertriangle and the points
// so far) whose circumcircles contain the next point.
bool fig_13_48(SvgWriter& w) {
  const auto s = supertriangle(bw_points);
  if (!s) return false;
  const std::vector<Vec2d> in = bw_input(*s, bw_next);
  const Delaunay2Result dt = delaunay(std::span<const Vec2d>(in));
  if (dt.status != Status::ok) return false;
  bw_view(w, *s);
  const Vec2d p = bw_points[bw_next];
  const auto bad = conflicts(dt, in, p);
  if (bad.empty()) return false;
  const auto m = w.mapping();
  for (std::size_t t : bad) {
    const Triangle2<double> tri{in[dt.triangles[t][0]], in[dt.triangles[t][1]],
                                in[dt.triangles[t][2]]};
    draw(w, tri, filled(c::blue, 0.15, 0.5));
    const auto circ = circumscribed_circle(tri);
    if (!circ) return false;
    clipped_circle(w, *circ, m.inner_lo, m.inner_hi, dashed(c::blue, 1));
  }
  bw_mesh(w, in, dt);
  point(w, p, "P", c::red);
  return true;
}

// 13.49: the insertion polygon: the boundary of the conflicting triangles; P is joined to its
// vertices. Checked: these are exactly the triangles at P in locus::delaunay with P added.
bool fig_13_49(SvgWriter& w) {
  const auto s = supertriangle(bw_points);
  if (!s) return false;
  const std::vector<Vec2d> in = bw_input(*s, bw_next), in2 = bw_input(*s, bw_next + 1);
  const Delaunay2Result dt = delaunay(std::span<const Vec2d>(in));
  const Delaunay2Result dt2 = delaunay(std::span<const Vec2d>(in2));
  if (dt.status != Status::ok || dt2.status != Status::ok) return false;
  bw_view(w, *s);
  const Vec2d p = bw_points[bw_next];
  const Idx pi = static_cast<Idx>(in.size());
  const auto bad = conflicts(dt, in, p);
  const std::set<std::size_t> bad_set(bad.begin(), bad.end());
  std::set<std::pair<Idx, Idx>> fan;  // boundary edges, counter-clockwise around the polygon
  for (std::size_t t : bad) {
    w.polygon(
        std::vector<Vec2d>{in[dt.triangles[t][0]], in[dt.triangles[t][1]], in[dt.triangles[t][2]]},
        filled(c::blue, 0.12, 0.3));
    for (std::size_t i = 0; i < 3; ++i) {
      const Idx twin = dt.adjacency[t][i];
      if (twin != kNoTriangle && bad_set.count(twin)) continue;
      fan.insert({dt.triangles[t][i], dt.triangles[t][(i + 1) % 3]});
    }
  }
  std::set<std::pair<Idx, Idx>> at_p;  // edges opposite P in the new triangulation
  for (std::size_t t = 0; t < dt2.triangle_count(); ++t)
    for (std::size_t i = 0; i < 3; ++i)
      if (dt2.triangles[t][i] == pi)
        at_p.insert({dt2.triangles[t][(i + 1) % 3], dt2.triangles[t][(i + 2) % 3]});
  if (fan != at_p) return false;
  bw_mesh(w, in, dt);
  for (const auto& [u, v] : fan) {
    w.segment(in[u], in[v], pen(c::blue, 2.6));
    w.segment(p, in[u], dashed(c::red, 1.3));
  }
  point(w, p, "P", c::red);
  return true;
}

// 13.50: the modified insertion polygon: the conflicting triangles are replaced by the fan from
// P to the insertion polygon's edges; every new triangle's circumcircle (dashed) is empty of
// all points (exact incircle), which restores the Delaunay condition. Checked: the fan is
// exactly the triangles at P in locus::delaunay with P added.
bool fig_13_50(SvgWriter& w) {
  const auto s = supertriangle(bw_points);
  if (!s) return false;
  const std::vector<Vec2d> in = bw_input(*s, bw_next + 1);
  const Delaunay2Result dt = delaunay(std::span<const Vec2d>(in));
  if (dt.status != Status::ok) return false;
  bw_view(w, *s);
  const auto m = w.mapping();
  const Idx pi = static_cast<Idx>(in.size() - 1);
  const Vec2d p = in[pi];
  int fan = 0;
  for (std::size_t t = 0; t < dt.triangle_count(); ++t) {
    const Tri& tri = dt.triangles[t];
    if (tri[0] != pi && tri[1] != pi && tri[2] != pi) continue;
    ++fan;
    const Triangle2<double> tr{in[tri[0]], in[tri[1]], in[tri[2]]};
    draw(w, tr, filled(c::green, 0.18, 0.5));
    for (std::size_t q = 0; q < in.size(); ++q)
      if (incircle(in[tri[0]], in[tri[1]], in[tri[2]], in[q]) == Sign::positive) return false;
    const auto circ = circumscribed_circle(tr);
    if (!circ) return false;
    clipped_circle(w, *circ, m.inner_lo, m.inner_hi, dashed(c::green, 1));
    for (std::size_t i = 0; i < 3; ++i)
      if (tri[i] != pi && tri[(i + 1) % 3] != pi)
        w.segment(in[tri[i]], in[tri[(i + 1) % 3]], pen(c::blue, 2.6));
  }
  if (fan < 3) return false;
  bw_mesh(w, in, dt);
  point(w, p, "P", c::red);
  return true;
}

// 13.51: the triangulation of the supertriangle and all points; triangles using a supertriangle
// vertex (light) are removed, the others (dark) are the final mesh.
bool fig_13_51(SvgWriter& w) {
  const auto s = supertriangle(bw_points);
  if (!s) return false;
  const std::vector<Vec2d> in = bw_input(*s, bw_points.size());
  const Delaunay2Result dt = delaunay(std::span<const Vec2d>(in));
  if (dt.status != Status::ok) return false;
  bw_view(w, *s);
  for (const Tri& t : triangles_of(dt)) {
    const bool removed = t[0] < 3 || t[1] < 3 || t[2] < 3;
    SvgStyle st = filled(removed ? c::light : c::gray, removed ? 0.35 : 0.8, 1);
    if (!removed) st.stroke = "white";
    w.polygon(pick(in, t), st);
  }
  for (std::size_t i = 3; i < in.size(); ++i) w.point(in[i], dot(c::black, 3.2));
  return true;
}

// 13.52: (a) the 3D hull (locus::convex_hull) of the points lifted to z = x^2 + y^2, its lower
// faces (outward normal pointing down) filled; (b) their projection, which must be the same
// triangle set as locus::delaunay of the points.
bool fig_13_52(SvgWriter& w) {
  const std::vector<Vec2d> pts{{-1.2, -1.1}, {0.3, -1.4}, {1.4, -0.9}, {-0.4, -0.3}, {0.9, 0.2},
                               {-1.5, 0.4},  {0.1, 0.8},  {1.3, 1.2},  {-0.8, 1.4},  {0.6, -0.5}};
  std::vector<Vec3d> lifted;
  for (const Vec2d& p : pts) lifted.push_back({p.x, p.y, p.x * p.x + p.y * p.y});
  const Hull3Result h = convex_hull(lifted);
  const Delaunay2Result dt = delaunay(std::span<const Vec2d>(pts));
  if (h.status != Status::ok || h.dimension != 3 || dt.status != Status::ok) return false;
  std::set<Tri> lower, del;
  std::vector<bool> is_lower;
  for (const Tri& t : h.triangles) {
    is_lower.push_back(face_normal(lifted, t).z < 0);
    Tri k = t;
    std::sort(k.begin(), k.end());
    if (is_lower.back()) lower.insert(k);
  }
  for (Tri t : triangles_of(dt)) {
    std::sort(t.begin(), t.end());
    del.insert(t);
  }
  if (lower != del) return false;
  w.set_camera(camera({4, -7, 4.5}, {0, 0, 1.3}));
  for (std::size_t i : back_to_front(w, lifted, h.triangles)) {
    const Tri& t = h.triangles[i];
    if (is_lower[i]) closed(w, pick3(lifted, t), filled(c::blue, 0.18, 1.2));
  }
  for (std::size_t i = 0; i < h.triangles.size(); ++i)
    if (!is_lower[i]) closed(w, pick3(lifted, h.triangles[i]), dashed(c::gray, 0.8));
  for (const Vec3d& p : lifted) w.point(p, dot(c::black, 3));
  // (b) beside (a): the projection, drawn in the image plane to the right of the 3D view.
  Vec2d lo{1e9, 1e9}, hi{-1e9, -1e9};
  for (const Vec3d& p : lifted) {
    Vec2d q;
    if (!w.project(p, q)) return false;
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
  }
  const double scale = 0.8 * (hi.y - lo.y) / 3.0;  // the points span about 3 units
  const Vec2d origin{hi.x + 0.35 * (hi.x - lo.x) + 1.5 * scale, 0.5 * (lo.y + hi.y)};
  std::vector<Vec2d> placed;
  for (const Vec2d& p : pts) placed.push_back(origin + scale * p);
  for (const Tri& t : lower) w.polygon(pick(placed, t), filled(c::blue, 0.18, 1.2));
  for (const Vec2d& p : placed) w.point(p, dot(c::black, 3));
  w.text(Vec2d{0.5 * (lo.x + hi.x), lo.y}, "(a) lifted hull",
         text_style(c::black, 0, -18, SvgAnchor::middle, 13));
  w.text(Vec2d{origin.x, lo.y}, "(b) lower faces = Delaunay",
         text_style(c::black, 0, -18, SvgAnchor::middle, 13));
  return true;
}

// ---- 13.9-13.11 circles, bounding shapes, areas ------------------------------------------------

// 13.78: the circumscribed and inscribed circles of a triangle.
bool fig_13_78(SvgWriter& w) {
  const Triangle2<double> t{{0, 0}, {4, 0.4}, {1.2, 3}};
  const auto out = circumscribed_circle(t);
  const auto in = inscribed_circle(t);
  if (!out || !in) return false;
  draw(w, *out, pen(c::blue, 1.5));
  draw(w, *in, pen(c::red, 1.5));
  draw(w, t, filled(c::gray, 0.12, 1.8));
  point(w, out->center, "circumcentre", c::blue);
  point(w, in->center, "incentre", c::red);
  return true;
}

// Enclosing rectangle of `pts` with first axis u (unit): extents by projection.
Rectangle<double, 2> rect_with_axis(const std::vector<Vec2d>& pts, const Vec2d& u) {
  const Vec2d v = perp(u);
  double lo0 = 1e300, hi0 = -1e300, lo1 = 1e300, hi1 = -1e300;
  for (const Vec2d& p : pts) {
    lo0 = std::min(lo0, dot(p, u));
    hi0 = std::max(hi0, dot(p, u));
    lo1 = std::min(lo1, dot(p, v));
    hi1 = std::max(hi1, dot(p, v));
  }
  return {0.5 * (lo0 + hi0) * u + 0.5 * (lo1 + hi1) * v,
          {u, v},
          {0.5 * (hi0 - lo0), 0.5 * (hi1 - lo1)}};
}

// 13.79: (a) an enclosing rectangle with no side on a hull edge (axes turned from the optimum);
// (b) the minimum-area rectangle (locus::min_rect), flush with a hull edge (red).
bool fig_13_79(SvgWriter& w) {
  const std::vector<Vec2d> pts{{0, 0},     {2.6, -0.4}, {3.6, 0.9},
                               {3.0, 2.4}, {1.2, 2.8},  {-0.4, 1.6}};
  const MinRectResult<double> mr = min_rect(std::span<const Vec2d>(pts));
  if (mr.status != Status::ok) return false;
  const double turn = 0.4;
  const Vec2d u = normalize(mr.rectangle.axis[0] * std::cos(turn) +
                            perp(mr.rectangle.axis[0]) * std::sin(turn));
  const Rectangle<double, 2> other = rect_with_axis(pts, u);
  const double other_area = 4 * other.extent[0] * other.extent[1];
  if (!(other_area > mr.area)) return false;
  const Vec2d off{6, 0};
  w.polygon(pts, filled(c::gray, 0.2, 1.4));
  draw(w, other, pen(c::blue, 1.6));
  caption_at(w, Vec2d{-0.6, -2.0}, "(a) no side on an edge: area " + fmt(other_area), c::black, 13);
  std::vector<Vec2d> moved;
  for (const Vec2d& p : pts) moved.push_back(p + off);
  w.polygon(moved, filled(c::gray, 0.2, 1.4));
  Rectangle<double, 2> best = mr.rectangle;
  best.center += off;
  draw(w, best, pen(c::blue, 1.6));
  w.segment(pts[mr.edge[0]] + off, pts[mr.edge[1]] + off, pen(c::red, 3));
  caption_at(w, off + Vec2d{-0.6, -2.0}, "(b) min_rect: area " + fmt(mr.area), c::black, 13);
  return true;
}

// 13.80: (a) the smallest circle of the points so far (locus::min_circle) and a new point P
// outside it; (b) the circle through P and the old support points (min_circle of those): a point
// that was inside the old circle is outside the new one, so the scan restarts.
bool fig_13_80(SvgWriter& w) {
  const std::vector<Vec2d> pts{{-2, 0}, {2, 0}, {0, 1}, {0.5, -1.85}};
  const Vec2d p{0.5, 2.6};
  const MinCircleResult<double> old = min_circle(std::span<const Vec2d>(pts));
  if (old.status != Status::ok) return false;
  const auto outside = [](const Circle2<double>& circ, const Vec2d& q) {
    return length(q - circ.center) > circ.radius;
  };
  if (!outside(old.circle, p)) return false;
  std::vector<Vec2d> grow{p};
  for (int i = 0; i < old.support_count; ++i)
    grow.push_back(pts[old.support[static_cast<std::size_t>(i)]]);
  const MinCircleResult<double> next = min_circle(std::span<const Vec2d>(grow));
  if (next.status != Status::ok) return false;
  const Vec2d off{6, 0};
  draw(w, old.circle, pen(c::blue, 1.5));
  for (const Vec2d& q : pts) w.point(q, dot(c::black, 3.2));
  for (int i = 0; i < old.support_count; ++i)
    w.point(pts[old.support[static_cast<std::size_t>(i)]], dot(c::blue, 4.5));
  point(w, p, "P", c::red);
  caption_at(w, Vec2d{-2.2, -2.9}, "(a) P is outside: the circle grows", c::black, 13);
  Circle2<double> moved = next.circle;
  moved.center += off;
  Circle2<double> old_moved = old.circle;
  old_moved.center += off;
  draw(w, old_moved, dashed(c::light, 1));
  draw(w, moved, pen(c::blue, 1.5));
  bool restart = false;
  for (const Vec2d& q : pts) {
    const bool out = outside(next.circle, q);
    restart = restart || out;
    w.point(q + off, dot(out ? c::red : c::black, out ? 4.5 : 3.2));
    if (out) label(w, q + off, "now outside", c::red);
  }
  point(w, p + off, "P", c::blue);
  caption_at(w, off + Vec2d{-2.2, -2.9}, "(b) new circle through P: restart", c::black, 13);
  return restart;
}

// 13.81: the area of a triangle as the sum of the signed areas of the triangles <U, Vi, Vi+1>
// (locus::signed_area); the edges visible from U (exact orient2d < 0) give the negative terms.
bool fig_13_81(SvgWriter& w) {
  const Triangle2<double> t{{0, 0}, {3, 0}, {1, 2.4}};
  const std::pair<Vec2d, Vec2d> cases[] = {{{1.6, -1.4}, {0, 0}}, {{4.2, -1.0}, {6, 0}}};
  const char* names[] = {"U\u2081", "U\u2082"};
  for (int k = 0; k < 2; ++k) {
    const auto& [u, off] = cases[k];
    Triangle2<double> moved{off + t.v0, off + t.v1, off + t.v2};
    draw(w, moved, pen(c::black, 1.8));
    double sum = 0;
    int visible = 0;
    for (int i = 0; i < 3; ++i) {
      const Vec2d a = t[i], b = t[(i + 1) % 3];
      const Triangle2<double> part{off + u, off + a, off + b};
      const double sa = signed_area(part);
      sum += sa;
      const bool seen = orient2d(a, b, u) == Sign::negative;
      visible += seen ? 1 : 0;
      draw(w, part, filled(seen ? c::red : c::blue, 0.12, 0.8));
      if (seen) w.segment(off + a, off + b, pen(c::red, 3));
    }
    point(w, off + u, names[k], c::black);
    caption_at(w, off + Vec2d{-0.4, -2.2},
               std::to_string(visible) + (visible == 1 ? " edge" : " edges") + " visible; sum " +
                   fmt(sum) + " = area " + fmt(signed_area(t)),
               c::black, 12);
  }
  return true;
}

}  // namespace

std::vector<Figure> chapter13_figures() {
  return {
      {"13.13", "classify_convex; distance(Line2, Segment2) for the crossed edges", fig_13_13},
      {"13.14", "classify(Polygon2) (exact crossing number); distance(Ray2, Segment2)", fig_13_14},
      {"13.15", "the per-edge ray event of classify(Polygon2), half-open; classify_polygon",
       fig_13_15},
      {"13.16",
       "classify_polygon of the intervals around each boundary point; distance(Line2, "
       "Segment2)",
       fig_13_16},
      {"13.17", "classify_polygon at each interval's middle; distance(Line2, Segment2)", fig_13_17},
      {"13.18",
       "classify(p, vertices, triangles) (simulation of simplicity); orient3d for the "
       "face sides; distance(Ray3, Segment3)",
       fig_13_18},
      {"13.19", "convex_hull (3D); classify_convex just past V along each ray", fig_13_19},
      {"13.32", "polygon_is_convex, classify_polygon, distance(Segment2, Segment2)", fig_13_32},
      {"13.33", "convex_hull (2D)", fig_13_33},
      {"13.34", "convex_hull of H and of H + V (V's hull neighbours are the tangent points)",
       fig_13_34},
      {"13.35", "orient2d (exact), dot", fig_13_35},
      {"13.36", "convex_hull of each half and of the union (bridge edges)", fig_13_36},
      {"13.37",
       "convex_hull of the halves; tangent walk by exact orient2d, checked against the "
       "union's hull",
       fig_13_37},
      {"13.38",
       "convex_hull of the halves; tangent walk by exact orient2d, checked against the "
       "union's hull",
       fig_13_38},
      {"13.39", "convex_hull (3D) of the hull and of hull + P; orient3d face visibility",
       fig_13_39},
      {"13.40",
       "convex_hull (3D) of each icosahedron; of their union by divide_and_conquer (the band "
       "merge), checked against incremental",
       fig_13_40},
      {"13.41",
       "convex_hull (3D); orient3d / orient3d_value along the segment; rotation_about_x; "
       "divide_and_conquer checked against incremental",
       fig_13_41},
      {"13.42", "delaunay of all points; convex_hull, delaunay of the hull vertices", fig_13_42},
      {"13.43", "delaunay, angle_between", fig_13_43},
      {"13.44", "delaunay, circumscribed_circle, incircle (exact)", fig_13_44},
      {"13.45", "delaunay, locate (inside / on_edge)", fig_13_45},
      {"13.46", "incircle (exact), circumscribed_circle", fig_13_46},
      {"13.47", "min_circle (supertriangle around it), classify(Triangle2)", fig_13_47},
      {"13.48",
       "delaunay of the supertriangle and the points so far; incircle; "
       "circumscribed_circle",
       fig_13_48},
      {"13.49",
       "delaunay before and after inserting P (the fan at P = the insertion polygon); "
       "incircle",
       fig_13_49},
      {"13.50", "delaunay with P added, incircle (exact), circumscribed_circle", fig_13_50},
      {"13.51", "delaunay of the supertriangle and all points", fig_13_51},
      {"13.52", "convex_hull (3D) of the lifted points, delaunay (same triangles)", fig_13_52},
      {"13.78", "circumscribed_circle, inscribed_circle", fig_13_78},
      {"13.79", "min_rect (rotating calipers)", fig_13_79},
      {"13.80", "min_circle of the points so far and of the old supports + P", fig_13_80},
      {"13.81", "signed_area(Triangle2), orient2d (exact)", fig_13_81},
  };
}

}  // namespace locus_gallery
