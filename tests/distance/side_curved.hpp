// SPDX-License-Identifier: BSL-1.0
#pragma once
// Side<> descriptions (see harness.hpp) of the curved primitives used by the curved distance
// tests: ellipses, ellipsoids, Bézier / B-spline / NURBS curves and surfaces. Each maps the
// oracle's unit box onto the primitive's own parametrisation (the one its point_at uses).
#include <locus/curves/bezier.hpp>
#include <locus/curves/bezier_surface.hpp>
#include <locus/curves/bspline.hpp>
#include <locus/curves/bspline_surface.hpp>
#include <locus/curves/nurbs.hpp>
#include <locus/curves/nurbs_surface.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/ellipsoid.hpp>

#include "distance/harness.hpp"

#include <cmath>
#include <type_traits>
#include <utility>

namespace locus_test::dist {

template <class T>
struct Side<locus::Ellipse2<T>> {
  using P = locus::Ellipse2<T>;
  using Param = T;  // angle
  static constexpr int k = 1;
  static constexpr unsigned periodic = 1u;
  static constexpr bool rotatable = true;
  static Vec<T, 2> map(const P& e, const T* u, T) {
    return point_at(e, T(6.283185307179586) * u[0]);
  }
  static Vec<T, 2> at(const P& e, T a) { return point_at(e, a); }
  static bool param_ok(const P&, T a, T) { return locus::is_finite(a); }
  static bool in_window(const P&, T, T) { return true; }
  static P moved(const P& e, const locus::Mat<T, 2, 2>& r, const Vec<T, 2>& t) {
    return {r * e.center + t, {r * e.axis[0], r * e.axis[1]}, {e.extent[0], e.extent[1]}};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& e, T f) {
    return {f * e.center, {e.axis[0], e.axis[1]}, {f * e.extent[0], f * e.extent[1]}};
  }
};

template <class T>
struct Side<locus::Ellipsoid3<T>> {
  using P = locus::Ellipsoid3<T>;
  using Param = locus::Vec2<T>;  // (theta, phi)
  static constexpr int k = 2;
  static constexpr unsigned periodic = 3u;
  static constexpr bool rotatable = true;
  static Vec<T, 3> map(const P& e, const T* u, T) {
    return point_at(e, Param{T(6.283185307179586) * u[0], T(3.141592653589793) * u[1]});
  }
  static Vec<T, 3> at(const P& e, const Param& tp) { return point_at(e, tp); }
  static bool param_ok(const P&, const Param& tp, T tol) {
    return locus::is_finite(tp) && tp.y >= -tol && tp.y <= T(3.141592653589793) + tol;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& e, const locus::Mat<T, 3, 3>& r, const Vec<T, 3>& t) {
    return {r * e.center + t, {r * e.axis[0], r * e.axis[1], r * e.axis[2]}, e.extent};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& e, T f) {
    return {f * e.center, {e.axis[0], e.axis[1], e.axis[2]}, f * e.extent};
  }
};

// ---- curves: the parameter is the curve's own t ---------------------------------------------
template <class Curve, class T, int N>
struct CurveSide {
  using Param = T;
  static constexpr int k = 1;
  static constexpr bool rotatable = true;
  static locus::ParamDomain<T> dom(const Curve& c) {
    if constexpr (requires { domain(c); })
      return domain(c);
    else
      return {T(0), T(1)};
  }
  static Vec<T, N> map(const Curve& c, const T* u, T) {
    const auto d = dom(c);
    return point_at(c, d.min + u[0] * (d.max - d.min));
  }
  static Vec<T, N> at(const Curve& c, T t) { return point_at(c, t); }
  static bool param_ok(const Curve& c, T t, T tol) {
    const auto d = dom(c);
    return t >= d.min - tol && t <= d.max + tol;
  }
  static bool in_window(const Curve&, T, T) { return true; }
  static Curve moved(const Curve& c, const locus::Mat<T, N, N>& r, const Vec<T, N>& t) {
    Curve m = c;
    for (auto& q : m.control) q = r * q + t;
    return m;
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static Curve scaled(const Curve& c, T f) {
    Curve m = c;
    for (auto& q : m.control) q = f * q;
    return m;
  }
};
template <class T, int N>
struct Side<locus::BezierCurve<T, N>> : CurveSide<locus::BezierCurve<T, N>, T, N> {};
template <class T, int N>
struct Side<locus::BSplineCurve<T, N>> : CurveSide<locus::BSplineCurve<T, N>, T, N> {};
template <class T, int N>
struct Side<locus::NurbsCurve<T, N>> : CurveSide<locus::NurbsCurve<T, N>, T, N> {};

}  // namespace locus_test::dist
