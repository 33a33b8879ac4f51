// SPDX-License-Identifier: BSL-1.0
#pragma once
// Distance between a point and a Bézier (rectangle or triangle), B-spline or NURBS surface in 2D
// or 3D (3D is the book's case); row dist3.pt-paramsurface; book section 10.5, figure 10.26.
// Method (global branch and bound) and accuracy: docs/notes/distance.md. Compiled once
// (src/distance/point_surface.cpp) for float and double, N = 2 and 3.
//
// distance(p, surface) returns Distance<T, N, NoParam, Vec2<T>>: closest[1] =
// point_at(surface, u, v) with param_b = (u, v) in the surface's own parametrisation
// (BezierPatch: [0, 1]^2; BezierTriangle: barycentric (u, v, w = 1 - u - v), u, v >= 0,
// u + v <= 1; BSplineSurface / NurbsSurface: domain_u x domain_v). distance(surface, p) is the
// swapped result.
//
// Accuracy: closest[1] is a surface point (the distance is an upper bound) certified up to
// rounding to be within tau (about 2^-26 of the control box's size) of the global minimum;
// computed in compute_t<T> (double for float). unique = false when two distinct critical points
// tie (to 64 eps of T in the squared distance): a point on a symmetry plane, a sphere's centre.
//
// Degenerate input: degree 0 directions, constant patches, poles, repeated knots and C0 knot
// lines are fine. Invalid surfaces (bad shape, NaN/Inf control points, validate() != ok) and a
// NaN/Inf point give non_finite_distance().
// Cost: O(pieces) extraction plus O(d^4) per processed sub-piece (typically 50-200 for a bicubic
// patch); budget 4096 + 16 pieces sub-pieces (the result is still a surface point when it runs
// out). Allocates the piece nets and the work heap; a failed allocation never escapes: it ends
// the search with the best surface point found so far (unique = false; NaN if there is none).

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/curves/bezier_surface.hpp>
#include <locus/curves/bspline_surface.hpp>
#include <locus/curves/nurbs_surface.hpp>
#include <locus/distance/result.hpp>

namespace locus {

/// Distance from p to the rectangular Bézier patch; param_b is (u, v) in [0, 1]^2.
template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] Distance<T, N, NoParam, Vec2<T>> distance(const Vec<T, N>& p,
                                                            const BezierPatch<T, N>& s) noexcept;

/// Distance from p to the triangular Bézier patch; param_b is barycentric (u, v), w = 1 - u - v.
template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] Distance<T, N, NoParam, Vec2<T>> distance(const Vec<T, N>& p,
                                                            const BezierTriangle<T, N>& s) noexcept;

/// Distance from p to the B-spline surface; param_b is (u, v) in its domain.
template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] Distance<T, N, NoParam, Vec2<T>> distance(const Vec<T, N>& p,
                                                            const BSplineSurface<T, N>& s) noexcept;

/// Distance from p to the NURBS surface; param_b is (u, v) in its domain.
template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] Distance<T, N, NoParam, Vec2<T>> distance(const Vec<T, N>& p,
                                                            const NurbsSurface<T, N>& s) noexcept;

/// The swapped query: closest[0] and param_a belong to the surface.
template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] inline Distance<T, N, Vec2<T>, NoParam> distance(const BezierPatch<T, N>& s,
                                                                   const Vec<T, N>& p) noexcept {
  return swapped(distance(p, s));
}
/// The swapped query: closest[0] and param_a belong to the surface.
template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] inline Distance<T, N, Vec2<T>, NoParam> distance(const BezierTriangle<T, N>& s,
                                                                   const Vec<T, N>& p) noexcept {
  return swapped(distance(p, s));
}
/// The swapped query: closest[0] and param_a belong to the surface.
template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] inline Distance<T, N, Vec2<T>, NoParam> distance(const BSplineSurface<T, N>& s,
                                                                   const Vec<T, N>& p) noexcept {
  return swapped(distance(p, s));
}
/// The swapped query: closest[0] and param_a belong to the surface.
template <Real T, int N>
requires(N == 2 || N == 3)
    [[nodiscard]] inline Distance<T, N, Vec2<T>, NoParam> distance(const NurbsSurface<T, N>& s,
                                                                   const Vec<T, N>& p) noexcept {
  return swapped(distance(p, s));
}

}  // namespace locus
