// SPDX-License-Identifier: BSL-1.0
#pragma once
// The generic intersection-query harness of rows int2.* and int3.* (harness2_test.cpp,
// harness3_test.cpp), the counterpart of tests/distance/harness.hpp.
// check_intersection_pairs<T>(gen, opt, oracle) draws opt.cases pairs (a, b) from gen(rng) and
// checks r = intersection(a, b), seen as a list of pieces (an Intersection-shaped result is one
// piece; a PolylineIntersection2 lists its crossings), each with kind, count, point, params:
//   1. every point lies on both objects: its distance to each (the library's distance(point,
//      object) in double; direct ones for plane, sphere, cylinder, disk; 2D triangle: edges) is
//      <= opt.residual eps max(m, |X|inf), m the largest |coordinate|, radius or extent,
//      eps of T; each parameter is in its domain and point_at maps it to within opt.param of the
//      point (default opt.residual eps, same scale; a triangle's (s, t) may leave its domain by
//      opt.domain_slack eps, default 4, two parameters rounded separately);
//   2. intersection(b, a) == swapped(r) bit for bit (points, parameters, multiplicities) when the
//      pair has a swapped overload (opt.exact_swap); else (a same-type pair) the same kinds and
//      counts and the same point set within opt.position max(m, |X|inf);
//   3. intersects(a, b) and intersects(b, a) == (some piece is not empty), where they exist;
//   4. scaling both inputs by 2^+-k (exact; k = 20 float, 100 double, or opt.scale_exp) keeps
//      the kinds and counts, check 1 on the scaled pair, and (point, points, segment) the points
//      scaled within opt.position;
//   5. an exact rigid motion (a signed axis permutation: reflections and 90 degree rotations;
//      with opt.translate a shift by multiples of 2^-4, exact on the generators' 2^-10 grid)
//      keeps the kinds and counts, check 1 on the moved pair, and the moved points (as in 4);
//   6. an optional exact oracle (GMP: linear_oracle.hpp, conic_oracle.hpp, linear3_oracle.hpp,
//      or one written in the test) gives the same kind and count.
// Side<P> says how the harness sees a primitive: residual of a point, size m, parameter map and
// domain, rigid motion, scaling. Failures print the seed (LOCUS_TEST_SEED), the case and the
// inputs in hexadecimal floating point; LOCUS_HARNESS_KINDS=1 prints the kinds each draw hit.

#include <locus/distance/point_aligned_box.hpp>
#include <locus/distance/point_circle.hpp>
#include <locus/distance/point_ellipse.hpp>
#include <locus/distance/point_line.hpp>
#include <locus/distance/point_oriented_box.hpp>
#include <locus/distance/point_polyline.hpp>
#include <locus/distance/point_ray.hpp>
#include <locus/distance/point_segment.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/aligned_box.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/cylinder.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/polyline.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/sphere.hpp>
#include <locus/primitives/triangle.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace locus_test::ix {

using locus::Kind;
using locus::NoParam;
using locus::Vec;

/// An exact rigid motion: x -> (sign[i] x[perm[i]])_i + shift.
template <class T, int N>
struct Motion {
  std::array<int, N> perm{};
  std::array<T, N> sign{};
  Vec<T, N> shift{};
  Vec<T, N> operator()(const Vec<T, N>& x) const { return rot(x) + shift; }
  Vec<T, N> rot(const Vec<T, N>& x) const {
    Vec<T, N> y{};
    for (int i = 0; i < N; ++i) y[i] = sign[std::size_t(i)] * x[perm[std::size_t(i)]];
    return y;
  }
};

template <class T, int N>
Motion<T, N> random_motion(Rng& rng, bool translate) {
  Motion<T, N> m;
  for (int i = 0; i < N; ++i) m.perm[std::size_t(i)] = i;
  for (int i = N - 1; i > 0; --i)
    std::swap(m.perm[std::size_t(i)], m.perm[std::size_t(rng.uniform_int(0, i))]);
  for (int i = 0; i < N; ++i) {
    m.sign[std::size_t(i)] = rng.uniform_int(0, 1) ? T(1) : T(-1);
    m.shift[i] = translate ? T(rng.uniform_int(-64, 64)) / T(16) : T(0);
  }
  return m;
}

inline std::string hex(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}
inline std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}
template <class T, int N>
std::string hex(const Vec<T, N>& v) {
  std::string s = "(";
  for (int i = 0; i < N; ++i) s += (i ? ", " : "") + hex(double(v[i]));
  return s + ")";
}
template <class T, int N>
Vec<double, N> vd(const Vec<T, N>& v) {
  return locus::vec_cast<double>(v);
}
template <class T, int N>
double inf_norm(const Vec<T, N>& v) {
  double m = 0;
  for (int i = 0; i < N; ++i) m = std::max(m, std::abs(double(v[i])));
  return m;
}

template <class P>
struct Side;

// ---- linear components --------------------------------------------------------------------
template <class T, int N>
struct Side<locus::Segment<T, N>> {
  using P = locus::Segment<T, N>;
  static double residual(const P& s, const Vec<T, N>& x) {
    return double(locus::distance(vd(x), locus::Segment<double, N>{vd(s.p0), vd(s.p1)}).distance);
  }
  static double size(const P& s) { return std::max(inf_norm(s.p0), inf_norm(s.p1)); }
  static Vec<double, N> at(const P& s, T t) { return vd(s.p0) + double(t) * (vd(s.p1) - vd(s.p0)); }
  static bool param_ok(const P&, T t, double) { return t >= T(0) && t <= T(1); }
  static P moved(const P& s, const Motion<T, N>& m) { return {m(s.p0), m(s.p1)}; }
  static P scaled(const P& s, T f) { return {f * s.p0, f * s.p1}; }
  static std::string str(const P& s) { return "segment " + hex(s.p0) + " " + hex(s.p1); }
};

template <class T, int N>
struct Side<locus::Ray<T, N>> {
  using P = locus::Ray<T, N>;
  static double residual(const P& r, const Vec<T, N>& x) {
    return double(
        locus::distance(vd(x), locus::Ray<double, N>{vd(r.origin), vd(r.direction)}).distance);
  }
  static double size(const P& r) { return std::max(inf_norm(r.origin), inf_norm(r.direction)); }
  static Vec<double, N> at(const P& r, T t) { return vd(r.origin) + double(t) * vd(r.direction); }
  static bool param_ok(const P&, T t, double) { return t >= T(0) && std::isfinite(double(t)); }
  static P moved(const P& r, const Motion<T, N>& m) { return {m(r.origin), m.rot(r.direction)}; }
  static P scaled(const P& r, T f) { return {f * r.origin, f * r.direction}; }
  static std::string str(const P& r) { return "ray " + hex(r.origin) + " " + hex(r.direction); }
};

template <class T, int N>
struct Side<locus::Line<T, N>> {
  using P = locus::Line<T, N>;
  static double residual(const P& l, const Vec<T, N>& x) {
    return double(
        locus::distance(vd(x), locus::Line<double, N>{vd(l.origin), vd(l.direction)}).distance);
  }
  static double size(const P& l) { return std::max(inf_norm(l.origin), inf_norm(l.direction)); }
  static Vec<double, N> at(const P& l, T t) { return vd(l.origin) + double(t) * vd(l.direction); }
  static bool param_ok(const P&, T t, double) { return std::isfinite(double(t)); }
  static P moved(const P& l, const Motion<T, N>& m) { return {m(l.origin), m.rot(l.direction)}; }
  static P scaled(const P& l, T f) { return {f * l.origin, f * l.direction}; }
  static std::string str(const P& l) { return "line " + hex(l.origin) + " " + hex(l.direction); }
};

template <class T, int N>
struct Side<locus::Polyline<T, N>> {
  using P = locus::Polyline<T, N>;
  static locus::Polyline<double, N> to_d(const P& p) {
    locus::Polyline<double, N> d;
    d.closed = p.closed;
    for (const Vec<T, N>& v : p.vertices) d.vertices.push_back(vd(v));
    return d;
  }
  static double residual(const P& p, const Vec<T, N>& x) {
    return double(locus::distance(vd(x), to_d(p)).distance);
  }
  static double size(const P& p) {
    double m = 0;
    for (const Vec<T, N>& v : p.vertices) m = std::max(m, inf_norm(v));
    return m;
  }
  static Vec<double, N> at(const P& p, T t) { return locus::point_at(to_d(p), double(t)); }
  static bool param_ok(const P& p, T t, double) {
    return t >= T(0) && double(t) <= double(locus::segment_count(p));
  }
  static P moved(const P& p, const Motion<T, N>& m) {
    P o = p;
    for (Vec<T, N>& v : o.vertices) v = m(v);
    return o;
  }
  static P scaled(const P& p, T f) {
    P o = p;
    for (Vec<T, N>& v : o.vertices) v = f * v;
    return o;
  }
  static std::string str(const P& p) {
    std::string out = p.closed ? "closed polyline" : "polyline";
    for (const Vec<T, N>& v : p.vertices) out += " " + hex(v);
    return out;
  }
};

// ---- curves -------------------------------------------------------------------------------
template <class T>
struct Side<locus::Circle2<T>> {
  using P = locus::Circle2<T>;
  static double residual(const P& c, const Vec<T, 2>& x) {
    return std::abs(locus::length(vd(x) - vd(c.center)) - double(c.radius));
  }
  static double size(const P& c) { return std::max(inf_norm(c.center), double(c.radius)); }
  static Vec<double, 2> at(const P& c, T a) {
    return vd(c.center) +
           double(c.radius) * Vec<double, 2>{std::cos(double(a)), std::sin(double(a))};
  }
  static bool param_ok(const P&, T a, double) { return std::isfinite(double(a)); }
  static P moved(const P& c, const Motion<T, 2>& m) { return {m(c.center), c.radius}; }
  static P scaled(const P& c, T f) { return {f * c.center, f * c.radius}; }
  static std::string str(const P& c) { return "circle " + hex(c.center) + " r " + hex(c.radius); }
};

template <class T>
struct Side<locus::Ellipse2<T>> {
  using P = locus::Ellipse2<T>;
  static double residual(const P& e, const Vec<T, 2>& x) {
    locus::Ellipse2<double> d;
    d.center = vd(e.center);
    for (int i = 0; i < 2; ++i) {
      d.axis[i] = vd(e.axis[i]);
      d.extent[i] = double(e.extent[i]);
    }
    return double(locus::distance(vd(x), d).distance);
  }
  static double size(const P& e) {
    return std::max({inf_norm(e.center), double(e.extent[0]), double(e.extent[1])});
  }
  static Vec<double, 2> at(const P& e, T a) {
    return vd(e.center) + double(e.extent[0]) * std::cos(double(a)) * vd(e.axis[0]) +
           double(e.extent[1]) * std::sin(double(a)) * vd(e.axis[1]);
  }
  static bool param_ok(const P&, T a, double) { return std::isfinite(double(a)); }
  static P moved(const P& e, const Motion<T, 2>& m) {
    P o = e;
    o.center = m(e.center);
    for (int i = 0; i < 2; ++i) o.axis[i] = m.rot(e.axis[i]);
    return o;
  }
  static P scaled(const P& e, T f) {
    P o = e;
    o.center = f * e.center;
    for (int i = 0; i < 2; ++i) o.extent[i] = f * e.extent[i];
    return o;
  }
  static std::string str(const P& e) {
    return "ellipse " + hex(e.center) + " axes " + hex(e.axis[0]) + " " + hex(e.axis[1]) +
           " extents " + hex(double(e.extent[0])) + " " + hex(double(e.extent[1]));
  }
};

// ---- 3D surfaces ----------------------------------------------------------------------------
template <class T>
struct Side<locus::Plane3<T>> {
  using P = locus::Plane3<T>;
  static double residual(const P& p, const Vec<T, 3>& x) {
    const Vec<double, 3> n = vd(p.normal);
    return std::abs(locus::dot(n, vd(x)) - double(p.constant)) / locus::length(n);
  }
  // The plane's points of interest lie near the inputs of the other object; its own size is
  // that of a point of it nearest the origin.
  static double size(const P& p) {
    return std::abs(double(p.constant)) / locus::length(vd(p.normal));
  }
  static P moved(const P& p, const Motion<T, 3>& m) {
    const Vec<T, 3> n = m.rot(p.normal);
    return {n, p.constant + locus::dot(n, m.shift)};
  }
  static P scaled(const P& p, T f) { return {p.normal, f * p.constant}; }
  static std::string str(const P& p) {
    return "plane " + hex(p.normal) + " c " + hex(double(p.constant));
  }
};

template <class T, int N>
struct Side<locus::Triangle<T, N>> {
  using P = locus::Triangle<T, N>;
  static double residual(const P& t, const Vec<T, N>& x) {
    if constexpr (N == 2) {
      // distance(Vec2, Triangle2) solves for barycentrics, 20 eps off for a point on an edge
      // (seen: 4.7e-15 for one 0.1 eps from it); here 0 inside (rounded signs: a misjudged
      // point is that close to an edge), else the nearest edge (point-segment, accurate).
      const Vec<double, 2> p = vd(x), v[3] = {vd(t.v0), vd(t.v1), vd(t.v2)};
      double side[3], best = std::numeric_limits<double>::infinity();
      for (int i = 0; i < 3; ++i) {
        const Vec<double, 2> a = v[i], b = v[(i + 1) % 3];
        side[i] = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        best = std::min(best, double(locus::distance(p, locus::Segment<double, 2>{a, b}).distance));
      }
      const bool inside = (side[0] >= 0 && side[1] >= 0 && side[2] >= 0) ||
                          (side[0] <= 0 && side[1] <= 0 && side[2] <= 0);
      const double area =
          (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
      return inside && area != 0.0 ? 0.0 : best;  // a flat triangle is its edges
    } else {
      return double(locus::distance(vd(x), locus::Triangle<double, N>{vd(t.v0), vd(t.v1), vd(t.v2)})
                        .distance);
    }
  }
  static double size(const P& t) {
    return std::max({inf_norm(t.v0), inf_norm(t.v1), inf_norm(t.v2)});
  }
  static Vec<double, N> at(const P& t, const Vec<T, 2>& st) {
    return vd(t.v0) + double(st.x) * (vd(t.v1) - vd(t.v0)) + double(st.y) * (vd(t.v2) - vd(t.v0));
  }
  // Rounding s and t separately can leave the domain by an ulp (s + t = 1 on an edge): slack
  // eps of T times opt.domain_slack.
  static bool param_ok(const P&, const Vec<T, 2>& st, double slack) {
    const double tol = slack * double(std::numeric_limits<T>::epsilon());
    return st.x >= -tol && st.y >= -tol && double(st.x) + double(st.y) <= 1.0 + tol;
  }
  static P moved(const P& t, const Motion<T, N>& m) { return {m(t.v0), m(t.v1), m(t.v2)}; }
  static P scaled(const P& t, T f) { return {f * t.v0, f * t.v1, f * t.v2}; }
  static std::string str(const P& t) {
    return "triangle " + hex(t.v0) + " " + hex(t.v1) + " " + hex(t.v2);
  }
};

template <class T>
struct Side<locus::AlignedBox<T, 3>> {
  using P = locus::AlignedBox<T, 3>;
  static double residual(const P& b, const Vec<T, 3>& x) {
    return std::sqrt(
        double(locus::sqr_distance(vd(x), locus::AlignedBox<double, 3>{vd(b.min), vd(b.max)})));
  }
  static double size(const P& b) { return std::max(inf_norm(b.min), inf_norm(b.max)); }
  static P moved(const P& b, const Motion<T, 3>& m) {
    const Vec<T, 3> p = m(b.min), q = m(b.max);
    P o;
    for (int i = 0; i < 3; ++i) {
      o.min[i] = std::min(p[i], q[i]);
      o.max[i] = std::max(p[i], q[i]);
    }
    return o;
  }
  static P scaled(const P& b, T f) { return {f * b.min, f * b.max}; }
  static std::string str(const P& b) { return "box " + hex(b.min) + " " + hex(b.max); }
};

template <class T>
struct Side<locus::OrientedBox<T, 3>> {
  using P = locus::OrientedBox<T, 3>;
  static double residual(const P& b, const Vec<T, 3>& x) {
    const locus::OrientedBox<double, 3> d{
        vd(b.center), {vd(b.axis[0]), vd(b.axis[1]), vd(b.axis[2])}, vd(b.extent)};
    return std::sqrt(double(locus::sqr_distance(vd(x), d)));
  }
  static double size(const P& b) { return std::max(inf_norm(b.center), inf_norm(b.extent)); }
  static P moved(const P& b, const Motion<T, 3>& m) {
    return {m(b.center), {m.rot(b.axis[0]), m.rot(b.axis[1]), m.rot(b.axis[2])}, b.extent};
  }
  static P scaled(const P& b, T f) {
    return {f * b.center, {b.axis[0], b.axis[1], b.axis[2]}, f * b.extent};
  }
  static std::string str(const P& b) {
    return "obox " + hex(b.center) + " axes " + hex(b.axis[0]) + " " + hex(b.axis[1]) + " " +
           hex(b.axis[2]) + " extent " + hex(b.extent);
  }
};

/// A right circular cylinder with a unit axis direction (the generators use signed coordinate
/// axes, so motions keep it exact); residual: the distance to the infinite lateral surface, or
/// to the boundary of the finite closed solid (side and caps).
template <class T>
struct Side<locus::Cylinder3<T>> {
  using P = locus::Cylinder3<T>;
  static double residual(const P& c, const Vec<T, 3>& x) {
    const Vec<double, 3> w = vd(x) - vd(c.axis.origin), a = vd(c.axis.direction);
    const double z = locus::dot(a, w), rho = locus::length(w - z * a), r = double(c.radius);
    if (locus::is_infinite(c)) return std::abs(rho - r);
    const double h = double(c.height) / 2, out_r = rho - r, out_z = std::abs(z) - h;
    if (out_r <= 0 && out_z <= 0) return std::min(-out_r, -out_z);
    return std::hypot(std::max(out_r, 0.0), std::max(out_z, 0.0));
  }
  static double size(const P& c) {
    const double h = locus::is_infinite(c) ? 0.0 : double(c.height) / 2;
    return std::max({inf_norm(c.axis.origin), double(c.radius), h});
  }
  static Vec<double, 3> at(const P& c, const Vec<T, 2>& tt) {
    const locus::Cylinder3<double> d{
        {vd(c.axis.origin), vd(c.axis.direction)}, double(c.radius), double(c.height)};
    return locus::point_at(d, Vec<double, 2>{double(tt.x), double(tt.y)});
  }
  static bool param_ok(const P& c, const Vec<T, 2>& tt, double) {
    return std::isfinite(double(tt.x)) && std::isfinite(double(tt.y)) &&
           std::abs(double(tt.y)) <= double(c.height) / 2;
  }
  static P moved(const P& c, const Motion<T, 3>& m) {
    return {{m(c.axis.origin), m.rot(c.axis.direction)}, c.radius, c.height};
  }
  static P scaled(const P& c, T f) {
    return {{f * c.axis.origin, c.axis.direction}, f * c.radius, f * c.height};
  }
  static std::string str(const P& c) {
    return "cylinder " + hex(c.axis.origin) + " axis " + hex(c.axis.direction) + " r " +
           hex(c.radius) + " h " + hex(c.height);
  }
};

/// A closed disk in 3D (normal of any length); residual: the distance to the disk.
template <class T>
struct Side<locus::Disk3<T>> {
  using P = locus::Disk3<T>;
  static double residual(const P& c, const Vec<T, 3>& x) {
    const Vec<double, 3> w = vd(x) - vd(c.center), n = locus::normalize(vd(c.normal));
    const double z = locus::dot(w, n), rho = locus::length(w - z * n);
    return std::hypot(z, std::max(rho - double(c.radius), 0.0));
  }
  static double size(const P& c) { return std::max(inf_norm(c.center), double(c.radius)); }
  static Vec<double, 3> at(const P& c, const Vec<T, 2>& st) {
    const locus::Disk3<double> d{vd(c.center), vd(c.normal), double(c.radius)};
    return locus::point_at(d, Vec<double, 2>{double(st.x), double(st.y)});
  }
  static bool param_ok(const P& c, const Vec<T, 2>& st, double slack) {
    const double eps = double(std::numeric_limits<T>::epsilon());
    return std::hypot(double(st.x), double(st.y)) <= double(c.radius) + slack * eps * size(c);
  }
  static P moved(const P& c, const Motion<T, 3>& m) {
    return {m(c.center), m.rot(c.normal), c.radius};
  }
  static P scaled(const P& c, T f) { return {f * c.center, c.normal, f * c.radius}; }
  static std::string str(const P& c) {
    return "disk " + hex(c.center) + " normal " + hex(c.normal) + " r " + hex(c.radius);
  }
};

template <class T>
struct Side<locus::Sphere<T, 3>> {
  using P = locus::Sphere<T, 3>;
  static double residual(const P& s, const Vec<T, 3>& x) {
    return std::abs(locus::length(vd(x) - vd(s.center)) - double(s.radius));
  }
  static double size(const P& s) { return std::max(inf_norm(s.center), double(s.radius)); }
  static Vec<double, 3> at(const P& s, const Vec<T, 2>& tp) {
    const locus::Sphere<double, 3> d{vd(s.center), double(s.radius)};
    return locus::point_at(d, Vec<double, 2>{double(tp.x), double(tp.y)});
  }
  static bool param_ok(const P&, const Vec<T, 2>& tp, double) {
    return std::isfinite(double(tp.x)) && std::isfinite(double(tp.y));
  }
  static P moved(const P& s, const Motion<T, 3>& m) { return {m(s.center), s.radius}; }
  static P scaled(const P& s, T f) { return {f * s.center, f * s.radius}; }
  static std::string str(const P& s) { return "sphere " + hex(s.center) + " r " + hex(s.radius); }
};

// ---- the harness ----------------------------------------------------------------------------
struct Options {
  int cases = 150;
  double residual = 16;     ///< check 1: points within residual eps m of both objects
  double param = 0;         ///< check 1: |point_at(param) - point| <= param m (0: residual eps)
  double position = 0;      ///< checks 2, 4, 5: point agreement, relative to m (0: residual eps)
  int scale_exp = 0;        ///< check 4: 2^+-scale_exp (0: 20 float, 100 double)
  bool exact_swap = true;   ///< check 2: bit for bit (a swapped overload exists)
  bool translate = true;    ///< check 5: translations too (the generator's inputs are on a grid)
  double domain_slack = 4;  ///< check 1: a triangle's (s, t) may leave its domain by this many eps
};

/// The oracle's answer: kind and count.
struct Expected {
  Kind kind;
  int count;
};

inline const char* kind_name(Kind k) {
  static const char* names[] = {"empty",    "point",   "points", "segment", "ray",   "line",
                                "polyline", "polygon", "circle", "arc",     "plane", "coincident"};
  return names[static_cast<int>(k)];
}

template <class Par>
std::string param_str(const Par& x) {
  if constexpr (std::is_arithmetic_v<Par>) {
    return hex(double(x));
  } else {
    return hex(x);
  }
}

template <class Par>
bool same_param(const Par& x, const Par& y) {
  if constexpr (std::is_same_v<Par, NoParam>) {
    return true;
  } else if constexpr (std::is_arithmetic_v<Par>) {
    return x == y || (std::isnan(double(x)) && std::isnan(double(y)));
  } else {
    return x == y;
  }
}

/// A result as a list of Intersection pieces: an Intersection-shaped result is one piece (of
/// any kind, empty included); a PolylineIntersection2 lists its crossings (none when empty).
template <class R>
requires requires(const R& r) {
  r.kind;
  r.point;
}
std::vector<R> pieces(const R& r) { return {r}; }
template <class T>
std::vector<locus::Intersection<T, 2, T, T, 2>> pieces(const locus::PolylineIntersection2<T>& r) {
  std::vector<locus::Intersection<T, 2, T, T, 2>> out;
  for (const locus::PolylineCrossing2<T>& c : r.crossings)
    out.push_back({c.kind, c.count, c.point, c.param_a, c.param_b});
  return out;
}

template <class T, class A, class B>
class PairChecker {
 public:
  PairChecker(const Options& opt, Rng& rng) : opt_(opt), rng_(rng) {}

  using Raw = decltype(intersection(std::declval<const A&>(), std::declval<const B&>()));
  using R = typename decltype(pieces(std::declval<const Raw&>()))::value_type;
  using L = std::vector<R>;
  static constexpr int N = R::dimension;

  void run(const A& a, const B& b, int icase,
           const std::function<std::optional<Expected>(const A&, const B&)>& oracle) {
    what_ = "case " + std::to_string(icase) + ": " + Side<A>::str(a) + " / " + Side<B>::str(b);
    const double m = std::max(Side<A>::size(a), Side<B>::size(b));
    const L r = pieces(intersection(a, b));
    if (r.empty()) ++kinds_[0];
    for (const R& x : r) ++kinds_[static_cast<std::size_t>(x.kind)];
    on_both(a, b, r, m, "");
    check_swap(a, b, r, m);
    const bool meet =
        std::any_of(r.begin(), r.end(), [](const R& x) { return x.kind != Kind::empty; });
    if constexpr (requires { intersects(a, b); }) {
      if (intersects(a, b) != meet) fail("intersects(a, b) disagrees with the intersection");
    }
    if constexpr (requires { intersects(b, a); }) {
      if (intersects(b, a) != meet) fail("intersects(b, a) disagrees with the intersection");
    }
    if (oracle && r.size() == 1) {
      if (const std::optional<Expected> e = oracle(a, b)) {
        if (e->kind != r[0].kind || e->count != r[0].count)
          fail(std::string("oracle says ") + kind_name(e->kind) + " count " +
               std::to_string(e->count) + ", got " + kind_name(r[0].kind) + " count " +
               std::to_string(r[0].count));
      }
    }
    // 4. power-of-two scaling.
    const int kmax = opt_.scale_exp ? opt_.scale_exp : (std::is_same_v<T, float> ? 20 : 100);
    for (int k : {kmax, -kmax}) {
      const T f = std::ldexp(T(1), k);
      const A fa = Side<A>::scaled(a, f);
      const B fb = Side<B>::scaled(b, f);
      const L s = pieces(intersection(fa, fb));
      const std::string tag = " (scaled 2^" + std::to_string(k) + ")";
      if (!same_shape(r, s, tag)) continue;
      on_both(fa, fb, s, double(f) * m, tag);
      compare_points(
          r, s, [f](const Vec<T, N>& p) { return f * p; }, double(f) * m, tag);
    }
    // 5. exact rigid motion.
    const Motion<T, N> mo = random_motion<T, N>(rng_, opt_.translate);
    const A ma = Side<A>::moved(a, mo);
    const B mb = Side<B>::moved(b, mo);
    const L s = pieces(intersection(ma, mb));
    const double mm = std::max(Side<A>::size(ma), Side<B>::size(mb));
    if (same_shape(r, s, " (moved)")) {
      on_both(ma, mb, s, mm, " (moved)");
      compare_points(r, s, mo, std::max(m, mm), " (moved)");
    }
  }

  int failures() const { return failures_; }
  /// How many cases gave each kind (printed with LOCUS_HARNESS_KINDS set: the draw's coverage).
  std::string kind_tally() const {
    std::string s;
    for (std::size_t k = 0; k < kinds_.size(); ++k)
      if (kinds_[k]) s += std::string(kind_name(Kind(k))) + " " + std::to_string(kinds_[k]) + "  ";
    return s;
  }

 private:
  double eps() const { return double(std::numeric_limits<T>::epsilon()); }
  double pos_tol(double m) const {
    return (opt_.position > 0 ? opt_.position : opt_.residual * eps()) * m;
  }

  void fail(const std::string& msg) {
    ++failures_;
    if (failures_ <= 5) ADD_FAILURE() << what_ << "\n  " << msg;
  }

  template <class X, class Y, class S>
  void on_both(const X& a, const Y& b, const std::vector<S>& rs, double m, const std::string& tag) {
    for (const S& r : rs) on_both(a, b, r, m, tag);
  }
  template <class X, class Y, class S>
  requires(!std::is_same_v<S, std::vector<R>>) void on_both(const X& a, const Y& b, const S& r,
                                                            double m, const std::string& tag) {
    if (r.count < 0 || r.count > S::capacity) {
      fail("count " + std::to_string(r.count) + tag);
      return;
    }
    for (int i = 0; i < r.count; ++i) {
      const std::size_t j = std::size_t(i);
      const Vec<T, N>& p = r.point[j];
      // The pair headers bound residuals by eps max(|X|inf, m).
      const double mp = std::max(m, inf_norm(p));
      const double tol = opt_.residual * eps() * mp;
      const double ptol = (opt_.param > 0 ? opt_.param : opt_.residual * eps()) * mp;
      const double ra = Side<X>::residual(a, p), rb = Side<Y>::residual(b, p);
      if (!(ra <= tol) || !(rb <= tol))
        fail("point " + std::to_string(i) + " " + hex(p) + " residuals " + num(ra) + ", " +
             num(rb) + " > " + num(tol) + " (kind " + kind_name(r.kind) + ")" + tag);
      check_param<X>(a, r.param_a[j], p, ptol, "param_a", i, tag);
      check_param<Y>(b, r.param_b[j], p, ptol, "param_b", i, tag);
    }
  }

  template <class X, class Par>
  void check_param(const X& x, const Par& par, const Vec<T, N>& p, double ptol, const char* name,
                   int i, const std::string& tag) {
    if constexpr (!std::is_same_v<Par, NoParam>) {
      if (!Side<X>::param_ok(x, par, opt_.domain_slack)) {
        fail(std::string(name) + "[" + std::to_string(i) + "] = " + param_str(par) +
             " outside its domain" + tag);
        return;
      }
      const double d = inf_norm(Side<X>::at(x, par) - vd(p));
      if (!(d <= ptol))
        fail(std::string(name) + "[" + std::to_string(i) + "] maps " + num(d) +
             " from its point > " + num(ptol) + tag);
    }
  }

  template <class S>
  bool same_shape(const L& r, const std::vector<S>& s, const std::string& tag) {
    bool same = r.size() == s.size();
    for (std::size_t i = 0; same && i < r.size(); ++i)
      same = r[i].kind == s[i].kind && r[i].count == s[i].count;
    if (same) return true;
    fail("shape " + shape(r) + " becomes " + shape(s) + tag);
    return false;
  }
  template <class S>
  static std::string shape(const std::vector<S>& v) {
    std::string out = v.empty() ? "no pieces" : "";
    for (const S& x : v)
      out += std::string(out.empty() ? "" : ", ") + kind_name(x.kind) + " count " +
             std::to_string(x.count);
    return out;
  }

  /// Every point of s is the image of a point of r and back (kinds whose points are canonical).
  template <class S, class F>
  void compare_points(const L& r, const std::vector<S>& s, const F& image, double m,
                      const std::string& tag) {
    for (std::size_t i = 0; i < r.size() && i < s.size(); ++i)
      compare_points(r[i], s[i], image, m, tag);
  }
  template <class S, class F>
  requires(!std::is_same_v<S, L>) void compare_points(const R& r, const S& s, const F& image,
                                                      double m, const std::string& tag) {
    if (r.kind != Kind::point && r.kind != Kind::points && r.kind != Kind::segment) return;
    for (int i = 0; i < r.count; ++i) {
      const Vec<T, N> q = image(r.point[std::size_t(i)]);
      const double tol = pos_tol(std::max(m, inf_norm(q)));  // bounds are eps max(|X|inf, m)
      double best = std::numeric_limits<double>::infinity();
      for (int j = 0; j < s.count; ++j)
        best = std::min(best, inf_norm(vd(q) - vd(s.point[std::size_t(j)])));
      if (!(best <= tol))
        fail("point " + hex(r.point[std::size_t(i)]) + " has no counterpart (off by " + num(best) +
             " > " + num(tol) + ")" + tag);
    }
  }

  void check_swap(const A& a, const B& b, const L& r, double m) {
    const auto t = pieces(intersection(b, a));
    if (!same_shape(r, t, " (swapped)")) return;
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (opt_.exact_swap) {
        const auto w = swapped(r[i]);
        for (std::size_t j = 0; j < std::size_t(w.count); ++j) {
          if (!(t[i].point[j] == w.point[j]) || !same_param(t[i].param_a[j], w.param_a[j]) ||
              !same_param(t[i].param_b[j], w.param_b[j]))
            fail("intersection(b, a) != swapped(intersection(a, b)) at piece " + std::to_string(i) +
                 " entry " + std::to_string(j));
        }
        if constexpr (requires { w.multiplicity; }) {
          if (t[i].multiplicity != w.multiplicity) fail("swapped: multiplicities differ");
        }
      } else {
        compare_points(
            r[i], t[i], [](const Vec<T, N>& p) { return p; }, m, " (swapped)");
      }
    }
  }

  const Options& opt_;
  Rng& rng_;
  std::string what_;
  int failures_ = 0;
  std::array<int, 12> kinds_{};
};

/// Runs checks 1-6 (header comment) on opt.cases pairs drawn from gen(rng) (a std::pair<A, B>).
template <class T, class Gen, class A = typename std::invoke_result_t<Gen&, Rng&>::first_type,
          class B = typename std::invoke_result_t<Gen&, Rng&>::second_type>
void check_intersection_pairs(
    Gen gen, const Options& opt = {},
    std::type_identity_t<std::function<std::optional<Expected>(const A&, const B&)>> oracle = {}) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  PairChecker<T, A, B> checker(opt, rng);
  for (int i = 0; i < opt.cases; ++i) {
    const std::pair<A, B> ab = gen(rng);
    checker.run(ab.first, ab.second, i, oracle);
  }
  if (std::getenv("LOCUS_HARNESS_KINDS"))
    std::printf("  kinds: %s\n", checker.kind_tally().c_str());
  if (checker.failures() > 5) ADD_FAILURE() << checker.failures() << " failures in all";
}

/// A coordinate on the grid 2^-10 in [lo, hi]: sums, 2^k multiples and the motions stay exact.
template <class T>
T grid(Rng& rng, double lo, double hi) {
  return T(std::round(rng.uniform<double>(lo, hi) * 1024.0) / 1024.0);
}
template <class T, int N>
Vec<T, N> grid_vec(Rng& rng, double lo, double hi) {
  Vec<T, N> v{};
  for (int i = 0; i < N; ++i) v[i] = grid<T>(rng, lo, hi);
  return v;
}

}  // namespace locus_test::ix
