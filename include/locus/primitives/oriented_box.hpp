// SPDX-License-Identifier: BSL-1.0
#pragma once
// Oriented boxes in N dimensions (OBB); row prim3.solids; the solid primitives of the book's
// chapters 10-11 and the symmetric (center-axes-extents) form of the rectangle, section 5.1.3
// / 9.2.3.
//
// OrientedBox<T, N> {center, axis[N], extent} is the set
//   { center + sum_i s_i extent[i] axis[i] : s in [-1, 1]^N },
// with axis[] unit length and mutually orthogonal (a precondition, not checked; right-handed
// orientation is not required) and extent[i] >= 0 the half side lengths.
// point_at(box, s) evaluates exactly that sum for s in [-1, 1]^N (the symmetric parametrisation,
// so s = 0 is the center). Corner k takes s[i] = +1 where bit i of k is set and -1 elsewhere,
// matching AlignedBox's corner numbering when the axes are the coordinate axes.
//
// Conversions: oriented_box(AlignedBox) has the coordinate axes; rotated(box, R) applies the
// rotation R (columns = images of the coordinate axes; y = R x as in mat.hpp) about the
// coordinate origin; bounding_box(obb) is the tight AlignedBox, center +- sum_j |axis_j| extent_j.
//
// Degenerate input: a zero extent gives a flat box (measure 0); a negative extent is invalid
// and measure() returns NaN for it. Non-orthonormal axes make the measures wrong (they assume
// orthonormality); non-finite input propagates. O(N^2) per call (corners O(N 2^N)).

#include <locus/config.hpp>
#include <locus/core/mat.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/aligned_box.hpp>

#include <array>
#include <cstddef>
#include <limits>

namespace locus {

/// The box { center + sum_i s_i extent[i] axis[i] : |s_i| <= 1 } with orthonormal axes.
template <class T, int N>
struct OrientedBox {
  Vec<T, N> center;
  Vec<T, N> axis[N];
  Vec<T, N> extent;
};

template <Real T>
using OrientedBox2 = OrientedBox<T, 2>;
template <Real T>
using OrientedBox3 = OrientedBox<T, 3>;
using OrientedBox2f = OrientedBox2<float>;
using OrientedBox2d = OrientedBox2<double>;
using OrientedBox3f = OrientedBox3<float>;
using OrientedBox3d = OrientedBox3<double>;

/// center + sum_i s[i] extent[i] axis[i], s in [-1, 1]^N.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const OrientedBox<T, N>& b,
                                           const Vec<T, N>& s) noexcept {
  Vec<T, N> p = b.center;
  for (int i = 0; i < N; ++i) p += (s[i] * b.extent[i]) * b.axis[i];
  return p;
}

/// Corner k: s[i] = +1 where bit i of k is set, -1 elsewhere (0 <= k < 2^N).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> corner(const OrientedBox<T, N>& b, int k) noexcept {
  LOCUS_ASSERT(k >= 0 && k < (1 << N), "OrientedBox corner index out of range");
  Vec<T, N> s{};
  for (int i = 0; i < N; ++i) s[i] = ((k >> i) & 1) ? T(1) : T(-1);
  return point_at(b, s);
}

/// All 2^N corners, corner(b, k) at index k.
template <class T, int N>
[[nodiscard]] constexpr std::array<Vec<T, N>, (std::size_t{1} << N)> corners(
    const OrientedBox<T, N>& b) noexcept {
  std::array<Vec<T, N>, (std::size_t{1} << N)> c{};
  for (int k = 0; k < (1 << N); ++k) c[static_cast<std::size_t>(k)] = corner(b, k);
  return c;
}

/// N-dimensional volume 2^N prod extent[i]; NaN if an extent is negative.
template <class T, int N>
[[nodiscard]] constexpr T measure(const OrientedBox<T, N>& b) noexcept {
  T m = T(1);
  for (int i = 0; i < N; ++i) {
    if (b.extent[i] < T(0)) return std::numeric_limits<T>::quiet_NaN();
    m *= T(2) * b.extent[i];
  }
  return m;
}

/// Volume of a 3D box.
template <Real T>
[[nodiscard]] constexpr T volume(const OrientedBox3<T>& b) noexcept {
  return measure(b);
}

/// Area of a 2D box.
template <Real T>
[[nodiscard]] constexpr T area(const OrientedBox2<T>& b) noexcept {
  return measure(b);
}

/// Surface area 8 (e0 e1 + e1 e2 + e2 e0) of a 3D box; NaN if an extent is negative.
template <Real T>
[[nodiscard]] constexpr T surface_area(const OrientedBox3<T>& b) noexcept {
  const Vec3<T>& e = b.extent;
  if (e.x < T(0) || e.y < T(0) || e.z < T(0)) return std::numeric_limits<T>::quiet_NaN();
  return T(8) * (e.x * e.y + e.y * e.z + e.z * e.x);
}

/// The aligned box as an oriented box with the coordinate axes.
template <class T, int N>
[[nodiscard]] constexpr OrientedBox<T, N> oriented_box(const AlignedBox<T, N>& a) noexcept {
  OrientedBox<T, N> b{};
  b.center = center(a);
  for (int i = 0; i < N; ++i) b.axis[i] = unit_vec<T, N>(i);
  b.extent = extents(a);
  return b;
}

/// The box rotated by R about the coordinate origin: center R c, axes R a_i.
template <class T, int N>
[[nodiscard]] constexpr OrientedBox<T, N> rotated(const OrientedBox<T, N>& b,
                                                  const Mat<T, N, N>& r) noexcept {
  OrientedBox<T, N> o{};
  o.center = r * b.center;
  for (int i = 0; i < N; ++i) o.axis[i] = r * b.axis[i];
  o.extent = b.extent;
  return o;
}

/// The tight axis-aligned bounding box: center +- sum_j |axis_j| extent_j.
template <class T, int N>
[[nodiscard]] constexpr AlignedBox<T, N> bounding_box(const OrientedBox<T, N>& b) noexcept {
  Vec<T, N> h{};
  for (int j = 0; j < N; ++j) h += b.extent[j] * cwise_abs(b.axis[j]);
  return {b.center - h, b.center + h};
}

/// Centroid of the solid box (its center).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> centroid(const OrientedBox<T, N>& b) noexcept {
  return b.center;
}

}  // namespace locus
