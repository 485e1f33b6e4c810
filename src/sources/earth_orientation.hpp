// Earth orientation parameters (MODEL §10, --eop FILE): UT1 - UTC and the pole's coordinates
// x_p, y_p from an IERS file in the finals2000A format (finals2000A.all, .data, .daily: what the
// IERS Rapid Service publishes, one line per UTC day), for turning an ITRF ephemeris into the
// scene frame (earth_rotation.hpp) with the Earth's real angle instead of UT1 = UTC and a pole
// at the CIP.
//
// The format (IERS readme.finals2000A, fixed columns, 1-based): 8-15 MJD of the day's 0h UTC,
// 17 the pole's flag (I: IERS, P: prediction), 19-27 x_p (arcsec), 38-46 y_p (arcsec), 58 UT1's
// flag, 59-68 UT1 - UTC (s); the other columns (errors, LOD, nutation, Bulletin B) are not read.
// Read: every line up to the first whose x_p, y_p or UT1 - UTC is blank (the end of the
// predictions: the rest of the file is days without values), the days consecutive.
// Refused, with the file and line: a line too short for these columns or whose fields are not
// numbers, a day that is not the one after the line before, a flag other than I or P, a file
// with no day. At most max_days days (a finals2000A.all holds some 20 000).
//
// Between days: linear in UT1 - TAI (continuous across a leap second, where UT1 - UTC jumps by
// 1 s) and in x_p, y_p. IERS recommends a higher-order interpolation with the tidal terms for
// microseconds; linearly the error over a day is a quarter of what each day's value differs from
// its neighbours' mean: in the sample's days below 0.04 ms of UT1 (2 cm along the equator at
// 7000 km) and 0.13 mas of the pole (tests/apps/test_earth_orientation.cpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

namespace conescan::sources {

/// At one instant: UT1 - UTC (s) and the pole's coordinates (rad, IERS sign: x_p along the
/// Greenwich meridian, y_p along 90 deg west).
struct earth_orientation_values {
  double ut1_minus_utc_s = 0;
  double xp_rad = 0;
  double yp_rad = 0;
};

class earth_orientation {
 public:
  /// The most days a file may hold (years 1973 to 2300).
  static constexpr std::size_t max_days = 120000;

  /// Reads `path` (format above).
  static checked<earth_orientation> read_finals2000a(const std::string& path);

  /// The values at t, or nullopt outside [first(), last()].
  std::optional<earth_orientation_values> at(const instant& t) const noexcept;

  /// The first and the last day's 0h UTC.
  instant first() const noexcept { return days_.front().t; }
  instant last() const noexcept { return days_.back().t; }
  /// The file as given, for messages.
  const std::string& path() const noexcept { return path_; }
  /// "FILE covers 2016-02-01 to 2016-05-10 (UTC)", for refusals.
  std::string coverage() const;

 private:
  struct day {
    instant t;               // 0h UTC
    double ut1_minus_tai_s;  // continuous across leap seconds
    double xp_rad, yp_rad;
  };
  std::string path_;
  std::vector<day> days_;
};

}  // namespace conescan::sources
