// Earth orientation (--eop; src/sources/earth_orientation.hpp, earth_rotation.hpp): the IERS
// finals2000A sample read as written (tests/data/eop/), its days interpolated (through a leap
// second too), hostile files refused with their line, the ITRF turn with UT1 and the pole against
// ERFA's own composition (eraC2tcio), and an ITRF OEM through conescan-sim with and without
// --eop: the rows' orbit moves by what the Earth's orientation says.
#include <erfa.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "sources/earth_orientation.hpp"
#include "sources/earth_rotation.hpp"
#include "support/cli.hpp"

namespace src = conescan::sources;
using conescan::norm;
using conescan::vec3;
using conescan_test::run_sim;
using conescan_test::temp_file;

namespace {

constexpr double arcsec = std::numbers::pi / (180.0 * 3600.0);
const std::string sample = CONESCAN_TEST_DATA "/eop/finals2000A-2016-sample.txt";

src::instant utc(const char* text) {
  return src::parse_epoch(text, src::time_scale::utc).value();
}

// A finals2000A line (the columns earth_orientation.hpp reads, and the error columns after).
std::string finals_line(int y, int m, int d, double mjd, char flag, double xp, double yp,
                        double ut1) {
  char line[128];
  std::snprintf(line, sizeof line, "%2d%2d%2d %8.2f %c %9.6f%9.6f %9.6f%9.6f  %c%10.7f%10.7f",
                y % 100, m, d, mjd, flag, xp, 0.000031, yp, 0.000025, flag, ut1, 0.0000042);
  return line;
}

std::string refusal_of(const std::string& body) {
  const temp_file file(body, ".txt");
  const auto read = src::earth_orientation::read_finals2000a(file.path);
  REQUIRE_FALSE(read.ok());
  const std::string text = read.error().text();
  return text.substr(text.find(file.path) + file.path.size());
}

// ERFA's own route, ITRS to CIRS: rc2t = eraC2tcio(I, ERA, W) maps CIRS to ITRS.
vec3<double> cirs_by_erfa(const vec3<double>& itrs, const src::instant& t,
                          const src::earth_orientation_values& eop) {
  const src::julian_date tt = src::tt_julian_date(t);
  const std::string utc_text = src::format_utc(t, 9);
  int y = 0, mo = 0, d = 0, h = 0, mi = 0;
  double s = 0;
  REQUIRE(std::sscanf(utc_text.c_str(), "%d-%d-%dT%d:%d:%lf", &y, &mo, &d, &h, &mi, &s) == 6);
  double utc1 = 0, utc2 = 0, ut11 = 0, ut12 = 0;
  REQUIRE(eraDtf2d("UTC", y, mo, d, h, mi, s, &utc1, &utc2) == 0);
  REQUIRE(eraUtcut1(utc1, utc2, eop.ut1_minus_utc_s, &ut11, &ut12) == 0);
  double rpom[3][3], identity[3][3], rc2t[3][3];
  eraPom00(eop.xp_rad, eop.yp_rad, eraSp00(tt.jd1, tt.jd2), rpom);
  eraIr(identity);
  eraC2tcio(identity, eraEra00(ut11, ut12), rpom, rc2t);
  double p[3] = {itrs.x, itrs.y, itrs.z};
  double out[3];
  eraTrxp(rc2t, p, out);
  return {out[0], out[1], out[2]};
}

// The data lines of an OEM: time and position (km).
std::vector<std::pair<std::string, vec3<double>>> oem_positions(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::pair<std::string, vec3<double>>> out;
  bool data = false;
  while (std::getline(in, line)) {
    if (line.rfind("META_STOP", 0) == 0) {
      data = true;
      continue;
    }
    if (!data || line.empty()) continue;
    std::istringstream fields(line);
    std::string t;
    vec3<double> r;
    fields >> t >> r.x >> r.y >> r.z;
    out.push_back({t, r});
  }
  return out;
}

}  // namespace

TEST_CASE("eop: the sample read as written, linear between days", "[eop]") {
  const auto read = src::earth_orientation::read_finals2000a(sample);
  INFO((read.ok() ? std::string() : read.error().text()));
  REQUIRE(read.ok());
  const src::earth_orientation& eop = read.value();
  CHECK(eop.first() == utc("2016-02-01T00:00:00"));
  CHECK(eop.last() == utc("2016-05-10T00:00:00"));
  CHECK(eop.coverage() == sample + " covers 2016-02-01 to 2016-05-10 (UTC)");
  // Line 1 (IERS values) and line 100 (a prediction), as written.
  const auto first = eop.at(utc("2016-02-01T00:00:00")).value();
  CHECK(first.ut1_minus_utc_s == Approx(0.0262864).margin(1e-14));
  CHECK(first.xp_rad == Approx(-0.003225 * arcsec).epsilon(1e-13));
  CHECK(first.yp_rad == Approx(0.299494 * arcsec).epsilon(1e-13));
  const auto last = eop.at(utc("2016-05-10T00:00:00")).value();
  CHECK(last.ut1_minus_utc_s == Approx(-0.1508450).margin(1e-14));
  CHECK(last.yp_rad == Approx(0.480379 * arcsec).epsilon(1e-13));
  // Halfway through 2016-02-01: the mean of lines 1 and 2 (no leap second: UT1 - UTC linear).
  const auto noon = eop.at(utc("2016-02-01T12:00:00")).value();
  CHECK(noon.ut1_minus_utc_s == Approx((0.0262864 + 0.0249911) / 2).epsilon(1e-12));
  CHECK(noon.xp_rad == Approx((-0.003225 - 0.004706) / 2 * arcsec).epsilon(1e-12));
  CHECK(noon.yp_rad == Approx((0.299494 + 0.301252) / 2 * arcsec).epsilon(1e-12));
  CHECK_FALSE(eop.at(utc("2016-01-31T23:59:59")));
  CHECK_FALSE(eop.at(utc("2016-05-10T00:00:01")));
  // Linear interpolation's own error: each IERS day against its neighbours' mean (four times
  // the error of interpolating over one day, at its middle): at most 0.15 ms of UT1 and 0.5 mas
  // of the pole (earth_orientation.hpp).
  double worst_ut1 = 0, worst_pole = 0;
  for (int day = 2; day <= 85; ++day) {
    const src::instant t = src::add_seconds(eop.first(), (day - 1) * 86400.0);
    const auto at = eop.at(t).value();
    const auto before = eop.at(src::add_seconds(t, -86400.0)).value();
    const auto after = eop.at(src::add_seconds(t, 86400.0)).value();
    worst_ut1 = std::max(worst_ut1, std::abs(at.ut1_minus_utc_s -
                                             (before.ut1_minus_utc_s + after.ut1_minus_utc_s) / 2));
    worst_pole = std::max({worst_pole, std::abs(at.xp_rad - (before.xp_rad + after.xp_rad) / 2),
                           std::abs(at.yp_rad - (before.yp_rad + after.yp_rad) / 2)});
  }
  CHECK(worst_ut1 < 1.5e-4);
  CHECK(worst_pole < 0.5e-3 * arcsec);
  // The test's line writer reproduces the file's first line, columns and all.
  std::ifstream in(sample);
  std::string line1;
  std::getline(in, line1);
  CHECK(line1.rfind(finals_line(2016, 2, 1, 57419, 'I', -0.003225, 0.299494, 0.0262864), 0) == 0);
}

TEST_CASE("eop: across a leap second UT1 - TAI is interpolated, not UT1 - UTC", "[eop]") {
  // 2016 ended with a leap second: UT1 - UTC went from -0.59 s to +0.41 s.
  const temp_file file(finals_line(2016, 12, 31, 57753, 'I', 0.1, 0.3, -0.5923) + "\n" +
                           finals_line(2017, 1, 1, 57754, 'I', 0.1, 0.3, 0.4069) + "\n",
                       ".txt");
  const auto eop = src::earth_orientation::read_finals2000a(file.path).value();
  // UT1 - TAI: -36.5923 and -36.5931 over the day's 86401 s (TAI - UTC 36, then 37); linear in
  // UT1 - UTC, noon would be 0.5 s off.
  CHECK(eop.at(utc("2016-12-31T12:00:00"))->ut1_minus_utc_s ==
        Approx(-0.5923 - 0.0008 * 43200 / 86401).margin(1e-12));
  CHECK(eop.at(utc("2016-12-31T23:59:60.5"))->ut1_minus_utc_s ==
        Approx(-0.5923 - 0.0008 * 86400.5 / 86401).margin(1e-12));
  CHECK(eop.at(utc("2017-01-01T00:00:00"))->ut1_minus_utc_s == Approx(0.4069).epsilon(1e-12));
}

TEST_CASE("eop: hostile files refused with their line", "[eop]") {
  const std::string ok = finals_line(2016, 2, 1, 57419, 'I', -0.003225, 0.299494, 0.0262864);
  const std::string next = finals_line(2016, 2, 2, 57420, 'I', -0.004706, 0.301252, 0.0249911);
  CHECK(refusal_of(ok + "\n" + next.substr(0, 60) + "\n") ==
        ":2: a line of 60 characters: finals2000A's lines reach UT1 - UTC at columns 59-68");
  CHECK(refusal_of(ok + "\n" + finals_line(2016, 2, 3, 57421, 'I', 0, 0.3, 0.02) + "\n") ==
        ":2: MJD 57421 after 57419: the days must follow each other");
  std::string bad_number = next;
  bad_number[63] = 'x';
  CHECK(refusal_of(ok + "\n" + bad_number + "\n").find(":2: columns 59-68 (UT1 - UTC) hold") == 0);
  std::string bad_flag = next;
  bad_flag[16] = 'Q';
  CHECK(refusal_of(ok + "\n" + bad_flag + "\n") ==
        ":2: column 17 holds 'Q', not I (IERS) or P (prediction)");
  CHECK(refusal_of(finals_line(2016, 2, 1, 57419, 'I', 0, 0.3, 3.5) + "\n")
            .find(":1: UT1 - UTC 3.5 s") == 0);
  CHECK(refusal_of("") == ": no day with UT1 - UTC and the pole: not a finals2000A file");
  std::string no_mjd = ok;
  no_mjd.replace(7, 8, "  hello ");
  CHECK(refusal_of(no_mjd + "\n").find(":1: columns 8-15 hold 'hello'") == 0);
  // The end of the predictions: days without values end the table, whatever follows.
  std::string blank = next;
  blank.replace(58, 10, std::string(10, ' '));
  const temp_file file(ok + "\n" + blank + "\ngarbage\n", ".txt");
  const auto eop = src::earth_orientation::read_finals2000a(file.path);
  REQUIRE(eop.ok());
  CHECK(eop.value().last() == utc("2016-02-01T00:00:00"));
  CHECK_FALSE(src::earth_orientation::read_finals2000a("no-such-eop-file.txt").ok());
}

TEST_CASE("eop: the ITRF turn with UT1 and the pole is ERFA's", "[eop]") {
  const src::cartesian_state itrf{{4.1e6, -5.2e6, 2.3e6}, {1200.0, 3400.0, -6100.0}};
  const src::instant t = utc("2016-03-14T15:09:26.5");
  const src::earth_orientation_values eop{-0.0512, 0.03 * arcsec, 0.42 * arcsec};
  const src::cartesian_state turned = src::inertial_from_itrf(itrf, t, eop);
  const vec3<double> expected = cirs_by_erfa(itrf.r_m, t, eop);
  CHECK(norm(turned.r_m - expected) < 1e-8);
  // Values of zero: the turn without them but for s' (8 microarcsec in 2016: 0.3 mm).
  const src::cartesian_state zero =
      src::inertial_from_itrf(itrf, t, src::earth_orientation_values{});
  const src::cartesian_state old = src::inertial_from_itrf(itrf, t, 0.0);
  CHECK(norm(zero.r_m - old.r_m) < 1e-3);
  CHECK(norm(zero.v_m_s - old.v_m_s) < 1e-6);
  // 0.9 s of UT1 turns a point 7000 km from the axis by 0.46 km (earth_rotation.hpp).
  const src::cartesian_state equator{{7e6, 0, 0}, {0, 0, 0}};
  const double moved = norm(src::inertial_from_itrf(equator, t, {0.9, 0, 0}).r_m -
                            src::inertial_from_itrf(equator, t, 0.0).r_m);
  CHECK(moved == Approx(459.4).margin(0.1));
}

TEST_CASE("eop: an ITRF OEM through conescan-sim moves by the Earth's orientation", "[eop][cli]") {
  // A circular 7000 km orbit at 51.6 deg, in ITRF (turned with UT1 = UTC), a state a minute.
  const src::instant t0 = utc("2016-03-01T00:00:00");
  std::ostringstream oem;
  oem << "CCSDS_OEM_VERS = 2.0\nCREATION_DATE = 2026-01-01T00:00:00\nORIGINATOR = test\n\n"
         "META_START\nOBJECT_NAME = test\nOBJECT_ID = NONE\nCENTER_NAME = EARTH\n"
         "REF_FRAME = ITRF2014\nTIME_SYSTEM = UTC\nSTART_TIME = 2016-03-01T00:00:00\n"
         "STOP_TIME = 2016-03-01T02:00:00\nINTERPOLATION = HERMITE\nINTERPOLATION_DEGREE = 7\n"
         "META_STOP\n\n";
  const double radius = 7e6, inclination = 51.6 * std::numbers::pi / 180;
  const double rate = std::sqrt(3.986004418e14 / (radius * radius * radius));
  std::vector<vec3<double>> itrs;
  for (int k = 0; k <= 120; ++k) {
    const src::instant t = src::add_seconds(t0, 60.0 * k);
    const double u = rate * 60.0 * k;
    const vec3<double> r(radius * std::cos(u), radius * std::sin(u) * std::cos(inclination),
                         radius * std::sin(u) * std::sin(inclination));
    const vec3<double> v(-radius * rate * std::sin(u),
                         radius * rate * std::cos(u) * std::cos(inclination),
                         radius * rate * std::cos(u) * std::sin(inclination));
    const double era = src::earth_rotation_angle_rad(t, 0.0), c = std::cos(era), s = std::sin(era);
    const vec3<double> r_itrs(c * r.x + s * r.y, -s * r.x + c * r.y, r.z);
    const vec3<double> v_rot(c * v.x + s * v.y, -s * v.x + c * v.y, v.z);
    const vec3<double> v_itrs = v_rot - vec3<double>(-src::earth_rotation_rate_rad_s * r_itrs.y,
                                                     src::earth_rotation_rate_rad_s * r_itrs.x, 0);
    itrs.push_back(r_itrs);
    char line[256];
    std::snprintf(line, sizeof line, "%s %.17g %.17g %.17g %.17g %.17g %.17g\n",
                  src::format_utc(t, 6).c_str(), r_itrs.x / 1e3, r_itrs.y / 1e3, r_itrs.z / 1e3,
                  v_itrs.x / 1e3, v_itrs.y / 1e3, v_itrs.z / 1e3);
    oem << line;
  }
  const temp_file file(oem.str(), ".oem");
  const temp_file with_out("", ".oem"), without_out("", ".oem");
  const std::string scene = "--oem " + file.path + " --duration-s 3600 --step-s 60 --summary ";
  const auto with = run_sim(scene + "--eop " + sample + " --write-oem " + with_out.path);
  INFO(with.err);
  REQUIRE(with.exit_status == 0);
  REQUIRE(run_sim(scene + "--write-oem " + without_out.path).exit_status == 0);
  const auto a = oem_positions(with_out.path), b = oem_positions(without_out.path);
  REQUIRE(a.size() == 61);
  REQUIRE(b.size() == 61);
  const src::earth_orientation eop = src::earth_orientation::read_finals2000a(sample).value();
  double largest = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const src::instant t = src::add_seconds(t0, 60.0 * static_cast<double>(k));
    // In the CIRS, by ERFA: the turn with the day's values against UT1 = UTC and no pole; the
    // scene frame is the CIRS turned by the equation of the origins, the same in both runs.
    const vec3<double> expected = cirs_by_erfa(itrs[k], t, eop.at(t).value()) -
                                  cirs_by_erfa(itrs[k], t, src::earth_orientation_values{});
    const double moved_m = norm(a[k].second - b[k].second) * 1e3;
    CHECK(moved_m == Approx(norm(expected)).margin(1e-3));
    largest = std::max(largest, moved_m);
  }
  // On 2016-03-01 UT1 - UTC was -0.0204 s (at most 10 m along the equator at 7000 km) and the
  // pole 0.354 arcsec from the CIP (12 m): together up to 16 m.
  CHECK(largest > 12);
  CHECK(largest < 20);
  // Refused: the Orekit ITRF example (2017) beyond the sample's days, naming the line; --eop
  // without an ITRF OEM.
  const auto refused =
      run_sim("--oem " CONESCAN_TEST_DATA "/ccsds/OEMExample5ITRF.txt --eop " + sample);
  CHECK(refused.exit_status == 2);
  CHECK(refused.err.find("OEMExample5ITRF.txt:16: --oem: no Earth orientation for "
                         "2017-04-11T22:31:43.121856 (ITRF): --eop " +
                         sample + " covers 2016-02-01 to 2016-05-10 (UTC)") != std::string::npos);
  const auto no_itrf = run_sim("--eop " + sample);
  CHECK(no_itrf.exit_status == 2);
  CHECK(no_itrf.err.find("--eop: turns an ITRF --oem's states with the Earth's orientation, and "
                         "this scene's orbit is not an OEM: drop it") != std::string::npos);
}
