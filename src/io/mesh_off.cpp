// SPDX-License-Identifier: BSL-1.0
// Object File Format (OFF), ASCII, 3D (io/mesh_io.hpp).

#include "mesh_detail.hpp"

#include <locus/io/mesh_io.hpp>

#include <algorithm>
#include <string>

namespace locus::mesh_io {

template <Real T>
Parsed<T> read_off(std::string_view text) {
  Parsed<T> p;
  PolygonMesh<T>& m = p.mesh;
  LineReader lines(text);
  std::string_view line;
  bool nul = false;
  // The first NUL byte, found once (a line holding it is an error).
  const std::size_t first_nul = text.find('\0');
  // The next line with content, comments removed.
  const auto next_content = [&]() {
    std::string_view raw;
    while (lines.next(raw)) {
      if (first_nul != std::string_view::npos && first_nul < lines.line_start() + raw.size()) {
        nul = true;
        return false;
      }
      line = strip_comment(raw);
      if (!blank(line)) return true;
    }
    return false;
  };
  const auto eof = [&](const std::string& what) {
    if (nul) {
      return p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
                    "NUL byte: not a text file");
    }
    return p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
                  "unexpected end of file: " + what);
  };

  if (!next_content()) {
    eof("no OFF header or counts");
    return p;
  }
  std::string_view rest = line;
  std::string_view tok = next_token(rest);
  std::uint64_t counts[2] = {0, 0};
  std::string_view count_line = line;
  if (tok.size() >= 3 && tok.substr(tok.size() - 3) == "OFF") {
    for (const char c : tok.substr(0, tok.size() - 3)) {
      if (c == '4' || c == 'n') {
        p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
               "header " + quote(tok) + ": only 3D OFF is supported");
        return p;
      }
      if (c != 'S' && c != 'T' && c != 'C' && c != 'N') {
        p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
               "unknown header " + quote(tok));
        return p;
      }
    }
    std::string_view after = rest;
    if (next_token(after) == "BINARY") {
      p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
             "binary OFF is not supported");
      return p;
    }
    if (blank(rest)) {
      if (!next_content()) {
        eof("no counts after the header");
        return p;
      }
      count_line = line;
    } else {
      count_line = rest;
    }
  }
  {
    std::string_view c = count_line;
    for (std::uint64_t& n : counts) {
      const std::string_view t = next_token(c);
      if (!parse_uint(t, n)) {
        p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
               t.empty() ? std::string("missing vertex and face counts")
                         : "bad count " + quote(t) + " (not an OFF file?)");
        return p;
      }
    }
  }
  const std::uint64_t nv = counts[0], nf = counts[1];
  if (nv > max_count) {
    p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
           "vertex count " + std::to_string(nv) + " exceeds 2^32 - 1");
    return p;
  }
  // A face line takes at least 8 bytes ("3 0 1 2\n"; the last maybe without its newline), a
  // vertex line 6 ("0 0 0\n"): a face count beyond that is refused, and nothing is reserved
  // beyond what the rest of the text could hold.
  const std::uint64_t left = lines.remaining();
  if (nf > (left + 1) / 8) {
    p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
           std::to_string(nf) + " faces cannot fit in the remaining " + std::to_string(left) +
               " bytes");
    return p;
  }
  m.vertices.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(nv, lines.remaining() / 6)));
  for (std::uint64_t i = 0; i < nv; ++i) {
    if (!next_content()) {
      eof("expected " + std::to_string(nv) + " vertices, found " + std::to_string(i));
      return p;
    }
    std::string_view l = line;
    Vec3<T> v{};
    for (int c = 0; c < 3; ++c) {
      const std::string_view t = next_token(l);
      if (t.empty()) {
        p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
               "vertex with fewer than 3 coordinates");
        return p;
      }
      const NumberError e = parse_real(t, v[c]);
      if (e != NumberError::none) {
        p.fail(
            e == NumberError::syntax ? Status::parse_error : Status::non_finite_input,
            lines.line_number(), lines.line_start(),
            (e == NumberError::syntax ? "bad coordinate " : "non-finite coordinate ") + quote(t));
        return p;
      }
    }
    m.vertices.push_back(v);  // colours, normals and texture coordinates that follow: ignored
  }
  m.face_offsets.reserve(
      static_cast<std::size_t>(std::min<std::uint64_t>(nf, lines.remaining() / 8)) + 1);
  // Triangles are the common case; an index takes at least 2 bytes of text.
  m.face_indices.reserve(
      static_cast<std::size_t>(std::min<std::uint64_t>(3 * nf, lines.remaining() / 2)));
  for (std::uint64_t f = 0; f < nf; ++f) {
    if (!next_content()) {
      eof("expected " + std::to_string(nf) + " faces, found " + std::to_string(f));
      return p;
    }
    std::string_view l = line;
    const std::string_view t = next_token(l);
    std::uint64_t n = 0;
    if (!parse_uint(t, n)) {
      p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
             "bad face size " + quote(t));
      return p;
    }
    if (n < 3) {
      p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
             "face with fewer than 3 vertices");
      return p;
    }
    // The loop ends at the first missing index, so a huge n costs only the line's length.
    for (std::uint64_t k = 0; k < n; ++k) {
      const std::string_view it = next_token(l);
      std::uint64_t idx = 0;
      if (it.empty()) {
        p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
               "face announces " + std::to_string(n) + " vertices, the line lists " +
                   std::to_string(k));
        return p;
      }
      if (!parse_uint(it, idx)) {
        p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
               "bad vertex index " + quote(it));
        return p;
      }
      if (idx >= nv) {
        p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
               "vertex index " + std::to_string(idx) + " out of range (" + std::to_string(nv) +
                   " vertices)");
        return p;
      }
      if (m.face_indices.size() >= max_count) {
        p.fail(Status::parse_error, lines.line_number(), lines.line_start(),
               "more than 2^32 - 1 face indices");
        return p;
      }
      m.face_indices.push_back(static_cast<std::uint32_t>(idx));
    }
    m.face_offsets.push_back(static_cast<std::uint32_t>(m.face_indices.size()));
  }
  return p;  // edges and anything after the faces are not part of the mesh
}

template <Real T>
void write_off(const PolygonMesh<T>& mesh, std::string& out) {
  out += "OFF\n";
  append_uint(out, mesh.vertices.size());
  out += ' ';
  append_uint(out, face_count(mesh));
  out += " 0\n";
  for (const Vec3<T>& v : mesh.vertices) {
    append_real(out, v.x);
    out += ' ';
    append_real(out, v.y);
    out += ' ';
    append_real(out, v.z);
    out += '\n';
  }
  for (std::size_t f = 0; f < face_count(mesh); ++f) {
    const auto fv = face(mesh, f);
    append_uint(out, fv.size());
    for (const std::uint32_t i : fv) {
      out += ' ';
      append_uint(out, i);
    }
    out += '\n';
  }
}

template Parsed<float> read_off<float>(std::string_view);
template Parsed<double> read_off<double>(std::string_view);
template void write_off<float>(const PolygonMesh<float>&, std::string&);
template void write_off<double>(const PolygonMesh<double>&, std::string&);

}  // namespace locus::mesh_io
