// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 11 (intersection in 3D). Every intersection point, parameter, hit, side and
// separating-axis answer shown is computed by a locus::intersection / intersects / side_of_plane
// query on the literal inputs; the 3D scenes are projected through the SvgWriter camera.
// Figures (all 77 of the chapter): linear component and plane (11.1), line and triangle with
// barycentrics (11.2), ray and polygon, disk, octahedron, triangle mesh (BVH) and the half-lines
// of a convex polyhedron (11.3-11.8), linear components and quadrics (11.9-11.17), a ray and a
// NURBS surface with the refinement hierarchy and a tessellation it misses (11.18-11.22), two
// and three planes (11.23, 11.24), plane-triangle, triangle-triangle (with the interval
// overlap), plane-mesh, polygon-plane and polygon-triangle (11.25-11.31), plane sections of
// sphere, cylinder and cone with edge-on views, Dandelin spheres and focal definitions
// (11.32-11.52), plane and parametric surface with the Hermite curves (11.53-11.58), two
// B-spline surfaces (11.59, 11.60), slabs and boxes (11.61-11.73), linear component and torus
// (11.74-11.77).
#include "gallery.hpp"

#include <locus/intersection/aligned_box_aligned_box.hpp>
#include <locus/intersection/aligned_box_plane.hpp>
#include <locus/intersection/aligned_box_sphere.hpp>
#include <locus/intersection/line_aligned_box.hpp>
#include <locus/intersection/line_capsule.hpp>
#include <locus/intersection/line_cone.hpp>
#include <locus/intersection/line_cylinder.hpp>
#include <locus/intersection/line_disk.hpp>
#include <locus/intersection/line_ellipsoid.hpp>
#include <locus/intersection/line_oriented_box.hpp>
#include <locus/intersection/line_plane.hpp>
#include <locus/intersection/line_quadric.hpp>
#include <locus/intersection/line_sphere.hpp>
#include <locus/intersection/line_torus.hpp>
#include <locus/intersection/line_triangle.hpp>
#include <locus/intersection/linear_polyhedron.hpp>
#include <locus/intersection/oriented_box_oriented_box.hpp>
#include <locus/intersection/oriented_box_plane.hpp>
#include <locus/intersection/plane_cone.hpp>
#include <locus/intersection/plane_cylinder.hpp>
#include <locus/intersection/plane_mesh.hpp>
#include <locus/intersection/plane_plane.hpp>
#include <locus/intersection/plane_polygon.hpp>
#include <locus/intersection/plane_sphere.hpp>
#include <locus/intersection/plane_surface.hpp>
#include <locus/intersection/plane_triangle.hpp>
#include <locus/intersection/ray_aligned_box.hpp>
#include <locus/intersection/ray_cone.hpp>
#include <locus/intersection/ray_cylinder.hpp>
#include <locus/intersection/ray_plane.hpp>
#include <locus/intersection/ray_polygon.hpp>
#include <locus/intersection/ray_sphere.hpp>
#include <locus/intersection/ray_surface.hpp>
#include <locus/intersection/ray_torus.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/intersection/segment_disk.hpp>
#include <locus/intersection/segment_plane.hpp>
#include <locus/intersection/surface_surface.hpp>
#include <locus/intersection/triangle_triangle.hpp>
#include <locus/io/svg_primitives.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/planar_polygon.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/sphere.hpp>
#include <locus/primitives/triangle.hpp>
#include <locus/spatial/bvh.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
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

// A square patch of the plane around `at` (half size h).
void plane_patch(SvgWriter& w, const Plane3<double>& pl, const Vec3d& at, double h,
                 const char* colour) {
  const auto f = plane_frame(pl);
  if (!f) return;
  const Vec3d o = project(pl, at);
  closed(w,
         std::vector<Vec3d>{o + (-h) * f->u + (-h) * f->v, o + h * f->u + (-h) * f->v,
                            o + h * f->u + h * f->v, o + (-h) * f->u + h * f->v},
         filled(colour, 0.10, 1));
}

void draw_box(SvgWriter& w, const AlignedBox3<double>& b, const SvgStyle& s) {
  std::array<Vec3d, 8> c8{};
  for (int k = 0; k < 8; ++k)
    c8[static_cast<std::size_t>(k)] = {(k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y,
                                       (k & 4) ? b.max.z : b.min.z};
  box_edges(w, c8, s);
}
void draw_box(SvgWriter& w, const OrientedBox3<double>& b, const SvgStyle& s) {
  box_edges(w, corners(b), s);
}

// ---- linear components against planes and triangles -----------------------------------------

// 11.1: a line crossing a plane at P = origin + t direction.
bool fig_11_1(SvgWriter& w) {
  w.set_camera(camera({7, -5, 3}, {0, 0, 0.5}));
  const Plane3<double> pl{{0.1, 0.2, 1.0}, 0.3};
  const Line3<double> l{{-1.2, 0.4, 2.2}, {0.8, -0.2, -1.0}};
  const auto r = intersection(l, pl);
  if (r.kind != Kind::point) return false;
  plane_patch(w, pl, r.point[0], 1.8, c::blue);
  w.segment(point_at(l, -0.6), point_at(l, 3.0), pen(c::red));
  w.arrow(l.origin, l.origin + l.direction, pen(c::red, 2));
  point(w, l.origin, "P", c::red);
  label(w, l.origin + l.direction, "d", c::red);
  point(w, r.point[0], "X = P + t d, t = " + fmt(r.param_a[0]), c::black);
  w.arrow(r.point[0], r.point[0] + 0.8 * normalize(pl.normal), pen(c::blue));
  label(w, r.point[0] + 0.8 * normalize(pl.normal), "n", c::blue);
  return true;
}

// 11.2: a ray through a triangle: the hit point, its barycentrics and the watertight hit's side.
bool fig_11_2(SvgWriter& w) {
  w.set_camera(camera({4, -7, 5}, {1, 1, 0}));
  const Triangle3<double> t{{-1, -1, 0}, {3, 0, 0.4}, {0, 3, 0.2}};
  const Ray3<double> ray{{0.2, 0.4, 3}, {0.3, 0.2, -1}};
  const auto r = intersection(ray, t);
  const TriangleHit<double> h = watertight_hit(ray, t);
  if (r.kind != Kind::point || !h.hit) return false;
  closed(w, std::vector<Vec3d>{t.v0, t.v1, t.v2}, filled(c::blue, 0.15));
  point(w, t.v0, "V0", c::blue);
  point(w, t.v1, "V1", c::blue);
  point(w, t.v2, "V2", c::blue);
  for (const Vec3d& v : {t.v0, t.v1, t.v2}) w.segment(r.point[0], v, dashed(c::gray, 1));
  w.arrow(ray.origin, r.point[0], pen(c::red, 2));
  w.segment(r.point[0], point_at(ray, r.param_a[0] + 0.8), dashed(c::red, 1.2));
  point(w, ray.origin, "P", c::red);
  point(w, r.point[0], "", c::black);
  label(w, r.point[0] + Vec3d{0.3, 0, 0},
        "b = (" + fmt(h.barycentric.x) + ", " + fmt(h.barycentric.y) + ", " + fmt(h.barycentric.z) +
            ")" + (h.front ? ", front" : ", back"),
        c::black);
  return true;
}

// 11.23: two planes meet in a line.
bool fig_11_23(SvgWriter& w) {
  w.set_camera(camera({6, -6, 4}, {0, 0, 0}));
  const Plane3<double> a{{0, 0, 1}, 0}, b{{1, 0, 1}, 0.4};
  const auto r = intersection(a, b);
  if (r.kind != Kind::line) return false;
  plane_patch(w, a, r.point[0], 1.6, c::blue);
  plane_patch(w, b, r.point[0], 1.6, c::green);
  const Vec3d d = r.point[1] - r.point[0];
  w.segment(r.point[0] - 2.0 * d, r.point[0] + 2.0 * d, pen(c::red, 2.5));
  label(w, r.point[0] + 2.0 * d, "line of intersection", c::red);
  return true;
}

// 11.24: the configurations of three planes (the book's table 11.1), each classified by
// intersection(a, b, c).
bool fig_11_24(SvgWriter& w) {
  const Plane3<double> x0{{1, 0, 0}, 0}, x1{{1, 0, 0}, 1.2}, y0{{0, 1, 0}, 0}, z0{{0, 0, 1}, 0},
      d{{1, 1, 0}, 0}, d1{{1, 1, 0}, 1.4}, x2{{1, 0, 0}, -1.2};
  const std::array<std::array<Plane3<double>, 3>, 6> cases = {
      {{x0, y0, z0}, {x0, y0, d}, {x0, y0, d1}, {x0, x1, y0}, {x2, x0, x1}, {x0, x0, y0}}};
  const char* names[] = {"(a) ", "(b) ", "(c) ", "(d) ", "(e) ", "(f) "};
  w.set_camera(camera({7, -9, 6}, {9, 0, 0}));
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& p = cases[i];
    const auto r = intersection(p[0], p[1], p[2]);
    const Vec3d shift{double(i % 3) * 6.0, double(i / 3) * 7.0, 0};
    const char* cols[] = {c::blue, c::green, c::orange};
    for (int k = 0; k < 3; ++k) {
      const Plane3<double> moved{p[static_cast<std::size_t>(k)].normal,
                                 p[static_cast<std::size_t>(k)].constant +
                                     dot(p[static_cast<std::size_t>(k)].normal, shift)};
      plane_patch(w, moved, shift, 1.5, cols[k]);
    }
    if (r.kind == Kind::point) point(w, r.point[0] + shift, "", c::red);
    if (r.kind == Kind::line) {
      const Vec3d a = r.point[0] + shift, b = r.point[1] + shift;
      w.segment(a - 1.5 * (b - a), a + 1.5 * (b - a), pen(c::red, 2.5));
    }
    label(w, shift + Vec3d{0, 0, -2.4}, std::string(names[i]) + std::string(to_string(r.kind)),
          c::black);
  }
  return true;
}

// ---- plane, triangle and mesh (section 11.5) ---------------------------------------------------

// 11.25: a plane cutting a triangle: the segment from the crossings of the two edges that leave
// the lone vertex's side.
bool fig_11_25(SvgWriter& w) {
  w.set_camera(camera({6, -7, 4}, {1, 1, 0}));
  const Plane3<double> pl{{0.1, 0.2, 1}, 0.3};
  const Triangle3<double> t{{0, 0, 1.6}, {2.5, 0.5, -0.6}, {0.4, 2.6, -0.8}};
  const auto r = intersection(t, pl);
  if (r.kind != Kind::segment) return false;
  plane_patch(w, pl, 0.5 * (r.point[0] + r.point[1]), 2.2, c::blue);
  closed(w, std::vector<Vec3d>{t.v0, t.v1, t.v2}, filled(c::green, 0.25));
  point(w, t.v0, "V0", c::green);
  point(w, t.v1, "V1", c::green);
  point(w, t.v2, "V2", c::green);
  w.segment(r.point[0], r.point[1], pen(c::red, 2.5));
  point(w, r.point[0], "", c::red);
  point(w, r.point[1], "", c::red);
  return true;
}

// 11.26: the configurations: no contact, a vertex, an edge, a vertex and a crossing, two
// crossings, the whole triangle in the plane; each labelled with the computed kind.
bool fig_11_26(SvgWriter& w) {
  w.set_camera(camera({8, -10, 7}, {7, 0, 0}));
  const Plane3<double> z0{{0, 0, 1}, 0};
  const std::array<Triangle3<double>, 6> ts = {{{{0, 0, 0.5}, {1.5, 0, 1}, {0, 1.5, 1.5}},
                                                {{0, 0, 0}, {1.5, 0, 1}, {0, 1.5, 1.2}},
                                                {{0, 0, 0}, {1.5, 0, 0}, {0, 1.5, 1.2}},
                                                {{0, 0, 0}, {1.5, 0, -1}, {0, 1.5, 1.2}},
                                                {{0, 0, -1}, {1.5, 0, 1}, {0, 1.5, 1}},
                                                {{0, 0, 0}, {1.5, 0, 0}, {0, 1.5, 0}}}};
  const Kind want[] = {Kind::empty,   Kind::point,   Kind::segment,
                       Kind::segment, Kind::segment, Kind::polygon};
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Vec3d sh{double(i % 3) * 4.5, double(i / 3) * 4.5, 0};
    const Triangle3<double> t{ts[i].v0 + sh, ts[i].v1 + sh, ts[i].v2 + sh};
    const auto r = intersection(t, z0);
    if (r.kind != want[i]) return false;
    plane_patch(w, z0, sh + Vec3d{0.6, 0.6, 0}, 1.6, c::blue);
    closed(w, std::vector<Vec3d>{t.v0, t.v1, t.v2}, filled(c::green, 0.3));
    if (r.kind == Kind::point) point(w, r.point[0], "", c::red);
    if (r.kind == Kind::segment) w.segment(r.point[0], r.point[1], pen(c::red, 2.5));
    if (r.kind == Kind::polygon) {
      closed(w, std::vector<Vec3d>{r.point[0], r.point[1], r.point[2]}, pen(c::red, 2.5));
    }
    label(w, sh + Vec3d{0, 0, -1.6}, std::string(to_string(r.kind)), c::black);
  }
  return true;
}

// 11.27: two triangles: (a) parallel planes, (b) coplanar (the common polygon), (c) crossing
// (the common segment), (d) the planes cross but the triangles do not meet.
bool fig_11_27(SvgWriter& w) {
  w.set_camera(camera({8, -12, 8}, {5, 2, 0}));
  const Triangle3<double> a{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}};
  const std::array<Triangle3<double>, 4> bs = {{{{0.5, 0.5, 1}, {3.5, 0.5, 1}, {0.5, 3.5, 1}},
                                                {{1, 1, 0}, {4, 1, 0}, {1, 4, 0}},
                                                {{0.5, 0.5, -1}, {0.5, 0.8, 1.2}, {2.5, -0.8, 0}},
                                                {{3, 3, -1}, {3, 3, 1}, {5, 1.5, 0}}}};
  const Kind want[] = {Kind::empty, Kind::polygon, Kind::segment, Kind::empty};
  const char* names[] = {"(a) ", "(b) ", "(c) ", "(d) "};
  for (std::size_t i = 0; i < bs.size(); ++i) {
    const Vec3d sh{double(i % 2) * 6.5, double(i / 2) * 6.5, 0};
    const Triangle3<double> ta{a.v0 + sh, a.v1 + sh, a.v2 + sh};
    const Triangle3<double> tb{bs[i].v0 + sh, bs[i].v1 + sh, bs[i].v2 + sh};
    const auto r = intersection(ta, tb);
    if (r.kind != want[i]) return false;
    closed(w, std::vector<Vec3d>{ta.v0, ta.v1, ta.v2}, filled(c::blue, 0.2));
    closed(w, std::vector<Vec3d>{tb.v0, tb.v1, tb.v2}, filled(c::green, 0.2));
    if (r.kind == Kind::segment) w.segment(r.point[0], r.point[1], pen(c::red, 2.5));
    if (r.kind == Kind::polygon) {
      closed(w, std::vector<Vec3d>(r.point.begin(), r.point.begin() + r.count),
             filled(c::red, 0.5));
    }
    label(w, sh + Vec3d{0, 0, -1.6}, std::string(names[i]) + std::string(to_string(r.kind)),
          c::black);
  }
  return true;
}

// 11.29: a triangle mesh (a torus) sliced by a plane: the closed loops of slice_mesh().
bool fig_11_29(SvgWriter& w) {
  w.set_camera(camera({5, -8, 6}, {0, 0, 0}));
  const PolygonMesh<double> m = torus_mesh<double>(2.0, 0.8, 32, 16);
  const Plane3<double> pl{{0.3, 0.1, 1}, 0.2};
  const MeshSlice<double> s = slice_mesh(m.vertices, fan_triangles(m), pl);
  if (s.status != Status::ok || s.polylines.size() != 2) return false;
  for (const auto& t : fan_triangles(m)) {
    closed(w, std::vector<Vec3d>{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]},
           pen(c::gray, 0.4));
  }
  plane_patch(w, pl, {0, 0, 0.2}, 3.2, c::blue);
  for (const auto& l : s.polylines) {
    if (!l.closed) return false;
    closed(w, l.vertices, pen(c::red, 2.5));
  }
  return true;
}

// ---- slabs and boxes --------------------------------------------------------------------------

// 11.61: a line through an axis-aligned box: entry and exit points.
bool fig_11_61(SvgWriter& w) {
  w.set_camera(camera({6, -7, 5}, {0.5, 0.5, 0.5}));
  const AlignedBox3<double> b{{0, 0, 0}, {2, 1.5, 1}};
  const Line3<double> l{{-1, 0.2, 0.2}, {1, 0.4, 0.25}};
  const auto r = intersection(l, b);
  if (r.kind != Kind::segment) return false;
  draw_box(w, b, pen(c::blue));
  w.segment(point_at(l, -0.5), point_at(l, 4.5), pen(c::gray));
  w.segment(r.point[0], r.point[1], pen(c::red, 3));
  point(w, r.point[0], "t0 = " + fmt(r.param_a[0]), c::red);
  point(w, r.point[1], "t1 = " + fmt(r.param_a[1]), c::red);
  return true;
}

// 11.62: the box as the intersection of three slabs (each drawn as its two bounding planes).
bool fig_11_62(SvgWriter& w) {
  w.set_camera(camera({6, -7, 5}, {0.5, 0.5, 0.5}));
  const AlignedBox3<double> b{{0, 0, 0}, {1, 1, 1}};
  const char* cols[] = {c::red, c::green, c::blue};
  for (int k = 0; k < 3; ++k) {
    Vec3d n{};
    n[k] = 1;
    for (const double v : {b.min[k], b.max[k]}) {
      // The slab's planes, verified to touch the box (side_of_plane zero).
      const Plane3<double> pl{n, v};
      if (side_of_plane(b, pl) != Sign::zero) return false;
      plane_patch(w, pl, Vec3d{0.5, 0.5, 0.5}, 0.95, cols[k]);
    }
  }
  draw_box(w, b, pen(c::black, 2));
  return true;
}

// 11.63 / 11.64: slab clipping of rays seen down the z axis: each slab clips the ray to an
// interval; the box is hit when the intervals overlap.
bool fig_11_64(SvgWriter& w) {
  w.set_camera(camera({0.5, 0.5, 10}, {0.5, 0.5, 0}));
  const AlignedBox3<double> b{{0, 0, 0}, {2, 1, 1}};
  w.segment(Vec3d{0, -1.5, 0.5}, Vec3d{0, 2.5, 0.5}, dashed(c::gray));
  w.segment(Vec3d{2, -1.5, 0.5}, Vec3d{2, 2.5, 0.5}, dashed(c::gray));
  w.segment(Vec3d{-1.5, 0, 0.5}, Vec3d{3.5, 0, 0.5}, dashed(c::gray));
  w.segment(Vec3d{-1.5, 1, 0.5}, Vec3d{3.5, 1, 0.5}, dashed(c::gray));
  draw_box(w, b, pen(c::blue, 2));
  const std::array<Ray3<double>, 2> rays = {Ray3<double>{{-1.2, -1.0, 0.5}, {1, 0.8, 0}},
                                            Ray3<double>{{-1.2, 0.4, 0.5}, {1, 1.6, 0}}};
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto r = intersection(rays[i], b);
    w.arrow(rays[i].origin, point_at(rays[i], 3.5), pen(i == 0 ? c::red : c::orange));
    point(w, rays[i].origin, i == 0 ? "hits" : "misses", i == 0 ? c::red : c::orange);
    if (r.kind == Kind::segment) {
      w.segment(r.point[0], r.point[1], pen(c::red, 4));
      point(w, r.point[0], "entry", c::red);
      point(w, r.point[1], "exit", c::red);
    }
    if ((i == 0) != (r.kind != Kind::empty)) return false;
  }
  return true;
}

// 11.65: an oriented box: centre, axes and extents.
bool fig_11_65(SvgWriter& w) {
  w.set_camera(camera({6, -7, 5}, {0, 0, 0}));
  const double s = std::sqrt(0.5);
  const OrientedBox3<double> b{{0, 0, 0}, {{s, s, 0}, {-s, s, 0}, {0, 0, 1}}, {1.5, 0.8, 0.6}};
  draw_box(w, b, pen(c::blue));
  const char* names[] = {"a0 e0", "a1 e1", "a2 e2"};
  for (int k = 0; k < 3; ++k) {
    const Vec3d tip = b.center + b.extent[k] * b.axis[k];
    w.arrow(b.center, tip, pen(c::red));
    label(w, tip, names[k], c::red);
  }
  point(w, b.center, "C", c::black);
  return true;
}

// 11.66: clipping a line against an oriented box (oriented slabs).
bool fig_11_66(SvgWriter& w) {
  w.set_camera(camera({6, -7, 5}, {0, 0, 0}));
  const double s = std::sqrt(0.5);
  const OrientedBox3<double> b{{0, 0, 0}, {{s, s, 0}, {-s, s, 0}, {0, 0, 1}}, {1.5, 0.8, 0.6}};
  const Line3<double> l{{-2, -1.2, -0.3}, {1, 0.7, 0.2}};
  const auto r = intersection(l, b);
  if (r.kind != Kind::segment) return false;
  draw_box(w, b, pen(c::blue));
  w.segment(point_at(l, -0.5), point_at(l, 4.5), pen(c::gray));
  w.segment(r.point[0], r.point[1], pen(c::red, 3));
  point(w, r.point[0], "t0 = " + fmt(r.param_a[0]), c::red);
  point(w, r.point[1], "t1 = " + fmt(r.param_a[1]), c::red);
  return true;
}

// 11.67 / 11.68: a plane against an aligned box: only the two corners at the ends of the
// diagonal most aligned with the normal matter; their exact sides classify the box.
bool fig_11_67(SvgWriter& w) {
  w.set_camera(camera({6, -7, 4}, {0.5, 0.5, 0.5}));
  const AlignedBox3<double> b{{0, 0, 0}, {1.5, 1, 1}};
  const Plane3<double> pl{{0.4, 0.3, 1.0}, 0.9};
  const Sign s = side_of_plane(b, pl);
  if (s != Sign::zero) return false;
  draw_box(w, b, pen(c::blue));
  plane_patch(w, pl, Vec3d{0.75, 0.5, 0.5}, 1.4, c::green);
  const Vec3d lo = b.min, hi = b.max;  // the normal has positive components
  w.segment(lo, hi, dashed(c::red, 1.5));
  point(w, lo, "Vmin: " + fmt(signed_value(pl, lo)), c::red);
  point(w, hi, "Vmax: " + fmt(signed_value(pl, hi)), c::red);
  label(w, Vec3d{0, 1, 1.4}, "side_of_plane = 0 (meets)", c::black);
  return true;
}

// 11.68: the same box against parallel planes on either side and through a corner.
bool fig_11_68(SvgWriter& w) {
  w.set_camera(camera({6, -7, 4}, {0.5, 0.5, 0.5}));
  const AlignedBox3<double> b{{0, 0, 0}, {1, 1, 1}};
  draw_box(w, b, pen(c::blue));
  const Vec3d n{1, 1, 1};
  const std::array<double, 3> cs = {-0.6, 3.0, 3.6};
  const char* cols[] = {c::green, c::orange, c::purple};
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const Plane3<double> pl{n, cs[i]};
    plane_patch(w, pl, Vec3d{0.5, 0.5, 0.5}, 1.0, cols[i]);
    const Sign s = side_of_plane(b, pl);
    label(w, project(pl, Vec3d{0.5, 0.5, 0.5}) + Vec3d{0.4, -0.4, 0},
          s == Sign::zero ? "touches" : (s == Sign::positive ? "box on + side" : "box on - side"),
          cols[i]);
  }
  w.segment(b.min, b.max, dashed(c::red));
  return side_of_plane(b, Plane3<double>{n, 3.0}) == Sign::zero;
}

// 11.69 / 11.70: a plane against an oriented box; the extreme corners along the normal.
bool fig_11_69(SvgWriter& w) {
  w.set_camera(camera({6, -7, 4}, {0, 0, 0}));
  const double s = std::sqrt(0.5);
  const OrientedBox3<double> b{{0, 0, 0}, {{s, s, 0}, {-s, s, 0}, {0, 0, 1}}, {1.2, 0.6, 0.5}};
  const Plane3<double> pl{{0.2, -0.3, 1.0}, 0.3};
  if (side_of_plane(b, pl) != Sign::zero) return false;
  draw_box(w, b, pen(c::blue));
  plane_patch(w, pl, Vec3d{0, 0, 0}, 1.6, c::green);
  label(w, Vec3d{0, 0, 1.8}, "side_of_plane = 0 (meets)", c::black);
  return true;
}

// 11.71: two aligned boxes and their common box.
bool fig_11_71(SvgWriter& w) {
  w.set_camera(camera({6, -7, 5}, {1, 1, 0.5}));
  const AlignedBox3<double> a{{0, 0, 0}, {1.5, 1.2, 1}}, b{{0.8, 0.6, 0.4}, {2.2, 1.8, 1.5}};
  const auto r = intersection(a, b);
  if (!r) return false;
  draw_box(w, a, pen(c::blue));
  draw_box(w, b, pen(c::green));
  draw_box(w, *r, pen(c::red, 2.5));
  label(w, r->max, "common box", c::red);
  return true;
}

// 11.72: the separating-axis schematic: two oriented boxes, their projections on a face axis
// of the first, and whether intersects() finds them separated.
bool fig_11_72(SvgWriter& w) {
  w.set_camera(camera({0, 0, 10}, {1.5, 0, 0}));
  const double s = std::sqrt(0.5);
  const OrientedBox3<double> a{{0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, 0.6, 0.5}};
  const OrientedBox3<double> b{{2.9, 0.6, 0}, {{s, s, 0}, {-s, s, 0}, {0, 0, 1}}, {1, 0.5, 0.5}};
  const bool meet = intersects(a, b);
  draw_box(w, a, pen(c::blue));
  draw_box(w, b, pen(c::green));
  // Projections onto the x axis (a's first face normal): radii r_a, r_b and the centre distance.
  const double ra = a.extent.x;
  double rb = 0;
  for (int k = 0; k < 3; ++k) rb += b.extent[k] * std::abs(b.axis[k].x);
  const double y = -1.6;
  w.segment(Vec3d{-ra, y, 0}, Vec3d{ra, y, 0}, pen(c::blue, 4));
  w.segment(Vec3d{b.center.x - rb, y - 0.2, 0}, Vec3d{b.center.x + rb, y - 0.2, 0},
            pen(c::green, 4));
  label(w, Vec3d{-1, y - 0.7, 0},
        "|D.L| = " + fmt(b.center.x) + " vs rA + rB = " + fmt(ra + rb) +
            (meet ? ": overlap on every axis" : ": separated"),
        c::black);
  return !meet;
}

// 11.73: an aligned box and spheres: Arvo's squared distance against r^2 (exact).
bool fig_11_73(SvgWriter& w) {
  w.set_camera(camera({0.5, 0.5, 10}, {1, 0.5, 0}));
  const AlignedBox3<double> b{{0, 0, 0}, {2, 1, 1}};
  draw_box(w, b, pen(c::blue, 2));
  const std::array<Sphere3<double>, 3> ss = {Sphere3<double>{{3, 2, 0.5}, 1.6},
                                             Sphere3<double>{{-1, 0.5, 0.5}, 1.0},
                                             Sphere3<double>{{3.5, -1, 0.5}, 1.0}};
  for (const auto& sp : ss) {
    const bool m = intersects(b, sp);
    std::vector<Vec3d> ring;
    for (int k = 0; k <= 64; ++k) {
      const double a = 2 * std::numbers::pi * k / 64;
      ring.push_back(sp.center + sp.radius * Vec3d{std::cos(a), std::sin(a), 0});
    }
    w.polyline(ring, pen(m ? c::red : c::gray));
    const Vec3d q = cwise_min(cwise_max(sp.center, b.min), b.max);
    w.segment(sp.center, q, dashed(c::gray));
    point(w, sp.center, m ? "meets" : "misses", m ? c::red : c::gray);
  }
  // A sphere tangent to the face x = 2 meets the closed box (decided exactly).
  return intersects(b, Sphere3<double>{{3, 0.5, 0.5}, 1.0}) && intersects(b, ss[0]) &&
         !intersects(b, ss[2]);
}

// ---- linear components and quadric surfaces (11.9-11.17), plane sections (11.32-11.52) -------

std::vector<Vec3d> ring(const Vec3d& c, const Vec3d& u, const Vec3d& v, double r, int n = 64) {
  std::vector<Vec3d> pts;
  for (int k = 0; k <= n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    pts.push_back(c + (r * std::cos(a)) * u + (r * std::sin(a)) * v);
  }
  return pts;
}

void draw_sphere(SvgWriter& w, const Sphere3<double>& s, const char* col) {
  const Vec3d ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  w.polyline(ring(s.center, ex, ey, s.radius), pen(col, 1.4));
  w.polyline(ring(s.center, ex, ez, s.radius), dashed(col, 1));
  w.polyline(ring(s.center, ey, ez, s.radius), dashed(col, 1));
}

void draw_cylinder(SvgWriter& w, const Cylinder3<double>& c, double half, const char* col) {
  const auto b = perpendicular_basis(c.axis.direction);
  const Vec3d lo = c.axis.origin - half * c.axis.direction,
              hi = c.axis.origin + half * c.axis.direction;
  w.polyline(ring(lo, b.u, b.v, c.radius), pen(col, 1.4));
  w.polyline(ring(hi, b.u, b.v, c.radius), pen(col, 1.4));
  for (int k = 0; k < 4; ++k) {
    const double a = std::numbers::pi * k / 2;
    const Vec3d off = c.radius * (std::cos(a) * b.u + std::sin(a) * b.v);
    w.segment(lo + off, hi + off, dashed(col, 1));
  }
}

void draw_cone(SvgWriter& w, const Cone3<double>& c, double hlo, double hhi, const char* col) {
  const auto b = perpendicular_basis(c.axis);
  const double t = std::tan(c.angle);
  for (double h : {hlo, hhi})
    if (h != 0.0)
      w.polyline(ring(c.vertex + h * c.axis, b.u, b.v, std::fabs(h) * t), pen(col, 1.4));
  for (int k = 0; k < 4; ++k) {
    const double a = std::numbers::pi * k / 2;
    const Vec3d dir = std::cos(a) * b.u + std::sin(a) * b.v;
    w.segment(c.vertex + hlo * c.axis + (std::fabs(hlo) * t) * dir,
              c.vertex + hhi * c.axis + (std::fabs(hhi) * t) * dir, dashed(col, 1));
  }
}

/// The hits of a linear component: points, normals, labels t.
void draw_hits(SvgWriter& w, const LinearSurfaceIntersection3<double>& r, const char* col) {
  for (int i = 0; i < r.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    point(w, r.point[k], "t=" + fmt(r.param_a[k]) + (r.multiplicity[k] == 2 ? " (x2)" : ""), col);
    if (r.normal[k] != Vec3d{})
      w.arrow(r.point[k], r.point[k] + 0.6 * r.normal[k], pen(c::green, 1.2));
  }
}

void draw_conic(SvgWriter& w, const PlaneConic3<double>& c, const char* col) {
  const int branches = c.type == ConicType::hyperbola || c.type == ConicType::parallel_lines ||
                               c.type == ConicType::crossing_lines
                           ? 2
                           : 1;
  for (int b = 0; b < branches; ++b) {
    std::vector<Vec3d> pts;
    const bool closed_curve = c.type == ConicType::circle || c.type == ConicType::ellipse;
    for (int k = 0; k <= 80; ++k) {
      const double s = closed_curve ? 2 * std::numbers::pi * k / 80 : -2.0 + 4.0 * k / 80;
      pts.push_back(point_at(c, s, b));
    }
    if (c.type == ConicType::point) {
      point(w, c.center, "point", col);
      return;
    }
    w.polyline(pts, pen(col, 2.4));
  }
  if (c.type == ConicType::ellipse || c.type == ConicType::hyperbola) {
    point(w, c.focus[0], "F", col);
    point(w, c.focus[1], "F'", col);
  }
  if (c.type == ConicType::parabola) point(w, c.focus[0], "F", col);
}

// 11.9: the possible ray-sphere intersections: two hits, tangent, miss, from inside.
bool fig_11_9(SvgWriter& w) {
  w.set_camera(camera({0.5, -10, 3}, {0, 0, 0}));
  const Sphere3<double> s{{0, 0, 0}, 1.5};
  draw_sphere(w, s, c::blue);
  const std::array<Ray3<double>, 4> rays = {
      Ray3<double>{{-4, 0, 0.5}, {1, 0, 0}}, Ray3<double>{{-4, 0, 1.5}, {1, 0, 0}},
      Ray3<double>{{-4, 0, 2.2}, {1, 0, 0}}, Ray3<double>{{0, 0, -0.5}, {1, 0, 0.2}}};
  const int want[4] = {2, 1, 0, 1};
  bool ok = true;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto r = intersection(rays[i], s);
    w.arrow(rays[i].origin, point_at(rays[i], 7.0), pen(r.count ? c::red : c::gray, 1.4));
    draw_hits(w, r, c::red);
    ok = ok && r.count == want[i];
  }
  return ok && intersection(rays[1], s).multiplicity[0] == 2;
}

// 11.10: a line and an ellipsoid.
bool fig_11_10(SvgWriter& w) {
  w.set_camera(camera({3, -9, 4}, {0, 0, 0}));
  const double q = std::sqrt(0.5);
  const Ellipsoid3<double> e{{0, 0, 0}, {{q, q, 0}, {-q, q, 0}, {0, 0, 1}}, {2.5, 1.2, 1}};
  for (int k = 0; k < 3; ++k) {
    const Vec3d& u = e.axis[k];
    const Vec3d& v = e.axis[(k + 1) % 3];
    std::vector<Vec3d> pts;
    for (int j = 0; j <= 64; ++j) {
      const double a = 2 * std::numbers::pi * j / 64;
      pts.push_back(e.center + (e.extent[k] * std::cos(a)) * u +
                    (e.extent[(k + 1) % 3] * std::sin(a)) * v);
    }
    w.polyline(pts, k == 0 ? pen(c::blue, 1.4) : dashed(c::blue, 1));
  }
  const Line3<double> l{{-3, -1, -1}, {1, 0.3, 0.35}};
  const auto r = intersection(l, e);
  w.segment(point_at(l, -0.5), point_at(l, 6.5), pen(c::red, 1.4));
  draw_hits(w, r, c::red);
  return r.count == 2;
}

// 11.11 / 11.12: a finite cylinder in its standard and general position; a ray enters through
// the side and leaves through a cap.
bool cylinder_figure(SvgWriter& w, const Vec3d& axis) {
  w.set_camera(camera({6, -7, 4}, {0, 0, 0}));
  const Cylinder3<double> cyl{{{0, 0, 0}, normalize(axis)}, 1, 3};
  draw_cylinder(w, cyl, 1.5, c::blue);
  const Ray3<double> ray{{-3, -0.2, -0.4}, {1, 0.05, 0.45}};
  const auto r = intersection(ray, cyl);
  w.arrow(ray.origin, point_at(ray, 6.0), pen(c::red, 1.4));
  draw_hits(w, r, c::red);
  return r.count == 2;
}
bool fig_11_11(SvgWriter& w) { return cylinder_figure(w, {0, 0, 1}); }
bool fig_11_12(SvgWriter& w) { return cylinder_figure(w, {0.3, 0.2, 1}); }

// 11.13 / 11.14: a finite cone, standard and general; a line through side and base.
bool cone_figure(SvgWriter& w, const Vec3d& vertex, const Vec3d& axis) {
  w.set_camera(camera({6, -8, 3}, vertex + Vec3d{0, 0, 1}));
  const Cone3<double> cone{vertex, normalize(axis), 0.5, 0, 3};
  draw_cone(w, cone, 0, 3, c::blue);
  const Line3<double> l{vertex + Vec3d{-2, 0, 0.8}, {1, 0.1, 0.6}};
  const auto r = intersection(l, cone);
  w.segment(point_at(l, -0.5), point_at(l, 4.5), pen(c::red, 1.4));
  draw_hits(w, r, c::red);
  return r.count == 2;
}
bool fig_11_13(SvgWriter& w) { return cone_figure(w, {0, 0, 0}, {0, 0, 1}); }
bool fig_11_14(SvgWriter& w) { return cone_figure(w, {0.5, 0.2, -0.3}, {0.2, -0.3, 1}); }

// 11.15: an acute (infinite) cone: a line steeper than the cone enters it once, in one nappe.
bool fig_11_15(SvgWriter& w) {
  w.set_camera(camera({5, -9, 2}, {0, 0, 1.5}));
  const Cone3<double> cone{{0, 0, 0}, {0, 0, 1}, 0.45, 0, std::numeric_limits<double>::infinity()};
  draw_cone(w, cone, 0, 3.5, c::blue);
  const Line3<double> l{{0.6, 0, 0}, {0.3, 0, 1}};
  const auto r = intersection(l, cone);
  w.segment(point_at(l, -2.5), point_at(l, 3.5), pen(c::red, 1.4));
  draw_hits(w, r, c::red);
  return r.count == 1;  // it enters the unbounded solid and never leaves
}

// 11.16: an acute double cone: the same line crosses both nappes (four hits with the caps).
bool fig_11_16(SvgWriter& w) {
  w.set_camera(camera({5, -9, 1}, {0, 0, 0}));
  const Cone3<double> cone{{0, 0, 0}, {0, 0, 1}, 0.6, -2.5, 2.5};
  draw_cone(w, cone, -2.5, 2.5, c::blue);
  const Line3<double> l{{0.4, 0, 0}, {0.15, 0, 1}};
  const auto r = intersection(l, cone);
  w.segment(point_at(l, -3.5), point_at(l, 3.5), pen(c::red, 1.4));
  draw_hits(w, r, c::red);
  return r.count == 4;
}

// 11.17: c2 = 0: a line along an asymptotic direction of a hyperbolic paraboloid z = x y meets
// it once (a), or lies on it (b) (a ruling), decided exactly.
bool fig_11_17(SvgWriter& w) {
  w.set_camera(camera({6, -7, 5}, {0, 0, 0}));
  Quadric3<double> hp{};
  hp.a.a[0][1] = hp.a.a[1][0] = 0.5;
  hp.b = {0, 0, -1};
  for (int i = -4; i <= 4; ++i) {
    std::vector<Vec3d> a, b;
    for (int j = -4; j <= 4; ++j) {
      const double x = 0.5 * i, y = 0.5 * j;
      a.push_back({x, y, x * y});
      b.push_back({y, x, x * y});
    }
    w.polyline(a, pen(c::light, 1));
    w.polyline(b, pen(c::light, 1));
  }
  const Line3<double> la{{1.5, -2, 0.5}, {0, 1, 0}}, lb{{1, -2, -2}, {0, 1, 1}};
  const auto ra = intersection(la, hp), rb = intersection(lb, hp);
  w.segment(point_at(la, 0.0), point_at(la, 4.0), pen(c::red, 1.6));
  w.segment(point_at(lb, 0.0), point_at(lb, 4.0), pen(c::purple, 2.4));
  draw_hits(w, ra, c::red);
  label(w, point_at(lb, 4.0), "(b) on the surface", c::purple);
  label(w, point_at(la, 4.0), "(a) one point", c::red);
  return ra.count == 1 && rb.kind == Kind::line;
}

// 11.32 / 11.33: a plane and a sphere: a circle (and its cross-section).
bool fig_11_32(SvgWriter& w) {
  w.set_camera(camera({5, -8, 4}, {0, 0, 0}));
  const Sphere3<double> s{{0, 0, 0}, 2};
  const Plane3<double> pl{{0.2, 0.1, 1}, 1.0};
  draw_sphere(w, s, c::blue);
  const auto c0 = intersection(pl, s);
  plane_patch(w, pl, c0.center, 2.6, c::green);
  draw_conic(w, c0, c::red);
  point(w, c0.center, "center", c::red);
  return c0.type == ConicType::circle;
}
bool fig_11_33(SvgWriter& w) {
  w.set_camera(camera({0, -10, 0}, {0, 0, 0}));
  const Sphere3<double> s{{0, 0, 0}, 2};
  w.polyline(ring(s.center, {1, 0, 0}, {0, 0, 1}, 2), pen(c::blue, 1.4));
  bool ok = true;
  const double ks[3] = {1.0, 2.0, 2.6};
  const ConicType want[3] = {ConicType::circle, ConicType::point, ConicType::empty};
  for (int i = 0; i < 3; ++i) {
    const Plane3<double> pl{{0, 0, 1}, ks[i]};
    const auto c0 = intersection(pl, s);
    w.segment(Vec3d{-3, 0, ks[i]}, Vec3d{3, 0, ks[i]}, dashed(c::green, 1.2));
    label(w, Vec3d{3, 0, ks[i]}, std::string(to_string(c0.type)), c::green);
    if (c0.type == ConicType::circle)
      w.segment(c0.center - c0.extent[0] * Vec3d{1, 0, 0},
                c0.center + c0.extent[0] * Vec3d{1, 0, 0}, pen(c::red, 2.4));
    if (c0.type == ConicType::point) point(w, c0.center, "", c::red);
    ok = ok && c0.type == want[i];
  }
  return ok;
}

// 11.34 / 11.35: a plane and a cylinder: ellipse, circle, two lines, one line, nothing.
bool fig_11_34(SvgWriter& w) {
  w.set_camera(camera({6, -8, 3}, {0, 0, 0}));
  const Cylinder3<double> cyl{{{0, 0, 0}, {0, 0, 1}}, 1, std::numeric_limits<double>::infinity()};
  draw_cylinder(w, cyl, 2.5, c::blue);
  const Plane3<double> pl{{0.6, 0.2, 1}, 0.3};
  const auto c0 = intersection(pl, cyl);
  plane_patch(w, pl, c0.center, 2.2, c::green);
  draw_conic(w, c0, c::red);
  return c0.type == ConicType::ellipse;
}
bool fig_11_35(SvgWriter& w) {
  w.set_camera(camera({3, -9, 6}, {0, 0, 0}));
  const Cylinder3<double> cyl{{{0, 0, 0}, {0, 0, 1}}, 1, std::numeric_limits<double>::infinity()};
  draw_cylinder(w, cyl, 2, c::blue);
  const std::array<Plane3<double>, 4> pls = {
      Plane3<double>{{0, 0, 1}, 1.5}, Plane3<double>{{1, 0, 0}, 0.4}, Plane3<double>{{0, 1, 0}, -1},
      Plane3<double>{{1, 0, 0}, -1.6}};
  const ConicType want[4] = {ConicType::circle, ConicType::parallel_lines, ConicType::line,
                             ConicType::empty};
  const char* cols[4] = {c::red, c::purple, c::orange, c::gray};
  bool ok = true;
  for (std::size_t i = 0; i < pls.size(); ++i) {
    const auto c0 = intersection(pls[i], cyl);
    draw_conic(w, c0, cols[i]);
    if (c0.type != ConicType::empty)
      label(w, point_at(c0, 2.0), std::string(to_string(c0.type)), cols[i]);
    ok = ok && c0.type == want[i];
  }
  return ok;
}

// 11.37 / 11.41: the ellipse (tilted plane) and the circle (plane normal along the axis) as 3D
// conics: center, axes, extents, foci.
bool fig_11_37(SvgWriter& w) {
  w.set_camera(camera({4, -7, 5}, {0, 0, 0}));
  const Cylinder3<double> cyl{{{0, 0, 0}, {0, 0, 1}}, 1.2, std::numeric_limits<double>::infinity()};
  const auto c0 = intersection(Plane3<double>{{0.8, 0, 1}, 0}, cyl);
  draw_conic(w, c0, c::red);
  w.arrow(c0.center, c0.center + c0.extent[0] * c0.axis[0], pen(c::blue));
  w.arrow(c0.center, c0.center + c0.extent[1] * c0.axis[1], pen(c::blue));
  label(w, c0.center + c0.extent[0] * c0.axis[0], "a = " + fmt(c0.extent[0]), c::blue);
  label(w, c0.center + c0.extent[1] * c0.axis[1], "b = " + fmt(c0.extent[1]), c::blue);
  return c0.type == ConicType::ellipse;
}
bool fig_11_41(SvgWriter& w) {
  w.set_camera(camera({5, -8, 4}, {0, 0, 0}));
  const Cylinder3<double> cyl{
      {{0, 0, 0}, normalize(Vec3d{0.3, 0.2, 1})}, 1, std::numeric_limits<double>::infinity()};
  draw_cylinder(w, cyl, 2, c::blue);
  // The normal is the axis itself: N x D = 0 exactly, a circle.
  const auto c0 = intersection(Plane3<double>{cyl.axis.direction, 0.5}, cyl);
  draw_conic(w, c0, c::red);
  return c0.type == ConicType::circle;
}

// 11.42 / 11.43: a plane and a cone; the ways they can meet (ellipse, parabola, hyperbola).
bool fig_11_42(SvgWriter& w) {
  w.set_camera(camera({6, -8, 2}, {0, 0, 0}));
  const double inf = std::numeric_limits<double>::infinity();
  const Cone3<double> cone{{0, 0, 0}, {0, 0, 1}, 0.5, -inf, inf};
  draw_cone(w, cone, -2.5, 2.5, c::blue);
  const Plane3<double> pl{{0.3, 0, 1}, 1.2};
  const auto c0 = intersection(pl, cone);
  plane_patch(w, pl, c0.center, 2, c::green);
  draw_conic(w, c0, c::red);
  return c0.type == ConicType::ellipse;
}
bool fig_11_43(SvgWriter& w) {
  w.set_camera(camera({7, -9, 2}, {0, 0, 0}));
  const double inf = std::numeric_limits<double>::infinity();
  const Cone3<double> cone{{0, 0, 0}, {0, 0, 1}, 0.5, -inf, inf};
  draw_cone(w, cone, -3, 3, c::blue);
  const std::array<Plane3<double>, 3> pls = {Plane3<double>{{0.2, 0, 1}, 1.5},
                                             Plane3<double>{{1, 0, 0.1}, 0.8},
                                             Plane3<double>{{0, 1, 0}, 0.5}};
  const ConicType want[3] = {ConicType::ellipse, ConicType::hyperbola, ConicType::hyperbola};
  const char* cols[3] = {c::red, c::purple, c::orange};
  bool ok = true;
  for (std::size_t i = 0; i < pls.size(); ++i) {
    const auto c0 = intersection(pls[i], cone);
    draw_conic(w, c0, cols[i]);
    ok = ok && c0.type == want[i];
  }
  return ok;
}

// 11.48-11.52: parabola, circle, ellipse, hyperbola and the degenerate sections through the
// vertex (point, one line, two lines), each decided exactly on the data as given.
bool cone_section(SvgWriter& w, const Plane3<double>& pl, ConicType want) {
  w.set_camera(camera({6, -8, 2}, {0, 0, 0}));
  const double inf = std::numeric_limits<double>::infinity();
  const Cone3<double> cone{{0, 0, 0}, {0, 0, 1}, 0.5, -inf, inf};
  draw_cone(w, cone, -2.5, 2.5, c::blue);
  const auto c0 = intersection(pl, cone);
  plane_patch(w, pl, c0.center, 2, c::green);
  draw_conic(w, c0, c::red);
  label(w, c0.center + Vec3d{0, 0, -0.4}, std::string(to_string(c0.type)), c::red);
  return c0.type == want;
}
bool fig_11_48(SvgWriter& w) {
  // Normal at the cone's angle from the axis: (cos a, 0, sin a) against sin a, exactly tied
  // only if the rounded values satisfy (N.D)^2 = sin^2 |N|^2; the type shows what the data say.
  const double a = 0.5;
  const Plane3<double> pl{{std::cos(a), 0, std::sin(a)}, 0.8};
  w.set_camera(camera({6, -8, 2}, {0, 0, 0}));
  const auto c0 = intersection(pl, Cone3<double>{{0, 0, 0}, {0, 0, 1}, a, -1e9, 1e9});
  const bool near_parabolic = c0.type == ConicType::parabola || c0.type == ConicType::ellipse ||
                              c0.type == ConicType::hyperbola;
  return cone_section(w, pl, c0.type) && near_parabolic;
}
bool fig_11_49(SvgWriter& w) { return cone_section(w, {{0, 0, 1}, 1.5}, ConicType::circle); }
bool fig_11_50(SvgWriter& w) { return cone_section(w, {{0.4, 0, 1}, 1.5}, ConicType::ellipse); }
bool fig_11_51(SvgWriter& w) { return cone_section(w, {{1, 0, 0.2}, 0.6}, ConicType::hyperbola); }
bool fig_11_52(SvgWriter& w) {
  return cone_section(w, {{1, 0, 0.2}, 0}, ConicType::crossing_lines);
}

// ---- torus (11.74-11.77) -----------------------------------------------------------------------

void draw_torus(SvgWriter& w, const Torus3<double>& t, const char* col) {
  const auto b = perpendicular_basis(t.normal);
  for (double r : {t.major_radius - t.minor_radius, t.major_radius + t.minor_radius})
    w.polyline(ring(t.center, b.u, b.v, r), pen(col, 1.4));
  w.polyline(ring(t.center + t.minor_radius * t.normal, b.u, b.v, t.major_radius), dashed(col, 1));
  for (int k = 0; k < 8; ++k) {
    const double a = std::numbers::pi * k / 4;
    const Vec3d dir = std::cos(a) * b.u + std::sin(a) * b.v;
    w.polyline(ring(t.center + t.major_radius * dir, dir, t.normal, t.minor_radius, 32),
               dashed(col, 0.8));
  }
}

// 11.74 / 11.75: a line through a torus: four hits, their normals.
bool fig_11_74(SvgWriter& w) {
  w.set_camera(camera({3, -9, 5}, {0, 0, 0}));
  const Torus3<double> t{{0, 0, 0}, {0, 0, 1}, 2, 0.7};
  draw_torus(w, t, c::blue);
  const Line3<double> l{{-4, -0.5, 0.2}, {1, 0.12, 0}};
  const auto r = intersection(l, t);
  w.segment(point_at(l, -0.5), point_at(l, 8.5), pen(c::red, 1.4));
  draw_hits(w, r, c::red);
  return r.count == 4;
}
bool fig_11_75(SvgWriter& w) {
  w.set_camera(camera({3, -9, 6}, {0, 0, 0}));
  const Torus3<double> t{{0, 0, 0}, {0, 0, 1}, 2, 0.7};
  draw_torus(w, t, c::blue);
  const Ray3<double> ray{{-1, -4, 2}, {0.3, 1, -0.75}};
  const auto r = intersection(ray, t);
  w.arrow(ray.origin, point_at(ray, 5.0), pen(c::red, 1.4));
  draw_hits(w, r, c::red);
  return r.count >= 1;
}

// 11.76 / 11.77: the (u, v) parameters of a hit: u about the axis, v about the tube.
bool torus_uv(SvgWriter& w, bool show_u) {
  w.set_camera(camera({2, -8, 7}, {0, 0, 0}));
  const Torus3<double> t{{0, 0, 0}, {0, 0, 1}, 2, 0.7};
  draw_torus(w, t, c::light);
  const Line3<double> l{{-4, 1.1, 0.45}, {1, 0, 0}};
  const auto r = intersection(l, t);
  if (r.count == 0) return false;
  const Vec3d p = r.point[0];
  const Vec2d uv = r.param_b[0];
  const auto b = perpendicular_basis(t.normal);
  const Vec3d dir = std::cos(uv.x) * b.u + std::sin(uv.x) * b.v;
  if (show_u) {
    w.arrow(t.center, t.center + 2.6 * b.u, pen(c::gray));
    w.arrow(t.center, t.center + t.major_radius * dir, pen(c::blue, 1.6));
    label(w, t.center + t.major_radius * dir, "u = " + fmt(uv.x), c::blue);
  } else {
    const Vec3d tube = t.center + t.major_radius * dir;
    w.polyline(ring(tube, dir, t.normal, t.minor_radius, 48), pen(c::blue, 1.4));
    w.arrow(tube, p, pen(c::blue, 1.6));
    label(w, p, "v = " + fmt(uv.y), c::blue);
  }
  point(w, p, "", c::red);
  return locus::length(point_at(t, uv) - p) < 1e-9;
}
bool fig_11_76(SvgWriter& w) { return torus_uv(w, true); }
bool fig_11_77(SvgWriter& w) { return torus_uv(w, false); }

// ---- parametric surfaces (sections 11.6-11.8) -------------------------------------------------

/// The iso-parameter wireframe of a surface (n lines each way), evaluated with point_at.
template <class S>
void wireframe(SvgWriter& w, const S& s, double u0, double u1, double v0, double v1,
               const char* col, int n = 10) {
  for (int k = 0; k <= n; ++k) {
    std::vector<Vec3d> a, b;
    for (int i = 0; i <= 40; ++i) {
      const double t = double(i) / 40.0, q = double(k) / n;
      a.push_back(point_at(s, u0 + q * (u1 - u0), v0 + t * (v1 - v0)));
      b.push_back(point_at(s, u0 + t * (u1 - u0), v0 + q * (v1 - v0)));
    }
    w.polyline(a, pen(col, 0.6));
    w.polyline(b, pen(col, 0.6));
  }
}

/// A wavy bicubic NURBS patch (weights != 1) used by 11.18-11.22.
NurbsSurface<double, 3> wavy_nurbs() {
  NurbsSurface<double, 3> s{3, 3, 4, 4, {}, {}, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}};
  const double z[4][4] = {
      {0, 0.6, -0.4, 0}, {0.5, 1.4, 0.2, -0.3}, {-0.2, 0.3, 1.2, 0.4}, {0, -0.5, 0.4, 0.2}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      s.control.push_back({double(i) - 1.5, double(j) - 1.5, z[i][j]});
      s.weights.push_back(i == 1 && j == 2 ? 2.5 : 1.0);
    }
  return s;
}

// 11.18: a ray meets a NURBS surface: every hit with its normal (hierarchy refinement + Newton).
bool fig_11_18(SvgWriter& w) {
  w.set_camera(camera({5, -7, 5}, {0, 0, 0.3}));
  const NurbsSurface<double, 3> s = wavy_nurbs();
  wireframe(w, s, 0, 1, 0, 1, c::gray);
  const Ray3<double> ray{{-2.5, -0.8, 2.2}, {1.0, 0.25, -0.55}};
  const LinearSurfaceHits<double> r = intersection(ray, s);
  if (r.status != Status::ok || r.hits.empty()) return false;
  w.polyline(std::vector<Vec3d>{ray.origin, ray.origin + 5.5 * ray.direction}, pen(c::red, 1.6));
  point(w, ray.origin, "P", c::red);
  for (const auto& h : r.hits) {
    point(w, h.point, "t = " + fmt(h.t), c::black);
    w.arrow(h.point, h.point + 0.7 * h.normal, pen(c::blue, 1.4));
  }
  return true;
}

// 11.20: the ray as the intersection of two planes through it (the frame of the refinement).
bool fig_11_20(SvgWriter& w) {
  w.set_camera(camera({5, -7, 4}, {0, 0, 0}));
  const Ray3<double> ray{{-2, -0.5, 0.4}, normalize(Vec3d{1, 0.3, -0.2})};
  const auto b = perpendicular_basis(ray.direction);
  const Plane3<double> p1{b.u, dot(b.u, ray.origin)}, p2{b.v, dot(b.v, ray.origin)};
  const Vec3d mid = ray.origin + 2.0 * ray.direction;
  plane_patch(w, p1, mid, 2.0, c::blue);
  plane_patch(w, p2, mid, 2.0, c::green);
  w.polyline(std::vector<Vec3d>{ray.origin, ray.origin + 4.0 * ray.direction}, pen(c::red, 2.2));
  point(w, ray.origin, "P", c::red);
  return std::fabs(dot(p1.normal, mid) - p1.constant) < 1e-12 &&
         std::fabs(dot(p2.normal, mid) - p2.constant) < 1e-12;
}

// 11.21-11.22: control-net boxes of the subpatches the refinement keeps along a ray (box-ray
// rejection down three levels), the leaf boxes and their parent level.
bool refinement_boxes(SvgWriter& w, int levels) {
  w.set_camera(camera({5, -7, 5}, {0, 0, 0.3}));
  const NurbsSurface<double, 3> s = wavy_nurbs();
  wireframe(w, s, 0, 1, 0, 1, c::gray, 6);
  const Ray3<double> ray{{-2.5, -0.8, 2.2}, {1.0, 0.25, -0.55}};
  w.polyline(std::vector<Vec3d>{ray.origin, ray.origin + 5.5 * ray.direction}, pen(c::red, 1.6));
  const RationalPatchGrid<double, 3> g = to_bezier(s);
  if (g.status != Status::ok || g.patches.size() != 1) return false;
  // The homogeneous patch, split in four per level; boxes from the projected control points.
  BezierPatch<double, 4> h{g.patches[0].rows, g.patches[0].cols, {}};
  for (std::size_t k = 0; k < g.patches[0].control.size(); ++k) {
    const double wt = g.patches[0].weights[k];
    const Vec3d p = wt * g.patches[0].control[k];
    h.control.push_back({p.x, p.y, p.z, wt});
  }
  std::vector<BezierPatch<double, 4>> cur{h};
  int kept = 0;
  for (int level = 1; level <= levels; ++level) {
    std::vector<BezierPatch<double, 4>> next;
    for (const auto& q : cur) {
      const auto a = subdivide_u(q, 0.5);
      for (const auto* half : {&a.first, &a.second}) {
        const auto b = subdivide_v(*half, 0.5);
        for (const auto* piece : {&b.first, &b.second}) {
          std::vector<Vec3d> pts;
          for (const auto& c4 : piece->control) pts.push_back(Vec3d{c4.x, c4.y, c4.z} / c4.w);
          const AlignedBox3<double> box = bounding_box(pts.data(), pts.size());
          if (!intersects(ray, box)) continue;
          next.push_back(*piece);
          if (level == levels) {
            draw_box(w, box, pen(c::blue, 0.9));
            ++kept;
          } else if (level == levels - 1) {
            draw_box(w, box, pen(c::green, 0.5));
          }
        }
      }
    }
    cur = std::move(next);
  }
  for (const auto& hit : intersection(ray, s).hits) point(w, hit.point, "", c::red);
  return kept > 0;
}
bool fig_11_21(SvgWriter& w) { return refinement_boxes(w, 3); }
bool fig_11_22(SvgWriter& w) { return refinement_boxes(w, 2); }

/// A bicubic bump patch for the plane-surface figures: a dome with a dimple.
BezierPatch<double, 3> dome() {
  BezierPatch<double, 3> p{4, 4, {}};
  const double z[4][4] = {
      {0, 0.3, 0.3, 0}, {0.3, 2.0, 0.4, 0.3}, {0.3, 0.4, 2.0, 0.3}, {0, 0.3, 0.3, 0}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.control.push_back({double(i) - 1.5, double(j) - 1.5, z[i][j]});
  return p;
}

// 11.53: a plane cuts a parametric surface: the traced curves (closed loops and open branches).
bool fig_11_53(SvgWriter& w) {
  w.set_camera(camera({5, -7, 6}, {0, 0, 0.4}));
  const BezierPatch<double, 3> p = dome();
  wireframe(w, p, 0, 1, 0, 1, c::gray);
  const Plane3<double> pl{{0.1, 0.05, 1}, 0.75};
  const SurfaceCurves<double> r = intersection(pl, p);
  if (r.status != Status::ok || r.curves.empty()) return false;
  plane_patch(w, pl, {0, 0, 0.75}, 2.0, c::blue);
  for (const auto& cv : r.curves) w.polyline(cv.points, pen(c::red, 2.4), cv.closed);
  return true;
}

// 11.58: the same curves in the surface's parameter space (the grid cells of the subdivision).
bool fig_11_58(SvgWriter& w) {
  w.set_view({-0.05, -0.05}, {1.05, 1.05});
  const Plane3<double> pl{{0.1, 0.05, 1}, 0.75};
  SurfaceCurveOptions opt;
  opt.grid = 16;
  const SurfaceCurves<double> r = intersection(pl, dome(), opt);
  if (r.status != Status::ok || r.curves.empty()) return false;
  for (int k = 0; k <= opt.grid; ++k) {
    const double q = double(k) / opt.grid;
    w.polyline(std::vector<Vec2d>{{q, 0}, {q, 1}}, pen(c::gray, 0.4));
    w.polyline(std::vector<Vec2d>{{0, q}, {1, q}}, pen(c::gray, 0.4));
  }
  for (const auto& cv : r.curves) {
    w.polyline(cv.param_b, pen(c::red, 2.0), cv.closed);
    label(w, cv.param_b.front(), cv.closed ? "closed" : "open", c::black);
  }
  return true;
}

/// Two bicubic B-spline surfaces for 11.59-11.60 (a dome and a tilted wave).
void two_bsplines(BSplineSurface<double, 3>& a, BSplineSurface<double, 3>& b) {
  const std::vector<double> k{0, 0, 0, 0, 0.5, 1, 1, 1, 1};
  a = {3, 3, 5, 5, {}, k, k};
  b = {3, 3, 5, 5, {}, k, k};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const double x = double(i) - 2, y = double(j) - 2;
      a.control.push_back({x, y, 1.6 - 0.25 * (x * x + y * y)});
      b.control.push_back({x + 0.3, y - 0.2, 0.3 + 0.25 * x + 0.6 * std::sin(1.3 * y)});
    }
}

// 11.59: two B-spline surfaces and their intersection curves (seeds by subdivision, tracing).
bool fig_11_59(SvgWriter& w) {
  w.set_camera(camera({6, -8, 6}, {0, 0, 0.3}));
  BSplineSurface<double, 3> a, b;
  two_bsplines(a, b);
  wireframe(w, a, 0, 1, 0, 1, c::blue, 8);
  wireframe(w, b, 0, 1, 0, 1, c::green, 8);
  const SurfaceCurves<double> r = intersection(a, b);
  if (r.status != Status::ok || r.curves.empty()) return false;
  for (const auto& cv : r.curves) w.polyline(cv.points, pen(c::red, 2.6), cv.closed);
  return true;
}

// 11.60: the same curves in the parameter space of the first surface.
bool fig_11_60(SvgWriter& w) {
  w.set_view({-0.05, -0.05}, {1.05, 1.05});
  BSplineSurface<double, 3> a, b;
  two_bsplines(a, b);
  const SurfaceCurves<double> r = intersection(a, b);
  if (r.status != Status::ok || r.curves.empty()) return false;
  closed(w, std::vector<Vec2d>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, pen(c::gray, 0.8));
  for (const auto& cv : r.curves) w.polyline(cv.param_a, pen(c::red, 2.0), cv.closed);
  label(w, Vec2d{0.02, 1.02}, "(u, v) of the first surface", c::black);
  return true;
}

// ---- linear components against polygons, disks and polyhedra (11.3-11.8) ----------------------

/// A non-convex pentagon in the plane z = 0.1 x + 0.2 y + 0.3 (the notch at vertex 3).
std::vector<Vec3d> notched_pentagon() {
  std::vector<Vec3d> v;
  for (const Vec2d& p :
       {Vec2d{-1, -1}, Vec2d{2, -0.8}, Vec2d{2.2, 1.6}, Vec2d{0.6, 0.4}, Vec2d{-0.8, 2}})
    v.push_back({p.x, p.y, 0.1 * p.x + 0.2 * p.y + 0.3});
  return v;
}

// 11.3: rays against a filled planar polygon: one crosses inside (its (s, t) in the polygon's
// frame), one crosses the plane in the notch and misses.
bool fig_11_3(SvgWriter& w) {
  w.set_camera(camera({4, -8, 7}, {0.5, 0.5, 0.4}));
  const std::vector<Vec3d> verts = notched_pentagon();
  const auto poly = planar_polygon(std::span<const Vec3d>(verts));
  if (!poly) return false;
  closed(w, verts, filled(c::blue, 0.18));
  const Plane3<double> pl{poly->frame.normal, dot(poly->frame.normal, poly->frame.origin)};
  const std::array<Ray3<double>, 2> rays = {Ray3<double>{{-0.5, -0.6, 3.2}, {0.15, 0.35, -1}},
                                            Ray3<double>{{0.9, 2.0, 3.2}, {-0.1, -0.25, -1}}};
  bool ok = true;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto r = intersection(rays[i], *poly);
    const auto through = intersection(rays[i], pl);  // where the ray crosses the plane
    if (through.kind != Kind::point) return false;
    const Vec3d x = through.point[0];
    w.arrow(rays[i].origin, x, pen(i == 0 ? c::red : c::orange, 1.8));
    w.segment(x, point_at(rays[i], through.param_a[0] + 0.9), dashed(i == 0 ? c::red : c::orange));
    point(w, rays[i].origin, i == 0 ? "P0" : "P1", i == 0 ? c::red : c::orange);
    if (r.kind == Kind::point) {
      point(w, r.point[0], "hit, (s, t) = " + coordinates(r.param_b[0].x, r.param_b[0].y), c::red);
    } else {
      point(w, x, "in the notch: misses", c::orange);
    }
    ok = ok && (r.kind == Kind::point) == (i == 0);
  }
  return ok;
}

// 11.4: a line, a segment and an in-plane line against a disk: a crossing, a segment that stops
// short (empty), and the chord of a line lying in the disk's plane.
bool fig_11_4(SvgWriter& w) {
  w.set_camera(camera({5, -8, 5}, {0, 0, 0.3}));
  const Disk3<double> d{{0, 0, 0.25}, {0, 0, 1}, 1.6};
  const auto ax = in_plane_axes(d);
  w.polyline(ring(d.center, ax.u, ax.v, d.radius), filled(c::blue, 0.15), true);
  point(w, d.center, "C", c::blue);
  const Line3<double> l{{-0.8, 0.5, 2.8}, {0.25, -0.15, -1}};
  const auto rl = intersection(l, d);
  w.segment(point_at(l, -0.3), point_at(l, 4.2), pen(c::red, 1.6));
  if (rl.kind == Kind::point) {
    point(w, rl.point[0], "", c::red);
    label(w, rl.point[0], "line: point", c::red, -80, -16);
  }
  const Segment3<double> s{{1.0, -0.8, 2.6}, {1.2, -0.9, 1.3}};
  const auto rs = intersection(s, d);
  w.segment(s.p0, s.p1, pen(c::orange, 2.2));
  label(w, s.p1, "segment: " + std::string(to_string(rs.kind)), c::orange);
  const Line3<double> in{d.center + Vec3d{0.3, 0.8, 0}, {1, 0.2, 0}};  // in the plane z = 0.25
  const auto rc = intersection(in, d);
  w.segment(in.origin - 2.4 * in.direction, in.origin + 2.4 * in.direction, dashed(c::purple));
  if (rc.kind == Kind::segment) {
    w.segment(rc.point[0], rc.point[1], pen(c::purple, 2.6));
    label(w, rc.point[1], "in the plane: chord", c::purple);
  }
  return rl.kind == Kind::point && rs.kind == Kind::empty && rc.kind == Kind::segment;
}

/// The outward face planes {n, n.a} of a convex mesh about the origin (fan triangles).
std::vector<Plane3<double>> face_planes(const PolygonMesh<double>& m) {
  std::vector<Plane3<double>> planes;
  for (const auto& t : fan_triangles(m)) {
    const Vec3d a = m.vertices[t[0]], b = m.vertices[t[1]], cc = m.vertices[t[2]];
    Vec3d n = cross(b - a, cc - a);
    if (dot(n, a) < 0) n = -n;
    planes.push_back({n, dot(n, a)});
  }
  return planes;
}

void mesh_edges(SvgWriter& w, const PolygonMesh<double>& m, const SvgStyle& s) {
  for (const auto& t : fan_triangles(m))
    closed(w, std::vector<Vec3d>{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]}, s);
}

// 11.5: a ray through an octahedron (the convex solid of its eight face half-spaces): entry and
// exit.
bool fig_11_5(SvgWriter& w) {
  w.set_camera(camera({4, -7, 4}, {0, 0, 0}));
  PolygonMesh<double> m = octahedron_mesh<double>();
  for (auto& v : m.vertices) v = 1.6 * v;
  const std::vector<Plane3<double>> planes = face_planes(m);
  mesh_edges(w, m, pen(c::blue, 1.2));
  const Ray3<double> ray{{-2.8, -1.2, 0.9}, {1, 0.45, -0.3}};
  const auto r = intersection(ray, ConvexPolyhedron3<double>{planes});
  if (r.kind != Kind::segment) return false;
  w.arrow(ray.origin, point_at(ray, 5.6), pen(c::gray, 1.4));
  w.segment(r.point[0], r.point[1], pen(c::red, 3));
  point(w, ray.origin, "P", c::gray);
  point(w, r.point[0], "entry t = " + fmt(r.param_a[0]), c::red);
  point(w, r.point[1], "exit t = " + fmt(r.param_a[1]), c::red);
  return true;
}

// 11.6: segments against a triangle mesh (an icosphere) through its BVH: every hit triangle.
bool fig_11_6(SvgWriter& w) {
  w.set_camera(camera({4, -7, 4}, {0, 0, 0}));
  const PolygonMesh<double> m = icosphere_mesh<double>(1.5, 1);
  const auto tris = fan_triangles(m);
  const Bvh<double> bvh{std::span<const Vec3d>(m.vertices),
                        std::span<const std::array<std::uint32_t, 3>>(tris)};
  if (bvh.status() != Status::ok) return false;
  mesh_edges(w, m, pen(c::light, 0.7));
  const std::array<Segment3<double>, 2> segs = {Segment3<double>{{-3, -0.6, 0.4}, {3, 0.5, 0.1}},
                                                Segment3<double>{{0.4, -3, -0.6}, {0.2, 0, -0.3}}};
  const std::size_t want[2] = {2, 1};
  bool ok = true;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    // The segment p0 + t (p1 - p0), t in [0, 1]: a ray with tmax = 1.
    const auto hits = bvh.all_hits(Ray3<double>{segs[i].p0, segs[i].p1 - segs[i].p0}, 1.0);
    for (const auto& h : hits) {
      const Triangle3<double> t = bvh.triangle(h.triangle);
      closed(w, std::vector<Vec3d>{t.v0, t.v1, t.v2}, filled(c::orange, 0.5));
    }
    w.segment(segs[i].p0, segs[i].p1, pen(c::red, 1.8));
    point(w, segs[i].p0, "", c::red);
    point(w, segs[i].p1, "", c::red);
    for (const auto& h : hits)
      point(w, segs[i].p0 + h.t * (segs[i].p1 - segs[i].p0),
            "t = " + fmt(h.t) + (h.front ? " (enters)" : " (leaves)"), c::black);
    ok = ok && hits.size() == want[i];
  }
  return ok;
}

/// A pentagonal prism |z| <= 1 over a convex pentagon: its outward planes (5 sides first).
std::vector<Plane3<double>> pentagon_prism() {
  const std::array<Vec2d, 5> p = {Vec2d{-1.5, -1}, Vec2d{1.2, -1.4}, Vec2d{2, 0.6}, Vec2d{0.3, 1.8},
                                  Vec2d{-1.7, 0.9}};
  std::vector<Plane3<double>> planes;
  for (std::size_t i = 0; i < 5; ++i) {
    const Vec2d a = p[i], b = p[(i + 1) % 5];
    const Vec3d n{b.y - a.y, a.x - b.x, 0};  // outward for a counter-clockwise pentagon
    planes.push_back({n, n.x * a.x + n.y * a.y});
  }
  planes.push_back({{0, 0, 1}, 1});
  planes.push_back({{0, 0, -1}, 1});
  return planes;
}

// 11.7 / 11.8: each face plane bounds the line to a half-line (entering: t >= t_i, leaving:
// t <= t_i); the line meets the polyhedron in their logical intersection, empty when the
// half-lines have no common part. Seen from above, half-lines stacked below the line.
bool half_lines(SvgWriter& w, const Line3<double>& l, bool meets) {
  w.set_camera(camera({0.2, -0.5, 10}, {0.2, -0.5, 0}));
  const std::vector<Plane3<double>> planes = pentagon_prism();
  std::vector<Vec3d> outline;
  for (std::size_t i = 0; i < 5; ++i) {
    const auto corner = intersection(planes[i], planes[(i + 1) % 5], planes[5]);
    if (corner.kind != Kind::point) return false;
    outline.push_back(corner.point[0]);
  }
  closed(w, outline, filled(c::blue, 0.15));
  const Vec3d d = normalize(l.direction);
  const Vec3d side = normalize(cross(Vec3d{0, 0, 1}, d));
  w.segment(point_at(l, -3.2), point_at(l, 3.2), pen(c::black, 1.4));
  label(w, point_at(l, 3.2), "line", c::black);
  const char* cols[] = {c::red, c::green, c::orange, c::purple, c::blue};
  for (std::size_t i = 0; i < 5; ++i) {
    const std::array<Plane3<double>, 1> one = {planes[i]};
    const auto h = intersection(l, ConvexPolyhedron3<double>{one});
    if (h.kind != Kind::ray) return false;
    // The half-line within the drawn range t in [-3.2, 3.2] (its bound may lie outside).
    const bool forward = dot(h.point[1] - h.point[0], d) > 0;
    const double t0 = std::clamp(h.param_a[0], -3.2, 3.2), t1 = forward ? 3.2 : -3.2;
    const Vec3d off = (-0.3 * double(i + 1) - 0.2) * side;
    const Vec3d b = point_at(l, t0) + off;
    if (t0 == h.param_a[0]) w.segment(h.point[0], b, dashed(cols[i], 0.8));
    if (t0 != t1) w.arrow(b, point_at(l, t1) + off, pen(cols[i], 2));
    label(w, b, (forward ? "t >= " : "t <= ") + fmt(h.param_a[0]), cols[i], -8, -14);
  }
  const auto all = intersection(l, ConvexPolyhedron3<double>{planes});
  if (all.kind == Kind::segment) {
    w.segment(all.point[0], all.point[1], pen(c::red, 4));
    label(w, all.point[1], "[" + fmt(all.param_a[0]) + ", " + fmt(all.param_a[1]) + "]", c::red);
  } else {
    label(w, point_at(l, -3.2), "common part: " + std::string(to_string(all.kind)), c::red, 0, 14);
  }
  return (all.kind == Kind::segment) == meets;
}
bool fig_11_7(SvgWriter& w) { return half_lines(w, {{-0.5, -0.2, 0}, {1, 0.3, 0}}, true); }
bool fig_11_8(SvgWriter& w) { return half_lines(w, {{0.5, 2.2, 0}, {1, -0.9, 0}}, false); }

// 11.19: a ray between a bump and its coarse tessellation (cross section): it hits the true
// surface (ray-NURBS refinement) twice and misses every triangle of the mesh (BVH).
bool fig_11_19(SvgWriter& w) {
  w.set_camera(camera({0, -10, 0.6}, {0, 0, 0.6}));
  BezierPatch<double, 3> p{4, 4, {}};
  const double zs[4] = {0, 1.6, 1.6, 0};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.control.push_back({double(i) - 1.5, double(j) - 1.5, zs[i]});
  // The tessellation: u in {0, 1/2, 1}, v in {0, 1}.
  std::vector<Vec3d> verts;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) verts.push_back(point_at(p, 0.5 * i, double(j)));
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::uint32_t i = 0; i < 2; ++i) {
    tris.push_back({2 * i, 2 * i + 2, 2 * i + 3});
    tris.push_back({2 * i, 2 * i + 3, 2 * i + 1});
  }
  const Bvh<double> bvh{std::span<const Vec3d>(verts),
                        std::span<const std::array<std::uint32_t, 3>>(tris)};
  // Parallel to the first chord, 0.15 above it.
  const Ray3<double> ray{{-2.6, 0, -0.73}, {1, 0, 0.8}};
  const auto true_hits = intersection(ray, p);
  const auto mesh_hits = bvh.all_hits(ray);
  std::vector<Vec3d> curve;
  for (int k = 0; k <= 60; ++k) curve.push_back(point_at(p, k / 60.0, 0.5));
  w.polyline(curve, pen(c::blue, 2));
  w.polyline(std::vector<Vec3d>{verts[0], verts[2], verts[4]}, pen(c::green, 2));
  for (const int k : {0, 2, 4}) point(w, verts[static_cast<std::size_t>(k)], "", c::green);
  label(w, point_at(p, 0.8, 0.5), "surface", c::blue);
  label(w, verts[4] + Vec3d{-0.6, 0, 0.5}, "tessellation", c::green, 0, -18);
  w.arrow(ray.origin, point_at(ray, 3.6), pen(c::red, 1.6));
  point(w, ray.origin, "P", c::red);
  for (const auto& h : true_hits.hits) point(w, h.point, "", c::red);
  if (!true_hits.hits.empty())
    label(w, true_hits.hits.back().point, "hits the surface", c::red, 8, 10);
  label(w, point_at(ray, 3.2), mesh_hits.empty() ? "misses the mesh" : "hits the mesh", c::red);
  return true_hits.status == Status::ok && true_hits.hits.size() == 2 && mesh_hits.empty();
}

// ---- triangle intervals, polygons (11.28, 11.30, 11.31) -------------------------------------

Plane3<double> plane_of(const Triangle3<double>& t) {
  const Vec3d n = cross(t.v1 - t.v0, t.v2 - t.v0);
  return {n, dot(n, t.v0)};
}

// 11.28: each triangle meets the other's plane in an interval of the common line; the triangles
// meet iff the intervals overlap: (a) overlap, (b) disjoint.
bool fig_11_28(SvgWriter& w) {
  w.set_camera(camera({6, -10, 5}, {1.5, 0.5, -2}));
  const Triangle3<double> a{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}};
  const Triangle3<double> b0{{0.5, 0.5, -1}, {0.8, 1.0, 1.2}, {2.6, -0.6, 0.2}};
  // (b): the same triangle slid along the common line (its plane unchanged) past a's interval.
  const auto l0 = intersection(plane_of(a), plane_of(b0));
  const auto ia0 = intersection(a, plane_of(b0)), ib0 = intersection(b0, plane_of(a));
  if (l0.kind != Kind::line || ia0.kind != Kind::segment || ib0.kind != Kind::segment) return false;
  const Vec3d slide =
      (length(ia0.point[1] - ia0.point[0]) + length(ib0.point[1] - ib0.point[0]) + 0.4) *
      normalize(l0.point[1] - l0.point[0]);
  const Vec3d away =
      dot(slide, 0.5 * (ia0.point[0] + ia0.point[1]) - 0.5 * (ib0.point[0] + ib0.point[1])) > 0
          ? -slide
          : slide;
  const std::array<Triangle3<double>, 2> bs = {
      b0, Triangle3<double>{b0.v0 + away, b0.v1 + away, b0.v2 + away}};
  const Kind want[2] = {Kind::segment, Kind::empty};
  const char* names[2] = {"(a) intervals overlap", "(b) disjoint intervals"};
  for (std::size_t i = 0; i < 2; ++i) {
    const Vec3d sh{0, 0, -4.0 * double(i)};
    const Triangle3<double> ta{a.v0 + sh, a.v1 + sh, a.v2 + sh};
    const Triangle3<double> tb{bs[i].v0 + sh, bs[i].v1 + sh, bs[i].v2 + sh};
    const auto line = intersection(plane_of(ta), plane_of(tb));
    const auto ia = intersection(ta, plane_of(tb));  // a's interval on the common line
    const auto ib = intersection(tb, plane_of(ta));  // b's interval
    const auto r = intersection(ta, tb);
    if (line.kind != Kind::line || ia.kind != Kind::segment || ib.kind != Kind::segment ||
        r.kind != want[i])
      return false;
    closed(w, std::vector<Vec3d>{ta.v0, ta.v1, ta.v2}, filled(c::blue, 0.15));
    closed(w, std::vector<Vec3d>{tb.v0, tb.v1, tb.v2}, filled(c::green, 0.15));
    const Vec3d dl = normalize(line.point[1] - line.point[0]);
    const Vec3d mid = 0.5 * (ia.point[0] + ia.point[1]);
    w.segment(mid - 3.0 * dl, mid + 3.0 * dl, dashed(c::gray, 1));
    w.segment(ia.point[0], ia.point[1], pen(c::blue, 4));
    const Vec3d lift{0, 0, -0.25};  // b's interval drawn just below the line
    w.segment(ib.point[0] + lift, ib.point[1] + lift, pen(c::green, 4));
    if (r.kind == Kind::segment) w.segment(r.point[0], r.point[1], pen(c::red, 2.5));
    label(w, sh + Vec3d{3.2, 0, -0.4}, names[i], c::black);
  }
  return true;
}

/// A non-convex (U-shaped) polygon in a tilted plane through (1, 1, 0.5).
std::vector<Vec3d> u_polygon() {
  std::vector<Vec3d> v;
  for (const Vec2d& p : {Vec2d{0, 0}, Vec2d{3, 0}, Vec2d{3, 2.5}, Vec2d{2, 2.5}, Vec2d{2, 1},
                         Vec2d{1, 1}, Vec2d{1, 2.5}, Vec2d{0, 2.5}})
    v.push_back({p.x, p.y, 0.5 + 0.15 * (p.x - 1) - 0.1 * (p.y - 1)});
  return v;
}

// 11.30: a plane cuts a U-shaped polygon in two pieces of the common line.
bool fig_11_30(SvgWriter& w) {
  w.set_camera(camera({6, -7, 6}, {1.5, 1.2, 0.5}));
  const std::vector<Vec3d> poly = u_polygon();
  const Plane3<double> pl{{0, 1, 0.6}, 2.2};
  const auto r = intersection(std::span<const Vec3d>(poly), pl);
  if (r.status != Status::ok || r.segments.size() != 2) return false;
  plane_patch(w, pl, {1.5, 1.8, 0.6}, 2.2, c::green);
  closed(w, poly, filled(c::blue, 0.2));
  for (const auto& s : r.segments) {
    w.segment(s.p0, s.p1, pen(c::red, 3));
    point(w, s.p0, "", c::red);
    point(w, s.p1, "", c::red);
  }
  label(w, r.segments[0].p0, "2 pieces", c::red, -60, 12);
  return true;
}

// 11.31: the same polygon against a triangle: the pieces of the common line inside both.
bool fig_11_31(SvgWriter& w) {
  w.set_camera(camera({6, -7, 6}, {1.5, 1.2, 0.5}));
  const std::vector<Vec3d> poly = u_polygon();
  const Triangle3<double> t{{-0.4, 1.6, 2.2}, {2.6, 2.4, -1.2}, {2.8, 1.2, 1.6}};
  const auto r = intersection(std::span<const Vec3d>(poly), t);
  if (r.status != Status::ok || r.coplanar || r.segments.empty()) return false;
  closed(w, poly, filled(c::blue, 0.2));
  closed(w, std::vector<Vec3d>{t.v0, t.v1, t.v2}, filled(c::green, 0.25));
  for (const auto& s : r.segments) {
    w.segment(s.p0, s.p1, pen(c::red, 3));
    point(w, s.p0, "", c::red);
    point(w, s.p1, "", c::red);
  }
  label(w, r.segments.back().p1, std::to_string(r.segments.size()) + " piece(s)", c::red);
  return true;
}

// ---- slab, OBB projection (11.63, 11.70) -----------------------------------------------------

// 11.63: a line clipped by one slab (two parallel planes), seen from above.
bool fig_11_63(SvgWriter& w) {
  w.set_camera(camera({1, 0.5, 10}, {1, 0.5, 0}));
  const std::array<Plane3<double>, 2> slab = {Plane3<double>{{-1, 0, 0}, 0},
                                              Plane3<double>{{1, 0, 0}, 2}};
  closed(w, std::vector<Vec3d>{{0, -1.6, 0}, {2, -1.6, 0}, {2, 2.6, 0}, {0, 2.6, 0}},
         filled(c::blue, 0.12, 0));
  w.segment(Vec3d{0, -1.6, 0}, Vec3d{0, 2.6, 0}, pen(c::blue, 1.6));
  w.segment(Vec3d{2, -1.6, 0}, Vec3d{2, 2.6, 0}, pen(c::blue, 1.6));
  label(w, Vec3d{0, 2.6, 0}, "x = min", c::blue);
  label(w, Vec3d{2, 2.6, 0}, "x = max", c::blue);
  const Line3<double> l{{-1.2, -1.0, 0}, {1, 0.7, 0}};
  const auto r = intersection(l, ConvexPolyhedron3<double>{slab});
  if (r.kind != Kind::segment) return false;
  w.segment(point_at(l, -0.3), point_at(l, 4.8), pen(c::gray, 1.4));
  w.segment(r.point[0], r.point[1], pen(c::red, 3.5));
  point(w, l.origin, "P", c::gray);
  point(w, r.point[0], "t0 = " + fmt(r.param_a[0]), c::red);
  point(w, r.point[1], "t1 = " + fmt(r.param_a[1]), c::red);
  return true;
}

// 11.70: an oriented box against a plane: the corners at the ends of the diagonal most aligned
// with the normal project onto the normal line through the centre to C.n +- r,
// r = sum e_i |a_i . n|; the box meets the plane iff |C.n - k| <= r.
bool fig_11_70(SvgWriter& w) {
  w.set_camera(camera({6, -7, 3}, {0, 0, 0.3}));
  const double s = std::sqrt(0.5);
  const OrientedBox3<double> b{{0, 0, 0}, {{s, s, 0}, {-s, s, 0}, {0, 0, 1}}, {1.2, 0.6, 0.5}};
  const Plane3<double> pl{{0.3, -0.35, 1.0}, 0.55};
  const Vec3d n = normalize(pl.normal);
  const auto cs = corners(b);
  std::size_t lo = 0, hi = 0;
  for (std::size_t k = 1; k < 8; ++k) {
    if (dot(n, cs[k]) < dot(n, cs[lo])) lo = k;
    if (dot(n, cs[k]) > dot(n, cs[hi])) hi = k;
  }
  double r = 0;
  for (int k = 0; k < 3; ++k) r += b.extent[k] * std::fabs(dot(b.axis[k], n));
  const Sign side = side_of_plane(b, pl);
  draw_box(w, b, pen(c::blue));
  plane_patch(w, pl, b.center + 0.9 * n, 1.3, c::green);
  w.segment(cs[lo], cs[hi], pen(c::red, 2));
  w.segment(b.center - 2.0 * n, b.center + 2.0 * n, dashed(c::black, 1));
  label(w, b.center + 2.0 * n, "n", c::black);
  const Vec3d plo = b.center + dot(n, cs[lo] - b.center) * n;
  const Vec3d phi = b.center + dot(n, cs[hi] - b.center) * n;
  w.segment(cs[lo], plo, dashed(c::red, 1));
  w.segment(cs[hi], phi, dashed(c::red, 1));
  w.segment(plo, phi, pen(c::orange, 4));
  point(w, b.center, "C", c::black);
  label(w, phi, "r = " + fmt(r), c::orange, -60, 4);
  const double dist = dot(n, b.center) - pl.constant / length(pl.normal);
  point(w, b.center - dist * n, "plane: k = " + fmt(pl.constant / length(pl.normal)), c::green);
  label(w, b.center + Vec3d{0, 0, -1.4},
        std::string("|C.n - k| = ") + fmt(std::fabs(dist)) +
            (side == Sign::zero ? " <= r: meets" : " > r: apart"),
        c::black);
  // The extreme diagonal's half-projection is r, and the exact side agrees with the test.
  return std::fabs(0.5 * dot(n, cs[hi] - cs[lo]) - r) < 1e-12 &&
         (side == Sign::zero) == (std::fabs(dist) <= r);
}

// ---- plane sections: edge-on views, circle, Dandelin spheres, cone (11.36-11.47) -------------

/// The cylinder x^2 + y^2 = 1 about z cut by the plane 0.5 x + z = 0.3 (11.36, 11.39, 11.40).
const Cylinder3<double> kDandelinCylinder{
    {{0, 0, 0}, {0, 0, 1}}, 1, std::numeric_limits<double>::infinity()};
const Plane3<double> kDandelinPlane{{0.5, 0, 1}, 0.3};

/// The two Dandelin spheres of an ellipse cut from a cylinder: radius r, centred on the axis at
/// focus +- r n (the sign that lands on the axis); false if a centre is off the axis (a check of
/// the computed foci).
bool dandelin_spheres(const PlaneConic3<double>& c0, const Cylinder3<double>& cyl,
                      std::array<Sphere3<double>, 2>& out) {
  for (int i = 0; i < 2; ++i) {
    const Vec3d f = c0.focus[i];
    const Vec3d a = f + cyl.radius * c0.normal, b = f - cyl.radius * c0.normal;
    const auto off_axis = [&](const Vec3d& x) {
      const Vec3d q = x - cyl.axis.origin;
      return length(q - dot(q, cyl.axis.direction) * cyl.axis.direction);
    };
    const Vec3d centre = off_axis(a) < off_axis(b) ? a : b;
    if (off_axis(centre) > 1e-9) return false;
    out[static_cast<std::size_t>(i)] = {centre, cyl.radius};
  }
  return true;
}

// 11.36: the plane-cylinder section seen edge-on (along the ellipse's minor axis): the plane is
// a line and the ellipse its major axis, a = r / cos(angle between normal and axis).
bool fig_11_36(SvgWriter& w) {
  const auto c0 = intersection(kDandelinPlane, kDandelinCylinder);
  if (c0.type != ConicType::ellipse) return false;
  w.set_camera(camera(c0.center + 10.0 * c0.axis[1], c0.center));
  draw_cylinder(w, kDandelinCylinder, 2.2, c::blue);
  plane_patch(w, kDandelinPlane, c0.center, 2.0, c::green);
  const Vec3d e0 = c0.center - c0.extent[0] * c0.axis[0],
              e1 = c0.center + c0.extent[0] * c0.axis[0];
  w.segment(e0, e1, pen(c::red, 3));
  point(w, e0, "", c::red);
  point(w, e1, "", c::red);
  label(w, c0.center, "2a = " + fmt(2 * c0.extent[0]), c::red, 8, -18);
  w.arrow(c0.center, c0.center + 1.2 * c0.normal, pen(c::green, 1.6));
  label(w, c0.center + 1.2 * c0.normal, "n", c::green);
  w.arrow(c0.center, c0.center + Vec3d{0, 0, 1.6}, pen(c::blue, 1.6));
  label(w, c0.center + Vec3d{0, 0, 1.6}, "axis", c::blue);
  const double cos_angle = std::fabs(dot(c0.normal, kDandelinCylinder.axis.direction));
  label(w, c0.center + Vec3d{0, 0, -2.0}, "r / cos = " + fmt(1.0 / cos_angle), c::black);
  return std::fabs(c0.extent[0] - kDandelinCylinder.radius / cos_angle) < 1e-12;
}

// 11.38: the circle in 3D from a plane and a sphere: centre, normal, in-plane axes, radius.
bool fig_11_38(SvgWriter& w) {
  w.set_camera(camera({5, -7, 5}, {0, 0, 0.5}));
  const Sphere3<double> s{{0, 0, 0}, 2};
  const Plane3<double> pl{{0.2, 0.3, 1}, 1.0};
  const auto c0 = intersection(pl, s);
  if (c0.type != ConicType::circle) return false;
  draw_sphere(w, s, c::light);
  draw_conic(w, c0, c::red);
  point(w, c0.center, "C", c::black);
  w.arrow(c0.center, c0.center + 1.2 * c0.normal, pen(c::green, 1.8));
  label(w, c0.center + 1.2 * c0.normal, "N", c::green);
  w.arrow(c0.center, c0.center + c0.extent[0] * c0.axis[0], pen(c::blue, 1.8));
  label(w, c0.center + c0.extent[0] * c0.axis[0], "U", c::blue);
  w.arrow(c0.center, c0.center + c0.extent[1] * c0.axis[1], pen(c::blue, 1.8));
  label(w, c0.center + c0.extent[1] * c0.axis[1], "V", c::blue);
  label(w, c0.center + 0.5 * c0.extent[0] * c0.axis[0], "r = " + fmt(c0.extent[0]), c::blue, 4,
        -16);
  const double d = pl.constant / length(pl.normal);  // the centre's distance
  return std::fabs(c0.extent[0] - std::sqrt(s.radius * s.radius - d * d)) < 1e-12;
}

// 11.39: Dandelin's construction: the spheres inscribed in the cylinder touching the plane touch
// it at the foci; for P on the ellipse |PF1| + |PF2| is the distance between the circles where
// the spheres touch the cylinder, 2a.
bool fig_11_39(SvgWriter& w) {
  w.set_camera(camera({5, -8, 3}, {0, 0, 0}));
  const auto c0 = intersection(kDandelinPlane, kDandelinCylinder);
  std::array<Sphere3<double>, 2> sp{};
  if (c0.type != ConicType::ellipse || !dandelin_spheres(c0, kDandelinCylinder, sp)) return false;
  draw_cylinder(w, kDandelinCylinder, 2.4, c::light);
  plane_patch(w, kDandelinPlane, c0.center, 1.8, c::green);
  for (const auto& s : sp) {
    draw_sphere(w, s, c::blue);
    w.polyline(ring(s.center, {1, 0, 0}, {0, 1, 0}, s.radius), pen(c::purple, 1.6));
  }
  draw_conic(w, c0, c::red);
  const Vec3d p = point_at(c0, 2.2);
  const Vec3d q0{p.x, p.y, sp[0].center.z}, q1{p.x, p.y, sp[1].center.z};
  w.segment(q0, q1, pen(c::purple, 1.6));
  w.segment(p, c0.focus[0], pen(c::orange, 1.6));
  w.segment(p, c0.focus[1], pen(c::orange, 1.6));
  point(w, p, "P", c::black);
  const double sum = length(p - c0.focus[0]) + length(p - c0.focus[1]);
  label(w, Vec3d{0, 0, -2.8}, "|PF| + |PF'| = " + fmt(sum) + " = 2a = " + fmt(2 * c0.extent[0]),
        c::black);
  return std::fabs(sum - 2 * c0.extent[0]) < 1e-9 && std::fabs(sum - length(q1 - q0)) < 1e-9;
}

// 11.40: the same in cross section (edge-on along the minor axis): the spheres are circles
// touching the cylinder's sides and the plane's line at the foci.
bool fig_11_40(SvgWriter& w) {
  const auto c0 = intersection(kDandelinPlane, kDandelinCylinder);
  std::array<Sphere3<double>, 2> sp{};
  if (c0.type != ConicType::ellipse || !dandelin_spheres(c0, kDandelinCylinder, sp)) return false;
  w.set_camera(camera(c0.center + 10.0 * c0.axis[1], c0.center));
  const Vec3d side = normalize(cross(c0.axis[1], kDandelinCylinder.axis.direction));
  for (const double k : {-1.0, 1.0})
    w.segment(k * side + Vec3d{0, 0, -2.6}, k * side + Vec3d{0, 0, 2.6}, pen(c::blue, 1.6));
  plane_patch(w, kDandelinPlane, c0.center, 2.0, c::green);
  for (const auto& s : sp) {
    w.polyline(ring(s.center, side, {0, 0, 1}, s.radius), pen(c::purple, 1.6));
    point(w, s.center, "", c::purple);
  }
  w.segment(c0.center - c0.extent[0] * c0.axis[0], c0.center + c0.extent[0] * c0.axis[0],
            pen(c::red, 3));
  point(w, c0.focus[0], "F", c::red);
  point(w, c0.focus[1], "F'", c::red);
  return true;
}

// 11.44: the test for a plane and a (one-nappe) infinite cone: the plane meets the conic of the
// double cone; it meets the drawn nappe iff part of that conic lies on the axis side of the
// vertex (checked on the computed conic's centre and type).
bool fig_11_44(SvgWriter& w) {
  w.set_camera(camera({6, -9, 2}, {0, 0, 0.8}));
  const double inf = std::numeric_limits<double>::infinity();
  const Cone3<double> cone{{0, 0, 0}, {0, 0, 1}, 0.5, 0, inf};
  draw_cone(w, cone, 0, 3, c::blue);
  w.arrow(cone.vertex, cone.vertex + 1.0 * cone.axis, pen(c::blue, 1.6));
  point(w, cone.vertex, "V", c::blue);
  const std::array<Plane3<double>, 2> pls = {Plane3<double>{{0.3, 0, 1}, 1.6},
                                             Plane3<double>{{0.25, 0, 1}, -0.5}};
  const char* cols[2] = {c::red, c::orange};
  bool ok = true;
  for (std::size_t i = 0; i < 2; ++i) {
    const auto c0 = intersection(pls[i], cone);
    const bool upper = c0.type == ConicType::ellipse && dot(c0.center - cone.vertex, cone.axis) > 0;
    plane_patch(w, pls[i], project(pls[i], Vec3d{0, 0, 0}), 1.8, i == 0 ? c::green : c::gray);
    if (upper) draw_conic(w, c0, cols[i]);
    label(w, project(pls[i], Vec3d{1.8, 0, 0}),
          upper ? "meets the nappe (ellipse)"
                : "misses: " + std::string(to_string(c0.type)) + " on the other nappe",
          cols[i]);
    ok = ok && upper == (i == 0);
  }
  return ok;
}

// 11.45: the plane-cone section edge-on (along the minor axis): the plane is a line through the
// two generators, the ellipse its major axis between them.
bool fig_11_45(SvgWriter& w) {
  const double inf = std::numeric_limits<double>::infinity();
  const Cone3<double> cone{{0, 0, 0}, {0, 0, 1}, 0.5, -inf, inf};
  const Plane3<double> pl{{0.4, 0, 1}, 1.5};
  const auto c0 = intersection(pl, cone);
  if (c0.type != ConicType::ellipse) return false;
  w.set_camera(camera(Vec3d{0, 0, 1.2} + 10.0 * c0.axis[1], {0, 0, 1.2}));
  draw_cone(w, cone, -0.5, 3, c::blue);
  w.arrow(cone.vertex, cone.vertex + 3.2 * cone.axis, dashed(c::blue, 1));
  point(w, cone.vertex, "V", c::blue);
  plane_patch(w, pl, c0.center, 2.2, c::green);
  const Vec3d e0 = c0.center - c0.extent[0] * c0.axis[0],
              e1 = c0.center + c0.extent[0] * c0.axis[0];
  w.segment(e0, e1, pen(c::red, 3));
  point(w, e0, "", c::red);
  point(w, e1, "", c::red);
  point(w, c0.center, "C", c::red);
  label(w, c0.center, "2a = " + fmt(2 * c0.extent[0]), c::red, 8, -18);
  // Both ends of the major axis lie on generators: angle alpha to the axis.
  const double a0 = std::acos(dot(normalize(e0 - cone.vertex), cone.axis));
  const double a1 = std::acos(dot(normalize(e1 - cone.vertex), cone.axis));
  return std::fabs(a0 - cone.angle) < 1e-9 && std::fabs(a1 - cone.angle) < 1e-9;
}

// 11.46: the infinite cone: vertex V, unit axis A, angle alpha; X is on it iff
// A.(X - V) = |X - V| cos(alpha) (X a computed line-cone hit).
bool fig_11_46(SvgWriter& w) {
  w.set_camera(camera({6, -9, 2}, {0, 0, 1.2}));
  const double inf = std::numeric_limits<double>::infinity();
  const Cone3<double> cone{{0, 0, 0}, {0, 0, 1}, 0.5, 0, inf};
  draw_cone(w, cone, 0, 3, c::blue);
  point(w, cone.vertex, "V", c::blue);
  w.arrow(cone.vertex, cone.vertex + 3.3 * cone.axis, pen(c::black, 1.6));
  label(w, cone.vertex + 3.3 * cone.axis, "A", c::black);
  const Line3<double> l{{-2, -1, 2}, {1, 0.3, 0}};
  const auto r = intersection(l, cone);
  if (r.count < 1) return false;
  const Vec3d x = r.point[0];
  w.segment(cone.vertex, x + 0.3 * (x - cone.vertex), pen(c::red, 1.8));
  point(w, x, "X", c::red);
  // The angle alpha between A and the generator through X.
  const Vec3d g = normalize(x - cone.vertex);
  std::vector<Vec3d> arc;
  for (int k = 0; k <= 20; ++k) {
    const double t = cone.angle * k / 20;
    const Vec3d side = normalize(g - dot(g, cone.axis) * cone.axis);
    arc.push_back(cone.vertex + 0.9 * (std::cos(t) * cone.axis + std::sin(t) * side));
  }
  w.polyline(arc, pen(c::gray, 1.2));
  label(w, arc[10], "alpha", c::gray);
  const double lhs = dot(cone.axis, x - cone.vertex);
  const double rhs = length(x - cone.vertex) * std::cos(cone.angle);
  label(w, Vec3d{0, 0, -0.6},
        "A.(X - V) = " + fmt(lhs, 4) + ",  |X - V| cos(alpha) = " + fmt(rhs, 4), c::black);
  return std::fabs(lhs - rhs) < 1e-9;
}

// 11.47: the focal definitions, drawn in each conic's own (axis[0], axis[1]) frame: a hyperbola,
// | |PF| - |PF'| | = 2a; a parabola, |PF| = distance to the directrix. The parabola is exact:
// axis (1, 1, 0), normal (1, 0, 1) and an angle whose double sine is exactly 1/2.
bool fig_11_47(SvgWriter& w) {
  const double inf = std::numeric_limits<double>::infinity();
  const auto flat = [](const PlaneConic3<double>& c0, const Vec3d& x, const Vec2d& at) {
    return at + Vec2d{dot(x - c0.center, c0.axis[0]), dot(x - c0.center, c0.axis[1])};
  };
  // Hyperbola.
  const Cone3<double> cone{{0, 0, 0}, {0, 0, 1}, 0.5, -inf, inf};
  const auto h = intersection(Plane3<double>{{1, 0, 0.1}, 1.2}, cone);
  if (h.type != ConicType::hyperbola) return false;
  const Vec2d ha{0, 0};
  for (int b = 0; b < 2; ++b) {
    std::vector<Vec2d> pts;
    for (int k = 0; k <= 60; ++k) pts.push_back(flat(h, point_at(h, -1.5 + 3.0 * k / 60, b), ha));
    w.polyline(pts, pen(c::red, 2.2));
  }
  const Vec3d p = point_at(h, 0.9, 0);
  point(w, flat(h, h.focus[0], ha), "F", c::red);
  point(w, flat(h, h.focus[1], ha), "F'", c::red);
  point(w, flat(h, p, ha), "P", c::black);
  w.segment(flat(h, p, ha), flat(h, h.focus[0], ha), pen(c::orange, 1.4));
  w.segment(flat(h, p, ha), flat(h, h.focus[1], ha), pen(c::orange, 1.4));
  const double diff = std::fabs(length(p - h.focus[0]) - length(p - h.focus[1]));
  label(w, ha + Vec2d{-2.5, -4.2}, "||PF| - |PF'|| = " + fmt(diff) + " = 2a", c::black);
  // Parabola: find the angle near pi/6 whose sine rounds to exactly 1/2.
  double angle = std::asin(0.5);
  for (int k = 0; k < 8 && std::sin(angle) != 0.5; ++k)
    angle = std::nextafter(angle, std::sin(angle) < 0.5 ? 1.0 : 0.0);
  if (std::sin(angle) != 0.5) return false;
  const auto q = intersection(Plane3<double>{{1, 0, 1}, 1.0},
                              Cone3<double>{{0, 0, 0}, {1, 1, 0}, angle, -inf, inf});
  if (q.type != ConicType::parabola) return false;
  const Vec2d qa{1.0, -9.0};
  std::vector<Vec2d> pts;
  for (int k = 0; k <= 60; ++k) pts.push_back(flat(q, point_at(q, -3.0 + 6.0 * k / 60), qa));
  w.polyline(pts, pen(c::red, 2.2));
  const double f = q.extent[0];  // focal length
  w.segment(qa + Vec2d{-f, -3.2}, qa + Vec2d{-f, 3.2}, pen(c::blue, 1.6));
  label(w, qa + Vec2d{-f, 3.2}, "directrix", c::blue);
  const Vec3d pp = point_at(q, 1.8);
  const Vec2d p2 = flat(q, pp, qa);
  point(w, flat(q, q.focus[0], qa), "F", c::red);
  point(w, p2, "P", c::black);
  w.segment(p2, flat(q, q.focus[0], qa), pen(c::orange, 1.4));
  w.segment(p2, Vec2d{qa.x - f, p2.y}, pen(c::orange, 1.4));
  const double to_focus = length(pp - q.focus[0]);
  const double to_line = dot(pp - q.center, q.axis[0]) + f;
  label(w, qa + Vec2d{-1.5, -4.2}, "|PF| = " + fmt(to_focus) + " = distance to directrix",
        c::black);
  return std::fabs(diff - 2 * h.extent[0]) < 1e-9 && std::fabs(to_focus - to_line) < 1e-9;
}

// ---- Hermite interpolation of the plane-surface curves (11.54-11.57) --------------------------

/// The dome cut by the plane of 11.53 with a coarse grid (4 cells: long Hermite segments).
bool dome_hermite(std::vector<HermiteSurfaceCurve<double>>& out, Plane3<double>& pl) {
  pl = {{0.1, 0.05, 1}, 0.75};
  SurfaceCurveOptions opt;
  opt.grid = 4;
  const SurfaceCurves<double> r = intersection(pl, dome(), opt);
  if (r.status != Status::ok || r.curves.empty()) return false;
  for (const auto& cv : r.curves) {
    out.push_back(hermite_curve(pl, dome(), cv));
    if (out.back().status != Status::ok) return false;
  }
  return true;
}

// 11.54: the cubic Hermite basis functions.
bool fig_11_54(SvgWriter& w) {
  w.set_view({-0.12, -0.32}, {1.25, 1.12});
  w.arrow(Vec2d{0, 0}, Vec2d{1.12, 0}, pen(c::gray, 1));
  w.arrow(Vec2d{0, -0.25}, Vec2d{0, 1.08}, pen(c::gray, 1));
  label(w, Vec2d{1.12, 0}, "t", c::gray);
  const char* cols[4] = {c::blue, c::red, c::green, c::orange};
  const char* names[4] = {"h0", "h1", "h2", "h3"};
  const double at[4] = {0.2, 0.8, 0.25, 0.75};
  for (std::size_t k = 0; k < 4; ++k) {
    std::vector<Vec2d> pts;
    for (int i = 0; i <= 80; ++i) {
      const double t = i / 80.0;
      pts.push_back({t, hermite_basis(t)[k]});
    }
    w.polyline(pts, pen(cols[k], 2.2));
    label(w, Vec2d{at[k], hermite_basis(at[k])[k]}, names[k], cols[k]);
  }
  label(w, Vec2d{1.0, 0}, "1", c::gray, -4, -16);
  label(w, Vec2d{0, 1.0}, "1", c::gray, -14, -4);
  const auto b0 = hermite_basis(0.0), b1 = hermite_basis(1.0);
  return b0[0] == 1 && b1[1] == 1 && b0[1] == 0 && b1[0] == 0;
}

/// The index of the longest Hermite segment of a curve.
std::size_t longest_segment(const HermiteSurfaceCurve<double>& h) {
  std::size_t best = 0;
  double len = -1;
  for (std::size_t i = 0; i < segment_count(h); ++i) {
    const double l = length(h.points[(i + 1) % h.points.size()] - h.points[i]);
    if (l > len) {
      len = l;
      best = i;
    }
  }
  return best;
}

// 11.55: one Hermite segment of the traced curve, seen face-on in the plane: end points P0, P1,
// end derivatives L T0, L T1 (drawn at a third), the cubic against the chord and the true curve.
bool fig_11_55(SvgWriter& w) {
  std::vector<HermiteSurfaceCurve<double>> hs;
  Plane3<double> pl{};
  if (!dome_hermite(hs, pl)) return false;
  const HermiteSurfaceCurve<double>& h = hs[0];
  const std::size_t i = longest_segment(h), j = (i + 1) % h.points.size();
  const Vec3d p0 = h.points[i], p1 = h.points[j];
  const double len = length(p1 - p0);
  const Vec3d mid = 0.5 * (p0 + p1);
  w.set_camera(camera(mid + 10.0 * normalize(pl.normal), mid));
  // The true curve on this stretch: a fine trace.
  SurfaceCurveOptions fine;
  fine.grid = 64;
  for (const auto& cv : intersection(pl, dome(), fine).curves) {
    std::vector<Vec3d> near;
    for (const auto& x : cv.points)
      if (length(x - mid) < 0.9 * len) near.push_back(x);
    if (near.size() > 1) w.polyline(near, pen(c::light, 5));
  }
  std::vector<Vec3d> cubic;
  for (int k = 0; k <= 40; ++k) cubic.push_back(point_at(h, i, k / 40.0).point);
  w.segment(p0, p1, dashed(c::gray, 1.2));
  w.polyline(cubic, pen(c::red, 2.2));
  w.arrow(p0, p0 + (len / 3) * h.tangents[i], pen(c::blue, 1.8));
  w.arrow(p1, p1 + (len / 3) * h.tangents[j], pen(c::blue, 1.8));
  point(w, p0, "P0", c::black);
  point(w, p1, "P1", c::black);
  label(w, p0 + (len / 3) * h.tangents[i], "L T0 / 3", c::blue);
  label(w, p1 + (len / 3) * h.tangents[j], "L T1 / 3", c::blue);
  label(w, cubic[20], "R(t)", c::red, 6, 10);
  return std::fabs(length(h.tangents[i]) - 1) < 1e-12;
}

// 11.56: a subpatch (grid cell) of parameter space, drawn flat beside the patch, and its image on
// the patch; the curve's crossings of the cell boundary and its Hermite segment inside.
bool fig_11_56(SvgWriter& w) {
  std::vector<HermiteSurfaceCurve<double>> hs;
  Plane3<double> pl{};
  if (!dome_hermite(hs, pl)) return false;
  const HermiteSurfaceCurve<double>& h = hs[0];
  const std::size_t i = longest_segment(h), j = (i + 1) % h.points.size();
  const HermiteCurvePoint<double> m = point_at(h, i, 0.5);
  const double u0 = std::floor(m.param.x * 4) / 4, v0 = std::floor(m.param.y * 4) / 4;
  w.set_camera(camera({4, -9, 7}, {1.2, 0, 0}));
  const BezierPatch<double, 3> p = dome();
  wireframe(w, p, 0, 1, 0, 1, c::light, 4);
  // Parameter space: the unit square at x in [2.5, 5.5], z = -1.
  const auto flat = [](const Vec2d& uv) { return Vec3d{2.5 + 3 * uv.x, -1.5 + 3 * uv.y, -1}; };
  closed(w, std::vector<Vec3d>{flat({0, 0}), flat({1, 0}), flat({1, 1}), flat({0, 1})},
         pen(c::gray, 1));
  for (int k = 1; k < 4; ++k) {
    w.segment(flat({k / 4.0, 0}), flat({k / 4.0, 1}), pen(c::light, 0.6));
    w.segment(flat({0, k / 4.0}), flat({1, k / 4.0}), pen(c::light, 0.6));
  }
  label(w, flat({0, 0}), "(u, v) space", c::gray, -10, -18);
  const std::array<Vec2d, 4> cell = {Vec2d{u0, v0}, Vec2d{u0 + 0.25, v0},
                                     Vec2d{u0 + 0.25, v0 + 0.25}, Vec2d{u0, v0 + 0.25}};
  std::vector<Vec3d> flat_cell, image;
  for (std::size_t e = 0; e < 4; ++e) {
    flat_cell.push_back(flat(cell[e]));
    for (int k = 0; k < 10; ++k) {
      const Vec2d uv = cell[e] + (k / 10.0) * (cell[(e + 1) % 4] - cell[e]);
      image.push_back(point_at(p, uv.x, uv.y));
    }
  }
  closed(w, flat_cell, filled(c::blue, 0.3));
  closed(w, image, filled(c::blue, 0.3));
  w.arrow(flat(cell[2]), point_at(p, cell[2].x, cell[2].y), dashed(c::blue, 1));
  std::vector<Vec3d> seg3, seg2;
  for (int k = 0; k <= 30; ++k) {
    const HermiteCurvePoint<double> q = point_at(h, i, k / 30.0);
    seg3.push_back(q.point);
    seg2.push_back(flat(q.param));
  }
  w.polyline(seg3, pen(c::red, 2.4));
  w.polyline(seg2, pen(c::red, 2.4));
  for (const std::size_t k : {i, j}) {
    point(w, h.points[k], "", c::red);
    point(w, flat(h.params[k]), "", c::red);
  }
  label(w, seg2.back(), "p(t)", c::red);
  label(w, seg3.back(), "R(t)", c::red);
  // The segment's ends lie on the cell's boundary.
  const auto on_cell = [&](const Vec2d& uv) {
    return uv.x >= u0 - 1e-12 && uv.x <= u0 + 0.25 + 1e-12 && uv.y >= v0 - 1e-12 &&
           uv.y <= v0 + 0.25 + 1e-12;
  };
  return on_cell(h.params[i]) && on_cell(h.params[j]);
}

// 11.57: the 3-space intersection curve R(t): the traced points, their tangents and the
// piecewise Hermite curve through them (a coarse grid, so the points are sparse).
bool fig_11_57(SvgWriter& w) {
  std::vector<HermiteSurfaceCurve<double>> hs;
  Plane3<double> pl{};
  if (!dome_hermite(hs, pl)) return false;
  w.set_camera(camera({5, -7, 6}, {0, 0, 0.6}));
  wireframe(w, dome(), 0, 1, 0, 1, c::gray, 8);
  plane_patch(w, pl, {0, 0, 0.75}, 1.2, c::blue);
  double worst = 0;
  for (const auto& h : hs) {
    std::vector<Vec3d> pts;
    for (std::size_t i = 0; i < segment_count(h); ++i)
      for (int k = 0; k < 12; ++k) {
        const HermiteCurvePoint<double> q = point_at(h, i, k / 12.0);
        pts.push_back(q.point);
        worst = std::max(
            worst, std::fabs(dot(normalize(pl.normal), q.point) - pl.constant / length(pl.normal)));
      }
    if (!h.closed) pts.push_back(h.points.back());
    w.polyline(pts, pen(c::red, 2.4), h.closed);
    for (std::size_t i = 0; i < h.points.size(); ++i) {
      point(w, h.points[i], "", c::black);
      w.arrow(h.points[i], h.points[i] + 0.35 * h.tangents[i], pen(c::green, 1.2));
    }
  }
  label(w, hs[0].points[0], "R(t)", c::red, 8, 12);
  return worst < 1e-12;
}

}  // namespace

std::vector<Figure> chapter11_intersection_figures() {
  return {
      {"11.1", "intersection(Line3, Plane3)", fig_11_1},
      {"11.2", "intersection(Ray3, Triangle3), watertight_hit", fig_11_2},
      {"11.3", "intersection(Ray3, PlanarPolygon3), intersection(Ray3, Plane3)", fig_11_3},
      {"11.4", "intersection(Line3 / Segment3, Disk3) (point, empty, chord)", fig_11_4},
      {"11.5", "intersection(Ray3, ConvexPolyhedron3) (octahedron faces)", fig_11_5},
      {"11.6", "Bvh::all_hits (segment as ray with tmax = 1) on an icosphere", fig_11_6},
      {"11.7", "intersection(Line3, ConvexPolyhedron3) per face: half-lines", fig_11_7},
      {"11.8", "intersection(Line3, ConvexPolyhedron3): empty common part", fig_11_8},
      {"11.9", "intersection(Ray3, Sphere3) (two, tangent, none, from inside)", fig_11_9},
      {"11.10", "intersection(Line3, Ellipsoid3)", fig_11_10},
      {"11.11", "intersection(Ray3, Cylinder3) (side and cap)", fig_11_11},
      {"11.12", "intersection(Ray3, Cylinder3) (general position)", fig_11_12},
      {"11.13", "intersection(Line3, Cone3) (finite cone)", fig_11_13},
      {"11.14", "intersection(Line3, Cone3) (general position)", fig_11_14},
      {"11.15", "intersection(Line3, Cone3) (acute infinite cone)", fig_11_15},
      {"11.16", "intersection(Line3, Cone3) (double cone: four hits)", fig_11_16},
      {"11.17", "intersection(Line3, Quadric3) (c2 = 0: one point, or on the surface)", fig_11_17},
      {"11.18", "intersection(Ray3, NurbsSurface) (hits and normals)", fig_11_18},
      {"11.19", "intersection(Ray3, BezierPatch) vs Bvh::all_hits of its tessellation", fig_11_19},
      {"11.20", "perpendicular_basis: the ray as two planes", fig_11_20},
      {"11.21", "to_bezier, subdivide_u/v, intersects(Ray3, AlignedBox3): leaf boxes", fig_11_21},
      {"11.22", "to_bezier, subdivide_u/v: the coarser level of the hierarchy", fig_11_22},
      {"11.23", "intersection(Plane3, Plane3)", fig_11_23},
      {"11.24", "intersection(Plane3, Plane3, Plane3) (every configuration)", fig_11_24},
      {"11.25", "intersection(Triangle3, Plane3)", fig_11_25},
      {"11.26", "intersection(Triangle3, Plane3) (every configuration)", fig_11_26},
      {"11.27", "intersection(Triangle3, Triangle3)", fig_11_27},
      {"11.28", "intersection(Triangle3, Plane3) intervals, intersection(Triangle3, Triangle3)",
       fig_11_28},
      {"11.29", "slice_mesh(vertices, triangles, Plane3)", fig_11_29},
      {"11.30", "intersection(polygon, Plane3) (U-shaped polygon: two pieces)", fig_11_30},
      {"11.31", "intersection(polygon, Triangle3)", fig_11_31},
      {"11.32", "intersection(Plane3, Sphere3) (circle)", fig_11_32},
      {"11.33", "intersection(Plane3, Sphere3) (circle, point, empty)", fig_11_33},
      {"11.34", "intersection(Plane3, Cylinder3) (ellipse)", fig_11_34},
      {"11.35", "intersection(Plane3, Cylinder3) (circle, two lines, one line, empty)", fig_11_35},
      {"11.36", "intersection(Plane3, Cylinder3) edge-on: a = r / cos", fig_11_36},
      {"11.37", "PlaneConic3 ellipse: center, axes, extents", fig_11_37},
      {"11.38", "intersection(Plane3, Sphere3): circle center, normal, axes, radius", fig_11_38},
      {"11.39", "intersection(Plane3, Cylinder3) foci: Dandelin spheres checked on the axis",
       fig_11_39},
      {"11.40", "intersection(Plane3, Cylinder3) foci: Dandelin spheres, cross section", fig_11_40},
      {"11.41", "intersection(Plane3, Cylinder3) (circle: normal along the axis)", fig_11_41},
      {"11.42", "intersection(Plane3, Cone3)", fig_11_42},
      {"11.43", "intersection(Plane3, Cone3) (ellipse, hyperbolas)", fig_11_43},
      {"11.44", "intersection(Plane3, Cone3): meets the nappe or not", fig_11_44},
      {"11.45", "intersection(Plane3, Cone3) edge-on: major axis on two generators", fig_11_45},
      {"11.46", "intersection(Line3, Cone3): A.(X - V) = |X - V| cos(alpha)", fig_11_46},
      {"11.47", "intersection(Plane3, Cone3): hyperbola and exact parabola foci", fig_11_47},
      {"11.48", "intersection(Plane3, Cone3) (near-parabolic, type decided exactly)", fig_11_48},
      {"11.49", "intersection(Plane3, Cone3) (circle)", fig_11_49},
      {"11.50", "intersection(Plane3, Cone3) (ellipse)", fig_11_50},
      {"11.51", "intersection(Plane3, Cone3) (hyperbola)", fig_11_51},
      {"11.52", "intersection(Plane3, Cone3) (through the vertex: two lines)", fig_11_52},
      {"11.53", "intersection(Plane3, BezierPatch) (traced curves)", fig_11_53},
      {"11.54", "hermite_basis", fig_11_54},
      {"11.55", "hermite_curve, point_at(HermiteSurfaceCurve): one segment", fig_11_55},
      {"11.56", "hermite_curve: a subpatch and its image, p(t) and R(t)", fig_11_56},
      {"11.57", "hermite_curve: tangents and the Hermite curve R(t)", fig_11_57},
      {"11.58", "intersection(Plane3, BezierPatch): curves in parameter space", fig_11_58},
      {"11.59", "intersection(BSplineSurface, BSplineSurface)", fig_11_59},
      {"11.60", "intersection(BSplineSurface, BSplineSurface): param_a curves", fig_11_60},
      {"11.61", "intersection(Line3, AlignedBox3)", fig_11_61},
      {"11.62", "side_of_plane(AlignedBox3, Plane3) (slab planes)", fig_11_62},
      {"11.63", "intersection(Line3, ConvexPolyhedron3) (one slab)", fig_11_63},
      {"11.64", "intersection(Ray3, AlignedBox3) (slab clipping)", fig_11_64},
      {"11.65", "OrientedBox3, corners", fig_11_65},
      {"11.66", "intersection(Line3, OrientedBox3)", fig_11_66},
      {"11.67", "side_of_plane(AlignedBox3, Plane3)", fig_11_67},
      {"11.68", "side_of_plane(AlignedBox3, Plane3) (extreme corners)", fig_11_68},
      {"11.69", "side_of_plane(OrientedBox3, Plane3)", fig_11_69},
      {"11.70", "corners(OrientedBox3), side_of_plane(OrientedBox3, Plane3)", fig_11_70},
      {"11.71", "intersection(AlignedBox3, AlignedBox3)", fig_11_71},
      {"11.72", "intersects(OrientedBox3, OrientedBox3) (separating axes)", fig_11_72},
      {"11.73", "intersects(AlignedBox3, Sphere3)", fig_11_73},
      {"11.74", "intersection(Line3, Torus3) (four hits, normals)", fig_11_74},
      {"11.75", "intersection(Ray3, Torus3): the normal at a hit", fig_11_75},
      {"11.76", "intersection(Line3, Torus3): the u parameter", fig_11_76},
      {"11.77", "intersection(Line3, Torus3): the v parameter", fig_11_77},
  };
}

}  // namespace locus_gallery
