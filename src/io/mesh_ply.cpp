// SPDX-License-Identifier: BSL-1.0
// Stanford PLY: ASCII, binary little endian and binary big endian (io/mesh_io.hpp).

#include "mesh_detail.hpp"

#include <locus/io/mesh_io.hpp>

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>
#include <vector>

namespace locus::mesh_io {

namespace {

enum class PlyType : std::uint8_t { none, i8, u8, i16, u16, i32, u32, f32, f64 };

PlyType parse_type(std::string_view s) noexcept {
  if (s == "char" || s == "int8") return PlyType::i8;
  if (s == "uchar" || s == "uint8") return PlyType::u8;
  if (s == "short" || s == "int16") return PlyType::i16;
  if (s == "ushort" || s == "uint16") return PlyType::u16;
  if (s == "int" || s == "int32") return PlyType::i32;
  if (s == "uint" || s == "uint32") return PlyType::u32;
  if (s == "float" || s == "float32") return PlyType::f32;
  if (s == "double" || s == "float64") return PlyType::f64;
  return PlyType::none;
}

std::size_t type_size(PlyType t) noexcept {
  switch (t) {
    case PlyType::i8:
    case PlyType::u8:
      return 1;
    case PlyType::i16:
    case PlyType::u16:
      return 2;
    case PlyType::i32:
    case PlyType::u32:
    case PlyType::f32:
      return 4;
    case PlyType::f64:
      return 8;
    case PlyType::none:
      break;
  }
  return 0;
}

bool is_integer(PlyType t) noexcept { return t != PlyType::f32 && t != PlyType::f64; }

struct Property {
  std::string name;
  PlyType type = PlyType::none;        // the scalar, or the items of a list
  PlyType count_type = PlyType::none;  // the list length; none for a scalar property
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
  std::size_t line = 0;
};

enum class Encoding { ascii, little, big };

// A value of type t stored at p in the file's byte order (the caller checked the bounds).
template <class U>
U load(const char* p, bool swap) noexcept {
  char b[sizeof(U)];
  std::memcpy(b, p, sizeof(U));
  if (swap) std::reverse(b, b + sizeof(U));
  U u;
  std::memcpy(&u, b, sizeof(U));
  return u;
}

double load_real(const char* p, PlyType t, bool swap) noexcept {
  switch (t) {
    case PlyType::i8:
      return load<std::int8_t>(p, swap);
    case PlyType::u8:
      return load<std::uint8_t>(p, swap);
    case PlyType::i16:
      return load<std::int16_t>(p, swap);
    case PlyType::u16:
      return load<std::uint16_t>(p, swap);
    case PlyType::i32:
      return load<std::int32_t>(p, swap);
    case PlyType::u32:
      return load<std::uint32_t>(p, swap);
    case PlyType::f32:
      return static_cast<double>(load<float>(p, swap));
    case PlyType::f64:
      return load<double>(p, swap);
    case PlyType::none:
      break;
  }
  return 0;
}

std::int64_t load_int(const char* p, PlyType t, bool swap) noexcept {
  switch (t) {
    case PlyType::i8:
      return load<std::int8_t>(p, swap);
    case PlyType::u8:
      return load<std::uint8_t>(p, swap);
    case PlyType::i16:
      return load<std::int16_t>(p, swap);
    case PlyType::u16:
      return load<std::uint16_t>(p, swap);
    case PlyType::i32:
      return load<std::int32_t>(p, swap);
    case PlyType::u32:
      return load<std::uint32_t>(p, swap);
    default:
      break;
  }
  return -1;
}

// Tokens of an ASCII body, across lines, counting lines for messages.
class Tokens {
 public:
  Tokens(std::string_view text, std::size_t pos, std::size_t line) noexcept
      : text_(text), pos_(pos), line_(line) {}
  std::string_view next() noexcept {
    while (pos_ < text_.size() && (is_space(text_[pos_]) || text_[pos_] == '\n')) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    const std::size_t b = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    if (pos_ > b) last_line_ = line_;
    return text_.substr(b, pos_ - b);
  }
  /// The line of the last token returned (for errors at the end of the text).
  [[nodiscard]] std::size_t last_line() const noexcept { return last_line_; }
  [[nodiscard]] std::size_t line() const noexcept { return line_; }
  [[nodiscard]] std::size_t pos() const noexcept { return pos_; }
  [[nodiscard]] std::size_t remaining() const noexcept { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_;
  std::size_t line_;
  std::size_t last_line_ = line_;
};

}  // namespace

template <Real T>
Parsed<T> read_ply(std::string_view bytes) {
  Parsed<T> p;
  PolygonMesh<T>& m = p.mesh;
  LineReader lines(bytes);
  std::string_view raw;
  const auto hfail = [&](std::string reason) {
    return p.fail(Status::parse_error, lines.line_number(), lines.line_start(), std::move(reason));
  };
  if (!lines.next(raw) || next_token(raw) != "ply" || !blank(raw)) {
    hfail("not a PLY file (no 'ply' line)");
    return p;
  }
  Encoding enc = Encoding::ascii;
  bool have_format = false, ended = false;
  std::vector<Element> elements;
  while (!ended && lines.next(raw)) {
    std::string_view l = raw;
    const std::string_view key = next_token(l);
    if (key == "comment" || key == "obj_info" || key.empty()) continue;
    if (key == "end_header") {
      ended = true;
    } else if (key == "format") {
      const std::string_view f = next_token(l);
      if (f == "ascii") {
        enc = Encoding::ascii;
      } else if (f == "binary_little_endian") {
        enc = Encoding::little;
      } else if (f == "binary_big_endian") {
        enc = Encoding::big;
      } else {
        hfail("unknown format " + quote(f));
        return p;
      }
      have_format = true;
    } else if (key == "element") {
      Element e;
      e.name = std::string(next_token(l));
      const std::string_view c = next_token(l);
      if (e.name.empty() || !parse_uint(c, e.count)) {
        hfail("bad element line");
        return p;
      }
      e.line = lines.line_number();
      elements.push_back(std::move(e));
    } else if (key == "property") {
      if (elements.empty()) {
        hfail("property before any element");
        return p;
      }
      Property prop;
      const std::string_view t = next_token(l);
      if (t == "list") {
        prop.count_type = parse_type(next_token(l));
        prop.type = parse_type(next_token(l));
        if (prop.count_type == PlyType::none || prop.type == PlyType::none ||
            !is_integer(prop.count_type)) {
          hfail("bad list property types");
          return p;
        }
      } else {
        prop.type = parse_type(t);
        if (prop.type == PlyType::none) {
          hfail("unknown property type " + quote(t));
          return p;
        }
      }
      prop.name = std::string(next_token(l));
      if (prop.name.empty()) {
        hfail("property without a name");
        return p;
      }
      elements.back().props.push_back(std::move(prop));
    } else {
      hfail("unknown header keyword " + quote(key));
      return p;
    }
  }
  if (!ended) {
    hfail("unexpected end of file in the header (no end_header)");
    return p;
  }
  if (!have_format) {
    hfail("no format line");
    return p;
  }

  // Which element holds the vertices and faces, and which properties they need.
  std::uint64_t nv = 0;
  bool have_vertex = false;
  for (const Element& e : elements) {
    if (e.name == "vertex") {
      if (have_vertex) {
        p.fail(Status::parse_error, e.line, 0, "two vertex elements");
        return p;
      }
      have_vertex = true;
      nv = e.count;
      if (nv > max_count) {
        p.fail(Status::parse_error, e.line, 0,
               "vertex count " + std::to_string(nv) + " exceeds 2^32 - 1");
        return p;
      }
      for (const char* axis : {"x", "y", "z"}) {
        const auto it = std::find_if(e.props.begin(), e.props.end(),
                                     [&](const Property& q) { return q.name == axis; });
        if (it == e.props.end() || it->count_type != PlyType::none) {
          p.fail(Status::parse_error, e.line, 0,
                 std::string("vertex element has no scalar property ") + axis);
          return p;
        }
      }
    } else if (e.name == "face") {
      const auto it = std::find_if(e.props.begin(), e.props.end(), [](const Property& q) {
        return q.name == "vertex_indices" || q.name == "vertex_index";
      });
      if (it == e.props.end() || it->count_type == PlyType::none || !is_integer(it->type)) {
        p.fail(Status::parse_error, e.line, 0,
               "face element has no integer list property vertex_indices");
        return p;
      }
    }
  }
  if (!have_vertex) {
    p.fail(Status::parse_error, lines.line_number(), lines.line_start(), "no vertex element");
    return p;
  }

  // role of a property: 0..2 coordinate, 3 face indices, -1 skipped
  const auto role = [](const Element& e, const Property& q) {
    if (e.name == "vertex" && q.count_type == PlyType::none) {
      if (q.name == "x") return 0;
      if (q.name == "y") return 1;
      if (q.name == "z") return 2;
    }
    if (e.name == "face" && q.count_type != PlyType::none &&
        (q.name == "vertex_indices" || q.name == "vertex_index")) {
      return 3;
    }
    return -1;
  };

  const std::size_t body = lines.position();
  if (enc == Encoding::ascii) {
    Tokens tok(bytes, body, lines.line_number() + 1);
    for (const Element& e : elements) {
      if (e.props.empty()) continue;
      const std::uint64_t k = e.props.size();
      if (e.count > (tok.remaining() + 1) / (2 * k)) {
        p.fail(Status::parse_error, e.line, tok.pos(),
               "element '" + e.name + "' announces " + std::to_string(e.count) +
                   " records, more than the remaining " + std::to_string(tok.remaining()) +
                   " bytes can hold");
        return p;
      }
      const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
      if (is_vertex) m.vertices.reserve(static_cast<std::size_t>(e.count));
      if (is_face) {
        m.face_offsets.reserve(static_cast<std::size_t>(e.count) + 1);
        // Triangles are the common case; an index takes at least 2 bytes of text.
        m.face_indices.reserve(
            static_cast<std::size_t>(std::min<std::uint64_t>(3 * e.count, tok.remaining() / 2)));
      }
      std::vector<int> roles;
      for (const Property& q : e.props) roles.push_back(role(e, q));
      for (std::uint64_t r = 0; r < e.count; ++r) {
        Vec3<T> v{};
        for (std::size_t j = 0; j < e.props.size(); ++j) {
          const Property& q = e.props[j];
          const std::string_view t = tok.next();
          if (t.empty()) {
            p.fail(
                Status::parse_error, tok.line(), tok.pos(),
                "unexpected end of file in element '" + e.name + "' record " + std::to_string(r));
            return p;
          }
          if (roles[j] >= 0 && roles[j] < 3) {
            const NumberError ne = parse_real(t, v[roles[j]]);
            if (ne != NumberError::none) {
              p.fail(ne == NumberError::syntax ? Status::parse_error : Status::non_finite_input,
                     tok.line(), tok.pos() - t.size(),
                     (ne == NumberError::syntax ? "bad coordinate " : "non-finite coordinate ") +
                         quote(t));
              return p;
            }
            continue;
          }
          if (q.count_type == PlyType::none) continue;  // a skipped scalar
          std::uint64_t n = 0;
          if (!parse_uint(t, n)) {
            p.fail(Status::parse_error, tok.line(), tok.pos() - t.size(),
                   "bad list length " + quote(t));
            return p;
          }
          if (roles[j] == 3 && n < 3) {
            p.fail(Status::parse_error, tok.line(), tok.pos() - t.size(),
                   "face with fewer than 3 vertices");
            return p;
          }
          // Each item is a token: a huge n stops at the end of the text.
          for (std::uint64_t i = 0; i < n; ++i) {
            const std::string_view it = tok.next();
            if (it.empty()) {
              p.fail(Status::parse_error, tok.last_line(), tok.pos(),
                     "unexpected end of file in a list of " + std::to_string(n) + " items");
              return p;
            }
            if (roles[j] != 3) continue;
            std::int64_t idx = 0;
            if (!parse_int(it, idx)) {
              p.fail(Status::parse_error, tok.line(), tok.pos() - it.size(),
                     "bad vertex index " + quote(it));
              return p;
            }
            if (idx < 0 || static_cast<std::uint64_t>(idx) >= nv) {
              p.fail(Status::parse_error, tok.line(), tok.pos() - it.size(),
                     "vertex index " + std::to_string(idx) + " out of range (" +
                         std::to_string(nv) + " vertices)");
              return p;
            }
            if (m.face_indices.size() >= max_count) {
              p.fail(Status::parse_error, tok.line(), tok.pos(), "more than 2^32 - 1 indices");
              return p;
            }
            m.face_indices.push_back(static_cast<std::uint32_t>(idx));
          }
          if (roles[j] == 3) {
            m.face_offsets.push_back(static_cast<std::uint32_t>(m.face_indices.size()));
          }
        }
        if (is_vertex) m.vertices.push_back(v);
      }
    }
    return p;
  }

  const bool swap = (enc == Encoding::big) != (std::endian::native == std::endian::big);
  const char* const data = bytes.data();
  std::size_t pos = body;
  for (const Element& e : elements) {
    if (e.props.empty()) continue;
    std::size_t min_size = 0;
    for (const Property& q : e.props) {
      min_size += type_size(q.count_type == PlyType::none ? q.type : q.count_type);
    }
    const std::size_t left = bytes.size() - pos;
    if (e.count > left / min_size) {
      p.fail(Status::parse_error, 0, pos,
             "element '" + e.name + "' announces " + std::to_string(e.count) + " records of " +
                 std::to_string(min_size) + "+ bytes, only " + std::to_string(left) +
                 " bytes remain");
      return p;
    }
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    if (is_vertex) m.vertices.reserve(static_cast<std::size_t>(e.count));
    if (is_face) {
      m.face_offsets.reserve(static_cast<std::size_t>(e.count) + 1);
      // Triangles are the common case; an index takes at least 1 byte.
      m.face_indices.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(3 * e.count, left)));
    }
    std::vector<int> roles;
    for (const Property& q : e.props) roles.push_back(role(e, q));
    for (std::uint64_t r = 0; r < e.count; ++r) {
      Vec3<T> v{};
      for (std::size_t j = 0; j < e.props.size(); ++j) {
        const Property& q = e.props[j];
        if (q.count_type == PlyType::none) {
          const std::size_t sz = type_size(q.type);
          if (bytes.size() - pos < sz) {
            p.fail(Status::parse_error, 0, pos, "truncated in element '" + e.name + "'");
            return p;
          }
          if (roles[j] >= 0) {
            const T c = static_cast<T>(load_real(data + pos, q.type, swap));
            if (!std::isfinite(c)) {
              p.fail(Status::non_finite_input, 0, pos, "non-finite coordinate");
              return p;
            }
            v[roles[j]] = c;
          }
          pos += sz;
          continue;
        }
        const std::size_t csz = type_size(q.count_type), isz = type_size(q.type);
        if (bytes.size() - pos < csz) {
          p.fail(Status::parse_error, 0, pos, "truncated in element '" + e.name + "'");
          return p;
        }
        const std::int64_t n = load_int(data + pos, q.count_type, swap);
        if (n < 0) {
          p.fail(Status::parse_error, 0, pos, "negative list length");
          return p;
        }
        const std::uint64_t un = static_cast<std::uint64_t>(n);
        if (roles[j] == 3 && un < 3) {
          p.fail(Status::parse_error, 0, pos, "face with fewer than 3 vertices");
          return p;
        }
        pos += csz;
        if (un > (bytes.size() - pos) / isz) {
          p.fail(Status::parse_error, 0, pos - csz,
                 "list of " + std::to_string(un) + " items runs past the end of the file");
          return p;
        }
        if (roles[j] == 3) {
          if (m.face_indices.size() + un > max_count) {
            p.fail(Status::parse_error, 0, pos, "more than 2^32 - 1 indices");
            return p;
          }
          for (std::uint64_t i = 0; i < un; ++i, pos += isz) {
            const std::int64_t idx = load_int(data + pos, q.type, swap);
            if (idx < 0 || static_cast<std::uint64_t>(idx) >= nv) {
              p.fail(Status::parse_error, 0, pos,
                     "vertex index " + std::to_string(idx) + " out of range (" +
                         std::to_string(nv) + " vertices)");
              return p;
            }
            m.face_indices.push_back(static_cast<std::uint32_t>(idx));
          }
          m.face_offsets.push_back(static_cast<std::uint32_t>(m.face_indices.size()));
        } else {
          pos += static_cast<std::size_t>(un) * isz;
        }
      }
      if (is_vertex) m.vertices.push_back(v);
    }
  }
  return p;  // bytes after the last element are ignored
}

namespace {

template <class U>
void store(std::string& out, U u, bool big) {
  char b[sizeof(U)];
  std::memcpy(b, &u, sizeof(U));
  if (big != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(U));
  out.append(b, sizeof(U));
}

}  // namespace

template <Real T>
void write_ply(const PolygonMesh<T>& mesh, int encoding, std::string& out) {
  const std::size_t nf = face_count(mesh);
  std::size_t max_face = 0;
  for (std::size_t f = 0; f < nf; ++f) max_face = std::max(max_face, face(mesh, f).size());
  const bool wide_count = max_face > 255;
  const bool wide_index = mesh.vertices.size() > 0x7fffffffu;
  const char* scalar = std::is_same_v<T, float> ? "float" : "double";
  out += "ply\nformat ";
  out += encoding == 0 ? "ascii" : encoding == 1 ? "binary_little_endian" : "binary_big_endian";
  out += " 1.0\ncomment written by locus\nelement vertex ";
  append_uint(out, mesh.vertices.size());
  for (const char* axis : {"x", "y", "z"}) {
    out += "\nproperty ";
    out += scalar;
    out += ' ';
    out += axis;
  }
  out += "\nelement face ";
  append_uint(out, nf);
  out += "\nproperty list ";
  out += wide_count ? "uint " : "uchar ";
  out += wide_index ? "uint" : "int";
  out += " vertex_indices\nend_header\n";
  if (encoding == 0) {
    for (const Vec3<T>& v : mesh.vertices) {
      append_real(out, v.x);
      out += ' ';
      append_real(out, v.y);
      out += ' ';
      append_real(out, v.z);
      out += '\n';
    }
    for (std::size_t f = 0; f < nf; ++f) {
      const auto fv = face(mesh, f);
      append_uint(out, fv.size());
      for (const std::uint32_t i : fv) {
        out += ' ';
        append_uint(out, i);
      }
      out += '\n';
    }
    return;
  }
  const bool big = encoding == 2;
  out.reserve(out.size() + mesh.vertices.size() * 3 * sizeof(T) + nf * 4 +
              mesh.face_indices.size() * 4);
  for (const Vec3<T>& v : mesh.vertices) {
    store(out, v.x, big);
    store(out, v.y, big);
    store(out, v.z, big);
  }
  for (std::size_t f = 0; f < nf; ++f) {
    const auto fv = face(mesh, f);
    if (wide_count) {
      store(out, static_cast<std::uint32_t>(fv.size()), big);
    } else {
      store(out, static_cast<std::uint8_t>(fv.size()), big);
    }
    for (const std::uint32_t i : fv) store(out, i, big);  // int and uint share the bytes
  }
}

template Parsed<float> read_ply<float>(std::string_view);
template Parsed<double> read_ply<double>(std::string_view);
template void write_ply<float>(const PolygonMesh<float>&, int, std::string&);
template void write_ply<double>(const PolygonMesh<double>&, int, std::string&);

}  // namespace locus::mesh_io
