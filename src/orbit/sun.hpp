// The Sun's declination for a calendar date, from the Astronomical Almanac's low-precision
// formulas for the Sun (Astronomical Almanac, section C, "Low-precision formulas for the Sun's
// coordinates"; also USNO, "Approximate Solar Coordinates"):
//   n = JD - 2451545.0                              (days from J2000.0)
//   L = 280.460 + 0.9856474 n                       (mean longitude, deg, aberration included)
//   g = 357.528 + 0.9856003 n                       (mean anomaly, deg)
//   lambda = L + 1.915 sin g + 0.020 sin 2g         (ecliptic longitude, deg)
//   epsilon = 23.439 - 0.0000004 n                  (obliquity of the ecliptic, deg)
//   delta = asin(sin epsilon sin lambda)            (declination; the ecliptic latitude is 0)
// Stated accuracy: 0.01 deg between 1950 and 2050. Outside that span the Almanac states none;
// the error grows slowly (the mean elements are linear in time, the obliquity rate is rounded to
// one digit) and is not measured here for 1900..1950 and 2050..2100. UT is used for TT (Delta T
// ~ 1 min moves delta by < 0.0003 deg).
//
// Double only (orbit layer). The date is a Gregorian calendar date; the time is 12:00 UTC.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>

namespace conescan::orbit {

/// The years sun_declination_rad accepts: 1900..2100 (the formulas' mean elements are fitted
/// around 2000; beyond two centuries they are not worth using).
inline constexpr int sun_year_min = 1900;
inline constexpr int sun_year_max = 2100;

/// Gregorian leap year: divisible by 4, except centuries not divisible by 400 (1900 and 2100 are
/// not leap years, 2000 is).
constexpr bool is_leap_year(int year) noexcept {
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

/// Days in a month of the Gregorian calendar; 0 for a month outside 1..12.
constexpr int days_in_month(int year, int month) noexcept {
  constexpr int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12) return 0;
  return month == 2 && is_leap_year(year) ? 29 : days[month - 1];
}

/// True for a Gregorian date with year in [sun_year_min, sun_year_max], month 1..12 and day
/// within the month (leap years included).
constexpr bool is_valid_sun_date(int year, int month, int day) noexcept {
  return year >= sun_year_min && year <= sun_year_max && day >= 1 &&
         day <= days_in_month(year, month);
}

/// The Julian Day Number of a Gregorian date, which is the Julian Date at 12:00 UTC of that date
/// (Fliegel and Van Flandern, Comm. ACM 11, 657 (1968), integer arithmetic, valid for any date
/// after -4713). 2000-01-01 gives 2451545 (J2000.0).
constexpr long julian_day_number(int year, int month, int day) noexcept {
  const long a = (14 - month) / 12;  // 1 for January and February, else 0
  const long y = year + 4800L - a;
  const long m = month + 12 * a - 3;
  return day + (153 * m + 2) / 5 + 365 * y + y / 4 - y / 100 + y / 400 - 32045;
}

/// The Sun's declination (rad, north positive) at 12:00 UTC of a Gregorian date, by the
/// Astronomical Almanac's low-precision formulas (top of this file). nullopt for an invalid date
/// (is_valid_sun_date). Accuracy: ~0.01 deg for 1950..2050 (tests/test_sun.cpp compares the
/// solstices and equinoxes of 2025 with their published instants).
inline std::optional<double> sun_declination_rad(int year, int month, int day) noexcept {
  if (!is_valid_sun_date(year, month, day)) return std::nullopt;
  constexpr double deg = std::numbers::pi / 180.0;
  // JD at 12:00 UTC minus 2451545.0 is an integer: exact in a double.
  const double n = static_cast<double>(julian_day_number(year, month, day) - 2451545L);
  // L and g grow by ~36000 deg a century: reduced to (-360, 360) before the sines (fmod is exact).
  const double mean_longitude_deg = std::fmod(280.460 + 0.9856474 * n, 360.0);
  const double mean_anomaly_deg = std::fmod(357.528 + 0.9856003 * n, 360.0);
  const double g = mean_anomaly_deg * deg;
  const double ecliptic_longitude =
      (mean_longitude_deg + 1.915 * std::sin(g) + 0.020 * std::sin(2.0 * g)) * deg;
  const double obliquity = (23.439 - 0.0000004 * n) * deg;
  return std::asin(std::sin(obliquity) * std::sin(ecliptic_longitude));
}

/// sun_declination_rad for a date written exactly "YYYY-MM-DD" (ten characters, ASCII digits,
/// '-' at positions 4 and 7; no sign, spaces, time or other form). nullopt for any other text or
/// an invalid date ("2025-1-1", "2025-02-29" and "abc" are all nullopt).
inline std::optional<double> sun_declination_from_iso_date(std::string_view text) noexcept {
  if (text.size() != 10 || text[4] != '-' || text[7] != '-') return std::nullopt;
  int fields[3] = {0, 0, 0};
  const int begin[3] = {0, 5, 8};
  const int end[3] = {4, 7, 10};
  for (int f = 0; f < 3; ++f) {
    for (int i = begin[f]; i < end[f]; ++i) {
      const char c = text[static_cast<std::size_t>(i)];
      if (c < '0' || c > '9') return std::nullopt;
      fields[f] = fields[f] * 10 + (c - '0');
    }
  }
  return sun_declination_rad(fields[0], fields[1], fields[2]);
}

}  // namespace conescan::orbit
