// SPDX-License-Identifier: BSL-1.0
// Gallery, appendix A (numerical methods): figures A.1-A.24 except the conceptual A.5 and A.6.
// Level curves are locus::level_set (marching squares) of the sampled function; critical points
// come from locus::critical_points (polynomials: roots of p'), critical_points_1d (sign changes
// of f', cusps included) and critical_points_2d (Newton on grad f = 0, classified by the
// Hessian's eigenvalues); constrained extrema from locus::minimize_quadratic_on_sphere /
// maximize_quadratic_on_sphere and eigen_symmetric (Lagrange's condition). Graphs of functions
// of two variables are drawn as 3D wireframes through the SvgWriter camera.
#include "gallery.hpp"

#include <locus/core/mat.hpp>
#include <locus/core/products.hpp>
#include <locus/core/projection.hpp>
#include <locus/core/transform.hpp>
#include <locus/numeric/calculus.hpp>
#include <locus/numeric/decompose.hpp>
#include <locus/numeric/eigen_sym.hpp>
#include <locus/numeric/minimize.hpp>
#include <locus/numeric/polynomial.hpp>
#include <locus/numeric/roots.hpp>
#include <locus/primitives/cylinder.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/sphere.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

constexpr double nan_v = std::numeric_limits<double>::quiet_NaN();

std::string fmt(double x, int prec = 2) {
  if (std::abs(x) < 0.5 * std::pow(10.0, -prec)) x = 0;  // no "-0.00"
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, x);
  return buf;
}

std::string coords3(const Vec3d& p, int prec = 0) {
  return "(" + fmt(p.x, prec) + ", " + fmt(p.y, prec) + ", " + fmt(p.z, prec) + ")";
}

const char* kind_name(CriticalKind k) {
  switch (k) {
    case CriticalKind::minimum:
      return "minimum";
    case CriticalKind::maximum:
      return "maximum";
    case CriticalKind::saddle:
      return "saddle";
    case CriticalKind::inflection:
      return "inflection";
    case CriticalKind::degenerate:
      break;
  }
  return "degenerate";
}

const char* kind_colour(CriticalKind k) {
  switch (k) {
    case CriticalKind::minimum:
      return c::blue;
    case CriticalKind::maximum:
      return c::red;
    case CriticalKind::saddle:
      return c::green;
    case CriticalKind::inflection:
      return c::purple;
    case CriticalKind::degenerate:
      break;
  }
  return c::gray;
}

// ---- graphs of functions of one variable ------------------------------------------------------

// A graph window: data (x, y) is drawn at world origin + (x sx, y sy), so functions with very
// different x and y ranges still fit the SvgWriter's uniform scale; tick labels show data values.
struct Plot {
  double x0, x1, y0, y1;  // data window
  double sx = 1, sy = 1;
  Vec2d origin{0, 0};
  [[nodiscard]] Vec2d at(double x, double y) const {
    return {origin.x + x * sx, origin.y + y * sy};
  }
};

// Axes through the data origin (or along the window's edge when 0 is outside), with ticks every
// xtick / ytick data units (0 for none).
void plot_axes(SvgWriter& w, const Plot& p, double xtick, double ytick, int xprec = 0,
               int yprec = 0) {
  const double ay = p.y0 <= 0 && 0 <= p.y1 ? 0.0 : p.y0;
  const double ax = p.x0 <= 0 && 0 <= p.x1 ? 0.0 : p.x0;
  w.arrow(p.at(p.x0, ay), p.at(p.x1, ay), pen(c::gray, 1));
  w.arrow(p.at(ax, p.y0), p.at(ax, p.y1), pen(c::gray, 1));
  const double tick = 0.012 * ((p.x1 - p.x0) * p.sx + (p.y1 - p.y0) * p.sy);
  if (xtick > 0)
    for (double k = std::ceil(p.x0 / xtick); k * xtick < p.x1 - 0.4 * xtick; k += 1) {
      const double x = k * xtick;
      if (x == ax) continue;
      const Vec2d q = p.at(x, ay);
      w.segment(q - Vec2d{0, tick}, q + Vec2d{0, tick}, pen(c::gray, 1));
      w.text(q, fmt(x, xprec), text_style(c::gray, 0, -16, SvgAnchor::middle, 11));
    }
  if (ytick > 0)
    for (double k = std::ceil(p.y0 / ytick); k * ytick < p.y1 - 0.4 * ytick; k += 1) {
      const double y = k * ytick;
      if (y == ay) continue;
      const Vec2d q = p.at(ax, y);
      w.segment(q - Vec2d{tick, 0}, q + Vec2d{tick, 0}, pen(c::gray, 1));
      w.text(q, fmt(y, yprec), text_style(c::gray, -6, -4, SvgAnchor::end, 11));
    }
}

void plot_curve(SvgWriter& w, const Plot& p, const std::function<double(double)>& f, double a,
                double b, const SvgStyle& s, int n = 240) {
  // Samples outside the window's y range are cut away (SvgWriter::curve splits at NaN).
  w.curve(
      [&](double x) {
        const double y = f(x);
        return y >= p.y0 && y <= p.y1 ? p.at(x, y) : Vec2d{nan_v, nan_v};
      },
      a, b, n, s);
}

// ---- functions of two variables ---------------------------------------------------------------

using Fn2 = std::function<double(Vec2d)>;

// The graph z = zscale f(x, y) over [lo, hi] as a wireframe of lines x = const and y = const.
// Values outside [zmin, zmax] (display units) are cut away: the polyline is split there.
void graph_wireframe(SvgWriter& w, const Fn2& f, const Vec2d& lo, const Vec2d& hi, int lines,
                     double zscale, const SvgStyle& s, double zmin = -1e300, double zmax = 1e300) {
  const int samples = 60;
  for (int dir = 0; dir < 2; ++dir)
    for (int i = 0; i <= lines; ++i) {
      std::vector<Vec3d> pts;
      for (int k = 0; k <= samples; ++k) {
        const double a = static_cast<double>(i) / lines, b = static_cast<double>(k) / samples;
        const Vec2d q = dir == 0 ? Vec2d{lo.x + a * (hi.x - lo.x), lo.y + b * (hi.y - lo.y)}
                                 : Vec2d{lo.x + b * (hi.x - lo.x), lo.y + a * (hi.y - lo.y)};
        const double z = zscale * f(q);
        pts.push_back({q.x, q.y, z >= zmin && z <= zmax ? z : nan_v});
      }
      w.polyline(pts, s);
    }
}

// The rectangle [lo, hi] at height z.
void rect3(SvgWriter& w, const Vec2d& lo, const Vec2d& hi, double z, const SvgStyle& s) {
  closed(w, std::vector<Vec3d>{{lo.x, lo.y, z}, {hi.x, lo.y, z}, {hi.x, hi.y, z}, {lo.x, hi.y, z}},
         s);
}

std::vector<Vec3d> lift(const std::vector<Vec2d>& pts, double z) {
  std::vector<Vec3d> out;
  for (const Vec2d& p : pts) out.push_back({p.x, p.y, z});
  return out;
}

// Draws the level set f = level of a sampled function; its contours go to `out` if given.
// False when marching squares reports a problem.
bool draw_level(SvgWriter& w, const ScalarGrid<double>& g, double level, const SvgStyle& s,
                LevelSet<double>* out = nullptr) {
  LevelSet<double> ls = level_set(g, level);
  if (ls.status != Status::ok || ls.contours.empty()) return false;
  for (const auto& ct : ls.contours) w.polyline(ct.points, s, ct.closed);
  if (out) *out = std::move(ls);
  return true;
}

// The same level set lifted to height z = zscale * level in 3D.
bool draw_level_3d(SvgWriter& w, const ScalarGrid<double>& g, double level, double zscale,
                   const SvgStyle& s) {
  const LevelSet<double> ls = level_set(g, level);
  if (ls.status != Status::ok || ls.contours.empty()) return false;
  for (const auto& ct : ls.contours) w.polyline(lift(ct.points, zscale * level), s, ct.closed);
  return true;
}

// The contour point with the largest x + y: a tidy place for a level label.
Vec2d label_spot(const LevelSet<double>& ls) {
  Vec2d best{nan_v, nan_v};
  double score = -1e300;
  for (const auto& ct : ls.contours)
    for (const Vec2d& p : ct.points)
      if (p.x + 0.3 * p.y > score) {
        score = p.x + 0.3 * p.y;
        best = p;
      }
  return best;
}

// A sum of Gaussian bumps a exp(-|x - c|^2 / s): hills (a > 0) and valleys (a < 0), with its
// exact gradient and Hessian for critical_points_2d.
struct Bump {
  double a;
  Vec2d center;
  double s;
};

double bumps_f(const std::vector<Bump>& bs, const Vec2d& x) {
  double v = 0;
  for (const Bump& b : bs) v += b.a * std::exp(-sqr_length(x - b.center) / b.s);
  return v;
}
Vec2d bumps_grad(const std::vector<Bump>& bs, const Vec2d& x) {
  Vec2d g{0, 0};
  for (const Bump& b : bs) {
    const Vec2d d = x - b.center;
    g += (b.a * std::exp(-sqr_length(d) / b.s) * (-2 / b.s)) * d;
  }
  return g;
}
Mat2d bumps_hess(const std::vector<Bump>& bs, const Vec2d& x) {
  double hxx = 0, hxy = 0, hyy = 0;
  for (const Bump& b : bs) {
    const Vec2d d = x - b.center;
    const double e = b.a * std::exp(-sqr_length(d) / b.s), k = 4 / (b.s * b.s);
    hxx += e * (k * d.x * d.x - 2 / b.s);
    hyy += e * (k * d.y * d.y - 2 / b.s);
    hxy += e * k * d.x * d.y;
  }
  return Mat2d::from_rows(Vec2d{hxx, hxy}, Vec2d{hxy, hyy});
}

CriticalPoints2<double> bumps_critical(const std::vector<Bump>& bs, const Vec2d& lo,
                                       const Vec2d& hi) {
  return critical_points_2d([&](Vec2d x) { return bumps_f(bs, x); },
                            [&](Vec2d x) { return bumps_grad(bs, x); },
                            [&](Vec2d x) { return bumps_hess(bs, x); }, lo, hi);
}

// Marks critical points on a 3D graph (display height zscale f).
void mark_critical_3d(SvgWriter& w, const CriticalPoints2<double>& cp, double zscale,
                      bool with_coordinates = false) {
  for (const auto& p : cp.points) {
    const Vec3d q{p.point.x, p.point.y, zscale * p.value};
    w.point(q, dot(kind_colour(p.kind), 4.5));
    std::string name = kind_name(p.kind);
    if (with_coordinates) name += " " + coordinates(p.point.x, p.point.y);
    label(w, q, name, kind_colour(p.kind), 6, 6);
  }
}

// A sampled circle of radius r about the origin (the input shape of figure A.1).
std::vector<Vec2d> circle_points(double r, int n = 96) {
  std::vector<Vec2d> pts;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * pi_v<double> * i / n;
    pts.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return pts;
}

std::vector<Vec2d> shifted(const std::vector<Vec2d>& pts, const Vec2d& by) {
  return map_points(translation(by), pts);
}

// ---- A.1 --------------------------------------------------------------------------------------

// A.1: the circle under "scale (2x, y), then rotate by pi/4" (top) and under "rotate, then scale"
// (bottom). The top ellipse's axes are the left singular vectors of the composite linear map
// (locus::svd), at 45 degrees: no axis-aligned scaling of the (rotation-invariant) circle
// produces it.
bool fig_A_1(SvgWriter& w) {
  const Affine2d scale = scaling_axes(Vec2d{0, 0}, Vec2d{2, 1});
  const Affine2d rot = rotation(Vec2d{0, 0}, pi_v<double> / 4);
  const std::vector<Vec2d> circle = circle_points(1);
  const Vec2d spoke{1, 0};  // a radius, so that the rotation of the circle is visible
  const Affine2d id = Affine2d::identity();
  // One row: the circle's images under the given maps, left to right, joined by labelled arrows.
  const auto row = [&](double y, const Affine2d(&maps)[3], const char*(&names)[2],
                       const char* col) {
    double x = 0, prev_right = 0;
    std::vector<Vec2d> centres;
    for (int k = 0; k < 3; ++k) {
      const std::vector<Vec2d> img = map_points(maps[k], circle);
      double lo = 1e300, hi = -1e300;
      for (const Vec2d& q : img) lo = std::min(lo, q.x), hi = std::max(hi, q.x);
      if (k > 0) {
        x = prev_right + 1.6 - lo;
        const Vec2d a{prev_right + 0.2, y}, b{x + lo - 0.2, y};
        w.arrow(a, b, pen(c::gray, 1.2));
        w.text(lerp(a, b, 0.5), names[k - 1], text_style(c::gray, 0, 6, SvgAnchor::middle, 13));
      }
      const Vec2d at{x, y};
      closed(w, shifted(img, at), filled(col, 0.12));
      w.segment(at, at + apply_vector(maps[k], spoke), pen(col, 1.2));
      prev_right = x + hi;
      centres.push_back(at);
    }
    return centres.back();
  };
  const Affine2d top_maps[3] = {id, scale, compose(rot, scale)};
  const Affine2d bottom_maps[3] = {id, rot, compose(scale, rot)};
  const char* top_names[2] = {"scale", "rotate"};
  const char* bottom_names[2] = {"rotate", "scale"};
  const Vec2d top_end = row(0, top_maps, top_names, c::blue);
  const Vec2d bottom_end = row(-3.4, bottom_maps, bottom_names, c::red);
  // Principal axes of the top ellipse: M = U diag(s) V^T, axes s_i u_i.
  const SVD<double> d = svd(MatX<double>(top_maps[2].linear));
  if (d.status != Status::ok || d.s.size() != 2) return false;
  for (int i = 0; i < 2; ++i) {
    const Vec2d u{d.u(0, i), d.u(1, i)};
    w.arrow(top_end, top_end + d.s[static_cast<std::size_t>(i)] * u, pen(c::green, 1.5));
  }
  double major_deg = std::atan2(d.u(1, 0), d.u(0, 0)) * 180 / pi_v<double>;
  if (major_deg < 0) major_deg += 180;  // an axis, not a direction
  w.text(top_end + Vec2d{0, -1.6},
         "SVD: axes " + fmt(d.s[0]) + ", " + fmt(d.s[1]) + " at " + fmt(major_deg, 0) + "\u00b0",
         text_style(c::green, 0, -6, SvgAnchor::middle, 13));
  w.text(bottom_end + Vec2d{0, -1.0}, "axes along x and y",
         text_style(c::red, 0, -10, SvgAnchor::middle, 13));
  return true;
}

// ---- A.2-A.4: level curves --------------------------------------------------------------------

const std::vector<Bump>& hill_a2() {
  static const std::vector<Bump> h{{1.0, {0.5, 0.1}, 1.6}, {0.55, {-0.9, 0.4}, 0.9}};
  return h;
}

// A.2: the graph of f cut by the plane z = 0.8; the cut is the level curve f = 0.8, drawn on the
// surface and projected onto the xy-plane.
bool fig_A_2(SvgWriter& w) {
  const Vec2d lo{-2.4, -2}, hi{2.4, 2};
  const Fn2 f = [](Vec2d x) { return bumps_f(hill_a2(), x); };
  const double zs = 1.6, level = 0.8;
  w.set_camera(camera({7, -9, 6}, {0, 0, 0.4}));
  rect3(w, lo, hi, 0, pen(c::light, 1));
  // The graph below and above the cutting plane.
  graph_wireframe(w, f, lo, hi, 20, zs, pen(c::gray, 0.7), -1e300, zs * level);
  rect3(w, lo, hi, zs * level, filled(c::orange, 0.1, 1));
  graph_wireframe(w, f, lo, hi, 20, zs, pen(c::purple, 0.8), zs * level, 1e300);
  const ScalarGrid<double> g = sample_grid<double>(f, lo, hi, 97, 81);
  const LevelSet<double> ls = level_set(g, level);
  if (ls.status != Status::ok || ls.contours.empty()) return false;
  for (const auto& ct : ls.contours) {
    w.polyline(lift(ct.points, zs * level), pen(c::red, 2.2), ct.closed);
    w.polyline(lift(ct.points, 0), pen(c::red, 1.6), ct.closed);
    for (std::size_t i = 0; i < ct.points.size(); i += ct.points.size() / 6 + 1)
      w.segment(Vec3d{ct.points[i].x, ct.points[i].y, zs * level},
                Vec3d{ct.points[i].x, ct.points[i].y, 0}, dashed(c::gray, 0.8));
  }
  label(w, Vec3d{hi.x, hi.y, zs * level}, "z = " + fmt(level, 1), c::orange, 6, 0);
  label(w, Vec3d{hi.x, lo.y, 0}, "xy-plane", c::gray, 6, -8);
  const Vec2d s = label_spot(ls);
  label(w, Vec3d{s.x, s.y, 0}, "level curve f(x, y) = 0.8", c::red, 8, -16);
  return true;
}

double a3_f(Vec2d x) { return 2 * x.x * x.x / 3 + x.y * x.y; }
const double a3_levels[] = {0.5, 1.5, 2.5, 3.5};

// A.3: level curves of f = 2x^2/3 + y^2 at their heights on the graph.
bool fig_A_3(SvgWriter& w) {
  const Vec2d lo{-2.6, -2.1}, hi{2.6, 2.1};
  const double zs = 0.45;
  w.set_camera(camera({8, -9, 5}, {0, 0, 0.8}));
  rect3(w, lo, hi, 0, pen(c::light, 1));
  graph_wireframe(w, a3_f, lo, hi, 14, zs, pen(c::gray, 0.6));
  const ScalarGrid<double> g = sample_grid<double>(a3_f, lo, hi, 105, 85);
  for (double lv : a3_levels) {
    const LevelSet<double> ls = level_set(g, lv);
    if (ls.status != Status::ok || ls.contours.empty()) return false;
    // The lifted curve, labelled at its rightmost point in the picture.
    Vec3d right{};
    double best = -1e300;
    for (const auto& ct : ls.contours) {
      const std::vector<Vec3d> pts = lift(ct.points, zs * lv);
      w.polyline(pts, pen(c::blue, 2.2), ct.closed);
      for (const Vec3d& q : pts) {
        Vec2d img;
        if (w.project(q, img) && img.x > best) best = img.x, right = q;
      }
    }
    label(w, right, "f = " + fmt(lv, 1), c::blue, 4, -4);
  }
  return true;
}

// A.4: the same level curves projected onto the xy-plane, and the minimum found by
// critical_points_2d.
bool fig_A_4(SvgWriter& w) {
  const Vec2d lo{-2.5, -2}, hi{2.5, 2};
  const ScalarGrid<double> g = sample_grid<double>(a3_f, lo, hi, 101, 81);
  closed(w, std::vector<Vec2d>{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, pen(c::light, 1));
  w.segment(Vec2d{lo.x, 0}, Vec2d{hi.x, 0}, pen(c::light, 1));
  w.segment(Vec2d{0, lo.y}, Vec2d{0, hi.y}, pen(c::light, 1));
  for (double lv : a3_levels) {
    LevelSet<double> ls;
    if (!draw_level(w, g, lv, pen(c::blue, 1.8), &ls)) return false;
    label(w, label_spot(ls), fmt(lv, 1), c::blue, 4, 2);
  }
  const auto cp = critical_points_2d(
      a3_f,
      [](Vec2d x) {
        return Vec2d{4 * x.x / 3, 2 * x.y};
      },
      [](Vec2d) {
        return Mat2d::from_rows(Vec2d{4.0 / 3, 0}, Vec2d{0, 2});
      },
      lo, hi);
  if (cp.status != Status::ok || cp.points.size() != 1) return false;
  point(w, cp.points[0].point, kind_name(cp.points[0].kind), kind_colour(cp.points[0].kind));
  label(w, Vec2d{lo.x, hi.y}, "f(x, y) = 2x\u00b2/3 + y\u00b2", c::black, 4, 6);
  return true;
}

// ---- A.7-A.12: functions of one variable ------------------------------------------------------

// A.7: four functions and their critical points, classified by locus::critical_points (the
// roots of p' and the sign of the first non-vanishing higher derivative there).
bool fig_A_7(SvgWriter& w) {
  const Polynomial<double> ps[4] = {
      Polynomial<double>{-0.6, 0, 1},       // (a) x^2 - 0.6
      Polynomial<double>{0.4, 0.2, -1},     // (b) 0.4 + 0.2x - x^2
      Polynomial<double>{0, 0, 0, 1},       // (c) x^3
      Polynomial<double>{0.1, 0, 0, -0.8},  // (d) 0.1 - 0.8 x^3
  };
  const char* tag[] = {"(a)", "(b)", "(c)", "(d)"};
  for (int k = 0; k < 4; ++k) {
    const Plot p{-1.2, 1.2, -1.2, 1.2, 1, 1, Vec2d{(k % 2) * 3.2, -(k / 2) * 3.2}};
    plot_axes(w, p, 0, 0);
    const Polynomial<double>& f = ps[k];
    plot_curve(
        w, p, [&](double x) { return f(x); }, -1.05, 1.05, pen(c::blue, 2));
    const CriticalPoints1<double> cp = critical_points(f, -1.2, 1.2);
    if (cp.status != Status::ok || cp.points.size() != 1) return false;
    const auto& q = cp.points[0];
    point(w, p.at(q.x, q.value), "", kind_colour(q.kind));
    label(w, p.at(-1.2, 1.2), std::string(tag[k]) + " " + kind_name(q.kind), kind_colour(q.kind), 0,
          0);
  }
  return true;
}

// A.8: x^3 - 3x on two intervals: the absolute maximum (critical_points' extrema over the
// critical points and the ends) is interior on the first and at the right end on the second.
bool fig_A_8(SvgWriter& w) {
  const Polynomial<double> f{0, -3, 0, 1};
  const double ends[2][2] = {{-1.8, 1.5}, {-1.8, 2.2}};
  for (int k = 0; k < 2; ++k) {
    const double a = ends[k][0], b = ends[k][1];
    const Plot p{-2, 2.4, -2.4, 4.4, 1, 0.6, Vec2d{k * 5.6, 0}};
    plot_axes(w, p, 1, 2);
    plot_curve(
        w, p, [&](double x) { return f(x); }, -2, 2.4, pen(c::light, 1.2));
    plot_curve(
        w, p, [&](double x) { return f(x); }, a, b, pen(c::blue, 2.2));
    for (double e : {a, b}) w.segment(p.at(e, -2.4), p.at(e, 4.2), dashed(c::gray, 1));
    const CriticalPoints1<double> cp = critical_points(f, a, b);
    if (cp.status != Status::ok) return false;
    for (const auto& q : cp.points) w.point(p.at(q.x, q.value), dot(kind_colour(q.kind), 3));
    point(w, p.at(cp.max_x, cp.max_value), "max " + fmt(cp.max_value), c::red);
    w.text(p.at(0.2, -2.4),
           "[" + fmt(a, 1) + ", " + fmt(b, 1) +
               "]: " + (cp.max_x == b || cp.max_x == a ? "maximum at an end" : "maximum inside"),
           text_style(c::black, 0, -22, SvgAnchor::middle, 13));
  }
  return true;
}

const Polynomial<double>& a9_f() {
  static const Polynomial<double> f{19, -7, 6, 1};  // x^3 + 6x^2 - 7x + 19
  return f;
}

// A.9: f = x^3 + 6x^2 - 7x + 19 on [-8, 3] with its relative and absolute extrema.
bool fig_A_9(SvgWriter& w) {
  const Polynomial<double>& f = a9_f();
  const double a = -8, b = 3;
  const CriticalPoints1<double> cp = critical_points(f, a, b);
  if (cp.status != Status::ok || cp.points.size() != 2) return false;
  const Plot p{a - 0.5, b + 0.8, -60, 100, 1, 0.055};
  plot_axes(w, p, 2, 20);
  plot_curve(
      w, p, [&](double x) { return f(x); }, a, b, pen(c::blue, 2.2));
  for (const auto& q : cp.points)
    point(w, p.at(q.x, q.value),
          std::string("relative ") + kind_name(q.kind) + " " + coordinates(q.x, q.value),
          kind_colour(q.kind));
  point(w, p.at(b, f(b)), "f(3) = " + fmt(f(b), 0), c::black);
  point(w, p.at(a, f(a)), "", c::black);
  label(w, p.at(a, f(a)), "absolute minimum f(-8) = " + fmt(cp.min_value, 0), c::blue, 8, -4);
  label(w, p.at(a, 96), "absolute maximum at x = " + fmt(cp.max_x), c::red, 0, 0);
  return true;
}

// A.10: f' = 3x^2 + 12x - 7 on [-8, 3]; its roots (locus::real_roots of derivative(f)) are the
// critical points of figure A.9.
bool fig_A_10(SvgWriter& w) {
  const Polynomial<double> df = derivative(a9_f());
  const double a = -8, b = 3;
  const RealRootsResult<double> r = real_roots(df, a, b);
  if (r.status != Status::ok || r.roots.size() != 2) return false;
  const Plot p{a - 0.5, b + 0.8, -25, 95, 1, 0.075};
  plot_axes(w, p, 2, 20);
  plot_curve(
      w, p, [&](double x) { return df(x); }, a, b, pen(c::green, 2.2));
  for (const auto& rt : r.roots) point(w, p.at(rt.value, 0), "", c::red);
  label(w, p.at(-6.2, 80), "f'(x) = 3x\u00b2 + 12x - 7", c::green, 0, 0);
  label(w, p.at(-6.2, 68),
        "zeros x = " + fmt(r.roots[0].value, 3) + ", " + fmt(r.roots[1].value, 3), c::red, 0, 0);
  return true;
}

// A.11: relative extrema of a quintic; critical_points lists them, the ends are not among them.
bool fig_A_11(SvgWriter& w) {
  const Polynomial<double> f = Polynomial<double>{0.2} * Polynomial<double>{2.4, 1} *
                               Polynomial<double>{0.9, 1} * Polynomial<double>{-0.6, 1} *
                               Polynomial<double>{-2.0, 1} * Polynomial<double>{-3.0, 1};
  const double a = -2.6, b = 3.15;
  const CriticalPoints1<double> cp = critical_points(f, a, b);
  if (cp.status != Status::ok || cp.points.size() != 4) return false;
  const Plot p{a - 0.2, b + 0.3, -4, 5, 1, 0.5};
  plot_axes(w, p, 1, 2);
  plot_curve(
      w, p, [&](double x) { return f(x); }, a, b, pen(c::blue, 2.2));
  for (const auto& q : cp.points) {
    const bool up = q.kind == CriticalKind::maximum;
    w.point(p.at(q.x, q.value), dot(kind_colour(q.kind), 4));
    w.text(p.at(q.x, q.value), std::string("relative ") + kind_name(q.kind),
           text_style(kind_colour(q.kind), 0, up ? 10 : -22, SvgAnchor::middle, 13));
  }
  return true;
}

// A.12: f = 3x^(5/3) - 15x^(2/3): a maximum at the cusp x = 0 (f' is infinite there) and a
// minimum at x = 2, both found by critical_points_1d from the sign changes of f'.
bool fig_A_12(SvgWriter& w) {
  const auto f = [](double x) {
    const double c3 = std::cbrt(x);
    return 3 * c3 * c3 * c3 * c3 * c3 - 15 * c3 * c3;
  };
  const auto df = [](double x) {
    const double c3 = std::cbrt(x);
    return 5 * c3 * c3 - 10 / c3;
  };
  const double a = -1, b = 5.5;
  // Refining the bracket of the cusp at 0 walks through the dense floating-point numbers near
  // zero (about a thousand halvings), more than the default budget.
  CriticalPoints1Options opt;
  opt.max_iterations = 4000;
  const CriticalPoints1<double> cp = critical_points_1d(f, df, a, b, opt);
  if (cp.status != Status::ok || cp.points.size() != 2) return false;
  const Plot p{a - 0.3, b + 0.4, -20, 12, 1, 0.22};
  plot_axes(w, p, 1, 5);
  plot_curve(w, p, f, a, b, pen(c::blue, 2.2), 400);
  for (const auto& q : cp.points)
    point(
        w, p.at(q.x, q.value),
        std::string("relative ") + kind_name(q.kind) + " (" + fmt(q.x) + ", " + fmt(q.value) + ")",
        kind_colour(q.kind));
  label(w, p.at(2.2, 9), "f(x) = 3x^(5/3) - 15x^(2/3)", c::blue, 0, 0);
  return true;
}

// ---- A.13-A.17: functions of two variables ----------------------------------------------------

const std::vector<Bump>& hills_a13() {
  static const std::vector<Bump> h{{1.0, {1.0, 1.0}, 0.8},
                                   {-0.8, {-1.1, -0.6}, 0.8},
                                   {0.7, {-1.2, 1.3}, 0.6},
                                   {-0.6, {1.3, -1.3}, 0.7}};
  return h;
}

// A.13: hills and valleys of a function of two variables, with its relative extrema and saddles
// from critical_points_2d.
bool fig_A_13(SvgWriter& w) {
  const Vec2d lo{-2.6, -2.6}, hi{2.6, 2.6};
  const Fn2 f = [](Vec2d x) { return bumps_f(hills_a13(), x); };
  const double zs = 1.4;
  w.set_camera(camera({8, -10, 7}, {0, 0, 0}));
  graph_wireframe(w, f, lo, hi, 22, zs, pen(c::gray, 0.7));
  const auto cp = bumps_critical(hills_a13(), Vec2d{-2, -2}, Vec2d{2, 2});
  if (cp.status != Status::ok) return false;
  int extrema = 0;
  for (const auto& q : cp.points)
    extrema += q.kind == CriticalKind::minimum || q.kind == CriticalKind::maximum ? 1 : 0;
  if (extrema != 4) return false;
  mark_critical_3d(w, cp, zs);
  return true;
}

// A.14: a relative maximum: f(x0, y0) >= f(x, y) for (x, y) in a disk around (x0, y0); the disk
// and its image on the graph are drawn around the maximum found by critical_points_2d.
bool fig_A_14(SvgWriter& w) {
  static const std::vector<Bump> hill{{1.2, {0.3, -0.2}, 2.2}, {0.3, {-1.5, 1.2}, 1.0}};
  const Vec2d lo{-2.5, -2.5}, hi{2.5, 2.5};
  const Fn2 f = [](Vec2d x) { return bumps_f(hill, x); };
  const double zs = 1.5;
  w.set_camera(camera({8, -10, 6}, {0, 0, 0.5}));
  rect3(w, lo, hi, 0, pen(c::light, 1));
  graph_wireframe(w, f, lo, hi, 18, zs, pen(c::light, 0.9));
  const auto cp = bumps_critical(hill, lo, hi);
  if (cp.status != Status::ok) return false;
  const CriticalPoint2<double>* top = nullptr;
  for (const auto& q : cp.points)
    if (q.kind == CriticalKind::maximum && (!top || q.value > top->value)) top = &q;
  if (!top) return false;
  const Vec2d m = top->point;
  std::vector<Vec3d> disk, cap;
  for (const Vec2d& d : circle_points(0.7, 64)) {
    disk.push_back({m.x + d.x, m.y + d.y, 0});
    cap.push_back({m.x + d.x, m.y + d.y, zs * f(m + d)});
  }
  closed(w, disk, filled(c::blue, 0.2));
  closed(w, cap, pen(c::blue, 2));
  const Vec3d peak{m.x, m.y, zs * top->value};
  w.segment(Vec3d{m.x, m.y, 0}, peak, dashed(c::gray, 1));
  point(w, Vec3d{m.x, m.y, 0}, "(x\u2080, y\u2080)", c::blue);
  point(w, peak, "relative maximum f(x\u2080, y\u2080) = " + fmt(top->value), c::red);
  return true;
}

// A.15: the saddle f = x^2 - y^2: grad f = 0 at the origin, whose Hessian has eigenvalues of both
// signs (critical_points_2d classifies it as a saddle); the two principal sections are drawn.
bool fig_A_15(SvgWriter& w) {
  const Vec2d lo{-2, -2}, hi{2, 2};
  const Fn2 f = [](Vec2d x) { return x.x * x.x - x.y * x.y; };
  const double zs = 0.5;
  w.set_camera(camera({8, -6, 6}, {0, 0, 0}));
  graph_wireframe(w, f, lo, hi, 16, zs, pen(c::gray, 0.6));
  const auto grad = [](Vec2d x) { return Vec2d{2 * x.x, -2 * x.y}; };
  const auto hess = [](Vec2d) { return Mat2d::from_rows(Vec2d{2, 0}, Vec2d{0, -2}); };
  const auto cp = critical_points_2d(f, grad, hess, lo, hi);
  if (cp.status != Status::ok || cp.points.size() != 1) return false;
  const auto& s = cp.points[0];
  // The sections along the Hessian's eigenvectors: the positive-eigenvalue direction curves up,
  // the negative one down.
  const auto eig = eigen_symmetric(hess(s.point));
  for (int k = 0; k < 2; ++k) {
    const Vec2d e{eig.vectors(0, k), eig.vectors(1, k)};
    std::vector<Vec3d> sec;
    for (int i = 0; i <= 60; ++i) {
      const Vec2d q = s.point + (-2 + 4.0 * i / 60) * e;
      sec.push_back({q.x, q.y, zs * f(q)});
    }
    w.polyline(sec, pen(eig.values[k] < 0 ? c::red : c::blue, 2.2));
  }
  mark_critical_3d(w, cp, zs, true);
  return true;
}

// f = 2y^2 x - y x^2 + 4xy of figures A.16 and A.17, its gradient and Hessian.
double a16_f(Vec2d p) { return 2 * p.y * p.y * p.x - p.y * p.x * p.x + 4 * p.x * p.y; }
CriticalPoints2<double> a16_critical(const Vec2d& lo, const Vec2d& hi) {
  return critical_points_2d(
      a16_f,
      [](Vec2d p) {
        return Vec2d{2 * p.y * p.y - 2 * p.x * p.y + 4 * p.y, 4 * p.x * p.y - p.x * p.x + 4 * p.x};
      },
      [](Vec2d p) {
        const double fxy = 4 * p.y - 2 * p.x + 4;
        return Mat2d::from_rows(Vec2d{-2 * p.y, fxy}, Vec2d{fxy, 4 * p.x});
      },
      lo, hi);
}

// A.16: the graph of 2y^2 x - yx^2 + 4xy (cut to a height window) with its three saddles and
// relative minimum.
bool fig_A_16(SvgWriter& w) {
  const Vec2d lo{-1.2, -2.8}, hi{5.2, 0.8};
  const double zs = 0.3;
  w.set_camera(camera({-4, -12, 9}, {2, -1, 0}));
  rect3(w, lo, hi, 0, filled(c::light, 0.15, 1));
  graph_wireframe(w, a16_f, lo, hi, 24, zs, pen(c::gray, 0.7), -1.5, 1.5);
  const auto cp = a16_critical(lo, hi);
  if (cp.status != Status::ok || cp.points.size() != 4) return false;
  mark_critical_3d(w, cp, zs, true);
  return true;
}

// A.17: contour plot of the same function, with the critical points: the level f = 0 is the three
// lines x = 0, y = 0, x = 2y + 4 crossing at the saddles.
bool fig_A_17(SvgWriter& w) {
  const Vec2d lo{-1.5, -3.5}, hi{5.5, 1.5};
  const ScalarGrid<double> g = sample_grid<double>(a16_f, lo, hi, 141, 101);
  closed(w, std::vector<Vec2d>{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, pen(c::light, 1));
  for (double lv : {-6.0, -3.0, -1.0, -0.5, 0.5, 1.0, 3.0, 6.0})
    if (!draw_level(w, g, lv, pen(lv < 0 ? c::blue : c::red, 1.2))) return false;
  if (!draw_level(w, g, 0.0, pen(c::black, 1.6))) return false;
  const auto cp = a16_critical(lo, hi);
  if (cp.status != Status::ok || cp.points.size() != 4) return false;
  for (const auto& q : cp.points) {
    w.point(q.point, dot(kind_colour(q.kind), 4.5));
    const bool right = q.point.x > 0.5 * (lo.x + hi.x) + 1;  // keep labels inside the frame
    w.text(q.point, std::string(kind_name(q.kind)) + " " + coordinates(q.point.x, q.point.y),
           text_style(kind_colour(q.kind), right ? -8 : 8, 9,
                      right ? SvgAnchor::end : SvgAnchor::start, 12));
  }
  label(w, Vec2d{lo.x, hi.y}, "f < 0 blue, f > 0 red, f = 0 black", c::black, 2, 6);
  return true;
}

// ---- A.18-A.24: Lagrange multipliers ----------------------------------------------------------

// The constraint 17x^2 + 8y^2 + 12xy = 100 of figures A.18 and A.21: g(x) = x^T A x.
const Mat2d a18_matrix = Mat2d::from_rows(Vec2d{17, 12.0 / 2}, Vec2d{12.0 / 2, 8});
double a18_g(Vec2d p) { return 17 * p.x * p.x + 8 * p.y * p.y + 12 * p.x * p.y; }

// A.18: the ellipse as the level set g = 100, its axes from eigen_symmetric(A): semi-axis
// sqrt(100 / lambda) along each eigenvector.
bool fig_A_18(SvgWriter& w) {
  const Vec2d lo{-4, -4.5}, hi{4, 4.5};
  w.segment(Vec2d{lo.x, 0}, Vec2d{hi.x, 0}, pen(c::gray, 1));
  w.segment(Vec2d{0, lo.y}, Vec2d{0, hi.y}, pen(c::gray, 1));
  const ScalarGrid<double> g = sample_grid<double>(a18_g, lo, hi, 121, 131);
  if (!draw_level(w, g, 100, pen(c::blue, 2.2))) return false;
  const auto eig = eigen_symmetric(a18_matrix);
  if (eig.status != Status::ok) return false;
  for (int k = 0; k < 2; ++k) {
    const Vec2d e{eig.vectors(0, k), eig.vectors(1, k)};
    const double r = std::sqrt(100 / eig.values[k]);
    w.segment(-r * e, r * e, dashed(c::green, 1.2));
    label(w, r * e, "\u03bb = " + fmt(eig.values[k], 0) + ", semi-axis " + fmt(r), c::green, 5, 5);
  }
  label(w, Vec2d{lo.x, lo.y}, "17x\u00b2 + 8y\u00b2 + 12xy = 100", c::blue, 0, 0);
  return true;
}

double a19_f(Vec2d p) { return p.x * p.x + p.y * p.y; }

// A.19: the graph of x^2 + y^2 with level circles on it and its minimum (minimize_quadratic).
bool fig_A_19(SvgWriter& w) {
  const Vec2d lo{-2, -2}, hi{2, 2};
  const double zs = 0.5;
  w.set_camera(camera({8, -9, 6}, {0, 0, 1}));
  rect3(w, lo, hi, 0, pen(c::light, 1));
  graph_wireframe(w, a19_f, lo, hi, 16, zs, pen(c::gray, 0.6));
  const ScalarGrid<double> g = sample_grid<double>(a19_f, lo, hi, 81, 81);
  for (double lv : {1.0, 2.0, 3.0})
    if (!draw_level_3d(w, g, lv, zs, pen(c::blue, 1.8))) return false;
  const auto m = minimize_quadratic(Mat2d::identity(), Vec2d{0, 0}, 0.0);
  if (m.status != Status::ok) return false;
  point(w, Vec3d{m.x.x, m.x.y, zs * m.value}, "minimum " + fmt(m.value, 0), c::red);
  return true;
}

// A.20: level curves x^2 + y^2 = c (level_set), circles of radius sqrt(c).
bool fig_A_20(SvgWriter& w) {
  const Vec2d lo{-2.8, -2.8}, hi{2.8, 2.8};
  w.segment(Vec2d{lo.x, 0}, Vec2d{hi.x, 0}, pen(c::gray, 1));
  w.segment(Vec2d{0, lo.y}, Vec2d{0, hi.y}, pen(c::gray, 1));
  const ScalarGrid<double> g = sample_grid<double>(a19_f, lo, hi, 113, 113);
  // Levels c = r^2 for equally spaced radii r.
  for (double lv : {0.25, 1.0, 2.25, 4.0, 6.25}) {
    LevelSet<double> ls;
    if (!draw_level(w, g, lv, pen(c::blue, 1.6), &ls)) return false;
    label(w, label_spot(ls), fmt(lv, lv == std::floor(lv) ? 0 : 2), c::blue, 3, 0);
  }
  label(w, Vec2d{lo.x, hi.y}, "x\u00b2 + y\u00b2 = c", c::blue, 0, 0);
  return true;
}

// A.21 (our reading of A.18-A.21 as one example: the extrema of x^2 + y^2, figures A.19 and A.20,
// subject to the ellipse of A.18): Lagrange's condition
// grad(x^2 + y^2) = mu grad g means A x = (1/mu) x, so the extrema lie along the eigenvectors of
// A (eigen_symmetric): x^2 + y^2 = 100 / lambda, minimal for the largest lambda, where the level
// circle touches the ellipse.
bool fig_A_21(SvgWriter& w) {
  const Vec2d lo{-4.8, -4.8}, hi{4.8, 4.8};
  const ScalarGrid<double> ge = sample_grid<double>(a18_g, lo, hi, 145, 145);
  const ScalarGrid<double> gc = sample_grid<double>(a19_f, lo, hi, 145, 145);
  const auto eig = eigen_symmetric(a18_matrix);
  if (eig.status != Status::ok) return false;
  const double fmin = 100 / eig.values[1], fmax = 100 / eig.values[0];
  for (double lv : {2.0, 10.0, 14.0})
    if (!draw_level(w, gc, lv, dashed(c::gray, 1))) return false;
  if (!draw_level(w, gc, fmin, pen(c::red, 1.6))) return false;
  if (!draw_level(w, gc, fmax, pen(c::orange, 1.2))) return false;
  if (!draw_level(w, ge, 100, pen(c::blue, 2.2))) return false;
  const Vec2d emin{eig.vectors(0, 1), eig.vectors(1, 1)},
      emax{eig.vectors(0, 0), eig.vectors(1, 0)};
  for (double s : {-1.0, 1.0}) {
    w.point(s * std::sqrt(fmin) * emin, dot(c::red, 4.5));
    w.point(s * std::sqrt(fmax) * emax, dot(c::orange, 4.5));
  }
  label(w, std::sqrt(fmin) * emin, "minimum x\u00b2 + y\u00b2 = " + fmt(fmin, 0), c::red, 6, 4);
  label(w, std::sqrt(fmax) * emax, "maximum " + fmt(fmax, 0), c::orange, 6, 4);
  label(w, Vec2d{lo.x, hi.y}, "constraint 17x\u00b2 + 8y\u00b2 + 12xy = 100", c::blue, 0, 0);
  return true;
}

// A sphere as a wireframe of latitude and longitude circles (locus::point_at(Sphere3)).
void sphere_wireframe(SvgWriter& w, const Sphere3<double>& s, int lat, int lon,
                      const SvgStyle& st) {
  for (int i = 1; i < lat; ++i) {
    std::vector<Vec3d> ring;
    for (int k = 0; k < 72; ++k)
      ring.push_back(point_at(s, Vec2d{2 * pi_v<double> * k / 72, pi_v<double> * i / lat}));
    closed(w, ring, st);
  }
  for (int i = 0; i < lon; ++i) {
    std::vector<Vec3d> meridian;
    for (int k = 0; k <= 36; ++k)
      meridian.push_back(point_at(s, Vec2d{2 * pi_v<double> * i / lon, pi_v<double> * k / 36}));
    w.polyline(meridian, st);
  }
}

// A.22: the closest and farthest points of the sphere |x| = 6 to p = (1, 2, 2): the extrema of
// |x - p|^2 = x^T I x - 2 p^T x + |p|^2 on the sphere (minimize / maximize_quadratic_on_sphere).
bool fig_A_22(SvgWriter& w) {
  const Vec3d p{1, 2, 2};
  const Sphere3<double> s{{0, 0, 0}, 6};
  const auto lo =
      minimize_quadratic_on_sphere(Mat3d::identity(), -2.0 * p, sqr_length(p), s.center, s.radius);
  const auto hi =
      maximize_quadratic_on_sphere(Mat3d::identity(), -2.0 * p, sqr_length(p), s.center, s.radius);
  if (lo.status != Status::ok || hi.status != Status::ok) return false;
  // Looking across the line through the origin and p, on which both answers lie.
  w.set_camera(camera({20, -10, 6}, {0, 0, 0}));
  sphere_wireframe(w, s, 8, 12, pen(c::light, 0.9));
  w.segment(hi.x, lo.x, dashed(c::gray, 1));
  w.segment(p, lo.x, pen(c::red, 2));
  w.segment(p, hi.x, pen(c::orange, 1.4));
  point(w, Vec3d{0, 0, 0}, "O", c::gray);
  point(w, p, "p = " + coords3(p), c::black);
  point(w, lo.x, "closest " + coords3(lo.x) + ", distance " + fmt(std::sqrt(lo.value), 0), c::red);
  point(w, hi.x, "farthest " + coords3(hi.x) + ", distance " + fmt(std::sqrt(hi.value), 0),
        c::orange);
  return true;
}

// The constraint set of A.23 / A.24: the cylinder x^2 + y^2 = 1 (g2 = 0) and the plane
// x - y + z = 1 (g1 = 0). Their intersection is the image of the cylinder's cross-section circle
// under the projection along the cylinder's axis onto the plane (locus::oblique_projection).
struct TwoConstraints {
  Cylinder3<double> cyl{{{0, 0, 1}, {0, 0, 1}}, 1.0, 5.0};
  Vec3d plane_point{1, 0, 0};
  Vec3d plane_normal{1, -1, 1};
  std::optional<Mat4d> along_axis =
      oblique_projection(plane_point, plane_normal, cyl.axis.direction);

  // The point of the plane above (x, y).
  [[nodiscard]] std::optional<Vec3d> on_plane(const Vec2d& q) const {
    if (!along_axis) return std::nullopt;
    return apply_projective(*along_axis, Vec3d{q.x, q.y, 0});
  }
};

// Oblique to the plane x - y + z = 1, so that the constraint curve shows as an ellipse.
const Vec3d a23_eye{9, 1, 5};

bool draw_constraints(SvgWriter& w, const TwoConstraints& k, std::vector<Vec3d>& curve) {
  // The cylinder: its rulings and two cross-sections.
  const double h = k.cyl.height / 2;
  for (int i = 0; i < 16; ++i) {
    const double t = 2 * pi_v<double> * i / 16;
    w.segment(point_at(k.cyl, Vec2d{t, -h}), point_at(k.cyl, Vec2d{t, h}), pen(c::light, 0.9));
  }
  for (double z : {-h, h}) {
    std::vector<Vec3d> ring;
    for (int i = 0; i < 72; ++i)
      ring.push_back(point_at(k.cyl, Vec2d{2 * pi_v<double> * i / 72, z}));
    closed(w, ring, pen(c::gray, 1));
  }
  // The plane over [-1.3, 1.3]^2.
  std::vector<Vec3d> quad;
  for (const Vec2d& q : {Vec2d{-1.3, -1.3}, Vec2d{1.3, -1.3}, Vec2d{1.3, 1.3}, Vec2d{-1.3, 1.3}}) {
    const auto p = k.on_plane(q);
    if (!p) return false;
    quad.push_back(*p);
  }
  closed(w, quad, filled(c::green, 0.12, 1));
  curve.clear();
  for (const Vec2d& q : circle_points(k.cyl.radius, 120)) {
    const auto p = k.on_plane(q);
    if (!p) return false;
    curve.push_back(*p);
  }
  closed(w, curve, pen(c::blue, 2.4));
  label(w, quad[1], "g\u2081: x - y + z = 1", c::green, 6, 0);
  label(w, point_at(k.cyl, Vec2d{1.6, h}), "g\u2082: x\u00b2 + y\u00b2 = 1", c::gray, 6, 4);
  return true;
}

// A.23: the two constraint surfaces and the curve where both hold.
bool fig_A_23(SvgWriter& w) {
  const TwoConstraints k;
  w.set_camera(camera(a23_eye, {0, 0, 1}));
  axes3(w, 2.2);
  std::vector<Vec3d> curve;
  if (!draw_constraints(w, k, curve)) return false;
  label(w, curve[30], "g\u2081 = 0 and g\u2082 = 0", c::blue, 8, 0);
  return true;
}

// A.24: the extrema of f on that curve. The caption does not state f; as in
// tests/numeric/minimize_test.cpp we take f = x^2 + y^2 + z^2. The linear constraint eliminates z:
// the plane over (x, y) is the affine map u -> M u + t read off the projection along the axis
// (images of the origin and the unit vectors), so f = |M u + t|^2 = u^T (M^T M) u + 2 t^T M u +
// |t|^2 on the unit circle g2 = 0 (here 2x^2 - 2xy + 2y^2 - 2x + 2y + 1), whose extrema
// minimize_quadratic_on_sphere / maximize_quadratic_on_sphere find. The minimum is attained twice
// (the solver's "hard case", unique = false, which reports one of them): the second minimiser is
// the mirror image of the first across the line orthogonal to A's lowest eigenvector
// (eigen_symmetric). The level sets of
// f there are spheres about the origin, drawn through the extrema.
bool fig_A_24(SvgWriter& w) {
  const TwoConstraints k;
  const auto t = k.on_plane(Vec2d{0, 0}), ex = k.on_plane(Vec2d{1, 0}),
             ey = k.on_plane(Vec2d{0, 1});
  if (!t || !ex || !ey) return false;
  const Vec3d m0 = *ex - *t, m1 = *ey - *t;  // the columns of M
  const Mat2d a =
      Mat2d::from_rows(Vec2d{dot(m0, m0), dot(m0, m1)}, Vec2d{dot(m1, m0), dot(m1, m1)});
  const Vec2d b{2 * dot(*t, m0), 2 * dot(*t, m1)};
  const double c0 = sqr_length(*t);
  const auto lo = minimize_quadratic_on_sphere(a, b, c0, Vec2d{0, 0}, k.cyl.radius);
  const auto hi = maximize_quadratic_on_sphere(a, b, c0, Vec2d{0, 0}, k.cyl.radius);
  const auto eig = eigen_symmetric(a);
  if (lo.status != Status::ok || hi.status != Status::ok || eig.status != Status::ok) return false;
  // The mirror image across the line orthogonal to the lowest eigenvector is another point of
  // the circle; it is listed when q is as low there (the hard case's second minimiser).
  std::vector<Vec2d> minima{lo.x};
  const Vec2d v{eig.vectors(0, 0), eig.vectors(1, 0)};
  const Vec2d mirror = lo.x - 2 * dot(lo.x, v) * v;
  const double q_mirror = dot(mirror, a * mirror) + dot(b, mirror) + c0;
  if (length(mirror - lo.x) > 1e-6 && std::abs(q_mirror - lo.value) <= 1e-9 * (1 + lo.value))
    minima.push_back(mirror);
  w.set_camera(camera(a23_eye, {0, 0, 1}));
  std::vector<Vec3d> curve;
  if (!draw_constraints(w, k, curve)) return false;
  const auto top = k.on_plane(hi.x);
  if (!top) return false;
  // The level spheres |x|^2 = f through the extrema, drawn by their outline as seen from the
  // camera and their equator.
  const auto outline = locus::plane_frame(Vec3d{0, 0, 0}, a23_eye);
  if (!outline) return false;
  for (const auto& [value, col] : {std::pair{lo.value, c::red}, std::pair{hi.value, c::orange}}) {
    const double r = std::sqrt(value);
    std::vector<Vec3d> rim, equator;
    for (const Vec2d& q : circle_points(r)) {
      rim.push_back(to_world(*outline, q));
      equator.push_back({q.x, q.y, 0});
    }
    closed(w, rim, filled(col, 0.06, 1.2));
    closed(w, equator, dashed(col, 1));
  }
  // Minimum labels point away from each other in the picture.
  std::vector<Vec3d> mins;
  double mean_x = 0;
  for (const Vec2d& m : minima) {
    const auto p = k.on_plane(m);
    Vec2d img;
    if (!p || !w.project(*p, img)) return false;
    mins.push_back(*p);
    mean_x += img.x / static_cast<double>(minima.size());
  }
  for (const Vec3d& p : mins) {
    Vec2d img;
    if (!w.project(p, img)) return false;
    const bool left = minima.size() > 1 && img.x < mean_x;
    w.point(p, dot(c::red));
    w.text(p, "min f = " + fmt(lo.value, 0),
           text_style(c::red, left ? -8 : 8, -4, left ? SvgAnchor::end : SvgAnchor::start));
  }
  point(w, *top, "max f = " + fmt(hi.value, 3), c::orange);
  return true;
}

}  // namespace

std::vector<Figure> appendix_a_figures() {
  return {
      {"A.1", "scaling_axes, rotation, compose, map_points; svd of the composite (ellipse axes)",
       fig_A_1},
      {"A.2", "sample_grid, level_set (marching squares), drawn on the graph and projected",
       fig_A_2},
      {"A.3", "sample_grid, level_set lifted to the graph of 2x^2/3 + y^2", fig_A_3},
      {"A.4", "sample_grid, level_set; critical_points_2d (the minimum)", fig_A_4},
      {"A.7", "Polynomial, critical_points (roots of p', classified)", fig_A_7},
      {"A.8", "Polynomial, critical_points with absolute extrema on [a, b]", fig_A_8},
      {"A.9", "Polynomial, critical_points (relative and absolute extrema on [-8, 3])", fig_A_9},
      {"A.10", "derivative, real_roots on [-8, 3]", fig_A_10},
      {"A.11", "Polynomial products, critical_points", fig_A_11},
      {"A.12", "critical_points_1d (sign changes of f', the cusp included)", fig_A_12},
      {"A.13", "critical_points_2d (Newton on grad f = 0, Hessian classification)", fig_A_13},
      {"A.14", "critical_points_2d (the relative maximum)", fig_A_14},
      {"A.15", "critical_points_2d (saddle), eigen_symmetric of the Hessian (sections)", fig_A_15},
      {"A.16", "critical_points_2d (three saddles, one minimum)", fig_A_16},
      {"A.17", "sample_grid, level_set, critical_points_2d", fig_A_17},
      {"A.18", "sample_grid, level_set; eigen_symmetric (the ellipse's axes)", fig_A_18},
      {"A.19", "level_set lifted to the graph; minimize_quadratic", fig_A_19},
      {"A.20", "sample_grid, level_set", fig_A_20},
      {"A.21", "level_set of constraint and objective; eigen_symmetric (Lagrange condition)",
       fig_A_21},
      {"A.22", "minimize_quadratic_on_sphere, maximize_quadratic_on_sphere, Sphere3 point_at",
       fig_A_22},
      {"A.23",
       "Cylinder3 point_at, oblique_projection (the plane over the cylinder), "
       "apply_projective",
       fig_A_23},
      {"A.24",
       "minimize/maximize_quadratic_on_sphere after eliminating z, eigen_symmetric "
       "(second minimiser), oblique_projection",
       fig_A_24},
  };
}

}  // namespace locus_gallery
