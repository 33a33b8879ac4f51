// SPDX-License-Identifier: BSL-1.0
#pragma once
// Internals shared by the mesh readers and writers (src/io/mesh_*.cpp): error reporting, text
// scanning, number parsing and printing. Not installed.

#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>
#include <locus/mesh/polygon_mesh.hpp>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>

namespace locus::mesh_io {

// The largest vertex count and index count a PolygonMesh can address (uint32 indices/offsets).
inline constexpr std::uint64_t max_count = std::numeric_limits<std::uint32_t>::max();

/// What went wrong and where; the message is composed by the caller, who knows the name.
struct Failure {
  Status status = Status::ok;
  std::string reason;
  std::size_t line = 0;    // 0: a binary position
  std::size_t offset = 0;  // byte offset from the start of the input
};

/// A reader's outcome before the file name is attached.
template <Real T>
struct Parsed {
  Failure failure;
  PolygonMesh<T> mesh;
  bool fail(Status s, std::size_t line, std::size_t offset, std::string reason) {
    failure = Failure{s, std::move(reason), line, offset};
    return false;
  }
};

[[nodiscard]] inline bool is_space(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// Splits whitespace-separated tokens off the front of a line.
[[nodiscard]] inline std::string_view next_token(std::string_view& s) noexcept {
  std::size_t i = 0;
  while (i < s.size() && is_space(s[i])) ++i;
  std::size_t j = i;
  while (j < s.size() && !is_space(s[j])) ++j;
  const std::string_view tok = s.substr(i, j - i);
  s.remove_prefix(j);
  return tok;
}

/// Iterates over the lines of a text (LF or CRLF; a trailing CR is kept, is_space skips it).
class LineReader {
 public:
  explicit LineReader(std::string_view text, std::size_t start = 0) noexcept
      : text_(text), pos_(start) {}
  /// The next line without its '\n'; false at the end of the text.
  bool next(std::string_view& line) noexcept {
    if (pos_ >= text_.size()) return false;
    line_start_ = pos_;
    const std::size_t nl = text_.find('\n', pos_);
    const std::size_t end = nl == std::string_view::npos ? text_.size() : nl;
    line = text_.substr(pos_, end - pos_);
    pos_ = nl == std::string_view::npos ? text_.size() : nl + 1;
    ++line_no_;
    return true;
  }
  [[nodiscard]] std::size_t line_number() const noexcept { return line_no_; }
  [[nodiscard]] std::size_t line_start() const noexcept { return line_start_; }
  [[nodiscard]] std::size_t position() const noexcept { return pos_; }
  [[nodiscard]] std::size_t remaining() const noexcept { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_no_ = 0;
  std::size_t line_start_ = 0;
};

/// Drops a '#' comment from a line.
[[nodiscard]] inline std::string_view strip_comment(std::string_view line) noexcept {
  const std::size_t h = line.find('#');
  return h == std::string_view::npos ? line : line.substr(0, h);
}

[[nodiscard]] inline bool blank(std::string_view s) noexcept {
  for (const char c : s) {
    if (!is_space(c)) return false;
  }
  return true;
}

enum class NumberError { none, syntax, non_finite };

/// Parses a whole token as a real number of type T, correctly rounded. A leading '+' is allowed.
/// Overflow, NaN and infinities are non_finite; underflow gives a signed zero.
template <Real T>
[[nodiscard]] NumberError parse_real(std::string_view tok, T& out) noexcept {
  if (tok.size() >= 2 && tok[0] == '+' && tok[1] != '-' && tok[1] != '+') tok.remove_prefix(1);
  const char* b = tok.data();
  const char* e = b + tok.size();
  if (b == e) return NumberError::syntax;
  T v{};
  const auto r = std::from_chars(b, e, v);
  if (r.ptr != e) return NumberError::syntax;
  if (r.ec == std::errc::result_out_of_range) {
    long double wide = 0;
    const auto rw = std::from_chars(b, e, wide);
    if (rw.ec == std::errc() && std::isfinite(wide) && std::fabs(wide) < 1) {
      out = std::signbit(wide) ? -T(0) : T(0);
      return NumberError::none;
    }
    return NumberError::non_finite;
  }
  if (r.ec != std::errc()) return NumberError::syntax;
  if (!std::isfinite(v)) return NumberError::non_finite;
  out = v;
  return NumberError::none;
}

/// Parses a whole token as a signed decimal integer (a leading '+' is allowed).
[[nodiscard]] inline bool parse_int(std::string_view tok, std::int64_t& out) noexcept {
  if (tok.size() >= 2 && tok[0] == '+' && tok[1] != '-' && tok[1] != '+') tok.remove_prefix(1);
  const char* b = tok.data();
  const char* e = b + tok.size();
  if (b == e) return false;
  const auto r = std::from_chars(b, e, out);
  return r.ec == std::errc() && r.ptr == e;
}

/// Parses a whole token as an unsigned decimal integer.
[[nodiscard]] inline bool parse_uint(std::string_view tok, std::uint64_t& out) noexcept {
  const char* b = tok.data();
  const char* e = b + tok.size();
  if (b == e) return false;
  const auto r = std::from_chars(b, e, out);
  return r.ec == std::errc() && r.ptr == e;
}

/// Appends the shortest decimal form of v that reads back exactly.
template <Real T>
void append_real(std::string& s, T v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, r.ptr);
}

inline void append_uint(std::string& s, std::uint64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, r.ptr);
}

/// Quotes a token for a message, shortened and with control bytes escaped.
[[nodiscard]] inline std::string quote(std::string_view tok) {
  std::string q = "'";
  const std::size_t n = tok.size() < 32 ? tok.size() : 32;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(tok[i]);
    if (c < 0x20 || c >= 0x7f) {
      static constexpr char hex[] = "0123456789abcdef";
      q += "\\x";
      q += hex[c >> 4];
      q += hex[c & 15];
    } else {
      q += static_cast<char>(c);
    }
  }
  if (tok.size() > n) q += "...";
  q += "'";
  return q;
}

/// The readers and writers of each format (src/io/mesh_<format>.cpp).
template <Real T>
Parsed<T> read_obj(std::string_view text);
template <Real T>
Parsed<T> read_off(std::string_view text);
template <Real T>
Parsed<T> read_ply(std::string_view bytes);
template <Real T>
Parsed<T> read_stl(std::string_view bytes, int encoding);  // 0 detect, 1 ASCII, 2 binary

template <Real T>
void write_obj(const PolygonMesh<T>& mesh, std::string& out);
template <Real T>
void write_off(const PolygonMesh<T>& mesh, std::string& out);
template <Real T>
void write_ply(const PolygonMesh<T>& mesh, int encoding, std::string& out);  // 0 ASCII, 1 LE, 2 BE
template <Real T>
bool write_stl(const PolygonMesh<T>& mesh, bool binary, std::string& out);  // false: float overflow

}  // namespace locus::mesh_io
