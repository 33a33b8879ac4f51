// SPDX-License-Identifier: BSL-1.0
#pragma once
// A small strict JSON tokenizer (RFC 8259) for the GeoJSON reader: the text becomes a flat
// array of values in document order, each container knowing where its subtree ends, so that
// the reader walks it without recursion on the text and skips what it does not use. Numbers
// and strings keep their source text (numbers are converted by the caller, to its precision).
// Not installed.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace locus::json {

enum class Kind : std::uint8_t { null, boolean, number, string, array, object };

struct Value {
  std::size_t pos = 0;      ///< byte offset of the value's first character (a string's quote)
  std::size_t end = 0;      ///< index of the first value after this one's subtree
  std::uint32_t count = 0;  ///< array elements or object members
  std::uint32_t len = 0;    ///< source length of a number or a string's contents (no quotes)
  Kind kind = Kind::null;
  bool escaped = false;  ///< a string holding backslash escapes
};
// Object members are stored as a string value (the name) followed by the member's value.

struct Document {
  std::vector<Value> values;  ///< values[0] is the top value
  std::string error;          ///< empty when the text is valid JSON
  std::size_t error_pos = 0;
};

/// Tokenizes a whole text (an optional UTF-8 byte-order mark, one value, white space).
/// Containers deeper than max_depth are an error.
[[nodiscard]] Document parse(std::string_view text, int max_depth);

/// The contents of a string value, escapes decoded (invalid UTF-16 pairs give U+FFFD).
[[nodiscard]] std::string string_value(std::string_view text, const Value& v);

/// Whether a string value equals s (escapes decoded).
[[nodiscard]] bool string_equals(std::string_view text, const Value& v, std::string_view s);

}  // namespace locus::json
