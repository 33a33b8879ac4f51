// SPDX-License-Identifier: BSL-1.0
#pragma once
// Side<> descriptions (for the generic harness in distance/harness.hpp) of the solid tetrahedron
// and the planar polygon in 3D.

#include <locus/primitives/planar_polygon.hpp>
#include <locus/primitives/tetrahedron.hpp>

#include "distance/harness.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace locus_test::dist {

// Solid tetrahedron, barycentric parameter (b0, b1, b2, b3). The unit cube maps onto the simplex
// continuously by sorting: with x1 <= x2 <= x3 the sorted coordinates, b = (x1, x2 - x1, x3 - x2,
// 1 - x3) (each of the cube's six sorted sub-simplices maps linearly onto the tetrahedron).
template <class T>
struct Side<locus::Tetrahedron3<T>> {
  using P = locus::Tetrahedron3<T>;
  using Param = locus::Vec4<T>;
  static constexpr int k = 3;
  static constexpr bool rotatable = true;
  static Vec<T, 3> map(const P& tet, const T* u, T) {
    T x[3] = {u[0], u[1], u[2]};
    std::sort(x, x + 3);
    return point_at_barycentric(tet, Param{x[0], x[1] - x[0], x[2] - x[1], T(1) - x[2]});
  }
  static Vec<T, 3> at(const P& tet, const Param& b) { return point_at_barycentric(tet, b); }
  static bool param_ok(const P&, const Param& b, T tol) {
    return b.x >= -tol && b.y >= -tol && b.z >= -tol && b.w >= -tol &&
           std::abs(b.x + b.y + b.z + b.w - T(1)) <= tol;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& tet, const locus::Mat<T, 3, 3>& r, const Vec<T, 3>& t) {
    return {{r * tet.v[0] + t, r * tet.v[1] + t, r * tet.v[2] + t, r * tet.v[3] + t}};
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& tet, T f) {
    return {{f * tet.v[0], f * tet.v[1], f * tet.v[2], f * tet.v[3]}};
  }
};

// Planar polygon in 3D, parameter = plane coordinates (s, t) in its frame. The oracle's map
// assumes a polygon that is star-shaped with respect to the origin of its frame (the test
// generators build such polygons): u[0] walks around the boundary (by vertex-index fraction) and
// u[1] is the radial fraction, so the map is continuous and onto the filled polygon.
template <class T>
struct Side<locus::PlanarPolygon3<T>> {
  using P = locus::PlanarPolygon3<T>;
  using Param = locus::Vec2<T>;
  static constexpr int k = 2;
  static constexpr unsigned periodic = 1u;  // u[0] walks around the boundary
  static constexpr bool rotatable = true;
  static Param plane_point(const P& poly, const T* u) {
    const auto& v = poly.polygon.vertices;
    const std::size_t n = v.size();
    T w = u[0] - std::floor(u[0]);
    w *= static_cast<T>(n);
    std::size_t i = static_cast<std::size_t>(w);
    if (i >= n) i = n - 1;
    const T f = w - static_cast<T>(i);
    const Param b = lerp(v[i], v[(i + 1) % n], f);
    return T(std::clamp(u[1], T(0), T(1))) * b;
  }
  static Vec<T, 3> map(const P& poly, const T* u, T) {
    return point_at(poly, plane_point(poly, u));
  }
  static Vec<T, 3> at(const P& poly, const Param& st) { return point_at(poly, st); }
  static bool param_ok(const P&, const Param& st, T) { return locus::is_finite(st); }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& poly, const locus::Mat<T, 3, 3>& r, const Vec<T, 3>& t) {
    P q = poly;
    q.frame.origin = r * poly.frame.origin + t;
    q.frame.u = r * poly.frame.u;
    q.frame.v = r * poly.frame.v;
    q.frame.normal = r * poly.frame.normal;
    return q;
  }
  /// The object scaled by f about the origin (a power of two: exact).
  static P scaled(const P& poly, T f) {
    P q = poly;
    q.frame.origin = f * poly.frame.origin;
    for (auto& v : q.polygon.vertices) v = f * v;
    return q;
  }
};

}  // namespace locus_test::dist
