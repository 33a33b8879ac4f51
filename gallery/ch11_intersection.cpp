// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 11 (intersection in 3D). Every intersection point, parameter, hit, side and
// separating-axis answer shown is computed by a locus::intersection / intersects / side_of_plane
// query on the literal inputs; the 3D scenes are projected through the SvgWriter camera.
// Figures: linear component and plane (11.1), line and triangle with barycentrics (11.2),
// linear components and quadrics (11.9-11.17), a ray and a NURBS surface with the refinement
// hierarchy (11.18, 11.20-11.22), two and three planes (11.23, 11.24),
// plane-triangle, triangle-triangle and plane-mesh (11.25-11.27, 11.29), plane sections of
// sphere, cylinder and cone (11.32-11.52), plane and parametric surface (11.53, 11.58), two
// B-spline surfaces (11.59, 11.60), slabs and boxes (11.61-11.73), linear component and
// torus (11.74-11.77).
#include "gallery.hpp"

#include <locus/intersection/aligned_box_aligned_box.hpp>
#include <locus/intersection/aligned_box_plane.hpp>
#include <locus/intersection/aligned_box_sphere.hpp>
#include <locus/intersection/line_aligned_box.hpp>
#include <locus/intersection/line_capsule.hpp>
#include <locus/intersection/line_cone.hpp>
#include <locus/intersection/line_cylinder.hpp>
#include <locus/intersection/line_ellipsoid.hpp>
#include <locus/intersection/line_oriented_box.hpp>
#include <locus/intersection/line_plane.hpp>
#include <locus/intersection/line_quadric.hpp>
#include <locus/intersection/line_sphere.hpp>
#include <locus/intersection/line_torus.hpp>
#include <locus/intersection/line_triangle.hpp>
#include <locus/intersection/oriented_box_oriented_box.hpp>
#include <locus/intersection/oriented_box_plane.hpp>
#include <locus/intersection/plane_cone.hpp>
#include <locus/intersection/plane_cylinder.hpp>
#include <locus/intersection/plane_mesh.hpp>
#include <locus/intersection/plane_plane.hpp>
#include <locus/intersection/plane_sphere.hpp>
#include <locus/intersection/plane_surface.hpp>
#include <locus/intersection/plane_triangle.hpp>
#include <locus/intersection/ray_aligned_box.hpp>
#include <locus/intersection/ray_cone.hpp>
#include <locus/intersection/ray_cylinder.hpp>
#include <locus/intersection/ray_sphere.hpp>
#include <locus/intersection/ray_surface.hpp>
#include <locus/intersection/ray_torus.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/intersection/segment_plane.hpp>
#include <locus/intersection/surface_surface.hpp>
#include <locus/intersection/triangle_triangle.hpp>
#include <locus/io/svg_primitives.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/sphere.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
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

}  // namespace

std::vector<Figure> chapter11_intersection_figures() {
  return {
      {"11.1", "intersection(Line3, Plane3)", fig_11_1},
      {"11.2", "intersection(Ray3, Triangle3), watertight_hit", fig_11_2},
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
      {"11.20", "perpendicular_basis: the ray as two planes", fig_11_20},
      {"11.21", "to_bezier, subdivide_u/v, intersects(Ray3, AlignedBox3): leaf boxes", fig_11_21},
      {"11.22", "to_bezier, subdivide_u/v: the coarser level of the hierarchy", fig_11_22},
      {"11.23", "intersection(Plane3, Plane3)", fig_11_23},
      {"11.24", "intersection(Plane3, Plane3, Plane3) (every configuration)", fig_11_24},
      {"11.25", "intersection(Triangle3, Plane3)", fig_11_25},
      {"11.26", "intersection(Triangle3, Plane3) (every configuration)", fig_11_26},
      {"11.27", "intersection(Triangle3, Triangle3)", fig_11_27},
      {"11.29", "slice_mesh(vertices, triangles, Plane3)", fig_11_29},
      {"11.32", "intersection(Plane3, Sphere3) (circle)", fig_11_32},
      {"11.33", "intersection(Plane3, Sphere3) (circle, point, empty)", fig_11_33},
      {"11.34", "intersection(Plane3, Cylinder3) (ellipse)", fig_11_34},
      {"11.35", "intersection(Plane3, Cylinder3) (circle, two lines, one line, empty)", fig_11_35},
      {"11.37", "PlaneConic3 ellipse: center, axes, extents", fig_11_37},
      {"11.41", "intersection(Plane3, Cylinder3) (circle: normal along the axis)", fig_11_41},
      {"11.42", "intersection(Plane3, Cone3)", fig_11_42},
      {"11.43", "intersection(Plane3, Cone3) (ellipse, hyperbolas)", fig_11_43},
      {"11.48", "intersection(Plane3, Cone3) (near-parabolic, type decided exactly)", fig_11_48},
      {"11.49", "intersection(Plane3, Cone3) (circle)", fig_11_49},
      {"11.50", "intersection(Plane3, Cone3) (ellipse)", fig_11_50},
      {"11.51", "intersection(Plane3, Cone3) (hyperbola)", fig_11_51},
      {"11.52", "intersection(Plane3, Cone3) (through the vertex: two lines)", fig_11_52},
      {"11.53", "intersection(Plane3, BezierPatch) (traced curves)", fig_11_53},
      {"11.58", "intersection(Plane3, BezierPatch): curves in parameter space", fig_11_58},
      {"11.59", "intersection(BSplineSurface, BSplineSurface)", fig_11_59},
      {"11.60", "intersection(BSplineSurface, BSplineSurface): param_a curves", fig_11_60},
      {"11.61", "intersection(Line3, AlignedBox3)", fig_11_61},
      {"11.62", "side_of_plane(AlignedBox3, Plane3) (slab planes)", fig_11_62},
      {"11.64", "intersection(Ray3, AlignedBox3) (slab clipping)", fig_11_64},
      {"11.65", "OrientedBox3, corners", fig_11_65},
      {"11.66", "intersection(Line3, OrientedBox3)", fig_11_66},
      {"11.67", "side_of_plane(AlignedBox3, Plane3)", fig_11_67},
      {"11.68", "side_of_plane(AlignedBox3, Plane3) (extreme corners)", fig_11_68},
      {"11.69", "side_of_plane(OrientedBox3, Plane3)", fig_11_69},
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
