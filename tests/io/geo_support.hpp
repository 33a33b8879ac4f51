// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared by tests/io/wkt_test.cpp and geojson_test.cpp: random 2D geometries whose coordinates
// cover the awkward doubles and floats (subnormals, the largest finite values, -0, random bit
// patterns), and a bit-exact comparison (tests/fuzz/geo_fuzz.hpp).

#include <locus/io/geometry.hpp>

#include "fuzz/geo_fuzz.hpp"
#include "support/typed.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace geo_test {

using locus::Geometry2;
using locus::GeometryType;
using locus::RingPolygon2;
using locus::Vec2;

/// A finite value of an awkward kind.
template <class T>
T awkward(locus_test::Rng& rng) {
  using L = std::numeric_limits<T>;
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  switch (rng.uniform_int(0, 7)) {
    case 0:
      return T(rng.uniform_int(-100, 100));
    case 1:
      return L::denorm_min() * T(rng.uniform_int(-1000, 1000));
    case 2:
      return L::max() / T(rng.uniform_int(1, 7)) * T(rng.uniform_int(0, 1) ? 1 : -1);
    case 3:
      return rng.uniform_int(0, 1) ? T(0) : -T(0);
    case 4:
      return L::min() * rng.uniform<T>(-4, 4);
    default:
      for (;;) {
        const T v = std::bit_cast<T>(static_cast<Bits>(rng.engine()()));
        if (std::isfinite(v)) return v;
      }
  }
}

template <class T>
Vec2<T> awkward_point(locus_test::Rng& rng) {
  return Vec2<T>{awkward<T>(rng), awkward<T>(rng)};
}

/// n >= 3 ring points (closing point not repeated) with at least three distinct ones.
template <class T>
void add_ring(locus_test::Rng& rng, RingPolygon2<T>& p, int n) {
  for (;;) {
    std::vector<Vec2<T>> r;
    for (int i = 0; i < n; ++i) r.push_back(awkward_point<T>(rng));
    if (r[0] == r[1] || r[0] == r[2] || r[1] == r[2]) continue;
    p.points.insert(p.points.end(), r.begin(), r.end());
    p.ring_ends.push_back(static_cast<std::uint32_t>(p.points.size()));
    return;
  }
}

template <class T>
RingPolygon2<T> random_polygon(locus_test::Rng& rng) {
  RingPolygon2<T> p;
  const int rings = rng.uniform_int(1, 3);
  for (int k = 0; k < rings; ++k) add_ring(rng, p, rng.uniform_int(3, 7));
  return p;
}

template <class T>
std::vector<Vec2<T>> random_line(locus_test::Rng& rng) {
  std::vector<Vec2<T>> l;
  const int n = rng.uniform_int(2, 6);
  for (int i = 0; i < n; ++i) l.push_back(awkward_point<T>(rng));
  return l;
}

/// A random geometry of the given type; empty with probability 1/8.
template <class T>
Geometry2<T> random_geometry(locus_test::Rng& rng, GeometryType type) {
  Geometry2<T> g;
  g.type = type;
  if (rng.uniform_int(0, 7) == 0) return g;
  const bool multi = type == GeometryType::multi_point || type == GeometryType::multi_line_string ||
                     type == GeometryType::multi_polygon;
  const int parts = multi ? rng.uniform_int(1, 4) : 1;
  for (int i = 0; i < parts; ++i) {
    switch (type) {
      case GeometryType::point:
      case GeometryType::multi_point:
        g.points.push_back(awkward_point<T>(rng));
        break;
      case GeometryType::line_string:
      case GeometryType::multi_line_string:
        g.lines.push_back(random_line<T>(rng));
        break;
      case GeometryType::polygon:
      case GeometryType::multi_polygon:
        g.polygons.push_back(random_polygon<T>(rng));
        break;
    }
  }
  return g;
}

inline constexpr GeometryType all_types[] = {
    GeometryType::point,       GeometryType::line_string,       GeometryType::polygon,
    GeometryType::multi_point, GeometryType::multi_line_string, GeometryType::multi_polygon};

/// max_digits10 digits with printf: a second way to print numbers that read back exactly.
template <class T>
std::string number(T v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", std::numeric_limits<T>::max_digits10, double(v));
  return buf;
}

}  // namespace geo_test
