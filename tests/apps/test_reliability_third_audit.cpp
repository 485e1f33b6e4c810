// The third audit (docs/RELIABILITY.md, "A third audit"): the rough edges a new user and a hostile
// tester met, each pinned by the command that showed it. The OMM reader's are in
// tests/orbit/test_omm.cpp, the plotting scripts' in tests/plot_scripts.sh, Python's in
// tests/python/test_fit.py and the README's C++ example in tests/doc_examples.py.
#include <sys/stat.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/guarded_main.hpp"
#include "support/cli.hpp"
#include "text/number_text.hpp"
#include "text/out_of_memory.hpp"

namespace fs = std::filesystem;
using conescan_test::csv_table;
using conescan_test::parse_csv;
using conescan_test::read_file;
using conescan_test::run_program;
using conescan_test::run_result;
using conescan_test::run_sim;
using conescan_test::temp_file;

namespace {

run_result run_fit(const std::string& args, const std::string& before = "") {
  return run_program(CONESCAN_FIT_PATH, args, before);
}

void check_refused(const run_result& r, const std::vector<std::string>& said) {
  INFO("stderr: " << r.err);
  CHECK(r.exit_status == 2);
  CHECK(r.out.empty());
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one line
  for (const std::string& s : said) CHECK(r.err.find(s) != std::string::npos);
}

const std::string scene = " --model scan --step-s 30 --orbits 1";
const std::string truth_heads =
    " --head sigma=0.05,phase=60,noise=0.01 --head beta=-90,sigma=0.03,phase=200,noise=0.01";
const std::string start_heads = " --head sigma=0,noise=0.01 --head beta=-90,sigma=0,noise=0.01";

// conescan-sim's CSV of the truth: one orbit at 30 s.
const std::string& telemetry_csv() {
  static const std::string csv = run_sim(scene + truth_heads + " --seed 5").out;
  return csv;
}

// The telemetry with its t_s column replaced by gps_week, gps_s for a scene whose epoch is
// 2026-01-04T00:00:00 UTC: the start of GPS week 2400 (GPS = UTC + 18 s).
std::string with_gps_times(const std::string& csv, int week) {
  std::istringstream in(csv);
  std::string line, out;
  std::size_t column = 0;
  for (bool header = true; std::getline(in, line); header = false) {
    std::vector<std::string> fields;
    std::istringstream split(line);
    for (std::string f; std::getline(split, f, ',');) fields.push_back(f);
    if (header) {
      column =
          static_cast<std::size_t>(std::find(fields.begin(), fields.end(), "t_s") - fields.begin());
      fields[column] = "gps_week,gps_s";
    } else {
      fields[column] = std::to_string(week) + "," +
                       conescan::text::shortest_text(std::stod(fields[column]) + 18);
    }
    for (std::size_t k = 0; k < fields.size(); ++k) out += (k ? "," : "") + fields[k];
    out += "\n";
  }
  return out;
}

}  // namespace

// --- 2. Telemetry of another time ----------------------------------------------------------------

TEST_CASE("third audit 2: telemetry outside the scene's span is refused, naming the row",
          "[reliability][third-audit][fit]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const std::string free = " --free h1.sigma,h1.phase";
  // The whole orbit fits; the same telemetry against a 10-minute scene stops at its row past 600 s
  // (line 2 is t = 0, so t = 630 is line 23).
  REQUIRE(run_fit("--telemetry " + tm.path + scene + start_heads + free).exit_status == 0);
  check_refused(run_fit("--telemetry " + tm.path + " --model scan --step-s 30 --duration-s 600" +
                        start_heads + free),
                {tm.path + ":23:3: --telemetry: t_s = 630 is outside the scene's span, t_s 0 to "
                           "600 s (--duration-s)"});
  // GPS weeks: counted on they fit; modulo 1024 (19.6 years early) they fitted "converged" to a
  // misalignment of 16.9 deg.
  const std::string epoch = " --epoch 2026-01-04T00:00:00";
  const temp_file right(with_gps_times(telemetry_csv(), 2400), ".csv");
  const temp_file wrapped(with_gps_times(telemetry_csv(), 2400 - 1024), ".csv");
  const run_result good = run_fit("--telemetry " + right.path + scene + epoch + start_heads + free);
  INFO(good.err);
  CHECK(good.exit_status == 0);
  check_refused(run_fit("--telemetry " + wrapped.path + scene + epoch + start_heads + free),
                {wrapped.path + ":2:3: --telemetry: gps_week 1376, gps_s 18", "modulo 1024",
                 "outside the scene's span"});
}

// --- 3. Attitude tables' interpolation error ---------------------------------------------------

TEST_CASE("third audit 3: an attitude table too coarse for 1e-6 deg is refused, with the escape",
          "[reliability][third-audit][sources]") {
  // The nadir attitude of the paper's eccentric orbit as a star tracker's table (inertial to body,
  // TOD), from conescan-sim's own AEM: every 60 s the geodesic between rows is 6e-4 deg off.
  const temp_file aem("", ".aem");
  REQUIRE(run_sim("--step-s 60 --orbits 1 --write-aem " + aem.path).exit_status == 0);
  std::istringstream in(read_file(aem.path));
  std::string line, table = "t_s,q_x,q_y,q_z,q_w\n";
  bool data = false;
  for (double t_s = 0; std::getline(in, line);) {
    if (line == "DATA_STOP") break;
    if (data) {
      table += std::to_string(t_s) + "," + line.substr(line.find(' ') + 1) + "\n";
      for (char& c : table)
        if (c == ' ') c = ',';
      t_s += 60;
    }
    data = data || line == "DATA_START";
  }
  const temp_file csv(table, ".csv");
  const std::string args =
      "--attitude-csv " + csv.path + " --attitude-frame TOD --step-s 60 --orbits 1";
  check_refused(run_sim(args),
                {"--attitude-csv", csv.path, "attitude interpolation error estimate",
                 "exceeds the 1e-06 deg the angles need", "--interpolation-tolerance-deg"});
  const run_result escaped = run_sim(args + " --interpolation-tolerance-deg 0.01");
  INFO(escaped.err);
  CHECK(escaped.exit_status == 0);
  // The same attitude by its elements, and an AEM (LAGRANGE 7) of it, pass.
  CHECK(run_sim("--aem " + aem.path + " --step-s 60 --orbits 1").exit_status == 0);
}

// --- 4. Every value of a scene file is checked, used or not
// ---------------------------------------

TEST_CASE("third audit 4: a scene file's overridden values are checked; head = [] is refused",
          "[reliability][third-audit][options]") {
  const temp_file nan_duration("duration-s = nan\n");
  check_refused(run_sim("--config " + nan_duration.path + " --duration-s 60"),
                {nan_duration.path + ":1", "--duration-s", "'nan' is not a finite number"});
  const temp_file fine("duration-s = 600\n");
  CHECK(run_sim("--config " + fine.path + " --duration-s 60").exit_status == 0);
  const temp_file no_heads("head = []\n");
  check_refused(run_sim("--config " + no_heads.path),
                {no_heads.path + ":1", "--head", "an empty list: give at least one head"});
}

// --- 5. Refuse what cannot be -------------------------------------------------------------------

TEST_CASE("third audit 5: a sweep that changes nothing and a fit's impossible values are refused",
          "[reliability][third-audit][options]") {
  check_refused(run_sim("--sweep radiance-season=0:0.2:0.1 --model scan --duration-s 60"),
                {"--sweep", "sweeping radiance-season changes nothing"});
  // A fit's JSON with values no fit writes: refused by --apply, naming the member.
  const temp_file tm(telemetry_csv(), ".csv");
  const run_result fit = run_fit("--telemetry " + tm.path + scene + start_heads +
                                 " --free h1.sigma,h1.phase,h2.sigma,h2.phase --json");
  REQUIRE(fit.exit_status == 0);
  const auto edited = [&](const std::string& from, const std::string& to) {
    std::string text = fit.out;
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
  };
  const std::string chi2 = fit.out.substr(fit.out.find("\"chi2_dof\": "), 40);
  const std::string chi2_value = chi2.substr(12, chi2.find(',') - 12);
  for (const auto& [from, to, said] :
       {std::tuple{"\"chi2_dof\": " + chi2_value, std::string("\"chi2_dof\": -1"),
                   std::string(".chi2_dof: -1 is outside [0, inf]")},
        std::tuple{std::string("\"correlation\": [\n    [1,"),
                   std::string("\"correlation\": [\n    [2,"),
                   std::string(".correlation[0][0]: 2")}}) {
    const temp_file bad(edited(from, to), ".json");
    check_refused(run_sim("--model scan --duration-s 60 --apply " + bad.path + truth_heads),
                  {"--apply", bad.path, said});
  }
}

// --- 6. --print-config writes what the run uses
// ---------------------------------------------------

TEST_CASE("third audit 6: --print-config --sun-sync writes the inclination the run uses",
          "[reliability][third-audit][options]") {
  const run_result printed = run_sim("--sun-sync --print-config");
  REQUIRE(printed.exit_status == 0);
  CHECK(printed.out.find("i-deg = 97.7\n") == std::string::npos);
  CHECK(printed.out.find("i-deg = 98.86") != std::string::npos);
  CHECK(printed.out.find("# the inclination --sun-sync derives") != std::string::npos);
  const temp_file written(printed.out);
  CHECK(run_sim("--config " + written.path + " --duration-s 600").out ==
        run_sim("--sun-sync --duration-s 600").out);
}

// --- 7. conescan-fit's standard output: all of it or an error
// -------------------------------------

TEST_CASE("third audit 7: conescan-fit past a file-size limit or on a full device says why, exit 1",
          "[reliability][third-audit][outputs]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const std::string args =
      "--telemetry " + tm.path + scene + start_heads + " --free h1.sigma,h1.phase --json";
  const temp_file out("before\n", ".json");
  const run_result limited = run_fit(args + " >> " + out.path, "ulimit -f 1;");
  INFO(limited.err);
  CHECK(limited.exit_status == 1);  // was 153, killed by SIGXFSZ
  CHECK(limited.err ==
        "conescan-fit: error writing the report to standard output: File too large\n");
  CHECK(read_file(out.path) == "before\n");  // nothing half-written
  const run_result full = run_fit(args + " > /dev/full");
  CHECK(full.exit_status == 1);
  CHECK(full.err ==
        "conescan-fit: error writing the report to standard output: No space left on device\n");
}

// --- 8. An output is never an input, nor standard output's file ---------------------------------

TEST_CASE("third audit 8: an output naming the scene file or standard output's file is refused",
          "[reliability][third-audit][outputs]") {
  const temp_file config("duration-s = 60\n");
  const std::string kept = read_file(config.path);
  check_refused(run_sim("--config " + config.path + " --write-oem " + config.path),
                {"--write-oem", "is the file of --config, which this run reads"});
  CHECK(read_file(config.path) == kept);
  const temp_file out("", ".csv");
  const run_result same = run_sim("--duration-s 60 --write-oem " + out.path + " > " + out.path);
  INFO(same.err);
  CHECK(same.exit_status == 1);
  CHECK(same.err.find("is the file standard output goes to") != std::string::npos);
  CHECK(read_file(out.path).empty());
  // /dev/null is a device, written as before.
  CHECK(run_sim("--duration-s 60 --write-oem /dev/null > /dev/null").exit_status == 0);
  const temp_file tm(telemetry_csv(), ".csv");
  check_refused(run_fit("--config " + config.path + " --telemetry " + tm.path + start_heads +
                        " --model scan --free h1.sigma --residuals " + config.path),
                {"--residuals", "is the file of --config"});
}

// --- 10. Messages: one line, quoted -----------------------------------------------------------

TEST_CASE("third audit 10: a scene file's and a fit's syntax errors are one printable line",
          "[reliability][third-audit][readers]") {
  const temp_file escape("e = 0.1\x1b[2J\n");
  const run_result r = run_sim("--config " + escape.path);
  INFO(r.err);
  CHECK(r.exit_status == 2);
  CHECK(r.err.find('\x1b') == std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  const temp_file digits("{\"kind\": " + std::string(1000000, '9') + "}", ".json");
  const run_result apply = run_sim("--model scan --duration-s 0 --apply " + digits.path);
  INFO(apply.err.substr(0, 300));
  CHECK(apply.exit_status == 2);
  CHECK(apply.err.size() < 300);
  CHECK(apply.err.find("--apply") != std::string::npos);
}

// --- 11. Messages: each names what it is about ------------------------------------------------

TEST_CASE("third audit 11: --apply, --config, leap seconds and counts are said as the rest",
          "[reliability][third-audit][readers]") {
  const temp_file empty_object("{}\n", ".json");
  check_refused(run_sim("--model scan --duration-s 0 --apply " + empty_object.path),
                {empty_object.path + ": --apply: "});
  check_refused(run_sim("--config /tmp"), {"--config: /tmp: cannot read: Is a directory"});
  check_refused(run_sim("--config /nonexistent/scene"),
                {"--config: /nonexistent/scene: cannot open: No such file or directory"});
  // 2016-12-31 has a leap second, at 23:59:60; 23:58:60 is no time of it.
  check_refused(run_sim("--epoch 2016-12-31T23:58:60 --duration-s 0"),
                {"second 60 outside the last minute of the day"});
  const run_result one = run_sim("--runs 2 --threads 1 --summary --head noise=0.01 --duration-s 60",
                                 conescan_test::address_space_limit(600000));
  CHECK(one.err.find("1 worker threads") == std::string::npos);
  check_refused(run_fit("--telemetry x.csv --model scan --free h1.sigma --residuals ''"),
                {"--residuals: empty value: give a file name"});
}

// --- 13. Drifting parameters' segments cover the data -------------------------------------------

TEST_CASE("third audit 13: segments cover the telemetry's span, the last one closed",
          "[reliability][third-audit][fit]") {
  // 0 ... 5400 s exactly, at 30 s: horizon-km@2700 is two segments (was three, the last of one
  // row), and the last segment ends at the last row.
  const std::string day = " --model scan --step-s 30 --duration-s 5400";
  const temp_file tm(run_sim(day + truth_heads + " --seed 5").out, ".csv");
  const run_result fit = run_fit("--telemetry " + tm.path + day + start_heads +
                                 " --free h1.sigma,h1.phase,horizon-km@2700 --json");
  INFO(fit.err);
  REQUIRE(fit.exit_status == 0);
  CHECK(fit.out.find("horizon-km[1]") != std::string::npos);
  CHECK(fit.out.find("horizon-km[2]") == std::string::npos);
  CHECK(fit.out.find("\"end_s\": 5400") != std::string::npos);
  // A length of 1e-300 s: counts a message can say.
  check_refused(
      run_fit("--telemetry " + tm.path + day + start_heads + " --free h1.sigma,horizon-km@1e-300"),
      {"over 10^15 estimated values", "(over 10^15 segments)"});
}

// --- 21. conescan-fit --threads -------------------------------------------------------------

TEST_CASE("third audit 21: conescan-fit takes --threads as conescan-sim does",
          "[reliability][third-audit][fit]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const std::string args =
      "--telemetry " + tm.path + scene + start_heads + " --free h1.sigma,h1.phase --json";
  const run_result one = run_fit(args + " --threads 1");
  const run_result three = run_fit(args + " --threads 3");
  INFO(one.err << three.err);
  REQUIRE(one.exit_status == 0);
  REQUIRE(three.exit_status == 0);
  // The same estimates to the sums' rounding (printed shortest: compare the first digits).
  const auto estimate = [](const std::string& json) {
    const std::size_t at = json.find("\"estimate\": ", json.find("\"h1.sigma\""));
    return std::stod(json.substr(at + 12, 30));
  };
  CHECK(estimate(one.out) == Approx(estimate(three.out)).epsilon(1e-9));
  check_refused(run_fit(args + " --threads 0"), {"--threads", "outside [1, 1024]"});
  CHECK(run_fit("--help").out.find("--threads") != std::string::npos);
}

// --- 14. Bounded work: refused early, in bounded memory -----------------------------------------

TEST_CASE("third audit 14: a file without line ends, and a state file that goes wrong, at once",
          "[reliability][third-audit][readers]") {
  // Every line reader said "line longer than 4096 characters" only at a line end: /dev/zero was
  // read for ever (--oem, --aem, --attitude-csv). Now at its 4097th byte.
  for (const std::string option : {"--oem", "--aem", "--attitude-csv", "--omm"}) {
    const run_result r = run_sim(option + " /dev/zero", "ulimit -t 20;");
    INFO(option << ": " << r.err);
    CHECK(r.exit_status == 2);
    CHECK(r.err.find("/dev/zero") != std::string::npos);
  }
  // A summary state's first line, then 100 MB of anything: refused at its second line within an
  // address space of 150 MB (it was read whole: 1.05 GB for 900 MB).
  const temp_file state("", ".state");
  REQUIRE(run_sim("--summary --duration-s 60 --summary-state " + state.path).exit_status == 0);
  const std::string first_line = read_file(state.path).substr(0, read_file(state.path).find('\n'));
  const temp_file big("", ".state");
  const run_result made =
      run_program("head", "-c 100000000 /dev/zero | tr '\\0' x | fold -w 100 >> " + big.path,
                  "echo '" + first_line + "' > " + big.path + ";");
  REQUIRE(made.exit_status == 0);
  const run_result merged =
      run_sim("--merge " + big.path, conescan_test::address_space_limit(150000));
  INFO(merged.err);
  CHECK(merged.exit_status == 2);
  CHECK(merged.err.find(big.path + ": corrupt summary state (line 2)") != std::string::npos);
}

// --- 15. Long runs say how long, on a terminal only ---------------------------------------------

TEST_CASE("third audit 15: a long run shows its progress on a terminal from its first second",
          "[reliability][third-audit][outputs]") {
  // The sensor physics on a circular field over a million rows: the table of the physics is
  // built before the first row (minutes, on one thread while the others wait). script(1) gives
  // the run a terminal; it is stopped after 5 s. The line is drawn by a thread of its own from
  // the first second, whatever the workers are doing (the sanitizers' build too).
  const std::string slow = std::string(CONESCAN_SIM_PATH) +
                           " --earth wgs84 --model scan --radiance-offset-km 40 "
                           "--processing-horizon-km 40 --head fov=1.5,fov-shape=circle "
                           "--step-s 1 --duration-s 999999 --max-rows 1000000";
  const run_result on_terminal =
      run_program("timeout", "5 script -qfec '" + slow + " > /dev/null' /dev/null");
  INFO(on_terminal.out);
  CHECK(on_terminal.out.find("/1000000 rows") != std::string::npos);
  // Without a terminal: nothing but the rows.
  const run_result quiet = run_program("timeout", "2 " + slow + " > /dev/null");
  CHECK(quiet.err.empty());
}

// --- 11. Memory that runs out while a file is read names it ------------------------------------

namespace {
int reads_and_runs_out(int, char**) {
  return conescan::text::naming_input("telemetry", "month.csv",
                                      []() -> int { throw std::bad_alloc(); });
}
int runs_out(int, char**) {
  throw std::bad_alloc();
}
}  // namespace

TEST_CASE("third audit 11: memory that runs out while a file is read names the option and file",
          "[reliability][third-audit][resources]") {
  // The readers' calls go through text::naming_input (--tle, --omm, --oem, --aem, --attitude-csv,
  // --telemetry, --merge, --apply); cli::guarded_main says what the exception carries, exit 1.
  try {
    (void)reads_and_runs_out(0, nullptr);
    FAIL("no exception");
  } catch (const conescan::text::out_of_memory_reading& e) {
    CHECK(std::string(e.what()) == "--telemetry: month.csv");
  }
  CHECK(conescan::cli::guarded_main("conescan-fit", reads_and_runs_out, 0, nullptr) == 1);
  CHECK(conescan::cli::guarded_main("conescan-fit", runs_out, 0, nullptr) == 1);
}
