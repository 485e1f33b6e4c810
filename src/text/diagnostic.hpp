// The one error shape above the core: what is wrong with which input, and where it was given.
//
// Every routine outside the core that reads what a user gave (options, head specs, sweeps, scene
// files, element sets, ephemerides, attitude tables, telemetry, a fit's JSON, a summary state)
// returns checked<T>: a value, or the diagnostic that prevented it. A diagnostic names the option
// (its long name without dashes) when there is one, the file, line and column when the value
// came from a file, and says what is wrong, quoting the bad text (quote()) and stating what is
// allowed. Programs print text() after their name and exit 2 (conescan-sim, conescan-fit); the
// Python module raises ValueError(text()). The wording of a cause is written once, where it is
// found; callers only add the option and the place they know.
//
// The core (include/conescan/) does not use this: it returns statuses (status.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace conescan {

/// Where a value came from: the command line (or a program's keyword arguments), or a place in
/// a file. Line and column are 1-based; 0 means unknown (the whole file, or the line as a whole).
struct origin {
  std::string file{};        ///< empty: the command line
  std::uint64_t line = 0;    ///< 1-based line of `file`
  std::uint64_t column = 0;  ///< 1-based byte column within the line

  static origin command_line() { return {}; }
  static origin file_line(std::string file_name, std::uint64_t line_number,
                          std::uint64_t column_number = 0) {
    return {std::move(file_name), line_number, column_number};
  }
  bool from_file() const noexcept { return !file.empty(); }
  /// "FILE", "FILE:LINE" or "FILE:LINE:COLUMN" (the parts known), or "" for the command line.
  std::string text() const;
};

/// An input that cannot be used.
struct diagnostic {
  std::string option{};   ///< long option name without dashes ("e", "tle", "telemetry"), or ""
  std::string message{};  ///< what is wrong, quoting the value, and what is allowed
  origin where{};         ///< where the value was given
  std::size_t head = 0;   ///< a scene's 1-based head at fault (option "head"), 0 otherwise

  /// A diagnostic with only its message: what a parser of one value knows; the caller names the
  /// option and the place it was given.
  static diagnostic saying(std::string message) { return {{}, std::move(message)}; }

  /// A diagnostic about a place in a file, no option named yet (readers of files: the caller
  /// that knows which option named the file sets `option`).
  static diagnostic in_file(std::string file, std::uint64_t line, std::string message,
                            std::uint64_t column = 0) {
    return {{}, std::move(message), origin::file_line(std::move(file), line, column)};
  }

  /// "FILE:LINE:COLUMN: --option: message", the parts that are known: what a user reads.
  std::string text() const;
};

/// A value of type T, or the diagnostic that prevented it. checked<void> carries no value.
/// No implicit bool: test ok(), so that "an error is present" and "the value is good" cannot be
/// confused at a call site.
template <class T>
class [[nodiscard]] checked {
 public:
  checked(T value) : state_(std::move(value)) {}           // NOLINT: a value converts implicitly
  checked(diagnostic error) : state_(std::move(error)) {}  // NOLINT: so does an error

  bool ok() const noexcept { return state_.index() == 0; }
  const T& value() const& { return std::get<0>(state_); }
  T& value() & { return std::get<0>(state_); }
  T&& value() && { return std::get<0>(std::move(state_)); }
  const diagnostic& error() const& { return std::get<1>(state_); }
  diagnostic& error() & { return std::get<1>(state_); }
  diagnostic&& error() && { return std::get<1>(std::move(state_)); }

 private:
  std::variant<T, diagnostic> state_;
};

template <>
class [[nodiscard]] checked<void> {
 public:
  checked() = default;
  checked(diagnostic error) : error_(std::move(error)) {}  // NOLINT: an error converts

  bool ok() const noexcept { return !error_.has_value(); }
  const diagnostic& error() const& { return *error_; }
  diagnostic& error() & { return *error_; }
  diagnostic&& error() && { return std::move(*error_); }

 private:
  std::optional<diagnostic> error_;
};

/// The success of a checked<void>.
inline checked<void> success() {
  return {};
}

/// A text a user gave, as a message quotes it: in single quotes, control characters and bytes
/// that are not UTF-8 written as \r, \t, \n, \xNN (a CR-only file must not put a raw CR on the
/// terminal, a binary file no raw bytes), cut after 80 characters with "...".
std::string quote(std::string_view text);

/// A library's message about a file (nlohmann-json's, toml++'s) as one printable line: the text
/// it quotes from the file, between its first and last single quote, shown by quote() (a token
/// of a million digits was a line of a megabyte, an ESC reached the terminal); every other byte
/// that is not printable ASCII, a line end too, written as \xNN.
std::string requoted(std::string_view message);

}  // namespace conescan
