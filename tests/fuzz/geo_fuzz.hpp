// SPDX-License-Identifier: BSL-1.0
#pragma once
// The property the WKT and GeoJSON readers are fuzzed for (tests/fuzz/{wkt,geojson}_fuzz.cpp),
// also replayed on every committed input by tests/io/{wkt,geojson}_test.cpp: reading any
// bytes, as float and as double, returns (no crash, hang or huge allocation; the sanitizers and
// libFuzzer's limits catch those); an error has a message and a position inside the input; an
// ok result holds only finite coordinates, closed-ring invariants hold, and writing it back and
// reading that gives the same geometries bit for bit, in both formats.

#include <locus/io/geojson.hpp>
#include <locus/io/wkt.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace locus_fuzz {

template <class T>
bool same_points(const std::vector<locus::Vec2<T>>& a, const std::vector<locus::Vec2<T>>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
}

/// "" when the two lists hold the same geometries bit for bit, else the first difference.
template <class T>
std::string same_geometries(const std::vector<locus::Geometry2<T>>& a,
                            const std::vector<locus::Geometry2<T>>& b) {
  if (a.size() != b.size()) return "geometry count differs";
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto &x = a[i], &y = b[i];
    if (x.type != y.type) return "type differs at " + std::to_string(i);
    if (!same_points(x.points, y.points)) return "points differ at " + std::to_string(i);
    if (x.lines.size() != y.lines.size()) return "line count differs at " + std::to_string(i);
    for (std::size_t k = 0; k < x.lines.size(); ++k)
      if (!same_points(x.lines[k], y.lines[k])) return "line differs at " + std::to_string(i);
    if (x.polygons.size() != y.polygons.size()) return "polygon count differs";
    for (std::size_t k = 0; k < x.polygons.size(); ++k) {
      if (!same_points(x.polygons[k].points, y.polygons[k].points) ||
          x.polygons[k].ring_ends != y.polygons[k].ring_ends) {
        return "polygon differs at " + std::to_string(i);
      }
    }
  }
  return {};
}

/// Writes a list as WKT, one geometry per line.
template <class T>
std::string wkt_text(const std::vector<locus::Geometry2<T>>& list, std::string& error) {
  std::string text;
  for (const auto& g : list) {
    const auto w = locus::write_wkt_string(g);
    if (w.status != locus::Status::ok) error = "cannot write WKT back: " + w.message;
    text += w.data + "\n";
  }
  return text;
}

template <class T>
std::string check_result(const locus::GeometryReadResult<T>& r, std::string_view bytes) {
  using locus::Status;
  if (r.status != Status::ok) {
    if (r.message.empty()) return "error without a message";
    if (r.byte_offset > bytes.size() || r.line == 0 || r.column == 0) return "bad error position";
    return {};
  }
  for (const auto& g : r.geometries) {
    if (locus::check_geometry(g) != Status::ok) return "ok result fails check_geometry";
  }
  std::string error;
  const std::string wkt = wkt_text(r.geometries, error);
  if (!error.empty()) return error;
  const auto again = locus::parse_wkt<T>(wkt, "again");
  const bool none = r.geometries.empty();
  if (!none && again.status != Status::ok) return "cannot read back WKT: " + again.message;
  if (!none) {
    if (std::string e = same_geometries(r.geometries, again.geometries); !e.empty()) {
      return "WKT round trip: " + e;
    }
  }
  const auto json = locus::write_geojson_string(r.geometries);
  if (json.status != Status::ok) return "cannot write GeoJSON back: " + json.message;
  const auto back = locus::parse_geojson<T>(json.data, "again");
  if (back.status != Status::ok) return "cannot read back GeoJSON: " + back.message;
  if (std::string e = same_geometries(r.geometries, back.geometries); !e.empty()) {
    return "GeoJSON round trip: " + e;
  }
  return {};
}

/// The property for one reader (wkt: true for WKT, false for GeoJSON), float then double.
inline std::string check_geo(bool wkt, const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::string e = wkt ? check_result(locus::parse_wkt<float>(bytes, "fuzz"), bytes)
                      : check_result(locus::parse_geojson<float>(bytes, "fuzz"), bytes);
  if (e.empty()) {
    e = wkt ? check_result(locus::parse_wkt<double>(bytes, "fuzz"), bytes)
            : check_result(locus::parse_geojson<double>(bytes, "fuzz"), bytes);
  }
  return e;
}

}  // namespace locus_fuzz
