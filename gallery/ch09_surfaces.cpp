// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 9 (polynomial curves and surfaces in 3D): figures 9.22-9.26, drawn through the
// SvgWriter camera (locus's look_at / orthographic pipeline). Curve and surface points come from
// locus::point_at (de Casteljau for Bézier curves, rectangle and triangle patches; de Boor for
// B-spline curves and surfaces), end tangents from derivative_at, normals from normal_at.
#include "gallery.hpp"

#include <locus/core/vec.hpp>
#include <locus/curves/bezier.hpp>
#include <locus/curves/bezier_surface.hpp>
#include <locus/curves/bspline.hpp>
#include <locus/curves/bspline_surface.hpp>

#include <cstdio>
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

const Vec3d eye{9, -11, 7};

// The control net of a rows x cols tensor-product surface (row-major), dashed.
void control_net(SvgWriter& w, const std::vector<Vec3d>& ctrl, int rows, int cols) {
  const auto at = [&](int i, int j) {
    return ctrl[static_cast<std::size_t>(i) * static_cast<std::size_t>(cols) +
                static_cast<std::size_t>(j)];
  };
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      if (j + 1 < cols) w.segment(at(i, j), at(i, j + 1), dashed(c::gray, 1));
      if (i + 1 < rows) w.segment(at(i, j), at(i + 1, j), dashed(c::gray, 1));
      w.point(at(i, j), dot(c::black, 2.6));
    }
}

// Isoparametric curves u = const and v = const of a surface point_at(u, v) over [u0, u1] x
// [v0, v1]: `lines` + 1 of each, every one sampled at 48 points.
template <class Eval>
void isolines(SvgWriter& w, const Eval& eval, double u0, double u1, double v0, double v1, int lines,
              const SvgStyle& s) {
  const int samples = 48;
  for (int dir = 0; dir < 2; ++dir)
    for (int i = 0; i <= lines; ++i) {
      std::vector<Vec3d> pts;
      for (int k = 0; k <= samples; ++k) {
        const double a = static_cast<double>(i) / lines, b = static_cast<double>(k) / samples;
        const double u = dir == 0 ? u0 + a * (u1 - u0) : u0 + b * (u1 - u0);
        const double v = dir == 0 ? v0 + b * (v1 - v0) : v0 + a * (v1 - v0);
        pts.push_back(eval(u, v));
      }
      w.polyline(pts, s);
    }
}

// Drops a 3D point onto the xy-plane: the "shadow" that gives a space curve its depth.
Vec3d shadow(const Vec3d& p) { return {p.x, p.y, 0}; }

// 9.22: a cubic Bézier curve in 3D with its control polygon, and their shadows on the xy-plane.
bool fig_9_22(SvgWriter& w) {
  const BezierCurve3<double> bez{{{0, 0, 0}, {0.8, 3.0, 2.2}, {3.2, 0.4, 2.6}, {4.2, 2.6, 0.6}}};
  w.set_camera(camera(eye, {2.1, 1.3, 1.0}));
  axes3(w, 1.2);
  std::vector<Vec3d> pts, low, poly_low;
  for (int i = 0; i <= 96; ++i) {
    pts.push_back(point_at(bez, i / 96.0));
    low.push_back(shadow(pts.back()));
  }
  for (const Vec3d& p : bez.control) poly_low.push_back(shadow(p));
  w.polyline(poly_low, dashed(c::light, 1));
  w.polyline(low, pen(c::light, 1.6));
  for (const Vec3d& p : bez.control) w.segment(p, shadow(p), dashed(c::light, 0.8));
  w.polyline(bez.control, dashed(c::gray));
  w.polyline(pts, pen(c::blue, 2.4));
  for (std::size_t i = 0; i < 4; ++i) point(w, bez.control[i], "P" + std::to_string(i));
  // The curve leaves P0 towards P1 and arrives at P3 from P2: C'(0) = 3 (P1 - P0).
  const Vec3d d0 = derivative_at(bez, 0.0, 1);
  w.arrow(bez.control[0], bez.control[0] + d0 / 6.0, pen(c::red, 1.8));
  label(w, bez.control[0] + d0 / 6.0, "C'(0)/6", c::red, -60, 0);
  return true;
}

// 9.23: a cubic B-spline curve in 3D (open uniform knots) with its control polygon, the images
// of its knots (which separate its polynomial pieces) and the shadows on the xy-plane.
bool fig_9_23(SvgWriter& w) {
  const std::vector<Vec3d> ctrl{{0, 0, 0},       {0.6, 2.4, 1.8}, {2.0, 0.4, 2.6}, {3.0, 2.8, 0.4},
                                {4.4, 0.2, 1.2}, {5.0, 2.6, 2.4}, {6.2, 1.2, 0.6}};
  const int degree = 3;
  const BSplineCurve3<double> bs{degree, ctrl,
                                 open_uniform_knots<double>(static_cast<int>(ctrl.size()), degree)};
  if (validate(bs) != Status::ok) return false;
  w.set_camera(camera({5, -12, 6}, {3.1, 1.3, 1.0}));
  axes3(w, 1.2);
  const ParamDomain<double> dom = domain(bs);
  std::vector<Vec3d> pts, low, poly_low;
  for (int i = 0; i <= 200; ++i) {
    pts.push_back(point_at(bs, dom.min + (dom.max - dom.min) * i / 200.0));
    low.push_back(shadow(pts.back()));
  }
  for (const Vec3d& p : ctrl) {
    poly_low.push_back(shadow(p));
    w.segment(p, shadow(p), dashed(c::light, 0.8));
  }
  w.polyline(poly_low, dashed(c::light, 1));
  w.polyline(low, pen(c::light, 1.6));
  w.polyline(bs.control, dashed(c::gray));
  w.polyline(pts, pen(c::blue, 2.4));
  for (std::size_t i = 0; i < ctrl.size(); ++i) point(w, ctrl[i], "P" + std::to_string(i));
  for (std::size_t k = static_cast<std::size_t>(degree);
       k + static_cast<std::size_t>(degree) < bs.knots.size(); ++k) {
    const Vec3d p = point_at(bs, bs.knots[k]);
    w.point(p, dot(c::red, 3.5));
    w.text(p, "t = " + fmt(bs.knots[k]), text_style(c::red, 0, -20, SvgAnchor::middle, 12));
  }
  return true;
}

// A 4 x 4 net over the square [0, 3]^2 with varying heights (the input of 9.24 and 9.26).
std::vector<Vec3d> bicubic_net() {
  const double z[4][4] = {
      {0.0, 0.6, 0.4, 0.0}, {0.5, 2.2, 1.6, 0.3}, {0.2, 1.4, 2.4, 0.8}, {-0.2, 0.3, 0.9, 0.4}};
  std::vector<Vec3d> net;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) net.push_back({1.0 * i, 1.0 * j, z[i][j]});
  return net;
}

// 9.24: a bicubic Bézier patch, its control net and isoparametric curves; the corners
// interpolate P00, P03, P30, P33 and the normal at the centre comes from normal_at.
bool fig_9_24(SvgWriter& w) {
  const BezierPatch<double, 3> patch{4, 4, bicubic_net()};
  w.set_camera(camera(eye, {1.5, 1.5, 0.6}));
  control_net(w, patch.control, 4, 4);
  isolines(
      w, [&](double u, double v) { return point_at(patch, u, v); }, 0, 1, 0, 1, 10,
      pen(c::blue, 1.2));
  const Vec3d mid = point_at(patch, 0.5, 0.5), n = normal_at(patch, 0.5, 0.5);
  if (n == Vec3d{0, 0, 0}) return false;
  w.arrow(mid, mid + 1.2 * n, pen(c::red, 1.8));
  label(w, mid + 1.2 * n, "normal", c::red);
  for (int i : {0, 3})
    for (int j : {0, 3})
      label(w, patch.control[static_cast<std::size_t>(i * 4 + j)],
            "P" + std::to_string(i) + std::to_string(j));
  return true;
}

// 9.25: a cubic triangular Bézier patch: its ten control points P_ijk (i + j + k = 3) form the
// triangular net; the isoparametric curves u, v, w = const are drawn on the patch.
bool fig_9_25(SvgWriter& w) {
  const int n = 3;
  BezierTriangle<double, 3> tri{
      n, std::vector<Vec3d>(static_cast<std::size_t>(triangle_control_count(n)))};
  // P_ijk over the planar triangle with corners e1 = (3, 0), e2 = (0, 3), e3 = (0, 0) (the
  // barycentric grid), lifted by heights that bulge the interior.
  const double lift[4][4] = {
      {0.0, 0.5, 0.7, 0.2}, {0.6, 1.3, 0.4, 0}, {0.9, 0.8, 0, 0}, {0.3, 0, 0, 0}};  // lift[j][i]
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i) {
      const Vec3d p{1.0 * i + 0.5 * j, 0.9 * j, lift[j][i]};
      tri.control[static_cast<std::size_t>(triangle_index(n, i, j))] = p;
    }
  const auto P = [&](int i, int j) {
    return tri.control[static_cast<std::size_t>(triangle_index(n, i, j))];
  };
  w.set_camera(camera({5, -8, 9}, {1.5, 1.2, 0.5}));
  // The net: one triangle per (i, j, k) with i + j + k = n - 1.
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + j < n; ++i)
      closed(w, std::vector<Vec3d>{P(i + 1, j), P(i, j + 1), P(i, j)}, dashed(c::gray, 1));
  for (const Vec3d& p : tri.control) w.point(p, dot(c::black, 2.6));
  // Isoparametric curves of each barycentric coordinate.
  const int lines = 8, samples = 40;
  for (int which = 0; which < 3; ++which)
    for (int l = 0; l <= lines; ++l) {
      const double a = static_cast<double>(l) / lines;
      std::vector<Vec3d> pts;
      for (int k = 0; k <= samples; ++k) {
        const double b = (1 - a) * k / samples;
        const double u = which == 0 ? a : (which == 1 ? b : 1 - a - b);
        const double v = which == 0 ? b : (which == 1 ? a : b);
        pts.push_back(point_at(tri, u, v));
      }
      w.polyline(pts, pen(c::blue, 1.2));
    }
  label(w, P(3, 0), "P\u2083\u2080\u2080", c::black);
  label(w, P(0, 3), "P\u2080\u2083\u2080", c::black);
  label(w, P(0, 0), "P\u2080\u2080\u2083", c::black);
  const Vec3d centre = point_at(tri, 1.0 / 3, 1.0 / 3), nrm = normal_at(tri, 1.0 / 3, 1.0 / 3);
  if (nrm == Vec3d{0, 0, 0}) return false;
  w.arrow(centre, centre + 0.8 * nrm, pen(c::red, 1.8));
  label(w, centre + 0.8 * nrm, "normal", c::red);
  return true;
}

// 9.26: a uniform bicubic B-spline surface on a 6 x 6 net: with uniform knots the surface does not
// reach the border control points; its patches meet with C2 continuity (the knot lines drawn
// darker).
bool fig_9_26(SvgWriter& w) {
  const int rows = 6, cols = 6, d = 3;
  std::vector<Vec3d> net;
  const double z[6][6] = {{0.0, 0.3, 0.5, 0.4, 0.2, 0.0}, {0.3, 1.2, 1.6, 1.0, 0.6, 0.2},
                          {0.4, 1.6, 2.6, 1.8, 0.9, 0.3}, {0.2, 0.8, 1.6, 2.2, 1.4, 0.4},
                          {0.0, 0.4, 0.8, 1.2, 1.0, 0.3}, {-0.2, 0.0, 0.3, 0.4, 0.3, 0.0}};
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) net.push_back({0.8 * i, 0.8 * j, z[i][j]});
  const BSplineSurface<double, 3> s{
      d, d, rows, cols, net, uniform_knots<double>(rows, d), uniform_knots<double>(cols, d)};
  if (validate(s) != Status::ok) return false;
  const ParamDomain<double> du = domain_u(s), dv = domain_v(s);
  w.set_camera(camera(eye, {2.0, 2.0, 0.6}));
  control_net(w, s.control, rows, cols);
  const auto eval = [&](double u, double v) { return point_at(s, u, v); };
  isolines(w, eval, du.min, du.max, dv.min, dv.max, 12, pen(c::blue, 0.9));
  // The knot lines: the boundaries of the (rows - 3) x (cols - 3) polynomial patches.
  isolines(w, eval, du.min, du.max, dv.min, dv.max, rows - d, pen(c::blue, 2));
  label(w, s.control[0], "P00", c::black);
  label(w, point_at(s, du.min, dv.min), "S(" + fmt(du.min, 0) + ", " + fmt(dv.min, 0) + ")",
        c::blue, 6, -16);
  return true;
}

}  // namespace

std::vector<Figure> chapter9_surface_figures() {
  return {
      {"9.22", "BezierCurve3 point_at (de Casteljau), derivative_at (end tangents)", fig_9_22},
      {"9.23", "BSplineCurve3 open_uniform_knots, validate, domain, point_at (de Boor)", fig_9_23},
      {"9.24", "BezierPatch point_at (isoparametric curves), normal_at", fig_9_24},
      {"9.25",
       "BezierTriangle triangle_index, point_at (barycentric isoparametric curves), "
       "normal_at",
       fig_9_25},
      {"9.26", "BSplineSurface uniform_knots, validate, domain_u/v, point_at (de Boor)", fig_9_26},
  };
}

}  // namespace locus_gallery
