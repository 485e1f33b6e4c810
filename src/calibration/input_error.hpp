// The calibration layer's one error shape: what is wrong with which input, and where.
//
// Every routine that reads what a user gave (--free, telemetry, a fit's JSON) or sets up a fit
// returns checked<T>: a value, or an input_error naming the option or file, the position in the
// file (line, and column when the reader knows it) and what is wrong, quoting the bad text.
// Programs print it as "FILE:LINE:COLUMN: --option: message" and exit 2.
//
// The shape follows the scene layer's config_error/checked<T> (branch reliability, not merged
// when this was written); the two become one type once it is, the column joining its origin.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace conescan::calibration {

/// A bad input. Parts left empty (0 for line and column) are not printed.
struct input_error {
  std::string option;        ///< long option name without dashes ("free", "telemetry"), or ""
  std::string message;       ///< what is wrong, quoting the value, and what is allowed
  std::string file;          ///< the file the value came from, or "" (command line)
  std::uint64_t line = 0;    ///< 1-based line of `file`
  std::uint64_t column = 0;  ///< 1-based byte column within the line

  input_error() = default;
  input_error(std::string option_name, std::string what, std::string file_name = {},
              std::uint64_t line_number = 0, std::uint64_t column_number = 0)
      : option(std::move(option_name)),
        message(std::move(what)),
        file(std::move(file_name)),
        line(line_number),
        column(column_number) {}

  /// "FILE:LINE:COLUMN: --option: message", the parts that are known.
  std::string text() const;
};

/// A value of type T, or the input_error that prevented it. No implicit bool: test ok().
template <class T>
class [[nodiscard]] checked {
 public:
  checked(T value) : state_(std::move(value)) {}            // NOLINT: a value converts implicitly
  checked(input_error error) : state_(std::move(error)) {}  // NOLINT: so does an error

  bool ok() const noexcept { return state_.index() == 0; }
  const T& value() const& { return std::get<0>(state_); }
  T& value() & { return std::get<0>(state_); }
  T&& value() && { return std::get<0>(std::move(state_)); }
  const input_error& error() const& { return std::get<1>(state_); }

 private:
  std::variant<T, input_error> state_;
};

/// A text as a message quotes it: in single quotes, control characters and non-ASCII bytes as
/// \xNN, cut after 60 characters with "...".
std::string quote(std::string_view text);

}  // namespace conescan::calibration
