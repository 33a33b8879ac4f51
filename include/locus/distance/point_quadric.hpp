// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a general quadric surface X^T A X + b . X + c = 0 in 3D; row
// dist3.pt-ellipsoid (general quadric part); book section 10.5 (the Lagrange condition
// P - X = t grad Q(X)). Ellipsoids in axis form are in point_ellipsoid.hpp. Method per type:
// docs/notes/distance.md.
//
// distance(p, quadric) returns Distance<T, 3, NoParam, NoParam>: a general quadric has no
// parametrisation in locus (primitives/quadric.hpp), so closest[1] itself is the answer (it
// satisfies the equation to rounding). distance(quadric, p) is the swapped result.
//
// By the EXACT type of quadric_type(q): an ellipsoid uses the bisection of point_ellipsoid.hpp,
// competing with the Lagrange candidates; hyperboloids, cones, paraboloids, cylinders and plane
// pairs use the Lagrange candidates of detail/quadric_lagrange.hpp (all real roots of a sextic,
// plus symmetry-plane, apex and singular-line points), each Newton-projected onto the surface.
//   plane, double plane, line, point   the orthogonal projection onto that affine subspace.
//   entire space          closest[1] = p, distance 0.
//   empty                 distance = sqr_distance = +infinity, closest[1] NaN, unique = false.
// unique = false when two distinct surface points are equally close (64 eps relative in the
// squared distance): points on symmetry planes and axes, the centre of a sphere, ...
//
// Bad input: NaN or infinite coefficients or point give non_finite_distance(). Cost: O(1): the
// exact classification (13 exact principal minors), one 3x3 eigen-decomposition, one sextic
// (or the ellipsoid bisection). Computed in compute_t<T> (double for float).

#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/detail/quadric_lagrange.hpp>
#include <locus/distance/point_ellipsoid.hpp>
#include <locus/distance/point_quadratic_curve.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/quadric.hpp>

#include <cmath>

namespace locus {

/// Distance from p to the quadric surface; closest[1] is the nearest point of the surface.
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, NoParam> distance(const Vec3<T>& p,
                                                               const Quadric3<T>& q) noexcept {
  using R = Distance<T, 3, NoParam, NoParam>;
  if (!is_finite(p)) return non_finite_distance<T, 3, NoParam, NoParam>();
  const QuadricClass cls = quadric_type(q);
  if (cls.status != Status::ok) return non_finite_distance<T, 3, NoParam, NoParam>();
  if (cls.type == QuadricType::empty) return detail::empty_set_distance<T, 3, NoParam, NoParam>(p);
  if (cls.type == QuadricType::entire_space) return R{T(0), T(0), {p, p}, {}, {}, true};
  using C = compute_t<T>;
  const Vec3<C> pc = vec_cast<C>(p);
  detail::QuadricN<C, 3> qc{};
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) qc.a.a[i][j] = qc.a.a[j][i] = static_cast<C>(q.a.a[i][j]);
  qc.b = vec_cast<C>(q.b);
  qc.c = static_cast<C>(q.c);
  if (cls.type == QuadricType::plane && cls.rank_a == 0) {
    const Vec3<C> x = pc - (qc.value(pc) / sqr_length(qc.b)) * qc.b;
    return detail::make_distance(p, vec_cast<T>(x), NoParam{}, NoParam{}, true);
  }
  if (cls.type == QuadricType::plane || cls.type == QuadricType::line ||
      cls.type == QuadricType::point) {
    const Vec3<C> x = detail::quadric_pseudo_center(qc, pc, cls.rank_a);
    return detail::make_distance(p, vec_cast<T>(x), NoParam{}, NoParam{}, true);
  }
  // Ellipsoids: Eberly's robust point (converted in compute precision, Newton-projected onto the
  // quadric) competes with the Lagrange candidates, which are centred at p and stay accurate for
  // nearly paraboloidal ellipsoids.
  bool have_extra = false, extra_unique = true;
  Vec3<C> extra{};
  if (cls.type == QuadricType::ellipsoid) {
    Quadric3<C> qd{};
    qd.a = qc.a;
    qd.b = qc.b;
    qd.c = qc.c;
    const QuadricStandardForm<C> f = standard_form(qd);
    if (f.status == Status::ok && f.constant < C(0) && f.diagonal.x > C(0) && f.diagonal.y > C(0) &&
        f.diagonal.z > C(0)) {
      const C ext[3] = {std::sqrt(-f.constant / f.diagonal.x),
                        std::sqrt(-f.constant / f.diagonal.y),
                        std::sqrt(-f.constant / f.diagonal.z)};
      Vec3<C> ax[3];
      C y[3];
      for (int i = 0; i < 3; ++i) {
        ax[i] = col(f.rotation, i);
        y[i] = dot(pc - f.center, ax[i]);
      }
      const detail::EllipsoidLocal<C> loc = detail::ellipsoid_closest_local(ext, y);
      extra = detail::project_onto(
          qc, f.center + loc.x[0] * ax[0] + loc.x[1] * ax[1] + loc.x[2] * ax[2]);
      have_extra = is_finite(extra);
      extra_unique = loc.unique;
    }
  }
  const C scale = C(1) + static_cast<C>(max_abs(p));
  auto tr =
      detail::quadric_nearest<C, 3>(qc, pc, cls.rank_a, C(1024) * C(eps_v<T>) * scale * scale);
  const C tie = C(64) * C(eps_v<T>);
  if (have_extra) tr.offer(sqr_length(extra - pc), C(0), extra);
  if (!tr.found) return detail::empty_set_distance<T, 3, NoParam, NoParam>(p);
  const bool unique = !tr.tied(tie) && !(have_extra && !extra_unique &&
                                         sqr_length(extra - pc) <= tr.best_d2 * (C(1) + tie));
  return detail::make_distance(p, vec_cast<T>(tr.best_point), NoParam{}, NoParam{}, unique);
}

/// The swapped query: closest[0] belongs to the quadric.
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, NoParam> distance(const Quadric3<T>& q,
                                                               const Vec3<T>& p) noexcept {
  return swapped(distance(p, q));
}

}  // namespace locus
