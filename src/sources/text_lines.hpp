// Reading text files line by line in bounded memory, and the number syntax of CCSDS and CSV
// files, for the readers of this layer.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "sources/source_error.hpp"

namespace conescan::sources {

/// Longest line a reader accepts. CCSDS KVN limits lines to 254 characters; this leaves room for
/// long comments while keeping a file that is not text (or has no line ends) from filling memory.
inline constexpr std::size_t max_line_chars = 4096;

/// What a reader does with each line: nullopt to go on, or the error that stops the reading.
using line_handler = std::function<std::optional<source_error>(std::string_view line)>;

/// Calls on_line for each line of the file (without its "\n" or "\r\n"), holding one line at a
/// time. Refused: a file that cannot be opened or read, a line longer than max_line_chars, a NUL
/// byte. Every error, the handler's too, leaves with file = path and, when the handler gave
/// none, line = the current line.
std::optional<source_error> for_each_line(const std::string& path, const line_handler& on_line);

/// The text without leading and trailing blanks (space, tab).
std::string_view trim(std::string_view text) noexcept;

/// ASCII upper case (CCSDS values are case-insensitive: "Earth", "Lagrange").
std::string to_upper(std::string_view text);

/// A finite decimal number: optional sign, digits with an optional '.', optional exponent
/// (e/E). Nothing else: no "nan", "inf", hexadecimal, spaces or trailing text.
std::optional<double> parse_number(std::string_view text) noexcept;

/// The whitespace-separated fields of a line: up to `capacity` of them into out; returns how
/// many the line has (which may exceed capacity: then only the first capacity are stored).
std::size_t split_fields(std::string_view line, std::string_view* out,
                         std::size_t capacity) noexcept;

/// 'text' in quotes for messages, cut to 60 characters.
std::string quoted(std::string_view text);

/// A number for messages: shortest round-trip text.
std::string number_text(double value);

/// A measured figure for messages: three significant digits ("2.35e+06", "0.0123").
std::string rounded_text(double value);

}  // namespace conescan::sources
