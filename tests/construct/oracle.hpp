// SPDX-License-Identifier: BSL-1.0
#pragma once
// Oracles of the construct tests: conditions (through a point, tangent to a line, tangent to a
// circle) evaluated in 1024-bit GMP floats (mpf) on the exact input values, so a residual is the
// true residual of the rounded solution; and counts from the plain geometric comparisons
// (distance against radius sums, with square roots taken in mpf), a second formulation next to
// the library's squared polynomials. Inputs of the tie cases are small integers and Pythagorean
// directions, where every mpf operation below is exact, so a zero is a true zero.

#include <gmpxx.h>

#include <locus/core/vec.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace locus_test::cons {

inline mpf_class F(double x) {
  static const bool init = (mpf_set_default_prec(1024), true);  // every temporary in 1024 bits
  (void)init;
  return mpf_class(x, 1024);
}
inline mpf_class Z() { return mpf_class(0, 1024); }
inline int sign_of(const mpf_class& v) {
  // Random inputs stay far from ties; tie inputs are exact. Anything below 2^-600 is a zero.
  if (abs(v) < mpf_class("1e-180", 1024)) return 0;
  return v > 0 ? 1 : -1;
}
inline mpf_class msqrt(const mpf_class& v) {
  mpf_class r(0, 1024);
  mpf_sqrt(r.get_mpf_t(), v.get_mpf_t());
  return r;
}

/// A defining condition of a construction.
struct Cond {
  enum Kind { point, line, circle } kind;
  double a, b, c, d;  // point (a, b); line origin (a, b) direction (c, d); circle (a, b) radius c
  template <class T>
  static Cond of(const locus::Vec2<T>& p) {
    return {point, double(p.x), double(p.y), 0, 0};
  }
  template <class T>
  static Cond of(const locus::Line2<T>& l) {
    return {line, double(l.origin.x), double(l.origin.y), double(l.direction.x),
            double(l.direction.y)};
  }
  template <class T>
  static Cond of(const locus::Circle2<T>& c) {
    return {circle, double(c.center.x), double(c.center.y), double(c.radius), 0};
  }
  double magnitude() const {
    return std::max({std::abs(a), std::abs(b), kind == circle ? std::abs(c) : 0.0});
  }
};

/// Distance from (x, y) to what the condition names (point, line; circle: to its centre).
inline mpf_class dist(const Cond& k, double x, double y) {
  const mpf_class dx = F(x) - F(k.a), dy = F(y) - F(k.b);
  if (k.kind == Cond::line) {
    const mpf_class cr = F(k.c) * dy - F(k.d) * dx;
    return abs(cr) / msqrt(F(k.c) * F(k.c) + F(k.d) * F(k.d));
  }
  return msqrt(dx * dx + dy * dy);
}

/// Residual of the circle (x, y, r) against the condition: | |X - p| - r |, | dist - r |, or for a
/// circle the smaller of | |X - C| - (R + r) | and | |X - C| - |R - r| |.
inline double residual(const Cond& k, double x, double y, double r) {
  const mpf_class d = dist(k, x, y);
  if (k.kind != Cond::circle) return std::abs(mpf_class(d - F(r)).get_d());
  const double e = std::abs(mpf_class(d - (F(k.c) + F(r))).get_d());
  const double i = std::abs(mpf_class(d - abs(F(k.c) - F(r))).get_d());
  return std::min(e, i);
}

/// The locus of centres of radius-r circles meeting the condition: for a point or a line one
/// (distance r), for a circle two (R + r, and |R - r| when R != r). Number of intersection
/// points of two loci, -1 for infinitely many.
struct Locus {
  bool is_line;
  mpf_class x, y, dx, dy, rho;  // circle: centre, radius; line: origin, unit direction
};
inline int meet(const Locus& a, const Locus& b) {
  if (a.is_line && b.is_line) {
    const mpf_class cr = a.dx * b.dy - a.dy * b.dx;
    if (sign_of(cr) != 0) return 1;
    const mpf_class off = a.dx * (b.y - a.y) - a.dy * (b.x - a.x);
    return sign_of(off) == 0 ? -1 : 0;
  }
  if (a.is_line || b.is_line) {
    const Locus& l = a.is_line ? a : b;
    const Locus& c = a.is_line ? b : a;
    const mpf_class dd = abs(l.dx * (c.y - l.y) - l.dy * (c.x - l.x));
    const int s = sign_of(c.rho - dd);
    return s < 0 ? 0 : (s == 0 ? 1 : 2);
  }
  const mpf_class d = msqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
  if (sign_of(d) == 0) return sign_of(a.rho - b.rho) == 0 ? -1 : 0;
  const int hi = sign_of(a.rho + b.rho - d), lo = sign_of(d - abs(a.rho - b.rho));
  if (hi < 0 || lo < 0) return 0;
  return (hi == 0 || lo == 0) ? 1 : 2;
}

inline void loci(const Cond& k, double r, Locus* out, int& n) {
  n = 0;
  if (k.kind == Cond::point) {
    out[n++] = {false, F(k.a), F(k.b), Z(), Z(), F(r)};
  } else if (k.kind == Cond::circle) {
    out[n++] = {false, F(k.a), F(k.b), Z(), Z(), F(k.c) + F(r)};
    if (k.c != r) out[n++] = {false, F(k.a), F(k.b), Z(), Z(), abs(F(k.c) - F(r))};
  } else {
    const mpf_class len = msqrt(F(k.c) * F(k.c) + F(k.d) * F(k.d));
    const mpf_class ux = F(k.c) / len, uy = F(k.d) / len;
    for (int s : {1, -1})
      out[n++] = {true, F(k.a) - s * F(r) * uy, F(k.b) + s * F(r) * ux, ux, uy, Z()};
  }
}

/// Number of radius-r circles meeting both conditions; -1 when infinitely many.
inline int radius_count(const Cond& a, const Cond& b, double r) {
  Locus la[2], lb[2];
  int na = 0, nb = 0;
  loci(a, r, la, na);
  loci(b, r, lb, nb);
  int total = 0;
  bool inf = false;
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j) {
      const int m = meet(la[i], lb[j]);
      if (m < 0)
        inf = true;
      else
        total += m;
    }
  return inf ? -1 - total : total;
}

// ---- exact transforms of the inputs: a 90 degree rotation and a power-of-two scale ------------

template <class T>
locus::Vec2<T> rot(const locus::Vec2<T>& p) {
  return {-p.y, p.x};
}
template <class T>
locus::Line2<T> rot(const locus::Line2<T>& l) {
  return {rot(l.origin), rot(l.direction)};
}
template <class T>
locus::Circle2<T> rot(const locus::Circle2<T>& c) {
  return {rot(c.center), c.radius};
}
template <class T>
T scaled(T x, int k) {
  return std::ldexp(x, k);
}
template <class T>
locus::Vec2<T> scaled(const locus::Vec2<T>& p, int k) {
  return {std::ldexp(p.x, k), std::ldexp(p.y, k)};
}
template <class T>
locus::Line2<T> scaled(const locus::Line2<T>& l, int k) {
  return {scaled(l.origin, k), scaled(l.direction, k)};
}
template <class T>
locus::Circle2<T> scaled(const locus::Circle2<T>& c, int k) {
  return {scaled(c.center, k), std::ldexp(c.radius, k)};
}

}  // namespace locus_test::cons
