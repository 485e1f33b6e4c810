// The full error budget: apparent horizon surface, detector noise and quantisation,
// per-source budget, horizon-vector processing, through the scene layer and the CLI.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "scene/budget.hpp"
#include "simulation/simulation.hpp"
#include "support/cli.hpp"

using namespace conescan;
using namespace conescan::scene;
using conescan_test::csv_table;
using conescan_test::parse_csv;
using conescan_test::run_sim;

namespace {

const double deg = pi<double>() / 180;

scene_config polar_scene() {
  scene_config s;
  s.e = 0;
  s.i_deg = 90;
  s.earth = earth_model::wgs84;
  s.model = forward_model::scan;
  s.horizon_km = 40;
  s.heads = {head_config{0, 90, 45, 0, 0}};
  return s;
}

row first_row_over(const scene_config& s, double fraction_of_orbit) {
  scene_config one = s;
  one.duration_s = fraction_of_orbit * orbital_period_s(load_scene(s).value());
  one.step_s = *one.duration_s > 0 ? *one.duration_s : 1;
  const simulation sim = simulation::of(one).value();
  row r = sim.make_row();
  sim.compute(sim.rows() - 1, r);
  return r;
}

}  // namespace

TEST_CASE("apparent horizon: a pole term of b - a turns the sphere into the inflated ellipsoid",
          "[budget][horizon]") {
  // With the geodetic flattening off the surface starts from a sphere of radius a + h0; a polar
  // term of (b - a) must give back MODEL §3's inflated ellipsoid (a + h0, b + h0).
  scene_config inflated = polar_scene();
  scene_config apparent = inflated;
  apparent.geodetic_flattening = false;
  apparent.horizon_pole_km = (6356752.314245179 - 6378137.0) / 1000;
  for (double fraction : {0.0, 0.1, 0.25}) {
    const row a = first_row_over(inflated, fraction), b = first_row_over(apparent, fraction);
    REQUIRE(a.heads[0].state == status::ok);
    CHECK(b.heads[0].chord_rad == Approx(a.heads[0].chord_rad).margin(1e-12));
    CHECK(b.heads[0].phase_rad == Approx(a.heads[0].phase_rad).margin(1e-12));
    CHECK(b.roll_err_rad == Approx(a.roll_err_rad).margin(1e-12));
  }
  // And with h_pole = h_shift = 0 the apparent surface is the inflated ellipsoid itself.
  scene_config zero = inflated;
  zero.horizon_shift_km = 0;
  zero.horizon_pole_km = 0;
  zero.sun_declination_deg = 20;
  CHECK(first_row_over(zero, 0.25).roll_err_rad == first_row_over(inflated, 0.25).roll_err_rad);
}

TEST_CASE("apparent horizon: a centre shift over the pole acts as a change of orbit radius",
          "[budget][horizon]") {
  // Over the north pole the shift moves the horizon surface's centre straight towards the
  // satellite by dz = h_shift sin(declination): the Earth looks as from r - dz. On the sphere
  // (flattening off) that changes rho by asin(R/(r - dz)) - asin(R/r), and Eq. (5) at a fixed
  // chord turns it into eta_s - eta = (sin rho / cos gamma) (rho_p - rho_true) at eta = 90 deg.
  scene_config sphere = polar_scene();
  sphere.geodetic_flattening = false;
  sphere.processing_radius = processing_radius_kind::equatorial;
  scene_config shifted = sphere;
  shifted.horizon_shift_km = 11.5;
  shifted.sun_declination_deg = 23.44;
  const row still = first_row_over(sphere, 0.25), moved = first_row_over(shifted, 0.25);
  REQUIRE(moved.heads[0].state == status::ok);
  CHECK(std::abs(still.heads[0].eta_err_rad) < 1e-12);  // the truth is the assumed sphere
  const double r = 7280e3, radius = 6378137.0 + 40e3, gamma = 45 * deg;
  const double dz = 11.5e3 * std::sin(23.44 * deg);
  const double rho = std::asin(radius / r), rho_true = std::asin(radius / (r - dz));
  const double predicted = std::sin(rho) / std::cos(gamma) * (rho - rho_true);
  CHECK(moved.heads[0].eta_err_rad == Approx(predicted).epsilon(0.02));
  // A northward shift seen from over the south pole moves the centre away: the opposite sign.
  const row south = first_row_over(shifted, 0.75);
  CHECK(south.heads[0].eta_err_rad * moved.heads[0].eta_err_rad < 0);
}

TEST_CASE("noise: a fixed seed reproduces the run exactly; another seed does not",
          "[budget][noise]") {
  const std::string args = "--step-s 600 --head noise=0.01,lsb=0.001";
  const auto a = run_sim(args + " --seed 7"), b = run_sim(args + " --seed 7"),
             c = run_sim(args + " --seed 8");
  REQUIRE(a.exit_status == 0);
  CHECK(a.out == b.out);
  CHECK(a.out != c.out);
  const csv_table t = parse_csv(a.out);
  CHECK(t.header.at(0) == "seed");  // the seed is echoed into the output
  CHECK(t.text(0, "seed") == "7");
}

TEST_CASE("noise: the chord's spread is sqrt(2) times the crossing noise", "[budget][noise]") {
  // Many runs of one instant: every run draws new crossing noise. The chord is the difference
  // of two independent crossings: sigma_W = sigma sqrt(2). The sample standard deviation of n
  // draws has a relative standard error of about 1/sqrt(2(n-1)) (4.5 % at n = 250): allow 4x.
  scene_config s;
  s.duration_s = 0;
  s.runs = 250;
  const double sigma_deg = 0.01;
  s.heads = {head_config{0, 90, 45, 0.02, 0, sigma_deg, 0}};
  const simulation sim = simulation::of(s).value();
  row r = sim.make_row();
  double sum = 0, sum2 = 0;
  for (std::uint64_t run = 0; run < s.runs; ++run) {
    sim.compute(0, r, run);
    REQUIRE(r.heads[0].state == status::ok);
    const double w = r.heads[0].chord_rad / deg;
    sum += w;
    sum2 += w * w;
  }
  const double n = static_cast<double>(s.runs);
  const double std_w = std::sqrt((sum2 - sum * sum / n) / (n - 1));
  CHECK(std_w == Approx(sigma_deg * std::sqrt(2.0)).epsilon(4 / std::sqrt(2 * (n - 1))));
  // The mean stays on the noiseless chord (142.2487 deg, tests/data/reference) within 4
  // sigma/sqrt(n).
  CHECK(sum / n == Approx(142.24871185850856).margin(4 * sigma_deg * std::sqrt(2.0 / n)));
}

TEST_CASE("quantisation: chord and phase land on the LSB grid", "[budget][quantisation]") {
  const double lsb = 0.01;
  const auto run = run_sim("--step-s 300 --model scan --head phase=90,lsb=0.01");
  REQUIRE(run.exit_status == 0);
  const csv_table t = parse_csv(run.out);
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    for (const char* column : {"h1_chord_deg", "h1_phase_deg"}) {
      const double v = t.number(k, column);
      CHECK(std::abs(v / lsb - std::round(v / lsb)) < 1e-9);
    }
  }
  // The quantised phase of phi_A = 90 deg is the rounded exact phase.
  const csv_table exact = parse_csv(run_sim("--step-s 300 --model scan --head phase=90").out);
  CHECK(t.number(0, "h1_phase_deg") ==
        Approx(lsb * std::round(exact.number(0, "h1_phase_deg") / lsb)).margin(1e-12));
}

TEST_CASE("budget: each source alone equals a normal run with only that source on", "[budget]") {
  scene_config all = polar_scene();
  all.heads = {head_config{0, 90, 45, 0.03, 60, 0, 0}, head_config{0, 0, 45, 0.02, 200, 0, 0}};
  all.horizon_pole_km = -13;
  all.horizon_shift_km = 11.5;
  all.sun_declination_deg = 10;
  all.step_s = 600;
  const std::vector<budget_source> sources = budget_sources(load_scene(all).value()).value();
  std::vector<std::string> names;
  for (const budget_source& s : sources) names.push_back(s.name);
  CHECK(names == std::vector<std::string>{"misalignment", "oblateness", "horizon-pole",
                                          "horizon-season", "all"});
  // misalignment alone = the scan model on the processing's sphere with sigma on.
  scene_config misalignment;
  misalignment.e = 0;
  misalignment.i_deg = 90;
  misalignment.model = forward_model::scan;
  misalignment.horizon_km = 40;
  misalignment.step_s = 600;
  misalignment.heads = {head_config{0, 90, 45, 0.03, 60}, head_config{0, 0, 45, 0.02, 200}};
  const simulation expected = simulation::of(misalignment).value();
  const simulation budget = simulation::of(sources[0].scene).value();
  row re = expected.make_row(), rb = budget.make_row();
  for (std::uint64_t k = 0; k < expected.rows(); ++k) {
    expected.compute(k, re);
    budget.compute(k, rb);
    CHECK(rb.roll_err_rad == re.roll_err_rad);
    CHECK(rb.pitch_err_rad == re.pitch_err_rad);
  }
  // oblateness alone = WGS84 with the horizon, sigma 0.
  scene_config oblate = polar_scene();
  oblate.step_s = 600;
  oblate.heads = {head_config{0, 90, 45, 0, 60}, head_config{0, 0, 45, 0, 200}};
  const simulation expected_oblate = simulation::of(oblate).value();
  const simulation budget_oblate = simulation::of(sources[1].scene).value();
  expected_oblate.compute(3, re);
  budget_oblate.compute(3, rb);
  CHECK(rb.roll_err_rad == re.roll_err_rad);

  // Linearity: the sources are small, so the single-source errors add up to the total within
  // the second-order terms (products of 0.5 deg-size errors: ~1e-2 of them).
  std::vector<simulation> sims;
  for (const budget_source& s : sources) sims.push_back(simulation::of(s.scene).value());
  std::vector<row> rows;
  for (const simulation& s : sims) rows.push_back(s.make_row());
  double worst = 0, largest = 0;
  for (std::uint64_t k = 0; k < sims[0].rows(); ++k) {
    double roll_sum = 0;
    for (std::size_t i = 0; i < sims.size(); ++i) {
      sims[i].compute(k, rows[i]);
      if (i + 1 < sims.size()) roll_sum += rows[i].roll_err_rad;
    }
    worst = std::max(worst, std::abs(roll_sum - rows.back().roll_err_rad));
    largest = std::max(largest, std::abs(rows.back().roll_err_rad));
  }
  INFO("largest roll error " << largest / deg << " deg, worst non-additivity " << worst / deg);
  CHECK(largest > 0.05 * deg);
  CHECK(worst < 0.05 * largest);
}

TEST_CASE("budget: the CLI's table has every source, the sum and all", "[budget][cli]") {
  const auto run = run_sim(
      "--earth wgs84 --horizon-preset co2-15um --date 2026-06-21 --head "
      "phase=60,noise=0.01,lsb=0.005 "
      "--step-s 600 --budget --summary");
  INFO(run.err);
  REQUIRE(run.exit_status == 0);
  const csv_table t = parse_csv(run.out);
  std::vector<std::string> sources;
  for (std::size_t k = 0; k < t.rows.size(); ++k) sources.push_back(t.text(k, "source"));
  CHECK(sources == std::vector<std::string>{"misalignment", "oblateness", "horizon-pole",
                                            "horizon-season", "noise", "quantisation", "all", "sum",
                                            "interaction"});
  // Oblateness dominates the misalignment, as the paper says (Concluding remarks).
  CHECK(std::abs(t.number(1, "roll_rms_deg")) > 5 * std::abs(t.number(0, "roll_rms_deg")));
  // The bad combinations are refused with the option named.
  for (const char* bad : {"--budget --sweep e=0:0.1:0.05", "--budget --runs 3",
                          "--horizon-preset co2-15um --date 2026-06-21",
                          "--earth wgs84 --model scan --horizon-shift-km 5 --date 2026-02-30",
                          "--horizon-preset stratosphere"}) {
    const auto r = run_sim(bad);
    INFO(bad << ": " << r.err);
    CHECK(r.exit_status == 2);
    CHECK(r.out.empty());
  }
  // Without --date the season term takes the Sun's declination at each row's time (MODEL §10).
  CHECK(
      run_sim("--earth wgs84 --model scan --horizon-preset co2-15um --duration-s 0").exit_status ==
      0);
}

namespace {

// A CO2 limb the processing models (its 50 % point 40 km up, the processing
// assuming a 40 km horizon), one head with a 1.5 deg field and 1 ms of lag at 1 rev/s; seven
// rows (a physics row costs milliseconds).
const std::string co2_limb =
    "--model scan --radiance-offset-km 40 --processing-horizon-km 40 --duration-s 3600 "
    "--step-s 600";

csv_table budget_rows(const std::string& args) {
  const auto run = run_sim(args + " --budget");
  INFO(args << "\n" << run.err);
  REQUIRE(run.exit_status == 0);
  return parse_csv(run.out);
}

csv_table scene_rows(const std::string& args) {
  const auto run = run_sim(args);
  INFO(args << "\n" << run.err);
  REQUIRE(run.exit_status == 0);
  return parse_csv(run.out);
}

}  // namespace

TEST_CASE("budget with physics: each source on the user's limb, the limb one source",
          "[budget][physics]") {
  const csv_table t = budget_rows(co2_limb + " --head sigma=0,fov=1.5,spin-hz=1,tau-ms=1");
  const std::vector<std::string> singles{"horizon-height", "field-of-view", "detector-lag"};
  for (const std::string& source : singles)
    CHECK(std::count(t.header.begin(), t.header.end(), source + "_roll_err_deg") == 1);
  CHECK(std::count(t.header.begin(), t.header.end(), "radiance_roll_err_deg") == 0);
  // The field and the lag alone on the same limb: the budget's sources are these scenes less
  // the limb's own error (the horizon-height source: a pencil on the 40 km limb the processing
  // assumes, within 1e-9 deg of it), so within 1e-8 deg of them. They ran at delta50 = 0 before:
  // the field reported 0.21 deg of roll where alone it gives 0.071.
  const csv_table field = scene_rows(co2_limb + " --head sigma=0,fov=1.5");
  const csv_table lag = scene_rows(co2_limb + " --head sigma=0,spin-hz=1,tau-ms=1");
  REQUIRE(field.rows.size() == t.rows.size());
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    CHECK(std::abs(t.number(r, "horizon-height_roll_err_deg")) < 1e-8);
    for (const char* axis : {"roll", "pitch"}) {
      const std::string column = std::string(axis) + "_err_deg";
      CHECK(t.number(r, "field-of-view_" + column) == Approx(field.number(r, column)).margin(1e-8));
      CHECK(t.number(r, "detector-lag_" + column) == Approx(lag.number(r, column)).margin(1e-8));
    }
  }
  CHECK(t.number(0, "field-of-view_roll_err_deg") > 0.01);
  CHECK(t.number(0, "detector-lag_pitch_err_deg") < -0.2);
  // No pair of sources cancels: the single sources' errors have one sign per row and axis (the
  // limb's height and its radiance, as two sources, were -2.2 and +2.3 deg of roll), so the sum
  // of their sizes is the size of their sum.
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    for (const char* axis : {"roll", "pitch"}) {
      double sizes = 0;
      for (const std::string& source : singles)
        sizes += std::abs(t.number(r, source + "_" + axis + "_err_deg"));
      CHECK(sizes <= std::abs(t.number(r, std::string("sum_") + axis + "_err_deg")) + 1e-8);
    }
  // The limb's height and its radiance are one source: the 50 % point 40 km above the surface
  // with the processing at the surface is the geometric 40 km horizon it does not model.
  const std::string unmodelled = "--model scan --duration-s 3600 --step-s 600 --head sigma=0,fov=1";
  const csv_table radiance = budget_rows(unmodelled + " --radiance-offset-km 40");
  const csv_table height = budget_rows(unmodelled + " --horizon-km 40 --processing-horizon-km 0");
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    CHECK(radiance.number(r, "horizon-height_roll_err_deg") ==
          Approx(height.number(r, "horizon-height_roll_err_deg")).margin(1e-8));
    CHECK(std::abs(radiance.number(r, "horizon-height_roll_err_deg")) > 0.5);
  }
}

TEST_CASE("budget with physics: the interaction is all - sum, the field and the lag's coupling",
          "[budget][physics]") {
  // The field and the lag act on the same limb: the lag delays the field's smoothed pulse more
  // than the pencil's (the phase, pitch: -0.35 deg together against -0.29 to -0.33 deg alone),
  // so `all` is not the sum of the two, and the budget says by how much.
  const csv_table t = budget_rows(co2_limb + " --head sigma=0,fov=1.5,spin-hz=1,tau-ms=1");
  double largest = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    CHECK(t.text(r, "interaction_status") == "ok");
    for (const char* axis : {"roll", "pitch"}) {
      const std::string column = std::string(axis) + "_err_deg";
      const double all = t.number(r, "all_" + column), sum = t.number(r, "sum_" + column);
      CHECK(t.number(r, "interaction_" + column) == Approx(all - sum).margin(1e-12));
      largest = std::max(largest, std::abs(all - sum));
    }
  }
  CHECK(largest > 0.01);
  // The summary's last lines: all, sum, interaction.
  const auto summary = run_sim(co2_limb +
                               " --head sigma=0,fov=1.5,spin-hz=1,tau-ms=1 --budget "
                               "--summary");
  REQUIRE(summary.exit_status == 0);
  const csv_table lines = parse_csv(summary.out);
  REQUIRE(lines.rows.size() == 6);
  CHECK(lines.text(3, "source") == "all");
  CHECK(lines.text(4, "source") == "sum");
  CHECK(lines.text(5, "source") == "interaction");
  CHECK(lines.number(5, "ok") == 7);
  // Without any source on, nothing is added: a scene with only noise has no interaction.
  const csv_table noise = budget_rows("--step-s 600 --head sigma=0,noise=0.01");
  for (std::size_t r = 0; r < noise.rows.size(); ++r)
    CHECK(noise.number(r, "interaction_roll_err_deg") == Approx(0).margin(1e-15));
}

TEST_CASE("horizon-vector processing equals the chord/phase inversion for one head",
          "[budget][horizon_vector]") {
  // One head, no noise, a sphere: two crossings determine the nadir up to the mirror ambiguity,
  // which the seed from the chord/phase solution resolves, so both processings agree.
  for (double phase : {0.0, 90.0, 200.0}) {
    scene_config s;
    s.model = forward_model::scan;
    s.step_s = 700;
    s.heads = {head_config{10, 60, 45, 0.05, phase}};
    scene_config hv = s;
    hv.processing = processing_method::horizon_vector;
    const simulation a = simulation::of(s).value();
    const simulation b = simulation::of(hv).value();
    row ra = a.make_row(), rb = b.make_row();
    for (std::uint64_t k = 0; k < a.rows(); ++k) {
      a.compute(k, ra);
      b.compute(k, rb);
      REQUIRE(rb.state == status::ok);
      CHECK(rb.roll_err_rad == Approx(ra.roll_err_rad).margin(1e-12));
      CHECK(rb.pitch_err_rad == Approx(ra.pitch_err_rad).margin(1e-12));
    }
  }
}
