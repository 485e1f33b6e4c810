// Reading text files line by line in bounded memory, and splitting a line into fields: for the
// readers of files (element sets, CCSDS messages, attitude tables, telemetry).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "text/diagnostic.hpp"

namespace conescan::text {

/// Longest line a reader accepts. CCSDS KVN limits lines to 254 characters; this leaves room for
/// long comments while keeping a file that is not text (or has no line ends) from filling memory.
inline constexpr std::size_t max_line_chars = 4096;

/// What a reader does with each line: success() to go on, or the error that stops the reading.
using line_handler = std::function<checked<void>(std::string_view line)>;

/// Calls on_line for each line of the file (without its "\n" or "\r\n"), holding one line at a
/// time. Refused: a file that cannot be opened or read, a line longer than max_line_chars, a NUL
/// byte. Every error, the handler's too, leaves with file = path and, when the handler gave
/// none, line = the current line.
checked<void> for_each_line(const std::string& path, const line_handler& on_line);

/// ASCII upper case (CCSDS values are case-insensitive: "Earth", "Lagrange").
std::string to_upper(std::string_view text);

/// The whitespace-separated fields of a line: up to `capacity` of them into out; returns how
/// many the line has (which may exceed capacity: then only the first capacity are stored).
std::size_t split_fields(std::string_view line, std::string_view* out,
                         std::size_t capacity) noexcept;

}  // namespace conescan::text
