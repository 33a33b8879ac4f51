// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a general quadratic curve (conic) a x^2 + b xy + c y^2 + d x +
// e y + f = 0 in the plane; row dist2.pt-quadratic; book section 6.2.2 (figure 6.14, the
// Lagrange condition P - X = t grad Q(X)). Method per class: docs/notes/distance.md.
//
// distance(p, conic) returns Distance<T, 2, NoParam, NoParam>: a general conic has no
// parametrisation in locus (primitives/quadratic_curve.hpp), so closest[1] itself is the answer
// (it satisfies the equation to rounding). distance(conic, p) is the swapped result.
//
// By the EXACT class of classify_conic(): ellipses and circles use the bisection of
// point_ellipse.hpp, competing with the Lagrange candidates; hyperbolas, parabolas and line
// pairs use the Lagrange candidates (all real roots of a quartic, plus the points it cannot see)
// of detail/quadric_lagrange.hpp, each Newton-projected onto the curve; a double line, a point
// or a line (a = b = c = 0) give the orthogonal projection.
//   plane (all zero)   every point is on the "curve": closest[1] = p, distance 0.
//   empty              no closest point: distance = sqr_distance = +infinity, closest[1] and
//                      unique as in the NaN result (closest[0] = p).
// unique = false when two distinct points of the curve are equally close (to 64 eps relative in
// the squared distance): p on an axis of symmetry inside the curve's "evolute", the centre of a
// circle/ellipse, the crossing of two lines' bisectors.
//
// Bad input: a NaN or infinite coefficient or point gives non_finite_distance(). Cost: O(1):
// the exact classification (a few hundred flops), one 2x2 eigen-decomposition and one quartic
// (or the ellipse bisection). Computed in compute_t<T> (double for float).

#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/quadric_lagrange.hpp>
#include <locus/distance/point_ellipse.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/quadratic_curve.hpp>

#include <cmath>
#include <limits>
#include <optional>

namespace locus {

namespace detail {

/// The result when the set is empty: no closest point, distance +infinity.
template <class T, int N, class PA, class PB>
[[nodiscard]] inline Distance<T, N, PA, PB> empty_set_distance(const Vec<T, N>& p) noexcept {
  Distance<T, N, PA, PB> r = non_finite_distance<T, N, PA, PB>();
  r.distance = r.sqr_distance = std::numeric_limits<T>::infinity();
  r.closest[0] = p;
  return r;
}

}  // namespace detail

/// Distance from p to the conic q(x, y) = 0; closest[1] is the nearest point of the conic.
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, NoParam> distance(
    const Vec2<T>& p, const QuadraticCurve2<T>& q) noexcept {
  using R = Distance<T, 2, NoParam, NoParam>;
  const ConicKind kind = classify_conic(q);
  if (kind == ConicKind::non_finite || !is_finite(p))
    return non_finite_distance<T, 2, NoParam, NoParam>();
  if (kind == ConicKind::empty) return detail::empty_set_distance<T, 2, NoParam, NoParam>(p);
  if (kind == ConicKind::plane) return R{T(0), T(0), {p, p}, {}, {}, true};
  using C = compute_t<T>;
  const Vec2<C> pc = vec_cast<C>(p);
  detail::QuadricN<C, 2> qc{};
  qc.a.a[0][0] = C(q.a);
  qc.a.a[0][1] = qc.a.a[1][0] = C(0.5) * C(q.b);
  qc.a.a[1][1] = C(q.c);
  qc.b = {C(q.d), C(q.e)};
  qc.c = C(q.f);
  if (kind == ConicKind::line) {
    const Vec2<C> x = pc - (qc.value(pc) / sqr_length(qc.b)) * qc.b;
    return detail::make_distance(p, vec_cast<T>(x), NoParam{}, NoParam{}, true);
  }
  if (kind == ConicKind::point || kind == ConicKind::double_line) {
    const Vec2<C> x = detail::quadric_pseudo_center(qc, pc, kind == ConicKind::point ? 2 : 1);
    return detail::make_distance(p, vec_cast<T>(x), NoParam{}, NoParam{}, true);
  }
  // Ellipses: Eberly's robust point (exact on the axes), converted in compute precision and
  // Newton-projected onto the conic, competes with the Lagrange candidates (centred at p, so
  // they stay accurate when the axis form is ill-conditioned: nearly parabolic ellipses whose
  // centre lies far away).
  bool have_extra = false, extra_unique = true;
  Vec2<C> extra{};
  if (kind == ConicKind::ellipse || kind == ConicKind::circle) {
    const QuadraticCurve2<C> qd{C(q.a), C(q.b), C(q.c), C(q.d), C(q.e), C(q.f)};
    if (const std::optional<Ellipse2<C>> e = to_ellipse(qd)) {
      const Vec2<C> dd = pc - e->center;
      const C y[2] = {dot(dd, e->axis[0]), dot(dd, e->axis[1])};
      const C ext[2] = {e->extent[0], e->extent[1]};
      const detail::EllipseLocal<C> loc = detail::ellipse_closest_local(ext, y);
      extra = detail::project_onto(qc, e->center + loc.x[0] * e->axis[0] + loc.x[1] * e->axis[1]);
      // Only a point of the curve may compete (the Lagrange candidates pass the same test): for
      // a nearly parabolic ellipse the axis form (centre ~1e9 away) loses every digit, the point
      // lands far off the curve, and the six Newton steps need not bring it back; unchecked it
      // beat the true nearest point (found by a non-default test seed).
      have_extra = qc.contains(extra);
      extra_unique = loc.unique;
    }
  }
  const int rank = (kind == ConicKind::parabola || kind == ConicKind::parallel_lines) ? 1 : 2;
  const C scale = C(1) + static_cast<C>(max_abs(p));
  auto tr = detail::quadric_nearest<C, 2>(qc, pc, rank, C(1024) * C(eps_v<T>) * scale * scale);
  const C tie = C(64) * C(eps_v<T>);
  if (have_extra) tr.offer(sqr_length(extra - pc), C(0), extra);
  if (!tr.found) return detail::empty_set_distance<T, 2, NoParam, NoParam>(p);
  const bool unique = !tr.tied(tie) && !(have_extra && !extra_unique &&
                                         sqr_length(extra - pc) <= tr.best_d2 * (C(1) + tie));
  return detail::make_distance(p, vec_cast<T>(tr.best_point), NoParam{}, NoParam{}, unique);
}

/// The swapped query: closest[0] belongs to the conic.
template <Real T>
[[nodiscard]] inline Distance<T, 2, NoParam, NoParam> distance(const QuadraticCurve2<T>& q,
                                                               const Vec2<T>& p) noexcept {
  return swapped(distance(p, q));
}

}  // namespace locus
