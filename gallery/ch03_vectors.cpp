// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 3 (vector algebra): figures 3.1-3.17. Every drawn vector is the result of a
// locus operation on the input vectors (sums, scalings, differences, basis coordinates, angles).
#include "gallery.hpp"

#include <locus/core/angle.hpp>
#include <locus/core/basis.hpp>
#include <locus/core/products.hpp>
#include <locus/core/transform.hpp>

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

// 3.1: one vector v drawn at several tails: every copy is tail + v.
bool fig_3_1(SvgWriter& w) {
  const Vec2d v{2.0, 1.0};
  for (const Vec2d& tail : {Vec2d{0, 0}, Vec2d{1.2, 1.6}, Vec2d{3.0, -0.4}, Vec2d{-0.6, 2.2}})
    vector(w, tail, tail + v, "v", c::blue);
  return true;
}

// 3.2: two vectors u and v.
bool fig_3_2(SvgWriter& w) {
  const Vec2d u{2.4, 0.6}, v{0.8, 1.8};
  vector(w, Vec2d{0, 0}, u, "u", c::blue);
  vector(w, Vec2d{2.0, 1.2}, Vec2d{2.0, 1.2} + v, "v", c::red);
  return true;
}

// 3.3: v drawn head-to-tail after u: its tail is the head of u.
bool fig_3_3(SvgWriter& w) {
  const Vec2d o{0, 0}, u{2.4, 0.6}, v{0.8, 1.8};
  vector(w, o, o + u, "u", c::blue);
  vector(w, o + u, o + u + v, "v", c::red);
  return true;
}

// 3.4: u + v closes the head-to-tail triangle.
bool fig_3_4(SvgWriter& w) {
  const Vec2d o{0, 0}, u{2.4, 0.6}, v{0.8, 1.8};
  vector(w, o, u, "u", c::blue, -12);
  vector(w, u, u + v, "v", c::red, -12);
  vector(w, o, u + v, "u + v", c::green);
  return true;
}

// 3.5: a chain of vectors and their sum.
bool fig_3_5(SvgWriter& w) {
  const std::array<Vec2d, 4> vs{Vec2d{1.5, 0.3}, Vec2d{0.6, 1.2}, Vec2d{-0.9, 1.0},
                                Vec2d{0.4, 1.1}};
  const char* names[] = {"v\u2081", "v\u2082", "v\u2083", "v\u2084"};
  Vec2d p{0, 0}, sum{0, 0};
  for (std::size_t i = 0; i < vs.size(); ++i) {
    vector(w, p, p + vs[i], names[i], c::blue, -12);
    p += vs[i];
    sum += vs[i];
  }
  vector(w, Vec2d{0, 0}, sum, "v\u2081 + v\u2082 + v\u2083 + v\u2084", c::green, 14);
  return true;
}

// 3.6: u - v runs from the head of v to the head of u.
bool fig_3_6(SvgWriter& w) {
  const Vec2d o{0, 0}, u{2.6, 0.8}, v{0.7, 1.9};
  vector(w, o, u, "u", c::blue, -12);
  vector(w, o, v, "v", c::red);
  vector(w, v, v + (u - v), "u \u2212 v", c::green);
  return true;
}

// 3.7: scalar multiples of v.
bool fig_3_7(SvgWriter& w) {
  const Vec2d v{1.2, 0.6};
  const double ks[] = {1.0, 2.0, -0.5, 1.5};
  const char* names[] = {"v", "2v", "\u2212\u00bdv", "1.5v"};
  for (int i = 0; i < 4; ++i) {
    const Vec2d tail{0.0, -1.0 * i};
    vector(w, tail, tail + ks[i] * v, names[i], i == 0 ? c::blue : c::green);
  }
  return true;
}

// 3.8: v and its negation -v.
bool fig_3_8(SvgWriter& w) {
  const Vec2d v{1.8, 1.0};
  vector(w, Vec2d{0, 0}, v, "v", c::blue);
  vector(w, Vec2d{1.0, 0}, Vec2d{1.0, 0} + (-v), "\u2212v", c::red);
  return true;
}

// 3.9: u + v = v + u: both head-to-tail paths end at the same point.
bool fig_3_9(SvgWriter& w) {
  const Vec2d o{0, 0}, u{2.5, 0.5}, v{0.8, 1.7};
  vector(w, o, u, "u", c::blue, -12);
  vector(w, u, u + v, "v", c::red, -12);
  vector(w, o, v, "v", c::red);
  vector(w, v, v + u, "u", c::blue);
  vector(w, o, u + v, "u + v = v + u", c::green, 0);
  return true;
}

// 3.10: (u + v) + w = u + (v + w).
bool fig_3_10(SvgWriter& w) {
  const Vec2d o{0, 0}, u{2.2, 0.3}, v{0.6, 1.4}, x{-1.2, 1.0};
  vector(w, o, u, "u", c::blue, -12);
  vector(w, u, u + v, "v", c::red, -12);
  vector(w, u + v, u + v + x, "w", c::purple, -12);
  vector(w, o, u + v, "u + v", c::orange, 10);
  vector(w, u, u + (v + x), "v + w", c::orange, 10);
  vector(w, o, (u + v) + x, "(u + v) + w = u + (v + w)", c::green, 14);
  return true;
}

// 3.11: (a + b) v = a v + b v.
bool fig_3_11(SvgWriter& w) {
  const Vec2d v{1.0, 0.5};
  const double a = 1.5, b = 1.0;
  vector(w, Vec2d{0, 0}, a * v, "av", c::blue, 12);
  vector(w, a * v, a * v + b * v, "bv", c::red, 12);
  const Vec2d off{0.3, -0.6};
  vector(w, off, off + (a + b) * v, "(a + b)v", c::green, -14);
  vector(w, Vec2d{-0.8, 0.4}, Vec2d{-0.8, 0.4} + v, "v", c::gray);
  return true;
}

// 3.12: a (u + v) = a u + a v: similar triangles.
bool fig_3_12(SvgWriter& w) {
  const Vec2d o{0, 0}, u{1.4, 0.2}, v{0.3, 1.0};
  const double a = 2.0;
  vector(w, o, u, "u", c::blue, -12);
  vector(w, u, u + v, "v", c::red, -12);
  vector(w, o, u + v, "u + v", c::green);
  const Vec2d off{2.2, 0};
  vector(w, off, off + a * u, "au", c::blue, -12);
  vector(w, off + a * u, off + a * u + a * v, "av", c::red, -12);
  vector(w, off, off + a * (u + v), "a(u + v)", c::green);
  return true;
}

// 3.13: the span of two vectors in 3D: a patch of the plane {a u + b v}.
bool fig_3_13(SvgWriter& w) {
  w.set_camera(camera({6, 3.5, 4}));
  const Vec3d u{1.6, 0.3, 0.2}, v{0.2, 1.4, 0.9};
  axes3(w, 1.2, c::light);
  for (int i = -2; i <= 2; ++i) {
    const double t = i;
    w.segment(t * u - 2.0 * v, t * u + 2.0 * v, pen(c::light, 1));
    w.segment(t * v - 2.0 * u, t * v + 2.0 * u, pen(c::light, 1));
  }
  w.arrow(Vec3d{0, 0, 0}, u, pen(c::blue, 2.2));
  w.arrow(Vec3d{0, 0, 0}, v, pen(c::red, 2.2));
  label(w, u, "u", c::blue);
  label(w, v, "v", c::red);
  const Vec3d s = 1.5 * u + 1.0 * v;  // one member of the span
  w.arrow(Vec3d{0, 0, 0}, s, pen(c::green, 1.8));
  label(w, s, "1.5u + v", c::green);
  return true;
}

// 3.14: v = c0 b0 + c1 b1 with the coordinates from locus::basis_coordinates.
bool fig_3_14(SvgWriter& w) {
  const Vec2d b0{1.0, 0.2}, b1{0.3, 1.0}, v{2.3, 1.9};
  const auto cs = basis_coordinates(v, std::array<Vec2d, 2>{b0, b1});
  if (!cs) return false;
  const Vec2d p0 = (*cs)[0] * b0, p1 = (*cs)[1] * b1;
  w.segment(p0, p0 + p1, dashed(c::gray));
  w.segment(p1, p1 + p0, dashed(c::gray));
  w.arrow(Vec2d{0, 0}, p0, pen(c::light, 4));
  w.arrow(Vec2d{0, 0}, p1, pen(c::light, 4));
  vector(w, Vec2d{0, 0}, b0, "b\u2080", c::blue, -12);
  vector(w, Vec2d{0, 0}, b1, "b\u2081", c::red);
  vector(w, Vec2d{0, 0}, v, "v", c::green);
  label(w, p0, fmt((*cs)[0]) + " b\u2080", c::blue, 4, -16);
  label(w, p1, fmt((*cs)[1]) + " b\u2081", c::red, -60, 4);
  return true;
}

// 3.15: the angle between two vectors, from locus::angle_between.
bool fig_3_15(SvgWriter& w) {
  const Vec2d u{2.5, 0.4}, v{0.9, 1.8};
  const double theta = angle_between(u, v);
  vector(w, Vec2d{0, 0}, u, "u", c::blue, -12);
  vector(w, Vec2d{0, 0}, v, "v", c::red);
  angle_mark(w, Vec2d{0, 0}, u, v, 0.6, "\u03b8 = " + fmt(to_degrees(theta), 1) + "\u00b0");
  return true;
}

// 3.16: the right-hand rule: x rotated a quarter turn about z gives y.
bool fig_3_16(SvgWriter& w) {
  w.set_camera(camera({5, 3, 3.5}));
  axes3(w, 1.5, c::black);
  const Affine3d rz = rotation_about_z(0.5 * pi_v<double>);
  // The curled fingers: the path of x under rotations about z by 0..90 degrees.
  std::vector<Vec3d> path;
  for (int i = 0; i <= 24; ++i)
    path.push_back(
        apply_point(rotation_about_z(0.5 * pi_v<double> * i / 24.0), Vec3d{0.8, 0, 0.3}));
  w.polyline(path, pen(c::red, 1.6));
  w.arrow(path[path.size() - 4], path.back(), pen(c::red, 1.6));
  const Vec3d y_image = apply_vector(rz, Vec3d{1.5, 0, 0});
  w.point(y_image, dot(c::green, 4));
  label(w, Vec3d{0, 0, 1.5}, "thumb = x \u00d7 y", c::gray, 8, -14);
  return true;
}

// 3.17: one vector in two bases; coordinates from locus::basis_coordinates for each.
bool fig_3_17(SvgWriter& w) {
  const Vec2d v{2.0, 1.6};
  const std::array<std::array<Vec2d, 2>, 2> bases{
      std::array<Vec2d, 2>{Vec2d{1, 0}, Vec2d{0, 1}},
      std::array<Vec2d, 2>{Vec2d{1.0, 0.5}, Vec2d{-0.4, 0.9}}};
  for (std::size_t k = 0; k < 2; ++k) {
    const Vec2d off{3.2 * static_cast<double>(k), 0};
    const auto cs = basis_coordinates(v, bases[k]);
    if (!cs) return false;
    const Vec2d p0 = (*cs)[0] * bases[k][0], p1 = (*cs)[1] * bases[k][1];
    w.polyline(std::vector<Vec2d>{off + p0, off + p0 + p1, off + p1}, dashed(c::gray));
    vector(w, off, off + bases[k][0], k ? "b\u2080" : "i", c::blue, -12);
    vector(w, off, off + bases[k][1], k ? "b\u2081" : "j", c::red);
    vector(w, off, off + v, "v", c::green);
    label(w, off + Vec2d{0.2, -0.6}, "v = (" + fmt((*cs)[0]) + ", " + fmt((*cs)[1]) + ")", c::black,
          0, 0);
  }
  return true;
}

}  // namespace

std::vector<Figure> chapter3_vector_figures() {
  return {
      {"3.1", "Vec addition (tail + v)", fig_3_1},
      {"3.2", "Vec", fig_3_2},
      {"3.3", "Vec addition (head of u + v)", fig_3_3},
      {"3.4", "operator+ on Vec", fig_3_4},
      {"3.5", "operator+= on Vec", fig_3_5},
      {"3.6", "operator- on Vec", fig_3_6},
      {"3.7", "scalar * Vec", fig_3_7},
      {"3.8", "unary operator- on Vec", fig_3_8},
      {"3.9", "operator+ on Vec (both orders)", fig_3_9},
      {"3.10", "operator+ on Vec (both groupings)", fig_3_10},
      {"3.11", "scalar * Vec, operator+", fig_3_11},
      {"3.12", "scalar * Vec, operator+", fig_3_12},
      {"3.13", "linear combinations a u + b v; SvgWriter 3D camera (look_at)", fig_3_13},
      {"3.14", "basis_coordinates", fig_3_14},
      {"3.15", "angle_between, to_degrees", fig_3_15},
      {"3.16", "rotation_about_z, apply_point, apply_vector", fig_3_16},
      {"3.17", "basis_coordinates (two bases)", fig_3_17},
  };
}

}  // namespace locus_gallery
