// SPDX-License-Identifier: BSL-1.0
#pragma once
// Point lists: read and write 2D and 3D points as CSV or XYZ text (row mesh.io, CSV/XYZ part).
// Compiled once for float and double, N = 2 and 3; reading also N = 6 (CSV rows of six
// numbers, e.g. rays ox,oy,oz,dx,dy,dz).
//
// CSV (.csv .txt .tsv): one point per line, exactly N fields. The separator is fixed by the
// first non-blank line: ';' if it holds one, else ',' if it holds one, else runs of whitespace
// (spaces, tabs). Fields are trimmed and may be wrapped in one pair of double quotes; an empty
// field is an error; decimal commas are not supported. The first line is a header, skipped,
// when none of its fields is a number. XYZ (.xyz): the point-cloud format, whitespace-separated
// x y z on each line; further columns (colours, normals, intensity) are ignored unread; no
// header; 3D only (reading 2D points from XYZ is invalid_input). Not the chemistry .xyz format.
// Both: LF or CRLF line ends, '#' starts a comment to the end of the line, blank lines skipped.
// Numbers: decimal or scientific, correctly rounded to T (std::from_chars; a leading '+' is
// allowed); an underflow gives a signed zero.
// Errors: parse_error (a bad or missing field, a wrong field count, a NUL byte, a NaN, infinite
// or overflowing coordinate, more than 2^32 - 1 points), io_error (unreadable file) or
// invalid_input (unknown format, XYZ asked for 2D); message = "name:line: reason", line set.
// Empty input (no data line) is ok with no points. Memory: the points read (at most 4 times the
// input size for double; no size is ever taken from the file); time O(input).
// point_list_dimension(): the number of fields of the first data line (CSV; 3 for XYZ with 3 or
// more columns), 0 when there is none, to pick N before reading.
// Writing (a span, or any point range of core/point_range.hpp): CSV with a header "x,y[,z]" and
// comma-separated rows, XYZ as "x y z" rows; numbers in the shortest form that reads back
// exactly (std::to_chars), so a round trip is bit-exact (-0.0 stays -0.0). A non-finite point is
// refused (non_finite_input), as is XYZ for 2D points.

#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace locus {

/// A point-list file format.
enum class PointListFormat : std::uint8_t {
  from_extension,  ///< from the file name: .csv .txt .tsv -> csv, .xyz -> xyz (any case)
  csv,
  xyz,
};

template <Real T, int N>
struct PointListReadResult {
  Status status = Status::empty_input;
  std::string message;          ///< empty when ok; else "name:line: reason"
  std::size_t line = 0;         ///< 1-based line of the error, 0 when none
  std::size_t byte_offset = 0;  ///< offset of the start of that line
  std::vector<Vec<T, N>> points;
};

struct PointListWriteResult {
  Status status = Status::empty_input;
  std::string message;  ///< empty when ok
  std::string data;     ///< the file's bytes (write_points_string only)
};

/// The format a file name's extension names, or from_extension when it names none.
[[nodiscard]] PointListFormat point_list_format_from_name(std::string_view name) noexcept;

/// Fields on the first data line (see the header comment); 0 when there is none.
[[nodiscard]] int point_list_dimension(std::string_view bytes, PointListFormat format) noexcept;

/// Reads a point-list file.
template <Real T, int N>
[[nodiscard]] PointListReadResult<T, N> read_points(
    const std::filesystem::path& path, PointListFormat format = PointListFormat::from_extension);

/// Reads points from memory; name is used in messages and, with from_extension, for the format.
template <Real T, int N>
[[nodiscard]] PointListReadResult<T, N> parse_points(std::string_view bytes, PointListFormat format,
                                                     std::string_view name = "<memory>");

/// Writes a point-list file (status io_error when it cannot be written).
template <Real T, int N>
[[nodiscard]] PointListWriteResult write_points(
    const std::filesystem::path& path, std::span<const Vec<T, N>> points,
    PointListFormat format = PointListFormat::from_extension);

/// The bytes of a point-list file (result.data); format must name one (not from_extension).
template <Real T, int N>
[[nodiscard]] PointListWriteResult write_points_string(std::span<const Vec<T, N>> points,
                                                       PointListFormat format);

/// The same for any 2D or 3D point range (core/point_range.hpp), without template arguments.
template <PointRange R>
requires(range_dimension_v<R> == 2 || range_dimension_v<R> == 3) [[nodiscard]] PointListWriteResult
    write_points(const std::filesystem::path& path, const R& points,
                 PointListFormat format = PointListFormat::from_extension) {
  return write_points<range_scalar_t<R>, range_dimension_v<R>>(path, point_span(points), format);
}
template <PointRange R>
requires(range_dimension_v<R> == 2 || range_dimension_v<R> == 3) [[nodiscard]] PointListWriteResult
    write_points_string(const R& points, PointListFormat format) {
  return write_points_string<range_scalar_t<R>, range_dimension_v<R>>(point_span(points), format);
}

}  // namespace locus
