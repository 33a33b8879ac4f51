// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a line, ray or segment with a convex polyhedron given by half-spaces
// (clipping: entry and exit); row int3.linear-polyhedron, book section 11.5 (figures 11.6-11.8).
// The ray against a triangle mesh (the other half of the row) is spatial/bvh.hpp.
// ConvexPolyhedron3<T> {planes} is a view of the solid { X : dot(n_i, X) <= c_i for every i }
// (each Plane3 {n_i, c_i} with its normal pointing OUT of the solid; normals need not be unit);
// no planes is the whole space, an empty or flat intersection of half-spaces is allowed.
// intersection(component, poly) -> LinearPolyhedronIntersection<T> (param_a on the component:
// Line3 / Ray3 origin + t direction, Segment3 p0 + t (p1 - p0)): empty; point (entry = exit);
// segment [entry, exit] by increasing t; ray (a ray, or a line entering and never leaving:
// point[0] at the entry, point[1] one direction further; a line only leaving: point[1] one
// direction back); line (the whole line inside). Each plane bounds t from below where the
// component enters its half-space (sign of dot(n, d) < 0) and from above where it leaves (> 0);
// a parallel plane (dot(n, d) = 0) empties the result when the origin is strictly outside.
// Decisions exact: the signs of dot(n, d) and dot(n, o) - c (core/plane_side.hpp) and every
// comparison of two plane parameters (c_i - n_i.o)/(n_i.d) against each other, 0 and 1 (the
// sign of a degree-4 polynomial: a floating-point filter, then core/exact_sum.hpp). So a
// component through an edge or vertex, or touching a face, is classified exactly. Points: the
// parameters are rounded ((c - n.o) / n.d with compensated dot products) and the points
// o + t d; the component's own end points are returned exactly when they are entry or exit.
// Degenerate: a zero direction (or zero-length segment) acts as its point; a zero normal
// with c >= 0 constrains nothing and with c < 0 empties the result. NaN or infinite input:
// empty. intersects() is kind != empty. Swapped overloads return swapped(). Cost: O(planes)
// exact signs plus, per plane, O(1) parameter comparisons; no allocation.

#include <locus/core/exact_sum.hpp>
#include <locus/core/plane_side.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <cmath>
#include <cstddef>
#include <span>
#include <type_traits>

namespace locus {

/// A view of the convex solid { X : dot(n_i, X) <= c_i } of outward planes {n_i, c_i}.
template <Real T>
struct ConvexPolyhedron3 {
  std::span<const Plane3<T>> planes;
};

/// The result of intersection() of a Line3, Ray3 or Segment3 with a ConvexPolyhedron3.
template <Real T>
using LinearPolyhedronIntersection = Intersection<T, 3, T, NoParam, 2>;

namespace detail::linear_polyhedron {

using V = Vec3<double>;

/// A component o + t d, t >= 0 if lo, t <= 1 if hi (then q = p1 exact and d = q - o as a
/// polynomial, never rounded in decisions).
struct Comp {
  V o, d, q;
  bool lo, hi;
};

/// Terms of A = c - n.o (a_count 4) and B = n.d (3 terms) or n.q - n.o (6 terms).
struct Plane {
  V n;
  double c;
};

inline int collect(const Plane& p, const Comp& l, ExactMonomial (&a)[4], ExactMonomial (&b)[6]) {
  a[0] = {1, 0, 1, {p.c, 0, 0, 0}};
  for (int k = 0; k < 3; ++k) a[k + 1] = {-1, 0, 2, {p.n[k], l.o[k], 0, 0}};
  if (!l.hi) {
    for (int k = 0; k < 3; ++k) b[k] = {1, 0, 2, {p.n[k], l.d[k], 0, 0}};
    return 3;
  }
  for (int k = 0; k < 3; ++k) {
    b[k] = {1, 0, 2, {p.n[k], l.q[k], 0, 0}};
    b[k + 3] = {-1, 0, 2, {p.n[k], l.o[k], 0, 0}};
  }
  return 6;
}

/// Exact sign of a sum of monomials of at most four factors: a floating-point filter (at most
/// 3 roundings per product and n - 1 per sum, each 2^-53 relative to a partial sum of
/// magnitudes <= mag; the bound is taken at 2^-45 mag for n <= 48), then exact_sum.hpp.
inline int sum_sign(const ExactMonomial* m, int n) noexcept {
  double v = 0.0, mag = 0.0;
  for (int i = 0; i < n; ++i) {
    double prod = 1.0;
    for (int k = 0; k < m[i].count; ++k) prod *= m[i].f[k];
    v += m[i].sign * prod;
    mag += std::abs(prod);
  }
  if (mag > 0x1p-900 && mag < 0x1p900 && std::abs(v) > 0x1p-45 * mag) return v > 0 ? 1 : -1;
  return exact_sign_of_sum(std::span<const ExactMonomial>(m, static_cast<std::size_t>(n)));
}

/// Exact sign of A_i B_j - A_j B_i.
inline int cross_sign(const Plane& pi, const Plane& pj, const Comp& l) noexcept {
  ExactMonomial ai[4], bi[6], aj[4], bj[6];
  const int nb = collect(pi, l, ai, bi);
  (void)collect(pj, l, aj, bj);
  ExactMonomial m[48];
  int n = 0;
  const auto add = [&](const ExactMonomial& x, const ExactMonomial& y, int sign) {
    ExactMonomial t{x.sign * y.sign * sign, 0, x.count + y.count, {0, 0, 0, 0}};
    for (int k = 0; k < x.count; ++k) t.f[k] = x.f[k];
    for (int k = 0; k < y.count; ++k) t.f[x.count + k] = y.f[k];
    m[n++] = t;
  };
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < nb; ++b) {
      add(ai[a], bj[b], 1);
      add(aj[a], bi[b], -1);
    }
  return sum_sign(m, n);
}

/// Exact sign of B = n.d (or n.q - n.o).
inline int b_sign(const Plane& p, const Comp& l) noexcept {
  ExactMonomial a[4], b[6];
  const int nb = collect(p, l, a, b);
  return sum_sign(b, nb);
}

/// One plane's bound on t: sb = sign of B (-1: entering, t >= t_i; +1: leaving, t <= t_i),
/// s0 = sign of t_i, s1 = sign of t_i - 1 (segments).
struct Bound {
  std::size_t index;
  int sb, s0, s1;
};

using Result = Intersection<double, 3, double, NoParam, 2>;

inline double param(const Plane& p, const Comp& l) noexcept {
  const double a = -plane_value(p.n, p.c, l.o);
  const double b =
      l.hi ? plane_value(p.n, 0.0, l.q) - plane_value(p.n, 0.0, l.o) : dot_accurate(p.n, l.d);
  return a / b;
}

inline V at(const Comp& l, double t) noexcept {
  if (t == 0.0) return l.o;
  if (l.hi) return t == 1.0 ? l.q : l.o + t * (l.q - l.o);
  return l.o + t * l.d;
}

inline bool finite(const V& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

template <Real T>
[[nodiscard]] Result clip(const Comp& l, std::span<const Plane3<T>> poly) noexcept {
  Result r;
  if (!finite(l.o) || !finite(l.d) || !finite(l.q)) return r;
  const auto plane = [&](std::size_t i) {
    return Plane{vec_cast<double>(poly[i].normal), double(poly[i].constant)};
  };
  const auto compare = [&](const Bound& x, const Bound& y) {  // sign(t_x - t_y)
    return cross_sign(plane(x.index), plane(y.index), l) * x.sb * y.sb;
  };
  const bool point = l.hi ? l.o == l.q : l.d == V{};
  bool has_lo = false, has_hi = false;
  Bound lo{}, hi{};
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Plane p = plane(i);
    if (!finite(p.n) || !std::isfinite(p.c)) return r;
    const int so = to_int(side_of_plane(p.n, p.c, l.o));  // sign of n.o - c = -sign(A)
    const int sb = point ? 0 : b_sign(p, l);
    if (sb == 0) {
      if (so > 0) return r;  // parallel (or a point) strictly outside this half-space
      continue;
    }
    // t_i = A / B; t_i - 1 = (c - n.q) / B for a segment.
    const Bound b{i, sb, -so * sb, l.hi ? -to_int(side_of_plane(p.n, p.c, l.q)) * sb : 0};
    if (sb < 0) {
      if (!has_lo || compare(b, lo) > 0) lo = b, has_lo = true;
    } else {
      if (!has_hi || compare(b, hi) < 0) hi = b, has_hi = true;
    }
  }
  if (point) {
    r.kind = Kind::point;
    r.count = 1;
    r.point[0] = l.o;
    return r;
  }
  // The domain t >= 0 (lo), t <= 1 (hi): a plane bound replaces 0 when t_i > 0 and 1 when
  // t_i < 1 (exact signs).
  const bool lo_plane = has_lo && (!l.lo || lo.s0 > 0);
  const bool hi_plane = has_hi && (!l.hi || hi.s1 < 0);
  const bool lo_fin = lo_plane || l.lo, hi_fin = hi_plane || l.hi;
  int order = -1;  // sign(lower - upper)
  if (lo_fin && hi_fin) {
    if (lo_plane && hi_plane)
      order = compare(lo, hi);
    else if (lo_plane)
      order = lo.s1;  // against t = 1
    else if (hi_plane)
      order = -hi.s0;  // against t = 0
  }
  if (order > 0) return r;
  const double t0 = lo_plane ? param(plane(lo.index), l) : 0.0;
  double t1 = hi_plane ? param(plane(hi.index), l) : 1.0;
  if (order == 0) {
    r.kind = Kind::point;
    r.count = 1;
    r.param_a[0] = !lo_plane ? 0.0 : (!hi_plane ? 1.0 : t0);
    r.point[0] = at(l, r.param_a[0]);
    return r;
  }
  r.count = 2;
  if (lo_fin && hi_fin) {
    if (t1 < t0) t1 = t0;  // rounding cannot reverse the exact order
    r.kind = Kind::segment;
    r.param_a = {t0, t1};
    r.point = {at(l, t0), at(l, t1)};
  } else if (lo_fin) {
    r.kind = Kind::ray;
    r.param_a = {t0, t0 + 1.0};
    r.point = {at(l, t0), at(l, t0) + l.d};
  } else if (hi_fin) {
    r.kind = Kind::ray;
    r.param_a = {t1, t1 - 1.0};
    r.point = {at(l, t1), at(l, t1) - l.d};
  } else {
    r.kind = Kind::line;
    r.param_a = {0.0, 1.0};
    r.point = {l.o, l.o + l.d};
  }
  return r;
}

template <Real T>
[[nodiscard]] inline LinearPolyhedronIntersection<T> cast(const Result& r) noexcept {
  LinearPolyhedronIntersection<T> o;
  o.kind = r.kind;
  o.count = r.count;
  for (std::size_t i = 0; i < static_cast<std::size_t>(r.count); ++i) {
    o.point[i] = vec_cast<T>(r.point[i]);
    o.param_a[i] = static_cast<T>(r.param_a[i]);
  }
  return o;
}

}  // namespace detail::linear_polyhedron

/// The part of the line inside the convex polyhedron (see the header comment).
template <Real T>
[[nodiscard]] inline LinearPolyhedronIntersection<T> intersection(
    const Line3<T>& a, const ConvexPolyhedron3<T>& p) noexcept {
  namespace lp = detail::linear_polyhedron;
  return lp::cast<T>(lp::clip<T>(
      {vec_cast<double>(a.origin), vec_cast<double>(a.direction), {}, false, false}, p.planes));
}

/// The part of the ray inside the convex polyhedron: entry and exit (see the header comment).
template <Real T>
[[nodiscard]] inline LinearPolyhedronIntersection<T> intersection(
    const Ray3<T>& a, const ConvexPolyhedron3<T>& p) noexcept {
  namespace lp = detail::linear_polyhedron;
  return lp::cast<T>(lp::clip<T>(
      {vec_cast<double>(a.origin), vec_cast<double>(a.direction), {}, true, false}, p.planes));
}

/// The part of the segment inside the convex polyhedron (see the header comment).
template <Real T>
[[nodiscard]] inline LinearPolyhedronIntersection<T> intersection(
    const Segment3<T>& a, const ConvexPolyhedron3<T>& p) noexcept {
  namespace lp = detail::linear_polyhedron;
  const Vec3<double> p0 = vec_cast<double>(a.p0), p1 = vec_cast<double>(a.p1);
  return lp::cast<T>(lp::clip<T>({p0, p1 - p0, p1, true, true}, p.planes));
}

/// Whether the component meets the closed convex polyhedron (exact).
template <class C, Real T>
requires(std::is_same_v<C, Line3<T>> || std::is_same_v<C, Ray3<T>> ||
         std::is_same_v<C, Segment3<T>>)
    [[nodiscard]] inline bool intersects(const C& a, const ConvexPolyhedron3<T>& p) noexcept {
  return intersection(a, p).kind != Kind::empty;
}

/// Swapped arguments: swapped(intersection(a, p)).
template <class C, Real T>
requires(std::is_same_v<C, Line3<T>> || std::is_same_v<C, Ray3<T>> ||
         std::is_same_v<C, Segment3<T>>)
    [[nodiscard]] inline Intersection<T, 3, NoParam, T, 2> intersection(
        const ConvexPolyhedron3<T>& p, const C& a) noexcept {
  return swapped(intersection(a, p));
}

/// Swapped arguments: intersects(a, p).
template <class C, Real T>
requires(std::is_same_v<C, Line3<T>> || std::is_same_v<C, Ray3<T>> ||
         std::is_same_v<C, Segment3<T>>)
    [[nodiscard]] inline bool intersects(const ConvexPolyhedron3<T>& p, const C& a) noexcept {
  return intersects(a, p);
}

}  // namespace locus
