// conescan-fit and conescan-sim --apply as a user runs them: the table and the JSON
// of a fit of conescan-sim's own CSV, --predict, the correction, and every bad input refused with
// exit 2, a message naming the file, line or option, and nothing on standard output.
#include <catch2/catch.hpp>
#include <string>

#include "calibration/fit_json.hpp"
#include "calibration/json.hpp"
#include "support/cli.hpp"
#include "support/text_file.hpp"

namespace cal = conescan::calibration;
using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::temp_file;

namespace {

conescan_test::run_result run_fit(const std::string& args) {
  return run_program(CONESCAN_FIT_PATH, args);
}

const std::string scene = " --model scan --step-s 30 --orbits 1";
const std::string truth_heads =
    " --head sigma=0.05,phase=60,noise=0.01 --head beta=-90,sigma=0.03,phase=200,noise=0.01";
const std::string start_heads = " --head sigma=0,noise=0.01 --head beta=-90,sigma=0,noise=0.01";
const std::string free_option = " --free h1.sigma,h1.phase,h2.sigma,h2.phase";

// conescan-sim's CSV of the truth, in a file.
const std::string& telemetry_csv() {
  static const std::string csv = run_sim(scene + truth_heads + " --seed 5").out;
  return csv;
}

void check_refused(const conescan_test::run_result& r, const std::string& named) {
  INFO("stderr: " << r.err);
  CHECK(r.exit_status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find(named) != std::string::npos);
}

}  // namespace

TEST_CASE("conescan-fit: a fit of conescan-sim's CSV, table and JSON", "[cli][fit]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const auto table = run_fit("--telemetry " + tm.path + scene + start_heads + free_option);
  INFO(table.err << table.out);
  REQUIRE(table.exit_status == 0);
  CHECK(table.out.find("h1.sigma") != std::string::npos);
  CHECK(table.out.find("converged: yes") != std::string::npos);
  const auto json =
      run_fit("--telemetry " + tm.path + scene + start_heads + free_option + " --json");
  REQUIRE(json.exit_status == 0);
  // The shape, read back by the strict reader.
  const auto fit = cal::read_fit_json(json.out, "stdout");
  INFO((fit.ok() ? std::string() : fit.error().text()));
  REQUIRE(fit.ok());
  for (const char* member :
       {"\"parameters\"", "\"correlation\"", "\"chi2_dof\"", "\"residual_rms_deg\"",
        "\"condition\"", "\"unobservable\"", "\"converged\": true", "\"unit\": \"deg\""})
    CHECK(json.out.find(member) != std::string::npos);
  const auto& p = fit.value().uncertainty.parameters;
  CHECK(p[0].name == "h1.sigma");
  CHECK(std::abs(p[0].estimate - 0.05) < 3 * p[0].sigma);
  // The loss switched off: still a fit, the report says so.
  const auto plain =
      run_fit("--telemetry " + tm.path + scene + start_heads + free_option + " --loss none --json");
  REQUIRE(plain.exit_status == 0);
  CHECK(plain.out.find("\"kind\": \"none\"") != std::string::npos);
}

TEST_CASE("conescan-fit: a fit that does not converge says so and exits 1", "[cli][fit]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const std::string args =
      "--telemetry " + tm.path + scene + start_heads + free_option + " --max-iterations 1";
  const auto table = run_fit(args);
  INFO(table.err << table.out);
  CHECK(table.exit_status == 1);
  CHECK(table.out.find("NOT CONVERGED") != std::string::npos);
  CHECK(table.out.find("1 sigma") == std::string::npos);  // no estimate presented as one
  const auto json = run_fit(args + " --json");
  CHECK(json.exit_status == 1);
  CHECK(json.out.find("\"converged\": false") != std::string::npos);
  CHECK(json.out.find("\"last_state\"") != std::string::npos);
  CHECK(json.out.find("\"parameters\"") == std::string::npos);
  for (const char* bad : {"0", "-1", "10001", "1.5", "x"})
    check_refused(run_fit("--telemetry " + tm.path + scene + start_heads + free_option +
                          " --max-iterations " + bad),
                  "--max-iterations");
}

TEST_CASE("conescan-fit --predict: the design without data", "[cli][fit]") {
  const auto r = run_fit("--predict" + scene + truth_heads + free_option);
  INFO(r.err);
  REQUIRE(r.exit_status == 0);
  CHECK(r.out.find("h2.phase") != std::string::npos);
  const auto json = run_fit("--predict --json" + scene + truth_heads + free_option);
  REQUIRE(json.exit_status == 0);
  CHECK(json.out.find("\"kind\": \"design\"") != std::string::npos);
  // No stated noise: nothing to predict from.
  check_refused(run_fit("--predict" + scene + " --head sigma=0.05 --free h1.sigma"), "noise");
}

TEST_CASE("conescan-sim --apply: the corrected errors fall far below the uncorrected",
          "[cli][fit][apply]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const auto json =
      run_fit("--telemetry " + tm.path + scene + start_heads + free_option + " --json");
  REQUIRE(json.exit_status == 0);
  const temp_file fit(json.out, ".json");
  const std::string clean =
      scene + " --head sigma=0.05,phase=60 --head beta=-90,sigma=0.03,phase=200 --summary";
  const auto before = run_sim(clean);
  const auto after = run_sim(clean + " --apply " + fit.path);
  INFO(after.err);
  REQUIRE(after.exit_status == 0);
  const auto rms = [](const std::string& csv, const std::string& column) {
    const conescan_test::csv_table t = conescan_test::parse_csv(csv);
    return std::stod(t.rows.back()[t.column(column)]);
  };
  CHECK(rms(after.out, "pitch_rms_deg") < rms(before.out, "pitch_rms_deg") / 20);
  CHECK(rms(after.out, "roll_rms_deg") < rms(before.out, "roll_rms_deg") / 20);
  // Refused: a fit of other heads, a file that is no fit, --apply with a sweep.
  check_refused(run_sim(scene + " --apply " + fit.path), "heads");
  const temp_file not_json("{\"kind\": \"fit\"", ".json");
  check_refused(run_sim(clean + " --apply " + not_json.path), not_json.path);
  check_refused(run_sim(clean + " --apply " + fit.path + " --sweep e=0:0.1:0.05"), "--apply");
  check_refused(run_sim(clean + " --apply no-such-file.json"), "--apply");
}

TEST_CASE("conescan-fit: bad input is refused naming the file, line or option",
          "[cli][fit][hostile]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const std::string good = scene + start_heads;
  // The command line.
  check_refused(run_fit("--telemetry " + tm.path + good), "--free");
  check_refused(run_fit("--telemetry " + tm.path + good + " --free ''"), "--free");
  check_refused(run_fit("--telemetry " + tm.path + good + " --free h1.sigma,h1.sigma"), "twice");
  check_refused(run_fit("--telemetry " + tm.path + good + " --free h1.tilt"), "h1.tilt");
  check_refused(run_fit("--telemetry " + tm.path + good + " --free h3.sigma"), "h3.sigma");
  check_refused(run_fit(good + free_option), "--telemetry");
  check_refused(run_fit("--telemetry " + tm.path + " --predict" + good + free_option),
                "--telemetry");
  check_refused(run_fit("--telemetry " + tm.path + good + free_option + " --loss cauchy"),
                "--loss");
  check_refused(run_fit("--telemetry " + tm.path + " --step-s 30" + start_heads + free_option),
                "--model scan");
  check_refused(run_fit("--telemetry " + tm.path + good + free_option + " --sweep e=0:0.1:0.05"),
                "--sweep");
  check_refused(run_fit("--telemetry no-such.csv" + good + free_option), "no-such.csv");
  check_refused(run_fit("--telemetry " + tm.path + good + free_option + " --e 2"), "--e");
  // The head count disagrees with the scene's (one head in the scene, two in the telemetry).
  check_refused(
      run_fit("--telemetry " + tm.path + scene + " --head sigma=0,noise=0.01" + " --free h1.sigma"),
      tm.path);
  // The telemetry's content: each error names the file and line.
  const std::string header = "t_s,h1_chord_deg,h1_phase_deg,h2_chord_deg,h2_phase_deg\n";
  const struct {
    std::string body;
    std::string named;
  } files[] = {
      {"t_s,h1_chord_deg,h1_phase_deg\n0,140,0\n", ":1:"},                 // h2's columns missing
      {header + "0,140,0,140,0\n10,abc,0,140,0\n", ":3:"},                 // not a number
      {header + "0,140,0,140,0\n10,inf,0,140,0\n", ":3:"},                 // not finite
      {header + "0,140,0,140,0\n10,140,0,140,0\n5,140,0,140,0\n", ":4:"},  // out of order
      {header + "0,140,0,140,0\n10,140,0\n", ":3:"},                       // a field missing
      {header, ":1"},                                                      // no rows
  };
  for (const auto& f : files) {
    const temp_file bad(f.body, ".csv");
    check_refused(run_fit("--telemetry " + bad.path + good + free_option), bad.path + f.named);
  }
}

TEST_CASE("conescan-sim: the head keys dgamma, bias-in, bias-out simulate a biased sensor",
          "[cli][fit]") {
  // A crossing bias moves the chord by bias-out - bias-in and the phase by their mean.
  const auto plain = run_sim("--duration-s 0 --model scan");
  const auto biased = run_sim("--duration-s 0 --model scan --head bias-in=0.01,bias-out=0.03");
  REQUIRE(biased.exit_status == 0);
  const auto p = conescan_test::parse_csv(plain.out), b = conescan_test::parse_csv(biased.out);
  CHECK(b.number(0, "h1_chord_deg") - p.number(0, "h1_chord_deg") == Approx(0.02).margin(1e-12));
  CHECK(b.number(0, "h1_phase_deg") - p.number(0, "h1_phase_deg") == Approx(0.02).margin(1e-12));
  // The budget lists them as one source, and the single sources add up to all.
  const auto budget =
      run_sim("--duration-s 0 --budget --head sigma=0.02,dgamma=0.01,bias-in=0.005");
  REQUIRE(budget.exit_status == 0);
  const auto t = conescan_test::parse_csv(budget.out);
  CHECK(t.number(0, "head-biases_pitch_err_deg") != 0);
  CHECK(t.number(0, "misalignment_pitch_err_deg") == Approx(0).margin(1e-15));
  CHECK(t.number(0, "sum_roll_err_deg") == Approx(t.number(0, "all_roll_err_deg")).epsilon(1e-3));
  // Domain: gamma + dgamma in (sigma, 90) deg, biases in [-10, 10] deg; each refusal names the key.
  for (const char* bad : {"dgamma=45", "dgamma=-44.99", "bias-in=10.5", "bias-out=-11"}) {
    const auto r = run_sim(std::string("--duration-s 0 --head ") + bad);
    INFO(bad << ": " << r.err);
    CHECK(r.exit_status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(std::string(bad).substr(0, std::string(bad).find('='))) != std::string::npos);
  }
  for (const char* good : {"dgamma=44.9", "dgamma=-44.9", "bias-in=10", "bias-out=-10"})
    CHECK(run_sim(std::string("--duration-s 0 --head ") + good).exit_status == 0);
}

TEST_CASE("conescan-fit --residuals: every measurement's residuals at the solution",
          "[cli][fit][residuals]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const temp_file out("", ".csv");
  const auto r = run_fit("--telemetry " + tm.path + scene + start_heads + free_option +
                         " --json --residuals " + out.path);
  INFO(r.err);
  REQUIRE(r.exit_status == 0);
  const std::string text = conescan_test::read_text(out.path);
  const std::string header =
      "t_s,row,head,lat_deg,chord_residual_deg,phase_residual_deg,normalised,fitted\n";
  REQUIRE(text.substr(0, header.size()) == header);
  const auto fit = cal::read_fit_json(r.out, "stdout");
  REQUIRE(fit.ok());
  // One line per measurement: the heads' measurements of every row (none dropped here).
  std::size_t lines = 0, first_row_lines = 0;
  for (std::size_t at = header.size(); at < text.size(); at = text.find('\n', at) + 1) {
    ++lines;
    if (text.compare(at, 4, "0,0,") == 0) ++first_row_lines;
  }
  CHECK(lines == fit.value().residual_count / 2);
  CHECK(first_row_lines == 2);
  // The first measurement: row 0, head 1, at the orbit's start (latitude 0), fitted.
  const std::string first =
      text.substr(header.size(), text.find('\n', header.size()) - header.size());
  CHECK(first.substr(0, 8) == "0,0,1,0,");
  CHECK(first.substr(first.size() - 2) == ",1");
  // Refused before any fit: with --predict, and a file that cannot be written.
  check_refused(run_fit("--predict" + scene + start_heads + free_option + " --residuals x.csv"),
                "--residuals: --predict plans a scene without data");
  // An output that cannot be written: exit 1 (a write error), before the fit, nothing written.
  const auto unwritable = run_fit("--telemetry " + tm.path + scene + start_heads + free_option +
                                  " --residuals /nonexistent/r.csv");
  CHECK(unwritable.exit_status == 1);
  CHECK(unwritable.out.empty());
  CHECK(
      unwritable.err ==
      "conescan-fit: --residuals: cannot write '/nonexistent/r.csv': No such file or directory\n");
}
