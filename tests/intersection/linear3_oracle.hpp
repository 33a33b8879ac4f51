// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact (GMP rational) intersection of a 3D linear component with a plane and with a closed
// triangle: the oracle of the int3.linear-plane and int3.linear-triangle tests. Independent of
// the library's method (which decides by Pluecker signs and orient3d): here the crossing
// parameter solves dot(n, o + t d) = c in rationals and the crossing point's barycentrics are
// solved from the normal (s = N.((X - v0) x e2) / N.N, t = N.(e1 x (X - v0)) / N.N); a
// component in the triangle's plane is clipped against the three edge half-planes, each an
// affine inequality alpha + beta t >= 0 in its parameter.

#include <locus/core/vec.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>
#include <locus/primitives/triangle.hpp>

#include <gmpxx.h>

#include <algorithm>

namespace locus_test::exact3 {

struct Q3 {
  mpq_class x, y, z;
};
inline Q3 operator-(const Q3& a, const Q3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Q3 operator+(const Q3& a, const Q3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Q3 operator*(const mpq_class& s, const Q3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline mpq_class qdot(const Q3& a, const Q3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Q3 qcross(const Q3& a, const Q3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline bool operator==(const Q3& a, const Q3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
inline bool is_zero(const Q3& a) { return a.x == 0 && a.y == 0 && a.z == 0; }

template <class T>
Q3 q(const locus::Vec3<T>& v) {
  return {mpq_class(double(v.x)), mpq_class(double(v.y)), mpq_class(double(v.z))};
}
inline double qmax_abs(const Q3& p) {
  return std::max({std::abs(p.x.get_d()), std::abs(p.y.get_d()), std::abs(p.z.get_d())});
}

/// o + t d with t >= 0 if lo, t <= 1 if hi.
struct QLin {
  Q3 o, d;
  bool lo, hi;
};
template <class T>
QLin ql(const locus::Line3<T>& l) {
  return {q(l.origin), q(l.direction), false, false};
}
template <class T>
QLin ql(const locus::Ray3<T>& r) {
  return {q(r.origin), q(r.direction), true, false};
}
template <class T>
QLin ql(const locus::Segment3<T>& s) {
  return {q(s.p0), q(s.p1) - q(s.p0), true, true};
}
inline bool in_domain(const QLin& l, const mpq_class& t) {
  return !(l.lo && t < 0) && !(l.hi && t > 1);
}

enum class QKind { empty, point, segment, ray, line };

/// The exact answer: kind; for point and segment the points (by increasing t) with t and, on a
/// triangle, (s, t).
struct QResult {
  QKind kind = QKind::empty;
  int count = 0;
  Q3 point[2];
  mpq_class t[2];
  mpq_class s2[2], t2[2];
};

/// Against the plane { X : dot(n, X) = c } (n != 0).
inline QResult plane(const QLin& l, const Q3& n, const mpq_class& c) {
  QResult r;
  const mpq_class v0 = qdot(n, l.o) - c, nd = qdot(n, l.d);
  if (is_zero(l.d)) {
    if (v0 != 0) return r;
    r.kind = QKind::point;
    r.count = 1;
    r.point[0] = l.o;
    r.t[0] = 0;
    return r;
  }
  if (nd == 0) {
    if (v0 != 0) return r;
    r.kind = l.hi ? QKind::segment : (l.lo ? QKind::ray : QKind::line);
    r.count = 2;
    r.point[0] = l.o;
    r.point[1] = l.o + l.d;
    r.t[0] = 0;
    r.t[1] = 1;
    return r;
  }
  const mpq_class t = -v0 / nd;
  if (!in_domain(l, t)) return r;
  r.kind = QKind::point;
  r.count = 1;
  r.t[0] = t;
  r.point[0] = l.o + t * l.d;
  return r;
}

struct QTri {
  Q3 v0, v1, v2;
};
template <class T>
QTri qt(const locus::Triangle3<T>& t) {
  return {q(t.v0), q(t.v1), q(t.v2)};
}

/// (s, t) of a point of the triangle's plane (N != 0).
inline void st_of(const QTri& tr, const Q3& x, mpq_class& s, mpq_class& t) {
  const Q3 e1 = tr.v1 - tr.v0, e2 = tr.v2 - tr.v0, n = qcross(e1, e2);
  const mpq_class nn = qdot(n, n);
  s = qdot(n, qcross(x - tr.v0, e2)) / nn;
  t = qdot(n, qcross(e1, x - tr.v0)) / nn;
}

/// Against the closed triangle; a degenerate triangle gives empty (the library's convention).
inline QResult triangle(const QLin& l, const QTri& tr) {
  QResult r;
  const Q3 e1 = tr.v1 - tr.v0, e2 = tr.v2 - tr.v0, n = qcross(e1, e2);
  if (is_zero(n)) return r;
  const auto put = [&](const mpq_class& t) {
    const Q3 x = l.o + t * l.d;
    r.point[r.count] = x;
    r.t[r.count] = t;
    st_of(tr, x, r.s2[r.count], r.t2[r.count]);
    ++r.count;
  };
  const mpq_class nd = qdot(n, l.d), side = qdot(n, l.o - tr.v0);
  if (nd != 0 || is_zero(l.d)) {
    const mpq_class t = is_zero(l.d) ? mpq_class(0) : mpq_class(-side / nd);
    if (is_zero(l.d) && side != 0) return r;
    if (!in_domain(l, t)) return r;
    put(t);
    if (r.s2[0] < 0 || r.t2[0] < 0 || r.s2[0] + r.t2[0] > 1) return QResult{};
    r.kind = QKind::point;
    return r;
  }
  if (side != 0) return r;
  // Coplanar: the parameter interval where o + t d is inside each edge's half-plane.
  bool lo_inf = !l.lo, hi_inf = !l.hi;
  mpq_class lo = 0, hi = 1;
  const Q3 v[3] = {tr.v0, tr.v1, tr.v2};
  for (int i = 0; i < 3; ++i) {
    const Q3 a = v[i], b = v[(i + 1) % 3];
    // inside iff N.((b - a) x (x - a)) >= 0, x = o + t d: alpha + beta t >= 0.
    const mpq_class alpha = qdot(n, qcross(b - a, l.o - a)), beta = qdot(n, qcross(b - a, l.d));
    if (beta == 0) {
      if (alpha < 0) return r;
      continue;
    }
    const mpq_class t = -alpha / beta;
    if (beta > 0) {
      if (lo_inf || t > lo) lo = t, lo_inf = false;
    } else {
      if (hi_inf || t < hi) hi = t, hi_inf = false;
    }
  }
  if (lo > hi) return r;
  put(lo);
  if (lo == hi) {
    r.kind = QKind::point;
    return r;
  }
  put(hi);
  r.kind = QKind::segment;
  return r;
}

}  // namespace locus_test::exact3
