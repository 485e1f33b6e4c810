// The fit's time series of the chain (src/scene_calibration/physics_time_series.hpp): on a
// function of time it serves within its tolerance and costs its nodes and checks; where the
// chain fails, or a chord lies beyond those it saw, the rows are the chain's; new inputs
// rebuild; and in the real model (scene_model.hpp) the served crossings and their derivatives
// are the chain's, on the sphere and on the apparent ellipsoid, with a pencil and a field.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "scene_calibration/physics_time_series.hpp"
#include "scene_calibration/scene_model.hpp"
#include "support/scene_of.hpp"

namespace cal = conescan::calibration;
using conescan_test::scene_of;

namespace {

constexpr double degree = 3.14159265358979323846 / 180;
constexpr double period_s = 5800;
// A piece's evaluations: its nodes and its checks.
const std::size_t per_piece = static_cast<std::size_t>(cal::physics_time_series_settings{}.nodes +
                                                       cal::physics_time_series_settings{}.checks);
constexpr cal::series_mask none = 0, input_0 = 1, inputs_0_1 = 3;

std::vector<double> times_every(double step_s, std::size_t count) {
  std::vector<double> t(count);
  for (std::size_t i = 0; i < count; ++i) t[i] = static_cast<double>(i) * step_s;
  return t;
}

// A smooth stand-in for the chain: shifts (rad) that turn with the orbit, scaled by input 0,
// with that input's derivative; the chord turns too. `fails_from`..`fails_to` (s): no ok there.
struct synthetic_chain {
  std::vector<double> times_s;
  double fails_from = 1e300, fails_to = -1e300;
  cal::series_sample operator()(std::size_t row, const cal::series_inputs& in,
                                cal::series_mask gradient) const {
    const double t = times_s[row], phase = 2 * 3.14159265358979323846 * t / period_s;
    cal::series_sample s;
    s.ok = !(t >= fails_from && t <= fails_to);
    for (std::size_t c = 0; c < 2; ++c) {
      s.shift[c] = in[0] * 1e-3 * std::sin(phase + static_cast<double>(c)) + 2e-3;
      if (gradient & 1u) s.gradient[c][0] = 1e-3 * std::sin(phase + static_cast<double>(c));
      if (gradient & 2u) s.gradient[c][1] = 2e-3 * std::cos(phase + static_cast<double>(c));
    }
    s.chord_rad = 2.0 + 0.01 * std::cos(phase);
    return s;
  }
};

cal::series_inputs inputs_with(double first) {
  cal::series_inputs in{};
  in[0] = first;
  in[4] = std::numeric_limits<double>::quiet_NaN();  // an absent input (a slope's threshold)
  return in;
}

}  // namespace

TEST_CASE("physics time series: a smooth function of time, served within the tolerance",
          "[calibration][physics-series]") {
  const std::vector<double> times = times_every(1, 7200);  // two hours at 1 Hz: 6 blocks
  synthetic_chain chain{times};
  const cal::physics_time_series series(times);
  const cal::series_evaluator evaluate = chain;
  std::mt19937 random(7);
  std::uniform_int_distribution<std::size_t> any_row(0, times.size() - 1);
  double worst = 0, worst_gradient = 0;
  for (int i = 0; i < 300; ++i) {
    const std::size_t row = any_row(random);
    cal::series_sample served;
    const cal::series_sample truth = chain(row, inputs_with(1.5), input_0);
    REQUIRE(series.shift_at(row, inputs_with(1.5), input_0, truth.chord_rad, evaluate, served));
    for (std::size_t c = 0; c < 2; ++c) {
      worst = std::max(worst, std::abs(served.shift[c] - truth.shift[c]));
      worst_gradient =
          std::max(worst_gradient, std::abs(served.gradient[c][0] - truth.gradient[c][0]));
    }
  }
  CHECK(worst <= 1e-7 * degree);
  CHECK(worst_gradient <= 1e-4 * 1e-3);
  // Each block built once, at its nodes and checks; the same inputs (NaN included) again
  // cost nothing more.
  CHECK(series.evaluations() == 6 * per_piece);
  cal::series_sample served;
  REQUIRE(series.shift_at(3, inputs_with(1.5), none, 2.01, evaluate, served));
  CHECK(series.evaluations() == 6 * per_piece);

  SECTION("other inputs rebuild the row's block, and serve their own values") {
    REQUIRE(series.shift_at(3, inputs_with(-0.5), none, 2.01, evaluate, served));
    CHECK(series.evaluations() == 7 * per_piece);
    CHECK(served.shift[0] == Approx(chain(3, inputs_with(-0.5), none).shift[0]).margin(1e-12));
  }
  SECTION("gradients asked of a block built without them rebuild it") {
    const cal::physics_time_series values_only(times);
    REQUIRE(values_only.shift_at(3, inputs_with(1.5), none, 2.01, evaluate, served));
    REQUIRE(values_only.shift_at(3, inputs_with(1.5), input_0, 2.01, evaluate, served));
    CHECK(values_only.evaluations() == 2 * per_piece);
  }
  SECTION("a block built with some gradients serves those and fewer, and rebuilds for more") {
    CHECK(served.gradient[0][1] == 0);  // not asked: not carried
    REQUIRE(series.shift_at(3, inputs_with(1.5), inputs_0_1, 2.01, evaluate, served));
    CHECK(series.evaluations() == 7 * per_piece);
    CHECK(served.gradient[0][1] == Approx(chain(3, inputs_with(1.5), inputs_0_1).gradient[0][1]));
    REQUIRE(series.shift_at(3, inputs_with(1.5), input_0, 2.01, evaluate, served));
    REQUIRE(series.shift_at(3, inputs_with(1.5), inputs_0_1, 2.01, evaluate, served));
    CHECK(series.evaluations() == 7 * per_piece);
  }
  SECTION("two sets of gradients asked in turn build the block once more, with both") {
    constexpr cal::series_mask input_1 = 2;
    REQUIRE(series.shift_at(3, inputs_with(1.5), input_1, 2.01, evaluate, served));
    CHECK(series.evaluations() == 7 * per_piece);
    for (int i = 0; i < 3; ++i) {
      REQUIRE(series.shift_at(3, inputs_with(1.5), input_0, 2.01, evaluate, served));
      REQUIRE(series.shift_at(3, inputs_with(1.5), input_1, 2.01, evaluate, served));
    }
    CHECK(series.evaluations() == 7 * per_piece);
    CHECK(served.gradient[0][0] != 0);
  }
  SECTION("a chord beyond those the piece saw, by more than the margin, is the chain's") {
    CHECK(series.shift_at(3, inputs_with(1.5), none, 2.01 + 0.5e-3, evaluate, served));
    CHECK_FALSE(series.shift_at(3, inputs_with(1.5), none, 2.01 + 2e-3, evaluate, served));
    CHECK_FALSE(series.shift_at(3, inputs_with(1.5), none, 1.99 - 2e-3, evaluate, served));
  }
}

TEST_CASE("physics time series: where the chain fails, its rows are the chain's",
          "[calibration][physics-series]") {
  const std::vector<double> times = times_every(1, 1201);  // one block
  synthetic_chain chain{times, 600, 610};
  const cal::physics_time_series series(times);
  const cal::series_evaluator evaluate = chain;
  cal::series_sample served;
  // The failed piece is halved down to pieces of fewer than 76 rows: the rows about the
  // failure are the chain's, those far from it served.
  CHECK_FALSE(series.shift_at(605, inputs_with(1), none, 2.0, evaluate, served));
  CHECK_FALSE(series.shift_at(595, inputs_with(1), none, 2.0, evaluate, served));
  const std::size_t far_rows[] = {0, 100, 300, 900, 1200};
  for (std::size_t row : far_rows) {
    INFO("row " << row);
    REQUIRE(series.shift_at(row, inputs_with(1), none, chain(row, inputs_with(1), none).chord_rad,
                            evaluate, served));
    CHECK(std::abs(served.shift[0] - chain(row, inputs_with(1), none).shift[0]) <= 1e-7 * degree);
  }

  SECTION("too few rows for a piece: every row is the chain's, at no cost") {
    const std::vector<double> few = times_every(1, 37);
    synthetic_chain short_chain{few};
    const cal::physics_time_series short_series(few);
    CHECK_FALSE(short_series.shift_at(10, inputs_with(1), none, 2.0, short_chain, served));
    CHECK(short_series.evaluations() == 0);
  }
}

TEST_CASE("physics time series: times a series can follow", "[calibration][physics-series]") {
  CHECK(cal::series_times_usable({0, 1, 2.5}));
  CHECK_FALSE(cal::series_times_usable({0, 1, 1}));
  CHECK_FALSE(cal::series_times_usable({0, 2, 1}));
  CHECK_FALSE(cal::series_times_usable({}));
  CHECK_FALSE(cal::series_times_usable({0, std::numeric_limits<double>::infinity()}));
}

namespace {

// The model's inputs at a working point, as Jets seeded in slots 0 to 9 (the series' order),
// or only those in `free`: the others carry no derivative, as a held parameter.
struct jet_inputs {
  cal::head_geometry<cal::parameter_jet> head{};
  cal::earth_geometry<cal::parameter_jet> earth{};
  explicit jet_inputs(double tau_ms, cal::series_mask free = cal::all_series_inputs) {
    const double values[cal::series_input_count] = {0.03, 0.04, 0.02, tau_ms, 0.45,
                                                    0.0,  0.0,  0.0,  40.0,   7.0};
    const auto fields = cal::series_fields(head, earth);
    for (std::size_t i = 0; i < fields.size(); ++i)
      *fields[i] = free >> i & 1u ? cal::parameter_jet(values[i], static_cast<int>(i))
                                  : cal::parameter_jet(values[i]);
  }
};

// The model with its time series against the same model on the chain, at `checked` rows spread
// over the scene: chord and phase within 1e-7 deg (2e-7 for the chord: two crossings), each
// derivative within 1e-4 of the largest of its output's (the series' gradient check).
void check_series_against_chain(const std::vector<std::pair<std::string, std::string>>& options,
                                const std::vector<double>& times, std::size_t checked) {
  auto series_model = cal::scene_model::of(scene_of(options), times);
  auto chain_model = cal::scene_model::of(scene_of(options), times);
  REQUIRE(series_model.ok());
  REQUIRE(chain_model.ok());
  series_model.value().use_physics_series(0);
  chain_model.value().use_physics_series(std::numeric_limits<std::size_t>::max());
  const jet_inputs jets(1.0);
  std::size_t ok_rows = 0;
  for (std::size_t j = 0; j < checked; ++j) {
    const std::size_t row = (2 * j + 1) * times.size() / (2 * checked);
    const cal::telemetry_sample s{row, times[row], 0};
    const auto a = series_model.value().predict(s, jets.head, jets.earth);
    const auto b = chain_model.value().predict(s, jets.head, jets.earth);
    INFO("t_s " << times[row]);
    REQUIRE(a.state == b.state);
    if (b.state != conescan::status::ok) continue;
    CHECK(std::abs(a.chord_deg.a - b.chord_deg.a) <= 2e-7);
    CHECK(std::abs(a.phase_deg.a - b.phase_deg.a) <= 1e-7);
    const double largest[2] = {b.chord_deg.v.cwiseAbs().maxCoeff(),
                               b.phase_deg.v.cwiseAbs().maxCoeff()};
    CHECK((a.chord_deg.v - b.chord_deg.v).cwiseAbs().maxCoeff() <= 1e-4 * largest[0]);
    CHECK((a.phase_deg.v - b.phase_deg.v).cwiseAbs().maxCoeff() <= 1e-4 * largest[1]);
    ++ok_rows;
  }
  // Every row compared was served by the series, which ran the chain at its nodes and checks
  // only: far fewer than the rows.
  const std::size_t evaluations = series_model.value().physics_series_evaluations();
  INFO("evaluations " << evaluations);
  CHECK(ok_rows == checked);
  CHECK(series_model.value().physics_series_served() == checked);
  CHECK(evaluations > 0);
  CHECK(evaluations < times.size() / 2);
}

}  // namespace

TEST_CASE("physics time series in the fit's model: the chain's crossings and derivatives",
          "[calibration][physics-series]") {
  const std::vector<std::pair<std::string, std::string>> pencil{
      {"model", "scan"},
      {"radiance-offset-km", "40"},
      {"head", "sigma=0.05,phase=53.13,spin-hz=1,tau-ms=1,locator=fixed,threshold=0.45"}};
  SECTION("a pencil with lag on the paper's ellipse, an orbit at 5 s") {
    check_series_against_chain(pencil, times_every(5, 1230), 40);
  }
  SECTION("the same on the apparent ellipsoid with the season term") {
    auto wgs84 = pencil;
    wgs84.push_back({"earth", "wgs84"});
    wgs84.push_back({"horizon-pole-km", "-1"});
    wgs84.push_back({"horizon-shift-km", "2"});
    wgs84.push_back({"radiance-season", "0.2"});
    check_series_against_chain(wgs84, times_every(5, 1230), 40);
  }
  SECTION("a 1.5 deg square field with lag, 20 minutes at 10 s") {
    auto field = pencil;
    field.back().second += ",fov=1.5";
    check_series_against_chain(field, times_every(10, 121), 4);
  }
}

TEST_CASE(
    "physics in the fit's model: a Jet of the free inputs' slots gives the full Jet's derivatives",
    "[calibration][physics-series]") {
  // Four inputs free (the compact Jet's size) against all ten (the fit's full Jet): the chain
  // with each, on every row of a short scene, the series off.
  const std::vector<std::pair<std::string, std::string>> options{
      {"model", "scan"},
      {"earth", "wgs84"},
      {"radiance-offset-km", "40"},
      {"radiance-season", "0.2"},
      {"head", "sigma=0.05,phase=53.13,spin-hz=1,tau-ms=1,locator=fixed,threshold=0.45"}};
  const std::vector<double> times = times_every(600, 10);
  auto model = cal::scene_model::of(scene_of(options), times);
  REQUIRE(model.ok());
  model.value().use_physics_series(std::numeric_limits<std::size_t>::max());
  const cal::series_mask four = 0b0100011001;  // misalignment x, tau, threshold, the limb's height
  const jet_inputs all(1.0), some(1.0, four), held(1.0, 0);
  for (std::size_t row = 0; row < times.size(); ++row) {
    const cal::telemetry_sample s{row, times[row], 0};
    const auto full = model.value().predict(s, all.head, all.earth);
    const auto compact = model.value().predict(s, some.head, some.earth);
    const auto none_free = model.value().predict(s, held.head, held.earth);
    INFO("t_s " << times[row]);
    REQUIRE(full.state == compact.state);
    REQUIRE(full.state == none_free.state);
    if (full.state != conescan::status::ok) continue;
    CHECK(compact.chord_deg.a == full.chord_deg.a);
    CHECK(compact.phase_deg.a == full.phase_deg.a);
    // No input free: the chain in double, the same values to rounding (a Jet divides by its
    // divisor's inverse), no derivatives.
    CHECK(std::abs(none_free.chord_deg.a - full.chord_deg.a) <= 1e-12);
    CHECK(std::abs(none_free.phase_deg.a - full.phase_deg.a) <= 1e-12);
    CHECK(none_free.chord_deg.v.isZero());
    CHECK(none_free.phase_deg.v.isZero());
    for (int i = 0; i < static_cast<int>(cal::series_input_count); ++i) {
      if (!(four >> i & 1u)) {
        CHECK(compact.chord_deg.v[i] == 0);
        continue;
      }
      CHECK(compact.chord_deg.v[i] ==
            Approx(full.chord_deg.v[i]).epsilon(1e-12).margin(1e-15 * full.chord_deg.v.norm()));
      CHECK(compact.phase_deg.v[i] ==
            Approx(full.phase_deg.v[i]).epsilon(1e-12).margin(1e-15 * full.phase_deg.v.norm()));
    }
  }
}
