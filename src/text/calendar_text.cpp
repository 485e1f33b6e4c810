#include "text/calendar_text.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>

namespace conescan::text {

namespace {

/// Fixed-width unsigned decimal field text[pos, pos + width); nullopt unless all digits.
std::optional<int> digits(std::string_view text, std::size_t pos, std::size_t width) noexcept {
  if (pos + width > text.size()) return std::nullopt;
  int v = 0;
  for (std::size_t i = pos; i < pos + width; ++i) {
    const char c = text[i];
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + (c - '0');
  }
  return v;
}

/// "hh:mm:ss[.f...]" at text[pos...] to the end; fills c's time fields.
bool parse_time_of_day(std::string_view text, std::size_t pos, calendar_time& c) noexcept {
  const std::optional<int> h = digits(text, pos, 2), m = digits(text, pos + 3, 2),
                           s = digits(text, pos + 6, 2);
  if (!h || !m || !s || text.size() < pos + 8 || text[pos + 2] != ':' || text[pos + 5] != ':') {
    return false;
  }
  c.hour = *h;
  c.minute = *m;
  const std::string_view seconds = text.substr(pos + 6);
  if (seconds.size() > 2) {
    // ".f..." only: from_chars would also take exponents, signs and "nan".
    if (seconds[2] != '.' || seconds.size() == 3) return false;
    for (std::size_t i = 3; i < seconds.size(); ++i) {
      if (seconds[i] < '0' || seconds[i] > '9') return false;
    }
  }
  const auto [end, ec] = std::from_chars(seconds.data(), seconds.data() + seconds.size(), c.second);
  if (ec != std::errc() || end != seconds.data() + seconds.size()) return false;
  // "59.9999999999999999" is before second 60, but the nearest double is 60: keep it in its
  // second (the largest double below 60, 7e-15 s off), so that it is not read as second 60.
  const double next_second = static_cast<double>(*s + 1);
  if (!(c.second < next_second)) c.second = std::nextafter(next_second, 0.0);
  return true;
}

}  // namespace

bool is_leap_year(int year) noexcept {
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

int days_in_month(int year, int month) noexcept {
  static constexpr int month_days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12) return 0;
  return month_days[month - 1] + (month == 2 && is_leap_year(year) ? 1 : 0);
}

int day_of_year(int year, int month, int day) noexcept {
  int before = 0;
  for (int m = 1; m < month; ++m) before += days_in_month(year, m);
  return before + day;
}

std::optional<calendar_time> parse_calendar(std::string_view text) noexcept {
  if (!text.empty() && text.back() == 'Z') text.remove_suffix(1);
  calendar_time c;
  const std::optional<int> year = digits(text, 0, 4);
  if (!year || text.size() < 5 || text[4] != '-') return std::nullopt;
  c.year = *year;
  std::size_t time_at = 0;
  if (text.size() > 10 && text[10] == 'T') {  // YYYY-MM-DDT
    const std::optional<int> month = digits(text, 5, 2), day = digits(text, 8, 2);
    if (!month || !day || text[7] != '-') return std::nullopt;
    c.month = *month;
    c.day = *day;
    time_at = 11;
  } else if (text.size() > 8 && text[8] == 'T') {  // YYYY-DDDT
    const std::optional<int> doy = digits(text, 5, 3);
    if (!doy || *doy < 1 || *doy > (is_leap_year(c.year) ? 366 : 365)) return std::nullopt;
    c.month = 1;
    c.day = *doy;
    while (c.day > days_in_month(c.year, c.month)) c.day -= days_in_month(c.year, c.month++);
    time_at = 9;
  } else {
    return std::nullopt;
  }
  if (c.day < 1 || c.day > days_in_month(c.year, c.month)) return std::nullopt;
  if (!parse_time_of_day(text, time_at, c)) return std::nullopt;
  if (c.hour > 23 || c.minute > 59 || !(c.second < 61.0)) return std::nullopt;
  return c;
}

}  // namespace conescan::text
