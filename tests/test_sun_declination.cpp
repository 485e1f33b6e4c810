// The Sun's apparent declination from ERFA (src/sources/sun_declination.hpp): against published
// equinox instants, against the project's low-precision formula (src/orbit/sun.hpp) over
// 1900..2100, and the interpolating track against direct calls.
//
// Equinox instants (USNO, "Earth's Seasons and Apsides", rounded to the minute): 2024-03-20
// 03:06, 2024-09-22 12:44, 2025-03-20 09:01, 2025-09-22 18:19 UTC. At an equinox the Sun's
// apparent ecliptic longitude is 0 or 180 deg, so its declination is its ecliptic latitude
// times cos(obliquity), |beta| < 1.2 arcsec (planetary perturbations): 3.1e-4 deg; it moves
// 0.0164 deg/h there, 1.4e-4 deg in the minute's rounding: |delta| < 4.5e-4 deg.
//
// The measured differences of sun.hpp are printed by `conescan_tests "[sun_erfa]" -s` and
// quoted in docs/SOURCES.md.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "orbit/sun.hpp"
#include "sources/sun_declination.hpp"
#include "support/diagnostic_of.hpp"

using conescan::checked;

using namespace conescan::sources;

namespace {

constexpr double deg = std::numbers::pi / 180;

instant utc(const char* text) {
  return (parse_epoch(text, time_scale::utc)).value();
}

/// The largest |sun.hpp - ERFA| (deg) at noon of every `every_days`-th day of years [first,
/// last], both taken
/// at the same TT = the date's 12:00 (the formula's own assumption: UT for TT), and the day.
struct worst_day {
  double deg = 0;
  int year = 0, month = 0, day = 0;
};

worst_day sun_hpp_against_erfa(int first, int last, int every_days) {
  worst_day worst;
  int count = 0;
  for (int y = first; y <= last; ++y) {
    for (int m = 1; m <= 12; ++m) {
      for (int d = 1; d <= conescan::orbit::days_in_month(y, m); ++d) {
        if (count++ % every_days != 0) continue;
        const double formula = *conescan::orbit::sun_declination_rad(y, m, d);
        const double jd = static_cast<double>(conescan::orbit::julian_day_number(y, m, d));
        const double erfa = apparent_sun_declination_rad(julian_date{jd, 0.0});
        const double diff = std::abs(formula - erfa) / deg;
        if (diff > worst.deg) worst = {diff, y, m, d};
      }
    }
  }
  return worst;
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

TEST_CASE("sun.hpp against ERFA, noon of every tenth day 1900..2100", "[sun_erfa]") {
  // Every day (bench/sources_bench.cpp, docs/SOURCES.md): 0.0057 deg at most over 1950..2050,
  // within the formula's stated 0.01 deg; 0.0069 deg over 1900..1949, 0.0071 over 2051..2100.
  const worst_day centre = sun_hpp_against_erfa(1950, 2050, 10);
  const worst_day early = sun_hpp_against_erfa(1900, 1949, 10);
  const worst_day late = sun_hpp_against_erfa(2051, 2100, 10);
  CHECK(centre.deg < 0.0058);
  CHECK(early.deg < 0.007);
  CHECK(late.deg < 0.0072);
  CHECK(centre.deg > 0.004);  // the formula is no better than its stated class
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
