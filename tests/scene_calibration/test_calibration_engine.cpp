// The calibration's estimator (src/calibration/estimator.hpp) on the analytic model of
// synthetic_model.hpp, whose truth is known: recovery, honest uncertainty over many seeds,
// experiment design against the scatter of fits, degeneracy, outliers, non-convergence.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>

#include "calibration/estimator.hpp"
#include "calibration/misalignment.hpp"
#include "calibration/report.hpp"
#include "support/synthetic_model.hpp"

namespace cal = conescan::calibration;
using cal::earth_parameter;
using cal::head_parameter;
using cal::parameter_index;

namespace {

cal::parameter_set truth_parameters() {
  return cal::recovery_truth();
}

cal::parameter_set start_parameters() {
  return cal::recovery_start();
}

const cal::forward_model_of<cal::synthetic_model>& model() {
  static const cal::forward_model_of<cal::synthetic_model> m{cal::synthetic_model({})};
  return m;
}

cal::fit_result fit_converged(const cal::fit_problem& problem,
                              const cal::fit_options& options = {}) {
  conescan::checked<cal::fit_outcome> outcome = cal::fit(problem, options);
  REQUIRE(outcome.ok());
  REQUIRE(std::holds_alternative<cal::fit_result>(outcome.value()));
  return std::get<cal::fit_result>(outcome.value());
}

// The observations are borrowed (fit_problem): they must outlive the problem.
cal::fit_problem problem_with(std::span<const cal::observation> observations, double noise_deg) {
  return {&model(), start_parameters(), observations,
          std::vector<cal::head_noise>(2, {noise_deg, 0.0})};
}

/// (estimate - truth) / sigma of every free parameter, phi_A compared modulo 360.
std::vector<double> normalised_errors(const cal::fit_result& r, const cal::parameter_set& truth) {
  std::vector<double> z;
  for (std::size_t index : r.uncertainty.free_parameters) {
    const cal::parameter_estimate& e = r.uncertainty.parameters[index];
    REQUIRE(e.determined);
    z.push_back(cal::wrap_deg(e.estimate - truth.values[index]) / e.sigma);
  }
  return z;
}

}  // namespace

TEST_CASE("calibration: the optical axis from the components is smooth at sigma = 0",
          "[calibration]") {
  using jet = cal::parameter_jet;
  const cal::optical_axis<jet> at_zero =
      cal::optical_axis_from_components(jet(0.0, 0), jet(0.0, 1));
  CHECK(at_zero.z.a == 1);
  CHECK(at_zero.x.v[0] == 1);  // d(sin sigma cos phi_A)/dx = 1 at 0: no 0/0
  CHECK(at_zero.y.v[1] == 1);
  CHECK(at_zero.z.v[0] == 0);
  CHECK(std::isfinite(at_zero.z.v[1]));
  // Both sides of the series' limit agree with the direct form to an ulp or two.
  const double limit_rad2 = conescan::misalignment_series_limit<double>();
  for (double sigma :
       {0.99999 * std::sqrt(limit_rad2), 1.00001 * std::sqrt(limit_rad2), 1e-6, 0.3}) {
    const double phase = 0.7;
    const cal::optical_axis<double> a =
        cal::optical_axis_from_components(sigma * std::cos(phase), sigma * std::sin(phase));
    CHECK_THAT(a.x, Catch::Matchers::WithinRel(std::sin(sigma) * std::cos(phase), 4e-16));
    CHECK_THAT(a.y, Catch::Matchers::WithinRel(std::sin(sigma) * std::sin(phase), 4e-16));
    CHECK_THAT(a.z, Catch::Matchers::WithinRel(std::cos(sigma), 2e-16));
  }
}

TEST_CASE("calibration: the fit recovers a known truth within 3 sigma", "[calibration]") {
  const cal::parameter_set truth = truth_parameters();
  const cal::fit_result r = fit_converged(problem_with(
      cal::simulate_observations(model().model(), truth, 0, 10, 1200, 0.01, 7, 0), 0.01));
  INFO(cal::fit_table(r));
  for (double z : normalised_errors(r, truth)) CHECK(std::abs(z) < 3);
  CHECK(r.uncertainty.unobservable.empty());
  CHECK(r.chi2_dof == Approx(1).margin(0.1));
  CHECK(r.outlier_count == 0);
  CHECK(r.dropped_at_start == 0);
  CHECK(r.residual_count == 2 * 2 * 1200);
  // Chord sqrt(2) n and phase n / sqrt(2): together sqrt(5/4) n.
  for (double rms : r.residual_rms_deg) CHECK(rms == Approx(0.01 * std::sqrt(1.25)).epsilon(0.05));
}

TEST_CASE("calibration: the fit is the same to the bit on any number of threads", "[calibration]") {
  // The passes sum over parts that do not depend on the threads (text::reduction_part_count):
  // with one part a thread, the sums' rounding changed with their count, and so could the
  // iterations and the last digits of every estimate. 2400 observations: more than the 64 parts.
  const std::vector<cal::observation> observations =
      cal::simulate_observations(model().model(), truth_parameters(), 0, 10, 1200, 0.01, 11, 0);
  cal::fit_options one_thread;
  one_thread.threads = 1;
  const cal::fit_result first = fit_converged(problem_with(observations, 0.01), one_thread);
  for (int threads : {2, 3, 7}) {
    cal::fit_options options;
    options.threads = threads;
    const cal::fit_result r = fit_converged(problem_with(observations, 0.01), options);
    INFO(threads << " threads");
    CHECK(r.iterations == first.iterations);
    CHECK(r.chi2_dof == first.chi2_dof);
    CHECK(r.residual_rms_deg == first.residual_rms_deg);
    for (std::size_t index : first.uncertainty.free_parameters) {
      CHECK(r.uncertainty.parameters[index].estimate ==
            first.uncertainty.parameters[index].estimate);
      CHECK(r.uncertainty.parameters[index].sigma == first.uncertainty.parameters[index].sigma);
    }
  }
}

namespace {

// The synthetic model with a jitter of its chords and phases (1e-5 of the stated noise, 1e-7
// deg) that changes with every parameter's value, as the fit's time series of the chain, rebuilt
// at each step, changes in its last digits: chi2 then moves from step to step by more than the
// Gauss-Newton falls the final tolerance asks for.
class jittered_model {
 public:
  template <class T>
  cal::predicted_measurement<T> predict(const cal::telemetry_sample& sample,
                                        const cal::head_geometry<T>& head,
                                        const cal::earth_geometry<T>& earth) const {
    auto p = model().model().predict<T>(sample, head, earth);
    const double key = cal::value_of(head.misalignment_x_deg) * 1e6 +
                       cal::value_of(head.misalignment_y_deg) * 3e6 +
                       cal::value_of(head.dgamma_deg) * 7e6 + cal::value_of(earth.horizon_km) * 11 +
                       static_cast<double>(sample.row) * 0.618 + static_cast<double>(sample.head);
    const double jitter_deg = 1e-7 * std::sin(1e4 * key);
    p.chord_deg = p.chord_deg + jitter_deg;
    p.phase_deg = p.phase_deg - jitter_deg;
    return p;
  }
};

}  // namespace

TEST_CASE("calibration: a model that jitters below the noise ends the fit at its resolution",
          "[calibration]") {
  // The solver stops where a rejected step's Gauss-Newton fall is below 1e-6 of the residual
  // variance (solver.hpp): on such a model it had gone on until the damping shrank the step to
  // nothing. The estimates agree with the smooth model's within 1e-3 of their 1 sigma.
  const std::vector<cal::observation> observations =
      cal::simulate_observations(model().model(), truth_parameters(), 0, 10, 1200, 0.01, 13, 0);
  const cal::forward_model_of<jittered_model> jittered{jittered_model{}};
  cal::fit_problem problem = problem_with(observations, 0.01);
  const cal::fit_result smooth = fit_converged(problem);
  problem.model = &jittered;
  const cal::fit_result r = fit_converged(problem);
  INFO(r.solver_message << " after " << r.iterations << " iterations (smooth: " << smooth.iterations
                        << ", " << smooth.solver_message << ")");
  CHECK(r.iterations <= smooth.iterations + 3);
  for (std::size_t index : smooth.uncertainty.free_parameters) {
    const cal::parameter_estimate& e = smooth.uncertainty.parameters[index];
    CHECK(std::abs(cal::wrap_deg(r.uncertainty.parameters[index].estimate - e.estimate)) <=
          1e-3 * e.sigma);
  }
}

TEST_CASE("calibration: over 300 seeds the 1 sigma are honest and the design predicts them",
          "[calibration][many-fits]") {
  // One orbit at 10 s (600 rows, 2400 residuals) per seed: sigma / 1 sigma(sigma) is about 34
  // on head 1, where the linear propagation to sigma and phi_A holds (at 200 rows, a ratio of
  // 19, sigma's normalised errors have a standard deviation of 1.20: docs/CALIBRATION.md).
  // Tolerances: with 300 seeds the mean of a normal sample has a standard error of 0.058, its
  // standard deviation 0.041 and a coverage fraction 0.027, so the checks (0.2, 10 %, 8 %) sit
  // at 3.4, 2.4 and 3 of those errors, and the coverage of all 1800 intervals is held to the
  // issue's 68 +- 5 %; the seeds are fixed, so the test is deterministic.
  const cal::parameter_set truth = truth_parameters();
  constexpr int seeds = 300;
  const std::size_t p = 6;
  std::vector<std::vector<double>> z(p), estimates(p);
  for (int seed = 1; seed <= seeds; ++seed) {
    const cal::fit_result r = fit_converged(problem_with(
        cal::simulate_observations(model().model(), truth, 0, 10, 600, 0.01, 1000 + seed, 0),
        0.01));
    const std::vector<double> zs = normalised_errors(r, truth);
    for (std::size_t i = 0; i < p; ++i) {
      z[i].push_back(zs[i]);
      estimates[i].push_back(r.uncertainty.parameters[r.uncertainty.free_parameters[i]].estimate);
    }
  }
  // The design: the Fisher information at the truth, the same 600 rows, no data.
  std::vector<cal::telemetry_sample> samples;
  for (std::size_t i = 0; i < 600; ++i)
    for (std::size_t k = 0; k < 2; ++k) samples.push_back({i, 10.0 * static_cast<double>(i), k});
  cal::parameter_set at_truth = truth;
  at_truth.free = start_parameters().free;
  const conescan::checked<cal::design_result> design = cal::predict_uncertainty(
      model(), at_truth, samples, std::vector<cal::head_noise>(2, {0.01, 0.0}));
  REQUIRE(design.ok());
  double inside_all = 0;
  for (std::size_t i = 0; i < p; ++i) {
    const std::size_t index = design.value().uncertainty.free_parameters[i];
    const std::string& name = design.value().uncertainty.parameters[index].name;
    const double n = seeds;
    const double mean = std::accumulate(z[i].begin(), z[i].end(), 0.0) / n;
    double square = 0, inside = 0, estimate_mean = 0, estimate_square = 0;
    for (double v : z[i]) {
      square += (v - mean) * (v - mean);
      inside += std::abs(v) <= 1;
    }
    for (double e : estimates[i]) estimate_mean += e / n;
    for (double e : estimates[i]) {
      const double d = cal::wrap_deg(e - estimate_mean);
      estimate_square += d * d;
    }
    const double scatter = std::sqrt(estimate_square / (n - 1));
    const double predicted = design.value().uncertainty.parameters[index].sigma;
    INFO(name << ": mean " << mean << ", std " << std::sqrt(square / (n - 1)) << ", coverage "
              << inside / n << ", scatter " << scatter << ", predicted " << predicted);
    CHECK(std::abs(mean) < 0.2);
    CHECK(std::sqrt(square / (n - 1)) == Approx(1).epsilon(0.1));
    CHECK(inside / n == Approx(0.6827).margin(0.08));
    CHECK(predicted == Approx(scatter).epsilon(0.15));
    inside_all += inside;
  }
  CHECK(inside_all / (seeds * double(p)) == Approx(0.6827).margin(0.05));
}

namespace {

/// The synthetic model with the horizon moved into the cone angle: h0 and dgamma enter only as
/// dgamma + 0.001 deg/km h0, an exact degeneracy.
struct sum_model {
  cal::synthetic_model base{cal::synthetic_scene{}};

  template <class T>
  cal::predicted_measurement<T> predict(const cal::telemetry_sample& sample,
                                        const cal::head_geometry<T>& head,
                                        const cal::earth_geometry<T>& earth) const {
    cal::head_geometry<T> h = head;
    h.dgamma_deg = head.dgamma_deg + 0.001 * earth.horizon_km;
    cal::earth_geometry<T> e = earth;
    e.horizon_km = T(0.0);
    return base.predict(sample, h, e);
  }
};

cal::parameter_set one_head(std::initializer_list<std::size_t> free) {
  cal::parameter_set p = cal::parameter_set::nominal(1);
  for (std::size_t index : free) p.free[index] = true;
  return p;
}

}  // namespace

TEST_CASE("calibration: two parameters that enter only as their sum are flagged unobservable",
          "[calibration]") {
  const cal::forward_model_of<sum_model> degenerate{sum_model{}};
  cal::parameter_set truth = cal::parameter_set::nominal(1);
  truth.value(0, head_parameter::sigma) = 0.05;
  truth.value(0, head_parameter::phase) = 60;
  truth.value(0, head_parameter::dgamma) = 0.02;
  truth.value(earth_parameter::horizon) = 5;
  const cal::parameter_set start =
      one_head({0, 1, 2, parameter_index(1, earth_parameter::horizon)});
  const cal::fit_result r =
      fit_converged({&degenerate,
                     start,
                     cal::simulate_observations(degenerate.model(), truth, 0, 10, 600, 0.01, 3, 0),
                     {{0.01, 0.0}}});
  INFO(cal::fit_table(r));
  REQUIRE(r.uncertainty.unobservable.size() == 1);
  const auto& c = r.uncertainty.unobservable[0].components;
  REQUIRE(c.size() == 2);
  // The normalised columns are equal, so the null vector is (1, -1) / sqrt(2) exactly.
  CHECK(std::abs(c[0].second) == Approx(std::sqrt(0.5)).epsilon(1e-9));
  CHECK(c[1].second == Approx(-c[0].second).epsilon(1e-9));
  CHECK(((c[0].first == "h1.dgamma" && c[1].first == "horizon-km") ||
         (c[1].first == "h1.dgamma" && c[0].first == "horizon-km")));
  CHECK(r.uncertainty.unobservable[0].eigenvalue_ratio < 1e-12);
  CHECK(r.uncertainty.rank == 3);
  CHECK(r.dof == r.residual_count - 3);
  CHECK(r.uncertainty.condition > 1e12);
  for (std::size_t index :
       {parameter_index(0, head_parameter::dgamma), parameter_index(1, earth_parameter::horizon)}) {
    const cal::parameter_estimate& e = r.uncertainty.parameters[index];
    CHECK_FALSE(e.determined);
    CHECK(std::isnan(e.estimate));
    CHECK(std::isnan(e.sigma));
    CHECK(e.withheld.find("unobservable") != std::string::npos);
  }
  // sigma and phi_A do not take part: determined, within 3 sigma.
  for (std::size_t index : {std::size_t{0}, std::size_t{1}}) {
    const cal::parameter_estimate& e = r.uncertainty.parameters[index];
    REQUIRE(e.determined);
    CHECK(std::abs(cal::wrap_deg(e.estimate - truth.values[index])) < 3 * e.sigma);
  }
  CHECK(cal::fit_table(r).find("0.707107 h1.dgamma") != std::string::npos);
}

namespace {

/// The synthetic model with the misalignment's y component moved into the cone angle: y and
/// dgamma enter only as their sum, x alone.
struct y_into_cone_model {
  cal::synthetic_model base{cal::synthetic_scene{}};

  template <class T>
  cal::predicted_measurement<T> predict(const cal::telemetry_sample& sample,
                                        const cal::head_geometry<T>& head,
                                        const cal::earth_geometry<T>& earth) const {
    const cal::head_geometry<T> h{
        {head.misalignment_x_deg, T(0.0), T(head.dgamma_deg + head.misalignment_y_deg)},
        head.tau_ms,
        head.threshold};
    return base.predict(sample, h, earth);
  }
};

}  // namespace

TEST_CASE("calibration: one misalignment component in a combination withholds sigma and phi_A",
          "[calibration]") {
  const cal::forward_model_of<y_into_cone_model> degenerate{y_into_cone_model{}};
  cal::parameter_set truth = cal::parameter_set::nominal(1);
  truth.value(0, head_parameter::sigma) = 0.05;
  truth.value(0, head_parameter::phase) = 60;
  const cal::fit_result r =
      fit_converged({&degenerate,
                     one_head({0, 1, 2}),
                     cal::simulate_observations(degenerate.model(), truth, 0, 10, 300, 0.01, 8, 0),
                     {{0.01, 0.0}}});
  INFO(cal::fit_table(r));
  REQUIRE(r.uncertainty.unobservable.size() == 1);
  std::vector<std::string> names;
  for (const auto& [name, component] : r.uncertainty.unobservable[0].components)
    names.push_back(name);
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"h1.dgamma", "h1.misalign-y"});
  for (std::size_t index : {0, 1, 2}) CHECK_FALSE(r.uncertainty.parameters[index].determined);
  // x is determined: its coordinate keeps its estimate and variance.
  CHECK(std::isfinite(r.uncertainty.coordinate_values[0]));
  CHECK(std::isfinite(r.uncertainty.coordinate_covariance[0][0]));
  CHECK(std::isnan(r.uncertainty.coordinate_values[1]));
}

TEST_CASE("calibration: phi_A at a held sigma of 0 changes nothing and is reported unobservable",
          "[calibration]") {
  const cal::parameter_set truth = one_head({});
  const cal::fit_result r =
      fit_converged({&model(),
                     one_head({1, 2}),
                     cal::simulate_observations(model().model(), truth, 0, 10, 300, 0.01, 5, 0),
                     {{0.01, 0.0}}});
  REQUIRE(r.uncertainty.unobservable.size() == 1);
  CHECK(r.uncertainty.unobservable[0].components ==
        std::vector<std::pair<std::string, double>>{{"h1.phase", 1.0}});
  CHECK_FALSE(r.uncertainty.parameters[1].determined);
  CHECK(r.uncertainty.parameters[2].determined);
}

TEST_CASE("calibration: without a misalignment phi_A is withheld as undetermined",
          "[calibration]") {
  const cal::parameter_set truth = one_head({});
  const cal::fit_result r =
      fit_converged({&model(),
                     one_head({0, 1}),
                     cal::simulate_observations(model().model(), truth, 0, 10, 300, 0.01, 11, 0),
                     {{0.01, 0.0}}});
  const cal::parameter_estimate& sigma = r.uncertainty.parameters[0];
  const cal::parameter_estimate& phase = r.uncertainty.parameters[1];
  INFO(cal::fit_table(r));
  REQUIRE(sigma.determined);
  CHECK(sigma.estimate < 3 * sigma.sigma);
  CHECK_FALSE(phase.determined);
  CHECK(phase.withheld.find("undetermined") != std::string::npos);
  CHECK(std::isnan(r.uncertainty.correlation[0][1]));
  CHECK(r.uncertainty.unobservable.empty());
  // The components are still determined, for a correction to use.
  CHECK(std::isfinite(r.uncertainty.coordinate_covariance[0][1]));
  CHECK(r.uncertainty.coordinate_names ==
        std::vector<std::string>{"h1.misalign-x", "h1.misalign-y"});
}

TEST_CASE("calibration: sigma alone is a signed sigma along the held phi_A", "[calibration]") {
  cal::parameter_set truth = one_head({});
  truth.value(0, head_parameter::sigma) = 0.05;
  truth.value(0, head_parameter::phase) = 30;
  cal::parameter_set start = one_head({0});
  start.value(0, head_parameter::phase) = 210;  // the opposite azimuth
  const cal::fit_result r =
      fit_converged({&model(),
                     start,
                     cal::simulate_observations(model().model(), truth, 0, 10, 300, 0.01, 2, 0),
                     {{0.01, 0.0}}});
  const cal::parameter_estimate& sigma = r.uncertainty.parameters[0];
  CHECK(std::abs(sigma.estimate + 0.05) < 3 * sigma.sigma);
  CHECK(r.uncertainty.parameters[1].estimate == 210);  // held, as given
}

TEST_CASE("calibration: the robust loss ignores an outlier and reports it", "[calibration]") {
  const cal::parameter_set truth = truth_parameters();
  std::vector<cal::observation> clean =
      cal::simulate_observations(model().model(), truth, 0, 6, 1000, 0.01, 21, 0);
  std::vector<cal::observation> spoiled = clean;
  // One crossing in 1000 off by 1 deg: Earth-in of observations 500 and 1500.
  for (std::size_t i : {std::size_t{500}, std::size_t{1500}}) {
    spoiled[i].chord_deg -= 1;
    spoiled[i].phase_deg += 0.5;
  }
  const cal::fit_result reference = fit_converged(problem_with(clean, 0.01));
  const cal::fit_result robust = fit_converged(problem_with(spoiled, 0.01));
  cal::fit_options off;
  off.loss = cal::robust_loss::none;
  const cal::fit_result plain = fit_converged(problem_with(spoiled, 0.01), off);
  INFO(cal::fit_table(robust));
  double worst_robust = 0, worst_plain = 0;
  for (std::size_t index : reference.uncertainty.free_parameters) {
    const cal::parameter_estimate& e = reference.uncertainty.parameters[index];
    const double moved =
        std::abs(cal::wrap_deg(robust.uncertainty.parameters[index].estimate - e.estimate));
    CHECK(moved < e.sigma);
    worst_robust = std::max(worst_robust, moved / e.sigma);
    worst_plain = std::max(
        worst_plain,
        std::abs(cal::wrap_deg(plain.uncertainty.parameters[index].estimate - e.estimate)) /
            e.sigma);
  }
  INFO("largest move in 1 sigma: robust " << worst_robust << ", least squares " << worst_plain);
  CHECK(worst_plain > 3 * worst_robust);
  CHECK(robust.loss == cal::robust_loss::huber);
  REQUIRE(robust.outlier_count == 2);
  for (const cal::outlier& o : robust.worst_outliers) {
    CHECK((o.sample.row == 250 || o.sample.row == 750));
    CHECK(o.sample.head == 0);
    CHECK(o.chord_residual_deg == Approx(-1).margin(0.05));
    CHECK(o.normalised > 50);
  }
  CHECK(cal::fit_table(robust).find("outliers (normalised residual above 6): 2") !=
        std::string::npos);
}

TEST_CASE("calibration: a fit that stops early is not converged and carries its last state",
          "[calibration]") {
  cal::fit_options options;
  options.max_iterations = 1;
  const conescan::checked<cal::fit_outcome> outcome = cal::fit(
      problem_with(
          cal::simulate_observations(model().model(), truth_parameters(), 0, 10, 300, 0.01, 4, 0),
          0.01),
      options);
  REQUIRE(outcome.ok());
  REQUIRE(std::holds_alternative<cal::unconverged_fit>(outcome.value()));
  const cal::unconverged_fit& u = std::get<cal::unconverged_fit>(outcome.value());
  CHECK(u.iterations >= 1);
  CHECK(u.last_state.values[parameter_index(2, earth_parameter::horizon)] != 40);
  const std::string table = cal::fit_table(outcome.value());
  CHECK(table.find("NOT CONVERGED") != std::string::npos);
  CHECK(table.find("1 sigma") == std::string::npos);
  CHECK(table.find("converged: no") != std::string::npos);
}

TEST_CASE("calibration: without stated noise the heads are weighted alike and the loss is off",
          "[calibration]") {
  const cal::parameter_set truth = truth_parameters();
  const cal::fit_result r = fit_converged(
      problem_with(cal::simulate_observations(model().model(), truth, 0, 10, 300, 0.0, 1, 0), 0.0));
  CHECK(r.unit_weights);
  CHECK(r.loss == cal::robust_loss::none);
  CHECK(r.chi2_dof < 1e-20);
  for (std::size_t index : r.uncertainty.free_parameters)
    CHECK(std::abs(cal::wrap_deg(r.uncertainty.parameters[index].estimate - truth.values[index])) <
          1e-9 * std::max(1.0, std::abs(truth.values[index])));
}

TEST_CASE("calibration: measurement sigmas from the crossing noise and the telemetry step",
          "[calibration]") {
  const cal::measurement_sigma s = cal::measurement_sigma_of({0.01, 0.0});
  CHECK(s.chord_deg == Approx(0.01 * std::sqrt(2.0)).epsilon(1e-15));
  CHECK(s.phase_deg == Approx(0.01 / std::sqrt(2.0)).epsilon(1e-15));
  const cal::measurement_sigma q = cal::measurement_sigma_of({0.0, 0.012});
  CHECK(q.chord_deg == Approx(0.012 / std::sqrt(12.0)).epsilon(1e-15));
  CHECK(q.phase_deg == q.chord_deg);
}

TEST_CASE("calibration: a fit refuses what it cannot do, naming why", "[calibration]") {
  const std::vector<cal::observation> data =
      cal::simulate_observations(model().model(), truth_parameters(), 0, 10, 50, 0.01, 1, 0);
  auto message = [](const conescan::checked<cal::fit_outcome>& o) {
    REQUIRE_FALSE(o.ok());
    return o.error().text();
  };
  cal::fit_problem none_free = problem_with(data, 0.01);
  none_free.parameters.free.assign(none_free.parameters.free.size(), false);
  CHECK(message(cal::fit(none_free, {})) == "--free: no free parameter: name at least one");
  cal::fit_problem mixed = problem_with(data, 0.01);
  mixed.noise[1] = {0.0, 0.0};
  CHECK_THAT(message(cal::fit(mixed, {})),
             Catch::Matchers::Contains("1 of 2 heads state a crossing noise"));
  cal::fit_problem negative = problem_with(data, 0.01);
  negative.noise[0] = {-0.01, 0.0};
  CHECK_THAT(message(cal::fit(negative, {})), Catch::Matchers::StartsWith("--head: head 1:"));
  std::vector<cal::observation> third_head = data;
  third_head[3].sample.head = 2;
  CHECK_THAT(message(cal::fit(problem_with(third_head, 0.01), {})),
             Catch::Matchers::Contains("(head 3)"));
  const cal::fit_problem too_few =
      problem_with(std::span<const cal::observation>(data).first(3), 0.01);
  CHECK(message(cal::fit(too_few, {})) == "--free: 6 residuals cannot determine 6 free parameters");
  const conescan::checked<cal::design_result> design = cal::predict_uncertainty(
      model(), start_parameters(), {{0, 0.0, 0}}, std::vector<cal::head_noise>(2, {0.0, 0.0}));
  REQUIRE_FALSE(design.ok());
  CHECK_THAT(design.error().text(),
             Catch::Matchers::Contains("experiment design needs each head's crossing noise"));
}
