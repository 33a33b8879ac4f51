// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact (GMP rational) intersection of two 2D linear components: the oracle of the int2.linear
// tests. Independent of the library's method: each component is origin + t direction with its
// parameter domain; crossing parameters solve the 2x2 system by Cramer's rule in rationals;
// parallel components are collinear when the origins' difference is parallel too, and then the
// second's parameter interval is mapped onto the first's affinely and intersected.

#include <locus/core/vec.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <gmpxx.h>

#include <optional>

namespace locus_test::exact2 {

struct Q2 {
  mpq_class x, y;
};
inline Q2 operator-(const Q2& a, const Q2& b) { return {a.x - b.x, a.y - b.y}; }
inline Q2 operator+(const Q2& a, const Q2& b) { return {a.x + b.x, a.y + b.y}; }
inline Q2 operator*(const mpq_class& s, const Q2& a) { return {s * a.x, s * a.y}; }
inline mpq_class cross(const Q2& a, const Q2& b) { return a.x * b.y - a.y * b.x; }
inline mpq_class qdot(const Q2& a, const Q2& b) { return a.x * b.x + a.y * b.y; }
inline bool operator==(const Q2& a, const Q2& b) { return a.x == b.x && a.y == b.y; }

template <class T>
Q2 q(const locus::Vec2<T>& v) {
  return {mpq_class(double(v.x)), mpq_class(double(v.y))};
}

/// origin + t dir with t >= 0 if lo, t <= 1 if hi.
struct QLin {
  Q2 o, d;
  bool lo, hi;
};
template <class T>
QLin ql(const locus::Line2<T>& l) {
  return {q(l.origin), q(l.direction), false, false};
}
template <class T>
QLin ql(const locus::Ray2<T>& r) {
  return {q(r.origin), q(r.direction), true, false};
}
template <class T>
QLin ql(const locus::Segment2<T>& s) {
  return {q(s.p0), q(s.p1) - q(s.p0), true, true};
}

enum class QKind { empty, point, segment, ray, line };

/// One parameter bound: infinite or a rational.
struct QEnd {
  bool inf;
  mpq_class t;
};

/// The exact answer: the kind; for point, segment and ray the finite points (ordered by the
/// first component's parameter) with their exact parameters on both components; for ray also
/// the sign (+1/-1) of the direction along the first component's parameter.
struct QResult {
  QKind kind = QKind::empty;
  int count = 0;
  Q2 point[2];
  mpq_class ta[2], tb[2];
  int ray_dir = 0;
};

inline bool in_domain(const QLin& l, const mpq_class& t) {
  return !(l.lo && t < 0) && !(l.hi && t > 1);
}

inline QResult point_result(const Q2& p, const mpq_class& ta, const mpq_class& tb) {
  QResult r;
  r.kind = QKind::point;
  r.count = 1;
  r.point[0] = p;
  r.ta[0] = ta;
  r.tb[0] = tb;
  return r;
}

/// Parameter on l of a point p of l's line (l non-degenerate).
inline mpq_class param_of(const QLin& l, const Q2& p) {
  return qdot(p - l.o, l.d) / qdot(l.d, l.d);
}

inline QResult intersect(const QLin& A, const QLin& B) {
  const Q2 zero{0, 0};
  const bool pa = A.d == zero, pb = B.d == zero;
  if (pa && pb) return A.o == B.o ? point_result(A.o, 0, 0) : QResult{};
  if (pa || pb) {
    const QLin& L = pa ? B : A;
    const Q2& p = pa ? A.o : B.o;
    if (cross(L.d, p - L.o) != 0) return {};
    const mpq_class t = param_of(L, p);
    if (!in_domain(L, t)) return {};
    return pa ? point_result(p, 0, t) : point_result(p, t, 0);
  }
  const mpq_class den = cross(A.d, B.d);
  const Q2 w = B.o - A.o;
  if (den != 0) {
    const mpq_class t = cross(w, B.d) / den, u = cross(w, A.d) / den;
    if (!in_domain(A, t) || !in_domain(B, u)) return {};
    return point_result(A.o + t * A.d, t, u);
  }
  if (cross(w, A.d) != 0) return {};
  // Collinear: B's parameter u maps to A's parameter s0 + k u.
  const mpq_class s0 = param_of(A, B.o), k = qdot(B.d, A.d) / qdot(A.d, A.d);
  QEnd alo{!A.lo, 0}, ahi{!A.hi, 1};
  QEnd b0{!B.lo, s0}, b1{!B.hi, s0 + k};
  QEnd blo = k > 0 ? b0 : b1, bhi = k > 0 ? b1 : b0;
  QEnd lo = alo.inf ? blo : (blo.inf ? alo : (alo.t >= blo.t ? alo : blo));
  QEnd hi = ahi.inf ? bhi : (bhi.inf ? ahi : (ahi.t <= bhi.t ? ahi : bhi));
  QResult r;
  const auto put = [&](const mpq_class& t) {
    r.point[r.count] = A.o + t * A.d;
    r.ta[r.count] = t;
    r.tb[r.count] = (t - s0) / k;
    ++r.count;
  };
  if (!lo.inf && !hi.inf) {
    if (lo.t > hi.t) return r;
    r.kind = lo.t == hi.t ? QKind::point : QKind::segment;
    put(lo.t);
    if (lo.t < hi.t) put(hi.t);
    return r;
  }
  if (lo.inf && hi.inf) {
    r.kind = QKind::line;
    return r;
  }
  r.kind = QKind::ray;
  put(lo.inf ? hi.t : lo.t);
  r.ray_dir = lo.inf ? -1 : 1;
  return r;
}

}  // namespace locus_test::exact2
