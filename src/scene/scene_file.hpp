// Scene files (--config): TOML 1.0, read by toml++ (Debian libtomlplusplus-dev), and
// --print-config's writer.
//
//   # comment                     a-km = 7280          earth = "wgs84"
//   sun-sync = true               sweep = "e=0:0.1:0.025"
//   epoch = "2026-06-21T12:00:00" (or a TOML date-time: epoch = 2026-06-21T12:00:00Z)
//   head = "alpha=0,beta=90"                   one head, as the command line's --head
//   head = ["beta=90", "beta=-90"]             several (TOML forbids a key given twice)
//   head = [{beta = 90}, {beta = -90, sigma = 0.05}]      inline tables, one a line or not
//   [[head]]                                   or tables, one per head
//   beta = 90                     keys alpha, beta, gamma, sigma, phase, noise, lsb, ... (deg)
//
// Keys are the option table's names (option_table.hpp); every TOML feature is read as TOML says
// (basic and literal strings with escapes, multi-line strings and arrays, inline tables,
// comments). A value reaches the option table as text, as the command line's does, with
// FILE:LINE:COLUMN as its origin: a string as it is; a number as written, without TOML's
// digit-separating underscores (so 7100.1000000000008185 is read by the one number parser,
// correctly rounded, -0 keeps its sign, and hex, octal, binary, inf and nan are refused as on the
// command line); true and false; a date-time as written. A count above 2^63 - 1 (the largest
// TOML integer) is written in quotes: seed = "18446744073709551615" (--print-config does so).
// Multiple heads: `head` once, as a string, an array of strings or inline tables, an inline
// table; or [[head]] tables (not both: TOML forbids it). Top-level keys come before the first
// [[head]] table (in TOML a table runs to the next header). Lines end at LF, CR LF or a lone CR.
//
// Refused, with FILE:LINE:COLUMN: TOML syntax (toml++'s message), an unknown key or table, a key
// that takes one value given an array or a table, an empty head table, a head key that is not
// one or whose value is not a number. The reader is bounded before it spends: lines of at most
// 4096 bytes, files of at most 1 MiB, a NUL byte refused (a binary file, /dev/zero), at most
// max_heads heads (the 17th refused at its place).
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
/// each top-level key in file order, then the heads in file order (a table as one head spec
/// "key=value,...", placed at the table).
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
