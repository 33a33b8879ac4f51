// SPDX-License-Identifier: BSL-1.0
#pragma once
// Rectangles in the plane and embedded in 3D (N = 2 or 3); row prim2.rectangle; book section
// 5.3, figures 5.6 (parametric form) and 5.7 (symmetric form).
//
// Symmetric form Rectangle<T, N> {center, axis[2], extent[2]} (fig 5.7): axis[0], axis[1] unit
// and orthogonal, extent[i] >= 0 the half side lengths; the point set is
// { center + s axis[0] + t axis[1] : |s| <= extent[0], |t| <= extent[1] } and
// point_at(rect, {s, t}) evaluates it. In 2D this is an oriented box.
//
// Parametric (corner-edge) form CornerRectangle<T, N> {corner, edge0, edge1} (fig 5.6): edge0
// and edge1 orthogonal, of any length; the point set is
// { corner + s edge0 + t edge1 : s, t in [0, 1] } and point_at(rect, {s, t}) evaluates it.
//
// Corner order: corners() lists (-,-), (+,-), (+,+), (-,+) in (s, t) signs, i.e. corner,
// corner + edge0, corner + edge0 + edge1, corner + edge1: counter-clockwise in 2D when
// perp_dot(axis[0], axis[1]) > 0 (right-handed axes), and counter-clockwise about
// cross(axis[0], axis[1]) in 3D.
//
// Degenerate input: the axes are not checked (orthonormality is the caller's contract;
// is_orthonormal() tests it with a tolerance). A zero extent or zero edge gives a rectangle that
// degenerates to a segment or a point; to_symmetric() then reports the zero edge with a zero
// axis and zero extent, and is_degenerate() is true. Conversions are rounded (normalisation).
// Cost O(N), no allocation.

#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cmath>

namespace locus {

/// Symmetric form: center, unit orthogonal axes, half side lengths (book fig 5.7).
template <class T, int N>
struct Rectangle {
  static_assert(N == 2 || N == 3, "locus: Rectangle is defined in 2D and 3D");
  Vec<T, N> center;
  Vec<T, N> axis[2];
  Vec2<T> extent;  ///< half side lengths along axis[0], axis[1] (a Vec, as in OrientedBox)
};

/// Parametric form: a corner and two orthogonal edge vectors (book fig 5.6).
template <class T, int N>
struct CornerRectangle {
  static_assert(N == 2 || N == 3, "locus: CornerRectangle is defined in 2D and 3D");
  Vec<T, N> corner;
  Vec<T, N> edge0;
  Vec<T, N> edge1;
};

template <Real T>
using Rectangle2 = Rectangle<T, 2>;
template <Real T>
using Rectangle3 = Rectangle<T, 3>;
using Rectangle2f = Rectangle2<float>;
using Rectangle2d = Rectangle2<double>;
using Rectangle3f = Rectangle3<float>;
using Rectangle3d = Rectangle3<double>;

/// center + s axis[0] + t axis[1] with st = (s, t), |s| <= extent[0], |t| <= extent[1].
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const Rectangle<T, N>& r, const Vec2<T>& st) noexcept {
  return r.center + st.x * r.axis[0] + st.y * r.axis[1];
}

/// corner + s edge0 + t edge1 with st = (s, t) in [0, 1]^2.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const CornerRectangle<T, N>& r,
                                           const Vec2<T>& st) noexcept {
  return r.corner + st.x * r.edge0 + st.y * r.edge1;
}

/// The four corners, counter-clockwise for right-handed axes (see the header comment).
template <class T, int N>
[[nodiscard]] constexpr std::array<Vec<T, N>, 4> corners(const Rectangle<T, N>& r) noexcept {
  const Vec<T, N> a = r.extent[0] * r.axis[0], b = r.extent[1] * r.axis[1];
  return {r.center - a - b, r.center + a - b, r.center + a + b, r.center - a + b};
}

/// The four corners corner, corner + edge0, corner + edge0 + edge1, corner + edge1.
template <class T, int N>
[[nodiscard]] constexpr std::array<Vec<T, N>, 4> corners(const CornerRectangle<T, N>& r) noexcept {
  return {r.corner, r.corner + r.edge0, r.corner + r.edge0 + r.edge1, r.corner + r.edge1};
}

/// 4 extent[0] extent[1].
template <class T, int N>
[[nodiscard]] constexpr T area(const Rectangle<T, N>& r) noexcept {
  return T(4) * r.extent[0] * r.extent[1];
}

/// |edge0| |edge1|.
template <class T, int N>
[[nodiscard]] inline T area(const CornerRectangle<T, N>& r) noexcept {
  return length(r.edge0) * length(r.edge1);
}

/// 4 (extent[0] + extent[1]).
template <class T, int N>
[[nodiscard]] constexpr T perimeter(const Rectangle<T, N>& r) noexcept {
  return T(4) * (r.extent[0] + r.extent[1]);
}

/// True when an extent is not positive or a value is not finite (the set is a segment, a point,
/// or undefined).
template <class T, int N>
[[nodiscard]] constexpr bool is_degenerate(const Rectangle<T, N>& r) noexcept {
  return !(r.extent[0] > T(0)) || !(r.extent[1] > T(0)) || !is_finite(r.extent[0]) ||
         !is_finite(r.extent[1]) || !is_finite(r.center) || !is_finite(r.axis[0]) ||
         !is_finite(r.axis[1]);
}

/// True when an edge is zero or a value is not finite.
template <class T, int N>
[[nodiscard]] constexpr bool is_degenerate(const CornerRectangle<T, N>& r) noexcept {
  return !is_finite(r.corner) || !is_finite(r.edge0) || !is_finite(r.edge1) ||
         r.edge0 == Vec<T, N>{} || r.edge1 == Vec<T, N>{};
}

/// True when the axes are unit length and orthogonal within tolerance `tol` (a dimensionless
/// bound on |axis_i . axis_j - delta_ij|; the default allows a few roundings).
template <class T, int N>
[[nodiscard]] inline bool is_orthonormal(const Rectangle<T, N>& r,
                                         T tol = T(16) * eps_v<T>) noexcept {
  return std::abs(dot(r.axis[0], r.axis[0]) - T(1)) <= tol &&
         std::abs(dot(r.axis[1], r.axis[1]) - T(1)) <= tol &&
         std::abs(dot(r.axis[0], r.axis[1])) <= tol;
}

/// Symmetric -> corner-edge form: corner = center - extent[0] axis[0] - extent[1] axis[1],
/// edge_i = 2 extent[i] axis[i].
template <class T, int N>
[[nodiscard]] constexpr CornerRectangle<T, N> to_corner_form(const Rectangle<T, N>& r) noexcept {
  const Vec<T, N> a = r.extent[0] * r.axis[0], b = r.extent[1] * r.axis[1];
  return {r.center - a - b, T(2) * a, T(2) * b};
}

/// Corner-edge -> symmetric form: center = corner + (edge0 + edge1) / 2, axis_i = unit edge_i,
/// extent_i = |edge_i| / 2. A zero edge gives a zero axis and a zero extent.
template <class T, int N>
[[nodiscard]] inline Rectangle<T, N> to_symmetric_form(const CornerRectangle<T, N>& r) noexcept {
  const Normalized<T, N> a = normalize_with_length(r.edge0), b = normalize_with_length(r.edge1);
  return {r.corner + T(0.5) * r.edge0 + T(0.5) * r.edge1,
          {a.dir, b.dir},
          {T(0.5) * a.length, T(0.5) * b.length}};
}

}  // namespace locus
