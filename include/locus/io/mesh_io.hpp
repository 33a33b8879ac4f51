// SPDX-License-Identifier: BSL-1.0
#pragma once
// Mesh files: read and write PolygonMesh (mesh/polygon_mesh.hpp) as OBJ, OFF, PLY (ASCII,
// binary little and big endian) and STL (ASCII and binary). Compiled once for float and double.
//
// Reading: read_mesh(path) or parse_mesh(bytes, format, name). OBJ: v (x y z; w and colours
// ignored), f with v, v/vt, v//vn, v/vt/vn corners, negative (relative) indices, n-gons; every
// other statement is ignored. OFF: [C][N][ST]OFF header (optional), counts on the header line or
// the next, trailing colours ignored; 4OFF, nOFF and binary OFF are parse errors. PLY: x y z of
// any numeric type, the face list vertex_indices (or vertex_index) of any integer count and
// index type; other elements and properties are skipped. STL: ASCII (keywords in any case) or
// binary, told apart by size and content; corners with bit-identical coordinates are merged into
// one vertex, numbered by first appearance. LF or CRLF line ends; '#' comments in OBJ and OFF.
// Errors: the result's status is parse_error (malformed, truncated, an index out of range, a
// count the remaining bytes cannot hold, more than 2^32 - 1 vertices or indices),
// non_finite_input (a NaN, infinite or overflowing coordinate), io_error (unreadable file) or
// invalid_input (format unknown); message = "name:line: reason" (text) or "name: byte N:
// reason" (binary), with line / byte_offset set. Never allocates more than a constant times the
// input size; reads in O(input).
// Writing: write_mesh(path, mesh) or write_mesh_string(mesh, format). Numbers are printed in the
// shortest form that reads back exactly (std::to_chars), binary PLY stores T, so every round trip
// is bit-exact; STL stores triangles (faces are fanned, binary STL rounds to float) with normals
// from the corner cross product. A mesh that fails check_polygon_mesh() is refused with its
// status. Format by extension (.obj .off .ply .stl, any case; .ply and .stl write binary) or
// given.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/mesh/polygon_mesh.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace locus {

/// A mesh file format. For reading, the ply_* and stl_* encodings behave like ply (the header
/// tells the encoding) and, for STL, force the ASCII or binary parser.
enum class MeshFormat : std::uint8_t {
  from_extension,  ///< from the file name: .obj .off .ply .stl (case-insensitive)
  obj,
  off,
  ply,  ///< reading: any encoding; writing: binary little endian
  ply_ascii,
  ply_binary_le,
  ply_binary_be,
  stl,  ///< reading: ASCII or binary, detected; writing: binary
  stl_ascii,
  stl_binary,
};

template <Real T>
struct MeshReadResult {
  Status status = Status::empty_input;
  std::string message;          ///< empty when ok; else "name:line: reason" / "name: byte N: ..."
  std::size_t line = 0;         ///< 1-based line of the error in a text file, 0 otherwise
  std::size_t byte_offset = 0;  ///< offset of the error from the start of the input
  PolygonMesh<T> mesh;          ///< the mesh read (unspecified unless status == ok)
};

struct MeshWriteResult {
  Status status = Status::empty_input;
  std::string message;  ///< empty when ok
  std::string data;     ///< the file's bytes (write_mesh_string only)
};

/// The format a file name's extension names, or from_extension when it names none.
[[nodiscard]] MeshFormat mesh_format_from_name(std::string_view name) noexcept;

/// Reads a mesh file.
template <Real T>
[[nodiscard]] MeshReadResult<T> read_mesh(const std::filesystem::path& path,
                                          MeshFormat format = MeshFormat::from_extension);

/// Reads a mesh from memory; name is used in messages and, with from_extension, for the format.
template <Real T>
[[nodiscard]] MeshReadResult<T> parse_mesh(std::string_view bytes, MeshFormat format,
                                           std::string_view name = "<memory>");
template <Real T>
[[nodiscard]] MeshReadResult<T> parse_mesh(std::span<const std::byte> bytes, MeshFormat format,
                                           std::string_view name = "<memory>") {
  return parse_mesh<T>(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                       format, name);
}

/// Writes a mesh file (status io_error when it cannot be written).
template <Real T>
[[nodiscard]] MeshWriteResult write_mesh(const std::filesystem::path& path,
                                         const PolygonMesh<T>& mesh,
                                         MeshFormat format = MeshFormat::from_extension);

/// The bytes of a mesh file in memory (result.data); format must name one (not from_extension).
template <Real T>
[[nodiscard]] MeshWriteResult write_mesh_string(const PolygonMesh<T>& mesh, MeshFormat format);

}  // namespace locus
