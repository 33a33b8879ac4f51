// SPDX-License-Identifier: BSL-1.0
// The strict JSON tokenizer of the GeoJSON reader (src/io/json.hpp). An explicit stack of open
// containers (bounded by max_depth) replaces recursion; every byte is looked at once.

#include "json.hpp"

#include <limits>

namespace locus::json {
namespace {

[[nodiscard]] bool is_ws(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}
[[nodiscard]] bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }
[[nodiscard]] int hex_value(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

/// Length of the valid UTF-8 sequence starting at s[i] (a byte >= 0x80), or 0.
[[nodiscard]] std::size_t utf8_length(std::string_view s, std::size_t i) noexcept {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;  // no UTF-16 surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (s.size() - i < n) return 0;
  if (b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  return n;
}

class Tokenizer {
 public:
  Tokenizer(std::string_view text, Document& doc) noexcept : s_(text), doc_(doc) {}

  void run(int max_depth) {
    if (s_.size() >= 3 && s_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;
    std::vector<std::size_t> open;  // indices of the open containers
    while (true) {
      // A value.
      skip();
      if (i_ >= s_.size()) return error(i_, "unexpected end of text, expected a value");
      const char c = s_[i_];
      if (c == '{' || c == '[') {
        if (open.size() >= static_cast<std::size_t>(max_depth)) {
          return error(i_, "nested deeper than " + std::to_string(max_depth) + " levels");
        }
        open.push_back(push(c == '{' ? Kind::object : Kind::array, i_, 0));
        ++i_;
        skip();
        const char close = c == '{' ? '}' : ']';
        if (i_ < s_.size() && s_[i_] == close) {
          ++i_;
          doc_.values[open.back()].end = doc_.values.size();
          open.pop_back();
        } else if (c == '{') {
          if (!member_name()) return;
          continue;
        } else {
          continue;
        }
      } else if (c == '"') {
        if (!string()) return;
      } else if (c == '-' || is_digit(c)) {
        if (!number()) return;
      } else if (!literal()) {
        return;
      }
      // After a value: close containers or go on to the next element.
      while (true) {
        if (open.empty()) {
          skip();
          if (i_ < s_.size()) return error(i_, "unexpected text after the JSON value");
          return;
        }
        Value& parent = doc_.values[open.back()];
        if (parent.count == std::numeric_limits<std::uint32_t>::max()) {
          return error(i_, "more than 2^32 - 1 elements in one container");
        }
        ++parent.count;
        const bool object = parent.kind == Kind::object;
        skip();
        if (i_ >= s_.size()) {
          return error(i_, object ? "unexpected end of text, expected ',' or '}'"
                                  : "unexpected end of text, expected ',' or ']'");
        }
        if (s_[i_] == ',') {
          ++i_;
          if (object && !member_name()) return;
          break;
        }
        if (s_[i_] == (object ? '}' : ']')) {
          ++i_;
          parent.end = doc_.values.size();
          open.pop_back();
          continue;
        }
        return error(i_, object ? "expected ',' or '}'" : "expected ',' or ']'");
      }
    }
  }

 private:
  std::string_view s_;
  Document& doc_;
  std::size_t i_ = 0;

  void skip() noexcept {
    while (i_ < s_.size() && is_ws(s_[i_])) ++i_;
  }
  void error(std::size_t pos, std::string what) {
    doc_.error = std::move(what);
    doc_.error_pos = pos;
  }
  std::size_t push(Kind k, std::size_t pos, std::size_t len) {
    Value v;
    v.kind = k;
    v.pos = pos;
    v.len = static_cast<std::uint32_t>(len);
    v.end = doc_.values.size() + 1;
    doc_.values.push_back(v);
    return doc_.values.size() - 1;
  }

  bool member_name() {
    skip();
    if (i_ >= s_.size()) {
      error(i_, "unexpected end of text, expected a member name");
      return false;
    }
    if (s_[i_] != '"') {
      error(i_, "expected a member name (a string)");
      return false;
    }
    if (!string()) return false;
    skip();
    if (i_ >= s_.size() || s_[i_] != ':') {
      error(i_, i_ >= s_.size() ? "unexpected end of text, expected ':'" : "expected ':'");
      return false;
    }
    ++i_;
    return true;
  }

  bool string() {
    const std::size_t start = i_;
    bool escaped = false;
    ++i_;
    while (true) {
      if (i_ >= s_.size()) {
        error(start, "unterminated string");
        return false;
      }
      const auto c = static_cast<unsigned char>(s_[i_]);
      if (c == '"') break;
      if (c < 0x20) {
        error(i_, "control character in a string");
        return false;
      }
      if (c == '\\') {
        escaped = true;
        if (i_ + 1 >= s_.size()) {
          error(start, "unterminated string");
          return false;
        }
        const char e = s_[i_ + 1];
        if (e == 'u') {
          for (std::size_t k = 2; k < 6; ++k) {
            if (i_ + k >= s_.size() || hex_value(s_[i_ + k]) < 0) {
              error(i_, "bad \\u escape (four hex digits expected)");
              return false;
            }
          }
          i_ += 6;
          continue;
        }
        if (e != '"' && e != '\\' && e != '/' && e != 'b' && e != 'f' && e != 'n' && e != 'r' &&
            e != 't') {
          error(i_, "bad escape in a string");
          return false;
        }
        i_ += 2;
        continue;
      }
      if (c >= 0x80) {
        const std::size_t n = utf8_length(s_, i_);
        if (n == 0) {
          error(i_, "invalid UTF-8 in a string");
          return false;
        }
        i_ += n;
        continue;
      }
      ++i_;
    }
    const std::size_t len = i_ - start - 1;
    if (len > std::numeric_limits<std::uint32_t>::max()) {
      error(start, "string longer than 4 GiB");
      return false;
    }
    const std::size_t k = push(Kind::string, start, len);
    doc_.values[k].escaped = escaped;
    ++i_;
    return true;
  }

  bool number() {
    const std::size_t start = i_;
    if (s_[i_] == '-') ++i_;
    if (i_ >= s_.size() || !is_digit(s_[i_])) {
      error(start, "bad number (a digit must follow '-')");
      return false;
    }
    if (s_[i_] == '0') {
      ++i_;
      if (i_ < s_.size() && is_digit(s_[i_])) {
        error(start, "bad number (leading zero)");
        return false;
      }
    } else {
      while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
    }
    if (i_ < s_.size() && s_[i_] == '.') {
      ++i_;
      if (i_ >= s_.size() || !is_digit(s_[i_])) {
        error(start, "bad number (a digit must follow '.')");
        return false;
      }
      while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
    }
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      ++i_;
      if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
      if (i_ >= s_.size() || !is_digit(s_[i_])) {
        error(start, "bad number (a digit must follow the exponent)");
        return false;
      }
      while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
    }
    if (i_ - start > std::numeric_limits<std::uint32_t>::max()) {
      error(start, "number longer than 4 GiB");
      return false;
    }
    push(Kind::number, start, i_ - start);
    return true;
  }

  bool literal() {
    const std::string_view rest = s_.substr(i_);
    const auto starts = [&](std::string_view w) { return rest.substr(0, w.size()) == w; };
    if (starts("true") || starts("null") || starts("false")) {
      const bool null = rest[0] == 'n';
      const std::size_t n = rest[0] == 'f' ? 5 : 4;
      push(null ? Kind::null : Kind::boolean, i_, n);
      i_ += n;
      return true;
    }
    error(i_, "unexpected character (not the start of a JSON value)");
    return false;
  }
};

void append_utf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

}  // namespace

Document parse(std::string_view text, int max_depth) {
  Document doc;
  Tokenizer(text, doc).run(max_depth);
  return doc;
}

std::string string_value(std::string_view text, const Value& v) {
  const std::string_view raw = text.substr(v.pos + 1, v.len);
  if (!v.escaped) return std::string(raw);
  std::string out;
  out.reserve(raw.size());
  const auto hex4 = [&](std::size_t i) {
    std::uint32_t x = 0;
    for (std::size_t k = 0; k < 4; ++k)
      x = x * 16 + static_cast<std::uint32_t>(hex_value(raw[i + k]));
    return x;
  };
  for (std::size_t i = 0; i < raw.size();) {
    if (raw[i] != '\\') {
      out += raw[i++];
      continue;
    }
    const char e = raw[i + 1];  // the tokenizer checked every escape
    if (e != 'u') {
      switch (e) {
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        default:
          out += e;
      }
      i += 2;
      continue;
    }
    std::uint32_t cp = hex4(i + 2);
    i += 6;
    if (cp >= 0xD800 && cp <= 0xDBFF && i + 6 <= raw.size() && raw[i] == '\\' &&
        raw[i + 1] == 'u') {
      const std::uint32_t lo = hex4(i + 2);
      if (lo >= 0xDC00 && lo <= 0xDFFF) {
        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
        i += 6;
      }
    }
    if (cp >= 0xD800 && cp <= 0xDFFF) cp = 0xFFFD;  // an unpaired surrogate
    append_utf8(out, cp);
  }
  return out;
}

bool string_equals(std::string_view text, const Value& v, std::string_view s) {
  if (!v.escaped) return text.substr(v.pos + 1, v.len) == s;
  return string_value(text, v) == s;
}

}  // namespace locus::json
