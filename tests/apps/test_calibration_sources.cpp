// The calibration on the scene's own sources: conescan-fit on telemetry that
// conescan-sim simulated from an OEM orbit with an AEM or attitude-CSV attitude history recovers
// the misalignment within 3 sigma; the reference attitude is the scene's attitude source (a fit
// that drops it shows residuals far above the declared noise, and warns); telemetry outside a
// source's usable span is refused with exit 2 naming the telemetry's file and line and the span;
// scene_truth_at reads the sources for the telemetry's span, not the scene's --duration-s.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "calibration/fit_json.hpp"
#include "scene_calibration/scene_geometry.hpp"
#include "simulation/truth_source.hpp"
#include "support/cli.hpp"
#include "support/diagnostic_of.hpp"

namespace cal = conescan::calibration;
using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::temp_file;

namespace {

const std::string data = CONESCAN_TEST_DATA;
// tests/data/ccsds/README.md: the paper's orbit over 6 h (2000-01-01T12:00 to 18:00 UTC, every
// 60 s, HERMITE 7) and its nadir pointing with wobble.csv's roll/pitch wobble (0.5 and 0.3 deg).
const std::string oem = " --oem " + data + "/ccsds/paper-orbit.oem";
// Both attitudes are coarser than the 1e-6 deg the angles need (the wobble sampled every 60 s:
// 1.1e-4 deg as the AEM's LAGRANGE 7, 0.024 deg as the table's lines), accepted with the escape.
const std::string coarse = " --interpolation-tolerance-deg 0.05";
const std::string aem = " --aem " + data + "/ccsds/paper-orbit-wobble.aem" + coarse;
const std::string attitude_csv = " --attitude-csv " + data + "/attitude/wobble.csv" + coarse;
const std::string span = " --model scan --step-s 30 --duration-s 21600";
const std::string truth_heads =
    " --head sigma=0.05,phase=60,dgamma=0.02,noise=0.01"
    " --head beta=-90,sigma=0.03,phase=200,dgamma=-0.01,noise=0.01";
const std::string start_heads = " --head noise=0.01 --head beta=-90,noise=0.01";
const std::string free_all = " --free h1.sigma,h1.phase,h1.dgamma,h2.sigma,h2.phase,h2.dgamma";

conescan_test::run_result run_fit(const std::string& args) {
  return run_program(CONESCAN_FIT_PATH, args);
}

// Truth minus estimate, angles wrapped to (-180, 180].
double error_of(const std::string& name, double estimate, double truth) {
  double d = estimate - truth;
  if (name.find("phase") != std::string::npos) d = std::remainder(d, 360.0);
  return d;
}

// Fits `telemetry` with the scene `sources` and checks every freed parameter within 3 sigma.
void check_recovery(const std::string& telemetry_csv, const std::string& sources) {
  const temp_file tm(telemetry_csv, ".csv");
  const auto r =
      run_fit("--telemetry " + tm.path + span + sources + start_heads + free_all + " --json");
  INFO(r.err << r.out);
  REQUIRE(r.exit_status == 0);
  const auto fit = cal::read_fit_json(r.out, "stdout");
  REQUIRE(fit.ok());
  // Each head's sigma, phi_A and dgamma (its other parameters held).
  const double truth[2][3] = {{0.05, 60, 0.02}, {0.03, 200, -0.01}};
  int freed = 0;
  for (std::size_t i = 0; i < 2 * cal::head_parameter_count; ++i) {
    const auto& p = fit.value().uncertainty.parameters[i];
    if (!(p.sigma > 0)) continue;  // held
    ++freed;
    REQUIRE(i % cal::head_parameter_count < 3);
    const double t = truth[i / cal::head_parameter_count][i % cal::head_parameter_count];
    INFO(p.name << " = " << p.estimate << " +- " << p.sigma << ", truth " << t);
    CHECK(std::abs(error_of(p.name, p.estimate, t)) < 3 * p.sigma);
  }
  CHECK(freed == 6);
  CHECK(fit.value().chi2_dof < 1.2);
}

void check_refused(const conescan_test::run_result& r, const std::string& named) {
  INFO("stderr: " << r.err);
  CHECK(r.exit_status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find(named) != std::string::npos);
}

const std::string& oem_aem_telemetry() {
  static const std::string csv = run_sim(span + oem + aem + truth_heads + " --seed 11").out;
  return csv;
}

}  // namespace

TEST_CASE("conescan-fit recovers the misalignment on an OEM orbit with an AEM attitude",
          "[cli][fit][sources]") {
  REQUIRE(oem_aem_telemetry().size() > 1000);
  check_recovery(oem_aem_telemetry(), oem + aem);
}

TEST_CASE("conescan-fit recovers the misalignment with an attitude CSV history",
          "[cli][fit][sources]") {
  const std::string csv = run_sim(span + oem + attitude_csv + truth_heads + " --seed 12").out;
  REQUIRE(csv.size() > 1000);
  check_recovery(csv, oem + attitude_csv);
}

TEST_CASE("conescan-fit: the reference attitude is the scene's attitude source",
          "[cli][fit][sources]") {
  // The same telemetry fitted as if the satellite pointed at nadir throughout: the 0.5 deg wobble
  // is 50 times the crossing noise, nothing the misalignment can absorb. The residuals' noise
  // (estimated from them, as the weights are) is far above the declared, and the fit says so.
  const temp_file tm(oem_aem_telemetry(), ".csv");
  const auto r = run_fit("--telemetry " + tm.path + span + oem + start_heads + free_all +
                         " --loss none --json");
  INFO(r.err);
  REQUIRE(r.exit_status == 0);
  const auto fit = cal::read_fit_json(r.out, "stdout");
  REQUIRE(fit.ok());
  REQUIRE(fit.value().noise.size() == 2);
  for (const cal::head_noise_estimate& n : fit.value().noise) CHECK(n.ratio > 10);
  REQUIRE(fit.value().warnings.size() >= 2);
  CHECK_THAT(fit.value().warnings[0], Catch::Matchers::StartsWith("h1: its residuals show "));
}

TEST_CASE("conescan-fit: telemetry outside the scene's span is refused, whatever its sources",
          "[cli][fit][sources]") {
  // The last row moved 30 s past the scene's end (21600 s, the OEM's and AEM's end too): line 723
  // of the file (header, then 721 rows at 0, 30, ..., 21600 s, then the moved copy). The row is
  // refused as outside the scene's span (the third audit, docs/RELIABILITY.md) before any
  // source is asked for its time: the scene's own span lies within its sources' (checked when
  // the scene is planned), so a source's span is never the first to be passed.
  const std::string& csv = oem_aem_telemetry();
  const std::size_t last_line = csv.rfind('\n', csv.size() - 2) + 1;
  std::string moved = csv.substr(last_line);
  const std::string seed_and_t = "11,21600,";
  REQUIRE(moved.rfind(seed_and_t, 0) == 0);
  moved.replace(0, seed_and_t.size(), "11,21630,");
  const temp_file past(csv + moved, ".csv");
  const std::string fit_args = span + start_heads + " --free h1.sigma,h1.phase";
  const std::string outside =
      ":723:4: --telemetry: t_s = 21630 is outside the scene's span, t_s 0 to 21600 s "
      "(--duration-s)";
  for (const std::string& sources : {oem + aem, aem, attitude_csv}) {
    INFO(sources);
    check_refused(run_fit("--telemetry " + past.path + fit_args + sources), past.path + outside);
  }
  SECTION("the last row inside the span: accepted (the other side of the boundary)") {
    const temp_file inside(csv, ".csv");
    const auto r = run_fit("--telemetry " + inside.path + fit_args + oem + aem);
    INFO(r.err);
    CHECK(r.exit_status == 0);
  }
  SECTION("a time before the epoch, with a file source") {
    const temp_file before(
        "t_s,h1_chord_deg,h1_phase_deg,h2_chord_deg,h2_phase_deg\n"
        "-30,100,0,100,0\n0,100,0,100,0\n",
        ".csv");
    const auto r = run_fit("--telemetry " + before.path + fit_args + oem);
    check_refused(r, before.path + ":2:1: --telemetry: t_s = -30 is outside the scene's span");
  }
}

TEST_CASE("scene_truth_at: the sources are read for the telemetry's span",
          "[calibration][sources]") {
  // A scene of 600 s whose AEM the plan read for those 600 s only, asked for 6 h: the truth of
  // the scene made for 6 h.
  conescan::scene::scene_config short_config;
  short_config.oem_file = data + "/ccsds/paper-orbit.oem";
  short_config.aem_file = data + "/ccsds/paper-orbit-wobble.aem";
  short_config.interpolation_tolerance_deg = 0.05;  // the wobble's AEM: 1.1e-4 deg
  short_config.epoch_utc = "2000-01-01T12:00:00";
  short_config.duration_s = 600;
  conescan::scene::scene_config whole_config = short_config;
  whole_config.duration_s = 21600;
  const auto shortened = conescan::scene::load_scene(short_config);
  const auto whole = conescan::scene::load_scene(whole_config);
  REQUIRE(shortened.ok());
  REQUIRE(whole.ok());
  const double times[] = {0, 599, 600, 601, 10000, 21599, 21600};
  const auto got = cal::scene_truth_at(shortened.value(), times);
  INFO((got.ok() ? std::string() : got.error().text()));
  REQUIRE(got.ok());
  const conescan::scene::truth_source truth =
      conescan::scene::truth_source::of(whole.value()).value();
  for (std::size_t i = 0; i < std::size(times); ++i) {
    INFO("t_s = " << times[i]);
    const conescan::scene::truth_state t = truth.truth_at(times[i]);
    REQUIRE(t.ok);
    CHECK(got.value()[i].r_eci_m == t.r_eci_m);
    CHECK(got.value()[i].v_eci_m_s == t.v_eci_m_s);
    CHECK(got.value()[i].body_from_orbit == t.body_from_orbit);
  }
  // One second past the files' end: refused, naming the time's index (1-based) among the times.
  const double past[] = {0, 21600, 21601};
  const auto refused = cal::scene_truth_at(shortened.value(), past);
  REQUIRE(!refused.ok());
  CHECK(refused.error().option == "telemetry");
  CHECK(refused.error().where.line == 3);
  CHECK(refused.error().message.find("t_s = 21601: --oem: ") != std::string::npos);
}
