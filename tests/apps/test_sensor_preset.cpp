// --sensor-preset (src/scene/sensor_preset.hpp): what conical-15um sets, each value overridden,
// heads given with and without the preset's keys, its scene file read back to the same rows, and
// where it is refused. Scenes of a few rows: the physics on WGS84 costs tens of us a head-row.
#include <catch2/catch.hpp>
#include <string>

#include "support/cli.hpp"
#include "support/scene_of.hpp"

namespace sc = conescan::scene;
using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::scene_of;
using conescan_test::temp_file;

namespace {

using options = std::vector<std::pair<std::string, std::string>>;

options with_preset(options more) {
  more.insert(more.begin(), {"sensor-preset", "conical-15um"});
  return more;
}

}  // namespace

TEST_CASE("sensor preset: conical-15um's values", "[preset]") {
  const sc::scene_config s = scene_of(with_preset({})).config;
  CHECK(s.earth == sc::earth_model::wgs84);
  CHECK(s.model == sc::forward_model::scan);
  CHECK(s.processing_radius == sc::processing_radius_kind::local);
  // The CO2 horizon preset's figures.
  CHECK(s.horizon_km == 40);
  CHECK(s.horizon_pole_km == -13);
  CHECK(s.horizon_shift_km == 11.5);
  // conescan's defaults it keeps: the profile and the locator.
  CHECK(s.radiance_scale_km == 7);
  CHECK(s.radiance_offset_km == 0);
  REQUIRE(s.heads.size() == 2);
  for (const sc::head_config& h : s.heads) {
    CHECK(h.alpha_deg == 0);
    CHECK(h.gamma_deg == 45);
    CHECK(h.sigma_deg == 0.02);
    CHECK(h.noise_deg == 0.01);
    CHECK(h.fov_deg == 1.5);
    CHECK(h.shape == conescan::field_shape::square);
    CHECK(h.spin_hz == 1);
    CHECK(h.tau_ms == 1);
    CHECK(h.locator == conescan::locator_kind::normalised);
    CHECK(h.threshold == 0.5);
  }
  CHECK(s.heads[0].beta_deg == 90);
  CHECK(s.heads[0].phase_deg == 60);
  CHECK(s.heads[1].beta_deg == -90);
  CHECK(s.heads[1].phase_deg == 200);
}

TEST_CASE("sensor preset: every value it sets can be overridden", "[preset]") {
  const sc::scene_config s = scene_of(with_preset({{"earth", "sphere"},
                                                   {"horizon-km", "30"},
                                                   {"processing-radius", "equatorial"},
                                                   {"horizon-preset", "none"}}))
                                 .config;
  CHECK(s.earth == sc::earth_model::sphere);
  CHECK(s.horizon_km == 30);
  CHECK(s.horizon_pole_km == 0);  // no CO2 preset: nothing fills it in
  CHECK(s.processing_radius == sc::processing_radius_kind::equatorial);
  // Heads given replace the pair; each takes the preset's keys its spec does not give.
  const sc::scene_config h =
      scene_of(with_preset({{"head", "beta=90,sigma=0.05,fov=0.5"},
                            {"head", "beta=-90,tau-ms=0"},
                            {"head", "alpha=10,beta=0,spin-hz=2,tau-ms=0.5"}}))
          .config;
  REQUIRE(h.heads.size() == 3);
  CHECK(h.heads[0].sigma_deg == 0.05);
  CHECK(h.heads[0].fov_deg == 0.5);
  CHECK(h.heads[0].spin_hz == 1);
  CHECK(h.heads[0].tau_ms == 1);
  CHECK(h.heads[0].noise_deg == 0);  // the preset's heads, noise and all, were replaced
  CHECK(h.heads[1].fov_deg == 1.5);
  CHECK(h.heads[1].tau_ms == 0);
  CHECK(h.heads[2].spin_hz == 2);
  CHECK(h.heads[2].tau_ms == 0.5);
  // The model: the physics needs the scan model, so a bias model given is refused, naming it.
  const auto bias = run_sim("--sensor-preset conical-15um --model bias --duration-s 0");
  CHECK(bias.exit_status == 2);
  CHECK(bias.err.find("--model") != std::string::npos);
}

TEST_CASE("sensor preset: --print-config writes what it set, and reads back to the same rows",
          "[preset][cli]") {
  const std::string scene = "--sensor-preset conical-15um --duration-s 60 --step-s 20 ";
  const auto config = run_sim(scene + "--print-config");
  REQUIRE(config.exit_status == 0);
  for (const char* line : {"earth = \"wgs84\"", "model = \"scan\"", "horizon-preset = \"co2-15um\"",
                           "horizon-km = 40", "horizon-pole-km = -13", "horizon-shift-km = 11.5",
                           "processing-radius = \"local\"", "sensor-preset = \"conical-15um\"",
                           "fov = 1.5", "spin-hz = 1", "tau-ms = 1", "noise = 0.01", "phase = 200"})
    CHECK(config.out.find(std::string(line) + "\n") != std::string::npos);
  const temp_file file(config.out);
  const auto rows = run_sim(scene);
  const auto again = run_sim("--config " + file.path);
  REQUIRE(rows.exit_status == 0);
  CHECK(rows.out == again.out);
  CHECK(std::count(rows.out.begin(), rows.out.end(), '\n') == 5);
  // Not a word of the list: refused, listing them.
  const auto unknown = run_sim("--sensor-preset ces --duration-s 0");
  CHECK(unknown.exit_status == 2);
  CHECK(unknown.err.find("none, conical-15um") != std::string::npos);
  // conescan-fit: not its option (a fit's forward model has no physics).
  const auto fit = run_program(CONESCAN_FIT_PATH, "--sensor-preset conical-15um --predict");
  CHECK(fit.exit_status == 2);
  CHECK(fit.err.find("--sensor-preset: not an option of conescan-fit") != std::string::npos);
}
