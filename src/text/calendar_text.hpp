// The Gregorian calendar as text writes it: the syntax of CCSDS and ISO 8601 epochs and the
// calendar's arithmetic (leap years, days of the months, day of the year), with no time scale.
// The ground floor of both epoch readers: the orbit tier's OMM (orbit/omm.cpp: UTC as SGP4
// takes it, 1900-2099, no leap second) and the sources tier's time scales
// (sources/time_scales.hpp: UTC, TAI, TT, GPS through ERFA, leap seconds included), which check
// what their own time scale allows on the calendar_time this parser returns.
#pragma once

#include <optional>
#include <string_view>

namespace conescan::text {

/// A calendar date and time of day as text holds it (Gregorian; second may be 60.x, for the last
/// minute of a UTC day that ends with a leap second: the caller's time scale decides).
struct calendar_time {
  int year = 0, month = 0, day = 0, hour = 0, minute = 0;
  double second = 0;
};

/// Gregorian leap year (every 4th, not every 100th, every 400th).
bool is_leap_year(int year) noexcept;

/// Days of `month` (1..12) in `year`; 0 for a month outside 1..12.
int days_in_month(int year, int month) noexcept;

/// The day of the year of a valid date (1 = 1 January).
int day_of_year(int year, int month, int day) noexcept;

/// The syntax of CCSDS and ISO 8601 epochs: "YYYY-MM-DDThh:mm:ss[.f...][Z]" or the day-of-year
/// form "YYYY-DDDThh:mm:ss[.f...][Z]" (any number of decimals, digits only: no sign, exponent or
/// "nan"). Checks the fields' ranges (year 0000-9999, month 1..12, day within the month, day of
/// the year within the year, hour < 24, minute < 60, second < 61) but not the time scale; a
/// second whose decimals round to the next whole second in a double is kept in its second (the
/// largest double below it, 7e-15 s off). nullopt for any other text.
std::optional<calendar_time> parse_calendar(std::string_view text) noexcept;

}  // namespace conescan::text
