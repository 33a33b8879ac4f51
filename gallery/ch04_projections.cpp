// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 4 (projections and normals): figures 4.26-4.34. Projected points are images
// under locus's projection matrices (orthographic_projection, oblique_projection,
// perspective_projection via apply_projective); cross-ratios come from locus::cross_ratio,
// transformed normals from locus::apply_normal / normal_from_tangents.
#include "gallery.hpp"

#include <locus/core/frame.hpp>
#include <locus/core/products.hpp>
#include <locus/core/projection.hpp>
#include <locus/core/transform.hpp>
#include <locus/primitives/plane.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

std::string fmt(double x, int prec = 3) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, x);
  return buf;
}

// A rectangle of the plane through p with normal n, half-sizes a x b (locus::plane_frame).
std::vector<Vec3d> plane_quad(const Vec3d& p, const Vec3d& n, double a, double b) {
  const auto f = plane_frame(p, n);
  if (!f) return {};
  return {to_world(*f, Vec2d{-a, -b}), to_world(*f, Vec2d{a, -b}), to_world(*f, Vec2d{a, b}),
          to_world(*f, Vec2d{-a, b})};
}

const std::vector<Vec3d> object3{
    {0.3, 1.6, 0.4}, {1.3, 2.2, 0.6}, {0.9, 2.0, 1.6}, {0.2, 2.6, 1.2}};

// Projects every vertex with a homogeneous matrix; false when a point has no image.
bool project_all(const Mat4d& m, const std::vector<Vec3d>& pts, std::vector<Vec3d>& out) {
  out.clear();
  for (const Vec3d& p : pts) {
    const std::optional<Vec3d> q = apply_projective(m, p);
    if (!q) return false;
    out.push_back(*q);
  }
  return true;
}

bool projection_figure(SvgWriter& w, const std::optional<Mat4d>& m, const Vec3d* eye) {
  if (!m) return false;
  w.set_camera(camera({7, 2.5, 3.5}, {0, 1, 0.5}));
  const Vec3d p{0, 0, 0}, n{0, 1, 0};
  closed(w, plane_quad(p, n, 2.2, 1.6), filled(c::gray, 0.08, 1));
  std::vector<Vec3d> img;
  if (!project_all(*m, object3, img)) return false;
  closed(w, object3, filled(c::blue, 0.2));
  closed(w, img, filled(c::red, 0.25));
  for (std::size_t i = 0; i < object3.size(); ++i)
    w.segment(eye ? *eye : object3[i], img[i], dashed(c::gray, 1));
  if (eye) point(w, *eye, "eye");
  return true;
}

// 4.26: orthographic projection onto the plane y = 0.
bool fig_4_26(SvgWriter& w) {
  return projection_figure(w, orthographic_projection(Vec3d{0, 0, 0}, Vec3d{0, 1, 0}), nullptr);
}
// 4.27: oblique projection along a direction not parallel to the normal.
bool fig_4_27(SvgWriter& w) {
  return projection_figure(
      w, oblique_projection(Vec3d{0, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0.6, 1, -0.3}), nullptr);
}

// 4.28: an oblique projection seen edge-on: the 2D projection onto a line.
bool fig_4_28(SvgWriter& w) {
  const Vec2d p{0, 0}, n{0, 1}, d{0.7, 1};
  const auto m = oblique_projection(p, n, d);
  if (!m) return false;
  w.line(p, perp(n), pen(c::black, 1.2));
  const std::vector<Vec2d> obj{{0.4, 1.0}, {1.6, 1.6}, {1.0, 2.4}};
  closed(w, obj, filled(c::blue, 0.2));
  for (const Vec2d& q : obj) {
    const std::optional<Vec2d> r = apply_projective(*m, q);
    if (!r) return false;
    w.arrow(q, *r, dashed(c::gray, 1));
    w.point(*r, dot(c::red));
  }
  vector(w, Vec2d{-1.2, 0}, Vec2d{-1.2, 0} + normalize(n), "n", c::black);
  vector(w, Vec2d{-0.6, 1.4}, Vec2d{-0.6, 1.4} - normalize(d), "projection direction", c::green);
  return true;
}

// 4.29: perspective projection from an eye point.
bool fig_4_29(SvgWriter& w) {
  const Vec3d eye{0.6, 5.0, 1.0};
  return projection_figure(w, perspective_projection(eye, Vec3d{0, 0, 0}, Vec3d{0, 1, 0}), &eye);
}

// 4.30: the cross-ratio of four collinear points survives a perspective projection.
bool fig_4_30(SvgWriter& w) {
  const Vec2d eye{0, 3.5};
  const auto m = perspective_projection(eye, Vec2d{0, 0}, Vec2d{0, 1});  // onto y = 0
  if (!m) return false;
  const Vec2d a0{-1.5, 1.2}, dir{1.0, 0.35};
  const double ts[] = {0.0, 0.8, 1.5, 2.6};
  const char* names[] = {"A", "B", "C", "D"};
  std::array<Vec2d, 4> pts{}, img{};
  w.line(Vec2d{0, 0}, Vec2d{1, 0}, pen(c::black, 1.2));
  w.segment(a0 - 0.3 * dir, a0 + 3.0 * dir, pen(c::blue, 1.2));
  for (int i = 0; i < 4; ++i) {
    pts[static_cast<std::size_t>(i)] = a0 + ts[i] * dir;
    const std::optional<Vec2d> q = apply_projective(*m, pts[static_cast<std::size_t>(i)]);
    if (!q) return false;
    img[static_cast<std::size_t>(i)] = *q;
    w.segment(eye, *q, dashed(c::light, 1));
    point(w, pts[static_cast<std::size_t>(i)], names[i], c::blue);
    point(w, *q, std::string(names[i]) + "'", c::red);
  }
  point(w, eye, "eye");
  const auto r0 = cross_ratio(pts[0], pts[1], pts[2], pts[3]);
  const auto r1 = cross_ratio(img[0], img[1], img[2], img[3]);
  if (!r0 || !r1) return false;
  label(w, Vec2d{-2.2, -0.7}, "(A,B;C,D) = " + fmt(*r0) + ",   (A',B';C',D') = " + fmt(*r1),
        c::black, 0, 0);
  return true;
}

// 4.31: a perspective map does not preserve the midpoint of a segment.
bool fig_4_31(SvgWriter& w) {
  const Vec2d eye{0, 3.0};
  const auto m = perspective_projection(eye, Vec2d{0, 0}, Vec2d{0, 1});
  if (!m) return false;
  const Vec2d a{-1.6, 0.8}, b{1.8, 2.0}, mid = lerp(a, b, 0.5);
  const auto ia = apply_projective(*m, a), ib = apply_projective(*m, b),
             im = apply_projective(*m, mid);
  if (!ia || !ib || !im) return false;
  w.line(Vec2d{0, 0}, Vec2d{1, 0}, pen(c::black, 1.2));
  w.arrow(a, b, pen(c::blue));
  for (const auto& [p, q] : {std::pair{a, *ia}, std::pair{b, *ib}, std::pair{mid, *im}})
    w.segment(eye, q, dashed(c::light, 1));
  w.arrow(*ia, *ib, pen(c::red));
  point(w, mid, "midpoint M", c::blue);
  point(w, *im, "image of M", c::red);
  w.point(lerp(*ia, *ib, 0.5), dot(c::green));
  label(w, lerp(*ia, *ib, 0.5), "midpoint of the image", c::green, 5, -18);
  point(w, eye, "eye");
  return true;
}

// 4.32: the plane x + y = k with its normal (1, 1, 0) (locus::Plane3, closest_to_origin).
bool fig_4_32(SvgWriter& w) {
  w.set_camera(camera({6, 5, 3.5}));
  const Plane3<double> pl{{1, 1, 0}, 2.0};  // n . X = k
  const Vec3d p0 = closest_to_origin(pl);
  axes3(w, 2.6, c::gray);
  closed(w, plane_quad(p0, pl.normal, 1.8, 1.2), filled(c::blue, 0.15, 1));
  w.arrow(p0, p0 + normalize(pl.normal), pen(c::red));
  label(w, p0 + normalize(pl.normal), "n = (1, 1, 0)", c::red);
  point(w, p0, "x + y = " + fmt(p0.x + p0.y, 1), c::blue);
  w.segment(Vec3d{0, 0, 0}, p0, dashed(c::gray, 1));
  return true;
}

// 4.33: transforming a normal like a vector breaks perpendicularity; locus::apply_normal keeps it.
bool fig_4_33(SvgWriter& w) {
  const Affine2d s = scaling_axes(Vec2d{0, 0}, Vec2d{2.5, 1.0});
  const Vec2d a{0, 0}, b{1, 1}, mid = lerp(a, b, 0.5);
  const Vec2d n = normalize(perp(b - a));
  w.segment(a, b, pen(c::blue, 2));
  vector(w, mid, mid + 0.8 * n, "n", c::blue);
  const Vec2d ta = apply_point(s, a) + Vec2d{2, 0}, tb = apply_point(s, b) + Vec2d{2, 0};
  const Vec2d tm = lerp(ta, tb, 0.5);
  w.segment(ta, tb, pen(c::black, 2));
  const Vec2d wrong = normalize(apply_vector(s, n)), right = normalize(apply_normal(s, n));
  vector(w, tm, tm + 0.8 * wrong, "M n (wrong)", c::red, 14);
  vector(w, tm, tm + 0.8 * right, "normal_matrix \u00b7 n", c::green, -14);
  right_angle_mark(w, tm, tb - ta, right, 0.12);
  return true;
}

// 4.34: the normal as the cross product of surface tangents, before and after a transform
// (locus::normal_from_tangents).
bool fig_4_34(SvgWriter& w) {
  w.set_camera(camera({6, 3, 3}));
  const Vec3d p{0, 0, 0}, t0{1.2, 0, 0.2}, t1{0.2, 1.2, 0};
  const Vec3d n = normal_from_tangents(t0, t1);
  closed(w, std::vector<Vec3d>{p, p + t0, p + t0 + t1, p + t1}, filled(c::gray, 0.1, 1));
  w.arrow(p, p + t0, pen(c::blue));
  w.arrow(p, p + t1, pen(c::blue));
  w.arrow(p, p + normalize(n), pen(c::green));
  label(w, p + normalize(n), "t\u2080 \u00d7 t\u2081", c::green);
  const Affine3d a =
      compose(translation(Vec3d{0, 2.8, 0}), scaling_axes(Vec3d{0, 0, 0}, Vec3d{1.6, 0.6, 1}));
  const Vec3d q = apply_point(a, p), s0 = apply_vector(a, t0), s1 = apply_vector(a, t1);
  const Vec3d m = normal_from_tangents(a, t0, t1);
  closed(w, std::vector<Vec3d>{q, q + s0, q + s0 + s1, q + s1}, filled(c::gray, 0.1, 1));
  w.arrow(q, q + s0, pen(c::red));
  w.arrow(q, q + s1, pen(c::red));
  w.arrow(q, q + normalize(m), pen(c::green));
  label(w, q + normalize(m), "M t\u2080 \u00d7 M t\u2081", c::green);
  return true;
}

}  // namespace

std::vector<Figure> chapter4_projection_figures() {
  return {
      {"4.26", "orthographic_projection, apply_projective", fig_4_26},
      {"4.27", "oblique_projection, apply_projective", fig_4_27},
      {"4.28", "oblique_projection (2D), apply_projective", fig_4_28},
      {"4.29", "perspective_projection, apply_projective", fig_4_29},
      {"4.30", "perspective_projection (2D), cross_ratio", fig_4_30},
      {"4.31", "perspective_projection (2D), lerp", fig_4_31},
      {"4.32", "Plane3, closest_to_origin, plane_frame", fig_4_32},
      {"4.33", "scaling_axes, apply_vector vs apply_normal", fig_4_33},
      {"4.34", "normal_from_tangents (plain and transformed)", fig_4_34},
  };
}

}  // namespace locus_gallery
