// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internals shared by the WKT and GeoJSON readers and writers (src/io/wkt.cpp, geojson.cpp):
// failures with a byte offset, the ring and line checks both formats make, file access. Not
// installed.

#include <locus/io/geometry.hpp>

#include "mesh_detail.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace locus::geo_io {

using mesh_io::append_real;
using mesh_io::NumberError;
using mesh_io::parse_real;
using mesh_io::quote;

// The most points one polygon can hold (ring_ends are uint32).
inline constexpr std::size_t max_points = std::numeric_limits<std::uint32_t>::max();

/// What went wrong and where (a byte offset into the text).
struct Failure {
  Status status = Status::ok;
  std::string reason;
  std::size_t offset = 0;
};

/// Records the first failure; always returns false so that callers can `return fail(...)`.
class Errors {
 public:
  bool fail(Status s, std::size_t offset, std::string reason) {
    if (failure.status == Status::ok) failure = Failure{s, std::move(reason), offset};
    return false;
  }
  Failure failure;
};

/// The result of a reader: the failure (if any) located by line and column in the text.
template <Real T>
GeometryReadResult<T> finish(const Failure& f, std::string_view text, std::string_view name,
                             std::vector<Geometry2<T>>&& geometries) {
  GeometryReadResult<T> r;
  r.status = f.status;
  if (f.status == Status::ok) {
    r.geometries = std::move(geometries);
    return r;
  }
  const std::size_t offset = f.offset < text.size() ? f.offset : text.size();
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  r.line = line;
  r.column = offset - line_start + 1;
  r.byte_offset = offset;
  r.message = std::string(name) + ':' + std::to_string(r.line) + ':' + std::to_string(r.column) +
              ": " + f.reason;
  return r;
}

/// Checks the points of a ring just read (closing point included) and drops the closing point.
/// Returns the reason it is not a ring, or nullptr.
template <Real T>
const char* close_ring(std::vector<Vec2<T>>& points, std::size_t begin) {
  const std::size_t n = points.size() - begin;
  if (n < 4) return "a ring needs at least 4 points (the last repeating the first)";
  if (!(points[begin] == points.back())) return "ring not closed (last point differs from first)";
  points.pop_back();
  // At least three distinct points: a second point unlike the first, a third unlike both.
  const Vec2<T> a = points[begin];
  std::size_t i = begin + 1;
  while (i < points.size() && points[i] == a) ++i;
  if (i == points.size()) return "a ring needs at least 3 distinct points";
  const Vec2<T> b = points[i];
  while (i < points.size() && (points[i] == a || points[i] == b)) ++i;
  if (i == points.size()) return "a ring needs at least 3 distinct points";
  return nullptr;
}

/// Writes text to a file; false when it cannot be written.
bool write_file(const std::filesystem::path& path, std::string_view text);

/// io_error result for an unreadable file.
template <Real T>
GeometryReadResult<T> unreadable(const std::filesystem::path& path, std::string_view reason) {
  GeometryReadResult<T> r;
  r.status = Status::io_error;
  r.message = path.string() + ": " + std::string(reason);
  return r;
}

/// The message of a geometry that cannot be written (check_geometry() said why).
[[nodiscard]] const char* write_refusal(Status s) noexcept;

}  // namespace locus::geo_io
