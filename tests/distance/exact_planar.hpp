// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact (GMP rational) squared distances from points and lines, rays and segments to solid
// triangles, parallelograms (rectangles) and tetrahedra in 3D: the exact oracles of the
// linear-triangle, linear-rectangle, linear-tetrahedron, point-tetrahedron and triangle/rectangle
// pair tests. Method (independent of the library, all exact): a convex quadratic's minimum over a
// polytope is the unconstrained minimiser when it is feasible, otherwise the minimum over the
// polytope's facets; the facets are reduced to exact.hpp's point/linear queries.

#include <locus/core/vec.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/tetrahedron.hpp>
#include <locus/primitives/triangle.hpp>

#include "distance/exact.hpp"

#include <gmpxx.h>

#include <array>
#include <vector>

namespace locus_test::exact {

using Q3 = QVec<3>;

inline Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline bool is_zero(const Q3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

/// Exact triangle: three rational vertices.
struct QTri {
  Q3 v0, v1, v2;
};
template <class T>
QTri tri_of(const locus::Triangle3<T>& t) {
  return {to_q(t.v0), to_q(t.v1), to_q(t.v2)};
}

inline mpq_class min_q(const mpq_class& a, const mpq_class& b) { return a < b ? a : b; }

inline mpq_class sqr_point_triangle(const Q3& p, const QTri& t) {
  const Q3 e0 = sub(t.v1, t.v0), e1 = sub(t.v2, t.v0), w = sub(p, t.v0);
  if (!is_zero(cross(e0, e1))) {
    const mpq_class a = dot(e0, e0), b = dot(e0, e1), c = dot(e1, e1), d0 = dot(e0, w),
                    d1 = dot(e1, w), det = a * c - b * b;
    const mpq_class s = (c * d0 - b * d1) / det, u = (a * d1 - b * d0) / det;
    if (s >= 0 && u >= 0 && s + u <= 1) {
      const Q3 r = sub(w, axpy(axpy(Q3{0, 0, 0}, s, e0), u, e1));
      return dot(r, r);
    }
  }
  mpq_class best = sqr_point_linear(p, QLinear<3>{t.v0, e0, true, true});
  best = min_q(best, sqr_point_linear(p, QLinear<3>{t.v0, e1, true, true}));
  best = min_q(best, sqr_point_linear(p, QLinear<3>{t.v1, sub(t.v2, t.v1), true, true}));
  return best;
}

/// Exactly: does the linear component cross the (non-degenerate) triangle transversally?
inline bool crosses(const QLinear<3>& A, const QTri& t) {
  const Q3 e0 = sub(t.v1, t.v0), e1 = sub(t.v2, t.v0), n = cross(e0, e1);
  if (is_zero(n)) return false;
  const mpq_class dn = dot(n, A.dir);
  if (dn == 0) return false;
  const Q3 w = sub(A.origin, t.v0);
  const mpq_class tt = -dot(n, w) / dn;
  if (clamp_param(A, tt) != tt) return false;
  const Q3 x = sub(axpy(A.origin, tt, A.dir), t.v0);
  const mpq_class a = dot(e0, e0), b = dot(e0, e1), c = dot(e1, e1), d0 = dot(e0, x),
                  d1 = dot(e1, x), det = a * c - b * b;
  const mpq_class s = (c * d0 - b * d1) / det, u = (a * d1 - b * d0) / det;
  return s >= 0 && u >= 0 && s + u <= 1;
}

inline mpq_class sqr_linear_triangle(const QLinear<3>& A, const QTri& t) {
  if (is_zero(A.dir)) return sqr_point_triangle(A.origin, t);
  if (crosses(A, t)) return 0;
  // Otherwise the minimum lies on a facet: a finite end, or an edge of the triangle.
  mpq_class best = sqr_linear_linear(A, QLinear<3>{t.v0, sub(t.v1, t.v0), true, true});
  best = min_q(best, sqr_linear_linear(A, QLinear<3>{t.v0, sub(t.v2, t.v0), true, true}));
  best = min_q(best, sqr_linear_linear(A, QLinear<3>{t.v1, sub(t.v2, t.v1), true, true}));
  if (A.lo) best = min_q(best, sqr_point_triangle(A.origin, t));
  if (A.hi) best = min_q(best, sqr_point_triangle(axpy(A.origin, mpq_class(1), A.dir), t));
  return best;
}

/// The exact parallelogram center + s axis0 + t axis1, |s| <= e0, |t| <= e1, of a (rounded)
/// rectangle, as two exact triangles sharing the diagonal corner0-corner2.
template <class T>
std::array<QTri, 2> rect_triangles(const locus::Rectangle<T, 3>& r) {
  const Q3 c = to_q(r.center), a0 = to_q(r.axis[0]), a1 = to_q(r.axis[1]);
  const mpq_class e0(double(r.extent[0] > T(0) ? r.extent[0] : T(0)));
  const mpq_class e1(double(r.extent[1] > T(0) ? r.extent[1] : T(0)));
  const auto corner = [&](int sx, int sy) {
    return axpy(axpy(c, mpq_class(sx) * e0, a0), mpq_class(sy) * e1, a1);
  };
  const Q3 k0 = corner(-1, -1), k1 = corner(1, -1), k2 = corner(1, 1), k3 = corner(-1, 1);
  return {QTri{k0, k1, k2}, QTri{k0, k2, k3}};
}

template <class T>
mpq_class sqr_linear_rectangle(const QLinear<3>& A, const locus::Rectangle<T, 3>& r) {
  const auto tris = rect_triangles(r);
  return min_q(sqr_linear_triangle(A, tris[0]), sqr_linear_triangle(A, tris[1]));
}

/// Exact tetrahedron: inside test by the signs of the four sub-volumes.
inline mpq_class det3(const Q3& a, const Q3& b, const Q3& c) { return dot(a, cross(b, c)); }

inline bool inside_tetrahedron(const Q3& p, const std::array<Q3, 4>& v) {
  const mpq_class vol = det3(sub(v[1], v[0]), sub(v[2], v[0]), sub(v[3], v[0]));
  if (vol == 0) return false;  // flat: the faces decide
  for (int i = 0; i < 4; ++i) {
    std::array<Q3, 4> w = v;
    w[static_cast<std::size_t>(i)] = p;
    const mpq_class s = det3(sub(w[1], w[0]), sub(w[2], w[0]), sub(w[3], w[0]));
    if ((vol > 0 && s < 0) || (vol < 0 && s > 0)) return false;
  }
  return true;
}

inline std::array<QTri, 4> tet_faces(const std::array<Q3, 4>& v) {
  return {QTri{v[1], v[2], v[3]}, QTri{v[0], v[2], v[3]}, QTri{v[0], v[1], v[3]},
          QTri{v[0], v[1], v[2]}};
}

inline mpq_class sqr_point_tetrahedron(const Q3& p, const std::array<Q3, 4>& v) {
  if (inside_tetrahedron(p, v)) return 0;
  const auto f = tet_faces(v);
  mpq_class best = sqr_point_triangle(p, f[0]);
  for (int i = 1; i < 4; ++i)
    best = min_q(best, sqr_point_triangle(p, f[static_cast<std::size_t>(i)]));
  return best;
}

/// Linear component to solid tetrahedron: 0 when a finite end (or, for a line, any point) is
/// inside or the component crosses a face; otherwise the minimum over the faces. A zero
/// direction is the point origin (a line or ray too: it crosses no face).
inline mpq_class sqr_linear_tetrahedron(const QLinear<3>& A, const std::array<Q3, 4>& v) {
  const bool is_point = dot(A.dir, A.dir) == 0;
  if ((A.lo || is_point) && inside_tetrahedron(A.origin, v)) return 0;
  if (A.hi && inside_tetrahedron(axpy(A.origin, mpq_class(1), A.dir), v)) return 0;
  const auto f = tet_faces(v);
  mpq_class best = sqr_linear_triangle(A, f[0]);
  for (int i = 1; i < 4; ++i)
    best = min_q(best, sqr_linear_triangle(A, f[static_cast<std::size_t>(i)]));
  return best;
}

template <class T>
std::array<Q3, 4> tet_of(const locus::Tetrahedron3<T>& t) {
  return {to_q(t.v[0]), to_q(t.v[1]), to_q(t.v[2]), to_q(t.v[3])};
}

/// Two solid triangles: 0 when they meet, otherwise the minimum over the six edge-triangle
/// distances (two disjoint convex planar pieces have a closest pair on an edge of one).
inline mpq_class sqr_triangle_triangle(const QTri& a, const QTri& b) {
  const auto edges = [](const QTri& t) {
    return std::array<QLinear<3>, 3>{QLinear<3>{t.v0, sub(t.v1, t.v0), true, true},
                                     QLinear<3>{t.v1, sub(t.v2, t.v1), true, true},
                                     QLinear<3>{t.v2, sub(t.v0, t.v2), true, true}};
  };
  mpq_class best = -1;
  for (const auto& e : edges(a)) {
    const mpq_class q = sqr_linear_triangle(e, b);
    if (best < 0 || q < best) best = q;
  }
  for (const auto& e : edges(b)) best = min_q(best, sqr_linear_triangle(e, a));
  return best;
}

}  // namespace locus_test::exact
