// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 6 (distance in 2D): figures 6.1-6.10 and 6.16-6.23. Every closest point,
// distance and parameter shown is the result of a locus::distance query on the literal inputs;
// region maps classify a grid of query points by the parameters locus::distance returns (which
// barycentric coordinates or box coordinates are clamped), and level curves of the squared
// distance F over a parameter domain are drawn as the preimages of circles under the
// parametrisation, mapped back with locus::barycentric.
#include "gallery.hpp"

#include <locus/curves/bezier.hpp>

#include <locus/distance/line_curve.hpp>
#include <locus/distance/line_line.hpp>
#include <locus/distance/line_quadratic_curve.hpp>
#include <locus/distance/line_ray.hpp>
#include <locus/distance/line_segment.hpp>
#include <locus/distance/point_convex_polygon.hpp>
#include <locus/distance/point_curve.hpp>
#include <locus/distance/point_ellipse.hpp>
#include <locus/distance/point_frustum.hpp>
#include <locus/distance/point_line.hpp>
#include <locus/distance/point_polyline.hpp>
#include <locus/distance/point_ray.hpp>
#include <locus/distance/point_rectangle.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/ray_ray.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/io/svg_primitives.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/frustum.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/polygon.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/quadratic_curve.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <optional>
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

const char* const panel_names[] = {"(a)", "(b)", "(c)", "(d)"};

// The closest pair of a distance result: a dashed link, the query side in red, the object side
// in blue.
template <class D>
void closest_link(SvgWriter& w, const D& d, std::string_view name0, std::string_view name1) {
  w.segment(d.closest[0], d.closest[1], dashed(c::gray, 1.2));
  point(w, d.closest[0], name0, c::red);
  point(w, d.closest[1], name1, c::blue);
}

// `colour` ("#rrggbb") mixed with white: opaque pale fills, so that touching cells of a region map
// can overlap slightly (hiding anti-aliasing seams) without darker bands.
std::string pale(const char* colour, double f) {
  unsigned rgb = 0;
  if (std::sscanf(colour, "#%6x", &rgb) != 1) return colour;
  const auto mix = [&](unsigned shift) {
    const double v = static_cast<double>((rgb >> shift) & 0xffu);
    return static_cast<unsigned>(std::lround(255.0 - f * (255.0 - v)));
  };
  char buf[16];
  std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", mix(16), mix(8), mix(0));
  return buf;
}

// A filled axis-aligned cell [lo, hi] without outline.
void cell(SvgWriter& w, const Vec2d& lo, const Vec2d& hi, const std::string& fill,
          double opacity = 1.0) {
  SvgStyle s;
  s.stroke = "none";
  s.fill = fill;
  s.fill_opacity = opacity;
  w.polygon(std::vector<Vec2d>{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, s);
}

// Shades [lo, hi] by the class (an index into `colours`, or -1 for none) of a grid of sample
// points; runs of equal class along a row are merged into one rectangle.
void region_map(SvgWriter& w, const Vec2d& lo, const Vec2d& hi, int nx, int ny,
                const std::function<int(const Vec2d&)>& classify,
                const std::vector<const char*>& colours, double strength = 0.3) {
  const double dx = (hi.x - lo.x) / nx, dy = (hi.y - lo.y) / ny;
  for (int j = 0; j < ny; ++j) {
    const double y0 = lo.y + j * dy;
    // Rows overlap the next one by a fraction of a cell (the last row does not stick out).
    const double y1 = j + 1 < ny ? y0 + 1.3 * dy : hi.y;
    int run_start = 0, run_class = -2;
    for (int i = 0; i <= nx; ++i) {
      const int k = i < nx ? classify(Vec2d{lo.x + (i + 0.5) * dx, y0 + 0.5 * dy}) : -3;
      if (k == run_class) continue;
      if (run_class >= 0 && run_class < static_cast<int>(colours.size())) {
        const double x1 = i < nx ? lo.x + (i + 0.3) * dx : hi.x;
        cell(w, Vec2d{lo.x + run_start * dx, y0}, Vec2d{x1, y1},
             pale(colours[static_cast<std::size_t>(run_class)], strength));
      }
      run_start = i;
      run_class = k;
    }
  }
}

// ---- point to linear components -----------------------------------------------------------

// 6.1: the closest point X(t) on a line to Y, and the perpendicular from Y.
bool fig_6_1(SvgWriter& w) {
  const Line2<double> line{{-1.0, -0.4}, {1.0, 0.35}};
  const Vec2d y{0.6, 1.6};
  const auto d = distance(y, line);
  if (!std::isfinite(d.distance)) return false;
  draw(w, line, pen(c::blue));
  point(w, line.origin, "P", c::blue);
  w.arrow(line.origin, line.origin + line.direction, pen(c::blue, 2.2));
  label(w, line.origin + line.direction, "d", c::blue, 2, -18);
  closest_link(w, d, "Y", "X(t\u0304), t\u0304 = " + fmt(d.param_b));
  right_angle_mark(w, d.closest[1], line.direction, y - d.closest[1], 0.15);
  label(w, lerp(d.closest[0], d.closest[1], 0.5), "dist = " + fmt(d.distance), c::gray, 8, 0);
  return true;
}

// 6.2: point to ray: (a) the projection is on the ray; (b) it falls behind the origin P, which
// is then the closest point (t clamped to 0).
bool fig_6_2(SvgWriter& w) {
  const Vec2d dir{1.0, 0.3};
  const std::array<Vec2d, 2> ys{Vec2d{1.2, 1.5}, Vec2d{-1.5, 0.9}};
  for (std::size_t k = 0; k < 2; ++k) {
    const Vec2d off{3.6 * static_cast<double>(k), 0};
    const Ray<double, 2> ray{off + Vec2d{-0.6, 0}, dir};
    const Vec2d y = off + ys[k];
    const auto d = distance(y, ray);
    if (!std::isfinite(d.distance)) return false;
    w.segment(ray.origin, ray.origin + 2.6 * dir, pen(c::blue));
    w.arrow(ray.origin + 2.2 * dir, ray.origin + 2.7 * dir, pen(c::blue));
    point(w, ray.origin, "P", c::blue);
    w.segment(ray.origin - 1.2 * dir, ray.origin, dashed(c::light, 1));
    closest_link(w, d, "Y", d.param_b > 0 ? "X(t\u0304)" : "");
    label(w, off + Vec2d{-0.8, -0.9}, std::string(panel_names[k]) + " t\u0304 = " + fmt(d.param_b));
  }
  return true;
}

// 6.3: point to segment: (a) interior point; (b) P0 closest (t clamped to 0); (c) P1 closest.
bool fig_6_3(SvgWriter& w) {
  const std::array<Vec2d, 3> ys{Vec2d{0.8, 1.3}, Vec2d{-1.0, 1.0}, Vec2d{2.4, 1.1}};
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec2d off{3.8 * static_cast<double>(k), 0};
    const Segment<double, 2> seg{off + Vec2d{-0.4, 0}, off + Vec2d{1.8, 0.5}};
    const Vec2d y = off + ys[k];
    const auto d = distance(y, seg);
    if (!std::isfinite(d.distance)) return false;
    draw(w, seg, pen(c::blue));
    point(w, seg.p0, "P\u2080", c::blue);
    point(w, seg.p1, "P\u2081", c::blue);
    w.segment(lerp(seg.p0, seg.p1, -0.6), lerp(seg.p0, seg.p1, 1.6), dashed(c::light, 1));
    closest_link(w, d, "Y", d.param_b > 0 && d.param_b < 1 ? "X(t\u0304)" : "");
    label(w, off + Vec2d{-0.4, -0.8}, std::string(panel_names[k]) + " t\u0304 = " + fmt(d.param_b));
  }
  return true;
}

// The end point of s farther from y, where a label does not cover the interesting part.
Vec2d far_end(const Segment<double, 2>& s, const Vec2d& y) {
  return sqr_length(s.p0 - y) > sqr_length(s.p1 - y) ? s.p0 : s.p1;
}
// A label style that puts the text on the far side of `at` as seen from y.
SvgStyle side_label(const Vec2d& at, const Vec2d& y) {
  const bool right = at.x > y.x;
  return text_style(c::blue, right ? 8 : -8, at.y > y.y ? 4 : -14,
                    right ? locus::SvgAnchor::start : locus::SvgAnchor::end, 13);
}

// Status of polyline segment i against the current minimum mu of segment 0, as
// locus::distance(point, polyline) sees it: rejected when both end points lie beyond one side of
// the strip |x - Y.x| <= mu or |y - Y.y| <= mu (no projection computed), otherwise projected.
template <class Dist>
std::string strip_status(const Segment<double, 2>& s, const Vec2d& y, double mu, std::size_t i,
                         const Dist& dist) {
  for (int k = 0; k < 2; ++k) {
    const double lo = y[k] - mu, hi = y[k] + mu;
    if ((s.p0[k] > hi && s.p1[k] > hi) || (s.p0[k] < lo && s.p1[k] < lo))
      return k == 0 ? "rejected by the vertical strip" : "rejected by the horizontal strip";
  }
  if (i == 0) return "sets μ = " + fmt(mu);
  const double d = dist(s);
  return d < mu ? "updates μ to " + fmt(d) : "dist " + fmt(d) + " > μ";
}

// 6.4: point to polyline with the rejection tests of locus::distance(point, polyline). Segment
// S0 sets the current minimum mu (locus::distance(Y, S0)); S1 lies partly in both strips but
// outside the circle of radius mu; S2 is rejected by the vertical strip; S3 meets the circle and
// updates mu. The unlabelled connecting segments are part of the polyline too. The final closest
// point (green) is the polyline query's.
bool fig_6_4(SvgWriter& w) {
  const Vec2d y{0, 0};
  const Polyline2<double> pl{{{-1.4, 0.2},
                              {0.2, 1.4},
                              {0.5, 2.6},
                              {2.6, 0.5},
                              {2.2, -0.4},
                              {1.5, -1.9},
                              {0.2, -2.4},
                              {-0.8, 0.3}},
                             false};
  const double mu = distance(y, Segment<double, 2>{pl.vertices[0], pl.vertices[1]}).distance;
  const auto final_d = distance(y, pl);
  if (!std::isfinite(mu) || !std::isfinite(final_d.distance)) return false;
  const double big = 3.0;
  cell(w, Vec2d{-mu, -big}, Vec2d{mu, big}, pale(c::gray, 0.12));
  cell(w, Vec2d{-big, -mu}, Vec2d{big, mu}, pale(c::gray, 0.12));
  cell(w, Vec2d{-mu, -mu}, Vec2d{mu, mu}, pale(c::gray, 0.25));
  closed(w, std::vector<Vec2d>{{-mu, -mu}, {mu, -mu}, {mu, mu}, {-mu, mu}}, dashed(c::black, 1));
  w.circle(y, mu, dashed(c::red, 1.2));
  for (std::size_t i = 0; i + 1 < pl.vertices.size(); ++i) {
    const Segment<double, 2> s{pl.vertices[i], pl.vertices[i + 1]};
    if (i % 2 == 1) {
      w.segment(s.p0, s.p1, pen(c::light, 1.2));
      continue;
    }
    draw(w, s, pen(c::blue, 2));
    const std::string status = strip_status(
        s, y, mu, i, [&](const Segment<double, 2>& x) { return distance(y, x).distance; });
    w.text(far_end(s, y), "S" + std::to_string(i / 2) + ": " + status,
           side_label(far_end(s, y), y));
  }
  point(w, y, "Y", c::red);
  w.segment(y, final_d.closest[1], pen(c::green, 1.4));
  point(w, final_d.closest[1], "", c::green);
  label(w, Vec2d{-big, -big},
        "closest: " + fmt(final_d.distance) + " (segment " +
            std::to_string(static_cast<int>(final_d.param_b)) + ")",
        c::green, 0, 0);
  return true;
}

// ---- point to triangle ----------------------------------------------------------------------

const Triangle2<double> tri65{{0, 0}, {2.2, 0.3}, {0.7, 1.7}};

// Which feature of the triangle a closest point lies on, from its barycentric coordinates.
std::string feature(const Vec3d& bary) {
  const char* v[] = {"P\u2080", "P\u2081", "P\u2082"};
  int zeros = 0, nonzero = -1;
  for (int i = 0; i < 3; ++i) {
    if (bary[i] == 0)
      ++zeros;
    else
      nonzero = nonzero < 0 ? i : nonzero;
  }
  if (zeros == 0) return "interior";
  if (zeros == 2) return std::string("vertex ") + v[nonzero];
  std::string e = "edge <";
  for (int i = 0; i < 3; ++i)
    if (bary[i] != 0) e += std::string(e.size() > 6 ? ", " : "") + v[i];
  return e + ">";
}

// 6.5: point to triangle: (a) inside, distance 0; (b) edge P0 P1; (c) vertex P2; (d) edge P1 P2.
bool fig_6_5(SvgWriter& w) {
  const std::array<Vec2d, 4> ys{Vec2d{0.9, 0.6}, Vec2d{1.0, -0.9}, Vec2d{0.6, 2.6},
                                Vec2d{2.2, 1.5}};
  for (std::size_t k = 0; k < 4; ++k) {
    const Vec2d off{3.4 * static_cast<double>(k % 2), -3.9 * static_cast<double>(k / 2)};
    const Triangle2<double> t{tri65.v0 + off, tri65.v1 + off, tri65.v2 + off};
    const Vec2d y = off + ys[k];
    const auto d = distance(y, t);
    if (!std::isfinite(d.distance)) return false;
    draw(w, t, filled(c::blue, 0.12));
    point(w, t.v0, "P\u2080", c::blue);
    point(w, t.v1, "P\u2081", c::blue);
    point(w, t.v2, "P\u2082", c::blue);
    if (d.distance > 0) {
      closest_link(w, d, "Y", "");
    } else {
      point(w, y, "Y", c::red);
    }
    label(w, off + Vec2d{-0.2, -1.35},
          std::string(panel_names[k]) + " " + feature(d.param_b) + ", dist " + fmt(d.distance));
  }
  return true;
}

// The seven regions of the parameter plane (figure 6.6): the cells of the arrangement of the
// lines s = 0, t = 0 and s + t = 1, numbered as in the book.
int st_region(double s, double t) {
  if (s + t <= 1) {
    if (s < 0) return t < 0 ? 4 : 3;
    return t < 0 ? 5 : 0;
  }
  if (s < 0) return 2;
  return t < 0 ? 6 : 1;
}

const std::vector<const char*> seven{c::gray,   c::blue, c::green, c::orange,
                                     c::purple, c::red,  "#1a9a9a"};

// The parameter-plane frame: the domain triangle and the lines s = 0, t = 0, s + t = 1.
void st_frame(SvgWriter& w, const Vec2d& off, double lo, double hi) {
  w.segment(off + Vec2d{lo, 0}, off + Vec2d{hi, 0}, pen(c::gray, 1));
  w.segment(off + Vec2d{0, lo}, off + Vec2d{0, hi}, pen(c::gray, 1));
  w.segment(off + Vec2d{1 - hi, hi}, off + Vec2d{hi, 1 - hi}, pen(c::gray, 1));
  closed(w, std::vector<Vec2d>{off, off + Vec2d{1, 0}, off + Vec2d{0, 1}}, pen(c::black, 2));
  label(w, off + Vec2d{hi, 0}, "t\u2080", c::black, 2, 4);
  label(w, off + Vec2d{0, hi}, "t\u2081", c::black, 4, -12);
}

// 6.6: the seven regions of the (t0, t1) plane. The samples are query points Y of the
// triangle's plane, placed in the parameter plane at their unconstrained minimiser
// (locus::barycentric) and coloured by its region; the label of each region names the feature
// locus::distance finds for the region's sample point.
bool fig_6_6(SvgWriter& w) {
  const double lo = -1.0, hi = 2.0;
  const auto bary_of_st = [](const Vec2d& st) { return barycentric(tri65, point_at(tri65, st)); };
  region_map(
      w, Vec2d{lo, lo}, Vec2d{hi, hi}, 90, 90,
      [&](const Vec2d& st) {
        const auto b = bary_of_st(st);
        return b ? st_region(b->y, b->z) : -1;
      },
      seven, 0.25);
  st_frame(w, Vec2d{0, 0}, lo, hi);
  const std::array<Vec2d, 7> at{Vec2d{0.25, 0.25}, Vec2d{0.9, 0.9},   Vec2d{-0.6, 1.5},
                                Vec2d{-0.6, 0.45}, Vec2d{-0.6, -0.6}, Vec2d{0.4, -0.6},
                                Vec2d{1.5, -0.6}};
  for (std::size_t r = 0; r < 7; ++r) {
    const auto b = bary_of_st(at[r]);
    if (!b) return false;
    const int region = st_region(b->y, b->z);
    label(w, at[r], std::to_string(region), c::black, -4, -6);
  }
  return true;
}

// Level curves of F(t0, t1) = |X(t0, t1) - Y|^2 over the parameter plane for the triangle t and
// query y: the curve F = r^2 is the preimage of the circle |X - Y| = r, mapped back with
// locus::barycentric. The constrained minimiser (locus::distance) is where the smallest level
// curve touches the domain.
bool level_panel(SvgWriter& w, const Triangle2<double>& t, const Vec2d& y, const Vec2d& off,
                 std::string_view caption_text) {
  const auto d = distance(y, t);
  const auto centre = barycentric(t, y);
  if (!std::isfinite(d.distance) || !centre) return false;
  st_frame(w, off, -0.7, 2.2);
  const auto to_st = [&](const Vec2d& x) -> Vec2d {
    const auto b = barycentric(t, x);
    return b ? off + Vec2d{b->y, b->z} : off;
  };
  for (const double f : {0.5, 1.0, 1.3}) {
    const double r = f * d.distance;
    w.curve(
        [&](double a) {
          return to_st(y + r * Vec2d{std::cos(a), std::sin(a)});
        },
        0, 2 * std::numbers::pi, 96, f == 1.0 ? pen(c::red, 1.6) : dashed(c::orange, 1));
  }
  point(w, off + Vec2d{centre->y, centre->z}, "", c::gray);
  point(w, off + Vec2d{d.param_b.y, d.param_b.z}, "", c::red);
  label(w, off + Vec2d{-0.7, -1.15}, std::string(caption_text) + " " + feature(d.param_b), c::red);
  return true;
}

// The triangle of figures 6.7 and 6.8: obtuse at P2, so that points of region 2 can touch
// either edge at P2.
const Triangle2<double> tri_level{{0, 0}, {2.2, 0.2}, {0.9, 0.8}};

// 6.7: level curves in region 1: (a) contact with an edge; (b) contact with a vertex.
bool fig_6_7(SvgWriter& w) {
  const std::array<Vec2d, 2> st{Vec2d{0.7, 0.6}, Vec2d{1.5, 0.05}};
  for (std::size_t k = 0; k < 2; ++k)
    if (!level_panel(w, tri_level, point_at(tri_level, st[k]),
                     Vec2d{3.2 * static_cast<double>(k), 0}, panel_names[k]))
      return false;
  return true;
}

// 6.8: level curves in region 2: (a) contact with an edge; (b) another edge; (c) a vertex.
bool fig_6_8(SvgWriter& w) {
  const std::array<Vec2d, 3> st{Vec2d{-0.1, 1.9}, Vec2d{-0.5, 1.55}, Vec2d{-0.2, 1.5}};
  for (std::size_t k = 0; k < 3; ++k)
    if (!level_panel(w, tri_level, point_at(tri_level, st[k]),
                     Vec2d{3.2 * static_cast<double>(k), 0}, panel_names[k]))
      return false;
  return true;
}

// 6.9: the triangle, its bounding box, and the regions of points closest to each vertex and each
// edge: every grid point is classified by which barycentric coordinates of its closest point
// (locus::distance) are zero.
bool fig_6_9(SvgWriter& w) {
  const Vec2d lo{-1.3, -1.2}, hi{3.4, 2.9};
  const std::vector<const char*> colours{c::red,    c::green,  c::blue, c::orange,
                                         "#1a9a9a", c::purple, c::gray};
  region_map(
      w, lo, hi, 120, 105,
      [&](const Vec2d& p) {
        const Vec3d b = distance(p, tri65).param_b;
        const int zeros = (b.x == 0) + (b.y == 0) + (b.z == 0);
        if (zeros == 0) return 6;                                  // inside
        if (zeros == 2) return b.x != 0 ? 0 : (b.y != 0 ? 1 : 2);  // vertex regions
        return b.z == 0 ? 3 : (b.x == 0 ? 4 : 5);                  // edge regions
      },
      colours, 0.3);
  draw(w, tri65, pen(c::black, 2));
  const AlignedBox2<double> box{{0, 0}, {2.2, 1.7}};
  closed(w, std::vector<Vec2d>{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}},
         dashed(c::black, 1.2));
  point(w, tri65.v0, "P\u2080");
  point(w, tri65.v1, "P\u2081");
  point(w, tri65.v2, "P\u2082");
  return true;
}

// 6.10: the nine regions of the plane around a rectangle: which of the coordinates (s, t) that
// locus::distance(point, rectangle) returns are clamped to +-extent.
bool fig_6_10(SvgWriter& w) {
  const Vec2d u = normalize(Vec2d{1, 0.35});
  const Rectangle2<double> r{{0, 0}, {u, perp(u)}, {1.2, 0.7}};
  const std::vector<const char*> colours{c::red,    c::green,  c::blue,  c::orange, c::gray,
                                         c::purple, "#1a9a9a", c::black, "#b0a000"};
  const auto region = [&](const Vec2d& p) {
    const Vec2d st = distance(p, r).param_b;
    const int i = st.x == -r.extent[0] ? 0 : (st.x == r.extent[0] ? 2 : 1);
    const int j = st.y == -r.extent[1] ? 0 : (st.y == r.extent[1] ? 2 : 1);
    return 3 * j + i;
  };
  region_map(w, Vec2d{-2.8, -2.3}, Vec2d{2.8, 2.3}, 120, 100, region, colours, 0.3);
  draw(w, r, pen(c::black, 2));
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      const Vec2d p = r.center + (1.9 * i) * r.axis[0] + (1.45 * j) * r.axis[1];
      const Vec2d st = distance(p, r).param_b;
      const std::string s = st.x == -r.extent[0]  ? "s=\u2212e\u2080"
                            : st.x == r.extent[0] ? "s=e\u2080"
                                                  : "";
      const std::string t = st.y == -r.extent[1]  ? "t=\u2212e\u2081"
                            : st.y == r.extent[1] ? "t=e\u2081"
                                                  : "";
      label(w, p, s.empty() && t.empty() ? "inside" : s + (s.empty() || t.empty() ? "" : " ") + t,
            c::black, -20, -6);
    }
  return true;
}

// ---- frustum, convex polygon, curves ------------------------------------------------------

const Frustum2<double> frustum6{{0, 0}, {0, 1}, {-1, 0}, 1.0, 3.0, 0.6};

// The frustum's trapezoid from locus::point_at(Frustum2, (s, w)).
std::vector<Vec2d> frustum_outline(const Frustum2<double>& f) {
  return {point_at(f, Vec2d{-1, 0}), point_at(f, Vec2d{1, 0}), point_at(f, Vec2d{1, 1}),
          point_at(f, Vec2d{-1, 1})};
}

// 6.11 (c): the orthogonal frustum (a trapezoid in 2D) cut from the cone with apex E, and
// closest points of a few query points (locus::distance(Vec2, Frustum2)).
bool fig_6_11(SvgWriter& w) {
  const Frustum2<double>& f = frustum6;
  const double q = f.d_max / f.d_min;
  w.segment(f.origin, f.origin + f.d_max * f.direction + q * f.l_bound * f.left,
            dashed(c::gray, 1));
  w.segment(f.origin, f.origin + f.d_max * f.direction - q * f.l_bound * f.left,
            dashed(c::gray, 1));
  closed(w, frustum_outline(f), filled(c::blue, 0.15));
  point(w, f.origin, "E", c::gray);
  w.arrow(f.origin, f.origin + 0.7 * f.direction, pen(c::gray, 1.2));
  label(w, f.origin + 0.7 * f.direction, "D", c::gray);
  for (const Vec2d& p : {Vec2d{1.6, 1.2}, Vec2d{-0.3, 3.6}, Vec2d{-2.4, 3.4}, Vec2d{0.3, 0.4}}) {
    const auto d = distance(p, f);
    if (!std::isfinite(d.distance)) return false;
    closest_link(w, d, "", "");
  }
  label(w, Vec2d{-2.2, -0.4},
        "(c) orthogonal frustum: near d = " + fmt(f.d_min) + ", far d = " + fmt(f.d_max));
  return true;
}

// 6.12: the portion of the frustum in the first quadrant of its frame (x along L, y along D,
// |x| reflected as the query does); query points in each Voronoi region and their closest
// points.
bool fig_6_12(SvgWriter& w) {
  const Frustum2<double> f{{0, 0}, {0, 1}, {1, 0}, 1.0, 3.0, 0.6};
  const std::vector<Vec2d> half{point_at(f, Vec2d{0, 0}), point_at(f, Vec2d{1, 0}),
                                point_at(f, Vec2d{1, 1}), point_at(f, Vec2d{0, 1})};
  w.arrow(Vec2d{0, 0}, Vec2d{2.8, 0}, pen(c::gray, 1));
  w.arrow(Vec2d{0, 0}, Vec2d{0, 4.0}, pen(c::gray, 1));
  label(w, Vec2d{2.8, 0}, "x (L)", c::gray);
  label(w, Vec2d{0, 4.0}, "y (D)", c::gray);
  closed(w, half, filled(c::blue, 0.15));
  label(w, half[1], "(l, n)", c::blue, 6, -14);
  label(w, half[2], "(fl/n, f)", c::blue, 6, 0);
  for (const Vec2d& p : {Vec2d{0.3, 0.4}, Vec2d{1.1, 0.3}, Vec2d{1.9, 1.6}, Vec2d{2.4, 3.6},
                         Vec2d{0.8, 3.7}, Vec2d{0.5, 2.0}}) {
    const auto d = distance(p, f);
    if (!std::isfinite(d.distance)) return false;
    if (d.distance > 0)
      closest_link(w, d, "", "");
    else
      point(w, p, "inside", c::red);
  }
  return true;
}

// 6.13: point to a convex polygon (locus::distance_to_convex_polygon, O(log n)): only the edges
// visible from the query point (the point is strictly outside their lines, exact
// locus::orientation) can hold the closest point; they are dotted.
bool fig_6_13(SvgWriter& w) {
  std::vector<Vec2d> v;
  for (int k = 0; k < 9; ++k) {
    const double a = 2 * std::numbers::pi * k / 9 + 0.2;
    v.push_back(Vec2d{1.6 * std::cos(a), 1.1 * std::sin(a)});
  }
  const Vec2d p{2.9, 1.6};
  const auto d = distance_to_convex_polygon(p, std::span<const Vec2d>(v));
  if (!std::isfinite(d.distance)) return false;
  closed(w, v, filled(c::blue, 0.1));
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2d a = v[i], b = v[(i + 1) % v.size()];
    if (orientation(Triangle2<double>{a, b, p}) == Sign::negative) {
      SvgStyle st = pen(c::orange, 3.0);
      st.dash = {2, 4};
      w.segment(a, b, st);
      w.segment(p, a, dashed(c::light, 1));
      w.segment(p, b, dashed(c::light, 1));
    }
  }
  closest_link(w, d, "Y", "");
  return true;
}

// 6.14: the closest point on a quadratic curve (an ellipse, locus::distance(Vec2, Ellipse2)):
// the connecting segment is normal to the curve there.
bool fig_6_14(SvgWriter& w) {
  const Vec2d u = normalize(Vec2d{1, 0.3});
  const Ellipse2<double> e{{0, 0}, {u, perp(u)}, {2.0, 1.0}};
  draw(w, e, pen(c::blue, 2));
  for (const Vec2d& p : {Vec2d{2.2, 1.6}, Vec2d{-0.6, 0.2}, Vec2d{-1.0, -1.9}}) {
    const auto d = distance(p, e);
    if (!std::isfinite(d.distance)) return false;
    closest_link(w, d, "Y", "");
  }
  return true;
}

// 6.15: the closest point on a polynomial curve (a cubic Bezier curve, locus::distance(Vec2,
// BezierCurve2): every root of the derivative of the squared distance).
bool fig_6_15(SvgWriter& w) {
  const BezierCurve2<double> curve{{{0, 0}, {1.0, 2.2}, {2.4, -1.2}, {3.4, 1.0}}};
  w.curve([&](double t) { return point_at(curve, t); }, 0, 1, 120, pen(c::blue, 2));
  w.polyline(curve.control, dashed(c::light, 1));
  for (const Vec2d& p : {Vec2d{1.6, 1.6}, Vec2d{2.0, -0.9}, Vec2d{3.9, 0.2}}) {
    const auto d = distance(p, curve);
    if (!std::isfinite(d.distance)) return false;
    closest_link(w, d, "Y", "t = " + fmt(d.param_b));
  }
  return true;
}

// ---- linear components ----------------------------------------------------------------------

template <class A, class B>
bool linear_panel(SvgWriter& w, const A& a, const B& b, const Vec2d& at, std::string_view name) {
  const auto d = distance(a, b);
  if (!std::isfinite(d.distance)) return false;
  closest_link(w, d, "", "");
  std::string text = std::string(name) + " dist = " + fmt(d.distance);
  if (!d.unique) text += " (not unique)";
  label(w, at, text);
  return true;
}

void draw_ray(SvgWriter& w, const Ray<double, 2>& r, double len, const char* colour) {
  w.segment(r.origin, r.origin + len * r.direction, pen(colour));
  w.arrow(r.origin + (len - 0.3) * r.direction, r.origin + len * r.direction, pen(colour));
  w.point(r.origin, dot(colour, 3));
}

void draw_line(SvgWriter& w, const Line2<double>& l, double len, const char* colour) {
  w.segment(l.origin - len * l.direction, l.origin + len * l.direction, pen(colour));
}

// 6.16: line-line: (a) intersecting, distance 0; (b) parallel, positive distance.
bool fig_6_16(SvgWriter& w) {
  const Line2<double> a0{{0, 0}, normalize(Vec2d{1, 0.3})},
      b0{{0.3, -0.5}, normalize(Vec2d{0.2, 1})};
  const Line2<double> a1{{4.2, 0}, normalize(Vec2d{1, 0.3})},
      b1{{4.2, 0.8}, normalize(Vec2d{-1, -0.3})};
  draw_line(w, a0, 1.5, c::blue);
  draw_line(w, b0, 1.2, c::green);
  draw_line(w, a1, 1.5, c::blue);
  draw_line(w, b1, 1.5, c::green);
  return linear_panel(w, a0, b0, Vec2d{-1.4, -1.6}, "(a)") &&
         linear_panel(w, a1, b1, Vec2d{2.8, -1.6}, "(b)");
}

// 6.17: line-ray: (a) the ray crosses the line; (b) it points away, its origin is closest.
bool fig_6_17(SvgWriter& w) {
  const Vec2d dl = normalize(Vec2d{1, 0.2});
  const Line2<double> l0{{0, 0}, dl}, l1{{4.2, 0}, dl};
  const Ray<double, 2> r0{{0.2, 1.0}, normalize(Vec2d{0.3, -1})},
      r1{{4.4, 0.7}, normalize(Vec2d{0.5, 1})};
  draw_line(w, l0, 1.6, c::blue);
  draw_line(w, l1, 1.6, c::blue);
  draw_ray(w, r0, 1.8, c::green);
  draw_ray(w, r1, 1.3, c::green);
  return linear_panel(w, l0, r0, Vec2d{-1.4, -1.3}, "(a)") &&
         linear_panel(w, l1, r1, Vec2d{2.8, -1.3}, "(b)");
}

// 6.18: line-segment: (a) the segment crosses the line; (b) an end point is closest.
bool fig_6_18(SvgWriter& w) {
  const Vec2d dl = normalize(Vec2d{1, 0.2});
  const Line2<double> l0{{0, 0}, dl}, l1{{4.2, 0}, dl};
  const Segment<double, 2> s0{{-0.2, 0.9}, {0.6, -0.8}}, s1{{3.8, 0.6}, {4.9, 1.6}};
  draw_line(w, l0, 1.6, c::blue);
  draw_line(w, l1, 1.6, c::blue);
  draw(w, s0, pen(c::green));
  draw(w, s1, pen(c::green));
  return linear_panel(w, l0, s0, Vec2d{-1.4, -1.3}, "(a)") &&
         linear_panel(w, l1, s1, Vec2d{2.8, -1.3}, "(b)");
}

// 6.19: nonparallel rays: (a) crossing; (b) an end point to an interior point; (c) end points.
bool fig_6_19(SvgWriter& w) {
  const std::array<std::pair<Ray<double, 2>, Ray<double, 2>>, 3> rays{{
      {{{0, 0}, normalize(Vec2d{1, 0.2})}, {{0.4, -0.6}, normalize(Vec2d{0.3, 1})}},
      {{{3.0, 0}, normalize(Vec2d{1, 0.2})}, {{3.6, 0.7}, normalize(Vec2d{0.2, 1})}},
      {{{6.0, 0}, normalize(Vec2d{1, 0.2})}, {{5.6, 0.6}, normalize(Vec2d{-0.4, 1})}},
  }};
  for (std::size_t k = 0; k < 3; ++k) {
    draw_ray(w, rays[k].first, 2.0, c::blue);
    draw_ray(w, rays[k].second, 1.5, c::green);
    if (!linear_panel(w, rays[k].first, rays[k].second,
                      Vec2d{3.0 * static_cast<double>(k) - 0.2, -1.0}, panel_names[k]))
      return false;
  }
  return true;
}

// 6.20: the level curves of F(t0, t1) = |A(t0) - B(t1)|^2 over the quadrant t0, t1 >= 0 of two
// rays, and the boundary minimum locus::distance(ray, ray) finds: (a) at (t0, 0), (b) at (0, 0).
// The level curve F = r^2 is the preimage of the circle |A - B| = r under the affine map
// (t0, t1) -> A(t0) - B(t1), inverted with locus::barycentric of the triangle
// (A0 - B0, A0 - B0 + dA, A0 - B0 - dB).
bool fig_6_20(SvgWriter& w) {
  const std::array<std::pair<Ray<double, 2>, Ray<double, 2>>, 2> rays{{
      {{{0, 0}, normalize(Vec2d{1, 0.15})}, {{1.0, 0.9}, normalize(Vec2d{0.3, 1})}},
      {{{0, 0}, normalize(Vec2d{1, 0.15})}, {{-0.6, 0.7}, normalize(Vec2d{-0.2, 1})}},
  }};
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& [a, b] = rays[k];
    const auto d = distance(a, b);
    if (!std::isfinite(d.distance)) return false;
    const Vec2d x0 = a.origin - b.origin;
    const Triangle2<double> map{x0, x0 + a.direction, x0 - b.direction};
    const auto unconstrained = barycentric(map, Vec2d{0, 0});
    if (!unconstrained) return false;
    const Vec2d off{4.2 * static_cast<double>(k), 0};
    const auto to_st = [&](const Vec2d& x) -> Vec2d {
      const auto bc = barycentric(map, x);
      return bc ? off + Vec2d{bc->y, bc->z} : off;
    };
    // The domain: the quadrant.
    cell(w, off, off + Vec2d{2.4, 2.4}, c::light, 0.3);
    w.arrow(off + Vec2d{-1.4, 0}, off + Vec2d{2.6, 0}, pen(c::gray, 1));
    w.arrow(off + Vec2d{0, -1.4}, off + Vec2d{0, 2.6}, pen(c::gray, 1));
    label(w, off + Vec2d{2.6, 0}, "t\u2080", c::black, 2, 4);
    label(w, off + Vec2d{0, 2.6}, "t\u2081", c::black, 4, -12);
    for (const double f : {0.5, 1.0, 1.5}) {
      const double r = f * d.distance;
      w.curve(
          [&](double t) {
            return to_st(r * Vec2d{std::cos(t), std::sin(t)});
          },
          0, 2 * std::numbers::pi, 120, f == 1.0 ? pen(c::red, 1.6) : dashed(c::orange, 1));
    }
    point(w, off + Vec2d{unconstrained->y, unconstrained->z}, "", c::gray);
    const Vec2d m = off + Vec2d{d.param_a, d.param_b};
    point(w, m, d.param_a > 0 ? "(t\u0302\u2080, 0)" : "(0, 0)", c::red);
    label(w, off + Vec2d{-1.4, -1.7}, panel_names[k]);
  }
  return true;
}

// 6.21: parallel rays: (a) the same direction; (b) opposite directions, overlapping;
// (c) opposite directions, not overlapping. locus reports unique = false when infinitely many
// closest pairs exist.
bool fig_6_21(SvgWriter& w) {
  const Vec2d d = normalize(Vec2d{1, 0.1});
  const std::array<std::pair<Ray<double, 2>, Ray<double, 2>>, 3> rays{{
      {{{0, 0}, d}, {{0.6, 0.6}, d}},
      {{{0, -2.0}, d}, {{1.6, -1.4}, -d}},
      {{{0, -4.0}, d}, {{-0.8, -3.4}, -d}},
  }};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& [a, b] = rays[k];
    draw_ray(w, a, 2.4, c::blue);
    draw_ray(w, b, 2.4, c::green);
    const auto r = distance(a, b);
    if (!std::isfinite(r.distance)) return false;
    closest_link(w, r, "", "");
    label(w, Vec2d{3.0, a.origin.y + 0.1},
          std::string(panel_names[k]) + " dist " + fmt(r.distance) +
              (r.unique ? ", unique" : ", not unique"));
  }
  return true;
}

// 6.22: the analogue of figure 6.4 for a segment S at current minimum distance mu from a
// polyline: the points within mu of S form a capsule, its bounding rectangle is the rejection
// test. Each labelled polyline segment is measured with locus::distance(S, segment).
bool fig_6_22(SvgWriter& w) {
  const Segment<double, 2> s{{-0.6, -0.2}, {0.6, 0.2}};
  const std::vector<Vec2d> pl{{-2.1, 0.3}, {-0.5, 1.3}, {0.6, 1.9},  {2.1, 0.5},
                              {2.4, 0.0},  {2.1, -1.5}, {0.8, -2.3}, {-0.6, -1.0}};
  const double mu = distance(s, Segment<double, 2>{pl[0], pl[1]}).distance;
  if (!std::isfinite(mu)) return false;
  const Vec2d lo{std::min(s.p0.x, s.p1.x) - mu, std::min(s.p0.y, s.p1.y) - mu};
  const Vec2d hi{std::max(s.p0.x, s.p1.x) + mu, std::max(s.p0.y, s.p1.y) + mu};
  cell(w, lo, hi, pale(c::gray, 0.2));
  closed(w, std::vector<Vec2d>{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, dashed(c::black, 1));
  // The capsule {X : dist(X, S) <= mu}: two half circles joined by the offset segments.
  const Vec2d dir = normalize(s.p1 - s.p0), n = perp(dir);
  const double a = std::atan2(n.y, n.x);
  w.arc(s.p1, mu, a - std::numbers::pi, a, dashed(c::red, 1.2));
  w.arc(s.p0, mu, a, a + std::numbers::pi, dashed(c::red, 1.2));
  w.segment(s.p0 + mu * n, s.p1 + mu * n, dashed(c::red, 1.2));
  w.segment(s.p0 - mu * n, s.p1 - mu * n, dashed(c::red, 1.2));
  draw(w, s, pen(c::red, 2.6));
  label(w, s.p1, "S", c::red, 6, -6);
  double best = mu;
  Segment<double, 2> best_link{};
  for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
    const Segment<double, 2> e{pl[i], pl[i + 1]};
    const auto d = distance(s, e);
    if (!std::isfinite(d.distance)) return false;
    if (i == 0 || d.distance < best) {
      best = d.distance;
      best_link = {d.closest[0], d.closest[1]};
    }
    if (i % 2 == 1) {
      w.segment(e.p0, e.p1, pen(c::light, 1.2));
      continue;
    }
    draw(w, e, pen(c::blue, 2));
    const bool outside = std::max(e.p0.x, e.p1.x) < lo.x || std::min(e.p0.x, e.p1.x) > hi.x ||
                         std::max(e.p0.y, e.p1.y) < lo.y || std::min(e.p0.y, e.p1.y) > hi.y;
    const std::string status = i == 0            ? "sets μ = " + fmt(mu)
                               : outside         ? "rejected by the rectangle"
                               : d.distance < mu ? "updates μ to " + fmt(d.distance)
                                                 : "dist " + fmt(d.distance) + " > μ";
    const Vec2d centre = lerp(s.p0, s.p1, 0.5);
    w.text(far_end(e, centre), "S" + std::to_string(i / 2) + ": " + status,
           side_label(far_end(e, centre), centre));
  }
  w.segment(best_link.p0, best_link.p1, pen(c::green, 1.4));
  point(w, best_link.p1, "", c::green);
  return true;
}

// A right-angle mark at `at` between the unit directions u (along the object) and v (towards the
// other closest point).
void right_angle(SvgWriter& w, const Vec2d& at, Vec2d u, const Vec2d& v, double size) {
  if (dot(u, v) < 0) u = -u;
  if (perp_dot(v, u) < 0) u = -u;  // keep the mark on one side, whatever the tangent's sign
  w.polyline(std::vector<Vec2d>{at + size * u, at + size * (u + v), at + size * v},
             pen(c::gray, 1));
}

// 6.23: the segment connecting the closest points is perpendicular to both objects: (a) a
// segment and a cubic Bézier curve, (b) a line and an ellipse given as a general quadratic curve.
// The right-angle marks use the tangents at the returned points (the curve's derivative, the
// conic's gradient), not the drawing.
bool fig_6_23(SvgWriter& w) {
  const BezierCurve2<double> curve{{{0, 0}, {0.7, 2.6}, {2.2, -1.0}, {3.2, 1.4}}};
  const Segment<double, 2> seg{{-0.3, 2.0}, {2.2, 1.45}};
  w.curve([&](double t) { return point_at(curve, t); }, 0, 1, 120, pen(c::blue, 2));
  w.polyline(curve.control, dashed(c::light, 1));
  draw(w, seg, pen(c::green, 2));
  const auto a = distance(seg, curve);
  // The figure's point: an interior pair on both, where the connecting segment is perpendicular.
  if (!std::isfinite(a.distance) || !(a.param_a > 0 && a.param_a < 1) ||
      !(a.param_b > 0 && a.param_b < 1))
    return false;
  const Vec2d link_a = normalize(a.closest[1] - a.closest[0]);
  right_angle(w, a.closest[0], normalize(seg.p1 - seg.p0), link_a, 0.14);
  right_angle(w, a.closest[1], normalize(derivative_at(curve, a.param_b, 1)), -link_a, 0.14);
  closest_link(w, a, "", "");
  label(w, Vec2d{0.4, -1.5}, "(a) segment, Bézier: dist = " + fmt(a.distance));

  // The ellipse with half-axes 1.6, 0.8 rotated by 30 degrees about (6.6, 0.6), handed to the
  // query as a general quadratic curve.
  const double ang = std::numbers::pi / 6;
  const Ellipse2<double> e{
      {6.6, 0.6}, {{std::cos(ang), std::sin(ang)}, {-std::sin(ang), std::cos(ang)}}, {1.6, 0.8}};
  const QuadraticCurve2<double> q = to_quadratic(e);
  const Line2<double> line{{7.2, 2.35}, normalize(Vec2d{1, -0.35})};
  w.curve([&](double t) { return point_at(e, t); }, 0, 2 * std::numbers::pi, 160, pen(c::blue, 2));
  draw_line(w, line, 2.0, c::green);
  const auto b = distance(line, q);
  if (!std::isfinite(b.distance) || !(b.distance > 0)) return false;
  const Vec2d x = b.closest[1];
  const Vec2d grad{2 * q.a * x.x + q.b * x.y + q.d, q.b * x.x + 2 * q.c * x.y + q.e};
  const Vec2d link_b = normalize(b.closest[0] - b.closest[1]);
  right_angle(w, b.closest[0], line.direction, -link_b, 0.14);
  right_angle(w, x, normalize(perp(grad)), link_b, 0.14);
  closest_link(w, b, "", "");
  label(w, Vec2d{5.4, -1.5}, "(b) line, conic: dist = " + fmt(b.distance));
  return true;
}

}  // namespace

std::vector<Figure> chapter6_distance_figures() {
  return {
      {"6.1", "distance(Vec2, Line2)", fig_6_1},
      {"6.2", "distance(Vec2, Ray2)", fig_6_2},
      {"6.3", "distance(Vec2, Segment2)", fig_6_3},
      {"6.4", "distance(Vec2, Segment2), distance(Vec2, Polyline2) and its strip rejection",
       fig_6_4},
      {"6.5", "distance(Vec2, Triangle2)", fig_6_5},
      {"6.6", "barycentric, point_at(Triangle2, st)", fig_6_6},
      {"6.7", "distance(Vec2, Triangle2), barycentric (level curves)", fig_6_7},
      {"6.8", "distance(Vec2, Triangle2), barycentric (level curves)", fig_6_8},
      {"6.9", "distance(Vec2, Triangle2) on a grid (which barycentric coordinates vanish)",
       fig_6_9},
      {"6.10", "distance(Vec2, Rectangle2) on a grid (which coordinates are clamped)", fig_6_10},
      {"6.11", "distance(Vec2, Frustum2), point_at(Frustum2)", fig_6_11},
      {"6.12", "distance(Vec2, Frustum2)", fig_6_12},
      {"6.13", "distance_to_convex_polygon, orientation (visible edges)", fig_6_13},
      {"6.14", "distance(Vec2, Ellipse2)", fig_6_14},
      {"6.15", "distance(Vec2, BezierCurve2), point_at(BezierCurve2)", fig_6_15},
      {"6.16", "distance(Line2, Line2)", fig_6_16},
      {"6.17", "distance(Line2, Ray2)", fig_6_17},
      {"6.18", "distance(Line2, Segment2)", fig_6_18},
      {"6.19", "distance(Ray2, Ray2)", fig_6_19},
      {"6.20", "distance(Ray2, Ray2), barycentric (level curves)", fig_6_20},
      {"6.21", "distance(Ray2, Ray2), unique", fig_6_21},
      {"6.22", "distance(Segment2, Segment2)", fig_6_22},
      {"6.23", "distance(Segment2, BezierCurve2), distance(Line2, QuadraticCurve2)", fig_6_23},
  };
}

}  // namespace locus_gallery
