// SPDX-License-Identifier: BSL-1.0
#pragma once
// Moving convex polygons in the plane by separating axes: the first time of contact and the
// contact set; row int2.sat-moving, book section 7.7.3, figures 7.17 (predicted contacts) and
// 7.18 (edge-edge contact of two moving triangles).
// Polygon a moves as a + t va, b as b + t vb (constant velocities), t in [0, tmax]. Inputs as in
// intersection/convex_polygon2.hpp: triangles, rectangles, oriented boxes (rounded corners) and
// convex vertex ranges in either orientation. first_contact() returns Contact2<T>: kind empty
// (no contact in [0, tmax]); point or segment, the contact set at `time` (vertex-vertex and
// vertex-edge contacts give a point, edge-edge contacts a segment, ends in lexicographic order);
// or polygon with count 0 when the interiors already overlap at time 0 (the overlap is
// intersection(a, b)). intersects(a, va, b, vb, tmax) is whether first_contact is not empty.
// Time 0 is decided exactly (the stationary test). Otherwise, for each candidate axis (the edge
// lines of both polygons; for segment-like or point-like polygons also the coordinate axes and
// the segment's direction) the projection gaps det[q - p; x - y] and the speed det[q - p; vb -
// va] are rounded once from their exact values (core/crossing.hpp turn2d_value) and divided; the
// extreme vertices along each axis are chosen exactly. Bound: the reported time t satisfies
// |t - t*| <= 5 eps t*, t* the exact first time of the same projection intervals, eps of T
// (computed in double; float adds one final rounding). Contact near a grazing pass or near tmax
// (exit time within that bound of the entry time, or entry within it of tmax) may be reported
// either way. An axis with exactly zero speed separates forever when its projections are apart
// (exact). Contact set: the extreme features of the axis of last entry, moved to `time` (rounded);
// the edge-edge overlap is decided on those rounded positions. NaN/Inf, tmax < 0 or NaN, or an
// empty polygon: kind empty. No allocation; O((n + m)^2) exact signs; src/intersection/sat2.cpp.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/rectangle.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <span>

namespace locus {

/// The first contact of two moving polygons (see the header comment).
template <Real T>
struct Contact2 {
  Kind kind = Kind::empty;         ///< empty, point, segment, or polygon (overlap at time 0)
  int count = 0;                   ///< entries of point: 0, 1 or 2
  T time = T(0);                   ///< the first time of contact in [0, tmax]
  std::array<Vec2<T>, 2> point{};  ///< the contact set at `time`
  /// True when the polygons meet during [0, tmax].
  [[nodiscard]] constexpr explicit operator bool() const noexcept { return kind != Kind::empty; }
};

namespace detail::sat2 {
/// src/intersection/sat2.cpp.
template <Real T>
[[nodiscard]] Contact2<T> first_contact(std::span<const Vec2<T>> a, const Vec2<T>& va,
                                        std::span<const Vec2<T>> b, const Vec2<T>& vb,
                                        T tmax) noexcept;
extern template Contact2<float> first_contact<float>(std::span<const Vec2<float>>,
                                                     const Vec2<float>&,
                                                     std::span<const Vec2<float>>,
                                                     const Vec2<float>&, float) noexcept;
extern template Contact2<double> first_contact<double>(std::span<const Vec2<double>>,
                                                       const Vec2<double>&,
                                                       std::span<const Vec2<double>>,
                                                       const Vec2<double>&, double) noexcept;
}  // namespace detail::sat2

/// First contact of convex polygons a + t va and b + t vb over [0, tmax].
template <Real T>
[[nodiscard]] inline Contact2<T> first_contact_convex_polygons(std::span<const Vec2<T>> a,
                                                               const Vec2<T>& va,
                                                               std::span<const Vec2<T>> b,
                                                               const Vec2<T>& vb, T tmax) noexcept {
  return detail::sat2::first_contact<T>(a, va, b, vb, tmax);
}

/// The same for any contiguous ranges of Vec2.
template <PointRange2 RA, PointRange2 RB>
requires std::same_as<range_point_t<RA>, range_point_t<RB>>
[[nodiscard]] inline Contact2<range_scalar_t<RA>> first_contact_convex_polygons(
    const RA& a, const range_point_t<RA>& va, const RB& b, const range_point_t<RA>& vb,
    range_scalar_t<RA> tmax) noexcept {
  return detail::sat2::first_contact<range_scalar_t<RA>>(point_span(a), va, point_span(b), vb,
                                                         tmax);
}

/// Whether moving convex polygons meet during [0, tmax].
template <PointRange2 RA, PointRange2 RB>
requires std::same_as<range_point_t<RA>, range_point_t<RB>>
[[nodiscard]] inline bool intersects_convex_polygons(const RA& a, const range_point_t<RA>& va,
                                                     const RB& b, const range_point_t<RA>& vb,
                                                     range_scalar_t<RA> tmax) noexcept {
  return detail::sat2::first_contact<range_scalar_t<RA>>(point_span(a), va, point_span(b), vb, tmax)
             .kind != Kind::empty;
}

/// First contact of two moving triangles.
template <Real T>
[[nodiscard]] inline Contact2<T> first_contact(const Triangle2<T>& a, const Vec2<T>& va,
                                               const Triangle2<T>& b, const Vec2<T>& vb,
                                               T tmax) noexcept {
  const auto pa = detail::sat2::vertices_of(a), pb = detail::sat2::vertices_of(b);
  return detail::sat2::first_contact<T>(pa, va, pb, vb, tmax);
}

/// First contact of two moving rectangles.
template <Real T>
[[nodiscard]] inline Contact2<T> first_contact(const Rectangle2<T>& a, const Vec2<T>& va,
                                               const Rectangle2<T>& b, const Vec2<T>& vb,
                                               T tmax) noexcept {
  const auto pa = corners(a), pb = corners(b);
  return detail::sat2::first_contact<T>(pa, va, pb, vb, tmax);
}

/// First contact of two moving oriented boxes.
template <Real T>
[[nodiscard]] inline Contact2<T> first_contact(const OrientedBox2<T>& a, const Vec2<T>& va,
                                               const OrientedBox2<T>& b, const Vec2<T>& vb,
                                               T tmax) noexcept {
  const auto pa = detail::sat2::cycle(a), pb = detail::sat2::cycle(b);
  return detail::sat2::first_contact<T>(pa, va, pb, vb, tmax);
}

/// Whether two moving triangles meet during [0, tmax].
template <Real T>
[[nodiscard]] inline bool intersects(const Triangle2<T>& a, const Vec2<T>& va,
                                     const Triangle2<T>& b, const Vec2<T>& vb, T tmax) noexcept {
  return first_contact(a, va, b, vb, tmax).kind != Kind::empty;
}

/// Whether two moving rectangles meet during [0, tmax].
template <Real T>
[[nodiscard]] inline bool intersects(const Rectangle2<T>& a, const Vec2<T>& va,
                                     const Rectangle2<T>& b, const Vec2<T>& vb, T tmax) noexcept {
  return first_contact(a, va, b, vb, tmax).kind != Kind::empty;
}

/// Whether two moving oriented boxes meet during [0, tmax].
template <Real T>
[[nodiscard]] inline bool intersects(const OrientedBox2<T>& a, const Vec2<T>& va,
                                     const OrientedBox2<T>& b, const Vec2<T>& vb, T tmax) noexcept {
  return first_contact(a, va, b, vb, tmax).kind != Kind::empty;
}

}  // namespace locus
