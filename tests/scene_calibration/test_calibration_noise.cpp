// The noise from the data (src/calibration/estimator.hpp): each head's crossing noise estimated
// from its residuals, the weights and the 1 sigma scaled by it, so that the 1 sigma stay honest
// when the declared noise is wrong by 10 times either way, for one head or all; and the warnings.
// The coverage cases run 200 seeds each on the analytic model (one orbit at 10 s); the long
// version with every way of weighting and the real model is bench/calibration_coverage.cpp.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "calibration/estimator.hpp"
#include "calibration/fit_json.hpp"
#include "calibration/passes.hpp"
#include "calibration/report.hpp"
#include "simulation/random.hpp"
#include "support/synthetic_model.hpp"

namespace cal = conescan::calibration;

namespace {

const cal::forward_model_of<cal::synthetic_model>& model() {
  static const cal::forward_model_of<cal::synthetic_model> m{cal::synthetic_model({})};
  return m;
}

cal::fit_result fit_converged(const cal::fit_problem& problem,
                              const cal::fit_options& options = {}) {
  const conescan::checked<cal::fit_outcome> outcome = cal::fit(problem, options);
  REQUIRE(outcome.ok());
  REQUIRE(std::holds_alternative<cal::fit_result>(outcome.value()));
  return std::get<cal::fit_result>(outcome.value());
}

// The truth's noise is 0.01 deg on both heads; the fit is told head1_deg and head2_deg.
// Checks, over 200 seeds: the 1 sigma intervals of all six parameters (1200) cover the truth
// 68 +- 5 % (the bound; the binomial standard deviation of 1200 intervals is 1.3 %,
// though the six of one fit are correlated), each parameter's 68 +- 10 % (3 of its binomial
// standard deviations, 3.3 %), and the normalised errors' rms within 10 % of 1.
void check_coverage(double head1_deg, double head2_deg) {
  const cal::parameter_set truth = cal::recovery_truth();
  const double truth_values[] = {0.05, 60, 0.02, 0.03, -160, 42};
  constexpr int seeds = 200;
  constexpr std::size_t parameters = 6;
  int inside[parameters] = {}, inside_all = 0;
  double square = 0, ratio1 = 0, ratio2 = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    const std::vector<cal::observation> data =
        cal::simulate_observations(model().model(), truth, 0, 10, 600, 0.01, 1000 + seed, 0);
    const cal::fit_result r = fit_converged(
        {&model(), cal::recovery_start(), data, {{head1_deg, 0.0}, {head2_deg, 0.0}}});
    ratio1 += r.noise[0].estimated_deg / seeds;
    ratio2 += r.noise[1].estimated_deg / seeds;
    for (std::size_t i = 0; i < parameters; ++i) {
      const cal::parameter_estimate& e = r.uncertainty.parameters[r.uncertainty.free_parameters[i]];
      REQUIRE(e.determined);
      const double z = cal::wrap_deg(e.estimate - truth_values[i]) / e.sigma;
      inside[i] += std::abs(z) <= 1;
      inside_all += std::abs(z) <= 1;
      square += z * z;
    }
  }
  const double coverage = inside_all / double(seeds * parameters);
  const double rms = std::sqrt(square / double(seeds * parameters));
  INFO("declared " << head1_deg << ", " << head2_deg << " deg: coverage " << coverage << ", rms "
                   << rms << ", mean estimated noise " << ratio1 << ", " << ratio2 << " deg");
  CHECK(std::abs(coverage - 0.6827) <= 0.05);
  CHECK(std::abs(rms - 1) <= 0.1);
  for (std::size_t i = 0; i < parameters; ++i) {
    INFO("parameter " << i + 1 << ": coverage " << inside[i] / double(seeds));
    CHECK(std::abs(inside[i] / double(seeds) - 0.6827) <= 0.10);
  }
  // The estimate recovers the truth's 0.01 deg (the MAD's scatter with 1200 residuals per head
  // is 3 %, its mean over 200 seeds 0.2 %).
  CHECK(ratio1 == Approx(0.01).epsilon(0.02));
  CHECK(ratio2 == Approx(0.01).epsilon(0.02));
}

}  // namespace

TEST_CASE("calibration noise: declared 10 times too small on both heads, the 1 sigma hold",
          "[calibration][noise][many-fits]") {
  check_coverage(0.001, 0.001);
}

TEST_CASE("calibration noise: declared 10 times too large on both heads, the 1 sigma hold",
          "[calibration][noise][many-fits]") {
  check_coverage(0.1, 0.1);
}

TEST_CASE("calibration noise: declared 10 times too small on one head, the 1 sigma hold",
          "[calibration][noise][many-fits]") {
  check_coverage(0.001, 0.01);
}

TEST_CASE("calibration noise: declared 10 times too large on one head, the 1 sigma hold",
          "[calibration][noise][many-fits]") {
  check_coverage(0.1, 0.01);
}

TEST_CASE("calibration noise: the estimate is reported beside the declared, with a warning",
          "[calibration][noise]") {
  const std::vector<cal::observation> data =
      cal::simulate_observations(model().model(), cal::recovery_truth(), 0, 10, 600, 0.01, 5, 0);
  SECTION("right: no warning, the weights barely move") {
    const cal::fit_result r =
        fit_converged({&model(), cal::recovery_start(), data, {{0.01, 0.0}, {0.01, 0.0}}});
    INFO(cal::fit_table(r));
    CHECK(r.warnings.empty());
    for (const cal::head_noise_estimate& n : r.noise) {
      CHECK(n.declared_deg == 0.01);
      CHECK(n.ratio == Approx(1).epsilon(0.1));
      CHECK(n.estimated_deg == Approx(0.01).epsilon(0.1));
    }
    CHECK(r.scaling == cal::noise_scaling::estimated);
  }
  SECTION("10 times too small on head 2: a warning naming it, weights from the estimate") {
    const cal::fit_result r =
        fit_converged({&model(), cal::recovery_start(), data, {{0.01, 0.0}, {0.001, 0.0}}});
    const std::string table = cal::fit_table(r);
    INFO(table);
    REQUIRE(r.warnings.size() == 1);
    CHECK_THAT(r.warnings[0], Catch::Matchers::StartsWith("h2: its residuals show "));
    CHECK_THAT(r.warnings[0], Catch::Matchers::Contains("declared 0.001 deg"));
    CHECK(r.noise[1].ratio == Approx(10).epsilon(0.1));
    CHECK(r.noise[1].weight_ratio == Approx(r.noise[1].ratio).epsilon(0.03));
    CHECK(r.chi2_dof == Approx(1).margin(0.1));
    CHECK(table.find("noise (deg)") != std::string::npos);
    CHECK(table.find("warning: h2: its residuals show") != std::string::npos);
    // The JSON carries them, and reads back.
    const std::string json = cal::fit_json(r);
    CHECK(json.find("\"noise_scaling\": \"estimated\"") != std::string::npos);
    CHECK(json.find("\"h2\": {\"declared_deg\": 0.001, \"ratio\": ") != std::string::npos);
    CHECK(json.find("\"warnings\": [\n    \"h2: its residuals show") != std::string::npos);
    const auto read = cal::read_fit_json(json, "fit.json");
    REQUIRE(read.ok());
    CHECK(cal::fit_json(read.value()) == json);
  }
  SECTION("declared weights kept: the warning says so, chi2/dof is far from 1") {
    cal::fit_options declared;
    declared.scaling = cal::noise_scaling::declared;
    const cal::fit_result r = fit_converged(
        {&model(), cal::recovery_start(), data, {{0.001, 0.0}, {0.001, 0.0}}}, declared);
    INFO(cal::fit_table(r));
    REQUIRE(r.warnings.size() == 3);
    CHECK_THAT(r.warnings[0], Catch::Matchers::EndsWith("its weights use the declared noise"));
    CHECK_THAT(r.warnings[2], Catch::Matchers::StartsWith("chi2/dof 4."));
    CHECK(r.noise[0].weight_ratio == 1);
  }
}

TEST_CASE("calibration noise: without stated noise the noise is estimated and weights the heads",
          "[calibration][noise]") {
  // Head 1 at 0.01 deg, head 2 five times noisier: unit weights would weight them alike.
  std::vector<cal::observation> data =
      cal::simulate_observations(model().model(), cal::recovery_truth(), 0, 10, 600, 0.01, 9, 0);
  const std::vector<cal::observation> noisy =
      cal::simulate_observations(model().model(), cal::recovery_truth(), 0, 10, 600, 0.05, 9, 0);
  for (std::size_t i = 0; i < data.size(); ++i)
    if (data[i].sample.head == 1) data[i] = noisy[i];
  const cal::fit_result r =
      fit_converged({&model(), cal::recovery_start(), data, {{0.0, 0.0}, {0.0, 0.0}}});
  INFO(cal::fit_table(r));
  CHECK(r.unit_weights);
  CHECK(r.loss == cal::robust_loss::huber);
  CHECK(r.noise[0].estimated_deg == Approx(0.01).epsilon(0.1));
  CHECK(r.noise[1].estimated_deg == Approx(0.05).epsilon(0.1));
  CHECK(r.warnings.empty());
  CHECK(cal::fit_table(r).find("of the estimated noise (no stated noise)") != std::string::npos);
}

TEST_CASE("calibration noise: the histogram's median against the exact one",
          "[calibration][noise]") {
  // |x| of standard normal samples (the scene layer's generator, fixed seeds); the median of a
  // histogram of 256 bins per octave, interpolated within its bin, against nth_element's.
  for (const auto& [n, tolerance] :
       {std::pair{std::size_t{100}, 1e-3}, std::pair{std::size_t{1000}, 1e-3},
        std::pair{std::size_t{1000000}, 5e-5}}) {
    cal::passes::log_histogram h;
    std::vector<double> values;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = std::abs(conescan::scene::standard_normal(77, 0, i, 0, 0));
      h.add(x);
      values.push_back(x);
    }
    std::sort(values.begin(), values.end());
    const double exact = (values[n / 2 - 1] + values[n / 2]) / 2;
    INFO(n << " values: histogram " << h.median() << ", exact " << exact << ", relative error "
           << std::abs(h.median() / exact - 1));
    CHECK(std::abs(h.median() / exact - 1) < tolerance);
    CHECK(h.total() == n);
  }
  cal::passes::log_histogram empty;
  CHECK(std::isnan(empty.median()));
  cal::passes::log_histogram extremes;  // beyond the bins' range: the end bins, no overflow
  for (double v : {0.0, 1e-300, 1e300, -std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN()})
    extremes.add(v);
  CHECK(extremes.total() == 5);
  CHECK(extremes.median() < 1e-18);
}
