// SPDX-License-Identifier: BSL-1.0
#pragma once
// GeoJSON (RFC 7946) for 2D geometries (io/geometry.hpp). Compiled for float and double.
// Reading: parse_geojson(text) or read_geojson(path). The text is strict JSON (RFC 8259: no
// comments, trailing commas, NaN, leading '+' or zeros; strings valid with their escapes; an
// optional UTF-8 byte-order mark), nested at most 64 deep, read by a small tokenizer of our own.
// The top value is a FeatureCollection (its features in order), a Feature (its geometry) or a
// geometry: Point, MultiPoint, LineString, MultiLineString, Polygon, MultiPolygon or
// GeometryCollection (flattened into its members). A Feature whose geometry is null adds
// nothing. Members the format defines but locus does not use (properties, id, bbox, crs,
// foreign members) are checked as JSON and ignored; members may come in any order; a member
// that locus uses appearing twice is an error. "type" names are case-sensitive, as RFC 7946
// says. Positions: [x, y] or [x, y, z] (z dropped); 1 or 4+ numbers are errors. Empty
// "coordinates" arrays give the empty forms. Numbers are read correctly rounded to T.
// Rings: at least 4 positions, the last equal to the first (x and y, compared with ==), which is
// dropped; at least 3 distinct points; line strings at least 2 positions. Rings are reported
// in the orientation read (RFC 7946 asks for counter-clockwise outer rings but old files do
// not follow it; orient_rings() normalises).
// Errors: parse_error for bad JSON, truncated text, a wrong type or structure, unclosed rings,
// too few points; non_finite_input for a number overflowing T; both with line, column and
// byte offset (io/geometry.hpp). Memory: a token array of 32 bytes per JSON value plus
// the geometries, so proportional to the input; O(input) time.
// Writing: write_geojson_string(geometry) gives a geometry object; write_geojson_string(list)
// and write_geojson(path, list) a FeatureCollection with one Feature ("properties": null) per
// geometry. Rings are closed by repeating their first point; numbers in the shortest form that
// reads back exactly (std::to_chars), so a write-read round trip is bit-exact. Empty geometries
// are written with "coordinates": [] .

#include <locus/io/geometry.hpp>

#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace locus {

/// Reads the geometries of a GeoJSON text; name is used in messages.
template <Real T>
[[nodiscard]] GeometryReadResult<T> parse_geojson(std::string_view text,
                                                  std::string_view name = "<memory>");

/// Reads a GeoJSON file.
template <Real T>
[[nodiscard]] GeometryReadResult<T> read_geojson(const std::filesystem::path& path);

/// One geometry as a GeoJSON geometry object (result.data).
template <Real T>
[[nodiscard]] GeometryWriteResult write_geojson_string(const Geometry2<T>& geometry);

/// Geometries as a FeatureCollection (result.data).
template <Real T>
[[nodiscard]] GeometryWriteResult write_geojson_string(std::span<const Geometry2<T>> geometries);

/// Writes geometries to a file as a FeatureCollection.
template <Real T>
[[nodiscard]] GeometryWriteResult write_geojson(const std::filesystem::path& path,
                                                std::span<const Geometry2<T>> geometries);

/// The vector forms of the two above.
template <Real T>
[[nodiscard]] GeometryWriteResult write_geojson_string(const std::vector<Geometry2<T>>& list) {
  return write_geojson_string(std::span<const Geometry2<T>>(list));
}
template <Real T>
[[nodiscard]] GeometryWriteResult write_geojson(const std::filesystem::path& path,
                                                const std::vector<Geometry2<T>>& list) {
  return write_geojson(path, std::span<const Geometry2<T>>(list));
}

extern template GeometryReadResult<float> parse_geojson<float>(std::string_view, std::string_view);
extern template GeometryReadResult<double> parse_geojson<double>(std::string_view,
                                                                 std::string_view);
extern template GeometryReadResult<float> read_geojson<float>(const std::filesystem::path&);
extern template GeometryReadResult<double> read_geojson<double>(const std::filesystem::path&);
extern template GeometryWriteResult write_geojson_string(const Geometry2<float>&);
extern template GeometryWriteResult write_geojson_string(const Geometry2<double>&);
extern template GeometryWriteResult write_geojson_string(std::span<const Geometry2<float>>);
extern template GeometryWriteResult write_geojson_string(std::span<const Geometry2<double>>);
extern template GeometryWriteResult write_geojson(const std::filesystem::path&,
                                                  std::span<const Geometry2<float>>);
extern template GeometryWriteResult write_geojson(const std::filesystem::path&,
                                                  std::span<const Geometry2<double>>);

}  // namespace locus
