// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 4 (frames and affine transformations): figures 4.1-4.25. Frame coordinates
// come from locus::to_local_* / to_world_*, every transformed shape is the image under a locus
// transform factory (translation, rotation, scaling, reflection, shear).
#include "gallery.hpp"

#include <locus/core/angle.hpp>
#include <locus/core/frame.hpp>
#include <locus/core/products.hpp>
#include <locus/core/transform.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

std::string fmt(double x, int prec = 2) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, x);
  return buf;
}
std::string fmt(const Vec2d& v) { return coordinates(v.x, v.y); }

const Frame3d world3 = Frame3d::identity();

// 4.1: P = p1 i + p2 j + p3 k + O, the point from locus::to_world_point.
bool fig_4_1(SvgWriter& w) {
  w.set_camera(camera({6, 3.5, 3.5}));
  const Vec3d p_local{1.5, 2.0, 1.2};
  const Vec3d p = to_world_point(world3, p_local);
  frame(w, world3, c::black, "O", "i", "j", "k");
  const Vec3d a = world3.origin + p_local.x * world3.axis[0];
  const Vec3d b = a + p_local.y * world3.axis[1];
  w.polyline(std::vector<Vec3d>{world3.origin, a, b, p}, dashed(c::gray));
  point(w, p, "P = [1.5 2 1.2 1]", c::red);
  return true;
}

// 4.2: v = v1 i + v2 j + v3 k, the vector from locus::to_world_vector.
bool fig_4_2(SvgWriter& w) {
  w.set_camera(camera({6, 3.5, 3.5}));
  const Vec3d v_local{1.5, 2.0, 1.2};
  const Vec3d v = to_world_vector(world3, v_local);
  frame(w, world3, c::black, "O", "i", "j", "k");
  const Vec3d a = v_local.x * world3.axis[0], b = a + v_local.y * world3.axis[1];
  w.polyline(std::vector<Vec3d>{Vec3d{}, a, b, v}, dashed(c::gray));
  w.arrow(Vec3d{}, v, pen(c::red));
  label(w, v, "v = [1.5 2 1.2 0]", c::red);
  return true;
}

// 4.3: the perp operator.
bool fig_4_3(SvgWriter& w) {
  const Vec2d v{2.0, 0.8};
  vector(w, Vec2d{0, 0}, v, "v", c::blue, -12);
  vector(w, Vec2d{0, 0}, perp(v), "v\u22a5", c::red);
  right_angle_mark(w, Vec2d{0, 0}, v, perp(v), 0.2);
  return true;
}

// 4.4: perp_dot(u, v) = |u||v| sin(theta) with the signed angle.
bool fig_4_4(SvgWriter& w) {
  const Vec2d o{0, 0}, u{2.2, 0.4}, v{0.9, 1.7}, v2{1.6, -1.2};
  vector(w, o, u, "u", c::blue, -12);
  vector(w, o, perp(u), "u\u22a5", c::gray);
  vector(w, o, v, "v", c::red);
  vector(w, o, v2, "v'", c::purple);
  angle_mark(w, o, u, v, 0.5);
  angle_mark(w, o, v2, u, 0.6);
  label(w, Vec2d{-0.4, -1.6},
        "u\u22a5\u00b7v = " + fmt(perp_dot(u, v)) +
            " (\u03b8 = " + fmt(to_degrees(signed_angle(u, v)), 1) +
            "\u00b0),  u\u22a5\u00b7v' = " + fmt(perp_dot(u, v2)) +
            " (\u03b8 = " + fmt(to_degrees(signed_angle(u, v2)), 1) + "\u00b0)",
        c::black, 0, 0);
  return true;
}

// 4.5: perp_dot(u, v) / 2 is the signed area of the triangle (0, u, v) (locus::signed_area).
bool fig_4_5(SvgWriter& w) {
  const Vec2d o{0, 0}, u{2.4, 0.4}, v{0.8, 1.6};
  const Triangle2<double> t{o, u, v};
  closed(w, std::vector<Vec2d>{o, u, u + v, v}, dashed(c::gray));
  closed(w, std::vector<Vec2d>{t.v0, t.v1, t.v2}, filled(c::green, 0.2));
  vector(w, o, u, "u", c::blue, -12);
  vector(w, o, v, "v", c::red);
  label(w, Vec2d{0.3, -0.4},
        "signed_area = " + fmt(signed_area(t)) +
            " = \u00bd u\u22a5\u00b7v = " + fmt(0.5 * perp_dot(u, v)),
        c::black, 0, 0);
  return true;
}

const Frame2d frame_a{{0.4, 0.3}, {Vec2d{1, 0}, Vec2d{0, 1}}};
Frame2d frame_b() {
  const Affine2d r = rotation_2d(0.5);
  return {{3.0, 0.8}, {apply_vector(r, Vec2d{1, 0}), apply_vector(r, Vec2d{0, 1})}};
}

// 4.6: the same point in two frames (locus::to_local_point).
bool fig_4_6(SvgWriter& w) {
  const Frame2d b = frame_b();
  const Vec2d p{2.2, 2.6};
  frame(w, frame_a, c::blue, "O\u1d2c", "", "");
  frame(w, b, c::red, "O\u1d2e", "", "");
  w.segment(frame_a.origin, p, dashed(c::blue, 1));
  w.segment(b.origin, p, dashed(c::red, 1));
  point(w, p, "P");
  label(w, p, "P\u1d2c = " + fmt(to_local_point(frame_a, p)), c::blue, 8, -14);
  label(w, p, "P\u1d2e = " + fmt(to_local_point(frame_b(), p)), c::red, 8, -30);
  return true;
}

// 4.7: the origin of frame B expressed in the global frame G.
bool fig_4_7(SvgWriter& w) {
  const Frame2d g = Frame2d::identity();
  const Frame2d b = frame_b();
  frame(w, g, c::black, "O\u1d33", "", "");
  frame(w, b, c::red, "", "", "");
  const Vec2d ob = to_local_point(g, b.origin);
  w.arrow(g.origin, to_world_point(g, ob), dashed(c::gray));
  point(w, b.origin, "O\u1d2e = " + fmt(ob) + " in G", c::red);
  return true;
}

// 4.8: the axes of frame A expressed in frame B (locus::to_local_vector).
bool fig_4_8(SvgWriter& w) {
  const Frame2d b = frame_b();
  frame(w, b, c::red, "O\u1d2e", "u\u2081", "u\u2082");
  const Frame2d a{b.origin + Vec2d{1.6, 0.2}, {Vec2d{1.0, 0.4}, Vec2d{-0.3, 0.9}}};
  frame(w, a, c::blue, "", "v\u2081", "v\u2082");
  const Vec2d c1 = to_local_vector(b, a.axis[0]), c2 = to_local_vector(b, a.axis[1]);
  label(w, a.origin + Vec2d{0, -0.5},
        "v\u2081 = " + fmt(c1) + "\u1d2e,  v\u2082 = " + fmt(c2) + "\u1d2e", c::blue, 0, 0);
  return true;
}

// 4.9: translation of a shape (locus::translation).
bool fig_4_9(SvgWriter& w) {
  const Vec2d t{2.5, 1.0};
  const Affine2d a = translation(t);
  const std::vector<Vec2d> h = house(Vec2d{0, 0}, 1.0);
  const std::vector<Vec2d> th = map_points(a, h);
  closed(w, h, filled(c::blue, 0.15));
  closed(w, th, filled(c::red, 0.15));
  for (std::size_t i : {0u, 1u, 3u}) w.arrow(h[i], th[i], dashed(c::gray, 1));
  return true;
}

Frame2d map_frame(const Affine2d& a, const Frame2d& f) {
  return {apply_point(a, f.origin), {apply_vector(a, f.axis[0]), apply_vector(a, f.axis[1])}};
}

// 4.10: translating a frame moves its origin, not its axes.
bool fig_4_10(SvgWriter& w) {
  const Affine2d a = translation(Vec2d{2.4, 1.2});
  const Frame2d f = Frame2d::identity();
  frame(w, f, c::blue, "O", "i", "j");
  frame(w, map_frame(a, f), c::red, "T(O)", "T(i)", "T(j)");
  w.arrow(f.origin, apply_point(a, f.origin), dashed(c::gray));
  return true;
}

// 4.11: rotating a frame about its origin.
bool fig_4_11(SvgWriter& w) {
  const double th = 0.6;
  const Affine2d r = rotation_2d(th);
  const Frame2d f = Frame2d::identity();
  const Frame2d g = map_frame(r, f);
  frame(w, f, c::blue, "O", "i", "j");
  frame(w, g, c::red, "", "R(i)", "R(j)");
  angle_mark(w, f.origin, f.axis[0], g.axis[0], 0.4, "\u03b8");
  angle_mark(w, f.origin, f.axis[1], g.axis[1], 0.3, "\u03b8");
  return true;
}

const std::vector<Vec3d> flag3{{1.6, 0.0, 0.0}, {1.6, 0.0, 1.0}, {2.2, 0.2, 0.8}, {1.6, 0.0, 0.6}};

// 4.12: rotation about an arbitrary axis (locus::rotation(point, axis, angle)); the orbit of a
// vertex is the set of its images under rotations by 0..angle.
bool fig_4_12(SvgWriter& w) {
  w.set_camera(camera({6, 4, 3}));
  const Vec3d q{0.2, 0.3, 0}, u{0.2, 0.3, 1};
  const double angle = 2.0;
  w.segment(q - 0.4 * u, q + 1.8 * u, pen(c::black, 1.2));
  w.arrow(q + 1.4 * u, q + 1.8 * u, pen(c::black, 1.2));
  label(w, q + 1.8 * u, "u", c::black);
  closed(w, flag3, filled(c::blue, 0.15));
  closed(w, map_points(rotation(q, u, angle), flag3), filled(c::red, 0.15));
  for (const Vec3d& v : {flag3[1], flag3[2]}) {
    std::vector<Vec3d> orbit;
    for (int i = 0; i <= 32; ++i) orbit.push_back(apply_point(rotation(q, u, angle * i / 32.0), v));
    w.polyline(orbit, dashed(c::gray, 1));
  }
  return true;
}

// 4.13: the same rotation seen in the plane through P perpendicular to u: P circles about its
// foot Q on the axis (Q = q + project_onto(P - q, u)).
bool fig_4_13(SvgWriter& w) {
  const Vec3d q{0.2, 0.3, 0}, u{0.2, 0.3, 1};
  const double angle = 2.0;
  const Vec3d p = flag3[2];
  const Vec3d foot = q + project_onto(p - q, u);
  const Vec3d rp = apply_point(rotation(q, u, angle), p);
  locus::SvgCamera cam = camera(foot + 5.0 * normalize(u), foot);
  cam.up = {1, 0, 0};
  w.set_camera(cam);
  std::vector<Vec3d> circle;
  for (int i = 0; i <= 64; ++i)
    circle.push_back(apply_point(rotation(q, u, 2 * pi_v<double> * i / 64.0), p));
  w.polyline(circle, pen(c::light, 1));
  std::vector<Vec3d> arc;
  for (int i = 0; i <= 24; ++i)
    arc.push_back(apply_point(rotation(q, u, angle * i / 24.0), p + 0.3 * (foot - p)));
  w.polyline(arc, pen(c::gray, 1));
  w.arrow(foot, p, pen(c::blue));
  w.arrow(foot, rp, pen(c::red));
  point(w, foot, "Q (u toward the viewer)");
  point(w, p, "P", c::blue);
  point(w, rp, "R(P)", c::red);
  label(w, arc[12], "\u03b8", c::gray);
  return true;
}

// 4.14: scaling a frame's axes (locus::scaling_axes).
bool fig_4_14(SvgWriter& w) {
  const Affine2d s = scaling_axes(Vec2d{0, 0}, Vec2d{2.0, 1.5});
  const Frame2d f = Frame2d::identity();
  frame(w, map_frame(s, f), c::red, "", "S(i)", "S(j)");
  frame(w, f, c::blue, "O", "i", "j");
  return true;
}

// 4.15: uniform scale about a centre: image points lie on rays from the centre.
bool fig_4_15(SvgWriter& w) {
  const Vec2d ctr{-0.5, -0.3};
  const Affine2d s = scaling(ctr, 1.8);
  const std::vector<Vec2d> h = house(Vec2d{0, 0}, 1.0);
  const std::vector<Vec2d> sh = map_points(s, h);
  for (std::size_t i = 0; i < h.size(); i += 3) w.segment(ctr, sh[i], dashed(c::light, 1));
  closed(w, h, filled(c::blue, 0.15));
  closed(w, sh, filled(c::red, 0.1));
  point(w, ctr, "centre");
  return true;
}

// 4.16: nonuniform scale along a direction (locus::scaling_along).
bool fig_4_16(SvgWriter& w) {
  const Vec2d ctr{0, 0}, dir{1, 0.6};
  const Affine2d s = scaling_along(ctr, dir, 2.0);
  const std::vector<Vec2d> h = house(Vec2d{0.2, -0.2}, 1.0);
  w.line(ctr, dir, dashed(c::gray, 1));
  closed(w, h, filled(c::blue, 0.15));
  closed(w, map_points(s, h), filled(c::red, 0.1));
  vector(w, ctr, ctr + normalize(dir), "scale 2 along d", c::green);
  return true;
}

// Mirror figures: shape, mirror, image and the connectors of corresponding points.
void mirror2(SvgWriter& w, const Affine2d& m, const Vec2d& p, const Vec2d& d,
             const std::vector<Vec2d>& h) {
  w.line(p, d, pen(c::black, 1.2));
  const std::vector<Vec2d> mh = map_points(m, h);
  closed(w, h, filled(c::blue, 0.15));
  closed(w, mh, filled(c::red, 0.15));
  for (std::size_t i = 0; i < h.size(); i += 2) w.segment(h[i], mh[i], dashed(c::light, 1));
}

// 4.17: a mirror image across a line (locus::reflection with the line's normal).
bool fig_4_17(SvgWriter& w) {
  const Vec2d p{0, 0}, d{1, 1.5};
  mirror2(w, reflection(p, perp(d)), p, d, house(Vec2d{0.6, -0.4}, 1.0));
  return true;
}

// 4.18: simple reflection in 2D: about the x axis.
bool fig_4_18(SvgWriter& w) {
  mirror2(w, reflection(Vec2d{0, 0}, Vec2d{0, 1}), Vec2d{0, 0}, Vec2d{1, 0},
          house(Vec2d{0.4, 0.3}, 1.0));
  label(w, Vec2d{1.8, 0}, "x", c::black);
  return true;
}

// 4.19: the book's simple 3D reflection about a coordinate axis (locus::reflection_about_line).
bool fig_4_19(SvgWriter& w) {
  w.set_camera(camera({5, 6, 3.5}));
  axes3(w, 2.4, c::gray);
  const Affine3d m = reflection_about_line(Vec3d{0, 0, 0}, Vec3d{1, 0, 0});
  closed(w, flag3, filled(c::blue, 0.15));
  const std::vector<Vec3d> mf = map_points(m, flag3);
  closed(w, mf, filled(c::red, 0.15));
  for (std::size_t i = 0; i < flag3.size(); ++i) w.segment(flag3[i], mf[i], dashed(c::light, 1));
  return true;
}

// 4.20: reflection in a general plane (locus::reflection(point, normal)).
bool fig_4_20(SvgWriter& w) {
  w.set_camera(camera({6, 4, 3}));
  const Vec3d p{0, 0, 0}, n{0.3, 1, 0.4};
  const auto pf = plane_frame(p, n);
  if (!pf) return false;
  std::vector<Vec3d> quad;
  for (const Vec2d& s : {Vec2d{-2, -1.5}, Vec2d{2, -1.5}, Vec2d{2, 1.5}, Vec2d{-2, 1.5}})
    quad.push_back(to_world(*pf, s));
  closed(w, quad, filled(c::gray, 0.08, 1));
  w.arrow(p, p + normalize(n), pen(c::black, 1.4));
  label(w, p + normalize(n), "n", c::black);
  const std::vector<Vec3d> tri{{0.5, 1.2, 0.4}, {1.4, 1.0, 0.9}, {0.8, 1.6, 1.5}};
  const std::vector<Vec3d> mt = map_points(reflection(p, n), tri);
  closed(w, tri, filled(c::blue, 0.2));
  closed(w, mt, filled(c::red, 0.2));
  for (std::size_t i = 0; i < 3; ++i) w.segment(tri[i], mt[i], dashed(c::gray, 1));
  return true;
}

// 4.21: mirror image in 2D about a line (locus::reflection_about_line).
bool fig_4_21(SvgWriter& w) {
  const Vec2d p{0.5, 0}, d{0.4, 1};
  mirror2(w, reflection_about_line(p, d), p, d, house(Vec2d{1.0, 0.2}, 1.0));
  return true;
}

// 4.22: mirror image in 3D: a tetrahedron reflected in a plane.
bool fig_4_22(SvgWriter& w) {
  w.set_camera(camera({6, -5, 3}));
  const Vec3d p{0, 0, 0}, n{1, 0, 0};
  closed(w, std::vector<Vec3d>{{0, -1.5, -0.5}, {0, 2, -0.5}, {0, 2, 2}, {0, -1.5, 2}},
         filled(c::gray, 0.08, 1));
  const std::vector<Vec3d> tet{{0.8, 0, 0}, {2.0, 0.2, 0}, {1.2, 1.2, 0}, {1.3, 0.5, 1.4}};
  const std::vector<Vec3d> mt = map_points(reflection(p, n), tet);
  for (const auto* t : {&tet, &mt})
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j)
        w.segment((*t)[i], (*t)[j], pen(t == &tet ? c::blue : c::red));
  w.point(tet[3], dot(c::blue));
  w.point(mt[3], dot(c::red));
  return true;
}

// 4.23: shear in 2D (locus::shear(point, dir, angle)).
bool fig_4_23(SvgWriter& w) {
  const double th = 0.5;
  const Affine2d s = shear(Vec2d{0, 0}, Vec2d{1, 0}, th);
  const std::vector<Vec2d> sq{{0, 0}, {1.5, 0}, {1.5, 1.5}, {0, 1.5}};
  const std::vector<Vec2d> ss = map_points(s, sq);
  closed(w, sq, filled(c::blue, 0.15));
  closed(w, ss, filled(c::red, 0.15));
  angle_mark(w, Vec2d{0, 0}, Vec2d{0, 1}, ss[3], 0.5, "\u03b8");
  return true;
}

// 4.24: the 3D shear T_xy,theta: a cube sheared parallel to the xy plane (locus::shear with the
// z normal and a direction in the xy plane).
bool fig_4_24(SvgWriter& w) {
  w.set_camera(camera({6, 3.5, 3}));
  const Affine3d s = shear(Vec3d{0, 0, 0}, Vec3d{0, 0, 1}, Vec3d{1, 1, 0}, 0.6);
  std::array<Vec3d, 8> cube{}, sheared{};
  for (std::size_t i = 0; i < 8; ++i) {
    cube[i] = Vec3d{i & 1 ? 1.0 : 0.0, i & 2 ? 1.0 : 0.0, i & 4 ? 1.0 : 0.0};
    sheared[i] = apply_point(s, cube[i]);
  }
  axes3(w, 1.6, c::light);
  box_edges(w, cube, dashed(c::blue, 1));
  box_edges(w, sheared, pen(c::red, 1.5));
  return true;
}

// 4.25: the general shear: fixed line through P with normal n, direction w, angle theta.
bool fig_4_25(SvgWriter& w) {
  const Vec2d p{0, 0}, n{0.3, 1}, d{1, -0.2};
  const double th = 0.55;
  const Affine2d s = shear(p, n, d, th);
  w.line(p, perp(n), pen(c::black, 1.2));
  const std::vector<Vec2d> h = house(Vec2d{-0.6, 0.1}, 1.2);
  closed(w, h, filled(c::blue, 0.15));
  closed(w, map_points(s, h), filled(c::red, 0.15));
  vector(w, p, p + normalize(n), "n", c::black);
  const Vec2d wdir = apply_vector(s, normalize(n)) - normalize(n);
  vector(w, p, p + normalize(wdir), "w", c::green, -12);
  angle_mark(w, p, apply_vector(s, n), n, 0.45, "\u03b8");
  return true;
}

}  // namespace

std::vector<Figure> chapter4_transform_figures() {
  return {
      {"4.1", "Frame3, to_world_point", fig_4_1},
      {"4.2", "Frame3, to_world_vector", fig_4_2},
      {"4.3", "perp", fig_4_3},
      {"4.4", "perp_dot, signed_angle", fig_4_4},
      {"4.5", "Triangle2 signed_area, perp_dot", fig_4_5},
      {"4.6", "to_local_point in two frames", fig_4_6},
      {"4.7", "to_local_point, to_world_point", fig_4_7},
      {"4.8", "to_local_vector", fig_4_8},
      {"4.9", "translation", fig_4_9},
      {"4.10", "translation applied to a frame (apply_point, apply_vector)", fig_4_10},
      {"4.11", "rotation_2d applied to a frame", fig_4_11},
      {"4.12", "rotation(point, axis, angle) in 3D", fig_4_12},
      {"4.13", "rotation(point, axis, angle), project_onto", fig_4_13},
      {"4.14", "scaling_axes applied to a frame", fig_4_14},
      {"4.15", "scaling(center, s)", fig_4_15},
      {"4.16", "scaling_along(center, dir, s)", fig_4_16},
      {"4.17", "reflection(point, normal) in 2D", fig_4_17},
      {"4.18", "reflection about the x axis", fig_4_18},
      {"4.19", "reflection_about_line in 3D", fig_4_19},
      {"4.20", "reflection(point, normal) in 3D, plane_frame", fig_4_20},
      {"4.21", "reflection_about_line in 2D", fig_4_21},
      {"4.22", "reflection(point, normal) of a tetrahedron", fig_4_22},
      {"4.23", "shear(point, dir, angle)", fig_4_23},
      {"4.24", "shear(point, normal, dir, angle) in 3D", fig_4_24},
      {"4.25", "shear(point, normal, dir, angle) in 2D", fig_4_25},
  };
}

}  // namespace locus_gallery
