// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and an ellipse in the plane; row dist2.pt-quadratic (ellipse part);
// book section 6.2.2 (figure 6.14). The general conic is in point_quadratic_curve.hpp. Method
// (Eberly's bracketed root of F(t), exact axis cases): docs/notes/distance.md.
//
// distance(p, ellipse) returns Distance<T, 2, NoParam, T>: closest[1] is the point of the ellipse
// CURVE nearest to p (a point inside is at a positive distance from it), param_b its angle
// parameter a, point_at(ellipse, a) = center + extent[0] cos(a) axis[0] + extent[1] sin(a) axis[1]
// (primitives/ellipse.hpp), a in (-pi, pi]. distance(ellipse, p) is the swapped result. The axes
// must be orthonormal (the primitive's precondition); they are used as given.
// The root is found by bisection to the last bit (no Newton divergence, no quartic): points on
// and near the axes keep full relative precision. Computed in compute_t<T> (double for float).
//
// unique = false exactly when two or more points of the curve are closest: p inside on the major
// axis near the centre (the point with positive local x1 is returned), the centre of a circle
// (angle 0 is returned) and the centre of any ellipse. A point with y1 tiny but not zero has a
// unique answer and gets it, continuously.
//
// Degenerate input: a zero extent collapses the ellipse to the segment [-e, e] along the other
// axis (the curve traversed twice): the closest point of that segment is returned (unique, angle
// in [0, pi]); both extents zero give the point center (angle 0). A negative extent and NaN or
// infinite values give non_finite_distance() (result.hpp). Near-degenerate ellipses (ratio 1e-6
// and beyond) keep full accuracy. Cost: O(1): typically 55-70 bisection steps (at most 2200),
// one atan2.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/ellipse.hpp>

#include <cmath>
#include <limits>

namespace locus {

namespace detail {

/// Bisection budget of the ellipse/ellipsoid root: more than the number of doubles' exponents.
inline constexpr int ellipse_bisection_budget = 2200;

/// The root of sum_i (n_i / (sigma + r_i - 1))^2 - 1 = 0, n_i = r_i z_i, r_{K-1} = 1, i.e. Eberly's
/// GetRoot in the shifted variable sigma = s + 1, so that a root close to s = -1 (a point near a
/// symmetry plane: sigma ~ z_{K-1} tiny) keeps full relative precision. g = sum z_i^2 - 1 != 0
/// (outside / inside). sigma is bracketed by [z_{K-1}, max(1, |n|)] and bisected until the
/// midpoint equals an end; while the bracket spans more than a factor 4 the midpoint is the
/// geometric mean, so tiny roots cost a few dozen steps, not a thousand.
template <class C, int K>
[[nodiscard]] inline C ellipse_secular_root(const C (&r)[K], const C (&z)[K], C g) noexcept {
  C n[K], rm1[K];
  C len2 = C(0), big = C(0);
  for (int i = 0; i < K; ++i) {
    n[i] = r[i] * z[i];
    rm1[i] = r[i] - C(1);
    big = std::fmax(big, std::fabs(n[i]));
  }
  // |n| by scaling (robust length): no overflow for huge points.
  if (big > C(0))
    for (int i = 0; i < K; ++i) len2 += sqr(n[i] / big);
  C s0 = z[K - 1];
  C s1 = g < C(0) ? C(1) : big * std::sqrt(len2);
  C s = s0;
  for (int it = 0; it < ellipse_bisection_budget; ++it) {
    s = (s0 > C(0) && s1 > C(4) * s0) ? std::sqrt(s0) * std::sqrt(s1) : C(0.5) * (s0 + s1);
    if (s == s0 || s == s1) break;
    C f = C(-1);
    for (int i = 0; i < K; ++i) f += sqr(n[i] / (s + rm1[i]));
    if (f > C(0))
      s0 = s;
    else if (f < C(0))
      s1 = s;
    else
      break;
  }
  return s;
}

/// Closest point of the ellipse (x0/e0)^2 + (x1/e1)^2 = 1, e0 >= e1 > 0, to (y0, y1) in the first
/// quadrant (y0, y1 >= 0). unique = false when another closest point exists.
template <class C>
struct QuadrantPoint2 {
  C x0, x1;
  bool unique;
};

template <class C>
[[nodiscard]] inline QuadrantPoint2<C> ellipse_quadrant_closest(C e0, C e1, C y0, C y1) noexcept {
  if (y1 > C(0)) {
    if (y0 > C(0)) {
      const C z0 = y0 / e0, z1 = y1 / e1;
      const C g = z0 * z0 + z1 * z1 - C(1);
      if (g == C(0)) return {y0, y1, true};
      const C r0 = sqr(e0 / e1);
      const C rr[2] = {r0, C(1)}, zz[2] = {z0, z1};
      const C sigma = ellipse_secular_root<C, 2>(rr, zz, g);
      return {r0 * y0 / (sigma + (r0 - C(1))), y1 / sigma, true};
    }
    return {C(0), e1, true};
  }
  // On the major axis (y1 == 0).
  const C numer0 = e0 * y0, denom0 = (e0 - e1) * (e0 + e1);
  if (numer0 < denom0) {
    const C xde0 = numer0 / denom0;
    return {e0 * xde0, e1 * std::sqrt(std::fmax(C(0), (C(1) - xde0) * (C(1) + xde0))), false};
  }
  // The vertex; at the centre of a circle every point is closest.
  return {e0, C(0), y0 > C(0)};
}

/// Local frame coordinates and the closest point, for Ellipse2 (shared by the linear queries).
template <class C>
struct EllipseLocal {
  C x[2];  // closest point, in the frame of axis[0], axis[1] (original order)
  bool unique;
};

/// Closest point to local coordinates y (frame of axis[0], axis[1]) on the ellipse with
/// extents e[0], e[1] >= 0 (zero extents degenerate as the header says).
template <class C>
[[nodiscard]] inline EllipseLocal<C> ellipse_closest_local(const C (&e)[2],
                                                           const C (&y)[2]) noexcept {
  const int big = e[0] >= e[1] ? 0 : 1, small = 1 - big;
  EllipseLocal<C> out{{C(0), C(0)}, true};
  const C eb = e[big], es = e[small];
  if (!(eb > C(0))) return out;  // the centre
  if (!(es > C(0))) {
    // The segment [-eb, eb] along the big axis.
    out.x[big] = clamp(y[big], -eb, eb);
    return out;
  }
  const QuadrantPoint2<C> q =
      ellipse_quadrant_closest(eb, es, std::fabs(y[big]), std::fabs(y[small]));
  out.x[big] = y[big] < C(0) ? -q.x0 : q.x0;
  out.x[small] = y[small] < C(0) ? -q.x1 : q.x1;
  out.unique = q.unique;
  return out;
}

/// The angle parameter of the local point x on the ellipse (extents e >= 0).
template <class C>
[[nodiscard]] inline C ellipse_angle(const C (&e)[2], const C (&x)[2]) noexcept {
  if (e[0] > C(0) && e[1] > C(0)) return std::atan2(x[1] / e[1], x[0] / e[0]);
  if (e[0] > C(0)) return std::acos(clamp(x[0] / e[0], C(-1), C(1)));
  if (e[1] > C(0)) return std::asin(clamp(x[1] / e[1], C(-1), C(1)));
  return C(0);
}

template <Real T>
[[nodiscard]] constexpr bool ellipse_ok(const Ellipse2<T>& e) noexcept {
  return is_finite(e.center) && is_finite(e.axis[0]) && is_finite(e.axis[1]) &&
         is_finite(e.extent[0]) && is_finite(e.extent[1]) && e.extent[0] >= T(0) &&
         e.extent[1] >= T(0);
}

}  // namespace detail

/// Distance from p to the ellipse (the curve); param_b is the angle parameter.
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, T> distance(const Vec2<T>& p,
                                                         const Ellipse2<T>& e) noexcept {
  if (!is_finite(p) || !detail::ellipse_ok(e)) return non_finite_distance<T, 2, NoParam, T>();
  using C = compute_t<T>;
  const Vec2<C> d = vec_cast<C>(p) - vec_cast<C>(e.center);
  const Vec2<C> a0 = vec_cast<C>(e.axis[0]), a1 = vec_cast<C>(e.axis[1]);
  const C y[2] = {dot(d, a0), dot(d, a1)};
  const C ext[2] = {C(e.extent[0]), C(e.extent[1])};
  const detail::EllipseLocal<C> loc = detail::ellipse_closest_local(ext, y);
  const Vec2<T> q = vec_cast<T>(vec_cast<C>(e.center) + loc.x[0] * a0 + loc.x[1] * a1);
  const T angle = static_cast<T>(detail::ellipse_angle(ext, loc.x));
  return detail::make_distance(p, q, NoParam{}, angle, loc.unique);
}

/// The swapped query: closest[0] and param_a belong to the ellipse.
template <Real T>
[[nodiscard]] inline Distance<T, 2, T, NoParam> distance(const Ellipse2<T>& e,
                                                         const Vec2<T>& p) noexcept {
  return swapped(distance(p, e));
}

}  // namespace locus
