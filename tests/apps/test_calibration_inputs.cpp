// What the calibration reads from users: --free lists, telemetry CSV and a fit's JSON, with every
// bad input refused by a message naming the option or file and position (src/calibration/).
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "calibration/estimator.hpp"
#include "calibration/fit_json.hpp"
#include "calibration/json.hpp"
#include "calibration/parameters.hpp"
#include "calibration/report.hpp"
#include "calibration/telemetry.hpp"
#include "support/cli.hpp"
#include "support/synthetic_model.hpp"
#include "text/json_document.hpp"

namespace cal = conescan::calibration;
using cal::earth_parameter;
using cal::head_parameter;
using cal::parameter_index;

// ---- names and --free ---------------------------------------------------------------------

TEST_CASE("calibration: parameter names and units come from one table", "[calibration]") {
  // 7 per head (5 of the geometry and biases, 2 of the sensor physics), 5 of the Earth.
  CHECK(cal::parameter_count(2) == 19);
  CHECK(cal::parameter_name(0, 2) == "h1.sigma");
  CHECK(cal::parameter_name(parameter_index(1, head_parameter::tau_ms), 2) == "h2.tau-ms");
  CHECK(cal::parameter_unit(parameter_index(0, head_parameter::tau_ms), 2) == "ms");
  CHECK(cal::parameter_name(parameter_index(2, earth_parameter::radiance_offset), 2) ==
        "radiance-offset-km");
  // The physics' parameters, and only they, may be absent (NaN where the scene has no chain).
  for (std::size_t i = 0; i < cal::parameter_count(2); ++i) {
    const std::string name = cal::parameter_name(i, 2);
    const bool physics = name.find("tau-ms") != std::string::npos ||
                         name.find("threshold") != std::string::npos ||
                         name.rfind("radiance-", 0) == 0;
    CHECK(cal::is_physics_parameter(i, 2) == physics);
    CHECK(cal::physics_absent(i, 2, std::nan("")) == physics);
    CHECK_FALSE(cal::physics_absent(i, 2, 1.0));
  }
  CHECK(cal::parameter_name(parameter_index(1, head_parameter::bias_out), 2) == "h2.bias-out");
  CHECK(cal::parameter_name(parameter_index(2, earth_parameter::horizon_shift), 2) ==
        "horizon-shift-km");
  CHECK(cal::parameter_unit(parameter_index(1, head_parameter::dgamma), 2) == "deg");
  CHECK(cal::parameter_unit(parameter_index(2, earth_parameter::horizon_pole), 2) == "km");
  // Every name reads back to its index.
  for (std::size_t heads : {1, 3, 16})
    for (std::size_t i = 0; i < cal::parameter_count(heads); ++i) {
      const conescan::checked<std::vector<std::size_t>> parsed =
          cal::parse_free_list(cal::parameter_name(i, heads), heads);
      REQUIRE(parsed.ok());
      CHECK(parsed.value() == std::vector<std::size_t>{i});
    }
}

TEST_CASE("calibration: --free reads the issue's list in its order", "[calibration]") {
  const auto parsed = cal::parse_free_list(
      "h1.sigma,h1.phase,h1.dgamma,h1.bias-in,h1.bias-out,horizon-km,horizon-pole-km,"
      "horizon-shift-km,h2.phase",
      2);
  REQUIRE(parsed.ok());
  CHECK(parsed.value() == std::vector<std::size_t>{0, 1, 2, 3, 4, 14, 15, 16, 8});
}

TEST_CASE("calibration: every bad --free list is refused naming the option and the token",
          "[calibration]") {
  auto message = [](std::string_view list, std::size_t heads) {
    const auto parsed = cal::parse_free_list(list, heads);
    REQUIRE_FALSE(parsed.ok());
    CHECK(parsed.error().option == "free");
    return parsed.error().text();
  };
  CHECK_THAT(message("", 2), Catch::Matchers::StartsWith("--free: no free parameter: give a "
                                                         "comma-separated list of hK.sigma"));
  CHECK(message("h1.sigma,,h1.phase", 2) == "--free: item 2 of 'h1.sigma,,h1.phase' is empty");
  CHECK(message("h1.sigma,", 2) == "--free: item 2 of 'h1.sigma,' is empty");
  CHECK(message(",h1.sigma", 2) == "--free: item 1 of ',h1.sigma' is empty");
  CHECK_THAT(message("h1.gamma", 2), Catch::Matchers::StartsWith("--free: unknown parameter "
                                                                 "'h1.gamma'; allowed: hK.sigma"));
  CHECK_THAT(message("horizon", 2),
             Catch::Matchers::StartsWith("--free: unknown parameter 'horizon'"));
  CHECK_THAT(message("h1.sigma, h1.phase", 2),
             Catch::Matchers::StartsWith("--free: unknown parameter ' h1.phase'"));
  CHECK_THAT(message("H1.sigma", 2),
             Catch::Matchers::StartsWith("--free: unknown parameter 'H1.sigma'"));
  CHECK_THAT(message("h01.sigma", 2),
             Catch::Matchers::StartsWith("--free: unknown parameter 'h01.sigma'"));
  CHECK_THAT(message("h.sigma", 2),
             Catch::Matchers::StartsWith("--free: unknown parameter 'h.sigma'"));
  CHECK_THAT(message("h1x.sigma", 2),
             Catch::Matchers::StartsWith("--free: unknown parameter 'h1x.sigma'"));
  CHECK_THAT(
      message("h99999999999999999999999.sigma", 2),
      Catch::Matchers::StartsWith("--free: unknown parameter 'h99999999999999999999999.sigma'"));
  CHECK(message("h0.sigma", 2) == "--free: heads are numbered from 1: 'h0.sigma' names head 0");
  CHECK(message("h3.sigma", 2) == "--free: 'h3.sigma' names head 3 but the scene has 2 heads");
  CHECK(message("h2.dgamma", 1) == "--free: 'h2.dgamma' names head 2 but the scene has 1 head");
  CHECK(message("h1.sigma,horizon-km,h1.sigma", 2) == "--free: 'h1.sigma' is named twice");
  CHECK_THAT(message("h1.sigma\x01", 2), Catch::Matchers::Contains("'h1.sigma\\x01'"));
}

// ---- telemetry ------------------------------------------------------------------------------

namespace {

conescan::checked<cal::telemetry> read_text(const std::string& text, std::size_t heads) {
  std::istringstream in(text);
  return cal::read_telemetry(in, "tm.csv", heads);
}

std::string telemetry_error(const std::string& text, std::size_t heads) {
  const auto t = read_text(text, heads);
  REQUIRE_FALSE(t.ok());
  CHECK(t.error().option == "telemetry");
  return t.error().text();
}

}  // namespace

TEST_CASE("calibration: telemetry with the columns in any order, others ignored", "[calibration]") {
  const auto t = read_text(
      "\xEF\xBB\xBFh2_phase_deg,x,t_s,h1_chord_deg,h2_chord_deg,h1_phase_deg,h1_status\r\n"
      "1.5,whatever,0,100,120,-2,ok\r\n"
      "-179.5,,10.5,100.25,nan,1e-3,fold\n"
      "3,z,20,nan,130,nan,miss",
      2);
  REQUIRE(t.ok());
  const cal::telemetry& m = t.value();
  CHECK(m.row_count == 3);
  CHECK(m.skipped_per_head == std::vector<std::size_t>{1, 1});
  REQUIRE(m.observations.size() == 4);
  CHECK(m.observations[0].sample.t_s == 0);
  CHECK(m.observations[0].sample.head == 0);
  CHECK(m.observations[0].chord_deg == 100);
  CHECK(m.observations[0].phase_deg == -2);
  CHECK(m.observations[1].sample.head == 1);
  CHECK(m.observations[1].phase_deg == 1.5);
  CHECK(m.observations[2].sample.row == 1);
  CHECK(m.observations[2].sample.t_s == 10.5);
  CHECK(m.observations[2].phase_deg == 1e-3);
  CHECK(m.observations[3].sample.row == 2);
  CHECK(m.observations[3].sample.head == 1);
}

TEST_CASE("calibration: conescan-sim's own CSV is telemetry, nan heads skipped and counted",
          "[calibration]") {
  // Head 2 at alpha = 70 deg sees the whole Earth near perigee (engulfed, nan) and measures
  // elsewhere.
  const auto run = conescan_test::run_sim(
      "--step-s 60 --head alpha=0,beta=90 --head alpha=70,beta=-90,gamma=45");
  REQUIRE(run.exit_status == 0);
  const conescan_test::csv_table csv = conescan_test::parse_csv(run.out);
  std::size_t head2_nan = 0;
  for (std::size_t r = 0; r < csv.rows.size(); ++r)
    head2_nan += csv.text(r, "h2_chord_deg") == "nan";
  REQUIRE(head2_nan > 0);
  REQUIRE(head2_nan < csv.rows.size());
  const auto t = read_text(run.out, 2);
  REQUIRE(t.ok());
  CHECK(t.value().row_count == csv.rows.size());
  CHECK(t.value().skipped_per_head == std::vector<std::size_t>{0, head2_nan});
  CHECK(t.value().observations.size() == 2 * csv.rows.size() - head2_nan);
  // Numbers read back exactly (conescan-sim writes the shortest round-trip text).
  const cal::observation& last = t.value().observations.back();
  CHECK(last.sample.t_s == csv.number(csv.rows.size() - 1, "t_s"));
  // The same CSV for a one-head scene has a head too many.
  CHECK(telemetry_error(run.out, 1) ==
        "tm.csv:1:124: --telemetry: the telemetry has columns of head 2 but the scene has 1 head");
}

TEST_CASE("calibration: every bad telemetry is refused with the file, line and column",
          "[calibration]") {
  const std::string header = "t_s,h1_chord_deg,h1_phase_deg\n";
  CHECK(telemetry_error("", 1) == "tm.csv: --telemetry: the file is empty: expected a header line");
  CHECK(telemetry_error(header, 1) == "tm.csv:1: --telemetry: no telemetry row after the header");
  CHECK(telemetry_error("h1_chord_deg,h1_phase_deg\n1,2\n", 1) ==
        "tm.csv:1: --telemetry: missing column 't_s' in the header (or a time as utc, or "
        "gps_week and gps_s)");
  CHECK(telemetry_error("t_s,h1_chord_deg\n0,1\n", 1) ==
        "tm.csv:1: --telemetry: missing column 'h1_phase_deg' (the scene has 1 heads)");
  CHECK(telemetry_error(header + "0,100,0\n", 2) ==
        "tm.csv:1: --telemetry: missing column 'h2_chord_deg' (the scene has 2 heads)");
  CHECK(telemetry_error("t_s,h1_chord_deg,h1_phase_deg,t_s\n", 1) ==
        "tm.csv:1:31: --telemetry: column 't_s' appears twice");
  CHECK(telemetry_error("t_s,h1_chord_deg,h1_phase_deg,h1_chord_deg\n", 1) ==
        "tm.csv:1:31: --telemetry: column 'h1_chord_deg' appears twice");
  CHECK(telemetry_error(header + "0,100,0\n10,100\n", 1) ==
        "tm.csv:3: --telemetry: 2 fields, the header has 3");
  CHECK(telemetry_error(header + "0,100,0\n\n20,100,0\n", 1) ==
        "tm.csv:3:1: --telemetry: an empty line");
  CHECK(telemetry_error(header + "0,abc,0\n", 1) ==
        "tm.csv:2:3: --telemetry: column h1_chord_deg: 'abc' is not a finite number (nan marks a "
        "head that did not measure)");
  CHECK(telemetry_error(header + "nan,100,0\n", 1) ==
        "tm.csv:2:1: --telemetry: column t_s: 'nan' is not a finite number");
  CHECK(telemetry_error(header + "0,100,inf\n", 1) ==
        "tm.csv:2:7: --telemetry: column h1_phase_deg: 'inf' is not a finite number (nan marks a "
        "head that did not measure)");
  CHECK(telemetry_error(header + "0,NaN,0\n", 1) ==
        "tm.csv:2:3: --telemetry: column h1_chord_deg: 'NaN' is not a finite number (nan marks a "
        "head that did not measure)");
  CHECK(telemetry_error(header + "0,1e999,0\n", 1) ==
        "tm.csv:2:3: --telemetry: column h1_chord_deg: '1e999' is beyond the range of a double");
  CHECK(telemetry_error(header + "0, 100,0\n", 1) ==
        "tm.csv:2:3: --telemetry: column h1_chord_deg: ' 100' is not a finite number (nan marks a "
        "head that did not measure)");
  CHECK(telemetry_error(header + "+1,100,0\n", 1) ==
        "tm.csv:2:1: --telemetry: column t_s: '+1' is not a finite number");
  CHECK(telemetry_error(header + "0x10,100,0\n", 1) ==
        "tm.csv:2:1: --telemetry: column t_s: '0x10' is not a finite number");
  CHECK(telemetry_error(header + "0,,0\n", 1) ==
        "tm.csv:2:3: --telemetry: column h1_chord_deg is empty");
  CHECK(telemetry_error(header + "0,360,0\n", 1) ==
        "tm.csv:2:3: --telemetry: column h1_chord_deg: '360' is outside (0, 360) deg");
  CHECK(telemetry_error(header + "0,-0,0\n", 1) ==
        "tm.csv:2:3: --telemetry: column h1_chord_deg: '-0' is outside (0, 360) deg");
  CHECK(telemetry_error(header + "10,100,0\n10,100,0\n", 1) ==
        "tm.csv:3:1: --telemetry: t_s = 10 does not follow the previous row's 10: rows must "
        "be in increasing time");
  CHECK(telemetry_error(header + "10,100,0\n5,100,0\n", 1) ==
        "tm.csv:3:1: --telemetry: t_s = 5 does not follow the previous row's 10: rows must "
        "be in increasing time");
  CHECK(telemetry_error(header + std::string(cal::max_telemetry_line_bytes + 1, '1'), 1) ==
        "tm.csv:2: --telemetry: a line longer than 1 MiB: not telemetry");
  CHECK(telemetry_error(std::string(cal::max_telemetry_line_bytes + 1, 'x'), 1) ==
        "tm.csv:1: --telemetry: a line longer than 1 MiB: not telemetry");
  CHECK(cal::read_telemetry_file("/nonexistent/tm.csv", 1).error().text() ==
        "/nonexistent/tm.csv: --telemetry: cannot open: No such file or directory");
}

TEST_CASE("calibration: telemetry beyond the measurement limit is refused at its line",
          "[calibration]") {
  // 16 heads: the limit is reached at row max / 16 + 1.
  std::string text = "t_s";
  for (int k = 1; k <= 16; ++k)
    text += ",h" + std::to_string(k) + "_chord_deg,h" + std::to_string(k) + "_phase_deg";
  text += "\n";
  std::string tail;
  for (int k = 1; k <= 16; ++k) tail += ",100,0";
  tail += "\n";
  const std::size_t rows = cal::max_telemetry_measurements / 16;
  text.reserve(text.size() + (rows + 1) * (tail.size() + 8));
  for (std::size_t r = 0; r <= rows; ++r) text += std::to_string(r) + tail;
  CHECK(telemetry_error(text, 16) == "tm.csv:" + std::to_string(rows + 2) +
                                         ": --telemetry: more than 6000000 measurements (rows "
                                         "times heads): the limit of a fit");
}

// ---- JSON -----------------------------------------------------------------------------------

TEST_CASE("calibration: JSON is read by nlohmann-json, strictly, with positions and paths",
          "[calibration][json]") {
  const auto v = conescan::text::parse_json_document(
      " {\"a\": [1, -0.5e-3, 1E2, true, false, null], \"b\": {\"c\": "
      "\"x\\u00e9\\ud83d\\ude00\\n\"}} ",
      "f.json");
  REQUIRE(v.ok());
  const nlohmann::ordered_json& a = v.value()["a"];
  REQUIRE(a.size() == 6);
  CHECK(a[1].get<double>() == -0.5e-3);
  CHECK(a[2].get<double>() == 100);
  CHECK(a[3].get<bool>());
  CHECK(a[5].is_null());
  CHECK(v.value()["b"]["c"].get<std::string>() == "x\xC3\xA9\xF0\x9F\x98\x80\n");
  auto error = [](std::string_view text) {
    const auto r = conescan::text::parse_json_document(text, "f.json");
    REQUIRE_FALSE(r.ok());
    return r.error().text();
  };
  // Syntax: nlohmann's message at its line and column.
  CHECK(error("") ==
        "f.json:1:1: syntax error while parsing value - unexpected end of input; expected '[', "
        "'{', or a literal");
  CHECK(error("[1, 2,]") ==
        "f.json:1:7: syntax error while parsing value - unexpected ']'; expected '[', '{', or a "
        "literal");
  CHECK(error("[01]") ==
        "f.json:1:3: syntax error while parsing array - unexpected number literal; expected ']'");
  CHECK(error("[1.]").rfind("f.json:1:4: syntax error while parsing value - invalid number", 0) ==
        0);
  CHECK(error("[+1]").rfind("f.json:1:2: ", 0) == 0);
  CHECK(error("[NaN]").rfind("f.json:1:2: ", 0) == 0);
  CHECK(error("{} x").rfind("f.json:1:4: ", 0) == 0);
  CHECK(error("{\"a\" 1}").rfind("f.json:1:6: ", 0) == 0);
  CHECK(error("{\"a\": 1 \"b\": 2}").rfind("f.json:1:11: ", 0) == 0);
  CHECK(error("[\"a\nb\"]").rfind("f.json:1:4: ", 0) == 0);
  CHECK(error("[\"\\x\"]").rfind("f.json:1:4: ", 0) == 0);
  CHECK(error("[\"\\ud83d\"]").rfind("f.json:1:9: ", 0) == 0);
  CHECK(error("[\"abc").rfind("f.json:1:6: ", 0) == 0);
  CHECK(error("{1: 2}").rfind("f.json:1:2: ", 0) == 0);
  CHECK(error("\n\n  [1,,]").rfind("f.json:3:6: ", 0) == 0);
  // Bytes that are not UTF-8 are refused and not echoed raw.
  CHECK(error("[\"\xff\"]") ==
        "f.json:1:3: syntax error while parsing value - invalid string: ill-formed UTF-8 byte; "
        "last read: '\"\\xff'");
  // What nlohmann would keep silently or without bound: refused by path.
  CHECK(error("{\"a\": 1,\n \"a\": 2}") == "f.json: .a: member given twice in one object");
  CHECK(error("{\"b\": [1, {\"c\": 1, \"c\": 2}]}") ==
        "f.json: .b[1].c: member given twice in one object");
  CHECK(error("[1e400]") == "f.json: number overflow parsing '1e400'");
  CHECK(error(std::string(65, '[') + std::string(65, ']'))
            .ends_with(": nesting deeper than 64 levels"));
  CHECK(conescan::text::parse_json_document(std::string(64, '[') + std::string(64, ']'), "f.json")
            .ok());
}

namespace {

/// A fit of the synthetic model with a degenerate pair and an outlier: every member of the JSON
/// in use (withheld values, an unobservable combination, an outlier, held parameters).
cal::fit_result sample_fit() {
  static const cal::forward_model_of<cal::synthetic_model> model{cal::synthetic_model({})};
  cal::parameter_set truth = cal::parameter_set::nominal(2);
  truth.value(0, head_parameter::sigma) = 0.05;
  truth.value(0, head_parameter::phase) = 60;
  truth.value(earth_parameter::horizon) = 40;
  cal::parameter_set start = truth;
  start.value(0, head_parameter::sigma) = 0;
  // h2.phase at h2.sigma = 0 held: unobservable.
  for (std::size_t index : {std::size_t{0}, std::size_t{1}, std::size_t{6}, std::size_t{11}})
    start.free[index] = true;
  std::vector<cal::observation> data =
      cal::simulate_observations(model.model(), truth, 0, 10, 300, 0.01, 9, 0);
  data[17].chord_deg += 0.5;
  const auto outcome =
      cal::fit({&model, start, data, std::vector<cal::head_noise>(2, {0.01, 0.0})}, {});
  return std::get<cal::fit_result>(outcome.value());
}

}  // namespace

TEST_CASE("calibration: a fit's JSON reads back exactly", "[calibration]") {
  const cal::fit_result written = sample_fit();
  const std::string text = cal::fit_json(written);
  INFO(text);
  // The members, with the values the fit holds.
  for (const char* member : {"\"parameters\": {", "\"correlation\": [",
                             "\"chi2_dof\": ", "\"residual_rms_deg\": {\"h1\": ", "\"condition\": ",
                             "\"unobservable\": [", "\"converged\": true"})
    CHECK(text.find(member) != std::string::npos);
  CHECK(text.find("\"h1.sigma\": {\"estimate\": " +
                  cal::json_number(written.uncertainty.parameters[0].estimate) +
                  ", \"sigma\": " + cal::json_number(written.uncertainty.parameters[0].sigma) +
                  ", \"unit\": \"deg\", \"free\": true}") != std::string::npos);
  const auto read = cal::read_fit_json(text, "fit.json");
  REQUIRE(read.ok());
  const cal::fit_result& r = read.value();
  CHECK(cal::fit_json(r) == text);
  // Field by field, bit for bit (NaN where withheld).
  auto same = [](double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; };
  REQUIRE(r.uncertainty.parameters.size() == written.uncertainty.parameters.size());
  for (std::size_t i = 0; i < r.uncertainty.parameters.size(); ++i) {
    const auto& a = r.uncertainty.parameters[i];
    const auto& b = written.uncertainty.parameters[i];
    CHECK(a.name == b.name);
    CHECK(same(a.estimate, b.estimate));
    CHECK(same(a.sigma, b.sigma));
    CHECK(a.free == b.free);
    CHECK(a.determined == b.determined);
    CHECK(a.withheld == b.withheld);
  }
  for (std::size_t i = 0; i < r.uncertainty.coordinate_covariance.size(); ++i)
    for (std::size_t j = 0; j < r.uncertainty.coordinate_covariance.size(); ++j)
      CHECK(same(r.uncertainty.coordinate_covariance[i][j],
                 written.uncertainty.coordinate_covariance[i][j]));
  for (std::size_t i = 0; i < r.uncertainty.correlation.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      CHECK(same(r.uncertainty.correlation[i][j], r.uncertainty.correlation[j][i]));
  CHECK(r.chi2_dof == written.chi2_dof);
  CHECK(r.outlier_count == written.outlier_count);
  CHECK(r.worst_outliers.size() == written.worst_outliers.size());
  CHECK(written.outlier_count == 1);
  REQUIRE(written.uncertainty.unobservable.size() == 1);
  CHECK(r.uncertainty.unobservable[0].components == written.uncertainty.unobservable[0].components);
}

TEST_CASE("calibration: bad fit JSON is refused with the file, position and member",
          "[calibration]") {
  const std::string good = cal::fit_json(sample_fit());
  auto error = [](const std::string& text) {
    const auto r = cal::read_fit_json(text, "fit.json");
    REQUIRE_FALSE(r.ok());
    return r.error().text();
  };
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    const std::size_t at = t.find(from);
    REQUIRE(at != std::string::npos);
    return t.replace(at, from.size(), to);
  };
  CHECK(error("[]") == "fit.json: the top level: expected a JSON object, found an array");
  CHECK(error(replaced("\"kind\": \"fit\"", "\"kind\": \"design\"")) ==
        "fit.json: .kind: expected \"fit\": this is not a fit's result");
  CHECK(error(replaced("\"converged\": true", "\"converged\": false")) ==
        "fit.json: .converged: the fit did not converge: it holds no estimate");
  CHECK(error(replaced("\"chi2_dof\"", "\"chi2\"")) ==
        "fit.json: the top level: missing member \"chi2_dof\"");
  CHECK(error(replaced("\"kind\": \"fit\"", "\"kind\": 3")) ==
        "fit.json: .kind: expected a string, found a number");
  CHECK(error(replaced("\"converged\": true,", "\"converged\": true, \"converged\": true,")) ==
        "fit.json: .converged: member given twice in one object");
  CHECK(error(replaced("\"converged\": true", "\"converged\": tru")).rfind("fit.json:3:", 0) == 0);
  CHECK_THAT(error(replaced("\"h1.sigma\": {\"estimate\": ",
                            "\"h1.sigma\": {\"estimate\": \"x\", \"was\": ")),
             Catch::Matchers::EndsWith(".parameters.h1.sigma.estimate: expected a number"));
  CHECK_THAT(error(replaced("\"h1.sigma\"", "\"h1.sigmas\"")),
             Catch::Matchers::Contains(".parameters: unknown parameter 'h1.sigmas'"));
  CHECK_THAT(error(replaced("\"unit\": \"km\"", "\"unit\": \"m\"")),
             Catch::Matchers::EndsWith(".parameters.horizon-km.unit: expected \"km\""));
  CHECK_THAT(error(replaced("\"parameter_order\": [\"h1.sigma\", ", "\"parameter_order\": [")),
             Catch::Matchers::EndsWith(
                 ".parameter_order: expected the 4 free parameters in parameter order"));
  CHECK_THAT(error(replaced("\"correlation\": [\n", "\"correlation\": [\n    [1],\n")),
             Catch::Matchers::EndsWith(".correlation: expected 4 rows (one per free parameter)"));
  CHECK_THAT(error(replaced("\"names\": [\"h1.misalign-x\"", "\"names\": [\"h1.sigma\"")),
             Catch::Matchers::EndsWith(".coordinates.names[0]: expected \"h1.misalign-x\""));
  CHECK_THAT(error(replaced("\"dof\": ", "\"dof\": -")),
             Catch::Matchers::EndsWith(".dof: expected a whole number >= 0"));
  CHECK_THAT(error(replaced("\"kind\": \"huber\"", "\"kind\": \"cauchy\"")),
             Catch::Matchers::EndsWith(".robust_loss.kind: expected \"huber\" or \"none\""));
  CHECK(cal::read_fit_json_file("/nonexistent/fit.json").error().text() ==
        "/nonexistent/fit.json: --apply: cannot open: No such file or directory");
}

TEST_CASE("calibration: a fit that did not converge and a design have their own JSON",
          "[calibration]") {
  cal::parameter_set last = cal::parameter_set::nominal(1);
  last.free[0] = true;
  last.values[0] = 0.125;
  const std::string text = cal::fit_json(cal::unconverged_fit{last, 3, 12.5, "stopped", {}});
  CHECK(text.find("\"converged\": false") != std::string::npos);
  CHECK(text.find("\"h1.sigma\": {\"value\": 0.125, \"unit\": \"deg\", \"free\": true}") !=
        std::string::npos);
  CHECK(text.find("\"parameters\"") == std::string::npos);
  CHECK(conescan::text::parse_json_document(text, "u.json").ok());
  CHECK_THAT(cal::read_fit_json(text, "u.json").error().text(),
             Catch::Matchers::Contains("the fit did not converge"));
}

TEST_CASE("calibration: an experiment design's table and JSON", "[calibration]") {
  static const cal::forward_model_of<cal::synthetic_model> model{cal::synthetic_model({})};
  cal::parameter_set planned = cal::parameter_set::nominal(1);
  planned.value(0, head_parameter::sigma) = 0.05;
  planned.value(earth_parameter::horizon) = 40;
  planned.free[0] = planned.free[1] = planned.free[parameter_index(1, earth_parameter::horizon)] =
      true;
  std::vector<cal::telemetry_sample> samples;
  for (std::size_t i = 0; i < 100; ++i) samples.push_back({i, 60.0 * static_cast<double>(i), 0});
  const auto design = cal::predict_uncertainty(model, planned, samples, {{0.01, 0.0}});
  REQUIRE(design.ok());
  const cal::uncertainty_report& u = design.value().uncertainty;
  CHECK(design.value().residual_count == 200);
  for (std::size_t index : u.free_parameters) {
    CHECK(u.parameters[index].determined);
    CHECK(u.parameters[index].sigma > 0);
  }
  const std::string table = cal::design_table(design.value());
  CHECK_THAT(table, Catch::Matchers::StartsWith("experiment design: 200 planned residuals\n"));
  CHECK_THAT(table, Catch::Matchers::Contains("predicted 1 sigma"));
  CHECK_THAT(table, Catch::Matchers::Contains("unobservable combinations: none"));
  const std::string text = cal::design_json(design.value());
  const auto parsed = conescan::text::parse_json_document(text, "design.json");
  REQUIRE(parsed.ok());
  CHECK(parsed.value()["kind"] == "design");
  CHECK(parsed.value()["parameters"]["h1.phase"]["sigma"].get<double>() == u.parameters[1].sigma);
  CHECK_THAT(cal::read_fit_json(text, "design.json").error().text(),
             Catch::Matchers::Contains(".kind: expected \"fit\""));
}
