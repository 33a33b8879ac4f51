// SPDX-License-Identifier: BSL-1.0
// CSV and XYZ point lists (io/point_list.hpp). The text scanning and number parsing are the mesh
// readers' (mesh_detail.hpp), so every text format of io/ rounds and reports alike.

#include <locus/io/point_list.hpp>

#include "file_bytes.hpp"
#include "mesh_detail.hpp"

#include <array>
#include <fstream>
#include <string>
#include <system_error>

namespace locus {

namespace {

using mesh_io::blank;
using mesh_io::Failure;
using mesh_io::is_space;
using mesh_io::LineReader;
using mesh_io::NumberError;
using mesh_io::quote;

constexpr std::size_t max_points = 0xffffffffu;

enum class Separator : std::uint8_t { undecided, semicolon, comma, whitespace };

Separator pick_separator(std::string_view line) noexcept {
  if (line.find(';') != std::string_view::npos) return Separator::semicolon;
  if (line.find(',') != std::string_view::npos) return Separator::comma;
  return Separator::whitespace;
}

std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// The fields of one line: the first three kept, all counted (a line is never stored whole).
struct Fields {
  std::array<std::string_view, 6> field{};  // the most any N reads (6: rays, read only)
  std::size_t count = 0;
  std::size_t first_empty = 0;  // 1-based index of the first empty field, 0 when none
};

Fields split(std::string_view line, Separator sep) noexcept {
  Fields f;
  auto add = [&f](std::string_view v) {
    v = trim(v);
    if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
    if (f.count < f.field.size()) f.field[f.count] = v;
    ++f.count;
    if (v.empty() && f.first_empty == 0) f.first_empty = f.count;
  };
  if (sep == Separator::whitespace) {
    for (std::string_view t = mesh_io::next_token(line); !t.empty();
         t = mesh_io::next_token(line)) {
      add(t);
    }
    return f;
  }
  const char c = sep == Separator::semicolon ? ';' : ',';
  for (;;) {
    const std::size_t k = line.find(c);
    add(line.substr(0, k));
    if (k == std::string_view::npos) break;
    line.remove_prefix(k + 1);
  }
  return f;
}

// A header line: no field reads as a number (finite or not).
bool is_header(const Fields& f) noexcept {
  const std::size_t n = f.count < f.field.size() ? f.count : f.field.size();
  for (std::size_t i = 0; i < n; ++i) {
    double v = 0;
    if (mesh_io::parse_real(f.field[i], v) != NumberError::syntax) return false;
  }
  return true;
}

template <Real T, int N>
struct Scan {
  Failure failure;
  std::vector<Vec<T, N>> points;
  void fail(std::size_t line, std::size_t offset, std::string reason) {
    failure = Failure{Status::parse_error, std::move(reason), line, offset};
  }
};

// Parses the first N fields into a point; false (and s.failure) on a bad one.
template <Real T, int N>
bool parse_point(const Fields& f, std::size_t ln, std::size_t at, Scan<T, N>& s) {
  Vec<T, N> p{};
  for (int i = 0; i < N; ++i) {
    const std::string_view tok = f.field[std::size_t(i)];
    const std::string where = " in field " + std::to_string(i + 1);
    switch (mesh_io::parse_real(tok, p[i])) {
      case NumberError::none:
        break;
      case NumberError::syntax:
        s.fail(ln, at, "bad number " + quote(tok) + where);
        return false;
      case NumberError::non_finite:
        s.fail(ln, at, "non-finite coordinate " + quote(tok) + where);
        return false;
    }
  }
  if (s.points.size() >= max_points) {
    s.fail(ln, at, "more than 2^32 - 1 points");
    return false;
  }
  s.points.push_back(p);
  return true;
}

template <Real T, int N>
Scan<T, N> read_csv(std::string_view text) {
  Scan<T, N> s;
  Separator sep = Separator::undecided;
  bool first = true;
  LineReader lines(text);
  std::string_view raw;
  while (lines.next(raw)) {
    const std::size_t ln = lines.line_number();
    const std::size_t at = lines.line_start();
    if (raw.find('\0') != std::string_view::npos) {
      s.fail(ln, at, "NUL byte: not a text file");
      return s;
    }
    const std::string_view line = mesh_io::strip_comment(raw);
    if (blank(line)) continue;
    if (sep == Separator::undecided) sep = pick_separator(line);
    const Fields f = split(line, sep);
    if (first) {
      first = false;
      if (is_header(f)) continue;
    }
    if (f.count != std::size_t(N)) {
      s.fail(ln, at, "expected " + std::to_string(N) + " fields, found " + std::to_string(f.count));
      return s;
    }
    if (f.first_empty != 0) {
      s.fail(ln, at, "empty field " + std::to_string(f.first_empty));
      return s;
    }
    if (!parse_point(f, ln, at, s)) return s;
  }
  return s;
}

template <Real T, int N>
Scan<T, N> read_xyz(std::string_view text) {
  Scan<T, N> s;
  LineReader lines(text);
  std::string_view raw;
  while (lines.next(raw)) {
    const std::size_t ln = lines.line_number();
    const std::size_t at = lines.line_start();
    if (raw.find('\0') != std::string_view::npos) {
      s.fail(ln, at, "NUL byte: not a text file");
      return s;
    }
    std::string_view line = mesh_io::strip_comment(raw);
    if (blank(line)) continue;
    Fields f;
    for (; f.count < 3; ++f.count) {
      const std::string_view tok = mesh_io::next_token(line);
      if (tok.empty()) break;
      f.field[f.count] = tok;
    }
    if (f.count < 3) {
      s.fail(ln, at, "expected 3 columns (x y z), found " + std::to_string(f.count));
      return s;
    }
    if (!parse_point(f, ln, at, s)) return s;
  }
  return s;
}

std::string unknown_format(std::string_view name) {
  return std::string(name) + ": unknown point-list format (extension not .csv .txt .tsv .xyz)";
}

template <Real T, int N>
void append_row(std::string& out, const Vec<T, N>& p, char sep) {
  for (int i = 0; i < N; ++i) {
    if (i > 0) out += sep;
    mesh_io::append_real(out, p[i]);
  }
  out += '\n';
}

}  // namespace

PointListFormat point_list_format_from_name(std::string_view name) noexcept {
  using io_detail::has_extension;
  if (has_extension(name, "csv") || has_extension(name, "txt") || has_extension(name, "tsv")) {
    return PointListFormat::csv;
  }
  if (has_extension(name, "xyz")) return PointListFormat::xyz;
  return PointListFormat::from_extension;
}

int point_list_dimension(std::string_view bytes, PointListFormat format) noexcept {
  if (format == PointListFormat::from_extension) return 0;
  Separator sep = Separator::undecided;
  bool first = true;
  LineReader lines(bytes);
  std::string_view raw;
  while (lines.next(raw)) {
    std::string_view line = mesh_io::strip_comment(raw);
    if (blank(line)) continue;
    if (format == PointListFormat::xyz) {
      int n = 0;
      while (n < 3 && !mesh_io::next_token(line).empty()) ++n;
      return n;
    }
    if (sep == Separator::undecided) sep = pick_separator(line);
    const Fields f = split(line, sep);
    if (first) {
      first = false;
      if (is_header(f)) continue;
    }
    return f.count > 1000 ? 1000 : static_cast<int>(f.count);
  }
  return 0;
}

template <Real T, int N>
PointListReadResult<T, N> parse_points(std::string_view bytes, PointListFormat format,
                                       std::string_view name) {
  PointListReadResult<T, N> r;
  if (format == PointListFormat::from_extension) format = point_list_format_from_name(name);
  Scan<T, N> s;
  switch (format) {
    case PointListFormat::from_extension:
      r.status = Status::invalid_input;
      r.message = unknown_format(name);
      return r;
    case PointListFormat::csv:
      s = read_csv<T, N>(bytes);
      break;
    case PointListFormat::xyz:
      if constexpr (N != 3) {
        r.status = Status::invalid_input;
        r.message = std::string(name) + ": XYZ files hold 3D points";
        return r;
      } else {
        s = read_xyz<T, N>(bytes);
      }
      break;
  }
  r.status = s.failure.status;
  if (r.status != Status::ok) {
    r.line = s.failure.line;
    r.byte_offset = s.failure.offset;
    r.message = std::string(name) + ':' + std::to_string(r.line) + ": " + s.failure.reason;
    return r;
  }
  r.points = std::move(s.points);
  return r;
}

template <Real T, int N>
PointListReadResult<T, N> read_points(const std::filesystem::path& path, PointListFormat format) {
  PointListReadResult<T, N> r;
  const std::string name = path.string();
  if (format == PointListFormat::from_extension) {
    format = point_list_format_from_name(name);
    if (format == PointListFormat::from_extension) {
      r.status = Status::invalid_input;
      r.message = unknown_format(name);
      return r;
    }
  }
  const io_detail::FileBytes file = io_detail::read_file_bytes(path);
  if (!file.error.empty()) {
    r.status = Status::io_error;
    r.message = name + ": " + file.error;
    return r;
  }
  return parse_points<T, N>(file.bytes(), format, name);
}

template <Real T, int N>
PointListWriteResult write_points_string(std::span<const Vec<T, N>> points,
                                         PointListFormat format) {
  PointListWriteResult r;
  for (const Vec<T, N>& p : points) {
    if (!is_finite(p)) {
      r.status = Status::non_finite_input;
      r.message = "a point has a non-finite coordinate";
      return r;
    }
  }
  r.status = Status::ok;
  switch (format) {
    case PointListFormat::from_extension:
      r.status = Status::invalid_input;
      r.message = "no point-list format given";
      return r;
    case PointListFormat::csv:
      r.data = N == 2 ? "x,y\n" : "x,y,z\n";
      for (const Vec<T, N>& p : points) append_row(r.data, p, ',');
      break;
    case PointListFormat::xyz:
      if constexpr (N != 3) {
        r.status = Status::invalid_input;
        r.message = "XYZ files hold 3D points";
        return r;
      } else {
        for (const Vec<T, N>& p : points) append_row(r.data, p, ' ');
      }
      break;
  }
  return r;
}

template <Real T, int N>
PointListWriteResult write_points(const std::filesystem::path& path,
                                  std::span<const Vec<T, N>> points, PointListFormat format) {
  const std::string name = path.string();
  if (format == PointListFormat::from_extension) format = point_list_format_from_name(name);
  if (format == PointListFormat::from_extension) {
    return PointListWriteResult{Status::invalid_input, unknown_format(name), {}};
  }
  PointListWriteResult r = write_points_string<T, N>(points, format);
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

#define LOCUS_POINT_LIST_INSTANTIATE(T, N)                                                 \
  template PointListReadResult<T, N> parse_points<T, N>(std::string_view, PointListFormat, \
                                                        std::string_view);                 \
  template PointListReadResult<T, N> read_points<T, N>(const std::filesystem::path&,       \
                                                       PointListFormat);                   \
  template PointListWriteResult write_points_string<T, N>(std::span<const Vec<T, N>>,      \
                                                          PointListFormat);                \
  template PointListWriteResult write_points<T, N>(const std::filesystem::path&,           \
                                                   std::span<const Vec<T, N>>, PointListFormat);
LOCUS_POINT_LIST_INSTANTIATE(float, 2)
LOCUS_POINT_LIST_INSTANTIATE(float, 3)
LOCUS_POINT_LIST_INSTANTIATE(double, 2)
LOCUS_POINT_LIST_INSTANTIATE(double, 3)
#undef LOCUS_POINT_LIST_INSTANTIATE

// Six-column CSV records (rays: origin, direction; the locus raycast command): reading only.
#define LOCUS_POINT_LIST_INSTANTIATE_READ(T, N)                                            \
  template PointListReadResult<T, N> parse_points<T, N>(std::string_view, PointListFormat, \
                                                        std::string_view);                 \
  template PointListReadResult<T, N> read_points<T, N>(const std::filesystem::path&,       \
                                                       PointListFormat);
LOCUS_POINT_LIST_INSTANTIATE_READ(float, 6)
LOCUS_POINT_LIST_INSTANTIATE_READ(double, 6)
#undef LOCUS_POINT_LIST_INSTANTIATE_READ

}  // namespace locus
