// conescan-calibration-speed: the estimator (src/calibration/) on issue 15's problem size with
// the analytic model of synthetic_model.hpp: one day of 1 Hz telemetry from two heads (86 400
// rows, 172 800 observations, 345 600 residuals), 6 free parameters (both heads' sigma and phi_A,
// head 1's dgamma, the horizon height), 0.01 deg crossing noise, from sigma = 0.
//
// Prints, for 1 and 2 threads in one run: the fit's wall time and where it went (setup, Ceres'
// residual and Jacobian evaluations, its linear solver, the uncertainty pass), the forward
// model's share (one pass of the model alone, in double and in Jets, timed here and multiplied
// by the evaluation counts Ceres reports), and the peak resident memory. The synthetic model
// costs about what one step of the exact scan model does; the real model's share will differ.
//
// Usage: conescan-calibration-speed [ROWS] (default 86400)
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <variant>

#include "calibration/estimator.hpp"
#include "calibration/synthetic_model.hpp"
#include "timing.hpp"

namespace cal = conescan::calibration;
using cal::earth_parameter;
using cal::head_parameter;

namespace {

double seconds(const std::chrono::steady_clock::time_point& start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// ns per observation of the model alone over all observations, for scalar T.
template <class T>
double model_ns(const cal::synthetic_model& model, const std::vector<cal::observation>& data) {
  const cal::head_geometry<T> head{T(0.01), T(0.02), T(0.0)};
  const cal::earth_geometry<T> earth{T(40.0), T(0.0), T(0.0)};
  return conescan::bench::time_per_sample(
             data.size(),
             [&] {
               for (const cal::observation& o : data) {
                 const cal::predicted_measurement<T> p = model.predict<T>(o.sample, head, earth);
                 conescan::bench::keep(p);
               }
             },
             3, 0.2)
      .median_ns;
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
  std::printf("%zu observations, %zu residuals, 6 free parameters (simulated in %.2f s)\n",
              data.size(), 2 * data.size(), seconds(simulate_start));
  const double double_ns = model_ns<double>(model.model(), data);
  const double jet_ns = model_ns<cal::parameter_jet>(model.model(), data);
  std::printf("model alone: %.0f ns per observation in double, %.0f ns in Jet<double, 8>\n",
              double_ns, jet_ns);
  for (int threads : {1, 2}) {
    cal::fit_options options;
    options.threads = threads;
    const auto fit_start = std::chrono::steady_clock::now();
    const cal::checked<cal::fit_outcome> outcome =
        cal::fit({&model, start, data, std::vector<cal::head_noise>(2, {0.01, 0.0})}, options);
    const double total = seconds(fit_start);
    if (!outcome.ok() || !std::holds_alternative<cal::fit_result>(outcome.value())) {
      std::fprintf(stderr, "conescan-calibration-speed: the fit failed\n");
      return 1;
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
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("peak resident memory %.0f MiB (%.0f bytes per observation)\n",
              static_cast<double>(usage.ru_maxrss) / 1024,
              static_cast<double>(usage.ru_maxrss) * 1024 / static_cast<double>(data.size()));
  return 0;
}
