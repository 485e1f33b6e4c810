// The one error shape of the time, orbit and attitude sources (SPEC §10): a refusal that names
// the file, the line and the keyword or value at fault, for the CLI to print and exit 2 on.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <variant>

namespace conescan::sources {

/// Why a source cannot be used. `file` is the path as the user gave it (empty for text that did
/// not come from a file, e.g. an --epoch value); `line` is 1-based (0: the whole file, or no
/// file); `message` names the keyword or value and, where there is one, the allowed set.
struct source_error {
  std::string file;
  std::size_t line = 0;
  std::string message;

  /// "FILE:LINE: MESSAGE", "FILE: MESSAGE" without a line, "MESSAGE" without a file.
  std::string to_string() const {
    if (file.empty()) return message;
    if (line == 0) return file + ": " + message;
    return file + ":" + std::to_string(line) + ": " + message;
  }
};

/// A value or the reason there is none. Nothing in this layer throws: every refusal is one.
template <class T>
using source_result = std::variant<T, source_error>;

/// The error of a result, or nullptr when it holds a value.
template <class T>
const source_error* error_of(const source_result<T>& r) noexcept {
  return std::get_if<source_error>(&r);
}

/// Not on a temporary: the pointer would outlive it (name the result first).
template <class T>
const source_error* error_of(const source_result<T>&& r) = delete;

}  // namespace conescan::sources
