// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and an ellipsoid in 3D; row dist3.pt-ellipsoid (ellipsoid part);
// book section 10.5 (figure 10.24). Spheres are in point_sphere.hpp, general quadrics in
// point_quadric.hpp. Method (Eberly's bracketed root, exact limit cases on the symmetry planes):
// docs/notes/distance.md.
//
// distance(p, ellipsoid) returns Distance<T, 3, NoParam, Vec2<T>>: closest[1] is the point of the
// SURFACE nearest to p (a point inside is at a positive distance from it), param_b = (theta, phi)
// with point_at(ellipsoid, (theta, phi)) = closest[1] (primitives/ellipsoid.hpp: theta in
// (-pi, pi] the azimuth from axis 0 towards axis 1, phi in [0, pi] from axis 2). The axes must be
// orthonormal (the primitive's precondition). distance(ellipsoid, p) is the swapped result.
// Points on the axes, on the coordinate planes and at the centre are exact limit cases, not a
// polynomial's weak spot. Computed in compute_t<T> (double for float).
//
// unique = false exactly when several surface points are closest (p inside near the plane of
// the two longer axes, the centre, points on the axis of a spheroid inside it, the centre of a
// sphere); one is returned (the one with non-negative local coordinates).
//
// Degenerate input: zero extents flatten the ellipsoid: one zero extent gives the FILLED
// ellipse in the plane of the other two axes (point_at covers it), so a point above its
// interior projects orthogonally (unique); two give the segment along the remaining axis; three
// the point center. A negative extent and NaN or infinite values give non_finite_distance().
// Cost: O(1), typically 60-100 bisection steps (at most 2200), one atan2 and one acos/atan2 for
// the parameter.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/distance/point_ellipse.hpp>
#include <locus/distance/result.hpp>
#include <locus/primitives/ellipsoid.hpp>

#include <cmath>

namespace locus {

namespace detail {

template <class C>
struct OctantPoint3 {
  C x[3];
  bool unique;
};

/// Closest point of the ellipsoid with e0 >= e1 >= e2 > 0 to y in the first octant (y_i >= 0).
template <class C>
[[nodiscard]] inline OctantPoint3<C> ellipsoid_octant_closest(const C (&e)[3],
                                                              const C (&y)[3]) noexcept {
  if (y[2] > C(0)) {
    if (y[1] > C(0)) {
      if (y[0] > C(0)) {
        const C z[3] = {y[0] / e[0], y[1] / e[1], y[2] / e[2]};
        const C g = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] - C(1);
        if (g == C(0)) return {{y[0], y[1], y[2]}, true};
        const C r[3] = {sqr(e[0] / e[2]), sqr(e[1] / e[2]), C(1)};
        const C sigma = ellipse_secular_root<C, 3>(r, z, g);
        return {{r[0] * y[0] / (sigma + (r[0] - C(1))), r[1] * y[1] / (sigma + (r[1] - C(1))),
                 y[2] / sigma},
                true};
      }
      const QuadrantPoint2<C> q = ellipse_quadrant_closest(e[1], e[2], y[1], y[2]);
      return {{C(0), q.x0, q.x1}, q.unique};
    }
    if (y[0] > C(0)) {
      const QuadrantPoint2<C> q = ellipse_quadrant_closest(e[0], e[2], y[0], y[2]);
      return {{q.x0, C(0), q.x1}, q.unique};
    }
    return {{C(0), C(0), e[2]}, true};
  }
  // In the plane of the two longer axes (y2 == 0).
  const C denom0 = (e[0] - e[2]) * (e[0] + e[2]), denom1 = (e[1] - e[2]) * (e[1] + e[2]);
  const C numer0 = e[0] * y[0], numer1 = e[1] * y[1];
  if (numer0 < denom0 && numer1 < denom1) {
    const C xde0 = numer0 / denom0, xde1 = numer1 / denom1;
    const C discr = C(1) - xde0 * xde0 - xde1 * xde1;
    if (discr > C(0)) return {{e[0] * xde0, e[1] * xde1, e[2] * std::sqrt(discr)}, false};
  }
  const QuadrantPoint2<C> q = ellipse_quadrant_closest(e[0], e[1], y[0], y[1]);
  return {{q.x0, q.x1, C(0)}, q.unique};
}

template <class C>
struct EllipsoidLocal {
  C x[3];  // closest point in the frame of axis[0..2] (original order)
  bool unique;
};

/// Closest point to local coordinates y on the ellipsoid with extents e >= 0 (zero extents
/// degenerate as the header says).
template <class C>
[[nodiscard]] inline EllipsoidLocal<C> ellipsoid_closest_local(const C (&e)[3],
                                                               const C (&y)[3]) noexcept {
  // Sort the axes by decreasing extent.
  int idx[3] = {0, 1, 2};
  for (int i = 1; i < 3; ++i)
    for (int j = i; j > 0 && e[idx[j]] > e[idx[j - 1]]; --j) {
      const int t = idx[j];
      idx[j] = idx[j - 1];
      idx[j - 1] = t;
    }
  const C es[3] = {e[idx[0]], e[idx[1]], e[idx[2]]};
  const C ys[3] = {y[idx[0]], y[idx[1]], y[idx[2]]};
  C xs[3] = {C(0), C(0), C(0)};
  bool unique = true;
  if (es[2] > C(0)) {
    const C ya[3] = {std::fabs(ys[0]), std::fabs(ys[1]), std::fabs(ys[2])};
    const OctantPoint3<C> o = ellipsoid_octant_closest(es, ya);
    for (int i = 0; i < 3; ++i) xs[i] = ys[i] < C(0) ? -o.x[i] : o.x[i];
    unique = o.unique;
  } else if (es[1] > C(0)) {
    // The filled ellipse in the plane of the two longer axes.
    if (sqr(ys[0] / es[0]) + sqr(ys[1] / es[1]) <= C(1)) {
      xs[0] = ys[0];
      xs[1] = ys[1];
    } else {
      const C e2[2] = {es[0], es[1]}, y2[2] = {ys[0], ys[1]};
      const EllipseLocal<C> l = ellipse_closest_local(e2, y2);
      xs[0] = l.x[0];
      xs[1] = l.x[1];
    }
  } else if (es[0] > C(0)) {
    xs[0] = clamp(ys[0], -es[0], es[0]);
  }
  EllipsoidLocal<C> out{{C(0), C(0), C(0)}, unique};
  for (int i = 0; i < 3; ++i) out.x[idx[i]] = xs[i];
  return out;
}

/// (theta, phi) of the local point x on the ellipsoid (extents e >= 0): the unit-sphere point u
/// with x_i = e_i u_i; a flattened direction takes the remaining length of u (non-negative).
template <class C>
[[nodiscard]] inline Vec2<C> ellipsoid_angles(const C (&e)[3], const C (&x)[3]) noexcept {
  C u[3] = {C(0), C(0), C(0)};
  C sum = C(0);
  for (int i = 0; i < 3; ++i)
    if (e[i] > C(0)) {
      u[i] = clamp(x[i] / e[i], C(-1), C(1));
      sum += u[i] * u[i];
    }
  for (int i = 0; i < 3; ++i)
    if (!(e[i] > C(0))) {
      u[i] = std::sqrt(std::fmax(C(0), C(1) - sum));
      break;
    }
  return {std::atan2(u[1], u[0]), std::atan2(std::hypot(u[0], u[1]), u[2])};
}

}  // namespace detail

/// Distance from p to the ellipsoid's surface; param_b = (theta, phi).
template <Real T>
[[nodiscard]] inline Distance<T, 3, NoParam, Vec2<T>> distance(const Vec3<T>& p,
                                                               const Ellipsoid3<T>& e) noexcept {
  if (!is_finite(p) || !is_finite(e.center) || !is_finite(e.axis[0]) || !is_finite(e.axis[1]) ||
      !is_finite(e.axis[2]) || !is_finite(e.extent) || e.extent.x < T(0) || e.extent.y < T(0) ||
      e.extent.z < T(0))
    return non_finite_distance<T, 3, NoParam, Vec2<T>>();
  using C = compute_t<T>;
  const Vec3<C> d = vec_cast<C>(p) - vec_cast<C>(e.center);
  const Vec3<C> ax[3] = {vec_cast<C>(e.axis[0]), vec_cast<C>(e.axis[1]), vec_cast<C>(e.axis[2])};
  const C y[3] = {dot(d, ax[0]), dot(d, ax[1]), dot(d, ax[2])};
  const C ext[3] = {C(e.extent.x), C(e.extent.y), C(e.extent.z)};
  const detail::EllipsoidLocal<C> loc = detail::ellipsoid_closest_local(ext, y);
  const Vec3<T> q =
      vec_cast<T>(vec_cast<C>(e.center) + loc.x[0] * ax[0] + loc.x[1] * ax[1] + loc.x[2] * ax[2]);
  const Vec2<T> tp = vec_cast<T>(detail::ellipsoid_angles(ext, loc.x));
  return detail::make_distance(p, q, NoParam{}, tp, loc.unique);
}

/// The swapped query: closest[0] and param_a belong to the ellipsoid.
template <Real T>
[[nodiscard]] inline Distance<T, 3, Vec2<T>, NoParam> distance(const Ellipsoid3<T>& e,
                                                               const Vec3<T>& p) noexcept {
  return swapped(distance(p, e));
}

}  // namespace locus
