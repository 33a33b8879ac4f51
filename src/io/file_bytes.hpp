// SPDX-License-Identifier: BSL-1.0
// Reading a whole file, and a file name's extension: the one implementation behind every reader
// of src/io (meshes, WKT, GeoJSON, point lists). Private to src/io.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace locus::io_detail {

// The bytes of a file, read into a buffer that is not zero-filled first. The file is read as it
// is when opened: at most the size fstat reports then; if it shrinks meanwhile, the bytes read
// are kept (the parser then reports the truncation), and if it grows, the rest is not read. No
// mapping, so a file truncated by another process gives short reads rather than SIGBUS.
struct FileBytes {
  [[nodiscard]] std::string_view bytes() const noexcept { return {data.get(), size}; }
  std::unique_ptr<char[]> data;
  std::size_t size = 0;
  std::string error;  // empty when read
};

/// The bytes of a regular file (see FileBytes); error says why not, without the file name.
[[nodiscard]] FileBytes read_file_bytes(const std::filesystem::path& path);

/// Whether a file name's extension (after its last dot, not a dot of a directory name) is ext,
/// ignoring ASCII case; ext is given in lower case without the dot.
[[nodiscard]] bool has_extension(std::string_view name, std::string_view ext) noexcept;

}  // namespace locus::io_detail
