// SPDX-License-Identifier: BSL-1.0
#pragma once
// Line segments in N dimensions, endpoint and center-direction-extent forms; rows prim2.linear
// and prim3.linear; book section 5.1, figure 5.1(c).
//
// Endpoint form Segment<T, N> {p0, p1}: the point set { (1 - t) p0 + t p1 : t in [0, 1] }.
// point_at(seg, t) evaluates (1 - t) p0 + t p1 (mathematically p0 + t (p1 - p0)); this form is
// exact at t = 0 and t = 1, so the endpoints are reproduced bit for bit.
//
// Center-direction-extent form SegmentCDE<T, N> {center, direction, extent} (the "symmetric"
// form used by GTE and by separating-axis tests): { center + s * direction : s in [-extent,
// extent] } with a unit direction and extent >= 0 (half the length). point_at(cde, s) =
// center + s * direction.
//
// Degenerate input: a zero-length segment (p0 == p1) acts as the point p0 (library policy);
// to_cde() then gives direction = 0 and extent = 0, and direction()/unit_direction() give the
// zero vector. Non-finite coordinates propagate through the arithmetic (is_degenerate() reports
// them); nothing divides by zero. Conversions are rounded (the unit direction needs a sqrt).
// Cost O(N), no allocation.

#include <locus/config.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/line.hpp>

namespace locus {

/// The segment { (1 - t) p0 + t p1 : 0 <= t <= 1 } between p0 and p1.
template <class T, int N>
struct Segment {
  Vec<T, N> p0;
  Vec<T, N> p1;
  /// Endpoint i (0 or 1).
  [[nodiscard]] constexpr Vec<T, N>& operator[](int i) noexcept {
    LOCUS_ASSERT(i == 0 || i == 1, "Segment endpoint index out of range");
    return i == 0 ? p0 : p1;
  }
  [[nodiscard]] constexpr const Vec<T, N>& operator[](int i) const noexcept {
    LOCUS_ASSERT(i == 0 || i == 1, "Segment endpoint index out of range");
    return i == 0 ? p0 : p1;
  }
};

template <Real T>
using Segment2 = Segment<T, 2>;
template <Real T>
using Segment3 = Segment<T, 3>;
using Segment2f = Segment2<float>;
using Segment2d = Segment2<double>;
using Segment3f = Segment3<float>;
using Segment3d = Segment3<double>;

/// The segment { center + s * direction : -extent <= s <= extent }, unit direction, extent >= 0.
template <class T, int N>
struct SegmentCDE {
  Vec<T, N> center;
  Vec<T, N> direction;
  T extent;
};

template <Real T>
using SegmentCDE2 = SegmentCDE<T, 2>;
template <Real T>
using SegmentCDE3 = SegmentCDE<T, 3>;

/// (1 - t) p0 + t p1; exact at t = 0 and t = 1.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const Segment<T, N>& seg, T t) noexcept {
  return lerp(seg.p0, seg.p1, t);
}

/// center + s * direction, s in [-extent, extent].
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> point_at(const SegmentCDE<T, N>& seg, T s) noexcept {
  return seg.center + s * seg.direction;
}

/// True when the endpoints coincide (the segment is a point) or a coordinate is not finite.
template <class T, int N>
[[nodiscard]] constexpr bool is_degenerate(const Segment<T, N>& seg) noexcept {
  return !is_finite(seg.p0) || !is_finite(seg.p1) || seg.p0 == seg.p1;
}

/// The direction vector p1 - p0 (not normalised; its length is the segment's length).
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> direction(const Segment<T, N>& seg) noexcept {
  return seg.p1 - seg.p0;
}

/// (p1 - p0) / |p1 - p0|, or the zero vector for a zero-length segment.
template <class T, int N>
[[nodiscard]] inline Vec<T, N> unit_direction(const Segment<T, N>& seg) noexcept {
  return normalize(seg.p1 - seg.p0);
}

/// |p1 - p0| (overflow-safe, see locus::length).
template <class T, int N>
[[nodiscard]] inline T length(const Segment<T, N>& seg) noexcept {
  return length(seg.p1 - seg.p0);
}

/// |p1 - p0|^2.
template <class T, int N>
[[nodiscard]] constexpr T sqr_length(const Segment<T, N>& seg) noexcept {
  return sqr_length(seg.p1 - seg.p0);
}

/// (p0 + p1) / 2, computed as p0/2 + p1/2 so that it cannot overflow.
template <class T, int N>
[[nodiscard]] constexpr Vec<T, N> midpoint(const Segment<T, N>& seg) noexcept {
  return T(0.5) * seg.p0 + T(0.5) * seg.p1;
}

/// 2 * extent.
template <class T, int N>
[[nodiscard]] constexpr T length(const SegmentCDE<T, N>& seg) noexcept {
  return T(2) * seg.extent;
}

/// The line through p0 and p1 with direction p1 - p0, so point_at agrees with the segment's
/// parameter t (up to rounding of p0 + t (p1 - p0) versus (1 - t) p0 + t p1).
template <class T, int N>
[[nodiscard]] constexpr Line<T, N> supporting_line(const Segment<T, N>& seg) noexcept {
  return {seg.p0, seg.p1 - seg.p0};
}

/// Endpoint form -> center-direction-extent form. A zero-length segment gives the center p0,
/// direction 0 and extent 0.
template <class T, int N>
[[nodiscard]] inline SegmentCDE<T, N> to_cde(const Segment<T, N>& seg) noexcept {
  const Normalized<T, N> d = normalize_with_length(seg.p1 - seg.p0);
  return {midpoint(seg), d.dir, T(0.5) * d.length};
}

/// Center-direction-extent form -> endpoint form: p0 = center - extent * direction,
/// p1 = center + extent * direction.
template <class T, int N>
[[nodiscard]] constexpr Segment<T, N> to_segment(const SegmentCDE<T, N>& seg) noexcept {
  return {seg.center - seg.extent * seg.direction, seg.center + seg.extent * seg.direction};
}

}  // namespace locus
