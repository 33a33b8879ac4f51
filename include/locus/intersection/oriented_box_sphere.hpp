// SPDX-License-Identifier: BSL-1.0
#pragma once
// An oriented box against a sphere (the solid ball) in 3D: intersects(); row int3.boxes, book
// section 11.12.4 (figure 11.71).
// Both are closed; touching counts. Method: the centre is expressed in the box frame,
// s_k = dot(center - box.center, axis_k) (rounded: a few eps of the distances involved), and
// then Arvo's test against the aligned box [-extent, extent] decides EXACTLY on those
// coordinates (aligned_box_sphere.hpp): tangency is exact for boxes whose frame transform is
// exact (axis-aligned or small integer data), within a few eps of the sphere's surface otherwise.
// Axes must be unit and orthogonal (OrientedBox's precondition).
// Degenerate: a negative extent, a negative radius or NaN/Inf input gives false. Swapped
// overloads take (sphere, box). Cost: about 30 flops when the filter decides; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/box3.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/sphere.hpp>

namespace locus {

/// Whether the closed box and the closed ball meet.
template <Real T>
[[nodiscard]] inline bool intersects(const OrientedBox3<T>& b, const Sphere3<T>& s) noexcept {
  if (!is_finite(b.center) || !is_finite(b.axis[0]) || !is_finite(b.axis[1]) ||
      !is_finite(b.axis[2]) || !is_finite(b.extent) || !is_valid(s))
    return false;
  const Vec3<double> e = vec_cast<double>(b.extent);
  if (!(e.x >= 0 && e.y >= 0 && e.z >= 0)) return false;
  const Vec3<double> c = detail::box3::to_box(b, vec_cast<double>(s.center));
  return detail::box3::sphere_box_sign(c, double(s.radius), -1.0 * e, e) <= 0;
}

/// Swapped arguments: intersects(b, s).
template <Real T>
[[nodiscard]] inline bool intersects(const Sphere3<T>& s, const OrientedBox3<T>& b) noexcept {
  return intersects(b, s);
}

}  // namespace locus
