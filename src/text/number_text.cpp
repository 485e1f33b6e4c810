#include "text/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <system_error>

namespace conescan::text {

namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// inf, infinity, nan, nan(...) in any case, after an optional sign: std::from_chars reads them,
// but a scene's numbers must be finite.
bool names_a_non_finite(std::string_view text) {
  if (!text.empty() && (text.front() == '-' || text.front() == '+')) text.remove_prefix(1);
  if (text.size() < 3) return false;
  std::string head;
  for (char c : text.substr(0, 3)) head += static_cast<char>(c | 0x20);
  return head == "inf" || head == "nan";
}

}  // namespace

checked<double> parse_real(std::string_view text) {
  if (text.empty()) return diagnostic::saying("empty value: give a number");
  if (is_blank(text.front()) || is_blank(text.back()))
    return diagnostic::saying(quote(text) + " has blanks around the number");
  if (names_a_non_finite(text)) return diagnostic::saying(quote(text) + " is not a finite number");
  // std::from_chars takes no '+'; a leading '+' is still a decimal number (but not "+-1").
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+')
    digits.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value,
                                         std::chars_format::general);
  if (ec == std::errc::result_out_of_range)
    return diagnostic::saying(
        quote(text) + " is outside the range of a double (4.9e-324 to 1.8e308 in magnitude)");
  if (ec != std::errc() || end != digits.data() + digits.size())
    return diagnostic::saying(
        quote(text) +
        " is not a decimal number (digits with an optional sign, point and exponent; "
        "no hex, no spaces)");
  return value;
}

checked<std::uint64_t> parse_count(std::string_view text) {
  if (text.empty()) return diagnostic::saying("empty value: give a count (decimal digits)");
  bool digits_only = true;
  for (char c : text) digits_only = digits_only && is_digit(c);
  if (!digits_only) {
    // "1e9" or "1000000.0": say which digits to write.
    const checked<double> real = parse_real(text);
    if (real.ok() && real.value() >= 0 && real.value() < 0x1p64 &&
        real.value() == std::floor(real.value()))
      return diagnostic::saying(quote(text) + " is not a count: decimal digits only, e.g. " +
                                std::to_string(static_cast<std::uint64_t>(real.value())));
    return diagnostic::saying(quote(text) +
                              " is not a count: decimal digits only (no sign, no point, no "
                              "exponent, no hex, no spaces)");
  }
  if (text.size() > 1 && text.front() == '0')
    return diagnostic::saying(
        quote(text) + " has a leading zero (octal in some tools): write the count without it");
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range)
    return diagnostic::saying(quote(text) + " is above the largest count, 18446744073709551615");
  if (ec != std::errc() || end != text.data() + text.size())
    return diagnostic::saying(quote(text) + " is not a count");
  return value;
}

checked<bool> parse_flag(std::string_view text) {
  if (text == "true") return true;
  if (text == "false") return false;
  return diagnostic::saying(quote(text) + " is not true or false");
}

std::optional<double> parse_number(std::string_view text) {
  const checked<double> value = parse_real(text);
  if (!value.ok()) return std::nullopt;
  return value.value();
}

std::string rounded_text(double value) {
  char buffer[32];
  const int n = std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return std::string(buffer, static_cast<std::size_t>(std::max(n, 0)));
}

}  // namespace conescan::text
