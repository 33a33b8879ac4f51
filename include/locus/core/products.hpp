// SPDX-License-Identifier: BSL-1.0
#pragma once
// Products of vectors beyond dot/cross/perp (row core.products; book sections 3.3, 4.x,
// figures 3.15, 3.27-3.34, 4.3-4.5). dot, cross, perp and perp_dot live in core/vec.hpp.
//
// Computes: the scalar triple product a . (b x c) = det[a b c] (signed volume of the
// parallelepiped, figures 3.33-3.34), the vector triple product a x (b x c), the unsigned angle
// between two vectors, the signed angle in 2D (counter-clockwise positive, the sign of
// perp_dot, figure 4.4) and in 3D about a reference axis, and the projection of a vector onto a
// direction with its rejection (perpendicular part, figure 3.29).
//
// Conventions: right-handed; triple_product(a, b, c) > 0 when (a, b, c) is a right-handed
// triple. The unsigned angle is in [0, pi]; the signed 2D angle in (-pi, pi] (pi for opposite
// vectors).
//
// Robustness: angles are never acos(dot): both vectors are normalised first (which also rescues
// tiny and huge vectors from underflow/overflow), then the 3D angle is atan2(|a x b|, a . b), the
// 2D one atan2(|perp_dot|, dot), and in other dimensions Kahan's 2 atan2(|a - b|, |a + b|) of the
// unit vectors; all are accurate near 0 and near pi. Projection divides by a rescaled |d|^2, so
// it neither overflows nor underflows for extreme but finite d.
//
// Degenerate input: an angle involving a zero vector is 0; projection onto the zero vector is
// the zero vector (and the rejection is v itself); scalar_projection onto zero is 0. Angles,
// projections and scalar projections involving a NaN or infinite direction are NaN; the triple
// products follow IEEE arithmetic.
//
// Cost: O(N) flops; angles add two square roots and one atan2.

#include <locus/core/angle.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <cmath>
#include <limits>

namespace locus {

/// Scalar triple product a . (b x c) = det[a b c]: the signed volume of the parallelepiped
/// spanned by a, b, c; positive for a right-handed triple. Invariant under cyclic permutation.
template <Real T>
[[nodiscard]] constexpr T triple_product(const Vec3<T>& a, const Vec3<T>& b,
                                         const Vec3<T>& c) noexcept {
  return dot(a, cross(b, c));
}

/// Vector triple product a x (b x c) = b (a . c) - c (a . b): lies in the span of b and c.
template <Real T>
[[nodiscard]] constexpr Vec3<T> vector_triple_product(const Vec3<T>& a, const Vec3<T>& b,
                                                      const Vec3<T>& c) noexcept {
  return cross(a, cross(b, c));
}

/// Unsigned angle between a and b in [0, pi]; 0 when either is the zero vector; NaN when
/// either is not finite.
template <Real T, int N>
[[nodiscard]] inline T angle_between(const Vec<T, N>& a, const Vec<T, N>& b) noexcept {
  if (!is_finite(a) || !is_finite(b)) return std::numeric_limits<T>::quiet_NaN();
  const Normalized<T, N> na = normalize_with_length(a), nb = normalize_with_length(b);
  if (na.length == T(0) || nb.length == T(0)) return T(0);
  const Vec<T, N>&ua = na.dir, &ub = nb.dir;
  if constexpr (N == 3) {
    return std::atan2(length(cross(ua, ub)), dot(ua, ub));
  } else if constexpr (N == 2) {
    return std::atan2(std::abs(perp_dot(ua, ub)), dot(ua, ub));
  } else {
    return T(2) * std::atan2(length(ua - ub), length(ua + ub));
  }
}

/// Signed angle from a to b in (-pi, pi]: positive when b is counter-clockwise from a
/// (perp_dot(a, b) > 0), pi for opposite vectors, 0 when either is zero, NaN when not finite.
template <Real T>
[[nodiscard]] inline T signed_angle(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  if (!is_finite(a) || !is_finite(b)) return std::numeric_limits<T>::quiet_NaN();
  const Normalized<T, 2> na = normalize_with_length(a), nb = normalize_with_length(b);
  if (na.length == T(0) || nb.length == T(0)) return T(0);
  return atan2_signed(perp_dot(na.dir, nb.dir), dot(na.dir, nb.dir));
}

/// Signed angle from a to b about `axis`: angle_between(a, b) with the sign of
/// axis . (a x b) (counter-clockwise seen from the tip of axis is positive). When the sign is
/// zero (parallel vectors, or axis perpendicular to a x b, or a zero axis) the angle is >= 0.
template <Real T>
[[nodiscard]] inline T signed_angle(const Vec3<T>& a, const Vec3<T>& b,
                                    const Vec3<T>& axis) noexcept {
  const T angle = angle_between(a, b);
  // Normalise first so the sign test cannot underflow to zero for tiny inputs.
  const T s = dot(normalize_with_length(axis).dir,
                  cross(normalize_with_length(a).dir, normalize_with_length(b).dir));
  return s < T(0) ? -angle : angle;
}

/// Projection of v onto the direction d: (v . d / d . d) d, the component of v parallel to d.
/// The zero vector when d is zero; NaN components when d is not finite.
template <Real T, int N>
[[nodiscard]] inline Vec<T, N> project_onto(const Vec<T, N>& v, const Vec<T, N>& d) noexcept {
  if (!is_finite(d)) return splat<T, N>(std::numeric_limits<T>::quiet_NaN());
  const T m = max_abs(d);
  if (m == T(0)) return Vec<T, N>{};
  const Vec<T, N> s = d / m;  // |s| in [1, sqrt(N)]: no overflow or underflow in s . s
  return s * (dot(v, s) / dot(s, s));
}

/// Rejection of v from d: v - project_onto(v, d), the component of v perpendicular to d.
/// v itself when d is zero.
template <Real T, int N>
[[nodiscard]] inline Vec<T, N> reject_from(const Vec<T, N>& v, const Vec<T, N>& d) noexcept {
  return v - project_onto(v, d);
}

/// Signed length of the projection of v onto d: v . d / |d| (|v| cos angle). 0 when d is
/// zero, NaN when d is not finite.
template <Real T, int N>
[[nodiscard]] inline T scalar_projection(const Vec<T, N>& v, const Vec<T, N>& d) noexcept {
  if (!is_finite(d)) return std::numeric_limits<T>::quiet_NaN();
  const Normalized<T, N> nd = normalize_with_length(d);
  if (nd.length == T(0)) return T(0);
  return dot(v, nd.dir);
}

}  // namespace locus
