// SPDX-License-Identifier: BSL-1.0
#pragma once
// Separating axes for convex polyhedra in 3D, stationary and moving; row int3.sat, book section
// 11.11 (convex polyhedra, triangles, boxes; contact sets). 2D versions: convex_polygon2.hpp,
// moving_convex2.hpp. Derivation: docs/notes/sat3.md.
// ConvexMesh3<T> is a view: `vertices` and `triangles` (index triples covering the boundary,
// any orientation), optional `edges` (index pairs; when empty, the triangles' edges). From points:
// {points, convex_hull(points).triangles} (hull/hull3.hpp); or a closed convex triangle mesh, or a
// triangulated flat polygon. The OBB and triangle overloads below go through the general code.
// Convexity is a precondition, not checked. Closed sets: touching counts as meeting.
// Axes: the normals of the triangles of both, the cross products of an edge of each (parallel
// edges are tested once), and, for two flat polyhedra in parallel planes, the in-plane edge
// normals.
// Exactness: every projection comparison is the exact sign of det[p1 - p0, q1 - q0, x - y] over
// input coordinates (a face normal (p1 - p0) x (q1 - q0) or an edge pair's cross product; a
// floating-point filter, then core/exact_sum.hpp), so intersects(a, b) is the exact answer for the
// given vertices: symmetric, invariant under power-of-two scaling and exact translations.
// first_contact(a, va, b, vb, tmax): a moves as a + t va, b as b + t vb, t in [0, tmax]. Sides at
// time 0, the speed signs and the extreme features are exact; entry times are rounded quotients
// (gap and speed each a rounded determinant: a relative error of a few eps unless they cancel),
// so contact within rounding of a grazing pass or of tmax may be reported either way. Contact3:
// kind empty (no contact), point / segment / polygon (the contact set at `time`: the intersection
// of the extreme features of the axis of last entry, clipped in 2D by convex_polygon2's exact
// clipper on the rounded moved features and lifted back to their plane: rounded), or
// `overlap` true (they meet at time 0 and no axis only touches: interiors overlap, or flat ones
// cross; kind empty, no points). intersection(a, b): points spanning the common part of a and b
// (ConvexOverlap3). Degenerate: a polyhedron without a non-degenerate triangle (empty, a point or a
// segment): intersects false, status degenerate_input. NaN/Inf: false, status non_finite_input;
// tmax < 0 or NaN: status invalid_input. Cost: O((Fa + Fb + Ea Eb)(Va + Vb)) filtered signs,
// stationary with early exit; allocates scratch. Compiled in src/intersection/sat3.cpp. OBB and
// triangle overloads below; the book's 15-axis OBB test is oriented_box_oriented_box.hpp.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/intersection/result.hpp>
#include <locus/primitives/oriented_box.hpp>
#include <locus/primitives/triangle.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// A convex polyhedron as a view of vertices, boundary triangles and optional edges.
template <Real T>
struct ConvexMesh3 {
  std::span<const Vec3<T>> vertices;
  std::span<const std::array<std::uint32_t, 3>> triangles;
  std::span<const std::array<std::uint32_t, 2>> edges{};  ///< empty: the triangles' edges
};

/// The first contact of two moving convex polyhedra (see the header comment).
template <Real T>
struct Contact3 {
  Status status = Status::ok;
  Kind kind = Kind::empty;      ///< empty, point, segment or polygon
  bool overlap = false;         ///< the interiors overlap at time 0 (no contact set given)
  T time = T(0);                ///< first time of contact in [0, tmax]
  std::vector<Vec3<T>> points;  ///< the contact set: 1, 2 or >= 3 vertices in order
  /// True when the polyhedra meet during [0, tmax].
  [[nodiscard]] explicit operator bool() const noexcept { return kind != Kind::empty || overlap; }
};

/// The common part of two convex polyhedra as points whose convex hull it is: vertices of each
/// inside the other and the crossings of the edges of each with the triangles of the other (all
/// its corners, plus boundary points where triangulation diagonals cross; see intersection()).
/// status ok, degenerate_input, non_finite_input or invalid_input.
template <Real T>
struct ConvexOverlap3 {
  Status status = Status::ok;
  bool intersects = false;
  std::vector<Vec3<T>> vertices;  ///< no exact duplicates; hull them for the faces
};

/// The stationary test with its status (see the header comment).
struct SatTest3 {
  Status status = Status::ok;
  bool intersects = false;
};

namespace detail::sat3 {
/// Exact sign of det[p1 - p0, q1 - q0, x - y] for finite doubles (src/intersection/sat3.cpp).
[[nodiscard]] int sign_det_diff(const Vec3<double>& p0, const Vec3<double>& p1,
                                const Vec3<double>& q0, const Vec3<double>& q1,
                                const Vec3<double>& x, const Vec3<double>& y) noexcept;
/// src/intersection/sat3.cpp.
template <Real T>
[[nodiscard]] SatTest3 test(const ConvexMesh3<T>& a, const ConvexMesh3<T>& b);
template <Real T>
[[nodiscard]] Contact3<T> first_contact(const ConvexMesh3<T>& a, const Vec3<T>& va,
                                        const ConvexMesh3<T>& b, const Vec3<T>& vb, T tmax);
template <Real T>
[[nodiscard]] ConvexOverlap3<T> overlap(const ConvexMesh3<T>& a, const ConvexMesh3<T>& b);
extern template ConvexOverlap3<float> overlap<float>(const ConvexMesh3<float>&,
                                                     const ConvexMesh3<float>&);
extern template ConvexOverlap3<double> overlap<double>(const ConvexMesh3<double>&,
                                                       const ConvexMesh3<double>&);
extern template SatTest3 test<float>(const ConvexMesh3<float>&, const ConvexMesh3<float>&);
extern template SatTest3 test<double>(const ConvexMesh3<double>&, const ConvexMesh3<double>&);
extern template Contact3<float> first_contact<float>(const ConvexMesh3<float>&, const Vec3<float>&,
                                                     const ConvexMesh3<float>&, const Vec3<float>&,
                                                     float);
extern template Contact3<double> first_contact<double>(const ConvexMesh3<double>&,
                                                       const Vec3<double>&,
                                                       const ConvexMesh3<double>&,
                                                       const Vec3<double>&, double);

/// The 12 triangles of a box or frustum whose corner k has bits (x, y, z) (OrientedBox, Frustum3).
inline constexpr std::array<std::array<std::uint32_t, 3>, 12> cube_triangles{{{0, 2, 6},
                                                                              {0, 6, 4},
                                                                              {1, 5, 7},
                                                                              {1, 7, 3},
                                                                              {0, 4, 5},
                                                                              {0, 5, 1},
                                                                              {2, 3, 7},
                                                                              {2, 7, 6},
                                                                              {0, 1, 3},
                                                                              {0, 3, 2},
                                                                              {4, 6, 7},
                                                                              {4, 7, 5}}};
/// Its 12 edges.
inline constexpr std::array<std::array<std::uint32_t, 2>, 12> cube_edges{{{0, 1},
                                                                          {2, 3},
                                                                          {4, 5},
                                                                          {6, 7},
                                                                          {0, 2},
                                                                          {1, 3},
                                                                          {4, 6},
                                                                          {5, 7},
                                                                          {0, 4},
                                                                          {1, 5},
                                                                          {2, 6},
                                                                          {3, 7}}};
inline constexpr std::array<std::array<std::uint32_t, 3>, 1> triangle_triangles{{{0, 1, 2}}};
}  // namespace detail::sat3

/// Whether two convex polyhedra meet (exact; see the header comment).
template <Real T>
[[nodiscard]] inline bool intersects(const ConvexMesh3<T>& a, const ConvexMesh3<T>& b) {
  return detail::sat3::test<T>(a, b).intersects;
}

/// The stationary test with a status (degenerate or non-finite input).
template <Real T>
[[nodiscard]] inline SatTest3 sat_test(const ConvexMesh3<T>& a, const ConvexMesh3<T>& b) {
  return detail::sat3::test<T>(a, b);
}

/// The intersection of two convex polyhedra as a point set (its convex hull, e.g. by
/// hull/hull3.hpp, is the common part of a and b): empty when they are disjoint (exact test). Which
/// input vertices are inside is exact (orient3d against every triangle of a solid); crossings come
/// from intersection(Segment3, Triangle3) (exact decisions, rounded points). Cost O(Ea Fb + Eb Fa).
template <Real T>
[[nodiscard]] inline ConvexOverlap3<T> intersection(const ConvexMesh3<T>& a,
                                                    const ConvexMesh3<T>& b) {
  return detail::sat3::overlap<T>(a, b);
}

/// First contact of convex polyhedra a + t va and b + t vb over [0, tmax].
template <Real T>
[[nodiscard]] inline Contact3<T> first_contact(const ConvexMesh3<T>& a, const Vec3<T>& va,
                                               const ConvexMesh3<T>& b, const Vec3<T>& vb, T tmax) {
  return detail::sat3::first_contact<T>(a, va, b, vb, tmax);
}

/// Whether moving convex polyhedra meet during [0, tmax].
template <Real T>
[[nodiscard]] inline bool intersects(const ConvexMesh3<T>& a, const Vec3<T>& va,
                                     const ConvexMesh3<T>& b, const Vec3<T>& vb, T tmax) {
  return static_cast<bool>(detail::sat3::first_contact<T>(a, va, b, vb, tmax));
}

/// A box's (or frustum's) corners as a polyhedron; `corners` must outlive the view. Each face is
/// split along a fixed diagonal: rounded corners may leave a face's four corners off one plane by
/// a rounding error, and the exact answers are then those of this triangulated solid.
template <Real T>
[[nodiscard]] inline ConvexMesh3<T> box_polyhedron(const std::array<Vec3<T>, 8>& corners) noexcept {
  return {corners, detail::sat3::cube_triangles, detail::sat3::cube_edges};
}

/// First contact of two moving oriented boxes (over their rounded corners; contact set included).
template <Real T>
[[nodiscard]] inline Contact3<T> first_contact(const OrientedBox3<T>& a, const Vec3<T>& va,
                                               const OrientedBox3<T>& b, const Vec3<T>& vb,
                                               T tmax) {
  const auto ca = corners(a), cb = corners(b);
  return detail::sat3::first_contact<T>(box_polyhedron(ca), va, box_polyhedron(cb), vb, tmax);
}

/// Whether two moving oriented boxes meet during [0, tmax].
template <Real T>
[[nodiscard]] inline bool intersects(const OrientedBox3<T>& a, const Vec3<T>& va,
                                     const OrientedBox3<T>& b, const Vec3<T>& vb, T tmax) {
  return static_cast<bool>(first_contact(a, va, b, vb, tmax));
}

/// First contact of two moving triangles (flat polyhedra; a degenerate triangle: status
/// degenerate_input, no contact).
template <Real T>
[[nodiscard]] inline Contact3<T> first_contact(const Triangle3<T>& a, const Vec3<T>& va,
                                               const Triangle3<T>& b, const Vec3<T>& vb, T tmax) {
  const std::array<Vec3<T>, 3> pa{a.v0, a.v1, a.v2}, pb{b.v0, b.v1, b.v2};
  const ConvexMesh3<T> ha{pa, detail::sat3::triangle_triangles},
      hb{pb, detail::sat3::triangle_triangles};
  return detail::sat3::first_contact<T>(ha, va, hb, vb, tmax);
}

/// Whether two moving triangles meet during [0, tmax].
template <Real T>
[[nodiscard]] inline bool intersects(const Triangle3<T>& a, const Vec3<T>& va,
                                     const Triangle3<T>& b, const Vec3<T>& vb, T tmax) {
  return static_cast<bool>(first_contact(a, va, b, vb, tmax));
}

}  // namespace locus
