// Scene files (--config): TOML 1.0 read by toml++ (Debian libtomlplusplus-dev) into the option
// table's values, and --print-config's writer, whose text reads back to the same scenes.
//
// Keys are the option table's names (option_table.hpp); a value reaches the table as text, as the
// command line's does, with FILE:LINE:COLUMN as its origin; heads as `head` (a string, an array of
// strings or of inline tables) or [[head]] tables. Refused, with FILE:LINE:COLUMN: TOML syntax, an
// unknown key or table, a value of the wrong shape, a head key that is not one or not a number;
// and before toml++ reads anything, a file over max_scene_file_bytes, a line over
// max_scene_file_line, a NUL byte, a head beyond max_heads. Every rule: docs/CLI.md, "Scene files".
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
/// (tests/apps/test_cli_config.cpp): every option of the table that has a value, numbers in their
/// shortest round-trip form, then each head as a [[head]] table with every key.
std::string scene_file_text(const scene_request& request);

}  // namespace conescan::scene
