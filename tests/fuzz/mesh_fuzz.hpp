// SPDX-License-Identifier: BSL-1.0
#pragma once
// The property every mesh reader is fuzzed for (tests/fuzz/*_fuzz.cpp) and that the corpus
// replay test (tests/io/fuzz_corpus_test.cpp) checks on every committed input: reading any
// bytes, as float and as double, returns (no crash, hang or huge allocation; the sanitizers
// and libFuzzer's limits catch those); an error has a message; an ok mesh is well formed, and
// writing it back in its format and reading that gives the same mesh bit for bit (STL: the
// same triangle corners).

#include <locus/io/mesh_io.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace locus_fuzz {

template <class T>
std::string same_mesh(const locus::PolygonMesh<T>& a, const locus::PolygonMesh<T>& b) {
  if (a.vertices.size() != b.vertices.size()) return "vertex count differs";
  if (!a.vertices.empty() && std::memcmp(a.vertices.data(), b.vertices.data(),
                                         a.vertices.size() * sizeof(a.vertices[0]))) {
    return "vertex bits differ";
  }
  if (a.face_offsets != b.face_offsets || a.face_indices != b.face_indices) return "faces differ";
  return {};
}

template <class T>
std::string same_corners(const locus::PolygonMesh<T>& a, const locus::PolygonMesh<T>& b) {
  const auto ta = locus::fan_triangles(a), tb = locus::fan_triangles(b);
  if (ta.size() != tb.size()) return "triangle count differs";
  for (std::size_t t = 0; t < ta.size(); ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (std::memcmp(&a.vertices[ta[t][k]], &b.vertices[tb[t][k]], sizeof(a.vertices[0]))) {
        return "corner bits differ";
      }
    }
  }
  return {};
}

/// "" when the property holds, else what broke.
template <class T>
std::string check_reader(locus::MeshFormat format, std::string_view bytes) {
  using locus::MeshFormat;
  using locus::Status;
  const auto r = locus::parse_mesh<T>(bytes, format, "fuzz");
  if (r.status != Status::ok) return r.message.empty() ? "error without a message" : "";
  if (locus::check_polygon_mesh(r.mesh) != Status::ok) return "ok result fails check_polygon_mesh";
  MeshFormat out = format;
  if (format == MeshFormat::ply) out = MeshFormat::ply_binary_be;
  if (format == MeshFormat::stl) out = MeshFormat::stl_ascii;  // exact: shortest decimals
  const auto w = locus::write_mesh_string(r.mesh, out);
  if (w.status != Status::ok) return "cannot write back what was read: " + w.message;
  const auto again = locus::parse_mesh<T>(w.data, format, "fuzz-again");
  if (again.status != Status::ok) return "cannot read back what was written: " + again.message;
  if (format == MeshFormat::stl) return same_corners(r.mesh, again.mesh);
  return same_mesh(r.mesh, again.mesh);
}

inline std::string check_both(locus::MeshFormat format, const std::uint8_t* data,
                              std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::string e = check_reader<float>(format, bytes);
  if (e.empty()) e = check_reader<double>(format, bytes);
  return e;
}

}  // namespace locus_fuzz
