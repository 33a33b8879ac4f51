// SPDX-License-Identifier: BSL-1.0
#pragma once
// Intersection of a segment and a general quadric X^T A X + b.X + c = 0 (10 coefficients) in 3D:
// intersects() and intersection() (find); row int3.linear-quadric, book section 11.3
// (section 11.3.1). Parameters: Segment3 t in [0, 1] (p0 + t (p1 - p0)); param_b = (0, 0) (a
// general quadric has no point_at). Result (LinearSurfaceIntersection3<T>,
// intersection/detail/quadric3.hpp): empty; point or points (by increasing param_a), each with the
// outward unit normal and its multiplicity (2 at a tangency); kind segment (count 2, params 0 and
// 1) when the segment lies on the surface. Exact decisions: q(t) = Q(o + t d); the signs of its
// leading coefficient, of q and q' at the component's ends and of the discriminant (for a segment
// the binary form over p0, p1: no rounded p1 - p0) are exact signs of polynomials in the
// coefficients and coordinates (core/exact_poly.hpp): count, multiplicity, asymptotic directions (q
// linear) and containment are exact for the quadric as given. Points: the stable quadratic root
// form, rounded; |Q(X)| <= 64 eps (S(X) + |grad Q(X)| m), S the sum of |terms| of Q at X, m the
// largest |coordinate|. Degenerate: NaN/Inf or invalid shape (negative radius, zero axis...):
// empty; a zero direction acts as its origin (a point on the surface: one hit). Float input is
// computed in double. The swapped overload returns swapped(). Cost: about 1-10 us (exact terms
// built each call; the big-integer path only near a tie); no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric3.hpp>
#include <locus/primitives/quadric.hpp>
#include <locus/primitives/segment.hpp>

namespace locus {

/// The points where a segment meets the surface (see the header comment).
template <Real T>
[[nodiscard]] inline LinearSurfaceIntersection3<T> intersection(const Segment3<T>& a,
                                                                const Quadric3<T>& b) noexcept {
  return detail::quadric3::find<T>(a, b);
}

/// The same with the arguments exchanged: swapped() of the other order.
template <Real T>
[[nodiscard]] inline auto intersection(const Quadric3<T>& a, const Segment3<T>& b) noexcept {
  return swapped(intersection(b, a));
}

/// Whether a segment meets the surface.
template <Real T>
[[nodiscard]] inline bool intersects(const Segment3<T>& a, const Quadric3<T>& b) noexcept {
  return intersection(a, b).kind != Kind::empty;
}
template <Real T>
[[nodiscard]] inline bool intersects(const Quadric3<T>& a, const Segment3<T>& b) noexcept {
  return intersects(b, a);
}

}  // namespace locus
