// SPDX-License-Identifier: BSL-1.0
// Well-known text reader and writer for 2D geometries (io/wkt.hpp).
// The grammar nests at most three parentheses deep inside one geometry (MULTIPOLYGON), so each
// geometry type has its own fixed-depth routine; GEOMETRYCOLLECTION nesting is kept as a
// counter in the driver loop, so no recursion follows the input.

#include <locus/io/wkt.hpp>

#include "file_bytes.hpp"
#include "geometry_detail.hpp"

#include <array>
#include <cstring>

namespace locus {
namespace {

using geo_io::Errors;
using geo_io::NumberError;

constexpr int max_collection_depth = 32;

[[nodiscard]] bool is_ws(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
[[nodiscard]] bool is_delim(char c) noexcept {
  return is_ws(c) || c == '(' || c == ')' || c == ',';
}
[[nodiscard]] bool is_alpha(char c) noexcept {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
[[nodiscard]] char upper(char c) noexcept {
  return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}
[[nodiscard]] bool iequals(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (upper(a[i]) != upper(b[i])) return false;
  return true;
}

enum class Tag : std::uint8_t { geometry, collection };

template <Real T>
class WktReader : public Errors {
 public:
  explicit WktReader(std::string_view text) noexcept : s_(text) {}

  std::vector<Geometry2<T>> run() {
    std::vector<Geometry2<T>> out;
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // a UTF-8 byte-order mark
    skip();
    if (at_end()) {
      failure.status = Status::empty_input;
      failure.reason = "no geometry in the text";
      return out;
    }
    int depth = 0;  // open GEOMETRYCOLLECTION parentheses
    while (true) {
      skip();
      if (depth == 0 && at_end()) break;
      Tag tag{};
      if (!tagged(out, tag, depth)) return out;
      if (tag == Tag::collection) continue;  // '(' consumed: its first member follows
      // After a geometry (or an empty collection): close or continue the open collections.
      while (depth > 0) {
        skip();
        if (peek(',')) {
          ++i_;
          break;
        }
        if (peek(')')) {
          ++i_;
          --depth;
          continue;
        }
        expected("',' or ')' in GEOMETRYCOLLECTION");
        return out;
      }
    }
    return out;
  }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
  int dims_ = 0;  // numbers per point in the current geometry, 0 while unknown

  [[nodiscard]] bool at_end() const noexcept { return i_ >= s_.size(); }
  void skip() noexcept {
    while (i_ < s_.size() && is_ws(s_[i_])) ++i_;
  }
  [[nodiscard]] bool peek(char c) const noexcept { return i_ < s_.size() && s_[i_] == c; }
  [[nodiscard]] std::string_view token_at(std::size_t at) const noexcept {
    std::size_t j = at;
    while (j < s_.size() && !is_delim(s_[j])) ++j;
    if (j == at && j < s_.size()) ++j;
    return s_.substr(at, j - at);
  }
  bool expected(const char* what) {
    skip();
    if (at_end())
      return fail(Status::parse_error, i_, std::string("unexpected end of text, expected ") + what);
    return fail(Status::parse_error, i_,
                std::string("expected ") + what + ", found " + geo_io::quote(token_at(i_)));
  }
  bool expect(char c, const char* what) {
    skip();
    if (!peek(c)) return expected(what);
    ++i_;
    return true;
  }
  /// Consumes an EMPTY keyword if one follows.
  bool empty_keyword() noexcept {
    skip();
    std::size_t j = i_;
    while (j < s_.size() && is_alpha(s_[j])) ++j;
    if (iequals(s_.substr(i_, j - i_), "EMPTY")) {
      i_ = j;
      return true;
    }
    return false;
  }

  /// A type keyword with its optional dimension, then its body; a collection only opens.
  bool tagged(std::vector<Geometry2<T>>& out, Tag& tag, int& depth) {
    skip();
    const std::size_t start = i_;
    std::size_t j = i_;
    while (j < s_.size() && is_alpha(s_[j])) ++j;
    std::string_view word = s_.substr(i_, j - i_);
    if (word.empty()) return expected("a geometry keyword");
    static constexpr std::array<std::pair<const char*, int>, 8> names{{{"POINT", 0},
                                                                       {"LINESTRING", 1},
                                                                       {"LINEARRING", 1},
                                                                       {"POLYGON", 2},
                                                                       {"MULTIPOINT", 3},
                                                                       {"MULTILINESTRING", 4},
                                                                       {"MULTIPOLYGON", 5},
                                                                       {"GEOMETRYCOLLECTION", 6}}};
    int kind = -1;
    int dims = 0;
    for (const auto& [name, k] : names) {
      const std::size_t n = std::strlen(name);
      if (word.size() < n || !iequals(word.substr(0, n), name)) continue;
      const std::string_view suffix = word.substr(n);
      if (suffix.empty()) {
        kind = k;
      } else if (iequals(suffix, "Z") || iequals(suffix, "M")) {
        kind = k;
        dims = 3;
      } else if (iequals(suffix, "ZM")) {
        kind = k;
        dims = 4;
      }
      if (kind >= 0) break;
    }
    if (kind < 0) {
      return fail(Status::parse_error, start,
                  "unknown or unsupported geometry keyword " + geo_io::quote(word));
    }
    i_ = j;
    if (dims == 0) {  // a separate dimension keyword?
      skip();
      std::size_t k = i_;
      while (k < s_.size() && is_alpha(s_[k])) ++k;
      const std::string_view d = s_.substr(i_, k - i_);
      if (iequals(d, "Z") || iequals(d, "M")) {
        dims = 3;
        i_ = k;
      } else if (iequals(d, "ZM")) {
        dims = 4;
        i_ = k;
      }
    }
    dims_ = dims;
    tag = Tag::geometry;
    if (kind == 6) {
      if (empty_keyword()) return true;
      if (!expect('(', "'(' or EMPTY after GEOMETRYCOLLECTION")) return false;
      if (depth == max_collection_depth) {
        return fail(Status::parse_error, start, "GEOMETRYCOLLECTION nested more than 32 deep");
      }
      ++depth;
      tag = Tag::collection;
      return true;
    }
    Geometry2<T> g;
    g.type = static_cast<GeometryType>(kind);
    bool ok = true;
    if (!empty_keyword()) {
      switch (g.type) {
        case GeometryType::point:
          g.points.emplace_back();
          ok = expect('(', "'(' or EMPTY") && point(g.points.back()) && expect(')', "')'");
          break;
        case GeometryType::line_string:
          g.lines.emplace_back();
          ok = line(g.lines.back());
          break;
        case GeometryType::polygon:
          g.polygons.emplace_back();
          ok = polygon(g.polygons.back());
          if (ok && g.polygons.back().ring_ends.empty()) g.polygons.clear();
          break;
        case GeometryType::multi_point:
          ok = multi_point(g.points);
          break;
        case GeometryType::multi_line_string:
          ok = multi_line(g.lines);
          break;
        case GeometryType::multi_polygon:
          ok = multi_polygon(g.polygons);
          break;
      }
    }
    if (!ok) return false;
    out.push_back(std::move(g));
    return true;
  }

  /// The numbers of one point (x y [z [m]]); extra dimensions are dropped.
  bool point(Vec2<T>& p) {
    T v[2] = {};
    int count = 0;
    skip();
    const std::size_t start = i_;
    while (true) {
      skip();
      if (at_end() || is_delim(s_[i_])) break;
      const std::size_t at = i_;
      const std::string_view tok = token_at(at);
      if (count == 4) return fail(Status::parse_error, at, "more than 4 numbers in a point");
      T x{};
      const NumberError e = geo_io::parse_real<T>(tok, x);
      if (e == NumberError::syntax) {
        return fail(Status::parse_error, at, "expected a number, found " + geo_io::quote(tok));
      }
      if (e == NumberError::non_finite) {
        return fail(Status::non_finite_input, at,
                    "coordinate " + geo_io::quote(tok) + " is not finite in this precision");
      }
      if (count < 2) v[count] = x;
      ++count;
      i_ = at + tok.size();
    }
    if (count == 0) return expected("a coordinate");
    if (count == 1) return fail(Status::parse_error, start, "a point needs at least 2 numbers");
    if (dims_ == 0) dims_ = count;
    if (count != dims_) {
      return fail(Status::parse_error, start,
                  "point has " + std::to_string(count) + " numbers, expected " +
                      std::to_string(dims_) + " as in the rest of the geometry");
    }
    p = Vec2<T>{v[0], v[1]};
    return true;
  }

  /// '(' point {',' point} ')' appended to out; the offset of '(' in open.
  bool point_list(std::vector<Vec2<T>>& out, std::size_t& open) {
    skip();
    open = i_;
    if (!expect('(', "'('")) return false;
    while (true) {
      if (out.size() >= geo_io::max_points) {
        return fail(Status::parse_error, i_, "more than 2^32 - 1 points in one geometry");
      }
      out.emplace_back();
      if (!point(out.back())) return false;
      skip();
      if (peek(',')) {
        ++i_;
        continue;
      }
      return expect(')', "',' or ')'");
    }
  }

  bool line(std::vector<Vec2<T>>& out) {
    std::size_t open = 0;
    if (!point_list(out, open)) return false;
    if (out.size() < 2) {
      return fail(Status::parse_error, open, "a line string needs at least 2 points");
    }
    return true;
  }

  bool ring(RingPolygon2<T>& poly) {
    const std::size_t begin = poly.points.size();
    std::size_t open = 0;
    if (!point_list(poly.points, open)) return false;
    if (const char* why = geo_io::close_ring(poly.points, begin)) {
      return fail(Status::parse_error, open, why);
    }
    poly.ring_ends.push_back(static_cast<std::uint32_t>(poly.points.size()));
    return true;
  }

  /// Rings of a polygon; EMPTY rings (JTS writes them) are dropped, but not an empty outer
  /// ring followed by holes.
  bool polygon(RingPolygon2<T>& poly) {
    if (!expect('(', "'(' or EMPTY")) return false;
    bool outer_empty = false;
    for (bool first = true;; first = false) {
      skip();
      const std::size_t at = i_;
      if (empty_keyword()) {
        outer_empty = outer_empty || first;
      } else if (outer_empty) {
        return fail(Status::parse_error, at, "a hole after an EMPTY outer ring");
      } else if (!ring(poly)) {
        return false;
      }
      skip();
      if (peek(',')) {
        ++i_;
        continue;
      }
      return expect(')', "',' or ')'");
    }
  }

  bool multi_point(std::vector<Vec2<T>>& out) {
    if (!expect('(', "'(' or EMPTY")) return false;
    while (true) {
      if (!empty_keyword()) {
        if (out.size() >= geo_io::max_points) {
          return fail(Status::parse_error, i_, "more than 2^32 - 1 points in one geometry");
        }
        skip();
        const bool wrapped = peek('(');
        if (wrapped) ++i_;
        out.emplace_back();
        if (!point(out.back())) return false;
        if (wrapped && !expect(')', "')'")) return false;
      }
      skip();
      if (peek(',')) {
        ++i_;
        continue;
      }
      return expect(')', "',' or ')'");
    }
  }

  bool multi_line(std::vector<std::vector<Vec2<T>>>& out) {
    if (!expect('(', "'(' or EMPTY")) return false;
    while (true) {
      if (!empty_keyword()) {
        out.emplace_back();
        if (!line(out.back())) return false;
      }
      skip();
      if (peek(',')) {
        ++i_;
        continue;
      }
      return expect(')', "',' or ')'");
    }
  }

  bool multi_polygon(std::vector<RingPolygon2<T>>& out) {
    if (!expect('(', "'(' or EMPTY")) return false;
    while (true) {
      if (!empty_keyword()) {
        out.emplace_back();
        if (!polygon(out.back())) return false;
        if (out.back().ring_ends.empty()) out.pop_back();
      }
      skip();
      if (peek(',')) {
        ++i_;
        continue;
      }
      return expect(')', "',' or ')'");
    }
  }
};

// ---- writing -------------------------------------------------------------------------------

template <Real T>
void append_point(std::string& s, const Vec2<T>& p) {
  geo_io::append_real(s, p.x);
  s += ' ';
  geo_io::append_real(s, p.y);
}

template <Real T>
void append_points(std::string& s, std::span<const Vec2<T>> v, bool close) {
  s += '(';
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s += ", ";
    append_point(s, v[i]);
  }
  if (close && !v.empty()) {
    s += ", ";
    append_point(s, v[0]);
  }
  s += ')';
}

template <Real T>
void append_polygon(std::string& s, const RingPolygon2<T>& p) {
  s += '(';
  std::size_t begin = 0;
  for (std::size_t k = 0; k < p.ring_ends.size(); ++k) {
    if (k) s += ", ";
    append_points<T>(s, std::span<const Vec2<T>>(p.points.data() + begin, p.ring_ends[k] - begin),
                     true);
    begin = p.ring_ends[k];
  }
  s += ')';
}

template <Real T>
void append_wkt(std::string& s, const Geometry2<T>& g) {
  s += wkt_name(g.type);
  if (g.empty()) {
    s += " EMPTY";
    return;
  }
  s += ' ';
  switch (g.type) {
    case GeometryType::point:
      append_points<T>(s, g.points, false);
      break;
    case GeometryType::line_string:
      append_points<T>(s, g.lines[0], false);
      break;
    case GeometryType::polygon:
      append_polygon(s, g.polygons[0]);
      break;
    case GeometryType::multi_point:
      s += '(';
      for (std::size_t i = 0; i < g.points.size(); ++i) {
        if (i) s += ", ";
        append_points<T>(s, std::span<const Vec2<T>>(&g.points[i], 1), false);
      }
      s += ')';
      break;
    case GeometryType::multi_line_string:
      s += '(';
      for (std::size_t i = 0; i < g.lines.size(); ++i) {
        if (i) s += ", ";
        append_points<T>(s, g.lines[i], false);
      }
      s += ')';
      break;
    case GeometryType::multi_polygon:
      s += '(';
      for (std::size_t i = 0; i < g.polygons.size(); ++i) {
        if (i) s += ", ";
        append_polygon(s, g.polygons[i]);
      }
      s += ')';
      break;
  }
}

}  // namespace

template <Real T>
GeometryReadResult<T> parse_wkt(std::string_view text, std::string_view name) {
  WktReader<T> reader(text);
  std::vector<Geometry2<T>> g = reader.run();
  return geo_io::finish<T>(reader.failure, text, name, std::move(g));
}

template <Real T>
GeometryReadResult<T> read_wkt(const std::filesystem::path& path) {
  const io_detail::FileBytes file = io_detail::read_file_bytes(path);
  if (!file.error.empty()) return geo_io::unreadable<T>(path, file.error);
  return parse_wkt<T>(file.bytes(), path.string());
}

template <Real T>
GeometryWriteResult write_wkt_string(const Geometry2<T>& geometry) {
  GeometryWriteResult r;
  r.status = check_geometry(geometry);
  if (r.status != Status::ok) {
    r.message = geo_io::write_refusal(r.status);
    return r;
  }
  append_wkt(r.data, geometry);
  return r;
}

template <Real T>
GeometryWriteResult write_wkt(const std::filesystem::path& path,
                              std::span<const Geometry2<T>> geometries) {
  GeometryWriteResult r;
  std::string text;
  for (std::size_t i = 0; i < geometries.size(); ++i) {
    r.status = check_geometry(geometries[i]);
    if (r.status != Status::ok) {
      r.message = path.string() + ": geometry " + std::to_string(i) + ": " +
                  geo_io::write_refusal(r.status);
      return r;
    }
    append_wkt(text, geometries[i]);
    text += '\n';
  }
  if (!geo_io::write_file(path, text)) {
    r.status = Status::io_error;
    r.message = path.string() + ": cannot write the file";
    return r;
  }
  r.status = Status::ok;
  return r;
}

template GeometryReadResult<float> parse_wkt<float>(std::string_view, std::string_view);
template GeometryReadResult<double> parse_wkt<double>(std::string_view, std::string_view);
template GeometryReadResult<float> read_wkt<float>(const std::filesystem::path&);
template GeometryReadResult<double> read_wkt<double>(const std::filesystem::path&);
template GeometryWriteResult write_wkt_string(const Geometry2<float>&);
template GeometryWriteResult write_wkt_string(const Geometry2<double>&);
template GeometryWriteResult write_wkt(const std::filesystem::path&,
                                       std::span<const Geometry2<float>>);
template GeometryWriteResult write_wkt(const std::filesystem::path&,
                                       std::span<const Geometry2<double>>);

}  // namespace locus
