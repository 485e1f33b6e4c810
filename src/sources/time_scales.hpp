// Instants and time scales (MODEL §10): UTC, TAI, TT and GPS through ERFA (IAU SOFA's routines,
// Debian liberfa-dev), leap seconds included.
//
// An `instant` is held on TAI, which has no leap seconds, as a whole TAI day and the seconds into
// it: the seconds between two instants are then an integer number of days times 86400 (exact)
// plus a difference of two seconds-of-day (one rounding), 1e-11 s or better for any two
// instants of ERFA's table, where a single Julian Date in a double would keep only 4e-5 s.
//
// ERFA's leap-second table: UTC is defined from 1960-01-01, and ERFA 2.0.0 (2021) calls every year
// after its release year + 5 "dubious" (it cannot know later leap seconds). Decision:
// later UTC is taken with no further leap second, TAI - UTC = 37 s (the last since 2017-01-01;
// IERS Bulletin C has announced none since, and the CGPM decided in 2022 to stop inserting them
// by 2035), so that a TLE or an ephemeris of 2027 is read; should one be inserted, times after
// it are 1 s off until ERFA's table is updated. Every instant this layer makes lies in
// [utc_table_start, utc_table_end): 1960-01-01 to 2100-01-01 UTC (the span of the Sun's series,
// eraEpv00, and of --date); text outside it is refused with a message naming the span,
// whatever its time scale (a scene's rows relate every time to a UTC epoch).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "text/calendar_text.hpp"
#include "text/diagnostic.hpp"

namespace conescan::sources {

enum class time_scale { utc, tai, tt, gps };

/// The CCSDS spelling: "UTC", "TAI", "TT", "GPS".
std::string_view to_string(time_scale scale) noexcept;

/// TT - TAI (exact, by definition of TT) and TAI - GPS (GPS time is TAI - 19 s, fixed in 1980).
inline constexpr double tt_minus_tai_s = 32.184;
inline constexpr double tai_minus_gps_s = 19.0;
inline constexpr double seconds_per_day = 86400.0;

/// An instant on the TAI scale: TAI Modified Julian Day number (days from 1858-11-17T00:00 TAI)
/// and the seconds into that TAI day, in [0, 86400). Construct it with the functions below (they
/// keep the seconds in range); compare instants with the operators.
struct instant {
  std::int64_t tai_mjd = 0;
  double tai_seconds = 0;
  friend auto operator<=>(const instant&, const instant&) = default;
};

/// to - from, s. Exact to the rounding of one subtraction of seconds of day (<= 7.3e-12 s).
double seconds_between(const instant& from, const instant& to) noexcept;

/// t + seconds (any sign). The whole days of `seconds` are moved exactly (fmod); the remainder
/// costs one rounding of the seconds of day (<= 7.3e-12 s).
instant add_seconds(const instant& t, double seconds) noexcept;

/// A calendar date and time of day as text holds it, and the syntax of CCSDS and ISO 8601
/// epochs: the ground floor's (text/calendar_text.hpp), which the OMM reader shares.
using text::calendar_time;
using text::parse_calendar;

/// The instant of a calendar time on a scale. Refused: a second of 60 or more except in the last
/// minute of a UTC day that ends with a leap second, and any time outside ERFA's table.
checked<instant> from_calendar(const calendar_time& c, time_scale scale);

/// parse_calendar then from_calendar, with one message naming the text on failure; a trailing
/// 'Z' is accepted only on the UTC scale. The error's file and line are left empty for the
/// caller to fill.
checked<instant> parse_epoch(std::string_view text, time_scale scale);

/// GPS time as receivers count it: `week` whole weeks since 1980-01-06T00:00:00 GPS (counted on,
/// not modulo 1024) and `seconds` into the week, [0, 604800). GPS = TAI - 19 s, without leap
/// seconds. Refused, with a message naming the values: a week that is not a whole number >= 0,
/// seconds outside [0, 604800), a time beyond the UTC table. Exact to one rounding of the
/// seconds of day (the weeks are whole days).
checked<instant> from_gps_week(double week, double seconds);

/// The last UTC year conescan takes (top of file).
inline constexpr int utc_last_year = 2099;

/// The first and the one-past-last instant of UTC conescan takes (1960-01-01T00:00:00 UTC and
/// 2100-01-01T00:00:00 UTC, TAI - UTC = 37 s after ERFA's table: top of file).
instant utc_table_start() noexcept;
instant utc_table_end() noexcept;

/// nullopt when [t0, t1] lies within the table, else an error naming the span.
checked<void> check_in_utc_table(const instant& t0, const instant& t1);

/// TAI - UTC at an instant (37 s since 2017-01-01; a fraction before 1972). Within the table.
double tai_minus_utc_s(const instant& t) noexcept;

/// "YYYY-MM-DDThh:mm:ss.fff" in UTC with `decimals` digits (0..9), 23:59:60 during a leap
/// second (eraD2dtf). For messages and files.
std::string format_utc(const instant& t, int decimals = 6);

/// A two-part Julian Date as ERFA takes it: jd1 + jd2 days (jd1 the half-integer day start).
struct julian_date {
  double jd1 = 0;
  double jd2 = 0;
};

julian_date tai_julian_date(const instant& t) noexcept;
/// TT = TAI + 32.184 s (eraTaitt).
julian_date tt_julian_date(const instant& t) noexcept;
/// UT1 = UTC + ut1_minus_utc_s (eraTaiutc, eraUtcut1). Without IERS data conescan takes
/// UT1 - UTC = 0: |UT1 - UTC| < 0.9 s by the IERS's definition of UTC.
julian_date ut1_julian_date(const instant& t, double ut1_minus_utc_s) noexcept;

}  // namespace conescan::sources
