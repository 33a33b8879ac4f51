// SPDX-License-Identifier: BSL-1.0
// Mesh file dispatch: format from the name, files in and out, messages (io/mesh_io.hpp).

#include <locus/io/mesh_io.hpp>

#include "file_bytes.hpp"
#include "mesh_detail.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <system_error>

namespace locus {

MeshFormat mesh_format_from_name(std::string_view name) noexcept {
  using io_detail::has_extension;
  if (has_extension(name, "obj")) return MeshFormat::obj;
  if (has_extension(name, "off")) return MeshFormat::off;
  if (has_extension(name, "ply")) return MeshFormat::ply;
  if (has_extension(name, "stl")) return MeshFormat::stl;
  return MeshFormat::from_extension;
}

template <Real T>
MeshReadResult<T> parse_mesh(std::string_view bytes, MeshFormat format, std::string_view name) {
  MeshReadResult<T> r;
  if (format == MeshFormat::from_extension) format = mesh_format_from_name(name);
  mesh_io::Parsed<T> p;
  switch (format) {
    case MeshFormat::from_extension:
      r.status = Status::invalid_input;
      r.message = std::string(name) + ": unknown mesh format (extension not .obj .off .ply .stl)";
      return r;
    case MeshFormat::obj:
      p = mesh_io::read_obj<T>(bytes);
      break;
    case MeshFormat::off:
      p = mesh_io::read_off<T>(bytes);
      break;
    case MeshFormat::ply:
    case MeshFormat::ply_ascii:
    case MeshFormat::ply_binary_le:
    case MeshFormat::ply_binary_be:
      p = mesh_io::read_ply<T>(bytes);
      break;
    case MeshFormat::stl:
      p = mesh_io::read_stl<T>(bytes, 0);
      break;
    case MeshFormat::stl_ascii:
      p = mesh_io::read_stl<T>(bytes, 1);
      break;
    case MeshFormat::stl_binary:
      p = mesh_io::read_stl<T>(bytes, 2);
      break;
  }
  r.status = p.failure.status;
  if (r.status != Status::ok) {
    r.line = p.failure.line;
    r.byte_offset = p.failure.offset;
    r.message = std::string(name);
    if (r.line > 0) {
      r.message += ':' + std::to_string(r.line) + ": ";
    } else {
      r.message += ": byte " + std::to_string(r.byte_offset) + ": ";
    }
    r.message += p.failure.reason;
    return r;
  }
  r.mesh = std::move(p.mesh);
  return r;
}

template <Real T>
MeshReadResult<T> read_mesh(const std::filesystem::path& path, MeshFormat format) {
  MeshReadResult<T> r;
  const std::string name = path.string();
  if (format == MeshFormat::from_extension) {
    format = mesh_format_from_name(name);
    if (format == MeshFormat::from_extension) {
      r.status = Status::invalid_input;
      r.message = name + ": unknown mesh format (extension not .obj .off .ply .stl)";
      return r;
    }
  }
  const io_detail::FileBytes file = io_detail::read_file_bytes(path);
  if (!file.error.empty()) {
    r.status = Status::io_error;
    r.message = name + ": " + file.error;
    return r;
  }
  return parse_mesh<T>(file.bytes(), format, name);
}

template <Real T>
MeshWriteResult write_mesh_string(const PolygonMesh<T>& mesh, MeshFormat format) {
  MeshWriteResult r;
  const Status s = check_polygon_mesh(mesh);
  if (s != Status::ok) {
    r.status = s;
    r.message = s == Status::non_finite_input
                    ? "the mesh has a non-finite coordinate"
                    : "the mesh is malformed (offsets, a face under 3 vertices, or an index)";
    return r;
  }
  r.status = Status::ok;
  switch (format) {
    case MeshFormat::from_extension:
      r.status = Status::invalid_input;
      r.message = "no mesh format given";
      break;
    case MeshFormat::obj:
      mesh_io::write_obj(mesh, r.data);
      break;
    case MeshFormat::off:
      mesh_io::write_off(mesh, r.data);
      break;
    case MeshFormat::ply_ascii:
      mesh_io::write_ply(mesh, 0, r.data);
      break;
    case MeshFormat::ply:
    case MeshFormat::ply_binary_le:
      mesh_io::write_ply(mesh, 1, r.data);
      break;
    case MeshFormat::ply_binary_be:
      mesh_io::write_ply(mesh, 2, r.data);
      break;
    case MeshFormat::stl_ascii:
      mesh_io::write_stl(mesh, false, r.data);
      break;
    case MeshFormat::stl:
    case MeshFormat::stl_binary:
      if (!mesh_io::write_stl(mesh, true, r.data)) {
        r.status = Status::non_finite_input;
        r.message = "a coordinate overflows binary STL's float, or too many triangles";
      }
      break;
  }
  if (r.status != Status::ok) r.data.clear();
  return r;
}

template <Real T>
MeshWriteResult write_mesh(const std::filesystem::path& path, const PolygonMesh<T>& mesh,
                           MeshFormat format) {
  const std::string name = path.string();
  if (format == MeshFormat::from_extension) format = mesh_format_from_name(name);
  if (format == MeshFormat::from_extension) {
    return MeshWriteResult{Status::invalid_input,
                           name + ": unknown mesh format (extension not .obj .off .ply .stl)",
                           {}};
  }
  MeshWriteResult r = write_mesh_string(mesh, format);
  if (r.status != Status::ok) {
    r.message = name + ": " + r.message;
    return r;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(r.data.data(), static_cast<std::streamsize>(r.data.size()));
  out.close();
  r.data.clear();
  if (!out) {
    r.status = Status::io_error;
    r.message = name + ": cannot write the file";
  }
  return r;
}

template MeshReadResult<float> parse_mesh<float>(std::string_view, MeshFormat, std::string_view);
template MeshReadResult<double> parse_mesh<double>(std::string_view, MeshFormat, std::string_view);
template MeshReadResult<float> read_mesh<float>(const std::filesystem::path&, MeshFormat);
template MeshReadResult<double> read_mesh<double>(const std::filesystem::path&, MeshFormat);
template MeshWriteResult write_mesh_string<float>(const PolygonMesh<float>&, MeshFormat);
template MeshWriteResult write_mesh_string<double>(const PolygonMesh<double>&, MeshFormat);
template MeshWriteResult write_mesh<float>(const std::filesystem::path&, const PolygonMesh<float>&,
                                           MeshFormat);
template MeshWriteResult write_mesh<double>(const std::filesystem::path&,
                                            const PolygonMesh<double>&, MeshFormat);

}  // namespace locus
