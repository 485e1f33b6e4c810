// NORAD two-line element sets (TLE): reading and checking them, and their epoch
// (MODEL §10). SGP4/SDP4 (sgp4.hpp) propagates what this reads.
//
// A set is an optional name line ("line 0", with or without a leading "0 ") and two lines of
// 69 columns (Hoots & Roehrich, Spacetrack Report #3, 1980, §12; the column table is in
// tle.cpp). Every line is checked: length, the mod-10 checksum of column 69, each field's
// format and range, the blank separator columns, the order of the lines, and that both lines
// carry one catalogue number. A malformed input is an error value naming the source, the line
// and the field (columns, what was read, what is allowed); nothing throws.
#pragma once

#include <cstddef>
#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "text/diagnostic.hpp"

namespace conescan::orbit {

/// A UTC calendar time, as ERFA's eraDtf2d("UTC", ...) takes it.
struct utc_calendar {
  int year, month, day, hour, minute;
  double second;
};

/// The epoch of an element set, UTC as the TLE writes it: a year and a day of that year with
/// its fraction. NORAD's days have 86400 s (the fraction ignores leap seconds).
struct tle_epoch {
  int year;                ///< four digits: two-digit years 57-99 are 19xx, 00-56 are 20xx
  int day_of_year;         ///< 1 = 1 January
  double fraction_of_day;  ///< [0, 1): the digits after the point, rounded once
};

/// The epoch as a two-part Julian date (UTC): the day's start, JD = N + 0.5 exactly, and the
/// fraction of the day, kept apart so that neither loses digits (as ERFA's two-part dates).
/// jd_day_start(e) + e.fraction_of_day is the epoch.
double jd_day_start(const tle_epoch& epoch) noexcept;

/// The epoch as year, month, day, hour, minute, second (second = remainder of the fraction of
/// the day, to ~1e-11 s), for a day_of_year within its year (as read_tle gives it).
utc_calendar calendar(const tle_epoch& epoch) noexcept;

/// Minutes from the epoch to the UTC Julian date jd_whole + jd_fraction (any split), the time
/// argument of SGP4 (as Vallado's sgp4(jd, fr): days of 1440 min, no leap seconds inside).
double minutes_since_epoch(const tle_epoch& epoch, double jd_whole, double jd_fraction) noexcept;

/// One element set as printed, in the TLE's own units. The mean elements are SGP4's (Kozai
/// mean motion, TEME of epoch); sgp4.hpp's mean_elements() turns them into the model's units.
struct tle {
  std::string name;            ///< line 0 without "0 ", trailing blanks removed; "" if none
  std::string catalog_number;  ///< columns 3-7 as written: "25544", or alpha-5 "A1234" (an
                               ///< OMM's NORAD_CAT_ID as written, up to 9 digits: omm.hpp)
  long satellite_number;       ///< the same decoded (alpha-5: A = 10 .. Z = 33, no I, O); 64
                               ///< bits: an OMM's catalogue numbers beyond 339999 fit
  char classification;         ///< 'U', 'C' or 'S' (a blank column reads as 'U')
  std::string international_designator;  ///< columns 10-17, trailing blanks removed
  tle_epoch epoch;
  double mean_motion_dot_rev_day2;   ///< first derivative of the mean motion / 2, rev/day^2
  double mean_motion_ddot_rev_day3;  ///< second derivative / 6, rev/day^3
  double bstar_per_earth_radius;     ///< B*, the drag term, 1/earth radii
  int ephemeris_type;                ///< column 63 (a blank reads as 0)
  int element_set_number;            ///< columns 65-68
  double inclination_deg;            ///< [0, 180]
  double raan_deg;                   ///< right ascension of the ascending node, [0, 360]
  double eccentricity;               ///< [0, 1)
  double argument_of_perigee_deg;    ///< [0, 360]
  double mean_anomaly_deg;           ///< [0, 360]
  double mean_motion_rev_day;        ///< > 0, revolutions per day
  long revolution_number;            ///< at epoch, columns 64-68
  std::size_t line_number = 0;       ///< line of the source where the set begins (1-based)
};

/// The mod-10 checksum of a TLE line: the sum of the digits of columns 1-68, a '-' counting 1,
/// every other character 0 (Spacetrack Report #3, §12). Column 69 should hold it.
int tle_checksum(std::string_view line) noexcept;

/// The value of a TLE's catalogue-number columns (3-7): five digits, or alpha-5 (a letter other
/// than I and O, then four digits; A0000 = 100000 .. Z9999 = 339999); nullopt for other text.
std::optional<long> catalog_number_value(std::string_view columns) noexcept;

/// Checks and reads lines 1 and 2 of one set (trailing blanks and a '\r' are ignored).
/// `source` and `line1_number` (the line of the source that holds line 1) only place the error
/// messages; the set's name is empty.
checked<tle> parse_tle(std::string_view line1, std::string_view line2,
                       std::string_view source = "TLE", std::size_t line1_number = 1);

/// Every element set of a stream, in order. Blank lines are skipped; any other line must belong
/// to a set. At least one set is required. Lines longer than 256 characters are refused as they
/// are met, so a file that is not a TLE file is refused without reading it whole.
checked<std::vector<tle>> read_tle_sets(std::istream& input, std::string_view source);

/// The same for a file (source = the path as given).
checked<std::vector<tle>> read_tle_sets(const std::filesystem::path& path);

/// Which set read_tle takes from a source that may hold several.
enum class tle_selection {
  first,    ///< the first set; the lines after it are not read
  only_one  ///< the only set: a second set is an error naming the line where it begins (and the
            ///< first few sets, saying to choose with --object: read_tle_object with "")
};

/// One element set of a stream or a file, as `selection` says.
checked<tle> read_tle(std::istream& input, std::string_view source, tle_selection selection);
checked<tle> read_tle(const std::filesystem::path& path, tle_selection selection);

/// The element set of a stream or a file (a catalogue) that `object` names (catalogue.hpp: its
/// NORAD catalogue number, international designator or name; exactly one set must match, every
/// set is read and checked), one set at a time; with `object` "" the only set (only_one).
checked<tle> read_tle_object(std::istream& input, std::string_view source, std::string_view object);
checked<tle> read_tle_object(const std::filesystem::path& path, std::string_view object);

}  // namespace conescan::orbit
