// A small strict JSON reader (RFC 8259) for the calibration's own files, with line and column in
// every error. Why not a library: none is a dependency of the project yet, the files are small
// and of one shape, and the reader must refuse what a lenient one accepts (duplicate keys,
// NaN, numbers beyond double, trailing text) with a position, which a DOM library reports only
// as a byte offset. Numbers are read by std::from_chars (correctly rounded, so the shortest
// round-trip text that to_chars writes reads back to the same double).
//
// Limits (bounded memory and stack for any input): 64 MiB of text, nesting depth 64.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "text/diagnostic.hpp"

namespace conescan::calibration {

inline constexpr std::size_t json_max_bytes = std::size_t{64} << 20;
inline constexpr int json_max_depth = 64;

struct json_member;

struct json_value {
  enum class type : unsigned char { null, boolean, number, string, array, object };
  type kind = type::null;
  bool boolean = false;
  double number = 0;
  std::string text;                  ///< a string's value (UTF-8)
  std::vector<json_value> items;     ///< an array's
  std::vector<json_member> members;  ///< an object's, in file order
  std::uint64_t line = 0;            ///< where the value starts, 1-based
  std::uint64_t column = 0;          ///< 1-based byte column

  /// The member named `key` of an object, or nullptr.
  const json_value* find(std::string_view key) const;
};

/// An object's member: its name and value (a struct, not a std::pair, which libstdc++ refuses
/// to form of the incomplete json_value inside json_value itself under clang).
struct json_member {
  std::string first;
  json_value second;
};

/// The one JSON value of `text` (whitespace around it allowed). Errors name `file_name`, the
/// line and column, and what was expected.
checked<json_value> parse_json(std::string_view text, const std::string& file_name);

/// JSON text of a string (quoted, escaped) and of a number (the shortest text that reads back
/// to the same double, std::to_chars; null for NaN and infinities, which JSON cannot hold).
std::string json_string(std::string_view text);
std::string json_number(double value);

}  // namespace conescan::calibration
