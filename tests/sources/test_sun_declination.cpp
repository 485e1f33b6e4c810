// The Sun's apparent declination from ERFA (src/sources/sun_declination.hpp, conescan's one Sun:
// sun_moon.hpp's apparent Sun): against published equinox instants, against --date's values
// before the one Sun (the Astronomical Almanac's low-precision formula), and the interpolating
// track against direct calls. The Almanac's formulas over a year: tests/sources/test_sun_moon.cpp.
//
// Equinox instants (USNO, "Earth's Seasons and Apsides", rounded to the minute): 2024-03-20
// 03:06, 2024-09-22 12:44, 2025-03-20 09:01, 2025-09-22 18:19 UTC. At an equinox the Sun's
// apparent ecliptic longitude is 0 or 180 deg, so its declination is its ecliptic latitude
// times cos(obliquity), |beta| < 1.2 arcsec (planetary perturbations): 3.1e-4 deg; it moves
// 0.0164 deg/h there, 1.4e-4 deg in the minute's rounding: |delta| < 4.5e-4 deg.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "sources/sun_declination.hpp"
#include "support/diagnostic_of.hpp"

using conescan::checked;

using namespace conescan::sources;

namespace {

constexpr double deg = std::numbers::pi / 180;

instant utc(const char* text) {
  return (parse_epoch(text, time_scale::utc)).value();
}

}  // namespace

TEST_CASE("ERFA's apparent declination is 0 at the published equinoxes", "[sun_erfa]") {
  for (const char* t : {"2024-03-20T03:06:00", "2024-09-22T12:44:00", "2025-03-20T09:01:00",
                        "2025-09-22T18:19:00"}) {
    INFO(t);
    CHECK(std::abs(sun_declination_rad(utc(t))) / deg < 4.5e-4);
  }
  // The rate near the March equinox, 0.0164 deg/h northward, and at the solstice of June 2025
  // (02:42 UTC) the declination is the true obliquity: the mean one, 23.4360 deg (IAU 2006:
  // 23.439279 - 0.0130102 T deg), plus the nutation in obliquity, |delta eps| <= 9.2 arcsec.
  const double rate = (sun_declination_rad(utc("2025-03-20T10:01:00")) -
                       sun_declination_rad(utc("2025-03-20T08:01:00"))) /
                      2 / deg;
  CHECK(rate == Approx(0.0164).margin(2e-4));
  CHECK(sun_declination_rad(utc("2025-06-21T02:42:00")) / deg == Approx(23.436).margin(0.0026));
}

TEST_CASE("the declination track interpolates ERFA to 1e-9 deg", "[sun_erfa]") {
  const instant t0 = utc("2025-01-01T00:00:00");
  const instant t1 = add_seconds(t0, 365.25 * 86400);
  checked<sun_declination_track> track = sun_declination_track::over(t0, t1);
  REQUIRE(error_of(track) == nullptr);
  const sun_declination_track& s = track.value();
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> offset(0, 365.25 * 86400);
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const instant t = add_seconds(t0, offset(rng));
    worst = std::max(worst, std::abs(s.at(t) - sun_declination_rad(t)) / deg);
  }
  CHECK(s.at(t0) == Approx(sun_declination_rad(t0)).margin(1e-12));
  CHECK(s.at(t1) == Approx(sun_declination_rad(t1)).margin(1e-11));
  CHECK(worst < 1e-9);
  // A span of length 0 (a scene of one row) and one of exactly one node spacing.
  for (double length : {0.0, sun_track_node_spacing_s}) {
    const auto short_track = sun_declination_track::over(t0, add_seconds(t0, length));
    REQUIRE(error_of(short_track) == nullptr);
    const auto& few = short_track.value();
    CHECK(few.at(t0) == Approx(sun_declination_rad(t0)).margin(1e-12));
    const instant end = add_seconds(t0, length);
    CHECK(few.at(end) == Approx(sun_declination_rad(end)).margin(1e-11));
  }
  // A span reaching beyond the UTC conescan takes (2099-12-31, time_scales.hpp) is refused.
  const checked<sun_declination_track> beyond =
      sun_declination_track::over(t0, add_seconds(t0, 4e9));
  CHECK(error_of(beyond) != nullptr);
}
