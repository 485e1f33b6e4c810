// Reading text files line by line in bounded memory, and splitting a line into fields: for the
// readers of files (element sets, CCSDS messages, attitude tables, telemetry).
#pragma once

#include <cstddef>
#include <fstream>
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

/// Calls on_line for each line of the file (without its line end: "\n", "\r\n" or a lone "\r",
/// as scene files read them), holding one line at a time (memory: max_line_chars and a block
/// of 64 KiB, whatever the file). Refused: a file that cannot be opened or read (errno's text:
/// file_error), a line longer than max_line_chars, a NUL byte. Every error, the handler's too,
/// leaves with file = path and, when the handler gave none, line = the current line.
checked<void> for_each_line(const std::string& path, const line_handler& on_line);

/// The one wording of a file that cannot be used: "PATH: WHAT: errno's text", e.g.
/// file_error("x.oem", "cannot read", EISDIR) is "x.oem: cannot read: Is a directory".
diagnostic file_error(const std::string& path, std::string_view what, int error_number);

/// Opens `path` as a stream to read (a FIFO or a device too), or file_error's reason: "cannot
/// open: ...", and a directory "cannot read: Is a directory" (a stream would open it and read it
/// as an empty file).
checked<void> open_for_reading(const std::string& path, std::ifstream& in);

/// What a whole-file reader checks of a file's start (its first 4 KiB or more, or all of a shorter
/// file) before it reads on: its format's signature. The error holds the message, and the line
/// when the check knows it (the file is set by the reader).
using start_check = std::function<checked<void>(std::string_view start)>;

/// The bytes of `path`, at most max_bytes of them: a longer file is refused ("larger than N
/// bytes: not WHAT") after reading max_bytes + 1, never held whole; a start that `check_start`
/// refuses is refused before anything more is read (a file of zeros, a binary).
/// Errors name the file (line 0); open and read errors are file_error's.
checked<std::string> read_bounded_file(const std::string& path, std::size_t max_bytes,
                                       std::string_view what, const start_check& check_start = {});

/// ASCII upper case (CCSDS values are case-insensitive: "Earth", "Lagrange").
std::string to_upper(std::string_view text);

/// The whitespace-separated fields of a line: up to `capacity` of them into out; returns how
/// many the line has (which may exceed capacity: then only the first capacity are stored).
std::size_t split_fields(std::string_view line, std::string_view* out,
                         std::size_t capacity) noexcept;

}  // namespace conescan::text
