// Time scales (src/sources/time_scales.hpp) and the Earth rotation angle
// (src/sources/earth_rotation.hpp).
//
// Reference values and their origin:
//  - TAI - UTC: 10 s from 1972-01-01, 36 s from 2015-07-01, 37 s from 2017-01-01 (IERS Bulletin C
//    52, the leap second at the end of 2016-12-31); 0.943482 s on 1960-01-01 (USNO tai-utc.dat,
//    whose first line extended back to 1960 as ERFA does: 1.4178180 + (MJD - 37300) 0.001296 s
//    at MJD 36934).
//  - TT - TAI = 32.184 s and GPS = TAI - 19 s by definition; J2000.0 (2000-01-01T12:00:00 TT) is
//    2000-01-01T11:58:55.816 UTC (Astronomical Almanac, section B).
//  - ERA = 2 pi (0.7790572732640 + 1.00273781191135448 Tu), Tu = JD(UT1) - 2451545.0 (IERS
//    Conventions 2010, Eq. (5.15)), evaluated here in long double from the calendar by hand.
#include <erfa.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "sources/earth_rotation.hpp"
#include "sources/time_scales.hpp"
#include "support/approx.hpp"
#include "support/diagnostic_of.hpp"

using conescan::checked;
using conescan::diagnostic;

using namespace conescan::sources;

namespace {

instant at(const char* text, time_scale scale = time_scale::utc) {
  checked<instant> t = parse_epoch(text, scale);
  if (const diagnostic* e = error_of(t)) FAIL(e->text());
  return t.value();
}

std::string refusal(const char* text, time_scale scale = time_scale::utc) {
  checked<instant> t = parse_epoch(text, scale);
  const diagnostic* e = error_of(t);
  REQUIRE(e != nullptr);
  return e->message;
}

}  // namespace

TEST_CASE("TAI - UTC, TT - TAI and GPS around known dates", "[time]") {
  const instant t2017 = at("2017-04-11T22:31:43.121856");
  CHECK(tai_minus_utc_s(t2017) == 37.0);
  CHECK(tai_minus_utc_s(at("2016-12-31T12:00:00")) == 36.0);
  CHECK(tai_minus_utc_s(at("1972-01-01T00:00:00")) == 10.0);
  CHECK_WITHIN(tai_minus_utc_s(at("1960-01-01T00:00:00")), 1.4178180 - 366 * 0.001296, 1e-12);
  // The same wall-clock text on each scale: TAI is 37 s after UTC, TT 32.184 s after TAI.
  CHECK(seconds_between(at("2017-04-11T22:31:43.121856", time_scale::tai), t2017) == 37.0);
  CHECK_WITHIN(seconds_between(at("2017-04-11T22:31:43.121856", time_scale::tt),
                               at("2017-04-11T22:31:43.121856", time_scale::tai)),
               32.184, 1e-11);
  CHECK(seconds_between(at("2017-04-11T22:31:43", time_scale::gps),
                        at("2017-04-11T22:31:43", time_scale::utc)) == 18.0);
  CHECK(at("1980-01-06T00:00:00", time_scale::gps) == at("1980-01-06T00:00:00"));  // GPS epoch
  CHECK(format_utc(at("2000-01-01T12:00:00", time_scale::tt), 3) == "2000-01-01T11:58:55.816");
  const julian_date tt = tt_julian_date(at("2000-01-01T12:00:00", time_scale::tt));
  CHECK_WITHIN(tt.jd1 + tt.jd2, 2451545.0, 1e-9);
}

TEST_CASE("the leap second at the end of 2016", "[time]") {
  CHECK(seconds_between(at("2016-12-31T23:59:59"), at("2017-01-01T00:00:00")) == 2.0);
  CHECK(seconds_between(at("2016-12-31T23:59:59"), at("2016-12-31T23:59:60.5")) == 1.5);
  CHECK(format_utc(at("2016-12-31T23:59:60.5"), 3) == "2016-12-31T23:59:60.500");
  CHECK(format_utc(add_seconds(at("2016-12-31T23:59:59"), 2.0), 0) == "2017-01-01T00:00:00");
  CHECK(refusal("2017-12-31T23:59:60").find("without a leap second") != std::string::npos);
  CHECK(refusal("2016-12-31T23:59:61").find("malformed") != std::string::npos);
  // No leap second on other scales, nor before the last minute of the day.
  CHECK(refusal("2016-12-31T23:59:60", time_scale::tai).find("without") != std::string::npos);
  // That day has one, at 23:59:60: said so (it was "a day without a leap second").
  CHECK(refusal("2016-12-31T23:58:60").find("outside the last minute of the day") !=
        std::string::npos);
}

TEST_CASE("epochs: calendar and day-of-year forms, any decimals, Z on UTC only", "[time]") {
  CHECK(at("2017-101T22:31:43.121856") == at("2017-04-11T22:31:43.121856"));
  CHECK(at("2016-366T00:00:00") == at("2016-12-31T00:00:00"));
  CHECK(at("2015-08-27T00:01:00.000000000Z") == at("2015-08-27T00:01:00"));
  CHECK(seconds_between(at("2015-08-27T00:01:00"), at("2015-08-27T00:01:00.000000001")) ==
        Approx(1e-9).margin(1e-11));
  for (const char* bad :
       {"2017-04-11 22:31:43", "2017-4-11T22:31:43", "2017-02-29T00:00:00", "2017-04-11T24:00:00",
        "2017-04-11T22:60:00", "2017-04-11T22:31:43.", "2017-04-11T22:31:43.5e3",
        "2017-04-11T22:31:4", "2017-366T00:00:00", "2017-000T00:00:00", "2017-04-11", "",
        "2017-04-11T22:31:43.1.2", "2017-04-11T22:31:43+00:00", "+2017-04-11T22:31:43",
        "2017-04-11T22:31:nan", "2017-04-11T-1:31:43"}) {
    INFO(bad);
    CHECK(refusal(bad).find("malformed epoch") != std::string::npos);
  }
  CHECK(refusal("2017-04-11T22:31:43Z", time_scale::tai).find("ends in Z") != std::string::npos);
}

TEST_CASE("times outside ERFA's leap-second table are refused, on every scale", "[time]") {
  CHECK(refusal("1959-12-31T23:59:59").find("leap-second table") != std::string::npos);
  CHECK(refusal("2100-01-01T00:00:00").find("2099-12-31") != std::string::npos);
  CHECK(refusal("2100-06-01T00:00:00", time_scale::tt).find("leap-second table") !=
        std::string::npos);
  at("1960-01-01T00:00:00");
  at("2099-12-31T23:59:59.999");
  CHECK(utc_table_start() == at("1960-01-01T00:00:00"));
  CHECK(utc_table_end() == add_seconds(at("2099-12-31T23:59:59"), 1.0));
  CHECK(check_in_utc_table(at("2000-01-01T00:00:00"), at("2099-01-01T00:00:00")).ok());
  const checked<void> e =
      check_in_utc_table(at("2099-01-01T00:00:00"), add_seconds(at("2099-12-31T00:00:00"), 1e6));
  REQUIRE_FALSE(e.ok());
  CHECK(e.error().message.find("leaves the leap-second table") != std::string::npos);
}

TEST_CASE("after ERFA's table: no further leap second, TAI - UTC = 37 s", "[time]") {
  // Both sides of the table's end (2026-12-31 with ERFA 2.0.0): one TAI - UTC, 86400 s a day.
  const instant before = at("2026-12-31T12:00:00"), after = at("2027-01-01T12:00:00");
  CHECK(tai_minus_utc_s(before) == 37.0);
  CHECK(tai_minus_utc_s(after) == 37.0);
  CHECK(seconds_between(before, after) == 86400.0);
  CHECK(seconds_between(at("2027-06-30T23:59:59"), at("2027-07-01T00:00:00")) == 1.0);
  CHECK(refusal("2027-06-30T23:59:60").find("without a leap second") != std::string::npos);
  CHECK(format_utc(at("2099-12-31T23:59:59.5"), 1) == "2099-12-31T23:59:59.5");
}

TEST_CASE("instants agree with ERFA's own UTC to TAI (eraDtf2d, eraUtctai)", "[time]") {
  std::mt19937_64 rng(14);
  std::uniform_int_distribution<int> year(1960, 2026), month(1, 12), day(1, 28), hour(0, 23),
      minute(0, 59);
  std::uniform_real_distribution<double> second(0.0, 60.0);
  double worst_s = 0;
  for (int k = 0; k < 2000; ++k) {
    const calendar_time c{year(rng), month(rng), day(rng), hour(rng), minute(rng), second(rng)};
    checked<instant> t = from_calendar(c, time_scale::utc);
    REQUIRE(error_of(t) == nullptr);
    double u1 = 0, u2 = 0, tai1 = 0, tai2 = 0;
    REQUIRE(eraDtf2d("UTC", c.year, c.month, c.day, c.hour, c.minute, c.second, &u1, &u2) == 0);
    REQUIRE(eraUtctai(u1, u2, &tai1, &tai2) == 0);
    const julian_date ours = tai_julian_date(t.value());
    worst_s = std::max(worst_s, std::abs(((ours.jd1 - tai1) + (ours.jd2 - tai2)) * 86400.0));
  }
  // ERFA holds the time of day as a fraction of a day (a rounding of 1e-11 s): measured 1.9e-11
  // s at most over 2e5 times 1972..2026, 2.9e-11 s over 1960..1971 (drifting TAI - UTC).
  CHECK(worst_s < 5e-11);
}

TEST_CASE("seconds between instants and adding seconds are exact where the numbers are", "[time]") {
  const instant t = at("2017-04-11T22:31:43.121856");
  for (double s : {0.5, -0.5, 86400.25, -3.75, 1e6, -1e6 - 0.125, 3.0 * 365.25 * 86400.0}) {
    INFO(s);
    CHECK(seconds_between(t, add_seconds(t, s)) == Approx(s).margin(1e-11));
  }
  const instant u = add_seconds(t, 1.5e-3);
  CHECK(u > t);
  CHECK(add_seconds(u, -1.5e-3) == t);
  // Across years: days times 86400 plus a difference of seconds of day.
  CHECK(seconds_between(at("2000-01-01T00:00:00"), at("2017-01-01T00:00:00")) ==
        (6210.0 * 86400.0 + 5.0));  // 6210 days and five leap seconds (2005, 08, 12, 15, 16)
}

TEST_CASE("Earth rotation angle against IERS 2010 Eq. (5.15) from the calendar", "[time][era]") {
  const long double two_pi = 2 * std::numbers::pi_v<long double>;
  // At J2000.0 UT1 (UT1 = UTC: dut1 = 0), ERA = 0.7790572732640 turns = 280.46061837504 deg.
  CHECK_WITHIN(earth_rotation_angle_rad(at("2000-01-01T12:00:00")) * 180 / std::numbers::pi,
               280.46061837504, 1e-9);
  // 2017-04-11T22:31:43.121856 UTC: MJD 57854, JD 2457854.5 + 81103.121856 / 86400.
  const long double tu = (2457854.5L - 2451545.0L) + 81103.121856L / 86400.0L;
  const long double turns = 0.7790572732640L + tu + 0.00273781191135448L * tu;
  const long double era = two_pi * (turns - std::floor(turns));
  CHECK_WITHIN(earth_rotation_angle_rad(at("2017-04-11T22:31:43.121856")), static_cast<double>(era),
               1e-12);
  // UT1 - UTC moves it at the Earth's rate.
  const double shift = earth_rotation_angle_rad(at("2017-04-11T22:31:43.121856"), 0.5) -
                       earth_rotation_angle_rad(at("2017-04-11T22:31:43.121856"));
  CHECK_WITHIN(shift, 0.5 * earth_rotation_rate_rad_s, 1e-13);
}

TEST_CASE("ITRF to inertial: a point fixed on the Earth moves at w x r", "[time][era]") {
  const instant t = at("2017-04-11T22:31:43.121856");
  const cartesian_state fixed{{6378137.0, 0.0, 1000.0}, {0.0, 0.0, 0.0}};
  const cartesian_state i = inertial_from_itrf(fixed, t);
  const double era = earth_rotation_angle_rad(t);
  CHECK_WITHIN(i.r_m.x, 6378137.0 * std::cos(era), 1e-8);
  CHECK_WITHIN(i.r_m.y, 6378137.0 * std::sin(era), 1e-8);
  CHECK(i.r_m.z == 1000.0);
  // Velocity: the Earth's rate times the radius, along the inertial east at that longitude.
  CHECK_WITHIN(i.v_m_s.x, -earth_rotation_rate_rad_s * 6378137.0 * std::sin(era), 1e-12);
  CHECK_WITHIN(i.v_m_s.y, earth_rotation_rate_rad_s * 6378137.0 * std::cos(era), 1e-12);
  // The same point 1 s later, turned with the later angle, is where the velocity predicts
  // (to the curvature of the circle, w^2 r / 2 = 0.017 m).
  const cartesian_state later = inertial_from_itrf(fixed, add_seconds(t, 1.0));
  CHECK_WITHIN(later.r_m.x, i.r_m.x + i.v_m_s.x, 0.02);
  CHECK_WITHIN(later.r_m.y, i.r_m.y + i.v_m_s.y, 0.02);
}
