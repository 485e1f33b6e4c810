// The one error shape of the scene layer: what went wrong with which option, typed where.
//
// Every routine that reads what a user typed (numbers, head specs, sweeps, scene files, the
// option table, validation) returns checked<T>: a value, or a config_error naming the option
// (its long name without dashes), saying what is wrong and the allowed values, and where the
// option was typed (the command line, or FILE:LINE of a scene file). Programs print it as
//   conescan-sim: FILE:LINE: --option: message
// (conescan-sim) or raise it (the Python bindings' ValueError), so the wording is written once.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace conescan::scene {

/// Where an option's value came from: the command line (or a program's keyword arguments),
/// or line `line` (1-based) of scene file `file`.
struct origin {
  std::string file;        ///< empty: the command line
  std::uint64_t line = 0;  ///< 1-based line of `file`

  static origin command_line() { return {}; }
  static origin file_line(std::string file_name, std::uint64_t line_number) {
    return {std::move(file_name), line_number};
  }
  bool from_file() const noexcept { return !file.empty(); }
  /// "FILE:LINE", or "" for the command line.
  std::string text() const;
};

/// A value a user gave that cannot be used.
struct config_error {
  std::string option;    ///< long option name without dashes ("e", "a-km", "head"); may be ""
  std::string message;   ///< what is wrong, quoting the value, and what is allowed
  origin where;          ///< where the option was given
  std::size_t head = 0;  ///< 1-based index of the head at fault (option "head"), 0 otherwise

  /// "FILE:LINE: --option: message" (parts left out when empty): what a user reads.
  std::string text() const;
};

/// A value of type T, or the config_error that prevented it. checked<void> carries no value.
/// No implicit bool: test ok(), so that "an error is present" and "the value is good" cannot be
/// confused at a call site.
template <class T>
class [[nodiscard]] checked {
 public:
  checked(T value) : state_(std::move(value)) {}             // NOLINT: a value converts implicitly
  checked(config_error error) : state_(std::move(error)) {}  // NOLINT: so does an error

  bool ok() const noexcept { return state_.index() == 0; }
  const T& value() const& { return std::get<0>(state_); }
  T& value() & { return std::get<0>(state_); }
  T&& value() && { return std::get<0>(std::move(state_)); }
  const config_error& error() const& { return std::get<1>(state_); }
  config_error&& error() && { return std::get<1>(std::move(state_)); }

 private:
  std::variant<T, config_error> state_;
};

template <>
class [[nodiscard]] checked<void> {
 public:
  checked() = default;
  checked(config_error error) : error_(std::move(error)) {}  // NOLINT: an error converts

  bool ok() const noexcept { return !error_.has_value(); }
  const config_error& error() const& { return *error_; }
  config_error&& error() && { return std::move(*error_); }

 private:
  std::optional<config_error> error_;
};

/// The success of a checked<void>.
inline checked<void> success() {
  return {};
}

/// A text a user typed, as a message quotes it: in single quotes, control characters and bytes
/// that are not UTF-8 written as \r, \t, \xNN (a CR-only file must not put a raw CR on the
/// terminal), cut after 80 characters with "...".
std::string quote(std::string_view text);

}  // namespace conescan::scene
