// Numbers as users type them and read them: the one parser of every number an option, a head
// key, a sweep or a scene file holds, and the text written back (messages, --print-config).
//
// Reals are read by std::from_chars, which rounds correctly (the double nearest the decimal
// text, ties to even: 7100.100000000000818545231595635414123535156250001 is 7100.100000000001,
// on the command line, in sweeps, head specs and scene files alike), locale-independent. Counts
// (seeds, rows, runs) are decimal digits only, so that 010 is not read as octal 8 by one tool
// and as 10 by another, and 2^64 - 1 is the largest.
#pragma once

#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "text/diagnostic.hpp"

namespace conescan::text {

/// The shortest decimal text that reads back to the same double (std::to_chars): what a user
/// would type, e.g. "6378.137", never "6378.1369999999997". Locale-independent.
inline std::string shortest_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

/// The text without the blanks (spaces, tabs) around it: the separators of a head spec and of a
/// scene file's `key = value` may have them, a number itself may not.
inline std::string_view trim_blanks(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

/// A finite real: an optional sign, decimal digits with an optional point and an optional
/// exponent (e or E), correctly rounded; denormals are kept. Refused, with the reason: an empty
/// text, spaces around the number, hex (0x10, 0x1p-4), inf and nan, a value beyond the doubles'
/// range (1e400, 1e-400), trailing text, any other character (unicode digits, a comma).
/// On failure the diagnostic holds only the message; the caller names the option and origin.
checked<double> parse_real(std::string_view text);

/// A count in [0, 2^64 - 1]: decimal digits only, no sign, no leading zero (but "0" itself), no
/// exponent, no spaces. Failures as parse_real; "1e9" is refused with the digits to write.
checked<std::uint64_t> parse_count(std::string_view text);

/// true or false, as a scene file writes a flag.
checked<bool> parse_flag(std::string_view text);

/// parse_real's number, or nothing: for readers of files that word their own message (CCSDS
/// and CSV fields, which name the field and its line).
std::optional<double> parse_number(std::string_view text);

/// A measured figure for messages: three significant digits ("2.35e+06", "0.0123").
std::string rounded_text(double value);

}  // namespace conescan::text
