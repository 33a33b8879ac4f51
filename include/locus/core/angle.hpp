// SPDX-License-Identifier: BSL-1.0
#pragma once
// Angle utilities and triangle solving (row core.trig; book appendix B, figures B.1-B.10).
//
// Computes: degree/radian conversion, arc length, clamped acos/asin, atan2 normalised to
// [0, 2pi) or (-pi, pi], angle wrapping, the laws of cosines and sines, and solving a triangle
// from three of its parts (SSS, SAS, ASA, AAS, SSA).
//
// Parametrisation: angles are in radians. A triangle has sides a, b, c opposite the angles
// alpha, beta, gamma (at vertices A, B, C); SAS's angle is the one between its two sides, ASA's
// side the one between its two angles, and SSA's angle is opposite the first side.
// Intervals use the rounded constant pi_v<T>: "(-pi, pi]" means [-pi_v, pi_v] with the exact
// negative axis (y = +-0, x < 0) mapped to +pi_v.
//
// Robustness: the law of cosines is evaluated in cancellation-free forms (Kahan, "Miscalculating
// Area and Angles of a Needle-like Triangle", 2014; docs/notes/core.md), so needle-shaped
// triangles keep full relative accuracy; no solved angle comes from acos of a rounded cosine.
//
// Degenerate input: acos_clamped/asin_clamped clamp the argument to [-1, 1] (a cosine computed
// as 1 + 1e-16 gives 0, not NaN); NaN stays NaN. Wrapping and atan2 helpers return NaN for NaN
// or infinite input. law_of_* helpers return NaN when the quantity is undefined (a zero sine in
// a denominator, sides that violate the triangle inequality). The solve_* functions return
// count = 0 when no triangle exists or an input is NaN, infinite, a non-positive side or an angle
// outside (0, pi); a flat triangle (a = b + c exactly) is accepted by solve_sss with angles
// (pi, 0, 0). Nothing divides by zero.
//
// Cost: a handful of flops and at most a few trig calls per function; no allocation.

#include <locus/core/scalar.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace locus {

/// 2 pi rounded to T (exactly twice pi_v<T>).
template <Real T>
inline constexpr T two_pi_v = T(2) * pi_v<T>;

/// Degrees to radians; multiples of 45 degrees map to exact multiples of pi_v/4.
template <Real T>
[[nodiscard]] constexpr T to_radians(T degrees) noexcept {
  // Dividing by 180 first keeps 180 -> pi_v, 90 -> pi_v / 2 exact.
  return (degrees / T(180)) * pi_v<T>;
}

/// Radians to degrees; pi_v maps to exactly 180.
template <Real T>
[[nodiscard]] constexpr T to_degrees(T radians) noexcept {
  return (radians / pi_v<T>)*T(180);
}

/// Arc length r * theta subtended by angle theta on a circle of radius r (figure B.2).
template <Real T>
[[nodiscard]] constexpr T arc_length(T radius, T angle) noexcept {
  return radius * angle;
}

/// acos with the argument clamped to [-1, 1]: result in [0, pi]; NaN stays NaN.
template <Real T>
[[nodiscard]] inline T acos_clamped(T x) noexcept {
  return std::acos(clamp(x, T(-1), T(1)));
}

/// asin with the argument clamped to [-1, 1]: result in [-pi/2, pi/2]; NaN stays NaN.
template <Real T>
[[nodiscard]] inline T asin_clamped(T x) noexcept {
  return std::asin(clamp(x, T(-1), T(1)));
}

namespace detail {
// r in [-2 pi_v, 0) plus 2 pi_v can round up to 2 pi_v; keep the half-open interval.
template <Real T>
[[nodiscard]] inline T add_two_pi_below(T r) noexcept {
  const T s = r + two_pi_v<T>;
  return s < two_pi_v<T> ? s : std::nextafter(two_pi_v<T>, T(0));
}
}  // namespace detail

/// Angle of (x, y) in [0, 2pi): atan2 shifted to the positive range. atan2_positive(0, 0) = 0.
template <Real T>
[[nodiscard]] inline T atan2_positive(T y, T x) noexcept {
  const T r = std::atan2(y, x);
  if (r < T(0)) return detail::add_two_pi_below(r);
  return r == T(0) ? T(0) : r;  // folds -0 to +0
}

/// Angle of (x, y) in (-pi, pi]; the negative x-axis (y = +0 or -0) gives +pi.
template <Real T>
[[nodiscard]] inline T atan2_signed(T y, T x) noexcept {
  if (y == T(0) && x < T(0)) return pi_v<T>;
  const T r = std::atan2(y, x);
  return r == T(0) ? T(0) : r;
}

/// An angle reduced to [0, 2pi) modulo the rounded 2 pi_v (the remainder is exact; a negative
/// one is shifted up by 2 pi_v with one rounding). NaN for NaN/inf.
template <Real T>
[[nodiscard]] inline T wrap_angle_positive(T angle) noexcept {
  const T r = std::fmod(angle, two_pi_v<T>);  // exact, in (-2pi, 2pi), NaN for inf
  if (r < T(0)) return detail::add_two_pi_below(r);
  return r == T(0) ? T(0) : r;
}

/// An angle reduced to (-pi, pi] (exact reduction modulo 2 pi_v). NaN for NaN/inf.
template <Real T>
[[nodiscard]] inline T wrap_angle_signed(T angle) noexcept {
  const T r = std::remainder(angle, two_pi_v<T>);  // exact, in [-pi_v, pi_v]
  if (r <= -pi_v<T>) return pi_v<T>;
  return r == T(0) ? T(0) : r;
}

/// The signed rotation in (-pi, pi] that takes direction `from` to direction `to`.
template <Real T>
[[nodiscard]] inline T angle_difference(T from, T to) noexcept {
  return wrap_angle_signed(to - from);
}

// ---- laws of cosines and sines -----------------------------------------------------------

/// Law of cosines for a side: the side opposite the angle between sides b and c,
/// sqrt(b^2 + c^2 - 2 b c cos(angle)), evaluated without cancellation for small angles.
/// NaN when a side is negative or an input is NaN.
template <Real T>
[[nodiscard]] inline T law_of_cosines_side(T b, T c, T angle) noexcept {
  if (!(b >= T(0) && c >= T(0))) return std::numeric_limits<T>::quiet_NaN();
  const T s = std::sin(angle / T(2));
  return std::sqrt(sqr(b - c) + T(4) * b * c * s * s);
}

/// Law of cosines for an angle: the angle in [0, pi] opposite side `a` of the triangle with
/// sides a, b, c (Kahan's formula, accurate for needle-like triangles). NaN unless the sides are
/// non-negative, finite and satisfy the triangle inequality; a flat triangle gives 0 or pi.
template <Real T>
[[nodiscard]] inline T law_of_cosines_angle(T a, T b, T c) noexcept {
  // Kahan names the wanted angle's side c and needs the other two ordered, x >= y.
  const T z = a;
  T x = b, y = c;
  if (x < y) {
    const T t = x;
    x = y;
    y = t;
  }
  const T nan = std::numeric_limits<T>::quiet_NaN();
  if (!(y >= T(0) && z >= T(0)) || !is_finite(x) || !is_finite(z)) return nan;
  T mu;
  if (y >= z)
    mu = z - (x - y);
  else
    mu = y - (x - z);
  const T num = ((x - y) + z) * mu;
  const T den = (x + (y + z)) * ((x - z) + y);
  if (!(num >= T(0)) || !(den >= T(0))) return nan;      // triangle inequality violated
  if (den == T(0)) return num == T(0) ? T(0) : pi_v<T>;  // z = x + y: flat, angle pi
  return T(2) * std::atan(std::sqrt(num / den));
}

/// Law of sines for a side: the side opposite `angle_b` in a triangle where side `a` is
/// opposite `angle_a`, a sin(angle_b) / sin(angle_a). NaN when sin(angle_a) = 0.
template <Real T>
[[nodiscard]] inline T law_of_sines_side(T a, T angle_a, T angle_b) noexcept {
  const T sa = std::sin(angle_a);
  if (sa == T(0)) return std::numeric_limits<T>::quiet_NaN();
  return a * std::sin(angle_b) / sa;
}

/// Law of sines for an angle: the principal value in [0, pi/2] of the angle opposite side `b`
/// when side `a` is opposite `angle_a` (asin of b sin(angle_a) / a, clamped). The obtuse
/// alternative pi - result is the caller's choice; solve_ssa enumerates both. NaN when a = 0.
template <Real T>
[[nodiscard]] inline T law_of_sines_angle(T a, T angle_a, T b) noexcept {
  if (a == T(0)) return std::numeric_limits<T>::quiet_NaN();
  return asin_clamped(b * std::sin(angle_a) / a);
}

// ---- solving triangles (appendix B) ------------------------------------------------------

/// A solved triangle: sides a, b, c opposite angles alpha, beta, gamma (radians).
template <Real T>
struct SolvedTriangle {
  T a, b, c;
  T alpha, beta, gamma;
};

/// The triangles (0, 1 or 2) determined by three parts; solution[0..count) are valid.
template <Real T>
struct TriangleSolutions {
  int count;
  std::array<SolvedTriangle<T>, 2> solution;
};

namespace detail {
template <Real T>
[[nodiscard]] constexpr bool positive_side(T s) noexcept {
  return s > T(0) && is_finite(s);
}
template <Real T>
[[nodiscard]] constexpr bool open_angle(T t) noexcept {
  return t > T(0) && t < pi_v<T>;
}
template <Real T>
[[nodiscard]] inline TriangleSolutions<T> one_triangle(const SolvedTriangle<T>& t) noexcept {
  TriangleSolutions<T> r{};
  r.count = 1;
  r.solution[0] = t;
  return r;
}
// Sides b, c and the included angle alpha known: the two remaining angles by atan2 of the
// apex coordinates (A at the origin, B = (c, 0), C = b (cos alpha, sin alpha)).
template <Real T>
[[nodiscard]] inline SolvedTriangle<T> from_sas(T b, T alpha, T c, T a) noexcept {
  const T sa = std::sin(alpha), ca = std::cos(alpha);
  SolvedTriangle<T> t{};
  t.a = a;
  t.b = b;
  t.c = c;
  t.alpha = alpha;
  t.beta = std::atan2(b * sa, c - b * ca);
  t.gamma = std::atan2(c * sa, b - c * ca);
  return t;
}
}  // namespace detail

/// SSS: the triangle with sides a, b, c. count = 0 unless all sides are positive, finite and
/// satisfy the triangle inequality (equality, a flat triangle, is accepted).
template <Real T>
[[nodiscard]] inline TriangleSolutions<T> solve_sss(T a, T b, T c) noexcept {
  if (!detail::positive_side(a) || !detail::positive_side(b) || !detail::positive_side(c))
    return {};
  SolvedTriangle<T> t{a,
                      b,
                      c,
                      law_of_cosines_angle(a, b, c),
                      law_of_cosines_angle(b, c, a),
                      law_of_cosines_angle(c, a, b)};
  if (t.alpha != t.alpha || t.beta != t.beta || t.gamma != t.gamma) return {};
  return detail::one_triangle(t);
}

/// SAS: sides b and c with the included angle alpha in (0, pi).
template <Real T>
[[nodiscard]] inline TriangleSolutions<T> solve_sas(T b, T alpha, T c) noexcept {
  if (!detail::positive_side(b) || !detail::positive_side(c) || !detail::open_angle(alpha))
    return {};
  return detail::one_triangle(detail::from_sas(b, alpha, c, law_of_cosines_side(b, c, alpha)));
}

/// ASA: angles alpha and beta with the included side c (between A and B); alpha + beta < pi.
template <Real T>
[[nodiscard]] inline TriangleSolutions<T> solve_asa(T alpha, T c, T beta) noexcept {
  if (!detail::positive_side(c) || !detail::open_angle(alpha) || !detail::open_angle(beta))
    return {};
  const T sum = alpha + beta;
  if (!(sum < pi_v<T>)) return {};
  // sin(gamma) = sin(alpha + beta) avoids the rounding of pi_v in pi - alpha - beta.
  const T sg = std::sin(sum);
  if (!(sg > T(0))) return {};
  SolvedTriangle<T> t{
      c * std::sin(alpha) / sg, c * std::sin(beta) / sg, c, alpha, beta, pi_v<T> - sum};
  return detail::one_triangle(t);
}

/// AAS: angles alpha and beta and the side a opposite alpha; alpha + beta < pi.
template <Real T>
[[nodiscard]] inline TriangleSolutions<T> solve_aas(T alpha, T beta, T a) noexcept {
  if (!detail::positive_side(a) || !detail::open_angle(alpha) || !detail::open_angle(beta))
    return {};
  const T sum = alpha + beta;
  if (!(sum < pi_v<T>)) return {};
  const T sa = std::sin(alpha), sg = std::sin(sum);
  if (!(sg > T(0))) return {};
  SolvedTriangle<T> t{a, a * std::sin(beta) / sa, a * sg / sa, alpha, beta, pi_v<T> - sum};
  return detail::one_triangle(t);
}

/// SSA: sides a and b and the angle alpha opposite a (the ambiguous case). With
/// h = b sin(alpha): no triangle when a < h; one (right angle at B) when a = h; two when
/// h < a < b and alpha is acute; one when a >= b. Solutions are ordered by decreasing c.
/// The third side solves c^2 - 2 b cos(alpha) c + (b^2 - a^2) = 0 with the cancellation-free
/// quadratic formula.
template <Real T>
[[nodiscard]] inline TriangleSolutions<T> solve_ssa(T a, T b, T alpha) noexcept {
  if (!detail::positive_side(a) || !detail::positive_side(b) || !detail::open_angle(alpha))
    return {};
  const T h = b * std::sin(alpha);
  const T disc = (a - h) * (a + h);
  if (!(disc >= T(0))) return {};
  const T bc = b * std::cos(alpha);
  const T prod = (b - a) * (b + a);  // product of the two roots
  T roots[2];
  int n = 0;
  if (disc == T(0)) {
    roots[n++] = bc;
  } else {
    const T q = bc >= T(0) ? bc + std::sqrt(disc) : bc - std::sqrt(disc);
    roots[n++] = q;
    roots[n++] = prod / q;  // q != 0: |q| >= sqrt(disc) > 0
  }
  if (n == 2 && roots[0] < roots[1]) {
    const T t = roots[0];
    roots[0] = roots[1];
    roots[1] = t;
  }
  TriangleSolutions<T> r{};
  for (int i = 0; i < n; ++i) {
    const T c = roots[i];
    if (!(c > T(0)) || !is_finite(c)) continue;
    r.solution[r.count++] = detail::from_sas(b, alpha, c, a);
  }
  return r;
}

}  // namespace locus
