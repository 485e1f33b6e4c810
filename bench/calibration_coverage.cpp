// conescan-calibration-coverage: how honest the 1 sigma of a fit are when the declared noise is
// wrong (docs/CALIBRATION.md, "Noise from the data"). The suite's test
// (tests/scene_calibration/test_calibration_noise.cpp) runs 200 seeds per case on the analytic
// model; this program runs as many as asked, on the analytic model or on the real one, for each
// way of weighting a head (fit_options::noise_scaling), and prints the table of the documentation.
//
// Cases: the truth's crossing noise is 0.01 deg on both heads; the fit is told 0.01 (right), 0.001
// on both heads (10 times too small), 0.1 on both (10 times too large), 0.001 or 0.1 on head 1
// only. Per case and scaling: the fraction of 1 sigma intervals that hold the truth, over every
// free parameter and seed, and its worst parameter; the normalised errors' standard deviation.
//
// Usage: conescan-calibration-coverage [SEEDS] [analytic|scene] (default 200 analytic). The
// analytic model fits one orbit at 10 s (600 rows, 6 free parameters); the real one (the scan
// model of the README's recovery scene) one orbit at 5 s (1238 rows).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

#include "calibration/estimator.hpp"
#include "scene/scene_plan.hpp"
#include "scene_calibration/scene_fit.hpp"
#include "simulation/simulation.hpp"
#include "support/synthetic_model.hpp"

namespace cal = conescan::calibration;
namespace sc = conescan::scene;

namespace {

struct noise_case {
  const char* name;
  double head1_deg;  // the declared crossing noise of each head (the truth's is 0.01)
  double head2_deg;
};

constexpr noise_case cases[] = {{"declared right", 0.01, 0.01},
                                {"10x too small, both heads", 0.001, 0.001},
                                {"10x too large, both heads", 0.1, 0.1},
                                {"10x too small, head 1", 0.001, 0.01},
                                {"10x too large, head 1", 0.1, 0.01}};
constexpr cal::noise_scaling scalings[] = {cal::noise_scaling::declared, cal::noise_scaling::larger,
                                           cal::noise_scaling::estimated};

// The normalised errors of one fit's free parameters, in free-parameter order, or empty when it
// did not converge or withheld one.
std::vector<double> normalised_errors(const cal::fit_outcome& outcome,
                                      const std::vector<double>& truth) {
  const auto* r = std::get_if<cal::fit_result>(&outcome);
  if (r == nullptr) return {};
  std::vector<double> z;
  for (std::size_t i = 0; i < r->uncertainty.free_parameters.size(); ++i) {
    const cal::parameter_estimate& e = r->uncertainty.parameters[r->uncertainty.free_parameters[i]];
    if (!e.determined) return {};
    z.push_back(cal::wrap_deg(e.estimate - truth[i]) / e.sigma);
  }
  return z;
}

struct tally {
  std::vector<std::size_t> inside;  // per parameter
  std::vector<double> square;       // sum of z^2 per parameter
  std::size_t fits = 0;
  std::size_t failed = 0;

  void add(const std::vector<double>& z, std::size_t parameters) {
    inside.resize(parameters, 0);
    square.resize(parameters, 0.0);
    if (z.size() != parameters) {
      ++failed;
      return;
    }
    ++fits;
    for (std::size_t i = 0; i < parameters; ++i) {
      inside[i] += std::abs(z[i]) <= 1;
      square[i] += z[i] * z[i];
    }
  }
  void print(const char* case_name, cal::noise_scaling scaling) const {
    std::size_t all = 0, worst = 0;
    double rms = 0;
    for (std::size_t i = 0; i < inside.size(); ++i) {
      all += inside[i];
      if (std::abs(double(inside[i]) - 0.6827 * double(fits)) >
          std::abs(double(inside[worst]) - 0.6827 * double(fits)))
        worst = i;
      rms += square[i];
    }
    const double n = static_cast<double>(fits);
    std::printf("| %s | %s | %.1f %% | %.1f %% (parameter %zu) | %.2f | %zu |\n", case_name,
                cal::noise_scaling_name(scaling), 100.0 * double(all) / (n * double(inside.size())),
                100.0 * double(inside[worst]) / n, worst + 1,
                std::sqrt(rms / (n * double(inside.size()))), failed);
  }
};

// The analytic model: the engine's recovery truth
// (tests/scene_calibration/test_calibration_engine.cpp).
void analytic(int seeds) {
  static const cal::forward_model_of<cal::synthetic_model> model{cal::synthetic_model({})};
  const cal::parameter_set truth = cal::recovery_truth();
  const cal::parameter_set start = cal::recovery_start();
  const std::vector<double> truth_values = {0.05, 60, 0.02, 0.03, -160, 42};
  for (const noise_case& c : cases)
    for (cal::noise_scaling scaling : scalings) {
      tally t;
      for (int seed = 1; seed <= seeds; ++seed) {
        const std::vector<cal::observation> data =
            cal::simulate_observations(model.model(), truth, 0, 10, 600, 0.01, 1000 + seed, 0);
        cal::fit_options options;
        options.scaling = scaling;
        const auto outcome =
            cal::fit({&model, start, data, {{c.head1_deg, 0.0}, {c.head2_deg, 0.0}}}, options);
        t.add(
            outcome.ok() ? normalised_errors(outcome.value(), truth_values) : std::vector<double>{},
            truth_values.size());
      }
      t.print(c.name, scaling);
    }
}

sc::loaded_scene scene_of(const std::vector<sc::option_value>& entries) {
  return sc::build_scene_plan(entries).value().scene(0);
}

// The real model: the README's recovery scene over one orbit at 5 s.
void real(int seeds) {
  const std::string heads[] = {"sigma=0.05,phase=60,dgamma=0.02,noise=0.01",
                               "beta=-90,sigma=0.03,phase=200,noise=0.01"};
  const sc::loaded_scene truth = scene_of({{"model", "scan", {}},
                                           {"step-s", "5", {}},
                                           {"orbits", "1", {}},
                                           {"horizon-km", "42", {}},
                                           {"head", heads[0], {}},
                                           {"head", heads[1], {}}});
  const std::string free = "h1.sigma,h1.phase,h1.dgamma,h2.sigma,h2.phase,horizon-km";
  const std::vector<double> truth_values = {0.05, 60, 0.02, 0.03, -160, 42};
  const sc::simulation sim = sc::simulation::of(truth).value();
  for (const noise_case& c : cases) {
    const sc::loaded_scene start =
        scene_of({{"model", "scan", {}},
                  {"step-s", "5", {}},
                  {"orbits", "1", {}},
                  {"horizon-km", "40", {}},
                  {"head", "sigma=0,noise=" + std::to_string(c.head1_deg), {}},
                  {"head", "beta=-90,sigma=0,noise=" + std::to_string(c.head2_deg), {}}});
    const std::vector<std::size_t> indices = cal::parse_free_list(free, 2).value();
    for (cal::noise_scaling scaling : scalings) {
      tally t;
      for (int run = 0; run < seeds; ++run) {
        cal::telemetry data;
        data.skipped_per_head.assign(2, 0);
        sc::row row = sim.make_row();
        for (std::uint64_t k = 0; k < sim.rows(); ++k) {
          sim.compute(k, row, static_cast<std::uint64_t>(run));
          for (std::size_t h = 0; h < 2; ++h)
            if (row.heads[h].state == conescan::status::ok)
              data.observations.push_back({{static_cast<std::size_t>(k), row.t_s, h},
                                           row.heads[h].chord_rad / cal::radians_per_degree,
                                           row.heads[h].phase_rad / cal::radians_per_degree});
        }
        data.row_count = sim.rows();
        cal::fit_options options;
        options.scaling = scaling;
        const auto outcome = cal::fit_scene(start, data, indices, options);
        t.add(
            outcome.ok() ? normalised_errors(outcome.value(), truth_values) : std::vector<double>{},
            truth_values.size());
      }
      t.print(c.name, scaling);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int seeds = argc > 1 ? std::atoi(argv[1]) : 200;
  const std::string model = argc > 2 ? argv[2] : "analytic";
  if (seeds < 1 || (model != "analytic" && model != "scene")) {
    std::fprintf(stderr, "usage: conescan-calibration-coverage [SEEDS] [analytic|scene]\n");
    return 2;
  }
  std::printf("%d seeds, %s model; truth noise 0.01 deg on both heads\n\n", seeds, model.c_str());
  std::printf(
      "| declared noise | weights | coverage, all | worst parameter | rms of (est - truth)/1sigma "
      "| "
      "failed |\n|---|---|---|---|---|---|\n");
  if (model == "analytic")
    analytic(seeds);
  else
    real(seeds);
  return 0;
}
