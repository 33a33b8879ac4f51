// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 10 (distance in 3D). Every closest point, distance and parameter shown is
// the result of a locus::distance query on the literal inputs; the 3D scenes are projected
// through the SvgWriter camera (locus's look_at / projection matrices). Figures over a parameter
// domain (10.10, 10.28, 10.29, 10.36) mark the minimiser locus::distance returns; the level
// curves of the squared distance Q are the preimages of spheres around the query under the
// parametrisation (10.10), or Q's sublevel ellipses about the unconstrained minimiser of the
// two carrier lines (locus::distance(Line3, Line3); 10.36).
#include "gallery.hpp"

#include <locus/curves/bezier.hpp>
#include <locus/curves/bezier_surface.hpp>
#include <locus/distance/line_line.hpp>
#include <locus/distance/line_oriented_box.hpp>
#include <locus/distance/line_ray.hpp>
#include <locus/distance/line_rectangle.hpp>
#include <locus/distance/line_segment.hpp>
#include <locus/distance/line_tetrahedron.hpp>
#include <locus/distance/line_triangle.hpp>
#include <locus/distance/point_circle.hpp>
#include <locus/distance/point_convex_polygon.hpp>
#include <locus/distance/point_curve.hpp>
#include <locus/distance/point_ellipsoid.hpp>
#include <locus/distance/point_frustum.hpp>
#include <locus/distance/point_line.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_plane.hpp>
#include <locus/distance/point_polygon3.hpp>
#include <locus/distance/point_polyline.hpp>
#include <locus/distance/point_rectangle.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/distance/point_surface.hpp>
#include <locus/distance/point_tetrahedron.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/ray_ray.hpp>
#include <locus/distance/ray_segment.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/hull/hull2.hpp>
#include <locus/io/svg_primitives.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/ellipsoid.hpp>
#include <locus/primitives/frustum.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/planar_polygon.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/tetrahedron.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

std::string fmt(double x, int prec = 2) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, x);
  return buf;
}

const char* const panel_names[] = {"(a)", "(b)", "(c)", "(d)", "(e)", "(f)"};

// The closest pair of a distance result: a dashed link, the first argument's point in red, the
// second's in blue.
template <class D>
void link(SvgWriter& w, const D& d, std::string_view name0 = "", std::string_view name1 = "") {
  w.segment(d.closest[0], d.closest[1], dashed(c::gray, 1.2));
  point(w, d.closest[0], name0, c::red);
  point(w, d.closest[1], name1, c::blue);
}

// A square of the plane with the given frame (half size h) as a translucent quad.
void plane_patch(SvgWriter& w, const PlaneFrame3<double>& f, double h, const char* colour) {
  closed(w,
         std::vector<Vec3d>{to_world(f, Vec2d{-h, -h}), to_world(f, Vec2d{h, -h}),
                            to_world(f, Vec2d{h, h}), to_world(f, Vec2d{-h, h})},
         filled(colour, 0.08, 1));
}

// A text label in the 2D drawing (panels of parameter domains).
void caption2(SvgWriter& w, const Vec2d& at, std::string_view s, const char* colour = c::black) {
  label(w, at, s, colour, 0, 0);
}

// ---- point to linear components and polylines ---------------------------------------------

// 10.1: distance between a point Q and a line L in 3D.
bool fig_10_1(SvgWriter& w) {
  w.set_camera(camera({3, -7, 3}, {0.5, 0.5, 0.5}));
  const Line3<double> l{{-1, 0, 0}, {1, 0.5, 0.25}};
  const Vec3d q{0.6, 1.6, 1.8};
  const auto d = distance(q, l);
  if (!std::isfinite(d.distance)) return false;
  axes3(w, 1.0, c::light);
  w.segment(point_at(l, -0.8), point_at(l, 3.2), pen(c::blue));
  point(w, l.origin, "P", c::blue);
  w.arrow(l.origin, l.origin + l.direction, pen(c::blue, 2.4));
  label(w, l.origin + l.direction, "d", c::blue, 2, -16);
  link(w, d, "Q", "Q' = P + t\u0304 d");
  label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist " + fmt(d.distance), c::gray);
  return true;
}

// 10.2: the projection of Q - P onto the direction d gives Q'.
bool fig_10_2(SvgWriter& w) {
  w.set_camera(camera({3, -7, 3}, {0.5, 0.5, 0.5}));
  const Line3<double> l{{-1, 0, 0}, {1, 0.5, 0.25}};
  const Vec3d q{0.6, 1.6, 1.8};
  const auto d = distance(q, l);
  if (!std::isfinite(d.distance)) return false;
  w.segment(point_at(l, -0.8), point_at(l, 3.2), pen(c::blue, 1.2));
  w.arrow(l.origin, q, pen(c::green));
  label(w, lerp(l.origin, q, 0.5), "Q \u2212 P", c::green, -60, 0);
  w.arrow(l.origin, d.closest[1], pen(c::orange, 2.4));
  label(w, lerp(l.origin, d.closest[1], 0.6), "t\u0304 d, t\u0304 = " + fmt(d.param_b), c::orange,
        4, -18);
  w.segment(q, d.closest[1], dashed(c::gray, 1.2));
  point(w, l.origin, "P", c::blue);
  point(w, q, "Q", c::red);
  point(w, d.closest[1], "Q'", c::blue);
  return true;
}

// 10.3: distance between a segment and a point: interior point, P0 and P1 closest.
bool fig_10_3(SvgWriter& w) {
  w.set_camera(camera({5, -7, 4}, {2.8, 0, 0.5}));
  const std::array<Vec3d, 3> qs{Vec3d{0.8, 0.2, 1.3}, Vec3d{-0.9, 0.3, 1.0}, Vec3d{2.3, 0, 1.4}};
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3d off{2.8 * static_cast<double>(k), 0, 0};
    const Segment3<double> s{off + Vec3d{-0.3, 0, 0}, off + Vec3d{1.5, 0.4, 0.3}};
    const auto d = distance(qs[k] + off, s);
    if (!std::isfinite(d.distance)) return false;
    draw(w, s, pen(c::blue));
    point(w, s.p0, "P\u2080", c::blue);
    point(w, s.p1, "P\u2081", c::blue);
    link(w, d, "Q", "");
    label(w, off + Vec3d{0, 0, -0.6}, std::string(panel_names[k]) + " t = " + fmt(d.param_b));
  }
  return true;
}

// 10.4: the half-space (slab) test of point/polyline distance: with the current minimum mu, a
// segment whose end points both lie beyond x = Q.x + mu (or below Q.x - mu) is rejected without
// a projection (locus::distance(point, polyline) applies it to every coordinate).
bool fig_10_4(SvgWriter& w) {
  w.set_camera(camera({1.5, -8, 2.5}, {0.5, 0, 0}));
  const Vec3d q{0, 0, 0};
  const Polyline3<double> pl{
      {{-1.6, 1.0, 0.7}, {-0.3, 0.9, 0.4}, {0.6, 1.2, -0.3}, {1.9, 0.6, 0.6}, {2.6, -0.4, 0.2}},
      false};
  const double mu = distance(q, Segment3<double>{pl.vertices[0], pl.vertices[1]}).distance;
  const auto d = distance(q, pl);
  if (!std::isfinite(mu) || !std::isfinite(d.distance)) return false;
  for (const double x : {-mu, mu}) {
    const auto f = plane_frame(Vec3d{x, 0, 0}, Vec3d{1, 0, 0});
    if (!f) return false;
    plane_patch(w, *f, 1.6, c::gray);
    label(w, Vec3d{x, -1.6, -1.6}, x < 0 ? "x = Q.x \u2212 \u03bc" : "x = Q.x + \u03bc", c::gray);
  }
  for (std::size_t i = 0; i + 1 < pl.vertices.size(); ++i) {
    const Segment3<double> s{pl.vertices[i], pl.vertices[i + 1]};
    const bool rejected =
        (s.p0.x > q.x + mu && s.p1.x > q.x + mu) || (s.p0.x < q.x - mu && s.p1.x < q.x - mu);
    draw(w, s, rejected ? dashed(c::orange, 2) : pen(c::blue, 2));
    label(w, lerp(s.p0, s.p1, 0.5), rejected ? "rejected" : "tested",
          rejected ? c::orange : c::blue);
  }
  point(w, q, "Q", c::red);
  w.segment(q, d.closest[1], pen(c::green, 1.4));
  point(w, d.closest[1], "closest", c::green);
  return true;
}

// ---- point to plane, triangle, rectangle ------------------------------------------------------

// 10.6: distance between a point and a plane; the closest point is the orthogonal projection.
bool fig_10_6(SvgWriter& w) {
  w.set_camera(camera({7, -4, 2.2}, {0, 0, 0.5}));
  const Plane3<double> pl{{0.2, 0.3, 1.0}, 0.4};
  const Vec3d q{0.6, -0.3, 2.0};
  const auto d = distance(q, pl);
  const auto f = plane_frame(pl);
  if (!std::isfinite(d.distance) || !f) return false;
  plane_patch(w, PlaneFrame3<double>{d.closest[1], f->u, f->v, f->normal}, 1.6, c::blue);
  w.arrow(d.closest[1] + Vec3d{-1.0, 0.6, 0} - dot(Vec3d{-1.0, 0.6, 0}, f->normal) * f->normal,
          d.closest[1] + Vec3d{-1.0, 0.6, 0} - dot(Vec3d{-1.0, 0.6, 0}, f->normal) * f->normal +
              f->normal,
          pen(c::blue));
  link(w, d, "Q", "Q' (projection)");
  label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist " + fmt(d.distance), c::gray);
  return true;
}

// 10.7: the plane edge-on: the signed distance n . Q + c (locus::signed_distance) is positive on
// the side the normal points to.
bool fig_10_7(SvgWriter& w) {
  const Plane3<double> pl{{0, 0, 1}, 0.0};
  const std::array<Vec3d, 2> qs{Vec3d{-1.0, 0, 1.2}, Vec3d{1.2, 0, -0.8}};
  w.set_camera(camera({0, -8, 0}, {0, 0, 0}));
  w.segment(Vec3d{-2.2, 0, 0}, Vec3d{2.2, 0, 0}, pen(c::blue, 2));
  label(w, Vec3d{2.2, 0, 0}, "plane (edge-on)", c::blue);
  w.arrow(Vec3d{0, 0, 0}, Vec3d{0, 0, 0.8}, pen(c::blue));
  label(w, Vec3d{0, 0, 0.8}, "n", c::blue);
  for (const Vec3d& q : qs) {
    const auto d = distance(q, pl);
    const double sd = signed_distance(q, pl);
    if (!std::isfinite(sd)) return false;
    link(w, d, "Q", "");
    label(w, lerp(d.closest[0], d.closest[1], 0.5), "signed " + fmt(sd), c::gray);
  }
  return true;
}

// 10.8: point to triangle in 3D: the closest point is (a) inside, (b) on an edge, (c) a vertex.
bool fig_10_8(SvgWriter& w) {
  w.set_camera(camera({3.2, -8, 3}, {3.2, 0.5, 0.4}));
  const std::array<Vec3d, 3> qs{Vec3d{0.7, 0.5, 1.2}, Vec3d{1.0, -0.8, 0.8},
                                Vec3d{-0.6, -0.4, 0.9}};
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3d off{3.0 * static_cast<double>(k), 0, 0};
    const Triangle3<double> t{off + Vec3d{0, 0, 0}, off + Vec3d{2, 0.2, 0.1},
                              off + Vec3d{0.6, 1.6, 0.2}};
    const auto d = distance(off + qs[k], t);
    if (!std::isfinite(d.distance)) return false;
    draw(w, t, filled(c::blue, 0.15));
    link(w, d, "Q", "");
    const Vec3d b = d.param_b;
    const int zeros = (b.x == 0) + (b.y == 0) + (b.z == 0);
    label(w, off + Vec3d{0.2, -0.4, -0.5},
          std::string(panel_names[k]) + (zeros == 0   ? " interior"
                                         : zeros == 1 ? " edge"
                                                      : " vertex"));
  }
  return true;
}

// 10.10: level curves Q(s, t) = V of the squared distance over the triangle's (s, t) domain for
// a query point above the triangle's plane: preimages of circles about the projection (a
// sphere about the query meets the plane in a circle), mapped to (s, t) by locus::barycentric in
// plane coordinates (plane_frame, to_plane). The minimum (red) is where the smallest level
// curve touches the domain.
bool fig_10_10(SvgWriter& w) {
  const Triangle3<double> t{{0, 0, 0}, {2.0, 0.3, 0.4}, {0.5, 1.6, 0.2}};
  const std::array<Vec2d, 2> st{Vec2d{0.9, 0.7}, Vec2d{1.4, -0.35}};
  const auto f = plane_frame(t.v0, normal(t));
  if (!f) return false;
  const Triangle2<double> t2{to_plane(*f, t.v0), to_plane(*f, t.v1), to_plane(*f, t.v2)};
  for (std::size_t k = 0; k < 2; ++k) {
    const Vec2d off{2.8 * static_cast<double>(k), 0};
    const Vec3d q = point_at(t, st[k]) + 0.6 * f->normal;
    const auto d = distance(q, t);
    const auto pd = distance(q, plane_of(*f));
    if (!std::isfinite(d.distance) || !std::isfinite(pd.distance)) return false;
    const Vec2d foot = to_plane(*f, pd.closest[1]);
    w.segment(off + Vec2d{-0.6, 0}, off + Vec2d{2.0, 0}, pen(c::gray, 1));
    w.segment(off + Vec2d{0, -0.6}, off + Vec2d{0, 2.0}, pen(c::gray, 1));
    closed(w, std::vector<Vec2d>{off, off + Vec2d{1, 0}, off + Vec2d{0, 1}}, pen(c::black, 2));
    label(w, off + Vec2d{2.0, 0}, "s", c::black, 2, 4);
    label(w, off + Vec2d{0, 2.0}, "t", c::black, 4, -12);
    // In-plane radius of the sphere |X - Q| = r: sqrt(r^2 - h^2).
    const double h2 = pd.sqr_distance;
    for (const double factor : {0.6, 1.0, 1.5}) {
      const double rin = std::sqrt(std::max(0.0, d.sqr_distance - h2)) * factor;
      w.curve(
          [&](double a) {
            const auto b = barycentric(t2, foot + rin * Vec2d{std::cos(a), std::sin(a)});
            return b ? off + Vec2d{b->y, b->z} : off;
          },
          0, 2 * std::numbers::pi, 96, factor == 1.0 ? pen(c::red, 1.6) : dashed(c::orange, 1));
    }
    const auto bf = barycentric(t2, foot);
    if (!bf) return false;
    point(w, off + Vec2d{bf->y, bf->z}, "", c::gray);
    point(w, off + Vec2d{d.param_b.y, d.param_b.z}, "", c::red);
    caption2(w, off + Vec2d{-0.6, -0.9},
             std::string(panel_names[k]) + " Q = " + fmt(d.sqr_distance, 3));
  }
  return true;
}

// 10.12: distance between a point and a rectangle in 3D.
bool fig_10_12(SvgWriter& w) {
  w.set_camera(camera({5, -6, 5}, {0.5, 0, 0.3}));
  const Vec3d u = normalize(Vec3d{1, 0.2, 0.1});
  const Vec3d v = normalize(cross(Vec3d{0.1, -0.2, 1}, u));
  const Rectangle3<double> r{{0, 0, 0}, {u, v}, {1.2, 0.7}};
  draw(w, r, filled(c::blue, 0.15));
  point(w, r.center, "C", c::blue);
  w.arrow(r.center, r.center + r.axis[0], pen(c::blue, 1.2));
  w.arrow(r.center, r.center + r.axis[1], pen(c::blue, 1.2));
  const std::array<Vec3d, 2> qs{Vec3d{0.3, 0.2, 1.2}, Vec3d{2.2, 1.0, 0.8}};
  for (const Vec3d& q : qs) {
    const auto d = distance(q, r);
    if (!std::isfinite(d.distance)) return false;
    link(w, d, "Q", "(s, t) = " + coordinates(d.param_b.x, d.param_b.y));
  }
  return true;
}

// ---- point to polygon ---------------------------------------------------------------------------

// The non-convex pentagon of 10.14 / 10.15 (vertices on the plane z = 0.1 x + 0.15 y), as a
// PlanarPolygon3 (locus::planar_polygon: Newell plane, frame, plane coordinates), and the queries.
std::optional<PlanarPolygon3<double>> polygon10() {
  const std::vector<Vec3d> v{
      {0, 0, 0}, {2.2, 0.2, 0.25}, {2.0, 1.6, 0.44}, {1.1, 0.9, 0.245}, {0.3, 1.8, 0.3}};
  return planar_polygon(std::span<const Vec3d>(v));
}
const std::array<Vec3d, 3> polygon10_queries{Vec3d{1.2, 0.5, 1.4}, Vec3d{1.2, 1.7, 1.1},
                                             Vec3d{2.9, -0.5, 0.3}};

// 10.14: distance from points to a filled polygon in 3D: above the interior the closest point
// is the projection, otherwise a point of the boundary.
bool fig_10_14(SvgWriter& w) {
  const auto poly = polygon10();
  if (!poly) return false;
  w.set_camera(camera({4, -6, 5}, {1.1, 0.8, 0.5}));
  std::vector<Vec3d> v3;
  for (std::size_t i = 0; i < poly->polygon.vertices.size(); ++i) v3.push_back(vertex(*poly, i));
  closed(w, v3, filled(c::blue, 0.15));
  for (std::size_t i = 0; i < v3.size(); ++i) point(w, v3[i], "V" + std::to_string(i), c::blue);
  for (const Vec3d& p : polygon10_queries) {
    const auto d = distance(p, *poly);
    if (!std::isfinite(d.distance)) return false;
    const double h = std::abs(dot(p - poly->frame.origin, poly->frame.normal));
    const bool interior = std::abs(d.distance - h) <= 1e-12 * (1 + h);
    bool at_vertex = false;
    for (const Vec3d& v : v3) at_vertex = at_vertex || length(v - d.closest[1]) <= 1e-12;
    link(w, d, at_vertex ? "P (a vertex is closest)" : "P",
         interior ? "projection" : (at_vertex ? "" : "edge point"));
    label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist " + fmt(d.distance), c::gray);
  }
  return true;
}

// 10.15: the same queries solved in the polygon's plane: P projects to P' = to_plane(frame, P)
// at height h; the 2D nearest point of the filled polygon to P' (param_b, plane coordinates)
// gives dist^2 = h^2 + |P' - closest|^2.
bool fig_10_15(SvgWriter& w) {
  const auto poly = polygon10();
  if (!poly) return false;
  closed(w, poly->polygon.vertices, filled(c::blue, 0.15, 2));
  for (std::size_t i = 0; i < poly->polygon.vertices.size(); ++i)
    point(w, poly->polygon.vertices[i], "V" + std::to_string(i), c::blue);
  // The plane axes, drawn beside the polygon (their origin is the vertex average).
  const Vec2d ax = poly->polygon.vertices[0] + Vec2d{-0.7, 0.2};
  w.arrow(ax, ax + Vec2d{0.5, 0}, pen(c::gray, 1.2));
  w.arrow(ax, ax + Vec2d{0, 0.5}, pen(c::gray, 1.2));
  label(w, ax + Vec2d{0.5, 0}, "u", c::gray, 2, 4);
  label(w, ax + Vec2d{0, 0.5}, "v", c::gray, 4, -12);
  double y = -1.6;
  for (std::size_t k = 0; k < polygon10_queries.size(); ++k) {
    const Vec3d& p = polygon10_queries[k];
    const auto d = distance(p, *poly);
    if (!std::isfinite(d.distance)) return false;
    const Vec2d q = to_plane(poly->frame, p);
    const double h = dot(p - poly->frame.origin, poly->frame.normal);
    const double in_plane = length(q - d.param_b);
    w.segment(q, d.param_b, dashed(c::gray, 1.2));
    point(w, q, "P'" + std::to_string(k), c::red);
    w.point(d.param_b, dot(c::blue));
    caption2(w, Vec2d{-1.4, y},
             "P'" + std::to_string(k) + ": h = " + fmt(h) + ", in plane " + fmt(in_plane) +
                 ", dist = \u221a(h\u00b2 + d\u00b2) = " +
                 fmt(std::sqrt(h * h + in_plane * in_plane)) + " (3D: " + fmt(d.distance) + ")");
    y -= 0.32;
  }
  return true;
}

// ---- circles and disks ----------------------------------------------------------------------

void circle_scene(SvgWriter& w, const Circle3<double>& circ) {
  w.set_camera(camera({5, -6, 3.5}, {0, 0, 0.4}));
  draw(w, circ, pen(c::blue, 2));
  point(w, circ.center, "C", c::blue);
  w.arrow(circ.center, circ.center + normalize(circ.normal), pen(c::blue, 1.2));
  label(w, circ.center + normalize(circ.normal), "N", c::blue);
}

// 10.16: the typical case: the closest point of the circle to P.
bool fig_10_16(SvgWriter& w) {
  const Circle3<double> circ{{0, 0, 0}, {0, 0, 1}, 1.2};
  circle_scene(w, circ);
  const Vec3d p{1.5, -0.8, 1.2};
  const auto d = distance(p, circ);
  if (!std::isfinite(d.distance)) return false;
  const Vec3d proj{p.x, p.y, 0};
  w.segment(p, proj, dashed(c::light, 1));
  w.segment(circ.center, proj, dashed(c::light, 1));
  link(w, d, "P", "K");
  return true;
}

// 10.17: P on the axis: every circle point is at the same distance (unique = false).
bool fig_10_17(SvgWriter& w) {
  const Circle3<double> circ{{0, 0, 0}, {0, 0, 1}, 1.2};
  circle_scene(w, circ);
  const Vec3d p{0, 0, 1.4};
  const auto d = distance(p, circ);
  if (!std::isfinite(d.distance)) return false;
  for (int k = 0; k < 8; ++k)
    w.segment(p, point_at(circ, k * std::numbers::pi / 4), dashed(c::light, 1));
  link(w, d, "P", "");
  label(w, Vec3d{0, 0, -0.7},
        std::string("dist ") + fmt(d.distance) +
            (d.unique ? "" : ", every circle point closest (not unique)"));
  return true;
}

// 10.18 / 10.19: the disk: P projects inside (closest = projection) or outside (the rim).
bool disk_figure(SvgWriter& w, const Vec3d& p) {
  const Disk3<double> disk{{0, 0, 0}, {0, 0, 1}, 1.2};
  w.set_camera(camera({5, -6, 3.5}, {0, 0, 0.4}));
  draw(w, Circle3<double>{disk.center, disk.normal, disk.radius}, filled(c::blue, 0.15));
  point(w, disk.center, "C", c::blue);
  const auto d = distance(p, disk);
  if (!std::isfinite(d.distance)) return false;
  w.segment(p, Vec3d{p.x, p.y, 0}, dashed(c::light, 1));
  link(w, d, "P", "closest");
  return true;
}
bool fig_10_18(SvgWriter& w) { return disk_figure(w, Vec3d{0.5, -0.4, 1.3}); }
bool fig_10_19(SvgWriter& w) { return disk_figure(w, Vec3d{1.9, -0.9, 1.0}); }

// ---- polyhedra, boxes, frustum, ellipsoid -------------------------------------------------

// 10.20: distance from points to a solid tetrahedron (face, edge, vertex closest).
bool fig_10_20(SvgWriter& w) {
  w.set_camera(camera({5, -6, 3}, {0.5, 0.4, 0.5}));
  const Tetrahedron3<double> tet{{{0, 0, 0}, {1.8, 0, 0}, {0.6, 1.6, 0}, {0.7, 0.6, 1.5}}};
  draw(w, tet, filled(c::blue, 0.1));
  const std::array<Vec3d, 3> ps{Vec3d{1.5, -0.8, 1.3}, Vec3d{-0.9, -0.5, 0.4},
                                Vec3d{0.7, 0.5, 2.4}};
  for (const Vec3d& p : ps) {
    const auto d = distance(p, tet);
    if (!std::isfinite(d.distance)) return false;
    int nonzero = 0;
    for (int i = 0; i < 4; ++i) nonzero += d.param_b[i] != 0;
    link(w, d, nonzero == 3 ? "P (face)" : nonzero == 2 ? "P (edge)" : "P (vertex)", "");
  }
  return true;
}

const OrientedBox3<double> box10{
    {0, 0, 0}, {Vec3d{0.8, 0.6, 0}, Vec3d{-0.6, 0.8, 0}, Vec3d{0, 0, 1}}, {1.2, 0.7, 0.5}};

// 10.21: distance from points to an oriented box.
bool fig_10_21(SvgWriter& w) {
  w.set_camera(camera({6, -4, 5}));
  draw(w, box10, filled(c::blue, 0.08));
  frame(w, Frame3d{box10.center, {box10.axis[0], box10.axis[1], box10.axis[2]}}, c::gray, "C",
        "U\u2080", "U\u2081", "U\u2082");
  const std::array<Vec3d, 2> ps{Vec3d{2.2, 0.8, 1.3}, Vec3d{-0.5, -2.0, 0.2}};
  for (const Vec3d& p : ps) {
    const auto d = distance(p, box10);
    if (!std::isfinite(d.distance)) return false;
    link(w, d, "P", "");
  }
  return true;
}

// 10.22: the computation in the box frame: the coordinates of P - C along the axes are clamped
// to the extents (seen along U2: the face z = const of the box frame).
bool fig_10_22(SvgWriter& w) {
  const Vec3d p{0.74, 2.18, 0.3};
  const auto d = distance(p, box10);
  if (!std::isfinite(d.distance)) return false;
  const Vec3d dp = p - box10.center;
  const Vec2d local{dot(dp, box10.axis[0]), dot(dp, box10.axis[1])};
  const Vec2d clamped{d.param_b.x * box10.extent.x, d.param_b.y * box10.extent.y};
  const double e0 = box10.extent.x, e1 = box10.extent.y;
  closed(w, std::vector<Vec2d>{{-e0, -e1}, {e0, -e1}, {e0, e1}, {-e0, e1}}, filled(c::blue, 0.12));
  w.arrow(Vec2d{0, 0}, Vec2d{1.0, 0}, pen(c::gray, 1.2));
  w.arrow(Vec2d{0, 0}, Vec2d{0, 1.0}, pen(c::gray, 1.2));
  label(w, Vec2d{1.0, 0}, "U\u2080", c::gray);
  label(w, Vec2d{0, 1.0}, "U\u2081", c::gray);
  w.segment(Vec2d{local.x, 0}, local, dashed(c::light, 1));
  w.segment(Vec2d{0, local.y}, local, dashed(c::light, 1));
  w.segment(local, clamped, dashed(c::gray, 1.2));
  w.point(local, dot(c::red));
  label(w, local, "(P \u2212 C)\u00b7U\u1d62 = " + coordinates(local.x, local.y), c::red, -40, 10);
  w.point(clamped, dot(c::blue));
  label(w, clamped, "clamped: " + coordinates(clamped.x, clamped.y), c::blue, 6, -18);
  caption2(w, Vec2d{-e0, -e1 - 0.5}, "dist " + fmt(d.distance) + " (in 3D)");
  return true;
}

// 10.23: the frustum and closest points of the first octant's Voronoi regions.
bool fig_10_23(SvgWriter& w) {
  w.set_camera(camera({-4, -7, 4}, {0, 0, 2}));
  const Frustum3<double> fr{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, 1.0, 3.0, 0.5, 0.8};
  const std::array<Vec3d, 8> k = corners(fr);
  box_edges(w, k, pen(c::blue, 1.4));  // corner bits: +R, +U, far, as box_edges expects
  for (std::size_t i = 0; i < 4; ++i) w.segment(fr.origin, k[i], dashed(c::light, 1));
  point(w, fr.origin, "E", c::gray);
  const std::array<Vec3d, 4> ps{Vec3d{0.4, 0.2, 0.2}, Vec3d{2.0, 0.3, 2.0}, Vec3d{1.8, 1.8, 3.8},
                                Vec3d{0.2, 0.1, 4.0}};
  for (const Vec3d& p : ps) {
    const auto d = distance(p, fr);
    if (!std::isfinite(d.distance)) return false;
    link(w, d, "", "");
  }
  return true;
}

// 10.24: closest points of an ellipsoid's surface to a few query points (inside and outside).
bool fig_10_24(SvgWriter& w) {
  w.set_camera(camera({5, -6, 3}));
  const Ellipsoid3<double> e{
      {0, 0, 0}, {Vec3d{1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, 0, 1}}, {1.6, 1.0, 0.7}};
  for (int k = 0; k < 12; ++k) {
    const double th = k * std::numbers::pi / 6;
    w.curve(
        [&](double ph) {
          Vec2d out{};
          return w.project(point_at(e, Vec2d{th, ph}), out) ? out : Vec2d{NAN, NAN};
        },
        0, std::numbers::pi, 48, pen(c::light, 0.8));
  }
  for (int k = 1; k < 6; ++k) {
    const double ph = k * std::numbers::pi / 6;
    w.curve(
        [&](double th) {
          Vec2d out{};
          return w.project(point_at(e, Vec2d{th, ph}), out) ? out : Vec2d{NAN, NAN};
        },
        0, 2 * std::numbers::pi, 96, pen(c::light, 0.8));
  }
  const std::array<Vec3d, 4> ps{Vec3d{2.3, 0.6, 0.8}, Vec3d{0.3, -1.6, 0.9}, Vec3d{0.5, 0.2, 0.1},
                                Vec3d{-0.6, 0.3, 1.5}};
  for (const Vec3d& p : ps) {
    const auto d = distance(p, e);
    if (!std::isfinite(d.distance)) return false;
    link(w, d, "", "");
  }
  return true;
}

// 10.25: distance from points to a parametric curve (a cubic Bezier curve in 3D,
// locus::distance(Vec3, BezierCurve3): every critical point of the squared distance).
bool fig_10_25(SvgWriter& w) {
  w.set_camera(camera({5, -6, 3}, {1.2, 0.5, 0.5}));
  const BezierCurve<double, 3> curve{
      {{0, 0, 0}, {0.8, 1.8, 0.6}, {2.0, -0.8, 1.4}, {2.8, 1.2, 0.4}}};
  std::vector<Vec3d> pts;
  for (int k = 0; k <= 120; ++k) pts.push_back(point_at(curve, k / 120.0));
  w.polyline(pts, pen(c::blue, 2));
  w.polyline(curve.control, dashed(c::light, 1));
  for (const Vec3d& p : {Vec3d{1.0, 1.4, 1.6}, Vec3d{2.2, -0.6, 0.2}, Vec3d{3.3, 1.6, 1.2}}) {
    const auto d = distance(p, curve);
    if (!std::isfinite(d.distance)) return false;
    link(w, d, "P", "t = " + fmt(d.param_b));
  }
  return true;
}

// 10.26: distance from points to a parametric surface: a bicubic Bézier patch and the closest
// points locus::distance(Vec3, BezierPatch) finds (the global minimum of |S(u, v) - P|^2; an
// interior critical point, or a point of the boundary curves).
bool fig_10_26(SvgWriter& w) {
  const double z[4][4] = {
      {0.0, 0.6, 0.4, 0.0}, {0.5, 2.2, 1.6, 0.3}, {0.2, 1.4, 2.4, 0.8}, {-0.2, 0.3, 0.9, 0.4}};
  BezierPatch<double, 3> patch{4, 4, {}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) patch.control.push_back({1.0 * i, 1.0 * j, z[i][j]});
  w.set_camera(camera({7, -6, 5}, {1.5, 1.5, 0.8}));
  for (int i = 0; i < 4; ++i) {
    std::vector<Vec3d> row, col;
    for (int j = 0; j < 4; ++j) {
      row.push_back(patch.control[static_cast<std::size_t>(i * 4 + j)]);
      col.push_back(patch.control[static_cast<std::size_t>(j * 4 + i)]);
    }
    w.polyline(row, dashed(c::light, 0.8));
    w.polyline(col, dashed(c::light, 0.8));
  }
  for (int k = 0; k <= 10; ++k) {
    std::vector<Vec3d> iso_u, iso_v;
    for (int m = 0; m <= 40; ++m) {
      iso_u.push_back(point_at(patch, k / 10.0, m / 40.0));
      iso_v.push_back(point_at(patch, m / 40.0, k / 10.0));
    }
    const SvgStyle st = (k == 0 || k == 10) ? pen(c::blue, 1.8) : pen(c::blue, 0.7);
    w.polyline(iso_u, st);
    w.polyline(iso_v, st);
  }
  for (const Vec3d& p : {Vec3d{1.1, 1.4, 3.2}, Vec3d{3.9, 2.4, 1.6}, Vec3d{1.8, 1.3, -0.9}}) {
    const auto d = distance(p, patch);
    if (!std::isfinite(d.distance)) return false;
    link(w, d, "P", "(u, v) = " + coordinates(d.param_b.x, d.param_b.y));
  }
  return true;
}

// ---- linear-linear ----------------------------------------------------------------------------

// 10.27: distance between two lines in 3D; the connecting segment is perpendicular to both.
bool fig_10_27(SvgWriter& w) {
  w.set_camera(camera({6, -5, 3}, {0.5, 0.5, 0.5}));
  const Line3<double> a{{-1, 0, 0}, {1, 0.2, 0}}, b{{0.5, -1, 1.2}, {0.1, 1, 0.2}};
  const auto d = distance(a, b);
  if (!std::isfinite(d.distance)) return false;
  w.segment(point_at(a, -1.0), point_at(a, 3.0), pen(c::blue));
  w.segment(point_at(b, -1.0), point_at(b, 2.8), pen(c::green));
  label(w, point_at(a, 3.0), "L\u2080(s)", c::blue);
  label(w, point_at(b, 2.8), "L\u2081(t)", c::green);
  link(w, d, "L\u2080(s\u0304)", "L\u2081(t\u0304)");
  label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist " + fmt(d.distance), c::gray);
  return true;
}

// The six parameter domains of figure 10.28, drawn clipped to [lo, hi]^2 about off.
void domain(SvgWriter& w, const Vec2d& off, bool s_lo, bool s_hi, bool t_lo, bool t_hi) {
  const double lo = -1.2, hi = 2.2;
  const Vec2d a{s_lo ? 0.0 : lo, t_lo ? 0.0 : lo}, b{s_hi ? 1.0 : hi, t_hi ? 1.0 : hi};
  closed(w, std::vector<Vec2d>{off + a, off + Vec2d{b.x, a.y}, off + b, off + Vec2d{a.x, b.y}},
         filled(c::blue, 0.12, 0.8));
  w.arrow(off + Vec2d{lo, 0}, off + Vec2d{hi + 0.2, 0}, pen(c::gray, 1));
  w.arrow(off + Vec2d{0, lo}, off + Vec2d{0, hi + 0.2}, pen(c::gray, 1));
  label(w, off + Vec2d{hi + 0.2, 0}, "s", c::gray, 2, 4);
  label(w, off + Vec2d{0, hi + 0.2}, "t", c::gray, 4, -12);
}

// 10.28: the parameter domains of the six linear-linear pairs, each with the minimiser that
// locus::distance returns for a sample pair.
bool fig_10_28(SvgWriter& w) {
  const Vec3d p0{0, 0, 0}, d0{1, 0.2, 0}, p1{1.7, 0.9, 0.7}, d1{0.05, 1, 0.1};
  const Line3<double> la{p0, d0}, lb{p1, d1};
  const Ray<double, 3> ra{p0, d0}, rb{p1, d1};
  const Segment3<double> sa{p0, p0 + d0}, sb{p1, p1 + d1};
  struct Panel {
    const char* name;
    bool s_lo, s_hi, t_lo, t_hi;
    double s, t;
  };
  const auto ll = distance(la, lb);
  const auto lr = distance(la, rb);
  const auto ls = distance(la, sb);
  const auto rr = distance(ra, rb);
  const auto rs = distance(ra, sb);
  const auto ss = distance(sa, sb);
  const std::array<Panel, 6> panels{{
      {"line-line", false, false, false, false, ll.param_a, ll.param_b},
      {"line-ray", false, false, true, false, lr.param_a, lr.param_b},
      {"line-segment", false, false, true, true, ls.param_a, ls.param_b},
      {"ray-ray", true, false, true, false, rr.param_a, rr.param_b},
      {"ray-segment", true, false, true, true, rs.param_a, rs.param_b},
      {"segment-segment", true, true, true, true, ss.param_a, ss.param_b},
  }};
  for (std::size_t k = 0; k < 6; ++k) {
    const auto& pn = panels[k];
    if (!std::isfinite(pn.s) || !std::isfinite(pn.t)) return false;
    const Vec2d off{4.6 * static_cast<double>(k % 3), -5.2 * static_cast<double>(k / 3)};
    domain(w, off, pn.s_lo, pn.s_hi, pn.t_lo, pn.t_hi);
    point(w, off + Vec2d{pn.s, pn.t}, "", c::red);
    caption2(w, off + Vec2d{-1.2, -1.8}, std::string(panel_names[k]) + " " + pn.name);
    caption2(w, off + Vec2d{-1.2, -2.4}, "minimiser " + coordinates(pn.s, pn.t), c::red);
  }
  return true;
}

// 10.29: visibility of the domain boundaries: with the unconstrained minimiser (the two carrier
// lines' parameters, locus::distance(Line3, Line3)) outside the unit square, only the edges
// facing it can hold the constrained minimum (locus::distance(Segment3, Segment3), red).
bool fig_10_29(SvgWriter& w) {
  const std::array<std::pair<Segment3<double>, Segment3<double>>, 2> pairs{{
      {{{0, 0, 0}, {1, 0.2, 0}}, {{1.6, -0.3, 0.6}, {1.8, 0.8, 0.5}}},
      {{{0, 0, 0}, {1, 0.2, 0}}, {{-0.9, -1.6, 0.6}, {-0.7, -0.7, 0.5}}},
  }};
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& [a, b] = pairs[k];
    const auto free = distance(Line3<double>{a.p0, a.p1 - a.p0}, Line3<double>{b.p0, b.p1 - b.p0});
    const auto con = distance(a, b);
    if (!std::isfinite(free.distance) || !std::isfinite(con.distance)) return false;
    const Vec2d off{4.6 * static_cast<double>(k), 0};
    const Vec2d m{free.param_a, free.param_b};
    const std::array<Vec2d, 4> sq{Vec2d{0, 0}, Vec2d{1, 0}, Vec2d{1, 1}, Vec2d{0, 1}};
    for (std::size_t e = 0; e < 4; ++e) {
      const Vec2d p = sq[e], q = sq[(e + 1) % 4];
      // Visible: the minimiser is strictly on the outer side of the edge's line.
      const Vec2d outward = -perp(q - p);
      const bool visible = dot(m - p, outward) > 0;
      w.segment(off + p, off + q, visible ? pen(c::green, 3) : pen(c::black, 1.2));
    }
    w.segment(off + m, off + Vec2d{con.param_a, con.param_b}, dashed(c::light, 1));
    point(w, off + m, "(s\u0304, t\u0304) free", c::gray);
    point(w, off + Vec2d{con.param_a, con.param_b}, "", c::red);
    caption2(w, off + Vec2d{-0.2, -0.6}, std::string(panel_names[k]) + " visible edges green");
  }
  return true;
}

// 3D pairs of linear components, with the connecting segment.
template <class A, class B>
bool pair3(SvgWriter& w, const A& a, const B& b, const std::vector<Vec3d>& a_pts,
           const std::vector<Vec3d>& b_pts, bool a_arrow, bool b_arrow) {
  w.set_camera(camera({6, -5, 3}, {0.5, 0.3, 0.4}));
  const auto d = distance(a, b);
  if (!std::isfinite(d.distance)) return false;
  const auto draw_part = [&](const std::vector<Vec3d>& pts, bool arrow, const char* colour) {
    if (arrow)
      w.arrow(pts[0], pts[1], pen(colour));
    else
      w.segment(pts[0], pts[1], pen(colour));
  };
  draw_part(a_pts, a_arrow, c::blue);
  draw_part(b_pts, b_arrow, c::green);
  link(w, d, "s = " + fmt(d.param_a), "t = " + fmt(d.param_b));
  label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist " + fmt(d.distance), c::gray);
  return true;
}

// 10.31: two segments.
bool fig_10_31(SvgWriter& w) {
  const Segment3<double> a{{-1, 0, 0}, {1.5, 0.5, 0}}, b{{0.9, -1.2, 1.0}, {1.6, 0.9, 1.4}};
  w.set_camera(camera({6, -5, 3}, {0.5, 0.3, 0.4}));
  point(w, a.p0, "P\u2080", c::blue);
  point(w, a.p1, "P\u2081", c::blue);
  point(w, b.p0, "Q\u2080", c::green);
  point(w, b.p1, "Q\u2081", c::green);
  return pair3(w, a, b, {a.p0, a.p1}, {b.p0, b.p1}, false, false);
}
// 10.32: a line and a ray.
bool fig_10_32(SvgWriter& w) {
  const Line3<double> a{{-1, 0, 0}, {1, 0.2, 0}};
  const Ray<double, 3> b{{1.2, 0.4, 0.8}, {0.1, 1, 0.3}};
  return pair3(w, a, b, {point_at(a, -0.8), point_at(a, 3.0)}, {b.origin, point_at(b, 2.0)}, false,
               true);
}
// 10.33: a line and a segment.
bool fig_10_33(SvgWriter& w) {
  const Line3<double> a{{-1, 0, 0}, {1, 0.2, 0}};
  const Segment3<double> b{{0.4, -1.3, 1.1}, {1.4, 0.8, 0.7}};
  return pair3(w, a, b, {point_at(a, -0.8), point_at(a, 3.0)}, {b.p0, b.p1}, false, false);
}
// 10.34: a ray and a segment.
bool fig_10_34(SvgWriter& w) {
  const Ray<double, 3> a{{-1, 0, 0}, {1, 0.2, 0}};
  const Segment3<double> b{{-1.6, -1.0, 0.9}, {-1.2, 1.0, 0.5}};
  return pair3(w, a, b, {a.origin, point_at(a, 3.0)}, {b.p0, b.p1}, true, false);
}

// 10.35: the nine regions of the (s, t) plane around the unit square, each labelled with the
// part of the square's boundary where locus::distance(Segment3, Segment3) finds the minimum for a
// segment pair whose carrier lines have their minimiser in that region.
bool fig_10_35(SvgWriter& w) {
  const double lo = -1.0, hi = 2.0;
  for (const double x : {0.0, 1.0}) {
    w.segment(Vec2d{x, lo}, Vec2d{x, hi}, pen(c::gray, 1));
    w.segment(Vec2d{lo, x}, Vec2d{hi, x}, pen(c::gray, 1));
  }
  closed(w, std::vector<Vec2d>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, filled(c::blue, 0.15, 2));
  // Segments A(s) = s e_x, B(t) = (x, y + t, h): the lines' minimiser is (s, t) = (x, -y).
  // Regions numbered as in the book: 0 the square, then counter-clockwise from s > 1.
  const int number[3][3] = {{6, 7, 8}, {5, 0, 1}, {4, 3, 2}};  // [t class][s class]
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const double s = -0.5 + i, t = -0.5 + j;
      const Segment3<double> a{{0, 0, 0}, {1, 0, 0}}, b{{s, -t, 0.5}, {s, 1 - t, 0.5}};
      const auto d = distance(a, b);
      if (!std::isfinite(d.distance)) return false;
      point(w, Vec2d{s, t}, "", c::gray);
      w.segment(Vec2d{s, t}, Vec2d{d.param_a, d.param_b}, dashed(c::light, 1));
      point(w, Vec2d{d.param_a, d.param_b}, "", c::red);
      label(w, Vec2d{s, t}, std::to_string(number[j][i]), c::black, 6, 4);
    }
  label(w, Vec2d{hi, 0}, "s", c::black, 2, 4);
  label(w, Vec2d{0, hi}, "t", c::black, 4, -12);
  return true;
}

// 10.36: level curves Q(s, t) = V over the unit square for two segments: ellipses about the
// carrier lines' minimiser (s0, t0) (locus::distance(Line3, Line3)), Q = Q0 + |dA ds - dB dt|^2;
// the constrained minimum (locus::distance(Segment3, Segment3)) is where the smallest level curve
// touches the square: (a) interior, (b) an edge, (c) a corner.
bool fig_10_36(SvgWriter& w) {
  const Segment3<double> a{{0, 0, 0}, {1.6, 0.3, 0}};
  const std::array<Segment3<double>, 3> bs{
      Segment3<double>{{0.4, -0.8, 0.5}, {0.9, 1.0, 0.5}},
      Segment3<double>{{2.2, -0.6, 0.5}, {2.5, 1.2, 0.4}},
      Segment3<double>{{2.6, 1.2, 0.5}, {2.9, 2.9, 0.4}},
  };
  for (std::size_t k = 0; k < 3; ++k) {
    const Segment3<double>& b = bs[k];
    const Vec3d da = a.p1 - a.p0, db = b.p1 - b.p0;
    const auto free = distance(Line3<double>{a.p0, da}, Line3<double>{b.p0, db});
    const auto con = distance(a, b);
    if (!std::isfinite(free.distance) || !std::isfinite(con.distance)) return false;
    const Vec2d off{3.8 * static_cast<double>(k), 0};
    const Vec2d m{free.param_a, free.param_b};
    closed(w, std::vector<Vec2d>{off, off + Vec2d{1, 0}, off + Vec2d{1, 1}, off + Vec2d{0, 1}},
           filled(c::blue, 0.12, 2));
    const double q0 = free.sqr_distance, v = con.sqr_distance;
    // Interior minimum (v = q0): a few levels above it instead.
    const double step = v - q0 > 1e-9 ? v - q0 : 0.12;
    for (const double f : {0.4, 1.0, 1.8}) {
      const double level = q0 + f * step;
      if (!(level > q0)) continue;
      w.curve(
          [&](double th) {
            const Vec2d u{std::cos(th), std::sin(th)};
            const double rate = sqr_length(u.x * da - u.y * db);
            return off + m + std::sqrt((level - q0) / rate) * u;
          },
          0, 2 * std::numbers::pi, 120,
          f == 1.0 && v - q0 > 1e-9 ? pen(c::red, 1.6) : dashed(c::orange, 1));
    }
    point(w, off + m, "", c::gray);
    point(w, off + Vec2d{con.param_a, con.param_b}, "", c::red);
    caption2(w, off + Vec2d{0, -1.4},
             std::string(panel_names[k]) + " " + coordinates(con.param_a, con.param_b));
  }
  return true;
}

// ---- linear to planar components and boxes -------------------------------------------------

// 10.37: distance between a line and a triangle.
bool fig_10_37(SvgWriter& w) {
  w.set_camera(camera({5, -6, 4}, {0.6, 0.4, 0.4}));
  const Triangle3<double> t{{0, 0, 0}, {2, 0.2, 0.1}, {0.6, 1.6, 0.2}};
  const Line3<double> l{{2.2, 1.4, 1.2}, {1, -0.6, 0.3}};
  const auto d = distance(l, t);
  if (!std::isfinite(d.distance)) return false;
  draw(w, t, filled(c::blue, 0.15));
  w.segment(point_at(l, -1.8), point_at(l, 1.2), pen(c::green));
  link(w, d, "", "");
  label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist " + fmt(d.distance), c::gray);
  return true;
}

// 10.38: the parametric triangle T(s, t) = P0 + s e0 + t e1 (locus::point_at).
bool fig_10_38(SvgWriter& w) {
  w.set_camera(camera({5, -6, 4}, {0.6, 0.4, 0.4}));
  const Triangle3<double> t{{0, 0, 0}, {2, 0.2, 0.1}, {0.6, 1.6, 0.2}};
  for (int k = 1; k < 5; ++k) {
    const double u = k / 5.0;
    w.segment(point_at(t, Vec2d{u, 0}), point_at(t, Vec2d{u, 1 - u}), pen(c::light, 1));
    w.segment(point_at(t, Vec2d{0, u}), point_at(t, Vec2d{1 - u, u}), pen(c::light, 1));
  }
  draw(w, t, pen(c::blue));
  w.arrow(t.v0, t.v1, pen(c::red));
  w.arrow(t.v0, t.v2, pen(c::green));
  label(w, lerp(t.v0, t.v1, 0.6), "e\u2080", c::red, 0, -16);
  label(w, lerp(t.v0, t.v2, 0.6), "e\u2081", c::green, -18, 0);
  point(w, t.v0, "P\u2080", c::blue);
  point(w, point_at(t, Vec2d{0.3, 0.4}), "T(0.3, 0.4)", c::black);
  return true;
}

// 10.42: distance between a line and a rectangle.
bool fig_10_42(SvgWriter& w) {
  w.set_camera(camera({5, -6, 4}, {0, 0, 0.4}));
  const Rectangle3<double> r{{0, 0, 0}, {Vec3d{1, 0, 0}, Vec3d{0, 1, 0}}, {1.2, 0.7}};
  const Line3<double> l{{1.6, 1.3, 0.9}, {0.6, -1, 0.4}};
  const auto d = distance(l, r);
  if (!std::isfinite(d.distance)) return false;
  draw(w, r, filled(c::blue, 0.15));
  w.segment(point_at(l, -1.6), point_at(l, 1.4), pen(c::green));
  link(w, d, "", "(s, t) = " + coordinates(d.param_b.x, d.param_b.y));
  label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist " + fmt(d.distance), c::gray);
  return true;
}

const Tetrahedron3<double> tet10{{{0, 0, 0}, {1.8, 0, 0}, {0.6, 1.6, 0}, {0.7, 0.6, 1.5}}};
const Line3<double> tet10_line{{2.2, 1.2, 1.1}, {0.35, -1, 0.45}};

// 10.44: distance between a line and a solid tetrahedron.
bool fig_10_44(SvgWriter& w) {
  const auto d = distance(tet10_line, tet10);
  if (!std::isfinite(d.distance)) return false;
  // Look along the perpendicular of the line and the connecting segment (tilted a little
  // upwards), so both appear in true length and at a right angle, as in the book.
  Vec3d side = normalize(cross(d.closest[1] - d.closest[0], tet10_line.direction));
  if (side.z < 0) side = -side;
  const Vec3d target = lerp(d.closest[0], centroid(tet10), 0.5);
  w.set_camera(camera(target + 7.0 * normalize(side + Vec3d{0, 0, 0.3}), target));
  draw(w, tet10, filled(c::blue, 0.1));
  for (int i = 0; i < 4; ++i) point(w, tet10.v[i], "V" + std::to_string(i), c::blue);
  w.segment(point_at(tet10_line, -1.6), point_at(tet10_line, 2.0), pen(c::green));
  label(w, point_at(tet10_line, 2.0), "line", c::green);
  link(w, d, "", "");
  label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist " + fmt(d.distance), c::gray);
  return true;
}

// 10.45: (a) the tetrahedron projected onto the plane through the line's origin perpendicular
// to its direction (plane_frame, to_plane): the line becomes one point O; (b) in the plane's 2D
// coordinates the projection is the convex hull of the projected vertices (convex_hull), and
// the distance from O to that polygon (distance_to_convex_polygon) equals the line-tetrahedron
// distance (locus::distance(Line3, Tetrahedron3), which uses exact face queries instead).
bool fig_10_45(SvgWriter& w) {
  const Line3<double>& l = tet10_line;
  const auto f = plane_frame(l.origin, l.direction);
  const auto d3 = distance(l, tet10);
  if (!f || !std::isfinite(d3.distance)) return false;
  std::vector<Vec2d> proj;
  for (const Vec3d& v : tet10.v) proj.push_back(to_plane(*f, v));
  const auto hull = convex_hull(proj);
  if (hull.status != Status::ok || hull.dimension != 2) return false;
  std::vector<Vec2d> poly2;
  for (const std::uint32_t i : hull.indices) poly2.push_back(proj[i]);
  const Vec2d o = to_plane(*f, l.origin);
  const auto d2 = distance_to_convex_polygon(o, std::span<const Vec2d>(poly2));
  if (!std::isfinite(d2.distance)) return false;

  // (a) in 3D, seen obliquely (about 50 degrees off the line direction); the plane square is
  // centred on the shadow.
  w.set_camera(camera({-3.1, -5.0, 3.0}, {0.9, 0.5, 0.6}));
  Vec2d mid{};
  for (const Vec2d& q : proj) mid += 0.25 * q;
  const PlaneFrame3<double> patch{to_world(*f, mid), f->u, f->v, f->normal};
  plane_patch(w, patch, 1.7, c::gray);
  draw(w, tet10, filled(c::blue, 0.1));
  w.segment(point_at(l, -1.6), point_at(l, 2.0), pen(c::green));
  std::vector<Vec3d> shadow;
  for (std::size_t i = 0; i < proj.size(); ++i)
    w.segment(tet10.v[i], to_world(*f, proj[i]), dashed(c::light, 1));
  for (const Vec2d& q : poly2) shadow.push_back(to_world(*f, q));
  closed(w, shadow, filled(c::orange, 0.25, 1.6));
  point(w, l.origin, "O", c::green);
  // Place panel (b) to the right of panel (a)'s image (the camera's image-plane coordinates are
  // the drawing's world coordinates).
  double right = -1e300, top = -1e300, bottom = 1e300;
  for (const Vec3d& p :
       {tet10.v[0], tet10.v[1], tet10.v[2], tet10.v[3], point_at(l, -1.6), point_at(l, 2.0),
        to_world(patch, Vec2d{1.7, 1.7}), to_world(patch, Vec2d{-1.7, 1.7}),
        to_world(patch, Vec2d{1.7, -1.7}), to_world(patch, Vec2d{-1.7, -1.7})}) {
    Vec2d q{};
    if (!w.project(p, q)) return false;
    right = std::max(right, q.x);
    top = std::max(top, q.y);
    bottom = std::min(bottom, q.y);
  }
  label(w, Vec2d{right - 2.0, bottom - 0.4}, "(a) projection onto the plane \u27c2 d", c::black);
  double lo_x = 1e300, lo_y = 1e300, hi_y = -1e300;
  for (const Vec2d& q : poly2) {
    lo_x = std::min(lo_x, std::min(q.x, o.x));
    lo_y = std::min(lo_y, std::min(q.y, o.y));
    hi_y = std::max(hi_y, std::max(q.y, o.y));
  }
  const Vec2d off{right + 1.0 - lo_x, 0.5 * (top + bottom) - 0.5 * (lo_y + hi_y)};
  // (b) in the plane's 2D coordinates.
  std::vector<Vec2d> panel;
  for (const Vec2d& q : poly2) panel.push_back(off + q);
  closed(w, panel, filled(c::orange, 0.25, 1.6));
  for (std::size_t i = 0; i < proj.size(); ++i)
    point(w, off + proj[i], "V" + std::to_string(i) + "'", c::blue);
  w.segment(off + o, off + d2.closest[1], dashed(c::gray, 1.2));
  point(w, off + o, "O (the line)", c::green);
  w.point(off + d2.closest[1], dot(c::blue));
  label(w, off + Vec2d{lo_x, lo_y - 0.5},
        "(b) 2D: " + fmt(d2.distance, 3) + " = 3D line-tetrahedron " + fmt(d3.distance, 3),
        c::black);
  return true;
}

// 10.46: distance between a line and an oriented box.
bool fig_10_46(SvgWriter& w) {
  w.set_camera(camera({6, -4, 5}));
  const Line3<double> l{{1.8, 1.8, 1.0}, {0.5, -1, 0.35}};
  const auto d = distance(l, box10);
  if (!std::isfinite(d.distance)) return false;
  draw(w, box10, filled(c::blue, 0.08));
  w.segment(point_at(l, -3.2), point_at(l, 2.4), pen(c::green));
  link(w, d, "", "");
  label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist " + fmt(d.distance), c::gray);
  return true;
}

}  // namespace

std::vector<Figure> chapter10_distance_figures() {
  return {
      {"10.1", "distance(Vec3, Line3)", fig_10_1},
      {"10.2", "distance(Vec3, Line3) (param_b: the projection)", fig_10_2},
      {"10.3", "distance(Vec3, Segment3)", fig_10_3},
      {"10.4", "distance(Vec3, Segment3), distance(Vec3, Polyline3) and its slab rejection",
       fig_10_4},
      {"10.6", "distance(Vec3, Plane3), plane_frame", fig_10_6},
      {"10.7", "distance(Vec3, Plane3), signed_distance", fig_10_7},
      {"10.8", "distance(Vec3, Triangle3)", fig_10_8},
      {"10.10", "distance(Vec3, Triangle3), distance(Vec3, Plane3), barycentric (level curves)",
       fig_10_10},
      {"10.12", "distance(Vec3, Rectangle3)", fig_10_12},
      {"10.14", "distance(Vec3, PlanarPolygon3), planar_polygon", fig_10_14},
      {"10.15", "distance(Vec3, PlanarPolygon3) (param_b: plane coordinates), to_plane", fig_10_15},
      {"10.16", "distance(Vec3, Circle3)", fig_10_16},
      {"10.17", "distance(Vec3, Circle3) (unique = false on the axis)", fig_10_17},
      {"10.18", "distance(Vec3, Disk3)", fig_10_18},
      {"10.19", "distance(Vec3, Disk3)", fig_10_19},
      {"10.20", "distance(Vec3, Tetrahedron3)", fig_10_20},
      {"10.21", "distance(Vec3, OrientedBox3)", fig_10_21},
      {"10.22", "distance(Vec3, OrientedBox3) (param_b: clamped box coordinates)", fig_10_22},
      {"10.23", "distance(Vec3, Frustum3), corners", fig_10_23},
      {"10.24", "distance(Vec3, Ellipsoid3), point_at(Ellipsoid3)", fig_10_24},
      {"10.25", "distance(Vec3, BezierCurve3), point_at(BezierCurve3)", fig_10_25},
      {"10.26", "distance(Vec3, BezierPatch3), point_at(BezierPatch3)", fig_10_26},
      {"10.27", "distance(Line3, Line3)", fig_10_27},
      {"10.28", "distance for the six linear-linear pairs (param_a, param_b)", fig_10_28},
      {"10.29", "distance(Line3, Line3), distance(Segment3, Segment3)", fig_10_29},
      {"10.31", "distance(Segment3, Segment3)", fig_10_31},
      {"10.32", "distance(Line3, Ray3)", fig_10_32},
      {"10.33", "distance(Line3, Segment3)", fig_10_33},
      {"10.34", "distance(Ray3, Segment3)", fig_10_34},
      {"10.35", "distance(Segment3, Segment3) for minimisers in the nine regions", fig_10_35},
      {"10.36", "distance(Line3, Line3), distance(Segment3, Segment3) (level curves)", fig_10_36},
      {"10.37", "distance(Line3, Triangle3)", fig_10_37},
      {"10.38", "point_at(Triangle3, st)", fig_10_38},
      {"10.42", "distance(Line3, Rectangle3)", fig_10_42},
      {"10.44", "distance(Line3, Tetrahedron3)", fig_10_44},
      {"10.45",
       "distance(Line3, Tetrahedron3), plane_frame, to_plane, convex_hull, "
       "distance_to_convex_polygon",
       fig_10_45},
      {"10.46", "distance(Line3, OrientedBox3)", fig_10_46},
  };
}

}  // namespace locus_gallery
