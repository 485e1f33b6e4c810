// The one fit flow (src/scene_calibration/fit_run.hpp) that conescan-fit and conescan.fit both
// run: run_fit on telemetry columns gives the structs conescan-fit --json writes, byte for byte;
// columns are read exactly as the CSV they make (the same checks, messages, lines and columns);
// and a fit's coordinates are addressed by (head, parameter), with a file's edited names refused
// before anything looks a coordinate up.
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "calibration/fit_json.hpp"
#include "calibration/telemetry.hpp"
#include "calibration/uncertainty.hpp"
#include "scene/scene_request.hpp"
#include "scene_calibration/fit_correction.hpp"
#include "scene_calibration/fit_request.hpp"
#include "scene_calibration/fit_run.hpp"
#include "support/cli.hpp"

namespace cal = conescan::calibration;
using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::temp_file;

namespace {

const std::string scene_args = " --model scan --step-s 30 --orbits 1";
const std::string truth_heads =
    " --head sigma=0.05,phase=60,noise=0.01 --head beta=-90,sigma=0.03,phase=200,noise=0.01";
const std::string free_list = "h1.sigma,h1.phase,h2.sigma,h2.phase,horizon-km";

// The same scene and fit as option entries, as conescan-fit's command line or conescan.fit's
// keywords give them.
std::vector<conescan::scene::option_value> fit_entries(const std::string& free,
                                                       std::optional<std::string> telemetry) {
  const auto typed = [](std::string name, std::string text) {
    return conescan::scene::option_value{std::move(name), std::move(text),
                                         conescan::origin::command_line()};
  };
  std::vector<conescan::scene::option_value> entries{typed("model", "scan"),
                                                     typed("step-s", "30"),
                                                     typed("orbits", "1"),
                                                     typed("head", "sigma=0,noise=0.01"),
                                                     typed("head", "beta=-90,sigma=0,noise=0.01"),
                                                     typed("free", free)};
  if (telemetry) entries.push_back(typed("telemetry", *telemetry));
  return entries;
}

cal::fit_plan plan_of(const std::vector<conescan::scene::option_value>& entries,
                      cal::telemetry_input input) {
  conescan::checked<cal::fit_plan> plan = cal::build_fit_plan(entries, input);
  INFO((plan.ok() ? std::string() : plan.error().text()));
  REQUIRE(plan.ok());
  return std::move(plan).value();
}

// conescan-sim's CSV of the truth: every column as numbers (its values are shortest round-trip
// texts, so from_chars gives the doubles conescan-sim had).
const std::string& telemetry_csv() {
  static const std::string csv = run_sim(scene_args + truth_heads + " --seed 5").out;
  return csv;
}

struct numeric_columns {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;

  cal::telemetry_columns view(
      std::vector<std::pair<std::string, std::vector<std::string>>> texts = {}) const {
    cal::telemetry_columns c{std::move(texts), {}};
    for (std::size_t i = 0; i < names.size(); ++i)
      c.numbers.emplace_back(names[i], std::span<const double>(values[i]));
    return c;
  }
};

numeric_columns columns_of(const std::string& csv, const std::vector<std::string>& wanted) {
  const conescan_test::csv_table t = conescan_test::parse_csv(csv);
  numeric_columns out;
  for (const std::string& name : wanted) {
    out.names.push_back(name);
    std::vector<double>& v = out.values.emplace_back();
    for (const auto& row : t.rows) {
      const std::string& text = row[t.column(name)];
      double x = std::numeric_limits<double>::quiet_NaN();
      if (text != "nan")
        REQUIRE(std::from_chars(text.data(), text.data() + text.size(), x).ec == std::errc());
      v.push_back(x);
    }
  }
  return out;
}

const std::vector<std::string> five = {"t_s", "h1_chord_deg", "h1_phase_deg", "h2_chord_deg",
                                       "h2_phase_deg"};

// The CSV text conescan.fit wrote of its arrays before it passed columns (text columns first, a
// number as its shortest round-trip text, NaN as nan): what read_telemetry_columns must read
// alike.
std::string csv_of(const cal::telemetry_columns& c) {
  std::string text;
  for (const auto& [name, values] : c.texts) text += (text.empty() ? "" : ",") + name;
  for (const auto& [name, values] : c.numbers)
    text += (text.empty() && c.texts.empty() ? "" : ",") + name;
  text += '\n';
  char buffer[32];
  for (std::size_t k = 0; k < c.row_count(); ++k) {
    std::string line;
    for (const auto& [name, values] : c.texts) line += (line.empty() ? "" : ",") + values[k];
    bool first = c.texts.empty();
    for (const auto& [name, values] : c.numbers) {
      if (!first) line += ',';
      first = false;
      if (std::isnan(values[k])) {
        line += "nan";
      } else {
        line.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, values[k]).ptr);
      }
    }
    text += line + '\n';
  }
  return text;
}

// Both readers' results as one comparable text: the error, or every observation.
std::string reading(const conescan::checked<cal::telemetry>& t) {
  if (!t.ok()) return "error " + t.error().text();
  std::ostringstream out;
  out.precision(17);
  out << t.value().row_count << " rows;";
  for (const cal::observation& o : t.value().observations)
    out << ' ' << o.sample.row << ':' << o.sample.head << ':' << o.sample.t_s << ':' << o.chord_deg
        << ':' << o.phase_deg;
  for (std::size_t s : t.value().skipped_per_head) out << " skipped " << s;
  return out.str();
}

}  // namespace

TEST_CASE("fit entry: run_fit on columns gives the structs conescan-fit --json writes",
          "[calibration][fit][fit_entry]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const auto cli = run_program(CONESCAN_FIT_PATH, "--telemetry " + tm.path + scene_args +
                                                      " --head sigma=0,noise=0.01"
                                                      " --head beta=-90,sigma=0,noise=0.01"
                                                      " --free " +
                                                      free_list + " --json");
  INFO(cli.err);
  REQUIRE(cli.exit_status == 0);

  // conescan.fit's path: the plan for columns, the columns read, run_fit.
  const cal::fit_plan in_memory =
      plan_of(fit_entries(free_list, std::nullopt), cal::telemetry_input::in_memory);
  const numeric_columns columns = columns_of(telemetry_csv(), five);
  const auto data = cal::read_fit_telemetry(in_memory, columns.view(), "<array>");
  REQUIRE(data.ok());
  const auto outcome = cal::run_fit(in_memory, data.value());
  REQUIRE(outcome.ok());
  REQUIRE(std::holds_alternative<cal::fit_result>(outcome.value()));
  CHECK(cal::fit_json(outcome.value()) == cli.out);

  // conescan-fit's path: the plan naming the file.
  const cal::fit_plan from_file = plan_of(fit_entries(free_list, tm.path), {});
  const auto file_data = cal::read_fit_telemetry(from_file);
  REQUIRE(file_data.ok());
  const auto file_outcome = cal::run_fit(from_file, file_data.value());
  REQUIRE(file_outcome.ok());
  CHECK(cal::fit_json(file_outcome.value()) == cli.out);

  // The structs themselves, as the JSON reads back: the coordinates by key too.
  const auto read_back = cal::read_fit_json(cli.out, "cli.json");
  REQUIRE(read_back.ok());
  const cal::uncertainty_report& u = std::get<cal::fit_result>(outcome.value()).uncertainty;
  CHECK(read_back.value().uncertainty.coordinate_names == u.coordinate_names);
  CHECK(read_back.value().uncertainty.coordinate_keys == u.coordinate_keys);
  CHECK(read_back.value().uncertainty.coordinate_values == u.coordinate_values);

  // --predict: run_design is the CLI's design.
  const auto design = run_program(
      CONESCAN_FIT_PATH, "--predict --json" + scene_args + truth_heads + " --free " + free_list);
  REQUIRE(design.exit_status == 0);
  std::vector<conescan::scene::option_value> predict = fit_entries(free_list, std::nullopt);
  predict[3].text = "sigma=0.05,phase=60,noise=0.01";
  predict[4].text = "beta=-90,sigma=0.03,phase=200,noise=0.01";
  predict.push_back({"predict", "true", conescan::origin::command_line()});
  const auto designed = cal::run_design(plan_of(predict, {}));
  REQUIRE(designed.ok());
  CHECK(cal::design_json(designed.value()) == design.out);

  // A plan without a telemetry file has nothing for read_fit_telemetry(plan) to read.
  const auto none = cal::read_fit_telemetry(in_memory);
  REQUIRE_FALSE(none.ok());
  CHECK(none.error().option == "telemetry");
}

TEST_CASE("fit entry: columns are read exactly as the CSV they make",
          "[calibration][fit][fit_entry]") {
  const cal::fit_plan plan =
      plan_of(fit_entries("h1.sigma", std::nullopt), cal::telemetry_input::in_memory);
  const cal::telemetry_time_stamps stamps = cal::scene_time_stamps(plan.scene);
  const numeric_columns good = columns_of(telemetry_csv(), five);
  const auto same = [&](const numeric_columns& c, std::size_t heads = 2,
                        std::vector<std::pair<std::string, std::vector<std::string>>> texts = {}) {
    const cal::telemetry_columns view = c.view(std::move(texts));
    std::istringstream in(csv_of(view));
    const std::string from_text = reading(cal::read_telemetry(in, "<array>", heads, stamps));
    const std::string from_columns =
        reading(cal::read_telemetry_columns(view, "<array>", heads, stamps));
    INFO(from_text);
    CHECK(from_columns == from_text);
    return from_columns;
  };
  CHECK(same(good).rfind("207 rows;", 0) == 0);
  // Each hostile value at a row and column whose byte column depends on the texts before it.
  const auto with = [&](std::size_t column, std::size_t row, double value) {
    numeric_columns c = good;
    c.values[column][row] = value;
    return c;
  };
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(same(with(1, 3, inf)), Catch::Matchers::Contains("<array>:5:"));
  CHECK_THAT(same(with(4, 5, -inf)), Catch::Matchers::Contains("'-inf' is not a finite number"));
  CHECK_THAT(same(with(0, 7, nan)), Catch::Matchers::Contains("column t_s: 'nan'"));
  CHECK_THAT(same(with(0, 4, 20)), Catch::Matchers::Contains("does not follow"));
  CHECK_THAT(same(with(0, 206, 1e9)), Catch::Matchers::Contains("outside the scene's span"));
  CHECK_THAT(same(with(2, 9, 400)), Catch::Matchers::Contains("207 rows;"));  // a phase: any
  CHECK_THAT(same(with(3, 9, 400)), Catch::Matchers::Contains("outside (0, 360)"));
  CHECK_THAT(same(with(3, 9, 1e-320)), Catch::Matchers::Contains("207 rows;"));  // subnormal
  CHECK_THAT(same(with(1, 2, nan)), Catch::Matchers::Contains("skipped 1 skipped 0"));
  // The header's refusals: a head missing, beyond the scene's, a column twice, two kinds of time.
  numeric_columns cut = good;
  cut.names.pop_back();
  cut.values.pop_back();
  CHECK_THAT(same(cut), Catch::Matchers::Contains("missing column 'h2_phase_deg'"));
  CHECK_THAT(same(good, 1), Catch::Matchers::Contains("columns of head 2"));
  numeric_columns twice = good;
  twice.names[2] = "h1_chord_deg";
  CHECK_THAT(same(twice), Catch::Matchers::Contains("appears twice"));
  numeric_columns gps = good;
  gps.names.push_back("gps_s");
  gps.values.push_back(good.values[0]);
  CHECK_THAT(same(gps), Catch::Matchers::Contains("mixed time columns"));
  // No rows; no columns at all.
  numeric_columns empty = good;
  for (auto& v : empty.values) v.clear();
  CHECK_THAT(same(empty), Catch::Matchers::Contains("no telemetry row after the header"));
  CHECK_THAT(same(numeric_columns{}), Catch::Matchers::Contains("missing column 't_s'"));
  // utc as text columns, before the numbers: refused without an epoch in both.
  numeric_columns heads_only = good;
  heads_only.names.erase(heads_only.names.begin());
  heads_only.values.erase(heads_only.values.begin());
  for (auto& v : heads_only.values) v.resize(3);
  CHECK_THAT(same(heads_only, 2,
                  {{"utc", {"2000-01-01T12:00:00", "2000-01-01T12:00:30", "2000-01-01T12:01:00"}}}),
             Catch::Matchers::Contains("need the scene's epoch"));
}

TEST_CASE("fit entry: a fit's coordinates are addressed by (head, parameter)",
          "[calibration][fit][fit_entry][apply]") {
  const numeric_columns columns = columns_of(telemetry_csv(), five);
  const auto fitted = [&](const std::string& free) {
    const cal::fit_plan plan =
        plan_of(fit_entries(free, std::nullopt), cal::telemetry_input::in_memory);
    const auto data = cal::read_fit_telemetry(plan, columns.view(), "<array>");
    REQUIRE(data.ok());
    auto outcome = cal::run_fit(plan, data.value());
    REQUIRE(outcome.ok());
    REQUIRE(std::holds_alternative<cal::fit_result>(outcome.value()));
    return std::get<cal::fit_result>(std::move(outcome).value());
  };
  using cal::head_parameter;
  using cal::misalignment_axis;
  // Head 1 cartesian (sigma and phase free), head 2 polar (sigma alone), the horizon.
  const cal::fit_result fit = fitted("h1.sigma,h1.phase,h2.sigma,h2.dgamma,horizon-km");
  const cal::uncertainty_report& u = fit.uncertainty;
  const auto name_at = [&](std::optional<std::size_t> i) {
    return i ? u.coordinate_names[*i] : std::string("none");
  };
  CHECK(name_at(cal::find_coordinate(u, 0, misalignment_axis::x)) == "h1.misalign-x");
  CHECK(name_at(cal::find_coordinate(u, 0, misalignment_axis::y)) == "h1.misalign-y");
  CHECK(name_at(cal::find_coordinate(u, 0, head_parameter::sigma)) == "none");  // x and y
  CHECK(name_at(cal::find_coordinate(u, 1, head_parameter::sigma)) == "h2.sigma");
  CHECK(name_at(cal::find_coordinate(u, 1, misalignment_axis::x)) == "none");  // polar
  CHECK(name_at(cal::find_coordinate(u, 1, head_parameter::dgamma)) == "h2.dgamma");
  CHECK(name_at(cal::find_coordinate(u, 1, head_parameter::phase)) == "none");  // held
  CHECK(name_at(cal::find_coordinate(u, cal::earth_parameter::horizon)) == "horizon-km");
  CHECK(name_at(cal::find_coordinate(u, 2, head_parameter::sigma)) == "none");  // no head 3
  CHECK(name_at(cal::find_coordinate(u, 99, misalignment_axis::x)) == "none");
  // Every key names its coordinate's slot as the layout does.
  REQUIRE(u.coordinate_keys.size() == u.coordinate_names.size());
  for (std::size_t i = 0; i < u.coordinate_keys.size(); ++i) {
    const cal::coordinate_key& key = u.coordinate_keys[i];
    CHECK_FALSE(key.segment);
    CHECK(key.cartesian == (u.coordinate_names[i].find(".misalign-") != std::string::npos));
    if (!key.cartesian) CHECK(u.parameters[key.slot].name == u.coordinate_names[i]);
  }
  // A drifting coordinate has its segment, and no global value to find.
  const cal::fit_result drift = fitted("h1.sigma@3000,h1.phase@3000,h2.sigma");
  const cal::uncertainty_report& d = drift.uncertainty;
  REQUIRE(d.coordinate_keys.size() >= 5);
  CHECK(d.coordinate_names[2] == "h1.misalign-x[1]");
  CHECK(d.coordinate_keys[2] ==
        cal::coordinate_key{cal::parameter_index(0, head_parameter::sigma), 1, true});
  CHECK_FALSE(cal::find_coordinate(d, 0, misalignment_axis::x));
  CHECK(cal::find_coordinate(d, 1, head_parameter::sigma).has_value());
}

TEST_CASE("fit entry: --apply refuses a fit file whose coordinate names were edited",
          "[calibration][fit][fit_entry][apply]") {
  const temp_file tm(telemetry_csv(), ".csv");
  const auto cli =
      run_program(CONESCAN_FIT_PATH, "--telemetry " + tm.path + scene_args +
                                         " --head sigma=0,noise=0.01"
                                         " --head beta=-90,sigma=0,noise=0.01"
                                         " --free h1.sigma,h1.phase,h2.sigma,h2.phase --json");
  REQUIRE(cli.exit_status == 0);
  const std::string json = cli.out;
  const std::string first = "\"h1.misalign-x\"";
  const std::size_t names_at = json.find(first, json.find("\"coordinates\""));
  REQUIRE(names_at != std::string::npos);
  const cal::fit_plan plan =
      plan_of(fit_entries("h1.sigma", std::nullopt), cal::telemetry_input::in_memory);
  // A head number that is none of the scene's, not a number, zero, beyond any integer; the other
  // component; another parameter's name; not a name at all.
  for (const std::string bad :
       {"\"h9.misalign-x\"", "\"hx.misalign-x\"", "\"h0.misalign-x\"",
        "\"h99999999999999999999999.misalign-x\"", "\"h1.misalign-y\"", "\"h1.sigma\"",
        "\"h-1.misalign-x\"", "\"\"", "\"h1.misalign-x \"", "5", "null"}) {
    std::string edited = json;
    edited.replace(names_at, first.size(), bad);
    INFO(bad);
    const auto read = cal::read_fit_json(edited, "edited.json");
    REQUIRE_FALSE(read.ok());
    CHECK_THAT(read.error().text(),
               Catch::Matchers::Contains(".coordinates.names[0]: expected \"h1.misalign-x\""));
    const temp_file file(edited, ".json");
    const auto correction = conescan::scene::fit_correction::of(plan.scene, file.path);
    REQUIRE_FALSE(correction.ok());
    CHECK(correction.error().option == "apply");
    CHECK_THAT(correction.error().text(), Catch::Matchers::Contains(file.path));
  }
  // The file as written is taken.
  const temp_file good(json, ".json");
  const auto taken = conescan::scene::fit_correction::of(plan.scene, good.path);
  INFO((taken.ok() ? std::string() : taken.error().text()));
  CHECK(taken.ok());
}
