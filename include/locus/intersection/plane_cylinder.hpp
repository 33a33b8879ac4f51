// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a plane and a cylinder (its infinite lateral surface): intersects() and
// intersection() (find); row int3.plane-quadric, book section 11.5 (figures 11.35-11.41 (circle,
// ellipse, one line, two lines, empty)). Plane3 {normal N (any length), constant k} is N.X = k.
// Result PlaneConic3<T> (intersection/detail/plane_quadric3.hpp): the conic type and its
// parameters, in 3D; axes are unit, normal = N / |N|; point_at(conic, s, branch) samples it. Types
// here: ellipse (circle when the plane is perpendicular to the axis: exact test N x D = 0), two
// parallel lines, one line (tangent plane) or empty when the plane is parallel to the axis
// (exact test N.D = 0, then the exact sign of (N.C - k)^2 - r^2 |N|^2). The height is ignored:
// the section of the infinite surface. Ellipse: center on the axis, semi-axes r / |cos theta|
// along the projection of the axis and r across (theta the angle between normal and axis).
// Degenerate: NaN/Inf, a zero normal or axis, a negative radius or an angle outside (0, pi/2):
// type empty. Float input is computed in double. The swapped overload gives the same result.
// Cost: well under a microsecond (a few exact signs, filtered; trigonometry for the cone).
//
// Parametrisation of the result (see ConicType): circle/ellipse center + e0 cos s axis[0] +
// e1 sin s axis[1]; hyperbola center +- e0 cosh s axis[0] + e1 sinh s axis[1]; parabola vertex
// center + s^2 / (4 e0) axis[0] + s axis[1] (e0 the focal length); lines center + s axis[i].
// The points are rounded: sampled points lie on the plane and on the surface within a few eps
// relative to the scale (away from the parabola boundary of the cone, where the extents of a
// nearly parabolic ellipse or hyperbola are ill-conditioned by nature).

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/plane_quadric3.hpp>
#include <locus/primitives/cylinder.hpp>
#include <locus/primitives/plane.hpp>

namespace locus {

/// The section of the surface by the plane (see the header comment).
template <Real T>
[[nodiscard]] inline PlaneConic3<T> intersection(const Plane3<T>& a,
                                                 const Cylinder3<T>& b) noexcept {
  const Vec3<double> n = vec_cast<double>(a.normal);
  const double k = double(a.constant);
  return detail::plane_quadric3::cast<T>(detail::plane_quadric3::section(
      n, k, vec_cast<double>(b.axis.origin), vec_cast<double>(b.axis.direction), double(b.radius)));
}

/// The same with the arguments exchanged (the conic is symmetric in them).
template <Real T>
[[nodiscard]] inline PlaneConic3<T> intersection(const Cylinder3<T>& a,
                                                 const Plane3<T>& b) noexcept {
  return intersection(b, a);
}

/// Whether the plane meets the surface.
template <Real T>
[[nodiscard]] inline bool intersects(const Plane3<T>& a, const Cylinder3<T>& b) noexcept {
  return intersection(a, b).type != ConicType::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Cylinder3<T>& a, const Plane3<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
