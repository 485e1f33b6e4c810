#include "sources/time_scales.hpp"
#include "conescan/enum_names.hpp"
#include "text/number_text.hpp"

#include <erfa.h>
#include <erfaextra.h>

#include <cmath>

namespace conescan::sources {

namespace {

constexpr double mjd_zero_jd = 2400000.5;  // JD of MJD 0 (ERFA's DJM0)

/// Whole days and seconds into [0, 86400): one carry either way covers |seconds| < 2 days.
instant normalised(std::int64_t mjd, double seconds) noexcept {
  if (seconds >= seconds_per_day) {
    seconds -= seconds_per_day;
    ++mjd;
  } else if (seconds < 0) {
    seconds += seconds_per_day;
    --mjd;
  }
  return instant{mjd, seconds};
}

/// The Modified Julian Day number of a Gregorian date (eraCal2jd: exact integer in a double);
/// nullopt for an invalid date.
std::optional<std::int64_t> mjd_of_date(int year, int month, int day) noexcept {
  double djm0 = 0, djm = 0;
  if (eraCal2jd(year, month, day, &djm0, &djm) != 0) return std::nullopt;
  return static_cast<std::int64_t>(djm);
}

/// TAI - UTC at a UTC date and fraction of day (eraDat), and whether conescan takes it: ERFA's
/// status 0 (1960 up to its release year + 5) or +1 ("dubious year": later, where eraDat gives
/// its last value, 37 s, i.e. no further leap second), up to utc_last_year (time_scales.hpp).
struct dat_value {
  double seconds;
  bool in_table;
};

dat_value dat_at(int year, int month, int day, double fraction_of_day) noexcept {
  double dat = 0;
  const int status = eraDat(year, month, day, fraction_of_day, &dat);
  return dat_value{dat, status >= 0 && year <= utc_last_year};
}

/// A UTC day's length minus 86400 s: the leap second (or, before 1972, the step) that ends it,
/// as eraDtf2d computes it: the jump of TAI - UTC at the next midnight beyond its drift.
double utc_day_extra_seconds(int year, int month, int day) noexcept {
  const double dat0 = dat_at(year, month, day, 0.0).seconds;
  const double dat12 = dat_at(year, month, day, 0.5).seconds;
  int y2 = 0, m2 = 0, d2 = 0;
  double fraction = 0, djm0 = 0, djm = 0;
  eraCal2jd(year, month, day, &djm0, &djm);
  eraJd2cal(djm0, djm + 1.5, &y2, &m2, &d2, &fraction);
  const double dat24 = dat_at(y2, m2, d2, 0.0).seconds;
  return dat24 - (2.0 * dat12 - dat0);
}

/// The first year eraDat calls dubious (its release year + 6), found once by asking it.
int first_dubious_year() noexcept {
  static const int year = [] {
    int y = 2000;
    double dat = 0;
    while (y < 3000 && eraDat(y, 1, 1, 0.0, &dat) == 0) ++y;
    return y;
  }();
  return year;
}

std::string two_digits(int v) {
  return std::string(v < 10 ? "0" : "") + std::to_string(v);
}

std::string describe_table() {
  return "conescan takes UTC 1960-01-01 to " + std::to_string(utc_last_year) + "-12-31 (ERFA " +
         std::string(eraVersion()) + "'s leap-second table to " +
         std::to_string(first_dubious_year() - 1) + "-12-31, then no further leap second)";
}

}  // namespace

std::string_view to_string(time_scale scale) noexcept {
  static constexpr enum_names<time_scale, 4> names{{{time_scale::utc, "UTC"},
                                                    {time_scale::tai, "TAI"},
                                                    {time_scale::tt, "TT"},
                                                    {time_scale::gps, "GPS"}}};
  return name_of(names, scale, "?");
}

double seconds_between(const instant& from, const instant& to) noexcept {
  return static_cast<double>(to.tai_mjd - from.tai_mjd) * seconds_per_day +
         (to.tai_seconds - from.tai_seconds);
}

instant add_seconds(const instant& t, double seconds) noexcept {
  const double remainder = std::fmod(seconds, seconds_per_day);  // exact
  const auto days = static_cast<std::int64_t>((seconds - remainder) / seconds_per_day);
  return normalised(t.tai_mjd + days, t.tai_seconds + remainder);
}

checked<instant> from_calendar(const calendar_time& c, time_scale scale) {
  const std::optional<std::int64_t> mjd = mjd_of_date(c.year, c.month, c.day);
  if (!mjd) return diagnostic::in_file({}, 0, "no such date");
  const bool last_minute = c.hour == 23 && c.minute == 59;
  const double day_extra =
      scale == time_scale::utc ? utc_day_extra_seconds(c.year, c.month, c.day) : 0;
  const double extra = last_minute ? day_extra : 0;
  if (!(c.second < 60.0 + extra)) {
    return diagnostic::in_file(
        {}, 0,
        extra > 0 ? "second " + std::to_string(c.second) + " beyond the leap second"
        : day_extra > 0
            ? "second 60 outside the last minute of the day (its leap second is "
              "23:59:60 UTC)"
            : "second 60 on a day without a leap second (" + std::string(to_string(scale)) + ")");
  }
  const double seconds_of_day = 3600.0 * c.hour + 60.0 * c.minute + c.second;
  double tai_offset = 0;
  switch (scale) {
    case time_scale::utc: {
      // The fraction of this UTC day's own length (86401 s on a leap-second day): eraDat wants
      // it in [0, 1) and uses it only for the drift of TAI - UTC before 1972.
      const double fraction = seconds_of_day / (seconds_per_day + extra);
      const dat_value dat = dat_at(c.year, c.month, c.day, fraction);
      if (!dat.in_table)
        return diagnostic::in_file({}, 0, "outside the leap-second table: " + describe_table());
      tai_offset = dat.seconds;
      break;
    }
    case time_scale::tai:
      break;
    case time_scale::tt:
      tai_offset = -tt_minus_tai_s;
      break;
    case time_scale::gps:
      tai_offset = tai_minus_gps_s;
      break;
  }
  const instant t = normalised(*mjd, seconds_of_day + tai_offset);
  if (t < utc_table_start() || !(t < utc_table_end())) {
    return diagnostic::in_file({}, 0, "outside the leap-second table: " + describe_table());
  }
  return t;
}

checked<instant> parse_epoch(std::string_view text, time_scale scale) {
  const std::string quoted = quote(text);
  if (!text.empty() && text.back() == 'Z' && scale != time_scale::utc) {
    return diagnostic::in_file({}, 0,
                               "epoch " + quoted + " ends in Z (UTC) but the time system is " +
                                   std::string(to_string(scale)));
  }
  const std::optional<calendar_time> c = parse_calendar(text);
  if (!c) {
    return diagnostic::in_file(
        {}, 0,
        "malformed epoch " + quoted +
            " (expected YYYY-MM-DDThh:mm:ss[.fff] or YYYY-DDDThh:mm:ss[.fff])");
  }
  checked<instant> t = from_calendar(*c, scale);
  if (!t.ok())
    t.error().message =
        "epoch " + quoted + " " + std::string(to_string(scale)) + ": " + t.error().message;
  return t;
}

checked<instant> from_gps_week(double week, double seconds) {
  constexpr double seconds_per_week = 7 * seconds_per_day;
  if (!(week >= 0 && week == std::floor(week) && week < 1e6))
    return diagnostic::in_file(
        {}, 0,
        "GPS week " + text::shortest_text(week) + " is not a whole number of weeks in [0, 1e6)");
  if (!(seconds >= 0 && seconds < seconds_per_week))
    return diagnostic::in_file(
        {}, 0,
        "GPS seconds of the week " + text::shortest_text(seconds) + " are outside [0, 604800)");
  static const instant gps_epoch = from_calendar({1980, 1, 6, 0, 0, 0}, time_scale::gps).value();
  const instant t = add_seconds(add_seconds(gps_epoch, week * seconds_per_week), seconds);
  if (!(t < utc_table_end()))
    return diagnostic::in_file({}, 0,
                               "GPS week " + text::shortest_text(week) +
                                   " is beyond the leap-second table: " + describe_table());
  return t;
}

instant utc_table_start() noexcept {
  static const instant t = normalised(*mjd_of_date(1960, 1, 1), dat_at(1960, 1, 1, 0.0).seconds);
  return t;
}

instant utc_table_end() noexcept {
  static const instant t = [] {
    // TAI - UTC of the last day taken: no leap second is assumed after ERFA's table.
    return normalised(*mjd_of_date(utc_last_year + 1, 1, 1),
                      dat_at(utc_last_year, 12, 31, 0.0).seconds);
  }();
  return t;
}

checked<void> check_in_utc_table(const instant& t0, const instant& t1) {
  if (t0 < utc_table_start() || !(t1 < utc_table_end())) {
    return diagnostic::in_file({}, 0,
                               "span " + format_utc(t0, 3) + " to " + format_utc(t1, 3) +
                                   " UTC leaves the leap-second table: " + describe_table());
  }
  return success();
}

julian_date tai_julian_date(const instant& t) noexcept {
  return julian_date{mjd_zero_jd + static_cast<double>(t.tai_mjd), t.tai_seconds / seconds_per_day};
}

julian_date tt_julian_date(const instant& t) noexcept {
  const julian_date tai = tai_julian_date(t);
  julian_date tt;
  eraTaitt(tai.jd1, tai.jd2, &tt.jd1, &tt.jd2);
  return tt;
}

julian_date ut1_julian_date(const instant& t, double ut1_minus_utc_s) noexcept {
  const julian_date tai = tai_julian_date(t);
  double utc1 = 0, utc2 = 0;
  eraTaiutc(tai.jd1, tai.jd2, &utc1, &utc2);
  julian_date ut1;
  eraUtcut1(utc1, utc2, ut1_minus_utc_s, &ut1.jd1, &ut1.jd2);
  return ut1;
}

double tai_minus_utc_s(const instant& t) noexcept {
  const julian_date tai = tai_julian_date(t);
  double utc1 = 0, utc2 = 0, fraction = 0;
  int y = 0, m = 0, d = 0;
  eraTaiutc(tai.jd1, tai.jd2, &utc1, &utc2);
  eraJd2cal(utc1, utc2, &y, &m, &d, &fraction);
  return dat_at(y, m, d, fraction).seconds;
}

std::string format_utc(const instant& t, int decimals) {
  const julian_date tai = tai_julian_date(t);
  double utc1 = 0, utc2 = 0;
  eraTaiutc(tai.jd1, tai.jd2, &utc1, &utc2);
  int y = 0, m = 0, d = 0, hmsf[4] = {0, 0, 0, 0};
  eraD2dtf("UTC", decimals, utc1, utc2, &y, &m, &d, hmsf);
  std::string s = std::to_string(y) + "-" + two_digits(m) + "-" + two_digits(d) + "T" +
                  two_digits(hmsf[0]) + ":" + two_digits(hmsf[1]) + ":" + two_digits(hmsf[2]);
  if (decimals > 0) {
    std::string fraction = std::to_string(hmsf[3]);
    s += "." + std::string(static_cast<std::size_t>(decimals) - fraction.size(), '0') + fraction;
  }
  return s;
}

}  // namespace conescan::sources
