// SPDX-License-Identifier: BSL-1.0
#pragma once
// 2D geometries as exchanged by the WKT and GeoJSON readers and writers (io/wkt.hpp,
// io/geojson.hpp): points, line strings, polygons with holes and their multi- forms (the
// OGC simple-features types; a GeometryCollection is flattened into a list of these).
// RingPolygon2<T> {points, ring_ends}: ring k is points[ring_ends[k-1] .. ring_ends[k])
// (ring_ends[-1] = 0), closed implicitly, the closing point NOT repeated: the input layout of
// the polygon triangulations (triangulate/polygon_triangulation.hpp) and of
// triangulate_polygon() (delaunay/constrained_delaunay2.hpp). Ring 0 is the outer boundary,
// rings 1.. are holes. A multipolygon is a vector of them.
// Orientation: the readers report rings as written (WKT and GeoJSON disagree on the winding
// and files disagree with both); orient_rings() makes the outer ring counter-clockwise and the
// holes clockwise, by the exact orientation at each ring's lowest vertex (polygon_orientation,
// primitives/polygon.hpp); a ring of orientation zero (collinear, spike) is left as it is.
// Validity beyond what a file format requires (simple rings, holes inside the outer ring) is
// not checked here: see polygon_is_simple() and the triangulators' statuses.
// Empty forms: a Geometry2 may hold no part (POINT EMPTY, "coordinates": []); empty() says so.
// Conversions to and from PolygonWithHoles2<T> (outer + holes) are lossless.
// GeometryReadResult: status ok, empty_input (no geometry text at all), parse_error (with the
// reason and position: 1-based line and column in bytes, byte offset) or non_finite_input (a
// NaN, infinite or overflowing coordinate: its position), io_error (unreadable file); message =
// "name:line:column: reason". GeometryWriteResult: non_finite_input or invalid_input (a ring
// of fewer than 3 distinct points, a line of fewer than 2 points, ring_ends not increasing or
// not ending at the last point, several parts in a single geometry) when it cannot be written.
// Format notes (closing vertices, dimensions, precision): docs/notes/io.md.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/primitives/polygon.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace locus {

/// The simple-features geometry types (2D).
enum class GeometryType : std::uint8_t {
  point,
  line_string,
  polygon,
  multi_point,
  multi_line_string,
  multi_polygon,
};

/// A polygon with holes as rings over one point array (see the header comment).
template <Real T>
struct RingPolygon2 {
  std::vector<Vec2<T>> points;
  std::vector<std::uint32_t> ring_ends;  ///< end of each ring in points; ring 0 is the outer one
};

/// One geometry; only the member matching its type is used.
template <Real T>
struct Geometry2 {
  GeometryType type = GeometryType::point;
  std::vector<Vec2<T>> points;              ///< point (0 or 1 entries), multi_point
  std::vector<std::vector<Vec2<T>>> lines;  ///< line_string (0 or 1 entries), multi_line_string
  std::vector<RingPolygon2<T>> polygons;    ///< polygon (0 or 1 entries), multi_polygon

  /// True for the empty forms (no point, line or polygon of its type).
  [[nodiscard]] bool empty() const noexcept {
    switch (type) {
      case GeometryType::point:
      case GeometryType::multi_point:
        return points.empty();
      case GeometryType::line_string:
      case GeometryType::multi_line_string:
        return lines.empty();
      case GeometryType::polygon:
      case GeometryType::multi_polygon:
        return polygons.empty();
    }
    return true;
  }
};

template <Real T>
struct GeometryReadResult {
  Status status = Status::empty_input;
  std::string message;                   ///< empty when ok; else "name:line:column: reason"
  std::size_t line = 0;                  ///< 1-based line of the error, 0 when ok
  std::size_t column = 0;                ///< 1-based column (in bytes) of the error, 0 when ok
  std::size_t byte_offset = 0;           ///< offset of the error from the start of the input
  std::vector<Geometry2<T>> geometries;  ///< in file order (unspecified unless status == ok)
};

struct GeometryWriteResult {
  Status status = Status::empty_input;
  std::string message;  ///< empty when ok
  std::string data;     ///< the text (the *_string writers only)
};

/// The name of a type as WKT spells it ("POINT", "MULTIPOLYGON", ...).
[[nodiscard]] const char* wkt_name(GeometryType type) noexcept;

/// Makes ring 0 counter-clockwise and every other ring clockwise (see the header comment).
template <Real T>
void orient_rings(RingPolygon2<T>& polygon) noexcept;

/// orient_rings() on every polygon of the geometry.
template <Real T>
void orient_rings(Geometry2<T>& geometry) noexcept;

/// The polygon as outer + holes (ring ends past the points or decreasing are clamped).
template <Real T>
[[nodiscard]] PolygonWithHoles2<T> to_polygon_with_holes(const RingPolygon2<T>& polygon);

/// The polygon as rings over one point array.
template <Real T>
[[nodiscard]] RingPolygon2<T> to_ring_polygon(const PolygonWithHoles2<T>& polygon);

/// invalid_input, non_finite_input or ok: whether the geometry can be written (see above).
template <Real T>
[[nodiscard]] Status check_geometry(const Geometry2<T>& geometry) noexcept;

extern template void orient_rings<float>(RingPolygon2<float>&) noexcept;
extern template void orient_rings<double>(RingPolygon2<double>&) noexcept;
extern template void orient_rings<float>(Geometry2<float>&) noexcept;
extern template void orient_rings<double>(Geometry2<double>&) noexcept;
extern template PolygonWithHoles2<float> to_polygon_with_holes(const RingPolygon2<float>&);
extern template PolygonWithHoles2<double> to_polygon_with_holes(const RingPolygon2<double>&);
extern template RingPolygon2<float> to_ring_polygon(const PolygonWithHoles2<float>&);
extern template RingPolygon2<double> to_ring_polygon(const PolygonWithHoles2<double>&);
extern template Status check_geometry(const Geometry2<float>&) noexcept;
extern template Status check_geometry(const Geometry2<double>&) noexcept;

}  // namespace locus
