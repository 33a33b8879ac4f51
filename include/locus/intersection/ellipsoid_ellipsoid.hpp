// SPDX-License-Identifier: BSL-1.0
#pragma once
// Test intersection of two ellipsoids (solids): relation() (separated, touching, overlapping,
// one inside the other, tangent inside, equal) and intersects() (the solids share a point); row
// int3.surface-surface (quadric pairs), book section 11.8 (ellipsoid-ellipsoid test).
// Exact: the answer is that of the solids sum_i (U_i.(X - C))^2 / e_i^2 <= 1 exactly as stored
// (center C, axes U_i, extents e_i, all doubles taken exactly). The axes need not be unit or
// orthogonal, only independent: for orthonormal-to-rounding axes this quadric is the intended
// ellipsoid within rounding, and an exactly tangent pair (e.g. axis-aligned, dyadic data) is
// reported touching while a pair 2^-45 apart is separated. Method (the book's pencil form, made
// exact; derivation and proofs in docs/notes/surface_intersection.md, "Exact ellipsoid
// relation"): each quadric is a 4x4 symmetric integer matrix (scaled by e0^2 e1^2 e2^2 and a
// common power of two), A for a and B for b, and p(mu) = det(B - mu A) has exact integer
// coefficients. Negative roots of p exist iff the interiors are disjoint: two simple ones,
// separated; one double one, touching (Wang, Wang, Kim 2001). Otherwise b lies strictly inside a
// iff B - mu A is positive definite on a gap between consecutive roots (a strictly inside b:
// negative definite), and inside with contact iff B - r A is semidefinite at a multiple root r;
// else overlapping. Proportional matrices are equal. Most pairs are settled first by cheap exact
// certificates (points in both solids and in each alone: overlapping; p(mu) > 0 at some mu < 0:
// separated; B - mu A definite at some mu > 0: containment). Decided in integers: Sturm counts,
// definiteness by principal minors at rational or quadratic-irrational mu.
// Degenerate: non-positive extents, dependent axes (exact determinant zero), NaN/Inf, memory
// exhausted: undecided (intersects() false). Swapping the arguments swaps the containment
// relations. Float input is converted exactly to double. Cost: exact integers of about 1400 bits
// for full-precision double input: about 0.1-0.3 ms when certified, up to about 15 ms for
// tangent or nearly tangent pairs; more when the sizes differ by huge powers of two; allocates.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric_pair3.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/ellipsoid.hpp>

namespace locus {

/// How the two solid ellipsoids lie relative to each other (see the header comment).
template <Real T>
[[nodiscard]] inline RegionRelation relation(const Ellipsoid3<T>& a,
                                             const Ellipsoid3<T>& b) noexcept {
  using V = Vec3<double>;
  const V a_axes[3] = {vec_cast<double>(a.axis[0]), vec_cast<double>(a.axis[1]),
                       vec_cast<double>(a.axis[2])};
  const V b_axes[3] = {vec_cast<double>(b.axis[0]), vec_cast<double>(b.axis[1]),
                       vec_cast<double>(b.axis[2])};
  return detail::quadric_pair3::ellipsoid_relation(
      vec_cast<double>(a.center), a_axes, vec_cast<double>(a.extent), vec_cast<double>(b.center),
      b_axes, vec_cast<double>(b.extent));
}

/// Whether the two solid ellipsoids share a point (relation() neither separated nor undecided).
template <Real T>
[[nodiscard]] inline bool intersects(const Ellipsoid3<T>& a, const Ellipsoid3<T>& b) noexcept {
  const RegionRelation r = relation(a, b);
  return r != RegionRelation::separated && r != RegionRelation::undecided;
}

}  // namespace locus
