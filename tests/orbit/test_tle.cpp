// Two-line element sets (src/orbit/tle.hpp): fields, epoch, files of several sets, and every
// kind of malformed input with the message it must give.
#include <unistd.h>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "orbit/tle.hpp"

using namespace conescan::orbit;

namespace {

// The ISS example of CelesTrak's "NORAD Two-Line Element Set Format" (and Wikipedia's).
const std::string iss_name = "ISS (ZARYA)";
const std::string iss1 = "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927";
const std::string iss2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537";

/// `line` with columns `first`.. replaced by `text` and the checksum made right again, so that
/// a test reaches the check it means to reach.
std::string edited(std::string line, std::size_t first_column, const std::string& text) {
  line.replace(first_column - 1, text.size(), text);
  line[68] = static_cast<char>('0' + tle_checksum(line));
  return line;
}

conescan::checked<std::vector<tle>> read_text(const std::string& text) {
  std::istringstream in(text);
  return read_tle_sets(in, "sat.tle");
}

/// The error text of reading `text`; fails if it is read.
std::string error_of(const std::string& text) {
  const conescan::checked<std::vector<tle>> result = read_text(text);
  if (!result.ok()) return result.error().text();
  FAIL("read without an error:\n" << text);
  return {};
}

std::string error_of_lines(const std::string& line1, const std::string& line2) {
  return error_of(line1 + "\n" + line2 + "\n");
}

tle only_set(const std::string& text) {
  const conescan::checked<std::vector<tle>> result = read_text(text);
  if (!result.ok()) FAIL(result.error().text());
  const auto& sets = result.value();
  REQUIRE(sets.size() == 1);
  return sets[0];
}

}  // namespace

TEST_CASE("tle: the checksum is the digits' sum mod 10, a minus counting 1", "[tle]") {
  CHECK(tle_checksum(iss1) == 7);
  CHECK(tle_checksum(iss2) == 7);
  CHECK(tle_checksum("1 -") == 2);
  CHECK(tle_checksum("ABC +.") == 0);
  CHECK(tle_checksum(std::string(68, '9') + "5") == 2);  // column 69 is not summed: 612 mod 10
}

TEST_CASE("tle: every field of the ISS example", "[tle]") {
  const tle set = only_set(iss_name + "\n" + iss1 + "\n" + iss2 + "\n");
  CHECK(set.name == iss_name);
  CHECK(set.catalog_number == "25544");
  CHECK(set.satellite_number == 25544);
  CHECK(set.classification == 'U');
  CHECK(set.international_designator == "98067A");
  CHECK(set.epoch.year == 2008);
  CHECK(set.epoch.day_of_year == 264);
  CHECK(set.epoch.fraction_of_day == 0.51782528);
  CHECK(set.mean_motion_dot_rev_day2 == -0.00002182);
  CHECK(set.mean_motion_ddot_rev_day3 == 0.0);
  CHECK(set.bstar_per_earth_radius == -0.11606 * 1e-4);
  CHECK(set.ephemeris_type == 0);
  CHECK(set.element_set_number == 292);
  CHECK(set.inclination_deg == 51.6416);
  CHECK(set.raan_deg == 247.4627);
  CHECK(set.eccentricity == 0.0006703);
  CHECK(set.argument_of_perigee_deg == 130.5360);
  CHECK(set.mean_anomaly_deg == 325.0288);
  CHECK(set.mean_motion_rev_day == 15.72125391);
  CHECK(set.revolution_number == 56353);
  CHECK(set.line_number == 1);
}

TEST_CASE("tle: the epoch as a Julian date pair and a UTC calendar time", "[tle]") {
  const tle set = only_set(iss1 + "\n" + iss2 + "\n");
  CHECK(set.name.empty());
  CHECK(jd_day_start(set.epoch) == 2454729.5);  // 2008-09-20 0 h (python-sgp4: jdsatepoch)
  const utc_calendar c = calendar(set.epoch);
  CHECK(c.year == 2008);
  CHECK(c.month == 9);
  CHECK(c.day == 20);
  CHECK(c.hour == 12);
  CHECK(c.minute == 25);
  CHECK(std::fabs(c.second - 40.104192) < 1e-9);  // 0.51782528 d = 44740.104192 s
  // Julian dates at 0 h (as python-sgp4's jday gives them): 2000-01-01, 1957-01-01 and
  // 2056-12-31, day 366 of a leap year.
  CHECK(jd_day_start({2000, 1, 0}) == 2451544.5);
  CHECK(jd_day_start({1957, 1, 0}) == 2435839.5);
  CHECK(jd_day_start({2056, 366, 0}) == 2472363.5);
  CHECK(calendar({2056, 366, 0}).month == 12);
  CHECK(calendar({2056, 366, 0}).day == 31);
  CHECK(calendar({2023, 60, 0}).month == 3);  // 1 March in a common year,
  CHECK(calendar({2024, 60, 0}).day == 29);   // 29 February in a leap year
  // Minutes since the epoch from any split of a Julian date.
  CHECK(minutes_since_epoch(set.epoch, 2454729.5, 0.51782528) == 0.0);
  CHECK(minutes_since_epoch(set.epoch, 2454730.5, 0.51782528) == 1440.0);
  CHECK(std::fabs(minutes_since_epoch(set.epoch, 2454729.0, 1.01782528) - 0.0) < 1e-9);
}

TEST_CASE("tle: two-digit years 57-99 are 19xx, 00-56 are 20xx", "[tle]") {
  const auto year_of = [](const std::string& yy) {
    return (parse_tle(edited(iss1, 19, yy), iss2)).value().epoch.year;
  };
  CHECK(year_of("57") == 1957);
  CHECK(year_of("99") == 1999);
  CHECK(year_of("00") == 2000);
  CHECK(year_of("56") == 2056);
}

TEST_CASE("tle: names, blank lines, CR LF, trailing blanks and several sets", "[tle]") {
  const std::string text = "\n0 FIRST  \r\n" + iss1 + "\r\n" + iss2 + "  \r\n\n" + iss1 + "\n" +
                           iss2 + "\nTHIRD\n" + edited(iss1, 3, "A0001") + "\n" +
                           edited(iss2, 3, "A0001") + "\n\n";
  const conescan::checked<std::vector<tle>> result = read_text(text);
  REQUIRE(result.ok());
  const auto& sets = result.value();
  REQUIRE(sets.size() == 3);
  CHECK(sets[0].name == "FIRST");  // "0 " dropped, as space-track's three-line sets write it
  CHECK(sets[0].line_number == 2);
  CHECK(sets[1].name.empty());
  CHECK(sets[1].line_number == 6);
  CHECK(sets[2].name == "THIRD");
  CHECK(sets[2].line_number == 8);
  CHECK(sets[2].catalog_number == "A0001");
  CHECK(sets[2].satellite_number == 100001);  // alpha-5: A = 10
}

TEST_CASE("tle: a UTF-8 byte order mark before the first line is skipped", "[tle]") {
  CHECK(only_set("\xEF\xBB\xBF" + iss1 + "\n" + iss2 + "\n").satellite_number == 25544);
  CHECK(only_set("\xEF\xBB\xBF" + iss_name + "\n" + iss1 + "\n" + iss2).name == iss_name);
}

TEST_CASE("tle: alpha-5 catalogue numbers skip I and O", "[tle]") {
  const auto number_of = [](const std::string& digits) {
    const conescan::checked<tle> r = parse_tle(edited(iss1, 3, digits), edited(iss2, 3, digits));
    return r.ok() ? r.value().satellite_number : -1;
  };
  CHECK(number_of("H9999") == 179999);
  CHECK(number_of("J0000") == 180000);
  CHECK(number_of("P0000") == 230000);
  CHECK(number_of("Z9999") == 339999);
  CHECK(number_of("I0000") == -1);
  CHECK(number_of("O0000") == -1);
  CHECK(number_of("a0000") == -1);
}

TEST_CASE("tle: a wrong checksum names the file, the line and both digits", "[tle][bad input]") {
  std::string bad = iss2;
  bad[68] = '3';
  CHECK(error_of(iss_name + "\n" + iss1 + "\n" + bad + "\n") ==
        "sat.tle:3: line 2: checksum is 7, the line says 3");
  std::string letter = iss1;
  letter[68] = 'x';
  CHECK(error_of_lines(letter, iss2) ==
        "sat.tle:1: line 1, column 69 (checksum) holds 'x', not a digit");
}

TEST_CASE("tle: a line of the wrong length is refused", "[tle][bad input]") {
  CHECK(error_of_lines(iss1.substr(0, 68), iss2) ==
        "sat.tle:1: line 1 is 68 characters long, a TLE line has 69");
  CHECK(error_of_lines(iss1, iss2 + "0") ==
        "sat.tle:2: line 2 is 70 characters long, a TLE line has 69");
  CHECK(error_of_lines(iss1, "2") == "sat.tle:2: line 2 is 1 characters long, a TLE line has 69");
  CHECK(error_of(std::string(300, 'x')) ==
        "sat.tle:1: the line is longer than 256 characters: not an element set");
}

TEST_CASE("tle: non-numeric and malformed fields name their columns", "[tle][bad input]") {
  CHECK(error_of_lines(iss1, edited(iss2, 9, " 5x.6416")) ==
        "sat.tle:2: line 2, columns 9-16 (inclination (deg)): ' 5x.6416' is not a decimal number");
  CHECK(error_of_lines(edited(iss1, 21, "264.5178252a"), iss2) ==
        "sat.tle:1: line 1, columns 21-32 (epoch day of the year): '264.5178252a' is not a "
        "decimal number");
  CHECK(error_of_lines(edited(iss1, 54, "-11606 4"), iss2) ==
        "sat.tle:1: line 1, columns 54-61 (B* drag term): '-11606 4' is not of the form ' "
        "12345-6' (+-0.12345 x 10^-6)");
  CHECK(error_of_lines(iss1, edited(iss2, 27, "00067 3")) ==
        "sat.tle:2: line 2, columns 27-33 (eccentricity (decimal point assumed)): '00067 3' is "
        "not 7 digits (a leading decimal point is assumed)");
  CHECK(error_of_lines(iss1, edited(iss2, 53, "15.72.25391")) ==
        "sat.tle:2: line 2, columns 53-63 (mean motion (rev/day)): '15.72.25391' is not a "
        "decimal number");
  CHECK(error_of_lines(edited(iss1, 19, "O8"), iss2) ==
        "sat.tle:1: line 1, columns 19-20 (epoch year): 'O8' is not two digits");
  CHECK(error_of_lines(edited(iss1, 65, " 2x2"), iss2) ==
        "sat.tle:1: line 1, columns 65-68 (element set number): ' 2x2' is not a whole number");
  CHECK(error_of_lines(edited(iss1, 8, "X"), iss2) ==
        "sat.tle:1: line 1, column 8 (classification): 'X' is not U, C, S or blank");
  CHECK(error_of_lines(edited(iss1, 18, "7"), iss2) ==
        "sat.tle:1: line 1, column 18 must be blank, it holds '7'");
  CHECK(error_of_lines(edited(iss1, 35, ".0000\t182"), iss2) ==
        "sat.tle:1: line 1, column 40 holds a control or non-ASCII character (byte 9)");
}

TEST_CASE("tle: values outside their range are refused", "[tle][bad input]") {
  CHECK(error_of_lines(iss1, edited(iss2, 9, "180.0001")) ==
        "sat.tle:2: line 2, columns 9-16 (inclination (deg)): 180.0001 is outside [0, 180]");
  CHECK(error_of_lines(iss1, edited(iss2, 18, "360.0001")) ==
        "sat.tle:2: line 2, columns 18-25 (right ascension of the ascending node (deg)): "
        "360.0001 is outside [0, 360]");
  CHECK(error_of_lines(iss1, edited(iss2, 53, " 0.00000000")) ==
        "sat.tle:2: line 2, columns 53-63 (mean motion (rev/day)): 0.00000000 is not positive");
  CHECK(error_of_lines(edited(iss1, 19, "07366.50000000"), iss2) ==
        "sat.tle:1: line 1, columns 21-32 (epoch day of the year): 366.50000000 is outside [1, "
        "366) for 2007");
  CHECK(error_of_lines(edited(iss1, 19, "08000.50000000"), iss2) ==
        "sat.tle:1: line 1, columns 21-32 (epoch day of the year): 000.50000000 is outside [1, "
        "367) for 2008");
  // Both sides of the boundaries are read.
  CHECK((parse_tle(iss1, edited(iss2, 9, "180.0000"))).ok());
  CHECK((parse_tle(edited(iss1, 19, "08366.99999999"), iss2)).ok());
  CHECK((parse_tle(edited(iss1, 19, "08001.00000000"), iss2)).ok());
}

TEST_CASE("tle: the lines of a set must come in order and complete", "[tle][bad input]") {
  CHECK(error_of(iss2 + "\n" + iss1 + "\n") ==
        "sat.tle:1: line 2 of an element set without a line 1 before it");
  CHECK(error_of(iss1 + "\n") ==
        "sat.tle:1: line 1 of an element set is not followed by its line 2");
  CHECK(error_of(iss1 + "\n" + iss1 + "\n" + iss2 + "\n") ==
        "sat.tle:2: expected line 2 of the element set begun on line 1, found '" + iss1 + "'");
  CHECK(error_of("NAME\nOTHER NAME\n" + iss1 + "\n" + iss2 + "\n") ==
        "sat.tle:2: expected line 1 of the element set named on line 1, found 'OTHER NAME'");
  CHECK(error_of(iss1 + "\n" + iss2 + "\nLAST NAME\n") ==
        "sat.tle:3: the name line 'LAST NAME' is not followed by an element set");
  CHECK(error_of(iss1 + "\n" + edited(iss2, 3, "25545") + "\n") ==
        "sat.tle:2: line 2, columns 3-7 (satellite number): '25545' differs from line 1's "
        "'25544'");
  CHECK(error_of(std::string("NAME\0X\n", 7) + iss1 + "\n" + iss2 + "\n") ==
        "sat.tle:1: the name line 'NAME\\x00X' holds a control character: not an element set");
}

TEST_CASE("tle: an empty source, a missing file and a directory", "[tle][bad input]") {
  CHECK(error_of("") == "sat.tle: holds no element set");
  CHECK(error_of("\n  \n\t\n") == "sat.tle: holds no element set");
  const conescan::checked<std::vector<tle>> missing =
      read_tle_sets(std::filesystem::path("/nonexistent/sat.tle"));
  REQUIRE(!missing.ok());
  CHECK(missing.error().text() == "/nonexistent/sat.tle: cannot open: No such file or directory");
  const conescan::checked<tle> directory =
      read_tle(std::filesystem::temp_directory_path(), tle_selection::first);
  REQUIRE(!directory.ok());
  CHECK(directory.error().message == "cannot read: Is a directory");
}

TEST_CASE("tle: the first set, or the only one", "[tle]") {
  const std::string two = iss_name + "\n" + iss1 + "\n" + iss2 + "\nSECOND\n" + iss1 + "\n" + iss2;
  std::istringstream first_in(two + "\nno element set here\n");
  const conescan::checked<tle> first = read_tle(first_in, "sat.tle", tle_selection::first);
  REQUIRE(first.ok());
  CHECK(first.value().name == iss_name);  // the lines after the first set are not read

  std::istringstream only_in(two);
  const conescan::checked<tle> only = read_tle(only_in, "sat.tle", tle_selection::only_one);
  REQUIRE(!only.ok());
  CHECK(only.error().text() ==
        "sat.tle:4: a second element set begins here: the file is a catalogue of several; "
        "choose one with --object and its NORAD catalogue number, international designator "
        "(1998-067A) or name: line 1 'ISS (ZARYA)' (NORAD 25544, 1998-067A); line 4 'SECOND' "
        "(NORAD 25544, 1998-067A)");

  std::istringstream malformed_second(iss1 + "\n" + iss2 + "\n" + iss1 + "\n");
  const conescan::checked<tle> bad = read_tle(malformed_second, "sat.tle", tle_selection::only_one);
  REQUIRE(!bad.ok());
  CHECK(bad.error().text() == "sat.tle:3: line 1 of an element set is not followed by its line 2");

  std::istringstream one(iss1 + "\n" + iss2 + "\n");
  CHECK((read_tle(one, "sat.tle", tle_selection::only_one)).ok());

  // From a file, by path.
  // A name of this process's own: other builds may run this test at the same time.
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("conescan_iss_" + std::to_string(getpid()) + ".tle");
  std::ofstream(path) << iss_name << "\n" << iss1 << "\n" << iss2 << "\n";
  const conescan::checked<tle> from_file = read_tle(path, tle_selection::only_one);
  std::filesystem::remove(path);
  REQUIRE(from_file.ok());
  CHECK(from_file.value().satellite_number == 25544);
}

TEST_CASE("tle: parse_tle places its errors at the lines it is told", "[tle][bad input]") {
  std::string bad = iss2;
  bad[68] = '0';
  const conescan::checked<tle> r = parse_tle(iss1, bad, "scene.toml", 12);
  REQUIRE(!r.ok());
  CHECK(r.error().text() == "scene.toml:13: line 2: checksum is 7, the line says 0");
}
