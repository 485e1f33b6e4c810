// The text of a number as users see it in messages and scene files.
#pragma once

#include <charconv>
#include <string>

namespace conescan::scene {

/// The shortest decimal text that reads back to the same double (std::to_chars): what a user
/// would type, e.g. "6378.137", never "6378.1369999999997". Locale-independent.
inline std::string shortest_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace conescan::scene
