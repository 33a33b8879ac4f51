// SPDX-License-Identifier: BSL-1.0
// 2D geometries for WKT and GeoJSON: orientation, conversions, the writers' checks, files
// (io/geometry.hpp).

#include <locus/io/geometry.hpp>

#include "geometry_detail.hpp"

#include <algorithm>
#include <fstream>
#include <span>
#include <system_error>

namespace locus {

const char* wkt_name(GeometryType type) noexcept {
  switch (type) {
    case GeometryType::point:
      return "POINT";
    case GeometryType::line_string:
      return "LINESTRING";
    case GeometryType::polygon:
      return "POLYGON";
    case GeometryType::multi_point:
      return "MULTIPOINT";
    case GeometryType::multi_line_string:
      return "MULTILINESTRING";
    case GeometryType::multi_polygon:
      return "MULTIPOLYGON";
  }
  return "GEOMETRY";
}

template <Real T>
void orient_rings(RingPolygon2<T>& polygon) noexcept {
  std::size_t begin = 0;
  const std::size_t n = polygon.points.size();
  for (std::size_t k = 0; k < polygon.ring_ends.size(); ++k) {
    const std::size_t end = std::min<std::size_t>(polygon.ring_ends[k], n);
    if (end <= begin) continue;
    const std::span<Vec2<T>> ring(polygon.points.data() + begin, end - begin);
    const Sign s = polygon_orientation(std::span<const Vec2<T>>(ring));
    const Sign want = k == 0 ? Sign::positive : Sign::negative;
    if (s != Sign::zero && s != want) std::reverse(ring.begin(), ring.end());
    begin = end;
  }
}

template <Real T>
void orient_rings(Geometry2<T>& geometry) noexcept {
  for (RingPolygon2<T>& p : geometry.polygons) orient_rings(p);
}

template <Real T>
PolygonWithHoles2<T> to_polygon_with_holes(const RingPolygon2<T>& polygon) {
  PolygonWithHoles2<T> out;
  std::size_t begin = 0;
  const std::size_t n = polygon.points.size();
  for (std::size_t k = 0; k < polygon.ring_ends.size(); ++k) {
    const std::size_t end = std::clamp<std::size_t>(polygon.ring_ends[k], begin, n);
    Polygon2<T> ring{std::vector<Vec2<T>>(polygon.points.begin() + std::ptrdiff_t(begin),
                                          polygon.points.begin() + std::ptrdiff_t(end))};
    if (k == 0) {
      out.outer = std::move(ring);
    } else {
      out.holes.push_back(std::move(ring));
    }
    begin = end;
  }
  return out;
}

template <Real T>
RingPolygon2<T> to_ring_polygon(const PolygonWithHoles2<T>& polygon) {
  RingPolygon2<T> out;
  const auto add = [&](const Polygon2<T>& ring) {
    out.points.insert(out.points.end(), ring.vertices.begin(), ring.vertices.end());
    out.ring_ends.push_back(static_cast<std::uint32_t>(out.points.size()));
  };
  add(polygon.outer);
  for (const Polygon2<T>& h : polygon.holes) add(h);
  return out;
}

namespace {

template <Real T>
bool finite(std::span<const Vec2<T>> v) noexcept {
  for (const Vec2<T>& p : v)
    if (!is_finite(p)) return false;
  return true;
}

// Whether a ring has three distinct points (what the readers require).
template <Real T>
bool three_distinct(std::span<const Vec2<T>> v) noexcept {
  std::size_t i = 1;
  while (i < v.size() && v[i] == v[0]) ++i;
  if (i == v.size()) return false;
  const Vec2<T> b = v[i];
  while (i < v.size() && (v[i] == v[0] || v[i] == b)) ++i;
  return i < v.size();
}

}  // namespace

template <Real T>
Status check_geometry(const Geometry2<T>& g) noexcept {
  switch (g.type) {
    case GeometryType::point:
      if (g.points.size() > 1) return Status::invalid_input;
      [[fallthrough]];
    case GeometryType::multi_point:
      return finite<T>(g.points) ? Status::ok : Status::non_finite_input;
    case GeometryType::line_string:
      if (g.lines.size() > 1) return Status::invalid_input;
      [[fallthrough]];
    case GeometryType::multi_line_string:
      for (const auto& line : g.lines) {
        if (line.size() < 2) return Status::invalid_input;
        if (!finite<T>(line)) return Status::non_finite_input;
      }
      return Status::ok;
    case GeometryType::polygon:
      if (g.polygons.size() > 1) return Status::invalid_input;
      [[fallthrough]];
    case GeometryType::multi_polygon:
      for (const RingPolygon2<T>& p : g.polygons) {
        if (p.ring_ends.empty() || p.ring_ends.back() != p.points.size()) {
          return Status::invalid_input;
        }
        if (!finite<T>(p.points)) return Status::non_finite_input;
        std::size_t begin = 0;
        for (const std::uint32_t end : p.ring_ends) {
          if (end < begin || end - begin < 3) return Status::invalid_input;
          if (!three_distinct(std::span<const Vec2<T>>(p.points.data() + begin, end - begin))) {
            return Status::invalid_input;
          }
          begin = end;
        }
      }
      return Status::ok;
  }
  return Status::invalid_input;
}

template void orient_rings<float>(RingPolygon2<float>&) noexcept;
template void orient_rings<double>(RingPolygon2<double>&) noexcept;
template void orient_rings<float>(Geometry2<float>&) noexcept;
template void orient_rings<double>(Geometry2<double>&) noexcept;
template PolygonWithHoles2<float> to_polygon_with_holes(const RingPolygon2<float>&);
template PolygonWithHoles2<double> to_polygon_with_holes(const RingPolygon2<double>&);
template RingPolygon2<float> to_ring_polygon(const PolygonWithHoles2<float>&);
template RingPolygon2<double> to_ring_polygon(const PolygonWithHoles2<double>&);
template Status check_geometry(const Geometry2<float>&) noexcept;
template Status check_geometry(const Geometry2<double>&) noexcept;

namespace geo_io {

bool write_file(const std::filesystem::path& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary);
  return out && out.write(text.data(), static_cast<std::streamsize>(text.size())) && out.flush();
}

const char* write_refusal(Status s) noexcept {
  return s == Status::non_finite_input
             ? "a coordinate is NaN or infinite"
             : "malformed geometry (a ring of fewer than 3 distinct points, a line of fewer than "
               "2, "
               "ring_ends not matching the points, or several parts in a single geometry)";
}

}  // namespace geo_io
}  // namespace locus
