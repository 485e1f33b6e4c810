// Scene files (--config): the options as `key = value` lines, and --print-config's writer.
//
//   # comment                     a-km = 7280          earth = "wgs84"
//   sun-sync = true               sweep = "e=0:0.1:0.025"
//   head = "alpha=0,beta=90"      (repeatable, or an array ["...", "..."]), or tables:
//   [[head]]
//   alpha = 0                     keys alpha, beta, gamma, sigma, phase, noise, lsb (degrees)
//
// Keys are the option table's names (option_table.hpp). Values are "text" (no escapes), a bare
// token, or, for head, an array of strings; they are read by the option table as the command
// line's are, with FILE:LINE as their origin. Top-level keys come before the first [[head]]
// table (as in TOML, a table runs to the next table header). Lines end at LF, CR LF or a lone
// CR. The reader is bounded before it spends: lines of at most 4096 bytes, files of at most
// 1 MiB, at most max_heads heads (counted as they are read), and a NUL byte ends it with an
// error (a binary file, /dev/zero).
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "scene/scene_request.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

inline constexpr std::size_t max_scene_file_line = 4096;
inline constexpr std::size_t max_scene_file_bytes = std::size_t(1) << 20;

/// The options of a scene file read from `input`, named `file_name` in origins and messages:
/// each top-level key in file order, then the heads in file order (a [[head]] table as one head
/// spec, with the table's line). Errors (malformed line, unknown key, a key given twice, a head
/// key's value that is not a number, too many heads, a file too long) carry FILE:LINE.
checked<std::vector<option_value>> read_scene_file(std::istream& input,
                                                   const std::string& file_name);

/// The same from the file at `path`; errors about the file itself (empty name, missing, a
/// directory, unreadable) name option "config".
checked<std::vector<option_value>> read_scene_file(const std::string& path);

/// The request as a scene file that reads back to the same scenes, byte for byte the same CSV
/// (tests/test_cli_config.cpp): every option of the table that has a value, numbers in their
/// shortest round-trip form, then each head as a [[head]] table with every key.
std::string scene_file_text(const scene_request& request);

}  // namespace conescan::scene
