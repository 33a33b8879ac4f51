// SPDX-License-Identifier: BSL-1.0
#pragma once
// Ellipsoids in 3D in axis form and implicit matrix form; row prim3.solids; book section 9.4.1
// (the quadric with three positive eigenvalues, figure 9.18).
//
// Axis form Ellipsoid3<T> {center, axis[3], extent}: the surface
//   { C + sum_i u_i extent[i] axis[i] : |u| = 1 },
// axis[] orthonormal (precondition, handedness free), extent[i] > 0 the semi-axis lengths.
// Implicit form: (X - C)^T M (X - C) = 1 with M = sum_i axis_i axis_i^T / extent_i^2, symmetric
// positive definite. signed_value(e, X) = sum_i (dot(axis_i, X - C) / extent_i)^2 - 1, negative
// inside. point_at(e, (theta, phi)) maps the unit sphere point of sphere.hpp's parametrisation
// (theta azimuth from axis 0 towards axis 1, phi polar angle from axis 2) through the axes.
//
// ellipsoid_from_implicit(C, M) converts back by the eigen-decomposition of M (extent_i =
// 1/sqrt(lambda_i), axis_i the eigenvectors, sorted by increasing eigenvalue, i.e. decreasing
// extent, forming a right-handed frame) with numeric/eigen_sym.hpp's eigen_symmetric (closed
// form, robust for repeated eigenvalues; eigenvalues accurate to O(eps * max|lambda|); float
// input is computed in double).
//
// Degenerate input: a zero extent makes M infinite, so implicit_matrix() is only meaningful for
// positive extents; ellipsoid_from_implicit() returns std::nullopt unless M is finite and all
// three computed eigenvalues are > 0 (and the extents finite). The surface area has no closed
// form (elliptic integrals) and is not provided. volume() = 4/3 pi e0 e1 e2 (NaN if an extent is
// negative). Cost O(1); the eigen-solver is a few hundred flops; no allocation.

#include <locus/config.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/numeric/eigen_sym.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <cmath>
#include <limits>
#include <optional>

namespace locus {

/// The ellipsoid { C + sum_i u_i extent[i] axis[i] : |u| = 1 } with orthonormal axes.
template <Real T>
struct Ellipsoid3 {
  Vec3<T> center;
  Vec3<T> axis[3];
  Vec3<T> extent;
};

using Ellipsoid3f = Ellipsoid3<float>;
using Ellipsoid3d = Ellipsoid3<double>;

/// M = sum_i axis_i axis_i^T / extent_i^2, so the surface is (X - C)^T M (X - C) = 1.
template <Real T>
[[nodiscard]] constexpr Mat3<T> implicit_matrix(const Ellipsoid3<T>& e) noexcept {
  Mat3<T> m{};
  for (int i = 0; i < 3; ++i)
    m = m + outer(e.axis[i], e.axis[i]) * (T(1) / (e.extent[i] * e.extent[i]));
  return m;
}

/// sum_i (dot(axis_i, X - C) / extent_i)^2 - 1: negative inside, zero on the surface.
template <Real T>
[[nodiscard]] constexpr T signed_value(const Ellipsoid3<T>& e, const Vec3<T>& x) noexcept {
  const Vec3<T> d = x - e.center;
  T s = T(0);
  for (int i = 0; i < 3; ++i) s += sqr(dot(e.axis[i], d) / e.extent[i]);
  return s - T(1);
}

/// C + sum_i u_i extent[i] axis[i], u = (cos theta sin phi, sin theta sin phi, cos phi).
template <Real T>
[[nodiscard]] inline Vec3<T> point_at(const Ellipsoid3<T>& e, const Vec2<T>& tp) noexcept {
  const T st = std::sin(tp.x), ct = std::cos(tp.x), sp = std::sin(tp.y), cp = std::cos(tp.y);
  return e.center + (e.extent.x * ct * sp) * e.axis[0] + (e.extent.y * st * sp) * e.axis[1] +
         (e.extent.z * cp) * e.axis[2];
}

/// 4/3 pi e0 e1 e2; NaN if an extent is negative.
template <Real T>
[[nodiscard]] constexpr T volume(const Ellipsoid3<T>& e) noexcept {
  if (e.extent.x < T(0) || e.extent.y < T(0) || e.extent.z < T(0))
    return std::numeric_limits<T>::quiet_NaN();
  return T(4) / T(3) * pi_v<T> * e.extent.x * e.extent.y * e.extent.z;
}

/// The tight axis-aligned box: half width along e_k is sqrt(sum_i (extent_i axis_i[k])^2).
template <Real T>
[[nodiscard]] inline AlignedBox3<T> bounding_box(const Ellipsoid3<T>& e) noexcept {
  Vec3<T> h{};
  for (int k = 0; k < 3; ++k) {
    T s = T(0);
    for (int i = 0; i < 3; ++i) s += sqr(e.extent[i] * e.axis[i][k]);
    h[k] = std::sqrt(s);
  }
  return {e.center - h, e.center + h};
}

/// Axis form of (X - C)^T M (X - C) = 1 (M symmetric, upper triangle read); std::nullopt
/// unless M is finite and positive definite (all computed eigenvalues > 0).
template <Real T>
[[nodiscard]] inline std::optional<Ellipsoid3<T>> ellipsoid_from_implicit(
    const Vec3<T>& center, const Mat3<T>& m) noexcept {
  using C = compute_t<T>;
  Mat3<C> mc{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) mc.a[i][j] = static_cast<C>(m.a[i][j]);
  const auto eig = eigen_symmetric(mc);  // reads the upper triangle
  if (!is_finite(center) || eig.status == Status::non_finite_input) return std::nullopt;
  Ellipsoid3<T> e{center, {}, {}};
  for (int i = 0; i < 3; ++i) {
    if (!(eig.values[i] > C(0))) return std::nullopt;
    e.extent[i] = static_cast<T>(C(1) / std::sqrt(eig.values[i]));
    if (!is_finite(e.extent[i]) || e.extent[i] == T(0)) return std::nullopt;
    e.axis[i] = vec_cast<T>(col(eig.vectors, i));
  }
  return e;
}

/// Centroid of the solid ellipsoid (its center).
template <Real T>
[[nodiscard]] constexpr Vec3<T> centroid(const Ellipsoid3<T>& e) noexcept {
  return e.center;
}

}  // namespace locus
