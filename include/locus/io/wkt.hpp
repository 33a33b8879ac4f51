// SPDX-License-Identifier: BSL-1.0
#pragma once
// Well-known text (OGC simple features, ISO 13249-3) for 2D geometries (io/geometry.hpp):
// POINT, LINESTRING, POLYGON, MULTIPOINT, MULTILINESTRING, MULTIPOLYGON and GEOMETRYCOLLECTION
// (flattened into its members, nesting at most 32 deep). Compiled for float and double.
// Reading: parse_wkt(text) or read_wkt(path): one or more geometries separated by white space
// (a file with one geometry per line reads as a list). Keywords in any case; spaces, tabs, LF
// and CRLF anywhere between tokens; an optional UTF-8 byte-order mark. EMPTY wherever a
// geometry or a member may stand (empty members of a multi- geometry and EMPTY rings are
// dropped). MULTIPOINT members with or without parentheses. LINEARRING (JTS) reads as a
// LINESTRING, its points as written.
// Dimensions: "Z", "M", "ZM" (also attached: POINTZ) announce 3, 3, 4 numbers per point, of
// which x and y are kept; without a keyword every point of a geometry has 2, 3 or 4 numbers
// (the same count throughout), extra ones dropped. Coordinates are read correctly rounded to T.
// Rings: the closing point must repeat the first (x and y equal) and is dropped; a ring
// needs at least 3 distinct points, a line string at least 2 points. Rings keep the orientation
// they were written in (orient_rings() normalises). SRID=n; (EWKT) and other keywords
// (CIRCULARSTRING, TIN, ...) are parse errors naming the word.
// Errors: parse_error for malformed, truncated or unknown text, unclosed rings, too few points,
// more than 2^32 - 1 points; non_finite_input for NaN, inf or a number overflowing T; both
// with line, column and byte offset (io/geometry.hpp). Memory is proportional to the input;
// O(input) time; the parser is iterative (no recursion on the input's nesting).
// Writing: write_wkt_string(geometry) gives canonical text ("POLYGON ((0 0, 1 0, 0 1, 0 0))",
// "POINT EMPTY"), rings closed by repeating the first point, numbers in the shortest form that
// reads back exactly (std::to_chars), so a write-read round trip is bit-exact (-0 included).
// write_wkt(path, geometries) writes one geometry per line.

#include <locus/io/geometry.hpp>

#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace locus {

/// Reads the geometries of a WKT text; name is used in messages.
template <Real T>
[[nodiscard]] GeometryReadResult<T> parse_wkt(std::string_view text,
                                              std::string_view name = "<memory>");

/// Reads a WKT file.
template <Real T>
[[nodiscard]] GeometryReadResult<T> read_wkt(const std::filesystem::path& path);

/// The WKT of one geometry (result.data, no line end).
template <Real T>
[[nodiscard]] GeometryWriteResult write_wkt_string(const Geometry2<T>& geometry);

/// Writes geometries to a file, one per line.
template <Real T>
[[nodiscard]] GeometryWriteResult write_wkt(const std::filesystem::path& path,
                                            std::span<const Geometry2<T>> geometries);

/// The vector form of the above.
template <Real T>
[[nodiscard]] GeometryWriteResult write_wkt(const std::filesystem::path& path,
                                            const std::vector<Geometry2<T>>& list) {
  return write_wkt(path, std::span<const Geometry2<T>>(list));
}

extern template GeometryReadResult<float> parse_wkt<float>(std::string_view, std::string_view);
extern template GeometryReadResult<double> parse_wkt<double>(std::string_view, std::string_view);
extern template GeometryReadResult<float> read_wkt<float>(const std::filesystem::path&);
extern template GeometryReadResult<double> read_wkt<double>(const std::filesystem::path&);
extern template GeometryWriteResult write_wkt_string(const Geometry2<float>&);
extern template GeometryWriteResult write_wkt_string(const Geometry2<double>&);
extern template GeometryWriteResult write_wkt(const std::filesystem::path&,
                                              std::span<const Geometry2<float>>);
extern template GeometryWriteResult write_wkt(const std::filesystem::path&,
                                              std::span<const Geometry2<double>>);

}  // namespace locus
