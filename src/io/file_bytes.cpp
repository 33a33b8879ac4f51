// SPDX-License-Identifier: BSL-1.0
// Reading a whole file into an uninitialised buffer (src/io/file_bytes.hpp); why there is no
// mapping: docs/notes/io.md.

#include "file_bytes.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <new>
#include <system_error>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#define LOCUS_IO_POSIX 1
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace locus::io_detail {

namespace {

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

}  // namespace

#if defined(LOCUS_IO_POSIX)
namespace {
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
}  // namespace

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

bool has_extension(std::string_view name, std::string_view ext) noexcept {
  const std::size_t dot = name.rfind('.');
  const std::size_t sep = name.find_last_of("/\\");
  if (dot == std::string_view::npos || (sep != std::string_view::npos && dot < sep)) return false;
  const std::string_view e = name.substr(dot + 1);
  if (e.size() != ext.size()) return false;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const char c = e[i] >= 'A' && e[i] <= 'Z' ? static_cast<char>(e[i] - 'A' + 'a') : e[i];
    if (c != ext[i]) return false;
  }
  return true;
}

}  // namespace locus::io_detail
