// The output's columns and conversions (src/simulation/csv_columns.hpp), shared by conescan-sim's
// CSV and the Python module: MODEL §1's wraps on both sides of each boundary, the columns' names
// and kinds in the order visit_row gives the values, the leading columns of a plan, and the
// summary's statistics. (That both programs print the same numbers is
// tests/python/test_simulate.py's.)
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "scene/scene_plan.hpp"
#include "simulation/csv_columns.hpp"

using conescan::checked;
using conescan::origin;

using namespace conescan;
using namespace conescan::scene;

namespace {

constexpr double half_turn = 3.141592653589793;  // pi rad

// Records what visit_row gives, in order.
struct recorder {
  std::vector<row_column> columns;
  std::vector<double> values;
  void real(row_column c, double v) {
    columns.push_back(c);
    values.push_back(v);
  }
  void state(row_column c, status s) {
    columns.push_back(c);
    values.push_back(static_cast<double>(status_index(s)));
  }
};

scene_plan plan_of(std::vector<option_value> entries) {
  checked<scene_plan> plan = build_scene_plan(entries);
  REQUIRE(plan.ok());
  return std::move(plan).value();
}

}  // namespace

TEST_CASE("degrees_pm180 wraps to -180 < deg <= 180", "[csv_columns]") {
  CHECK(degrees_pm180(0.0) == 0.0);
  CHECK(degrees_pm180(half_turn) == 180.0);   // the upper end is kept
  CHECK(degrees_pm180(-half_turn) == 180.0);  // the lower end is not: -180 is 180
  CHECK(degrees_pm180(std::nextafter(-half_turn, 0.0)) > -180.0);
  CHECK(degrees_pm180(3 * half_turn) == Approx(180.0).margin(1e-12));  // past it, by remainder
  CHECK(degrees_pm180(-3 * half_turn) == Approx(180.0).margin(1e-12));
  CHECK(degrees_pm180(1.5 * half_turn) == Approx(-90.0).margin(1e-12));
  CHECK(degrees_pm180(-1.5 * half_turn) == Approx(90.0).margin(1e-12));
  CHECK(degrees_pm180(0.001) == rad_to_deg(0.001));  // inside: the plain conversion, exactly
  CHECK(std::isnan(degrees_pm180(std::nan(""))));
}

TEST_CASE("degrees_0_360 wraps to 0 <= deg < 360", "[csv_columns]") {
  CHECK(degrees_0_360(0.0) == 0.0);
  CHECK(degrees_0_360(2 * half_turn) == 0.0);
  CHECK(degrees_0_360(std::nextafter(2 * half_turn, 0.0)) < 360.0);
  CHECK(degrees_0_360(-1e-20) == 0.0);  // 360 - 5.7e-19 rounds to 360, which is 0
  CHECK(degrees_0_360(-0.5 * half_turn) == Approx(270.0).margin(1e-12));
  CHECK(degrees_0_360(5 * half_turn) == Approx(180.0).margin(1e-9));
  CHECK(degrees_0_360(1.0) == rad_to_deg(1.0));
  CHECK(km_from_m(6378137.0) == 6378.137);
}

TEST_CASE("row columns: names and kinds in the order visit_row gives the values", "[csv_columns]") {
  for (const bool condition : {false, true}) {
    row r{1, 2, 3, 4, 5, 6, std::vector<head_row>(2), 7, 8, status::none, 9};
    r.heads[0] = {0.1, 0.2, 0.3, 0.4, 0.5, status::ok, 0};
    r.heads[1] = {0.1, 0.2, 0.3, 0.4, 0.5, status::miss, 0};
    recorder seen;
    visit_row(r, condition, seen);
    const std::vector<column_name> names = row_columns(2, condition);
    REQUIRE(names.size() == seen.columns.size());
    CHECK(names.size() == 6 + 2 * 6 + 3 + (condition ? 1 : 0));
    for (std::size_t k = 0; k < names.size(); ++k) {
      const bool is_status =
          seen.columns[k] == row_column::head_status || seen.columns[k] == row_column::status;
      CHECK((names[k].kind == column_kind::state) == is_status);
    }
    CHECK(names[6].name == "h1_chord_deg");
    CHECK(names[17].name == "h2_status");
    CHECK(seen.values[17] == static_cast<double>(status_index(status::miss)));
    CHECK(names[20].name == "status");
    CHECK(seen.values[2] == 3.0 / 1000);  // r in km
    if (condition) CHECK((names.back().name == "condition" && seen.values.back() == 9));
  }
}

TEST_CASE("leading columns: the swept option, run, seed when some scene has them",
          "[csv_columns]") {
  const origin cli = origin::command_line();
  CHECK(leading_layout_of(plan_of({})).columns().empty());
  // The error budget has none, even with noise (its seed is not a column of it).
  CHECK(leading_layout_of(plan_of({{"budget", "true", cli}, {"head", "noise=0.1", cli}}))
            .columns()
            .empty());
  const scene_plan swept = plan_of({{"sweep", "e=0:0.1:0.05", cli},
                                    {"runs", "2", cli},
                                    {"head", "noise=0.1", cli},
                                    {"seed", "5", cli},
                                    {"processing", "horizon-vector", cli}});
  const leading_layout layout = leading_layout_of(swept);
  const std::vector<column_name> columns = layout.columns();
  REQUIRE(columns.size() == 3);
  CHECK((columns[0].name == "e" && columns[0].kind == column_kind::real));
  CHECK((columns[1].name == "run" && columns[1].kind == column_kind::count));
  CHECK((columns[2].name == "seed" && columns[2].kind == column_kind::count));
  CHECK(layout.condition);
  const std::vector<leading_value> values =
      leading_values(layout, swept, 2, swept.scene(2).config, 2);
  CHECK((values[0].real == 0.1 && !values[0].is_count));
  CHECK((values[1].count == 2 && values[1].is_count));
  CHECK((values[2].count == 5 && values[2].is_count));
}

TEST_CASE("summary statistics in degrees, NaN where there are too few ok rows", "[csv_columns]") {
  error_statistics s;
  for (double v : summary_statistics_deg(s)) CHECK(std::isnan(v));
  s.add(deg_to_rad(1.0), deg_to_rad(-2.0), status::ok);
  s.add(1.0, 1.0, status::miss);  // not ok: counted, not averaged
  std::array<double, 12> one = summary_statistics_deg(s);
  CHECK(one[0] == Approx(1.0));
  CHECK(one[2] == Approx(1.0));
  CHECK(one[3] == Approx(1.0));
  CHECK(std::isnan(one[4]));  // a standard deviation needs two
  CHECK(one[6] == Approx(-2.0));
  s.add(deg_to_rad(3.0), deg_to_rad(-2.0), status::ok);
  const std::array<double, 12> two = summary_statistics_deg(s);
  CHECK(two[1] == Approx(3.0));
  CHECK(two[2] == Approx(2.0));
  CHECK(two[4] == Approx(std::sqrt(2.0)));
  CHECK(two[5] == Approx(3 * std::sqrt(2.0)));
  CHECK(two[10] == Approx(0.0).margin(1e-12));
  CHECK(summary_columns().size() == 2 + status_count + 12);
  CHECK(summary_columns().back().name == std::string(summary_statistic_names().back()));
  CHECK(summary_source_name(0) == "h1");
}
