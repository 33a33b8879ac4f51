// SPDX-License-Identifier: BSL-1.0
#pragma once
// Test intersection of two ellipsoids (solids): relation() (separated, touching, overlapping,
// one inside the other, tangent inside, equal) and intersects() (the solids share a point); row
// int3.surface-surface (quadric pairs), book section 11.8 (ellipsoid-ellipsoid test).
// Method (the book's Lagrange-multiplier form of the test): the affine map taking a onto the
// unit ball takes b to Q(y) = y^T H y - 2 g^T y + k <= 0 (H symmetric positive definite). The
// extremes of Q on the unit sphere (the boundary of a) are where (H - mu I) y = g, |y| = 1: in
// H's eigenframe (numeric/eigen_sym.hpp) the secular equation sum g_i^2 / (lambda_i - mu)^2 = 1,
// the characteristic polynomial of the pencil, whose smallest root (mu <= lambda_min) gives the
// minimum and largest root (mu >= lambda_max) the maximum; both are found by bisection on their
// monotone branches (the "hard case" g_i = 0 handled by completing y to unit length), and Q is
// evaluated at the unit vector obtained. min Q > 0: the boundary of a lies outside b, so b is
// inside a (its center inside a) or they are separated; max Q < 0: a inside b; a sign change:
// overlapping. Not exact: an extreme within tau = 2^-40 (|H| + |g| + |k| + 1) of zero (2^-20 for
// float input, whose axes are orthonormal only to float rounding) is taken as zero (touching,
// tangent inside, or equal when both are; identical inputs are equal), so exactly tangent inputs
// are reported as touching and inputs closer to tangency than that bound are too. Degenerate:
// non-positive extents, zero axes, NaN/Inf: undecided (intersects() false). Axes must be
// orthonormal (the primitive's precondition). Swapping the arguments swaps the containment
// relations. Float input is computed in double. Cost: two 3x3 eigen-decompositions' worth of
// flops plus about 200 bisection steps; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/intersection/detail/quadric_pair3.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/ellipsoid.hpp>

#include <type_traits>

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
      b_axes, vec_cast<double>(b.extent), std::is_same_v<T, float> ? 0x1p-20 : 0x1p-40);
}

/// Whether the two solid ellipsoids share a point (relation() neither separated nor undecided).
template <Real T>
[[nodiscard]] inline bool intersects(const Ellipsoid3<T>& a, const Ellipsoid3<T>& b) noexcept {
  const RegionRelation r = relation(a, b);
  return r != RegionRelation::separated && r != RegionRelation::undecided;
}

}  // namespace locus
