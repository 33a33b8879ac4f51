// SPDX-License-Identifier: BSL-1.0
#pragma once
// Test intersection of two oriented boxes in 3D by separating axes: intersects(); row
// int3.boxes, book section 11.12.3 (figures 11.67-11.69, the 15 potential separating axes).
// Boxes are closed solids {center + sum_k s_k extent_k axis_k : |s_k| <= 1} with unit,
// mutually orthogonal axes (OrientedBox's precondition). They are disjoint iff some axis L
// among the 3 + 3 face normals and the 9 cross products A_i x B_j separates their projections:
// |dot(L, D)| > r_A(L) + r_B(L), D = b.center - a.center, r the projected radius
// sum_k extent_k |dot(L, axis_k)|; with C_ij = dot(A_i, B_j) every quantity is a short sum of
// products of C and dot(A_i, D) (the book's table 11.4).
// Near-parallel edges (the book's robust treatment): when some |C_ij| >= 1 - parallel_tolerance
// a pair of axes is (nearly) parallel; the cross-product axes are then zero or nearly zero
// vectors along which rounding noise could claim a separation, and the face axes alone decide
// (for exactly parallel axes they are a complete set). parallel_tolerance is a named, scale-free
// parameter (the axes are unit), default 2^-20: cross products shorter than about 1.4e-3 are
// never used as separating axes. Arithmetic: in double (float input promoted); the comparisons
// are of rounded sums, so boxes within a few eps (relative to their size) of touching may be
// reported either way; touching is otherwise counted as meeting (closed boxes).
// Degenerate: zero extents are flat boxes (valid); a negative extent or NaN/Inf input gives
// false. Cost: at most 15 axis tests, about 200 flops; compiled once in
// src/intersection/oriented_box3.cpp for float and double; no allocation.

#include <locus/core/scalar.hpp>
#include <locus/primitives/oriented_box.hpp>

namespace locus {

namespace detail::box3 {
/// The separating-axis test (compiled in src/intersection/oriented_box3.cpp).
template <Real T>
[[nodiscard]] bool oriented_boxes_meet(const OrientedBox3<T>& a, const OrientedBox3<T>& b,
                                       T parallel_tolerance) noexcept;
extern template bool oriented_boxes_meet<float>(const OrientedBox3<float>&,
                                                const OrientedBox3<float>&, float) noexcept;
extern template bool oriented_boxes_meet<double>(const OrientedBox3<double>&,
                                                 const OrientedBox3<double>&, double) noexcept;
}  // namespace detail::box3

/// Whether two closed oriented boxes meet (separating axes; see the header comment).
template <Real T>
[[nodiscard]] inline bool intersects(const OrientedBox3<T>& a, const OrientedBox3<T>& b,
                                     T parallel_tolerance = T(0x1p-20)) noexcept {
  return detail::box3::oriented_boxes_meet(a, b, parallel_tolerance);
}

}  // namespace locus
