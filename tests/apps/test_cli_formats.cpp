// Real data in, end to end: a star tracker's quaternion table against an AEM of the same attitude
// in conescan-sim's rows, and conescan-fit fed telemetry with UTC or GPS time stamps instead of
// t_s (the same fit).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"
#include "sources/time_scales.hpp"
#include "support/cli.hpp"
#include "text/number_text.hpp"

using conescan_test::parse_csv;
using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::temp_file;

namespace {

const std::string data = CONESCAN_TEST_DATA;

/// The paper orbit's wobble AEM with LINEAR interpolation (the geodesic a table has), and the
/// same quaternions as a star tracker's table with UTC times, scalar last as the AEM writes them.
std::pair<std::string, std::string> aem_and_table() {
  std::istringstream in(conescan_test::read_file(data + "/ccsds/paper-orbit-wobble.aem"));
  std::string aem, table = "utc,q_x,q_y,q_z,q_w\n", line;
  bool in_data = false;
  while (std::getline(in, line)) {
    if (line.rfind("INTERPOLATION_DEGREE", 0) == 0) continue;
    if (line.rfind("INTERPOLATION_METHOD", 0) == 0) line = "INTERPOLATION_METHOD = LINEAR";
    aem += line + "\n";
    if (line == "DATA_STOP") in_data = false;
    if (in_data) {
      std::istringstream fields(line);
      std::string t, x, y, z, w;
      fields >> t >> x >> y >> z >> w;
      table += t + "," + x + "," + y + "," + z + "," + w + "\n";
    }
    if (line == "DATA_START") in_data = true;
  }
  return {aem, table};
}

double max_column_difference(const std::string& a, const std::string& b) {
  const conescan_test::csv_table x = parse_csv(a), y = parse_csv(b);
  REQUIRE(x.rows.size() == y.rows.size());
  REQUIRE(x.header == y.header);
  double worst = 0;
  for (std::size_t r = 0; r < x.rows.size(); ++r)
    for (std::size_t c = 0; c < x.header.size(); ++c) {
      const std::optional<double> u = conescan::text::parse_number(x.rows[r][c]);
      const std::optional<double> v = conescan::text::parse_number(y.rows[r][c]);
      if (u && v) worst = std::max(worst, std::abs(*u - *v));
      if (!u || !v) CHECK(x.rows[r][c] == y.rows[r][c]);
    }
  return worst;
}

}  // namespace

TEST_CASE(
    "formats: a star tracker's quaternion table writes the rows of an AEM of the same "
    "attitude",
    "[cli][attitude_csv]") {
  const auto [aem, table] = aem_and_table();
  const temp_file aem_file(aem, ".aem"), table_file(table, ".csv");
  const std::string scene = "--oem " + data +
                            "/ccsds/paper-orbit.oem --duration-s 3600 --step-s 7 --earth wgs84 "
                            "--model scan --head beta=90 --head beta=-90"
                            // the wobble every 60 s, coarser than 1e-6 deg: its geodesic taken
                            " --interpolation-tolerance-deg 0.05";
  const auto by_aem = run_sim(scene + " --aem " + aem_file.path);
  // The AEM says its frame (REF_FRAME_A TOD); the table's is --attitude-frame's.
  const auto by_table =
      run_sim(scene + " --attitude-csv " + table_file.path + " --attitude-frame TOD");
  const auto by_eme2000 = run_sim(scene + " --attitude-csv " + table_file.path);
  INFO(by_aem.err << by_table.err);
  REQUIRE(by_aem.exit_status == 0);
  REQUIRE(by_table.exit_status == 0);
  // Angles in degrees and km: the two geodesics' rounding (1e-13 rad, test_attitude_csv.cpp).
  CHECK(max_column_difference(by_aem.out, by_table.out) < 1e-9);
  // The same quaternions taken as EME2000's: the attitude turns by TOD <- EME2000, 0.0042 deg at
  // 2000-01-01T12:00 (nutation alone: no precession yet; 0.37 deg in 2026).
  CHECK(max_column_difference(by_aem.out, by_eme2000.out) > 1e-3);
}

TEST_CASE("formats: conescan-fit reads UTC and GPS time stamps as the scene's t_s",
          "[cli][fit][time]") {
  const std::string scene = " --model scan --step-s 60 --orbits 1 --epoch 2016-12-31T23:00:00";
  const std::string heads = " --head sigma=0.05,phase=60,noise=0.01";
  const auto sim = run_sim(scene + heads + " --seed 3");
  REQUIRE(sim.exit_status == 0);
  // The same rows with t_s replaced by UTC text (the leap second at 23:59:60 falls inside) and
  // by GPS week and seconds (GPS = UTC + 17 s before it).
  // The rows' fields with t_s (the second column, after the seed) replaced.
  const auto with_time = [](const std::string& row, const std::string& time) {
    const std::size_t first = row.find(','), second = row.find(',', first + 1);
    return row.substr(0, first + 1) + time + row.substr(second) + "\n";
  };
  std::istringstream in(sim.out);
  std::string line, utc, gps;
  std::getline(in, line);
  REQUIRE(line.rfind("seed,t_s,", 0) == 0);
  utc = with_time(line, "utc");
  gps = with_time(line, "gps_week,gps_s");
  while (std::getline(in, line)) {
    const std::size_t first = line.find(',');
    const double t_s = std::stod(line.substr(first + 1));
    // 2016-12-31T23:00:00 UTC + t_s: 23:59:59 at 3599 s, the leap second 23:59:60 at 3600 s,
    // 2017-01-01T00:00:00 at 3601 s.
    const int whole = static_cast<int>(t_s), after = whole - 3601;
    char text[64];
    if (whole < 3600)
      std::snprintf(text, sizeof text, "2016-12-31T23:%02d:%02d", whole / 60, whole % 60);
    else if (whole == 3600)
      std::snprintf(text, sizeof text, "2016-12-31T23:59:60");
    else
      std::snprintf(text, sizeof text, "2017-01-01T%02d:%02d:%02d", after / 3600, after / 60 % 60,
                    after % 60);
    utc += with_time(line, text);
    // GPS week 1929 began 2016-12-25T00:00 GPS; 2016-12-31T23:00:00 UTC is 23:00:17 GPS; week
    // 1930 begins 3583 s later.
    const double of_week = 6 * 86400 + 23 * 3600 + 17 + t_s;
    gps += with_time(line, of_week < 604800
                               ? "1929," + conescan::text::shortest_text(of_week)
                               : "1930," + conescan::text::shortest_text(of_week - 604800));
  }
  const temp_file by_t(sim.out, ".csv"), by_utc(utc, ".csv"), by_gps(gps, ".csv");
  const std::string fit = scene + " --head sigma=0,noise=0.01 --free h1.sigma,h1.phase --json";
  const auto t = run_program(CONESCAN_FIT_PATH, "--telemetry " + by_t.path + fit);
  REQUIRE(t.exit_status == 0);
  for (const temp_file* other : {&by_utc, &by_gps}) {
    const auto r = run_program(CONESCAN_FIT_PATH, "--telemetry " + other->path + fit);
    INFO(r.err);
    REQUIRE(r.exit_status == 0);
    CHECK(r.out == t.out);
  }
  // Without --epoch (the scene's epoch MODEL §10's default of 2000) absolute times are refused,
  // not read 16 years past the scene; an attitude table's alike.
  const std::string no_epoch = " --model scan --step-s 60 --orbits 1 --head sigma=0,noise=0.01";
  const auto refused = run_program(
      CONESCAN_FIT_PATH, "--telemetry " + by_utc.path + no_epoch + " --free h1.sigma,h1.phase");
  CHECK(refused.exit_status == 2);
  CHECK(refused.err.find("absolute times (utc, GPS) need the scene's epoch") != std::string::npos);
  const temp_file table("utc,roll_deg,pitch_deg,yaw_deg\n2026-01-01T00:00:00,0,0,0\n", ".csv");
  const auto table_refused = run_sim("--attitude-csv " + table.path + " --duration-s 0");
  CHECK(table_refused.exit_status == 2);
  CHECK(table_refused.err.find("--attitude-csv: absolute times (utc, GPS) need the scene's "
                               "epoch") != std::string::npos);
}

namespace {

/// The largest difference of the columns whose names end in `suffix` (numbers), after checking
/// that every text column (statuses) agrees.
double max_difference_of(const conescan_test::csv_table& x, const conescan_test::csv_table& y,
                         const std::string& suffix) {
  REQUIRE(x.rows.size() == y.rows.size());
  REQUIRE(x.header == y.header);
  double worst = 0;
  for (std::size_t c = 0; c < x.header.size(); ++c) {
    const std::string& name = x.header[c];
    const bool numbers = name.size() > suffix.size() && name.ends_with(suffix);
    for (std::size_t r = 0; r < x.rows.size(); ++r) {
      if (!numbers) {
        if (name.ends_with("status")) CHECK(x.rows[r][c] == y.rows[r][c]);
        continue;
      }
      worst = std::max(worst, std::abs(std::stod(x.rows[r][c]) - std::stod(y.rows[r][c])));
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("formats: one orbit as a TLE, a TEME OEM and a GCRF OEM gives the same rows",
          "[cli][frame]") {
  // delta-1-deb's set moved to 2026 (day 176), when GCRF and TOD are 0.37 deg apart.
  std::istringstream tle_lines(conescan_test::read_file(data + "/tle/delta-1-deb.tle"));
  std::string name, line1, line2;
  std::getline(tle_lines, name);
  std::getline(tle_lines, line1);
  std::getline(tle_lines, line2);
  line1.replace(line1.find(" 06176."), 7, " 26176.");
  line1[68] = static_cast<char>('0' + conescan::orbit::tle_checksum(line1));
  const temp_file tle(name + "\n" + line1 + "\n" + line2 + "\n", ".tle");
  const auto set = conescan::orbit::parse_tle(line1, line2);
  REQUIRE(set.ok());
  const conescan::orbit::sgp4_propagator sgp4(set.value());
  const std::string epoch_text = "2026-06-25T19:46:43.980096";
  const conescan::sources::instant epoch =
      conescan::sources::parse_epoch(epoch_text, conescan::sources::time_scale::utc).value();
  // SGP4's TEME states every 30 s from 5 min before the scene to 5 min after it, LAGRANGE 7
  // (SGP4's velocity is not its position's derivative: Hermite would trust it).
  std::string teme =
      "CCSDS_OEM_VERS = 2.0\nCREATION_DATE = 2026-11-26T00:00:00\nORIGINATOR = conescan tests\n"
      "META_START\nOBJECT_NAME = DELTA 1 DEB\nOBJECT_ID = 1962-025E\nCENTER_NAME = EARTH\n"
      "REF_FRAME = TEME\nTIME_SYSTEM = UTC\nSTART_TIME = " +
      conescan::sources::format_utc(conescan::sources::add_seconds(epoch, -300), 9) +
      "\nSTOP_TIME = " +
      conescan::sources::format_utc(conescan::sources::add_seconds(epoch, 3300), 9) +
      "\nINTERPOLATION = LAGRANGE\nINTERPOLATION_DEGREE = 7\nMETA_STOP\n";
  for (int k = -10; k <= 110; ++k) {
    const conescan::orbit::teme_state s = sgp4.state_at(0.5 * k);
    REQUIRE(s.status == conescan::orbit::sgp4_status::ok);
    teme += conescan::sources::format_utc(conescan::sources::add_seconds(epoch, 30.0 * k), 9);
    for (double x : {s.r_teme_km.x, s.r_teme_km.y, s.r_teme_km.z, s.v_teme_km_s.x, s.v_teme_km_s.y,
                     s.v_teme_km_s.z})
      teme += " " + conescan::text::shortest_text(x);
    teme += "\n";
  }
  const temp_file teme_oem(teme, ".oem"), gcrf_oem("", ".oem");
  const std::string convert = std::string(CONESCAN_DEBIAN_PYTHON) + " " +
                              CONESCAN_TEST_SUPPORT "/oem_teme_to_gcrf.py " + teme_oem.path + " " +
                              gcrf_oem.path;
  REQUIRE(std::system(convert.c_str()) == 0);
  REQUIRE(conescan_test::read_file(gcrf_oem.path).find("REF_FRAME = GCRF") != std::string::npos);

  const std::string scene = " --epoch " + epoch_text +
                            " --duration-s 3000 --step-s 10 --earth wgs84 --model scan "
                            "--horizon-km 40 --head beta=90 --head beta=-90,sigma=0.03,phase=60";
  const auto by_tle = run_sim("--tle " + tle.path + scene);
  const auto by_teme = run_sim("--oem " + teme_oem.path + scene);
  const auto by_gcrf = run_sim("--oem " + gcrf_oem.path + scene);
  INFO(by_tle.err << by_teme.err << by_gcrf.err);
  REQUIRE(by_tle.exit_status == 0);
  REQUIRE(by_teme.exit_status == 0);
  REQUIRE(by_gcrf.exit_status == 0);
  const conescan_test::csv_table a = parse_csv(by_tle.out), b = parse_csv(by_teme.out),
                                 c = parse_csv(by_gcrf.out);
  // Measured: 2.1e-10 deg and 3.2e-11 km (TEME OEM), 2.2e-10 deg and 3.8e-11 km (GCRF OEM):
  // LAGRANGE 7's interpolation of SGP4 at 30 s, the two routes' rounding, the frame track.
  for (const auto* other : {&b, &c}) {
    CHECK(max_difference_of(a, *other, "_deg") < 1e-6);
    CHECK(max_difference_of(a, *other, "_km") < 1e-6);
  }
  // The same GCRF numbers taken for TEME's (the old "used as ECI unrotated"): latitudes move by
  // up to the 0.15 deg between the GCRS pole and the true one.
  const temp_file mislabelled(
      conescan_test::read_file(gcrf_oem.path)
          .replace(conescan_test::read_file(gcrf_oem.path).find("REF_FRAME = GCRF"), 16,
                   "REF_FRAME = TEME"),
      ".oem");
  const auto unrotated = run_sim("--oem " + mislabelled.path + scene);
  REQUIRE(unrotated.exit_status == 0);
  const conescan_test::csv_table d = parse_csv(unrotated.out);
  double lat = 0;
  for (std::size_t r = 0; r < a.rows.size(); ++r)
    lat = std::max(lat, std::abs(a.number(r, "lat_deg") - d.number(r, "lat_deg")));
  CHECK(lat > 0.1);  // measured 0.148 deg
}

TEST_CASE(
    "formats: docs/SOURCES.md's \"Your satellite\" runs, and its star tracker is the "
    "attitude it claims",
    "[cli][docs]") {
  // The command as the documentation writes it, run from the repository's root.
  const std::string root = data + "/../..";
  const std::string doc = conescan_test::read_file(root + "/docs/SOURCES.md");
  const std::size_t marker = doc.find("<!-- your-satellite:");
  REQUIRE(marker != std::string::npos);
  const std::size_t start = doc.find("build/conescan-sim", marker);
  const std::size_t stop = doc.find("> rows.csv", start);
  REQUIRE(stop != std::string::npos);
  std::string command = doc.substr(start, stop - start);
  command.replace(0, std::string("build/conescan-sim").size(), CONESCAN_SIM_PATH);
  const auto run = run_sim("", "cd " + root + " && " + command + " #");
  INFO(command << "\n" << run.err);
  REQUIRE(run.exit_status == 0);
  const conescan_test::csv_table rows = parse_csv(run.out);
  REQUIRE(rows.rows.size() == 61);
  for (std::size_t r = 0; r < rows.rows.size(); ++r) CHECK(rows.text(r, "status") == "ok");
  // The table is nadir pointing with roll 0.2 deg and pitch -0.1 deg, given in EME2000.
  const std::string scene =
      " --epoch 2024-05-01T12:00:00 --duration-s 600 --step-s 10 --earth wgs84 --model scan "
      "--horizon-km 40 --head beta=90 --head beta=-90";
  const std::string omm = " --omm " + root + "/data/satellite/iss.json";
  const auto angles = run_sim(omm + " --roll-deg 0.2 --pitch-deg -0.1" + scene);
  REQUIRE(angles.exit_status == 0);
  CHECK(max_difference_of(rows, parse_csv(angles.out), "_deg") < 1e-9);  // measured 7.1e-11
  // Taken as TOD, the same quaternions tilt the attitude by TOD <- EME2000 (0.338 deg).
  const auto as_tod = run_sim(omm + " --attitude-csv " + root +
                              "/data/satellite/star-tracker.csv --attitude-frame TOD" + scene);
  REQUIRE(as_tod.exit_status == 0);
  CHECK(max_difference_of(rows, parse_csv(as_tod.out), "_phase_deg") > 0.05);  // measured 0.094
}

TEST_CASE("formats: --attitude-frame only where a quaternion table uses it", "[cli][time]") {
  const std::string wobble = std::string(CONESCAN_TEST_DATA) + "/attitude/wobble.csv";
  const auto no_table = run_sim("--attitude-frame GCRF --duration-s 0");
  CHECK(no_table.exit_status == 2);
  CHECK(no_table.err.find("--attitude-frame: names the inertial frame of --attitude-csv's "
                          "quaternions, and no --attitude-csv is given") != std::string::npos);
  const auto angles = run_sim("--attitude-csv " + wobble + " --attitude-frame GCRF --duration-s 0");
  CHECK(angles.exit_status == 2);
  CHECK(angles.err.find("this table holds angles") != std::string::npos);
  // The default, as --print-config writes it beside any table, is read.
  CHECK(run_sim("--attitude-csv " + wobble +
                " --attitude-frame EME2000 --duration-s 0 --interpolation-tolerance-deg 0.05")
            .exit_status == 0);
}

TEST_CASE("write-oem with J2: an OEM conescan-sim reads back, the same orbit", "[cli][oem]") {
  // J2's velocity is the osculating ellipse's, not the drifting position's derivative (MODEL
  // §3): as HERMITE the file was refused on reading, its velocities 24.5 m/s from the
  // positions' (a low, nearly equatorial orbit); as LAGRANGE it reads within the tolerance.
  const std::string span = " --epoch 2026-02-14T00:00:00 --step-s 60 --duration-s 6000";
  const std::string orbit =
      "--a-km 7301.5 --e 0.0215 --i-deg 6.3 --argp-deg 307.4 --m0-deg 356.3 --j2" + span;
  const temp_file written("", ".oem");
  const auto elements = run_sim(orbit + " --write-oem " + written.path);
  REQUIRE(elements.exit_status == 0);
  CHECK(conescan_test::read_file(written.path).find("INTERPOLATION = LAGRANGE") !=
        std::string::npos);
  const auto back = run_sim("--oem " + written.path + span);
  INFO(back.err);
  REQUIRE(back.exit_status == 0);
  const auto a = parse_csv(elements.out), b = parse_csv(back.out);
  REQUIRE(a.rows.size() == 101);
  REQUIRE(b.rows.size() == a.rows.size());
  for (std::size_t k = 0; k < a.rows.size(); ++k) {
    CHECK(b.number(k, "r_km") == Approx(a.number(k, "r_km")).margin(1e-6));
    CHECK(b.number(k, "lat_deg") == Approx(a.number(k, "lat_deg")).margin(1e-6));
  }
}
