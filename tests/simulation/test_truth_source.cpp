// The scene's truth source (src/simulation/truth_source.hpp): the API other layers (the
// calibration's telemetry prediction) call gives exactly what the rows were computed from; the
// quaternion of a rotation matrix that --write-aem relies on.

#include <catch2/catch.hpp>
#include <random>

#include "conescan/orbital_frame.hpp"
#include "simulation/simulation.hpp"
#include "simulation/truth_source.hpp"
#include "sources/rotation.hpp"
#include "support/temp_file.hpp"

using conescan::checked;

using namespace conescan;
using namespace conescan::scene;

namespace {

const std::string data = CONESCAN_TEST_DATA;

loaded_scene loaded(const scene_config& s) {
  checked<loaded_scene> made = load_scene(s);
  INFO((made.ok() ? std::string() : made.error().message));
  REQUIRE(made.ok());
  return std::move(made).value();
}

}  // namespace

TEST_CASE("truth_at gives the states and attitude the rows were computed from",
          "[sources][truth]") {
  scene_config tle;
  tle.tle_file = data + "/tle/delta-1-deb.tle";
  scene_config oem_aem;
  oem_aem.oem_file = data + "/ccsds/paper-orbit.oem";
  oem_aem.aem_file = data + "/ccsds/paper-orbit-wobble.aem";
  oem_aem.interpolation_tolerance_deg = 0.05;  // the wobble's AEM: 1.1e-4 deg
  scene_config classical;                      // the paper's scene: the fast block path
  for (const scene_config& config : {tle, oem_aem, classical}) {
    const loaded_scene s = loaded(config);
    const simulation sim = simulation::of(s).value();
    const truth_source truth = truth_source::of(s).value();
    row r = sim.make_row();
    for (std::uint64_t k : {std::uint64_t{0}, std::uint64_t{137}, sim.rows() - 1}) {
      sim.compute(k, r);
      const truth_state t = truth.truth_at(static_cast<double>(k) * s.config.step_s);
      INFO("row " << k);
      REQUIRE(t.ok);
      CHECK(r.r_m == norm(t.r_eci_m));
      CHECK(r.true_anomaly_rad == t.true_anomaly_rad);
      // The row's error is sensed minus the truth's roll: the same nadir in body axes.
      const vec3<double> nadir_body = apply(t.body_from_orbit, vec3<double>(0, 0, 1));
      const roll_pitch<double> true_rp = roll_pitch_from_nadir(nadir_body);
      CHECK(std::abs(r.heads[0].roll_err_rad) < 1e-3);
      CHECK(std::abs(true_rp.roll) < 0.01);  // the wobble's 0.5 deg at most
    }
  }
  // The epoch: the TLE's, the OEM's first usable time, or 2000-01-01T12:00:00 UTC.
  CHECK(sources::format_utc(truth_source::of(loaded(tle)).value().epoch(), 3) ==
        "2006-06-25T19:46:43.980");
  CHECK(sources::format_utc(truth_source::of(loaded(oem_aem)).value().epoch(), 3) ==
        "2000-01-01T12:00:00.000");
  CHECK(sources::format_utc(truth_source::of(loaded(classical)).value().epoch(), 3) ==
        "2000-01-01T12:00:00.000");
  CHECK(truth_source::of(loaded(classical)).value().kepler_with_constant_attitude());
  CHECK_FALSE(truth_source::of(loaded(tle)).value().kepler_with_constant_attitude());
}

TEST_CASE("truth_at with a carried cursor: the same truth, a resonant orbit's far rows cheap",
          "[sources][truth]") {
  // XM-3 (SGP4-VER.TLE's 28626), a 24-hour resonant orbit: SDP4 integrates its resonance from
  // the epoch in 720-min steps, which the cursor carries from row to row (and the simulation
  // over the rows of one compute_rows call). 60 days at 1 h: every truth equal, bit for bit.
  const conescan_test::temp_file geo(
      "1 28626U 05008A   06176.46683397 -.00000205  00000-0  10000-3 0  2190\n"
      "2 28626   0.0019 286.9433 0000335  13.7918  55.6504  1.00270176  4891\n",
      ".tle");
  scene_config config;
  config.tle_file = geo.path;
  config.step_s = 3600;
  config.duration_s = 60 * 86400.0;
  const loaded_scene s = loaded(config);
  const truth_source truth = truth_source::of(s).value();
  const simulation sim = simulation::of(s).value();
  std::vector<row> rows(sim.rows(), sim.make_row());
  sim.compute_rows(0, rows.size(), rows.data());
  truth_source::cursor carried;
  for (std::uint64_t k = 0; k < sim.rows(); ++k) {
    const double t_s = static_cast<double>(k) * s.config.step_s;
    const truth_state fresh = truth.truth_at(t_s);
    const truth_state resumed = truth.truth_at(t_s, carried);
    INFO("row " << k);
    REQUIRE(fresh.ok);
    CHECK(resumed.r_eci_m == fresh.r_eci_m);
    CHECK(resumed.v_eci_m_s == fresh.v_eci_m_s);
    CHECK(resumed.true_anomaly_rad == fresh.true_anomaly_rad);
    CHECK(rows[k].r_m == norm(fresh.r_eci_m));
  }
  // Times that turn back restart from the epoch: still the same truth.
  CHECK(truth.truth_at(86400.0, carried).r_eci_m == truth.truth_at(86400.0).r_eci_m);
}

TEST_CASE("osculating_of: the Kepler orbit's own elements back", "[sources][truth]") {
  scene_config config;
  config.e = 0.3;
  config.argp_deg = 40;
  const loaded_scene s = loaded(config);
  const truth_source truth = truth_source::of(s).value();
  for (double t : {0.0, 1000.0, 3000.0, 5000.0}) {
    const truth_state st = truth.truth_at(t);
    const osculating_elements el = osculating_of(st.r_eci_m, st.v_eci_m_s);
    INFO("t = " << t);
    CHECK(el.a_m == Approx(7280e3).epsilon(1e-12));
    CHECK(el.e == Approx(0.3).epsilon(1e-11));
    CHECK(std::remainder(el.true_anomaly_rad - st.true_anomaly_rad, 2 * M_PI) ==
          Approx(0).margin(1e-11));
  }
}

TEST_CASE("quaternion_from_rotation_matrix inverts rotation_matrix", "[sources][truth]") {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0;
  for (int n = 0; n < 10000; ++n) {
    // Every branch: angles up to pi about random axes (near pi the trace is smallest).
    vec3<double> axis(u(rng), u(rng), u(rng));
    axis = axis / norm(axis);
    const double angle = M_PI * (n % 4 == 0 ? 1 - 1e-9 * std::abs(u(rng)) : std::abs(u(rng)));
    const sources::quaternion q = sources::quaternion_from_rotation_vector(axis * angle);
    const sources::quaternion back =
        sources::quaternion_from_rotation_matrix(sources::rotation_matrix(q));
    CHECK(back.w >= 0);
    worst = std::max(worst, sources::angle_between(q, back));
  }
  CHECK(worst < 1e-14);
}
