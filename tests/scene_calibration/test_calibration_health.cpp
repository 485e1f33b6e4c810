// What a fit says about itself (src/calibration/estimator.hpp): measurements dropped far from
// the solution are tested again at it (the far starts sigma = 20 deg and dgamma = -30 deg), what
// stays dropped is counted per head with a warning above 1 %, outliers that share a sign are a
// systematic effect, and telemetry that the model does not describe (random numbers) warns.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <variant>

#include "calibration/fit_json.hpp"
#include "calibration/report.hpp"
#include "scene/scene_plan.hpp"
#include "scene_calibration/scene_fit.hpp"
#include "simulation/simulation.hpp"
#include "support/scene_of.hpp"
#include "support/scene_telemetry.hpp"
#include "support/synthetic_model.hpp"

namespace cal = conescan::calibration;
namespace sc = conescan::scene;
using conescan_test::scene_of;
using conescan_test::simulated_telemetry;

namespace {

using options_list = std::vector<std::pair<std::string, std::string>>;

// The README's recovery scene over one orbit at 10 s; `head1` the first head's keys of the fit.
const options_list orbit{{"model", "scan"}, {"step-s", "10"}, {"orbits", "1"}};
const std::string recovery_free = "h1.sigma,h1.phase,h1.dgamma,h2.sigma,h2.phase,horizon-km";

sc::loaded_scene recovery_start(const std::string& head1) {
  options_list o = orbit;
  o.push_back({"horizon-km", "40"});
  o.push_back({"head", head1 + ",noise=0.01"});
  o.push_back({"head", "beta=-90,sigma=0,noise=0.01"});
  return scene_of(o);
}

const cal::telemetry& recovery_telemetry() {
  static const cal::telemetry t = [] {
    options_list o = orbit;
    o.push_back({"horizon-km", "42"});
    o.push_back({"seed", "15"});
    o.push_back({"head", "sigma=0.05,phase=60,dgamma=0.02,noise=0.01"});
    o.push_back({"head", "beta=-90,sigma=0.03,phase=200,noise=0.01"});
    return simulated_telemetry(scene_of(o));
  }();
  return t;
}

cal::fit_result fit_scene(const sc::loaded_scene& start, const cal::telemetry& data,
                          const std::string& free) {
  const auto outcome = cal::fit_scene(
      start, data, cal::parse_free_list(free, start.config.heads.size()).value(), {});
  INFO((outcome.ok() ? cal::fit_table(outcome.value()) : outcome.error().text()));
  REQUIRE(outcome.ok());
  REQUIRE(std::holds_alternative<cal::fit_result>(outcome.value()));
  return std::get<cal::fit_result>(outcome.value());
}

}  // namespace

TEST_CASE("calibration health: measurements dropped at a far start are re-admitted at the solution",
          "[calibration][health]") {
  const cal::fit_result reference =
      fit_scene(recovery_start("sigma=0"), recovery_telemetry(), recovery_free);
  CHECK(reference.dropped_at_start == 0);
  for (const char* far : {"sigma=20", "dgamma=-30", "sigma=20,phase=240"}) {
    const cal::fit_result r = fit_scene(recovery_start(far), recovery_telemetry(), recovery_free);
    INFO(far << "\n" << cal::fit_table(r));
    CHECK(r.readmitted == r.dropped_at_start);
    CHECK(r.dropped_per_head == std::vector<std::size_t>{0, 0});
    CHECK(r.observations_per_head == reference.observations_per_head);
    // The same solution as from sigma = 0, to a small fraction of the 1 sigma.
    for (std::size_t index : reference.uncertainty.free_parameters) {
      const cal::parameter_estimate& a = r.uncertainty.parameters[index];
      const cal::parameter_estimate& b = reference.uncertainty.parameters[index];
      INFO(a.name);
      CHECK(std::abs(cal::wrap_deg(a.estimate - b.estimate)) < 0.01 * b.sigma);
    }
    CHECK(r.warnings.empty());
  }
  // Delta gamma = -30 deg leaves head 1's scan off the Earth for much of the orbit at the start.
  const cal::fit_result far =
      fit_scene(recovery_start("dgamma=-30"), recovery_telemetry(), recovery_free);
  CHECK(far.dropped_at_start > 300);
  CHECK_THAT(cal::fit_table(far),
             Catch::Matchers::Contains(std::to_string(far.dropped_at_start) +
                                       " measurements the model cannot predict at the start (" +
                                       std::to_string(far.dropped_at_start) +
                                       " of them re-admitted at a solution)"));
}

namespace {

// The analytic model, blind on head 1 one row in `every`: those measurements can never be
// predicted.
struct blind_model {
  cal::synthetic_model base{cal::synthetic_scene{}};
  std::size_t every = 50;

  template <class T>
  cal::predicted_measurement<T> predict(const cal::telemetry_sample& s,
                                        const cal::head_geometry<T>& head,
                                        const cal::earth_geometry<T>& earth) const {
    if (s.head == 0 && s.row % every == 0) return {T(0.0), T(0.0), conescan::status::miss};
    return base.predict(s, head, earth);
  }
};

}  // namespace

TEST_CASE("calibration health: measurements left out at the solution are counted and warned",
          "[calibration][health]") {
  const auto data = cal::simulate_observations(cal::synthetic_model({}), cal::recovery_truth(), 0,
                                               10, 600, 0.01, 3, 0);
  for (std::size_t every : {std::size_t{50}, std::size_t{200}}) {
    const cal::forward_model_of<blind_model> model{blind_model{cal::synthetic_model({}), every}};
    const auto outcome =
        cal::fit({&model, cal::recovery_start(), data, {{0.01, 0}, {0.01, 0}}}, {});
    REQUIRE(outcome.ok());
    const cal::fit_result& r = std::get<cal::fit_result>(outcome.value());
    const std::size_t blind = (600 + every - 1) / every;
    INFO(cal::fit_table(r));
    CHECK(r.dropped_at_start == blind);
    CHECK(r.readmitted == 0);
    CHECK(r.dropped_per_head == std::vector<std::size_t>{blind, 0});
    CHECK(r.observations_per_head == std::vector<std::size_t>{600 - blind, 600});
    // 12 of 600 is 2 %: a warning; 3 of 600 is 0.5 %: none.
    if (every == 50) {
      REQUIRE(r.warnings.size() == 1);
      CHECK(r.warnings[0] ==
            "h1: 12 of its 600 measurements (2 %) cannot be predicted at the solution and are "
            "left out");
    } else {
      CHECK(r.warnings.empty());
    }
    const std::string json = cal::fit_json(r);
    CHECK(json.find("\"dropped\": {\"h1\": {\"count\": " + std::to_string(blind)) !=
          std::string::npos);
  }
}

TEST_CASE("calibration health: outliers that share a sign are a systematic effect",
          "[calibration][health]") {
  // 50 of 1400 Earth-in crossings of head 1 (3.6 %) 0.1 deg late (10 times the noise): each
  // chord 0.1 deg short and each phase 0.05 deg ahead.
  std::vector<cal::observation> data = cal::simulate_observations(
      cal::synthetic_model({}), cal::recovery_truth(), 0, 4, 1400, 0.01, 8, 0);
  std::size_t shifted = 0;
  for (cal::observation& o : data)
    if (o.sample.head == 0 && o.sample.row % 28 == 5) {
      o.chord_deg -= 0.1;
      o.phase_deg += 0.05;
      ++shifted;
    }
  REQUIRE(shifted == 50);
  static const cal::forward_model_of<cal::synthetic_model> model{cal::synthetic_model({})};
  const auto outcome = cal::fit({&model, cal::recovery_start(), data, {{0.01, 0}, {0.01, 0}}}, {});
  REQUIRE(outcome.ok());
  const cal::fit_result& r = std::get<cal::fit_result>(outcome.value());
  const std::string table = cal::fit_table(r);
  INFO(table);
  CHECK(r.outlier_count == 50);
  REQUIRE(r.systematic.size() == 2);
  CHECK(r.systematic[0].head == 0);
  CHECK_FALSE(r.systematic[0].phase);
  CHECK(r.systematic[0].sign == -1);
  CHECK(r.systematic[0].same_sign == 50);
  CHECK(r.systematic[0].mean_residual_deg == Approx(-0.1).margin(0.01));
  CHECK(r.systematic[0].probability == Approx(std::ldexp(1.0, -49)).epsilon(1e-9));
  CHECK(r.systematic[1].phase);
  CHECK(r.systematic[1].sign == 1);
  CHECK(r.systematic[1].mean_residual_deg == Approx(0.05).margin(0.005));
  CHECK(table.find("systematic: h1 chord residuals of 50 of 50 outliers negative") !=
        std::string::npos);
  REQUIRE(r.warnings.size() == 2);
  CHECK_THAT(r.warnings[0], Catch::Matchers::Contains(
                                "50 of its 50 outliers have a negative chord residual (mean -0.0"));
  CHECK_THAT(r.warnings[0], Catch::Matchers::EndsWith(
                                "a systematic effect the model does not describe, not noise"));
  const std::string json = cal::fit_json(r);
  CHECK(json.find("{\"head\": 1, \"residual\": \"chord\", \"outliers\": 50, \"same_sign\": 50, "
                  "\"sign\": -1") != std::string::npos);
  const auto read = cal::read_fit_json(json, "fit.json");
  REQUIRE(read.ok());
  CHECK(cal::fit_json(read.value()) == json);
  // Noise alone: outliers of either sign, no effect. Two crossings of each sign.
  std::vector<cal::observation> clean = cal::simulate_observations(
      cal::synthetic_model({}), cal::recovery_truth(), 0, 4, 1400, 0.01, 8, 0);
  for (std::size_t i : {100, 300, 500, 700}) clean[i].chord_deg += i % 200 == 100 ? 0.2 : -0.2;
  const auto mixed = cal::fit({&model, cal::recovery_start(), clean, {{0.01, 0}, {0.01, 0}}}, {});
  REQUIRE(mixed.ok());
  CHECK(std::get<cal::fit_result>(mixed.value()).outlier_count == 4);
  CHECK(std::get<cal::fit_result>(mixed.value()).systematic.empty());
}

TEST_CASE("calibration health: random telemetry warns", "[calibration][health]") {
  // Chords uniform in (1, 359) deg and phases in [-180, 180) deg from a fixed generator: nothing
  // the scan model describes. Whatever the fit converges to, the residuals are 10^4 times the
  // declared noise, and it says so.
  cal::telemetry data = recovery_telemetry();
  std::uint64_t state = 12345;
  auto uniform = [&] {  // a 64-bit LCG (Knuth's MMIX constants); the top 53 bits
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (cal::observation& o : data.observations) {
    o.chord_deg = 1 + 358 * uniform();
    o.phase_deg = -180 + 360 * uniform();
  }
  const cal::fit_result r = fit_scene(recovery_start("sigma=0"), data, "horizon-km");
  const std::string table = cal::fit_table(r);
  INFO(table);
  REQUIRE(r.warnings.size() >= 2);
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(r.noise[k].ratio > 1000);
    CHECK_THAT(r.warnings[k],
               Catch::Matchers::StartsWith("h" + std::to_string(k + 1) + ": its residuals show "));
  }
  CHECK(table.find("warning: h1: its residuals show") != std::string::npos);
}

TEST_CASE("calibration health: an estimate outside its parameter's domain warns",
          "[calibration][health]") {
  // Head 1's sigma alone free along a held phi_A of 240 deg, opposite the truth's 60: the signed
  // sigma comes out negative (-0.1 deg: it also absorbs the held dgamma and horizon), which the
  // scene's own checks refuse (sigma in [0, gamma)).
  const cal::fit_result r =
      fit_scene(recovery_start("sigma=0,phase=240"), recovery_telemetry(), "h1.sigma");
  INFO(cal::fit_table(r));
  const cal::parameter_estimate& sigma = r.uncertainty.parameters[0];
  REQUIRE(sigma.determined);
  CHECK(sigma.estimate < -0.04);
  REQUIRE_FALSE(r.warnings.empty());
  CHECK_THAT(r.warnings.back(), Catch::Matchers::StartsWith("h1.sigma = -0."));
  CHECK_THAT(r.warnings.back(), Catch::Matchers::Contains("deg leaves the parameter's domain: "));
  CHECK_THAT(r.warnings.back(), Catch::Matchers::Contains("sigma"));
  CHECK(cal::fit_json(r).find("leaves the parameter's domain") != std::string::npos);
  // The same fit along the truth's phi_A: inside the domain, no such warning.
  const cal::fit_result along =
      fit_scene(recovery_start("sigma=0,phase=60"), recovery_telemetry(), "h1.sigma");
  for (const std::string& w : along.warnings)
    CHECK(w.find("leaves the parameter's domain") == std::string::npos);
}
