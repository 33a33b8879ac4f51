// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a ray and an oriented box in 3D: intersects() (the book's test) and
// intersection() (find: the part of the ray inside the solid box); row int3.boxes, book
// section 11.12.1 (slab clipping, figures 11.61-11.63).
// Parameters: Ray3 t >= 0 (origin + t direction). Result (LinearBoxIntersection<T>,
// intersection/detail/box3.hpp): empty; point (the component touches the box, or is a point inside
// it); segment (entry and exit points, by increasing param_a); param_b is NoParam. The box is
// closed (faces included). Method: slabs. Each axis with a nonzero direction component gives an
// entry and an exit parameter t = (face - o_k) / d_k; an axis with a zero component (exactly) only
// asks face_min <= o_k <= face_max, so no 0/0 or inf - inf arises (NaN-free for axis-parallel
// directions). The largest entry and smallest exit are chosen by EXACT comparisons of these
// ratios (sign of (a - o_i) d_j - (b - o_j) d_i, core/exact_sum.hpp), as are the domain
// limits (t >= 0 for rays, t <= 1 for segments), so a ray starting on a face, grazing an edge or
// touching a face is decided exactly on the component transformed into the box frame
// (o_k = dot(o - center, axis_k), d_k = dot(d, axis_k), rounded: the box is taken as given,
// within a few eps of its surface the transform decides); points are mapped back.
// Points: the face coordinate of an entry/exit point is the face's exactly, the others are
// rounded (eps relative) and clamped into the box; an end point or origin inside the box is
// returned exactly. Degenerate: a zero direction (zero-length segment) acts as its point; an
// empty box (min > max on an axis; a negative extent) or NaN/Inf input gives kind empty. The
// swapped overload returns swapped(). Cost: about 20 flops and six comparisons when the filters
// decide.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/box3.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/ray.hpp>

namespace locus {

/// Whether a ray meets the closed box (see the header comment).
template <Real T>
[[nodiscard]] inline bool intersects(const Ray3<T>& a, const OrientedBox3<T>& b) noexcept {
  namespace bx = detail::box3;
  return bx::oriented(detail::linear3::as_lin(a), b, false).kind != Kind::empty;
}

/// The part of a ray inside the closed box (see the header comment).
template <Real T>
[[nodiscard]] inline LinearBoxIntersection<T> intersection(const Ray3<T>& a,
                                                           const OrientedBox3<T>& b) noexcept {
  namespace bx = detail::box3;
  return intersection_cast<T>(bx::oriented(detail::linear3::as_lin(a), b, true));
}

/// Swapped arguments: intersects(a, b).
template <Real T>
[[nodiscard]] inline bool intersects(const OrientedBox3<T>& b, const Ray3<T>& a) noexcept {
  return intersects(a, b);
}

/// Swapped arguments: swapped(intersection(a, b)).
template <Real T>
[[nodiscard]] inline Intersection<T, 3, NoParam, T, 2> intersection(const OrientedBox3<T>& b,
                                                                    const Ray3<T>& a) noexcept {
  return swapped(intersection(a, b));
}

}  // namespace locus
