// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 12 (miscellaneous 3D problems). Every projected point and vector, every angle
// and every constructed plane shown is computed by construct/misc3.hpp on the literal inputs;
// the 3D scenes are projected through the SvgWriter camera.
// Figures: projections (12.1-12.3), angles (12.4, 12.5, 12.9, 12.10), planes (12.6-12.8).
#include "gallery.hpp"

#include <locus/construct/misc3.hpp>
#include <locus/io/svg.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/plane.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

std::string deg(double radians) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.1f deg", radians * 180.0 / std::numbers::pi);
  return buf;
}

// A square patch of the plane around the projection of `at` (half size h).
void plane_patch(SvgWriter& w, const Plane3<double>& pl, const Vec3d& at, double h,
                 const char* colour) {
  const auto f = plane_frame(pl);
  if (!f) return;
  const Vec3d o = project_point(at, pl);
  closed(w,
         std::vector<Vec3d>{o + (-h) * f->u + (-h) * f->v, o + h * f->u + (-h) * f->v,
                            o + h * f->u + h * f->v, o + (-h) * f->u + h * f->v},
         filled(colour, 0.10, 1));
}

// The normal arrow of a plane drawn at `at` (on the plane), labelled n.
void normal_arrow(SvgWriter& w, const Plane3<double>& pl, const Vec3d& at, const char* colour) {
  const Vec3d n = normalize(pl.normal);
  w.arrow(at, at + n, pen(colour));
  label(w, at + n, "n", colour);
}

// 12.1: a point Q and its orthogonal projection Q' onto the plane.
bool fig_12_1(SvgWriter& w) {
  w.set_camera(camera({6, -5, 4}, {0, 0, 0.5}));
  const Plane3<double> pl{{0.2, 0.1, 1.0}, 0.2};
  const Vec3d q{0.6, 0.3, 2.2};
  const Vec3d qp = project_point(q, pl);
  plane_patch(w, pl, q, 1.8, c::blue);
  normal_arrow(w, pl, project_point(Vec3d{-1.0, -1.0, 0}, pl), c::blue);
  w.segment(q, qp, dashed(c::gray));
  point(w, q, "Q", c::red);
  point(w, qp, "Q'", c::black);
  return std::abs(signed_distance(pl, qp)) < 1e-12;
}

// 12.2: a vector v and its projection v' onto the plane (parallel to it).
bool fig_12_2(SvgWriter& w) {
  w.set_camera(camera({6, -5, 4}, {0, 0, 0.5}));
  const Plane3<double> pl{{0.0, 0.3, 1.0}, 0.0};
  const Vec3d o = project_point(Vec3d{-0.5, -0.5, 0}, pl);
  const Vec3d v{1.6, 0.8, 1.5};
  const Vec3d vp = project_vector(v, pl);
  plane_patch(w, pl, o, 1.8, c::blue);
  normal_arrow(w, pl, project_point(Vec3d{-1.3, 0.8, 0}, pl), c::blue);
  w.arrow(o, o + v, pen(c::red, 2));
  label(w, o + v, "v", c::red);
  w.arrow(o, o + vp, pen(c::black, 2));
  label(w, o + vp, "v'", c::black);
  w.segment(o + v, o + vp, dashed(c::gray));
  return std::abs(dot(vp, pl.normal)) < 1e-12;
}

// 12.3: u projected onto v.
bool fig_12_3(SvgWriter& w) {
  w.set_camera(camera({2, -6, 3}, {1, 0, 0.5}));
  const Vec3d o{0, 0, 0}, u{1.2, 0.3, 1.6}, v{2.5, 0.4, 0.2};
  const Vec3d p = project_vector(u, v);
  w.arrow(o, v, pen(c::blue, 2));
  label(w, v, "v", c::blue);
  w.arrow(o, u, pen(c::red, 2));
  label(w, u, "u", c::red);
  w.arrow(o, p, pen(c::black, 2.5));
  label(w, p, "u'", c::black, 5, -15);
  w.segment(u, p, dashed(c::gray));
  return length(cross(p, v)) < 1e-12;
}

// 12.4: the angle between a line and a plane (the complement of the angle with the normal).
bool fig_12_4(SvgWriter& w) {
  w.set_camera(camera({6, -5, 3}, {0, 0, 0.5}));
  const Plane3<double> pl{{0, 0, 1}, 0};
  const Line3<double> l{{0, 0, 0}, {1.0, 0.6, 1.2}};
  const double a = angle_between(l, pl);
  plane_patch(w, pl, l.origin, 1.8, c::blue);
  normal_arrow(w, pl, l.origin, c::blue);
  w.segment(point_at(l, -0.6), point_at(l, 1.4), pen(c::red, 2));
  label(w, point_at(l, 1.4), "L", c::red);
  const Vec3d shadow = project_vector(l.direction, pl);
  w.segment(l.origin, l.origin + 1.2 * shadow, dashed(c::gray));
  label(w, l.origin + 0.6 * (normalize(shadow) + normalize(l.direction)), "theta = " + deg(a),
        c::black);
  return a > 0 && a < std::numbers::pi / 2;
}

// 12.5: the angle between two planes, measured between their normals.
bool fig_12_5(SvgWriter& w) {
  w.set_camera(camera({6, -6, 3}, {0, 0, 0}));
  const Plane3<double> a{{0, 0, 1}, 0}, b{{0.9, 0, 1}, 0};
  const double t = angle_between(a, b);
  plane_patch(w, a, {0, 0, 0}, 1.5, c::blue);
  plane_patch(w, b, {0, 0, 0}, 1.5, c::green);
  normal_arrow(w, a, {0, -1, 0}, c::blue);
  normal_arrow(w, b, {0, -1, 0}, c::green);
  label(w, Vec3d{0, -1, 1.2}, "theta = " + deg(t), c::black);
  return std::abs(t - acute_angle(a, b)) < 1e-15;
}

// 12.6: the plane through P normal to the line L.
bool fig_12_6(SvgWriter& w) {
  w.set_camera(camera({6, -5, 3}, {0, 0, 0.5}));
  const Line3<double> l{{-1.2, -0.4, -0.6}, {0.8, 0.3, 1.0}};
  const Vec3d p{0.4, 0.2, 0.6};
  const PlaneResult<double> r = plane_normal_to_line(l, p);
  if (r.status != Status::ok) return false;
  plane_patch(w, r.plane, p, 1.4, c::blue);
  w.segment(point_at(l, -0.2), point_at(l, 2.8), pen(c::red, 2));
  label(w, point_at(l, 2.8), "L", c::red);
  point(w, p, "P", c::black);
  return std::abs(acute_angle(l, r.plane) - std::numbers::pi / 2) < 1e-12;
}

// 12.7: the distance coefficient d = -n . P (constant = n . P): the plane's offset from the origin.
bool fig_12_7(SvgWriter& w) {
  w.set_camera(camera({6, -5, 3}, {0, 0, 0.8}));
  const Line3<double> l{{0, 0, 0}, {0.3, 0.2, 1.0}};
  const Vec3d p{0.5, -0.3, 1.4};
  const PlaneResult<double> r = plane_normal_to_line(l, p);
  if (r.status != Status::ok) return false;
  axes3(w, 1.0);
  plane_patch(w, r.plane, p, 1.2, c::blue);
  const Vec3d foot = project_point(Vec3d{0, 0, 0}, r.plane);
  w.segment(Vec3d{0, 0, 0}, foot, dashed(c::red));
  point(w, p, "P", c::black);
  point(w, foot, "", c::red);
  char buf[96];
  std::snprintf(buf, sizeof(buf), "d = -n.P = %.2f, |d|/|n| = %.2f", -r.plane.constant,
                std::abs(r.plane.constant) / length(r.plane.normal));
  label(w, foot, buf, c::red);
  return std::abs(length(foot) - std::abs(r.plane.constant) / length(r.plane.normal)) < 1e-12;
}

// 12.8: the plane through three points, normal (P1 - P0) x (P2 - P0).
bool fig_12_8(SvgWriter& w) {
  w.set_camera(camera({5, -6, 4}, {0.5, 0.5, 0.3}));
  const Vec3d p0{0, 0, 0.2}, p1{2, 0.3, 0.5}, p2{0.4, 1.8, 0.1};
  const PlaneResult<double> r = plane_through_points(p0, p1, p2);
  if (r.status != Status::ok) return false;
  plane_patch(w, r.plane, (p0 + p1 + p2) / 3.0, 1.6, c::blue);
  closed(w, std::vector<Vec3d>{p0, p1, p2}, pen(c::black, 1.2));
  point(w, p0, "P0", c::black);
  point(w, p1, "P1", c::black);
  point(w, p2, "P2", c::black);
  normal_arrow(w, r.plane, (p0 + p1 + p2) / 3.0, c::red);
  return true;
}

// 12.9 / 12.10: the angle between two lines, and with one line reversed (pi minus it).
bool lines_figure(SvgWriter& w, bool reversed) {
  w.set_camera(camera({4, -6, 4}, {0, 0, 0}));
  const Line3<double> a{{0, 0, 0}, {1.5, 0.2, 0.4}};
  Line3<double> b{{0, 0, 0}, {0.4, 1.2, 0.9}};
  if (reversed) b.direction = -b.direction;
  const double t = angle_between(a, b);
  w.segment(point_at(a, -1.0), point_at(a, 1.2), pen(c::blue, 1.5));
  w.segment(point_at(b, -1.2), point_at(b, 1.2), pen(c::green, 1.5));
  w.arrow(a.origin, point_at(a, 1.0), pen(c::blue, 2.2));
  w.arrow(b.origin, point_at(b, 1.0), pen(c::green, 2.2));
  label(w, point_at(a, 1.0), "d0", c::blue);
  label(w, point_at(b, 1.0), reversed ? "-d1" : "d1", c::green);
  label(w, 0.5 * (normalize(a.direction) + normalize(b.direction)), "theta = " + deg(t), c::black);
  return std::abs(acute_angle(a, b) - std::min(t, std::numbers::pi - t)) < 1e-15;
}
bool fig_12_9(SvgWriter& w) { return lines_figure(w, false); }
bool fig_12_10(SvgWriter& w) { return lines_figure(w, true); }

}  // namespace

std::vector<Figure> chapter12_misc_figures() {
  return {
      {"12.1", "project_point(Vec3, Plane3)", fig_12_1},
      {"12.2", "project_vector(Vec3, Plane3)", fig_12_2},
      {"12.3", "project_vector(Vec3, Vec3)", fig_12_3},
      {"12.4", "angle_between(Line3, Plane3)", fig_12_4},
      {"12.5", "angle_between(Plane3, Plane3)", fig_12_5},
      {"12.6", "plane_normal_to_line(Line3, Vec3)", fig_12_6},
      {"12.7", "plane_normal_to_line (constant n.P), project_point", fig_12_7},
      {"12.8", "plane_through_points(Vec3, Vec3, Vec3)", fig_12_8},
      {"12.9", "angle_between(Line3, Line3)", fig_12_9},
      {"12.10", "angle_between(Line3, Line3) (one line reversed)", fig_12_10},
  };
}

}  // namespace locus_gallery
