// SPDX-License-Identifier: BSL-1.0
// Wavefront OBJ: the v and f statements (io/mesh_io.hpp).

#include "mesh_detail.hpp"

#include <locus/io/mesh_io.hpp>

#include <cstring>
#include <string>

namespace locus::mesh_io {

namespace {

// One slash-separated field of a face corner, resolved to a 0-based index against `count`
// elements defined so far. Positive indices may point forward (checked once the file is read);
// the largest one is remembered with its line.
struct IndexCheck {
  std::uint64_t max = 0;  // largest positive 1-based index
  std::size_t line = 0;
  std::size_t offset = 0;
};

enum class Resolve { ok, syntax, zero, before_start, too_large };

Resolve resolve(std::string_view field, std::uint64_t count, IndexCheck& check, std::size_t line,
                std::size_t offset, std::uint64_t& out) {
  std::int64_t k = 0;
  if (!parse_int(field, k)) return Resolve::syntax;
  if (k == 0) return Resolve::zero;
  if (k < 0) {
    // k >= -2^63 + 1 here? -k may overflow for INT64_MIN; compare without negating.
    if (static_cast<std::uint64_t>(-(k + 1)) >= count) return Resolve::before_start;
    out = count - static_cast<std::uint64_t>(-(k + 1)) - 1;
    return Resolve::ok;
  }
  if (static_cast<std::uint64_t>(k) > max_count) return Resolve::too_large;
  if (static_cast<std::uint64_t>(k) > check.max) check = IndexCheck{std::uint64_t(k), line, offset};
  out = static_cast<std::uint64_t>(k) - 1;
  return Resolve::ok;
}

// Reserves the arrays from a first pass that counts the v and f lines (a memchr per line), so
// that they are allocated once: no copies while growing, no spare capacity (faces are assumed
// triangles; n-gons grow the index array). Bounded by the number of lines, so by the input.
template <Real T>
void reserve_for(std::string_view text, PolygonMesh<T>& m) {
  std::size_t nv = 0, nf = 0;
  const char* p = text.data();
  const char* const end = p + text.size();
  while (p < end) {
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    if (end - p >= 2 && (p[1] == ' ' || p[1] == '\t')) {
      nv += p[0] == 'v';
      nf += p[0] == 'f';
    }
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    if (nl == nullptr) break;
    p = static_cast<const char*>(nl) + 1;
  }
  m.vertices.reserve(nv);
  m.face_offsets.reserve(nf + 1);
  m.face_indices.reserve(3 * nf);
}

}  // namespace

template <Real T>
Parsed<T> read_obj(std::string_view text) {
  Parsed<T> p;
  PolygonMesh<T>& m = p.mesh;
  std::uint64_t vt_count = 0, vn_count = 0;
  IndexCheck check_v, check_vt, check_vn;
  reserve_for(text, m);
  LineReader lines(text);
  std::string_view raw;
  const std::size_t first_nul = text.find('\0');  // found once; its line is the error
  while (lines.next(raw)) {
    const std::size_t ln = lines.line_number();
    const std::size_t at = lines.line_start();
    if (first_nul != std::string_view::npos && first_nul < at + raw.size()) {
      p.fail(Status::parse_error, ln, at, "NUL byte: not a text file");
      return p;
    }
    std::string_view line = strip_comment(raw);
    const std::string_view key = next_token(line);
    if (key == "v") {
      Vec3<T> v{};
      for (int c = 0; c < 3; ++c) {
        const std::string_view tok = next_token(line);
        if (tok.empty()) {
          p.fail(Status::parse_error, ln, at, "vertex with fewer than 3 coordinates");
          return p;
        }
        const NumberError e = parse_real(tok, v[c]);
        if (e == NumberError::syntax) {
          p.fail(Status::parse_error, ln, at, "bad coordinate " + quote(tok));
          return p;
        }
        if (e == NumberError::non_finite) {
          p.fail(Status::non_finite_input, ln, at, "non-finite coordinate " + quote(tok));
          return p;
        }
      }
      if (m.vertices.size() >= max_count) {
        p.fail(Status::parse_error, ln, at, "more than 2^32 - 1 vertices");
        return p;
      }
      m.vertices.push_back(v);
    } else if (key == "vt") {
      ++vt_count;
    } else if (key == "vn") {
      ++vn_count;
    } else if (key == "f" || key == "fo") {
      const std::size_t first = m.face_indices.size();
      for (std::string_view tok = next_token(line); !tok.empty(); tok = next_token(line)) {
        // v, v/vt, v//vn or v/vt/vn.
        std::string_view fields[3];
        int nf = 1;
        const std::size_t s1 = tok.find('/');
        fields[0] = tok.substr(0, s1);
        bool bad = fields[0].empty();
        if (s1 != std::string_view::npos) {
          const std::string_view rest = tok.substr(s1 + 1);
          const std::size_t s2 = rest.find('/');
          fields[1] = rest.substr(0, s2);
          nf = 2;
          if (s2 != std::string_view::npos) {
            fields[2] = rest.substr(s2 + 1);
            nf = 3;
            bad = bad || fields[2].empty() || fields[2].find('/') != std::string_view::npos;
          } else {
            bad = bad || fields[1].empty();
          }
        }
        if (bad) {
          p.fail(Status::parse_error, ln, at, "bad face corner " + quote(tok));
          return p;
        }
        std::uint64_t idx[3] = {0, 0, 0};
        const std::uint64_t counts[3] = {m.vertices.size(), vt_count, vn_count};
        IndexCheck* checks[3] = {&check_v, &check_vt, &check_vn};
        static constexpr const char* what[3] = {"vertex", "texture coordinate", "normal"};
        for (int k = 0; k < nf; ++k) {
          if (k > 0 && fields[k].empty()) continue;
          switch (resolve(fields[k], counts[k], *checks[k], ln, at, idx[k])) {
            case Resolve::ok:
              break;
            case Resolve::syntax:
              p.fail(Status::parse_error, ln, at, "bad face corner " + quote(tok));
              return p;
            case Resolve::zero:
              p.fail(Status::parse_error, ln, at,
                     std::string(what[k]) + " index 0 (indices start at 1)");
              return p;
            case Resolve::before_start:
            case Resolve::too_large:
              p.fail(Status::parse_error, ln, at,
                     std::string(what[k]) + " index " + quote(fields[k]) + " out of range");
              return p;
          }
        }
        if (m.face_indices.size() >= max_count) {
          p.fail(Status::parse_error, ln, at, "more than 2^32 - 1 face indices");
          return p;
        }
        m.face_indices.push_back(static_cast<std::uint32_t>(idx[0]));
      }
      if (m.face_indices.size() - first < 3) {
        p.fail(Status::parse_error, ln, at, "face with fewer than 3 vertices");
        return p;
      }
      m.face_offsets.push_back(static_cast<std::uint32_t>(m.face_indices.size()));
    }
    // Every other statement (vp, l, p, g, o, s, usemtl, mtllib, curves...) carries no geometry
    // of a polygon mesh and is skipped.
  }
  const IndexCheck* checks[3] = {&check_v, &check_vt, &check_vn};
  const std::uint64_t counts[3] = {m.vertices.size(), vt_count, vn_count};
  static constexpr const char* what[3] = {"vertex", "texture coordinate", "normal"};
  for (int k = 0; k < 3; ++k) {
    if (checks[k]->max > counts[k]) {
      p.fail(Status::parse_error, checks[k]->line, checks[k]->offset,
             std::string(what[k]) + " index " + std::to_string(checks[k]->max) +
                 " out of range (the file defines " + std::to_string(counts[k]) + ")");
      return p;
    }
  }
  return p;
}

template <Real T>
void write_obj(const PolygonMesh<T>& mesh, std::string& out) {
  out += "# written by locus\n";
  for (const Vec3<T>& v : mesh.vertices) {
    out += "v ";
    append_real(out, v.x);
    out += ' ';
    append_real(out, v.y);
    out += ' ';
    append_real(out, v.z);
    out += '\n';
  }
  for (std::size_t f = 0; f < face_count(mesh); ++f) {
    out += 'f';
    for (const std::uint32_t i : face(mesh, f)) {
      out += ' ';
      append_uint(out, std::uint64_t(i) + 1);
    }
    out += '\n';
  }
}

template Parsed<float> read_obj<float>(std::string_view);
template Parsed<double> read_obj<double>(std::string_view);
template void write_obj<float>(const PolygonMesh<float>&, std::string&);
template void write_obj<double>(const PolygonMesh<double>&, std::string&);

}  // namespace locus::mesh_io
