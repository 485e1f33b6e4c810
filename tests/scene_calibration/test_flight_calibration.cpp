// The calibration on board against conescan-sim --apply, bit for bit, on the README's calibrated
// scene: the C interface (conescan_correct_d, conescan/conescan.h) with the constants that
// scripts/fit-header.py wrote from examples/flight_software/fit.json (its calibration.h), at the
// rows' true geometry, corrects every measurement exactly as the CLI's correction
// (src/scene_calibration/fit_correction.cpp) reading the same file. Both call the core's rule
// (conescan/head_calibration.hpp); what this checks is everything around it: the header's
// decimals, the interface's conversions, the head built from the mounting, the geometry.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "conescan/attitude.hpp"
#include "conescan/c_interface.hpp"
#include "conescan/conescan.h"
#include "scene/degrees.hpp"
#include "scene_calibration/fit_correction.hpp"
#include "scene_calibration/scene_geometry.hpp"
#include "support/scene_of.hpp"
#define CONESCAN_FIT_SCALAR double
#include "../examples/flight_software/calibration.h"

namespace sc = conescan::scene;
using conescan_test::scene_of;

namespace {

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("flight calibration: conescan_correct_d equals conescan-sim --apply bit for bit",
          "[flight][calibration][apply]") {
  // The README's --apply command: its scene, the fit of examples/flight_software/fit.json.
  const sc::loaded_scene scene = scene_of({{"model", "scan"},
                                           {"step-s", "10"},
                                           {"duration-s", "21600"},
                                           {"horizon-km", "42"},
                                           {"head", "sigma=0.05,phase=60"},
                                           {"head", "beta=-90,sigma=0.03,phase=200"}});
  auto cli =
      sc::fit_correction::of(scene, CONESCAN_TEST_DATA "/../../examples/flight_software/fit.json");
  INFO((cli.ok() ? std::string() : cli.error().text()));
  REQUIRE(cli.ok());

  // Flight code's side: the heads from their mountings (rad, as the scene's model converts
  // them), the calibration from the generated header.
  conescan_head_d heads[CONESCAN_FIT_HEAD_COUNT];
  REQUIRE(scene.config.heads.size() == CONESCAN_FIT_HEAD_COUNT);
  for (std::size_t k = 0; k < scene.config.heads.size(); ++k) {
    const sc::head_config& h = scene.config.heads[k];
    const conescan_head_config_d config{conescan::deg_to_rad(h.alpha_deg),
                                        sc::deg_to_rad_reduced(h.beta_deg),
                                        conescan::deg_to_rad(h.gamma_deg),
                                        0,
                                        0,
                                        conescan::deg_to_rad(10.0)};
    REQUIRE(conescan_head_init_d(&heads[k], &config) == CONESCAN_OK);
  }
  const conescan_calibration_d calibration[CONESCAN_FIT_HEAD_COUNT] = CONESCAN_FIT_CALIBRATION;

  std::vector<double> times;
  for (int k = 0; k * 10 <= 21600; ++k) times.push_back(k * 10.0);
  std::vector<conescan::calibration::row_truth> truth(times.size());
  REQUIRE(conescan::calibration::scene_truth_each(
              scene, times, 1,
              [&](std::size_t i, const conescan::calibration::row_truth& t) { truth[i] = t; })
              .ok());

  int compared = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    // The geometry flight code would estimate, here the truth the CLI uses: the nadir in body
    // axes, the sphere of the fitted horizon seen from the orbit radius.
    const conescan::vec3<double> nadir =
        conescan::apply(truth[i].body_from_orbit, conescan::vec3<double>(0, 0, 1));
    const double nadir_body[3] = {nadir.x, nadir.y, nadir.z};
    const conescan_disk_d disk = conescan_disk_of_d(6378137.0 + CONESCAN_FIT_HORIZON_KM * 1000.0,
                                                    conescan::norm(truth[i].r_eci_m));
    for (std::size_t h = 0; h < scene.config.heads.size(); ++h) {
      // Any measurement: the correction is the same rule whatever it is.
      const double chord = 2.5 - 0.3 * static_cast<double>(h),
                   phase = 1e-3 * static_cast<double>(i);
      const conescan_crossings_d measured = conescan_crossings_of_d(chord, phase);
      const conescan_crossings_d flight =
          conescan_correct_d(&heads[h], &calibration[h], &measured, nadir_body, &disk);
      const conescan::crossings<double> expected = cli.value()->corrected(
          i, times[i], h, {measured.phi_in_rad, measured.phi_out_rad, conescan::status::ok, 0});
      INFO("row " << i << ", head " << h + 1);
      REQUIRE(flight.status == CONESCAN_OK);
      REQUIRE(expected.state == conescan::status::ok);
      CHECK(same_bits(flight.phi_in_rad, expected.phi_in));
      CHECK(same_bits(flight.phi_out_rad, expected.phi_out));
      // The correction did something: the measurement moved by the modelled errors.
      CHECK_FALSE(same_bits(flight.phi_in_rad, measured.phi_in_rad));
      ++compared;
    }
  }
  CHECK(compared == 2 * 2161);
}

TEST_CASE("flight calibration: the C interface's statuses and failures", "[flight][calibration]") {
  CHECK(std::string(conescan_status_name(CONESCAN_OK)) == "ok");
  CHECK(std::string(conescan_status_name(CONESCAN_NONE)) == "none");
  CHECK(conescan_status_name(static_cast<conescan_status>(CONESCAN_NONE + 1)) == nullptr);
  // A head outside its domain (gamma 90 deg) says invalid, and so does every call with it.
  conescan_head_f bad{};
  const conescan_head_config_f config{0, 1.5707964f, 1.5707964f, 0, 0, 0.17453292f};
  CHECK(conescan_head_init_f(&bad, &config) == CONESCAN_INVALID);
  const conescan_crossings_f measured = conescan_crossings_of_f(2.f, 0.f);
  const conescan_disk_f disk = conescan_disk_of_f(6378.f, 7000.f);
  CHECK(conescan_process_f(&bad, &measured, &disk).status == CONESCAN_INVALID);
  const conescan_calibration_f none{0, 0, 0, 0, 0};
  const float nadir[3] = {0, 0, 1};
  CHECK(conescan_correct_f(&bad, &none, &measured, nadir, &disk).status == CONESCAN_INVALID);
  // The disk of a satellite inside the sphere, and no head ok for the system solution.
  CHECK(conescan_disk_of_f(7000.f, 6378.f).status == CONESCAN_INVALID);
  const conescan_estimate_f failed[2] = {{{0, 0, 0}, 0, CONESCAN_GRAZING},
                                         {{0, 0, 0}, 0, CONESCAN_FOLD}};
  const conescan_estimate_f system = conescan_combine_f(failed, 2);
  CHECK(system.status == CONESCAN_NONE);
  CHECK(std::isnan(system.nadir[0]));
  CHECK(conescan_roll_pitch_f(&system).status == CONESCAN_NONE);
}

#include "../examples/flight_software/telemetry.hpp"

TEST_CASE("flight calibration: the first solution's nadir as the correction's geometry",
          "[flight][calibration]") {
  // The flight example's choice (docs/FLIGHT_SOFTWARE.md): the modelled errors at the nadir of
  // the sample's uncorrected solution rather than the true one (the scene's attitude is zero:
  // the true nadir is body +z). In double, over the example's 73 samples.
  using conescan::deg_to_rad;
  using conescan::rad_to_deg;
  using head = conescan::sensor_head<double>;
  const head heads[2] = {head::from_mounting(0.0, deg_to_rad(90.0), {deg_to_rad(45.0), 0, 0}),
                         head::from_mounting(0.0, deg_to_rad(-90.0), {deg_to_rad(45.0), 0, 0})};
  const conescan::head_calibration<double> calibration[2] = CONESCAN_FIT_CALIBRATION;
  double crossing_change_deg = 0, attitude_change_deg = 0, raw_error_deg = 0;
  for (const auto& row : telemetry_rows) {
    const auto assumed = conescan::disk_trig_of(6378.137 + 42, row[0]);
    const auto fitted = conescan::disk_trig_of(6378.137 + CONESCAN_FIT_HORIZON_KM, row[0]);
    conescan::crossings<double> measured[2];
    conescan::head_estimate<double> first[2], estimated[2], true_geometry[2];
    for (int k = 0; k < 2; ++k) {
      measured[k] = conescan::crossings<double>::from_chord_phase(deg_to_rad(row[1 + 2 * k]),
                                                                  deg_to_rad(row[2 + 2 * k]));
      first[k] = heads[k].process(measured[k], assumed);
    }
    const auto nadir = conescan::combine_heads<double>(first, first + 2);
    REQUIRE(nadir.state == conescan::status::ok);
    const auto raw = conescan::roll_pitch_from_nadir(nadir.nadir);
    raw_error_deg = std::fmax(
        raw_error_deg, std::fmax(std::abs(rad_to_deg(raw.roll)), std::abs(rad_to_deg(raw.pitch))));
    for (int k = 0; k < 2; ++k) {
      const double gamma = heads[k].optics().gamma;
      const auto at_estimate = conescan::calibrated_crossings(
          measured[k], gamma, calibration[k], heads[k].in_scan_frame(nadir.nadir), fitted);
      const auto at_truth = conescan::calibrated_crossings(
          measured[k], gamma, calibration[k],
          heads[k].in_scan_frame(conescan::vec3<double>(0, 0, 1)), fitted);
      crossing_change_deg =
          std::fmax(crossing_change_deg,
                    std::fmax(std::abs(rad_to_deg(at_estimate.phi_in - at_truth.phi_in)),
                              std::abs(rad_to_deg(at_estimate.phi_out - at_truth.phi_out))));
      estimated[k] = heads[k].process(at_estimate, assumed);
      true_geometry[k] = heads[k].process(at_truth, assumed);
    }
    const auto a = conescan::roll_pitch_from_nadir(
        conescan::combine_heads<double>(estimated, estimated + 2).nadir);
    const auto b = conescan::roll_pitch_from_nadir(
        conescan::combine_heads<double>(true_geometry, true_geometry + 2).nadir);
    attitude_change_deg = std::fmax(
        attitude_change_deg,
        std::fmax(std::abs(rad_to_deg(a.roll - b.roll)), std::abs(rad_to_deg(a.pitch - b.pitch))));
  }
  // Measured: the first solution 0.0226 deg off; the crossings' correction moves by 9.2e-5 deg
  // at most, the corrected roll and pitch by 1.0e-5 deg.
  CHECK(raw_error_deg > 0.02);
  CHECK(crossing_change_deg < 1e-4);
  CHECK(attitude_change_deg < 1.1e-5);
}
