// The calibration with the sensor physics (MODEL §12) in its forward model
// (src/scene_calibration/scene_model.hpp): the Jacobian of a physics crossing, by automatic
// differentiation through the chain, against central differences of the chain in double; the
// detector's lag recovered on the paper's ellipse and removed by --apply; what the data cannot
// separate (the limb's height and the horizon's, the lag and the crossing biases on a circular
// orbit), in a fit and in --predict's design.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "calibration/fit_json.hpp"
#include "calibration/layout.hpp"
#include "calibration/report.hpp"
#include "scene_calibration/fit_correction.hpp"
#include "scene_calibration/scene_fit.hpp"
#include "scene_calibration/scene_model.hpp"
#include "simulation/simulation.hpp"
#include "support/scene_of.hpp"
#include "support/scene_telemetry.hpp"
#include "support/temp_file.hpp"

namespace cal = conescan::calibration;
namespace sc = conescan::scene;
using conescan_test::scene_of;
using conescan_test::simulated_telemetry;

namespace {

// The model's inputs a physics crossing depends on, in the order of `model_inputs`.
constexpr int input_count = 10;
const char* const input_names[input_count] = {
    "misalignment x",     "misalignment y",   "dgamma",          "tau-ms",
    "threshold",          "horizon-km",       "horizon-pole-km", "horizon-shift-km",
    "radiance-offset-km", "radiance-scale-km"};
// Central-difference steps, each in its input's unit (deg, ms, 1, km): large against the
// chain's own noise (~1e-11 deg: a step of 1e-4 left 6e-6 of a derivative), small enough that
// the Richardson-extrapolated difference's h^4 term is far below 1e-6.
const double input_steps[input_count] = {1e-3, 1e-3, 1e-3, 1e-3, 1e-3, 0.1, 0.1, 0.1, 0.1, 0.1};

template <class T>
struct model_inputs {
  cal::head_geometry<T> head;
  cal::earth_geometry<T> earth;
  T* at(int i) {
    T* slots[input_count] = {&head.misalignment_x_deg,  &head.misalignment_y_deg,
                             &head.dgamma_deg,          &head.tau_ms,
                             &head.threshold,           &earth.horizon_km,
                             &earth.horizon_pole_km,    &earth.horizon_shift_km,
                             &earth.radiance_offset_km, &earth.radiance_scale_km};
    return slots[i];
  }
};

model_inputs<double> nominal_inputs() {
  return {{{0.03, 0.04, 0.02}, 1.0, 0.45}, {0.0, 0.0, 0.0, 40.0, 7.0}};
}

// The chord and phase (deg) at `inputs` in double.
std::array<double, 2> measured_at(const cal::scene_model& model, const cal::telemetry_sample& s,
                                  const model_inputs<double>& inputs) {
  const cal::predicted_measurement<double> p = model.predict(s, inputs.head, inputs.earth);
  REQUIRE(p.state == conescan::status::ok);
  return {p.chord_deg, p.phase_deg};
}

// d(chord, phase)/d(input i) by central differences at steps h and h/2, Richardson-extrapolated.
std::array<double, 2> central_difference(const cal::scene_model& model,
                                         const cal::telemetry_sample& s, int i) {
  auto at_step = [&](double h) {
    model_inputs<double> plus = nominal_inputs(), minus = nominal_inputs();
    *plus.at(i) += h;
    *minus.at(i) -= h;
    const auto p = measured_at(model, s, plus), m = measured_at(model, s, minus);
    return std::array<double, 2>{(p[0] - m[0]) / (2 * h), (p[1] - m[1]) / (2 * h)};
  };
  const auto coarse = at_step(input_steps[i]), fine = at_step(input_steps[i] / 2);
  return {(4 * fine[0] - coarse[0]) / 3, (4 * fine[1] - coarse[1]) / 3};
}

// Every input's Jet derivative against central differences, at each of `rows`: within 1e-6 of
// the derivative's size, or of the largest derivative of the same output in the row where it is
// smaller (an input the output barely depends on, such as the phase on the horizon's height).
void check_jacobian(const sc::loaded_scene& scene, const std::vector<double>& times_s) {
  const auto model = cal::scene_model::of(scene, times_s);
  REQUIRE(model.ok());
  for (std::size_t row = 0; row < times_s.size(); ++row) {
    const cal::telemetry_sample s{row, times_s[row], 0};
    model_inputs<cal::parameter_jet> jets;
    model_inputs<double> values = nominal_inputs();
    for (int i = 0; i < input_count; ++i) *jets.at(i) = cal::parameter_jet(*values.at(i), i);
    const cal::predicted_measurement<cal::parameter_jet> p =
        model.value().predict(s, jets.head, jets.earth);
    REQUIRE(p.state == conescan::status::ok);
    const double largest[2] = {p.chord_deg.v.head(input_count).cwiseAbs().maxCoeff(),
                               p.phase_deg.v.head(input_count).cwiseAbs().maxCoeff()};
    for (int i = 0; i < input_count; ++i) {
      const auto difference = central_difference(model.value(), s, i);
      const double jet[2] = {p.chord_deg.v[i], p.phase_deg.v[i]};
      for (int c = 0; c < 2; ++c) {
        INFO("t_s " << times_s[row] << ", d " << (c == 0 ? "chord" : "phase") << " / d "
                    << input_names[i] << ": jet " << jet[c] << ", differences " << difference[c]);
        CHECK(std::abs(jet[c] - difference[c]) <= 1e-6 * std::max(std::abs(jet[c]), largest[c]));
      }
    }
  }
}

// --apply refuses the fit in `fit_path` for `scene`, naming the option and saying each of `what`.
void check_apply_refused(const sc::loaded_scene& scene, const std::string& fit_path,
                         std::initializer_list<const char*> what) {
  const auto refused = sc::fit_correction::of(scene, fit_path);
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().option == "apply");
  for (const char* text : what) CHECK_THAT(refused.error().text(), Catch::Matchers::Contains(text));
}

}  // namespace

TEST_CASE("calibration physics: the Jacobian is the chain's, within 1e-6 of central differences",
          "[calibration][physics][jacobian]") {
  // The paper's ellipse: perigee, a quarter and half an orbit on.
  const std::vector<double> times{0, 1500, 3000};
  const std::vector<std::pair<std::string, std::string>> pencil{
      {"model", "scan"},
      {"radiance-offset-km", "40"},
      {"head",
       "sigma=0.05,phase=53.13,dgamma=0.02,spin-hz=1,tau-ms=1,locator=fixed,"
       "threshold=0.45"}};
  SECTION("a pencil with lag on the sphere") {
    check_jacobian(scene_of(pencil), times);
  }
  SECTION("a pencil with lag on the apparent ellipsoid, with the pole and season terms") {
    auto wgs84 = pencil;
    wgs84.push_back({"earth", "wgs84"});
    wgs84.push_back({"horizon-pole-km", "-1"});
    wgs84.push_back({"horizon-shift-km", "2"});
    wgs84.push_back({"sun-declination-deg", "20"});
    check_jacobian(scene_of(wgs84), times);
  }
  SECTION("a 1.5 deg square field with lag, at perigee") {
    auto field = pencil;
    field.back().second += ",fov=1.5";
    check_jacobian(scene_of(field), {0});
  }
}

TEST_CASE("calibration physics: the lag recovered on the paper's ellipse, --apply removes it",
          "[calibration][physics][apply]") {
  // One head with 1 ms of lag at 1 rev/s, noise 0.001 deg; the fit starts at 0.5 ms and frees
  // the lag beside the crossing biases.
  const std::vector<std::pair<std::string, std::string>> common{
      {"model", "scan"}, {"radiance-offset-km", "40"}, {"step-s", "30"}, {"orbits", "1"}};
  auto truth_options = common;
  truth_options.push_back({"head", "sigma=0,spin-hz=1,tau-ms=1,noise=0.001"});
  auto start_options = common;
  start_options.push_back({"head", "sigma=0,spin-hz=1,tau-ms=0.5,noise=0.001"});
  const auto free = cal::parse_free_list("h1.bias-in,h1.bias-out,h1.tau-ms", 1);
  REQUIRE(free.ok());
  const auto outcome = cal::fit_scene(
      scene_of(start_options), simulated_telemetry(scene_of(truth_options), 2), free.value(), {});
  REQUIRE(outcome.ok());
  const auto* r = std::get_if<cal::fit_result>(&outcome.value());
  REQUIRE(r != nullptr);
  INFO(cal::fit_table(*r));
  const cal::parameter_estimate& tau =
      r->uncertainty.parameters[cal::parameter_index(0, cal::head_parameter::tau_ms)];
  REQUIRE(tau.determined);
  CHECK(std::abs(tau.estimate - 1) <= 3 * tau.sigma);
  CHECK(tau.sigma < 0.01);
  // The lag's shift and the biases are strongly correlated on this orbit, but separable.
  CHECK(r->uncertainty.unobservable.empty());
  CHECK(std::abs(r->uncertainty.correlation[0][2]) > 0.9);
  // --apply on the noise-free truth with the processing's horizon at the limb's 50 % height:
  // what is left is the estimates' error, far below the 0.33 deg the lag makes.
  auto clean_options = common;
  clean_options.push_back({"processing-horizon-km", "40"});
  clean_options.push_back({"head", "sigma=0,spin-hz=1,tau-ms=1"});
  const sc::loaded_scene clean = scene_of(clean_options);
  const conescan_test::temp_file json(cal::fit_json(outcome.value()), ".json");
  auto correction = sc::fit_correction::of(clean, json.path);
  INFO((correction.ok() ? std::string() : correction.error().text()));
  REQUIRE(correction.ok());
  // A scene whose head has no spin cannot take the fitted lag.
  auto spinless_options = common;
  spinless_options.push_back({"processing-horizon-km", "40"});
  spinless_options.push_back({"head", "sigma=0"});
  check_apply_refused(scene_of(spinless_options), json.path,
                      {"head 1: tau-ms = ", "needs spin-hz="});
  for (const bool corrected : {false, true}) {
    sc::simulation sim = sc::simulation::of(clean).value();
    if (corrected) sim.set_correction(correction.value().get());
    double largest_deg = 0;
    sc::row row = sim.make_row();
    for (std::uint64_t k = 0; k < sim.rows(); ++k) {
      sim.compute(k, row);
      REQUIRE(row.state == conescan::status::ok);
      largest_deg = std::max({largest_deg, std::abs(row.roll_err_rad) / cal::radians_per_degree,
                              std::abs(row.pitch_err_rad) / cal::radians_per_degree});
    }
    if (corrected)
      CHECK(largest_deg < 1e-3);
    else
      CHECK(largest_deg > 0.3);
  }
}

namespace {

// The fit's (or the design's) one unobservable combination, its names sorted (none: empty).
std::vector<std::string> combination_names(const cal::uncertainty_report& u) {
  REQUIRE(u.unobservable.size() <= 1);
  std::vector<std::string> names;
  if (u.unobservable.empty()) return names;
  for (const auto& [name, component] : u.unobservable.front().components) names.push_back(name);
  std::sort(names.begin(), names.end());
  return names;
}

// The fit of `start` to `truth`'s telemetry, whose combinations the design predicted too.
cal::fit_result fitted(const std::vector<std::pair<std::string, std::string>>& truth,
                       const std::vector<std::pair<std::string, std::string>>& start,
                       const std::string& free_list) {
  const auto free = cal::parse_free_list(free_list, 1);
  REQUIRE(free.ok());
  const auto outcome =
      cal::fit_scene(scene_of(start), simulated_telemetry(scene_of(truth), 1), free.value(), {});
  INFO((outcome.ok() ? std::string() : outcome.error().text()));
  REQUIRE(outcome.ok());
  const auto* r = std::get_if<cal::fit_result>(&outcome.value());
  INFO(cal::fit_table(outcome.value()));
  REQUIRE(r != nullptr);
  // The design predicts the same before the data exist.
  const auto design = cal::predict_scene(scene_of(start), free.value());
  REQUIRE(design.ok());
  CHECK(combination_names(design.value().uncertainty) == combination_names(r->uncertainty));
  return *r;
}

}  // namespace

TEST_CASE("calibration physics: what the data cannot separate is said, in a fit and a design",
          "[calibration][physics][observability]") {
  const std::vector<std::pair<std::string, std::string>> common{
      {"model", "scan"}, {"step-s", "60"}, {"orbits", "1"}};
  SECTION("the limb's height above the horizon and the horizon's height") {
    // A pencil sees the limb 40 km above a surface it never reaches: only their sum matters.
    auto truth = common, start = common;
    truth.push_back({"radiance-offset-km", "40"});
    truth.push_back({"head", "sigma=0,spin-hz=1,tau-ms=1,noise=0.001"});
    start.push_back({"radiance-offset-km", "38"});
    start.push_back({"horizon-km", "1"});
    start.push_back({"head", "sigma=0,spin-hz=1,tau-ms=1,noise=0.001"});
    const cal::uncertainty_report u =
        fitted(truth, start, "horizon-km,radiance-offset-km").uncertainty;
    CHECK(combination_names(u) == std::vector<std::string>{"horizon-km", "radiance-offset-km"});
    for (const char* name : {"horizon-km", "radiance-offset-km"})
      for (const cal::parameter_estimate& p : u.parameters)
        if (p.name == name) CHECK_FALSE(p.determined);  // never an estimate without its 1 sigma
  }
  SECTION("a fit that modelled the physics, applied to a scene that runs none") {
    // A pencil without lag reading the limb 40 km up: the chain runs (tau-ms = 0, held).
    auto truth = common;
    truth.push_back({"radiance-offset-km", "40"});
    truth.push_back({"head", "sigma=0,noise=0.001"});
    const cal::fit_result r = fitted(truth, truth, "h1.bias-in,h1.bias-out");
    const conescan_test::temp_file json(cal::fit_json(cal::fit_outcome{r}), ".json");
    auto bare = common;
    bare.push_back({"head", "sigma=0"});
    check_apply_refused(scene_of(bare), json.path, {"head 1: the fit modelled its sensor physics"});
    CHECK(sc::fit_correction::of(scene_of(truth), json.path).ok());
  }
  SECTION("the lag and the crossing biases on a circular orbit") {
    // Every row sees the same Earth: the lag's shift is a constant the biases can take.
    auto truth = common, start = common;
    for (auto* options : {&truth, &start}) {
      options->push_back({"e", "0"});
      options->push_back({"radiance-offset-km", "40"});
    }
    truth.push_back({"head", "sigma=0,spin-hz=1,tau-ms=1,noise=0.001"});
    start.push_back({"head", "sigma=0,spin-hz=1,tau-ms=0.8,noise=0.001"});
    const cal::fit_result r = fitted(truth, start, "h1.bias-in,h1.bias-out,h1.tau-ms");
    CHECK(combination_names(r.uncertainty) ==
          std::vector<std::string>{"h1.bias-in", "h1.bias-out", "h1.tau-ms"});
    // Such a fit has no bias to subtract: --apply refuses it, naming the head.
    const conescan_test::temp_file json(cal::fit_json(cal::fit_outcome{r}), ".json");
    check_apply_refused(scene_of(truth), json.path,
                        {"head 1: the fit leaves a parameter undetermined"});
  }
}
