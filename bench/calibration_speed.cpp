// conescan-calibration-speed: the estimator (src/calibration/) on the problem size with
// the analytic model of synthetic_model.hpp: one day of 1 Hz telemetry from two heads (86 400
// rows, 172 800 observations, 345 600 residuals), 6 free parameters (both heads' sigma and phi_A,
// head 1's dgamma, the horizon height), 0.01 deg crossing noise, from sigma = 0.
//
// Prints, for 1 and 2 threads in one run: the fit's wall time and where it went (setup, Ceres'
// residual and Jacobian evaluations, its linear solver, the uncertainty pass), the forward
// model's share (one pass of the model alone, in double and in Jets, timed here and multiplied
// by the evaluation counts Ceres reports), and the peak resident memory. Both models: the
// analytic one, and the real one (src/scene_calibration/scene_model.hpp: the scan model of the
// paper's orbit, e = 0.1, two heads at beta = 90 and -90 deg) on telemetry that the scene layer
// simulates with the same truth.
//
// Usage: conescan-calibration-speed [ROWS] (default 86400)
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <variant>

#include "calibration/estimator.hpp"
#include "scene/scene_plan.hpp"
#include "scene/simulation.hpp"
#include "scene_calibration/scene_model.hpp"
#include "support/synthetic_model.hpp"
#include "timing.hpp"

namespace cal = conescan::calibration;
using cal::earth_parameter;
using cal::head_parameter;

namespace {

double seconds(const std::chrono::steady_clock::time_point& start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// ns per observation of the model alone over all observations, for scalar T.
template <class T, class Model>
double model_ns(const Model& model, const std::vector<cal::observation>& data) {
  const cal::head_geometry<T> head{T(0.01), T(0.02), T(0.0)};
  const cal::earth_geometry<T> earth{T(40.0), T(0.0), T(0.0)};
  return conescan::bench::time_per_sample(
             data.size(),
             [&] {
               for (const cal::observation& o : data) {
                 const cal::predicted_measurement<T> p =
                     model.template predict<T>(o.sample, head, earth);
                 conescan::bench::keep(p);
               }
             },
             3, 0.2)
      .median_ns;
}

// The fits with 1 and 2 threads of `data` from `start`, and where their time went.
template <class Model>
bool time_fits(const cal::forward_model_of<Model>& model, const cal::parameter_set& start,
               const std::vector<cal::observation>& data) {
  const double double_ns = model_ns<double>(model.model(), data);
  const double jet_ns = model_ns<cal::parameter_jet>(model.model(), data);
  std::printf("model alone: %.0f ns per observation in double, %.0f ns in Jet<double, 8>\n",
              double_ns, jet_ns);
  for (int threads : {1, 2}) {
    cal::fit_options options;
    options.threads = threads;
    const auto fit_start = std::chrono::steady_clock::now();
    const conescan::checked<cal::fit_outcome> outcome =
        cal::fit({&model, start, data, std::vector<cal::head_noise>(2, {0.01, 0.0})}, options);
    const double total = seconds(fit_start);
    if (!outcome.ok() || !std::holds_alternative<cal::fit_result>(outcome.value())) {
      std::fprintf(stderr, "conescan-calibration-speed: the fit failed\n");
      return false;
    }
    const cal::fit_result& r = std::get<cal::fit_result>(outcome.value());
    const cal::fit_timing& t = r.timing;
    // Model time: each residual evaluation runs it in double, each Jacobian evaluation and the
    // uncertainty pass in Jets, and the start's check once in double; divided among threads.
    const double n = static_cast<double>(data.size());
    const double model_s =
        (n * double_ns * (t.residual_evaluations + 1) + n * jet_ns * (t.jacobian_evaluations + 1)) *
        1e-9 / threads;
    std::printf(
        "threads %d: fit %.2f s (%d iterations, %d residual and %d Jacobian evaluations): setup "
        "%.2f s, solve %.2f s (residuals %.2f s, Jacobians %.2f s, linear solver %.2f s), "
        "uncertainty %.2f s; forward model about %.2f s (%.0f %%); chi2/dof %.4f\n",
        threads, total, r.iterations, t.residual_evaluations, t.jacobian_evaluations, t.setup_s,
        t.solve_s, t.residuals_s, t.jacobians_s, t.linear_solver_s, t.uncertainty_s, model_s,
        100 * model_s / total, r.chi2_dof);
  }
  return true;
}

// The paper's orbit seen by two heads of the scan model, `heads` their keys, one day at 1 s
// (or `rows` rows).
conescan::scene::scene_config paper_scene(std::size_t rows, const char* head1, const char* head2,
                                          const char* horizon_km) {
  namespace sc = conescan::scene;
  const std::vector<sc::option_value> entries{{"model", "scan", {}},
                                              {"step-s", "1", {}},
                                              {"duration-s", std::to_string(rows - 1), {}},
                                              {"horizon-km", horizon_km, {}},
                                              {"head", head1, {}},
                                              {"head", head2, {}}};
  return sc::build_scene_plan(entries).value().scene(0);
}

// The telemetry of the scene layer's simulation, as the calibration reads it.
std::vector<cal::observation> simulated_telemetry(const conescan::scene::scene_config& truth) {
  const conescan::scene::simulation sim = conescan::scene::simulation::of(truth).value();
  std::vector<cal::observation> out;
  conescan::scene::row row = sim.make_row();
  for (std::uint64_t k = 0; k < sim.rows(); ++k) {
    sim.compute(k, row);
    for (std::size_t h = 0; h < sim.head_count(); ++h)
      if (row.heads[h].state == conescan::status::ok)
        out.push_back({{static_cast<std::size_t>(k), row.t_s, h},
                       row.heads[h].chord_rad / cal::radians_per_degree,
                       row.heads[h].phase_rad / cal::radians_per_degree});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t rows = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 86400;
  const cal::forward_model_of<cal::synthetic_model> model{cal::synthetic_model({})};
  cal::parameter_set truth = cal::parameter_set::nominal(2);
  truth.value(0, head_parameter::sigma) = 0.05;
  truth.value(0, head_parameter::phase) = 60;
  truth.value(1, head_parameter::sigma) = 0.03;
  truth.value(1, head_parameter::phase) = 200;
  truth.value(0, head_parameter::dgamma) = 0.02;
  truth.value(earth_parameter::horizon) = 42;
  cal::parameter_set start = cal::parameter_set::nominal(2);
  start.value(earth_parameter::horizon) = 40;
  for (std::size_t index : {0, 1, 5, 6, 2, 10}) start.free[static_cast<std::size_t>(index)] = true;

  const auto simulate_start = std::chrono::steady_clock::now();
  const std::vector<cal::observation> data =
      cal::simulate_observations(model.model(), truth, 0, 1, rows, 0.01, 1, 0);
  std::printf(
      "analytic model: %zu observations, %zu residuals, 6 free parameters (simulated in "
      "%.2f s)\n",
      data.size(), 2 * data.size(), seconds(simulate_start));
  if (!time_fits(model, start, data)) return 1;

  // The real model on the scene layer's telemetry of the same truth.
  const auto scene_start = std::chrono::steady_clock::now();
  const std::vector<cal::observation> scene_data =
      simulated_telemetry(paper_scene(rows, "sigma=0.05,phase=60,dgamma=0.02,noise=0.01",
                                      "beta=-90,sigma=0.03,phase=200,noise=0.01", "42"));
  std::vector<double> times(rows);
  for (std::size_t k = 0; k < rows; ++k) times[k] = static_cast<double>(k);
  const auto built = cal::scene_model::of(
      paper_scene(rows, "sigma=0,noise=0.01", "beta=-90,sigma=0,noise=0.01", "40"), times);
  if (!built.ok()) return 1;
  const cal::forward_model_of<cal::scene_model> real(built.value());
  std::printf(
      "real model (scan model, sphere): %zu observations (simulated and geometry "
      "precomputed in %.2f s)\n",
      scene_data.size(), seconds(scene_start));
  if (!time_fits(real, start, scene_data)) return 1;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("peak resident memory %.0f MiB (%.0f bytes per observation)\n",
              static_cast<double>(usage.ru_maxrss) / 1024,
              static_cast<double>(usage.ru_maxrss) * 1024 / static_cast<double>(data.size()));
  return 0;
}
