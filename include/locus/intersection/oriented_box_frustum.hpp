// SPDX-License-Identifier: BSL-1.0
#pragma once
// Test intersection of an oriented box and an orthogonal view frustum in 3D by separating axes:
// intersects(); row int3.boxes, book section 11.12 (the OBB / orthogonal frustum test; the
// frustum of figure 10.23, primitives/frustum.hpp).
// Both are closed solids (touching counts as meeting). In the frustum's frame (E; R, U, D), with
// near distance n, far f and near half extents r, u, the frustum is {n <= z <= f, |x| <= r z/n,
// |y| <= u z/n}. The candidate axes (26) are D, the four side-plane normals (+-n, 0, -r) and
// (0, +-n, -u), the box axes A_i, and the cross products of R, U and the four lateral edge
// directions (+-r, +-u, n) with each A_i. On axis L the box projects to dot(L, C) +- sum_i e_i
// |dot(L, A_i)|; the frustum to z (p -+ q) over z in [n, f], p = L_z, q = (r |L_x| + u |L_y|)/n,
// whose extremes are at z = n or z = f by the signs of p -+ q (docs/notes/sat3.md).
// Nearly parallel edge pairs (sine below 2^-20) skip their cross product, as the OBB-OBB test does.
// Arithmetic: double (float input promoted), rounded; a box within a few eps (relative to the
// sizes and distances) of touching may be reported either way. Exact alternative: the general
// exact test of intersection/sat.hpp over the rounded corners (box_polyhedron of both corner
// sets), which the tests use as the oracle.
// Degenerate: zero extents (flat boxes), r = 0 or u = 0 and f == n are valid; an invalid frustum
// (is_valid() false), a negative extent or NaN/Inf input gives false. Cost: at most 26 axis tests,
// about 400 flops, no allocation; compiled in src/intersection/oriented_box_frustum.cpp.

#include <locus/core/scalar.hpp>
#include <locus/primitives/frustum.hpp>
#include <locus/primitives/oriented_box.hpp>

namespace locus {

namespace detail::box_frustum {
/// src/intersection/oriented_box_frustum.cpp.
template <Real T>
[[nodiscard]] bool test(const OrientedBox3<T>& box, const Frustum3<T>& frustum) noexcept;
extern template bool test<float>(const OrientedBox3<float>&, const Frustum3<float>&) noexcept;
extern template bool test<double>(const OrientedBox3<double>&, const Frustum3<double>&) noexcept;
}  // namespace detail::box_frustum

/// Whether an oriented box and an orthogonal frustum meet (see the header comment).
template <Real T>
[[nodiscard]] inline bool intersects(const OrientedBox3<T>& box,
                                     const Frustum3<T>& frustum) noexcept {
  return detail::box_frustum::test<T>(box, frustum);
}

/// The swapped-argument overload.
template <Real T>
[[nodiscard]] inline bool intersects(const Frustum3<T>& frustum,
                                     const OrientedBox3<T>& box) noexcept {
  return detail::box_frustum::test<T>(box, frustum);
}

}  // namespace locus
