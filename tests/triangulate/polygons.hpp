// SPDX-License-Identifier: BSL-1.0
#pragma once
// Test polygons for the triangulate area: seeded star-shaped rings with square holes, combs,
// the earcut fixtures (a small reader for their JSON arrays), and the three triangulators
// behind one call so every test runs on each.

#include <locus/core/vec.hpp>
#include <locus/triangulate/ear_clipping.hpp>
#include <locus/triangulate/monotone.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace locus_test {

template <class T>
struct Polygon {
  std::vector<locus::Vec2<T>> points;
  std::vector<std::uint32_t> ends;

  void add_ring(const std::vector<locus::Vec2<T>>& ring) {
    points.insert(points.end(), ring.begin(), ring.end());
    ends.push_back(static_cast<std::uint32_t>(points.size()));
  }
};

enum class Method { ear_clipping, monotone };

inline const char* method_name(Method m) {
  return m == Method::ear_clipping ? "ear_clipping" : "monotone";
}

template <class T>
locus::PolygonTriangulation triangulate(Method m, const Polygon<T>& p) {
  const std::span<const locus::Vec2<T>> pts(p.points);
  const std::span<const std::uint32_t> ends(p.ends);
  return m == Method::ear_clipping ? locus::triangulate_ear_clipping(pts, ends)
                                   : locus::triangulate_monotone(pts, ends);
}

/// Coordinates on a 2^-10 grid so float and double hold them exactly.
template <class T>
T snap(double v) {
  return static_cast<T>(std::round(v * 1024.0) / 1024.0);
}

/// A star-shaped ring around c (radii in [r0, r1], n vertices), counter-clockwise, with
/// optional square holes of half-size h on a ring of radius rh (all inside the kernel disc).
template <class T>
Polygon<T> star_polygon(Rng& rng, int n, double r0, double r1, int holes = 0) {
  // The holes reach 0.5 r0 + 0.2 sqrt(2) r0 < 0.79 r0 from c; an edge between vertices at
  // radius >= r0 whose angles differ by at most 3.8 pi / n stays beyond r0 cos(1.9 pi / n), which
  // is above 0.82 r0 for n >= 10: with fewer vertices a hole could cross the outer ring.
  if (holes > 0) n = std::max(n, 10);
  Polygon<T> p;
  std::vector<locus::Vec2<T>> ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + rng.uniform(0.0, 0.9)) / n;
    const double r = rng.uniform(r0, r1);
    ring.push_back({snap<T>(r * std::cos(a)), snap<T>(r * std::sin(a))});
  }
  if (rng.uniform_int(0, 1)) std::reverse(ring.begin(), ring.end());
  p.add_ring(ring);
  for (int k = 0; k < holes; ++k) {
    const double a = 2 * std::numbers::pi * k / holes;
    const double cx = 0.5 * r0 * std::cos(a), cy = 0.5 * r0 * std::sin(a);
    const double h = std::min(0.2 * r0, 1.2 * r0 / holes);
    std::vector<locus::Vec2<T>> hole = {{snap<T>(cx - h), snap<T>(cy - h)},
                                        {snap<T>(cx + h), snap<T>(cy - h)},
                                        {snap<T>(cx + h), snap<T>(cy + h)},
                                        {snap<T>(cx - h), snap<T>(cy + h)}};
    if (rng.uniform_int(0, 1)) std::reverse(hole.begin(), hole.end());
    p.add_ring(hole);
  }
  return p;
}

/// A comb: `teeth` downward teeth of random depth hanging from a bar (many reflex vertices,
/// many split/merge vertices for the sweep).
template <class T>
Polygon<T> comb_polygon(Rng& rng, int teeth) {
  std::vector<locus::Vec2<T>> ring;
  ring.push_back({T(0), T(0)});
  for (int i = 0; i < teeth; ++i) {
    const T x0 = T(2 * i), depth = T(rng.uniform_int(1, 20));
    ring.push_back({x0 + T(1), T(0)});
    ring.push_back({x0 + T(1), -depth});
    ring.push_back({x0 + T(2), -depth});
    ring.push_back({x0 + T(2), T(0)});
  }
  ring.push_back({T(2 * teeth + 1), T(0)});
  ring.push_back({T(2 * teeth + 1), T(5)});
  ring.push_back({T(0), T(5)});
  // Upward teeth are the gaps: make the bar's top wavy too.
  Polygon<T> p;
  p.add_ring(ring);
  return p;
}

// ---- the earcut fixtures ----------------------------------------------------------------

/// A minimal JSON reader: numbers, strings, arrays and objects (enough for the fixtures).
struct Json {
  enum Kind { number, string, array, object } kind = number;
  double num = 0;
  std::string str;
  std::vector<Json> items;
  // An object's members, keys[i] naming values[i] (std::pair<std::string, Json> would need Json
  // complete inside its own definition, which clang rejects).
  std::vector<std::string> keys;
  std::vector<Json> values;

  static Json parse(const std::string& s) {
    std::size_t i = 0;
    return value(s, i);
  }

 private:
  static void ws(const std::string& s, std::size_t& i) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  }
  static Json value(const std::string& s, std::size_t& i) {
    ws(s, i);
    Json j;
    if (s[i] == '[' || s[i] == '{') {
      const bool obj = s[i] == '{';
      j.kind = obj ? object : array;
      ++i;
      ws(s, i);
      while (s[i] != ']' && s[i] != '}') {
        if (obj) {
          Json key = value(s, i);
          ws(s, i);
          ++i;  // ':'
          j.keys.push_back(key.str);
          j.values.push_back(value(s, i));
        } else {
          j.items.push_back(value(s, i));
        }
        ws(s, i);
        if (s[i] == ',') ++i;
        ws(s, i);
      }
      ++i;
    } else if (s[i] == '"') {
      j.kind = string;
      const std::size_t e = s.find('"', i + 1);
      j.str = s.substr(i + 1, e - i - 1);
      i = e + 1;
    } else {
      std::size_t used = 0;
      j.num = std::stod(s.substr(i, 40), &used);
      i += used;
    }
    return j;
  }
};

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::string earcut_dir() { return std::string(LOCUS_SHARED_DIR "/corpus/earcut/"); }

/// Fixture `name` as a polygon (rings as given; GeoJSON rings may repeat the first point).
template <class T>
Polygon<T> earcut_fixture(const std::string& name) {
  const Json j = Json::parse(read_text(earcut_dir() + "fixtures/" + name + ".json"));
  Polygon<T> p;
  for (const Json& ring : j.items) {
    std::vector<locus::Vec2<T>> r;
    for (const Json& pt : ring.items)
      r.push_back({static_cast<T>(pt.items[0].num), static_cast<T>(pt.items[1].num)});
    p.add_ring(r);
  }
  return p;
}

}  // namespace locus_test
