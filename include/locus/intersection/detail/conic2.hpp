// SPDX-License-Identifier: BSL-1.0
#pragma once
// The engine behind the 2D curve pairs (rows int2.linear-quadratic, int2.quadratic): linear
// components against circles, arcs, ellipses and general quadratic curves; circle-circle,
// circle-arc, arc-arc; ellipse-ellipse and quadratic pairs. Everything is computed in double
// (float input is promoted exactly) and compiled once in src/intersection/conic2.cpp; the pair
// headers only convert. Exact decisions: a linear component p(t) = o + t d against a conic
// Q(X) = 0 reduces to q(t) = Q(p(t)) = A t^2 + B t + C; the signs of A, B, C, of q and q' at a
// segment's end and of the discriminant are polynomials in the input doubles, evaluated exactly
// (core/exact_poly.hpp), and fix how many roots lie in the parameter domain.
// docs/notes/intersection.md derives each case.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/arc.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/quadratic_curve.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <cstdint>

namespace locus {

/// The result of intersection() between a linear component and a circle, arc, ellipse or
/// quadratic curve (at most two points, or the component itself).
template <Real T>
using LinearCurveIntersection2 = CurveIntersection2<T, 2>;
/// The result of intersection() between two of circle, ellipse, quadratic curve (at most four
/// points, or coincident).
template <Real T>
using CurvePairIntersection2 = CurveIntersection2<T, 4>;
/// The result of intersection() involving an arc and a circle or arc: up to two points, or up to
/// two overlapping arcs of the common circle (three points each: start, middle, end).
template <Real T>
using ArcIntersection2 = CurveIntersection2<T, 6>;

namespace detail::conic2 {

using V = Vec2<double>;

/// A linear component: o + t d with t >= 0 if lo and t <= 1 if hi. For a segment o = p0,
/// p1 = its end and d = p1 - p0 rounded (exact decisions use p0 and p1, never d).
struct Lin {
  V o, p1, d;
  bool lo, hi;
};

template <Real T>
[[nodiscard]] constexpr Lin as_lin(const Line2<T>& l) noexcept {
  return {vec_cast<double>(l.origin), V{}, vec_cast<double>(l.direction), false, false};
}
template <Real T>
[[nodiscard]] constexpr Lin as_lin(const Ray2<T>& r) noexcept {
  return {vec_cast<double>(r.origin), V{}, vec_cast<double>(r.direction), true, false};
}
template <Real T>
[[nodiscard]] constexpr Lin as_lin(const Segment2<T>& s) noexcept {
  const V p0 = vec_cast<double>(s.p0), p1 = vec_cast<double>(s.p1);
  return {p0, p1, p1 - p0, true, true};
}

/// A conic in one of its three given forms.
enum class Form : std::uint8_t { circle, ellipse, general };
struct Conic {
  Form form = Form::general;
  V c{};                  ///< centre (circle, ellipse)
  double r = 0;           ///< radius (circle)
  V u0{}, u1{};           ///< axes (ellipse)
  double e0 = 0, e1 = 0;  ///< extents (ellipse)
  double q[6] = {};       ///< a, b, c, d, e, f (general)
};

template <Real T>
[[nodiscard]] constexpr Conic as_conic(const Circle2<T>& c) noexcept {
  Conic k;
  k.form = Form::circle;
  k.c = vec_cast<double>(c.center);
  k.r = double(c.radius);
  return k;
}
template <Real T>
[[nodiscard]] constexpr Conic as_conic(const Ellipse2<T>& e) noexcept {
  Conic k;
  k.form = Form::ellipse;
  k.c = vec_cast<double>(e.center);
  k.u0 = vec_cast<double>(e.axis[0]);
  k.u1 = vec_cast<double>(e.axis[1]);
  k.e0 = double(e.extent[0]);
  k.e1 = double(e.extent[1]);
  return k;
}
template <Real T>
[[nodiscard]] constexpr Conic as_conic(const QuadraticCurve2<T>& q) noexcept {
  Conic k;
  k.form = Form::general;
  k.q[0] = double(q.a);
  k.q[1] = double(q.b);
  k.q[2] = double(q.c);
  k.q[3] = double(q.d);
  k.q[4] = double(q.e);
  k.q[5] = double(q.f);
  return k;
}

/// An arc in double: circle, start angle, sweep.
struct ArcD {
  V c;
  double r, start, sweep;
};
template <Real T>
[[nodiscard]] constexpr ArcD as_arc(const Arc2<T>& a) noexcept {
  return {vec_cast<double>(a.circle.center), double(a.circle.radius), double(a.start),
          double(a.sweep)};
}

using R2 = CurveIntersection2<double, 2>;
using R4 = CurveIntersection2<double, 4>;
using R6 = CurveIntersection2<double, 6>;

// Compiled in src/intersection/conic2.cpp.
[[nodiscard]] R2 linear_conic(const Lin& l, const Conic& k) noexcept;
[[nodiscard]] R2 linear_arc(const Lin& l, const ArcD& a) noexcept;
[[nodiscard]] R4 circle_circle(V c0, double r0, V c1, double r1) noexcept;
[[nodiscard]] RegionRelation circle_relation(V c0, double r0, V c1, double r1) noexcept;
[[nodiscard]] R6 circle_arc(V c0, double r0, const ArcD& a) noexcept;
[[nodiscard]] R6 arc_arc(const ArcD& a, const ArcD& b) noexcept;
[[nodiscard]] R4 conic_conic(const Conic& a, const Conic& b) noexcept;
[[nodiscard]] RegionRelation ellipse_relation(const Conic& a, const Conic& b) noexcept;

/// The result in T (points and parameters rounded once more for float).
template <Real T, int C>
[[nodiscard]] constexpr CurveIntersection2<T, C> cast(
    const CurveIntersection2<double, C>& r) noexcept {
  CurveIntersection2<T, C> s;
  static_cast<Intersection<T, 2, T, T, C>&>(s) =
      intersection_cast<T>(static_cast<const Intersection<double, 2, double, double, C>&>(r));
  s.multiplicity = r.multiplicity;
  return s;
}

}  // namespace detail::conic2
}  // namespace locus
