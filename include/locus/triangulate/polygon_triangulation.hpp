// SPDX-License-Identifier: BSL-1.0
#pragma once
// The result shared by the polygon triangulations of this area (ear_clipping.hpp, monotone.hpp)
// and their input convention. CAPABILITIES row cg.triangulate; book section 13.9.
// Input: points and ring_ends; ring k is points[ring_ends[k-1] .. ring_ends[k]) (ring_ends[-1] =
// 0), closed implicitly (a repeated closing point is dropped), the layout of triangulate_polygon()
// in delaunay/constrained_delaunay2.hpp. Ring 0 is the outer boundary, rings 1.. are holes; any
// orientation (each ring is reoriented: outer counter-clockwise, holes clockwise).
// Output: triangles as indices into points, each counter-clockwise (orient2d > 0), the index
// layout of docs/notes/api.md.
// Status: ok; empty_input (no ring or no point); invalid_input (ring_ends not non-decreasing or
// past the end of points); non_finite_input (NaN/Inf in a ring); degenerate_input (the outer
// ring has zero area after the clean-up below: no triangles); invalid_topology (the rings are
// not a polygon with holes: detected self-intersection, crossing rings; the triangles are then a
// best effort that terminates, never presented as ok).
// Clean-up, decided exactly: consecutive equal points are merged; a zero-area spike (a, b, a'
// with a' on the ray from b through a) loses its tip; a hole left with fewer than 3 vertices is
// dropped. Whether straight runs keep their middle vertices is each algorithm's choice (its
// header says). Details: docs/notes/triangulate.md.

#include <locus/core/status.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace locus {

/// Triangles of a polygon with holes (see the top of the header).
struct PolygonTriangulation {
  Status status = Status::empty_input;
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into points, CCW

  [[nodiscard]] std::size_t triangle_count() const noexcept { return triangles.size(); }
};

}  // namespace locus
