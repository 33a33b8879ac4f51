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
// extent, forming a right-handed frame). It uses detail::symmetric_eigen3, a cyclic Jacobi
// solver: the matrix is scaled by its largest entry (exact power of two, so no overflow), each
// sweep annihilates the three off-diagonal entries in turn with the stable small-angle rotation
// formula, an entry negligible against both diagonal entries is set to zero, and the budget is
// 64 sweeps (quadratic convergence needs about 5-8 for 3x3 matrices; converged = false reports
// an exhausted budget). Eigenvectors are orthonormal to rounding, eigenvalues are accurate to
// O(eps * max|lambda|). Float input is promoted to double inside the solver.
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
#include <locus/primitives/aligned_box.hpp>

#include <cmath>
#include <limits>
#include <optional>

namespace locus {

namespace detail {

/// Eigen-decomposition m = V diag(values) V^T of a symmetric 3x3 matrix.
template <class C>
struct SymmetricEigen3 {
  Vec3<C> values;   ///< ascending
  Mat3<C> vectors;  ///< column i is the unit eigenvector of values[i]; det = +1
  bool converged;   ///< false when the input is not finite or the sweep budget ran out
};

/// Cyclic Jacobi eigen-solver for a symmetric 3x3 matrix (upper triangle read).
template <class C>
[[nodiscard]] inline SymmetricEigen3<C> symmetric_eigen3(const Mat3<C>& m) noexcept {
  SymmetricEigen3<C> r{Vec3<C>{}, Mat3<C>::identity(), true};
  C a[3][3];
  C scale = C(0);
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      a[i][j] = a[j][i] = m.a[i][j];
      if (!is_finite(m.a[i][j])) {
        const C nan = std::numeric_limits<C>::quiet_NaN();
        r.values = {nan, nan, nan};
        r.converged = false;
        return r;
      }
      scale = std::fmax(scale, std::fabs(m.a[i][j]));
    }
  if (scale == C(0)) return r;
  // A power-of-two scale is exact: eigenvectors are untouched and eigenvalues scale back exactly.
  int e = 0;
  (void)std::frexp(scale, &e);
  for (auto& rw : a)
    for (auto& x : rw) x = std::ldexp(x, -e);
  C v[3][3] = {{C(1), C(0), C(0)}, {C(0), C(1), C(0)}, {C(0), C(0), C(1)}};
  constexpr int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  bool done = false;
  for (int sweep = 0; sweep < 64 && !done; ++sweep) {
    done = true;
    for (const auto& pq : pairs) {
      const int p = pq[0], q = pq[1];
      const C apq = a[p][q];
      if (apq == C(0)) continue;
      const C app = a[p][p], aqq = a[q][q];
      // Negligible against both diagonal entries: rotating would not change them any more.
      const C small = C(128) * std::fabs(apq);
      if (std::fabs(app) + small == std::fabs(app) && std::fabs(aqq) + small == std::fabs(aqq)) {
        a[p][q] = a[q][p] = C(0);
        continue;
      }
      done = false;
      const C theta = (aqq - app) / (C(2) * apq);
      // t = tan of the rotation angle, the smaller root of t^2 + 2 theta t - 1 = 0.
      C t;
      if (std::fabs(theta) > C(1e150)) {
        t = C(0.5) / theta;
      } else {
        t = C(1) / (std::fabs(theta) + std::sqrt(theta * theta + C(1)));
        if (theta < C(0)) t = -t;
      }
      const C c = C(1) / std::sqrt(t * t + C(1)), s = t * c;
      a[p][p] = app - t * apq;
      a[q][q] = aqq + t * apq;
      a[p][q] = a[q][p] = C(0);
      const int k = 3 - p - q;
      const C akp = a[k][p], akq = a[k][q];
      a[k][p] = a[p][k] = c * akp - s * akq;
      a[k][q] = a[q][k] = s * akp + c * akq;
      for (auto& vr : v) {
        const C vp = vr[p], vq = vr[q];
        vr[p] = c * vp - s * vq;
        vr[q] = s * vp + c * vq;
      }
    }
  }
  r.converged = done;
  int idx[3] = {0, 1, 2};
  // Sort ascending (three elements: a tiny insertion sort).
  for (int i = 1; i < 3; ++i)
    for (int j = i; j > 0 && a[idx[j]][idx[j]] < a[idx[j - 1]][idx[j - 1]]; --j) {
      const int tmp = idx[j];
      idx[j] = idx[j - 1];
      idx[j - 1] = tmp;
    }
  for (int i = 0; i < 3; ++i) {
    r.values[i] = std::ldexp(a[idx[i]][idx[i]], e);
    for (int k = 0; k < 3; ++k) r.vectors.a[k][i] = v[k][idx[i]];
  }
  if (determinant(r.vectors) < C(0))
    for (int k = 0; k < 3; ++k) r.vectors.a[k][2] = -r.vectors.a[k][2];
  return r;
}

}  // namespace detail

/// The ellipsoid { C + sum_i u_i extent[i] axis[i] : |u| = 1 } with orthonormal axes.
template <class T>
struct Ellipsoid3 {
  Vec3<T> center;
  Vec3<T> axis[3];
  Vec3<T> extent;
};

using Ellipsoid3f = Ellipsoid3<float>;
using Ellipsoid3d = Ellipsoid3<double>;

/// M = sum_i axis_i axis_i^T / extent_i^2, so the surface is (X - C)^T M (X - C) = 1.
template <class T>
[[nodiscard]] constexpr Mat3<T> implicit_matrix(const Ellipsoid3<T>& e) noexcept {
  Mat3<T> m{};
  for (int i = 0; i < 3; ++i)
    m = m + outer(e.axis[i], e.axis[i]) * (T(1) / (e.extent[i] * e.extent[i]));
  return m;
}

/// sum_i (dot(axis_i, X - C) / extent_i)^2 - 1: negative inside, zero on the surface.
template <class T>
[[nodiscard]] constexpr T signed_value(const Ellipsoid3<T>& e, const Vec3<T>& x) noexcept {
  const Vec3<T> d = x - e.center;
  T s = T(0);
  for (int i = 0; i < 3; ++i) s += sqr(dot(e.axis[i], d) / e.extent[i]);
  return s - T(1);
}

/// C + sum_i u_i extent[i] axis[i], u = (cos theta sin phi, sin theta sin phi, cos phi).
template <class T>
[[nodiscard]] inline Vec3<T> point_at(const Ellipsoid3<T>& e, const Vec2<T>& tp) noexcept {
  const T st = std::sin(tp.x), ct = std::cos(tp.x), sp = std::sin(tp.y), cp = std::cos(tp.y);
  return e.center + (e.extent.x * ct * sp) * e.axis[0] + (e.extent.y * st * sp) * e.axis[1] +
         (e.extent.z * cp) * e.axis[2];
}

/// 4/3 pi e0 e1 e2; NaN if an extent is negative.
template <class T>
[[nodiscard]] constexpr T volume(const Ellipsoid3<T>& e) noexcept {
  if (e.extent.x < T(0) || e.extent.y < T(0) || e.extent.z < T(0))
    return std::numeric_limits<T>::quiet_NaN();
  return T(4) / T(3) * pi_v<T> * e.extent.x * e.extent.y * e.extent.z;
}

/// The tight axis-aligned box: half width along e_k is sqrt(sum_i (extent_i axis_i[k])^2).
template <class T>
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
template <class T>
[[nodiscard]] inline std::optional<Ellipsoid3<T>> ellipsoid_from_implicit(
    const Vec3<T>& center, const Mat3<T>& m) noexcept {
  using C = compute_t<T>;
  Mat3<C> mc{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) mc.a[i][j] = static_cast<C>(m.a[i][j]);
  const auto eig = detail::symmetric_eigen3(mc);
  if (!is_finite(center) || !eig.converged) return std::nullopt;
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
template <class T>
[[nodiscard]] constexpr Vec3<T> centroid(const Ellipsoid3<T>& e) noexcept {
  return e.center;
}

}  // namespace locus
