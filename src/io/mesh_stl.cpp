// SPDX-License-Identifier: BSL-1.0
// STL: ASCII and binary (io/mesh_io.hpp). Corners with bit-identical coordinates are merged.

#include "mesh_detail.hpp"

#include <locus/io/mesh_io.hpp>

#include <array>
#include <bit>
#include <cstring>
#include <string>
#include <vector>

namespace locus::mesh_io {

namespace {

template <Real T>
using Bits = std::conditional_t<std::is_same_v<T, float>, std::uint32_t, std::uint64_t>;

template <Real T>
struct Key {
  std::array<Bits<T>, 3> b;
  bool operator==(const Key&) const = default;
};

template <Real T>
std::size_t hash_key(const Key<T>& k) noexcept {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (const auto x : k.b) {
    h ^= static_cast<std::uint64_t>(x);
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 32;
  }
  return static_cast<std::size_t>(h);
}

// Gives each distinct corner position one vertex index, in order of first appearance. An
// open-addressing table of vertex indices (linear probing, at most half full, 4 bytes a slot):
// no allocation per vertex, and the keys are the mesh's own vertices.
template <Real T>
class Welder {
 public:
  // expect: the number of triangles; a closed mesh has about half as many vertices.
  Welder(PolygonMesh<T>& m, std::size_t expect) : m_(m) {
    std::size_t cap = 16;
    while (cap < expect) cap <<= 1;
    slots_.assign(cap, 0);
    m_.vertices.reserve(expect / 2 + 4);
  }
  std::uint32_t index(const Vec3<T>& v) {
    const Key<T> k = key(v);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash_key(k) & mask;; i = (i + 1) & mask) {
      const std::uint32_t s = slots_[i];
      if (s == 0) break;
      if (key(m_.vertices[s - 1]) == k) return s - 1;
    }
    const auto id = static_cast<std::uint32_t>(m_.vertices.size());
    m_.vertices.push_back(v);
    if (2 * m_.vertices.size() > slots_.size()) {
      rehash(2 * slots_.size());
    } else {
      place(id);
    }
    return id;
  }

 private:
  static Key<T> key(const Vec3<T>& v) noexcept {
    return Key<T>{
        {std::bit_cast<Bits<T>>(v.x), std::bit_cast<Bits<T>>(v.y), std::bit_cast<Bits<T>>(v.z)}};
  }
  void place(std::uint32_t id) noexcept {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = hash_key(key(m_.vertices[id])) & mask;
    while (slots_[i] != 0) i = (i + 1) & mask;
    slots_[i] = id + 1;
  }
  void rehash(std::size_t cap) {
    slots_.assign(cap, 0);
    for (std::size_t id = 0; id < m_.vertices.size(); ++id) place(static_cast<std::uint32_t>(id));
  }

  PolygonMesh<T>& m_;
  std::vector<std::uint32_t> slots_;
};

// Little-endian 32-bit words, independent of the host's byte order.
std::uint32_t load_le32(const char* p) noexcept {
  const auto b = [&](int i) { return std::uint32_t(static_cast<unsigned char>(p[i])); };
  return b(0) | b(1) << 8 | b(2) << 16 | b(3) << 24;
}
void store_le32(std::string& out, std::uint32_t u) {
  const char b[4] = {char(u & 0xff), char(u >> 8 & 0xff), char(u >> 16 & 0xff), char(u >> 24)};
  out.append(b, 4);
}

bool iequal(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char c = a[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != b[i]) return false;
  }
  return true;
}

template <Real T>
void read_binary(std::string_view bytes, Parsed<T>& p) {
  PolygonMesh<T>& m = p.mesh;
  if (bytes.size() < 84) {
    p.fail(Status::parse_error, 0, bytes.size(),
           "truncated binary STL: " + std::to_string(bytes.size()) + " bytes, the header is 84");
    return;
  }
  const std::uint32_t n = load_le32(bytes.data() + 80);
  const std::uint64_t need = 84 + 50 * std::uint64_t(n);
  if (need > bytes.size()) {
    p.fail(Status::parse_error, 0, 80,
           "truncated binary STL: " + std::to_string(n) + " triangles need " +
               std::to_string(need) + " bytes, the file has " + std::to_string(bytes.size()));
    return;
  }
  if (3 * std::uint64_t(n) > max_count) {
    p.fail(Status::parse_error, 0, 80, "more than 2^32 - 1 corners");
    return;
  }
  Welder<T> weld(m, n);
  m.face_offsets.reserve(std::size_t(n) + 1);
  m.face_indices.reserve(3 * std::size_t(n));
  for (std::uint32_t t = 0; t < n; ++t) {
    const std::size_t base = 84 + 50 * std::size_t(t) + 12;  // skip the normal
    for (int c = 0; c < 3; ++c) {
      Vec3<T> v{};
      for (int k = 0; k < 3; ++k) {
        const std::size_t at = base + 12 * std::size_t(c) + 4 * std::size_t(k);
        const float f = std::bit_cast<float>(load_le32(bytes.data() + at));
        if (!std::isfinite(f)) {
          p.fail(Status::non_finite_input, 0, at, "non-finite coordinate");
          return;
        }
        v[k] = static_cast<T>(f);
      }
      m.face_indices.push_back(weld.index(v));
    }
    m.face_offsets.push_back(static_cast<std::uint32_t>(m.face_indices.size()));
  }
}

template <Real T>
void read_ascii(std::string_view text, Parsed<T>& p) {
  PolygonMesh<T>& m = p.mesh;
  LineReader lines(text);
  std::string_view line;
  const auto next = [&]() {
    std::string_view raw;
    while (lines.next(raw)) {
      if (!blank(raw)) {
        line = raw;
        return true;
      }
    }
    return false;
  };
  const auto fail = [&](std::string reason) {
    return p.fail(Status::parse_error, lines.line_number(), lines.line_start(), std::move(reason));
  };
  // Expects a line whose first tokens are the given keywords; leaves the rest in `line`.
  const auto expect = [&](std::string_view k1, std::string_view k2) {
    if (!next()) return fail("unexpected end of file: expected '" + std::string(k1) + "'");
    const std::string_view a = next_token(line);
    if (!iequal(a, k1)) return fail("expected '" + std::string(k1) + "', found " + quote(a));
    if (!k2.empty()) {
      const std::string_view b = next_token(line);
      if (!iequal(b, k2)) return fail("expected '" + std::string(k2) + "', found " + quote(b));
    }
    return true;
  };
  if (!expect("solid", "")) return;
  // A reservation hint: "facet" starts and ends each triangle (lower case, as writers spell it;
  // other spellings only lose the hint). 'f' occurs in nothing else of a valid file but names.
  std::size_t facets = 0;
  for (std::size_t at = text.find("facet"); at != std::string_view::npos;
       at = text.find("facet", at + 5)) {
    ++facets;
  }
  Welder<T> weld(m, facets / 2);
  m.face_offsets.reserve(facets / 2 + 1);
  m.face_indices.reserve(3 * (facets / 2));
  while (true) {
    if (!next()) {
      fail("unexpected end of file: expected 'facet' or 'endsolid'");
      return;
    }
    const std::string_view key = next_token(line);
    if (iequal(key, "endsolid")) {
      // Some exporters write several solids into one file.
      if (!next()) return;
      const std::string_view k = next_token(line);
      if (!iequal(k, "solid")) {
        fail("expected 'solid' or the end of the file, found " + quote(k));
        return;
      }
      continue;
    }
    if (!iequal(key, "facet")) {
      fail("expected 'facet' or 'endsolid', found " + quote(key));
      return;
    }
    if (!expect("outer", "loop")) return;
    for (int c = 0; c < 3; ++c) {
      if (!expect("vertex", "")) return;
      Vec3<T> v{};
      for (int k = 0; k < 3; ++k) {
        const std::string_view t = next_token(line);
        const NumberError e = parse_real(t, v[k]);
        if (e != NumberError::none) {
          p.fail(
              e == NumberError::syntax ? Status::parse_error : Status::non_finite_input,
              lines.line_number(), lines.line_start(),
              (e == NumberError::syntax ? "bad coordinate " : "non-finite coordinate ") + quote(t));
          return;
        }
      }
      if (m.face_indices.size() >= max_count) {
        fail("more than 2^32 - 1 corners");
        return;
      }
      m.face_indices.push_back(weld.index(v));
    }
    if (!expect("endloop", "") || !expect("endfacet", "")) return;
    m.face_offsets.push_back(static_cast<std::uint32_t>(m.face_indices.size()));
  }
}

}  // namespace

template <Real T>
Parsed<T> read_stl(std::string_view bytes, int encoding) {
  Parsed<T> p;
  if (encoding == 0) {
    // A binary file's size is exactly 84 + 50 n (some writers start its header with "solid").
    bool binary = true;
    if (bytes.size() >= 84) {
      binary = 84 + 50 * std::uint64_t(load_le32(bytes.data() + 80)) == bytes.size();
    }
    if (!binary || bytes.size() < 84) {
      std::string_view t = bytes;
      while (!t.empty() && (is_space(t.front()) || t.front() == '\n')) t.remove_prefix(1);
      binary = !(t.size() >= 5 && iequal(t.substr(0, 5), "solid"));
    }
    encoding = binary ? 2 : 1;
  }
  if (encoding == 2) {
    read_binary(bytes, p);
  } else {
    read_ascii(bytes, p);
  }
  return p;
}

template <Real T>
bool write_stl(const PolygonMesh<T>& mesh, bool binary, std::string& out) {
  const std::size_t nt = fan_triangle_count(mesh);
  const auto tris = fan_triangles(mesh);
  const auto normal = [&](const std::array<std::uint32_t, 3>& t) {
    const Vec3<T>& a = mesh.vertices[t[0]];
    const Vec3<T>& b = mesh.vertices[t[1]];
    const Vec3<T>& c = mesh.vertices[t[2]];
    const double ux = double(b.x) - a.x, uy = double(b.y) - a.y, uz = double(b.z) - a.z;
    const double vx = double(c.x) - a.x, vy = double(c.y) - a.y, vz = double(c.z) - a.z;
    double n[3] = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0) || !std::isfinite(len)) return std::array<T, 3>{0, 0, 0};
    return std::array<T, 3>{T(n[0] / len), T(n[1] / len), T(n[2] / len)};
  };
  if (!binary) {
    out += "solid locus\n";
    for (const auto& t : tris) {
      const auto n = normal(t);
      out += "facet normal ";
      for (int k = 0; k < 3; ++k) {
        if (k) out += ' ';
        append_real(out, n[std::size_t(k)]);
      }
      out += "\n outer loop\n";
      for (const std::uint32_t i : t) {
        const Vec3<T>& v = mesh.vertices[i];
        out += "  vertex ";
        append_real(out, v.x);
        out += ' ';
        append_real(out, v.y);
        out += ' ';
        append_real(out, v.z);
        out += '\n';
      }
      out += " endloop\nendfacet\n";
    }
    out += "endsolid locus\n";
    return true;
  }
  if (nt > 0xffffffffu) return false;
  // The header must not begin with "solid", or readers would take the file for ASCII.
  std::string header = "binary STL written by locus";
  header.resize(80, ' ');
  out += header;
  const auto put32 = [&](std::uint32_t u) { store_le32(out, u); };
  const auto putf = [&](T x) {
    const float f = static_cast<float>(x);
    if (!std::isfinite(f)) return false;
    put32(std::bit_cast<std::uint32_t>(f));
    return true;
  };
  put32(static_cast<std::uint32_t>(nt));
  out.reserve(out.size() + 50 * nt);
  for (const auto& t : tris) {
    const auto n = normal(t);
    for (int k = 0; k < 3; ++k) putf(n[std::size_t(k)]);
    for (const std::uint32_t i : t) {
      const Vec3<T>& v = mesh.vertices[i];
      if (!putf(v.x) || !putf(v.y) || !putf(v.z)) return false;
    }
    out.append(2, '\0');
  }
  return true;
}

template Parsed<float> read_stl<float>(std::string_view, int);
template Parsed<double> read_stl<double>(std::string_view, int);
template bool write_stl<float>(const PolygonMesh<float>&, bool, std::string&);
template bool write_stl<double>(const PolygonMesh<double>&, bool, std::string&);

}  // namespace locus::mesh_io
