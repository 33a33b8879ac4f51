// SPDX-License-Identifier: BSL-1.0
#pragma once
// Axis-aligned boxes in N dimensions (AABB); row prim3.solids (and the 2D aligned rectangle);
// the solid primitives the book uses in chapters 10-11 and the bounding boxes of chapter 13.
//
// AlignedBox<T, N> {min, max} is the closed set { X : min[i] <= X[i] <= max[i] for all i }.
// Empty-box convention: a box is empty when min[i] > max[i] for some i (or a bound is NaN);
// empty_box<T, N>() returns {+inf, -inf}, the identity of merge() and expand(), so bounding
// boxes are accumulated from it. A box with min == max is a single point (not empty).
//
// Parametrisation: point_at(box, p) = min + p (.) (max - min) component-wise, p in [0, 1]^N
// (p[i] = 0 gives min[i], 1 gives max[i] exactly). Corner k (0 <= k < 2^N) takes max[i] where
// bit i of k is set and min[i] elsewhere, so corner 0 is min and corner 2^N - 1 is max.
//
// Measures: measure() is the N-dimensional volume (length, area, volume), 0 for an empty box;
// surface_area() (N = 3) is 2 (xy + yz + zx); perimeter() (N = 2). center() and extents()
// (half the side lengths) describe the symmetric form used by oriented_box.hpp.
//
// Degenerate input: NaN coordinates of points passed to bounding_box()/expand() are skipped
// (comparisons with NaN are false); infinite coordinates are kept. Measures of an empty box are
// 0; center() and extents() of an empty box are meaningless (they are computed as written).
// Everything is O(N) (corners O(N 2^N)); no allocation.

#include <locus/config.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstddef>
#include <limits>
#include <span>

namespace locus {

/// The axis-aligned box { X : min <= X <= max component-wise }.
template <class T, int N>
struct AlignedBox {
  Vec<T, N> min;
  Vec<T, N> max;
};

template <Real T>
using AlignedBox2 = AlignedBox<T, 2>;
template <Real T>
using AlignedBox3 = AlignedBox<T, 3>;
using AlignedBox2f = AlignedBox2<float>;
using AlignedBox2d = AlignedBox2<double>;
using AlignedBox3f = AlignedBox3<float>;
using AlignedBox3d = AlignedBox3<double>;

/// The empty box {+inf, -inf}: the identity of merge() and expand().
template <class T, int N>
[[nodiscard]] constexpr AlignedBox<T, N> empty_box() noexcept {
  return {splat<T, N>(std::numeric_limits<T>::infinity()),
          splat<T, N>(-std::numeric_limits<T>::infinity())};
}

/// True when min[i] <= max[i] fails for some i (including NaN bounds).
template <class T, int N>
[[nodiscard]] constexpr bool is_empty(const AlignedBox<T, N>& b) noexcept {
  for (int i = 0; i < N; ++i)
    if (!(b.min[i] <= b.max[i])) return true;
  return false;
}

/// The smallest box containing a and p.
template <class T, int N>
[[nodiscard]] constexpr AlignedBox<T, N> expand(const AlignedBox<T, N>& b,
                                                const Vec<T, N>& p) noexcept {
  return {cwise_min(b.min, p), cwise_max(b.max, p)};
}

/// The smallest box containing a and b (an empty operand is ignored).
template <class T, int N>
[[nodiscard]] constexpr AlignedBox<T, N> merge(const AlignedBox<T, N>& a,
                                               const AlignedBox<T, N>& b) noexcept {
  if (is_empty(a)) return b;
  if (is_empty(b)) return a;
  return {cwise_min(a.min, b.min), cwise_max(a.max, b.max)};
}

/// The box grown by margin on every side (shrunk for margin < 0; may become empty).
template <class T, int N>
[[nodiscard]] constexpr AlignedBox<T, N> inflate(const AlignedBox<T, N>& b, T margin) noexcept {
  return {b.min - splat<T, N>(margin), b.max + splat<T, N>(margin)};
}

/// The bounding box of the points (the empty box for no points; NaN coordinates skipped).
template <class T, int N>
[[nodiscard]] constexpr AlignedBox<T, N> bounding_box(std::span<const Vec<T, N>> pts) noexcept {
  AlignedBox<T, N> b = empty_box<T, N>();
  for (const auto& p : pts) b = expand(b, p);
  return b;
}

/// The same for any point range (core/point_range.hpp).
template <PointRange R>
[[nodiscard]] constexpr AlignedBox<range_scalar_t<R>, range_dimension_v<R>> bounding_box(
    const R& pts) noexcept {
  return bounding_box(point_span(pts));
}

/// The bounding box of n points starting at pts.
template <class T, int N>
[[nodiscard]] constexpr AlignedBox<T, N> bounding_box(const Vec<T, N>* pts,
                                                      std::size_t n) noexcept {
  return bounding_box(std::span<const Vec<T, N>>(pts, n));
}

/// (min + max) / 2, halved first so that it cannot overflow.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> center(const AlignedBox<T, N>& b) noexcept {
  return b.min * T(0.5) + b.max * T(0.5);
}

/// Side lengths max - min.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> size(const AlignedBox<T, N>& b) noexcept {
  return b.max - b.min;
}

/// Half side lengths (max - min) / 2.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> extents(const AlignedBox<T, N>& b) noexcept {
  return (b.max - b.min) * T(0.5);
}

/// N-dimensional volume (product of the side lengths); 0 for an empty box.
template <class T, int N>
[[nodiscard]] constexpr T measure(const AlignedBox<T, N>& b) noexcept {
  if (is_empty(b)) return T(0);
  T m = T(1);
  for (int i = 0; i < N; ++i) m *= b.max[i] - b.min[i];
  return m;
}

/// Volume of a 3D box; 0 when empty.
template <Real T>
[[nodiscard]] constexpr T volume(const AlignedBox3<T>& b) noexcept {
  return measure(b);
}

/// Area of a 2D box; 0 when empty.
template <Real T>
[[nodiscard]] constexpr T area(const AlignedBox2<T>& b) noexcept {
  return measure(b);
}

/// Perimeter of a 2D box; 0 when empty.
template <Real T>
[[nodiscard]] constexpr T perimeter(const AlignedBox2<T>& b) noexcept {
  if (is_empty(b)) return T(0);
  return T(2) * ((b.max.x - b.min.x) + (b.max.y - b.min.y));
}

/// Surface area 2 (xy + yz + zx) of a 3D box; 0 when empty.
template <Real T>
[[nodiscard]] constexpr T surface_area(const AlignedBox3<T>& b) noexcept {
  if (is_empty(b)) return T(0);
  const Vec3<T> s = size(b);
  return T(2) * (s.x * s.y + s.y * s.z + s.z * s.x);
}

/// Corner k: max[i] where bit i of k is set, min[i] elsewhere (0 <= k < 2^N).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> corner(const AlignedBox<T, N>& b, int k) noexcept {
  LOCUS_ASSERT(k >= 0 && k < (1 << N), "AlignedBox corner index out of range");
  Vec<T, N> p{};
  for (int i = 0; i < N; ++i) p[i] = ((k >> i) & 1) ? b.max[i] : b.min[i];
  return p;
}

/// All 2^N corners, corner(b, k) at index k.
template <class T, int N>
[[nodiscard]] constexpr std::array<Vec<T, N>, (std::size_t{1} << N)> corners(
    const AlignedBox<T, N>& b) noexcept {
  std::array<Vec<T, N>, (std::size_t{1} << N)> c{};
  for (int k = 0; k < (1 << N); ++k) c[static_cast<std::size_t>(k)] = corner(b, k);
  return c;
}

/// min + p (.) (max - min) with p in [0, 1]^N; exact at p[i] = 0 and 1.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const AlignedBox<T, N>& b, const Vec<T, N>& p) noexcept {
  Vec<T, N> r{};
  for (int i = 0; i < N; ++i) r[i] = (T(1) - p[i]) * b.min[i] + p[i] * b.max[i];
  return r;
}

/// Centroid of the solid box (its center).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> centroid(const AlignedBox<T, N>& b) noexcept {
  return center(b);
}

}  // namespace locus
