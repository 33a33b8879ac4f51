// SPDX-License-Identifier: BSL-1.0
// GeoJSON reader and writer for 2D geometries (io/geojson.hpp). The text is tokenized first
// (src/io/json.hpp, depth-bounded, no recursion); the geometry objects are then read from the
// token array, so members may come in any order. GeometryCollection members are read by
// recursion whose depth the tokenizer's bound limits.

#include <locus/io/geojson.hpp>

#include "file_bytes.hpp"
#include "geometry_detail.hpp"
#include "json.hpp"

#include <array>

namespace locus {
namespace {

using geo_io::Errors;
using geo_io::NumberError;
using json::Kind;
using json::Value;

constexpr int max_depth = 64;

template <Real T>
class GeoJsonReader : public Errors {
 public:
  GeoJsonReader(std::string_view text, const std::vector<Value>& values) noexcept
      : s_(text), v_(values) {}

  void run(std::vector<Geometry2<T>>& out) {
    const std::size_t top = 0;
    if (v_[top].kind != Kind::object) {
      fail(Status::parse_error, v_[top].pos, "the top value is not a GeoJSON object");
      return;
    }
    std::string type;
    if (!type_of(top, type)) return;
    if (type == "FeatureCollection") {
      std::size_t features = 0;
      if (!member(top, "features", features, true)) return;
      if (v_[features].kind != Kind::array) {
        fail(Status::parse_error, v_[features].pos, "\"features\" is not an array");
        return;
      }
      for (std::size_t f = features + 1; f < v_[features].end; f = v_[f].end) {
        if (!feature(f, out)) return;
      }
      return;
    }
    if (type == "Feature") {
      feature(top, out);
      return;
    }
    geometry(top, type, out);
  }

 private:
  std::string_view s_;
  const std::vector<Value>& v_;

  /// The value of member `name` of object o (0 when absent); false on a duplicate.
  bool member(std::size_t o, std::string_view name, std::size_t& found, bool required) {
    found = 0;
    for (std::size_t k = o + 1; k < v_[o].end; k = v_[k + 1].end) {
      if (!json::string_equals(s_, v_[k], name)) continue;
      if (found != 0) {
        return fail(Status::parse_error, v_[k].pos,
                    "member \"" + std::string(name) + "\" appears twice");
      }
      found = k + 1;
    }
    if (found == 0 && required) {
      return fail(Status::parse_error, v_[o].pos,
                  "object has no \"" + std::string(name) + "\" member");
    }
    return true;
  }

  bool type_of(std::size_t o, std::string& type) {
    std::size_t t = 0;
    if (!member(o, "type", t, true)) return false;
    if (v_[t].kind != Kind::string) {
      return fail(Status::parse_error, v_[t].pos, "\"type\" is not a string");
    }
    type = json::string_value(s_, v_[t]);
    return true;
  }

  bool feature(std::size_t f, std::vector<Geometry2<T>>& out) {
    if (v_[f].kind != Kind::object) {
      return fail(Status::parse_error, v_[f].pos, "a feature is not an object");
    }
    std::string type;
    if (!type_of(f, type)) return false;
    if (type != "Feature") {
      return fail(Status::parse_error, v_[f].pos,
                  "expected a Feature, found type " + geo_io::quote(type));
    }
    std::size_t g = 0;
    if (!member(f, "geometry", g, true)) return false;
    if (v_[g].kind == Kind::null) return true;
    if (v_[g].kind != Kind::object) {
      return fail(Status::parse_error, v_[g].pos, "\"geometry\" is neither an object nor null");
    }
    if (!type_of(g, type)) return false;
    return geometry(g, type, out);
  }

  bool geometry(std::size_t g, const std::string& type, std::vector<Geometry2<T>>& out) {
    static constexpr std::array<std::pair<const char*, GeometryType>, 6> names{
        {{"Point", GeometryType::point},
         {"LineString", GeometryType::line_string},
         {"Polygon", GeometryType::polygon},
         {"MultiPoint", GeometryType::multi_point},
         {"MultiLineString", GeometryType::multi_line_string},
         {"MultiPolygon", GeometryType::multi_polygon}}};
    if (type == "GeometryCollection") {
      std::size_t list = 0;
      if (!member(g, "geometries", list, true)) return false;
      if (v_[list].kind != Kind::array) {
        return fail(Status::parse_error, v_[list].pos, "\"geometries\" is not an array");
      }
      for (std::size_t m = list + 1; m < v_[list].end; m = v_[m].end) {
        if (v_[m].kind != Kind::object) {
          return fail(Status::parse_error, v_[m].pos, "a geometry is not an object");
        }
        std::string t;
        if (!type_of(m, t)) return false;
        if (!geometry(m, t, out)) return false;
      }
      return true;
    }
    Geometry2<T> result;
    bool known = false;
    for (const auto& [name, kind] : names) {
      if (type == name) {
        result.type = kind;
        known = true;
      }
    }
    if (!known) {
      std::size_t t = 0;
      (void)member(g, "type", t, true);
      return fail(Status::parse_error, v_[t].pos,
                  "unknown geometry type " + geo_io::quote(type) + " (names are case-sensitive)");
    }
    std::size_t c = 0;
    if (!member(g, "coordinates", c, true)) return false;
    if (!array(c, "\"coordinates\"")) return false;
    const bool empty = v_[c].count == 0;
    bool ok = true;
    switch (result.type) {
      case GeometryType::point:
        if (!empty) {
          result.points.emplace_back();
          ok = position(c, result.points.back());
        }
        break;
      case GeometryType::line_string:
        if (!empty) {
          result.lines.emplace_back();
          ok = line(c, result.lines.back());
        }
        break;
      case GeometryType::polygon:
        if (!empty) {
          result.polygons.emplace_back();
          ok = polygon(c, result.polygons.back());
        }
        break;
      case GeometryType::multi_point:
        for (std::size_t p = c + 1; ok && p < v_[c].end; p = v_[p].end) {
          result.points.emplace_back();
          ok = position(p, result.points.back());
        }
        break;
      case GeometryType::multi_line_string:
        for (std::size_t l = c + 1; ok && l < v_[c].end; l = v_[l].end) {
          ok = array(l, "a line string");
          if (!ok || v_[l].count == 0) continue;
          result.lines.emplace_back();
          ok = line(l, result.lines.back());
        }
        break;
      case GeometryType::multi_polygon:
        for (std::size_t p = c + 1; ok && p < v_[c].end; p = v_[p].end) {
          ok = array(p, "a polygon");
          if (!ok || v_[p].count == 0) continue;
          result.polygons.emplace_back();
          ok = polygon(p, result.polygons.back());
        }
        break;
    }
    if (!ok) return false;
    out.push_back(std::move(result));
    return true;
  }

  bool array(std::size_t a, const char* what) {
    if (v_[a].kind == Kind::array) return true;
    return fail(Status::parse_error, v_[a].pos, std::string(what) + " is not an array");
  }

  bool position(std::size_t p, Vec2<T>& out) {
    if (!array(p, "a position")) return false;
    const std::uint32_t n = v_[p].count;
    if (n < 2 || n > 3) {
      return fail(Status::parse_error, v_[p].pos,
                  "a position needs 2 or 3 numbers, found " + std::to_string(n));
    }
    T xy[2] = {};
    std::size_t k = p + 1;
    for (std::uint32_t i = 0; i < n; ++i, k = v_[k].end) {
      const Value& x = v_[k];
      if (x.kind != Kind::number) {
        return fail(Status::parse_error, x.pos, "a coordinate is not a number");
      }
      if (i >= 2) continue;  // z is dropped
      const std::string_view tok = s_.substr(x.pos, x.len);
      if (geo_io::parse_real<T>(tok, xy[i]) != NumberError::none) {
        return fail(Status::non_finite_input, x.pos,
                    "coordinate " + geo_io::quote(tok) + " overflows this precision");
      }
    }
    out = Vec2<T>{xy[0], xy[1]};
    return true;
  }

  bool positions(std::size_t a, std::vector<Vec2<T>>& out) {
    if (out.size() + v_[a].count > geo_io::max_points) {
      return fail(Status::parse_error, v_[a].pos, "more than 2^32 - 1 points in one geometry");
    }
    for (std::size_t p = a + 1; p < v_[a].end; p = v_[p].end) {
      out.emplace_back();
      if (!position(p, out.back())) return false;
    }
    return true;
  }

  bool line(std::size_t l, std::vector<Vec2<T>>& out) {
    if (!positions(l, out)) return false;
    if (out.size() < 2) {
      return fail(Status::parse_error, v_[l].pos, "a line string needs at least 2 positions");
    }
    return true;
  }

  bool polygon(std::size_t p, RingPolygon2<T>& out) {
    for (std::size_t r = p + 1; r < v_[p].end; r = v_[r].end) {
      if (!array(r, "a ring")) return false;
      const std::size_t begin = out.points.size();
      if (!positions(r, out.points)) return false;
      if (const char* why = geo_io::close_ring(out.points, begin)) {
        return fail(Status::parse_error, v_[r].pos, why);
      }
      out.ring_ends.push_back(static_cast<std::uint32_t>(out.points.size()));
    }
    return true;
  }
};

// ---- writing -------------------------------------------------------------------------------

template <Real T>
void append_position(std::string& s, const Vec2<T>& p) {
  s += '[';
  geo_io::append_real(s, p.x);
  s += ',';
  geo_io::append_real(s, p.y);
  s += ']';
}

template <Real T>
void append_positions(std::string& s, std::span<const Vec2<T>> v, bool close) {
  s += '[';
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s += ',';
    append_position(s, v[i]);
  }
  if (close && !v.empty()) {
    s += ',';
    append_position(s, v[0]);
  }
  s += ']';
}

template <Real T>
void append_polygon(std::string& s, const RingPolygon2<T>& p) {
  s += '[';
  std::size_t begin = 0;
  for (std::size_t k = 0; k < p.ring_ends.size(); ++k) {
    if (k) s += ',';
    append_positions<T>(
        s, std::span<const Vec2<T>>(p.points.data() + begin, p.ring_ends[k] - begin), true);
    begin = p.ring_ends[k];
  }
  s += ']';
}

template <Real T>
void append_geometry(std::string& s, const Geometry2<T>& g) {
  static constexpr std::array<const char*, 6> names{
      "Point", "LineString", "Polygon", "MultiPoint", "MultiLineString", "MultiPolygon"};
  s += "{\"type\":\"";
  s += names[static_cast<std::size_t>(g.type)];
  s += "\",\"coordinates\":";
  switch (g.type) {
    case GeometryType::point:
      if (g.points.empty()) {
        s += "[]";
      } else {
        append_position(s, g.points[0]);
      }
      break;
    case GeometryType::line_string:
      if (g.lines.empty()) {
        s += "[]";
      } else {
        append_positions<T>(s, g.lines[0], false);
      }
      break;
    case GeometryType::polygon:
      if (g.polygons.empty()) {
        s += "[]";
      } else {
        append_polygon(s, g.polygons[0]);
      }
      break;
    case GeometryType::multi_point:
      append_positions<T>(s, g.points, false);
      break;
    case GeometryType::multi_line_string:
      s += '[';
      for (std::size_t i = 0; i < g.lines.size(); ++i) {
        if (i) s += ',';
        append_positions<T>(s, g.lines[i], false);
      }
      s += ']';
      break;
    case GeometryType::multi_polygon:
      s += '[';
      for (std::size_t i = 0; i < g.polygons.size(); ++i) {
        if (i) s += ',';
        append_polygon(s, g.polygons[i]);
      }
      s += ']';
      break;
  }
  s += '}';
}

template <Real T>
GeometryWriteResult collection(std::span<const Geometry2<T>> geometries) {
  GeometryWriteResult r;
  r.data = "{\"type\":\"FeatureCollection\",\"features\":[";
  for (std::size_t i = 0; i < geometries.size(); ++i) {
    r.status = check_geometry(geometries[i]);
    if (r.status != Status::ok) {
      r.message = "geometry " + std::to_string(i) + ": " + geo_io::write_refusal(r.status);
      r.data.clear();
      return r;
    }
    r.data += i ? ",\n" : "\n";
    r.data += "{\"type\":\"Feature\",\"properties\":null,\"geometry\":";
    append_geometry(r.data, geometries[i]);
    r.data += '}';
  }
  r.data += "\n]}\n";
  r.status = Status::ok;
  return r;
}

}  // namespace

template <Real T>
GeometryReadResult<T> parse_geojson(std::string_view text, std::string_view name) {
  std::vector<Geometry2<T>> out;
  Errors errors;
  std::size_t i = 0;
  while (i < text.size() &&
         (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r')) {
    ++i;
  }
  if (i == text.size()) {
    errors.fail(Status::empty_input, i, "no JSON value in the text");
    return geo_io::finish<T>(errors.failure, text, name, std::move(out));
  }
  const json::Document doc = json::parse(text, max_depth);
  if (!doc.error.empty()) {
    errors.fail(Status::parse_error, doc.error_pos, doc.error);
    return geo_io::finish<T>(errors.failure, text, name, std::move(out));
  }
  GeoJsonReader<T> reader(text, doc.values);
  reader.run(out);
  return geo_io::finish<T>(reader.failure, text, name, std::move(out));
}

template <Real T>
GeometryReadResult<T> read_geojson(const std::filesystem::path& path) {
  const io_detail::FileBytes file = io_detail::read_file_bytes(path);
  if (!file.error.empty()) return geo_io::unreadable<T>(path, file.error);
  return parse_geojson<T>(file.bytes(), path.string());
}

template <Real T>
GeometryWriteResult write_geojson_string(const Geometry2<T>& geometry) {
  GeometryWriteResult r;
  r.status = check_geometry(geometry);
  if (r.status != Status::ok) {
    r.message = geo_io::write_refusal(r.status);
    return r;
  }
  append_geometry(r.data, geometry);
  return r;
}

template <Real T>
GeometryWriteResult write_geojson_string(std::span<const Geometry2<T>> geometries) {
  return collection(geometries);
}

template <Real T>
GeometryWriteResult write_geojson(const std::filesystem::path& path,
                                  std::span<const Geometry2<T>> geometries) {
  GeometryWriteResult r = collection(geometries);
  if (r.status != Status::ok) {
    r.message = path.string() + ": " + r.message;
    return r;
  }
  if (!geo_io::write_file(path, r.data)) {
    r.status = Status::io_error;
    r.message = path.string() + ": cannot write the file";
  }
  r.data.clear();
  return r;
}

template GeometryReadResult<float> parse_geojson<float>(std::string_view, std::string_view);
template GeometryReadResult<double> parse_geojson<double>(std::string_view, std::string_view);
template GeometryReadResult<float> read_geojson<float>(const std::filesystem::path&);
template GeometryReadResult<double> read_geojson<double>(const std::filesystem::path&);
template GeometryWriteResult write_geojson_string(const Geometry2<float>&);
template GeometryWriteResult write_geojson_string(const Geometry2<double>&);
template GeometryWriteResult write_geojson_string(std::span<const Geometry2<float>>);
template GeometryWriteResult write_geojson_string(std::span<const Geometry2<double>>);
template GeometryWriteResult write_geojson(const std::filesystem::path&,
                                           std::span<const Geometry2<float>>);
template GeometryWriteResult write_geojson(const std::filesystem::path&,
                                           std::span<const Geometry2<double>>);

}  // namespace locus
