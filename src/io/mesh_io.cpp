// SPDX-License-Identifier: BSL-1.0
// Mesh file dispatch: format from the name, files in and out, messages (io/mesh_io.hpp).

#include <locus/io/mesh_io.hpp>

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

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#define LOCUS_MESH_IO_POSIX 1
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace locus {

namespace {

// The bytes of a file, read into a buffer that is not zero-filled first. The file is read as it
// is when opened: at most the size fstat reports then; if it shrinks meanwhile, the bytes read
// are kept (the parser then reports the truncation), and if it grows, the rest is not read. No
// mapping, so a file truncated by another process gives short reads rather than SIGBUS.
struct FileBytes {
  std::unique_ptr<char[]> data;
  std::size_t size = 0;
  std::string error;  // empty when read
};

// A buffer of n bytes, nullptr when it cannot be allocated.
std::unique_ptr<char[]> uninitialised_buffer(std::size_t n) noexcept {
  try {
    return std::make_unique_for_overwrite<char[]>(n);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

std::string size_error(std::uintmax_t size) {
  return "cannot allocate " + std::to_string(size) + " bytes to read the file";
}

#if defined(LOCUS_MESH_IO_POSIX)
// The buffer's pages are first touched by read(), one page fault each; at 4 KiB a page the faults
// cost several times the copy itself (bench/results/io.md). Transparent huge pages cut them
// 512-fold, so the 2 MiB-aligned interior of a buffer of 4 MiB or more is advised to use them
// (such blocks are the allocator's own mappings). Advice only: ignored where unsupported.
void advise_huge_pages([[maybe_unused]] char* p, [[maybe_unused]] std::size_t n) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t(1) << 21;
  if (n < 2 * huge) return;
  const auto first = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t begin = (first + huge - 1) & ~(huge - 1);
  const std::uintptr_t end = (first + n) & ~(huge - 1);
  if (end > begin) (void)::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
}

FileBytes read_file_bytes(const std::filesystem::path& path) {
  FileBytes out;
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer. The type is taken
  // from the open descriptor, so the file checked is the file read.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    out.error = "cannot open the file (" + std::generic_category().message(errno) + ")";
    return out;
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    out.error = "cannot read the file (" + std::generic_category().message(errno) + ")";
    return out;
  }
  // A directory, FIFO, socket or device has no length to read up to (/dev/zero has no end).
  if (!S_ISREG(st.st_mode)) {
    out.error = "cannot read the file (not a regular file)";
    return out;
  }
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (st.st_size < 0 || size > std::uintmax_t(std::numeric_limits<std::ptrdiff_t>::max())) {
    out.error = size_error(size);
    return out;
  }
  const auto n = static_cast<std::size_t>(size);
  out.data = uninitialised_buffer(n);
  if (!out.data) {
    out.error = size_error(size);
    return out;
  }
  advise_huge_pages(out.data.get(), n);
  // Linux moves at most 0x7ffff000 bytes a call; any call may return fewer than asked.
  constexpr std::size_t chunk = std::size_t(1) << 30;
  while (out.size < n) {
    const std::size_t want = std::min(n - out.size, chunk);
    const ::ssize_t got = ::read(fd, out.data.get() + out.size, want);
    if (got < 0) {
      if (errno == EINTR) continue;
      out.error = "cannot read the file (" + std::generic_category().message(errno) + ")";
      return out;
    }
    if (got == 0) break;  // the file shrank since fstat
    out.size += static_cast<std::size_t>(got);
  }
  return out;
}
#else
FileBytes read_file_bytes(const std::filesystem::path& path) {
  FileBytes out;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || ec) {
    out.error = "cannot read the file (missing, or not a regular file)";
    return out;
  }
  std::FILE* file = std::fopen(path.string().c_str(), "rb");
  if (file == nullptr) {
    out.error = "cannot open the file";
    return out;
  }
  struct Closer {
    std::FILE* file;
    ~Closer() { std::fclose(file); }
  } closer{file};
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > std::uintmax_t(std::numeric_limits<std::ptrdiff_t>::max())) {
    out.error = ec ? "cannot read the file" : size_error(size);
    return out;
  }
  const auto n = static_cast<std::size_t>(size);
  out.data = uninitialised_buffer(n);
  if (!out.data) {
    out.error = size_error(size);
    return out;
  }
  while (out.size < n) {
    const std::size_t got = std::fread(out.data.get() + out.size, 1, n - out.size, file);
    out.size += got;
    if (got == 0) break;  // end of file (the file shrank) or an error, told apart below
  }
  if (std::ferror(file)) out.error = "cannot read the file";
  return out;
}
#endif

}  // namespace

MeshFormat mesh_format_from_name(std::string_view name) noexcept {
  const std::size_t dot = name.rfind('.');
  const std::size_t sep = name.find_last_of("/\\");
  if (dot == std::string_view::npos || (sep != std::string_view::npos && dot < sep)) {
    return MeshFormat::from_extension;
  }
  const std::string_view ext = name.substr(dot + 1);
  if (ext.size() != 3) return MeshFormat::from_extension;
  char e[3];
  for (int i = 0; i < 3; ++i) {
    const char c = ext[std::size_t(i)];
    e[i] = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  const std::string_view x(e, 3);
  if (x == "obj") return MeshFormat::obj;
  if (x == "off") return MeshFormat::off;
  if (x == "ply") return MeshFormat::ply;
  if (x == "stl") return MeshFormat::stl;
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
  const FileBytes file = read_file_bytes(path);
  if (!file.error.empty()) {
    r.status = Status::io_error;
    r.message = name + ": " + file.error;
    return r;
  }
  return parse_mesh<T>(std::string_view(file.data.get(), file.size), format, name);
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
