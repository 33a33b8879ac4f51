// SPDX-License-Identifier: BSL-1.0
// Side<> descriptions (see distance/harness.hpp) of the primitives the shared harness does not
// know: orthogonal frusta (3D and 2D); solid tetrahedra come from side_solids.hpp.
#pragma once

#include <locus/core/mat.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/frustum.hpp>

#include "distance/harness.hpp"
#include "distance/side_solids.hpp"

#include <cmath>
#include <vector>

namespace locus_test::dist {

/// A frustum (3D or 2D) scaled by k about the origin (a power of two: exact): its origin, near
/// and far distances and bounds; the axes are unit vectors.
template <class F, class T>
F scaled_frustum(F f, T k) {
  f.origin = k * f.origin;
  f.d_min *= k;
  f.d_max *= k;
  if constexpr (requires { f.l_bound; }) {
    f.l_bound *= k;
  } else {
    f.u_bound *= k;
    f.r_bound *= k;
  }
  return f;
}

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
  static P scaled(const P& f, T factor) { return scaled_frustum(f, factor); }
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
  static P scaled(const P& f, T factor) { return scaled_frustum(f, factor); }
};

}  // namespace locus_test::dist
