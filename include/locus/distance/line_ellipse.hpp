// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a line, ray or segment and an ellipse in the plane; row dist2.linear-curve
// (ellipse part); book section 6.4 (linear component to quadratic curve, figure 6.23). The
// candidate set (intersections, the two tangent points parallel to the line, the domain's ends,
// the projected centre): docs/notes/distance.md.
//
// distance(linear, Ellipse2) returns Distance<T, 2, T, T>: param_a is the linear parameter of
// closest[0] (Line: t in R, Ray: t >= 0, Segment: t in [0, 1], as point_at), param_b the
// ellipse's angle parameter of closest[1] (point_at(ellipse, a) = center + extent[0] cos(a)
// axis[0] + extent[1] sin(a) axis[1], primitives/ellipse.hpp), in (-pi, pi]. The ellipse is the
// CURVE (a segment inside it is at a positive distance). distance(Ellipse2, linear) is the
// swapped result. The axes must be orthonormal (the primitive's precondition).
// Every candidate is scored by the point-ellipse distance (point_ellipse.hpp), so the result is
// the global minimum, never below the true distance by more than rounding; an intersection gives
// 0 up to the rounding of the root. Computed in compute_t<T> (double for float), rescaled by a
// power of two when the quadratic's coefficients would leave the range (detail/rescale.hpp).
//
// unique = false only when the point-ellipse answer at the winning point is not unique (the
// centre of a circle, or an inside point of the major axis where a ray or segment ends); other
// finite ties (a line crossing the ellipse twice) return one pair with unique = true.
//
// Degenerate input: a zero direction (zero-length segment) acts as its point (t = 0); a zero
// extent collapses the ellipse to a segment traversed twice, both zero to its center (as in
// point_ellipse.hpp). A negative extent and NaN or infinite values give non_finite_distance()
// (result.hpp). Cost: O(1): one quadratic and at most 7 point-ellipse evaluations.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/linear.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/distance/point_ellipse.hpp>
#include <locus/distance/result.hpp>
#include <locus/numeric/roots.hpp>
#include <locus/primitives/ellipse.hpp>
#include <locus/primitives/line.hpp>
#include <locus/primitives/ray.hpp>
#include <locus/primitives/segment.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace locus {

namespace detail {

/// The candidate parameters on the linear component (before clamping to its domain): its ends,
/// the projection of the center, the crossings of the curve and the projections of the two
/// points whose tangent is parallel to the direction.
template <Real T>
struct LinearEllipseCandidates {
  std::array<compute_t<T>, 8> t{};
  int count = 0;
};
template <Real T>
[[nodiscard]] inline LinearEllipseCandidates<T> linear_ellipse2_candidates(
    const LinearView<T, 2>& v, const Ellipse2<T>& e) noexcept {
  using C = compute_t<T>;
  const Vec2<C> a0 = vec_cast<C>(e.axis[0]), a1 = vec_cast<C>(e.axis[1]);
  const Vec2<C> d = vec_cast<C>(v.origin) - vec_cast<C>(e.center);
  const Vec2<C> m = vec_cast<C>(v.dir);
  const C e0 = static_cast<C>(e.extent[0]), e1 = static_cast<C>(e.extent[1]);
  const C x0 = dot(d, a0), x1 = dot(d, a1), u0 = dot(m, a0), u1 = dot(m, a1);

  LinearEllipseCandidates<T> out;
  auto& cand = out.t;
  int& nc = out.count;
  cand[nc++] = C(0);
  if (v.bounded_hi) cand[nc++] = C(1);
  const C mm = dot(m, m);
  if (mm > C(0) && is_finite(mm)) {
    cand[nc++] = -dot(d, m) / mm;  // projection of the center
    // Intersections with the curve.
    const C p0 = e0 * e0, p1 = e1 * e1;
    const RootsResult<C> roots = solve_quadratic<C>(p1 * x0 * x0 + p0 * x1 * x1 - p0 * p1,
                                                    C(2) * (p1 * x0 * u0 + p0 * x1 * u1),
                                                    p1 * u0 * u0 + p0 * u1 * u1, near_roots());
    for (const Root<C>& root : roots) cand[nc++] = root.value;
    // The two points whose tangent is parallel to the direction, projected onto the line.
    const C w0 = e0 * u1, w1 = e1 * u0;
    const C wl = std::hypot(w0, w1);
    if (wl > C(0)) {
      // Offset of the tangent point from the center, in the ellipse frame: (e0 w0, -e1 w1) / wl.
      const Vec2<C> off = (e0 * w0 / wl) * a0 - (e1 * w1 / wl) * a1;
      cand[nc++] = dot(off - d, m) / mm;
      cand[nc++] = dot(-off - d, m) / mm;
    }
  }
  return out;
}

template <class T, class Lin>
[[nodiscard]] inline Distance<T, 2, T, T> linear_ellipse2(const Lin& lin,
                                                          const Ellipse2<T>& e) noexcept {
  if (!finite_input(lin) || !ellipse_ok(e)) return non_finite_distance<T, 2, T, T>();
  const LinearView<T, 2> v = view(lin);
  // The candidates' parameters are scale-free: coordinates whose fourth powers (the quadratic's
  // coefficients) leave the range are first scaled by a power of two (detail/rescale.hpp); the
  // candidates are evaluated on the input.
  const T mag = std::max({max_abs(v.origin), max_abs(v.end), max_abs(v.dir), max_abs(e.center),
                          std::abs(e.extent[0]), std::abs(e.extent[1])});
  const T f = outside_product_range(mag) ? normalising_scale(mag) : T(1);
  const LinearEllipseCandidates<T> cands = linear_ellipse2_candidates(
      scaled_view(v, f),
      Ellipse2<T>{f * e.center, {e.axis[0], e.axis[1]}, {f * e.extent[0], f * e.extent[1]}});
  const auto& cand = cands.t;
  const int nc = cands.count;
  using C = compute_t<T>;

  Distance<T, 2, T, T> best = non_finite_distance<T, 2, T, T>();
  for (int i = 0; i < nc; ++i) {
    const C tc = cand[static_cast<std::size_t>(i)];
    if (!is_finite(tc)) continue;
    T t = static_cast<T>(tc);
    if (v.bounded_lo && t < T(0)) t = T(0);
    if (v.bounded_hi && t > T(1)) t = T(1);
    if (!is_finite(t)) continue;
    const Vec2<T> p = v.at(t);
    const Distance<T, 2, NoParam, T> pe = distance(p, e);
    if (!(pe.sqr_distance >= best.sqr_distance))  // also replaces the initial NaN
      best = {pe.distance, pe.sqr_distance, pe.closest, t, pe.param_b, pe.unique};
  }
  return best;
}

}  // namespace detail

/// Distance between a line and an ellipse (the curve); param_a = t, param_b = the angle.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, T> distance(const Line<T, 2>& l,
                                                   const Ellipse2<T>& e) noexcept {
  return detail::linear_ellipse2(l, e);
}
/// Distance between a ray and an ellipse (the curve); param_a = t >= 0, param_b = the angle.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, T> distance(const Ray<T, 2>& r,
                                                   const Ellipse2<T>& e) noexcept {
  return detail::linear_ellipse2(r, e);
}
/// Distance between a segment and an ellipse (the curve); param_a = t in [0, 1], param_b = the
/// angle.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, T> distance(const Segment<T, 2>& s,
                                                   const Ellipse2<T>& e) noexcept {
  return detail::linear_ellipse2(s, e);
}

/// The swapped query: closest[0] and param_a belong to the ellipse.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, T> distance(const Ellipse2<T>& e,
                                                   const Line<T, 2>& l) noexcept {
  return swapped(distance(l, e));
}
/// The swapped query: closest[0] and param_a belong to the ellipse.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, T> distance(const Ellipse2<T>& e,
                                                   const Ray<T, 2>& r) noexcept {
  return swapped(distance(r, e));
}
/// The swapped query: closest[0] and param_a belong to the ellipse.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, T> distance(const Ellipse2<T>& e,
                                                   const Segment<T, 2>& s) noexcept {
  return swapped(distance(s, e));
}

}  // namespace locus
