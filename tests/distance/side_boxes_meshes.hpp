// SPDX-License-Identifier: BSL-1.0
// Side<> descriptions (see distance/harness.hpp) of the primitives the shared harness does not
// know: orthogonal frusta (3D and 2D) and solid tetrahedra.
#pragma once

#include <locus/core/mat.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/frustum.hpp>
#include <locus/primitives/tetrahedron.hpp>

#include "distance/harness.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace locus_test::dist {

template <class T>
struct Side<locus::Frustum3<T>> {
  using P = locus::Frustum3<T>;
  using Param = locus::Vec3<T>;  // (s, t, w): s, t in [-1, 1], w in [0, 1]
  static constexpr int k = 3;
  static constexpr bool rotatable = true;
  static Vec<T, 3> map(const P& f, const T* u, T) {
    return point_at(f, Param{T(2) * u[0] - T(1), T(2) * u[1] - T(1), u[2]});
  }
  static Vec<T, 3> at(const P& f, const Param& p) { return point_at(f, p); }
  static bool param_ok(const P&, const Param& p, T tol) {
    return std::abs(p.x) <= T(1) + tol && std::abs(p.y) <= T(1) + tol && p.z >= -tol &&
           p.z <= T(1) + tol;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& f, const locus::Mat<T, 3, 3>& r, const Vec<T, 3>& t) {
    P o = f;
    o.origin = r * f.origin + t;
    o.direction = r * f.direction;
    o.up = r * f.up;
    o.right = r * f.right;
    return o;
  }
};

template <class T>
struct Side<locus::Frustum2<T>> {
  using P = locus::Frustum2<T>;
  using Param = locus::Vec2<T>;  // (s, w)
  static constexpr int k = 2;
  static constexpr bool rotatable = true;
  static Vec<T, 2> map(const P& f, const T* u, T) {
    return point_at(f, Param{T(2) * u[0] - T(1), u[1]});
  }
  static Vec<T, 2> at(const P& f, const Param& p) { return point_at(f, p); }
  static bool param_ok(const P&, const Param& p, T tol) {
    return std::abs(p.x) <= T(1) + tol && p.y >= -tol && p.y <= T(1) + tol;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& f, const locus::Mat<T, 2, 2>& r, const Vec<T, 2>& t) {
    P o = f;
    o.origin = r * f.origin + t;
    o.direction = r * f.direction;
    o.left = r * f.left;
    return o;
  }
};

template <class T>
struct Side<locus::Tetrahedron3<T>> {
  using P = locus::Tetrahedron3<T>;
  using Param = locus::Vec4<T>;  // barycentric
  static constexpr int k = 3;
  static constexpr bool rotatable = true;
  // The unit cube onto the simplex: sorted coordinates s0 <= s1 <= s2 give the barycentric
  // (s0, s1 - s0, s2 - s1, 1 - s2) (continuous and onto).
  static Vec<T, 3> map(const P& t, const T* u, T) {
    T s[3] = {u[0], u[1], u[2]};
    std::sort(s, s + 3);
    return point_at_barycentric(t, Param{s[0], s[1] - s[0], s[2] - s[1], T(1) - s[2]});
  }
  static Vec<T, 3> at(const P& t, const Param& b) { return point_at_barycentric(t, b); }
  static bool param_ok(const P&, const Param& b, T tol) {
    return b.x >= -tol && b.y >= -tol && b.z >= -tol && b.w >= -tol &&
           std::abs(b.x + b.y + b.z + b.w - T(1)) <= tol;
  }
  static bool in_window(const P&, const Param&, T) { return true; }
  static P moved(const P& t, const locus::Mat<T, 3, 3>& r, const Vec<T, 3>& x) {
    return {{r * t.v[0] + x, r * t.v[1] + x, r * t.v[2] + x, r * t.v[3] + x}};
  }
};

}  // namespace locus_test::dist
