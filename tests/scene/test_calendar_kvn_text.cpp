// The ground floor's calendar and KVN line syntax (src/text/calendar_text.hpp, kvn_line.hpp), which
// the OMM reader (orbit tier) and the time scales and OEM/AEM readers (sources tier) share: the
// calendar's arithmetic against a day count, both epoch forms alike on every day, the edges of
// the syntax, and the readers taking them alike (an OMM's EPOCH and a KVN comment as the OEM's).
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "orbit/omm.hpp"
#include "sources/kvn.hpp"
#include "sources/time_scales.hpp"
#include "text/calendar_text.hpp"
#include "text/kvn_line.hpp"

namespace tx = conescan::text;

namespace {

std::string two(int v) {
  return (v < 10 ? "0" : "") + std::to_string(v);
}

std::string three(int v) {
  return (v < 100 ? "0" : "") + two(v);
}

// A one-set OMM in KVN whose EPOCH line and an extra line are the test's.
std::string omm_with(const std::string& epoch, const std::string& extra = "") {
  return "CCSDS_OMM_VERS = 2.0\n"
         "CREATION_DATE = 2026-11-26T00:00:00\n"
         "ORIGINATOR = CONESCAN\n" +
         extra +
         "OBJECT_NAME = DELTA 1 DEB\n"
         "OBJECT_ID = 1962-025E\n"
         "CENTER_NAME = EARTH\n"
         "REF_FRAME = TEME\n"
         "TIME_SYSTEM = UTC\n"
         "MEAN_ELEMENT_THEORY = SGP4\n"
         "EPOCH = " +
         epoch +
         "\n"
         "MEAN_MOTION = 15.56387291 [rev/day]\n"
         "ECCENTRICITY = .0030035\n"
         "INCLINATION = 58.0579 [deg]\n"
         "RA_OF_ASC_NODE = 54.0425 [deg]\n"
         "ARG_OF_PERICENTER = 139.1568 [deg]\n"
         "MEAN_ANOMALY = 221.1854 [deg]\n"
         "NORAD_CAT_ID = 6251\n"
         "BSTAR = .12808E-3 [1/ER]\n";
}

std::string omm_reading(const std::string& text) {
  const auto sets = conescan::orbit::read_omm_sets(text, "t.kvn");
  if (!sets.ok()) return sets.error().text();
  const auto& e = sets.value().front().elements.epoch;
  return std::to_string(e.year) + " day " + std::to_string(e.day_of_year);
}

}  // namespace

TEST_CASE("calendar text: leap years, month lengths and days of the year against a day count",
          "[text][calendar]") {
  // The days from 1600-01-01 counted one by one (the Gregorian rule written out once more here)
  // equal the sum of the calendar's month lengths; day_of_year counts within each year.
  long counted = 0;
  for (int year = 1600; year <= 2400; ++year) {
    const bool leap = year % 400 == 0 || (year % 4 == 0 && year % 100 != 0);
    CHECK(tx::is_leap_year(year) == leap);
    int in_year = 0;
    for (int month = 1; month <= 12; ++month) {
      const int days = tx::days_in_month(year, month);
      REQUIRE((days >= 28 && days <= 31));
      for (int day = 1; day <= days; ++day) REQUIRE(tx::day_of_year(year, month, day) == ++in_year);
    }
    CHECK(in_year == (leap ? 366 : 365));
    counted += in_year;
  }
  CHECK(counted == 801 * 365 + 195);  // 1600-2400: 201 leap years less 6 centuries (1700, ...)
  CHECK(tx::days_in_month(2024, 0) == 0);
  CHECK(tx::days_in_month(2024, 13) == 0);
}

TEST_CASE("calendar text: both epoch forms give one date on every day of a leap and a common year",
          "[text][calendar]") {
  for (int year : {2000, 2001, 2100}) {
    for (int month = 1; month <= 12; ++month)
      for (int day = 1; day <= tx::days_in_month(year, month); ++day) {
        const std::string ymd =
            std::to_string(year) + "-" + two(month) + "-" + two(day) + "T12:34:56.5";
        const std::string yd =
            std::to_string(year) + "-" + three(tx::day_of_year(year, month, day)) + "T12:34:56.5";
        const auto a = tx::parse_calendar(ymd), b = tx::parse_calendar(yd);
        REQUIRE(a);
        REQUIRE(b);
        CHECK((a->year == year && a->month == month && a->day == day));
        CHECK((b->year == year && b->month == month && b->day == day));
        CHECK((a->hour == 12 && a->minute == 34 && a->second == 56.5));
      }
  }
  // Both sides of every field's range.
  for (const char* good :
       {"2000-366T00:00:00", "2001-365T23:59:60.999", "2004-02-29T00:00:00", "0000-01-01T00:00:00",
        "9999-12-31T23:59:59Z", "2025-06-21T02:42:00.", "2025-06-21T02:42:07.123456789012345678"})
    CHECK((tx::parse_calendar(good).has_value() == (std::string(good).back() != '.')));
  for (const char* bad : {"2001-366T00:00:00",
                          "2000-000T00:00:00",
                          "2000-367T00:00:00",
                          "2001-02-29T00:00:00",
                          "2001-00-10T00:00:00",
                          "2001-13-10T00:00:00",
                          "2001-04-31T00:00:00",
                          "2001-04-00T00:00:00",
                          "2001-01-01T24:00:00",
                          "2001-01-01T00:60:00",
                          "2001-01-01T00:00:61",
                          "2001-01-01T00:00",
                          "2001-01-01 00:00:00",
                          "2001-01-01T00:00:1e1",
                          "2001-01-01T00:00:12.5e-3",
                          "2001-01-01T00:00:+1.5",
                          "2001-01-01T00:00:01.nan",
                          "2001-01-01T0:00:00",
                          "01-01-01T00:00:00",
                          "",
                          "Z",
                          "2001-1-1T00:00:00",
                          "2001-01-01T00:00:00ZZ",
                          "2001-01-01t00:00:00"})
    CHECK_FALSE(tx::parse_calendar(bad).has_value());
  // Decimals that round to the next second in a double stay in their second.
  const auto nines = tx::parse_calendar("2016-12-31T23:59:59.9999999999999999");
  REQUIRE(nines);
  CHECK(nines->second < 60);
  CHECK(nines->second > 59.99999999999998);
  // The time scales take the ground floor's parser itself.
  CHECK(&conescan::sources::parse_calendar == &tx::parse_calendar);
}

TEST_CASE("calendar text: an OMM's EPOCH is the calendar's syntax, in 1900-2099, no leap second",
          "[text][calendar][omm]") {
  CHECK(omm_reading(omm_with("2006-06-25T19:46:43.980096")) == "2006 day 176");
  CHECK(omm_reading(omm_with("2006-176T19:46:43.980096Z")) == "2006 day 176");
  CHECK(omm_reading(omm_with("2004-366T00:00:00")) == "2004 day 366");
  CHECK(omm_reading(omm_with("1900-01-01T00:00:00")) == "1900 day 1");
  CHECK(omm_reading(omm_with("2099-12-31T23:59:59.999")) == "2099 day 365");
  // Decimals that round to 60 in a double are before second 60: taken, as the time scales do.
  CHECK(omm_reading(omm_with("2006-06-25T19:46:59.9999999999999999")) == "2006 day 176");
  for (const char* bad :
       {"1899-12-31T23:59:59", "2100-01-01T00:00:00", "2005-12-31T23:59:60.5", "2005-366T00:00:00",
        "2005-02-29T00:00:00", "2006-06-25T19:46:12.5e-3", "2006-06-25T19:46", "2006-06-25"}) {
    INFO(bad);
    CHECK_THAT(omm_reading(omm_with(bad)), Catch::Matchers::Contains("is not a UTC epoch"));
  }
}

TEST_CASE("kvn line: one classifier for the OMM and the OEM/AEM readers", "[text][kvn][omm]") {
  using tx::kvn_kind;
  const auto kind = [](const char* line) { return tx::classify_kvn_line(line).kind; };
  CHECK(kind("") == kvn_kind::blank);
  CHECK(kind(" \t ") == kvn_kind::blank);
  CHECK(kind("COMMENT") == kvn_kind::comment);
  CHECK(kind("  COMMENT a = b") == kvn_kind::comment);
  CHECK(kind("COMMENT\tx") == kvn_kind::comment);
  CHECK(kind("COMMENTARY = x") == kvn_kind::keyword_value);
  CHECK(kind("COMMENTxyz") == kvn_kind::malformed);
  CHECK(kind("COMMENT_X") == kvn_kind::marker);
  CHECK(kind("META_START") == kvn_kind::marker);
  CHECK(kind("2020-01-01T00:00:00 1 2 3") == kvn_kind::data);
  CHECK(kind("-1.5 2") == kvn_kind::data);
  CHECK(kind("lower case") == kvn_kind::malformed);
  const tx::kvn_line l = tx::classify_kvn_line("  EPOCH =  2020-001T00:00:00 [x] ");
  CHECK(l.kind == kvn_kind::keyword_value);
  CHECK(l.keyword == "EPOCH");
  CHECK(l.value == "2020-001T00:00:00 [x]");
  CHECK(tx::classify_kvn_line("A = B = C").value == "B = C");
  CHECK(&conescan::sources::classify_kvn_line == &tx::classify_kvn_line);
  // The OMM reader takes comments as the OEM's: a word beginning with COMMENT is none.
  CHECK(omm_reading(omm_with("2006-176T00:00:00", "COMMENT a comment\nCOMMENT\n")) ==
        "2006 day 176");
  CHECK_THAT(omm_reading(omm_with("2006-176T00:00:00", "COMMENTARY = x\n")),
             Catch::Matchers::Contains("t.kvn:4:1: unknown keyword 'COMMENTARY'"));
  CHECK_THAT(omm_reading(omm_with("2006-176T00:00:00", "COMMENTxyz\n")),
             Catch::Matchers::Contains("t.kvn:4: expected KEYWORD = value, not 'COMMENTxyz'"));
  CHECK_THAT(omm_reading(omm_with("2006-176T00:00:00", "META_START\n")),
             Catch::Matchers::Contains("expected KEYWORD = value, not 'META_START'"));
}
