// SPDX-License-Identifier: BSL-1.0
#pragma once
// 3D rotation representations and conversions between them (row core.rotation; book appendix A,
// figure A.1 for the rotation/scale split of a general linear map). The gimbal-lock accuracy
// argument: docs/notes/core.md.
//
//   * rotation matrix  Mat3<T> R, column vectors: y = R * x, R^T R = I, det R = +1;
//   * axis-angle       AxisAngle<T>{axis, angle}: right-handed rotation by `angle` radians about
//                      the unit vector `axis` (counter-clockwise when the axis points at the eye);
//   * quaternion       Quat<T>{w, x, y, z} of core/quat.hpp, q = (cos(t/2), sin(t/2) axis);
//   * Euler angles     EulerAngles<T>{order, angles, unique}, the six Tait-Bryan orders.
// Euler convention: order "ABC" with angles (a0, a1, a2) is R = R_A(a0) * R_B(a1) * R_C(a2)
// (e.g. EulerOrder::xyz: Rx(a0) Ry(a1) Rz(a2), Rx(t) = [[1,0,0],[0,c,-s],[0,s,c]]): EXTRINSIC C,
// B, A about the world axes, or INTRINSIC A, B', C'' about the body axes. Output ranges: a0, a2
// in [-pi, pi], a1 in [-pi/2, pi/2].
// Gimbal lock: to_euler reports unique = false when cos(a1) <= lock_tolerance (default 16 eps)
// and returns a2 = 0, a1 = +-pi/2, a0 carrying the whole sum (reproducing the matrix to about
// pi * lock_tolerance); elsewhere the round trip matrix -> angles -> matrix stays at rounding
// level even when cos(a1) is tiny.
//
// Degenerate input: a zero or non-finite axis, a non-finite angle, a zero or non-finite
// quaternion and a non-finite matrix all convert to the identity rotation (to_axis_angle gives
// {(1, 0, 0), 0}). A matrix that is not a rotation goes through Shepperd's quaternion, which
// normalises, in to_quat and to_axis_angle; to_euler reads its entries as if it were a rotation.
// Use nearest_rotation() or orthonormalize_rotation() to repair drifted matrices explicitly.
// Conversions are O(1); nearest_rotation iterates (quadratic convergence, typically 3-6 iterations
// of a 3x3 inverse) and computes in double for float input.

#include <locus/config.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/quat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <cstdint>

namespace locus {

/// Right-handed rotation by `angle` radians about the unit vector `axis`.
template <Real T>
struct AxisAngle {
  Vec3<T> axis;
  T angle;
};

/// The six Tait-Bryan orders; order ABC means R = R_A(a0) R_B(a1) R_C(a2) (see the top comment).
enum class EulerOrder : std::uint8_t { xyz, xzy, yxz, yzx, zxy, zyx };

/// Euler (Tait-Bryan) angles in radians. `unique` is false when the middle angle is at +-90
/// degrees (gimbal lock); the angles are then the canonical solution with angles[2] == 0.
template <Real T>
struct EulerAngles {
  EulerOrder order;
  Vec3<T> angles;
  bool unique = true;
};

/// The default gimbal-lock tolerance on cos(middle angle): 16 eps (a few roundings of entries
/// of magnitude 1).
template <Real T>
inline constexpr T default_lock_tolerance = T(16) * eps_v<T>;

namespace detail {

/// Axis indices (i, j, k) of an order and whether it is an even (cyclic) permutation.
struct EulerAxes {
  int i, j, k;
  bool cyclic;
};
[[nodiscard]] constexpr EulerAxes euler_axes(EulerOrder o) noexcept {
  switch (o) {
    case EulerOrder::xyz:
      return {0, 1, 2, true};
    case EulerOrder::yzx:
      return {1, 2, 0, true};
    case EulerOrder::zxy:
      return {2, 0, 1, true};
    case EulerOrder::xzy:
      return {0, 2, 1, false};
    case EulerOrder::yxz:
      return {1, 0, 2, false};
    case EulerOrder::zyx:
      return {2, 1, 0, false};
  }
  return {0, 1, 2, true};
}

/// Rotation matrix about coordinate axis `axis` (0, 1, 2) by angle t.
template <Real T>
[[nodiscard]] inline Mat3<T> axis_rotation(int axis, T t) noexcept {
  const T c = std::cos(t), s = std::sin(t);
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // (a, b) is a cyclic pair after `axis`
  Mat3<T> m = Mat3<T>::identity();
  m.a[a][a] = c;
  m.a[a][b] = -s;
  m.a[b][a] = s;
  m.a[b][b] = c;
  return m;
}

template <Real T>
[[nodiscard]] inline Quat<T> axis_quat(int axis, T t) noexcept {
  Quat<T> q{std::cos(t / T(2)), T(0), T(0), T(0)};
  const T s = std::sin(t / T(2));
  if (axis == 0) q.x = s;
  if (axis == 1) q.y = s;
  if (axis == 2) q.z = s;
  return q;
}

}  // namespace detail

// ---- to quaternion ------------------------------------------------------------------------

/// Unit quaternion of an axis-angle rotation; the axis need not be unit. Zero or non-finite
/// axis, or non-finite angle: the identity.
template <Real T>
[[nodiscard]] inline Quat<T> to_quat(const AxisAngle<T>& aa) noexcept {
  const Vec3<T> u = normalize(aa.axis);
  if (u == Vec3<T>{} || !is_finite(aa.angle)) return Quat<T>::identity();
  const T h = aa.angle / T(2);
  return Quat<T>::from_parts(std::cos(h), std::sin(h) * u);
}

/// Unit quaternion of a rotation matrix by Shepperd's method: the largest of the trace and the
/// three diagonal entries selects which component is taken from a square root, so the divisor
/// is never below 1/2 and the result is accurate for every rotation (including angle pi).
/// The output has w >= 0. Non-rotation input is normalised through the quaternion; a zero or
/// non-finite matrix gives the identity.
template <Real T>
[[nodiscard]] inline Quat<T> to_quat(const Mat3<T>& r) noexcept {
  if (!is_finite(r)) return Quat<T>::identity();
  const auto& m = r.a;
  const T tr = m[0][0] + m[1][1] + m[2][2];
  Quat<T> q{};
  if (tr >= m[0][0] && tr >= m[1][1] && tr >= m[2][2]) {
    const T w4 = T(2) * std::sqrt(T(1) + tr);  // 4w
    q = {w4 / T(4), (m[2][1] - m[1][2]) / w4, (m[0][2] - m[2][0]) / w4, (m[1][0] - m[0][1]) / w4};
  } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
    const T x4 = T(2) * std::sqrt(T(1) + m[0][0] - m[1][1] - m[2][2]);
    q = {(m[2][1] - m[1][2]) / x4, x4 / T(4), (m[0][1] + m[1][0]) / x4, (m[0][2] + m[2][0]) / x4};
  } else if (m[1][1] >= m[2][2]) {
    const T y4 = T(2) * std::sqrt(T(1) - m[0][0] + m[1][1] - m[2][2]);
    q = {(m[0][2] - m[2][0]) / y4, (m[0][1] + m[1][0]) / y4, y4 / T(4), (m[1][2] + m[2][1]) / y4};
  } else {
    const T z4 = T(2) * std::sqrt(T(1) - m[0][0] - m[1][1] + m[2][2]);
    q = {(m[1][0] - m[0][1]) / z4, (m[0][2] + m[2][0]) / z4, (m[1][2] + m[2][1]) / z4, z4 / T(4)};
  }
  // 4w^2 - 4x^2 = 2 (tr - m00) etc., so the branch picks the largest of |w|, |x|, |y|, |z|, which
  // is >= 1/2 for a unit quaternion. For any finite matrix the chosen radicand is >= 1 (the
  // comparisons force it), so the divisor is >= 2 even for garbage input; normalize() then
  // makes the result unit.
  q = normalize(q);
  return q.w < T(0) ? -q : q;
}

/// Unit quaternion of Euler angles: the product q_A(a0) q_B(a1) q_C(a2).
template <Real T>
[[nodiscard]] inline Quat<T> to_quat(const EulerAngles<T>& e) noexcept {
  if (!is_finite(e.angles)) return Quat<T>::identity();
  const detail::EulerAxes ax = detail::euler_axes(e.order);
  return detail::axis_quat(ax.i, e.angles[0]) * detail::axis_quat(ax.j, e.angles[1]) *
         detail::axis_quat(ax.k, e.angles[2]);
}

// ---- to matrix ----------------------------------------------------------------------------

/// Rotation matrix of a quaternion. Any nonzero q is accepted: the formula divides by |q|^2,
/// so q and s q give the same rotation. Zero or non-finite q: the identity.
template <Real T>
[[nodiscard]] inline Mat3<T> to_matrix(const Quat<T>& q0) noexcept {
  const Quat<T> q = normalize(q0);
  const T xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  const T xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  const T wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  return {{{T(1) - T(2) * (yy + zz), T(2) * (xy - wz), T(2) * (xz + wy)},
           {T(2) * (xy + wz), T(1) - T(2) * (xx + zz), T(2) * (yz - wx)},
           {T(2) * (xz - wy), T(2) * (yz + wx), T(1) - T(2) * (xx + yy)}}};
}

/// Rotation matrix of an axis-angle pair by Rodrigues' formula
/// R = I + sin(t) K + 2 sin^2(t/2) K^2 with K = skew(unit axis); the half-angle form keeps
/// 1 - cos(t) accurate for tiny t. Zero or non-finite axis, or non-finite angle: the identity.
template <Real T>
[[nodiscard]] inline Mat3<T> to_matrix(const AxisAngle<T>& aa) noexcept {
  const Vec3<T> u = normalize(aa.axis);
  if (u == Vec3<T>{} || !is_finite(aa.angle)) return Mat3<T>::identity();
  const Mat3<T> k = skew(u);
  const T sh = std::sin(aa.angle / T(2));
  return Mat3<T>::identity() + k * std::sin(aa.angle) + (k * k) * (T(2) * sh * sh);
}

/// Rotation matrix of Euler angles: R_A(a0) R_B(a1) R_C(a2). Non-finite angles: the identity.
template <Real T>
[[nodiscard]] inline Mat3<T> to_matrix(const EulerAngles<T>& e) noexcept {
  if (!is_finite(e.angles)) return Mat3<T>::identity();
  const detail::EulerAxes ax = detail::euler_axes(e.order);
  return detail::axis_rotation(ax.i, e.angles[0]) * detail::axis_rotation(ax.j, e.angles[1]) *
         detail::axis_rotation(ax.k, e.angles[2]);
}

// ---- to axis-angle ------------------------------------------------------------------------

/// Axis-angle of a quaternion, angle in [0, pi], unit axis. The angle is 2 atan2(|v|, |w|),
/// accurate near 0 and near pi. The identity (and zero or non-finite q) gives {(1, 0, 0), 0}.
template <Real T>
[[nodiscard]] inline AxisAngle<T> to_axis_angle(const Quat<T>& q0) noexcept {
  Quat<T> q = normalize(q0);
  if (q.w < T(0)) q = -q;
  const Normalized<T, 3> v = normalize_with_length(vector_part(q));
  if (!(v.length > T(0))) return {Vec3<T>{T(1), T(0), T(0)}, T(0)};
  return {v.dir, T(2) * std::atan2(v.length, q.w)};
}

/// Axis-angle of a rotation matrix (through Shepperd's quaternion, robust near 0 and pi).
template <Real T>
[[nodiscard]] inline AxisAngle<T> to_axis_angle(const Mat3<T>& r) noexcept {
  return to_axis_angle(to_quat(r));
}

// ---- to Euler angles ----------------------------------------------------------------------

/// Euler angles of a rotation matrix in the given order. See the top comment for the
/// convention, ranges and gimbal-lock handling (unique == false when cos(a1) <= lock_tolerance).
/// A non-finite matrix gives zero angles with unique == false.
template <Real T>
[[nodiscard]] inline EulerAngles<T> to_euler(
    const Mat3<T>& r, EulerOrder order, T lock_tolerance = default_lock_tolerance<T>) noexcept {
  if (!is_finite(r)) return {order, Vec3<T>{}, false};
  const detail::EulerAxes ax = detail::euler_axes(order);
  const int i = ax.i, j = ax.j, k = ax.k;
  const T s = ax.cyclic ? T(1) : T(-1);
  const auto& m = r.a;
  // Row i of R is (cos a1 cos a2, -s cos a1 sin a2, s sin a1) in columns (i, j, k).
  const T cb = std::hypot(m[i][i], m[i][j]);
  const T a1 = std::atan2(s * m[i][k], cb);
  const bool unique = cb > lock_tolerance;
  const T a2 = unique ? std::atan2(-s * m[i][j], m[i][i]) : T(0);
  // a0 from the residual R_A(a0) = R R_C(-a2) R_B(-a1): its (j, k) block is a plane rotation
  // whatever the conditioning of a2, so the reconstruction error stays at rounding level.
  const Mat3<T> res = r * detail::axis_rotation(k, -a2) * detail::axis_rotation(j, -a1);
  const T sin0 = s * (res.a[k][j] - res.a[j][k]) / T(2);
  const T cos0 = (res.a[j][j] + res.a[k][k]) / T(2);
  const T a0 = std::atan2(sin0, cos0);
  return {order, Vec3<T>{a0, a1, a2}, unique};
}

/// Euler angles of a quaternion (through its rotation matrix).
template <Real T>
[[nodiscard]] inline EulerAngles<T> to_euler(
    const Quat<T>& q, EulerOrder order, T lock_tolerance = default_lock_tolerance<T>) noexcept {
  return to_euler(to_matrix(q), order, lock_tolerance);
}

// ---- comparison and interpolation ---------------------------------------------------------

/// The angle in [0, pi] of the rotation taking a to b (a, b unit): 2 atan2(|a - b|, |a + b|)
/// on the shorter arc, accurate for tiny and near-pi angles.
template <Real T>
[[nodiscard]] inline T angle_between(const Quat<T>& a, const Quat<T>& b) noexcept {
  const Quat<T> bb = dot(a, b) < T(0) ? -b : b;
  return T(4) * std::atan2(norm(a - bb), norm(a + bb));
}

/// Interpolates between two rotation matrices by quaternion slerp along the shorter arc:
/// constant angular velocity about a fixed axis; t = 0 gives a, t = 1 gives b (to rounding).
template <Real T>
[[nodiscard]] inline Mat3<T> slerp(const Mat3<T>& a, const Mat3<T>& b, T t) noexcept {
  return to_matrix(slerp(to_quat(a), to_quat(b), t));
}

// ---- repairing drifted matrices -----------------------------------------------------------

/// Result of nearest_rotation / orthonormalize_rotation.
template <Real T>
struct RotationFix {
  Status status =
      Status::empty_input;  ///< ok, degenerate_input (det <= 0 or rank < 3), non_finite_input
  Mat3<T> rotation;         ///< the rotation (identity unless status is ok)
  int iterations;           ///< Newton steps taken (0 for Gram-Schmidt)
};

/// The rotation nearest to m in the Frobenius norm: the orthogonal polar factor of m = R S
/// (S symmetric positive definite; figure A.1 splits a map into scale then rotation this way).
/// Computed by the scaled Newton iteration X <- (g X + X^-T / g) / 2, g = |det X|^(-1/3)
/// (Higham), in double for float input, until the update is at rounding level. Needs
/// det(m) > 0 (else the polar factor is a reflection): otherwise degenerate_input and the
/// identity. At most 50 iterations (limit_exceeded, best so far, never seen for det > 0).
template <Real T>
[[nodiscard]] inline RotationFix<T> nearest_rotation(const Mat3<T>& m) noexcept {
  using C = compute_t<T>;
  if (!is_finite(m)) return {Status::non_finite_input, Mat3<T>::identity(), 0};
  Mat3<C> x{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) x.a[r][c] = static_cast<C>(m.a[r][c]);
  // Scale to unit max entry first so the determinant cannot overflow or underflow.
  C mx = C(0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) mx = std::fmax(mx, std::fabs(x.a[r][c]));
  if (!(mx > C(0))) return {Status::degenerate_input, Mat3<T>::identity(), 0};
  x = x * (C(1) / mx);
  if (!(determinant(x) > C(0))) return {Status::degenerate_input, Mat3<T>::identity(), 0};
  for (int it = 1; it <= 50; ++it) {
    const C det = determinant(x);
    const auto inv = inverse(x);
    if (!inv || !(det > C(0))) return {Status::degenerate_input, Mat3<T>::identity(), it};
    const C g = std::cbrt(C(1) / det);
    const Mat3<C> next = (x * g + transpose(*inv) * (C(1) / g)) * C(0.5);
    C diff = C(0);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) diff = std::fmax(diff, std::fabs(next.a[r][c] - x.a[r][c]));
    x = next;
    // Quadratic convergence: once the step is below sqrt(eps) the next one is below eps; one
    // more step lands at rounding level. Stop after the step falls under 8 eps.
    if (diff <= C(8) * eps_v<C>) {
      Mat3<T> out{};
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out.a[r][c] = static_cast<T>(x.a[r][c]);
      return {Status::ok, out, it};
    }
  }
  Mat3<T> out{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.a[r][c] = static_cast<T>(x.a[r][c]);
  return {Status::limit_exceeded, out, 50};
}

/// Cheap repair of a slightly drifted rotation by Gram-Schmidt on the columns: column 0 is
/// normalised, column 1 made orthogonal to it and normalised, column 2 = col0 x col1 (so the
/// result is right-handed). Biased towards column 0, unlike nearest_rotation. det(m) <= 0 (a
/// reflection or a singular matrix) or columns 0 and 1 dependent: degenerate_input and the
/// identity.
template <Real T>
[[nodiscard]] inline RotationFix<T> orthonormalize_rotation(const Mat3<T>& m) noexcept {
  if (!is_finite(m)) return {Status::non_finite_input, Mat3<T>::identity(), 0};
  // Orientation test on unit columns, so that tiny or huge scales cannot underflow/overflow it.
  if (!(dot(cross(normalize(col(m, 0)), normalize(col(m, 1))), normalize(col(m, 2))) > T(0)))
    return {Status::degenerate_input, Mat3<T>::identity(), 0};
  const Normalized<T, 3> c0 = normalize_with_length(col(m, 0));
  const Vec3<T> c1raw = col(m, 1);
  const Normalized<T, 3> c1 = normalize_with_length(c1raw - dot(c0.dir, c1raw) * c0.dir);
  // Column 1's remaining part must be more than rounding noise of its own length.
  if (!(c0.length > T(0)) || !(c1.length > T(8) * eps_v<T> * length(c1raw)))
    return {Status::degenerate_input, Mat3<T>::identity(), 0};
  return {Status::ok, Mat3<T>::from_cols(c0.dir, c1.dir, cross(c0.dir, c1.dir)), 0};
}

}  // namespace locus
