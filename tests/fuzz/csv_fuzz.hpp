// SPDX-License-Identifier: BSL-1.0
#pragma once
// The property the point-list reader is fuzzed for (tests/fuzz/csv_fuzz.cpp) and that
// tests/io/point_list_test.cpp replays on every committed input: reading any bytes as CSV (2D
// and 3D) and XYZ, as float and as double, returns (no crash, hang or huge allocation; the
// sanitizers and libFuzzer's limits catch those); an error is a parse_error with a message
// naming a line of the input; ok points are finite, and writing them back and reading that
// gives the same points bit for bit.

#include <locus/io/point_list.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace locus_fuzz {

template <class T, int N>
std::string check_points_reader(locus::PointListFormat format, std::string_view bytes) {
  using locus::Status;
  const auto r = locus::parse_points<T, N>(bytes, format, "fuzz");
  if (r.status != Status::ok) {
    if (r.status != Status::parse_error) return "error other than parse_error";
    if (r.message.rfind("fuzz:" + std::to_string(r.line) + ": ", 0) != 0) {
      return "message does not start with name:line";
    }
    const std::size_t lines = std::size_t(std::count(bytes.begin(), bytes.end(), '\n')) + 1;
    if (r.line < 1 || r.line > lines) return "error line outside the input";
    return {};
  }
  for (const auto& p : r.points) {
    if (!locus::is_finite(p)) return "ok result with a non-finite point";
  }
  const auto w = locus::write_points_string<T, N>(r.points, format);
  if (w.status != Status::ok) return "cannot write back what was read: " + w.message;
  const auto again = locus::parse_points<T, N>(w.data, format, "fuzz-again");
  if (again.status != Status::ok) return "cannot read back what was written: " + again.message;
  if (again.points.size() != r.points.size()) return "point count differs";
  if (!r.points.empty() &&
      std::memcmp(r.points.data(), again.points.data(), r.points.size() * sizeof(r.points[0]))) {
    return "point bits differ";
  }
  return {};
}

/// "" when the property holds for every reading of the bytes, else what broke.
inline std::string check_point_lists(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  using locus::PointListFormat;
  std::string e = check_points_reader<float, 2>(PointListFormat::csv, bytes);
  if (e.empty()) e = check_points_reader<double, 2>(PointListFormat::csv, bytes);
  if (e.empty()) e = check_points_reader<float, 3>(PointListFormat::csv, bytes);
  if (e.empty()) e = check_points_reader<double, 3>(PointListFormat::csv, bytes);
  if (e.empty()) e = check_points_reader<double, 3>(PointListFormat::xyz, bytes);
  if (e.empty()) e = check_points_reader<float, 3>(PointListFormat::xyz, bytes);
  return e;
}

}  // namespace locus_fuzz
