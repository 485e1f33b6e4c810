// Real data in, end to end: a star tracker's quaternion table against an AEM of the same attitude
// in conescan-sim's rows, and conescan-fit fed telemetry with UTC or GPS time stamps instead of
// t_s (the same fit).
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>

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
                            "--model scan --head beta=90 --head beta=-90";
  const auto by_aem = run_sim(scene + " --aem " + aem_file.path);
  const auto by_table = run_sim(scene + " --attitude-csv " + table_file.path);
  INFO(by_aem.err << by_table.err);
  REQUIRE(by_aem.exit_status == 0);
  REQUIRE(by_table.exit_status == 0);
  // Angles in degrees and km: the two geodesics' rounding (1e-13 rad, test_attitude_csv.cpp).
  CHECK(max_column_difference(by_aem.out, by_table.out) < 1e-9);
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
}
