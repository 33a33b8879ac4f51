// SPDX-License-Identifier: BSL-1.0
#pragma once
// Circles of a given radius r > 0 through points and tangent to lines and circles; rows
// cons2.circle-2pts-r, -pt-line-r, -2lines-r, -pt-circle-r, -line-circle-r, -2circles-r, book
// sections 8.6-8.11 (figures 8.8-8.29). circles_of_radius(a, b, r), a and b points, lines or
// circles (both argument orders). The centre X of a solution lies on two loci, each a circle
// or a line, whose intersection count is decided exactly:
//   point p:   |X - p| = r.                                 line l: s_l(X) = +-r (both sides).
//   circle c:  |X - c.center| = c.radius + r (outside, "external"), or = |c.radius - r| when
//              r != c.radius ("internal": the solution inside c, or c inside it).
// Counts (maximum in the array type): two points 2 (8.9), 1 when |p - q| = 2r, 0 beyond;
// point and line 2 (8.12; mirrored when p is on the line, 8.13), 1 when p is 2r away, 0
// beyond; two crossing lines 4 (8.15), parallel lines 0, or infinitely many exactly 2r apart;
// point and circle up to 4 (8.18: external then internal); line and circle up to 8 (8.23, 8.24);
// two circles up to 8 (8.28: external/external, external/internal, internal/external,
// internal/internal). Order: by locus pair as listed, each pair's two intersections right then
// left of the segment between the loci centres (or along the line's direction). A tangency
// of the loci gives one solution. Coincident loci (two equal points, concentric circles with
// the radius that fits between them, ...) set infinite. Solutions from different locus pairs
// never coincide (r > 0); they are all returned.
//
// Bad input: non-finite values give non_finite_input; r <= 0, a circle radius <= 0 or a zero line
// direction degenerate_input (count 0). Accuracy: centres are rounded; each defining residual
// (|X - p| - r, |s_l(X)| - r, |X - c| - (c.radius +- r)) is within 64 eps_T S, S the largest
// of the input magnitudes, the radii and |X|, near tangency too (computed in double; float
// rounded once).
// Cost O(1); the exact fallback runs only near a change of the count. Derivations:
// docs/notes/construct.md.

#include <locus/construct/solutions.hpp>
#include <locus/core/scalar.hpp>
#include <locus/primitives/circle.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 2> circles_of_radius(const Vec2<T>& p, const Vec2<T>& q,
                                                         T r) noexcept;
template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 2> circles_of_radius(const Vec2<T>& p, const Line2<T>& l,
                                                         T r) noexcept;
template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 4> circles_of_radius(const Line2<T>& l0, const Line2<T>& l1,
                                                         T r) noexcept;
template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 4> circles_of_radius(const Vec2<T>& p, const Circle2<T>& c,
                                                         T r) noexcept;
template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 8> circles_of_radius(const Line2<T>& l, const Circle2<T>& c,
                                                         T r) noexcept;
template <Real T>
[[nodiscard]] Solutions<Circle2<T>, 8> circles_of_radius(const Circle2<T>& c0, const Circle2<T>& c1,
                                                         T r) noexcept;

/// The swapped-argument overloads (same solutions, same order).
template <Real T>
[[nodiscard]] inline Solutions<Circle2<T>, 2> circles_of_radius(const Line2<T>& l, const Vec2<T>& p,
                                                                T r) noexcept {
  return circles_of_radius(p, l, r);
}
template <Real T>
[[nodiscard]] inline Solutions<Circle2<T>, 4> circles_of_radius(const Circle2<T>& c,
                                                                const Vec2<T>& p, T r) noexcept {
  return circles_of_radius(p, c, r);
}
template <Real T>
[[nodiscard]] inline Solutions<Circle2<T>, 8> circles_of_radius(const Circle2<T>& c,
                                                                const Line2<T>& l, T r) noexcept {
  return circles_of_radius(l, c, r);
}

#define LOCUS_CONSTRUCT_RADIUS_EXTERN(T)                                                           \
  extern template Solutions<Circle2<T>, 2> circles_of_radius<T>(const Vec2<T>&, const Vec2<T>&,    \
                                                                T) noexcept;                       \
  extern template Solutions<Circle2<T>, 2> circles_of_radius<T>(const Vec2<T>&, const Line2<T>&,   \
                                                                T) noexcept;                       \
  extern template Solutions<Circle2<T>, 4> circles_of_radius<T>(const Line2<T>&, const Line2<T>&,  \
                                                                T) noexcept;                       \
  extern template Solutions<Circle2<T>, 4> circles_of_radius<T>(const Vec2<T>&, const Circle2<T>&, \
                                                                T) noexcept;                       \
  extern template Solutions<Circle2<T>, 8> circles_of_radius<T>(const Line2<T>&,                   \
                                                                const Circle2<T>&, T) noexcept;    \
  extern template Solutions<Circle2<T>, 8> circles_of_radius<T>(const Circle2<T>&,                 \
                                                                const Circle2<T>&, T) noexcept;
LOCUS_CONSTRUCT_RADIUS_EXTERN(float)
LOCUS_CONSTRUCT_RADIUS_EXTERN(double)
#undef LOCUS_CONSTRUCT_RADIUS_EXTERN

}  // namespace locus
