// The calibration on real scenes: telemetry simulated by the scene layer with a known
// truth and fixed seeds (the same pipeline as conescan-sim's CSV, without the text), fitted with
// the real forward model (src/scene_calibration/scene_model.hpp). Recovery, honest uncertainty over
// 200 seeds, experiment design against the scatter, degeneracy, outliers, and the correction of
// conescan-sim --apply against the propagated uncertainty.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "calibration/fit_json.hpp"
#include "calibration/layout.hpp"
#include "calibration/report.hpp"
#include "scene/head_spec.hpp"
#include "scene/scene_plan.hpp"
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

cal::fit_result fit_converged(const sc::loaded_scene& start, const cal::telemetry& data,
                              const std::string& free, cal::fit_options options = {}) {
  const auto indices = cal::parse_free_list(free, start.config.heads.size());
  REQUIRE(indices.ok());
  const auto outcome = cal::fit_scene(start, data, indices.value(), options);
  INFO((outcome.ok() ? std::string() : outcome.error().text()));
  REQUIRE(outcome.ok());
  const auto* r = std::get_if<cal::fit_result>(&outcome.value());
  INFO(cal::fit_table(outcome.value()));
  REQUIRE(r != nullptr);
  return *r;
}

// The paper's orbit (e = 0.1) seen by two heads (beta = 90 and -90 deg) of the scan model; the
// heads' keys and the scene's further options given. `noise` on each head.
std::vector<std::pair<std::string, std::string>> two_head_scene(
    const std::string& head1, const std::string& head2,
    std::vector<std::pair<std::string, std::string>> more) {
  more.push_back({"model", "scan"});
  more.push_back({"head", "noise=0.01," + head1});
  more.push_back({"head", "beta=-90,noise=0.01," + head2});
  return more;
}

// The truth of the recovery: sigma 0.05 and 0.03 deg at phi_A 60 and 200 deg, and a
// cone-angle bias of 0.02 deg on head 1, the horizon at 42 km; the fit starts from sigma = 0,
// no bias and 40 km.
const std::string recovery_free = "h1.sigma,h1.phase,h1.dgamma,h2.sigma,h2.phase,horizon-km";
const double recovery_truth[] = {0.05, 60, 0.02, 0.03, -160, 42};  // in recovery_free's order

std::vector<std::size_t> free_indices(const std::string& free, std::size_t heads) {
  return cal::parse_free_list(free, heads).value();
}

// The recovery's truth and the fit's start over `time` (options), the truth's noise from `seed`.
struct recovery_scenes {
  sc::loaded_scene truth;
  sc::loaded_scene start;
};

recovery_scenes recovery_scenes_over(const std::vector<std::pair<std::string, std::string>>& time,
                                     const std::string& seed = "1") {
  auto truth = two_head_scene("sigma=0.05,phase=60,dgamma=0.02", "sigma=0.03,phase=200", time);
  truth.push_back({"horizon-km", "42"});
  truth.push_back({"seed", seed});
  auto start = two_head_scene("sigma=0", "sigma=0", time);
  start.push_back({"horizon-km", "40"});
  return {scene_of(truth), scene_of(start)};
}

double normalised_error(const cal::parameter_estimate& e, double truth) {
  return cal::wrap_deg(e.estimate - truth) / e.sigma;
}

}  // namespace

TEST_CASE("calibration scene: recovery on one day at 1 s, every parameter within 3 sigma",
          "[calibration][scene]") {
  const std::vector<std::pair<std::string, std::string>> time{{"step-s", "1"},
                                                              {"duration-s", "86400"}};
  const recovery_scenes scenes = recovery_scenes_over(time, "15");
  const cal::fit_result r =
      fit_converged(scenes.start, simulated_telemetry(scenes.truth, 0), recovery_free);
  INFO(cal::fit_table(r));
  const std::vector<std::size_t> free = free_indices(recovery_free, 2);
  for (std::size_t i = 0; i < free.size(); ++i) {
    const cal::parameter_estimate& e = r.uncertainty.parameters[free[i]];
    INFO(e.name << " " << e.estimate << " +- " << e.sigma << " truth " << recovery_truth[i]);
    REQUIRE(e.determined);
    CHECK(std::abs(normalised_error(e, recovery_truth[i])) < 3);
  }
  CHECK(r.uncertainty.unobservable.empty());
  CHECK(r.chi2_dof == Approx(1).margin(0.02));
  CHECK(r.residual_count == 2 * 2 * 86401);
}

TEST_CASE("calibration scene: the apparent ellipsoid's horizon terms and crossing biases",
          "[calibration][scene]") {
  // WGS84 with the apparent horizon (pole and season terms), three orbits at 10 s.
  const std::vector<std::pair<std::string, std::string>> common{{"earth", "wgs84"},
                                                                {"step-s", "10"},
                                                                {"orbits", "3"},
                                                                {"sun-declination-deg", "20"},
                                                                {"horizon-km", "40"}};
  auto truth_options = two_head_scene("sigma=0.05,phase=60,bias-in=0.01,bias-out=-0.02",
                                      "sigma=0.03,phase=200", common);
  truth_options.push_back({"horizon-pole-km", "-5"});
  truth_options.push_back({"horizon-shift-km", "3"});
  truth_options.push_back({"seed", "4"});
  auto start_options = two_head_scene("sigma=0", "sigma=0", common);
  const std::string free =
      "h1.sigma,h1.phase,h1.bias-in,h1.bias-out,h2.sigma,h2.phase,horizon-km,horizon-pole-km,"
      "horizon-shift-km";
  const double truth[] = {0.05, 60, 0.01, -0.02, 0.03, -160, 40, -5, 3};
  const cal::fit_result r =
      fit_converged(scene_of(start_options), simulated_telemetry(scene_of(truth_options), 0), free);
  INFO(cal::fit_table(r));
  const std::vector<std::size_t> indices = free_indices(free, 2);
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const cal::parameter_estimate& e = r.uncertainty.parameters[indices[i]];
    INFO(e.name);
    REQUIRE(e.determined);
    CHECK(std::abs(normalised_error(e, truth[i])) < 3);
  }
  CHECK(r.dropped_at_start == 0);
}

TEST_CASE("calibration scene: honest uncertainty over 200 seeds, and --predict's 1 sigma",
          "[calibration][scene][statistics][many-fits]") {
  // One orbit at 5 s per fit (1238 rows, 4952 residuals), not one day at 1 s: 200 fits of a day
  // would take minutes of CI. The statistics are those of the issue: per parameter the normalised
  // errors' mean and standard deviation, the 1 sigma intervals' coverage, and experiment
  // design's prediction against the estimates' scatter. Coverage: with 200 fits one parameter's
  // coverage has a binomial standard deviation of 3.3 %, so the 68 % +- 5 % is checked
  // on the 1200 intervals of all six parameters (1.35 %), and each parameter's within three of
  // its own standard deviations (+- 10 %). (At 10 s, h2.phase's mean normalised error was 0.24,
  // 3.4 standard errors: the linearisation's bias, which more data per fit shrinks.)
  const std::vector<std::pair<std::string, std::string>> time{{"step-s", "5"}, {"orbits", "1"}};
  const recovery_scenes scenes = recovery_scenes_over(time);
  const sc::loaded_scene& truth = scenes.truth;
  const sc::loaded_scene& start = scenes.start;
  const std::vector<std::size_t> free = free_indices(recovery_free, 2);
  constexpr int fits = 200;
  std::vector<std::vector<double>> z(free.size()), estimates(free.size());
  for (int run = 0; run < fits; ++run) {
    const cal::fit_result r = fit_converged(start, simulated_telemetry(truth, run), recovery_free);
    for (std::size_t i = 0; i < free.size(); ++i) {
      const cal::parameter_estimate& e = r.uncertainty.parameters[free[i]];
      REQUIRE(e.determined);
      z[i].push_back(normalised_error(e, recovery_truth[i]));
      estimates[i].push_back(recovery_truth[i] + cal::wrap_deg(e.estimate - recovery_truth[i]));
    }
  }
  // Experiment design at the truth (the Fisher information where the estimates scatter).
  const auto design = cal::predict_scene(truth, free);
  REQUIRE(design.ok());
  std::string summary;
  int covered_all = 0;
  for (std::size_t i = 0; i < free.size(); ++i) {
    const auto mean_std = [](const std::vector<double>& v) {
      double mean = 0, sq = 0;
      for (double x : v) mean += x;
      mean /= static_cast<double>(v.size());
      for (double x : v) sq += (x - mean) * (x - mean);
      return std::pair{mean, std::sqrt(sq / static_cast<double>(v.size() - 1))};
    };
    const auto [mean, std_dev] = mean_std(z[i]);
    const double covered =
        static_cast<double>(
            std::count_if(z[i].begin(), z[i].end(), [](double x) { return std::abs(x) <= 1; })) /
        fits;
    const double scatter = mean_std(estimates[i]).second;
    const double predicted = design.value().uncertainty.parameters[free[i]].sigma;
    const std::string name = design.value().uncertainty.parameters[free[i]].name;
    summary += name + ": mean " + cal::short_number(mean) + ", std " + cal::short_number(std_dev) +
               ", coverage " + cal::short_number(covered) + ", predicted 1 sigma " +
               cal::short_number(predicted) + ", scatter " + cal::short_number(scatter) + "\n";
    INFO(summary);
    CHECK(std::abs(mean) < 3 / std::sqrt(double(fits)));  // 3 standard errors of the mean
    CHECK(std::abs(std_dev - 1) < 0.1);
    CHECK(std::abs(covered - 0.68) <= 0.1);
    covered_all += static_cast<int>(std::lround(covered * fits));
    CHECK(std::abs(predicted / scatter - 1) < 0.15);
  }
  const double coverage = covered_all / (fits * static_cast<double>(free.size()));
  WARN("200 seeds, one orbit at 5 s each:\n" << summary << "coverage of all: " << coverage);
  CHECK(std::abs(coverage - 0.68) <= 0.05);
}

TEST_CASE("calibration scene: a circular orbit with one head cannot separate dgamma and h0",
          "[calibration][scene]") {
  const std::vector<std::pair<std::string, std::string>> scene{
      {"model", "scan"}, {"e", "0"}, {"step-s", "10"}, {"orbits", "1"}};
  auto truth_options = scene;
  truth_options.push_back({"head", "sigma=0,dgamma=0.02,noise=0.01"});
  auto start_options = scene;
  start_options.push_back({"head", "sigma=0,noise=0.01"});
  const cal::fit_result r =
      fit_converged(scene_of(start_options), simulated_telemetry(scene_of(truth_options), 0),
                    "h1.dgamma,horizon-km");
  REQUIRE(r.uncertainty.unobservable.size() == 1);
  const auto& combination = r.uncertainty.unobservable.front().components;
  REQUIRE(combination.size() == 2);
  std::vector<std::string> names{combination[0].first, combination[1].first};
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"h1.dgamma", "horizon-km"});
  // Both move the chord alike: equal weights (in units of their own 1 sigma), opposite signs.
  CHECK(std::abs(combination[0].second) == Approx(std::sqrt(0.5)).epsilon(1e-4));
  CHECK(combination[0].second * combination[1].second < 0);
  for (const char* name : {"h1.dgamma", "horizon-km"}) {
    const auto& p = r.uncertainty.parameters;
    const auto it = std::find_if(p.begin(), p.end(), [&](const auto& e) { return e.name == name; });
    REQUIRE(it != p.end());
    CHECK_FALSE(it->determined);  // never an estimate without its uncertainty
  }
  // The eccentric orbit separates them (the Earth's angular size changes along the orbit).
  auto eccentric = start_options;
  eccentric[1] = {"e", "0.1"};
  auto eccentric_truth = truth_options;
  eccentric_truth[1] = {"e", "0.1"};
  const cal::fit_result separated =
      fit_converged(scene_of(eccentric), simulated_telemetry(scene_of(eccentric_truth), 0),
                    "h1.dgamma,horizon-km");
  CHECK(separated.uncertainty.unobservable.empty());
}

TEST_CASE("calibration scene: 1 crossing in 1000 off by 1 deg, the robust loss holds",
          "[calibration][scene]") {
  const std::vector<std::pair<std::string, std::string>> time{{"step-s", "5"}, {"orbits", "1"}};
  const recovery_scenes scenes = recovery_scenes_over(time);
  const sc::loaded_scene& truth = scenes.truth;
  const sc::loaded_scene& start = scenes.start;
  // Every 500th measurement (row and head) has its Earth-in crossing 1 deg late: one crossing in
  // 1000 (chord -1 deg, phase +0.5 deg).
  std::size_t corrupted = 0, seen = 0;
  const cal::telemetry dirty =
      simulated_telemetry(truth, 0, [&](std::uint64_t, std::size_t, double& chord, double& phase) {
        if (++seen % 500 != 0) return;
        ++corrupted;
        chord -= 1;
        phase += 0.5;
      });
  const cal::fit_result clean = fit_converged(start, simulated_telemetry(truth, 0), recovery_free);
  const cal::fit_result robust = fit_converged(start, dirty, recovery_free);
  cal::fit_options plain_options;
  plain_options.loss = cal::robust_loss::none;
  const cal::fit_result plain = fit_converged(start, dirty, recovery_free, plain_options);
  INFO(cal::fit_table(robust));
  CHECK(robust.outlier_count == corrupted);  // reported, every one
  double plain_worst = 0;
  for (std::size_t i : free_indices(recovery_free, 2)) {
    const auto& c = clean.uncertainty.parameters[i];
    const double moved =
        cal::wrap_deg(robust.uncertainty.parameters[i].estimate - c.estimate) / c.sigma;
    INFO(c.name << " moved by " << moved << " sigma");
    CHECK(std::abs(moved) < 1);
    plain_worst = std::max(
        plain_worst,
        std::abs(cal::wrap_deg(plain.uncertainty.parameters[i].estimate - c.estimate) / c.sigma));
  }
  // Without the loss the same outliers pull an estimate by more than its 1 sigma.
  CHECK(plain_worst > 1);
}

TEST_CASE("calibration scene: --apply leaves errors below 3 sigma of the propagated uncertainty",
          "[calibration][scene][apply]") {
  const std::vector<std::pair<std::string, std::string>> time{{"step-s", "10"}, {"orbits", "1"}};
  const std::string truth_heads[] = {"sigma=0.05,phase=60", "sigma=0.03,phase=200"};
  const sc::loaded_scene truth = scene_of(two_head_scene(truth_heads[0], truth_heads[1], time));
  const sc::loaded_scene start = scene_of(two_head_scene("sigma=0", "sigma=0", time));
  const std::string free = "h1.sigma,h1.phase,h2.sigma,h2.phase";
  const cal::fit_result fit = fit_converged(start, simulated_telemetry(truth, 3), free);
  // The scene to correct: the truth without noise, so that what remains is the misalignment's
  // error left by the estimate's own error.
  std::vector<std::pair<std::string, std::string>> clean_options = time;
  clean_options.push_back({"model", "scan"});
  clean_options.push_back({"head", truth_heads[0]});
  clean_options.push_back({"head", "beta=-90," + truth_heads[1]});
  const sc::loaded_scene clean = scene_of(clean_options);
  // Roll and pitch errors (rad) of every row after the correction with `f`.
  auto corrected_errors = [&](const cal::fit_result& f) {
    const conescan_test::temp_file json(cal::fit_json(cal::fit_outcome(f)), ".json");
    auto correction = sc::fit_correction::of(clean, json.path);
    REQUIRE(correction.ok());
    sc::simulation sim = sc::simulation::of(clean).value();
    sim.set_correction(correction.value().get());
    std::vector<double> out;
    sc::row row = sim.make_row();
    for (std::uint64_t k = 0; k < sim.rows(); ++k) {
      sim.compute(k, row);
      REQUIRE(row.state == conescan::status::ok);
      out.push_back(row.roll_err_rad);
      out.push_back(row.pitch_err_rad);
    }
    return out;
  };
  const std::vector<double> after = corrected_errors(fit);
  // Propagated 1 sigma of each error: its derivatives with respect to the estimated coordinates
  // (central differences of the correction itself) through their covariance.
  const auto& u = fit.uncertainty;
  const std::size_t n = u.coordinate_values.size();
  std::vector<std::vector<double>> gradient(n);
  // A coordinate moved by `delta`, and the parameters' estimates with it (--apply refuses a fit
  // whose two blocks disagree): sigma and phase from a misalignment's x and y.
  const auto moved = [&](std::size_t c, double delta) {
    cal::fit_result f = fit;
    cal::uncertainty_report& r = f.uncertainty;
    r.coordinate_values[c] += delta;
    const std::size_t head = r.coordinate_keys[c].slot / cal::head_parameter_count;
    double x = 0, y = 0;
    if (const auto i = cal::find_coordinate(r, head, cal::misalignment_axis::x))
      x = r.coordinate_values[*i];
    if (const auto i = cal::find_coordinate(r, head, cal::misalignment_axis::y))
      y = r.coordinate_values[*i];
    r.parameters[cal::parameter_index(head, cal::head_parameter::sigma)].estimate =
        std::hypot(x, y);
    r.parameters[cal::parameter_index(head, cal::head_parameter::phase)].estimate =
        std::atan2(y, x) / cal::radians_per_degree;
    return f;
  };
  for (std::size_t c = 0; c < n; ++c) {
    const double h = 1e-3 * std::sqrt(u.coordinate_covariance[c][c]);
    const cal::fit_result plus = moved(c, h), minus = moved(c, -h);
    const std::vector<double> up = corrected_errors(plus), down = corrected_errors(minus);
    for (std::size_t i = 0; i < up.size(); ++i) gradient[c].push_back((up[i] - down[i]) / (2 * h));
  }
  double worst_ratio = 0, worst_error = 0, before_worst = 0;
  for (std::size_t i = 0; i < after.size(); ++i) {
    double variance = 0;
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b)
        variance += gradient[a][i] * u.coordinate_covariance[a][b] * gradient[b][i];
    worst_ratio = std::max(worst_ratio, std::abs(after[i]) / std::sqrt(variance));
    worst_error = std::max(worst_error, std::abs(after[i]));
  }
  {
    const sc::simulation sim = sc::simulation::of(clean).value();
    sc::row row = sim.make_row();
    for (std::uint64_t k = 0; k < sim.rows(); ++k) {
      sim.compute(k, row);
      before_worst =
          std::max({before_worst, std::abs(row.roll_err_rad), std::abs(row.pitch_err_rad)});
    }
  }
  WARN("--apply: max |roll|, |pitch| error "
       << worst_error / cal::radians_per_degree
       << " deg (before: " << before_worst / cal::radians_per_degree << " deg), at most "
       << worst_ratio << " times its propagated 1 sigma");
  CHECK(worst_ratio < 3);
  CHECK(worst_error < before_worst / 20);
}

TEST_CASE("calibration scene: --apply refuses a fit of another head count or the bias model",
          "[calibration][scene][apply]") {
  const sc::loaded_scene one_head = scene_of({{"model", "scan"}, {"orbits", "0.1"}});
  CHECK_FALSE(sc::fit_correction::of(one_head, CONESCAN_TEST_DATA "/calibration/fit-h2.json").ok());
  CHECK(sc::fit_correction::of(one_head, CONESCAN_TEST_DATA "/calibration/fit-h1.json").ok());
  const sc::loaded_scene bias = scene_of({{"orbits", "0.1"}});
  const auto refused = sc::fit_correction::of(bias, CONESCAN_TEST_DATA "/calibration/fit-h1.json");
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().text().find("--model scan") != std::string::npos);
}

TEST_CASE("scene fit: each head parameter is the head key of its name", "[calibration][scene]") {
  // The fit reads and sets a head's parameters through the head key table (head_spec.hpp):
  // each parameter names a number key, in the key's unit, and the scene's parameter set holds
  // that key's value (the physics' where the chain runs).
  sc::scene_config scene;
  scene.model = sc::forward_model::scan;
  scene.heads[0].tau_ms = 0.5;
  scene.heads[0].spin_hz = 1;
  for (std::size_t i = 0; i < cal::head_parameter_count; ++i) {
    const auto p = static_cast<cal::head_parameter>(i);
    const std::string_view name = cal::head_parameter_specs[i].key;
    INFO(name);
    const sc::head_key* key = sc::find_head_key(name);
    REQUIRE(key != nullptr);
    REQUIRE(key->field != nullptr);
    CHECK(&cal::head_parameter_key(p) == key);
    const std::string_view unit = cal::head_parameter_specs[i].unit;
    CHECK(unit == (std::string_view(key->unit).empty() ? "1" : key->unit));
    scene.heads[0].*key->field += 0.125;
    CHECK(cal::scene_parameters(scene).value(0, p) == scene.heads[0].*key->field);
  }
}
