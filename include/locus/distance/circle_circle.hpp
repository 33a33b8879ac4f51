// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between two circles in 3D; row dist3.misc (circle-circle part); book section 10.3.4
// (the point-circle building block), method of Eberly, "Distance to Circles in 3D" (the
// degree-8 polynomial in tan(a / 2) and its candidates: docs/notes/distance.md).
//
// distance(Circle3, Circle3) returns Distance<T, 3, T, T>: param_a / param_b are the angles of
// closest[0] / closest[1] on the first / second circle (point_at(circle, angle),
// primitives/circle.hpp), in (-pi, pi]. Both circles are CURVES. The minimum is global (never
// below the true distance by more than rounding). Computed in compute_t<T> (double for float),
// rescaled by a power of two when the polynomial's coefficients would leave the range
// (detail/rescale.hpp). The pair is solved in a canonical argument order, so distance(b, a) is
// bit for bit the swap of distance(a, b).
//
// unique = false for coaxial circles (parallel normals, centers on a common axis, including
// concentric coplanar circles: angle 0 of the first circle is returned) and when the chosen
// point lies on the other circle's axis. Other finite ties (symmetric configurations, two
// intersection points) return one pair with unique = true. Coplanar, touching and intersecting
// circles need no special case (intersecting: distance 0 up to rounding of the root).
//
// Degenerate input: a zero radius makes that circle the point center (point_circle.hpp; its
// angle is 0); two zero radii give the two centers. A negative radius, a zero normal, and NaN
// or infinite values give non_finite_distance() (result.hpp). Cost: O(1) but heavier than most
// pairs: a degree-8 polynomial and its real roots (fixed stack workspace, no allocation), at
// most 11 candidate evaluations, three atan2.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/distance/line_circle.hpp>  // detail::sqr_distance_to_circle
#include <locus/distance/point_circle.hpp>
#include <locus/distance/result.hpp>
#include <locus/numeric/roots.hpp>
#include <locus/primitives/circle.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace locus {

namespace detail {

/// A polynomial of degree <= 8 with fixed storage (coefficients low to high): the arithmetic the
/// circle-circle polynomial needs, without allocation.
template <class C>
struct CirclePoly {
  std::array<C, 9> c{};
  friend CirclePoly operator+(const CirclePoly& p, const CirclePoly& q) noexcept {
    CirclePoly r;
    for (std::size_t i = 0; i < 9; ++i) r.c[i] = p.c[i] + q.c[i];
    return r;
  }
  friend CirclePoly operator-(const CirclePoly& p, const CirclePoly& q) noexcept {
    CirclePoly r;
    for (std::size_t i = 0; i < 9; ++i) r.c[i] = p.c[i] - q.c[i];
    return r;
  }
  friend CirclePoly operator*(C s, const CirclePoly& p) noexcept {
    CirclePoly r;
    for (std::size_t i = 0; i < 9; ++i) r.c[i] = s * p.c[i];
    return r;
  }
  /// The product; the callers' degrees add up to at most 8 (terms beyond are dropped).
  friend CirclePoly operator*(const CirclePoly& p, const CirclePoly& q) noexcept {
    CirclePoly r;
    for (std::size_t i = 0; i < 9; ++i)
      for (std::size_t j = 0; i + j < 9; ++j) r.c[i + j] += p.c[i] * q.c[j];
    return r;
  }
};

/// Lexicographic order on the raw scalars of a circle, for the canonical argument order.
template <Real T>
[[nodiscard]] inline bool circle3_less(const Circle3<T>& a, const Circle3<T>& b) noexcept {
  const T va[7] = {a.center.x, a.center.y, a.center.z, a.normal.x,
                   a.normal.y, a.normal.z, a.radius};
  const T vb[7] = {b.center.x, b.center.y, b.center.z, b.normal.x,
                   b.normal.y, b.normal.z, b.radius};
  return std::lexicographical_compare(va, va + 7, vb, vb + 7);
}

template <Real T>
struct CircleCircleAngle {
  compute_t<T> angle;
  bool coaxial;
};
template <Real T>
[[nodiscard]] inline CircleCircleAngle<T> circle_circle3_angle(
    const Circle3<T>& c0, const Circle3<T>& c1, const CircleAxes<compute_t<T>>& ax,
    const Vec3<compute_t<T>>& n1) noexcept;

template <Real T>
[[nodiscard]] inline Distance<T, 3, T, T> circle_circle3(const Circle3<T>& c0,
                                                         const Circle3<T>& c1) noexcept {
  using C = compute_t<T>;
  // A zero radius: that circle is its center.
  if (!(c1.radius > T(0))) {
    const Distance<T, 3, T, NoParam> pc = distance(c0, c1.center);
    return {pc.distance, pc.sqr_distance, pc.closest, pc.param_a, T(0), pc.unique};
  }
  if (!(c0.radius > T(0))) {
    const Distance<T, 3, NoParam, T> pc = distance(c0.center, c1);
    return {pc.distance, pc.sqr_distance, pc.closest, T(0), pc.param_b, pc.unique};
  }
  const CircleAxes<C> ax = circle_axes_of_normal(vec_cast<C>(c0.normal));
  const Vec3<C> n1 = normalize(vec_cast<C>(c1.normal));
  if (ax.u == Vec3<C>{} || n1 == Vec3<C>{}) return non_finite_distance<T, 3, T, T>();
  // The angle is scale-free: coordinates whose products of up to eight (the polynomial's
  // coefficients) leave the range are first scaled by a power of two (detail/rescale.hpp); the
  // pair comes from the input itself.
  const T mag = std::max({max_abs(c0.center), max_abs(c1.center), c0.radius, c1.radius});
  const T f = outside_product_range<T, 8>(mag) ? normalising_scale(mag) : T(1);
  const CircleCircleAngle<T> sol =
      circle_circle3_angle(Circle3<T>{f * c0.center, c0.normal, f * c0.radius},
                           Circle3<T>{f * c1.center, c1.normal, f * c1.radius}, ax, n1);
  const T angle0 = static_cast<T>(sol.angle);
  const Vec3<T> p = point_at(c0, angle0);
  const Distance<T, 3, NoParam, T> pc = distance(p, c1);
  if (std::isnan(pc.distance)) return non_finite_distance<T, 3, T, T>();
  return make_distance(p, pc.closest[1], angle0, pc.param_b, pc.unique && !sol.coaxial);
}

/// The angle on c0 of the closest pair of two circles of positive radii (see the header), and
/// whether they are coaxial; ax are c0's plane axes, n1 c1's unit normal.
template <Real T>
[[nodiscard]] inline CircleCircleAngle<T> circle_circle3_angle(
    const Circle3<T>& c0, const Circle3<T>& c1, const CircleAxes<compute_t<T>>& ax,
    const Vec3<compute_t<T>>& n1) noexcept {
  using C = compute_t<T>;
  const C r0 = static_cast<C>(c0.radius), r1 = static_cast<C>(c1.radius);
  const Vec3<C> d = vec_cast<C>(c0.center) - vec_cast<C>(c1.center);
  const auto perp = [&](const Vec3<C>& w) { return w - dot(w, n1) * n1; };
  const Vec3<C> dp = perp(d), up = perp(ax.u), vp = perp(ax.v);
  const C a = dot(d, ax.u), b = dot(d, ax.v);
  const C dd = dot(dp, dp), du = dot(dp, up), dv = dot(dp, vp);
  const C uu = dot(up, up), vv = dot(vp, vp), uv = dot(up, vp);

  // Polynomials in x = tan(a / 2) of degree <= 8 as fixed coefficient arrays (low to high).
  using Poly = CirclePoly<C>;
  const Poly one_p{{C(1), C(0), C(1)}};   // 1 + x^2
  const Poly one_m{{C(1), C(0), C(-1)}};  // 1 - x^2
  const Poly x{{C(0), C(1)}};
  // (1 + x^2) h'(a), (1 + x^2)^2 g(a) and (1 + x^2)^2 g'(a) as polynomials in x.
  const Poly hp = C(2) * r0 * (b * one_m - C(2) * a * x);
  const Poly g = dd * (one_p * one_p) +
                 r0 * r0 * (uu * (one_m * one_m) + C(4) * uv * (x * one_m) + C(4) * vv * (x * x)) +
                 C(2) * r0 * (one_p * (du * one_m + C(2) * dv * x));
  const Poly gp =
      r0 * r0 * (C(4) * (vv - uu) * (x * one_m) + C(2) * uv * (one_m * one_m - C(4) * (x * x))) +
      C(2) * r0 * (one_p * (dv * one_m - C(2) * du * x));
  const Poly lhs = hp * hp * g;
  const Poly rhs = r1 * r1 * (gp * gp);

  // Coaxial circles: F is constant and the two sides agree to rounding.
  C size = C(0), diff = C(0);
  for (std::size_t i = 0; i <= 8; ++i) {
    size = std::max(size, std::abs(lhs.c[i]) + std::abs(rhs.c[i]));
    diff = std::max(diff, std::abs(lhs.c[i] - rhs.c[i]));
  }
  const bool coaxial = diff <= C(1024) * eps_v<C> * size;

  C best_a = C(0);
  if (!coaxial) {
    const auto f_at = [&](C angle) {
      const Vec3<C> w = d + (r0 * std::cos(angle)) * ax.u + (r0 * std::sin(angle)) * ax.v;
      return sqr_distance_to_circle(w, n1, r1);
    };
    best_a = pi_v<C>;
    C best_f = f_at(best_a);
    // All real roots of the degree-8 polynomial, on stack buffers of the engine's documented
    // sizes (real_roots() would allocate them).
    constexpr int deg = 8;
    double coeff[deg + 1];
    bool finite = true;
    for (std::size_t i = 0; i <= 8; ++i) {
      coeff[i] = static_cast<double>(lhs.c[i] - rhs.c[i]);
      finite = finite && is_finite(coeff[i]);
    }
    double work[roots::work_doubles(deg)];
    roots::R r_out[deg], r_tmp[deg];
    bool budget_hit = false;
    const int cnt =
        finite ? roots::real_roots_engine(coeff, nullptr, deg, work, r_out, r_tmp, 0.0, budget_hit)
               : 0;
    for (int i = 0; i < cnt; ++i) {
      const C angle = C(2) * std::atan(static_cast<C>(r_out[i].x));
      const C f = f_at(angle);
      if (f < best_f) best_f = f, best_a = angle;
    }
    // Squaring made double roots: the equation is (h' sqrt(g) - r1 g') (h' sqrt(g) + r1 g') = 0,
    // and both factors vanish where h' and g' vanish together. Rounding of the coefficients can
    // turn such a double root into a complex pair that the root finder rightly does not report,
    // losing a critical point of F that may be the minimum. It happens when the center of circle
    // 0 lies on the axis of circle 1 (D = |D| n1): with e(a) = cos a U0 + sin a V0, h' = 2 r0 |D|
    // n1.e' and g' = -2 r0^2 (n1.e) (n1.e'), so both vanish where n1.e' = 0, at the two extremes
    // of circle 0 along n1. Every common zero of h' and g' is a zero of h' = 2 r0 (b cos a -
    // a sin a), and those are known in closed form: they are always candidates.
    if (a != C(0) || b != C(0)) {
      for (const C angle : {std::atan2(b, a), std::atan2(-b, -a)}) {
        if (!(angle > -pi_v<C>)) continue;  // -pi is pi, already a candidate
        const C f = f_at(angle);
        if (f < best_f) best_f = f, best_a = angle;
      }
    }
  }
  return {best_a, coaxial};
}

}  // namespace detail

/// Distance between two circles (curves) in 3D; param_a, param_b are the angles.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, T> distance(const Circle3<T>& a,
                                                   const Circle3<T>& b) noexcept {
  if (!detail::circle3_ok(a.center, a.center, a.normal, a.radius) ||
      !detail::circle3_ok(b.center, b.center, b.normal, b.radius))
    return non_finite_distance<T, 3, T, T>();
  if (detail::circle3_less(b, a)) return swapped(detail::circle_circle3(b, a));
  return detail::circle_circle3(a, b);
}

}  // namespace locus
