// The calibration's estimator (src/calibration/estimator.hpp) on the analytic model of
// synthetic_model.hpp, whose truth is known: recovery, honest uncertainty over many seeds,
// experiment design against the scatter of fits, degeneracy, outliers, non-convergence.
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>

#include "calibration/estimator.hpp"
#include "calibration/misalignment.hpp"
#include "calibration/report.hpp"
#include "calibration/synthetic_model.hpp"

namespace cal = conescan::calibration;
using cal::earth_parameter;
using cal::head_parameter;
using cal::parameter_index;

namespace {

/// SPEC §11's recovery scene in the synthetic model: two heads, sigma 0.05 and 0.03 deg at
/// phi_A 60 and 200 deg, a cone-angle bias of 0.02 deg on head 1, a horizon 2 km above the
/// nominal 40 km.
cal::parameter_set truth_parameters() {
  cal::parameter_set p = cal::parameter_set::nominal(2);
  p.value(0, head_parameter::sigma) = 0.05;
  p.value(0, head_parameter::phase) = 60;
  p.value(1, head_parameter::sigma) = 0.03;
  p.value(1, head_parameter::phase) = 200;
  p.value(0, head_parameter::dgamma) = 0.02;
  p.value(earth_parameter::horizon) = 42;
  return p;
}

/// The nominal start: sigma 0, no bias, horizon 40 km; the six of the benchmark freed.
cal::parameter_set start_parameters() {
  cal::parameter_set p = cal::parameter_set::nominal(2);
  p.value(earth_parameter::horizon) = 40;
  for (std::size_t index :
       {parameter_index(0, head_parameter::sigma), parameter_index(0, head_parameter::phase),
        parameter_index(1, head_parameter::sigma), parameter_index(1, head_parameter::phase),
        parameter_index(0, head_parameter::dgamma), parameter_index(2, earth_parameter::horizon)})
    p.free[index] = true;
  return p;
}

const cal::forward_model_of<cal::synthetic_model>& model() {
  static const cal::forward_model_of<cal::synthetic_model> m{cal::synthetic_model({})};
  return m;
}

cal::fit_result fit_converged(const cal::fit_problem& problem,
                              const cal::fit_options& options = {}) {
  cal::checked<cal::fit_outcome> outcome = cal::fit(problem, options);
  REQUIRE(outcome.ok());
  REQUIRE(std::holds_alternative<cal::fit_result>(outcome.value()));
  return std::get<cal::fit_result>(outcome.value());
}

cal::fit_problem problem_with(std::vector<cal::observation> observations, double noise_deg) {
  return {&model(), start_parameters(), std::move(observations),
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
  for (double sigma : {0.99999 * std::sqrt(cal::misalignment_series_limit_rad2),
                       1.00001 * std::sqrt(cal::misalignment_series_limit_rad2), 1e-6, 0.3}) {
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

TEST_CASE("calibration: over 300 seeds the 1 sigma are honest and the design predicts them",
          "[calibration]") {
  // One orbit at 10 s (600 rows, 2400 residuals) per seed: sigma / 1 sigma(sigma) is about 40
  // on head 1, where the linear propagation to sigma and phi_A holds (at 200 rows, a ratio of
  // 19, sigma's normalised errors have a standard deviation of 1.20: docs/CALIBRATION.md).
  // Tolerances: with 300 seeds the mean of a normal sample has a standard error of 0.058, its
  // standard deviation 0.041 and a coverage fraction 0.027, so the checks (0.2, 10 %, 5 %) sit
  // at 3.4, 2.4 and 1.9 of those errors; the seeds are fixed, so the test is deterministic.
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
  const cal::checked<cal::design_result> design = cal::predict_uncertainty(
      model(), at_truth, samples, std::vector<cal::head_noise>(2, {0.01, 0.0}));
  REQUIRE(design.ok());
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
    CHECK(inside / n == Approx(0.6827).margin(0.05));
    CHECK(predicted == Approx(scatter).epsilon(0.15));
  }
}
