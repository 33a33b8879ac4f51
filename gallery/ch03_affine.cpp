// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 3 (linear transformations, affine spaces, products, barycentric coordinates):
// figures 3.19-3.42. Transformed shapes are images under locus transforms; projections, cross
// products, triple products, frame coordinates and barycentric coordinates come from locus.
#include "gallery.hpp"

#include <locus/core/affine.hpp>
#include <locus/core/angle.hpp>
#include <locus/core/barycentric.hpp>
#include <locus/core/frame.hpp>
#include <locus/core/products.hpp>
#include <locus/core/transform.hpp>
#include <locus/primitives/tetrahedron.hpp>

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

// A linear map applied to the house and to the basis vectors i, j (its matrix columns).
void linear_figure(SvgWriter& w, const Affine2d& a) {
  const std::vector<Vec2d> h = house(Vec2d{0.3, 0.2}, 1.0);
  closed(w, h, filled(c::blue, 0.15));
  closed(w, map_points(a, h), filled(c::red, 0.15));
  w.arrow(Vec2d{0, 0}, Vec2d{1, 0}, pen(c::blue, 1.2));
  w.arrow(Vec2d{0, 0}, Vec2d{0, 1}, pen(c::blue, 1.2));
  const Vec2d ti = apply_vector(a, Vec2d{1, 0}), tj = apply_vector(a, Vec2d{0, 1});
  vector(w, Vec2d{0, 0}, ti, "T(i)", c::red, -12);
  vector(w, Vec2d{0, 0}, tj, "T(j)", c::red);
}

bool fig_3_19(SvgWriter& w) {
  linear_figure(w, scaling(Vec2d{0, 0}, 2.0));
  return true;
}
bool fig_3_20(SvgWriter& w) {
  linear_figure(w, scaling_axes(Vec2d{0, 0}, Vec2d{2.0, 0.6}));
  return true;
}
bool fig_3_21(SvgWriter& w) {
  linear_figure(w, rotation_2d(pi_v<double> / 5));
  return true;
}
bool fig_3_22(SvgWriter& w) {
  linear_figure(w, shear(Vec2d{0, 0}, Vec2d{1, 0}, pi_v<double> / 6));
  return true;
}

// 3.23: v = Q - P.
bool fig_3_23(SvgWriter& w) {
  const Vec2d p{0.5, 0.4}, q{2.8, 1.6};
  point(w, p, "P");
  point(w, q, "Q");
  vector(w, p, p + (q - p), "v = Q \u2212 P", c::blue);
  return true;
}

// 3.24: (Q - P) + (R - Q) = R - P.
bool fig_3_24(SvgWriter& w) {
  const Vec2d p{0, 0}, q{2.5, 0.6}, r{1.6, 2.2};
  const Vec2d sum = (q - p) + (r - q);
  vector(w, p, p + (q - p), "Q \u2212 P", c::blue, -12);
  vector(w, q, q + (r - q), "R \u2212 Q", c::red, -12);
  vector(w, p, p + sum, "R \u2212 P", c::green);
  point(w, p, "P");
  point(w, q, "Q");
  point(w, r, "R");
  return true;
}

// 3.25: R = (1 - t) P0 + t P1 by locus::affine_combination for several t.
bool fig_3_25(SvgWriter& w) {
  const Vec2d p0{0, 0}, p1{2, 1};
  w.line(p0, p1 - p0, pen(c::light, 1));
  for (double t : {-0.5, 0.25, 0.5, 1.5}) {
    const auto r =
        affine_combination(std::array<Vec2d, 2>{p0, p1}, std::array<double, 2>{1 - t, t});
    if (r.status != Status::ok) return false;
    w.point(r.point, dot(c::green));
    label(w, r.point, "t = " + fmt(t), c::green, 6, -16);
  }
  point(w, p0, "P\u2080 (t = 0)", c::blue);
  point(w, p1, "P\u2081 (t = 1)", c::blue);
  return true;
}

// 3.26: an affine combination of four points, shown as P0 + sum w_i (P_i - P0).
bool fig_3_26(SvgWriter& w) {
  const std::array<Vec2d, 4> p{Vec2d{0, 0}, Vec2d{3, 0.4}, Vec2d{2.4, 2.2}, Vec2d{0.3, 1.8}};
  const std::array<double, 4> wt{0.1, 0.4, 0.3, 0.2};
  const auto r = affine_combination(p, wt);
  if (r.status != Status::ok) return false;
  closed(w, std::vector<Vec2d>(p.begin(), p.end()), pen(c::light, 1));
  Vec2d at = p[0];
  for (std::size_t i = 1; i < 4; ++i) {
    const Vec2d step = wt[i] * (p[i] - p[0]);
    w.arrow(at, at + step, pen(c::orange, 1.4));
    at += step;
  }
  const char* names[] = {"P\u2080", "P\u2081", "P\u2082", "P\u2083"};
  for (std::size_t i = 0; i < 4; ++i)
    point(w, p[i], std::string(names[i]) + " (" + fmt(wt[i], 1) + ")");
  point(w, r.point, "R = \u03a3 w\u1d62P\u1d62", c::green);
  return true;
}

// 3.27: the angle between u and v and the law of cosines for |u - v|.
bool fig_3_27(SvgWriter& w) {
  const Vec2d o{0, 0}, u{2.6, 0.5}, v{1.0, 1.8};
  const double th = angle_between(u, v);
  vector(w, o, u, "u", c::blue, -12);
  vector(w, o, v, "v", c::red);
  vector(w, v, v + (u - v), "u \u2212 v", c::green);
  angle_mark(w, o, u, v, 0.5, "\u03b8");
  const double side = law_of_cosines_side(length(u), length(v), th);
  label(w, Vec2d{0.2, -0.5},
        "|u \u2212 v| = " + fmt(length(u - v), 3) + ",  law of cosines: " + fmt(side, 3), c::black,
        0, 0);
  return true;
}

// 3.28: the parallelogram rule: diagonals u + v and u - v.
bool fig_3_28(SvgWriter& w) {
  const Vec2d o{0, 0}, u{2.5, 0.3}, v{0.9, 1.6};
  w.polyline(std::vector<Vec2d>{u, u + v, v}, dashed(c::gray));
  vector(w, o, u, "u", c::blue, -12);
  vector(w, o, v, "v", c::red);
  vector(w, o, u + v, "u + v", c::green);
  vector(w, v, v + (u - v), "u \u2212 v", c::purple);
  return true;
}

// 3.29: the projection of u onto v (locus::project_onto) and the perpendicular rest.
bool fig_3_29(SvgWriter& w) {
  const Vec2d o{0, 0}, v{3.0, 0.8}, u{1.4, 1.8};
  const Vec2d par = project_onto(u, v), perp_part = reject_from(u, v);
  vector(w, o, v, "v", c::red, -12);
  vector(w, o, u, "u", c::blue);
  w.arrow(o, par, pen(c::green, 3));
  label(w, par, "proj\u1d65 u", c::green, -10, -20);
  w.segment(par, par + perp_part, dashed(c::gray));
  right_angle_mark(w, par, -v, perp_part, 0.15);
  return true;
}

// 3.30: an obtuse angle: the projection points against v.
bool fig_3_30(SvgWriter& w) {
  const Vec2d o{0, 0}, v{2.4, 0.5}, u{-1.3, 1.5};
  const Vec2d par = project_onto(u, v);
  w.line(o, v, pen(c::light, 1));
  vector(w, o, v, "v", c::red, -12);
  vector(w, o, u, "u", c::blue);
  w.arrow(o, par, pen(c::green, 3));
  label(w, par, "proj\u1d65 u", c::green, -10, -20);
  w.segment(par, u, dashed(c::gray));
  right_angle_mark(w, par, v, u - par, 0.15);
  angle_mark(w, o, v, u, 0.45,
             "\u03b8 > 90\u00b0, cos \u03b8 = " + fmt(std::cos(angle_between(u, v))));
  return true;
}

void cross_figure(SvgWriter& w, bool both) {
  w.set_camera(camera({5, 3.2, 3}));
  const Vec3d o{0, 0, 0}, u{1.8, 0.2, 0}, v{0.5, 1.5, 0};
  const Vec3d n = cross(u, v);
  closed(w, std::vector<Vec3d>{o, u, u + v, v}, filled(c::gray, 0.12, 0.8));
  w.arrow(o, u, pen(c::blue));
  w.arrow(o, v, pen(c::red));
  w.arrow(o, n * 0.6, pen(c::green));
  label(w, u, "u", c::blue);
  label(w, v, "v", c::red);
  label(w, n * 0.6, "u \u00d7 v", c::green);
  if (both) {
    const Vec3d m = cross(v, u);
    w.arrow(o, m * 0.6, pen(c::purple));
    label(w, m * 0.6, "v \u00d7 u = \u2212(u \u00d7 v)", c::purple);
  } else {
    label(w, u + v, "area = |u \u00d7 v| = " + fmt(length(n)), c::gray);
  }
}
bool fig_3_31(SvgWriter& w) {
  cross_figure(w, false);
  return true;
}
bool fig_3_32(SvgWriter& w) {
  cross_figure(w, true);
  return true;
}

std::array<Vec3d, 8> parallelepiped(const Vec3d& u, const Vec3d& v, const Vec3d& x) {
  std::array<Vec3d, 8> cs{};
  for (std::size_t i = 0; i < 8; ++i)
    cs[i] = (i & 1 ? u : Vec3d{}) + (i & 2 ? v : Vec3d{}) + (i & 4 ? x : Vec3d{});
  return cs;
}

// 3.33: the parallelepiped spanned by three vectors.
bool fig_3_33(SvgWriter& w) {
  w.set_camera(camera({5, 3.4, 2.8}));
  const Vec3d u{2, 0.2, 0}, v{0.4, 1.6, 0}, x{0.5, 0.4, 1.3};
  box_edges(w, parallelepiped(u, v, x), pen(c::gray, 1));
  w.arrow(Vec3d{}, u, pen(c::blue));
  w.arrow(Vec3d{}, v, pen(c::red));
  w.arrow(Vec3d{}, x, pen(c::green));
  label(w, u, "u", c::blue);
  label(w, v, "v", c::red);
  label(w, x, "w", c::green);
  return true;
}

// 3.34: volume = w . (u x v) = locus::triple_product; the height is w projected onto u x v.
bool fig_3_34(SvgWriter& w) {
  w.set_camera(camera({5, 3.4, 2.8}));
  const Vec3d u{2, 0.2, 0}, v{0.4, 1.6, 0}, x{0.5, 0.4, 1.3};
  box_edges(w, parallelepiped(u, v, x), pen(c::light, 1));
  const Vec3d n = cross(u, v);
  const Vec3d h = project_onto(x, n);
  w.arrow(Vec3d{}, u, pen(c::blue));
  w.arrow(Vec3d{}, v, pen(c::red));
  w.arrow(Vec3d{}, x, pen(c::green));
  w.arrow(Vec3d{}, normalize(n) * 1.8, pen(c::purple, 1.2));
  w.segment(x, x - (x - h), dashed(c::gray));
  w.segment(Vec3d{}, h, pen(c::orange, 2.5));
  label(w, normalize(n) * 1.8, "u \u00d7 v", c::purple);
  label(w, h * 0.5, "height", c::orange);
  label(w, x, "w", c::green);
  label(w, u + v, "volume = w\u00b7(u \u00d7 v) = " + fmt(triple_product(x, u, v)), c::black, 10,
        -10);
  return true;
}

// 3.35: a point's coordinates relative to a skew frame, from locus::to_local_point.
bool fig_3_35(SvgWriter& w) {
  const Frame2d f{{0.5, 0.3}, {Vec2d{1.2, 0.3}, Vec2d{0.4, 1.0}}};
  const Vec2d p{3.1, 2.4};
  const Vec2d a = to_local_point(f, p);
  const Vec2d s0 = f.origin + a.x * f.axis[0];
  w.polyline(std::vector<Vec2d>{f.origin, s0, p}, dashed(c::gray));
  frame(w, f, c::blue, "O", "v\u2081", "v\u2082");
  point(w, p, "P = O + " + fmt(a.x) + " v\u2081 + " + fmt(a.y) + " v\u2082", c::red);
  return true;
}

// 3.36: an affine map keeps the ratio in which R divides PQ (locus::barycentric of the images).
bool fig_3_36(SvgWriter& w) {
  const Vec2d p{0, 0}, q{2, 0.5};
  const double t = 0.3;
  const Vec2d r = lerp(p, q, t);
  const Affine2d a = compose(translation(Vec2d{3, 0.5}),
                             compose(rotation_2d(0.6), shear(Vec2d{0, 0}, Vec2d{1, 0}, 0.5)));
  const Vec2d tp = apply_point(a, p), tq = apply_point(a, q), tr = apply_point(a, r);
  const auto b = barycentric(tr, tp, tq);
  if (!b.valid) return false;
  w.segment(p, q, pen(c::blue));
  w.segment(tp, tq, pen(c::red));
  point(w, p, "P");
  point(w, q, "Q");
  point(w, r, "R (t = " + fmt(t) + ")", c::blue);
  point(w, tp, "T(P)");
  point(w, tq, "T(Q)");
  point(w, tr, "T(R) (t = " + fmt(b.w[1]) + ")", c::red);
  return true;
}

// 3.37 - 3.39: an affine map T respects vector sums, scaling and point + vector.
const Affine2d& sample_map() {
  static const Affine2d a =
      compose(translation(Vec2d{3.2, -0.4}),
              compose(rotation_2d(0.5), scaling_axes(Vec2d{0, 0}, Vec2d{1.2, 0.7})));
  return a;
}
bool fig_3_37(SvgWriter& w) {
  const Affine2d& a = sample_map();
  const Vec2d o{0, 0}, u{1.5, 0.2}, v{0.4, 1.1};
  vector(w, o, u, "u", c::blue, -12);
  vector(w, u, u + v, "v", c::red, -12);
  vector(w, o, u + v, "u + v", c::green);
  const Vec2d to = apply_point(a, o), tu = apply_vector(a, u), tv = apply_vector(a, v);
  vector(w, to, to + tu, "T(u)", c::blue, -12);
  vector(w, to + tu, to + tu + tv, "T(v)", c::red, -12);
  vector(w, to, to + apply_vector(a, u + v), "T(u + v)", c::green);
  return true;
}
bool fig_3_38(SvgWriter& w) {
  const Affine2d& a = sample_map();
  const Vec2d o{0, 0}, v{1.0, 0.5};
  const double k = 2.0;
  vector(w, o, k * v, "2v", c::green, 12);
  vector(w, o, v, "v", c::blue, -12);
  const Vec2d to = apply_point(a, o);
  vector(w, to, to + apply_vector(a, k * v), "T(2v) = 2T(v)", c::green, 12);
  vector(w, to, to + apply_vector(a, v), "T(v)", c::blue, -12);
  return true;
}
bool fig_3_39(SvgWriter& w) {
  const Affine2d& a = sample_map();
  const Vec2d p{0.2, 0.3}, v{1.4, 0.8};
  point(w, p, "P");
  vector(w, p, p + v, "v", c::blue);
  point(w, p + v, "P + v", c::green);
  const Vec2d tp = apply_point(a, p);
  point(w, tp, "T(P)");
  vector(w, tp, tp + apply_vector(a, v), "T(v)", c::blue);
  point(w, apply_point(a, p + v), "T(P + v)", c::green);
  return true;
}

// 3.40: two rotations about different centres compose to one rotation; its centre is the
// fixed point, solved with locus::inverse.
bool fig_3_40(SvgWriter& w) {
  const Vec2d c1{0, 0}, c2{3, 0};
  const Affine2d r1 = rotation(c1, pi_v<double> / 4), r2 = rotation(c2, pi_v<double> / 3);
  const Affine2d both = compose(r2, r1);
  // Fixed point c: (I - L) c = t.
  const auto inv = inverse(Mat2d::identity() - both.linear);
  if (!inv) return false;
  const Vec2d fixed = *inv * both.translation;
  const std::vector<Vec2d> h = house(Vec2d{1.0, 0.3}, 0.8);
  closed(w, h, filled(c::blue, 0.15));
  closed(w, map_points(r1, h), filled(c::orange, 0.15));
  closed(w, map_points(both, h), filled(c::red, 0.15));
  point(w, c1, "C\u2081", c::orange);
  point(w, c2, "C\u2082", c::red);
  point(w, fixed, "centre of R\u2082\u2218R\u2081", c::purple);
  const double total = signed_angle(Vec2d{1, 0}, apply_vector(both, Vec2d{1, 0}));
  w.arc(fixed, length(h[0] - fixed), atan2_positive(h[0].y - fixed.y, h[0].x - fixed.x),
        atan2_positive(h[0].y - fixed.y, h[0].x - fixed.x) + total, dashed(c::purple));
  return true;
}

// 3.41: affine coordinates (frame P0; P1 - P0, P2 - P0) and barycentric coordinates of P.
bool fig_3_41(SvgWriter& w) {
  const Vec2d p0{0, 0}, p1{2.4, 0.3}, p2{0.8, 1.9}, p{1.3, 0.8};
  for (int panel = 0; panel < 2; ++panel) {
    const Vec2d off{3.6 * panel, 0};
    const Vec2d a = off + p0, b = off + p1, cc = off + p2, q = off + p;
    closed(w, std::vector<Vec2d>{a, b, cc}, pen(c::gray, 1.2));
    if (panel == 0) {
      const Frame2d f{a, {b - a, cc - a}};
      const Vec2d l = to_local_point(f, q);
      w.polyline(std::vector<Vec2d>{a, a + l.x * f.axis[0], q}, dashed(c::blue));
      w.arrow(a, b, pen(c::blue, 1.2));
      w.arrow(a, cc, pen(c::blue, 1.2));
      point(w, q, "P", c::red);
      label(w, off + Vec2d{-0.2, -0.45},
            "P = P\u2080 + " + fmt(l.x) + "(P\u2081\u2212P\u2080) + " + fmt(l.y) +
                "(P\u2082\u2212P\u2080)",
            c::red, 0, 0);
    } else {
      const auto bc = barycentric(q, a, b, cc);
      if (!bc.valid) return false;
      // Iso-lines of each barycentric coordinate through P, from locus::from_barycentric.
      for (int k = 0; k < 3; ++k) {
        const double s = bc.w[static_cast<std::size_t>(k)];
        std::array<double, 3> w0{}, w1{};
        w0[static_cast<std::size_t>(k)] = s;
        w1[static_cast<std::size_t>(k)] = s;
        w0[static_cast<std::size_t>((k + 1) % 3)] = 1 - s;
        w1[static_cast<std::size_t>((k + 2) % 3)] = 1 - s;
        w.segment(from_barycentric(a, b, cc, w0), from_barycentric(a, b, cc, w1),
                  dashed(c::green, 1));
      }
      point(w, q, "P", c::red);
      label(w, off + Vec2d{0.2, -0.45},
            "P = (" + fmt(bc.w[0]) + ", " + fmt(bc.w[1]) + ", " + fmt(bc.w[2]) + ")", c::red, 0, 0);
    }
    point(w, a, "P\u2080");
    point(w, b, "P\u2081");
    point(w, cc, "P\u2082");
  }
  return true;
}

// 3.42: the simplexes of dimension 1, 2, 3 with their barycentres (locus::from_barycentric).
bool fig_3_42(SvgWriter& w) {
  w.set_camera(camera({4, -6, 3}));
  const Vec3d a{0, 0, 0}, b{1.5, 0, 0};
  w.segment(a, b, pen(c::blue));
  w.point(from_barycentric(a, b, std::array<double, 2>{0.5, 0.5}), dot(c::red));
  const Vec3d o2{2.5, 0, 0};
  const Vec3d t0 = o2, t1 = o2 + Vec3d{1.6, 0, 0}, t2 = o2 + Vec3d{0.6, 0, 1.3};
  closed(w, std::vector<Vec3d>{t0, t1, t2}, filled(c::blue, 0.15));
  w.point(from_barycentric(t0, t1, t2, std::array<double, 3>{1. / 3, 1. / 3, 1. / 3}), dot(c::red));
  const Vec3d o3{5.2, 0, 0};
  const Tetrahedron3d tet{
      {o3, o3 + Vec3d{1.6, 0, 0}, o3 + Vec3d{0.5, 1.2, 0}, o3 + Vec3d{0.7, 0.4, 1.4}}};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) w.segment(tet.v[i], tet.v[j], pen(c::blue));
  w.point(from_barycentric(tet.v[0], tet.v[1], tet.v[2], tet.v[3],
                           std::array<double, 4>{0.25, 0.25, 0.25, 0.25}),
          dot(c::red));
  label(w, Vec3d{0.4, 0, -0.4}, "(a)");
  label(w, o2 + Vec3d{0.6, 0, -0.4}, "(b)");
  label(w, o3 + Vec3d{0.6, 0, -0.4}, "(c)");
  return true;
}

}  // namespace

std::vector<Figure> chapter3_affine_figures() {
  return {
      {"3.19", "scaling, apply_point, apply_vector", fig_3_19},
      {"3.20", "scaling_axes", fig_3_20},
      {"3.21", "rotation_2d", fig_3_21},
      {"3.22", "shear", fig_3_22},
      {"3.23", "point subtraction (Vec operator-)", fig_3_23},
      {"3.24", "point subtraction, vector addition", fig_3_24},
      {"3.25", "affine_combination", fig_3_25},
      {"3.26", "affine_combination", fig_3_26},
      {"3.27", "angle_between, law_of_cosines_side, length", fig_3_27},
      {"3.28", "vector sum and difference", fig_3_28},
      {"3.29", "project_onto, reject_from", fig_3_29},
      {"3.30", "project_onto, angle_between", fig_3_30},
      {"3.31", "cross", fig_3_31},
      {"3.32", "cross (both orders)", fig_3_32},
      {"3.33", "linear combinations of three vectors", fig_3_33},
      {"3.34", "cross, project_onto, triple_product", fig_3_34},
      {"3.35", "Frame2, to_local_point", fig_3_35},
      {"3.36", "compose, apply_point, barycentric (segment)", fig_3_36},
      {"3.37", "apply_vector of a sum", fig_3_37},
      {"3.38", "apply_vector of a multiple", fig_3_38},
      {"3.39", "apply_point, apply_vector", fig_3_39},
      {"3.40", "rotation about a point, compose, inverse (fixed point)", fig_3_40},
      {"3.41", "to_local_point, barycentric (triangle), from_barycentric", fig_3_41},
      {"3.42", "Tetrahedron3, from_barycentric", fig_3_42},
  };
}

}  // namespace locus_gallery
