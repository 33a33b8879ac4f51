// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a line, ray or segment and a circle in 3D; row dist3.misc (linear-circle
// part); book section 10.3.4 (the point-circle building block, figures 10.16-10.19), method of
// Eberly, "Distance between a line and a circle in 3D" (the quartic and its candidates:
// docs/notes/distance.md).
//
// distance(linear, Circle3) returns Distance<T, 3, T, T>: param_a is the linear parameter of
// closest[0] (Line: t in R, Ray: t >= 0, Segment: t in [0, 1], as point_at), param_b the circle's
// angle of closest[1] (point_at(circle, angle), primitives/circle.hpp), in (-pi, pi]. The circle
// is the CURVE. distance(Circle3, linear) is the swapped result. The minimum is global (never
// below the true distance by more than rounding); crossings of the circle are accurate to
// rounding. Computed in compute_t<T> (double for float), rescaled by a power of two when the
// quartic's coefficients would leave the range (detail/rescale.hpp).
//
// unique = false when the closest point of the linear component lies on the circle's axis with
// a positive radius (every circle point is then equidistant): the line IS the axis, or a ray /
// segment ends on the axis nearer than any other point ("on the axis" within 64 eps times the
// coordinates' scale). Finitely many tied pairs (a line in the circle's plane crossing it twice,
// symmetric configurations) return one of them with unique = true.
//
// Degenerate input: a zero direction (zero-length segment) acts as its point (t = 0); a zero
// radius is the point center; a line in the circle's plane needs no special case. A negative
// radius, a zero normal, and NaN or infinite values give non_finite_distance() (result.hpp).
// Cost: O(1): one quartic (solve_quartic, no allocation), at most 10 candidates, one atan2.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/distance/point_circle.hpp>
#include <locus/distance/result.hpp>
#include <locus/numeric/roots.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace locus {

namespace detail {

/// The squared distance from the point D (relative to the circle's center) to the circle with
/// unit normal n and radius r, in the cancellation-free form z^2 + (rho - r)^2.
template <class C>
[[nodiscard]] inline C sqr_distance_to_circle(const Vec3<C>& d, const Vec3<C>& n, C r) noexcept {
  const C z = dot(d, n);
  const C rho = length(d - z * n);
  return z * z + sqr(rho - r);
}

/// The parameter t of the closest pair on the component (unclamped above 1 by rounding) and
/// whether that point is on the circle's axis (every circle point equally close); n is the unit
/// normal.
template <Real T>
struct LinearCircleParam {
  compute_t<T> t;
  bool on_axis;
};
template <Real T>
[[nodiscard]] inline LinearCircleParam<T> linear_circle3_param(
    const LinearView<T, 3>& v, const Circle3<T>& c, const Vec3<compute_t<T>>& n) noexcept {
  using C = compute_t<T>;
  const Vec3<C> d = vec_cast<C>(v.origin) - vec_cast<C>(c.center);
  const Vec3<C> m = vec_cast<C>(v.dir);
  const C r = static_cast<C>(c.radius);

  // Candidate parameters (clamped to the domain below).
  std::array<C, 10> cand{};
  int nc = 0;
  cand[nc++] = C(0);
  if (v.bounded_hi) cand[nc++] = C(1);
  const C mm = dot(m, m);
  if (mm > C(0) && is_finite(mm)) {
    const Vec3<C> dp = d - dot(d, n) * n;  // parts perpendicular to the axis
    const Vec3<C> mp = m - dot(m, n) * n;
    const C md = dot(m, d), pp = dot(mp, mp), pd = dot(mp, dp), dd = dot(dp, dp);
    cand[nc++] = -md / mm;                 // minimiser of h: the point nearest the center
    if (pp > C(0)) cand[nc++] = -pd / pp;  // minimiser of g: nearest the axis
    // (h'/2)^2 g - r^2 (g'/2)^2 with h'/2 = mm t + md, g = pp t^2 + 2 pd t + dd, g'/2 = pp t + pd.
    const C r2 = r * r;
    const C q0 = md * md, q1 = C(2) * mm * md, q2 = mm * mm;
    const C g0 = dd, g1 = C(2) * pd, g2 = pp;
    const RootsResult<C> roots = solve_quartic<C>(
        q0 * g0 - r2 * pd * pd, q0 * g1 + q1 * g0 - r2 * C(2) * pp * pd,
        q0 * g2 + q1 * g1 + q2 * g0 - r2 * pp * pp, q1 * g2 + q2 * g1, q2 * g2, near_roots());
    for (const Root<C>& root : roots) cand[nc++] = root.value;
    // Where the line meets the cylinder rho = r: g(t) = r^2, solved as a quadratic without
    // cancellation (dd - r^2 = (rho0 - r)(rho0 + r); the discriminant pd^2 - pp (dd - r^2) =
    // pp (r^2 - h^2) with h = |mp x dp| / |mp| the distance of the axis from the projected line).
    // Every crossing of the circle is among these, accurate to rounding, where the quartic's roots
    // carry the rounding of its squared coefficients (a line in the circle's plane crossing it:
    // 1e-10 instead of ~0 in double at LOCUS_TEST_SEED=24, 26, 39).
    if (pp > C(0) && r > C(0)) {
      const C rho0 = std::sqrt(dd), h = std::sqrt(sqr_length(cross(mp, dp)) / pp);
      const C disc = pp * (r - h) * (r + h);
      const C q = -(pd + std::copysign(std::sqrt(disc), pd));
      if (disc >= C(0) && q != C(0)) {  // q = 0: the double root t = 0 = -pd / pp, offered above
        cand[nc++] = q / pp;
        cand[nc++] = (rho0 - r) * (rho0 + r) / q;
      }
    }
  }

  C best_t = C(0);
  C best_f = std::numeric_limits<C>::infinity();
  for (int i = 0; i < nc; ++i) {
    C t = cand[static_cast<std::size_t>(i)];
    if (!is_finite(t)) continue;
    if (v.bounded_lo && t < C(0)) t = C(0);
    if (v.bounded_hi && t > C(1)) t = C(1);
    const C f = sqr_distance_to_circle(d + t * m, n, r);
    if (f < best_f) best_f = f, best_t = t;
  }

  // On the axis every circle point is equally close. point_circle.hpp only sees an EXACT axis
  // point, which the rounded minimiser of a tilted axis never is: accept distances from the axis
  // within the rounding of the input (64 eps of its scale).
  const Vec3<C> w = d + best_t * m;
  const C rho = length(w - dot(w, n) * n);
  const C scale = static_cast<C>(max_abs(v.origin)) + static_cast<C>(max_abs(c.center)) +
                  std::fabs(best_t) * static_cast<C>(max_abs(v.dir)) + r;
  return {best_t, r > C(0) && rho <= C(64) * static_cast<C>(eps_v<T>) * scale};
}

template <class T, class Lin>
[[nodiscard]] inline Distance<T, 3, T, T> linear_circle3(const Lin& lin,
                                                         const Circle3<T>& c) noexcept {
  if (!finite_input(lin) || !circle3_ok(c.center, c.center, c.normal, c.radius))
    return non_finite_distance<T, 3, T, T>();
  using C = compute_t<T>;
  const LinearView<T, 3> v = view(lin);
  const Vec3<C> n = normalize(vec_cast<C>(c.normal));
  if (n == Vec3<C>{}) return non_finite_distance<T, 3, T, T>();
  // The parameter is scale-free: coordinates whose products of six (the quartic's coefficients)
  // leave the range are first scaled by a power of two (detail/rescale.hpp).
  const T mag = std::max(
      {max_abs(v.origin), max_abs(v.end), max_abs(v.dir), max_abs(c.center), std::abs(c.radius)});
  const T f = outside_product_range<T, 6>(mag) ? normalising_scale(mag) : T(1);
  const LinearCircleParam<T> sol =
      linear_circle3_param(scaled_view(v, f), Circle3<T>{f * c.center, c.normal, f * c.radius}, n);
  T t = static_cast<T>(sol.t);
  if (v.bounded_hi && t > T(1)) t = T(1);
  const Vec3<T> p = v.at(t);
  const Distance<T, 3, NoParam, T> pc = distance(p, c);
  if (std::isnan(pc.distance)) return non_finite_distance<T, 3, T, T>();
  return make_distance(p, pc.closest[1], t, pc.param_b, pc.unique && !sol.on_axis);
}

}  // namespace detail

/// Distance between a line and a circle (the curve) in 3D; param_a = t, param_b = the angle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, T> distance(const Line<T, 3>& l,
                                                   const Circle3<T>& c) noexcept {
  return detail::linear_circle3(l, c);
}
/// Distance between a ray and a circle (the curve) in 3D; param_a = t >= 0, param_b = the angle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, T> distance(const Ray<T, 3>& r,
                                                   const Circle3<T>& c) noexcept {
  return detail::linear_circle3(r, c);
}
/// Distance between a segment and a circle (the curve) in 3D; param_a = t in [0, 1], param_b =
/// the angle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, T> distance(const Segment<T, 3>& s,
                                                   const Circle3<T>& c) noexcept {
  return detail::linear_circle3(s, c);
}

/// The swapped query: closest[0] and param_a belong to the circle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, T> distance(const Circle3<T>& c,
                                                   const Line<T, 3>& l) noexcept {
  return swapped(distance(l, c));
}
/// The swapped query: closest[0] and param_a belong to the circle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, T> distance(const Circle3<T>& c,
                                                   const Ray<T, 3>& r) noexcept {
  return swapped(distance(r, c));
}
/// The swapped query: closest[0] and param_a belong to the circle.
template <Real T>
[[nodiscard]] inline Distance<T, 3, T, T> distance(const Circle3<T>& c,
                                                   const Segment<T, 3>& s) noexcept {
  return swapped(distance(s, c));
}

}  // namespace locus
