// The Sun's declination (src/orbit/sun.hpp) against the published instants of the 2025 solstices
// and equinoxes, and the calendar checks.
//
// Expected values, derived independently of the formulas under test:
//  - Solstices: the Sun's declination is then the obliquity of the ecliptic, 23.4360 deg in 2025
//    (IAU 2006: 23.439279 - 0.0130102 T deg, T = 0.25 Julian centuries from J2000). The
//    declination changes only quadratically near a solstice: at 12:00 UTC of 2025-06-21 (9.3 h
//    after the solstice, 02:42 UTC) and of 2025-12-21 (3.1 h before it, 15:03 UTC) it is within
//    0.001 deg of the obliquity.
//  - Equinoxes (USNO: 2025-03-20 09:01 UTC, 2025-09-22 18:19 UTC): the Sun's ecliptic longitude
//    moves 0.9856 deg/day, so at 12:00 UTC it is 2.98 h past 0 deg (March) and 6.32 h before
//    180 deg (September), and delta = asin(sin 23.436 deg sin(lambda)): +0.0487 deg and +0.1032
//    deg (the speed's annual variation of +-1.7 % changes these by < 0.002 deg).
// Tolerance: the formulas' stated accuracy, 0.01 deg.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <optional>

#include "orbit/sun.hpp"

using conescan::orbit::days_in_month;
using conescan::orbit::is_leap_year;
using conescan::orbit::julian_day_number;
using conescan::orbit::sun_declination_from_iso_date;
using conescan::orbit::sun_declination_rad;

namespace {

constexpr double deg = std::numbers::pi / 180;
constexpr double accuracy_deg = 0.01;

double declination_deg(const char* iso_date) {
  const std::optional<double> d = sun_declination_from_iso_date(iso_date);
  REQUIRE(d.has_value());
  return *d / deg;
}

}  // namespace

TEST_CASE("Julian day numbers of known dates", "[sun]") {
  CHECK(julian_day_number(2000, 1, 1) == 2451545);  // J2000.0 is 2000-01-01 12:00
  CHECK(julian_day_number(1999, 12, 31) == 2451544);
  CHECK(julian_day_number(2000, 3, 1) - julian_day_number(2000, 2, 28) == 2);  // 2000 is leap
  CHECK(julian_day_number(1900, 3, 1) - julian_day_number(1900, 2, 28) == 1);  // 1900 is not
  CHECK(julian_day_number(1858, 11, 17) == 2400001);  // MJD 0 is JD 2400000.5
  CHECK(julian_day_number(2025, 1, 1) - julian_day_number(2024, 1, 1) == 366);
}

TEST_CASE("the Sun's declination at the 2025 solstices is the obliquity", "[sun]") {
  const double obliquity_2025_deg = 23.4360;
  CHECK(std::abs(declination_deg("2025-06-21") - obliquity_2025_deg) < accuracy_deg);
  CHECK(std::abs(declination_deg("2025-12-21") + obliquity_2025_deg) < accuracy_deg);
  // A day either side the declination is still within 0.01 deg of the extreme, and no larger.
  CHECK(declination_deg("2025-06-20") < obliquity_2025_deg + accuracy_deg);
  CHECK(declination_deg("2025-06-22") < obliquity_2025_deg + accuracy_deg);
  CHECK(declination_deg("2025-06-20") > obliquity_2025_deg - 0.02);
}

TEST_CASE("the Sun's declination at the 2025 equinoxes", "[sun]") {
  CHECK(std::abs(declination_deg("2025-03-20") - 0.0487) < accuracy_deg);
  CHECK(std::abs(declination_deg("2025-09-22") - 0.1032) < accuracy_deg);
  // The sign changes across each equinox: the Sun moves ~0.4 deg/day in declination there.
  CHECK(declination_deg("2025-03-19") < -0.3);
  CHECK(declination_deg("2025-03-21") > 0.3);
  CHECK(declination_deg("2025-09-21") > 0.4);
  CHECK(declination_deg("2025-09-23") < -0.2);
}

TEST_CASE("the declination stays within the obliquity all year", "[sun]") {
  for (int month = 1; month <= 12; ++month) {
    for (int day = 1; day <= days_in_month(2025, month); ++day) {
      const std::optional<double> d = sun_declination_rad(2025, month, day);
      REQUIRE(d.has_value());
      CHECK(std::abs(*d / deg) < 23.4360 + accuracy_deg);
    }
  }
}

TEST_CASE("invalid dates give nullopt", "[sun]") {
  CHECK_FALSE(sun_declination_from_iso_date("2025-02-29").has_value());  // 2025 is not leap
  CHECK_FALSE(sun_declination_from_iso_date("2024-02-30").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("2025-13-01").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("2025-00-10").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("2025-04-31").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("2025-04-00").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("1900-02-29").has_value());  // century, not leap
  CHECK_FALSE(sun_declination_from_iso_date("2100-02-29").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("1899-12-31").has_value());  // outside 1900..2100
  CHECK_FALSE(sun_declination_from_iso_date("2101-01-01").has_value());
  // Not exactly YYYY-MM-DD.
  CHECK_FALSE(sun_declination_from_iso_date("2025-1-1").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("abc").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("2025-01-01 ").has_value());
  CHECK_FALSE(sun_declination_from_iso_date(" 2025-01-01").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("2025/01/01").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("2025-01-0a").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("+025-01-01").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("20250101").has_value());
  CHECK_FALSE(sun_declination_from_iso_date("2025-01-01T12:00").has_value());
  CHECK_FALSE(sun_declination_rad(2025, 2, 29).has_value());
  CHECK_FALSE(sun_declination_rad(2025, 0, 1).has_value());
  CHECK_FALSE(sun_declination_rad(2025, 1, -1).has_value());
}

TEST_CASE("valid dates at the edges of the calendar checks", "[sun]") {
  CHECK(is_leap_year(2024));
  CHECK(is_leap_year(2000));
  CHECK_FALSE(is_leap_year(1900));
  CHECK_FALSE(is_leap_year(2025));
  CHECK(sun_declination_from_iso_date("2024-02-29").has_value());  // 2024 is leap
  CHECK(sun_declination_from_iso_date("2000-02-29").has_value());  // 400-year rule
  CHECK(sun_declination_from_iso_date("1900-01-01").has_value());
  CHECK(sun_declination_from_iso_date("2100-12-31").has_value());
  CHECK(sun_declination_from_iso_date("2025-04-30").has_value());
  CHECK(sun_declination_from_iso_date("2025-12-31").has_value());
  // The text and the integer forms agree exactly.
  CHECK(*sun_declination_from_iso_date("2024-02-29") == *sun_declination_rad(2024, 2, 29));
  // Late February 2024: the Sun is ~8 deg south and climbing (~0.38 deg/day).
  const double feb29 = declination_deg("2024-02-29");
  CHECK(feb29 < -7);
  CHECK(feb29 > -8.5);
  CHECK(declination_deg("2024-03-01") > feb29);
}
